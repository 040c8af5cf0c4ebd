//! The reference semantics of the S5 timers, one function per rule.
//!
//! Sources: seed 000 §9.1 (timer word, OS update), §9.3-9.7 (the five kinds), seed 003 §7 (OS
//! update asynchronous to the scan, value 0, `R T n`). Rule IDs refer to
//! `spec/requirements/s5.toml`; `spec/s5.md` gives the reasons for the modelling decisions.

use super::{ticks_between, S5Input, S5Kind, S5Output, S5State};
use crate::time::TimeBase;

/// One S5 timer of kind `kind`, executed as the LAD box (or its STL sequence
/// `FR`, `SP/SE/SD/SS/SF`, `R`) at successive CPU times.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct S5TimerRef {
    /// The box kind.
    pub kind: S5Kind,
    /// The timer's state.
    pub state: S5State,
    /// The CPU time (ms) of the previous execution: ticks after it and up to the next execution
    /// are applied before that execution.
    pub t_prev: u64,
}

/// The status Q while the time runs: 1 for the pulses and the off-delay (seed 000 §9.3, §9.4:
/// "while the timer runs, a scan of Q for 1 gives 1"; §9.7: "Q = 1 if S = 1 or the timer runs");
/// 0 for the on-delays, which switch on when the time has run out (§9.5, §9.6).
pub const fn q_while_running(kind: S5Kind) -> bool {
    matches!(kind, S5Kind::SPulse | S5Kind::SPext | S5Kind::SOffdt)
}

impl S5TimerRef {
    /// A cleared timer at CPU time 0.
    pub const fn new(kind: S5Kind) -> S5TimerRef {
        S5TimerRef {
            kind,
            state: S5State::RESET,
            t_prev: 0,
        }
    }

    /// S5TMR-TICK-01 / S5TMR-EXPIRE-01: the operating system decrements the value of a running
    /// timer by one unit per tick of its base until it is 0 (seed 000 §9.1); when it reaches 0 the
    /// time has run out and the status changes (seed 003 §7). Of `ticks` ticks, at most `value`
    /// take effect.
    pub fn tick(&mut self, ticks: u64) {
        let s = &mut self.state;
        if !s.running || ticks == 0 || s.value == 0 {
            return;
        }
        if ticks >= u64::from(s.value) {
            s.value = 0;
            Self::expire(s);
        } else {
            // ticks < value <= 999, so the cast is exact.
            s.value -= ticks as u16;
        }
    }

    /// The time has run out: the timer stops and its status switches (pulses and off-delay to 0,
    /// on-delays to 1). A running timer's Q is [`q_while_running`], so expiry inverts it.
    fn expire(s: &mut S5State) {
        s.running = false;
        s.q = !s.q;
    }

    /// S5TMR-ZERO-01 (seed 003 §7): a timer started with the value 0 stays active until the CPU,
    /// processing the timer, finds the time run out: at its next execution.
    fn process_zero_value(&mut self) {
        if self.state.running && self.state.value == 0 {
            Self::expire(&mut self.state);
        }
    }

    /// S5TMR-FR-01 (STL `FR T n`, modelling decision): a rising edge at FR re-enables the timer:
    /// it clears the start edge memory so that the current S level counts as a start edge.
    fn enable(&mut self, fr: bool) {
        if fr && !self.state.fr_prev {
            self.state.s_prev = self.kind.starts_on_falling_edge();
        }
        self.state.fr_prev = fr;
    }

    /// Loads TV and starts the time (seed 000 §9.1: "when the timer starts, the contents of
    /// the timer cell are used as the time value").
    fn start(&mut self, input: &S5Input) {
        let s = &mut self.state;
        s.running = true;
        s.value = input.tv.units();
        s.base = input.tv.base();
        s.q = q_while_running(self.kind);
    }

    /// Stops the time without clearing the value (SP-STOP-01, SD-STOP-01: S falling stops the
    /// timer and Q = 0; the remaining value stays readable, a decision).
    fn stop(&mut self) {
        self.state.running = false;
        self.state.q = false;
    }

    /// The start logic of the kind (seed 000 §9.3-9.7). Every start needs a signal change at S
    /// (S5TMR-EDGE-01): rising, or falling for S_OFFDT.
    fn start_logic(&mut self, input: &S5Input) {
        let rising = input.s && !self.state.s_prev;
        let falling = !input.s && self.state.s_prev;
        match self.kind {
            // §9.3: starts on a rising S, runs while S = 1; S falling before the end stops it.
            S5Kind::SPulse => {
                if rising && !self.state.running {
                    self.start(input);
                } else if !input.s && self.state.running {
                    self.stop();
                }
            }
            // §9.4: starts on a rising S, runs on when S falls; a rising S while running
            // restarts it with TV.
            S5Kind::SPext => {
                if rising {
                    self.start(input);
                }
            }
            // §9.5: starts on a rising S, runs while S = 1; Q = 1 when the time has run out and
            // S is still 1; S falling stops it, and Q = 0.
            S5Kind::SOdt => {
                if rising {
                    self.start(input);
                } else if !input.s {
                    self.stop();
                }
            }
            // §9.6: starts on a rising S, runs on when S falls; Q = 1 after the time whatever S
            // does; a rising S (while running or after the end) restarts it (SS-RESTART-01).
            S5Kind::SOdts => {
                if rising {
                    self.start(input);
                }
            }
            // §9.7: starts on a falling S; Q = 1 while S = 1 or the timer runs; a rising S while
            // running stops it (it restarts only on the next falling S).
            S5Kind::SOffdt => {
                if falling {
                    self.start(input);
                } else if input.s {
                    self.state.running = false;
                    self.state.q = true;
                }
            }
        }
        self.state.s_prev = input.s;
    }

    /// S5TMR-R-01 (seed 003 §7.1.3, seed 000 §9.3-9.7): while R = 1 the timer is reset: stopped,
    /// value and base cleared, Q = 0. Applied after the start logic of the same execution, so a
    /// scan for 1 gives 0 as long as R = 1.
    fn reset(&mut self, r: bool) {
        if r {
            let s = &mut self.state;
            s.running = false;
            s.value = 0;
            s.base = TimeBase::Ms10;
            s.q = false;
        }
    }

    /// One execution of the box with the OS ticks since the previous execution already applied.
    pub fn execute(&mut self, input: S5Input) -> S5Output {
        self.process_zero_value();
        self.enable(input.fr);
        self.start_logic(&input);
        self.reset(input.r);
        self.state.output()
    }

    /// One execution at CPU time `t_ms` (not before the previous one): the ticks of the timer's
    /// base in `(t_prev, t_ms]` are applied first.
    pub fn call(&mut self, t_ms: u64, input: S5Input) -> S5Output {
        self.tick(ticks_between(self.t_prev, t_ms, self.state.base));
        self.t_prev = t_ms;
        self.execute(input)
    }
}
