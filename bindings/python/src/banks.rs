//! `TonBank` and `CounterBank` over numpy arrays: one Python call per scan of thousands of
//! timers or counters. The core's banks are const-generic (`TonBank<N>`, `CounterBank<T, N>`);
//! a bank of `n` lanes here is a row of core banks of [`CHUNK`] lanes, the last one padded with
//! lanes whose inputs stay 0.

use std::time::Instant;

use numpy::{Element, PyArray1, PyArrayMethods, PyReadonlyArray1, PyUntypedArrayMethods};
use plc_timers::counter::{BankInputs, CounterBank, CounterInt};
use plc_timers::iec::TonBank;
use plc_timers::time::{CpuTime, Time};
use plc_timers_cli::trace::IntType;
use pyo3::exceptions::{PyTypeError, PyValueError};
use pyo3::prelude::*;
use pyo3::types::PyTuple;

use crate::args::{self, forward, shown, type_name};
use crate::blocks::{counter_pv, int_type};

/// Lanes per core bank: a multiple of the TON kernel's 16 lanes, small enough that a chunk's
/// inputs and state stay in the first-level cache while it is scanned.
pub const CHUNK: usize = 1024;

/// The most lanes a bank may have.
const MAX_LANES: usize = 1 << 24;

fn lanes(n: usize) -> PyResult<usize> {
    if n == 0 || n > MAX_LANES {
        return Err(PyValueError::new_err(format!(
            "n is the number of lanes, 1..={MAX_LANES}; got {n}"
        )));
    }
    Ok(n)
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
    let arr = obj.cast::<PyArray1<T>>().map_err(|_| {
        let got = match (obj.getattr("dtype"), obj.getattr("shape")) {
            (Ok(d), Ok(s)) => format!("an array of {} with shape {}", shown(&d), shown(&s)),
            _ => format!("{} ({})", shown(obj), type_name(obj)),
        };
        PyTypeError::new_err(format!("{}; got {got}", wanted()))
    })?;
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

/// The outputs of a TON bank's scan: Q and ET.
type TonArrays<'py> = (Bound<'py, PyArray1<bool>>, Bound<'py, PyArray1<i32>>);

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

/// `n` TON timers called together once per scan, each exactly as `TON` called once per scan
/// (IEC-BANK-01).
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
#[pyclass(module = "plc_timers", name = "TonBank")]
pub struct PyTonBank {
    banks: Vec<Box<TonBank<CHUNK>>>,
    n: usize,
    last: Option<CpuTime>,
    /// The PT of one chunk as `Time`s, reused for every chunk.
    pt: Box<[Time; CHUNK]>,
    /// The inputs of the last, padded chunk.
    tail: Box<[bool; CHUNK]>,
    /// One chunk's Q (for the last, shorter chunk) and ET (ms, before the cast to int32).
    q: Box<[bool; CHUNK]>,
    et: Box<[u32; CHUNK]>,
}

#[pymethods]
impl PyTonBank {
    /// A bank of `n` new timers.
    #[new]
    fn new(n: usize) -> PyResult<Self> {
        let n = lanes(n)?;
        Ok(PyTonBank {
            banks: (0..n.div_ceil(CHUNK)).map(|_| Box::default()).collect(),
            n,
            last: None,
            pt: Box::new([Time::from_millis(0); CHUNK]),
            tail: Box::new([false; CHUNK]),
            q: Box::new([false; CHUNK]),
            et: Box::new([0; CHUNK]),
        })
    }

    fn __len__(&self) -> usize {
        self.n
    }

    /// One scan at CPU time `now_ms`: timer `i` called as TON with IN = `in_[i]` and PT =
    /// `pt[i]` (ms). `in_` is a numpy array of bool, `pt` of int32, both of length `n`.
    /// Returns `(q, et)`: arrays of bool and int32 (ms), new ones or those of `out=(q, et)`.
    #[pyo3(signature = (now_ms, in_, pt, *, out = None))]
    fn scan<'py>(
        &mut self,
        py: Python<'py>,
        now_ms: &Bound<'py, PyAny>,
        in_: &Bound<'py, PyAny>,
        pt: &Bound<'py, PyAny>,
        out: Option<&Bound<'py, PyAny>>,
    ) -> PyResult<TonArrays<'py>> {
        let now = args::now_ms(now_ms)?;
        forward(now, self.last)?;
        let n = self.n;
        let input = array::<bool>(in_, "in_", "bool_", n)?;
        let preset = array::<i32>(pt, "pt", "int32", n)?;
        let (q_out, et_out) = out_pair(out)?;
        let q = output::<bool>(py, q_out.as_ref(), "q", "bool_", n)?;
        let et = output::<i32>(py, et_out.as_ref(), "et", "int32", n)?;
        // `array` checked that both are contiguous.
        let (input, preset) = match (input.as_slice(), preset.as_slice()) {
            (Ok(i), Ok(p)) => (i, p),
            _ => return Err(PyValueError::new_err("in_ and pt must be contiguous")),
        };
        // The outputs are borrowed before the scan, so that an array that cannot be written
        // (e.g. `in_` given again as an output) fails the call before any timer changes.
        let mut q_rw = writable(&q, "q")?;
        let mut et_rw = writable(&et, "et")?;
        let (q_all, et_all) = match (q_rw.as_slice_mut(), et_rw.as_slice_mut()) {
            (Ok(q), Ok(et)) => (q, et),
            _ => {
                return Err(PyValueError::new_err(
                    "the output arrays must be contiguous",
                ))
            }
        };
        self.last = Some(now);
        let chunks = self
            .banks
            .iter_mut()
            .zip(q_all.chunks_mut(CHUNK).zip(et_all.chunks_mut(CHUNK)))
            .zip(input.chunks(CHUNK).zip(preset.chunks(CHUNK)));
        for ((bank, (q, et)), (input, preset)) in chunks {
            for (t, &ms) in self.pt.iter_mut().zip(preset) {
                *t = Time::from_millis(ms);
            }
            let inputs: &[bool; CHUNK] = match <&[bool; CHUNK]>::try_from(input) {
                Ok(full) => full,
                Err(_) => {
                    self.tail[..input.len()].copy_from_slice(input);
                    &self.tail
                }
            };
            bank.scan(now, inputs, &self.pt);
            // Q and ET of the chunk just scanned, while its state is in cache.
            match <&mut [bool; CHUNK]>::try_from(&mut *q) {
                Ok(full) => bank.outputs_into(full, &mut self.et),
                Err(_) => {
                    bank.outputs_into(&mut self.q, &mut self.et);
                    q.copy_from_slice(&self.q[..q.len()]);
                }
            }
            for (slot, &v) in et.iter_mut().zip(self.et.iter()) {
                // ET <= PT <= 2**31-1 (IecState::is_valid): the cast keeps the value.
                *slot = v as i32;
            }
        }
        Ok((q, et))
    }

    /// The outputs of timer `i` (Q, ET) after the last scan.
    fn output(&self, i: usize) -> PyResult<crate::blocks::PyIecOutput> {
        self.banks
            .get(i / CHUNK)
            .filter(|_| i < self.n)
            // `i % CHUNK` is always a timer of the chunk: the bound that matters is `self.n`,
            // whose message says what exists in this bank.
            .and_then(|b| b.output(i % CHUNK).ok())
            .map(Into::into)
            .ok_or_else(|| {
                pyo3::exceptions::PyIndexError::new_err(format!(
                    "no timer {i}: this bank has 0 to {}",
                    self.n - 1
                ))
            })
    }

    fn __repr__(&self) -> String {
        format!("TonBank({})", self.n)
    }
}

/// The seconds one scan of the core's `TonBank<10048>` takes in Rust, timed over `scans` scans
/// with the inputs of `inputs` in turn (a list of bool arrays) and `pt` (int32): the figure
/// `bench.py` compares the numpy bank with. Not part of the API.
#[pyfunction]
fn _rust_ton_scan_seconds(
    inputs: Vec<PyReadonlyArray1<'_, bool>>,
    pt: PyReadonlyArray1<'_, i32>,
    scans: u64,
) -> PyResult<f64> {
    const N: usize = 10_048;
    let to_array = |s: Result<&[bool], _>| -> PyResult<Box<[bool; N]>> {
        s.ok()
            .and_then(|s: &[bool]| Box::<[bool; N]>::try_from(s.to_vec().into_boxed_slice()).ok())
            .ok_or_else(|| {
                PyValueError::new_err(format!("inputs are contiguous arrays of {N} bools"))
            })
    };
    let scans_in: Vec<Box<[bool; N]>> = inputs
        .iter()
        .map(|a| to_array(a.as_slice()))
        .collect::<PyResult<_>>()?;
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
    fn scan<'py>(
        &mut self,
        py: Python<'py>,
        inputs: [Option<&[bool]>; 4],
        pv: i128,
        out: [Option<Bound<'py, PyAny>>; 3],
    ) -> PyResult<Bound<'py, PyTuple>>;
}

struct Lanes<T> {
    banks: Vec<Box<CounterBank<T, CHUNK>>>,
    n: usize,
    /// The inputs of one chunk: CU, CD, R, LD.
    buf: Box<[[bool; CHUNK]; 4]>,
    dtype: &'static str,
}

impl<T: CounterInt + Element> AnyBank for Lanes<T> {
    fn scan<'py>(
        &mut self,
        py: Python<'py>,
        inputs: [Option<&[bool]>; 4],
        pv: i128,
        out: [Option<Bound<'py, PyAny>>; 3],
    ) -> PyResult<Bound<'py, PyTuple>> {
        let n = self.n;
        let pv = T::from_i128(pv)
            .ok_or_else(|| PyValueError::new_err(format!("pv {pv} is outside the type")))?;
        let [qu_out, qd_out, cv_out] = out;
        let qu = output::<bool>(py, qu_out.as_ref(), "qu", "bool_", n)?;
        let qd = output::<bool>(py, qd_out.as_ref(), "qd", "bool_", n)?;
        let cv = output::<T>(py, cv_out.as_ref(), "cv", self.dtype, n)?;
        // The outputs are borrowed before the scan, so that an array that cannot be written
        // fails the call before any counter changes.
        let mut qu_rw = writable(&qu, "qu")?;
        let mut qd_rw = writable(&qd, "qd")?;
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
        for (k, (bank, ((qu, qd), cv))) in self.banks.iter_mut().zip(outs).enumerate() {
            let lo = k * CHUNK;
            let hi = (lo + CHUNK).min(n);
            for (buf, given) in self.buf.iter_mut().zip(&inputs) {
                match given {
                    Some(s) => buf[..hi - lo].copy_from_slice(&s[lo..hi]),
                    None => buf[..hi - lo].fill(false),
                }
            }
            let [cu, cd, r, ld] = &*self.buf;
            bank.scan(&BankInputs { cu, cd, r, ld }, pv);
            let slots = qu.iter_mut().zip(qd.iter_mut()).zip(cv.iter_mut());
            for (((qu, qd), cv), o) in slots.zip(bank.outputs(pv)) {
                *qu = o.qu;
                *qd = o.qd;
                *cv = o.cv;
            }
        }
        drop((qu_rw, qd_rw, cv_rw));
        PyTuple::new(py, [qu.into_any(), qd.into_any(), cv.into_any()])
    }
}

fn lanes_of<T: CounterInt + Element>(n: usize, dtype: &'static str) -> Box<dyn AnyBank> {
    Box::new(Lanes::<T> {
        banks: (0..n.div_ceil(CHUNK)).map(|_| Box::default()).collect(),
        n,
        buf: Box::new([[false; CHUNK]; 4]),
        dtype,
    })
}

/// The numpy dtype name of the integer type `t`.
fn dtype_of(t: IntType) -> &'static str {
    match t {
        IntType::SInt => "int8",
        IntType::Int => "int16",
        IntType::DInt => "int32",
        IntType::LInt => "int64",
        IntType::USInt => "uint8",
        IntType::UInt => "uint16",
        IntType::UDInt => "uint32",
        IntType::ULInt => "uint64",
    }
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
#[pyclass(module = "plc_timers", name = "CounterBank")]
pub struct PyCounterBank {
    bank: Box<dyn AnyBank>,
    n: usize,
    int_type: IntType,
}

#[pymethods]
impl PyCounterBank {
    /// A bank of `n` new counters of integer type `type` (SINT … ULINT, default INT).
    #[new]
    #[pyo3(signature = (n, r#type = "INT"))]
    fn new(n: usize, r#type: &str) -> PyResult<Self> {
        let n = lanes(n)?;
        let t = int_type(r#type)?;
        let bank = match t {
            IntType::SInt => lanes_of::<i8>(n, dtype_of(t)),
            IntType::Int => lanes_of::<i16>(n, dtype_of(t)),
            IntType::DInt => lanes_of::<i32>(n, dtype_of(t)),
            IntType::LInt => lanes_of::<i64>(n, dtype_of(t)),
            IntType::USInt => lanes_of::<u8>(n, dtype_of(t)),
            IntType::UInt => lanes_of::<u16>(n, dtype_of(t)),
            IntType::UDInt => lanes_of::<u32>(n, dtype_of(t)),
            IntType::ULInt => lanes_of::<u64>(n, dtype_of(t)),
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
    /// `ld[i]` (numpy arrays of bool of length `n`; an input not given is 0) and preset `pv`.
    /// Returns `(qu, qd, cv)`: arrays of bool, bool and the type's dtype, new ones or those of
    /// `out=(qu, qd, cv)`.
    #[pyo3(signature = (*, pv, cu = None, cd = None, r = None, ld = None, out = None))]
    #[allow(clippy::too_many_arguments)]
    fn scan<'py>(
        &mut self,
        py: Python<'py>,
        pv: &Bound<'py, PyAny>,
        cu: Option<&Bound<'py, PyAny>>,
        cd: Option<&Bound<'py, PyAny>>,
        r: Option<&Bound<'py, PyAny>>,
        ld: Option<&Bound<'py, PyAny>>,
        out: Option<&Bound<'py, PyAny>>,
    ) -> PyResult<Bound<'py, PyTuple>> {
        let n = self.n;
        let pv = counter_pv(pv, self.int_type, "pv")?;
        let read = |a: Option<&Bound<'py, PyAny>>, what: &str| {
            a.map(|a| array::<bool>(a, what, "bool_", n)).transpose()
        };
        let arrays = [
            read(cu, "cu")?,
            read(cd, "cd")?,
            read(r, "r")?,
            read(ld, "ld")?,
        ];
        let mut slices: [Option<&[bool]>; 4] = [None; 4];
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

    fn __repr__(&self) -> String {
        format!("CounterBank({}, type={:?})", self.n, self.int_type.name())
    }
}

/// Adds the classes to the module.
pub fn register(m: &Bound<'_, PyModule>) -> PyResult<()> {
    m.add_class::<PyTonBank>()?;
    m.add_class::<PyCounterBank>()?;
    m.add_function(wrap_pyfunction!(_rust_ton_scan_seconds, m)?)?;
    Ok(())
}
