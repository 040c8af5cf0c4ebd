//! The trace engine of the `plc-timers` command: CSV traces through the blocks of the
//! `plc-timers` crate (reference or optimized), conformance checks that explain a difference by
//! the requirement that decides it, timing diagrams, VCD export and test vectors. Every block
//! list comes from [`plc_timers::catalog::Block`]; the contract is `spec/cli.md`. The command
//! (package plc-timers-cli), the Python package and the fuzz targets all run this one engine.
//!
//! - [`reader`]: a strict CSV reader that knows each record's line.
//! - [`family`]: a block as the command line asks for it ([`BlockSpec`]: the core's
//!   [`plc_timers::block::Instruction`] and implementation), and the parsers of its names.
//! - [`engine`]: the header resolved against the catalog; [`run`], [`check`], [`observe`];
//!   [`parse_value`] reads one cell as a trace does.
//! - [`diagram`]: timing diagrams (SVG), streamed; `vcd`: VCD export (feature `vcd`).
//! - [`examples`]: the example traces of `examples/traces/`; `vectors`: test vectors (feature
//!   `vectors`).
//! - [`error`]: errors that name the line and column; [`show`] quotes a cell in a message.
//!
//! Both features are on by default; without them the engine needs neither the `vcd` crate nor
//! `fastrand`.

pub mod diagram;
pub mod engine;
pub mod error;
pub mod examples;
pub mod family;
pub mod reader;
#[cfg(feature = "vcd")]
pub mod vcd;
#[cfg(feature = "vectors")]
pub mod vectors;

pub use engine::{
    check, observe, parse_value, preset_option, run, run_explained, CheckReport, Columns,
    ContextRow, Difference, Observation, Observer, Why,
};
pub use error::{show, Error, Location, TraceError};
pub use family::{
    parse_block, parse_data_type, parse_instruction, BlockSpec, Implementation, Outputs, Signals,
    Value,
};
