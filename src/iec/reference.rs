//! The reference semantics of the IEC timers, one function per rule of the manual.
//!
//! Sources: S7-1200 manual, timer instructions (Tables 8-19 to 8-22 and the "Timer operation" /
//! "Timer programming" notes); Strączyński lecture (same table). Rule IDs refer to
//! `spec/requirements/iec.toml`.

use super::{IecInput, IecKind, IecOutput, IecState, IecTimerOps};
use crate::rule::{out, Explained, Explanation, Recorder, Rule, RuleSet};
use crate::time::clock::ClockWord;
use core::marker::PhantomData;

use crate::time::{CpuTime, IecDuration, LTime, Time};

/// The reference model of one `IEC_TIMER` structure on a clock word `C` (`u32` on the CPU).
///
/// ```
/// use plc_timers::iec::{IecInput, IecKind, IecTimerOps, IecTimerRef};
/// use plc_timers::time::CpuTime;
///
/// let pt = plc_timers::time!("T#100MS");
/// let mut tp = IecTimerRef::new();
/// let at = CpuTime::from_millis;
/// assert!(tp.call(IecKind::Tp, at(0), IecInput::new(true, pt)).q); // the pulse starts
/// assert!(tp.call(IecKind::Tp, at(50), IecInput::new(false, pt)).q); // IN has no effect
/// assert!(!tp.call(IecKind::Tp, at(100), IecInput::new(false, pt)).q); // ET = PT: over
/// ```
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct IecTimerRef<C = u32, D = Time> {
    /// The structure's members, named as in the manual.
    state: IecState<C>,
    /// The data type of PT and ET (`TIME` or `LTIME`): their unit, in the type only.
    unit: PhantomData<D>,
}

/// `PT` as the instruction uses it: negative taken as 0 (IEC-PT-NEG-01), in clock units.
fn preset<C: ClockWord, D: IecDuration>(pt: D) -> C {
    C::from_preset(pt.units())
}

/// The outputs Q and ET, as explanations mask them.
const Q: u8 = out::O0;
const ET: u8 = out::O1;

/// The rule of each kind's reaction to IN (Table 8-20); TONR's start is its resume rule.
pub const fn kind_rule(kind: IecKind) -> Rule {
    match kind {
        IecKind::Tp => Rule::TP_IN_01,
        IecKind::Ton => Rule::TON_IN_01,
        IecKind::Tof => Rule::TOF_IN_01,
        IecKind::Tonr => Rule::TONR_RESUME_01,
    }
}

/// Q while the timer is timing: TP's pulse and TOF's delayed Q are 1; TON and TONR wait.
fn q_while_running(kind: IecKind) -> bool {
    matches!(kind, IecKind::Tp | IecKind::Tof)
}

/// Q once ET has reached PT: TON and TONR switch on, TP's pulse and TOF's delay end.
fn q_after_expiry(kind: IecKind) -> bool {
    matches!(kind, IecKind::Ton | IecKind::Tonr)
}

impl IecTimerRef {
    /// The initial structure on the S7-1200's 32-bit millisecond clock: everything 0 (a new
    /// or non-retentive instance DB). On another clock word `C`,
    /// `IecTimerRef::<C>::default()` is the same structure.
    ///
    /// ```
    /// use plc_timers::iec::{IecTimerOps, IecTimerRef};
    /// assert_eq!(IecTimerRef::new().state(), Default::default());
    /// ```
    pub const fn new() -> IecTimerRef {
        IecTimerRef {
            state: IecState {
                kind: None,
                input: false,
                running: false,
                start: 0,
                pt: 0,
                et: 0,
                q: false,
            },
            unit: PhantomData,
        }
    }
}

/// The reference model of one `IEC_LTIMER` (S7-1500): `PT` and `ET` of data type `LTIME` on
/// the 64-bit nanosecond clock. `IecLTimerRef::default()` is the initial structure.
///
/// ```
/// use plc_timers::iec::{IecInput, IecKind, IecLTimerRef, IecTimerOps};
/// use plc_timers::time::CpuTime;
/// let pt = plc_timers::ltime!("LT#100NS");
/// let mut tp = IecLTimerRef::default();
/// assert!(tp.call(IecKind::Tp, CpuTime::from_nanos(0), IecInput::new(true, pt)).q);
/// assert!(!tp.call(IecKind::Tp, CpuTime::from_nanos(100), IecInput::new(false, pt)).q);
/// ```
pub type IecLTimerRef = IecTimerRef<u64, LTime>;

impl<C: ClockWord, D: IecDuration> IecTimerRef<C, D> {
    /// The timer in `state`, or `None` when the state is not valid ([`IecState::is_valid`]).
    ///
    /// ```
    /// use plc_timers::iec::{IecState, IecTimerRef};
    /// let running = IecState::<u32> { running: true, start: 5, pt: 10, ..Default::default() };
    /// assert!(IecTimerRef::<u32>::from_state(running).is_some());
    /// assert!(IecTimerRef::<u32>::from_state(IecState { et: 11, ..running }).is_none()); // ET > PT
    /// ```
    pub fn from_state(state: IecState<C>) -> Option<IecTimerRef<C, D>> {
        state.is_valid().then_some(IecTimerRef {
            state,
            unit: PhantomData,
        })
    }

    /// IEC-START-01: on the starting edge the CPU clock is copied into START and the preset is
    /// latched; it stays in force while the timer runs (IEC-PT-LATCH-01).
    ///
    /// `also`: further rules that made this start (TP-RETRIGGER-01).
    fn start(
        &mut self,
        now: CpuTime<D::Unit>,
        pt: D,
        kind: IecKind,
        also: RuleSet,
        rec: &mut impl Recorder,
    ) {
        rec.write(
            also.with(kind_rule(kind))
                .with(Rule::IEC_START_01)
                .with(Rule::IEC_PT_LATCH_01)
                .with(Rule::IEC_EDGE_01),
            Q | ET,
        );
        let s = &mut self.state;
        s.running = true;
        s.start = now.clock();
        s.pt = preset(pt);
        s.et = C::default();
        s.q = q_while_running(kind);
    }

    /// IEC-UPDATE-01: an update subtracts START from the CPU clock (modulo 2^BITS, IEC-WRAP-01),
    /// compares with PT and sets ELAPSED and Q; ELAPSED stops at PT (IEC-EXPIRY-01: expiry at
    /// ET >= PT).
    ///
    /// `box_pt`: the preset at the box in a box call (`None` for a read through the structure):
    /// when it differs from the latched one, the latch decided (IEC-PT-LATCH-01).
    ///
    /// IEC-WRAP-01 decides when the subtraction wraps, and whenever the CPU time has passed
    /// 2^BITS ms: from then on the clock word is the time modulo 2^BITS, so the gap since START
    /// is known only modulo 2^BITS (a gap of 2^BITS ms or more aliases).
    fn update(
        &mut self,
        now: CpuTime<D::Unit>,
        kind: IecKind,
        box_pt: Option<D>,
        rec: &mut impl Recorder,
    ) {
        let s = &mut self.state;
        if !s.running {
            return;
        }
        let t = now.ticks();
        let now = now.clock::<C>();
        let elapsed = now.elapsed_since(s.start);
        let rules = RuleSet::EMPTY
            .with_if(now < s.start || now.to_u64() != t, Rule::IEC_WRAP_01)
            .with_if(
                box_pt.is_some_and(|pt| preset::<C, D>(pt) != s.pt),
                Rule::IEC_PT_LATCH_01,
            );
        if elapsed >= s.pt {
            rec.write(
                rules
                    .with(Rule::IEC_EXPIRY_01)
                    .with_if(s.pt == C::ZERO, Rule::IEC_PT0_01),
                Q | ET,
            );
            s.et = s.pt;
            s.q = q_after_expiry(kind);
            s.running = false;
            s.start = C::default();
        } else {
            // ET follows the clock (IEC-START-01: each update computes now - START); Q stays
            // the running one because ET < PT (IEC-EXPIRY-01).
            rec.update(rules.with(Rule::IEC_START_01), ET);
            let q = q_while_running(kind);
            if s.q == q {
                rec.add(rules.with(Rule::IEC_EXPIRY_01), Q);
            } else {
                // Q of another instruction that ran on the structure before: replaced.
                rec.update(rules.with(Rule::IEC_EXPIRY_01), Q);
            }
            s.et = elapsed;
            s.q = q;
        }
    }

    /// IEC-ACCESS-01: an instruction reads a member of the structure: the update of the
    /// instruction that last ran on it happens first (none before the first call).
    fn access(&mut self, now: CpuTime<D::Unit>) -> &IecState<C> {
        if let Some(kind) = self.state.kind {
            self.update(now, kind, None, &mut ());
        }
        &self.state
    }

    /// Stops timing and clears ELAPSED and Q: TON on IN = 0, TOF on IN = 1 (Table 8-20), TONR on R.
    fn reset_and_stop(&mut self) {
        let s = &mut self.state;
        s.running = false;
        s.start = C::default();
        s.et = C::default();
        s.q = false;
    }

    /// TP (Table 8-20: "changing PT or IN while running has no effect"): a rising IN starts a
    /// pulse of PT when no pulse runs; after the pulse ET stays at PT while IN = 1 and returns
    /// to 0 when IN = 0 (TP-ET-01).
    fn tp(&mut self, now: CpuTime<D::Unit>, input: IecInput<D>, rec: &mut impl Recorder) {
        let pt = Some(input.pt);
        let was_running = self.state.running;
        self.update(now, IecKind::Tp, pt, rec);
        let rising = input.input && !self.state.input;
        if rising && !self.state.running {
            // TP-RETRIGGER-01: the pulse ended in this very call's update.
            let retrigger = RuleSet::EMPTY.with_if(was_running, Rule::TP_RETRIGGER_01);
            self.start(now, input.pt, IecKind::Tp, retrigger, rec);
            self.update(now, IecKind::Tp, pt, rec);
        }
        if !self.state.running && !input.input {
            if self.state.et != C::ZERO {
                rec.write(RuleSet::of(Rule::TP_IN_01), ET);
            }
            self.state.et = C::default();
        }
    }

    /// TON: a rising IN starts timing; Q = 1 once ET reaches PT while IN stays 1; IN = 0 resets
    /// and stops (Table 8-20).
    fn ton(&mut self, now: CpuTime<D::Unit>, input: IecInput<D>, rec: &mut impl Recorder) {
        let pt = Some(input.pt);
        if !input.input {
            rec.write(RuleSet::of(Rule::TON_IN_01), Q | ET);
            self.reset_and_stop();
        } else if !self.state.input {
            self.start(now, input.pt, IecKind::Ton, RuleSet::EMPTY, rec);
            self.update(now, IecKind::Ton, pt, rec);
        } else {
            self.update(now, IecKind::Ton, pt, rec);
        }
    }

    /// TOF: Q = 1 while IN = 1; a falling IN starts timing, Q falls when ET reaches PT; IN = 1
    /// resets and stops (Table 8-20).
    fn tof(&mut self, now: CpuTime<D::Unit>, input: IecInput<D>, rec: &mut impl Recorder) {
        let pt = Some(input.pt);
        if input.input {
            rec.write(RuleSet::of(Rule::TOF_IN_01), Q | ET);
            self.reset_and_stop();
            self.state.q = true;
        } else if self.state.input {
            self.start(now, input.pt, IecKind::Tof, RuleSet::EMPTY, rec);
            self.update(now, IecKind::Tof, pt, rec);
        } else {
            self.update(now, IecKind::Tof, pt, rec);
        }
    }

    /// TONR: R resets ET and Q (TONR-R-01, before anything else); while IN = 1 the timer
    /// accumulates, resuming from the accumulated ET with the PT of the moment it resumes
    /// (TONR-RESUME-01); IN = 0 stops without reset (Table 8-20); Q stays 1 after expiry until R.
    fn tonr(&mut self, now: CpuTime<D::Unit>, input: IecInput<D>, rec: &mut impl Recorder) {
        let pt = Some(input.pt);
        if input.reset {
            rec.write(RuleSet::of(Rule::TONR_R_01), Q | ET);
            self.reset_and_stop();
            return;
        }
        let expired = self.state.q;
        if input.input {
            if !self.state.running && !expired {
                // Resume: START shifted back by the accumulated time, so that an update's
                // `now - START` is the accumulated total.
                let accumulated = self.state.et;
                self.start(now, input.pt, IecKind::Tonr, RuleSet::EMPTY, rec);
                self.state.start = now.clock::<C>().elapsed_since(accumulated);
            }
            self.update(now, IecKind::Tonr, pt, rec);
        } else if self.state.running {
            self.update(now, IecKind::Tonr, pt, rec);
            if self.state.running {
                rec.state(RuleSet::of(Rule::TONR_IN_01));
                self.state.running = false;
                self.state.start = C::default();
            }
        }
    }

    fn call_rec(
        &mut self,
        kind: IecKind,
        now: CpuTime<D::Unit>,
        input: IecInput<D>,
        rec: &mut impl Recorder,
    ) -> IecOutput<C> {
        match kind {
            IecKind::Tp => self.tp(now, input, rec),
            IecKind::Ton => self.ton(now, input, rec),
            IecKind::Tof => self.tof(now, input, rec),
            IecKind::Tonr => self.tonr(now, input, rec),
        }
        if self.state.input != input.input {
            rec.state(RuleSet::of(Rule::IEC_EDGE_01));
        }
        if self.state.kind != Some(kind) {
            rec.state(RuleSet::of(Rule::IEC_ACCESS_01));
        }
        // PT <= 0 at the box is a preset like any other, not a reset: the outputs are what the
        // other rules give with PT = 0 (or with the latched PT of a running timer).
        rec.add(
            RuleSet::EMPTY.with_if(input.pt.units() == 0, Rule::IEC_PT0_01),
            Q | ET,
        );
        self.state.kind = Some(kind);
        self.state.input = input.input;
        IecOutput {
            q: self.state.q,
            et: self.state.et,
        }
    }

    /// [`IecTimerOps::call`], explained: the same outputs and state, with the rules that
    /// decided Q and ET and acted on the state ([`Explained`]).
    ///
    /// ```
    /// use plc_timers::iec::{IecInput, IecKind, IecTimerRef};
    /// use plc_timers::rule::Rule;
    /// use plc_timers::time::CpuTime;
    ///
    /// let mut ton = IecTimerRef::<u32>::new();
    /// let e = ton.call_explained(IecKind::Ton, CpuTime::ZERO, IecInput::new(true, plc_timers::time!("T#0MS")));
    /// assert!(e.output.q); // PT = 0: on in the starting call
    /// assert!(e.outputs[0].contains(Rule::IEC_PT0_01) && e.outputs[0].contains(Rule::IEC_EXPIRY_01));
    /// ```
    pub fn call_explained(
        &mut self,
        kind: IecKind,
        now: CpuTime<D::Unit>,
        input: IecInput<D>,
    ) -> Explained<IecOutput<C>> {
        let mut rec = Explanation::default();
        let o = self.call_rec(kind, now, input, &mut rec);
        rec.finish(o)
    }

    /// The outputs Q and ET as the structure holds them now.
    fn held(&self) -> IecOutput<C> {
        IecOutput {
            q: self.state.q,
            et: self.state.et,
        }
    }

    /// [`IecTimerOps::reset_timer`] (the `-(RT)-` coil), explained as a call is: the same
    /// action, with [`Rule::IEC_RT_01`] deciding the Q and ET the structure holds after it (0:
    /// the coil wrote them) and acting on the state. [`Explained::then`] joins it with the box
    /// call that follows in the same scan.
    ///
    /// ```
    /// use plc_timers::iec::{IecInput, IecKind, IecTimerOps, IecTimerRef};
    /// use plc_timers::rule::{Rule, RuleSet};
    /// use plc_timers::time::CpuTime;
    ///
    /// let pt = plc_timers::time!("T#100MS");
    /// let mut ton = IecTimerRef::<u32>::new();
    /// ton.call(IecKind::Ton, CpuTime::ZERO, IecInput::new(true, pt));
    /// let e = ton.reset_timer_explained();
    /// assert_eq!((e.state, e.outputs[1], e.written), (RuleSet::of(Rule::IEC_RT_01), RuleSet::of(Rule::IEC_RT_01), 0b11));
    /// let state = ton.state();
    /// assert!(!state.running && !state.input && state.et == 0 && state.pt == 100);
    /// ```
    pub fn reset_timer_explained(&mut self) -> Explained<IecOutput<C>> {
        let mut rec = Explanation::default();
        rec.write(RuleSet::of(Rule::IEC_RT_01), Q | ET);
        self.reset_timer();
        rec.finish(self.held())
    }

    /// The `-(RT)-` coil followed by the box call in the same scan, explained as one
    /// ([`Explained::then`]). IEC-RT-01 cleared the stored IN, so an IN still 1 is a rising
    /// edge: a start in the call is the coil's too, and IEC-RT-01 decides the outputs it wrote.
    ///
    /// ```
    /// use plc_timers::iec::{IecInput, IecKind, IecTimerRef};
    /// use plc_timers::rule::Rule;
    /// use plc_timers::time::CpuTime;
    ///
    /// let on = IecInput::new(true, plc_timers::time!("T#100MS"));
    /// let mut ton = IecTimerRef::<u32>::new();
    /// ton.call_explained(IecKind::Ton, CpuTime::ZERO, on);
    /// let e = ton.reset_timer_then_call_explained(IecKind::Ton, CpuTime::from_millis(50), on);
    /// assert_eq!(e.output.et, 0); // started again
    /// assert!(e.outputs[1].contains(Rule::IEC_RT_01) && e.outputs[1].contains(Rule::IEC_START_01));
    /// ```
    pub fn reset_timer_then_call_explained(
        &mut self,
        kind: IecKind,
        now: CpuTime<D::Unit>,
        input: IecInput<D>,
    ) -> Explained<IecOutput<C>> {
        let held = self.state.input;
        let coil = self.reset_timer_explained();
        let mut e = coil.then(self.call_explained(kind, now, input));
        for (i, o) in e.outputs.iter_mut().enumerate().take(2) {
            if held && e.written & (1 << i) != 0 && o.contains(Rule::IEC_EDGE_01) {
                o.insert(Rule::IEC_RT_01);
            }
        }
        e
    }

    /// [`IecTimerOps::preset_timer`] (the `-(PT)-` coil), explained: [`Rule::IEC_PT_COIL_01`]
    /// acts on the state when the preset member changes, and decides ET when the coil clamps it.
    ///
    /// ```
    /// use plc_timers::iec::{IecInput, IecKind, IecTimerOps, IecTimerRef};
    /// use plc_timers::rule::Rule;
    /// use plc_timers::time::CpuTime;
    ///
    /// let mut ton = IecTimerRef::<u32>::new();
    /// ton.call(IecKind::Ton, CpuTime::ZERO, IecInput::new(true, plc_timers::time!("T#100MS")));
    /// ton.call(IecKind::Ton, CpuTime::from_millis(60), IecInput::new(true, plc_timers::time!("T#100MS")));
    /// let e = ton.preset_timer_explained(plc_timers::time!("T#50MS"));
    /// assert_eq!(e.output.et, 50); // clamped to the new preset
    /// assert!(e.state.contains(Rule::IEC_PT_COIL_01) && e.outputs[1].contains(Rule::IEC_PT_COIL_01));
    /// ```
    pub fn preset_timer_explained(&mut self, pt: D) -> Explained<IecOutput<C>> {
        let mut rec = Explanation::default();
        let before = self.state;
        self.preset_timer(pt);
        let coil = RuleSet::of(Rule::IEC_PT_COIL_01);
        if self.state.et != before.et {
            rec.write(coil, ET);
        } else if self.state.pt != before.pt {
            rec.state(coil);
        }
        rec.finish(self.held())
    }

    /// [`IecTimerOps::read_q`] and [`IecTimerOps::read_et`] (a read of the structure's Q or
    /// ELAPSED member), explained: [`Rule::IEC_ACCESS_01`] decides both (the read updates the
    /// timer first), with the rules of that update.
    ///
    /// ```
    /// use plc_timers::iec::{IecInput, IecKind, IecTimerOps, IecTimerRef};
    /// use plc_timers::rule::Rule;
    /// use plc_timers::time::CpuTime;
    ///
    /// let pt = plc_timers::time!("T#100MS");
    /// let mut ton = IecTimerRef::<u32>::new();
    /// ton.call(IecKind::Ton, CpuTime::ZERO, IecInput::new(true, pt));
    /// let e = ton.read_explained(CpuTime::from_millis(100));
    /// assert!(e.output.q); // expired in the read's update
    /// assert!(e.outputs[0].contains(Rule::IEC_ACCESS_01) && e.outputs[0].contains(Rule::IEC_EXPIRY_01));
    /// ```
    pub fn read_explained(&mut self, now: CpuTime<D::Unit>) -> Explained<IecOutput<C>> {
        let mut rec = Explanation::default();
        if let Some(kind) = self.state.kind {
            self.update(now, kind, None, &mut rec);
        }
        rec.add(RuleSet::of(Rule::IEC_ACCESS_01), Q | ET);
        rec.finish(self.held())
    }

    /// [`IecTimerOps::run_stop_run`], explained: [`Rule::IEC_RETAIN_01`] decides Q and ET
    /// (returned to their initial values, or kept by a retentive structure).
    ///
    /// ```
    /// use plc_timers::iec::{IecInput, IecKind, IecTimerOps, IecTimerRef};
    /// use plc_timers::rule::Rule;
    /// use plc_timers::time::CpuTime;
    ///
    /// let mut ton = IecTimerRef::<u32>::new();
    /// ton.call(IecKind::Ton, CpuTime::ZERO, IecInput::new(true, plc_timers::time!("T#0MS")));
    /// let e = ton.run_stop_run_explained(false);
    /// assert!(!e.output.q && e.outputs[0].contains(Rule::IEC_RETAIN_01) && e.wrote(0));
    /// ```
    pub fn run_stop_run_explained(&mut self, retentive: bool) -> Explained<IecOutput<C>> {
        let mut rec = Explanation::default();
        let retain = RuleSet::of(Rule::IEC_RETAIN_01);
        if retentive {
            rec.add(retain, Q | ET);
        } else {
            rec.write(retain, Q | ET);
        }
        self.run_stop_run(retentive);
        rec.finish(self.held())
    }
}

impl<C: ClockWord, D: IecDuration> IecTimerOps<C, D> for IecTimerRef<C, D> {
    fn call(&mut self, kind: IecKind, now: CpuTime<D::Unit>, input: IecInput<D>) -> IecOutput<C> {
        self.call_rec(kind, now, input, &mut ())
    }

    /// IEC-ACCESS-01: reading Q through the structure updates the timer first.
    fn read_q(&mut self, now: CpuTime<D::Unit>) -> bool {
        self.access(now).q
    }

    /// IEC-ACCESS-01: reading ELAPSED through the structure updates the timer first.
    fn read_et(&mut self, now: CpuTime<D::Unit>) -> C {
        self.access(now).et
    }

    /// IEC-RT-01: the timer data is zeroed (Strączyński lecture: "wyzerowanie danych timera";
    /// S7-1200 manual: ELAPSED reset to 0): ET, Q, the running status and the stored IN; the
    /// preset stays.
    fn reset_timer(&mut self) {
        self.reset_and_stop();
        self.state.input = false;
    }

    /// IEC-PT-COIL-01: the preset member is loaded; a running timer uses it from its next update.
    /// ET is clamped to it so that ET <= PT holds.
    fn preset_timer(&mut self, pt: D) {
        self.state.pt = preset(pt);
        self.state.et = self.state.et.min(self.state.pt);
    }

    /// IEC-RETAIN-01: timer data is lost on RUN-STOP-RUN unless the structure is retentive.
    fn run_stop_run(&mut self, retentive: bool) {
        if !retentive {
            *self = IecTimerRef::default();
        }
    }

    fn state(&self) -> IecState<C> {
        self.state
    }
}
