//! A counter memory area of S5 counters (`C 0` .. `C N-1`), with the STL operations on it.

use super::word::S5Counter;
use super::{
    CounterPreset, S5CounterInput, S5CounterKind, S5CounterOps, S5CounterOutput, S5CounterRef,
    S5CounterState,
};
use crate::operand::{self, NoSuchOperand, Operand};
use crate::rule::{Explained, Explanation};

/// A counter memory area of `N` S5 counters (256 by default).
///
/// The LAD boxes ([`CounterMemory::call`]) and the STL operations ([`CounterMemory::cu`],
/// [`CounterMemory::cd`], [`CounterMemory::set`], [`CounterMemory::reset`],
/// [`CounterMemory::fr`], [`CounterMemory::load`], …) act on the same words; each operation
/// evaluates and stores only its own input's edge memory (SC-STL-01).
///
/// ```
/// use plc_timers::counter::s5::{CounterMemory, CounterPreset, S5CounterInput, S5CounterKind};
///
/// // A scan loop: C 0 counts parts on a rising sensor, C 1 is loaded with 10 and counts down.
/// let mut counters = CounterMemory::<2>::new();
/// let ten = CounterPreset::new(10).expect("0..=999");
/// counters.set(1, true, ten)?;
/// for sensor in [true, false, true, false, true] {
///     counters.call(0, S5CounterKind::SCu, S5CounterInput { cu: sensor, ..Default::default() })?;
///     counters.cd(1, sensor)?;
/// }
/// assert_eq!(counters.load(0)?, 3);
/// assert_eq!(counters.load_bcd(1)?, 0x0007);
/// let q: Vec<bool> = counters.outputs().map(|o| o.q).collect();
/// assert_eq!(q, [true, true]);
/// # Ok::<(), plc_timers::NoSuchOperand>(())
/// ```
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct CounterMemory<const N: usize = 256> {
    words: [S5Counter; N],
}

impl<const N: usize> Default for CounterMemory<N> {
    fn default() -> Self {
        CounterMemory::new()
    }
}

impl<const N: usize> CounterMemory<N> {
    /// The number of counters.
    pub const LEN: usize = N;

    /// An area of cleared counters.
    ///
    /// ```
    /// use plc_timers::counter::s5::CounterMemory;
    /// let area = CounterMemory::<8>::new();
    /// assert_eq!(area.load(7), Ok(0));
    /// ```
    pub const fn new() -> CounterMemory<N> {
        CounterMemory {
            words: [S5Counter::new(); N],
        }
    }

    /// The counter words.
    pub const fn words(&self) -> &[S5Counter; N] {
        &self.words
    }

    /// The state of counter `index`.
    pub fn get(&self, index: usize) -> Result<S5CounterState, NoSuchOperand> {
        self.read(index).map(S5Counter::state)
    }

    /// Puts counter `index` in `state`; `Ok(false)` (and no change) when the state is not valid.
    #[must_use = "`Ok(false)` says the state was not valid and the operand did not change"]
    pub fn set_state(
        &mut self,
        index: usize,
        state: S5CounterState,
    ) -> Result<bool, NoSuchOperand> {
        let w = self.word(index)?;
        Ok(match S5Counter::from_state(state) {
            Some(new) => {
                *w = new;
                true
            }
            None => false,
        })
    }

    /// The outputs (Q, CV, CV_BCD) of every counter, `C 0` first.
    pub fn outputs(&self) -> impl ExactSizeIterator<Item = S5CounterOutput> + '_ {
        self.words.iter().map(|w| w.output())
    }

    fn word(&mut self, index: usize) -> Result<&mut S5Counter, NoSuchOperand> {
        operand::word_mut(&mut self.words, Operand::Counter, index)
    }

    fn read(&self, index: usize) -> Result<S5Counter, NoSuchOperand> {
        operand::word(&self.words, Operand::Counter, index)
    }

    fn apply(
        &mut self,
        index: usize,
        op: impl FnOnce(S5Counter) -> S5Counter,
    ) -> Result<(), NoSuchOperand> {
        let w = self.word(index)?;
        *w = op(*w);
        Ok(())
    }

    /// `FR C n` with RLO `rlo`: a rising RLO clears the edge memories of CU, CD and S (SC-FR-01).
    pub fn fr(&mut self, index: usize, rlo: bool) -> Result<(), NoSuchOperand> {
        self.apply(index, |w| w.enable(rlo))
    }

    /// `CU C n` (`ZV Z n`) with RLO `rlo`: count up on a rising RLO.
    pub fn cu(&mut self, index: usize, rlo: bool) -> Result<(), NoSuchOperand> {
        self.apply(index, |w| w.count_up(rlo))
    }

    /// `CD C n` (`ZR Z n`) with RLO `rlo`: count down on a rising RLO.
    pub fn cd(&mut self, index: usize, rlo: bool) -> Result<(), NoSuchOperand> {
        self.apply(index, |w| w.count_down(rlo))
    }

    /// `S C n` with RLO `rlo` and the preset in ACCU 1: set CV to PV on a rising RLO.
    pub fn set(&mut self, index: usize, rlo: bool, pv: CounterPreset) -> Result<(), NoSuchOperand> {
        self.apply(index, |w| w.set(rlo, pv))
    }

    /// `R C n` with RLO `rlo`: CV = 0 while 1.
    pub fn reset(&mut self, index: usize, rlo: bool) -> Result<(), NoSuchOperand> {
        self.apply(index, |w| w.reset(rlo))
    }

    /// `L C n`: CV in binary.
    pub fn load(&self, index: usize) -> Result<u16, NoSuchOperand> {
        self.read(index).map(|c| c.output().cv)
    }

    /// `LC C n`: CV in BCD.
    pub fn load_bcd(&self, index: usize) -> Result<u16, NoSuchOperand> {
        self.read(index).map(|c| c.output().cv_bcd)
    }

    /// `A C n`: Q = CV != 0.
    pub fn status(&self, index: usize) -> Result<bool, NoSuchOperand> {
        self.read(index).map(|c| c.output().q)
    }

    /// The box `kind` on counter `index`: all its inputs in one call.
    pub fn call(
        &mut self,
        index: usize,
        kind: S5CounterKind,
        input: S5CounterInput,
    ) -> Result<S5CounterOutput, NoSuchOperand> {
        let w = self.word(index)?;
        *w = w.execute(kind, input);
        Ok(w.output())
    }

    /// Runs `op` on the reference counter in the state of counter `index`, stores the state it
    /// leaves, and gives the outputs with the rules `op` recorded: the reference path of the
    /// explained operations (the words have no recorder).
    fn explained(
        &mut self,
        index: usize,
        op: impl FnOnce(&mut S5CounterRef, &mut Explanation),
    ) -> Result<Explained<S5CounterOutput>, NoSuchOperand> {
        let w = self.word(index)?;
        let mut rec = Explanation::default();
        // A word always holds a valid state, and the reference keeps it valid (SC-RANGE-01).
        if let Some(mut counter) = S5CounterRef::from_state(w.state()) {
            op(&mut counter, &mut rec);
            if let Some(new) = S5Counter::from_state(counter.state()) {
                *w = new;
            }
        }
        Ok(rec.finish(w.output()))
    }

    /// [`CounterMemory::call`], explained through the reference
    /// ([`S5CounterRef::call_explained`]): the same outputs and words, with the rules that
    /// decided them.
    ///
    /// ```
    /// use plc_timers::counter::s5::{CounterMemory, S5CounterInput, S5CounterKind};
    /// use plc_timers::rule::Rule;
    /// let mut counters = CounterMemory::<1>::new();
    /// let e = counters.call_explained(0, S5CounterKind::SCd, S5CounterInput { cd: true, ..Default::default() })?;
    /// assert!(e.outputs[1].contains(Rule::SC_SAT_01)); // CV: 0 stays 0
    /// # Ok::<(), plc_timers::NoSuchOperand>(())
    /// ```
    pub fn call_explained(
        &mut self,
        index: usize,
        kind: S5CounterKind,
        input: S5CounterInput,
    ) -> Result<Explained<S5CounterOutput>, NoSuchOperand> {
        self.explained(index, |c, rec| {
            c.call_rec(kind, input, rec);
        })
    }

    /// [`CounterMemory::fr`] (`FR C n`), explained.
    ///
    /// ```
    /// use plc_timers::counter::s5::{CounterMemory, CounterPreset};
    /// use plc_timers::rule::Rule;
    /// let mut counters = CounterMemory::<1>::new();
    /// assert!(counters.fr_explained(0, true)?.state.contains(Rule::SC_FR_01));
    /// # Ok::<(), plc_timers::NoSuchOperand>(())
    /// ```
    pub fn fr_explained(
        &mut self,
        index: usize,
        rlo: bool,
    ) -> Result<Explained<S5CounterOutput>, NoSuchOperand> {
        self.explained(index, |c, rec| c.enable_rec(rlo, rec))
    }

    /// [`CounterMemory::cu`] (`CU C n`), explained.
    ///
    /// ```
    /// use plc_timers::counter::s5::{CounterMemory, CounterPreset};
    /// use plc_timers::rule::Rule;
    /// let mut counters = CounterMemory::<1>::new();
    /// assert!(counters.cu_explained(0, true)?.state.contains(Rule::SC_EDGE_01));
    /// # Ok::<(), plc_timers::NoSuchOperand>(())
    /// ```
    pub fn cu_explained(
        &mut self,
        index: usize,
        rlo: bool,
    ) -> Result<Explained<S5CounterOutput>, NoSuchOperand> {
        self.explained(index, |c, rec| c.count_up_rec(rlo, rec))
    }

    /// [`CounterMemory::cd`] (`CD C n`), explained.
    ///
    /// ```
    /// use plc_timers::counter::s5::{CounterMemory, CounterPreset};
    /// use plc_timers::rule::Rule;
    /// let mut counters = CounterMemory::<1>::new();
    /// assert!(counters.cd_explained(0, true)?.state.contains(Rule::SC_EDGE_01));
    /// # Ok::<(), plc_timers::NoSuchOperand>(())
    /// ```
    pub fn cd_explained(
        &mut self,
        index: usize,
        rlo: bool,
    ) -> Result<Explained<S5CounterOutput>, NoSuchOperand> {
        self.explained(index, |c, rec| c.count_down_rec(rlo, rec))
    }

    /// [`CounterMemory::set`] (`S C n`), explained.
    ///
    /// ```
    /// use plc_timers::counter::s5::{CounterMemory, CounterPreset};
    /// use plc_timers::rule::Rule;
    /// let mut counters = CounterMemory::<1>::new();
    /// assert!(counters.set_explained(0, true, CounterPreset::new(3).expect("0..=999"))?.state.contains(Rule::SC_SET_01));
    /// # Ok::<(), plc_timers::NoSuchOperand>(())
    /// ```
    pub fn set_explained(
        &mut self,
        index: usize,
        rlo: bool,
        pv: CounterPreset,
    ) -> Result<Explained<S5CounterOutput>, NoSuchOperand> {
        self.explained(index, |c, rec| c.set_rec(rlo, pv, rec))
    }

    /// [`CounterMemory::reset`] (`R C n`), explained.
    ///
    /// ```
    /// use plc_timers::counter::s5::{CounterMemory, CounterPreset};
    /// use plc_timers::rule::Rule;
    /// let mut counters = CounterMemory::<1>::new();
    /// assert!(counters.reset_explained(0, true)?.state.contains(Rule::SC_PRIO_01));
    /// # Ok::<(), plc_timers::NoSuchOperand>(())
    /// ```
    pub fn reset_explained(
        &mut self,
        index: usize,
        rlo: bool,
    ) -> Result<Explained<S5CounterOutput>, NoSuchOperand> {
        self.explained(index, |c, rec| c.reset_rec(rlo, rec))
    }
}

impl<const N: usize> CounterMemory<N> {
    /// SC-RETAIN-01: a RUN-STOP-RUN. The first `retentive` counters (`C 0` .. `C retentive-1`:
    /// the S7-300/400 CPUs' retentivity setting, "number of counters from C 0", recalled) keep
    /// their words and the others are cleared; 0 clears all, `N` or more keeps all.
    ///
    /// ```
    /// use plc_timers::counter::s5::{CounterMemory, CounterPreset};
    /// let mut area = CounterMemory::<2>::new();
    /// let five = CounterPreset::new(5).expect("0..=999");
    /// area.set(0, true, five)?;
    /// area.set(1, true, five)?;
    /// area.run_stop_run(1); // C 0 retentive, C 1 not
    /// assert_eq!((area.load(0)?, area.load(1)?), (5, 0));
    /// # Ok::<(), plc_timers::NoSuchOperand>(())
    /// ```
    pub fn run_stop_run(&mut self, retentive: usize) {
        for w in self.words.iter_mut().skip(retentive) {
            w.run_stop_run(false);
        }
    }
}
