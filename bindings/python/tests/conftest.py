"""Shared fixtures: the repository, the `plc-timers` command and the test vectors it writes."""

from __future__ import annotations

import csv
import os
import shutil
import subprocess
from pathlib import Path
from typing import Dict, Iterator, List, Tuple

import pytest

REPO = Path(__file__).resolve().parents[3]
EXAMPLES = REPO / "examples" / "traces"


# Set by ci.sh: every test must run there, so a skip (e.g. the command not found) fails the run.
NO_SKIPS = os.environ.get("PLC_TIMERS_NO_SKIPS") == "1"


def find_cli() -> Path | None:
    """The `plc-timers` command: $PLC_TIMERS_BIN, else a build in cargo's target directory
    ($CARGO_TARGET_DIR, else the repository's target/)."""
    given = os.environ.get("PLC_TIMERS_BIN")
    if given:
        return Path(given)
    target = Path(os.environ.get("CARGO_TARGET_DIR") or REPO / "target")
    for profile in ("release", "debug"):
        candidate = target / profile / "plc-timers"
        if candidate.exists():
            return candidate
    found = shutil.which("plc-timers")
    return Path(found) if found else None


@pytest.fixture(scope="session")
def cli() -> Path:
    path = find_cli()
    if path is None:
        pytest.skip(
            "the plc-timers command is not built (cargo build --release -p plc-timers-cli, "
            "or set PLC_TIMERS_BIN); ci.sh builds it"
        )
    return path


@pytest.fixture(scope="session")
def vectors(cli: Path, tmp_path_factory: pytest.TempPathFactory) -> Path:
    """The test vectors, written by `plc-timers vectors`."""
    out = tmp_path_factory.mktemp("vectors") / "v"
    subprocess.run([str(cli), "vectors", str(out)], check=True, capture_output=True)
    return out


def read_trace(path: Path) -> Tuple[List[str], List[List[str]]]:
    """The header and the rows of a CSV trace, without blank and `#` comment lines."""
    with path.open(newline="") as f:
        lines = [
            line for line in f if line.strip() and not line.lstrip().startswith("#")
        ]
    records = list(csv.reader(lines))
    return [c.strip() for c in records[0]], [[c.strip() for c in r] for r in records[1:]]


def vector_files(root: Path) -> Iterator[Tuple[str, str, Path]]:
    """(block, integer type, file) of every vector under `root`."""
    for d in sorted(p for p in root.iterdir() if p.is_dir()):
        block, _, int_type = d.name.partition("-")
        for f in sorted(d.glob("*.csv")):
            yield block, int_type or "INT", f


_skipped: List[str] = []


def pytest_runtest_logreport(report: pytest.TestReport) -> None:
    if report.skipped:
        _skipped.append(report.nodeid)


def pytest_sessionfinish(session: pytest.Session, exitstatus: int) -> None:
    """With PLC_TIMERS_NO_SKIPS=1 (CI), a skipped test is a failure: it should have run."""
    if NO_SKIPS and _skipped and exitstatus == 0:
        print(f"\n{len(_skipped)} test(s) skipped where every test must run:", *_skipped[:5])
        session.exitstatus = pytest.ExitCode.TESTS_FAILED


def as_dicts(header: List[str], rows: List[List[str]]) -> List[Dict[str, str]]:
    return [dict(zip(header, r)) for r in rows]
