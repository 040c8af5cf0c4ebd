//! Properties of the counters: the packed IEC counter and the counter bank simulate the
//! reference, the S5 counter cell simulates the S5 reference, CV stays in range, the priorities
//! and edge rules hold, no panic.
//!
//! Small scope: the IEC counters are one generic implementation over [`CounterInt`]; the
//! exhaustive drivers cover every state and input of the 8-bit types (SInt and USInt, signed and
//! unsigned, so both saturation ends and the sign of `CV <= 0`), and proptest and the Kani
//! harnesses the wide types.

use plc_timers::counter::packed::{BankInputs, CounterBank, PackedCounter};
use plc_timers::counter::reference::CounterRef;
use plc_timers::counter::s5::{
    CounterMemory, CounterPreset, S5CounterCell, S5CounterInput, S5CounterKind, S5CounterRef,
    S5CounterState, CV_MAX,
};
use plc_timers::counter::{CounterInput, CounterInt, CounterKind, CounterOps, CounterState};
use proptest::prelude::*;

/// CNT-EQUIV-01: one packed step equals one reference step, state and outputs.
pub fn prop_step_equivalence<T: CounterInt>(
    kind: CounterKind,
    state: CounterState<T>,
    input: CounterInput<T>,
) {
    let mut r = CounterRef { kind, state };
    let mut p = PackedCounter::from_state(state);
    assert_eq!(
        p.abstraction(),
        state,
        "CNT-EQUIV-01: abstraction inverts from_state"
    );
    let ro = r.call(input);
    // Through the interface, the instruction named in the call is the one that runs.
    let mut via_trait = CounterRef {
        kind: CounterKind::Ctud,
        state,
    };
    assert_eq!(
        CounterOps::call(&mut via_trait, kind, input),
        ro,
        "CNT-EQUIV-01 via CounterOps"
    );
    let po = p.call(kind, input);
    assert_eq!(po, ro, "CNT-EQUIV-01 outputs {kind:?} {state:?} {input:?}");
    // The interface's view and the accessor read the same state, in both implementations.
    assert_eq!(
        CounterOps::state(&p),
        p.abstraction(),
        "CNT-EQUIV-01 via CounterOps"
    );
    assert_eq!(
        CounterOps::state(&r),
        r.state,
        "CNT-EQUIV-01 reference via CounterOps"
    );
    assert_eq!(p.cv(), po.cv, "CNT-EQUIV-01: CV accessor");
    assert_eq!(
        p.abstraction(),
        r.state,
        "CNT-EQUIV-01 state {kind:?} {state:?} {input:?}"
    );
}

/// CNT-SAT-01, CNT-PRIO-01, CNT-EDGE-01, CNT-SIMUL-01, CNT-Q-01: CV moves by at most one and
/// never wraps; R gives 0, else LD gives PV; without a rising edge (or with both) CV does not
/// count; the outputs follow CV and PV.
pub fn prop_rules<T: CounterInt>(
    kind: CounterKind,
    state: CounterState<T>,
    input: CounterInput<T>,
) {
    let mut r = CounterRef { kind, state };
    let out = r.call(input);
    let i = input.with_signals(kind.mask(input.signals()));
    let (before, after) = (state.cv.to_i128(), r.state.cv.to_i128());
    assert_eq!(
        (out.qu, out.qd, out.cv),
        (r.state.cv >= input.pv, r.state.cv <= T::ZERO, r.state.cv),
        "CNT-Q-01"
    );
    assert_eq!(
        (r.state.cu_prev, r.state.cd_prev),
        (i.cu, i.cd),
        "CNT-EDGE-01: edge memories take the inputs"
    );
    if i.r {
        assert_eq!(r.state.cv, T::ZERO, "CNT-PRIO-01: R resets");
        return;
    }
    if i.ld {
        assert_eq!(r.state.cv, input.pv, "CNT-PRIO-01: LD loads PV");
        return;
    }
    let up = i.cu && !state.cu_prev;
    let down = i.cd && !state.cd_prev;
    let expected = match (up, down) {
        (true, false) => (before + 1).min(T::MAX.to_i128()),
        (false, true) => (before - 1).max(T::MIN.to_i128()),
        _ => before,
    };
    assert_eq!(
        after, expected,
        "CNT-SAT-01 / CNT-SIMUL-01 / CNT-EDGE-01 {kind:?} {state:?} {input:?}"
    );
}

fn all_states<T: CounterInt>(
    values: impl Iterator<Item = T> + Clone,
) -> impl Iterator<Item = CounterState<T>> {
    values.flat_map(|cv| {
        (0..4u8).map(move |e| CounterState {
            cv,
            cu_prev: e & 1 != 0,
            cd_prev: e & 2 != 0,
        })
    })
}

fn exhaustive_8bit<T: CounterInt>(values: impl Iterator<Item = T> + Clone) -> u64 {
    let mut n = 0;
    for kind in CounterKind::ALL {
        for state in all_states(values.clone()) {
            for pv in values.clone() {
                for bits in 0..16u8 {
                    let input = CounterInput {
                        cu: bits & 1 != 0,
                        cd: bits & 2 != 0,
                        r: bits & 4 != 0,
                        ld: bits & 8 != 0,
                        pv,
                    };
                    prop_step_equivalence(kind, state, input);
                    prop_rules(kind, state, input);
                    n += 1;
                }
            }
        }
    }
    n
}

/// Exhaustive for SInt: 3 kinds x 256 CV x 4 edge memories x 256 PV x 16 inputs (12.6 million).
#[test]
fn exhaustive_sint() {
    assert_eq!(exhaustive_8bit(i8::MIN..=i8::MAX), 3 * 256 * 4 * 256 * 16);
}

/// Exhaustive for USInt: the same domain, unsigned (QD is CV = 0; saturation at 0 and 255).
#[test]
fn exhaustive_usint() {
    assert_eq!(exhaustive_8bit(u8::MIN..=u8::MAX), 3 * 256 * 4 * 256 * 16);
}

fn arb_wide<T: CounterInt + Arbitrary>() -> impl Strategy<Value = T> {
    let near = |v: T, up: bool| {
        (0i128..4).prop_map(move |d| {
            T::from_i128(if up { v.to_i128() + d } else { v.to_i128() - d }).unwrap_or(v)
        })
    };
    prop_oneof![
        any::<T>(),
        near(T::MIN, true),
        near(T::MAX, false),
        near(T::ZERO, true),
        near(T::ZERO, false)
    ]
}

fn check_wide<T: CounterInt + Arbitrary>(
) -> impl Strategy<Value = (CounterKind, CounterState<T>, CounterInput<T>)> {
    (
        prop::sample::select(CounterKind::ALL.to_vec()),
        arb_wide::<T>(),
        any::<[bool; 6]>(),
        arb_wide::<T>(),
    )
        .prop_map(|(kind, cv, b, pv)| {
            (
                kind,
                CounterState {
                    cv,
                    cu_prev: b[0],
                    cd_prev: b[1],
                },
                CounterInput {
                    cu: b[2],
                    cd: b[3],
                    r: b[4],
                    ld: b[5],
                    pv,
                },
            )
        })
}

#[cfg(not(kani))]
proptest! {
    #![proptest_config(ProptestConfig::with_cases(10_000))]

    /// CNT-EQUIV-01 and the rules at Int, weighted to the limits.
    #[test]
    fn proptest_int((kind, state, input) in check_wide::<i16>()) {
        prop_step_equivalence(kind, state, input);
        prop_rules(kind, state, input);
    }

    /// CNT-EQUIV-01 and the rules at LInt.
    #[test]
    fn proptest_lint((kind, state, input) in check_wide::<i64>()) {
        prop_step_equivalence(kind, state, input);
        prop_rules(kind, state, input);
    }

    /// CNT-EQUIV-01 and the rules at ULInt, DInt, UDInt, UInt.
    #[test]
    fn proptest_other_widths(
        a in check_wide::<u64>(), b in check_wide::<i32>(), c in check_wide::<u32>(), d in check_wide::<u16>()
    ) {
        prop_step_equivalence(a.0, a.1, a.2);
        prop_rules(a.0, a.1, a.2);
        prop_step_equivalence(b.0, b.1, b.2);
        prop_rules(b.0, b.1, b.2);
        prop_step_equivalence(c.0, c.1, c.2);
        prop_rules(c.0, c.1, c.2);
        prop_step_equivalence(d.0, d.1, d.2);
        prop_rules(d.0, d.1, d.2);
    }

    /// CNT-BANK-01: a bank of 128 CTUD counters (two words) over 12 scans of random inputs
    /// equals 128 reference counters.
    #[test]
    fn proptest_bank_equals_reference(
        scans in prop::collection::vec(any::<[[u64; 2]; 4]>(), 12),
        pv in arb_wide::<i16>(),
    ) {
        let mut bank = CounterBank::<i16, 2>::new();
        let mut refs = vec![CounterRef::<i16>::new(CounterKind::Ctud); 128];
        // Two words of 64: counters 0..=127 exist, 128 does not.
        prop_assert_eq!(CounterBank::<i16, 2>::LEN, refs.len());
        prop_assert_eq!(bank.state(128), None);
        for [cu, cd, r, ld] in scans {
            // Thin out R and LD so that counting is exercised too.
            let r = [r[0] & cu[0] & cd[0], r[1] & cu[1] & cd[1]];
            let ld = [ld[0] & !cu[0] & cd[0], ld[1] & !cu[1] & cd[1]];
            bank.scan(BankInputs { cu: &cu, cd: &cd, r: &r, ld: &ld }, pv);
            for (i, c) in refs.iter_mut().enumerate() {
                let bit = |w: &[u64; 2]| w[i / 64] >> (i % 64) & 1 != 0;
                let o = c.call(CounterInput { cu: bit(&cu), cd: bit(&cd), r: bit(&r), ld: bit(&ld), pv });
                prop_assert_eq!(bank.state(i), Some(c.state), "CNT-BANK-01 counter {}", i);
                prop_assert_eq!(bank.output(i, pv), Some(o));
            }
        }
    }
}

/// SC-EQUIV-01: one packed S5 counter step equals one reference step.
pub fn prop_s5_step_equivalence(
    kind: S5CounterKind,
    state: S5CounterState,
    input: S5CounterInput,
) -> bool {
    let Some(cell) = S5CounterCell::from_state(state) else {
        return false;
    };
    assert_eq!(
        cell.abstraction(),
        state,
        "SC-EQUIV-01: abstraction inverts from_state"
    );
    let mut r = S5CounterRef { kind, state };
    let ro = r.call(input);
    let cell = cell.step(kind.mask(input));
    assert_eq!(
        cell.abstraction(),
        r.state,
        "SC-EQUIV-01 {kind:?} {state:?} {input:?}"
    );
    assert_eq!(cell.output(), ro, "SC-EQUIV-01 outputs");
    true
}

/// SC-RANGE-01, SC-Q-01, SC-PRIO-01: CV stays in 0..=999, CV_BCD is its BCD form, Q = CV != 0,
/// R = 1 gives 0, a rising S (without R) gives PV.
pub fn prop_s5_rules(kind: S5CounterKind, state: S5CounterState, input: S5CounterInput) -> bool {
    if !state.is_valid() {
        return false;
    }
    let mut r = S5CounterRef { kind, state };
    let out = r.call(input);
    assert!(out.cv <= CV_MAX, "SC-RANGE-01");
    assert_eq!(
        CounterPreset::from_bcd(out.cv_bcd).map(CounterPreset::value),
        Ok(out.cv),
        "SC-BCD-01"
    );
    assert_eq!(out.q, out.cv != 0, "SC-Q-01");
    if input.r {
        assert_eq!(out.cv, 0, "SC-PRIO-01: R resets");
    } else if input.s && !state.s_prev {
        assert_eq!(out.cv, input.pv.value(), "SC-PRIO-01: a rising S sets PV");
    } else {
        assert!(
            out.cv.abs_diff(state.cv) <= 1,
            "SC-SAT-01: counting moves CV by at most 1"
        );
    }
    true
}

/// Exhaustive S5 counters: 3 kinds x CV 0..=999 x 8 edge memories x 16 inputs x 5 presets
/// (1.9 million); the preset only matters on a rising S, where it is copied (checked by
/// `prop_s5_rules` for each), so five values incl. both ends suffice.
#[test]
fn exhaustive_s5_counters() {
    let mut checked = 0;
    let presets: Vec<CounterPreset> = [0, 1, 500, 998, 999]
        .into_iter()
        .filter_map(|n| CounterPreset::new(n).ok())
        .collect();
    for kind in S5CounterKind::ALL {
        for cv in 0..=CV_MAX {
            for e in 0..8u8 {
                let state = S5CounterState {
                    cv,
                    cu_prev: e & 1 != 0,
                    cd_prev: e & 2 != 0,
                    s_prev: e & 4 != 0,
                };
                for &pv in &presets {
                    for bits in 0..16u8 {
                        let input = S5CounterInput {
                            cu: bits & 1 != 0,
                            cd: bits & 2 != 0,
                            s: bits & 4 != 0,
                            r: bits & 8 != 0,
                            pv,
                        };
                        checked += u32::from(prop_s5_step_equivalence(kind, state, input));
                        checked += u32::from(prop_s5_rules(kind, state, input));
                    }
                }
            }
        }
    }
    // Every enumerated state is valid: both properties apply to every case.
    assert_eq!(checked, 2 * 3 * 1000 * 8 * presets.len() as u32 * 16);
    assert_eq!(presets.len(), 5);
}

/// One STL operation on an S5 counter: `CU`, `CD`, `S` or `R C n` with its RLO.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum StlOp {
    /// `CU C n` (`ZV`).
    Cu(bool),
    /// `CD C n` (`ZR`).
    Cd(bool),
    /// `S C n` with the preset in ACCU 1.
    S(bool),
    /// `R C n`.
    R(bool),
}

/// SC-STL-01: each STL operation evaluates only its own input. The model is the reference box
/// called once per operation with every input line at the RLO its own operation last gave it
/// (so a line that did not change shows no edge) and R at the RLO of this operation if it is
/// `R C n`, else 0 (R acts only where it is programmed). The counter memory area's operations
/// must give the same CV, BCD and status after every operation, from the initial counter.
pub fn prop_stl_operations(pv: CounterPreset, ops: &[StlOp]) {
    let mut reference = S5CounterRef::new(S5CounterKind::SCud);
    let mut area = CounterMemory::<1>::new();
    let mut lines = S5CounterInput {
        pv,
        ..S5CounterInput::default()
    };
    for (n, &op) in ops.iter().enumerate() {
        lines.r = false;
        let done = match op {
            StlOp::Cu(rlo) => {
                lines.cu = rlo;
                area.cu(0, rlo)
            }
            StlOp::Cd(rlo) => {
                lines.cd = rlo;
                area.cd(0, rlo)
            }
            StlOp::S(rlo) => {
                lines.s = rlo;
                area.set(0, rlo, pv)
            }
            StlOp::R(rlo) => {
                lines.r = rlo;
                area.reset(0, rlo)
            }
        };
        assert_eq!(done, Ok(()), "counter 0 exists");
        let expected = reference.call(lines);
        assert_eq!(
            (area.load(0), area.load_bcd(0), area.status(0)),
            (Ok(expected.cv), Ok(expected.cv_bcd), Ok(expected.q)),
            "SC-STL-01 after operation {n} of {ops:?}"
        );
    }
}

/// SC-STL-01 driver: every sequence of 5 operations over the 8 (operation, RLO) pairs (32 768
/// sequences), with the presets 0, 1 and 999: reaches counting from both sides of the edge
/// memories, set, reset, and the count after each.
#[test]
fn exhaustive_stl_operations() {
    const SYMBOLS: [StlOp; 8] = [
        StlOp::Cu(false),
        StlOp::Cu(true),
        StlOp::Cd(false),
        StlOp::Cd(true),
        StlOp::S(false),
        StlOp::S(true),
        StlOp::R(false),
        StlOp::R(true),
    ];
    let mut sequences = 0;
    for pv in [0, 1, 999] {
        let pv = CounterPreset::new(pv).expect("at most 999");
        for mut code in 0..8usize.pow(5) {
            let mut ops = [StlOp::Cu(false); 5];
            for op in ops.iter_mut() {
                *op = SYMBOLS[code % 8];
                code /= 8;
            }
            prop_stl_operations(pv, &ops);
            sequences += 1;
        }
    }
    assert_eq!(sequences, 3 * 32_768);
}

/// SC-BCD-01, exhaustive over all 65 536 words: a preset word is accepted exactly when it is
/// three BCD digits (bits 15-12 zero, each digit 0-9), and then its value is the decimal reading.
#[test]
fn exhaustive_s5_preset_words() {
    let mut accepted = 0;
    for w in 0..=u16::MAX {
        let digits = [w >> 12, (w >> 8) & 0xF, (w >> 4) & 0xF, w & 0xF];
        let valid = digits[0] == 0 && digits[1..].iter().all(|&d| d <= 9);
        match CounterPreset::from_bcd(w) {
            Ok(p) => {
                assert!(valid, "SC-BCD-01: W#16#{w:04X} accepted");
                assert_eq!(p.value(), digits[1] * 100 + digits[2] * 10 + digits[3]);
                assert_eq!(p.to_bcd(), w);
                accepted += 1;
            }
            Err(_) => assert!(!valid, "SC-BCD-01: W#16#{w:04X} rejected"),
        }
    }
    assert_eq!(accepted, 1000);
}

#[cfg(kani)]
mod kani_harnesses {
    use super::*;

    macro_rules! wide_harness {
        ($name:ident, $t:ty) => {
            /// CNT-EQUIV-01 and the counter rules for every state and input of this type.
            #[kani::proof]
            fn $name() {
                let kind: CounterKind = kani::any();
                let state: CounterState<$t> = kani::any();
                let input: CounterInput<$t> = kani::any();
                prop_step_equivalence(kind, state, input);
                prop_rules(kind, state, input);
            }
        };
    }

    wide_harness!(kani_counter_sint, i8);
    wide_harness!(kani_counter_int, i16);
    wide_harness!(kani_counter_dint, i32);
    wide_harness!(kani_counter_lint, i64);
    wide_harness!(kani_counter_usint, u8);
    wide_harness!(kani_counter_uint, u16);
    wide_harness!(kani_counter_udint, u32);
    wide_harness!(kani_counter_ulint, u64);

    /// SC-EQUIV-01 and the S5 counter rules for every state and input.
    #[kani::proof]
    fn kani_s5_counter() {
        let cv: u16 = kani::any();
        kani::assume(cv <= CV_MAX);
        let state = S5CounterState {
            cv,
            cu_prev: kani::any(),
            cd_prev: kani::any(),
            s_prev: kani::any(),
        };
        let pv = CounterPreset::new(kani::any::<u16>() % 1000).unwrap_or_default();
        let input = S5CounterInput {
            cu: kani::any(),
            cd: kani::any(),
            s: kani::any(),
            r: kani::any(),
            pv,
        };
        let kind: S5CounterKind = kani::any();
        let checked = prop_s5_step_equivalence(kind, state, input);
        kani::cover!(checked, "the premise is reachable");
        prop_s5_rules(kind, state, input);
    }
}
