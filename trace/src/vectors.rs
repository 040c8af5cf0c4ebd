//! Test vectors for other implementations: for every block of the catalog (IEC counters: for
//! every integer type), self-contained CSV traces (the preset is a column) with the reference
//! outputs, so that `plc-timers check BLOCK FILE` replays them.
//!
//! Per block: the shipped example (`example.csv`), [`TRACES_PER_BLOCK`] random traces
//! (`random-NN.csv`: edges clustered, presets at edge values, time steps around ticks and
//! presets, IEC timers across the 2^32 ms clock wrap), and traces aimed at the rules ports
//! most often break:
//! - `preset-change.csv` (every block): TV/PT/PV change mid-run; the IEC timers latch PT while
//!   running (IEC-PT-LATCH-01), where every peer runtime re-reads it.
//! - `long-gaps.csv` (IEC timers): gaps between calls up to and past 2^31 ms and 2^32 ms
//!   (IEC-WRAP-01).
//! - `limits.csv` (counters): counting into the type's limits (CNT-SAT-01, SC-SAT-01); CTU
//!   has no load, so it reaches the top of the 8-bit types by counting.
//! - `simultaneous.csv` (every block): every combination of the boolean inputs rising
//!   together, from several states (counters: CV 0, at the type's limits and at PV; S5
//!   counters: CV 0, 5 and 999).
//! - `fr.csv` (blocks with FR): FR edges with S (or CU, CD) high and low, running and stopped.
//! - `decisions.csv` (every timer, the IEC counters): one block of rows per decision of `spec/`
//!   that departs from, or chooses between readings of, a manual's wording, or where a peer
//!   runtime differs (`spec/s5.md` "Departures weighed", `spec/iec.md`, `spec/counter.md`).
//!   The IEC timers' file has the optional `RT` column (the `-(RT)-` coil, IEC-RT-01); no
//!   other file sets a coil, so theirs have the box's columns only.
//!
//! The S7-1500 long IEC timers (`TON-LTIME`, …; `--type LTIME`, time column `t_ns`) have their
//! own files: random traces with presets from 1 ns to past TIME's range (`LT#30D`), gaps of up
//! to 30 days; `long-gaps.csv` with gaps past 2^62 and 2^63 ns under presets of `LT#30D` and
//! LTIME's largest value (LTIMER-CLOCK-01); and the TIME files' `preset-change.csv`,
//! `simultaneous.csv` and `decisions.csv` read in nanoseconds (`T#20MS` as `LT#20NS`, the
//! times unchanged), which LTIMER-SAME-01 says behave alike.

use plc_timers::block::{BlockOps, Visit};
use plc_timers::catalog::Port::{self, Cd, Cu, Fr, In, Ld, Rt, R, S};
use plc_timers::catalog::{Block, DataType, Family, PresetKind, ValueKind};
use plc_timers::time::Time;

use super::engine::run;
use super::error::TraceError;
use super::examples;
use super::family::{parse_preset, BlockSpec, Signals};

/// Random traces per block (besides the example and the aimed traces).
pub const TRACES_PER_BLOCK: usize = 20;
/// Rows per random trace.
pub const ROWS: usize = 40;
/// The seed of the random traces.
const SEED: u64 = 0x5EED_0000;

/// One vector file.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Vector {
    /// The directory: the block's name, with the integer type for IEC counters (`CTUD-SINT`)
    /// and the data type for the IEC timers on LTIME (`TON-LTIME`).
    pub dir: String,
    /// The file name.
    pub file: String,
    /// The block (and `--type`) for `plc-timers check`.
    pub spec: BlockSpec,
    /// The CSV text: inputs, preset column, reference outputs.
    pub csv: String,
}

impl Vector {
    /// The `plc-timers check` command that replays it, from the vectors' directory.
    pub fn check_command(&self) -> String {
        let block = self.spec.block();
        let ty = if block.family() == Family::IecCounter
            || self.spec.data_type() != block.default_data_type()
        {
            format!(" --type {}", self.spec.data_type())
        } else {
            String::new()
        };
        format!("plc-timers check {block}{ty} {}/{}", self.dir, self.file)
    }
}

/// A trace under construction: rows of (t, the inputs at 1, preset text).
struct Trace {
    block: Block,
    /// `t_ms`, or `t_ns` on LTIME.
    time_column: &'static str,
    rows: Vec<(u64, Signals, String)>,
}

impl Trace {
    fn new(spec: BlockSpec) -> Trace {
        Trace {
            block: spec.block(),
            time_column: spec.time_column(),
            rows: Vec::new(),
        }
    }

    /// The same trace on LTIME: every TIME preset read as as many nanoseconds as it has
    /// milliseconds (`T#20MS` as `LT#20NS`), the times unchanged (LTIMER-SAME-01).
    fn in_nanoseconds(mut self) -> Trace {
        for (_, _, preset) in &mut self.rows {
            if let Ok(t) = preset.parse::<Time>() {
                *preset = format!("LT#{}NS", t.as_millis());
            }
        }
        self
    }

    /// Adds a row with the inputs and coils `on` at 1 (those the block has; the others are not
    /// columns).
    fn row(&mut self, t: u64, on: &[Port], preset: &str) {
        self.rows.push((t, Signals::of(on), preset.to_string()));
    }

    /// The CSV text: the time column (timers), the inputs, then a column for each coil (`RT`) that
    /// some row sets: a trace that uses no coil has the box's columns only.
    fn text(&self) -> String {
        let timed = self.block.requires_time();
        let coils: Vec<Port> = self
            .block
            .coils()
            .iter()
            .copied()
            .filter(|&c| self.rows.iter().any(|(_, on, _)| on.get(c)))
            .collect();
        let mut names: Vec<&str> = Vec::new();
        if timed {
            names.push(self.time_column);
        }
        names.extend(self.block.inputs().iter().chain(&coils).map(|p| p.name()));
        let mut text = names.join(",");
        text.push('\n');
        for (t, on, preset) in &self.rows {
            let mut fields: Vec<String> = Vec::new();
            if timed {
                fields.push(t.to_string());
            }
            for &port in self.block.inputs().iter().chain(&coils) {
                fields.push(match port.kind() {
                    ValueKind::Bool => u8::from(on.get(port)).to_string(),
                    _ => preset.clone(),
                });
            }
            text.push_str(&fields.join(","));
            text.push('\n');
        }
        text
    }
}

/// The smallest and the largest preset `spec`'s block takes: the range its preset parser
/// accepts (an IEC counter's PV: its integer type's), found by bisection so that the one list
/// of the types and their ranges stays the core's.
fn limits_of(spec: BlockSpec) -> (i128, i128) {
    struct Limits;
    impl Visit for Limits {
        type Out = (i128, i128);
        fn visit<B: BlockOps>(self, _: B, _: B::Kind) -> (i128, i128) {
            let ok = |v: i128| parse_preset::<B>(&v.to_string()).is_ok();
            // The last value for which `ok` holds, from `inside` (where it holds) towards
            // `outside` (where it does not).
            let edge = |mut inside: i128, mut outside: i128| {
                while inside.abs_diff(outside) > 1 {
                    let mid = inside + (outside - inside) / 2;
                    if ok(mid) {
                        inside = mid;
                    } else {
                        outside = mid;
                    }
                }
                inside
            };
            (edge(0, -(1 << 100)), edge(0, 1 << 100))
        }
    }
    spec.visit(Limits)
}

/// Presets at edge values, and the time steps around ticks and presets, per preset kind.
fn presets_and_steps(kind: PresetKind, spec: BlockSpec) -> (Vec<String>, Vec<u64>) {
    let s = |v: &[&str]| v.iter().map(|x| x.to_string()).collect::<Vec<_>>();
    match kind {
        PresetKind::Time if spec.data_type() == DataType::LTime => (
            s(&[
                "LT#0NS",
                "-5",
                "LT#1NS",
                "LT#30NS",
                "LT#1MS_500US",
                "LT#30D",
            ]),
            vec![
                0,
                1,
                29,
                30,
                31,
                100,
                1_500_000,
                THIRTY_DAYS_NS - 1,
                THIRTY_DAYS_NS,
            ],
        ),
        PresetKind::S5Time => (
            s(&[
                "S5T#0MS",
                "W#16#0001",
                "W#16#0003",
                "W#16#1002",
                "W#16#2001",
                "S5T#50MS",
            ]),
            vec![0, 1, 9, 10, 11, 20, 30, 100, 1_000, 2_000],
        ),
        PresetKind::Time => (
            s(&["T#0MS", "-5", "T#1MS", "T#30MS", "T#100MS"]),
            vec![0, 1, 29, 30, 31, 50, 100, 5_000],
        ),
        PresetKind::S5Count => (
            s(&["C#0", "C#1", "C#3", "C#998", "C#999", "W#16#0500"]),
            vec![1],
        ),
        PresetKind::Integer => {
            let (min, max) = limits_of(spec);
            let pvs = [0, 1, 3, -1, min, max, max - 1, min + 1]
                .into_iter()
                .filter(|v| (min..=max).contains(v))
                .map(|v| v.to_string())
                .collect();
            (pvs, vec![1])
        }
    }
}

/// 30 days in nanoseconds: `LT#30D`, past TIME's range.
const THIRTY_DAYS_NS: u64 = 30 * 86_400 * 1_000_000_000;

/// The first time of a generated trace: IEC timers on TIME start 50 ms before the 32-bit clock
/// wraps (on LTIME the trace's time is the clock, whose wrap at 2^64 ns no trace reaches).
fn start_time(kind: PresetKind, spec: BlockSpec) -> u64 {
    if kind == PresetKind::Time && spec.data_type() != DataType::LTime {
        (1 << 32) - 50
    } else {
        0
    }
}

fn random(spec: BlockSpec, kind: PresetKind, rng: &mut fastrand::Rng) -> Trace {
    let block = spec.block();
    let (presets, steps) = presets_and_steps(kind, spec);
    let preset = presets[rng.usize(..presets.len())].clone();
    let mut trace = Trace::new(spec);
    let mut t = start_time(kind, spec);
    let mut bits = 0u64;
    for _ in 0..ROWS {
        t += steps[rng.usize(..steps.len())];
        bits ^= rng.u64(..) & rng.u64(..);
        let mut on: Vec<Port> = Vec::new();
        for (i, &port) in block.inputs().iter().enumerate() {
            // Resets, loads and enables are rarer than the counting and start signals.
            let rare = matches!(port, R | Ld | Fr);
            if port.kind() == ValueKind::Bool && bits >> i & 1 == 1 && (!rare || rng.u32(..3) == 0)
            {
                on.push(port);
            }
        }
        trace.row(t, &on, &preset);
    }
    trace
}

/// The presets a trace changes between: [p0, p1, p2, p3].
fn changing_presets(kind: PresetKind) -> [&'static str; 4] {
    match kind {
        PresetKind::S5Time => ["S5T#100MS", "S5T#50MS", "S5T#20MS", "S5T#200MS"],
        PresetKind::Time => ["T#100MS", "T#50MS", "T#20MS", "T#200MS"],
        PresetKind::S5Count => ["C#5", "C#2", "C#10", "C#1"],
        PresetKind::Integer => ["5", "2", "10", "1"],
    }
}

fn preset_change(spec: BlockSpec, kind: PresetKind) -> Trace {
    let block = spec.block();
    let p = changing_presets(kind);
    let mut trace = Trace::new(spec);
    if block.requires_time() {
        // The start input: S or IN; TONR's R resets at the end.
        let start = if block.has_input(S) { S } else { In };
        let t0 = start_time(kind, spec);
        let pattern: &[(u64, bool, usize)] = &[
            (0, false, 0),
            (10, true, 0),
            (30, true, 1),
            (60, true, 2),
            (80, true, 3),
            (109, true, 3),
            (110, true, 3),
            (120, true, 0),
            (130, false, 0),
            (140, false, 1),
            (160, false, 2),
            (200, false, 2),
            (250, false, 3),
            (300, true, 3),
            (310, false, 3),
            (320, false, 2),
            (400, false, 2),
            (500, true, 1),
            (520, true, 3),
            (560, true, 3),
            (600, false, 0),
            (700, false, 0),
        ];
        let started = [start];
        for &(dt, on, k) in pattern {
            trace.row(t0 + dt, if on { &started[..] } else { &[] }, p[k]);
        }
        trace.row(t0 + 800, &[R], p[0]);
    } else {
        let pattern: &[(&[Port], usize)] = &[
            (&[Ld, S], 0),
            (&[], 0),
            (&[Cu], 0),
            (&[], 0),
            (&[Cu], 0),
            (&[], 1),
            (&[Cd], 1),
            (&[], 2),
            (&[Cu], 2),
            (&[], 2),
            (&[Ld, S], 2),
            (&[], 3),
            (&[Cd], 3),
            (&[], 3),
            (&[Cu], 0),
            (&[R], 0),
            (&[], 1),
        ];
        for (t, &(on, k)) in pattern.iter().enumerate() {
            trace.row(t as u64, on, p[k]);
        }
    }
    trace
}

/// Gaps past 2^62 and 2^63 ns on LTIME (LTIMER-CLOCK-01): each gap once, as the trace's time
/// cannot pass 2^64 ns.
fn long_gaps_ltime(spec: BlockSpec) -> Trace {
    let mut trace = Trace::new(spec);
    let mut t = 1_000u64;
    let max = "LT#106751D_23H_47M_16S_854MS_775US_807NS";
    for (pt, gap) in [
        ("LT#30D", THIRTY_DAYS_NS - 1),
        ("LT#30D", THIRTY_DAYS_NS),
        ("LT#30D", THIRTY_DAYS_NS + 1),
        ("LT#30D", 1 << 61),
        (max, (1 << 62) + 1),
        (max, (1 << 63) + 1),
    ] {
        trace.row(t, &[], pt);
        trace.row(t + 1, &[In], pt);
        trace.row(t + 1 + gap, &[In], pt);
        trace.row(t + 2 + gap, &[], pt);
        trace.row(t + 3 + gap, &[R], pt);
        t += 5 + gap;
    }
    trace
}

fn long_gaps(spec: BlockSpec) -> Trace {
    let mut trace = Trace::new(spec);
    let mut t = 1_000u64;
    for pt in ["T#10S", "T#24D_20H_31M_23S_647MS"] {
        for gap in [
            (1u64 << 31) - 1,
            1 << 31,
            (1 << 31) + 1,
            (1 << 32) - 1,
            1 << 32,
            (1 << 32) + 1,
            (1 << 32) + (1 << 31),
        ] {
            trace.row(t, &[], pt);
            trace.row(t + 1, &[In], pt);
            trace.row(t + 1 + gap, &[In], pt);
            trace.row(t + 2 + gap, &[], pt);
            trace.row(t + 2 + 2 * gap, &[], pt);
            trace.row(t + 3 + 2 * gap, &[R], pt);
            t += 5 + 2 * gap;
        }
    }
    trace
}

/// Rows that bring a counter to a known CV: (inputs, preset) pairs, each followed by a row
/// with every input 0.
fn setups(spec: BlockSpec) -> Vec<(Vec<Port>, String)> {
    let block = spec.block();
    match block.family() {
        Family::IecCounter => {
            let (min, max) = limits_of(spec);
            let mut v = Vec::new();
            if block.has_input(R) {
                v.push((vec![R], "3".to_string()));
            }
            if block.has_input(Ld) {
                for cv in [max, min, 0, 3] {
                    v.push((vec![Ld], cv.to_string()));
                }
            }
            v
        }
        Family::S5Counter => vec![
            (vec![R], "C#5".to_string()),
            (vec![S], "C#999".to_string()),
            (vec![S], "C#5".to_string()),
        ],
        _ => vec![(vec![], String::new())],
    }
}

fn simultaneous(spec: BlockSpec, kind: PresetKind) -> Trace {
    let block = spec.block();
    let bools: Vec<Port> = block
        .inputs()
        .iter()
        .copied()
        .filter(|p| p.kind() == ValueKind::Bool)
        .collect();
    let timer_preset = changing_presets(kind)[2];
    let mut trace = Trace::new(spec);
    let mut t = start_time(kind, spec);
    for (setup, preset) in setups(spec) {
        let preset = if preset.is_empty() {
            timer_preset.to_string()
        } else {
            preset
        };
        for combo in 0u32..1 << bools.len() {
            let on: Vec<Port> = (0..bools.len())
                .filter(|i| combo >> i & 1 == 1)
                .map(|i| bools[i])
                .collect();
            trace.row(t, &setup, &preset);
            trace.row(t + 1, &[], &preset);
            trace.row(t + 2, &on, &preset);
            trace.row(t + 3, &on, &preset);
            trace.row(t + 13, &[], &preset);
            t += 30;
        }
    }
    trace
}

fn limits(spec: BlockSpec) -> Trace {
    let block = spec.block();
    let mut trace = Trace::new(spec);
    // Counters only: their traces have no time column, so every row's time is 0.
    let mut row = |on: &[Port], preset: &str| trace.row(0, on, preset);
    match block.family() {
        Family::S5Counter => {
            for (set, count) in [("C#999", Cu), ("C#998", Cu), ("C#1", Cd), ("C#0", Cd)] {
                row(&[S], set);
                row(&[], set);
                for _ in 0..3 {
                    row(&[count], set);
                    row(&[], set);
                }
            }
        }
        _ => {
            let (min, max) = limits_of(spec);
            for (load, count) in [(max - 1, Cu), (max, Cu), (min + 1, Cd), (min, Cd)] {
                let pv = load.to_string();
                row(&[Ld], &pv);
                row(&[], &pv);
                for _ in 0..3 {
                    row(&[count], &pv);
                    row(&[], &pv);
                }
                row(&[Cu, Cd], &pv);
                row(&[], &pv);
            }
            // Without a load input, the top is reached by counting (8-bit types only).
            if !block.has_input(Ld) && max <= 255 {
                let pv = max.to_string();
                row(&[R], &pv);
                row(&[], &pv);
                for _ in 0..=max + 2 {
                    row(&[Cu], &pv);
                    row(&[], &pv);
                }
            }
        }
    }
    trace
}

fn fr(spec: BlockSpec, kind: PresetKind) -> Trace {
    let block = spec.block();
    let mut trace = Trace::new(spec);
    let preset = changing_presets(kind)[1];
    if block.requires_time() {
        let pattern: &[(u64, &[Port])] = &[
            (0, &[]),
            (10, &[S]),
            (20, &[S, Fr]),
            (30, &[S, Fr]),
            (40, &[S]),
            (50, &[S, Fr]),
            (100, &[S]),
            (150, &[S]),
            (160, &[S, Fr]),
            (170, &[Fr]),
            (180, &[]),
            (190, &[Fr]),
            (200, &[S, Fr]),
            (210, &[Fr]),
            (230, &[]),
            (240, &[Fr]),
            (300, &[]),
            (310, &[S]),
            (320, &[S, R, Fr]),
            (330, &[S]),
            (340, &[S, Fr]),
            (400, &[]),
            (410, &[Fr]),
            (420, &[]),
        ];
        for &(t, on) in pattern {
            trace.row(t, on, preset);
        }
    } else {
        for input in [Cu, Cd, S] {
            if !block.has_input(input) {
                continue;
            }
            let pattern: &[&[Port]] = &[
                &[input],
                &[input, Fr],
                &[input, Fr],
                &[input],
                &[input, Fr],
                &[Fr],
                &[],
                &[Fr],
                &[input, Fr],
                &[input, R, Fr],
                &[input],
                &[input, Fr],
                &[],
            ];
            for on in pattern {
                trace.row(0, on, preset);
            }
        }
    }
    trace
}

/// The rows that pin the weighed decisions of `spec/` (see the module documentation); `None`
/// for the S5 counters, whose decisions the other aimed traces already pin.
fn decisions(spec: BlockSpec) -> Option<Trace> {
    let block = spec.block();
    let mut trace = Trace::new(spec);
    // (t_ms, inputs at 1, preset)
    let mut rows = |rows: &[(u64, &[Port], &str)]| {
        for &(t, on, preset) in rows {
            trace.row(t, on, preset);
        }
    };
    const TV: &str = "S5T#100MS"; // 10 units of the 10 ms base
    match block {
        Block::SPulse => rows(&[
            // S5TMR-R-01 (s5.md D3): R on a timer stopped by S clears the kept value: BI 6 -> 0.
            (0, &[], TV),
            (10, &[S], TV),
            (50, &[], TV),
            (60, &[], TV),
            (70, &[R], TV),
            (80, &[], TV),
            // S5TMR-LOAD-01: after R both loads are 0, the base too (awlsim's LC keeps
            // W#16#2000 here).
            (100, &[S], "W#16#2002"),
            (1100, &[S], "W#16#2002"),
            (1200, &[S, R], "W#16#2002"),
            (1300, &[], "W#16#2002"),
            // S5TMR-LOAD-01: BCD is the BCD of BI on the 10 s base (15.119 s left in awlsim's
            // clock, where its L gives 2 and its LC W#16#3001).
            (1400, &[S], "W#16#3002"),
            (6281, &[S], "W#16#3002"),
            (6290, &[R], "W#16#3002"),
            // S5T-RES-01 (decisions.md R16): S5T#5MS is cut to S5T#0MS: the pulse shows Q = 1
            // in its starting execution (6310) and is run out at the next (6311).
            (6300, &[], "S5T#5MS"),
            (6310, &[S], "S5T#5MS"),
            (6311, &[S], "S5T#5MS"),
        ]),
        Block::SPext => rows(&[
            // S5TMR-R-01 (s5.md D3): a run-out S_PEXT keeps its base in BCD until R clears it.
            (0, &[], "W#16#2002"),
            (10, &[S], "W#16#2002"),
            (20, &[], "W#16#2002"),
            (3000, &[], "W#16#2002"),
            (3010, &[R], "W#16#2002"),
            (3020, &[], "W#16#2002"),
            // S5TMR-TV-01 (decisions.md R14): TV changed while the timer runs changes nothing:
            // started at 3100 with 10 units, BI 7 at 3130 and 4 at 3160 whatever TV says; run
            // out at 3200; the next start (3300) loads the TV of its row, 50 units.
            (3100, &[S], "S5T#100MS"),
            (3130, &[], "S5T#500MS"),
            (3160, &[], "S5T#0MS"),
            (3200, &[], "S5T#0MS"),
            (3300, &[S], "S5T#500MS"),
            (3310, &[R], "S5T#500MS"),
        ]),
        Block::SOdt => rows(&[
            // SD-Q-01: restarted by FR with S held after expiry, Q = 0 while the new time runs
            // (awlsim keeps Q = 1).
            (0, &[], TV),
            (10, &[S], TV),
            (200, &[S], TV),
            (210, &[S, Fr], TV),
            (260, &[S], TV),
            (400, &[S], TV),
        ]),
        Block::SOdts => rows(&[
            // SS-Q-01: run out with no execution in between, restarted by a rising S: Q stays
            // 1 (awlsim shows Q = 0 until the new time runs out).
            (0, &[], TV),
            (10, &[S], TV),
            (20, &[], TV),
            (500, &[S], TV),
            (550, &[S], TV),
            (700, &[S], TV),
            // The same through FR with S held.
            (710, &[S, R], TV),
            (720, &[], TV),
            (730, &[S], TV),
            (1000, &[S, Fr], TV),
            (1050, &[S], TV),
            (1060, &[R], TV),
        ]),
        Block::SOffdt => rows(&[
            // SF-Q-01 (s5.md D1): R with S held: Q stays 0 until S falls.
            (0, &[], TV),
            (10, &[S], TV),
            (20, &[S, R], TV),
            (30, &[S], TV),
            (40, &[], TV),
            (200, &[], TV),
            // SF-Q-01 (s5.md D2): a rising S while running stops the time, Q = 1, value kept.
            (210, &[S], TV),
            (220, &[], TV),
            (250, &[S], TV),
            (260, &[S], TV),
            (270, &[S, R], TV),
            (280, &[], TV),
            (400, &[], TV),
        ]),
        Block::Tp => rows(&[
            // IEC-EXPIRY-01: the pulse ends in the call where ET reaches PT.
            (0, &[], "T#20MS"),
            (10, &[In], "T#20MS"),
            (29, &[], "T#20MS"),
            (30, &[], "T#20MS"),
            (31, &[], "T#20MS"),
            // IEC-RT-01 (iec.md W3): RT during a pulse with IN = 0 ends it: Q = 0, ET = 0 at
            // 110 and 115, where the pulse started at 100 would still run (Q = 1, ET 15).
            (100, &[In], "T#20MS"),
            (105, &[], "T#20MS"),
            (110, &[Rt], "T#20MS"),
            (115, &[], "T#20MS"),
            // IEC-RT-01: RT during a pulse with IN held ends it and clears the stored IN, so
            // IN = 1 at the box in that row is a rising edge: a new pulse of PT starts at 210
            // (Q = 1, ET 0), runs at 225 (ET 15, where the old one had ended at 220) and ends
            // at 230.
            (200, &[In], "T#20MS"),
            (210, &[In, Rt], "T#20MS"),
            (225, &[In], "T#20MS"),
            (230, &[In], "T#20MS"),
            // IEC-RT-01: after the pulse, IN still held (ET = PT): RT clears ET, and the same
            // rising edge starts a new pulse at 240.
            (240, &[In, Rt], "T#20MS"),
            (250, &[In], "T#20MS"),
            (260, &[In], "T#20MS"),
            (270, &[], "T#20MS"),
            // IEC-RT-01 (decisions.md R1): RT energised on every row with IN held: each row's
            // box call sees a rising edge and starts a pulse, so Q = 1 and ET 0 from 300 to
            // 340, longer than PT; the pulse of 340 runs its full PT once RT is released (ET
            // 10 at 350, Q = 0 at 360).
            (300, &[In, Rt], "T#20MS"),
            (310, &[In, Rt], "T#20MS"),
            (320, &[In, Rt], "T#20MS"),
            (330, &[In, Rt], "T#20MS"),
            (340, &[In, Rt], "T#20MS"),
            (350, &[In], "T#20MS"),
            (360, &[In], "T#20MS"),
            (370, &[], "T#20MS"),
        ]),
        Block::Ton => rows(&[
            // IEC-EXPIRY-01: Q rises in the call where ET reaches PT, not one call later.
            (0, &[], "T#20MS"),
            (10, &[In], "T#20MS"),
            (29, &[In], "T#20MS"),
            (30, &[In], "T#20MS"),
            (31, &[], "T#20MS"),
            // IEC-RT-01 (iec.md W3): RT while timing with IN held: ET = 0, Q = 0, and the
            // stored IN cleared, so IN = 1 in that row is a rising edge: timing starts again
            // at 115, and again at 120 (RT held); it expires PT after the last start (Q = 1 at
            // 140, not at 120 as started at 100).
            (100, &[In], "T#20MS"),
            (110, &[In], "T#20MS"),
            (115, &[In, Rt], "T#20MS"),
            (120, &[In, Rt], "T#20MS"),
            (130, &[In], "T#20MS"),
            (139, &[In], "T#20MS"),
            (140, &[In], "T#20MS"),
            // IEC-RT-01: RT on an expired TON with IN held: Q falls, timing restarts at 150,
            // Q = 1 again at 170.
            (150, &[In, Rt], "T#20MS"),
            (160, &[In], "T#20MS"),
            (170, &[In], "T#20MS"),
            (180, &[], "T#20MS"),
        ]),
        Block::Tof => rows(&[
            // IEC-EXPIRY-01: Q falls in the call where ET reaches PT.
            (0, &[In], "T#20MS"),
            (10, &[], "T#20MS"),
            (29, &[], "T#20MS"),
            (30, &[], "T#20MS"),
            (31, &[In], "T#20MS"),
            // IEC-RT-01 (iec.md W3): RT during the off-delay (started at 110): Q = 0, ET = 0;
            // no falling edge follows, so Q stays 0 (at 125 and 140, where the delay would
            // still run) until IN rises (150) and falls (160) again.
            (100, &[In], "T#20MS"),
            (110, &[], "T#20MS"),
            (115, &[], "T#20MS"),
            (118, &[Rt], "T#20MS"),
            (125, &[], "T#20MS"),
            (140, &[], "T#20MS"),
            (150, &[In], "T#20MS"),
            (160, &[], "T#20MS"),
            (175, &[], "T#20MS"),
            (180, &[], "T#20MS"),
            // IEC-RT-01: RT after the delay clears the ET held at PT.
            (190, &[Rt], "T#20MS"),
            // IEC-RT-01: RT with IN = 1: the box's IN = 1 sets Q again in that row.
            (200, &[In, Rt], "T#20MS"),
            (210, &[], "T#20MS"),
            (230, &[], "T#20MS"),
        ]),
        Block::Tonr => rows(&[
            // IEC-EXPIRY-01: the accumulated time reaches PT: Q = 1 at ET = PT.
            (0, &[], "T#20MS"),
            (10, &[In], "T#20MS"),
            (20, &[], "T#20MS"),
            (30, &[In], "T#20MS"),
            (39, &[In], "T#20MS"),
            (40, &[In], "T#20MS"),
            // TONR-RESUME-01: after R is released with IN held, it times again from 0.
            (50, &[In, R], "T#20MS"),
            (60, &[In, R], "T#20MS"),
            (70, &[In], "T#20MS"),
            (80, &[In], "T#20MS"),
            (90, &[In], "T#20MS"),
            (100, &[], "T#20MS"),
            // IEC-RT-01 (iec.md W3): RT clears the accumulated time as R does (ET 10 -> 0 at
            // 220); with IN held, the box finds the timer stopped with ET = 0 and Q = 0 in the
            // RT row, so it times again from 0 (245: ET 0, not 15), and an expired TONR
            // restarts (270: Q 1 -> 0, ET 0; Q = 1 again at 290).
            (150, &[R], "T#20MS"),
            (200, &[In], "T#20MS"),
            (210, &[], "T#20MS"),
            (220, &[Rt], "T#20MS"),
            (230, &[In], "T#20MS"),
            (240, &[In], "T#20MS"),
            (245, &[In, Rt], "T#20MS"),
            (255, &[In], "T#20MS"),
            (265, &[In], "T#20MS"),
            (270, &[In, Rt], "T#20MS"),
            (280, &[In], "T#20MS"),
            (290, &[In], "T#20MS"),
            (300, &[], "T#20MS"),
        ]),
        Block::Ctu | Block::Ctd | Block::Ctud => {
            // CNT-PRIO-01: R and LD act as levels: edges at CU and CD while one is held do not
            // count; releasing it with the count input held does not count (CNT-EDGE-01); R
            // wins over LD.
            let has = |p: Port| block.has_input(p);
            if has(R) {
                rows(&[
                    (0, &[Cu], "3"),
                    (0, &[], "3"),
                    (0, &[R], "3"),
                    (0, &[R, Cu], "3"),
                    (0, &[R], "3"),
                    (0, &[R, Cu], "3"),
                    (0, &[Cu], "3"),
                    (0, &[], "3"),
                    (0, &[Cu], "3"),
                ]);
            }
            if has(Ld) {
                rows(&[
                    (0, &[Ld], "3"),
                    (0, &[Ld, Cd], "3"),
                    (0, &[Ld], "3"),
                    (0, &[Ld, Cd], "3"),
                    (0, &[Cd], "3"),
                    (0, &[], "3"),
                    (0, &[Cd], "3"),
                ]);
            }
            if has(R) && has(Ld) {
                rows(&[(0, &[R, Ld], "3"), (0, &[Ld], "3"), (0, &[], "3")]);
            }
        }
        Block::SCu | Block::SCd | Block::SCud => return None,
    }
    Some(trace)
}

/// The reference's output for `text`.
fn reference(spec: BlockSpec, text: &str) -> Result<String, TraceError> {
    let mut out = Vec::new();
    run(spec, None, text.as_bytes(), &mut out).map_err(|e| match e {
        super::error::Error::Input(e) => e,
        super::error::Error::Output(e) => {
            TraceError::new(super::error::Location::Command, e.to_string())
        }
    })?;
    Ok(String::from_utf8_lossy(&out).into_owned())
}

/// The example trace of `spec`'s instruction with its preset as a column (comments and blank
/// lines dropped).
fn example_with_preset(spec: BlockSpec) -> Option<String> {
    let example = examples::of_instruction(spec.instruction)?;
    let value = example.preset?;
    let preset = spec.block().preset().port.name();
    let mut text = String::new();
    for line in example
        .text
        .lines()
        .filter(|l| !l.starts_with('#') && !l.trim().is_empty())
    {
        let extra = if text.is_empty() { preset } else { value };
        text.push_str(&format!("{line},{extra}\n"));
    }
    Some(text)
}

fn block_vectors(spec: BlockSpec, seed: u64) -> Result<Vec<Vector>, TraceError> {
    let block = spec.block();
    let kind = block.preset().kind;
    let ltime = spec.data_type() == DataType::LTime;
    let dir = if block.family() == Family::IecCounter || ltime {
        format!("{block}-{}", spec.data_type())
    } else {
        block.name().to_string()
    };
    // The TIME files' traces, read in nanoseconds on LTIME.
    let time_based = |trace: Trace| if ltime { trace.in_nanoseconds() } else { trace };
    let mut traces: Vec<(String, String)> = Vec::new();
    if let Some(text) = example_with_preset(spec) {
        traces.push(("example.csv".into(), text));
    }
    let mut rng = fastrand::Rng::with_seed(seed);
    for k in 0..TRACES_PER_BLOCK {
        traces.push((
            format!("random-{k:02}.csv"),
            random(spec, kind, &mut rng).text(),
        ));
    }
    traces.push((
        "preset-change.csv".into(),
        time_based(preset_change(spec, kind)).text(),
    ));
    if ltime {
        traces.push(("long-gaps.csv".into(), long_gaps_ltime(spec).text()));
    } else if kind == PresetKind::Time {
        traces.push(("long-gaps.csv".into(), long_gaps(spec).text()));
    }
    if matches!(block.family(), Family::IecCounter | Family::S5Counter) {
        traces.push(("limits.csv".into(), limits(spec).text()));
    }
    traces.push((
        "simultaneous.csv".into(),
        time_based(simultaneous(spec, kind)).text(),
    ));
    if block.has_input(Fr) {
        traces.push(("fr.csv".into(), fr(spec, kind).text()));
    }
    if let Some(trace) = decisions(spec) {
        traces.push(("decisions.csv".into(), time_based(trace).text()));
    }
    traces
        .into_iter()
        .map(|(file, text)| {
            Ok(Vector {
                dir: dir.clone(),
                file,
                spec,
                csv: reference(spec, &text)?,
            })
        })
        .collect()
}

/// Every vector: each block of the catalog on each of its data types (the IEC counters' integer
/// types, the IEC timers' TIME and LTIME).
pub fn all() -> Result<Vec<Vector>, TraceError> {
    let mut v = Vec::new();
    for (i, block) in Block::ALL.into_iter().enumerate() {
        for (j, &ty) in block.data_types().iter().enumerate() {
            let spec = BlockSpec::typed(block, Some(ty))
                .map_err(|e| TraceError::new(super::error::Location::Command, e))?;
            v.extend(block_vectors(spec, SEED + (i * 16 + j) as u64 + 1)?);
        }
    }
    Ok(v)
}

/// The README written beside the vectors.
pub fn readme() -> String {
    let mut outputs = String::new();
    for block in Block::ALL {
        let names: Vec<&str> = block.outputs().iter().map(|p| p.name()).collect();
        outputs.push_str(&format!("  {:<8} {}\n", block.name(), names.join(",")));
    }
    format!(
        "plc-timers test vectors\n\
         =======================\n\n\
         One directory per block (IEC counters: one per integer type, e.g. CTUD-SINT). Each CSV\n\
         file is a trace in the format of spec/cli.md: the inputs (t_ms for timers, the boolean\n\
         inputs, the preset as a column) followed by the reference outputs:\n\n{outputs}\n\
         example.csv is the crate's example trace; random-NN.csv are generated (clustered edges,\n\
         presets at edge values, time steps around ticks and presets, IEC timers across the\n\
         2^32 ms clock wrap); preset-change.csv changes TV/PT/PV mid-run (the IEC timers latch\n\
         PT while running); long-gaps.csv (IEC timers) has gaps up to and past 2^31 and 2^32 ms;\n\
         limits.csv (counters) counts into the type's limits; simultaneous.csv raises every\n\
         combination of inputs together; fr.csv (S5 blocks) has FR edges; decisions.csv (timers,\n\
         IEC counters) pins the decisions of spec/ that weigh a manual's wording or where other\n\
         runtimes differ (the comments of cli/src/trace/vectors.rs name each); in TP, TON, TOF\n\
         and TONR it has an RT column, the -(RT)- coil, which a row with RT = 1 runs before the\n\
         box call of that row (spec/cli.md, \"Traces\"); the other files have no RT column.\n\n\
         Replay a file through your implementation, write the same columns, and compare with\n\
         \x20 plc-timers check BLOCK FILE          (add --type T for IEC counters)\n\
         which reports the first differing line and column, the rule that decides it, and the\n\
         rows before it (exit status 1). The LTIME timers' directories (TP-LTIME, TON-LTIME,\n\
         TOF-LTIME, TONR-LTIME) take --type LTIME: their time column is t_ns, PT and ET are in\n\
         nanoseconds.\n"
    )
}
