//! The test vectors replay cleanly through `check`, for the reference and for the optimized
//! implementation (a cross-check of the two on 700+ traces), and `check` catches a changed output.

use plc_timers::trace::{check, lookup, vectors, BlockOptions, Implementation};

fn options(v: &vectors::Vector, implementation: Implementation) -> BlockOptions {
    BlockOptions {
        int_type: v.int_type.map(String::from),
        implementation,
    }
}

#[test]
fn vectors_replay_through_reference_and_optimized() {
    let all = vectors::all().expect("vectors generate");
    assert!(all.len() > 700, "{} vectors", all.len());
    for v in &all {
        for implementation in [Implementation::Reference, Implementation::Optimized] {
            let mut block = lookup(v.block, &options(v, implementation)).expect("block");
            let report =
                check(block.as_mut(), v.csv.as_bytes(), &[]).expect("vector is well-formed");
            assert_eq!(
                report.difference, None,
                "{}/{} {implementation:?}",
                v.dir, v.file
            );
            assert!(report.rows >= 5 && !report.compared.is_empty());
        }
    }
}

#[test]
fn check_catches_a_changed_output() {
    let all = vectors::all().expect("vectors generate");
    let v = all
        .iter()
        .find(|v| v.dir == "TON" && v.file == "example.csv")
        .expect("TON example");
    // Change the last field (ET) of the 4th data row.
    let mut lines: Vec<String> = v.csv.lines().map(String::from).collect();
    let row = &mut lines[4];
    let cut = row.rfind(',').expect("fields");
    row.truncate(cut + 1);
    row.push_str("12345");
    let changed = lines.join("\n");
    let mut block = lookup("TON", &BlockOptions::default()).expect("TON");
    let report = check(block.as_mut(), changed.as_bytes(), &[]).expect("well-formed");
    let d = report.difference.expect("a difference");
    assert_eq!(
        (d.line, d.name.as_str(), d.found.as_str()),
        (5, "ET", "12345")
    );
}
