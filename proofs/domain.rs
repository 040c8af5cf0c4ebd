//! The small-scope domains the drivers of several modules share (the counters' rule and
//! equivalence drivers in `counter.rs`, their explanation drivers in `explain.rs`), each written
//! once, and the S5 timers' inputs (their drivers in `s5.rs`, `explain.rs`, `decisions.rs`): a
//! state is its data word(s) times every combination of its edge memories, an input every
//! combination of its boolean inputs with the preset.

use plc_timers::counter::s5::{CounterPreset, S5CounterInput, S5CounterState};
use plc_timers::counter::{CounterInput, CounterInt, CounterState};
use plc_timers::s5::S5Input;
use plc_timers::time::S5Time;

/// The 8 S5 timer inputs with the time value `tv`: every combination of S, R and FR.
pub fn s5_timer_inputs(tv: S5Time) -> [S5Input; 8] {
    core::array::from_fn(|bits| S5Input {
        s: bits & 1 != 0,
        r: bits & 2 != 0,
        fr: bits & 4 != 0,
        tv,
    })
}

/// Every IEC counter state with CV in `cvs`: each CV with the 4 combinations of the CU and CD
/// edge memories.
pub fn counter_states<T: CounterInt>(
    cvs: impl Iterator<Item = T> + Clone,
) -> impl Iterator<Item = CounterState<T>> + Clone {
    cvs.flat_map(|cv| {
        (0..4u8).map(move |e| CounterState {
            cv,
            cu_prev: e & 1 != 0,
            cd_prev: e & 2 != 0,
        })
    })
}

/// The 16 IEC counter inputs with PV `pv`: every combination of CU, CD, R and LD.
pub fn counter_inputs<T: CounterInt>(pv: T) -> [CounterInput<T>; 16] {
    core::array::from_fn(|bits| CounterInput {
        cu: bits & 1 != 0,
        cd: bits & 2 != 0,
        r: bits & 4 != 0,
        ld: bits & 8 != 0,
        pv,
    })
}

/// Every S5 counter state with CV in `cvs`: each CV with the 16 combinations of the CU, CD, S
/// and FR edge memories.
pub fn s5_counter_states(
    cvs: impl Iterator<Item = u16> + Clone,
) -> impl Iterator<Item = S5CounterState> + Clone {
    cvs.flat_map(|cv| {
        (0..16u8).map(move |e| S5CounterState {
            cv,
            cu_prev: e & 1 != 0,
            cd_prev: e & 2 != 0,
            s_prev: e & 4 != 0,
            fr_prev: e & 8 != 0,
        })
    })
}

/// The 32 S5 counter inputs with the preset `pv`: every combination of CU, CD, S, R and FR.
pub fn s5_counter_inputs(pv: CounterPreset) -> [S5CounterInput; 32] {
    core::array::from_fn(|bits| S5CounterInput {
        cu: bits & 1 != 0,
        cd: bits & 2 != 0,
        s: bits & 4 != 0,
        r: bits & 8 != 0,
        fr: bits & 16 != 0,
        pv,
    })
}
