//! Properties of the counters: the packed IEC counter and the counter bank simulate the
//! reference, the S5 counter cell simulates the S5 reference, CV stays in range, the priorities
//! and edge rules hold, no panic.
//!
//! Small scope: the IEC counters are one generic implementation over [`CounterInt`]; the
//! exhaustive drivers cover every state and input of the 8-bit types (SInt and USInt, signed and
//! unsigned, so both saturation ends and the sign of `CV <= 0`), and proptest and the Kani
//! harnesses the wide types.

use crate::cover::{check, check_eq};
use crate::domain::{counter_inputs, counter_states, s5_counter_inputs, s5_counter_states};
use plc_timers::counter::s5::{
    CounterMemory, CounterPreset, S5Counter, S5CounterInput, S5CounterKind, S5CounterOps,
    S5CounterRef, S5CounterState, CV_MAX,
};
use plc_timers::counter::{
    ArrayOutputs, BankInputs, Counter, CounterBank, CounterInput, CounterInt, CounterKind,
    CounterOps, CounterRef, CounterState,
};
use plc_timers::{NoSuchOperand, Operand};
use proptest::prelude::*;

/// CNT-EQUIV-01: one packed step equals one reference step, state and outputs.
pub fn prop_step_equivalence<T: CounterInt>(
    kind: CounterKind,
    state: CounterState<T>,
    input: CounterInput<T>,
) {
    let mut r = CounterRef::from_state(state);
    let mut p = Counter::from_state(state);
    check_eq!(
        p.state(),
        state,
        "CNT-EQUIV-01: abstraction inverts from_state"
    );
    let ro = r.call(kind, input);
    let po = p.call(kind, input);
    check_eq!(po, ro, "CNT-EQUIV-01 outputs {kind:?} {state:?} {input:?}");
    check_eq!(p.cv(), po.cv, "CNT-EQUIV-01: CV accessor");
    check_eq!(
        p.state(),
        r.state(),
        "CNT-EQUIV-01 state {kind:?} {state:?} {input:?}"
    );
    // The form for arrays: the same outputs and state, computed without a branch.
    let mut a = Counter::from_state(state);
    assert_eq!(
        a.call_for_arrays(kind, input),
        ro,
        "CNT-EQUIV-01 call_for_arrays outputs {kind:?} {state:?} {input:?}"
    );
    assert_eq!(
        a.state(),
        r.state(),
        "CNT-EQUIV-01 call_for_arrays state {kind:?} {state:?} {input:?}"
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
    check_eq!(
        (out.qu, out.qd, out.cv),
        (
            r.state().cv >= input.pv,
            r.state().cv <= T::ZERO,
            r.state().cv
        ),
        "CNT-Q-01"
    );
    check_eq!(
        (r.state().cu_prev, r.state().cd_prev),
        (i.cu, i.cd),
        "CNT-EDGE-01: edge memories take the inputs"
    );
    if i.r {
        check_eq!(r.state().cv, T::ZERO, "CNT-PRIO-01: R resets");
        return;
    }
    if i.ld {
        check_eq!(r.state().cv, input.pv, "CNT-PRIO-01: LD loads PV");
        return;
    }
    let up = i.cu && !state.cu_prev;
    let down = i.cd && !state.cd_prev;
    let expected = match (up, down) {
        (true, false) => (before + 1).min(T::MAX.to_i128()),
        (false, true) => (before - 1).max(T::MIN.to_i128()),
        _ => before,
    };
    check_eq!(
        after,
        expected,
        "CNT-SAT-01 / CNT-SIMUL-01 / CNT-EDGE-01 {kind:?} {state:?} {input:?}"
    );
}

fn exhaustive_8bit<T: CounterInt>(values: impl Iterator<Item = T> + Clone) -> u64 {
    let mut n = 0;
    for kind in CounterKind::ALL {
        for state in counter_states(values.clone()) {
            for pv in values.clone() {
                for input in counter_inputs(pv) {
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
    check_eq!(exhaustive_8bit(i8::MIN..=i8::MAX), 3 * 256 * 4 * 256 * 16);
}

/// Exhaustive for USInt: the same domain, unsigned (QD is CV = 0; saturation at 0 and 255).
#[test]
fn exhaustive_usint() {
    check_eq!(exhaustive_8bit(u8::MIN..=u8::MAX), 3 * 256 * 4 * 256 * 16);
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

    /// CNT-EQUIV-01: `call_array` over 40 counters of each kind (two groups of 16 and a padded
    /// last group of 8), 12 scans of random inputs, presets near 0 and anywhere: equal to 40
    /// reference counters.
    #[test]
    fn proptest_call_array_equals_reference(
        scans in prop::collection::vec(any::<[u64; 4]>(), 12),
        pv in prop::collection::vec(prop_oneof![-3i16..4, arb_wide::<i16>()], 40),
        kind in 0usize..3,
    ) {
        let pv: [i16; 40] = core::array::from_fn(|i| pv[i]);
        prop_call_array::<i16, 40>(CounterKind::ALL[kind], &scans, &pv);
    }

    /// CNT-EQUIV-01: a bank of 72 CTUD counters over 12 scans of random inputs equals 72
    /// reference counters: four groups of 16 and 8 counters one at a time, or with
    /// `simd-dispatch` on AVX2 or AVX-512 one group of 64 and 8 (counters 64-71 take the
    /// inputs of 0-7, each from its own state).
    #[test]
    fn proptest_bank_equals_reference(
        scans in prop::collection::vec(any::<[u64; 4]>(), 12),
        pv in arb_wide::<i16>(),
    ) {
        prop_bank::<i16, 72>(&scans, pv);
    }
}

/// The CU, CD, R and LD of `N` counters in one scan from four words (bit `i % 64` of each is
/// counter `i`'s), R and LD thinned out so that counting is exercised too.
fn scan_inputs<const N: usize>([cu, cd, r, ld]: [u64; 4]) -> [[bool; N]; 4] {
    let (r, ld) = (r & cu & cd, ld & !cu & cd);
    [cu, cd, r, ld].map(|w| core::array::from_fn(|i| w >> (i % 64) & 1 != 0))
}

/// The inputs of `scan_inputs` as the bank and the array form take them.
fn bank_inputs<const N: usize>([cu, cd, r, ld]: &[[bool; N]; 4]) -> BankInputs<'_, N> {
    BankInputs { cu, cd, r, ld }
}

/// CNT-EQUIV-01 (the bank): a bank of `N` CTUD counters scanned with the input bits `scans`
/// (bit `i % 64` of each word is counter `i`'s CU, CD, R, LD) equals `N` reference counters.
pub fn prop_bank<T: CounterInt, const N: usize>(scans: &[[u64; 4]], pv: T) {
    let mut bank = CounterBank::<T, N>::new();
    let mut refs = [CounterRef::<T>::new(); N];
    check_eq!(
        bank.get(N),
        Err(NoSuchOperand {
            operand: Operand::Counter,
            index: N,
            count: N
        }),
        "counter {N} does not exist"
    );
    for &scan in scans {
        let ins = scan_inputs::<N>(scan);
        let [bcu, bcd, br, bld] = &ins;
        bank.scan(&bank_inputs(&ins), pv);
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
            check_eq!(bank.get(i), Ok(c.state()), "CNT-EQUIV-01 bank counter {i}");
            check_eq!(bank.output(i, pv), Ok(o), "CNT-EQUIV-01 bank output {i}");
        }
    }
}

/// CNT-EQUIV-01 (the array form): `N` counters called as `kind` by `Counter::call_array` with
/// the input bits `scans` (bit `i % 64` of each word is counter `i`'s CU, CD, R, LD) and the
/// presets `pv` equal `N` reference counters, called one by one: each counter's state, and the
/// outputs written for it.
pub fn prop_call_array<T: CounterInt, const N: usize>(
    kind: CounterKind,
    scans: &[[u64; 4]],
    pv: &[T; N],
) {
    let mut counters = [Counter::<T>::new(); N];
    let mut refs = [CounterRef::<T>::new(); N];
    for (k, &scan) in scans.iter().enumerate() {
        let ins = scan_inputs::<N>(scan);
        let [bcu, bcd, br, bld] = &ins;
        // Outputs from a fill that differs scan by scan: an output left unwritten shows.
        let fill = k % 2 == 0;
        let (mut qu, mut qd) = ([fill; N], [!fill; N]);
        let mut cv = [if fill { T::MAX } else { T::MIN }; N];
        Counter::call_array(
            &mut counters,
            kind,
            &bank_inputs(&ins),
            pv,
            &mut ArrayOutputs {
                qu: &mut qu,
                qd: &mut qd,
                cv: &mut cv,
            },
        );
        for (i, c) in refs.iter_mut().enumerate() {
            let o = c.call(
                kind,
                CounterInput {
                    cu: bcu[i],
                    cd: bcd[i],
                    r: br[i],
                    ld: bld[i],
                    pv: pv[i],
                },
            );
            check_eq!(
                (qu[i], qd[i], cv[i]),
                (o.qu, o.qd, o.cv),
                "CNT-EQUIV-01 call_array outputs of counter {i} ({kind:?})"
            );
            check_eq!(
                counters[i].state(),
                c.state(),
                "CNT-EQUIV-01 call_array state of counter {i} ({kind:?})"
            );
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
    check_eq!(
        word.state(),
        state,
        "CNT-EQUIV-01: abstraction inverts from_state"
    );
    let mut r = S5CounterRef::from_state(state).expect("valid");
    let ro = r.call(kind, input);
    let mut word = word;
    let wo = word.call(kind, input);
    check_eq!(
        wo,
        word.output(),
        "CNT-EQUIV-01: call returns the word's outputs"
    );
    check_eq!(
        word.state(),
        r.state(),
        "CNT-EQUIV-01 S5 {kind:?} {state:?} {input:?}"
    );
    check_eq!(word.output(), ro, "CNT-EQUIV-01 S5 outputs");
    let mut area = CounterMemory::<2>::new();
    check_eq!(area.set_state(1, state), Ok(true));
    check_eq!(area.call(1, kind, input), Ok(ro), "CNT-EQUIV-01 S5 area");
    check_eq!(area.get(1), Ok(r.state()), "CNT-EQUIV-01 S5 area state");
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
    check!(out.cv <= CV_MAX, "SC-RANGE-01");
    check_eq!(
        CounterPreset::from_bcd(out.cv_bcd).map(CounterPreset::value),
        Ok(out.cv),
        "SC-RANGE-01: CV_BCD"
    );
    check_eq!(out.q, out.cv != 0, "SC-Q-01");
    if input.r {
        check_eq!(out.cv, 0, "SC-PRIO-01: R resets");
    } else if input.s && !s_prev {
        check_eq!(out.cv, input.pv.value(), "SC-PRIO-01: a rising S sets PV");
    } else {
        check!(
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
        for state in s5_counter_states(0..=CV_MAX) {
            for &pv in &presets {
                for input in s5_counter_inputs(pv) {
                    checked += u32::from(prop_s5_step_equivalence(kind, state, input));
                    checked += u32::from(prop_s5_rules(kind, state, input));
                }
            }
        }
    }
    check_eq!(checked, 2 * 3 * 1000 * 16 * presets.len() as u32 * 32);
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
        check_eq!(done, Ok(()), "counter 0 exists");
        let after = reference.state();
        check_eq!(
            area.get(0),
            Ok(after),
            "SC-STL-01 area after operation {n} of {ops:?}"
        );
        let expected = after.output();
        check_eq!(
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
            check_eq!(
                a[k],
                expect,
                "SC-STL-01: memory {k} after {op:?} at {n} of {ops:?}"
            );
        }
    }
}

/// SC-STL-01 driver: every sequence of 5 operations over the 10 (operation, RLO) pairs
/// (100 000 sequences), with the presets 0, 1 and 999.
#[test]
fn exhaustive_stl_operations() {
    crate::cover::check_ids(&["SC-STL-01"], || {
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
        check_eq!(sequences, 3 * 100_000);
    });
}

/// SC-RANGE-01 for the optimized word, exhaustive over all 65 536 bit patterns: a word is
/// accepted exactly when its layout holds (CV in bits 9-0 at most 999, bits 11-10 zero; the
/// edge memories of CU, CD, S and FR in bits 12-15, any), and then it reads back its bits,
/// its state is those fields, and the state packs into the same word.
#[test]
fn exhaustive_s5_counter_words() {
    let mut accepted = 0;
    for w in 0..=u16::MAX {
        let cv = w & 0x3FF;
        let valid = (w >> 10) & 0b11 == 0 && cv <= 999;
        match S5Counter::from_bits(w) {
            Some(word) => {
                check!(valid, "SC-RANGE-01: bits {w:#06X} accepted");
                check_eq!(word.bits(), w);
                let st = word.state();
                check_eq!(
                    S5CounterOps::state(&word),
                    st,
                    "SC-RANGE-01: the trait's view"
                );
                let edges = [st.cu_prev, st.cd_prev, st.s_prev, st.fr_prev];
                check_eq!(
                    (st.cv, edges),
                    (cv, [12, 13, 14, 15].map(|b| w >> b & 1 == 1))
                );
                check_eq!(S5Counter::from_state(st), Some(word));
                accepted += 1;
            }
            None => check!(!valid, "SC-RANGE-01: bits {w:#06X} rejected"),
        }
    }
    check_eq!(accepted, 1000 * 16);
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
                check!(valid, "SC-BCD-01: W#16#{w:04X} accepted");
                check_eq!(p.value(), digits[1] * 100 + digits[2] * 10 + digits[3]);
                check_eq!(p.to_bcd(), w);
                accepted += 1;
            }
            Err(_) => check!(!valid, "SC-BCD-01: W#16#{w:04X} rejected"),
        }
    }
    check_eq!(accepted, 1000);
}

/// SC-BCD-01 in text form: `C#n` and the plain number `n` are the preset `n` exactly when
/// `n <= 999`; above, the error is `OutOfRange(n)` (the value saturated at `u32::MAX`), with or
/// without blanks around; `C#`, a sign or another character is a syntax error.
pub fn prop_preset_text(n: u64) {
    use plc_timers::counter::s5::CounterPresetError;
    let expected = if n <= 999 {
        Ok(u16::try_from(n).expect("at most 999"))
    } else {
        Err(CounterPresetError::OutOfRange(
            u32::try_from(n).unwrap_or(u32::MAX),
        ))
    };
    for text in [
        format!("C#{n}"),
        format!("c#{n}"),
        format!("{n}"),
        format!(" C#{n} "),
    ] {
        check_eq!(
            CounterPreset::parse(&text).map(CounterPreset::value),
            expected,
            "SC-BCD-01: {text:?} is C#0..C#999 or 0..999; above 999 it is out of range"
        );
    }
    for bad in [
        format!("C#-{n}"),
        format!("C#+{n}"),
        format!("C#{n}x"),
        String::from("C#"),
    ] {
        check_eq!(
            CounterPreset::parse(&bad),
            Err(CounterPresetError::Syntax),
            "SC-BCD-01: {bad:?} is not a preset"
        );
    }
}

/// SC-BCD-01 in text form over 0..=100 000 and the ends of `u32` and beyond.
#[test]
fn exhaustive_s5_preset_texts() {
    crate::cover::check_ids(&["SC-BCD-01"], || {
        (0..=100_000).for_each(prop_preset_text);
        for n in [
            u64::from(u32::MAX) - 1,
            u64::from(u32::MAX),
            u64::from(u32::MAX) + 1,
            u64::MAX,
        ] {
            prop_preset_text(n);
        }
    });
}

// ---------------------------------------------------------------------------------------------
// One property per requirement: the rule's text as a predicate over one call, checked on every
// implementation (IEC: reference, packed counter, bank for CTUD; S5: reference, packed word,
// the area's box call and the area's STL sequence FR, CU, CD, S, R).
// ---------------------------------------------------------------------------------------------

use crate::cover::{cover, covers};

/// One IEC counter call through each implementation: (name, state after, outputs).
fn iec_counter_impls<T: CounterInt>(
    kind: CounterKind,
    st: CounterState<T>,
    i: CounterInput<T>,
) -> Vec<(
    &'static str,
    CounterState<T>,
    plc_timers::counter::CounterOutput<T>,
)> {
    let mut v = Vec::with_capacity(5);
    let mut r = CounterRef::from_state(st);
    let o = r.call(kind, i);
    v.push(("reference", r.state(), o));
    let mut p = Counter::from_state(st);
    let o = p.call(kind, i);
    v.push(("packed", p.state(), o));
    let mut a = Counter::from_state(st);
    let o = a.call_for_arrays(kind, i);
    v.push(("packed, call_for_arrays", a.state(), o));
    // The array form on an array of one: its group code on a padded copy of 16.
    let mut arr = [Counter::from_state(st)];
    let (mut qu, mut qd, mut cv) = ([true], [true], [T::MAX]);
    Counter::call_array(
        &mut arr,
        kind,
        &BankInputs {
            cu: &[i.cu],
            cd: &[i.cd],
            r: &[i.r],
            ld: &[i.ld],
        },
        &[i.pv],
        &mut ArrayOutputs {
            qu: &mut qu,
            qd: &mut qd,
            cv: &mut cv,
        },
    );
    let o = plc_timers::counter::CounterOutput {
        qu: qu[0],
        qd: qd[0],
        cv: cv[0],
    };
    v.push(("packed, call_array", arr[0].state(), o));
    if kind == CounterKind::Ctud {
        let mut bank = CounterBank::<T, 1>::new();
        check_eq!(bank.set_state(0, st), Ok(()));
        bank.scan(
            &BankInputs {
                cu: &[i.cu],
                cd: &[i.cd],
                r: &[i.r],
                ld: &[i.ld],
            },
            i.pv,
        );
        v.push((
            "bank",
            bank.get(0).expect("0"),
            bank.output(0, i.pv).expect("0"),
        ));
    }
    v
}

/// CNT-EDGE-01, CNT-PRIO-01, CNT-SAT-01, CNT-SIMUL-01, CNT-Q-01, CNT-INPUTS-01, each stated on
/// its own, in `i128` where `CV +- 1` cannot overflow.
#[covers]
pub fn prop_iec_counter_rules<T: CounterInt>(
    kind: CounterKind,
    st: CounterState<T>,
    i: CounterInput<T>,
) {
    let (has_cu, has_cd, has_r, has_ld) = match kind {
        CounterKind::Ctu => (true, false, true, false),
        CounterKind::Ctd => (false, true, false, true),
        CounterKind::Ctud => (true, true, true, true),
    };
    let (cu, cd, r, ld) = (i.cu && has_cu, i.cd && has_cd, i.r && has_r, i.ld && has_ld);
    let up = cu && !st.cu_prev;
    let down = cd && !st.cd_prev;
    let cv = st.cv.to_i128();
    let (min, max) = (T::MIN.to_i128(), T::MAX.to_i128());
    // CNT-INPUTS-01: an absent input has no effect: the call equals the one with it at 0.
    let masked = CounterInput {
        cu,
        cd,
        r,
        ld,
        pv: i.pv,
    };
    let reference = iec_counter_impls(kind, st, masked);
    for (name, post, out) in iec_counter_impls(kind, st, i) {
        let same = reference
            .iter()
            .find(|(n, _, _)| *n == name)
            .expect("same impl");
        check_eq!(
            (post, out),
            (same.1, same.2),
            "CNT-INPUTS-01: {name}: {kind:?} ignores the inputs it does not have"
        );
        check_eq!(
            (post.cu_prev, post.cd_prev),
            (cu, cd),
            "CNT-EDGE-01: {name}: the edge memories take the inputs on every call (also under R, LD)"
        );
        let after = post.cv.to_i128();
        if r {
            check_eq!(after, 0, "CNT-PRIO-01: {name}: R = 1 gives CV = 0");
        } else if ld {
            check_eq!(
                post.cv,
                i.pv,
                "CNT-PRIO-01: {name}: LD = 1 (R = 0) gives CV = PV"
            );
        } else if up && down {
            check_eq!(
                after,
                cv,
                "CNT-SIMUL-01: {name}: CU and CD rising together leave CV"
            );
        } else if up {
            check_eq!(
                after,
                (cv + 1).min(max),
                "CNT-SAT-01: {name}: counting up stops at MAX"
            );
        } else if down {
            check_eq!(
                after,
                (cv - 1).max(min),
                "CNT-SAT-01: {name}: counting down stops at MIN"
            );
        } else {
            check_eq!(after, cv, "CNT-EDGE-01: {name}: no rising edge, no count");
        }
        check_eq!(
            (out.qu, out.qd, out.cv),
            (post.cv >= i.pv, post.cv <= T::ZERO, post.cv),
            "CNT-Q-01: {name}: QU = CV >= PV, QD = CV <= 0"
        );
    }
    cover!(
        up && !down && !r && !ld && cv == max,
        "CNT-SAT-01: count up at MAX"
    );
    cover!(up && down && !r && !ld, "CNT-SIMUL-01: both edges");
    cover!(r && ld, "CNT-PRIO-01: R and LD together");
    cover!(i.cu && st.cu_prev && !r, "CNT-EDGE-01: CU held");
}

/// Exhaustive on the 8-bit types: every kind x CV x edge memories x PV in {MIN, -1, 0, 1, MAX}
/// x inputs. Small scope: the rules compare CV with MIN, MAX and PV and 0; at 8 bits every such
/// case occurs, and the code is the same generic code as at 64 bits (Kani: `kani_counter_*`).
// Uses the cover recorder, which exists outside Kani only (proofs/cover.rs).
#[cfg(not(kani))]
#[test]
fn exhaustive_counter_rules_8bit() {
    crate::cover::check_ids(
        &[
            "CNT-EDGE-01",
            "CNT-PRIO-01",
            "CNT-SAT-01",
            "CNT-SIMUL-01",
            "CNT-Q-01",
            "CNT-INPUTS-01",
        ],
        || {
            for kind in CounterKind::ALL {
                for st in counter_states(i8::MIN..=i8::MAX) {
                    for pv in [i8::MIN, -1, 0, 1, i8::MAX] {
                        for i in counter_inputs(pv) {
                            prop_iec_counter_rules(kind, st, i);
                            // The same bits as USInt: the unsigned saturation ends.
                            let ust = CounterState {
                                cv: st.cv as u8,
                                cu_prev: st.cu_prev,
                                cd_prev: st.cd_prev,
                            };
                            let ui = CounterInput {
                                cu: i.cu,
                                cd: i.cd,
                                r: i.r,
                                ld: i.ld,
                                pv: pv as u8,
                            };
                            prop_iec_counter_rules(kind, ust, ui);
                        }
                    }
                }
            }
        },
    );
}

/// `st` with CV at a limit of its type (MAX when CU's memory is 0, else MIN): a state of every
/// harness's domain that random values of the wide types almost never reach. Harnesses run it
/// beside each random case under `cargo test` (Kani covers it with the rest).
pub fn at_limit<T: CounterInt>(st: CounterState<T>) -> CounterState<T> {
    CounterState {
        cv: if st.cu_prev { T::MIN } else { T::MAX },
        ..st
    }
}

/// `st` with CV at a limit of the S5 counter (999 when S's memory is 0, else 0): a state of
/// every harness's domain that random 16-bit values seldom reach. Harnesses run it beside each
/// random case under `cargo test` (Kani covers it with the rest).
pub fn s5_at_limit(st: S5CounterState) -> S5CounterState {
    S5CounterState {
        cv: if st.s_prev { 0 } else { 999 },
        ..st
    }
}

macro_rules! counter_harness {
    ($name:ident, $t:ty) => {
        /// CNT-EQUIV-01 and every IEC counter rule for this type: random under `cargo test`,
        /// every state and input under Kani. Symbolic: the kind, the state (CV of this type,
        /// the edge memories, Q), CU, CD, R, LD and PV. `#[kani::unwind(17)]`: the array form
        /// (`call_array` on one counter) runs its group code on a padded copy of 16 (loops of
        /// 16 iterations and the exit, the largest); the loop over the implementations (5 for
        /// CTUD) and the bank's one counter are shorter.
        #[test]
        #[cfg_attr(kani, kani::proof, kani::unwind(17))]
        fn $name() {
            crate::cover::harness(concat!(module_path!(), "::", stringify!($name)), || {
                bolero::check!()
                    .with_type::<(CounterKind, CounterState<$t>, CounterInput<$t>)>()
                    .with_iterations(5_000)
                    .for_each(|&(kind, st, i)| {
                        prop_step_equivalence(kind, st, i);
                        prop_iec_counter_rules(kind, st, i);
                        #[cfg(not(kani))]
                        {
                            prop_step_equivalence(kind, at_limit(st), i);
                            prop_iec_counter_rules(kind, at_limit(st), i);
                        }
                    });
            });
        }
    };
}

counter_harness!(kani_counter_sint, i8);
counter_harness!(kani_counter_int, i16);
counter_harness!(kani_counter_dint, i32);
counter_harness!(kani_counter_lint, i64);
counter_harness!(kani_counter_usint, u8);
counter_harness!(kani_counter_uint, u16);
counter_harness!(kani_counter_udint, u32);
counter_harness!(kani_counter_ulint, u64);

/// One S5 counter call through each implementation: (name, state after, outputs).
fn s5_counter_impls(
    kind: S5CounterKind,
    st: S5CounterState,
    i: S5CounterInput,
) -> [(
    &'static str,
    S5CounterState,
    plc_timers::counter::s5::S5CounterOutput,
); 4] {
    let mut r = S5CounterRef::from_state(st).expect("valid");
    let ro = r.call(kind, i);
    let mut w = S5Counter::from_state(st).expect("valid");
    w.call(kind, i);
    let mut area = CounterMemory::<2>::new();
    check_eq!(area.set_state(1, st), Ok(true));
    let ao = area.call(1, kind, i).expect("C 1");
    // The box as its STL sequence FR, CU, CD, S, R on C 0 (SC-PRIO-01, SC-INPUTS-01).
    let mut stl = CounterMemory::<1>::new();
    check_eq!(stl.set_state(0, st), Ok(true));
    let mut ops = vec![stl.fr(0, i.fr)];
    if kind.counts_up() {
        ops.push(stl.cu(0, i.cu));
    }
    if kind.counts_down() {
        ops.push(stl.cd(0, i.cd));
    }
    ops.push(stl.set(0, i.s, i.pv));
    ops.push(stl.reset(0, i.r));
    check!(ops.iter().all(Result::is_ok), "C 0 exists");
    let so = plc_timers::counter::s5::S5CounterOutput {
        q: stl.status(0).expect("C 0"),
        cv: stl.load(0).expect("C 0"),
        cv_bcd: stl.load_bcd(0).expect("C 0"),
    };
    [
        ("reference", r.state(), ro),
        ("word", w.state(), w.output()),
        ("area box", area.get(1).expect("C 1"), ao),
        ("area STL", stl.get(0).expect("C 0"), so),
    ]
}

/// Every S5 counter rule on one call, each stated on its own, through every implementation.
#[covers]
pub fn prop_s5_counter_rules(kind: S5CounterKind, st: S5CounterState, i: S5CounterInput) -> bool {
    if !st.is_valid() {
        return false;
    }
    let fr_rise = i.fr && !st.fr_prev;
    let (cu_m, cd_m, s_m) = s5_memories_after_fr(&st, i.fr);
    let up = kind.counts_up() && i.cu && !cu_m;
    let down = kind.counts_down() && i.cd && !cd_m;
    let set = i.s && !s_m;
    let cv = i32::from(st.cv);
    let pv = i.pv.value();
    for (name, post, out) in s5_counter_impls(kind, st, i) {
        check!(
            post.cv <= 999,
            "SC-RANGE-01: {name}: CV {} in 0..=999",
            post.cv
        );
        let bcd = (post.cv / 100) << 8 | (post.cv / 10 % 10) << 4 | (post.cv % 10);
        check_eq!(
            (out.cv, out.cv_bcd),
            (post.cv, bcd),
            "SC-RANGE-01: {name}: CV_BCD is the BCD of CV"
        );
        check_eq!(
            out.q,
            post.cv != 0,
            "SC-Q-01: {name}: Q = 1 exactly when CV != 0"
        );
        check_eq!(
            post.fr_prev,
            i.fr,
            "SC-FR-01: {name}: the FR memory takes FR"
        );
        check_eq!(
            post.s_prev,
            i.s,
            "SC-EDGE-01: {name}: the S memory takes S on every call"
        );
        // The CU and CD memories: the input if the box has it, else left (SC-INPUTS-01); a
        // rising FR clears them first (SC-FR-01); a set clears them (SC-SET-01).
        let cu_after = if set {
            false
        } else if kind.counts_up() {
            i.cu
        } else {
            cu_m
        };
        let cd_after = if set {
            false
        } else if kind.counts_down() {
            i.cd
        } else {
            cd_m
        };
        if kind.counts_up() {
            check_eq!(
                post.cu_prev,
                cu_after,
                "SC-EDGE-01: {name}: the CU memory takes CU (cleared by a set)"
            );
        } else {
            check_eq!(
                post.cu_prev,
                cu_after,
                "SC-INPUTS-01: {name}: S_CD leaves the CU memory alone"
            );
        }
        if kind.counts_down() {
            check_eq!(
                post.cd_prev,
                cd_after,
                "SC-EDGE-01: {name}: the CD memory takes CD (cleared by a set)"
            );
        } else {
            check_eq!(
                post.cd_prev,
                cd_after,
                "SC-INPUTS-01: {name}: S_CU leaves the CD memory alone"
            );
        }
        let after = i32::from(post.cv);
        if i.r {
            check_eq!(
                after,
                0,
                "SC-PRIO-01: {name}: R = 1 holds CV at 0 over S and counting"
            );
            continue;
        }
        if set {
            check_eq!(
                post.cv,
                pv,
                "SC-SET-01: {name}: a rising S sets CV = PV over counting"
            );
            check!(
                !post.cu_prev && !post.cd_prev,
                "SC-SET-01: {name}: a set clears the CU and CD memories"
            );
            continue;
        }
        match (up, down) {
            (true, true) => check_eq!(
                after,
                match cv {
                    999 => 998,
                    0 => 0,
                    v => v,
                },
                "SC-SIMUL-01: {name}: CU and CD rising together both count, each saturating"
            ),
            (true, false) => check_eq!(
                after,
                (cv + 1).min(999),
                "SC-SAT-01: {name}: up stops at 999"
            ),
            (false, true) => {
                check_eq!(after, (cv - 1).max(0), "SC-SAT-01: {name}: down stops at 0")
            }
            (false, false) => check_eq!(after, cv, "SC-EDGE-01: {name}: no rising edge, no count"),
        }
        if fr_rise && !i.cu && !i.cd && !i.s {
            check_eq!(after, cv, "SC-FR-01: {name}: FR alone changes no CV");
        }
    }
    // SC-FR-01 as a relation: a rising FR equals the call from the memories cleared and FR 1.
    if fr_rise {
        let cleared = S5CounterState {
            cu_prev: false,
            cd_prev: false,
            s_prev: false,
            fr_prev: true,
            ..st
        };
        for ((name, a, ao), (_, b, bo)) in s5_counter_impls(kind, st, i)
            .into_iter()
            .zip(s5_counter_impls(kind, cleared, i))
        {
            check_eq!(
                (a, ao),
                (b, bo),
                "SC-FR-01: {name}: a rising FR clears the CU, CD and S memories, nothing else"
            );
        }
    }
    // SC-SET-01 over two calls: a counter set while CU (CD) is held counts once at the next call.
    if set && !i.r && kind != S5CounterKind::SCud {
        let held = S5CounterInput {
            s: i.s,
            r: false,
            ..i
        };
        for (name, post, _) in s5_counter_impls(kind, st, i) {
            let (_, next, _) = s5_counter_impls(kind, post, held)[0];
            let counts = if kind.counts_up() { held.cu } else { held.cd };
            let expected = match (counts, kind.counts_up()) {
                (false, _) => pv,
                (true, true) => (pv + 1).min(999),
                (true, false) => pv.saturating_sub(1),
            };
            check_eq!(
                next.cv,
                expected,
                "SC-SET-01: {name}: a held count input counts once after a set"
            );
        }
    }
    cover!(
        up && down && !set && !i.r && cv == 999,
        "SC-SIMUL-01: both at 999"
    );
    cover!(
        set && i.cu && kind == S5CounterKind::SCu,
        "SC-SET-01: set with CU held"
    );
    cover!(
        fr_rise && st.cu_prev && i.cu,
        "SC-FR-01: FR re-arms a held CU"
    );
    cover!(
        kind == S5CounterKind::SCu && i.cd != st.cd_prev,
        "SC-INPUTS-01: S_CU sees a CD change"
    );
    true
}

/// Exhaustive S5 counter rules: every kind x CV in {0, 1, 2, 500, 997, 998, 999} x every edge
/// memory x every input x PV in {0, 1, 998, 999}. Small scope: the rules compare CV with 0, 1,
/// 998 and 999 and copy PV; the full CV range is in `exhaustive_s5_counters` (equivalence) and
/// Kani's `kani_s5_counter` (every state).
// Uses the cover recorder, which exists outside Kani only (proofs/cover.rs).
#[cfg(not(kani))]
#[test]
fn exhaustive_s5_counter_rules() {
    let n = crate::cover::check_ids(
        &[
            "SC-RANGE-01",
            "SC-PRIO-01",
            "SC-EDGE-01",
            "SC-SAT-01",
            "SC-Q-01",
            "SC-SIMUL-01",
            "SC-SET-01",
            "SC-FR-01",
            "SC-INPUTS-01",
        ],
        || {
            let mut n = 0u32;
            for kind in S5CounterKind::ALL {
                for st in s5_counter_states([0, 1, 2, 500, 997, 998, 999].into_iter()) {
                    for pv in [0, 1, 998, 999] {
                        let pv = CounterPreset::new(pv).expect("<= 999");
                        for i in s5_counter_inputs(pv) {
                            n += u32::from(prop_s5_counter_rules(kind, st, i));
                        }
                    }
                }
            }
            n
        },
    );
    check_eq!(n, 3 * 7 * 16 * 32 * 4);
}

/// The bolero harness of the S5 counters: equivalence and every rule, random under `cargo
/// test`, every state and input under Kani. Symbolic: the kind, the state (CV 0..=999, the CU,
/// CD, S and FR memories, Q), CU, CD, S, PV, R, FR. `#[kani::unwind(6)]`: the box's five STL
/// operations and the exit (the loop over the four implementations is shorter).
#[test]
#[cfg_attr(kani, kani::proof, kani::unwind(6))]
fn kani_s5_counter() {
    crate::cover::harness(
        concat!(module_path!(), "::", stringify!(kani_s5_counter)),
        || {
            bolero::check!()
                .with_type::<(S5CounterKind, S5CounterState, S5CounterInput)>()
                .with_iterations(20_000)
                .for_each(|&(kind, st, i)| {
                    prop_s5_step_equivalence(kind, st, i);
                    prop_s5_counter_rules(kind, st, i);
                    #[cfg(not(kani))]
                    {
                        prop_s5_step_equivalence(kind, s5_at_limit(st), i);
                        prop_s5_counter_rules(kind, s5_at_limit(st), i);
                    }
                });
        },
    );
}

/// The bolero harness of the counter memory's STL operations (SC-STL-01, FR included). Symbolic:
/// the preset (0..=999) and four operations, each one of FR, CU, CD, S, R with its RLO.
/// `#[kani::unwind(5)]`: the four operations and the loop's exit.
#[test]
#[cfg_attr(kani, kani::proof, kani::unwind(5))]
fn kani_stl_operations() {
    crate::cover::harness(
        concat!(module_path!(), "::", stringify!(kani_stl_operations)),
        || {
            bolero::check!()
                .with_type::<(CounterPreset, [(u8, bool); 4])>()
                .with_iterations(20_000)
                .for_each(|&(pv, ops)| {
                    let ops = ops.map(|(k, rlo)| match k % 5 {
                        0 => StlOp::Fr(rlo),
                        1 => StlOp::Cu(rlo),
                        2 => StlOp::Cd(rlo),
                        3 => StlOp::S(rlo),
                        _ => StlOp::R(rlo),
                    });
                    prop_stl_operations(pv, &ops);
                });
        },
    );
}

/// The bolero harness of the array form (CNT-EQUIV-01): 2 counters of each kind, 3 scans.
/// Symbolic: the kind, the CU, CD, R and LD bit masks of each scan (`u64` each; bits 0 and 1
/// are the two counters'), the 2 presets (any `i16`). `#[kani::unwind(17)]`: the 2 counters go
/// through the group code on a padded copy of 16 (loops of 16 iterations and the exit); the 3
/// scans and the check's loop over 2 counters are shorter.
#[test]
#[cfg_attr(kani, kani::proof, kani::unwind(17))]
fn kani_call_array() {
    crate::cover::harness(
        concat!(module_path!(), "::", stringify!(kani_call_array)),
        || {
            bolero::check!()
                .with_type::<(u8, [[u64; 4]; 3], [i16; 2])>()
                .with_iterations(2_000)
                .for_each(|(kind, scans, pv)| {
                    let kind = match kind % 3 {
                        0 => CounterKind::Ctu,
                        1 => CounterKind::Ctd,
                        _ => CounterKind::Ctud,
                    };
                    prop_call_array::<i16, 2>(kind, scans, pv)
                });
        },
    );
}

/// The bolero harness of the CTUD bank (CNT-EQUIV-01): 2 counters, 3 scans. Symbolic: the CU,
/// CD, R and LD bit masks of each scan (`u64` each; bits 0 and 1 are the two counters'), PV (any
/// `i16`). `#[kani::unwind(5)]`: the 4 input words of a scan taken apart (`scan_inputs`) and the
/// exit, the longest; the 3 scans and the bank's and the check's loops over the 2 counters are
/// shorter.
#[test]
#[cfg_attr(kani, kani::proof, kani::unwind(5))]
fn kani_counter_bank() {
    crate::cover::harness(
        concat!(module_path!(), "::", stringify!(kani_counter_bank)),
        || {
            bolero::check!()
                .with_type::<([[u64; 4]; 3], i16)>()
                .with_iterations(2_000)
                .for_each(|(scans, pv)| prop_bank::<i16, 2>(scans, *pv));
        },
    );
}
