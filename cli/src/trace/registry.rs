//! The blocks a trace can name, and how the command line's options reach them.

use std::boxed::Box;
use std::format;
use std::string::String;

use super::block::{Implementation, TraceBlock};
use super::blocks;
use super::error::{Location, TraceError};

/// Every block name `plc-timers run` accepts (case-insensitive), aliases included.
pub const BLOCK_NAMES: &[&str] = &[
    "S_PULSE", "S_PEXT", "S_ODT", "S_ODTS", "S_OFFDT", "SP", "SE", "SD", "SS", "SF", "TP", "TON",
    "TOF", "TONR", "CTU", "CTD", "CTUD", "S_CU", "S_CD", "S_CUD",
];

/// How the block is to be built: the options that are not presets.
#[derive(Clone, Debug, Default, PartialEq, Eq)]
pub struct BlockOptions {
    /// `--type` of the IEC counters (`SINT INT DINT LINT USINT UINT UDINT ULINT`).
    pub int_type: Option<String>,
    /// Which implementation to drive.
    pub implementation: Implementation,
}

/// The block called `name` (case-insensitive; aliases accepted).
pub fn lookup(name: &str, options: &BlockOptions) -> Result<Box<dyn TraceBlock>, TraceError> {
    let upper = name.to_ascii_uppercase();
    let found = blocks::s5::lookup(&upper, options)
        .or_else(|| blocks::iec::lookup(&upper, options))
        .or_else(|| blocks::counter::lookup(&upper, options));
    let block = match found {
        Some(Ok(block)) => block,
        Some(Err(message)) => return Err(TraceError::new(Location::Option("type"), message)),
        None => {
            return Err(TraceError::new(
                Location::Command,
                format!(
                    "unknown block `{name}`; known blocks: {}",
                    BLOCK_NAMES.join(", ")
                ),
            ))
        }
    };
    if options.int_type.is_some() && !matches!(block.name(), "CTU" | "CTD" | "CTUD") {
        return Err(TraceError::new(
            Location::Option("type"),
            format!(
                "--type applies to CTU, CTD and CTUD only, not to {}",
                block.name()
            ),
        ));
    }
    Ok(block)
}
