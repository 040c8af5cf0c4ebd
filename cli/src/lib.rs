//! The `plc-timers` command's machinery: CSV traces through the reference semantics of the
//! `plc-timers` crate, checks of other implementations' outputs, test vectors and diagrams.
//! The contract is `spec/cli.md`.

pub mod trace;
