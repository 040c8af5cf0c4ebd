//! The built binary against `shared/trace-format.md`: conversions with values derived from the
//! manuals, and the exit statuses of `run` and `check`.

mod common;

use common::{plc, text};

/// CLI-CONV-01: seed 000 Fig. 9-1 shows the time value word `W#16#2127`: base bits 10 (1 s),
/// BCD 127, so 127 s = 127000 ms, which the automatic base writes back as the same word; the TIME
/// range ends of seed 001 (T#-24D_20H_31M_23S_648MS .. T#24D_20H_31M_23S_647MS) are
/// i32::MIN ..= i32::MAX ms and one step beyond either end is rejected with exit status 2.
#[test]
fn cli_conv_seed000_fig9_1_and_time_range_ends() {
    let ok: &[(&[&str], String)] = &[
        (
            &["s5time", "W#16#2127"],
            "W#16#2127 127000 S5T#2M7S\n".into(),
        ),
        (
            &["s5time", "w#16#2127"],
            "W#16#2127 127000 S5T#2M7S\n".into(),
        ),
        (
            &["time", "T#24D_20H_31M_23S_647MS"],
            format!("{} T#24D_20H_31M_23S_647MS\n", i32::MAX),
        ),
        (
            &["time", "TIME#-24d_20h_31m_23s_648ms"],
            format!("{} T#-24D_20H_31M_23S_648MS\n", i32::MIN),
        ),
        (&["time", "T#-5s"], "-5000 T#-5S\n".into()),
    ];
    for (args, expected) in ok {
        let o = plc(args, b"");
        assert!(o.status.success(), "{args:?}: {}", text(&o.stderr));
        assert_eq!(text(&o.stdout), *expected, "{args:?}");
    }
    for args in [
        &["time", "T#24D_20H_31M_23S_648MS"][..],
        &["time", "T#-24D_20H_31M_23S_649MS"],
        &["s5time", "W#16#20A0"],
        &["s5time", "S5T#"],
        &["time", ""],
    ] {
        let o = plc(args, b"");
        assert_eq!(o.status.code(), Some(2), "{args:?}");
        assert!(o.stdout.is_empty(), "{args:?}");
        assert!(!text(&o.stderr).trim().is_empty(), "{args:?}: a message");
        assert!(!text(&o.stderr).contains("panicked"), "{args:?}");
    }
}

/// CLI-RUN-01: a header-only trace through the binary (file `-` is standard input) writes the
/// output header and exits 0; a CRLF trace with a BOM gives the same output as the plain one.
#[test]
fn cli_run_header_only_and_text_variants_through_the_binary() {
    let o = plc(&["run", "ton", "--pt", "T#5ms", "-"], b"t_ms,IN\n");
    assert!(o.status.success(), "{}", text(&o.stderr));
    assert_eq!(text(&o.stdout), "t_ms,IN,Q,ET\n");
    let plain = plc(&["run", "TON", "--pt", "5"], b"t_ms,IN\n0,1\n5,1\n");
    let variant = plc(
        &["run", "TON", "--pt", "5"],
        b"\xef\xbb\xbft_ms,IN\r\n0,1\r\n5,1\r\n\r\n",
    );
    assert!(plain.status.success() && variant.status.success());
    assert_eq!(text(&plain.stdout), text(&variant.stdout));
}

/// CLI-CHECK-01 / CLI-ERR-01: `check` exits 0 on agreement, 1 on a difference and 2 on bad input
/// (so a script can tell a wrong implementation from a wrong trace).
#[test]
fn cli_check_exit_statuses() {
    let run = plc(&["run", "CTU", "--pv", "2"], b"CU\n1\n0\n1\n");
    assert!(run.status.success(), "{}", text(&run.stderr));
    let good = run.stdout;
    assert_eq!(text(&good), "CU,Q,CV\n1,0,1\n0,0,1\n1,1,2\n");
    assert_eq!(
        plc(&["check", "CTU", "--pv", "2"], &good).status.code(),
        Some(0)
    );
    let flipped = text(&good).replace("1,1,2", "1,0,2");
    let o = plc(&["check", "CTU", "--pv", "2"], flipped.as_bytes());
    assert_eq!(o.status.code(), Some(1));
    assert!(
        text(&o.stdout).contains("line 4, column 2 (Q)"),
        "{}",
        text(&o.stdout)
    );
    let o = plc(&["check", "CTU", "--pv", "2"], b"CU,Q,CV\n1,0,x\n");
    assert_eq!(
        o.status.code(),
        Some(1),
        "an unparsable output is a difference"
    );
    let o = plc(&["check", "CTU", "--pv", "2"], b"CU,Q,CV\nmaybe,0,1\n");
    assert_eq!(o.status.code(), Some(2));
    assert!(
        text(&o.stderr).contains("line 2, column 1 (CU)"),
        "{}",
        text(&o.stderr)
    );
    let o = plc(&["check", "CTU", "--pv", "2"], b"CU\n1\n");
    assert_eq!(o.status.code(), Some(2));
    assert!(
        text(&o.stderr).contains("no output column"),
        "{}",
        text(&o.stderr)
    );
}
