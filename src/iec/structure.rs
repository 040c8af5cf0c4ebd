//! The `IEC_TIMER` structure as a soft-PLC holds it: 16 bytes, `#[repr(C)]` (S7-1200 manual:
//! "each timer uses a 16-byte IEC_Timer structure"), with IN, Q, the running status and the last
//! instruction packed into one flag byte, followed by three zero bytes.

use super::{IecInput, IecKind, IecOutput, IecState, IecTimerOps};
use crate::time::clock::ClockWord;
use core::marker::PhantomData;

use crate::time::{CpuTime, IecDuration, LTime, Time};

/// Flag bits of the flag byte ([`IecTimerOf::flags`]).
///
/// The byte is stored as a byte (a single step writes one byte), and every operation on the
/// flags is 32 bits wide: byte-wide arithmetic writes part of a register, and on AMD Zen the
/// result then waits for that register's previous value, which chained each call of a single
/// step to the previous call (measured: see `IecTimerOps::call` for [`IecTimerOf`]).
/// [`IecTimerOf::ton_array`] reads and writes the flag byte with the three zero bytes after it as
/// one 32-bit word: four whole words per timer move in and out of vector registers with
/// word shuffles, where a lone byte took one insert and one extract per timer.
mod flag {
    /// IN as the last call saw it.
    pub const IN: u32 = 0b0000_0001;
    /// Q.
    pub const Q: u32 = 0b0000_0010;
    /// Timing.
    pub const RUNNING: u32 = 0b0000_0100;
    /// Bits 4-5 hold the last instruction's kind; this bit says one has run.
    pub const KIND_VALID: u32 = 0b0100_0000;
    /// Shift of the kind field.
    pub const KIND_SHIFT: u32 = 4;
    /// Every bit in use.
    pub const ALL: u32 = IN | Q | RUNNING | KIND_VALID | (0b11 << KIND_SHIFT);

    // The five fields are disjoint (their sum is their union), so combining them with `|`, `^`
    // or `+` is the same and clearing one (`flags & !MASK`) keeps the others.
    const _: () = assert!(IN + Q + RUNNING + KIND_VALID + (0b11 << KIND_SHIFT) == ALL);
    // The flag byte: every bit below 2^8.
    const _: () = assert!(ALL < 0x100);
}

const Q_RUNNING: [u32; 4] = [flag::Q, 0, flag::Q, 0];
/// Q after expiry, by kind code.
const Q_EXPIRED: [u32; 4] = [0, flag::Q, 0, flag::Q];

const fn code(kind: IecKind) -> usize {
    kind as usize
}

const fn kind_of(code: u32) -> IecKind {
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
/// flag byte and three bytes that stay 0. The fields are private: every structure this type
/// holds is one the operations can reach ([`IecTimerOf::from_state`] checks).
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
pub struct IecTimerOf<C = u32, D = Time> {
    start: C,
    pt: C,
    et: C,
    /// The flags (`flag`), below 2^8.
    flag_byte: u8,
    /// Always 0: with the flag byte, the structure's last 32-bit word, which
    /// [`IecTimerOf::ton_array`] moves whole.
    zero: [u8; 3],
    /// The data type of PT and ET (`TIME` or `LTIME`): their unit, in the type only.
    unit: PhantomData<D>,
}

impl<C: ClockWord, D: IecDuration> IecTimerOf<C, D> {
    /// The flags, in a 32-bit word for the arithmetic (see `flag`).
    #[inline(always)]
    fn flags(&self) -> u32 {
        u32::from(self.flag_byte)
    }

    /// Stores `flags` (below 2^8: `flag::ALL`) in the flag byte: a single step writes one byte.
    #[inline(always)]
    fn set_flags(&mut self, flags: u32) {
        self.flag_byte = flags as u8;
    }

    /// The structure's last word, the flag byte and the three zero bytes (the flags, as the
    /// zero bytes are 0): read as one 32-bit word, so that [`IecTimerOf::ton_array`] moves four
    /// whole words per timer.
    #[inline(always)]
    fn flag_word(&self) -> u32 {
        let [a, b, c] = self.zero;
        u32::from_le_bytes([self.flag_byte, a, b, c])
    }

    /// The structure with these members, `flags` below 2^8, written as four whole words.
    #[inline(always)]
    fn from_words(start: C, pt: C, et: C, flags: u32) -> IecTimerOf<C, D> {
        let [flag_byte, a, b, c] = flags.to_le_bytes();
        IecTimerOf {
            start,
            pt,
            et,
            flag_byte,
            zero: [a, b, c],
            unit: PhantomData,
        }
    }
}

/// The S7-1200 `IEC_TIMER`: the structure on the 32-bit millisecond clock.
///
/// ```
/// use plc_timers::iec::{IecInput, IecKind, IecTimer, IecTimerOps};
/// use plc_timers::time::CpuTime;
/// let mut t = IecTimer::new();
/// // The 32-bit clock wraps: a TON started 100 ms before the wrap runs out 400 ms after it.
/// let start = CpuTime::from_millis(u64::from(u32::MAX) - 99);
/// let pt = plc_timers::time!("T#500MS");
/// t.call(IecKind::Ton, start, IecInput::new(true, pt));
/// assert!(t.call(IecKind::Ton, start.add_millis(500), IecInput::new(true, pt)).q);
/// ```
pub type IecTimer = IecTimerOf<u32>;

// The manual's size, checked at compile time.
const _: () = assert!(core::mem::size_of::<IecTimer>() == 16);

/// The S7-1500 `IEC_LTIMER`: the same structure on the 64-bit nanosecond clock, `PT` and `ET`
/// of data type `LTIME` (the instance types `TP_LTIME`, `TON_LTIME`, `TOF_LTIME`,
/// `TONR_LTIME`): START, PT, ET (8 bytes each), the flag byte, padding to 32 bytes
/// (LTIMER-STRUCT-01).
///
/// ```
/// use plc_timers::iec::{IecInput, IecKind, IecLTimer, IecTimerOps};
/// use plc_timers::time::CpuTime;
/// let pt = plc_timers::ltime!("LT#1MS_500US");
/// let mut t = IecLTimer::new();
/// t.call(IecKind::Ton, CpuTime::from_nanos(0), IecInput::new(true, pt));
/// let out = t.call(IecKind::Ton, CpuTime::from_nanos(1_500_000), IecInput::new(true, pt));
/// assert_eq!((out.q, out.et), (true, 1_500_000));
/// assert_eq!(core::mem::size_of::<IecLTimer>(), 32);
/// ```
pub type IecLTimer = IecTimerOf<u64, LTime>;

const _: () = assert!(core::mem::size_of::<IecLTimer>() == 32);

impl<C: ClockWord, D: IecDuration> IecTimerOf<C, D> {
    /// The initial structure (all zero).
    ///
    /// ```
    /// use plc_timers::iec::{IecTimerOf, IecTimerOps};
    /// const T: IecTimerOf<u32> = IecTimerOf::new();
    /// assert_eq!(T.state(), Default::default());
    /// ```
    pub const fn new() -> IecTimerOf<C, D> {
        IecTimerOf {
            start: C::ZERO,
            pt: C::ZERO,
            et: C::ZERO,
            flag_byte: 0,
            zero: [0; 3],
            unit: PhantomData,
        }
    }

    /// The structure holding `state`, or `None` if `state` violates [`IecState::is_valid`].
    /// The inverse of [`IecTimerOps::state`].
    ///
    /// ```
    /// use plc_timers::iec::{IecKind, IecState, IecTimer, IecTimerOps};
    /// let expired = IecState::<u32> { kind: Some(IecKind::Ton), input: true, pt: 50, et: 50, q: true, ..Default::default() };
    /// assert_eq!(IecTimer::from_state(expired).map(|t| t.state()), Some(expired));
    /// assert!(IecTimer::from_state(IecState { start: 3, ..expired }).is_none()); // START kept while stopped
    /// ```
    pub fn from_state(state: IecState<C>) -> Option<IecTimerOf<C, D>> {
        if !state.is_valid() {
            return None;
        }
        let mut flags = 0;
        flags |= if state.input { flag::IN } else { 0 };
        flags |= if state.q { flag::Q } else { 0 };
        flags |= if state.running { flag::RUNNING } else { 0 };
        if let Some(kind) = state.kind {
            flags |= flag::KIND_VALID | (kind as u32) << flag::KIND_SHIFT;
        }
        Some(IecTimerOf::from_words(
            state.start,
            state.pt,
            state.et,
            flags,
        ))
    }

    /// The abstraction function: the reference state this structure represents (also
    /// [`IecTimerOps::state`]).
    fn abstraction(&self) -> IecState<C> {
        let f = self.flags();
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
        b[12] = self.flag_byte;
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
            flag_byte: bytes[12],
            zero: [bytes[13], bytes[14], bytes[15]],
            unit: PhantomData,
        };
        t.checked()
    }
}

impl<C: ClockWord, D: IecDuration> IecTimerOf<C, D> {
    /// `self` if it is a state the operations can reach (the check of `from_bytes`): no flag
    /// bit outside IN, Q, RUNNING and the kind, ET at most PT, no START kept by a stopped
    /// timer, zero padding.
    fn checked(self) -> Option<IecTimerOf<C, D>> {
        let valid = self.zero == [0, 0, 0]
            && self.flags() & !flag::ALL == 0
            && self.abstraction().is_valid();
        valid.then_some(self)
    }
}

impl IecLTimer {
    /// The 32 bytes of the structure in its memory layout (native byte order): START, PT, ET
    /// (8 bytes each), the flag byte, seven zero bytes (three zero members and the padding to
    /// the 8-byte alignment). For saving a retentive structure.
    ///
    /// ```
    /// use plc_timers::iec::{IecInput, IecKind, IecLTimer, IecTimerOps};
    /// use plc_timers::time::CpuTime;
    /// let mut t = IecLTimer::new();
    /// t.call(IecKind::Ton, CpuTime::from_nanos(7), IecInput::new(true, plc_timers::ltime!("LT#1S")));
    /// assert_eq!(IecLTimer::from_bytes(t.to_bytes()), Some(t));
    /// ```
    pub fn to_bytes(&self) -> [u8; 32] {
        let mut b = [0u8; 32];
        b[0..8].copy_from_slice(&self.start.to_ne_bytes());
        b[8..16].copy_from_slice(&self.pt.to_ne_bytes());
        b[16..24].copy_from_slice(&self.et.to_ne_bytes());
        b[24] = self.flag_byte;
        b
    }

    /// The structure saved in `bytes` by [`IecLTimer::to_bytes`], or `None` when the bytes are
    /// not a state the operations can reach (as [`IecTimer::from_bytes`]; the padding too must
    /// be 0).
    ///
    /// ```
    /// use plc_timers::iec::IecLTimer;
    /// let mut bytes = IecLTimer::new().to_bytes();
    /// bytes[31] = 1; // padding
    /// assert!(IecLTimer::from_bytes(bytes).is_none());
    /// ```
    pub fn from_bytes(bytes: [u8; 32]) -> Option<IecLTimer> {
        let word = |i: usize| {
            let mut w = [0u8; 8];
            w.copy_from_slice(&bytes[i..i + 8]);
            u64::from_ne_bytes(w)
        };
        if bytes[28..32] != [0, 0, 0, 0] {
            return None;
        }
        IecTimerOf {
            start: word(0),
            pt: word(8),
            et: word(16),
            flag_byte: bytes[24],
            zero: [bytes[25], bytes[26], bytes[27]],
            unit: PhantomData,
        }
        .checked()
    }
}

impl<C: ClockWord, D: IecDuration> IecTimerOf<C, D> {
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
        if self.flags() & flag::RUNNING == 0 {
            return;
        }
        let elapsed = now.elapsed_since(self.start);
        if reached(elapsed, self.pt) {
            self.et = self.pt;
            self.start = C::default();
            self.set_flags((self.flags() & !(flag::RUNNING | flag::Q)) | Q_EXPIRED[k]);
        } else {
            self.et = elapsed;
            self.set_flags((self.flags() & !flag::Q) | Q_RUNNING[k]);
        }
    }

    /// The update of a read through the structure (IEC-ACCESS-01), as the instruction of the
    /// last call (none before the first call).
    #[inline]
    fn update_on_read(&mut self, now: C) {
        if self.flags() & flag::KIND_VALID != 0 {
            // The kind field has two bits: an index below 4.
            self.update(now, ((self.flags() >> flag::KIND_SHIFT) & 0b11) as usize);
        }
    }

    #[inline]
    fn stop_clear(&mut self) {
        self.start = C::default();
        self.et = C::default();
        self.set_flags(self.flags() & !(flag::RUNNING | flag::Q));
    }
}

/// `mask` where `on`, else 0: a flag bit.
#[inline(always)]
fn bit(on: bool, mask: u32) -> u32 {
    u32::from(on) * mask
}

impl<C: ClockWord, D: IecDuration> IecTimerOf<C, D> {
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
        pt: D,
        flags: u32,
        q_running: bool,
        q_expired: bool,
    ) -> IecOutput<C> {
        let pt = C::from_preset(pt.units());
        let runs = !reached(C::ZERO, pt);
        let q = if runs { q_running } else { q_expired };
        self.start = if runs { now } else { C::ZERO };
        self.pt = pt;
        self.et = C::ZERO;
        self.set_flags(flags | bit(runs, flag::RUNNING) | bit(q, flag::Q));
        IecOutput { q, et: C::ZERO }
    }

    /// The reference's `update` of a running timer (IEC-UPDATE-01): `elapsed = now - START`
    /// (modulo 2^BITS); at `elapsed >= PT` it has expired: ET = PT, Q = `q_expired`, stopped,
    /// START = 0; before, ET = elapsed and Q = `q_running`, still running.
    #[inline(always)]
    fn advance(&mut self, now: C, flags: u32, q_running: bool, q_expired: bool) -> IecOutput<C> {
        let elapsed = now.elapsed_since(self.start);
        let expired = reached(elapsed, self.pt);
        let q = if expired { q_expired } else { q_running };
        let et = if expired { self.pt } else { elapsed };
        self.start = if expired { C::ZERO } else { self.start };
        self.et = et;
        self.set_flags(flags | bit(!expired, flag::RUNNING) | bit(q, flag::Q));
        IecOutput { q, et }
    }

    /// Nothing but the call's kind and IN recorded: a stopped timer whose call changes no
    /// member (Q, ET, START = 0 and PT as they are).
    #[inline(always)]
    fn idle(&mut self, flags: u32) -> IecOutput<C> {
        let q = self.flags() & flag::Q;
        self.set_flags(flags | q);
        IecOutput {
            q: q != 0,
            et: self.et,
        }
    }

    /// The reference's `reset_and_stop` with Q = `q`: stopped, START = ET = 0; PT kept.
    #[inline(always)]
    fn clear(&mut self, flags: u32, q: bool) -> IecOutput<C> {
        self.start = C::ZERO;
        self.et = C::ZERO;
        self.set_flags(flags | bit(q, flag::Q));
        IecOutput { q, et: C::ZERO }
    }
}

// `ton_for_arrays` computes the flag bits by arithmetic on these values.
const _: () = assert!(flag::IN == 1 && flag::Q == 2 && flag::RUNNING == 4);

/// Marks the path that calls it as rarely taken, so that the compiler lays out the other as the
/// straight line (`core::hint::cold_path`, stable only after this crate's MSRV, 1.88).
#[cold]
fn cold_path() {}

/// IEC-EXPIRY-01: the time has run out when the elapsed time reaches PT. Every update of this
/// module compares through here.
#[inline(always)]
fn reached<C: ClockWord>(elapsed: C, pt: C) -> bool {
    elapsed >= pt
}

/// `c` where `mask` is all ones, 0 where it is 0 (an `and` instead of a conditional move, which
/// needs a register holding 0). The mask is sign-extended to 64 bits: zero-extended, it would
/// clear the upper half of a 64-bit clock word (the `LTIME` clock).
#[inline(always)]
fn masked<C: ClockWord>(c: C, mask: u32) -> C {
    C::from_u64_wrapping(c.to_u64() & i64::from(mask as i32) as u64)
}

impl<C: ClockWord, D: IecDuration> IecTimerOf<C, D> {
    /// The call `call(IecKind::Ton, now, input)` for a loop over an array of timers: no branch
    /// on IN, on its rising edge or on the timer's state, which differ from one timer to the
    /// next in such a loop (a branch on them is mispredicted about as often as they change:
    /// the rising edge, once a branch, cost as much as the rest of the call on random
    /// inputs). Same outputs and same
    /// structure afterwards as [`IecTimerOps::call`] (`proofs/iec.rs` compares it with the
    /// reference on every structure and operation of a 4-bit clock). `call` is faster for a
    /// timer called once per scan, whose branches go the same way scan after scan.
    ///
    /// Why it equals the reference's `ton`: a rise is `begin`, the reference's `start` and
    /// `update` at one instant (see there), which is the update of a running timer with START
    /// = now and the new PT (elapsed = 0: reached exactly when PT = 0), so a rise selects
    /// those two and goes through the update below. Then both remaining cases are computed and
    /// selected: a running timer updates (`elapsed = now - START` modulo 2^BITS; reached at
    /// `elapsed >= PT`: ET = PT, Q = 1, stopped, START = 0; before: ET = elapsed, Q = 0, still
    /// running), a stopped one keeps ET and Q (its START is 0 already, [`IecState::is_valid`]);
    /// then IN = 0 forces START = ET = 0, Q = 0, stopped (the reference's `reset_and_stop`; PT
    /// is kept on both paths). `select_unpredictable` keeps each choice a conditional move,
    /// which the compiler would otherwise be free to turn back into a branch (it did, in a
    /// loop over an array, when this was written with `if`). Q and RUNNING are computed as
    /// the bits they are in the flags: a running timer's go to 4 (still running) or 2
    /// (expired, Q = 1), which is `2 + 2 * not_reached`.
    #[inline]
    pub fn ton_for_arrays(&mut self, now: CpuTime<D::Unit>, input: IecInput<D>) -> IecOutput<C> {
        let now = now.clock::<C>();
        let lane = ton_lane(
            Lane {
                start: self.start,
                pt: self.pt,
                et: self.et,
                flags: self.flags(),
            },
            now,
            input.input,
            input.pt,
        );
        *self = IecTimerOf::from_words(lane.start, lane.pt, lane.et, lane.flags);
        IecOutput {
            q: lane.flags & flag::Q != 0,
            et: lane.et,
        }
    }

    /// Every TON of an array called once at `now`, timer `i` with `IN` = `input[i]` and `PT` =
    /// `pt[i]`, its outputs written to `q[i]` and `et[i]`: the loop
    /// `for i in 0..N { timers[i].ton_for_arrays(now, IecInput::new(input[i], pt[i])) }` (what
    /// a PLC program's `FOR` loop over an `ARRAY OF IEC_TIMER` called as TON does), in one
    /// pass that the compiler vectorizes over the structures in their own layout, for the
    /// widest vector extension this CPU has with the feature `simd-dispatch`. Same structures
    /// and outputs afterwards as that loop, and as the reference called once per timer
    /// (`proofs/iec.rs`).
    ///
    /// Called one structure at a time, a timer cannot cost less than moving its inputs in and
    /// its outputs out (the per-instance floor of `benches/peers`); a loop the library owns
    /// can process several timers per instruction.
    ///
    /// ```
    /// use plc_timers::iec::IecTimer;
    /// use plc_timers::time::{CpuTime, Time};
    /// let mut timers = [IecTimer::new(); 2];
    /// let pt = [Time::from_millis(100); 2];
    /// let (mut q, mut et) = ([false; 2], [0; 2]);
    /// for ms in [0, 60, 120] {
    ///     IecTimer::ton_array(&mut timers, CpuTime::from_millis(ms), &[true, false], &pt, &mut q, &mut et);
    /// }
    /// assert_eq!((q, et), ([true, false], [100, 0]));
    /// ```
    pub fn ton_array<const N: usize>(
        timers: &mut [IecTimerOf<C, D>; N],
        now: CpuTime<D::Unit>,
        input: &[bool; N],
        pt: &[D; N],
        q: &mut [bool; N],
        et: &mut [C; N],
    ) {
        crate::simd::run(TonArray {
            timers,
            now: now.clock::<C>(),
            input,
            pt,
            q,
            et,
        });
    }
}

/// The members of one structure, in and out of [`ton_lane`].
#[derive(Clone, Copy)]
struct Lane<C> {
    start: C,
    pt: C,
    et: C,
    flags: u32,
}

/// One TON call without a branch: the structure after the call at clock `now` with IN = `on`
/// and PT = `pt_in` (its Q is the Q flag, its ET the output ET). The lane of
/// [`IecTimerOf::ton_for_arrays`] and [`IecTimerOf::ton_array`]; why it equals the reference
/// is said at the first.
#[inline(always)]
fn ton_lane<C: ClockWord, D: IecDuration>(timer: Lane<C>, now: C, on: bool, pt_in: D) -> Lane<C> {
    use core::hint::select_unpredictable as select;
    let kind_bits = flag::KIND_VALID | (code(IecKind::Ton) as u32) << flag::KIND_SHIFT;
    let f = timer.flags;
    let on = u32::from(on);
    // A rise is taken as a running timer with START = now and the new PT, whose update
    // then finds elapsed = 0 (see above): selected, not branched to.
    let rise = on & !f & flag::IN != 0;
    let start = select(rise, now, timer.start);
    let pt = select(rise, C::from_preset(pt_in.units()), timer.pt);
    let run = rise | (f & flag::RUNNING != 0);
    let elapsed = now.elapsed_since(start);
    let not_reached = !reached(elapsed, pt);
    let et = select(run, select(not_reached, elapsed, pt), timer.et);
    // Q (bit 1) and RUNNING (bit 2) after the update: a running timer is either still
    // running (4) or has expired with Q = 1 (2); a stopped one keeps its Q.
    let status = select(run, 2 + 2 * u32::from(not_reached), f & flag::Q);
    // IN = 0 clears everything but PT.
    let on_mask = on.wrapping_neg();
    let status = (flag::IN | status) & on_mask;
    Lane {
        start: masked(start, (status >> 2).wrapping_neg()),
        pt,
        et: masked(et, on_mask),
        flags: kind_bits | status,
    }
}

/// [`IecTimerOf::ton_array`] as a loop for [`crate::simd::run`].
struct TonArray<'a, C, D, const N: usize> {
    timers: &'a mut [IecTimerOf<C, D>; N],
    now: C,
    input: &'a [bool; N],
    pt: &'a [D; N],
    q: &'a mut [bool; N],
    et: &'a mut [C; N],
}

impl<C: ClockWord, D: IecDuration, const N: usize> crate::simd::Kernel for TonArray<'_, C, D, N> {
    #[inline(always)]
    fn run(self) {
        let TonArray {
            timers,
            now,
            input,
            pt,
            q,
            et,
        } = self;
        ton_array_lanes(timers, now, input, pt, q, et);
    }
}

/// Timers per group of [`IecTimerOf::ton_array`].
const LANES: usize = 16;

/// The loop of [`IecTimerOf::ton_array`]: the timers in groups of [`LANES`], the last
/// `N % LANES` through the same code on a padded copy (the padding timers are new ones with
/// IN = 0, whose results are dropped), so that every timer takes the one path.
#[inline(always)]
fn ton_array_lanes<C: ClockWord, D: IecDuration, const N: usize>(
    timers: &mut [IecTimerOf<C, D>; N],
    now: C,
    input: &[bool; N],
    pt: &[D; N],
    q: &mut [bool; N],
    et: &mut [C; N],
) {
    let (timers, timers_tail) = timers.as_chunks_mut::<LANES>();
    let (inputs, inputs_tail) = input.as_chunks::<LANES>();
    let (presets, presets_tail) = pt.as_chunks::<LANES>();
    let (qs, q_tail) = q.as_chunks_mut::<LANES>();
    let (ets, et_tail) = et.as_chunks_mut::<LANES>();
    let groups = timers
        .iter_mut()
        .zip(inputs.iter().zip(presets))
        .zip(qs.iter_mut().zip(ets.iter_mut()));
    for ((timers, (input, pt)), (q, et)) in groups {
        ton_group(timers, now, input, pt, q, et);
    }
    let n = timers_tail.len();
    if n > 0 {
        let mut timers = [IecTimerOf::new(); LANES];
        let mut input = [false; LANES];
        let mut pt = [D::ZERO; LANES];
        let (mut q, mut et) = ([false; LANES], [C::ZERO; LANES]);
        timers[..n].copy_from_slice(timers_tail);
        input[..n].copy_from_slice(inputs_tail);
        pt[..n].copy_from_slice(presets_tail);
        ton_group(&mut timers, now, &input, &pt, &mut q, &mut et);
        timers_tail.copy_from_slice(&timers[..n]);
        q_tail.copy_from_slice(&q[..n]);
        et_tail.copy_from_slice(&et[..n]);
    }
}

/// [`LANES`] timers of [`IecTimerOf::ton_array`], every array a parameter of its own:
/// parameters that are `&mut` are known not to overlap anything else (LLVM's `noalias`, kept
/// when inlined), which lets the compiler keep the arrays' addresses in registers and
/// vectorize the stores. The members are moved into arrays of their own (structure of arrays,
/// which the lane loop vectorizes), the lane run on each, and the results moved back.
#[inline(always)]
fn ton_group<C: ClockWord, D: IecDuration>(
    timers: &mut [IecTimerOf<C, D>; LANES],
    now: C,
    input: &[bool; LANES],
    pt: &[D; LANES],
    q: &mut [bool; LANES],
    et: &mut [C; LANES],
) {
    let mut start: [C; LANES] = core::array::from_fn(|j| timers[j].start);
    let mut latched: [C; LANES] = core::array::from_fn(|j| timers[j].pt);
    let mut elapsed: [C; LANES] = core::array::from_fn(|j| timers[j].et);
    let mut flags: [u32; LANES] = core::array::from_fn(|j| timers[j].flag_word());
    for j in 0..LANES {
        let lane = Lane {
            start: start[j],
            pt: latched[j],
            et: elapsed[j],
            flags: flags[j],
        };
        let lane = ton_lane(lane, now, input[j], pt[j]);
        (start[j], latched[j], elapsed[j], flags[j]) = (lane.start, lane.pt, lane.et, lane.flags);
    }
    for j in 0..LANES {
        timers[j] = IecTimerOf::from_words(start[j], latched[j], elapsed[j], flags[j]);
        q[j] = flags[j] & flag::Q != 0;
        et[j] = elapsed[j];
    }
}

impl<C: ClockWord, D: IecDuration> IecTimerOps<C, D> for IecTimerOf<C, D> {
    /// One box call: the reference's decisions, taken as branches on the inputs and on the
    /// timer's state (the reference's functions are named below), and per path only the
    /// members that path changes are written. A timer called once per scan takes the same
    /// branches scan after scan, which the processor predicts: measured, this costs less than
    /// computing every case without branches (for a loop over many TON timers, whose states
    /// differ from one timer to the next, see [`IecTimerOf::ton_for_arrays`]). `kind` is a
    /// constant at every call site of a program, and the `match` on it disappears when the
    /// call is inlined; the call is always inlined, so that the compiler sees the fields of
    /// the input from the start (inlined late, it had packed the input into one integer and
    /// unpacked it again on every call). The flags are computed in 32-bit words: in bytes,
    /// each call waited for the previous call's flag arithmetic (measured in `benches/peers`,
    /// on random inputs: TON 1.49 → 1.21-1.48 ns, TOF 1.43 → 1.27-1.37 ns across builds).
    /// Selecting the update's outcome instead of branching on the expiry, tried for TP, TON
    /// and TOF, cost more on square waves (0.1-0.25 ns) than it saved on random inputs.
    ///
    /// Why each kind equals the reference ([`super::IecTimerRef`]): `begin` is
    /// its `start` + `update` at one instant, `advance` its `update` of a running
    /// timer, `clear` its `reset_and_stop`; a stopped timer's `update` changes
    /// nothing, which is `idle`. Every path records the kind and IN, as the
    /// reference does after every call. A stopped timer has START = 0 already
    /// ([`IecState::is_valid`], which every structure satisfies).
    #[inline(always)]
    fn call(&mut self, kind: IecKind, now: CpuTime<D::Unit>, input: IecInput<D>) -> IecOutput<C> {
        let now = now.clock::<C>();
        let f = self.flags();
        let was_in = f & flag::IN != 0;
        let running = f & flag::RUNNING != 0;
        let on = input.input;
        let kind_bits = flag::KIND_VALID | (code(kind) as u32) << flag::KIND_SHIFT;
        let flags = kind_bits | bit(on, flag::IN);
        match kind {
            // TP: update; a rising IN with no pulse running starts one; stopped with IN = 0,
            // ET returns to 0. A pulse still running after the update ignores IN.
            IecKind::Tp => {
                if running {
                    let elapsed = now.elapsed_since(self.start);
                    if !reached(elapsed, self.pt) {
                        self.et = elapsed;
                        self.set_flags(flags | flag::RUNNING | flag::Q);
                        return IecOutput {
                            q: true,
                            et: elapsed,
                        };
                    }
                    // Expired on this update: ET = PT, Q = 0, stopped; then as a stopped timer.
                    // Once per pulse: marked cold, so that the compiler keeps the running
                    // pulse as the straight line (`benches/peers`, TP's loop on square waves
                    // 25.2-25.5 → 23.8-24.2 µs, its step on random inputs 1.35 → 1.25 ns).
                    cold_path();
                    self.start = C::ZERO;
                    if on && !was_in {
                        return self.begin(now, input.pt, flags, true, false);
                    }
                    let et = if on { self.pt } else { C::ZERO };
                    self.et = et;
                    self.set_flags(flags);
                    return IecOutput { q: false, et };
                }
                // Stopped: a rising IN starts a pulse; else Q kept, ET kept while IN = 1 and 0
                // with IN = 0. One branch, on the rise (tested on the flag words, so that it
                // stays one test); IN itself only selects ET: as a branch, a falling IN on a
                // stopped timer cost a misprediction the rise test does not (random inputs,
                // `benches/peers`: 1.55-1.69 → 1.23-1.25 ns in three builds; square waves
                // 1.11-1.12 → 1.18 ns). ET is kept by a mask of IN: without a rise, IN is
                // set only where the remembered IN is too, so IN and the remembered IN give
                // it (as `select_unpredictable(on, ET, 0)`, the select lost its hint when
                // the compiler rewrote the conditional move, llvm/llvm-project#223469, and
                // in a loop over timers it became a branch on IN again: `benches/peers`,
                // loop of 10 048 TP on square waves, 23.8-24.8 → 21.2-22.0 µs in the plain
                // build, about even with `simd-dispatch`).
                if flags & !f & flag::IN == 0 {
                    let q = f & flag::Q;
                    let et = masked(self.et, (flags & f & flag::IN).wrapping_neg());
                    self.et = et;
                    self.set_flags(flags | q);
                    return IecOutput { q: q != 0, et };
                }
                self.begin(now, input.pt, flags, true, false)
            }
            // TON: IN = 0 resets; a rising IN starts; else update (the reference's `ton`).
            // Branches on IN and on the state, which a timer called once per scan takes the
            // same way scan after scan; for arrays of timers whose states differ, see
            // [`IecTimerOf::ton_for_arrays`].
            // The commonest case of IN = 1, a timer timing since an earlier call (IN
            // remembered and running: one test of two flag bits), is tested before the rise;
            // the order changes no outcome, as both tests need IN remembered.
            IecKind::Ton => {
                if !on {
                    self.clear(flags, false)
                } else if f & (flag::IN | flag::RUNNING) == flag::IN | flag::RUNNING {
                    self.advance(now, flags, false, true)
                } else if !was_in {
                    self.begin(now, input.pt, flags, false, true)
                } else {
                    self.idle(flags)
                }
            }
            // TOF: IN = 1 resets with Q = 1; a falling IN starts; else update.
            IecKind::Tof => {
                if on {
                    self.clear(flags, true)
                } else if was_in {
                    self.begin(now, input.pt, flags, true, false)
                } else if running {
                    self.advance(now, flags, true, false)
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
                    // The update, then with IN = 0 the pause.
                    let elapsed = now.elapsed_since(self.start);
                    if reached(elapsed, self.pt) {
                        self.start = C::ZERO;
                        self.et = self.pt;
                        self.set_flags(flags | flag::Q);
                        return IecOutput {
                            q: true,
                            et: self.pt,
                        };
                    }
                    // The pause selected, not branched to: in a loop over timers IN falls
                    // on one timer or another, and the branch was mispredicted there.
                    self.et = elapsed;
                    self.start = core::hint::select_unpredictable(on, self.start, C::ZERO);
                    self.set_flags(flags | bit(on, flag::RUNNING));
                    IecOutput {
                        q: false,
                        et: elapsed,
                    }
                } else if on && f & flag::Q == 0 {
                    // Resume: the update that follows the reference's `start` finds `now -
                    // START` = the accumulated ET (exactly: START = now - ET modulo 2^BITS), so
                    // the timer has expired at once when ET reaches the new PT; else it runs
                    // on from ET (its Q is 0 already).
                    let pt = C::from_preset(input.pt.units());
                    self.pt = pt;
                    if reached(self.et, pt) {
                        self.et = pt;
                        self.set_flags(flags | flag::Q);
                        return IecOutput { q: true, et: pt };
                    }
                    self.start = now.elapsed_since(self.et);
                    self.set_flags(flags | flag::RUNNING);
                    IecOutput {
                        q: false,
                        et: self.et,
                    }
                } else {
                    self.idle(flags)
                }
            }
        }
    }

    #[inline]
    fn read_q(&mut self, now: CpuTime<D::Unit>) -> bool {
        self.update_on_read(now.clock());
        self.flags() & flag::Q != 0
    }

    #[inline]
    fn read_et(&mut self, now: CpuTime<D::Unit>) -> C {
        self.update_on_read(now.clock());
        self.et
    }

    fn reset_timer(&mut self) {
        self.stop_clear();
        self.set_flags(self.flags() & !flag::IN);
    }

    fn preset_timer(&mut self, pt: D) {
        self.pt = C::from_preset(pt.units());
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
