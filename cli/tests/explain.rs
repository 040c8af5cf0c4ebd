//! CLI-CHECK-02: `check` names the requirement that decides an output at the differing row,
//! from the reference's state before and after the step. One scenario per branch of each
//! family's classifier: a trace is run, one output cell changed, and the first rule `check`
//! names is the expected one.

use plc_timers::catalog::{Block, Port, ValueKind};
use plc_timers_cli::trace::{check, run, BlockSpec, IntType, Why};

/// The rules `check` gives when output `output` of the data row at `t` (the `row`-th data row,
/// 1-based) is changed in the reference's own trace.
fn rules(spec: BlockSpec, trace: &str, row: usize, output: Port) -> Vec<&'static str> {
    explanation(spec, trace, row, output).rules
}

/// The whole explanation (rules and what happened) of that difference.
fn explanation(spec: BlockSpec, trace: &str, row: usize, output: Port) -> Why {
    let mut out = Vec::new();
    run(spec, None, trace.as_bytes(), &mut out).expect("the trace runs");
    let text = String::from_utf8(out).expect("UTF-8");
    let mut lines: Vec<String> = text.lines().map(String::from).collect();
    let header: Vec<&str> = lines[0].split(',').collect();
    let column = header
        .iter()
        .position(|h| *h == output.name())
        .expect("the output column");
    assert!(spec.block.outputs().contains(&output), "an output");
    let kind = output.kind();
    let mut fields: Vec<String> = lines[row].split(',').map(String::from).collect();
    fields[column] = match (kind, fields[column].as_str()) {
        (ValueKind::Bool, "1") => "0".into(),
        (ValueKind::Bool, _) => "1".into(),
        (ValueKind::Word, "W#16#0FFF") => "W#16#0FFE".into(),
        (ValueKind::Word, _) => "W#16#0FFF".into(),
        (_, n) => (n.parse::<i128>().expect("an integer") + 1).to_string(),
    };
    lines[row] = fields.join(",");
    let changed = lines.join("\n");
    let report = check(spec, None, None, changed.as_bytes()).expect("well-formed");
    let d = report.difference.expect("a difference");
    assert_eq!(d.line, row as u64 + 1, "{changed}");
    d.why
}

fn first(spec: BlockSpec, trace: &str, row: usize, output: Port) -> &'static str {
    rules(spec, trace, row, output)[0]
}

fn block(b: Block) -> BlockSpec {
    BlockSpec::new(b)
}

#[test]
fn iec_timer_rules() {
    let ton = block(Block::Ton);
    let t = "t_ms,IN,PT\n0,0,T#500MS\n1000,1,T#500MS\n1200,1,T#500MS\n1300,0,T#500MS\n\
             2000,1,T#500MS\n2250,1,T#100MS\n2500,1,T#500MS\n3000,1,T#500MS\n3200,0,T#500MS\n";
    assert_eq!(
        first(ton, t, 2, Port::Et),
        "IEC-START-01",
        "the starting edge"
    );
    assert_eq!(
        first(ton, t, 3, Port::Et),
        "IEC-START-01",
        "running: ET = now - START"
    );
    assert_eq!(
        first(ton, t, 3, Port::Q),
        "IEC-EXPIRY-01",
        "Q waits for ET >= PT"
    );
    assert_eq!(
        rules(ton, t, 4, Port::Et),
        ["TON-IN-01"],
        "IN falls while running: ET returns to 0 (Q stays 0), no edge rule"
    );
    assert_eq!(
        first(ton, t, 6, Port::Q),
        "IEC-PT-LATCH-01",
        "PT changed while running"
    );
    assert_eq!(
        first(ton, t, 7, Port::Q),
        "IEC-EXPIRY-01",
        "Q rises at ET = PT"
    );
    assert_eq!(
        first(ton, t, 7, Port::Et),
        "IEC-EXPIRY-01",
        "ET stops at PT"
    );
    assert_eq!(first(ton, t, 9, Port::Q), "TON-IN-01", "Q falls with IN");
    assert_eq!(
        rules(ton, t, 1, Port::Q),
        ["TON-IN-01", "IEC-EDGE-01"],
        "no starting edge"
    );
    // A gap of 2^32 + 5 ms while running: elapsed is taken modulo 2^32.
    let wrap = "t_ms,IN,PT\n10,1,T#10S\n4294967311,1,T#10S\n";
    assert_eq!(first(ton, wrap, 2, Port::Et), "IEC-WRAP-01");
    // A gap of 2^31 + 10 ms: elapsed passes PT in that call, so the timer stops running; the
    // wrap rule still decides it.
    let wrap_out = "t_ms,IN,PT\n10,1,T#10S\n2147483668,1,T#10S\n";
    assert_eq!(first(ton, wrap_out, 2, Port::Q), "IEC-WRAP-01");
    // PT = 0: the starting call itself expires.
    let zero = "t_ms,IN,PT\n0,0,0\n5,1,0\n";
    assert_eq!(first(ton, zero, 2, Port::Q), "IEC-PT0-01");
    let tp = block(Block::Tp);
    let p = "t_ms,IN,PT\n0,1,T#100MS\n50,0,T#100MS\n60,1,T#100MS\n100,1,T#100MS\n150,0,T#100MS\n200,1,T#100MS\n300,0,T#100MS\n300,1,T#100MS\n";
    assert_eq!(
        first(tp, p, 1, Port::Q),
        "IEC-START-01",
        "a rising IN starts the pulse"
    );
    assert_eq!(
        first(tp, p, 3, Port::Q),
        "TP-IN-01",
        "a rising IN while running"
    );
    assert_eq!(first(tp, p, 4, Port::Q), "IEC-EXPIRY-01", "the pulse ends");
    assert_eq!(
        first(tp, p, 5, Port::Et),
        "TP-IN-01",
        "ET returns to 0 with IN = 0"
    );
    let retrigger = "t_ms,IN,PT\n0,1,T#100MS\n50,0,T#100MS\n100,1,T#100MS\n";
    assert_eq!(first(tp, retrigger, 3, Port::Q), "TP-RETRIGGER-01");
    let tof = block(Block::Tof);
    let f = "t_ms,IN,PT\n0,1,T#100MS\n10,0,T#100MS\n50,1,T#100MS\n60,0,T#100MS\n160,0,T#100MS\n";
    assert_eq!(first(tof, f, 1, Port::Q), "TOF-IN-01", "IN = 1: Q = 1");
    assert_eq!(
        first(tof, f, 2, Port::Et),
        "IEC-START-01",
        "a falling IN starts the delay"
    );
    assert_eq!(
        first(tof, f, 3, Port::Et),
        "TOF-IN-01",
        "IN back to 1 resets"
    );
    assert_eq!(
        first(tof, f, 5, Port::Q),
        "IEC-EXPIRY-01",
        "Q falls at ET = PT"
    );
    let held = "t_ms,IN,PT\n0,1,T#100MS\n10,1,T#100MS\n";
    assert_eq!(
        first(tof, held, 2, Port::Q),
        "TOF-IN-01",
        "IN held at 1 starts nothing"
    );
    let tonr = block(Block::Tonr);
    let r = "t_ms,IN,R,PT\n0,1,0,T#100MS\n40,0,0,T#100MS\n60,1,0,T#100MS\n80,1,1,T#100MS\n";
    assert_eq!(
        first(tonr, r, 2, Port::Et),
        "TONR-IN-01",
        "IN = 0 stops without reset"
    );
    assert_eq!(
        first(tonr, r, 3, Port::Et),
        "TONR-RESUME-01",
        "resumes from the accumulated ET"
    );
    assert_eq!(first(tonr, r, 4, Port::Q), "TONR-R-01");
    let held = "t_ms,IN,R,PT\n0,1,0,T#100MS\n40,1,0,T#100MS\n";
    assert_eq!(
        first(tonr, held, 2, Port::Et),
        "IEC-START-01",
        "IN held: running, no new start"
    );
}

#[test]
fn s5_timer_rules() {
    let sd = block(Block::SOdt);
    let t = "t_ms,S,R,FR,TV\n0,0,0,0,S5T#50MS\n5,1,0,0,S5T#50MS\n20,1,0,0,S5T#50MS\n32,0,0,0,S5T#50MS\n\
             100,1,0,0,S5T#50MS\n150,1,0,0,S5T#50MS\n170,1,0,0,S5T#50MS\n175,1,0,1,S5T#50MS\n180,1,1,0,S5T#50MS\n";
    assert_eq!(
        rules(sd, t, 2, Port::Bi),
        ["SD-Q-01", "S5TMR-EDGE-01"],
        "S rises: start"
    );
    assert_eq!(
        first(sd, t, 3, Port::Bi),
        "S5TMR-TICK-01",
        "ticks count down"
    );
    // The tick explains BI and BCD only: Q of a running SD that has not run out is its kind's
    // rule; a stopped timer's BI did not tick; a call with no tick boundary since the last one
    // (0 -> 2 ms on the 10 ms base) counted nothing.
    assert_eq!(first(sd, t, 3, Port::Q), "SD-Q-01", "Q while running");
    assert_eq!(first(sd, t, 1, Port::Bi), "SD-Q-01", "BI while stopped");
    let no_tick = "t_ms,S,TV\n0,1,S5T#50MS\n2,1,S5T#50MS\n";
    assert_eq!(
        first(sd, no_tick, 2, Port::Bi),
        "SD-Q-01",
        "no tick in 0..2 ms"
    );
    assert_eq!(
        rules(sd, t, 3, Port::Bcd),
        ["S5TMR-TICK-01", "S5TMR-RANGE-01"],
        "BCD: the tick and the BCD form"
    );
    assert_eq!(
        first(sd, t, 4, Port::Bi),
        "S5TMR-STOP-01",
        "S falls: stopped, value kept"
    );
    assert_eq!(
        first(sd, t, 6, Port::Q),
        "S5TMR-EXPIRE-01",
        "the time runs out"
    );
    assert_eq!(
        first(sd, t, 7, Port::Q),
        "S5TMR-EDGE-01",
        "S held: no start"
    );
    assert_eq!(
        first(sd, t, 8, Port::Bi),
        "S5TMR-FR-01",
        "FR with S = 1 restarts"
    );
    assert_eq!(first(sd, t, 9, Port::Q), "S5TMR-R-01");
    assert_eq!(first(sd, t, 1, Port::Q), "SD-Q-01", "nothing happens");
    let zero = "t_ms,S,TV\n0,1,S5T#0MS\n1,1,S5T#0MS\n";
    assert_eq!(first(sd, zero, 2, Port::Q), "S5TMR-ZERO-01");
    let sf = block(Block::SOffdt);
    let f = "t_ms,S,TV\n0,1,S5T#50MS\n10,0,S5T#50MS\n20,1,S5T#50MS\n";
    assert_eq!(
        first(sf, f, 2, Port::Bi),
        "SF-Q-01",
        "S falls: the off-delay starts"
    );
    assert_eq!(
        first(sf, f, 3, Port::Bi),
        "SF-Q-01",
        "S rises: stopped, Q = 1"
    );
    let held = "t_ms,S,TV\n0,1,S5T#50MS\n10,1,S5T#50MS\n";
    assert_eq!(
        first(sf, held, 2, Port::Q),
        "S5TMR-EDGE-01",
        "S held at 1: no edge, nothing starts or stops"
    );
    let sp = block(Block::SPulse);
    let p = "t_ms,S,TV\n0,1,S5T#50MS\n20,0,S5T#50MS\n";
    assert_eq!(first(sp, p, 2, Port::Q), "S5TMR-STOP-01");
    let se = block(Block::SPext);
    assert_eq!(first(se, p, 1, Port::Q), "SE-RUN-ON-01");
    let ss = block(Block::SOdts);
    assert_eq!(first(ss, p, 1, Port::Bi), "SS-Q-01");
}

#[test]
fn iec_counter_rules() {
    let ctud = BlockSpec {
        int_type: IntType::SInt,
        ..block(Block::Ctud)
    };
    let t = "CU,CD,R,LD,PV\n1,0,0,0,3\n0,0,0,0,3\n1,1,0,0,3\n0,0,0,1,127\n1,0,0,0,127\n1,0,0,0,127\n0,0,1,1,3\n";
    assert_eq!(
        first(ctud, t, 1, Port::Cv),
        "CNT-EDGE-01",
        "CU rises: counts"
    );
    assert_eq!(
        rules(ctud, t, 1, Port::Qd),
        ["CNT-Q-01", "CNT-EDGE-01"],
        "QD follows CV"
    );
    assert_eq!(rules(ctud, t, 2, Port::Qu), ["CNT-Q-01"], "CV unchanged");
    assert_eq!(first(ctud, t, 3, Port::Cv), "CNT-SIMUL-01");
    assert_eq!(first(ctud, t, 4, Port::Cv), "CNT-PRIO-01", "LD loads PV");
    assert_eq!(
        first(ctud, t, 5, Port::Cv),
        "CNT-SAT-01",
        "at 127, SINT's top"
    );
    assert_eq!(
        first(ctud, t, 6, Port::Cv),
        "CNT-EDGE-01",
        "CU held: no count"
    );
    assert_eq!(first(ctud, t, 7, Port::Cv), "CNT-PRIO-01", "R before LD");
    let ctd = block(Block::Ctd);
    let d = "CD,LD,PV\n0,1,1\n1,0,1\n";
    assert_eq!(
        rules(ctd, d, 2, Port::Q),
        ["CNT-Q-01", "CNT-EDGE-01"],
        "CTD's Q is QD"
    );
    let why = explanation(ctud, t, 1, Port::Cv);
    assert!(why.what.starts_with("CU rises: CV 0 -> 1"), "{why:?}");
    let why = explanation(ctd, d, 2, Port::Q);
    assert!(why.what.starts_with("QD = CV <= 0 with CV = 0"), "{why:?}");
    let why = explanation(ctud, t, 2, Port::Qu);
    assert!(
        why.what.starts_with("QU = CV >= PV with CV = 1, PV = 3"),
        "{why:?}"
    );
    let why = explanation(ctud, t, 2, Port::Qd);
    assert!(why.what.starts_with("QD = CV <= 0 with CV = 1"), "{why:?}");
}

#[test]
fn s5_counter_rules() {
    let c = block(Block::SCud);
    let t = "CU,CD,S,R,FR,PV\n1,0,0,0,0,C#5\n1,0,0,0,1,C#5\n1,1,0,0,0,C#5\n0,0,1,0,0,C#999\n\
             1,0,0,0,0,C#999\n0,0,0,1,0,C#999\n0,1,0,0,0,C#999\n1,0,1,0,0,C#7\n";
    assert_eq!(first(c, t, 1, Port::Cv), "SC-EDGE-01", "CU rises: counts");
    let why = explanation(c, t, 1, Port::Cv);
    assert!(why.what.starts_with("CU rises: CV 0 -> 1"), "{why:?}");
    let held = "CU,PV\n1,C#5\n1,C#5\n";
    assert_eq!(
        rules(c, held, 2, Port::Cv),
        ["SC-EDGE-01"],
        "CU held, FR never rose"
    );
    assert_eq!(
        first(c, t, 2, Port::Cv),
        "SC-FR-01",
        "FR rises: the held CU counts again"
    );
    assert_eq!(
        first(c, t, 3, Port::Cv),
        "SC-EDGE-01",
        "CD rises alone (CU held)"
    );
    assert_eq!(first(c, t, 4, Port::Cv), "SC-SET-01", "S rises: CV = PV");
    assert_eq!(first(c, t, 5, Port::Cv), "SC-SAT-01", "at 999");
    assert_eq!(first(c, t, 6, Port::Cv), "SC-PRIO-01", "R");
    assert_eq!(first(c, t, 7, Port::Cv), "SC-SAT-01", "at 0");
    assert_eq!(
        rules(c, t, 8, Port::Cv),
        ["SC-SET-01", "SC-PRIO-01"],
        "S over counting"
    );
    assert_eq!(
        rules(c, t, 6, Port::Q),
        ["SC-Q-01", "SC-PRIO-01"],
        "Q = CV != 0"
    );
    assert_eq!(rules(c, t, 4, Port::CvBcd), ["SC-RANGE-01", "SC-SET-01"]);
    // FR rises with S: the set is FR's doing only when S was already held (its memory cleared);
    // a CU that falls meanwhile has nothing to do with it.
    let fr = "CU,S,FR,PV\n1,0,0,C#5\n0,1,1,C#7\n0,1,0,C#7\n0,1,1,C#8\n";
    assert_eq!(rules(c, fr, 2, Port::Cv), ["SC-SET-01"], "S rises with FR");
    let fr_cd = "CD,S,FR,PV\n1,0,0,C#5\n0,1,1,C#7\n";
    assert_eq!(
        rules(c, fr_cd, 2, Port::Cv),
        ["SC-SET-01"],
        "S rises with FR, CD falls"
    );
    assert_eq!(
        rules(c, fr, 4, Port::Cv),
        ["SC-SET-01", "SC-FR-01"],
        "FR rises, S held: set again"
    );
    let both = "CU,CD,PV\n1,1,C#5\n";
    assert_eq!(first(c, both, 1, Port::Cv), "SC-SIMUL-01");
    assert_eq!(rules(c, "CU,PV\n0,C#5\n", 1, Port::Q), ["SC-Q-01"]);
}
