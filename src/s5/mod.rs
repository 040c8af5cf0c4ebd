//! S5 timers of S7-300/400: `S_PULSE`, `S_PEXT`, `S_ODT`, `S_ODTS`, `S_OFFDT` (seed 000 §9.1-9.7,
//! seed 003 §7).
//!
//! - [`reference::S5TimerRef`]: one timer as the manual describes it, one function per rule.
//! - [`cell`]: the optimized timer cell, the whole state packed in the CPU's 16-bit timer word.
//! - [`memory::TimerMemory`]: a timer memory area of N cells whose time-base tick updates every
//!   running timer in one pass, with the STL operations (SP/SE/SD/SS/SF, R, FR, L, LC, A/AN).
//!
//! Time follows the operating-system tick model (S5TMR-TICK-01): the tick of a base falls on
//! every whole multiple of the base on the CPU millisecond clock, and decrements each running
//! timer of that base by one unit; before a timer executes at `t`, every tick in `(t_prev, t]`
//! has been applied.
//!
//! ```
//! use plc_timers::s5::{reference::S5TimerRef, S5Input, S5Kind};
//! use plc_timers::time::S5Time;
//!
//! let tv: S5Time = "S5T#50MS".parse()?; // 5 units of 10 ms
//! let mut sd = S5TimerRef::new(S5Kind::SOdt);
//! assert!(!sd.call(0, S5Input::new(true, false, tv)).q); // rising S starts the on-delay
//! assert_eq!(sd.call(40, S5Input::new(true, false, tv)).bi, 1); // 4 ticks: 1 unit left
//! assert!(sd.call(50, S5Input::new(true, false, tv)).q); // 5th tick: expired, S = 1: Q = 1
//! # Ok::<(), plc_timers::time::LiteralError>(())
//! ```

pub mod cell;
pub mod memory;
pub mod reference;

use crate::time::{S5Time, TimeBase};

/// The five S5 timer kinds, with both mnemonic sets (watch the clash: English `SE` is the
/// extended pulse, German `SE` the on-delay).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
#[cfg_attr(kani, derive(kani::Arbitrary))]
pub enum S5Kind {
    /// `S_PULSE`, STL `SP` (German `SI`): pulse, Q = 1 while running and S = 1 (seed 000 §9.3).
    #[doc(alias = "SP")]
    #[doc(alias = "SI")]
    SPulse,
    /// `S_PEXT`, STL `SE` (German `SV`): extended pulse, runs on when S falls (seed 000 §9.4).
    #[doc(alias = "SE")]
    #[doc(alias = "SV")]
    SPext,
    /// `S_ODT`, STL `SD` (German `SE`): on-delay, Q = 1 after the time while S = 1 (seed 000 §9.5).
    #[doc(alias = "SD")]
    SOdt,
    /// `S_ODTS`, STL `SS`: retentive on-delay, Q = 1 after the time until R (seed 000 §9.6).
    #[doc(alias = "SS")]
    SOdts,
    /// `S_OFFDT`, STL `SF` (German `SA`): off-delay, starts on a falling S (seed 000 §9.7).
    #[doc(alias = "SF")]
    #[doc(alias = "SA")]
    SOffdt,
}

impl S5Kind {
    /// All five, in manual order.
    pub const ALL: [S5Kind; 5] = [
        S5Kind::SPulse,
        S5Kind::SPext,
        S5Kind::SOdt,
        S5Kind::SOdts,
        S5Kind::SOffdt,
    ];

    /// The LAD box name (`S_PULSE`, …).
    pub const fn name(self) -> &'static str {
        match self {
            S5Kind::SPulse => "S_PULSE",
            S5Kind::SPext => "S_PEXT",
            S5Kind::SOdt => "S_ODT",
            S5Kind::SOdts => "S_ODTS",
            S5Kind::SOffdt => "S_OFFDT",
        }
    }

    /// The international STL mnemonic (`SP`, `SE`, `SD`, `SS`, `SF`).
    pub const fn stl(self) -> &'static str {
        match self {
            S5Kind::SPulse => "SP",
            S5Kind::SPext => "SE",
            S5Kind::SOdt => "SD",
            S5Kind::SOdts => "SS",
            S5Kind::SOffdt => "SF",
        }
    }

    /// Whether the timer starts on a falling edge of S (only `S_OFFDT`).
    pub const fn starts_on_falling_edge(self) -> bool {
        matches!(self, S5Kind::SOffdt)
    }
}

/// The inputs of one execution of an S5 timer box.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct S5Input {
    /// `S`, the start input.
    pub s: bool,
    /// `R`, the reset input.
    pub r: bool,
    /// `FR`, the enable input (STL `FR T n`; not on the LAD boxes, false there).
    pub fr: bool,
    /// `TV` (`TW`), the time value loaded on a start.
    pub tv: S5Time,
}

impl S5Input {
    /// `S`, `R` and `TV`, with `FR` = 0.
    pub const fn new(s: bool, r: bool, tv: S5Time) -> S5Input {
        S5Input {
            s,
            r,
            fr: false,
            tv,
        }
    }
}

/// The outputs of one execution.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct S5Output {
    /// `Q`, the timer status.
    pub q: bool,
    /// `BI` (`DUAL`): the remaining value in units, binary.
    pub bi: u16,
    /// `BCD` (`DEZ`): the remaining value as three BCD digits with the base in bits 13-12.
    pub bcd: u16,
}

/// The state of one S5 timer as the reference names it; the packed cell maps to it through
/// [`cell::abstraction`].
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub struct S5State {
    /// Whether the time is running (being decremented by the OS).
    pub running: bool,
    /// The remaining value in units, 0..=999 (binary, seed 000 §9.1 "bits 0-9").
    pub value: u16,
    /// The time base of the running or last value.
    pub base: TimeBase,
    /// The timer status `Q` (what `A T n` scans).
    pub q: bool,
    /// `S` at the previous execution: the edge memory for starts.
    pub s_prev: bool,
    /// `FR` at the previous execution: the edge memory of the enable.
    pub fr_prev: bool,
}

impl S5State {
    /// A cleared timer: stopped, value and base 0, Q = 0, edge memories 0.
    pub const RESET: S5State = S5State {
        running: false,
        value: 0,
        base: TimeBase::Ms10,
        q: false,
        s_prev: false,
        fr_prev: false,
    };

    /// The invariant of every reachable state: the value fits its 10 bits and three BCD
    /// digits (0..=999).
    pub const fn is_valid(&self) -> bool {
        self.value <= 999
    }

    /// The outputs this state shows.
    pub const fn output(&self) -> S5Output {
        S5Output {
            q: self.q,
            bi: self.value,
            bcd: (self.base.bits() as u16) << 12 | crate::time::bcd3_encode(self.value),
        }
    }
}

/// The number of ticks of `base` in the interval `(from, to]` of the CPU millisecond clock:
/// ticks fall on whole multiples of the base (S5TMR-TICK-01).
pub const fn ticks_between(from: u64, to: u64, base: TimeBase) -> u64 {
    let b = base.millis() as u64;
    (to / b).saturating_sub(from / b)
}
