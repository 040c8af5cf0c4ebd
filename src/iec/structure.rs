//! The `IEC_TIMER` structure as a soft-PLC holds it: 16 bytes, `#[repr(C)]` (S7-1200 manual:
//! "each timer uses a 16-byte IEC_Timer structure"), with IN, Q, the running status and the last
//! instruction packed into one flag byte.

use super::{IecInput, IecKind, IecOutput, IecState, IecTimerOps};
use crate::time::clock::ClockWord;
use crate::time::{CpuTime, Time};

/// Flag bits of [`IecTimerOf::flags`].
mod flag {
    /// IN as the last call saw it.
    pub const IN: u8 = 0b0000_0001;
    /// Q.
    pub const Q: u8 = 0b0000_0010;
    /// Timing.
    pub const RUNNING: u8 = 0b0000_0100;
    /// Bits 4-5 hold the last instruction's kind; this bit says one has run.
    pub const KIND_VALID: u8 = 0b0100_0000;
    /// Shift of the kind field.
    pub const KIND_SHIFT: u8 = 4;
    /// Every bit in use.
    pub const ALL: u8 = IN | Q | RUNNING | KIND_VALID | (0b11 << KIND_SHIFT);

    // The five fields are disjoint (their sum is their union), so combining them with `|`, `^`
    // or `+` is the same and clearing one (`flags & !MASK`) keeps the others.
    const _: () = assert!(
        IN as u16 + Q as u16 + RUNNING as u16 + KIND_VALID as u16 + (0b11u16 << KIND_SHIFT)
            == ALL as u16
    );
}

/// Q while running, by kind code (TP, TON, TOF, TONR), as a mask of [`flag::Q`].
const Q_RUNNING: [u8; 4] = [flag::Q, 0, flag::Q, 0];
/// Q after expiry, by kind code.
const Q_EXPIRED: [u8; 4] = [0, flag::Q, 0, flag::Q];

const fn code(kind: IecKind) -> usize {
    kind as usize
}

const fn kind_of(code: u8) -> IecKind {
    match code & 0b11 {
        0 => IecKind::Tp,
        1 => IecKind::Ton,
        2 => IecKind::Tof,
        _ => IecKind::Tonr,
    }
}

/// The `IEC_TIMER` structure over a clock word `C`.
///
/// On the 32-bit clock ([`IecTimer`]) it is exactly 16 bytes: START, PT, ET (4 bytes each), one
/// flag byte, three bytes of padding. The fields are private: every structure this type holds is
/// one the operations can reach ([`IecTimerOf::from_state`] checks).
///
/// ```
/// use plc_timers::iec::{IecInput, IecKind, IecTimer, IecTimerOps};
/// use plc_timers::time::CpuTime;
///
/// // The self-resetting timer of the S7-1200 manual: reading Q through the structure updates it.
/// let pt = plc_timers::time!("T#1S");
/// let mut t = IecTimer::new();
/// t.call(IecKind::Ton, CpuTime::from_millis(0), IecInput::new(true, pt));
/// assert!(t.read_q(CpuTime::from_millis(1_000))); // the read itself finds the time run out
/// assert_eq!(core::mem::size_of::<IecTimer>(), 16);
/// ```
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
#[repr(C)]
pub struct IecTimerOf<C> {
    start: C,
    pt: C,
    et: C,
    flags: u8,
}

/// The S7-1200 `IEC_TIMER`: the structure on the 32-bit millisecond clock.
pub type IecTimer = IecTimerOf<u32>;

// The manual's size, checked at compile time.
const _: () = assert!(core::mem::size_of::<IecTimer>() == 16);

impl<C: ClockWord> IecTimerOf<C> {
    /// The initial structure (all zero).
    pub const fn new() -> IecTimerOf<C> {
        IecTimerOf {
            start: C::ZERO,
            pt: C::ZERO,
            et: C::ZERO,
            flags: 0,
        }
    }

    /// The structure holding `state`, or `None` if `state` violates [`IecState::is_valid`].
    /// The inverse of [`IecTimerOps::state`].
    pub fn from_state(state: IecState<C>) -> Option<IecTimerOf<C>> {
        if !state.is_valid() {
            return None;
        }
        let mut flags = 0;
        flags |= if state.input { flag::IN } else { 0 };
        flags |= if state.q { flag::Q } else { 0 };
        flags |= if state.running { flag::RUNNING } else { 0 };
        if let Some(kind) = state.kind {
            flags |= flag::KIND_VALID | (kind as u8) << flag::KIND_SHIFT;
        }
        Some(IecTimerOf {
            start: state.start,
            pt: state.pt,
            et: state.et,
            flags,
        })
    }

    /// The abstraction function: the reference state this structure represents (also
    /// [`IecTimerOps::state`]).
    fn abstraction(&self) -> IecState<C> {
        let f = self.flags;
        IecState {
            kind: (f & flag::KIND_VALID != 0).then(|| kind_of(f >> flag::KIND_SHIFT)),
            input: f & flag::IN != 0,
            running: f & flag::RUNNING != 0,
            start: self.start,
            pt: self.pt,
            et: self.et,
            q: f & flag::Q != 0,
        }
    }
}

impl IecTimer {
    /// The 16 bytes of the structure in its memory layout (native byte order): START, PT, ET,
    /// the flag byte, three zero bytes. For saving a retentive structure.
    ///
    /// ```
    /// use plc_timers::iec::{IecInput, IecKind, IecTimer, IecTimerOps};
    /// use plc_timers::time::CpuTime;
    /// let mut t = IecTimer::new();
    /// t.call(IecKind::Ton, CpuTime::from_millis(7), IecInput::new(true, plc_timers::time!("T#1S")));
    /// assert_eq!(IecTimer::from_bytes(t.to_bytes()), Some(t));
    /// ```
    pub fn to_bytes(&self) -> [u8; 16] {
        let mut b = [0u8; 16];
        b[0..4].copy_from_slice(&self.start.to_ne_bytes());
        b[4..8].copy_from_slice(&self.pt.to_ne_bytes());
        b[8..12].copy_from_slice(&self.et.to_ne_bytes());
        b[12] = self.flags;
        b
    }

    /// The structure saved in `bytes` by [`IecTimer::to_bytes`] (from retentive memory, or an
    /// area shared with another runtime), or `None` when the bytes are not a state the
    /// operations can reach: a flag bit outside IN, Q, RUNNING and the kind, ET above PT, a
    /// START kept by a stopped timer, or non-zero padding.
    ///
    /// ```
    /// use plc_timers::iec::IecTimer;
    /// let mut bytes = IecTimer::new().to_bytes();
    /// bytes[12] = 0x80; // a flag bit no operation sets
    /// assert!(IecTimer::from_bytes(bytes).is_none());
    /// ```
    pub fn from_bytes(bytes: [u8; 16]) -> Option<IecTimer> {
        let word =
            |i: usize| u32::from_ne_bytes([bytes[i], bytes[i + 1], bytes[i + 2], bytes[i + 3]]);
        let t = IecTimerOf {
            start: word(0),
            pt: word(4),
            et: word(8),
            flags: bytes[12],
        };
        let valid =
            bytes[13..] == [0, 0, 0] && t.flags & !flag::ALL == 0 && t.abstraction().is_valid();
        valid.then_some(t)
    }
}

impl<C: ClockWord> IecTimerOf<C> {
    /// The latched preset `PT` in milliseconds, as stored (no update).
    pub fn pt(&self) -> C {
        self.pt
    }

    /// `ET` (`ELAPSED`) as stored, without the update that [`IecTimerOps::read_et`] performs.
    pub fn et(&self) -> C {
        self.et
    }

    /// The update for instruction code `k`: one subtraction and one compare on the hot path.
    #[inline]
    fn update(&mut self, now: C, k: usize) {
        if self.flags & flag::RUNNING == 0 {
            return;
        }
        let elapsed = now.elapsed_since(self.start);
        if elapsed >= self.pt {
            self.et = self.pt;
            self.start = C::default();
            self.flags = (self.flags & !(flag::RUNNING | flag::Q)) | Q_EXPIRED[k];
        } else {
            self.et = elapsed;
            self.flags = (self.flags & !flag::Q) | Q_RUNNING[k];
        }
    }

    #[inline]
    fn stop_clear(&mut self) {
        self.start = C::default();
        self.et = C::default();
        self.flags &= !(flag::RUNNING | flag::Q);
    }
}

/// `a` if `c`, else `b`, by arithmetic on the bits (`b ^ ((a ^ b) & mask)`) rather than by
/// `if`, which LLVM may turn into a branch. Exact: the mask is all ones or 0, so the u64 is
/// `a.to_u64()` or `b.to_u64()`, a value below `2^BITS`, which `from_u64_wrapping` (the value
/// modulo `2^BITS`) gives back as the clock word it came from.
#[inline(always)]
fn blend<C: ClockWord>(c: bool, a: C, b: C) -> C {
    let (a, b) = (a.to_u64(), b.to_u64());
    C::from_u64_wrapping(b ^ ((a ^ b) & u64::from(c).wrapping_neg()))
}

impl<C: ClockWord> IecTimerOf<C> {
    /// The reference's `start` followed by its `update` at the same instant, in closed form:
    /// START = now, the preset latched (negative as 0), ET = 0; the update then finds
    /// `elapsed = 0`, which reaches PT exactly when PT = 0: then the timer has expired at once
    /// (ET = PT = 0, Q = `q_expired`, stopped, START = 0), else it runs (Q = `q_running`).
    /// `flags` holds the kind and IN bits of the call. The choice is made by selects (the
    /// preset of a program rarely changes, but the cost of a misprediction is not worth a
    /// branch here).
    #[inline(always)]
    fn begin(
        &mut self,
        now: C,
        pt: Time,
        flags: u8,
        q_running: bool,
        q_expired: bool,
    ) -> IecOutput<C> {
        let pt = C::from_preset(pt.clamp_negative());
        let runs = pt != C::ZERO;
        let q = if runs { q_running } else { q_expired };
        self.start = if runs { now } else { C::ZERO };
        self.pt = pt;
        self.et = C::ZERO;
        self.flags = flags | if runs { flag::RUNNING } else { 0 } | if q { flag::Q } else { 0 };
        IecOutput { q, et: C::ZERO }
    }

    /// The reference's `update` of a running timer (IEC-UPDATE-01): `elapsed = now - START`
    /// (modulo 2^BITS); at `elapsed >= PT` it has expired: ET = PT, Q = `q_expired`, stopped,
    /// START = 0; before, ET = elapsed and Q = `q_running`, still running. With `pause`, the
    /// timer then stops in either case (TONR with IN = 0: the reference's pause after the
    /// update), keeping ET and Q.
    #[inline(always)]
    fn advance(
        &mut self,
        now: C,
        flags: u8,
        q_running: bool,
        q_expired: bool,
        pause: bool,
    ) -> IecOutput<C> {
        let elapsed = now.elapsed_since(self.start);
        let reached = elapsed >= self.pt;
        let q = if reached { q_expired } else { q_running };
        let et = if reached { self.pt } else { elapsed };
        let runs = !reached & !pause;
        self.start = if runs { self.start } else { C::ZERO };
        self.et = et;
        self.flags = flags | if runs { flag::RUNNING } else { 0 } | if q { flag::Q } else { 0 };
        IecOutput { q, et }
    }

    /// Nothing but the call's kind and IN recorded: a stopped timer whose call changes no
    /// member (Q, ET, START = 0 and PT as they are).
    #[inline(always)]
    fn idle(&mut self, flags: u8) -> IecOutput<C> {
        let q = self.flags & flag::Q;
        self.flags = flags | q;
        IecOutput {
            q: q != 0,
            et: self.et,
        }
    }

    /// The reference's `reset_and_stop` with Q = `q`: stopped, START = ET = 0; PT kept.
    #[inline(always)]
    fn clear(&mut self, flags: u8, q: bool) -> IecOutput<C> {
        self.start = C::ZERO;
        self.et = C::ZERO;
        self.flags = flags | if q { flag::Q } else { 0 };
        IecOutput { q, et: C::ZERO }
    }
}

impl<C: ClockWord> IecTimerOps<C> for IecTimerOf<C> {
    /// One box call. TP, TOF and TONR: the reference's decisions, taken on the inputs and on
    /// the timer's state (the reference's functions are named below), and per path only the
    /// members that path changes are written; where the outcome depends on the time
    /// (expiry), selects instead of branches. TON: straight-line, see its arm. `kind` is a constant at every call site of a program, and the `match` on it
    /// disappears when the call is inlined. (An earlier version first tested for a quiet
    /// stopped timer and returned; that test cost more than it saved, and is gone: the quiet
    /// cases are now the `idle` paths, which write one byte.)
    ///
    /// Why each kind equals the reference ([`super::IecTimerRef`]): `begin` is
    /// its `start` + `update` at one instant, `advance` its `update` of a running
    /// timer, `clear` its `reset_and_stop`; a stopped timer's `update` changes
    /// nothing, which is `idle`. Every path records the kind and IN, as the
    /// reference does after every call. A stopped timer has START = 0 already
    /// ([`IecState::is_valid`], which every structure satisfies).
    #[inline]
    fn call(&mut self, kind: IecKind, now: CpuTime, input: IecInput) -> IecOutput<C> {
        let now = now.clock::<C>();
        let f = self.flags;
        let was_in = f & flag::IN != 0;
        let running = f & flag::RUNNING != 0;
        let on = input.input;
        let kind_bits = flag::KIND_VALID | (code(kind) as u8) << flag::KIND_SHIFT;
        let flags = kind_bits | if on { flag::IN } else { 0 };
        match kind {
            // TP: update; a rising IN with no pulse running starts one; stopped with IN = 0,
            // ET returns to 0. A pulse still running after the update ignores IN.
            IecKind::Tp => {
                let (q, et) = if running {
                    let elapsed = now.elapsed_since(self.start);
                    if elapsed < self.pt {
                        self.et = elapsed;
                        self.flags = flags | flag::RUNNING | flag::Q;
                        return IecOutput {
                            q: true,
                            et: elapsed,
                        };
                    }
                    // Expired on this update: ET = PT, Q = 0, stopped.
                    self.start = C::ZERO;
                    (false, self.pt)
                } else {
                    (f & flag::Q != 0, self.et)
                };
                if on & !was_in {
                    return self.begin(now, input.pt, flags, true, false);
                }
                let et = if on { et } else { C::ZERO };
                self.et = et;
                self.flags = flags | if q { flag::Q } else { 0 };
                IecOutput { q, et }
            }
            // TON: IN = 0 resets; a rising IN starts; else update. Written without a branch
            // on IN or on the timer's state (`blend` and bit arithmetic), because TON is the
            // timer of which a program has many: in an array of timers, IN and the state
            // differ from one timer to the next and a branch on them is mispredicted about
            // every other call. The reference's three cases are all computed: a rising IN
            // replaces START and PT (its `start`), the update follows on the running timer
            // (after a start it finds `elapsed = 0`, as the reference's), a stopped timer
            // keeps ET and Q, and IN = 0 then forces START = ET = 0, Q = 0, stopped (its
            // `reset_and_stop`; PT is unchanged on that path since a rise needs IN = 1).
            IecKind::Ton => {
                let rise = on & !was_in;
                let start = blend(rise, now, self.start);
                let pt = blend(rise, C::from_preset(input.pt.clamp_negative()), self.pt);
                let run = running | rise;
                let elapsed = now.elapsed_since(start);
                let reached = elapsed >= pt;
                let et = blend(run, blend(reached, pt, elapsed), self.et);
                let q = (run & reached) | (!run & (f & flag::Q != 0));
                let goes_on = run & !reached;
                self.start = blend(on & goes_on, start, C::ZERO);
                self.pt = pt;
                self.et = blend(on, et, C::ZERO);
                self.flags = flags | u8::from(on & q) << 1 | u8::from(on & goes_on) << 2;
                IecOutput {
                    q: on & q,
                    et: self.et,
                }
            }
            // TOF: IN = 1 resets with Q = 1; a falling IN starts; else update.
            IecKind::Tof => {
                if on {
                    self.clear(flags, true)
                } else if was_in {
                    self.begin(now, input.pt, flags, true, false)
                } else if running {
                    self.advance(now, flags, true, false, false)
                } else {
                    self.idle(flags)
                }
            }
            // TONR: R resets (PT kept); IN = 1 on a stopped timer that has not expired resumes
            // with START shifted back by the accumulated ET, so that the update's `now - START`
            // is the accumulated total (the reference's own arithmetic, modulo 2^BITS), and PT
            // latched; a running timer updates; with IN = 0 it pauses after the update.
            IecKind::Tonr => {
                if input.reset {
                    self.clear(flags, false)
                } else if running {
                    self.advance(now, flags, false, true, !on)
                } else if on & (f & flag::Q == 0) {
                    self.start = now.elapsed_since(self.et);
                    self.pt = C::from_preset(input.pt.clamp_negative());
                    self.advance(now, flags, false, true, false)
                } else {
                    self.idle(flags)
                }
            }
        }
    }

    #[inline]
    fn read_q(&mut self, now: CpuTime) -> bool {
        if self.flags & flag::KIND_VALID != 0 {
            self.update(
                now.clock(),
                usize::from((self.flags >> flag::KIND_SHIFT) & 0b11),
            );
        }
        self.flags & flag::Q != 0
    }

    #[inline]
    fn read_et(&mut self, now: CpuTime) -> C {
        if self.flags & flag::KIND_VALID != 0 {
            self.update(
                now.clock(),
                usize::from((self.flags >> flag::KIND_SHIFT) & 0b11),
            );
        }
        self.et
    }

    fn reset_timer(&mut self) {
        self.stop_clear();
        self.flags &= !flag::IN;
    }

    fn preset_timer(&mut self, pt: Time) {
        self.pt = C::from_preset(pt.clamp_negative());
        self.et = self.et.min(self.pt);
    }

    fn run_stop_run(&mut self, retentive: bool) {
        if !retentive {
            *self = IecTimerOf::new();
        }
    }

    fn state(&self) -> IecState<C> {
        self.abstraction()
    }
}
