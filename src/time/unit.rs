//! Time units in the type, as fugit keeps them: [`Millis`] for `TIME` and the S7-1200 clock,
//! [`Nanos`] for `LTIME` and the S7-1500 long timers.
//!
//! A [`CpuTime<U>`](super::CpuTime) counts units `U` since the CPU started; an IEC duration type
//! ([`IecDuration`]: [`Time`] or [`LTime`]) names its unit and the clock word its timers run
//! on. One IEC timer body serves both: the unit decides what `now`, `PT` and `ET` count, never
//! the arithmetic, so a `TIME` timer cannot be driven by a nanosecond clock by mistake (it does
//! not compile).
//!
//! ```
//! use plc_timers::time::{CpuTime, IecDuration, LTime, Millis, Nanos, Time, TimeUnit};
//! assert_eq!((Millis::SYMBOL, Nanos::SYMBOL), ("ms", "ns"));
//! assert_eq!(<LTime as IecDuration>::units(plc_timers::ltime!("LT#1US")), 1_000);
//! assert_eq!(<Time as IecDuration>::units(plc_timers::time!("T#-5MS")), 0); // negative: 0
//! let now: CpuTime<Nanos> = CpuTime::from_nanos(1_500);
//! assert_eq!(now.ticks(), 1_500);
//! ```

use core::fmt::{Debug, Display};
use core::hash::Hash;
use core::str::FromStr;

use super::clock::ClockWord;
use super::{LTime, LiteralError, Time};

/// A unit of time: what one tick of a [`CpuTime`](super::CpuTime), a preset and an elapsed time
/// count.
pub trait TimeUnit:
    Copy + Clone + Debug + Default + PartialEq + Eq + PartialOrd + Ord + Hash + Send + Sync + 'static
{
    /// The unit's symbol: `ms`, `ns`.
    const SYMBOL: &'static str;
    /// Nanoseconds per unit.
    const NANOS: u64;
}

/// Milliseconds: the unit of `TIME`, of the S5 time bases' ticks and of the S7-1200 clock.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, PartialOrd, Ord, Hash)]
pub struct Millis;

/// Nanoseconds: the unit of `LTIME` and of the clock of the S7-1500 long IEC timers.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, PartialOrd, Ord, Hash)]
pub struct Nanos;

impl TimeUnit for Millis {
    const SYMBOL: &'static str = "ms";
    const NANOS: u64 = 1_000_000;
}

impl TimeUnit for Nanos {
    const SYMBOL: &'static str = "ns";
    const NANOS: u64 = 1;
}

/// An IEC duration data type an IEC timer takes as `PT` and gives as `ET`: [`Time`] (signed
/// 32-bit ms, `IEC_TIMER` on a 32-bit millisecond clock) or [`LTime`] (signed 64-bit ns,
/// `IEC_LTIMER` on a 64-bit nanosecond clock).
pub trait IecDuration:
    Copy
    + Debug
    + Default
    + Display
    + PartialEq
    + Eq
    + Ord
    + Hash
    + Send
    + Sync
    + 'static
    + FromStr<Err = LiteralError>
{
    /// The unit it counts.
    type Unit: TimeUnit;
    /// The CPU clock word the timers of this data type run on (and the type of their START,
    /// PT and ET members): `u32` for `TIME`, `u64` for `LTIME`.
    type Clock: ClockWord;
    /// The data type's name as the manual writes it: `TIME`, `LTIME`.
    const NAME: &'static str;
    /// 0.
    const ZERO: Self;
    /// The largest value.
    const MAX: Self;
    /// The value in units, negative values taken as 0 (IEC-PT-NEG-01).
    fn units(self) -> u64;
    /// The value in units, signed.
    fn units_signed(self) -> i64;
    /// The duration of `units` units, or `None` outside the data type's range.
    fn from_units(units: i128) -> Option<Self>;
}

impl IecDuration for Time {
    type Unit = Millis;
    type Clock = u32;
    const NAME: &'static str = "TIME";
    const ZERO: Time = Time::ZERO;
    const MAX: Time = Time::MAX;

    #[inline(always)]
    fn units(self) -> u64 {
        u64::from(self.clamp_negative())
    }

    fn units_signed(self) -> i64 {
        i64::from(self.as_millis())
    }

    fn from_units(units: i128) -> Option<Time> {
        i64::try_from(units).ok().and_then(Time::from_millis_i64)
    }
}

impl IecDuration for LTime {
    type Unit = Nanos;
    type Clock = u64;
    const NAME: &'static str = "LTIME";
    const ZERO: LTime = LTime::ZERO;
    const MAX: LTime = LTime::MAX;

    #[inline(always)]
    fn units(self) -> u64 {
        self.clamp_negative()
    }

    fn units_signed(self) -> i64 {
        self.as_nanos()
    }

    fn from_units(units: i128) -> Option<LTime> {
        LTime::from_nanos_i128(units)
    }
}
