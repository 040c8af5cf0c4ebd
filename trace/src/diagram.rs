//! Timing diagrams (SVG) drawn as the manuals draw timers: the boolean inputs and outputs as
//! waveforms, the integer output (ET, BI, CV) as a ramp with a labelled value axis and the
//! preset as a dashed line, and a time axis in the unit of the block's clock (ms; ns on LTIME).
//!
//! The trace is streamed, never loaded: up to [`EXACT_ROWS`] rows are kept and drawn exactly;
//! past that, rows are folded into at most `2 x` [`COLUMNS`] time buckets (one or two per pixel
//! column) that keep, per signal, the first, last, smallest and largest value, so that no edge
//! is lost however long the trace (a 1 ms pulse in a day-long trace is a vertical bar). When a
//! row falls past the last bucket, neighbouring buckets are merged in pairs (the bucket width
//! doubles). Memory and output size are therefore bounded whatever the trace's length.

use std::fmt::Write as _;
use std::io::{Read, Write};

use plc_timers::catalog::{Port, ValueKind};

use super::engine::{observe, Columns, Observation, Observer};
use super::error::Error;
use super::family::{BlockSpec, Value};

/// Rows drawn one by one; a longer trace is drawn from buckets.
pub const EXACT_ROWS: usize = 2048;
/// The width of the SVG.
pub const WIDTH: f64 = 900.0;
const LEFT: f64 = 86.0;
const RIGHT: f64 = 18.0;
/// Pixel columns of the plot area.
pub const COLUMNS: usize = (WIDTH - LEFT - RIGHT) as usize;
const TOP: f64 = 44.0;
const BOOL_LANE: f64 = 36.0;
const VALUE_LANE: f64 = 110.0;
const AXIS: f64 = 44.0;
/// Rows up to which a light vertical line marks every execution.
const ROW_LINES: usize = 200;
/// The most lanes (boolean inputs and all outputs, and the preset).
const LANES: usize = 10;

/// Which part of the trace to draw.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct Window {
    /// Draw from this time (in the time column's unit) on; the state at that time is the one the rows before it left.
    pub from: Option<u64>,
    /// Draw up to this time (in the time column's unit); reading stops after it.
    pub to: Option<u64>,
}

/// What a drawing took.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct Stats {
    /// Rows read.
    pub rows: u64,
    /// Rows drawn (inside the window).
    pub drawn: u64,
    /// Whether every drawn row was drawn exactly (otherwise through buckets).
    pub exact: bool,
    /// The most samples or buckets held at once.
    pub held: usize,
    /// The width of a bucket in the time column's unit at the end (0 when drawn exactly).
    pub bucket_ms: u64,
}

/// One row's lane values.
#[derive(Clone, Copy, Debug)]
struct Sample {
    t: u64,
    v: [i128; LANES],
    /// Signed clock units per unit of the ramp while it runs (ET +1, BI minus its base).
    ramp: Option<i64>,
    /// The preset's literal: its index in [`Diagram::literals`].
    preset: usize,
}

/// The rows of one time bucket, per lane.
#[derive(Clone, Copy, Debug)]
struct Bucket {
    first: [i128; LANES],
    last: [i128; LANES],
    min: [(i128, u64); LANES],
    max: [(i128, u64); LANES],
}

impl Bucket {
    fn new(s: &Sample) -> Bucket {
        Bucket {
            first: s.v,
            last: s.v,
            min: s.v.map(|v| (v, s.t)),
            max: s.v.map(|v| (v, s.t)),
        }
    }

    fn add(&mut self, s: &Sample) {
        self.last = s.v;
        for k in 0..LANES {
            if s.v[k] < self.min[k].0 {
                self.min[k] = (s.v[k], s.t);
            }
            if s.v[k] > self.max[k].0 {
                self.max[k] = (s.v[k], s.t);
            }
        }
    }

    fn merge(&mut self, later: &Bucket) {
        self.last = later.last;
        for k in 0..LANES {
            if later.min[k].0 < self.min[k].0 {
                self.min[k] = later.min[k];
            }
            if later.max[k].0 > self.max[k].0 {
                self.max[k] = later.max[k];
            }
        }
    }
}

/// Buckets of `width` ms from the diagram's origin (offset 0); `None` where no row fell.
struct Buckets {
    width: u64,
    slots: Vec<Option<Bucket>>,
}

impl Buckets {
    fn new(span: u64) -> Buckets {
        let mut width = 1u64;
        while span / width >= COLUMNS as u64 {
            width *= 2;
        }
        Buckets {
            width,
            slots: vec![None; 2 * COLUMNS],
        }
    }

    /// Merges neighbours in pairs: the width doubles.
    fn halve(&mut self) {
        let n = self.slots.len();
        for i in 0..n / 2 {
            let (a, b) = (self.slots[2 * i], self.slots[2 * i + 1]);
            self.slots[i] = match (a, b) {
                (Some(mut a), Some(b)) => {
                    a.merge(&b);
                    Some(a)
                }
                (a, None) => a,
                (None, b) => b,
            };
        }
        for slot in &mut self.slots[n / 2..] {
            *slot = None;
        }
        self.width = self.width.saturating_mul(2);
    }

    fn add(&mut self, s: &Sample) {
        while s.t / self.width >= self.slots.len() as u64 {
            self.halve();
        }
        let i = (s.t / self.width) as usize;
        match &mut self.slots[i] {
            Some(b) => b.add(s),
            slot => *slot = Some(Bucket::new(s)),
        }
    }
}

/// A lane: what it draws.
#[derive(Clone, Debug)]
struct Lane {
    name: &'static str,
    kind: LaneKind,
}

#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum LaneKind {
    Input(Port),
    BoolOutput(usize),
    Ramp(usize),
}

/// The diagram under construction.
struct Diagram {
    window: Window,
    columns: Option<Columns>,
    lanes: Vec<Lane>,
    /// The lane index of the preset (after the signal lanes).
    preset_lane: usize,
    exact: Vec<Sample>,
    buckets: Option<Buckets>,
    /// The last row before the window: its values hold at the window's start.
    before: Option<Sample>,
    /// The time every drawn time is relative to (`--from`, or the first drawn row): the
    /// geometry is computed in offsets from it, which f64 resolves at any CPU time.
    origin: Option<u64>,
    /// The last drawn row's offset.
    last_t: u64,
    /// The presets' literals in the order met (each one again when it changes back).
    literals: Vec<String>,
    /// The first drawn row's preset, and whether a later drawn row has another.
    preset: Option<(usize, bool)>,
    stats: Stats,
}

impl Diagram {
    fn sample(&mut self, o: &Observation<'_>) -> Sample {
        if self.literals.last().map(String::as_str) != Some(o.preset_value) {
            self.literals.push(o.preset_value.to_string());
        }
        let mut v = [0i128; LANES];
        for (k, lane) in self.lanes.iter().enumerate() {
            v[k] = match lane.kind {
                LaneKind::Input(port) => i128::from(o.signals.get(port)),
                LaneKind::BoolOutput(i) | LaneKind::Ramp(i) => match o.outputs.as_slice()[i] {
                    Value::Bool(b) => i128::from(b),
                    Value::Int(x) => x,
                    Value::Word(w) => i128::from(w),
                },
            };
        }
        v[self.preset_lane] = o.preset;
        // ET counts up one per ms; BI counts down one per base.
        let ramp = o
            .ramp
            .map(|ms| match self.columns.as_ref().map(|c| c.block.family()) {
                Some(plc_timers::catalog::Family::S5Timer) => -(ms as i64),
                _ => ms as i64,
            });
        Sample {
            t: o.t,
            v,
            ramp,
            preset: self.literals.len() - 1,
        }
    }

    fn push(&mut self, mut s: Sample) {
        let origin = *self.origin.get_or_insert(self.window.from.unwrap_or(s.t));
        s.t -= origin;
        self.last_t = s.t;
        match &mut self.preset {
            None => self.preset = Some((s.preset, false)),
            Some((first, changes)) => {
                *changes |= self.literals[*first] != self.literals[s.preset];
            }
        }
        self.stats.drawn += 1;
        match &mut self.buckets {
            Some(b) => b.add(&s),
            None if self.exact.len() < EXACT_ROWS => self.exact.push(s),
            None => {
                let span = self.window.to.map_or(s.t, |to| to - origin);
                let mut b = Buckets::new(span);
                for e in self.exact.drain(..) {
                    b.add(&e);
                }
                b.add(&s);
                self.buckets = Some(b);
                self.exact = Vec::new();
            }
        }
        let held = self.exact.len() + self.buckets.as_ref().map_or(0, |b| b.slots.len());
        self.stats.held = self.stats.held.max(held);
    }
}

impl Observer for Diagram {
    fn start(&mut self, columns: &Columns) -> Result<(), Error> {
        for &port in &columns.inputs {
            self.lanes.push(Lane {
                name: port.name(),
                kind: LaneKind::Input(port),
            });
        }
        for (i, port) in columns.block.outputs().iter().enumerate() {
            let kind = match port.kind() {
                ValueKind::Bool => LaneKind::BoolOutput(i),
                ValueKind::Int => LaneKind::Ramp(i),
                _ => continue,
            };
            self.lanes.push(Lane {
                name: port.name(),
                kind,
            });
        }
        self.preset_lane = self.lanes.len();
        self.columns = Some(columns.clone());
        Ok(())
    }

    fn step(&mut self, o: &Observation<'_>) -> Result<bool, Error> {
        self.stats.rows += 1;
        let s = self.sample(o);
        if let Some(to) = self.window.to {
            if o.t > to {
                return Ok(false);
            }
        }
        match self.window.from {
            Some(from) if o.t < from => {
                self.before = Some(s);
                return Ok(true);
            }
            Some(from) => {
                if let Some(mut b) = self.before.take() {
                    if o.t > from {
                        b.t = from;
                        self.push(b);
                    }
                }
            }
            None => {}
        }
        self.push(s);
        Ok(true)
    }
}

/// Draws the trace read from `input` through the block of `spec` as an SVG to `out`.
pub fn svg<R: Read, W: Write>(
    spec: BlockSpec,
    preset: Option<&str>,
    input: R,
    window: Window,
    mut out: W,
) -> Result<Stats, Error> {
    let mut d = Diagram {
        window,
        columns: None,
        lanes: Vec::new(),
        preset_lane: 0,
        exact: Vec::new(),
        buckets: None,
        before: None,
        origin: None,
        last_t: 0,
        literals: Vec::new(),
        preset: None,
        stats: Stats::default(),
    };
    observe(spec, preset, input, &mut d)?;
    // A window past the trace's end still shows the state the trace left.
    if d.origin.is_none() {
        if let Some(b) = d.before.take() {
            d.push(b);
        }
    }
    d.stats.exact = d.buckets.is_none();
    d.stats.bucket_ms = d.buckets.as_ref().map_or(0, |b| b.width);
    let text = render(&d);
    out.write_all(text.as_bytes())?;
    out.flush()?;
    Ok(d.stats)
}

fn escape(text: &str) -> String {
    text.replace('&', "&amp;")
        .replace('<', "&lt;")
        .replace('>', "&gt;")
        .replace('"', "&quot;")
}

/// A "nice" step (1, 2 or 5 x 10^k) giving at most about `n` ticks over `span`.
fn tick_step(span: f64, n: f64) -> f64 {
    let raw = (span / n).max(1.0);
    let magnitude = 10f64.powf(raw.log10().floor());
    [1.0, 2.0, 5.0, 10.0]
        .into_iter()
        .map(|m| m * magnitude)
        .find(|s| *s >= raw)
        .unwrap_or(raw)
}

/// A polyline's points, mapped to the drawing and rounded to 0.1 px; a point equal to the one
/// before is left out.
struct Points<'a> {
    text: String,
    previous: (f64, f64),
    x: &'a dyn Fn(f64) -> f64,
    y: &'a dyn Fn(i128) -> f64,
}

impl<'a> Points<'a> {
    fn new(x: &'a dyn Fn(f64) -> f64, y: &'a dyn Fn(i128) -> f64) -> Points<'a> {
        Points {
            text: String::new(),
            previous: (f64::NAN, f64::NAN),
            x,
            y,
        }
    }

    fn push(&mut self, t: f64, v: i128) {
        let p = (
            ((self.x)(t) * 10.0).round() / 10.0,
            ((self.y)(v) * 10.0).round() / 10.0,
        );
        if p != self.previous {
            let _ = write!(self.text, "{:.1},{:.1} ", p.0, p.1);
            self.previous = p;
        }
    }

    fn finish(self) -> String {
        self.text.trim_end().to_string()
    }
}

/// The points of lane `k` (value `v` mapped by `y`), drawn exactly from the samples.
fn exact_points(
    samples: &[Sample],
    k: usize,
    ramp: bool,
    mut pts: Points<'_>,
    t_end: f64,
) -> String {
    let mut point = |t: f64, v: i128| pts.push(t, v);
    for (i, s) in samples.iter().enumerate() {
        if let Some(p) = i.checked_sub(1).map(|j| &samples[j]) {
            let (dt, dv) = ((s.t - p.t) as f64, s.v[k] - p.v[k]);
            match p.ramp.filter(|_| ramp) {
                // The value runs with time in its direction: a ramp, then flat once reached.
                // One unit of slack: S5 ticks fall on multiples of the base, not at the row.
                Some(rate) if dv != 0 && (dv > 0) == (rate > 0) => {
                    let unit = rate.unsigned_abs() as f64;
                    let need = (dv.unsigned_abs() as f64) * unit;
                    if need <= dt + unit {
                        point((p.t as f64 + need).min(s.t as f64), s.v[k]);
                    } else {
                        point(p.t as f64, p.v[k]);
                        point(s.t as f64, p.v[k]);
                    }
                }
                _ => point(s.t as f64, p.v[k]),
            }
        }
        point(s.t as f64, s.v[k]);
    }
    if let Some(last) = samples.last() {
        point(t_end, last.v[k]);
    }
    pts.finish()
}

/// The points of lane `k` drawn from buckets: per bucket the first value at its start, the
/// extremes in the order they occurred, the last value; booleans as steps.
fn bucket_points(b: &Buckets, k: usize, ramp: bool, mut pts: Points<'_>, t_end: f64) -> String {
    let mut point = |t: f64, v: i128| pts.push(t, v);
    let mut prev: Option<i128> = None;
    for (i, slot) in b.slots.iter().enumerate() {
        let Some(bucket) = slot else { continue };
        let start = (i as u64).saturating_mul(b.width) as f64;
        let end = (start + b.width as f64).min(t_end);
        if let Some(p) = prev {
            point(start, p);
        }
        let (first, last) = (bucket.first[k], bucket.last[k]);
        let (min, max) = (bucket.min[k], bucket.max[k]);
        let mut extremes = [min, max];
        extremes.sort_by_key(|e| e.1);
        if ramp {
            point(start, first);
            let mid = (start + end) / 2.0;
            for (v, _) in extremes {
                if v != first && v != last {
                    point(mid, v);
                }
            }
            point(end, last);
        } else {
            point(start, first);
            for (v, _) in extremes {
                point(start, v);
            }
            point(start, last);
            point(end, last);
        }
        prev = Some(last);
    }
    pts.finish()
}

fn render(d: &Diagram) -> String {
    let Some(columns) = &d.columns else {
        return String::new();
    };
    let ramps = d
        .lanes
        .iter()
        .filter(|l| matches!(l.kind, LaneKind::Ramp(_)))
        .count();
    let bools = d.lanes.len() - ramps;
    let height = TOP + bools as f64 * BOOL_LANE + ramps as f64 * VALUE_LANE + AXIS;
    // Times are offsets from the origin, so the drawing starts at 0; the labels add it back.
    let origin = d.origin.unwrap_or(0);
    let last = d
        .window
        .to
        .map_or(d.last_t as f64, |t| t.saturating_sub(origin) as f64);
    let span = last.max(1.0);
    let t_end = if d.window.to.is_some() {
        last.max(1.0)
    } else {
        last + (span * 0.08).max(1.0)
    };
    let plot = WIDTH - LEFT - RIGHT;
    let x = move |t: f64| LEFT + t / t_end * plot;
    let mut s = String::new();
    let _ = write!(
        s,
        "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"{WIDTH}\" height=\"{height}\" \
         viewBox=\"0 0 {WIDTH} {height}\" font-family=\"sans-serif\" font-size=\"12\">\n\
         <rect width=\"100%\" height=\"100%\" fill=\"white\"/>\n"
    );
    let presets: Vec<i128> = if d.buckets.is_some() {
        let b = d.buckets.as_ref().map(|b| b.slots.iter().flatten());
        b.into_iter()
            .flatten()
            .flat_map(|k| [k.min[d.preset_lane].0, k.max[d.preset_lane].0])
            .collect()
    } else {
        d.exact.iter().map(|e| e.v[d.preset_lane]).collect()
    };
    // The preset as its literal (`TV = S5T#50MS`), and where it comes from.
    let pname = columns.block.preset().port.name();
    let (label, title) = match d.preset {
        Some((p, false)) => {
            let p = &d.literals[p];
            (format!("{pname} = {p}"), format!("{pname} = {p}"))
        }
        Some((_, true)) => (pname.to_string(), format!("{pname} changes")),
        None => (pname.to_string(), String::new()),
    };
    let title = match (title.is_empty(), columns.preset_column) {
        (true, _) => columns.block.name().to_string(),
        (false, false) => format!("{}, {title}", columns.block),
        (false, true) => format!("{}, {title} (from the trace)", columns.block),
    };
    let _ = writeln!(
        s,
        "<text x=\"{LEFT}\" y=\"22\" font-size=\"15\" font-weight=\"bold\">{}</text>",
        escape(&title)
    );
    // `exact` is empty once the drawing is made of buckets.
    if d.exact.len() <= ROW_LINES {
        for e in &d.exact {
            let xt = x(e.t as f64);
            let _ = writeln!(
                s,
                "<line class=\"row\" x1=\"{xt:.1}\" y1=\"{TOP}\" x2=\"{xt:.1}\" y2=\"{:.1}\" stroke=\"#eee\"/>",
                height - AXIS
            );
        }
    }
    let points = |k: usize, ramp: bool, y: &dyn Fn(i128) -> f64| match &d.buckets {
        Some(b) => bucket_points(b, k, ramp, Points::new(&x, y), t_end),
        None => exact_points(&d.exact, k, ramp, Points::new(&x, y), t_end),
    };
    let extent = |k: usize| -> (i128, i128) {
        match &d.buckets {
            Some(b) => b.slots.iter().flatten().fold((0, 1), |(lo, hi), bk| {
                (lo.min(bk.min[k].0), hi.max(bk.max[k].0))
            }),
            None => d
                .exact
                .iter()
                .fold((0, 1), |(lo, hi), e| (lo.min(e.v[k]), hi.max(e.v[k]))),
        }
    };
    let mut y = TOP;
    for (k, lane) in d.lanes.iter().enumerate() {
        let name = escape(lane.name);
        match lane.kind {
            LaneKind::Input(_) | LaneKind::BoolOutput(_) => {
                let (lo, hi) = (y + BOOL_LANE - 8.0, y + 6.0);
                let color = if matches!(lane.kind, LaneKind::Input(_)) {
                    "#1f4e79"
                } else {
                    "#c0392b"
                };
                let yv = move |v: i128| if v != 0 { hi } else { lo };
                let _ = writeln!(s, "<text x=\"8\" y=\"{:.1}\">{name}</text>", lo - 4.0);
                let _ = writeln!(
                    s,
                    "<polyline class=\"signal\" data-name=\"{name}\" points=\"{}\" fill=\"none\" stroke=\"{color}\" stroke-width=\"2\"/>",
                    points(k, false, &yv)
                );
                y += BOOL_LANE;
            }
            LaneKind::Ramp(_) => {
                let (lo_v, hi_v) = extent(k);
                let (plo, phi) = extent(d.preset_lane);
                // Both extents span at least 0..=1, so `hi_v > lo_v`.
                let (lo_v, hi_v) = (lo_v.min(plo), hi_v.max(phi));
                let (lo, hi) = (y + VALUE_LANE - 14.0, y + 12.0);
                let scale =
                    move |v: i128| lo - (lo - hi) * ((v - lo_v) as f64 / (hi_v - lo_v) as f64);
                let _ = writeln!(
                    s,
                    "<text x=\"8\" y=\"{:.1}\" font-weight=\"bold\">{name}</text>",
                    (lo + hi) / 2.0
                );
                // The value axis: a vertical line with nice ticks and labels.
                let _ = writeln!(
                    s,
                    "<line class=\"value-axis\" x1=\"{LEFT}\" y1=\"{hi:.1}\" x2=\"{LEFT}\" y2=\"{lo:.1}\" stroke=\"black\"/>"
                );
                let step = tick_step((hi_v - lo_v) as f64, 4.0) as i128;
                let mut v = lo_v.div_euclid(step.max(1)) * step.max(1);
                while v <= hi_v {
                    if v >= lo_v {
                        let yv = scale(v);
                        let _ = writeln!(
                            s,
                            "<line x1=\"{:.1}\" y1=\"{yv:.1}\" x2=\"{LEFT}\" y2=\"{yv:.1}\" stroke=\"black\"/>\
                             <text class=\"tick\" x=\"{:.1}\" y=\"{:.1}\" text-anchor=\"end\" fill=\"#555\">{v}</text>",
                            LEFT - 4.0,
                            LEFT - 6.0,
                            yv + 4.0
                        );
                    }
                    v += step.max(1);
                }
                let py = presets.last().map_or(lo, |p| scale(*p));
                let _ = writeln!(
                    s,
                    "<polyline class=\"preset\" data-name=\"{pname}\" points=\"{}\" fill=\"none\" stroke=\"#888\" stroke-dasharray=\"5,4\"/>\n\
                     <text x=\"{:.1}\" y=\"{:.1}\" fill=\"#888\" text-anchor=\"end\">{}</text>",
                    points(d.preset_lane, false, &scale),
                    WIDTH - RIGHT,
                    py - 4.0,
                    escape(&label)
                );
                let _ = writeln!(
                    s,
                    "<polyline class=\"ramp\" data-name=\"{name}\" points=\"{}\" fill=\"none\" stroke=\"#27ae60\" stroke-width=\"2\"/>",
                    points(k, true, &scale)
                );
                y += VALUE_LANE;
            }
        }
    }
    // The time axis.
    let _ = writeln!(
        s,
        "<line x1=\"{LEFT}\" y1=\"{y:.1}\" x2=\"{:.1}\" y2=\"{y:.1}\" stroke=\"black\"/>",
        WIDTH - RIGHT
    );
    let step = tick_step(t_end, 8.0);
    // Ticks on whole multiples of the step in absolute time, at most a dozen.
    let step_ms = (step as u64).max(1);
    let first = (origin.div_ceil(step_ms).saturating_mul(step_ms) - origin) as f64;
    for t in (0..12).map(|k| first + f64::from(k) * step_ms as f64) {
        if t > t_end {
            break;
        }
        let xt = x(t);
        let _ = writeln!(
            s,
            "<line x1=\"{xt:.1}\" y1=\"{y:.1}\" x2=\"{xt:.1}\" y2=\"{:.1}\" stroke=\"black\"/>\n\
             <text x=\"{xt:.1}\" y=\"{:.1}\" text-anchor=\"middle\">{}</text>",
            y + 5.0,
            y + 18.0,
            origin.saturating_add(t as u64)
        );
    }
    let unit = if columns.timed {
        format!("t [{}]", columns.unit)
    } else {
        "row".to_string()
    };
    let _ = writeln!(
        s,
        "<text x=\"{:.1}\" y=\"{:.1}\" text-anchor=\"end\">{unit}</text>",
        WIDTH - RIGHT,
        y + 36.0
    );
    s.push_str("</svg>\n");
    s
}
