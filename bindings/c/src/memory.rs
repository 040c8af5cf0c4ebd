//! The memory areas of S7-300/400: a timer memory area of 256 S5 timers (`T 0` … `T 255`) and a
//! counter memory area of 256 S5 counters (`C 0` … `C 255`), with the STL operations on them.
//!
//! 256 is the number of timers and counters LAD can address, and the library's default area
//! size; the header gives it as `PLC_TIMERS_TIMER_COUNT` and `PLC_TIMERS_COUNTER_COUNT`. Each
//! call checks the whole area (every word a valid state) before it acts, so one corrupted word
//! is reported as `PLC_TIMERS_INVALID_STATE` by any operation on the area.

use plc_timers::counter::s5::{CounterMemory, S5Counter, S5CounterInput};
use plc_timers::s5::{TimerMemory, TimerWord};
use plc_timers::time::CpuTime;

use crate::counters::{
    counter_preset, counter_preset_bcd, plc_timers_bcd_word, plc_timers_s5_count,
    plc_timers_s5_counter_input, plc_timers_s5_counter_input_bcd, plc_timers_s5_counter_output,
    s5_counter_kind,
};
use crate::export::CInput;
use crate::status::plc_timers_status::{self, *};
use crate::timers::{plc_timers_s5_input, plc_timers_s5_output, s5_kind, s5time, time_base};
use crate::{bit, init, on_state, on_state_only, read_state, Mirror};

/// The number of timers in a `plc_timers_timer_memory`: `T 0` to `T 255`.
pub const PLC_TIMERS_TIMER_COUNT: usize = 256;
/// The number of counters in a `plc_timers_counter_memory`: `C 0` to `C 255`.
pub const PLC_TIMERS_COUNTER_COUNT: usize = 256;

/// A timer memory area: 256 timer words and the CPU time up to which the operating system's
/// ticks have been applied. 1032 bytes, alignment 8; all zero is an area of cleared timers at
/// 0 ms.
#[repr(C)]
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct plc_timers_timer_memory {
    /// The CPU time (ms) up to which the ticks have been applied.
    pub now_ms: u64,
    /// The timer words, `T 0` first, each laid out as `plc_timers_s5_timer.word`.
    pub words: [u32; PLC_TIMERS_TIMER_COUNT],
}

/// A counter memory area: 256 counter words. 512 bytes, alignment 2; all zero is an area of
/// cleared counters.
#[repr(C)]
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct plc_timers_counter_memory {
    /// The counter words, `C 0` first, each laid out as `plc_timers_s5_counter.word`.
    pub words: [u16; PLC_TIMERS_COUNTER_COUNT],
}

const _: () = assert!(core::mem::size_of::<plc_timers_timer_memory>() == 1032);
const _: () = assert!(core::mem::size_of::<plc_timers_counter_memory>() == 512);
const _: () = assert!(TimerMemory::<PLC_TIMERS_TIMER_COUNT>::LEN == 256);
const _: () = assert!(CounterMemory::<PLC_TIMERS_COUNTER_COUNT>::LEN == 256);

impl Mirror for plc_timers_timer_memory {
    type Core = TimerMemory<PLC_TIMERS_TIMER_COUNT>;

    fn load(&self) -> Option<Self::Core> {
        let mut words = [TimerWord::RESET; PLC_TIMERS_TIMER_COUNT];
        for (w, &bits) in words.iter_mut().zip(self.words.iter()) {
            *w = TimerWord::from_bits(bits)?;
        }
        Some(TimerMemory::from_words(
            words,
            CpuTime::from_millis(self.now_ms),
        ))
    }

    fn store(m: &Self::Core) -> Self {
        let mut words = [0; PLC_TIMERS_TIMER_COUNT];
        for (bits, w) in words.iter_mut().zip(m.words()) {
            *bits = w.bits();
        }
        plc_timers_timer_memory {
            now_ms: m.now().as_millis(),
            words,
        }
    }
}

impl Mirror for plc_timers_counter_memory {
    type Core = CounterMemory<PLC_TIMERS_COUNTER_COUNT>;

    fn load(&self) -> Option<Self::Core> {
        let mut area = CounterMemory::new();
        for (index, &bits) in self.words.iter().enumerate() {
            let counter = S5Counter::from_bits(bits)?;
            // `index` is below the area's size (both are 256), and a word that `from_bits`
            // accepted is a valid state: `set_state` gives `Ok(true)`.
            if area.set_state(index, counter.state()) != Ok(true) {
                return None;
            }
        }
        Some(area)
    }

    fn store(m: &Self::Core) -> Self {
        let mut words = [0; PLC_TIMERS_COUNTER_COUNT];
        for (bits, w) in words.iter_mut().zip(m.words().iter()) {
            *bits = w.bits();
        }
        plc_timers_counter_memory { words }
    }
}

/// The status of an operand outside the area.
fn no_such_operand<E>(_: E) -> plc_timers_status {
    PLC_TIMERS_NO_SUCH_OPERAND
}

/// Initializes a timer memory area: every timer cleared, the area's clock at 0 ms (the same as
/// zeroing it).
///
/// Returns `PLC_TIMERS_OK`; `PLC_TIMERS_NULL_POINTER` / `PLC_TIMERS_MISALIGNED_POINTER`.
///
/// # Safety
/// `timers` is NULL or points to writable memory for its type.
#[no_mangle]
pub unsafe extern "C" fn plc_timers_timer_memory_init(
    timers: *mut plc_timers_timer_memory,
) -> plc_timers_status {
    // SAFETY: the caller's contract.
    unsafe { init(timers, TimerMemory::new()) }
}

/// Advances the area's clock to `now_ms` (ms since the CPU started): the OS ticks of every time
/// base in (previous time, `now_ms`] are applied to every running timer of that base (ticks fall
/// on whole multiples of the base). An earlier time applies no ticks.
/// Call it once per scan before the STL operations.
///
/// Returns `PLC_TIMERS_OK`; `PLC_TIMERS_NULL_POINTER` / `PLC_TIMERS_MISALIGNED_POINTER`; `PLC_TIMERS_INVALID_STATE` (a word of the area).
///
/// # Safety
/// `timers` is NULL or points to memory valid for reads and writes of its type.
#[no_mangle]
pub unsafe extern "C" fn plc_timers_timer_memory_advance_to(
    timers: *mut plc_timers_timer_memory,
    now_ms: u64,
) -> plc_timers_status {
    // SAFETY: the caller's contract.
    unsafe {
        on_state_only(timers, |m| {
            m.advance_to(CpuTime::from_millis(now_ms));
            Ok(())
        })
    }
}

/// `n` OS ticks of the time base `base` (`plc_timers_time_base`) for the whole area: every
/// running timer of that base loses `min(n, value)` units. For a runtime whose own interrupt
/// provides the time bases; use it or `plc_timers_timer_memory_advance_to`, not both.
///
/// Returns `PLC_TIMERS_OK`; `PLC_TIMERS_NULL_POINTER` / `PLC_TIMERS_MISALIGNED_POINTER`; `PLC_TIMERS_INVALID_STATE` (a word of the area); `PLC_TIMERS_INVALID_TIME_BASE`.
///
/// # Safety
/// `timers` is NULL or points to memory valid for reads and writes of its type.
#[no_mangle]
pub unsafe extern "C" fn plc_timers_timer_memory_tick(
    timers: *mut plc_timers_timer_memory,
    base: i32,
    n: u64,
) -> plc_timers_status {
    // SAFETY: the caller's contract.
    unsafe {
        on_state_only(timers, |m| {
            m.tick(time_base(base)?, n);
            Ok(())
        })
    }
}

/// `FR T index` with RLO `rlo` (enable): a rising RLO clears the start edge memory, so that a
/// start operation with RLO 1 restarts the timer.
///
/// Returns `PLC_TIMERS_OK`; `PLC_TIMERS_NULL_POINTER` / `PLC_TIMERS_MISALIGNED_POINTER`; `PLC_TIMERS_INVALID_STATE` (a word of the area); `PLC_TIMERS_NO_SUCH_OPERAND` (`index` above 255).
///
/// # Safety
/// `timers` is NULL or points to memory valid for reads and writes of its type.
#[no_mangle]
pub unsafe extern "C" fn plc_timers_timer_memory_fr(
    timers: *mut plc_timers_timer_memory,
    index: usize,
    rlo: u8,
) -> plc_timers_status {
    // SAFETY: the caller's contract.
    unsafe { on_state_only(timers, |m| m.fr(index, bit(rlo)).map_err(no_such_operand)) }
}

/// `SP`/`SE`/`SD`/`SS`/`SF T index` (the start operation of `kind`, a `plc_timers_s5_kind`)
/// with RLO `rlo` and the time value `tv` (an S5TIME word, as loaded in ACCU 1).
///
/// Returns `PLC_TIMERS_OK`; `PLC_TIMERS_NULL_POINTER` / `PLC_TIMERS_MISALIGNED_POINTER`; `PLC_TIMERS_INVALID_STATE` (a word of the area); `PLC_TIMERS_NO_SUCH_OPERAND` (`index` above 255); `PLC_TIMERS_INVALID_KIND`; `PLC_TIMERS_INVALID_S5TIME` (`tv`).
///
/// # Safety
/// `timers` is NULL or points to memory valid for reads and writes of its type.
#[no_mangle]
pub unsafe extern "C" fn plc_timers_timer_memory_start(
    timers: *mut plc_timers_timer_memory,
    index: usize,
    kind: i32,
    rlo: u8,
    tv: u16,
) -> plc_timers_status {
    // SAFETY: the caller's contract.
    unsafe {
        on_state_only(timers, |m| {
            let kind = s5_kind(kind)?;
            let tv = s5time(tv)?;
            m.start(index, kind, bit(rlo), tv).map_err(no_such_operand)
        })
    }
}

/// `R T index` with RLO `rlo`: RLO 1 stops the timer and clears its value and status.
///
/// Returns `PLC_TIMERS_OK`; `PLC_TIMERS_NULL_POINTER` / `PLC_TIMERS_MISALIGNED_POINTER`; `PLC_TIMERS_INVALID_STATE` (a word of the area); `PLC_TIMERS_NO_SUCH_OPERAND` (`index` above 255).
///
/// # Safety
/// `timers` is NULL or points to memory valid for reads and writes of its type.
#[no_mangle]
pub unsafe extern "C" fn plc_timers_timer_memory_reset(
    timers: *mut plc_timers_timer_memory,
    index: usize,
    rlo: u8,
) -> plc_timers_status {
    // SAFETY: the caller's contract.
    unsafe {
        on_state_only(timers, |m| {
            m.reset(index, bit(rlo)).map_err(no_such_operand)
        })
    }
}

/// `L T index`: writes the remaining value of the timer, in binary (units of its base, 0 to
/// 999), to `value`.
///
/// Returns `PLC_TIMERS_OK`; `PLC_TIMERS_NULL_POINTER` / `PLC_TIMERS_MISALIGNED_POINTER`; `PLC_TIMERS_INVALID_STATE` (a word of the area); `PLC_TIMERS_NO_SUCH_OPERAND` (`index` above 255).
///
/// # Safety
/// `timers` is NULL or points to memory valid for reads of its type; `value` is NULL or points to memory valid for writes of its type.
#[no_mangle]
pub unsafe extern "C" fn plc_timers_timer_memory_load(
    timers: *const plc_timers_timer_memory,
    index: usize,
    value: *mut u16,
) -> plc_timers_status {
    // SAFETY: the caller's contract.
    unsafe { read_state(timers, value, |m| m.load(index).map_err(no_such_operand)) }
}

/// `LC T index`: writes the remaining value of the timer as three BCD digits with the time base
/// in bits 13-12 to `value`.
///
/// Returns `PLC_TIMERS_OK`; `PLC_TIMERS_NULL_POINTER` / `PLC_TIMERS_MISALIGNED_POINTER`; `PLC_TIMERS_INVALID_STATE` (a word of the area); `PLC_TIMERS_NO_SUCH_OPERAND` (`index` above 255).
///
/// # Safety
/// `timers` is NULL or points to memory valid for reads of its type; `value` is NULL or points to memory valid for writes of its type.
#[no_mangle]
pub unsafe extern "C" fn plc_timers_timer_memory_load_bcd(
    timers: *const plc_timers_timer_memory,
    index: usize,
    value: *mut u16,
) -> plc_timers_status {
    // SAFETY: the caller's contract.
    unsafe {
        read_state(timers, value, |m| {
            m.load_bcd(index).map_err(no_such_operand)
        })
    }
}

/// `A T index`: writes the timer status to `q` (`AN T index` is its negation).
///
/// Returns `PLC_TIMERS_OK`; `PLC_TIMERS_NULL_POINTER` / `PLC_TIMERS_MISALIGNED_POINTER`; `PLC_TIMERS_INVALID_STATE` (a word of the area); `PLC_TIMERS_NO_SUCH_OPERAND` (`index` above 255).
///
/// # Safety
/// `timers` is NULL or points to memory valid for reads of its type; `q` is NULL or points to memory valid for writes of its type.
#[no_mangle]
pub unsafe extern "C" fn plc_timers_timer_memory_status(
    timers: *const plc_timers_timer_memory,
    index: usize,
    q: *mut bool,
) -> plc_timers_status {
    // SAFETY: the caller's contract.
    unsafe { read_state(timers, q, |m| m.status(index).map_err(no_such_operand)) }
}

/// The LAD box `kind` (`plc_timers_s5_kind`) on timer `index` at CPU time `now_ms`: the area's
/// clock is advanced to `now_ms` (as `plc_timers_timer_memory_advance_to`), then `FR`, the start
/// operation and `R` run as the box compiles to STL. The outputs are written to `out`.
///
/// Returns `PLC_TIMERS_OK`; `PLC_TIMERS_NULL_POINTER` / `PLC_TIMERS_MISALIGNED_POINTER`; `PLC_TIMERS_INVALID_STATE` (a word of the area); `PLC_TIMERS_NO_SUCH_OPERAND` (`index` above 255); `PLC_TIMERS_INVALID_KIND`; `PLC_TIMERS_INVALID_S5TIME` (`input.tv`).
///
/// # Safety
/// `timers` and `out` are NULL or point to memory valid for reads and writes of their types.
#[no_mangle]
pub unsafe extern "C" fn plc_timers_timer_memory_call(
    timers: *mut plc_timers_timer_memory,
    index: usize,
    kind: i32,
    now_ms: u64,
    input: plc_timers_s5_input,
    out: *mut plc_timers_s5_output,
) -> plc_timers_status {
    // SAFETY: the caller's contract.
    unsafe {
        on_state(timers, out, |m| {
            let kind = s5_kind(kind)?;
            let input = input.load()?;
            m.call(index, kind, CpuTime::from_millis(now_ms), input)
                .map(Into::into)
                .map_err(no_such_operand)
        })
    }
}

/// Initializes a counter memory area: every counter cleared (the same as zeroing it).
///
/// Returns `PLC_TIMERS_OK`; `PLC_TIMERS_NULL_POINTER` / `PLC_TIMERS_MISALIGNED_POINTER`.
///
/// # Safety
/// `counters` is NULL or points to writable memory for its type.
#[no_mangle]
pub unsafe extern "C" fn plc_timers_counter_memory_init(
    counters: *mut plc_timers_counter_memory,
) -> plc_timers_status {
    // SAFETY: the caller's contract.
    unsafe { init(counters, CounterMemory::new()) }
}

/// `FR C index` with RLO `rlo` (enable): a rising RLO clears the edge memories of CU, CD and S.
///
/// Returns `PLC_TIMERS_OK`; `PLC_TIMERS_NULL_POINTER` / `PLC_TIMERS_MISALIGNED_POINTER`; `PLC_TIMERS_INVALID_STATE` (a word of the area); `PLC_TIMERS_NO_SUCH_OPERAND` (`index` above 255).
///
/// # Safety
/// `counters` is NULL or points to memory valid for reads and writes of its type.
#[no_mangle]
pub unsafe extern "C" fn plc_timers_counter_memory_fr(
    counters: *mut plc_timers_counter_memory,
    index: usize,
    rlo: u8,
) -> plc_timers_status {
    // SAFETY: the caller's contract.
    unsafe { on_state_only(counters, |m| m.fr(index, bit(rlo)).map_err(no_such_operand)) }
}

/// `CU C index` with RLO `rlo`: a rising RLO counts up (CV stays at most 999).
///
/// Returns `PLC_TIMERS_OK`; `PLC_TIMERS_NULL_POINTER` / `PLC_TIMERS_MISALIGNED_POINTER`; `PLC_TIMERS_INVALID_STATE` (a word of the area); `PLC_TIMERS_NO_SUCH_OPERAND` (`index` above 255).
///
/// # Safety
/// `counters` is NULL or points to memory valid for reads and writes of its type.
#[no_mangle]
pub unsafe extern "C" fn plc_timers_counter_memory_cu(
    counters: *mut plc_timers_counter_memory,
    index: usize,
    rlo: u8,
) -> plc_timers_status {
    // SAFETY: the caller's contract.
    unsafe { on_state_only(counters, |m| m.cu(index, bit(rlo)).map_err(no_such_operand)) }
}

/// `CD C index` with RLO `rlo`: a rising RLO counts down (CV stays at least 0).
///
/// Returns `PLC_TIMERS_OK`; `PLC_TIMERS_NULL_POINTER` / `PLC_TIMERS_MISALIGNED_POINTER`; `PLC_TIMERS_INVALID_STATE` (a word of the area); `PLC_TIMERS_NO_SUCH_OPERAND` (`index` above 255).
///
/// # Safety
/// `counters` is NULL or points to memory valid for reads and writes of its type.
#[no_mangle]
pub unsafe extern "C" fn plc_timers_counter_memory_cd(
    counters: *mut plc_timers_counter_memory,
    index: usize,
    rlo: u8,
) -> plc_timers_status {
    // SAFETY: the caller's contract.
    unsafe { on_state_only(counters, |m| m.cd(index, bit(rlo)).map_err(no_such_operand)) }
}

/// `R C index` with RLO `rlo`: RLO 1 resets CV to 0.
///
/// Returns `PLC_TIMERS_OK`; `PLC_TIMERS_NULL_POINTER` / `PLC_TIMERS_MISALIGNED_POINTER`; `PLC_TIMERS_INVALID_STATE` (a word of the area); `PLC_TIMERS_NO_SUCH_OPERAND` (`index` above 255).
///
/// # Safety
/// `counters` is NULL or points to memory valid for reads and writes of its type.
#[no_mangle]
pub unsafe extern "C" fn plc_timers_counter_memory_reset(
    counters: *mut plc_timers_counter_memory,
    index: usize,
    rlo: u8,
) -> plc_timers_status {
    // SAFETY: the caller's contract.
    unsafe {
        on_state_only(counters, |m| {
            m.reset(index, bit(rlo)).map_err(no_such_operand)
        })
    }
}

/// `S C index` with RLO `rlo`: a rising RLO sets CV to the preset `pv`, a count 0 to 999 in
/// binary (`C#123` is 123; for the BCD word the PLC holds, `plc_timers_counter_memory_set_bcd`).
///
/// Returns `PLC_TIMERS_OK`; `PLC_TIMERS_NULL_POINTER` / `PLC_TIMERS_MISALIGNED_POINTER`; `PLC_TIMERS_INVALID_STATE` (a word of the area); `PLC_TIMERS_NO_SUCH_OPERAND` (`index` above 255); `PLC_TIMERS_INVALID_PRESET` (`pv` above 999).
///
/// # Safety
/// `counters` is NULL or points to memory valid for reads and writes of its type.
#[no_mangle]
pub unsafe extern "C" fn plc_timers_counter_memory_set(
    counters: *mut plc_timers_counter_memory,
    index: usize,
    rlo: u8,
    pv: plc_timers_s5_count,
) -> plc_timers_status {
    // SAFETY: the caller's contract.
    unsafe {
        on_state_only(counters, |m| {
            let pv = counter_preset(pv)?;
            m.set(index, bit(rlo), pv).map_err(no_such_operand)
        })
    }
}

/// `S C index` as the PLC executes it after `L C#n`: a rising RLO sets CV to the preset
/// `pv_bcd`, the BCD word in ACCU 1 (`C#123` is `W#16#0123`), each digit checked.
///
/// Returns `PLC_TIMERS_OK`; `PLC_TIMERS_NULL_POINTER` / `PLC_TIMERS_MISALIGNED_POINTER`; `PLC_TIMERS_INVALID_STATE` (a word of the area); `PLC_TIMERS_NO_SUCH_OPERAND` (`index` above 255); `PLC_TIMERS_INVALID_BCD_PRESET` (a digit above 9 or bits 15-12 set).
///
/// # Safety
/// `counters` is NULL or points to memory valid for reads and writes of its type.
#[no_mangle]
pub unsafe extern "C" fn plc_timers_counter_memory_set_bcd(
    counters: *mut plc_timers_counter_memory,
    index: usize,
    rlo: u8,
    pv_bcd: plc_timers_bcd_word,
) -> plc_timers_status {
    // SAFETY: the caller's contract.
    unsafe {
        on_state_only(counters, |m| {
            let pv = counter_preset_bcd(pv_bcd)?;
            m.set(index, bit(rlo), pv).map_err(no_such_operand)
        })
    }
}

/// `L C index`: writes the count in binary (0 to 999) to `value`.
///
/// Returns `PLC_TIMERS_OK`; `PLC_TIMERS_NULL_POINTER` / `PLC_TIMERS_MISALIGNED_POINTER`; `PLC_TIMERS_INVALID_STATE` (a word of the area); `PLC_TIMERS_NO_SUCH_OPERAND` (`index` above 255).
///
/// # Safety
/// `counters` is NULL or points to memory valid for reads of its type; `value` is NULL or points to memory valid for writes of its type.
#[no_mangle]
pub unsafe extern "C" fn plc_timers_counter_memory_load(
    counters: *const plc_timers_counter_memory,
    index: usize,
    value: *mut plc_timers_s5_count,
) -> plc_timers_status {
    // SAFETY: the caller's contract.
    unsafe { read_state(counters, value, |m| m.load(index).map_err(no_such_operand)) }
}

/// `LC C index`: writes the count as three BCD digits to `value`.
///
/// Returns `PLC_TIMERS_OK`; `PLC_TIMERS_NULL_POINTER` / `PLC_TIMERS_MISALIGNED_POINTER`; `PLC_TIMERS_INVALID_STATE` (a word of the area); `PLC_TIMERS_NO_SUCH_OPERAND` (`index` above 255).
///
/// # Safety
/// `counters` is NULL or points to memory valid for reads of its type; `value` is NULL or points to memory valid for writes of its type.
#[no_mangle]
pub unsafe extern "C" fn plc_timers_counter_memory_load_bcd(
    counters: *const plc_timers_counter_memory,
    index: usize,
    value: *mut plc_timers_bcd_word,
) -> plc_timers_status {
    // SAFETY: the caller's contract.
    unsafe {
        read_state(counters, value, |m| {
            m.load_bcd(index).map_err(no_such_operand)
        })
    }
}

/// `A C index`: writes the counter status (CV != 0) to `q`.
///
/// Returns `PLC_TIMERS_OK`; `PLC_TIMERS_NULL_POINTER` / `PLC_TIMERS_MISALIGNED_POINTER`; `PLC_TIMERS_INVALID_STATE` (a word of the area); `PLC_TIMERS_NO_SUCH_OPERAND` (`index` above 255).
///
/// # Safety
/// `counters` is NULL or points to memory valid for reads of its type; `q` is NULL or points to memory valid for writes of its type.
#[no_mangle]
pub unsafe extern "C" fn plc_timers_counter_memory_status(
    counters: *const plc_timers_counter_memory,
    index: usize,
    q: *mut bool,
) -> plc_timers_status {
    // SAFETY: the caller's contract.
    unsafe { read_state(counters, q, |m| m.status(index).map_err(no_such_operand)) }
}

/// The LAD box `kind` (`plc_timers_s5_counter_kind`) on counter `index`: all its inputs in one
/// call. The outputs are written to `out`.
///
/// Returns `PLC_TIMERS_OK`; `PLC_TIMERS_NULL_POINTER` / `PLC_TIMERS_MISALIGNED_POINTER`; `PLC_TIMERS_INVALID_STATE` (a word of the area); `PLC_TIMERS_NO_SUCH_OPERAND` (`index` above 255); `PLC_TIMERS_INVALID_KIND`; `PLC_TIMERS_INVALID_PRESET` (`input.pv` above 999).
///
/// # Safety
/// `counters` and `out` are NULL or point to memory valid for reads and writes of their types.
#[no_mangle]
pub unsafe extern "C" fn plc_timers_counter_memory_call(
    counters: *mut plc_timers_counter_memory,
    index: usize,
    kind: i32,
    input: plc_timers_s5_counter_input,
    out: *mut plc_timers_s5_counter_output,
) -> plc_timers_status {
    // SAFETY: the caller's contract.
    unsafe { counter_memory_call(counters, index, kind, input, out) }
}

/// `plc_timers_counter_memory_call` with the preset as a BCD word (`input.pv_bcd`, as the PLC
/// holds `C#n`).
///
/// Returns `PLC_TIMERS_OK`; `PLC_TIMERS_NULL_POINTER` / `PLC_TIMERS_MISALIGNED_POINTER`; `PLC_TIMERS_INVALID_STATE` (a word of the area); `PLC_TIMERS_NO_SUCH_OPERAND` (`index` above 255); `PLC_TIMERS_INVALID_KIND`; `PLC_TIMERS_INVALID_BCD_PRESET` (`input.pv_bcd`).
///
/// # Safety
/// `counters` and `out` are NULL or point to memory valid for reads and writes of their types.
#[no_mangle]
pub unsafe extern "C" fn plc_timers_counter_memory_call_bcd(
    counters: *mut plc_timers_counter_memory,
    index: usize,
    kind: i32,
    input: plc_timers_s5_counter_input_bcd,
    out: *mut plc_timers_s5_counter_output,
) -> plc_timers_status {
    // SAFETY: the caller's contract.
    unsafe { counter_memory_call(counters, index, kind, input, out) }
}

/// The counter box on the area with either input struct.
///
/// # Safety
/// As the callers'.
unsafe fn counter_memory_call(
    counters: *mut plc_timers_counter_memory,
    index: usize,
    kind: i32,
    input: impl CInput<S5CounterInput>,
    out: *mut plc_timers_s5_counter_output,
) -> plc_timers_status {
    // SAFETY: the caller's contract.
    unsafe {
        on_state(counters, out, |m| {
            let kind = s5_counter_kind(kind)?;
            let input = input.load()?;
            m.call(index, kind, input)
                .map(Into::into)
                .map_err(no_such_operand)
        })
    }
}
