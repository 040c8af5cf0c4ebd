"""The S7-1500 long IEC timers (`TP`, `TON`, `TOF`, `TONR` with `type="LTIME"`): the clock, PT and
ET in nanoseconds; `LTime` beside `Time`; bad input.

The oracle of the behaviour is independent of the LTIME code path: the same call sequence run on
the TIME timer in milliseconds and on the LTIME timer in nanoseconds (every time and preset times
10**6) must give the same Q and ET times 10**6, since the rules of the four instructions do not
depend on the unit (LTIMER-SAME-01). Values past TIME's range are checked against arithmetic on
the literal's definition."""

from __future__ import annotations

import copy
import pickle
from typing import Any, Callable, List, Tuple

import numpy as np
import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

import plc_timers
from plc_timers import LiteralError, LTime, Time

IEC_TIMERS: List[Callable[..., Any]] = [plc_timers.TP, plc_timers.TON, plc_timers.TOF,
                                        plc_timers.TONR]
NS_PER_MS = 10**6
DAY_NS = 86_400 * 10**9
many = settings(max_examples=150, deadline=None, suppress_health_check=[HealthCheck.too_slow])

ops = st.lists(
    st.tuples(st.integers(0, 5000), st.booleans(), st.booleans(), st.integers(-100, 4000),
              st.sampled_from(["call", "rt", "pt", "read", "stop"])),
    max_size=60,
)


@many
@given(block=st.sampled_from(IEC_TIMERS), optimized=st.booleans(), calls=ops,
       start=st.integers(0, 2**33))
def test_ltime_timer_is_the_time_timer_in_nanoseconds(
    block: Callable[..., Any], optimized: bool, calls: List[Tuple[int, bool, bool, int, str]],
    start: int,
) -> None:
    ms = block(optimized=optimized)
    ns = block(type="LTIME", optimized=optimized)
    tonr = block is plc_timers.TONR
    now = start
    for dt, i, r, pt, op in calls:
        now += dt
        r = r and tonr
        if op == "call":
            a = ms.call(now, in_=i, r=r, pt=pt)
            b = ns.call(now * NS_PER_MS, in_=i, r=r, pt=pt * NS_PER_MS)
            assert (b.q, b.et) == (a.q, a.et * NS_PER_MS), (
                f"LTIMER-SAME-01: {block.__name__} at {now} ms: LTIME {b}, TIME {a}")
        elif op == "rt":
            ms.reset_timer()
            ns.reset_timer()
        elif op == "pt":
            ms.preset_timer(pt)
            ns.preset_timer(pt * NS_PER_MS)
        elif op == "stop":
            ms.run_stop_run(i)
            ns.run_stop_run(i)
        else:
            a_q, a_et = ms.read_q(now), ms.read_et(now)
            b_q, b_et = ns.read_q(now * NS_PER_MS), ns.read_et(now * NS_PER_MS)
            assert (b_q, b_et) == (a_q, a_et * NS_PER_MS), (
                f"LTIMER-SAME-01: {block.__name__} read at {now} ms")


@many
@given(block=st.sampled_from(IEC_TIMERS),
       calls=st.lists(st.tuples(st.integers(0, 2**40), st.booleans(), st.booleans(),
                                st.integers(-(2**40), 2**42)), max_size=40))
def test_ltime_reference_is_optimized(
    block: Callable[..., Any], calls: List[Tuple[int, bool, bool, int]]
) -> None:
    ref, opt = block(type="LTIME"), block(type="LTIME", optimized=True)
    r_ok = block is plc_timers.TONR
    now = 0
    for dt, i, r, pt in calls:
        now += dt
        got = (ref.call(now, in_=i, r=r and r_ok, pt=pt), opt.call(now, in_=i, r=r and r_ok, pt=pt))
        assert got[0] == got[1], f"IEC-EQUIV-02: {block.__name__} LTIME at {now} ns"


def test_ton_ltime_expires_at_its_preset_in_nanoseconds() -> None:
    for optimized in (False, True):
        t = plc_timers.TON(pt="LT#1ms500us", type="LTIME", optimized=optimized)
        assert t.call(0, in_=True) == plc_timers.IecOutput(q=False, et=0)
        # 1 ms 500 us = 1_500_000 ns (LTIME-LIT-01); Q rises when ET reaches PT (IEC-EXPIRY-01).
        assert t.call(1_499_999, in_=True) == plc_timers.IecOutput(q=False, et=1_499_999), \
            "IEC-EXPIRY-01: one ns before PT"
        assert t.call(now_ns=1_500_000, in_=True) == plc_timers.IecOutput(q=True, et=1_500_000), \
            "IEC-EXPIRY-01: at PT"
        assert t.read_et(now_ns=9_000_000) == 1_500_000, "IEC-ET-RANGE-01: ET stops at PT"


def test_presets_and_gaps_past_times_range() -> None:
    """LT#30D is past TIME's 2**31 ms (about 24.8 days); a gap of 50 days is past the 2**32 ms
    after which the TIME clock wraps (IEC-WRAP-01): the LTIME timer times them exactly."""
    thirty_days = 30 * DAY_NS
    assert thirty_days > (2**31 - 1) * NS_PER_MS
    ton = plc_timers.TON(pt="LT#30D", type="LTIME")
    ton.call(0, in_=True)
    assert ton.call(thirty_days - 1, in_=True).q is False, "IEC-EXPIRY-01: LT#30D less 1 ns"
    assert ton.call(thirty_days, in_=True) == plc_timers.IecOutput(q=True, et=thirty_days), \
        "IEC-EXPIRY-01: LT#30D"
    tp = plc_timers.TP(pt="LTIME#60D", type="LTIME")
    tp.call(0, in_=True)
    fifty_days = 50 * DAY_NS
    assert fifty_days > 2**32 * NS_PER_MS
    assert tp.call(fifty_days, in_=True) == plc_timers.IecOutput(q=True, et=fifty_days), \
        "IEC-WRAP-01: a 50-day gap on the 64-bit nanosecond clock"


@pytest.mark.parametrize("optimized", [False, True])
def test_boolean_inputs_as_every_numpy_byte(optimized: bool) -> None:
    """IN and R given as numpy bools viewed from every byte 0x00-0xFF: the call is the one with
    the Python bool numpy reads (non-zero is True)."""
    flags = np.arange(256, dtype=np.uint8).view(np.bool_)
    for b in range(256):
        got = plc_timers.TONR(pt=5, type="LTIME", optimized=optimized)
        want = plc_timers.TONR(pt=5, type="LTIME", optimized=optimized)
        for now in (0, 3, 7):
            a = got.call(now, in_=flags[b], r=flags[b] and now == 7)
            e = want.call(now, in_=b != 0, r=b != 0 and now == 7)
            assert a == e, f"TONR-IN-01: byte {b:#04x} at {now} ns"


def test_ltime_literals() -> None:
    t = LTime.parse("LT#1ms500us")
    assert t.nanos == 1_500_000, "LTIME-LIT-01: LT#1ms500us"
    assert str(t) == "LT#1MS_500US", "LTIME-LIT-01: the canonical literal"
    assert LTime.parse(str(t)) == t and LTime.from_nanos(t.nanos) == t
    assert LTime.parse("LTIME#-1D").nanos == -DAY_NS, "LTIME-LIT-01: LTIME# and a sign"
    assert LTime.from_nanos(-(2**63)).nanos == -(2**63), "LTIME-RANGE-01: the lowest value"
    assert pickle.loads(pickle.dumps(t)) == t and copy.copy(t) == t
    assert LTime.parse("1") < t
    with pytest.raises(LiteralError, match="LTIME") as e:
        LTime.parse("LT#106751D_23H_47M_16S_854MS_775US_808NS")
    assert e.value.kind == "OutOfRange", "LTIME-RANGE-01: one past the highest value"
    with pytest.raises(ValueError, match=r"-9223372036854775808\.\.=9223372036854775807"):
        LTime.from_nanos(2**63)


@given(ns=st.integers(-(2**63), 2**63 - 1))
@settings(max_examples=200, deadline=None, suppress_health_check=[HealthCheck.too_slow])
def test_ltime_round_trips(ns: int) -> None:
    t = LTime.from_nanos(ns)
    assert LTime.parse(str(t)) == t, f"LTIME-LIT-01: {t} back to {ns}"
    assert LTime.parse(str(ns)).nanos == ns


def test_copy_and_pickle_keep_the_data_type_and_state() -> None:
    for block in IEC_TIMERS:
        for optimized in (False, True):
            t = block(pt="LT#40D", type="LTIME", optimized=optimized)
            t.call(0, in_=True)
            t.call(DAY_NS, in_=False)
            copies: List[Any] = [copy.copy(t), copy.deepcopy(t), pickle.loads(pickle.dumps(t))]
            for c in copies:
                assert c.type == "LTIME" and c.optimized is optimized and repr(c) == repr(t)
                assert c.call(3 * DAY_NS, in_=True) == copy.copy(t).call(3 * DAY_NS, in_=True)
            with pytest.raises(ValueError, match="goes backwards"):
                pickle.loads(pickle.dumps(t)).call(DAY_NS - 1)


def test_a_pickled_preset_outside_the_data_type_is_refused() -> None:
    ton = plc_timers.TON(pt=5)
    optimized, _, last, fields = ton.__reduce__()[2]
    with pytest.raises(ValueError, match="not a state of TON"):
        ton.__setstate__((optimized, 2**40, last, fields))  # PT past TIME's 2**31-1 ms
    lton = plc_timers.TON(type="LTIME")
    lton.__setstate__((optimized, 2**40, last, fields))  # the same PT is an LTIME one
    assert repr(lton) == 'TON(pt="LT#18M_19S_511MS_627US_776NS", type="LTIME", optimized=False)'


def test_type_is_checked_and_errors_name_what_is_allowed() -> None:
    assert plc_timers.TON().type == "TIME" and plc_timers.TON(type="ltime").type == "LTIME"
    with pytest.raises(ValueError, match="TON does not take the data type INT; it takes TIME LTIME"):
        plc_timers.TON(type="INT")
    with pytest.raises(ValueError, match="unknown data type `LTIMER`; TP takes TIME LTIME"):
        plc_timers.TP(type="LTIMER")


def test_a_literal_of_the_other_time_type_is_refused_with_a_hint() -> None:
    with pytest.raises(LiteralError, match=r'literal of TIME, which the block takes with type="TIME"'):
        plc_timers.TON(pt="T#5S", type="LTIME")
    with pytest.raises(LiteralError, match=r'literal of LTIME, which the block takes with type="LTIME"'):
        plc_timers.TOF(pt="LT#5S")
    lt = plc_timers.TONR(type="LTIME")
    with pytest.raises(LiteralError, match="LTIME"):
        lt.preset_timer("T#1S")
    with pytest.raises(LiteralError, match="LTIME"):
        lt.call(0, pt="TIME#1S")
    with pytest.raises(TypeError, match="is an LTIME.*got Time"):
        plc_timers.TP(pt=Time.parse("T#1S"), type="LTIME")
    with pytest.raises(TypeError, match='is a TIME.*type="LTIME".*got LTime'):
        plc_timers.TP(pt=LTime.parse("LT#1S"))


def test_out_of_range_and_wrong_types_say_what_is_allowed() -> None:
    with pytest.raises(ValueError, match=r"an LTIME in nanoseconds, .*got 9223372036854775808"):
        plc_timers.TON(pt=2**63, type="LTIME")
    with pytest.raises(LiteralError) as e:
        plc_timers.TON(pt="LT#106752D", type="LTIME")
    assert e.value.kind == "OutOfRange", "LTIME-RANGE-01"
    with pytest.raises(TypeError, match="is an LTIME"):
        plc_timers.TON(pt=True, type="LTIME")
    with pytest.raises(TypeError, match="is an LTIME"):
        plc_timers.TON(pt=1.5, type="LTIME")  # type: ignore[arg-type]
    t = plc_timers.TON(pt=10, type="LTIME")
    with pytest.raises(ValueError, match=r"now_ns is the CPU time in whole nanoseconds"):
        t.call(2**64)
    with pytest.raises(ValueError, match=r"now_ns is the CPU time in whole nanoseconds"):
        t.call(-1)


def test_the_clock_keyword_is_the_blocks_unit() -> None:
    lt, t = plc_timers.TON(pt=10, type="LTIME"), plc_timers.TON(pt=10)
    with pytest.raises(TypeError, match="TON LTIME runs on a clock in ns"):
        lt.call(now_ms=5)
    with pytest.raises(TypeError, match="TON TIME runs on a clock in ms"):
        t.call(now_ns=5)
    with pytest.raises(TypeError, match="once"):
        t.call(5, now_ms=5)
    with pytest.raises(TypeError, match="needs the CPU time"):
        lt.read_q()
    assert t.call(now_ms=10, in_=True).et == 0 and lt.call(now_ns=10, in_=True).et == 0
    with pytest.raises(ValueError, match="now_ns goes backwards: 9 after 10"):
        lt.read_et(9)


# --- the numpy bank on LTIME ---------------------------------------------------------------------


def test_ltime_ton_bank_lanes_are_ltime_ton_blocks() -> None:
    """IEC-BANK-01 on LTIME: every watched lane of an LTIME bank (full chunks and a padded one)
    equals an LTIME `TON` block called one scan at a time, with presets past TIME's range
    (up to LT#30D and beyond), negative ones and 0, and gaps of up to 2**40 ns."""
    n = 1024 + 37
    rng = np.random.default_rng(36)
    bank = plc_timers.TonBank(n, type="LTIME")
    assert (bank.type, len(bank), repr(bank)) == ("LTIME", n, f'TonBank({n}, type="LTIME")')
    watched = [0, 1, 1023, 1024, n - 1]
    blocks = {i: plc_timers.TON(type="LTIME") for i in watched}
    pt = np.concatenate([
        rng.integers(-5, 5, n // 4),
        rng.integers(0, 3 * 10**9, n // 4),
        rng.integers(2**31 * NS_PER_MS, 40 * DAY_NS, n // 4),
        rng.integers(-(2**62), 2**62, n - 3 * (n // 4)),
    ]).astype(np.int64)
    rng.shuffle(pt)
    pt[watched] = [0, 30 * DAY_NS, 1_500_000, -7, 2**63 - 1]
    now = 2**64 - 2**47  # 120 gaps of up to 2**40 ns: the scans end near the clock's top
    for k in range(120):
        now += int(rng.choice([0, int(rng.integers(1, 10**9)), int(rng.integers(0, 2**40))]))
        inputs = rng.random(n) < 0.85
        q, et = bank.scan(now, inputs, pt)
        assert q.dtype == np.bool_ and et.dtype == np.uint64 and len(et) == n
        for i, b in blocks.items():
            o = b.call(now, in_=bool(inputs[i]), pt=int(pt[i]))
            assert (bool(q[i]), int(et[i])) == (o.q, o.et), (
                f"IEC-BANK-01: LTIME lane {i}, scan {k} at {now} ns")
            assert bank.output(i) == o, f"IEC-BANK-01: output({i}) at {now} ns"
    q2, et2 = np.zeros(n, np.bool_), np.zeros(n, np.uint64)
    res = bank.scan(now, inputs, pt, out=(q2, et2))
    assert res[0] is q2 and res[1] is et2 and (q2 == q).all() and (et2 == et).all()


@many
@given(n=st.integers(1, 70), start=st.integers(0, 2**33), seed=st.integers(0, 2**32),
       scans=st.integers(1, 40))
def test_ltime_ton_bank_is_the_time_bank_in_nanoseconds(
    n: int, start: int, seed: int, scans: int
) -> None:
    """IEC-BANK-01 and LTIMER-SAME-01: the LTIME bank scanned at every time and with every
    preset of a TIME bank times 10**6 gives the TIME bank's Q and its ET times 10**6 (an
    oracle independent of the LTIME code path). The steps stay below 2**31 ms, so that the
    TIME clock's wrap at 2**32 ms, which `start` may cross, changes no elapsed time."""
    rng = np.random.default_rng(seed)
    ms_bank, ns_bank = plc_timers.TonBank(n), plc_timers.TonBank(n, type="LTIME")
    pt = rng.choice([rng.integers(-5, 5, n), rng.integers(0, 500, n),
                     rng.integers(-(2**31), 2**31, n)]).astype(np.int32)
    pt_ns = pt.astype(np.int64) * NS_PER_MS
    now = start
    for _ in range(scans):
        now += int(rng.choice([0, int(rng.integers(1, 300)), int(rng.integers(0, 2**31))]))
        inputs = rng.random(n) < 0.8
        q_ms, et_ms = ms_bank.scan(now, inputs, pt)
        q_ns, et_ns = ns_bank.scan(now * NS_PER_MS, inputs, pt_ns)
        assert q_ns.tolist() == q_ms.tolist(), f"LTIMER-SAME-01: bank Q at {now} ms"
        assert et_ns.tolist() == [e * NS_PER_MS for e in et_ms.tolist()], (
            f"LTIMER-SAME-01: bank ET at {now} ms")


def test_ltime_ton_bank_copy_and_pickle() -> None:
    bank = plc_timers.TonBank(3, type="LTIME")
    pt = np.array([30 * DAY_NS, 5, 10**9], np.int64)
    bank.scan(0, np.array([True, True, False]), pt)
    bank.scan(7, np.array([True, True, True]), pt)
    copies = (copy.copy(bank), copy.deepcopy(bank), pickle.loads(pickle.dumps(bank)))
    # From the rules: timer 0 runs since 0 ns (PT 30 days), timer 1 expired at PT = 5 ns,
    # timer 2 rose at 7 ns and has run out 10**9 ns later.
    want = ([False, True, True], [2 * 10**9, 5, 10**9])
    for c in (bank, *copies):
        assert c.type == "LTIME"
        q, et = c.scan(2 * 10**9, np.ones(3, np.bool_), pt)
        assert (q.tolist(), et.tolist()) == want, (
            "IEC-BANK-01: a copied LTIME bank goes on as the original")
    # A TIME bank's pickle refuses an LTIME-sized clock word; an LTIME one takes it.
    state = bank.__reduce__()[2]
    big = (state[0], [(True, True, 2**40, 2**41, 0, False)] * 3)
    with pytest.raises(ValueError, match=r"START, PT and ET are 0..=4294967295 for TIME"):
        plc_timers.TonBank(3).__setstate__(big)
    plc_timers.TonBank(3, type="LTIME").__setstate__(big)


def test_ltime_ton_bank_refuses_bad_input() -> None:
    bank = plc_timers.TonBank(4, type="LTIME")
    ok_in, ok_pt = np.zeros(4, np.bool_), np.zeros(4, np.int64)
    with pytest.raises(TypeError, match=r"pt is a 1-D contiguous numpy array of int64 with 4"):
        bank.scan(0, ok_in, np.zeros(4, np.int32))
    with pytest.raises(TypeError, match=r"pt is a 1-D contiguous numpy array of int32 with 4"):
        plc_timers.TonBank(4).scan(0, ok_in, ok_pt)
    with pytest.raises(TypeError, match=r"out's et is a 1-D numpy array of uint64"):
        bank.scan(0, ok_in, ok_pt, out=(np.zeros(4, np.bool_), np.zeros(4, np.int64)))
    with pytest.raises(ValueError, match=r"now_ns is the CPU time in whole nanoseconds, "
                                         r"0..=18446744073709551615; got -1"):
        bank.scan(-1, ok_in, ok_pt)
    with pytest.raises(ValueError, match=r"now_ns is .*; got 18446744073709551616"):
        bank.scan(2**64, ok_in, ok_pt)
    with pytest.raises(TypeError, match=r"now_ns is .*; got 1.5 \(float\)"):
        bank.scan(1.5, ok_in, ok_pt)  # type: ignore[arg-type]
    bank.scan(10**12, ok_in, ok_pt)
    with pytest.raises(ValueError, match=r"now_ns goes backwards: 5 after 1000000000000"):
        bank.scan(5, ok_in, ok_pt)
    with pytest.raises(ValueError, match=r"unknown data type `XTIME`; TON takes TIME LTIME"):
        plc_timers.TonBank(4, type="XTIME")
    with pytest.raises(ValueError, match=r"TON does not take the data type INT; it takes TIME"):
        plc_timers.TonBank(4, type="INT")
    with pytest.raises(ValueError, match="n is the number of lanes"):
        plc_timers.TonBank(-3, type="LTIME")
