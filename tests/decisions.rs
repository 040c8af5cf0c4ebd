//! Scenarios that pin the items of the decision register (`spec/decisions.md`) that no vector
//! pins: each test names its item and rule. Expected values are worked out by hand from the
//! rule's text in the comments.

use plc_timers::counter::s5::{
    CounterMemory, S5Counter, S5CounterInput, S5CounterKind, S5CounterOps, S5CounterRef,
};
use plc_timers::iec::{IecInput, IecKind, IecTimer, IecTimerOps, IecTimerRef};
use plc_timers::s5::{S5Input, S5Kind, S5State, S5Timer, S5TimerOps, S5TimerRef, TimerMemory};
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

/// decisions.md R17, S5TMR-RETAIN-01: S_ODT with S5T#100MS (10 units of 10 ms), S held from 0
/// ms, the CPU in STOP from 45 ms to 5 000 ms. The ticks at 10, 20, 30 and 40 ms leave 6 units
/// at STOP; none falls in STOP, so a retentive timer has 6 units at the restart and runs out
/// with the 6th tick after it, at 5 060 ms (BI 1 and Q 0 at 5 050 ms). Counting the STOP would
/// have given Q = 1 at 5 000 ms. A non-retentive timer is cleared; S still 1 at 5 000 ms is a
/// rising edge: it starts again with 10 units (BI 5 at 5 050 ms) and runs out at 5 100 ms.
/// The area takes T 0 as retentive and T 1 not.
#[test]
fn s_odt_across_stop_no_tick_in_stop() {
    let on = S5Input::new(true, false, S5Time::parse("S5T#100MS").expect("literal"));
    let kind = S5Kind::SOdt;
    for retentive in [false, true] {
        let mut r = S5TimerRef::new();
        let mut w = S5Timer::new();
        r.call(kind, at(0), on);
        w.call(kind, at(0), on);
        assert_eq!(r.call(kind, at(40), on).bi, 6);
        assert_eq!(w.call(kind, at(40), on).bi, 6);
        r.run_stop_run(at(45), at(5_000), retentive);
        w.run_stop_run(at(45), at(5_000), retentive);
        if !retentive {
            assert_eq!(r.state(), S5State::RESET, "S5TMR-RETAIN-01: cleared");
            assert_eq!(w.state(), S5State::RESET, "S5TMR-RETAIN-01: cleared");
        }
        let expected = if retentive {
            [(5_000, false, 6), (5_050, false, 1), (5_060, true, 0)]
        } else {
            [(5_000, false, 10), (5_050, false, 5), (5_100, true, 0)]
        };
        for t in [&mut r as &mut dyn S5TimerOps, &mut w] {
            for (ms, q, bi) in expected {
                let o = t.call(kind, at(ms), on);
                assert_eq!(
                    (o.q, o.bi),
                    (q, bi),
                    "S5TMR-RETAIN-01: retentive = {retentive}, at {ms} ms"
                );
            }
        }
    }
    let mut area = TimerMemory::<2>::new();
    for index in 0..2 {
        area.call(index, kind, at(0), on).expect("T 0 and T 1");
    }
    area.run_stop_run(at(45), at(5_000), 1);
    let bi = |area: &mut TimerMemory<2>, index, ms| {
        area.call(index, kind, at(ms), on).expect("T 0 and T 1").bi
    };
    assert_eq!(
        (bi(&mut area, 0, 5_050), bi(&mut area, 1, 5_050)),
        (1, 10),
        "S5TMR-RETAIN-01: T 0 kept with 6 units, T 1 cleared and started again at 5 050 ms"
    );
}

/// decisions.md R17, SC-RETAIN-01: S_CU counted to 3 by three rising CU, CU held at 1 across a
/// STOP. Retentive: CV 3 kept, and the held CU (its memory kept) does not count: 3.
/// Non-retentive: CV 0, the CU memory cleared, so the held CU counts once: 1. The area takes C 0
/// as retentive and C 1 not.
#[test]
fn s_cu_across_stop_kept_or_cleared() {
    let cu = |cu| S5CounterInput {
        cu,
        ..S5CounterInput::default()
    };
    let count_to_three = |c: &mut dyn S5CounterOps| {
        for level in [true, false, true, false, true] {
            c.call(S5CounterKind::SCu, cu(level));
        }
    };
    for retentive in [false, true] {
        let mut r = S5CounterRef::new();
        let mut w = S5Counter::new();
        count_to_three(&mut r);
        count_to_three(&mut w);
        r.run_stop_run(retentive);
        w.run_stop_run(retentive);
        let expected = if retentive { 3 } else { 1 };
        for c in [&mut r as &mut dyn S5CounterOps, &mut w] {
            assert_eq!(
                c.call(S5CounterKind::SCu, cu(true)).cv,
                expected,
                "SC-RETAIN-01: retentive = {retentive}"
            );
        }
    }
    let mut area = CounterMemory::<2>::new();
    for index in 0..2 {
        for level in [true, false, true, false, true] {
            area.call(index, S5CounterKind::SCu, cu(level))
                .expect("C 0 and C 1");
        }
    }
    area.run_stop_run(1);
    let cv: Vec<u16> = (0..2)
        .map(|index| {
            area.call(index, S5CounterKind::SCu, cu(true))
                .expect("C 0 and C 1")
                .cv
        })
        .collect();
    assert_eq!(
        cv,
        [3, 1],
        "SC-RETAIN-01: C 0 kept, C 1 cleared and counted once"
    );
}
