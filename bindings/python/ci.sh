#!/usr/bin/env bash
# CI of the Python package plc-timers, on a fresh machine: a virtual environment with the test
# tools from PyPI, the package installed as the README says (`pip install ./bindings/python`,
# which builds the abi3 wheel with maturin), then pytest (the vectors and examples against the
# plc-timers command, the API, the hypothesis properties, the doctests, the README example),
# mypy --strict on the tests and the example, and the doctests once more on their own.
#
#   bash bindings/python/ci.sh          (from anywhere; run by .ci/run)
#
# PLC_TIMERS_PY_VENV: where the environment goes (default target/python-ci-venv).
set -euo pipefail
here="$(cd "$(dirname "$0")" && pwd)"
repo="$(cd "$here/../.." && pwd)"
cd "$repo"

venv="${PLC_TIMERS_PY_VENV:-$repo/target/python-ci-venv}"
python="${PYTHON:-python3}"

echo "== python: $("$python" --version) in $venv"
"$python" -m venv "$venv"
py="$venv/bin/python"
"$py" -m pip install --quiet --upgrade pip
"$py" -m pip install --quiet maturin pytest hypothesis numpy mypy

echo "== python: pip install ./bindings/python (maturin, release, abi3 wheel)"
"$py" -m pip install --quiet --force-reinstall ./bindings/python
"$py" - <<'EOF'
import plc_timers, pathlib
pkg = pathlib.Path(plc_timers.__file__).parent
missing = [f for f in ("__init__.pyi", "py.typed") if not (pkg / f).exists()]
assert not missing, f"the installed package lacks {missing}"
print("installed", plc_timers.__version__, "from", pkg)
EOF

echo "== python: the plc-timers command the tests compare with"
cargo build --release -p plc-timers-cli
export PLC_TIMERS_BIN="$repo/target/release/plc-timers"

echo "== python: pytest"
# Run from the tests' directory so that `plc_timers` is the installed package. Exit status 5
# means no test was collected: a broken suite, not a pass.
set +e
(cd "$here/tests" && "$py" -m pytest -q -p no:cacheprovider)
status=$?
set -e
if [ "$status" -eq 5 ]; then
    echo "pytest collected no tests" >&2
    exit 1
elif [ "$status" -ne 0 ]; then
    exit "$status"
fi

echo "== python: mypy --strict (tests, example) against the installed stubs"
(cd "$here/tests" && "$py" -m mypy --strict --no-incremental . ../examples/readme.py)

echo "== python: doctests"
"$py" - <<'EOF'
import doctest, sys
import plc_timers
result = doctest.testmod(plc_timers)
print(f"doctests: {result.attempted} run, {result.failed} failed")
sys.exit(1 if result.failed or result.attempted == 0 else 0)
EOF

echo "== python: the README example"
"$py" "$here/examples/readme.py"
