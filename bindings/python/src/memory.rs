//! The S5 timer and counter memory areas (`T 0` … and `Z/C 0` …) with their STL operations.
//! The core's areas are const-generic; an area here has one of the sizes S7-300/400 CPUs had.

use plc_timers::catalog::{Family, Kind, Port};
use plc_timers::counter::s5::{CounterMemory, S5Counter, S5CounterInput, S5CounterKind};
use plc_timers::s5::{S5Input, S5Kind, TimerMemory, TimerWord};
use plc_timers::time::{CpuTime, TimeBase};
use plc_timers::NoSuchOperand;
use pyo3::exceptions::{PyIndexError, PyValueError};
use pyo3::prelude::*;
use pyo3::types::PyType;

use crate::args::{self, block_of, forward};
use crate::blocks::{PyS5CounterOutput, PyS5Output};

/// The sizes an area may have.
const SIZES: [usize; 6] = [64, 128, 256, 512, 1024, 2048];

/// An operand number: a whole number 0 and up (the area says which exist).
fn operand(obj: &Bound<'_, PyAny>) -> PyResult<usize> {
    args::int_in::<usize>(obj, "index", "an operand number, 0 and up (T 0, C 0, …)")
}

fn no_such(e: NoSuchOperand) -> PyErr {
    PyIndexError::new_err(e.to_string())
}

/// An area size (a negative one is a `ValueError` saying what is allowed, not pyo3's
/// `OverflowError`).
fn area_size(count: i128) -> PyResult<usize> {
    usize::try_from(count)
        .ok()
        .filter(|c| SIZES.contains(c))
        .ok_or_else(|| size_error(count))
}

fn size_error(count: i128) -> PyErr {
    let sizes: Vec<String> = SIZES.iter().map(usize::to_string).collect();
    PyValueError::new_err(format!(
        "count {count} is not an area size; an area has {} operands",
        sizes.join(", ")
    ))
}

macro_rules! sized {
    ($area:ident, $ty:ident) => {
        /// An area of one of [`SIZES`].
        #[derive(Clone)]
        enum $area {
            N64(Box<$ty<64>>),
            N128(Box<$ty<128>>),
            N256(Box<$ty<256>>),
            N512(Box<$ty<512>>),
            N1024(Box<$ty<1024>>),
            N2048(Box<$ty<2048>>),
        }

        impl $area {
            fn new(count: i128) -> PyResult<$area> {
                let count = area_size(count)?;
                Ok(match count {
                    64 => $area::N64(Box::default()),
                    128 => $area::N128(Box::default()),
                    256 => $area::N256(Box::default()),
                    512 => $area::N512(Box::default()),
                    1024 => $area::N1024(Box::default()),
                    2048 => $area::N2048(Box::default()),
                    _ => return Err(size_error(count as i128)),
                })
            }
        }
    };
}

/// Runs `$body` with `$m` bound to the area, whatever its size.
macro_rules! with {
    ($area:ident, $self:expr, $m:ident => $body:expr) => {
        match $self {
            $area::N64($m) => $body,
            $area::N128($m) => $body,
            $area::N256($m) => $body,
            $area::N512($m) => $body,
            $area::N1024($m) => $body,
            $area::N2048($m) => $body,
        }
    };
}

/// The arguments `__reduce__` gives pickle for a `TimerMemory`.
type TimerMemoryReduce<'py> = (Bound<'py, PyType>, (usize,), (u64, Option<u64>, Vec<u32>));

/// The arguments `__reduce__` gives pickle for a `CounterMemory`.
type CounterMemoryReduce<'py> = (Bound<'py, PyType>, (usize,), (Vec<u16>,));

/// An area of `N` timers holding `words` (`N` of them), ticked up to `now`.
fn timer_area<const N: usize>(words: &[TimerWord], now: CpuTime) -> PyResult<Box<TimerMemory<N>>> {
    let words: [TimerWord; N] = words.try_into().map_err(|_| {
        PyValueError::new_err(format!(
            "an area of {N} timers needs {N} words; got {}",
            words.len()
        ))
    })?;
    Ok(Box::new(TimerMemory::from_words(words, now)))
}

sized!(TimerArea, TimerMemory);
sized!(CounterArea, CounterMemory);

fn s5_kind(name: &str) -> PyResult<S5Kind> {
    match block_of(name, Family::S5Timer, "kind")?.kind() {
        Kind::S5Timer(k) => Ok(k),
        _ => Err(PyValueError::new_err(format!("{name} is not an S5 timer"))),
    }
}

fn time_base(ms: &Bound<'_, PyAny>) -> PyResult<TimeBase> {
    let ms = args::int_in::<u32>(ms, "base_ms", "a time base in ms: 10, 100, 1000 or 10000")?;
    TimeBase::ALL
        .into_iter()
        .find(|b| b.millis() == ms)
        .ok_or_else(|| {
            PyValueError::new_err(format!(
                "base_ms {ms} is not a time base; the bases are 10, 100, 1000 and 10000 ms"
            ))
        })
}

/// The S5 timer memory area `T 0` … `T count-1` (optimized words), with the operating
/// system's tick and the STL operations `FR`, `SP`…`SF`, `R`, `L`, `LC`, `A`.
///
/// >>> from plc_timers import TimerMemory
/// >>> area = TimerMemory(64)
/// >>> area.advance_to(0)
/// >>> area.start(3, "SD", True, "S5T#200MS")  # A I 0.0; L S5T#200MS; SD T 3
/// >>> area.advance_to(150); (area.status(3), area.load(3))
/// (False, 5)
/// >>> area.advance_to(200); area.status(3)
/// True
#[pyclass(module = "plc_timers", name = "TimerMemory")]
#[derive(Clone)]
pub struct PyTimerMemory {
    area: TimerArea,
    count: usize,
    last: Option<CpuTime>,
}

#[pymethods]
impl PyTimerMemory {
    /// An area of `count` cleared timers: 64, 128, 256, 512, 1024 or 2048.
    #[new]
    #[pyo3(signature = (count = 256))]
    fn new(count: i128) -> PyResult<Self> {
        let area = TimerArea::new(count)?;
        Ok(PyTimerMemory {
            count: with!(TimerArea, &area, m => m.words().len()),
            area,
            last: None,
        })
    }

    /// A copy with the same timers and clock: `copy.copy(area)` and `copy.deepcopy(area)` (a
    /// snapshot to go back to).
    fn __copy__(&self) -> Self {
        self.clone()
    }

    fn __deepcopy__(&self, _memo: &Bound<'_, PyAny>) -> Self {
        self.clone()
    }

    /// For pickle: `TimerMemory(count)`, then the time the ticks reached, the last
    /// `advance_to` time and every timer word's 32 bits (`T 0` first).
    fn __reduce__<'py>(slf: &Bound<'py, Self>) -> PyResult<TimerMemoryReduce<'py>> {
        let this = slf.borrow();
        let now = with!(TimerArea, &this.area, m => m.now().as_millis());
        let words: Vec<u32> =
            with!(TimerArea, &this.area, m => m.words().map(TimerWord::bits).collect());
        let last = this.last.map(CpuTime::as_millis);
        Ok((slf.get_type(), (this.count,), (now, last, words)))
    }

    /// Restores what `__reduce__` saved; a word no timer can hold is a `ValueError`.
    fn __setstate__(&mut self, state: &Bound<'_, PyAny>) -> PyResult<()> {
        let (now, last, bits): (u64, Option<u64>, Vec<u32>) = state.extract().map_err(|_| {
            PyValueError::new_err("a TimerMemory's state is (now_ms, last_ms, [word, …])")
        })?;
        if bits.len() != self.count {
            return Err(PyValueError::new_err(format!(
                "the state has {} timers; this area has {}",
                bits.len(),
                self.count
            )));
        }
        let mut words = Vec::with_capacity(bits.len());
        for (i, &b) in bits.iter().enumerate() {
            words.push(TimerWord::from_bits(b).ok_or_else(|| {
                PyValueError::new_err(format!("T {i}: 0x{b:08X} is not a timer word"))
            })?);
        }
        let now = CpuTime::from_millis(now);
        self.area = match &self.area {
            TimerArea::N64(_) => TimerArea::N64(timer_area(&words, now)?),
            TimerArea::N128(_) => TimerArea::N128(timer_area(&words, now)?),
            TimerArea::N256(_) => TimerArea::N256(timer_area(&words, now)?),
            TimerArea::N512(_) => TimerArea::N512(timer_area(&words, now)?),
            TimerArea::N1024(_) => TimerArea::N1024(timer_area(&words, now)?),
            TimerArea::N2048(_) => TimerArea::N2048(timer_area(&words, now)?),
        };
        self.last = last.map(CpuTime::from_millis);
        Ok(())
    }

    fn __len__(&self) -> usize {
        self.count
    }

    /// The CPU time the area's clock has reached (ms).
    #[getter]
    fn now_ms(&self) -> u64 {
        with!(TimerArea, &self.area, m => m.now().as_millis())
    }

    /// The operating system's ticks up to CPU time `now_ms`.
    fn advance_to(&mut self, now_ms: &Bound<'_, PyAny>) -> PyResult<()> {
        let now = args::now_ms(now_ms)?;
        forward(now, self.last)?;
        self.last = Some(now);
        with!(TimerArea, &mut self.area, m => m.advance_to(now));
        Ok(())
    }

    /// `n` ticks of the time base `base_ms` (10, 100, 1000, 10000) on every running timer.
    fn tick(&mut self, base_ms: &Bound<'_, PyAny>, n: &Bound<'_, PyAny>) -> PyResult<()> {
        let base = time_base(base_ms)?;
        let n = args::int_in::<u64>(n, "n", "a number of ticks, 0..=18446744073709551615")?;
        with!(TimerArea, &mut self.area, m => m.tick(base, n));
        Ok(())
    }

    /// `FR T index` with RLO `rlo`.
    fn fr(&mut self, index: &Bound<'_, PyAny>, rlo: bool) -> PyResult<()> {
        let index = operand(index)?;
        with!(TimerArea, &mut self.area, m => m.fr(index, rlo)).map_err(no_such)
    }

    /// `SP`/`SE`/`SD`/`SS`/`SF T index` (kind by STL or block name: "SD" or "S_ODT") with RLO
    /// `rlo` and the time value `tv` in ACCU 1 (a literal, a word or an `S5Time`).
    fn start(
        &mut self,
        index: &Bound<'_, PyAny>,
        kind: &str,
        rlo: bool,
        tv: &Bound<'_, PyAny>,
    ) -> PyResult<()> {
        let index = operand(index)?;
        let kind = s5_kind(kind)?;
        let tv = args::s5time(tv, "tv")?;
        with!(TimerArea, &mut self.area, m => m.start(index, kind, rlo, tv)).map_err(no_such)
    }

    /// `R T index` with RLO `rlo`.
    fn reset(&mut self, index: &Bound<'_, PyAny>, rlo: bool) -> PyResult<()> {
        let index = operand(index)?;
        with!(TimerArea, &mut self.area, m => m.reset(index, rlo)).map_err(no_such)
    }

    /// `L T index`: the remaining value in binary (units of the base).
    fn load(&self, index: &Bound<'_, PyAny>) -> PyResult<u16> {
        let index = operand(index)?;
        with!(TimerArea, &self.area, m => m.load(index)).map_err(no_such)
    }

    /// `LC T index`: the remaining value in BCD with the base in bits 13-12.
    fn load_bcd(&self, index: &Bound<'_, PyAny>) -> PyResult<u16> {
        let index = operand(index)?;
        with!(TimerArea, &self.area, m => m.load_bcd(index)).map_err(no_such)
    }

    /// `A T index`: the timer status.
    fn status(&self, index: &Bound<'_, PyAny>) -> PyResult<bool> {
        let index = operand(index)?;
        with!(TimerArea, &self.area, m => m.status(index)).map_err(no_such)
    }

    /// The LAD box `kind` on timer `index` at `now_ms`: the OS ticks up to `now_ms`, then FR,
    /// the start operation and R.
    #[pyo3(signature = (index, kind, now_ms, s = false, r = false, fr = false, tv = None))]
    #[allow(clippy::too_many_arguments)]
    fn call(
        &mut self,
        index: &Bound<'_, PyAny>,
        kind: &str,
        now_ms: &Bound<'_, PyAny>,
        s: bool,
        r: bool,
        fr: bool,
        tv: Option<&Bound<'_, PyAny>>,
    ) -> PyResult<PyS5Output> {
        let index = operand(index)?;
        let kind = s5_kind(kind)?;
        let now = args::now_ms(now_ms)?;
        forward(now, self.last)?;
        let tv =
            match tv {
                Some(t) => args::s5time(t, "tv")?,
                None => return Err(PyValueError::new_err(
                    "tv is needed: the time value the box loads (a literal, a word or an S5Time)",
                )),
            };
        let input = S5Input::new(s, r, tv).with_fr(fr);
        let out = with!(TimerArea, &mut self.area, m => m.call(index, kind, now, input))
            .map_err(no_such)?;
        self.last = Some(now);
        Ok(out.into())
    }

    /// The outputs of timer `index` (Q, BI, BCD) without a tick.
    fn output(&self, index: &Bound<'_, PyAny>) -> PyResult<PyS5Output> {
        let index = operand(index)?;
        let state = with!(TimerArea, &self.area, m => m.get(index)).map_err(no_such)?;
        Ok(state.output().into())
    }

    fn __repr__(&self) -> String {
        format!("TimerMemory({})", self.count)
    }
}

/// The S5 counter memory area `C 0` … `C count-1` (optimized words), with the STL operations
/// `FR`, `CU`, `CD`, `S`, `R`, `L`, `LC`, `A`.
///
/// >>> from plc_timers import CounterMemory
/// >>> area = CounterMemory(64)
/// >>> area.set(5, True, "C#2")  # L C#2; S C 5
/// >>> area.cd(5, True); area.cd(5, False); area.cd(5, True)
/// >>> (area.load(5), area.status(5))
/// (0, False)
#[pyclass(module = "plc_timers", name = "CounterMemory")]
#[derive(Clone)]
pub struct PyCounterMemory {
    area: CounterArea,
    count: usize,
}

#[pymethods]
impl PyCounterMemory {
    /// An area of `count` cleared counters: 64, 128, 256, 512, 1024 or 2048.
    #[new]
    #[pyo3(signature = (count = 256))]
    fn new(count: i128) -> PyResult<Self> {
        let area = CounterArea::new(count)?;
        Ok(PyCounterMemory {
            count: with!(CounterArea, &area, m => m.words().len()),
            area,
        })
    }

    /// A copy with the same counters: `copy.copy(area)` and `copy.deepcopy(area)` (a snapshot
    /// to go back to).
    fn __copy__(&self) -> Self {
        self.clone()
    }

    fn __deepcopy__(&self, _memo: &Bound<'_, PyAny>) -> Self {
        self.clone()
    }

    /// For pickle: `CounterMemory(count)`, then every counter word's 16 bits (`C 0` first).
    fn __reduce__<'py>(slf: &Bound<'py, Self>) -> PyResult<CounterMemoryReduce<'py>> {
        let this = slf.borrow();
        let words =
            with!(CounterArea, &this.area, m => m.words().iter().map(|w| w.bits()).collect());
        Ok((slf.get_type(), (this.count,), (words,)))
    }

    /// Restores what `__reduce__` saved; a word no counter can hold is a `ValueError`.
    fn __setstate__(&mut self, state: &Bound<'_, PyAny>) -> PyResult<()> {
        let (bits,): (Vec<u16>,) = state
            .extract()
            .map_err(|_| PyValueError::new_err("a CounterMemory's state is ([word, …],)"))?;
        if bits.len() != self.count {
            return Err(PyValueError::new_err(format!(
                "the state has {} counters; this area has {}",
                bits.len(),
                self.count
            )));
        }
        let mut area = self.area.clone();
        for (i, &b) in bits.iter().enumerate() {
            let state = S5Counter::from_bits(b)
                .map(S5Counter::state)
                .ok_or_else(|| {
                    PyValueError::new_err(format!("C {i}: 0x{b:04X} is not a counter word"))
                })?;
            let set = with!(CounterArea, &mut area, m => m.set_state(i, state)).map_err(no_such)?;
            if !set {
                return Err(PyValueError::new_err(format!(
                    "C {i}: 0x{b:04X} is not a counter word"
                )));
            }
        }
        self.area = area;
        Ok(())
    }

    fn __len__(&self) -> usize {
        self.count
    }

    /// `FR C index` with RLO `rlo`.
    fn fr(&mut self, index: &Bound<'_, PyAny>, rlo: bool) -> PyResult<()> {
        let index = operand(index)?;
        with!(CounterArea, &mut self.area, m => m.fr(index, rlo)).map_err(no_such)
    }

    /// `CU C index` with RLO `rlo`: counts up on a rising RLO.
    fn cu(&mut self, index: &Bound<'_, PyAny>, rlo: bool) -> PyResult<()> {
        let index = operand(index)?;
        with!(CounterArea, &mut self.area, m => m.cu(index, rlo)).map_err(no_such)
    }

    /// `CD C index` with RLO `rlo`: counts down on a rising RLO.
    fn cd(&mut self, index: &Bound<'_, PyAny>, rlo: bool) -> PyResult<()> {
        let index = operand(index)?;
        with!(CounterArea, &mut self.area, m => m.cd(index, rlo)).map_err(no_such)
    }

    /// `S C index` with RLO `rlo` and the preset `pv` in ACCU 1 (a literal, an int 0..=999 or
    /// a `CounterPreset`).
    fn set(&mut self, index: &Bound<'_, PyAny>, rlo: bool, pv: &Bound<'_, PyAny>) -> PyResult<()> {
        let index = operand(index)?;
        let pv = args::counter_preset(pv, "pv")?;
        with!(CounterArea, &mut self.area, m => m.set(index, rlo, pv)).map_err(no_such)
    }

    /// `R C index` with RLO `rlo`.
    fn reset(&mut self, index: &Bound<'_, PyAny>, rlo: bool) -> PyResult<()> {
        let index = operand(index)?;
        with!(CounterArea, &mut self.area, m => m.reset(index, rlo)).map_err(no_such)
    }

    /// `L C index`: the count in binary.
    fn load(&self, index: &Bound<'_, PyAny>) -> PyResult<u16> {
        let index = operand(index)?;
        with!(CounterArea, &self.area, m => m.load(index)).map_err(no_such)
    }

    /// `LC C index`: the count in BCD.
    fn load_bcd(&self, index: &Bound<'_, PyAny>) -> PyResult<u16> {
        let index = operand(index)?;
        with!(CounterArea, &self.area, m => m.load_bcd(index)).map_err(no_such)
    }

    /// `A C index`: the counter status (count != 0).
    fn status(&self, index: &Bound<'_, PyAny>) -> PyResult<bool> {
        let index = operand(index)?;
        with!(CounterArea, &self.area, m => m.status(index)).map_err(no_such)
    }

    /// The LAD box `kind` ("S_CU", "S_CD", "S_CUD") on counter `index`.
    #[pyo3(signature = (index, kind, cu = false, cd = false, s = false, r = false, fr = false, pv = None))]
    #[allow(clippy::too_many_arguments)]
    fn call(
        &mut self,
        index: &Bound<'_, PyAny>,
        kind: &str,
        cu: bool,
        cd: bool,
        s: bool,
        r: bool,
        fr: bool,
        pv: Option<&Bound<'_, PyAny>>,
    ) -> PyResult<PyS5CounterOutput> {
        let index = operand(index)?;
        let block = block_of(kind, Family::S5Counter, "kind")?;
        let kind: S5CounterKind = match block.kind() {
            Kind::S5Counter(k) => k,
            _ => {
                return Err(PyValueError::new_err(format!(
                    "{kind} is not an S5 counter"
                )))
            }
        };
        for (port, v) in [(Port::Cu, cu), (Port::Cd, cd)] {
            if v && !block.has_input(port) {
                return Err(PyValueError::new_err(format!(
                    "{block} has no {} input; use S_CUD to count both ways",
                    port.name()
                )));
            }
        }
        // PV matters only when S sets the counter.
        let pv =
            match pv {
                Some(p) => args::counter_preset(p, "pv")?,
                None if s => return Err(PyValueError::new_err(
                    "pv is needed when s is True: the preset S loads (a literal such as \"C#5\", \
                     an int 0..=999 or a CounterPreset)",
                )),
                None => Default::default(),
            };
        let input = S5CounterInput {
            cu,
            cd,
            s,
            r,
            fr,
            pv,
        };
        let out =
            with!(CounterArea, &mut self.area, m => m.call(index, kind, input)).map_err(no_such)?;
        Ok(out.into())
    }

    /// The outputs of counter `index` (Q, CV, CV_BCD).
    fn output(&self, index: &Bound<'_, PyAny>) -> PyResult<PyS5CounterOutput> {
        let index = operand(index)?;
        let state = with!(CounterArea, &self.area, m => m.get(index)).map_err(no_such)?;
        Ok(state.output().into())
    }

    fn __repr__(&self) -> String {
        format!("CounterMemory({})", self.count)
    }
}

/// Adds the classes to the module.
pub fn register(m: &Bound<'_, PyModule>) -> PyResult<()> {
    m.add_class::<PyTimerMemory>()?;
    m.add_class::<PyCounterMemory>()?;
    Ok(())
}
