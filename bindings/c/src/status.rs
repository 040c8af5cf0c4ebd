//! The status codes every function returns, and their messages.

use std::ffi::{c_char, CStr};

/// What a function did: `PLC_TIMERS_OK` (0), or why it did nothing.
///
/// In C an `int32_t` (the enum's constants name the values). On any code other than
/// `PLC_TIMERS_OK` the function has written nothing: the state and the outputs are as they were.
#[repr(i32)]
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum plc_timers_status {
    /// Done.
    PLC_TIMERS_OK = 0,
    /// A pointer argument is NULL (for the parsers' optional `error_position`, NULL is allowed).
    PLC_TIMERS_NULL_POINTER = 1,
    /// A pointer argument is not aligned for its type.
    PLC_TIMERS_MISALIGNED_POINTER = 2,
    /// The kind argument is not one of its enum's values.
    PLC_TIMERS_INVALID_KIND = 3,
    /// The state struct does not hold a state the block can be in (a field out of its range,
    /// a flag byte other than 0 or 1, an unused bit set): a corrupted or foreign instance.
    PLC_TIMERS_INVALID_STATE = 4,
    /// An S5TIME word with a BCD digit above 9 in bits 11-0.
    PLC_TIMERS_INVALID_S5TIME = 5,
    /// An S5 counter preset above 999.
    PLC_TIMERS_INVALID_PRESET = 6,
    /// A timer or counter number outside the memory area (0 to 255).
    PLC_TIMERS_NO_SUCH_OPERAND = 7,
    /// A time base argument that is not one of `plc_timers_time_base`.
    PLC_TIMERS_INVALID_TIME_BASE = 8,
    /// An S5 counter preset BCD word (`plc_timers_bcd_word`) with a digit above 9 or bits 15-12
    /// set.
    PLC_TIMERS_INVALID_BCD_PRESET = 9,
    /// Literal: the text is empty.
    PLC_TIMERS_LITERAL_EMPTY = 20,
    /// Literal: it does not start with an accepted prefix (`S5T#`, `S5TIME#`, `W#16#`; `T#`,
    /// `TIME#` or a number).
    PLC_TIMERS_LITERAL_PREFIX = 21,
    /// Literal: nothing follows the prefix.
    PLC_TIMERS_LITERAL_NO_COMPONENTS = 22,
    /// Literal: a number without a unit (D, H, M, S, MS).
    PLC_TIMERS_LITERAL_MISSING_UNIT = 23,
    /// Literal: letters that are not a unit of the literal.
    PLC_TIMERS_LITERAL_UNKNOWN_UNIT = 24,
    /// Literal: a unit without a number before it.
    PLC_TIMERS_LITERAL_MISSING_DIGITS = 25,
    /// Literal: a character that has no place in it (any byte outside ASCII included).
    PLC_TIMERS_LITERAL_UNEXPECTED_CHAR = 26,
    /// Literal: a unit repeated or after a smaller one (the order is D, H, M, S, MS).
    PLC_TIMERS_LITERAL_UNIT_ORDER = 27,
    /// Literal: a component after the first out of its unit's range (e.g. 75M after hours).
    PLC_TIMERS_LITERAL_COMPONENT_RANGE = 28,
    /// Literal: a fraction such as `1.5S`; write `1S_500MS`.
    PLC_TIMERS_LITERAL_FRACTION = 29,
    /// Literal: a number too large to be any valid duration.
    PLC_TIMERS_LITERAL_OVERFLOW = 30,
    /// Literal: `W#16#` without 1 to 4 hexadecimal digits.
    PLC_TIMERS_LITERAL_HEX_DIGITS = 31,
    /// Literal: a BCD digit above 9 in a `W#16#` S5TIME word.
    PLC_TIMERS_LITERAL_BCD_DIGIT = 32,
    /// Literal: a sign on an S5TIME, which is never negative.
    PLC_TIMERS_LITERAL_NEGATIVE = 33,
    /// Literal: outside the type's range (S5TIME: 0 to 9 990 s; TIME: -2147483648 to
    /// 2147483647 ms).
    PLC_TIMERS_LITERAL_OUT_OF_RANGE = 34,
    /// Literal: invalid in a way newer than this list (the library's error kinds may grow).
    PLC_TIMERS_LITERAL_INVALID = 35,
    /// Counter preset: not `C#n`, a whole number or `W#16#xyz`.
    PLC_TIMERS_PRESET_SYNTAX = 40,
    /// Counter preset: above 999.
    PLC_TIMERS_PRESET_OUT_OF_RANGE = 41,
    /// Counter preset: a `W#16#` word with a BCD digit above 9 or bits 15-12 set.
    PLC_TIMERS_PRESET_BCD_DIGIT = 42,
    /// A Rust panic was caught at the boundary. No code path should lead here (see the
    /// library's docs); please report it.
    PLC_TIMERS_INTERNAL_ERROR = 99,
}

use plc_timers_status::*;

/// Every status, for `plc_timers_status_message` (the C test `tests/status.c` asks it for the
/// message of every constant of the header's enum, so that a status missing here fails).
pub(crate) const ALL: [plc_timers_status; 30] = [
    PLC_TIMERS_OK,
    PLC_TIMERS_NULL_POINTER,
    PLC_TIMERS_MISALIGNED_POINTER,
    PLC_TIMERS_INVALID_KIND,
    PLC_TIMERS_INVALID_STATE,
    PLC_TIMERS_INVALID_S5TIME,
    PLC_TIMERS_INVALID_PRESET,
    PLC_TIMERS_NO_SUCH_OPERAND,
    PLC_TIMERS_INVALID_TIME_BASE,
    PLC_TIMERS_INVALID_BCD_PRESET,
    PLC_TIMERS_LITERAL_EMPTY,
    PLC_TIMERS_LITERAL_PREFIX,
    PLC_TIMERS_LITERAL_NO_COMPONENTS,
    PLC_TIMERS_LITERAL_MISSING_UNIT,
    PLC_TIMERS_LITERAL_UNKNOWN_UNIT,
    PLC_TIMERS_LITERAL_MISSING_DIGITS,
    PLC_TIMERS_LITERAL_UNEXPECTED_CHAR,
    PLC_TIMERS_LITERAL_UNIT_ORDER,
    PLC_TIMERS_LITERAL_COMPONENT_RANGE,
    PLC_TIMERS_LITERAL_FRACTION,
    PLC_TIMERS_LITERAL_OVERFLOW,
    PLC_TIMERS_LITERAL_HEX_DIGITS,
    PLC_TIMERS_LITERAL_BCD_DIGIT,
    PLC_TIMERS_LITERAL_NEGATIVE,
    PLC_TIMERS_LITERAL_OUT_OF_RANGE,
    PLC_TIMERS_LITERAL_INVALID,
    PLC_TIMERS_PRESET_SYNTAX,
    PLC_TIMERS_PRESET_OUT_OF_RANGE,
    PLC_TIMERS_PRESET_BCD_DIGIT,
    PLC_TIMERS_INTERNAL_ERROR,
];

/// The message of a status, as a static NUL-terminated string.
const fn message(status: plc_timers_status) -> &'static CStr {
    match status {
        PLC_TIMERS_OK => c"ok",
        PLC_TIMERS_NULL_POINTER => c"a pointer argument is NULL",
        PLC_TIMERS_MISALIGNED_POINTER => c"a pointer argument is not aligned for its type",
        PLC_TIMERS_INVALID_KIND => {
            c"the kind is not one of its enum's values (plc_timers_s5_kind, plc_timers_iec_kind, plc_timers_counter_kind, plc_timers_s5_counter_kind)"
        }
        PLC_TIMERS_INVALID_STATE => {
            c"the state struct holds no state the block can be in (a field out of range, a flag other than 0 or 1, an unused bit set); initialize it with its _init function or zero it"
        }
        PLC_TIMERS_INVALID_S5TIME => {
            c"the S5TIME word has a BCD digit above 9 in bits 11-0; the value field holds three decimal digits"
        }
        PLC_TIMERS_INVALID_PRESET => c"the S5 counter preset is above 999",
        PLC_TIMERS_NO_SUCH_OPERAND => {
            c"no such timer or counter: the memory area has numbers 0 to 255"
        }
        PLC_TIMERS_INVALID_TIME_BASE => {
            c"the time base is not one of plc_timers_time_base (0 = 10 ms, 1 = 100 ms, 2 = 1 s, 3 = 10 s)"
        }
        PLC_TIMERS_INVALID_BCD_PRESET => {
            c"the S5 counter preset BCD word has a digit above 9 or bits 15-12 set (C#0 to C#999 are W#16#0000 to W#16#0999)"
        }
        PLC_TIMERS_LITERAL_EMPTY => c"invalid literal: the text is empty",
        PLC_TIMERS_LITERAL_PREFIX => {
            c"invalid literal: unknown prefix; write S5T#..., S5TIME#... or W#16#wxyz for S5TIME, T#..., TIME#... or whole milliseconds for TIME"
        }
        PLC_TIMERS_LITERAL_NO_COMPONENTS => c"invalid literal: no value after the prefix",
        PLC_TIMERS_LITERAL_MISSING_UNIT => {
            c"invalid literal: a number needs a unit (D, H, M, S, MS)"
        }
        PLC_TIMERS_LITERAL_UNKNOWN_UNIT => {
            c"invalid literal: unknown unit; units are D, H, M, S, MS (no D in S5TIME)"
        }
        PLC_TIMERS_LITERAL_MISSING_DIGITS => c"invalid literal: a unit needs a number before it",
        PLC_TIMERS_LITERAL_UNEXPECTED_CHAR => {
            c"invalid literal: a character that has no place in the literal"
        }
        PLC_TIMERS_LITERAL_UNIT_ORDER => {
            c"invalid literal: a unit repeated or out of order; units go from largest to smallest, each once"
        }
        PLC_TIMERS_LITERAL_COMPONENT_RANGE => {
            c"invalid literal: a component after the first is out of its unit's range (e.g. 75M after hours)"
        }
        PLC_TIMERS_LITERAL_FRACTION => {
            c"invalid literal: fractions are not accepted; split into units, e.g. 1S_500MS"
        }
        PLC_TIMERS_LITERAL_OVERFLOW => c"invalid literal: the number is too large",
        PLC_TIMERS_LITERAL_HEX_DIGITS => {
            c"invalid literal: W#16# takes 1 to 4 hexadecimal digits"
        }
        PLC_TIMERS_LITERAL_BCD_DIGIT => {
            c"invalid literal: a BCD digit above 9; the value field W#16#?xyz holds three decimal digits"
        }
        PLC_TIMERS_LITERAL_NEGATIVE => {
            c"invalid literal: an S5TIME cannot be negative; it is 0 to 9 990 s (S5T#0MS to S5T#2H46M30S)"
        }
        PLC_TIMERS_LITERAL_OUT_OF_RANGE => {
            c"invalid literal: out of range; S5TIME is 0 to 9 990 s (S5T#2H46M30S), TIME is -2147483648 to 2147483647 ms"
        }
        PLC_TIMERS_LITERAL_INVALID => c"invalid literal",
        PLC_TIMERS_PRESET_SYNTAX => {
            c"not a counter preset; write C#0 to C#999, 0 to 999, or W#16#0000 to W#16#0999"
        }
        PLC_TIMERS_PRESET_OUT_OF_RANGE => {
            c"the counter preset is above the S5 counter maximum of 999"
        }
        PLC_TIMERS_PRESET_BCD_DIGIT => {
            c"the counter preset word is not a BCD count: every digit must be 0-9 and the value at most 999"
        }
        PLC_TIMERS_INTERNAL_ERROR => {
            c"internal error: a Rust panic was caught at the C boundary; please report it"
        }
    }
}

/// The message for the status `code`: a static NUL-terminated string (never NULL, never to be
/// freed). A code that is no `plc_timers_status` gives "unknown status code".
#[no_mangle]
pub extern "C" fn plc_timers_status_message(code: i32) -> *const c_char {
    ALL.iter()
        .find(|s| **s as i32 == code)
        .map_or(c"unknown status code", |s| message(*s))
        .as_ptr()
}

#[cfg(test)]
mod tests {
    use super::{message, plc_timers_status_message, ALL};
    use std::ffi::CStr;

    /// Every status is listed once and its message is found by its code; other codes are unknown.
    #[test]
    fn every_code_has_its_message() {
        for (i, s) in ALL.iter().enumerate() {
            assert!(!ALL.iter().take(i).any(|x| x == s), "{s:?} listed twice");
            // SAFETY: the function returns a static NUL-terminated string.
            let m = unsafe { CStr::from_ptr(plc_timers_status_message(*s as i32)) };
            assert_eq!(m, message(*s));
        }
        for code in [-1, 10, 19, 36, 43, 98, 100, i32::MIN, i32::MAX] {
            // SAFETY: as above.
            let m = unsafe { CStr::from_ptr(plc_timers_status_message(code)) };
            assert_eq!(m, c"unknown status code", "code {code}");
        }
    }
}
