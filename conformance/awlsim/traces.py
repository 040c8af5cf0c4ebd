"""The traces the runner replays: the shipped vectors (``plc-timers vectors DIR``) and seeded
random traces per block, shaped like the vectors (edges clustered, time steps around the ticks
of the time base and around the preset, presets at edge values, presets changing mid-run)."""

from __future__ import annotations

import csv
import random
from pathlib import Path

import program
import reference

#: The blocks awlsim can run (program.layout) in the order of the catalog; IEC counters as INT.
BLOCKS = ["S_PULSE", "S_PEXT", "S_ODT", "S_ODTS", "S_OFFDT", "TP", "TON", "TOF",
          "CTU", "CTD", "CTUD", "S_CU", "S_CD", "S_CUD"]
#: What the vectors hold that awlsim cannot run, and why (reported, not compared).
NOT_RUN = {
    "TONR": "awlsim has no TONR (its IEC blocks are the S7-300/400 SFB 0..5)",
    "IEC counters other than INT": "awlsim's SFB 0, 1, 2 have an INT PV and CV only",
    "the RT coil": "awlsim's SFB 3, 4, 5 have no -(RT)- coil (S7-300/400), so the rows of a "
                   "vector from its first row with RT = 1 on are not run",
}

#: The coil column of the IEC timers' vectors (spec/cli.md, "Traces"), which awlsim cannot run.
COIL = "RT"


def read_csv(path: Path) -> list:
    """The records of a trace file as dicts (comment and blank lines skipped)."""
    with open(path, newline="", encoding="utf-8") as f:
        lines = [ln for ln in f if ln.strip() and not ln.lstrip().startswith("#")]
    return [dict(r) for r in csv.DictReader(lines)]


def _cell(text: str):
    """A vector's cell as a row value: integers (t_ms, booleans, numeric presets) as int,
    literals (S5T#…, T#…, C#…, W#16#…) as written."""
    t = text.strip()
    if t.lower() in ("true", "false"):
        return int(t.lower() == "true")
    try:
        return int(t)
    except ValueError:
        return t


def vector_traces(vectors: Path) -> list:
    """(block, name, rows with the inputs and the preset) for every vector awlsim can run."""
    out = []
    for block in BLOCKS:
        folder = vectors / (f"{block}-INT" if block.startswith("CT") else block)
        for path in sorted(folder.glob("*.csv")):
            rows = [{k: _cell(v) for k, v in r.items() if k.upper() not in reference.OUTPUTS}
                    for r in read_csv(path)]
            rows = before_coil(rows)
            if rows:
                out.append((block, f"vectors/{folder.name}/{path.name}", rows))
    return out


def before_coil(rows: list) -> list:
    """The rows before the first one with the RT coil at 1, without the RT column: what awlsim
    can run of a vector (NOT_RUN); the rows after it depend on the coil's effect."""
    out = []
    for r in rows:
        if r.get(COIL, 0):
            break
        out.append({k: v for k, v in r.items() if k != COIL})
    return out


#: The chance of R, LD or FR being 1 in a row.
PULSE = 0.1


def _flip(rng: random.Random, v: int, p: float) -> int:
    return 1 - v if rng.random() < p else v


def random_trace(block: str, rng: random.Random, n_rows: int = 30) -> list:
    """One random trace of ``block``: rows with ``t_ms`` (timers), the inputs and the preset."""
    lay = program.layout(block)
    inputs = list(lay.bits)
    preset_col = lay.preset[0]
    if block in program.S5_TIMER_OPS:
        base = rng.choice([10, 10, 100, 1000, 10000])
        code = {10: 0, 100: 1, 1000: 2, 10000: 3}[base]
        presets = [f"W#16#{code}{rng.choice([0, 0, 1, 1, 2, 3, 5, 9, 12]):03d}" for _ in range(2)]
        steps = [0, 1, base // 2, base - 1, base, base + 1, 2 * base, 3 * base, 5 * base]
        probs = {"S": 0.35}
    elif block in ("TP", "TON", "TOF"):
        pt = rng.choice([0, 1, 2, 5, 10, 10, 30, 100, 1000])
        presets = [pt, rng.choice([0, 1, 5, 10, 30, 100, -1])]
        steps = [0, 1, 2, pt // 2, pt - 1, pt, pt + 1, 2 * pt, 7]
        probs = {"IN": 0.35}
    elif block.startswith("CT"):
        presets = [rng.choice([0, 1, 2, 3, 5, -1, 32767, -32768]) for _ in range(2)]
        steps = [1]
        probs = {"CU": 0.45, "CD": 0.45}
    else:
        presets = [f"C#{rng.choice([0, 1, 2, 3, 5, 998, 999])}" for _ in range(2)]
        steps = [1]
        probs = {"CU": 0.45, "CD": 0.45, "S": 0.3}
    change = rng.random() < 0.3  # a preset change somewhere in the trace
    t = rng.choice([0, 0, 3, 5])
    state = {c: 0 for c in inputs}
    rows = []
    for i in range(n_rows):
        for c in inputs:
            if c in probs:  # a signal: changes now and then, so levels are held
                state[c] = _flip(rng, state[c], probs[c])
            else:  # R, LD, FR: short pulses
                state[c] = int(rng.random() < PULSE)
        row = {"t_ms": t, **state}
        row[preset_col] = presets[1] if change and i >= n_rows // 2 else presets[0]
        rows.append(row)
        t += max(0, rng.choice(steps))
    return rows
