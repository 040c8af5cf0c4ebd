//! Errors of the trace machinery, located by line and column.

use std::fmt;
use std::string::String;

/// Where in the input an error was found.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum Location {
    /// Not tied to the file (an unknown block name, a bad `--type`).
    Command,
    /// A command-line option such as `--tv`.
    Option(&'static str),
    /// A line of the CSV file (1-based), the whole line.
    Line(u64),
    /// A cell: 1-based line, 1-based column and the column's name as the header gives it.
    Cell {
        /// The line, 1-based (the header is line 1).
        line: u64,
        /// The column, 1-based.
        column: usize,
        /// The column's name as written in the header.
        name: String,
    },
}

/// An error in a trace or in how the block was asked for: what was wrong and where.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct TraceError {
    /// Where the problem is.
    pub location: Location,
    /// What was wrong and what is allowed.
    pub message: String,
}

impl TraceError {
    pub(crate) fn new(location: Location, message: impl Into<String>) -> TraceError {
        TraceError {
            location,
            message: message.into(),
        }
    }
}

impl fmt::Display for TraceError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match &self.location {
            Location::Command => write!(f, "{}", self.message),
            Location::Option(o) => write!(f, "option --{o}: {}", self.message),
            Location::Line(l) => write!(f, "line {l}: {}", self.message),
            Location::Cell { line, column, name } => {
                write!(f, "line {line}, column {column} ({name}): {}", self.message)
            }
        }
    }
}

impl std::error::Error for TraceError {}
