//! The optimized IEC counter: [`Counter`], CV and the two edge memories in one small struct with
//! a branch-free step.

use super::{
    outputs, CounterInput, CounterInt, CounterKind, CounterOps, CounterOutput, CounterState,
};

const CU_PREV: u8 = 1;
const CD_PREV: u8 = 2;

/// One IEC counter: CV and a byte of edge memories.
///
/// ```
/// use plc_timers::counter::{Counter, CounterInput, CounterKind, CounterOps};
/// let mut ctud = Counter::<i16>::new();
/// let both = CounterInput { cu: true, cd: true, pv: 5, ..Default::default() };
/// assert_eq!(ctud.call(CounterKind::Ctud, both).cv, 0); // simultaneous edges cancel
/// ```
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
#[repr(C)]
pub struct Counter<T> {
    cv: T,
    edges: u8,
}

/// CU and CD as the bits of the `edges` byte.
#[inline]
const fn edge_bits(cu: bool, cd: bool) -> u8 {
    // `(b as u8).wrapping_neg()` is 0xFF for true and 0 for false: a mask that selects the bit.
    ((cu as u8).wrapping_neg() & CU_PREV) | ((cd as u8).wrapping_neg() & CD_PREV)
}

impl<T: CounterInt> Counter<T> {
    /// A new counter (CV = 0, no edge seen).
    pub const fn new() -> Counter<T> {
        Counter {
            cv: T::ZERO,
            edges: 0,
        }
    }

    /// The counter holding `state` (every state is representable).
    pub const fn from_state(state: CounterState<T>) -> Counter<T> {
        Counter {
            cv: state.cv,
            edges: edge_bits(state.cu_prev, state.cd_prev),
        }
    }

    /// `CV`.
    pub const fn cv(&self) -> T {
        self.cv
    }
}

impl<T: CounterInt> CounterOps<T> for Counter<T> {
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

    /// The abstraction function.
    fn state(&self) -> CounterState<T> {
        CounterState {
            cv: self.cv,
            cu_prev: self.edges & CU_PREV != 0,
            cd_prev: self.edges & CD_PREV != 0,
        }
    }
}
