//! Properties of the IEC timers: the 16-byte structure simulates the reference for every
//! operation (box call, update-on-access reads, RT and PT coils, RUN-STOP-RUN), the invariants
//! hold, no start without the starting edge, no panic.
//!
//! Small scope: both implementations are generic over the clock width. The exhaustive driver
//! runs them on a 4-bit clock ([`U4`]), where every state and every operation can be
//! enumerated; the code under test is the same generic code as on the 32-bit clock, and every
//! ordering of START, now, ET and PT, and every wrap of `now - START`, occurs at 4 bits. The
//! proptest driver and the Kani harnesses cover the 32-bit clock.

use std::thread;

use plc_timers::iec::{IecInput, IecKind, IecState, IecTimerOf, IecTimerOps, IecTimerRef, TonBank};
use plc_timers::time::clock::ClockWord;
use plc_timers::time::{CpuTime, Time};
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
    fn from_preset(millis: u32) -> Self {
        U4(millis.min(15) as u8)
    }
}

/// One operation on a timer structure.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
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

/// IEC-EQUIV-01: for every valid state and operation, the structure's result and its state
/// mapped through the abstraction function equal the reference's.
pub fn prop_step_equivalence<C: ClockWord>(state: IecState<C>, op: Op) -> bool {
    let Some(mut opt) = IecTimerOf::from_state(state) else {
        return false;
    };
    assert_eq!(
        opt.state(),
        state,
        "IEC-EQUIV-01: abstraction inverts from_state"
    );
    let mut r = IecTimerRef::from_state(state).expect("valid");
    let ro = apply(&mut r, op);
    let oo = apply(&mut opt, op);
    assert_eq!(oo, ro, "IEC-EQUIV-01 outputs {state:?} {op:?}");
    assert_eq!(
        opt.state(),
        r.state(),
        "IEC-EQUIV-01 state {state:?} {op:?}"
    );
    // Equal states are equal bytes: the structure is exactly the encoding of the reference
    // state (no stray flag bits, no stale START), and its accessors read the same members.
    assert_eq!(
        IecTimerOf::from_state(r.state()),
        Some(opt),
        "IEC-EQUIV-01 canonical bytes {state:?} {op:?}"
    );
    assert_eq!((opt.pt(), opt.et()), (r.state().pt, r.state().et));
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
    assert_eq!(oo, ro, "IEC-EQUIV-02 outputs at step {step} of {ops:?}");
    assert_eq!(
        opt.state(),
        r.state(),
        "IEC-EQUIV-02 state at step {step} of {ops:?}"
    );
    assert!(
        opt.state().is_valid() && r.state().is_valid(),
        "IEC-ET-RANGE-01 at step {step} of {ops:?}"
    );
    assert_eq!(
        IecTimerOf::from_state(r.state()),
        Some(*opt),
        "IEC-EQUIV-02 canonical bytes at step {step} of {ops:?}"
    );
}

/// IEC-EQUIV-02: from the initial structure, every sequence of operations gives the same
/// outputs and (through the abstraction function) the same states in the reference and the
/// 16-byte structure, and every state on the way is valid.
pub fn prop_sequence_equivalence<C: ClockWord>(ops: &[Op]) {
    let mut r = IecTimerRef::<C>::new();
    let mut opt = IecTimerOf::<C>::new();
    assert_eq!(opt.state(), r.state(), "IEC-EQUIV-02 initial state");
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
    assert!(
        after.et <= after.pt,
        "IEC-ET-RANGE-01: {after:?} after {op:?}"
    );
    assert!(
        after.running || after.start == C::default(),
        "a stopped timer keeps no START: {after:?} after {op:?}"
    );
    assert_eq!(
        (q, et),
        (after.q, after.et),
        "outputs are the structure's members"
    );
    assert!(
        after.pt.to_u64() <= i32::MAX as u64,
        "IEC-ET-RANGE-01: PT is a non-negative TIME"
    );
    match op {
        Op::Rt => assert!(
            after.et == C::default() && !after.q && !after.running,
            "IEC-RT-01: RT clears ET and Q"
        ),
        Op::Call(kind, _, input) if !state.running && after.running => {
            let edge = match kind {
                IecKind::Tp | IecKind::Ton => input.input && !state.input,
                IecKind::Tof => !input.input && state.input,
                IecKind::Tonr => input.input && !input.reset,
            };
            assert!(
                edge,
                "IEC-EDGE-01: {kind:?} started without its starting edge"
            );
        }
        Op::ReadQ(_) | Op::ReadEt(_) | Op::PtCoil(_) | Op::RunStopRun(true) => {
            assert!(
                !after.running || state.running,
                "an access or coil never starts a timer"
            );
        }
        _ => {}
    }
    true
}

/// Seed 001 Table 8-20, all kinds: while a timer runs, a change of PT has no effect (the call
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
    assert_eq!(
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
            assert_eq!(
                (o2, a2.running, a2.start, a2.pt),
                (o, after.running, after.start, after.pt),
                "TP-IN-01"
            );
        }
        IecKind::Ton if !input.input => {
            assert!(!after.running && !o.q && o.et == C::default(), "TON-IN-01");
        }
        IecKind::Tof if input.input => {
            assert!(!after.running && o.q && o.et == C::default(), "TOF-IN-01");
        }
        IecKind::Tonr if !input.input && !input.reset => {
            let accumulated = now.clock::<C>().elapsed_since(state.start);
            assert!(
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
    assert_eq!(states.len(), 46_240);
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
    assert_eq!((n[0], n[1]), (all, all), "every case checked");
    assert!(n[2] > 0 && n[2] < all, "{} Table 8-20 cases", n[2]);
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
    assert_eq!(alphabet.len(), 168);
    let steps = sequences_from(
        &IecTimerRef::new(),
        &IecTimerOf::new(),
        &alphabet,
        &mut Vec::new(),
        3,
    );
    assert_eq!(steps, 168 + 168 * 168 + 168 * 168 * 168);
}

/// The update on the real `u8` instance of the generic code (no test-only clock): every START
/// (256) x every `now` (256) x every latched PT (256) for each of the four kinds, a running
/// timer with ET = 0 called with IN held (the plain update path): 67 million steps of
/// IEC-EQUIV-01 and the invariants. Every wrap of `now - START` on the 8-bit clock occurs, at
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
    assert_eq!(checked, 2 * 4 * 256 * 256 * 256, "every case checked");
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

    /// IEC-EQUIV-01 and the invariants on the 32-bit clock, random states and operations
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
    let mut refs = [IecTimerRef::<u32>::new(); N];
    assert_eq!(
        bank.output(N),
        None,
        "IEC-BANK-01: timer {N} does not exist"
    );
    let mut now = CpuTime::from_millis(start);
    for (dt, input) in steps.iter().zip(inputs) {
        now = now.add_millis(*dt);
        bank.scan(now, input, pts);
        for (i, r) in refs.iter_mut().enumerate() {
            let o = r.call(IecKind::Ton, now, IecInput::new(input[i], pts[i]));
            assert_eq!(bank.output(i), Some(o), "IEC-BANK-01: timer {i} at {now:?}");
            assert_eq!(
                bank.get(i),
                Some(r.state()),
                "IEC-BANK-01: state of timer {i} at {now:?}"
            );
        }
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
