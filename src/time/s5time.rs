//! The S5TIME word (LAD manual §9.1, Berger §7.1).
//!
//! ```text
//!  15 14 | 13 12 | 11 .. 8 | 7 .. 4 | 3 .. 0
//!  ignored| base  | hundreds|  tens  |  ones      (three BCD digits, 0..=999 units)
//! ```

use core::fmt;

use super::bcd::{bcd3_decode, bcd3_encode};
use super::literal::{has_prefix_ci, parse_components, write_components};
use super::literal::{LiteralError, LiteralErrorKind, LiteralType};

/// The time base of an S5 timer: the interval after which the operating system decrements the
/// timer value by one unit (LAD manual §9.1, Table 9-1).
///
/// ```
/// use plc_timers::time::TimeBase;
/// assert_eq!(TimeBase::ALL.map(TimeBase::millis), [10, 100, 1_000, 10_000]);
/// assert_eq!(TimeBase::from_bits(0b10), TimeBase::S1);
/// ```
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, PartialOrd, Ord)]
#[cfg_attr(kani, derive(kani::Arbitrary))]
#[cfg_attr(feature = "bolero", derive(bolero_generator::TypeGenerator))]
#[repr(u8)]
pub enum TimeBase {
    /// 10 ms, bits 13-12 = `00`.
    Ms10 = 0,
    /// 100 ms, bits 13-12 = `01`.
    Ms100 = 1,
    /// 1 s, bits 13-12 = `10`.
    S1 = 2,
    /// 10 s, bits 13-12 = `11`.
    S10 = 3,
}

impl TimeBase {
    /// All four bases, finest first.
    pub const ALL: [TimeBase; 4] = [TimeBase::Ms10, TimeBase::Ms100, TimeBase::S1, TimeBase::S10];

    /// The base encoded by the two low bits of `bits` (the word's bits 13-12 shifted down).
    ///
    /// ```
    /// use plc_timers::time::TimeBase;
    /// assert_eq!(TimeBase::from_bits(3), TimeBase::S10);
    /// assert_eq!(TimeBase::from_bits(7), TimeBase::S10); // only the two low bits count
    /// ```
    pub const fn from_bits(bits: u8) -> TimeBase {
        match bits & 0b11 {
            0 => TimeBase::Ms10,
            1 => TimeBase::Ms100,
            2 => TimeBase::S1,
            _ => TimeBase::S10,
        }
    }

    /// The two-bit code of this base (Table 9-1).
    pub const fn bits(self) -> u8 {
        self as u8
    }

    /// The length of one unit of this base in milliseconds.
    pub const fn millis(self) -> u32 {
        match self {
            TimeBase::Ms10 => 10,
            TimeBase::Ms100 => 100,
            TimeBase::S1 => 1_000,
            TimeBase::S10 => 10_000,
        }
    }
}

/// What was wrong with an S5TIME value.
///
/// ```
/// use plc_timers::time::{S5Time, S5TimeError};
/// let e = S5Time::from_word(0x20A1).unwrap_err();
/// assert_eq!(e, S5TimeError::BcdDigit { word: 0x20A1, position: 1, digit: 0xA });
/// assert_eq!(e.to_string(), "W#16#20A1 is not a valid S5TIME: its tens BCD digit is A, digits must be 0-9");
/// ```
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
#[non_exhaustive]
pub enum S5TimeError {
    /// A BCD digit of the word's value field is above 9.
    BcdDigit {
        /// The word as given.
        word: u16,
        /// Which digit: 0 = ones (bits 3-0), 1 = tens (bits 7-4), 2 = hundreds (bits 11-8).
        position: u8,
        /// The digit's value, 10..=15.
        digit: u8,
    },
    /// A unit count above 999.
    UnitsOutOfRange {
        /// The count given.
        units: u16,
    },
    /// A duration above 9 990 s (`S5T#2H_46M_30S`), the largest an S5TIME can hold.
    DurationOutOfRange {
        /// The duration given, in milliseconds.
        millis: u64,
    },
}

impl fmt::Display for S5TimeError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match *self {
            S5TimeError::BcdDigit {
                word,
                position,
                digit,
            } => {
                let name = ["ones", "tens", "hundreds"][position as usize % 3];
                write!(
                    f,
                    "W#16#{word:04X} is not a valid S5TIME: its {name} BCD digit is {digit:X}, \
                     digits must be 0-9"
                )
            }
            S5TimeError::UnitsOutOfRange { units } => {
                write!(
                    f,
                    "{units} time units do not fit in S5TIME: the value is 0..=999 units"
                )
            }
            S5TimeError::DurationOutOfRange { millis } => write!(
                f,
                "{millis} ms is above the S5TIME maximum of 9 990 000 ms (S5T#2H_46M_30S)"
            ),
        }
    }
}

#[cfg(feature = "std")]
impl std::error::Error for S5TimeError {}

/// A valid S5TIME: 0..=999 units of a [`TimeBase`].
///
/// The invariant `units <= 999` holds for every value of this type; constructors check it.
///
/// ```
/// use plc_timers::time::{S5Time, TimeBase};
/// let t = S5Time::new(127, TimeBase::S1)?;
/// assert_eq!((t.as_millis(), t.to_word(), t.to_string()), (127_000, 0x2127, "S5T#2M7S".to_string()));
/// # Ok::<(), plc_timers::time::S5TimeError>(())
/// ```
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub struct S5Time {
    units: u16,
    base: TimeBase,
}

/// Kani's symbolic S5TIME: any base, any units within the invariant `units <= 999`.
#[cfg(kani)]
impl kani::Arbitrary for S5Time {
    fn any() -> S5Time {
        let units: u16 = kani::any();
        kani::assume(units <= 999);
        S5Time {
            units,
            base: kani::any(),
        }
    }
}

/// Any valid S5TIME: units 0..=999 of any base (feature `bolero`).
#[cfg(feature = "bolero")]
impl bolero_generator::TypeGenerator for S5Time {
    fn generate<D: bolero_generator::Driver>(driver: &mut D) -> Option<S5Time> {
        use bolero_generator::ValueGenerator;
        let units = (0u16..=999).generate(driver)?;
        Some(S5Time {
            units,
            base: driver.produce()?,
        })
    }
}

impl S5Time {
    /// Zero: `W#16#0000`.
    pub const ZERO: S5Time = S5Time {
        units: 0,
        base: TimeBase::Ms10,
    };
    /// The largest S5TIME: 999 x 10 s = 9 990 s, `W#16#3999`.
    pub const MAX: S5Time = S5Time {
        units: 999,
        base: TimeBase::S10,
    };
    /// The largest duration in milliseconds, 9 990 000.
    pub const MAX_MILLIS: u32 = 9_990_000;

    /// `units` (0..=999) of `base`.
    ///
    /// ```
    /// use plc_timers::time::{S5Time, TimeBase};
    /// assert!(S5Time::new(999, TimeBase::S10).is_ok());
    /// assert!(S5Time::new(1000, TimeBase::Ms10).is_err());
    /// ```
    pub const fn new(units: u16, base: TimeBase) -> Result<S5Time, S5TimeError> {
        if units > 999 {
            return Err(S5TimeError::UnitsOutOfRange { units });
        }
        Ok(S5Time { units, base })
    }

    /// Decodes a word: bits 11-0 three BCD digits (each checked), bits 13-12 the base, bits 15-14
    /// ignored (LAD manual §9.1; the Siemens help calls them irrelevant).
    ///
    /// ```
    /// use plc_timers::time::{S5Time, TimeBase};
    /// let t = S5Time::from_word(0xC127)?; // bits 15-14 ignored
    /// assert_eq!((t.units(), t.base()), (127, TimeBase::Ms10));
    /// # Ok::<(), plc_timers::time::S5TimeError>(())
    /// ```
    pub const fn from_word(word: u16) -> Result<S5Time, S5TimeError> {
        match bcd3_decode(word) {
            Ok(units) => Ok(S5Time {
                units,
                base: TimeBase::from_bits((word >> 12) as u8),
            }),
            Err((position, digit)) => Err(S5TimeError::BcdDigit {
                word,
                position,
                digit,
            }),
        }
    }

    /// The word: BCD value in bits 11-0, base in bits 13-12, bits 15-14 zero.
    pub const fn to_word(self) -> u16 {
        (self.base.bits() as u16) << 12 | self.bcd()
    }

    /// The value field as three BCD digits (bits 11-0, no base): the DEZ/BCD reading of the
    /// units.
    #[doc(alias = "DEZ")]
    pub const fn bcd(self) -> u16 {
        bcd3_encode(self.units)
    }

    /// The number of time-base units, 0..=999, in binary (the DUAL/BI reading).
    #[doc(alias = "DUAL")]
    #[doc(alias = "BI")]
    pub const fn units(self) -> u16 {
        self.units
    }

    /// The time base.
    pub const fn base(self) -> TimeBase {
        self.base
    }

    /// The duration in milliseconds: `units x base`, at most 9 990 000.
    pub const fn as_millis(self) -> u32 {
        self.units as u32 * self.base.millis()
    }

    /// The S5TIME for a duration, as `S5T#` literals are encoded (LAD manual §9.1): the finest base
    /// whose value, rounded **down** to that base, fits in 999 units; the value rounded down.
    ///
    /// Errors above 9 990 000 ms rather than clamping.
    ///
    /// ```
    /// use plc_timers::time::S5Time;
    /// assert_eq!(S5Time::from_millis(10_005).map(S5Time::to_word), Ok(0x1100)); // rounded down
    /// assert!(S5Time::from_millis(9_990_001).is_err());
    /// ```
    pub const fn from_millis(millis: u64) -> Result<S5Time, S5TimeError> {
        if millis > S5Time::MAX_MILLIS as u64 {
            return Err(S5TimeError::DurationOutOfRange { millis });
        }
        let mut i = 0;
        while i < TimeBase::ALL.len() {
            let base = TimeBase::ALL[i];
            let units = millis / base.millis() as u64;
            if units <= 999 {
                return Ok(S5Time {
                    units: units as u16,
                    base,
                });
            }
            i += 1;
        }
        // Unreachable: 9 990 000 / 10 000 = 999 fits the coarsest base.
        Err(S5TimeError::DurationOutOfRange { millis })
    }

    /// The automatic encoding of this value's duration (what [`S5Time::from_millis`] gives for
    /// it): the same duration on the finest base that holds it. A value on a coarser base than
    /// needed (Berger §7.1: `W#16#2001` for 1 s) becomes the preferred form (`W#16#0100`).
    ///
    /// ```
    /// use plc_timers::time::S5Time;
    /// let t = S5Time::from_word(0x2001)?;
    /// assert_eq!(t.to_automatic().to_word(), 0x0100);
    /// # Ok::<(), plc_timers::time::S5TimeError>(())
    /// ```
    #[must_use]
    pub const fn to_automatic(self) -> S5Time {
        match S5Time::from_millis(self.as_millis() as u64) {
            Ok(t) => t,
            // Unreachable: as_millis() <= MAX_MILLIS for every valid value.
            Err(_) => self,
        }
    }

    /// Whether this value is on the automatic base for its duration (`self == self.to_automatic()`).
    pub const fn is_automatic(self) -> bool {
        let a = self.to_automatic();
        a.units == self.units && a.base as u8 == self.base as u8
    }
}

impl S5Time {
    /// Parses `S5T#aH_bbM_ccS_dddMS`, `S5TIME#…` (case-insensitive, underscores optional, units
    /// from largest to smallest, each at most once; the first may exceed its usual range, as in
    /// `S5T#120S`) with the automatic base and rounding down, or `W#16#wxyz` (one to four hex
    /// digits, BCD checked, bits 15-14 ignored). A `const fn`, so that [`crate::s5time!`] checks
    /// a literal at compile time; [`str::parse`] calls it too.
    ///
    /// ```
    /// use plc_timers::time::{S5Time, TimeBase};
    /// let t = S5Time::parse("S5T#2M7S")?;
    /// assert_eq!((t.units(), t.base()), (127, TimeBase::S1));
    /// assert_eq!(t.to_word(), 0x2127);
    /// assert!(S5Time::parse("W#16#20A1").is_err()); // BCD digit A
    /// # Ok::<(), plc_timers::time::LiteralError>(())
    /// ```
    pub const fn parse(text: &str) -> Result<S5Time, LiteralError> {
        const WHAT: LiteralType = LiteralType::S5Time;
        const fn fail(position: usize, kind: LiteralErrorKind) -> Result<S5Time, LiteralError> {
            Err(LiteralError::new(WHAT, position, kind))
        }
        let b = text.as_bytes();
        if b.is_empty() {
            return fail(0, LiteralErrorKind::Empty);
        }
        if has_prefix_ci(b, 0, "W#16#") {
            let offset = 5;
            let digits = b.len() - offset;
            if digits == 0 || digits > 4 {
                return fail(offset, LiteralErrorKind::HexDigits);
            }
            let mut word = 0u16;
            let mut i = offset;
            while i < b.len() {
                let d = match (b[i] as char).to_digit(16) {
                    Some(d) => d as u16,
                    None => return fail(offset, LiteralErrorKind::HexDigits),
                };
                word = word << 4 | d;
                i += 1;
            }
            return match S5Time::from_word(word) {
                Ok(t) => Ok(t),
                // The digit's byte in the text: the last hex digit is the ones digit.
                Err(S5TimeError::BcdDigit {
                    position, digit, ..
                }) => fail(
                    (b.len() - 1).saturating_sub(position as usize),
                    LiteralErrorKind::BcdDigit(digit),
                ),
                Err(_) => fail(offset, LiteralErrorKind::OutOfRange),
            };
        }
        let offset = if has_prefix_ci(b, 0, "S5TIME#") {
            7
        } else if has_prefix_ci(b, 0, "S5T#") {
            4
        } else {
            return fail(0, LiteralErrorKind::Prefix);
        };
        if offset < b.len() && b[offset] == b'-' {
            return fail(offset, LiteralErrorKind::Negative);
        }
        match parse_components(WHAT, b, offset) {
            Ok(millis) => match S5Time::from_millis(millis) {
                Ok(t) => Ok(t),
                Err(_) => fail(offset, LiteralErrorKind::OutOfRange),
            },
            Err(e) => Err(e),
        }
    }
}

impl core::str::FromStr for S5Time {
    type Err = LiteralError;

    /// [`S5Time::parse`].
    fn from_str(text: &str) -> Result<S5Time, LiteralError> {
        S5Time::parse(text)
    }
}

impl fmt::Display for S5Time {
    /// The canonical literal: `S5T#` and the duration without underscores, zero units omitted
    /// (`S5T#2M7S`, `S5T#10MS`, `S5T#0MS`). The base is not shown: parsing the literal gives the
    /// automatic base, which may differ from this value's base for the same duration.
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str("S5T#")?;
        write_components(f, u64::from(self.as_millis()), LiteralType::S5Time, "")
    }
}
