//! The README's and spec/cli.md's examples are run against the real binary (trycmd, every
//! `console` block), and the example traces name the command the README gives.

mod common;

use plc_timers_trace::examples;

/// CLI-DOC-01: every `console` block of README.md and spec/cli.md gives exactly the output
/// shown. (`TRYCMD=overwrite cargo test -p plc-timers-cli --test readme` rewrites them.)
#[test]
fn readme_and_spec_examples() {
    std::env::set_current_dir(common::root()).expect("the repository's root");
    trycmd::TestCases::new()
        .register_bin(
            "plc-timers",
            std::path::Path::new(env!("CARGO_BIN_EXE_plc-timers")),
        )
        .case("README.md")
        .case("spec/cli.md");
}

/// CLI-DOC-01: the README's main command is the first line of the TON example, every example's
/// first line is a command that the README's form covers, and the README says how to install.
#[test]
fn examples_name_the_readme_command() {
    let readme = std::fs::read_to_string(common::root().join("README.md")).expect("README");
    let ton = examples::of(plc_timers::catalog::Block::Ton).expect("TON example");
    let main = format!("cargo run --release -- {}", ton.command);
    assert_eq!(
        main,
        "cargo run --release -- run TON --pt T#500ms examples/traces/ton.csv"
    );
    assert!(
        readme.contains(&format!("\n{main}\n")),
        "the README gives `{main}`"
    );
    for e in examples::all().expect("examples") {
        assert!(e
            .text
            .starts_with(&format!("{}{}\n", examples::COMMAND_PREFIX, e.command)));
    }
    assert!(
        readme.contains("cargo install --path cli"),
        "the install command"
    );
    // Every command the README quotes for an example is that example's first line.
    for line in readme.lines() {
        if let Some(pos) = line.find("cargo run --release -- run ") {
            let quoted = line[pos..].split('`').next().unwrap_or_default().trim();
            assert!(
                examples::all()
                    .expect("examples")
                    .iter()
                    .any(|e| quoted == format!("cargo run --release -- {}", e.command)),
                "`{quoted}` is no example's first line"
            );
        }
    }
}
