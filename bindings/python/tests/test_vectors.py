"""Every block against the `plc-timers` command: the test vectors it writes (inputs with its
reference outputs) and the example traces it runs give the same outputs in Python, row for row,
for the reference and the optimized implementation."""

from __future__ import annotations

import subprocess
from pathlib import Path
from typing import Any, Dict, List, Optional, Tuple, Union

import plc_timers
import pytest

from conftest import EXAMPLES, as_dicts, read_trace, vector_files

BOOLS = {"Q", "QU", "QD"}
WORDS = {"BCD", "CV_BCD"}
OUTPUTS = BOOLS | {"ET", "BI", "CV"} | WORDS


def expected(name: str, cell: str) -> Union[bool, int]:
    """An output cell of the trace format as `run` returns it."""
    if name in BOOLS:
        assert cell in ("0", "1"), cell
        return cell == "1"
    if name in WORDS:
        assert cell.startswith("W#16#"), cell
        return int(cell[5:], 16)
    return int(cell)


def same_types(got: Dict[str, Union[bool, int]]) -> None:
    for name, v in got.items():
        assert isinstance(v, bool) == (name in BOOLS), (name, v)


def test_every_vector_runs_the_same(vectors: Path) -> None:
    files = list(vector_files(vectors))
    blocks = {b for b, _, _ in files}
    assert len(blocks) == 15, blocks
    rows_compared = 0
    for block, int_type, path in files:
        header, rows = read_trace(path)
        inputs = [c for c in header if c.upper() not in OUTPUTS]
        outs = [c for c in header if c.upper() in OUTPUTS]
        assert outs, path
        table = as_dicts(header, rows)
        given = [{c: r[c] for c in inputs} for r in table]
        for optimized in (False, True):
            got = plc_timers.run(block, given, type=int_type, optimized=optimized)
            assert len(got) == len(table), path
            for line, (mine, theirs) in enumerate(zip(got, table), start=2):
                same_types(mine)
                want = {c.upper(): expected(c.upper(), theirs[c]) for c in outs}
                assert mine == want, f"{path}:{line} optimized={optimized}"
            # The whole file, outputs included, is what `check` accepts without a difference.
            assert plc_timers.check(block, table, type=int_type, optimized=optimized) is None
        rows_compared += len(table)
    assert rows_compared > 10_000


def example_command(path: Path) -> List[str]:
    """The `run` command of an example trace, from its first line."""
    first = path.read_text().splitlines()[0]
    prefix = "# cargo run --release -- "
    assert first.startswith(prefix), first
    return first[len(prefix) :].split()


@pytest.mark.parametrize("path", sorted(EXAMPLES.glob("*.csv")), ids=lambda p: p.stem)
def test_example_trace_matches_the_command(cli: Path, path: Path) -> None:
    words = example_command(path)
    assert words[0] == "run" and words[-1].endswith(path.name)
    block, options = words[1], words[2:-1]
    kwargs: Dict[str, str] = {}
    for name, val in zip(options[::2], options[1::2]):
        kwargs[name.lstrip("-")] = val
    done = subprocess.run(
        [str(cli), *words[:-1], str(path)], check=True, capture_output=True, text=True
    )
    cli_header, cli_rows = read_trace_text(done.stdout)
    header, rows = read_trace(path)
    n_out = len(cli_header) - len(header)
    assert n_out >= 2
    table = as_dicts(header, rows)
    for optimized in (False, True):
        got = plc_timers.run(
            block,
            table,
            tv=kwargs.get("tv"),
            pt=kwargs.get("pt"),
            pv=kwargs.get("pv"),
            type=kwargs.get("type", "INT"),
            optimized=optimized,
        )
        assert len(got) == len(cli_rows)
        for mine, theirs in zip(got, cli_rows):
            want = {
                name: expected(name, cell)
                for name, cell in zip(cli_header[-n_out:], theirs[-n_out:])
            }
            assert mine == want


def read_trace_text(text: str) -> tuple[List[str], List[List[str]]]:
    lines = [line.split(",") for line in text.splitlines() if line.strip()]
    return lines[0], lines[1:]


def test_check_message_is_the_command_s(cli: Path, tmp_path: Path) -> None:
    """`check` forwards the engine's report: its message is what `plc-timers check` prints."""
    header, rows = read_trace(EXAMPLES / "ton.csv")
    reference = plc_timers.run("TON", as_dicts(header, rows), pt="T#500ms")
    # Another implementation whose Q rises one call late.
    table: List[Dict[str, Union[str, bool, int]]] = []
    for k, (row, out) in enumerate(zip(rows, reference)):
        late = bool(reference[k - 1]["Q"]) if k > 0 else False
        table.append({**dict(zip(header, row)), "Q": out["Q"] and late, "ET": out["ET"]})
    d = plc_timers.check("TON", table, pt="T#500ms")
    assert d is not None
    first_q = next(k for k, out in enumerate(reference) if out["Q"])
    assert (d.line, d.output, d.expected, d.actual) == (first_q + 2, "Q", True, False)
    assert d.column == len(header) + 1
    assert d.rules and all(r.startswith("IEC-") for r in d.rules)
    csv_text = ",".join([*header, "Q", "ET"]) + "\n"
    for cells in table:
        csv_text += ",".join(str(int(v)) if isinstance(v, bool) else str(v) for v in cells.values())
        csv_text += "\n"
    trace = tmp_path / "late.csv"
    trace.write_text(csv_text)
    done = subprocess.run(
        [str(cli), "check", "TON", "--pt", "T#500ms", str(trace)],
        capture_output=True,
        text=True,
    )
    assert done.returncode == 1
    assert done.stdout == d.message
    assert str(d) == d.message
    assert named(d) == why_in_message(done.stdout)


def named(d: plc_timers.Difference) -> Tuple[List[str], Optional[int], List[str]]:
    """The rules of a Difference as the command prints them: it does not repeat at the earlier
    row a rule it named at the row."""
    return d.rules, d.earlier_line, [r for r in d.earlier_rules if r not in d.rules]


def why_in_message(message: str) -> Tuple[List[str], Optional[int], List[str]]:
    """The rules `plc-timers check` prints: those that decided at the row, and the earlier row
    with the rules that acted there and still matter (its `ID: text` lines)."""
    rules: List[str] = []
    earlier_line: Optional[int] = None
    earlier: List[str] = []
    into: Optional[List[str]] = None
    for line in message.splitlines()[1:]:
        if line == "decided at this row by:":
            into = rules
        elif line.startswith("after line ") and line.endswith(", where these acted and still matter:"):
            earlier_line = int(line[len("after line ") :].split(",")[0])
            into = earlier
        elif line.startswith("rows up to it"):
            break
        elif into is not None and ": " in line and not line.startswith(" "):
            into.append(line.split(": ", 1)[0])
        else:
            into = None
    return rules, earlier_line, earlier


@pytest.mark.parametrize("path", sorted(EXAMPLES.glob("*.csv")), ids=lambda p: p.stem)
def test_check_names_the_rules_the_command_names(cli: Path, path: Path, tmp_path: Path) -> None:
    """An example trace with one output changed at each of its last rows: `check`'s rules and
    earlier row are those in the text `plc-timers check` prints, and that text is the message."""
    words = example_command(path)
    block, options = words[1], words[2:-1]
    kwargs: Dict[str, str] = {}
    for name, val in zip(options[::2], options[1::2]):
        kwargs[name.lstrip("-")] = val
    header, rows = read_trace(path)
    presets: Dict[str, Any] = {
        "tv": kwargs.get("tv"),
        "pt": kwargs.get("pt"),
        "pv": kwargs.get("pv"),
        "type": kwargs.get("type", "INT"),
    }
    reference = plc_timers.run(block, as_dicts(header, rows), **presets)
    outputs = list(reference[0])
    for k in range(max(0, len(rows) - 3), len(rows)):
        # The first output of row k, changed (a bit flipped, a number one more).
        name = outputs[0]
        value = reference[k][name]
        wrong: Union[bool, int] = (not value) if isinstance(value, bool) else value + 1
        table: List[Dict[str, Any]] = [
            {**dict(zip(header, row)), **out, **({name: wrong} if j == k else {})}
            for j, (row, out) in enumerate(zip(rows, reference))
        ]
        d = plc_timers.check(block, table, **presets)
        assert d is not None
        assert (d.line, d.output, d.expected) == (k + 2, name, value)
        cells = [[str(int(v)) if isinstance(v, bool) else str(v) for v in r.values()] for r in table]
        trace = tmp_path / f"{path.stem}-{k}.csv"
        trace.write_text("\n".join(",".join(r) for r in [list(table[0]), *cells]) + "\n")
        command = [str(cli), "check", *words[1:-1], str(trace)]
        done = subprocess.run(command, capture_output=True, text=True)
        assert done.returncode == 1, done.stderr
        assert d.message == done.stdout
        assert named(d) == why_in_message(done.stdout)
        assert d.rules or "no rule acted" in d.message
        assert d.earlier_line is None or 2 <= d.earlier_line < d.line
        if d.earlier_line is None:
            assert d.earlier_rules == []


@pytest.mark.parametrize(
    ("block", "keyword", "value", "option"),
    [
        ("TON", "tv", "S5T#1S", None),  # a preset keyword the block does not take
        ("S_CU", "pt", "T#1S", None),
        ("TON", "pt", "T#1.5S", "pt"),  # the block's keyword, a value it refuses
        ("CTU", "pv", "70000", "pv"),
        ("S_ODT", "tv", "S5T#10000S", "tv"),
    ],
)
def test_preset_keyword_errors_are_the_command_s(
    cli: Path, tmp_path: Path, block: str, keyword: str, value: str, option: Union[str, None]
) -> None:
    """A preset keyword is read as the command line's parser reads its option: the same
    message, before any row is read (the trace below is valid), naming the keyword argument
    where the command names its option (`--pt`), which a Python user never typed."""
    columns = {"TON": ["t_ms", "IN"], "S_CU": ["CU"], "CTU": ["CU"], "S_ODT": ["t_ms", "S"]}[block]
    presets: Dict[str, Any] = {keyword: value}
    with pytest.raises(plc_timers.TraceError) as e:
        plc_timers.run(block, [dict.fromkeys(columns, 0)], **presets)
    assert e.value.option == option
    trace = tmp_path / "trace.csv"
    trace.write_text(",".join(columns) + "\n" + ",".join("0" for _ in columns) + "\n")
    done = subprocess.run(
        [str(cli), "run", block, f"--{keyword}", value, str(trace)],
        capture_output=True,
        text=True,
    )
    assert done.returncode != 0
    assert "--" not in str(e.value)
    first = done.stderr.splitlines()[0]
    if option is None:
        # The command refuses the option; Python names the keyword the block takes.
        assert f"--{keyword}" in first
        assert f"the keyword argument {keyword} does not apply to {block}" in str(e.value)
    else:
        assert first == f"error: option --{option}: {e.value.message}"
        assert str(e.value) == f"keyword argument {option}: {e.value.message}"
