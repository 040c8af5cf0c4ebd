//! Time formats: the S5TIME word of S7-300/400 and IEC `TIME` of S7-1200/1500.
//!
//! - [`S5Time`] and [`TimeBase`]: the 16-bit word with three BCD digits and a time base
//!   (seed 000 §9.1, seed 003 §7); literals `S5T#…`, `S5TIME#…`, `W#16#…`.
//! - [`Time`]: signed 32-bit milliseconds with `T#…` literals (seed 001).
//! - [`clock`]: the wrapping CPU millisecond clock, generic over its width.
//! - [`LiteralError`]: what was wrong with a literal, and where.

pub mod clock;
mod iec_time;
mod literal;
mod s5time;

pub use iec_time::Time;
pub use literal::{LiteralError, LiteralErrorKind, Unit};
pub use s5time::{bcd3_decode, bcd3_encode, S5Time, S5TimeError, TimeBase};
