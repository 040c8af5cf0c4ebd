//! A bank of TON timers in structure-of-arrays form, for a soft-PLC that scans thousands of
//! on-delays: one array per structure member, so that a scan is one pass over each array.
//! Each timer behaves exactly as [`super::IecTimerRef`] called as `TON` once per scan
//! (IEC-BANK-01, checked in `proofs/iec.rs`), for `TIME` and for `LTIME` (one body, generic over
//! the data type as the timers are).

use super::{IecKind, IecOutput, IecState};
use crate::operand::{NoSuchOperand, Operand};
use crate::time::clock::ClockWord;
use crate::time::{CpuTime, IecDuration, Time};

/// Flag bits of [`TonBank::flags`].
const IN: u8 = 0b0001;
const Q: u8 = 0b0010;
const RUNNING: u8 = 0b0100;
/// A running timer put in the bank by [`TonBank::set_state`], whose ET slot holds its ET (see
/// [`TonBank`]'s representation); cleared by the next scan.
const EXPLICIT: u8 = 0b1000;

/// Timers per step of the scan's kernel: 16 flag bytes fill one 128-bit vector, their 16 words
/// four.
const LANES: usize = 16;

/// `N` TON timers of data type `D`, called together once per scan: `TIME` (the default; a
/// 32-bit millisecond clock, `u32` members) or `LTIME` (the S7-1500 long timers; a 64-bit
/// nanosecond clock, `u64` members).
///
/// ```
/// use plc_timers::iec::TonBank;
/// use plc_timers::time::{CpuTime, Time};
///
/// // Three conveyors, each with a 2 s on-delay; the scan runs every 500 ms.
/// let mut delays = TonBank::<3>::new();
/// let pt = [Time::from_millis(2_000); 3];
/// let sensors = [true, false, true];
/// for scan in 0..=4u64 {
///     delays.scan(CpuTime::from_millis(500 * scan), &sensors, &pt);
/// }
/// let q: Vec<bool> = delays.outputs().map(|o| o.q).collect();
/// assert_eq!(q, [true, false, true]);
/// assert_eq!(delays.output(0).map(|o| o.et), Ok(2_000));
/// ```
///
/// The same bank of `LTIME` timers, on the nanosecond clock:
///
/// ```
/// use plc_timers::iec::TonBank;
/// use plc_timers::time::{CpuTime, LTime};
///
/// let mut delays = TonBank::<3, LTime>::new();
/// let pt = [plc_timers::ltime!("LT#2S"); 3];
/// for scan in 0..=4u64 {
///     delays.scan(CpuTime::from_nanos(500_000_000 * scan), &[true, false, true], &pt);
/// }
/// assert_eq!(delays.output(0).map(|o| (o.q, o.et)), Ok((true, 2_000_000_000)));
/// ```
///
/// # Representation
///
/// Per timer: START, PT (stored with its top bit flipped, [`ClockWord::flip_top`], the form
/// the scan compares in), an ET slot and
/// a flag byte (IN, Q, RUNNING). The ET slot of a stopped timer holds its ET. A running timer's
/// ET is not stored: it is `now - START` for the clock `now` of the last scan (the bank keeps
/// it), which is exactly what that scan's update computed (ET = elapsed while elapsed < PT); its
/// ET slot holds its PT instead, the ET it will have when it expires, so that the expiry writes
/// nothing there. A running timer put in the bank by [`TonBank::set_state`], whose ET need not be
/// `now - START`, keeps its ET in the slot and a flag saying so until the next scan. The scan
/// then needs, per timer, one subtraction, one compare and a few masks.
#[derive(Clone, Debug)]
pub struct TonBank<const N: usize, D: IecDuration = Time> {
    start: [D::Clock; N],
    /// PT with its top bit flipped ([`ClockWord::flip_top`]).
    pt: [D::Clock; N],
    /// ET of a stopped timer; PT of a running one (unless [`EXPLICIT`]).
    et: [D::Clock; N],
    flags: [u8; N],
    /// The clock of the last scan.
    now: D::Clock,
    /// Whether a scan has run: before it, no instruction has run on the structures.
    scanned: bool,
    /// Whether some timer has the [`EXPLICIT`] flag.
    explicit: bool,
}

impl<const N: usize, D: IecDuration> Default for TonBank<N, D> {
    fn default() -> Self {
        TonBank::new()
    }
}

/// Two banks are equal when their timers are: the same states ([`TonBank::get`]), whatever
/// their representation.
impl<const N: usize, D: IecDuration> PartialEq for TonBank<N, D> {
    fn eq(&self, other: &Self) -> bool {
        self.scanned == other.scanned && (0..N).all(|i| self.get(i) == other.get(i))
    }
}

impl<const N: usize, D: IecDuration> Eq for TonBank<N, D> {}

/// `c` where `mask` is all ones, 0 where it is 0 (the masks of the scan are 64-bit, all ones or
/// 0, whatever the clock word's width; on the 32-bit word the compiler keeps it 32 bits wide).
#[inline(always)]
fn masked<C: ClockWord>(c: C, mask: u64) -> C {
    C::from_u64_wrapping(c.to_u64() & mask)
}

/// `a` where `mask` is all ones, `b` where it is 0.
#[inline(always)]
fn select<C: ClockWord>(mask: u64, a: C, b: C) -> C {
    C::from_u64_wrapping(a.to_u64() & mask | b.to_u64() & !mask)
}

/// All ones when `on`, else 0.
#[inline(always)]
fn mask(on: bool) -> u64 {
    u64::from(on).wrapping_neg()
}

impl<const N: usize, D: IecDuration> TonBank<N, D> {
    /// The number of timers.
    pub const LEN: usize = N;

    /// A bank of new timers (every structure zero).
    ///
    /// ```
    /// use plc_timers::iec::TonBank;
    /// let bank = TonBank::<10>::new();
    /// assert_eq!(bank.outputs().filter(|o| o.q).count(), 0);
    /// ```
    pub const fn new() -> TonBank<N, D> {
        TonBank {
            start: [<D::Clock as ClockWord>::ZERO; N],
            // PT = 0, top bit flipped.
            pt: [<D::Clock as ClockWord>::TOP_BIT; N],
            et: [<D::Clock as ClockWord>::ZERO; N],
            flags: [0; N],
            now: <D::Clock as ClockWord>::ZERO,
            scanned: false,
            explicit: false,
        }
    }

    /// ET of timer `i` (`i < N`): derived for a running timer (see the representation).
    fn et_of(&self, i: usize) -> D::Clock {
        // A select by mask, not a branch: read in bulk ([`TonBank::outputs`]), RUNNING varies
        // from timer to timer and a branch would mispredict on it; the mask form also lets the
        // loop over the timers vectorize.
        let derived = mask(self.flags[i] & (RUNNING | EXPLICIT) == RUNNING);
        select(derived, self.now.elapsed_since(self.start[i]), self.et[i])
    }

    /// Timer `i`'s flags, or the error naming the bank's range.
    fn flags_of(&self, i: usize) -> Result<u8, NoSuchOperand> {
        crate::operand::word(&self.flags, Operand::Timer, i)
    }

    /// The outputs `Q` and `ET` of timer `i`.
    pub fn output(&self, i: usize) -> Result<IecOutput<D::Clock>, NoSuchOperand> {
        Ok(IecOutput {
            q: self.flags_of(i)? & Q != 0,
            et: self.et_of(i),
        })
    }

    /// The outputs of every timer, timer 0 first.
    pub fn outputs(&self) -> impl ExactSizeIterator<Item = IecOutput<D::Clock>> + '_ {
        (0..N).map(|i| IecOutput {
            q: self.flags[i] & Q != 0,
            et: self.et_of(i),
        })
    }

    /// The outputs of every timer written into `q` and `et` (timer `i` at index `i`), equal to
    /// [`TonBank::outputs`]: for a caller that copies them into arrays of its own (the Python
    /// bank's numpy arrays), one straight-line pass that vectorizes.
    ///
    /// ```
    /// use plc_timers::iec::TonBank;
    /// use plc_timers::time::{CpuTime, Time};
    /// let mut bank = TonBank::<2>::new();
    /// bank.scan(CpuTime::from_millis(0), &[true, false], &[Time::from_millis(100); 2]);
    /// bank.scan(CpuTime::from_millis(40), &[true, false], &[Time::from_millis(100); 2]);
    /// let (mut q, mut et) = ([true; 2], [7; 2]);
    /// bank.outputs_into(&mut q, &mut et);
    /// assert_eq!((q, et), ([false, false], [40, 0]));
    /// ```
    pub fn outputs_into(&self, q: &mut [bool; N], et: &mut [D::Clock; N]) {
        for i in 0..N {
            q[i] = self.flags[i] & Q != 0;
            et[i] = self.et_of(i);
        }
    }

    /// The state of timer `i` as the reference names it.
    pub fn get(&self, i: usize) -> Result<IecState<D::Clock>, NoSuchOperand> {
        let f = self.flags_of(i)?;
        Ok(IecState {
            kind: self.scanned.then_some(IecKind::Ton),
            input: f & IN != 0,
            running: f & RUNNING != 0,
            start: self.start[i],
            pt: self.pt[i].flip_top(),
            et: self.et_of(i),
            q: f & Q != 0,
        })
    }

    /// Puts timer `i` in `state` (a TON state: its `kind` is ignored). `Ok(false)`, and no
    /// change, when the state is not valid ([`IecState::is_valid`]).
    #[must_use = "`Ok(false)` says the state was not valid and the timer did not change"]
    pub fn set_state(
        &mut self,
        i: usize,
        state: IecState<D::Clock>,
    ) -> Result<bool, NoSuchOperand> {
        self.flags_of(i)?;
        if !state.is_valid() {
            return Ok(false);
        }
        self.start[i] = state.start;
        self.pt[i] = state.pt.flip_top();
        self.et[i] = state.et;
        self.flags[i] = (u8::from(state.input) * IN)
            | (u8::from(state.q) * Q)
            | (u8::from(state.running) * (RUNNING | EXPLICIT));
        self.explicit |= state.running;
        Ok(true)
    }

    /// Brings every [`EXPLICIT`] timer to the representation the scan expects: ET slot = PT,
    /// and Q = 0 (a running timer's Q does not enter the TON update: after it, Q is whether
    /// the time has run out). Its ET and Q before the scan no longer matter: the scan gives
    /// a running timer a new ET and Q (update, restart or reset), whatever they were.
    fn settle_explicit(&mut self) {
        for ((f, et), &pt) in self.flags.iter_mut().zip(self.et.iter_mut()).zip(&self.pt) {
            if *f & EXPLICIT != 0 {
                *et = pt.flip_top();
                *f &= !(EXPLICIT | Q);
            }
        }
        self.explicit = false;
    }

    /// One scan at CPU time `now`: timer `i` called as TON with `IN` = `input[i]` and
    /// `PT` = `pt[i]`.
    ///
    /// One pass over the timers, 16 at a time, with the same straight-line code for every
    /// timer: no branch on a timer's state or on its IN, so that the compiler keeps 16 timers
    /// in vector registers and no input costs a misprediction. A rising IN (once per switching
    /// on, but at random in a plant: a branch on it was mispredicted in about half of the
    /// groups of 16 when IN flips with probability 0.10 per scan) is selected, not branched to.
    ///
    /// Why it equals the reference's TON ([`super::IecTimerRef`], `ton`), with the
    /// representation of [`TonBank`] (a running timer's ET slot = PT, ET = clock - START):
    ///
    /// - IN = 0 (`reset_and_stop`): START = ET = 0, flags 0 (stopped, Q = 0, IN memory 0); PT
    ///   kept. The pass masks START, the ET slot and the flags with IN.
    /// - IN = 1, memory 1, running (the update): `elapsed = now - START` modulo 2^BITS; the
    ///   pass compares `elapsed < PT` as `flip_top(now) - START < flip_top(PT)` signed (both
    ///   sides are the unsigned values plus 2^(BITS-1), see [`ClockWord::flip_top`]). Not reached: START kept, still
    ///   running, Q = 0, and ET = elapsed = the new clock - START (derived). Reached: START =
    ///   0, stopped, Q = 1, and ET = PT, which the slot holds already.
    /// - IN = 1, memory 1, stopped: nothing changes (its START is 0, [`IecState::is_valid`],
    ///   so masking it changes nothing; the ET slot and Q are kept).
    /// - IN = 1, memory 0 (a rise: `start` then `update` at the same instant): START = now,
    ///   PT latched (negative as 0), ET = 0; the update finds `elapsed = 0`, which reaches PT
    ///   only when PT = 0: then stopped with Q = 1 and ET = PT = 0 (START = 0), else running
    ///   with Q = 0, whose ET slot takes PT and whose derived ET is `now - now` = 0. The pass
    ///   selects START = now, the new latched PT and the flags IN | RUNNING (Q = 0) for such a
    ///   timer and runs the update above on them: elapsed = 0, not reached exactly when PT > 0
    ///   (START = now kept, still running) and reached when PT = 0 (START = 0, Q = 1,
    ///   stopped); its ET slot takes PT in both cases.
    ///
    /// The flags after the pass: Q (bit 1) and RUNNING (bit 2) of a running timer go from 4
    /// to 2 (expired) by subtracting 2, a stopped timer's stay; the running timers' Q is 0
    /// (kept so by every step and by `settle_explicit`), so bits 1-2 are 4, 2 or 0 and the
    /// subtraction never borrows.
    pub fn scan(&mut self, now: CpuTime<D::Unit>, input: &[bool; N], pt: &[D; N]) {
        let now = now.clock::<D::Clock>();
        if self.explicit {
            self.settle_explicit();
        }
        self.scanned = true;
        self.now = now;
        crate::simd::run(Scan {
            bank: self,
            input,
            pt,
            now,
        });
    }
}

/// [`TonBank::scan`]'s pass over the timers, as a loop for [`crate::simd::run`].
struct Scan<'a, const N: usize, D: IecDuration> {
    bank: &'a mut TonBank<N, D>,
    input: &'a [bool; N],
    pt: &'a [D; N],
    now: D::Clock,
}

impl<const N: usize, D: IecDuration> crate::simd::Kernel for Scan<'_, N, D> {
    #[inline(always)]
    fn run(self) {
        let Scan {
            bank,
            input,
            pt,
            now,
        } = self;
        let (start, start_tail) = bank.start.as_chunks_mut::<LANES>();
        let (slots, slots_tail) = bank.et.as_chunks_mut::<LANES>();
        let (flags, flags_tail) = bank.flags.as_chunks_mut::<LANES>();
        let (latched, latched_tail) = bank.pt.as_chunks_mut::<LANES>();
        let (inputs, inputs_tail) = input.as_chunks::<LANES>();
        let (presets, presets_tail) = pt.as_chunks::<LANES>();
        let chunks = start
            .iter_mut()
            .zip(slots.iter_mut())
            .zip(flags.iter_mut())
            .zip(latched.iter_mut())
            .zip(inputs.iter().zip(presets));
        for ((((start, slots), flags), latched), (inputs, presets)) in chunks {
            pass(now, start, latched, slots, flags, inputs, presets);
        }
        // The last `N % LANES` timers: through the same code on a padded copy (the padding
        // timers are new ones with IN = 0, which stay as they are).
        let n = start_tail.len();
        if n > 0 {
            let mut start = [<D::Clock as ClockWord>::ZERO; LANES];
            let mut latched = [<D::Clock as ClockWord>::TOP_BIT; LANES];
            let mut slots = [<D::Clock as ClockWord>::ZERO; LANES];
            let mut flags = [0; LANES];
            let mut inputs = [false; LANES];
            let mut presets = [D::ZERO; LANES];
            start[..n].copy_from_slice(start_tail);
            latched[..n].copy_from_slice(latched_tail);
            slots[..n].copy_from_slice(slots_tail);
            flags[..n].copy_from_slice(flags_tail);
            inputs[..n].copy_from_slice(inputs_tail);
            presets[..n].copy_from_slice(presets_tail);
            pass(
                now,
                &mut start,
                &mut latched,
                &mut slots,
                &mut flags,
                &inputs,
                &presets,
            );
            start_tail.copy_from_slice(&start[..n]);
            latched_tail.copy_from_slice(&latched[..n]);
            slots_tail.copy_from_slice(&slots[..n]);
            flags_tail.copy_from_slice(&flags[..n]);
        }
    }
}

/// The pass of [`TonBank::scan`] over 16 timers: every case as masks and selects, the start of
/// a timer included (see the proof there), with the same straight-line code for every timer.
#[inline(always)]
fn pass<C: ClockWord, D: IecDuration>(
    now: C,
    start: &mut [C; LANES],
    latched: &mut [C; LANES],
    slots: &mut [C; LANES],
    flags: &mut [u8; LANES],
    inputs: &[bool; LANES],
    presets: &[D; LANES],
) {
    let now_biased = now.flip_top();
    let on: [u8; LANES] = core::array::from_fn(|j| u8::from(inputs[j]));
    // A rise: IN = 1 and its memory 0 (bytes 0/1).
    let rise: [u8; LANES] = core::array::from_fn(|j| on[j] & !flags[j] & IN);
    let mut not_reached = [0u8; LANES];
    for j in 0..LANES {
        // All ones when IN = 1, and when IN rose.
        let on = mask(on[j] != 0);
        let rise = mask(rise[j] != 0);
        // A rising timer is taken as a running one with START = now and the new PT (negative
        // as 0).
        let pt = C::from_preset(presets[j].units());
        let begun = select(rise, now, start[j]);
        latched[j] = select(rise, pt.flip_top(), latched[j]);
        let elapsed_biased = now_biased.elapsed_since(begun);
        let nr = mask(elapsed_biased.lt_signed(latched[j]));
        start[j] = masked(begun, nr & on);
        slots[j] = select(rise, pt, masked(slots[j], on));
        not_reached[j] = nr as u8;
    }
    for j in 0..LANES {
        let rise = rise[j].wrapping_neg();
        let f = (IN | RUNNING) & rise | flags[j] & !rise;
        let status = (f & (IN | Q | RUNNING)) - ((f >> 1) & !not_reached[j] & Q);
        flags[j] = status & on[j].wrapping_neg();
    }
}

#[cfg(test)]
mod tests {
    extern crate std;
    use super::TonBank;
    use crate::iec::{IecInput, IecKind, IecState, IecTimerOps, IecTimerRef};
    use crate::time::{CpuTime, Time};
    use std::vec::Vec;

    /// A small deterministic generator (xorshift64*).
    struct Rng(u64);
    impl Rng {
        fn next(&mut self) -> u64 {
            self.0 ^= self.0 >> 12;
            self.0 ^= self.0 << 25;
            self.0 ^= self.0 >> 27;
            self.0.wrapping_mul(0x2545_F491_4F6C_DD1D)
        }
        fn below(&mut self, n: u64) -> u64 {
            self.next() % n
        }
    }

    /// A valid structure of any kind's making (for `set_state`): running or stopped, any IN and Q.
    fn any_state(rng: &mut Rng) -> IecState<u32> {
        let pt = rng.below(60) as u32;
        let running = rng.below(2) == 0;
        IecState {
            kind: None,
            input: rng.below(2) == 0,
            running,
            start: if running { rng.next() as u32 } else { 0 },
            pt,
            et: rng.below(u64::from(pt) + 1) as u32,
            q: rng.below(2) == 0,
        }
    }

    /// `N` timers (full groups of 16 and a shorter last group) scanned with random inputs and
    /// presets (negative, 0, small), random scan intervals (across the 2^32 ms wrap of the
    /// clock), and now and then a timer put in any valid state by `set_state`: every timer's
    /// outputs and state equal a reference TON called once per scan.
    fn bank_equals_reference<const N: usize>(seed: u64) {
        let mut rng = Rng(seed);
        let mut bank = TonBank::<N>::new();
        let mut refs = [IecTimerRef::new(); N];
        let mut now = (1u64 << 32) - 300;
        let mut inputs = [false; N];
        for _ in 0..400 {
            for (i, (input, r)) in inputs.iter_mut().zip(refs.iter_mut()).enumerate() {
                if rng.below(4) == 0 {
                    *input = !*input;
                }
                if rng.below(50) == 0 {
                    let s = any_state(&mut rng);
                    *r = IecTimerRef::from_state(s).expect("a valid state");
                    assert_eq!(bank.set_state(i, s), Ok(true));
                    let kind = bank.get(i).ok().and_then(|b| b.kind);
                    assert_eq!(bank.get(i), Ok(IecState { kind, ..s }));
                }
            }
            let pt: [Time; N] =
                core::array::from_fn(|_| Time::from_millis(rng.below(70) as i32 - 10));
            now += rng.below(25);
            let at = CpuTime::from_millis(now);
            bank.scan(at, &inputs, &pt);
            for (i, r) in refs.iter_mut().enumerate() {
                let out = r.call(IecKind::Ton, at, IecInput::new(inputs[i], pt[i]));
                assert_eq!(bank.output(i), Ok(out), "timer {i} at {now}");
                assert_eq!(bank.get(i), Ok(r.state()), "timer {i} at {now}");
            }
            let outs: Vec<_> = bank.outputs().collect();
            assert_eq!(outs.len(), N);
            assert!(outs
                .iter()
                .enumerate()
                .all(|(i, o)| Ok(*o) == bank.output(i)));
            let (mut q, mut et) = ([false; N], [0u32; N]);
            bank.outputs_into(&mut q, &mut et);
            assert!(outs
                .iter()
                .enumerate()
                .all(|(i, o)| (o.q, o.et) == (q[i], et[i])));
        }
    }

    #[test]
    fn scan_equals_reference() {
        for seed in 1..=20 {
            bank_equals_reference::<1>(seed);
            bank_equals_reference::<16>(seed);
            bank_equals_reference::<37>(seed);
        }
    }

    /// Equality is that of the timers, whatever their representation: a running timer put in
    /// by `set_state` (its ET stored) equals the same timer reached by a scan (its ET derived).
    #[test]
    fn equality_is_of_the_timers() {
        let pt = [Time::from_millis(100)];
        let mut scanned = TonBank::<1>::new();
        scanned.scan(CpuTime::from_millis(10), &[true], &pt);
        scanned.scan(CpuTime::from_millis(40), &[true], &pt);
        let mut set = TonBank::<1>::new();
        set.scan(CpuTime::from_millis(0), &[false], &pt);
        assert_eq!(set.set_state(0, scanned.get(0).expect("timer 0")), Ok(true));
        assert_eq!(set.get(0), scanned.get(0));
        assert_eq!(set, scanned);
        assert_eq!(scanned.output(0).map(|o| o.et), Ok(30));
    }
}
