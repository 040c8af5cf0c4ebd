//! Every block as a Python class, reference or optimized (`optimized=True`), written once
//! against the core's block interface: one object-safe trait, `DynBlock`, with a blanket
//! implementation over [`BlockOps`], built by [`Instruction::visit`] (the one table of the
//! families, implementations and data types). A keyword argument names a port of the catalog
//! (`in_` for `IN`), the preset is read by the block's own parser, the outputs come in the
//! catalog's order, a pickle holds the state's members: the classes differ only in their
//! Python signatures and output class. Outputs are small immutable objects with named fields.

use plc_timers::block::{
    Access, BlockOps, Family as _, Fields, Instruction, Outputs, Signals, Value, Visit,
};
use plc_timers::catalog::{Block, DataType, Port, PresetKind, ValueKind};
use plc_timers::counter::s5::S5CounterOutput;
use plc_timers::s5::S5Output;
use plc_timers::time::CpuTime;
use pyo3::exceptions::{PyTypeError, PyValueError};
use pyo3::prelude::*;
use pyo3::types::{PyBool, PyTuple, PyType};

use crate::args;

// ---------------------------------------------------------------------------------------------
// Outputs

/// A small immutable Python class of one block's outputs (frozen, compared, hashed, every field
/// readable), constructible from its fields, picklable, with its constructor call as `repr`
/// (each field written by `$show`: `py_bool`, `decimal` or `hex`); the fields, in order, and
/// their documentation as the invocation gives them.
macro_rules! output_class {
    (
        $(#[doc = $doc:literal])*
        $py:ident = $name:literal, new: $new_doc:literal,
        { $($(#[doc = $fdoc:literal])* $field:ident: $t:ty => $show:ident),+ $(,)? }
    ) => {
        $(#[doc = $doc])*
        #[pyclass(module = "plc_timers", name = $name, frozen, eq, hash, get_all)]
        #[derive(Clone, Copy, PartialEq, Eq, Hash)]
        pub struct $py {
            $($(#[doc = $fdoc])* pub $field: $t,)+
        }

        impl OutputClass for $py {
            const FIELDS: &'static [&'static str] = &[$(stringify!($field)),+];

            fn from_outputs(values: &[Value]) -> Option<Self> {
                let mut values = values.iter().copied();
                let out = $py { $($field: FromValue::from_value(values.next()?)?),+ };
                values.next().is_none().then_some(out)
            }
        }

        #[pymethods]
        impl $py {
            #[doc = $new_doc]
            #[new]
            fn new($($field: $t),+) -> Self {
                $py { $($field),+ }
            }

            /// For pickle and `copy`: the arguments of the constructor.
            fn __getnewargs__(&self) -> ($($t,)+) {
                ($(self.$field,)+)
            }

            fn __repr__(&self) -> String {
                let fields = [$(format!("{}={}", stringify!($field), $show(self.$field))),+];
                format!("{}({})", $name, fields.join(", "))
            }
        }
    };
}

/// A field's type, read from an output's [`Value`].
trait FromValue: Sized {
    fn from_value(v: Value) -> Option<Self>;
}

impl FromValue for bool {
    fn from_value(v: Value) -> Option<bool> {
        v.as_bool()
    }
}

impl FromValue for u16 {
    fn from_value(v: Value) -> Option<u16> {
        match v {
            Value::Word(w) => Some(w),
            v => u16::try_from(v.as_int()?).ok(),
        }
    }
}

impl FromValue for u64 {
    fn from_value(v: Value) -> Option<u64> {
        u64::try_from(v.as_int()?).ok()
    }
}

impl FromValue for i128 {
    fn from_value(v: Value) -> Option<i128> {
        v.as_int()
    }
}

/// An integer field as Python writes it.
fn decimal(v: impl std::fmt::Display) -> String {
    v.to_string()
}

/// A word field in hexadecimal, four digits (BCD words read as their digits).
fn hex(v: u16) -> String {
    format!("0x{v:04X}")
}

output_class! {
    /// The outputs of an S5 timer: Q, BI (the remaining time in units of its base, binary) and
    /// BCD (the remaining time in BCD with the base in bits 13-12, as `LC T n` loads it).
    PyS5Output = "S5Output",
    new: "The outputs Q, BI (0..=999) and BCD (a word) as given, e.g. to compare a call's \
          result with: `out == S5Output(q, bi, bcd)`.",
    {
        /// Q.
        q: bool => py_bool,
        /// BI.
        bi: u16 => decimal,
        /// BCD.
        bcd: u16 => hex,
    }
}

impl From<S5Output> for PyS5Output {
    fn from(o: S5Output) -> Self {
        PyS5Output {
            q: o.q,
            bi: o.bi,
            bcd: o.bcd,
        }
    }
}

output_class! {
    /// The outputs of an IEC timer: Q and ET (in the unit of its clock: ms for TIME, ns for
    /// LTIME).
    PyIecOutput = "IecOutput",
    new: "The outputs Q and ET (ms, or ns for LTIME) as given, e.g. to compare a call's \
          result with: `out == IecOutput(q, et)`.",
    {
        /// Q.
        q: bool => py_bool,
        /// ET in the clock's unit (ms for TIME, ns for LTIME).
        et: u64 => decimal,
    }
}

output_class! {
    /// The outputs of an IEC counter: QU (CV >= PV), QD (CV <= 0) and CV. CTU's Q is `qu`,
    /// CTD's Q is `qd`.
    PyCounterOutput = "CounterOutput",
    new: "The outputs QU, QD and CV as given, e.g. to compare a call's result with: `out == \
          CounterOutput(qu, qd, cv)`.",
    {
        /// QU.
        qu: bool => py_bool,
        /// QD.
        qd: bool => py_bool,
        /// CV.
        cv: i128 => decimal,
    }
}

output_class! {
    /// The outputs of an S5 counter: Q (CV != 0), CV (binary) and CV_BCD.
    PyS5CounterOutput = "S5CounterOutput",
    new: "The outputs Q, CV and CV_BCD as given, e.g. to compare a call's result with: `out \
          == S5CounterOutput(q, cv, cv_bcd)`.",
    {
        /// Q.
        q: bool => py_bool,
        /// CV.
        cv: u16 => decimal,
        /// CV_BCD.
        cv_bcd: u16 => hex,
    }
}

impl From<S5CounterOutput> for PyS5CounterOutput {
    fn from(o: S5CounterOutput) -> Self {
        PyS5CounterOutput {
            q: o.q,
            cv: o.cv,
            cv_bcd: o.cv_bcd,
        }
    }
}

/// `True`/`False` as Python writes them.
pub fn py_bool(b: bool) -> &'static str {
    if b {
        "True"
    } else {
        "False"
    }
}

// ---------------------------------------------------------------------------------------------
// Any block behind one object

/// The block of `block`'s family with the most outputs (CTUD among the IEC counters): an output
/// class carries its outputs, which the output struct of every block of the family holds (CTU's
/// QD too).
fn widest(block: Block) -> Block {
    Block::ALL
        .into_iter()
        .filter(|b| b.family() == block.family())
        .fold(block, |w, b| {
            if b.outputs().len() > w.outputs().len() {
                b
            } else {
                w
            }
        })
}

/// A port's Python keyword: its name lower-cased, `in_` for `IN` (a Python keyword).
fn keyword(port: Port) -> String {
    match port {
        Port::In => "in_".to_string(),
        p => p.name().to_ascii_lowercase(),
    }
}

/// The port a keyword argument names ([`keyword`], compared without building it: once per
/// input of every call).
fn port_of(name: &str) -> Option<Port> {
    Port::ALL.into_iter().find(|&p| match p {
        Port::In => name == "in_",
        p => p.name().eq_ignore_ascii_case(name) && !name.bytes().any(|b| b.is_ascii_uppercase()),
    })
}

/// Any block, data type and implementation behind one object-safe interface (times in whole
/// units of its clock, presets as text of its data type), so that the Python classes are
/// written once. Its one implementation is [`Held`], over every [`BlockOps`].
trait DynBlock: Send + Sync {
    fn clone_box(&self) -> Box<dyn DynBlock>;
    /// Sets (or clears) the block's own preset, read from text by the block's parser.
    fn set_preset(&mut self, text: Option<&str>) -> Result<(), String>;
    /// The block's own preset as its literal, if it has one.
    fn preset(&self) -> Option<String>;
    /// One row at `now` (clock units) with the inputs and coils `signals` and this call's
    /// preset `text`, else the block's own: the outputs of the family's widest box.
    fn call(&mut self, now: u64, signals: Signals, text: Option<&str>) -> Result<Outputs, String>;
    /// An access to the instance data ([`BlockOps::access`]), a preset as text.
    fn access(&mut self, now: u64, access: Access<&str>) -> Result<Option<Value>, String>;
    /// The state's members.
    fn fields(&self) -> Fields;
    /// Puts the block in the state of members `fields`, its previous call at `last_call`;
    /// `false` (and the block unchanged) when no block of its kind can be in it.
    fn restore(&mut self, fields: &[Value], last_call: u64) -> bool;
}

/// A block `B` executing `kind`, with the kind whose outputs the Python output class carries
/// (`wide`, [`widest`]) and its own preset.
struct Held<B: BlockOps> {
    block: B,
    kind: B::Kind,
    wide: B::Kind,
    preset: Option<B::Preset>,
}

impl<B: BlockOps> Held<B> {
    fn parse(text: &str) -> Result<B::Preset, String> {
        B::parse_preset(text).map_err(|e| e.to_string())
    }
}

impl<B: BlockOps> DynBlock for Held<B> {
    fn clone_box(&self) -> Box<dyn DynBlock> {
        Box::new(Held::<B> { ..*self })
    }

    fn set_preset(&mut self, text: Option<&str>) -> Result<(), String> {
        self.preset = text.map(Self::parse).transpose()?;
        Ok(())
    }

    fn preset(&self) -> Option<String> {
        self.preset.map(|p| p.to_string())
    }

    fn call(&mut self, now: u64, signals: Signals, text: Option<&str>) -> Result<Outputs, String> {
        let preset = match (text, self.preset) {
            (Some(text), _) => Self::parse(text)?,
            (None, Some(p)) => p,
            (None, None) => return Err("no preset".to_string()),
        };
        let out = self
            .block
            .step(self.kind, CpuTime::from_ticks(now), signals, preset);
        Ok(B::values(self.wide, &out))
    }

    fn access(&mut self, now: u64, access: Access<&str>) -> Result<Option<Value>, String> {
        let access = match access {
            Access::Read(port) => Access::Read(port),
            Access::Reset => Access::Reset,
            Access::Preset(text) => Access::Preset(Self::parse(text)?),
            Access::RunStopRun(retentive) => Access::RunStopRun(retentive),
        };
        self.block
            .access(CpuTime::from_ticks(now), access)
            .map_err(|e| e.to_string())
    }

    fn fields(&self) -> Fields {
        B::Family::state_fields(&self.block.state())
    }

    fn restore(&mut self, fields: &[Value], last_call: u64) -> bool {
        let block = B::Family::state_from_fields(fields)
            .and_then(|state| B::from_state(state, CpuTime::from_ticks(last_call)));
        if let Some(block) = block {
            self.block = block;
        }
        block.is_some()
    }
}

/// Builds the [`Held`] block of a catalog block for [`Instruction::visit`].
struct Build(Block);

impl Visit for Build {
    type Out = Option<Box<dyn DynBlock>>;
    fn visit<B: BlockOps>(self, block: B, kind: B::Kind) -> Self::Out {
        let wide = B::Family::kind(widest(self.0))?;
        Some(Box::new(Held {
            block,
            kind,
            wide,
            preset: None,
        }))
    }
}

/// The error for a pickled state that no block of this kind can be in.
fn bad_state(block: Block) -> PyErr {
    PyValueError::new_err(format!(
        "not a state of {block}: restore only what pickle saved from a {block}"
    ))
}

/// Rejects a true input that `block` does not have (e.g. CD of CTU): the core would take it as
/// 0, which is not what the caller meant.
fn has_input(block: Block, port: Port, value: bool) -> PyResult<()> {
    if value && !block.has_input(port) {
        let inputs: Vec<&str> = block.inputs().iter().map(|p| p.name()).collect();
        return Err(PyValueError::new_err(format!(
            "{block} has no {} input; its inputs are {}",
            port.name(),
            inputs.join(", ")
        )));
    }
    Ok(())
}

/// The instruction `block` on the data type named `type_name` (ASCII case ignored), or a
/// `ValueError` naming the data types the block takes.
pub(crate) fn instruction(block: Block, type_name: &str) -> PyResult<Instruction> {
    let takes = || {
        let names: Vec<&str> = block.data_types().iter().map(|t| t.name()).collect();
        names.join(" ")
    };
    let data_type = DataType::lookup(type_name.trim()).ok_or_else(|| {
        PyValueError::new_err(format!(
            "unknown data type `{type_name}`; {block} takes {}",
            takes()
        ))
    })?;
    Instruction::new(block, data_type).map_err(|e| PyValueError::new_err(e.to_string()))
}

/// The CPU time of a call as Python gave it: first (`given`), or by the keyword of its unit
/// (`now_ms=`, `now_ns=`); exactly one, that of the block's clock.
struct NowArg<'a, 'py> {
    given: Option<&'a Bound<'py, PyAny>>,
    ms: Option<&'a Bound<'py, PyAny>>,
    ns: Option<&'a Bound<'py, PyAny>>,
}

impl<'a, 'py> NowArg<'a, 'py> {
    /// The time given first (or by the only keyword a block on a clock in ms has).
    fn first(given: &'a Bound<'py, PyAny>) -> Self {
        NowArg {
            given: Some(given),
            ms: None,
            ns: None,
        }
    }
}

/// What pickle saves of a block (`__reduce__`): optimized, its preset (the int its data type's
/// reader takes back, [`args::preset`]), the last `now`, the state's members
/// ([`plc_timers::block::Family::state_fields`]); the data type is an argument of the class when
/// it takes several.
type Pickle<'py> = (
    bool,
    Option<Bound<'py, PyAny>>,
    Option<u64>,
    Vec<Bound<'py, PyAny>>,
);

/// A block of one kind and data type, reference or optimized, as every class holds it.
pub struct BlockCore {
    instruction: Instruction,
    optimized: bool,
    inner: Box<dyn DynBlock>,
    /// The block's own preset as [`args::preset`] read it.
    preset: Option<i128>,
    /// The last `now`, which the next must not precede (timers only).
    last: Option<u64>,
}

impl Clone for BlockCore {
    fn clone(&self) -> Self {
        BlockCore {
            inner: self.inner.clone_box(),
            ..*self
        }
    }
}

impl BlockCore {
    /// `block` on the data type named `type_name` (its default when `None`), with the preset
    /// `preset`, of the implementation `optimized`.
    fn new(
        block: Block,
        preset: Option<&Bound<'_, PyAny>>,
        type_name: Option<&str>,
        optimized: bool,
    ) -> PyResult<BlockCore> {
        let instruction = match type_name {
            None => Instruction::of(block),
            Some(name) => instruction(block, name)?,
        };
        let imp = if optimized {
            plc_timers::block::Implementation::Optimized
        } else {
            plc_timers::block::Implementation::Reference
        };
        let inner = instruction.visit(imp, Build(block)).ok_or_else(|| {
            PyValueError::new_err(format!("{block} is not a block of its family"))
        })?;
        let mut core = BlockCore {
            instruction,
            optimized,
            inner,
            preset: None,
            last: None,
        };
        core.set_preset(preset)?;
        Ok(core)
    }

    fn block(&self) -> Block {
        self.instruction.block()
    }

    /// The preset's keyword (`tv`, `pt`, `pv`).
    fn preset_name(&self) -> String {
        keyword(self.block().preset().port)
    }

    /// A preset from Python as the text of the block's data type, and the int pickle saves.
    fn read_preset(&self, obj: &Bound<'_, PyAny>) -> PyResult<(i128, String)> {
        let t = self.instruction.data_type();
        let v = args::preset(obj, t, &self.preset_name())?;
        Ok((v, args::preset_text(t, v)))
    }

    /// Sets (or clears) the block's own preset.
    fn set_preset(&mut self, obj: Option<&Bound<'_, PyAny>>) -> PyResult<()> {
        let read = obj.map(|o| self.read_preset(o)).transpose()?;
        self.inner
            .set_preset(read.as_ref().map(|(_, text)| text.as_str()))
            .map_err(PyValueError::new_err)?;
        self.preset = read.map(|(v, _)| v);
        Ok(())
    }

    /// The CPU time of a call, given positionally (in the block's unit) or by the keyword of
    /// the block's unit (`now_ms`, `now_ns`), not before the previous call's.
    fn at(&mut self, now: NowArg<'_, '_>) -> PyResult<u64> {
        let unit = self.instruction.clock_unit();
        let keyword = format!("now_{unit}");
        let given = match (now.given, now.ms, now.ns) {
            (Some(t), None, None) => t,
            (None, Some(t), None) if unit == "ms" => t,
            (None, None, Some(t)) if unit == "ns" => t,
            (None, None, None) => {
                return Err(PyTypeError::new_err(format!(
                    "{} needs the CPU time: give it first or as {keyword}= (whole {unit})",
                    self.instruction
                )))
            }
            _ => {
                return Err(PyTypeError::new_err(format!(
                    "{} runs on a clock in {unit}: give the CPU time once, first or as \
                     {keyword}=",
                    self.instruction
                )))
            }
        };
        let now = args::clock(given, unit)?;
        args::forward_in(now, self.last, unit)?;
        self.last = Some(now);
        Ok(now)
    }

    /// One call with the boolean inputs and coils named by their keywords (`inputs`; one the
    /// block lacks must be False), the preset of this call (`preset`) or the block's, at `now`
    /// (`None` for a counter); `needs_preset`: whether this call reads the preset (an S5
    /// counter's only when S sets it; a call without one then runs with 0). Returns the
    /// outputs of the family's widest box.
    fn call(
        &mut self,
        now: Option<NowArg<'_, '_>>,
        inputs: &[(&str, bool)],
        preset: Option<&Bound<'_, PyAny>>,
        needs_preset: bool,
    ) -> PyResult<Outputs> {
        let block = self.block();
        let mut signals = Signals::NONE;
        for &(name, on) in inputs {
            let port = port_of(name)
                .ok_or_else(|| PyTypeError::new_err(format!("{block} has no input `{name}`")))?;
            has_input(block, port, on)?;
            signals = signals.set(port, on);
        }
        let text = match (preset, self.preset) {
            (Some(obj), _) => Some(self.read_preset(obj)?.1),
            (None, Some(_)) => None,
            (None, None) if !needs_preset => Some("0".to_string()),
            (None, None) => {
                let name = self.preset_name();
                return Err(PyValueError::new_err(format!(
                    "{block} needs its {name}: give {name}= to {block}(…) or to call()"
                )));
            }
        };
        let now = match now {
            Some(now) => self.at(now)?,
            None => 0,
        };
        self.inner
            .call(now, signals, text.as_deref())
            .map_err(PyValueError::new_err)
    }

    /// Reads the member `port` of the instance data at `now`.
    fn read(&mut self, now: NowArg<'_, '_>, port: Port) -> PyResult<Value> {
        let now = self.at(now)?;
        match self.inner.access(now, Access::Read(port)) {
            Ok(Some(v)) => Ok(v),
            Ok(None) => Err(PyValueError::new_err(format!(
                "{} has no member {}",
                self.block(),
                port.name()
            ))),
            Err(e) => Err(PyValueError::new_err(e)),
        }
    }

    /// A coil or mode change on the instance data (no time: it reads no clock).
    fn write(&mut self, access: Access<&Bound<'_, PyAny>>) -> PyResult<()> {
        let text;
        let access = match access {
            Access::Preset(obj) => {
                text = self.read_preset(obj)?.1;
                Access::Preset(text.as_str())
            }
            Access::Read(p) => Access::Read(p),
            Access::Reset => Access::Reset,
            Access::RunStopRun(r) => Access::RunStopRun(r),
        };
        // The time of the last call: a coil does not move the clock.
        let now = self.last.unwrap_or(0);
        self.inner
            .access(now, access)
            .map(|_| ())
            .map_err(PyValueError::new_err)
    }

    /// The constructor's arguments for pickle: the data type when the block takes several
    /// (the preset is in the state).
    fn newargs<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyTuple>> {
        if self.block().data_types().len() > 1 {
            let args = (py.None(), self.instruction.data_type().name());
            args.into_pyobject(py)
        } else {
            Ok(PyTuple::empty(py))
        }
    }

    fn getstate<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyTuple>> {
        let mut members = Vec::new();
        for v in self.inner.fields().as_slice() {
            members.push(match *v {
                Value::Bool(b) => PyBool::new(py, b).to_owned().into_any(),
                Value::Int(i) => i.into_pyobject(py)?.into_any(),
                Value::Word(w) => w.into_pyobject(py)?.into_any(),
            });
        }
        let members = PyTuple::new(py, members)?;
        (self.optimized, self.preset, self.last, members).into_pyobject(py)
    }

    fn setstate(&mut self, state: &Bound<'_, PyAny>) -> PyResult<()> {
        let bad = || bad_state(self.block());
        let (optimized, preset, last, members): Pickle<'_> = state.extract().map_err(|_| bad())?;
        let fields = members
            .iter()
            .map(|m| {
                if m.is_instance_of::<PyBool>() {
                    m.extract::<bool>().ok().map(Value::Bool)
                } else {
                    m.extract::<i128>().ok().map(Value::Int)
                }
            })
            .collect::<Option<Vec<Value>>>()
            .ok_or_else(bad)?;
        let mut restored = BlockCore::new(
            self.block(),
            None,
            Some(self.instruction.data_type().name()),
            optimized,
        )?;
        // A preset the data type does not take is no block's.
        restored.set_preset(preset.as_ref()).map_err(|_| bad())?;
        // The core's last call is the last `now`: here time never goes back.
        if !restored.inner.restore(&fields, last.unwrap_or(0)) {
            return Err(bad());
        }
        restored.last = last;
        *self = restored;
        Ok(())
    }

    fn repr(&self) -> String {
        let block = self.block();
        let preset = match self.inner.preset() {
            None => "None".to_string(),
            // An integer preset is written as the int it is.
            Some(p) if block.preset().kind == PresetKind::Integer => p,
            Some(p) => format!("{p:?}"),
        };
        let data_type = self.instruction.data_type();
        let ty = if data_type == block.default_data_type() {
            String::new()
        } else {
            format!(", type={:?}", data_type.name())
        };
        format!(
            "{block}({}={preset}{ty}, optimized={})",
            self.preset_name(),
            py_bool(self.optimized)
        )
    }
}
/// The Python classes of the blocks of one family: each a class around a [`BlockCore`] with the
/// family's Python signatures (the braces: the constructor and the calls, which name the class's
/// catalog block `Self::BLOCK`), and what every block class does the same way, written here
/// once: the implementation it drives, copies, pickle (the class called with `newargs()`, then
/// `getstate()`), `repr`.
macro_rules! block_classes {
    (@class $cls:ident, $block:ident, { $($methods:tt)* }) => {
        impl $cls {
            /// The catalog's block of this class.
            const BLOCK: Block = Block::$block;
        }

        #[pymethods]
        impl $cls {
            $($methods)*

            /// Whether this is the optimized implementation.
            #[getter]
            fn optimized(&self) -> bool {
                self.0.optimized
            }

            /// A copy with the same state: `copy.copy(block)`, `copy.deepcopy(block)` (a
            /// snapshot to go back to).
            fn __copy__(&self) -> Self {
                Self(self.0.clone())
            }

            fn __deepcopy__(&self, _memo: &Bound<'_, PyAny>) -> Self {
                Self(self.0.clone())
            }

            /// For pickle: the class with the arguments that set what the state does not
            /// hold (the data type), then the state (implementation, preset, last time, the
            /// core's state).
            fn __reduce__<'py>(
                slf: &Bound<'py, Self>,
            ) -> PyResult<(Bound<'py, PyType>, Bound<'py, PyTuple>, Bound<'py, PyTuple>)> {
                let py = slf.py();
                let this = slf.borrow();
                Ok((slf.get_type(), this.0.newargs(py)?, this.0.getstate(py)?))
            }

            /// Restores what `__reduce__` saved; a state no block of the kind can be in is a
            /// `ValueError`.
            fn __setstate__(&mut self, state: &Bound<'_, PyAny>) -> PyResult<()> {
                self.0.setstate(state)
            }

            fn __repr__(&self) -> String {
                self.0.repr()
            }
        }
    };
    (
        $family_doc:literal,
        $methods:tt,
        $($cls:ident = $name:literal, $block:ident, $doc:literal;)*
    ) => {$(
        #[doc = $doc]
        ///
        #[doc = $family_doc]
        #[pyclass(module = "plc_timers", name = $name)]
        pub struct $cls(BlockCore);

        block_classes!(@class $cls, $block, $methods);
    )*};
}

// ---------------------------------------------------------------------------------------------
// The classes: their Python signatures

// The boolean keywords of each family's `call`, in the order of its Python signature: the
// boolean inputs of the family's blocks ([`check_keywords`]), named as [`keyword`] names them.
const S5_TIMER_KEYWORDS: [&str; 3] = ["s", "r", "fr"];
const IEC_TIMER_KEYWORDS: [&str; 2] = ["in_", "r"];
const COUNTER_KEYWORDS: [&str; 4] = ["cu", "cd", "r", "ld"];
const S5_COUNTER_KEYWORDS: [&str; 5] = ["cu", "cd", "s", "r", "fr"];

/// The keywords `names` with the values Python gave them.
fn inputs<const N: usize>(
    names: [&'static str; N],
    values: [bool; N],
) -> [(&'static str, bool); N] {
    core::array::from_fn(|i| (names[i], values[i]))
}

/// Whether the keywords `names` are the boolean inputs of the blocks of `block`'s family, as
/// the catalog names them (the coils left out: a class gives them by method, `reset_timer`):
/// checked when the module loads, so that a catalog change a signature does not follow is an
/// `ImportError`.
fn check_keywords(names: &[&str], block: Block) -> PyResult<()> {
    let mut ports: Vec<String> = Block::ALL
        .into_iter()
        .filter(|b| b.family() == block.family())
        .flat_map(|b| b.inputs().iter().copied())
        .filter(|p| p.kind() == ValueKind::Bool)
        .map(keyword)
        .collect();
    ports.sort();
    ports.dedup();
    let mut given: Vec<String> = names.iter().map(|n| n.to_string()).collect();
    given.sort();
    if given != ports {
        return Err(pyo3::exceptions::PyImportError::new_err(format!(
            "the keywords of {}'s family are {given:?}; its blocks' inputs are {ports:?}",
            block
        )));
    }
    Ok(())
}

block_classes! {
    "`tv`: the time value, a literal (`\"S5T#5S\"`, `\"W#16#2050\"`), a word (int) or an \
     `S5Time`; `call()` may give another. `optimized=True` drives the optimized implementation \
     (one 32-bit word) instead of the reference.",
    {
        #[new]
        #[pyo3(signature = (tv = None, *, optimized = false))]
        fn new(tv: Option<&Bound<'_, PyAny>>, optimized: bool) -> PyResult<Self> {
            BlockCore::new(Self::BLOCK, tv, None, optimized).map(Self)
        }

        /// One call at CPU time `now_ms` with the inputs S, R, FR and TV (this call's or
        /// the block's); returns Q, BI and BCD.
        #[pyo3(signature = (now_ms, s = false, r = false, fr = false, tv = None))]
        fn call(
            &mut self,
            now_ms: &Bound<'_, PyAny>,
            s: bool,
            r: bool,
            fr: bool,
            tv: Option<&Bound<'_, PyAny>>,
        ) -> PyResult<PyS5Output> {
            let inputs = inputs(S5_TIMER_KEYWORDS, [s, r, fr]);
            let out = self.0.call(Some(NowArg::first(now_ms)), &inputs, tv, true)?;
            output(out)
        }
    },
    SPulse = "S_PULSE", SPulse, "S_PULSE (STL `SP`): a pulse of TV while S stays 1.";
    SPext = "S_PEXT", SPext, "S_PEXT (STL `SE`): an extended pulse of TV from a rising S.";
    SOdt = "S_ODT", SOdt,
        "S_ODT (STL `SD`): on-delay; Q rises TV after S rose, while S stays 1.\n\n\
         >>> from plc_timers import S_ODT\n\
         >>> t = S_ODT(tv=\"S5T#50MS\")\n\
         >>> t.call(0, s=True)\n\
         S5Output(q=False, bi=5, bcd=0x0005)\n\
         >>> t.call(50, s=True).q\n\
         True";
    SOdts = "S_ODTS", SOdts, "S_ODTS (STL `SS`): retentive on-delay; Q stays 1 until R.";
    SOffdt = "S_OFFDT", SOffdt, "S_OFFDT (STL `SF`): off-delay; Q falls TV after S fell.";
}

block_classes! {
    "`type`: the data type of PT and ET, `\"TIME\"` (default; the clock, PT and ET in \
     milliseconds, the 16-byte IEC_TIMER) or `\"LTIME\"` (S7-1500; in nanoseconds, the 32-byte \
     IEC_LTIMER). `pt`: the preset, a literal (`\"T#500ms\"`, or `\"LT#1ms500us\"` for LTIME), \
     an int in the clock's unit, a `Time` (TIME) or an `LTime` (LTIME); `call()` may give \
     another. `optimized=True` drives the optimized structure instead of the reference.",
    {
        #[new]
        #[pyo3(signature = (pt = None, r#type = "TIME", *, optimized = false))]
        fn new(pt: Option<&Bound<'_, PyAny>>, r#type: &str, optimized: bool) -> PyResult<Self> {
            BlockCore::new(Self::BLOCK, pt, Some(r#type), optimized).map(Self)
        }

        /// One call of the box at CPU time `now` (whole ms for TIME, whole ns for LTIME;
        /// by keyword `now_ms=` or `now_ns=`) with IN (`in_`), R (TONR only) and PT (this
        /// call's or the block's); returns Q and ET (in the clock's unit).
        #[pyo3(signature = (now = None, /, in_ = false, r = false, pt = None, *, now_ms = None, now_ns = None))]
        #[allow(clippy::too_many_arguments)]
        fn call(
            &mut self,
            now: Option<&Bound<'_, PyAny>>,
            in_: bool,
            r: bool,
            pt: Option<&Bound<'_, PyAny>>,
            now_ms: Option<&Bound<'_, PyAny>>,
            now_ns: Option<&Bound<'_, PyAny>>,
        ) -> PyResult<PyIecOutput> {
            let now = NowArg { given: now, ms: now_ms, ns: now_ns };
            let inputs = inputs(IEC_TIMER_KEYWORDS, [in_, r]);
            let out = self.0.call(Some(now), &inputs, pt, true)?;
            output(out)
        }

        /// Reads the structure's Q at `now` (the clock's unit): an update happens first
        /// (IEC-ACCESS-01).
        #[pyo3(signature = (now = None, /, *, now_ms = None, now_ns = None))]
        fn read_q(
            &mut self,
            now: Option<&Bound<'_, PyAny>>,
            now_ms: Option<&Bound<'_, PyAny>>,
            now_ns: Option<&Bound<'_, PyAny>>,
        ) -> PyResult<bool> {
            let now = NowArg { given: now, ms: now_ms, ns: now_ns };
            read_as(self.0.read(now, Port::Q)?)
        }

        /// Reads the structure's ET at `now` (the clock's unit): an update happens first
        /// (IEC-ACCESS-01).
        #[pyo3(signature = (now = None, /, *, now_ms = None, now_ns = None))]
        fn read_et(
            &mut self,
            now: Option<&Bound<'_, PyAny>>,
            now_ms: Option<&Bound<'_, PyAny>>,
            now_ns: Option<&Bound<'_, PyAny>>,
        ) -> PyResult<u64> {
            let now = NowArg { given: now, ms: now_ms, ns: now_ns };
            read_as(self.0.read(now, Port::Et)?)
        }

        /// The `-(RT)-` coil with power flow: resets the timer data (IEC-RT-01).
        fn reset_timer(&mut self) -> PyResult<()> {
            self.0.write(Access::Reset)
        }

        /// The `-(PT)-` coil with power flow: loads `pt` (of the block's data type) into
        /// the structure's preset.
        fn preset_timer(&mut self, pt: &Bound<'_, PyAny>) -> PyResult<()> {
            self.0.write(Access::Preset(pt))
        }

        /// A RUN-STOP-RUN transition: a non-retentive structure returns to its initial
        /// values; a retentive one keeps its data.
        fn run_stop_run(&mut self, retentive: bool) -> PyResult<()> {
            self.0.write(Access::RunStopRun(retentive))
        }

        /// The data type's name (`TIME`, `LTIME`).
        #[getter]
        fn r#type(&self) -> &'static str {
            self.0.instruction.data_type().name()
        }
    },
    Tp = "TP", Tp, "TP: a pulse of PT from a rising IN.";
    Ton = "TON", Ton,
        "TON: on-delay; Q rises when IN has been 1 for PT.\n\n\
         >>> from plc_timers import TON\n\
         >>> t = TON(pt=\"T#500ms\")\n\
         >>> t.call(1000, in_=True)\n\
         IecOutput(q=False, et=0)\n\
         >>> t.call(1500, in_=True)\n\
         IecOutput(q=True, et=500)\n\
         >>> t.reset_timer()  # the RT coil\n\
         >>> t.read_q(1600)\n\
         False\n\
         >>> lt = TON(pt=\"LT#1ms500us\", type=\"LTIME\")  # S7-1500: nanoseconds\n\
         >>> lt.call(0, in_=True).q, lt.call(now_ns=1_500_000, in_=True)\n\
         (False, IecOutput(q=True, et=1500000))";
    Tof = "TOF", Tof, "TOF: off-delay; Q falls PT after IN fell.";
    Tonr = "TONR", Tonr, "TONR: retentive on-delay; ET accumulates while IN is 1, R clears it.";
}

block_classes! {
    "`pv`: the preset (an int of the type); `call()` may give another. `type`: the integer type \
     of PV and CV, one of SINT INT DINT LINT USINT UINT UDINT ULINT (default INT). \
     `optimized=True` drives the optimized implementation.",
    {
        #[new]
        #[pyo3(signature = (pv = None, r#type = "INT", *, optimized = false))]
        fn new(pv: Option<&Bound<'_, PyAny>>, r#type: &str, optimized: bool) -> PyResult<Self> {
            BlockCore::new(Self::BLOCK, pv, Some(r#type), optimized).map(Self)
        }

        /// One call with the inputs the block has (CU, CD, R, LD; an input it lacks must
        /// stay False) and PV (this call's or the block's); returns QU, QD and CV.
        #[pyo3(signature = (cu = false, cd = false, r = false, ld = false, pv = None))]
        fn call(
            &mut self,
            cu: bool,
            cd: bool,
            r: bool,
            ld: bool,
            pv: Option<&Bound<'_, PyAny>>,
        ) -> PyResult<PyCounterOutput> {
            let inputs = inputs(COUNTER_KEYWORDS, [cu, cd, r, ld]);
            output(self.0.call(None, &inputs, pv, true)?)
        }

        /// The integer type's name.
        #[getter]
        fn r#type(&self) -> &'static str {
            self.0.instruction.data_type().name()
        }
    },
    Ctu = "CTU", Ctu,
        "CTU: counts rising edges of CU up to the type's maximum; Q (`qu`) = CV >= PV.\n\n\
         >>> from plc_timers import CTU\n\
         >>> c = CTU(pv=2)\n\
         >>> [c.call(cu=x).cv for x in (True, False, True)]\n\
         [1, 1, 2]\n\
         >>> c.call().qu\n\
         True";
    Ctd = "CTD", Ctd, "CTD: counts rising edges of CD down; LD loads PV; Q (`qd`) = CV <= 0.";
    Ctud = "CTUD", Ctud, "CTUD: counts up (CU) and down (CD); R clears, LD loads PV.";
}

block_classes! {
    "`pv`: the preset that S loads, a literal (`\"C#5\"`), an int 0..=999 or a `CounterPreset`; \
     `call()` may give another. `optimized=True` drives the optimized implementation (one \
     16-bit word).",
    {
        #[new]
        #[pyo3(signature = (pv = None, *, optimized = false))]
        fn new(pv: Option<&Bound<'_, PyAny>>, optimized: bool) -> PyResult<Self> {
            BlockCore::new(Self::BLOCK, pv, None, optimized).map(Self)
        }

        /// One call with CU, CD (those the block has), S, R, FR and PV (this call's or the
        /// block's; needed when S is 1); returns Q, CV and CV_BCD.
        #[pyo3(signature = (cu = false, cd = false, s = false, r = false, fr = false, pv = None))]
        #[allow(clippy::too_many_arguments)]
        fn call(
            &mut self,
            cu: bool,
            cd: bool,
            s: bool,
            r: bool,
            fr: bool,
            pv: Option<&Bound<'_, PyAny>>,
        ) -> PyResult<PyS5CounterOutput> {
            let inputs = inputs(S5_COUNTER_KEYWORDS, [cu, cd, s, r, fr]);
            // PV matters only when S sets the counter.
            output(self.0.call(None, &inputs, pv, s)?)
        }
    },
    SCu = "S_CU", SCu, "S_CU (STL `CU`, `S`, `R`): an up counter 0..=999.";
    SCd = "S_CD", SCd,
        "S_CD (STL `CD`, `S`, `R`): a down counter, loaded with PV by S.\n\n\
         >>> from plc_timers import S_CD\n\
         >>> c = S_CD(pv=\"C#1\")\n\
         >>> c.call(s=True)\n\
         S5CounterOutput(q=True, cv=1, cv_bcd=0x0001)\n\
         >>> c.call(cd=True).q\n\
         False";
    SCud = "S_CUD", SCud, "S_CUD: an up-down counter 0..=999.";
}

/// An output class from the outputs of the family's widest box.
fn output<O: OutputClass>(out: Outputs) -> PyResult<O> {
    O::from_outputs(out.as_slice()).ok_or_else(|| {
        PyValueError::new_err(format!(
            "the outputs {:?} do not fit the fields {:?}",
            out.as_slice(),
            O::FIELDS
        ))
    })
}

/// A member read as the Python type of its method.
fn read_as<T: FromValue>(v: Value) -> PyResult<T> {
    T::from_value(v).ok_or_else(|| PyValueError::new_err(format!("unexpected member {v}")))
}

/// An output class: its fields are the outputs of the family's widest box ([`widest`]), named
/// as the catalog's ports lower-cased.
trait OutputClass: Sized {
    /// The fields in order.
    const FIELDS: &'static [&'static str];
    /// The outputs `values` of the family's widest box, one per field in the catalog's order;
    /// `None` when they are not.
    fn from_outputs(values: &[Value]) -> Option<Self>;
}

/// Whether the fields of `O` are the outputs of the widest box of `block`'s family, as the
/// catalog names them: checked when the module loads, so that a catalog change a class does
/// not follow is an `ImportError`, not a wrong field.
fn check_fields<O: OutputClass>(block: Block) -> PyResult<()> {
    let ports: Vec<String> = widest(block)
        .outputs()
        .iter()
        .map(|&p| keyword(p))
        .collect();
    if ports != O::FIELDS {
        return Err(pyo3::exceptions::PyImportError::new_err(format!(
            "the output class of {block} has the fields {:?}; its family's outputs are {ports:?}",
            O::FIELDS
        )));
    }
    Ok(())
}

/// Adds the classes to the module.
pub fn register(m: &Bound<'_, PyModule>) -> PyResult<()> {
    check_fields::<PyS5Output>(Block::SOdt)?;
    check_fields::<PyIecOutput>(Block::Ton)?;
    check_fields::<PyCounterOutput>(Block::Ctu)?;
    check_fields::<PyS5CounterOutput>(Block::SCu)?;
    check_keywords(&S5_TIMER_KEYWORDS, Block::SOdt)?;
    check_keywords(&IEC_TIMER_KEYWORDS, Block::Ton)?;
    check_keywords(&COUNTER_KEYWORDS, Block::Ctu)?;
    check_keywords(&S5_COUNTER_KEYWORDS, Block::SCu)?;
    m.add_class::<PyS5Output>()?;
    m.add_class::<PyIecOutput>()?;
    m.add_class::<PyCounterOutput>()?;
    m.add_class::<PyS5CounterOutput>()?;
    m.add_class::<SPulse>()?;
    m.add_class::<SPext>()?;
    m.add_class::<SOdt>()?;
    m.add_class::<SOdts>()?;
    m.add_class::<SOffdt>()?;
    m.add_class::<Tp>()?;
    m.add_class::<Ton>()?;
    m.add_class::<Tof>()?;
    m.add_class::<Tonr>()?;
    m.add_class::<Ctu>()?;
    m.add_class::<Ctd>()?;
    m.add_class::<Ctud>()?;
    m.add_class::<SCu>()?;
    m.add_class::<SCd>()?;
    m.add_class::<SCud>()?;
    Ok(())
}
