//! The optimized S5 timer: the whole state of one timer packed in one 32-bit word
//! ([`TimerWord`]), and [`S5Timer`], a word with the time of its previous call.
//!
//! ```text
//!  31 .. 21   20      19      18          17   16        15 14  13 12  11 10  9 .. 0
//!  0          FR edge S edge  Q on expiry Q    running   0  0   base   0  0   value
//! ```
//!
//! The low half is the CPU's 16-bit timer word as LAD manual §9.1 describes it: the remaining
//! value in binary in bits 9-0, the time base in bits 13-12. The high half holds what the CPU
//! keeps beside it: the status Q, whether the time runs, the status the timer takes when the time
//! runs out (1 for the on-delays, 0 for the pulses and the off-delay; Berger §7), and the edge
//! memories of S and FR. One word per timer, so a timer memory area is a `[u32; N]` that the
//! OS tick processes as a vector, without knowing the timers' kinds.

use super::{S5Input, S5Kind, S5Output, S5State, S5TimerOps};
use crate::time::{CpuTime, S5Time, TimeBase, BCD3_TABLE};

/// Bits 9-0: the remaining value in binary.
pub const VALUE: u32 = 0x0000_03FF;
/// Bits 13-12: the time base.
pub const BASE: u32 = 0x0000_3000;
/// Bit 16: the time is running.
pub const RUNNING: u32 = 1 << 16;
/// Bit 17: the status Q.
pub const Q: u32 = 1 << 17;
/// Bit 18: the status when the running time runs out.
pub const Q_ON_EXPIRY: u32 = 1 << 18;
/// Bit 19: S at the previous execution.
pub const S_PREV: u32 = 1 << 19;
/// Bit 20: FR at the previous execution.
pub const FR_PREV: u32 = 1 << 20;
/// Every bit a word may have set.
const USED: u32 = VALUE | BASE | RUNNING | Q | Q_ON_EXPIRY | S_PREV | FR_PREV;

// The seven fields are disjoint: no two masks share a bit. So `a | b` of two fields equals
// `a ^ b` and `a + b` (the code uses `|`), and clearing one field (`w & !MASK`) leaves every
// other field as it was.
const _: () = {
    let masks = [VALUE, BASE, RUNNING, Q, Q_ON_EXPIRY, S_PREV, FR_PREV];
    let mut union = 0u32;
    let mut i = 0;
    while i < masks.len() {
        assert!(union & masks[i] == 0, "timer word fields overlap");
        union |= masks[i];
        i += 1;
    }
    assert!(union == USED);
};

/// The flag bits of a timer memory area's 16-bit cell ([`TimerWord::to_cell`]); value and base
/// are where the word has them.
pub(crate) mod cell {
    /// Bit 10: the status when the running time runs out.
    pub const Q_ON_EXPIRY: u32 = 1 << 10;
    /// Bit 14: the status Q.
    pub const Q: u32 = 1 << 14;
    /// Bit 15: the time is running.
    pub const RUNNING: u32 = 1 << 15;
    // Disjoint from each other and from VALUE (bits 9-0) and BASE (bits 13-12).
    const _: () = assert!(
        (Q_ON_EXPIRY | Q | RUNNING) & (super::VALUE | super::BASE) == 0
            && Q_ON_EXPIRY + Q + RUNNING == Q_ON_EXPIRY | Q | RUNNING
    );
}

/// Cells per group of [`TimerWord::tick_once_cells`]: four 128-bit vectors of 16-bit lanes.
const CELL_GROUP: usize = 32;

/// One group of [`TimerWord::tick_once_cells`] (see there why it equals `tick_once`), with
/// `offset = 2^15 - (target + 1)` for the ticking base's `target`.
#[inline(always)]
fn tick_cell_group(group: &mut [u16; CELL_GROUP], offset: u16, base_bits: u32) {
    const KEY: u16 = cell::RUNNING as u16 | BASE as u16 | VALUE as u16;
    const BIAS: u16 = 0x8000;
    let limit = (1023 ^ BIAS) as i16;
    let mut ticked = [0u16; CELL_GROUP];
    let mut ends = false;
    for (t, &c) in ticked.iter_mut().zip(group.iter()) {
        let x = (c & KEY).wrapping_add(offset);
        ends |= x == BIAS;
        *t = c.wrapping_sub(u16::from((x as i16) < limit));
    }
    if ends {
        for c in group.iter_mut() {
            *c = TimerWord::from_cell(*c, 0).tick_once(base_bits).to_cell().0;
        }
    } else {
        *group = ticked;
    }
}

/// Division of a CPU time by a time base (10^k ms, k = 1..=4, base code k - 1) without a
/// division instruction: `(t >> k) * M >> (64 - k + L)`, with `L = ceil(log2(5^k))` and
/// `M = ceil(2^(64 - k + L) / 5^k)`.
///
/// Why it is exact for every `u64`: `t / 10^k = (t / 2^k) / 5^k` (floors of floors), and
/// `x = t >> k` is below `2^N` with `N = 64 - k`. For a divisor `d = 5^k` with
/// `2^(L-1) < d <= 2^L`, `M = ceil(2^(N+L) / d)` satisfies `2^(N+L) <= M d <= 2^(N+L) + d - 1
/// < 2^(N+L) + 2^L`, and then `floor(x M / 2^(N+L)) = floor(x / d)` for every `0 <= x < 2^N`
/// (Granlund and Montgomery 1994, theorem 4.2). `M` fits 64 bits for k = 1..=4 (checked
/// below), and `x M` fits the 128-bit product.
const BASE_DIVISORS: [(u32, u64, u32); 4] = {
    let mut table = [(0u32, 0u64, 0u32); 4];
    let mut k = 1u32;
    while k <= 4 {
        let d = 5u128.pow(k);
        let l = 128 - (d - 1).leading_zeros(); // ceil(log2(d)) for d > 1
        let shift = 64 - k + l;
        let m = (1u128 << shift).div_ceil(d);
        assert!(m < 1 << 64, "the multiplier fits 64 bits");
        assert!(10u128.pow(k) == 5u128.pow(k) << k);
        table[k as usize - 1] = (k, m as u64, shift);
        k += 1;
    }
    table
};

/// `t / base.millis()`, by multiplication ([`BASE_DIVISORS`]).
#[inline(always)]
const fn div_by_base(t: u64, base_bits: usize) -> u64 {
    let (k, m, shift) = BASE_DIVISORS[base_bits & 3];
    (((t >> k) as u128 * m as u128) >> shift) as u64
}

/// [`super::ticks_between`] (the ticks of `base` in `(from, to]`: `to / b - from / b`, 0 when
/// `to` is not after `from`), with the two divisions done by multiplication.
#[inline(always)]
pub(crate) const fn ticks_between_fast(from: CpuTime, to: CpuTime, base_bits: usize) -> u64 {
    div_by_base(to.as_millis(), base_bits).saturating_sub(div_by_base(from.as_millis(), base_bits))
}

/// One timer, packed in a word. Its field is private: every word this type holds is a valid
/// state (value at most 999, no stray bits, no expiry status on a stopped timer), which
/// [`TimerWord::from_bits`] checks.
///
/// ```
/// use plc_timers::s5::{S5Input, S5Kind, TimerWord};
/// let tv = plc_timers::s5time!("S5T#2M7S"); // 127 units of 1 s
/// let w = TimerWord::RESET.execute(S5Kind::SPext, S5Input::new(true, false, tv));
/// assert_eq!((w.q(), w.value(), w.bcd()), (true, 127, 0x2127));
/// assert_eq!(w.tick(27).value(), 100);
/// assert!(TimerWord::from_bits(0x03E8).is_none()); // value field 1000
/// ```
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash)]
#[repr(transparent)]
pub struct TimerWord(u32);

/// `mask` if `b`, else 0.
const fn bit(b: bool, mask: u32) -> u32 {
    (b as u32).wrapping_neg() & mask
}

impl TimerWord {
    /// A cleared timer.
    pub const RESET: TimerWord = TimerWord(0);

    /// The word with bits `bits`, or `None` when it is not a valid state: a value field above
    /// 999, a bit outside the fields, or an expiry status on a stopped timer.
    ///
    /// ```
    /// use plc_timers::s5::TimerWord;
    /// let w = TimerWord::from_bits(0x0003_207F).expect("running, Q = 1, 127 (binary) units of 1 s");
    /// assert_eq!((w.value(), w.q(), w.is_running()), (127, true, true));
    /// assert!(TimerWord::from_bits(0x0004_0000).is_none()); // an expiry status on a stopped timer
    /// ```
    pub const fn from_bits(bits: u32) -> Option<TimerWord> {
        let valid = bits & !USED == 0
            && bits & VALUE <= 999
            && (bits & RUNNING != 0 || bits & Q_ON_EXPIRY == 0);
        if valid {
            Some(TimerWord(bits))
        } else {
            None
        }
    }

    /// The word's bits.
    pub const fn bits(self) -> u32 {
        self.0
    }

    /// The word holding `state`, or `None` when the state is not valid.
    ///
    /// ```
    /// use plc_timers::s5::{S5State, TimerWord};
    /// let state = S5State { value: 999, ..S5State::RESET };
    /// assert_eq!(TimerWord::from_state(state).map(TimerWord::state), Some(state));
    /// ```
    pub const fn from_state(state: S5State) -> Option<TimerWord> {
        if !state.is_valid() {
            return None;
        }
        Some(TimerWord(
            state.value as u32
                | (state.base.bits() as u32) << 12
                | bit(state.running, RUNNING)
                | bit(state.q, Q)
                | bit(state.q_on_expiry, Q_ON_EXPIRY)
                | bit(state.s_prev, S_PREV)
                | bit(state.fr_prev, FR_PREV),
        ))
    }

    /// The abstraction function: the reference state this word represents. With
    /// [`TimerWord::from_state`] a bijection between words and valid states.
    pub const fn state(self) -> S5State {
        let w = self.0;
        S5State {
            running: w & RUNNING != 0,
            value: (w & VALUE) as u16,
            base: TimeBase::from_bits((w >> 12) as u8),
            q: w & Q != 0,
            q_on_expiry: w & Q_ON_EXPIRY != 0,
            s_prev: w & S_PREV != 0,
            fr_prev: w & FR_PREV != 0,
        }
    }

    /// Whether the time is running.
    pub const fn is_running(self) -> bool {
        self.0 & RUNNING != 0
    }

    /// The remaining value (`L T n`, `BI`).
    pub const fn value(self) -> u16 {
        (self.0 & VALUE) as u16
    }

    /// The time base.
    pub const fn base(self) -> TimeBase {
        TimeBase::from_bits((self.0 >> 12) as u8)
    }

    /// The status (`A T n`, `Q`).
    pub const fn q(self) -> bool {
        self.0 & Q != 0
    }

    /// The value as the DEZ/BCD word with the base (`LC T n`, `BCD`): a table lookup instead of
    /// two divisions.
    pub const fn bcd(self) -> u16 {
        (self.0 & BASE) as u16 | BCD3_TABLE[(self.0 & VALUE) as usize]
    }

    /// The outputs of the box.
    pub const fn output(self) -> S5Output {
        S5Output {
            q: self.q(),
            bi: self.value(),
            bcd: self.bcd(),
        }
    }

    /// The end of the time: stop, Q takes the expiry status, which is cleared. Applied where
    /// `expired` is all ones, a no-op where it is 0.
    #[inline]
    const fn expire_where(w: u32, expired: u32) -> u32 {
        let q = (w & Q_ON_EXPIRY) >> 1; // bit 18 to bit 17
        (w & !(expired & (RUNNING | Q | Q_ON_EXPIRY))) | (expired & q)
    }

    /// Applies `n` ticks of the word's base: `min(n, value)` units off a running timer; reaching
    /// 0 stops it and Q takes its expiry status. Branch-free, so that a loop over an area
    /// vectorizes.
    #[inline]
    #[must_use]
    pub const fn tick(self, n: u64) -> TimerWord {
        let w = self.0;
        let value = w & VALUE;
        let running = w & RUNNING != 0;
        let dec = if n < value as u64 { n as u32 } else { value };
        let dec = dec & bit(running, VALUE);
        let left = value - dec;
        let expired = bit(dec != 0 && left == 0, u32::MAX);
        TimerWord(Self::expire_where((w & !VALUE) | left, expired))
    }

    /// `n` ticks (`n <= 1 000`) of base code `base_bits` (0..=3): [`TimerWord::tick`] for a
    /// word of that base, the word as it is for another base. 32-bit arithmetic without
    /// branches, so that a pass over an area vectorizes. Why it equals `tick`: a value is at
    /// most 999, so `min(n, value)` is the same for the u64 count and for any count from
    /// 1 000 on, which the caller clamps to; a word of another base is ticked with 0, which
    /// `tick` leaves unchanged.
    #[inline]
    #[must_use]
    pub const fn tick_units(self, base_bits: u32, n: u32) -> TimerWord {
        let w = self.0;
        let mine = (w & (RUNNING | BASE)) == (RUNNING | base_bits << 12);
        let value = w & VALUE;
        let dec = if n < value { n } else { value } & bit(mine, VALUE);
        let left = value - dec;
        let expired = bit(dec != 0 && left == 0, u32::MAX);
        TimerWord(Self::expire_where((w & !VALUE) | left, expired))
    }

    /// One tick of base code `base_bits` (0..=3): the OS tick as it comes, every base interval.
    /// Pure 32-bit arithmetic without branches, so that a pass over an area vectorizes:
    /// subtracting 1 from a non-zero value field cannot borrow into the other fields.
    #[inline]
    #[must_use]
    pub const fn tick_once(self, base_bits: u32) -> TimerWord {
        let w = self.0;
        let active = ((w & (RUNNING | BASE)) == (RUNNING | base_bits << 12)) as u32;
        let value = w & VALUE;
        let dec = active & (value != 0) as u32;
        let expired = (dec & (value == 1) as u32).wrapping_neg();
        TimerWord(Self::expire_where(w - dec, expired))
    }

    /// The word as a timer memory area stores it ([`super::TimerMemory`]): a 16-bit cell with
    /// everything the OS tick reads and writes, and a byte with the edge memories, which only
    /// the operations use. Cell: value in bits 9-0 and base in bits 13-12 (the CPU's timer word,
    /// LAD manual §9.1), the expiry status in bit 10, Q in bit 14, RUNNING in bit 15 (bits the
    /// CPU's word leaves 0); edge byte: S in bit 0, FR in bit 1. The inverse of
    /// [`TimerWord::from_cell`]: the fields are moved, none is lost (the word's five flags and
    /// 12 bits of value and base are 17 bits, one more than a cell has; the edges are the two
    /// the tick never reads).
    #[inline(always)]
    pub(crate) const fn to_cell(self) -> (u16, u8) {
        let w = self.0;
        let cell =
            (w & (VALUE | BASE)) | (w & RUNNING) >> 1 | (w & Q) >> 3 | (w & Q_ON_EXPIRY) >> 8;
        (cell as u16, ((w & (S_PREV | FR_PREV)) >> 19) as u8)
    }

    /// The word a timer memory area stores as `cell` and `edges` ([`TimerWord::to_cell`]).
    /// Valid for every cell and edge byte `to_cell` gives; the area holds no other.
    #[inline(always)]
    pub(crate) const fn from_cell(cell: u16, edges: u8) -> TimerWord {
        let c = cell as u32;
        TimerWord(
            (c & (VALUE | BASE))
                | (c & cell::RUNNING) << 1
                | (c & cell::Q) << 3
                | (c & cell::Q_ON_EXPIRY) << 8
                | ((edges & 3) as u32) << 19,
        )
    }

    /// [`TimerWord::tick_once`] for every cell of `cells` (the OS tick of an area, cells as
    /// [`TimerWord::to_cell`] makes them), 32 cells at a time: 16-bit lanes, 8 cells per SSE2
    /// instruction (twice the words of 32-bit lanes). A tick ends a timer's time in very few
    /// cells (value 1 of the ticking base); a group of 32 in which none ends is done by the
    /// short form below, a group in which one ends by `tick_once` itself on each word.
    ///
    /// Why the short form equals `tick_once` on such a group: `tick_once` subtracts 1 from a
    /// timer running on this base whose value is not 0, and changes no other timer unless it
    /// expires one (value 1). In a cell those timers are the ones whose bits RUNNING, BASE and
    /// VALUE, `key = c & (RUNNING | BASE | VALUE)`, lie in `target + 1 ..= target + 1023` for
    /// `target = RUNNING | base << 12` (VALUE is the low 10 bits, so within that range only
    /// VALUE differs from `target`), and subtracting 1 from such a cell takes 1 from its value
    /// field alone. The range test is `key - (target + 1) < 1023` unsigned (modulo 2^16),
    /// computed as the signed 16-bit compare `x < 1023 ^ 2^15` of `x = key + 2^15 - (target +
    /// 1)` (adding 2^15 modulo 2^16 flips the top bit, which maps the unsigned order onto the
    /// signed one). Such a cell expires when `key = target + 1`, i.e. `x = 2^15`; the group
    /// takes the short form only when no cell has that `x`.
    #[inline(always)]
    pub(crate) fn tick_once_cells(cells: &mut [u16], base_bits: u32) {
        const BIAS: u16 = 0x8000;
        let target = cell::RUNNING as u16 | ((base_bits & 3) as u16) << 12;
        // `black_box` only hides the constant from the optimizer (it is the same value):
        // seeing it, LLVM rewrites the signed compare below as an unsigned one, which SSE2
        // does with more instructions.
        let offset = core::hint::black_box(BIAS.wrapping_sub(target + 1));
        let (groups, rest) = cells.as_chunks_mut::<CELL_GROUP>();
        for group in groups {
            tick_cell_group(group, offset, base_bits);
        }
        // The last `len % 32` cells: through the same code on a padded copy (the padding
        // cells are stopped timers, which a tick leaves as they are).
        if !rest.is_empty() {
            let mut group = [0u16; CELL_GROUP];
            group[..rest.len()].copy_from_slice(rest);
            tick_cell_group(&mut group, offset, base_bits);
            rest.copy_from_slice(&group[..rest.len()]);
        }
    }

    /// The `process` step of an execution: a running timer with value 0 (started with TV = 0)
    /// is found expired (Berger §7).
    #[inline]
    const fn process_zero(self) -> TimerWord {
        let w = self.0;
        let zero_running = w & RUNNING != 0 && w & VALUE == 0;
        TimerWord(Self::expire_where(w, bit(zero_running, u32::MAX)))
    }

    /// `FR T n` with RLO `fr`: a rising edge clears the start edge memory (S5TMR-FR-01).
    #[inline]
    #[must_use]
    pub const fn enable(self, fr: bool) -> TimerWord {
        let w = self.0;
        let rising = fr && w & FR_PREV == 0;
        TimerWord((w & !(bit(rising, S_PREV) | FR_PREV)) | bit(fr, FR_PREV))
    }

    /// `SP/SE/SD/SS/SF T n` with RLO `s` and time value `tv` already loaded.
    #[inline]
    #[must_use]
    pub const fn start(self, kind: S5Kind, s: bool, tv: S5Time) -> TimerWord {
        let w = self.process_zero().0;
        let rising = s && w & S_PREV == 0;
        let falling = !s && w & S_PREV != 0;
        let running = w & RUNNING != 0;
        let loaded = tv.units() as u32 | RUNNING | (tv.base().bits() as u32) << 12;
        let edges = w & (S_PREV | FR_PREV);
        let stopped = w & !(RUNNING | Q | Q_ON_EXPIRY);
        let w = match kind {
            S5Kind::SPulse | S5Kind::SPext if rising => edges | loaded | Q,
            S5Kind::SPulse if !s && running => stopped,
            S5Kind::SOdt if rising => edges | loaded | Q_ON_EXPIRY,
            S5Kind::SOdt if !s => stopped,
            // S_ODTS keeps its status: Q = 1 stays from the first expiry until R (SS-Q-01).
            S5Kind::SOdts if rising => edges | loaded | (w & Q) | Q_ON_EXPIRY,
            S5Kind::SOffdt if falling => edges | loaded | Q,
            S5Kind::SOffdt if rising => stopped | Q,
            _ => w,
        };
        TimerWord((w & !S_PREV) | bit(s, S_PREV))
    }

    /// `R T n` with RLO `r`: while 1, stopped, value and base 0, Q = 0; edge memories kept.
    #[inline]
    #[must_use]
    pub const fn reset(self, r: bool) -> TimerWord {
        TimerWord(self.0 & !bit(r, VALUE | BASE | RUNNING | Q | Q_ON_EXPIRY))
    }

    /// One box execution (`FR`, start, `R`), the ticks already applied.
    #[inline]
    #[must_use]
    pub const fn execute(self, kind: S5Kind, input: S5Input) -> TimerWord {
        self.enable(input.fr)
            .start(kind, input.s, input.tv)
            .reset(input.r)
    }
}

/// One optimized timer on its own (outside a timer memory area): the packed word and the CPU
/// time of its previous execution, from which the ticks of its base are counted, as the
/// reference does. The ticks are only counted while the timer runs (a stopped timer ignores
/// them).
///
/// ```
/// use plc_timers::s5::{S5Input, S5Kind, S5Timer, S5TimerOps};
/// use plc_timers::time::CpuTime;
///
/// let tv = plc_timers::s5time!("S5T#20MS");
/// let mut sf = S5Timer::new();
/// let at = CpuTime::from_millis;
/// assert!(sf.call(S5Kind::SOffdt, at(0), S5Input::new(true, false, tv)).q); // S = 1: Q = 1
/// assert!(sf.call(S5Kind::SOffdt, at(5), S5Input::new(false, false, tv)).q); // S falls: runs
/// assert!(!sf.call(S5Kind::SOffdt, at(20), S5Input::new(false, false, tv)).q); // 2 ticks: off
/// ```
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct S5Timer {
    word: TimerWord,
    last_call: CpuTime,
}

impl S5Timer {
    /// A cleared timer whose previous execution was at CPU time 0.
    ///
    /// ```
    /// use plc_timers::s5::{S5State, S5Timer, S5TimerOps};
    /// assert_eq!(S5Timer::new().state(), S5State::RESET);
    /// ```
    pub const fn new() -> S5Timer {
        S5Timer {
            word: TimerWord::RESET,
            last_call: CpuTime::ZERO,
        }
    }

    /// The timer in `state` whose previous execution was at `last_call`, or `None` when the
    /// state is not valid.
    ///
    /// ```
    /// use plc_timers::s5::{S5Input, S5Kind, S5State, S5Timer, S5TimerOps};
    /// use plc_timers::time::{CpuTime, TimeBase};
    /// // A stopped S_PULSE that kept 40 units of 10 ms; its last call was at 1 s.
    /// let kept = S5State { value: 40, base: TimeBase::Ms10, ..S5State::RESET };
    /// let mut t = S5Timer::from_state(kept, CpuTime::from_millis(1_000)).expect("valid");
    /// let out = t.call(S5Kind::SPulse, CpuTime::from_millis(2_000), S5Input::new(false, false, plc_timers::s5time!("S5T#1S")));
    /// assert_eq!(out.bi, 40); // a stopped timer ignores the ticks
    /// ```
    pub const fn from_state(state: S5State, last_call: CpuTime) -> Option<S5Timer> {
        match TimerWord::from_state(state) {
            Some(word) => Some(S5Timer { word, last_call }),
            None => None,
        }
    }

    /// The timer word.
    pub const fn word(&self) -> TimerWord {
        self.word
    }

    /// The latest CPU time an execution saw: the previous execution's, unless the clock went
    /// back (S5TMR-CLOCK-01).
    pub const fn last_call(&self) -> CpuTime {
        self.last_call
    }
}

impl S5TimerOps for S5Timer {
    /// The ticks since the previous call are counted without a division instruction
    /// (`ticks_between_fast`), and only for a running timer: a stopped one ignores them, as
    /// the reference's tick does (its first test). Measured: the branch on the running bit
    /// costs less than counting on every call (a timer runs for many calls in a row).
    #[inline(always)]
    fn call(&mut self, kind: S5Kind, now: CpuTime, input: S5Input) -> S5Output {
        if self.word.is_running() {
            let base = ((self.word.0 & BASE) >> 12) as usize;
            let n = ticks_between_fast(self.last_call, now, base);
            self.word = self.word.tick(n);
        }
        // S5TMR-CLOCK-01: the clock does not go back (no tick was counted above either).
        if now > self.last_call {
            self.last_call = now;
        }
        self.word = self.word.execute(kind, input);
        self.word.output()
    }

    fn state(&self) -> S5State {
        self.word.state()
    }
}

impl S5Timer {
    /// S5TMR-RETAIN-01: a RUN-STOP-RUN, the CPU in STOP from `stop` to `restart`, as
    /// [`super::S5TimerRef::run_stop_run`]: the ticks up to `stop`, none in STOP, and at the
    /// restart the word kept (retentive) or cleared ([`TimerWord::RESET`]).
    ///
    /// ```
    /// use plc_timers::s5::{S5Input, S5Kind, S5Timer, S5TimerOps};
    /// use plc_timers::time::CpuTime;
    /// let at = CpuTime::from_millis;
    /// let on = S5Input::new(true, false, plc_timers::s5time!("S5T#100MS"));
    /// let mut t = S5Timer::new();
    /// t.call(S5Kind::SOdt, at(0), on);
    /// t.run_stop_run(at(40), at(5_000), true);
    /// assert_eq!(t.call(S5Kind::SOdt, at(5_030), on).bi, 3);
    /// ```
    pub fn run_stop_run(&mut self, stop: CpuTime, restart: CpuTime, retentive: bool) {
        let base = ((self.word.0 & BASE) >> 12) as usize;
        // `tick` leaves a stopped word as it is.
        self.word = self
            .word
            .tick(ticks_between_fast(self.last_call, stop, base));
        self.last_call = self.last_call.max(stop).max(restart);
        if !retentive {
            self.word = TimerWord::RESET;
        }
    }
}

#[cfg(test)]
mod tests {
    use super::{div_by_base, TimerWord, BASE_DIVISORS, USED};

    /// `tick_once_cells` equals `tick_once` on every word: areas of random valid words
    /// (values 0..=999 with many 0, 1 and 2, every base, running or not, any status bits), as
    /// cells, of lengths that are and are not multiples of the group of 32, for every base.
    #[test]
    fn tick_once_cells_equals_tick_once() {
        let mut x = 0x2545_F491_4F6C_DD1Du64;
        let mut next = move || {
            x ^= x << 13;
            x ^= x >> 7;
            x ^= x << 17;
            x
        };
        for len in [0, 1, 15, 16, 17, 31, 32, 33, 64, 100] {
            for round in 0..200 {
                let words: [TimerWord; 100] = core::array::from_fn(|_| {
                    let r = next();
                    let value = match r % 4 {
                        0 => (r >> 8) % 3,
                        _ => (r >> 8) % 1000,
                    } as u32;
                    let bits = ((r >> 20) as u32 & USED & !super::VALUE) | value;
                    TimerWord::from_bits(bits)
                        .or_else(|| TimerWord::from_bits(bits & !super::Q_ON_EXPIRY))
                        .expect("a valid word")
                });
                let base = round % 4;
                let cells = words.map(|w| w.to_cell());
                let mut area = cells.map(|(c, _)| c);
                TimerWord::tick_once_cells(&mut area[..len], base);
                for i in 0..100 {
                    let expected = if i < len {
                        words[i].tick_once(base)
                    } else {
                        words[i]
                    };
                    assert_eq!(
                        TimerWord::from_cell(area[i], cells[i].1),
                        expected,
                        "word {i} of {len}, base {base}"
                    );
                    assert_eq!(expected.to_cell().1, cells[i].1, "a tick keeps the edges");
                }
            }
        }
    }

    /// The multiplication equals the division for every base: all times below 2^22, every
    /// time within 2^16 of the top of the range, and a spread of times in between (the
    /// theorem behind it covers all of them; this checks the table's constants).
    #[test]
    fn division_by_multiplication_is_exact() {
        for (bits, &(k, _, _)) in BASE_DIVISORS.iter().enumerate() {
            let b = 10u64.pow(k);
            let check = |t: u64| assert_eq!(div_by_base(t, bits), t / b, "{t} / {b}");
            (0..1u64 << 22).for_each(check);
            (0..1u64 << 16).for_each(|d| check(u64::MAX - d));
            let mut x = 0x9E37_79B9_7F4A_7C15u64;
            for _ in 0..1 << 20 {
                x ^= x << 13;
                x ^= x >> 7;
                x ^= x << 17;
                check(x);
                check(x / b * b);
                check((x / b * b).wrapping_sub(1));
            }
        }
    }
}
