//! The peers benchmark: the crate's optimized forms beside its reference and beside ports of
//! the timers and counters of two open IEC 61131-3 runtimes, on the same deterministic inputs
//! in one run, with a copy of the same state as the floor of the bulk scans. At the end it
//! prints a summary table with every ratio of issue 17 and whether its goal is met.
//!
//! ```sh
//! cargo bench --bench peers                     # every workload, then the summary
//! cargo bench --bench peers -- "step TON"       # groups whose name contains it (TON, TONR)
//! cargo bench --bench peers -- 'step TON$'      # the group of that exact name
//! PEERS_SUMMARY_ONLY=1 cargo bench --bench peers            # the summary pass only
//! PEERS_SUMMARY_ONLY=1 cargo bench --bench peers -- random  # one input family
//! PEERS_ONLY=optimized cargo bench --bench peers -- 'random: step TP$'  # one form (a profiler)
//! ```
//!
//! Timing: criterion runs every workload for its own report (skipped with
//! `PEERS_SUMMARY_ONLY`). Then, group by group, a summary pass runs the forms of one block (or
//! one plant) in turn, 100 rounds of 3 ms each, and keeps each form's fastest round: taken in
//! turn, the forms meet the same load from other processes, so their ratios hold on a shared
//! machine, where figures taken minutes apart do not; short turns, many of them, so that some
//! fit between two preemptions on a loaded machine. A one-step workload is timed in four
//! copies of its loop at four placements in the code (`PLACEMENTS`: the same machine code ran
//! 0.98-1.43 ns for one TONR step by its address alone), and its figure is their mean; the
//! summary prints each one's fastest and slowest placement beside the table. So is every loop
//! that calls a block one instance at a time compiled into this binary (the per-instance
//! loops and the per-instance forms of the bulk groups, `Workload::placed`), each placement
//! with instances of its own; the forms that are one library call for the whole array or bank,
//! and the copies, run their code where the library's build put it, one placement each,
//! except `TonBank`, timed on eight banks of its own (`DATA_PLACEMENTS`: one bank allocation
//! took 6.9 µs per scan where others took 5.6).
//!
//! Input families (`common::Family`): every workload runs on steady square waves and on random
//! inputs (IN flipping with probability 0.10 per step or scan; counters with random edges on
//! every input), and the summary prints every goal for each family: a form whose branches
//! follow its inputs is fast on the first and mispredicted on the second. The summary table
//! at the end prints those figures: ns per step (one call of one instance), or µs per scan of
//! a plant, and whether each goal of issue 29 is met, per family.
//!
//! One-step workloads: 8 instances of the block, each fed the same stream of 1 024 steps
//! (`common::family_step_stream`) from a different offset, called in turn as a scan calls its
//! timers; every form builds its arguments from the same input bits in the timed loop. The
//! block's kind is a constant at the call, as at every call site of a PLC program (one generic
//! function per kind). The instances are passed to `black_box` once per step, so that every
//! form reads and writes its instances in memory on every call, and each call's outputs go to
//! `black_box` (for the IEC counters, the outputs the box has: CTU Q = QU and CV, CTD Q = QD
//! and CV, as the peers return them). Bulk workloads: one scan of 10 048 TON
//! (`common::family_ton_plant`), of 10 048 CTUD or CTU INT counters
//! (`common::family_counter_scans`; the kind a constant at the call here too), and one 10 ms
//! tick of 65 536 S5 timers (two thirds running, on mixed bases,
//! `common::family_area_contents`); their floor is a copy (`copy_from_slice`) of as many bytes
//! as the optimized form's state, for the timer area of 2 bytes per timer (the S7 timer word).
//! The arrays of `IecTimer` and of `Counter` are run twice: through `call`, the single-step
//! form, and through `ton_for_arrays` / `call_for_arrays`, the forms for loops over many
//! instances (the goals' figures).
//!
//! Per-instance loops (issue 41): for each of TP, TON, TOF, TONR, CTU, CTD and CTUD, a plain
//! `for` over 10 048 instances calling `call` once per scan, as a runtime compiles `FOR i :=
//! ... DO block[i](...)`, the optimized form's loop beside the reference's (TON, CTU and CTUD
//! in the bulk groups above; TP, TOF, TONR on the TON plant's inputs, TONR's R a pulse at each
//! rise of another timer's IN, and CTD on the CTUD scans, in groups `loop of 10 048 ...`).
//! Goals: the optimized loop no slower than the reference's, and the array forms
//! (`ton_array`, `call_array`) at least 2x faster than it.
//!
//! The peers, ported in [`rusty`] and [`matiec`]:
//!
//! - RuSTy (github `PLC-lang/rusty`), its standard library written in Rust,
//!   `libs/stdlib/src/timers.rs` and `libs/stdlib/src/counters.rs`.
//! - matiec (github `beremiz/matiec`), the standard function blocks written in ST
//!   (`lib/timer.txt`, `lib/counter.txt`, `lib/edge_detection.txt`) as they are compiled to C in
//!   `lib/C/iec_std_FB.h`; OpenPLC v3 ships the same blocks in `utils/matiec_src`.
//!
//! Every port was written from a reading of the algorithm; no source text was copied. All of
//! them have one interface: timers `call(input, pt_ms, now_ms) -> (Q, ET in ms)`, counters
//! `call(cu_or_cd, r_or_ld, pv) -> (Q, CV)`. The clock is a free-running `u32` millisecond
//! counter that the caller passes; where a runtime reads its own clock (RuSTy: the OS monotonic
//! clock through `std::time::Instant`; matiec: the global `__CURRENT_TIME`), the port reads
//! `now_ms` instead. The peers have TON, TOF, TP, CTU and CTD; TONR, CTUD and the S5 blocks are
//! measured against the reference alone.
//!
//! The ports compute what their runtime computes, which is not always what S7 computes (below):
//! on the same input stream they take other paths now and then (a TP pulse swallowed, a counter
//! stopped at PV), so their times are those of the same inputs, not of the same outputs.
//!
//! # Where they differ from S7-1200
//!
//! The S7-1200 semantics as the crate models them: PT is latched when the timer starts; expiry
//! when ET >= PT; ET then stays at PT; START is a copy of a free-running wrapping 32-bit
//! millisecond clock and the elapsed time is `now - START` modulo 2^32; a negative PT counts as
//! 0; counters saturate at the limits of their type and never wrap; CTUD with CU and CD rising
//! together leaves CV unchanged; the edge memories of a counter take the input on every call,
//! also while R or LD holds.
//!
//! | Point | S7-1200 | RuSTy | matiec |
//! |---|---|---|---|
//! | PT while running | latched at start | read on every call: ET clamp and expiry use the current PT, also after expiry | read on every call until expiry (TON/TP/TOF state 1); ignored after |
//! | Expiry | ET >= PT | elapsed > PT (`elapsed <= PT` is "in range"); ET = min(PT, elapsed) reaches PT one unit before Q changes | START + PT <= CURRENT, i.e. ET >= PT |
//! | Expiry tested on the starting call | yes (PT = 0: TON Q = 1, TP no pulse, TOF Q = 0 at once) | no: TON Q = 0, TP and TOF Q = 1 on the starting call | no: same as RuSTy |
//! | After expiry | timer stops, ET = PT | stays "running": the clock is read and ET, Q recomputed on every call | STATE = 2, ET frozen at the PT of that moment |
//! | Clock | wrapping u32 ms, elapsed = now - START mod 2^32 | monotonic `Instant` (never wraps), read up to twice per call; port: now - START mod 2^32 | absolute 64-bit timespec `__CURRENT_TIME` (never wraps), compared as START + PT <= CURRENT; port: a running timer stalls when `now_ms` wraps |
//! | Negative PT | taken as 0 | never expires (PT converted to unsigned), ET = PT < 0 | expires on the first update, ET = PT < 0 |
//! | TP retrigger | new pulse on any rising IN when no pulse runs | re-armed only by a falling IN seen after expiry: if IN fell during the pulse, the next trigger is swallowed | new pulse needs STATE = 0: a rising IN on the first call after the pulse has run out is lost (expiry is noticed after the start test) |
//! | CTU limit | counts past PV, saturates at the type max | counts past PV, saturates at the type max | stops at PV (counts only while CV < PV) |
//! | CTD limit | counts below 0, saturates at the type min | counts below 0, saturates at the type min | stops at 0 (counts only while CV > 0) |
//! | Edge memory while R/LD holds | updated | updated (since PR #1877, 2026; before, R/LD froze it and releasing R with CU held counted once) | updated (R_TRIG called before the R/LD test) |
//! | CTUD | CU and CD rising together: unchanged | exists, not ported: edges evaluated only when R = LD = 0 | exists, not ported: same rule, bounded by PV and 0 |
//! | Per-call overhead | - | instance carries a vtable word | EN/ENO test, a force-flag test on every write (`__SET_VAR`), a nested R_TRIG block in the counters |

// `criterion` generates undocumented items; the ports keep members they never read.
#![allow(missing_docs, dead_code)]

#[path = "../common/mod.rs"]
mod common;
pub mod matiec;
pub mod rusty;

use std::collections::BTreeMap;
use std::hint::black_box;
use std::sync::Mutex;
use std::time::{Duration, Instant};

use common::{Family, Step, AREA, BANK, SCANS, STEPS};
use criterion::Criterion;
use plc_timers::counter::s5::{
    CounterPreset, S5Counter, S5CounterInput, S5CounterKind, S5CounterOps, S5CounterRef,
};
use plc_timers::counter::{
    ArrayOutputs, BankInputs, Counter, CounterBank, CounterInput, CounterKind, CounterOps,
    CounterOutput, CounterRef,
};
use plc_timers::iec::{IecInput, IecKind, IecTimer, IecTimerOps, IecTimerRef, TonBank};
use plc_timers::s5::{
    S5Input, S5Kind, S5State, S5Timer, S5TimerOps, S5TimerRef, TimerMemory, TimerWord,
};
use plc_timers::time::{CpuTime, S5Time, Time, TimeBase};

/// The integer types the counter ports run on: `i16` (INT), `i32` (DINT), `i64` (LINT).
///
/// Both runtimes guard every `+ 1` and `- 1` by a comparison first, so the plain operators of
/// [`PeerInt::plus_one`] and [`PeerInt::minus_one`] never overflow in a faithful port.
pub trait PeerInt: Copy + Ord + Default + core::fmt::Debug {
    /// 0.
    const ZERO: Self;
    /// The type's smallest value.
    const MIN: Self;
    /// The type's largest value.
    const MAX: Self;
    /// `self + 1`.
    fn plus_one(self) -> Self;
    /// `self - 1`.
    fn minus_one(self) -> Self;
}

macro_rules! peer_int {
    ($($t:ty),*) => {$(
        impl PeerInt for $t {
            const ZERO: Self = 0;
            const MIN: Self = <$t>::MIN;
            const MAX: Self = <$t>::MAX;
            #[inline(always)]
            fn plus_one(self) -> Self {
                self + 1
            }
            #[inline(always)]
            fn minus_one(self) -> Self {
                self - 1
            }
        }
    )*};
}

peer_int!(i16, i32, i64);

// ---------------------------------------------------------------------------------------------
// Timing: every workload is a routine that runs `iters` iterations and returns the time they
// took. Criterion runs each one for its own report; then the summary pass runs the workloads of
// each group in turn, round after round, and keeps each one's fastest round.

/// The routine that runs `iteration` `iters` times and returns the time they took.
fn timed<'a>(mut iteration: impl FnMut() + 'a) -> Run<'a> {
    Box::new(move |iters| {
        let start = Instant::now();
        for _ in 0..iters {
            iteration();
        }
        start.elapsed()
    })
}

/// A routine that runs `iters` iterations of a workload and returns the time they took.
type Run<'a> = Box<dyn FnMut(u64) -> Duration + 'a>;

/// One workload: a form of a block (or a copy) on a group's inputs.
struct Workload<'a> {
    name: String,
    /// Time per iteration / `units` is the time per step (ns) or per scan (µs, with `scale`).
    units: f64,
    scale: f64,
    /// The routine, once per placement of its code: one-step workloads and the per-instance
    /// loops have [`PLACEMENTS`] copies of their timed loop (see [`step_loop`] and
    /// [`Workload::placed`]), the other bulk workloads one.
    runs: Vec<Run<'a>>,
}

impl<'a> Workload<'a> {
    /// A workload whose iteration is `routine`, timed as a whole.
    fn plain(name: &str, units: usize, scale: f64, routine: impl FnMut() + 'a) -> Self {
        Workload {
            name: name.to_owned(),
            units: units as f64,
            scale,
            runs: vec![timed(routine)],
        }
    }

    /// A workload whose iteration is `scan`, a loop that calls a block once per instance inline
    /// in this binary (the per-instance loops), timed at the [`PLACEMENTS`] of a one-step
    /// workload: placement `P` runs its own clone of `scan` (its own instances, which the
    /// closure owns) in [`placed_scan`]`::<P>`. Callers mark the closure `#[inline(always)]`, so
    /// that the loop is compiled into each placement's function, not called from it.
    fn placed(name: &str, units: usize, scale: f64, scan: impl FnMut() + Clone + 'a) -> Self {
        let runs: [Run<'a>; PLACEMENTS] = [
            placed_run::<0>(scan.clone()),
            placed_run::<1>(scan.clone()),
            placed_run::<2>(scan.clone()),
            placed_run::<3>(scan),
        ];
        Workload {
            name: name.to_owned(),
            units: units as f64,
            scale,
            runs: runs.into(),
        }
    }

    /// A workload that times itself (to leave an untimed restore out).
    fn custom(name: &str, scale: f64, run: impl FnMut(u64) -> Duration + 'a) -> Self {
        Workload {
            name: name.to_owned(),
            units: 1.0,
            scale,
            runs: vec![Box::new(run)],
        }
    }

    /// Time per unit of `iters` iterations of placement `p`.
    fn per_unit(&mut self, p: usize, iters: u64) -> f64 {
        let t = (self.runs[p])(iters);
        t.as_nanos() as f64 / iters as f64 / self.units * self.scale
    }
}

/// A per-instance loop over [`BANK`] instances made from `new`, timed at the [`PLACEMENTS`]
/// ([`Workload::placed`]): scan `k` (1, 2, ...) runs `scan(instances, k)`, the loop over the
/// instances as a runtime compiles `FOR i := ... DO block[i](...)`. Callers mark `scan`
/// `#[inline(always)]`, so that the loop is compiled into each placement's function.
fn per_instance_scans<'a, T: Clone + 'a>(
    name: &str,
    new: T,
    mut scan: impl FnMut(&mut [T], u64) + Clone + 'a,
) -> Workload<'a> {
    let mut instances = vec![new; BANK];
    let mut k = 0u64;
    Workload::placed(
        name,
        1,
        1e-3,
        #[inline(always)]
        move || {
            k += 1;
            scan(&mut instances, k);
        },
    )
}

/// The summary figure of each workload (`group/name`): its fastest interleaved round, the mean
/// over its placements.
static RESULTS: Mutex<BTreeMap<String, f64>> = Mutex::new(BTreeMap::new());

/// The fastest and slowest placement of each workload timed at several (`group/name`), for
/// the summary.
static SPREADS: Mutex<BTreeMap<String, (f64, f64)>> = Mutex::new(BTreeMap::new());

/// Rounds of the summary pass, and the time of one workload's turn in a round.
const ROUNDS: usize = 100;
const TURN: Duration = Duration::from_millis(3);

/// Runs a group: each workload under criterion (its report), then the summary pass, which runs
/// the group's workloads in turn for `ROUNDS` rounds and records each one's fastest round. Taken
/// in turn, the forms of a block meet the same load from other processes, and the fastest of
/// several rounds is the one least disturbed: on a shared machine the ratios come out steadier
/// than from figures taken minutes apart.
fn run_group(c: &mut Criterion, group: &str, mut workloads: Vec<Workload<'_>>) {
    if !c_filter_matches(group) {
        return;
    }
    if let Ok(only) = std::env::var("PEERS_ONLY") {
        workloads.retain(|w| w.name == only);
    }
    if std::env::var_os("PEERS_SUMMARY_ONLY").is_none() {
        let mut g = c.benchmark_group(group);
        for w in workloads.iter_mut() {
            // Criterion's report: the iterations shared out over the placements, `iters` in all.
            g.bench_function(w.name.as_str(), |b| {
                b.iter_custom(|iters| {
                    let n = w.runs.len() as u64;
                    (w.runs.iter_mut().zip(0..))
                        .map(|(run, p)| run(iters / n + u64::from(p < iters % n)))
                        .sum()
                })
            });
        }
        g.finish();
    }
    // Every placement of every workload, each a workload of the summary pass.
    let slots: Vec<(usize, usize)> = (workloads.iter().enumerate())
        .flat_map(|(i, w)| (0..w.runs.len()).map(move |p| (i, p)))
        .collect();
    // Iterations per turn, from one probe each.
    let iters: Vec<u64> = (slots.iter())
        .map(|&(i, p)| {
            let t = (workloads[i].runs[p])(1).max(Duration::from_nanos(1));
            (TURN.as_nanos() / t.as_nanos()).clamp(1, 1 << 20) as u64
        })
        .collect();
    let mut best = vec![f64::INFINITY; slots.len()];
    for _ in 0..ROUNDS {
        for ((&(i, p), &n), b) in slots.iter().zip(&iters).zip(best.iter_mut()) {
            *b = b.min(workloads[i].per_unit(p, n));
        }
    }
    let mut results = RESULTS.lock().expect("no panic while holding the lock");
    let mut spreads = SPREADS.lock().expect("no panic while holding the lock");
    for (i, w) in workloads.iter().enumerate() {
        let bests: Vec<f64> = (slots.iter().zip(&best))
            .filter(|((j, _), _)| *j == i)
            .map(|(_, &b)| b)
            .collect();
        let key = format!("{group}/{}", w.name);
        let mean = bests.iter().sum::<f64>() / bests.len() as f64;
        let (lo, hi) = bests.iter().fold((f64::INFINITY, 0.0f64), |(lo, hi), &b| {
            (lo.min(b), hi.max(b))
        });
        if bests.len() > 1 {
            spreads.insert(key.clone(), (lo, hi));
        }
        results.insert(key, mean);
    }
}

/// The filter given on the command line (`cargo bench --bench peers -- FILTER`), if any: a
/// group runs when its name contains one of the `|`-separated parts, or equals a part written
/// with a final `$` (criterion's own filter is a regular expression; this one, for the summary
/// pass, is a plain substring, which the group names in this file fit).
fn c_filter_matches(group: &str) -> bool {
    let args: Vec<String> = std::env::args().skip(1).collect();
    let mut filter = None;
    let mut skip = false;
    for a in &args {
        if skip {
            skip = false;
            continue;
        }
        if a.starts_with("--") {
            // Options with a value.
            skip = matches!(
                a.as_str(),
                "--warm-up-time"
                    | "--measurement-time"
                    | "--sample-size"
                    | "--save-baseline"
                    | "--baseline"
                    | "--profile-time"
                    | "--noise-threshold"
                    | "--confidence-level"
                    | "--significance-level"
                    | "--nresamples"
                    | "--output-format"
                    | "--color"
                    | "--plotting-backend"
                    | "--format"
            );
            continue;
        }
        filter = Some(a.clone());
    }
    filter.is_none_or(|f| {
        f.split('|').any(|part| match part.strip_suffix('$') {
            Some(exact) => group == exact,
            None => group.contains(part),
        })
    })
}

/// The summary figure of a workload, if it ran.
fn result(key: &str) -> Option<f64> {
    RESULTS
        .lock()
        .expect("no panic while holding the lock")
        .get(key)
        .copied()
}

// ---------------------------------------------------------------------------------------------
// One step: 1 024 steps of each of 8 instances of one block per iteration.

/// Instances of a block in a one-step workload, called in turn as a scan calls them.
const INSTANCES: usize = 8;

/// A one-step input stream as every implementation reads it: per step, the input bits of each
/// of `INSTANCES` instances (instance `j` reads the stream `j * STEPS / INSTANCES` steps
/// further on, so that the instances are in different states) and the step's CPU time relative
/// to the start of an iteration; and the time an iteration spans (the next iteration continues
/// from there, so time never goes back). Every implementation builds its call's arguments from
/// the same bits inside the timed loop, so the decoding costs all of them alike.
///
/// Why several instances: a PLC calls each of its timers once per scan, with the other
/// timers' calls in between. One instance called back to back would instead measure the
/// latency of a chain of calls through the same memory (each call waiting for the previous
/// call's stores), which no program runs.
struct Stream {
    bits: Vec<[u8; INSTANCES]>,
    times: Vec<u64>,
    span: u64,
}

impl Stream {
    fn new(steps: &[Step]) -> Stream {
        let mut t = 0;
        let times = steps
            .iter()
            .map(|s| {
                t += s.dt;
                t
            })
            .collect();
        let bits = (0..steps.len())
            .map(|i| core::array::from_fn(|j| steps[(i + j * STEPS / INSTANCES) % STEPS].bits))
            .collect();
        Stream {
            bits,
            times,
            span: t,
        }
    }

    /// The workload `name`: `step(instance, bits, now)` over the stream for `INSTANCES`
    /// instances made by `new`, each output passed to `black_box`; in [`PLACEMENTS`] copies of
    /// the timed loop, each with instances of its own.
    fn workload<'a, T: 'a, O>(
        &'a self,
        name: &str,
        new: impl Fn() -> T,
        step: impl FnMut(&mut T, u8, u64) -> O + Clone + 'a,
    ) -> Workload<'a> {
        let runs: [Run<'a>; PLACEMENTS] = [
            self.placed::<0, T, O>(&new, step.clone()),
            self.placed::<1, T, O>(&new, step.clone()),
            self.placed::<2, T, O>(&new, step.clone()),
            self.placed::<3, T, O>(&new, step),
        ];
        Workload {
            name: name.to_owned(),
            units: (STEPS * INSTANCES) as f64,
            scale: 1.0,
            runs: runs.into(),
        }
    }

    /// The routine of placement `P`: iterations of [`step_loop`]`::<P>`.
    fn placed<'a, const P: usize, T: 'a, O>(
        &'a self,
        new: &impl Fn() -> T,
        mut step: impl FnMut(&mut T, u8, u64) -> O + 'a,
    ) -> Run<'a> {
        let mut instances: [Instance<T>; INSTANCES] = core::array::from_fn(|_| Instance(new()));
        let mut base = 0;
        timed(move || {
            step_loop::<P, T, O>(self, &mut instances, base, &mut step);
            base += self.span;
        })
    }
}

/// Copies of each one-step workload's timed loop. The same machine code of a single step ran
/// up to 30 % faster or slower from one build to the next, by where the linker put it (TONR's
/// optimized step: 0.99 and 1.31 ns on square waves in two builds whose loops differ only in
/// their addresses, by 32 bytes within a cache line among others; the reference's TP 1.16 and
/// 1.36). A figure of one placement is then a draw, and a ratio of two such figures says as
/// much about the two addresses as about the two forms. Each one-step workload is therefore
/// timed in four copies of its loop, the `k`-th moved `k` × 16 bytes further into its function
/// (x86-64: the loops are aligned to 16 bytes, so the four copies put the loop at each
/// 16-byte offset of a 64-byte line, whatever the function's own address), and its figure
/// is the mean of the four.
///
/// The per-instance loops over 10 048 instances (`Workload::placed`) inline `call` into a loop
/// of this binary, so they move with every change too: the reference's TOF loop took 36.0 and
/// 38.4 µs per scan in two builds that differed only in another block's code, and the TOF
/// loop's ratio to the reference's went from 0.96x to 1.04x with unchanged code, as large as
/// the few per cent its goal is about. They are timed at the same placements.
const PLACEMENTS: usize = 4;

/// One iteration of a one-step workload: every step of the stream, each instance called in
/// turn. A function of its own per placement `P` (never inlined, so that each copy has its own
/// address; the padding of [`shift_code`] makes the copies differ, so that none is merged
/// with another).
#[inline(never)]
fn step_loop<const P: usize, T, O>(
    stream: &Stream,
    instances: &mut [Instance<T>; INSTANCES],
    base: u64,
    step: &mut impl FnMut(&mut T, u8, u64) -> O,
) {
    shift_code::<P>();
    for (bits, &t) in stream.bits.iter().zip(&stream.times) {
        let now = base + t;
        // The instances go to `black_box` once per step: the compiler must then take their
        // memory as read and written outside, so every call reads and writes its instance in
        // memory, as a PLC does with its instance data (without it, the compiler kept some
        // forms' state in registers across steps and not others').
        black_box(&mut *instances);
        for (instance, &bits) in instances.iter_mut().zip(bits) {
            black_box(step(&mut instance.0, bits, now));
        }
    }
}

/// The routine of placement `P` of a [`Workload::placed`]: iterations of [`placed_scan`]`::<P>`.
fn placed_run<'a, const P: usize>(mut scan: impl FnMut() + 'a) -> Run<'a> {
    timed(move || placed_scan::<P>(&mut scan))
}

/// One iteration of a per-instance loop at placement `P`: the loop of `scan` (inlined here)
/// moved by [`shift_code`], as [`step_loop`] moves a step's loop.
#[inline(never)]
fn placed_scan<const P: usize>(scan: &mut impl FnMut()) {
    shift_code::<P>();
    scan();
}

/// `P` × 16 bytes of one-byte `nop`s before the loop that follows, run once per iteration
/// (8 192 steps): they move the loop `P` × 16 bytes further into its function.
#[inline(always)]
fn shift_code<const P: usize>() {
    #[cfg(target_arch = "x86_64")]
    // SAFETY: the block is `P * 16` one-byte `nop` instructions (0x90), which read and write no
    // register, no memory and no flag, as the options declare.
    unsafe {
        core::arch::asm!(
            ".fill {n}, 1, 0x90",
            n = const P * 16,
            options(nomem, nostack, preserves_flags)
        );
    }
}

/// One instance's data, on a cache line of its own, as in a PLC each block has its instance
/// data block: the instances of a one-step workload do not share lines, so that no form gains
/// or loses by how many of its instances fit in one (two-byte S5 counters side by side let the
/// compiler merge their loads across instances, and the merged load then waits for the
/// previous step's stores).
#[repr(align(64))]
struct Instance<T>(T);

/// Bit `i` of a step's input bits.
#[inline(always)]
fn bit(bits: u8, i: u32) -> bool {
    bits >> i & 1 != 0
}

/// PT of the IEC timers, in ms.
const IEC_PT_MS: i32 = 30;

/// One group per IEC timer kind: reference, optimized and the peers, on IN = bit 0 (and R =
/// bit 2 for TONR).
fn step_iec(c: &mut Criterion, stream: &Stream, family: Family) {
    step_iec_kind::<0>(c, stream, family);
    step_iec_kind::<1>(c, stream, family);
    step_iec_kind::<2>(c, stream, family);
    step_iec_kind::<3>(c, stream, family);
}

/// The group of `IecKind::ALL[K]`. The kind is a constant in every call (`IecKind::ALL[K]` in the
/// closure's body, not a captured variable), as it is at every call site of a PLC program: the
/// compiler drops the other kinds' code from the reference and the optimized call alike, as the
/// peers' types have only their own.
fn step_iec_kind<const K: usize>(c: &mut Criterion, stream: &Stream, family: Family) {
    const PT: Time = Time::from_millis(IEC_PT_MS);
    let input = |b: u8| IecInput::new(bit(b, 0), PT).with_reset(bit(b, 2));
    let kind = IecKind::ALL[K];
    let mut ws = vec![
        stream.workload("reference", IecTimerRef::<u32>::new, move |t, x, now| {
            t.call(IecKind::ALL[K], CpuTime::from_millis(now), input(x))
        }),
        stream.workload("optimized", IecTimer::new, move |t, x, now| {
            t.call(IecKind::ALL[K], CpuTime::from_millis(now), input(x))
        }),
    ];
    macro_rules! peers {
        ($rusty:ty, $matiec:ty) => {{
            ws.push(stream.workload("RuSTy", <$rusty>::new, |t, x, now| {
                t.call(bit(x, 0), IEC_PT_MS, now as u32)
            }));
            ws.push(stream.workload("matiec", <$matiec>::new, |t, x, now| {
                t.call(bit(x, 0), IEC_PT_MS, now as u32)
            }));
        }};
    }
    match kind {
        IecKind::Ton => {
            // The TON of the arrays, on the same stream (for comparison; not a goal).
            ws.push(
                stream.workload("optimized, ton_for_arrays", IecTimer::new, |t, x, now| {
                    t.ton_for_arrays(CpuTime::from_millis(now), input(x))
                }),
            );
            peers!(rusty::Ton, matiec::Ton)
        }
        IecKind::Tof => peers!(rusty::Tof, matiec::Tof),
        IecKind::Tp => peers!(rusty::Tp, matiec::Tp),
        IecKind::Tonr => {}
    }
    run_group(c, &group_name(family, &format!("step {}", kind.name())), ws);
}

/// PV of the IEC counters.
const COUNTER_PV: i16 = 10;

/// One group per IEC counter kind (INT): CU = bit 0, CD = bit 1, R = bit 2, LD = bit 3; the
/// peers' CTU takes (CU, R), their CTD (CD, LD).
fn step_counters(c: &mut Criterion, stream: &Stream, family: Family) {
    step_counter_kind::<0>(c, stream, family);
    step_counter_kind::<1>(c, stream, family);
    step_counter_kind::<2>(c, stream, family);
}

/// The group of `CounterKind::ALL[K]`, the kind a constant in every call (see `step_iec_kind`).
fn step_counter_kind<const K: usize>(c: &mut Criterion, stream: &Stream, family: Family) {
    let input = |b: u8| CounterInput {
        cu: bit(b, 0),
        cd: bit(b, 1),
        r: bit(b, 2),
        ld: bit(b, 3),
        pv: COUNTER_PV,
    };
    let kind = CounterKind::ALL[K];
    // The outputs the box has (CTU: Q = QU and CV; CTD: Q = QD and CV; CTUD: QU, QD, CV), as
    // a program reads them and as the peers return them.
    let outputs = |o: CounterOutput<i16>| match CounterKind::ALL[K] {
        CounterKind::Ctu => (o.qu, false, o.cv),
        CounterKind::Ctd => (false, o.qd, o.cv),
        CounterKind::Ctud => (o.qu, o.qd, o.cv),
    };
    let mut ws = vec![
        stream.workload("reference", CounterRef::<i16>::new, move |t, x, _| {
            outputs(t.call(CounterKind::ALL[K], input(x)))
        }),
        stream.workload("optimized", Counter::<i16>::new, move |t, x, _| {
            outputs(t.call(CounterKind::ALL[K], input(x)))
        }),
        // The form for arrays, on the same stream (for comparison; not a goal).
        stream.workload(
            "optimized, call_for_arrays",
            Counter::<i16>::new,
            move |t, x, _| outputs(t.call_for_arrays(CounterKind::ALL[K], input(x))),
        ),
    ];
    macro_rules! peers {
        ($rusty:ty, $matiec:ty, $count:literal, $level:literal) => {{
            ws.push(stream.workload("RuSTy", <$rusty>::new, |t, x, _| {
                t.call(bit(x, $count), bit(x, $level), COUNTER_PV)
            }));
            ws.push(stream.workload("matiec", <$matiec>::new, |t, x, _| {
                t.call(bit(x, $count), bit(x, $level), COUNTER_PV)
            }));
        }};
    }
    match kind {
        CounterKind::Ctu => peers!(rusty::Ctu<i16>, matiec::Ctu<i16>, 0, 2),
        CounterKind::Ctd => peers!(rusty::Ctd<i16>, matiec::Ctd<i16>, 1, 3),
        CounterKind::Ctud => {}
    }
    run_group(c, &group_name(family, &format!("step {}", kind.name())), ws);
}

/// One group per S5 timer kind (S = bit 0, R = bit 2, FR = 0 as in a LAD box, TV 5 x 10 ms)
/// and per S5 counter kind (CU = bit 0, CD = bit 1, R = bit 2, S = bit 3, PV C#5).
fn step_s5(c: &mut Criterion, stream: &Stream, family: Family) {
    step_s5_timer_kind::<0>(c, stream, family);
    step_s5_timer_kind::<1>(c, stream, family);
    step_s5_timer_kind::<2>(c, stream, family);
    step_s5_timer_kind::<3>(c, stream, family);
    step_s5_timer_kind::<4>(c, stream, family);
    step_s5_counter_kind::<0>(c, stream, family);
    step_s5_counter_kind::<1>(c, stream, family);
    step_s5_counter_kind::<2>(c, stream, family);
}

/// The group of `S5Kind::ALL[K]`, the kind a constant in every call (see `step_iec_kind`).
fn step_s5_timer_kind<const K: usize>(c: &mut Criterion, stream: &Stream, family: Family) {
    const TV: S5Time = plc_timers::s5time!("S5T#50MS");
    let input = |b: u8| S5Input::new(bit(b, 0), bit(b, 2), TV);
    let ws = vec![
        stream.workload("reference", S5TimerRef::new, move |t, x, now| {
            t.call(S5Kind::ALL[K], CpuTime::from_millis(now), input(x))
        }),
        stream.workload("optimized", S5Timer::new, move |t, x, now| {
            t.call(S5Kind::ALL[K], CpuTime::from_millis(now), input(x))
        }),
    ];
    run_group(
        c,
        &group_name(family, &format!("step {}", S5Kind::ALL[K].name())),
        ws,
    );
}

/// The group of `S5CounterKind::ALL[K]`, the kind a constant in every call.
fn step_s5_counter_kind<const K: usize>(c: &mut Criterion, stream: &Stream, family: Family) {
    const PV: CounterPreset = match CounterPreset::new(5) {
        Ok(pv) => pv,
        Err(_) => panic!("0..=999"),
    };
    let input = move |b: u8| S5CounterInput {
        cu: bit(b, 0),
        cd: bit(b, 1),
        r: bit(b, 2),
        s: bit(b, 3),
        fr: false,
        pv: PV,
    };
    let ws = vec![
        stream.workload("reference", S5CounterRef::new, move |t, x, _| {
            t.call(S5CounterKind::ALL[K], input(x))
        }),
        stream.workload("optimized", S5Counter::new, move |t, x, _| {
            t.call(S5CounterKind::ALL[K], input(x))
        }),
    ];
    run_group(
        c,
        &group_name(family, &format!("step {}", S5CounterKind::ALL[K].name())),
        ws,
    );
}

// ---------------------------------------------------------------------------------------------
// Bulk: one scan of a plant per iteration.

/// Allocations of the TON bank: its scan is timed on [`DATA_PLACEMENTS`] banks of their own,
/// each with its own copy of the PT array at an offset from the bank (spread evenly over a 4
/// KiB page, the offsets that decide whether loads and stores alias in an x86 processor's
/// memory disambiguation), and its figure is their mean. With one bank, the same binary took
/// 6.86-6.89 µs per scan in two whole runs (commit 3258cce) and 5.55-5.73 when the heap lay
/// otherwise (a group filter, which skips the other groups' allocations; another `malloc`
/// threshold). What made that one allocation slow was not found: it was not PT's offset (here
/// the eight offsets take the same time, 5.57-5.65 µs in a whole run), and the eight banks of a
/// run have not shown it. (The IN arrays are one allocation per scan already.)
const DATA_PLACEMENTS: usize = 8;

/// A copy of a slice in a buffer of its own, element 0 at `offset` bytes past `anchor` modulo
/// 4 096.
struct PlacedCopy<T> {
    buf: Vec<T>,
    start: usize,
}

impl<T: Copy + Default> PlacedCopy<T> {
    fn new(data: &[T], anchor: usize, offset: usize) -> Self {
        const PAGE: usize = 4096;
        let size = size_of::<T>();
        let mut buf = vec![T::default(); data.len() + PAGE / size];
        let want = (anchor + offset) % PAGE;
        let start = (want + PAGE - buf.as_ptr() as usize % PAGE) % PAGE / size;
        buf[start..start + data.len()].copy_from_slice(data);
        PlacedCopy { buf, start }
    }

    fn array<const N: usize>(&self) -> &[T; N] {
        self.buf[self.start..][..N].try_into().expect("N elements")
    }
}

/// A copy of `bytes` bytes from one buffer to another: the floor of a scan that reads and
/// writes a state of that size once.
fn copy_floor<'a>(name: &str, bytes: usize) -> Workload<'a> {
    let src = vec![0x5Au8; bytes];
    let mut dst = vec![0u8; bytes];
    Workload::plain(name, 1, 1e-3, move || {
        dst.copy_from_slice(black_box(&src));
        black_box(&mut dst);
    })
}

/// The clock of scan `k`: a scan every 10 ms.
fn scan_time(k: u64) -> u64 {
    10 * k
}

fn bulk_ton(c: &mut Criterion, family: Family) {
    let plant = common::family_ton_plant(family);
    let pt: Box<[Time; BANK]> = plant.pt.clone().try_into().expect("BANK PTs");
    let scans: Vec<Box<[bool; BANK]>> = plant
        .scans
        .iter()
        .map(|s| s.clone().try_into().expect("BANK inputs"))
        .collect();
    let pt_ms: Box<[i32; BANK]> = plant
        .pt
        .iter()
        .map(|t| t.as_millis())
        .collect::<Vec<i32>>()
        .try_into()
        .expect("BANK PTs");
    let (pt, scans, pt_ms): (&[Time; BANK], _, &[i32; BANK]) = (&pt, &scans, &pt_ms);
    /// The per-instance loop: every timer called once with its IN and PT, its outputs passed
    /// to `black_box`. The inputs are walked in step with the timers (one zip), so that the
    /// loop costs every form the same few instructions.
    macro_rules! per_instance {
        ($name:literal, $new:expr, $pts:expr, |$t:ident, $input:ident, $pt:ident, $now:ident| $call:expr) => {
            per_instance_scans(
                $name,
                $new,
                #[inline(always)]
                move |timers, k| {
                    let $now = scan_time(k);
                    let inputs: &[bool; BANK] = &scans[k as usize % SCANS];
                    for (($t, &$input), &$pt) in timers.iter_mut().zip(inputs).zip($pts) {
                        black_box($call);
                    }
                },
            )
        };
    }
    let ws = vec![
        per_instance!(
            "reference (IecTimerRef array)",
            IecTimerRef::new(),
            pt,
            |t, input, pt, now| {
                t.call(
                    IecKind::Ton,
                    CpuTime::from_millis(now),
                    IecInput::new(input, pt),
                )
            }
        ),
        per_instance!(
            "optimized (IecTimer array, call)",
            IecTimer::new(),
            pt,
            |t, input, pt, now| {
                t.call(
                    IecKind::Ton,
                    CpuTime::from_millis(now),
                    IecInput::new(input, pt),
                )
            }
        ),
        per_instance!(
            "optimized (IecTimer array, ton_for_arrays)",
            IecTimer::new(),
            pt,
            |t, input, pt, now| {
                t.ton_for_arrays(CpuTime::from_millis(now), IecInput::new(input, pt))
            }
        ),
        per_instance!(
            "RuSTy (array)",
            rusty::Ton::new(),
            pt_ms,
            |t, input, pt, now| t.call(input, pt, now as u32)
        ),
        per_instance!(
            "matiec (array)",
            matiec::Ton::new(),
            pt_ms,
            |t, input, pt, now| t.call(input, pt, now as u32)
        ),
        Workload {
            name: "optimized (TonBank)".to_owned(),
            units: 1.0,
            scale: 1e-3,
            runs: (0..DATA_PLACEMENTS)
                .map(|p| -> Run<'_> {
                    let mut bank = Box::new(TonBank::<BANK>::new());
                    let anchor = &raw const *bank as usize;
                    let pt = PlacedCopy::new(pt, anchor, p * 4096 / DATA_PLACEMENTS);
                    let mut k = 0u64;
                    timed(move || {
                        k += 1;
                        bank.scan(
                            CpuTime::from_millis(scan_time(k)),
                            &scans[k as usize % SCANS],
                            pt.array(),
                        );
                        black_box(&mut bank);
                    })
                })
                .collect(),
        },
        {
            let mut timers = Box::new([IecTimer::new(); BANK]);
            let (mut q, mut et) = (Box::new([false; BANK]), Box::new([0u32; BANK]));
            let mut k = 0u64;
            Workload::plain(
                "optimized (IecTimer array, ton_array)",
                1,
                1e-3,
                move || {
                    k += 1;
                    IecTimer::ton_array(
                        &mut timers,
                        CpuTime::from_millis(scan_time(k)),
                        &scans[k as usize % SCANS],
                        pt,
                        &mut q,
                        &mut et,
                    );
                    black_box((&mut timers, &mut q, &mut et));
                },
            )
        },
        copy_floor("copy of the TonBank state", size_of::<TonBank<BANK>>()),
        copy_floor("copy of the IecTimer array", BANK * size_of::<IecTimer>()),
        // The per-instance floor: the loop above with a call that only takes its inputs into
        // its 16 bytes and passes on an output of the IecOutput's size, no rule. No form that
        // calls one instance at a time in its own data does less.
        per_instance!(
            "per-instance floor",
            [0u32; 4],
            pt_ms,
            |t, input, pt, now| {
                t[0] = u32::from(input) ^ now as u32;
                t[1] = pt as u32;
                (input, t[2])
            }
        ),
    ];
    run_group(c, &group_name(family, TON_BANK), ws);
}

/// The per-instance loop of IEC timer kind `IecKind::ALL[K]` (TP, TOF, TONR; TON's is in
/// [`bulk_ton`]) as a runtime writes it: a plain `for` over 10 048 instances, each called once
/// per scan with its IN and PT (the TON plant's), its outputs passed to `black_box`; TONR's R
/// is a one-scan pulse at each rise of another timer's IN (timer `i + BANK / 2`), so that it
/// follows the family's inputs too. The reference's loop against the optimized `call`'s.
fn loop_iec<const K: usize>(c: &mut Criterion, family: Family) {
    let kind = IecKind::ALL[K];
    let plant = common::family_ton_plant(family);
    let pt: &[Time] = &plant.pt;
    let scans: &[Vec<bool>] = &plant.scans;
    let resets: Vec<Vec<bool>> = (0..SCANS)
        .map(|k| {
            let (now, before) = (&scans[k], &scans[(k + SCANS - 1) % SCANS]);
            (0..BANK)
                .map(|i| {
                    let j = (i + BANK / 2) % BANK;
                    now[j] && !before[j]
                })
                .collect()
        })
        .collect();
    let resets = &resets;
    macro_rules! per_instance {
        ($name:literal, $new:expr) => {
            per_instance_scans(
                $name,
                $new,
                #[inline(always)]
                move |timers, k| {
                    let now = CpuTime::from_millis(scan_time(k));
                    let s = k as usize % SCANS;
                    let lanes = timers.iter_mut().zip(&scans[s]).zip(&resets[s]).zip(pt);
                    for (((t, &input), &reset), &pt) in lanes {
                        // The kind a constant at the call, as in a PLC program.
                        let input = IecInput::new(input, pt).with_reset(reset);
                        black_box(t.call(IecKind::ALL[K], now, input));
                    }
                },
            )
        };
    }
    let ws = vec![
        per_instance!("reference (IecTimerRef array)", IecTimerRef::<u32>::new()),
        per_instance!("optimized (IecTimer array, call)", IecTimer::new()),
    ];
    run_group(c, &group_name(family, &loop_group(kind.name())), ws);
}

/// The group of the per-instance loop over 10 048 instances of `block` (TP, TOF, TONR, CTD).
fn loop_group(block: &str) -> String {
    format!("loop of 10 048 {block}")
}

/// The per-instance loop of 10 048 CTD INT counters (CTU's and CTUD's are in
/// [`bulk_counters`]), on the CTUD banks' scans (CD and LD of each counter): the reference's
/// `call` against the optimized forms, called one counter at a time and as one
/// `Counter::call_array`.
fn loop_ctd(c: &mut Criterion, family: Family) {
    let scans: Vec<[Box<[bool; BANK]>; 4]> = common::family_counter_scans(family, false)
        .into_iter()
        .map(|s| [s.cu, s.cd, s.r, s.ld].map(|v| v.try_into().expect("BANK inputs")))
        .collect();
    let scans = &scans;
    let pv: i16 = 100;
    macro_rules! per_instance {
        ($name:literal, $new:expr, |$t:ident, $input:ident| $call:expr) => {
            per_instance_scans(
                $name,
                $new,
                #[inline(always)]
                move |counters, k| {
                    let s = &scans[k as usize % scans.len()];
                    for (i, $t) in counters.iter_mut().enumerate() {
                        let $input = CounterInput {
                            cu: s[0][i],
                            cd: s[1][i],
                            r: s[2][i],
                            ld: s[3][i],
                            pv,
                        };
                        black_box($call);
                    }
                },
            )
        };
    }
    let mut ws = vec![
        per_instance!(
            "reference (CounterRef array)",
            CounterRef::<i16>::new(),
            |t, input| t.call(CounterKind::Ctd, input)
        ),
        per_instance!(
            "optimized (Counter array, call)",
            Counter::<i16>::new(),
            |t, input| t.call(CounterKind::Ctd, input)
        ),
        per_instance!(
            "optimized (Counter array, call_for_arrays)",
            Counter::<i16>::new(),
            |t, input| t.call_for_arrays(CounterKind::Ctd, input)
        ),
    ];
    let mut counters = Box::new([Counter::<i16>::new(); BANK]);
    let pvs = Box::new([pv; BANK]);
    let (mut qu, mut qd) = (Box::new([false; BANK]), Box::new([false; BANK]));
    let mut cv = Box::new([0i16; BANK]);
    let mut k = 0usize;
    ws.push(Workload::plain(
        "optimized (Counter array, call_array)",
        1,
        1e-3,
        move || {
            k += 1;
            let s = &scans[k % scans.len()];
            Counter::call_array(
                &mut counters,
                CounterKind::Ctd,
                &bank_inputs(s),
                &pvs,
                &mut ArrayOutputs {
                    qu: &mut qu,
                    qd: &mut qd,
                    cv: &mut cv,
                },
            );
            black_box((&mut counters, &mut qu, &mut qd, &mut cv));
        },
    ));
    run_group(c, &group_name(family, &loop_group("CTD")), ws);
}

/// One scan's CU, CD, R and LD as the bank and `Counter::call_array` take them.
fn bank_inputs(s: &[Box<[bool; BANK]>; 4]) -> BankInputs<'_, BANK> {
    BankInputs {
        cu: &s[0],
        cd: &s[1],
        r: &s[2],
        ld: &s[3],
    }
}

/// The bank of CTUD counters, or with `UP_ONLY` of CTU counters (CD and LD always 0). The
/// kind is a constant at every call (`KIND` below), as at a call site of a PLC program (see
/// `step_iec_kind`): every form's code for the other kinds disappears alike.
fn bulk_counters<const UP_ONLY: bool>(c: &mut Criterion, family: Family) {
    let up_only = UP_ONLY;
    let scans: Vec<[Box<[bool; BANK]>; 4]> = common::family_counter_scans(family, up_only)
        .into_iter()
        .map(|s| [s.cu, s.cd, s.r, s.ld].map(|v| v.try_into().expect("BANK inputs")))
        .collect();
    let scans = &scans;
    let pv: i16 = 100;
    struct Kind<const UP_ONLY: bool>;
    impl<const UP_ONLY: bool> Kind<UP_ONLY> {
        const KIND: CounterKind = if UP_ONLY {
            CounterKind::Ctu
        } else {
            CounterKind::Ctud
        };
    }
    let group = if up_only { CTU_BANK } else { CTUD_BANK };
    macro_rules! per_instance {
        ($name:literal, $new:expr, |$t:ident, $s:ident, $i:ident| $call:expr) => {
            per_instance_scans(
                $name,
                $new,
                #[inline(always)]
                move |counters, k| {
                    let $s = &scans[k as usize % scans.len()];
                    for ($i, $t) in counters.iter_mut().enumerate() {
                        black_box($call);
                    }
                },
            )
        };
    }
    let mut ws = vec![
        per_instance!(
            "reference (CounterRef array)",
            CounterRef::<i16>::new(),
            |t, s, i| {
                t.call(
                    Kind::<UP_ONLY>::KIND,
                    CounterInput {
                        cu: s[0][i],
                        cd: s[1][i],
                        r: s[2][i],
                        ld: s[3][i],
                        pv,
                    },
                )
            }
        ),
        per_instance!(
            "optimized (Counter array, call)",
            Counter::<i16>::new(),
            |t, s, i| {
                t.call(
                    Kind::<UP_ONLY>::KIND,
                    CounterInput {
                        cu: s[0][i],
                        cd: s[1][i],
                        r: s[2][i],
                        ld: s[3][i],
                        pv,
                    },
                )
            }
        ),
        per_instance!(
            "optimized (Counter array, call_for_arrays)",
            Counter::<i16>::new(),
            |t, s, i| {
                t.call_for_arrays(
                    Kind::<UP_ONLY>::KIND,
                    CounterInput {
                        cu: s[0][i],
                        cd: s[1][i],
                        r: s[2][i],
                        ld: s[3][i],
                        pv,
                    },
                )
            }
        ),
    ];
    {
        let mut counters = Box::new([Counter::<i16>::new(); BANK]);
        let pvs = Box::new([pv; BANK]);
        let (mut qu, mut qd) = (Box::new([false; BANK]), Box::new([false; BANK]));
        let mut cv = Box::new([0i16; BANK]);
        let mut k = 0usize;
        ws.push(Workload::plain(
            "optimized (Counter array, call_array)",
            1,
            1e-3,
            move || {
                k += 1;
                let s = &scans[k % scans.len()];
                Counter::call_array(
                    &mut counters,
                    Kind::<UP_ONLY>::KIND,
                    &bank_inputs(s),
                    &pvs,
                    &mut ArrayOutputs {
                        qu: &mut qu,
                        qd: &mut qd,
                        cv: &mut cv,
                    },
                );
                black_box((&mut counters, &mut qu, &mut qd, &mut cv));
            },
        ));
    }
    // The per-instance floor: the loop above with a call that only takes the inputs it reads
    // into the byte after CV of a 4-byte cell (`Counter<i16>`'s size) and passes the cell on, no
    // rule. No form that calls one instance at a time in its own data does less.
    ws.push(per_instance!("per-instance floor", 0u32, |t, s, i| {
        let edges = if UP_ONLY {
            u32::from(s[0][i]) | u32::from(s[2][i]) << 2
        } else {
            u32::from(s[0][i])
                | u32::from(s[1][i]) << 1
                | u32::from(s[2][i]) << 2
                | u32::from(s[3][i]) << 3
        };
        // CV kept, the byte after it replaced: one 4-byte store, no partial write.
        *t = *t & 0xFFFF | edges << 16;
        *t
    }));
    if up_only {
        ws.push(per_instance!(
            "RuSTy (array)",
            rusty::Ctu::<i16>::new(),
            |t, s, i| t.call(s[0][i], s[2][i], pv)
        ));
        ws.push(per_instance!(
            "matiec (array)",
            matiec::Ctu::<i16>::new(),
            |t, s, i| t.call(s[0][i], s[2][i], pv)
        ));
    }
    let mut bank = Box::new(CounterBank::<i16, BANK>::new());
    let mut k = 0usize;
    ws.push(Workload::plain(
        "optimized (CounterBank)",
        1,
        1e-3,
        move || {
            k += 1;
            let s = &scans[k % scans.len()];
            bank.scan(&bank_inputs(s), pv);
            black_box(&mut bank);
        },
    ));
    ws.push(copy_floor(
        "copy of the CounterBank state",
        size_of::<CounterBank<i16, BANK>>(),
    ));
    run_group(c, &group_name(family, group), ws);
}

/// Ticks between two restores of the timer area: few enough that the area stays about as busy
/// as at the start (a tenth of the running 10 ms timers run out).
const TICKS_PER_RESTORE: u64 = 100;

/// A workload that runs `work` once per iteration on a copy of `original`, restored (untimed)
/// every `TICKS_PER_RESTORE` iterations.
fn restoring<'a, T: Clone + 'a>(
    name: &str,
    original: T,
    mut work: impl FnMut(&mut T, u64) + 'a,
) -> Workload<'a> {
    let mut state = original.clone();
    let mut k = 0u64;
    Workload::custom(name, 1e-3, move |iters| {
        let mut total = Duration::ZERO;
        for _ in 0..iters {
            k += 1;
            if k.is_multiple_of(TICKS_PER_RESTORE) {
                state.clone_from(&original);
            }
            let start = Instant::now();
            work(&mut state, k);
            total += start.elapsed();
            black_box(&mut state);
        }
        total
    })
}

fn bulk_area(c: &mut Criterion, family: Family) {
    let contents = common::family_area_contents(family, AREA);
    let states: Vec<S5State> = contents
        .iter()
        .enumerate()
        .map(|(i, c)| match *c {
            None => S5State::RESET,
            Some((value, base)) => {
                let on_delay = matches!(S5Kind::ALL[i % 5], S5Kind::SOdt | S5Kind::SOdts);
                S5State {
                    running: true,
                    value,
                    base: TimeBase::from_bits(base),
                    q: !on_delay,
                    q_on_expiry: on_delay,
                    s_prev: true,
                    fr_prev: false,
                }
            }
        })
        .collect();
    let refs: Vec<S5TimerRef> = states
        .iter()
        .map(|&s| S5TimerRef::from_state(s, CpuTime::ZERO).expect("a valid state"))
        .collect();
    let mut words = Box::new([TimerWord::RESET; AREA]);
    for (w, &s) in words.iter_mut().zip(&states) {
        *w = TimerWord::from_state(s).expect("a valid state");
    }
    let area = Box::new(TimerMemory::<AREA>::from_words(*words, CpuTime::ZERO));
    let ws = vec![
        restoring("reference (S5TimerRef array)", refs, |refs, _| {
            // The OS tick of the 10 ms base: every timer of that base loses one unit.
            for t in refs.iter_mut() {
                if t.state().base == TimeBase::Ms10 {
                    t.tick(1);
                }
            }
        }),
        restoring("optimized (TimerMemory::tick)", area.clone(), |a, _| {
            a.tick(TimeBase::Ms10, 1)
        }),
        restoring("optimized (TimerMemory::advance_to)", area, |a, k| {
            // 10 ms later: the 10 ms tick, and every 10th call the 100 ms tick too.
            a.advance_to(CpuTime::from_millis(10 * (k % TICKS_PER_RESTORE)))
        }),
        copy_floor(
            "copy of the TimerMemory state",
            size_of::<TimerMemory<AREA>>(),
        ),
        copy_floor("copy of 2 bytes per timer", 2 * AREA),
    ];
    run_group(c, &group_name(family, AREA_TICK), ws);
}

// ---------------------------------------------------------------------------------------------
// The summary.

/// The bulk groups, by name (without the family's prefix).
const TON_BANK: &str = "scan of 10 048 TON";
const CTUD_BANK: &str = "bank of 10 048 CTUD INT";
const CTU_BANK: &str = "bank of 10 048 CTU INT";
const AREA_TICK: &str = "timer area of 65 536, one 10 ms tick";

/// The name of `group` run on `family`'s inputs.
fn group_name(family: Family, group: &str) -> String {
    format!("{}: {group}", family.name())
}

fn fmt(v: Option<f64>) -> String {
    v.map_or("-".into(), |v| format!("{v:.2}"))
}

fn verdict(ok: Option<bool>) -> &'static str {
    match ok {
        Some(true) => "met",
        Some(false) => "MISSED",
        None => "-",
    }
}

/// The verdicts of every goal, for the last line of the summary.
#[derive(Default)]
struct Tally {
    met: usize,
    missed: Vec<String>,
    not_run: usize,
}

impl Tally {
    fn record(&mut self, what: &str, ok: Option<bool>) {
        match ok {
            Some(true) => self.met += 1,
            Some(false) => self.missed.push(what.to_owned()),
            None => self.not_run += 1,
        }
    }
}

/// The summary of one family: the one-step table, the bulk table, the goals.
fn summary(family: Family, tally: &mut Tally) {
    let fam = family.name();
    let result = |key: &str| result(&format!("{fam}: {key}"));
    println!();
    println!("== Family `{fam}`: {}", family.description());
    println!();
    println!(
        "One step, ns per step (1 024 steps of the family's stream per iteration, 8 instances):"
    );
    println!();
    println!("| block | reference | optimized | RuSTy port | matiec port | reference / optimized | best peer / optimized | goal: optimized <= reference and <= best peer |");
    println!("|---|---|---|---|---|---|---|---|");
    let blocks: Vec<&str> = IecKind::ALL
        .iter()
        .map(|k| k.name())
        .chain(CounterKind::ALL.iter().map(|k| k.name()))
        .chain(S5Kind::ALL.iter().map(|k| k.name()))
        .chain(S5CounterKind::ALL.iter().map(|k| k.name()))
        .collect();
    for block in &blocks {
        let get = |name: &str| result(&format!("step {block}/{name}"));
        let (r, o, ru, ma) = (
            get("reference"),
            get("optimized"),
            get("RuSTy"),
            get("matiec"),
        );
        let best_peer = match (ru, ma) {
            (Some(a), Some(b)) => Some(a.min(b)),
            (a, b) => a.or(b),
        };
        let ratio = |x: Option<f64>| x.zip(o).map(|(x, o)| x / o);
        let ok = o.map(|o| r.is_none_or(|r| o <= r) && best_peer.is_none_or(|p| o <= p));
        tally.record(&format!("{fam}: step {block}"), ok);
        println!(
            "| {block} | {} | {} | {} | {} | {}x | {} | {} |",
            fmt(r),
            fmt(o),
            fmt(ru),
            fmt(ma),
            fmt(ratio(r)),
            ratio(best_peer).map_or("-".into(), |v| format!("{v:.2}x")),
            verdict(ok),
        );
    }
    println!();
    println!(
        "Each figure above is the mean of the loop's {PLACEMENTS} placements (`PLACEMENTS`); \
         the fastest and the slowest placement, ns:"
    );
    println!();
    let spreads = SPREADS.lock().expect("no panic while holding the lock");
    for block in &blocks {
        let forms: Vec<String> = ["reference", "optimized", "RuSTy", "matiec"]
            .iter()
            .filter_map(|name| {
                let (lo, hi) = spreads.get(&format!("{fam}: step {block}/{name}"))?;
                Some(format!("{name} {lo:.2}-{hi:.2}"))
            })
            .collect();
        if !forms.is_empty() {
            println!("- {block}: {}", forms.join(", "));
        }
    }
    drop(spreads);
    println!();
    for (block, form) in [
        ("TON", "ton_for_arrays"),
        ("CTU", "call_for_arrays"),
        ("CTD", "call_for_arrays"),
        ("CTUD", "call_for_arrays"),
    ] {
        if let Some(v) = result(&format!("step {block}/optimized, {form}")) {
            println!("{block} on the same stream through `{form}` (the array form; not a goal for one step): {v:.2} ns");
        }
    }
    println!();
    println!("Bulk, µs per scan:");
    println!();
    println!("| workload | form | µs per scan | vs the floor | reference / this |");
    println!("|---|---|---|---|---|");
    let bulk: [(&str, &str, &str, &[&str]); 4] = [
        (
            TON_BANK,
            "reference (IecTimerRef array)",
            "copy of the TonBank state",
            &[
                "optimized (TonBank)",
                "optimized (IecTimer array, call)",
                "optimized (IecTimer array, ton_for_arrays)",
                "optimized (IecTimer array, ton_array)",
                "RuSTy (array)",
                "matiec (array)",
                "copy of the IecTimer array",
                "per-instance floor",
            ],
        ),
        (
            CTUD_BANK,
            "reference (CounterRef array)",
            "copy of the CounterBank state",
            &[
                "optimized (CounterBank)",
                "optimized (Counter array, call)",
                "optimized (Counter array, call_for_arrays)",
                "optimized (Counter array, call_array)",
                "per-instance floor",
            ],
        ),
        (
            CTU_BANK,
            "reference (CounterRef array)",
            "copy of the CounterBank state",
            &[
                "optimized (CounterBank)",
                "optimized (Counter array, call)",
                "optimized (Counter array, call_for_arrays)",
                "optimized (Counter array, call_array)",
                "RuSTy (array)",
                "matiec (array)",
                "per-instance floor",
            ],
        ),
        (
            AREA_TICK,
            "reference (S5TimerRef array)",
            "copy of 2 bytes per timer",
            &[
                "optimized (TimerMemory::tick)",
                "optimized (TimerMemory::advance_to)",
                "copy of the TimerMemory state",
            ],
        ),
    ];
    for (group, reference, floor, forms) in bulk {
        let get = |name: &str| result(&format!("{group}/{name}"));
        let (r, f) = (get(reference), get(floor));
        println!(
            "| {group} | {reference} | {} | {} | 1.00x |",
            fmt(r),
            ratio_x(r, f)
        );
        for form in forms {
            let v = get(form);
            if v.is_none() {
                continue;
            }
            println!(
                "| {group} | {form} | {} | {} | {} |",
                fmt(v),
                ratio_x(v, f),
                ratio_x(r, v)
            );
        }
        println!("| {group} | {floor} (the floor) | {} | 1.00x | |", fmt(f));
    }
    println!();
    println!(
        "Each per-instance form above (a loop calling one instance at a time, compiled into the \
         benchmark) is the mean of the loop's {PLACEMENTS} placements; the fastest and the \
         slowest placement, µs:"
    );
    println!();
    for (group, reference, _, forms) in bulk {
        let forms = std::iter::once(reference).chain(forms.iter().copied());
        let forms = forms.map(|name| (name, name));
        print_spreads(&format!("{fam}: {group}/"), group, forms);
    }
    println!();
    println!(
        "Per-instance loops (issue 41), µs per scan: a plain `for` over 10 048 instances \
         calling `call`, as a runtime compiles `FOR i := ... DO block[i](...)`:"
    );
    println!();
    println!("| block | reference loop | optimized `call` loop | reference / optimized | array form | reference / array form | goal: `call` loop <= reference loop |");
    println!("|---|---|---|---|---|---|---|");
    for (block, group, reference, array) in per_instance_loops() {
        let get = |name: &str| result(&format!("{group}/{name}"));
        let (r, o) = (
            get(reference),
            get(LOOP_CALL[usize::from(reference == COUNTER_REF)]),
        );
        let a = array.and_then(get);
        let ok = r.zip(o).map(|(r, o)| o <= r);
        tally.record(&format!("{fam}: {block} loop, call"), ok);
        println!(
            "| {block} | {} | {} | {} | {} | {} | {} |",
            fmt(r),
            fmt(o),
            ratio_x(r, o),
            array.map_or("-".into(), |name| format!("{name}: {}", fmt(a))),
            ratio_x(r, a),
            verdict(ok),
        );
    }
    println!();
    println!(
        "Each figure above is the mean of the loop's {PLACEMENTS} placements (`PLACEMENTS`); \
         the fastest and the slowest placement, µs:"
    );
    println!();
    for (block, group, reference, _) in per_instance_loops() {
        let call = LOOP_CALL[usize::from(reference == COUNTER_REF)];
        let forms = [(reference, "reference"), (call, "call")];
        print_spreads(&format!("{fam}: {group}/"), block, forms);
    }
    println!();
    println!("Goals of issue 29, family `{fam}` (the single steps: the table above):");
    let ratio = |a: &str, b: &str| result(a).zip(result(b)).map(|(a, b)| a / b);
    let mut goal = |what: &str, value: Option<f64>, ok: fn(f64) -> bool| {
        let ok = value.map(ok);
        tally.record(&format!("{fam}: {what}"), ok);
        println!(
            "- {what}: {} {}",
            value.map_or("-".into(), |v| format!("{v:.2}x")),
            verdict(ok)
        );
    };
    // The array goals, met by the array forms (`ton_array`, `call_array`: one call for the
    // whole array, each instance in its own structure). A form called one instance at a time
    // cannot meet them (see benches/README.md): its bound and its figure follow, as notes.
    goal(
        "IecTimerRef array / IecTimer array (ton_array), 10 048 TON (>= 2x)",
        ratio(
            &format!("{TON_BANK}/reference (IecTimerRef array)"),
            &format!("{TON_BANK}/optimized (IecTimer array, ton_array)"),
        ),
        |v| v >= 2.0,
    );
    let ctd_loop = loop_group("CTD");
    for bank in [CTUD_BANK, CTU_BANK, ctd_loop.as_str()] {
        goal(
            &format!("CounterRef array / Counter array (call_array), {bank} (>= 2x)"),
            ratio(
                &format!("{bank}/reference (CounterRef array)"),
                &format!("{bank}/optimized (Counter array, call_array)"),
            ),
            |v| v >= 2.0,
        );
    }
    // What a per-instance form can reach at most: the reference against the loop that only
    // moves each instance's inputs, state and outputs (not a goal; it says how far off one is),
    // and what the per-instance array forms reach.
    for (group, reference, per_instance) in [
        (
            TON_BANK,
            "reference (IecTimerRef array)",
            "optimized (IecTimer array, ton_for_arrays)",
        ),
        (
            CTUD_BANK,
            "reference (CounterRef array)",
            "optimized (Counter array, call_for_arrays)",
        ),
        (
            CTU_BANK,
            "reference (CounterRef array)",
            "optimized (Counter array, call_for_arrays)",
        ),
    ] {
        let reference_over =
            |form: &str| ratio(&format!("{group}/{reference}"), &format!("{group}/{form}"));
        if let (Some(bound), Some(v)) = (
            reference_over("per-instance floor"),
            reference_over(per_instance),
        ) {
            println!(
                "  (not a goal, {group}: one instance per call: {reference} / {per_instance} {v:.2}x; bound {reference} / per-instance floor {bound:.2}x)"
            );
        }
    }
    goal(
        "TonBank scan / copy of its state (<= 2.5x)",
        ratio(
            &format!("{TON_BANK}/optimized (TonBank)"),
            &format!("{TON_BANK}/copy of the TonBank state"),
        ),
        |v| v <= 2.5,
    );
    for bank in [CTUD_BANK, CTU_BANK] {
        goal(
            &format!("CounterBank scan / copy of its state, {bank} (<= 3x)"),
            ratio(
                &format!("{bank}/optimized (CounterBank)"),
                &format!("{bank}/copy of the CounterBank state"),
            ),
            |v| v <= 3.0,
        );
    }
    goal(
        "TimerMemory::tick of 65 536 / copy of 2 bytes per timer (<= 3x)",
        ratio(
            &format!("{AREA_TICK}/optimized (TimerMemory::tick)"),
            &format!("{AREA_TICK}/copy of 2 bytes per timer"),
        ),
        |v| v <= 3.0,
    );
}

/// The reference's array workloads, by family of block.
const TIMER_REF: &str = "reference (IecTimerRef array)";
const COUNTER_REF: &str = "reference (CounterRef array)";
/// The optimized `call` loops: timers, counters.
const LOOP_CALL: [&str; 2] = [
    "optimized (IecTimer array, call)",
    "optimized (Counter array, call)",
];

/// Every per-instance loop of the summary: (block, group, the reference's workload, the array
/// form's workload if the block has one).
fn per_instance_loops() -> Vec<(&'static str, String, &'static str, Option<&'static str>)> {
    let call_array = Some("optimized (Counter array, call_array)");
    vec![
        ("TP", loop_group("TP"), TIMER_REF, None),
        (
            "TON",
            TON_BANK.to_owned(),
            TIMER_REF,
            Some("optimized (IecTimer array, ton_array)"),
        ),
        ("TOF", loop_group("TOF"), TIMER_REF, None),
        ("TONR", loop_group("TONR"), TIMER_REF, None),
        ("CTU", CTU_BANK.to_owned(), COUNTER_REF, call_array),
        ("CTD", loop_group("CTD"), COUNTER_REF, call_array),
        ("CTUD", CTUD_BANK.to_owned(), COUNTER_REF, call_array),
    ]
}

/// One line `- {label}: {form} {fastest}-{slowest}, ...`: the placements of each workload
/// `prefix` + `name` of `forms` (`(name, form)`) that was timed at several; nothing if none was.
fn print_spreads<'n>(
    prefix: &str,
    label: &str,
    forms: impl IntoIterator<Item = (&'n str, &'n str)>,
) {
    let spreads = SPREADS.lock().expect("no panic while holding the lock");
    let forms: Vec<String> = (forms.into_iter())
        .filter_map(|(name, form)| {
            let (lo, hi) = spreads.get(&format!("{prefix}{name}"))?;
            Some(format!("{form} {lo:.2}-{hi:.2}"))
        })
        .collect();
    if !forms.is_empty() {
        println!("- {label}: {}", forms.join(", "));
    }
}

fn ratio_x(a: Option<f64>, b: Option<f64>) -> String {
    a.zip(b)
        .map_or("-".into(), |(a, b)| format!("{:.2}x", a / b))
}

/// What the build targets: the vector extensions the compiler may use without a run-time
/// test, and those this machine has.
fn target_line() -> String {
    let compiled: Vec<&str> = [
        ("sse2", cfg!(target_feature = "sse2")),
        ("sse4.1", cfg!(target_feature = "sse4.1")),
        ("avx2", cfg!(target_feature = "avx2")),
        ("avx512f", cfg!(target_feature = "avx512f")),
    ]
    .into_iter()
    .filter_map(|(name, on)| on.then_some(name))
    .collect();
    #[cfg(target_arch = "x86_64")]
    let detected = format!(
        "; this CPU has avx2: {}, avx512f: {}",
        std::arch::is_x86_feature_detected!("avx2"),
        std::arch::is_x86_feature_detected!("avx512f")
    );
    #[cfg(not(target_arch = "x86_64"))]
    let detected = String::new();
    format!(
        "compiled for {} with {}{detected}; plc-timers feature `simd-dispatch` {}",
        std::env::consts::ARCH,
        if compiled.is_empty() {
            "no vector extension".to_owned()
        } else {
            compiled.join(", ")
        },
        if cfg!(feature = "simd-dispatch") {
            "on (the bank scans, the array forms and the area tick run compiled for the widest of AVX-512BW and AVX2 this CPU has)"
        } else {
            "off (every loop runs as compiled for the target)"
        },
    )
}

fn main() {
    let mut c = Criterion::default()
        .warm_up_time(Duration::from_millis(500))
        .measurement_time(Duration::from_secs(2))
        .sample_size(30)
        .configure_from_args();
    for family in Family::ALL {
        let stream = Stream::new(&common::family_step_stream(family, 1));
        step_iec(&mut c, &stream, family);
        step_counters(&mut c, &stream, family);
        step_s5(&mut c, &stream, family);
        bulk_ton(&mut c, family);
        bulk_counters::<false>(&mut c, family);
        bulk_counters::<true>(&mut c, family);
        loop_iec::<0>(&mut c, family);
        loop_iec::<2>(&mut c, family);
        loop_iec::<3>(&mut c, family);
        loop_ctd(&mut c, family);
        bulk_area(&mut c, family);
    }
    c.final_summary();
    println!();
    println!("== Summary (per workload, the fastest of {ROUNDS} rounds in which the forms of a group run in turn)");
    println!("Build: {}", target_line());
    let mut tally = Tally::default();
    for family in Family::ALL {
        summary(family, &mut tally);
    }
    println!();
    if tally.missed.is_empty() && tally.not_run == 0 {
        println!(
            "All {} goals met, on both input families, in this run.",
            tally.met
        );
    } else {
        println!(
            "{} goals met, {} missed, {} not run (filtered out): {}",
            tally.met,
            tally.missed.len(),
            tally.not_run,
            tally.missed.join("; ")
        );
    }
}
