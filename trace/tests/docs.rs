//! The timing diagrams: `docs/` holds the ones the renderer draws from `examples/traces/` now
//! (`UPDATE_DOCS=1 cargo test -p plc-timers-trace --test docs` redraws them); a 2 M-row trace is
//! drawn in bounded memory into a small SVG with no edge lost; `--from/--to` zoom; VCD export
//! parses back with the `vcd` crate.

use std::fs;
use std::path::{Path, PathBuf};

use plc_timers::catalog::{Block, ValueKind};
use plc_timers_trace::diagram::{self, Stats, Window, COLUMNS, EXACT_ROWS};
use plc_timers_trace::{engine, examples, vcd, BlockSpec};

/// The repository's root, where `docs/` is.
fn root() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR"))
        .parent()
        .expect("trace/ is inside the repository")
        .to_path_buf()
}

fn draw(spec: BlockSpec, preset: Option<&str>, trace: &[u8], window: Window) -> (String, Stats) {
    let mut out = Vec::new();
    let stats = diagram::svg(spec, preset, trace, window, &mut out).expect("draws");
    (String::from_utf8(out).expect("UTF-8"), stats)
}

/// `text` read as `block`'s preset, as the command line's parser reads it.
fn preset(block: Block, text: &'static str) -> Option<&'static str> {
    BlockSpec::new(block)
        .preset_literal(text)
        .expect("a valid preset");
    Some(text)
}

fn example_svg(e: &examples::Example) -> (String, Stats) {
    draw(e.spec, e.preset, e.text.as_bytes(), Window::default())
}

/// CLI-DIAG-01: one diagram per block in `docs/`, each the renderer's drawing of its example:
/// a waveform per boolean input and output, one ramp with a value axis and the preset line.
#[test]
fn docs_diagrams_are_current() {
    let update = std::env::var_os("UPDATE_DOCS").is_some();
    let mut stale = Vec::new();
    for e in examples::all().expect("examples") {
        let (svg, stats) = example_svg(&e);
        assert!(stats.exact);
        let bools = e
            .spec
            .block()
            .inputs()
            .iter()
            .filter(|p| p.kind() == plc_timers::catalog::ValueKind::Bool)
            .count();
        let waves = svg.matches("class=\"signal\"").count();
        assert!(waves >= 2 && waves <= bools + 2, "{}: {waves}", e.stem);
        assert_eq!(svg.matches("class=\"ramp\"").count(), 1, "{}", e.stem);
        assert_eq!(svg.matches("class=\"preset\"").count(), 1, "{}", e.stem);
        assert_eq!(svg.matches("class=\"value-axis\"").count(), 1, "{}", e.stem);
        assert!(svg.matches("class=\"tick\"").count() >= 2, "{}", e.stem);
        assert!(svg.starts_with("<svg") && svg.ends_with("</svg>\n"));
        let path = root().join(format!("docs/{}.svg", e.stem));
        if update {
            fs::write(&path, &svg).expect("write docs");
        }
        if fs::read_to_string(&path).ok().as_deref() != Some(svg.as_str()) {
            stale.push(path);
        }
    }
    assert!(
        stale.is_empty(),
        "stale diagrams {stale:?}; redraw with `UPDATE_DOCS=1 cargo test -p plc-timers-trace --test docs`"
    );
}

fn polyline(svg: &str, class: &str, name: &str) -> Vec<(f64, f64)> {
    let line = svg
        .lines()
        .find(|l| l.contains(&format!("class=\"{class}\" data-name=\"{name}\"")))
        .unwrap_or_else(|| panic!("no {class} {name}"));
    let points = line
        .split("points=\"")
        .nth(1)
        .and_then(|r| r.split('"').next())
        .expect("points");
    points
        .split_whitespace()
        .map(|p| {
            let (x, y) = p.split_once(',').expect("x,y");
            (x.parse().expect("x"), y.parse().expect("y"))
        })
        .collect()
}

/// The x of time `t` in a drawing of [t0, t_end].
fn x_of(t: f64, t0: f64, t_end: f64) -> f64 {
    86.0 + (t - t0) / (t_end - t0) * COLUMNS as f64
}

/// CLI-DIAG-01: TON's Q rises where ET reaches PT (t = 2500): a vertical step at that x; ET is a
/// ramp (a sloped segment from 2000 to 2500 ms), not a staircase.
#[test]
fn ton_q_rises_at_expiry_and_et_ramps() {
    let e = examples::of(Block::Ton).expect("TON example");
    let (svg, _) = example_svg(&e);
    let t_end = 3300.0 + 3300.0 * 0.08;
    let x = |t: f64| (x_of(t, 0.0, t_end) * 10.0).round() / 10.0;
    let q = polyline(&svg, "signal", "Q");
    let step: Vec<&(f64, f64)> = q
        .iter()
        .filter(|p| (p.0 - x(2500.0)).abs() < 0.06)
        .collect();
    assert_eq!(step.len(), 2, "a vertical step at 2500: {q:?}");
    assert_ne!(step[0].1, step[1].1);
    let et = polyline(&svg, "ramp", "ET");
    let i = et
        .iter()
        .position(|p| (p.0 - x(2000.0)).abs() < 0.06)
        .expect("a point at 2000");
    let (a, b) = (et[i + 1], et[i + 2]);
    assert!(
        (a.0 - x(2250.0)).abs() < 0.06 && a.1 < et[i].1,
        "ET rises from 2000 to 2250: {et:?}"
    );
    assert!(
        b.1 < a.1 && (b.0 - x(2499.0)).abs() < 0.06,
        "and on to 2499: {et:?}"
    );
}

/// CLI-LTIME-03: the LTIME example's diagram has its time axis in ns, its title shows PT as
/// its LTIME literal, and Q rises where ET reaches PT: 1 000 000 ns (the start) + 1 500 000 ns.
#[test]
fn ltime_diagram_in_nanoseconds() {
    let ton = BlockSpec::typed(Block::Ton, Some(plc_timers::catalog::DataType::LTime))
        .expect("TON takes LTIME");
    let e = examples::of_instruction(ton.instruction).expect("the TON LTIME example");
    let (svg, _) = example_svg(&e);
    assert!(
        svg.contains(">t [ns]</text>"),
        "CLI-LTIME-03: the axis' unit"
    );
    assert!(
        svg.contains(">TON, PT = LT#1MS_500US</text>"),
        "CLI-LTIME-03: the title"
    );
    let t_last = 4_000_000.0;
    let t_end = t_last + t_last * 0.08;
    let x = |t: f64| (x_of(t, 0.0, t_end) * 10.0).round() / 10.0;
    let q = polyline(&svg, "signal", "Q");
    let step: Vec<&(f64, f64)> = q
        .iter()
        .filter(|p| (p.0 - x(2_500_000.0)).abs() < 0.06)
        .collect();
    assert_eq!(step.len(), 2, "CLI-LTIME-03: a step at 2 500 000 ns: {q:?}");
    assert_ne!(step[0].1, step[1].1);
}

/// CLI-DIAG-01: an S5 timer's BI runs down one unit per tick of its own time base. S5T#20S is
/// 200 units of the 100 ms base (2 000 units of 10 ms would pass 999), so S_PULSE started at 0
/// ramps BI from 200 down to 0 at t = 200 x 100 ms = 20 000 ms, then stays flat until the next
/// row at 30 000 ms.
#[test]
fn s5_bi_ramps_on_its_time_base() {
    let (svg, _) = draw(
        BlockSpec::new(Block::SPulse),
        preset(Block::SPulse, "S5T#20S"),
        b"t_ms,S\n0,1\n30000,1\n",
        Window::default(),
    );
    let t_end = 30000.0 + 30000.0 * 0.08;
    let x = |t: f64| (x_of(t, 0.0, t_end) * 10.0).round() / 10.0;
    let bi = polyline(&svg, "ramp", "BI");
    let i = bi
        .iter()
        .position(|p| (p.0 - x(20000.0)).abs() < 0.06)
        .unwrap_or_else(|| panic!("BI reaches 0 at 20 000 ms: {bi:?}"));
    assert!(bi[i].1 > bi[0].1, "down from 200 at 0 to 0 there: {bi:?}");
    assert!(
        bi[..i].iter().all(|p| p.0 < x(20000.0)),
        "no earlier end of the ramp: {bi:?}"
    );
}

/// CLI-DIAG-01: the value axis spans every value drawn, negative ones too, with ticks on whole
/// multiples of a 1-2-5 step giving at most about four intervals. CTD loaded with PV = 2 and
/// counted down five times runs CV from 2 to -3: a span of 5, so the step is 2 (5 / 4 = 1.25
/// rounded up to 1-2-5) and the ticks are the multiples of 2 in [-3, 2], drawn from the bottom up.
#[test]
fn value_axis_covers_negative_counts() {
    let mut trace = String::from("t_ms,CD,LD\n0,0,1\n10,0,0\n");
    for k in 0..5u64 {
        trace.push_str(&format!("{},1,0\n{},0,0\n", 20 + 20 * k, 30 + 20 * k));
    }
    let (svg, _) = draw(
        BlockSpec::new(Block::Ctd),
        preset(Block::Ctd, "2"),
        trace.as_bytes(),
        Window::default(),
    );
    // Each tick is one line of the SVG: its mark (`<line … y1="Y" …/>`) then its label.
    let ticks: Vec<(i64, f64)> = svg
        .lines()
        .filter(|l| l.contains("class=\"tick\""))
        .map(|l| {
            let y = l.split("y1=\"").nth(1).and_then(|r| r.split('"').next());
            let v = l.rsplit("\">").next().and_then(|r| r.split('<').next());
            (
                v.and_then(|v| v.parse().ok()).expect("a tick value"),
                y.and_then(|y| y.parse().ok()).expect("a tick y"),
            )
        })
        .collect();
    let values: Vec<i64> = ticks.iter().map(|t| t.0).collect();
    assert_eq!(values, [-2, 0, 2], "{svg}");
    let gaps: Vec<f64> = ticks.windows(2).map(|w| w[0].1 - w[1].1).collect();
    assert!(
        gaps.iter().all(|g| *g > 0.0 && (g - gaps[0]).abs() < 0.11),
        "ticks evenly spaced, upwards: {ticks:?}"
    );
    let cv = polyline(&svg, "ramp", "CV");
    let (lowest, highest) = cv.iter().fold((f64::MIN, f64::MAX), |(lo, hi), p| {
        (lo.max(p.1), hi.min(p.1))
    });
    let span = ticks[0].1 - ticks[2].1;
    // CV = 2 is the top tick; CV = -3 lies half a step below the -2 tick.
    assert!((highest - ticks[2].1).abs() < 0.11, "{cv:?} {ticks:?}");
    assert!(
        (lowest - (ticks[0].1 + span / 4.0)).abs() < 0.11,
        "{cv:?} {ticks:?}"
    );
}

/// Glitches of IN (1 ms at 1) inside its long 0 stretches.
const GLITCHES: [u64; 4] = [100_001, 333_333, 1_300_001, 1_777_777];
/// Dips of IN (1 ms at 0) inside its long 1 stretches.
const DIPS: [u64; 3] = [10_007, 1_010_003, 1_630_001];

/// A TON trace of `rows` rows, 1 ms apart: IN is 1 for the first 50 000 ms of every 200 000 ms
/// and 0 otherwise, but for the 1 ms glitches and dips.
fn long_trace(rows: u64) -> Vec<u8> {
    let mut s = Vec::with_capacity(rows as usize * 12);
    s.extend_from_slice(b"t_ms,IN\n");
    for t in 0..rows {
        let level = (t % 200_000 < 50_000 && !DIPS.contains(&t)) || GLITCHES.contains(&t);
        s.extend_from_slice(format!("{t},{}\n", u8::from(level)).as_bytes());
    }
    s
}

/// CLI-DIAG-02: a 2 M-row trace is drawn from at most 2 x COLUMNS buckets (bounded memory,
/// whatever the length), into an SVG under 5 MB, and every 1 ms glitch in it is still drawn (a
/// vertical bar in the IN waveform where it is), and none where there is none.
#[test]
fn two_million_rows_bounded_and_no_edge_lost() {
    let rows = 2_000_000;
    let trace = long_trace(rows);
    let (svg, stats) = draw(
        BlockSpec::new(Block::Ton),
        preset(Block::Ton, "T#500MS"),
        &trace,
        Window::default(),
    );
    assert_eq!(stats.rows, rows);
    assert!(!stats.exact);
    // The most held at once: the exact rows before they fold into 2 x COLUMNS buckets.
    assert_eq!(stats.held, EXACT_ROWS.max(2 * COLUMNS), "held");
    // 2 M ms in at most 2 x 796 buckets: 2048 ms each.
    assert_eq!(stats.bucket_ms, 2048);
    assert!(svg.len() < 5_000_000, "{} bytes", svg.len());
    assert!(svg.len() < 500_000, "{} bytes", svg.len());
    let t_end = (rows - 1) as f64 * 1.08;
    let input = polyline(&svg, "signal", "IN");
    // SVG y grows downwards: the high level has the smallest y.
    let (high, low) = input
        .iter()
        .fold((f64::MAX, f64::MIN), |(a, b), p| (a.min(p.1), b.max(p.1)));
    let levels_near = |t: u64| -> (bool, bool) {
        let x = x_of(t as f64, 0.0, t_end);
        let near: Vec<&(f64, f64)> = input.iter().filter(|p| (p.0 - x).abs() < 1.5).collect();
        (
            near.iter().any(|p| p.1 == high),
            near.iter().any(|p| p.1 == low),
        )
    };
    for glitch in GLITCHES.into_iter().chain(DIPS) {
        assert_eq!(
            levels_near(glitch),
            (true, true),
            "the glitch at {glitch} ms"
        );
    }
    for quiet in [150_000, 750_000, 1_550_000] {
        assert_eq!(levels_near(quiet), (false, true), "no glitch at {quiet} ms");
    }
    for quiet_high in [30_000, 1_025_000] {
        assert_eq!(
            levels_near(quiet_high),
            (true, false),
            "no dip at {quiet_high} ms"
        );
    }
    // ET ramps up to PT in every high stretch: the ramp reaches the preset line.
    let et = polyline(&svg, "ramp", "ET");
    let top = et.iter().map(|p| p.1).fold(f64::MAX, f64::min);
    let preset = polyline(&svg, "preset", "PT");
    assert!(
        (top - preset[0].1).abs() < 0.06,
        "ET reaches PT: {top} vs {}",
        preset[0].1
    );
}

/// CLI-DIAG-02: `--from/--to` draw only that window, starting from the state the rows before
/// left; the time axis spans exactly the window.
#[test]
fn window_zooms() {
    let e = examples::of(Block::Ton).expect("TON example");
    let window = Window {
        from: Some(2200),
        to: Some(2600),
    };
    let (svg, stats) = draw(e.spec, e.preset, e.text.as_bytes(), window);
    assert_eq!(stats.rows, 9, "reading stops after the first row past --to");
    assert_eq!(stats.drawn, 4, "2200 (state of 2000), 2250, 2499, 2500");
    let q = polyline(&svg, "signal", "Q");
    assert!((q[0].0 - 86.0).abs() < 0.06, "{q:?}");
    assert!(
        svg.contains(">2200</text>") && svg.contains(">2600</text>"),
        "axis ends"
    );
    let et = polyline(&svg, "ramp", "ET");
    assert!(
        (et.last().expect("points").0 - (900.0 - 18.0)).abs() < 0.06,
        "{et:?}"
    );
    // Windows that start and end on rows: each row drawn once, the one at --to included.
    for (from, to, rows, drawn) in [(2000, 2500, 9, 4), (2000, 2499, 8, 3), (1999, 2000, 6, 2)] {
        let window = Window {
            from: Some(from),
            to: Some(to),
        };
        let (_, stats) = draw(e.spec, e.preset, e.text.as_bytes(), window);
        assert_eq!((stats.rows, stats.drawn), (rows, drawn), "{from}..{to}");
    }
}

/// CLI-DIAG-02: drawings from buckets are pinned too: a 6 000-row TONR trace whose PT column
/// changes (a ramp, a step line for the preset), whole and through a window, against
/// `trace/tests/data/*.svg` (`UPDATE_DOCS=1` redraws them).
#[test]
fn bucket_drawings_are_current() {
    let mut trace = String::from("t_ms,IN,R,PT\n");
    for t in 0..6_000u64 {
        let input = u8::from(t % 900 < 500 || t % 1_700 == 1_000);
        let reset = u8::from(t % 2_500 == 2_400);
        let pt = if t < 3_000 { "T#700MS" } else { "T#300MS" };
        trace.push_str(&format!("{t},{input},{reset},{pt}\n"));
    }
    let update = std::env::var_os("UPDATE_DOCS").is_some();
    let tonr = BlockSpec::new(Block::Tonr);
    for (name, window) in [
        ("bucket", Window::default()),
        (
            "bucket-window",
            Window {
                from: Some(1_000),
                to: Some(5_500),
            },
        ),
    ] {
        let (svg, stats) = draw(tonr, None, trace.as_bytes(), window);
        assert!(!stats.exact, "{name}");
        let path = Path::new(env!("CARGO_MANIFEST_DIR")).join(format!("tests/data/{name}.svg"));
        if update {
            fs::write(&path, &svg).expect("write");
        }
        assert_eq!(
            fs::read_to_string(&path).ok().as_deref(),
            Some(svg.as_str()),
            "{name}.svg is stale; redraw with UPDATE_DOCS=1"
        );
        assert!(svg.contains("TONR, PT changes"), "{name}");
    }
}

/// CLI-DIAG-02: up to EXACT_ROWS rows are drawn exactly, one more is drawn from buckets whose
/// width follows the span: the smallest power of two that gives fewer than COLUMNS buckets.
#[test]
fn exact_up_to_the_limit_then_buckets() {
    let trace = long_trace(EXACT_ROWS as u64 + 1);
    let text: String = String::from_utf8(trace).expect("UTF-8");
    let upto =
        |n: usize| -> String { text.lines().take(n + 1).map(|l| format!("{l}\n")).collect() };
    let ton = BlockSpec::new(Block::Ton);
    let (_, stats) = draw(
        ton,
        preset(Block::Ton, "T#500MS"),
        upto(EXACT_ROWS).as_bytes(),
        Window::default(),
    );
    assert!(stats.exact && stats.bucket_ms == 0 && stats.held == EXACT_ROWS);
    let (_, stats) = draw(
        ton,
        preset(Block::Ton, "T#500MS"),
        upto(EXACT_ROWS + 1).as_bytes(),
        Window::default(),
    );
    assert!(!stats.exact);
    // 2048 ms over 796 columns: 4 ms buckets (2048 / 2 = 1024 >= 796, 2048 / 4 = 512 < 796).
    assert_eq!(stats.bucket_ms, 4);
    // A window of the 2 M-row trace: 100 000 ms, so 128 ms buckets.
    let long = long_trace(1_200_000);
    let window = Window {
        from: Some(1_000_000),
        to: Some(1_100_000),
    };
    let (_, stats) = draw(ton, preset(Block::Ton, "T#500MS"), &long, window);
    assert_eq!((stats.drawn, stats.bucket_ms), (100_001, 128));
}

/// CLI-VCD-01: the VCD of every example parses back with the `vcd` crate: a 1 ms timescale (1 ns
/// on LTIME, CLI-LTIME-03),
/// one variable per boolean input, the preset and each output, and the values of the run.
#[test]
fn vcd_parses_back() {
    for e in examples::all().expect("examples") {
        let mut out = Vec::new();
        let rows = vcd::export(e.spec, e.preset, e.text.as_bytes(), &mut out).expect("exports");
        let mut parser = ::vcd::Parser::new(&out[..]);
        let header = parser.parse_header().expect("a VCD header");
        let unit = match e.spec.time_column() {
            "t_ns" => ::vcd::TimescaleUnit::NS,
            _ => ::vcd::TimescaleUnit::MS,
        };
        assert_eq!(header.timescale, Some((1, unit)), "{}", e.stem);
        let module = match &header.items[0] {
            ::vcd::ScopeItem::Scope(s) => s,
            other => panic!("{other:?}"),
        };
        let names: Vec<String> = module
            .items
            .iter()
            .filter_map(|i| match i {
                ::vcd::ScopeItem::Var(v) => Some(v.reference.clone()),
                _ => None,
            })
            .collect();
        for port in e.spec.block().outputs() {
            assert!(
                names.iter().any(|n| n == port.name()),
                "{}: {names:?}",
                e.stem
            );
        }
        let mut times = 0;
        let mut last = 0;
        for command in parser {
            if let ::vcd::Command::Timestamp(t) = command.expect("a valid command") {
                assert!(t >= last);
                last = t;
                times += 1;
            }
        }
        assert!(times > 3 && times as u64 <= rows, "{}", e.stem);
    }
    // TON: Q rises at 2500 ms.
    let e = examples::of(Block::Ton).expect("TON");
    let mut out = Vec::new();
    vcd::export(
        e.spec,
        preset(Block::Ton, "T#500MS"),
        e.text.as_bytes(),
        &mut out,
    )
    .expect("exports");
    let text = String::from_utf8(out).expect("ASCII");
    let at = text.find("#2500\n").expect("a change at 2500 ms");
    let q_id = text
        .lines()
        .find(|l| l.starts_with("$var wire 1 ") && l.contains(" Q $end"))
        .and_then(|l| l.split_whitespace().nth(3))
        .expect("Q's id");
    assert!(
        text[at..]
            .lines()
            .nth(1)
            .is_some_and(|l| l == format!("1{q_id}")),
        "{}",
        &text[at..at + 40]
    );
}

/// CLI-VCD-01: every example's VCD, read back with the `vcd` crate, holds at the end of each
/// timestamp exactly the values of the last row of that time in `run`'s output (an independent
/// path: the CSV writer): every boolean input and every output, declared as a 1-bit wire
/// (BOOL), a 16-bit reg (WORD) or a 64-bit integer (the rest), each change as wide as its
/// declaration. TON's preset signal holds PT = 500 (1 500 000 on LTIME, in ns).
#[test]
fn vcd_agrees_with_run() {
    use ::vcd::{Command, IdCode, Value as Bit, VarType};
    use std::collections::HashMap;
    for e in examples::all().expect("examples") {
        // The run's rows by time: the last row of each time.
        let mut csv = Vec::new();
        engine::run(e.spec, e.preset, e.text.as_bytes(), &mut csv).expect("runs");
        let csv = String::from_utf8(csv).expect("UTF-8");
        let mut lines = csv.lines().filter(|l| !l.starts_with('#'));
        let header: Vec<String> = lines
            .next()
            .expect("a header")
            .split(',')
            .map(str::to_ascii_uppercase)
            .collect();
        let time = e.spec.time_column().to_ascii_uppercase();
        let t_col = header.iter().position(|h| *h == time);
        let mut rows: Vec<(u64, Vec<String>)> = Vec::new();
        for (i, line) in lines.enumerate() {
            let cells: Vec<String> = line.split(',').map(str::to_string).collect();
            let t = t_col.map_or(i as u64, |c| cells[c].parse().expect("a time"));
            match rows.last_mut() {
                Some(last) if last.0 == t => last.1 = cells,
                _ => rows.push((t, cells)),
            }
        }
        // The VCD's declarations and its values at the end of each timestamp.
        let mut out = Vec::new();
        vcd::export(e.spec, e.preset, e.text.as_bytes(), &mut out).expect("exports");
        let mut declared: HashMap<IdCode, (VarType, u32, String)> = HashMap::new();
        let mut values: HashMap<IdCode, i128> = HashMap::new();
        let mut snapshots: Vec<(u64, HashMap<IdCode, i128>)> = Vec::new();
        for command in ::vcd::Parser::new(&out[..]) {
            match command.expect("a valid command") {
                Command::VarDef(ty, size, id, name, _) => {
                    declared.insert(id, (ty, size, name));
                }
                Command::Timestamp(t) => snapshots.push((t, values.clone())),
                Command::ChangeScalar(id, b) => {
                    assert_eq!(
                        declared[&id].1, 1,
                        "{}: a scalar change of a wide signal",
                        e.stem
                    );
                    values.insert(id, i128::from(b == Bit::V1));
                }
                Command::ChangeVector(id, v) => {
                    let (_, size, name) = &declared[&id];
                    assert_eq!(v.len(), *size as usize, "{}: {name}'s change width", e.stem);
                    let mut x: i128 = 0;
                    for b in &v {
                        x = x << 1 | i128::from(b == Bit::V1);
                    }
                    if *size == vcd::INT_BITS && x >> (size - 1) & 1 == 1 {
                        x -= 1 << size; // two's complement
                    }
                    values.insert(id, x);
                }
                _ => {}
            }
        }
        snapshots.push((u64::MAX, values));
        // Snapshot k holds the values before timestamp k: those of timestamp k - 1.
        let at: Vec<(u64, &HashMap<IdCode, i128>)> =
            snapshots.windows(2).map(|w| (w[0].0, &w[1].1)).collect();
        assert_eq!(
            at.iter().map(|a| a.0).collect::<Vec<_>>(),
            rows.iter().map(|r| r.0).collect::<Vec<_>>(),
            "{}: one timestamp per time of the trace",
            e.stem
        );
        let block = e.spec.block();
        let mut checked = 0;
        for ((t, vals), (_, cells)) in at.iter().zip(&rows) {
            for (id, (ty, size, name)) in &declared {
                let port_kind = block
                    .outputs()
                    .iter()
                    .find(|p| p.name() == name.as_str())
                    .map(|p| p.kind());
                let is_input = block.inputs().iter().any(|p| p.name() == name.as_str());
                let expected_decl = match port_kind {
                    Some(ValueKind::Bool) => (VarType::Wire, 1),
                    Some(ValueKind::Word) => (VarType::Reg, 16),
                    Some(_) => (VarType::Integer, vcd::INT_BITS),
                    None if is_input && block.preset().port.name() != name.as_str() => {
                        (VarType::Wire, 1)
                    }
                    None => (VarType::Integer, vcd::INT_BITS),
                };
                assert_eq!((*ty, *size), expected_decl, "{}: {name}", e.stem);
                let Some(col) = header.iter().position(|h| *h == name.to_ascii_uppercase()) else {
                    if block.preset().port.name() == name.as_str() && block == Block::Ton {
                        // T#500ms = 500 ms; LT#1MS500US = 1 500 000 ns.
                        let pt = if e.spec.time_column() == "t_ns" {
                            1_500_000
                        } else {
                            500
                        };
                        assert_eq!(vals.get(id), Some(&pt), "{}: PT at {t}", e.stem);
                    }
                    continue;
                };
                let cell = cells[col].as_str();
                let want: i128 = match port_kind {
                    Some(ValueKind::Word) => {
                        i128::from_str_radix(cell.trim_start_matches("W#16#"), 16).expect("a word")
                    }
                    Some(ValueKind::Bool) | None => {
                        i128::from(matches!(cell.to_ascii_lowercase().as_str(), "1" | "true"))
                    }
                    Some(_) => cell.parse().expect("an integer"),
                };
                assert_eq!(vals.get(id), Some(&want), "{}: {name} at {t} ms", e.stem);
                checked += 1;
            }
        }
        assert!(
            checked >= 3 * rows.len(),
            "{}: {checked} values checked",
            e.stem
        );
    }
}

/// CLI-DIAG-01: the title gives the preset as its literal, and says when the trace's column
/// gives it; a preset that changes is named, not valued.
#[test]
fn title_shows_the_preset_literal() {
    let title = |svg: &str| -> String {
        let start = svg.find("font-weight=\"bold\">").expect("a title") + 19;
        svg[start..start + svg[start..].find('<').expect("end")].to_string()
    };
    let ton = BlockSpec::new(Block::Ton);
    let (svg, _) = draw(
        ton,
        preset(Block::Ton, "T#500ms"),
        b"t_ms,IN\n0,1\n600,1\n",
        Window::default(),
    );
    assert_eq!(title(&svg), "TON, PT = T#500MS");
    let (svg, _) = draw(
        ton,
        None,
        b"t_ms,IN,PT\n0,1,500\n600,1,T#500MS\n",
        Window::default(),
    );
    assert_eq!(title(&svg), "TON, PT = T#500MS (from the trace)");
    let (svg, _) = draw(
        ton,
        None,
        b"t_ms,IN,PT\n0,1,500\n600,1,T#1S\n",
        Window::default(),
    );
    assert_eq!(title(&svg), "TON, PT changes (from the trace)");
    let (svg, _) = draw(
        BlockSpec::new(Block::SOffdt),
        preset(Block::SOffdt, "W#16#1005"),
        b"t_ms,S\n0,1\n10,0\n",
        Window::default(),
    );
    assert_eq!(title(&svg), "S_OFFDT, TV = S5T#500MS");
    let (svg, _) = draw(
        BlockSpec::new(Block::Ctu),
        preset(Block::Ctu, "4"),
        b"CU\n1\n0\n",
        Window::default(),
    );
    assert_eq!(title(&svg), "CTU, PV = 4");
}
