//! The lexer shared by the duration literals `S5T#…` and `T#…`: a sequence of
//! `<digits><unit>` components, optionally separated by `_`, units case-insensitive.

use core::fmt;

/// A duration unit of a literal.
#[derive(Clone, Copy, Debug, PartialEq, Eq, PartialOrd, Ord)]
pub enum Unit {
    /// `D`, days (TIME only).
    Day,
    /// `H`, hours.
    Hour,
    /// `M`, minutes.
    Minute,
    /// `S`, seconds.
    Second,
    /// `MS`, milliseconds.
    Milli,
}

impl Unit {
    /// The unit's length in milliseconds.
    pub const fn millis(self) -> u64 {
        match self {
            Unit::Day => 86_400_000,
            Unit::Hour => 3_600_000,
            Unit::Minute => 60_000,
            Unit::Second => 1_000,
            Unit::Milli => 1,
        }
    }

    /// How many of this unit make the next larger one: the bound for a component that is not
    /// the first (`T#1H_75M` is an error, `T#75M` is not).
    const fn limit(self) -> u64 {
        match self {
            Unit::Day => u64::MAX,
            Unit::Hour => 24,
            Unit::Minute | Unit::Second => 60,
            Unit::Milli => 1_000,
        }
    }

    const fn symbol(self) -> &'static str {
        match self {
            Unit::Day => "D",
            Unit::Hour => "H",
            Unit::Minute => "M",
            Unit::Second => "S",
            Unit::Milli => "MS",
        }
    }
}

/// What was wrong with a duration or word literal.
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
    /// A unit appears twice, or after a smaller one (the order is D, H, M, S, MS).
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
    /// The value is outside the type's range (the message names the range).
    OutOfRange,
}

/// An error in a literal: what was wrong and where (byte offset in the given text).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct LiteralError {
    /// Which literal type was being parsed (`S5TIME`, `TIME`).
    pub what: &'static str,
    /// The byte offset in the text where the problem was found.
    pub position: usize,
    /// What was wrong.
    pub kind: LiteralErrorKind,
}

impl fmt::Display for LiteralError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        let (what, at) = (self.what, self.position);
        let units = if what == "S5TIME" {
            "H, M, S, MS"
        } else {
            "D, H, M, S, MS"
        };
        let forms = if what == "S5TIME" {
            "S5T#aH_bbM_ccS_dddMS, S5TIME#… or W#16#wxyz"
        } else {
            "T#…, TIME#… (e.g. T#2S_200MS, T#-5S) or whole milliseconds"
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
            LiteralErrorKind::OutOfRange => {
                if what == "S5TIME" {
                    write!(f, "above the S5TIME maximum of 9 990 s (S5T#2H46M30S)")
                } else {
                    write!(
                        f,
                        "outside T#-24D_20H_31M_23S_648MS ..= T#24D_20H_31M_23S_647MS \
                         (-2147483648 ..= 2147483647 ms)"
                    )
                }
            }
        }
    }
}

#[cfg(feature = "std")]
impl std::error::Error for LiteralError {}

/// Strips an ASCII prefix case-insensitively.
pub(crate) fn strip_prefix_ci<'a>(text: &'a str, prefix: &str) -> Option<&'a str> {
    let n = prefix.len();
    if text.len() >= n && text.is_char_boundary(n) && text[..n].eq_ignore_ascii_case(prefix) {
        Some(&text[n..])
    } else {
        None
    }
}

/// Parses the components `body` (which starts at byte `offset` of the whole text) into a total
/// number of milliseconds. `days` says whether `D` is a unit here.
pub(crate) fn parse_components(
    what: &'static str,
    body: &str,
    offset: usize,
    days: bool,
) -> Result<u64, LiteralError> {
    let err = |position: usize, kind| LiteralError {
        what,
        position,
        kind,
    };
    let bytes = body.as_bytes();
    if bytes.is_empty() {
        return Err(err(offset, LiteralErrorKind::NoComponents));
    }
    let mut i = 0;
    let mut total: u64 = 0;
    let mut last: Option<Unit> = None;
    while i < bytes.len() {
        if bytes[i] == b'_' && i > 0 && i + 1 < bytes.len() && bytes[i - 1] != b'_' {
            i += 1;
            continue;
        }
        let start = i;
        let mut value: u64 = 0;
        while i < bytes.len() && bytes[i].is_ascii_digit() {
            value = value
                .checked_mul(10)
                .and_then(|v| v.checked_add(u64::from(bytes[i] - b'0')))
                .ok_or(err(offset + start, LiteralErrorKind::Overflow))?;
            i += 1;
        }
        if i == start {
            let kind = match body[i..].chars().next() {
                Some(c) if c.is_ascii_alphabetic() => LiteralErrorKind::MissingDigits,
                Some(c) => LiteralErrorKind::UnexpectedChar(c),
                None => LiteralErrorKind::MissingUnit,
            };
            return Err(err(offset + i, kind));
        }
        if i < bytes.len() && (bytes[i] == b'.' || bytes[i] == b',') {
            return Err(err(offset + i, LiteralErrorKind::Fraction));
        }
        let unit_start = i;
        while i < bytes.len() && bytes[i].is_ascii_alphabetic() {
            i += 1;
        }
        let letters = &body[unit_start..i];
        let unit = if letters.is_empty() {
            // Say what stands where the unit should be: nothing, a separator, a non-ASCII letter
            // (`5µs`: not a unit), or another character (`5 s`).
            let kind = match body[unit_start..].chars().next() {
                None | Some('_') => LiteralErrorKind::MissingUnit,
                Some(c) if c.is_alphabetic() => LiteralErrorKind::UnknownUnit,
                Some(c) => LiteralErrorKind::UnexpectedChar(c),
            };
            return Err(err(offset + unit_start, kind));
        } else if letters.eq_ignore_ascii_case("d") && days {
            Unit::Day
        } else if letters.eq_ignore_ascii_case("h") {
            Unit::Hour
        } else if letters.eq_ignore_ascii_case("m") {
            Unit::Minute
        } else if letters.eq_ignore_ascii_case("s") {
            Unit::Second
        } else if letters.eq_ignore_ascii_case("ms") {
            Unit::Milli
        } else {
            return Err(err(offset + unit_start, LiteralErrorKind::UnknownUnit));
        };
        match last {
            Some(prev) if unit <= prev => {
                return Err(err(offset + unit_start, LiteralErrorKind::UnitOrder(unit)))
            }
            Some(_) if value >= unit.limit() => {
                return Err(err(
                    offset + start,
                    LiteralErrorKind::ComponentRange(unit, value),
                ))
            }
            _ => {}
        }
        last = Some(unit);
        total = value
            .checked_mul(unit.millis())
            .and_then(|v| total.checked_add(v))
            .ok_or(err(offset + start, LiteralErrorKind::Overflow))?;
    }
    Ok(total)
}

/// Writes `millis` as components (`2H46M30S`), with `sep` between them, `D` included when
/// `days`; zero components are omitted, and zero itself is written `0MS`.
pub(crate) fn write_components(
    f: &mut fmt::Formatter<'_>,
    millis: u64,
    days: bool,
    sep: &str,
) -> fmt::Result {
    if millis == 0 {
        return f.write_str("0MS");
    }
    let units: &[Unit] = if days {
        &[
            Unit::Day,
            Unit::Hour,
            Unit::Minute,
            Unit::Second,
            Unit::Milli,
        ]
    } else {
        &[Unit::Hour, Unit::Minute, Unit::Second, Unit::Milli]
    };
    let mut rest = millis;
    let mut first = true;
    for &unit in units {
        let n = rest / unit.millis();
        rest %= unit.millis();
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
