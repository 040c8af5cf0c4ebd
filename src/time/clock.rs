//! The free-running CPU millisecond clock of S7-1200/1500, which wraps (seed 001, "Timer
//! operation": the start value is subtracted from the current value of the internal CPU timer).
//!
//! The arithmetic is generic over the clock's width so that the same code runs on the real
//! 32-bit clock and on 8-bit and 16-bit clocks, which the exhaustive proof drivers enumerate
//! completely (the small-scope argument: every wrap case of the 32-bit clock has the same shape
//! at 8 bits, and the code is the same generic code).

use core::fmt::Debug;

/// An unsigned clock word that counts milliseconds and wraps at `2^BITS`.
pub trait ClockWord: Copy + Eq + Ord + Debug + Default {
    /// The width in bits.
    const BITS: u32;
    /// The largest value before the wrap.
    const MAX: Self;

    /// `self - earlier` modulo `2^BITS`: the time elapsed since `earlier`, correct across one
    /// wrap of the clock.
    fn elapsed_since(self, earlier: Self) -> Self;
    /// `self + d` modulo `2^BITS`.
    fn advance(self, d: Self) -> Self;
    /// A CPU time `t_ms` (milliseconds since start, 64-bit) as this clock shows it: modulo `2^BITS`.
    fn from_u64_wrapping(t_ms: u64) -> Self;
    /// The value as an unsigned 64-bit number.
    fn to_u64(self) -> u64;
    /// A non-negative preset in milliseconds, saturated at [`ClockWord::MAX`] (for the narrow
    /// clocks of the proofs; on the 32-bit clock every non-negative `TIME` fits).
    fn from_preset(millis: u32) -> Self;
}

macro_rules! clock_word {
    ($t:ty) => {
        impl ClockWord for $t {
            const BITS: u32 = <$t>::BITS;
            const MAX: Self = <$t>::MAX;

            #[inline]
            fn elapsed_since(self, earlier: Self) -> Self {
                self.wrapping_sub(earlier)
            }
            #[inline]
            fn advance(self, d: Self) -> Self {
                self.wrapping_add(d)
            }
            #[inline]
            fn from_u64_wrapping(t_ms: u64) -> Self {
                // Truncation is the point: the CPU clock keeps the low BITS bits.
                t_ms as $t
            }
            #[inline]
            fn to_u64(self) -> u64 {
                u64::from(self)
            }
            #[inline]
            fn from_preset(millis: u32) -> Self {
                <$t>::try_from(millis).unwrap_or(<$t>::MAX)
            }
        }
    };
}

clock_word!(u8);
clock_word!(u16);
clock_word!(u32);
