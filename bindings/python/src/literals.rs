//! `S5Time`, `Time`, `LTime` and `CounterPreset`: the core's values with their literal parsers, immutable
//! and hashable in Python.

use plc_timers::counter::s5::CounterPreset;
use plc_timers::time::{LTime, S5Time, Time};
use pyo3::exceptions::PyValueError;
use pyo3::prelude::*;

use crate::args::{int_in, literal_error, preset_error};

/// An S5TIME: a duration of 0 to 999 units of a time base (10 ms, 100 ms, 1 s, 10 s), the word
/// of the S5 timers (base in bits 13-12, three BCD digits).
///
/// >>> from plc_timers import S5Time
/// >>> t = S5Time.parse("S5T#2M7S")
/// >>> (t.millis, hex(t.word), str(t))
/// (127000, '0x2127', 'S5T#2M7S')
/// >>> S5Time.from_word(0x2127) == t
/// True
/// >>> S5Time.parse("S5T#1.5S")
/// Traceback (most recent call last):
///   ...
/// plc_timers.LiteralError: invalid S5TIME literal at byte 5: fractions are not accepted; split into units, e.g. 1S_500MS
#[pyclass(module = "plc_timers", name = "S5Time", frozen, eq, hash)]
#[derive(Clone, Copy, PartialEq, Eq, Hash)]
pub struct PyS5Time(pub S5Time);

#[pymethods]
impl PyS5Time {
    /// Parses `S5T#…`, `S5TIME#…` (automatic time base) or `W#16#wxyz` (the word); raises
    /// `LiteralError` (a `ValueError`) with `kind` and `position`.
    #[staticmethod]
    fn parse(py: Python<'_>, text: &str) -> PyResult<PyS5Time> {
        S5Time::parse(text)
            .map(PyS5Time)
            .map_err(|e| literal_error(py, e))
    }

    /// The S5TIME of a word (0..=65535): base in bits 13-12, BCD value in bits 11-0.
    #[staticmethod]
    fn from_word(word: &Bound<'_, PyAny>) -> PyResult<PyS5Time> {
        let w = int_in::<u16>(word, "word", "an S5TIME word, 0..=65535")?;
        S5Time::from_word(w)
            .map(PyS5Time)
            .map_err(|e| PyValueError::new_err(e.to_string()))
    }

    /// The S5TIME of `millis` with the automatic (smallest exact) time base; raises
    /// `ValueError` when no base holds it exactly (0..=9 990 000 ms).
    #[staticmethod]
    fn from_millis(millis: &Bound<'_, PyAny>) -> PyResult<PyS5Time> {
        let ms = int_in::<u64>(millis, "millis", "a duration in ms, 0..=9990000")?;
        S5Time::from_millis(ms)
            .map(PyS5Time)
            .map_err(|e| PyValueError::new_err(e.to_string()))
    }

    /// For pickle and `copy`: `S5Time.from_word(word)`.
    fn __reduce__<'py>(slf: &Bound<'py, Self>) -> PyResult<(Bound<'py, PyAny>, (u16,))> {
        Ok((
            slf.get_type().getattr("from_word")?,
            (slf.get().0.to_word(),),
        ))
    }

    /// The word (base in bits 13-12, three BCD digits).
    #[getter]
    fn word(&self) -> u16 {
        self.0.to_word()
    }

    /// The duration in milliseconds.
    #[getter]
    fn millis(&self) -> u32 {
        self.0.as_millis()
    }

    /// The value in units of the base, 0..=999.
    #[getter]
    fn units(&self) -> u16 {
        self.0.units()
    }

    /// The time base in milliseconds: 10, 100, 1000 or 10000.
    #[getter]
    fn base_ms(&self) -> u32 {
        self.0.base().millis()
    }

    fn __str__(&self) -> String {
        self.0.to_string()
    }

    fn __repr__(&self) -> String {
        format!("S5Time.from_word(0x{:04X})", self.0.to_word())
    }
}

/// An IEC TIME: signed 32-bit milliseconds.
///
/// >>> from plc_timers import Time
/// >>> Time.parse("T#1M_30S").millis
/// 90000
/// >>> str(Time.from_millis(-1500))
/// 'T#-1S_500MS'
/// >>> Time.parse("T#5S_75M")
/// Traceback (most recent call last):
///   ...
/// plc_timers.LiteralError: invalid TIME literal at byte 7: unit M repeated or out of order; units go from largest to smallest, each once
#[pyclass(module = "plc_timers", name = "Time", frozen, eq, hash, ord)]
#[derive(Clone, Copy, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub struct PyTime(pub Time);

#[pymethods]
impl PyTime {
    /// Parses `T#…`, `TIME#…` or whole milliseconds; raises `LiteralError` (a `ValueError`)
    /// with `kind` and `position`.
    #[staticmethod]
    fn parse(py: Python<'_>, text: &str) -> PyResult<PyTime> {
        Time::parse(text)
            .map(PyTime)
            .map_err(|e| literal_error(py, e))
    }

    /// The TIME of `millis`, -2**31..=2**31-1.
    #[staticmethod]
    fn from_millis(millis: &Bound<'_, PyAny>) -> PyResult<PyTime> {
        int_in::<i32>(
            millis,
            "millis",
            "a TIME in milliseconds, -2147483648..=2147483647",
        )
        .map(|ms| PyTime(Time::from_millis(ms)))
    }

    /// For pickle and `copy`: `Time.from_millis(millis)`.
    fn __reduce__<'py>(slf: &Bound<'py, Self>) -> PyResult<(Bound<'py, PyAny>, (i32,))> {
        Ok((
            slf.get_type().getattr("from_millis")?,
            (slf.get().0.as_millis(),),
        ))
    }

    /// The duration in milliseconds.
    #[getter]
    fn millis(&self) -> i32 {
        self.0.as_millis()
    }

    fn __str__(&self) -> String {
        self.0.to_string()
    }

    fn __repr__(&self) -> String {
        format!("Time.parse({:?})", self.0.to_string())
    }
}

/// An IEC LTIME (S7-1500): signed 64-bit nanoseconds, the data type of the long IEC timers
/// (`TON(type="LTIME")`).
///
/// >>> from plc_timers import LTime
/// >>> LTime.parse("LT#1ms500us").nanos
/// 1500000
/// >>> str(LTime.from_nanos(-1_500_000))
/// 'LT#-1MS_500US'
/// >>> LTime.parse("T#5S")
/// Traceback (most recent call last):
///   ...
/// plc_timers.LiteralError: invalid LTIME literal at byte 0: unknown prefix; write LT#…, LTIME#… (e.g. LT#1MS_500US, LT#-5S) or whole nanoseconds
#[pyclass(module = "plc_timers", name = "LTime", frozen, eq, hash, ord)]
#[derive(Clone, Copy, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub struct PyLTime(pub LTime);

#[pymethods]
impl PyLTime {
    /// Parses `LT#…`, `LTIME#…` (units D H M S MS US NS) or whole nanoseconds; raises
    /// `LiteralError` (a `ValueError`) with `kind` and `position`.
    #[staticmethod]
    fn parse(py: Python<'_>, text: &str) -> PyResult<PyLTime> {
        LTime::parse(text)
            .map(PyLTime)
            .map_err(|e| literal_error(py, e))
    }

    /// The LTIME of `nanos`, -2**63..=2**63-1.
    #[staticmethod]
    fn from_nanos(nanos: &Bound<'_, PyAny>) -> PyResult<PyLTime> {
        int_in::<i64>(
            nanos,
            "nanos",
            "an LTIME in nanoseconds, -9223372036854775808..=9223372036854775807",
        )
        .map(|ns| PyLTime(LTime::from_nanos(ns)))
    }

    /// For pickle and `copy`: `LTime.from_nanos(nanos)`.
    fn __reduce__<'py>(slf: &Bound<'py, Self>) -> PyResult<(Bound<'py, PyAny>, (i64,))> {
        Ok((
            slf.get_type().getattr("from_nanos")?,
            (slf.get().0.as_nanos(),),
        ))
    }

    /// The duration in nanoseconds.
    #[getter]
    fn nanos(&self) -> i64 {
        self.0.as_nanos()
    }

    fn __str__(&self) -> String {
        self.0.to_string()
    }

    fn __repr__(&self) -> String {
        format!("LTime.parse({:?})", self.0.to_string())
    }
}

/// The preset of an S5 counter, 0..=999 (`C#n`).
///
/// >>> from plc_timers import CounterPreset
/// >>> CounterPreset.parse("C#25").value
/// 25
/// >>> hex(CounterPreset(25).bcd)
/// '0x25'
/// >>> CounterPreset.parse("C#1000")
/// Traceback (most recent call last):
///   ...
/// plc_timers.LiteralError: 1000 is above the S5 counter maximum of 999
#[pyclass(module = "plc_timers", name = "CounterPreset", frozen, eq, hash, ord)]
#[derive(Clone, Copy, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub struct PyCounterPreset(pub CounterPreset);

#[pymethods]
impl PyCounterPreset {
    /// The preset `value`, 0..=999.
    /// For pickle and `copy`: the argument of the constructor.
    fn __getnewargs__(&self) -> (u16,) {
        (self.0.value(),)
    }

    #[new]
    fn new(py: Python<'_>, value: &Bound<'_, PyAny>) -> PyResult<PyCounterPreset> {
        let n = int_in::<u16>(value, "value", "a counter preset, 0..=999")?;
        CounterPreset::new(n)
            .map(PyCounterPreset)
            .map_err(|e| preset_error(py, e))
    }

    /// Parses `C#n`, `n` or `W#16#0xyz` (BCD); raises `LiteralError` (a `ValueError`) with
    /// `kind` (`position` is None).
    #[staticmethod]
    fn parse(py: Python<'_>, text: &str) -> PyResult<PyCounterPreset> {
        CounterPreset::parse(text)
            .map(PyCounterPreset)
            .map_err(|e| preset_error(py, e))
    }

    /// The value, 0..=999.
    #[getter]
    fn value(&self) -> u16 {
        self.0.value()
    }

    /// The value in BCD (three digits), as `L C#n` loads it.
    #[getter]
    fn bcd(&self) -> u16 {
        self.0.to_bcd()
    }

    fn __str__(&self) -> String {
        format!("C#{}", self.0.value())
    }

    fn __repr__(&self) -> String {
        format!("CounterPreset({})", self.0.value())
    }
}

/// Adds the classes to the module.
pub fn register(m: &Bound<'_, PyModule>) -> PyResult<()> {
    m.add_class::<PyS5Time>()?;
    m.add_class::<PyTime>()?;
    m.add_class::<PyLTime>()?;
    m.add_class::<PyCounterPreset>()?;
    Ok(())
}
