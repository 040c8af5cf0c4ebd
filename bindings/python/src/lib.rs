//! The Python package `plc-timers` (module `plc_timers`): the reference semantics of the Siemens
//! S7 timers and counters of the crate `plc-timers`, callable from Python.
//!
//! - [`blocks`]: every block (`TON`, `S_ODT`, `CTU`, `S_CU`, …), reference or optimized, with
//!   its outputs as small immutable objects; the IEC timer's RT and PT coils and reads.
//! - [`memory`]: the S5 timer and counter memory areas with their STL operations.
//! - [`literals`]: `S5Time`, `Time` and `CounterPreset` with their parsers.
//! - [`trace`]: `run` and `check` over rows in memory, through the engine of the `plc-timers`
//!   command (`plc_timers_trace`), so that Python and the command line agree by
//!   construction.
//! - [`banks`]: `TonBank` and `CounterBank` over numpy arrays, one call per scan.
//!
//! No panic crosses into Python: every bad argument is a Python exception whose message says
//! what was wrong and what is allowed ([`args`]).

use pyo3::prelude::*;
use pyo3::types::{PyBool, PyInt, PyString, PyTuple};

pub mod args;
pub mod banks;
pub mod blocks;
pub mod int_type;
pub mod literals;
pub mod memory;
pub mod trace;

pyo3::create_exception!(
    plc_timers,
    LiteralError,
    pyo3::exceptions::PyValueError,
    "A literal (S5TIME, TIME, counter preset) that cannot be read: `kind` names what was wrong \
     (e.g. 'Fraction', 'BcdDigit'), `position` is the byte offset in the text where it was \
     found (None for a counter preset, whose errors concern the whole text), `literal` the type \
     ('S5TIME', 'TIME', 'C#')."
);

pyo3::create_exception!(
    plc_timers,
    TraceError,
    pyo3::exceptions::PyValueError,
    "Bad trace input for `run` or `check`: `line` (the header is line 1, the first row line 2), \
     `column` (1-based) and `column_name` where the trace has them (else None), `option` when a \
     keyword argument (tv, pt, pv, type, outputs) is wrong, and `message`: what was wrong and \
     what is allowed."
);

/// plc_timers: the reference semantics of the Siemens S7 timers and counters (S5 timers S_PULSE
/// … S_OFFDT, IEC timers TP TON TOF TONR, IEC counters CTU CTD CTUD, S5 counters S_CU S_CD
/// S_CUD), each as a class with the reference or the optimized implementation
/// (`optimized=True`); the memory areas TimerMemory and CounterMemory with their STL
/// operations; the literals S5Time, Time and CounterPreset; `run` and `check` over traces in
/// memory (the engine of the `plc-timers` command); TonBank and CounterBank over numpy arrays.
/// No block reads a clock: every timer call takes the CPU time it runs at, in ms.
///
/// >>> import plc_timers
/// >>> ton = plc_timers.TON(pt="T#500ms")
/// >>> ton.call(0, in_=True).q, ton.call(500, in_=True).q
/// (False, True)
#[pymodule(name = "plc_timers")]
fn native(m: &Bound<'_, PyModule>) -> PyResult<()> {
    let py = m.py();
    m.add("__version__", env!("CARGO_PKG_VERSION"))?;
    m.add("LiteralError", py.get_type::<LiteralError>())?;
    m.add("TraceError", py.get_type::<TraceError>())?;
    literals::register(m)?;
    blocks::register(m)?;
    memory::register(m)?;
    trace::register(m)?;
    banks::register(m)?;
    aliases(m)?;
    Ok(())
}

/// The type aliases of the stubs (`TimeLike`, `Row`, …), defined at runtime too, so that a test
/// can import what it annotates with (`from plc_timers import TimeLike`).
fn aliases<'py>(m: &Bound<'py, PyModule>) -> PyResult<()> {
    let py = m.py();
    let typing = py.import("typing")?;
    let union = typing.getattr("Union")?;
    let of = |items: Vec<Bound<'py, PyAny>>| union.get_item(PyTuple::new(py, items)?);
    let (s5time, time, preset) = (
        m.getattr("S5Time")?,
        m.getattr("Time")?,
        m.getattr("CounterPreset")?,
    );
    let (int, str_, bool_) = (
        py.get_type::<PyInt>().into_any(),
        py.get_type::<PyString>().into_any(),
        py.get_type::<PyBool>().into_any(),
    );
    let cell = of(vec![
        bool_,
        int.clone(),
        str_.clone(),
        s5time.clone(),
        time.clone(),
        preset.clone(),
    ])?;
    let mapping = typing
        .getattr("Mapping")?
        .get_item((str_.clone(), cell.clone()))?;
    let sequence = typing.getattr("Sequence")?.get_item(cell.clone())?;
    m.add("Cell", &cell)?;
    m.add("Row", of(vec![mapping, sequence])?)?;
    m.add("S5TimeLike", of(vec![str_.clone(), int.clone(), s5time])?)?;
    m.add("TimeLike", of(vec![str_.clone(), int.clone(), time])?)?;
    m.add("CounterPresetLike", of(vec![str_, int, preset])?)?;
    Ok(())
}
