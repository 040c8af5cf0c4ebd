//! Properties of the S5 timers: the packed word simulates the reference, the invariants hold,
//! R resets, no start without a signal change, no panic.
//!
//! Each property is a plain function; `exhaustive_*` tests drive it over finite domains. A
//! property returns whether its premise held (the case was checked): the drivers count the
//! checked cases against the size of their domain, so that no driver can pass vacuously by
//! skipping every case.

use crate::cover::{check, check_eq};
use crate::domain::s5_timer_inputs;
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
    // Called at its previous call's time: no further tick, the box executes once.
    let out = r.call(kind, CpuTime::ZERO, input);
    (r.state(), out)
}

/// S5-EQUIV-01: for every valid state, tick count and input, one step of the packed word,
/// mapped through the abstraction function, equals one step of the reference, and the outputs
/// agree. By induction over the steps this covers every trace.
pub fn prop_step_equivalence(kind: S5Kind, state: S5State, ticks: u64, input: S5Input) -> bool {
    let Some(w) = TimerWord::from_state(state) else {
        return false;
    };
    check_eq!(
        w.state(),
        state,
        "S5-EQUIV-01: abstraction inverts from_state"
    );
    let (r_state, r_out) = reference_step(kind, state, ticks, input);
    let w = w.tick(ticks).execute(kind, input);
    check_eq!(
        w.state(),
        r_state,
        "S5-EQUIV-01 {kind:?} {state:?} {ticks} {input:?}"
    );
    check_eq!(
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
    check!(after.value <= 999, "S5TMR-RANGE-01: value {}", after.value);
    check!(
        S5Time::from_word(out.bcd).is_ok_and(|t| t.units() == out.bi),
        "S5TMR-RANGE-01: BCD {:#06X} is the BCD form of BI {}",
        out.bcd,
        out.bi
    );
    check_eq!(
        out.bcd & 0xC000,
        0,
        "S5TMR-RANGE-01: bits 15-14 are never produced"
    );
    if input.r {
        check_eq!(
            (after.running, after.value, after.base, after.q),
            (false, 0, TimeBase::Ms10, false),
            "S5TMR-R-01: R = 1 resets"
        );
    }
    if !start_signal(kind, &state, &input) {
        check!(
            !after.running || state.running,
            "S5TMR-EDGE-01: started without a signal change"
        );
        check!(
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
    check!(
        r.state().running && r.state().value == 1,
        "S5TMR-TICK-01: still running before the v-th tick"
    );
    r.tick(1);
    check!(
        !r.state().running && r.state().value == 0,
        "S5TMR-TICK-01: run out on the v-th tick"
    );
    check_eq!(
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
            check!(
                state.is_valid(),
                "S5-EQUIV-01: a valid word has a valid state"
            );
            check_eq!(
                TimerWord::from_state(state),
                Some(w),
                "S5-EQUIV-01: from_state inverts the abstraction: {bits:#010X}"
            );
            check_eq!(w.bits(), bits);
            check_eq!(
                (w.value(), w.base(), w.q(), w.is_running()),
                (state.value, state.base, state.q, state.running),
                "S5-EQUIV-01: the word's accessors read its state: {bits:#010X}"
            );
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
    check!(
        kind_invariant(kind, &after),
        "{kind:?}: invariant broken by {input:?} from {state:?}"
    );
    if input.r {
        return true;
    }
    match kind {
        S5Kind::SPulse | S5Kind::SOdt if !input.s => {
            check!(!after.running, "SP-Q-01 / SD-Q-01: S = 0 stops the timer");
        }
        S5Kind::SPext | S5Kind::SOdts
            if state.running && !input.s && ticks < u64::from(state.value) =>
        {
            check!(
                after.running,
                "SE-RUN-ON-01 / SS-Q-01: runs on when S falls"
            );
        }
        S5Kind::SOffdt if input.s != s_memory_after_fr(&state, &input) => {
            check!(after.q, "SF-Q-01: an edge at S sets Q");
        }
        _ => {}
    }
    true
}

/// Every valid S5 state: value 0..=999, four bases, the five flags with no expiry status on a
/// stopped timer (24 combinations): 96 000 states.
pub fn all_states() -> impl Iterator<Item = S5State> {
    states_with_values(0..=999u16)
}

/// Every valid S5 state with one of `values`: four bases, the five flags with no expiry status
/// on a stopped timer (24 combinations per value and base).
pub fn states_with_values(values: impl IntoIterator<Item = u16>) -> impl Iterator<Item = S5State> {
    values.into_iter().flat_map(|value| {
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
            for input in s5_timer_inputs(tv) {
                f(ticks, input);
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
        check_eq!(
            (n[0], n[1]),
            (per_kind, per_kind),
            "{kind:?}: cases checked"
        );
        check!(
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
    check_eq!(valid, 1000 * 4 * 24);
    for high in [1u32 << 21, 1 << 31, u32::MAX, 0x0400, 0x4000] {
        check!(!prop_cell_word(high), "{high:#X}: bits outside the fields");
    }
}

/// `TimerMemory::set_state` over every valid state (96 000) on the middle timer of three: the
/// timer then holds exactly that state (`get`), its neighbours keep theirs, and `Ok(true)` says
/// so; an invalid state (value above 999, an expiry status on a stopped timer) is refused with
/// `Ok(false)` and changes nothing; an index past the area is an error. The oracle is the state
/// itself.
#[test]
fn exhaustive_area_set_state() {
    let running = S5State {
        running: true,
        value: 500,
        base: TimeBase::Ms100,
        q: true,
        q_on_expiry: false,
        s_prev: true,
        fr_prev: false,
    };
    let expired = S5State {
        running: false,
        value: 0,
        base: TimeBase::S10,
        q: true,
        q_on_expiry: false,
        s_prev: false,
        fr_prev: true,
    };
    let mut area = TimerMemory::<3>::new();
    check_eq!(
        area.set_state(0, running),
        Ok(true),
        "set_state: a valid state is taken"
    );
    check_eq!(
        area.set_state(2, expired),
        Ok(true),
        "set_state: a valid state is taken"
    );
    let mut n = 0u32;
    for state in all_states() {
        check_eq!(
            area.set_state(1, state),
            Ok(true),
            "set_state: {state:?} is valid"
        );
        check_eq!(
            area.get(1),
            Ok(state),
            "set_state: the timer holds the state set"
        );
        check!(
            area.get(0) == Ok(running) && area.get(2) == Ok(expired),
            "set_state: the other timers keep their states ({state:?})"
        );
        check!(
            area.set_state(3, state).is_err(),
            "set_state: no timer 3 in an area of 3"
        );
        n += 1;
    }
    check_eq!(n, 96_000);
    let before = area.get(1);
    for bad in [
        S5State {
            value: 1000,
            ..running
        },
        S5State {
            value: u16::MAX,
            ..expired
        },
        S5State {
            q_on_expiry: true,
            ..expired
        },
    ] {
        check_eq!(
            area.set_state(1, bad),
            Ok(false),
            "set_state: {bad:?} is refused"
        );
        check_eq!(
            area.get(1),
            before,
            "set_state: a refused state changes nothing"
        );
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
    check_eq!(n, 4_000, "every valid S5TIME word visited");
    check_eq!(checked, 2 * 4_000 * 5 * 64 * 3, "every case checked");
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
    check_eq!(checked, 5 * 999 * 4, "every case checked");
}

/// S5-EQUIV-02: from the initial state, the input sequence `steps` (time step in ms, input)
/// gives the same outputs and states through the reference's `call`, a lone [`S5Timer`], a
/// one-timer [`TimerMemory`] box call, and the STL sequence the box compiles to (`FR`,
/// `SP`..`SF`, `R`, then `L`, `LC`, `A`) on a second area.
pub fn prop_sequence_equivalence(kind: S5Kind, steps: &[(u64, S5Input)]) {
    prop_sequence_equivalence_from(kind, S5State::RESET, steps);
}

/// [`prop_sequence_equivalence`] from a valid state `initial` at time 0 instead of power-up.
pub fn prop_sequence_equivalence_from(kind: S5Kind, initial: S5State, steps: &[(u64, S5Input)]) {
    let w = TimerWord::from_state(initial).expect("a valid state");
    let mut r = S5TimerRef::from_state(initial, CpuTime::ZERO).expect("valid");
    let mut lone = S5Timer::from_state(initial, CpuTime::ZERO).expect("valid");
    let mut area = TimerMemory::<1>::from_words([w], CpuTime::ZERO);
    let mut stl = TimerMemory::<1>::from_words([w], CpuTime::ZERO);
    let mut t = CpuTime::ZERO;
    for &(dt, input) in steps {
        t = t.add_millis(dt);
        let a = r.call(kind, t, input);
        let b = area.call(0, kind, t, input).expect("timer 0 exists");
        check_eq!(a, b, "S5-EQUIV-02 {kind:?} at t = {t:?}");
        check_eq!(area.get(0), Ok(r.state()), "S5-EQUIV-02 state");
        check_eq!(area.now(), t, "the area's clock follows the calls");
        check_eq!(lone.call(kind, t, input), a, "S5-EQUIV-02 S5Timer at {t:?}");
        check_eq!(lone.state(), r.state(), "S5-EQUIV-02 S5Timer state");
        stl.advance_to(t);
        let ops = [
            stl.fr(0, input.fr),
            stl.start(0, kind, input.s, input.tv),
            stl.reset(0, input.r),
        ];
        check_eq!(ops, [Ok(()); 3], "timer 0 exists");
        let read = (stl.status(0), stl.load(0), stl.load_bcd(0));
        check_eq!(
            read,
            (Ok(a.q), Ok(a.bi), Ok(a.bcd)),
            "S5-EQUIV-02 STL at t = {t:?}"
        );
        check!(stl.words().eq(area.words()), "S5-EQUIV-02 STL state");
    }
}

/// S5TMR-CLOCK-01: called at the CPU times of `steps` (absolute, in any order, the first
/// execution after time 0) from the valid state `initial`, every S5 form behaves as the
/// reference called at the latest time seen so far: a step back applies no tick, and the span
/// it went back is not counted again when the clock comes forward. The oracle is that monotone
/// clock (whose behaviour S5-EQUIV-02 and the rule properties check); the forms checked are the
/// reference, a lone [`S5Timer`] and a one-timer [`TimerMemory`] box.
#[covers]
pub fn prop_backward_clock(kind: S5Kind, initial: S5State, steps: &[(u64, S5Input)]) -> bool {
    let Some(w) = TimerWord::from_state(initial) else {
        return false;
    };
    let valid = "a valid state";
    let mut oracle = S5TimerRef::from_state(initial, CpuTime::ZERO).expect(valid);
    let mut r = oracle;
    let mut lone = S5Timer::from_state(initial, CpuTime::ZERO).expect(valid);
    let mut area = TimerMemory::<1>::from_words([w], CpuTime::ZERO);
    let mut latest = CpuTime::ZERO;
    for &(t, input) in steps {
        let t = CpuTime::from_millis(t);
        cover!(
            t < latest && oracle.state().running,
            "S5TMR-CLOCK-01: the clock goes back under a running timer"
        );
        latest = latest.max(t);
        let expected = oracle.call(kind, latest, input);
        check_eq!(
            r.call(kind, t, input),
            expected,
            "S5TMR-CLOCK-01 reference at {t:?}"
        );
        check_eq!(r.state(), oracle.state(), "S5TMR-CLOCK-01 reference state");
        check_eq!(r.last_call(), latest, "S5TMR-CLOCK-01 reference clock");
        check_eq!(
            lone.call(kind, t, input),
            expected,
            "S5TMR-CLOCK-01 S5Timer at {t:?}"
        );
        check_eq!(lone.state(), oracle.state(), "S5TMR-CLOCK-01 S5Timer state");
        check_eq!(lone.last_call(), latest, "S5TMR-CLOCK-01 S5Timer clock");
        let b = area.call(0, kind, t, input).expect("timer 0 exists");
        check_eq!(b, expected, "S5TMR-CLOCK-01 area at {t:?}");
        check_eq!(area.get(0), Ok(oracle.state()), "S5TMR-CLOCK-01 area state");
        check_eq!(area.now(), latest, "S5TMR-CLOCK-01 area clock");
    }
    true
}

/// S5TMR-CLOCK-01 driver: every sequence of four executions over 20 symbols (S, R, FR patterns
/// x the absolute times 0, 9, 10, 30 and 45 ms, so that the clock goes back, stands and comes
/// forward across ticks) from the initial state, for every kind. TV = 30 ms (3 ticks).
#[test]
fn exhaustive_backward_clock() {
    const PATTERNS: [(bool, bool, bool); 4] = [
        (false, false, false),
        (true, false, false),
        (false, true, false),
        (true, false, true),
    ];
    const TIMES: [u64; 5] = [0, 9, 10, 30, 45];
    let tv = S5Time::from_word(0x0003).expect("valid word");
    let symbols = PATTERNS.len() * TIMES.len();
    let sequences = symbols.pow(4);
    crate::cover::check_ids(&["S5TMR-CLOCK-01"], || {
        let mut checked = 0usize;
        for kind in S5Kind::ALL {
            for mut code in 0..sequences {
                let mut steps = [(0u64, S5Input::new(false, false, tv)); 4];
                for step in steps.iter_mut() {
                    let sym = code % symbols;
                    code /= symbols;
                    let (s, r, fr) = PATTERNS[sym % PATTERNS.len()];
                    *step = (TIMES[sym / PATTERNS.len()], S5Input { s, r, fr, tv });
                }
                checked += usize::from(prop_backward_clock(kind, S5State::RESET, &steps));
            }
        }
        check_eq!(checked, 5 * sequences, "every case checked");
    });
}

/// S5-AREA-01: `n` ticks of `tick_base` on an area of `N` timers in the states `states` equal
/// the reference tick of each timer whose base is `tick_base`, and leave the others unchanged.
pub fn prop_area_tick<const N: usize>(states: [S5State; N], tick_base: TimeBase, n: u64) -> bool {
    let mut words = [TimerWord::RESET; N];
    for (w, &s) in words.iter_mut().zip(states.iter()) {
        match TimerWord::from_state(s) {
            Some(valid) => *w = valid,
            None => return false,
        }
    }
    let mut area = TimerMemory::<N>::from_words(words, CpuTime::ZERO);
    area.tick(tick_base, n);
    for (i, &state) in states.iter().enumerate() {
        let mut r = S5TimerRef::from_state(state, CpuTime::ZERO).expect("valid");
        if state.base == tick_base {
            r.tick(n);
        }
        check_eq!(area.get(i), Ok(r.state()), "S5-AREA-01 timer {i}");
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
    crate::cover::check_ids(&["S5-AREA-01"], || {
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
        check_eq!(checked, 1000 * 4 * 4 * 5, "every case checked");
    });
}

// ---------------------------------------------------------------------------------------------
// One property per requirement. The oracle is the rule's text as a predicate over one step
// (pre-state, ticks, input, post-state, outputs), with a closed-form model of the tick rule
// (`ticked`); each property checks every implementation: the reference, the packed word, a
// timer memory area (tick per base, then the box's STL sequence FR, SP..SF, R, and the reads L,
// LC, A) and, outside Kani, an `S5Timer` and an area box called at a time that gives the ticks.
// ---------------------------------------------------------------------------------------------

use crate::cover::{cover, covers};

/// One step of the S5 box: the kind, the state before, the OS ticks of the timer's base since
/// its previous execution, and the inputs.
#[derive(Clone, Copy, Debug, bolero::TypeGenerator)]
pub struct S5Case {
    /// The box.
    pub kind: S5Kind,
    /// The state before (valid).
    pub state: S5State,
    /// The ticks of the timer's base before the execution.
    pub ticks: u64,
    /// S, R, FR, TV.
    pub input: S5Input,
}

/// `c` moved near the end of its time: at most 3 ticks and a value below 4 (still valid). A
/// case of every harness's domain, which random `u64` tick counts and values up to 999 almost
/// never reach: a running timer that a few ticks leave running or run out exactly. Harnesses run
/// it beside each random case under `cargo test` (Kani covers it with the rest).
pub fn near_expiry(c: S5Case) -> S5Case {
    S5Case {
        ticks: c.ticks % 4,
        state: S5State {
            value: c.state.value % 4,
            ..c.state
        },
        ..c
    }
}

/// `c` at the top of the range: value 999 in the 10 s base, no tick, TV = 9 990 s (a valid state
/// whatever else `c` holds). A case of every harness's domain that random values seldom reach
/// (one TV in 4 000); run beside each random case under `cargo test`, as [`near_expiry`].
pub fn at_top(c: S5Case) -> S5Case {
    S5Case {
        ticks: 0,
        state: S5State {
            value: 999,
            base: TimeBase::S10,
            ..c.state
        },
        input: S5Input {
            tv: S5Time::MAX,
            ..c.input
        },
        ..c
    }
}

/// Whether the kind is an on-delay (written here from LAD manual §9.5-9.6, not taken from the
/// reference).
fn on_delay(kind: S5Kind) -> bool {
    matches!(kind, S5Kind::SOdt | S5Kind::SOdts)
}

/// The tick rule in closed form (S5TMR-TICK-01, S5TMR-EXPIRE-01): `n` ticks take
/// `min(n, value)` units off a running timer; reaching 0 stops it and Q takes the status its
/// start chose. A stopped timer, or one started with value 0, is left alone.
pub fn ticked(st: S5State, n: u64) -> S5State {
    if !st.running || st.value == 0 {
        return st;
    }
    if n >= u64::from(st.value) {
        S5State {
            running: false,
            value: 0,
            q: st.q_on_expiry,
            q_on_expiry: false,
            ..st
        }
    } else {
        S5State {
            value: st.value - n as u16,
            ..st
        }
    }
}

/// What the start logic of the execution sees: the ticks applied, and a running timer of value
/// 0 found run out (S5TMR-ZERO-01).
pub fn seen(st: S5State, n: u64) -> S5State {
    let t = ticked(st, n);
    if t.running && t.value == 0 {
        S5State {
            running: false,
            q: t.q_on_expiry,
            q_on_expiry: false,
            ..t
        }
    } else {
        t
    }
}

impl S5Case {
    fn fr_rising(&self) -> bool {
        self.input.fr && !self.state.fr_prev
    }
    /// The S memory after FR (S5TMR-FR-01).
    fn memory(&self) -> bool {
        self.state.s_prev && !self.fr_rising()
    }
    fn rising(&self) -> bool {
        self.input.s && !self.memory()
    }
    fn falling(&self) -> bool {
        !self.input.s && self.memory()
    }
    /// The kind's start signal (S5TMR-EDGE-01).
    fn starts(&self) -> bool {
        if self.kind == S5Kind::SOffdt {
            self.falling()
        } else {
            self.rising()
        }
    }
    fn with_state(self, state: S5State) -> S5Case {
        S5Case { state, ..self }
    }
    fn with_input(self, input: S5Input) -> S5Case {
        S5Case { input, ..self }
    }
}

/// The implementations a step runs through.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum S5Impl {
    /// `S5TimerRef::tick` then `execute`.
    Reference,
    /// `TimerWord::tick` then `execute`.
    Word,
    /// `TimerMemory::tick` of the timer's base, then the STL operations `FR`, `SP`..`SF`, `R`.
    AreaStl,
    /// `S5Timer::call` at a CPU time that gives the ticks (a division by the base: not under
    /// Kani, which has `kani_s5_timer_call_*` with a fixed base).
    Timer,
    /// `TimerMemory::call` (`advance_to`, then the box) at that time.
    AreaCall,
}

/// Every implementation a harness body checks.
#[cfg(not(kani))]
pub const IMPLS: [S5Impl; 5] = [
    S5Impl::Reference,
    S5Impl::Word,
    S5Impl::AreaStl,
    S5Impl::Timer,
    S5Impl::AreaCall,
];
/// Every implementation a harness body checks (without the divisions by a symbolic base).
#[cfg(kani)]
pub const IMPLS: [S5Impl; 3] = [S5Impl::Reference, S5Impl::Word, S5Impl::AreaStl];

/// The CPU time, from a previous execution at 0, that gives `ticks` ticks of `base`.
fn time_for(ticks: u64, base: TimeBase) -> CpuTime {
    let b = u64::from(base.millis());
    CpuTime::from_millis(ticks.min(u64::MAX / b) * b)
}

/// One step through `imp`: the state after and the outputs; for the area, also the STL reads
/// (`L`, `LC`, `A`) checked against the outputs (S5TMR-LOAD-01).
pub fn run(imp: S5Impl, c: S5Case) -> (S5State, S5Output) {
    let S5Case {
        kind,
        state,
        ticks,
        input,
    } = c;
    match imp {
        S5Impl::Reference => reference_step(kind, state, ticks, input),
        S5Impl::Word => {
            let w = TimerWord::from_state(state)
                .expect("a valid state")
                .tick(ticks)
                .execute(kind, input);
            (w.state(), w.output())
        }
        S5Impl::AreaStl => {
            // T 1 is the timer; T 0 a neighbour of another base that must not change.
            let w = TimerWord::from_state(state).expect("a valid state");
            let other = TimerWord::from_state(S5State {
                running: true,
                value: 5,
                base: TimeBase::from_bits(state.base.bits() + 1),
                ..S5State::RESET
            })
            .expect("valid");
            let mut area = TimerMemory::<2>::from_words([other, w], CpuTime::ZERO);
            area.tick(state.base, ticks);
            let ops = [
                area.fr(1, input.fr),
                area.start(1, kind, input.s, input.tv),
                area.reset(1, input.r),
            ];
            check_eq!(ops, [Ok(()); 3], "timer 1 exists");
            check_eq!(
                area.words().next().expect("T 0"),
                other,
                "S5-AREA-01: T 0 of another base untouched"
            );
            let after = area.get(1).expect("timer 1 exists");
            let out = S5Output {
                q: area.status(1).expect("T 1"),
                bi: area.load(1).expect("T 1"),
                bcd: area.load_bcd(1).expect("T 1"),
            };
            (after, out)
        }
        S5Impl::Timer => {
            let mut t = S5Timer::from_state(state, CpuTime::ZERO).expect("a valid state");
            let out = t.call(kind, time_for(ticks, state.base), input);
            (t.state(), out)
        }
        S5Impl::AreaCall => {
            let w = TimerWord::from_state(state).expect("a valid state");
            let mut area = TimerMemory::<1>::from_words([w], CpuTime::ZERO);
            let out = area
                .call(0, kind, time_for(ticks, state.base), input)
                .expect("T 0");
            (area.get(0).expect("T 0"), out)
        }
    }
}

/// S5TMR-TICK-01 and S5TMR-EXPIRE-01 on the OS tick alone, in every implementation that has
/// one (the reference's `tick`, the word's `tick`, the area's per-base `tick`), against the
/// closed form [`ticked`].
#[covers]
pub fn prop_tick(state: S5State, n: u64) -> bool {
    if !state.is_valid() {
        return false;
    }
    let expected = ticked(state, n);
    let mut r = S5TimerRef::from_state(state, CpuTime::ZERO).expect("valid");
    r.tick(n);
    let w = TimerWord::from_state(state).expect("valid").tick(n);
    let mut area = TimerMemory::<1>::from_words(
        [TimerWord::from_state(state).expect("valid")],
        CpuTime::ZERO,
    );
    area.tick(state.base, n);
    for (name, after) in [
        ("reference", r.state()),
        ("word", w.state()),
        ("area", area.get(0).expect("T 0")),
    ] {
        check_eq!(
            after.value, expected.value,
            "S5TMR-TICK-01: {name}: {n} ticks take min(n, value) units off a running timer: {state:?}"
        );
        check_eq!(
            (after.base, after.s_prev, after.fr_prev),
            (state.base, state.s_prev, state.fr_prev),
            "S5TMR-TICK-01: {name}: a tick changes only value and status"
        );
        check_eq!(
            (after.running, after.q),
            (expected.running, expected.q),
            "S5TMR-EXPIRE-01: {name}: at 0 the timer stops and Q takes its expiry status: {state:?} {n}"
        );
    }
    let expires = state.running && state.value > 0 && n >= u64::from(state.value);
    cover!(expires, "S5TMR-EXPIRE-01: a tick runs a timer out");
    cover!(
        state.running && state.value > 0 && n > 0 && !expires,
        "S5TMR-TICK-01: a tick leaves time"
    );
    true
}

/// The OS ticks of a base of `b` ms in the CPU-time interval `(from, to]`, counted one
/// millisecond at a time as S5TMR-TICK-01 states them (a tick on every whole multiple of the
/// base), not with the crate's `ticks_between`. Linear in `to - from`: for the concrete drivers.
pub fn ticks_in(from: u64, to: u64, b: u64) -> u64 {
    (from.saturating_add(1)..=to).filter(|t| t % b == 0).count() as u64
}

/// S5TMR-TICK-01 (the tick instants): a running S_PEXT of value 999 executed at `from` and
/// again at `to` (S held, no edge) has lost exactly the ticks of its base in `(from, to]`
/// ([`ticks_in`]), through the reference's `call`, an `S5Timer`, an area's box call and an
/// area's `advance_to`. Returns the tick count.
pub fn prop_tick_instants(base: TimeBase, from: u64, to: u64) -> u64 {
    let n = ticks_in(from, to, u64::from(base.millis()));
    let state = S5State {
        running: true,
        value: 999,
        base,
        q: true,
        q_on_expiry: false,
        s_prev: true,
        fr_prev: false,
    };
    let expected = 999 - n.min(999) as u16;
    let input = S5Input {
        s: true,
        r: false,
        fr: false,
        tv: S5Time::new(999, base).expect("valid"),
    };
    let (from_t, to_t) = (CpuTime::from_millis(from), CpuTime::from_millis(to));
    let mut r = S5TimerRef::from_state(state, from_t).expect("valid");
    let mut lone = S5Timer::from_state(state, from_t).expect("valid");
    let w = TimerWord::from_state(state).expect("valid");
    let mut area = TimerMemory::<1>::from_words([w], from_t);
    let mut moved = TimerMemory::<1>::from_words([w], from_t);
    r.call(S5Kind::SPext, to_t, input);
    lone.call(S5Kind::SPext, to_t, input);
    area.call(0, S5Kind::SPext, to_t, input).expect("T 0");
    moved.advance_to(to_t);
    for (name, value) in [
        ("reference call", r.state().value),
        ("S5Timer call", lone.state().value),
        ("area call", area.get(0).expect("T 0").value),
        ("area advance_to", moved.get(0).expect("T 0").value),
    ] {
        check_eq!(
            value, expected,
            "S5TMR-TICK-01: {name}: {n} ticks of {base:?} in ({from}, {to}] ms, one per whole multiple"
        );
    }
    n
}

/// S5TMR-TICK-01's instants for every base: previous executions just before, at and just after
/// a multiple of the base (near 0 and near 2^40 ms), and intervals from 0 to five bases and a
/// few ms, so that every position of both ends relative to the multiples occurs.
#[test]
fn exhaustive_tick_instants() {
    crate::cover::check_ids(&["S5TMR-TICK-01"], || {
        let mut ticked = 0;
        for base in TimeBase::ALL {
            let b = u64::from(base.millis());
            for k in [0u64, 1, 2, 1 << 40] {
                for from in [k * b, k * b + 1, (k + 1) * b - 1] {
                    for dt in [
                        0,
                        1,
                        b - 1,
                        b,
                        b + 1,
                        2 * b - 1,
                        2 * b,
                        2 * b + 1,
                        5 * b + 3,
                    ] {
                        ticked += prop_tick_instants(base, from, from + dt);
                    }
                }
            }
        }
        check!(ticked > 0, "S5TMR-TICK-01: some interval holds a tick");
    });
}

/// The status a timer of `kind` shows in the reachable states (the per-kind invariant, proved
/// inductive by [`prop_kind_rules`]): the per-kind rules below are stated from these states.
fn reachable(c: &S5Case) -> bool {
    kind_invariant(c.kind, &c.state)
}

/// Every S5 rule on one step through `imp`. Returns whether the step was checked.
#[covers]
pub fn check_s5_rules(imp: S5Impl, c: S5Case) -> bool {
    if !c.state.is_valid() {
        return false;
    }
    let (post, out) = run(imp, c);
    let seen = seen(c.state, c.ticks);
    let tv = c.input.tv;
    let loaded = |p: &S5State| p.value == tv.units() && p.base == tv.base();
    rule_range(imp, c, &post, &out);
    rule_r(imp, c, &post, &out);
    rule_edge(imp, c, &post);
    rule_zero(imp, c, &post);
    rule_fr(imp, c, &post);
    rule_expire_start(imp, c, &post);
    if c.input.r {
        return true;
    }
    if c.starts() {
        check!(
            post.running && loaded(&post),
            "S5TMR-EDGE-01: {imp:?}: a start loads TV and runs: {c:?} -> {post:?}"
        );
    }
    // S5TMR-STOP-01: S = 0 stops S_PULSE and S_ODT; the value is kept, Q = 0.
    if matches!(c.kind, S5Kind::SPulse | S5Kind::SOdt) && !c.input.s && seen.running {
        check!(
            !post.running && !post.q && post.value == seen.value && post.base == seen.base,
            "S5TMR-STOP-01: {imp:?}: S = 0 stops, value kept, Q = 0: {c:?} -> {post:?}"
        );
    }
    cover!(
        matches!(c.kind, S5Kind::SPulse | S5Kind::SOdt)
            && !c.input.s
            && seen.running
            && seen.value > 0,
        "S5TMR-STOP-01: a running S_PULSE or S_ODT sees S = 0"
    );
    if !reachable(&c) {
        return true;
    }
    let held = !c.rising() && !c.falling();
    match c.kind {
        S5Kind::SPulse => {
            if c.rising() {
                check!(
                    post.q && post.running && loaded(&post),
                    "SP-Q-01: {imp:?}: a rising S starts the pulse with TV, Q = 1 (even while it runs): {c:?}"
                );
            } else if !c.input.s {
                check!(
                    !post.q && !post.running,
                    "SP-Q-01: {imp:?}: S = 0: Q = 0: {c:?}"
                );
            } else {
                check_eq!(
                    (post.running, post.q),
                    (seen.running, seen.running),
                    "SP-Q-01: {imp:?}: with S held Q = 1 exactly while it runs; Q = 0 when the time runs out: {c:?}"
                );
            }
            cover!(
                c.rising() && c.state.running,
                "SP-Q-01: restart of a running pulse (FR)"
            );
        }
        S5Kind::SPext => {
            if c.rising() {
                check!(
                    post.q && post.running && loaded(&post),
                    "SE-RUN-ON-01: {imp:?}: a rising S (re)starts with TV, Q = 1: {c:?}"
                );
            } else {
                check_eq!(
                    (post.running, post.q, post.value),
                    (seen.running, seen.running, seen.value),
                    "SE-RUN-ON-01: {imp:?}: runs on whatever S does, Q = 1 while it runs: {c:?}"
                );
            }
            cover!(
                !c.input.s && seen.running,
                "SE-RUN-ON-01: runs on after S fell"
            );
        }
        S5Kind::SOdt => {
            if c.rising() {
                check!(
                    !post.q && post.running && loaded(&post),
                    "SD-Q-01: {imp:?}: a (re)start reloads TV with Q = 0: {c:?}"
                );
            } else if !c.input.s {
                check!(
                    !post.q && !post.running,
                    "SD-Q-01: {imp:?}: S = 0 stops, Q = 0: {c:?}"
                );
            } else {
                check_eq!(
                    (post.running, post.q),
                    (seen.running, !seen.running && seen.q),
                    "SD-Q-01: {imp:?}: with S held Q = 1 once the time has run out: {c:?}"
                );
            }
            cover!(
                c.input.s && held && c.state.running && !seen.running,
                "SD-Q-01: the on-delay runs out with S held"
            );
        }
        S5Kind::SOdts => {
            if c.state.q {
                check!(post.q, "SS-Q-01: {imp:?}: Q = 1 stays until R: {c:?}");
            }
            if c.rising() {
                check!(
                    post.running && loaded(&post) && post.q == seen.q,
                    "SS-Q-01: {imp:?}: a rising S restarts with TV, Q kept: {c:?}"
                );
            } else {
                check_eq!(
                    (post.running, post.q, post.value),
                    (seen.running, seen.q, seen.value),
                    "SS-Q-01: {imp:?}: runs on whatever S does; Q = 1 once run out: {c:?}"
                );
            }
            cover!(
                c.rising() && seen.q,
                "SS-Q-01: restart after expiry keeps Q = 1"
            );
        }
        S5Kind::SOffdt => {
            if c.falling() {
                check!(
                    post.q && post.running && loaded(&post),
                    "SF-Q-01: {imp:?}: a falling S starts the off-delay, Q = 1: {c:?}"
                );
            } else if c.rising() {
                check!(
                    post.q && !post.running && post.value == seen.value,
                    "SF-Q-01: {imp:?}: a rising S sets Q = 1 and stops the time, value kept: {c:?}"
                );
            } else {
                check_eq!(
                    (post.running, post.q, post.value),
                    (seen.running, seen.q, seen.value),
                    "SF-Q-01: {imp:?}: without an edge Q is the status bit: kept, 0 when run out: {c:?}"
                );
            }
            cover!(
                c.rising() && c.state.running,
                "SF-Q-01: a rising S stops a running off-delay"
            );
        }
    }
    true
}

/// S5TMR-RANGE-01 (and S5TMR-LOAD-01 for the area's reads): the value fits 0..=999; BCD is the
/// valid three-digit form of BI with the base in bits 13-12 and bits 15-14 zero; the duration
/// the BCD word shows (its digits times the base its bits 13-12 name) is the state's; the value
/// and base come from the state before or from the TV (so at most 9 990 s, 999 units of 10 s).
#[covers]
fn rule_range(imp: S5Impl, c: S5Case, post: &S5State, out: &S5Output) {
    check!(
        post.value <= 999,
        "S5TMR-RANGE-01: {imp:?}: value {}",
        post.value
    );
    let digits = [(out.bcd >> 8) & 0xF, (out.bcd >> 4) & 0xF, out.bcd & 0xF];
    check!(
        digits.iter().all(|&d| d <= 9),
        "S5TMR-RANGE-01: {imp:?}: BCD {:#06X} has a digit above 9",
        out.bcd
    );
    check_eq!(
        digits[0] * 100 + digits[1] * 10 + digits[2],
        out.bi,
        "S5TMR-RANGE-01: {imp:?}: BCD {:#06X} is the BCD form of BI {}",
        out.bcd,
        out.bi
    );
    check_eq!(
        out.bcd >> 14,
        0,
        "S5TMR-RANGE-01: {imp:?}: bits 15-14 are never produced"
    );
    check_eq!(
        u8::try_from((out.bcd >> 12) & 3).expect("two bits"),
        post.base.bits(),
        "S5TMR-RANGE-01: {imp:?}: BCD bits 13-12 are the time base"
    );
    let base_ms = [10u32, 100, 1_000, 10_000][usize::from((out.bcd >> 12) & 3)];
    let shown = u32::from(out.bi) * base_ms;
    check_eq!(
        shown,
        u32::from(post.value) * post.base.millis(),
        "S5TMR-RANGE-01: {imp:?}: the BCD word shows the state's duration"
    );
    // The 9 990 s cap follows from the value's range and the base; what can break is where the
    // value comes from: a step only counts a value down or loads the TV (or R clears it).
    let tv = c.input.tv;
    check!(
        post.value <= c.state.value.max(tv.units())
            && (post.base == c.state.base || post.base == tv.base() || c.input.r),
        "S5TMR-RANGE-01: {imp:?}: the value and base come from the state or the TV: {c:?} -> {post:?}"
    );
    if imp == S5Impl::AreaStl {
        // Only here are the outputs the STL reads (`A`, `L`, `LC`), not the state itself.
        check_eq!(
            (out.q, out.bi),
            (post.q, post.value),
            "S5TMR-LOAD-01: {imp:?}: A T and L T read the status and the value"
        );
    }
    cover!(
        out.bcd & 0x3000 == 0x3000 && out.bi == 999,
        "S5TMR-RANGE-01: 9 990 s shown"
    );
}

/// S5TMR-R-01: R = 1 leaves the timer stopped, value and base 0, Q = 0, for every kind, running
/// or not; the S memory still takes S. S5TMR-LOAD-01: after R, L and LC read 0.
#[covers]
fn rule_r(imp: S5Impl, c: S5Case, post: &S5State, out: &S5Output) {
    if !c.input.r {
        return;
    }
    check!(
        !post.running && post.value == 0 && post.base == TimeBase::Ms10 && !post.q,
        "S5TMR-R-01: {imp:?}: R = 1 resets: {c:?} -> {post:?}"
    );
    check_eq!(
        post.s_prev,
        c.input.s,
        "S5TMR-R-01: {imp:?}: the S memory is still updated"
    );
    check_eq!(
        (out.bi, out.bcd, out.q),
        (0, 0, false),
        "S5TMR-LOAD-01: {imp:?}: after R, L T and LC T read 0"
    );
    cover!(
        c.state.running && c.starts(),
        "S5TMR-R-01: R in the execution of a start"
    );
}

/// S5TMR-EDGE-01: without its start signal (a change of S in the kind's direction, against the
/// memory as FR leaves it) no timer starts or reloads, and the base changes only by R.
#[covers]
fn rule_edge(imp: S5Impl, c: S5Case, post: &S5State) {
    if c.starts() {
        return;
    }
    check!(
        !post.running || c.state.running,
        "S5TMR-EDGE-01: {imp:?}: started without a signal change: {c:?}"
    );
    check!(
        post.value <= c.state.value && (post.base == c.state.base || c.input.r),
        "S5TMR-EDGE-01: {imp:?}: reloaded without a signal change: {c:?}"
    );
    cover!(
        c.input.s && c.state.s_prev && !c.fr_rising(),
        "S5TMR-EDGE-01: S held at 1"
    );
}

/// S5TMR-ZERO-01: a timer started with the value 0 stays active in the starting execution and
/// is found run out at its next execution, even with no tick.
#[covers]
fn rule_zero(imp: S5Impl, c: S5Case, post: &S5State) {
    if c.input.r {
        return;
    }
    if c.starts() && c.input.tv.units() == 0 {
        check!(
            post.running && post.value == 0,
            "S5TMR-ZERO-01: {imp:?}: a start with value 0 stays active in its execution: {c:?}"
        );
    }
    // The next execution: no new edge, and (for S_PULSE and S_ODT) S held at 1, which would
    // otherwise stop the timer by its own rule.
    let quiet = !c.rising()
        && !c.falling()
        && (c.input.s || !matches!(c.kind, S5Kind::SPulse | S5Kind::SOdt));
    if c.state.running && c.state.value == 0 && quiet {
        check!(
            !post.running && post.q == c.state.q_on_expiry,
            "S5TMR-ZERO-01: {imp:?}: found run out at the next execution: {c:?} -> {post:?}"
        );
    }
    cover!(
        c.state.running && c.state.value == 0 && quiet && c.ticks == 0,
        "S5TMR-ZERO-01: value 0 processed with no tick"
    );
}

/// S5TMR-EXPIRE-01 (the start's half): a start records the status the timer takes when its time
/// runs out, 1 for S_ODT and S_ODTS, 0 for the others; running that time out gives it.
fn rule_expire_start(imp: S5Impl, c: S5Case, post: &S5State) {
    if c.input.r || !c.starts() {
        return;
    }
    check_eq!(
        post.q_on_expiry,
        on_delay(c.kind),
        "S5TMR-EXPIRE-01: {imp:?}: a start of {:?} chooses its expiry status",
        c.kind
    );
    if post.value > 0 {
        // The time run out through the implementation's own tick, not the closed form.
        let out = tick_through(imp, *post, u64::from(post.value));
        check!(
            !out.running && out.q == on_delay(c.kind),
            "S5TMR-EXPIRE-01: {imp:?}: {:?} runs out with Q = {}",
            c.kind,
            on_delay(c.kind)
        );
    }
}

/// `n` OS ticks of a valid state through the tick of `imp` (the reference's, the word's, or the
/// area's per-base tick; the timer and the area box share the word's).
fn tick_through(imp: S5Impl, state: S5State, n: u64) -> S5State {
    match imp {
        S5Impl::Reference => {
            let mut r = S5TimerRef::from_state(state, CpuTime::ZERO).expect("valid");
            r.tick(n);
            r.state()
        }
        S5Impl::Word | S5Impl::Timer => {
            TimerWord::from_state(state).expect("valid").tick(n).state()
        }
        S5Impl::AreaStl | S5Impl::AreaCall => {
            let w = TimerWord::from_state(state).expect("valid");
            let mut area = TimerMemory::<1>::from_words([w], CpuTime::ZERO);
            area.tick(state.base, n);
            area.get(0).expect("T 0")
        }
    }
}

/// S5TMR-FR-01: a rising FR clears the S memory and does nothing else (the step equals the one
/// from the state with the memory cleared and FR already 1); with S = 1 the kind's start sees a
/// rising edge and restarts with TV (S_PULSE too, even while it runs); with S = 0 nothing
/// starts. FR held at 1, or falling, does nothing.
#[covers]
fn rule_fr(imp: S5Impl, c: S5Case, post: &S5State) {
    let i = c.input;
    let st = c.state;
    if i.fr && !st.fr_prev {
        let cleared = c.with_state(S5State {
            s_prev: false,
            fr_prev: true,
            ..st
        });
        check_eq!(
            run(imp, cleared).0,
            *post,
            "S5TMR-FR-01: {imp:?}: a rising FR clears the S memory and nothing else: {c:?}"
        );
        if !i.r && i.s && c.kind != S5Kind::SOffdt {
            check!(
                post.running && post.value == i.tv.units() && post.base == i.tv.base(),
                "S5TMR-FR-01: {imp:?}: with S = 1 the timer restarts with TV: {c:?}"
            );
        }
        if !i.s {
            check!(
                !post.running || st.running,
                "S5TMR-FR-01: {imp:?}: with S = 0 nothing starts: {c:?}"
            );
        }
        cover!(
            i.s && st.s_prev && st.running,
            "S5TMR-FR-01: FR restarts a running timer with S held"
        );
    } else if st.fr_prev {
        // FR held (1 -> 1) or falling (1 -> 0): the same step as from FR = 0 without FR.
        let plain = c
            .with_state(S5State {
                fr_prev: false,
                ..st
            })
            .with_input(S5Input { fr: false, ..i });
        let (p, _) = run(imp, plain);
        check_eq!(
            S5State { fr_prev: i.fr, ..p },
            *post,
            "S5TMR-FR-01: {imp:?}: FR held or falling does nothing: {c:?}"
        );
    }
}

/// Every S5 rule through every implementation (the harness body).
pub fn prop_s5_rules(c: S5Case) -> bool {
    let mut checked = true;
    for imp in IMPLS {
        checked &= check_s5_rules(imp, c);
    }
    if checked {
        prop_sf_after_r(c);
    }
    checked
}

/// SF-Q-01: after R with S held at 1, Q stays 0 until S changes: R = 1 with S = 1, then an
/// execution with S = 1, R = 0 and FR unchanged leaves Q = 0.
fn prop_sf_after_r(c: S5Case) {
    if c.kind != S5Kind::SOffdt || !c.input.r || !c.input.s {
        return;
    }
    for imp in IMPLS {
        let (post, _) = run(imp, c);
        let next = S5Case {
            state: post,
            ticks: c.ticks,
            input: S5Input {
                r: false,
                ..c.input
            },
            kind: c.kind,
        };
        let (after, _) = run(imp, next);
        check!(
            !after.q,
            "SF-Q-01: {imp:?}: after R with S held, Q stays 0 until S changes: {c:?}"
        );
    }
}

/// The values of the rule driver: every ordering of value and tick count (0, 1, 2 below and at
/// the ticks 0..=4, and the top of the range) with the ticks below.
const RULE_VALUES: [u16; 6] = [0, 1, 2, 3, 998, 999];
/// Tick counts: none, 1..=4 (below, at and above the small values), 999, 1000 and the largest.
const RULE_TICKS: [u64; 8] = [0, 1, 2, 3, 4, 999, 1000, u64::MAX];

/// Every rule, exhaustively over a small scope that is complete for the rules: the rules only
/// compare the value with the tick count (below, equal, above) and with 0 and 999, which the
/// value and tick sets above reach in every combination; every base, every flag combination of
/// a valid state, S, R and FR, and the six TVs (0, 1 and 999 units, every base). The full state
/// space is covered by `exhaustive_step_equivalence_and_invariants`; Kani (`kani_s5_rules`)
/// covers every value, tick count and TV.
// Uses the cover recorder, which exists outside Kani only (proofs/cover.rs).
#[cfg(not(kani))]
#[test]
fn exhaustive_s5_rules() {
    let cases: u64 = crate::cover::check_ids(
        &[
            "S5TMR-TICK-01",
            "S5TMR-EXPIRE-01",
            "S5TMR-ZERO-01",
            "S5TMR-EDGE-01",
            "S5TMR-R-01",
            "S5TMR-RANGE-01",
            "S5TMR-STOP-01",
            "S5TMR-FR-01",
            "S5TMR-LOAD-01",
            "SP-Q-01",
            "SE-RUN-ON-01",
            "SD-Q-01",
            "SS-Q-01",
            "SF-Q-01",
            "S5-AREA-01",
        ],
        || {
            let mut n = 0;
            for kind in S5Kind::ALL {
                for value in RULE_VALUES {
                    for base in TimeBase::ALL {
                        for f in 0..32u8 {
                            let state = S5State {
                                running: f & 1 != 0,
                                value,
                                base,
                                q: f & 2 != 0,
                                q_on_expiry: f & 4 != 0,
                                s_prev: f & 8 != 0,
                                fr_prev: f & 16 != 0,
                            };
                            for ticks in RULE_TICKS {
                                for tv in tvs() {
                                    for (bits, input) in s5_timer_inputs(tv).into_iter().enumerate()
                                    {
                                        let c = S5Case {
                                            kind,
                                            state,
                                            ticks,
                                            input,
                                        };
                                        n += u64::from(prop_s5_rules(c));
                                        if bits == 0 && tv == tvs()[0] {
                                            prop_tick(state, ticks);
                                        }
                                    }
                                }
                            }
                        }
                    }
                }
            }
            n
        },
    );
    check_eq!(
        cases,
        5 * 6 * 4 * 24 * 8 * 6 * 8,
        "every valid case checked"
    );
}

/// The bolero harness of every S5 rule: random cases under `cargo test`, a proof over every
/// kind, valid state, tick count and input under Kani. Symbolic: the kind, the state (invalid
/// ones skipped), the tick count (any `u64`), S, R, FR and the TV (any valid S5TIME); the
/// implementations are the reference, the word and the area's tick and STL operations (no
/// division by the base: the area ticks by base). `#[kani::unwind(33)]`: the longest loops
/// are the area tick's for one tick (`TimerWord::tick_once_cells` takes the area's cells in
/// groups of 32, the last ones on a padded copy: 32 iterations per loop) and its exit; the others are
/// shorter (the loop over `IMPLS`, 3 under Kani; the area's 2 words for more than one tick).
#[test]
#[cfg_attr(kani, kani::proof, kani::unwind(33))]
fn kani_s5_rules() {
    crate::cover::harness(
        concat!(module_path!(), "::", stringify!(kani_s5_rules)),
        || {
            bolero::check!()
                .with_type::<S5Case>()
                .with_iterations(20_000)
                .for_each(|&c| {
                    prop_s5_rules(c);
                    prop_tick(c.state, c.ticks);
                    #[cfg(not(kani))]
                    for edge in [near_expiry(c), at_top(c)] {
                        prop_s5_rules(edge);
                        prop_tick(edge.state, edge.ticks);
                    }
                });
        },
    );
}

/// S5-EQUIV-01 for every state, tick count and input. Symbolic: the kind, the state, the tick
/// count (any `u64`), S, R, FR and the TV. No loop.
#[test]
#[cfg_attr(kani, kani::proof)]
fn kani_step_equivalence() {
    crate::cover::harness(
        concat!(module_path!(), "::", stringify!(kani_step_equivalence)),
        || {
            bolero::check!()
                .with_type::<S5Case>()
                .with_iterations(20_000)
                .for_each(|c| {
                    prop_step_equivalence(c.kind, c.state, c.ticks, c.input);
                    prop_invariants(c.kind, c.state, c.ticks, c.input);
                    prop_kind_rules(c.kind, c.state, c.ticks, c.input);
                });
        },
    );
}

/// S5-EQUIV-01 on the bits of a word: valid exactly when its state is. Symbolic: the 32 bits
/// (once masked to the 21 of the fields, once whole). No loop.
#[test]
#[cfg_attr(kani, kani::proof)]
fn kani_cell_word() {
    crate::cover::harness(
        concat!(module_path!(), "::", stringify!(kani_cell_word)),
        || {
            bolero::check!()
                .with_type::<u32>()
                .with_iterations(20_000)
                .for_each(|&w| {
                    prop_cell_word(w & 0x001F_FFFF);
                    prop_cell_word(w);
                });
        },
    );
}

/// S5-AREA-01 on a two-timer area. Symbolic: both timers' states (any, invalid ones skipped),
/// the tick base, the tick count `n` (any `u64`). The area's one-tick path runs its group code on
/// a padded copy of 32 cells whatever the area's size, so two timers keep the rest small.
/// `#[kani::unwind(33)]`: that path's loops over the 32 cells (32 iterations and the exit); the
/// loops over the area's 2 words and the check's over the 2 timers are shorter.
#[test]
#[cfg_attr(kani, kani::proof, kani::unwind(33))]
fn kani_area_tick() {
    crate::cover::harness(
        concat!(module_path!(), "::", stringify!(kani_area_tick)),
        || {
            bolero::check!()
                .with_type::<([S5State; 2], TimeBase, u64)>()
                .with_iterations(20_000)
                .for_each(|&(states, base, n)| {
                    prop_area_tick(states, base, n);
                });
        },
    );
}

/// `S5Timer::call` = `S5TimerRef::call` at any time after the previous execution, one harness
/// per base so that the tick count divides by a constant (`ticks_between`'s two divisions);
/// the times are below 2^32 ms so that no division is wider than needed. No loop.
pub fn prop_timer_call(c: S5Case, base: TimeBase, last: u32, dt: u32) {
    let state = S5State { base, ..c.state };
    let last = CpuTime::from_millis(u64::from(last));
    let now = last.add_millis(u64::from(dt));
    let mut r = S5TimerRef::from_state(state, last).expect("valid");
    let mut t = S5Timer::from_state(state, last).expect("valid");
    let (a, b) = (r.call(c.kind, now, c.input), t.call(c.kind, now, c.input));
    check_eq!(
        a,
        b,
        "S5-EQUIV-01: S5Timer::call outputs at {now:?} from {last:?}"
    );
    check_eq!(t.state(), r.state(), "S5-EQUIV-01: S5Timer::call state");
    check_eq!(
        (t.last_call(), r.last_call()),
        (now, now),
        "S5-EQUIV-01: last call"
    );
}

macro_rules! timer_call_harness {
    ($name:ident, $base:expr) => {
        /// `S5Timer::call` against the reference for this base (see [`prop_timer_call`]).
        /// Symbolic: the kind, the state (its base replaced by this one), S, R, FR, the TV, the
        /// previous call's time (`u32` ms) and the step (below 200 000 ms). No loop. The two
        /// divisions of the tick count are by this constant base; kissat, for the 64-bit
        /// division and multiplication (a choice to be measured by the workflow's first runs).
        #[test]
        #[cfg_attr(kani, kani::proof, kani::solver(kissat))]
        fn $name() {
            crate::cover::harness(concat!(module_path!(), "::", stringify!($name)), || {
                bolero::check!()
                    .with_type::<(S5Case, u32, u32)>()
                    .with_iterations(5_000)
                    .for_each(|&(c, last, dt)| prop_timer_call(c, $base, last, dt % 200_000));
            });
        }
    };
}

timer_call_harness!(kani_s5_timer_call_10ms, TimeBase::Ms10);
timer_call_harness!(kani_s5_timer_call_100ms, TimeBase::Ms100);
timer_call_harness!(kani_s5_timer_call_1s, TimeBase::S1);
timer_call_harness!(kani_s5_timer_call_10s, TimeBase::S10);

/// The ticks of a base of `b` ms in `(from, to]` in closed form (the multiples of `b` up to `to`
/// minus those up to `from`), written here; `b` is a constant in every harness that calls it.
pub fn ticks_closed(from: u64, to: u64, b: u64) -> u64 {
    to / b - from / b
}

/// S5-AREA-01 with `advance_to` over three timers: two of base `base`, one of the next base
/// (`S5TMR-TICK-01`'s instants from [`ticks_closed`]); the area's clock moved from `from` to
/// `to` gives each timer the ticks of its own base in `(from, to]`. The bases are constants, so
/// that no division is by a symbolic base.
pub fn prop_advance_to(states: [S5State; 3], base: TimeBase, from: u32, dt: u32) {
    let other = TimeBase::from_bits((base.bits() + 1) % 4);
    let states = [
        S5State { base, ..states[0] },
        S5State { base, ..states[1] },
        S5State {
            base: other,
            ..states[2]
        },
    ];
    if !states.iter().all(S5State::is_valid) {
        return;
    }
    let from = CpuTime::from_millis(u64::from(from));
    let to = from.add_millis(u64::from(dt));
    let words = states.map(|s| TimerWord::from_state(s).expect("valid"));
    let mut area = TimerMemory::<3>::from_words(words, from);
    area.advance_to(to);
    check_eq!(
        area.now(),
        to,
        "S5-AREA-01: the area's clock is at the new time"
    );
    for (i, &s) in states.iter().enumerate() {
        let b = u64::from(if i < 2 { base } else { other }.millis());
        let mut r = S5TimerRef::from_state(s, from).expect("valid");
        r.tick(ticks_closed(from.as_millis(), to.as_millis(), b));
        check_eq!(
            area.get(i),
            Ok(r.state()),
            "S5-AREA-01: advance_to gives timer {i} the ticks of its base"
        );
    }
}

macro_rules! advance_to_harness {
    ($name:ident, $base:expr) => {
        /// `advance_to` over three timers whose bases are constants (see [`prop_advance_to`]).
        /// Symbolic: the three states (any; invalid ones skipped), the clock `from` (`u32` ms) and
        /// the step `dt` (below 100 000 ms). `#[kani::unwind(33)]`: `advance_to`'s loop over the
        /// 4 bases, the one-tick path's loops over a padded group of 32 cells (32 iterations and
        /// the exit, the largest), the loop over the 3 words for more ticks, the check's over the
        /// 3 timers.
        #[test]
        #[cfg_attr(kani, kani::proof, kani::unwind(33), kani::solver(kissat))]
        fn $name() {
            crate::cover::harness(concat!(module_path!(), "::", stringify!($name)), || {
                bolero::check!()
                    .with_type::<([S5State; 3], u32, u32)>()
                    .with_iterations(5_000)
                    .for_each(|&(states, from, dt)| {
                        prop_advance_to(states, $base, from, dt % 100_000)
                    });
            });
        }
    };
}

advance_to_harness!(kani_advance_to_10ms, TimeBase::Ms10);
advance_to_harness!(kani_advance_to_100ms, TimeBase::Ms100);
advance_to_harness!(kani_advance_to_1s, TimeBase::S1);
advance_to_harness!(kani_advance_to_10s, TimeBase::S10);

macro_rules! sequence_harness {
    ($name:ident, $base:expr) => {
        /// S5-EQUIV-02 with one constant time base: every sequence of three executions (any kind,
        /// S and FR, any TV units of this base, time steps from a tick-boundary set) from a
        /// stopped timer of this base, through the reference, an `S5Timer`, the area's box and
        /// its STL operations. R, which sets the base to 10 ms, is only in the 10 ms harness, so
        /// that every division by the timer's base is by a constant. Symbolic: the kind, per step
        /// S, FR, the TV's units (0..=999) and an index into the steps. `#[kani::unwind(33)]`: the
        /// sequence loop (3 iterations), `advance_to`'s loop over the 4 bases, and the one-tick
        /// path's loops over a padded group of 32 cells (32 and the exit, the largest).
        #[test]
        #[cfg_attr(kani, kani::proof, kani::unwind(33), kani::solver(kissat))]
        fn $name() {
            crate::cover::harness(concat!(module_path!(), "::", stringify!($name)), || {
                const DT: [u64; 8] = [0, 1, 9, 10, 11, 1_000, 10_000, 99_999];
                let base: TimeBase = $base;
                bolero::check!()
                    .with_type::<(S5Kind, [(u8, bool, bool, bool, u16); 3])>()
                    .with_iterations(5_000)
                    .for_each(|&(kind, steps)| {
                        let steps = steps.map(|(d, s, r, fr, units)| {
                            let input = S5Input {
                                s,
                                r: r && base == TimeBase::Ms10,
                                fr,
                                tv: S5Time::new(units % 1_000, base).expect("at most 999 units"),
                            };
                            (DT[usize::from(d) % DT.len()], input)
                        });
                        let initial = S5State {
                            base,
                            ..S5State::RESET
                        };
                        prop_sequence_equivalence_from(kind, initial, &steps);
                    });
            });
        }
    };
}

sequence_harness!(kani_sequence_equivalence_10ms, TimeBase::Ms10);
sequence_harness!(kani_sequence_equivalence_100ms, TimeBase::Ms100);
sequence_harness!(kani_sequence_equivalence_1s, TimeBase::S1);
sequence_harness!(kani_sequence_equivalence_10s, TimeBase::S10);
