//! Trace adapter of the counters: IEC `CTU`/`CTD`/`CTUD` (`--type`) and S5 `S_CU`/`S_CD`/`S_CUD`.

use std::boxed::Box;
use std::format;
use std::string::String;
use std::vec::Vec;

use plc_timers::counter::s5::{
    CounterPreset, S5Counter, S5CounterInput, S5CounterKind, S5CounterOps, S5CounterRef,
};
use plc_timers::counter::{Counter, CounterInput, CounterInt, CounterKind, CounterOps, CounterRef};
use crate::trace::block::{CellError, Implementation, Input, Row, TraceBlock, Value};
use crate::trace::registry::BlockOptions;

use super::PresetCache;

const PV: Input = Input::preset("PV", "pv");
const CTU_INPUTS: &[Input] = &[Input::bool("CU"), Input::bool("R"), PV];
const CTD_INPUTS: &[Input] = &[Input::bool("CD"), Input::bool("LD"), PV];
const CTUD_INPUTS: &[Input] = &[
    Input::bool("CU"),
    Input::bool("CD"),
    Input::bool("R"),
    Input::bool("LD"),
    PV,
];
const S_CU_INPUTS: &[Input] = &[
    Input::bool("CU"),
    Input::bool("S"),
    Input::bool("R"),
    Input::bool("FR"),
    PV,
];
const S_CD_INPUTS: &[Input] = &[
    Input::bool("CD"),
    Input::bool("S"),
    Input::bool("R"),
    Input::bool("FR"),
    PV,
];
const S_CUD_INPUTS: &[Input] = &[
    Input::bool("CU"),
    Input::bool("CD"),
    Input::bool("S"),
    Input::bool("R"),
    Input::bool("FR"),
    PV,
];

/// The integer types of `--type`, by name.
pub(crate) const TYPE_NAMES: &str = "SINT INT DINT LINT USINT UINT UDINT ULINT";

/// The block called `name` if it is a counter; `Err` for a bad `--type`.
pub(crate) fn lookup(
    name: &str,
    options: &BlockOptions,
) -> Option<Result<Box<dyn TraceBlock>, String>> {
    if let Some(kind) = S5CounterKind::ALL.into_iter().find(|k| k.name() == name) {
        return Some(Ok(match options.implementation {
            Implementation::Reference => Box::new(S5CounterBlock {
                kind,
                counter: S5CounterRef::new(),
            }),
            Implementation::Optimized => Box::new(S5CounterBlock {
                kind,
                counter: S5Counter::new(),
            }),
        }));
    }
    let kind = CounterKind::ALL.into_iter().find(|k| k.name() == name)?;
    let ty = options
        .int_type
        .as_deref()
        .unwrap_or("INT")
        .to_ascii_uppercase();
    let opt = options.implementation;
    Some(match ty.as_str() {
        "SINT" => Ok(iec::<i8>(kind, opt)),
        "INT" => Ok(iec::<i16>(kind, opt)),
        "DINT" => Ok(iec::<i32>(kind, opt)),
        "LINT" => Ok(iec::<i64>(kind, opt)),
        "USINT" => Ok(iec::<u8>(kind, opt)),
        "UINT" => Ok(iec::<u16>(kind, opt)),
        "UDINT" => Ok(iec::<u32>(kind, opt)),
        "ULINT" => Ok(iec::<u64>(kind, opt)),
        _ => Err(format!(
            "unknown integer type `{}`; --type takes one of {TYPE_NAMES}",
            options.int_type.as_deref().unwrap_or("")
        )),
    })
}

fn iec<T: CounterInt>(kind: CounterKind, implementation: Implementation) -> Box<dyn TraceBlock> {
    match implementation {
        Implementation::Reference => Box::new(IecCounterBlock {
            kind,
            counter: CounterRef::<T>::new(),
            pv: PresetCache::new(),
        }),
        Implementation::Optimized => Box::new(IecCounterBlock {
            kind,
            counter: Counter::<T>::new(),
            pv: PresetCache::new(),
        }),
    }
}

/// Parses an IEC counter's `PV`: a whole number in the range of `T`.
pub(crate) fn parse_pv<T: CounterInt>(text: &str) -> Result<T, CellError> {
    let error = || CellError {
        input: "PV",
        message: format!(
            "`{text}` is not a valid {} preset; PV is a whole number from {} to {}",
            T::NAME,
            T::MIN.to_i128(),
            T::MAX.to_i128()
        ),
    };
    let value: i128 = text.trim().parse().map_err(|_| error())?;
    T::from_i128(value).ok_or_else(error)
}

struct IecCounterBlock<T, C> {
    kind: CounterKind,
    counter: C,
    pv: PresetCache<T>,
}

impl<T: CounterInt, C: CounterOps<T>> TraceBlock for IecCounterBlock<T, C> {
    fn name(&self) -> &'static str {
        self.kind.name()
    }

    fn inputs(&self) -> &'static [Input] {
        match self.kind {
            CounterKind::Ctu => CTU_INPUTS,
            CounterKind::Ctd => CTD_INPUTS,
            CounterKind::Ctud => CTUD_INPUTS,
        }
    }

    fn outputs(&self) -> &'static [&'static str] {
        match self.kind {
            CounterKind::Ctud => &["QU", "QD", "CV"],
            _ => &["Q", "CV"],
        }
    }

    fn requires_time(&self) -> bool {
        false
    }

    fn step(&mut self, row: &Row<'_>, out: &mut Vec<Value>) -> Result<(), CellError> {
        let text = row.preset("PV").unwrap_or("");
        let pv = self.pv.get(text, parse_pv::<T>)?;
        let input = CounterInput {
            cu: row.bool("CU"),
            cd: row.bool("CD"),
            r: row.bool("R"),
            ld: row.bool("LD"),
            pv,
        };
        let o = self.counter.call(self.kind, input);
        match self.kind {
            CounterKind::Ctu => out.push(Value::Bool(o.qu)),
            CounterKind::Ctd => out.push(Value::Bool(o.qd)),
            CounterKind::Ctud => {
                out.push(Value::Bool(o.qu));
                out.push(Value::Bool(o.qd));
            }
        }
        out.push(Value::Int(o.cv.to_i128()));
        Ok(())
    }
}

struct S5CounterBlock<C> {
    kind: S5CounterKind,
    counter: C,
}

impl<C: S5CounterOps> TraceBlock for S5CounterBlock<C> {
    fn name(&self) -> &'static str {
        self.kind.name()
    }

    fn inputs(&self) -> &'static [Input] {
        match self.kind {
            S5CounterKind::SCu => S_CU_INPUTS,
            S5CounterKind::SCd => S_CD_INPUTS,
            S5CounterKind::SCud => S_CUD_INPUTS,
        }
    }

    fn outputs(&self) -> &'static [&'static str] {
        &["Q", "CV", "CV_BCD"]
    }

    fn requires_time(&self) -> bool {
        false
    }

    fn step(&mut self, row: &Row<'_>, out: &mut Vec<Value>) -> Result<(), CellError> {
        let text = row.preset("PV").unwrap_or("");
        let pv: CounterPreset = text.parse().map_err(|e| CellError {
            input: "PV",
            message: format!("`{text}`: {e}"),
        })?;
        let input = S5CounterInput {
            cu: row.bool("CU"),
            cd: row.bool("CD"),
            s: row.bool("S"),
            r: row.bool("R"),
            fr: row.bool("FR"),
            pv,
        };
        let o = self.counter.call(self.kind, input);
        out.push(Value::Bool(o.q));
        out.push(Value::Int(i128::from(o.cv)));
        out.push(Value::Word(o.cv_bcd));
        Ok(())
    }
}
