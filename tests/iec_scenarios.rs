//! IEC timer scenarios from the S7-1200 manual and the Strączyński lecture: every row of the
//! "change of PT / IN while running" table (Table 8-20), the clock wrap, negative and maximum PT,
//! update-on-access, the RT and PT coils, retentivity, and the self-resetting-timer pitfall.
//! Each runs the reference and the 16-byte structure side by side; the assertions are the
//! manual's sentence.

use plc_timers::iec::{IecInput, IecKind, IecOutput, IecTimer, IecTimerOps, IecTimerRef, TonBank};
use plc_timers::rule::{Rule, RuleSet};
use plc_timers::time::{CpuTime, Time};

struct Both {
    kind: IecKind,
    reference: IecTimerRef,
    structure: IecTimer,
}

impl Both {
    fn new(kind: IecKind) -> Both {
        Both {
            kind,
            reference: IecTimerRef::new(),
            structure: IecTimer::new(),
        }
    }

    /// A call at the 32-bit clock reading `now` (the CPU time's low 32 bits).
    fn call(&mut self, now: u32, input: bool, pt: i32) -> IecOutput {
        self.call_r(now, input, false, pt)
    }

    fn call_r(&mut self, now: u32, input: bool, reset: bool, pt: i32) -> IecOutput {
        self.call_at(u64::from(now), input, reset, pt)
    }

    /// A call at CPU time `t` ms (64-bit: for gaps past the 32-bit clock's wrap).
    fn call_at(&mut self, t: u64, input: bool, reset: bool, pt: i32) -> IecOutput {
        let i = IecInput::new(input, Time::from_millis(pt)).with_reset(reset);
        let now = CpuTime::from_millis(t);
        let a = self.reference.call(self.kind, now, i);
        let b = self.structure.call(self.kind, now, i);
        assert_eq!(a, b, "reference and structure differ at {t}");
        assert_eq!(self.reference.state(), self.structure.state());
        a
    }

    fn read_q(&mut self, now: u32) -> bool {
        let now = CpuTime::from_millis(u64::from(now));
        let a = self.reference.read_q(now);
        assert_eq!(a, self.structure.read_q(now));
        a
    }

    fn read_et(&mut self, now: u32) -> u32 {
        let now = CpuTime::from_millis(u64::from(now));
        let a = self.reference.read_et(now);
        assert_eq!(a, self.structure.read_et(now));
        a
    }

    /// The coil on both; the reference's through its explained form, which must act as the
    /// plain coil does and name IEC-RT-01 alone.
    fn rt(&mut self) {
        let mut plain = self.reference;
        plain.reset_timer();
        let e = self.reference.reset_timer_explained();
        assert_eq!(
            (e.state, e.outputs[0], e.outputs[1]),
            (
                RuleSet::of(Rule::IEC_RT_01),
                RuleSet::of(Rule::IEC_RT_01),
                RuleSet::of(Rule::IEC_RT_01)
            ),
            "IEC-RT-01: the coil's rules"
        );
        assert_eq!(self.reference, plain, "IEC-RT-01: explained coil = coil");
        self.structure.reset_timer();
    }
}

fn out(q: bool, et: u32) -> IecOutput {
    IecOutput { q, et }
}

/// Table 8-20, TP: "changing PT while the timer runs has no effect".
#[test]
fn tp_s7_1200_table_8_20_pt_change_no_effect() {
    let mut t = Both::new(IecKind::Tp);
    t.call(0, true, 100);
    assert_eq!(t.call(50, true, 10), out(true, 50), "PT 10 ignored");
    assert_eq!(t.call(100, true, 10), out(false, 100));
}

/// Table 8-20, TP: "changing IN while the timer runs has no effect".
#[test]
fn tp_s7_1200_table_8_20_in_change_no_effect() {
    let mut t = Both::new(IecKind::Tp);
    t.call(0, true, 100);
    assert_eq!(t.call(20, false, 100), out(true, 20));
    assert_eq!(
        t.call(40, true, 100),
        out(true, 40),
        "a new rising IN does not retrigger"
    );
    assert_eq!(t.call(100, true, 100), out(false, 100));
}

/// Brief §3 / Strączyński lecture: TP's ET stays at PT while IN = 1 after the pulse, 0 once IN = 0.
#[test]
fn tp_lecture_et_after_pulse() {
    let mut t = Both::new(IecKind::Tp);
    t.call(0, true, 100);
    assert_eq!(t.call(500, true, 100), out(false, 100));
    assert_eq!(t.call(600, false, 100), out(false, 0));
}

/// Table 8-20, TON: "changing PT while the timer runs has no effect".
#[test]
fn ton_s7_1200_table_8_20_pt_change_no_effect() {
    let mut t = Both::new(IecKind::Ton);
    t.call(0, true, 100);
    assert_eq!(
        t.call(60, true, 50),
        out(false, 60),
        "PT 50 ignored while running"
    );
    assert_eq!(t.call(100, true, 50), out(true, 100));
}

/// Table 8-20, TON: "changing IN to FALSE while the timer runs resets and stops it".
#[test]
fn ton_s7_1200_table_8_20_in_false_resets() {
    let mut t = Both::new(IecKind::Ton);
    t.call(0, true, 100);
    assert_eq!(t.call(60, false, 100), out(false, 0));
    assert_eq!(t.call(200, true, 100), out(false, 0), "a new start from 0");
    assert_eq!(t.call(299, true, 100), out(false, 99));
    assert_eq!(
        t.call(300, true, 100),
        out(true, 100),
        "IEC-EXPIRY-01: Q at ET = PT"
    );
}

/// Table 8-20, TOF: "changing PT while the timer runs has no effect".
#[test]
fn tof_s7_1200_table_8_20_pt_change_no_effect() {
    let mut t = Both::new(IecKind::Tof);
    t.call(0, true, 100);
    t.call(10, false, 100);
    assert_eq!(t.call(50, false, 20), out(true, 40));
    assert_eq!(t.call(110, false, 20), out(false, 100));
}

/// Table 8-20, TOF: "changing IN to TRUE while the timer runs resets and stops it".
#[test]
fn tof_s7_1200_table_8_20_in_true_resets() {
    let mut t = Both::new(IecKind::Tof);
    t.call(0, true, 100);
    t.call(10, false, 100);
    assert_eq!(t.call(50, true, 100), out(true, 0));
    assert_eq!(
        t.call(500, true, 100),
        out(true, 0),
        "not timing while IN = 1"
    );
    t.call(510, false, 100);
    assert_eq!(
        t.call(610, false, 100),
        out(false, 100),
        "ET holds PT after the delay"
    );
}

/// Table 8-20, TONR: "changing PT has no effect while running, but when the timer resumes".
#[test]
fn tonr_s7_1200_table_8_20_pt_on_resume() {
    let mut t = Both::new(IecKind::Tonr);
    t.call(0, true, 100);
    assert_eq!(
        t.call(40, true, 50),
        out(false, 40),
        "PT change ignored while running"
    );
    t.call(60, false, 50);
    assert_eq!(
        t.call(70, true, 50),
        out(true, 50),
        "resumes with PT 50: 60 >= 50, clamped"
    );
}

/// Table 8-20, TONR: "IN to FALSE stops without reset; IN back to TRUE continues from the
/// accumulated time".
#[test]
fn tonr_s7_1200_table_8_20_accumulates() {
    let mut t = Both::new(IecKind::Tonr);
    t.call(0, true, 100);
    assert_eq!(t.call(30, false, 100), out(false, 30));
    assert_eq!(t.call(1000, false, 100), out(false, 30), "stopped: ET held");
    t.call(1000, true, 100);
    assert_eq!(t.call(1069, true, 100), out(false, 99));
    assert_eq!(t.call(1070, true, 100), out(true, 100));
    assert_eq!(
        t.call(2000, false, 100),
        out(true, 100),
        "Q stays 1 after IN falls"
    );
}

/// Table 8-19, TONR's R: "1 = reset the elapsed time and the Q bit to 0".
#[test]
fn tonr_s7_1200_table_8_19_r_resets() {
    let mut t = Both::new(IecKind::Tonr);
    t.call(0, true, 100);
    t.call(100, true, 100);
    assert_eq!(t.call_r(110, true, true, 100), out(false, 0));
    assert_eq!(
        t.call(120, true, 100),
        out(false, 0),
        "TONR-RESUME-01: R released, IN = 1 resumes"
    );
    assert_eq!(t.call(220, true, 100), out(true, 100));
}

/// IEC-WRAP-01 (S7-1200 manual: START is subtracted from the CPU timer's current value): a TON started
/// 100 ms before the 32-bit millisecond clock wraps expires 400 ms after the wrap.
#[test]
fn ton_clock_wrap_s7_1200() {
    let mut t = Both::new(IecKind::Ton);
    let start = u32::MAX - 99;
    t.call(start, true, 500);
    assert_eq!(t.call(u32::MAX, true, 500), out(false, 99));
    assert_eq!(t.call(0, true, 500), out(false, 100), "the wrap itself");
    assert_eq!(t.call(399, true, 500), out(false, 499));
    assert_eq!(t.call(400, true, 500), out(true, 500));
}

/// The same through the CLI's clock: t_ms beyond 2^32 is taken modulo 2^32.
#[test]
fn tp_clock_wrap_pulse_spans_the_wrap() {
    let mut t = Both::new(IecKind::Tp);
    t.call(u32::MAX - 10, true, 50);
    assert!(t.call(20, true, 50).q);
    assert_eq!(t.call(39, true, 50), out(false, 50));
}

/// S7-1200 manual, Table 8-21 note: "a negative PT is set to 0 when the timer instruction executes;
/// ET is always positive".
#[test]
fn negative_pt_s7_1200_table_8_21_taken_as_zero() {
    let mut ton = Both::new(IecKind::Ton);
    assert_eq!(
        ton.call(5, true, -1000),
        out(true, 0),
        "IEC-PT0-01: TON with PT 0 is on at once"
    );
    let mut tp = Both::new(IecKind::Tp);
    assert_eq!(
        tp.call(5, true, i32::MIN),
        out(false, 0),
        "TP with PT 0 gives no pulse"
    );
    let mut tof = Both::new(IecKind::Tof);
    tof.call(0, true, -5);
    assert_eq!(
        tof.call(1, false, -5),
        out(false, 0),
        "TOF with PT 0 switches off at once"
    );
}

/// The maximum PT, T#24d_20h_31m_23s_647ms (S7-1200 manual Table 8-21), across the clock wrap.
#[test]
fn maximum_pt_s7_1200_table_8_21() {
    let pt = "T#24d_20h_31m_23s_647ms"
        .parse::<Time>()
        .expect("valid")
        .as_millis();
    let mut t = Both::new(IecKind::Ton);
    t.call(3_000_000_000, true, pt);
    let end = 3_000_000_000u32.wrapping_add(i32::MAX as u32);
    assert_eq!(t.call(end - 1, true, pt), out(false, i32::MAX as u32 - 1));
    assert_eq!(t.call(end, true, pt), out(true, i32::MAX as u32));
}

/// S7-1200 manual "Timer operation": an update happens only when the instruction executes or Q or
/// ELAPSED is read through the structure; a read updates (IEC-ACCESS-01).
#[test]
fn update_on_access_s7_1200() {
    let mut t = Both::new(IecKind::Ton);
    t.call(0, true, 100);
    assert_eq!(t.structure.et(), 0, "no update without an access");
    assert_eq!(t.read_et(40), 40, "reading ELAPSED updates");
    assert!(!t.read_q(99));
    assert!(
        t.read_q(100),
        "reading Q updates: Q rises without a box call"
    );
    assert_eq!(t.structure.et(), 100);
}

/// S7-1200 manual "Timer programming", the self-resetting timer: a normally-closed contact on the
/// structure's Q in front of the timer reads Q (an update), so the timer is restarted in the same
/// scan it expires and the Q output is never seen 1; the remedy, a contact on a variable written
/// by the box's Q output, gives one scan with Q = 1.
#[test]
fn self_resetting_timer_pitfall_s7_1200() {
    let pt = 100;
    // The pitfall: IN = NOT "DB".Q, read through the structure just before the call.
    let mut t = Both::new(IecKind::Ton);
    let mut seen_q = 0;
    for scan in 0..100u32 {
        let now = scan * 7;
        let input = !t.read_q(now);
        if t.call(now, input, pt).q {
            seen_q += 1;
        }
    }
    assert_eq!(seen_q, 0, "Q is never 1 at the box output");
    // The remedy: IN = NOT "Tag_Q", where Tag_Q is the box's Q output of the previous scan.
    let mut t = Both::new(IecKind::Ton);
    let mut tag_q = false;
    let mut pulses = 0;
    for scan in 0..100u32 {
        let now = scan * 7;
        tag_q = t.call(now, !tag_q, pt).q;
        if tag_q {
            pulses += 1;
        }
    }
    assert!(
        pulses >= 5,
        "Q is 1 for one scan each period ({pulses} pulses in 700 ms)"
    );
}

/// IEC-RT-01: the RT coil zeroes the timer data; a TON with IN still 1 starts again from 0.
#[test]
fn rt_coil_lecture_restarts_ton() {
    let mut t = Both::new(IecKind::Ton);
    t.call(0, true, 100);
    t.call(150, true, 100);
    t.rt();
    assert_eq!(t.reference.state().et, 0);
    assert_eq!(t.call(160, true, 100), out(false, 0));
    assert_eq!(t.call(260, true, 100), out(true, 100));
}

/// IEC-RT-01 (decision): RT on a running TP ends the pulse; on a running TOF ends the delay.
#[test]
fn rt_coil_on_running_tp_and_tof() {
    let mut tp = Both::new(IecKind::Tp);
    tp.call(0, true, 100);
    tp.rt();
    assert_eq!(tp.call(10, false, 100), out(false, 0));
    let mut tof = Both::new(IecKind::Tof);
    tof.call(0, true, 100);
    tof.call(10, false, 100);
    tof.rt();
    assert_eq!(
        tof.call(20, false, 100),
        out(false, 0),
        "no falling edge after RT: stays off"
    );
}

/// IEC-RT-01: RT clears the stored IN, so a TP whose IN is still 1 sees a rising edge at its
/// next call and starts a new pulse of PT, running or expired before the coil.
#[test]
fn rt_coil_tp_with_in_held_starts_a_new_pulse() {
    let mut tp = Both::new(IecKind::Tp);
    tp.call(0, true, 100);
    assert_eq!(tp.call(40, true, 100), out(true, 40));
    tp.rt();
    assert_eq!(tp.call(50, true, 100), out(true, 0), "a new pulse from 50");
    assert_eq!(
        tp.call(120, true, 100),
        out(true, 70),
        "the old one ended at 100"
    );
    assert_eq!(tp.call(150, true, 100), out(false, 100));
    tp.rt();
    assert_eq!(tp.call(160, true, 100), out(true, 0), "after expiry too");
}

/// IEC-PT-COIL-01: the PT coil loads the preset, which a running timer uses from its next update.
#[test]
fn pt_coil_loads_preset() {
    let mut t = Both::new(IecKind::Ton);
    t.call(0, true, 100);
    t.reference.preset_timer(Time::from_millis(30));
    t.structure.preset_timer(Time::from_millis(30));
    assert_eq!(
        t.call(30, true, 100),
        out(true, 30),
        "the box's PT input is latched, the coil's is not"
    );
}

/// S7-1200 manual "Retaining timer data": data is lost on RUN-STOP-RUN unless retentive.
#[test]
fn retentivity_s7_1200_run_stop_run() {
    for retentive in [false, true] {
        let mut t = Both::new(IecKind::Tonr);
        t.call(0, true, 100);
        t.call(40, false, 100);
        t.reference.run_stop_run(retentive);
        t.structure.run_stop_run(retentive);
        let expected = if retentive { 40 } else { 0 };
        assert_eq!(
            t.call(1000, false, 100).et,
            expected,
            "retentive = {retentive}"
        );
    }
}

/// The structure is the manual's 16 bytes.
#[test]
fn iec_timer_is_16_bytes_s7_1200() {
    assert_eq!(std::mem::size_of::<IecTimer>(), 16);
}

/// The instruction names of S7-1200 manual (TP, TON, TOF, TONR), in the manual's order.
#[test]
fn kind_names_s7_1200() {
    assert_eq!(
        IecKind::ALL.map(IecKind::name),
        ["TP", "TON", "TOF", "TONR"]
    );
}

/// The state invariant: ET never exceeds the latched PT (S7-1200 manual: ET runs from 0 to PT), and a
/// stopped timer keeps no START; the 16-byte structure refuses any other state.
#[test]
fn state_validity_et_within_pt() {
    use plc_timers::iec::IecState;
    let base = IecState::<u32> {
        pt: 500,
        et: 500,
        ..IecState::default()
    };
    assert!(base.is_valid());
    let et_past_pt = IecState { et: 501, ..base };
    let stopped_with_start = IecState { start: 7, ..base };
    let running_with_start = IecState {
        start: 7,
        running: true,
        ..base
    };
    assert!(!et_past_pt.is_valid() && !stopped_with_start.is_valid());
    assert!(running_with_start.is_valid());
    assert!(IecTimer::from_state(base).is_some());
    assert!(IecTimer::from_state(et_past_pt).is_none());
    assert!(IecTimer::from_state(stopped_with_start).is_none());
}

/// A structure restored from raw bytes (retentive memory, an area shared with another runtime)
/// can hold what no operation produces; `from_bytes` refuses it: a flag bit outside IN (bit 0),
/// Q (1), RUNNING (2), the kind (4-5) and its valid bit (6); ET above PT; START kept while
/// stopped; non-zero padding.
#[test]
fn structure_validity_from_raw_bytes() {
    let raw = |start: u32, pt: u32, et: u32, flags: u8| -> Option<IecTimer> {
        let mut bytes = [0u8; 16];
        bytes[0..4].copy_from_slice(&start.to_ne_bytes());
        bytes[4..8].copy_from_slice(&pt.to_ne_bytes());
        bytes[8..12].copy_from_slice(&et.to_ne_bytes());
        bytes[12] = flags;
        IecTimer::from_bytes(bytes)
    };
    let expired_ton = raw(0, 500, 500, 0b0101_0010).expect("TON expired: Q, kind TON");
    assert!(expired_ton.state().q && expired_ton.pt() == 500);
    let running_tp = raw(7, 500, 0, 0b0100_0101).expect("TP running with START");
    assert_eq!(running_tp.state().start, 7);
    assert!(raw(0, 500, 500, 0x80).is_none(), "stray bit 7");
    assert!(raw(0, 500, 501, 0).is_none(), "ET above PT");
    assert!(raw(7, 500, 0, 0).is_none(), "START kept while stopped");
    let mut padded = running_tp.to_bytes();
    padded[15] = 1;
    assert!(IecTimer::from_bytes(padded).is_none(), "non-zero padding");
}

/// IEC-WRAP-01: gaps between two updates of 2^31 ms and more (but below 2^32 ms) give the exact
/// elapsed time on the wrapping 32-bit clock; a gap of exactly 2^32 ms looks like no time at all.
#[test]
fn gaps_past_2_pow_31_ms() {
    let max = i32::MAX; // the largest PT, 2^31 - 1 ms
    let mut t = Both::new(IecKind::Ton);
    let start = 5_000_000_000u64; // the 32-bit clock has wrapped once already
    t.call_at(start, true, false, max);
    let o = t.call_at(start + (1 << 31) - 2, true, false, max);
    assert_eq!(o, out(false, max as u32 - 1), "2^31 - 2 ms: one ms short");
    let o = t.call_at(start + (1 << 31) + 5, true, false, max);
    assert_eq!(
        o,
        out(true, max as u32),
        "a gap past 2^31 ms: expired, ET = PT"
    );
    let mut t = Both::new(IecKind::Ton);
    t.call_at(start, true, false, 1_000);
    let o = t.call_at(start + (1 << 32), true, false, 1_000);
    assert_eq!(
        o,
        out(false, 0),
        "a gap of 2^32 ms aliases to 0 (IEC-WRAP-01)"
    );
}

/// TP-RETRIGGER-01: a rising IN in the call where the pulse runs out starts the next pulse (the
/// update comes first and ends the pulse, then the edge starts one).
#[test]
fn tp_rising_in_at_expiry_starts_a_new_pulse() {
    let mut t = Both::new(IecKind::Tp);
    t.call(0, true, 100);
    t.call(50, false, 100);
    assert_eq!(
        t.call(100, true, 100),
        out(true, 0),
        "new pulse at the expiring call"
    );
    assert_eq!(t.call(199, true, 100), out(true, 99));
    assert_eq!(t.call(200, true, 100), out(false, 100));
}

/// IEC-PT0-01: with PT = 0 the starting call updates: TON is on at once, TP gives no pulse, TOF
/// is off in the call of the falling edge.
#[test]
fn pt_zero_takes_effect_in_the_starting_call() {
    let mut ton = Both::new(IecKind::Ton);
    assert_eq!(ton.call(10, true, 0), out(true, 0));
    let mut tp = Both::new(IecKind::Tp);
    assert_eq!(tp.call(10, true, 0), out(false, 0));
    let mut tof = Both::new(IecKind::Tof);
    assert!(tof.call(10, true, 0).q);
    assert_eq!(tof.call(20, false, 0), out(false, 0));
}

/// IEC-EXPIRY-01: Q changes in the call where ET reaches PT exactly (ET >= PT), for TON, TP and
/// TOF, never one call later.
#[test]
fn expiry_at_et_equal_pt() {
    let mut ton = Both::new(IecKind::Ton);
    ton.call(0, true, 100);
    assert_eq!(ton.call(100, true, 100), out(true, 100));
    let mut tp = Both::new(IecKind::Tp);
    tp.call(0, true, 100);
    assert_eq!(tp.call(100, true, 100), out(false, 100));
    let mut tof = Both::new(IecKind::Tof);
    tof.call(0, true, 100);
    tof.call(0, false, 100);
    assert_eq!(tof.call(100, false, 100), out(false, 100));
}

/// The input builder sets R and keeps IN and PT (the command-line tool and the bindings build
/// every row's inputs through it).
#[test]
fn input_builder_sets_reset() {
    let pt = Time::from_millis(250);
    for (input, reset) in [(false, false), (true, false), (false, true), (true, true)] {
        let i = IecInput::new(input, pt).with_reset(reset);
        assert_eq!((i.input, i.pt, i.reset), (input, pt, reset));
        assert_eq!(i.with_reset(!reset).reset, !reset, "the builder overwrites");
    }
}

/// Two TON banks are equal exactly when their timers' states are (and both have scanned or
/// neither has).
#[test]
fn ton_banks_compare_by_their_timers() {
    let pt = [Time::from_millis(100); 3];
    let scanned = |input: [bool; 3]| {
        let mut b = TonBank::<3>::new();
        b.scan(CpuTime::from_millis(0), &input, &pt);
        b
    };
    assert_eq!(TonBank::<3>::new(), TonBank::<3>::new());
    assert_ne!(TonBank::<3>::new(), scanned([false; 3]), "one has scanned");
    assert_eq!(scanned([false, true, false]), scanned([false, true, false]));
    assert_ne!(
        scanned([false, true, false]),
        scanned([true, false, false]),
        "timers differ"
    );
}

/// S5TMR-CLOCK-01 / IEC-WRAP-01: the IEC timers compute ET as now - START modulo 2^32, so a
/// clock 1 ms behind the start reads as 2^32 - 1 ms elapsed: a running TON expires at once.
/// (That is why `now` must not go back.)
#[test]
fn ton_clock_behind_start_reads_as_a_wrap() {
    let mut t = Both::new(IecKind::Ton);
    t.call(1000, true, 500);
    assert_eq!(t.call(1100, true, 500), out(false, 100));
    assert_eq!(
        t.call(999, true, 500),
        out(true, 500),
        "S5TMR-CLOCK-01: 1 ms behind START is 2^32 - 1 ms later"
    );
}
