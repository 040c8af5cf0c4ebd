//! Properties of the S5 timers: the packed cell simulates the reference, the invariants hold,
//! R resets, no start without a signal change, no panic.
//!
//! Each property is a plain function; `exhaustive_*` tests drive it over finite domains, and the
//! `kani` module drives it over symbolic state for `cargo kani --tests`. A property returns
//! whether its premise held (the case was checked): the drivers count the checked cases against
//! the size of their domain, and the harnesses `kani::cover!` it, so that no driver can pass
//! vacuously by skipping every case.

use std::thread;

use plc_timers::s5::cell::{self, Cell, PackedTimer};
use plc_timers::s5::memory::TimerMemory;
use plc_timers::s5::reference::S5TimerRef;
use plc_timers::s5::{S5Input, S5Kind, S5Output, S5State};
use plc_timers::time::{S5Time, TimeBase};

/// Whether `input` gives `kind` a start signal from `state`: a change of S in the kind's
/// direction, or a rising FR (which re-arms the edge memory).
pub fn start_signal(kind: S5Kind, state: &S5State, input: &S5Input) -> bool {
    let edge = if kind.starts_on_falling_edge() {
        !input.s && state.s_prev
    } else {
        input.s && !state.s_prev
    };
    edge || (input.fr && !state.fr_prev)
}

/// One reference step from `state`: `ticks` OS ticks, then one execution.
pub fn reference_step(
    kind: S5Kind,
    state: S5State,
    ticks: u64,
    input: S5Input,
) -> (S5State, S5Output) {
    let mut r = S5TimerRef {
        kind,
        state,
        t_prev: 0,
    };
    r.tick(ticks);
    let out = r.execute(input);
    (r.state, out)
}

/// S5-EQUIV-01: for every valid state, tick count and input, one step of the packed cell,
/// mapped through the abstraction function, equals one step of the reference, and the outputs
/// agree. By induction over the steps this covers every trace.
pub fn prop_step_equivalence(kind: S5Kind, state: S5State, ticks: u64, input: S5Input) -> bool {
    let Some(c) = Cell::from_state(state) else {
        return false;
    };
    assert_eq!(
        cell::abstraction(c),
        state,
        "S5-EQUIV-01: abstraction inverts from_state"
    );
    let (r_state, r_out) = reference_step(kind, state, ticks, input);
    let c = c.tick(ticks).execute(kind, input);
    assert_eq!(
        cell::abstraction(c),
        r_state,
        "S5-EQUIV-01 {kind:?} {state:?} {ticks} {input:?}"
    );
    assert_eq!(
        c.output(),
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
    let millis = u32::from(after.value) * after.base.millis();
    assert!(
        millis <= S5Time::MAX_MILLIS,
        "S5TMR-RANGE-01: {millis} ms above 9 990 s"
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
        q: plc_timers::s5::reference::q_while_running(kind),
        s_prev: true,
        fr_prev: false,
    };
    let mut r = S5TimerRef {
        kind,
        state,
        t_prev: 0,
    };
    r.tick(u64::from(value) - 1);
    assert!(
        r.state.running && r.state.value == 1,
        "S5TMR-TICK-01: still running before the v-th tick"
    );
    r.tick(1);
    assert!(
        !r.state.running && r.state.value == 0,
        "S5TMR-TICK-01: run out on the v-th tick"
    );
    assert_eq!(r.state.q, !state.q, "S5TMR-EXPIRE-01: expiry inverts Q");
    true
}

/// S5-EQUIV-01 (the abstraction): a timer word is valid exactly when the state it stands for is,
/// and then `from_state` gives the same word back; an invalid word (value field above 999) has
/// no state. So the abstraction is a bijection between valid words and valid states. Returns
/// whether the word is valid.
pub fn prop_cell_word(word: u16) -> bool {
    let c = Cell(word);
    let state = cell::abstraction(c);
    assert_eq!(
        c.is_valid(),
        state.is_valid(),
        "Cell::is_valid agrees with the state invariant: {word:#06X}"
    );
    let back = Cell::from_state(state);
    if c.is_valid() {
        assert_eq!(
            back,
            Some(c),
            "from_state inverts the abstraction: {word:#06X}"
        );
    } else {
        assert_eq!(back, None, "an invalid word has no state: {word:#06X}");
    }
    c.is_valid()
}

/// The per-kind invariant every reachable state satisfies (seed 000 §9.3-9.7): the pulses have
/// Q exactly while running (SP-Q-01, SE-Q-01); S_ODT's Q needs S = 1 and the time run out
/// (SD-Q-01); S_ODTS's Q comes only after the time (SS-Q-01); S_OFFDT has Q while running and
/// otherwise only with S = 1 (SF-Q-01).
pub fn kind_invariant(kind: S5Kind, st: &S5State) -> bool {
    match kind {
        S5Kind::SPulse | S5Kind::SPext => st.q == st.running,
        S5Kind::SOdt => !st.q || (st.s_prev && !st.running),
        S5Kind::SOdts => !(st.q && st.running),
        S5Kind::SOffdt => (!st.running || st.q) && (!st.q || st.s_prev || st.running),
    }
}

/// SP-Q-01 .. SF-Q-01, SP-STOP-01, SD-STOP-01, SE-RUN-ON-01, SS-RUN-ON-01: from a state that
/// satisfies the kind's invariant, a step keeps it, and the kind's rules hold: S_PULSE and S_ODT
/// stop when S = 0; S_PEXT and S_ODTS run on when S falls (unless the ticks run them out);
/// S_OFFDT's Q is S or running when R = 0.
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
            assert!(
                !after.running,
                "SP-STOP-01 / SD-STOP-01: S = 0 stops the timer"
            );
        }
        S5Kind::SPext | S5Kind::SOdts
            if state.running && !input.s && ticks < u64::from(state.value) && !input.fr =>
        {
            assert!(
                after.running,
                "SE-RUN-ON-01 / SS-RUN-ON-01: runs on when S falls"
            );
        }
        S5Kind::SOffdt => assert_eq!(after.q, input.s || after.running, "SF-Q-01"),
        _ => {}
    }
    true
}

/// Every S5 state: value 0..=999, four bases, four flags (64 000 states).
pub fn all_states() -> impl Iterator<Item = S5State> {
    (0..=999u16).flat_map(|value| {
        TimeBase::ALL.into_iter().flat_map(move |base| {
            (0..16u8).map(move |f| S5State {
                running: f & 1 != 0,
                value,
                base,
                q: f & 2 != 0,
                s_prev: f & 4 != 0,
                fr_prev: f & 8 != 0,
            })
        })
    })
}

/// Tick counts that reach every case of the tick rule: none, one, two, one short of the
/// largest value, the largest value, past it, and the largest count.
const TICKS: [u64; 7] = [0, 1, 2, 998, 999, 1000, u64::MAX];

/// TVs that reach every case of a start: zero (seed 003's value 0), one unit, the largest value,
/// and each base. The value of TV only matters on a start, where `exhaustive_every_tv` takes all
/// 4 000 valid words.
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

/// Exhaustive: every kind x every state (64 000) x tick counts (7) x S, R, FR (8) x TVs (6):
/// 107.5 million steps, split over two threads. Complete for the state space; the tick counts
/// cover every branch of the tick rule (0, below, at and above the value), and the TV values
/// every branch of a start (the full TV range is `exhaustive_every_tv`).
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
    // Every enumerated state is valid: all 64 000 x 336 inputs are checked, per kind.
    let per_kind = 64_000 * (TICKS.len() as u64) * 8 * (tvs().len() as u64);
    assert_eq!(per_kind, 21_504_000);
    for (kind, n) in S5Kind::ALL.iter().zip(&counts) {
        assert_eq!(
            (n[0], n[1]),
            (per_kind, per_kind),
            "{kind:?}: cases checked"
        );
        // The kind rules apply from the states of the kind's invariant: half or fewer.
        assert!(
            n[2] > 0 && n[2] < per_kind,
            "{kind:?}: {} kind-rule cases",
            n[2]
        );
    }
}

/// Exhaustive: all 65 536 timer words. The valid ones are the 1 000 values 0..=999 times the 64
/// combinations of the six other bits.
#[test]
fn exhaustive_cell_words() {
    let valid = (0..=u16::MAX).filter(|&w| prop_cell_word(w)).count();
    assert_eq!(valid, 1000 * 64);
}

/// Exhaustive over TV: all 4 000 valid S5TIME words x every kind x every combination of the
/// edge memories and S, R, FR (64) x three representative prior states (cleared, running,
/// expired) x 0 or 1 tick. Together with `exhaustive_step_equivalence_and_invariants` (which
/// covers every state) this covers every (state, TV) pair on the steps where TV is read.
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
/// gives the same outputs and states through the reference's `call` (ticks counted from the
/// clock per timer), a lone `PackedTimer`, a one-timer `TimerMemory` box call (ticks applied per
/// base by the area), and the STL sequence the box compiles to (`FR`, `SP`..`SF`, `R`, then
/// `L`, `LC`, `A`) on a second area.
pub fn prop_sequence_equivalence(kind: S5Kind, steps: &[(u64, S5Input)]) {
    let mut r = S5TimerRef::new(kind);
    let mut packed = PackedTimer::new();
    let mut area = TimerMemory::<1>::new();
    let mut stl = TimerMemory::<1>::new();
    let mut t = 0u64;
    for &(dt, input) in steps {
        t = t.saturating_add(dt);
        let a = r.call(t, input);
        let b = area.call(0, kind, t, input).expect("timer 0 exists");
        assert_eq!(a, b, "S5-EQUIV-02 {kind:?} at t = {t}");
        assert_eq!(
            cell::abstraction(area.cells()[0]),
            r.state,
            "S5-EQUIV-02 state"
        );
        assert_eq!(area.now(), t, "the area's clock follows the calls");
        assert_eq!(
            packed.call(kind, t, input),
            a,
            "S5-EQUIV-02 PackedTimer at t = {t}"
        );
        stl.advance_to(t);
        let ops = [
            stl.fr(0, kind, input.fr),
            stl.start(0, kind, input.s, input.tv),
            stl.reset(0, input.r),
        ];
        assert_eq!(ops, [Ok(()); 3], "timer 0 exists");
        let read = (stl.status(0), stl.load(0), stl.load_bcd(0));
        assert_eq!(
            read,
            (Ok(a.q), Ok(a.bi), Ok(a.bcd)),
            "S5-EQUIV-02 STL at t = {t}"
        );
        assert_eq!(stl.cells(), area.cells(), "S5-EQUIV-02 STL state");
    }
}

/// S5-AREA-01: `n` ticks of `tick_base` on an area of four timers in the states `states` equal
/// the reference tick of each timer whose base is `tick_base`, and leave the others unchanged.
pub fn prop_area_tick(states: [S5State; 4], tick_base: TimeBase, n: u64) -> bool {
    let mut cells = [Cell::RESET; 4];
    for (c, &s) in cells.iter_mut().zip(states.iter()) {
        match Cell::from_state(s) {
            Some(valid) => *c = valid,
            None => return false,
        }
    }
    let mut area = TimerMemory::<4>::from_cells(cells, 0);
    area.tick(tick_base, n);
    for (i, &state) in states.iter().enumerate() {
        let mut r = S5TimerRef {
            kind: S5Kind::SOdt,
            state,
            t_prev: 0,
        };
        if state.base == tick_base {
            r.tick(n);
        }
        assert_eq!(
            cell::abstraction(area.cells()[i]),
            r.state,
            "S5-AREA-01 timer {i}"
        );
    }
    true
}

/// S5-EQUIV-02 driver: every input sequence of length 5 over 24 symbols (six S/R/FR patterns x
/// a time step of 0 ms, one 10 ms tick, 25 ms or 1 s: 7.96 million sequences per kind) from the
/// initial state. TV = 30 ms (3 units): the sequences reach start, run, expiry, restart and
/// reset.
#[test]
fn bounded_sequences_reference_vs_memory_area() {
    // Symbols: (S, R, FR) x time step; 6 input patterns x 4 steps = 24 symbols, length 5.
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
/// timers holding that value in each of the four bases, ticked by each base with 1, 2 or 999
/// ticks (every branch of the tick rule: below, and at or past the value).
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

#[cfg(kani)]
mod kani_harnesses {
    use super::*;

    fn any_state() -> S5State {
        let value: u16 = kani::any();
        kani::assume(value <= 999);
        S5State {
            running: kani::any(),
            value,
            base: TimeBase::from_bits(kani::any()),
            q: kani::any(),
            s_prev: kani::any(),
            fr_prev: kani::any(),
        }
    }

    fn any_input() -> S5Input {
        let units: u16 = kani::any();
        kani::assume(units <= 999);
        let tv = match S5Time::new(units, TimeBase::from_bits(kani::any())) {
            Ok(tv) => tv,
            Err(_) => S5Time::ZERO,
        };
        S5Input {
            s: kani::any(),
            r: kani::any(),
            fr: kani::any(),
            tv,
        }
    }

    /// S5-EQUIV-01 over every state, tick count and input.
    #[kani::proof]
    fn kani_step_equivalence() {
        let checked = prop_step_equivalence(kani::any(), any_state(), kani::any(), any_input());
        kani::cover!(checked, "the premise is reachable");
    }

    /// S5TMR-RANGE-01, S5TMR-R-01, S5TMR-EDGE-01 over every state, tick count and input.
    #[kani::proof]
    fn kani_invariants() {
        let checked = prop_invariants(kani::any(), any_state(), kani::any(), any_input());
        kani::cover!(checked, "the premise is reachable");
    }

    /// The per-kind rules over every state, tick count and input.
    #[kani::proof]
    fn kani_kind_rules() {
        let checked = prop_kind_rules(kani::any(), any_state(), kani::any(), any_input());
        kani::cover!(checked, "the premise is reachable");
    }

    /// S5TMR-TICK-01 for every kind, value and base.
    #[kani::proof]
    fn kani_expiry_on_vth_tick() {
        let checked =
            prop_expiry_on_vth_tick(kani::any(), kani::any(), TimeBase::from_bits(kani::any()));
        kani::cover!(checked, "the premise is reachable");
    }

    /// The abstraction is a bijection between valid timer words and valid states.
    #[kani::proof]
    fn kani_cell_word() {
        prop_cell_word(kani::any());
    }

    /// S5-AREA-01: a tick of a four-timer area over symbolic cells, base and tick count.
    #[kani::proof]
    fn kani_area_tick() {
        let states = [any_state(), any_state(), any_state(), any_state()];
        let checked = prop_area_tick(states, TimeBase::from_bits(kani::any()), kani::any());
        kani::cover!(checked, "the premise is reachable");
    }

    /// S5-EQUIV-02: from the initial state, every symbolic sequence of three executions
    /// (symbolic inputs and TVs, time steps from the tick-boundary set 0, 1, 9, 10, 11 ms, 1 s,
    /// 10 s) through the reference and the area. The clock stays below 31 s, but `call` still
    /// divides the clock by the (symbolic) base: the one harness here with a symbolic division.
    #[kani::proof]
    #[kani::unwind(4)]
    fn kani_sequence_equivalence() {
        const DT: [u64; 7] = [0, 1, 9, 10, 11, 1_000, 10_000];
        let mut steps = [(0u64, S5Input::new(false, false, S5Time::ZERO)); 3];
        for step in steps.iter_mut() {
            let i: usize = kani::any();
            kani::assume(i < DT.len());
            *step = (DT[i], any_input());
        }
        prop_sequence_equivalence(kani::any(), &steps);
    }
}
