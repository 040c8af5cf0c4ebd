//! Property tests for the counters over whole traces (CNT-EQUIV-01, CNT-BANK-01, SC-PRIO-01).
//!
//! `proofs/counter.rs` checks one step from every state (exhaustively at 8 bits, randomly at the
//! wide types). These tests run long input sequences from states near the type's limits and check,
//! at every call, that three implementations agree and that all of them agree with a small
//! independent model computed in `i128`:
//!
//! - IEC (INT, LINT, ULINT): the reference [`CounterRef`], the packed [`Counter`], and (for
//!   CTUD) a one-word [`CounterBank`] whose counter 0 gets the trace and the other 63 counters get
//!   the trace shifted by one call — so the bank's word operations see neighbours that differ.
//! - S5 (`S_CU`, `S_CD`, `S_CUD`): the reference [`S5CounterRef`], a lone [`S5Counter`] and a
//!   [`CounterMemory`] box call.
//!
//! The traces cluster edges: signals come as runs (held for 1..4 calls) and as bursts that
//! toggle every call, R and LD are rare enough that counting runs long; the start CV and PV are
//! drawn near MIN, 0 and MAX so that saturation is reached within a trace. A failure shrinks to a
//! short `Debug` list of steps.

use plc_timers::counter::s5::{
    CounterMemory, CounterPreset, S5Counter, S5CounterInput, S5CounterKind, S5CounterOps,
    S5CounterRef, S5CounterState, CV_MAX,
};
use plc_timers::counter::{
    BankInputs, Counter, CounterBank, CounterInput, CounterInt, CounterKind, CounterOps,
    CounterRef, CounterState,
};
use proptest::prelude::*;

/// One call's binary inputs.
#[derive(Clone, Copy, Debug)]
struct Signals {
    cu: bool,
    cd: bool,
    r: bool,
    ld: bool,
}

/// A boolean signal as a sequence of `len` calls: runs held for 1..4 calls, with bursts that
/// toggle every call (the edge-dense case), and a weight for how often the signal is 1.
fn signal(len: usize, rare: bool) -> impl Strategy<Value = Vec<bool>> {
    let run = if rare {
        prop_oneof![
            6 => (1usize..=6).prop_map(|n| vec![false; n]),
            1 => (1usize..=3).prop_map(|n| vec![true; n]),
        ]
        .boxed()
    } else {
        prop_oneof![
            3 => (1usize..=4, any::<bool>()).prop_map(|(n, v)| vec![v; n]),
            1 => (2usize..=8).prop_map(|n| (0..n).map(|i| i % 2 == 0).collect()),
        ]
        .boxed()
    };
    prop::collection::vec(run, len).prop_map(move |runs| {
        let mut v: Vec<bool> = runs.into_iter().flatten().collect();
        v.truncate(len);
        v
    })
}

/// Up to 60 calls of clustered CU/CD edges with rare R and LD levels.
fn signals() -> impl Strategy<Value = Vec<Signals>> {
    (1usize..=60).prop_flat_map(|len| {
        (
            signal(len, false),
            signal(len, false),
            signal(len, true),
            signal(len, true),
        )
            .prop_map(|(cu, cd, r, ld)| {
                let n = cu.len().min(cd.len()).min(r.len()).min(ld.len());
                (0..n)
                    .map(|i| Signals {
                        cu: cu[i],
                        cd: cd[i],
                        r: r[i],
                        ld: ld[i],
                    })
                    .collect::<Vec<_>>()
            })
    })
}

/// Values near the limits of `T` (MIN, MIN + 1..3, -1..1, MAX - 3..MAX) and, rarely, any value.
fn near_limits<T: CounterInt + Arbitrary>() -> impl Strategy<Value = T> {
    let near = |base: i128| {
        (-3i128..=3).prop_filter_map("outside the type", move |d| T::from_i128(base + d))
    };
    prop_oneof![
        3 => near(T::MIN.to_i128()),
        3 => near(0),
        3 => near(T::MAX.to_i128()),
        1 => any::<T>(),
    ]
}

/// The independent model of one call (CNT-EDGE-01, CNT-PRIO-01, CNT-SAT-01, CNT-SIMUL-01,
/// CNT-INPUTS-01) in `i128`, where `cv ± 1` cannot overflow and saturation is an explicit clamp.
fn model_call<T: CounterInt>(kind: CounterKind, s: &mut (i128, bool, bool), i: Signals, pv: T) {
    let (has_cu, has_cd, has_r, has_ld) = match kind {
        CounterKind::Ctu => (true, false, true, false),
        CounterKind::Ctd => (false, true, false, true),
        CounterKind::Ctud => (true, true, true, true),
    };
    let (cu, cd) = (i.cu && has_cu, i.cd && has_cd);
    let up = cu && !s.1;
    let down = cd && !s.2;
    s.1 = cu;
    s.2 = cd;
    s.0 = if i.r && has_r {
        0
    } else if i.ld && has_ld {
        pv.to_i128()
    } else {
        let next = s.0 + i128::from(up) - i128::from(down);
        next.clamp(T::MIN.to_i128(), T::MAX.to_i128())
    };
}

/// Runs `trace` from `start` through reference, packed, bank (CTUD) and model, comparing each call.
fn check_iec<T: CounterInt>(
    kind: CounterKind,
    start: CounterState<T>,
    pv: T,
    trace: &[Signals],
) -> Result<(), TestCaseError> {
    let mut reference = CounterRef::from_state(start);
    let mut packed = Counter::from_state(start);
    let mut model = (start.cv.to_i128(), start.cu_prev, start.cd_prev);
    // Bank: counter 0 runs the trace; counters 1..64 run it one call late (their call 0 is idle).
    let mut bank = CounterBank::<T, 64>::new();
    let mut lagging = CounterRef::<T>::new();
    let bank_from_zero = start == CounterState::default();
    let mut prev = Signals {
        cu: false,
        cd: false,
        r: false,
        ld: false,
    };
    for (n, &sig) in trace.iter().enumerate() {
        let input = CounterInput {
            cu: sig.cu,
            cd: sig.cd,
            r: sig.r,
            ld: sig.ld,
            pv,
        };
        let o_ref = reference.call(kind, input);
        let o_packed = packed.call(kind, input);
        model_call(kind, &mut model, sig, pv);
        prop_assert_eq!(o_ref, o_packed, "CNT-EQUIV-01 outputs at call {}", n);
        prop_assert_eq!(
            reference.state(),
            packed.state(),
            "CNT-EQUIV-01 state at call {}",
            n
        );
        prop_assert_eq!(o_ref.cv.to_i128(), model.0, "model CV at call {}", n);
        prop_assert_eq!(
            (reference.state().cu_prev, reference.state().cd_prev),
            (model.1, model.2),
            "CNT-EDGE-01 memories at call {}",
            n
        );
        prop_assert_eq!(o_ref.qu, o_ref.cv >= pv, "CNT-Q-01 QU at call {}", n);
        prop_assert_eq!(o_ref.qd, o_ref.cv <= T::ZERO, "CNT-Q-01 QD at call {}", n);

        if kind == CounterKind::Ctud && bank_from_zero {
            let word = |now: bool, before: bool| -> [bool; 64] {
                core::array::from_fn(|i| if i == 0 { now } else { before })
            };
            let (cu, cd, r, ld) = (
                word(sig.cu, prev.cu),
                word(sig.cd, prev.cd),
                word(sig.r, prev.r),
                word(sig.ld, prev.ld),
            );
            bank.scan(
                &BankInputs {
                    cu: &cu,
                    cd: &cd,
                    r: &r,
                    ld: &ld,
                },
                pv,
            );
            let o_lag = lagging.call(
                CounterKind::Ctud,
                CounterInput {
                    cu: prev.cu,
                    cd: prev.cd,
                    r: prev.r,
                    ld: prev.ld,
                    pv,
                },
            );
            prop_assert_eq!(
                bank.output(0, pv),
                Ok(o_ref),
                "CNT-BANK-01 counter 0 call {}",
                n
            );
            for i in 1..64 {
                prop_assert_eq!(
                    bank.get(i),
                    Ok(lagging.state()),
                    "CNT-BANK-01 counter {} call {}",
                    i,
                    n
                );
            }
            prop_assert_eq!(
                bank.output(63, pv),
                Ok(o_lag),
                "CNT-BANK-01 counter 63 call {}",
                n
            );
            prev = sig;
        }
    }
    Ok(())
}

fn kind() -> impl Strategy<Value = CounterKind> {
    prop::sample::select(CounterKind::ALL.to_vec())
}

/// A start state near the limits with any edge memories.
fn start<T: CounterInt + Arbitrary>() -> impl Strategy<Value = CounterState<T>> {
    (near_limits::<T>(), any::<bool>(), any::<bool>()).prop_map(|(cv, cu_prev, cd_prev)| {
        CounterState {
            cv,
            cu_prev,
            cd_prev,
        }
    })
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(2_000))]

    /// INT: traces from states near the limits (CNT-EQUIV-01 and the rules along the trace).
    #[test]
    fn iec_traces_int(k in kind(), s in start::<i16>(), pv in near_limits::<i16>(), t in signals()) {
        check_iec(k, s, pv, &t)?;
    }

    /// LINT: as for INT; near `i64::MIN` a wrong `- 1` would overflow (overflow checks are on).
    #[test]
    fn iec_traces_lint(k in kind(), s in start::<i64>(), pv in near_limits::<i64>(), t in signals()) {
        check_iec(k, s, pv, &t)?;
    }

    /// ULINT: as for INT; QD = CV <= 0 is CV == 0 for an unsigned counter.
    #[test]
    fn iec_traces_ulint(k in kind(), s in start::<u64>(), pv in near_limits::<u64>(), t in signals()) {
        check_iec(k, s, pv, &t)?;
    }

    /// CTUD from the initial state (bank included): CNT-EQUIV-01 and CNT-BANK-01 over traces.
    #[test]
    fn iec_traces_from_initial_state_with_bank(pv in near_limits::<i16>(), t in signals()) {
        check_iec(CounterKind::Ctud, CounterState::<i16>::default(), pv, &t)?;
        check_iec(CounterKind::Ctud, CounterState::<u64>::default(), 2u64, &t)?;
        check_iec(CounterKind::Ctud, CounterState::<i64>::default(), -1i64, &t)?;
    }
}

/// One call of an S5 counter box: the binary inputs and the preset.
#[derive(Clone, Copy, Debug)]
struct S5Step {
    cu: bool,
    cd: bool,
    s: bool,
    r: bool,
    fr: bool,
    pv: u16,
}

fn s5_steps() -> impl Strategy<Value = Vec<S5Step>> {
    let pv = prop_oneof![
        2 => Just(0u16),
        2 => 995u16..=CV_MAX,
        2 => 1u16..=4,
        1 => 0u16..=CV_MAX,
    ];
    (1usize..=60).prop_flat_map(move |len| {
        (
            signal(len, false),
            signal(len, false),
            signal(len, true),
            signal(len, true),
            signal(len, true),
            prop::collection::vec(pv.clone(), len),
        )
            .prop_map(|(cu, cd, s, r, fr, pv)| {
                let n = cu
                    .len()
                    .min(cd.len())
                    .min(s.len())
                    .min(r.len())
                    .min(fr.len());
                (0..n)
                    .map(|i| S5Step {
                        cu: cu[i],
                        cd: cd[i],
                        s: s[i],
                        r: r[i],
                        fr: fr[i],
                        pv: pv[i],
                    })
                    .collect::<Vec<_>>()
            })
    })
}

/// The independent S5 model, written from the rules: a rising FR clears the CU, CD and S
/// memories (SC-FR-01); a box without CU or CD leaves that memory alone (SC-INPUTS-01); rising
/// CU and rising CD both count, each saturating in 0..=999 (SC-SIMUL-01, SC-SAT-01); a rising S
/// loads PV and clears the CU and CD memories (SC-SET-01); R (level) clears CV last
/// (SC-PRIO-01).
fn s5_model(kind: S5CounterKind, st: &mut S5CounterState, i: S5Step) {
    if i.fr && !st.fr_prev {
        st.cu_prev = false;
        st.cd_prev = false;
        st.s_prev = false;
    }
    st.fr_prev = i.fr;
    let mut cv = i32::from(st.cv);
    if kind != S5CounterKind::SCd {
        if i.cu && !st.cu_prev {
            cv = (cv + 1).min(999);
        }
        st.cu_prev = i.cu;
    }
    if kind != S5CounterKind::SCu {
        if i.cd && !st.cd_prev {
            cv = (cv - 1).max(0);
        }
        st.cd_prev = i.cd;
    }
    if i.s && !st.s_prev {
        cv = i32::from(i.pv);
        st.cu_prev = false;
        st.cd_prev = false;
    }
    st.s_prev = i.s;
    if i.r {
        cv = 0;
    }
    st.cv = u16::try_from(cv).expect("0..=999");
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(2_000))]

    /// S5 counters from a start CV near 0 or 999: reference, packed word, memory area and model
    /// agree at every call (SC-PRIO-01, SC-RANGE-01).
    #[test]
    fn s5_counter_traces(
        k in prop::sample::select(S5CounterKind::ALL.to_vec()),
        cv in prop_oneof![0u16..=3, 996u16..=CV_MAX, 0u16..=CV_MAX],
        memories in any::<(bool, bool, bool, bool)>(),
        slot in 0usize..256,
        t in s5_steps(),
    ) {
        let start = S5CounterState {
            cv,
            cu_prev: memories.0,
            cd_prev: memories.1,
            s_prev: memories.2,
            fr_prev: memories.3,
        };
        let mut reference = S5CounterRef::from_state(start).expect("CV <= 999");
        let mut word = S5Counter::from_state(start).expect("CV <= 999");
        let mut memory = CounterMemory::<256>::new();
        prop_assert_eq!(memory.set_state(slot, start), Ok(true));
        prop_assert_eq!(memory.load(slot), Ok(cv), "area seeded with the start CV");
        let mut model = start;
        for (n, &step) in t.iter().enumerate() {
            let input = S5CounterInput {
                cu: step.cu,
                cd: step.cd,
                s: step.s,
                r: step.r,
                fr: step.fr,
                pv: CounterPreset::new(step.pv).expect("pv <= 999"),
            };
            let o_ref = reference.call(k, input);
            word.call(k, input);
            s5_model(k, &mut model, step);
            prop_assert_eq!(reference.state(), model, "model state at call {}", n);
            prop_assert_eq!(word.state(), reference.state(), "S5 word state at call {}", n);
            prop_assert_eq!(word.output(), o_ref, "S5 word outputs at call {}", n);
            prop_assert!(o_ref.cv <= CV_MAX, "SC-RANGE-01 at call {}", n);
            prop_assert_eq!(o_ref.q, o_ref.cv != 0, "Q = CV != 0 at call {}", n);
            prop_assert_eq!(
                CounterPreset::from_bcd(o_ref.cv_bcd).map(CounterPreset::value),
                Ok(o_ref.cv),
                "CV_BCD is the BCD of CV at call {}", n
            );
            let o_mem = memory.call(slot, k, input).expect("slot < 256");
            prop_assert_eq!(o_mem, o_ref, "counter area box call at call {}", n);
            prop_assert_eq!(memory.load(slot), Ok(o_ref.cv), "L C at call {}", n);
            prop_assert_eq!(memory.load_bcd(slot), Ok(o_ref.cv_bcd), "LC C at call {}", n);
            prop_assert_eq!(memory.status(slot), Ok(o_ref.q), "A C at call {}", n);
        }
    }
}
