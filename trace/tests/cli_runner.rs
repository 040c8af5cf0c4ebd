//! The trace engine through the library: input-text variants, typed headers, strict CSV, and
//! totality on arbitrary bytes (reference and optimized agree on every trace both accept).

use plc_timers::catalog::{Block, PresetKind};
use plc_timers_trace::diagram::{self, Window};
use plc_timers_trace::{check, run, vcd, BlockSpec, Error, Implementation, Location, TraceError};
use proptest::prelude::*;

fn ton() -> BlockSpec {
    BlockSpec::new(Block::Ton)
}

/// `text` as TON's PT, read as the command line's parser reads `--pt`.
fn pt(text: &str) -> Option<&str> {
    ton().preset_literal(text).expect("a valid PT");
    Some(text)
}

fn run_str(spec: BlockSpec, input: &[u8], preset: Option<&str>) -> Result<String, TraceError> {
    let mut out = Vec::new();
    match run(spec, preset, input, &mut out) {
        Ok(_) => Ok(String::from_utf8(out).expect("the runner writes UTF-8 for UTF-8 input")),
        Err(Error::Input(e)) => Err(e),
        Err(Error::Output(e)) => panic!("writing to a Vec fails: {e}"),
    }
}

const PLAIN: &str = "t_ms,IN\n0,1\n3,1\n5,1\n9,1\n";
/// By hand from TON's rules with PT = 5: START = 0, ET = min(t, 5), Q = ET >= 5.
const PLAIN_OUT: &str = "t_ms,IN,Q,ET\n0,1,0,0\n3,1,0,3\n5,1,1,5\n9,1,1,5\n";

/// CLI-RUN-01: the plain trace gives the outputs computed by hand.
#[test]
fn cli_run_plain_trace() {
    assert_eq!(
        run_str(ton(), PLAIN.as_bytes(), pt("5")).unwrap(),
        PLAIN_OUT
    );
}

/// CLI-RUN-01: a header-only trace writes the output header.
#[test]
fn cli_run_header_only_writes_header() {
    for input in [
        &b"t_ms,IN\n"[..],
        b"t_ms,IN\n\n\n",
        b"t_ms,IN",
        b"# c\r\nt_ms,IN\r\n",
    ] {
        let out = run_str(ton(), input, pt("5")).unwrap();
        assert_eq!(out, "t_ms,IN,Q,ET\n");
    }
}

/// CLI-RUN-01: a BOM, CRLF, trailing blank lines, no final line end, comment lines, quoted
/// fields, blanks around cells and names in another case give the outputs of the plain trace.
#[test]
fn cli_run_text_variants_are_equivalent() {
    let variants: &[&[u8]] = &[
        b"\xef\xbb\xbft_ms,IN\n0,1\n3,1\n5,1\n9,1\n",
        b"t_ms,IN\r\n0,1\r\n3,1\r\n5,1\r\n9,1\r\n",
        b"t_ms,IN\n0,1\n3,1\n5,1\n9,1\n\n\n",
        b"t_ms,IN\n0,1\n3,1\n5,1\n9,1",
        b"# a comment\nt_ms,IN\n0,1\n# another\n3,1\n5,1\n\n9,1\n",
        b"\"t_ms\",\"IN\"\n\"0\",\"1\"\n3,1\n5, \"1\" \n9,1\n",
        b"T_MS,in\n 0 ,true\n3,TRUE\n5,1\n9,\tTrue\n",
        b"t_ms,IN\r\n\"0\",\"1\"\r\n3,1\r\n5,1\r\n9,1",
    ];
    let outputs = |s: &str| -> Vec<String> {
        s.lines()
            .skip(1)
            .map(|l| l.rsplitn(3, ',').take(2).collect::<Vec<_>>().join(","))
            .collect()
    };
    for v in variants {
        let out = run_str(ton(), v, pt("5"))
            .unwrap_or_else(|e| panic!("{:?}: {e}", String::from_utf8_lossy(v)));
        assert_eq!(
            outputs(&out),
            outputs(PLAIN_OUT),
            "{:?}",
            String::from_utf8_lossy(v)
        );
        assert!(out.lines().next().unwrap().ends_with(",Q,ET"), "{out}");
        assert!(!out.contains('\r'), "line ends are LF");
    }
}

/// CLI-RUN-01: columns in any order; each record is echoed as written; a preset column.
#[test]
fn cli_run_column_order_and_preset_column() {
    let out = run_str(ton(), b"IN,PT,t_ms\ntrue,5,0\n1,\"5\",7\n", None).unwrap();
    assert_eq!(out, "IN,PT,t_ms,Q,ET\ntrue,5,0,0,0\n1,\"5\",7,1,5\n");
}

fn err(input: &[u8]) -> TraceError {
    run_str(ton(), input, pt("5")).expect_err("must be rejected")
}

fn cell(e: &TraceError) -> (u64, usize) {
    match &e.location {
        Location::Cell { line, column, .. } => (*line, *column),
        other => panic!("{other:?}: {e}"),
    }
}

/// CLI-ERR-01: non-UTF-8 cells and headers, empty traces, strict quotes, field counts: each
/// is located to its line and column.
#[test]
fn cli_err_located() {
    assert_eq!(cell(&err(b"t_ms,IN\n0,\xff\n")), (2, 2));
    assert_eq!(cell(&err(b"t_ms,\xff\n")), (1, 2));
    assert_eq!(err(b"").location, Location::Line(1));
    assert_eq!(err(b"\n\n# x\n").location, Location::Line(1));
    assert_eq!(cell(&err(b"t_ms,IN\r\n\r\n0,\"1\r\n")), (3, 2));
    assert_eq!(cell(&err(b"t_ms,IN\n\"0\"\"\",1\n")), (2, 1));
    assert_eq!(cell(&err(b"t_ms,IN\n#\n0,1,\n")), (3, 3));
    assert_eq!(cell(&err(b"t_ms,IN\n\n\n0\n")), (4, 2));
    // A quoted cell spanning lines is located to the line where it starts.
    assert_eq!(cell(&err(b"t_ms,IN\n0,\"1\n\"\n1,x\n")), (2, 2));
    let e = err(b"t_ms,IN\n0,1,2\n");
    assert!(
        e.message.contains("the header (line 1) has 2: t_ms,IN"),
        "{e}"
    );
}

/// CLI-ERR-01: a bad preset is located to its cell, or to its option.
#[test]
fn cli_err_preset_located() {
    let e = run_str(ton(), b"t_ms,IN,PT\n0,1,T#1S\n1,1,T#1X\n", None).expect_err("bad PT");
    assert_eq!(cell(&e), (3, 3));
    let e = run_str(ton(), b"t_ms,IN\n", Some("T#1X")).expect_err("bad --pt");
    assert_eq!(e.location, Location::Option("pt"));
    assert!(!e.message.is_empty(), "{e}");
    // A preset of another kind (a library caller's mistake) is located to the block's option.
    let e = run_str(ton(), b"t_ms,IN\n", Some("S5T#1S")).expect_err("a TV for TON");
    assert_eq!(e.location, Location::Option("pt"));
}

/// CLI-CHECK-01: a header-only trace checks clean with zero rows; every flipped output cell of
/// a trace is found at its line and column.
#[test]
fn cli_check_every_flipped_cell_is_found() {
    let report = check(ton(), pt("5"), None, &b"t_ms,IN,Q,ET\n"[..]).expect("valid");
    assert_eq!((report.rows, report.difference), (0, None));
    let good = run_str(ton(), b"t_ms,IN\n0,1\n3,1\n5,1\n9,0\n12,1\n", pt("5")).unwrap();
    let lines: Vec<&str> = good.lines().collect();
    for row in 1..lines.len() {
        for col in [2usize, 3] {
            let mut fields: Vec<String> = lines[row].split(',').map(String::from).collect();
            fields[col] = if col == 2 {
                if fields[col] == "1" { "0" } else { "1" }.to_string()
            } else {
                (fields[col].parse::<i64>().unwrap() + 1).to_string()
            };
            let mut bad: Vec<String> = lines.iter().map(|l| l.to_string()).collect();
            bad[row] = fields.join(",");
            let text = bad.join("\n");
            let report = check(ton(), pt("5"), None, text.as_bytes()).expect("valid");
            let d = report.difference.expect("a difference");
            assert_eq!((d.line, d.column), (row as u64 + 1, col + 1));
            assert!(!d.why.rules.is_empty());
            assert_eq!(d.context.len(), row.min(4));
        }
    }
}

/// CLI-CHECK-01: `--outputs` names each output once whatever its spelling; an empty list or an
/// unknown name is bad input at the option.
#[test]
fn cli_check_output_selection() {
    let trace = &b"t_ms,IN,Q,ET\n0,1,0,0\n5,1,1,5\n"[..];
    let report = check(ton(), pt("5"), Some(&["q", "Q", " et"]), trace).expect("valid");
    assert_eq!(report.compared, ["Q", "ET"]);
    assert_eq!((report.rows, report.difference), (2, None));
    let report = check(ton(), pt("5"), Some(&["ET"]), trace).expect("valid");
    assert_eq!(report.compared, ["ET"]);
    for outputs in [&[][..], &["CV"]] {
        let e = check(ton(), pt("5"), Some(outputs), trace).expect_err("bad --outputs");
        assert_eq!(e.location, Location::Option("outputs"), "{e}");
    }
}

/// IEC-RT-01, CLI-RUN-01: the `RT` column is the -(RT)- coil, run before the box call of its
/// row; it is echoed by `run`, drawn by `diagram` and dumped by `vcd`; only the IEC timers
/// take it.
#[test]
fn rt_column_is_the_coil_before_the_call() {
    let trace = "t_ms,IN,RT\n0,1,0\n3,1,0\n4,1,1\n8,1,0\n9,1,0\n10,0,1\n";
    // By hand from IEC-RT-01 and TON's rules with PT = 5: START = 0; at 4 the coil clears the
    // data (the stored IN too), so IN = 1 is a rising edge: START = 4, ET 0; ET 4 at 8, Q = 1
    // with ET = 5 at 9; at 10 the coil and IN = 0 both leave Q = 0, ET 0.
    let expected =
        "t_ms,IN,RT,Q,ET\n0,1,0,0,0\n3,1,0,0,3\n4,1,1,0,0\n8,1,0,0,4\n9,1,0,1,5\n10,0,1,0,0\n";
    for imp in [Implementation::Reference, Implementation::Optimized] {
        assert_eq!(
            run_str(ton().with(imp), trace.as_bytes(), pt("5")).as_deref(),
            Ok(expected),
            "{imp:?}"
        );
    }
    // Without the column, or with it at 0 throughout, the trace runs as the box alone.
    let zeros = "t_ms,IN,RT\n0,1,0\n3,1,0\n5,1,0\n";
    let plain = run_str(ton(), b"t_ms,IN\n0,1\n3,1\n5,1\n", pt("5")).expect("valid");
    let with = run_str(ton(), zeros.as_bytes(), pt("5")).expect("valid");
    let strip = |t: &str| -> Vec<String> {
        t.lines()
            .map(|l| {
                let f: Vec<&str> = l.split(',').collect();
                [&f[..2], &f[f.len() - 2..]].concat().join(",")
            })
            .collect()
    };
    assert_eq!(
        strip(&with),
        plain.lines().map(String::from).collect::<Vec<_>>()
    );
    // check agrees with run's output, and finds a port that ignores the coil.
    let report = check(ton(), pt("5"), None, expected.as_bytes()).expect("valid");
    assert_eq!((report.rows, report.difference), (6, None));
    let ignored = expected.replace("4,1,1,0,0", "4,1,1,0,4");
    let d = check(ton(), pt("5"), None, ignored.as_bytes())
        .expect("valid")
        .difference
        .expect("a difference");
    assert_eq!((d.line, d.output), (4, "ET"));
    assert!(
        d.why.rules.contains(plc_timers::rule::Rule::IEC_RT_01),
        "{d}"
    );
    // diagram: a waveform lane RT; vcd: a 1-bit wire RT that is 1 at 4 and 10.
    let mut svg = Vec::new();
    diagram::svg(
        ton(),
        pt("5"),
        trace.as_bytes(),
        Window::default(),
        &mut svg,
    )
    .expect("draws");
    let svg = String::from_utf8(svg).expect("UTF-8");
    assert!(svg.contains("class=\"signal\" data-name=\"RT\""), "{svg}");
    let mut dump = Vec::new();
    vcd::export(ton(), pt("5"), trace.as_bytes(), &mut dump).expect("dumps");
    let dump = String::from_utf8(dump).expect("UTF-8");
    let id = dump
        .lines()
        .find_map(|l| l.strip_prefix("$var wire 1 ")?.strip_suffix(" RT $end"))
        .unwrap_or_else(|| panic!("no RT wire in\n{dump}"));
    let rt_changes: Vec<&str> = dump
        .lines()
        .filter(|l| l.len() == 1 + id.len() && l.ends_with(id))
        .collect();
    assert_eq!(
        rt_changes,
        [
            format!("0{id}"),
            format!("1{id}"),
            format!("0{id}"),
            format!("1{id}")
        ]
    );
    // Errors: RT twice; RT on a block without the coil, at its cell, naming who has it.
    let e = run_str(ton(), b"t_ms,RT,IN,rt\n", pt("5")).expect_err("RT twice");
    assert!(e.message.contains("appears twice"), "{e}");
    let sd = BlockSpec::new(Block::SOdt);
    let tv = Some("S5T#20MS");
    let e = run_str(sd, b"t_ms,S,RT\n0,1,1\n", tv).expect_err("no RT on S_ODT");
    assert_eq!(
        e.to_string(),
        "line 1, column 3 (RT): `RT` is the -(RT)- coil, which only TP, TON, TOF, TONR have; \
         S_ODT takes the columns t_ms, S, R, FR, TV"
    );
    // An IEC timer's unknown column lists RT among its columns.
    let e = run_str(ton(), b"t_ms,IN,X\n", pt("5")).expect_err("unknown");
    assert!(
        e.message
            .ends_with("TON takes the columns t_ms, IN, PT, RT"),
        "{e}"
    );
}

/// CLI-DIAG-02: times at the end of the u64 range, in the exact and in the bucket mode, and a
/// window of one instant draw without overflow.
#[test]
fn diagram_at_the_end_of_time() {
    let top = u64::MAX - 5_000;
    let mut trace = String::from("t_ms,IN\n");
    for k in 0..5_000u64 {
        trace.push_str(&format!("{},{}\n", top + k, k / 100 % 2));
    }
    for rows in [10, 5_000] {
        let text: String = trace
            .lines()
            .take(rows + 1)
            .map(|l| format!("{l}\n"))
            .collect();
        let mut out = Vec::new();
        diagram::svg(
            ton(),
            pt("T#5MS"),
            text.as_bytes(),
            Window::default(),
            &mut out,
        )
        .expect("draws");
        assert!(!String::from_utf8(out).expect("UTF-8").contains("NaN"));
    }
    let mut out = Vec::new();
    let window = Window {
        from: Some(3),
        to: Some(3),
    };
    diagram::svg(ton(), pt("5"), PLAIN.as_bytes(), window, &mut out).expect("draws");
    assert!(!String::from_utf8(out).expect("UTF-8").contains("NaN"));
}

/// Bytes that look like traces: a header of TON's columns, then rows of small tokens.
fn csvish() -> impl Strategy<Value = Vec<u8>> {
    let token = prop_oneof![
        Just("0".to_string()),
        Just("1".to_string()),
        Just("true".to_string()),
        Just("\"1\"".to_string()),
        Just("\"".to_string()),
        Just("".to_string()),
        Just("T#5MS".to_string()),
        (0u64..100).prop_map(|n| n.to_string()),
        "[ -~]{0,3}",
    ];
    let sep = prop_oneof![Just(","), Just(",,"), Just("\n"), Just("\r\n"), Just("#")];
    let header = prop_oneof![
        Just("t_ms,IN\n"),
        Just("t_ms,IN,PT\n"),
        Just("t_ms,IN,RT\n"),
        Just("IN,t_ms\r\n"),
        Just("t_ms,S,R,FR,TV\n"),
        Just("CU,CD,R,LD,PV\n"),
        Just(""),
    ];
    (header, prop::collection::vec((token, sep), 0..40)).prop_map(|(h, body)| {
        let mut s = h.as_bytes().to_vec();
        for (t, sep) in body {
            s.extend_from_slice(t.as_bytes());
            s.extend_from_slice(sep.as_bytes());
        }
        s
    })
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(400))]

    /// CLI-ERR-01: on arbitrary bytes, every block's `run` and `check` return outputs or a
    /// located error, never panic; reference and optimized give the same result.
    #[test]
    fn runner_total_on_arbitrary_bytes(bytes in prop_oneof![csvish(), prop::collection::vec(any::<u8>(), 0..200)]) {
        for block in Block::ALL {
            let spec = BlockSpec::new(block);
            let text = match block.preset().kind {
                PresetKind::S5Time => "S5T#20MS",
                PresetKind::Time => "T#5MS",
                PresetKind::Integer | PresetKind::S5Count => "3",
            };
            spec.preset_literal(text).expect("a valid preset");
            let presets = Some(text);
            let reference = run_str(spec, &bytes, presets);
            let optimized = run_str(spec.with(Implementation::Optimized), &bytes, presets);
            prop_assert_eq!(&reference, &optimized, "{}", block);
            if let Err(e) = &reference {
                prop_assert!(!e.message.is_empty());
            }
            let _ = check(spec, presets, None, &bytes[..]);
            let _ = diagram::svg(spec, presets, &bytes[..], Window::default(), Vec::new());
            let _ = vcd::export(spec, presets, &bytes[..], Vec::new());
        }
    }
}
