//! The S5 counters of S7-300/400: `S_CU`, `S_CD`, `S_CUD` (STL `CU`/`CD`/`S`/`R`/`FR`/`L C`/`LC C`,
//! German `ZV`/`ZR`/`S`/`R`/`FR`/`L Z`/`LC Z`), the same family as the S5 timers.
//!
//! CV is 0..=999 and saturates at both ends; the preset is `C#0`..`C#999`, loaded as three BCD
//! digits ([`CounterPreset`]); Q = CV != 0. One interface, [`S5CounterOps`], two
//! implementations:
//! - [`S5CounterRef`]: the rules one by one;
//! - [`S5Counter`]: a counter packed in one 16-bit word;
//!
//! and [`CounterMemory`], a counter memory area with the STL operations.
//!
//! ```
//! use plc_timers::counter::s5::{
//!     CounterPreset, S5Counter, S5CounterInput, S5CounterKind, S5CounterOps, S5CounterRef,
//! };
//!
//! let pv = CounterPreset::parse("C#998")?;
//! let set = S5CounterInput { s: true, pv, ..S5CounterInput::default() };
//! let up = S5CounterInput { cu: true, pv, ..S5CounterInput::default() };
//! let mut reference = S5CounterRef::new();
//! let mut optimized = S5Counter::new();
//! for c in [&mut reference as &mut dyn S5CounterOps, &mut optimized] {
//!     assert_eq!(c.call(S5CounterKind::SCu, set).cv, 998); // a rising S loads PV
//!     assert_eq!(c.call(S5CounterKind::SCu, up).cv, 999);
//!     c.call(S5CounterKind::SCu, S5CounterInput::default());
//!     assert_eq!(c.call(S5CounterKind::SCu, up).cv, 999); // saturates, never wraps
//! }
//! # Ok::<(), plc_timers::counter::s5::CounterPresetError>(())
//! ```

pub mod memory;
pub mod preset;
pub mod reference;
pub mod word;

pub use memory::CounterMemory;
pub use preset::{CounterPreset, CounterPresetError};
pub use reference::S5CounterRef;
pub use word::S5Counter;

use crate::time::bcd3_encode;

/// Which S5 counter box.
///
/// ```
/// use plc_timers::counter::s5::S5CounterKind;
/// assert!(S5CounterKind::SCud.counts_up() && S5CounterKind::SCud.counts_down());
/// assert!(!S5CounterKind::SCu.counts_down());
/// ```
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
#[cfg_attr(kani, derive(kani::Arbitrary))]
#[cfg_attr(feature = "bolero", derive(bolero_generator::TypeGenerator))]
pub enum S5CounterKind {
    /// `S_CU` (German `Z_VORW`): up counter (no CD input).
    #[doc(alias = "Z_VORW")]
    SCu,
    /// `S_CD` (German `Z_RUECK`): down counter (no CU input).
    #[doc(alias = "Z_RUECK")]
    SCd,
    /// `S_CUD` (German `ZAEHLER`): up-down counter.
    #[doc(alias = "ZAEHLER")]
    SCud,
}

impl S5CounterKind {
    /// All three.
    pub const ALL: [S5CounterKind; 3] =
        [S5CounterKind::SCu, S5CounterKind::SCd, S5CounterKind::SCud];

    /// The box name.
    pub const fn name(self) -> &'static str {
        match self {
            S5CounterKind::SCu => "S_CU",
            S5CounterKind::SCd => "S_CD",
            S5CounterKind::SCud => "S_CUD",
        }
    }

    /// Whether the box has the CU input (S_CU and S_CUD; SC-INPUTS-01).
    pub const fn counts_up(self) -> bool {
        !matches!(self, S5CounterKind::SCd)
    }

    /// Whether the box has the CD input (S_CD and S_CUD; SC-INPUTS-01).
    pub const fn counts_down(self) -> bool {
        !matches!(self, S5CounterKind::SCu)
    }
}

/// The largest counter value.
pub const CV_MAX: u16 = 999;

/// The inputs of one S5 counter box call.
///
/// ```
/// use plc_timers::counter::s5::{CounterPreset, S5CounterInput};
/// let set = S5CounterInput::new(false, false, CounterPreset::new(20)?).with_s(true);
/// assert!(set.s && !set.cu && !set.fr);
/// assert_eq!(S5CounterInput::default(), S5CounterInput::new(false, false, CounterPreset::default()));
/// # Ok::<(), plc_timers::counter::s5::CounterPresetError>(())
/// ```
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
#[cfg_attr(feature = "bolero", derive(bolero_generator::TypeGenerator))]
pub struct S5CounterInput {
    /// `CU` (`ZV`), count up on a rising edge.
    pub cu: bool,
    /// `CD` (`ZR`), count down on a rising edge.
    pub cd: bool,
    /// `S`, set CV to PV on a rising edge.
    pub s: bool,
    /// `R`, reset CV to 0 (level).
    pub r: bool,
    /// `FR`, the enable (STL `FR C n`; the LAD boxes have none: false there): a rising edge
    /// clears the edge memories of CU, CD and S.
    pub fr: bool,
    /// `PV`.
    pub pv: CounterPreset,
}

impl S5CounterInput {
    /// `CU`, `CD` and `PV`, with `S` = `R` = `FR` = 0.
    pub const fn new(cu: bool, cd: bool, pv: CounterPreset) -> S5CounterInput {
        S5CounterInput {
            cu,
            cd,
            s: false,
            r: false,
            fr: false,
            pv,
        }
    }

    /// These inputs with `S` = `s`.
    #[must_use]
    pub const fn with_s(self, s: bool) -> S5CounterInput {
        S5CounterInput { s, ..self }
    }

    /// These inputs with `R` = `r`.
    #[must_use]
    pub const fn with_r(self, r: bool) -> S5CounterInput {
        S5CounterInput { r, ..self }
    }

    /// These inputs with `FR` = `fr`.
    #[must_use]
    pub const fn with_fr(self, fr: bool) -> S5CounterInput {
        S5CounterInput { fr, ..self }
    }
}

/// The outputs of one S5 counter box call.
///
/// ```
/// use plc_timers::counter::s5::S5CounterState;
/// let out = S5CounterState { cv: 120, ..Default::default() }.output();
/// assert_eq!((out.q, out.cv, out.cv_bcd), (true, 120, 0x0120));
/// ```
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct S5CounterOutput {
    /// `Q`: CV != 0.
    pub q: bool,
    /// `CV` (`DUAL`), binary.
    pub cv: u16,
    /// `CV_BCD` (`DEZ`), three BCD digits.
    pub cv_bcd: u16,
}

/// The state of an S5 counter as the reference names it.
///
/// A plain description: [`S5CounterState::is_valid`] says whether a counter can be in it; the
/// types that hold a counter take a state only through their checking `from_state`.
///
/// ```
/// use plc_timers::counter::s5::S5CounterState;
/// assert!(S5CounterState { cv: 999, ..Default::default() }.is_valid());
/// assert!(!S5CounterState { cv: 1000, ..Default::default() }.is_valid());
/// ```
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash)]
pub struct S5CounterState {
    /// `CV`, 0..=999.
    pub cv: u16,
    /// Edge memory of CU.
    pub cu_prev: bool,
    /// Edge memory of CD.
    pub cd_prev: bool,
    /// Edge memory of S.
    pub s_prev: bool,
    /// Edge memory of FR.
    pub fr_prev: bool,
}

/// Any valid state: CV 0..=999, any edge memories (feature `bolero`).
#[cfg(feature = "bolero")]
impl bolero_generator::TypeGenerator for S5CounterState {
    fn generate<D: bolero_generator::Driver>(driver: &mut D) -> Option<S5CounterState> {
        use bolero_generator::ValueGenerator;
        Some(S5CounterState {
            cv: (0u16..=CV_MAX).generate(driver)?,
            cu_prev: driver.produce()?,
            cd_prev: driver.produce()?,
            s_prev: driver.produce()?,
            fr_prev: driver.produce()?,
        })
    }
}

/// Any preset 0..=999 (feature `bolero`).
#[cfg(feature = "bolero")]
impl bolero_generator::TypeGenerator for CounterPreset {
    fn generate<D: bolero_generator::Driver>(driver: &mut D) -> Option<CounterPreset> {
        use bolero_generator::ValueGenerator;
        CounterPreset::new((0u16..=CV_MAX).generate(driver)?).ok()
    }
}

impl S5CounterState {
    /// A new counter: CV = 0, every edge memory 0.
    pub const RESET: S5CounterState = S5CounterState {
        cv: 0,
        cu_prev: false,
        cd_prev: false,
        s_prev: false,
        fr_prev: false,
    };

    /// The invariant: CV <= 999 (SC-RANGE-01).
    pub const fn is_valid(&self) -> bool {
        self.cv <= CV_MAX
    }

    /// The outputs this state shows (SC-Q-01: Q = CV != 0).
    pub const fn output(&self) -> S5CounterOutput {
        S5CounterOutput {
            q: self.cv != 0,
            cv: self.cv,
            cv_bcd: bcd3_encode(self.cv),
        }
    }
}

/// What both S5 counter implementations offer.
///
/// ```
/// use plc_timers::counter::s5::{S5Counter, S5CounterInput, S5CounterKind, S5CounterOps, S5CounterRef};
/// let down = S5CounterInput { cd: true, ..Default::default() };
/// for c in [&mut S5CounterRef::new() as &mut dyn S5CounterOps, &mut S5Counter::new()] {
///     assert_eq!(c.call(S5CounterKind::SCd, down).cv, 0); // saturates at 0
/// }
/// ```
pub trait S5CounterOps {
    /// One call of the box `kind` (the inputs it lacks are taken as 0, SC-INPUTS-01).
    fn call(&mut self, kind: S5CounterKind, input: S5CounterInput) -> S5CounterOutput;
    /// The state, as the reference names it.
    fn state(&self) -> S5CounterState;
}

/// The S5 counters as one [`Family`](crate::block::Family) of the block interface: `CU`,
/// `CD`, `S`, `R`, `FR` and `PV` in; `Q`, `CV` and `CV_BCD` out.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct S5Counters;

impl crate::block::Family for S5Counters {
    type Kind = S5CounterKind;
    type Input = S5CounterInput;
    type Output = S5CounterOutput;
    type State = S5CounterState;
    type Preset = CounterPreset;
    type PresetError = CounterPresetError;
    type Unit = crate::time::Millis;

    fn kind(block: crate::catalog::Block) -> Option<S5CounterKind> {
        match block.kind() {
            crate::catalog::Kind::S5Counter(k) => Some(k),
            _ => None,
        }
    }

    #[inline]
    fn input(signals: crate::block::Signals, pv: CounterPreset) -> S5CounterInput {
        use crate::catalog::Port;
        S5CounterInput::new(signals.get(Port::Cu), signals.get(Port::Cd), pv)
            .with_s(signals.get(Port::S))
            .with_r(signals.get(Port::R))
            .with_fr(signals.get(Port::Fr))
    }

    #[inline]
    fn values(_: S5CounterKind, o: &S5CounterOutput) -> crate::block::Outputs {
        use crate::block::{Outputs, Value};
        Outputs::three(
            Value::Bool(o.q),
            Value::Int(i128::from(o.cv)),
            Value::Word(o.cv_bcd),
        )
    }

    fn parse_preset(text: &str) -> Result<CounterPreset, CounterPresetError> {
        CounterPreset::parse(text)
    }

    fn preset_units(pv: CounterPreset) -> i128 {
        i128::from(pv.value())
    }

    fn ramp(_: &S5CounterOutput) -> Option<u64> {
        None
    }

    fn state_fields(s: &S5CounterState) -> crate::block::Fields {
        use crate::block::{Fields, Value};
        Fields::of([
            Value::Int(i128::from(s.cv)),
            Value::Bool(s.cu_prev),
            Value::Bool(s.cd_prev),
            Value::Bool(s.s_prev),
            Value::Bool(s.fr_prev),
        ])
    }

    fn state_from_fields(fields: &[crate::block::Value]) -> Option<S5CounterState> {
        let [cv, cu_prev, cd_prev, s_prev, fr_prev] = *fields else {
            return None;
        };
        Some(S5CounterState {
            cv: u16::try_from(cv.as_int()?).ok()?,
            cu_prev: cu_prev.as_bool()?,
            cd_prev: cd_prev.as_bool()?,
            s_prev: s_prev.as_bool()?,
            fr_prev: fr_prev.as_bool()?,
        })
    }
}

crate::block::block_ops! {
    impl[] S5CounterRef: S5Counters,
    call: |c, kind, _now, input| S5CounterOps::call(c, kind, input),
    state: S5CounterOps::state,
    from_state: |state, _last_call| S5CounterRef::from_state(state),
    explains: |c, kind, _now, input| c.call_explained(kind, input),
}

crate::block::block_ops! {
    impl[] S5Counter: S5Counters,
    call: |c, kind, _now, input| S5CounterOps::call(c, kind, input),
    state: S5CounterOps::state,
    from_state: |state, _last_call| S5Counter::from_state(state),
}
