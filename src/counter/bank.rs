//! A bank of CTUD counters in structure-of-arrays form, for a soft-PLC that scans thousands of
//! counters sharing one preset. Each counter behaves exactly as [`super::CounterRef`] called as
//! `CTUD` once per scan (CNT-EQUIV-01, checked in `proofs/counter.rs`).

use super::packed::{ctud_lanes, HAS_ALL};
use super::{outputs, CounterInt, CounterOutput, CounterState};
use crate::operand::{self, NoSuchOperand, Operand};

const CU_PREV: u8 = 0b01;
const CD_PREV: u8 = 0b10;

/// The inputs of one scan of a [`CounterBank`]: input `x[i]` belongs to counter `i`.
///
/// ```
/// use plc_timers::counter::{BankInputs, CounterBank};
/// let (on, off) = ([true; 2], [false; 2]);
/// let mut bank = CounterBank::<u8, 2>::new();
/// bank.scan(&BankInputs { cu: &on, cd: &off, r: &off, ld: &off }, 1);
/// assert_eq!(bank.output(1, 1).map(|o| o.qu), Ok(true));
/// ```
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct BankInputs<'a, const N: usize> {
    /// CU of every counter.
    pub cu: &'a [bool; N],
    /// CD of every counter.
    pub cd: &'a [bool; N],
    /// R of every counter.
    pub r: &'a [bool; N],
    /// LD of every counter.
    pub ld: &'a [bool; N],
}

/// `N` CTUD counters of integer type `T`, called together once per scan with one preset.
///
/// ```
/// use plc_timers::counter::{BankInputs, CounterBank};
///
/// // Parts counted on four lines, each batch of 3; line 2 is reset.
/// let mut lines = CounterBank::<i16, 4>::new();
/// let none = [false; 4];
/// let reset = [false, false, true, false];
/// for pulse in [true, false, true, false, true] {
///     let cu = [pulse, pulse, pulse, false];
///     lines.scan(&BankInputs { cu: &cu, cd: &none, r: &reset, ld: &none }, 3);
/// }
/// let full: Vec<bool> = lines.outputs(3).map(|o| o.qu).collect();
/// assert_eq!(full, [true, true, false, false]);
/// ```
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct CounterBank<T, const N: usize> {
    cv: [T; N],
    edges: [u8; N],
}

impl<T: CounterInt, const N: usize> Default for CounterBank<T, N> {
    fn default() -> Self {
        CounterBank::new()
    }
}

impl<T: CounterInt, const N: usize> CounterBank<T, N> {
    /// The number of counters.
    pub const LEN: usize = N;

    /// A bank of new counters.
    ///
    /// ```
    /// use plc_timers::counter::CounterBank;
    /// let bank = CounterBank::<i32, 100>::new();
    /// assert!(bank.outputs(0).all(|o| o.cv == 0 && o.qu));
    /// ```
    pub const fn new() -> CounterBank<T, N> {
        CounterBank {
            cv: [T::ZERO; N],
            edges: [0; N],
        }
    }

    /// The state of counter `i`.
    pub fn get(&self, i: usize) -> Result<CounterState<T>, NoSuchOperand> {
        let e = operand::word(&self.edges, Operand::Counter, i)?;
        Ok(CounterState {
            cv: self.cv[i],
            cu_prev: e & CU_PREV != 0,
            cd_prev: e & CD_PREV != 0,
        })
    }

    /// Puts counter `i` in `state` (every counter state is valid).
    pub fn set_state(&mut self, i: usize, state: CounterState<T>) -> Result<(), NoSuchOperand> {
        *operand::word_mut(&mut self.edges, Operand::Counter, i)? =
            (u8::from(state.cu_prev) * CU_PREV) | (u8::from(state.cd_prev) * CD_PREV);
        self.cv[i] = state.cv;
        Ok(())
    }

    /// The outputs of counter `i` for preset `pv`.
    pub fn output(&self, i: usize, pv: T) -> Result<CounterOutput<T>, NoSuchOperand> {
        operand::word(&self.cv, Operand::Counter, i).map(|cv| outputs(cv, pv))
    }

    /// The outputs of every counter for preset `pv`, counter 0 first.
    pub fn outputs(&self, pv: T) -> impl ExactSizeIterator<Item = CounterOutput<T>> + '_ {
        self.cv.iter().map(move |&cv| outputs(cv, pv))
    }

    /// One scan: every counter called once as CTUD with preset `pv`.
    ///
    /// The counters in groups of 16 through the same straight-line code, the lane code of
    /// [`super::Counter::call_for_arrays`] (the reference's CTUD, see there for why): the
    /// edges give a step of -1, 0 or 1, applied by saturating arithmetic, and R and LD choose
    /// by masks, without a branch, so that LLVM vectorizes each group (its bytes 16 counters
    /// per 128-bit instruction, its INT counts 8) and random edges cost no misprediction.
    pub fn scan(&mut self, inputs: &BankInputs<'_, N>, pv: T) {
        crate::simd::run(Scan {
            bank: self,
            inputs,
            pv,
        });
    }
}

/// [`CounterBank::scan`] as a loop for [`crate::simd::run`].
struct Scan<'a, 'b, T, const N: usize> {
    bank: &'a mut CounterBank<T, N>,
    inputs: &'a BankInputs<'b, N>,
    pv: T,
}

impl<T: CounterInt, const N: usize> crate::simd::Kernel for Scan<'_, '_, T, N> {
    #[inline(always)]
    fn run(self) {
        self.groups::<GROUP>();
    }

    #[inline(always)]
    fn run_wide(self) {
        self.groups::<WIDE_GROUP>();
    }
}

impl<T: CounterInt, const N: usize> Scan<'_, '_, T, N> {
    /// The scan in groups of `G` counters, the last `N % G` one at a time, all through the
    /// same lane code.
    #[inline(always)]
    fn groups<const G: usize>(self) {
        let Scan { bank, inputs, pv } = self;
        let (cv, cv_tail) = bank.cv.as_chunks_mut::<G>();
        let (edges, edges_tail) = bank.edges.as_chunks_mut::<G>();
        let (cu, cu_tail) = inputs.cu.as_chunks::<G>();
        let (cd, cd_tail) = inputs.cd.as_chunks::<G>();
        let (r, r_tail) = inputs.r.as_chunks::<G>();
        let (ld, ld_tail) = inputs.ld.as_chunks::<G>();
        let pvs = [pv; G];
        for (g, (cv, edges)) in cv.iter_mut().zip(edges.iter_mut()).enumerate() {
            ctud_lanes(cv, edges, [&cu[g], &cd[g], &r[g], &ld[g]], HAS_ALL, &pvs);
        }
        for (j, (cv, edges)) in cv_tail.iter_mut().zip(edges_tail.iter_mut()).enumerate() {
            let (cv, edges) = (core::array::from_mut(cv), core::array::from_mut(edges));
            let ins =
                [&cu_tail[j], &cd_tail[j], &r_tail[j], &ld_tail[j]].map(core::array::from_ref);
            ctud_lanes(cv, edges, ins, HAS_ALL, &[pv]);
        }
    }
}

/// Counters per group of the scan compiled for AVX2 and AVX-512 (`simd-dispatch`): one
/// AVX-512 vector of their bytes.
const WIDE_GROUP: usize = 64;

/// Counters per pass of [`CounterBank::scan`]'s lane code: one SSE2 vector of their bytes.
/// groups of 32 and 64 ran slower on SSE2 (`benches/peers`, one build each, against the same
/// 0.57 µs copy floor: 1.79-1.82 µs per scan of 10 048 INT counters with 32, 2.44-2.47 with
/// 64, 1.67 with 16), holding more vectors than SSE2's 16 registers.
const GROUP: usize = 16;
