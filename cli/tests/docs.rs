//! The timing diagrams in `docs/` are the ones the renderer draws from `examples/traces/` now.
//! Regenerate them with `UPDATE_DOCS=1 cargo test --test docs`.

use std::fs;

use plc_timers::trace::{diagram, lookup, record, BlockOptions, PresetOption};

/// (example file, block, preset option, value): one per block kind.
const EXAMPLES: &[(&str, &str, &str, &str)] = &[
    ("s_pulse", "S_PULSE", "tv", "S5T#50MS"),
    ("s_pext", "S_PEXT", "tv", "S5T#50MS"),
    ("s_odt", "S_ODT", "tv", "S5T#50MS"),
    ("s_odts", "S_ODTS", "tv", "S5T#50MS"),
    ("s_offdt", "S_OFFDT", "tv", "S5T#50MS"),
    ("tp", "TP", "pt", "T#100ms"),
    ("ton", "TON", "pt", "T#500ms"),
    ("tof", "TOF", "pt", "T#200ms"),
    ("tonr", "TONR", "pt", "T#300ms"),
    ("ctu", "CTU", "pv", "3"),
    ("ctd", "CTD", "pv", "2"),
    ("ctud", "CTUD", "pv", "4"),
    ("s_cu", "S_CU", "pv", "C#998"),
    ("s_cd", "S_CD", "pv", "C#2"),
    ("s_cud", "S_CUD", "pv", "C#5"),
];

#[test]
fn docs_diagrams_are_current() {
    let update = std::env::var_os("UPDATE_DOCS").is_some();
    let mut stale = Vec::new();
    for &(file, block, option, value) in EXAMPLES {
        let mut b = lookup(block, &BlockOptions::default()).expect("known block");
        let trace = fs::read(format!("examples/traces/{file}.csv")).expect("example exists");
        let presets: [PresetOption<'_>; 1] = [(option, value)];
        let rec = record(b.as_mut(), &trace[..], &presets).expect("example runs");
        let svg = diagram::svg(&rec);
        // One waveform per boolean input present and per boolean output, one ramp per integer
        // output, and a preset mark where the block has a ramp.
        let waves = svg.matches("class=\"signal\"").count();
        let bool_outputs = rec
            .outputs
            .iter()
            .filter(|(_, v)| matches!(v[0], plc_timers::trace::Value::Bool(_)))
            .count();
        assert_eq!(waves, rec.inputs.len() + bool_outputs, "{file}");
        assert_eq!(
            svg.matches("class=\"ramp\"").count(),
            1,
            "{file}: one ramp (ET, BI or CV)"
        );
        assert_eq!(
            svg.matches("class=\"preset\"").count(),
            1,
            "{file}: the preset is marked"
        );
        assert!(svg.starts_with("<svg") && svg.ends_with("</svg>\n"));
        let path = format!("docs/{file}.svg");
        if update {
            fs::write(&path, &svg).expect("write docs");
        }
        if fs::read_to_string(&path).ok().as_deref() != Some(svg.as_str()) {
            stale.push(path);
        }
    }
    assert!(
        stale.is_empty(),
        "stale diagrams {stale:?}; regenerate with `UPDATE_DOCS=1 cargo test --test docs`"
    );
}

/// The Q waveform of TON rises where ET reaches PT (t = 2500 in the example): the polyline has a
/// vertical step at that x.
#[test]
fn ton_q_rises_at_expiry() {
    let mut b = lookup("TON", &BlockOptions::default()).expect("TON");
    let trace = fs::read("examples/traces/ton.csv").expect("example");
    let rec = record(b.as_mut(), &trace[..], &[("pt", "T#500ms")]).expect("runs");
    let q = &rec.outputs[0].1;
    let first_on = q
        .iter()
        .position(|v| *v == plc_timers::trace::Value::Bool(true))
        .expect("Q rises");
    assert_eq!(rec.time[first_on], 2500);
    let svg = diagram::svg(&rec);
    let line = svg
        .lines()
        .find(|l| l.contains("data-name=\"Q\""))
        .expect("Q waveform");
    let t0 = rec.time[0] as f64;
    let t_end = *rec.time.last().expect("rows") as f64 * 1.08;
    let x = 80.0 + (2500.0 - t0) / (t_end - t0) * (900.0 - 80.0 - 24.0);
    assert!(
        line.contains(&format!("{x:.1},")),
        "a step at x = {x:.1}: {line}"
    );
}
