//! A stand-in for the documented API of the [Kani](https://model-checking.github.io/kani/) model
//! checker's `kani` crate: enough of it that code under `cfg(kani)` (the harnesses in `proofs/`,
//! the `kani::Arbitrary` impls of the library, bolero's Kani engine) compiles without Kani.
//!
//! **It proves nothing.** `cargo kani` compiles the same code with the real crate and checks the
//! harnesses symbolically; here [`any`] draws a pseudo-random value, [`assume`] panics when its
//! condition is false, [`cover!`] only evaluates its condition, and the attributes keep the item
//! unchanged (after checking their arguments). `.ci/run` builds the test targets with
//! `--cfg kani` against this crate, so that a harness that would not compile under `cargo kani`
//! fails CI. See README.md.

use std::cell::Cell;

pub use kani_macros::{
    ensures, modifies, proof, proof_for_contract, recursion, requires, should_panic, solver, stub,
    stub_verified, unwind, Arbitrary,
};

thread_local! {
    // xorshift64 state: the stand-in's values are reproducible per thread.
    static STATE: Cell<u64> = const { Cell::new(0x9E37_79B9_7F4A_7C15) };
}

/// The next 64 pseudo-random bits of this thread.
fn next_bits() -> u64 {
    STATE.with(|s| {
        let mut x = s.get();
        x ^= x << 13;
        x ^= x >> 7;
        x ^= x << 17;
        s.set(x);
        x
    })
}

/// A value of a type Kani can make symbolic.
pub trait Arbitrary
where
    Self: Sized,
{
    /// Any value of the type (under Kani a symbolic one; here a pseudo-random one).
    fn any() -> Self;

    /// An array of any values.
    fn any_array<const MAX_ARRAY_LENGTH: usize>() -> [Self; MAX_ARRAY_LENGTH] {
        core::array::from_fn(|_| Self::any())
    }
}

/// Any value of `T` (under Kani a symbolic one; here a pseudo-random one).
pub fn any<T: Arbitrary>() -> T {
    T::any()
}

/// Any value of `T` that satisfies `constraint` (here: a pseudo-random value, and a panic from
/// [`assume`] when it does not satisfy it).
pub fn any_where<T: Arbitrary, F: FnOnce(&T) -> bool>(constraint: F) -> T {
    let v = T::any();
    assume(constraint(&v));
    v
}

/// Restricts the paths Kani explores to those where `cond` holds. The stand-in cannot restrict
/// anything: it panics when `cond` is false, so a caller that runs a harness body on
/// pseudo-random values must treat that panic as "input outside the harness's domain".
#[track_caller]
pub fn assume(cond: bool) {
    if !cond {
        panic!("kani stand-in: assumption does not hold for this value");
    }
}

/// Kani's `assert`: `cond` must hold on every path.
#[track_caller]
pub fn assert(cond: bool, msg: &'static str) {
    if !cond {
        panic!("{msg}");
    }
}

/// The function behind [`cover!`]: Kani reports whether `cond` can be true; the stand-in only
/// evaluates it.
#[doc(hidden)]
pub fn cover(cond: bool, msg: &'static str) {
    let _ = (cond, msg);
}

/// Kani's `cover!`: states that some path reaches this point with the condition true. Kani
/// reports each cover as satisfied, unsatisfiable or unreachable; the stand-in only evaluates the
/// condition.
#[macro_export]
macro_rules! cover {
    () => {
        $crate::cover(true, "cover location")
    };
    ($cond:expr $(,)?) => {
        $crate::cover($cond, ::core::stringify!($cond))
    };
    ($cond:expr, $msg:literal $(,)?) => {
        $crate::cover($cond, $msg)
    };
}

macro_rules! from_bits {
    ($($t:ty),*) => {$(
        impl Arbitrary for $t {
            fn any() -> Self {
                // Truncation keeps the low bits of the 64 (for 128 bits: two draws).
                (((next_bits() as u128) << 64) | next_bits() as u128) as $t
            }
        }
    )*};
}
from_bits!(u8, u16, u32, u64, u128, usize, i8, i16, i32, i64, i128, isize);

macro_rules! non_zero {
    ($($t:ident: $p:ty),*) => {$(
        impl Arbitrary for core::num::$t {
            fn any() -> Self {
                any_where::<$p, _>(|v| *v != 0).try_into().expect("checked to be non-zero")
            }
        }
    )*};
}
non_zero!(NonZeroU8: u8, NonZeroU16: u16, NonZeroU32: u32, NonZeroU64: u64, NonZeroU128: u128,
    NonZeroUsize: usize, NonZeroI8: i8, NonZeroI16: i16, NonZeroI32: i32, NonZeroI64: i64,
    NonZeroI128: i128, NonZeroIsize: isize);

impl Arbitrary for bool {
    fn any() -> Self {
        next_bits() & 1 == 1
    }
}

impl Arbitrary for char {
    fn any() -> Self {
        // A Unicode scalar value: Kani assumes the same ranges.
        char::from_u32(any_where::<u32, _>(|c| char::from_u32(*c).is_some()))
            .expect("checked to be a char")
    }
}

impl Arbitrary for f32 {
    fn any() -> Self {
        f32::from_bits(any())
    }
}

impl Arbitrary for f64 {
    fn any() -> Self {
        f64::from_bits(any())
    }
}

impl Arbitrary for () {
    fn any() -> Self {}
}

impl<T: ?Sized> Arbitrary for core::marker::PhantomData<T> {
    fn any() -> Self {
        core::marker::PhantomData
    }
}

impl<T: Arbitrary, const N: usize> Arbitrary for [T; N] {
    fn any() -> Self {
        T::any_array()
    }
}

impl<T: Arbitrary> Arbitrary for Option<T> {
    fn any() -> Self {
        if any() {
            Some(any())
        } else {
            None
        }
    }
}

impl<T: Arbitrary, E: Arbitrary> Arbitrary for Result<T, E> {
    fn any() -> Self {
        if any() {
            Ok(any())
        } else {
            Err(any())
        }
    }
}

macro_rules! tuples {
    ($(($($t:ident),+)),*) => {$(
        impl<$($t: Arbitrary),+> Arbitrary for ($($t,)+) {
            fn any() -> Self {
                ($($t::any(),)+)
            }
        }
    )*};
}
tuples!(
    (A),
    (A, B),
    (A, B, C),
    (A, B, C, D),
    (A, B, C, D, E),
    (A, B, C, D, E, F)
);
