//! Properties of the IEC timers: the 16-byte structure simulates the reference for every
//! operation (box call, update-on-access reads, RT and PT coils, RUN-STOP-RUN), the invariants
//! hold, no start without the starting edge, no panic.
//!
//! Small scope: both implementations are generic over the clock width. The exhaustive driver
//! runs them on a 4-bit clock ([`U4`]), where every state and every operation can be
//! enumerated; the code under test is the same generic code as on the 32-bit clock, and every
//! ordering of START, now, ET and PT, and every wrap of `now - START`, occurs at 4 bits. The
//! proptest driver and the Kani harnesses cover the 32-bit clock.

use crate::cover::{check, check_eq};
use std::thread;

use plc_timers::iec::{IecInput, IecKind, IecState, IecTimerOf, IecTimerOps, IecTimerRef, TonBank};
use plc_timers::time::clock::ClockWord;
use plc_timers::time::{CpuTime, Time};
use plc_timers::{NoSuchOperand, Operand};
use proptest::prelude::*;

/// A 4-bit wrapping clock, for exhaustive enumeration.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, PartialOrd, Ord, Hash)]
pub struct U4(u8);

impl ClockWord for U4 {
    const BITS: u32 = 4;
    const ZERO: Self = U4(0);
    const MAX: Self = U4(15);
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

/// One operation on a timer structure.
#[derive(Clone, Copy, Debug, PartialEq, Eq, bolero::TypeGenerator)]
pub enum Op {
    /// A box call.
    Call(IecKind, CpuTime, IecInput),
    /// Reading `Q` through the structure at a time.
    ReadQ(CpuTime),
    /// Reading `ELAPSED` through the structure at a time.
    ReadEt(CpuTime),
    /// The RT coil.
    Rt,
    /// The PT coil.
    PtCoil(Time),
    /// RUN-STOP-RUN (retentive or not).
    RunStopRun(bool),
}

fn apply<C: ClockWord, T: IecTimerOps<C>>(t: &mut T, op: Op) -> (bool, C) {
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
pub fn prop_step_equivalence<C: ClockWord>(state: IecState<C>, op: Op) -> bool {
    let Some(mut opt) = IecTimerOf::from_state(state) else {
        return false;
    };
    check_eq!(
        opt.state(),
        state,
        "IEC-STRUCT-01: abstraction inverts from_state"
    );
    let mut r = IecTimerRef::from_state(state).expect("valid");
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
fn sequence_step<C: ClockWord>(
    r: &mut IecTimerRef<C>,
    opt: &mut IecTimerOf<C>,
    op: Op,
    step: usize,
    ops: &[Op],
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
pub fn prop_sequence_equivalence<C: ClockWord>(ops: &[Op]) {
    let mut r = IecTimerRef::<C>::default();
    let mut opt = IecTimerOf::<C>::new();
    check_eq!(opt.state(), r.state(), "IEC-EQUIV-02 initial state");
    for (i, &op) in ops.iter().enumerate() {
        sequence_step(&mut r, &mut opt, op, i, ops);
    }
}

/// IEC-ET-RANGE-01, IEC-RT-01, IEC-EDGE-01: after any operation ET is within 0..=PT (the
/// latched, non-negative preset); after RT, ET = 0 and Q = 0 and the timer is stopped; a stopped
/// timer starts only on its starting edge (rising IN for TP and TON, falling IN for TOF; for
/// TONR, IN = 1 with R = 0, the decision TONR-RESUME-01).
pub fn prop_invariants<C: ClockWord>(state: IecState<C>, op: Op) -> bool {
    if !state.is_valid() {
        return false;
    }
    let mut r = IecTimerRef::from_state(state).expect("valid");
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
        after.pt.to_u64() <= i32::MAX as u64,
        "IEC-ET-RANGE-01: PT is a non-negative TIME"
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
pub fn prop_table_8_20<C: ClockWord>(
    state: IecState<C>,
    kind: IecKind,
    now: CpuTime,
    input: IecInput,
    other_pt: Time,
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
    let step = |input: IecInput| {
        let mut r = IecTimerRef::from_state(state).expect("valid");
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

/// PT inputs: negative (taken as 0), 0, 1, the middle, one below the clock's range, its top,
/// above it, and the largest TIME.
const PTS: [i32; 8] = [-1, 0, 1, 5, 14, 15, 16, i32::MAX];

/// Every operation on the 4-bit clock: calls of each kind at every `now` with every IN (and R
/// for TONR) and PT of `PTS`; reads at every `now`; RT; PT coil with every PT; RUN-STOP-RUN.
pub fn all_ops_u4() -> Vec<Op> {
    let mut ops = Vec::new();
    for kind in IecKind::ALL {
        for now in 0..16u8 {
            for input in [false, true] {
                for reset in [false, true] {
                    if reset && kind != IecKind::Tonr {
                        continue;
                    }
                    for pt in PTS {
                        ops.push(Op::Call(
                            kind,
                            CpuTime::from_millis(u64::from(now)),
                            IecInput {
                                input,
                                pt: Time::from_millis(pt),
                                reset,
                            },
                        ));
                    }
                }
            }
        }
    }
    for now in 0..16u8 {
        ops.push(Op::ReadQ(CpuTime::from_millis(u64::from(now))));
        ops.push(Op::ReadEt(CpuTime::from_millis(u64::from(now))));
    }
    ops.push(Op::Rt);
    ops.extend(PTS.map(|pt| Op::PtCoil(Time::from_millis(pt))));
    ops.push(Op::RunStopRun(false));
    ops.push(Op::RunStopRun(true));
    ops
}

/// Exhaustive on the 4-bit clock: every valid state (46 240) x every operation (1 323):
/// 61 million steps, on two threads. See the module doc for why 4 bits is a complete small
/// scope for this generic code.
#[test]
fn exhaustive_u4_step_equivalence_and_invariants() {
    let states = all_states_u4();
    let ops = all_ops_u4();
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
                                prop_table_8_20(state, kind, now, input, Time::from_millis(3));
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
fn sequence_ops_u4() -> Vec<Op> {
    let pts = [-1, 0, 5, 15];
    all_ops_u4()
        .into_iter()
        .filter(|op| match *op {
            Op::Call(_, now, input) => {
                [0, 2, 7, 14].contains(&now.as_millis()) && pts.contains(&input.pt.as_millis())
            }
            Op::ReadQ(now) | Op::ReadEt(now) => now.as_millis() == 2 || now.as_millis() == 14,
            Op::PtCoil(pt) => pt.as_millis() == 5,
            Op::Rt | Op::RunStopRun(_) => true,
        })
        .collect()
}

/// Depth-first over every sequence of `depth` more operations from `alphabet`, checking each
/// step as [`prop_sequence_equivalence`] does; returns the number of steps checked.
fn sequences_from(
    r: &IecTimerRef<U4>,
    opt: &IecTimerOf<U4>,
    alphabet: &[Op],
    prefix: &mut Vec<Op>,
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
/// steps), from the initial structure. This complements the one-step simulation relation
/// (which covers every valid state, reachable or not) with the end-to-end view from power-up.
#[test]
fn bounded_sequences_u4_from_initial_state() {
    let alphabet = sequence_ops_u4();
    check_eq!(alphabet.len(), 168);
    let steps = sequences_from(
        &IecTimerRef::default(),
        &IecTimerOf::new(),
        &alphabet,
        &mut Vec::new(),
        3,
    );
    check_eq!(steps, 168 + 168 * 168 + 168 * 168 * 168);
}

/// The update on the real `u8` instance of the generic code (no test-only clock): every START
/// (256) x every `now` (256) x every latched PT (256) for each of the four kinds, a running
/// timer with ET = 0 called with IN held (the plain update path): 67 million steps of
/// IEC-STRUCT-01 and the invariants. Every wrap of `now - START` on the 8-bit clock occurs, at
/// every START; the generic code is the same as on the 32-bit clock.
#[test]
fn exhaustive_u8_update_every_start_now_pt() {
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
                                        CpuTime::from_millis(u64::from(now)),
                                        IecInput::new(input, Time::from_millis(5)),
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
        prop_sequence_equivalence::<u32>(&ops);
    }
}

/// IEC-BANK-01: a TON bank of `N` timers scanned with the IN bits `inputs[k]` and presets `pts`
/// at the times `start + steps[..=k]` equals one reference TON per timer, called once per scan.
pub fn prop_ton_bank<const N: usize>(
    start: u64,
    steps: &[u64],
    inputs: &[[bool; N]],
    pts: &[Time; N],
) {
    let mut bank = TonBank::<N>::new();
    let mut refs = [IecTimerRef::new(); N];
    check_eq!(
        bank.output(N),
        Err(NoSuchOperand {
            operand: Operand::Timer,
            index: N,
            count: N
        }),
        "IEC-BANK-01: timer {N} does not exist"
    );
    let mut now = CpuTime::from_millis(start);
    for (dt, input) in steps.iter().zip(inputs) {
        now = now.add_millis(*dt);
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
        for (fill_q, fill_et) in [(true, u32::MAX), (false, 0)] {
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
        let mut input = 0u64;
        let inputs: Vec<[bool; 40]> = flips
            .iter()
            .map(|f| {
                input ^= f & f.rotate_left(17);
                core::array::from_fn(|i| input >> i & 1 != 0)
            })
            .collect();
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
        let mut input = 0u64;
        let inputs: Vec<[bool; 64]> = flips
            .iter()
            .map(|f| {
                input ^= f & f.rotate_left(17);
                core::array::from_fn(|i| input >> i & 1 != 0)
            })
            .collect();
        prop_ton_bank(start, &steps, &inputs, &all);
    }
}

// ---------------------------------------------------------------------------------------------
// One property per requirement: the rule's text as a predicate over one operation (state
// before, operation, state after, outputs), with the update in closed form and the clock's
// modular arithmetic computed independently in u64; checked on the reference, the 16-byte
// structure and, for TON calls on the 32-bit clock, the TON bank.
// ---------------------------------------------------------------------------------------------

use crate::cover::{cover, covers};

/// The implementations an operation runs through.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum IecImpl {
    /// `IecTimerRef`.
    Reference,
    /// `IecTimerOf` (the 16-byte structure).
    Structure,
    /// `TonBank` (TON calls on the 32-bit clock only).
    Bank,
    /// `IecTimerOf::ton_for_arrays` (TON calls only), the array form of the structure's call.
    TonForArrays,
    /// `IecTimerOf::ton_array` on an array of one (TON calls only): the group code of the
    /// array loop, on a padded copy of 16.
    TonArray,
}

/// `op` from `state` through `imp`: the state after and the outputs (Q, ET), or `None` when the
/// implementation has no such operation.
pub fn iec_run<C: ClockWord>(
    imp: IecImpl,
    state: IecState<C>,
    op: Op,
) -> Option<(IecState<C>, (bool, C))> {
    match imp {
        IecImpl::Reference => {
            let mut t = IecTimerRef::from_state(state).expect("valid");
            let out = apply(&mut t, op);
            Some((t.state(), out))
        }
        IecImpl::Structure => {
            let mut t = IecTimerOf::from_state(state).expect("valid");
            let out = apply(&mut t, op);
            Some((t.state(), out))
        }
        IecImpl::Bank => bank_run(state, op),
        IecImpl::TonForArrays => {
            let Op::Call(IecKind::Ton, now, input) = op else {
                return None;
            };
            let mut t = IecTimerOf::from_state(state).expect("valid");
            let out = t.ton_for_arrays(now, input);
            Some((t.state(), (out.q, out.et)))
        }
        IecImpl::TonArray => {
            let Op::Call(IecKind::Ton, now, input) = op else {
                return None;
            };
            let mut t = [IecTimerOf::from_state(state).expect("valid")];
            let (mut q, mut et) = ([!state.q], [C::ZERO]);
            IecTimerOf::ton_array(&mut t, now, &[input.input], &[input.pt], &mut q, &mut et);
            Some((t[0].state(), (q[0], et[0])))
        }
    }
}

/// A TON call on a one-timer bank holding `state` (32-bit clock only).
fn bank_run<C: ClockWord>(state: IecState<C>, op: Op) -> Option<(IecState<C>, (bool, C))> {
    let Op::Call(IecKind::Ton, now, input) = op else {
        return None;
    };
    // The bank holds TON states as a scan leaves them: running only with IN = 1 and Q = 0.
    if C::BITS != 32 || !matches!(state.kind, Some(IecKind::Ton)) || !iec_reachable(&state) {
        return None;
    }
    let w = |c: C| u32::try_from(c.to_u64()).expect("32 bits");
    let c = |v: u32| C::from_u64_wrapping(u64::from(v));
    let mut bank = TonBank::<1>::new();
    let s32 = IecState {
        kind: state.kind,
        input: state.input,
        running: state.running,
        start: w(state.start),
        pt: w(state.pt),
        et: w(state.et),
        q: state.q,
    };
    check_eq!(
        bank.set_state(0, s32),
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
fn latched<C: ClockWord>(pt: Time) -> u64 {
    u64::try_from(pt.as_millis().max(0))
        .expect("non-negative")
        .min(C::MAX.to_u64())
}

/// `now - start` modulo 2^BITS on the CPU's millisecond clock, computed in u64.
fn elapsed<C: ClockWord>(now: CpuTime, start: C) -> u64 {
    let m = 1u64 << C::BITS;
    (now.as_millis() % m + m - start.to_u64()) % m
}

fn q_while(kind: IecKind) -> bool {
    matches!(kind, IecKind::Tp | IecKind::Tof)
}

/// The update in closed form (IEC-START-01's `elapsed = now - START`, IEC-EXPIRY-01).
fn updated<C: ClockWord>(st: IecState<C>, now: CpuTime, kind: IecKind) -> IecState<C> {
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
pub fn check_iec_rules<C: ClockWord, K: KindCovers>(imp: IecImpl, st: IecState<C>, op: Op) -> bool {
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
        post.pt.to_u64() <= i32::MAX as u64,
        "IEC-ET-RANGE-01: {imp:?}: PT is a non-negative TIME"
    );
    match op {
        Op::Call(kind, now, i) => call_rules::<C, K>(imp, st, kind, now, i, post),
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
            let p = latched::<C>(pt);
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
fn call_rules<C: ClockWord, K: KindCovers>(
    imp: IecImpl,
    st: IecState<C>,
    kind: IecKind,
    now: CpuTime,
    i: IecInput,
    post: IecState<C>,
) {
    // The clock's value at `now`, computed here (not with the crate's `ClockWord`): the CPU's
    // millisecond count modulo 2^BITS.
    let now_clock = now.as_millis() & ((1u64 << C::BITS) - 1);
    let e = elapsed(now, st.start);
    let p = latched::<C>(i.pt);
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
        if i.pt.as_millis() < 0 {
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
        "IEC-EXPIRY-01: one ms before PT"
    );
    cover!(
        continues && e == st.pt.to_u64(),
        "IEC-EXPIRY-01: exactly at PT"
    );
    cover!(
        continues && st.start.to_u64() > now.as_millis() % (1u64 << C::BITS),
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
        let other = IecInput {
            pt: Time::from_millis(i.pt.as_millis().wrapping_add(3)),
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
pub fn prop_iec_rules<C: ClockWord, K: KindCovers>(st: IecState<C>, op: Op) -> bool {
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
        checked |= check_iec_rules::<C, K>(imp, st, op);
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
/// the 4-bit clock covers in every wrap case; Kani (`kani_iec_*_rules`, one per kind) runs the same body on
/// the 32-bit clock.
// Uses the cover recorder, which exists outside Kani only (proofs/cover.rs).
#[cfg(not(kani))]
#[test]
fn exhaustive_u4_iec_rules() {
    let states: Vec<IecState<U4>> = all_states_u4()
        .into_iter()
        .filter(|s| [0, 1, 2, 5, 14, 15].contains(&s.pt.0))
        .collect();
    let ops = all_ops_u4();
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
                                n += u64::from(prop_iec_rules::<U4, AllKindCovers>(st, op));
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
    check_eq!(n, (states.len() * ops.len()) as u64, "every case checked");
}

/// The rules on the real 8-bit clock for the TON bank's 32-bit path is `kani_iec_ton_rules`; here
/// every START x now x PT of a running TON, TP, TOF and TONR on `u8` (IEC-WRAP-01 at every
/// wrap), with IN held.
// Uses the cover recorder, which exists outside Kani only (proofs/cover.rs).
#[cfg(not(kani))]
#[test]
fn exhaustive_u8_wrap_rules() {
    crate::cover::check_only(&["IEC-WRAP-01", "IEC-EXPIRY-01"], || {
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
                            CpuTime::from_millis(now),
                            IecInput::new(input, Time::from_millis(9)),
                        );
                        check!(prop_iec_rules::<u8, AllKindCovers>(st, op));
                    }
                }
            }
        }
    });
}

/// `op` moved to `before` ms before PT (at least 0 ms after START) when it is a call or a read:
/// with `before` 0 and 1, the instants at which a running timer `st` expires or is about to,
/// which random 32-bit times almost never reach. Harnesses run them beside each random case
/// under `cargo test` (Kani covers them with the rest).
pub fn near_expiry(st: IecState<u32>, op: Op, before: u64) -> Op {
    let at = |_: CpuTime| {
        CpuTime::from_millis(u64::from(st.start) + u64::from(st.pt) - before.min(u64::from(st.pt)))
    };
    match op {
        Op::Call(kind, now, input) => Op::Call(kind, at(now), input),
        Op::ReadQ(now) => Op::ReadQ(at(now)),
        Op::ReadEt(now) => Op::ReadEt(at(now)),
        other => other,
    }
}

/// The body of the per-kind harnesses: `st` and `op` made of `kind` (a state of another kind
/// becomes one of this kind, a call one of this kind; PT and ET within the TIME range), every
/// IEC rule with the kind covers `K`, the structure's layout; under `cargo test` also the same
/// case at PT and one ms before it ([`near_expiry`]).
pub fn iec_rules_case<K: KindCovers>(kind: IecKind, st: IecState<u32>, op: Op) {
    let st = IecState {
        kind: st.kind.map(|_| kind),
        pt: st.pt.min(i32::MAX as u32),
        et: st.et.min(st.pt.min(i32::MAX as u32)),
        ..st
    };
    let op = match op {
        Op::Call(_, now, input) => Op::Call(kind, now, input),
        other => other,
    };
    prop_iec_rules::<u32, K>(st, op);
    prop_struct(st);
    #[cfg(not(kani))]
    for before in [0, 1] {
        prop_iec_rules::<u32, K>(st, near_expiry(st, op, before));
    }
}

macro_rules! iec_rules_harness {
    ($name:ident, $kind:expr, $covers:ty) => {
        /// Every IEC rule for one kind on the 32-bit clock (`prop_iec_rules`: the reference, the
        /// structure, its array forms and, for TON, a one-timer bank; the metamorphic reruns)
        /// and the structure's layout. Symbolic: the state (any valid one, of this kind or none,
        /// PT and ET within the TIME range), the operation (a call of this kind at any time with
        /// any IN and PT, a read of Q or ET at any time, RT, a PT coil with any TIME,
        /// RUN-STOP-RUN). `#[kani::unwind(17)]`: the TON bank's scan runs its group code on a
        /// padded copy of 16 timers, and so does `ton_array` (loops of 16 iterations and the exit, the
        /// largest); the loop over the 5 implementations is shorter. The kind is a constant, so each harness
        /// holds one kind's branches only, and its kind's covers only ([`KindCovers`]).
        #[test]
        #[cfg_attr(kani, kani::proof, kani::unwind(17))]
        fn $name() {
            crate::cover::harness(concat!(module_path!(), "::", stringify!($name)), || {
                bolero::check!()
                    .with_type::<(IecState<u32>, Op)>()
                    .with_iterations(5_000)
                    .for_each(|&(st, op)| iec_rules_case::<$covers>($kind, st, op));
            });
        }
    };
}

iec_rules_harness!(kani_iec_tp_rules, IecKind::Tp, TpCovers);
iec_rules_harness!(kani_iec_ton_rules, IecKind::Ton, TonCovers);
iec_rules_harness!(kani_iec_tof_rules, IecKind::Tof, TofCovers);
iec_rules_harness!(kani_iec_tonr_rules, IecKind::Tonr, TonrCovers);

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
            .for_each(|&(st, op)| iec_rules_case::<TpCovers>(IecKind::Ton, st, op));
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

/// IEC-EQUIV-02 over three operations from power-up on the 32-bit clock. Symbolic: the three
/// operations (each any call, read, coil or RUN-STOP-RUN, with any time, IN and PT).
/// `#[kani::unwind(4)]`: the loop over the 3 operations and its exit.
#[test]
#[cfg_attr(kani, kani::proof, kani::unwind(4))]
fn kani_sequence_equivalence() {
    crate::cover::harness(
        concat!(module_path!(), "::", stringify!(kani_sequence_equivalence)),
        || {
            bolero::check!()
                .with_type::<[Op; 3]>()
                .with_iterations(20_000)
                .for_each(|ops| prop_sequence_equivalence::<u32>(ops));
        },
    );
}

/// IEC-STRUCT-01 one step on the 32-bit clock. Symbolic: the state (PT and ET within the TIME
/// range) and the operation. No loop.
#[test]
#[cfg_attr(kani, kani::proof)]
fn kani_step_equivalence() {
    crate::cover::harness(
        concat!(module_path!(), "::", stringify!(kani_step_equivalence)),
        || {
            crate::cover::check_ids(&["IEC-STRUCT-01"], || {
                bolero::check!()
                    .with_type::<(IecState<u32>, Op)>()
                    .with_iterations(20_000)
                    .for_each(|&(st, op)| {
                        let st = IecState {
                            pt: st.pt.min(i32::MAX as u32),
                            et: st.et.min(st.pt.min(i32::MAX as u32)),
                            ..st
                        };
                        prop_step_equivalence(st, op);
                        prop_invariants(st, op);
                        if let Op::Call(kind, now, input) = op {
                            prop_table_8_20(st, kind, now, input, Time::from_millis(7));
                        }
                    });
            });
        },
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

/// IEC-BANK-01: a bank of 2 TONs over 3 scans against 2 reference TONs. Symbolic: the start
/// time (`u32` ms), the 3 time steps (`u32` ms each), the IN bits of each timer in each scan,
/// the 2 presets (any TIME). `#[kani::unwind(17)]`: the scan takes the 2 timers through the group
/// code on a padded copy of 16 (loops of 16 iterations and the exit, the rising edges at most
/// 16); the check's loops over 2 timers (the readers' too: `outputs`, and `outputs_into` from
/// 2 fills) and the 3 scans are shorter.
#[test]
#[cfg_attr(kani, kani::proof, kani::unwind(17))]
fn kani_ton_bank() {
    crate::cover::harness(
        concat!(module_path!(), "::", stringify!(kani_ton_bank)),
        || {
            crate::cover::check_ids(&["IEC-BANK-01"], || {
                bolero::check!()
                    .with_type::<(u32, [u32; 3], [[bool; 2]; 3], [Time; 2])>()
                    .with_iterations(20_000)
                    .for_each(|(start, steps, inputs, pts)| {
                        let steps = steps.map(u64::from);
                        prop_ton_bank::<2>(u64::from(*start), &steps, inputs, pts);
                    });
            });
        },
    );
}
