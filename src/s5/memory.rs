//! A timer memory area (seed 000 §9.1: "timers have their own reserved memory area in the CPU;
//! a 16-bit word for each timer"; LAD addresses 256) with the STL operations on it.
//!
//! The operating system's tick of each base updates every running timer of that base in one
//! pass over the area ([`TimerMemory::tick`]); the STL operations act on one timer.

use core::fmt;

use super::cell::{Cell, BASE, RUNNING};
use super::{S5Input, S5Kind, S5Output};
use crate::time::{S5Time, TimeBase};

/// An STL operation named a timer the area does not have.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct NoSuchTimer {
    /// The timer number given.
    pub index: usize,
    /// How many timers the area has (`T 0` .. `T count-1`).
    pub count: usize,
}

impl fmt::Display for NoSuchTimer {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(
            f,
            "no timer T {}: this area has T 0 to T {}",
            self.index,
            self.count.saturating_sub(1)
        )
    }
}

#[cfg(feature = "std")]
impl std::error::Error for NoSuchTimer {}

/// A timer memory area of `N` timers (256 by default, the number LAD can address) and the CPU
/// time up to which the operating system's ticks have been applied.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct TimerMemory<const N: usize = 256> {
    cells: [Cell; N],
    now: u64,
}

impl<const N: usize> Default for TimerMemory<N> {
    fn default() -> Self {
        TimerMemory::new()
    }
}

impl<const N: usize> TimerMemory<N> {
    /// An area of cleared timers at CPU time 0.
    pub const fn new() -> TimerMemory<N> {
        TimerMemory {
            cells: [Cell::RESET; N],
            now: 0,
        }
    }

    /// An area holding `cells`, with the OS ticks applied up to `now` (for restoring a saved
    /// area, and for the proofs).
    pub const fn from_cells(cells: [Cell; N], now: u64) -> TimerMemory<N> {
        TimerMemory { cells, now }
    }

    /// The cells, for inspection (and for the abstraction function of each timer).
    pub const fn cells(&self) -> &[Cell; N] {
        &self.cells
    }

    /// The CPU time up to which ticks have been applied.
    pub const fn now(&self) -> u64 {
        self.now
    }

    fn cell(&mut self, index: usize) -> Result<&mut Cell, NoSuchTimer> {
        self.cells
            .get_mut(index)
            .ok_or(NoSuchTimer { index, count: N })
    }

    fn read(&self, index: usize) -> Result<Cell, NoSuchTimer> {
        self.cells
            .get(index)
            .copied()
            .ok_or(NoSuchTimer { index, count: N })
    }

    /// `n` ticks of `base` for the whole area: every running timer of that base loses
    /// `min(n, value)` units (S5TMR-TICK-01). One branch-free pass over the words.
    pub fn tick(&mut self, base: TimeBase, n: u64) {
        if n == 1 {
            let bits = u16::from(base.bits());
            for cell in self.cells.iter_mut() {
                *cell = cell.tick_once(bits);
            }
            return;
        }
        let b = (base.bits() as u16) << 12;
        for cell in self.cells.iter_mut() {
            // Cells of another base are ticked with 0, which leaves them unchanged; selecting
            // with arithmetic instead of a branch keeps the loop vectorizable.
            let mine = (cell.0 & BASE == b) as u64;
            *cell = cell.tick(n * mine);
        }
    }

    /// Advances the CPU clock to `t_ms`, applying the ticks of every base in `(now, t_ms]`.
    /// A time before the current one applies no ticks.
    pub fn advance_to(&mut self, t_ms: u64) {
        if t_ms <= self.now {
            return;
        }
        // Only the bases of running timers need their ticks counted (each count is two
        // divisions); one pass collects them.
        let mut present = 0u8;
        for cell in self.cells.iter() {
            present |= u8::from(cell.0 & RUNNING != 0) << (cell.0 >> 12 & 3);
        }
        for base in TimeBase::ALL {
            if present & 1 << base.bits() != 0 {
                let n = super::ticks_between(self.now, t_ms, base);
                if n > 0 {
                    self.tick(base, n);
                }
            }
        }
        self.now = t_ms;
    }

    /// `FR T n` with RLO `fr` (enable), for a timer that the program starts with `kind`.
    pub fn fr(&mut self, index: usize, kind: S5Kind, fr: bool) -> Result<(), NoSuchTimer> {
        let c = self.cell(index)?;
        *c = c.enable(kind, fr);
        Ok(())
    }

    /// `SP`/`SE`/`SD`/`SS`/`SF T n` with RLO `s`, the time value `tv` loaded in ACCU 1.
    pub fn start(
        &mut self,
        index: usize,
        kind: S5Kind,
        s: bool,
        tv: S5Time,
    ) -> Result<(), NoSuchTimer> {
        let c = self.cell(index)?;
        *c = c.start(kind, s, tv);
        Ok(())
    }

    /// `R T n` with RLO `r`.
    pub fn reset(&mut self, index: usize, r: bool) -> Result<(), NoSuchTimer> {
        let c = self.cell(index)?;
        *c = c.reset(r);
        Ok(())
    }

    /// `L T n`: the remaining value in binary (S5TMR-LOAD-01).
    pub fn load(&self, index: usize) -> Result<u16, NoSuchTimer> {
        self.read(index).map(Cell::value)
    }

    /// `LC T n`: the remaining value in BCD with the base in bits 13-12 (S5TMR-LOAD-01).
    pub fn load_bcd(&self, index: usize) -> Result<u16, NoSuchTimer> {
        self.read(index).map(Cell::bcd)
    }

    /// `A T n`: the timer status (`AN T n` is its negation).
    pub fn status(&self, index: usize) -> Result<bool, NoSuchTimer> {
        self.read(index).map(Cell::q)
    }

    /// The LAD box at CPU time `t_ms`: the OS ticks up to `t_ms`, then `FR`, the start
    /// operation and `R`, as the box compiles to STL.
    pub fn call(
        &mut self,
        index: usize,
        kind: S5Kind,
        t_ms: u64,
        input: S5Input,
    ) -> Result<S5Output, NoSuchTimer> {
        self.advance_to(t_ms);
        let c = self.cell(index)?;
        *c = c.execute(kind, input);
        Ok(c.output())
    }
}
