//! The optimized S5 timer: the whole state of one timer packed in the CPU's 16-bit timer word.
//!
//! ```text
//!  15      14      13 12   11   10        9 .. 0
//!  FR edge S edge  base    Q    running   value (binary, 0..=999; seed 000 §9.1)
//! ```
//!
//! The value and base sit where seed 000 §9.1 puts them; bits 10, 11, 14 and 15 (unused by the
//! value) hold the status and the two edge memories, so a timer is exactly one `u16` and a
//! timer memory area is a `[u16; N]` that the tick can process as a vector.
//!
//! Why the tick needs no kind: while a timer runs, its Q is `q_while_running(kind)` and expiry
//! sets Q to the opposite (pulses and off-delay end, on-delays switch on), so expiry is "stop and
//! invert Q" for every kind. `proofs/s5.rs` checks this against the reference for every state.

use super::{S5Input, S5Kind, S5Output, S5State};
use crate::time::{bcd3_encode, TimeBase};

/// Bits 9-0: the remaining value in binary.
pub const VALUE: u16 = 0x03FF;
/// Bit 10: the time is running.
pub const RUNNING: u16 = 1 << 10;
/// Bit 11: the status Q.
pub const Q: u16 = 1 << 11;
/// Bits 13-12: the time base.
pub const BASE: u16 = 0x3000;
/// Bit 14: S at the previous execution.
pub const S_PREV: u16 = 1 << 14;
/// Bit 15: FR at the previous execution.
pub const FR_PREV: u16 = 1 << 15;

// The six fields partition the word: no two masks share a bit, and together they cover all 16.
// So `a | b` of two fields equals `a ^ b` and `a + b` (the code uses `|`), and clearing one field
// (`w & !MASK`) leaves every other field as it was.
const _: () = {
    let masks = [VALUE, RUNNING, Q, BASE, S_PREV, FR_PREV];
    let mut union = 0u16;
    let mut i = 0;
    while i < masks.len() {
        assert!(union & masks[i] == 0, "cell fields overlap");
        union |= masks[i];
        i += 1;
    }
    assert!(union == u16::MAX, "cell fields leave a bit unused");
};

/// The BCD form of every value the 10-bit field can hold (0..=1023; only 0..=999 occur).
pub(crate) const BCD_TABLE: [u16; 1024] = {
    let mut t = [0u16; 1024];
    let mut v = 0;
    while v < 1000 {
        t[v] = bcd3_encode(v as u16);
        v += 1;
    }
    t
};

/// One timer cell: the packed 16-bit timer word.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash)]
#[repr(transparent)]
pub struct Cell(pub u16);

const fn bit(b: bool, mask: u16) -> u16 {
    (b as u16).wrapping_neg() & mask
}

impl Cell {
    /// A cleared timer.
    pub const RESET: Cell = Cell(0);

    /// The cell holding `state`, or `None` when the value exceeds 999.
    pub const fn from_state(state: S5State) -> Option<Cell> {
        if !state.is_valid() {
            return None;
        }
        Some(Cell(
            state.value
                | bit(state.running, RUNNING)
                | bit(state.q, Q)
                | (state.base.bits() as u16) << 12
                | bit(state.s_prev, S_PREV)
                | bit(state.fr_prev, FR_PREV),
        ))
    }

    /// Whether the remaining value is at most 999 (every other bit pattern is meaningful).
    pub const fn is_valid(self) -> bool {
        self.0 & VALUE <= 999
    }

    /// The remaining value (`L T n`, `BI`).
    pub const fn value(self) -> u16 {
        self.0 & VALUE
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
        (self.0 & BASE) | BCD_TABLE[(self.0 & VALUE) as usize]
    }

    /// The outputs of the box.
    pub const fn output(self) -> S5Output {
        S5Output {
            q: self.q(),
            bi: self.value(),
            bcd: self.bcd(),
        }
    }

    /// Applies `n` ticks of the cell's base: `min(n, value)` units off a running timer; reaching
    /// 0 stops it and inverts Q. Branch-free, so that a loop over an area vectorizes.
    #[inline]
    pub const fn tick(self, n: u64) -> Cell {
        let w = self.0;
        let value = w & VALUE;
        let running = w & RUNNING != 0;
        let dec = if n < value as u64 { n as u16 } else { value };
        let dec = dec & bit(running, VALUE);
        let left = value - dec;
        let expired = bit(dec != 0 && left == 0, RUNNING | Q);
        Cell(((w & !VALUE) | left) ^ expired)
    }

    /// One tick of base code `base_bits` (0..=3): the OS tick as it comes, every base interval.
    /// Pure 16-bit arithmetic without branches, so that a pass over an area vectorizes:
    /// subtracting 1 from a non-zero value field cannot borrow into the flag bits.
    #[inline]
    pub const fn tick_once(self, base_bits: u16) -> Cell {
        let w = self.0;
        let active = ((w & (RUNNING | BASE)) == (RUNNING | base_bits << 12)) as u16;
        let value = w & VALUE;
        let dec = active & (value != 0) as u16;
        let expired = dec & (value == 1) as u16;
        Cell((w - dec) ^ (expired * (RUNNING | Q)))
    }

    /// The `process` step of an execution: a running timer with value 0 (started with TV = 0)
    /// is found expired (seed 003 §7).
    #[inline]
    const fn process_zero(self) -> Cell {
        let w = self.0;
        let zero_running = w & RUNNING != 0 && w & VALUE == 0;
        Cell(w ^ bit(zero_running, RUNNING | Q))
    }

    /// `FR T n` with RLO `fr`: a rising edge clears the start edge memory (for S_OFFDT: sets it,
    /// since its start edge is the falling one).
    #[inline]
    pub const fn enable(self, kind: S5Kind, fr: bool) -> Cell {
        let w = self.0;
        let rising = fr && w & FR_PREV == 0;
        let w = if rising {
            (w & !S_PREV) | bit(kind.starts_on_falling_edge(), S_PREV)
        } else {
            w
        };
        Cell((w & !FR_PREV) | bit(fr, FR_PREV))
    }

    /// `SP/SE/SD/SS/SF T n` with RLO `s` and time value `tv` already loaded.
    #[inline]
    pub const fn start(self, kind: S5Kind, s: bool, tv: crate::time::S5Time) -> Cell {
        let w = self.process_zero().0;
        let s_prev = w & S_PREV != 0;
        let running = w & RUNNING != 0;
        let rising = s && !s_prev;
        let falling = !s && s_prev;
        let loaded = tv.units() | RUNNING | (tv.base().bits() as u16) << 12;
        let keep = w & (S_PREV | FR_PREV);
        let w = match kind {
            S5Kind::SPulse if rising && !running => keep | loaded | Q,
            S5Kind::SPulse if !s && running => w & !(RUNNING | Q),
            S5Kind::SPext if rising => keep | loaded | Q,
            S5Kind::SOdt if rising => keep | loaded,
            S5Kind::SOdt if !s => w & !(RUNNING | Q),
            S5Kind::SOdts if rising => keep | loaded,
            S5Kind::SOffdt if falling => keep | loaded | Q,
            S5Kind::SOffdt if s => (w & !RUNNING) | Q,
            _ => w,
        };
        Cell((w & !S_PREV) | bit(s, S_PREV))
    }

    /// `R T n` with RLO `r`: while 1, stopped, value and base 0, Q = 0; edge memories kept.
    #[inline]
    pub const fn reset(self, r: bool) -> Cell {
        Cell(self.0 & !bit(r, VALUE | RUNNING | Q | BASE))
    }

    /// One box execution (`FR`, start, `R`), the ticks already applied.
    #[inline]
    pub const fn execute(self, kind: S5Kind, input: S5Input) -> Cell {
        self.enable(kind, input.fr)
            .start(kind, input.s, input.tv)
            .reset(input.r)
    }
}

/// One optimized timer on its own (outside a timer memory area): the packed cell and the CPU time
/// of its previous execution, from which the ticks of its base are counted, as the reference does.
/// The ticks are only counted while the timer runs (a stopped timer ignores them).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct PackedTimer {
    /// The timer word.
    pub cell: Cell,
    /// The CPU time (ms) of the previous execution.
    pub t_prev: u64,
}

impl PackedTimer {
    /// A cleared timer at CPU time 0.
    pub const fn new() -> PackedTimer {
        PackedTimer {
            cell: Cell::RESET,
            t_prev: 0,
        }
    }

    /// One execution of the box `kind` at CPU time `t_ms` (not before the previous one).
    #[inline]
    pub fn call(&mut self, kind: S5Kind, t_ms: u64, input: S5Input) -> S5Output {
        if self.cell.0 & RUNNING != 0 {
            let n = super::ticks_between(self.t_prev, t_ms, self.cell.base());
            self.cell = self.cell.tick(n);
        }
        self.t_prev = t_ms;
        self.cell = self.cell.execute(kind, input);
        self.cell.output()
    }
}

/// The abstraction function: the reference state a cell represents.
pub const fn abstraction(cell: Cell) -> S5State {
    let w = cell.0;
    S5State {
        running: w & RUNNING != 0,
        value: w & VALUE,
        base: TimeBase::from_bits((w >> 12) as u8),
        q: w & Q != 0,
        s_prev: w & S_PREV != 0,
        fr_prev: w & FR_PREV != 0,
    }
}
