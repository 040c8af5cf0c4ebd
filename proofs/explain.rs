//! The explanations of the references (`call_explained`, [`plc_timers::rule::Explained`]) are
//! proven for every family:
//!
//! - **faithful**: the explained call gives the outputs and state of `call` (the memory areas'
//!   explained operations give the words and outputs of the plain ones, and the area's
//!   explained box call gives the reference's explanation);
//! - **sound**: every rule reported acted: its premise, written below from the requirement's
//!   text (never from the reference's code), held in that call;
//! - **complete**: every rule whose premise held and whose action changed an output or the
//!   state is reported, and every output that changed has a rule and is marked written;
//! - **complete in what determined an output**: a rule whose premise held and that determines
//!   an output's value in the call is reported for that output, also when the value stayed (a
//!   running S5 timer's value and status are S5TMR-TICK-01's when no tick fell; PT <= 0 at an
//!   IEC box is IEC-PT0-01's; a count input held at 1 decides through CNT-EDGE-01 that CV
//!   stays). The "determines" relation below is written from the catalog's texts.
//!
//! Each premise is a function of the state before, the inputs and (where the text speaks of
//! the result) the state after. The drivers enumerate the same small scopes as the families'
//! rule drivers (`proofs/s5.rs`, `proofs/iec.rs`, `proofs/counter.rs`, whose docs give the
//! small-scope arguments); a cover per rule makes sure every rule is reported somewhere in the
//! domain, so that soundness is not vacuous. Assertion messages start with the requirement ID.

use std::fmt::Debug;
use std::thread;

use plc_timers::block::Now;
use plc_timers::counter::s5::{
    CounterMemory, CounterPreset, S5CounterInput, S5CounterKind, S5CounterOps, S5CounterRef,
    S5CounterState, CV_MAX,
};
use plc_timers::counter::{CounterInput, CounterInt, CounterKind, CounterRef};
use plc_timers::counter::{CounterOutput, CounterState};
use plc_timers::iec::{IecInput, IecKind, IecState, IecTimerOps, IecTimerRef};
use plc_timers::rule::{Explained, Rule, RuleSet};
use plc_timers::s5::{S5Kind, S5State, S5TimerOps, S5TimerRef, TimerMemory, TimerWord};
use plc_timers::time::clock::ClockWord;
use plc_timers::time::{CpuTime, IecDuration, LTime, Time, TimeBase};

use crate::cover::{check, cover, covers};
use crate::domain::{
    counter_inputs, counter_states, s5_counter_inputs, s5_counter_states, s5_timer_inputs,
};
use crate::iec::{all_states_u4, within_range, FullWidth, U4};
#[cfg(not(kani))]
use crate::s5::near_expiry;
use crate::s5::{seen, S5Case};

/// Soundness: every rule of `reported` satisfies `premise`.
///
/// The loop runs over the whole catalog (`Rule::ALL`, `Rule::COUNT` rules, fewer than 100:
/// asserted below, since the harnesses' `kani::unwind(100)` counts on it), not over the set's bits:
/// iterating the bits would index the catalog by a symbolic bit position, which CBMC handles
/// badly; here every index is a constant and each test of the set is a bit test.
fn sound(reported: RuleSet, premise: impl Fn(Rule) -> bool, case: &dyn Debug) {
    const _: () = assert!(
        Rule::COUNT < 100,
        "the explain harnesses unwind `sound`'s loop 100 times: raise their kani::unwind"
    );
    for rule in Rule::ALL.into_iter().filter(|r| reported.contains(*r)) {
        assert!(
            premise(rule),
            "{}: reported, but its premise did not hold in {case:?}",
            rule.id()
        );
    }
}

/// Completeness of one rule: when it acted and changed something, it is in `reported`.
fn complete(rule: Rule, acted: bool, reported: RuleSet, case: &dyn Debug) {
    assert!(
        !acted || reported.contains(rule),
        "{}: acted and changed the outputs or the state, but is not reported in {case:?}",
        rule.id()
    );
}

/// Every output that changed has a deciding rule and is marked written (the earlier row of
/// `check` relies on it), except the outputs of `derived`, which an input derives from the
/// state (a counter's Q from CV and PV: a new PV changes it with nothing written); and a
/// written output has a deciding rule. `id` is the requirement that defines the family's
/// outputs.
fn every_change_decided<O: Debug>(
    id: &str,
    e: &Explained<O>,
    changed: [bool; 3],
    derived: &[usize],
    case: &dyn Debug,
) {
    for (i, c) in changed.into_iter().enumerate() {
        assert!(
            !c || !e.outputs[i].is_empty(),
            "{id}: output {i} changed with no deciding rule in {case:?} ({e:?})"
        );
        assert!(
            !c || e.wrote(i) || derived.contains(&i),
            "{id}: output {i} changed but is not marked written in {case:?} ({e:?})"
        );
        assert!(
            !e.wrote(i) || !e.outputs[i].is_empty(),
            "{id}: output {i} written with no deciding rule in {case:?} ({e:?})"
        );
    }
}

/// Completeness in the new sense: `rule` determined output `o` (its premise held and the
/// output's value follows from it, changed or not), so it is reported for `o`.
fn determined<O: Debug>(
    rule: Rule,
    o: usize,
    determines: bool,
    e: &Explained<O>,
    case: &dyn Debug,
) {
    assert!(
        !determines || e.outputs[o].contains(rule),
        "{}: determined output {o} but is not reported for it in {case:?}: {:?}",
        rule.id(),
        e.outputs[o]
    );
}

/// Faithful, for every family at once (written against [`BlockOps`]): from `start`, the
/// explained call gives the outputs of the plain call and leaves the same block. `id` is the
/// family's equivalence requirement, which leads the messages. Returns the explanation and the
/// block after the call.
fn faithful<B: plc_timers::block::BlockOps + Copy + PartialEq + Debug>(
    start: B,
    kind: B::Kind,
    now: Now<B>,
    input: B::Input,
    id: &str,
    case: &dyn Debug,
) -> (Explained<B::Output>, B) {
    let (mut plain, mut explained) = (start, start);
    let out = plain.call(kind, now, input);
    let e = explained.call_explained(kind, now, input);
    assert_eq!(e.output, out, "{id}: explained outputs {case:?}");
    assert_eq!(explained, plain, "{id}: explained state {case:?}");
    (e, plain)
}

/// Runs `body` on each of the two halves of `kinds`, one thread each, requires every cover the
/// two evaluated to be hit, and returns the cases both checked.
#[cfg(not(kani))]
fn on_two_threads<K: Copy + Sync>(kinds: &[K], body: impl Fn(&[K]) -> u64 + Sync) -> u64 {
    let (low, high) = kinds.split_at(kinds.len() / 2 + 1);
    let (counts, hits): (Vec<u64>, Vec<_>) = thread::scope(|scope| {
        let workers: Vec<_> = [low, high]
            .into_iter()
            .map(|half| {
                let body = &body;
                scope.spawn(move || crate::cover::collect(|| body(half)))
            })
            .collect();
        workers
            .into_iter()
            .map(|w| w.join().expect("worker"))
            .unzip()
    });
    crate::cover::require(crate::cover::merge(hits));
    counts.iter().sum()
}

// ---------------------------------------------------------------------------------------------
// S5 timers

/// The S5 rules a call may report, with the premise of each (LAD manual §9.1-9.7, Berger §7,
/// STL manual `FR`, as the catalog states them).
fn s5_premise(c: &S5Case, rule: Rule) -> bool {
    let st = c.state;
    let i = c.input;
    let fr_edge = i.fr && !st.fr_prev;
    let memory = st.s_prev && !fr_edge;
    let rising = i.s && !memory;
    let falling = !i.s && memory;
    // What the start logic sees: the ticks applied, a value-0 timer found run out.
    let at = seen(st, c.ticks);
    let starts = if c.kind == S5Kind::SOffdt {
        falling
    } else {
        rising
    };
    let pulse_or_odt = matches!(c.kind, S5Kind::SPulse | S5Kind::SOdt);
    // S5TMR-STOP-01: S = 0 stops a running S_PULSE or S_ODT before the end.
    let stopped = pulse_or_odt && !i.s && at.running;
    let kind_rule = match c.kind {
        S5Kind::SPulse => Rule::SP_Q_01,
        S5Kind::SPext => Rule::SE_RUN_ON_01,
        S5Kind::SOdt => Rule::SD_Q_01,
        S5Kind::SOdts => Rule::SS_Q_01,
        S5Kind::SOffdt => Rule::SF_Q_01,
    };
    match rule {
        // A running timer with a value: the ticks in (t_prev, t], none or more, decide it.
        Rule::S5TMR_TICK_01 => st.running && st.value > 0,
        // BI and BCD are the value as L and LC read it, at every execution.
        Rule::S5TMR_LOAD_01 => true,
        // The value reached 0 (by ticks, or a start with 0 found at this execution).
        Rule::S5TMR_EXPIRE_01 => st.running && (c.ticks >= u64::from(st.value) || st.value == 0),
        // A timer started with 0: in its starting execution, or found run out at the next.
        Rule::S5TMR_ZERO_01 => (st.running && st.value == 0) || (starts && i.tv.units() == 0),
        // A start on the change at S, or the S memory taking a new value.
        Rule::S5TMR_EDGE_01 => starts || i.s != memory,
        Rule::S5TMR_R_01 => i.r,
        Rule::S5TMR_STOP_01 => stopped,
        // An FR edge, or FR's memory taking a new value.
        Rule::S5TMR_FR_01 => i.fr != st.fr_prev,
        // The kind's own rule: its start, S_PULSE's and S_ODT's stop, S_ODT's S = 0 clearing
        // an expired Q, S_OFFDT's rising S.
        r if r == kind_rule => {
            starts
                || stopped
                || (c.kind == S5Kind::SOdt && !i.s && at.q)
                || (c.kind == S5Kind::SOffdt && rising)
        }
        _ => false,
    }
}

/// The S5 rules whose action changes the state or an output when their premise holds, and the
/// condition for it.
fn s5_changes(c: &S5Case, rule: Rule, before: &S5State, after: &S5State) -> bool {
    let i = c.input;
    match rule {
        // Ticks take units off; expiry and a stop stop the timer.
        Rule::S5TMR_TICK_01 => c.ticks > 0,
        Rule::S5TMR_EXPIRE_01 | Rule::S5TMR_STOP_01 => true,
        Rule::S5TMR_ZERO_01 => before.running && before.value == 0,
        // R as a level: while R = 1 it decides every output, whatever the state was.
        Rule::S5TMR_R_01 => true,
        Rule::S5TMR_FR_01 => after.fr_prev != before.fr_prev,
        Rule::S5TMR_EDGE_01 => after.s_prev != before.s_prev && i.fr == before.fr_prev,
        _ => false,
    }
}

/// The S5 timer explanation, faithful, sound and complete for one case; and the memory area's
/// explained operations faithful to the plain ones and to the reference.
#[covers]
pub fn prop_explain_s5(c: S5Case) -> bool {
    if !c.state.is_valid() {
        return false;
    }
    let base = u64::from(c.state.base.millis());
    let ticks = c.ticks.min(1_000_000);
    let c = S5Case { ticks, ..c };
    let now = CpuTime::from_millis(ticks * base);
    let Some(start) = S5TimerRef::from_state(c.state, CpuTime::ZERO) else {
        return false;
    };
    let (e, plain) = faithful(start, c.kind, now, c.input, "S5-EQUIV-01", &c);
    let out = e.output;

    let reported = e.rules();
    sound(reported, |r| s5_premise(&c, r), &c);
    let after = plain.state();
    for rule in [
        Rule::S5TMR_TICK_01,
        Rule::S5TMR_EXPIRE_01,
        Rule::S5TMR_ZERO_01,
        Rule::S5TMR_EDGE_01,
        Rule::S5TMR_R_01,
        Rule::S5TMR_STOP_01,
        Rule::S5TMR_FR_01,
    ] {
        let acted = s5_premise(&c, rule) && s5_changes(&c, rule, &c.state, &after);
        complete(rule, acted, reported, &c);
    }
    // A start is its kind's and the edge's, and R decides every output alone.
    let kind_rules = [
        Rule::SP_Q_01,
        Rule::SE_RUN_ON_01,
        Rule::SD_Q_01,
        Rule::SS_Q_01,
        Rule::SF_Q_01,
    ];
    if c.input.r {
        for (i, o) in e.outputs.iter().enumerate() {
            // BI and BCD are the cleared value as L and LC read it.
            let load = RuleSet::EMPTY.with_if(i > 0, Rule::S5TMR_LOAD_01);
            assert_eq!(
                *o,
                load.with(Rule::S5TMR_R_01),
                "S5TMR-R-01: R decides output {i} alone in {c:?}"
            );
        }
    }
    // What determined the outputs, changed or not (from the texts of S5TMR-TICK-01 and
    // S5TMR-LOAD-01): a running timer's value is the ticks' unless a start or R writes it; its
    // status too, unless the ticks ran it out, S stopped it or S_OFFDT's rising S set it.
    let at = seen(c.state, c.ticks);
    let (st, i) = (c.state, c.input);
    let fr_edge = i.fr && !st.fr_prev;
    let memory = st.s_prev && !fr_edge;
    let rising = i.s && !memory;
    let starts = if c.kind == S5Kind::SOffdt {
        !i.s && memory
    } else {
        rising
    };
    let ticking = st.running && st.value > 0 && !i.r && !starts;
    let status_kept = at.running
        && (i.s || !matches!(c.kind, S5Kind::SPulse | S5Kind::SOdt))
        && !(c.kind == S5Kind::SOffdt && rising);
    cover!(
        ticking && status_kept && c.ticks == 0,
        "S5TMR-TICK-01 determines a value no tick changed"
    );
    determined(Rule::S5TMR_TICK_01, 0, ticking && status_kept, &e, &c);
    determined(Rule::S5TMR_TICK_01, 1, ticking, &e, &c);
    determined(Rule::S5TMR_TICK_01, 2, ticking, &e, &c);
    determined(Rule::S5TMR_LOAD_01, 1, true, &e, &c);
    determined(Rule::S5TMR_LOAD_01, 2, true, &e, &c);
    // An FR edge with S held clears the start memory, so S = 1 starts the timer again (every
    // kind but S_OFFDT, which starts on a falling S): the FR edge chose that start's write, and
    // Q carries it beside the edge (as `Explained` defines "decided").
    let fr_restart = c.input.fr
        && !c.state.fr_prev
        && c.state.s_prev
        && c.input.s
        && !c.input.r
        && c.kind != S5Kind::SOffdt;
    cover!(fr_restart, "S5TMR-FR-01 an FR restart explained");
    if !c.input.r {
        // Exactly then: an FR edge that cleared a memory already 0 chose no start.
        assert_eq!(
            e.outputs[0].contains(Rule::S5TMR_FR_01),
            fr_restart,
            "S5TMR-FR-01: Q carries the FR edge exactly when it restarted the timer, in {c:?}"
        );
    }
    if fr_restart {
        assert!(
            e.outputs[0].contains(Rule::S5TMR_EDGE_01),
            "S5TMR-FR-01: an FR restart's Q carries the edge too, in {c:?}: {:?}",
            e.outputs[0]
        );
    }
    let kind_rule = kind_rules[c.kind as usize];
    complete(kind_rule, s5_premise(&c, kind_rule), reported, &c);
    let was = c.state.output();
    every_change_decided(
        "S5TMR-RANGE-01",
        &e,
        [out.q != was.q, out.bi != was.bi, out.bcd != was.bcd],
        &[],
        &c,
    );
    for rule in Rule::ALL {
        if rule.id().starts_with("S5TMR") || kind_rules.contains(&rule) {
            s5_cover(rule, reported.contains(rule));
        }
    }

    // The memory area: T 1 is the timer, T 0 a running neighbour of another base.
    let neighbour = TimerWord::from_state(S5State {
        running: true,
        value: 5,
        base: TimeBase::from_bits((c.state.base.bits() + 1) % 4),
        ..S5State::RESET
    })
    .expect("a valid state");
    let word = TimerWord::from_state(c.state).expect("a valid state");
    let area = TimerMemory::from_words([neighbour, word], CpuTime::ZERO);
    let (mut a, mut b) = (area.clone(), area);
    let plain = a.call(1, c.kind, now, c.input).expect("T 1");
    let ea = b.call_explained(1, c.kind, now, c.input).expect("T 1");
    assert_eq!(
        b, a,
        "S5-EQUIV-02: the area's explained call changes the words as call"
    );
    assert_eq!(
        ea.output, plain,
        "S5-EQUIV-02: area explained outputs {c:?}"
    );
    assert_eq!(
        ea, e,
        "S5-EQUIV-02: the area explains as the reference {c:?}"
    );
    // The STL operations, one after the other, without ticks.
    let (mut a, mut b) = (
        TimerMemory::from_words([neighbour, word], now),
        TimerMemory::from_words([neighbour, word], now),
    );
    let fr = b.fr_explained(1, c.input.fr).expect("T 1");
    a.fr(1, c.input.fr).expect("T 1");
    assert_eq!(
        (&b, fr.output),
        (&a, a.outputs().nth(1).expect("T 1")),
        "S5TMR-FR-01: FR explained"
    );
    let st = b
        .start_explained(1, c.kind, c.input.s, c.input.tv)
        .expect("T 1");
    a.start(1, c.kind, c.input.s, c.input.tv).expect("T 1");
    assert_eq!(
        (&b, st.output),
        (&a, a.outputs().nth(1).expect("T 1")),
        "S5TMR-EDGE-01: start explained"
    );
    let r = b.reset_explained(1, c.input.r).expect("T 1");
    a.reset(1, c.input.r).expect("T 1");
    assert_eq!(
        (&b, r.output),
        (&a, a.outputs().nth(1).expect("T 1")),
        "S5TMR-R-01: R explained"
    );
    true
}

/// One cover per S5 rule: reported somewhere in the domain.
#[covers]
fn s5_cover(rule: Rule, hit: bool) {
    match rule {
        Rule::S5TMR_TICK_01 => cover!(hit, "S5TMR-TICK-01 explained"),
        Rule::S5TMR_EXPIRE_01 => cover!(hit, "S5TMR-EXPIRE-01 explained"),
        Rule::S5TMR_ZERO_01 => cover!(hit, "S5TMR-ZERO-01 explained"),
        Rule::S5TMR_EDGE_01 => cover!(hit, "S5TMR-EDGE-01 explained"),
        Rule::S5TMR_R_01 => cover!(hit, "S5TMR-R-01 explained"),
        Rule::S5TMR_STOP_01 => cover!(hit, "S5TMR-STOP-01 explained"),
        Rule::S5TMR_FR_01 => cover!(hit, "S5TMR-FR-01 explained"),
        Rule::SP_Q_01 => cover!(hit, "SP-Q-01 explained"),
        Rule::SE_RUN_ON_01 => cover!(hit, "SE-RUN-ON-01 explained"),
        Rule::SD_Q_01 => cover!(hit, "SD-Q-01 explained"),
        Rule::SS_Q_01 => cover!(hit, "SS-Q-01 explained"),
        Rule::SF_Q_01 => cover!(hit, "SF-Q-01 explained"),
        _ => {}
    }
}

/// Exhaustive over the scope of `exhaustive_s5_rules` (proofs/s5.rs): every kind, value 0, 1,
/// 2, 3, 998, 999, every base and valid flag combination, tick counts that reach every
/// comparison with the value, every S, R, FR and the six TVs; split over two threads.
// Uses the cover recorder, which exists outside Kani only (proofs/cover.rs).
#[cfg(not(kani))]
#[test]
fn exhaustive_explain_s5() {
    const VALUES: [u16; 6] = [0, 1, 2, 3, 998, 999];
    const TICKS: [u64; 7] = [0, 1, 2, 3, 4, 999, 1000];
    let tvs: Vec<_> = [0x0000u16, 0x0001, 0x0999, 0x1500, 0x2001, 0x3999]
        .into_iter()
        .filter_map(|w| plc_timers::time::S5Time::from_word(w).ok())
        .collect();
    let checked = on_two_threads(&S5Kind::ALL, |kinds| {
        let mut n = 0u64;
        for &kind in kinds {
            for value in VALUES {
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
                        for ticks in TICKS {
                            for &tv in &tvs {
                                for input in s5_timer_inputs(tv) {
                                    n += u64::from(prop_explain_s5(S5Case {
                                        kind,
                                        state,
                                        ticks,
                                        input,
                                    }));
                                }
                            }
                        }
                    }
                }
            }
        }
        n
    });
    assert_eq!(
        checked,
        5 * 6 * 4 * 24 * 7 * 6 * 8,
        "every valid case checked"
    );
}

macro_rules! explain_timer_harness {
    ($name:ident, $base:expr) => {
        /// The S5 explanation (faithful, sound, complete) with the timer's time base fixed to a
        /// constant, so that the tick count (`ticks_between`) divides by a constant: random
        /// cases under `cargo test`, every case under Kani. Symbolic: the kind, the state (its
        /// base replaced; invalid states skipped), the tick count, S, R, FR and the TV.
        /// `#[kani::unwind(100)]`: `sound`'s loop over the catalog's rules (`Rule::COUNT`, below 100, /// iterations and the exit) is the longest; the completeness loop has 7 and the loop
        /// over the outputs 3.
        #[test]
        #[cfg_attr(kani, kani::proof, kani::unwind(100))]
        fn $name() {
            crate::cover::harness(concat!(module_path!(), "::", stringify!($name)), || {
                bolero::check!()
                    .with_type::<S5Case>()
                    .with_iterations(2_000)
                    .for_each(|c| {
                        let state = S5State {
                            base: $base,
                            ..c.state
                        };
                        prop_explain_s5(S5Case { state, ..*c });
                        #[cfg(not(kani))]
                        prop_explain_s5(near_expiry(S5Case { state, ..*c }));
                    });
            });
        }
    };
}

explain_timer_harness!(kani_explain_s5_10ms, TimeBase::Ms10);
explain_timer_harness!(kani_explain_s5_100ms, TimeBase::Ms100);
explain_timer_harness!(kani_explain_s5_1s, TimeBase::S1);
explain_timer_harness!(kani_explain_s5_10s, TimeBase::S10);

// ---------------------------------------------------------------------------------------------
// IEC timers

/// One IEC box call of data type `D` (`TIME` or `LTIME`): the state before, the kind, the CPU
/// time (in `D`'s unit) and the inputs.
#[derive(Clone, Copy, Debug)]
pub struct IecCase<C, D: IecDuration = Time> {
    /// The structure before (valid).
    pub state: IecState<C>,
    /// The box.
    pub kind: IecKind,
    /// The CPU time of the call.
    pub now: CpuTime<D::Unit>,
    /// IN, PT, R.
    pub input: IecInput<D>,
}

impl<C: ClockWord, D: IecDuration> IecCase<C, D> {
    /// Whether the call starts the timer on its starting edge (S7-1200 manual, Table 8-20):
    /// TP on a rising IN with no pulse running (after the call's update), TON on a rising IN,
    /// TOF on a falling IN, TONR whenever IN = 1 and R = 0 with the timer stopped and not
    /// expired (TONR-RESUME-01).
    fn started(&self) -> bool {
        let (st, i) = (&self.state, &self.input);
        let now = self.now.clock::<C>();
        match self.kind {
            IecKind::Tp => {
                let pulse_runs = st.running && now.elapsed_since(st.start) < st.pt;
                i.input && !st.input && !pulse_runs
            }
            IecKind::Ton => i.input && !st.input,
            IecKind::Tof => !i.input && st.input,
            IecKind::Tonr => !i.reset && i.input && !st.running && !st.q,
        }
    }

    /// Whether the kind's reset condition holds (TON: IN = 0; TOF: IN = 1; TONR: R = 1).
    fn resets(&self) -> bool {
        match self.kind {
            IecKind::Tp => false,
            IecKind::Ton => !self.input.input,
            IecKind::Tof => self.input.input,
            IecKind::Tonr => self.input.reset,
        }
    }

    /// The preset at the box, as the instruction takes it (negative as 0, IEC-ET-RANGE-01).
    fn box_pt(&self) -> C {
        C::from_preset(self.input.pt.units())
    }
}

/// The premise of each IEC rule a call may report, from the catalog's texts.
fn iec_premise<C: ClockWord, D: IecDuration>(c: &IecCase<C, D>, rule: Rule) -> bool {
    let (st, i) = (&c.state, &c.input);
    let now = c.now.clock::<C>();
    let started = c.started();
    // An update of a running timer happens in the call (it ran before and the kind's reset
    // did not stop it first, or it started).
    let updated = (st.running && !c.resets()) || started;
    match rule {
        // START copied on the starting edge; ET = now - START on each update.
        Rule::IEC_START_01 => updated,
        // PT latched at the start, or a running timer's box PT differing from the latched one.
        Rule::IEC_PT_LATCH_01 => started || (st.running && c.box_pt() != st.pt),
        // A start on the edge, or the stored IN taking a new value.
        Rule::IEC_EDGE_01 => started || i.input != st.input,
        // The comparison ET >= PT of an update.
        Rule::IEC_EXPIRY_01 => updated,
        // Expiry with PT = 0: latched before, or at this start; or PT <= 0 at the box, a
        // preset like any other.
        Rule::IEC_PT0_01 => {
            (st.running && st.pt == C::ZERO)
                || (started && c.box_pt() == C::ZERO)
                || i.pt.units() == 0
        }
        // now - START wrapped: the clock is below START (or TONR's START shifted back below
        // 0); or an update after the CPU time passed 2^BITS ms (the clock word has wrapped).
        Rule::IEC_WRAP_01 => {
            (st.running && now < st.start)
                || (started && c.kind == IecKind::Tonr && st.et > now)
                || (updated && now.to_u64() != c.now.ticks())
        }
        // The structure records the instruction that last ran on it.
        Rule::IEC_ACCESS_01 => st.kind != Some(c.kind),
        Rule::TP_IN_01 => c.kind == IecKind::Tp && (started || !i.input),
        Rule::TP_RETRIGGER_01 => c.kind == IecKind::Tp && started && st.running,
        Rule::TON_IN_01 => c.kind == IecKind::Ton && (started || !i.input),
        Rule::TOF_IN_01 => c.kind == IecKind::Tof && (started || i.input),
        Rule::TONR_RESUME_01 => c.kind == IecKind::Tonr && started,
        Rule::TONR_IN_01 => c.kind == IecKind::Tonr && !i.reset && !i.input && st.running,
        Rule::TONR_R_01 => c.kind == IecKind::Tonr && i.reset,
        _ => false,
    }
}

/// The IEC explanation, faithful, sound and complete for one call.
#[covers]
pub fn prop_explain_iec<C: ClockWord, D: IecDuration>(c: IecCase<C, D>) -> bool {
    let Some(start) = IecTimerRef::from_state(c.state) else {
        return false;
    };
    let (e, plain) = faithful(start, c.kind, c.now, c.input, "IEC-STRUCT-01", &c);
    let out = e.output;

    let reported = e.rules();
    sound(reported, |r| iec_premise(&c, r), &c);
    let (st, after) = (c.state, plain.state());
    let started = c.started();
    let now = c.now.clock::<C>();
    // The call's update found ET >= PT: it ended a running timer (ET = PT, stopped), and no
    // reset of the kind came first.
    let expired = !c.resets()
        && (st.running || started)
        && !after.running
        && after.et == after.pt
        && c.kind != IecKind::Tp
        || (c.kind == IecKind::Tp && st.running && now.elapsed_since(st.start) >= st.pt);
    let acted = [
        (Rule::IEC_START_01, started),
        (Rule::IEC_PT_LATCH_01, started),
        (Rule::IEC_EDGE_01, after.input != st.input),
        (Rule::IEC_EXPIRY_01, expired),
        (
            Rule::IEC_PT0_01,
            started && c.box_pt() == C::ZERO && !c.resets(),
        ),
        // The update computed now - START from the START before the call (a restart on the
        // edge replaces it first, except TP's, whose update comes before its edge).
        (
            Rule::IEC_WRAP_01,
            st.running && now < st.start && !c.resets() && (c.kind == IecKind::Tp || !started),
        ),
        (Rule::IEC_ACCESS_01, after.kind != st.kind),
        (
            Rule::TP_RETRIGGER_01,
            c.kind == IecKind::Tp && started && st.running,
        ),
        (Rule::TON_IN_01, c.kind == IecKind::Ton && !c.input.input),
        (Rule::TOF_IN_01, c.kind == IecKind::Tof && c.input.input),
        (Rule::TONR_RESUME_01, c.kind == IecKind::Tonr && started),
        (
            Rule::TONR_IN_01,
            iec_premise(&c, Rule::TONR_IN_01) && after.et != after.pt,
        ),
        (Rule::TONR_R_01, c.kind == IecKind::Tonr && c.input.reset),
    ];
    for (rule, a) in acted {
        complete(rule, a, reported, &c);
        iec_cover(rule, reported.contains(rule));
    }
    // PT = 0 decides Q at the start (the outputs the open runtimes get wrong).
    if started && c.box_pt() == C::ZERO && !c.resets() {
        assert!(
            e.outputs[0].contains(Rule::IEC_PT0_01),
            "IEC-PT0-01: decides Q in the starting call {c:?}"
        );
    }
    // A start that leaves the timer running decides both outputs (Q and ET take their values
    // at the start): each names the start.
    if started && !c.resets() && after.running {
        for (i, rules) in e.outputs.iter().take(2).enumerate() {
            check!(
                rules.contains(Rule::IEC_START_01),
                "IEC-START-01: output {i} of a starting call names the start {c:?}"
            );
        }
    }
    // What determined the outputs, changed or not: PT <= 0 at the box (IEC-PT0-01's text: a
    // preset like any other, never a reset) decides both; a timer that was running and runs
    // on through the call's update (no start, no reset) has Q by the comparison ET < PT
    // (IEC-EXPIRY-01) and ET by the update (IEC-START-01), on a wrapped clock word by
    // IEC-WRAP-01 too.
    let pt0 = c.input.pt.units() == 0;
    determined(Rule::IEC_PT0_01, 0, pt0, &e, &c);
    determined(Rule::IEC_PT0_01, 1, pt0, &e, &c);
    let runs_on = st.running && !started && !c.resets() && after.running;
    cover!(
        runs_on,
        "IEC-EXPIRY-01 determines the Q of a timer running on"
    );
    determined(Rule::IEC_EXPIRY_01, 0, runs_on, &e, &c);
    determined(Rule::IEC_START_01, 1, runs_on, &e, &c);
    let wrapped = now.to_u64() != c.now.ticks();
    determined(Rule::IEC_WRAP_01, 1, runs_on && wrapped, &e, &c);
    let was = (st.q, st.et);
    every_change_decided(
        "IEC-ET-RANGE-01",
        &e,
        [out.q != was.0, out.et != was.1, false],
        &[],
        &c,
    );
    true
}

#[covers]
fn iec_cover(rule: Rule, hit: bool) {
    match rule {
        Rule::IEC_START_01 => cover!(hit, "IEC-START-01 explained"),
        Rule::IEC_PT_LATCH_01 => cover!(hit, "IEC-PT-LATCH-01 explained"),
        Rule::IEC_EDGE_01 => cover!(hit, "IEC-EDGE-01 explained"),
        Rule::IEC_EXPIRY_01 => cover!(hit, "IEC-EXPIRY-01 explained"),
        Rule::IEC_PT0_01 => cover!(hit, "IEC-PT0-01 explained"),
        Rule::IEC_WRAP_01 => cover!(hit, "IEC-WRAP-01 explained"),
        Rule::IEC_ACCESS_01 => cover!(hit, "IEC-ACCESS-01 explained"),
        Rule::TP_RETRIGGER_01 => cover!(hit, "TP-RETRIGGER-01 explained"),
        Rule::TON_IN_01 => cover!(hit, "TON-IN-01 explained"),
        Rule::TOF_IN_01 => cover!(hit, "TOF-IN-01 explained"),
        Rule::TONR_RESUME_01 => cover!(hit, "TONR-RESUME-01 explained"),
        Rule::TONR_IN_01 => cover!(hit, "TONR-IN-01 explained"),
        Rule::TONR_R_01 => cover!(hit, "TONR-R-01 explained"),
        _ => {}
    }
}

/// Exhaustive on the 4-bit clock (the small scope of `proofs/iec.rs`): every valid structure
/// (46 240) x every kind x every `now` (16) x IN (and R for TONR) x the PTs -1 (taken as 0), 0,
/// 1, 5 and 16 (above the clock: its top); two threads; for `TIME` (ms clock) and `LTIME` (ns
/// clock).
// Uses the cover recorder, which exists outside Kani only (proofs/cover.rs).
#[cfg(not(kani))]
#[test]
fn exhaustive_explain_iec_u4() {
    explain_iec_u4::<Time>();
    explain_iec_u4::<LTime>();
}

/// The body of [`exhaustive_explain_iec_u4`] for the data type `D`.
#[cfg(not(kani))]
fn explain_iec_u4<D: IecDuration>() {
    const PTS: [i128; 5] = [-1, 0, 1, 5, 16];
    let states = all_states_u4();
    let checked = on_two_threads(&IecKind::ALL, |kinds| {
        let mut n = 0u64;
        for &kind in kinds {
            for &state in &states {
                for now in 0..16u64 {
                    for bits in 0..4u8 {
                        let reset = bits & 2 != 0;
                        if reset && kind != IecKind::Tonr {
                            continue;
                        }
                        for pt in PTS {
                            let input = IecInput {
                                input: bits & 1 != 0,
                                pt: D::from_units(pt).expect("within TIME and LTIME"),
                                reset,
                            };
                            n += u64::from(prop_explain_iec::<U4, D>(IecCase {
                                state,
                                kind,
                                now: CpuTime::from_ticks(now),
                                input,
                            }));
                        }
                    }
                }
            }
        }
        n
    });
    assert_eq!(
        checked,
        states.len() as u64 * 16 * 5 * (3 * 2 + 4),
        "every case checked"
    );
}

/// The IEC explanation on a full-width clock, the body of the harnesses of both data types:
/// the structure's members (PT and ET kept to the data type's range), the kind, the CPU time
/// and IN, R, PT.
fn explain_iec_harness<D: FullWidth>()
where
    (IecState<D::Clock>, IecKind, CpuTime<D::Unit>, IecInput<D>): bolero::TypeGenerator,
{
    bolero::check!()
        .with_type::<(IecState<D::Clock>, IecKind, CpuTime<D::Unit>, IecInput<D>)>()
        .with_iterations(20_000)
        .for_each(|&(st, kind, now, input)| {
            prop_explain_iec(IecCase::<D::Clock, D> {
                state: within_range::<D>(st),
                kind,
                now,
                input,
            });
        });
}

/// The IEC explanation on the 32-bit clock (`TIME`): random cases under `cargo test`, every
/// case under Kani. Symbolic: the structure's members (PT and ET kept to TIME's range), the
/// kind, the CPU time and IN, R, PT. `#[kani::unwind(100)]`: `sound`'s loop over the catalog's
/// rules (`Rule::COUNT`, below 100, iterations and the exit) is the longest; the others run
/// over the 2 outputs.
#[test]
#[cfg_attr(kani, kani::proof, kani::unwind(100))]
fn kani_explain_iec() {
    crate::cover::harness(
        concat!(module_path!(), "::", stringify!(kani_explain_iec)),
        explain_iec_harness::<Time>,
    );
}

/// The IEC explanation on the 64-bit nanosecond clock (`LTIME`, `IEC_LTIMER`): random cases
/// under `cargo test`, every case under Kani. Symbolic: the structure's members (PT and ET kept
/// to LTIME's range), the kind, the CPU time and IN, R, PT. `#[kani::unwind(100)]`: `sound`'s
/// loop over the catalog's rules (`Rule::COUNT`, below 100, iterations and the exit) is the
/// longest; the others run over the 2 outputs.
#[test]
#[cfg_attr(kani, kani::proof, kani::unwind(100))]
fn kani_explain_ltimer() {
    crate::cover::harness(
        concat!(module_path!(), "::", stringify!(kani_explain_ltimer)),
        explain_iec_harness::<LTime>,
    );
}

// ---------------------------------------------------------------------------------------------
// IEC counters

/// The premise of each counter rule, from the catalog's texts; `input` masked to the kind's
/// inputs (CNT-INPUTS-01).
fn counter_premise<T: CounterInt>(
    kind: CounterKind,
    st: &CounterState<T>,
    raw: &CounterInput<T>,
    rule: Rule,
) -> bool {
    let i = raw.with_signals(kind.mask(raw.signals()));
    let up = i.cu && !st.cu_prev;
    let down = i.cd && !st.cd_prev;
    let counts = !i.r && !i.ld;
    match rule {
        // A count on an edge, an edge memory taking a new value, or a count input held at 1
        // that does not count.
        Rule::CNT_EDGE_01 => {
            (counts && (up || down))
                || i.cu != st.cu_prev
                || i.cd != st.cd_prev
                || (counts && (i.cu || i.cd))
        }
        Rule::CNT_PRIO_01 => i.r || i.ld,
        // Saturation at the limits, or counting down below 0 (only MIN stops it).
        Rule::CNT_SAT_01 => {
            counts
                && up != down
                && ((up && st.cv == T::MAX) || (down && (st.cv == T::MIN || st.cv <= T::ZERO)))
        }
        Rule::CNT_SIMUL_01 => counts && up && down,
        // Q derived from CV and PV (every call), and counting on past PV.
        Rule::CNT_Q_01 => true,
        Rule::CNT_INPUTS_01 => i.signals() != raw.signals(),
        _ => false,
    }
}

/// The catalog index of CV and the mask of the Q outputs of `kind`.
fn counter_outputs(kind: CounterKind) -> (usize, &'static [usize]) {
    match kind {
        CounterKind::Ctu | CounterKind::Ctd => (1, &[0]),
        CounterKind::Ctud => (2, &[0, 1]),
    }
}

/// The IEC counter explanation, faithful, sound and complete for one call.
#[covers]
pub fn prop_explain_counter<T: CounterInt>(
    kind: CounterKind,
    st: CounterState<T>,
    raw: CounterInput<T>,
) -> bool {
    let case = (kind, st, raw);
    // A counter's call takes no time: `now` is ignored.
    let start = CounterRef::from_state(st);
    let (e, _) = faithful(start, kind, CpuTime::ZERO, raw, "CNT-EQUIV-01", &case);
    let out = e.output;
    let reported = e.rules();
    sound(reported, |r| counter_premise(kind, &st, &raw, r), &case);
    let (cv_at, qs) = counter_outputs(kind);
    let i = raw.with_signals(kind.mask(raw.signals()));
    let up = i.cu && !st.cu_prev;
    let down = i.cd && !st.cd_prev;
    let counts = !i.r && !i.ld;
    // CNT-Q-01 decides the Q outputs only, and CV only when counting up goes past PV.
    for (n, o) in e.outputs.iter().enumerate() {
        if o.contains(Rule::CNT_Q_01) && !qs.contains(&n) {
            assert!(
                n == cv_at && counts && up && !down && st.cv >= i.pv,
                "CNT-Q-01: decides output {n} only when counting goes on past PV {case:?}"
            );
        }
    }
    let acted = [
        (Rule::CNT_EDGE_01, counts && (up || down)),
        (Rule::CNT_EDGE_01, i.cu != st.cu_prev || i.cd != st.cd_prev),
        (Rule::CNT_PRIO_01, i.r || i.ld),
        (
            Rule::CNT_SAT_01,
            counter_premise(kind, &st, &raw, Rule::CNT_SAT_01),
        ),
        (Rule::CNT_SIMUL_01, counts && up && down),
        (Rule::CNT_INPUTS_01, i.signals() != raw.signals()),
    ];
    for (rule, a) in acted {
        complete(rule, a, reported, &case);
    }
    complete(
        Rule::CNT_Q_01,
        counts && up && !down && st.cv >= i.pv && st.cv != T::MAX,
        e.outputs[cv_at],
        &case,
    );
    // What determined CV, changed or not: a count input held at 1 does not count (CNT-EDGE-01's
    // text); a count down from 0 or below goes on below 0 (CNT-SAT-01's text).
    let held = counts && !up && !down && (i.cu || i.cd);
    cover!(held, "CNT-EDGE-01 determines a CV a held input left");
    determined(Rule::CNT_EDGE_01, cv_at, held, &e, &case);
    let below = counts && down && !up && st.cv <= T::ZERO;
    // Unsigned types have MIN = 0: there the count down from 0 saturates.
    cover!(
        below && (st.cv != T::MIN || T::MIN == T::ZERO),
        "CNT-SAT-01 explained: counting below 0"
    );
    determined(Rule::CNT_SAT_01, cv_at, below, &e, &case);
    for &q in qs {
        complete(Rule::CNT_Q_01, true, e.outputs[q], &case);
        // A Q output is CV compared with PV: whatever decided CV decided it too.
        assert!(
            e.outputs[cv_at].is_subset(e.outputs[q]),
            "CNT-Q-01: output {q} is derived from CV, but lacks the rules that decided CV \
             ({:?} not in {:?}) {case:?}",
            e.outputs[cv_at],
            e.outputs[q]
        );
    }
    cover!(
        e.outputs[cv_at].contains(Rule::CNT_Q_01),
        "CNT-Q-01 explained: counting past PV"
    );
    cover!(reported.contains(Rule::CNT_SAT_01), "CNT-SAT-01 explained");
    cover!(
        reported.contains(Rule::CNT_SIMUL_01),
        "CNT-SIMUL-01 explained"
    );
    cover!(
        reported.contains(Rule::CNT_PRIO_01),
        "CNT-PRIO-01 explained"
    );
    cover!(
        reported.contains(Rule::CNT_EDGE_01),
        "CNT-EDGE-01 explained"
    );
    cover!(
        reported.contains(Rule::CNT_INPUTS_01),
        "CNT-INPUTS-01 explained"
    );
    let before = plc_timers::counter::outputs(st.cv, i.pv);
    let changed = |o: &CounterOutput<T>| [o.qu, o.qd];
    let mut ch = [false; 3];
    match kind {
        CounterKind::Ctu => ch[0] = out.qu != before.qu,
        CounterKind::Ctd => ch[0] = out.qd != before.qd,
        CounterKind::Ctud => {
            ch[0] = changed(&out)[0] != changed(&before)[0];
            ch[1] = changed(&out)[1] != changed(&before)[1];
        }
    }
    ch[cv_at] = out.cv != st.cv;
    every_change_decided("CNT-Q-01", &e, ch, qs, &case);
    true
}

/// Exhaustive on 8-bit types: every kind x CV x PV (each 256 values of `i8`, and of `u8`
/// for the unsigned limits) x the 4 edge memories x the 16 inputs.
// Uses the cover recorder, which exists outside Kani only (proofs/cover.rs).
#[cfg(not(kani))]
#[test]
fn exhaustive_explain_counters_8bit() {
    fn all<T: CounterInt>(values: impl Iterator<Item = T> + Clone) -> u64 {
        crate::cover::check_covers(|| {
            let mut n = 0;
            for kind in CounterKind::ALL {
                for st in counter_states(values.clone()) {
                    for pv in values.clone() {
                        for input in counter_inputs(pv) {
                            n += u64::from(prop_explain_counter(kind, st, input));
                        }
                    }
                }
            }
            n
        })
    }
    assert_eq!(all(i8::MIN..=i8::MAX), 3 * 256 * 256 * 4 * 16);
    assert_eq!(all(u8::MIN..=u8::MAX), 3 * 256 * 256 * 4 * 16);
}

/// The IEC counter explanation on `i32`: random cases, every case under Kani. Symbolic: the
/// kind, CV, the edge memories, CU, CD, R, LD and PV. `#[kani::unwind(100)]`: `sound`'s loop
/// over the catalog's rules (`Rule::COUNT`, below 100, iterations and the exit) is the longest.
#[test]
#[cfg_attr(kani, kani::proof, kani::unwind(100))]
fn kani_explain_counter() {
    crate::cover::harness(
        concat!(module_path!(), "::", stringify!(kani_explain_counter)),
        || {
            bolero::check!()
                .with_type::<(CounterKind, CounterState<i32>, CounterInput<i32>)>()
                .with_iterations(20_000)
                .for_each(|(kind, st, input)| {
                    prop_explain_counter(*kind, *st, *input);
                    #[cfg(not(kani))]
                    prop_explain_counter(*kind, crate::counter::at_limit(*st), *input);
                });
        },
    );
}

// ---------------------------------------------------------------------------------------------
// S5 counters

/// The premise of each S5 counter rule, from the catalog's texts: the box runs FR, CU, CD, S,
/// R (SC-STL-01), so the edges are seen with the memories after FR.
fn s5c_premise(kind: S5CounterKind, st: &S5CounterState, i: &S5CounterInput, rule: Rule) -> bool {
    let fr_edge = i.fr && !st.fr_prev;
    let (cu_m, cd_m, s_m) = (
        st.cu_prev && !fr_edge,
        st.cd_prev && !fr_edge,
        st.s_prev && !fr_edge,
    );
    let up = kind.counts_up() && i.cu && !cu_m;
    let down = kind.counts_down() && i.cd && !cd_m;
    let set = i.s && !s_m;
    // CV when CD runs: after CU.
    let cv_up = if up { (st.cv + 1).min(CV_MAX) } else { st.cv };
    match rule {
        Rule::SC_FR_01 => i.fr != st.fr_prev,
        Rule::SC_EDGE_01 => {
            up || down
                || set
                || (kind.counts_up() && i.cu != cu_m)
                || (kind.counts_down() && i.cd != cd_m)
                || i.s != s_m
        }
        Rule::SC_SAT_01 => (up && st.cv == CV_MAX) || (down && cv_up == 0),
        Rule::SC_SIMUL_01 => up && down,
        Rule::SC_SET_01 => set,
        Rule::SC_PRIO_01 => i.r || (set && (up || down)),
        Rule::SC_Q_01 => true,
        Rule::SC_INPUTS_01 => (!kind.counts_up() && i.cu) || (!kind.counts_down() && i.cd),
        _ => false,
    }
}

/// The S5 counter explanation, faithful, sound and complete for one call; and the counter
/// memory area's explained operations faithful to the plain ones.
#[covers]
pub fn prop_explain_s5_counter(kind: S5CounterKind, st: S5CounterState, i: S5CounterInput) -> bool {
    let Some(start) = S5CounterRef::from_state(st) else {
        return false;
    };
    let case = (kind, st, i);
    // A counter's call takes no time: `now` is ignored.
    let (e, plain) = faithful(start, kind, CpuTime::ZERO, i, "CNT-EQUIV-01", &case);
    let out = e.output;
    let reported = e.rules();
    sound(reported, |r| s5c_premise(kind, &st, &i, r), &case);
    assert!(
        !e.outputs[1]
            .union(e.outputs[2])
            .union(e.state)
            .contains(Rule::SC_Q_01),
        "SC-Q-01: decides Q only {case:?}"
    );
    let after = plain.state();
    for rule in [Rule::SC_SET_01, Rule::SC_PRIO_01] {
        complete(rule, s5c_premise(kind, &st, &i, rule), reported, &case);
    }
    // Saturation and simultaneous edges decide CV unless a set or R overrides the counting.
    let overridden = i.r || s5c_premise(kind, &st, &i, Rule::SC_SET_01);
    for rule in [Rule::SC_SAT_01, Rule::SC_SIMUL_01] {
        complete(
            rule,
            s5c_premise(kind, &st, &i, rule) && !overridden,
            reported,
            &case,
        );
    }
    // A missing operation matters unless R clears CV anyway.
    complete(
        Rule::SC_INPUTS_01,
        s5c_premise(kind, &st, &i, Rule::SC_INPUTS_01) && !i.r,
        reported,
        &case,
    );
    complete(Rule::SC_FR_01, after.fr_prev != st.fr_prev, reported, &case);
    let memories_changed =
        after.cu_prev != st.cu_prev || after.cd_prev != st.cd_prev || after.s_prev != st.s_prev;
    let fr_edge = i.fr && !st.fr_prev;
    complete(
        Rule::SC_EDGE_01,
        memories_changed && !fr_edge,
        reported,
        &case,
    );
    complete(Rule::SC_Q_01, true, e.outputs[0], &case);
    // R decides CV alone.
    if i.r {
        assert_eq!(
            e.outputs[1],
            RuleSet::of(Rule::SC_PRIO_01),
            "SC-PRIO-01: R decides CV alone {case:?}"
        );
    }
    let was = st.output();
    every_change_decided(
        "SC-Q-01",
        &e,
        [out.q != was.q, out.cv != was.cv, out.cv_bcd != was.cv_bcd],
        &[],
        &case,
    );
    for (rule, name) in [
        (Rule::SC_FR_01, 0),
        (Rule::SC_EDGE_01, 1),
        (Rule::SC_SAT_01, 2),
        (Rule::SC_SIMUL_01, 3),
        (Rule::SC_SET_01, 4),
        (Rule::SC_PRIO_01, 5),
        (Rule::SC_INPUTS_01, 6),
    ] {
        let hit = reported.contains(rule);
        match name {
            0 => cover!(hit, "SC-FR-01 explained"),
            1 => cover!(hit, "SC-EDGE-01 explained"),
            2 => cover!(hit, "SC-SAT-01 explained"),
            3 => cover!(hit, "SC-SIMUL-01 explained"),
            4 => cover!(hit, "SC-SET-01 explained"),
            5 => cover!(hit, "SC-PRIO-01 explained"),
            _ => cover!(hit, "SC-INPUTS-01 explained"),
        }
    }

    // The memory area: the box and the STL operations, explained and plain.
    let mut area = CounterMemory::<1>::new();
    assert!(area.set_state(0, st).expect("C 0"));
    let (mut a, mut b) = (area.clone(), area);
    let plain = a.call(0, kind, i).expect("C 0");
    let eb = b.call_explained(0, kind, i).expect("C 0");
    assert_eq!(
        (&b, eb.output),
        (&a, plain),
        "SC-STL-01: area call explained {case:?}"
    );
    assert_eq!(
        eb, e,
        "SC-STL-01: the area explains as the reference {case:?}"
    );
    let (mut a, mut b) = (area_with(st), area_with(st));
    for (which, rlo) in [i.fr, i.cu, i.cd, i.s, i.r].into_iter().enumerate() {
        let e = match which {
            0 => {
                a.fr(0, rlo).expect("C 0");
                b.fr_explained(0, rlo)
            }
            1 => {
                a.cu(0, rlo).expect("C 0");
                b.cu_explained(0, rlo)
            }
            2 => {
                a.cd(0, rlo).expect("C 0");
                b.cd_explained(0, rlo)
            }
            3 => {
                a.set(0, rlo, i.pv).expect("C 0");
                b.set_explained(0, rlo, i.pv)
            }
            _ => {
                a.reset(0, rlo).expect("C 0");
                b.reset_explained(0, rlo)
            }
        }
        .expect("C 0");
        assert_eq!(
            (&b, e.output),
            (&a, a.outputs().next().expect("C 0")),
            "SC-STL-01: STL operation {which} explained {case:?}"
        );
    }
    true
}

fn area_with(st: S5CounterState) -> CounterMemory<1> {
    let mut area = CounterMemory::<1>::new();
    assert!(area.set_state(0, st).expect("C 0"));
    area
}

/// Exhaustive: 3 kinds x CV 0..=999 x 16 edge memories x 32 inputs x the presets 0, 1, 999.
// Uses the cover recorder, which exists outside Kani only (proofs/cover.rs).
#[cfg(not(kani))]
#[test]
fn exhaustive_explain_s5_counters() {
    let presets: Vec<CounterPreset> = [0, 1, 999]
        .into_iter()
        .filter_map(|n| CounterPreset::new(n).ok())
        .collect();
    let n: u64 = crate::cover::check_covers(|| {
        let mut n = 0;
        for kind in S5CounterKind::ALL {
            for st in s5_counter_states(0..=CV_MAX) {
                for &pv in &presets {
                    for input in s5_counter_inputs(pv) {
                        n += u64::from(prop_explain_s5_counter(kind, st, input));
                    }
                }
            }
        }
        n
    });
    assert_eq!(n, 3 * 1000 * 16 * 3 * 32, "every case checked");
}

/// The S5 counter explanation: random cases, every case under Kani. Symbolic: the kind, CV,
/// the edge memories, CU, CD, S, R, FR and the preset. `#[kani::unwind(100)]`: `sound`'s loop
/// over the catalog's rules (`Rule::COUNT`, below 100, iterations and the exit) is the longest.
#[test]
#[cfg_attr(kani, kani::proof, kani::unwind(100))]
fn kani_explain_s5_counter() {
    crate::cover::harness(
        concat!(module_path!(), "::", stringify!(kani_explain_s5_counter)),
        || {
            bolero::check!()
                .with_type::<(S5CounterKind, S5CounterState, S5CounterInput)>()
                .with_iterations(20_000)
                .for_each(|(kind, st, input)| {
                    prop_explain_s5_counter(*kind, *st, *input);
                    #[cfg(not(kani))]
                    prop_explain_s5_counter(*kind, crate::counter::s5_at_limit(*st), *input);
                });
        },
    );
}
