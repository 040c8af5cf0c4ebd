"""The awlsim conformance run: replay traces through awlsim and through the reference, compare
row by row, group each difference by the requirements that decide it, shrink one trace per
group, and write the report. Exit status 1 when a difference is explained by no requirement or
by none that `spec/` documents as an awlsim deviation (deviations.py), 2 on bad usage.

    python runner.py --vectors DIR [--random N] [--seed S] [--report FILE]
"""

from __future__ import annotations

import argparse
import random
import sys
import time
from dataclasses import dataclass, field
from pathlib import Path

import awl
import deviations
import reference
import traces

REPO = reference.REPO


def preset_kw(block: str) -> dict:
    """The keyword arguments of reference.run/check for a block (the preset is a column)."""
    return {"type": "INT"} if block.startswith("CT") else {}


def with_outputs(rows: list, outs: list) -> list:
    return [{**r, **o} for r, o in zip(rows, outs)]


def first_difference(block: str, rows: list):
    """(awlsim's outputs, the reference's, index of the first differing row or None, count of
    differing rows)."""
    got = awl.run(block, rows)
    want = reference.run(block, rows, **preset_kw(block))
    differing = [i for i, (g, w) in enumerate(zip(got, want)) if g != w]
    return got, want, (differing[0] if differing else None), len(differing)


def explain(block: str, rows: list, got: list):
    """``check`` on the trace with awlsim's outputs: the first difference and its rules."""
    return reference.check(block, with_outputs(rows, got), **preset_kw(block))


def key_of(diff) -> tuple:
    """The requirements check names: (those that decided at the row, those that acted at the
    earlier row and still matter, less the former), each sorted."""
    at_row = tuple(sorted(diff.rules))
    return at_row, tuple(sorted(set(diff.earlier_rules) - set(at_row)))


def named_text(key: tuple) -> str:
    """A key_of as the report writes it."""
    at_row, earlier = key
    text = " + ".join(at_row) or "no requirement at the row"
    return text + (f", after an earlier row: {' + '.join(earlier)}" if earlier else "")


def case_of(block: str, rows: list, got: list, diff) -> deviations.Case:
    """The first differing row of a trace as the deviations' predicates see it."""
    i = diff.line - 1  # rows[i - 1] is the differing row
    want = reference.run(block, rows[:i], **preset_kw(block))
    column = next(c for c in want[-1] if want[-1][c] != got[i - 1][c])
    if diff.output.upper() != column.upper():
        raise AssertionError(f"{block}: check names output {diff.output}, the first differing "
                             f"output is {column}")
    at_row, earlier = key_of(diff)
    j = None if diff.earlier_line is None else diff.earlier_line - 2
    return deviations.Case(block, rows[:i], got[:i], want, column.upper(), at_row, earlier, j)


def classify(block: str, rows: list, got: list, diff) -> tuple:
    """The group of a trace's first difference: (the documented deviation's requirement, or
    None, and check's rules)."""
    dev = deviations.classify(case_of(block, rows, got, diff))
    return (dev.name if dev else None, key_of(diff))


def names_deciding(block: str, rows: list, got: list, diff):
    """Whether check names the requirement of the documented deviation at the first difference
    (at the row or at the earlier row), or None when no deviation explains it."""
    case = case_of(block, rows, got, diff)
    dev = deviations.classify(case)
    return None if dev is None else dev.rule in case.named


def group_key(cls: tuple) -> tuple:
    """A documented deviation is one group whatever rules check names (they are counted
    inside it); an undocumented difference is grouped by check's rules."""
    return (cls[0], None) if cls[0] else cls


def shrink(block: str, rows: list, key: tuple) -> list:
    """A short trace whose first difference falls in the same group (same deviation, same
    rules from check): the prefix up to the first difference, then rows removed one at a time
    while that still holds."""

    def reproduces(candidate: list):
        if not candidate:
            return None
        got = awl.run(block, candidate)
        d = explain(block, candidate, got)
        if d is not None and group_key(classify(block, candidate, got, d)) == key:
            return candidate[: d.line - 1]
        return None

    best = reproduces(rows)
    if best is None:  # cannot happen: rows reproduce by construction
        raise AssertionError(f"{block}: the trace no longer reproduces {key}")
    if "t_ms" in best[0]:
        # Earlier times: shift by a multiple of 10 s (S5 ticks of every base stay in place).
        shift = int(best[0]["t_ms"]) // 10000 * 10000
        if shift:
            moved = reproduces([{**r, "t_ms": int(r["t_ms"]) - shift} for r in best])
            if moved is not None:
                best = moved
    changed = True
    while changed:
        changed = False
        for i in range(len(best) - 1, -1, -1):
            if i >= len(best):
                continue
            shorter = reproduces(best[:i] + best[i + 1:])
            if shorter is not None:
                best, changed = shorter, True
    return best


@dataclass
class Group:
    block: str
    key: tuple  # group_key: (documented deviation, None) or (None, check's rules)
    by_rules: dict = field(default_factory=dict)  # check's rules -> [traces, rows]
    traces: int = 0
    rows: int = 0
    example: list = field(default_factory=list)
    example_name: str = ""
    example_line: int = 0
    message: str = ""
    column: str = ""
    minimal: list = field(default_factory=list)


@dataclass
class BlockStats:
    traces: int = 0
    rows: int = 0
    differing_rows: int = 0
    differing_traces: int = 0
    named: int = 0  # differing traces where check names the deviation's requirement


def fmt(col: str, v) -> str:
    if isinstance(v, bool):
        return "1" if v else "0"
    if col.upper() in reference.WORD_OUTPUTS:
        return f"W#16#{v:04X}"
    return str(v)


def table(block: str, rows: list) -> list:
    """A minimal trace as CSV lines: the inputs, then awlsim's and the reference's outputs."""
    got = awl.run(block, rows)
    want = reference.run(block, rows, **preset_kw(block))
    ins = list(rows[0])
    outs = list(got[0])
    lines = [",".join(ins + [f"awlsim {c}" for c in outs] + [f"ref {c}" for c in outs])]
    for r, g, w in zip(rows, got, want):
        mark = "" if g == w else "   <- differs"
        lines.append(",".join([fmt(c, r[c]) for c in ins] + [fmt(c, g[c]) for c in outs]
                              + [fmt(c, w[c]) for c in outs]) + mark)
    return lines


def main(argv=None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--vectors", type=Path, required=True,
                    help="the directory `plc-timers vectors DIR` wrote")
    ap.add_argument("--random", type=int, default=200, help="random traces per block")
    ap.add_argument("--seed", type=int, default=26)
    ap.add_argument("--report", type=Path, default=REPO / "docs" / "conformance" / "awlsim.md")
    ap.add_argument("--blocks", default=",".join(traces.BLOCKS))
    ap.add_argument("--named", action="store_true",
                    help="also print, per block, how often check names the documented "
                         "deviation's requirement at the first difference (not in the report)")
    args = ap.parse_args(argv)

    bad = deviations.verify(REPO)
    if bad:
        print("deviations.py cites no awlsim paragraph for:\n  " + "\n  ".join(bad),
              file=sys.stderr)
        return 1
    blocks = [b.strip().upper() for b in args.blocks.split(",") if b.strip()]
    unknown = [b for b in blocks if b not in traces.BLOCKS]
    if unknown:
        print(f"unknown block(s) {unknown}; awlsim runs {', '.join(traces.BLOCKS)}",
              file=sys.stderr)
        return 2
    if not args.vectors.is_dir():
        print(f"--vectors {args.vectors}: not a directory (write it with `plc-timers vectors "
              f"DIR`)", file=sys.stderr)
        return 2

    started = time.monotonic()
    rng = random.Random(args.seed)
    work = [t for t in traces.vector_traces(args.vectors) if t[0] in blocks]
    for block in blocks:
        for i in range(args.random):
            work.append((block, f"random seed {args.seed} #{i}",
                         traces.random_trace(block, rng, rng.choice([8, 20, 30, 40]))))

    stats = {b: BlockStats() for b in blocks}
    groups: dict = {}
    for block, name, rows in work:
        got, _want, first, n_diff = first_difference(block, rows)
        st = stats[block]
        st.traces += 1
        st.rows += len(rows)
        if first is None:
            continue
        st.differing_rows += n_diff
        st.differing_traces += 1
        d = explain(block, rows, got)
        if d is None or d.line != first + 2:
            print(f"{block} {name}: check disagrees with run on the first difference "
                  f"(run: line {first + 2}, check: {d})", file=sys.stderr)
            return 1
        cls = classify(block, rows, got, d)
        if args.named:
            hit = names_deciding(block, rows, got, d)
            st.named += hit is True
        key = group_key(cls)
        g = groups.setdefault((block, key), Group(block, key))
        sub = g.by_rules.setdefault(cls[1], [0, 0])
        sub[0] += 1
        sub[1] += n_diff
        g.traces += 1
        g.rows += n_diff
        if not g.example or first + 1 < len(g.example):
            g.example, g.example_name, g.example_line = rows[: first + 1], name, first + 2
            g.message, g.column = named_text(key_of(d)), d.output

    failures = 0
    for g in groups.values():
        g.minimal = shrink(g.block, g.example, g.key)
        if g.key[0] is None:
            failures += 1
    write_report(args, blocks, stats, groups)
    for block in blocks:
        st = stats[block]
        print(f"{block:8} {st.traces:4} traces {st.rows:6} rows, {st.differing_rows:5} rows "
              f"differ in {st.differing_traces} traces")
    if args.named:
        total = sum(stats[b].differing_traces for b in blocks)
        named = sum(stats[b].named for b in blocks)
        for block in blocks:
            st = stats[block]
            if st.differing_traces:
                print(f"named {block:8} {st.named:4} of {st.differing_traces:4} "
                      f"({100 * st.named / st.differing_traces:.1f} %)")
        if total:
            print(f"named overall  {named} of {total} ({100 * named / total:.1f} %)")
    for g in groups.values():
        name = g.key[0] or "NOT DOCUMENTED (check: " + named_text(g.key[1]) + ")"
        print(f"  {g.block:8} {name}: {g.traces} traces, {g.rows} rows, minimal trace "
              f"{len(g.minimal)} rows")
    print(f"report: {args.report}  ({time.monotonic() - started:.0f} s, reference: "
          f"{reference.backend()})")
    if failures:
        print(f"{failures} group(s) of differences that spec/ does not document as awlsim "
              f"deviations: see the report", file=sys.stderr)
        return 1
    return 0


def write_report(args, blocks, stats, groups) -> None:
    from awlsim.common.version import VERSION_STRING

    out = ["# awlsim against the reference", "",
           "Generated by `conformance/awlsim/run.sh` (`runner.py --random "
           f"{args.random} --seed {args.seed}`); do not edit. awlsim {VERSION_STRING} from "
           "PyPI runs one STL program per block (`conformance/awlsim/program.py`), one OB1 "
           "cycle per trace row, on a virtual clock set to the row's `t_ms`; the reference is "
           "the crate's (`plc-timers run` and `check`, or the Python package). Traces: the "
           "shipped vectors (`plc-timers vectors`) and seeded random traces.", "",
           "Each trace that differs is classified by its first differing row: the requirements "
           "`check` names for the reference's output there, and the deviation that `spec/` "
           "documents for awlsim which explains it (`conformance/awlsim/deviations.py`, one "
           "entry per documented deviation with the spec paragraph and the condition). The "
           "later differing rows of a trace are counted in the same group: once the states "
           "part, they follow from the first difference. Each group shows the shortest trace "
           "found that reproduces it (prefix, then rows removed while the group stays the same).",
           "", "Not run: " + "; ".join(f"{k}: {v}" for k, v in traces.NOT_RUN.items()) + ".",
           "", "## Summary", "",
           "| block | traces | rows compared | rows differing | traces differing | groups: deviation (traces) |",
           "|---|---:|---:|---:|---:|---|"]
    for b in blocks:
        st = stats[b]
        per: dict = {}
        for g in groups.values():
            if g.block == b:
                name = g.key[0] or "UNDOCUMENTED"
                per[name] = per.get(name, 0) + g.traces
        names = "; ".join(f"{k} ({v})" for k, v in sorted(per.items())) or "none"
        out.append(f"| {b} | {st.traces} | {st.rows} | {st.differing_rows} | "
                   f"{st.differing_traces} | {names} |")
    total = sum(s.rows for s in stats.values())
    diff = sum(s.differing_rows for s in stats.values())
    undoc = [g for g in groups.values() if g.key[0] is None]
    out += ["", f"{total} rows compared, {diff} differ; {len(groups)} groups, "
            f"{len(undoc)} not documented in `spec/`.", "", "## Documented deviations", "",
            "| requirement | documented in | awlsim | traces |", "|---|---|---|---:|"]
    for d in deviations.DOCUMENTED:
        n = sum(g.traces for g in groups.values() if g.key[0] == d.name)
        out.append(f"| {d.name} | `{d.spec}`: {deviations.spec_row(REPO, d)} | "
                   f"{d.awlsim} | {n} |")
    out += ["", "## Groups", ""]
    order = sorted(groups.values(), key=lambda g: (blocks.index(g.block), g.key[0] or "~",
                                                   g.key[1] or ()))
    for g in order:
        dev, rules = g.key
        title = dev or f"UNDOCUMENTED (check: {named_text(rules)})"
        out.append(f"### {g.block}: {title}")
        out.append("")
        out.append(f"{g.traces} traces, {g.rows} differing rows. The requirements `check` "
                   "names at the first difference: " + "; ".join(
                       f"{named_text(r)} ({t} traces, {n} rows)"
                       for r, (t, n) in sorted(g.by_rules.items())) + ".")
        out.append("")
        out.append(f"Shortest first seen in `{g.example_name}`, line {g.example_line}, column "
                   f"{g.column}; `check` names there: {g.message}.")
        out.append("")
        if dev:
            d = next(x for x in deviations.DOCUMENTED if x.name == dev)
            out.append(f"Documented in `{d.spec}`, row \"{deviations.spec_row(REPO, d)}\" "
                       f"({dev}): awlsim {d.awlsim}.")
        else:
            out.append("**Not documented**: no entry of `conformance/awlsim/deviations.py` "
                       "explains this difference.")
        out += ["", f"Minimal trace ({len(g.minimal)} rows):", "", "```",
                *table(g.block, g.minimal), "```", ""]
    args.report.parent.mkdir(parents=True, exist_ok=True)
    args.report.write_text("\n".join(out), encoding="utf-8")


if __name__ == "__main__":
    sys.exit(main())
