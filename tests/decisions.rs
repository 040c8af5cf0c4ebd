//! Scenarios that pin the items of the decision register (`spec/decisions.md`) that no vector
//! pins: each test names its item and rule. Expected values are worked out by hand from the
//! rule's text in the comments.

use plc_timers::iec::{IecInput, IecKind, IecTimer, IecTimerOps, IecTimerRef};
use plc_timers::s5::{S5Input, S5Kind, S5Timer, S5TimerOps, S5TimerRef};
use plc_timers::time::{CpuTime, S5Time};

fn at(ms: u64) -> CpuTime {
    CpuTime::from_millis(ms)
}

/// decisions.md R2, IEC-RETAIN-01: a retentive TONR running at STOP (started at 0 ms, PT 100
/// ms, 40 ms accumulated at the STOP) is restarted with IN = 0 at 1 000 ms: the 960 ms of the
/// STOP count, so the restart's first call finds ET = PT and Q = 1. Non-retentive: all 0.
#[test]
fn retentive_tonr_running_at_stop_counts_the_stop() {
    let pt = plc_timers::time!("T#100MS");
    for retentive in [false, true] {
        let mut r = IecTimerRef::<u32>::new();
        let mut s = IecTimer::new();
        for t in [&mut r as &mut dyn IecTimerOps<u32>, &mut s] {
            t.call(IecKind::Tonr, at(0), IecInput::new(true, pt));
            assert_eq!(
                t.call(IecKind::Tonr, at(40), IecInput::new(true, pt)).et,
                40
            );
            t.run_stop_run(retentive);
            let out = t.call(IecKind::Tonr, at(1_000), IecInput::new(false, pt));
            let expected = if retentive { (true, 100) } else { (false, 0) };
            assert_eq!(
                (out.q, out.et),
                expected,
                "IEC-RETAIN-01: retentive = {retentive}"
            );
        }
    }
}

/// decisions.md R14, S5TMR-TV-01: S_PEXT started at 10 ms with S5T#100MS (10 units); TV
/// changed to S5T#500MS at 30 ms and to S5T#0MS at 60 ms while it runs: it runs on with its
/// own value (BI 8 at 30 ms after the ticks at 20 and 30, BI 5 at 60 ms) and runs out at 110
/// ms; a new rising S at 200 ms loads the TV of that execution (S5T#500MS: 50 units).
#[test]
fn s_pext_tv_changed_while_running_is_latched() {
    let tv = |text| S5Time::parse(text).expect("literal");
    let mut r = S5TimerRef::new();
    let mut w = S5Timer::new();
    for t in [&mut r as &mut dyn S5TimerOps, &mut w] {
        let mut call = |ms, s, text| {
            let o = t.call(S5Kind::SPext, at(ms), S5Input::new(s, false, tv(text)));
            (o.q, o.bi)
        };
        assert_eq!(call(10, true, "S5T#100MS"), (true, 10));
        assert_eq!(call(30, false, "S5T#500MS"), (true, 8), "S5TMR-TV-01");
        assert_eq!(call(60, false, "S5T#0MS"), (true, 5), "S5TMR-TV-01");
        assert_eq!(call(110, false, "S5T#0MS"), (false, 0), "S5TMR-TV-01");
        assert_eq!(call(200, true, "S5T#500MS"), (true, 50), "S5TMR-TV-01");
    }
}

/// decisions.md R16, S5T-RES-01: S5T#5MS is S5T#0MS (cut off, no error), and S5T#10S_5MS loses
/// its 5 ms on the 100 ms base (10 005 ms would need 1 000 units of 10 ms, more than 999); a pulse
/// started with S5T#5MS shows Q = 1 in its starting execution and is run out at the next.
#[test]
fn s5t_5ms_is_zero_and_runs_out_at_the_next_execution() {
    assert_eq!(S5Time::parse("S5T#5MS"), Ok(S5Time::ZERO), "S5T-RES-01");
    assert_eq!(
        S5Time::parse("S5T#10S_5MS").map(S5Time::to_word),
        Ok(0x1100),
        "S5T-RES-01"
    );
    let on = S5Input::new(true, false, plc_timers::s5time!("S5T#5MS"));
    let mut r = S5TimerRef::new();
    let mut w = S5Timer::new();
    for t in [&mut r as &mut dyn S5TimerOps, &mut w] {
        assert!(t.call(S5Kind::SPulse, at(0), on).q, "S5T-RES-01");
        assert!(!t.call(S5Kind::SPulse, at(1), on).q, "S5T-RES-01");
    }
}

/// decisions.md R15, IEC-SHARE-01: a TP and a TON on one structure, both with IN held: the
/// TP's call at 0 ms starts a 100 ms pulse and stores IN = 1; the TON's call at 10 ms sees no
/// rising edge and updates the running timer by its own rule (Q = 0 while ET < PT, ET 10);
/// at 100 ms the TON's call finds ET = PT: Q = 1 (TON's rule), where the TP's would give 0.
#[test]
fn shared_structure_ton_after_tp_sees_no_edge() {
    let pt = plc_timers::time!("T#100MS");
    let mut r = IecTimerRef::<u32>::new();
    let mut s = IecTimer::new();
    for t in [&mut r as &mut dyn IecTimerOps<u32>, &mut s] {
        assert!(t.call(IecKind::Tp, at(0), IecInput::new(true, pt)).q);
        let o = t.call(IecKind::Ton, at(10), IecInput::new(true, pt));
        assert_eq!((o.q, o.et), (false, 10), "IEC-SHARE-01");
        let o = t.call(IecKind::Ton, at(100), IecInput::new(true, pt));
        assert_eq!((o.q, o.et), (true, 100), "IEC-SHARE-01");
    }
}

/// decisions.md R10, S5TMR-TVBCD-01: `W#16#00A0` (a tens digit of 10) is no TV: the literal and
/// the word are refused with the digit named, so no box can be called with it.
#[test]
fn tv_word_not_bcd_never_reaches_the_box() {
    assert!(S5Time::from_word(0x00A0).is_err(), "S5TMR-TVBCD-01");
    assert!(S5Time::parse("W#16#00A0").is_err(), "S5TMR-TVBCD-01");
    let message = S5Time::from_word(0x00A0)
        .map_err(|e| e.to_string())
        .expect_err("not BCD");
    assert!(message.contains("10") || message.contains('A'), "{message}");
}
