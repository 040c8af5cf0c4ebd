//! Properties of the rules added by the decision register (`spec/decisions.md`, R14-R17 and
//! R10): TV latched at the start, no non-BCD TV at the box, several instructions on one
//! IEC_TIMER, S5TIME below the resolution of its base, S5 timers and counters across STOP. Each oracle is written from the rule's
//! text, independently of both implementations; each driver names its rule in `check_ids`.

use crate::cover::{check, check_eq};
#[cfg(not(kani))]
use crate::cover::{check_ids, cover, covers};
use crate::domain::s5_timer_inputs;

use plc_timers::counter::s5::{
    CounterMemory, S5Counter, S5CounterInput, S5CounterKind, S5CounterOps, S5CounterRef,
    S5CounterState,
};
use plc_timers::iec::{IecInput, IecKind, IecTimer, IecTimerOps, IecTimerRef};
use plc_timers::s5::{S5Input, S5Kind, S5State, S5Timer, S5TimerOps, S5TimerRef, TimerMemory};
use plc_timers::time::{CpuTime, S5Time, Time};

use crate::s5::start_signal;

/// Both S5 timer forms from `state`, `ticks` OS ticks on its base, then one execution.
fn s5_step(
    kind: S5Kind,
    state: S5State,
    ticks: u64,
    input: S5Input,
) -> [(S5State, u16, u16, bool); 2] {
    let mut r = S5TimerRef::from_state(state, CpuTime::ZERO).expect("a valid state");
    let mut w = S5Timer::from_state(state, CpuTime::ZERO).expect("a valid state");
    // The ticks fall on whole multiples of the base: `ticks` bases later there are `ticks` ticks.
    let now = CpuTime::from_millis(ticks.saturating_mul(u64::from(state.base.millis())));
    let a = r.call(kind, now, input);
    let b = w.call(kind, now, input);
    [(r.state(), a.bi, a.bcd, a.q), (w.state(), b.bi, b.bcd, b.q)]
}

/// S5TMR-TV-01: from `state`, the same execution with TV `tv` and with TV `other` leaves the
/// same state and outputs unless the execution starts the timer (a change of S in the kind's
/// direction against the edge memory as FR leaves it); a start with R = 0 loads the TV of that
/// execution. Returns whether the TVs differed with no start while the timer ran.
pub fn prop_tv_latched(
    kind: S5Kind,
    state: S5State,
    ticks: u64,
    input: S5Input,
    other: S5Time,
) -> bool {
    let with_other = S5Input { tv: other, ..input };
    let start = start_signal(kind, &state, &input);
    let a = s5_step(kind, state, ticks, input);
    let b = s5_step(kind, state, ticks, with_other);
    if !start {
        check_eq!(
            a,
            b,
            "S5TMR-TV-01: a TV change without a start changes nothing: {kind:?} {state:?} {ticks} {input:?} {other:?}"
        );
    } else if !input.r {
        for (post, _, _, _) in a {
            check!(
                post.value == input.tv.units() && post.base == input.tv.base(),
                "S5TMR-TV-01: a start loads the TV of its execution: {kind:?} {state:?} {input:?} -> {post:?}"
            );
        }
    }
    !start && state.running && input.tv != other
}

/// States that reach every case of a start and of the tick rule: value 0, 1, 2, 998, 999, every
/// base and every valid flag combination.
#[cfg(not(kani))]
fn some_states() -> impl Iterator<Item = S5State> {
    crate::s5::states_with_values([0u16, 1, 2, 998, 999])
}

/// Exhaustive over every kind, the states of [`some_states`], tick counts 0, 1, 999 and 1000,
/// every S, R and FR, and every ordered pair of distinct TVs among zero, one unit, 999 units
/// and one of each base.
#[cfg(not(kani))]
#[test]
#[covers]
fn exhaustive_tv_latched() {
    let tvs: Vec<S5Time> = [0x0000u16, 0x0001, 0x0999, 0x1500, 0x2001, 0x3999]
        .into_iter()
        .map(|w| S5Time::from_word(w).expect("BCD"))
        .collect();
    let latched = check_ids(&["S5TMR-TV-01"], || {
        let mut latched = 0u64;
        for kind in S5Kind::ALL {
            for state in some_states() {
                for ticks in [0u64, 1, 999, 1000] {
                    for bits in 0..8u8 {
                        for &tv in &tvs {
                            for &other in tvs.iter().filter(|&&o| o != tv) {
                                let input = s5_timer_inputs(tv)[usize::from(bits)];
                                let hit = prop_tv_latched(kind, state, ticks, input, other);
                                cover!(hit, "S5TMR-TV-01: TV changed while running, no start");
                                latched += u64::from(hit);
                            }
                        }
                    }
                }
            }
        }
        latched
    });
    assert!(latched > 0);
}

/// The three BCD digits of a word's value field, hundreds first (an oracle of its own, not the
/// crate's decoder).
fn digits(word: u16) -> [u16; 3] {
    [(word >> 8) & 0xF, (word >> 4) & 0xF, word & 0xF]
}

/// S5TMR-TVBCD-01: a word is a TV exactly when its three value digits are 0..9 (bits 15-14
/// ignored); a valid one starts S_PEXT from the reset state with its value in binary at BI and
/// its digits and base, bits 15-14 cleared, at BCD, in both forms. Returns whether it was valid.
pub fn prop_tv_word_at_the_box(word: u16) -> bool {
    let d = digits(word);
    let bcd = d.iter().all(|&x| x <= 9);
    let tv = S5Time::from_word(word);
    check_eq!(
        tv.is_ok(),
        bcd,
        "S5TMR-TVBCD-01: a word reaches the box exactly when its digits are BCD: {word:#06x}"
    );
    let Ok(tv) = tv else {
        return false;
    };
    let start = S5Input::new(true, false, tv);
    let mut r = S5TimerRef::new();
    let mut w = S5Timer::new();
    for out in [
        r.call(S5Kind::SPext, CpuTime::ZERO, start),
        w.call(S5Kind::SPext, CpuTime::ZERO, start),
    ] {
        check_eq!(
            (out.bi, out.bcd),
            (100 * d[0] + 10 * d[1] + d[2], word & 0x3FFF),
            "S5TMR-TVBCD-01: the started timer shows the word's value: {word:#06x}"
        );
    }
    true
}

/// Exhaustive over every 16-bit word.
#[cfg(not(kani))]
#[test]
#[covers]
fn exhaustive_tv_words_at_the_box() {
    let valid = check_ids(&["S5TMR-TVBCD-01"], || {
        (0..=u16::MAX)
            .map(|w| {
                let ok = prop_tv_word_at_the_box(w);
                cover!(!ok, "S5TMR-TVBCD-01: a non-BCD word refused");
                u64::from(ok)
            })
            .sum::<u64>()
    });
    // Four bases x 1 000 values x bits 15-14 (4).
    assert_eq!(valid, 16_000);
}

/// IEC-SHARE-01: one structure, from power-up, PT = 100 ms: instruction `k1` executes at 0 ms
/// with IN = `a`, then instruction `k2` at 10 ms with IN = `b`. The second call acts on what
/// the first left: its stored IN, START, ET and Q. Oracle from the rules of each kind: the first
/// call starts the timer iff `a` and `k1` is not TOF (TOF starts on a falling IN, and the
/// stored IN of power-up is 0); the second call's (running, ET) follows below. Returns whether
/// the second call saw the stored IN of the first as its edge memory with `a` = `b` = 1 (no
/// edge, though this instruction never ran before).
pub fn prop_shared_structure(k1: IecKind, a: bool, k2: IecKind, b: bool) -> bool {
    let pt = Time::from_millis(100);
    let running1 = a && k1 != IecKind::Tof;
    let (running, et) = match k2 {
        IecKind::Tp if running1 => (true, 10),
        IecKind::Tp => (b && !a, 0),
        IecKind::Ton if !b => (false, 0),
        IecKind::Ton if !a => (true, 0),
        IecKind::Ton => (running1, if running1 { 10 } else { 0 }),
        IecKind::Tof => (!b && a, 0),
        // TONR times whenever IN = 1 and its Q is not 1 (a Q of 1 left by TOF is its expiry).
        IecKind::Tonr if b && running1 => (true, 10),
        IecKind::Tonr if b => (!(k1 == IecKind::Tof && a), 0),
        IecKind::Tonr => (false, if running1 { 10 } else { 0 }),
    };
    let mut r = IecTimerRef::<u32>::new();
    let mut s = IecTimer::new();
    for t in [&mut r as &mut dyn IecTimerOps<u32>, &mut s] {
        t.call(k1, CpuTime::ZERO, IecInput::new(a, pt));
        let out = t.call(k2, CpuTime::from_millis(10), IecInput::new(b, pt));
        let st = t.state();
        check_eq!(
            (st.running, st.et, out.et),
            (running, et, et),
            "IEC-SHARE-01: {k2:?} with IN = {b} acts on what {k1:?} with IN = {a} left"
        );
        check_eq!(
            st.input,
            b,
            "IEC-SHARE-01: the stored IN is the last call's, whichever instruction made it"
        );
        if k1 == IecKind::Tof && a && k2 == IecKind::Tonr && b {
            check!(
                st.q,
                "IEC-SHARE-01: TONR takes the Q of 1 that TOF left as its expiry"
            );
        }
    }
    k1 != k2 && a && b
}

/// Exhaustive over every pair of instructions and every pair of IN values.
#[cfg(not(kani))]
#[test]
#[covers]
fn exhaustive_shared_structure() {
    check_ids(&["IEC-SHARE-01"], || {
        for k1 in IecKind::ALL {
            for k2 in IecKind::ALL {
                for a in [false, true] {
                    for b in [false, true] {
                        let hit = prop_shared_structure(k1, a, k2, b);
                        cover!(hit, "IEC-SHARE-01: two instructions, IN held through both");
                    }
                }
            }
        }
    });
}

/// S5T-RES-01: `ms` milliseconds (at most 9 990 s) become the whole units of the finest base
/// whose count fits in 999, the rest cut off without error (oracle: the bases in order); below
/// 10 ms that is `S5T#0MS`, and an S_PULSE started with it shows Q = 1 in its starting
/// execution and Q = 0 at its next, with no tick in between. Returns whether something was cut.
pub fn prop_below_resolution(ms: u64) -> bool {
    let base = [10u64, 100, 1_000, 10_000]
        .into_iter()
        .find(|b| ms / b <= 999)
        .expect("at most 9 990 s");
    let t = S5Time::from_millis(ms);
    check!(
        t.is_ok(),
        "S5T-RES-01: a duration up to 9 990 s is never an error: {ms} ms"
    );
    let Ok(t) = t else {
        return false;
    };
    check_eq!(
        (u64::from(t.units()), u64::from(t.base().millis())),
        (ms / base, base),
        "S5T-RES-01: {ms} ms cut down to whole units of its base"
    );
    if ms < 10 {
        check_eq!(
            t,
            S5Time::ZERO,
            "S5T-RES-01: below 10 ms is S5T#0MS: {ms} ms"
        );
        let on = S5Input::new(true, false, t);
        let mut r = S5TimerRef::new();
        let mut w = S5Timer::new();
        for timer in [&mut r as &mut dyn S5TimerOps, &mut w] {
            let first = timer.call(S5Kind::SPulse, CpuTime::ZERO, on).q;
            let next = timer.call(S5Kind::SPulse, CpuTime::ZERO, on).q;
            check_eq!(
                (first, next),
                (true, false),
                "S5T-RES-01 / S5TMR-ZERO-01: {ms} ms runs out at the next execution"
            );
        }
    }
    !ms.is_multiple_of(base)
}

/// Exhaustive over every millisecond from 0 to 9 990 s.
#[cfg(not(kani))]
#[test]
#[covers]
fn exhaustive_below_resolution() {
    check_ids(&["S5T-RES-01"], || {
        for ms in 0..=9_990_000u64 {
            let cut = prop_below_resolution(ms);
            cover!(
                cut && ms < 10,
                "S5T-RES-01: a duration below 10 ms cut to 0"
            );
            cover!(
                cut && ms >= 10,
                "S5T-RES-01: a remainder below the base cut off"
            );
        }
    });
}

/// The multiples of `base` in `(from, to]`, stepped through one by one: the ticks of that base
/// in the interval (an oracle of its own, not the crate's tick count).
fn multiples_in(from: u64, to: u64, base: u64) -> u64 {
    let mut m = from - from % base;
    let mut n = 0;
    loop {
        m += base;
        if m > to {
            return n;
        }
        n += 1;
    }
}

/// What S5TMR-RETAIN-01 and the kind's rule give at the first execution after the restart, S
/// at its held level: `(running, value, Q)`. Retentive: the value at STOP less the ticks after
/// the restart, run out at 0 (on-delays then Q = 1, the others Q = 0). Cleared: a rising S
/// starts the timer again with the TV (Q = 1 for the pulses, 0 for the on-delays); the
/// off-delay, S held at 0, has no edge and stays cleared.
fn expected_after_restart(
    kind: S5Kind,
    units: u16,
    run_ticks: u64,
    kept: bool,
) -> (bool, u16, bool) {
    let on_delay = matches!(kind, S5Kind::SOdt | S5Kind::SOdts);
    if kept {
        let left = u64::from(units).saturating_sub(run_ticks) as u16;
        let running = left > 0;
        (running, left, if on_delay { !running } else { running })
    } else if kind == S5Kind::SOffdt {
        (false, 0, false)
    } else {
        (true, units, !on_delay)
    }
}

/// S5TMR-RETAIN-01: a timer of `kind` started at `t0` with `tv` (at least one unit), its S
/// held (at 0 after the falling edge for S_OFFDT), the CPU in STOP from `stop` to `restart`,
/// executed again at `t1` (`t0 <= stop <= restart <= t1`), in the three forms (reference,
/// optimized, and `T 0` and `T 1` of an area with `T 0` retentive iff `retentive` and `T 1`
/// never). Oracle: the ticks are the multiples of the base in `(t0, stop]` and `(restart, t1]`,
/// counted one by one; right after the restart a cleared timer is `S5State::RESET`. When the
/// STOP lasts a whole number of 10 s (every base's ticks fall alike), the kept timer also
/// equals an uninterrupted run with the STOP cut out of the clock. Returns whether a tick fell
/// in the STOP (so that counting it would have changed the result).
pub fn prop_s5_run_stop_run(
    kind: S5Kind,
    tv: S5Time,
    t0: u64,
    stop: u64,
    restart: u64,
    t1: u64,
    retentive: bool,
) -> bool {
    let at = CpuTime::from_millis;
    let base = u64::from(tv.base().millis());
    let level = !kind.starts_on_falling_edge();
    let start = |timer: &mut dyn S5TimerOps, t: u64| {
        timer.call(kind, at(t), S5Input::new(true, false, tv));
        if !level {
            timer.call(kind, at(t), S5Input::new(false, false, tv));
        }
    };
    let held = S5Input::new(level, false, tv);
    let run_ticks = multiples_in(t0, stop, base) + multiples_in(restart, t1, base);

    let mut r = S5TimerRef::new();
    let mut w = S5Timer::new();
    let mut area = TimerMemory::<2>::new();
    start(&mut r, t0);
    start(&mut w, t0);
    for index in 0..2 {
        area.call(index, kind, at(t0), S5Input::new(true, false, tv))
            .expect("T 0 and T 1 exist");
        if !level {
            area.call(index, kind, at(t0), S5Input::new(false, false, tv))
                .expect("T 0 and T 1 exist");
        }
    }
    r.run_stop_run(at(stop), at(restart), retentive);
    w.run_stop_run(at(stop), at(restart), retentive);
    area.run_stop_run(at(stop), at(restart), usize::from(retentive));
    let area_states = [area.get(0), area.get(1)].map(|s| s.expect("T 0 and T 1 exist"));
    for (form, state, kept) in [
        ("reference", r.state(), retentive),
        ("optimized", w.state(), retentive),
        ("area T 0", area_states[0], retentive),
        ("area T 1", area_states[1], false),
    ] {
        if !kept {
            check_eq!(
                state,
                S5State::RESET,
                "S5TMR-RETAIN-01: {form}: a non-retentive timer is cleared at the restart: {kind:?} {tv:?}"
            );
        }
    }
    let outs = [
        (
            "reference",
            r.call(kind, at(t1), held),
            r.state(),
            retentive,
        ),
        (
            "optimized",
            w.call(kind, at(t1), held),
            w.state(),
            retentive,
        ),
        (
            "area T 0",
            area.call(0, kind, at(t1), held).expect("T 0 exists"),
            area.get(0).expect("T 0 exists"),
            retentive,
        ),
        (
            "area T 1",
            area.call(1, kind, at(t1), held).expect("T 1 exists"),
            area.get(1).expect("T 1 exists"),
            false,
        ),
    ];
    for (form, out, state, kept) in outs {
        let expected = expected_after_restart(kind, tv.units(), run_ticks, kept);
        check_eq!(
            (state.running, out.bi, out.q),
            expected,
            "S5TMR-RETAIN-01: {form}: no tick in STOP, kept = {kept}: {kind:?} {tv:?} start {t0} STOP {stop}..{restart} call {t1}"
        );
    }
    let d = restart - stop;
    if retentive && d.is_multiple_of(10_000) {
        let mut cut = S5TimerRef::new();
        start(&mut cut, t0);
        let uninterrupted = cut.call(kind, at(t1 - d), held);
        check_eq!(
            (outs[0].1, outs[0].2),
            (uninterrupted, cut.state()),
            "S5TMR-RETAIN-01: the run across STOP is the run with the STOP cut out: {kind:?} {tv:?} start {t0} STOP {stop}..{restart} call {t1}"
        );
    }
    multiples_in(stop, restart, base) > 0
}

/// Exhaustive over the five kinds, TVs of 1, 2, 50 and 999 units of 10 ms and of one unit of
/// the other bases, start times on and off the 10 ms grid, STOPs beginning 0 to 1 s after the
/// start and lasting 0 ms to 20 s (on and off the 10 s grid), calls 0 ms to 10 s after the
/// restart, retentive or not: 38 880 cases.
#[cfg(not(kani))]
#[test]
#[covers]
fn exhaustive_s5_run_stop_run() {
    let tvs: Vec<S5Time> = [0x0001u16, 0x0002, 0x0050, 0x0999, 0x1001, 0x2001, 0x3001]
        .into_iter()
        .map(|w| S5Time::from_word(w).expect("BCD"))
        .collect();
    check_ids(&["S5TMR-RETAIN-01"], || {
        for kind in S5Kind::ALL {
            for &tv in &tvs {
                for t0 in [0u64, 5, 10] {
                    for to_stop in [0u64, 5, 10, 15, 100, 1_000] {
                        for d in [0u64, 5, 10, 9_995, 10_000, 20_000] {
                            for to_call in [0u64, 5, 10, 30, 1_000, 10_000] {
                                for retentive in [false, true] {
                                    let stop = t0 + to_stop;
                                    let restart = stop + d;
                                    let ticked = prop_s5_run_stop_run(
                                        kind,
                                        tv,
                                        t0,
                                        stop,
                                        restart,
                                        restart + to_call,
                                        retentive,
                                    );
                                    cover!(
                                        ticked && retentive,
                                        "S5TMR-RETAIN-01: a kept timer with ticks in STOP"
                                    );
                                    cover!(
                                        ticked && retentive && d.is_multiple_of(10_000) && d > 0,
                                        "S5TMR-RETAIN-01: the cut-clock comparison across a STOP"
                                    );
                                }
                            }
                        }
                    }
                }
            }
        }
    });
}

/// SC-RETAIN-01: from `state`, a RUN-STOP-RUN in the three forms (reference, optimized, and
/// `C 0` and `C 1` of an area with `C 0` retentive iff `retentive` and `C 1` never) leaves the
/// state as it was (retentive) or `S5CounterState::RESET`; then an S_CUD call with CU = 1 acts
/// as on a counter never stopped (retentive) or counts once from 0 (cleared: the CU memory is 0).
pub fn prop_s5_counter_run_stop_run(state: S5CounterState, retentive: bool) {
    let up = S5CounterInput {
        cu: true,
        ..S5CounterInput::default()
    };
    let mut r = S5CounterRef::from_state(state).expect("a valid state");
    let mut w = S5Counter::from_state(state).expect("a valid state");
    let mut area = CounterMemory::<2>::new();
    for index in 0..2 {
        let stored = area.set_state(index, state).expect("C 0 and C 1 exist");
        check!(stored, "SC-RETAIN-01: a valid state is stored: {state:?}");
    }
    r.run_stop_run(retentive);
    w.run_stop_run(retentive);
    area.run_stop_run(usize::from(retentive));
    let mut never_stopped = S5CounterRef::from_state(state).expect("a valid state");
    let forms: [(&str, &mut dyn S5CounterOps, bool); 2] = [
        ("reference", &mut r, retentive),
        ("optimized", &mut w, retentive),
    ];
    let mut results = Vec::new();
    for (form, counter, kept) in forms {
        results.push((
            form,
            counter.state(),
            counter.call(S5CounterKind::SCud, up),
            kept,
        ));
    }
    for index in 0..2 {
        let before = area.get(index).expect("C 0 and C 1 exist");
        let out = area
            .call(index, S5CounterKind::SCud, up)
            .expect("C 0 and C 1 exist");
        let form = if index == 0 { "area C 0" } else { "area C 1" };
        results.push((form, before, out, index == 0 && retentive));
    }
    let continued = never_stopped.call(S5CounterKind::SCud, up);
    for (form, before, out, kept) in results {
        let (expected_state, expected_cv) = if kept {
            (state, continued.cv)
        } else {
            (S5CounterState::RESET, 1)
        };
        check_eq!(
            (before, out.cv),
            (expected_state, expected_cv),
            "SC-RETAIN-01: {form}: kept = {kept}: {state:?}"
        );
    }
}

/// Exhaustive over CV 0, 1, 2, 998 and 999 with every combination of the four edge memories,
/// retentive or not.
#[cfg(not(kani))]
#[test]
#[covers]
fn exhaustive_s5_counter_run_stop_run() {
    check_ids(&["SC-RETAIN-01"], || {
        for cv in [0u16, 1, 2, 998, 999] {
            for f in 0..16u8 {
                let state = S5CounterState {
                    cv,
                    cu_prev: f & 1 != 0,
                    cd_prev: f & 2 != 0,
                    s_prev: f & 4 != 0,
                    fr_prev: f & 8 != 0,
                };
                for retentive in [false, true] {
                    prop_s5_counter_run_stop_run(state, retentive);
                    cover!(
                        retentive && state.cu_prev && cv > 0,
                        "SC-RETAIN-01: a kept CU memory does not count again"
                    );
                }
            }
        }
    });
}
