//! The requirements catalog (`spec/requirements/*.toml`) is well-formed and complete, and the
//! committed traceability matrix (`spec/matrix.md`) is the one it generates.
//!
//! Regenerate the matrix with `UPDATE_SPEC=1 cargo test --test spec_catalog`.

use std::collections::BTreeSet;
use std::fmt::Write as _;
use std::fs;
use std::path::Path;

use serde::Deserialize;

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct Catalog {
    requirement: Vec<Requirement>,
}

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct Requirement {
    id: String,
    rule: String,
    source: String,
    reason: Option<String>,
    proofs: Vec<String>,
    tests: Vec<String>,
}

#[path = "support/requirement_files.rs"]
mod requirement_files;
use requirement_files::FAMILIES;

/// Every `spec/requirements/*.toml` (`requirement_files::stems`), with its title and contents.
fn load_all() -> Vec<(String, String, Catalog)> {
    let stems = requirement_files::stems();
    stems
        .into_iter()
        .map(|stem| {
            let path = format!("spec/requirements/{stem}.toml");
            let text = fs::read_to_string(&path).unwrap_or_else(|e| panic!("{path}: {e}"));
            let catalog = toml::from_str(&text).unwrap_or_else(|e| panic!("{path}: {e}"));
            let title = FAMILIES
                .iter()
                .find(|(f, _)| *f == stem)
                .map_or(stem.clone(), |(_, t)| String::from(*t));
            (stem, title, catalog)
        })
        .collect()
}

/// The line index of `fn function` in `text` (with or without `pub`), if any.
fn definition(text: &str, function: &str) -> Option<usize> {
    text.lines().position(|l| {
        let l = l.trim_start();
        let l = l.strip_prefix("pub ").unwrap_or(l);
        l.strip_prefix("fn ").is_some_and(|rest| {
            rest.strip_prefix(function)
                .is_some_and(|after| after.starts_with('(') || after.starts_with('<'))
        })
    })
}

/// Where tests live: the core's, the trace engine's and the command's.
const TEST_DIRS: &[&str] = &[
    "tests/",
    "proofs/",
    "src/",
    "trace/tests/",
    "trace/src/",
    "cli/tests/",
    "cli/src/",
];

/// Whether `file::function` names a function defined in that file; with `test`, also that the
/// file is under one of [`TEST_DIRS`] and the function carries `#[test]` (among the attribute
/// and doc-comment lines right above it, which also covers functions inside `proptest!`) or is
/// defined in a `quickcheck!` block.
fn exists(reference: &str, test: bool) -> Result<(), String> {
    let (file, function) = reference
        .split_once("::")
        .ok_or(format!("`{reference}` is not file::function"))?;
    if test && !TEST_DIRS.iter().any(|d| file.starts_with(d)) {
        return Err(format!(
            "`{reference}`: tests live in {}",
            TEST_DIRS.join(", ")
        ));
    }
    let text = fs::read_to_string(Path::new(file)).map_err(|e| format!("{file}: {e}"))?;
    let line = definition(&text, function).ok_or(format!("no `fn {function}` in {file}"))?;
    if test {
        let lines: Vec<&str> = text.lines().collect();
        let marked = lines[..line]
            .iter()
            .rev()
            .map(|l| l.trim())
            .take_while(|l| l.starts_with("#[") || l.starts_with("//") || l.ends_with(")]"))
            .any(|l| l == "#[test]");
        // Or the function is one of a `quickcheck!` block's (the macro makes each a test): the
        // nearest item-level line above it opens such a block.
        let in_quickcheck = lines[..line]
            .iter()
            .rev()
            .find(|l| !l.starts_with(' ') && !l.trim().is_empty())
            .is_some_and(|l| l.starts_with("quickcheck! {"));
        if !marked && !in_quickcheck {
            return Err(format!("`fn {function}` in {file} is not a #[test]"));
        }
    }
    Ok(())
}

/// The short names a source may cite: the first column of every table in `spec/sources.md`
/// (the manuals, books and implementations), and the trace-format contract of the CLI.
fn source_names() -> Vec<String> {
    let text = fs::read_to_string("spec/sources.md").unwrap_or_default();
    let mut names: Vec<String> = text
        .lines()
        .filter_map(|l| l.strip_prefix("| "))
        .filter_map(|l| l.split(" |").next())
        .map(str::trim)
        .filter(|n| !n.is_empty() && *n != "short name" && !n.starts_with("---"))
        .map(String::from)
        .collect();
    names.push("trace-format contract".into());
    names
}

fn check(family: &str, r: &Requirement, ids: &mut BTreeSet<String>) -> Vec<String> {
    let mut errors = Vec::new();
    let mut err = |m: String| errors.push(format!("{family}: {}: {m}", r.id));
    let well_formed = r.id.split('-').count() >= 3
        && r.id
            .chars()
            .all(|c| c.is_ascii_uppercase() || c.is_ascii_digit() || c == '-')
        && r.id
            .rsplit('-')
            .next()
            .is_some_and(|n| n.len() == 2 && n.chars().all(|c| c.is_ascii_digit()));
    if !well_formed {
        err("ID must look like FAMILY-TOPIC-NN".into());
    }
    if !ids.insert(r.id.clone()) {
        err("duplicate ID".into());
    }
    if r.rule.trim().len() < 20 {
        err("the rule must be stated in a sentence".into());
    }
    let cites_source = source_names().iter().any(|s| r.source.contains(s.as_str()));
    let decision = r.source.contains("decision");
    if !cites_source && !decision {
        err(format!(
            "source `{}` cites no source of spec/sources.md and is no decision",
            r.source
        ));
    }
    if decision && r.reason.as_deref().is_none_or(|s| s.trim().is_empty()) {
        err("a decision needs its reason".into());
    }
    if !r.proofs.iter().any(|p| p.starts_with("proofs/")) {
        err("no proof property (a function in proofs/)".into());
    }
    if r.tests.is_empty() {
        err("no test".into());
    }
    for (reference, test) in r
        .proofs
        .iter()
        .map(|p| (p, false))
        .chain(r.tests.iter().map(|t| (t, true)))
    {
        if let Err(e) = exists(reference, test) {
            err(e);
        }
    }
    errors
}

fn cell(items: &[String]) -> String {
    items
        .iter()
        .map(|s| format!("`{s}`"))
        .collect::<Vec<_>>()
        .join("<br>")
}

fn matrix(catalogs: &[(String, String, Catalog)]) -> String {
    let mut m = String::from(
        "<!-- Generated by tests/spec_catalog.rs from spec/requirements/*.toml; do not edit.\n     \
         Regenerate: UPDATE_SPEC=1 cargo test --test spec_catalog -->\n\n# Traceability matrix\n\n\
         Every requirement, its source, and the proof properties and tests that cover it.\n",
    );
    for (_, title, catalog) in catalogs {
        let _ = write!(
            m,
            "\n## {title}\n\n| ID | Rule | Source | Proofs | Tests |\n|---|---|---|---|---|\n"
        );
        for r in &catalog.requirement {
            let source = match &r.reason {
                Some(reason) => format!("{} — *{}*", r.source, reason.trim()),
                None => r.source.clone(),
            };
            let _ = writeln!(
                m,
                "| {} | {} | {} | {} | {} |",
                r.id,
                r.rule.replace('|', "\\|"),
                source.replace('|', "\\|"),
                cell(&r.proofs),
                cell(&r.tests)
            );
        }
    }
    m
}

/// Whether a requirement is behavioural: every requirement of the core's families (every file
/// but a front end's, so a new family's file is checked too) except the pure equivalence ones
/// (`*-EQUIV-*`), which keep their equivalence properties. A front end's assertions (the CLI's)
/// live in its own tests (`trace/tests/`, `cli/tests/`), which its engineer maintains.
fn behavioural(family: &str, id: &str) -> bool {
    !requirement_files::FRONT_ENDS.contains(&family) && !id.contains("-EQUIV-")
}

/// The text of every `.rs` file under `dir`.
fn sources(dir: &str) -> Vec<(String, String)> {
    let mut out = Vec::new();
    let Ok(entries) = fs::read_dir(dir) else {
        return out;
    };
    for e in entries.flatten() {
        let path = e.path();
        if path.is_dir() {
            out.extend(sources(&path.to_string_lossy()));
        } else if path.extension().is_some_and(|x| x == "rs") {
            let text = fs::read_to_string(&path).unwrap_or_default();
            out.push((path.to_string_lossy().into_owned(), text));
        }
    }
    out
}

/// Whether `text` has an assertion whose message starts with `id`: a string literal beginning
/// `"ID:` or `"ID ` inside an `assert!`, `assert_eq!`, `assert_ne!` or `prop_assert*!` call
/// (the macro name within the 600 bytes before it, with no statement end in between).
fn asserts_id(text: &str, id: &str) -> bool {
    [format!("\"{id}:"), format!("\"{id} ")]
        .iter()
        .any(|needle| {
            text.match_indices(needle.as_str()).any(|(at, _)| {
                let from = text[..at]
                    .char_indices()
                    .rev()
                    .nth(600)
                    .map_or(0, |(i, _)| i);
                let before = &text[from..at];
                ["assert", "check"].iter().any(|name| {
                    before
                        .rfind(name)
                        .is_some_and(|m| !before[m..].contains(";\n"))
                })
            })
        })
}

/// Every behavioural requirement has a property of its own in `proofs/`: an assertion whose
/// message starts with its ID.
fn missing_assertions(catalogs: &[(String, String, Catalog)]) -> Vec<String> {
    let proofs = sources("proofs");
    catalogs
        .iter()
        .flat_map(|(family, _, c)| c.requirement.iter().map(move |r| (family, r)))
        .filter(|(family, r)| behavioural(family, &r.id))
        .filter(|(_, r)| !proofs.iter().any(|(_, text)| asserts_id(text, &r.id)))
        .map(|(family, r)| {
            format!(
                "{family}: {}: no assertion in proofs/ whose message starts with it",
                r.id
            )
        })
        .collect()
}

/// The requirement IDs named by the `check_ids(&[…])`, `check_only(&[…])` and
/// `require_checked(&[…], …)` calls in proofs/,
/// each inside a `#[test]` driver (`cargo test` runs it), and the errors found: a call outside a
/// test. At run time such a driver fails unless an assertion of each ID it names was reached
/// (`check!`/`check_eq!`, proofs/cover.rs), so an ID in this set was checked with its premise
/// true on every `cargo test`.
fn driver_checked_ids() -> (BTreeSet<String>, Vec<String>) {
    let mut ids = BTreeSet::new();
    let mut errors = Vec::new();
    for (path, text) in sources("proofs") {
        for call in ["check_ids(", "check_only(", "require_checked("] {
            for (at, _) in text.match_indices(call) {
                // A call with a literal list (not the definition in proofs/cover.rs).
                let Some(list) = text[at + call.len()..].trim_start().strip_prefix("&[") else {
                    continue;
                };
                let Some(end) = list.find(']') else {
                    errors.push(format!("{path}: unterminated {call}"));
                    continue;
                };
                let driver = text[..at]
                    .rfind("\nfn ")
                    .map(|f| &text[f + 4..])
                    .and_then(|rest| rest.split('(').next())
                    .unwrap_or("");
                if driver.is_empty() {
                    errors.push(format!("{path}: a `{call}` outside a function"));
                    continue;
                }
                if let Err(e) = exists(&format!("{path}::{driver}"), true) {
                    errors.push(format!(
                        "{path}: `{call}` in {driver}, which is not a test: {e}"
                    ));
                    continue;
                }
                ids.extend(
                    list[..end]
                        .split(',')
                        .map(|s| s.trim().trim_matches('"'))
                        .filter(|s| !s.is_empty())
                        .map(String::from),
                );
            }
        }
    }
    (ids, errors)
}

/// Every behavioural requirement is checked by a driver that `cargo test` runs: it is named by
/// a `check_ids`/`check_only` call of a `#[test]` driver in proofs/, which fails unless one of
/// the requirement's assertions ran with its premise true. (And it has a property of its own:
/// an assertion in proofs/ whose message starts with its ID.)
#[test]
fn every_behavioural_requirement_is_checked_by_a_driver() {
    let catalogs = load_all();
    let (checked_ids, errors) = driver_checked_ids();
    assert!(errors.is_empty(), "{}", errors.join("\n"));
    let unchecked: Vec<String> = catalogs
        .iter()
        .flat_map(|(family, _, c)| c.requirement.iter().map(move |r| (family, r)))
        .filter(|(family, r)| behavioural(family, &r.id) && !checked_ids.contains(&r.id))
        .map(|(family, r)| {
            format!(
                "{family}: {}: no driver in proofs/ names it in check_ids or check_only",
                r.id
            )
        })
        .collect();
    assert!(unchecked.is_empty(), "{}", unchecked.join("\n"));
    let missing = missing_assertions(&catalogs);
    assert!(missing.is_empty(), "{}", missing.join("\n"));
    let checked = catalogs
        .iter()
        .flat_map(|(f, _, c)| c.requirement.iter().map(move |r| (f, r)))
        .filter(|(f, r)| behavioural(f, &r.id))
        .count();
    assert!(
        checked >= 50,
        "only {checked} behavioural requirements found"
    );
}

/// The assertion check itself: a message inside an assertion counts, a comment or a plain
/// string does not, nor does another ID that shares a prefix.
#[test]
fn assertion_check_rejects_look_alikes() {
    assert!(asserts_id(
        "assert!(x, \"S5TMR-R-01: R resets\");",
        "S5TMR-R-01"
    ));
    assert!(asserts_id(
        "assert_eq!(\n a,\n b,\n \"SC-Q-01 {name}\"\n);",
        "SC-Q-01"
    ));
    assert!(!asserts_id("// \"S5TMR-R-01: R resets\"", "S5TMR-R-01"));
    assert!(!asserts_id(
        "assert!(x);\nlet m = \"S5TMR-R-01: no\";",
        "S5TMR-R-01"
    ));
    assert!(!asserts_id(
        "assert!(x, \"S5TMR-R-011: other\");",
        "S5TMR-R-01"
    ));
    assert!(!asserts_id(
        "cover!(x, \"S5TMR-R-01: a cover\");",
        "S5TMR-R-01"
    ));
}

#[test]
fn catalog_is_complete_and_matrix_is_current() {
    let catalogs = load_all();
    assert!(!catalogs.is_empty(), "no spec/requirements/*.toml");
    let mut ids = BTreeSet::new();
    let errors: Vec<String> = catalogs
        .iter()
        .flat_map(|(family, _, c)| c.requirement.iter().map(move |r| (family.as_str(), r)))
        .flat_map(|(family, r)| check(family, r, &mut ids))
        .collect();
    let generated = matrix(&catalogs);
    let path = "spec/matrix.md";
    if std::env::var_os("UPDATE_SPEC").is_some() {
        fs::write(path, &generated).expect("write spec/matrix.md");
    }
    assert!(errors.is_empty(), "catalog errors:\n{}", errors.join("\n"));
    let committed = fs::read_to_string(path).unwrap_or_default();
    assert!(
        committed == generated,
        "spec/matrix.md is stale; regenerate it with `UPDATE_SPEC=1 cargo test --test spec_catalog`"
    );
}

/// The checker itself: a reference to a missing function, a decision without a reason and a
/// requirement without a proof are all reported.
#[test]
fn checker_rejects_bad_entries() {
    let bad = Requirement {
        id: "X-BAD-01".into(),
        rule: "A rule long enough to be a sentence.".into(),
        source: "decision".into(),
        reason: None,
        proofs: vec!["tests/s5_props.rs::fixed_trace_ticks_follow_clock_phase".into()],
        tests: vec!["tests/s5_props.rs::no_such_function".into()],
    };
    let errors = check("test", &bad, &mut BTreeSet::new());
    assert!(
        errors.iter().any(|e| e.contains("needs its reason")),
        "{errors:?}"
    );
    assert!(
        errors.iter().any(|e| e.contains("no proof property")),
        "{errors:?}"
    );
    assert!(
        errors
            .iter()
            .any(|e| e.contains("no `fn no_such_function`")),
        "{errors:?}"
    );
    // A malformed or duplicate ID, a test that is no #[test], a test outside the test trees.
    let mut ids = BTreeSet::from([String::from("CLI-RUN-01")]);
    let bad = Requirement {
        id: "CLI-RUN-01".into(),
        rule: "A rule long enough to be a sentence.".into(),
        source: "LAD manual §9.5".into(),
        reason: None,
        proofs: vec!["proofs/iec.rs::prop_step_equivalence".into()],
        tests: vec![
            "tests/spec_catalog.rs::exists".into(),
            "README.md::anything".into(),
        ],
    };
    let errors = check("test", &bad, &mut ids);
    for expected in [
        "duplicate ID",
        "`fn exists` in tests/spec_catalog.rs is not a #[test]",
        "`README.md::anything`: tests live in tests/, proofs/, src/, trace/tests/",
    ] {
        assert!(
            errors.iter().any(|e| e.contains(expected)),
            "{expected}: {errors:?}"
        );
    }
    let mut fresh = BTreeSet::new();
    let bad_id = Requirement {
        id: "cli-run-1".into(),
        ..bad
    };
    let errors = check("test", &bad_id, &mut fresh);
    assert!(
        errors.iter().any(|e| e.contains("FAMILY-TOPIC-NN")),
        "{errors:?}"
    );
}
