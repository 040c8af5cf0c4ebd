//! Properties of the S5 timers: the packed word simulates the reference, the invariants hold,
//! R resets, no start without a signal change, no panic.
//!
//! Each property is a plain function; `exhaustive_*` tests drive it over finite domains. A
//! property returns whether its premise held (the case was checked): the drivers count the
//! checked cases against the size of their domain, so that no driver can pass vacuously by
//! skipping every case.

use std::thread;

use plc_timers::s5::reference::is_on_delay;
use plc_timers::s5::{
    S5Input, S5Kind, S5Output, S5State, S5Timer, S5TimerOps, S5TimerRef, TimerMemory, TimerWord,
};
use plc_timers::time::{CpuTime, S5Time, TimeBase};

/// The S edge memory as the start logic sees it: a rising FR has cleared it (S5TMR-FR-01).
pub fn s_memory_after_fr(state: &S5State, input: &S5Input) -> bool {
    let fr_rising = input.fr && !state.fr_prev;
    state.s_prev && !fr_rising
}

/// Whether `input` gives `kind` a start signal from `state`: a change of S in the kind's
/// direction against the edge memory as FR leaves it.
pub fn start_signal(kind: S5Kind, state: &S5State, input: &S5Input) -> bool {
    let s_prev = s_memory_after_fr(state, input);
    if kind.starts_on_falling_edge() {
        !input.s && s_prev
    } else {
        input.s && !s_prev
    }
}

/// One reference step from `state`: `ticks` OS ticks, then one execution.
pub fn reference_step(
    kind: S5Kind,
    state: S5State,
    ticks: u64,
    input: S5Input,
) -> (S5State, S5Output) {
    let mut r = S5TimerRef::from_state(state, CpuTime::ZERO).expect("a valid state");
    r.tick(ticks);
    let out = r.execute(kind, input);
    (r.state(), out)
}

/// S5-EQUIV-01: for every valid state, tick count and input, one step of the packed word,
/// mapped through the abstraction function, equals one step of the reference, and the outputs
/// agree. By induction over the steps this covers every trace.
pub fn prop_step_equivalence(kind: S5Kind, state: S5State, ticks: u64, input: S5Input) -> bool {
    let Some(w) = TimerWord::from_state(state) else {
        return false;
    };
    assert_eq!(
        w.state(),
        state,
        "S5-EQUIV-01: abstraction inverts from_state"
    );
    let (r_state, r_out) = reference_step(kind, state, ticks, input);
    let w = w.tick(ticks).execute(kind, input);
    assert_eq!(
        w.state(),
        r_state,
        "S5-EQUIV-01 {kind:?} {state:?} {ticks} {input:?}"
    );
    assert_eq!(
        w.output(),
        r_out,
        "S5-EQUIV-01 outputs {kind:?} {state:?} {ticks} {input:?}"
    );
    true
}

/// S5TMR-RANGE-01, S5TMR-R-01, S5TMR-EDGE-01: after any step the value is 0..=999 with valid
/// BCD and a base code, at most 9 990 s; R = 1 leaves the timer stopped and cleared with Q = 0;
/// a stopped timer only starts, and the value only grows, on a start signal.
pub fn prop_invariants(kind: S5Kind, state: S5State, ticks: u64, input: S5Input) -> bool {
    if !state.is_valid() {
        return false;
    }
    let (after, out) = reference_step(kind, state, ticks, input);
    assert!(after.value <= 999, "S5TMR-RANGE-01: value {}", after.value);
    assert!(
        S5Time::from_word(out.bcd).is_ok_and(|t| t.units() == out.bi),
        "S5TMR-RANGE-01: BCD {:#06X} is the BCD form of BI {}",
        out.bcd,
        out.bi
    );
    assert_eq!(
        out.bcd & 0xC000,
        0,
        "S5TMR-RANGE-01: bits 15-14 are never produced"
    );
    if input.r {
        assert_eq!(
            (after.running, after.value, after.base, after.q),
            (false, 0, TimeBase::Ms10, false),
            "S5TMR-R-01: R = 1 resets"
        );
    }
    if !start_signal(kind, &state, &input) {
        assert!(
            !after.running || state.running,
            "S5TMR-EDGE-01: started without a signal change"
        );
        assert!(
            after.value <= state.value,
            "S5TMR-EDGE-01: value reloaded without a signal change"
        );
    }
    true
}

/// S5TMR-TICK-01: a running timer of value v with a non-zero value stops on exactly its v-th
/// tick: after v - 1 ticks it still runs with value 1, after v it has run out.
pub fn prop_expiry_on_vth_tick(kind: S5Kind, value: u16, base: TimeBase) -> bool {
    if value == 0 || value > 999 {
        return false;
    }
    let state = S5State {
        running: true,
        value,
        base,
        q: !is_on_delay(kind),
        q_on_expiry: is_on_delay(kind),
        s_prev: true,
        fr_prev: false,
    };
    let mut r = S5TimerRef::from_state(state, CpuTime::ZERO).expect("valid");
    r.tick(u64::from(value) - 1);
    assert!(
        r.state().running && r.state().value == 1,
        "S5TMR-TICK-01: still running before the v-th tick"
    );
    r.tick(1);
    assert!(
        !r.state().running && r.state().value == 0,
        "S5TMR-TICK-01: run out on the v-th tick"
    );
    assert_eq!(
        r.state().q,
        is_on_delay(kind),
        "S5TMR-EXPIRE-01: expiry sets the kind's status"
    );
    true
}

/// S5-EQUIV-01 (the abstraction): a timer word is valid exactly when the state it stands for
/// is, and then `from_state` gives the same word back. Returns whether the word is valid.
pub fn prop_cell_word(bits: u32) -> bool {
    match TimerWord::from_bits(bits) {
        Some(w) => {
            let state = w.state();
            assert!(
                state.is_valid(),
                "S5-EQUIV-01: a valid word has a valid state"
            );
            assert_eq!(
                TimerWord::from_state(state),
                Some(w),
                "S5-EQUIV-01: from_state inverts the abstraction: {bits:#010X}"
            );
            assert_eq!(w.bits(), bits);
            true
        }
        None => false,
    }
}

/// The per-kind invariant every reachable state satisfies (LAD manual §9.3-9.7).
pub fn kind_invariant(kind: S5Kind, st: &S5State) -> bool {
    let expiry = !st.running || st.q_on_expiry == is_on_delay(kind);
    expiry
        && match kind {
            S5Kind::SPulse | S5Kind::SPext => st.q == st.running,
            S5Kind::SOdt => !st.q || (st.s_prev && !st.running),
            S5Kind::SOdts => true,
            // Q = 1 while running. (Q = 1 with S = 0 and stopped is reachable: an FR edge in the
            // execution where S falls clears the memory, so no off-delay starts.)
            S5Kind::SOffdt => !st.running || st.q,
        }
}

/// The per-kind rules: from a state that satisfies the kind's invariant, a step keeps it;
/// S_PULSE and S_ODT stop when S = 0; S_PEXT and S_ODTS run on when S falls (unless the ticks
/// run them out); S_OFFDT's Q is set by an edge at S.
pub fn prop_kind_rules(kind: S5Kind, state: S5State, ticks: u64, input: S5Input) -> bool {
    if !state.is_valid() || !kind_invariant(kind, &state) {
        return false;
    }
    let (after, _) = reference_step(kind, state, ticks, input);
    assert!(
        kind_invariant(kind, &after),
        "{kind:?}: invariant broken by {input:?} from {state:?}"
    );
    if input.r {
        return true;
    }
    match kind {
        S5Kind::SPulse | S5Kind::SOdt if !input.s => {
            assert!(!after.running, "SP-Q-01 / SD-Q-01: S = 0 stops the timer");
        }
        S5Kind::SPext | S5Kind::SOdts
            if state.running && !input.s && ticks < u64::from(state.value) =>
        {
            assert!(
                after.running,
                "SE-RUN-ON-01 / SS-Q-01: runs on when S falls"
            );
        }
        S5Kind::SOffdt if input.s != s_memory_after_fr(&state, &input) => {
            assert!(after.q, "SF-Q-01: an edge at S sets Q");
        }
        _ => {}
    }
    true
}

/// Every valid S5 state: value 0..=999, four bases, the five flags with no expiry status on a
/// stopped timer (24 combinations): 96 000 states.
pub fn all_states() -> impl Iterator<Item = S5State> {
    (0..=999u16).flat_map(|value| {
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

/// Tick counts that reach every case of the tick rule: none, one, two, one short of the
/// largest value, the largest value, past it, and the largest count.
const TICKS: [u64; 7] = [0, 1, 2, 998, 999, 1000, u64::MAX];

/// TVs that reach every case of a start: zero, one unit, the largest value, and each base.
fn tvs() -> Vec<S5Time> {
    [0x0000, 0x0001, 0x0999, 0x1500, 0x2001, 0x3999]
        .into_iter()
        .filter_map(|w| S5Time::from_word(w).ok())
        .collect()
}

fn for_all_inputs(mut f: impl FnMut(u64, S5Input)) {
    for tv in tvs() {
        for ticks in TICKS {
            for bits in 0..8u8 {
                f(
                    ticks,
                    S5Input {
                        s: bits & 1 != 0,
                        r: bits & 2 != 0,
                        fr: bits & 4 != 0,
                        tv,
                    },
                );
            }
        }
    }
}

/// Exhaustive: every kind x every valid state (96 000) x tick counts (7) x S, R, FR (8) x TVs
/// (6), split over two threads.
#[test]
fn exhaustive_step_equivalence_and_invariants() {
    let counts: Vec<[u64; 3]> = thread::scope(|scope| {
        let workers: Vec<_> = [&S5Kind::ALL[..3], &S5Kind::ALL[3..]]
            .into_iter()
            .map(|kinds| {
                scope.spawn(move || {
                    kinds
                        .iter()
                        .map(|&kind| {
                            let mut n = [0u64; 3];
                            for state in all_states() {
                                for_all_inputs(|ticks, input| {
                                    n[0] +=
                                        u64::from(prop_step_equivalence(kind, state, ticks, input));
                                    n[1] += u64::from(prop_invariants(kind, state, ticks, input));
                                    n[2] += u64::from(prop_kind_rules(kind, state, ticks, input));
                                });
                            }
                            n
                        })
                        .collect::<Vec<_>>()
                })
            })
            .collect();
        workers
            .into_iter()
            .flat_map(|w| w.join().expect("worker finished"))
            .collect()
    });
    let per_kind = 96_000 * (TICKS.len() as u64) * 8 * (tvs().len() as u64);
    for (kind, n) in S5Kind::ALL.iter().zip(&counts) {
        assert_eq!(
            (n[0], n[1]),
            (per_kind, per_kind),
            "{kind:?}: cases checked"
        );
        assert!(
            n[2] > 0 && n[2] < per_kind,
            "{kind:?}: {} kind-rule cases",
            n[2]
        );
    }
}

/// Exhaustive over the low 21 bits of a timer word (every field), and a sample of words with
/// bits above: valid exactly for the 1 000 values x 4 bases x 24 flag combinations.
#[test]
fn exhaustive_cell_words() {
    let valid = (0..1u32 << 21).filter(|&w| prop_cell_word(w)).count();
    assert_eq!(valid, 1000 * 4 * 24);
    for high in [1u32 << 21, 1 << 31, u32::MAX, 0x0400, 0x4000] {
        assert!(!prop_cell_word(high), "{high:#X}: bits outside the fields");
    }
}

/// Exhaustive over TV: all 4 000 valid S5TIME words x every kind x edge memories and S, R, FR
/// x three prior states (cleared, running, expired) x 0 or 1 tick.
#[test]
fn exhaustive_every_tv() {
    let mut n = 0u64;
    let mut checked = 0u64;
    for word in 0..=0x3FFFu16 {
        let Ok(tv) = S5Time::from_word(word) else {
            continue;
        };
        n += 1;
        for kind in S5Kind::ALL {
            for bits in 0..64u8 {
                for (running, value, q) in [(false, 0, false), (true, 7, true), (false, 0, true)] {
                    let state = S5State {
                        running,
                        value,
                        base: TimeBase::S1,
                        q,
                        q_on_expiry: running && is_on_delay(kind),
                        s_prev: bits & 8 != 0,
                        fr_prev: bits & 16 != 0,
                    };
                    let input = S5Input {
                        s: bits & 1 != 0,
                        r: bits & 2 != 0,
                        fr: bits & 4 != 0,
                        tv,
                    };
                    let ticks = u64::from(bits >> 5);
                    checked += u64::from(prop_step_equivalence(kind, state, ticks, input));
                    checked += u64::from(prop_invariants(kind, state, ticks, input));
                }
            }
        }
    }
    assert_eq!(n, 4_000, "every valid S5TIME word visited");
    assert_eq!(checked, 2 * 4_000 * 5 * 64 * 3, "every case checked");
}

/// Exhaustive: the expiry tick for every kind, every value 1..=999 and every base.
#[test]
fn exhaustive_expiry_on_vth_tick() {
    let mut checked = 0;
    for kind in S5Kind::ALL {
        for value in 1..=999 {
            for base in TimeBase::ALL {
                checked += u32::from(prop_expiry_on_vth_tick(kind, value, base));
            }
        }
    }
    assert_eq!(checked, 5 * 999 * 4, "every case checked");
}

/// S5-EQUIV-02: from the initial state, the input sequence `steps` (time step in ms, input)
/// gives the same outputs and states through the reference's `call`, a lone [`S5Timer`], a
/// one-timer [`TimerMemory`] box call, and the STL sequence the box compiles to (`FR`,
/// `SP`..`SF`, `R`, then `L`, `LC`, `A`) on a second area.
pub fn prop_sequence_equivalence(kind: S5Kind, steps: &[(u64, S5Input)]) {
    let mut r = S5TimerRef::new();
    let mut lone = S5Timer::new();
    let mut area = TimerMemory::<1>::new();
    let mut stl = TimerMemory::<1>::new();
    let mut t = CpuTime::ZERO;
    for &(dt, input) in steps {
        t = t.add_millis(dt);
        let a = r.call(kind, t, input);
        let b = area.call(0, kind, t, input).expect("timer 0 exists");
        assert_eq!(a, b, "S5-EQUIV-02 {kind:?} at t = {t:?}");
        assert_eq!(area.get(0), Ok(r.state()), "S5-EQUIV-02 state");
        assert_eq!(area.now(), t, "the area's clock follows the calls");
        assert_eq!(lone.call(kind, t, input), a, "S5-EQUIV-02 S5Timer at {t:?}");
        assert_eq!(lone.state(), r.state(), "S5-EQUIV-02 S5Timer state");
        stl.advance_to(t);
        let ops = [
            stl.fr(0, input.fr),
            stl.start(0, kind, input.s, input.tv),
            stl.reset(0, input.r),
        ];
        assert_eq!(ops, [Ok(()); 3], "timer 0 exists");
        let read = (stl.status(0), stl.load(0), stl.load_bcd(0));
        assert_eq!(
            read,
            (Ok(a.q), Ok(a.bi), Ok(a.bcd)),
            "S5-EQUIV-02 STL at t = {t:?}"
        );
        assert_eq!(stl.words(), area.words(), "S5-EQUIV-02 STL state");
    }
}

/// S5-AREA-01: `n` ticks of `tick_base` on an area of four timers in the states `states` equal
/// the reference tick of each timer whose base is `tick_base`, and leave the others unchanged.
pub fn prop_area_tick(states: [S5State; 4], tick_base: TimeBase, n: u64) -> bool {
    let mut words = [TimerWord::RESET; 4];
    for (w, &s) in words.iter_mut().zip(states.iter()) {
        match TimerWord::from_state(s) {
            Some(valid) => *w = valid,
            None => return false,
        }
    }
    let mut area = TimerMemory::<4>::from_words(words, CpuTime::ZERO);
    area.tick(tick_base, n);
    for (i, &state) in states.iter().enumerate() {
        let mut r = S5TimerRef::from_state(state, CpuTime::ZERO).expect("valid");
        if state.base == tick_base {
            r.tick(n);
        }
        assert_eq!(area.get(i), Ok(r.state()), "S5-AREA-01 timer {i}");
    }
    true
}

/// S5-EQUIV-02 driver: every input sequence of length 5 over 24 symbols (six S/R/FR patterns x
/// a time step of 0 ms, one 10 ms tick, 25 ms or 1 s) from the initial state. TV = 30 ms.
#[test]
fn bounded_sequences_reference_vs_memory_area() {
    const PATTERNS: [(bool, bool, bool); 6] = [
        (false, false, false),
        (true, false, false),
        (false, true, false),
        (true, true, false),
        (false, false, true),
        (true, false, true),
    ];
    const STEPS: [u64; 4] = [0, 10, 25, 1000];
    let tv = S5Time::from_word(0x0003).expect("valid word");
    let symbols = PATTERNS.len() * STEPS.len();
    let sequences = symbols.pow(5);
    thread::scope(|scope| {
        for kinds in [&S5Kind::ALL[..3], &S5Kind::ALL[3..]] {
            scope.spawn(move || {
                for &kind in kinds {
                    for mut code in 0..sequences {
                        let mut steps = [(0u64, S5Input::new(false, false, tv)); 5];
                        for step in steps.iter_mut() {
                            let sym = code % symbols;
                            code /= symbols;
                            let (s, r, fr) = PATTERNS[sym % PATTERNS.len()];
                            *step = (STEPS[sym / PATTERNS.len()], S5Input { s, r, fr, tv });
                        }
                        prop_sequence_equivalence(kind, &steps);
                    }
                }
            });
        }
    });
}

/// S5-AREA-01 driver: for every value 0..=999 and every (running, Q) pair, an area of four
/// timers holding that value in each of the four bases, ticked by each base.
#[test]
fn exhaustive_area_tick_per_base() {
    let mut checked = 0;
    for value in 0..=999u16 {
        for flags in 0..4u8 {
            let states = TimeBase::ALL.map(|base| S5State {
                running: flags & 1 != 0,
                value,
                base,
                q: flags & 2 != 0,
                q_on_expiry: false,
                s_prev: false,
                fr_prev: false,
            });
            for tick_base in TimeBase::ALL {
                for n in [0u64, 1, 2, 999, u64::MAX] {
                    checked += u32::from(prop_area_tick(states, tick_base, n));
                }
            }
        }
    }
    assert_eq!(checked, 1000 * 4 * 4 * 5, "every case checked");
}
