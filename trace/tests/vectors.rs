//! The test vectors: a golden digest of everything `vectors` writes, a replay of every vector
//! through the reference and the optimized implementation, and `check`'s explanation on every
//! output of the aimed vectors (each names requirements of the catalog).

use plc_timers::catalog::ValueKind;
use plc_timers_trace::vectors::{self, Vector};
use plc_timers_trace::{check, Implementation};
use sha2::{Digest, Sha256};

/// The SHA-256 of every vector's directory, file name and text, and the README, in order.
const GOLDEN: &str = "ef641f3a86f96cb51638f3c24225f1e65c31821228df4cb7d22bcd0fdf34a7c2";

fn digest(all: &[Vector]) -> String {
    let mut h = Sha256::new();
    for v in all {
        h.update(format!("{}/{}\n", v.dir, v.file));
        h.update(&v.csv);
    }
    h.update(vectors::readme());
    h.finalize().iter().map(|b| format!("{b:02x}")).collect()
}

/// CLI-VEC-02: any change to what `vectors` generates changes the digest; update it on purpose.
#[test]
fn vectors_golden_digest() {
    let all = vectors::all().expect("vectors generate");
    assert_eq!(
        digest(&all),
        GOLDEN,
        "the vectors changed; if on purpose, update GOLDEN"
    );
}

/// CLI-VEC-01: every vector replays cleanly through `check`, reference and optimized.
#[test]
fn vectors_replay_through_reference_and_optimized() {
    let all = vectors::all().expect("vectors generate");
    assert!(all.len() > 800, "{} vectors", all.len());
    for name in [
        "preset-change.csv",
        "long-gaps.csv",
        "limits.csv",
        "simultaneous.csv",
        "fr.csv",
        "decisions.csv",
    ] {
        assert!(all.iter().any(|v| v.file == name), "{name}");
    }
    for v in &all {
        for implementation in [Implementation::Reference, Implementation::Optimized] {
            let spec = v.spec.with(implementation);
            let report = check(spec, None, None, v.csv.as_bytes()).expect("well-formed");
            assert_eq!(
                report.difference, None,
                "{}/{} {implementation:?}",
                v.dir, v.file
            );
            assert!(report.rows >= 5 && report.compared.len() == v.spec.block.outputs().len());
        }
    }
}

/// CLI-CHECK-02: on the aimed vectors, every output cell changed in turn is found at its line
/// and column, and explained by requirements that exist in the catalog.
#[test]
fn check_explains_every_changed_output() {
    let all = vectors::all().expect("vectors generate");
    let mut explained = std::collections::BTreeSet::new();
    for v in all
        .iter()
        .filter(|v| !v.file.starts_with("random-") || v.file == "random-00.csv")
    {
        let lines: Vec<&str> = v.csv.lines().collect();
        let width = v.spec.block.outputs().len();
        let fields0 = lines[0].split(',').count();
        // Every row of the short traces, every 7th of the long ones.
        let stride = if lines.len() > 120 { 7 } else { 1 };
        for row in (1..lines.len()).step_by(stride) {
            for col in fields0 - width..fields0 {
                let mut fields: Vec<String> = lines[row].split(',').map(String::from).collect();
                let old = fields[col].clone();
                fields[col] = match v.spec.block.outputs()[col + width - fields0].kind() {
                    ValueKind::Bool if old == "1" => "0".into(),
                    ValueKind::Bool => "1".into(),
                    ValueKind::Word if old == "W#16#0FFF" => "W#16#0FFE".into(),
                    ValueKind::Word => "W#16#0FFF".into(),
                    _ => (old.parse::<i128>().expect("an integer") ^ 1).to_string(),
                };
                let mut text = lines[..row].join("\n");
                text.push('\n');
                text.push_str(&fields.join(","));
                text.push('\n');
                let report = check(v.spec, None, None, text.as_bytes()).expect("well-formed");
                let d = report.difference.unwrap_or_else(|| {
                    panic!("{}/{} line {}: no difference", v.dir, v.file, row + 1)
                });
                assert_eq!(
                    (d.line, d.column),
                    (row as u64 + 1, col + 1),
                    "{}/{}",
                    v.dir,
                    v.file
                );
                // The rules come from the core's `Rule` (generated from the catalog).
                for rule in d.why.all() {
                    explained.insert(rule.id());
                }
            }
        }
    }
    // The explanations reach the rules of every family.
    for id in [
        "S5TMR-TICK-01",
        "S5TMR-R-01",
        "S5TMR-FR-01",
        "S5TMR-EXPIRE-01",
        "SP-Q-01",
        "SF-Q-01",
        "IEC-EXPIRY-01",
        "IEC-PT-LATCH-01",
        "IEC-WRAP-01",
        "TON-IN-01",
        "TONR-R-01",
        "IEC-RT-01",
        "CNT-PRIO-01",
        "CNT-SAT-01",
        "CNT-SIMUL-01",
        "CNT-Q-01",
        "SC-SET-01",
        "SC-FR-01",
        "SC-SIMUL-01",
        "SC-Q-01",
    ] {
        assert!(
            explained.contains(id),
            "{id} never explains a difference: {explained:?}"
        );
    }
}
