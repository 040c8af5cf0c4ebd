//! The `plc-timers` command's machinery: CSV traces through the blocks of the `plc-timers`
//! crate (reference or optimized), conformance checks that explain a difference by the
//! requirement that decides it, test vectors, timing diagrams and VCD export. Every block list
//! comes from [`plc_timers::catalog::Block`]; the contract is `spec/cli.md`.

pub mod trace;
