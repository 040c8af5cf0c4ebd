//! Trace adapter of the S5 timers: columns `t_ms`, `S`, `R`, `TV` (+ `FR`, an extension);
//! outputs `Q,BI,BCD`.

use std::boxed::Box;
use std::format;
use std::string::String;
use std::vec::Vec;

use plc_timers::s5::{S5Input, S5Kind, S5Output, S5TimerOps, S5TimerRef, TimerMemory};
use plc_timers::time::CpuTime;
use plc_timers::time::S5Time;
use crate::trace::block::{CellError, Implementation, Input, Row, TraceBlock, Value};
use crate::trace::registry::BlockOptions;

use super::PresetCache;

const INPUTS: &[Input] = &[
    Input::bool("S"),
    Input::bool("R"),
    Input::bool("FR"),
    Input::preset("TV", "tv"),
];
const OUTPUTS: &[&str] = &["Q", "BI", "BCD"];

/// The block called `name` (`S_PULSE` … or the STL alias `SP` …) if it is an S5 timer.
pub(crate) fn lookup(
    name: &str,
    options: &BlockOptions,
) -> Option<Result<Box<dyn TraceBlock>, String>> {
    let kind = S5Kind::ALL
        .into_iter()
        .find(|k| k.name() == name || k.stl() == name)?;
    let timer = match options.implementation {
        Implementation::Reference => Timer::Reference(S5TimerRef::new()),
        Implementation::Optimized => Timer::Optimized(TimerMemory::new()),
    };
    Some(Ok(Box::new(S5Block {
        kind,
        timer,
        tv: PresetCache::new(),
    })))
}

/// Parses a `TV` cell: an S5TIME literal or word.
pub(crate) fn parse_tv(text: &str) -> Result<S5Time, CellError> {
    text.parse::<S5Time>().map_err(|e| CellError {
        input: "TV",
        message: format!("`{text}`: {e}"),
    })
}

enum Timer {
    Reference(S5TimerRef),
    /// A one-timer area: the optimized cell with the OS tick of the area.
    Optimized(TimerMemory<1>),
}

struct S5Block {
    kind: S5Kind,
    timer: Timer,
    tv: PresetCache<S5Time>,
}

impl TraceBlock for S5Block {
    fn name(&self) -> &'static str {
        self.kind.name()
    }

    fn inputs(&self) -> &'static [Input] {
        INPUTS
    }

    fn outputs(&self) -> &'static [&'static str] {
        OUTPUTS
    }

    fn requires_time(&self) -> bool {
        true
    }

    fn step(&mut self, row: &Row<'_>, out: &mut Vec<Value>) -> Result<(), CellError> {
        let text = row.preset("TV").unwrap_or("");
        let tv = self.tv.get(text, parse_tv)?;
        let input = S5Input {
            s: row.bool("S"),
            r: row.bool("R"),
            fr: row.bool("FR"),
            tv,
        };
        let t = CpuTime::from_millis(row.t_ms().unwrap_or(0));
        let output: S5Output = match &mut self.timer {
            Timer::Reference(timer) => timer.call(self.kind, t, input),
            Timer::Optimized(area) => area.call(0, self.kind, t, input).map_err(|e| CellError {
                input: "S",
                message: format!("{e}"),
            })?,
        };
        out.push(Value::Bool(output.q));
        out.push(Value::Int(i128::from(output.bi)));
        out.push(Value::Word(output.bcd));
        Ok(())
    }
}
