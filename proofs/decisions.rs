//! Properties of the rules added by the decision register (`spec/decisions.md`, R14-R16 and
//! R10): TV latched at the start, no non-BCD TV at the box, several instructions on one
//! IEC_TIMER, S5TIME below the resolution of its base. Each oracle is written from the rule's
//! text, independently of both implementations; each driver names its rule in `check_ids`.

use crate::cover::{check, check_eq};
#[cfg(not(kani))]
use crate::cover::{check_ids, cover, covers};

use plc_timers::iec::{IecInput, IecKind, IecTimer, IecTimerOps, IecTimerRef};
use plc_timers::s5::{S5Input, S5Kind, S5State, S5Timer, S5TimerOps, S5TimerRef};
use plc_timers::time::{CpuTime, S5Time, Time, TimeBase};

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
    [0u16, 1, 2, 998, 999].into_iter().flat_map(|value| {
        TimeBase::ALL.into_iter().flat_map(move |base| {
            (0..32u8)
                .map(move |f| S5State {
                    running: f & 1 != 0,
                    value,
                    base,
                    q: f & 2 != 0,
                    q_on_expiry: f & 4 != 0,
                    s_prev: f & 8 != 0,
                    fr_prev: f & 16 != 0,
                })
                .filter(S5State::is_valid)
        })
    })
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
                                let input = S5Input {
                                    s: bits & 1 != 0,
                                    r: bits & 2 != 0,
                                    fr: bits & 4 != 0,
                                    tv,
                                };
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
