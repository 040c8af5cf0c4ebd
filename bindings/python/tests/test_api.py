"""The Python API: blocks, memory areas, literals, banks and traces, against the manual's
behaviour as the crate states it (spec/) and against each other (a memory area or a bank lane
is the block called alone)."""

from __future__ import annotations

import doctest
import random
import runpy
import subprocess
import sys
from pathlib import Path
from typing import List

import numpy as np
import plc_timers
import pytest

HERE = Path(__file__).resolve().parent


def test_doctests() -> None:
    result = doctest.testmod(plc_timers, optionflags=doctest.ELLIPSIS)
    assert result.attempted >= 40
    assert result.failed == 0


def test_readme_block_is_the_example() -> None:
    """The repository README's Python block is examples/readme.py, which the next test runs."""
    readme = (HERE.parents[2] / "README.md").read_text()
    block = readme.split("```python\n", 1)[1].split("```", 1)[0]
    assert block == (HERE.parent / "examples" / "readme.py").read_text()


def test_readme_example_prints_its_comments() -> None:
    """examples/readme.py (the README's example) prints what its comments say."""
    path = HERE.parent / "examples" / "readme.py"
    done = subprocess.run([sys.executable, str(path)], capture_output=True, text=True, check=True)
    promised = [
        line.split("  # ", 1)[1].strip()
        for line in path.read_text().splitlines()
        if line.startswith("print(") and "  # " in line
    ]
    assert len(promised) == 3
    assert done.stdout.splitlines() == promised


# ---------------------------------------------------------------------------------------------
# Blocks


def test_ton_sequence() -> None:
    """TON (S7-1200 manual, Table 8-20): Q rises in the call where ET reaches PT; IN = 0 resets."""
    for optimized in (False, True):
        t = plc_timers.TON(pt="T#500ms", optimized=optimized)
        outs = [(o.q, o.et) for o in (t.call(ms, in_=i) for ms, i in
                [(1000, True), (1499, True), (1500, True), (2000, True), (2100, False)])]
        assert outs == [(False, 0), (False, 499), (True, 500), (True, 500), (False, 0)]


def test_outputs_are_immutable_values() -> None:
    t = plc_timers.TON(pt=500)
    o = t.call(0, in_=True)
    with pytest.raises(AttributeError):
        o.q = True  # type: ignore[misc]
    assert o == plc_timers.TON(pt=500).call(0, in_=True)
    assert hash(o) == hash(plc_timers.TON(pt=500).call(0, in_=True))
    assert repr(o) == "IecOutput(q=False, et=0)"


def test_iec_coils_and_reads() -> None:
    for optimized in (False, True):
        t = plc_timers.TON(pt="T#1S", optimized=optimized)
        t.call(0, in_=True)
        assert t.read_et(400) == 400  # update on access (IEC-ACCESS-01)
        t.reset_timer()  # RT coil
        assert (t.read_q(2000), t.read_et(2000)) == (False, 0)
        t.preset_timer("T#2S")  # PT coil
        t.run_stop_run(retentive=False)


def test_tonr_has_r_and_ton_has_not() -> None:
    t = plc_timers.TONR(pt=100)
    t.call(0, in_=True)
    assert t.call(60, in_=False).et == 60
    assert t.call(70, in_=False, r=True).et == 0
    with pytest.raises(ValueError, match="TON has no R input; its inputs are IN, PT"):
        plc_timers.TON(pt=100).call(0, in_=True, r=True)


def test_s5_timer_tv_forms() -> None:
    """TV as a literal, a word (W#16#0005: 5 x 10 ms) and an S5Time give the same timer."""
    for tv in ("S5T#50MS", 0x0005, plc_timers.S5Time.parse("W#16#0005")):
        t = plc_timers.S_ODT(tv=tv)
        assert not t.call(0, s=True).q
        assert t.call(50, s=True).q


def test_counters() -> None:
    c = plc_timers.CTUD(pv=2, type="SINT")
    assert c.type == "SINT"
    for _ in range(200):
        c.call(cu=True)
        c.call()
    assert c.call().cv == 127  # saturates at the type's maximum (CNT-SAT-01)
    with pytest.raises(ValueError, match="CTU has no CD input"):
        plc_timers.CTU(pv=1).call(cd=True)
    with pytest.raises(ValueError, match=r"pv is an int of SINT, -128..=127; got 300"):
        plc_timers.CTU(pv=300, type="SINT")
    s = plc_timers.S_CUD(pv="C#998")
    s.call(s=True)
    for _ in range(3):
        s.call(cu=True)
        s.call()
    assert s.call().cv == 999  # no wrap at 999


def test_timer_memory_is_the_block() -> None:
    """A timer of the memory area called as a box behaves as the block object."""
    rng = random.Random(7)
    area = plc_timers.TimerMemory(64)
    blocks = {k: plc_timers.S_ODT(tv="S5T#120MS", optimized=True) for k in (0, 63)}
    now = 0
    for _ in range(300):
        now += rng.randrange(0, 40)
        for k, b in blocks.items():
            s, r = rng.random() < 0.7, rng.random() < 0.05
            assert area.call(k, "SD", now, s=s, r=r, tv="S5T#120MS") == b.call(now, s=s, r=r)
    with pytest.raises(IndexError, match="no timer T 64: this area has T 0 to T 63"):
        area.status(64)
    with pytest.raises(ValueError, match="not an area size"):
        plc_timers.TimerMemory(100)


def test_counter_memory_is_the_block() -> None:
    rng = random.Random(8)
    area = plc_timers.CounterMemory(64)
    block = plc_timers.S_CUD(pv="C#5")
    for _ in range(300):
        cu, cd, s, r = (rng.random() < 0.5 for _ in range(4))
        got = area.call(9, "S_CUD", cu=cu, cd=cd, s=s, r=r, pv="C#5")
        assert got == block.call(cu=cu, cd=cd, s=s, r=r)
        assert area.output(9) == got
        assert (area.load(9), area.status(9)) == (got.cv, got.q)


# ---------------------------------------------------------------------------------------------
# Literals


def test_literal_error_carries_kind_and_position() -> None:
    with pytest.raises(plc_timers.LiteralError) as e:
        plc_timers.Time.parse("T#5S_75M")
    assert (e.value.kind, e.value.position, e.value.literal) == ("UnitOrder", 7, "TIME")
    assert isinstance(e.value, ValueError)
    with pytest.raises(plc_timers.LiteralError) as e:
        plc_timers.S5Time.parse("W#16#00A1")
    assert (e.value.kind, e.value.position) == ("BcdDigit", "W#16#00A1".index("A"))
    with pytest.raises(plc_timers.LiteralError) as e:
        plc_timers.CounterPreset.parse("C#1000")
    assert (e.value.kind, e.value.position, e.value.literal) == ("OutOfRange", None, "C#")


def test_bad_arguments_say_what_is_allowed() -> None:
    with pytest.raises(TypeError, match="tv is an S5TIME"):
        plc_timers.S_ODT(tv=1.5)  # type: ignore[arg-type]
    with pytest.raises(ValueError, match="now_ms is the CPU time in whole milliseconds"):
        plc_timers.TON(pt=1).call(-1)
    t = plc_timers.TON(pt=1)
    t.call(10)
    with pytest.raises(ValueError, match="now_ms goes backwards: 5 after 10"):
        t.call(5)
    with pytest.raises(ValueError, match="TON needs its pt"):
        plc_timers.TON().call(0)
    with pytest.raises(ValueError, match="CTU does not take the data type WORD; it takes SINT INT"):
        plc_timers.CTU(pv=1, type="WORD")


# ---------------------------------------------------------------------------------------------
# Banks


def test_ton_bank_lanes_are_ton_blocks() -> None:
    n = 2 * 1024 + 37  # two full chunks and a padded one
    rng = np.random.default_rng(3)
    bank = plc_timers.TonBank(n)
    watched = [0, 1023, 1024, 2048, n - 1]
    blocks = {i: plc_timers.TON() for i in watched}
    pt = rng.integers(-5, 300, n).astype(np.int32)
    now = 0
    for _ in range(200):
        now += int(rng.integers(0, 60))
        inputs = rng.random(n) < 0.8
        q, et = bank.scan(now, inputs, pt)
        assert q.dtype == np.bool_ and et.dtype == np.int32 and len(q) == n
        for i, b in blocks.items():
            o = b.call(now, in_=bool(inputs[i]), pt=int(pt[i]))
            assert (bool(q[i]), int(et[i])) == (o.q, o.et)
            assert bank.output(i) == o
    q2, et2 = np.zeros(n, np.bool_), np.zeros(n, np.int32)
    res = bank.scan(now, inputs, pt, out=(q2, et2))
    assert res[0] is q2 and res[1] is et2


def test_ton_bank_rejects_bad_arrays() -> None:
    bank = plc_timers.TonBank(4)
    ok_in, ok_pt = np.zeros(4, np.bool_), np.zeros(4, np.int32)
    with pytest.raises(TypeError, match=r"pt is a 1-D contiguous numpy array of int32 with 4"):
        bank.scan(0, ok_in, np.zeros(4, np.int64))
    with pytest.raises(ValueError, match="got 5 elements"):
        bank.scan(0, np.zeros(5, np.bool_), ok_pt)
    with pytest.raises(ValueError, match="non-contiguous"):
        bank.scan(0, np.zeros(8, np.bool_)[::2], ok_pt)
    with pytest.raises(ValueError, match="n is the number of lanes"):
        plc_timers.TonBank(0)


def test_counter_bank_lanes_are_ctud_blocks() -> None:
    n = 1500
    rng = np.random.default_rng(4)
    for int_type, dtype in (("INT", np.int16), ("USINT", np.uint8), ("LINT", np.int64)):
        bank = plc_timers.CounterBank(n, type=int_type)
        watched = [0, 1023, 1024, n - 1]
        blocks = {i: plc_timers.CTUD(type=int_type) for i in watched}
        for _ in range(300):
            cu, cd = rng.random(n) < 0.5, rng.random(n) < 0.3
            r, ld = rng.random(n) < 0.02, rng.random(n) < 0.02
            qu, qd, cv = bank.scan(cu=cu, cd=cd, r=r, ld=ld, pv=5)
            assert cv.dtype == dtype
            for i, b in blocks.items():
                o = b.call(cu=bool(cu[i]), cd=bool(cd[i]), r=bool(r[i]), ld=bool(ld[i]), pv=5)
                assert (bool(qu[i]), bool(qd[i]), int(cv[i])) == (o.qu, o.qd, o.cv)


# ---------------------------------------------------------------------------------------------
# Traces


def test_run_rows_as_tuples_or_dicts() -> None:
    rows: List[tuple[int, bool]] = [(0, True), (300, True), (500, True), (600, False)]
    by_tuple = plc_timers.run("TON", rows, columns=["t_ms", "IN"], pt="T#500ms")
    by_dict = plc_timers.run("TON", [{"t_ms": t, "IN": i} for t, i in rows], pt=500)
    assert by_tuple == by_dict
    assert [r["Q"] for r in by_tuple] == [False, False, True, False]


def test_trace_errors_name_line_and_column() -> None:
    with pytest.raises(plc_timers.TraceError) as e:
        plc_timers.run("TON", [{"t_ms": 0, "IN": 1}, {"t_ms": 5, "IN": "maybe"}], pt=1)
    assert (e.value.line, e.value.column, e.value.column_name) == (3, 2, "IN")
    assert "is not a boolean; use 0, 1, true or false" in e.value.message
    with pytest.raises(plc_timers.TraceError) as e:
        plc_timers.run("TON", [{"t_ms": 0, "IN": 1.5}], pt=1)  # type: ignore[dict-item]
    assert (e.value.line, e.value.column) == (2, 2)
    with pytest.raises(plc_timers.TraceError) as e:
        plc_timers.run("TON", [{"t_ms": 0, "IN": 1}], pt="T#1.5S")
    assert e.value.option == "pt"
    with pytest.raises(plc_timers.TraceError, match="unknown block `TONX`"):
        plc_timers.run("TONX", [{"t_ms": 0}])
    with pytest.raises(plc_timers.TraceError, match="the row has the keys"):
        plc_timers.run("TON", [{"t_ms": 0, "IN": 1}, {"t_ms": 1}], pt=1)


def test_rt_column_is_the_rt_coil_before_the_call() -> None:
    """A trace's RT column (spec/cli.md, "Traces") is the -(RT)- coil run before the box call of
    its row: `run` gives what the block object gives with `reset_timer()` before `call`, and
    `check` names IEC-RT-01 at a row with RT = 1 whose outputs ignore the coil."""
    rows = [(0, 0, 0), (100, 1, 0), (300, 1, 0), (350, 1, 1), (500, 1, 0), (850, 1, 0)]
    for block in ("TP", "TON", "TOF", "TONR"):
        for optimized in (False, True):
            got = plc_timers.run(
                block, rows, columns=["t_ms", "IN", "RT"], pt=500, optimized=optimized
            )
            timer = getattr(plc_timers, block)(pt=500, optimized=optimized)
            want: list[dict[str, bool | int]] = []
            for t, in_, rt in rows:
                if rt:
                    timer.reset_timer()
                o = timer.call(t, in_=bool(in_))
                want.append({"Q": o.q, "ET": o.et})
            assert got == want, (block, optimized)
    # A TON port that ignores RT goes on timing from 100 ms: ET 250 where the reference has 0.
    port = [(0, 0, 0, 0, 0), (100, 1, 0, 0, 0), (300, 1, 0, 0, 200), (350, 1, 1, 0, 250)]
    d = plc_timers.check("TON", port, columns=["t_ms", "IN", "RT", "Q", "ET"], pt=500)
    assert d is not None
    assert (d.line, d.output, d.expected, d.actual) == (5, "ET", 0, 250)
    assert "IEC-RT-01" in d.rules
    with pytest.raises(plc_timers.TraceError) as e:
        plc_timers.run("CTU", [(1, 1)], columns=["CU", "RT"], pv=3)
    assert (e.value.line, e.value.column, e.value.column_name) == (1, 2, "RT")
    assert "only TP, TON, TOF, TONR have" in e.value.message


def test_readme_example_runs_in_process() -> None:
    runpy.run_path(str(HERE.parent / "examples" / "readme.py"), run_name="__main__")


def test_check_some_outputs_and_tuples() -> None:
    """`outputs=` compares only those outputs; a trace without the others is then complete."""
    rows = [(0, 1, 0), (500, 1, 1), (700, 0, 1)]
    d = plc_timers.check("TON", rows, columns=["t_ms", "IN", "Q"], outputs=["Q"], pt=500)
    assert d is not None
    assert (d.line, d.column, d.output, d.expected, d.actual) == (4, 3, "Q", False, True)
    assert d.message.startswith("DIFFERENT at line 4, column 3 (Q)")
    # IN falls at line 4: TON-IN-01 resets Q there; the Q = 1 the trace keeps was made by the
    # expiry at line 3 (500 ms = PT), which still matters.
    assert d.rules == ["TON-IN-01"]
    assert (d.earlier_line, d.earlier_rules) == (3, ["IEC-EXPIRY-01"])
    with pytest.raises(plc_timers.TraceError, match="the trace has no `ET` column"):
        plc_timers.check("TON", rows, columns=["t_ms", "IN", "Q"], pt=500)
    with pytest.raises(plc_timers.TraceError) as e:
        plc_timers.check("TON", rows, columns=["t_ms", "IN", "Q"], outputs=["CV"], pt=500)
    assert e.value.option == "outputs"


def test_bank_output_that_is_an_input_fails_before_the_scan() -> None:
    bank = plc_timers.TonBank(4)
    inputs, pt = np.ones(4, np.bool_), np.full(4, 100, np.int32)
    with pytest.raises(ValueError, match="cannot be written now"):
        bank.scan(0, inputs, pt, out=(inputs, np.zeros(4, np.int32)))
    assert bank.output(0).et == 0
    q, et = bank.scan(50, inputs, pt)  # the failed call started nothing: this is the first start
    assert et.tolist() == [0, 0, 0, 0]
    counters = plc_timers.CounterBank(4)
    with pytest.raises(ValueError, match="cannot be written now"):
        counters.scan(pv=1, cu=inputs, out=(inputs, np.zeros(4, np.bool_), np.zeros(4, np.int16)))
    assert counters.scan(pv=1)[2].tolist() == [0, 0, 0, 0]


def test_operand_numbers_are_checked() -> None:
    area = plc_timers.CounterMemory(64)
    with pytest.raises(ValueError, match="index is an operand number, 0 and up"):
        area.load(-1)
    with pytest.raises(TypeError, match="index is an operand number"):
        area.load("C 1")  # type: ignore[arg-type]
    with pytest.raises(IndexError, match="no counter C 64: this area has C 0 to C 63"):
        area.cu(64, True)
