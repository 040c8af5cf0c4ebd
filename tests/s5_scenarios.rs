//! S5 timer scenarios, one per sentence of the manuals (LAD manual §9.1-9.7, Berger §7). Each
//! scenario runs the reference, the lone optimized timer, the timer memory area's box and the
//! area's STL sequence (`FR`, start, `R`, then `A`, `L`, `LC`) side by side and checks that all
//! four agree; the assertions are the manual's sentence.

use plc_timers::s5::{
    S5Input, S5Kind, S5Output, S5State, S5Timer, S5TimerOps, S5TimerRef, TimerMemory, TimerWord,
};
use plc_timers::time::{CpuTime, S5Time, TimeBase};

/// The four forms of one timer, driven together.
struct Both {
    kind: S5Kind,
    reference: S5TimerRef,
    lone: S5Timer,
    area: TimerMemory<1>,
    stl: TimerMemory<1>,
    tv: S5Time,
}

impl Both {
    fn new(kind: S5Kind, tv: &str) -> Both {
        let tv = tv.parse().expect("valid TV literal");
        Both {
            kind,
            reference: S5TimerRef::new(),
            lone: S5Timer::new(),
            area: TimerMemory::new(),
            stl: TimerMemory::new(),
            tv,
        }
    }

    /// Executes at `t` ms with S, R (FR = 0); asserts all four implementations agree.
    fn at(&mut self, t: u64, s: bool, r: bool) -> S5Output {
        self.with_fr(t, s, r, false)
    }

    fn with_fr(&mut self, t: u64, s: bool, r: bool, fr: bool) -> S5Output {
        let input = S5Input::new(s, r, self.tv).with_fr(fr);
        let now = CpuTime::from_millis(t);
        let a = self.reference.call(self.kind, now, input);
        assert_eq!(
            self.lone.call(self.kind, now, input),
            a,
            "S5Timer at t = {t}"
        );
        let b = self.area.call(0, self.kind, now, input).expect("timer 0");
        assert_eq!(b, a, "timer memory box at t = {t}");
        self.stl.advance_to(now);
        self.stl.fr(0, fr).expect("T 0");
        self.stl.start(0, self.kind, s, self.tv).expect("T 0");
        self.stl.reset(0, r).expect("T 0");
        let read = (self.stl.status(0), self.stl.load(0), self.stl.load_bcd(0));
        assert_eq!(
            read,
            (Ok(a.q), Ok(a.bi), Ok(a.bcd)),
            "STL sequence at t = {t}"
        );
        assert_eq!(
            self.reference.state(),
            self.lone.state(),
            "states at t = {t}"
        );
        a
    }
}

/// §9.3: "starts the timer when S has a rising edge … runs with the value at TV as long as S = 1
/// … while the timer runs, Q = 1".
#[test]
fn s_pulse_lad_9_3_runs_while_s_and_q_is_1() {
    let mut t = Both::new(S5Kind::SPulse, "S5T#50MS");
    assert!(t.at(0, true, false).q);
    let o = t.at(30, true, false);
    assert_eq!((o.q, o.bi), (true, 2));
    assert!(!t.at(50, true, false).q, "the programmed time has run out");
}

/// §9.3: "if S changes from 1 to 0 before the time has elapsed, the timer stops; Q = 0".
#[test]
fn s_pulse_lad_9_3_s_falling_stops() {
    let mut t = Both::new(S5Kind::SPulse, "S5T#50MS");
    t.at(0, true, false);
    let o = t.at(20, false, false);
    assert!(!o.q);
    assert_eq!(
        t.at(100, false, false).bi,
        3,
        "S5TMR-STOP-01: the stopped value stays readable"
    );
}

/// §9.3: "a change of signal state is always required to enable the timer": S held at 1 after
/// the pulse does not start it again.
#[test]
fn s_pulse_lad_9_3_needs_signal_change() {
    let mut t = Both::new(S5Kind::SPulse, "S5T#20MS");
    t.at(0, true, false);
    assert!(!t.at(20, true, false).q);
    assert!(!t.at(100, true, false).q, "no new edge, no new pulse");
    t.at(110, false, false);
    assert!(t.at(120, true, false).q, "a new rising edge starts it");
}

/// §9.3: "the timer is reset if R changes from 0 to 1 while the timer runs; the time value and
/// the time base are also reset to zero".
#[test]
fn s_pulse_lad_9_3_reset_while_running_clears_value_and_base() {
    let mut t = Both::new(S5Kind::SPulse, "S5T#5S"); // 500 x 10 ms
    t.at(0, true, false);
    let o = t.at(10, true, true);
    assert_eq!(
        o,
        S5Output {
            q: false,
            bi: 0,
            bcd: 0x0000
        }
    );
}

/// §9.3: "R = 1 has no effect if the timer is not running": Q stays 0 and a later start works.
#[test]
fn s_pulse_lad_9_3_reset_while_stopped_no_effect_on_q() {
    let mut t = Both::new(S5Kind::SPulse, "S5T#50MS");
    assert!(!t.at(0, false, true).q);
    assert!(t.at(10, true, false).q);
}

/// §9.4: "the timer keeps running … even if S changes to 0 before the time has elapsed".
#[test]
fn s_pext_lad_9_4_runs_on_when_s_falls() {
    let mut t = Both::new(S5Kind::SPext, "S5T#50MS");
    t.at(0, true, false);
    assert!(t.at(10, false, false).q);
    assert!(t.at(49, false, false).q);
    assert!(!t.at(50, false, false).q);
}

/// §9.4: "the timer is restarted with the programmed value if S changes from 0 to 1 while the
/// timer runs".
#[test]
fn s_pext_lad_9_4_retriggers() {
    let mut t = Both::new(S5Kind::SPext, "S5T#50MS");
    t.at(0, true, false);
    t.at(10, false, false);
    let o = t.at(30, true, false);
    assert_eq!((o.q, o.bi), (true, 5), "restarted with the full value");
    assert!(t.at(79, true, false).q);
    assert!(!t.at(80, true, false).q);
}

/// §9.4: R while running resets it, value and base cleared.
#[test]
fn s_pext_lad_9_4_reset() {
    let mut t = Both::new(S5Kind::SPext, "S5T#1M"); // 600 x 100 ms
    t.at(0, true, false);
    assert_eq!(
        t.at(5, false, true),
        S5Output {
            q: false,
            bi: 0,
            bcd: 0
        }
    );
}

/// §9.5: "Q = 1 when the time has elapsed without error, S is still 1 and R stays 0".
#[test]
fn s_odt_lad_9_5_q_after_time_while_s() {
    let mut t = Both::new(S5Kind::SOdt, "S5T#50MS");
    assert!(!t.at(0, true, false).q);
    assert!(!t.at(40, true, false).q);
    assert!(t.at(50, true, false).q);
    assert!(t.at(500, true, false).q);
    assert!(!t.at(510, false, false).q, "S = 0: Q = 0");
}

/// §9.5: "if S changes from 1 to 0 while the timer runs, it stops; Q = 0".
#[test]
fn s_odt_lad_9_5_s_falling_stops() {
    let mut t = Both::new(S5Kind::SOdt, "S5T#50MS");
    t.at(0, true, false);
    assert!(!t.at(20, false, false).q);
    assert!(!t.at(100, false, false).q, "stopped: never expires");
}

/// §9.5: "the timer is also reset if R = 1 while the timer is not running" (clears an expired Q).
#[test]
fn s_odt_lad_9_5_reset_when_not_running() {
    let mut t = Both::new(S5Kind::SOdt, "S5T#20MS");
    t.at(0, true, false);
    assert!(t.at(20, true, false).q);
    assert!(!t.at(30, true, true).q);
    assert!(
        !t.at(40, true, false).q,
        "no new edge after R: stays off (S5TMR-R-01)"
    );
}

/// §9.5 and decision SD-RESTART-01: after expiry a restart needs S to fall and rise again.
#[test]
fn s_odt_restart_after_expiry_needs_new_edge() {
    let mut t = Both::new(S5Kind::SOdt, "S5T#20MS");
    t.at(0, true, false);
    assert!(t.at(20, true, false).q);
    t.at(30, false, false);
    assert!(!t.at(40, true, false).q);
    assert!(t.at(60, true, false).q);
}

/// §9.6: "Q = 1 after the time has elapsed, whatever S does, as long as R stays 0".
#[test]
fn s_odts_lad_9_6_q_latched_until_r() {
    let mut t = Both::new(S5Kind::SOdts, "S5T#30MS");
    t.at(0, true, false);
    t.at(10, false, false);
    assert!(t.at(30, false, false).q);
    assert!(t.at(1000, false, false).q);
    assert!(!t.at(1010, false, true).q, "§9.6: R resets whatever S is");
}

/// §9.6: "if S changes from 0 to 1 while the timer runs, it restarts with the programmed value".
#[test]
fn s_odts_lad_9_6_retriggers() {
    let mut t = Both::new(S5Kind::SOdts, "S5T#30MS");
    t.at(0, true, false);
    t.at(10, false, false);
    let o = t.at(20, true, false);
    assert_eq!((o.q, o.bi), (false, 3));
    assert!(!t.at(49, true, false).q);
    assert!(t.at(50, true, false).q);
}

/// §9.6: "Q = 1 after the time has run out, whatever S does, as long as R stays 0": a rising S
/// after the end restarts the time (BI counts down again), and Q stays 1 (SS-Q-01).
#[test]
fn s_odts_lad_9_6_restart_after_expiry_keeps_q() {
    let mut t = Both::new(S5Kind::SOdts, "S5T#30MS");
    t.at(0, true, false);
    assert!(t.at(30, true, false).q, "run out: Q = 1");
    t.at(40, false, false);
    let o = t.at(50, true, false);
    assert_eq!((o.q, o.bi), (true, 3), "restarted with TV, Q still 1");
    assert_eq!(t.at(70, true, false).bi, 1);
    let o = t.at(80, true, false);
    assert_eq!((o.q, o.bi), (true, 0), "run out again, Q still 1");
    assert!(!t.at(90, true, true).q, "only R clears it");
}

/// §9.6: R resets "regardless of the RLO at S" (S = 1 held).
#[test]
fn s_odts_lad_9_6_reset_with_s_held() {
    let mut t = Both::new(S5Kind::SOdts, "S5T#20MS");
    t.at(0, true, false);
    assert!(t.at(20, true, false).q);
    assert_eq!(
        t.at(30, true, true),
        S5Output {
            q: false,
            bi: 0,
            bcd: 0
        }
    );
}

/// §9.7: "starts on a falling edge at S … Q = 1 if S = 1 or the timer runs".
#[test]
fn s_offdt_lad_9_7_falling_edge_and_q() {
    let mut t = Both::new(S5Kind::SOffdt, "S5T#30MS");
    assert!(!t.at(0, false, false).q, "S never 1, never started");
    assert!(t.at(5, true, false).q, "Q = 1 while S = 1");
    let o = t.at(15, false, false);
    assert_eq!((o.q, o.bi), (true, 3), "falling S starts the time");
    assert!(t.at(39, false, false).q);
    assert!(!t.at(40, false, false).q);
}

/// §9.7: "the timer is reset if S changes from 0 to 1 while it runs; it starts again only when S
/// changes from 1 to 0".
#[test]
fn s_offdt_lad_9_7_rising_s_while_running_stops() {
    let mut t = Both::new(S5Kind::SOffdt, "S5T#30MS");
    t.at(0, true, false);
    t.at(5, false, false);
    assert!(t.at(15, true, false).q, "Q follows S = 1");
    assert!(
        t.at(100, true, false).q,
        "not running: no expiry while S = 1"
    );
    t.at(105, false, false);
    assert!(t.at(120, false, false).q);
    assert!(!t.at(140, false, false).q);
}

/// §9.7 with Berger §7.1.3 and decision SF-Q-01: R while running resets; Q is the status bit
/// that the edges of S set, so after R with S held it stays 0 until S changes.
#[test]
fn s_offdt_reset_and_s_held() {
    let mut t = Both::new(S5Kind::SOffdt, "S5T#30MS");
    t.at(0, true, false);
    t.at(5, false, false);
    assert!(!t.at(10, false, true).q);
    assert!(!t.at(100, false, false).q, "reset: no time left");
    assert!(
        !t.at(110, true, true).q,
        "R = 1 holds Q at 0 even with S rising (Berger §7.1.3)"
    );
    assert!(
        !t.at(120, true, false).q,
        "R released, S held: no edge, Q stays 0"
    );
    let o = t.at(130, false, false);
    assert_eq!(
        (o.q, o.bi),
        (true, 3),
        "the next falling S starts the off-delay"
    );
    assert!(t.at(140, true, false).q, "and a rising S sets Q");
}

/// Berger §7.1.3: "while the RLO at R T n is 1, a check of the timer for 1 gives 0".
#[test]
fn r_level_berger_7_1_3_holds_q_at_zero() {
    for kind in S5Kind::ALL {
        let mut t = Both::new(kind, "S5T#20MS");
        for (time, s) in [(0, true), (10, false), (20, true), (30, true), (40, false)] {
            assert!(!t.at(time, s, true).q, "{kind:?} at {time}");
        }
    }
}

/// Berger §7: "if the time value is 0, the timer stays active until the CPU, processing the
/// timer, finds the time elapsed": active in the starting execution, run out at the next.
#[test]
fn value_zero_berger_7_active_until_next_processing() {
    let mut sp = Both::new(S5Kind::SPulse, "S5T#0MS");
    assert!(sp.at(0, true, false).q, "active in the starting call");
    assert!(
        !sp.at(0, true, false).q,
        "run out when processed again, even with no tick"
    );
    let mut sd = Both::new(S5Kind::SOdt, "S5T#0MS");
    assert!(!sd.at(0, true, false).q);
    assert!(sd.at(0, true, false).q);
}

/// LAD manual §9.1: the OS decrements the value by one unit per interval of the base: every base,
/// BI after each tick, and expiry exactly on the v-th tick after the start (S5TMR-TICK-01).
#[test]
fn time_base_model_lad_9_1_all_bases() {
    for (tv, base) in [
        ("W#16#0003", TimeBase::Ms10),
        ("W#16#1003", TimeBase::Ms100),
        ("W#16#2003", TimeBase::S1),
        ("W#16#3003", TimeBase::S10),
    ] {
        let b = u64::from(base.millis());
        let mut t = Both::new(S5Kind::SOdt, tv);
        // Start a little after a tick: the first tick comes less than one base later.
        let start = 5 * b + 1;
        assert_eq!(t.at(start, true, false).bcd >> 12, u16::from(base.bits()));
        assert_eq!(t.at(6 * b - 1, true, false).bi, 3, "{base:?}: no tick yet");
        assert_eq!(t.at(6 * b, true, false).bi, 2, "{base:?}: first tick");
        assert_eq!(t.at(7 * b, true, false).bi, 1, "{base:?}: second tick");
        assert!(!t.at(8 * b - 1, true, false).q);
        let o = t.at(8 * b, true, false);
        assert_eq!(
            (o.q, o.bi),
            (true, 0),
            "{base:?}: the third tick runs it out"
        );
    }
}

/// A 1 s base run to expiry: S5T#2M7S = W#16#2127 (Fig. 9-1), 127 ticks of 1 s.
#[test]
fn one_second_base_lad_fig_9_1_runs_to_expiry() {
    let mut t = Both::new(S5Kind::SPulse, "W#16#2127");
    let o = t.at(0, true, false);
    assert_eq!((o.q, o.bi, o.bcd), (true, 127, 0x2127));
    assert_eq!(t.at(100_000, true, false).bcd, 0x2027);
    assert!(t.at(126_999, true, false).q);
    assert!(!t.at(127_000, true, false).q);
}

/// A 10 s base run to expiry: the maximum, 999 ticks of 10 s (S5T#2H46M30S).
#[test]
fn ten_second_base_runs_to_expiry_at_9990_s() {
    let mut t = Both::new(S5Kind::SOdts, "S5T#2H46M30S");
    assert_eq!(t.at(0, true, false).bcd, 0x3999);
    assert_eq!(t.at(9_989_999, false, false).bi, 1);
    assert!(t.at(9_990_000, false, false).q);
}

/// Decision S5TMR-FR-01: a rising FR restarts a running S_PEXT with S held at 1, as a new S edge
/// would; without FR, S held does nothing.
#[test]
fn fr_enable_restarts_without_s_edge() {
    let mut t = Both::new(S5Kind::SPext, "S5T#50MS");
    t.at(0, true, false);
    assert_eq!(t.at(30, true, false).bi, 2);
    assert_eq!(t.with_fr(31, true, false, true).bi, 5, "FR edge: reloaded");
    assert_eq!(
        t.with_fr(35, true, false, true).bi,
        5,
        "FR held: no second edge"
    );
}

/// S5TMR-FR-01 and SP-Q-01 (STL manual, FR: "an enable restarts a running timer if the start
/// operation is processed with RLO = 1"): a rising FR with S held restarts a running S_PULSE
/// with its full value, as it does every other kind.
#[test]
fn fr_restarts_a_running_s_pulse() {
    let mut t = Both::new(S5Kind::SPulse, "S5T#50MS");
    t.at(0, true, false);
    let o = t.at(30, true, false);
    assert_eq!((o.q, o.bi), (true, 2));
    let o = t.with_fr(31, true, false, true);
    assert_eq!((o.q, o.bi), (true, 5), "FR edge, S = 1: restarted with TV");
    assert!(
        t.at(79, true, false).q,
        "the restarted pulse runs its full time"
    );
    assert!(!t.at(80, true, false).q);
}

/// S5TMR-FR-01: FR only clears the start edge memory. An S_OFFDT whose off-delay has run out
/// with S = 0 is not restarted by an FR edge (it starts on a falling S, which a cleared memory
/// cannot give); with S = 1 FR changes nothing visible either.
#[test]
fn fr_does_not_restart_an_expired_s_offdt() {
    let mut t = Both::new(S5Kind::SOffdt, "S5T#20MS");
    t.at(0, true, false);
    t.at(5, false, false);
    assert!(!t.at(20, false, false).q, "the off-delay has run out");
    let o = t.with_fr(30, false, false, true);
    assert_eq!(
        (o.q, o.bi),
        (false, 0),
        "FR edge with S = 0: nothing starts"
    );
    assert!(!t.at(100, false, false).q);
    let o = t.with_fr(110, true, false, false);
    assert!(o.q, "a rising S sets Q");
    t.with_fr(120, true, false, false);
    let o = t.with_fr(130, true, false, true);
    assert_eq!(
        (o.q, o.bi),
        (true, 0),
        "FR edge with S = 1: Q stays, nothing runs"
    );
    assert_eq!(
        t.at(140, false, false).bi,
        2,
        "the next falling S starts it"
    );
}

/// SD-Q-01 with S5TMR-FR-01: an FR edge with S held restarts an S_ODT that has run out; Q = 0
/// again until the new time runs out (§9.5: Q = 1 only when the time has run out).
#[test]
fn fr_restarts_an_expired_s_odt_with_q_0() {
    let mut t = Both::new(S5Kind::SOdt, "S5T#20MS");
    t.at(0, true, false);
    assert!(t.at(20, true, false).q);
    let o = t.with_fr(25, true, false, true);
    assert_eq!((o.q, o.bi), (false, 2), "restarted: running, Q = 0");
    assert!(t.at(40, true, false).q);
}

/// STL operations on the area (`L T`, `LC T`, `A T`) and R clearing value and base for L/LC.
#[test]
fn stl_operations_load_and_status() {
    let mut area = TimerMemory::<256>::new();
    let tv: S5Time = "W#16#2127".parse().expect("valid");
    area.start(7, S5Kind::SOdt, true, tv).expect("T 7");
    area.advance_to(CpuTime::from_millis(3_000));
    assert_eq!(area.load(7), Ok(124));
    assert_eq!(area.load_bcd(7), Ok(0x2124));
    assert_eq!(area.status(7), Ok(false));
    area.reset(7, true).expect("T 7");
    assert_eq!(
        (area.load(7), area.load_bcd(7)),
        (Ok(0), Ok(0)),
        "S5TMR-LOAD-01"
    );
    let err = area
        .load(256)
        .expect_err("T 256 does not exist in a 256-timer area");
    assert_eq!(
        err.to_string(),
        "no timer T 256: this area has T 0 to T 255",
        "the error names the timer and the valid range"
    );
    assert_eq!(area.fr(256, true), Err(err));
}

/// The LAD box names of LAD manual §9.3-9.7 (the international mnemonic set, Fig. 9-4 ff.) and
/// the STL operations that start the same timers, in the manual's order.
#[test]
fn kind_names_lad_9_3_to_9_7() {
    let names = S5Kind::ALL.map(|k| (k.name(), k.stl()));
    assert_eq!(
        names,
        [
            ("S_PULSE", "SP"),
            ("S_PEXT", "SE"),
            ("S_ODT", "SD"),
            ("S_ODTS", "SS"),
            ("S_OFFDT", "SF"),
        ]
    );
}

/// LAD manual §9.1: the time value is three BCD digits, 0 to 999; a state outside that range is
/// not a timer state, and every type that holds a timer refuses it.
#[test]
fn state_validity_lad_9_1_value_0_to_999() {
    let at = |value| S5State {
        value,
        ..S5State::RESET
    };
    assert!(at(0).is_valid() && at(999).is_valid());
    assert!(!at(1000).is_valid() && !at(u16::MAX).is_valid());
    assert!(TimerWord::from_state(at(999)).is_some());
    assert!(TimerWord::from_state(at(1000)).is_none());
    assert!(S5TimerRef::from_state(at(1000), CpuTime::ZERO).is_none());
    assert!(S5Timer::from_state(at(1000), CpuTime::ZERO).is_none());
    let mut area = TimerMemory::<1>::new();
    assert_eq!(area.set_state(0, at(1000)), Ok(false));
    assert_eq!(area.get(0), Ok(S5State::RESET), "refused: unchanged");
}

/// The input builders set the one input they name and keep the others (the command-line tool
/// and the bindings build every row's inputs through them).
#[test]
fn input_builders_set_one_input() {
    let tv = S5Time::new(7, TimeBase::Ms100).expect("7 x 100 ms");
    let base = S5Input::new(true, false, tv);
    for bits in 0..4u8 {
        let (r, fr) = (bits & 1 != 0, bits & 2 != 0);
        let i = base.with_r(r).with_fr(fr);
        assert_eq!((i.s, i.r, i.fr, i.tv), (true, r, fr, tv), "{bits:02b}");
        let back = i.with_r(!r).with_fr(!fr);
        assert_eq!((back.r, back.fr), (!r, !fr), "builders overwrite");
    }
}

/// S5TMR-CLOCK-01 (issue 37): an S_ODT of S5T#1S (100 ticks of 10 ms, LAD manual §9.5) started
/// at 0 ms and executed at 600, 100 (the clock goes back) and 600 ms again runs out at the
/// 100th tick after its start, at 1000 ms, in every form: the 500 ms it went back are neither
/// counted on the way back nor a second time on the way forward.
#[test]
fn clock_going_back_counts_no_span_twice() {
    let mut sd = Both::new(S5Kind::SOdt, "S5T#1S");
    assert!(!sd.at(0, true, false).q);
    assert_eq!(
        sd.at(600, true, false).bi,
        40,
        "S5TMR-CLOCK-01: 60 ticks taken"
    );
    assert_eq!(
        sd.at(100, true, false).bi,
        40,
        "S5TMR-CLOCK-01: no tick back"
    );
    let again = sd.at(600, true, false);
    assert!(!again.q, "S5TMR-CLOCK-01: 400 ms before the end");
    assert_eq!(
        again.bi, 40,
        "S5TMR-CLOCK-01: the span is not counted twice"
    );
    assert!(!sd.at(990, true, false).q, "S5TMR-CLOCK-01: one tick left");
    assert!(sd.at(1000, true, false).q, "S5TMR-CLOCK-01: the 100th tick");
    assert_eq!(sd.reference.last_call(), CpuTime::from_millis(1000));
}
