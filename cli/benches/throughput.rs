//! Throughput of `plc-timers run` and `check` against `mawk -F, '{print $0 ",0,0"}'` (append
//! two columns to every row, the least a tool can do) on the same 2 M-row TON trace, side by
//! side, and the time and output size of `diagram` on it. Prints the ratios.
//!
//! `cargo bench -p plc-timers-cli` (release build of the binary). `ROWS=…` changes the size.

use std::io::Write;
use std::path::Path;
use std::process::{Command, Stdio};
use std::time::{Duration, Instant};

const RUNS: usize = 9;

fn write_trace(path: &Path, rows: u64) {
    let mut out = std::io::BufWriter::new(std::fs::File::create(path).expect("trace file"));
    writeln!(out, "t_ms,IN").expect("write");
    let mut rng = fastrand::Rng::with_seed(7);
    let mut level = 0;
    for t in 0..rows {
        if rng.u32(..700) == 0 {
            level ^= 1;
        }
        writeln!(out, "{t},{level}").expect("write");
    }
}

/// The shortest wall time of `RUNS` runs of `program args`, output to /dev/null (the
/// minimum is the estimate least disturbed by other work on the machine).
fn time(program: &str, args: &[&str]) -> Option<Duration> {
    let mut times = Vec::new();
    for _ in 0..RUNS {
        let start = Instant::now();
        let status = Command::new(program)
            .args(args)
            .stdout(Stdio::null())
            .status()
            .ok()?;
        let elapsed = start.elapsed();
        if !status.success() && status.code() != Some(1) {
            return None;
        }
        times.push(elapsed);
    }
    times.sort();
    Some(times[0])
}

fn main() {
    let rows: u64 = std::env::var("ROWS")
        .ok()
        .and_then(|r| r.parse().ok())
        .unwrap_or(2_000_000);
    let dir = Path::new(env!("CARGO_TARGET_TMPDIR"));
    let trace = dir.join("throughput-ton.csv");
    let with_outputs = dir.join("throughput-ton-out.csv");
    let svg = dir.join("throughput-ton.svg");
    write_trace(&trace, rows);
    let bin = env!("CARGO_BIN_EXE_plc-timers");
    let out = Command::new(bin)
        .args(["run", "TON", "--pt", "T#500ms"])
        .arg(&trace)
        .output()
        .expect("run");
    std::fs::write(&with_outputs, &out.stdout).expect("write");
    let t = trace.to_string_lossy().into_owned();
    let o = with_outputs.to_string_lossy().into_owned();
    let s = svg.to_string_lossy().into_owned();
    let size = std::fs::metadata(&trace).map(|m| m.len()).unwrap_or(0);
    println!(
        "TON trace: {rows} rows, {:.1} MB; fastest of {RUNS} runs, output to /dev/null",
        size as f64 / 1e6
    );
    let mawk_on = |file: &str| {
        ["/usr/bin/mawk", "mawk"]
            .into_iter()
            .find_map(|m| time(m, &["-F,", "{print $0 \",0,0\"}", file]))
    };
    let mawk = mawk_on(&t);
    // check reads the trace with outputs: mawk on that file is its fair comparison.
    let mawk_out = mawk_on(&o);
    let run = time(bin, &["run", "TON", "--pt", "T#500ms", &t]).expect("run works");
    let check = time(bin, &["check", "TON", "--pt", "T#500ms", &o]).expect("check works");
    let diagram =
        time(bin, &["diagram", "TON", "--pt", "T#500ms", &t, "-o", &s]).expect("diagram works");
    let svg_size = std::fs::metadata(&svg).map(|m| m.len()).unwrap_or(0);
    let rate = |d: Duration| rows as f64 / d.as_secs_f64() / 1e6;
    println!("{:<34} {:>9} {:>12}", "command", "time", "rows/s");
    if let Some(m) = mawk_out {
        println!(
            "{:<34} {:>7.3} s {:>9.1} M",
            "mawk … (on the trace with outputs)",
            m.as_secs_f64(),
            rate(m)
        );
    }
    if let Some(m) = mawk {
        println!(
            "{:<34} {:>7.3} s {:>9.1} M",
            "mawk -F, '{print $0 \",0,0\"}'",
            m.as_secs_f64(),
            rate(m)
        );
    }
    for (name, d) in [
        ("plc-timers run TON", run),
        ("plc-timers check TON", check),
        ("plc-timers diagram TON", diagram),
    ] {
        println!("{name:<34} {:>7.3} s {:>9.1} M", d.as_secs_f64(), rate(d));
    }
    println!("diagram SVG: {:.1} kB", svg_size as f64 / 1e3);
    match (mawk, mawk_out) {
        (Some(m), Some(mo)) => {
            println!(
                "ratio mawk/run = {:.2}, mawk/check = {:.2} (above 1: plc-timers is faster)",
                m.as_secs_f64() / run.as_secs_f64(),
                mo.as_secs_f64() / check.as_secs_f64()
            );
        }
        _ => println!("mawk not found: no ratio"),
    }
}
