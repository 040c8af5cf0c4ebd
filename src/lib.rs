//! # plc-timers
//!
//! The executable, formally checked specification of Siemens S7 PLC timers and counters.
//!
//! Every block comes twice: a **reference semantics** written to be read line by line against
//! the manual, and an **optimized implementation** of the kind a soft-PLC would ship (compact
//! state, no allocation, `no_std`). Proofs (Kani harnesses and exhaustive concrete drivers, in
//! `proofs/`) show the two equivalent and check the invariants; `spec/` states every rule with an
//! ID and its source.
//!
//! ## Map
//! - [`time`]: the S5TIME word with its time base and BCD value, and IEC `TIME` (signed 32-bit
//!   milliseconds) with its literals and the wrapping CPU clock.
//! - [`s5`]: the S5 timers of S7-300/400 (`S_PULSE`, `S_PEXT`, `S_ODT`, `S_ODTS`, `S_OFFDT`).
//! - [`iec`]: the IEC timers of S7-1200/1500 (`TP`, `TON`, `TOF`, `TONR`).
//! - [`counter`]: the IEC counters (`CTU`, `CTD`, `CTUD`) and the S5 counters.
//! - `trace` (feature `cli`): CSV traces in, reference outputs out; the `plc-timers` command.
//!
//! ## Time is an input
//! No block reads a clock: every call takes the CPU time it runs at, so every behaviour is
//! deterministic, replayable from a trace, and checkable symbolically.
#![no_std]
#![forbid(unsafe_code)]
#![cfg_attr(docsrs, feature(doc_cfg))]

#[cfg(feature = "std")]
extern crate std;

pub mod counter;
pub mod iec;
pub mod s5;
pub mod time;
#[cfg(feature = "cli")]
pub mod trace;
