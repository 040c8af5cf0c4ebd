//! matiec's standard function blocks (github `beremiz/matiec`), as OpenPLC v3 runs them.
//!
//! - Timers: `lib/timer.txt`, function blocks `TON`, `TOF`, `TP` (a three-state machine each).
//! - Counters: `lib/counter.txt`, `CTU` / `CTD` (INT) and `CTU_DINT`, `CTD_DINT`, `..._LINT`.
//! - Edge detection: `lib/edge_detection.txt`, `R_TRIG`.
//! - The compiled form the ports follow: `lib/C/iec_std_FB.h` (`TON_body__`, `CTU_body__`, ...),
//!   with the variable macros of `lib/C/accessor.h` and the time arithmetic of
//!   `lib/C/iec_std_lib.h` (`__time_add`, `__time_sub`, `__normalize_timespec`, `__time_cmp`).
//!   OpenPLC v3 carries the same timer and counter blocks and the same `R_TRIG` in
//!   `utils/matiec_src/lib`, and compiles without `-e`, so EN/ENO are present.
//!
//! What the compiled blocks do on every call, and the ports do too:
//! - Every variable is a value with a flags byte (`__IEC_<type>_t`); every write checks the
//!   FORCE flag first (`__SET_VAR`). Nothing is ever forced here, as in a runtime where nobody
//!   forces: the test is always false.
//! - The body starts with the EN test and writes ENO.
//! - `TIME` is a `{ tv_sec, tv_nsec }` pair (C `long`s, 64-bit on the targets OpenPLC runs on);
//!   `+` and `-` normalize, `<=` compares seconds then nanoseconds.
//! - The timers copy the global clock `__CURRENT_TIME` into their own `CURRENT_TIME`. OpenPLC
//!   advances that global by the nominal cycle time after each scan (`updateTime`, generated
//!   into `glueVars.c` by `utils/glue_generator_src/glue_generator.cpp`, called after
//!   `config_run__` in `webserver/core/main.cpp`); it never wraps.
//! - The caller writes the inputs it passes (IN, PT; CU, R, PV) into the instance, with the
//!   force check, calls the body, reads the outputs.
//!
//! Translation: `__CURRENT_TIME` is `now_ms` as a `TIME`, PT is `pt_ms` as a `TIME`, and ET is
//! returned in milliseconds; these three conversions are the port's adapter (matiec has the
//! clock and PT already as `TIME`). matiec compiles `LE_TIME` as a variadic function, which C
//! compilers do not inline; the port's comparison is inline, so it is somewhat cheaper there.

use super::PeerInt;

/// The FORCE bit of a variable's flags byte (`__IEC_FORCE_FLAG`).
const FORCE_FLAG: u8 = 0x02;

/// One variable as matiec declares it: the value and a flags byte (`__IEC_<type>_t`).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
#[repr(C)]
struct Var<T> {
    /// The value.
    value: T,
    /// Debug flags: forced, retained, output.
    flags: u8,
}

impl<T: Copy> Var<T> {
    /// The variable with an initial value and no flag set (`__INIT_VAR`, not retained).
    const fn new(value: T) -> Var<T> {
        Var { value, flags: 0 }
    }

    /// `__GET_VAR`.
    #[inline(always)]
    fn get(&self) -> T {
        self.value
    }

    /// `__SET_VAR`: the write happens unless the variable is forced.
    #[inline(always)]
    fn set(&mut self, value: T) {
        if self.flags & FORCE_FLAG == 0 {
            self.value = value;
        }
    }
}

/// Nanoseconds in a second.
const NS_PER_S: i64 = 1_000_000_000;

/// matiec's `TIME` (`IEC_TIMESPEC`): seconds and nanoseconds, both signed; a negative duration
/// has both parts negative.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
#[repr(C)]
struct Time {
    /// Seconds.
    tv_sec: i64,
    /// Nanoseconds.
    tv_nsec: i64,
}

impl Time {
    /// `T#0s`.
    const ZERO: Time = Time {
        tv_sec: 0,
        tv_nsec: 0,
    };

    /// A duration or clock reading in milliseconds as a `TIME` (the port's adapter; the
    /// division truncates towards zero, so both parts take the sign, as matiec's literals do).
    #[inline(always)]
    fn from_ms(ms: i64) -> Time {
        Time {
            tv_sec: ms / 1000,
            tv_nsec: (ms % 1000) * 1_000_000,
        }
    }

    /// The duration in whole milliseconds (the port's adapter, for ET).
    #[inline(always)]
    fn to_ms(self) -> i64 {
        self.tv_sec * 1000 + self.tv_nsec / 1_000_000
    }

    /// `__normalize_timespec`: moves at most one second between the parts, so that they have
    /// the same sign and the nanoseconds stay within one second (the bounds are exclusive, as
    /// in matiec: exactly one second of nanoseconds is left as it is).
    #[inline(always)]
    fn normalize(&mut self) {
        if self.tv_nsec < -NS_PER_S || (self.tv_sec > 0 && self.tv_nsec < 0) {
            self.tv_sec -= 1;
            self.tv_nsec += NS_PER_S;
        }
        if self.tv_nsec > NS_PER_S || (self.tv_sec < 0 && self.tv_nsec > 0) {
            self.tv_sec += 1;
            self.tv_nsec -= NS_PER_S;
        }
    }

    /// `__time_add`.
    #[inline(always)]
    fn add(self, other: Time) -> Time {
        let mut res = Time {
            tv_sec: self.tv_sec + other.tv_sec,
            tv_nsec: self.tv_nsec + other.tv_nsec,
        };
        res.normalize();
        res
    }

    /// `__time_sub`.
    #[inline(always)]
    fn sub(self, other: Time) -> Time {
        let mut res = Time {
            tv_sec: self.tv_sec - other.tv_sec,
            tv_nsec: self.tv_nsec - other.tv_nsec,
        };
        res.normalize();
        res
    }

    /// `__time_cmp`: negative, zero or positive as `self` is before, at or after `other`
    /// (seconds first; the nanoseconds only when the seconds are equal).
    #[inline(always)]
    fn cmp_time(self, other: Time) -> i64 {
        if other.tv_sec == self.tv_sec {
            self.tv_nsec - other.tv_nsec
        } else {
            self.tv_sec - other.tv_sec
        }
    }

    /// `LE_TIME` with two operands.
    #[inline(always)]
    fn le(self, other: Time) -> bool {
        self.cmp_time(other) <= 0
    }
}

/// The instance of TON, TOF or TP: the same members, in the same order, in all three
/// (`iec_std_FB.h`, the `TON` / `TOF` / `TP` structures).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
#[repr(C)]
struct TimerFb {
    /// EN (initially 1, never written by the caller here).
    en: Var<bool>,
    /// ENO.
    eno: Var<bool>,
    /// IN.
    in_: Var<bool>,
    /// PT, written by every call.
    pt: Var<Time>,
    /// Q.
    q: Var<bool>,
    /// ET.
    et: Var<Time>,
    /// 0: reset, 1: counting, 2: set (expired).
    state: Var<i8>,
    /// IN on the previous call.
    prev_in: Var<bool>,
    /// The copy of the global clock taken at the start of the call.
    current_time: Var<Time>,
    /// CURRENT_TIME when the timer started.
    start_time: Var<Time>,
}

impl TimerFb {
    /// The state `TON_init__` (and `TOF_init__`, `TP_init__`) gives.
    const INIT: TimerFb = TimerFb {
        en: Var::new(true),
        eno: Var::new(true),
        in_: Var::new(false),
        pt: Var::new(Time::ZERO),
        q: Var::new(false),
        et: Var::new(Time::ZERO),
        state: Var::new(0),
        prev_in: Var::new(false),
        current_time: Var::new(Time::ZERO),
        start_time: Var::new(Time::ZERO),
    };

    /// The caller's part before the body: write the passed inputs.
    #[inline(always)]
    fn store_inputs(&mut self, input: bool, pt_ms: i32) {
        self.in_.set(input);
        self.pt.set(Time::from_ms(i64::from(pt_ms)));
    }

    /// The body's prologue: the EN test and ENO. False when the body is to be skipped.
    #[inline(always)]
    fn enabled(&mut self) -> bool {
        if !self.en.get() {
            self.eno.set(false);
            false
        } else {
            self.eno.set(true);
            true
        }
    }

    /// The caller's part after the body: read Q and ET (ET in milliseconds).
    #[inline(always)]
    fn outputs(&self) -> (bool, i32) {
        (self.q.get(), self.et.get().to_ms() as i32)
    }

    /// The expiry test of state 1: START_TIME + PT <= CURRENT_TIME.
    #[inline(always)]
    fn expired(&self) -> bool {
        self.start_time
            .get()
            .add(self.pt.get())
            .le(self.current_time.get())
    }
}

/// matiec's TON (`lib/timer.txt`, `FUNCTION_BLOCK TON`; compiled `TON_body__`).
///
/// Per call: CURRENT_TIME := the clock. STATE 0 with a rising IN (PREV_IN = 0, IN = 1): STATE
/// := 1, Q := 0, START_TIME := CURRENT_TIME. Otherwise IN = 0: ET := 0, Q := 0, STATE := 0;
/// or IN = 1 in STATE 1: if START_TIME + PT <= CURRENT_TIME then STATE := 2, Q := 1, ET := PT,
/// else ET := CURRENT_TIME - START_TIME. PREV_IN := IN.
///
/// Differences from S7-1200:
/// - PT is read on every call while counting (not latched); after expiry (STATE 2) ET stays at
///   the PT of the expiry call and later PT changes are ignored.
/// - Expiry at ET >= PT, as S7, but never on the starting call: with PT <= 0 Q comes one call
///   late.
/// - The clock is compared as absolute times, START + PT <= CURRENT, on a clock that never
///   wraps (64-bit seconds). Fed the port's wrapping `now_ms`, the clock jumps back by 2^32 ms
///   at the wrap and a timer counting across it stalls (ET negative) until the clock catches up;
///   S7 computes `now - START` modulo 2^32 and runs through the wrap.
/// - Negative PT: expires on the first call after the start with ET := PT (negative); S7 takes
///   PT as 0.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Ton(TimerFb);

/// matiec's TOF (`lib/timer.txt`, `FUNCTION_BLOCK TOF`; compiled `TOF_body__`).
///
/// Per call: CURRENT_TIME := the clock. STATE 0 with a falling IN (PREV_IN = 1, IN = 0): STATE
/// := 1, START_TIME := CURRENT_TIME. Otherwise IN = 1: ET := 0, STATE := 0; or IN = 0 in STATE
/// 1: if START_TIME + PT <= CURRENT_TIME then STATE := 2, ET := PT, else ET := CURRENT_TIME -
/// START_TIME. Then Q := IN OR STATE = 1; PREV_IN := IN.
///
/// Differences from S7-1200:
/// - PT is read on every call while timing (not latched); ET frozen at the PT of expiry.
/// - Q falls at ET >= PT, as S7, but never on the falling-edge call: with PT <= 0 Q stays 1 for
///   that call; S7 takes it to 0 at once.
/// - Absolute clock comparison, no wrap handling (see [`Ton`]): a delay running across the
///   wrap of `now_ms` keeps Q = 1 until the clock catches up.
/// - Negative PT: Q falls on the call after the falling edge, with ET := PT (negative).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Tof(TimerFb);

/// matiec's TP (`lib/timer.txt`, `FUNCTION_BLOCK TP`; compiled `TP_body__`).
///
/// Per call: CURRENT_TIME := the clock. STATE 0 with a rising IN: STATE := 1, Q := 1,
/// START_TIME := CURRENT_TIME. Else in STATE 1: if START_TIME + PT <= CURRENT_TIME then STATE
/// := 2, Q := 0, ET := PT, else ET := CURRENT_TIME - START_TIME. Then, in STATE 2 with IN = 0
/// (also on the expiry call itself): ET := 0, STATE := 0. PREV_IN := IN.
///
/// Differences from S7-1200:
/// - PT is read on every call during the pulse (not latched): lowering it ends the pulse early.
/// - The pulse ends at ET >= PT, as S7, but never on the starting call: PT <= 0 still gives a
///   one-call pulse; S7 gives none.
/// - A rising IN on the first call after the pulse has run out is lost: matiec notices the
///   expiry only on that call, after its start test has seen STATE = 1, and STATE 2 then waits
///   for IN = 0 and a further rising IN. S7 ends the pulse and starts the next one on that
///   call. Whenever no call falls between the end of the pulse and the next trigger (a trigger
///   period close to PT), every other trigger is lost.
/// - Absolute clock comparison, no wrap handling (see [`Ton`]): a pulse across the wrap of
///   `now_ms` lasts until the clock catches up.
/// - Negative PT: the pulse ends on the call after its start, with ET := PT (negative).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Tp(TimerFb);

impl Ton {
    /// A new instance, as `TON_init__` leaves it.
    pub const fn new() -> Ton {
        Ton(TimerFb::INIT)
    }

    /// One call of matiec's `TON` with IN = `input`, PT = `pt_ms`, `__CURRENT_TIME` = `now_ms`;
    /// returns (Q, ET in ms). See the type's documentation for the differences from S7.
    #[inline(always)]
    pub fn call(&mut self, input: bool, pt_ms: i32, now_ms: u32) -> (bool, i32) {
        let fb = &mut self.0;
        fb.store_inputs(input, pt_ms);
        if fb.enabled() {
            fb.current_time.set(Time::from_ms(i64::from(now_ms)));
            if fb.state.get() == 0 && !fb.prev_in.get() && fb.in_.get() {
                fb.state.set(1);
                fb.q.set(false);
                fb.start_time.set(fb.current_time.get());
            } else if !fb.in_.get() {
                fb.et.set(Time::ZERO);
                fb.q.set(false);
                fb.state.set(0);
            } else if fb.state.get() == 1 {
                if fb.expired() {
                    fb.state.set(2);
                    fb.q.set(true);
                    fb.et.set(fb.pt.get());
                } else {
                    fb.et.set(fb.current_time.get().sub(fb.start_time.get()));
                }
            }
            fb.prev_in.set(fb.in_.get());
        }
        fb.outputs()
    }
}

impl Tof {
    /// A new instance, as `TOF_init__` leaves it.
    pub const fn new() -> Tof {
        Tof(TimerFb::INIT)
    }

    /// One call of matiec's `TOF` with IN = `input`, PT = `pt_ms`, `__CURRENT_TIME` = `now_ms`;
    /// returns (Q, ET in ms). See the type's documentation for the differences from S7.
    #[inline(always)]
    pub fn call(&mut self, input: bool, pt_ms: i32, now_ms: u32) -> (bool, i32) {
        let fb = &mut self.0;
        fb.store_inputs(input, pt_ms);
        if fb.enabled() {
            fb.current_time.set(Time::from_ms(i64::from(now_ms)));
            if fb.state.get() == 0 && fb.prev_in.get() && !fb.in_.get() {
                fb.state.set(1);
                fb.start_time.set(fb.current_time.get());
            } else if fb.in_.get() {
                fb.et.set(Time::ZERO);
                fb.state.set(0);
            } else if fb.state.get() == 1 {
                if fb.expired() {
                    fb.state.set(2);
                    fb.et.set(fb.pt.get());
                } else {
                    fb.et.set(fb.current_time.get().sub(fb.start_time.get()));
                }
            }
            fb.q.set(fb.in_.get() || fb.state.get() == 1);
            fb.prev_in.set(fb.in_.get());
        }
        fb.outputs()
    }
}

impl Tp {
    /// A new instance, as `TP_init__` leaves it.
    pub const fn new() -> Tp {
        Tp(TimerFb::INIT)
    }

    /// One call of matiec's `TP` with IN = `input`, PT = `pt_ms`, `__CURRENT_TIME` = `now_ms`;
    /// returns (Q, ET in ms). See the type's documentation for the differences from S7.
    #[inline(always)]
    pub fn call(&mut self, input: bool, pt_ms: i32, now_ms: u32) -> (bool, i32) {
        let fb = &mut self.0;
        fb.store_inputs(input, pt_ms);
        if fb.enabled() {
            fb.current_time.set(Time::from_ms(i64::from(now_ms)));
            if fb.state.get() == 0 && !fb.prev_in.get() && fb.in_.get() {
                fb.state.set(1);
                fb.q.set(true);
                fb.start_time.set(fb.current_time.get());
            } else if fb.state.get() == 1 {
                if fb.expired() {
                    fb.state.set(2);
                    fb.q.set(false);
                    fb.et.set(fb.pt.get());
                } else {
                    fb.et.set(fb.current_time.get().sub(fb.start_time.get()));
                }
            }
            if fb.state.get() == 2 && !fb.in_.get() {
                fb.et.set(Time::ZERO);
                fb.state.set(0);
            }
            fb.prev_in.set(fb.in_.get());
        }
        fb.outputs()
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

/// matiec's R_TRIG (`lib/edge_detection.txt`; compiled `R_TRIG_body__`), the edge detector the
/// counters hold as a nested block: Q := CLK AND NOT M; M := CLK.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
#[repr(C)]
struct RTrig {
    /// EN.
    en: Var<bool>,
    /// ENO.
    eno: Var<bool>,
    /// CLK.
    clk: Var<bool>,
    /// Q.
    q: Var<bool>,
    /// CLK on the previous call.
    m: Var<bool>,
}

impl RTrig {
    /// The state `R_TRIG_init__` gives.
    const INIT: RTrig = RTrig {
        en: Var::new(true),
        eno: Var::new(true),
        clk: Var::new(false),
        q: Var::new(false),
        m: Var::new(false),
    };

    /// `R_TRIG_body__`.
    #[inline(always)]
    fn body(&mut self) {
        if !self.en.get() {
            self.eno.set(false);
            return;
        }
        self.eno.set(true);
        self.q.set(self.clk.get() && !self.m.get());
        self.m.set(self.clk.get());
    }
}

/// matiec's CTU (`lib/counter.txt`, `FUNCTION_BLOCK CTU` for INT = `i16`, `CTU_DINT` for
/// `i32`, `CTU_LINT` for `i64`; compiled `CTU_body__`).
///
/// Per call: CU_T(CLK := CU) (the edge memory takes CU on every call); R = 1: CV := 0; else on
/// a rising CU with CV < PV: CV := CV + 1. Q := CV >= PV.
///
/// Differences from S7-1200:
/// - Counting stops at PV: CV never passes PV (S7 counts on to the type's maximum). With
///   PV <= 0 it never counts; if PV is lowered below CV, CV stays where it is.
/// - Hence no overflow is possible; there is no explicit saturation at the type's limit.
/// - Same as S7: R dominates; the edge memory is updated while R holds, so releasing R with CU
///   held does not count.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
#[repr(C)]
pub struct Ctu<T> {
    /// EN.
    en: Var<bool>,
    /// ENO.
    eno: Var<bool>,
    /// CU.
    cu: Var<bool>,
    /// R.
    r: Var<bool>,
    /// PV.
    pv: Var<T>,
    /// Q.
    q: Var<bool>,
    /// CV.
    cv: Var<T>,
    /// The nested edge detector on CU.
    cu_t: RTrig,
}

impl<T: PeerInt> Ctu<T> {
    /// A new instance, as `CTU_init__` leaves it.
    pub fn new() -> Ctu<T> {
        Ctu {
            en: Var::new(true),
            eno: Var::new(true),
            cu: Var::new(false),
            r: Var::new(false),
            pv: Var::new(T::ZERO),
            q: Var::new(false),
            cv: Var::new(T::ZERO),
            cu_t: RTrig::INIT,
        }
    }

    /// One call of matiec's `CTU` with CU = `cu`, R = `r`, PV = `pv`; returns (Q, CV).
    #[inline(always)]
    pub fn call(&mut self, cu: bool, r: bool, pv: T) -> (bool, T) {
        self.cu.set(cu);
        self.r.set(r);
        self.pv.set(pv);
        if !self.en.get() {
            self.eno.set(false);
        } else {
            self.eno.set(true);
            self.cu_t.clk.set(self.cu.get());
            self.cu_t.body();
            if self.r.get() {
                self.cv.set(T::ZERO);
            } else if self.cu_t.q.get() && self.cv.get() < self.pv.get() {
                self.cv.set(self.cv.get().plus_one());
            }
            self.q.set(self.cv.get() >= self.pv.get());
        }
        (self.q.get(), self.cv.get())
    }
}

impl<T: PeerInt> Default for Ctu<T> {
    fn default() -> Ctu<T> {
        Ctu::new()
    }
}

/// matiec's CTD (`lib/counter.txt`, `FUNCTION_BLOCK CTD` for INT = `i16`, `CTD_DINT` for
/// `i32`, `CTD_LINT` for `i64`; compiled `CTD_body__`).
///
/// Per call: CD_T(CLK := CD) (the edge memory takes CD on every call); LD = 1: CV := PV; else
/// on a rising CD with CV > 0: CV := CV - 1. Q := CV <= 0.
///
/// Differences from S7-1200:
/// - Counting stops at 0: CV never goes below 0 by counting (S7 counts on to the type's
///   minimum). A negative PV loaded by LD stays as it is.
/// - Same as S7: LD dominates; the edge memory is updated while LD holds.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
#[repr(C)]
pub struct Ctd<T> {
    /// EN.
    en: Var<bool>,
    /// ENO.
    eno: Var<bool>,
    /// CD.
    cd: Var<bool>,
    /// LD.
    ld: Var<bool>,
    /// PV.
    pv: Var<T>,
    /// Q.
    q: Var<bool>,
    /// CV.
    cv: Var<T>,
    /// The nested edge detector on CD.
    cd_t: RTrig,
}

impl<T: PeerInt> Ctd<T> {
    /// A new instance, as `CTD_init__` leaves it.
    pub fn new() -> Ctd<T> {
        Ctd {
            en: Var::new(true),
            eno: Var::new(true),
            cd: Var::new(false),
            ld: Var::new(false),
            pv: Var::new(T::ZERO),
            q: Var::new(false),
            cv: Var::new(T::ZERO),
            cd_t: RTrig::INIT,
        }
    }

    /// One call of matiec's `CTD` with CD = `cd`, LD = `ld`, PV = `pv`; returns (Q, CV).
    #[inline(always)]
    pub fn call(&mut self, cd: bool, ld: bool, pv: T) -> (bool, T) {
        self.cd.set(cd);
        self.ld.set(ld);
        self.pv.set(pv);
        if !self.en.get() {
            self.eno.set(false);
        } else {
            self.eno.set(true);
            self.cd_t.clk.set(self.cd.get());
            self.cd_t.body();
            if self.ld.get() {
                self.cv.set(self.pv.get());
            } else if self.cd_t.q.get() && self.cv.get() > T::ZERO {
                self.cv.set(self.cv.get().minus_one());
            }
            self.q.set(self.cv.get() <= T::ZERO);
        }
        (self.q.get(), self.cv.get())
    }
}

impl<T: PeerInt> Default for Ctd<T> {
    fn default() -> Ctd<T> {
        Ctd::new()
    }
}
