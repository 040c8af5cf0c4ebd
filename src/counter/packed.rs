//! The optimized IEC counter: [`Counter`], CV and the two edge memories in one small struct with
//! a short step.

use super::{
    outputs, BankInputs, CounterInput, CounterInt, CounterKind, CounterOps, CounterOutput,
    CounterState,
};

const CU_PREV: u8 = 1;
const CD_PREV: u8 = 2;

/// One IEC counter: CV and a byte of edge memories, in `2 * size_of::<T>()` bytes.
///
/// The bytes are laid out so that a counter reads as one unsigned word of twice `T`'s width
/// (little-endian): the edge byte in the low byte, CV in the upper half, the bytes between
/// them 0. [`CounterOps::call`] reads and writes CV and the edge byte apart, as two fields;
/// [`Counter::call_array`] reads and writes each counter as one word, which the compiler
/// vectorizes over an array of counters (from a `{ cv, edges }` structure with a padding byte
/// it moved the fields one counter at a time, which took two thirds of that loop's
/// instructions on SSE2, issue 41). The alignment is 1 (the bytes are an array).
///
/// ```
/// use plc_timers::counter::{Counter, CounterInput, CounterKind, CounterOps};
/// let mut ctud = Counter::<i16>::new();
/// let both = CounterInput { cu: true, cd: true, pv: 5, ..Default::default() };
/// assert_eq!(ctud.call(CounterKind::Ctud, both).cv, 0); // simultaneous edges cancel
/// assert_eq!(size_of::<Counter<i16>>(), 4);
/// ```
#[derive(Clone, Copy, PartialEq, Eq)]
#[repr(transparent)]
pub struct Counter<T: CounterInt> {
    bytes: <T as sealed::CounterBytes>::Bytes,
}

/// The storage of [`Counter`], one implementation per [`CounterInt`] type (sealed: the trait
/// is public in a module no other crate can name).
pub(super) mod sealed {
    /// How a [`super::Counter`] of this type keeps CV and the edge byte in
    /// `2 * size_of::<Self>()` bytes: byte 0 the edges, CV little-endian in the upper half,
    /// the bytes between them 0; read little-endian, the bytes are the word
    /// `CV << Self::BITS | edges` ([`CounterBytes::Word`]) on every target.
    pub trait CounterBytes: Sized {
        /// `[u8; 2 * size_of::<Self>()]`.
        type Bytes: Copy + Eq + Send + Sync + 'static;
        /// The unsigned integer of twice `Self`'s width.
        type Word: Copy;
        /// A new counter's bytes: CV 0, no edge seen.
        const NEW: Self::Bytes;
        /// CV, read alone.
        fn cv(bytes: &Self::Bytes) -> Self;
        /// The edge byte, read alone.
        fn edges(bytes: &Self::Bytes) -> u8;
        /// CV and the edge byte, written apart (the bytes between them stay 0).
        fn set(bytes: &mut Self::Bytes, cv: Self, edges: u8);
        /// The bytes as one word.
        fn word(bytes: &Self::Bytes) -> Self::Word;
        /// CV of a word.
        fn word_cv(word: Self::Word) -> Self;
        /// The edge byte of a word.
        fn word_edges(word: Self::Word) -> u8;
        /// The bytes of `cv` and `edges`, written as one word.
        fn to_bytes(cv: Self, edges: u8) -> Self::Bytes;
    }

    macro_rules! counter_bytes {
        ($($t:ty => $word:ty),*) => {$(
            impl CounterBytes for $t {
                type Bytes = [u8; 2 * size_of::<$t>()];
                type Word = $word;
                const NEW: Self::Bytes = [0; 2 * size_of::<$t>()];
                #[inline(always)]
                fn cv(bytes: &Self::Bytes) -> $t {
                    <$t>::from_le_bytes(core::array::from_fn(|i| bytes[size_of::<$t>() + i]))
                }
                #[inline(always)]
                fn edges(bytes: &Self::Bytes) -> u8 {
                    bytes[0]
                }
                #[inline(always)]
                fn set(bytes: &mut Self::Bytes, cv: $t, edges: u8) {
                    bytes[0] = edges;
                    bytes[size_of::<$t>()..].copy_from_slice(&cv.to_le_bytes());
                }
                #[inline(always)]
                fn word(bytes: &Self::Bytes) -> $word {
                    <$word>::from_le_bytes(*bytes)
                }
                #[inline(always)]
                fn word_cv(word: $word) -> $t {
                    (word >> <$t>::BITS) as $t
                }
                #[inline(always)]
                fn word_edges(word: $word) -> u8 {
                    word as u8
                }
                #[inline(always)]
                fn to_bytes(cv: $t, edges: u8) -> Self::Bytes {
                    // `cv as $word` sign-extends a signed CV; the shift drops those bits.
                    ((cv as $word) << <$t>::BITS | <$word>::from(edges)).to_le_bytes()
                }
            }
        )*};
    }

    counter_bytes!(i8 => u16, u8 => u16, i16 => u32, u16 => u32, i32 => u64, u32 => u64,
        i64 => u128, u64 => u128);
}

impl<T: CounterInt> Default for Counter<T> {
    /// A new counter.
    fn default() -> Counter<T> {
        Counter::new()
    }
}

impl<T: CounterInt> core::fmt::Debug for Counter<T> {
    fn fmt(&self, f: &mut core::fmt::Formatter<'_>) -> core::fmt::Result {
        let state = CounterOps::state(self);
        f.debug_struct("Counter")
            .field("cv", &state.cv)
            .field("cu_prev", &state.cu_prev)
            .field("cd_prev", &state.cd_prev)
            .finish()
    }
}

/// CU and CD as the bits of the `edges` byte.
#[inline]
const fn edge_bits(cu: bool, cd: bool) -> u8 {
    // `(b as u8).wrapping_neg()` is 0xFF for true and 0 for false: a mask that selects the bit.
    ((cu as u8).wrapping_neg() & CU_PREV) | ((cd as u8).wrapping_neg() & CD_PREV)
}

impl<T: CounterInt> Counter<T> {
    /// A new counter (CV = 0, no edge seen).
    ///
    /// ```
    /// use plc_timers::counter::{Counter, CounterOps};
    /// assert_eq!(Counter::<u64>::new().state().cv, 0);
    /// ```
    pub const fn new() -> Counter<T> {
        Counter { bytes: T::NEW }
    }

    /// The counter holding `state` (every state is representable).
    ///
    /// ```
    /// use plc_timers::counter::{Counter, CounterInput, CounterKind, CounterOps, CounterState};
    /// let mut c = Counter::from_state(CounterState { cv: 0u8, cu_prev: false, cd_prev: false });
    /// let down = CounterInput { cd: true, pv: 0, ..Default::default() };
    /// assert_eq!(c.call(CounterKind::Ctd, down).cv, 0); // USINT stays at its minimum
    /// ```
    pub fn from_state(state: CounterState<T>) -> Counter<T> {
        Counter {
            bytes: T::to_bytes(state.cv, edge_bits(state.cu_prev, state.cd_prev)),
        }
    }

    /// `CV`.
    pub fn cv(&self) -> T {
        T::cv(&self.bytes)
    }

    /// The call `call(kind, input)` for a loop over an array of counters: the same outputs
    /// and the same counter afterwards as [`CounterOps::call`], computed without a branch on
    /// the inputs or the state (`proofs/counter.rs` compares it with the reference on every
    /// state and input of the small types).
    ///
    /// In a loop over many counters the inputs and states differ from one counter to the next,
    /// so the branches of `call` (R, LD, an edge) are mispredicted about as often as they
    /// change; here the edges give a step of -1, 0 or 1, applied by saturating arithmetic, and
    /// R and LD choose the new CV by bit masks. `call` computes CTU and CTD with scalar
    /// selects; for CTUD it branches, which is faster for a counter called once per scan,
    /// whose branches go the same way scan after scan.
    ///
    /// Why it equals the reference: see [`CounterOps::call`] (the same rules); its lane code
    /// is that of [`Counter::call_array`] and [`super::CounterBank::scan`], on one counter.
    ///
    /// ```
    /// use plc_timers::counter::{Counter, CounterInput, CounterKind, CounterOps};
    /// let mut counters = [Counter::<i16>::new(); 3];
    /// for cu in [true, false, true] {
    ///     for c in counters.iter_mut() {
    ///         c.call_for_arrays(CounterKind::Ctu, CounterInput { cu, pv: 2, ..Default::default() });
    ///     }
    /// }
    /// assert!(counters.iter().all(|c| c.cv() == 2));
    /// ```
    #[inline(always)]
    pub fn call_for_arrays(
        &mut self,
        kind: CounterKind,
        input: CounterInput<T>,
    ) -> CounterOutput<T> {
        let (cu, cd, r, ld) = masked_inputs(kind, &input);
        let (mut cv, mut edges) = ([T::cv(&self.bytes)], [T::edges(&self.bytes)]);
        ctud_lanes(
            &mut cv,
            &mut edges,
            [&[cu], &[cd], &[r], &[ld]],
            HAS_ALL,
            &[input.pv],
        );
        T::set(&mut self.bytes, cv[0], edges[0]);
        outputs(cv[0], input.pv)
    }
}

impl<T: CounterInt> Counter<T> {
    /// Every counter of an array called once as `kind`, counter `i` with the inputs at index `i`
    /// (`inputs.cu[i]`, ..., `pv[i]`) and its outputs written at index `i` of `out`'s arrays:
    /// the loop `for i in 0..N { let o = counters[i].call_for_arrays(kind, input_i); ... }`
    /// (what a PLC program's `FOR` loop over an `ARRAY OF CTU` does), in one pass that the compiler
    /// vectorizes over the counters in their own layout, for the widest vector extension this
    /// CPU has with the feature `simd-dispatch`. Same counters and outputs afterwards as that
    /// loop, and as the reference called once per counter (`proofs/counter.rs`).
    ///
    /// Called one counter at a time, a counter cannot cost less than moving its inputs in and
    /// its outputs out (the per-instance floor of `benches/peers`); a loop the library owns can
    /// process several counters per instruction.
    ///
    /// ```
    /// use plc_timers::counter::{ArrayOutputs, BankInputs, Counter, CounterKind};
    /// let mut counters = [Counter::<i16>::new(); 3];
    /// let (on, off) = ([true, false, true], [false; 3]);
    /// let inputs = BankInputs { cu: &on, cd: &off, r: &off, ld: &off };
    /// let (mut q, mut qd, mut cv) = ([false; 3], [false; 3], [0; 3]);
    /// let mut out = ArrayOutputs { qu: &mut q, qd: &mut qd, cv: &mut cv };
    /// Counter::call_array(&mut counters, CounterKind::Ctu, &inputs, &[1, 1, 2], &mut out);
    /// assert_eq!((q, cv), ([true, false, false], [1, 0, 1]));
    /// ```
    pub fn call_array<const N: usize>(
        counters: &mut [Counter<T>; N],
        kind: CounterKind,
        inputs: &BankInputs<'_, N>,
        pv: &[T; N],
        out: &mut ArrayOutputs<'_, T, N>,
    ) {
        crate::simd::run(CallArray {
            counters,
            kind,
            inputs,
            pv,
            out,
        });
    }
}

/// Where [`Counter::call_array`] writes the outputs: counter `i`'s at index `i` of each array.
#[derive(Debug, PartialEq, Eq)]
pub struct ArrayOutputs<'a, T, const N: usize> {
    /// `QU` (CTU's `Q`) of every counter.
    pub qu: &'a mut [bool; N],
    /// `QD` (CTD's `Q`) of every counter.
    pub qd: &'a mut [bool; N],
    /// `CV` of every counter.
    pub cv: &'a mut [T; N],
}

/// [`Counter::call_array`] as a loop for [`crate::simd::run`].
struct CallArray<'a, 'b, 'c, T: CounterInt, const N: usize> {
    counters: &'a mut [Counter<T>; N],
    kind: CounterKind,
    inputs: &'a BankInputs<'b, N>,
    pv: &'a [T; N],
    out: &'a mut ArrayOutputs<'c, T, N>,
}

impl<T: CounterInt, const N: usize> crate::simd::Kernel for CallArray<'_, '_, '_, T, N> {
    #[inline(always)]
    fn run(self) {
        let CallArray {
            counters,
            kind,
            inputs,
            pv,
            out,
        } = self;
        // The inputs `kind` has, as masks (the kernel is compiled apart from its caller,
        // where `kind` is not a constant). One `match` per array, not per counter: each arm
        // has its kind's masks as constants, so that its loop neither loads nor computes the
        // inputs the kind lacks (on SSE2 the loop of CTD, with the masks as variables, was
        // not 2x faster than the reference's, issue 41).
        let has = |kind| {
            let all = CounterInput {
                cu: true,
                cd: true,
                r: true,
                ld: true,
                pv: T::ZERO,
            };
            masked_inputs(kind, &all)
        };
        let out = ArrayOutputs {
            qu: out.qu,
            qd: out.qd,
            cv: out.cv,
        };
        match kind {
            CounterKind::Ctu => call_array_lanes(counters, has(CounterKind::Ctu), inputs, pv, out),
            CounterKind::Ctd => call_array_lanes(counters, has(CounterKind::Ctd), inputs, pv, out),
            CounterKind::Ctud => {
                call_array_lanes(counters, has(CounterKind::Ctud), inputs, pv, out)
            }
        }
    }
}

/// Counters per group of [`Counter::call_array`].
const LANES: usize = 16;

/// The loop of [`Counter::call_array`]: the counters in groups of [`LANES`], the last
/// `N % LANES` through the same code on a padded copy (the padding counters are new ones with
/// every input 0, whose results are dropped), so that every counter takes the one path.
#[inline(always)]
fn call_array_lanes<T: CounterInt, const N: usize>(
    counters: &mut [Counter<T>; N],
    has: (bool, bool, bool, bool),
    inputs: &BankInputs<'_, N>,
    pv: &[T; N],
    out: ArrayOutputs<'_, T, N>,
) {
    let (counters, counters_tail) = counters.as_chunks_mut::<LANES>();
    let (cu, cu_tail) = inputs.cu.as_chunks::<LANES>();
    let (cd, cd_tail) = inputs.cd.as_chunks::<LANES>();
    let (r, r_tail) = inputs.r.as_chunks::<LANES>();
    let (ld, ld_tail) = inputs.ld.as_chunks::<LANES>();
    let (pv, pv_tail) = pv.as_chunks::<LANES>();
    let (qu, qu_tail) = out.qu.as_chunks_mut::<LANES>();
    let (qd, qd_tail) = out.qd.as_chunks_mut::<LANES>();
    let (cv, cv_tail) = out.cv.as_chunks_mut::<LANES>();
    for (g, counters) in counters.iter_mut().enumerate() {
        counter_group(
            counters,
            has,
            [&cu[g], &cd[g], &r[g], &ld[g]],
            &pv[g],
            &mut qu[g],
            &mut qd[g],
            &mut cv[g],
        );
    }
    let n = counters_tail.len();
    if n > 0 {
        let mut counters = [Counter::new(); LANES];
        let mut inputs = [[false; LANES]; 4];
        let mut pv = [T::ZERO; LANES];
        let (mut qu, mut qd, mut cv) = ([false; LANES], [false; LANES], [T::ZERO; LANES]);
        counters[..n].copy_from_slice(counters_tail);
        for (padded, tail) in inputs.iter_mut().zip([cu_tail, cd_tail, r_tail, ld_tail]) {
            padded[..n].copy_from_slice(tail);
        }
        pv[..n].copy_from_slice(pv_tail);
        let [cu, cd, r, ld] = &inputs;
        counter_group(
            &mut counters,
            has,
            [cu, cd, r, ld],
            &pv,
            &mut qu,
            &mut qd,
            &mut cv,
        );
        counters_tail.copy_from_slice(&counters[..n]);
        qu_tail.copy_from_slice(&qu[..n]);
        qd_tail.copy_from_slice(&qd[..n]);
        cv_tail.copy_from_slice(&cv[..n]);
    }
}

/// [`LANES`] counters of [`Counter::call_array`], every array a parameter of its own:
/// parameters that are `&mut` are known not to overlap anything else (LLVM's `noalias`, kept
/// when inlined), which lets the compiler keep the arrays' addresses in registers and
/// vectorize the stores (read through the kernel's structure, they were reloaded after every
/// store). Each counter is read as one word ([`Counter`]'s layout), taken apart into CV and
/// the edge byte (structure of arrays), the group run through the lane code in its two passes,
/// as [`super::CounterBank::scan`] runs it, and each counter written back as one word. With
/// the `{ cv, edges }` structure of before, whose fields LLVM moved one counter at a time,
/// CTD's loop took 9.71 µs on SSE2 (1.97x faster than the reference's); with the words and
/// the lane code one counter at a time 3.84 µs, in two passes 3.08 (6.2x; CTUD 3.28 against
/// 4.84, CTU 2.40 against 2.17; `benches/peers`, one build each, issue 41).
#[allow(clippy::too_many_arguments)]
#[inline(always)]
fn counter_group<T: CounterInt>(
    counters: &mut [Counter<T>; LANES],
    has: (bool, bool, bool, bool),
    [cu, cd, r, ld]: [&[bool; LANES]; 4],
    pv: &[T; LANES],
    qu: &mut [bool; LANES],
    qd: &mut [bool; LANES],
    cv_out: &mut [T; LANES],
) {
    let words: [T::Word; LANES] = core::array::from_fn(|j| T::word(&counters[j].bytes));
    let mut cv: [T; LANES] = core::array::from_fn(|j| T::word_cv(words[j]));
    let mut edges: [u8; LANES] = core::array::from_fn(|j| T::word_edges(words[j]));
    ctud_lanes(&mut cv, &mut edges, [cu, cd, r, ld], has, pv);
    for j in 0..LANES {
        counters[j].bytes = T::to_bytes(cv[j], edges[j]);
        let o = outputs(cv[j], pv[j]);
        qu[j] = o.qu;
        qd[j] = o.qd;
        cv_out[j] = o.cv;
    }
}

/// The inputs `kind` has, others taken as 0 (CNT-INPUTS-01): (CU, CD, R, LD).
#[inline(always)]
fn masked_inputs<T>(kind: CounterKind, input: &CounterInput<T>) -> (bool, bool, bool, bool) {
    match kind {
        CounterKind::Ctu => (input.cu, false, input.r, false),
        CounterKind::Ctd => (false, input.cd, false, input.ld),
        CounterKind::Ctud => (input.cu, input.cd, input.r, input.ld),
    }
}

/// Which inputs a kind has, as `(CU, CD, R, LD)`: the masks of [`ctud_lanes`].
pub(crate) type Has = (bool, bool, bool, bool);

/// The inputs of every kind (the bank's CTUD).
pub(crate) const HAS_ALL: Has = (true, true, true, true);

/// `L` CTUD calls without a branch: counter `j`'s CV and edge byte (CU's memory in bit 0, CD's
/// in bit 1) after a call with the inputs at index `j` (those `has` lacks taken as 0) and PV
/// `pv[j]`. The one lane code of [`Counter::call_for_arrays`] (`L` = 1), of
/// [`Counter::call_array`] and of [`super::CounterBank::scan`] (`proofs/counter.rs` compares
/// each with the reference).
///
/// Why it equals the reference's CTUD: `up` and `down` are its edges (the input 1, its memory
/// 0); both memories take the inputs on every call, also under R and LD (CNT-EDGE-01). Up alone
/// counts up, down alone counts down, both or neither leave CV (CNT-SIMUL-01), with the
/// reference's saturating steps (CNT-SAT-01; both in [`CounterInt::saturating_up_down`]).
/// The count is kept only with neither R nor LD; PV is loaded with LD and not R, and with R
/// the result is 0 (CNT-PRIO-01).
///
/// Two passes, so that a vectorized loop works at the full width of each type: the first over
/// bytes only (the `bool` inputs, the edge bytes, the 0/1 edges and the choice of the new CV as
/// two byte masks), 16 counters per SSE2 instruction; the second over `T` (the saturating step
/// and the choice, [`CounterInt::select_by_masks`]), which widens each byte once. In one pass
/// (each counter's lane whole) LLVM vectorized at `T`'s width and loaded the bytes 8 at a time:
/// 42 instructions per 8 INT counters on SSE2, against 48 per 16 now (issue 41).
#[inline(always)]
pub(crate) fn ctud_lanes<T: CounterInt, const L: usize>(
    cv: &mut [T; L],
    edges: &mut [u8; L],
    [cu, cd, r, ld]: [&[bool; L]; 4],
    has: Has,
    pv: &[T; L],
) {
    let mut up = [0u8; L];
    let mut down = [0u8; L];
    let mut count = [0u8; L];
    let mut load = [0u8; L];
    for j in 0..L {
        // The inputs as 0/1 bytes, and the choices as byte masks (0 or 0xFF), which the
        // second pass widens to `T` with one unpack and one shift per vector.
        let cu = u8::from(cu[j] & has.0);
        let cd = u8::from(cd[j] & has.1);
        let (r, ld) = (u8::from(r[j] & has.2), u8::from(ld[j] & has.3));
        let e = edges[j];
        (up[j], down[j]) = (cu & !e & CU_PREV, cd & !(e >> 1) & 1);
        edges[j] = cu | cd << 1;
        count[j] = u8::from(r | ld == 0).wrapping_neg();
        load[j] = (ld & !r).wrapping_neg();
    }
    for j in 0..L {
        let counted = cv[j].saturating_up_down(up[j], down[j]);
        cv[j] = T::select_by_masks(counted, count[j], pv[j], load[j]);
    }
}

impl<T: CounterInt> CounterOps<T> for Counter<T> {
    /// The reference's rules (edges, then R before LD before counting), with the edge
    /// memories in one byte. CTU and CTD without a branch: every choice is a conditional move
    /// ([`core::hint::select_unpredictable`], which the compiler must keep as one). A PLC
    /// program's `FOR` loop over an `ARRAY OF CTU` calls counters whose inputs and states
    /// differ from one to the next, and a branch on an edge or on R was mispredicted about as
    /// often as it changed: such a loop ran 2-3x slower than the reference's (issue 41).
    /// CTUD keeps its branches: with selects its single step ran 2.7 ns against the
    /// branches' 1.6 (`benches/peers`, both input families; a predicted branch lets the
    /// processor run ahead of the previous call's CV, a select waits for it), and its loop
    /// with branches still beats the reference's (whose CTUD branches too). CV is written on every call, as the reference
    /// writes it.
    ///
    /// Why it equals [`super::CounterRef`]: the inputs a kind lacks are taken as 0, as the
    /// reference's `kind.mask` does (CNT-INPUTS-01). `up` and `down` are the reference's
    /// edges: the input is 1 and its memory, a bit of `edges`, is 0; both memories then take
    /// the inputs, on every call, also under R and LD (CNT-EDGE-01). R replaces the count by
    /// 0, else LD by PV (CNT-PRIO-01); else up alone counts up, down alone counts down, both
    /// or neither leave CV (CNT-SIMUL-01), with the reference's saturating steps
    /// (CNT-SAT-01).
    #[inline(always)]
    fn call(&mut self, kind: CounterKind, input: CounterInput<T>) -> CounterOutput<T> {
        use core::hint::select_unpredictable as select;
        let (cu, cd, r, ld) = masked_inputs(kind, &input);
        // Both members are read before either is written: a read of the whole struct after a
        // write of one byte of it would wait for that write to reach the cache.
        let (v, e) = (T::cv(&self.bytes), T::edges(&self.bytes));
        let up = cu & (e & CU_PREV == 0);
        let down = cd & (e & CD_PREV == 0);
        let edges = edge_bits(cu, cd);
        let cv = match kind {
            CounterKind::Ctu | CounterKind::Ctd => {
                let stepped = select(up, v.saturating_inc(), v.saturating_dec());
                let counted = select(up != down, stepped, v);
                select(r, T::ZERO, select(ld, input.pv, counted))
            }
            // R and LD as one branch and a select (two branches on them cost 0.1-0.2 ns more
            // per step on the square waves of `benches/peers`).
            CounterKind::Ctud => {
                if r | ld {
                    select(r, T::ZERO, input.pv)
                } else if up != down {
                    if up {
                        v.saturating_inc()
                    } else {
                        v.saturating_dec()
                    }
                } else {
                    v
                }
            }
        };
        T::set(&mut self.bytes, cv, edges);
        outputs(cv, input.pv)
    }

    /// The abstraction function.
    fn state(&self) -> CounterState<T> {
        let edges = T::edges(&self.bytes);
        CounterState {
            cv: T::cv(&self.bytes),
            cu_prev: edges & CU_PREV != 0,
            cd_prev: edges & CD_PREV != 0,
        }
    }
}

#[cfg(test)]
mod tests {
    extern crate std;
    use super::*;
    use std::format;

    /// The two ways in and out of a counter's bytes agree for every type, at CV's limits and
    /// around 0, with each edge byte a counter holds: the fields apart (`set`, `cv`, `edges`:
    /// `call`) and the word (`to_bytes`, `word_cv`, `word_edges`: `call_array`), and the
    /// bytes between them stay 0, so that `==` on counters is equality of their states.
    fn storage_round_trips<T: CounterInt>(values: [T; 5]) {
        for cv in values {
            for edges in 0..4u8 {
                let whole = T::to_bytes(cv, edges);
                let mut apart = T::NEW;
                T::set(&mut apart, cv, edges);
                assert!(
                    whole == apart,
                    "{} CV {cv} edges {edges}: set != to_bytes",
                    T::NAME
                );
                assert_eq!(
                    (T::cv(&whole), T::edges(&whole)),
                    (cv, edges),
                    "{}",
                    T::NAME
                );
                let word = T::word(&whole);
                assert_eq!(
                    (T::word_cv(word), T::word_edges(word)),
                    (cv, edges),
                    "{}",
                    T::NAME
                );
                let state = CounterState {
                    cv,
                    cu_prev: edges & CU_PREV != 0,
                    cd_prev: edges & CD_PREV != 0,
                };
                assert_eq!(Counter::from_state(state).state(), state, "{}", T::NAME);
                for other in values {
                    let (a, b) = (
                        Counter::from_state(state),
                        Counter::from_state(CounterState { cv: other, ..state }),
                    );
                    assert_eq!(a == b, cv == other, "{} CV {cv} and {other}", T::NAME);
                }
            }
        }
    }

    #[test]
    fn storage_of_every_type() {
        storage_round_trips([i8::MIN, -1, 0, 1, i8::MAX]);
        storage_round_trips([i16::MIN, -1, 0, 1, i16::MAX]);
        storage_round_trips([i32::MIN, -1, 0, 1, i32::MAX]);
        storage_round_trips([i64::MIN, -1, 0, 1, i64::MAX]);
        storage_round_trips([0, 1, 2, u8::MAX - 1, u8::MAX]);
        storage_round_trips([0, 1, 2, u16::MAX - 1, u16::MAX]);
        storage_round_trips([0, 1, 2, u32::MAX - 1, u32::MAX]);
        storage_round_trips([0, 1, 2, u64::MAX - 1, u64::MAX]);
    }

    #[test]
    fn debug_shows_the_state() {
        let c = Counter::from_state(CounterState {
            cv: -7i16,
            cu_prev: true,
            cd_prev: false,
        });
        assert_eq!(
            format!("{c:?}"),
            "Counter { cv: -7, cu_prev: true, cd_prev: false }"
        );
    }
}
