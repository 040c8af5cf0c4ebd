#!/bin/sh
# The awlsim conformance run (issue 26): awlsim 0.77.1 from PyPI in its own virtual environment,
# the unit tests of the runner's helpers, then every vector and the seeded random traces through
# awlsim and the reference; writes docs/conformance/awlsim.md. Exit status 1 when a difference
# is not a deviation that spec/ documents (see deviations.py). Arguments go to runner.py
# (--random N, --seed S, --blocks A,B, --report FILE).
#
# Environment: AWLSIM_VENV (default target/awlsim-venv), PYTHON (the interpreter that creates
# it, default python3), PLC_TIMERS_BIN (the plc-timers command; default: built with cargo),
# PLC_TIMERS_WHEEL (a wheel of the Python package to install into the venv, so the reference
# is called in-process instead of through the command).
set -eu
here=$(cd "$(dirname "$0")" && pwd)
repo=$(cd "$here/../.." && pwd)
venv=${AWLSIM_VENV:-$repo/target/awlsim-venv}
case $venv in /*) ;; *) venv=$(pwd)/$venv ;; esac
export PYTHONDONTWRITEBYTECODE=1

if [ ! -x "$venv/bin/python" ]; then
    "${PYTHON:-python3}" -m venv "$venv"
fi
"$venv/bin/python" -m pip install -q --disable-pip-version-check awlsim==0.77.1
if [ -n "${PLC_TIMERS_WHEEL:-}" ]; then
    "$venv/bin/python" -m pip install -q --disable-pip-version-check "$PLC_TIMERS_WHEEL"
fi

if [ -z "${PLC_TIMERS_BIN:-}" ]; then
    (cd "$repo" && cargo build -q -p plc-timers-cli)
    PLC_TIMERS_BIN=$repo/target/debug/plc-timers
fi
# A relative path made absolute: the runner works from this directory.
case $PLC_TIMERS_BIN in
    /*) ;;
    */*) PLC_TIMERS_BIN=$(cd "$(dirname "$PLC_TIMERS_BIN")" && pwd)/$(basename "$PLC_TIMERS_BIN") ;;
esac
export PLC_TIMERS_BIN

vectors=$(mktemp -d)
trap 'rm -rf "$vectors"' EXIT
"$PLC_TIMERS_BIN" vectors "$vectors" >/dev/null

cd "$here"
"$venv/bin/python" -m unittest -q test_helpers
"$venv/bin/python" runner.py --vectors "$vectors" "$@"
