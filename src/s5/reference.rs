//! The reference semantics of the S5 timers, one function per rule.
//!
//! Sources: LAD manual §9.1 (timer word, OS update), §9.3-9.7 (the five kinds); STL manual
//! (`FR`, `R T n`); Berger §7 (OS update asynchronous to the scan, value 0, `R T n`). Rule IDs
//! refer to `spec/requirements/s5.toml`; `spec/s5.md` gives the reasons for the modelling
//! decisions.

use super::{ticks_between, S5Input, S5Kind, S5Output, S5State, S5TimerOps};
use crate::rule::{out, Explained, Explanation, Recorder, Rule, RuleSet};
use crate::time::CpuTime;

/// The outputs Q (status) and BI, BCD (the value with its base), as explanations mask them.
const Q: u8 = out::O0;
const VALUE: u8 = out::O1 | out::O2;

/// The rule of each kind's start logic and status (LAD manual §9.3-9.7).
pub const fn kind_rule(kind: S5Kind) -> Rule {
    match kind {
        S5Kind::SPulse => Rule::SP_Q_01,
        S5Kind::SPext => Rule::SE_RUN_ON_01,
        S5Kind::SOdt => Rule::SD_Q_01,
        S5Kind::SOdts => Rule::SS_Q_01,
        S5Kind::SOffdt => Rule::SF_Q_01,
    }
}

/// One S5 timer, executed as the LAD box (or its STL sequence `FR`, `SP/SE/SD/SS/SF`, `R`) at
/// successive CPU times.
///
/// ```
/// use plc_timers::s5::{S5Input, S5Kind, S5TimerOps, S5TimerRef};
/// use plc_timers::time::CpuTime;
///
/// let tv = plc_timers::s5time!("S5T#30MS");
/// let mut sp = S5TimerRef::new();
/// let at = CpuTime::from_millis;
/// assert!(sp.call(S5Kind::SPulse, at(0), S5Input::new(true, false, tv)).q); // pulse starts
/// assert!(!sp.call(S5Kind::SPulse, at(30), S5Input::new(true, false, tv)).q); // 3 ticks: over
/// ```
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct S5TimerRef {
    state: S5State,
    /// The latest CPU time an execution saw (a step back leaves it, S5TMR-CLOCK-01): ticks
    /// after it and up to the next execution are applied before that execution.
    last_call: CpuTime,
}

impl Default for S5TimerRef {
    fn default() -> Self {
        S5TimerRef::new()
    }
}

/// Whether `kind` is an on-delay (S_ODT, S_ODTS): its status switches to 1 when the time runs
/// out (LAD manual §9.5, §9.6); the pulses and the off-delay have Q = 1 while the time runs and
/// switch to 0 when it runs out (§9.3, §9.4: "while the timer runs, a scan of Q for 1 gives 1";
/// §9.7: Q = 1 while the timer runs).
///
/// ```
/// use plc_timers::s5::{reference::is_on_delay, S5Kind};
/// assert!(is_on_delay(S5Kind::SOdts) && !is_on_delay(S5Kind::SOffdt));
/// ```
pub const fn is_on_delay(kind: S5Kind) -> bool {
    matches!(kind, S5Kind::SOdt | S5Kind::SOdts)
}

impl S5TimerRef {
    /// A cleared timer whose previous execution was at CPU time 0.
    ///
    /// ```
    /// use plc_timers::s5::{S5State, S5TimerOps, S5TimerRef};
    /// assert_eq!(S5TimerRef::new().state(), S5State::RESET);
    /// ```
    pub const fn new() -> S5TimerRef {
        S5TimerRef {
            state: S5State::RESET,
            last_call: CpuTime::ZERO,
        }
    }

    /// A timer in `state` whose previous execution was at `last_call`, or `None` when the state
    /// is not valid ([`S5State::is_valid`]).
    ///
    /// ```
    /// use plc_timers::s5::{S5State, S5TimerRef};
    /// use plc_timers::time::CpuTime;
    /// assert!(S5TimerRef::from_state(S5State::RESET, CpuTime::ZERO).is_some());
    /// let invalid = S5State { value: 1000, ..S5State::RESET };
    /// assert!(S5TimerRef::from_state(invalid, CpuTime::ZERO).is_none());
    /// ```
    pub const fn from_state(state: S5State, last_call: CpuTime) -> Option<S5TimerRef> {
        if state.is_valid() {
            Some(S5TimerRef { state, last_call })
        } else {
            None
        }
    }

    /// The latest CPU time an execution saw: the previous execution's, unless the clock went
    /// back (S5TMR-CLOCK-01).
    pub const fn last_call(&self) -> CpuTime {
        self.last_call
    }

    /// S5TMR-TICK-01 / S5TMR-EXPIRE-01: the operating system decrements the value of a running
    /// timer by one unit per tick of its base until it is 0 (LAD manual §9.1); when it reaches 0
    /// the time has run out and the status changes (Berger §7). Of `ticks` ticks, at most
    /// `value` take effect.
    pub fn tick(&mut self, ticks: u64) {
        self.tick_rec(ticks, &mut ());
    }

    fn tick_rec(&mut self, ticks: u64, rec: &mut impl Recorder) {
        let s = &mut self.state;
        if !s.running || s.value == 0 {
            return;
        }
        let tick = RuleSet::of(Rule::S5TMR_TICK_01);
        if ticks >= u64::from(s.value) {
            s.value = 0;
            Self::expire(s);
            rec.write(tick.with(Rule::S5TMR_EXPIRE_01), Q | VALUE);
        } else {
            if ticks > 0 {
                // ticks < value <= 999, so the cast is exact.
                s.value -= ticks as u16;
                rec.write(tick, VALUE);
            }
            // The ticks in (t_prev, t], none or too few to run out, decide the value and the
            // status of the running timer also when no tick fell: a deadline model that ends
            // the time between two ticks breaks this rule here.
            rec.add(tick, Q | VALUE);
        }
    }

    /// The time has run out: the timer stops and its status switches to the one its start
    /// chose (pulses and off-delay to 0, on-delays to 1; Berger §7).
    fn expire(s: &mut S5State) {
        s.running = false;
        s.q = s.q_on_expiry;
        s.q_on_expiry = false;
    }

    /// S5TMR-ZERO-01 (Berger §7): a timer started with the value 0 stays active until the CPU,
    /// processing the timer, finds the time run out: at its next execution.
    fn process_zero_value(&mut self, rec: &mut impl Recorder) {
        if self.state.running && self.state.value == 0 {
            Self::expire(&mut self.state);
            rec.write(
                RuleSet::of(Rule::S5TMR_ZERO_01).with(Rule::S5TMR_EXPIRE_01),
                Q,
            );
        }
    }

    /// S5TMR-FR-01 (STL manual, `FR`): a rising edge at FR clears the edge memory of the start
    /// input, and nothing else. A start operation executed with RLO = 1 then sees a rising edge
    /// and restarts the timer; with RLO = 0 nothing starts (an off-delay needs a falling edge,
    /// which a cleared memory cannot give).
    fn enable(&mut self, fr: bool, rec: &mut impl Recorder) {
        if fr != self.state.fr_prev {
            // The FR edge clears the start memory; the FR memory takes the RLO (both are the
            // rule's action).
            rec.state(RuleSet::of(Rule::S5TMR_FR_01));
        }
        if fr && !self.state.fr_prev {
            self.state.s_prev = false;
        }
        self.state.fr_prev = fr;
    }

    /// Loads TV and starts the time (LAD manual §9.1: "when the timer starts, the contents of
    /// the timer cell are used as the time value"). The status while the time runs: 1 for the
    /// pulses and the off-delay; 0 for S_ODT (it switches on when the time has run out); for
    /// S_ODTS unchanged, since its status stays 1 from the first expiry until R (SS-Q-01).
    fn start(&mut self, kind: S5Kind, input: &S5Input) {
        let s = &mut self.state;
        s.running = true;
        s.value = input.tv.units();
        s.base = input.tv.base();
        s.q_on_expiry = is_on_delay(kind);
        s.q = match kind {
            S5Kind::SOdt => false,
            S5Kind::SOdts => s.q,
            S5Kind::SPulse | S5Kind::SPext | S5Kind::SOffdt => true,
        };
    }

    /// Stops the time without clearing the value (S5TMR-STOP-01: S falling stops S_PULSE and
    /// S_ODT and Q = 0; the remaining value stays readable).
    fn stop(&mut self) {
        let s = &mut self.state;
        s.running = false;
        s.q = false;
        s.q_on_expiry = false;
    }

    /// The start logic of the kind (LAD manual §9.3-9.7). Every start needs a signal change at S
    /// (S5TMR-EDGE-01): rising, or falling for S_OFFDT; an FR edge makes a held S count as rising.
    ///
    /// `fr_edge`: an FR edge cleared the start memory in this execution (the start it makes
    /// possible is then FR's too).
    fn start_logic(
        &mut self,
        kind: S5Kind,
        input: &S5Input,
        fr_edge: bool,
        rec: &mut impl Recorder,
    ) {
        let rising = input.s && !self.state.s_prev;
        let falling = !input.s && self.state.s_prev;
        let rule = RuleSet::of(kind_rule(kind));
        let started = if kind.starts_on_falling_edge() {
            falling
        } else {
            rising
        };
        if started {
            rec.write(
                rule.with(Rule::S5TMR_EDGE_01)
                    .with_if(fr_edge && rising, Rule::S5TMR_FR_01)
                    .with_if(input.tv.units() == 0, Rule::S5TMR_ZERO_01),
                Q | VALUE,
            );
        }
        match kind {
            // §9.3 (SP-Q-01): starts on a rising S, runs while S = 1; S falling before the end
            // stops it. S cannot rise while the pulse runs, except after an FR edge, which
            // restarts it like every other kind.
            S5Kind::SPulse => {
                if rising {
                    self.start(kind, input);
                } else if !input.s && self.state.running {
                    self.stop();
                    rec.write(rule.with(Rule::S5TMR_STOP_01), Q);
                }
            }
            // §9.4 (SE-RUN-ON-01): starts on a rising S, runs on when S falls; a rising S while
            // running restarts it with TV.
            S5Kind::SPext => {
                if rising {
                    self.start(kind, input);
                }
            }
            // §9.5 (SD-Q-01): starts on a rising S, runs while S = 1; Q = 1 when the time has run
            // out and S is still 1; S falling stops it, and Q = 0.
            S5Kind::SOdt => {
                if rising {
                    self.start(kind, input);
                } else if !input.s {
                    // S = 0 stops a running S_ODT and clears an expired Q (nothing to do
                    // otherwise).
                    if self.state.running || self.state.q {
                        rec.write(rule.with_if(self.state.running, Rule::S5TMR_STOP_01), Q);
                    }
                    self.stop();
                }
            }
            // §9.6 (SS-Q-01): starts on a rising S, runs on when S falls; Q = 1 after the time
            // whatever S does, until R; a rising S (while running or after the end) restarts the
            // time, and a Q of 1 stays.
            S5Kind::SOdts => {
                if rising {
                    self.start(kind, input);
                }
            }
            // §9.7 (SF-Q-01): starts on a falling S; a rising S sets Q = 1 and stops a running
            // time (it restarts only on the next falling S). Q is the timer's status bit, set
            // by these edges, cleared by expiry and R: after R with S held, Q stays 0 until S
            // changes again.
            S5Kind::SOffdt => {
                if falling {
                    self.start(kind, input);
                } else if rising {
                    let s = &mut self.state;
                    s.running = false;
                    s.q = true;
                    s.q_on_expiry = false;
                    rec.write(rule, Q);
                }
            }
        }
        if self.state.s_prev != input.s {
            rec.state(RuleSet::of(Rule::S5TMR_EDGE_01));
        }
        self.state.s_prev = input.s;
    }

    /// S5TMR-R-01 (Berger §7.1.3; LAD manual §9.3-9.7): while R = 1 the timer is reset: stopped,
    /// value and base cleared, Q = 0. Applied after the start logic of the same execution, so a
    /// scan for 1 gives 0 as long as R = 1.
    fn reset(&mut self, r: bool, rec: &mut impl Recorder) {
        if r {
            rec.write(RuleSet::of(Rule::S5TMR_R_01), Q | VALUE);
            self.state = S5State {
                s_prev: self.state.s_prev,
                fr_prev: self.state.fr_prev,
                ..S5State::RESET
            };
        }
    }

    /// One execution of the box `kind` with the OS ticks since the previous execution already
    /// applied ([`S5TimerRef::tick`]): the value-0 check, `FR`, the start logic, `R`.
    pub(crate) fn execute_rec(
        &mut self,
        kind: S5Kind,
        input: S5Input,
        rec: &mut impl Recorder,
    ) -> S5Output {
        self.process_zero_value(rec);
        let fr_edge = input.fr && !self.state.fr_prev && self.state.s_prev;
        self.enable(input.fr, rec);
        self.start_logic(kind, &input, fr_edge, rec);
        self.reset(input.r, rec);
        // BI and BCD are the timer's value as `L T n` and `LC T n` read it.
        rec.add(RuleSet::of(Rule::S5TMR_LOAD_01), VALUE);
        self.state.output()
    }

    pub(crate) fn call_rec(
        &mut self,
        kind: S5Kind,
        now: CpuTime,
        input: S5Input,
        rec: &mut impl Recorder,
    ) -> S5Output {
        self.tick_rec(ticks_between(self.last_call, now, self.state.base), rec);
        // S5TMR-CLOCK-01: a step back applies no tick and the clock keeps the latest time it
        // saw, as the timer memory area's does; else the span back would be counted again.
        if now > self.last_call {
            self.last_call = now;
        }
        self.execute_rec(kind, input, rec)
    }

    /// [`S5TimerOps::call`], explained: the same outputs and state, with the rules that decided
    /// each output (Q, BI, BCD) and acted on the state ([`Explained`]).
    ///
    /// ```
    /// use plc_timers::rule::Rule;
    /// use plc_timers::s5::{S5Input, S5Kind, S5TimerRef};
    /// use plc_timers::time::CpuTime;
    ///
    /// let mut sp = S5TimerRef::new();
    /// let zero = S5Input::new(true, false, plc_timers::s5time!("S5T#0MS"));
    /// let e = sp.call_explained(S5Kind::SPulse, CpuTime::ZERO, zero);
    /// assert!(e.output.q); // active in the starting execution ...
    /// assert!(e.outputs[0].contains(Rule::S5TMR_ZERO_01));
    /// let e = sp.call_explained(S5Kind::SPulse, CpuTime::ZERO, zero);
    /// assert!(!e.output.q); // ... found run out at the next
    /// assert!(e.outputs[0].contains(Rule::S5TMR_ZERO_01) && e.outputs[0].contains(Rule::S5TMR_EXPIRE_01));
    /// ```
    pub fn call_explained(
        &mut self,
        kind: S5Kind,
        now: CpuTime,
        input: S5Input,
    ) -> Explained<S5Output> {
        let mut rec = Explanation::default();
        let o = self.call_rec(kind, now, input, &mut rec);
        rec.finish(o)
    }

    /// `FR T n` alone, recorded.
    pub(crate) fn fr_rec(&mut self, fr: bool, rec: &mut impl Recorder) {
        self.enable(fr, rec);
    }

    /// `SP`…`SF T n` alone (the value-0 check, then the start logic), recorded.
    pub(crate) fn start_rec(&mut self, kind: S5Kind, input: &S5Input, rec: &mut impl Recorder) {
        self.process_zero_value(rec);
        self.start_logic(kind, input, false, rec);
    }

    /// `R T n` alone, recorded.
    pub(crate) fn reset_rec(&mut self, r: bool, rec: &mut impl Recorder) {
        self.reset(r, rec);
    }
}

impl S5TimerOps for S5TimerRef {
    /// One execution at CPU time `now`: the ticks of the timer's base in `(last_call, now]` are
    /// applied first. `now` must not go back; if it does, no tick is applied and `last_call`
    /// stays (S5TMR-CLOCK-01).
    fn call(&mut self, kind: S5Kind, now: CpuTime, input: S5Input) -> S5Output {
        self.call_rec(kind, now, input, &mut ())
    }

    fn state(&self) -> S5State {
        self.state
    }
}

impl S5TimerRef {
    /// S5TMR-RETAIN-01: a RUN-STOP-RUN, the CPU in STOP from `stop` to `restart`. The OS ticks
    /// up to `stop` are applied; none falls in STOP (LAD manual §9.1: the OS decrements the
    /// value "in RUN mode"), so the first execution after the restart counts the ticks from
    /// `restart` on. At the restart a retentive timer keeps its whole state (value, base, Q,
    /// running, edge memories) and a non-retentive one is [`S5State::RESET`] (a decision, as
    /// IEC-RETAIN-01 is for the IEC timers). A time before the previous execution moves nothing
    /// back: no tick is applied twice.
    ///
    /// ```
    /// use plc_timers::s5::{S5Input, S5Kind, S5State, S5TimerOps, S5TimerRef};
    /// use plc_timers::time::CpuTime;
    /// let at = CpuTime::from_millis;
    /// let on = S5Input::new(true, false, plc_timers::s5time!("S5T#100MS")); // 10 units of 10 ms
    /// let mut t = S5TimerRef::new();
    /// t.call(S5Kind::SOdt, at(0), on);
    /// t.run_stop_run(at(40), at(5_000), true); // 4 ticks before the STOP, none in it
    /// assert_eq!(t.call(S5Kind::SOdt, at(5_030), on).bi, 3); // 3 ticks since the restart
    /// t.run_stop_run(at(5_030), at(6_000), false);
    /// assert_eq!(t.state(), S5State::RESET);
    /// ```
    pub fn run_stop_run(&mut self, stop: CpuTime, restart: CpuTime, retentive: bool) {
        self.tick(ticks_between(self.last_call, stop, self.state.base));
        self.last_call = self.last_call.max(stop).max(restart);
        if !retentive {
            self.state = S5State::RESET;
        }
    }
}
