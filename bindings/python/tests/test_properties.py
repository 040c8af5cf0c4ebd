"""Hypothesis properties: the reference equals the optimized implementation on random call
sequences, literals round-trip, and bad input raises a Python exception (never a crash)."""

from __future__ import annotations

from typing import Any, Callable, Dict, List, Tuple

import plc_timers
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

S5_TIMERS = [plc_timers.S_PULSE, plc_timers.S_PEXT, plc_timers.S_ODT, plc_timers.S_ODTS,
             plc_timers.S_OFFDT]
IEC_TIMERS = [plc_timers.TP, plc_timers.TON, plc_timers.TOF, plc_timers.TONR]
IEC_COUNTERS = [plc_timers.CTU, plc_timers.CTD, plc_timers.CTUD]
S5_COUNTERS = [plc_timers.S_CU, plc_timers.S_CD, plc_timers.S_CUD]
INT_TYPES = ["SINT", "INT", "DINT", "LINT", "USINT", "UINT", "UDINT", "ULINT"]
INPUTS = {
    "CTU": ("cu", "r"), "CTD": ("cd", "ld"), "CTUD": ("cu", "cd", "r", "ld"),
    "S_CU": ("cu",), "S_CD": ("cd",), "S_CUD": ("cu", "cd"),
}

# A valid S5TIME word: base in bits 13-12, three BCD digits.
s5_words = st.builds(
    lambda base, units: base << 12 | int(str(units), 16),
    st.integers(0, 3),
    st.integers(0, 999),
)
steps = st.integers(0, 3000)
many = settings(max_examples=150, deadline=None, suppress_health_check=[HealthCheck.too_slow])


@many
@given(
    block=st.sampled_from(S5_TIMERS),
    calls=st.lists(st.tuples(steps, st.booleans(), st.booleans(), st.booleans(), s5_words),
                   max_size=60),
)
def test_s5_timers_reference_is_optimized(
    block: Callable[..., Any], calls: List[Tuple[int, bool, bool, bool, int]]
) -> None:
    ref, opt = block(), block(optimized=True)
    now = 0
    for dt, s, r, fr, tv in calls:
        now += dt
        assert ref.call(now, s=s, r=r, fr=fr, tv=tv) == opt.call(now, s=s, r=r, fr=fr, tv=tv)


@many
@given(
    block=st.sampled_from(IEC_TIMERS),
    calls=st.lists(
        st.tuples(st.integers(0, 5000), st.booleans(), st.booleans(),
                  st.integers(-100, 4000), st.sampled_from(["call", "rt", "pt", "read"])),
        max_size=60,
    ),
    start=st.integers(0, 2**33),
)
def test_iec_timers_reference_is_optimized(
    block: Callable[..., Any], calls: List[Tuple[int, bool, bool, int, str]], start: int
) -> None:
    ref, opt = block(), block(optimized=True)
    tonr = block is plc_timers.TONR
    now = start  # also across the wrap of the 32-bit clock word
    for dt, i, r, pt, op in calls:
        now += dt
        r = r and tonr
        if op == "call":
            assert ref.call(now, in_=i, r=r, pt=pt) == opt.call(now, in_=i, r=r, pt=pt)
        elif op == "rt":
            ref.reset_timer()
            opt.reset_timer()
        elif op == "pt":
            ref.preset_timer(pt)
            opt.preset_timer(pt)
        else:
            assert (ref.read_q(now), ref.read_et(now)) == (opt.read_q(now), opt.read_et(now))


@many
@given(data=st.data(), block=st.sampled_from(IEC_COUNTERS), int_type=st.sampled_from(INT_TYPES))
def test_iec_counters_reference_is_optimized(
    data: st.DataObject, block: Callable[..., Any], int_type: str
) -> None:
    ref, opt = block(type=int_type), block(type=int_type, optimized=True)
    names = INPUTS[block.__name__]
    lo, hi = {"S": (-128, 127), "U": (0, 255)}.get(int_type[0], (-128, 127))
    for _ in range(data.draw(st.integers(0, 60))):
        kw: Dict[str, Any] = {n: data.draw(st.booleans()) for n in names}
        kw["pv"] = data.draw(st.integers(lo, hi))
        assert ref.call(**kw) == opt.call(**kw)


@many
@given(data=st.data(), block=st.sampled_from(S5_COUNTERS))
def test_s5_counters_reference_is_optimized(data: st.DataObject, block: Callable[..., Any]) -> None:
    ref, opt = block(), block(optimized=True)
    names = INPUTS[block.__name__] + ("s", "r", "fr")
    for _ in range(data.draw(st.integers(0, 60))):
        kw: Dict[str, Any] = {n: data.draw(st.booleans()) for n in names}
        kw["pv"] = data.draw(st.integers(0, 999))
        assert ref.call(**kw) == opt.call(**kw)


@many
@given(word=s5_words)
def test_s5time_round_trips(word: int) -> None:
    t = plc_timers.S5Time.from_word(word)
    assert t.word == word
    assert plc_timers.S5Time.parse(f"W#16#{word:04X}") == t
    again = plc_timers.S5Time.parse(str(t))  # the canonical literal, automatic base
    assert again.millis == t.millis == t.units * t.base_ms


@many
@given(ms=st.integers(-(2**31), 2**31 - 1))
def test_time_round_trips(ms: int) -> None:
    t = plc_timers.Time.from_millis(ms)
    assert plc_timers.Time.parse(str(t)) == t
    assert plc_timers.Time.parse(str(ms)).millis == ms


@many
@given(n=st.integers(0, 999))
def test_counter_preset_round_trips(n: int) -> None:
    p = plc_timers.CounterPreset(n)
    assert plc_timers.CounterPreset.parse(str(p)) == p
    assert plc_timers.CounterPreset.parse(f"W#16#{p.bcd:04X}").value == n


literal_text = st.one_of(
    st.text(max_size=20),
    st.text(alphabet="ST5#IMEWCD16_.-+0123456789HMSD ", max_size=20),
    st.builds(lambda p, s: p + s, st.sampled_from(["T#", "S5T#", "W#16#", "C#", "TIME#"]),
              st.text(alphabet="0123456789DHMS_.-+", max_size=12)),
)


@settings(max_examples=600, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(text=literal_text)
def test_parsers_raise_literal_errors_only(text: str) -> None:
    for parse in (plc_timers.S5Time.parse, plc_timers.Time.parse, plc_timers.CounterPreset.parse):
        try:
            parse(text)
        except plc_timers.LiteralError as e:
            assert isinstance(e.kind, str) and str(e)
            assert e.position is None or 0 <= e.position <= len(text.encode())


anything = st.one_of(
    st.none(), st.booleans(), st.integers(-(2**70), 2**70), st.floats(allow_nan=True),
    st.text(max_size=8), st.binary(max_size=4), st.lists(st.integers(), max_size=2),
)


@settings(max_examples=400, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(block=st.sampled_from(S5_TIMERS + IEC_TIMERS + IEC_COUNTERS + S5_COUNTERS),
       arg=anything, when=anything)
def test_bad_arguments_raise_never_crash(block: Callable[..., Any], arg: Any, when: Any) -> None:
    try:
        b = block(arg)
        if block in S5_TIMERS or block in IEC_TIMERS:
            b.call(when, True)
        else:
            b.call(True)
    except (ValueError, TypeError, OverflowError):
        pass


@settings(max_examples=300, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(
    block=st.sampled_from(["TON", "S_ODT", "CTUD", "S_CUD", "nope"]),
    rows=st.lists(st.dictionaries(st.sampled_from(["t_ms", "IN", "S", "CU", "PV", "TV", "Q", "x"]),
                                  anything, max_size=4), max_size=4),
    preset=anything,
)
def test_bad_traces_raise_never_crash(block: str, rows: List[Dict[str, Any]], preset: Any) -> None:
    for fn in (plc_timers.run, plc_timers.check):
        try:
            fn(block, rows, pt=preset)
        except (plc_timers.TraceError, TypeError):
            pass
