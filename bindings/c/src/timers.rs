//! The timers: S5 timers (`S_PULSE` … `S_OFFDT`) and IEC timers (`TP`, `TON`, `TOF`, `TONR`)
//! on TIME (S7-1200 `IEC_TIMER`) and on LTIME (S7-1500 `IEC_LTIMER`), each in its reference
//! and its optimized form. The C functions are registered on the bodies of `export`.

use plc_timers::block::BlockOps;
use plc_timers::iec::{IecInput, IecKind, IecLTimer, IecOutput, IecState, IecTimer, IecTimerRef};
use plc_timers::s5::{S5Input, S5Kind, S5State, S5Timer, S5TimerRef, TimerWord};
use plc_timers::time::clock::ClockWord;
use plc_timers::time::{CpuTime, IecDuration, LTime, S5Time, Time, TimeBase};

use crate::export::{export, CIecTimer, CInput, CKind};
use crate::status::plc_timers_status::{self, *};
use crate::{bit, flag, Mirror};

// ---------------------------------------------------------------------------------------------
// Kinds and inputs

/// The S5 timer kinds (LAD box names; STL `SP`, `SE`, `SD`, `SS`, `SF`). Passed as `int32_t`.
#[repr(i32)]
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum plc_timers_s5_kind {
    /// `S_PULSE`, STL `SP` (German `SI`): pulse.
    PLC_TIMERS_S_PULSE = 0,
    /// `S_PEXT`, STL `SE` (German `SV`): extended pulse.
    PLC_TIMERS_S_PEXT = 1,
    /// `S_ODT`, STL `SD` (German `SE`): on-delay.
    PLC_TIMERS_S_ODT = 2,
    /// `S_ODTS`, STL `SS`: retentive on-delay.
    PLC_TIMERS_S_ODTS = 3,
    /// `S_OFFDT`, STL `SF` (German `SA`): off-delay.
    PLC_TIMERS_S_OFFDT = 4,
}

/// The IEC timer instructions. Passed as `int32_t`.
#[repr(i32)]
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum plc_timers_iec_kind {
    /// `TP`, pulse.
    PLC_TIMERS_TP = 0,
    /// `TON`, on-delay.
    PLC_TIMERS_TON = 1,
    /// `TOF`, off-delay.
    PLC_TIMERS_TOF = 2,
    /// `TONR`, retentive on-delay (time accumulator).
    PLC_TIMERS_TONR = 3,
}

/// The S5 time bases, as in bits 13-12 of an S5TIME word. Passed as `int32_t`.
#[repr(i32)]
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum plc_timers_time_base {
    /// 10 ms.
    PLC_TIMERS_BASE_10MS = 0,
    /// 100 ms.
    PLC_TIMERS_BASE_100MS = 1,
    /// 1 s.
    PLC_TIMERS_BASE_1S = 2,
    /// 10 s.
    PLC_TIMERS_BASE_10S = 3,
}

/// The S5 timer kind `kind` stands for.
pub(crate) fn s5_kind(kind: i32) -> Result<S5Kind, plc_timers_status> {
    Ok(match kind {
        0 => S5Kind::SPulse,
        1 => S5Kind::SPext,
        2 => S5Kind::SOdt,
        3 => S5Kind::SOdts,
        4 => S5Kind::SOffdt,
        _ => return Err(PLC_TIMERS_INVALID_KIND),
    })
}

impl CKind for S5Kind {
    fn from_c(kind: i32) -> Result<S5Kind, plc_timers_status> {
        s5_kind(kind)
    }
}

/// The IEC timer kind `kind` stands for.
fn iec_kind(kind: i32) -> Result<IecKind, plc_timers_status> {
    Ok(match kind {
        0 => IecKind::Tp,
        1 => IecKind::Ton,
        2 => IecKind::Tof,
        3 => IecKind::Tonr,
        _ => return Err(PLC_TIMERS_INVALID_KIND),
    })
}

impl CKind for IecKind {
    fn from_c(kind: i32) -> Result<IecKind, plc_timers_status> {
        iec_kind(kind)
    }
}

/// The time base `base` stands for.
pub(crate) fn time_base(base: i32) -> Result<TimeBase, plc_timers_status> {
    Ok(match base {
        0 => TimeBase::Ms10,
        1 => TimeBase::Ms100,
        2 => TimeBase::S1,
        3 => TimeBase::S10,
        _ => return Err(PLC_TIMERS_INVALID_TIME_BASE),
    })
}

/// The S5TIME of word `tv`.
pub(crate) fn s5time(tv: u16) -> Result<S5Time, plc_timers_status> {
    S5Time::from_word(tv).map_err(|_| PLC_TIMERS_INVALID_S5TIME)
}

/// The inputs of one execution of an S5 timer box. The input bits are bytes, as a runtime's
/// process image holds them: 0 is FALSE, any other value TRUE.
#[repr(C)]
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct plc_timers_s5_input {
    /// `S`, the start input (0 FALSE, any other byte TRUE).
    pub s: u8,
    /// `R`, the reset input (0 FALSE, any other byte TRUE).
    pub r: u8,
    /// `FR`, the enable input (STL `FR T n`; the LAD boxes have none: 0).
    pub fr: u8,
    /// `TV`, the time value as an S5TIME word (`W#16#wxyz`: BCD value in bits 11-0, time base in
    /// bits 13-12, bits 15-14 ignored), e.g. from `plc_timers_s5time_parse`.
    pub tv: u16,
}

impl CInput<S5Input> for plc_timers_s5_input {
    fn load(self) -> Result<S5Input, plc_timers_status> {
        Ok(S5Input::new(bit(self.s), bit(self.r), s5time(self.tv)?).with_fr(bit(self.fr)))
    }
}

/// The outputs of one execution of an S5 timer.
#[repr(C)]
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct plc_timers_s5_output {
    /// `Q`, the timer status.
    pub q: bool,
    /// `BI` (`DUAL`): the remaining value in units of the time base, binary, 0 to 999.
    pub bi: u16,
    /// `BCD` (`DEZ`): the remaining value as three BCD digits, the time base in bits 13-12.
    pub bcd: u16,
}

impl From<plc_timers::s5::S5Output> for plc_timers_s5_output {
    fn from(o: plc_timers::s5::S5Output) -> Self {
        plc_timers_s5_output {
            q: o.q,
            bi: o.bi,
            bcd: o.bcd,
        }
    }
}

/// The inputs of one call of an IEC timer. The input bits are bytes: 0 is FALSE, any other
/// value TRUE.
#[repr(C)]
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct plc_timers_iec_input {
    /// `IN` (0 FALSE, any other byte TRUE).
    pub r#in: u8,
    /// `R`, the reset of `TONR` (ignored by `TP`, `TON`, `TOF`; 0 FALSE, any other byte TRUE).
    pub r: u8,
    /// `PT`, the preset: a `TIME` in milliseconds; a negative value is taken as 0.
    pub pt: i32,
}

impl CInput<IecInput<Time>> for plc_timers_iec_input {
    fn load(self) -> Result<IecInput<Time>, plc_timers_status> {
        Ok(IecInput::new(bit(self.r#in), Time::from_millis(self.pt)).with_reset(bit(self.r)))
    }
}

/// The outputs of one call of an IEC timer.
#[repr(C)]
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct plc_timers_iec_output {
    /// `Q`.
    pub q: bool,
    /// `ET`, the elapsed time in milliseconds, 0 to PT.
    pub et: u32,
}

impl From<IecOutput<u32>> for plc_timers_iec_output {
    fn from(o: IecOutput<u32>) -> Self {
        plc_timers_iec_output { q: o.q, et: o.et }
    }
}

/// The inputs of one call of an IEC timer on LTIME (`TP_LTIME`, `TON_LTIME`, `TOF_LTIME`,
/// `TONR_LTIME`). The input bits are bytes: 0 is FALSE, any other value TRUE.
#[repr(C)]
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct plc_timers_iec_ltime_input {
    /// `IN` (0 FALSE, any other byte TRUE).
    pub r#in: u8,
    /// `R`, the reset of `TONR` (ignored by `TP`, `TON`, `TOF`; 0 FALSE, any other byte TRUE).
    pub r: u8,
    /// `PT`, the preset: an `LTIME` in nanoseconds; a negative value is taken as 0.
    pub pt_ns: i64,
}

impl CInput<IecInput<LTime>> for plc_timers_iec_ltime_input {
    fn load(self) -> Result<IecInput<LTime>, plc_timers_status> {
        Ok(IecInput::new(bit(self.r#in), LTime::from_nanos(self.pt_ns)).with_reset(bit(self.r)))
    }
}

/// The outputs of one call of an IEC timer on LTIME.
#[repr(C)]
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct plc_timers_iec_ltime_output {
    /// `Q`.
    pub q: bool,
    /// `ET`, the elapsed time in nanoseconds, 0 to PT.
    pub et_ns: u64,
}

impl From<IecOutput<u64>> for plc_timers_iec_ltime_output {
    fn from(o: IecOutput<u64>) -> Self {
        plc_timers_iec_ltime_output {
            q: o.q,
            et_ns: o.et,
        }
    }
}

// ---------------------------------------------------------------------------------------------
// S5 timers

/// The state of one S5 timer for the reference semantics (`plc_timers_s5_timer_ref_*`): the
/// timer as the manual describes it, field by field. 16 bytes, alignment 8; all zero is a
/// cleared timer whose previous call was at 0 ms.
#[repr(C)]
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct plc_timers_s5_timer_ref {
    /// The latest CPU time a call saw, in ms (the previous call's unless the clock went back):
    /// the OS ticks after it and up to the next call are applied before that call.
    pub last_call_ms: u64,
    /// The remaining value in units of `base`, 0 to 999.
    pub value: u16,
    /// The time base of the running or last value (`plc_timers_time_base`, 0 to 3).
    pub base: u8,
    /// 1 while the time runs (the OS decrements it), else 0.
    pub running: u8,
    /// `Q`, the timer status, 0 or 1.
    pub q: u8,
    /// The status the timer takes when its time runs out: 1 after an on-delay start, else 0;
    /// 0 when stopped.
    pub q_on_expiry: u8,
    /// `S` at the previous call (the edge memory of the start), 0 or 1.
    pub s_prev: u8,
    /// `FR` at the previous call (the edge memory of the enable), 0 or 1.
    pub fr_prev: u8,
}

impl Mirror for plc_timers_s5_timer_ref {
    type Core = S5TimerRef;

    fn load(&self) -> Option<S5TimerRef> {
        let base = time_base(i32::from(self.base)).ok()?;
        let state = S5State {
            running: flag(self.running)?,
            value: self.value,
            base,
            q: flag(self.q)?,
            q_on_expiry: flag(self.q_on_expiry)?,
            s_prev: flag(self.s_prev)?,
            fr_prev: flag(self.fr_prev)?,
        };
        S5TimerRef::from_state(state, CpuTime::from_millis(self.last_call_ms))
    }

    fn store(t: &S5TimerRef) -> Self {
        let s = t.state();
        plc_timers_s5_timer_ref {
            last_call_ms: t.last_call().as_millis(),
            value: s.value,
            base: s.base.bits(),
            running: s.running.into(),
            q: s.q.into(),
            q_on_expiry: s.q_on_expiry.into(),
            s_prev: s.s_prev.into(),
            fr_prev: s.fr_prev.into(),
        }
    }
}

/// The state of one S5 timer for the optimized implementation (`plc_timers_s5_timer_*`): the
/// timer word and the time of the previous call. 16 bytes, alignment 8; all zero is a cleared
/// timer whose previous call was at 0 ms.
#[repr(C)]
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct plc_timers_s5_timer {
    /// The latest CPU time a call saw, in ms (the previous call's unless the clock went back).
    pub last_call_ms: u64,
    /// The timer word: bits 9-0 the remaining value (binary, 0 to 999), bits 13-12 the time
    /// base, bit 16 running, bit 17 Q, bit 18 the status on expiry, bit 19 the S edge memory,
    /// bit 20 the FR edge memory; the other bits 0.
    pub word: u32,
    /// Zero (it makes the struct's padding explicit, so that every byte of it is defined).
    pub reserved: u32,
}

impl Mirror for plc_timers_s5_timer {
    type Core = S5Timer;

    fn load(&self) -> Option<S5Timer> {
        if self.reserved != 0 {
            return None;
        }
        let word = TimerWord::from_bits(self.word)?;
        S5Timer::from_state(word.state(), CpuTime::from_millis(self.last_call_ms))
    }

    fn store(t: &S5Timer) -> Self {
        plc_timers_s5_timer {
            last_call_ms: t.last_call().as_millis(),
            word: t.word().bits(),
            reserved: 0,
        }
    }
}

export!(
    /// Initializes an S5 timer (reference form): cleared, previous call at 0 ms (the same as
    /// zeroing the struct).
    init plc_timers_s5_timer_ref_init(timer: plc_timers_s5_timer_ref)
);
export!(
    /// Initializes an S5 timer (optimized form): cleared, previous call at 0 ms (the same as
    /// zeroing the struct).
    init plc_timers_s5_timer_init(timer: plc_timers_s5_timer)
);
export!(
    /// One execution of the S5 timer box `kind` (`plc_timers_s5_kind`) at CPU time `now_ms`, by
    /// the reference semantics: the OS ticks of the timer's base since its previous call are
    /// applied (ticks fall on whole multiples of the base in `now_ms`), then `FR`, the start logic
    /// of the kind and `R`. `now_ms` must not go back: an earlier time applies no tick and
    /// `last_call_ms` keeps the latest time (rule S5TMR-CLOCK-01), as the timer memory area's
    /// clock does. The outputs are written to `out`.
    ///
    /// Returns `PLC_TIMERS_OK`; `PLC_TIMERS_NULL_POINTER` / `PLC_TIMERS_MISALIGNED_POINTER`
    /// (`timer` or `out`); `PLC_TIMERS_INVALID_KIND`; `PLC_TIMERS_INVALID_S5TIME` (`input.tv`);
    /// `PLC_TIMERS_INVALID_STATE` (`*timer`).
    call plc_timers_s5_timer_ref_call(timer: plc_timers_s5_timer_ref, kind, now_ms, input: plc_timers_s5_input, out: plc_timers_s5_output)
);
export!(
    /// One execution of the S5 timer box `kind` at CPU time `now_ms`, by the optimized
    /// implementation: the same as `plc_timers_s5_timer_ref_call` on the packed timer word.
    ///
    /// Returns `PLC_TIMERS_OK`; `PLC_TIMERS_NULL_POINTER` / `PLC_TIMERS_MISALIGNED_POINTER`
    /// (`timer` or `out`); `PLC_TIMERS_INVALID_KIND`; `PLC_TIMERS_INVALID_S5TIME` (`input.tv`);
    /// `PLC_TIMERS_INVALID_STATE` (`*timer`).
    call plc_timers_s5_timer_call(timer: plc_timers_s5_timer, kind, now_ms, input: plc_timers_s5_input, out: plc_timers_s5_output)
);

// ---------------------------------------------------------------------------------------------
// IEC timers

/// The state of one IEC timer for the reference semantics (`plc_timers_iec_timer_ref_*`): the
/// structure's members as the manual names them. 16 bytes, alignment 4; all zero is the initial
/// structure.
#[repr(C)]
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct plc_timers_iec_timer_ref {
    /// `START`: the 32-bit CPU clock (ms) when timing began; 0 when not running.
    pub start: u32,
    /// `PT` as latched at the start (or loaded by the PT coil), in ms.
    pub pt: u32,
    /// `ET` (`ELAPSED`), in ms, at most `pt`.
    pub et: u32,
    /// The instruction that last ran on the structure: 0 none yet, else 1 + its
    /// `plc_timers_iec_kind` (1 TP, 2 TON, 3 TOF, 4 TONR).
    pub kind: u8,
    /// `IN` as the last call saw it (the edge memory), 0 or 1.
    pub r#in: u8,
    /// 1 while timing, else 0.
    pub running: u8,
    /// `Q`, 0 or 1.
    pub q: u8,
}

/// The flag bytes of a reference IEC timer struct (`kind` as 0 for none or 1 + the kind, `in`,
/// `running`, `q`).
type RefFlags = [u8; 4];

/// The reference IEC timer with the members `start`, `pt`, `et` and `flags` of a C struct, or
/// `None` when they are not a state it can be in.
fn iec_ref_load<C: ClockWord, D: IecDuration>(
    [start, pt, et]: [C; 3],
    [kind, input, running, q]: RefFlags,
) -> Option<IecTimerRef<C, D>> {
    let kind = match kind {
        0 => None,
        k => Some(iec_kind(i32::from(k).checked_sub(1)?).ok()?),
    };
    IecTimerRef::from_state(IecState {
        kind,
        input: flag(input)?,
        running: flag(running)?,
        start,
        pt,
        et,
        q: flag(q)?,
    })
}

/// The members of a C struct for the reference IEC timer `t` (the inverse of `iec_ref_load`).
fn iec_ref_store<C: ClockWord, D: IecDuration>(t: &IecTimerRef<C, D>) -> ([C; 3], RefFlags) {
    let s = t.state();
    let kind = match s.kind {
        None => 0,
        Some(IecKind::Tp) => 1,
        Some(IecKind::Ton) => 2,
        Some(IecKind::Tof) => 3,
        Some(IecKind::Tonr) => 4,
    };
    (
        [s.start, s.pt, s.et],
        [kind, s.input.into(), s.running.into(), s.q.into()],
    )
}

impl Mirror for plc_timers_iec_timer_ref {
    type Core = IecTimerRef<u32>;

    fn load(&self) -> Option<IecTimerRef<u32>> {
        iec_ref_load(
            [self.start, self.pt, self.et],
            [self.kind, self.r#in, self.running, self.q],
        )
    }

    fn store(t: &IecTimerRef<u32>) -> Self {
        let ([start, pt, et], [kind, r#in, running, q]) = iec_ref_store(t);
        plc_timers_iec_timer_ref {
            start,
            pt,
            et,
            kind,
            r#in,
            running,
            q,
        }
    }
}

/// The S7-1200 `IEC_TIMER` structure, 16 bytes, alignment 4, for the optimized implementation
/// (`plc_timers_iec_timer_*`): the layout of the library's `IecTimer`. All zero is the initial
/// structure.
#[repr(C)]
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct plc_timers_iec_timer {
    /// `START`: the 32-bit CPU clock (ms) when timing began; 0 when not running.
    pub start: u32,
    /// `PT` as latched, in ms.
    pub pt: u32,
    /// `ET` (`ELAPSED`), in ms, at most `pt`.
    pub et: u32,
    /// Bit 0 `IN` of the last call, bit 1 `Q`, bit 2 running, bits 5-4 the last instruction
    /// (`plc_timers_iec_kind`) and bit 6 set once one has run; the other bits 0.
    pub flags: u8,
    /// Zero.
    pub reserved: [u8; 3],
}

// The manual's 16 bytes, the same as the library's structure.
const _: () = assert!(core::mem::size_of::<plc_timers_iec_timer>() == 16);
const _: () = assert!(core::mem::size_of::<IecTimer>() == 16);
const _: () = assert!(core::mem::size_of::<plc_timers_iec_timer_ref>() == 16);
const _: () = assert!(core::mem::size_of::<plc_timers_s5_timer_ref>() == 16);
const _: () = assert!(core::mem::size_of::<plc_timers_s5_timer>() == 16);

impl Mirror for plc_timers_iec_timer {
    type Core = IecTimer;

    /// Through the library's checked `IecTimer::from_bytes`, whose byte layout (START, PT, ET
    /// in native byte order, the flag byte, three zero bytes) is this struct's.
    fn load(&self) -> Option<IecTimer> {
        let [s0, s1, s2, s3] = self.start.to_ne_bytes();
        let [p0, p1, p2, p3] = self.pt.to_ne_bytes();
        let [e0, e1, e2, e3] = self.et.to_ne_bytes();
        let [r0, r1, r2] = self.reserved;
        IecTimer::from_bytes([
            s0, s1, s2, s3, p0, p1, p2, p3, e0, e1, e2, e3, self.flags, r0, r1, r2,
        ])
    }

    fn store(t: &IecTimer) -> Self {
        let [s0, s1, s2, s3, p0, p1, p2, p3, e0, e1, e2, e3, flags, r0, r1, r2] = t.to_bytes();
        plc_timers_iec_timer {
            start: u32::from_ne_bytes([s0, s1, s2, s3]),
            pt: u32::from_ne_bytes([p0, p1, p2, p3]),
            et: u32::from_ne_bytes([e0, e1, e2, e3]),
            flags,
            reserved: [r0, r1, r2],
        }
    }
}

/// The state of one IEC timer on LTIME for the reference semantics
/// (`plc_timers_iec_ltimer_ref_*`): the structure's members as the manual names them. 32 bytes,
/// alignment 8; all zero is the initial structure.
#[repr(C)]
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct plc_timers_iec_ltimer_ref {
    /// `START`: the 64-bit CPU clock (ns) when timing began; 0 when not running.
    pub start: u64,
    /// `PT` as latched at the start (or loaded by the PT coil), in ns.
    pub pt: u64,
    /// `ET` (`ELAPSED`), in ns, at most `pt`.
    pub et: u64,
    /// The instruction that last ran on the structure: 0 none yet, else 1 + its
    /// `plc_timers_iec_kind` (1 TP, 2 TON, 3 TOF, 4 TONR).
    pub kind: u8,
    /// `IN` as the last call saw it (the edge memory), 0 or 1.
    pub r#in: u8,
    /// 1 while timing, else 0.
    pub running: u8,
    /// `Q`, 0 or 1.
    pub q: u8,
    /// Zero (the padding to 32 bytes, explicit so that every byte is defined).
    pub reserved: [u8; 4],
}

impl Mirror for plc_timers_iec_ltimer_ref {
    type Core = IecTimerRef<u64, LTime>;

    fn load(&self) -> Option<IecTimerRef<u64, LTime>> {
        if self.reserved != [0; 4] {
            return None;
        }
        iec_ref_load(
            [self.start, self.pt, self.et],
            [self.kind, self.r#in, self.running, self.q],
        )
    }

    fn store(t: &IecTimerRef<u64, LTime>) -> Self {
        let ([start, pt, et], [kind, r#in, running, q]) = iec_ref_store(t);
        plc_timers_iec_ltimer_ref {
            start,
            pt,
            et,
            kind,
            r#in,
            running,
            q,
            reserved: [0; 4],
        }
    }
}

/// The S7-1500 `IEC_LTIMER` structure, 32 bytes, alignment 8, for the optimized implementation
/// (`plc_timers_iec_ltimer_*`): the layout of the library's `IecLTimer`. All zero is the
/// initial structure.
#[repr(C)]
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct plc_timers_iec_ltimer {
    /// `START`: the 64-bit CPU clock (ns) when timing began; 0 when not running.
    pub start: u64,
    /// `PT` as latched, in ns.
    pub pt: u64,
    /// `ET` (`ELAPSED`), in ns, at most `pt`.
    pub et: u64,
    /// Bit 0 `IN` of the last call, bit 1 `Q`, bit 2 running, bits 5-4 the last instruction
    /// (`plc_timers_iec_kind`) and bit 6 set once one has run; the other bits 0.
    pub flags: u8,
    /// Zero.
    pub reserved: [u8; 7],
}

// The library's 32 bytes (IEC_LTIMER), the same as this struct's.
const _: () = assert!(core::mem::size_of::<plc_timers_iec_ltimer>() == 32);
const _: () = assert!(core::mem::size_of::<IecLTimer>() == 32);
const _: () = assert!(core::mem::size_of::<plc_timers_iec_ltimer_ref>() == 32);

impl Mirror for plc_timers_iec_ltimer {
    type Core = IecLTimer;

    /// Through the library's checked `IecLTimer::from_bytes`, whose byte layout (START, PT, ET
    /// in native byte order, the flag byte, seven zero bytes) is this struct's.
    fn load(&self) -> Option<IecLTimer> {
        let [r0, r1, r2, r3, r4, r5, r6] = self.reserved;
        let words = [
            self.start.to_ne_bytes(),
            self.pt.to_ne_bytes(),
            self.et.to_ne_bytes(),
            [self.flags, r0, r1, r2, r3, r4, r5, r6],
        ];
        let mut bytes = [0u8; 32];
        for (chunk, word) in bytes.chunks_exact_mut(8).zip(words) {
            chunk.copy_from_slice(&word);
        }
        IecLTimer::from_bytes(bytes)
    }

    fn store(t: &IecLTimer) -> Self {
        let bytes = t.to_bytes();
        let mut words = bytes.chunks_exact(8).map(|chunk| {
            let mut word = [0u8; 8];
            word.copy_from_slice(chunk);
            word
        });
        // Four chunks of 8 in 32 bytes: the default is never taken.
        let [start, pt, et, [flags, r0, r1, r2, r3, r4, r5, r6]] =
            [(); 4].map(|()| words.next().unwrap_or_default());
        plc_timers_iec_ltimer {
            start: u64::from_ne_bytes(start),
            pt: u64::from_ne_bytes(pt),
            et: u64::from_ne_bytes(et),
            flags,
            reserved: [r0, r1, r2, r3, r4, r5, r6],
        }
    }
}

impl CIecTimer for plc_timers_iec_timer_ref {
    type Clock = u32;
    type Duration = Time;
    type Preset = i32;
    fn preset(pt_ms: i32) -> Time {
        Time::from_millis(pt_ms)
    }
}

impl CIecTimer for plc_timers_iec_timer {
    type Clock = u32;
    type Duration = Time;
    type Preset = i32;
    fn preset(pt_ms: i32) -> Time {
        Time::from_millis(pt_ms)
    }
}

impl CIecTimer for plc_timers_iec_ltimer_ref {
    type Clock = u64;
    type Duration = LTime;
    type Preset = i64;
    fn preset(pt_ns: i64) -> LTime {
        LTime::from_nanos(pt_ns)
    }
}

impl CIecTimer for plc_timers_iec_ltimer {
    type Clock = u64;
    type Duration = LTime;
    type Preset = i64;
    fn preset(pt_ns: i64) -> LTime {
        LTime::from_nanos(pt_ns)
    }
}

// ---------------------------------------------------------------------------------------------
// The IEC timers on TIME (IEC_TIMER): the calls and the structure operations (reading through
// the structure, the RT and PT coils, RUN-STOP-RUN), each form

export!(
    /// Initializes an IEC timer (reference form) to the initial structure (the same as zeroing it).
    init plc_timers_iec_timer_ref_init(timer: plc_timers_iec_timer_ref)
);
export!(
    /// Initializes an `IEC_TIMER` (optimized form) to the initial structure (the same as zeroing
    /// it).
    init plc_timers_iec_timer_init(timer: plc_timers_iec_timer)
);
export!(
    /// One call of the IEC timer instruction `kind` (`plc_timers_iec_kind`) at CPU time `now_ms`,
    /// by the reference semantics. The timer sees the low 32 bits of `now_ms` (the S7-1200
    /// millisecond clock, which wraps); `PT` is latched on the starting edge. The outputs `Q` and
    /// `ET` (ms) are written to `out`.
    ///
    /// Returns `PLC_TIMERS_OK`; `PLC_TIMERS_NULL_POINTER` / `PLC_TIMERS_MISALIGNED_POINTER`
    /// (`timer` or `out`); `PLC_TIMERS_INVALID_KIND`; `PLC_TIMERS_INVALID_STATE` (`*timer`).
    call plc_timers_iec_timer_ref_call(timer: plc_timers_iec_timer_ref, kind, now_ms, input: plc_timers_iec_input, out: plc_timers_iec_output)
);
export!(
    /// One call of the IEC timer instruction `kind` at CPU time `now_ms` on an `IEC_TIMER`, by the
    /// optimized implementation: the same as `plc_timers_iec_timer_ref_call`.
    ///
    /// Returns `PLC_TIMERS_OK`; `PLC_TIMERS_NULL_POINTER` / `PLC_TIMERS_MISALIGNED_POINTER`
    /// (`timer` or `out`); `PLC_TIMERS_INVALID_KIND`; `PLC_TIMERS_INVALID_STATE` (`*timer`).
    call plc_timers_iec_timer_call(timer: plc_timers_iec_timer, kind, now_ms, input: plc_timers_iec_input, out: plc_timers_iec_output)
);
export!(
    /// Reads `Q` through the structure at CPU time `now_ms` (reference form): as on the CPU, the
    /// update of the instruction that last ran on it happens first (the self-resetting timer of
    /// the S7-1200 manual). Writes `Q` to `q`.
    ///
    /// Returns `PLC_TIMERS_OK`; `PLC_TIMERS_NULL_POINTER` / `PLC_TIMERS_MISALIGNED_POINTER`
    /// (`timer` or `q`); `PLC_TIMERS_INVALID_STATE`.
    read_q plc_timers_iec_timer_ref_read_q(timer: plc_timers_iec_timer_ref, now_ms, q: bool)
);
export!(
    /// Reads `ET` (ms) through the structure at CPU time `now_ms` (reference form), the update
    /// first as in `plc_timers_iec_timer_ref_read_q`. Writes `ET` to `et`.
    ///
    /// Returns `PLC_TIMERS_OK`; `PLC_TIMERS_NULL_POINTER` / `PLC_TIMERS_MISALIGNED_POINTER`
    /// (`timer` or `et`); `PLC_TIMERS_INVALID_STATE`.
    read_et plc_timers_iec_timer_ref_read_et(timer: plc_timers_iec_timer_ref, now_ms, et: u32)
);
export!(
    /// The `-(RT)-` coil with power flow (reference form): stops the timer and clears ET, Q and
    /// the stored IN; the preset stays.
    ///
    /// Returns `PLC_TIMERS_OK`; `PLC_TIMERS_NULL_POINTER` / `PLC_TIMERS_MISALIGNED_POINTER`;
    /// `PLC_TIMERS_INVALID_STATE`.
    reset plc_timers_iec_timer_ref_reset(timer: plc_timers_iec_timer_ref)
);
export!(
    /// The `-(PT)-` coil with power flow (reference form): loads `pt_ms` (a `TIME` in ms;
    /// negative taken as 0) into the structure's preset; a running timer uses it from its next
    /// update.
    ///
    /// Returns `PLC_TIMERS_OK`; `PLC_TIMERS_NULL_POINTER` / `PLC_TIMERS_MISALIGNED_POINTER`;
    /// `PLC_TIMERS_INVALID_STATE`.
    preset plc_timers_iec_timer_ref_preset(timer: plc_timers_iec_timer_ref, pt_ms: i32)
);
export!(
    /// A RUN-STOP-RUN transition (reference form): a non-retentive structure (`retentive` 0)
    /// returns to its initial values; a retentive one keeps its data.
    ///
    /// Returns `PLC_TIMERS_OK`; `PLC_TIMERS_NULL_POINTER` / `PLC_TIMERS_MISALIGNED_POINTER`;
    /// `PLC_TIMERS_INVALID_STATE`.
    run_stop_run plc_timers_iec_timer_ref_run_stop_run(timer: plc_timers_iec_timer_ref, retentive: u8)
);
export!(
    /// Reads `Q` through the structure at CPU time `now_ms` (optimized form): as on the CPU, the
    /// update of the instruction that last ran on it happens first (the self-resetting timer of
    /// the S7-1200 manual). Writes `Q` to `q`.
    ///
    /// Returns `PLC_TIMERS_OK`; `PLC_TIMERS_NULL_POINTER` / `PLC_TIMERS_MISALIGNED_POINTER`
    /// (`timer` or `q`); `PLC_TIMERS_INVALID_STATE`.
    read_q plc_timers_iec_timer_read_q(timer: plc_timers_iec_timer, now_ms, q: bool)
);
export!(
    /// Reads `ET` (ms) through the structure at CPU time `now_ms` (optimized form), the update
    /// first as in `plc_timers_iec_timer_read_q`. Writes `ET` to `et`.
    ///
    /// Returns `PLC_TIMERS_OK`; `PLC_TIMERS_NULL_POINTER` / `PLC_TIMERS_MISALIGNED_POINTER`
    /// (`timer` or `et`); `PLC_TIMERS_INVALID_STATE`.
    read_et plc_timers_iec_timer_read_et(timer: plc_timers_iec_timer, now_ms, et: u32)
);
export!(
    /// The `-(RT)-` coil with power flow (optimized form): stops the timer and clears ET, Q and
    /// the stored IN; the preset stays.
    ///
    /// Returns `PLC_TIMERS_OK`; `PLC_TIMERS_NULL_POINTER` / `PLC_TIMERS_MISALIGNED_POINTER`;
    /// `PLC_TIMERS_INVALID_STATE`.
    reset plc_timers_iec_timer_reset(timer: plc_timers_iec_timer)
);
export!(
    /// The `-(PT)-` coil with power flow (optimized form): loads `pt_ms` (a `TIME` in ms;
    /// negative taken as 0) into the structure's preset; a running timer uses it from its next
    /// update.
    ///
    /// Returns `PLC_TIMERS_OK`; `PLC_TIMERS_NULL_POINTER` / `PLC_TIMERS_MISALIGNED_POINTER`;
    /// `PLC_TIMERS_INVALID_STATE`.
    preset plc_timers_iec_timer_preset(timer: plc_timers_iec_timer, pt_ms: i32)
);
export!(
    /// A RUN-STOP-RUN transition (optimized form): a non-retentive structure (`retentive` 0)
    /// returns to its initial values; a retentive one keeps its data.
    ///
    /// Returns `PLC_TIMERS_OK`; `PLC_TIMERS_NULL_POINTER` / `PLC_TIMERS_MISALIGNED_POINTER`;
    /// `PLC_TIMERS_INVALID_STATE`.
    run_stop_run plc_timers_iec_timer_run_stop_run(timer: plc_timers_iec_timer, retentive: u8)
);

// ---------------------------------------------------------------------------------------------
// The IEC timers on LTIME (S7-1500 IEC_LTIMER; TP_LTIME, TON_LTIME, TOF_LTIME, TONR_LTIME):
// the same bodies, the clock and the durations in nanoseconds

export!(
    /// Initializes an IEC timer on LTIME (reference form) to the initial structure (the same as
    /// zeroing it).
    init plc_timers_iec_ltimer_ref_init(timer: plc_timers_iec_ltimer_ref)
);
export!(
    /// Initializes an `IEC_LTIMER` (optimized form) to the initial structure (the same as
    /// zeroing it).
    init plc_timers_iec_ltimer_init(timer: plc_timers_iec_ltimer)
);
export!(
    /// One call of the IEC timer instruction `kind` (`plc_timers_iec_kind`) on LTIME at CPU time
    /// `now_ns` (nanoseconds since the CPU started, the S7-1500's 64-bit clock), by the
    /// reference semantics; `PT` (`input.pt_ns`) is latched on the starting edge. The outputs
    /// `Q` and `ET` (ns) are written to `out`.
    ///
    /// Returns `PLC_TIMERS_OK`; `PLC_TIMERS_NULL_POINTER` / `PLC_TIMERS_MISALIGNED_POINTER`
    /// (`timer` or `out`); `PLC_TIMERS_INVALID_KIND`; `PLC_TIMERS_INVALID_STATE` (`*timer`).
    call plc_timers_iec_ltimer_ref_call(timer: plc_timers_iec_ltimer_ref, kind, now_ns, input: plc_timers_iec_ltime_input, out: plc_timers_iec_ltime_output)
);
export!(
    /// One call of the IEC timer instruction `kind` on LTIME at CPU time `now_ns` on an
    /// `IEC_LTIMER`, by the optimized implementation: the same as
    /// `plc_timers_iec_ltimer_ref_call`.
    ///
    /// Returns `PLC_TIMERS_OK`; `PLC_TIMERS_NULL_POINTER` / `PLC_TIMERS_MISALIGNED_POINTER`
    /// (`timer` or `out`); `PLC_TIMERS_INVALID_KIND`; `PLC_TIMERS_INVALID_STATE` (`*timer`).
    call plc_timers_iec_ltimer_call(timer: plc_timers_iec_ltimer, kind, now_ns, input: plc_timers_iec_ltime_input, out: plc_timers_iec_ltime_output)
);
export!(
    /// Reads `Q` through the structure at CPU time `now_ns` (reference form, LTIME), the update
    /// of the instruction that last ran on it first. Writes `Q` to `q`.
    ///
    /// Returns `PLC_TIMERS_OK`; `PLC_TIMERS_NULL_POINTER` / `PLC_TIMERS_MISALIGNED_POINTER`
    /// (`timer` or `q`); `PLC_TIMERS_INVALID_STATE`.
    read_q plc_timers_iec_ltimer_ref_read_q(timer: plc_timers_iec_ltimer_ref, now_ns, q: bool)
);
export!(
    /// Reads `ET` (ns) through the structure at CPU time `now_ns` (reference form, LTIME), the
    /// update first. Writes `ET` to `et_ns`.
    ///
    /// Returns `PLC_TIMERS_OK`; `PLC_TIMERS_NULL_POINTER` / `PLC_TIMERS_MISALIGNED_POINTER`
    /// (`timer` or `et_ns`); `PLC_TIMERS_INVALID_STATE`.
    read_et plc_timers_iec_ltimer_ref_read_et(timer: plc_timers_iec_ltimer_ref, now_ns, et_ns: u64)
);
export!(
    /// The `-(RT)-` coil with power flow (reference form, LTIME): stops the timer and clears ET,
    /// Q and the stored IN; the preset stays.
    ///
    /// Returns `PLC_TIMERS_OK`; `PLC_TIMERS_NULL_POINTER` / `PLC_TIMERS_MISALIGNED_POINTER`;
    /// `PLC_TIMERS_INVALID_STATE`.
    reset plc_timers_iec_ltimer_ref_reset(timer: plc_timers_iec_ltimer_ref)
);
export!(
    /// The `-(PT)-` coil with power flow (reference form, LTIME): loads `pt_ns` (an `LTIME` in
    /// ns; negative taken as 0) into the structure's preset; a running timer uses it from its
    /// next update.
    ///
    /// Returns `PLC_TIMERS_OK`; `PLC_TIMERS_NULL_POINTER` / `PLC_TIMERS_MISALIGNED_POINTER`;
    /// `PLC_TIMERS_INVALID_STATE`.
    preset plc_timers_iec_ltimer_ref_preset(timer: plc_timers_iec_ltimer_ref, pt_ns: i64)
);
export!(
    /// A RUN-STOP-RUN transition (reference form, LTIME): a non-retentive structure
    /// (`retentive` 0) returns to its initial values; a retentive one keeps its data.
    ///
    /// Returns `PLC_TIMERS_OK`; `PLC_TIMERS_NULL_POINTER` / `PLC_TIMERS_MISALIGNED_POINTER`;
    /// `PLC_TIMERS_INVALID_STATE`.
    run_stop_run plc_timers_iec_ltimer_ref_run_stop_run(timer: plc_timers_iec_ltimer_ref, retentive: u8)
);
export!(
    /// Reads `Q` through the `IEC_LTIMER` at CPU time `now_ns` (optimized form), the update of
    /// the instruction that last ran on it first. Writes `Q` to `q`.
    ///
    /// Returns `PLC_TIMERS_OK`; `PLC_TIMERS_NULL_POINTER` / `PLC_TIMERS_MISALIGNED_POINTER`
    /// (`timer` or `q`); `PLC_TIMERS_INVALID_STATE`.
    read_q plc_timers_iec_ltimer_read_q(timer: plc_timers_iec_ltimer, now_ns, q: bool)
);
export!(
    /// Reads `ET` (ns) through the `IEC_LTIMER` at CPU time `now_ns` (optimized form), the
    /// update first. Writes `ET` to `et_ns`.
    ///
    /// Returns `PLC_TIMERS_OK`; `PLC_TIMERS_NULL_POINTER` / `PLC_TIMERS_MISALIGNED_POINTER`
    /// (`timer` or `et_ns`); `PLC_TIMERS_INVALID_STATE`.
    read_et plc_timers_iec_ltimer_read_et(timer: plc_timers_iec_ltimer, now_ns, et_ns: u64)
);
export!(
    /// The `-(RT)-` coil with power flow on an `IEC_LTIMER` (optimized form): stops the timer and
    /// clears ET, Q and the stored IN; the preset stays.
    ///
    /// Returns `PLC_TIMERS_OK`; `PLC_TIMERS_NULL_POINTER` / `PLC_TIMERS_MISALIGNED_POINTER`;
    /// `PLC_TIMERS_INVALID_STATE`.
    reset plc_timers_iec_ltimer_reset(timer: plc_timers_iec_ltimer)
);
export!(
    /// The `-(PT)-` coil with power flow on an `IEC_LTIMER` (optimized form): loads `pt_ns` (an
    /// `LTIME` in ns; negative taken as 0) into the structure's preset; a running timer uses it
    /// from its next update.
    ///
    /// Returns `PLC_TIMERS_OK`; `PLC_TIMERS_NULL_POINTER` / `PLC_TIMERS_MISALIGNED_POINTER`;
    /// `PLC_TIMERS_INVALID_STATE`.
    preset plc_timers_iec_ltimer_preset(timer: plc_timers_iec_ltimer, pt_ns: i64)
);
export!(
    /// A RUN-STOP-RUN transition on an `IEC_LTIMER` (optimized form): a non-retentive structure
    /// (`retentive` 0) returns to its initial values; a retentive one keeps its data.
    ///
    /// Returns `PLC_TIMERS_OK`; `PLC_TIMERS_NULL_POINTER` / `PLC_TIMERS_MISALIGNED_POINTER`;
    /// `PLC_TIMERS_INVALID_STATE`.
    run_stop_run plc_timers_iec_ltimer_run_stop_run(timer: plc_timers_iec_ltimer, retentive: u8)
);
