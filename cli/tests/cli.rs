//! The command-line contract of `shared/trace-format.md`, run against the built binary.

mod common;

use common::plc;
use std::process::Output;

fn stdout(o: &Output) -> String {
    common::text(&o.stdout)
}

fn stderr(o: &Output) -> String {
    common::text(&o.stderr)
}

/// CLI-RUN-01: columns in any order and case, absent boolean = 0, inputs echoed as given.
#[test]
fn run_echoes_inputs_and_appends_outputs() {
    let o = plc(
        &["run", "ton", "--pt", "T#100ms"],
        "in,T_MS\n1,0\ntrue,100\n0,150\n",
    );
    assert!(o.status.success(), "{}", stderr(&o));
    assert_eq!(
        stdout(&o),
        "in,T_MS,Q,ET\n1,0,0,0\ntrue,100,1,100\n0,150,0,0\n"
    );
    // S_ODT alias SD with a TV column and no R column.
    let o = plc(&["run", "SD"], "t_ms,S,TV\n0,1,W#16#0002\n20,1,W#16#0002\n");
    assert_eq!(
        stdout(&o),
        "t_ms,S,TV,Q,BI,BCD\n0,1,W#16#0002,0,2,W#16#0002\n20,1,W#16#0002,1,0,W#16#0000\n"
    );
    // Counters without t_ms, with --type.
    let o = plc(
        &["run", "CTUD", "--type", "usint", "--pv", "255"],
        "CD,CU\n1,0\n",
    );
    assert_eq!(stdout(&o), "CD,CU,QU,QD,CV\n1,0,0,1,0\n");
}

/// CLI-ERR-01: every error class names the line and the column and exits 2.
#[test]
fn bad_input_names_line_and_column_exit_2() {
    let cases: &[(&[&str], &str, &str)] = &[
        (&["run", "NOPE"], "t_ms\n", "unknown block `NOPE`"),
        (
            &["run", "TON", "--pt", "5"],
            "t_ms,IN,X\n",
            "line 1, column 3 (X): unknown column",
        ),
        (
            &["run", "TON", "--pt", "5"],
            "t_ms,IN\n0,1\n5,yes\n",
            "line 3, column 2 (IN)",
        ),
        (
            &["run", "TON", "--pt", "5"],
            "t_ms,IN\n10,1\n9,1\n",
            "line 3, column 1 (t_ms): t_ms goes backwards",
        ),
        (
            &["run", "TON", "--pt", "5"],
            "t_ms,IN\n-1,1\n",
            "line 2, column 1 (t_ms)",
        ),
        (
            &["run", "TON"],
            "t_ms,IN,PT\n0,1,T#24d_20h_31m_23s_648ms\n",
            "line 2, column 3 (PT)",
        ),
        (
            &["run", "SD"],
            "t_ms,S,TV\n0,1,W#16#00A0\n",
            "line 2, column 3 (TV)",
        ),
        (
            &["run", "SD", "--tv", "S5T#3H"],
            "t_ms,S\n0,1\n",
            "option --tv",
        ),
        (
            &["run", "TON"],
            "t_ms,IN\n0,1\n",
            "line 1: TON needs its preset",
        ),
        (
            &["run", "TON", "--pt", "5", "--type", "INT"],
            "t_ms,IN\n",
            "--type applies to CTU",
        ),
        (
            &["run", "CTU", "--pv", "5", "--type", "INT8"],
            "CU\n",
            "unknown integer type",
        ),
        (&["run", "CTU", "--pv", "40000"], "CU\n1\n", "option --pv"),
        (&["run", "S_CU", "--pv", "C#1000"], "CU\n1\n", "option --pv"),
        (
            &["run", "TON", "--pt", "5"],
            "t_ms,IN\n0,1,1\n",
            "line 2: the row has 3 fields",
        ),
        (
            &["run", "TON", "--pt", "5"],
            "IN\n1\n",
            "needs a `t_ms` column",
        ),
        (
            &["run", "TON", "--pt", "5"],
            "t_ms,IN,Q\n",
            "line 1, column 3 (Q): `Q` is an output",
        ),
        (&["run", "TON", "--pt", "5"], "", "the trace is empty"),
        (&["s5time", "S5T#2H46M31S"], "", "above the S5TIME maximum"),
        (
            &["time", "T#1h_75m"],
            "",
            "out of range after a larger unit",
        ),
    ];
    for (args, input, message) in cases {
        let o = plc(args, input);
        assert_eq!(o.status.code(), Some(2), "{args:?}: {}", stderr(&o));
        assert!(
            stderr(&o).contains(message),
            "{args:?}: expected `{message}` in `{}`",
            stderr(&o)
        );
        assert!(!stderr(&o).contains("panicked"), "{args:?}");
    }
}

/// CLI-CONV-01: the contract's own examples (`S5T#2M7S`, `T#2s_200ms`), seed 003's automatic
/// base for 1 s, and the TIME range ends (seed 001 Table 8-21).
#[test]
fn s5time_and_time_conversions() {
    let cases: &[(&[&str], &str)] = &[
        (&["s5time", "S5T#2M7S"], "W#16#2127 127000 S5T#2M7S\n"),
        (&["s5time", "W#16#2001"], "W#16#0100 1000 S5T#1S\n"),
        (
            &["s5time", "s5time#2h_46m_30s"],
            "W#16#3999 9990000 S5T#2H46M30S\n",
        ),
        (&["time", "T#2s_200ms"], "2200 T#2S_200MS\n"),
        (
            &["time", "T#-24d_20h_31m_23s_648ms"],
            "-2147483648 T#-24D_20H_31M_23S_648MS\n",
        ),
        (&["time", "200"], "200 T#200MS\n"),
    ];
    for (args, expected) in cases {
        let o = plc(args, "");
        assert!(o.status.success(), "{args:?}: {}", stderr(&o));
        assert_eq!(stdout(&o), *expected, "{args:?}");
    }
}

/// CLI-CHECK-01: a trace the reference produced checks clean; one flipped output is reported
/// at its line and column with exit status 1.
#[test]
fn check_finds_first_difference() {
    let run = plc(
        &["run", "TOF", "--pt", "T#200ms", "examples/traces/tof.csv"],
        "",
    );
    assert!(run.status.success());
    let good = stdout(&run);
    let o = plc(&["check", "TOF", "--pt", "T#200ms"], &good);
    assert_eq!(o.status.code(), Some(0), "{}{}", stdout(&o), stderr(&o));
    // Flip Q on the 5th data row (line 6).
    let mut lines: Vec<String> = good.lines().map(String::from).collect();
    let mut fields: Vec<String> = lines[5].split(',').map(String::from).collect();
    fields[2] = if fields[2] == "1" {
        "0".into()
    } else {
        "1".into()
    };
    lines[5] = fields.join(",");
    let bad = lines.join("\n") + "\n";
    let o = plc(&["check", "TOF", "--pt", "T#200ms"], &bad);
    assert_eq!(o.status.code(), Some(1));
    assert!(
        stdout(&o).contains("line 6, column 3 (Q)"),
        "{}",
        stdout(&o)
    );
}

/// Every example trace runs, and the optimized implementation gives the same output as the
/// reference on it.
#[test]
fn examples_reference_equals_optimized() {
    let examples: &[(&str, &[&str])] = &[
        ("s_pulse", &["S_PULSE", "--tv", "S5T#50MS"]),
        ("s_pext", &["S_PEXT", "--tv", "S5T#50MS"]),
        ("s_odt", &["S_ODT", "--tv", "S5T#50MS"]),
        ("s_odts", &["S_ODTS", "--tv", "S5T#50MS"]),
        ("s_offdt", &["S_OFFDT", "--tv", "S5T#50MS"]),
        ("tp", &["TP", "--pt", "T#100ms"]),
        ("ton", &["TON", "--pt", "T#500ms"]),
        ("tof", &["TOF", "--pt", "T#200ms"]),
        ("tonr", &["TONR", "--pt", "T#300ms"]),
        ("ctu", &["CTU", "--pv", "3"]),
        ("ctd", &["CTD", "--pv", "2"]),
        ("ctud", &["CTUD", "--pv", "4"]),
        ("s_cu", &["S_CU", "--pv", "C#998"]),
        ("s_cd", &["S_CD", "--pv", "C#2"]),
        ("s_cud", &["S_CUD", "--pv", "C#5"]),
    ];
    for (name, args) in examples {
        let file = format!("examples/traces/{name}.csv");
        let mut a: Vec<&str> = vec!["run"];
        a.extend_from_slice(args);
        a.push(&file);
        let reference = plc(&a, "");
        assert!(reference.status.success(), "{name}: {}", stderr(&reference));
        a.push("--optimized");
        let optimized = plc(&a, "");
        assert_eq!(stdout(&reference), stdout(&optimized), "{name}");
        assert!(stdout(&reference).lines().count() > 5, "{name} has rows");
    }
}

/// CLI-VEC-01 / CLI-DIAG-01: `vectors` writes the directories and a README; a written vector
/// checks clean through `check`; `diagram` writes an SVG.
#[test]
fn vectors_and_diagram_commands() {
    let dir = std::env::temp_dir().join(format!("plc-timers-vectors-{}", std::process::id()));
    let dir_s = dir.to_string_lossy().into_owned();
    let o = plc(&["vectors", &dir_s], "");
    assert!(o.status.success(), "{}", stderr(&o));
    assert!(dir.join("README.txt").is_file());
    let file = dir.join("S_ODTS").join("random-07.csv");
    let o = plc(&["check", "S_ODTS", &file.to_string_lossy()], "");
    assert_eq!(o.status.code(), Some(0), "{}", stdout(&o));
    let o = plc(
        &[
            "check",
            "CTUD",
            "--type",
            "ULINT",
            &dir.join("CTUD-ULINT")
                .join("random-00.csv")
                .to_string_lossy(),
        ],
        "",
    );
    assert_eq!(o.status.code(), Some(0), "{}", stdout(&o));
    let svg = dir.join("ton.svg");
    let o = plc(
        &[
            "diagram",
            "TON",
            "--pt",
            "T#500ms",
            "examples/traces/ton.csv",
            "-o",
            &svg.to_string_lossy(),
        ],
        "",
    );
    assert!(o.status.success(), "{}", stderr(&o));
    let text = std::fs::read_to_string(&svg).expect("svg written");
    assert!(text.starts_with("<svg") && text.contains("data-name=\"Q\""));
    let _ = std::fs::remove_dir_all(&dir);
}
