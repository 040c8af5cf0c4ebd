//! The interface every block family implements to be driven by a trace.

use std::fmt;
use std::string::String;
use std::vec::Vec;

/// What kind of value an input column carries.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum InputKind {
    /// A boolean signal: `0`/`1`, `true`/`false` (any case). An absent column is 0 on every row.
    Bool,
    /// A preset (TV, PT, PV): text the block parses itself. When the column is absent, the value
    /// of the command-line option `--<option>` is used on every row; one of the two is required.
    Preset {
        /// The option's long name without dashes (`tv`, `pt`, `pv`).
        option: &'static str,
    },
}

/// One input column a block reads.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Input {
    /// The canonical (upper-case) column name, e.g. `S`, `TV`, `IN`, `PT`, `CU`.
    pub name: &'static str,
    /// Its kind.
    pub kind: InputKind,
}

impl Input {
    /// A boolean input column.
    pub const fn bool(name: &'static str) -> Input {
        Input {
            name,
            kind: InputKind::Bool,
        }
    }

    /// A preset input column with its command-line option.
    pub const fn preset(name: &'static str, option: &'static str) -> Input {
        Input {
            name,
            kind: InputKind::Preset { option },
        }
    }
}

/// One output value of one execution.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Value {
    /// A boolean output (Q, QU, QD), written `0`/`1`.
    Bool(bool),
    /// An integer output (BI, ET, CV), written in decimal.
    Int(i128),
    /// A 16-bit word (BCD, CV_BCD), written `W#16#XXXX`.
    Word(u16),
}

impl fmt::Display for Value {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match *self {
            Value::Bool(b) => f.write_str(if b { "1" } else { "0" }),
            Value::Int(i) => write!(f, "{i}"),
            Value::Word(w) => write!(f, "W#16#{w:04X}"),
        }
    }
}

/// The inputs of one row, as the runner parsed them.
#[derive(Debug)]
pub struct Row<'a> {
    pub(crate) t_ms: Option<u64>,
    pub(crate) inputs: &'static [Input],
    pub(crate) bools: &'a [bool],
    pub(crate) presets: &'a [Option<&'a str>],
}

impl<'a> Row<'a> {
    /// The row's `t_ms` (milliseconds since CPU start), `None` when the trace has no such column.
    pub fn t_ms(&self) -> Option<u64> {
        self.t_ms
    }

    fn index(&self, name: &str) -> Option<usize> {
        self.inputs.iter().position(|i| i.name == name)
    }

    /// The boolean input `name` (false when absent from the trace or not declared).
    pub fn bool(&self, name: &str) -> bool {
        self.index(name).is_some_and(|i| self.bools[i])
    }

    /// The preset text for `name`: the row's cell, or the command-line option's value.
    pub fn preset(&self, name: &str) -> Option<&'a str> {
        self.index(name).and_then(|i| self.presets[i])
    }
}

/// A block's complaint about one input cell: the runner adds the line and column.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct CellError {
    /// The canonical name of the input whose value was wrong.
    pub input: &'static str,
    /// What was wrong and what is allowed.
    pub message: String,
}

/// Which implementation of a block to drive.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub enum Implementation {
    /// The reference semantics (what `plc-timers run` uses by default).
    #[default]
    Reference,
    /// The optimized implementation, observed through the same interface.
    Optimized,
}

/// A block that a trace can drive: one call of [`TraceBlock::step`] per row.
pub trait TraceBlock {
    /// The block's canonical name (`S_ODT`, `TON`, `CTUD`, …).
    fn name(&self) -> &'static str;
    /// The input columns it reads, `t_ms` excluded.
    fn inputs(&self) -> &'static [Input];
    /// The output column names, in output order.
    fn outputs(&self) -> &'static [&'static str];
    /// Whether the trace must have a `t_ms` column (timers: yes; counters: no).
    fn requires_time(&self) -> bool;
    /// Executes the block once with the row's inputs; pushes one value per output column.
    fn step(&mut self, row: &Row<'_>, out: &mut Vec<Value>) -> Result<(), CellError>;
}
