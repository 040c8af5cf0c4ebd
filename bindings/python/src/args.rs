//! Arguments from Python, checked: each reader turns a Python object into a core value or into a
//! Python exception that says what was wrong and what is allowed.

use plc_timers::catalog::{Block, DataType, Family};
use plc_timers::counter::s5::{CounterPreset, CounterPresetError};
use plc_timers::counter::CounterInt;
use plc_timers::time::{CpuTime, LTime, LiteralError, LiteralErrorKind, S5Time, Time};
use pyo3::exceptions::{PyTypeError, PyValueError};
use pyo3::prelude::*;
use pyo3::types::{PyBool, PyString};

use crate::literals::{PyCounterPreset, PyLTime, PyS5Time, PyTime};

/// The Python type name of `obj`, for messages.
pub fn type_name(obj: &Bound<'_, PyAny>) -> String {
    obj.get_type()
        .name()
        .map(|n| n.to_string())
        .unwrap_or_else(|_| "?".to_string())
}

/// `obj`'s `repr()`, cut to 60 characters, for messages.
pub fn shown(obj: &Bound<'_, PyAny>) -> String {
    let text = obj
        .repr()
        .map(|r| r.to_string())
        .unwrap_or_else(|_| "?".to_string());
    if text.chars().count() > 60 {
        let mut cut: String = text.chars().take(60).collect();
        cut.push('…');
        cut
    } else {
        text
    }
}

/// The name of a [`LiteralErrorKind`] variant, as Python sees it in `LiteralError.kind`.
fn kind_name(kind: LiteralErrorKind) -> &'static str {
    match kind {
        LiteralErrorKind::Empty => "Empty",
        LiteralErrorKind::Prefix => "Prefix",
        LiteralErrorKind::NoComponents => "NoComponents",
        LiteralErrorKind::MissingUnit => "MissingUnit",
        LiteralErrorKind::UnknownUnit => "UnknownUnit",
        LiteralErrorKind::MissingDigits => "MissingDigits",
        LiteralErrorKind::UnexpectedChar(_) => "UnexpectedChar",
        LiteralErrorKind::UnitOrder(_) => "UnitOrder",
        LiteralErrorKind::ComponentRange(..) => "ComponentRange",
        LiteralErrorKind::Fraction => "Fraction",
        LiteralErrorKind::Overflow => "Overflow",
        LiteralErrorKind::HexDigits => "HexDigits",
        LiteralErrorKind::BcdDigit(_) => "BcdDigit",
        LiteralErrorKind::Negative => "Negative",
        LiteralErrorKind::OutOfRange => "OutOfRange",
        // The enum is non-exhaustive: a kind added later still gets a name.
        _ => "Other",
    }
}

/// A `plc_timers.LiteralError` with its attributes.
fn literal_exception(
    py: Python<'_>,
    message: String,
    literal: &str,
    kind: &str,
    position: Option<usize>,
) -> PyErr {
    let err = crate::LiteralError::new_err(message);
    let value = err.value(py);
    // Setting attributes on a fresh exception instance cannot fail short of memory exhaustion;
    // if it did, the exception without them is still the right one to raise.
    let _ = value.setattr("literal", literal);
    let _ = value.setattr("kind", kind);
    let _ = value.setattr("position", position);
    err
}

/// The core's literal error as a `plc_timers.LiteralError`.
pub fn literal_error(py: Python<'_>, e: LiteralError) -> PyErr {
    literal_exception(
        py,
        e.to_string(),
        e.what.name(),
        kind_name(e.kind),
        Some(e.position),
    )
}

/// The error of a time preset `text` that is not a literal of its block's data type, with a
/// hint when it is one of the other IEC time type (`LT#…` given to a TIME timer, `T#…` to an
/// LTIME one): the data type is chosen by the block's `type=`.
fn time_literal_error(py: Python<'_>, e: LiteralError, other: Option<&str>) -> PyErr {
    let mut message = e.to_string();
    if let (LiteralErrorKind::Prefix, Some(other)) = (e.kind, other) {
        message.push_str(&format!(
            "; it is a literal of {other}, which the block takes with type=\"{other}\""
        ));
    }
    literal_exception(
        py,
        message,
        e.what.name(),
        kind_name(e.kind),
        Some(e.position),
    )
}

/// The core's counter preset error as a `plc_timers.LiteralError` (no position: its errors
/// concern the whole text).
pub fn preset_error(py: Python<'_>, e: CounterPresetError) -> PyErr {
    let kind = match e {
        CounterPresetError::Syntax => "Syntax",
        CounterPresetError::OutOfRange(_) => "OutOfRange",
        CounterPresetError::BcdDigit(_) => "BcdDigit",
        _ => "Other",
    };
    literal_exception(py, e.to_string(), "C#", kind, None)
}

/// A whole number that fits `T`, or a `ValueError`/`TypeError` naming `what` and `allowed`.
pub fn int_in<T: TryFrom<i128>>(obj: &Bound<'_, PyAny>, what: &str, allowed: &str) -> PyResult<T> {
    if obj.is_instance_of::<PyBool>() {
        return Err(PyTypeError::new_err(format!(
            "{what} is {allowed}; got the bool {}",
            shown(obj)
        )));
    }
    let Ok(v) = obj.extract::<i128>() else {
        return Err(PyTypeError::new_err(format!(
            "{what} is {allowed}; got {} ({})",
            shown(obj),
            type_name(obj)
        )));
    };
    T::try_from(v).map_err(|_| PyValueError::new_err(format!("{what} is {allowed}; got {v}")))
}

/// The CPU time of a call: a whole number of milliseconds, 0..=2**64-1.
pub fn now_ms(obj: &Bound<'_, PyAny>) -> PyResult<CpuTime> {
    clock(obj, "ms").map(CpuTime::from_millis)
}

/// The CPU time of a call in whole units of the block's clock (`unit`: `ms`, or `ns` for the
/// LTIME timers), 0..=2**64-1; the argument is named `now_<unit>` in messages.
pub fn clock(obj: &Bound<'_, PyAny>, unit: &str) -> PyResult<u64> {
    let name = format!("now_{unit}");
    let allowed = format!(
        "the CPU time in whole {}, 0..=18446744073709551615",
        unit_name(unit)
    );
    int_in::<u64>(obj, &name, &allowed)
}

/// The word for a clock unit's symbol.
fn unit_name(unit: &str) -> &str {
    match unit {
        "ns" => "nanoseconds",
        _ => "milliseconds",
    }
}

/// Rejects a CPU time before the previous call's: time must not decrease.
pub fn forward(now: CpuTime, last: Option<CpuTime>) -> PyResult<()> {
    forward_in(now.as_millis(), last.map(CpuTime::as_millis), "ms")
}

/// [`forward`] for a clock in `unit` (`ms`, `ns`).
pub fn forward_in(now: u64, last: Option<u64>, unit: &str) -> PyResult<()> {
    match last {
        Some(last) if now < last => Err(PyValueError::new_err(format!(
            "now_{unit} goes backwards: {now} after {last}; the CPU time must not decrease"
        ))),
        _ => Ok(()),
    }
}

/// A boolean input: a Python `bool` or `numpy.bool_`.
pub fn boolean(obj: &Bound<'_, PyAny>, what: &str) -> PyResult<bool> {
    obj.extract::<bool>().map_err(|_| {
        PyTypeError::new_err(format!(
            "{what} is a boolean (True or False); got {} ({})",
            shown(obj),
            type_name(obj)
        ))
    })
}

/// An S5TIME: a literal (`"S5T#5S"`, `"W#16#2050"`), a word (int 0..=65535, time base in bits
/// 13-12, three BCD digits) or an `S5Time`.
pub fn s5time(obj: &Bound<'_, PyAny>, what: &str) -> PyResult<S5Time> {
    let py = obj.py();
    if let Ok(t) = obj.cast::<PyS5Time>() {
        return Ok(t.get().0);
    }
    if let Ok(text) = obj.cast::<PyString>() {
        let text = text.to_cow()?;
        return S5Time::parse(text.trim()).map_err(|e| literal_error(py, e));
    }
    if obj.is_instance_of::<PyBool>() || obj.extract::<i128>().is_err() {
        return Err(PyTypeError::new_err(format!(
            "{what} is an S5TIME: a literal such as \"S5T#5S\" or \"W#16#2050\", a word \
             (int 0..=65535) or an S5Time; got {} ({})",
            shown(obj),
            type_name(obj)
        )));
    }
    let word = int_in::<u16>(obj, what, "an S5TIME word, 0..=65535")?;
    S5Time::from_word(word).map_err(|e| PyValueError::new_err(format!("{what}: {e}")))
}

/// A TIME: a literal (`"T#500ms"`, `"T#-5S"`, whole milliseconds as text), an int of
/// milliseconds (-2**31..=2**31-1) or a `Time`.
pub fn time(obj: &Bound<'_, PyAny>, what: &str) -> PyResult<Time> {
    let py = obj.py();
    if let Ok(t) = obj.cast::<PyTime>() {
        return Ok(t.get().0);
    }
    if let Ok(text) = obj.cast::<PyString>() {
        let text = text.to_cow()?;
        let text = text.trim();
        let other = LTime::parse(text).is_ok().then_some("LTIME");
        return Time::parse(text).map_err(|e| time_literal_error(py, e, other));
    }
    if obj.is_instance_of::<PyBool>() || obj.extract::<i128>().is_err() {
        return Err(PyTypeError::new_err(format!(
            "{what} is a TIME: a literal such as \"T#500ms\", an int of milliseconds \
             (-2147483648..=2147483647) or a Time (an LTime needs type=\"LTIME\"); got {} ({})",
            shown(obj),
            type_name(obj)
        )));
    }
    int_in::<i32>(
        obj,
        what,
        "a TIME in milliseconds, -2147483648..=2147483647",
    )
    .map(Time::from_millis)
}

/// An LTIME: a literal (`"LT#1ms500us"`, `"LTIME#30D"`, whole nanoseconds as text), an int of
/// nanoseconds (-2**63..=2**63-1) or an `LTime`. A `Time` is refused: the data types differ,
/// as TIA Portal keeps them apart.
pub fn ltime(obj: &Bound<'_, PyAny>, what: &str) -> PyResult<LTime> {
    let py = obj.py();
    if let Ok(t) = obj.cast::<PyLTime>() {
        return Ok(t.get().0);
    }
    if let Ok(text) = obj.cast::<PyString>() {
        let text = text.to_cow()?;
        let text = text.trim();
        let other = Time::parse(text).is_ok().then_some("TIME");
        return LTime::parse(text).map_err(|e| time_literal_error(py, e, other));
    }
    if obj.is_instance_of::<PyBool>() || obj.extract::<i128>().is_err() {
        return Err(PyTypeError::new_err(format!(
            "{what} is an LTIME: a literal such as \"LT#1ms500us\", an int of nanoseconds \
             (-9223372036854775808..=9223372036854775807) or an LTime; got {} ({})",
            shown(obj),
            type_name(obj)
        )));
    }
    int_in::<i64>(
        obj,
        what,
        "an LTIME in nanoseconds, -9223372036854775808..=9223372036854775807",
    )
    .map(LTime::from_nanos)
}

/// An S5 counter preset: a literal (`"C#5"`, `"5"`, `"W#16#0005"`), an int 0..=999 or a
/// `CounterPreset`.
pub fn counter_preset(obj: &Bound<'_, PyAny>, what: &str) -> PyResult<CounterPreset> {
    let py = obj.py();
    if let Ok(p) = obj.cast::<PyCounterPreset>() {
        return Ok(p.get().0);
    }
    if let Ok(text) = obj.cast::<PyString>() {
        let text = text.to_cow()?;
        return CounterPreset::parse(text.trim()).map_err(|e| preset_error(py, e));
    }
    let n = int_in::<u16>(
        obj,
        what,
        "a counter preset: \"C#0\" to \"C#999\", an int 0..=999 or a CounterPreset",
    )?;
    CounterPreset::new(n).map_err(|e| preset_error(py, e))
}

/// The block named `name` (a catalog name or alias, ASCII case ignored) of family `family`.
pub fn block_of(name: &str, family: Family, what: &str) -> PyResult<Block> {
    let names = || {
        Block::ALL
            .into_iter()
            .filter(|b| b.family() == family)
            .map(Block::name)
            .collect::<Vec<_>>()
            .join(", ")
    };
    match Block::lookup(name.trim()) {
        Some(b) if b.family() == family => Ok(b),
        _ => Err(PyValueError::new_err(format!(
            "{what} `{name}` is not one of {}",
            names()
        ))),
    }
}

/// The range of the integer data type `t` (SINT … ULINT), `None` for another data type.
pub fn int_limits(t: DataType) -> Option<(i128, i128)> {
    fn of<T: CounterInt>() -> Option<(i128, i128)> {
        Some((T::MIN.to_i128(), T::MAX.to_i128()))
    }
    match t {
        DataType::SInt => of::<i8>(),
        DataType::Int => of::<i16>(),
        DataType::DInt => of::<i32>(),
        DataType::LInt => of::<i64>(),
        DataType::USInt => of::<u8>(),
        DataType::UInt => of::<u16>(),
        DataType::UDInt => of::<u32>(),
        DataType::ULInt => of::<u64>(),
        _ => None,
    }
}

/// An IEC counter preset of the integer data type `t`: an int inside its range.
pub fn int_preset(obj: &Bound<'_, PyAny>, t: DataType, what: &str) -> PyResult<i128> {
    let Some((lo, hi)) = int_limits(t) else {
        return Err(PyValueError::new_err(format!("{t} is not an integer type")));
    };
    let v: i128 = int_in(obj, what, &format!("an int of {t}, {lo}..={hi}"))?;
    if v < lo || v > hi {
        return Err(PyValueError::new_err(format!(
            "{what} is an int of {t}, {lo}..={hi}; got {v}"
        )));
    }
    Ok(v)
}

/// A preset of the data type `t` read from Python by that type's reader ([`s5time`], [`time`],
/// [`ltime`], [`counter_preset`], [`int_preset`]), as the int that the reader takes back for
/// it (what pickle saves): the word of an S5TIME, the milliseconds of a TIME, the nanoseconds
/// of an LTIME, the count.
pub fn preset(obj: &Bound<'_, PyAny>, t: DataType, what: &str) -> PyResult<i128> {
    match t {
        DataType::S5Time => s5time(obj, what).map(|v| v.to_word().into()),
        DataType::Time => time(obj, what).map(|v| v.as_millis().into()),
        DataType::LTime => ltime(obj, what).map(|v| v.as_nanos().into()),
        DataType::Word => counter_preset(obj, what).map(|v| v.value().into()),
        _ => int_preset(obj, t, what),
    }
}

/// A preset that [`preset`] read, as the text of the data type `t` for the block's own
/// preset parser: a plain number (milliseconds, nanoseconds, a count), the word of an S5TIME
/// (whose plain number is not one: a word keeps the time base).
pub fn preset_text(t: DataType, v: i128) -> String {
    match t {
        DataType::S5Time => format!("W#16#{v:04X}"),
        _ => v.to_string(),
    }
}
