//! IEC timers of S7-1200/1500: `TP`, `TON`, `TOF`, `TONR`, the `-(RT)-` and `-(PT)-` coils,
//! update-on-access (seed 001; seed 004).
//!
//! Two implementations of one interface, [`IecTimerOps`]:
//! - [`reference::Reference`]: the rules as the manual states them, one function per rule.
//! - [`IecTimer`] ([`structure::IecTimerOf`] on the 32-bit clock): the 16-byte `IEC_TIMER`
//!   structure as a soft-PLC holds it, `#[repr(C)]`, flags packed in one byte.
//!
//! [`structure::IecTimerOf::abstraction`] maps the structure to the reference state; the proofs
//! in `proofs/iec.rs` show that every operation commutes with it.
//!
//! Both are generic over the width of the CPU clock ([`ClockWord`]): `u32` is the S7-1200 clock;
//! `u8` lets the proof drivers enumerate every state.
//!
//! ```
//! use plc_timers::iec::{IecInput, IecKind, IecTimer, IecTimerOps};
//! use plc_timers::time::Time;
//!
//! let mut t = IecTimer::new();
//! let pt = Time::from_millis(500);
//! assert!(!t.call(IecKind::Ton, 1_000, IecInput::new(true, pt)).q); // rising IN: START = 1000
//! assert!(!t.call(IecKind::Ton, 1_499, IecInput::new(true, pt)).q);
//! let out = t.call(IecKind::Ton, 1_500, IecInput::new(true, pt)); // ET reaches PT: Q rises
//! assert_eq!((out.q, out.et), (true, 500));
//! ```

pub mod bank;
pub mod reference;
pub mod structure;

use crate::time::clock::ClockWord;
use crate::time::Time;

pub use structure::{IecTimer, IecTimerOf};

/// Which timer instruction runs on the structure.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
#[cfg_attr(kani, derive(kani::Arbitrary))]
pub enum IecKind {
    /// `TP`, pulse: Q = 1 for PT after a rising IN; IN and PT changes while running have no effect.
    Tp,
    /// `TON`, on-delay: Q = 1 once IN has been 1 for PT; IN = 0 resets.
    Ton,
    /// `TOF`, off-delay: Q = 1 while IN = 1 and for PT after IN falls; IN = 1 resets.
    Tof,
    /// `TONR`, retentive on-delay: accumulates the time IN is 1; only R resets.
    Tonr,
}

impl IecKind {
    /// All four, in manual order.
    pub const ALL: [IecKind; 4] = [IecKind::Tp, IecKind::Ton, IecKind::Tof, IecKind::Tonr];

    /// The instruction's name as the manual writes it.
    pub const fn name(self) -> &'static str {
        match self {
            IecKind::Tp => "TP",
            IecKind::Ton => "TON",
            IecKind::Tof => "TOF",
            IecKind::Tonr => "TONR",
        }
    }
}

/// The box inputs of one call.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
#[cfg_attr(kani, derive(kani::Arbitrary))]
pub struct IecInput {
    /// `IN`.
    pub input: bool,
    /// `PT`, the preset; negative values are taken as 0 (seed 001, Table 8-21 note 1).
    pub pt: Time,
    /// `R` (TONR only; ignored by TP, TON and TOF).
    pub reset: bool,
}

impl IecInput {
    /// `IN` and `PT`, with `R` = 0.
    pub const fn new(input: bool, pt: Time) -> IecInput {
        IecInput {
            input,
            pt,
            reset: false,
        }
    }
}

/// The box outputs of one call.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct IecOutput<C = u32> {
    /// `Q`.
    pub q: bool,
    /// `ET`, the elapsed time in milliseconds, `0..=PT`.
    pub et: C,
}

/// The observable state of an IEC timer: what the proofs compare and the abstraction function
/// produces. Field names are the manual's structure members.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, Default)]
pub struct IecState<C> {
    /// The instruction that last ran on the structure (`None` before the first call); needed
    /// by update-on-access, which must know how Q follows ET.
    pub kind: Option<IecKind>,
    /// `IN` as the last call saw it: the edge memory.
    pub input: bool,
    /// Whether the timer is timing.
    pub running: bool,
    /// `START`: the CPU clock when timing began (for TONR, shifted back by the accumulated time).
    pub start: C,
    /// `PT` as latched at the start (or loaded by the PT coil), negative taken as 0.
    pub pt: C,
    /// `ET` (`ELAPSED`).
    pub et: C,
    /// `Q`.
    pub q: bool,
}

impl<C: ClockWord> IecState<C> {
    /// The validity invariant every reachable state satisfies: `ET <= PT`; a stopped timer has
    /// no pending START (START is 0 when not running, so equal states are equal bytes).
    pub fn is_valid(&self) -> bool {
        self.et <= self.pt && (self.running || self.start == C::default())
    }
}

/// The operations of an IEC timer structure, common to the reference and the optimized one.
/// `now` is the CPU millisecond clock (modulo `2^BITS`).
pub trait IecTimerOps<C: ClockWord> {
    /// Executes the box (or coil) instruction `kind` with its inputs; returns `Q` and `ET`.
    fn call(&mut self, kind: IecKind, now: C, input: IecInput) -> IecOutput<C>;
    /// Reads the structure's `Q` member: an update at `now` happens first (seed 001).
    fn read_q(&mut self, now: C) -> bool;
    /// Reads the structure's `ELAPSED` member: an update at `now` happens first (seed 001).
    fn read_et(&mut self, now: C) -> C;
    /// The `-(RT)-` coil with power flow: resets the timer data (see `spec/iec.md`, IEC-RT-01).
    fn reset_timer(&mut self);
    /// The `-(PT)-` coil with power flow: loads `pt` into the structure's preset.
    fn preset_timer(&mut self, pt: Time);
    /// A RUN-STOP-RUN transition: a non-retentive structure returns to its initial values; a
    /// retentive one keeps its data.
    fn run_stop_run(&mut self, retentive: bool);
    /// The observable state.
    fn state(&self) -> IecState<C>;
}
