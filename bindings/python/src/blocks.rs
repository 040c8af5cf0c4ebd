//! Every block as a Python class, reference or optimized (`optimized=True`), driven through the
//! core's interface traits, so that both implementations are called by the same code. Outputs
//! are small immutable objects with named fields.

use std::marker::PhantomData;

use crate::int_type::IntType;
use plc_timers::catalog::{Block, Kind, Port};
use plc_timers::counter::s5::{
    CounterPreset, S5Counter, S5CounterInput, S5CounterKind, S5CounterOps, S5CounterOutput,
    S5CounterRef, S5CounterState,
};
use plc_timers::counter::{
    Counter, CounterInput, CounterInt, CounterKind, CounterOps, CounterOutput, CounterRef,
    CounterState,
};
use plc_timers::iec::{IecInput, IecKind, IecOutput, IecState, IecTimer, IecTimerOps, IecTimerRef};
use plc_timers::s5::{S5Input, S5Kind, S5Output, S5State, S5Timer, S5TimerOps, S5TimerRef};
use plc_timers::time::{CpuTime, S5Time, Time, TimeBase};
use plc_timers_trace::preset_option;
use pyo3::exceptions::PyValueError;
use pyo3::prelude::*;
use pyo3::types::PyType;

use crate::args::{self, forward, now_ms};

// ---------------------------------------------------------------------------------------------
// Outputs

/// The outputs of an S5 timer: Q, BI (the remaining time in units of its base, binary) and BCD
/// (the remaining time in BCD with the base in bits 13-12, as `LC T n` loads it).
#[pyclass(module = "plc_timers", name = "S5Output", frozen, eq, hash, get_all)]
#[derive(Clone, Copy, PartialEq, Eq, Hash)]
pub struct PyS5Output {
    /// Q.
    pub q: bool,
    /// BI.
    pub bi: u16,
    /// BCD.
    pub bcd: u16,
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

#[pymethods]
impl PyS5Output {
    /// The outputs Q, BI (0..=999) and BCD (a word) as given, e.g. to compare a call's result with: `out ==
    /// S5Output(q, bi, bcd)`.
    #[new]
    #[pyo3(signature = (q, bi, bcd))]
    fn new(q: bool, bi: u16, bcd: u16) -> Self {
        PyS5Output { q, bi, bcd }
    }

    /// For pickle and `copy`: the arguments of the constructor.
    fn __getnewargs__(&self) -> (bool, u16, u16) {
        (self.q, self.bi, self.bcd)
    }

    fn __repr__(&self) -> String {
        format!(
            "S5Output(q={}, bi={}, bcd=0x{:04X})",
            py_bool(self.q),
            self.bi,
            self.bcd
        )
    }
}

/// The outputs of an IEC timer: Q and ET (ms).
#[pyclass(module = "plc_timers", name = "IecOutput", frozen, eq, hash, get_all)]
#[derive(Clone, Copy, PartialEq, Eq, Hash)]
pub struct PyIecOutput {
    /// Q.
    pub q: bool,
    /// ET in milliseconds.
    pub et: u32,
}

impl From<IecOutput<u32>> for PyIecOutput {
    fn from(o: IecOutput<u32>) -> Self {
        PyIecOutput { q: o.q, et: o.et }
    }
}

#[pymethods]
impl PyIecOutput {
    /// The outputs Q and ET (ms) as given, e.g. to compare a call's result with: `out ==
    /// IecOutput(q, et)`.
    #[new]
    #[pyo3(signature = (q, et))]
    fn new(q: bool, et: u32) -> Self {
        PyIecOutput { q, et }
    }

    /// For pickle and `copy`: the arguments of the constructor.
    fn __getnewargs__(&self) -> (bool, u32) {
        (self.q, self.et)
    }

    fn __repr__(&self) -> String {
        format!("IecOutput(q={}, et={})", py_bool(self.q), self.et)
    }
}

/// The outputs of an IEC counter: QU (CV >= PV), QD (CV <= 0) and CV. CTU's Q is `qu`, CTD's Q
/// is `qd`.
#[pyclass(
    module = "plc_timers",
    name = "CounterOutput",
    frozen,
    eq,
    hash,
    get_all
)]
#[derive(Clone, Copy, PartialEq, Eq, Hash)]
pub struct PyCounterOutput {
    /// QU.
    pub qu: bool,
    /// QD.
    pub qd: bool,
    /// CV.
    pub cv: i128,
}

#[pymethods]
impl PyCounterOutput {
    /// The outputs QU, QD and CV as given, e.g. to compare a call's result with: `out ==
    /// CounterOutput(qu, qd, cv)`.
    #[new]
    #[pyo3(signature = (qu, qd, cv))]
    fn new(qu: bool, qd: bool, cv: i128) -> Self {
        PyCounterOutput { qu, qd, cv }
    }

    /// For pickle and `copy`: the arguments of the constructor.
    fn __getnewargs__(&self) -> (bool, bool, i128) {
        (self.qu, self.qd, self.cv)
    }

    fn __repr__(&self) -> String {
        format!(
            "CounterOutput(qu={}, qd={}, cv={})",
            py_bool(self.qu),
            py_bool(self.qd),
            self.cv
        )
    }
}

/// The outputs of an S5 counter: Q (CV != 0), CV (binary) and CV_BCD.
#[pyclass(
    module = "plc_timers",
    name = "S5CounterOutput",
    frozen,
    eq,
    hash,
    get_all
)]
#[derive(Clone, Copy, PartialEq, Eq, Hash)]
pub struct PyS5CounterOutput {
    /// Q.
    pub q: bool,
    /// CV.
    pub cv: u16,
    /// CV_BCD.
    pub cv_bcd: u16,
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

#[pymethods]
impl PyS5CounterOutput {
    /// The outputs Q, CV and CV_BCD as given, e.g. to compare a call's result with: `out ==
    /// S5CounterOutput(q, cv, cv_bcd)`.
    #[new]
    #[pyo3(signature = (q, cv, cv_bcd))]
    fn new(q: bool, cv: u16, cv_bcd: u16) -> Self {
        PyS5CounterOutput { q, cv, cv_bcd }
    }

    /// For pickle and `copy`: the arguments of the constructor.
    fn __getnewargs__(&self) -> (bool, u16, u16) {
        (self.q, self.cv, self.cv_bcd)
    }

    fn __repr__(&self) -> String {
        format!(
            "S5CounterOutput(q={}, cv={}, cv_bcd=0x{:04X})",
            py_bool(self.q),
            self.cv,
            self.cv_bcd
        )
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

/// The preset of a call: the call's own, else the block's, else an error naming both places.
fn preset<T: Copy>(
    block: Block,
    given: Option<&Bound<'_, PyAny>>,
    default: Option<T>,
    read: impl FnOnce(&Bound<'_, PyAny>, &str) -> PyResult<T>,
) -> PyResult<T> {
    let name = preset_option(block);
    match (given, default) {
        (Some(obj), _) => read(obj, name),
        (None, Some(v)) => Ok(v),
        (None, None) => Err(PyValueError::new_err(format!(
            "{block} needs its {name}: give {name}= to {block}(…) or to call()"
        ))),
    }
}

// ---------------------------------------------------------------------------------------------
// S5 timers

/// An S5 timer of either implementation, copyable behind the interface.
trait S5Dyn: S5TimerOps + Send + Sync {
    fn clone_box(&self) -> Box<dyn S5Dyn>;
    /// The time of the previous execution (the ticks of the next call count from it).
    fn last_call(&self) -> CpuTime;
}

impl S5Dyn for S5TimerRef {
    fn clone_box(&self) -> Box<dyn S5Dyn> {
        Box::new(*self)
    }
    fn last_call(&self) -> CpuTime {
        S5TimerRef::last_call(self)
    }
}

impl S5Dyn for S5Timer {
    fn clone_box(&self) -> Box<dyn S5Dyn> {
        Box::new(*self)
    }
    fn last_call(&self) -> CpuTime {
        S5Timer::last_call(self)
    }
}

/// The state pickle saves for an S5 timer: optimized, TV (word), the last `now_ms`, the last
/// call of the core, then the [`S5State`]'s fields (the base in ms).
type S5TimerPickle = (
    bool,
    Option<u16>,
    Option<u64>,
    u64,
    (bool, u16, u32, bool, bool, bool, bool),
);

/// An S5 timer of one kind, reference or optimized.
pub struct S5Block {
    block: Block,
    kind: S5Kind,
    timer: Box<dyn S5Dyn>,
    optimized: bool,
    tv: Option<S5Time>,
    last: Option<CpuTime>,
}

impl Clone for S5Block {
    fn clone(&self) -> Self {
        S5Block {
            timer: self.timer.clone_box(),
            ..*self
        }
    }
}

impl S5Block {
    fn new(block: Block, tv: Option<&Bound<'_, PyAny>>, optimized: bool) -> PyResult<S5Block> {
        let Kind::S5Timer(kind) = block.kind() else {
            return Err(PyValueError::new_err(format!("{block} is not an S5 timer")));
        };
        let tv = tv.map(|t| args::s5time(t, "tv")).transpose()?;
        let timer: Box<dyn S5Dyn> = if optimized {
            Box::new(S5Timer::new())
        } else {
            Box::new(S5TimerRef::new())
        };
        Ok(S5Block {
            block,
            kind,
            timer,
            optimized,
            tv,
            last: None,
        })
    }

    fn call(
        &mut self,
        now: &Bound<'_, PyAny>,
        s: bool,
        r: bool,
        fr: bool,
        tv: Option<&Bound<'_, PyAny>>,
    ) -> PyResult<PyS5Output> {
        let now = now_ms(now)?;
        forward(now, self.last)?;
        let tv = preset(self.block, tv, self.tv, args::s5time)?;
        self.last = Some(now);
        let input = S5Input::new(s, r, tv).with_fr(fr);
        Ok(self.timer.call(self.kind, now, input).into())
    }

    fn getstate(&self) -> S5TimerPickle {
        let st = self.timer.state();
        (
            self.optimized,
            self.tv.map(S5Time::to_word),
            self.last.map(CpuTime::as_millis),
            self.timer.last_call().as_millis(),
            (
                st.running,
                st.value,
                st.base.millis(),
                st.q,
                st.q_on_expiry,
                st.s_prev,
                st.fr_prev,
            ),
        )
    }

    fn setstate(&mut self, state: &Bound<'_, PyAny>) -> PyResult<()> {
        let (optimized, tv, last, last_call, fields): S5TimerPickle =
            state.extract().map_err(|_| bad_state(self.block))?;
        let (running, value, base_ms, q, q_on_expiry, s_prev, fr_prev) = fields;
        let base = TimeBase::ALL
            .into_iter()
            .find(|b| b.millis() == base_ms)
            .ok_or_else(|| bad_state(self.block))?;
        let st = S5State {
            running,
            value,
            base,
            q,
            q_on_expiry,
            s_prev,
            fr_prev,
        };
        let last_call = CpuTime::from_millis(last_call);
        let timer: Box<dyn S5Dyn> = if optimized {
            Box::new(S5Timer::from_state(st, last_call).ok_or_else(|| bad_state(self.block))?)
        } else {
            Box::new(S5TimerRef::from_state(st, last_call).ok_or_else(|| bad_state(self.block))?)
        };
        let tv = tv
            .map(|w| S5Time::from_word(w).map_err(|_| bad_state(self.block)))
            .transpose()?;
        *self = S5Block {
            timer,
            optimized,
            tv,
            last: last.map(CpuTime::from_millis),
            ..*self
        };
        Ok(())
    }

    fn repr(&self) -> String {
        let tv = self
            .tv
            .map_or("None".to_string(), |t| format!("{:?}", t.to_string()));
        format!(
            "{}(tv={tv}, optimized={})",
            self.block,
            py_bool(self.optimized)
        )
    }
}

macro_rules! s5_timers {
    ($($cls:ident = $name:literal, $block:ident, $doc:literal;)*) => {$(
        #[doc = $doc]
        ///
        /// `tv`: the time value, a literal (`"S5T#5S"`, `"W#16#2050"`), a word (int) or an
        /// `S5Time`; `call()` may give another. `optimized=True` drives the optimized
        /// implementation (one 32-bit word) instead of the reference.
        #[pyclass(module = "plc_timers", name = $name)]
        pub struct $cls(S5Block);

        #[pymethods]
        impl $cls {
            #[new]
            #[pyo3(signature = (tv = None, *, optimized = false))]
            fn new(tv: Option<&Bound<'_, PyAny>>, optimized: bool) -> PyResult<Self> {
                S5Block::new(Block::$block, tv, optimized).map($cls)
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
                self.0.call(now_ms, s, r, fr, tv)
            }

            /// Whether this is the optimized implementation.
            #[getter]
            fn optimized(&self) -> bool {
                self.0.optimized
            }

            /// A copy with the same state: `copy.copy(block)`, `copy.deepcopy(block)` (a
            /// snapshot to go back to).
            fn __copy__(&self) -> Self {
                $cls(self.0.clone())
            }

            fn __deepcopy__(&self, _memo: &Bound<'_, PyAny>) -> Self {
                $cls(self.0.clone())
            }

            /// For pickle: the class with its defaults, then the state (preset,
            /// implementation, the core's state, the last time).
            fn __reduce__<'py>(
                slf: &Bound<'py, Self>,
            ) -> PyResult<(Bound<'py, PyType>, (), Bound<'py, PyAny>)> {
                let state = slf.borrow().0.getstate().into_pyobject(slf.py())?.into_any();
                Ok((slf.get_type(), (), state))
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
    )*};
}

s5_timers! {
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

// ---------------------------------------------------------------------------------------------
// IEC timers

/// An IEC timer of either implementation, copyable behind the interface.
trait IecDyn: IecTimerOps<u32> + Send + Sync {
    fn clone_box(&self) -> Box<dyn IecDyn>;
}

impl<X: IecTimerOps<u32> + Copy + Send + Sync + 'static> IecDyn for X {
    fn clone_box(&self) -> Box<dyn IecDyn> {
        Box::new(*self)
    }
}

/// The state pickle saves for an IEC timer: optimized, PT (ms), the last `now_ms`, then the
/// [`IecState`]'s fields (the kind by name).
type IecTimerPickle = (
    bool,
    Option<i32>,
    Option<u64>,
    (Option<String>, bool, bool, u32, u32, u32, bool),
);

/// An IEC timer of one kind, reference or optimized.
pub struct IecBlock {
    block: Block,
    kind: IecKind,
    timer: Box<dyn IecDyn>,
    optimized: bool,
    pt: Option<Time>,
    last: Option<CpuTime>,
}

impl Clone for IecBlock {
    fn clone(&self) -> Self {
        IecBlock {
            timer: self.timer.clone_box(),
            ..*self
        }
    }
}

impl IecBlock {
    fn new(block: Block, pt: Option<&Bound<'_, PyAny>>, optimized: bool) -> PyResult<IecBlock> {
        let Kind::IecTimer(kind) = block.kind() else {
            return Err(PyValueError::new_err(format!(
                "{block} is not an IEC timer"
            )));
        };
        let pt = pt.map(|t| args::time(t, "pt")).transpose()?;
        let timer: Box<dyn IecDyn> = if optimized {
            Box::new(IecTimer::new())
        } else {
            Box::new(IecTimerRef::<u32>::new())
        };
        Ok(IecBlock {
            block,
            kind,
            timer,
            optimized,
            pt,
            last: None,
        })
    }

    fn at(&mut self, now: &Bound<'_, PyAny>) -> PyResult<CpuTime> {
        let now = now_ms(now)?;
        forward(now, self.last)?;
        self.last = Some(now);
        Ok(now)
    }

    fn call(
        &mut self,
        now: &Bound<'_, PyAny>,
        input: bool,
        r: bool,
        pt: Option<&Bound<'_, PyAny>>,
    ) -> PyResult<PyIecOutput> {
        has_input(self.block, Port::R, r)?;
        let pt = preset(self.block, pt, self.pt, args::time)?;
        let now = self.at(now)?;
        let input = IecInput::new(input, pt).with_reset(r);
        Ok(self.timer.call(self.kind, now, input).into())
    }

    fn getstate(&self) -> IecTimerPickle {
        let st = self.timer.state();
        (
            self.optimized,
            self.pt.map(Time::as_millis),
            self.last.map(CpuTime::as_millis),
            (
                st.kind.map(|k| k.name().to_string()),
                st.input,
                st.running,
                st.start,
                st.pt,
                st.et,
                st.q,
            ),
        )
    }

    fn setstate(&mut self, state: &Bound<'_, PyAny>) -> PyResult<()> {
        let bad = || bad_state(self.block);
        let (optimized, pt, last, fields): IecTimerPickle = state.extract().map_err(|_| bad())?;
        let (kind, input, running, start, st_pt, et, q) = fields;
        let kind = match kind {
            None => None,
            Some(name) => Some(
                IecKind::ALL
                    .into_iter()
                    .find(|k| k.name() == name)
                    .ok_or_else(bad)?,
            ),
        };
        let st = IecState {
            kind,
            input,
            running,
            start,
            pt: st_pt,
            et,
            q,
        };
        let timer: Box<dyn IecDyn> = if optimized {
            Box::new(IecTimer::from_state(st).ok_or_else(bad)?)
        } else {
            Box::new(IecTimerRef::<u32>::from_state(st).ok_or_else(bad)?)
        };
        *self = IecBlock {
            timer,
            optimized,
            pt: pt.map(Time::from_millis),
            last: last.map(CpuTime::from_millis),
            ..*self
        };
        Ok(())
    }

    fn repr(&self) -> String {
        let pt = self
            .pt
            .map_or("None".to_string(), |t| format!("{:?}", t.to_string()));
        format!(
            "{}(pt={pt}, optimized={})",
            self.block,
            py_bool(self.optimized)
        )
    }
}

macro_rules! iec_timers {
    ($($cls:ident = $name:literal, $block:ident, $doc:literal;)*) => {$(
        #[doc = $doc]
        ///
        /// `pt`: the preset, a literal (`"T#500ms"`), an int of milliseconds or a `Time`;
        /// `call()` may give another. `optimized=True` drives the optimized 16-byte structure
        /// instead of the reference.
        #[pyclass(module = "plc_timers", name = $name)]
        pub struct $cls(IecBlock);

        #[pymethods]
        impl $cls {
            #[new]
            #[pyo3(signature = (pt = None, *, optimized = false))]
            fn new(pt: Option<&Bound<'_, PyAny>>, optimized: bool) -> PyResult<Self> {
                IecBlock::new(Block::$block, pt, optimized).map($cls)
            }

            /// One call of the box at CPU time `now_ms` with IN (`in_`), R (TONR only) and PT
            /// (this call's or the block's); returns Q and ET.
            #[pyo3(signature = (now_ms, in_ = false, r = false, pt = None))]
            fn call(
                &mut self,
                now_ms: &Bound<'_, PyAny>,
                in_: bool,
                r: bool,
                pt: Option<&Bound<'_, PyAny>>,
            ) -> PyResult<PyIecOutput> {
                self.0.call(now_ms, in_, r, pt)
            }

            /// Reads the structure's Q at `now_ms`: an update happens first (IEC-ACCESS-01).
            fn read_q(&mut self, now_ms: &Bound<'_, PyAny>) -> PyResult<bool> {
                let now = self.0.at(now_ms)?;
                Ok(self.0.timer.read_q(now))
            }

            /// Reads the structure's ET at `now_ms`: an update happens first (IEC-ACCESS-01).
            fn read_et(&mut self, now_ms: &Bound<'_, PyAny>) -> PyResult<u32> {
                let now = self.0.at(now_ms)?;
                Ok(self.0.timer.read_et(now))
            }

            /// The `-(RT)-` coil with power flow: resets the timer data (IEC-RT-01).
            fn reset_timer(&mut self) {
                self.0.timer.reset_timer();
            }

            /// The `-(PT)-` coil with power flow: loads `pt` into the structure's preset.
            fn preset_timer(&mut self, pt: &Bound<'_, PyAny>) -> PyResult<()> {
                let pt = args::time(pt, "pt")?;
                self.0.timer.preset_timer(pt);
                Ok(())
            }

            /// A RUN-STOP-RUN transition: a non-retentive structure returns to its initial
            /// values; a retentive one keeps its data.
            fn run_stop_run(&mut self, retentive: bool) {
                self.0.timer.run_stop_run(retentive);
            }

            /// Whether this is the optimized implementation.
            #[getter]
            fn optimized(&self) -> bool {
                self.0.optimized
            }

            /// A copy with the same state: `copy.copy(block)`, `copy.deepcopy(block)` (a
            /// snapshot to go back to).
            fn __copy__(&self) -> Self {
                $cls(self.0.clone())
            }

            fn __deepcopy__(&self, _memo: &Bound<'_, PyAny>) -> Self {
                $cls(self.0.clone())
            }

            /// For pickle: the class with its defaults, then the state (preset,
            /// implementation, the core's state, the last time).
            fn __reduce__<'py>(
                slf: &Bound<'py, Self>,
            ) -> PyResult<(Bound<'py, PyType>, (), Bound<'py, PyAny>)> {
                let state = slf.borrow().0.getstate().into_pyobject(slf.py())?.into_any();
                Ok((slf.get_type(), (), state))
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
    )*};
}

iec_timers! {
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
         False";
    Tof = "TOF", Tof, "TOF: off-delay; Q falls PT after IN fell.";
    Tonr = "TONR", Tonr, "TONR: retentive on-delay; ET accumulates while IN is 1, R clears it.";
}

// ---------------------------------------------------------------------------------------------
// IEC counters

/// An IEC counter of any integer type, behind one object-safe interface: PV and CV as `i128`
/// (every type's values fit).
trait AnyCounter: Send + Sync {
    fn clone_box(&self) -> Box<dyn AnyCounter>;
    /// CV, CU's and CD's edge memories.
    fn state(&self) -> (i128, bool, bool);
    /// This counter put in a state (`None`: CV outside the type).
    fn with_state(&self, cv: i128, cu_prev: bool, cd_prev: bool) -> Option<Box<dyn AnyCounter>>;
    fn call(
        &mut self,
        kind: CounterKind,
        cu: bool,
        cd: bool,
        r: bool,
        ld: bool,
        pv: i128,
    ) -> Option<PyCounterOutput>;
}

/// A counter `X` of integer type `T`.
struct Typed<X, T>(X, PhantomData<T>);

/// The two implementations' constructor from a state (every counter state is valid).
trait FromCounterState<T>: Sized {
    fn from_counter_state(state: CounterState<T>) -> Self;
}

impl<T: CounterInt> FromCounterState<T> for Counter<T> {
    fn from_counter_state(state: CounterState<T>) -> Self {
        Counter::from_state(state)
    }
}

impl<T: CounterInt> FromCounterState<T> for CounterRef<T> {
    fn from_counter_state(state: CounterState<T>) -> Self {
        CounterRef::from_state(state)
    }
}

impl<T: CounterInt, X> AnyCounter for Typed<X, T>
where
    X: CounterOps<T> + FromCounterState<T> + Copy + Send + Sync + 'static,
{
    fn clone_box(&self) -> Box<dyn AnyCounter> {
        Box::new(Typed(self.0, PhantomData))
    }

    fn state(&self) -> (i128, bool, bool) {
        let s = self.0.state();
        (s.cv.to_i128(), s.cu_prev, s.cd_prev)
    }

    fn with_state(&self, cv: i128, cu_prev: bool, cd_prev: bool) -> Option<Box<dyn AnyCounter>> {
        let state = CounterState {
            cv: T::from_i128(cv)?,
            cu_prev,
            cd_prev,
        };
        Some(Box::new(Typed(X::from_counter_state(state), PhantomData)))
    }

    fn call(
        &mut self,
        kind: CounterKind,
        cu: bool,
        cd: bool,
        r: bool,
        ld: bool,
        pv: i128,
    ) -> Option<PyCounterOutput> {
        let pv = T::from_i128(pv)?;
        let o: CounterOutput<T> = self.0.call(kind, CounterInput { cu, cd, r, ld, pv });
        Some(PyCounterOutput {
            qu: o.qu,
            qd: o.qd,
            cv: o.cv.to_i128(),
        })
    }
}

fn typed<T: CounterInt>(optimized: bool) -> Box<dyn AnyCounter> {
    if optimized {
        Box::new(Typed(Counter::<T>::new(), PhantomData))
    } else {
        Box::new(Typed(CounterRef::<T>::new(), PhantomData))
    }
}

/// A new counter of type `t`.
fn any_counter(t: IntType, optimized: bool) -> Box<dyn AnyCounter> {
    match t {
        IntType::SInt => typed::<i8>(optimized),
        IntType::Int => typed::<i16>(optimized),
        IntType::DInt => typed::<i32>(optimized),
        IntType::LInt => typed::<i64>(optimized),
        IntType::USInt => typed::<u8>(optimized),
        IntType::UInt => typed::<u16>(optimized),
        IntType::UDInt => typed::<u32>(optimized),
        IntType::ULInt => typed::<u64>(optimized),
    }
}

/// The integer type named `name` (SINT … ULINT, ASCII case ignored).
pub fn int_type(name: &str) -> PyResult<IntType> {
    IntType::lookup(name.trim()).ok_or_else(|| {
        PyValueError::new_err(format!(
            "unknown integer type `{name}`; type is one of {}",
            IntType::names()
        ))
    })
}

/// A preset of type `t`, as an `i128` inside its range.
pub fn counter_pv(obj: &Bound<'_, PyAny>, t: IntType, what: &str) -> PyResult<i128> {
    let (lo, hi) = t.limits();
    let v: i128 = args::int_in(obj, what, &format!("an int of {}, {lo}..={hi}", t.name()))?;
    if v < lo || v > hi {
        return Err(PyValueError::new_err(format!(
            "{what} is an int of {}, {lo}..={hi}; got {v}",
            t.name()
        )));
    }
    Ok(v)
}

/// The state pickle saves for an IEC counter: optimized, the integer type, PV, then CV and
/// the edge memories of CU and CD.
type CounterPickle = (bool, String, Option<i128>, (i128, bool, bool));

/// An IEC counter of one kind and integer type, reference or optimized.
pub struct CounterBlock {
    block: Block,
    kind: CounterKind,
    int_type: IntType,
    counter: Box<dyn AnyCounter>,
    optimized: bool,
    pv: Option<i128>,
}

impl Clone for CounterBlock {
    fn clone(&self) -> Self {
        CounterBlock {
            counter: self.counter.clone_box(),
            ..*self
        }
    }
}

impl CounterBlock {
    fn getstate(&self) -> CounterPickle {
        (
            self.optimized,
            self.int_type.name().to_string(),
            self.pv,
            self.counter.state(),
        )
    }

    fn setstate(&mut self, state: &Bound<'_, PyAny>) -> PyResult<()> {
        let bad = || bad_state(self.block);
        let (optimized, type_name, pv, (cv, cu_prev, cd_prev)): CounterPickle =
            state.extract().map_err(|_| bad())?;
        let t = IntType::lookup(&type_name).ok_or_else(bad)?;
        let (lo, hi) = t.limits();
        if pv.is_some_and(|v| v < lo || v > hi) {
            return Err(bad());
        }
        let counter = any_counter(t, optimized)
            .with_state(cv, cu_prev, cd_prev)
            .ok_or_else(bad)?;
        *self = CounterBlock {
            int_type: t,
            counter,
            optimized,
            pv,
            ..*self
        };
        Ok(())
    }

    fn new(
        block: Block,
        pv: Option<&Bound<'_, PyAny>>,
        type_name: &str,
        optimized: bool,
    ) -> PyResult<CounterBlock> {
        let Kind::IecCounter(kind) = block.kind() else {
            return Err(PyValueError::new_err(format!(
                "{block} is not an IEC counter"
            )));
        };
        let t = int_type(type_name)?;
        let pv = pv.map(|p| counter_pv(p, t, "pv")).transpose()?;
        Ok(CounterBlock {
            block,
            kind,
            int_type: t,
            counter: any_counter(t, optimized),
            optimized,
            pv,
        })
    }

    fn call(
        &mut self,
        cu: bool,
        cd: bool,
        r: bool,
        ld: bool,
        pv: Option<&Bound<'_, PyAny>>,
    ) -> PyResult<PyCounterOutput> {
        for (port, v) in [(Port::Cu, cu), (Port::Cd, cd), (Port::R, r), (Port::Ld, ld)] {
            has_input(self.block, port, v)?;
        }
        let t = self.int_type;
        let pv = preset(self.block, pv, self.pv, |o, what| counter_pv(o, t, what))?;
        // `pv` was checked against the type's range, so the conversion inside cannot fail.
        self.counter
            .call(self.kind, cu, cd, r, ld, pv)
            .ok_or_else(|| PyValueError::new_err(format!("pv {pv} is outside {}", t.name())))
    }

    fn repr(&self) -> String {
        let pv = self.pv.map_or("None".to_string(), |v| v.to_string());
        format!(
            "{}(pv={pv}, type={:?}, optimized={})",
            self.block,
            self.int_type.name(),
            py_bool(self.optimized)
        )
    }
}

macro_rules! iec_counters {
    ($($cls:ident = $name:literal, $block:ident, $doc:literal;)*) => {$(
        #[doc = $doc]
        ///
        /// `pv`: the preset (an int of the type); `call()` may give another. `type`: the
        /// integer type of PV and CV, one of SINT INT DINT LINT USINT UINT UDINT ULINT
        /// (default INT). `optimized=True` drives the optimized implementation.
        #[pyclass(module = "plc_timers", name = $name)]
        pub struct $cls(CounterBlock);

        #[pymethods]
        impl $cls {
            #[new]
            #[pyo3(signature = (pv = None, r#type = "INT", *, optimized = false))]
            fn new(pv: Option<&Bound<'_, PyAny>>, r#type: &str, optimized: bool) -> PyResult<Self> {
                CounterBlock::new(Block::$block, pv, r#type, optimized).map($cls)
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
                self.0.call(cu, cd, r, ld, pv)
            }

            /// The integer type's name.
            #[getter]
            fn r#type(&self) -> &'static str {
                self.0.int_type.name()
            }

            /// Whether this is the optimized implementation.
            #[getter]
            fn optimized(&self) -> bool {
                self.0.optimized
            }

            /// A copy with the same state: `copy.copy(block)`, `copy.deepcopy(block)` (a
            /// snapshot to go back to).
            fn __copy__(&self) -> Self {
                $cls(self.0.clone())
            }

            fn __deepcopy__(&self, _memo: &Bound<'_, PyAny>) -> Self {
                $cls(self.0.clone())
            }

            /// For pickle: the class with its defaults, then the state (preset,
            /// implementation, the core's state, the last time).
            fn __reduce__<'py>(
                slf: &Bound<'py, Self>,
            ) -> PyResult<(Bound<'py, PyType>, (), Bound<'py, PyAny>)> {
                let state = slf.borrow().0.getstate().into_pyobject(slf.py())?.into_any();
                Ok((slf.get_type(), (), state))
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
    )*};
}

iec_counters! {
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

// ---------------------------------------------------------------------------------------------
// S5 counters

/// An S5 counter of either implementation, copyable behind the interface.
trait S5CounterDyn: S5CounterOps + Send + Sync {
    fn clone_box(&self) -> Box<dyn S5CounterDyn>;
}

impl<X: S5CounterOps + Copy + Send + Sync + 'static> S5CounterDyn for X {
    fn clone_box(&self) -> Box<dyn S5CounterDyn> {
        Box::new(*self)
    }
}

/// The state pickle saves for an S5 counter: optimized, PV, then the [`S5CounterState`]'s
/// fields.
type S5CounterPickle = (bool, Option<u16>, (u16, bool, bool, bool, bool));

/// An S5 counter of one kind, reference or optimized.
pub struct S5CounterBlock {
    block: Block,
    kind: S5CounterKind,
    counter: Box<dyn S5CounterDyn>,
    optimized: bool,
    pv: Option<CounterPreset>,
}

impl Clone for S5CounterBlock {
    fn clone(&self) -> Self {
        S5CounterBlock {
            counter: self.counter.clone_box(),
            ..*self
        }
    }
}

impl S5CounterBlock {
    fn getstate(&self) -> S5CounterPickle {
        let st = self.counter.state();
        (
            self.optimized,
            self.pv.map(CounterPreset::value),
            (st.cv, st.cu_prev, st.cd_prev, st.s_prev, st.fr_prev),
        )
    }

    fn setstate(&mut self, state: &Bound<'_, PyAny>) -> PyResult<()> {
        let bad = || bad_state(self.block);
        let (optimized, pv, (cv, cu_prev, cd_prev, s_prev, fr_prev)): S5CounterPickle =
            state.extract().map_err(|_| bad())?;
        let st = S5CounterState {
            cv,
            cu_prev,
            cd_prev,
            s_prev,
            fr_prev,
        };
        let counter: Box<dyn S5CounterDyn> = if optimized {
            Box::new(S5Counter::from_state(st).ok_or_else(bad)?)
        } else {
            Box::new(S5CounterRef::from_state(st).ok_or_else(bad)?)
        };
        let pv = pv
            .map(|v| CounterPreset::new(v).map_err(|_| bad()))
            .transpose()?;
        *self = S5CounterBlock {
            counter,
            optimized,
            pv,
            ..*self
        };
        Ok(())
    }

    fn new(
        block: Block,
        pv: Option<&Bound<'_, PyAny>>,
        optimized: bool,
    ) -> PyResult<S5CounterBlock> {
        let Kind::S5Counter(kind) = block.kind() else {
            return Err(PyValueError::new_err(format!(
                "{block} is not an S5 counter"
            )));
        };
        let pv = pv.map(|p| args::counter_preset(p, "pv")).transpose()?;
        let counter: Box<dyn S5CounterDyn> = if optimized {
            Box::new(S5Counter::new())
        } else {
            Box::new(S5CounterRef::new())
        };
        Ok(S5CounterBlock {
            block,
            kind,
            counter,
            optimized,
            pv,
        })
    }

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
        for (port, v) in [(Port::Cu, cu), (Port::Cd, cd)] {
            has_input(self.block, port, v)?;
        }
        // PV matters only when S sets the counter; a call without it needs none.
        let pv = match (pv, self.pv) {
            (None, None) if !s => CounterPreset::default(),
            _ => preset(self.block, pv, self.pv, args::counter_preset)?,
        };
        let input = S5CounterInput {
            cu,
            cd,
            s,
            r,
            fr,
            pv,
        };
        Ok(self.counter.call(self.kind, input).into())
    }

    fn repr(&self) -> String {
        let pv = self
            .pv
            .map_or("None".to_string(), |p| format!("\"C#{}\"", p.value()));
        format!(
            "{}(pv={pv}, optimized={})",
            self.block,
            py_bool(self.optimized)
        )
    }
}

macro_rules! s5_counters {
    ($($cls:ident = $name:literal, $block:ident, $doc:literal;)*) => {$(
        #[doc = $doc]
        ///
        /// `pv`: the preset that S loads, a literal (`"C#5"`), an int 0..=999 or a
        /// `CounterPreset`; `call()` may give another. `optimized=True` drives the optimized
        /// implementation (one 16-bit word).
        #[pyclass(module = "plc_timers", name = $name)]
        pub struct $cls(S5CounterBlock);

        #[pymethods]
        impl $cls {
            #[new]
            #[pyo3(signature = (pv = None, *, optimized = false))]
            fn new(pv: Option<&Bound<'_, PyAny>>, optimized: bool) -> PyResult<Self> {
                S5CounterBlock::new(Block::$block, pv, optimized).map($cls)
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
                self.0.call(cu, cd, s, r, fr, pv)
            }

            /// Whether this is the optimized implementation.
            #[getter]
            fn optimized(&self) -> bool {
                self.0.optimized
            }

            /// A copy with the same state: `copy.copy(block)`, `copy.deepcopy(block)` (a
            /// snapshot to go back to).
            fn __copy__(&self) -> Self {
                $cls(self.0.clone())
            }

            fn __deepcopy__(&self, _memo: &Bound<'_, PyAny>) -> Self {
                $cls(self.0.clone())
            }

            /// For pickle: the class with its defaults, then the state (preset,
            /// implementation, the core's state, the last time).
            fn __reduce__<'py>(
                slf: &Bound<'py, Self>,
            ) -> PyResult<(Bound<'py, PyType>, (), Bound<'py, PyAny>)> {
                let state = slf.borrow().0.getstate().into_pyobject(slf.py())?.into_any();
                Ok((slf.get_type(), (), state))
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
    )*};
}

s5_counters! {
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

/// Adds the classes to the module.
pub fn register(m: &Bound<'_, PyModule>) -> PyResult<()> {
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
