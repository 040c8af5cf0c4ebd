//! The literal parsers: S5TIME, TIME and the S5 counter preset, as the library parses them.

use std::ffi::{c_char, CStr};

use plc_timers::counter::s5::{CounterPreset, CounterPresetError};
use plc_timers::time::{LTime, LiteralError, LiteralErrorKind, S5Time, Time};

use crate::status::plc_timers_status::{self, *};
use crate::{checked, checked_mut, guard};

/// The status of a literal error.
fn literal_status(e: &LiteralError) -> plc_timers_status {
    match e.kind {
        LiteralErrorKind::Empty => PLC_TIMERS_LITERAL_EMPTY,
        LiteralErrorKind::Prefix => PLC_TIMERS_LITERAL_PREFIX,
        LiteralErrorKind::NoComponents => PLC_TIMERS_LITERAL_NO_COMPONENTS,
        LiteralErrorKind::MissingUnit => PLC_TIMERS_LITERAL_MISSING_UNIT,
        LiteralErrorKind::UnknownUnit => PLC_TIMERS_LITERAL_UNKNOWN_UNIT,
        LiteralErrorKind::MissingDigits => PLC_TIMERS_LITERAL_MISSING_DIGITS,
        LiteralErrorKind::UnexpectedChar(_) => PLC_TIMERS_LITERAL_UNEXPECTED_CHAR,
        LiteralErrorKind::UnitOrder(_) => PLC_TIMERS_LITERAL_UNIT_ORDER,
        LiteralErrorKind::ComponentRange(..) => PLC_TIMERS_LITERAL_COMPONENT_RANGE,
        LiteralErrorKind::Fraction => PLC_TIMERS_LITERAL_FRACTION,
        LiteralErrorKind::Overflow => PLC_TIMERS_LITERAL_OVERFLOW,
        LiteralErrorKind::HexDigits => PLC_TIMERS_LITERAL_HEX_DIGITS,
        LiteralErrorKind::BcdDigit(_) => PLC_TIMERS_LITERAL_BCD_DIGIT,
        LiteralErrorKind::Negative => PLC_TIMERS_LITERAL_NEGATIVE,
        LiteralErrorKind::OutOfRange => PLC_TIMERS_LITERAL_OUT_OF_RANGE,
        // The library's error kinds are `non_exhaustive`: one added later is still an error.
        _ => PLC_TIMERS_LITERAL_INVALID,
    }
}

/// Parses the NUL-terminated `text` with `parse`, writes the value to `value` and, on a literal
/// error, the byte offset of the problem to `error_position` (when not NULL).
///
/// # Safety
/// `text` is NULL or a NUL-terminated string; `value` and `error_position` are NULL or point to
/// memory valid for writes of their types.
unsafe fn parse_literal<T, V>(
    text: *const c_char,
    value: *mut V,
    error_position: *mut usize,
    parse: impl FnOnce(&str) -> Result<T, LiteralError>,
    convert: impl FnOnce(T) -> V,
) -> plc_timers_status {
    guard(|| {
        let text = checked(text)?;
        let value = checked_mut(value)?;
        let position = if error_position.is_null() {
            None
        } else {
            Some(checked_mut(error_position)?)
        };
        // SAFETY: checked non-NULL; NUL-terminated is the caller's contract.
        let bytes = unsafe { CStr::from_ptr(text) }.to_bytes();
        // A byte outside ASCII has no place in any literal: the first one is the error (the
        // text before it, valid UTF-8, may parse, but the whole does not).
        let parsed = match std::str::from_utf8(bytes) {
            Ok(s) => parse(s).map_err(|e| (literal_status(&e), e.position)),
            Err(e) => Err((PLC_TIMERS_LITERAL_UNEXPECTED_CHAR, e.valid_up_to())),
        };
        match parsed {
            Ok(v) => {
                // SAFETY: checked non-NULL and aligned.
                unsafe { value.write(convert(v)) };
                Ok(())
            }
            Err((status, at)) => {
                if let Some(p) = position {
                    // SAFETY: checked non-NULL and aligned.
                    unsafe { p.write(at) };
                }
                Err(status)
            }
        }
    })
}

/// Parses an S5TIME literal: `S5T#aH_bbM_ccS_dddMS` or `S5TIME#…` (case-insensitive, underscores
/// optional, units H, M, S, MS from largest to smallest, each at most once; the time base is the
/// finest whose value fits in 999 units, the value rounded down), or a word `W#16#wxyz` (BCD
/// checked, bits 15-14 ignored). `text` is NUL-terminated.
///
/// On success writes the S5TIME word (BCD value in bits 11-0, time base in bits 13-12; as
/// `plc_timers_s5_input.tv` takes it) to `word`. On a literal error writes the byte offset in
/// `text` where the problem was found to `error_position`, unless that is NULL.
///
/// Returns `PLC_TIMERS_OK`; `PLC_TIMERS_NULL_POINTER` / `PLC_TIMERS_MISALIGNED_POINTER` (`text`
/// or `word`; `error_position` may be NULL); a `PLC_TIMERS_LITERAL_*` code saying what was wrong.
///
/// # Safety
/// `text` is NULL or a NUL-terminated string; `word` and `error_position` are NULL or point to
/// memory valid for writes of their types.
#[no_mangle]
pub unsafe extern "C" fn plc_timers_s5time_parse(
    text: *const c_char,
    word: *mut u16,
    error_position: *mut usize,
) -> plc_timers_status {
    // SAFETY: the caller's contract.
    unsafe { parse_literal(text, word, error_position, S5Time::parse, S5Time::to_word) }
}

/// Parses a TIME literal: `T#…` or `TIME#…` (case-insensitive, underscores optional, an
/// optional `-` after `#`, units D, H, M, S, MS from largest to smallest, each at most once), or
/// a whole number of milliseconds with an optional sign. The range is -2147483648 to 2147483647
/// ms (`T#-24D_20H_31M_23S_648MS` to `T#24D_20H_31M_23S_647MS`). `text` is NUL-terminated.
///
/// On success writes the duration in ms to `millis` (as `plc_timers_iec_input.pt` takes it). On
/// a literal error writes the byte offset in `text` where the problem was found to
/// `error_position`, unless that is NULL.
///
/// Returns `PLC_TIMERS_OK`; `PLC_TIMERS_NULL_POINTER` / `PLC_TIMERS_MISALIGNED_POINTER` (`text`
/// or `millis`; `error_position` may be NULL); a `PLC_TIMERS_LITERAL_*` code saying what was
/// wrong.
///
/// # Safety
/// `text` is NULL or a NUL-terminated string; `millis` and `error_position` are NULL or point to
/// memory valid for writes of their types.
#[no_mangle]
pub unsafe extern "C" fn plc_timers_time_parse(
    text: *const c_char,
    millis: *mut i32,
    error_position: *mut usize,
) -> plc_timers_status {
    // SAFETY: the caller's contract.
    unsafe { parse_literal(text, millis, error_position, Time::parse, Time::as_millis) }
}

/// Parses an LTIME literal: `LT#…` or `LTIME#…` (case-insensitive, underscores optional, an
/// optional `-` after `#`, units D, H, M, S, MS, US, NS from largest to smallest, each at most
/// once), or a whole number of nanoseconds with an optional sign. The range is
/// -9223372036854775808 to 9223372036854775807 ns (`LT#-106751D_23H_47M_16S_854MS_775US_808NS`
/// to `LT#106751D_23H_47M_16S_854MS_775US_807NS`). `text` is NUL-terminated.
///
/// On success writes the duration in ns to `nanos` (as `plc_timers_iec_ltime_input.pt_ns`
/// takes it). On a literal error writes the byte offset in `text` where the problem was found to
/// `error_position`, unless that is NULL.
///
/// Returns `PLC_TIMERS_OK`; `PLC_TIMERS_NULL_POINTER` / `PLC_TIMERS_MISALIGNED_POINTER` (`text`
/// or `nanos`; `error_position` may be NULL); a `PLC_TIMERS_LITERAL_*` code saying what was
/// wrong.
///
/// # Safety
/// `text` is NULL or a NUL-terminated string; `nanos` and `error_position` are NULL or point to
/// memory valid for writes of their types.
#[no_mangle]
pub unsafe extern "C" fn plc_timers_ltime_parse(
    text: *const c_char,
    nanos: *mut i64,
    error_position: *mut usize,
) -> plc_timers_status {
    // SAFETY: the caller's contract.
    unsafe { parse_literal(text, nanos, error_position, LTime::parse, LTime::as_nanos) }
}

/// Parses an S5 counter preset: `C#n` (n decimal, 0 to 999), a whole number 0 to 999, or a BCD
/// word `W#16#xyz`; surrounding spaces are ignored. `text` is NUL-terminated. On success writes
/// the count (binary, 0 to 999; as `plc_timers_s5_counter_input.pv` takes it) to `count`. (The
/// library's preset errors carry no position, so this parser reports none.)
///
/// Returns `PLC_TIMERS_OK`; `PLC_TIMERS_NULL_POINTER` / `PLC_TIMERS_MISALIGNED_POINTER` (`text`
/// or `count`); `PLC_TIMERS_PRESET_SYNTAX`, `PLC_TIMERS_PRESET_OUT_OF_RANGE` or
/// `PLC_TIMERS_PRESET_BCD_DIGIT`.
///
/// # Safety
/// `text` is NULL or a NUL-terminated string; `count` is NULL or points to memory valid for
/// writes of a `uint16_t`.
#[no_mangle]
pub unsafe extern "C" fn plc_timers_counter_preset_parse(
    text: *const c_char,
    count: *mut u16,
) -> plc_timers_status {
    guard(|| {
        let text = checked(text)?;
        let count = checked_mut(count)?;
        // SAFETY: checked non-NULL; NUL-terminated is the caller's contract.
        let bytes = unsafe { CStr::from_ptr(text) }.to_bytes();
        // Not UTF-8: not a preset (every accepted form is ASCII).
        let text = std::str::from_utf8(bytes).map_err(|_| PLC_TIMERS_PRESET_SYNTAX)?;
        let preset = CounterPreset::parse(text).map_err(|e| match e {
            CounterPresetError::OutOfRange(_) => PLC_TIMERS_PRESET_OUT_OF_RANGE,
            CounterPresetError::BcdDigit(_) => PLC_TIMERS_PRESET_BCD_DIGIT,
            // `Syntax`, and any error kind the library adds later (`non_exhaustive`).
            _ => PLC_TIMERS_PRESET_SYNTAX,
        })?;
        // SAFETY: checked non-NULL and aligned.
        unsafe { count.write(preset.value()) };
        Ok(())
    })
}
