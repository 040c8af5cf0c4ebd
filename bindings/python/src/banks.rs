//! `TonBank` and `CounterBank` over numpy arrays: one Python call per scan of thousands of
//! timers or counters. The core's banks are const-generic (`TonBank<N>`, `CounterBank<T, N>`);
//! a bank of `n` lanes here is a row of core banks of [`CHUNK`] lanes, the last one padded with
//! lanes whose inputs stay 0.

use std::sync::{Mutex, MutexGuard, PoisonError};
use std::time::Instant;

use numpy::{Element, PyArray1, PyArrayMethods, PyReadonlyArray1, PyUntypedArrayMethods};
use plc_timers::block::Instruction;
use plc_timers::catalog::{Block, DataType};
use plc_timers::counter::{BankInputs, CounterBank, CounterInt, CounterState};
use plc_timers::iec::{IecState, TonBank};
use plc_timers::time::clock::ClockWord;
use plc_timers::time::{CpuTime, IecDuration, LTime, Time, TimeUnit};
use pyo3::exceptions::{PyImportError, PyIndexError, PyTypeError, PyValueError};
use pyo3::prelude::*;
use pyo3::types::{PyTuple, PyType};

use crate::args::{self, forward_in, shown, type_name};

/// Lanes per core bank: a multiple of the TON kernel's 16 lanes, small enough that a chunk's
/// inputs and state stay in the first-level cache while it is scanned.
pub const CHUNK: usize = 1024;

/// The most lanes a bank may have.
const MAX_LANES: usize = 1 << 24;

/// numpy, imported; without it an `ImportError` that names the extra to install. numpy is an
/// optional dependency (the extra `numpy`): the numpy crate would panic where it fails to load
/// numpy's C API, and a panic reaches Python as a `BaseException` that `except Exception` does
/// not catch, so the banks' constructors ask first (every bank, pickled ones too, is made by
/// one, so numpy is loaded whenever a bank exists).
pub fn numpy_or_import_error(py: Python<'_>) -> PyResult<()> {
    py.import("numpy").map(drop).map_err(|e| {
        let err = PyImportError::new_err(format!(
            "TonBank and CounterBank need numpy, which cannot be imported ({e}); install the \
             extra: pip install plc-timers[numpy]"
        ));
        err.set_cause(py, Some(e));
        err
    })
}

/// The bank's state, locked. The lock is taken only around Rust code that makes no Python
/// call (all arrays are read and borrowed before), so a thread holding it never gives the GIL
/// away and a thread waiting for it never holds the GIL while the owner needs it. A panic
/// inside leaves a state the core's invariants still hold (every lane's state is valid), so a
/// poisoned lock is taken over, not a reason to fail every later call.
fn lock<T>(m: &Mutex<T>) -> MutexGuard<'_, T> {
    m.lock().unwrap_or_else(PoisonError::into_inner)
}

/// The number of lanes `n`: a whole number 1..=[`MAX_LANES`] (a negative one is a
/// `ValueError` saying so, not pyo3's `OverflowError`).
fn lanes(n: &Bound<'_, PyAny>) -> PyResult<usize> {
    let allowed = format!("the number of lanes, 1..={MAX_LANES}");
    let n = args::int_in::<i128>(n, "n", &allowed)?;
    match usize::try_from(n) {
        Ok(n) if (1..=MAX_LANES).contains(&n) => Ok(n),
        _ => Err(PyValueError::new_err(format!("n is {allowed}; got {n}"))),
    }
}

/// Lane `i` of a bank of `n` (`what` names a lane: "timer", "counter"), or an `IndexError`
/// that says which lanes exist.
fn lane(i: &Bound<'_, PyAny>, n: usize, what: &str) -> PyResult<usize> {
    let i = args::int_in::<i128>(i, "i", "a lane number")?;
    usize::try_from(i).ok().filter(|&i| i < n).ok_or_else(|| {
        PyIndexError::new_err(format!("no {what} {i}: this bank has 0 to {}", n - 1))
    })
}

/// A 1-D numpy array of `T` with `n` elements, read-only, as a slice; the error names the
/// argument, the dtype and length wanted, and what was given.
fn array<'py, T: Element>(
    obj: &Bound<'py, PyAny>,
    what: &str,
    dtype: &str,
    n: usize,
) -> PyResult<PyReadonlyArray1<'py, T>> {
    let wanted = || {
        format!(
            "{what} is a 1-D contiguous numpy array of {dtype} with {n} elements \
             (np.asarray(x, dtype=np.{dtype}))"
        )
    };
    let arr = obj
        .cast::<PyArray1<T>>()
        .map_err(|_| not_an_array(obj, &wanted()))?;
    if arr.len() != n {
        return Err(PyValueError::new_err(format!(
            "{}; got {} elements",
            wanted(),
            arr.len()
        )));
    }
    let ro = arr
        .try_readonly()
        .map_err(|e| PyValueError::new_err(format!("{what} cannot be read now: {e}")))?;
    if ro.as_slice().is_err() {
        return Err(PyValueError::new_err(format!(
            "{}; got a non-contiguous view (np.ascontiguousarray(x))",
            wanted()
        )));
    }
    Ok(ro)
}

/// The `TypeError` for `obj`, which is not the array `wanted` describes: it says what it is.
fn not_an_array(obj: &Bound<'_, PyAny>, wanted: &str) -> PyErr {
    let got = match (obj.getattr("dtype"), obj.getattr("shape")) {
        (Ok(d), Ok(s)) => format!("an array of {} with shape {}", shown(&d), shown(&s)),
        _ => format!("{} ({})", shown(obj), type_name(obj)),
    };
    PyTypeError::new_err(format!("{wanted}; got {got}"))
}

/// `arr` (a numpy array of bool) viewed as its bytes, uint8.
fn bytes_view<'py>(arr: &Bound<'py, PyAny>) -> PyResult<Bound<'py, PyArray1<u8>>> {
    let py = arr.py();
    arr.call_method1("view", (numpy::dtype::<u8>(py),))?
        .cast_into::<PyArray1<u8>>()
        .map_err(PyErr::from)
}

/// A 1-D numpy array of bool (or of uint8, a process image) with `n` elements, read as its
/// bytes: non-zero is True. A numpy bool is a byte that numpy takes as True when it is not 0
/// (`np.array([1, 2, 255], np.uint8).view(np.bool_)` shows `[True True True]`), while a Rust
/// `bool` must be 0 or 1: such an array read as `&[bool]` would be undefined behaviour, so no
/// bool array is ever read as one.
fn bool_bytes<'py>(
    obj: &Bound<'py, PyAny>,
    what: &str,
    n: usize,
) -> PyResult<PyReadonlyArray1<'py, u8>> {
    if obj.cast::<PyArray1<bool>>().is_ok() {
        let bytes = bytes_view(obj)?;
        array::<u8>(bytes.as_any(), what, "bool_", n)
    } else if obj.cast::<PyArray1<u8>>().is_ok() {
        array::<u8>(obj, what, "bool_", n)
    } else {
        Err(not_an_array(
            obj,
            &format!(
                "{what} is a 1-D contiguous numpy array of bool_ (or of uint8, non-zero = True) \
                 with {n} elements (np.asarray(x, dtype=np.bool_))"
            ),
        ))
    }
}

/// A fresh output array, or the caller's (`out=`), checked.
fn output<'py, T: Element>(
    py: Python<'py>,
    given: Option<&Bound<'py, PyAny>>,
    what: &str,
    dtype: &str,
    n: usize,
) -> PyResult<Bound<'py, PyArray1<T>>> {
    match given {
        None => Ok(PyArray1::<T>::zeros(py, n, false)),
        Some(obj) => {
            let arr = obj.cast::<PyArray1<T>>().map_err(|_| {
                PyTypeError::new_err(format!(
                    "out's {what} is a 1-D numpy array of {dtype} with {n} elements; got {}",
                    shown(obj)
                ))
            })?;
            if arr.len() != n {
                return Err(PyValueError::new_err(format!(
                    "out's {what} has {} elements; it needs {n}",
                    arr.len()
                )));
            }
            Ok(arr.clone())
        }
    }
}

/// A bool output array and the same memory as uint8.
type BoolOutput<'py> = (Bound<'py, PyArray1<bool>>, Bound<'py, PyArray1<u8>>);

/// A bool output array (fresh or the caller's) and its bytes, which the scan writes 0 or 1
/// into: the caller's array may hold any bytes (`np.empty`), which a `&mut [bool]` must not
/// cover.
fn bool_output<'py>(
    py: Python<'py>,
    given: Option<&Bound<'py, PyAny>>,
    what: &str,
    n: usize,
) -> PyResult<BoolOutput<'py>> {
    let arr = output::<bool>(py, given, what, "bool_", n)?;
    let bytes = bytes_view(arr.as_any())?;
    Ok((arr, bytes))
}

/// `arr` borrowed writable, or an error that says why it cannot be.
fn writable<'py, T: Element>(
    arr: &Bound<'py, PyArray1<T>>,
    what: &str,
) -> PyResult<numpy::PyReadwriteArray1<'py, T>> {
    arr.try_readwrite().map_err(|e| {
        PyValueError::new_err(format!(
            "the {what} output array cannot be written now ({e}); pass arrays that are not \
             also inputs"
        ))
    })
}

/// The arrays of `out=`, each `None` when `out` is not given.
type OutPair<'py> = (Option<Bound<'py, PyAny>>, Option<Bound<'py, PyAny>>);

/// The two arrays of `out=`, if given.
fn out_pair<'py>(out: Option<&Bound<'py, PyAny>>) -> PyResult<OutPair<'py>> {
    match out {
        None => Ok((None, None)),
        Some(o) => {
            let t = o.cast::<PyTuple>().map_err(|_| {
                PyTypeError::new_err(format!("out is a tuple of arrays; got {}", shown(o)))
            })?;
            let items: Vec<Bound<'py, PyAny>> = t.iter().collect();
            match items.as_slice() {
                [a, b] => Ok((Some(a.clone()), Some(b.clone()))),
                _ => Err(PyValueError::new_err(format!(
                    "out is a tuple of 2 arrays; got {} item(s)",
                    items.len()
                ))),
            }
        }
    }
}

/// A data type of the TON bank's timers with the numpy arrays of its PT (in) and ET (out): the
/// one place where `TIME` and `LTIME` banks differ.
trait BankData: IecDuration {
    /// PT's numpy element: int32 ms for TIME, int64 ns for LTIME (the data type's own range).
    type Pt: Element + Copy;
    /// ET's numpy element: int32 ms for TIME (ET <= PT < 2**31), uint64 ns for LTIME.
    type Et: Element + Copy;
    /// The numpy dtype names of PT and ET.
    const PT_DTYPE: &'static str;
    const ET_DTYPE: &'static str;
    /// PT as the data type.
    fn preset(v: Self::Pt) -> Self;
    /// ET as numpy takes it.
    fn et(c: Self::Clock) -> Self::Et;
}

impl BankData for Time {
    type Pt = i32;
    type Et = i32;
    const PT_DTYPE: &'static str = "int32";
    const ET_DTYPE: &'static str = "int32";
    fn preset(ms: i32) -> Time {
        Time::from_millis(ms)
    }
    fn et(ms: u32) -> i32 {
        // ET <= PT <= 2**31-1 (IecState::is_valid): the cast keeps the value.
        ms as i32
    }
}

impl BankData for LTime {
    type Pt = i64;
    type Et = u64;
    const PT_DTYPE: &'static str = "int64";
    const ET_DTYPE: &'static str = "uint64";
    fn preset(ns: i64) -> LTime {
        LTime::from_nanos(ns)
    }
    fn et(ns: u64) -> u64 {
        ns
    }
}

/// A timer's state as pickle keeps it: IN, running, START, PT, ET, Q (the clock words widened
/// to 64 bits).
type TonRow = (bool, bool, u64, u64, u64, bool);

/// A TON bank of any data type, behind one object-safe interface.
trait AnyTonBank: Send + Sync {
    /// One scan at `now` (whole units of the bank's clock) with IN as bytes (non-zero = 1)
    /// and PT, into new arrays or those of `out`; returns Q and ET.
    fn scan<'py>(
        &self,
        py: Python<'py>,
        now: &Bound<'py, PyAny>,
        in_: &Bound<'py, PyAny>,
        pt: &Bound<'py, PyAny>,
        out: OutPair<'py>,
    ) -> PyResult<Bound<'py, PyTuple>>;
    /// Q and ET of timer `i` (`i` < the bank's lanes) after the last scan.
    fn output(&self, i: usize) -> Option<(bool, u64)>;
    /// A copy with the same timers and clock.
    fn copy(&self) -> Box<dyn AnyTonBank>;
    /// The time of the last scan and every timer's state.
    fn states(&self) -> (Option<u64>, Vec<TonRow>);
    /// The timers put in `rows` (one per lane) and the time of the last scan; `Err` says
    /// which timer's state no timer can be in.
    fn set_states(&self, last: Option<u64>, rows: &[TonRow]) -> Result<(), String>;
}

/// The state of a TON bank: its chunks and the scratch arrays of one chunk.
#[derive(Clone)]
struct TonLanes<D: IecDuration> {
    banks: Vec<Box<TonBank<CHUNK, D>>>,
    /// The clock of the last scan, in the bank's unit.
    last: Option<u64>,
    /// The PT of one chunk, reused for every chunk.
    pt: Box<[D; CHUNK]>,
    /// The IN of one chunk as bools (the lanes past `n` in the last chunk stay 0).
    input: Box<[bool; CHUNK]>,
    /// One chunk's Q and ET (before the cast to numpy's element).
    q: Box<[bool; CHUNK]>,
    et: Box<[D::Clock; CHUNK]>,
}

impl<D: BankData> TonLanes<D> {
    fn new(n: usize) -> TonLanes<D> {
        TonLanes {
            banks: (0..n.div_ceil(CHUNK)).map(|_| Box::default()).collect(),
            last: None,
            pt: Box::new([D::ZERO; CHUNK]),
            input: Box::new([false; CHUNK]),
            q: Box::new([false; CHUNK]),
            et: Box::new([<D::Clock as ClockWord>::ZERO; CHUNK]),
        }
    }

    /// One scan: `input` as bytes (non-zero = IN), `preset` in the clock's unit; Q (0/1) and
    /// ET into `q`, `et`.
    fn scan(&mut self, now: u64, input: &[u8], preset: &[D::Pt], q: &mut [u8], et: &mut [D::Et]) {
        let now = CpuTime::from_ticks(now);
        let chunks = self
            .banks
            .iter_mut()
            .zip(q.chunks_mut(CHUNK).zip(et.chunks_mut(CHUNK)))
            .zip(input.chunks(CHUNK).zip(preset.chunks(CHUNK)));
        for ((bank, (q, et)), (input, preset)) in chunks {
            for (t, &v) in self.pt.iter_mut().zip(preset) {
                *t = D::preset(v);
            }
            for (b, &byte) in self.input.iter_mut().zip(input) {
                *b = byte != 0;
            }
            self.input[input.len()..].fill(false);
            bank.scan(now, &self.input, &self.pt);
            // Q and ET of the chunk just scanned, while its state is in cache.
            bank.outputs_into(&mut self.q, &mut self.et);
            for (slot, &v) in q.iter_mut().zip(self.q.iter()) {
                *slot = u8::from(v);
            }
            for (slot, &v) in et.iter_mut().zip(self.et.iter()) {
                *slot = D::et(v);
            }
        }
    }

    /// The state of lane `i` (`i` < the bank's lanes).
    fn get(&self, i: usize) -> Option<IecState<D::Clock>> {
        self.banks.get(i / CHUNK)?.get(i % CHUNK).ok()
    }
}

/// The TON bank of `n` lanes of data type `D`.
struct TonLanesOf<D: IecDuration> {
    n: usize,
    /// Locked as [`lock`] says.
    lanes: Mutex<TonLanes<D>>,
}

impl<D: BankData> AnyTonBank for TonLanesOf<D> {
    fn scan<'py>(
        &self,
        py: Python<'py>,
        now: &Bound<'py, PyAny>,
        in_: &Bound<'py, PyAny>,
        pt: &Bound<'py, PyAny>,
        (q_out, et_out): OutPair<'py>,
    ) -> PyResult<Bound<'py, PyTuple>> {
        let unit = <D::Unit as TimeUnit>::SYMBOL;
        let now = args::clock(now, unit)?;
        let n = self.n;
        let input = bool_bytes(in_, "in_", n)?;
        let preset = array::<D::Pt>(pt, "pt", D::PT_DTYPE, n)?;
        let (q, q_bytes) = bool_output(py, q_out.as_ref(), "q", n)?;
        let et = output::<D::Et>(py, et_out.as_ref(), "et", D::ET_DTYPE, n)?;
        // `array` checked that both are contiguous.
        let (input, preset) = match (input.as_slice(), preset.as_slice()) {
            (Ok(i), Ok(p)) => (i, p),
            _ => return Err(PyValueError::new_err("in_ and pt must be contiguous")),
        };
        // The outputs are borrowed before the scan, so that an array that cannot be written
        // (e.g. `in_` given again as an output) fails the call before any timer changes.
        let mut q_rw = writable(&q_bytes, "q")?;
        let mut et_rw = writable(&et, "et")?;
        let (q_all, et_all) = match (q_rw.as_slice_mut(), et_rw.as_slice_mut()) {
            (Ok(q), Ok(et)) => (q, et),
            _ => {
                return Err(PyValueError::new_err(
                    "the output arrays must be contiguous",
                ))
            }
        };
        // No Python call from here to the end of the scan: see `lock`.
        let mut lanes = lock(&self.lanes);
        forward_in(now, lanes.last, unit)?;
        lanes.last = Some(now);
        lanes.scan(now, input, preset, q_all, et_all);
        drop(lanes);
        drop((q_rw, et_rw));
        PyTuple::new(py, [q.into_any(), et.into_any()])
    }

    fn output(&self, i: usize) -> Option<(bool, u64)> {
        lock(&self.lanes).get(i).map(|s| (s.q, s.et.to_u64()))
    }

    fn copy(&self) -> Box<dyn AnyTonBank> {
        Box::new(TonLanesOf {
            n: self.n,
            lanes: Mutex::new(lock(&self.lanes).clone()),
        })
    }

    fn states(&self) -> (Option<u64>, Vec<TonRow>) {
        let lanes = lock(&self.lanes);
        let rows = (0..self.n)
            .filter_map(|i| lanes.get(i))
            .map(|s| {
                let (start, pt, et) = (s.start.to_u64(), s.pt.to_u64(), s.et.to_u64());
                (s.input, s.running, start, pt, et, s.q)
            })
            .collect();
        (lanes.last, rows)
    }

    fn set_states(&self, last: Option<u64>, rows: &[TonRow]) -> Result<(), String> {
        let mut restored = TonLanes::<D>::new(self.n);
        restored.last = last;
        let max = <D::Clock as ClockWord>::MAX.to_u64();
        for (i, &(input, running, start, pt, et, q)) in rows.iter().enumerate() {
            let not_a_state = || format!("the state of timer {i} is not one a timer can be in");
            if start > max || pt > max || et > max {
                return Err(format!(
                    "{}: START, PT and ET are 0..={max} for {}; got {start}, {pt}, {et}",
                    not_a_state(),
                    D::NAME
                ));
            }
            let word = <D::Clock as ClockWord>::from_u64_wrapping;
            let state = IecState {
                kind: None,
                input,
                running,
                start: word(start),
                pt: word(pt),
                et: word(et),
                q,
            };
            let bank = &mut restored.banks[i / CHUNK];
            if bank.set_state(i % CHUNK, state) != Ok(true) {
                return Err(format!("{}: {state:?}", not_a_state()));
            }
        }
        *lock(&self.lanes) = restored;
        Ok(())
    }
}

/// A bank of `n` new timers of data type `D`.
fn ton_lanes<D: BankData>(n: usize) -> Box<dyn AnyTonBank> {
    Box::new(TonLanesOf::<D> {
        n,
        lanes: Mutex::new(TonLanes::new(n)),
    })
}

/// The arguments `__reduce__` gives pickle for a `TonBank`: the class, `(n, type)`, the time of
/// the last scan and every timer's state.
type TonBankReduce<'py> = (
    Bound<'py, PyType>,
    (usize, &'static str),
    (Option<u64>, Vec<TonRow>),
);

/// `n` TON timers of data type `type` called together once per scan, each exactly as `TON`
/// called once per scan (IEC-BANK-01). `type` is `"TIME"` (default: the clock, PT and ET in
/// milliseconds; PT int32, ET int32) or `"LTIME"` (S7-1500: in nanoseconds; PT int64, ET
/// uint64).
///
/// >>> import numpy as np
/// >>> from plc_timers import TonBank
/// >>> bank = TonBank(3)
/// >>> pt = np.array([2000, 2000, 500], dtype=np.int32)
/// >>> sensors = np.array([True, False, True])
/// >>> for k in range(5):
/// ...     q, et = bank.scan(500 * k, sensors, pt)
/// >>> q.tolist(), et.tolist()
/// ([True, False, True], [2000, 0, 500])
/// >>> lbank = TonBank(2, type="LTIME")  # nanoseconds
/// >>> lpt = np.array([1_500_000, 30 * 86_400 * 10**9], dtype=np.int64)  # LT#1MS500US, LT#30D
/// >>> q, et = lbank.scan(0, np.array([True, True]), lpt)
/// >>> q, et = lbank.scan(1_500_000, np.array([True, True]), lpt)
/// >>> q.tolist(), et.tolist(), et.dtype.name
/// ([True, False], [1500000, 1500000], 'uint64')
#[pyclass(module = "plc_timers", name = "TonBank", frozen)]
pub struct PyTonBank {
    n: usize,
    data_type: DataType,
    bank: Box<dyn AnyTonBank>,
}

#[pymethods]
impl PyTonBank {
    /// A bank of `n` new timers of data type `type` (TIME or LTIME).
    #[new]
    #[pyo3(signature = (n, r#type = "TIME"))]
    fn new(py: Python<'_>, n: &Bound<'_, PyAny>, r#type: &str) -> PyResult<Self> {
        numpy_or_import_error(py)?;
        let n = lanes(n)?;
        let data_type = crate::blocks::instruction(Block::Ton, r#type)?.data_type();
        let bank = match data_type {
            DataType::LTime => ton_lanes::<LTime>(n),
            // TIME, the one left of the types TON takes.
            _ => ton_lanes::<Time>(n),
        };
        Ok(PyTonBank { n, data_type, bank })
    }

    fn __len__(&self) -> usize {
        self.n
    }

    /// The data type's name (`TIME`, `LTIME`).
    #[getter]
    fn r#type(&self) -> &'static str {
        self.data_type.name()
    }

    /// One scan at CPU time `now` (whole ms for TIME, whole ns for LTIME): timer `i` called
    /// as TON with IN = `in_[i]` and PT = `pt[i]` (in the same unit). `in_` is a numpy array
    /// of bool (its bytes read as numpy reads them: non-zero is True; a uint8 array is taken
    /// too), `pt` of int32 (TIME) or int64 (LTIME), both of length `n`. Returns `(q, et)`:
    /// arrays of bool and int32 (TIME) or uint64 (LTIME), new ones or those of `out=(q, et)`.
    #[pyo3(signature = (now, /, in_, pt, *, out = None))]
    fn scan<'py>(
        &self,
        py: Python<'py>,
        now: &Bound<'py, PyAny>,
        in_: &Bound<'py, PyAny>,
        pt: &Bound<'py, PyAny>,
        out: Option<&Bound<'py, PyAny>>,
    ) -> PyResult<Bound<'py, PyTuple>> {
        let out = out_pair(out)?;
        self.bank.scan(py, now, in_, pt, out)
    }

    /// The outputs of timer `i` (Q, ET) after the last scan.
    fn output(&self, i: &Bound<'_, PyAny>) -> PyResult<crate::blocks::PyIecOutput> {
        let i = lane(i, self.n, "timer")?;
        self.bank
            .output(i)
            .map(|(q, et)| crate::blocks::PyIecOutput { q, et })
            .ok_or_else(|| PyIndexError::new_err(format!("no timer {i}")))
    }

    /// A copy with the same timers and clock: `copy.copy(bank)` and `copy.deepcopy(bank)`
    /// (a snapshot to go back to).
    fn __copy__(&self) -> Self {
        PyTonBank {
            n: self.n,
            data_type: self.data_type,
            bank: self.bank.copy(),
        }
    }

    fn __deepcopy__(&self, _memo: &Bound<'_, PyAny>) -> Self {
        self.__copy__()
    }

    /// For pickle: `TonBank(n, type)`, then the time of the last scan and the state of every
    /// timer (IN, running, START, PT, ET, Q).
    fn __reduce__<'py>(slf: &Bound<'py, Self>) -> PyResult<TonBankReduce<'py>> {
        let this = slf.get();
        Ok((
            slf.get_type(),
            (this.n, this.data_type.name()),
            this.bank.states(),
        ))
    }

    /// Restores what `__reduce__` saved; a state that no timer can be in is a `ValueError`.
    fn __setstate__(&self, state: &Bound<'_, PyAny>) -> PyResult<()> {
        let (last, rows): (Option<u64>, Vec<TonRow>) = state.extract().map_err(|_| {
            PyValueError::new_err(
                "a TonBank's state is (last_now, [(in, running, start, pt, et, q), …])",
            )
        })?;
        if rows.len() != self.n {
            return Err(PyValueError::new_err(format!(
                "the state has {} timers; this bank has {}",
                rows.len(),
                self.n
            )));
        }
        self.bank
            .set_states(last, &rows)
            .map_err(PyValueError::new_err)
    }

    fn __repr__(&self) -> String {
        match self.data_type {
            DataType::Time => format!("TonBank({})", self.n),
            t => format!("TonBank({}, type={:?})", self.n, t.name()),
        }
    }
}

/// The seconds one scan of the core's `TonBank<10048>` takes in Rust, timed over `scans` scans
/// with the inputs of `inputs` in turn (a list of bool arrays) and `pt` (int32): the figure
/// `bench.py` compares the numpy bank with. Not part of the API.
#[pyfunction]
fn _rust_ton_scan_seconds(
    inputs: Vec<Bound<'_, PyAny>>,
    pt: PyReadonlyArray1<'_, i32>,
    scans: u64,
) -> PyResult<f64> {
    const N: usize = 10_048;
    let to_array = |a: &Bound<'_, PyAny>| -> PyResult<Box<[bool; N]>> {
        let bytes = bool_bytes(a, "inputs[k]", N)?;
        let bytes = bytes
            .as_slice()
            .map_err(|_| PyValueError::new_err("inputs are contiguous"))?;
        let bools: Vec<bool> = bytes.iter().map(|&b| b != 0).collect();
        Box::<[bool; N]>::try_from(bools.into_boxed_slice())
            .map_err(|_| PyValueError::new_err(format!("inputs are arrays of {N} bools")))
    };
    let scans_in: Vec<Box<[bool; N]>> = inputs.iter().map(to_array).collect::<PyResult<_>>()?;
    if scans_in.is_empty() || scans == 0 {
        return Err(PyValueError::new_err(
            "give at least one input array and one scan",
        ));
    }
    let pt: Vec<Time> = pt
        .as_slice()
        .map_err(|_| PyValueError::new_err("pt is contiguous"))?
        .iter()
        .map(|&ms| Time::from_millis(ms))
        .collect();
    let pt: Box<[Time; N]> = pt
        .into_boxed_slice()
        .try_into()
        .map_err(|_| PyValueError::new_err(format!("pt has {N} elements")))?;
    let mut bank = Box::new(TonBank::<N>::new());
    let start = Instant::now();
    for k in 0..scans {
        let input = &scans_in[(k % scans_in.len() as u64) as usize];
        bank.scan(CpuTime::from_millis(10 * k), input, &pt);
        std::hint::black_box(&mut bank);
    }
    Ok(start.elapsed().as_secs_f64() / scans as f64)
}

// ---------------------------------------------------------------------------------------------
// CounterBank

/// A counter bank of any integer type, behind one object-safe interface.
trait AnyBank: Send + Sync {
    /// One scan with the inputs as bytes (non-zero = 1; `None`: 0) and preset `pv`.
    fn scan<'py>(
        &self,
        py: Python<'py>,
        inputs: [Option<&[u8]>; 4],
        pv: i128,
        out: [Option<Bound<'py, PyAny>>; 3],
    ) -> PyResult<Bound<'py, PyTuple>>;
    /// A copy of the bank with its counters' states.
    fn copy(&self) -> Box<dyn AnyBank>;
    /// Every counter's state: CV, CU's and CD's edge memories.
    fn states(&self) -> Vec<(i128, bool, bool)>;
    /// The counters put in `states`; `Err(i)` when counter `i`'s CV is outside the type.
    fn set_states(&self, states: &[(i128, bool, bool)]) -> Result<(), usize>;
}

/// The counters of a bank of `n` lanes: its chunks and one chunk's inputs (CU, CD, R, LD).
#[derive(Clone)]
struct CounterLanes<T> {
    banks: Vec<Box<CounterBank<T, CHUNK>>>,
    buf: Box<[[bool; CHUNK]; 4]>,
}

struct Lanes<T> {
    n: usize,
    dtype: &'static str,
    /// Locked as [`lock`] says.
    lanes: Mutex<CounterLanes<T>>,
}

impl<T: CounterInt + Element> AnyBank for Lanes<T> {
    fn scan<'py>(
        &self,
        py: Python<'py>,
        inputs: [Option<&[u8]>; 4],
        pv: i128,
        out: [Option<Bound<'py, PyAny>>; 3],
    ) -> PyResult<Bound<'py, PyTuple>> {
        let n = self.n;
        let pv = T::from_i128(pv)
            .ok_or_else(|| PyValueError::new_err(format!("pv {pv} is outside the type")))?;
        let [qu_out, qd_out, cv_out] = out;
        let (qu, qu_bytes) = bool_output(py, qu_out.as_ref(), "qu", n)?;
        let (qd, qd_bytes) = bool_output(py, qd_out.as_ref(), "qd", n)?;
        let cv = output::<T>(py, cv_out.as_ref(), "cv", self.dtype, n)?;
        // The outputs are borrowed before the scan, so that an array that cannot be written
        // fails the call before any counter changes.
        let mut qu_rw = writable(&qu_bytes, "qu")?;
        let mut qd_rw = writable(&qd_bytes, "qd")?;
        let mut cv_rw = writable(&cv, "cv")?;
        let (qu_all, qd_all, cv_all) = match (
            qu_rw.as_slice_mut(),
            qd_rw.as_slice_mut(),
            cv_rw.as_slice_mut(),
        ) {
            (Ok(a), Ok(b), Ok(c)) => (a, b, c),
            _ => {
                return Err(PyValueError::new_err(
                    "the output arrays must be contiguous",
                ))
            }
        };
        let outs = qu_all
            .chunks_mut(CHUNK)
            .zip(qd_all.chunks_mut(CHUNK))
            .zip(cv_all.chunks_mut(CHUNK));
        // No Python call from here to the end of the scan: see `lock`.
        let mut guard = lock(&self.lanes);
        let CounterLanes { banks, buf } = &mut *guard;
        for (k, (bank, ((qu, qd), cv))) in banks.iter_mut().zip(outs).enumerate() {
            let lo = k * CHUNK;
            let hi = (lo + CHUNK).min(n);
            for (buf, given) in buf.iter_mut().zip(&inputs) {
                match given {
                    Some(s) => {
                        for (b, &byte) in buf.iter_mut().zip(&s[lo..hi]) {
                            *b = byte != 0;
                        }
                    }
                    None => buf[..hi - lo].fill(false),
                }
            }
            let [cu, cd, r, ld] = &**buf;
            bank.scan(&BankInputs { cu, cd, r, ld }, pv);
            let slots = qu.iter_mut().zip(qd.iter_mut()).zip(cv.iter_mut());
            for (((qu, qd), cv), o) in slots.zip(bank.outputs(pv)) {
                *qu = u8::from(o.qu);
                *qd = u8::from(o.qd);
                *cv = o.cv;
            }
        }
        drop(guard);
        drop((qu_rw, qd_rw, cv_rw));
        PyTuple::new(py, [qu.into_any(), qd.into_any(), cv.into_any()])
    }

    fn copy(&self) -> Box<dyn AnyBank> {
        Box::new(Lanes {
            n: self.n,
            dtype: self.dtype,
            lanes: Mutex::new(lock(&self.lanes).clone()),
        })
    }

    fn states(&self) -> Vec<(i128, bool, bool)> {
        let lanes = lock(&self.lanes);
        (0..self.n)
            .filter_map(|i| lanes.banks.get(i / CHUNK)?.get(i % CHUNK).ok())
            .map(|s| (s.cv.to_i128(), s.cu_prev, s.cd_prev))
            .collect()
    }

    fn set_states(&self, states: &[(i128, bool, bool)]) -> Result<(), usize> {
        let mut restored = CounterLanes::<T>::new(self.n);
        for (i, &(cv, cu_prev, cd_prev)) in states.iter().enumerate() {
            let cv = T::from_i128(cv).ok_or(i)?;
            let state = CounterState {
                cv,
                cu_prev,
                cd_prev,
            };
            restored
                .banks
                .get_mut(i / CHUNK)
                .and_then(|b| b.set_state(i % CHUNK, state).ok())
                .ok_or(i)?;
        }
        *lock(&self.lanes) = restored;
        Ok(())
    }
}

impl<T: CounterInt> CounterLanes<T> {
    fn new(n: usize) -> CounterLanes<T> {
        CounterLanes {
            banks: (0..n.div_ceil(CHUNK)).map(|_| Box::default()).collect(),
            buf: Box::new([[false; CHUNK]; 4]),
        }
    }
}

fn lanes_of<T: CounterInt + Element>(n: usize, dtype: &'static str) -> Box<dyn AnyBank> {
    Box::new(Lanes::<T> {
        n,
        dtype,
        lanes: Mutex::new(CounterLanes::new(n)),
    })
}

/// The arguments `__reduce__` gives pickle for a `CounterBank`: the class, `(n, type)`, every
/// counter's `(cv, cu_prev, cd_prev)`.
type CounterBankReduce<'py> = (
    Bound<'py, PyType>,
    (usize, &'static str),
    Vec<(i128, bool, bool)>,
);

/// The numpy dtype name of the integer type `t`.
fn dtype_of(t: DataType) -> Option<&'static str> {
    Some(match t {
        DataType::SInt => "int8",
        DataType::Int => "int16",
        DataType::DInt => "int32",
        DataType::LInt => "int64",
        DataType::USInt => "uint8",
        DataType::UInt => "uint16",
        DataType::UDInt => "uint32",
        DataType::ULInt => "uint64",
        _ => return None,
    })
}

/// `n` CTUD counters of one integer type called together once per scan with one preset, each
/// exactly as `CTUD` called once per scan (CNT-EQUIV-01).
///
/// >>> import numpy as np
/// >>> from plc_timers import CounterBank
/// >>> lines = CounterBank(4)  # INT counters
/// >>> reset = np.array([False, False, True, False])
/// >>> for pulse in (True, False, True, False, True):
/// ...     qu, qd, cv = lines.scan(cu=np.array([pulse, pulse, pulse, False]), r=reset, pv=3)
/// >>> qu.tolist(), cv.tolist(), cv.dtype.name
/// ([True, True, False, False], [3, 3, 0, 0], 'int16')
#[pyclass(module = "plc_timers", name = "CounterBank", frozen)]
pub struct PyCounterBank {
    bank: Box<dyn AnyBank>,
    n: usize,
    int_type: DataType,
}

#[pymethods]
impl PyCounterBank {
    /// A bank of `n` new counters of integer type `type` (SINT … ULINT, default INT).
    #[new]
    #[pyo3(signature = (n, r#type = "INT"))]
    fn new(py: Python<'_>, n: &Bound<'_, PyAny>, r#type: &str) -> PyResult<Self> {
        numpy_or_import_error(py)?;
        let n = lanes(n)?;
        // The bank's counters are CTUD's: their data types are CTUD's.
        let t = DataType::lookup(r#type.trim())
            .and_then(|t| Instruction::new(Block::Ctud, t).ok())
            .map(Instruction::data_type)
            .ok_or_else(|| {
                let names: Vec<&str> = Block::Ctud.data_types().iter().map(|t| t.name()).collect();
                PyValueError::new_err(format!(
                    "unknown integer type `{}`; type is one of {}",
                    r#type,
                    names.join(" ")
                ))
            })?;
        let dtype = dtype_of(t).unwrap_or("int16");
        let bank = match t {
            DataType::SInt => lanes_of::<i8>(n, dtype),
            DataType::DInt => lanes_of::<i32>(n, dtype),
            DataType::LInt => lanes_of::<i64>(n, dtype),
            DataType::USInt => lanes_of::<u8>(n, dtype),
            DataType::UInt => lanes_of::<u16>(n, dtype),
            DataType::UDInt => lanes_of::<u32>(n, dtype),
            DataType::ULInt => lanes_of::<u64>(n, dtype),
            // INT, the one left of the types CTUD takes.
            _ => lanes_of::<i16>(n, dtype),
        };
        Ok(PyCounterBank {
            bank,
            n,
            int_type: t,
        })
    }

    fn __len__(&self) -> usize {
        self.n
    }

    /// The integer type's name.
    #[getter]
    fn r#type(&self) -> &'static str {
        self.int_type.name()
    }

    /// One scan: counter `i` called as CTUD with CU = `cu[i]`, CD = `cd[i]`, R = `r[i]`, LD =
    /// `ld[i]` (numpy arrays of bool of length `n`, their bytes read as numpy reads them:
    /// non-zero is True; uint8 arrays are taken too; an input not given is 0) and preset `pv`.
    /// Returns `(qu, qd, cv)`: arrays of bool, bool and the type's dtype, new ones or those of
    /// `out=(qu, qd, cv)`.
    #[pyo3(signature = (*, pv, cu = None, cd = None, r = None, ld = None, out = None))]
    #[allow(clippy::too_many_arguments)]
    fn scan<'py>(
        &self,
        py: Python<'py>,
        pv: &Bound<'py, PyAny>,
        cu: Option<&Bound<'py, PyAny>>,
        cd: Option<&Bound<'py, PyAny>>,
        r: Option<&Bound<'py, PyAny>>,
        ld: Option<&Bound<'py, PyAny>>,
        out: Option<&Bound<'py, PyAny>>,
    ) -> PyResult<Bound<'py, PyTuple>> {
        let n = self.n;
        let pv = args::int_preset(pv, self.int_type, "pv")?;
        let read = |a: Option<&Bound<'py, PyAny>>, what: &str| {
            a.map(|a| bool_bytes(a, what, n)).transpose()
        };
        let arrays = [
            read(cu, "cu")?,
            read(cd, "cd")?,
            read(r, "r")?,
            read(ld, "ld")?,
        ];
        let mut slices: [Option<&[u8]>; 4] = [None; 4];
        for (s, a) in slices.iter_mut().zip(&arrays) {
            if let Some(a) = a {
                *s = Some(
                    a.as_slice()
                        .map_err(|_| PyValueError::new_err("inputs must be contiguous"))?,
                );
            }
        }
        let out: [Option<Bound<'py, PyAny>>; 3] = match out {
            None => [None, None, None],
            Some(o) => {
                let t = o.cast::<PyTuple>().map_err(|_| {
                    PyTypeError::new_err(format!("out is a tuple of 3 arrays; got {}", shown(o)))
                })?;
                let items: Vec<Bound<'py, PyAny>> = t.iter().collect();
                match <[Bound<'py, PyAny>; 3]>::try_from(items) {
                    Ok([a, b, c]) => [Some(a), Some(b), Some(c)],
                    Err(items) => {
                        return Err(PyValueError::new_err(format!(
                            "out is a tuple of 3 arrays; got {} item(s)",
                            items.len()
                        )))
                    }
                }
            }
        };
        self.bank.scan(py, slices, pv, out)
    }

    /// The state of counter `i`: `(cv, cu_prev, cd_prev)`, its CV and the edge memories of
    /// CU and CD.
    fn state(&self, i: &Bound<'_, PyAny>) -> PyResult<(i128, bool, bool)> {
        let i = lane(i, self.n, "counter")?;
        self.bank
            .states()
            .get(i)
            .copied()
            .ok_or_else(|| PyIndexError::new_err(format!("no counter {i}")))
    }

    /// A copy with the same counters: `copy.copy(bank)` and `copy.deepcopy(bank)` (a
    /// snapshot to go back to).
    fn __copy__(&self) -> Self {
        PyCounterBank {
            bank: self.bank.copy(),
            n: self.n,
            int_type: self.int_type,
        }
    }

    fn __deepcopy__(&self, _memo: &Bound<'_, PyAny>) -> Self {
        self.__copy__()
    }

    /// For pickle: `CounterBank(n, type)`, then every counter's `(cv, cu_prev, cd_prev)`.
    fn __reduce__<'py>(slf: &Bound<'py, Self>) -> PyResult<CounterBankReduce<'py>> {
        let this = slf.get();
        Ok((
            slf.get_type(),
            (this.n, this.int_type.name()),
            this.bank.states(),
        ))
    }

    /// Restores what `__reduce__` saved; a CV outside the type is a `ValueError`.
    fn __setstate__(&self, state: &Bound<'_, PyAny>) -> PyResult<()> {
        let states: Vec<(i128, bool, bool)> = state.extract().map_err(|_| {
            PyValueError::new_err("a CounterBank's state is [(cv, cu_prev, cd_prev), …]")
        })?;
        if states.len() != self.n {
            return Err(PyValueError::new_err(format!(
                "the state has {} counters; this bank has {}",
                states.len(),
                self.n
            )));
        }
        self.bank.set_states(&states).map_err(|i| {
            let (lo, hi) = args::int_limits(self.int_type).unwrap_or_default();
            PyValueError::new_err(format!(
                "the CV of counter {i}, {}, is outside {}, {lo}..={hi}",
                states[i].0,
                self.int_type.name()
            ))
        })
    }

    fn __repr__(&self) -> String {
        format!("CounterBank({}, type={:?})", self.n, self.int_type.name())
    }
}

/// Adds the classes to the module.
pub fn register(m: &Bound<'_, PyModule>) -> PyResult<()> {
    m.add_class::<PyTonBank>()?;
    m.add_class::<PyCounterBank>()?;
    // An attribute, not `add_function`: that would list it in `__all__`, the public names.
    m.setattr(
        "_rust_ton_scan_seconds",
        wrap_pyfunction!(_rust_ton_scan_seconds, m)?,
    )?;
    Ok(())
}
