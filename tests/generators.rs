//! The value generators of the `bolero` feature span the values they promise. Every property in
//! `proofs/` draws its states and presets from them; a generator that yields nothing, or one
//! value only, would leave those properties run on no case or on one, and passing. Each
//! generator is drawn from 4 000 times on random bytes (SplitMix64, fixed seed): every draw
//! must be a value (bolero drops a case whose generator returns `None`), valid, and together
//! the draws must reach both ends of every range and both values of every flag.

use bolero::generator::bolero_generator::driver::{ByteSliceDriver, Options};
use bolero::generator::TypeGenerator;
use plc_timers::counter::s5::{CounterPreset, S5CounterState};
use plc_timers::iec::IecState;
use plc_timers::s5::S5State;
use plc_timers::time::{S5Time, TimeBase};
use std::collections::BTreeSet;
use std::fmt::Debug;

const DRAWS: usize = 4_000;

/// `DRAWS` values of `T`, each from 64 fresh random bytes.
fn draws<T: TypeGenerator + Debug>() -> Vec<T> {
    let mut seed = 0x5EED_u64;
    let mut next = move || {
        // SplitMix64 (Steele, Lea and Flood 2014).
        seed = seed.wrapping_add(0x9E37_79B9_7F4A_7C15);
        let mut z = seed;
        z = (z ^ (z >> 30)).wrapping_mul(0xBF58_476D_1CE4_E5B9);
        z = (z ^ (z >> 27)).wrapping_mul(0x94D0_49BB_1331_11EB);
        z ^ (z >> 31)
    };
    (0..DRAWS)
        .map(|n| {
            let bytes: Vec<u8> = (0..8).flat_map(|_| next().to_le_bytes()).collect();
            let mut driver = ByteSliceDriver::new(&bytes, &Options::default());
            T::generate(&mut driver).unwrap_or_else(|| {
                panic!(
                    "draw {n}: the generator of {} yielded no value",
                    std::any::type_name::<T>()
                )
            })
        })
        .collect()
}

/// The set of `f` over the draws must be exactly `expected`.
fn spans<T, V: Ord + Debug>(what: &str, values: &[T], f: impl Fn(&T) -> V, expected: &[V]) {
    let seen: BTreeSet<V> = values.iter().map(f).collect();
    for v in expected {
        assert!(
            seen.contains(v),
            "{what}: {v:?} never drawn (seen {} values)",
            seen.len()
        );
    }
}

#[test]
fn s5_time_generator_spans_units_and_bases() {
    let v: Vec<S5Time> = draws();
    assert!(v.iter().all(|t| t.units() <= 999), "S5TIME units above 999");
    spans("S5TIME base", &v, |t| t.base() as u8, &[0, 1, 2, 3]);
    spans("S5TIME units", &v, |t| t.units(), &[0, 999]);
}

#[test]
fn s5_state_generator_spans_valid_states() {
    let v: Vec<S5State> = draws();
    assert!(v.iter().all(S5State::is_valid), "an invalid S5 state drawn");
    spans("value", &v, |s| s.value, &[0, 999]);
    spans("base", &v, |s| s.base, &[TimeBase::Ms10, TimeBase::S10]);
    for (name, f) in [
        ("running", (|s: &S5State| s.running) as fn(&S5State) -> bool),
        ("q", |s| s.q),
        ("q_on_expiry", |s| s.q_on_expiry),
        ("s_prev", |s| s.s_prev),
        ("fr_prev", |s| s.fr_prev),
    ] {
        spans(name, &v, f, &[false, true]);
    }
}

#[test]
fn s5_counter_generators_span_states_and_presets() {
    let v: Vec<S5CounterState> = draws();
    assert!(
        v.iter().all(S5CounterState::is_valid),
        "an invalid S5 counter state drawn"
    );
    spans("CV", &v, |s| s.cv, &[0, 999]);
    for (name, f) in [
        (
            "cu_prev",
            (|s: &S5CounterState| s.cu_prev) as fn(&S5CounterState) -> bool,
        ),
        ("cd_prev", |s| s.cd_prev),
        ("s_prev", |s| s.s_prev),
        ("fr_prev", |s| s.fr_prev),
    ] {
        spans(name, &v, f, &[false, true]);
    }
    let p: Vec<CounterPreset> = draws();
    spans("PV", &p, |p| p.value(), &[0, 999]);
}

#[test]
fn iec_state_generator_spans_valid_states() {
    let v: Vec<IecState<u32>> = draws();
    assert!(
        v.iter().all(IecState::is_valid),
        "an invalid IEC state drawn"
    );
    spans(
        "kind",
        &v,
        |s| s.kind.map(|k| k as u8),
        &[None, Some(0), Some(1), Some(2), Some(3)],
    );
    for (name, f) in [
        (
            "input",
            (|s: &IecState<u32>| s.input) as fn(&IecState<u32>) -> bool,
        ),
        ("running", |s| s.running),
        ("q", |s| s.q),
        ("ET below PT", |s| s.et < s.pt),
        ("START set", |s| s.start != 0),
    ] {
        spans(name, &v, f, &[false, true]);
    }
}
