//! IEC `LTIME` of the S7-1500: a signed 64-bit count of nanoseconds.

use super::literal::{parse_signed, write_components};
use super::literal::{LiteralError, LiteralErrorKind, LiteralType};
use super::Time;

/// IEC `LTIME`: signed 64-bit nanoseconds,
/// `LT#-106751d_23h_47m_16s_854ms_775us_808ns ..= LT#106751d_23h_47m_16s_854ms_775us_807ns`
/// (about ±292 years; LTIME-RANGE-01).
///
/// ```
/// use plc_timers::time::LTime;
/// let t: LTime = "LT#1ms_500us".parse()?;
/// assert_eq!(t.as_nanos(), 1_500_000);
/// assert_eq!(t.to_string(), "LT#1MS_500US");
/// # Ok::<(), plc_timers::time::LiteralError>(())
/// ```
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, PartialOrd, Ord, Hash)]
#[cfg_attr(kani, derive(kani::Arbitrary))]
#[cfg_attr(feature = "bolero", derive(bolero_generator::TypeGenerator))]
pub struct LTime(i64);

impl LTime {
    /// `LT#0ns`.
    pub const ZERO: LTime = LTime(0);
    /// `LT#-106751d_23h_47m_16s_854ms_775us_808ns`, -2^63 ns.
    pub const MIN: LTime = LTime(i64::MIN);
    /// `LT#106751d_23h_47m_16s_854ms_775us_807ns`, 2^63 - 1 ns.
    pub const MAX: LTime = LTime(i64::MAX);

    /// The `LTIME` of `nanos` nanoseconds.
    ///
    /// ```
    /// use plc_timers::time::LTime;
    /// assert_eq!(LTime::from_nanos(-5).to_string(), "LT#-5NS");
    /// ```
    pub const fn from_nanos(nanos: i64) -> LTime {
        LTime(nanos)
    }

    /// The value in nanoseconds.
    pub const fn as_nanos(self) -> i64 {
        self.0
    }

    /// The `LTIME` of `nanos` ns, or `None` outside the 64-bit range.
    ///
    /// ```
    /// use plc_timers::time::LTime;
    /// assert_eq!(LTime::from_nanos_i128(i128::from(i64::MIN)), Some(LTime::MIN));
    /// assert_eq!(LTime::from_nanos_i128(1 << 63), None);
    /// ```
    pub const fn from_nanos_i128(nanos: i128) -> Option<LTime> {
        if nanos < i64::MIN as i128 || nanos > i64::MAX as i128 {
            None
        } else {
            Some(LTime(nanos as i64))
        }
    }

    /// `self + rhs`, or `None` when the sum leaves the LTIME range (LTIME-RANGE-01).
    #[must_use = "the result is the new LTIME; the value itself is unchanged"]
    pub const fn checked_add(self, rhs: LTime) -> Option<LTime> {
        match self.0.checked_add(rhs.0) {
            Some(v) => Some(LTime(v)),
            None => None,
        }
    }

    /// `self - rhs`, or `None` when the difference leaves the LTIME range (LTIME-RANGE-01).
    #[must_use = "the result is the new LTIME; the value itself is unchanged"]
    pub const fn checked_sub(self, rhs: LTime) -> Option<LTime> {
        match self.0.checked_sub(rhs.0) {
            Some(v) => Some(LTime(v)),
            None => None,
        }
    }

    /// The preset as a timer instruction uses it: a negative `PT` is taken as 0, as for TIME.
    pub const fn clamp_negative(self) -> u64 {
        if self.0 < 0 {
            0
        } else {
            self.0 as u64
        }
    }

    /// Parses `LT#…` or `LTIME#…` (case-insensitive, underscores optional, an optional `-` after
    /// `#`, units D, H, M, S, MS, US, NS from largest to smallest, each at most once; the first
    /// may exceed its usual range, as in `LT#90M`), or a plain whole number of nanoseconds with an
    /// optional sign. The range is checked exactly. A `const fn`, so that [`crate::ltime!`]
    /// checks a literal at compile time; [`str::parse`] calls it too.
    ///
    /// ```
    /// use plc_timers::time::LTime;
    /// assert_eq!(LTime::parse("LT#1MS500US")?.as_nanos(), 1_500_000);
    /// assert_eq!(LTime::parse("LTIME#30D")?.as_nanos(), 30 * 86_400_000_000_000);
    /// assert_eq!(LTime::parse("-7")?.as_nanos(), -7);
    /// assert_eq!(LTime::parse("LT#-106751D_23H_47M_16S_854MS_775US_808NS")?, LTime::MIN);
    /// assert!(LTime::parse("LT#106751D_23H_47M_16S_854MS_775US_808NS").is_err());
    /// assert!(LTime::parse("T#5S").is_err()); // a TIME literal is not an LTIME one
    /// # Ok::<(), plc_timers::time::LiteralError>(())
    /// ```
    pub const fn parse(text: &str) -> Result<LTime, LiteralError> {
        let (negative, magnitude, value_start) =
            match parse_signed(LiteralType::LTime, text.as_bytes()) {
                Ok(parts) => parts,
                Err(e) => return Err(e),
            };
        let signed = if negative {
            -(magnitude as i128)
        } else {
            magnitude as i128
        };
        match LTime::from_nanos_i128(signed) {
            Some(t) => Ok(t),
            None => Err(LiteralError::new(
                LiteralType::LTime,
                value_start,
                LiteralErrorKind::OutOfRange,
            )),
        }
    }
}

impl From<Time> for LTime {
    /// The same duration: a TIME is at most 2^31 ms, about 2.1e15 ns, well inside LTIME.
    fn from(t: Time) -> LTime {
        LTime(t.as_millis() as i64 * 1_000_000)
    }
}

impl core::str::FromStr for LTime {
    type Err = LiteralError;

    /// [`LTime::parse`].
    fn from_str(text: &str) -> Result<LTime, LiteralError> {
        LTime::parse(text)
    }
}

impl core::fmt::Display for LTime {
    /// `LT#` and the components, upper case, separated by `_`, zero components omitted:
    /// `LT#1MS_500US`, `LT#0NS`, `LT#-106751D_23H_47M_16S_854MS_775US_808NS`.
    fn fmt(&self, f: &mut core::fmt::Formatter<'_>) -> core::fmt::Result {
        f.write_str(if self.0 < 0 { "LT#-" } else { "LT#" })?;
        write_components(f, self.0.unsigned_abs(), LiteralType::LTime, "_")
    }
}
