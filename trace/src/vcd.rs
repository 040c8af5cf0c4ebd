//! VCD export (IEEE 1364 value change dump) for GTKWave, Surfer and other waveform viewers: the
//! trace's boolean inputs, the preset and the reference outputs as signals, the time in the
//! unit of the block's clock (1 ms; 1 ns on LTIME).
//! Written with the `vcd` crate, streamed: only changes are written.

use std::io::{Read, Write};

use plc_timers::catalog::{Port, ValueKind};
use vcd::{IdCode, TimescaleUnit, VarType};

use super::engine::{observe, Columns, Observation, Observer};
use super::error::Error;
use super::family::{BlockSpec, Value};

/// The width of integer signals (ET, BI, CV, the preset): 64 bits, two's complement.
pub const INT_BITS: u32 = 64;

struct Signal {
    id: IdCode,
    kind: ValueKind,
    /// Where the value comes from: an input bit, an output index, or the preset.
    source: Source,
    last: Option<i128>,
}

#[derive(Clone, Copy)]
enum Source {
    Input(Port),
    Output(usize),
    Preset,
}

struct VcdObserver<W: Write> {
    writer: vcd::Writer<W>,
    signals: Vec<Signal>,
    time: Option<u64>,
    rows: u64,
}

fn bits(v: i128, width: u32) -> impl Iterator<Item = vcd::Value> {
    (0..width).rev().map(move |i| {
        if (v >> i) & 1 == 1 {
            vcd::Value::V1
        } else {
            vcd::Value::V0
        }
    })
}

impl<W: Write> Observer for VcdObserver<W> {
    fn start(&mut self, columns: &Columns) -> Result<(), Error> {
        let w = &mut self.writer;
        let unit = match columns.unit {
            "ns" => TimescaleUnit::NS,
            _ => TimescaleUnit::MS,
        };
        w.timescale(1, unit)?;
        w.add_module(&columns.block.name().to_ascii_lowercase())?;
        for &port in &columns.inputs {
            let id = w.add_wire(1, port.name())?;
            self.signals.push(Signal {
                id,
                kind: ValueKind::Bool,
                source: Source::Input(port),
                last: None,
            });
        }
        {
            let id = w.add_var(
                VarType::Integer,
                INT_BITS,
                columns.block.preset().port.name(),
                None,
            )?;
            self.signals.push(Signal {
                id,
                kind: ValueKind::Int,
                source: Source::Preset,
                last: None,
            });
        }
        for (i, port) in columns.block.outputs().iter().enumerate() {
            let id = match port.kind() {
                ValueKind::Bool => w.add_wire(1, port.name())?,
                ValueKind::Word => w.add_var(VarType::Reg, 16, port.name(), None)?,
                _ => w.add_var(VarType::Integer, INT_BITS, port.name(), None)?,
            };
            self.signals.push(Signal {
                id,
                kind: port.kind(),
                source: Source::Output(i),
                last: None,
            });
        }
        w.upscope()?;
        w.enddefinitions()?;
        Ok(())
    }

    fn step(&mut self, o: &Observation<'_>) -> Result<bool, Error> {
        self.rows += 1;
        if self.time != Some(o.t) {
            self.writer.timestamp(o.t)?;
            self.time = Some(o.t);
        }
        for s in &mut self.signals {
            let v = match s.source {
                Source::Input(port) => i128::from(o.signals.get(port)),
                Source::Preset => o.preset,
                Source::Output(i) => match o.outputs.as_slice()[i] {
                    Value::Bool(b) => i128::from(b),
                    Value::Int(x) => x,
                    Value::Word(w) => i128::from(w),
                },
            };
            if s.last == Some(v) {
                continue;
            }
            s.last = Some(v);
            match s.kind {
                ValueKind::Bool => self.writer.change_scalar(s.id, v != 0)?,
                ValueKind::Word => self.writer.change_vector(s.id, bits(v, 16))?,
                _ => self.writer.change_vector(s.id, bits(v, INT_BITS))?,
            }
        }
        Ok(true)
    }
}

/// Writes the trace read from `input`, run through the block of `spec`, as a VCD file to `out`.
/// The time unit is the block's clock's (1 ms; 1 ns on LTIME); a trace without its time column
/// uses the row index. Returns the rows written.
pub fn export<R: Read, W: Write>(
    spec: BlockSpec,
    preset: Option<&str>,
    input: R,
    out: W,
) -> Result<u64, Error> {
    let mut o = VcdObserver {
        writer: vcd::Writer::new(out),
        signals: Vec::new(),
        time: None,
        rows: 0,
    };
    observe(spec, preset, input, &mut o)?;
    o.writer.flush()?;
    Ok(o.rows)
}
