//! RuSTy's standard-library timers and counters (github `PLC-lang/rusty`).
//!
//! - Timers: `libs/stdlib/src/timers.rs`, functions `TON`, `TOF`, `TP` over one shared
//!   parameter structure (`TimerParams`), as of the version with PR #1667 (2026-04: `TP` no
//!   longer panics when it is called idle with IN = 0).
//! - Counters: `libs/stdlib/src/counters.rs`, generic `ctu` / `ctd` behind `CTU`, `CTU_DINT`,
//!   `CTD`, ..., as of the version with PR #1877 (2026-08: the CU/CD edge is evaluated before
//!   the R/LD test).
//! - Edge memory: `libs/stdlib/src/utils.rs`, `Signal`.
//!
//! Translation: RuSTy's `TIME` is an `i64` of nanoseconds and its clock is
//! `std::time::Instant` (monotonic, never wraps), read at the start and twice per call while
//! a timer runs. Here `TIME` is an `i64` of milliseconds, the start instant is the caller's
//! `now_ms`, and the running time is `now_ms - start` modulo 2^32 (exact for runs shorter than
//! 2^32 ms). The OS clock reads, which dominate the real block's cost, are not in the port.
//! As in a RuSTy program, a call first stores the inputs into the instance, then runs the body,
//! then reads the outputs from the instance.

use super::PeerInt;

/// RuSTy's `TIME`: a signed 64-bit duration (nanoseconds in RuSTy, milliseconds here).
type Time = i64;

/// A remembered boolean, RuSTy's `Signal`: the previous value of an input.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
#[repr(transparent)]
struct Signal {
    /// The value seen on the previous evaluation.
    current_value: bool,
}

impl Signal {
    /// 1 when `next` is 1 and differs from the remembered value; remembers `next`.
    #[inline(always)]
    fn rising_edge(&mut self, next: bool) -> bool {
        let edge = next && (self.current_value ^ next);
        self.current_value = next;
        edge
    }

    /// 1 when `next` is 0 and differs from the remembered value; remembers `next`.
    #[inline(always)]
    fn falling_edge(&mut self, next: bool) -> bool {
        let edge = !next && (self.current_value ^ next);
        self.current_value = next;
        edge
    }

    /// Remembers `value`.
    #[inline(always)]
    fn set(&mut self, value: bool) {
        self.current_value = value;
    }
}

/// The instance of one timer, RuSTy's `TimerParams`, shared by TON, TOF and TP; same members in
/// the same order. `start_time` is `Option<Instant>` in RuSTy, an optional clock reading here.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
#[repr(C)]
struct TimerParams {
    /// The pointer every RuSTy function-block instance starts with; kept for the size only.
    vtable: usize,
    /// IN.
    input: bool,
    /// PT, written by every call.
    preset_time: Time,
    /// Q.
    output: bool,
    /// ET.
    elapsed_time: Time,
    /// IN on the previous call.
    input_edge: Signal,
    /// Set by `start`, cleared by `reset`; not cleared by expiry.
    is_running: bool,
    /// The clock when the timer started; `None` when reset.
    start_time: Option<u32>,
}

impl TimerParams {
    /// The state RuSTy's initializer gives: all zero, not running.
    const INIT: TimerParams = TimerParams {
        vtable: 0,
        input: false,
        preset_time: 0,
        output: false,
        elapsed_time: 0,
        input_edge: Signal {
            current_value: false,
        },
        is_running: false,
        start_time: None,
    };

    #[inline(always)]
    fn is_running(&self) -> bool {
        self.is_running
    }

    /// Reads the clock into the start time, marks running, ET = 0.
    #[inline(always)]
    fn start(&mut self, now: u32) {
        self.start_time = Some(now);
        self.is_running = true;
        self.set_elapsed_time(0);
    }

    /// Forgets the start time, marks stopped, ET = 0.
    #[inline(always)]
    fn reset(&mut self) {
        self.start_time = None;
        self.is_running = false;
        self.set_elapsed_time(0);
    }

    #[inline(always)]
    fn set_elapsed_time(&mut self, duration: Time) {
        self.elapsed_time = duration;
    }

    /// While running: ET = the smaller of PT and the running time (a clock read).
    #[inline(always)]
    fn update_elapsed_time(&mut self, now: u32) {
        if self.is_running() {
            let run = self.get_run_time(now).expect("timer should be running");
            self.set_elapsed_time(core::cmp::min(self.preset_time, Time::from(run)));
        }
    }

    /// The running time (a second clock read) is at most PT, PT taken as unsigned: a negative
    /// PT becomes huge and is never passed. False when not started.
    #[inline(always)]
    fn is_in_preset_range(&self, now: u32) -> bool {
        let preset = self.preset_time as u64;
        self.get_run_time(now)
            .is_some_and(|run| u64::from(run) <= preset)
    }

    /// The time since the start, if started. RuSTy: `Instant::elapsed`; here the clock
    /// difference modulo 2^32.
    #[inline(always)]
    fn get_run_time(&self, now: u32) -> Option<u32> {
        self.start_time.map(|start| now.wrapping_sub(start))
    }

    #[inline(always)]
    fn set_output(&mut self, value: bool) {
        self.output = value;
    }

    #[inline(always)]
    fn input_rising_edge(&mut self) -> bool {
        self.input_edge.rising_edge(self.input)
    }

    #[inline(always)]
    fn input_falling_edge(&mut self) -> bool {
        self.input_edge.falling_edge(self.input)
    }

    /// What the caller does around the body: store IN and PT into the instance.
    #[inline(always)]
    fn store_inputs(&mut self, input: bool, pt_ms: i32) {
        self.input = input;
        self.preset_time = Time::from(pt_ms);
    }

    /// What the caller reads after the body: Q and ET (ET in milliseconds; it is never above
    /// PT, so it fits in `i32`).
    #[inline(always)]
    fn outputs(&self) -> (bool, i32) {
        (self.output, self.elapsed_time as i32)
    }
}

/// RuSTy's TON (`timers.rs`, function `TON`).
///
/// Per call: IN = 0 resets (ET = 0, not running) and Q = 0. IN = 1 and running: ET =
/// min(PT, elapsed), Q = elapsed > PT. IN = 1, not running, rising IN: start (START = now,
/// ET = 0), Q = 0. IN = 1, not running, no edge: Q = 1 (not reached from the initial state).
/// The edge memory then takes IN.
///
/// Differences from S7-1200:
/// - PT is read on every call, not latched: both the ET clamp and the expiry test use the
///   current PT, also after expiry (raising PT after Q = 1 takes Q back to 0).
/// - Expiry at elapsed > PT, not >= PT: when exactly PT has elapsed, ET = PT but Q = 0. (With
///   RuSTy's nanosecond clock the gap is 1 ns; with this millisecond port it is 1 ms.)
/// - The starting call never tests expiry: with PT = 0, Q comes on the next call with
///   elapsed > 0, where S7 sets Q on the starting call.
/// - The timer never stops after expiry while IN = 1: every call reads the clock and recomputes
///   ET and Q. RuSTy's clock does not wrap; in this port the elapsed time is modulo 2^32, so
///   after 2^32 ms of IN = 1 Q drops again (an artifact of the port's clock, not of RuSTy).
/// - Negative PT: never expires, ET = PT (negative); S7 takes it as 0.
/// - RuSTy reads its clock twice per running call (ET and Q may come from two instants); the
///   port uses `now_ms` for both.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Ton(TimerParams);

/// RuSTy's TOF (`timers.rs`, function `TOF`).
///
/// Per call: IN = 1: on its rising edge reset (ET = 0, not running); Q = 1. IN = 0 on its
/// falling edge: start (START = now, ET = 0), Q = 1. IN = 0, running: ET = min(PT, elapsed),
/// Q = elapsed <= PT. Otherwise Q = 0. The edge memory then takes IN.
///
/// Differences from S7-1200:
/// - PT is read on every call, not latched, also after expiry (raising PT then brings Q back).
/// - Q falls at elapsed > PT, not at ET >= PT: one clock unit late (1 ns in RuSTy, 1 ms here).
/// - The falling-edge call never tests expiry: with PT = 0 Q stays 1 on that call and falls on
///   the next one with elapsed > 0; S7 takes Q to 0 on the falling-edge call.
/// - After expiry the timer stays "running": every call with IN = 0 reads the clock. In this
///   port, with a wrapping clock, Q comes back for PT ms every 2^32 ms (port artifact).
/// - Negative PT: Q never falls (elapsed <= PT taken as unsigned is always true); ET = PT.
/// - ET and the running state are cleared only on the rising edge of IN, not on every call
///   with IN = 1 (the same outputs as S7 as long as nothing else writes the instance).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Tof(TimerParams);

/// RuSTy's TP (`timers.rs`, function `TP`).
///
/// Per call: running: ET = min(PT, elapsed); if elapsed <= PT, Q = 1; else Q = 0 and, on a
/// falling edge of IN, reset (ET = 0, not running). Not running: on a rising edge of IN start
/// (START = now, ET = 0), Q = 1; else Q = 0. The edge memory then takes IN.
///
/// Differences from S7-1200:
/// - Re-arming needs a falling edge of IN seen after the pulse ended. If IN fell during the
///   pulse, the timer stays "running" with Q = 0 and ET = PT; the next rising edge of IN is
///   swallowed (it only sets up the falling edge that re-arms), so of short triggers only
///   every other one makes a pulse. S7 starts a new pulse on any rising IN when none runs,
///   and returns ET to 0 when IN = 0 after the pulse.
/// - PT is read on every call, not latched: lowering PT shortens a running pulse; raising it
///   after the pulse, while IN is still 1, brings Q back.
/// - Expiry at elapsed > PT (Q stays 1 one clock unit longer than S7's ET >= PT).
/// - The starting call never tests expiry: PT = 0 still gives Q = 1 for one call; S7 gives no
///   pulse.
/// - Negative PT: the pulse never ends (Q = 1 for good), ET = PT.
/// - Before PR #1667 an idle call with IN = 0 (not running, no rising edge) panicked
///   (`unreachable!`); the port follows the fixed version (Q = 0).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Tp(TimerParams);

impl Ton {
    /// A new instance: not running, IN remembered as 0.
    pub const fn new() -> Ton {
        Ton(TimerParams::INIT)
    }

    /// One call of RuSTy's `TON` with IN = `input`, PT = `pt_ms`, the clock at `now_ms`;
    /// returns (Q, ET in ms). See the type's documentation for the differences from S7.
    #[inline(always)]
    pub fn call(&mut self, input: bool, pt_ms: i32, now_ms: u32) -> (bool, i32) {
        let timer = &mut self.0;
        timer.store_inputs(input, pt_ms);
        let output = if timer.input {
            if timer.is_running() {
                timer.update_elapsed_time(now_ms);
                !timer.is_in_preset_range(now_ms)
            } else if timer.input_rising_edge() {
                timer.start(now_ms);
                false
            } else {
                true
            }
        } else {
            timer.reset();
            false
        };
        timer.set_output(output);
        timer.input_edge.set(timer.input);
        timer.outputs()
    }
}

impl Tof {
    /// A new instance: not running, IN remembered as 0.
    pub const fn new() -> Tof {
        Tof(TimerParams::INIT)
    }

    /// One call of RuSTy's `TOF` with IN = `input`, PT = `pt_ms`, the clock at `now_ms`;
    /// returns (Q, ET in ms). See the type's documentation for the differences from S7.
    #[inline(always)]
    pub fn call(&mut self, input: bool, pt_ms: i32, now_ms: u32) -> (bool, i32) {
        let timer = &mut self.0;
        timer.store_inputs(input, pt_ms);
        let output = if timer.input {
            if timer.input_rising_edge() {
                timer.reset();
            }
            true
        } else if timer.input_falling_edge() {
            timer.start(now_ms);
            true
        } else if timer.is_running() {
            timer.update_elapsed_time(now_ms);
            timer.is_in_preset_range(now_ms)
        } else {
            false
        };
        timer.set_output(output);
        timer.input_edge.set(timer.input);
        timer.outputs()
    }
}

impl Tp {
    /// A new instance: not running, IN remembered as 0.
    pub const fn new() -> Tp {
        Tp(TimerParams::INIT)
    }

    /// One call of RuSTy's `TP` with IN = `input`, PT = `pt_ms`, the clock at `now_ms`;
    /// returns (Q, ET in ms). See the type's documentation for the differences from S7.
    #[inline(always)]
    pub fn call(&mut self, input: bool, pt_ms: i32, now_ms: u32) -> (bool, i32) {
        let timer = &mut self.0;
        timer.store_inputs(input, pt_ms);
        let output = if timer.is_running() {
            timer.update_elapsed_time(now_ms);
            if timer.is_in_preset_range(now_ms) {
                true
            } else {
                if timer.input_falling_edge() {
                    timer.reset();
                }
                false
            }
        } else if timer.input_rising_edge() {
            timer.start(now_ms);
            true
        } else {
            false
        };
        timer.set_output(output);
        timer.input_edge.set(timer.input);
        timer.outputs()
    }
}

impl Default for Ton {
    fn default() -> Ton {
        Ton::new()
    }
}

impl Default for Tof {
    fn default() -> Tof {
        Tof::new()
    }
}

impl Default for Tp {
    fn default() -> Tp {
        Tp::new()
    }
}

/// RuSTy's CTU (`counters.rs`, `ctu` behind `CTU` / `CTU_INT` for `i16`, `CTU_DINT` for `i32`,
/// `CTU_LINT` for `i64`); same members in the same order as `CTUParams`.
///
/// Per call: the rising edge of CU is taken first (the edge memory takes CU on every call);
/// then R = 1 sets CV = 0, else a rising edge with CV below the type's maximum adds 1;
/// Q = CV >= PV.
///
/// Differences from S7-1200: none in the outputs of CTU. It counts past PV and stops at the
/// type's maximum (no wrap), R dominates, and releasing R with CU held does not count. That
/// last point holds since PR #1877 (2026-08); before it the edge was evaluated only when R = 0,
/// so a CU edge during R, held when R was released, counted once on release. (RuSTy's CTUD,
/// not ported, still evaluates its edges only when R = LD = 0.)
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
#[repr(C)]
pub struct Ctu<T> {
    /// The function-block instance's vtable word; kept for the size only.
    vtable: usize,
    /// CU.
    cu: bool,
    /// R.
    r: bool,
    /// PV.
    pv: T,
    /// Q.
    q: bool,
    /// CV.
    cv: T,
    /// CU on the previous call.
    internal: Signal,
}

impl<T: PeerInt> Ctu<T> {
    /// A new instance: CV = 0, CU remembered as 0.
    pub fn new() -> Ctu<T> {
        Ctu {
            vtable: 0,
            cu: false,
            r: false,
            pv: T::ZERO,
            q: false,
            cv: T::ZERO,
            internal: Signal::default(),
        }
    }

    /// One call of RuSTy's `CTU` with CU = `cu`, R = `r`, PV = `pv`; returns (Q, CV).
    #[inline(always)]
    pub fn call(&mut self, cu: bool, r: bool, pv: T) -> (bool, T) {
        self.cu = cu;
        self.r = r;
        self.pv = pv;
        let cu_r_edge = self.internal.rising_edge(self.cu);
        if self.r {
            self.cv = T::ZERO;
        } else if cu_r_edge & (self.cv < T::MAX) {
            self.cv = self.cv.plus_one();
        }
        self.q = self.cv >= self.pv;
        (self.q, self.cv)
    }
}

impl<T: PeerInt> Default for Ctu<T> {
    fn default() -> Ctu<T> {
        Ctu::new()
    }
}

/// RuSTy's CTD (`counters.rs`, `ctd` behind `CTD` / `CTD_INT` for `i16`, `CTD_DINT` for `i32`,
/// `CTD_LINT` for `i64`); same members in the same order as `CTDParams`.
///
/// Per call: the rising edge of CD is taken first (the edge memory takes CD on every call);
/// then LD = 1 sets CV = PV, else a rising edge with CV above the type's minimum subtracts 1;
/// Q = CV <= 0.
///
/// Differences from S7-1200: none in the outputs of CTD. It counts below 0 and stops at the
/// type's minimum (no wrap), LD dominates, and releasing LD with CD held does not count (since
/// PR #1877; before it a CD edge during LD counted once when LD was released).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
#[repr(C)]
pub struct Ctd<T> {
    /// The function-block instance's vtable word; kept for the size only.
    vtable: usize,
    /// CD.
    cd: bool,
    /// LD.
    ld: bool,
    /// PV.
    pv: T,
    /// Q.
    q: bool,
    /// CV.
    cv: T,
    /// CD on the previous call.
    internal: Signal,
}

impl<T: PeerInt> Ctd<T> {
    /// A new instance: CV = 0, CD remembered as 0.
    pub fn new() -> Ctd<T> {
        Ctd {
            vtable: 0,
            cd: false,
            ld: false,
            pv: T::ZERO,
            q: false,
            cv: T::ZERO,
            internal: Signal::default(),
        }
    }

    /// One call of RuSTy's `CTD` with CD = `cd`, LD = `ld`, PV = `pv`; returns (Q, CV).
    #[inline(always)]
    pub fn call(&mut self, cd: bool, ld: bool, pv: T) -> (bool, T) {
        self.cd = cd;
        self.ld = ld;
        self.pv = pv;
        let cd_r_edge = self.internal.rising_edge(self.cd);
        if self.ld {
            self.cv = self.pv;
        } else if cd_r_edge & (self.cv > T::MIN) {
            self.cv = self.cv.minus_one();
        }
        self.q = self.cv <= T::ZERO;
        (self.q, self.cv)
    }
}

impl<T: PeerInt> Default for Ctd<T> {
    fn default() -> Ctd<T> {
        Ctd::new()
    }
}
