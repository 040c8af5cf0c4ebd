//! What every benchmark shares: the one deterministic generator and the input streams drawn
//! from it, so that every implementation of a block sees the same inputs, and two runs see the
//! same inputs too.

#![allow(dead_code)]

use plc_timers::time::Time;

/// SplitMix64 (Steele, Lea and Flood 2014): a small, fast, well-mixed deterministic generator.
/// The one generator of every benchmark in `benches/`.
#[derive(Clone, Debug)]
pub struct Rng(u64);

impl Rng {
    /// A generator from `seed`; the same seed gives the same sequence on every machine.
    pub const fn new(seed: u64) -> Rng {
        Rng(seed)
    }

    /// The next 64 random bits.
    pub fn next_u64(&mut self) -> u64 {
        self.0 = self.0.wrapping_add(0x9E37_79B9_7F4A_7C15);
        let mut z = self.0;
        z = (z ^ (z >> 30)).wrapping_mul(0xBF58_476D_1CE4_E5B9);
        z = (z ^ (z >> 27)).wrapping_mul(0x94D0_49BB_1331_11EB);
        z ^ (z >> 31)
    }

    /// A number in `0..n` (`n > 0`; the tiny modulo bias does not matter here).
    pub fn below(&mut self, n: u64) -> u64 {
        self.next_u64() % n
    }

    /// True with probability 1 / `n`.
    pub fn one_in(&mut self, n: u64) -> bool {
        self.below(n) == 0
    }
}

/// Steps per iteration of the one-step benchmarks: the inputs are drawn beforehand, so the timed
/// loop is only the block, and the time per step is the time of an iteration / `STEPS`.
pub const STEPS: usize = 1024;

/// One step of a block's input stream: four input bits with clustered edges, and the time that
/// passes before the step.
#[derive(Clone, Copy, Debug)]
pub struct Step {
    /// Bit 0: IN / S / CU; bit 1: CD; bit 2: R (TONR, counters, S5 timers); bit 3: LD / S of
    /// an S5 counter.
    pub bits: u8,
    /// Milliseconds since the previous step.
    pub dt: u64,
}

impl Step {
    /// Bit `i`.
    pub fn bit(self, i: u32) -> bool {
        self.bits >> i & 1 != 0
    }
}

/// The stream of the one-step benchmarks: IN and CD each flip with probability 1/4 per step
/// (clustered edges: a level lasts four steps on average); R and LD/S are short pulses, each
/// starting with probability 1/16; 0..=14 ms pass between steps (7 ms on average), so a timer
/// of 30 ms (IEC) or 50 ms (S5) runs out after about five steps, and every path is taken: start,
/// running, expiry, stop, reset.
pub fn step_stream(seed: u64) -> Vec<Step> {
    let mut rng = Rng::new(seed);
    let mut level = 0u8;
    (0..STEPS)
        .map(|_| {
            for bit in [0u8, 1] {
                if rng.one_in(4) {
                    level ^= 1 << bit;
                }
            }
            let mut bits = level;
            for bit in [2u8, 3] {
                if rng.one_in(16) {
                    bits |= 1 << bit;
                }
            }
            Step {
                bits,
                dt: rng.below(15),
            }
        })
        .collect()
}

/// The number of timers and counters of the bank scans: 157 words of 64.
pub const BANK: usize = 64 * 157;

/// A plant of `BANK` on-delays: each timer's IN follows its own square wave (period 20..=200
/// scans, duty 25..75 %, random phase) and its PT is 100..=2 000 ms; a scan every 10 ms. At
/// any scan some timers are timing, some have expired, some are off, and some see an edge.
pub struct TonPlant {
    /// PT of every timer.
    pub pt: Vec<Time>,
    /// IN of every timer, for each of `SCANS` successive scans.
    pub scans: Vec<Vec<bool>>,
}

/// Scans in the TON plant's input table; the benchmark cycles through them. Few enough that
/// the table (10 KB a scan) stays in the core's L2 cache, as a PLC's process image does (the
/// I/O update rewrites the same memory every scan); a table of hundreds of scans would
/// measure the L3 cache instead of the timers.
pub const SCANS: usize = 40;

/// The TON plant (seed 42).
pub fn ton_plant() -> TonPlant {
    let mut rng = Rng::new(42);
    let waves: Vec<(u64, u64, u64)> = (0..BANK)
        .map(|_| {
            let period = rng.below(181) + 20;
            let on = period * (rng.below(51) + 25) / 100;
            (period, on, rng.below(period))
        })
        .collect();
    let pt = (0..BANK)
        .map(|_| Time::from_millis(rng.below(1_901) as i32 + 100))
        .collect();
    let scans = (0..SCANS as u64)
        .map(|scan| {
            waves
                .iter()
                .map(|&(period, on, phase)| (scan + phase) % period < on)
                .collect()
        })
        .collect();
    TonPlant { pt, scans }
}

/// The inputs of one counter-bank scan: CU, CD, R, LD of every counter.
pub struct CounterScan {
    /// CU.
    pub cu: Vec<bool>,
    /// CD.
    pub cd: Vec<bool>,
    /// R.
    pub r: Vec<bool>,
    /// LD.
    pub ld: Vec<bool>,
}

/// Scans in the counter banks' input table (40 KB a scan; see [`SCANS`]).
pub const COUNTER_SCANS: usize = 8;

/// `COUNTER_SCANS` scans of `BANK` counters with random edges: CU and CD random bits (a counter sees
/// a rising edge on one scan in four), R and LD each 1 with probability 1/16 (seed 7). With
/// `up_only`, CD and LD stay 0: a CTUD bank driven so becomes a bank of CTU.
pub fn counter_scans(up_only: bool) -> Vec<CounterScan> {
    let mut rng = Rng::new(7);
    (0..COUNTER_SCANS)
        .map(|_| {
            let mut bits = |p: u64| -> Vec<bool> { (0..BANK).map(|_| rng.one_in(p)).collect() };
            let cu = bits(2);
            let r = bits(16);
            let (cd, ld) = if up_only {
                (vec![false; BANK], vec![false; BANK])
            } else {
                (bits(2), bits(16))
            };
            CounterScan { cu, cd, r, ld }
        })
        .collect()
}

/// The number of S5 timers of the timer-area tick.
pub const AREA: usize = 65_536;

/// A timer area's contents: for timer `i`, `None` (a third of them, stopped) or the units
/// (1..=999) and base code (0..=3) of a running time (seed `0x9E37_79B9_7F4A_7C15`).
pub fn area_contents(n: usize) -> Vec<Option<(u16, u8)>> {
    let mut rng = Rng::new(0x9E37_79B9_7F4A_7C15);
    (0..n)
        .map(|_| (!rng.one_in(3)).then(|| (rng.below(999) as u16 + 1, rng.below(4) as u8)))
        .collect()
}

/// The input families every workload of the peers benchmark runs on, so that no figure depends
/// on one shape of input.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Family {
    /// Steady square waves: every input repeats with a period of its own (a conveyor's
    /// sensors, a clock pulse), so a timer or counter takes the same path scan after scan
    /// for a while and the processor's branch predictor learns it.
    Square,
    /// Random inputs: IN (and CU, CD of the one-step stream) flips with probability 0.10 per
    /// step or scan, R, LD and S are random pulses, the counters of the banks see random
    /// edges on every input, the timer area holds random values on random bases. A branch on
    /// an input or on a state is mispredicted about as often as it changes.
    Random,
}

impl Family {
    /// Both families, in the order the benchmark runs them.
    pub const ALL: [Family; 2] = [Family::Square, Family::Random];

    /// The family's name, the prefix of its groups.
    pub const fn name(self) -> &'static str {
        match self {
            Family::Square => "square",
            Family::Random => "random",
        }
    }

    /// How the family's inputs are drawn, for the summary.
    pub const fn description(self) -> &'static str {
        match self {
            Family::Square => {
                "steady square waves: one step: IN/CU a square wave of 16 steps, CD of 12, R and \
                 LD/S a one-step pulse every 64 and 48 steps, 7 ms between steps; TON bank: IN a \
                 square wave per timer (period 20-200 scans, duty 25-75 %); counter banks: CU and \
                 CD square waves of 2, 4 or 8 scans per counter, R and LD a pulse every 8 scans \
                 on a quarter of the counters; timer area: blocks of 1 024 timers on one base, \
                 values in sequence"
            }
            Family::Random => {
                "random: one step: IN/CU and CD flip with probability 0.10 per step, R and LD/S \
                 are 1 with probability 1/16, 0-14 ms between steps; TON bank: IN flips with \
                 probability 0.10 per scan; counter banks: CU, CD random bits (a rising edge one \
                 scan in four), R and LD 1 with probability 1/16; timer area: random values \
                 1-999 on random bases"
            }
        }
    }
}

/// The one-step stream of `family` (see [`Family`]); [`Random`](Family::Random) from `seed`.
pub fn family_step_stream(family: Family, seed: u64) -> Vec<Step> {
    match family {
        Family::Square => (0..STEPS)
            .map(|i| {
                let in_ = u8::from(i % 16 < 8);
                let cd = u8::from((i + 5) % 12 < 6);
                let r = u8::from(i % 64 == 37);
                let ld = u8::from(i % 48 == 20);
                Step {
                    bits: in_ | cd << 1 | r << 2 | ld << 3,
                    dt: 7,
                }
            })
            .collect(),
        Family::Random => {
            let mut rng = Rng::new(seed);
            let mut level = 0u8;
            (0..STEPS)
                .map(|_| {
                    for bit in [0u8, 1] {
                        if rng.below(10) == 0 {
                            level ^= 1 << bit;
                        }
                    }
                    let mut bits = level;
                    for bit in [2u8, 3] {
                        if rng.one_in(16) {
                            bits |= 1 << bit;
                        }
                    }
                    Step {
                        bits,
                        dt: rng.below(15),
                    }
                })
                .collect()
        }
    }
}

/// The TON plant of `family`: [`ton_plant`] for the square waves; for the random family the
/// same presets, each IN flipping with probability 0.10 per scan (seed 43).
pub fn family_ton_plant(family: Family) -> TonPlant {
    let square = ton_plant();
    match family {
        Family::Square => square,
        Family::Random => {
            let mut rng = Rng::new(43);
            let mut level: Vec<bool> = (0..BANK).map(|_| rng.one_in(2)).collect();
            let scans = (0..SCANS)
                .map(|_| {
                    for l in level.iter_mut() {
                        if rng.below(10) == 0 {
                            *l = !*l;
                        }
                    }
                    level.clone()
                })
                .collect();
            TonPlant {
                pt: square.pt,
                scans,
            }
        }
    }
}

/// The counter-bank scans of `family`: [`counter_scans`] for the random family; square waves
/// for the other (see [`Family`]; the periods divide [`COUNTER_SCANS`], so the table repeats
/// without a seam). With `up_only`, CD and LD stay 0.
pub fn family_counter_scans(family: Family, up_only: bool) -> Vec<CounterScan> {
    match family {
        Family::Random => counter_scans(up_only),
        Family::Square => {
            let mut rng = Rng::new(8);
            // Per counter: (period of CU, phase, period of CD, phase, pulse scan of R, of LD).
            let waves: Vec<[u64; 6]> = (0..BANK)
                .map(|i| {
                    let pulses = i % 4 == 0;
                    [
                        2 << rng.below(3),
                        rng.below(8),
                        4 << rng.below(2),
                        rng.below(8),
                        if pulses { rng.below(8) } else { 8 },
                        if pulses { rng.below(8) } else { 8 },
                    ]
                })
                .collect();
            (0..COUNTER_SCANS as u64)
                .map(|s| {
                    let sq = |period: u64, phase: u64| (s + phase) % period < period / 2;
                    let cu = waves.iter().map(|w| sq(w[0], w[1])).collect();
                    let r = waves.iter().map(|w| s == w[4]).collect();
                    let (cd, ld) = if up_only {
                        (vec![false; BANK], vec![false; BANK])
                    } else {
                        (
                            waves.iter().map(|w| sq(w[2], w[3])).collect(),
                            waves.iter().map(|w| s == w[5]).collect(),
                        )
                    };
                    CounterScan { cu, cd, r, ld }
                })
                .collect()
        }
    }
}

/// The timer area's contents for `family` (as [`area_contents`]): random for the random
/// family; for the square family a third of each block of 1 024 timers stopped (every third
/// timer), the block's timers on one base (block `b` on base `b % 4`), values in sequence.
pub fn family_area_contents(family: Family, n: usize) -> Vec<Option<(u16, u8)>> {
    match family {
        Family::Random => area_contents(n),
        Family::Square => (0..n)
            .map(|i| (i % 3 != 0).then(|| ((i % 999) as u16 + 1, ((i / 1024) % 4) as u8)))
            .collect(),
    }
}
