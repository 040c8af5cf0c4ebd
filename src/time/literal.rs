//! The lexer shared by the duration literals `S5T#…`, `T#…` and `LT#…`: a sequence of
//! `<digits><unit>` components, optionally separated by `_`, units case-insensitive. Each
//! literal type has its set of units and its base unit (ms for S5TIME and TIME, ns for LTIME):
//! one lexer serves the three, and the value comes out as a count of the type's base unit.
//!
//! Everything here is a `const fn`, so that a literal can be checked at compile time
//! ([`crate::s5time!`], [`crate::time!`], [`crate::ltime!`]). That rules out iterators, closures and `?`; the
//! loops below walk byte indices of the whole literal, so every error position is a byte offset
//! of the text the user wrote.

use core::fmt;

/// A duration unit of a literal.
///
/// ```
/// use plc_timers::time::{LiteralErrorKind, Time, Unit};
/// let e = Time::parse("T#1S_2M").unwrap_err();
/// assert_eq!(e.kind, LiteralErrorKind::UnitOrder(Unit::Minute));
/// ```
#[derive(Clone, Copy, Debug, PartialEq, Eq, PartialOrd, Ord)]
pub enum Unit {
    /// `D`, days (TIME and LTIME).
    Day,
    /// `H`, hours.
    Hour,
    /// `M`, minutes.
    Minute,
    /// `S`, seconds.
    Second,
    /// `MS`, milliseconds.
    Milli,
    /// `US`, microseconds (LTIME only).
    Micro,
    /// `NS`, nanoseconds (LTIME only).
    Nano,
}

impl Unit {
    /// Every unit, from the largest to the smallest: the order a literal writes them in.
    pub const ALL: [Unit; 7] = [
        Unit::Day,
        Unit::Hour,
        Unit::Minute,
        Unit::Second,
        Unit::Milli,
        Unit::Micro,
        Unit::Nano,
    ];

    /// The unit's length in nanoseconds.
    ///
    /// ```
    /// use plc_timers::time::Unit;
    /// assert_eq!(Unit::Minute.nanos(), 60_000_000_000);
    /// assert_eq!(Unit::Micro.nanos(), 1_000);
    /// ```
    pub const fn nanos(self) -> u64 {
        match self {
            Unit::Day => 86_400_000_000_000,
            Unit::Hour => 3_600_000_000_000,
            Unit::Minute => 60_000_000_000,
            Unit::Second => 1_000_000_000,
            Unit::Milli => 1_000_000,
            Unit::Micro => 1_000,
            Unit::Nano => 1,
        }
    }

    /// The unit's length in the base unit of `what` (ms for S5TIME and TIME, ns for LTIME), for
    /// the units `what` has. A match, not a division: the lexer stays free of divisions.
    const fn in_base(self, what: LiteralType) -> u64 {
        match what {
            LiteralType::LTime => self.nanos(),
            LiteralType::S5Time | LiteralType::Time => match self {
                Unit::Day => 86_400_000,
                Unit::Hour => 3_600_000,
                Unit::Minute => 60_000,
                Unit::Second => 1_000,
                // The sub-millisecond units are not units of these types (`units_of`).
                Unit::Milli | Unit::Micro | Unit::Nano => 1,
            },
        }
    }

    /// How many of this unit make the next larger one: the bound for a component that is not
    /// the first (`T#1H_75M` is an error, `T#75M` is not).
    const fn limit(self) -> u64 {
        match self {
            Unit::Day => u64::MAX,
            Unit::Hour => 24,
            Unit::Minute | Unit::Second => 60,
            Unit::Milli | Unit::Micro | Unit::Nano => 1_000,
        }
    }

    /// The unit as literals write it (`D`, `H`, `M`, `S`, `MS`, `US`, `NS`).
    pub const fn symbol(self) -> &'static str {
        match self {
            Unit::Day => "D",
            Unit::Hour => "H",
            Unit::Minute => "M",
            Unit::Second => "S",
            Unit::Milli => "MS",
            Unit::Micro => "US",
            Unit::Nano => "NS",
        }
    }
}

/// The units a literal of `what` may use, largest first: S5TIME H to MS, TIME D to MS, LTIME D
/// to NS.
const fn units_of(what: LiteralType) -> &'static [Unit] {
    match what {
        LiteralType::S5Time => &[Unit::Hour, Unit::Minute, Unit::Second, Unit::Milli],
        LiteralType::Time => &[
            Unit::Day,
            Unit::Hour,
            Unit::Minute,
            Unit::Second,
            Unit::Milli,
        ],
        LiteralType::LTime => &Unit::ALL,
    }
}

/// Which literal type was being parsed.
///
/// ```
/// use plc_timers::time::{LiteralType, S5Time};
/// assert_eq!(S5Time::parse("T#1S").unwrap_err().what, LiteralType::S5Time);
/// ```
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum LiteralType {
    /// `S5TIME`: `S5T#…`, `S5TIME#…`, `W#16#…`.
    S5Time,
    /// `TIME`: `T#…`, `TIME#…`, whole milliseconds.
    Time,
    /// `LTIME`: `LT#…`, `LTIME#…`, whole nanoseconds.
    LTime,
}

impl LiteralType {
    /// The type's name as the manuals write it.
    pub const fn name(self) -> &'static str {
        match self {
            LiteralType::S5Time => "S5TIME",
            LiteralType::Time => "TIME",
            LiteralType::LTime => "LTIME",
        }
    }
}

/// What was wrong with a duration or word literal.
///
/// ```
/// use plc_timers::time::{LiteralErrorKind, S5Time};
/// assert_eq!(S5Time::parse("S5T#1.5S").unwrap_err().kind, LiteralErrorKind::Fraction);
/// assert_eq!(S5Time::parse("W#16#00A1").unwrap_err().kind, LiteralErrorKind::BcdDigit(0xA));
/// ```
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
#[non_exhaustive]
pub enum LiteralErrorKind {
    /// The text is empty.
    Empty,
    /// The literal does not start with an accepted prefix.
    Prefix,
    /// Nothing follows the prefix.
    NoComponents,
    /// A unit was expected after the digits but none is there.
    MissingUnit,
    /// Letters that are not a unit of this literal.
    UnknownUnit,
    /// A unit was expected to be preceded by digits.
    MissingDigits,
    /// A character that has no place in the literal.
    UnexpectedChar(char),
    /// A unit appears twice, or after a smaller one (the order is D, H, M, S, MS, US, NS).
    UnitOrder(Unit),
    /// A component after the first exceeds its unit's range (e.g. 75 minutes after hours).
    ComponentRange(Unit, u64),
    /// A fractional value such as `1.5S`: not accepted, write `1S_500MS`.
    Fraction,
    /// A number too large to be any valid duration.
    Overflow,
    /// A `W#16#` literal without 1 to 4 hexadecimal digits.
    HexDigits,
    /// A BCD digit above 9 in a `W#16#` S5TIME word (the digit's value).
    BcdDigit(u8),
    /// A sign where the type has none: an S5TIME is never negative.
    Negative,
    /// The value is outside the type's range (the message names the range).
    OutOfRange,
}

/// An error in a literal: what was wrong and where (byte offset in the given text).
///
/// ```
/// use plc_timers::time::Time;
/// let e = Time::parse("T#5S_75M").unwrap_err();
/// assert_eq!(e.position, 7); // the unit M, out of order
/// assert_eq!(
///     e.to_string(),
///     "invalid TIME literal at byte 7: unit M repeated or out of order; \
///      units go from largest to smallest, each once"
/// );
/// ```
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct LiteralError {
    /// Which literal type was being parsed.
    pub what: LiteralType,
    /// The byte offset in the text where the problem was found.
    pub position: usize,
    /// What was wrong.
    pub kind: LiteralErrorKind,
}

impl LiteralError {
    pub(crate) const fn new(what: LiteralType, position: usize, kind: LiteralErrorKind) -> Self {
        LiteralError {
            what,
            position,
            kind,
        }
    }
}

impl fmt::Display for LiteralError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        let (what, at) = (self.what.name(), self.position);
        let (units, forms) = match self.what {
            LiteralType::S5Time => ("H, M, S, MS", "S5T#aH_bbM_ccS_dddMS, S5TIME#… or W#16#wxyz"),
            LiteralType::Time => (
                "D, H, M, S, MS",
                "T#…, TIME#… (e.g. T#2S_200MS, T#-5S) or whole milliseconds",
            ),
            LiteralType::LTime => (
                "D, H, M, S, MS, US, NS",
                "LT#…, LTIME#… (e.g. LT#1MS_500US, LT#-5S) or whole nanoseconds",
            ),
        };
        write!(f, "invalid {what} literal at byte {at}: ")?;
        match self.kind {
            LiteralErrorKind::Empty => write!(f, "the text is empty; write {forms}"),
            LiteralErrorKind::Prefix => write!(f, "unknown prefix; write {forms}"),
            LiteralErrorKind::NoComponents => write!(f, "no value after the prefix; write {forms}"),
            LiteralErrorKind::MissingUnit => write!(f, "a number needs a unit ({units})"),
            LiteralErrorKind::UnknownUnit => write!(f, "unknown unit; units are {units}"),
            LiteralErrorKind::MissingDigits => write!(f, "a unit needs a number before it"),
            LiteralErrorKind::UnexpectedChar(c) => {
                write!(f, "unexpected character {c:?}; write {forms}")
            }
            LiteralErrorKind::UnitOrder(u) => write!(
                f,
                "unit {} repeated or out of order; units go from largest to smallest, each once",
                u.symbol()
            ),
            LiteralErrorKind::ComponentRange(u, v) => write!(
                f,
                "{v}{} is out of range after a larger unit; it must be below {}",
                u.symbol(),
                u.limit()
            ),
            LiteralErrorKind::Fraction => {
                write!(
                    f,
                    "fractions are not accepted; split into units, e.g. 1S_500MS"
                )
            }
            LiteralErrorKind::Overflow => write!(f, "the number is too large"),
            LiteralErrorKind::HexDigits => write!(f, "W#16# takes 1 to 4 hexadecimal digits"),
            LiteralErrorKind::BcdDigit(d) => write!(
                f,
                "BCD digit {d:X} is above 9; the value field W#16#?xyz holds three decimal digits"
            ),
            LiteralErrorKind::Negative => write!(
                f,
                "an S5TIME cannot be negative; it is 0 to 9 990 s (S5T#0MS to S5T#2H46M30S)"
            ),
            LiteralErrorKind::OutOfRange => match self.what {
                LiteralType::S5Time => {
                    write!(f, "above the S5TIME maximum of 9 990 s (S5T#2H46M30S)")
                }
                LiteralType::Time => write!(
                    f,
                    "outside T#-24D_20H_31M_23S_648MS ..= T#24D_20H_31M_23S_647MS \
                     (-2147483648 ..= 2147483647 ms)"
                ),
                LiteralType::LTime => write!(
                    f,
                    "outside LT#-106751D_23H_47M_16S_854MS_775US_808NS ..= \
                     LT#106751D_23H_47M_16S_854MS_775US_807NS \
                     (-9223372036854775808 ..= 9223372036854775807 ns)"
                ),
            },
        }
    }
}

#[cfg(feature = "std")]
impl std::error::Error for LiteralError {}

/// Whether `text[at..]` starts with the ASCII `prefix`, ignoring case.
pub(crate) const fn has_prefix_ci(text: &[u8], at: usize, prefix: &str) -> bool {
    let p = prefix.as_bytes();
    if text.len() < at + p.len() {
        return false;
    }
    let mut i = 0;
    while i < p.len() {
        if !text[at + i].eq_ignore_ascii_case(&p[i]) {
            return false;
        }
        i += 1;
    }
    true
}

/// The character that starts at byte `i` of `text` (which is UTF-8: it came from a `str`).
pub(crate) const fn char_at(text: &[u8], i: usize) -> char {
    let b0 = text[i];
    let (len, mut c) = if b0 < 0x80 {
        (1, b0 as u32)
    } else if b0 >= 0xF0 {
        (4, (b0 & 0x07) as u32)
    } else if b0 >= 0xE0 {
        (3, (b0 & 0x0F) as u32)
    } else {
        (2, (b0 & 0x1F) as u32)
    };
    let mut k = 1;
    while k < len && i + k < text.len() {
        c = c << 6 | (text[i + k] & 0x3F) as u32;
        k += 1;
    }
    match char::from_u32(c) {
        Some(ch) => ch,
        None => char::REPLACEMENT_CHARACTER,
    }
}

/// The unit spelled by the ASCII letters `text[from..to]`, if it is one of `what`'s units.
const fn unit_of(text: &[u8], from: usize, to: usize, what: LiteralType) -> Option<Unit> {
    let first = text[from].to_ascii_uppercase();
    let unit = match to - from {
        1 => match first {
            b'D' => Unit::Day,
            b'H' => Unit::Hour,
            b'M' => Unit::Minute,
            b'S' => Unit::Second,
            _ => return None,
        },
        2 if text[from + 1].eq_ignore_ascii_case(&b'S') => match first {
            b'M' => Unit::Milli,
            b'U' => Unit::Micro,
            b'N' => Unit::Nano,
            _ => return None,
        },
        _ => return None,
    };
    let units = units_of(what);
    let mut i = 0;
    while i < units.len() {
        if units[i] as u8 == unit as u8 {
            return Some(unit);
        }
        i += 1;
    }
    None
}

const fn fail(
    what: LiteralType,
    position: usize,
    kind: LiteralErrorKind,
) -> Result<u64, LiteralError> {
    Err(LiteralError::new(what, position, kind))
}

/// Parses the components of `text` from byte `start` to the end into a total count of `what`'s
/// base unit (ms for S5TIME and TIME, ns for LTIME), with `what`'s units. Positions in errors
/// are byte offsets of `text`.
pub(crate) const fn parse_components(
    what: LiteralType,
    text: &[u8],
    start: usize,
) -> Result<u64, LiteralError> {
    let len = text.len();
    if start >= len {
        return fail(what, start, LiteralErrorKind::NoComponents);
    }
    let mut i = start;
    let mut total: u64 = 0;
    // The previous component's unit: each one must be smaller than the one before.
    let mut last: Option<Unit> = None;
    while i < len {
        // One `_` between components (not first, not last, not doubled) is a separator.
        if text[i] == b'_' && i > start && i + 1 < len && text[i - 1] != b'_' {
            i += 1;
            continue;
        }
        let number = i;
        let mut value: u64 = 0;
        while i < len && text[i].is_ascii_digit() {
            value = match value.checked_mul(10) {
                Some(v) => match v.checked_add((text[i] - b'0') as u64) {
                    Some(v) => v,
                    None => return fail(what, number, LiteralErrorKind::Overflow),
                },
                None => return fail(what, number, LiteralErrorKind::Overflow),
            };
            i += 1;
        }
        if i == number {
            // No digits where a component must begin: say what stands there.
            return if text[i].is_ascii_alphabetic() {
                fail(what, i, LiteralErrorKind::MissingDigits)
            } else {
                fail(what, i, LiteralErrorKind::UnexpectedChar(char_at(text, i)))
            };
        }
        if i < len && (text[i] == b'.' || text[i] == b',') {
            return fail(what, i, LiteralErrorKind::Fraction);
        }
        let unit_start = i;
        while i < len && text[i].is_ascii_alphabetic() {
            i += 1;
        }
        if i == unit_start {
            // Say what stands where the unit should be: nothing or a separator (missing), a
            // non-ASCII character (`5µs`: not a unit), or another character (`5 s`).
            return if unit_start == len || text[unit_start] == b'_' {
                fail(what, unit_start, LiteralErrorKind::MissingUnit)
            } else if text[unit_start] >= 0x80 {
                fail(what, unit_start, LiteralErrorKind::UnknownUnit)
            } else {
                fail(
                    what,
                    unit_start,
                    LiteralErrorKind::UnexpectedChar(char_at(text, unit_start)),
                )
            };
        }
        let unit = match unit_of(text, unit_start, i, what) {
            Some(u) => u,
            None => return fail(what, unit_start, LiteralErrorKind::UnknownUnit),
        };
        if let Some(prev) = last {
            if unit as u8 <= prev as u8 {
                return fail(what, unit_start, LiteralErrorKind::UnitOrder(unit));
            }
            if value >= unit.limit() {
                return fail(what, number, LiteralErrorKind::ComponentRange(unit, value));
            }
        }
        last = Some(unit);
        total = match value.checked_mul(unit.in_base(what)) {
            Some(v) => match total.checked_add(v) {
                Some(t) => t,
                None => return fail(what, number, LiteralErrorKind::Overflow),
            },
            None => return fail(what, number, LiteralErrorKind::Overflow),
        };
    }
    Ok(total)
}

/// Writes `value`, a count of `what`'s base unit, as components (`2H46M30S`) in `what`'s units,
/// with `sep` between them; zero components are omitted, and zero itself is written with the
/// smallest unit (`0MS`, `0NS`).
pub(crate) fn write_components(
    f: &mut fmt::Formatter<'_>,
    value: u64,
    what: LiteralType,
    sep: &str,
) -> fmt::Result {
    let units = units_of(what);
    if value == 0 {
        return match units.last() {
            Some(smallest) => write!(f, "0{}", smallest.symbol()),
            None => Ok(()),
        };
    }
    let mut rest = value;
    let mut first = true;
    for &unit in units {
        let size = unit.in_base(what);
        let n = rest / size;
        rest %= size;
        if n > 0 {
            if !first {
                f.write_str(sep)?;
            }
            write!(f, "{n}{}", unit.symbol())?;
            first = false;
        }
    }
    Ok(())
}

/// A signed duration literal of `what` (TIME or LTIME) taken apart: whether it is negative, its
/// magnitude in the base unit, and the byte offset where the value begins (a range error
/// points there). The accepted forms: the type's prefixes (`TIME#`/`T#`, `LTIME#`/`LT#`, any
/// case) with an optional `-` and components, or a plain whole number with an optional sign.
/// The caller checks the range, which differs by type.
pub(crate) const fn parse_signed(
    what: LiteralType,
    text: &[u8],
) -> Result<(bool, u64, usize), LiteralError> {
    if text.is_empty() {
        return Err(LiteralError::new(what, 0, LiteralErrorKind::Empty));
    }
    let (long, short) = match what {
        LiteralType::LTime => ("LTIME#", "LT#"),
        LiteralType::Time | LiteralType::S5Time => ("TIME#", "T#"),
    };
    let prefix = if has_prefix_ci(text, 0, long) {
        long.len()
    } else if has_prefix_ci(text, 0, short) {
        short.len()
    } else {
        0
    };
    if prefix > 0 {
        let negative = prefix < text.len() && text[prefix] == b'-';
        match parse_components(what, text, prefix + negative as usize) {
            Ok(m) => Ok((negative, m, prefix)),
            Err(e) => Err(e),
        }
    } else {
        match parse_plain(what, text) {
            Ok((negative, m)) => Ok((negative, m, 0)),
            Err(e) => Err(e),
        }
    }
}

/// A plain whole number with an optional sign (`-5`, `+5`, `5`): its sign and magnitude.
const fn parse_plain(what: LiteralType, b: &[u8]) -> Result<(bool, u64), LiteralError> {
    let offset = if b[0] == b'-' || b[0] == b'+' { 1 } else { 0 };
    if offset == b.len() {
        return Err(LiteralError::new(
            what,
            offset,
            LiteralErrorKind::MissingDigits,
        ));
    }
    let mut value: u64 = 0;
    let mut i = offset;
    while i < b.len() {
        if !b[i].is_ascii_digit() {
            // A letter first means a missing or unknown prefix (`X#5S`, `5S` without `T#`).
            let kind = if b[i].is_ascii_alphabetic() && i == offset {
                LiteralErrorKind::Prefix
            } else {
                LiteralErrorKind::UnexpectedChar(char_at(b, i))
            };
            return Err(LiteralError::new(what, i, kind));
        }
        value = match value.checked_mul(10) {
            Some(v) => match v.checked_add((b[i] - b'0') as u64) {
                Some(v) => v,
                None => return Err(LiteralError::new(what, offset, LiteralErrorKind::Overflow)),
            },
            None => return Err(LiteralError::new(what, offset, LiteralErrorKind::Overflow)),
        };
        i += 1;
    }
    Ok((b[0] == b'-', value))
}
