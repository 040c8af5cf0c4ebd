//! The requirement files of `spec/requirements/`, shared by the tests that read the catalog
//! (`spec_catalog.rs`, `rule_table.rs`), so that both see the same files in the same order and a
//! new family's file cannot be left out of one of them.

use std::fs;

/// The families whose order is fixed (the order of the `Rule` enum and of `spec/matrix.md`),
/// with the title the matrix gives each.
pub const FAMILIES: [(&str, &str); 5] = [
    ("time", "Time formats (S5TIME, TIME, LTIME)"),
    ("s5", "S5 timers"),
    ("iec", "IEC timers"),
    ("counter", "Counters"),
    ("cli", "Command line"),
];

/// The families of a front end: their requirements name the front end's tests, not a rule a
/// block applies, so they stay out of the no_std core's `Rule` enum (`core_stems`) and live in
/// the catalog, the matrix and `spec_catalog.rs`'s checks only.
pub const FRONT_ENDS: [&str; 1] = ["cli"];

/// The stems whose requirements are the core's `Rule`s: every stem of [`stems`] but the front
/// ends', so a new family's file is in `Rule` unless it is listed in [`FRONT_ENDS`].
#[allow(dead_code)] // used by rule_table.rs, not by spec_catalog.rs
pub fn core_stems() -> Vec<String> {
    stems()
        .into_iter()
        .filter(|s| !FRONT_ENDS.contains(&s.as_str()))
        .collect()
}

/// The stem of every `spec/requirements/*.toml`: the known families in [`FAMILIES`] order (a family
/// whose file does not exist is skipped), then every other file by name.
pub fn stems() -> Vec<String> {
    let mut stems: Vec<String> = fs::read_dir("spec/requirements")
        .expect("spec/requirements")
        .filter_map(|e| {
            let path = e.ok()?.path();
            (path.extension()? == "toml").then(|| path.file_stem()?.to_str().map(String::from))?
        })
        .collect();
    let rank = |s: &str| {
        FAMILIES
            .iter()
            .position(|(f, _)| *f == s)
            .unwrap_or(FAMILIES.len())
    };
    stems.sort_by(|a, b| rank(a).cmp(&rank(b)).then(a.cmp(b)));
    stems
}
