//! The reference semantics of CTU, CTD and CTUD, one function per rule (Strączyński lecture;
//! S7-1200 manual, counter instructions). Rule IDs refer to `spec/requirements/counter.toml`.

use super::{
    outputs, CounterInput, CounterInt, CounterKind, CounterOps, CounterOutput, CounterState,
};

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
    fn edges(&mut self, input: &CounterInput<T>) -> (bool, bool) {
        let up = input.cu && !self.state.cu_prev;
        let down = input.cd && !self.state.cd_prev;
        self.state.cu_prev = input.cu;
        self.state.cd_prev = input.cd;
        (up, down)
    }

    /// CNT-SIMUL-01: rising CU and CD in the same call leave CV unchanged; CNT-SAT-01: counting
    /// stops at the type's limits, it never wraps.
    fn count(cv: T, up: bool, down: bool) -> T {
        match (up, down) {
            (true, false) => cv.saturating_inc(),
            (false, true) => cv.saturating_dec(),
            _ => cv,
        }
    }
}

impl<T: CounterInt> CounterOps<T> for CounterRef<T> {
    /// One call with the inputs this kind has (CNT-INPUTS-01). CNT-PRIO-01: R before LD before
    /// counting; R and LD are levels.
    fn call(&mut self, kind: CounterKind, input: CounterInput<T>) -> CounterOutput<T> {
        let input = input.with_signals(kind.mask(input.signals()));
        let (up, down) = self.edges(&input);
        self.state.cv = if input.r {
            T::ZERO
        } else if input.ld {
            input.pv
        } else {
            Self::count(self.state.cv, up, down)
        };
        outputs(self.state.cv, input.pv)
    }

    fn state(&self) -> CounterState<T> {
        self.state
    }
}
