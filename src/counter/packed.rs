//! The optimized IEC counters: [`PackedCounter`] (CV and the two edge memories in one small
//! struct, a branch-free step) and [`CounterBank`] (CTUD counters in structure-of-arrays form,
//! whose edges, resets and loads are found 64 counters at a time with word operations).

use super::{
    outputs, CounterInput, CounterInt, CounterKind, CounterOps, CounterOutput, CounterState,
};

const CU_PREV: u8 = 1;
const CD_PREV: u8 = 2;

/// One IEC counter: CV and a byte of edge memories.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
#[repr(C)]
pub struct PackedCounter<T> {
    cv: T,
    edges: u8,
}

/// CU and CD as the bits of [`PackedCounter::edges`].
#[inline]
const fn edge_bits(cu: bool, cd: bool) -> u8 {
    // `(b as u8).wrapping_neg()` is 0xFF for true and 0 for false: a mask that selects the bit.
    ((cu as u8).wrapping_neg() & CU_PREV) | ((cd as u8).wrapping_neg() & CD_PREV)
}

impl<T: CounterInt> PackedCounter<T> {
    /// A new counter (CV = 0, no edge seen).
    pub fn new() -> PackedCounter<T> {
        PackedCounter::default()
    }

    /// The counter holding `state` (every state is representable).
    pub fn from_state(state: CounterState<T>) -> PackedCounter<T> {
        PackedCounter {
            cv: state.cv,
            edges: edge_bits(state.cu_prev, state.cd_prev),
        }
    }

    /// The abstraction function.
    pub fn abstraction(&self) -> CounterState<T> {
        CounterState {
            cv: self.cv,
            cu_prev: self.edges & CU_PREV != 0,
            cd_prev: self.edges & CD_PREV != 0,
        }
    }

    /// `CV`.
    pub fn cv(&self) -> T {
        self.cv
    }
}

impl<T: CounterInt> CounterOps<T> for PackedCounter<T> {
    #[inline]
    fn call(&mut self, kind: CounterKind, input: CounterInput<T>) -> CounterOutput<T> {
        let i = kind.mask(input.signals());
        let now = edge_bits(i.cu, i.cd);
        let rising = now & !self.edges;
        self.edges = now;
        self.cv = if i.r {
            T::ZERO
        } else if i.ld {
            input.pv
        } else {
            // Up only, down only, or neither (both rising cancel out).
            match rising {
                CU_PREV => self.cv.saturating_inc(),
                CD_PREV => self.cv.saturating_dec(),
                _ => self.cv,
            }
        };
        outputs(self.cv, input.pv)
    }

    fn state(&self) -> CounterState<T> {
        self.abstraction()
    }
}

/// A bank of `64 * WORDS` CTUD counters sharing one preset, stored as arrays; inputs come as
/// bit sets (bit `i % 64` of word `i / 64` is counter `i`).
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct CounterBank<T, const WORDS: usize> {
    cv: [[T; 64]; WORDS],
    cu_prev: [u64; WORDS],
    cd_prev: [u64; WORDS],
}

/// The inputs of one scan of a [`CounterBank`], as bit sets.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct BankInputs<'a, const WORDS: usize> {
    /// CU of every counter.
    pub cu: &'a [u64; WORDS],
    /// CD of every counter.
    pub cd: &'a [u64; WORDS],
    /// R of every counter.
    pub r: &'a [u64; WORDS],
    /// LD of every counter.
    pub ld: &'a [u64; WORDS],
}

impl<T: CounterInt, const WORDS: usize> Default for CounterBank<T, WORDS> {
    fn default() -> Self {
        CounterBank::new()
    }
}

impl<T: CounterInt, const WORDS: usize> CounterBank<T, WORDS> {
    /// The number of counters.
    pub const LEN: usize = 64 * WORDS;

    /// A bank of new counters.
    pub fn new() -> CounterBank<T, WORDS> {
        CounterBank {
            cv: [[T::ZERO; 64]; WORDS],
            cu_prev: [0; WORDS],
            cd_prev: [0; WORDS],
        }
    }

    /// The state of counter `i`, if it exists.
    pub fn state(&self, i: usize) -> Option<CounterState<T>> {
        let (w, b) = (i / 64, i % 64);
        let cv = *self.cv.get(w)?.get(b)?;
        Some(CounterState {
            cv,
            cu_prev: self.cu_prev[w] >> b & 1 != 0,
            cd_prev: self.cd_prev[w] >> b & 1 != 0,
        })
    }

    /// The outputs of counter `i` for preset `pv`.
    pub fn output(&self, i: usize, pv: T) -> Option<CounterOutput<T>> {
        self.state(i).map(|s| outputs(s.cv, pv))
    }

    /// One scan: every counter called once as CTUD with preset `pv`. Only counters with an
    /// edge, R or LD are touched; the rest cost one word operation per 64.
    pub fn scan(&mut self, inputs: BankInputs<'_, WORDS>, pv: T) {
        for w in 0..WORDS {
            let up = inputs.cu[w] & !self.cu_prev[w];
            let down = inputs.cd[w] & !self.cd_prev[w];
            self.cu_prev[w] = inputs.cu[w];
            self.cd_prev[w] = inputs.cd[w];
            let r = inputs.r[w];
            let ld = inputs.ld[w] & !r;
            let hold = r | ld;
            let inc = up & !down & !hold;
            let dec = down & !up & !hold;
            let cv = &mut self.cv[w];
            for_each_bit(r, |b| cv[b] = T::ZERO);
            for_each_bit(ld, |b| cv[b] = pv);
            for_each_bit(inc, |b| cv[b] = cv[b].saturating_inc());
            for_each_bit(dec, |b| cv[b] = cv[b].saturating_dec());
        }
    }
}

#[inline]
fn for_each_bit(mut bits: u64, mut f: impl FnMut(usize)) {
    while bits != 0 {
        f(bits.trailing_zeros() as usize);
        bits &= bits - 1;
    }
}
