//! Timing diagrams of a recorded trace, drawn as the manuals draw timers: inputs and Q as digital
//! waveforms, ET / BI / CV as a stepped ramp with the preset marked, a time axis in ms.
//! Plain SVG, no dependency.

use std::fmt::Write as _;
use std::format;
use std::string::String;
use std::vec::Vec;

use super::block::Value;
use super::runner::Recording;
use plc_timers::time::{S5Time, Time};

const WIDTH: f64 = 900.0;
const LEFT: f64 = 80.0;
const RIGHT: f64 = 24.0;
const TOP: f64 = 44.0;
const BOOL_LANE: f64 = 36.0;
const VALUE_LANE: f64 = 90.0;
const AXIS: f64 = 40.0;

fn escape(text: &str) -> String {
    text.replace('&', "&amp;")
        .replace('<', "&lt;")
        .replace('>', "&gt;")
        .replace('"', "&quot;")
}

/// The value a preset marks on the ramp of `output`: PT in ms on ET, TV units on BI, PV on CV.
fn preset_mark(output: &str, preset: &str) -> Option<i128> {
    match output {
        "ET" => preset
            .parse::<Time>()
            .ok()
            .map(|t| i128::from(t.as_millis().max(0))),
        "BI" => preset.parse::<S5Time>().ok().map(|t| i128::from(t.units())),
        "CV" => {
            let digits = preset.trim_start_matches(['C', 'c', '#']);
            digits.parse::<i128>().ok()
        }
        _ => None,
    }
}

/// A "nice" step (1, 2 or 5 x 10^k) giving at most about 10 ticks over `span`.
fn tick_step(span: f64) -> f64 {
    let raw = (span / 10.0).max(1.0);
    let magnitude = 10f64.powf(raw.log10().floor());
    [1.0, 2.0, 5.0, 10.0]
        .into_iter()
        .map(|m| m * magnitude)
        .find(|s| *s >= raw)
        .unwrap_or(raw)
}

/// Renders `rec` as an SVG document.
pub fn svg(rec: &Recording) -> String {
    let ramps: Vec<&(&str, Vec<Value>)> = rec
        .outputs
        .iter()
        .filter(|(_, v)| matches!(v.first(), Some(Value::Int(_))))
        .collect();
    let bools: Vec<(&str, Vec<bool>)> = rec
        .inputs
        .iter()
        .map(|(n, v)| (*n, v.clone()))
        .chain(
            rec.outputs
                .iter()
                .filter(|&(_n, v)| matches!(v.first(), Some(Value::Bool(_))))
                .map(|(n, v)| {
                    (
                        *n,
                        v.iter().map(|x| matches!(x, Value::Bool(true))).collect(),
                    )
                }),
        )
        .collect();
    let height = TOP + bools.len() as f64 * BOOL_LANE + ramps.len() as f64 * VALUE_LANE + AXIS;
    let t0 = rec.time.first().copied().unwrap_or(0) as f64;
    let last = rec.time.last().copied().unwrap_or(0) as f64;
    let span = (last - t0).max(1.0);
    let t_end = last + (span * 0.08).max(1.0);
    let plot = WIDTH - LEFT - RIGHT;
    let x = |t: f64| LEFT + (t - t0) / (t_end - t0) * plot;
    let mut s = String::new();
    let _ = write!(
        s,
        "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"{WIDTH}\" height=\"{height}\" \
         viewBox=\"0 0 {WIDTH} {height}\" font-family=\"sans-serif\" font-size=\"12\">\n\
         <rect width=\"100%\" height=\"100%\" fill=\"white\"/>\n"
    );
    let title = match &rec.preset {
        Some((name, value)) => format!("{}, {name} = {value}", rec.block),
        None => String::from(rec.block),
    };
    let _ = writeln!(
        s,
        "<text x=\"{LEFT}\" y=\"22\" font-size=\"15\" font-weight=\"bold\">{}</text>",
        escape(&title)
    );
    // Light vertical lines at every execution.
    for &t in &rec.time {
        let xt = x(t as f64);
        let _ = writeln!(
            s,
            "<line class=\"row\" x1=\"{xt:.1}\" y1=\"{TOP}\" x2=\"{xt:.1}\" y2=\"{:.1}\" stroke=\"#eee\"/>",
            height - AXIS
        );
    }
    let mut y = TOP;
    let step_points = |values: &[f64], lo: f64, hi: f64| -> String {
        let mut pts = String::new();
        let mut prev: Option<f64> = None;
        for (t, v) in rec.time.iter().zip(values) {
            let vy = hi - (hi - lo) * v;
            let xt = x(*t as f64);
            if let Some(p) = prev {
                let _ = write!(pts, "{xt:.1},{p:.1} ");
            }
            let _ = write!(pts, "{xt:.1},{vy:.1} ");
            prev = Some(vy);
        }
        if let Some(p) = prev {
            let _ = write!(pts, "{:.1},{p:.1}", x(t_end));
        }
        pts
    };
    for (name, values) in &bools {
        let lo = y + 6.0;
        let hi = y + BOOL_LANE - 8.0;
        let v: Vec<f64> = values.iter().map(|&b| f64::from(u8::from(b))).collect();
        let color = if rec.outputs.iter().any(|(n, _)| n == name) {
            "#c0392b"
        } else {
            "#1f4e79"
        };
        let _ = writeln!(
            s,
            "<text x=\"8\" y=\"{:.1}\">{}</text>",
            hi - 4.0,
            escape(name)
        );
        let _ = writeln!(
            s,
            "<polyline class=\"signal\" data-name=\"{}\" points=\"{}\" fill=\"none\" stroke=\"{color}\" stroke-width=\"2\"/>",
            escape(name),
            step_points(&v, lo, hi)
        );
        y += BOOL_LANE;
    }
    for (name, values) in &ramps {
        let ints: Vec<i128> = values
            .iter()
            .map(|v| if let Value::Int(i) = v { *i } else { 0 })
            .collect();
        let mark = rec.preset.as_ref().and_then(|(_, p)| preset_mark(name, p));
        let max = ints.iter().copied().chain(mark).max().unwrap_or(1).max(1) as f64;
        let min = ints.iter().copied().min().unwrap_or(0).min(0) as f64;
        let lo = y + 10.0;
        let hi = y + VALUE_LANE - 12.0;
        let norm: Vec<f64> = ints
            .iter()
            .map(|&i| (i as f64 - min) / (max - min))
            .collect();
        let _ = writeln!(
            s,
            "<text x=\"8\" y=\"{:.1}\">{}</text>",
            (lo + hi) / 2.0,
            escape(name)
        );
        let _ = writeln!(
            s,
            "<text x=\"8\" y=\"{:.1}\" fill=\"#888\">{}</text>",
            lo + 4.0,
            max as i128
        );
        if let Some(m) = mark {
            let my = hi - (hi - lo) * ((m as f64 - min) / (max - min));
            let label = rec.preset.as_ref().map(|(n, _)| *n).unwrap_or("");
            let _ = writeln!(
                s,
                "<line class=\"preset\" x1=\"{LEFT}\" y1=\"{my:.1}\" x2=\"{:.1}\" y2=\"{my:.1}\" stroke=\"#888\" stroke-dasharray=\"5,4\"/>\n\
                 <text x=\"{:.1}\" y=\"{:.1}\" fill=\"#888\" text-anchor=\"end\">{label} = {m}</text>",
                WIDTH - RIGHT,
                WIDTH - RIGHT,
                my - 3.0
            );
        }
        let _ = writeln!(
            s,
            "<polyline class=\"ramp\" data-name=\"{}\" points=\"{}\" fill=\"none\" stroke=\"#27ae60\" stroke-width=\"2\"/>",
            escape(name),
            step_points(&norm, lo, hi)
        );
        y += VALUE_LANE;
    }
    // The time axis.
    let _ = writeln!(
        s,
        "<line x1=\"{LEFT}\" y1=\"{y:.1}\" x2=\"{:.1}\" y2=\"{y:.1}\" stroke=\"black\"/>",
        WIDTH - RIGHT
    );
    let step = tick_step(t_end - t0);
    let mut t = (t0 / step).ceil() * step;
    while t <= t_end {
        let xt = x(t);
        let _ = writeln!(
            s,
            "<line x1=\"{xt:.1}\" y1=\"{y:.1}\" x2=\"{xt:.1}\" y2=\"{:.1}\" stroke=\"black\"/>\n\
             <text x=\"{xt:.1}\" y=\"{:.1}\" text-anchor=\"middle\">{}</text>",
            y + 5.0,
            y + 18.0,
            t as u64
        );
        t += step;
    }
    let unit = if rec.timed { "t [ms]" } else { "execution" };
    let _ = writeln!(
        s,
        "<text x=\"{:.1}\" y=\"{:.1}\" text-anchor=\"end\">{unit}</text>",
        WIDTH - RIGHT,
        y + 34.0
    );
    s.push_str("</svg>\n");
    s
}
