//! Runs a CSV trace through a block (`plc-timers run`) or checks another implementation's outputs
//! against the reference (`plc-timers check`), per `shared/trace-format.md`.

use std::format;
use std::io;
use std::string::{String, ToString};
use std::vec;
use std::vec::Vec;

use super::block::{InputKind, Row, TraceBlock, Value};
use super::error::{Location, TraceError};

/// A preset given on the command line: (option name without dashes, value), e.g. `("tv", "S5T#1S")`.
pub type PresetOption<'a> = (&'static str, &'a str);

/// What a column of the input file is.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum Column {
    Time,
    Input(usize),
    /// An output column: only allowed when checking.
    Output(usize),
}

/// The first place where a trace's outputs differ from the reference.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Difference {
    /// The 1-based line of the row.
    pub line: u64,
    /// The 1-based column.
    pub column: usize,
    /// The output's name.
    pub name: String,
    /// What the reference computes, as the contract writes it.
    pub expected: String,
    /// What the file says.
    pub found: String,
}

/// The result of checking a trace with outputs against the reference.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct CheckReport {
    /// The number of data rows read (up to and including the first difference).
    pub rows: u64,
    /// The names of the output columns the file has and that were compared.
    pub compared: Vec<String>,
    /// The first difference, if any.
    pub difference: Option<Difference>,
}

/// A parsed header: what each column is, plus the resolved preset sources.
struct Layout {
    names: Vec<String>,
    columns: Vec<Column>,
    /// For each of the block's inputs: the column index that carries it, if any.
    input_column: Vec<Option<usize>>,
    /// For each of the block's inputs: the command-line value used when the column is absent.
    option_value: Vec<Option<String>>,
    time_column: Option<usize>,
    output_column: Vec<Option<usize>>,
}

fn csv_error(e: csv::Error) -> TraceError {
    let line = match e.kind() {
        csv::ErrorKind::Utf8 { pos: Some(pos), .. }
        | csv::ErrorKind::UnequalLengths { pos: Some(pos), .. } => Some(pos.line()),
        _ => e.position().map(csv::Position::line),
    };
    // A non-UTF-8 cell is located to its column (the header's name is not known here: it may
    // be the header itself that is not UTF-8).
    if let (csv::ErrorKind::Utf8 { err, .. }, Some(line)) = (e.kind(), line) {
        return TraceError::new(
            Location::Cell {
                line,
                column: err.field() + 1,
                name: format!("field {}", err.field() + 1),
            },
            format!(
                "the cell is not valid UTF-8 (invalid byte after {} valid bytes); \
                 traces are UTF-8 text",
                err.valid_up_to()
            ),
        );
    }
    let message = match e.kind() {
        csv::ErrorKind::UnequalLengths {
            expected_len, len, ..
        } => {
            format!("the row has {len} fields but the header has {expected_len}")
        }
        csv::ErrorKind::Utf8 { .. } => "the row is not valid UTF-8".to_string(),
        _ => e.to_string(),
    };
    match line {
        Some(line) => TraceError::new(Location::Line(line), message),
        None => TraceError::new(Location::Command, message),
    }
}

fn reader<R: io::Read>(input: R) -> csv::Reader<R> {
    csv::ReaderBuilder::new()
        .has_headers(false)
        .comment(Some(b'#'))
        .flexible(false)
        .from_reader(input)
}

fn layout(
    block: &dyn TraceBlock,
    header: &csv::StringRecord,
    line: u64,
    presets: &[PresetOption<'_>],
    allow_outputs: bool,
) -> Result<Layout, TraceError> {
    let inputs = block.inputs();
    let outputs = block.outputs();
    let mut layout = Layout {
        names: Vec::new(),
        columns: Vec::new(),
        input_column: vec![None; inputs.len()],
        option_value: vec![None; inputs.len()],
        time_column: None,
        output_column: vec![None; outputs.len()],
    };
    for (index, raw) in header.iter().enumerate() {
        let name = raw.trim();
        let cell = || Location::Cell {
            line,
            column: index + 1,
            name: name.to_string(),
        };
        let column = if name.eq_ignore_ascii_case("t_ms") {
            Column::Time
        } else if let Some(i) = inputs
            .iter()
            .position(|c| c.name.eq_ignore_ascii_case(name))
        {
            Column::Input(i)
        } else if let Some(i) = outputs.iter().position(|c| c.eq_ignore_ascii_case(name)) {
            if !allow_outputs {
                return Err(TraceError::new(
                    cell(),
                    format!(
                        "`{name}` is an output of {}; `run` takes inputs only \
                         (use `plc-timers check` to compare outputs)",
                        block.name()
                    ),
                ));
            }
            Column::Output(i)
        } else {
            let mut known: Vec<&str> = inputs.iter().map(|c| c.name).collect();
            known.insert(0, "t_ms");
            if allow_outputs {
                known.extend_from_slice(outputs);
            }
            return Err(TraceError::new(
                cell(),
                format!(
                    "unknown column `{name}`; {} takes the columns {}",
                    block.name(),
                    known.join(", ")
                ),
            ));
        };
        let slot = match column {
            Column::Time => &mut layout.time_column,
            Column::Input(i) => &mut layout.input_column[i],
            Column::Output(i) => &mut layout.output_column[i],
        };
        if slot.is_some() {
            return Err(TraceError::new(
                cell(),
                format!("column `{name}` appears twice"),
            ));
        }
        *slot = Some(index);
        layout.names.push(name.to_string());
        layout.columns.push(column);
    }
    if block.requires_time() && layout.time_column.is_none() {
        return Err(TraceError::new(
            Location::Line(line),
            format!(
                "{} is a timer: the header needs a `t_ms` column",
                block.name()
            ),
        ));
    }
    for (option, value) in presets {
        let declared = inputs
            .iter()
            .position(|c| c.kind == InputKind::Preset { option });
        match declared {
            Some(i) => layout.option_value[i] = Some(value.to_string()),
            None => {
                return Err(TraceError::new(
                    Location::Option(option),
                    format!("--{option} does not apply to {}", block.name()),
                ))
            }
        }
    }
    for (i, input) in inputs.iter().enumerate() {
        if let InputKind::Preset { option } = input.kind {
            if layout.input_column[i].is_none() && layout.option_value[i].is_none() {
                return Err(TraceError::new(
                    Location::Line(line),
                    format!(
                        "{} needs its preset: a `{}` column or the option --{option}",
                        block.name(),
                        input.name
                    ),
                ));
            }
        }
    }
    Ok(layout)
}

/// Parses a boolean cell: `0`, `1`, `true`, `false` (any case, surrounding blanks ignored).
pub fn parse_bool(text: &str) -> Option<bool> {
    let t = text.trim();
    if t == "1" || t.eq_ignore_ascii_case("true") {
        Some(true)
    } else if t == "0" || t.eq_ignore_ascii_case("false") {
        Some(false)
    } else {
        None
    }
}

/// Drives `block` through every row of the trace; calls `sink` with the row's line, the record and
/// the computed outputs. Stops early when `sink` returns `false`.
fn drive<R: io::Read>(
    block: &mut dyn TraceBlock,
    input: R,
    presets: &[PresetOption<'_>],
    allow_outputs: bool,
    mut header: impl FnMut(&Layout, u64) -> Result<(), TraceError>,
    mut sink: impl FnMut(&Layout, u64, &csv::StringRecord, &[Value]) -> Result<bool, TraceError>,
) -> Result<(), TraceError> {
    let mut rdr = reader(input);
    let mut record = csv::StringRecord::new();
    if !rdr.read_record(&mut record).map_err(csv_error)? {
        return Err(TraceError::new(
            Location::Line(1),
            "the trace is empty: it needs a header row",
        ));
    }
    let header_line = record.position().map_or(1, csv::Position::line);
    let layout = layout(block, &record, header_line, presets, allow_outputs)?;
    // Called before any data row, so that a header-only trace still gets its output header.
    header(&layout, header_line)?;
    let inputs = block.inputs();
    let mut bools = vec![false; inputs.len()];
    let mut outputs = Vec::with_capacity(block.outputs().len());
    let mut last_t: Option<u64> = None;
    while rdr.read_record(&mut record).map_err(csv_error)? {
        let line = record.position().map_or(0, csv::Position::line);
        let cell = |index: usize| Location::Cell {
            line,
            column: index + 1,
            name: layout.names[index].clone(),
        };
        let mut t_ms = None;
        if let Some(index) = layout.time_column {
            let text = record.get(index).unwrap_or("").trim();
            let t: u64 = text.parse().map_err(|_| {
                TraceError::new(
                    cell(index),
                    format!("`{text}` is not a time: t_ms is a whole number of milliseconds, 0..=18446744073709551615"),
                )
            })?;
            if let Some(prev) = last_t {
                if t < prev {
                    return Err(TraceError::new(
                        cell(index),
                        format!("t_ms goes backwards: {t} after {prev}; time must not decrease"),
                    ));
                }
            }
            last_t = Some(t);
            t_ms = Some(t);
        }
        let mut presets: Vec<Option<&str>> = Vec::with_capacity(inputs.len());
        for (i, input) in inputs.iter().enumerate() {
            let text = layout.input_column[i].map(|index| record.get(index).unwrap_or(""));
            match input.kind {
                InputKind::Bool => {
                    bools[i] = match (text, layout.input_column[i]) {
                        (Some(text), Some(index)) => parse_bool(text).ok_or_else(|| {
                            TraceError::new(
                                cell(index),
                                format!(
                                    "`{}` is not a boolean; use 0, 1, true or false",
                                    text.trim()
                                ),
                            )
                        })?,
                        _ => false,
                    };
                    presets.push(None);
                }
                InputKind::Preset { .. } => {
                    presets.push(text.map(str::trim).or(layout.option_value[i].as_deref()));
                }
            }
        }
        let row = Row {
            t_ms,
            inputs,
            bools: &bools,
            presets: &presets,
        };
        outputs.clear();
        block.step(&row, &mut outputs).map_err(|e| {
            let i = inputs.iter().position(|c| c.name == e.input);
            match i.and_then(|i| layout.input_column[i]) {
                Some(index) => TraceError::new(cell(index), e.message),
                None => {
                    let option = i.and_then(|i| match inputs[i].kind {
                        InputKind::Preset { option } => Some(option),
                        InputKind::Bool => None,
                    });
                    match option {
                        Some(option) => TraceError::new(Location::Option(option), e.message),
                        None => TraceError::new(Location::Line(line), e.message),
                    }
                }
            }
        })?;
        if !sink(&layout, line, &record, &outputs)? {
            break;
        }
    }
    Ok(())
}

/// Runs the trace read from `input` through `block` and writes the contract's CSV to `output`:
/// the input columns as given, then the block's outputs.
pub fn run<R: io::Read, W: io::Write>(
    block: &mut dyn TraceBlock,
    input: R,
    presets: &[PresetOption<'_>],
    output: W,
) -> Result<(), TraceError> {
    let wtr = csv::WriterBuilder::new().flexible(true).from_writer(output);
    let io_error =
        |e: csv::Error| TraceError::new(Location::Command, format!("cannot write the output: {e}"));
    let output_names = block.outputs();
    let mut fields: Vec<String> = Vec::new();
    let mut wtr = std::cell::RefCell::new(wtr);
    drive(
        block,
        input,
        presets,
        false,
        |layout, _line| {
            let mut header: Vec<&str> = layout.names.iter().map(String::as_str).collect();
            header.extend_from_slice(output_names);
            wtr.borrow_mut().write_record(&header).map_err(io_error)
        },
        |_layout, _line, record, values| {
            let mut wtr = wtr.borrow_mut();
            fields.clear();
            fields.extend(record.iter().map(str::to_string));
            fields.extend(values.iter().map(Value::to_string));
            wtr.write_record(&fields).map_err(io_error)?;
            Ok(true)
        },
    )?;
    wtr.get_mut()
        .flush()
        .map_err(|e| TraceError::new(Location::Command, format!("cannot write the output: {e}")))
}

/// Parses an output cell of another implementation in the form `expected` has.
fn parse_like(expected: Value, text: &str) -> Option<Value> {
    let t = text.trim();
    match expected {
        Value::Bool(_) => parse_bool(t).map(Value::Bool),
        Value::Int(_) => t.parse().ok().map(Value::Int),
        Value::Word(_) => {
            let upper = t.to_ascii_uppercase();
            match upper.strip_prefix("W#16#") {
                Some(hex) => u16::from_str_radix(hex, 16).ok().map(Value::Word),
                None => t.parse().ok().map(Value::Word),
            }
        }
    }
}

/// Reads a trace that carries outputs (another implementation's) and compares every output column
/// it has against the reference, row by row; stops at the first difference.
pub fn check<R: io::Read>(
    block: &mut dyn TraceBlock,
    input: R,
    presets: &[PresetOption<'_>],
) -> Result<CheckReport, TraceError> {
    let output_names = block.outputs();
    let mut report = CheckReport {
        rows: 0,
        compared: Vec::new(),
        difference: None,
    };
    let block_name = block.name();
    let mut compared = Vec::new();
    drive(
        block,
        input,
        presets,
        true,
        |layout, line| {
            compared = output_names
                .iter()
                .zip(&layout.output_column)
                .filter(|(_, c)| c.is_some())
                .map(|(n, _)| n.to_string())
                .collect();
            if compared.is_empty() {
                return Err(TraceError::new(
                    Location::Line(line),
                    format!(
                        "no output column to check; {block_name} writes {}",
                        output_names.join(", ")
                    ),
                ));
            }
            Ok(())
        },
        |layout, line, record, values| {
            report.rows += 1;
            for (o, column) in layout.output_column.iter().enumerate() {
                let Some(index) = *column else { continue };
                let text = record.get(index).unwrap_or("");
                if parse_like(values[o], text) != Some(values[o]) {
                    report.difference = Some(Difference {
                        line,
                        column: index + 1,
                        name: output_names[o].to_string(),
                        expected: values[o].to_string(),
                        found: text.trim().to_string(),
                    });
                    return Ok(false);
                }
            }
            Ok(true)
        },
    )?;
    report.compared = compared;
    Ok(report)
}

/// A trace with the block's outputs, as [`record`] returns it: what a diagram draws.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Recording {
    /// The block's canonical name.
    pub block: &'static str,
    /// `t_ms` of each row (the row index when the trace has no `t_ms`).
    pub time: Vec<u64>,
    /// Whether the trace had a `t_ms` column.
    pub timed: bool,
    /// Each boolean input column the trace has: its name and its value on each row.
    pub inputs: Vec<(&'static str, Vec<bool>)>,
    /// The preset text of the first row (column or option), if any: what the diagram marks.
    pub preset: Option<(&'static str, String)>,
    /// Each output: its name and its value on each row.
    pub outputs: Vec<(&'static str, Vec<Value>)>,
}

/// Runs the trace through `block` like [`run`], keeping the rows instead of writing them.
pub fn record<R: io::Read>(
    block: &mut dyn TraceBlock,
    input: R,
    presets: &[PresetOption<'_>],
) -> Result<Recording, TraceError> {
    let inputs = block.inputs();
    let name = block.name();
    let output_names = block.outputs();
    let mut rec = Recording {
        block: name,
        time: Vec::new(),
        timed: false,
        inputs: Vec::new(),
        preset: None,
        outputs: output_names.iter().map(|&n| (n, Vec::new())).collect(),
    };
    let mut row = 0u64;
    drive(
        block,
        input,
        presets,
        false,
        |_, _| Ok(()),
        |layout, _line, record, values| {
            if row == 0 {
                rec.timed = layout.time_column.is_some();
                for (i, input) in inputs.iter().enumerate() {
                    match (input.kind, layout.input_column[i]) {
                        (InputKind::Bool, Some(_)) => rec.inputs.push((input.name, Vec::new())),
                        (InputKind::Preset { .. }, column) => {
                            let text = column
                                .and_then(|c| record.get(c).map(str::to_string))
                                .or_else(|| layout.option_value[i].clone());
                            rec.preset = text.map(|t| (input.name, t.trim().to_string()));
                        }
                        _ => {}
                    }
                }
            }
            let t = layout
                .time_column
                .and_then(|c| record.get(c))
                .and_then(|t| t.trim().parse().ok())
                .unwrap_or(row);
            rec.time.push(t);
            for (name, values) in rec.inputs.iter_mut() {
                let i = inputs.iter().position(|c| c.name == *name);
                let text = i
                    .and_then(|i| layout.input_column[i])
                    .and_then(|c| record.get(c));
                values.push(text.and_then(parse_bool).unwrap_or(false));
            }
            for ((_, values), v) in rec.outputs.iter_mut().zip(values) {
                values.push(*v);
            }
            row += 1;
            Ok(true)
        },
    )?;
    Ok(rec)
}
