//! The optimized S5 counter: one 16-bit word.
//!
//! ```text
//!  15      14     13      12      11 10    9 .. 0
//!  FR edge S edge CD edge CU edge  0  0    CV (binary, 0..=999)
//! ```

use super::{S5CounterInput, S5CounterKind, S5CounterOps, S5CounterOutput, S5CounterState, CV_MAX};
use crate::time::BCD3_TABLE;

const CV: u16 = 0x03FF;
const CU_PREV: u16 = 1 << 12;
const CD_PREV: u16 = 1 << 13;
const S_PREV: u16 = 1 << 14;
const FR_PREV: u16 = 1 << 15;
/// Every bit a valid word may have set.
const USED: u16 = CV | CU_PREV | CD_PREV | S_PREV | FR_PREV;
// The five fields are disjoint (their sum is their union), so `|` of two of them is `^` and `+`,
// and clearing one leaves the others.
const _: () = assert!(CV + CU_PREV + CD_PREV + S_PREV + FR_PREV == USED);

const fn bit(b: bool, mask: u16) -> u16 {
    (b as u16).wrapping_neg() & mask
}

/// One S5 counter packed in a word: CV in bits 9-0, the edge memories of CU, CD, S and FR in
/// bits 12-15. The field is private: every word this type holds is valid (CV at most 999,
/// bits 11-10 zero), which [`S5Counter::from_bits`] checks.
///
/// ```
/// use plc_timers::counter::s5::{CounterPreset, S5Counter, S5CounterInput, S5CounterKind, S5CounterOps};
/// let pv = CounterPreset::new(999)?;
/// let mut w = S5Counter::new();
/// w.call(S5CounterKind::SCud, S5CounterInput::new(false, false, pv).with_s(true));
/// // CU and CD rising together at 999: the count up saturates, the count down takes one off.
/// assert_eq!(w.call(S5CounterKind::SCud, S5CounterInput::new(true, true, pv)).cv, 998);
/// # Ok::<(), plc_timers::counter::s5::CounterPresetError>(())
/// ```
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash)]
#[repr(transparent)]
pub struct S5Counter(u16);

impl S5Counter {
    /// A new counter: CV = 0, every edge memory 0.
    ///
    /// ```
    /// use plc_timers::counter::s5::{S5Counter, S5CounterOps, S5CounterState};
    /// assert_eq!(S5Counter::new().state(), S5CounterState::RESET);
    /// ```
    pub const fn new() -> S5Counter {
        S5Counter(0)
    }

    /// The word with bits `bits`, or `None` when CV exceeds 999 or bits 11-10 are set.
    ///
    /// ```
    /// use plc_timers::counter::s5::S5Counter;
    /// assert_eq!(S5Counter::from_bits(0x1005).map(|w| w.output().cv), Some(5)); // CU memory set, CV 5
    /// assert!(S5Counter::from_bits(1000).is_none());
    /// ```
    pub const fn from_bits(bits: u16) -> Option<S5Counter> {
        if bits & !USED == 0 && bits & CV <= CV_MAX {
            Some(S5Counter(bits))
        } else {
            None
        }
    }

    /// The word's bits.
    pub const fn bits(self) -> u16 {
        self.0
    }

    /// The word holding `state`, if CV <= 999.
    ///
    /// ```
    /// use plc_timers::counter::s5::{S5Counter, S5CounterState};
    /// let w = S5Counter::from_state(S5CounterState { cv: 999, cu_prev: true, ..S5CounterState::RESET });
    /// assert_eq!(w.map(S5Counter::bits), Some(0x13E7));
    /// ```
    pub const fn from_state(state: S5CounterState) -> Option<S5Counter> {
        if !state.is_valid() {
            return None;
        }
        Some(S5Counter(
            state.cv
                | bit(state.cu_prev, CU_PREV)
                | bit(state.cd_prev, CD_PREV)
                | bit(state.s_prev, S_PREV)
                | bit(state.fr_prev, FR_PREV),
        ))
    }

    /// The abstraction function: the reference state this word represents.
    pub const fn state(self) -> S5CounterState {
        S5CounterState {
            cv: self.0 & CV,
            cu_prev: self.0 & CU_PREV != 0,
            cd_prev: self.0 & CD_PREV != 0,
            s_prev: self.0 & S_PREV != 0,
            fr_prev: self.0 & FR_PREV != 0,
        }
    }

    /// `FR C n` with RLO `rlo`: a rising RLO clears the edge memories of CU, CD and S.
    #[inline]
    #[must_use]
    pub const fn enable(self, rlo: bool) -> S5Counter {
        // RLO 0: the memory takes 0. RLO 1 with the memory 1: no edge, nothing changes.
        // Otherwise a rising RLO: the three memories cleared, the FR memory set.
        let w = self.0;
        if !rlo {
            return S5Counter(w & !FR_PREV);
        }
        if w & FR_PREV != 0 {
            return self;
        }
        S5Counter((w & !(CU_PREV | CD_PREV | S_PREV)) | FR_PREV)
    }

    /// `CU C n` with RLO `rlo`: a rising RLO counts up, except at 999.
    #[inline]
    #[must_use]
    pub const fn count_up(self, rlo: bool) -> S5Counter {
        // RLO 0: the memory takes 0. RLO 1 with the memory 1: no edge. A rising RLO sets the
        // memory and adds 1 below 999 (CV is the low bits: no carry into the memories).
        let w = self.0;
        if !rlo {
            return S5Counter(w & !CU_PREV);
        }
        if w & CU_PREV != 0 {
            return self;
        }
        let up = w & CV < CV_MAX;
        S5Counter((w | CU_PREV) + up as u16)
    }

    /// `CD C n` with RLO `rlo`: a rising RLO counts down, except at 0.
    #[inline]
    #[must_use]
    pub const fn count_down(self, rlo: bool) -> S5Counter {
        // As `count_up`, subtracting 1 above 0 (no borrow from the memories).
        let w = self.0;
        if !rlo {
            return S5Counter(w & !CD_PREV);
        }
        if w & CD_PREV != 0 {
            return self;
        }
        let down = w & CV > 0;
        S5Counter((w | CD_PREV) - down as u16)
    }

    /// `S C n` with RLO `rlo` and the preset `pv` in ACCU 1: a rising RLO sets CV to PV and
    /// clears the edge memories of CU and CD.
    #[inline]
    #[must_use]
    pub const fn set(self, rlo: bool, pv: super::CounterPreset) -> S5Counter {
        // RLO 0: the memory takes 0. RLO 1 with the memory 1: no edge. A rising RLO loads PV
        // (at most 999, within the CV field), clears the CU and CD memories, sets its own.
        let w = self.0;
        if !rlo {
            return S5Counter(w & !S_PREV);
        }
        if w & S_PREV != 0 {
            return self;
        }
        S5Counter((w & !(CV | CU_PREV | CD_PREV)) | pv.value() | S_PREV)
    }

    /// `R C n` with RLO `rlo`: CV = 0 while 1.
    #[inline]
    #[must_use]
    pub const fn reset(self, rlo: bool) -> S5Counter {
        if rlo {
            S5Counter(self.0 & !CV)
        } else {
            self
        }
    }

    /// One box call `kind`: `FR`, `CU` (unless S_CD), `CD` (unless S_CU), `S`, `R`.
    #[inline]
    #[must_use]
    pub(crate) const fn execute(self, kind: S5CounterKind, i: S5CounterInput) -> S5Counter {
        let mut w = self.enable(i.fr);
        if kind.counts_up() {
            w = w.count_up(i.cu);
        }
        if kind.counts_down() {
            w = w.count_down(i.cd);
        }
        w.set(i.s, i.pv).reset(i.r)
    }

    /// The outputs (BCD by table lookup).
    pub const fn output(self) -> S5CounterOutput {
        let cv = self.0 & CV;
        S5CounterOutput {
            q: cv != 0,
            cv,
            cv_bcd: BCD3_TABLE[cv as usize],
        }
    }
}

impl S5CounterOps for S5Counter {
    /// One box call (`FR`, `CU`, `CD`, `S`, `R` on the word), then the outputs. Each operation of the box
    /// branches on its input and its edge memory, which for a counter called once per scan
    /// go the same way most scans (measured faster than computing every operation with
    /// masks, whose bit chains make each call wait for the previous one).
    #[inline(always)]
    fn call(&mut self, kind: S5CounterKind, input: S5CounterInput) -> S5CounterOutput {
        *self = self.execute(kind, input);
        self.output()
    }

    fn state(&self) -> S5CounterState {
        S5Counter::state(*self)
    }
}

impl S5Counter {
    /// SC-RETAIN-01: a RUN-STOP-RUN, as [`super::S5CounterRef::run_stop_run`]: the word kept
    /// (retentive) or cleared.
    ///
    /// ```
    /// use plc_timers::counter::s5::{S5Counter, S5CounterInput, S5CounterKind, S5CounterOps};
    /// let mut c = S5Counter::new();
    /// c.call(S5CounterKind::SCu, S5CounterInput { cu: true, ..Default::default() });
    /// c.run_stop_run(false);
    /// assert_eq!(c, S5Counter::new());
    /// ```
    pub fn run_stop_run(&mut self, retentive: bool) {
        if !retentive {
            *self = S5Counter::new();
        }
    }
}
