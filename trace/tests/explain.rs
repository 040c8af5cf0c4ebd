//! CLI-CHECK-02: `check` names the requirement that decides a difference, from the reference's
//! own explanation (`call_explained`), never from a copy of the semantics in the tool.
//!
//! One scenario per known deviation of another runtime (`spec/s5.md`, `spec/iec.md`,
//! `spec/counter.md`): each trace is written the way that runtime behaves (its outputs, row by
//! row, agreeing with the reference up to the deviation), and `check` must find the first
//! difference at the deviating row and name the requirement that decides it.

use plc_timers::catalog::Block;
use plc_timers::rule::{Explained, Rule};
use plc_timers_trace::{check, run_explained, BlockSpec, Why};

/// Checks `trace` against the reference of `block`, comparing `outputs` (all when `None`),
/// and returns the explanation of the first difference, which must be at `line`.
fn why(block: Block, outputs: Option<&[&str]>, trace: &str, line: u64) -> Why {
    let report =
        check(BlockSpec::new(block), None, outputs, trace.as_bytes()).expect("a well-formed trace");
    let d = report
        .difference
        .unwrap_or_else(|| panic!("no difference in\n{trace}"));
    assert_eq!(d.line, line, "the deviating row\n{d}");
    // The text shows the deciding rules with their catalog texts.
    let text = d.to_string();
    for rule in d.why.rules.union(
        d.why
            .earlier
            .map_or(Default::default(), |(_, r)| r.difference(d.why.rules)),
    ) {
        assert!(
            text.contains(&format!("{}: {}", rule.id(), rule.text())),
            "{text}"
        );
    }
    d.why
}

/// `rule` decided the difference at its row.
fn decided_at_row(why: &Why, rule: Rule) {
    assert!(
        why.rules.contains(rule),
        "{} not named at the row: {why:?}",
        rule.id()
    );
}

/// awlsim, matiec/OpenPLC, RuSTy and 4diac read PT on every call (spec/iec.md): a TON whose PT
/// drops from 100 ms to 40 ms while it runs switches on at once there. The reference latched
/// 100 ms at the start (IEC-PT-LATCH-01), at line 2.
#[test]
fn pt_read_live() {
    let trace = "t_ms,IN,PT,Q,ET\n\
                 0,1,T#100MS,0,0\n\
                 50,1,T#100MS,0,50\n\
                 60,1,T#40MS,1,40\n";
    let w = why(Block::Ton, None, trace, 4);
    decided_at_row(&w, Rule::IEC_PT_LATCH_01);
    let (line, earlier) = w.earlier.expect("the start");
    assert_eq!(line, 2, "{w:?}");
    assert!(earlier.contains(Rule::IEC_PT_LATCH_01) && earlier.contains(Rule::IEC_START_01));
}

/// awlsim's S7-300/400 system FBs treat PT = 0 as a reset: its TON stays off. The reference's
/// starting call updates and finds ET >= PT = 0 (IEC-PT0-01).
#[test]
fn pt_zero_as_a_reset() {
    let trace = "t_ms,IN,PT,Q,ET\n\
                 0,0,T#0MS,0,0\n\
                 10,1,T#0MS,0,0\n";
    let w = why(Block::Ton, None, trace, 3);
    decided_at_row(&w, Rule::IEC_PT0_01);
    decided_at_row(&w, Rule::IEC_EXPIRY_01);
}

/// matiec, RuSTy and 4diac compare ET with PT only from the next call: their TP with PT = 0
/// gives a pulse of one call. The reference's starting call expires it (IEC-PT0-01).
#[test]
fn no_expiry_in_the_starting_call() {
    let trace = "t_ms,IN,PT,Q,ET\n\
                 0,0,T#0MS,0,0\n\
                 10,1,T#0MS,1,0\n";
    let w = why(Block::Tp, None, trace, 3);
    decided_at_row(&w, Rule::IEC_PT0_01);
}

/// A runtime that expires at ET > PT keeps TON off at ET = PT; the reference expires at
/// ET >= PT (IEC-EXPIRY-01).
#[test]
fn expiry_only_at_et_above_pt() {
    let trace = "t_ms,IN,PT,Q,ET\n\
                 0,1,T#100MS,0,0\n\
                 100,1,T#100MS,0,100\n";
    let w = why(Block::Ton, None, trace, 3);
    decided_at_row(&w, Rule::IEC_EXPIRY_01);
}

/// awlsim computes the remaining time from a deadline in milliseconds (spec/s5.md): 9 ms
/// after a start at 5 ms, 91 ms of 100 remain, shown as 10 units. The reference's 10 ms base
/// ticked at 10 ms (S5TMR-TICK-01), and the running time started at line 2.
#[test]
fn a_deadline_instead_of_ticks() {
    let trace = "t_ms,S,R,TV,BI\n\
                 5,1,0,S5T#100MS,10\n\
                 14,1,0,S5T#100MS,10\n";
    let w = why(Block::SOdt, Some(&["BI"]), trace, 3);
    decided_at_row(&w, Rule::S5TMR_TICK_01);
    let (line, earlier) = w.earlier.expect("the start");
    assert_eq!(line, 2, "{w:?}");
    assert!(earlier.contains(Rule::SD_Q_01), "{w:?}");
}

/// awlsim expires a timer started with TV = 0 at its first access, even the box's own read of
/// Q: its S_PULSE never shows Q = 1. The reference keeps it active in the starting execution
/// (S5TMR-ZERO-01).
#[test]
fn tv_zero_expiring_at_the_first_access() {
    let trace = "t_ms,S,R,TV,Q\n\
                 0,0,0,S5T#0MS,0\n\
                 10,1,0,S5T#0MS,0\n";
    let w = why(Block::SPulse, Some(&["Q"]), trace, 3);
    decided_at_row(&w, Rule::S5TMR_ZERO_01);
}

/// A runtime whose set does not clear the count memories (the awlsim S_CU case): CU
/// held at 1 through the set at line 4 does not count at line 5 there. The reference's set
/// cleared the CU memory (SC-SET-01), so the held CU counts once.
#[test]
fn no_memory_clear_on_a_set() {
    let trace = "CU,S,R,PV,CV\n\
                 0,0,0,C#5,0\n\
                 1,0,0,C#5,1\n\
                 1,1,0,C#5,5\n\
                 1,0,0,C#5,5\n";
    let w = why(Block::SCu, Some(&["CV"]), trace, 5);
    decided_at_row(&w, Rule::SC_EDGE_01);
    let (line, earlier) = w.earlier.expect("the set");
    assert_eq!(line, 4, "{w:?}");
    assert!(earlier.contains(Rule::SC_SET_01), "{w:?}");
}

/// A CTU that stops counting at PV; the reference counts on past it (CNT-Q-01).
#[test]
fn ctu_stopping_at_pv() {
    let trace = "CU,R,PV,Q,CV\n\
                 1,0,2,0,1\n\
                 0,0,2,0,1\n\
                 1,0,2,1,2\n\
                 0,0,2,1,2\n\
                 1,0,2,1,2\n";
    let w = why(Block::Ctu, None, trace, 6);
    decided_at_row(&w, Rule::CNT_Q_01);
}

/// RuSTy's CTUD freezes its edge memories while R holds: releasing R with CU held counts
/// there. The reference's memory took CU = 1 under R at line 3 (CNT-EDGE-01), so nothing
/// counts at line 4.
#[test]
fn rusty_ctud_edge_memory_frozen_under_r() {
    let trace = "CU,CD,R,LD,PV,CV\n\
                 0,0,0,0,3,0\n\
                 1,0,1,0,3,0\n\
                 1,0,0,0,3,1\n";
    let w = why(Block::Ctud, Some(&["CV"]), trace, 4);
    // CU held at 1: its edge memory decides that nothing counts at the row.
    decided_at_row(&w, Rule::CNT_EDGE_01);
    let (line, earlier) = w.earlier.expect("the row under R");
    assert_eq!(line, 3, "{w:?}");
    assert!(earlier.contains(Rule::CNT_PRIO_01), "{w:?}");
}

/// A runtime that reads the S7-1200 manual's RT sentence as "ELAPSED only" (spec/iec.md W3,
/// reading (a)) zeroes ET in the RT row but keeps START: at its next update ET is the time since
/// the old start again, and its TON switches on 200 ms after the first start. The reference
/// zeroed the timer data at line 4 (IEC-RT-01), so IN = 1 there started the time again.
#[test]
fn rt_resets_elapsed_only() {
    let trace = "t_ms,IN,RT,PT,Q,ET\n\
                 0,1,0,T#200MS,0,0\n\
                 100,1,0,T#200MS,0,100\n\
                 150,1,1,T#200MS,0,0\n\
                 200,1,0,T#200MS,1,200\n";
    let w = why(Block::Ton, None, trace, 5);
    decided_at_row(&w, Rule::IEC_EXPIRY_01);
    let (line, earlier) = w.earlier.expect("the RT row");
    assert_eq!(line, 4, "{w:?}");
    assert!(earlier.contains(Rule::IEC_RT_01), "{w:?}");
    assert!(earlier.contains(Rule::IEC_START_01), "{w:?}");
}

/// The optimized implementation gives no rules, and `check` says so instead of naming any.
#[test]
fn optimized_check_names_no_rule() {
    use plc_timers_trace::Implementation;
    let trace = "t_ms,IN,PT,Q,ET\n0,1,T#100MS,0,0\n100,1,T#100MS,0,100\n";
    let spec = BlockSpec::new(Block::Ton).with(Implementation::Optimized);
    let d = check(spec, None, None, trace.as_bytes())
        .expect("well-formed")
        .difference
        .expect("a difference");
    assert!(!d.why.explained && d.why.all().is_empty(), "{:?}", d.why);
    assert!(d.to_string().contains("gives no rules"), "{d}");
}

/// `run --explain`: a `rules` column with the IDs of the rules that decided each row.
#[test]
fn run_explain_adds_the_deciding_rules() {
    let trace = "t_ms,IN,PT\n0,0,T#0MS\n10,1,T#0MS\n20,1,T#0MS\n";
    let mut out = Vec::new();
    run_explained(BlockSpec::new(Block::Ton), None, trace.as_bytes(), &mut out).expect("runs");
    let text = String::from_utf8(out).expect("UTF-8");
    let lines: Vec<&str> = text.lines().collect();
    assert_eq!(lines[0], "t_ms,IN,PT,Q,ET,rules");
    // IN = 0: TON-IN-01 resets (PT = 0 at the box is no reset: IEC-PT0-01); the start with
    // PT = 0 expires at once.
    assert_eq!(lines[1], "0,0,T#0MS,0,0,IEC-PT0-01 TON-IN-01");
    assert!(lines[2].starts_with("10,1,T#0MS,1,0,"), "{text}");
    let ids: Vec<&str> = lines[2]
        .rsplit(',')
        .next()
        .expect("rules")
        .split(' ')
        .collect();
    assert!(
        ids.contains(&"IEC-PT0-01") && ids.contains(&"IEC-EXPIRY-01"),
        "{text}"
    );
    // Nothing acts on a timer that has run out while IN stays 1; PT = 0 at the box still
    // decides that its outputs are those of a preset of 0.
    assert_eq!(lines[3], "20,1,T#0MS,1,0,IEC-PT0-01");
    // A stopped timer with a positive PT and IN held: no rule bears on its outputs.
    let trace = "t_ms,IN,PT\n0,1,T#0MS\n10,1,T#5MS\n";
    let mut out = Vec::new();
    run_explained(BlockSpec::new(Block::Ton), None, trace.as_bytes(), &mut out).expect("runs");
    let text = String::from_utf8(out).expect("UTF-8");
    assert_eq!(text.lines().nth(2), Some("10,1,T#5MS,1,0,"), "{text}");
}

/// A deadline model of the S5 tick (awlsim: the remaining time from a deadline, rounded): 8 ms
/// after a start at 1 ms with 30 ms on the 10 ms base, 22 ms remain, shown as 2 units. No tick
/// fell in (1, 9], and the reference's value stays 3: S5TMR-TICK-01 decides it at the row
/// though it changed nothing, and the start wrote the value at line 2.
#[test]
fn a_deadline_where_no_tick_fell() {
    let trace = "t_ms,S,R,TV,Q,BI\n\
                 1,1,0,S5T#30MS,1,3\n\
                 9,1,0,S5T#30MS,1,2\n";
    let w = why(Block::SPulse, Some(&["Q", "BI"]), trace, 3);
    decided_at_row(&w, Rule::S5TMR_TICK_01);
    let (line, earlier) = w.earlier.expect("the start");
    assert_eq!(line, 2, "{w:?}");
    assert!(earlier.contains(Rule::SP_Q_01), "{w:?}");
    // The ticks end the time before the deadline (a start at 9 ms with 2 units runs out on the
    // ticks at 10 and 20 ms): Q is the ticks' too.
    let trace = "t_ms,S,R,TV,Q\n\
                 9,1,0,S5T#20MS,1\n\
                 25,1,0,S5T#20MS,1\n";
    let w = why(Block::SPulse, Some(&["Q"]), trace, 3);
    decided_at_row(&w, Rule::S5TMR_TICK_01);
}

/// awlsim's TOF treats PT = 0 as a reset: Q = 0 with IN = 1. For the reference PT = 0 is a
/// preset like any other (IEC-PT0-01), and IN = 1 holds Q at 1 (TOF-IN-01).
#[test]
fn tof_pt_zero_as_a_reset() {
    let trace = "t_ms,IN,PT,Q,ET\n\
                 0,1,T#0MS,0,0\n";
    let w = why(Block::Tof, None, trace, 2);
    decided_at_row(&w, Rule::IEC_PT0_01);
    decided_at_row(&w, Rule::TOF_IN_01);
    // PT = 0 after the delay ran out, with IN held at 0: nothing else bears on Q.
    let trace = "t_ms,IN,PT,Q,ET\n\
                 0,1,T#5MS,1,0\n\
                 1,0,T#5MS,1,0\n\
                 10,0,T#5MS,0,5\n\
                 20,0,T#0MS,0,0\n";
    let w = why(Block::Tof, None, trace, 5);
    decided_at_row(&w, Rule::IEC_PT0_01);
}

/// Two sets of an S_CD, the second by a rising FR with S held (line 4): it cleared the CD
/// memory again, so CD held at 1 counts at line 5. A runtime whose set does not clear the
/// memory keeps 5 there. The earlier row named is the later set, the latest row that wrote CV.
#[test]
fn s_cd_two_sets_names_the_later() {
    let trace = "CD,S,R,FR,PV,CV\n\
                 0,1,0,0,C#5,5\n\
                 1,1,0,0,C#5,4\n\
                 1,1,0,1,C#5,5\n\
                 1,1,0,1,C#5,5\n";
    let w = why(Block::SCd, Some(&["CV"]), trace, 5);
    decided_at_row(&w, Rule::SC_EDGE_01);
    let (line, earlier) = w.earlier.expect("the set");
    assert_eq!(line, 4, "{w:?}");
    assert!(earlier.contains(Rule::SC_SET_01), "{w:?}");
}

/// matiec measures the gap on a clock that does not wrap: a TON started at 0 is on 2^32 ms
/// later. The reference's 32-bit clock reads 0 again there, with START = 0: ET = 0
/// (IEC-WRAP-01: a gap of 2^32 ms aliases), though the subtraction itself did not wrap.
#[test]
fn matiec_clock_gap_aliasing_without_a_wrap() {
    let trace = "t_ms,IN,PT,Q,ET\n\
                 0,1,T#500MS,0,0\n\
                 4294967296,1,T#500MS,1,500\n";
    let w = why(Block::Ton, None, trace, 3);
    decided_at_row(&w, Rule::IEC_WRAP_01);
}

/// matiec's CTD stops at 0; the reference counts on below 0 (CNT-SAT-01: only the type's
/// MIN stops it).
#[test]
fn matiec_ctd_stopping_at_zero() {
    let trace = "CD,LD,PV,Q,CV\n\
                 1,0,3,1,0\n";
    let w = why(Block::Ctd, Some(&["CV"]), trace, 2);
    decided_at_row(&w, Rule::CNT_SAT_01);
    decided_at_row(&w, Rule::CNT_EDGE_01);
}

/// matiec's CTUD also stops at 0 counting down, and that is the first difference here.
#[test]
fn matiec_ctud_stopping_at_zero() {
    let trace = "CU,CD,R,LD,PV,QU,QD,CV\n\
                 1,0,0,0,3,0,0,1\n\
                 0,1,0,0,3,0,1,0\n\
                 0,0,0,0,3,0,1,0\n\
                 0,1,0,0,3,0,1,0\n";
    let w = why(Block::Ctud, Some(&["CV"]), trace, 5);
    decided_at_row(&w, Rule::CNT_SAT_01);
}

/// One row of a generated trace: its CSV inputs, and the reference's explained call on them
/// (driven here directly through the library, not through `check`).
struct Driven {
    inputs: String,
    explained: Explained<Vec<i128>>,
}

/// The rows of a random trace of `block` (TON, S_ODT or CTUD) from `seed`, each with the
/// reference's outputs and explanation.
fn driven(block: Block, seeds: &[(u16, u8)]) -> (String, Vec<Driven>) {
    use plc_timers::counter::{CounterInput, CounterKind, CounterRef};
    use plc_timers::iec::{IecInput, IecKind, IecTimerRef};
    use plc_timers::s5::{S5Input, S5Kind, S5TimerRef};
    use plc_timers::time::{CpuTime, S5Time, Time};
    let mut t = 0u64;
    let mut ton = IecTimerRef::<u32>::new();
    let mut odt = S5TimerRef::new();
    let mut ctud = CounterRef::<i16>::new();
    let mut rows = Vec::new();
    for &(step, bits) in seeds {
        let b = |i: u8| bits >> i & 1 != 0;
        let map = |e: Explained<[i128; 3]>| Explained {
            output: e.output.to_vec(),
            outputs: e.outputs,
            state: e.state,
            written: e.written,
        };
        let (inputs, explained) = match block {
            Block::Ton => {
                t += u64::from(step % 300);
                let pt = [0, 50, 100, 200][usize::from(bits >> 1 & 3)];
                let input = IecInput::new(b(0), Time::from_millis(pt));
                let e = ton.call_explained(IecKind::Ton, CpuTime::from_millis(t), input);
                let o = [i128::from(e.output.q), i128::from(e.output.et), 0];
                (
                    format!("{t},{},T#{pt}MS", u8::from(b(0))),
                    map(Explained {
                        output: o,
                        outputs: e.outputs,
                        state: e.state,
                        written: e.written,
                    }),
                )
            }
            Block::SOdt => {
                t += u64::from(step % 40);
                let units = [0u16, 2, 5][usize::from(bits >> 2 & 3) % 3];
                let tv = S5Time::new(units, plc_timers::time::TimeBase::Ms10).expect("valid");
                // R rarely: one row in four at most.
                let r = b(1) && b(4);
                let e = odt.call_explained(
                    S5Kind::SOdt,
                    CpuTime::from_millis(t),
                    S5Input::new(b(0), r, tv),
                );
                let o = [
                    i128::from(e.output.q),
                    i128::from(e.output.bi),
                    i128::from(e.output.bcd),
                ];
                (
                    format!(
                        "{t},{},{},S5T#{}MS",
                        u8::from(b(0)),
                        u8::from(r),
                        u32::from(units) * 10
                    ),
                    map(Explained {
                        output: o,
                        outputs: e.outputs,
                        state: e.state,
                        written: e.written,
                    }),
                )
            }
            _ => {
                let pv = [0i16, 2, 3][usize::from(step % 3)];
                let (r, ld) = (b(2) && b(4), b(3) && b(5));
                let input = CounterInput {
                    cu: b(0),
                    cd: b(1),
                    r,
                    ld,
                    pv,
                };
                let e = ctud.call_explained(CounterKind::Ctud, input);
                let o = [
                    i128::from(e.output.qu),
                    i128::from(e.output.qd),
                    i128::from(e.output.cv),
                ];
                let f = |x: bool| u8::from(x);
                (
                    format!("{},{},{},{},{pv}", f(b(0)), f(b(1)), f(r), f(ld)),
                    map(Explained {
                        output: o,
                        outputs: e.outputs,
                        state: e.state,
                        written: e.written,
                    }),
                )
            }
        };
        rows.push(Driven { inputs, explained });
    }
    let header = match block {
        Block::Ton => "t_ms,IN,PT,Q,ET",
        Block::SOdt => "t_ms,S,R,TV,Q,BI,BCD",
        _ => "CU,CD,R,LD,PV,QU,QD,CV",
    };
    (header.to_string(), rows)
}

proptest::proptest! {
    #![proptest_config(proptest::prelude::ProptestConfig::with_cases(300))]

    /// CLI-CHECK-02, the earlier row as `spec/cli.md` defines it: a trace with the reference's
    /// outputs, one cell changed at row `n`, is checked; `check` names at the row the rules that
    /// determined the output there, and as the earlier row the latest row k < n whose call
    /// wrote the output (none when no row did), with the rules that determined it there (and
    /// those that acted on the state there when row n wrote the output as well). And
    /// what makes that row the one whose rules still determine the output: the reference's
    /// value of the output is the same at k and at every row up to n - 1 (no row between wrote
    /// it), an oracle from the outputs alone.
    #[test]
    fn check_names_the_latest_row_that_wrote_the_output(
        which in 0usize..3,
        seeds in proptest::collection::vec((proptest::prelude::any::<u16>(), proptest::prelude::any::<u8>()), 1..30),
        at in proptest::prelude::any::<proptest::sample::Index>(),
        output in 0usize..3,
    ) {
        let block = [Block::Ton, Block::SOdt, Block::Ctud][which];
        let n_outputs = block.outputs().len();
        let o = output % n_outputs;
        let (header, rows) = driven(block, &seeds);
        let n = at.index(rows.len());
        let mut text = format!("{header}\n");
        for (k, row) in rows.iter().enumerate() {
            let mut values: Vec<i128> = row.explained.output[..n_outputs].to_vec();
            if k == n {
                // A boolean flips; an integer goes one up.
                values[o] = if block.outputs()[o].name().starts_with('Q') { 1 - values[o] } else { values[o] + 1 };
            }
            let cells: Vec<String> = values
                .iter()
                .enumerate()
                .map(|(i, v)| if block == Block::SOdt && i == 2 { format!("W#16#{v:04X}") } else { v.to_string() })
                .collect();
            text.push_str(&format!("{},{}\n", row.inputs, cells.join(",")));
        }
        let report = check(BlockSpec::new(block), None, None, text.as_bytes()).expect("well-formed");
        let d = report.difference.expect("the changed cell differs");
        proptest::prop_assert_eq!(d.line, n as u64 + 2, "CLI-CHECK-02: the changed row\n{}", text);
        proptest::prop_assert_eq!(d.why.rules, rows[n].explained.outputs[o], "CLI-CHECK-02: the rules at the row");
        let k = (0..n).rev().find(|&k| rows[k].explained.written & (1 << o) != 0);
        // When row n wrote the output too, the rules that acted on the state at k are named.
        let wrote_n = rows[n].explained.written & (1 << o) != 0;
        let expected = k.map(|k| {
            let e = &rows[k].explained;
            (k as u64 + 2, if wrote_n { e.outputs[o].union(e.state) } else { e.outputs[o] })
        });
        proptest::prop_assert_eq!(d.why.earlier, expected, "CLI-CHECK-02: the earlier row\n{}", text);
        // CTUD's QU and QD are derived from CV and the PV of the row: only CV is carried.
        let carried = !(block == Block::Ctud && o < 2);
        if let (Some(k), true) = (k, carried) {
            for j in k + 1..n {
                proptest::prop_assert_eq!(
                    rows[j].explained.output[o], rows[k].explained.output[o],
                    "CLI-CHECK-02: no row after the earlier one changed the output\n{}", text
                );
            }
        }
    }
}
