//! The reference semantics of the S5 counters, one function per rule. The box executes as the
//! STL sequence it compiles to: `FR`, `CU`, `CD`, `S`, `R` (SC-STL-01).

use super::{S5CounterInput, S5CounterKind, S5CounterOps, S5CounterOutput, S5CounterState, CV_MAX};
use crate::rule::{out, Explained, Explanation, Recorder, Rule, RuleSet};

/// Every output (Q, CV, CV_BCD): all are read from CV.
const ALL: u8 = out::O0 | out::O1 | out::O2;
/// Q, derived from CV by SC-Q-01.
const Q: u8 = out::O0;

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
        self.enable_rec(rlo, &mut ());
    }

    pub(crate) fn enable_rec(&mut self, rlo: bool, rec: &mut impl Recorder) {
        if rlo != self.state.fr_prev {
            rec.state(RuleSet::of(Rule::SC_FR_01));
        }
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
        self.count_up_rec(rlo, &mut ());
    }

    pub(crate) fn count_up_rec(&mut self, rlo: bool, rec: &mut impl Recorder) {
        let s = &mut self.state;
        let edge = RuleSet::of(Rule::SC_EDGE_01);
        if rlo != s.cu_prev {
            rec.state(edge);
        }
        if rlo && !s.cu_prev {
            rec.write(edge.with_if(s.cv == CV_MAX, Rule::SC_SAT_01), ALL);
            if s.cv < CV_MAX {
                s.cv += 1;
            }
        }
        s.cu_prev = rlo;
    }

    /// `CD C n` (SC-EDGE-01, SC-SAT-01): a rising RLO counts down by one, except at 0.
    pub fn count_down(&mut self, rlo: bool) {
        self.count_down_rec(rlo, &mut ());
    }

    pub(crate) fn count_down_rec(&mut self, rlo: bool, rec: &mut impl Recorder) {
        let s = &mut self.state;
        let edge = RuleSet::of(Rule::SC_EDGE_01);
        if rlo != s.cd_prev {
            rec.state(edge);
        }
        if rlo && !s.cd_prev {
            rec.write(edge.with_if(s.cv == 0, Rule::SC_SAT_01), ALL);
            if s.cv > 0 {
                s.cv -= 1;
            }
        }
        s.cd_prev = rlo;
    }

    /// `S C n` with the preset in ACCU 1 (SC-SET-01): a rising RLO sets CV to PV and clears
    /// the edge memories of CU and CD, so that a count input held at 1 counts once at its next
    /// operation (the TIA Portal help on S_CU: "counts once in the next cycle").
    pub fn set(&mut self, rlo: bool, pv: super::CounterPreset) {
        self.set_rec(rlo, pv, &mut ());
    }

    pub(crate) fn set_rec(&mut self, rlo: bool, pv: super::CounterPreset, rec: &mut impl Recorder) {
        let s = &mut self.state;
        if rlo != s.s_prev {
            rec.state(RuleSet::of(Rule::SC_EDGE_01));
        }
        if rlo && !s.s_prev {
            rec.write(RuleSet::of(Rule::SC_SET_01).with(Rule::SC_EDGE_01), ALL);
            s.cv = pv.value();
            s.cu_prev = false;
            s.cd_prev = false;
        }
        s.s_prev = rlo;
    }

    /// `R C n` (SC-PRIO-01): while the RLO is 1, CV = 0.
    pub fn reset(&mut self, rlo: bool) {
        self.reset_rec(rlo, &mut ());
    }

    pub(crate) fn reset_rec(&mut self, rlo: bool, rec: &mut impl Recorder) {
        if rlo {
            rec.write(RuleSet::of(Rule::SC_PRIO_01), ALL);
            self.state.cv = 0;
        }
    }

    /// The box call, recorded ([`S5CounterOps::call`]).
    pub(crate) fn call_rec(
        &mut self,
        kind: S5CounterKind,
        input: S5CounterInput,
        rec: &mut impl Recorder,
    ) -> S5CounterOutput {
        self.enable_rec(input.fr, rec);
        let s = &self.state;
        let up = kind.counts_up() && input.cu && !s.cu_prev;
        let down = kind.counts_down() && input.cd && !s.cd_prev;
        let set = input.s && !s.s_prev;
        // The box lacks an input that is 1: its operation does not run.
        let lacking = (!kind.counts_up() && input.cu) || (!kind.counts_down() && input.cd);
        if kind.counts_up() {
            self.count_up_rec(input.cu, rec);
        }
        if kind.counts_down() {
            self.count_down_rec(input.cd, rec);
        }
        if up && down {
            rec.add(RuleSet::of(Rule::SC_SIMUL_01), ALL);
        }
        self.set_rec(input.s, input.pv, rec);
        if set && (up || down) {
            // The set comes after counting in the STL sequence: it overrides the count.
            rec.add(RuleSet::of(Rule::SC_PRIO_01), ALL);
        }
        self.reset_rec(input.r, rec);
        // (Under R, R alone decides: the missing operation would have changed nothing.)
        rec.add(
            RuleSet::EMPTY.with_if(lacking && !input.r, Rule::SC_INPUTS_01),
            ALL,
        );
        rec.add(RuleSet::of(Rule::SC_Q_01), Q);
        self.state.output()
    }

    /// [`S5CounterOps::call`], explained: the same outputs and state, with the rules that
    /// decided Q, CV and CV_BCD and acted on the state ([`Explained`]).
    ///
    /// ```
    /// use plc_timers::counter::s5::{CounterPreset, S5CounterInput, S5CounterKind, S5CounterRef};
    /// use plc_timers::rule::Rule;
    /// let mut c = S5CounterRef::new();
    /// let pv = CounterPreset::new(5).expect("0..=999");
    /// let e = c.call_explained(S5CounterKind::SCu, S5CounterInput { cu: true, s: true, pv, ..Default::default() });
    /// assert_eq!(e.output.cv, 5); // the set overrides the count
    /// assert!(e.outputs[1].contains(Rule::SC_SET_01) && e.outputs[1].contains(Rule::SC_PRIO_01));
    /// ```
    pub fn call_explained(
        &mut self,
        kind: S5CounterKind,
        input: S5CounterInput,
    ) -> Explained<S5CounterOutput> {
        let mut rec = Explanation::default();
        let o = self.call_rec(kind, input, &mut rec);
        rec.finish(o)
    }
}

impl S5CounterOps for S5CounterRef {
    /// One box call: the STL sequence `FR`, `CU`, `CD`, `S`, `R`, without the operation of an
    /// input the box lacks (SC-INPUTS-01: S_CU has no `CD`, S_CD no `CU`; their memories are not
    /// touched). Rising CU and CD together both count (SC-SIMUL-01): CV is unchanged between 1
    /// and 998, 999 becomes 998 and 0 stays 0 (the count up saturates first). S after
    /// counting, R last (SC-PRIO-01).
    fn call(&mut self, kind: S5CounterKind, input: S5CounterInput) -> S5CounterOutput {
        self.call_rec(kind, input, &mut ())
    }

    fn state(&self) -> S5CounterState {
        self.state
    }
}

impl S5CounterRef {
    /// SC-RETAIN-01: a RUN-STOP-RUN. A counter has no time, so the STOP's length does not
    /// matter: at the restart a retentive counter keeps its state (CV and edge memories) and a
    /// non-retentive one is [`S5CounterState::RESET`] (a decision, as IEC-RETAIN-01 is for the
    /// IEC timers).
    ///
    /// ```
    /// use plc_timers::counter::s5::{S5CounterInput, S5CounterKind, S5CounterOps, S5CounterRef};
    /// let mut c = S5CounterRef::new();
    /// c.call(S5CounterKind::SCu, S5CounterInput { cu: true, ..Default::default() });
    /// c.run_stop_run(true);
    /// assert_eq!(c.state().cv, 1);
    /// c.run_stop_run(false);
    /// assert_eq!(c.state().cv, 0);
    /// ```
    pub fn run_stop_run(&mut self, retentive: bool) {
        if !retentive {
            self.state = S5CounterState::RESET;
        }
    }
}
