//! A timer memory area (LAD manual §9.1: "timers have their own reserved memory area in the
//! CPU; a 16-bit word for each timer"; LAD addresses 256) with the STL operations on it.
//!
//! The operating system's tick of each base updates every running timer of that base in one
//! pass over the area ([`TimerMemory::tick`]); the STL operations act on one timer.

use super::word::{ticks_between_fast, TimerWord};
use super::{S5Input, S5Kind, S5Output, S5State, S5TimerOps, S5TimerRef};
use crate::operand::{self, NoSuchOperand, Operand};
use crate::rule::{Explained, Explanation};
use crate::time::{CpuTime, S5Time, TimeBase};

/// A timer memory area of `N` timers (`T 0` .. `T N-1`; 256 by default, the number LAD can
/// address) and the CPU time up to which the operating system's ticks have been applied.
///
/// # Which method when
/// - **A program of LAD boxes** (one box per timer per scan): [`TimerMemory::call`]. It first
///   brings the area's clock to the call's time ([`TimerMemory::advance_to`]), then executes
///   the box, exactly like [`super::S5TimerRef`] does for one timer.
/// - **An STL program** (`FR`, `SP`…`SF`, `R`, `L`, `LC`, `A` on timer operands): call
///   [`TimerMemory::advance_to`] once per scan (or whenever the program reads the clock), then
///   the operations ([`TimerMemory::start`], [`TimerMemory::reset`], [`TimerMemory::load`], …),
///   which act on the words as they are.
/// - **A runtime that owns the OS time base**, with an interrupt every 10 ms, 100 ms, 1 s and
///   10 s: [`TimerMemory::tick`] with the base that fired, and no `advance_to` (the two keep
///   time in different ways; use one of them).
///
/// ```
/// use plc_timers::s5::{S5Input, S5Kind, TimerMemory};
/// use plc_timers::time::CpuTime;
///
/// // A scan loop: T 0 an on-delay of 30 ms, T 1 a pulse of 1 s, every 10 ms.
/// let mut timers = TimerMemory::<2>::new();
/// let (delay, pulse) = (plc_timers::s5time!("S5T#30MS"), plc_timers::s5time!("S5T#1S"));
/// for scan in 0..5u64 {
///     let now = CpuTime::from_millis(10 * scan);
///     let sd = timers.call(0, S5Kind::SOdt, now, S5Input::new(true, false, delay))?;
///     let sp = timers.call(1, S5Kind::SPulse, now, S5Input::new(true, false, pulse))?;
///     assert_eq!(sd.q, scan >= 3); // on after three 10 ms ticks
///     assert!(sp.q);
/// }
/// let running: Vec<bool> = timers.outputs().map(|o| o.q).collect();
/// assert_eq!(running, [true, true]);
/// # Ok::<(), plc_timers::NoSuchOperand>(())
/// ```
///
/// # Representation
///
/// Per timer, a 16-bit cell with everything the OS tick reads and writes (value and base where
/// the CPU's timer word has them, RUNNING, Q and the expiry status in the bits the CPU's word
/// leaves 0), and a byte with the edge memories of S and FR, which only the operations use
/// ([`TimerWord`] holds the same fields in one 32-bit word: 17 bits of fields do not fit 16).
/// So a tick reads and writes 2 bytes per timer, the size of the S7 timer word, and the
/// operations convert a timer's cell and edges to its [`TimerWord`] and back.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct TimerMemory<const N: usize = 256> {
    /// Per timer: [`TimerWord::to_cell`]'s cell.
    cells: [u16; N],
    /// Per timer: [`TimerWord::to_cell`]'s edge byte.
    edges: [u8; N],
    now: CpuTime,
}

impl<const N: usize> Default for TimerMemory<N> {
    fn default() -> Self {
        TimerMemory::new()
    }
}

impl<const N: usize> TimerMemory<N> {
    /// The number of timers.
    pub const LEN: usize = N;

    /// An area of cleared timers at CPU time 0.
    ///
    /// ```
    /// use plc_timers::s5::TimerMemory;
    /// let area: TimerMemory = TimerMemory::new(); // 256 timers, as LAD can address
    /// assert_eq!((TimerMemory::<256>::LEN, area.status(255)), (256, Ok(false)));
    /// ```
    pub const fn new() -> TimerMemory<N> {
        TimerMemory {
            cells: [0; N],
            edges: [0; N],
            now: CpuTime::ZERO,
        }
    }

    /// An area holding `words`, with the OS ticks applied up to `now` (for restoring a saved
    /// area, and for the proofs).
    ///
    /// ```
    /// use plc_timers::s5::{S5Input, S5Kind, TimerMemory, TimerWord};
    /// use plc_timers::time::CpuTime;
    /// let running = TimerWord::RESET.execute(S5Kind::SPext, S5Input::new(true, false, plc_timers::s5time!("S5T#1S")));
    /// let mut area = TimerMemory::from_words([running, TimerWord::RESET], CpuTime::from_millis(5_000));
    /// area.advance_to(CpuTime::from_millis(5_300)); // S5T#1S is 100 units of 10 ms: 30 ticks
    /// assert_eq!(area.load(0), Ok(70));
    /// ```
    pub const fn from_words(words: [TimerWord; N], now: CpuTime) -> TimerMemory<N> {
        let mut area = TimerMemory::new();
        area.now = now;
        let mut i = 0;
        while i < N {
            (area.cells[i], area.edges[i]) = words[i].to_cell();
            i += 1;
        }
        area
    }

    /// The timer words, `T 0` first.
    ///
    /// ```
    /// use plc_timers::s5::{TimerMemory, TimerWord};
    /// let area = TimerMemory::<3>::new();
    /// assert!(area.words().all(|w| w == TimerWord::RESET));
    /// ```
    pub fn words(&self) -> impl ExactSizeIterator<Item = TimerWord> + '_ {
        self.cells
            .iter()
            .zip(&self.edges)
            .map(|(&c, &e)| TimerWord::from_cell(c, e))
    }

    /// The CPU time up to which ticks have been applied.
    pub const fn now(&self) -> CpuTime {
        self.now
    }

    /// The state of timer `index`.
    pub fn get(&self, index: usize) -> Result<S5State, NoSuchOperand> {
        self.read(index).map(TimerWord::state)
    }

    /// Puts timer `index` in `state`; `Ok(false)` (and no change) when the state is not valid.
    #[must_use = "`Ok(false)` says the state was not valid and the operand did not change"]
    pub fn set_state(&mut self, index: usize, state: S5State) -> Result<bool, NoSuchOperand> {
        self.read(index)?;
        Ok(match TimerWord::from_state(state) {
            Some(new) => {
                self.write(index, new);
                true
            }
            None => false,
        })
    }

    /// The outputs (Q, BI, BCD) of every timer, `T 0` first.
    pub fn outputs(&self) -> impl ExactSizeIterator<Item = S5Output> + '_ {
        self.words().map(TimerWord::output)
    }

    /// Timer `index`'s word with `op` applied, stored back; the new word.
    fn update(
        &mut self,
        index: usize,
        op: impl FnOnce(TimerWord) -> TimerWord,
    ) -> Result<TimerWord, NoSuchOperand> {
        let w = op(self.read(index)?);
        self.write(index, w);
        Ok(w)
    }

    /// Timer `index`'s word (the index checked, with the error that names the area's range).
    fn read(&self, index: usize) -> Result<TimerWord, NoSuchOperand> {
        let cell = operand::word(&self.cells, Operand::Timer, index)?;
        Ok(TimerWord::from_cell(cell, self.edges[index]))
    }

    /// Stores `w` as timer `index` (`index < N`, checked by [`TimerMemory::read`] before).
    fn write(&mut self, index: usize, w: TimerWord) {
        (self.cells[index], self.edges[index]) = w.to_cell();
    }

    /// `n` ticks of `base` for the whole area: every running timer of that base loses
    /// `min(n, value)` units (S5TMR-TICK-01). One pass over the 16-bit cells (2 bytes per
    /// timer; the edge memories are not touched), which LLVM vectorizes: for one tick, 32
    /// cells at a time by subtraction alone unless one of them runs out
    /// ([`TimerWord::tick_once`] then does those 32); for more, branch-free.
    pub fn tick(&mut self, base: TimeBase, n: u64) {
        let bits = u32::from(base.bits());
        if n == 1 {
            // The OS tick as it comes: one unit, the commonest case, with the least work.
            crate::simd::run(TickOnce {
                cells: &mut self.cells,
                bits,
            });
            return;
        }
        // A value is at most 999 units, so any count from 1 000 on acts as 1 000: the count
        // fits the 32-bit lanes of the words ([`TimerWord::tick_units`]). A tick changes no
        // edge memory, so the cells go through the word with edges 0.
        let n = n.min(1_000) as u32;
        for c in self.cells.iter_mut() {
            *c = TimerWord::from_cell(*c, 0).tick_units(bits, n).to_cell().0;
        }
    }

    /// Advances the area's clock to `now`, applying the ticks of every base in
    /// `(self.now(), now]`. A time before the current one applies no ticks.
    ///
    /// The tick counts are computed without a division instruction (`ticks_between_fast`,
    /// exact for every time), and a base is processed only when it has ticked: one pass over
    /// the area for the 10 ms base, a second one on every tenth 10 ms, and so on.
    pub fn advance_to(&mut self, now: CpuTime) {
        if now <= self.now {
            return;
        }
        for base in TimeBase::ALL {
            let n = ticks_between_fast(self.now, now, usize::from(base.bits()));
            if n > 0 {
                self.tick(base, n);
            }
        }
        self.now = now;
    }

    /// `FR T n` with RLO `fr` (enable): a rising RLO clears the start edge memory.
    pub fn fr(&mut self, index: usize, fr: bool) -> Result<(), NoSuchOperand> {
        self.update(index, |w| w.enable(fr)).map(drop)
    }

    /// `SP`/`SE`/`SD`/`SS`/`SF T n` with RLO `s`, the time value `tv` loaded in ACCU 1.
    pub fn start(
        &mut self,
        index: usize,
        kind: S5Kind,
        s: bool,
        tv: S5Time,
    ) -> Result<(), NoSuchOperand> {
        self.update(index, |w| w.start(kind, s, tv)).map(drop)
    }

    /// `R T n` with RLO `r`.
    pub fn reset(&mut self, index: usize, r: bool) -> Result<(), NoSuchOperand> {
        self.update(index, |w| w.reset(r)).map(drop)
    }

    /// `L T n`: the remaining value in binary (S5TMR-LOAD-01).
    pub fn load(&self, index: usize) -> Result<u16, NoSuchOperand> {
        self.read(index).map(TimerWord::value)
    }

    /// `LC T n`: the remaining value in BCD with the base in bits 13-12 (S5TMR-LOAD-01).
    pub fn load_bcd(&self, index: usize) -> Result<u16, NoSuchOperand> {
        self.read(index).map(TimerWord::bcd)
    }

    /// `A T n`: the timer status (`AN T n` is its negation).
    pub fn status(&self, index: usize) -> Result<bool, NoSuchOperand> {
        self.read(index).map(TimerWord::q)
    }

    /// The LAD box `kind` on timer `index` at CPU time `now`: the OS ticks up to `now`, then
    /// `FR`, the start operation and `R`, as the box compiles to STL.
    pub fn call(
        &mut self,
        index: usize,
        kind: S5Kind,
        now: CpuTime,
        input: S5Input,
    ) -> Result<S5Output, NoSuchOperand> {
        // Check the operand before the clock moves, so that an error changes nothing.
        self.read(index)?;
        self.advance_to(now);
        self.update(index, |w| w.execute(kind, input))
            .map(TimerWord::output)
    }

    /// Runs `op` on the reference timer in the state of timer `index` (its previous execution
    /// at the area's clock, so that it applies the ticks the area would), stores the state it
    /// leaves, and gives the outputs with the rules `op` recorded. This is the reference path
    /// of the explained operations: the words themselves have no recorder.
    fn explained(
        &mut self,
        index: usize,
        op: impl FnOnce(&mut S5TimerRef, &mut Explanation),
    ) -> Result<Explained<S5Output>, NoSuchOperand> {
        let state = self.read(index)?.state();
        let mut rec = Explanation::default();
        // A word always holds a valid state, so the reference accepts it.
        let Some(mut timer) = S5TimerRef::from_state(state, self.now) else {
            return Ok(rec.finish(self.read(index)?.output()));
        };
        op(&mut timer, &mut rec);
        // The reference keeps its state valid (S5TMR-RANGE-01), so the word takes it.
        if let Some(new) = TimerWord::from_state(timer.state()) {
            self.write(index, new);
        }
        Ok(rec.finish(self.read(index)?.output()))
    }

    /// [`TimerMemory::call`], explained through the reference ([`S5TimerRef::call_explained`]):
    /// the same outputs and words (S5-EQUIV-02), with the rules that decided them.
    ///
    /// ```
    /// use plc_timers::rule::Rule;
    /// use plc_timers::s5::{S5Input, S5Kind, TimerMemory};
    /// use plc_timers::time::CpuTime;
    ///
    /// let mut timers = TimerMemory::<1>::new();
    /// let on = S5Input::new(true, false, plc_timers::s5time!("S5T#20MS"));
    /// let e = timers.call_explained(0, S5Kind::SOdt, CpuTime::ZERO, on)?;
    /// assert!(e.outputs[1].contains(Rule::SD_Q_01)); // BI: loaded by the start
    /// let e = timers.call_explained(0, S5Kind::SOdt, CpuTime::from_millis(20), on)?;
    /// assert!(e.output.q && e.outputs[0].contains(Rule::S5TMR_TICK_01));
    /// # Ok::<(), plc_timers::NoSuchOperand>(())
    /// ```
    pub fn call_explained(
        &mut self,
        index: usize,
        kind: S5Kind,
        now: CpuTime,
        input: S5Input,
    ) -> Result<Explained<S5Output>, NoSuchOperand> {
        let from = self.now;
        // The area's clock does not go back: no tick before `from`, as in `call`.
        let e = self.explained(index, |t, rec| {
            t.call_rec(kind, now.max(from), input, rec);
        })?;
        self.advance_to_except(now, index);
        Ok(e)
    }

    /// [`TimerMemory::fr`], explained: the rule that acted (S5TMR-FR-01), if any.
    ///
    /// ```
    /// use plc_timers::rule::Rule;
    /// use plc_timers::s5::TimerMemory;
    /// let mut timers = TimerMemory::<1>::new();
    /// assert!(timers.fr_explained(0, true)?.state.contains(Rule::S5TMR_FR_01));
    /// assert!(timers.fr_explained(0, true)?.state.is_empty()); // FR held does nothing
    /// # Ok::<(), plc_timers::NoSuchOperand>(())
    /// ```
    pub fn fr_explained(
        &mut self,
        index: usize,
        fr: bool,
    ) -> Result<Explained<S5Output>, NoSuchOperand> {
        self.explained(index, |t, rec| t.fr_rec(fr, rec))
    }

    /// [`TimerMemory::start`], explained.
    ///
    /// ```
    /// use plc_timers::rule::Rule;
    /// use plc_timers::s5::{S5Kind, TimerMemory};
    /// let mut timers = TimerMemory::<1>::new();
    /// let e = timers.start_explained(0, S5Kind::SPext, true, plc_timers::s5time!("S5T#1S"))?;
    /// assert!(e.output.q && e.outputs[0].contains(Rule::SE_RUN_ON_01) && e.outputs[0].contains(Rule::S5TMR_EDGE_01));
    /// # Ok::<(), plc_timers::NoSuchOperand>(())
    /// ```
    pub fn start_explained(
        &mut self,
        index: usize,
        kind: S5Kind,
        s: bool,
        tv: S5Time,
    ) -> Result<Explained<S5Output>, NoSuchOperand> {
        self.explained(index, |t, rec| {
            t.start_rec(kind, &S5Input::new(s, false, tv), rec)
        })
    }

    /// [`TimerMemory::reset`], explained.
    ///
    /// ```
    /// use plc_timers::rule::Rule;
    /// use plc_timers::s5::TimerMemory;
    /// let mut timers = TimerMemory::<1>::new();
    /// assert_eq!(timers.reset_explained(0, true)?.outputs[0].iter().next(), Some(Rule::S5TMR_R_01));
    /// # Ok::<(), plc_timers::NoSuchOperand>(())
    /// ```
    pub fn reset_explained(
        &mut self,
        index: usize,
        r: bool,
    ) -> Result<Explained<S5Output>, NoSuchOperand> {
        self.explained(index, |t, rec| t.reset_rec(r, rec))
    }

    /// [`TimerMemory::advance_to`] for every timer but `index`, whose ticks the reference
    /// applied already.
    fn advance_to_except(&mut self, now: CpuTime, index: usize) {
        if now <= self.now {
            return;
        }
        // `index` was checked by the caller's `read`.
        let keep = (self.cells[index], self.edges[index]);
        self.advance_to(now);
        (self.cells[index], self.edges[index]) = keep;
    }
}

/// One tick of every cell ([`TimerWord::tick_once_cells`]) as a loop for [`crate::simd::run`].
struct TickOnce<'a> {
    cells: &'a mut [u16],
    bits: u32,
}

impl crate::simd::Kernel for TickOnce<'_> {
    #[inline(always)]
    fn run(self) {
        TimerWord::tick_once_cells(self.cells, self.bits);
    }
}

impl<const N: usize> TimerMemory<N> {
    /// S5TMR-RETAIN-01: a RUN-STOP-RUN, the CPU in STOP from `stop` to `restart`. The area's
    /// clock is advanced to `stop` ([`TimerMemory::advance_to`]); no OS tick falls in STOP (LAD
    /// manual §9.1: "in RUN mode"), so the clock then jumps to `restart` without ticks. At the
    /// restart the first `retentive` timers (`T 0` .. `T retentive-1`: the S7-300/400 CPUs'
    /// retentivity setting, "number of timers from T 0", recalled) keep their words and the
    /// others are cleared ([`TimerWord::RESET`]); 0 clears all, `N` or more keeps all. A time
    /// before the area's clock moves nothing back.
    ///
    /// ```
    /// use plc_timers::s5::{S5Input, S5Kind, TimerMemory};
    /// use plc_timers::time::CpuTime;
    /// let at = CpuTime::from_millis;
    /// let on = S5Input::new(true, false, plc_timers::s5time!("S5T#100MS"));
    /// let mut area = TimerMemory::<2>::new();
    /// area.call(0, S5Kind::SPext, at(0), on)?;
    /// area.call(1, S5Kind::SPext, at(0), on)?;
    /// area.run_stop_run(at(40), at(5_000), 1); // T 0 retentive, T 1 not
    /// area.advance_to(at(5_030));
    /// assert_eq!((area.load(0)?, area.load(1)?), (3, 0));
    /// # Ok::<(), plc_timers::NoSuchOperand>(())
    /// ```
    pub fn run_stop_run(&mut self, stop: CpuTime, restart: CpuTime, retentive: usize) {
        self.advance_to(stop);
        self.now = self.now.max(restart);
        for index in retentive.min(N)..N {
            self.write(index, TimerWord::RESET);
        }
    }
}
