//! The command-line contract of `spec/cli.md`, run against the built binary.

mod common;

use common::{plc, text};
use plc_timers::catalog::Block;
use plc_timers_trace::examples;
use std::process::Output;

fn stdout(o: &Output) -> String {
    text(&o.stdout)
}

fn stderr(o: &Output) -> String {
    text(&o.stderr)
}

/// CLI-RUN-01: columns in any order and case, absent boolean = 0, records echoed as written.
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
    // S_ODT by its alias SD, with a TV column and no R column.
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

/// CLI-LTIME-01: `--type LTIME` (or the instance type TON_LTIME) runs the S7-1500 long timer:
/// time column `t_ns`, PT and ET in integer nanoseconds. Expected by hand from TON's rules
/// (IEC-START-01, IEC-EXPIRY-01) with PT = LT#1MS500US = 1 500 000 ns: START = 0, ET =
/// min(t, PT), Q = ET >= PT; a PT of LT#30D (past TIME's range) still times after 2^40 ns.
#[test]
fn ltime_runs_in_nanoseconds() {
    let trace = "t_ns,IN\n0,1\n1000000,1\n1500000,1\n1099511627776,1\n1099511627777,0\n";
    let expected = "t_ns,IN,Q,ET\n0,1,0,0\n1000000,1,0,1000000\n1500000,1,1,1500000\n\
                    1099511627776,1,1,1500000\n1099511627777,0,0,0\n";
    for args in [
        &["run", "TON", "--type", "LTIME", "--pt", "LT#1MS500US"][..],
        &["run", "ton_ltime", "--pt", "1500000"],
        &[
            "run",
            "TON_LTIME",
            "--type",
            "ltime",
            "--pt",
            "LTIME#1ms_500us",
        ],
    ] {
        let o = plc(args, trace);
        assert!(o.status.success(), "CLI-LTIME-01: {args:?}: {}", stderr(&o));
        assert_eq!(stdout(&o), expected, "CLI-LTIME-01: {args:?}");
    }
    // LT#30D = 2 592 000 000 000 000 ns: not expired after 2^40 ns.
    let o = plc(
        &["run", "TON", "--type", "LTIME", "--pt", "LT#30D"],
        "t_ns,IN\n0,1\n1099511627776,1\n2592000000000000,1\n",
    );
    assert_eq!(
        stdout(&o),
        "t_ns,IN,Q,ET\n0,1,0,0\n1099511627776,1,0,1099511627776\n2592000000000000,1,1,2592000000000000\n",
        "CLI-LTIME-01: LT#30D"
    );
    // check agrees with run's own output, and finds a changed ET.
    let o = plc(
        &["check", "TON", "--type", "LTIME", "--pt", "LT#1MS500US"],
        expected,
    );
    assert_eq!(o.status.code(), Some(0), "CLI-LTIME-01: {}", stderr(&o));
    let changed = expected.replace(",1,0,1000000", ",1,0,1000001");
    let o = plc(&["check", "TON_LTIME", "--pt", "LT#1MS500US"], &changed);
    assert_eq!(o.status.code(), Some(1), "CLI-LTIME-01: {}", stderr(&o));
    assert!(
        stdout(&o).contains("DIFFERENT at line 3, column 4 (ET): the reference gives 1000000"),
        "CLI-LTIME-01: {}",
        stdout(&o)
    );
}

/// CLI-ERR-01: every error class names the line and the column, says what is allowed, and
/// exits 2; positions are right with CRLF line ends and blank or comment lines anywhere.
#[test]
fn bad_input_names_line_and_column_exit_2() {
    let cases: &[(&[&str], &str, &str)] = &[
        (&["run", "NOPE"], "t_ms\n", "unknown block `NOPE`; the blocks are S_PULSE (SP)"),
        (
            &["run", "TON", "--pt", "5"],
            "t_ms,IN,X\n",
            "line 1, column 3 (X): unknown column `X`; TON takes the columns t_ms, IN, PT",
        ),
        (
            &["run", "TON", "--pt", "5"],
            "t_ms,IN,PTT\n",
            "line 1, column 3 (PTT): unknown column",
        ),
        (
            &["run", "TON", "--pt", "5"],
            "t_ms,IN\n0,1\n5,yes\n",
            "line 3, column 2 (IN): `yes` is not a boolean; use 0, 1, true or false",
        ),
        (
            &["run", "TON", "--pt", "5"],
            "t_ms,IN\r\n\r\n# note\r\n0,1\r\n\r\n5,yes\r\n",
            "line 6, column 2 (IN)",
        ),
        (
            &["run", "TON", "--pt", "5"],
            "# c\n\nt_ms,IN\n# c\n0,1\n  \n#\n5,yes\n",
            "line 8, column 2 (IN)",
        ),
        (
            &["run", "TON", "--pt", "5"],
            "t_ms,IN\n10,1\n9,1\n",
            "line 3, column 1 (t_ms): t_ms goes backwards: 9 after 10",
        ),
        (&["run", "TON", "--pt", "5"], "t_ms,IN\n-1,1\n", "line 2, column 1 (t_ms)"),
        (
            &["run", "TON"],
            "t_ms,IN,PT\n0,1,T#24d_20h_31m_23s_648ms\n",
            "line 2, column 3 (PT)",
        ),
        (&["run", "SD"], "t_ms,S,TV\n0,1,W#16#00A0\n", "line 2, column 3 (TV)"),
        (&["run", "SD", "--tv", "S5T#3H"], "t_ms,S\n0,1\n", "option --tv"),
        (
            &["run", "TON"],
            "t_ms,IN\n0,1\n",
            "line 1: TON needs its preset: a `PT` column or the option --pt",
        ),
        (&["run", "TON", "--pv", "5"], "t_ms,IN\n", "option --pv does not apply to TON; its preset PT is given with --pt"),
        (&["run", "TON", "--pt", "5", "--type", "INT"], "t_ms,IN\n", "TON does not take the data type INT; it takes TIME LTIME"),
        (&["run", "CTU", "--pv", "5", "--type", "LTIME"], "CU\n", "CTU does not take the data type LTIME; it takes SINT INT DINT LINT USINT UINT UDINT ULINT"),
        (&["run", "CTU", "--pv", "5", "--type", "INT8"], "CU\n", "unknown data type `INT8`; --type takes TIME LTIME SINT INT DINT LINT USINT UINT UDINT ULINT"),
        // CLI-LTIME-02: the time column of the other data type, at its cell, with what is allowed.
        (
            &["run", "TON", "--type", "LTIME", "--pt", "LT#1MS"],
            "t_ms,IN\n0,1\n",
            "line 1, column 1 (t_ms): `t_ms` is a time in milliseconds; TON on LTIME counts its time in nanoseconds (`t_ns`), so its columns are t_ns, IN, PT, RT",
        ),
        (
            &["run", "TON", "--pt", "5"],
            "IN,t_ns\n1,0\n",
            "line 1, column 2 (t_ns): `t_ns` is a time in nanoseconds; TON on TIME counts its time in milliseconds (`t_ms`), so its columns are t_ms, IN, PT, RT",
        ),
        (
            &["run", "TON_LTIME", "--pt", "5"],
            "t_ns,IN\n10,1\n9,1\n",
            "line 3, column 1 (t_ns): t_ns goes backwards: 9 after 10",
        ),
        (&["run", "TP_LTIME", "--pt", "5"], "IN\n1\n", "TP is a timer: the header needs a `t_ns` column"),
        (&["run", "TON_LTIME", "--type", "TIME", "--pt", "5"], "t_ns,IN\n", "the instance type names the data type LTIME; --type TIME contradicts it"),
        (&["run", "TON", "--type", "LTIME", "--pt", "T#1S"], "t_ns,IN\n", "option --pt: `T#1S`: "),
        (&["run", "TON", "--type", "LTIME"], "t_ns,IN,PT\n0,1,LT#1S\n1,1,LT#1Q\n", "line 3, column 3 (PT): `LT#1Q`: "),
        (&["run", "CTU", "--pv", "40000"], "CU\n1\n", "option --pv: `40000`: not a valid INT preset; PV is a whole number from -32768 to 32767"),
        (&["run", "S_CU", "--pv", "C#1000"], "CU\n1\n", "option --pv"),
        (
            &["run", "TON", "--pt", "5"],
            "t_ms,IN\n0,1,1\n",
            "line 2, column 3 (beyond the header): the row has 3 fields but the header (line 1) has 2: t_ms,IN",
        ),
        (
            &["run", "TON", "--pt", "5"],
            "t_ms,IN\r\n\r\n0\r\n",
            "line 3, column 2 (IN): the row has 1 field(s) but the header (line 1) has 2: t_ms,IN",
        ),
        (&["run", "TON", "--pt", "5"], "IN\n1\n", "needs a `t_ms` column"),
        (
            &["run", "TON", "--pt", "5"],
            "t_ms,IN,Q\n",
            "line 1, column 3 (Q): `Q` is an output of TON",
        ),
        (&["run", "TON", "--pt", "5"], "t_ms,IN,in\n", "column `in` appears twice"),
        (&["run", "TON", "--pt", "5"], "t_ms,IN,PT,pt\n", "column `pt` appears twice"),
        (&["run", "TONR", "--pt", "5"], "t_ms,R,IN,r\n", "column `r` appears twice"),
        (&["run", "TON", "--pt", "5"], "", "line 1: the trace is empty"),
        (&["run", "TON", "--pt", "5"], "\n# only a comment\n", "line 1: the trace is empty"),
        // Strict CSV.
        (
            &["run", "TON", "--pt", "5"],
            "t_ms,IN\n0,\"1\n5,1\n",
            "line 2, column 2 (field 2): the quote opened here is never closed",
        ),
        (
            &["run", "TON", "--pt", "5"],
            "t_ms,IN\n0,1\"\n",
            "line 2, column 2 (field 2): stray quote in `1\"`",
        ),
        (
            &["run", "TON", "--pt", "5"],
            "t_ms,IN\r\n0,\"1\"x\r\n",
            "line 2, column 2 (field 2): `x` after the closing quote",
        ),
        (&["run", "TON", "--pt", "5", "no/such/file.csv"], "", "cannot open no/such/file.csv"),
        (&["s5time", "S5T#2H46M31S"], "", "above the S5TIME maximum"),
        (&["time", "T#1h_75m"], "", "out of range after a larger unit"),
    ];
    for (args, input, message) in cases {
        let o = plc(args, input);
        assert_eq!(o.status.code(), Some(2), "{args:?}: {}", stderr(&o));
        assert!(
            stderr(&o).contains(message),
            "{args:?} {input:?}: expected `{message}` in `{}`",
            stderr(&o)
        );
        assert!(!stderr(&o).contains("panicked"), "{args:?}");
    }
}

/// CLI-ERR-01: a shown cell is cut after 60 characters, so a huge cell gives a short message.
#[test]
fn long_cells_are_cut_in_messages() {
    let cell = "y".repeat(5_000_000);
    let o = plc(&["run", "TON", "--pt", "5"], format!("t_ms,IN\n0,{cell}\n"));
    assert_eq!(o.status.code(), Some(2));
    let e = stderr(&o);
    assert!(e.len() < 300, "{} bytes", e.len());
    assert!(e.contains(&format!("`{}…`", "y".repeat(60))), "{e}");
}

/// CLI-RUN-02: `run` streams: the rows before a bad row are written, then the error, exit 2.
#[test]
fn run_writes_the_rows_before_an_error() {
    let o = plc(
        &["run", "TON", "--pt", "5"],
        "t_ms,IN\n0,1\n5,1\n6,2\n7,1\n",
    );
    assert_eq!(o.status.code(), Some(2));
    assert_eq!(stdout(&o), "t_ms,IN,Q,ET\n0,1,0,0\n5,1,1,5\n");
    assert!(stderr(&o).contains("line 4, column 2 (IN)"));
}

/// CLI-RUN-02: `run` streams: output appears while the input is still open.
#[test]
fn run_streams_before_the_input_ends() {
    use std::io::{Read, Write};
    use std::process::{Command, Stdio};
    let mut child = Command::new(env!("CARGO_BIN_EXE_plc-timers"))
        .args(["run", "TON", "--pt", "5"])
        .stdin(Stdio::piped())
        .stdout(Stdio::piped())
        .spawn()
        .expect("starts");
    let mut stdin = child.stdin.take().expect("stdin");
    let mut stdout = child.stdout.take().expect("stdout");
    let (tx, rx) = std::sync::mpsc::channel();
    let reader = std::thread::spawn(move || {
        let mut first = [0u8; 13];
        let got = stdout.read_exact(&mut first).is_ok();
        let _ = tx.send(got);
        let _ = std::io::copy(&mut stdout, &mut std::io::sink());
    });
    // More than a block of output, and the input stays open.
    let mut trace = String::from("t_ms,IN\n");
    for t in 0..20_000 {
        trace.push_str(&format!("{t},1\n"));
    }
    stdin.write_all(trace.as_bytes()).expect("write");
    stdin.flush().expect("flush");
    let streamed = rx.recv_timeout(std::time::Duration::from_secs(20));
    drop(stdin);
    let _ = child.wait();
    let _ = reader.join();
    assert_eq!(streamed, Ok(true), "output before the end of the input");
}

/// CLI-RUN-02: writing to a pipe that closes early (`| head`) ends quietly with status 0.
#[test]
fn closed_pipe_ends_quietly() {
    use std::io::Write;
    use std::process::{Command, Stdio};
    let mut trace = String::from("t_ms,IN\n");
    for t in 0..200_000 {
        trace.push_str(&format!("{t},{}\n", t / 7 % 2));
    }
    let mut child = Command::new(env!("CARGO_BIN_EXE_plc-timers"))
        .args(["run", "TON", "--pt", "5", "-"])
        .stdin(Stdio::piped())
        .stdout(Stdio::piped())
        .stderr(Stdio::piped())
        .spawn()
        .expect("starts");
    let mut stdin = child.stdin.take().expect("stdin");
    let writer = std::thread::spawn(move || {
        let _ = stdin.write_all(trace.as_bytes());
    });
    // Read one line, then close the pipe.
    let mut stdout = child.stdout.take().expect("stdout");
    let mut first = [0u8; 16];
    let _ = std::io::Read::read(&mut stdout, &mut first);
    drop(stdout);
    let o = child.wait_with_output().expect("finishes");
    let _ = writer.join();
    assert_eq!(o.status.code(), Some(0), "{}", stderr(&o));
    assert_eq!(stderr(&o), "");
}

/// CLI-CONV-01: the conversions, with the automatic base and the TIME range ends.
#[test]
fn s5time_and_time_conversions() {
    let cases: &[(&[&str], String)] = &[
        (
            &["s5time", "S5T#2M7S"],
            "W#16#2127 127000 S5T#2M7S\n".into(),
        ),
        (
            &["s5time", "W#16#2127"],
            "W#16#2127 127000 S5T#2M7S\n".into(),
        ),
        (&["s5time", "W#16#2001"], "W#16#0100 1000 S5T#1S\n".into()),
        (
            &["s5time", "s5time#2h_46m_30s"],
            "W#16#3999 9990000 S5T#2H46M30S\n".into(),
        ),
        (&["time", "T#2s_200ms"], "2200 T#2S_200MS\n".into()),
        (
            &["time", "T#24D_20H_31M_23S_647MS"],
            format!("{} T#24D_20H_31M_23S_647MS\n", i32::MAX),
        ),
        (
            &["time", "T#-24d_20h_31m_23s_648ms"],
            format!("{} T#-24D_20H_31M_23S_648MS\n", i32::MIN),
        ),
        (&["time", "200"], "200 T#200MS\n".into()),
    ];
    for (args, expected) in cases {
        let o = plc(args, "");
        assert!(o.status.success(), "{args:?}: {}", stderr(&o));
        assert_eq!(stdout(&o), *expected, "{args:?}");
    }
    for args in [
        &["time", "T#24D_20H_31M_23S_648MS"][..],
        &["s5time", "W#16#20A0"],
        &["s5time", "S5T#"],
        &["time", ""],
    ] {
        let o = plc(args, "");
        assert_eq!(o.status.code(), Some(2), "{args:?}");
        assert!(
            o.stdout.is_empty() && !stderr(&o).trim().is_empty(),
            "{args:?}"
        );
    }
}

/// CLI-CHECK-01/02: a clean trace exits 0; a flipped output exits 1 with the line, column,
/// both values, the rule and the rows before; a malformed output cell or a missing output
/// column is bad input (2) unless `--outputs` leaves it out.
#[test]
fn check_exit_statuses_and_explanation() {
    let run = plc(
        &["run", "TON", "--pt", "T#500ms", "examples/traces/ton.csv"],
        "",
    );
    assert!(run.status.success());
    let good = stdout(&run);
    let o = plc(&["check", "TON", "--pt", "T#500ms"], &good);
    assert_eq!(o.status.code(), Some(0), "{}{}", stdout(&o), stderr(&o));
    assert_eq!(
        stdout(&o),
        "OK: 11 rows of TON: Q, ET agree with the reference\n"
    );
    let bad = good.replace("2500,1,1,500", "2500,1,0,500");
    let o = plc(&["check", "TON", "--pt", "T#500ms"], &bad);
    assert_eq!(o.status.code(), Some(1));
    let out = stdout(&o);
    assert!(
        out.starts_with(
            "DIFFERENT at line 9, column 3 (Q): the reference gives 1, the trace has 0\n"
        ),
        "{out}"
    );
    assert!(
        out.contains("\nIEC-EXPIRY-01: Expiry is at ET >= PT"),
        "{out}"
    );
    assert!(
        out.contains("  line 8      2499,1,0,499  | Q=0 ET=499\n"),
        "{out}"
    );
    assert!(
        out.contains("> line 9      2500,1,0,500  | Q=1 ET=500\n"),
        "{out}"
    );
    assert_eq!(
        out.matches("\n  line ").count(),
        3,
        "three rows before: {out}"
    );
    // Q falls because IN falls: TON-IN-01.
    let bad = good.replace("3200,0,0,0", "3200,0,1,500");
    let o = plc(&["check", "TON", "--pt", "T#500ms"], &bad);
    assert!(stdout(&o).contains("\nTON-IN-01: "), "{}", stdout(&o));
    // Malformed cells.
    for (from, to, message) in [
        (
            "2500,1,1,500",
            "2500,1,abc,500",
            "line 9, column 3 (Q): `abc` is not a valid Q output; it is 0, 1, true or false",
        ),
        (
            "2500,1,1,500",
            "2500,1,1,5x",
            "line 9, column 4 (ET): `5x` is not a valid ET output",
        ),
    ] {
        let o = plc(&["check", "TON", "--pt", "T#500ms"], good.replace(from, to));
        assert_eq!(o.status.code(), Some(2), "{}", stdout(&o));
        assert!(stderr(&o).contains(message), "{}", stderr(&o));
    }
    // A malformed word output names the word forms (S_ODT's BCD, from the second row of the
    // SD run at the top of this file).
    let o = plc(
        &["check", "SD"],
        "t_ms,S,TV,Q,BI,BCD\n0,1,W#16#0002,0,2,W#16#0002\n20,1,W#16#0002,1,0,W#16#00G0\n",
    );
    assert_eq!(o.status.code(), Some(2), "{}", stdout(&o));
    assert!(
        stderr(&o).contains(
            "line 3, column 6 (BCD): `W#16#00G0` is not a valid BCD output; \
             it is W#16# and 1 to 4 hexadecimal digits, or 0..65535"
        ),
        "{}",
        stderr(&o)
    );
    // A missing output column.
    let q_only: String = good
        .lines()
        .map(|l| l.rsplit_once(',').map_or(l, |(a, _)| a).to_string() + "\n")
        .collect();
    let o = plc(&["check", "TON", "--pt", "T#500ms"], &q_only);
    assert_eq!(o.status.code(), Some(2));
    assert!(
        stderr(&o).contains("line 1: the trace has no `ET` column"),
        "{}",
        stderr(&o)
    );
    let o = plc(
        &["check", "TON", "--pt", "T#500ms", "--outputs", "q"],
        &q_only,
    );
    assert_eq!(o.status.code(), Some(0), "{}", stderr(&o));
    assert_eq!(
        stdout(&o),
        "OK: 11 rows of TON: Q agree with the reference\n"
    );
    let o = plc(
        &["check", "TON", "--pt", "T#500ms", "--outputs", "CV"],
        &q_only,
    );
    assert_eq!(o.status.code(), Some(2));
    assert!(
        stderr(&o).contains("option --outputs: `CV` is not an output of TON; its outputs are Q,ET")
    );
}

/// Every example runs with the command of its first line, and the optimized implementation
/// gives the same output as the reference on it.
#[test]
fn examples_reference_equals_optimized() {
    let all = examples::all().expect("examples");
    assert!(all.len() >= Block::ALL.len());
    for e in all {
        let args: Vec<&str> = e.command.split_whitespace().collect();
        let reference = plc(&args, "");
        assert!(
            reference.status.success(),
            "{}: {}",
            e.stem,
            stderr(&reference)
        );
        let mut optimized = args.clone();
        optimized.push("--optimized");
        let optimized = plc(&optimized, "");
        assert_eq!(stdout(&reference), stdout(&optimized), "{}", e.stem);
        assert!(
            stdout(&reference).lines().count() > 5,
            "{} has rows",
            e.stem
        );
    }
}

/// CLI-VEC-01: `vectors` writes the directories and a README; written vectors check clean.
#[test]
fn vectors_command() {
    let dir = common::temp_dir("vectors");
    let dir_s = dir.to_string_lossy().into_owned();
    let o = plc(&["vectors", &dir_s], "");
    assert!(o.status.success(), "{}", stderr(&o));
    assert!(stdout(&o).starts_with("wrote "));
    assert!(dir.join("README.txt").is_file());
    // Each vector's own check command replays it.
    let all = plc_timers_trace::vectors::all().expect("vectors");
    for v in all
        .iter()
        .filter(|v| v.file == "limits.csv" || v.file == "fr.csv")
        .take(6)
    {
        let command = v.check_command();
        let words: Vec<&str> = command.split_whitespace().collect();
        assert_eq!(words[..2], ["plc-timers", "check"]);
        let path = dir
            .join(words[words.len() - 1])
            .to_string_lossy()
            .into_owned();
        let mut args = words[1..words.len() - 1].to_vec();
        args.push(&path);
        let o = plc(&args, "");
        assert_eq!(o.status.code(), Some(0), "{command}: {}", stderr(&o));
    }
    assert!(all
        .iter()
        .any(|v| v.check_command() == "plc-timers check CTUD --type SINT CTUD-SINT/limits.csv"));
    assert!(all
        .iter()
        .any(|v| v.check_command() == "plc-timers check S_CU S_CU/fr.csv"));
    for (args, file) in [
        (&["check", "S_ODTS"][..], dir.join("S_ODTS/random-07.csv")),
        (
            &["check", "CTUD", "--type", "ULINT"],
            dir.join("CTUD-ULINT/limits.csv"),
        ),
        (&["check", "TON"], dir.join("TON/long-gaps.csv")),
    ] {
        let mut a = args.to_vec();
        let f = file.to_string_lossy().into_owned();
        a.push(&f);
        let o = plc(&a, "");
        assert_eq!(
            o.status.code(),
            Some(0),
            "{a:?}: {}{}",
            stdout(&o),
            stderr(&o)
        );
    }
    let _ = std::fs::remove_dir_all(&dir);
}

/// CLI-DIAG-01 / CLI-VCD-01 through the binary: `diagram` writes an SVG, `--format vcd` and
/// `vcd` write VCD; `--from` after `--to` is an error.
#[test]
fn diagram_and_vcd_commands() {
    let dir = common::temp_dir("diagram");
    let svg = dir.join("ton.svg").to_string_lossy().into_owned();
    let ton = ["TON", "--pt", "T#500ms", "examples/traces/ton.csv"];
    let o = plc(&[&["diagram"][..], &ton, &["-o", &svg]].concat(), "");
    assert!(o.status.success(), "{}", stderr(&o));
    let text = std::fs::read_to_string(&svg).expect("svg written");
    assert!(text.starts_with("<svg") && text.contains("data-name=\"Q\""));
    let vcd1 = dir.join("a.vcd").to_string_lossy().into_owned();
    let vcd2 = dir.join("b.vcd").to_string_lossy().into_owned();
    let o = plc(
        &[&["diagram"][..], &ton, &["--format", "vcd", "-o", &vcd1]].concat(),
        "",
    );
    assert!(o.status.success(), "{}", stderr(&o));
    let o = plc(&[&["vcd"][..], &ton, &["-o", &vcd2]].concat(), "");
    assert!(o.status.success(), "{}", stderr(&o));
    let a = std::fs::read_to_string(&vcd1).expect("vcd");
    assert_eq!(a, std::fs::read_to_string(&vcd2).expect("vcd"));
    assert!(a.contains("$timescale 1 ms $end"), "{a}");
    let o = plc(
        &[
            &["diagram"][..],
            &ton,
            &["--from", "9", "--to", "3", "-o", &svg],
        ]
        .concat(),
        "",
    );
    assert_eq!(o.status.code(), Some(2));
    assert!(stderr(&o).contains("option --from: --from 9 is after --to 3"));
    let o = plc(
        &[
            &["diagram"][..],
            &ton,
            &["--from", "2500", "--to", "2500", "-o", &svg],
        ]
        .concat(),
        "",
    );
    assert!(
        o.status.success(),
        "a window of one instant: {}",
        stderr(&o)
    );
    // An output that cannot be written (a full device) is an error, unlike a closed pipe.
    if std::path::Path::new("/dev/full").exists() {
        let o = plc(&[&["vcd"][..], &ton, &["-o", "/dev/full"]].concat(), "");
        assert_eq!(o.status.code(), Some(2));
        assert!(
            stderr(&o).contains("cannot write the output"),
            "{}",
            stderr(&o)
        );
        let o = plc(&[&["vectors"][..], &["/dev/full/x"]].concat(), "");
        assert_eq!(o.status.code(), Some(2));
    }
    let _ = std::fs::remove_dir_all(&dir);
}
