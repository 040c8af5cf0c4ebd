//! CSV traces through the blocks of the catalog: the contract of `spec/cli.md`.
//!
//! - [`reader`]: a strict CSV reader that knows each record's line.
//! - [`family`]: the generic adapter between a row and a block family, and [`dispatch`].
//! - [`engine`]: the header resolved against the catalog; [`run`], [`check`], [`observe`].
//! - [`diagram`]: timing diagrams (SVG), streamed; [`vcd`]: VCD export.
//! - [`examples`]: the example traces of `examples/traces/`; [`vectors`]: test vectors.
//! - [`error`]: errors that name the line and column.

pub mod diagram;
pub mod engine;
pub mod error;
pub mod examples;
pub mod family;
pub mod reader;
pub mod vcd;
pub mod vectors;

pub use engine::{
    check, observe, run, run_explained, CheckReport, Columns, ContextRow, Difference, Observation,
    Observer, Why,
};
pub use error::{Error, Location, TraceError};
pub use family::{
    dispatch, parse_block, BlockSpec, Implementation, IntType, PresetValue, Signals, Value,
};
