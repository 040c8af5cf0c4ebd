//! The reference semantics of CTU, CTD and CTUD, one function per rule (Strączyński lecture;
//! S7-1200 manual, counter instructions). Rule IDs refer to `spec/requirements/counter.toml`.

use super::{
    outputs, CounterInput, CounterInt, CounterKind, CounterOps, CounterOutput, CounterState,
};
use crate::rule::{out, Explained, Explanation, Recorder, Rule, RuleSet};

/// The outputs of `kind` as explanations mask them: every output (all are read from CV), and
/// the Q outputs (derived from CV and PV by CNT-Q-01). CTU and CTD have Q, CV; CTUD QU, QD, CV.
const fn masks(kind: CounterKind) -> (u8, u8) {
    match kind {
        CounterKind::Ctu | CounterKind::Ctd => (out::O0 | out::O1, out::O0),
        CounterKind::Ctud => (out::O0 | out::O1 | out::O2, out::O0 | out::O1),
    }
}

/// One IEC counter instance (its instance data: CV and the edge memories).
///
/// ```
/// use plc_timers::counter::{CounterInput, CounterKind, CounterOps, CounterRef};
/// let mut ctd = CounterRef::<u8>::new();
/// let out = ctd.call(CounterKind::Ctd, CounterInput { ld: true, pv: 2, ..Default::default() });
/// assert_eq!(out.cv, 2); // LD loads PV
/// let out = ctd.call(CounterKind::Ctd, CounterInput { cd: true, pv: 2, ..Default::default() });
/// assert_eq!((out.cv, out.qd), (1, false));
/// ```
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct CounterRef<T> {
    state: CounterState<T>,
}

impl<T: CounterInt> CounterRef<T> {
    /// A new instance (CV = 0, no edge seen).
    ///
    /// ```
    /// use plc_timers::counter::{CounterOps, CounterRef};
    /// assert_eq!(CounterRef::<i64>::new().state().cv, 0);
    /// ```
    pub const fn new() -> CounterRef<T> {
        CounterRef::from_state(CounterState {
            cv: T::ZERO,
            cu_prev: false,
            cd_prev: false,
        })
    }

    /// The instance in `state` (every counter state is valid).
    ///
    /// ```
    /// use plc_timers::counter::{CounterInput, CounterKind, CounterOps, CounterRef, CounterState};
    /// let mut c = CounterRef::from_state(CounterState { cv: i8::MAX, cu_prev: false, cd_prev: false });
    /// let up = CounterInput { cu: true, pv: 0, ..Default::default() };
    /// assert_eq!(c.call(CounterKind::Ctu, up).cv, i8::MAX); // CNT-SAT-01
    /// ```
    pub const fn from_state(state: CounterState<T>) -> CounterRef<T> {
        CounterRef { state }
    }

    /// CNT-EDGE-01: a count needs a change from 0 to 1; the edge memory takes the input on every
    /// call, also while R or LD holds, so releasing R with CU held does not count.
    fn edges(&mut self, input: &CounterInput<T>, rec: &mut impl Recorder) -> (bool, bool) {
        if input.cu != self.state.cu_prev || input.cd != self.state.cd_prev {
            rec.state(RuleSet::of(Rule::CNT_EDGE_01));
        }
        let up = input.cu && !self.state.cu_prev;
        let down = input.cd && !self.state.cd_prev;
        self.state.cu_prev = input.cu;
        self.state.cd_prev = input.cd;
        (up, down)
    }

    /// CNT-SIMUL-01: rising CU and CD in the same call leave CV unchanged; CNT-SAT-01: counting
    /// stops at the type's limits only (up past PV, down below 0), it never wraps.
    fn count(cv: T, up: bool, down: bool) -> T {
        match (up, down) {
            (true, false) => cv.saturating_inc(),
            (false, true) => cv.saturating_dec(),
            _ => cv,
        }
    }
}

impl<T: CounterInt> CounterRef<T> {
    fn call_rec(
        &mut self,
        kind: CounterKind,
        input: CounterInput<T>,
        rec: &mut impl Recorder,
    ) -> CounterOutput<T> {
        let (all, q) = masks(kind);
        let masked = input.with_signals(kind.mask(input.signals()));
        // An input the instruction lacks was 1 and is taken as 0.
        let lacking = masked.signals() != input.signals();
        let input = masked;
        let (up, down) = self.edges(&input, rec);
        let cv = self.state.cv;
        self.state.cv = if input.r || input.ld {
            rec.write(RuleSet::of(Rule::CNT_PRIO_01), all);
            if input.r {
                T::ZERO
            } else {
                input.pv
            }
        } else {
            let counted = Self::count(cv, up, down);
            if !(up || down) && (input.cu || input.cd) {
                // A count input held at 1 does not count: its edge memory decides CV.
                rec.add(RuleSet::of(Rule::CNT_EDGE_01), all);
            }
            if up || down {
                let edge = RuleSet::of(Rule::CNT_EDGE_01);
                rec.write(
                    if up && down {
                        edge.with(Rule::CNT_SIMUL_01)
                    } else {
                        edge.with_if(counted == cv, Rule::CNT_SAT_01)
                            // Counting down goes on below 0: only the type's MIN stops it.
                            .with_if(down && counted < T::ZERO, Rule::CNT_SAT_01)
                            // Counting up goes on past PV.
                            .with_if(up && cv >= input.pv, Rule::CNT_Q_01)
                    },
                    all,
                );
            }
            counted
        };
        rec.add(RuleSet::EMPTY.with_if(lacking, Rule::CNT_INPUTS_01), all);
        rec.add(RuleSet::of(Rule::CNT_Q_01), q);
        outputs(self.state.cv, input.pv)
    }

    /// [`CounterOps::call`], explained: the same outputs and state, with the rules that
    /// decided each output (catalog order: Q, CV for CTU and CTD; QU, QD, CV for CTUD) and
    /// acted on the state ([`Explained`]).
    ///
    /// ```
    /// use plc_timers::counter::{CounterInput, CounterKind, CounterRef};
    /// use plc_timers::rule::Rule;
    /// let mut ctud = CounterRef::<i16>::new();
    /// let e = ctud.call_explained(CounterKind::Ctud, CounterInput { cu: true, r: true, ..Default::default() });
    /// assert_eq!(e.outputs[2].iter().collect::<Vec<_>>(), [Rule::CNT_PRIO_01]); // CV: R
    /// assert!(e.state.contains(Rule::CNT_EDGE_01)); // the CU memory took the input
    /// let e = ctud.call_explained(CounterKind::Ctud, CounterInput { cu: true, ..Default::default() });
    /// assert_eq!(e.output.cv, 0); // releasing R with CU held does not count:
    /// assert_eq!(e.outputs[2].iter().collect::<Vec<_>>(), [Rule::CNT_EDGE_01]); // the memory decided
    /// assert!(!e.wrote(2)); // CV carried from the row under R
    /// ```
    pub fn call_explained(
        &mut self,
        kind: CounterKind,
        input: CounterInput<T>,
    ) -> Explained<CounterOutput<T>> {
        let mut rec = Explanation::default();
        let o = self.call_rec(kind, input, &mut rec);
        rec.finish(o)
    }
}

impl<T: CounterInt> CounterOps<T> for CounterRef<T> {
    /// One call with the inputs this kind has (CNT-INPUTS-01). CNT-PRIO-01: R before LD before
    /// counting; R and LD are levels.
    fn call(&mut self, kind: CounterKind, input: CounterInput<T>) -> CounterOutput<T> {
        self.call_rec(kind, input, &mut ())
    }

    fn state(&self) -> CounterState<T> {
        self.state
    }
}
