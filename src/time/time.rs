//! IEC `TIME`: a signed 32-bit count of milliseconds (seed 001, Table 8-21).

/// IEC `TIME`: signed 32-bit milliseconds, `T#-24d_20h_31m_23s_648ms ..= T#24d_20h_31m_23s_647ms`.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, PartialOrd, Ord, Hash)]
pub struct Time(i32);

impl Time {
    /// `T#0ms`.
    pub const ZERO: Time = Time(0);
    /// `T#-24d_20h_31m_23s_648ms`, -2 147 483 648 ms.
    pub const MIN: Time = Time(i32::MIN);
    /// `T#24d_20h_31m_23s_647ms`, 2 147 483 647 ms.
    pub const MAX: Time = Time(i32::MAX);

    /// The `TIME` of `millis` milliseconds.
    pub const fn from_millis(millis: i32) -> Time {
        Time(millis)
    }

    /// The value in milliseconds.
    pub const fn as_millis(self) -> i32 {
        self.0
    }
}
