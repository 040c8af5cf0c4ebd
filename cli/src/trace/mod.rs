//! CSV traces (feature `cli`): the command-line contract of `shared/trace-format.md`.
//!
//! - [`block`]: the [`TraceBlock`] interface each family implements.
//! - [`registry`]: block names, aliases and options.
//! - [`runner`]: [`run`] (reference outputs for a trace) and [`check`] (compare another
//!   implementation's outputs with the reference).
//! - [`error`]: errors that name the line and column.
//! - [`diagram`]: timing diagrams (SVG) of a recorded trace.
//! - [`vectors`]: test vectors with reference outputs for other implementations.

pub mod block;
mod blocks;
pub mod diagram;
pub mod error;
pub mod registry;
pub mod runner;
pub mod vectors;

pub use block::{CellError, Implementation, Input, InputKind, Row, TraceBlock, Value};
pub use error::{Location, TraceError};
pub use registry::{lookup, BlockOptions, BLOCK_NAMES};
pub use runner::{check, record, run, CheckReport, Difference, PresetOption, Recording};
