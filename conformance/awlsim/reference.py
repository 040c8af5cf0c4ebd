"""The reference semantics, as the conformance runner sees it: two functions.

``run(block, rows, *, tv=None, pt=None, pv=None, type="INT", optimized=False)``
    The reference's outputs for a trace: one dict per row, output column -> value
    (booleans as ``bool``, integers as ``int``, BCD words as ``int``).
``check(block, rows, **same)``
    The first row where the outputs carried by ``rows`` differ from the reference's, as a
    ``Difference`` (``line`` counts CSV lines, the header is line 1; ``column``, 1-based;
    ``output``, its name; ``expected``; ``actual``; ``rules``, the requirement IDs that decided
    that output at the row (empty when none acted on it there); ``earlier_line`` and
    ``earlier_rules``, the latest earlier row that wrote that output, and the rules that
    determined it there (None and empty when there is none; from the command, less those
    already in ``rules``, which it does not repeat); ``message``, the whole text), or None.

Both come from the Python package ``plc_timers`` when it is importable (the bindings of the
crate); otherwise from the command ``plc-timers`` (``run`` and ``check`` over CSV, see
``spec/cli.md``). Setting ``PLC_TIMERS_REFERENCE=cli`` forces the command. The command is found
at ``$PLC_TIMERS_BIN``, else ``plc-timers`` on ``PATH``, else it is built with cargo in the
repository's ``target/``. Nothing here knows any semantics: it only moves rows in and out.
"""

from __future__ import annotations

import csv
import io
import os
import re
import shutil
import subprocess
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any, Mapping, Optional, Sequence

__all__ = ["run", "check", "Difference", "backend"]

#: Output columns that are booleans, and those that are words written W#16#XXXX.
BOOL_OUTPUTS = frozenset({"Q", "QU", "QD"})
WORD_OUTPUTS = frozenset({"BCD", "CV_BCD"})
#: Every output column of every block (the catalog's, spec/cli.md).
OUTPUTS = BOOL_OUTPUTS | WORD_OUTPUTS | {"BI", "ET", "CV"}

REPO = Path(__file__).resolve().parents[2]


@dataclass(frozen=True)
class Difference:
    """The first difference between a trace's outputs and the reference's."""

    line: int
    column: int
    output: str
    expected: str
    actual: str
    rules: list = field(default_factory=list)
    earlier_line: Optional[int] = None
    earlier_rules: list = field(default_factory=list)
    message: str = ""


try:  # the bindings, when built and installed
    if os.environ.get("PLC_TIMERS_REFERENCE", "") == "cli":
        raise ImportError("PLC_TIMERS_REFERENCE=cli")
    import plc_timers as _pkg  # type: ignore[import-not-found]
except ImportError:
    _pkg = None


def backend() -> str:
    """Which implementation answers: ``"package"`` or ``"cli"``."""
    return "package" if _pkg is not None else "cli"


def run(block: str, rows: Sequence[Mapping[str, Any]], *, tv=None, pt=None, pv=None,
        type: str = "INT", optimized: bool = False) -> list:
    """The reference's outputs for each row of the trace (see the module's docs)."""
    if _pkg is not None:
        return _pkg.run(block, rows, tv=tv, pt=pt, pv=pv, type=type, optimized=optimized)
    return _cli_run(block, rows, tv=tv, pt=pt, pv=pv, type=type, optimized=optimized)


def check(block: str, rows: Sequence[Mapping[str, Any]], *, tv=None, pt=None, pv=None,
          type: str = "INT", optimized: bool = False) -> Optional[Difference]:
    """The first difference of the rows' outputs from the reference's, or None."""
    if _pkg is not None:
        return _pkg.check(block, rows, tv=tv, pt=pt, pv=pv, type=type, optimized=optimized)
    return _cli_check(block, rows, tv=tv, pt=pt, pv=pv, type=type, optimized=optimized)


# --- the command-line path -------------------------------------------------------------------

_BIN: Optional[str] = None


def _binary() -> str:
    global _BIN
    if _BIN is None:
        env = os.environ.get("PLC_TIMERS_BIN")
        if env:
            _BIN = env
        elif shutil.which("plc-timers"):
            _BIN = shutil.which("plc-timers")
        else:
            subprocess.run(["cargo", "build", "-q", "-p", "plc-timers-cli"], cwd=REPO, check=True)
            _BIN = str(REPO / "target" / "debug" / "plc-timers")
    return _BIN


def _cell(value: Any) -> str:
    if isinstance(value, bool):
        return "1" if value else "0"
    return str(value)


def _csv(rows: Sequence[Mapping[str, Any]]) -> str:
    columns: list = []
    for row in rows:
        for name in row:
            if name not in columns:
                columns.append(name)
    out = io.StringIO()
    w = csv.writer(out, lineterminator="\n")
    w.writerow(columns)
    for row in rows:
        w.writerow([_cell(row.get(c, 0)) for c in columns])
    return out.getvalue()


def _options(block, tv, pt, pv, type, optimized) -> list:
    args = [block]
    for flag, value in (("--tv", tv), ("--pt", pt), ("--pv", pv)):
        if value is not None:
            args += [flag, str(value)]
    if block.upper().startswith("CT"):
        args += ["--type", type]
    if optimized:
        args.append("--optimized")
    return args


def _value(column: str, text: str):
    name = column.upper()
    if name in BOOL_OUTPUTS:
        return text == "1"
    if name in WORD_OUTPUTS:
        return int(text[5:], 16) if text.upper().startswith("W#16#") else int(text)
    return int(text)


def _cli_run(block, rows, *, tv, pt, pv, type, optimized) -> list:
    proc = subprocess.run([_binary(), "run", *_options(block, tv, pt, pv, type, optimized), "-"],
                          input=_csv(rows), capture_output=True, text=True)
    if proc.returncode != 0:
        raise ValueError(f"plc-timers run {block}: {proc.stderr.strip()}")
    lines = list(csv.reader(io.StringIO(proc.stdout)))
    header = lines[0]
    outs = [(i, c) for i, c in enumerate(header) if c.upper() in OUTPUTS]
    return [{c: _value(c, rec[i]) for i, c in outs} for rec in lines[1:]]


_DIFF = re.compile(r"DIFFERENT at line (\d+), column (\d+) \(([^)]*)\): "
                   r"the reference gives (.*), the trace has (.*)$")
_RULE = re.compile(r"^([A-Z0-9]+(?:-[A-Z0-9]+)+): ")
_EARLIER = re.compile(r"^after line (\d+), where these acted and still matter:$")


def _cli_check(block, rows, *, tv, pt, pv, type, optimized) -> Optional[Difference]:
    proc = subprocess.run([_binary(), "check", *_options(block, tv, pt, pv, type, optimized), "-"],
                          input=_csv(rows), capture_output=True, text=True)
    if proc.returncode == 0:
        return None
    if proc.returncode != 1:
        raise ValueError(f"plc-timers check {block}: {proc.stderr.strip()}")
    lines = proc.stdout.splitlines()
    m = _DIFF.match(lines[0])
    if m is None:
        raise ValueError(f"plc-timers check {block}: unexpected report: {lines[0]!r}")
    # "decided at this row by:" (or a line saying no rule acted), then "ID: text" lines; then
    # optionally "after line N, where these acted and still matter:" and its "ID: text" lines
    # (the command does not repeat there a rule named at the row).
    rules: list = []
    earlier_line = None
    earlier: list = []
    into = rules
    for line in lines[1:]:
        if line.startswith("rows up to it"):
            break
        e = _EARLIER.match(line)
        if e:
            earlier_line, into = int(e.group(1)), earlier
            continue
        r = _RULE.match(line)
        if r:
            into.append(r.group(1))
    return Difference(line=int(m.group(1)), column=int(m.group(2)), output=m.group(3),
                      expected=m.group(4), actual=m.group(5), rules=rules,
                      earlier_line=earlier_line, earlier_rules=earlier, message=proc.stdout)


# --- literal conversions (the command's `s5time` and `time`), for presets given as literals ----

_LITERALS: dict = {}


def _convert(kind: str, text: str) -> str:
    key = (kind, text)
    if key not in _LITERALS:
        proc = subprocess.run([_binary(), kind, text], capture_output=True, text=True)
        if proc.returncode != 0:
            raise ValueError(f"plc-timers {kind} {text}: {proc.stderr.strip()}")
        _LITERALS[key] = proc.stdout.split()
    return _LITERALS[key]


def s5time_word(text: Any) -> int:
    """The S5TIME word of a TV cell: ``W#16#…`` as written (bits 14-15 included, for the
    runtime to judge), an ``S5T#…`` literal with the automatic base (``plc-timers s5time``)."""
    t = str(text).strip()
    if t.upper().startswith("W#16#"):
        return int(t[5:], 16)
    return int(_convert("s5time", t)[0][5:], 16)


def time_ms(text: Any) -> int:
    """The milliseconds of a PT cell: an integer, or a ``T#…`` literal (``plc-timers time``)."""
    t = str(text).strip()
    try:
        return int(t)
    except ValueError:
        return int(_convert("time", t)[0])
