//! The trace engine: the header resolved once against the catalog into column indices, typed
//! rows, and the three ways a trace is consumed: [`run`] (write the reference outputs),
//! [`check`] (compare another implementation's outputs) and [`observe`] (hand each step to a
//! diagram or a VCD writer). All three are written once, generic over the core's
//! [`BlockOps`], for the instance [`BlockSpec::visit`] chooses.

use std::fmt;
use std::io::{Read, Write};

use plc_timers::block::{BlockOps, Family, Visit};
use plc_timers::catalog::{Block, Port, ValueKind};
use plc_timers::time::CpuTime;

use super::error::{show, Error, Location, TraceError};
use super::family::{names_of, parse_preset, BlockSpec, Outputs, Signals, Value, TIME_COLUMNS};
use super::reader::{Reader, Record};
use plc_timers::rule::{RuleSet, MAX_OUTPUTS as RULE_OUTPUTS};

/// The unit of a clock (`ms`, `ns`) in words, as messages write it.
fn unit_words(unit: &str) -> &'static str {
    match unit {
        "ns" => "nanoseconds",
        _ => "milliseconds",
    }
}

/// The option that gives `block`'s preset on the command line (without the dashes), also the
/// Python keyword argument: the preset input's name lower-cased (`tv`, `pt`, `pv`).
///
/// ```
/// use plc_timers::catalog::Block;
/// assert_eq!(plc_timers_trace::preset_option(Block::SOdt), "tv");
/// assert_eq!(plc_timers_trace::preset_option(Block::Ctud), "pv");
/// ```
pub fn preset_option(block: Block) -> &'static str {
    // Lower-cased once per port, so that the name is `'static` like the port's own and a
    // caller that asks per call allocates nothing.
    static OPTIONS: std::sync::OnceLock<Vec<(Port, String)>> = std::sync::OnceLock::new();
    let port = block.preset().port;
    OPTIONS
        .get_or_init(|| {
            Port::ALL
                .iter()
                .map(|p| (*p, p.name().to_ascii_lowercase()))
                .collect()
        })
        .iter()
        .find(|(p, _)| *p == port)
        .map(|(_, option)| option.as_str())
        .expect("Port::ALL holds every port")
}

/// How many rows before a difference `check` shows.
pub const CONTEXT_ROWS: usize = 3;

/// The most bytes of a row's text that `check` keeps for its context.
const CONTEXT_TEXT: usize = 72;

/// Output is handed to the writer in pieces of about this size.
const OUT_BUFFER: usize = 64 << 10;

/// What the trace is read for: which columns the header may have.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum Mode {
    /// Inputs only (`run`, `diagram`, `vcd`).
    Inputs,
    /// Inputs and outputs (`check`).
    WithOutputs,
}

/// The header, resolved against the catalog: which column carries what.
struct Layout {
    /// The header's names as written (trimmed).
    names: Vec<String>,
    /// The time column's name (`t_ms`, `t_ns` on LTIME).
    time_name: &'static str,
    /// The column of the time.
    time: Option<usize>,
    /// Each boolean input column and its input.
    bools: Vec<(usize, Port)>,
    /// The column of the preset.
    preset: Option<usize>,
    /// Each output column and its catalog index (check).
    outputs: Vec<(usize, usize)>,
    /// The header's line.
    line: u64,
}

fn utf8_cell<'a>(rec: &Record<'a>, i: usize) -> Result<&'a str, TraceError> {
    std::str::from_utf8(rec.cell(i)).map_err(|_| {
        TraceError::cell(
            rec.line(),
            i + 1,
            &format!("field {}", i + 1),
            format!(
                "`{}` is not UTF-8 text; traces are UTF-8",
                show(rec.cell(i))
            ),
        )
    })
}

impl Layout {
    fn resolve(spec: BlockSpec, header: &Record<'_>, mode: Mode) -> Result<Layout, TraceError> {
        let block = spec.block();
        let time_name = spec.time_column();
        let mut layout = Layout {
            names: Vec::with_capacity(header.len()),
            time_name,
            time: None,
            bools: Vec::new(),
            preset: None,
            outputs: Vec::new(),
            line: header.line(),
        };
        let mut seen_inputs = 0u32;
        for i in 0..header.len() {
            let name = utf8_cell(header, i)?;
            let here = |message: String| TraceError::cell(header.line(), i + 1, name, message);
            let input = block
                .inputs()
                .iter()
                .position(|p| p.name().eq_ignore_ascii_case(name));
            let output = block
                .outputs()
                .iter()
                .position(|p| p.name().eq_ignore_ascii_case(name));
            // A coil (RT) is read as a boolean input; its bit follows the inputs'.
            let coil = block
                .coils()
                .iter()
                .position(|p| p.name().eq_ignore_ascii_case(name));
            let duplicate = if name.eq_ignore_ascii_case(time_name) {
                layout.time.replace(i).is_some()
            } else if let Some(other) = TIME_COLUMNS
                .into_iter()
                .find(|t| t.eq_ignore_ascii_case(name))
            {
                // The other unit's time column: the trace was written for another data type.
                return Err(here(format!(
                    "`{name}` is a time in {}; {block} on {} counts its time in {} \
                     (`{time_name}`), so its columns are {}",
                    unit_words(&other[2..]),
                    spec.data_type(),
                    unit_words(spec.instruction.clock_unit()),
                    columns(block, time_name, mode)
                )));
            } else if let Some(k) = input {
                let again = seen_inputs >> k & 1 == 1;
                seen_inputs |= 1 << k;
                let port = block.inputs()[k];
                match port.kind() {
                    ValueKind::Bool => layout.bools.push((i, port)),
                    _ => layout.preset = Some(i),
                }
                again
            } else if let Some(k) = coil {
                let bit = block.inputs().len() + k;
                let again = seen_inputs >> bit & 1 == 1;
                seen_inputs |= 1 << bit;
                layout.bools.push((i, block.coils()[k]));
                again
            } else if let (Some(k), Mode::WithOutputs) = (output, mode) {
                let again = layout.outputs.iter().any(|&(_, o)| o == k);
                layout.outputs.push((i, k));
                again
            } else if output.is_some() {
                return Err(here(format!(
                    "`{name}` is an output of {block}; this command reads inputs only \
                     (`plc-timers check` compares outputs)"
                )));
            } else if let Some(port) = coil_elsewhere(name) {
                return Err(here(format!(
                    "`{}` is the {} coil, which only {} have; {block} takes the columns {}",
                    port.name(),
                    coil_form(port),
                    names_of(|b| b.coils().contains(&port)).replace(' ', ", "),
                    columns(block, time_name, mode)
                )));
            } else {
                return Err(here(format!(
                    "unknown column `{}`; {block} takes the columns {}",
                    show(name.as_bytes()),
                    columns(block, time_name, mode)
                )));
            };
            if duplicate {
                return Err(here(format!("column `{name}` appears twice")));
            }
            layout.names.push(name.to_string());
        }
        if block.requires_time() && layout.time.is_none() {
            return Err(TraceError::new(
                Location::Line(layout.line),
                format!(
                    "{block} is a timer: the header needs a `{time_name}` column; the header is `{}`",
                    show(header.raw())
                ),
            ));
        }
        Ok(layout)
    }
}

/// The coil of some block of the catalog named `name` (ASCII case ignored).
fn coil_elsewhere(name: &str) -> Option<Port> {
    Block::ALL
        .iter()
        .flat_map(|b| b.coils())
        .copied()
        .find(|p| p.name().eq_ignore_ascii_case(name))
}

/// How the manuals write a coil in LAD: `-(RT)-`.
fn coil_form(port: Port) -> String {
    format!("-({})-", port.name())
}

/// The columns `block`'s traces may have, as a message lists them.
fn columns(block: Block, time_name: &'static str, mode: Mode) -> String {
    let mut names = vec![time_name];
    names.extend(block.inputs().iter().map(|p| p.name()));
    names.extend(block.coils().iter().map(|p| p.name()));
    if mode == Mode::WithOutputs {
        names.extend(block.outputs().iter().map(|p| p.name()));
    }
    names.join(", ")
}

/// Parses a boolean cell: `0`, `1`, `true`, `false` (ASCII case ignored).
pub fn parse_bool(cell: &[u8]) -> Option<bool> {
    match cell {
        b"1" => Some(true),
        b"0" => Some(false),
        t if t.eq_ignore_ascii_case(b"true") => Some(true),
        t if t.eq_ignore_ascii_case(b"false") => Some(false),
        _ => None,
    }
}

/// Parses a whole number (of the clock's units), 0..=u64::MAX.
#[inline(always)]
pub fn parse_u64(cell: &[u8]) -> Option<u64> {
    if cell.is_empty() || cell.len() > 20 {
        return None;
    }
    if cell.len() < 20 {
        // At most 19 digits: below 10^19 < 2^64, so no overflow is possible.
        let mut v: u64 = 0;
        for &b in cell {
            let d = b.wrapping_sub(b'0');
            if d > 9 {
                return None;
            }
            v = v * 10 + u64::from(d);
        }
        return Some(v);
    }
    let mut v: u64 = 0;
    for &b in cell {
        let d = b.wrapping_sub(b'0');
        if d > 9 {
            return None;
        }
        v = v.checked_mul(10)?.checked_add(u64::from(d))?;
    }
    Some(v)
}

/// Parses an output cell of another implementation as a value of `kind`: a boolean as
/// [`parse_bool`], an integer in decimal, a word as `W#16#` and 1 to 4 hex digits or decimal.
/// `None` is a cell that is no such value; the caller names its line and column.
///
/// ```
/// use plc_timers::catalog::ValueKind;
/// use plc_timers_trace::{parse_value, Value};
///
/// assert_eq!(parse_value(ValueKind::Bool, b"TRUE"), Some(Value::Bool(true)));
/// assert_eq!(parse_value(ValueKind::Int, b"-7"), Some(Value::Int(-7)));
/// assert_eq!(parse_value(ValueKind::Word, b"W#16#0123"), Some(Value::Word(0x0123)));
/// assert_eq!(parse_value(ValueKind::Bool, b"2"), None);
/// ```
#[inline(always)]
pub fn parse_value(kind: ValueKind, cell: &[u8]) -> Option<Value> {
    match kind {
        ValueKind::Bool => return parse_bool(cell).map(Value::Bool),
        ValueKind::Int if !cell.is_empty() && cell.len() <= 18 => {
            let (negative, digits) = match cell {
                [b'-', rest @ ..] => (true, rest),
                [b'+', rest @ ..] => (false, rest),
                _ => (false, cell),
            };
            let v = i128::from(parse_u64(digits)?);
            return Some(Value::Int(if negative { -v } else { v }));
        }
        _ => {}
    }
    let text = std::str::from_utf8(cell).ok()?;
    match kind {
        ValueKind::Bool => None,
        ValueKind::Word => {
            let hex = text
                .get(..5)
                .filter(|p| p.eq_ignore_ascii_case("W#16#"))
                .map(|_| &text[5..]);
            match hex {
                Some(h)
                    if (1..=4).contains(&h.len()) && h.bytes().all(|b| b.is_ascii_hexdigit()) =>
                {
                    u16::from_str_radix(h, 16).ok().map(Value::Word)
                }
                Some(_) => None,
                None => text.parse::<u16>().ok().map(Value::Word),
            }
        }
        ValueKind::Int | ValueKind::Preset => text.parse::<i128>().ok().map(Value::Int),
    }
}

/// What a message says a value of `kind` may be.
fn allowed(kind: ValueKind) -> &'static str {
    match kind {
        ValueKind::Bool => "0, 1, true or false",
        ValueKind::Word => "W#16# and 1 to 4 hexadecimal digits, or 0..65535",
        _ => "a whole number in decimal",
    }
}

/// Appends `v` as the trace format writes it.
#[inline]
fn write_value(out: &mut Vec<u8>, v: Value) {
    match v {
        Value::Bool(b) => out.push(if b { b'1' } else { b'0' }),
        Value::Int(i) if (0..10).contains(&i) => out.push(b'0' + i as u8),
        Value::Int(i) => {
            let mut buf = itoa::Buffer::new();
            match u64::try_from(i) {
                Ok(small) => out.extend_from_slice(buf.format(small).as_bytes()),
                Err(_) => out.extend_from_slice(buf.format(i).as_bytes()),
            }
        }
        Value::Word(w) => {
            const HEX: &[u8; 16] = b"0123456789ABCDEF";
            out.extend_from_slice(b"W#16#");
            for shift in [12, 8, 4, 0] {
                out.push(HEX[usize::from(w >> shift & 0xF)]);
            }
        }
    }
}

/// One executed row.
struct Row<B: BlockOps> {
    /// The time column's value, or the row's index (0-based) when the trace has none.
    t: u64,
    signals: Signals,
    preset: B::Preset,
    output: B::Output,
    /// With [`Engine::explain`]: the rules that decided each output (catalog order), the
    /// rules that acted on the state, and the outputs the call wrote (bit per output).
    rules: Option<([RuleSet; RULE_OUTPUTS], RuleSet, u8)>,
}

/// A block instance with its resolved header, driven row by row.
struct Engine<B: BlockOps> {
    block: B,
    kind: B::Kind,
    spec: BlockSpec,
    layout: Layout,
    /// The preset of the command line, parsed once.
    option: Option<B::Preset>,
    /// The last preset cell's text and value: a preset column is parsed again only when it
    /// changes.
    cached: Option<(Vec<u8>, B::Preset)>,
    last: u64,
    rows: u64,
    /// Whether each call is explained ([`BlockOps::step_explained`]).
    explain: bool,
}

impl<B: BlockOps> Engine<B> {
    fn new(
        (block_ops, kind, spec): (B, B::Kind, BlockSpec),
        header: &Record<'_>,
        mode: Mode,
        preset: Option<&str>,
    ) -> Result<Engine<B>, TraceError> {
        let block = spec.block();
        let layout = Layout::resolve(spec, header, mode)?;
        let p = block.preset();
        let option = preset
            .map(parse_preset::<B>)
            .transpose()
            .map_err(|e| TraceError::new(Location::Option(preset_option(block)), e))?;
        if let (None, None) = (layout.preset, option) {
            return Err(TraceError::new(
                Location::Line(layout.line),
                format!(
                    "{block} needs its preset: a `{}` column or the option --{}",
                    p.port.name(),
                    preset_option(block)
                ),
            ));
        }
        Ok(Engine {
            block: block_ops,
            kind,
            spec,
            layout,
            option,
            cached: None,
            last: 0,
            rows: 0,
            explain: false,
        })
    }

    fn cell_error(&self, rec: &Record<'_>, i: usize, message: String) -> TraceError {
        TraceError::cell(rec.line(), i + 1, &self.layout.names[i], message)
    }

    /// Reads `rec`'s inputs and executes the block once.
    #[inline(always)]
    fn step(&mut self, rec: &Record<'_>) -> Result<Row<B>, Box<TraceError>> {
        let width = self.layout.names.len();
        if rec.len() != width {
            return Err(Box::new(self.width_error(rec)));
        }
        let t = match self.layout.time {
            Some(i) => {
                let cell = rec.cell(i);
                let Some(t) = parse_u64(cell) else {
                    return Err(Box::new(self.cell_error(
                        rec,
                        i,
                        format!(
                            "`{}` is not a time; {} is a whole number of {}, 0..={}",
                            show(cell),
                            self.layout.time_name,
                            unit_words(self.spec.instruction.clock_unit()),
                            u64::MAX
                        ),
                    )));
                };
                // `last` starts at 0, so the first row cannot go backwards.
                if t < self.last {
                    return Err(Box::new(self.cell_error(
                        rec,
                        i,
                        format!(
                            "{} goes backwards: {t} after {}; time must not decrease",
                            self.layout.time_name, self.last
                        ),
                    )));
                }
                t
            }
            None => self.rows,
        };
        let mut signals = Signals::NONE;
        for &(i, port) in &self.layout.bools {
            match parse_bool(rec.cell(i)) {
                Some(true) => signals = signals.with(port),
                Some(false) => {}
                None => {
                    return Err(Box::new(self.cell_error(
                        rec,
                        i,
                        format!(
                            "`{}` is not a boolean; use 0, 1, true or false",
                            show(rec.cell(i))
                        ),
                    )))
                }
            }
        }
        let preset = match (self.layout.preset, self.option) {
            (Some(i), _) => self.preset_cell(rec, i)?,
            (None, Some(p)) => p,
            // The header check makes sure one of the two exists.
            (None, None) => {
                return Err(Box::new(TraceError::new(
                    Location::Line(rec.line()),
                    "no preset",
                )));
            }
        };
        let now = CpuTime::from_ticks(t);
        let (output, rules) = if self.explain {
            let e = self.block.step_explained(self.kind, now, signals, preset);
            (e.output, Some((e.outputs, e.state, e.written)))
        } else {
            (self.block.step(self.kind, now, signals, preset), None)
        };
        self.last = t;
        self.rows += 1;
        Ok(Row {
            t,
            signals,
            preset,
            output,
            rules,
        })
    }

    fn preset_cell(&mut self, rec: &Record<'_>, i: usize) -> Result<B::Preset, Box<TraceError>> {
        let cell = rec.cell(i);
        if let Some((text, value)) = &self.cached {
            if text.as_slice() == cell {
                return Ok(*value);
            }
        }
        let text = std::str::from_utf8(cell)
            .map_err(|_| self.cell_error(rec, i, format!("`{}` is not UTF-8 text", show(cell))))?;
        let value = parse_preset::<B>(text)
            .map_err(|e| self.cell_error(rec, i, format!("`{}`: {e}", show(cell))))?;
        let (buf, v) = self.cached.get_or_insert_with(|| (Vec::new(), value));
        buf.clear();
        buf.extend_from_slice(cell);
        *v = value;
        Ok(value)
    }

    fn width_error(&self, rec: &Record<'_>) -> TraceError {
        let width = self.layout.names.len();
        let header = self.layout.names.join(",");
        let expected = format!(
            "the header (line {}) has {width}: {}",
            self.layout.line,
            show(header.as_bytes())
        );
        if rec.len() > width {
            TraceError::new(
                Location::Cell {
                    line: rec.line(),
                    column: width + 1,
                    name: "beyond the header".into(),
                },
                format!("the row has {} fields but {expected}", rec.len()),
            )
        } else {
            TraceError::cell(
                rec.line(),
                rec.len() + 1,
                &self.layout.names[rec.len()],
                format!("the row has {} field(s) but {expected}", rec.len()),
            )
        }
    }
}

fn empty() -> TraceError {
    TraceError::new(
        Location::Line(1),
        "the trace is empty: it needs a header row (e.g. `t_ms,IN`; `t_ns,IN` on LTIME)",
    )
}

// ---------------------------------------------------------------------------------------------
// run

/// Runs the trace read from `input` through the block of `spec` and writes the trace to
/// `output`: each record as written (line ends made LF), then the block's outputs. Rows are
/// written as they are computed: when a row is bad input, the rows before it have been written
/// (and flushed) and the error is returned. Returns the number of data rows.
pub fn run<R: Read, W: Write>(
    spec: BlockSpec,
    preset: Option<&str>,
    input: R,
    output: W,
) -> Result<u64, Error> {
    spec.visit(V(spec, preset, input, output, false))
}

/// [`run`] with one more column, `rules`: the IDs of the requirements that decided the row's
/// outputs (the reference's explanation, [`plc_timers::rule::Explained`]), separated by
/// blanks, in catalog order (`plc-timers run --explain`). The optimized implementation gives
/// no rules: its column is empty.
pub fn run_explained<R: Read, W: Write>(
    spec: BlockSpec,
    preset: Option<&str>,
    input: R,
    output: W,
) -> Result<u64, Error> {
    spec.visit(V(spec, preset, input, output, true))
}

struct V<'a, R, W>(BlockSpec, Option<&'a str>, R, W, bool);

impl<R: Read, W: Write> Visit for V<'_, R, W> {
    type Out = Result<u64, Error>;
    fn visit<B: BlockOps>(self, block: B, kind: B::Kind) -> Self::Out {
        run_block((block, kind, self.0), self.1, self.2, self.3, self.4)
    }
}

/// The name of the column `run --explain` adds.
pub const RULES_COLUMN: &str = "rules";

fn run_block<B: BlockOps, R: Read, W: Write>(
    block: (B, B::Kind, BlockSpec),
    preset: Option<&str>,
    input: R,
    mut output: W,
    explain: bool,
) -> Result<u64, Error> {
    let mut reader = Reader::new(input);
    let header = reader.next_record()?.ok_or_else(empty)?;
    let mut engine = Engine::new(block, &header, Mode::Inputs, preset)?;
    engine.explain = explain;
    let outputs = engine.spec.block().outputs();
    let n_outputs = outputs.len();
    let mut out: Vec<u8> = Vec::with_capacity(OUT_BUFFER + 1024);
    out.extend_from_slice(header.raw());
    for p in outputs {
        out.push(b',');
        out.extend_from_slice(p.name().as_bytes());
    }
    if explain {
        out.push(b',');
        out.extend_from_slice(RULES_COLUMN.as_bytes());
    }
    out.push(b'\n');
    let result = loop {
        let rec = match reader.next_record() {
            Ok(Some(rec)) => rec,
            Ok(None) => break Ok(()),
            Err(e) => break Err(*e),
        };
        let row = match engine.step(&rec) {
            Ok(row) => row,
            Err(e) => break Err(*e),
        };
        out.extend_from_slice(rec.raw());
        for &v in B::values(engine.kind, &row.output).as_slice() {
            out.push(b',');
            write_value(&mut out, v);
        }
        if let Some((outputs, _, _)) = row.rules {
            out.push(b',');
            let all = outputs[..n_outputs]
                .iter()
                .fold(RuleSet::EMPTY, |a, o| a.union(*o));
            for (k, rule) in all.iter().enumerate() {
                if k > 0 {
                    out.push(b' ');
                }
                out.extend_from_slice(rule.id().as_bytes());
            }
        }
        out.push(b'\n');
        if out.len() >= OUT_BUFFER {
            output.write_all(&out)?;
            out.clear();
        }
    };
    output.write_all(&out)?;
    output.flush()?;
    result?;
    Ok(engine.rows)
}

// ---------------------------------------------------------------------------------------------
// check

/// A row shown before a difference.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct ContextRow {
    /// Its line.
    pub line: u64,
    /// Its text as written (cut after about 70 characters).
    pub text: String,
    /// The reference's values of the compared outputs at that row.
    pub reference: Vec<(&'static str, Value)>,
}

/// Why the reference gives its value at a difference, from the core's explanation
/// ([`plc_timers::rule::Explained`]).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Why {
    /// The rules that determined the output at the row, whether its value changed or stayed
    /// (empty when no rule's premise bears on it there: it kept the value of an earlier row).
    pub rules: RuleSet,
    /// The earlier row: the latest row before this one whose call wrote the output (a rule's
    /// action there set the state it is read from: a start, a set, a tick, R), with the rules
    /// that determined the output there, and, when this row's call wrote the output too (its
    /// action started from the state that row left), the rules that acted on the state there.
    /// No row between them wrote it, so the output's value before this row is the one those
    /// rules gave (kept since by the rules named at the rows between); `None` when no earlier
    /// row wrote it (its initial value).
    pub earlier: Option<(u64, RuleSet)>,
    /// Whether the implementation explains its calls (the optimized forms do not: check
    /// against the reference, without `--optimized`, to see the rules).
    pub explained: bool,
}

impl Why {
    /// Every rule named: at the row and at the earlier row.
    pub fn all(&self) -> RuleSet {
        self.rules
            .union(self.earlier.map_or(RuleSet::EMPTY, |(_, r)| r))
    }
}

/// The first place where a trace's outputs differ from the reference, and why the reference
/// gives its value there.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Difference {
    /// The line of the row.
    pub line: u64,
    /// The column (1-based).
    pub column: usize,
    /// The output's catalog name.
    pub output: &'static str,
    /// What the reference computes.
    pub expected: Value,
    /// What the trace has (its cell, trimmed).
    pub found: String,
    /// The requirements that decide the reference's value there, and what happened.
    pub why: Why,
    /// Up to [`CONTEXT_ROWS`] rows before it, then the row itself.
    pub context: Vec<ContextRow>,
}

impl fmt::Display for Difference {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        writeln!(
            f,
            "DIFFERENT at line {}, column {} ({}): the reference gives {}, the trace has {}",
            self.line, self.column, self.output, self.expected, self.found
        )?;
        let why = &self.why;
        if !why.explained {
            writeln!(
                f,
                "(the optimized implementation gives no rules: check without --optimized to \
                 see the requirements that decide this value)"
            )?;
        } else if why.rules.is_empty() {
            writeln!(
                f,
                "no rule acted on {} at this row: it keeps its value from earlier rows",
                self.output
            )?;
        } else {
            writeln!(f, "decided at this row by:")?;
        }
        for rule in why.rules {
            writeln!(f, "{rule}: {}", rule.text())?;
        }
        if let Some((line, rules)) = why.earlier {
            writeln!(f, "after line {line}, where these acted and still matter:")?;
            // The rules named at the row already are not repeated.
            for rule in rules.difference(why.rules) {
                writeln!(f, "{rule}: {}", rule.text())?;
            }
        }
        writeln!(f, "rows up to it, with the reference's outputs:")?;
        let width = self
            .context
            .iter()
            .map(|r| r.text.chars().count())
            .max()
            .unwrap_or(0);
        for (k, row) in self.context.iter().enumerate() {
            let mark = if k + 1 == self.context.len() {
                '>'
            } else {
                ' '
            };
            let text = &row.text;
            let pad = width - text.chars().count();
            write!(f, "{mark} line {:<6} {text}{:pad$}  |", row.line, "")?;
            for (name, v) in &row.reference {
                write!(f, " {name}={v}")?;
            }
            writeln!(f)?;
        }
        Ok(())
    }
}

/// The result of [`check`].
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct CheckReport {
    /// The block.
    pub block: Block,
    /// The data rows read (up to and including the first difference).
    pub rows: u64,
    /// The outputs compared.
    pub compared: Vec<&'static str>,
    /// The first difference, if any.
    pub difference: Option<Difference>,
}

/// Compares the outputs of a trace (another implementation's) with the reference's, row by
/// row, up to the first difference. `outputs` restricts the comparison to those outputs (names
/// of the block's outputs, ASCII case ignored); by default every output of the block is
/// compared and the trace must have a column for each. A malformed output cell is bad input.
pub fn check<R: Read>(
    spec: BlockSpec,
    preset: Option<&str>,
    outputs: Option<&[&str]>,
    input: R,
) -> Result<CheckReport, TraceError> {
    struct V<'a, R>(BlockSpec, Option<&'a str>, Option<&'a [&'a str]>, R);
    impl<R: Read> Visit for V<'_, R> {
        type Out = Result<CheckReport, TraceError>;
        fn visit<B: BlockOps>(self, block: B, kind: B::Kind) -> Self::Out {
            check_block((block, kind, self.0), self.1, self.2, self.3)
        }
    }
    spec.visit(V(spec, preset, outputs, input))
}

/// The catalog indices of the outputs to compare.
fn chosen_outputs(block: Block, outputs: Option<&[&str]>) -> Result<Vec<usize>, TraceError> {
    let all = block.outputs();
    let Some(names) = outputs else {
        return Ok((0..all.len()).collect());
    };
    let list: Vec<&str> = all.iter().map(|p| p.name()).collect();
    let mut chosen = Vec::new();
    for name in names {
        let i = all
            .iter()
            .position(|p| p.name().eq_ignore_ascii_case(name.trim()))
            .ok_or_else(|| {
                TraceError::new(
                    Location::Option("outputs"),
                    format!(
                        "`{}` is not an output of {block}; its outputs are {}",
                        show(name.as_bytes()),
                        list.join(",")
                    ),
                )
            })?;
        if !chosen.contains(&i) {
            chosen.push(i);
        }
    }
    if chosen.is_empty() {
        return Err(TraceError::new(
            Location::Option("outputs"),
            format!("no output named; {block}'s outputs are {}", list.join(",")),
        ));
    }
    Ok(chosen)
}

/// The values of the `compared` (column, output) cells of a row's text, as far as they can be
/// read back.
fn values_of(block: Block, compared: &[(usize, usize)], text: &[u8]) -> Vec<(&'static str, Value)> {
    let mut reader = Reader::new(text);
    let Ok(Some(rec)) = reader.next_record() else {
        return Vec::new();
    };
    compared
        .iter()
        .filter_map(|&(column, o)| {
            let port = block.outputs()[o];
            parse_value(port.kind(), rec.cell(column)).map(|v| (port.name(), v))
        })
        .collect()
}

fn check_block<B: BlockOps, R: Read>(
    instance: (B, B::Kind, BlockSpec),
    preset: Option<&str>,
    outputs: Option<&[&str]>,
    input: R,
) -> Result<CheckReport, TraceError> {
    let block = instance.2.block();
    let chosen = chosen_outputs(block, outputs)?;
    let mut reader = Reader::new(input);
    let header = reader.next_record()?.ok_or_else(empty)?;
    let mut engine = Engine::new(instance, &header, Mode::WithOutputs, preset)?;
    engine.explain = true;
    let explained = B::EXPLAINS;
    // Per output (catalog order), the latest row whose call wrote it: its line, the rules that
    // determined the output there and those that acted on the state there.
    let mut wrote: [Option<(u64, RuleSet, RuleSet)>; RULE_OUTPUTS] = [None; RULE_OUTPUTS];
    // The compared columns: (column, output index), in the order of the catalog.
    let mut compared = Vec::with_capacity(chosen.len());
    for &o in &chosen {
        let port = block.outputs()[o];
        match engine.layout.outputs.iter().find(|&&(_, k)| k == o) {
            Some(&(column, _)) => compared.push((column, o)),
            None => {
                let names: Vec<&str> = block.outputs().iter().map(|p| p.name()).collect();
                return Err(TraceError::new(
                    Location::Line(engine.layout.line),
                    format!(
                        "the trace has no `{}` column; {block}'s outputs are {} (compare fewer \
                         with --outputs, e.g. --outputs {})",
                        port.name(),
                        names.join(","),
                        names[0]
                    ),
                ));
            }
        }
    }
    let mut report = CheckReport {
        block,
        rows: 0,
        compared: compared
            .iter()
            .map(|&(_, o)| block.outputs()[o].name())
            .collect(),
        difference: None,
    };
    let mut found = [Value::Bool(false); super::family::MAX_OUTPUTS];
    let kinds: Vec<ValueKind> = compared
        .iter()
        .map(|&(_, o)| block.outputs()[o].kind())
        .collect();
    while let Some(rec) = reader.next_record()? {
        let row = engine.step(&rec).map_err(|e| *e)?;
        let values = B::values(engine.kind, &row.output);
        for (k, &(column, o)) in compared.iter().enumerate() {
            let kind = kinds[k];
            let cell = rec.cell(column);
            let Some(value) = parse_value(kind, cell) else {
                return Err(engine.cell_error(
                    &rec,
                    column,
                    format!(
                        "`{}` is not a valid {} output; it is {}",
                        show(cell),
                        block.outputs()[o].name(),
                        allowed(kind)
                    ),
                ));
            };
            found[k] = value;
        }
        report.rows += 1;
        let differing = compared
            .iter()
            .enumerate()
            .find(|&(k, &(_, o))| found[k] != values.as_slice()[o]);
        let (outputs, state, written) = row.rules.unwrap_or_default();
        if let Some((_, &(column, o))) = differing {
            // When this row's action wrote the output, it started from the state the earlier
            // row left: the rules that acted on that state there matter too (a set whose
            // cleared memory lets a held input count here, though R decided CV there).
            let earlier = wrote.get(o).copied().flatten().map(|(line, rules, acted)| {
                (
                    line,
                    if written & (1 << o) != 0 {
                        rules.union(acted)
                    } else {
                        rules
                    },
                )
            });
            let why = Why {
                rules: outputs[o],
                earlier,
                explained,
            };
            let shown = |values: &Outputs| -> Vec<(&'static str, Value)> {
                compared
                    .iter()
                    .map(|&(_, o)| (block.outputs()[o].name(), values.as_slice()[o]))
                    .collect()
            };
            let this = ContextRow {
                line: rec.line(),
                text: show(&rec.raw()[..rec.raw().len().min(CONTEXT_TEXT)]),
                reference: shown(&values),
            };
            let found = show(rec.cell(column));
            // The rows before it agree with the reference: their values are read back from
            // their text, which the reader kept.
            let header_line = engine.layout.line;
            let recent: Vec<(u64, &[u8])> = reader
                .recent()
                .filter(|&(line, _)| line > header_line)
                .collect();
            let mut rows: Vec<ContextRow> = recent[..recent.len().saturating_sub(1)]
                .iter()
                .rev()
                .take(CONTEXT_ROWS)
                .rev()
                .map(|&(line, text)| ContextRow {
                    line,
                    text: show(&text[..text.len().min(CONTEXT_TEXT)]),
                    reference: values_of(block, &compared, text),
                })
                .collect();
            rows.push(this);
            report.difference = Some(Difference {
                line: rows[rows.len() - 1].line,
                column: column + 1,
                output: block.outputs()[o].name(),
                expected: values.as_slice()[o],
                found,
                why,
                context: rows,
            });
            break;
        }
        for (o, last) in wrote.iter_mut().enumerate() {
            if written & (1 << o) != 0 {
                *last = Some((rec.line(), outputs[o], state));
            }
        }
    }
    Ok(report)
}

// ---------------------------------------------------------------------------------------------
// observe

/// The columns a trace has, for an [`Observer`].
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Columns {
    /// The block.
    pub block: Block,
    /// Whether the trace has its time column (otherwise the time of a row is its index).
    pub timed: bool,
    /// The unit of the time column and of the block's clock: `ms`, or `ns` on LTIME.
    pub unit: &'static str,
    /// The boolean inputs the trace has, in catalog order, then the coils it has (`RT`).
    pub inputs: Vec<Port>,
    /// Whether the preset is a column of the trace (otherwise the command line gives it).
    pub preset_column: bool,
}

/// One step as an [`Observer`] sees it.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Observation<'a> {
    /// The time column's value (in [`Columns::unit`]), or the row's index.
    pub t: u64,
    /// The row's line.
    pub line: u64,
    /// The boolean inputs.
    pub signals: Signals,
    /// The outputs, in catalog order.
    pub outputs: Outputs,
    /// Clock units per unit of the integer output while it runs ([`Family::ramp`]).
    pub ramp: Option<u64>,
    /// The preset in the unit of the integer output ([`Family::preset_units`]).
    pub preset: i128,
    /// The preset as its literal (its `Display`: `T#500MS`, `C#5`).
    pub preset_value: &'a str,
}

/// Something that consumes a trace step by step (a diagram, a VCD file).
pub trait Observer {
    /// Called once with the trace's columns, before any step.
    fn start(&mut self, columns: &Columns) -> Result<(), Error>;
    /// Called for each step; `false` stops reading.
    fn step(&mut self, step: &Observation<'_>) -> Result<bool, Error>;
}

/// Runs the trace through the block of `spec` and hands each step to `observer`.
pub fn observe<R: Read>(
    spec: BlockSpec,
    preset: Option<&str>,
    input: R,
    observer: &mut dyn Observer,
) -> Result<(), Error> {
    struct V<'a, R>(BlockSpec, Option<&'a str>, R, &'a mut dyn Observer);
    impl<R: Read> Visit for V<'_, R> {
        type Out = Result<(), Error>;
        fn visit<B: BlockOps>(self, block: B, kind: B::Kind) -> Self::Out {
            observe_block((block, kind, self.0), self.1, self.2, self.3)
        }
    }
    spec.visit(V(spec, preset, input, observer))
}

fn observe_block<B: BlockOps, R: Read>(
    instance: (B, B::Kind, BlockSpec),
    preset: Option<&str>,
    input: R,
    observer: &mut dyn Observer,
) -> Result<(), Error> {
    let spec = instance.2;
    let block = spec.block();
    let mut reader = Reader::new(input);
    let header = reader.next_record()?.ok_or_else(empty)?;
    let mut engine = Engine::new(instance, &header, Mode::Inputs, preset)?;
    let inputs = block
        .inputs()
        .iter()
        .chain(block.coils())
        .copied()
        .filter(|&p| engine.layout.bools.iter().any(|&(_, q)| q == p))
        .collect();
    observer.start(&Columns {
        block,
        timed: engine.layout.time.is_some(),
        unit: spec.instruction.clock_unit(),
        inputs,
        preset_column: engine.layout.preset.is_some(),
    })?;
    // The preset's literal, written again only when the preset changes.
    let mut shown: Option<(B::Preset, String)> = None;
    while let Some(rec) = reader.next_record()? {
        let row = engine.step(&rec).map_err(|e| *e)?;
        if shown.as_ref().is_none_or(|(p, _)| *p != row.preset) {
            shown = Some((row.preset, row.preset.to_string()));
        }
        let go_on = observer.step(&Observation {
            t: row.t,
            line: rec.line(),
            signals: row.signals,
            outputs: B::values(engine.kind, &row.output),
            ramp: <B::Family as Family>::ramp(&row.output),
            preset: <B::Family as Family>::preset_units(row.preset),
            preset_value: shown.as_ref().map_or("", |(_, text)| text),
        })?;
        if !go_on {
            break;
        }
    }
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;

    /// CLI-RUN-01 (spec/cli.md, "Blocks"): the preset options are `--tv` for the S5 timers,
    /// `--pt` for the IEC timers and `--pv` for both kinds of counter.
    #[test]
    fn preset_options_as_the_contract_names_them() {
        use plc_timers::catalog::Family;
        for block in Block::ALL {
            let expected = match block.family() {
                Family::S5Timer => "tv",
                Family::IecTimer => "pt",
                Family::IecCounter | Family::S5Counter => "pv",
            };
            assert_eq!(preset_option(block), expected, "CLI-RUN-01: {block}");
        }
    }

    #[test]
    fn cell_parsers() {
        assert_eq!(parse_bool(b"TRUE"), Some(true));
        assert_eq!(parse_bool(b"0"), Some(false));
        assert_eq!(parse_bool(b"2"), None);
        assert_eq!(parse_u64(b"18446744073709551615"), Some(u64::MAX));
        assert_eq!(parse_u64(b"18446744073709551616"), None);
        assert_eq!(parse_u64(b"-1"), None);
        assert_eq!(parse_u64(b""), None);
        assert_eq!(
            parse_value(ValueKind::Word, b"w#16#00a1"),
            Some(Value::Word(0xA1))
        );
        assert_eq!(parse_value(ValueKind::Word, b"W#16#"), None);
        assert_eq!(parse_value(ValueKind::Word, b"W#16#12345"), None);
        assert_eq!(parse_value(ValueKind::Word, b"161"), Some(Value::Word(161)));
        assert_eq!(parse_value(ValueKind::Int, b"-5"), Some(Value::Int(-5)));
        assert_eq!(parse_value(ValueKind::Int, b"abc"), None);
        assert_eq!(parse_value(ValueKind::Int, b"+5"), Some(Value::Int(5)));
        assert_eq!(parse_value(ValueKind::Int, b"-"), None);
        assert_eq!(
            parse_value(ValueKind::Int, b"-170141183460469231731687303715884105728"),
            Some(Value::Int(i128::MIN))
        );
        assert_eq!(parse_value(ValueKind::Word, b"W#16#+1"), None);
        assert_eq!(parse_value(ValueKind::Word, b"W#16#zz"), None);
        assert_eq!(
            parse_value(ValueKind::Bool, b"FALSE"),
            Some(Value::Bool(false))
        );
        assert_eq!(parse_bool(b"false"), Some(false));
        let mut out = Vec::new();
        for v in [
            Value::Bool(true),
            Value::Int(-12),
            Value::Int(i128::from(u64::MAX)),
            Value::Word(0x2127),
        ] {
            write_value(&mut out, v);
            out.push(b' ');
        }
        assert_eq!(out, b"1 -12 18446744073709551615 W#16#2127 ");
    }
}
