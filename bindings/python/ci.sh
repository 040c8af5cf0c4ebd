#!/usr/bin/env bash
# CI of the Python package plc-timers, on a fresh machine: a virtual environment with the build
# and test tools from PyPI; the manylinux wheel (maturin with the zig linker from PyPI, so that
# it runs on glibc 2.17 and later) and the sdist; the wheel installed into a clean environment
# without a Rust toolchain on PATH and smoke-tested; then, against the same wheel, pytest (the
# vectors and examples against the plc-timers command, the API, the hypothesis properties, the
# doctests, the README example; a skipped test fails the run), stubtest, mypy --strict on the
# tests and the example, and the doctests once more on their own.
#
#   bash bindings/python/ci.sh          (from anywhere; run by .ci/run)
#
# CARGO_TARGET_DIR: cargo's target directory (default target/ of the repository).
# PLC_TIMERS_PY_VENV: where the test environment goes (default <target>/python-ci-venv).
set -euo pipefail
here="$(cd "$(dirname "$0")" && pwd)"
repo="$(cd "$here/../.." && pwd)"
cd "$repo"

target="${CARGO_TARGET_DIR:-$repo/target}"
venv="${PLC_TIMERS_PY_VENV:-$target/python-ci-venv}"
python="${PYTHON:-python3}"

echo "== python: $("$python" --version) in $venv"
"$python" -m venv "$venv"
py="$venv/bin/python"
"$py" -m pip install --quiet --upgrade pip
"$py" -m pip install --quiet maturin ziglang pytest hypothesis numpy mypy

echo "== python: the manylinux wheel (maturin --zig, release, abi3) and the sdist"
wheels="$target/python-wheels"
rm -rf "$wheels"
# maturin finds zig through the Python on PATH (`python -m ziglang`): the venv's.
(cd "$here" && PATH="$venv/bin:$PATH" maturin build --quiet --release --zig \
    --compatibility manylinux2014 --out "$wheels")
(cd "$here" && "$venv/bin/maturin" sdist --out "$wheels")
"$py" - "$wheels" <<'EOF'
import pathlib, sys, tarfile, zipfile
wheels = pathlib.Path(sys.argv[1])
[wheel] = wheels.glob("*.whl")
# maturin checked the symbols against the policy (auditwheel's check) before naming it so.
assert "manylinux_2_17_x86_64" in wheel.name and "abi3" in wheel.name, wheel.name
names = zipfile.ZipFile(wheel).namelist()
for f in ("LICENSE-MIT", "LICENSE-APACHE"):
    assert any(n.endswith(f) and ".dist-info/" in n for n in names), f"the wheel lacks {f}"
[sdist] = wheels.glob("*.tar.gz")
members = {m.split("/", 1)[1] for m in tarfile.open(sdist).getnames() if "/" in m}
needed = ["Cargo.toml", "Cargo.lock", "LICENSE-MIT", "LICENSE-APACHE", "src/lib.rs",
          "trace/Cargo.toml", "bindings/python/Cargo.toml", "pyproject.toml",
          "bindings/python/plc_timers.pyi", "bindings/python/src/lib.rs"]
missing = [f for f in needed if f not in members]
assert not missing, f"the sdist lacks {missing}"
print("wheel", wheel.name, "and sdist", sdist.name, "checked")
EOF
# The sdist's crates resolve on their own, with nothing outside it, to the versions of its lock
# file: maturin trims the workspace to the crates the package needs, so cargo drops the others'
# entries (bindings/c's cbindgen, tools/kani) from the lock, and must add or change none.
sdist_dir="$target/python-sdist"
rm -rf "$sdist_dir" && mkdir -p "$sdist_dir"
tar xzf "$wheels"/*.tar.gz -C "$sdist_dir"
sdist_root="$(echo "$sdist_dir"/plc_timers-*)"
cp "$sdist_root/Cargo.lock" "$sdist_dir/Cargo.lock.shipped"
cargo metadata --offline --format-version 1 \
    --manifest-path "$sdist_root/bindings/python/Cargo.toml" >/dev/null
"$py" - "$sdist_dir/Cargo.lock.shipped" "$sdist_root/Cargo.lock" <<'EOF'
import re, sys
def packages(path):
    text = open(path).read()
    return set(re.findall(r'^name = "([^"]+)"\nversion = "([^"]+)"', text, re.M))
shipped, resolved = packages(sys.argv[1]), packages(sys.argv[2])
assert resolved and resolved <= shipped, f"not pinned by the sdist: {sorted(resolved - shipped)}"
print(f"the sdist resolves to {len(resolved)} crates, all pinned by its Cargo.lock")
EOF
wheel="$(ls "$wheels"/*.whl)"

echo "== python: the wheel in a clean environment without a Rust toolchain on PATH"
clean="$target/python-clean-venv"
rm -rf "$clean"
"$python" -m venv "$clean"
no_rust="$clean/bin"
IFS=: read -ra dirs <<<"$PATH"
for d in "${dirs[@]}"; do
    if [ -n "$d" ] && [ ! -e "$d/cargo" ] && [ ! -e "$d/rustc" ]; then no_rust="$no_rust:$d"; fi
done
PATH="$no_rust" "$clean/bin/python" -m pip install --quiet "$wheel[numpy]"
(cd "$target" && PATH="$no_rust" "$clean/bin/python" - <<'EOF'
import shutil
assert shutil.which("cargo") is None and shutil.which("rustc") is None, "Rust is on PATH"
import numpy as np
import plc_timers
ton = plc_timers.TON(pt="T#500ms")
assert ton.call(0, in_=True) == plc_timers.IecOutput(q=False, et=0)
assert ton.call(500, in_=True) == plc_timers.IecOutput(q=True, et=500)
bank = plc_timers.TonBank(3)
q, et = bank.scan(0, np.array([1, 2, 255], np.uint8).view(np.bool_), np.zeros(3, np.int32))
assert q.tolist() == [True, True, True], q  # PT 0: Q at the rising IN, every non-zero byte
print("the wheel works without Rust:", plc_timers.__file__)
EOF
)

echo "== python: the same wheel into the test environment"
"$py" -m pip install --quiet --force-reinstall --no-deps "$wheel"
"$py" - <<'EOF'
import plc_timers, pathlib
pkg = pathlib.Path(plc_timers.__file__).parent
missing = [f for f in ("__init__.pyi", "py.typed") if not (pkg / f).exists()]
assert not missing, f"the installed package lacks {missing}"
print("installed", plc_timers.__version__, "from", pkg)
EOF

echo "== python: the plc-timers command the tests compare with"
cargo build --release -p plc-timers-cli
export PLC_TIMERS_BIN="$target/release/plc-timers"
test -x "$PLC_TIMERS_BIN"

echo "== python: pytest"
# Run from the tests' directory so that `plc_timers` is the installed package. Every test must
# run here: PLC_TIMERS_NO_SKIPS makes a skipped one fail the run (conftest.py), -rs lists them.
# Exit status 5 means no test was collected: a broken suite, not a pass.
set +e
(cd "$here/tests" && PLC_TIMERS_NO_SKIPS=1 "$py" -m pytest -q -rs -p no:cacheprovider)
status=$?
set -e
if [ "$status" -eq 5 ]; then
    echo "pytest collected no tests" >&2
    exit 1
elif [ "$status" -ne 0 ]; then
    exit "$status"
fi

echo "== python: stubtest (the stubs against the installed module)"
(cd "$here/tests" && "$py" -m mypy.stubtest plc_timers \
    --allowlist "$here/stubtest-allowlist.txt")

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
