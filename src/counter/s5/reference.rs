//! The reference semantics of the S5 counters, one function per rule. The box executes as the
//! STL sequence it compiles to: `FR`, `CU`, `CD`, `S`, `R` (SC-STL-01).

use super::{S5CounterInput, S5CounterKind, S5CounterOps, S5CounterOutput, S5CounterState, CV_MAX};

/// The reference S5 counter.
///
/// ```
/// use plc_timers::counter::s5::{S5CounterInput, S5CounterKind, S5CounterOps, S5CounterRef};
/// let mut c = S5CounterRef::new();
/// let up = S5CounterInput { cu: true, ..Default::default() };
/// assert_eq!(c.call(S5CounterKind::SCud, up).cv, 1);
/// let reset = S5CounterInput { r: true, ..Default::default() };
/// assert!(!c.call(S5CounterKind::SCud, reset).q);
/// ```
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct S5CounterRef {
    state: S5CounterState,
}

impl S5CounterRef {
    /// A new counter: CV = 0.
    ///
    /// ```
    /// use plc_timers::counter::s5::{S5CounterOps, S5CounterRef, S5CounterState};
    /// assert_eq!(S5CounterRef::new().state(), S5CounterState::RESET);
    /// ```
    pub const fn new() -> S5CounterRef {
        S5CounterRef {
            state: S5CounterState::RESET,
        }
    }

    /// The counter in `state`, or `None` when CV is above 999.
    ///
    /// ```
    /// use plc_timers::counter::s5::{S5CounterRef, S5CounterState};
    /// assert!(S5CounterRef::from_state(S5CounterState { cv: 999, ..S5CounterState::RESET }).is_some());
    /// assert!(S5CounterRef::from_state(S5CounterState { cv: 1000, ..S5CounterState::RESET }).is_none());
    /// ```
    pub const fn from_state(state: S5CounterState) -> Option<S5CounterRef> {
        if state.is_valid() {
            Some(S5CounterRef { state })
        } else {
            None
        }
    }

    /// `FR C n` (SC-FR-01): a rising RLO clears the edge memories of counting and setting, so
    /// that a CU, CD or S operation executed with RLO = 1 acts again.
    pub fn enable(&mut self, rlo: bool) {
        let s = &mut self.state;
        if rlo && !s.fr_prev {
            s.cu_prev = false;
            s.cd_prev = false;
            s.s_prev = false;
        }
        s.fr_prev = rlo;
    }

    /// `CU C n` (SC-EDGE-01, SC-SAT-01): a rising RLO counts up by one, except at 999.
    pub fn count_up(&mut self, rlo: bool) {
        let s = &mut self.state;
        if rlo && !s.cu_prev && s.cv < CV_MAX {
            s.cv += 1;
        }
        s.cu_prev = rlo;
    }

    /// `CD C n` (SC-EDGE-01, SC-SAT-01): a rising RLO counts down by one, except at 0.
    pub fn count_down(&mut self, rlo: bool) {
        let s = &mut self.state;
        if rlo && !s.cd_prev && s.cv > 0 {
            s.cv -= 1;
        }
        s.cd_prev = rlo;
    }

    /// `S C n` with the preset in ACCU 1 (SC-SET-01): a rising RLO sets CV to PV and clears
    /// the edge memories of CU and CD, so that a count input held at 1 counts once at its next
    /// operation (the TIA Portal help on S_CU: "counts once in the next cycle").
    pub fn set(&mut self, rlo: bool, pv: super::CounterPreset) {
        let s = &mut self.state;
        if rlo && !s.s_prev {
            s.cv = pv.value();
            s.cu_prev = false;
            s.cd_prev = false;
        }
        s.s_prev = rlo;
    }

    /// `R C n` (SC-PRIO-01): while the RLO is 1, CV = 0.
    pub fn reset(&mut self, rlo: bool) {
        if rlo {
            self.state.cv = 0;
        }
    }
}

impl S5CounterOps for S5CounterRef {
    /// One box call: the STL sequence `FR`, `CU`, `CD`, `S`, `R`, without the operation of an
    /// input the box lacks (SC-INPUTS-01: S_CU has no `CD`, S_CD no `CU`; their memories are not
    /// touched). Rising CU and CD together both count (SC-SIMUL-01): CV is unchanged between 1
    /// and 998, 999 becomes 998 and 0 stays 0 (the count up saturates first). S after
    /// counting, R last (SC-PRIO-01).
    fn call(&mut self, kind: S5CounterKind, input: S5CounterInput) -> S5CounterOutput {
        self.enable(input.fr);
        if kind.counts_up() {
            self.count_up(input.cu);
        }
        if kind.counts_down() {
            self.count_down(input.cd);
        }
        self.set(input.s, input.pv);
        self.reset(input.r);
        self.state.output()
    }

    fn state(&self) -> S5CounterState {
        self.state
    }
}
