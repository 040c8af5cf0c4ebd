//! The S5 counter preset `PV`: `C#0` .. `C#999`, loaded into the counter as three BCD digits.

use core::fmt;

use super::CV_MAX;
use crate::time::{bcd3_decode, bcd3_encode, has_prefix_ci};

/// A counter preset `PV`: 0..=999 (a `C#` value). The field is private: every value of this
/// type is in range.
///
/// ```
/// use plc_timers::counter::s5::CounterPreset;
/// const BATCH: CounterPreset = match CounterPreset::parse("C#120") {
///     Ok(pv) => pv,
///     Err(_) => panic!("not a counter preset"),
/// };
/// assert_eq!((BATCH.value(), BATCH.to_bcd()), (120, 0x0120));
/// ```
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub struct CounterPreset(u16);

/// What was wrong with a counter preset.
///
/// ```
/// use plc_timers::counter::s5::{CounterPreset, CounterPresetError};
/// assert_eq!(CounterPreset::parse("C#1000"), Err(CounterPresetError::OutOfRange(1000)));
/// assert_eq!(CounterPreset::parse("W#16#00A0"), Err(CounterPresetError::BcdDigit(0x00A0)));
/// ```
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
#[non_exhaustive]
pub enum CounterPresetError {
    /// Not `C#n`, a whole number or `W#16#xyz`.
    Syntax,
    /// Above 999 (the value given, saturated at `u32::MAX`).
    OutOfRange(u32),
    /// A BCD digit above 9, or bits 15-12 set, in a `W#16#` word (the word).
    BcdDigit(u16),
}

impl fmt::Display for CounterPresetError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match *self {
            CounterPresetError::Syntax => {
                write!(
                    f,
                    "not a counter preset; write C#0 to C#999, 0 to 999, or W#16#0000 to W#16#0999"
                )
            }
            CounterPresetError::OutOfRange(v) => {
                write!(f, "{v} is above the S5 counter maximum of 999")
            }
            CounterPresetError::BcdDigit(w) => write!(
                f,
                "W#16#{w:04X} is not a BCD count: every digit must be 0-9 and the value at most 999"
            ),
        }
    }
}

#[cfg(feature = "std")]
impl std::error::Error for CounterPresetError {}

impl CounterPreset {
    /// The preset `n`, 0..=999.
    ///
    /// ```
    /// use plc_timers::counter::s5::CounterPreset;
    /// assert_eq!(CounterPreset::new(999).map(CounterPreset::value), Ok(999));
    /// assert!(CounterPreset::new(1000).is_err());
    /// ```
    pub const fn new(n: u16) -> Result<CounterPreset, CounterPresetError> {
        if n > CV_MAX {
            Err(CounterPresetError::OutOfRange(n as u32))
        } else {
            Ok(CounterPreset(n))
        }
    }

    /// The preset from its BCD word as `S C n` takes it from ACCU 1 (SC-BCD-01): three BCD
    /// digits, each checked; bits 15-12 must be 0.
    ///
    /// ```
    /// use plc_timers::counter::s5::CounterPreset;
    /// assert_eq!(CounterPreset::from_bcd(0x0999).map(|p| p.value()), Ok(999));
    /// assert!(CounterPreset::from_bcd(0x09A9).is_err());
    /// ```
    pub const fn from_bcd(word: u16) -> Result<CounterPreset, CounterPresetError> {
        if word > 0x0999 {
            return Err(CounterPresetError::BcdDigit(word));
        }
        match bcd3_decode(word) {
            Ok(n) => Ok(CounterPreset(n)),
            Err(_) => Err(CounterPresetError::BcdDigit(word)),
        }
    }

    /// The count, 0..=999.
    pub const fn value(self) -> u16 {
        self.0
    }

    /// The BCD word (`W#16#0xyz`).
    pub const fn to_bcd(self) -> u16 {
        bcd3_encode(self.0)
    }

    /// Parses `C#n` (n decimal, 0..=999), a whole number 0..=999, or `W#16#xyz` (BCD checked),
    /// surrounding spaces ignored. A `const fn`, so a preset constant can be written as a
    /// literal; [`str::parse`] calls it too.
    ///
    /// ```
    /// use plc_timers::counter::s5::CounterPreset;
    /// assert_eq!("C#5".parse::<CounterPreset>().map(|p| p.value()), Ok(5));
    /// assert!("C#1000".parse::<CounterPreset>().is_err());
    /// assert!("W#16#00A1".parse::<CounterPreset>().is_err());
    /// ```
    pub const fn parse(text: &str) -> Result<CounterPreset, CounterPresetError> {
        let t = text.trim_ascii().as_bytes();
        if has_prefix_ci(t, 0, "W#16#") {
            let digits = t.len() - 5;
            if digits == 0 || digits > 4 {
                return Err(CounterPresetError::Syntax);
            }
            let mut word = 0u16;
            let mut i = 5;
            while i < t.len() {
                match (t[i] as char).to_digit(16) {
                    Some(d) => word = word << 4 | d as u16,
                    None => return Err(CounterPresetError::Syntax),
                }
                i += 1;
            }
            return CounterPreset::from_bcd(word);
        }
        let start = if has_prefix_ci(t, 0, "C#") { 2 } else { 0 };
        if start == t.len() {
            return Err(CounterPresetError::Syntax);
        }
        let mut n: u32 = 0;
        let mut i = start;
        while i < t.len() {
            if !t[i].is_ascii_digit() {
                return Err(CounterPresetError::Syntax);
            }
            n = n.saturating_mul(10).saturating_add((t[i] - b'0') as u32);
            i += 1;
        }
        if n > CV_MAX as u32 {
            return Err(CounterPresetError::OutOfRange(n));
        }
        Ok(CounterPreset(n as u16))
    }
}

impl core::str::FromStr for CounterPreset {
    type Err = CounterPresetError;

    /// [`CounterPreset::parse`].
    fn from_str(text: &str) -> Result<CounterPreset, CounterPresetError> {
        CounterPreset::parse(text)
    }
}

impl fmt::Display for CounterPreset {
    /// The literal `C#n`.
    ///
    /// ```
    /// use plc_timers::counter::s5::CounterPreset;
    /// assert_eq!(CounterPreset::new(5).map(|c| c.to_string()).as_deref(), Ok("C#5"));
    /// ```
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "C#{}", self.value())
    }
}
