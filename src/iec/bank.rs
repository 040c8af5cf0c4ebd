//! A bank of TON timers in structure-of-arrays form, for a soft-PLC that scans thousands of
//! on-delays: one array per structure member, so that a scan is one pass over each array.
//! Each timer behaves exactly as [`super::IecTimerRef`] called as `TON` once per scan
//! (IEC-BANK-01, checked in `proofs/iec.rs`).

use super::{IecKind, IecOutput, IecState};
use crate::time::{CpuTime, Time};

const IN: u8 = 0b001;
const Q: u8 = 0b010;
const RUNNING: u8 = 0b100;

/// `N` TON timers, called together once per scan.
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
/// assert_eq!(delays.output(0).map(|o| o.et), Some(2_000));
/// ```
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct TonBank<const N: usize> {
    start: [u32; N],
    pt: [u32; N],
    et: [u32; N],
    flags: [u8; N],
    /// Whether a scan has run: before it, no instruction has run on the structures.
    scanned: bool,
}

impl<const N: usize> Default for TonBank<N> {
    fn default() -> Self {
        TonBank::new()
    }
}

impl<const N: usize> TonBank<N> {
    /// The number of timers.
    pub const LEN: usize = N;

    /// A bank of new timers (every structure zero).
    pub const fn new() -> TonBank<N> {
        TonBank {
            start: [0; N],
            pt: [0; N],
            et: [0; N],
            flags: [0; N],
            scanned: false,
        }
    }

    /// The outputs `Q` and `ET` of timer `i`, if it exists.
    pub fn output(&self, i: usize) -> Option<IecOutput<u32>> {
        Some(IecOutput {
            q: *self.flags.get(i)? & Q != 0,
            et: self.et[i],
        })
    }

    /// The outputs of every timer, timer 0 first.
    pub fn outputs(&self) -> impl ExactSizeIterator<Item = IecOutput<u32>> + '_ {
        self.flags
            .iter()
            .zip(&self.et)
            .map(|(&f, &et)| IecOutput { q: f & Q != 0, et })
    }

    /// The state of timer `i` as the reference names it, if it exists.
    pub fn get(&self, i: usize) -> Option<IecState<u32>> {
        let f = *self.flags.get(i)?;
        Some(IecState {
            kind: self.scanned.then_some(IecKind::Ton),
            input: f & IN != 0,
            running: f & RUNNING != 0,
            start: self.start[i],
            pt: self.pt[i],
            et: self.et[i],
            q: f & Q != 0,
        })
    }

    /// Puts timer `i` in `state` (a TON state: its `kind` is ignored). `false`, and no change,
    /// when `i` is out of range or the state is not valid ([`IecState::is_valid`]).
    pub fn set(&mut self, i: usize, state: IecState<u32>) -> bool {
        if i >= N || !state.is_valid() {
            return false;
        }
        self.start[i] = state.start;
        self.pt[i] = state.pt;
        self.et[i] = state.et;
        self.flags[i] = (u8::from(state.input) * IN)
            | (u8::from(state.q) * Q)
            | (u8::from(state.running) * RUNNING);
        true
    }

    /// One scan at CPU time `now`: timer `i` called as TON with `IN` = `input[i]` and
    /// `PT` = `pt[i]`.
    ///
    /// One pass over the arrays with the same straight-line code for every timer: each member
    /// is computed for every case and the inputs select, without a branch, so that LLVM
    /// vectorizes the loop (several timers per instruction) and no timer's state costs a
    /// misprediction.
    ///
    /// Why it equals the reference's TON ([`super::IecTimerRef`], `ton`): a rising IN
    /// (`IN` = 1, its memory 0) starts: START = now, PT latched (negative as 0), running, and
    /// the update that follows sees `elapsed = now - now = 0`, so ET = 0 or PT = 0, and Q
    /// only if PT = 0. Otherwise a running timer updates (`elapsed = now - START` modulo
    /// 2^32, expiry at `elapsed >= PT`: ET = PT, Q = 1, stopped, START = 0; before: ET =
    /// elapsed, Q = 0) and a stopped one keeps ET and Q; its START is 0 already (the validity
    /// invariant, `IecState::is_valid`, which `set` checks and every scan keeps). Last, IN = 0
    /// resets: START = ET = 0, Q = 0, stopped, IN memory 0; PT is kept, as the reference keeps
    /// it (a rise needs IN = 1, so PT is unchanged on that path).
    pub fn scan(&mut self, now: CpuTime, input: &[bool; N], pt: &[Time; N]) {
        let now = now.clock::<u32>();
        self.scanned = true;
        let lanes = self
            .start
            .iter_mut()
            .zip(self.pt.iter_mut())
            .zip(self.et.iter_mut())
            .zip(self.flags.iter_mut())
            .zip(input.iter().zip(pt.iter()));
        for ((((start, latched), et), flags), (&on, preset)) in lanes {
            let f = *flags;
            let rise = on & (f & IN == 0);
            let run = rise | (f & RUNNING != 0);
            let s = if rise { now } else { *start };
            let p = if rise {
                preset.clamp_negative()
            } else {
                *latched
            };
            let elapsed = now.wrapping_sub(s);
            let reached = elapsed >= p;
            let e = if run { elapsed.min(p) } else { *et };
            let q = if run { reached } else { f & Q != 0 };
            let goes_on = run & !reached;
            *start = if on & goes_on { s } else { 0 };
            *latched = p;
            *et = if on { e } else { 0 };
            *flags = if on {
                IN | (u8::from(q) * Q) | (u8::from(goes_on) * RUNNING)
            } else {
                0
            };
        }
    }
}
