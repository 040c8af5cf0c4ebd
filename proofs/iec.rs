//! Properties of the IEC timers: the 16-byte structure simulates the reference for every
//! operation (box call, update-on-access reads, RT and PT coils, RUN-STOP-RUN), the invariants
//! hold, no start without the starting edge, no panic.
//!
//! Small scope: both implementations are generic over the clock width and over the data type
//! of PT and ET (`TIME` in milliseconds, `LTIME` in nanoseconds: [`IecDuration`]). The
//! exhaustive drivers run them on a 4-bit clock ([`U4`]) and on `u8`, where every state and
//! every operation can be enumerated, once with `TIME` presets on the millisecond clock and
//! once with `LTIME` presets on the nanosecond clock; the code under test is the same generic
//! code as on the full-width clocks, and every ordering of START, now, ET and PT, and every
//! wrap of `now - START`, occurs at 4 bits. The proptest driver covers the 32-bit clock; the
//! Kani harnesses state the full widths, `IEC_TIMER` (32-bit ms clock, `TIME`) and
//! `IEC_LTIMER` (64-bit ns clock, `LTIME`), from one generic body each.

use crate::cover::{check, check_eq};
use std::thread;

use plc_timers::iec::{IecInput, IecKind, IecState, IecTimerOf, IecTimerOps, IecTimerRef, TonBank};
use plc_timers::time::clock::ClockWord;
use plc_timers::time::{CpuTime, IecDuration, LTime, Time, TimeUnit};
use plc_timers::{NoSuchOperand, Operand};
use proptest::prelude::*;

/// A 4-bit wrapping clock, for exhaustive enumeration.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, PartialOrd, Ord, Hash)]
pub struct U4(u8);

impl ClockWord for U4 {
    const BITS: u32 = 4;
    const ZERO: Self = U4(0);
    const MAX: Self = U4(15);
    const TOP_BIT: Self = U4(8);
    fn elapsed_since(self, earlier: Self) -> Self {
        U4(self.0.wrapping_sub(earlier.0) & 15)
    }
    fn advance(self, d: Self) -> Self {
        U4(self.0.wrapping_add(d.0) & 15)
    }
    fn from_u64_wrapping(t_ms: u64) -> Self {
        U4((t_ms & 15) as u8)
    }
    fn to_u64(self) -> u64 {
        u64::from(self.0)
    }
    fn from_preset(units: u64) -> Self {
        U4(units.min(15) as u8)
    }
}

/// One operation on a timer structure of data type `D` (its CPU time in `D`'s unit).
#[derive(Clone, Copy, Debug, PartialEq, Eq, bolero::TypeGenerator)]
pub enum Op<D: IecDuration = Time> {
    /// A box call.
    Call(IecKind, CpuTime<D::Unit>, IecInput<D>),
    /// Reading `Q` through the structure at a time.
    ReadQ(CpuTime<D::Unit>),
    /// Reading `ELAPSED` through the structure at a time.
    ReadEt(CpuTime<D::Unit>),
    /// The RT coil.
    Rt,
    /// The PT coil.
    PtCoil(D),
    /// RUN-STOP-RUN (retentive or not).
    RunStopRun(bool),
}

/// `units` of `D` (a preset of the drivers), saturated at `D`'s range.
fn preset_of<D: IecDuration>(units: i128) -> D {
    D::from_units(units).unwrap_or(if units < 0 { D::ZERO } else { D::MAX })
}

fn apply<C: ClockWord, D: IecDuration, T: IecTimerOps<C, D>>(t: &mut T, op: Op<D>) -> (bool, C) {
    match op {
        Op::Call(kind, now, input) => {
            let o = t.call(kind, now, input);
            (o.q, o.et)
        }
        Op::ReadQ(now) => (t.read_q(now), t.state().et),
        Op::ReadEt(now) => {
            let et = t.read_et(now);
            (t.state().q, et)
        }
        Op::Rt => {
            t.reset_timer();
            (t.state().q, t.state().et)
        }
        Op::PtCoil(pt) => {
            t.preset_timer(pt);
            (t.state().q, t.state().et)
        }
        Op::RunStopRun(retentive) => {
            t.run_stop_run(retentive);
            (t.state().q, t.state().et)
        }
    }
}

/// IEC-STRUCT-01: for every valid state and operation, the structure's result and its state
/// mapped through the abstraction function equal the reference's.
pub fn prop_step_equivalence<C: ClockWord, D: IecDuration>(state: IecState<C>, op: Op<D>) -> bool {
    let Some(mut opt) = IecTimerOf::<C, D>::from_state(state) else {
        return false;
    };
    check_eq!(
        opt.state(),
        state,
        "IEC-STRUCT-01: abstraction inverts from_state"
    );
    let mut r = IecTimerRef::<C, D>::from_state(state).expect("valid");
    let ro = apply(&mut r, op);
    let oo = apply(&mut opt, op);
    check_eq!(oo, ro, "IEC-STRUCT-01 outputs {state:?} {op:?}");
    check_eq!(
        opt.state(),
        r.state(),
        "IEC-STRUCT-01 state {state:?} {op:?}"
    );
    // Equal states are equal bytes: the structure is exactly the encoding of the reference
    // state (no stray flag bits, no stale START), and its accessors read the same members.
    check_eq!(
        IecTimerOf::from_state(r.state()),
        Some(opt),
        "IEC-STRUCT-01 canonical bytes {state:?} {op:?}"
    );
    check_eq!((opt.pt(), opt.et()), (r.state().pt, r.state().et));
    true
}

/// One step of IEC-EQUIV-02: applies `op` to both timers, then compares the outputs, the
/// structure mapped through the abstraction function with the reference state, and the
/// validity invariant. `step` and `ops` only name the step in the failure message.
fn sequence_step<C: ClockWord, D: IecDuration>(
    r: &mut IecTimerRef<C, D>,
    opt: &mut IecTimerOf<C, D>,
    op: Op<D>,
    step: usize,
    ops: &[Op<D>],
) {
    let ro = apply(r, op);
    let oo = apply(opt, op);
    check_eq!(oo, ro, "IEC-EQUIV-02 outputs at step {step} of {ops:?}");
    check_eq!(
        opt.state(),
        r.state(),
        "IEC-EQUIV-02 state at step {step} of {ops:?}"
    );
    check!(
        opt.state().is_valid() && r.state().is_valid(),
        "IEC-ET-RANGE-01 at step {step} of {ops:?}"
    );
    check_eq!(
        IecTimerOf::from_state(r.state()),
        Some(*opt),
        "IEC-EQUIV-02 canonical bytes at step {step} of {ops:?}"
    );
}

/// IEC-EQUIV-02: from the initial structure, every sequence of operations gives the same
/// outputs and (through the abstraction function) the same states in the reference and the
/// 16-byte structure, and every state on the way is valid.
pub fn prop_sequence_equivalence<C: ClockWord, D: IecDuration>(ops: &[Op<D>]) {
    let mut r = IecTimerRef::<C, D>::default();
    let mut opt = IecTimerOf::<C, D>::new();
    check_eq!(opt.state(), r.state(), "IEC-EQUIV-02 initial state");
    for (i, &op) in ops.iter().enumerate() {
        sequence_step(&mut r, &mut opt, op, i, ops);
    }
}

/// IEC-ET-RANGE-01, IEC-RT-01, IEC-EDGE-01: after any operation ET is within 0..=PT (the
/// latched, non-negative preset); after RT, ET = 0 and Q = 0 and the timer is stopped; a stopped
/// timer starts only on its starting edge (rising IN for TP and TON, falling IN for TOF; for
/// TONR, IN = 1 with R = 0, the decision TONR-RESUME-01).
pub fn prop_invariants<C: ClockWord, D: IecDuration>(state: IecState<C>, op: Op<D>) -> bool {
    if !state.is_valid() {
        return false;
    }
    let mut r = IecTimerRef::<C, D>::from_state(state).expect("valid");
    let (q, et) = apply(&mut r, op);
    let after = r.state();
    // Stated here rather than through `IecState::is_valid`, so that the property does not
    // trust the predicate it is meant to check.
    check!(
        after.et <= after.pt,
        "IEC-ET-RANGE-01: {after:?} after {op:?}"
    );
    check!(
        after.running || after.start == C::default(),
        "a stopped timer keeps no START: {after:?} after {op:?}"
    );
    check_eq!(
        (q, et),
        (after.q, after.et),
        "outputs are the structure's members"
    );
    check!(
        i128::from(after.pt.to_u64()) <= i128::from(D::MAX.units_signed()),
        "IEC-ET-RANGE-01: PT is a non-negative {}",
        D::NAME
    );
    match op {
        Op::Rt => check!(
            after.et == C::default() && !after.q && !after.running,
            "IEC-RT-01: RT clears ET and Q"
        ),
        Op::Call(kind, _, input) if !state.running && after.running => {
            let edge = match kind {
                IecKind::Tp | IecKind::Ton => input.input && !state.input,
                IecKind::Tof => !input.input && state.input,
                IecKind::Tonr => input.input && !input.reset,
            };
            check!(
                edge,
                "IEC-EDGE-01: {kind:?} started without its starting edge"
            );
        }
        Op::ReadQ(_) | Op::ReadEt(_) | Op::PtCoil(_) | Op::RunStopRun(true) => {
            check!(
                !after.running || state.running,
                "an access or coil never starts a timer"
            );
        }
        _ => {}
    }
    true
}

/// S7-1200 manual, Table 8-20, all kinds: while a timer runs, a change of PT has no effect (the call
/// gives the same result whatever PT is: IEC-PT-LATCH-01); TP ignores IN while running
/// (TP-IN-01); TON resets and stops on IN = 0 (TON-IN-01); TOF resets and stops on IN = 1
/// (TOF-IN-01); TONR stops without reset on IN = 0 (TONR-IN-01).
pub fn prop_table_8_20<C: ClockWord, D: IecDuration>(
    state: IecState<C>,
    kind: IecKind,
    now: CpuTime<D::Unit>,
    input: IecInput<D>,
    other_pt: D,
) -> bool {
    // "While the timer runs": started, of this kind, not yet at PT at `now`, and with the stored
    // IN a running timer of this kind has (1 for TON and TONR, 0 for TOF): the reachable states.
    let stored_in_consistent = match kind {
        IecKind::Tp => true,
        IecKind::Ton | IecKind::Tonr => state.input,
        IecKind::Tof => !state.input,
    };
    if !state.is_valid()
        || !state.running
        || state.kind != Some(kind)
        || !stored_in_consistent
        || now.clock::<C>().elapsed_since(state.start) >= state.pt
    {
        return false;
    }
    let step = |input: IecInput<D>| {
        let mut r = IecTimerRef::<C, D>::from_state(state).expect("valid");
        let o = r.call(kind, now, input);
        (o, r.state())
    };
    let (o, after) = step(input);
    check_eq!(
        step(IecInput {
            pt: other_pt,
            ..input
        }),
        (o, after),
        "IEC-PT-LATCH-01: PT ignored while running"
    );
    match kind {
        IecKind::Tp => {
            let (o2, a2) = step(IecInput {
                input: !input.input,
                ..input
            });
            check_eq!(
                (o2, a2.running, a2.start, a2.pt),
                (o, after.running, after.start, after.pt),
                "TP-IN-01"
            );
        }
        IecKind::Ton if !input.input => {
            check!(!after.running && !o.q && o.et == C::default(), "TON-IN-01");
        }
        IecKind::Tof if input.input => {
            check!(!after.running && o.q && o.et == C::default(), "TOF-IN-01");
        }
        IecKind::Tonr if !input.input && !input.reset => {
            let accumulated = now.clock::<C>().elapsed_since(state.start);
            check!(
                !after.running && o.et == accumulated,
                "TONR-IN-01: stops, ET keeps the accumulated time"
            );
        }
        _ => {}
    }
    true
}

/// Every valid state on the 4-bit clock: kind (or none) x IN x running x Q x START (any when
/// running, 0 otherwise) x PT x ET <= PT: 46 240 states.
pub fn all_states_u4() -> Vec<IecState<U4>> {
    let kinds = [
        None,
        Some(IecKind::Tp),
        Some(IecKind::Ton),
        Some(IecKind::Tof),
        Some(IecKind::Tonr),
    ];
    let mut v = Vec::new();
    for kind in kinds {
        for flags in 0..8u8 {
            let running = flags & 4 != 0;
            let starts = if running { 0..16 } else { 0..1 };
            for start in starts {
                for pt in 0..16u8 {
                    for et in 0..=pt {
                        v.push(IecState {
                            kind,
                            input: flags & 1 != 0,
                            running,
                            start: U4(start),
                            pt: U4(pt),
                            et: U4(et),
                            q: flags & 2 != 0,
                        });
                    }
                }
            }
        }
    }
    v
}

/// PT inputs in units of the data type: negative (taken as 0), 0, 1, the middle, one below the
/// clock's range, its top, above it, and the largest value of the data type ([`pts`]).
const PTS: [i128; 8] = [-1, 0, 1, 5, 14, 15, 16, i128::MAX];

/// [`PTS`] of `D` (the last, the largest `D`).
fn pts<D: IecDuration>() -> [D; 8] {
    PTS.map(preset_of)
}

/// Every operation on the 4-bit clock: calls of each kind at every `now` with every IN (and R
/// for TONR) and PT of `PTS`; reads at every `now`; RT; PT coil with every PT; RUN-STOP-RUN.
/// `now` and PT in `D`'s unit (ms for `TIME`, ns for `LTIME`).
pub fn all_ops_u4<D: IecDuration>() -> Vec<Op<D>> {
    let mut ops = Vec::new();
    for kind in IecKind::ALL {
        for now in 0..16u8 {
            for input in [false, true] {
                for reset in [false, true] {
                    if reset && kind != IecKind::Tonr {
                        continue;
                    }
                    for pt in pts::<D>() {
                        ops.push(Op::Call(
                            kind,
                            CpuTime::from_ticks(u64::from(now)),
                            IecInput { input, pt, reset },
                        ));
                    }
                }
            }
        }
    }
    for now in 0..16u8 {
        ops.push(Op::ReadQ(CpuTime::from_ticks(u64::from(now))));
        ops.push(Op::ReadEt(CpuTime::from_ticks(u64::from(now))));
    }
    ops.push(Op::Rt);
    ops.extend(pts::<D>().map(Op::PtCoil));
    ops.push(Op::RunStopRun(false));
    ops.push(Op::RunStopRun(true));
    ops
}

/// Exhaustive on the 4-bit clock: every valid state (46 240) x every operation (1 323):
/// 61 million steps, on two threads, for `TIME` (ms clock) and for `LTIME` (ns clock). See the
/// module doc for why 4 bits is a complete small scope for this generic code.
#[test]
fn exhaustive_u4_step_equivalence_and_invariants() {
    step_equivalence_and_invariants_u4::<Time>();
    step_equivalence_and_invariants_u4::<LTime>();
}

/// The body of [`exhaustive_u4_step_equivalence_and_invariants`] for the data type `D`.
fn step_equivalence_and_invariants_u4<D: IecDuration>() {
    let states = all_states_u4();
    let ops = all_ops_u4::<D>();
    check_eq!(states.len(), 46_240);
    let (a, b) = states.split_at(states.len() / 2);
    let n = thread::scope(|scope| {
        let mut workers = Vec::new();
        for part in [a, b] {
            let ops = &ops;
            workers.push(scope.spawn(move || {
                let mut n = [0u64; 3];
                for &state in part {
                    for &op in ops {
                        n[0] += u64::from(prop_step_equivalence(state, op));
                        n[1] += u64::from(prop_invariants(state, op));
                        if let Op::Call(kind, now, input) = op {
                            let checked =
                                prop_table_8_20(state, kind, now, input, preset_of::<D>(3));
                            n[2] += u64::from(checked);
                        }
                    }
                }
                n
            }));
        }
        workers
            .into_iter()
            .map(|w| w.join().expect("worker finished"))
            .fold([0; 3], |a, b| [a[0] + b[0], a[1] + b[1], a[2] + b[2]])
    });
    // Every enumerated state is valid, so every (state, operation) pair is checked; Table 8-20
    // applies to the calls of a running timer of the called kind, a strict, non-empty subset.
    let all = (states.len() * ops.len()) as u64;
    check_eq!((n[0], n[1]), (all, all), "every case checked");
    check!(n[2] > 0 && n[2] < all, "{} Table 8-20 cases", n[2]);
}

/// The alphabet of the bounded sequence driver on the 4-bit clock: calls of every kind at
/// `now` in {0, 2, 7, 14} (so that a START of 14 followed by `now` = 2 crosses the wrap) with
/// every IN (and R for TONR) and PT in {-1, 0, 5, 15}; reads of Q and ELAPSED at 2 and 14; RT;
/// the PT coil with 5; RUN-STOP-RUN both ways: 168 operations.
fn sequence_ops_u4<D: IecDuration>() -> Vec<Op<D>> {
    let pts = [-1, 0, 5, 15];
    all_ops_u4::<D>()
        .into_iter()
        .filter(|op| match *op {
            Op::Call(_, now, input) => {
                [0, 2, 7, 14].contains(&now.ticks()) && pts.contains(&input.pt.units_signed())
            }
            Op::ReadQ(now) | Op::ReadEt(now) => now.ticks() == 2 || now.ticks() == 14,
            Op::PtCoil(pt) => pt.units_signed() == 5,
            Op::Rt | Op::RunStopRun(_) => true,
        })
        .collect()
}

/// Depth-first over every sequence of `depth` more operations from `alphabet`, checking each
/// step as [`prop_sequence_equivalence`] does; returns the number of steps checked.
fn sequences_from<D: IecDuration>(
    r: &IecTimerRef<U4, D>,
    opt: &IecTimerOf<U4, D>,
    alphabet: &[Op<D>],
    prefix: &mut Vec<Op<D>>,
    depth: usize,
) -> u64 {
    if depth == 0 {
        return 0;
    }
    let mut steps = 0;
    for &op in alphabet {
        let (mut r2, mut opt2) = (*r, *opt);
        prefix.push(op);
        sequence_step(&mut r2, &mut opt2, op, prefix.len() - 1, prefix);
        steps += 1 + sequences_from(&r2, &opt2, alphabet, prefix, depth - 1);
        prefix.pop();
    }
    steps
}

/// IEC-EQUIV-02, bounded exhaustive on the 4-bit clock: every sequence of up to 3 operations
/// from the 168-operation alphabet of [`sequence_ops_u4`] (168 + 168^2 + 168^3 = 4 769 640
/// steps), from the initial structure, for `TIME` and for `LTIME`. This complements the
/// one-step simulation relation (which covers every valid state, reachable or not) with the
/// end-to-end view from power-up.
#[test]
fn bounded_sequences_u4_from_initial_state() {
    fn sequences<D: IecDuration>() {
        let alphabet = sequence_ops_u4::<D>();
        check_eq!(alphabet.len(), 168);
        let steps = sequences_from(
            &IecTimerRef::<U4, D>::default(),
            &IecTimerOf::new(),
            &alphabet,
            &mut Vec::new(),
            3,
        );
        check_eq!(steps, 168 + 168 * 168 + 168 * 168 * 168);
    }
    sequences::<Time>();
    sequences::<LTime>();
}

/// The update on the real `u8` instance of the generic code (no test-only clock): every START
/// (256) x every `now` (256) x every latched PT (256) for each of the four kinds, a running
/// timer with ET = 0 called with IN held (the plain update path): 67 million steps of
/// IEC-STRUCT-01 and the invariants, for `TIME` (ms clock) and for `LTIME` (ns clock). Every
/// wrap of `now - START` on the 8-bit clock occurs, at every START; the generic code is the
/// same as on the full-width clocks.
#[test]
fn exhaustive_u8_update_every_start_now_pt() {
    update_every_start_now_pt_u8::<Time>();
    update_every_start_now_pt_u8::<LTime>();
}

/// The body of [`exhaustive_u8_update_every_start_now_pt`] for the data type `D`.
fn update_every_start_now_pt_u8<D: IecDuration>() {
    let kinds = IecKind::ALL;
    let checked: u64 = thread::scope(|scope| {
        let workers: Vec<_> = kinds
            .chunks(2)
            .map(|pair| {
                scope.spawn(move || {
                    let mut n = 0u64;
                    for &kind in pair {
                        // IN as the running timer holds it: 0 for TOF (timing after the fall), 1 otherwise.
                        let input = kind != IecKind::Tof;
                        for start in 0..=255u8 {
                            for pt in 0..=255u8 {
                                let state = IecState {
                                    kind: Some(kind),
                                    input,
                                    running: true,
                                    start,
                                    pt,
                                    et: 0,
                                    q: matches!(kind, IecKind::Tp | IecKind::Tof),
                                };
                                for now in 0..=255u8 {
                                    let op = Op::Call(
                                        kind,
                                        CpuTime::from_ticks(u64::from(now)),
                                        IecInput::new(input, preset_of::<D>(5)),
                                    );
                                    n += u64::from(prop_step_equivalence(state, op));
                                    n += u64::from(prop_invariants(state, op));
                                }
                            }
                        }
                    }
                    n
                })
            })
            .collect();
        workers
            .into_iter()
            .map(|w| w.join().expect("worker finished"))
            .sum()
    });
    check_eq!(checked, 2 * 4 * 256 * 256 * 256, "every case checked");
}

fn arb_kind() -> impl Strategy<Value = IecKind> {
    prop::sample::select(IecKind::ALL.to_vec())
}

/// Valid 32-bit states, with values near the wrap and the extremes of PT.
fn arb_state_u32() -> impl Strategy<Value = IecState<u32>> {
    let word = prop_oneof![
        any::<u32>(),
        Just(0u32),
        Just(u32::MAX),
        (u32::MAX - 1000)..=u32::MAX
    ];
    let pt = prop_oneof![
        0u32..=i32::MAX as u32,
        Just(0u32),
        Just(i32::MAX as u32),
        0u32..2000
    ];
    (
        prop::option::of(arb_kind()),
        any::<[bool; 3]>(),
        word,
        pt,
        any::<u32>(),
    )
        .prop_map(|(kind, [input, running, q], start, pt, et)| IecState {
            kind,
            input,
            running,
            start: if running { start } else { 0 },
            pt,
            et: if pt == 0 { 0 } else { et % (pt + 1) },
            q,
        })
}

fn arb_op_u32() -> impl Strategy<Value = Op> {
    let now = prop_oneof![
        any::<u32>().prop_map(u64::from),
        ((u32::MAX - 1000)..=u32::MAX).prop_map(u64::from),
        (0u64..1000),
        any::<u64>(),
    ]
    .prop_map(CpuTime::from_millis);
    let pt = prop_oneof![any::<i32>(), Just(i32::MAX), Just(0), Just(-1), 0i32..2000];
    prop_oneof![
        4 => (arb_kind(), now.clone(), any::<bool>(), any::<bool>(), pt.clone())
            .prop_map(|(k, now, input, reset, pt)| Op::Call(k, now, IecInput { input, pt: Time::from_millis(pt), reset })),
        1 => now.clone().prop_map(Op::ReadQ),
        1 => now.prop_map(Op::ReadEt),
        1 => Just(Op::Rt),
        1 => pt.prop_map(|pt| Op::PtCoil(Time::from_millis(pt))),
        1 => any::<bool>().prop_map(Op::RunStopRun),
    ]
}

#[cfg(not(kani))]
proptest! {
    #![proptest_config(ProptestConfig::with_cases(20_000))]

    /// IEC-STRUCT-01 and the invariants on the 32-bit clock, random states and operations
    /// weighted to the wrap and to the ends of PT.
    #[test]
    fn proptest_u32_step_equivalence_and_invariants(state in arb_state_u32(), op in arb_op_u32()) {
        // The strategy yields valid states only: both properties must apply.
        prop_assert!(prop_step_equivalence(state, op), "state not checked: {:?}", state);
        prop_assert!(prop_invariants(state, op), "state not checked: {:?}", state);
        if let Op::Call(kind, now, input) = op {
            prop_table_8_20(state, kind, now, input, Time::from_millis(7));
        }
    }

    /// IEC-EQUIV-02 on the 32-bit clock: random sequences of up to 40 operations (calls of any
    /// kind, reads, coils, RUN-STOP-RUN) from the initial structure, times near the wrap.
    #[test]
    fn proptest_u32_sequences_from_initial_state(ops in prop::collection::vec(arb_op_u32(), 1..40)) {
        prop_sequence_equivalence::<u32, Time>(&ops);
    }
}

/// IEC-BANK-01: a TON bank of `N` timers of data type `D` scanned with the IN bits `inputs[k]`
/// and presets `pts` at the times `start + steps[..=k]` (in `D`'s clock unit) equals one
/// reference TON of `D` per timer, called once per scan.
pub fn prop_ton_bank<D: IecDuration, const N: usize>(
    start: u64,
    steps: &[u64],
    inputs: &[[bool; N]],
    pts: &[D; N],
) {
    let mut bank = TonBank::<N, D>::new();
    let mut refs = [IecTimerRef::<D::Clock, D>::default(); N];
    check_eq!(
        bank.output(N),
        Err(NoSuchOperand {
            operand: Operand::Timer,
            index: N,
            count: N
        }),
        "IEC-BANK-01: timer {N} does not exist"
    );
    let mut now = CpuTime::<D::Unit>::from_ticks(start);
    for (dt, input) in steps.iter().zip(inputs) {
        now = now.add_ticks(*dt);
        bank.scan(now, input, pts);
        let mut outs = [None; N];
        for (i, r) in refs.iter_mut().enumerate() {
            let o = r.call(IecKind::Ton, now, IecInput::new(input[i], pts[i]));
            outs[i] = Some(o);
            check_eq!(bank.output(i), Ok(o), "IEC-BANK-01: timer {i} at {now:?}");
            check_eq!(
                bank.get(i),
                Ok(r.state()),
                "IEC-BANK-01: state of timer {i} at {now:?}"
            );
        }
        // The bank's bulk readers give what the reference gives, timer by timer: from two
        // opposite fills, so that a reader that skips a timer cannot pass by luck.
        let mut n = 0;
        for (i, o) in bank.outputs().enumerate() {
            check_eq!(
                Some(o),
                outs[i],
                "IEC-BANK-01: outputs() of timer {i} at {now:?}"
            );
            n += 1;
        }
        check_eq!(n, N, "IEC-BANK-01: outputs() gives every timer at {now:?}");
        for (fill_q, fill_et) in [
            (true, <D::Clock as ClockWord>::MAX),
            (false, <D::Clock as ClockWord>::ZERO),
        ] {
            let (mut q, mut et) = ([fill_q; N], [fill_et; N]);
            bank.outputs_into(&mut q, &mut et);
            for (i, want) in outs.iter().enumerate() {
                check_eq!(
                    Some((q[i], et[i])),
                    want.map(|w| (w.q, w.et)),
                    "IEC-BANK-01: outputs_into() of timer {i} at {now:?}"
                );
            }
        }
    }
}

/// IEC-STRUCT-01 (the array form): `N` structures called by `IecTimerOf::ton_array` with the
/// IN bits `inputs[k]` and presets `pts` at the times `start + steps[..=k]` equal one reference
/// TON per timer, called once per scan: each structure's state, and the outputs written for it.
pub fn prop_ton_array<const N: usize>(
    start: u64,
    steps: &[u64],
    inputs: &[[bool; N]],
    pts: &[Time; N],
) {
    let mut timers = [IecTimerOf::<u32>::new(); N];
    let mut refs = [IecTimerRef::new(); N];
    let mut now = CpuTime::from_millis(start);
    for (k, (dt, input)) in steps.iter().zip(inputs).enumerate() {
        now = now.add_millis(*dt);
        // Outputs from a fill that differs scan by scan: an output left unwritten shows.
        let (mut q, mut et) = ([k % 2 == 0; N], [k as u32; N]);
        IecTimerOf::ton_array(&mut timers, now, input, pts, &mut q, &mut et);
        for (i, r) in refs.iter_mut().enumerate() {
            let o = r.call(IecKind::Ton, now, IecInput::new(input[i], pts[i]));
            check_eq!(
                (q[i], et[i]),
                (o.q, o.et),
                "IEC-STRUCT-01: ton_array outputs of timer {i} at {now:?}"
            );
            check_eq!(
                timers[i].state(),
                r.state(),
                "IEC-STRUCT-01: ton_array state of timer {i} at {now:?}"
            );
        }
    }
}

#[cfg(not(kani))]
proptest! {
    #![proptest_config(ProptestConfig::with_cases(500))]

    /// IEC-STRUCT-01 for `ton_array` over 40 timers (two groups of 16 and a padded last group
    /// of 8): random IN patterns, presets including negative and 0, scan intervals crossing
    /// the 2^32 ms wrap.
    #[test]
    fn proptest_ton_array_equals_reference(
        start in prop_oneof![any::<u32>().prop_map(u64::from), ((u32::MAX - 500)..=u32::MAX).prop_map(u64::from)],
        steps in prop::collection::vec(prop_oneof![0u64..5, 0u64..200, any::<u32>().prop_map(u64::from)], 12),
        flips in prop::collection::vec(any::<u64>(), 12),
        pts in prop::collection::vec(prop_oneof![-5i32..5, 0i32..300, any::<i32>()], 40),
    ) {
        let pts: [Time; 40] = core::array::from_fn(|i| Time::from_millis(pts[i]));
        let inputs: Vec<[bool; 40]> = in_patterns(&flips);
        prop_ton_array(start, &steps, &inputs, &pts);
    }
}

#[cfg(not(kani))]
proptest! {
    #![proptest_config(ProptestConfig::with_cases(2_000))]

    /// IEC-BANK-01 on random IN patterns with clustered edges, presets including negative and
    /// 0, and scan intervals crossing the 2^32 ms wrap: a bank of 64.
    #[test]
    fn proptest_ton_bank_equals_reference(
        start in prop_oneof![any::<u32>().prop_map(u64::from), ((u32::MAX - 500)..=u32::MAX).prop_map(u64::from)],
        steps in prop::collection::vec(prop_oneof![0u64..5, 0u64..200, any::<u32>().prop_map(u64::from)], 16),
        flips in prop::collection::vec(any::<u64>(), 16),
        pts in prop::array::uniform32(prop_oneof![-5i32..5, 0i32..300, any::<i32>()]),
        pts2 in prop::array::uniform32(0i32..300),
    ) {
        let mut all = [Time::ZERO; 64];
        for (i, p) in all.iter_mut().enumerate() {
            *p = Time::from_millis(if i % 2 == 0 { pts[i / 2] } else { pts2[i / 2] });
        }
        let inputs: Vec<[bool; 64]> = in_patterns(&flips);
        prop_ton_bank(start, &steps, &inputs, &all);
    }

    /// IEC-BANK-01 for `LTIME` (the S7-1500 long timers on the 64-bit nanosecond clock): a bank
    /// of 64 with the IN patterns above, presets including negative, 0, small, past TIME's
    /// range (`LT#30D` and beyond) and any LTIME, scan intervals of a few ns to past 2^32 ns
    /// and any 64-bit step, starts anywhere on the clock (the CPU time saturates at its top).
    #[test]
    fn proptest_ltimer_ton_bank_equals_reference(
        start in prop_oneof![any::<u64>(), (u64::MAX - 500)..=u64::MAX, 0u64..1_000],
        steps in prop::collection::vec(prop_oneof![0u64..5, 0u64..200, (1u64 << 32)..(1u64 << 33), any::<u64>()], 16),
        flips in prop::collection::vec(any::<u64>(), 16),
        pts in prop::array::uniform32(prop_oneof![-5i64..5, 0i64..300, (1i64 << 31)..(1i64 << 52), any::<i64>()]),
        pts2 in prop::array::uniform32(0i64..300),
    ) {
        let all: [LTime; 64] = core::array::from_fn(|i| {
            LTime::from_nanos(if i % 2 == 0 { pts[i / 2] } else { pts2[i / 2] })
        });
        let inputs: Vec<[bool; 64]> = in_patterns(&flips);
        prop_ton_bank(start, &steps, &inputs, &all);
    }
}

/// The IN bits of `N` timers scan by scan, one scan per word of `flips`: each scan flips the
/// bits `f & f.rotate_left(17)` of the previous one, so that edges cluster and many timers
/// keep their IN for several scans.
fn in_patterns<const N: usize>(flips: &[u64]) -> Vec<[bool; N]> {
    let mut input = 0u64;
    flips
        .iter()
        .map(|f| {
            input ^= f & f.rotate_left(17);
            core::array::from_fn(|i| input >> i & 1 != 0)
        })
        .collect()
}

// ---------------------------------------------------------------------------------------------
// One property per requirement: the rule's text as a predicate over one operation (state
// before, operation, state after, outputs), with the update in closed form and the clock's
// modular arithmetic computed independently in u64; checked on the reference, the 16-byte
// structure and, for TON calls on the data type's own clock, the TON bank.
// ---------------------------------------------------------------------------------------------

use crate::cover::{cover, covers};

/// The implementations an operation runs through.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum IecImpl {
    /// `IecTimerRef`.
    Reference,
    /// `IecTimerOf` (the 16-byte structure).
    Structure,
    /// `TonBank` (TON calls on the data type's own clock only: 32 bits for TIME, 64 for LTIME).
    Bank,
    /// `IecTimerOf::ton_for_arrays` (TON calls only), the array form of the structure's call.
    TonForArrays,
    /// `IecTimerOf::ton_array` on an array of one (TON calls only): the group code of the
    /// array loop, on a padded copy of 16.
    TonArray,
}

/// `op` from `state` through `imp`: the state after and the outputs (Q, ET), or `None` when the
/// implementation has no such operation.
pub fn iec_run<C: ClockWord, D: IecDuration>(
    imp: IecImpl,
    state: IecState<C>,
    op: Op<D>,
) -> Option<(IecState<C>, (bool, C))> {
    match imp {
        IecImpl::Reference => {
            let mut t = IecTimerRef::<C, D>::from_state(state).expect("valid");
            let out = apply(&mut t, op);
            Some((t.state(), out))
        }
        IecImpl::Structure => {
            let mut t = IecTimerOf::<C, D>::from_state(state).expect("valid");
            let out = apply(&mut t, op);
            Some((t.state(), out))
        }
        IecImpl::Bank => bank_run(state, op),
        IecImpl::TonForArrays => {
            let Op::Call(IecKind::Ton, now, input) = op else {
                return None;
            };
            let mut t = IecTimerOf::<C, D>::from_state(state).expect("valid");
            let out = t.ton_for_arrays(now, input);
            Some((t.state(), (out.q, out.et)))
        }
        IecImpl::TonArray => {
            let Op::Call(IecKind::Ton, now, input) = op else {
                return None;
            };
            let mut t = [IecTimerOf::<C, D>::from_state(state).expect("valid")];
            let (mut q, mut et) = ([!state.q], [C::ZERO]);
            IecTimerOf::ton_array(&mut t, now, &[input.input], &[input.pt], &mut q, &mut et);
            Some((t[0].state(), (q[0], et[0])))
        }
    }
}

/// A TON call on a one-timer bank of `D` holding `state`: on `D`'s own clock only (the 32-bit
/// one for `TIME`, the 64-bit one for `LTIME`), as the bank has no narrow clocks.
fn bank_run<C: ClockWord, D: IecDuration>(
    state: IecState<C>,
    op: Op<D>,
) -> Option<(IecState<C>, (bool, C))> {
    let Op::Call(IecKind::Ton, now, input) = op else {
        return None;
    };
    // The bank holds TON states as a scan leaves them: running only with IN = 1 and Q = 0.
    if C::BITS != <D::Clock as ClockWord>::BITS
        || !matches!(state.kind, Some(IecKind::Ton))
        || !iec_reachable(&state)
    {
        return None;
    }
    // Same width: the values carry over unchanged.
    let w = |c: C| <D::Clock as ClockWord>::from_u64_wrapping(c.to_u64());
    let c = |v: D::Clock| C::from_u64_wrapping(v.to_u64());
    let mut bank = TonBank::<1, D>::new();
    let in_bank = IecState {
        kind: state.kind,
        input: state.input,
        running: state.running,
        start: w(state.start),
        pt: w(state.pt),
        et: w(state.et),
        q: state.q,
    };
    check_eq!(
        bank.set_state(0, in_bank),
        Ok(true),
        "IEC-BANK-01: the bank takes every valid TON state"
    );
    bank.scan(now, &[input.input], &[input.pt]);
    let after = bank.get(0).expect("timer 0");
    let out = bank.output(0).expect("timer 0");
    check_eq!(
        (out.q, out.et),
        (after.q, after.et),
        "IEC-BANK-01: outputs are the members"
    );
    Some((
        IecState {
            kind: after.kind,
            input: after.input,
            running: after.running,
            start: c(after.start),
            pt: c(after.pt),
            et: c(after.et),
            q: after.q,
        },
        (out.q, c(out.et)),
    ))
}

/// The preset an instruction latches, computed here: negative taken as 0, saturated at the
/// clock's top on the narrow clocks.
fn latched<C: ClockWord, D: IecDuration>(pt: D) -> u64 {
    u64::try_from(pt.units_signed().max(0))
        .expect("non-negative")
        .min(C::MAX.to_u64())
}

/// The clock's values, 0..2^BITS, as a mask in u128 (2^64 - 1 for the 64-bit clock): a value
/// modulo 2^BITS is the value and the mask (no division, which Kani handles badly).
fn clock_mask<C: ClockWord>() -> u128 {
    (1u128 << C::BITS) - 1
}

/// `now - start` modulo 2^BITS on the CPU's clock (in its unit), computed in u128.
fn elapsed<C: ClockWord, U: TimeUnit>(now: CpuTime<U>, start: C) -> u64 {
    let m = clock_mask::<C>();
    u64::try_from((u128::from(now.ticks()) + (m + 1) - u128::from(start.to_u64())) & m)
        .expect("below 2^BITS")
}

fn q_while(kind: IecKind) -> bool {
    matches!(kind, IecKind::Tp | IecKind::Tof)
}

/// The update in closed form (IEC-START-01's `elapsed = now - START`, IEC-EXPIRY-01).
fn updated<C: ClockWord, U: TimeUnit>(
    st: IecState<C>,
    now: CpuTime<U>,
    kind: IecKind,
) -> IecState<C> {
    if !st.running {
        return st;
    }
    let e = elapsed(now, st.start);
    if e >= st.pt.to_u64() {
        IecState {
            running: false,
            start: C::ZERO,
            et: st.pt,
            q: !q_while(kind),
            ..st
        }
    } else {
        IecState {
            et: C::from_u64_wrapping(e),
            q: q_while(kind),
            ..st
        }
    }
}

/// The states a running timer is in after a call of its kind (the per-kind rules are stated
/// from these): Q is the kind's status while timing, and the stored IN keeps TON and TONR
/// running (1) and TOF timing (0).
fn iec_reachable<C: ClockWord>(st: &IecState<C>) -> bool {
    !st.running
        || st.kind.is_some_and(|k| {
            st.q == q_while(k)
                && match k {
                    IecKind::Ton | IecKind::Tonr => st.input,
                    IecKind::Tof => !st.input,
                    IecKind::Tp => true,
                }
        })
}

/// The covers of the rules of one kind, chosen by type: a harness of one kind calls its kind's
/// only, since Kani counts every cover in the code a harness can call, and a cover that needs
/// another kind would be unreachable there (a runtime test of the kind would still leave it in
/// the code). The covers of the rules of every kind stay in [`call_rules`].
pub trait KindCovers {
    /// TP-RETRIGGER-01's premise: a rising IN in the call where a TP pulse runs out.
    fn tp_retrigger(_premise: bool) {}
    /// TONR-RESUME-01's premise: a TONR resumes with time accumulated.
    fn tonr_resume(_premise: bool) {}
}

/// TP's covers.
pub struct TpCovers;
/// TON's covers (its rules have none of their own).
pub struct TonCovers;
/// TOF's covers (its rules have none of their own).
pub struct TofCovers;
/// TONR's covers.
pub struct TonrCovers;
/// The covers of every kind, for a driver whose domain holds every kind.
pub struct AllKindCovers;

impl KindCovers for TpCovers {
    fn tp_retrigger(premise: bool) {
        cover_tp_retrigger(premise);
    }
}
impl KindCovers for TonCovers {}
impl KindCovers for TofCovers {}
impl KindCovers for TonrCovers {
    fn tonr_resume(premise: bool) {
        cover_tonr_resume(premise);
    }
}
impl KindCovers for AllKindCovers {
    fn tp_retrigger(premise: bool) {
        cover_tp_retrigger(premise);
    }
    fn tonr_resume(premise: bool) {
        cover_tonr_resume(premise);
    }
}

#[covers]
fn cover_tp_retrigger(premise: bool) {
    cover!(premise, "TP-RETRIGGER-01: rising IN as the pulse runs out");
}

#[covers]
fn cover_tonr_resume(premise: bool) {
    cover!(premise, "TONR-RESUME-01: resume with time accumulated");
}

/// Every IEC rule on one operation through `imp`, with the kind covers `K`. Returns whether it
/// was checked.
#[covers]
pub fn check_iec_rules<C: ClockWord, D: IecDuration, K: KindCovers>(
    imp: IecImpl,
    st: IecState<C>,
    op: Op<D>,
) -> bool {
    if !st.is_valid() {
        return false;
    }
    let Some((post, (q, et))) = iec_run(imp, st, op) else {
        return false;
    };
    if let Op::Call(..) = op {
        // The box's outputs (its return value) against the members read back from the state: two
        // code paths. The outputs of the coils and of RUN-STOP-RUN are read from the state by
        // `apply`, so nothing is compared for them.
        check_eq!(
            (q, et),
            (post.q, post.et),
            "IEC-ACCESS-01: {imp:?}: the box's Q and ET outputs are the members after the call"
        );
    }
    check!(
        post.et <= post.pt,
        "IEC-ET-RANGE-01: {imp:?}: ET <= PT: {st:?} {op:?} -> {post:?}"
    );
    check!(
        i128::from(post.pt.to_u64()) <= i128::from(D::MAX.units_signed()),
        "IEC-ET-RANGE-01: {imp:?}: PT is a non-negative {}",
        D::NAME
    );
    match op {
        Op::Call(kind, now, i) => call_rules::<C, D, K>(imp, st, kind, now, i, post),
        Op::ReadQ(now) | Op::ReadEt(now) => {
            let expected = match st.kind {
                Some(kind) => updated(st, now, kind),
                None => st,
            };
            check_eq!(
                post, expected,
                "IEC-ACCESS-01: {imp:?}: a read of Q or ELAPSED updates first, nothing else: {st:?} {op:?}"
            );
            // The value read is the updated member, from the closed form (not from the state
            // the implementation leaves).
            let read = if let Op::ReadQ(_) = op {
                (q, expected.et)
            } else {
                (expected.q, et)
            };
            check_eq!(
                read,
                (expected.q, expected.et),
                "IEC-ACCESS-01: {imp:?}: the read returns the updated member: {st:?} {op:?}"
            );
            cover!(
                st.running && !post.running,
                "IEC-ACCESS-01: a read finds the time run out"
            );
        }
        Op::Rt => check_eq!(
            post,
            IecState {
                input: false,
                running: false,
                start: C::ZERO,
                et: C::ZERO,
                q: false,
                ..st
            },
            "IEC-RT-01: {imp:?}: RT zeroes ET, Q, running and the stored IN; PT stays"
        ),
        Op::PtCoil(pt) => {
            let p = latched::<C, D>(pt);
            check_eq!(
                post.pt.to_u64(),
                p,
                "IEC-PT-COIL-01: {imp:?}: the PT coil loads the preset"
            );
            check_eq!(
                post.et.to_u64(),
                st.et.to_u64().min(p),
                "IEC-PT-COIL-01: {imp:?}: ET is clamped to it"
            );
            check_eq!(
                (post.kind, post.input, post.running, post.start, post.q),
                (st.kind, st.input, st.running, st.start, st.q),
                "IEC-PT-COIL-01: {imp:?}: no update; a running timer uses it from its next update"
            );
            cover!(
                st.running && p > st.et.to_u64(),
                "IEC-PT-COIL-01: PT loaded into a running timer"
            );
        }
        Op::RunStopRun(retentive) => {
            let expected = if retentive { st } else { IecState::default() };
            check_eq!(
                post,
                expected,
                "IEC-RETAIN-01: {imp:?}: RUN-STOP-RUN keeps a retentive structure, clears another"
            );
        }
    }
    true
}

#[covers]
fn call_rules<C: ClockWord, D: IecDuration, K: KindCovers>(
    imp: IecImpl,
    st: IecState<C>,
    kind: IecKind,
    now: CpuTime<D::Unit>,
    i: IecInput<D>,
    post: IecState<C>,
) {
    // The clock's value at `now`, computed here (not with the crate's `ClockWord`): the CPU's
    // count (ms or ns) modulo 2^BITS.
    let now_clock = u64::try_from(u128::from(now.ticks()) & clock_mask::<C>()).expect("a clock");
    let e = elapsed(now, st.start);
    let p = latched::<C, D>(i.pt);
    let same_kind = st.kind == Some(kind);
    let running = st.running && same_kind;
    let expired_now = running && e >= st.pt.to_u64();
    let rising = i.input && !st.input;
    let falling = !i.input && st.input;
    // The starting edges of the manual (IEC-START-01): TON's rising IN, TOF's falling IN, TP's
    // rising IN with no pulse running (after the call's update).
    let start_edge = match kind {
        IecKind::Ton => rising,
        IecKind::Tof => falling,
        IecKind::Tp => rising && (!st.running || expired_now || !same_kind),
        IecKind::Tonr => false,
    };
    // TONR has no starting edge: it starts (resumes) whenever IN = 1 and R = 0 on a stopped
    // timer that has not run out (TONR-RESUME-01); with PT = 0 that call runs out (IEC-PT0-01).
    let tonr_resume = kind == IecKind::Tonr && i.input && !i.reset && !st.running && !st.q;
    if start_edge && (kind != IecKind::Tp || same_kind || !st.running) {
        check_eq!(
            post.pt.to_u64(),
            p,
            "IEC-PT-LATCH-01: {imp:?}: the start latches PT"
        );
        if p > 0 {
            check!(
                post.running && post.start.to_u64() == now_clock && post.et == C::ZERO,
                "IEC-START-01: {imp:?}: the starting edge copies the clock into START: {st:?} {kind:?} {now:?} {i:?} -> {post:?}"
            );
            check_eq!(
                post.q,
                q_while(kind),
                "IEC-START-01: {imp:?}: Q while timing"
            );
        } else {
            check!(
                !post.running && post.et == C::ZERO && post.q == (kind == IecKind::Ton),
                "IEC-PT0-01: {imp:?}: PT = 0: the starting call updates (TON on, no TP pulse, TOF off): {st:?} {kind:?} {i:?} -> {post:?}"
            );
        }
        if i.pt.units_signed() < 0 {
            check_eq!(
                post.pt,
                C::ZERO,
                "IEC-ET-RANGE-01: {imp:?}: a negative PT is taken as 0"
            );
        }
    }
    cover!(
        (start_edge || tonr_resume) && p == 0,
        "IEC-PT0-01: a start with PT = 0"
    );
    // IEC-EDGE-01: a stopped timer starts only on its starting edge (TONR: IN = 1, R = 0).
    if !st.running && post.running {
        let edge = match kind {
            IecKind::Tp | IecKind::Ton => rising,
            IecKind::Tof => falling,
            IecKind::Tonr => i.input && !i.reset,
        };
        check!(
            edge,
            "IEC-EDGE-01: {imp:?}: {kind:?} started without its starting edge: {st:?} {i:?}"
        );
    }
    let reachable = iec_reachable(&st);
    // The kind covers, evaluated on every call (not in the kind's branch below), so that a
    // harness given another kind's covers fails under `cargo test` as its Kani job would.
    K::tp_retrigger(kind == IecKind::Tp && reachable && expired_now && rising);
    K::tonr_resume(
        kind == IecKind::Tonr
            && reachable
            && !i.reset
            && i.input
            && !st.running
            && !st.q
            && st.et > C::ZERO,
    );
    if !reachable {
        return;
    }
    // A running timer that the call keeps timing: the update (IEC-EXPIRY-01, IEC-WRAP-01).
    let continues = running
        && match kind {
            IecKind::Ton => i.input && st.input,
            IecKind::Tof => !i.input && !st.input,
            IecKind::Tp => !rising,
            IecKind::Tonr => i.input && !i.reset,
        };
    if continues {
        if e >= st.pt.to_u64() {
            let et = if kind == IecKind::Tp && !i.input {
                C::ZERO
            } else {
                st.pt
            };
            check!(
                !post.running && post.et == et && post.q != q_while(kind),
                "IEC-EXPIRY-01: {imp:?}: at ET >= PT the time has run out (ET = PT; TON/TONR Q = 1, TP/TOF Q = 0): {st:?} {kind:?} {now:?} -> {post:?}"
            );
        } else {
            check!(
                post.running && post.et.to_u64() == e && post.q == q_while(kind),
                "IEC-WRAP-01: {imp:?}: ET = now - START modulo 2^{}: {st:?} {now:?} -> {post:?}",
                C::BITS
            );
        }
        // PT at the box is ignored while running (IEC-PT-LATCH-01).
        check_eq!(
            post.pt,
            st.pt,
            "IEC-PT-LATCH-01: {imp:?}: PT latched while running"
        );
    }
    cover!(
        continues && e + 1 == st.pt.to_u64(),
        "IEC-EXPIRY-01: one clock unit (ms or ns) before PT"
    );
    cover!(
        continues && e == st.pt.to_u64(),
        "IEC-EXPIRY-01: exactly at PT"
    );
    cover!(
        continues && st.start.to_u64() > now_clock,
        "IEC-WRAP-01: the clock wrapped since START"
    );
    match kind {
        IecKind::Tp => {
            if running && !expired_now {
                check!(
                    post.running && post.start == st.start && post.pt == st.pt && post.q,
                    "TP-IN-01: {imp:?}: IN changes have no effect while the pulse runs"
                );
            }
            if !post.running && same_kind && !start_edge {
                let et = if !i.input {
                    C::ZERO
                } else if expired_now {
                    st.pt
                } else {
                    st.et
                };
                check_eq!(
                    post.et, et,
                    "TP-IN-01: {imp:?}: after the pulse ET stays at PT while IN = 1, 0 when IN = 0: {st:?} {i:?} -> {post:?}"
                );
            }
            if expired_now && rising {
                check_eq!(
                    post.pt.to_u64(),
                    p,
                    "TP-RETRIGGER-01: {imp:?}: a new pulse latches PT"
                );
                if p > 0 {
                    check!(
                        post.running && post.start.to_u64() == now_clock && post.q,
                        "TP-RETRIGGER-01: {imp:?}: a rising IN in the call where the pulse runs out starts a new one: {st:?} {now:?} -> {post:?}"
                    );
                }
            }
        }
        IecKind::Ton => {
            if !i.input {
                check!(
                    !post.running && !post.q && post.et == C::ZERO,
                    "TON-IN-01: {imp:?}: IN = 0 resets and stops: {st:?} -> {post:?}"
                );
            }
        }
        IecKind::Tof => {
            if i.input {
                check!(
                    !post.running && post.q && post.et == C::ZERO,
                    "TOF-IN-01: {imp:?}: IN = 1: Q = 1, reset and stopped: {st:?} -> {post:?}"
                );
            } else if !st.running && !st.input && same_kind {
                check_eq!(
                    (post.et, post.q),
                    (st.et, st.q),
                    "TOF-IN-01: {imp:?}: after the delay ET holds until IN returns to 1"
                );
            }
        }
        IecKind::Tonr => {
            if i.reset {
                check!(
                    !post.running && !post.q && post.et == C::ZERO && post.start == C::ZERO,
                    "TONR-R-01: {imp:?}: R resets ET and Q and stops, before anything else: {st:?} {i:?} -> {post:?}"
                );
                return;
            }
            if st.q && same_kind {
                check!(
                    post.q,
                    "TONR-IN-01: {imp:?}: Q stays 1 after expiry until R"
                );
            }
            if !i.input && running && !expired_now {
                check!(
                    !post.running && post.et.to_u64() == e && !post.q,
                    "TONR-IN-01: {imp:?}: IN = 0 stops without reset; ET keeps the accumulated time: {st:?} {now:?} -> {post:?}"
                );
            }
            if i.input && !st.running && !st.q {
                check_eq!(
                    post.pt.to_u64(),
                    p,
                    "TONR-RESUME-01: {imp:?}: resumes with the PT of that moment"
                );
                if st.et.to_u64() < p {
                    check!(
                        post.running
                            && post.et == st.et
                            && elapsed(now, post.start) == st.et.to_u64(),
                        "TONR-RESUME-01: {imp:?}: resumes from the accumulated ET (START shifted back): {st:?} {now:?} {i:?} -> {post:?}"
                    );
                } else {
                    check!(
                        !post.running && post.q && post.et == post.pt,
                        "TONR-RESUME-01: {imp:?}: an accumulated ET at or above the new PT has run out"
                    );
                }
                if p == 0 {
                    check!(
                        !post.running && post.q && post.et == C::ZERO,
                        "IEC-PT0-01: {imp:?}: PT = 0: TONR's resume runs out in that call (Q = 1, ET = 0): {st:?} {i:?} -> {post:?}"
                    );
                }
            }
        }
    }
    if !continues && st.running && same_kind {
        // IEC-PT-LATCH-01 as a metamorphic relation: the same call with another PT gives the
        // same result while the timer runs (unless this call starts it anew).
        let pt = i128::from(i.pt.units_signed());
        let other = IecInput {
            pt: D::from_units(pt + 3).unwrap_or(preset_of(pt - 3)),
            ..i
        };
        if !start_edge {
            let (alt, _) = iec_run(imp, st, Op::Call(kind, now, other)).expect("same impl");
            check_eq!(
                alt,
                post,
                "IEC-PT-LATCH-01: {imp:?}: PT ignored while running"
            );
        }
    }
}

/// Every IEC rule through every implementation (the harness body), and each implementation's
/// step equal to the reference's (IEC-STRUCT-01 for the structure and its array forms
/// `ton_for_arrays` and `ton_array`, IEC-BANK-01 for the bank's TON, against `IecTimerRef`).
/// `K`: the kind covers of the caller's domain ([`KindCovers`]).
pub fn prop_iec_rules<C: ClockWord, D: IecDuration, K: KindCovers>(
    st: IecState<C>,
    op: Op<D>,
) -> bool {
    let mut checked = false;
    let reference = st
        .is_valid()
        .then(|| iec_run(IecImpl::Reference, st, op))
        .flatten();
    for imp in [
        IecImpl::Reference,
        IecImpl::Structure,
        IecImpl::Bank,
        IecImpl::TonForArrays,
        IecImpl::TonArray,
    ] {
        checked |= check_iec_rules::<C, D, K>(imp, st, op);
        if let (Some(r), Some(x)) = (
            reference,
            st.is_valid().then(|| iec_run(imp, st, op)).flatten(),
        ) {
            let id = if imp == IecImpl::Bank {
                "IEC-BANK-01"
            } else {
                "IEC-STRUCT-01"
            };
            check_eq!(x, r, "{id}: {imp:?} equals the reference: {st:?} {op:?}");
        }
    }
    checked
}

/// IEC-STRUCT-01: the structure is 16 bytes, `#[repr(C)]` with START, PT, ET at offsets 0, 4,
/// 8 and the flags at 12; its bytes round-trip through `to_bytes`/`from_bytes`, which accepts
/// exactly the valid states.
pub fn prop_struct(state: IecState<u32>) {
    check_eq!(
        core::mem::size_of::<plc_timers::iec::IecTimer>(),
        16,
        "IEC-STRUCT-01: 16 bytes"
    );
    let Some(t) = plc_timers::iec::IecTimer::from_state(state) else {
        check!(
            !state.is_valid(),
            "IEC-STRUCT-01: every valid state has a structure"
        );
        return;
    };
    let bytes = t.to_bytes();
    check_eq!(
        bytes[0..4],
        state.start.to_ne_bytes(),
        "IEC-STRUCT-01: START at offset 0"
    );
    check_eq!(
        bytes[4..8],
        state.pt.to_ne_bytes(),
        "IEC-STRUCT-01: PT at offset 4"
    );
    check_eq!(
        bytes[8..12],
        state.et.to_ne_bytes(),
        "IEC-STRUCT-01: ET at offset 8"
    );
    check_eq!(bytes[13..], [0; 3], "IEC-STRUCT-01: padding zero");
    check_eq!(
        plc_timers::iec::IecTimer::from_bytes(bytes),
        Some(t),
        "IEC-STRUCT-01: the bytes restore the structure"
    );
    check_eq!(
        t.state(),
        state,
        "IEC-STRUCT-01: the abstraction inverts from_state"
    );
}

/// The rule driver on the 4-bit clock: every valid state with PT in {0, 1, 2, 5, 14, 15} (every
/// START, ET <= PT, kind, IN, running, Q) x every operation of [`all_ops_u4`]. Small scope:
/// the rules compare `now - START` modulo 16 with PT and 0, which every (START, now) pair of
/// the 4-bit clock covers in every wrap case; for `TIME` (ms clock) and `LTIME` (ns clock).
/// Kani (`kani_iec_*_rules` and `kani_ltimer_*_rules`, one per kind and data type) runs the
/// same body on the full-width clocks.
// Uses the cover recorder, which exists outside Kani only (proofs/cover.rs).
#[cfg(not(kani))]
#[test]
fn exhaustive_u4_iec_rules() {
    // Each data type's run reaches every rule and cover of its own.
    for hits in [iec_rules_u4::<Time>(), iec_rules_u4::<LTime>()] {
        crate::cover::require_checked(
            &[
                "IEC-START-01",
                "IEC-EDGE-01",
                "IEC-PT-LATCH-01",
                "IEC-EXPIRY-01",
                "IEC-ET-RANGE-01",
                "IEC-PT0-01",
                "IEC-WRAP-01",
                "IEC-ACCESS-01",
                "TP-IN-01",
                "TP-RETRIGGER-01",
                "TON-IN-01",
                "TOF-IN-01",
                "TONR-IN-01",
                "TONR-RESUME-01",
                "TONR-R-01",
                "IEC-RT-01",
                "IEC-PT-COIL-01",
                "IEC-RETAIN-01",
            ],
            &hits,
        );
        crate::cover::require(hits);
    }
}

/// The body of [`exhaustive_u4_iec_rules`] for the data type `D`: what its covers and checks
/// recorded.
#[cfg(not(kani))]
fn iec_rules_u4<D: IecDuration>() -> crate::cover::Hits {
    let states: Vec<IecState<U4>> = all_states_u4()
        .into_iter()
        .filter(|s| [0, 1, 2, 5, 14, 15].contains(&s.pt.0))
        .collect();
    let ops = all_ops_u4::<D>();
    let (a, b) = states.split_at(states.len() / 2);
    let hits = thread::scope(|scope| {
        let workers: Vec<_> = [a, b]
            .into_iter()
            .map(|part| {
                let ops = &ops;
                scope.spawn(move || {
                    crate::cover::collect(|| {
                        let mut n = 0u64;
                        for &st in part {
                            for &op in ops {
                                n += u64::from(prop_iec_rules::<U4, D, AllKindCovers>(st, op));
                            }
                        }
                        n
                    })
                })
            })
            .collect();
        workers
            .into_iter()
            .map(|w| w.join().expect("worker finished"))
            .collect::<Vec<_>>()
    });
    let n: u64 = hits.iter().map(|(n, _)| n).sum();
    let hits = crate::cover::merge(hits.into_iter().map(|(_, h)| h));
    check_eq!(n, (states.len() * ops.len()) as u64, "every case checked");
    hits
}

/// The rules on the real 8-bit clock for the TON bank's 32-bit path is `kani_iec_ton_rules`; here
/// every START x now x PT of a running TON, TP, TOF and TONR on `u8` (IEC-WRAP-01 at every
/// wrap), with IN held; for `TIME` (ms clock) and `LTIME` (ns clock).
// Uses the cover recorder, which exists outside Kani only (proofs/cover.rs).
#[cfg(not(kani))]
#[test]
fn exhaustive_u8_wrap_rules() {
    // Each data type's run reaches both rules and every cover of its own.
    for run in [wrap_rules_u8::<Time> as fn(), wrap_rules_u8::<LTime>] {
        crate::cover::check_only(&["IEC-WRAP-01", "IEC-EXPIRY-01"], run);
    }
}

/// The body of [`exhaustive_u8_wrap_rules`] for the data type `D`.
#[cfg(not(kani))]
fn wrap_rules_u8<D: IecDuration>() {
    for kind in IecKind::ALL {
        let input = kind != IecKind::Tof;
        for start in (0..=255u8).step_by(3) {
            for pt in [0u8, 1, 2, 127, 128, 200, 254, 255] {
                let st = IecState {
                    kind: Some(kind),
                    input,
                    running: true,
                    start,
                    pt,
                    et: 0,
                    q: q_while(kind),
                };
                for now in 0..=511u64 {
                    let op = Op::Call(
                        kind,
                        CpuTime::from_ticks(now),
                        IecInput::new(input, preset_of::<D>(9)),
                    );
                    check!(prop_iec_rules::<u8, D, AllKindCovers>(st, op));
                }
            }
        }
    }
}

/// `op` moved to `before` clock units (ms or ns) before PT (at least 0 after START) when it is a
/// call or a read: with `before` 0 and 1, the instants at which a running timer `st` expires or
/// is about to, which random full-width times almost never reach. Harnesses run them beside
/// each random case under `cargo test` (Kani covers them with the rest).
pub fn near_expiry<C: ClockWord, D: IecDuration>(st: IecState<C>, op: Op<D>, before: u64) -> Op<D> {
    let pt = st.pt.to_u64();
    // On the 64-bit clock START + PT may pass 2^64: the CPU time wraps with the clock there.
    let at = |_| CpuTime::from_ticks(st.start.to_u64().wrapping_add(pt - before.min(pt)));
    match op {
        Op::Call(kind, now, input) => Op::Call(kind, at(now), input),
        Op::ReadQ(now) => Op::ReadQ(at(now)),
        Op::ReadEt(now) => Op::ReadEt(at(now)),
        other => other,
    }
}

/// A data type on its full-width clock, in the structure of its manual: `TIME` in `IEC_TIMER`
/// (32-bit ms clock), `LTIME` in `IEC_LTIMER` (64-bit ns clock); the generic harnesses run over
/// it.
pub trait FullWidth: IecDuration {
    /// The layout property of the structure holding `state` (IEC-STRUCT-01, LTIMER-STRUCT-01).
    fn prop_layout(state: IecState<Self::Clock>);
}

impl FullWidth for Time {
    fn prop_layout(state: IecState<u32>) {
        prop_struct(state);
    }
}

impl FullWidth for LTime {
    fn prop_layout(state: IecState<u64>) {
        ltimer_struct_01(state);
    }
}

/// `st` with PT and ET within the range of `D` (a latched preset is a non-negative `D`).
pub fn within_range<D: IecDuration>(st: IecState<D::Clock>) -> IecState<D::Clock> {
    let top = <D::Clock as ClockWord>::from_u64_wrapping(D::MAX.units());
    IecState {
        pt: st.pt.min(top),
        et: st.et.min(st.pt.min(top)),
        ..st
    }
}

/// The body of the per-kind harnesses: `st` and `op` made of `kind` (a state of another kind
/// becomes one of this kind, a call one of this kind; PT and ET within the range of `D`), every
/// IEC rule with the kind covers `K`, the structure's layout; under `cargo test` also the same
/// case at PT and one clock unit before it ([`near_expiry`]).
pub fn iec_rules_case<D: FullWidth, K: KindCovers>(
    kind: IecKind,
    st: IecState<D::Clock>,
    op: Op<D>,
) {
    let st = within_range::<D>(IecState {
        kind: st.kind.map(|_| kind),
        ..st
    });
    let op = match op {
        Op::Call(_, now, input) => Op::Call(kind, now, input),
        other => other,
    };
    prop_iec_rules::<D::Clock, D, K>(st, op);
    D::prop_layout(st);
    #[cfg(not(kani))]
    for before in [0, 1] {
        prop_iec_rules::<D::Clock, D, K>(st, near_expiry(st, op, before));
    }
}

macro_rules! iec_rules_harness {
    ($name:ident, $data:ty, $kind:expr, $covers:ty) => {
        /// Every IEC rule for one kind and data type on its full-width clock (`prop_iec_rules`:
        /// the reference, the structure, its array forms and, for TON on `TIME`, a one-timer
        /// bank; the metamorphic reruns) and the structure's layout ([`FullWidth`]). Symbolic:
        /// the state (any valid one, of this kind or none, PT and ET within the data type's
        /// range), the operation (a call of this kind at any time with any IN and PT, a read of
        /// Q or ET at any time, RT, a PT coil with any value of the data type, RUN-STOP-RUN).
        /// `#[kani::unwind(17)]`: the TON bank's scan runs its group code on a padded copy of
        /// 16 timers, and so does `ton_array` (loops of 16 iterations and the exit, the
        /// largest; on `LTIME` the bank is not called); the loop over the 5 implementations is
        /// shorter. The kind is a constant, so each harness holds one kind's branches only,
        /// and its kind's covers only ([`KindCovers`]).
        #[test]
        #[cfg_attr(kani, kani::proof, kani::unwind(17))]
        fn $name() {
            crate::cover::harness(concat!(module_path!(), "::", stringify!($name)), || {
                bolero::check!()
                    .with_type::<(IecState<<$data as IecDuration>::Clock>, Op<$data>)>()
                    .with_iterations(5_000)
                    .for_each(|&(st, op)| iec_rules_case::<$data, $covers>($kind, st, op));
            });
        }
    };
}

iec_rules_harness!(kani_iec_tp_rules, Time, IecKind::Tp, TpCovers);
iec_rules_harness!(kani_iec_ton_rules, Time, IecKind::Ton, TonCovers);
iec_rules_harness!(kani_iec_tof_rules, Time, IecKind::Tof, TofCovers);
iec_rules_harness!(kani_iec_tonr_rules, Time, IecKind::Tonr, TonrCovers);
iec_rules_harness!(kani_ltimer_tp_rules, LTime, IecKind::Tp, TpCovers);
iec_rules_harness!(kani_ltimer_ton_rules, LTime, IecKind::Ton, TonCovers);
iec_rules_harness!(kani_ltimer_tof_rules, LTime, IecKind::Tof, TofCovers);
iec_rules_harness!(kani_ltimer_tonr_rules, LTime, IecKind::Tonr, TonrCovers);

/// Issue 39's case: the TON harness's body with TP's covers (as when every kind's harness held
/// every kind's covers) fails its harness with TP-RETRIGGER-01's cover, which no TON call
/// satisfies.
#[cfg(not(kani))]
#[test]
#[should_panic(
    expected = "covers never satisfied: [\n    \"TP-RETRIGGER-01: rising IN as the pulse runs out\",\n]"
)]
fn another_kinds_cover_fails_the_harness() {
    crate::cover::harness("iec::ton_with_tp_covers", || {
        bolero::check!()
            .with_type::<(IecState<u32>, Op)>()
            .with_iterations(5_000)
            .for_each(|&(st, op)| iec_rules_case::<Time, TpCovers>(IecKind::Ton, st, op));
    });
}

/// IEC-WRAP-01 over gaps on the 32-bit clock: a TON started at `t0` and updated `gap` ms later
/// shows ET = min(gap, PT) for every gap below 2^32 ms (2^31 and more included), and a gap of
/// 2^32 ms or more aliases to the gap 2^32 ms shorter.
#[covers]
pub fn prop_wrap_gap(t0: u64, gap: u64, pt: u32) {
    let pt = Time::from_millis(i32::try_from(pt >> 1).expect("31 bits"));
    let (t0, gap) = (CpuTime::from_millis(t0 >> 2), gap >> 2);
    let now = t0.add_millis(gap);
    let mut r = IecTimerRef::new();
    let mut s = plc_timers::iec::IecTimer::new();
    for t in [&mut r as &mut dyn IecTimerOps<u32>, &mut s] {
        t.call(IecKind::Ton, t0, IecInput::new(true, pt));
        let et = t.call(IecKind::Ton, now, IecInput::new(true, pt)).et;
        let seen = gap % (1 << 32);
        let pt = u64::try_from(pt.as_millis()).expect("non-negative");
        check_eq!(
            u64::from(et),
            seen.min(pt),
            "IEC-WRAP-01: a gap of {gap} ms shows ET = min(gap mod 2^32, PT)"
        );
    }
    cover!(
        (1 << 31..1 << 32).contains(&gap),
        "IEC-WRAP-01: a gap of 2^31 ms or more, exact"
    );
}

/// The bolero harness of IEC-WRAP-01 over gaps. Symbolic: the start time, the gap (once any
/// `u64` quartered, once below 2^36) and PT (31 bits). No loop but the two implementations:
/// `#[kani::unwind(3)]` (2 and the exit).
#[test]
#[cfg_attr(kani, kani::proof, kani::unwind(3))]
fn kani_wrap_gap() {
    crate::cover::harness(
        concat!(module_path!(), "::", stringify!(kani_wrap_gap)),
        || {
            bolero::check!()
                .with_type::<(u64, u64, u32)>()
                .with_iterations(20_000)
                .for_each(|&(t0, gap, pt)| {
                    prop_wrap_gap(t0, gap >> 28, pt);
                    prop_wrap_gap(t0, gap, pt);
                });
        },
    );
}

/// IEC-WRAP-01 at the boundaries: gaps 2^31 - 1, 2^31, 2^32 - 1 are exact, 2^32 and 2^32 + 5
/// alias.
// Uses the cover recorder, which exists outside Kani only (proofs/cover.rs).
#[cfg(not(kani))]
#[test]
fn wrap_gap_boundaries() {
    crate::cover::check_covers(|| {
        for gap in [
            0,
            1,
            (1 << 31) - 1,
            1 << 31,
            (1 << 32) - 1,
            1 << 32,
            (1 << 32) + 5,
        ] {
            for pt in [0, 2, u32::MAX] {
                // prop_wrap_gap takes its arguments times 4 (its generator's range).
                prop_wrap_gap(4 * 12_345, 4 * gap, pt);
            }
        }
    });
}

/// IEC-EQUIV-02 over three operations from power-up, the body of the harnesses of both data
/// types on their full-width clocks.
fn sequence_equivalence_harness<D: FullWidth>()
where
    Op<D>: bolero::TypeGenerator,
{
    bolero::check!()
        .with_type::<[Op<D>; 3]>()
        .with_iterations(20_000)
        .for_each(|ops| prop_sequence_equivalence::<D::Clock, D>(ops));
}

/// IEC-EQUIV-02 over three operations from power-up on the 32-bit clock (`TIME`). Symbolic: the
/// three operations (each any call, read, coil or RUN-STOP-RUN, with any time, IN and PT).
/// `#[kani::unwind(4)]`: the loop over the 3 operations and its exit.
#[test]
#[cfg_attr(kani, kani::proof, kani::unwind(4))]
fn kani_sequence_equivalence() {
    crate::cover::harness(
        concat!(module_path!(), "::", stringify!(kani_sequence_equivalence)),
        sequence_equivalence_harness::<Time>,
    );
}

/// IEC-EQUIV-02 over three operations from power-up on the 64-bit nanosecond clock (`LTIME`,
/// `IEC_LTIMER`). Symbolic: the three operations (each any call, read, coil or RUN-STOP-RUN,
/// with any time, IN and PT). `#[kani::unwind(4)]`: the loop over the 3 operations and its exit.
#[test]
#[cfg_attr(kani, kani::proof, kani::unwind(4))]
fn kani_ltimer_sequence_equivalence() {
    crate::cover::harness(
        concat!(
            module_path!(),
            "::",
            stringify!(kani_ltimer_sequence_equivalence)
        ),
        sequence_equivalence_harness::<LTime>,
    );
}

/// IEC-STRUCT-01 one step, the body of the harnesses of both data types on their full-width
/// clocks: the state (PT and ET within the data type's range) and the operation.
fn step_equivalence_harness<D: FullWidth>()
where
    (IecState<D::Clock>, Op<D>): bolero::TypeGenerator,
{
    bolero::check!()
        .with_type::<(IecState<D::Clock>, Op<D>)>()
        .with_iterations(20_000)
        .for_each(|&(st, op)| {
            let st = within_range::<D>(st);
            prop_step_equivalence(st, op);
            prop_invariants(st, op);
            if let Op::Call(kind, now, input) = op {
                prop_table_8_20(st, kind, now, input, preset_of::<D>(7));
            }
        });
}

/// IEC-STRUCT-01 one step on the 32-bit clock (`TIME`). Symbolic: the state (PT and ET within
/// the TIME range) and the operation. No loop.
#[test]
#[cfg_attr(kani, kani::proof)]
fn kani_step_equivalence() {
    crate::cover::harness(
        concat!(module_path!(), "::", stringify!(kani_step_equivalence)),
        || crate::cover::check_ids(&["IEC-STRUCT-01"], step_equivalence_harness::<Time>),
    );
}

/// IEC-STRUCT-01 one step on the 64-bit nanosecond clock (`LTIME`, `IEC_LTIMER`). Symbolic: the
/// state (PT and ET within the LTIME range) and the operation. No loop.
#[test]
#[cfg_attr(kani, kani::proof)]
fn kani_ltimer_step_equivalence() {
    crate::cover::harness(
        concat!(
            module_path!(),
            "::",
            stringify!(kani_ltimer_step_equivalence)
        ),
        || crate::cover::check_ids(&["IEC-STRUCT-01"], step_equivalence_harness::<LTime>),
    );
}

/// IEC-STRUCT-01 (the array form): `ton_array` on 2 structures over 3 scans against 2
/// reference TONs. Symbolic: the start time (`u32` ms), the 3 time steps (`u32` ms each), the
/// IN bits of each timer in each scan, the 2 presets (any TIME). `#[kani::unwind(17)]`: the 2
/// timers go through the group code on a padded copy of 16 (loops of 16 iterations and the
/// exit); the check's loop over 2 timers and the 3 scans are shorter.
#[test]
#[cfg_attr(kani, kani::proof, kani::unwind(17))]
fn kani_ton_array() {
    crate::cover::harness(
        concat!(module_path!(), "::", stringify!(kani_ton_array)),
        || {
            crate::cover::check_ids(&["IEC-STRUCT-01"], || {
                bolero::check!()
                    .with_type::<(u32, [u32; 3], [[bool; 2]; 3], [Time; 2])>()
                    .with_iterations(20_000)
                    .for_each(|(start, steps, inputs, pts)| {
                        let steps = steps.map(u64::from);
                        prop_ton_array::<2>(u64::from(*start), &steps, inputs, pts);
                    });
            });
        },
    );
}

/// IEC-BANK-01, the body of the bank's harnesses for both data types: a bank of 2 TONs of `D`
/// over 3 scans against 2 reference TONs; the start time and the 3 time steps are clock words
/// of `D` (in its unit), so that the scans reach across the clock's wrap.
fn ton_bank_harness<D: IecDuration>()
where
    (D::Clock, [D::Clock; 3], [[bool; 2]; 3], [D; 2]): bolero::TypeGenerator,
{
    bolero::check!()
        .with_type::<(D::Clock, [D::Clock; 3], [[bool; 2]; 3], [D; 2])>()
        .with_iterations(20_000)
        .for_each(|(start, steps, inputs, pts)| {
            let steps = steps.map(ClockWord::to_u64);
            prop_ton_bank::<D, 2>(start.to_u64(), &steps, inputs, pts);
        });
}

/// IEC-BANK-01 on the 32-bit clock (`TIME`): a bank of 2 TONs over 3 scans against 2 reference
/// TONs. Symbolic: the start time (`u32` ms), the 3 time steps (`u32` ms each), the IN bits of
/// each timer in each scan, the 2 presets (any TIME). `#[kani::unwind(17)]`: the scan takes the 2
/// timers through the group code on a padded copy of 16 (loops of 16 iterations and the exit,
/// the rising edges at most 16); the check's loops over 2 timers (the readers' too: `outputs`,
/// and `outputs_into` from 2 fills) and the 3 scans are shorter.
#[test]
#[cfg_attr(kani, kani::proof, kani::unwind(17))]
fn kani_ton_bank() {
    crate::cover::harness(
        concat!(module_path!(), "::", stringify!(kani_ton_bank)),
        || crate::cover::check_ids(&["IEC-BANK-01"], ton_bank_harness::<Time>),
    );
}

/// IEC-BANK-01 on the 64-bit nanosecond clock (`LTIME`): as [`kani_ton_bank`], the start time
/// and the 3 time steps `u64` ns each, the 2 presets any LTIME. `#[kani::unwind(17)]`: as
/// there.
#[test]
#[cfg_attr(kani, kani::proof, kani::unwind(17))]
fn kani_ltimer_ton_bank() {
    crate::cover::harness(
        concat!(module_path!(), "::", stringify!(kani_ltimer_ton_bank)),
        || crate::cover::check_ids(&["IEC-BANK-01"], ton_bank_harness::<LTime>),
    );
}

// ---------------------------------------------------------------------------------------------
// The S7-1500 long timers (LTIME, IEC_LTIMER): the rules of their own. The rules they share with
// the TIME timers run on them above (the drivers and harnesses over both data types).
// ---------------------------------------------------------------------------------------------

use plc_timers::iec::{IecLTimer, IecLTimerRef};
use plc_timers::time::Nanos;

/// LTIMER-STRUCT-01: `IEC_LTIMER` is 32 bytes, `#[repr(C)]` with START, PT, ET (8 bytes of
/// nanoseconds each) at offsets 0, 8 and 16 and the flags at 24 (the same flag byte as
/// `IEC_TIMER`'s, then three zero bytes); a structure holds exactly the valid states and maps
/// back to them.
pub fn ltimer_struct_01(state: IecState<u64>) {
    check_eq!(
        core::mem::size_of::<IecLTimer>(),
        32,
        "LTIMER-STRUCT-01: 32 bytes"
    );
    check_eq!(
        core::mem::align_of::<IecLTimer>(),
        8,
        "LTIMER-STRUCT-01: aligned as its 8-byte members"
    );
    let Some(t) = IecLTimer::from_state(state) else {
        check!(
            !state.is_valid(),
            "LTIMER-STRUCT-01: every valid state has a structure"
        );
        return;
    };
    // The structure's first 28 bytes are its members (the last 4 are padding, never read): read
    // through a pointer, since the members are private and the layout is what is checked.
    // SAFETY: `t` is a live, initialized `IecLTimer` of 32 bytes whose bytes 0..28 are its
    // fields (START, PT, ET, the flag byte, three zero bytes), so every byte read is initialized;
    // `[u8; 28]` has alignment 1.
    let bytes: [u8; 28] = unsafe { core::ptr::read(core::ptr::from_ref(&t).cast::<[u8; 28]>()) };
    check_eq!(
        bytes[0..8],
        state.start.to_ne_bytes(),
        "LTIMER-STRUCT-01: START (ns) at offset 0"
    );
    check_eq!(
        bytes[8..16],
        state.pt.to_ne_bytes(),
        "LTIMER-STRUCT-01: PT (ns) at offset 8"
    );
    check_eq!(
        bytes[16..24],
        state.et.to_ne_bytes(),
        "LTIMER-STRUCT-01: ET (ns) at offset 16"
    );
    // The flags of the same state in IEC_TIMER (its members zeroed: a valid state there too).
    let flags = IecState {
        start: 0u32,
        pt: 0,
        et: 0,
        ..IecState::default()
    };
    let flags = IecState {
        kind: state.kind,
        input: state.input,
        running: state.running,
        q: state.q,
        ..flags
    };
    let flag_byte = plc_timers::iec::IecTimer::from_state(flags)
        .expect("valid")
        .to_bytes()[12];
    check_eq!(
        bytes[24],
        flag_byte,
        "LTIMER-STRUCT-01: the flags at offset 24, as in IEC_TIMER"
    );
    check_eq!(
        bytes[25..],
        [0; 3],
        "LTIMER-STRUCT-01: zero after the flags"
    );
    check_eq!(
        t.state(),
        state,
        "LTIMER-STRUCT-01: the abstraction inverts from_state"
    );
    check_eq!(
        (t.pt(), t.et()),
        (state.pt, state.et),
        "LTIMER-STRUCT-01: PT and ET read the members"
    );
}

/// The bolero harness of LTIMER-STRUCT-01. Symbolic: the state (any valid one). No loop.
#[test]
#[cfg_attr(kani, kani::proof)]
fn kani_ltimer_struct() {
    crate::cover::harness(
        concat!(module_path!(), "::", stringify!(kani_ltimer_struct)),
        || {
            crate::cover::check_ids(&["LTIMER-STRUCT-01"], || {
                bolero::check!()
                    .with_type::<IecState<u64>>()
                    .with_iterations(20_000)
                    .for_each(|&st| ltimer_struct_01(st));
            });
        },
    );
}

/// The values of the S7-1500's nanosecond clock, 0..2^64, as a mask: a value modulo 2^64 is
/// the value and the mask (no division, which Kani handles badly).
const NS_CLOCK: u128 = (1 << 64) - 1;

/// LTIMER-CLOCK-01: on the 64-bit nanosecond clock that wraps at 2^64, a TON started at `t0` ns
/// and updated `gap` ns later (the clock then reads `t0 + gap` modulo 2^64) shows ET =
/// min(gap, PT) and Q = (gap >= PT) for every gap below 2^64: a gap of 2^63 ns or more, past the
/// largest PT, has run out; on the reference and on `IEC_LTIMER`. The clock's reading and the
/// elapsed time are computed here in u128.
#[covers]
pub fn ltimer_clock_01(t0: u64, gap: u64, pt: i64) {
    let pt = LTime::from_nanos(pt);
    let now = u64::try_from((u128::from(t0) + u128::from(gap)) & NS_CLOCK).expect("mod 2^64");
    let elapsed = (u128::from(now) + (NS_CLOCK + 1) - u128::from(t0)) & NS_CLOCK;
    let pt_ns = u128::try_from(pt.as_nanos().max(0)).expect("non-negative");
    let mut r = IecLTimerRef::default();
    let mut s = IecLTimer::new();
    for t in [&mut r as &mut dyn IecTimerOps<u64, LTime>, &mut s] {
        let start = CpuTime::<Nanos>::from_nanos(t0);
        t.call(IecKind::Ton, start, IecInput::new(true, pt));
        let o = t.call(
            IecKind::Ton,
            CpuTime::from_nanos(now),
            IecInput::new(true, pt),
        );
        check_eq!(
            (o.q, u128::from(o.et)),
            (elapsed >= pt_ns, elapsed.min(pt_ns)),
            "LTIMER-CLOCK-01: a gap of {gap} ns from {t0} ns shows ET = min(gap mod 2^64, PT)"
        );
        if gap >= 1 << 63 {
            check!(
                o.q && u128::from(o.et) == pt_ns,
                "LTIMER-CLOCK-01: a gap of 2^63 ns or more has run out (ET = PT, Q = 1)"
            );
        }
    }
    cover!(gap >= 1 << 63, "LTIMER-CLOCK-01: a gap of 2^63 ns or more");
    cover!(
        now < t0,
        "LTIMER-CLOCK-01: the clock wrapped at 2^64 since START"
    );
    cover!(
        u128::from(gap) < pt_ns,
        "LTIMER-CLOCK-01: still timing after the gap"
    );
}

/// The bolero harness of LTIMER-CLOCK-01. Symbolic: the start time, the gap (once any `u64`,
/// once below 2^40 ns) and PT (any LTIME). No loop but the two implementations:
/// `#[kani::unwind(3)]` (2 and the exit).
#[test]
#[cfg_attr(kani, kani::proof, kani::unwind(3))]
fn kani_ltimer_clock() {
    crate::cover::harness(
        concat!(module_path!(), "::", stringify!(kani_ltimer_clock)),
        || {
            bolero::check!()
                .with_type::<(u64, u64, i64)>()
                .with_iterations(20_000)
                .for_each(|&(t0, gap, pt)| {
                    ltimer_clock_01(t0, gap >> 24, pt);
                    ltimer_clock_01(t0, gap, pt);
                });
        },
    );
}

/// LTIMER-CLOCK-01 at the boundaries: gaps 2^63 - 1, 2^63, 2^64 - 1 against PT 0, 1, the
/// largest LTIME, and starts that make the clock wrap.
// Uses the cover recorder, which exists outside Kani only (proofs/cover.rs).
#[cfg(not(kani))]
#[test]
fn ltimer_clock_boundaries() {
    crate::cover::check_ids(&["LTIMER-CLOCK-01"], || {
        for t0 in [0, 12_345, u64::MAX - 1, u64::MAX] {
            for gap in [0, 1, (1 << 63) - 1, 1 << 63, u64::MAX - 1, u64::MAX] {
                for pt in [-1, 0, 1, i64::MAX - 1, i64::MAX] {
                    ltimer_clock_01(t0, gap, pt);
                }
            }
        }
    });
}

/// Nanoseconds per millisecond: the scale between the TIME and the LTIME timers.
const NS_PER_MS: u64 = 1_000_000;

/// A TIME operation as the same operation in nanoseconds on LTIME: its time and PT x 10^6.
fn in_nanos(op: Op<Time>) -> Op<LTime> {
    let t = |now: CpuTime| CpuTime::<Nanos>::from_nanos(now.as_millis() * NS_PER_MS);
    let pt = |pt: Time| LTime::from_nanos(i64::from(pt.as_millis()) * NS_PER_MS as i64);
    match op {
        Op::Call(kind, now, i) => Op::Call(
            kind,
            t(now),
            IecInput {
                input: i.input,
                pt: pt(i.pt),
                reset: i.reset,
            },
        ),
        Op::ReadQ(now) => Op::ReadQ(t(now)),
        Op::ReadEt(now) => Op::ReadEt(t(now)),
        Op::Rt => Op::Rt,
        Op::PtCoil(p) => Op::PtCoil(pt(p)),
        Op::RunStopRun(retentive) => Op::RunStopRun(retentive),
    }
}

/// A TIME timer's state with its clock values in nanoseconds.
fn state_in_nanos(s: IecState<u32>) -> IecState<u64> {
    let ns = |ms: u32| u64::from(ms) * NS_PER_MS;
    IecState {
        kind: s.kind,
        input: s.input,
        running: s.running,
        start: ns(s.start),
        pt: ns(s.pt),
        et: ns(s.et),
        q: s.q,
    }
}

/// `op` at a time not before `clock` and below 2^32 ms (where the TIME timer's 32-bit clock
/// does not wrap, so that both data types represent every time and duration of the trace);
/// `clock` becomes that time.
fn forward(op: Op<Time>, clock: &mut u64) -> Op<Time> {
    let mut at = |now: CpuTime| {
        *clock = (now.as_millis() & 0xFFFF_FFFF).max(*clock);
        CpuTime::from_millis(*clock)
    };
    match op {
        Op::Call(kind, now, i) => Op::Call(kind, at(now), i),
        Op::ReadQ(now) => Op::ReadQ(at(now)),
        Op::ReadEt(now) => Op::ReadEt(at(now)),
        other => other,
    }
}

/// LTIMER-SAME-01: TP, TON, TOF and TONR on LTIME follow the TIME rules. From power-up, the
/// trace `ops` (box calls, reads, coils, RUN-STOP-RUN; its times made non-decreasing and below
/// 2^32 ms by [`forward`], where both data types represent them) run on the TIME reference in
/// ms and, scaled to ns, on the LTIME reference and on `IEC_LTIMER`: at every step Q is the
/// same and ET and every clock member in ns is the TIME timer's in ms x 10^6. The TIME timer is
/// the oracle, independent of the LTIME code path through its data type and unit.
#[covers]
pub fn ltimer_same_01(ops: &[Op<Time>]) {
    let mut time = IecTimerRef::new();
    let mut reference = IecLTimerRef::default();
    let mut structure = IecLTimer::new();
    let mut clock = 0;
    for (k, &op) in ops.iter().enumerate() {
        let op = forward(op, &mut clock);
        let before = time.state();
        let (q, et) = apply(&mut time, op);
        let want = ((q, u64::from(et) * NS_PER_MS), state_in_nanos(time.state()));
        let ns = in_nanos(op);
        let by_ref = apply(&mut reference, ns);
        let by_struct = apply(&mut structure, ns);
        check_eq!(
            (by_ref, reference.state()),
            want,
            "LTIMER-SAME-01: the LTIME reference in ns = the TIME timer in ms x 10^6 at step {k} of {ops:?}"
        );
        check_eq!(
            (by_struct, structure.state()),
            want,
            "LTIMER-SAME-01: IEC_LTIMER in ns = the TIME timer in ms x 10^6 at step {k} of {ops:?}"
        );
        let after = time.state();
        cover!(
            before.running && !after.running && after.pt > 0 && after.et == after.pt,
            "LTIMER-SAME-01: a timer runs out in the trace"
        );
        cover!(
            before.running && after.running && after.et > before.et,
            "LTIMER-SAME-01: a timer keeps timing across a step"
        );
    }
}

/// LTIMER-SAME-01, bounded exhaustive: every trace of 3 operations from the 168-operation
/// alphabet of [`sequence_ops_u4`] (times 0, 2, 7, 14 ms, PT -1, 0, 5, 15 ms, reads, coils,
/// RUN-STOP-RUN: 168^3 traces, every shorter one a prefix), on the full-width timers (32-bit ms
/// clock for TIME, 64-bit ns clock for LTIME). Small scope: the rules compare elapsed times
/// with PT and 0 and copy the clock into START, which these times and presets order in every
/// way (below, at, past PT; PT 0 and negative); the times and presets of the full range are the
/// harness's (`kani_ltimer_same`).
// Uses the cover recorder, which exists outside Kani only (proofs/cover.rs).
#[cfg(not(kani))]
#[test]
fn exhaustive_ltimer_same() {
    let alphabet = sequence_ops_u4::<Time>();
    let n = crate::cover::check_ids(&["LTIMER-SAME-01"], || {
        let mut n = 0u64;
        for &a in &alphabet {
            for &b in &alphabet {
                for &c in &alphabet {
                    ltimer_same_01(&[a, b, c]);
                    n += 1;
                }
            }
        }
        n
    });
    check_eq!(n, 168 * 168 * 168, "every trace checked");
}

/// The bolero harness of LTIMER-SAME-01: 4 operations from power-up, any times (made
/// non-decreasing below 2^32 ms), IN, R, PT (any TIME). `#[kani::unwind(5)]`: the loop over the
/// 4 operations and its exit.
#[test]
#[cfg_attr(kani, kani::proof, kani::unwind(5))]
fn kani_ltimer_same() {
    crate::cover::harness(
        concat!(module_path!(), "::", stringify!(kani_ltimer_same)),
        || {
            bolero::check!()
                .with_type::<[Op<Time>; 4]>()
                .with_iterations(20_000)
                .for_each(|ops| ltimer_same_01(ops));
        },
    );
}

/// IEC-STRUCT-01 on the 64-bit nanosecond clock: the TON array forms keep the upper 32 bits of
/// START and ET. They once cleared them (a 32-bit mask zero-extended), which no clock of 32 bits
/// or fewer can show; `kani_ltimer_ton_rules` found it with this case.
#[test]
fn ltimer_ton_arrays_keep_upper_clock_bits() {
    let st = IecState {
        kind: None,
        input: true,
        running: true,
        start: 1u64 << 56,
        pt: 1,
        et: 1,
        q: true,
    };
    let op = Op::Call(
        IecKind::Ton,
        CpuTime::from_nanos(1 << 56),
        IecInput::new(true, LTime::ZERO).with_reset(true),
    );
    check!(prop_iec_rules::<u64, LTime, AllKindCovers>(st, op));
    // From power-up: a TON started past 2^32 ns and read 2^33 ns later.
    let pt = LTime::from_nanos(1 << 40);
    let mut reference = IecLTimerRef::default();
    let mut array = [IecLTimer::new()];
    for now in [5 << 32, 7 << 32] {
        let want = reference.call(
            IecKind::Ton,
            CpuTime::from_nanos(now),
            IecInput::new(true, pt),
        );
        let (mut q, mut et) = ([true], [0]);
        IecTimerOf::ton_array(
            &mut array,
            CpuTime::from_nanos(now),
            &[true],
            &[pt],
            &mut q,
            &mut et,
        );
        check_eq!(
            ((q[0], et[0]), array[0].state()),
            ((want.q, want.et), reference.state()),
            "IEC-STRUCT-01: ton_array on the 64-bit clock at {now} ns"
        );
    }
}

/// The box calls and coils of [`s71500_same_01`]'s driver on the 4-bit clock: every kind at
/// the times 0, 4, 9 and 15 (one clock period), IN 0 and 1, PT 0, 5 and 15, R 0 and 1 for TONR;
/// the RT coil; RUN-STOP-RUN, retentive or not. No `-(PT)-` coil: see
/// [`pt_coil_between_call_and_read_is_visible`].
fn s71500_ops<D: IecDuration>() -> Vec<Op<D>> {
    let mut ops = vec![Op::Rt, Op::RunStopRun(false), Op::RunStopRun(true)];
    for kind in IecKind::ALL {
        for t in [0, 4, 9, 15] {
            for on in [false, true] {
                for pt in [0, 5, 15] {
                    let resets: &[bool] = if kind == IecKind::Tonr {
                        &[false, true]
                    } else {
                        &[false]
                    };
                    for &r in resets {
                        let pt = D::from_units(pt).expect("a small preset");
                        let input = IecInput::new(on, pt).with_reset(r);
                        ops.push(Op::Call(kind, CpuTime::from_ticks(t), input));
                    }
                }
            }
        }
    }
    ops
}

/// The time of an operation, if it has one.
fn time_of<D: IecDuration>(op: Op<D>) -> Option<u64> {
    match op {
        Op::Call(_, now, _) | Op::ReadQ(now) | Op::ReadEt(now) => Some(now.ticks()),
        _ => None,
    }
}

/// S71500-SAME-01: reads through the structure are invisible. From power-up, the operations
/// `ops` (box calls of one instruction and coils, times non-decreasing within one clock
/// period) give the same
/// output at every box call whether or not the read `read` is inserted before `ops[at]` (at a
/// time between its neighbours'): the S7-1500's deferred update (done at the next read) and the
/// update at every call give the same outputs. The oracle is the run without the read, on the
/// same implementation; both the reference and the structure are checked.
#[covers]
pub fn s71500_same_01<D: IecDuration>(ops: &[Op<D>], read: Op<D>, at: usize) {
    fn run<D: IecDuration, T: IecTimerOps<U4, D> + Default>(ops: &[Op<D>], read: Op<D>, at: usize) {
        let (mut plain, mut with_read) = (T::default(), T::default());
        for (k, &op) in ops.iter().enumerate() {
            if k == at {
                let before = with_read.state();
                apply(&mut with_read, read);
                cover!(
                    before.running && with_read.state() != before,
                    "S71500-SAME-01: the inserted read updates a running timer"
                );
                cover!(
                    before.running && !with_read.state().running,
                    "S71500-SAME-01: the inserted read finds the time run out"
                );
            }
            let a = apply(&mut plain, op);
            let b = apply(&mut with_read, op);
            if let Op::Call(..) = op {
                check_eq!(
                    b,
                    a,
                    "S71500-SAME-01: a read before step {at} changes the output of step {k} of {ops:?} (read {read:?})"
                );
            }
        }
    }
    run::<D, IecTimerRef<U4, D>>(ops, read, at);
    run::<D, IecTimerOf<U4, D>>(ops, read, at);
}

/// S71500-SAME-01, exhaustive on the 4-bit clock: every sequence of 3 operations of
/// [`s71500_ops`] whose times are non-decreasing and whose box calls are of one instruction, with a read of Q or of ET inserted before
/// each of its operations at every time of 0, 4, 9, 15 between its neighbours', for TIME and
/// LTIME. Small scope: the update compares `now - START` with PT and 0, which these times and
/// presets order in every way (below, at and past PT, PT = 0) within one period of the clock;
/// the rule is stated for gaps below the period (a gap of a whole period aliases, IEC-WRAP-01).
#[test]
fn exhaustive_s71500_same_01() {
    fn all<D: IecDuration>() -> u64 {
        let ops = s71500_ops::<D>();
        let mut n = 0;
        for &a in &ops {
            for &b in &ops {
                for &c in &ops {
                    let seq = [a, b, c];
                    let times: Vec<u64> = seq.iter().filter_map(|&o| time_of(o)).collect();
                    let kinds: Vec<IecKind> = seq
                        .iter()
                        .filter_map(|&o| match o {
                            Op::Call(kind, ..) => Some(kind),
                            _ => None,
                        })
                        .collect();
                    // One instruction per structure (see `shared_structure_makes_a_read_visible`).
                    if times.windows(2).any(|w| w[0] > w[1])
                        || kinds.windows(2).any(|w| w[0] != w[1])
                    {
                        continue;
                    }
                    for at in 0..seq.len() {
                        let lo = seq[..at]
                            .iter()
                            .rev()
                            .find_map(|&o| time_of(o))
                            .unwrap_or(0);
                        let hi = seq[at..].iter().find_map(|&o| time_of(o)).unwrap_or(15);
                        for t in [0, 4, 9, 15].into_iter().filter(|t| (lo..=hi).contains(t)) {
                            let now = CpuTime::from_ticks(t);
                            for read in [Op::ReadQ(now), Op::ReadEt(now)] {
                                s71500_same_01::<D>(&seq, read, at);
                                n += 1;
                            }
                        }
                    }
                }
            }
        }
        n
    }
    let n = crate::cover::check_ids(&["S71500-SAME-01"], || all::<Time>() + all::<LTime>());
    check!(n > 1_000_000, "S71500-SAME-01: {n} sequences checked");
}

/// Where S71500-SAME-01 stops: a `-(PT)-` coil between a box call and a read. TON started at
/// 0 with PT = 5 and called again at 7 runs out in that call (ET = 5, Q = 1); a PT coil then
/// loads 15, and a call at 10 keeps the run-out timer. Had the call at 7 not updated (the
/// S7-1500 skipping the update of outputs nobody reads), the update at 10 would compare 10
/// with 15: not run out. The model updates at every call (spec/decisions.md, R22).
#[test]
fn pt_coil_between_call_and_read_is_visible() {
    let at = CpuTime::from_millis;
    let on = |pt| IecInput::new(true, Time::from_millis(pt));
    let mut eager = IecTimerRef::<u32>::new();
    eager.call(IecKind::Ton, at(0), on(5));
    eager.call(IecKind::Ton, at(7), on(5));
    eager.preset_timer(Time::from_millis(15));
    let eager_out = eager.call(IecKind::Ton, at(10), on(15));
    let mut deferred = IecTimerRef::<u32>::new();
    deferred.call(IecKind::Ton, at(0), on(5));
    deferred.preset_timer(Time::from_millis(15));
    let deferred_out = deferred.call(IecKind::Ton, at(10), on(15));
    check_eq!(
        (eager_out.q, eager_out.et),
        (true, 5),
        "S71500-SAME-01: run out at 7"
    );
    check_eq!(
        (deferred_out.q, deferred_out.et),
        (false, 10),
        "S71500-SAME-01: PT 15 at 10"
    );
}

/// Where S71500-SAME-01 stops, too: a structure shared by two instructions (IEC-SHARE-01). A TP
/// pulse of 5 started at 0 is still running when TON is called on the same structure at 9: the
/// call's update runs as TON, whose Q is 1 once the time has run out. A read of Q at 9 before
/// that call updates as the instruction that last ran, TP, whose Q is 0 after the pulse; the
/// stopped timer then stays at Q = 0 under TON's call with IN still 1.
#[test]
fn shared_structure_makes_a_read_visible() {
    let at = CpuTime::from_millis;
    let on = |pt| IecInput::new(true, Time::from_millis(pt));
    let mut without = IecTimerRef::<u32>::new();
    without.call(IecKind::Tp, at(0), on(5));
    let a = without.call(IecKind::Ton, at(9), on(0));
    let mut with = IecTimerRef::<u32>::new();
    with.call(IecKind::Tp, at(0), on(5));
    check!(
        !with.read_q(at(9)),
        "S71500-SAME-01: TP's pulse is over at 9"
    );
    let b = with.call(IecKind::Ton, at(9), on(0));
    check_eq!(
        (a.q, b.q),
        (true, false),
        "S71500-SAME-01: the read decides under sharing"
    );
}
