//! The CPU clock: [`CpuTime`], the time every timer call takes, and [`ClockWord`], the wrapping
//! clock word of the IEC timers.
//!
//! The IEC timers of S7-1200/1500 copy a free-running internal CPU millisecond timer into START
//! and subtract START from it on every update (S7-1200 manual, "Timer operation"); that timer
//! wraps. Their arithmetic is generic over the clock word's width so that the same code runs on
//! the real 32-bit clock and on 4- and 8-bit clocks, which the exhaustive proof drivers enumerate
//! completely (the small-scope argument: every wrap case of the 32-bit clock has the same shape
//! at 8 bits, and the code is the same generic code).

use core::fmt::Debug;
use core::marker::PhantomData;

use super::unit::{Millis, Nanos, TimeUnit};

/// A reading of the CPU's clock in units `U`: units since the CPU started, as one 64-bit count
/// that does not wrap in practice (585 million years in ms, 584 years in ns).
///
/// Every timer API takes the time it runs at as a `CpuTime`, so no block reads a clock and every
/// behaviour is replayable. `CpuTime` alone is `CpuTime<Millis>`: the S5 timers count the ticks
/// of their time base on it (whole multiples of the base), the IEC `TIME` timers see its low 32
/// bits, the wrapping S7-1200 clock ([`CpuTime::clock`]). The S7-1500 long timers (`LTIME`) run
/// on a `CpuTime<Nanos>`: the unit is in the type, so a clock of one unit cannot drive a timer
/// of the other.
///
/// ```
/// use plc_timers::time::{CpuTime, Nanos};
/// let t = CpuTime::from_millis((1 << 32) + 5);
/// assert_eq!(t.clock::<u32>(), 5); // the 32-bit CPU clock has wrapped once
/// assert!(CpuTime::from_millis(10) < t);
/// let n: CpuTime<Nanos> = CpuTime::from_nanos(7);
/// assert_eq!(n.ticks(), 7);
/// ```
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, PartialOrd, Ord, Hash)]
#[repr(transparent)]
pub struct CpuTime<U = Millis>(u64, PhantomData<U>);

#[cfg(kani)]
impl<U: TimeUnit> kani::Arbitrary for CpuTime<U> {
    fn any() -> CpuTime<U> {
        CpuTime::from_ticks(kani::any())
    }
}

/// Any time (feature `bolero`).
#[cfg(feature = "bolero")]
impl<U: TimeUnit> bolero_generator::TypeGenerator for CpuTime<U> {
    fn generate<D: bolero_generator::Driver>(driver: &mut D) -> Option<CpuTime<U>> {
        Some(CpuTime::from_ticks(driver.produce()?))
    }
}

impl<U: TimeUnit> CpuTime<U> {
    /// The CPU's start: 0.
    pub const ZERO: CpuTime<U> = CpuTime(0, PhantomData);

    /// The time `ticks` units after the CPU's start.
    ///
    /// ```
    /// use plc_timers::time::{CpuTime, Millis};
    /// assert_eq!(CpuTime::<Millis>::from_ticks(3), CpuTime::from_millis(3));
    /// ```
    pub const fn from_ticks(ticks: u64) -> CpuTime<U> {
        CpuTime(ticks, PhantomData)
    }

    /// Units since the CPU's start.
    pub const fn ticks(self) -> u64 {
        self.0
    }

    /// `ticks` units later, saturating at the largest time.
    #[must_use]
    pub const fn add_ticks(self, ticks: u64) -> CpuTime<U> {
        CpuTime(self.0.saturating_add(ticks), PhantomData)
    }

    /// This time as a clock word of type `C` shows it: its low `C::BITS` bits.
    pub fn clock<C: ClockWord>(self) -> C {
        C::from_u64_wrapping(self.0)
    }
}

impl CpuTime<Millis> {
    /// The time `millis` milliseconds after the CPU's start.
    ///
    /// ```
    /// use plc_timers::time::CpuTime;
    /// assert_eq!(CpuTime::from_millis(1_500).as_millis(), 1_500);
    /// ```
    pub const fn from_millis(millis: u64) -> CpuTime {
        CpuTime(millis, PhantomData)
    }

    /// Milliseconds since the CPU's start.
    pub const fn as_millis(self) -> u64 {
        self.0
    }

    /// `millis` later, saturating at the largest time.
    #[must_use]
    pub const fn add_millis(self, millis: u64) -> CpuTime {
        self.add_ticks(millis)
    }
}

impl CpuTime<Nanos> {
    /// The time `nanos` nanoseconds after the CPU's start.
    pub const fn from_nanos(nanos: u64) -> CpuTime<Nanos> {
        CpuTime(nanos, PhantomData)
    }

    /// Nanoseconds since the CPU's start.
    pub const fn as_nanos(self) -> u64 {
        self.0
    }
}

impl From<u64> for CpuTime {
    fn from(millis: u64) -> CpuTime {
        CpuTime::from_millis(millis)
    }
}

/// An unsigned clock word that counts milliseconds and wraps at `2^BITS`.
///
/// ```
/// use plc_timers::time::clock::ClockWord;
/// // START just before the 8-bit clock wraps, now just after: 20 ms have passed.
/// assert_eq!(5u8.elapsed_since(241), 20);
/// assert_eq!(u32::from_preset(7), 7);
/// ```
pub trait ClockWord: Copy + Eq + Ord + Debug + Default + Send + Sync + 'static {
    /// The width in bits.
    const BITS: u32;
    /// Zero.
    const ZERO: Self;
    /// The largest value before the wrap.
    const MAX: Self;
    /// The top bit alone, `2^(BITS-1)`: the bias of [`ClockWord::flip_top`].
    const TOP_BIT: Self;

    /// `self - earlier` modulo `2^BITS`: the time elapsed since `earlier`, correct across one
    /// wrap of the clock.
    fn elapsed_since(self, earlier: Self) -> Self;
    /// `self + d` modulo `2^BITS`.
    fn advance(self, d: Self) -> Self;
    /// A CPU time `t_ms` (milliseconds since start, 64-bit) as this clock shows it: modulo `2^BITS`.
    fn from_u64_wrapping(t_ms: u64) -> Self;
    /// The value as an unsigned 64-bit number.
    fn to_u64(self) -> u64;
    /// A non-negative preset in clock units, saturated at [`ClockWord::MAX`] (for the narrow
    /// clocks of the proofs; on the 32-bit clock every non-negative `TIME` fits, on the 64-bit
    /// clock every non-negative `LTIME`).
    fn from_preset(units: u64) -> Self;

    /// `self` with its top bit flipped, which is `self + 2^(BITS-1)` modulo `2^BITS` (the
    /// carry out of the top bit is dropped) and maps the unsigned order onto the signed one:
    /// `a < b` exactly when `a.flip_top().lt_signed(b.flip_top())`. The TON bank keeps its
    /// presets in this form, so that its scan compares as the vector units do, signed.
    #[inline(always)]
    fn flip_top(self) -> Self {
        Self::from_u64_wrapping(self.to_u64() ^ Self::TOP_BIT.to_u64())
    }

    /// `self < other`, both read as `BITS`-bit two's complement numbers.
    #[inline(always)]
    fn lt_signed(self, other: Self) -> bool {
        self.flip_top() < other.flip_top()
    }
}

macro_rules! clock_word {
    ($t:ty, $signed:ty) => {
        impl ClockWord for $t {
            const BITS: u32 = <$t>::BITS;
            const ZERO: Self = 0;
            const MAX: Self = <$t>::MAX;
            const TOP_BIT: Self = 1 << (<$t>::BITS - 1);

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
            fn from_preset(units: u64) -> Self {
                <$t>::try_from(units).unwrap_or(<$t>::MAX)
            }
            #[inline(always)]
            fn flip_top(self) -> Self {
                self ^ Self::TOP_BIT
            }
            #[inline(always)]
            fn lt_signed(self, other: Self) -> bool {
                // The reinterpretation is the point: the same bits, read signed.
                (self as $signed) < (other as $signed)
            }
        }
    };
}

clock_word!(u8, i8);
clock_word!(u16, i16);
clock_word!(u32, i32);
clock_word!(u64, i64);
