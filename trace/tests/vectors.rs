//! The test vectors: a golden digest of everything `vectors` writes, a replay of every vector
//! through the reference and the optimized implementation, and `check`'s explanation on every
//! output of the aimed vectors (each names requirements of the catalog).

use plc_timers::catalog::ValueKind;
use plc_timers_trace::vectors::{self, Vector};
use plc_timers_trace::{check, Implementation};
use sha2::{Digest, Sha256};

/// The SHA-256 of every vector's directory, file name and text, and the README, in order.
const GOLDEN: &str = "b5a13ac144b18e227b1bc73c8a32e604d75a8db59d15f445909d841eeb91aae8";

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

/// CLI-LTIME-04: the LTIME timers have their own vectors (t_ns, `--type LTIME`), with presets
/// past TIME's range and gaps past 2^63 ns. By TON's rules (IEC-EXPIRY-01, LTIMER-CLOCK-01),
/// IN held across a gap of g ns under PT gives ET = min(g, PT) and Q = (g >= PT): the 30-day
/// preset one nanosecond short of and at 30 days, and LTIME's largest PT after 2^63 + 1 ns.
#[test]
fn ltime_vectors() {
    let all = vectors::all().expect("vectors generate");
    for block in ["TP", "TON", "TOF", "TONR"] {
        let dir = format!("{block}-LTIME");
        let mine: Vec<&Vector> = all.iter().filter(|v| v.dir == dir).collect();
        assert!(mine.len() > 20, "CLI-LTIME-04: {dir}");
        for v in &mine {
            assert!(v.csv.starts_with("t_ns,"), "CLI-LTIME-04: {dir}/{}", v.file);
            assert!(
                v.check_command().contains(" --type LTIME "),
                "{}",
                v.check_command()
            );
        }
        assert!(
            mine.iter()
                .any(|v| v.file.starts_with("random-") && v.csv.contains("LT#30D")),
            "CLI-LTIME-04: {dir}: a random trace with LT#30D"
        );
    }
    let gaps = all
        .iter()
        .find(|v| v.dir == "TON-LTIME" && v.file == "long-gaps.csv")
        .expect("TON-LTIME/long-gaps.csv");
    let rows: Vec<Vec<&str>> = gaps
        .csv
        .lines()
        .skip(1)
        .map(|l| l.split(',').collect())
        .collect();
    let header: Vec<&str> = gaps
        .csv
        .lines()
        .next()
        .expect("a header")
        .split(',')
        .collect();
    let col = |name: &str| header.iter().position(|h| *h == name).expect("a column");
    let (t, input, pt, q, et) = (col("t_ns"), col("IN"), col("PT"), col("Q"), col("ET"));
    let ns = |lit: &str| -> u64 {
        lit.parse::<plc_timers::time::LTime>()
            .expect("an LTIME literal")
            .as_nanos()
            .try_into()
            .expect("a positive preset")
    };
    let mut seen = Vec::new();
    for w in rows.windows(2) {
        let (a, b) = (&w[0], &w[1]);
        if a[input] == "1" && b[input] == "1" {
            let g: u64 = b[t].parse::<u64>().expect("t") - a[t].parse::<u64>().expect("t");
            let p = ns(b[pt]);
            assert_eq!(
                b[et],
                g.min(p).to_string(),
                "CLI-LTIME-04: ET after a gap of {g} ns"
            );
            assert_eq!(
                b[q],
                if g >= p { "1" } else { "0" },
                "CLI-LTIME-04: Q after {g} ns"
            );
            seen.push(g);
        }
    }
    assert!(
        seen.iter().any(|&g| g > 1 << 63),
        "a gap past 2^63 ns: {seen:?}"
    );
    assert!(
        seen.contains(&(30 * 86_400 * 1_000_000_000 - 1)),
        "{seen:?}"
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
            assert!(report.rows >= 5 && report.compared.len() == v.spec.block().outputs().len());
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
        let width = v.spec.block().outputs().len();
        let fields0 = lines[0].split(',').count();
        // Every row of the short traces, every 7th of the long ones.
        let stride = if lines.len() > 120 { 7 } else { 1 };
        for row in (1..lines.len()).step_by(stride) {
            for col in fields0 - width..fields0 {
                let mut fields: Vec<String> = lines[row].split(',').map(String::from).collect();
                let old = fields[col].clone();
                fields[col] = match v.spec.block().outputs()[col + width - fields0].kind() {
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
