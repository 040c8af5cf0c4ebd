//! Counter scenarios (Strączyński lecture; TIA Portal help on CTUD and S_CU): saturation at
//! both ends for every type, priorities, the simultaneous-edge case, the R-released-with-CU-held
//! case, and the S5 counters with their STL operations. Reference and optimized implementations
//! run side by side; the assertions are the source's sentence.

use plc_timers::counter::s5::{
    CounterMemory, CounterPreset, CounterPresetError, S5Counter, S5CounterInput, S5CounterKind,
    S5CounterOps, S5CounterOutput, S5CounterRef, S5CounterState,
};
use plc_timers::counter::{
    Counter, CounterInput, CounterInt, CounterKind, CounterOps, CounterOutput, CounterRef,
};

struct Both<T: CounterInt> {
    kind: CounterKind,
    reference: CounterRef<T>,
    optimized: Counter<T>,
}

impl<T: CounterInt> Both<T> {
    fn new(kind: CounterKind) -> Both<T> {
        Both {
            kind,
            reference: CounterRef::new(),
            optimized: Counter::new(),
        }
    }

    fn call(&mut self, cu: bool, cd: bool, r: bool, ld: bool, pv: T) -> CounterOutput<T> {
        let input = CounterInput { cu, cd, r, ld, pv };
        let a = self.reference.call(self.kind, input);
        assert_eq!(a, self.optimized.call(self.kind, input));
        assert_eq!(self.reference.state(), self.optimized.state());
        a
    }

    fn pulses_up(&mut self, n: usize, pv: T) -> CounterOutput<T> {
        let mut last = self.call(false, false, false, false, pv);
        for _ in 0..n {
            last = self.call(true, false, false, false, pv);
            self.call(false, false, false, false, pv);
        }
        last
    }

    fn pulses_down(&mut self, n: usize, pv: T) -> CounterOutput<T> {
        let mut last = self.call(false, false, false, false, pv);
        for _ in 0..n {
            last = self.call(false, true, false, false, pv);
            self.call(false, false, false, false, pv);
        }
        last
    }
}

/// CNT-SAT-01 for one type: CTUD loaded with MAX stays at MAX on a count up; loaded with MIN
/// stays at MIN on a count down (never wraps, never panics).
fn saturation<T: CounterInt>() {
    let mut c = Both::<T>::new(CounterKind::Ctud);
    assert_eq!(c.call(false, false, false, true, T::MAX).cv, T::MAX);
    assert_eq!(c.pulses_up(3, T::MAX).cv, T::MAX, "{}: up at MAX", T::NAME);
    assert_eq!(c.pulses_down(1, T::MAX).cv.to_i128(), T::MAX.to_i128() - 1);
    assert_eq!(c.call(false, false, false, true, T::MIN).cv, T::MIN);
    assert_eq!(
        c.pulses_down(3, T::MIN).cv,
        T::MIN,
        "{}: down at MIN",
        T::NAME
    );
    assert_eq!(c.pulses_up(1, T::MIN).cv.to_i128(), T::MIN.to_i128() + 1);
}

#[test]
fn saturation_at_both_ends_for_every_type() {
    saturation::<i8>();
    saturation::<i16>();
    saturation::<i32>();
    saturation::<i64>();
    saturation::<u8>();
    saturation::<u16>();
    saturation::<u32>();
    saturation::<u64>();
}

/// Strączyński lecture, CTU: "if CU changes from 0 to 1, CTU counts up by 1; Q = 1 if CV >= PV" (the
/// lecture's diagram uses PV = 3). Counting goes on past PV (matiec stops at PV; this does not).
#[test]
fn ctu_lecture_counts_past_pv() {
    let mut c = Both::<u16>::new(CounterKind::Ctu);
    assert!(!c.pulses_up(2, 3).qu);
    assert!(c.pulses_up(1, 3).qu);
    assert_eq!(c.pulses_up(2, 3).cv, 5);
}

/// Strączyński lecture, CTD: "if LOAD changes from 0 to 1, PV is written to CV"; counting down to and past
/// 0; Q = CV <= 0.
#[test]
fn ctd_lecture_load_and_count_down() {
    let mut c = Both::<i16>::new(CounterKind::Ctd);
    assert_eq!(c.call(false, false, false, true, 2).cv, 2);
    assert!(!c.pulses_down(1, 2).qd);
    assert!(c.pulses_down(1, 2).qd);
    assert_eq!(c.pulses_down(1, 2).cv, -1);
}

/// CNT-PRIO-01: R over LD over counting, R and LD as levels.
#[test]
fn ctud_priorities_r_over_ld_over_count() {
    let mut c = Both::<i32>::new(CounterKind::Ctud);
    assert_eq!(c.call(true, false, true, true, 7).cv, 0, "R and LD: R wins");
    assert_eq!(c.call(false, false, false, true, 7).cv, 7, "LD alone");
    assert_eq!(
        c.call(true, false, false, true, 7).cv,
        7,
        "LD holds against a rising CU"
    );
    assert_eq!(c.call(false, false, true, false, 7).cv, 0, "R as a level");
}

/// CNT-SIMUL-01: rising CU and CD in the same call leave CV unchanged.
#[test]
fn ctud_simultaneous_edges_cancel() {
    let mut c = Both::<i16>::new(CounterKind::Ctud);
    c.pulses_up(2, 10);
    assert_eq!(c.call(true, true, false, false, 10).cv, 2);
}

/// CNT-EDGE-01: the edge memory is updated while R holds, so releasing R with CU held does not
/// count (RuSTy's CTUD counts here; this does not).
#[test]
fn r_released_with_cu_held_does_not_count() {
    for kind in [CounterKind::Ctu, CounterKind::Ctud] {
        let mut c = Both::<i16>::new(kind);
        c.call(false, false, true, false, 5);
        c.call(true, false, true, false, 5);
        assert_eq!(c.call(true, false, false, false, 5).cv, 0, "{kind:?}");
        c.call(false, false, false, false, 5);
        assert_eq!(
            c.call(true, false, false, false, 5).cv,
            1,
            "{kind:?}: a new edge counts"
        );
    }
}

/// CNT-INPUTS-01: CTU ignores CD and LD; CTD ignores CU and R.
#[test]
fn absent_inputs_are_ignored() {
    let mut ctu = Both::<i16>::new(CounterKind::Ctu);
    assert_eq!(ctu.call(false, true, false, true, 9).cv, 0);
    let mut ctd = Both::<i16>::new(CounterKind::Ctd);
    assert_eq!(ctd.call(true, false, true, false, 9).cv, 0);
}

/// The input builders set the one input they name and keep the others (the command-line tool
/// and the bindings build every row's inputs through them).
#[test]
fn input_builders_set_one_input() {
    let base = CounterInput::new(true, true, 7i16);
    for (r, ld) in [(false, false), (true, false), (false, true), (true, true)] {
        let i = base.with_r(r).with_ld(ld);
        assert_eq!(
            (i.cu, i.cd, i.r, i.ld, i.pv),
            (true, true, r, ld, 7),
            "with_r({r}).with_ld({ld})"
        );
        let back = i.with_r(!r).with_ld(!ld);
        assert_eq!((back.r, back.ld), (!r, !ld), "builders overwrite");
    }
    let pv = CounterPreset::new(7).expect("0..=999");
    let base = S5CounterInput::new(true, true, pv);
    for bits in 0..8u8 {
        let (s, r, fr) = (bits & 1 != 0, bits & 2 != 0, bits & 4 != 0);
        let i = base.with_s(s).with_r(r).with_fr(fr);
        assert_eq!(
            (i.cu, i.cd, i.s, i.r, i.fr, i.pv),
            (true, true, s, r, fr, pv),
            "S5 {bits:03b}"
        );
        let back = i.with_s(!s).with_r(!r).with_fr(!fr);
        assert_eq!(
            (back.s, back.r, back.fr),
            (!s, !r, !fr),
            "S5 builders overwrite"
        );
    }
}

/// QD = CV <= 0 for unsigned types means CV = 0.
#[test]
fn unsigned_qd_at_zero() {
    let mut c = Both::<u8>::new(CounterKind::Ctud);
    assert!(c.call(false, false, false, false, 1).qd);
    assert!(!c.pulses_up(1, 1).qd);
}

/// S5 counters: CV saturates at 999 and 0; S (rising) loads the BCD preset; R resets; Q = CV != 0.
#[test]
fn s5_counters_saturate_and_set() {
    let pv = "C#998".parse::<CounterPreset>().expect("valid");
    let mut c = S5Both::new(S5CounterKind::SCud);
    let mut both = |cu, cd, s, r| {
        c.call(S5CounterInput {
            cu,
            cd,
            s,
            r,
            fr: false,
            pv,
        })
    };
    assert_eq!(both(false, false, true, false).cv, 998);
    both(true, false, true, false);
    both(false, false, false, false);
    let o = both(true, false, false, false);
    assert_eq!(
        (o.q, o.cv, o.cv_bcd),
        (true, 999, 0x0999),
        "SC-SAT-01: stays at 999"
    );
    assert_eq!(both(false, false, false, true).cv, 0);
    assert!(
        !both(false, true, false, false).q,
        "SC-SAT-01: stays at 0, Q = 0"
    );
}

/// STL operations on the counter area: CU, CD, S, R, L C, LC C, A C, and a bad counter number.
#[test]
fn s5_counter_stl_operations() {
    let mut area = CounterMemory::<256>::new();
    let pv = CounterPreset::from_bcd(0x0125).expect("BCD 125");
    area.set(5, true, pv).expect("C 5");
    area.cu(5, true).expect("C 5");
    assert_eq!(
        (area.load(5), area.load_bcd(5), area.status(5)),
        (Ok(126), Ok(0x0126), Ok(true))
    );
    area.cd(5, true).expect("C 5");
    area.cd(5, true).expect("C 5");
    assert_eq!(area.load(5), Ok(125), "CD held: one count");
    area.reset(5, true).expect("C 5");
    assert_eq!(area.status(5), Ok(false));
    assert!(area.cu(256, true).is_err());
}

/// SC-BCD-01: C# presets and BCD words, with the BCD check.
#[test]
fn s5_counter_presets() {
    assert_eq!(
        "C#999".parse::<CounterPreset>().map(CounterPreset::value),
        Ok(999)
    );
    assert_eq!(
        "c#0".parse::<CounterPreset>().map(CounterPreset::value),
        Ok(0)
    );
    assert_eq!(
        "W#16#0999"
            .parse::<CounterPreset>()
            .map(CounterPreset::value),
        Ok(999)
    );
    for bad in [
        "C#1000",
        "C#",
        "C#-1",
        "C#1.5",
        "W#16#0A00",
        "W#16#1000",
        "X#5",
        "",
        "C#99999999999",
    ] {
        assert!(bad.parse::<CounterPreset>().is_err(), "{bad}");
    }
    // One to four hex digits after W#16#; the kind of each error.
    assert_eq!(
        "W#16#999"
            .parse::<CounterPreset>()
            .map(CounterPreset::value),
        Ok(999)
    );
    for (bad, kind) in [
        ("W#16#00999", CounterPresetError::Syntax),
        ("W#16#", CounterPresetError::Syntax),
        ("C#", CounterPresetError::Syntax),
        ("C#1.5", CounterPresetError::Syntax),
        ("C#1000", CounterPresetError::OutOfRange(1000)),
        ("W#16#0A00", CounterPresetError::BcdDigit(0x0A00)),
    ] {
        assert_eq!(bad.parse::<CounterPreset>(), Err(kind), "{bad}");
    }
    // The errors say what was wrong and what is allowed.
    let message = |text: &str| {
        text.parse::<CounterPreset>()
            .expect_err("rejected")
            .to_string()
    };
    assert_eq!(
        message("C#1000"),
        "1000 is above the S5 counter maximum of 999"
    );
    assert_eq!(
        message("W#16#0A00"),
        "W#16#0A00 is not a BCD count: every digit must be 0-9 and the value at most 999"
    );
    assert_eq!(
        message("X#5"),
        "not a counter preset; write C#0 to C#999, 0 to 999, or W#16#0000 to W#16#0999"
    );
}

/// The instruction names of the Strączyński lecture (CTU, CTD, CTUD) and the S5 counter boxes of
/// S7-300/400 (S_CU, S_CD, S_CUD; TIA Portal help), in that order.
#[test]
fn kind_names_lecture() {
    assert_eq!(
        CounterKind::ALL.map(CounterKind::name),
        ["CTU", "CTD", "CTUD"]
    );
    assert_eq!(
        S5CounterKind::ALL.map(S5CounterKind::name),
        ["S_CU", "S_CD", "S_CUD"]
    );
}

/// SC-RANGE-01: CV is 0..=999; a state outside is not a counter state, and every type that holds
/// a counter refuses it. A counter number outside the area is an error that names the valid range.
#[test]
fn s5_counter_state_range_and_numbers() {
    let at = |cv| S5CounterState {
        cv,
        ..S5CounterState::default()
    };
    assert!(at(0).is_valid() && at(999).is_valid());
    assert!(!at(1000).is_valid());
    assert!(S5Counter::from_state(at(999)).is_some());
    assert!(S5Counter::from_state(at(1000)).is_none());
    assert!(S5CounterRef::from_state(at(1000)).is_none());
    assert!(
        S5Counter::from_bits(0x0400).is_none(),
        "bit 10 is not a field"
    );
    let mut area = CounterMemory::<4>::new();
    let err = area
        .cu(4, true)
        .expect_err("C 4 does not exist in a 4-counter area");
    assert_eq!(err.to_string(), "no counter C 4: this area has C 0 to C 3");
}

/// The three forms of an S5 counter driven together: the reference, the lone word, and the box
/// on a counter memory area; and a second area driven by the box's STL sequence (`FR`, `CU`,
/// `CD`, `S`, `R` for the inputs the box has), which must give the same word.
struct S5Both {
    kind: S5CounterKind,
    reference: S5CounterRef,
    word: S5Counter,
    area: CounterMemory<3>,
    stl: CounterMemory<3>,
}

impl S5Both {
    fn new(kind: S5CounterKind) -> S5Both {
        S5Both {
            kind,
            reference: S5CounterRef::new(),
            word: S5Counter::new(),
            area: CounterMemory::new(),
            stl: CounterMemory::new(),
        }
    }

    fn call(&mut self, input: S5CounterInput) -> S5CounterOutput {
        let a = self.reference.call(self.kind, input);
        assert_eq!(self.word.call(self.kind, input), a, "word");
        assert_eq!(self.area.call(2, self.kind, input), Ok(a), "area box");
        let stl = &mut self.stl;
        stl.fr(2, input.fr).expect("C 2");
        if self.kind.counts_up() {
            stl.cu(2, input.cu).expect("C 2");
        }
        if self.kind.counts_down() {
            stl.cd(2, input.cd).expect("C 2");
        }
        stl.set(2, input.s, input.pv).expect("C 2");
        stl.reset(2, input.r).expect("C 2");
        assert_eq!(stl.get(2), Ok(self.reference.state()), "STL sequence");
        assert_eq!(self.word.state(), self.reference.state(), "states");
        a
    }

    fn state(&self) -> S5CounterState {
        self.reference.state()
    }
}

fn s5_input(cu: bool, cd: bool, pv: u16) -> S5CounterInput {
    S5CounterInput {
        cu,
        cd,
        pv: CounterPreset::new(pv).expect("0..=999"),
        ..S5CounterInput::default()
    }
}

/// SC-SIMUL-01 (LAD manual, S_CUD: "if both count inputs have a rising edge, both operations are
/// executed"): the box counts up, then down, each saturating, as its STL sequence does. CV is
/// unchanged in the middle; 999 becomes 998 (the count up saturates); 0 stays 0.
#[test]
fn s_cud_both_edges_execute_both_operations() {
    for (start, expected) in [(0, 0), (1, 1), (500, 500), (998, 998), (999, 998)] {
        let mut c = S5Both::new(S5CounterKind::SCud);
        let set = S5CounterInput {
            s: true,
            ..s5_input(false, false, start)
        };
        c.call(set);
        c.call(s5_input(false, false, start));
        assert_eq!(
            c.call(s5_input(true, true, start)).cv,
            expected,
            "from {start}"
        );
    }
}

/// SC-SET-01 (TIA Portal help, S_CU: "if the counter is set while CU is 1, it counts once in the
/// next cycle"): setting clears the count edge memories.
#[test]
fn setting_with_cu_held_counts_once_next_call() {
    let mut c = S5Both::new(S5CounterKind::SCu);
    c.call(s5_input(true, false, 5));
    assert_eq!(c.state().cv, 1);
    let set = S5CounterInput {
        s: true,
        ..s5_input(true, false, 5)
    };
    assert_eq!(
        c.call(set).cv,
        5,
        "the set overrides the count (SC-PRIO-01)"
    );
    let held = S5CounterInput {
        s: true,
        ..s5_input(true, false, 5)
    };
    assert_eq!(c.call(held).cv, 6, "CU held through the set counts once");
    assert_eq!(c.call(held).cv, 6, "and only once");
}

/// SC-FR-01 (STL manual, FR C n): a rising FR clears the edge memories of CU, CD and S, so an
/// input held at 1 acts once more; FR held at 1 does nothing further.
#[test]
fn fr_lets_held_inputs_act_again() {
    let mut c = S5Both::new(S5CounterKind::SCud);
    let held_cu = s5_input(true, false, 7);
    c.call(held_cu);
    assert_eq!(c.call(held_cu).cv, 1, "CU held: one count");
    let fr = S5CounterInput {
        fr: true,
        ..held_cu
    };
    assert_eq!(c.call(fr).cv, 2, "FR edge: the held CU counts again");
    assert_eq!(c.call(fr).cv, 2, "FR held: no further count");
    let set_fr = S5CounterInput { s: true, ..fr };
    assert_eq!(
        c.call(set_fr).cv,
        7,
        "S rising: the set wins over the count"
    );
    assert_eq!(
        c.call(held_cu).cv,
        8,
        "the set cleared CU's memory (SC-SET-01)"
    );
    assert_eq!(c.call(held_cu).cv, 8);
    assert_eq!(c.call(fr).cv, 9, "a new FR edge: CU once more");
}

/// SC-INPUTS-01: S_CU has no CD input, so its box leaves the CD edge memory alone (an STL `CD`
/// on the same counter still sees its own memory); likewise S_CD and CU.
#[test]
fn a_box_without_an_input_leaves_its_memory() {
    let mut area = CounterMemory::<1>::new();
    area.cd(0, true).expect("C 0");
    let box_input = s5_input(false, false, 0);
    area.call(0, S5CounterKind::SCu, box_input).expect("C 0");
    assert!(
        area.get(0).expect("C 0").cd_prev,
        "S_CU did not touch CD's memory"
    );
    area.call(0, S5CounterKind::SCd, box_input).expect("C 0");
    assert!(!area.get(0).expect("C 0").cd_prev, "S_CD did");
}
