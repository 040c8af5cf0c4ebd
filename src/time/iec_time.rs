//! IEC `TIME`: a signed 32-bit count of milliseconds (S7-1200 manual, Table 8-21).

use super::literal::{parse_signed, write_components};
use super::literal::{LiteralError, LiteralErrorKind, LiteralType};
use super::S5Time;

/// IEC `TIME`: signed 32-bit milliseconds, `T#-24d_20h_31m_23s_648ms ..= T#24d_20h_31m_23s_647ms`.
///
/// ```
/// use plc_timers::time::Time;
/// let t: Time = "T#1D_2H".parse()?;
/// assert_eq!(t.as_millis(), 93_600_000);
/// assert_eq!(t.to_string(), "T#1D_2H");
/// # Ok::<(), plc_timers::time::LiteralError>(())
/// ```
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, PartialOrd, Ord, Hash)]
#[cfg_attr(kani, derive(kani::Arbitrary))]
#[cfg_attr(feature = "bolero", derive(bolero_generator::TypeGenerator))]
pub struct Time(i32);

impl Time {
    /// `T#0ms`.
    pub const ZERO: Time = Time(0);
    /// `T#-24d_20h_31m_23s_648ms`, -2 147 483 648 ms.
    pub const MIN: Time = Time(i32::MIN);
    /// `T#24d_20h_31m_23s_647ms`, 2 147 483 647 ms.
    pub const MAX: Time = Time(i32::MAX);

    /// The `TIME` of `millis` milliseconds.
    ///
    /// ```
    /// use plc_timers::time::Time;
    /// assert_eq!(Time::from_millis(-5).to_string(), "T#-5MS");
    /// ```
    pub const fn from_millis(millis: i32) -> Time {
        Time(millis)
    }

    /// The value in milliseconds.
    pub const fn as_millis(self) -> i32 {
        self.0
    }
}

impl Time {
    /// The `TIME` of `millis` ms, or `None` outside the 32-bit range.
    ///
    /// ```
    /// use plc_timers::time::Time;
    /// assert_eq!(Time::from_millis_i64(i64::from(i32::MAX)), Some(Time::MAX));
    /// assert_eq!(Time::from_millis_i64(1 << 31), None);
    /// ```
    pub const fn from_millis_i64(millis: i64) -> Option<Time> {
        if millis < i32::MIN as i64 || millis > i32::MAX as i64 {
            None
        } else {
            Some(Time(millis as i32))
        }
    }

    /// `self + rhs`, or `None` when the sum leaves the TIME range (TIME-ARITH-01).
    #[must_use = "the result is the new TIME; the value itself is unchanged"]
    pub const fn checked_add(self, rhs: Time) -> Option<Time> {
        match self.0.checked_add(rhs.0) {
            Some(v) => Some(Time(v)),
            None => None,
        }
    }

    /// `self - rhs`, or `None` when the difference leaves the TIME range (TIME-ARITH-01).
    #[must_use = "the result is the new TIME; the value itself is unchanged"]
    pub const fn checked_sub(self, rhs: Time) -> Option<Time> {
        match self.0.checked_sub(rhs.0) {
            Some(v) => Some(Time(v)),
            None => None,
        }
    }

    /// `self + rhs`, clamped to [`Time::MIN`]`..=`[`Time::MAX`] (TIME-ARITH-01).
    ///
    /// ```
    /// use plc_timers::time::Time;
    /// assert_eq!(Time::MAX.saturating_add(Time::from_millis(1)), Time::MAX);
    /// assert_eq!(Time::from_millis(-5).saturating_add(Time::from_millis(7)).as_millis(), 2);
    /// ```
    #[must_use = "the result is the new TIME; the value itself is unchanged"]
    pub const fn saturating_add(self, rhs: Time) -> Time {
        Time(self.0.saturating_add(rhs.0))
    }

    /// `self - rhs`, clamped to [`Time::MIN`]`..=`[`Time::MAX`] (TIME-ARITH-01).
    #[must_use = "the result is the new TIME; the value itself is unchanged"]
    pub const fn saturating_sub(self, rhs: Time) -> Time {
        Time(self.0.saturating_sub(rhs.0))
    }

    /// `-self`, or `None` for [`Time::MIN`], whose negation is one past [`Time::MAX`]
    /// (TIME-ARITH-01).
    #[must_use = "the result is the new TIME; the value itself is unchanged"]
    pub const fn checked_neg(self) -> Option<Time> {
        match self.0.checked_neg() {
            Some(v) => Some(Time(v)),
            None => None,
        }
    }

    /// The preset as a timer instruction uses it: a negative `PT` is taken as 0 (S7-1200 manual,
    /// Table 8-21 note 1).
    pub const fn clamp_negative(self) -> u32 {
        if self.0 < 0 {
            0
        } else {
            self.0 as u32
        }
    }
}

impl From<S5Time> for Time {
    /// The same duration: an S5TIME is at most 9 990 000 ms, well inside TIME.
    fn from(t: S5Time) -> Time {
        // Lossless: as_millis() <= S5Time::MAX_MILLIS < i32::MAX.
        Time(t.as_millis() as i32)
    }
}

impl Time {
    /// Parses `T#…` or `TIME#…` (case-insensitive, underscores optional, an optional `-` after
    /// `#`, units D, H, M, S, MS from largest to smallest, each at most once; the first may exceed
    /// its usual range, as in `T#90M`), or a plain whole number of milliseconds with an optional
    /// sign (S7-1200 manual: "T#200ms or 200"). The range is checked exactly. A `const fn`, so that
    /// [`crate::time!`] checks a literal at compile time; [`str::parse`] calls it too.
    ///
    /// ```
    /// use plc_timers::time::Time;
    /// assert_eq!(Time::parse("T#2s_200ms")?.as_millis(), 2200);
    /// assert_eq!(Time::parse("200")?.as_millis(), 200);
    /// assert_eq!(Time::parse("T#-24D_20H_31M_23S_648MS")?, Time::MIN);
    /// assert!(Time::parse("T#24D_20H_31M_23S_648MS").is_err());
    /// # Ok::<(), plc_timers::time::LiteralError>(())
    /// ```
    pub const fn parse(text: &str) -> Result<Time, LiteralError> {
        let (negative, magnitude, value_start) =
            match parse_signed(LiteralType::Time, text.as_bytes()) {
                Ok(parts) => parts,
                Err(e) => return Err(e),
            };
        // Any magnitude above 2^31 is out of range; capping keeps the sign change exact.
        let capped = if magnitude > 1 << 40 {
            1 << 40
        } else {
            magnitude
        } as i64;
        let signed = if negative { -capped } else { capped };
        match Time::from_millis_i64(signed) {
            Some(t) => Ok(t),
            None => Err(LiteralError::new(
                LiteralType::Time,
                value_start,
                LiteralErrorKind::OutOfRange,
            )),
        }
    }
}

impl core::str::FromStr for Time {
    type Err = LiteralError;

    /// [`Time::parse`].
    fn from_str(text: &str) -> Result<Time, LiteralError> {
        Time::parse(text)
    }
}

impl core::fmt::Display for Time {
    /// `T#` and the components, upper case, separated by `_`, zero components omitted:
    /// `T#2S_200MS`, `T#0MS`, `T#-24D_20H_31M_23S_648MS`.
    fn fmt(&self, f: &mut core::fmt::Formatter<'_>) -> core::fmt::Result {
        f.write_str(if self.0 < 0 { "T#-" } else { "T#" })?;
        write_components(f, u64::from(self.0.unsigned_abs()), LiteralType::Time, "_")
    }
}
