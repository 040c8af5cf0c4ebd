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
    fn start(&mut self, now: C, pt: Time) {
        self.start = now;
        self.pt = C::from_preset(pt.clamp_negative());
        self.et = C::default();
        // Q is left to the `update` that follows every start: it sets Q from the kind and ET.
        self.flags |= flag::RUNNING;
    }

    #[inline]
    fn stop_clear(&mut self) {
        self.start = C::default();
        self.et = C::default();
        self.flags &= !(flag::RUNNING | flag::Q);
    }
}

impl<C: ClockWord> IecTimerOps<C> for IecTimerOf<C> {
    #[inline]
    fn call(&mut self, kind: IecKind, now: CpuTime, input: IecInput) -> IecOutput<C> {
        let now = now.clock::<C>();
        let k = code(kind);
        // Fast path: a stopped timer of the same kind whose IN did not change has nothing to do
        // when the call would leave every member as it is (checked by the equivalence proofs).
        let in_bit = if input.input { flag::IN } else { 0 };
        let same = flag::KIND_VALID | (k as u8) << flag::KIND_SHIFT | in_bit;
        if self.flags & !flag::Q == same {
            let zero = self.et == C::default();
            let q = self.flags & flag::Q != 0;
            let quiet = match kind {
                IecKind::Tp => input.input || zero,
                IecKind::Ton => input.input || (zero && !q),
                IecKind::Tof => !input.input || (zero && q),
                // TONR resumes on a level.
                IecKind::Tonr => false,
            };
            if quiet {
                return IecOutput { q, et: self.et };
            }
        }
        let was_in = self.flags & flag::IN != 0;
        let running = self.flags & flag::RUNNING != 0;
        match kind {
            IecKind::Tp => {
                self.update(now, k);
                if input.input && !was_in && self.flags & flag::RUNNING == 0 {
                    self.start(now, input.pt);
                    self.update(now, k);
                }
                if self.flags & flag::RUNNING == 0 && !input.input {
                    self.et = C::default();
                }
            }
            IecKind::Ton => {
                if !input.input {
                    self.stop_clear();
                } else {
                    if !was_in {
                        self.start(now, input.pt);
                    }
                    self.update(now, k);
                }
            }
            IecKind::Tof => {
                if input.input {
                    self.stop_clear();
                    self.flags |= flag::Q;
                } else {
                    if was_in {
                        self.start(now, input.pt);
                    }
                    self.update(now, k);
                }
            }
            IecKind::Tonr => {
                if input.reset {
                    self.stop_clear();
                } else if input.input {
                    if !running && self.flags & flag::Q == 0 {
                        let accumulated = self.et;
                        self.start(now, input.pt);
                        self.start = now.elapsed_since(accumulated);
                    }
                    self.update(now, k);
                } else if running {
                    self.update(now, k);
                    // Pause (a no-op if the update found the time elapsed: already stopped).
                    self.flags &= !flag::RUNNING;
                    self.start = C::default();
                }
            }
        }
        self.flags = (self.flags & (flag::Q | flag::RUNNING)) | same;
        IecOutput {
            q: self.flags & flag::Q != 0,
            et: self.et,
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
