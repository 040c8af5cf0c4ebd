//! `run` and `check` over rows in memory. The rows are written as the CSV text the command line
//! reads (header = line 1, one line per row) and handed to the trace engine of the `plc-timers`
//! command (`plc_timers_trace::{run, check}`): Python and the command line run one engine,
//! so they agree by construction, and a better explanation in the engine reaches Python
//! unchanged.

use std::io::Cursor;

use plc_timers::catalog::{Block, Kind, ValueKind};
use plc_timers::rule::RuleSet;
use plc_timers_trace::{
    self as engine, parse_value, preset_option, show, BlockSpec, Error, Implementation, Location,
    Value,
};
use pyo3::exceptions::{PyRuntimeError, PyTypeError};
use pyo3::prelude::*;
use pyo3::types::{PyBool, PyDict, PyList, PyString};

use crate::args::{self, shown, type_name};
use crate::literals::{PyCounterPreset, PyS5Time, PyTime};

/// A `plc_timers.TraceError` with its attributes.
fn trace_exception(
    py: Python<'_>,
    text: String,
    message: &str,
    line: Option<u64>,
    column: Option<usize>,
    column_name: Option<&str>,
    option: Option<&str>,
) -> PyErr {
    let err = crate::TraceError::new_err(text);
    let value = err.value(py);
    // Setting attributes on a fresh exception instance fails only without memory; the
    // exception is the right one to raise either way.
    let _ = value.setattr("message", message);
    let _ = value.setattr("line", line);
    let _ = value.setattr("column", column);
    let _ = value.setattr("column_name", column_name);
    let _ = value.setattr("option", option);
    err
}

/// `text` with the command line's options (`--pt`, `option --pt`) named as the keyword
/// arguments a Python caller gives (`keyword argument pt`): the engine's messages are written
/// for the command line, and a Python user never typed a flag.
fn keywords(text: &str) -> String {
    const OPTIONS: [&str; 4] = ["tv", "pt", "pv", "type"];
    let mut out = String::with_capacity(text.len() + 16);
    let mut rest = text;
    while let Some(at) = rest.find("--") {
        let after = &rest[at + 2..];
        let name_len = after
            .bytes()
            .take_while(|b| b.is_ascii_alphanumeric() || *b == b'_' || *b == b'-')
            .count();
        let name = &after[..name_len];
        if !OPTIONS.contains(&name) {
            // Not an option of theirs (e.g. a cell's text shown in the message): as it is.
            out.push_str(&rest[..at + 2]);
            rest = after;
            continue;
        }
        let before = &rest[..at];
        // "the option --pt" and "option --pt" already say what it is; a bare "--pt" needs it.
        let before = before
            .strip_suffix("the option ")
            .or_else(|| before.strip_suffix("option "))
            .unwrap_or(before);
        out.push_str(before);
        out.push_str("the keyword argument ");
        out.push_str(name);
        rest = &after[name_len..];
    }
    out.push_str(rest);
    out
}

/// The engine's bad-input error as a `plc_timers.TraceError`, worded for Python ([`keywords`]).
fn engine_error(py: Python<'_>, e: engine::TraceError) -> PyErr {
    let message = keywords(&e.message);
    let text = match &e.location {
        Location::Option(o) => format!("keyword argument {o}: {message}"),
        _ => keywords(&e.to_string()),
    };
    match &e.location {
        Location::Command => trace_exception(py, text, &message, None, None, None, None),
        Location::Option(o) => trace_exception(py, text, &message, None, None, None, Some(o)),
        Location::Line(l) => trace_exception(py, text, &message, Some(*l), None, None, None),
        Location::Cell { line, column, name } => trace_exception(
            py,
            text,
            &message,
            Some(*line),
            Some(*column),
            Some(name),
            None,
        ),
    }
}

/// A `TraceError` about a row or cell of the Python input, before the engine sees it.
fn input_error(py: Python<'_>, line: u64, column: Option<(usize, &str)>, message: String) -> PyErr {
    let text = match column {
        Some((c, name)) => format!("line {line}, column {c} ({name}): {message}"),
        None => format!("line {line}: {message}"),
    };
    trace_exception(
        py,
        text,
        &message,
        Some(line),
        column.map(|c| c.0),
        column.map(|c| c.1),
        None,
    )
}

/// Appends `text` as one CSV field: quoted when it would otherwise change the record (a comma,
/// a quote, blanks at its ends, a `#` that would make a comment line, or nothing at all, which
/// would make a blank line of a one-column trace).
fn push_field(out: &mut String, text: &str) {
    let plain = !text.is_empty()
        && !text.contains([',', '"'])
        && !text.starts_with(['#', ' ', '\t'])
        && !text.ends_with([' ', '\t']);
    if plain {
        out.push_str(text);
    } else {
        out.push('"');
        out.push_str(&text.replace('"', "\"\""));
        out.push('"');
    }
}

/// A preset given as a Python value (not a literal's text), read by the reader the block
/// classes use for it: one rule for `TON(pt=…)`, `run("TON", …, pt=…)` and a `PT` cell, so a
/// value of another literal type (a `CounterPreset` as PT, a `Time` as PV) is a `TypeError`
/// there as here, and an int is a word (TV), milliseconds (PT; nanoseconds on LTIME) or a count
/// (PV) everywhere. Returns the preset as the text of a trace cell, which the engine reads back
/// to the same value.
fn typed_preset(spec: BlockSpec, obj: &Bound<'_, PyAny>, name: &str) -> PyResult<String> {
    let t = spec.data_type();
    args::preset(obj, t, name).map(|v| args::preset_text(t, v))
}

/// A cell's text: a bool as 1/0, an int in decimal, a str as it is, an `S5Time` as its word, a
/// `Time` in ms, a `CounterPreset` as `C#n`; in the block's preset column, any value but a str
/// is read as the keyword argument is ([`typed_preset`]).
fn cell_text(
    py: Python<'_>,
    spec: BlockSpec,
    obj: &Bound<'_, PyAny>,
    line: u64,
    column: (usize, &str),
) -> PyResult<String> {
    let bad = |what: String| Err(input_error(py, line, Some(column), what));
    let preset = spec.block().preset();
    if column.1.trim() == preset.port.name() && !obj.is_instance_of::<PyString>() {
        return match typed_preset(spec, obj, column.1.trim()) {
            Ok(v) => Ok(v),
            // The reader's text says what is allowed; the error says where.
            Err(e) => bad(e.value(py).to_string()),
        };
    }
    if obj.is_instance_of::<PyBool>() {
        return Ok(if obj.extract::<bool>()? { "1" } else { "0" }.to_string());
    }
    if let Ok(s) = obj.cast::<PyString>() {
        let s = s.to_cow()?;
        if s.contains(['\n', '\r']) {
            return bad(format!(
                "{} holds a line break; a cell is one line of text",
                shown(obj)
            ));
        }
        return Ok(s.into_owned());
    }
    if let Ok(t) = obj.cast::<PyS5Time>() {
        return Ok(format!("W#16#{:04X}", t.get().0.to_word()));
    }
    if let Ok(t) = obj.cast::<PyTime>() {
        return Ok(t.get().0.as_millis().to_string());
    }
    if let Ok(p) = obj.cast::<PyCounterPreset>() {
        return Ok(format!("C#{}", p.get().0.value()));
    }
    // numpy's bool_ is not an int; its extraction as a bool is exact.
    if type_name(obj) == "bool_" || type_name(obj) == "bool" {
        if let Ok(b) = obj.extract::<bool>() {
            return Ok(if b { "1" } else { "0" }.to_string());
        }
    }
    if let Ok(i) = obj.extract::<i128>() {
        return Ok(i.to_string());
    }
    bad(format!(
        "{} ({}) is not a trace value; a cell is a bool, an int or a str (a literal such as \
         \"T#1S\")",
        shown(obj),
        type_name(obj)
    ))
}

/// The rows as the CSV text of a trace: header, then one line per row.
fn csv_of(
    py: Python<'_>,
    spec: BlockSpec,
    rows: &Bound<'_, PyAny>,
    columns: Option<Vec<String>>,
) -> PyResult<String> {
    let rows: Vec<Bound<'_, PyAny>> = rows
        .try_iter()
        .map_err(|_| {
            PyTypeError::new_err(format!(
                "rows is a list of dicts (column name -> value) or of tuples with columns=; got {}",
                type_name(rows)
            ))
        })?
        .collect::<PyResult<_>>()?;
    let dicts = rows.first().is_some_and(|r| r.is_instance_of::<PyDict>());
    let columns = match columns {
        Some(c) => c,
        None if dicts => {
            let first = rows[0].cast::<PyDict>()?;
            let mut names = Vec::with_capacity(first.len());
            for key in first.keys() {
                match key.cast::<PyString>() {
                    Ok(k) => names.push(k.to_cow()?.into_owned()),
                    Err(_) => {
                        return Err(input_error(
                            py,
                            2,
                            None,
                            format!("the key {} is not a column name (a str)", shown(&key)),
                        ))
                    }
                }
            }
            names
        }
        None if rows.is_empty() => {
            return Err(PyTypeError::new_err(
                "no rows and no columns=: give the columns (e.g. columns=[\"t_ms\", \"IN\"])",
            ))
        }
        None => {
            return Err(PyTypeError::new_err(
                "rows of tuples need columns= (the header, e.g. columns=[\"t_ms\", \"IN\"])",
            ))
        }
    };
    let mut out = String::with_capacity(16 * (rows.len() + 1));
    for (i, name) in columns.iter().enumerate() {
        if name.contains(['\n', '\r']) {
            return Err(input_error(
                py,
                1,
                Some((i + 1, name)),
                "a column name is one line of text".to_string(),
            ));
        }
        if i > 0 {
            out.push(',');
        }
        push_field(&mut out, name);
    }
    out.push('\n');
    for (k, row) in rows.iter().enumerate() {
        let line = k as u64 + 2;
        let cells: Vec<Bound<'_, PyAny>> = if let Ok(d) = row.cast::<PyDict>() {
            if d.len() != columns.len() {
                let keys: Vec<String> = d.keys().iter().map(|k| shown(&k)).collect();
                return Err(input_error(
                    py,
                    line,
                    None,
                    format!(
                        "the row has the keys {} but the columns are {}",
                        keys.join(", "),
                        columns.join(", ")
                    ),
                ));
            }
            let mut cells = Vec::with_capacity(columns.len());
            for (i, name) in columns.iter().enumerate() {
                match d.get_item(name)? {
                    Some(v) => cells.push(v),
                    None => {
                        return Err(input_error(
                            py,
                            line,
                            Some((i + 1, name)),
                            format!("the row has no `{name}`; every row has the same columns"),
                        ))
                    }
                }
            }
            cells
        } else if row.is_instance_of::<PyString>() {
            return Err(input_error(
                py,
                line,
                None,
                "a row is a dict or a tuple, not a str".to_string(),
            ));
        } else {
            match row.try_iter() {
                Ok(it) => it.collect::<PyResult<_>>()?,
                Err(_) => {
                    return Err(input_error(
                        py,
                        line,
                        None,
                        format!(
                            "{} ({}) is not a row; a row is a dict or a tuple",
                            shown(row),
                            type_name(row)
                        ),
                    ))
                }
            }
        };
        if cells.len() != columns.len() {
            return Err(input_error(
                py,
                line,
                None,
                format!(
                    "the row has {} value(s) but there are {} columns: {}",
                    cells.len(),
                    columns.len(),
                    columns.join(", ")
                ),
            ));
        }
        for (i, cell) in cells.iter().enumerate() {
            if i > 0 {
                out.push(',');
            }
            let text = cell_text(py, spec, cell, line, (i + 1, &columns[i]))?;
            push_field(&mut out, &text);
        }
        out.push('\n');
    }
    Ok(out)
}

/// The block spec and the preset, read as the command line reads its options.
struct Request {
    spec: BlockSpec,
    preset: Option<String>,
}

impl Request {
    #[allow(clippy::too_many_arguments)]
    fn new(
        py: Python<'_>,
        block: &str,
        tv: Option<&Bound<'_, PyAny>>,
        pt: Option<&Bound<'_, PyAny>>,
        pv: Option<&Bound<'_, PyAny>>,
        int_type: &str,
        optimized: bool,
    ) -> PyResult<Request> {
        let counter =
            Block::lookup(block.trim()).is_some_and(|b| matches!(b.kind(), Kind::IecCounter(_)));
        // `type` applies to IEC counters; its default says nothing for the other blocks.
        let t = (counter || !int_type.eq_ignore_ascii_case("INT")).then_some(int_type);
        let spec = BlockSpec::parse(block, t).map_err(|e| engine_error(py, e))?;
        let spec = spec.with(if optimized {
            Implementation::Optimized
        } else {
            Implementation::Reference
        });
        let mut preset = None;
        for (name, given) in [("tv", tv), ("pt", pt), ("pv", pv)] {
            if let Some(obj) = given {
                preset = Some(preset_value(py, spec, name, obj)?);
            }
        }
        Ok(Request { spec, preset })
    }
}

/// The preset keyword argument `name` given as `obj`: a keyword the block does not take is
/// refused with the one it does take; a str is read as the command line reads its preset
/// option (the same text, the same error), any other value by [`typed_preset`].
fn preset_value(
    py: Python<'_>,
    spec: BlockSpec,
    name: &'static str,
    obj: &Bound<'_, PyAny>,
) -> PyResult<String> {
    let block = spec.block();
    let preset = block.preset();
    if name != preset_option(block) {
        return Err(engine_error(
            py,
            engine::TraceError::new(
                Location::Command,
                format!(
                    "the keyword argument {name} does not apply to {block}; its preset {} is \
                     the keyword argument {}",
                    preset.port.name(),
                    preset_option(block)
                ),
            ),
        ));
    }
    let Ok(text) = obj.cast::<PyString>() else {
        // A value of the wrong type is the block classes' TypeError; a value out of range
        // their ValueError, here as the TraceError (a ValueError) of the keyword argument.
        return typed_preset(spec, obj, name).map_err(|e| {
            if e.is_instance_of::<PyTypeError>(py) {
                return e;
            }
            let message = e.value(py).to_string();
            let text = format!("keyword argument {name}: {message}");
            trace_exception(py, text, &message, None, None, None, Some(name))
        });
    };
    let text = text.to_cow()?.into_owned();
    match spec.preset_literal(&text) {
        Ok(_) => Ok(text),
        Err(e) => Err(engine_error(
            py,
            engine::TraceError::new(
                Location::Option(preset_option(block)),
                format!("`{}`: {e}", show(text.as_bytes())),
            ),
        )),
    }
}

/// A value of the trace format as a Python object: bool, int, or int (a word).
fn py_value(py: Python<'_>, v: Value) -> PyResult<Py<PyAny>> {
    Ok(match v {
        Value::Bool(b) => PyBool::new(py, b).to_owned().into_any().unbind(),
        Value::Int(i) => i.into_pyobject(py)?.into_any().unbind(),
        Value::Word(w) => w.into_pyobject(py)?.into_any().unbind(),
    })
}

/// Runs `rows` through `block` (reference, or optimized with `optimized=True`) and returns, for
/// every row, a dict of the block's outputs (bools as bool, integers and words as int), as
/// `plc-timers run` computes them.
///
/// `rows`: dicts (column name -> value) or tuples with `columns=`; the columns are those of
/// the command line's traces (`t_ms`, the block's inputs, optionally its preset; the IEC
/// timers optionally `RT`, the `-(RT)-` coil, run before the box call of its row). Presets:
/// `tv` (S5 timers), `pt` (IEC timers), `pv` (counters) as literals or ints; `type`: the IEC
/// counters' integer type. Bad rows raise `TraceError` with `line` (header = 1) and `column`.
///
/// >>> from plc_timers import run
/// >>> rows = [{"t_ms": 0, "IN": True}, {"t_ms": 400, "IN": True}, {"t_ms": 500, "IN": True}]
/// >>> [r["Q"] for r in run("TON", rows, pt="T#500ms")]
/// [False, False, True]
/// >>> run("TON", [(0, 1), (250, 1)], columns=["t_ms", "IN"], pt=500)[-1]
/// {'Q': False, 'ET': 250}
/// >>> run("TON", [{"t_ms": 0, "IN": 2}], pt=500)
/// Traceback (most recent call last):
///   ...
/// plc_timers.TraceError: line 2, column 2 (IN): `2` is not a boolean; use 0, 1, true or false
#[pyfunction]
#[pyo3(signature = (block, rows, *, columns = None, tv = None, pt = None, pv = None, r#type = "INT", optimized = false))]
#[allow(clippy::too_many_arguments)]
fn run(
    py: Python<'_>,
    block: &str,
    rows: &Bound<'_, PyAny>,
    columns: Option<Vec<String>>,
    tv: Option<&Bound<'_, PyAny>>,
    pt: Option<&Bound<'_, PyAny>>,
    pv: Option<&Bound<'_, PyAny>>,
    r#type: &str,
    optimized: bool,
) -> PyResult<Py<PyList>> {
    let request = Request::new(py, block, tv, pt, pv, r#type, optimized)?;
    let csv = csv_of(py, request.spec, rows, columns)?;
    let mut out = Vec::with_capacity(csv.len() * 2);
    let result = engine::run(
        request.spec,
        request.preset.as_deref(),
        Cursor::new(csv.as_bytes()),
        &mut out,
    );
    match result {
        Ok(_) => {}
        Err(Error::Input(e)) => return Err(engine_error(py, e)),
        Err(Error::Output(e)) => return Err(PyRuntimeError::new_err(e.to_string())),
    }
    // Each output line is the row as given, then the outputs: the last fields of the line
    // (an output never holds a comma; the row's own fields may, quoted).
    let ports = request.spec.block().outputs();
    let list = PyList::empty(py);
    let text = String::from_utf8_lossy(&out);
    for line in text.lines().skip(1) {
        let dict = PyDict::new(py);
        let mut fields = line.rsplitn(ports.len() + 1, ',');
        let mut values = Vec::with_capacity(ports.len());
        for port in ports.iter().rev() {
            let cell = fields.next().unwrap_or_default();
            let value = parse_value(port.kind(), cell.as_bytes()).ok_or_else(|| {
                PyRuntimeError::new_err(format!(
                    "the engine wrote `{cell}` for {}; this is a bug of plc-timers",
                    port.name()
                ))
            })?;
            values.push((port.name(), value));
        }
        for (name, value) in values.into_iter().rev() {
            dict.set_item(name, py_value(py, value)?)?;
        }
        list.append(dict)?;
    }
    Ok(list.unbind())
}

/// The first row where a trace's outputs differ from the reference, and why: the requirement
/// IDs that decided the reference's value at the row, the earlier row where the rules that
/// still matter acted (with their IDs), and the text `plc-timers check` prints.
#[pyclass(module = "plc_timers", name = "Difference", frozen, get_all)]
pub struct PyDifference {
    /// The row's line (the header is line 1).
    line: u64,
    /// The column (1-based).
    column: usize,
    /// The output's name (`Q`, `ET`, …).
    output: String,
    /// What the reference computes.
    expected: Py<PyAny>,
    /// What the trace has.
    actual: Py<PyAny>,
    /// The requirement IDs (`spec/requirements/*.toml`) that decided the output at the row, in
    /// catalog order; empty when no rule acted on it there (it kept an earlier row's value) or
    /// when the optimized implementation was checked (it explains nothing).
    rules: Vec<String>,
    /// The latest earlier row where rules acted on state that still matters at the row and
    /// that `rules` do not cover (the set whose memory made the count, the start of the
    /// running time, the row where PT was latched); None when there is none.
    earlier_line: Option<u64>,
    /// The IDs of the rules that acted at `earlier_line`, in catalog order (empty when None);
    /// `message` does not repeat there those already in `rules`.
    earlier_rules: Vec<String>,
    /// The text `plc-timers check` prints: the difference, the rules, the rows up to it.
    message: String,
}

#[pymethods]
impl PyDifference {
    fn __repr__(&self, py: Python<'_>) -> String {
        let show = |v: &Py<PyAny>| v.bind(py).repr().map(|r| r.to_string()).unwrap_or_default();
        format!(
            "Difference(line={}, column={}, output={:?}, expected={}, actual={}, rules={:?}, \
             earlier_line={}, earlier_rules={:?})",
            self.line,
            self.column,
            self.output,
            show(&self.expected),
            show(&self.actual),
            self.rules,
            self.earlier_line
                .map_or_else(|| "None".to_string(), |l| l.to_string()),
            self.earlier_rules
        )
    }

    fn __str__(&self) -> String {
        self.message.clone()
    }
}

/// Compares the outputs that `rows` carry (another implementation's, in columns named as the
/// block's outputs: `Q`, `ET`, …) with the reference's, row by row, and returns the first
/// `Difference` or None. `outputs` restricts the comparison to some outputs; the other keywords
/// are those of `run`.
///
/// >>> from plc_timers import check
/// >>> rows = [{"t_ms": 0, "IN": 1, "Q": 0, "ET": 0}, {"t_ms": 500, "IN": 1, "Q": 0, "ET": 500}]
/// >>> d = check("TON", rows, pt="T#500ms")
/// >>> (d.line, d.output, d.expected, d.actual)
/// (3, 'Q', True, False)
/// >>> check("TON", rows[:1], pt="T#500ms") is None
/// True
#[pyfunction]
#[pyo3(signature = (block, rows, *, columns = None, outputs = None, tv = None, pt = None, pv = None, r#type = "INT", optimized = false))]
#[allow(clippy::too_many_arguments)]
fn check(
    py: Python<'_>,
    block: &str,
    rows: &Bound<'_, PyAny>,
    columns: Option<Vec<String>>,
    outputs: Option<Vec<String>>,
    tv: Option<&Bound<'_, PyAny>>,
    pt: Option<&Bound<'_, PyAny>>,
    pv: Option<&Bound<'_, PyAny>>,
    r#type: &str,
    optimized: bool,
) -> PyResult<Option<PyDifference>> {
    let request = Request::new(py, block, tv, pt, pv, r#type, optimized)?;
    let csv = csv_of(py, request.spec, rows, columns)?;
    let names: Option<Vec<&str>> = outputs
        .as_ref()
        .map(|o| o.iter().map(String::as_str).collect());
    let report = engine::check(
        request.spec,
        request.preset.as_deref(),
        names.as_deref(),
        Cursor::new(csv.as_bytes()),
    )
    .map_err(|e| engine_error(py, e))?;
    let Some(d) = report.difference else {
        return Ok(None);
    };
    let kind = request
        .spec
        .block()
        .outputs()
        .iter()
        .find(|p| p.name() == d.output)
        .map_or(ValueKind::Int, |p| p.kind());
    // The trace's cell was read as a value of this kind by the engine; read it back so.
    let actual = match parse_value(kind, d.found.as_bytes()) {
        Some(v) => py_value(py, v)?,
        None => d.found.clone().into_pyobject(py)?.into_any().unbind(),
    };
    let ids = |rules: RuleSet| rules.iter().map(|r| r.to_string()).collect::<Vec<_>>();
    Ok(Some(PyDifference {
        line: d.line,
        column: d.column,
        output: d.output.to_string(),
        expected: py_value(py, d.expected)?,
        actual,
        rules: ids(d.why.rules),
        earlier_line: d.why.earlier.map(|(line, _)| line),
        earlier_rules: d.why.earlier.map_or_else(Vec::new, |(_, rules)| ids(rules)),
        message: d.to_string(),
    }))
}

/// Adds the functions and classes to the module.
pub fn register(m: &Bound<'_, PyModule>) -> PyResult<()> {
    m.add_function(wrap_pyfunction!(run, m)?)?;
    m.add_function(wrap_pyfunction!(check, m)?)?;
    m.add_class::<PyDifference>()?;
    Ok(())
}
