//! Properties of the counters: the packed IEC counter and the counter bank simulate the
//! reference, the S5 counter cell simulates the S5 reference, CV stays in range, the priorities
//! and edge rules hold, no panic.
//!
//! Small scope: the IEC counters are one generic implementation over [`CounterInt`]; the
//! exhaustive drivers cover every state and input of the 8-bit types (SInt and USInt, signed and
//! unsigned, so both saturation ends and the sign of `CV <= 0`), and proptest and the Kani
//! harnesses the wide types.

use plc_timers::counter::s5::{
    CounterMemory, CounterPreset, S5Counter, S5CounterInput, S5CounterKind, S5CounterOps,
    S5CounterRef, S5CounterState, CV_MAX,
};
use plc_timers::counter::{
    BankInputs, Counter, CounterBank, CounterInput, CounterInt, CounterKind, CounterOps,
    CounterRef, CounterState,
};
use proptest::prelude::*;

/// CNT-EQUIV-01: one packed step equals one reference step, state and outputs.
pub fn prop_step_equivalence<T: CounterInt>(
    kind: CounterKind,
    state: CounterState<T>,
    input: CounterInput<T>,
) {
    let mut r = CounterRef::from_state(state);
    let mut p = Counter::from_state(state);
    assert_eq!(
        p.state(),
        state,
        "CNT-EQUIV-01: abstraction inverts from_state"
    );
    let ro = r.call(kind, input);
    let po = p.call(kind, input);
    assert_eq!(po, ro, "CNT-EQUIV-01 outputs {kind:?} {state:?} {input:?}");
    assert_eq!(p.cv(), po.cv, "CNT-EQUIV-01: CV accessor");
    assert_eq!(
        p.state(),
        r.state(),
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
    let mut r = CounterRef::from_state(state);
    let out = r.call(kind, input);
    let i = input.with_signals(kind.mask(input.signals()));
    let (before, after) = (state.cv.to_i128(), r.state().cv.to_i128());
    assert_eq!(
        (out.qu, out.qd, out.cv),
        (
            r.state().cv >= input.pv,
            r.state().cv <= T::ZERO,
            r.state().cv
        ),
        "CNT-Q-01"
    );
    assert_eq!(
        (r.state().cu_prev, r.state().cd_prev),
        (i.cu, i.cd),
        "CNT-EDGE-01: edge memories take the inputs"
    );
    if i.r {
        assert_eq!(r.state().cv, T::ZERO, "CNT-PRIO-01: R resets");
        return;
    }
    if i.ld {
        assert_eq!(r.state().cv, input.pv, "CNT-PRIO-01: LD loads PV");
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

    /// CNT-EQUIV-01: a bank of 64 CTUD counters over 12 scans of random inputs equals 64
    /// reference counters.
    #[test]
    fn proptest_bank_equals_reference(
        scans in prop::collection::vec(any::<[u64; 4]>(), 12),
        pv in arb_wide::<i16>(),
    ) {
        prop_bank::<i16, 64>(&scans, pv);
    }
}

/// CNT-EQUIV-01 (the bank): a bank of `N` CTUD counters scanned with the input bits `scans`
/// (bit `i` of each word is counter `i`'s CU, CD, R, LD) equals `N` reference counters.
pub fn prop_bank<T: CounterInt, const N: usize>(scans: &[[u64; 4]], pv: T) {
    let mut bank = CounterBank::<T, N>::new();
    let mut refs = [CounterRef::<T>::new(); N];
    assert_eq!(bank.get(N), None, "counter {N} does not exist");
    for &[cu, cd, r, ld] in scans {
        // Thin out R and LD so that counting is exercised too.
        let (r, ld) = (r & cu & cd, ld & !cu & cd);
        let bits = |w: u64| -> [bool; N] { core::array::from_fn(|i| w >> (i % 64) & 1 != 0) };
        let (bcu, bcd, br, bld) = (bits(cu), bits(cd), bits(r), bits(ld));
        bank.scan(
            &BankInputs {
                cu: &bcu,
                cd: &bcd,
                r: &br,
                ld: &bld,
            },
            pv,
        );
        for (i, c) in refs.iter_mut().enumerate() {
            let o = c.call(
                CounterKind::Ctud,
                CounterInput {
                    cu: bcu[i],
                    cd: bcd[i],
                    r: br[i],
                    ld: bld[i],
                    pv,
                },
            );
            assert_eq!(
                bank.get(i),
                Some(c.state()),
                "CNT-EQUIV-01 bank counter {i}"
            );
            assert_eq!(bank.output(i, pv), Some(o), "CNT-EQUIV-01 bank output {i}");
        }
    }
}

/// The CU, CD and S edge memories as the operations after FR see them: a rising FR clears
/// them (SC-FR-01).
pub fn s5_memories_after_fr(state: &S5CounterState, fr: bool) -> (bool, bool, bool) {
    let clear = fr && !state.fr_prev;
    (
        state.cu_prev && !clear,
        state.cd_prev && !clear,
        state.s_prev && !clear,
    )
}

/// CNT-EQUIV-01 (S5 counters): one packed S5 counter step equals one reference step, and the
/// counter memory area's box call equals both.
pub fn prop_s5_step_equivalence(
    kind: S5CounterKind,
    state: S5CounterState,
    input: S5CounterInput,
) -> bool {
    let Some(word) = S5Counter::from_state(state) else {
        return false;
    };
    assert_eq!(
        word.state(),
        state,
        "CNT-EQUIV-01: abstraction inverts from_state"
    );
    let mut r = S5CounterRef::from_state(state).expect("valid");
    let ro = r.call(kind, input);
    let word = word.execute(kind, input);
    assert_eq!(
        word.state(),
        r.state(),
        "CNT-EQUIV-01 S5 {kind:?} {state:?} {input:?}"
    );
    assert_eq!(word.output(), ro, "CNT-EQUIV-01 S5 outputs");
    let mut area = CounterMemory::<2>::new();
    assert_eq!(area.set_state(1, state), Ok(true));
    assert_eq!(area.call(1, kind, input), Ok(ro), "CNT-EQUIV-01 S5 area");
    assert_eq!(area.get(1), Ok(r.state()), "CNT-EQUIV-01 S5 area state");
    true
}

/// SC-RANGE-01, SC-Q-01, SC-PRIO-01: CV stays in 0..=999, CV_BCD is its BCD form, Q = CV != 0,
/// R = 1 gives 0, a rising S (without R) gives PV, counting moves CV by at most one.
pub fn prop_s5_rules(kind: S5CounterKind, state: S5CounterState, input: S5CounterInput) -> bool {
    if !state.is_valid() {
        return false;
    }
    let mut r = S5CounterRef::from_state(state).expect("valid");
    let out = r.call(kind, input);
    let (_, _, s_prev) = s5_memories_after_fr(&state, input.fr);
    assert!(out.cv <= CV_MAX, "SC-RANGE-01");
    assert_eq!(
        CounterPreset::from_bcd(out.cv_bcd).map(CounterPreset::value),
        Ok(out.cv),
        "SC-RANGE-01: CV_BCD"
    );
    assert_eq!(out.q, out.cv != 0, "SC-Q-01");
    if input.r {
        assert_eq!(out.cv, 0, "SC-PRIO-01: R resets");
    } else if input.s && !s_prev {
        assert_eq!(out.cv, input.pv.value(), "SC-PRIO-01: a rising S sets PV");
    } else {
        assert!(
            out.cv.abs_diff(state.cv) <= 1,
            "SC-SAT-01: counting moves CV by at most 1"
        );
    }
    true
}

/// Exhaustive S5 counters: 3 kinds x CV 0..=999 x 16 edge memories x 32 inputs x 5 presets.
#[test]
fn exhaustive_s5_counters() {
    let mut checked = 0;
    let presets: Vec<CounterPreset> = [0, 1, 500, 998, 999]
        .into_iter()
        .filter_map(|n| CounterPreset::new(n).ok())
        .collect();
    for kind in S5CounterKind::ALL {
        for cv in 0..=CV_MAX {
            for e in 0..16u8 {
                let state = S5CounterState {
                    cv,
                    cu_prev: e & 1 != 0,
                    cd_prev: e & 2 != 0,
                    s_prev: e & 4 != 0,
                    fr_prev: e & 8 != 0,
                };
                for &pv in &presets {
                    for bits in 0..32u8 {
                        let input = S5CounterInput {
                            cu: bits & 1 != 0,
                            cd: bits & 2 != 0,
                            s: bits & 4 != 0,
                            r: bits & 8 != 0,
                            fr: bits & 16 != 0,
                            pv,
                        };
                        checked += u32::from(prop_s5_step_equivalence(kind, state, input));
                        checked += u32::from(prop_s5_rules(kind, state, input));
                    }
                }
            }
        }
    }
    assert_eq!(checked, 2 * 3 * 1000 * 16 * presets.len() as u32 * 32);
}

/// One STL operation on an S5 counter: `FR`, `CU`, `CD`, `S` or `R C n` with its RLO.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum StlOp {
    /// `FR C n`.
    Fr(bool),
    /// `CU C n` (`ZV`).
    Cu(bool),
    /// `CD C n` (`ZR`).
    Cd(bool),
    /// `S C n` with the preset in ACCU 1.
    S(bool),
    /// `R C n`.
    R(bool),
}

/// SC-STL-01: the counter memory area's STL operations equal the reference's operations, and
/// each evaluates only its own input: its edge memory takes the RLO, the others are untouched
/// except where the operation's own rule clears them (FR: all three; S: CU and CD).
pub fn prop_stl_operations(pv: CounterPreset, ops: &[StlOp]) {
    let mut reference = S5CounterRef::new();
    let mut area = CounterMemory::<1>::new();
    for (n, &op) in ops.iter().enumerate() {
        let before = reference.state();
        let done = match op {
            StlOp::Fr(rlo) => {
                reference.enable(rlo);
                area.fr(0, rlo)
            }
            StlOp::Cu(rlo) => {
                reference.count_up(rlo);
                area.cu(0, rlo)
            }
            StlOp::Cd(rlo) => {
                reference.count_down(rlo);
                area.cd(0, rlo)
            }
            StlOp::S(rlo) => {
                reference.set(rlo, pv);
                area.set(0, rlo, pv)
            }
            StlOp::R(rlo) => {
                reference.reset(rlo);
                area.reset(0, rlo)
            }
        };
        assert_eq!(done, Ok(()), "counter 0 exists");
        let after = reference.state();
        assert_eq!(
            area.get(0),
            Ok(after),
            "SC-STL-01 area after operation {n} of {ops:?}"
        );
        let expected = after.output();
        assert_eq!(
            (area.load(0), area.load_bcd(0), area.status(0)),
            (Ok(expected.cv), Ok(expected.cv_bcd), Ok(expected.q)),
            "SC-STL-01 reads after operation {n} of {ops:?}"
        );
        let memories = |s: &S5CounterState| [s.cu_prev, s.cd_prev, s.s_prev, s.fr_prev];
        let (b, a) = (memories(&before), memories(&after));
        let own = match op {
            StlOp::Cu(_) => 0,
            StlOp::Cd(_) => 1,
            StlOp::S(_) => 2,
            StlOp::Fr(_) => 3,
            StlOp::R(_) => 4,
        };
        for k in 0..4 {
            if k == own {
                continue;
            }
            let cleared = match op {
                StlOp::Fr(rlo) => rlo && !before.fr_prev,
                StlOp::S(rlo) => k < 2 && rlo && !before.s_prev,
                _ => false,
            };
            let expect = if cleared { false } else { b[k] };
            assert_eq!(
                a[k], expect,
                "SC-STL-01: memory {k} after {op:?} at {n} of {ops:?}"
            );
        }
    }
}

/// SC-STL-01 driver: every sequence of 5 operations over the 10 (operation, RLO) pairs
/// (100 000 sequences), with the presets 0, 1 and 999.
#[test]
fn exhaustive_stl_operations() {
    const SYMBOLS: [StlOp; 10] = [
        StlOp::Fr(false),
        StlOp::Fr(true),
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
        for mut code in 0..10usize.pow(5) {
            let mut ops = [StlOp::Cu(false); 5];
            for op in ops.iter_mut() {
                *op = SYMBOLS[code % 10];
                code /= 10;
            }
            prop_stl_operations(pv, &ops);
            sequences += 1;
        }
    }
    assert_eq!(sequences, 3 * 100_000);
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
