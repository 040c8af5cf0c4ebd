//! A bank of TON timers in structure-of-arrays form, for a soft-PLC scanning thousands of
//! on-delays: IN, Q and "running" are bit sets, so the edges of 64 timers are found with one
//! word operation, and only timers that start, stop or run are touched. Each timer behaves as
//! [`super::reference::Reference`] called as `TON` once per scan (checked by
//! `tests/iec_props.rs`).

use crate::time::Time;

/// `64 * WORDS` TON timers.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct TonBank<const WORDS: usize> {
    start: [[u32; 64]; WORDS],
    pt: [[u32; 64]; WORDS],
    et: [[u32; 64]; WORDS],
    input: [u64; WORDS],
    q: [u64; WORDS],
    running: [u64; WORDS],
}

impl<const WORDS: usize> Default for TonBank<WORDS> {
    fn default() -> Self {
        TonBank::new()
    }
}

impl<const WORDS: usize> TonBank<WORDS> {
    /// The number of timers.
    pub const LEN: usize = 64 * WORDS;

    /// A bank of new timers.
    pub const fn new() -> TonBank<WORDS> {
        TonBank {
            start: [[0; 64]; WORDS],
            pt: [[0; 64]; WORDS],
            et: [[0; 64]; WORDS],
            input: [0; WORDS],
            q: [0; WORDS],
            running: [0; WORDS],
        }
    }

    /// `Q` and `ET` of timer `i`, if it exists.
    pub fn output(&self, i: usize) -> Option<(bool, u32)> {
        let (w, b) = (i / 64, i % 64);
        let et = *self.et.get(w)?.get(b)?;
        Some((self.q[w] >> b & 1 != 0, et))
    }

    /// One scan at CPU time `now`: every timer called as TON with its IN (bit `i % 64` of word
    /// `i / 64`) and its preset `pt[i]`.
    pub fn scan(&mut self, now: u32, input: &[u64; WORDS], pt: &[[Time; 64]; WORDS]) {
        for w in 0..WORDS {
            let inp = input[w];
            let rising = inp & !self.input[w];
            let falling = !inp & self.input[w];
            self.input[w] = inp;
            // IN = 0 resets and stops (Table 8-20); ET can only be non-zero after a falling edge.
            self.running[w] &= inp;
            self.q[w] &= inp;
            each_bit(falling, |b| {
                self.et[w][b] = 0;
                self.start[w][b] = 0;
            });
            // A rising IN starts: START = now, PT latched, negative taken as 0.
            each_bit(rising, |b| {
                self.start[w][b] = now;
                self.pt[w][b] = pt[w][b].clamp_negative();
                self.et[w][b] = 0;
            });
            self.running[w] |= rising;
            // The update of every running timer: elapsed = now - START, expiry at ET >= PT.
            let mut expired = 0u64;
            let (start, pts, et) = (&mut self.start[w], &self.pt[w], &mut self.et[w]);
            each_bit(self.running[w], |b| {
                let elapsed = now.wrapping_sub(start[b]);
                if elapsed >= pts[b] {
                    et[b] = pts[b];
                    start[b] = 0;
                    expired |= 1 << b;
                } else {
                    et[b] = elapsed;
                }
            });
            self.running[w] &= !expired;
            self.q[w] |= expired;
        }
    }
}

#[inline]
fn each_bit(mut bits: u64, mut f: impl FnMut(usize)) {
    while bits != 0 {
        f(bits.trailing_zeros() as usize);
        bits &= bits - 1;
    }
}
