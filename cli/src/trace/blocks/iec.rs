//! Trace adapter of the IEC timers: columns `t_ms`, `IN` (+ `R` for TONR), `PT`; outputs `Q,ET`.

use std::boxed::Box;
use std::format;
use std::string::String;
use std::vec::Vec;

use plc_timers::iec::{IecInput, IecKind, IecTimer, IecTimerOps, IecTimerRef};
use plc_timers::time::{CpuTime, Time};
use crate::trace::block::{CellError, Implementation, Input, Row, TraceBlock, Value};
use crate::trace::registry::BlockOptions;

use super::PresetCache;

const INPUTS: &[Input] = &[Input::bool("IN"), Input::preset("PT", "pt")];
const INPUTS_TONR: &[Input] = &[
    Input::bool("IN"),
    Input::bool("R"),
    Input::preset("PT", "pt"),
];
const OUTPUTS: &[&str] = &["Q", "ET"];

/// The block called `name` if it is an IEC timer.
pub(crate) fn lookup(
    name: &str,
    options: &BlockOptions,
) -> Option<Result<Box<dyn TraceBlock>, String>> {
    let kind = IecKind::ALL.into_iter().find(|k| k.name() == name)?;
    Some(Ok(match options.implementation {
        Implementation::Reference => Box::new(IecBlock::<IecTimerRef<u32>>::new(kind)),
        Implementation::Optimized => Box::new(IecBlock::<IecTimer>::new(kind)),
    }))
}

/// Parses a `PT` cell: a TIME literal or whole milliseconds.
pub(crate) fn parse_pt(text: &str) -> Result<Time, CellError> {
    text.parse::<Time>().map_err(|e| CellError {
        input: "PT",
        message: format!("`{text}`: {e}"),
    })
}

struct IecBlock<T> {
    kind: IecKind,
    timer: T,
    pt: PresetCache<Time>,
}

impl<T: IecTimerOps<u32> + Default> IecBlock<T> {
    fn new(kind: IecKind) -> IecBlock<T> {
        IecBlock {
            kind,
            timer: T::default(),
            pt: PresetCache::new(),
        }
    }
}

impl<T: IecTimerOps<u32> + Default> TraceBlock for IecBlock<T> {
    fn name(&self) -> &'static str {
        self.kind.name()
    }

    fn inputs(&self) -> &'static [Input] {
        if self.kind == IecKind::Tonr {
            INPUTS_TONR
        } else {
            INPUTS
        }
    }

    fn outputs(&self) -> &'static [&'static str] {
        OUTPUTS
    }

    fn requires_time(&self) -> bool {
        true
    }

    fn step(&mut self, row: &Row<'_>, out: &mut Vec<Value>) -> Result<(), CellError> {
        let text = row.preset("PT").unwrap_or("");
        let pt = self.pt.get(text, parse_pt)?;
        // The timer sees the S7-1200 millisecond clock, t_ms modulo 2^32 (trace contract).
        let now = CpuTime::from_millis(row.t_ms().unwrap_or(0));
        let input = IecInput {
            input: row.bool("IN"),
            pt,
            reset: row.bool("R"),
        };
        let output = self.timer.call(self.kind, now, input);
        out.push(Value::Bool(output.q));
        out.push(Value::Int(i128::from(output.et)));
        Ok(())
    }
}
