//! Test vectors for other implementations: for every block, CSV traces with the reference
//! outputs, in the contract's format and self-contained (the preset is a column), so that
//! `plc-timers check BLOCK FILE` replays them.
//!
//! Each block gets its shipped example trace and [`TRACES_PER_BLOCK`] generated traces: random
//! inputs whose bits keep their value with probability 3/4 (clustered edges), presets from a
//! list of edge values (0, one unit, negative for IEC timers, the type's limits for counters),
//! and time steps drawn from the block's interesting intervals (0, 1 ms, one tick or the preset
//! and one either side, a long gap; IEC timers start 50 ms before the 32-bit clock wraps).

use std::format;
use std::string::{String, ToString};
use std::vec;
use std::vec::Vec;

use super::block::InputKind;
use super::registry::{lookup, BlockOptions};
use super::runner::run;

/// Generated traces per block (besides the example).
pub const TRACES_PER_BLOCK: usize = 20;
/// Rows per generated trace.
pub const ROWS: usize = 40;

/// One vector file.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Vector {
    /// The directory (block name, with the integer type for IEC counters, e.g. `CTUD-SINT`).
    pub dir: String,
    /// The file name.
    pub file: String,
    /// The block name for `plc-timers check`.
    pub block: &'static str,
    /// `--type` for `check`, for IEC counters.
    pub int_type: Option<&'static str>,
    /// The CSV text: inputs, preset column, outputs.
    pub csv: String,
}

struct Rng(u64);

impl Rng {
    fn next(&mut self) -> u64 {
        self.0 ^= self.0 << 13;
        self.0 ^= self.0 >> 7;
        self.0 ^= self.0 << 17;
        self.0
    }

    fn pick<'a, T>(&mut self, items: &'a [T]) -> &'a T {
        &items[(self.next() % items.len() as u64) as usize]
    }
}

const EXAMPLES: &[(&str, &str, &str, &str)] = &[
    (
        "S_PULSE",
        "tv",
        "S5T#50MS",
        include_str!("../../../examples/traces/s_pulse.csv"),
    ),
    (
        "S_PEXT",
        "tv",
        "S5T#50MS",
        include_str!("../../../examples/traces/s_pext.csv"),
    ),
    (
        "S_ODT",
        "tv",
        "S5T#50MS",
        include_str!("../../../examples/traces/s_odt.csv"),
    ),
    (
        "S_ODTS",
        "tv",
        "S5T#50MS",
        include_str!("../../../examples/traces/s_odts.csv"),
    ),
    (
        "S_OFFDT",
        "tv",
        "S5T#50MS",
        include_str!("../../../examples/traces/s_offdt.csv"),
    ),
    (
        "TP",
        "pt",
        "T#100ms",
        include_str!("../../../examples/traces/tp.csv"),
    ),
    (
        "TON",
        "pt",
        "T#500ms",
        include_str!("../../../examples/traces/ton.csv"),
    ),
    (
        "TOF",
        "pt",
        "T#200ms",
        include_str!("../../../examples/traces/tof.csv"),
    ),
    (
        "TONR",
        "pt",
        "T#300ms",
        include_str!("../../../examples/traces/tonr.csv"),
    ),
    (
        "CTU",
        "pv",
        "3",
        include_str!("../../../examples/traces/ctu.csv"),
    ),
    (
        "CTD",
        "pv",
        "2",
        include_str!("../../../examples/traces/ctd.csv"),
    ),
    (
        "CTUD",
        "pv",
        "4",
        include_str!("../../../examples/traces/ctud.csv"),
    ),
    (
        "S_CU",
        "pv",
        "C#998",
        include_str!("../../../examples/traces/s_cu.csv"),
    ),
    (
        "S_CD",
        "pv",
        "C#2",
        include_str!("../../../examples/traces/s_cd.csv"),
    ),
    (
        "S_CUD",
        "pv",
        "C#5",
        include_str!("../../../examples/traces/s_cud.csv"),
    ),
];

const TYPES: [(&str, i128, i128); 8] = [
    ("SINT", i8::MIN as i128, i8::MAX as i128),
    ("INT", i16::MIN as i128, i16::MAX as i128),
    ("DINT", i32::MIN as i128, i32::MAX as i128),
    ("LINT", i64::MIN as i128, i64::MAX as i128),
    ("USINT", 0, u8::MAX as i128),
    ("UINT", 0, u16::MAX as i128),
    ("UDINT", 0, u32::MAX as i128),
    ("ULINT", 0, u64::MAX as i128),
];

/// Presets and time steps for a block.
fn presets_and_steps(block: &str, int_type: Option<(i128, i128)>) -> (Vec<String>, Vec<u64>) {
    let s = |v: &[&str]| v.iter().map(|x| x.to_string()).collect::<Vec<_>>();
    match block {
        "S_PULSE" | "S_PEXT" | "S_ODT" | "S_ODTS" | "S_OFFDT" => (
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
        "TP" | "TON" | "TOF" | "TONR" => (
            s(&["T#0MS", "-5", "T#1MS", "T#30MS", "T#100MS"]),
            vec![0, 1, 29, 30, 31, 50, 100, 5_000],
        ),
        "S_CU" | "S_CD" | "S_CUD" => (
            s(&["C#0", "C#1", "C#3", "C#998", "C#999", "W#16#0500"]),
            vec![1],
        ),
        _ => {
            let (min, max) = int_type.unwrap_or((i16::MIN as i128, i16::MAX as i128));
            let pvs = [0, 1, 3, -1, min, max, max - 1, min + 1]
                .into_iter()
                .filter(|v| (min..=max).contains(v))
                .map(|v| v.to_string())
                .collect();
            (pvs, vec![1])
        }
    }
}

fn generate(
    block: &'static str,
    int_type: Option<&'static str>,
    seed: u64,
) -> Result<Vec<Vector>, String> {
    let options = BlockOptions {
        int_type: int_type.map(String::from),
        ..BlockOptions::default()
    };
    let probe = lookup(block, &options).map_err(|e| e.to_string())?;
    let inputs = probe.inputs();
    let timed = probe.requires_time();
    let limits = int_type
        .and_then(|t| TYPES.iter().find(|x| x.0 == t))
        .map(|x| (x.1, x.2));
    let (presets, steps) = presets_and_steps(block, limits);
    let dir = match int_type {
        Some(t) => format!("{block}-{t}"),
        None => block.to_string(),
    };
    let mut rng = Rng(seed);
    let mut out = Vec::new();
    let reference = |text: &str| -> Result<String, String> {
        let mut b = lookup(block, &options).map_err(|e| e.to_string())?;
        let mut buf = Vec::new();
        run(b.as_mut(), text.as_bytes(), &[], &mut buf).map_err(|e| e.to_string())?;
        String::from_utf8(buf).map_err(|e| e.to_string())
    };
    // The example, with its preset as a column.
    if let Some(&(_, _, value, text)) = EXAMPLES.iter().find(|e| e.0 == block) {
        let mut with_preset = String::new();
        let preset_name = inputs
            .iter()
            .find(|i| matches!(i.kind, InputKind::Preset { .. }))
            .map(|i| i.name);
        for line in text
            .lines()
            .filter(|l| !l.starts_with('#') && !l.trim().is_empty())
        {
            let extra = if with_preset.is_empty() {
                preset_name.unwrap_or("")
            } else {
                value
            };
            with_preset.push_str(&format!("{line},{extra}\n"));
        }
        if int_type.is_none() || int_type == Some("INT") {
            out.push(Vector {
                dir: dir.clone(),
                file: "example.csv".into(),
                block,
                int_type,
                csv: reference(&with_preset)?,
            });
        }
    }
    for k in 0..TRACES_PER_BLOCK {
        let mut header: Vec<&str> = Vec::new();
        if timed {
            header.push("t_ms");
        }
        header.extend(inputs.iter().map(|i| i.name));
        let mut text = header.join(",");
        text.push('\n');
        let preset = rng.pick(&presets).clone();
        // IEC timers start just before the 32-bit clock wraps.
        let mut t: u64 = if block.starts_with('T') {
            (1 << 32) - 50
        } else {
            0
        };
        let mut bits = 0u64;
        for _ in 0..ROWS {
            t += *rng.pick(&steps);
            bits ^= rng.next() & rng.next();
            let mut fields: Vec<String> = Vec::new();
            if timed {
                fields.push(t.to_string());
            }
            for (i, input) in inputs.iter().enumerate() {
                fields.push(match input.kind {
                    InputKind::Bool => {
                        // Resets and loads are rarer than the counting and start signals.
                        let rare = matches!(input.name, "R" | "LD" | "FR");
                        let on = bits >> i & 1 != 0 && (!rare || rng.next() % 3 == 0);
                        String::from(if on { "1" } else { "0" })
                    }
                    InputKind::Preset { .. } => preset.clone(),
                });
            }
            text.push_str(&fields.join(","));
            text.push('\n');
        }
        out.push(Vector {
            dir: dir.clone(),
            file: format!("random-{k:02}.csv"),
            block,
            int_type,
            csv: reference(&text)?,
        });
    }
    Ok(out)
}

/// Every vector: each block, and each integer type of the IEC counters.
pub fn all() -> Result<Vec<Vector>, String> {
    let mut v = Vec::new();
    for (i, &(block, ..)) in EXAMPLES.iter().enumerate() {
        if matches!(block, "CTU" | "CTD" | "CTUD") {
            for (j, &(ty, ..)) in TYPES.iter().enumerate() {
                v.extend(generate(
                    block,
                    Some(ty),
                    0x5EED_0000 + (i * 16 + j) as u64 + 1,
                )?);
            }
        } else {
            v.extend(generate(block, None, 0x5EED_0000 + (i * 16) as u64 + 1)?);
        }
    }
    Ok(v)
}

/// The README written beside the vectors.
pub const README: &str = "plc-timers test vectors\n\
=======================\n\n\
One directory per block (IEC counters: one per integer type, e.g. CTUD-SINT). Each CSV file is a\n\
trace in the format of the plc-timers command-line contract: the inputs (t_ms for timers, the\n\
boolean inputs, the preset as a column) followed by the reference outputs (S5 timers Q,BI,BCD;\n\
IEC timers Q,ET; CTU/CTD Q,CV; CTUD QU,QD,CV; S5 counters Q,CV,CV_BCD).\n\n\
example.csv is the crate's example trace; random-NN.csv are generated: clustered edges, presets\n\
at edge values, time steps around ticks and presets, IEC timers across the 2^32 ms clock wrap.\n\n\
Replay a file through your implementation, write the same columns, and compare with\n\
  plc-timers check BLOCK FILE          (add --type T for IEC counters)\n\
which reports the first differing line and column (exit status 1).\n";
