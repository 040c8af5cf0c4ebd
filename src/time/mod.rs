//! Time formats: the S5TIME word of S7-300/400, IEC `TIME` of S7-1200/1500, and the CPU clock.
//!
//! - [`S5Time`] and [`TimeBase`]: the 16-bit word with three BCD digits and a time base
//!   (LAD manual §9.1; Berger §7); literals `S5T#…`, `S5TIME#…`, `W#16#…`.
//! - [`Time`]: signed 32-bit milliseconds with `T#…` literals (S7-1200 manual, TIME data type).
//! - [`LTime`]: signed 64-bit nanoseconds with `LT#…` literals (S7-1500, LTIME data type).
//! - [`CpuTime`]: the CPU's clock, the one time argument every timer takes, its unit in its
//!   type ([`mod@unit`]: [`Millis`], [`Nanos`]);
//!   [`clock::ClockWord`]: the wrapping clock word the IEC timers compute with.
//! - [`LiteralError`]: what was wrong with a literal, and where.
//!
//! The literal parsers are `const fn`, so a constant can be written as a literal and checked at
//! compile time:
//!
//! ```
//! use plc_timers::time::{S5Time, Time};
//! const TV: S5Time = plc_timers::s5time!("S5T#2M7S");
//! const PT: Time = plc_timers::time!("T#2s_200ms");
//! assert_eq!(TV.to_word(), 0x2127);
//! assert_eq!(PT.as_millis(), 2_200);
//! ```

mod bcd;
pub mod clock;
mod iec_time;
mod literal;
mod ltime;
mod s5time;
pub mod unit;

pub(crate) use bcd::BCD3_TABLE;
pub use bcd::{bcd3_decode, bcd3_encode};
pub use clock::CpuTime;
pub use iec_time::Time;
pub(crate) use literal::has_prefix_ci;
pub use literal::{LiteralError, LiteralErrorKind, LiteralType, Unit};
pub use ltime::LTime;
pub use s5time::{S5Time, S5TimeError, TimeBase};
pub use unit::{IecDuration, Millis, Nanos, TimeUnit};

/// An [`S5Time`] constant from a literal, checked at compile time: a malformed literal, a BCD
/// digit above 9 or a value above 9 990 s does not compile.
///
/// ```
/// use plc_timers::s5time;
/// assert_eq!(s5time!("W#16#2127"), s5time!("S5T#2M7S"));
/// ```
///
/// ```compile_fail
/// let too_long = plc_timers::s5time!("S5T#3H"); // above 9 990 s
/// ```
#[macro_export]
macro_rules! s5time {
    ($literal:literal) => {{
        const VALUE: $crate::time::S5Time = match $crate::time::S5Time::parse($literal) {
            Ok(t) => t,
            Err(_) => panic!(concat!("not a valid S5TIME literal: ", $literal)),
        };
        VALUE
    }};
}

/// A [`Time`] constant from a literal, checked at compile time.
///
/// ```
/// assert_eq!(plc_timers::time!("T#1M_30S").as_millis(), 90_000);
/// ```
///
/// ```compile_fail
/// let too_long = plc_timers::time!("T#25D"); // above T#24D_20H_31M_23S_647MS
/// ```
#[macro_export]
macro_rules! time {
    ($literal:literal) => {{
        const VALUE: $crate::time::Time = match $crate::time::Time::parse($literal) {
            Ok(t) => t,
            Err(_) => panic!(concat!("not a valid TIME literal: ", $literal)),
        };
        VALUE
    }};
}

/// An [`LTime`] constant from a literal, checked at compile time.
///
/// ```
/// assert_eq!(plc_timers::ltime!("LT#1MS_500US").as_nanos(), 1_500_000);
/// ```
///
/// ```compile_fail
/// let too_long = plc_timers::ltime!("LT#106752D"); // above LT#106751D_23H_47M_16S_854MS_775US_807NS
/// ```
#[macro_export]
macro_rules! ltime {
    ($literal:literal) => {{
        const VALUE: $crate::time::LTime = match $crate::time::LTime::parse($literal) {
            Ok(t) => t,
            Err(_) => panic!(concat!("not a valid LTIME literal: ", $literal)),
        };
        VALUE
    }};
}
