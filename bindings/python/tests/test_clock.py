"""The clock going back (rule S5TMR-CLOCK-01, issue 37). `now_ms` must not go back. The library
applies no S5 tick for a step back and keeps the latest time (tests/s5_scenarios.rs, the C test
bindings/c/tests/bytes.c); the Python blocks, banks and memory areas refuse such a call with a
ValueError before anything changes, so the instance goes on as if the call had not been made:
an S_ODT of S5T#1S (100 ticks of 10 ms, LAD manual 9.5) started at 0 ms still runs out at
1000 ms, and a TON with PT 500 ms started at 1000 ms still at 1500 ms."""

from __future__ import annotations

from typing import Callable

import plc_timers
import pytest


def s5_steps(call: Callable[[int], plc_timers.S5Output]) -> None:
    """0 and 600 ms, 100 ms refused, then 600, 990 and 1000 ms: the span is counted once."""
    assert (call(0).q, call(600).bi) == (False, 40)
    with pytest.raises(ValueError, match="backwards"):
        call(100)
    out = call(600)
    assert (out.q, out.bi) == (False, 40), "S5TMR-CLOCK-01: the refused call changed nothing"
    assert (call(990).q, call(1000).q) == (False, True), "S5TMR-CLOCK-01: the 100th tick"


@pytest.mark.parametrize("optimized", [False, True])
def test_s5_timer_refuses_a_clock_going_back(optimized: bool) -> None:
    sd = plc_timers.S_ODT(tv="S5T#1S", optimized=optimized)
    s5_steps(lambda now_ms: sd.call(now_ms, s=True))


def test_timer_memory_refuses_a_clock_going_back() -> None:
    area = plc_timers.TimerMemory(64)
    s5_steps(lambda now_ms: area.call(2, "S_ODT", now_ms, s=True, tv="S5T#1S"))
    with pytest.raises(ValueError, match="backwards"):
        area.advance_to(999)
    assert area.now_ms == 1000


@pytest.mark.parametrize("optimized", [False, True])
def test_iec_timer_refuses_a_clock_going_back(optimized: bool) -> None:
    ton = plc_timers.TON(pt="T#500ms", optimized=optimized)
    assert not ton.call(1000, in_=True).q
    # In the library 999 would read as 2^32 - 1 ms after START (the 32-bit clock's wrap) and
    # expire the timer at once; Python refuses it instead.
    with pytest.raises(ValueError, match="backwards"):
        ton.call(999, in_=True)
    out = ton.call(1499, in_=True)
    assert (out.q, out.et) == (False, 499), "S5TMR-CLOCK-01: the refused call changed nothing"
    assert ton.call(1500, in_=True).q
