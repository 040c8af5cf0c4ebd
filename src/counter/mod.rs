//! Counters: the IEC counters `CTU`, `CTD`, `CTUD` of S7-1200/1500 over every integer type
//! (Strączyński lecture; S7-1200 manual, counter instructions), and the S5 counters `S_CU`,
//! `S_CD`, `S_CUD` of S7-300/400 ([`s5`]).
//!
//! IEC counters, one interface ([`CounterOps`]) and two implementations:
//! - [`CounterRef`]: the rules one by one, as the manual states them.
//! - [`Counter`]: CV and both edge memories in one small struct,
//!
//! and [`CounterBank`], thousands of CTUD counters scanned together.
//!
//! ```
//! use plc_timers::counter::{Counter, CounterInput, CounterKind, CounterOps, CounterRef};
//!
//! let pulse = |cu| CounterInput { cu, pv: 2, ..CounterInput::default() };
//! let mut reference = CounterRef::<i16>::new();
//! let mut optimized = Counter::<i16>::new();
//! for ctu in [&mut reference as &mut dyn CounterOps<i16>, &mut optimized] {
//!     for cu in [true, false, true] {
//!         ctu.call(CounterKind::Ctu, pulse(cu));
//!     }
//!     let out = ctu.call(CounterKind::Ctu, pulse(true)); // CU held: no new edge
//!     assert_eq!((out.cv, out.qu), (2, true));
//! }
//! ```

pub mod bank;
pub mod packed;
pub mod reference;
pub mod s5;

pub use bank::{BankInputs, CounterBank};
pub use packed::{ArrayOutputs, Counter};
pub use reference::CounterRef;

use core::fmt::Debug;

/// The integer types a counter counts in: SInt, Int, DInt, LInt, USInt, UInt, UDInt, ULInt.
/// One generic implementation serves all eight.
///
/// ```
/// use plc_timers::counter::CounterInt;
/// assert_eq!(<u8 as CounterInt>::NAME, "USINT");
/// assert_eq!(i16::MAX.saturating_inc(), i16::MAX); // never wraps
/// ```
pub trait CounterInt:
    packed::sealed::CounterBytes
    + Copy
    + Ord
    + Debug
    + core::fmt::Display
    + Default
    + Send
    + Sync
    + 'static
{
    /// The type's name in the manual (`INT`, `UDINT`, …).
    const NAME: &'static str;
    /// The smallest value.
    const MIN: Self;
    /// The largest value.
    const MAX: Self;
    /// Zero.
    const ZERO: Self;
    /// `self + 1`, staying at `MAX` (CNT-SAT-01: a counter never wraps).
    fn saturating_inc(self) -> Self;
    /// `self - 1`, staying at `MIN`.
    fn saturating_dec(self) -> Self;
    /// `self + up - down` for `up`, `down` in `{0, 1}`, each step saturating as in
    /// [`saturating_inc`](Self::saturating_inc) and [`saturating_dec`](Self::saturating_dec);
    /// both 1 leave `self` (simultaneous edges cancel, CNT-SIMUL-01).
    ///
    /// Straight-line code for the counters' vector lanes: for a signed type one saturating
    /// add of the step `up - down` (computed on the bytes, 16 counters per SSE2 instruction,
    /// then widened once), for an unsigned type a saturating add and a saturating subtract.
    ///
    /// ```
    /// use plc_timers::counter::CounterInt;
    /// assert_eq!(7u16.saturating_up_down(1, 0), 8);
    /// assert_eq!(0u16.saturating_up_down(0, 1), 0);
    /// assert_eq!(i8::MAX.saturating_up_down(1, 0), i8::MAX);
    /// assert_eq!(u8::MAX.saturating_up_down(1, 1), u8::MAX);
    /// assert_eq!(i8::MIN.saturating_up_down(1, 1), i8::MIN);
    /// ```
    fn saturating_up_down(self, up: u8, down: u8) -> Self;
    /// `a` where `mask_a` is `0xFF`, `b` where `mask_b` is `0xFF`, 0 where both are 0, for
    /// masks that are 0 or `0xFF` and never both `0xFF` (else: unspecified). The choice of the
    /// counters' lane code as bit operations (`(a & mask_a) | (b & mask_b)`, each mask byte
    /// repeated across `Self`): three instructions per vector after the masks are widened,
    /// where two `bool` selects cost four. Repeating the byte is one unpack of the mask with
    /// itself on SSE2 where sign-extending it took an unpack and a shift (`CounterBank::scan`
    /// of 10 048 INT counters: 1.67 → 1.45-1.47 µs, `benches/peers`, issue 41).
    ///
    /// ```
    /// use plc_timers::counter::CounterInt;
    /// assert_eq!(i32::select_by_masks(7, 0xFF, -3, 0), 7);
    /// assert_eq!(i32::select_by_masks(7, 0, -3, 0xFF), -3);
    /// assert_eq!(u64::select_by_masks(7, 0, 9, 0), 0);
    /// ```
    #[inline]
    fn select_by_masks(a: Self, mask_a: u8, b: Self, mask_b: u8) -> Self {
        if mask_a != 0 {
            a
        } else if mask_b != 0 {
            b
        } else {
            Self::ZERO
        }
    }
    /// The value as an `i128` (every type fits).
    fn to_i128(self) -> i128;
    /// The value `v` if it is in the type's range.
    fn from_i128(v: i128) -> Option<Self>;
}

macro_rules! counter_int {
    ($t:ty, $name:literal, signed) => {
        counter_int!($t, $name, |v, up, down| {
            // One saturating add of -1, 0 or 1 (the step as a byte, widened once).
            v.saturating_add((up as i8).wrapping_sub(down as i8) as $t)
        });
    };
    ($t:ty, $name:literal, unsigned) => {
        counter_int!($t, $name, |v, up, down| {
            v.saturating_add((up & !down) as $t)
                .saturating_sub((down & !up) as $t)
        });
    };
    ($t:ty, $name:literal, |$v:ident, $up:ident, $down:ident| $up_down:expr) => {
        impl CounterInt for $t {
            const NAME: &'static str = $name;
            const MIN: Self = <$t>::MIN;
            const MAX: Self = <$t>::MAX;
            const ZERO: Self = 0;
            #[inline]
            fn saturating_inc(self) -> Self {
                self.saturating_add(1)
            }
            #[inline]
            fn saturating_dec(self) -> Self {
                self.saturating_sub(1)
            }
            #[inline]
            fn saturating_up_down(self, $up: u8, $down: u8) -> Self {
                let $v = self;
                $up_down
            }
            #[inline]
            fn select_by_masks(a: Self, mask_a: u8, b: Self, mask_b: u8) -> Self {
                let widen = |m: u8| <$t>::from_ne_bytes([m; size_of::<$t>()]);
                (a & widen(mask_a)) | (b & widen(mask_b))
            }
            #[inline]
            fn to_i128(self) -> i128 {
                self as i128
            }
            #[inline]
            fn from_i128(v: i128) -> Option<Self> {
                <$t>::try_from(v).ok()
            }
        }
    };
}

counter_int!(i8, "SINT", signed);
counter_int!(i16, "INT", signed);
counter_int!(i32, "DINT", signed);
counter_int!(i64, "LINT", signed);
counter_int!(u8, "USINT", unsigned);
counter_int!(u16, "UINT", unsigned);
counter_int!(u32, "UDINT", unsigned);
counter_int!(u64, "ULINT", unsigned);

/// Which IEC counter instruction.
///
/// ```
/// use plc_timers::counter::CounterKind;
/// assert_eq!(CounterKind::ALL.map(CounterKind::name), ["CTU", "CTD", "CTUD"]);
/// ```
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
#[cfg_attr(kani, derive(kani::Arbitrary))]
#[cfg_attr(feature = "bolero", derive(bolero_generator::TypeGenerator))]
pub enum CounterKind {
    /// `CTU`: counts up on rising CU; R resets; Q = CV >= PV.
    Ctu,
    /// `CTD`: counts down on rising CD; LD loads PV; Q = CV <= 0.
    Ctd,
    /// `CTUD`: both; QU = CV >= PV, QD = CV <= 0.
    Ctud,
}

impl CounterKind {
    /// All three.
    pub const ALL: [CounterKind; 3] = [CounterKind::Ctu, CounterKind::Ctd, CounterKind::Ctud];

    /// The instruction's name.
    pub const fn name(self) -> &'static str {
        match self {
            CounterKind::Ctu => "CTU",
            CounterKind::Ctd => "CTD",
            CounterKind::Ctud => "CTUD",
        }
    }

    /// The inputs this instruction has, others forced to 0: CTU has no CD and no LD, CTD no CU
    /// and no R (CNT-INPUTS-01).
    pub const fn mask(self, input: CounterInput<()>) -> CounterInput<()> {
        match self {
            CounterKind::Ctu => CounterInput {
                cd: false,
                ld: false,
                ..input
            },
            CounterKind::Ctd => CounterInput {
                cu: false,
                r: false,
                ..input
            },
            CounterKind::Ctud => input,
        }
    }
}

/// The inputs of one call.
///
/// ```
/// use plc_timers::counter::CounterInput;
/// let input = CounterInput::new(true, false, 10i32).with_ld(true);
/// assert!(input.cu && input.ld && !input.r);
/// assert_eq!(CounterInput::<i16>::default(), CounterInput::new(false, false, 0));
/// ```
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
#[cfg_attr(kani, derive(kani::Arbitrary))]
#[cfg_attr(feature = "bolero", derive(bolero_generator::TypeGenerator))]
pub struct CounterInput<T> {
    /// `CU`, count up (rising edge).
    pub cu: bool,
    /// `CD`, count down (rising edge).
    pub cd: bool,
    /// `R`, reset CV to 0 (level).
    pub r: bool,
    /// `LD` (`LOAD`), load PV into CV (level).
    pub ld: bool,
    /// `PV`, the preset.
    pub pv: T,
}

impl<T> CounterInput<T> {
    /// `CU`, `CD` and `PV`, with `R` = `LD` = 0.
    pub const fn new(cu: bool, cd: bool, pv: T) -> CounterInput<T> {
        CounterInput {
            cu,
            cd,
            r: false,
            ld: false,
            pv,
        }
    }

    /// These inputs with `R` = `r`.
    #[must_use]
    pub fn with_r(self, r: bool) -> CounterInput<T> {
        CounterInput { r, ..self }
    }

    /// These inputs with `LD` = `ld`.
    #[must_use]
    pub fn with_ld(self, ld: bool) -> CounterInput<T> {
        CounterInput { ld, ..self }
    }

    /// The boolean inputs alone.
    pub const fn signals(&self) -> CounterInput<()> {
        CounterInput {
            cu: self.cu,
            cd: self.cd,
            r: self.r,
            ld: self.ld,
            pv: (),
        }
    }

    /// These inputs with the booleans replaced by `signals`.
    pub fn with_signals(self, signals: CounterInput<()>) -> CounterInput<T> {
        CounterInput {
            cu: signals.cu,
            cd: signals.cd,
            r: signals.r,
            ld: signals.ld,
            pv: self.pv,
        }
    }
}

/// The outputs of one call. CTU's Q is `qu`; CTD's Q is `qd`.
///
/// ```
/// use plc_timers::counter::{outputs, CounterOutput};
/// assert_eq!(outputs(-1i32, 5), CounterOutput { qu: false, qd: true, cv: -1 });
/// ```
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct CounterOutput<T> {
    /// `QU` (CTU's `Q`): CV >= PV.
    pub qu: bool,
    /// `QD` (CTD's `Q`): CV <= 0.
    pub qd: bool,
    /// `CV`.
    pub cv: T,
}

/// The observable state of an IEC counter: what the abstraction function produces. Every
/// combination of fields is a state a counter can be in.
///
/// ```
/// use plc_timers::counter::{CounterRef, CounterState};
/// let state = CounterState { cv: 41u16, cu_prev: true, cd_prev: false };
/// assert_eq!(plc_timers::counter::CounterOps::state(&CounterRef::from_state(state)), state);
/// ```
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash)]
#[cfg_attr(kani, derive(kani::Arbitrary))]
#[cfg_attr(feature = "bolero", derive(bolero_generator::TypeGenerator))]
pub struct CounterState<T> {
    /// `CV`.
    pub cv: T,
    /// CU at the previous call (edge memory).
    pub cu_prev: bool,
    /// CD at the previous call (edge memory).
    pub cd_prev: bool,
}

/// What both IEC counter implementations offer.
///
/// ```
/// use plc_timers::counter::{Counter, CounterInput, CounterKind, CounterOps, CounterRef};
/// fn count_three(c: &mut dyn CounterOps<i32>) -> i32 {
///     for cu in [true, false, true, false, true] {
///         c.call(CounterKind::Ctu, CounterInput { cu, pv: 3, ..Default::default() });
///     }
///     c.state().cv
/// }
/// assert_eq!(count_three(&mut CounterRef::new()), 3);
/// assert_eq!(count_three(&mut Counter::new()), 3);
/// ```
pub trait CounterOps<T: CounterInt> {
    /// One call of the instruction `kind` with its inputs (those it lacks are taken as 0,
    /// CNT-INPUTS-01).
    fn call(&mut self, kind: CounterKind, input: CounterInput<T>) -> CounterOutput<T>;
    /// The observable state.
    fn state(&self) -> CounterState<T>;
}

/// The outputs for `cv` and `pv` (CNT-Q-01): QU = CV >= PV, QD = CV <= 0.
///
/// ```
/// use plc_timers::counter::outputs;
/// let o = outputs(3i16, 3);
/// assert!(o.qu && !o.qd);
/// ```
pub fn outputs<T: CounterInt>(cv: T, pv: T) -> CounterOutput<T> {
    CounterOutput {
        qu: cv >= pv,
        qd: cv <= T::ZERO,
        cv,
    }
}

/// A preset that is not a whole number of the counter's integer type.
///
/// ```
/// use plc_timers::block::Family;
/// use plc_timers::counter::Counters;
/// let e = <Counters<i16> as Family>::parse_preset("40000").expect_err("beyond INT");
/// assert_eq!(e.to_string(), "not a valid INT preset; PV is a whole number from -32768 to 32767");
/// ```
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct IntPresetError {
    /// The type's name.
    pub type_name: &'static str,
    /// Its smallest value.
    pub min: i128,
    /// Its largest value.
    pub max: i128,
}

impl core::fmt::Display for IntPresetError {
    fn fmt(&self, f: &mut core::fmt::Formatter<'_>) -> core::fmt::Result {
        write!(
            f,
            "not a valid {} preset; PV is a whole number from {} to {}",
            self.type_name, self.min, self.max
        )
    }
}

#[cfg(feature = "std")]
impl std::error::Error for IntPresetError {}

/// The IEC counters over the integer type `T`, as one [`Family`](crate::block::Family) of
/// the block interface: `CU`, `CD`, `R`, `LD` and `PV` in; `Q` (`QU`/`QD`) and `CV` out.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct Counters<T = i16>(core::marker::PhantomData<T>);

impl<T: CounterInt> crate::block::Family for Counters<T> {
    type Kind = CounterKind;
    type Input = CounterInput<T>;
    type Output = CounterOutput<T>;
    type State = CounterState<T>;
    type Preset = T;
    type PresetError = IntPresetError;
    type Unit = crate::time::Millis;

    fn kind(block: crate::catalog::Block) -> Option<CounterKind> {
        match block.kind() {
            crate::catalog::Kind::IecCounter(k) => Some(k),
            _ => None,
        }
    }

    #[inline]
    fn input(signals: crate::block::Signals, pv: T) -> CounterInput<T> {
        use crate::catalog::Port;
        CounterInput::new(signals.get(Port::Cu), signals.get(Port::Cd), pv)
            .with_r(signals.get(Port::R))
            .with_ld(signals.get(Port::Ld))
    }

    #[inline]
    fn values(kind: CounterKind, o: &CounterOutput<T>) -> crate::block::Outputs {
        use crate::block::{Outputs, Value};
        let cv = Value::Int(o.cv.to_i128());
        match kind {
            CounterKind::Ctu => Outputs::two(Value::Bool(o.qu), cv),
            CounterKind::Ctd => Outputs::two(Value::Bool(o.qd), cv),
            CounterKind::Ctud => Outputs::three(Value::Bool(o.qu), Value::Bool(o.qd), cv),
        }
    }

    fn parse_preset(text: &str) -> Result<T, IntPresetError> {
        let error = IntPresetError {
            type_name: T::NAME,
            min: T::MIN.to_i128(),
            max: T::MAX.to_i128(),
        };
        let value: i128 = text.trim().parse().map_err(|_| error)?;
        T::from_i128(value).ok_or(error)
    }

    fn preset_units(pv: T) -> i128 {
        pv.to_i128()
    }

    fn ramp(_: &CounterOutput<T>) -> Option<u64> {
        None
    }

    fn state_fields(s: &CounterState<T>) -> crate::block::Fields {
        use crate::block::{Fields, Value};
        Fields::of([
            Value::Int(s.cv.to_i128()),
            Value::Bool(s.cu_prev),
            Value::Bool(s.cd_prev),
        ])
    }

    fn state_from_fields(fields: &[crate::block::Value]) -> Option<CounterState<T>> {
        let [cv, cu_prev, cd_prev] = *fields else {
            return None;
        };
        Some(CounterState {
            cv: T::from_i128(cv.as_int()?)?,
            cu_prev: cu_prev.as_bool()?,
            cd_prev: cd_prev.as_bool()?,
        })
    }
}

crate::block::block_ops! {
    impl[T: CounterInt] CounterRef<T>: Counters<T>,
    call: |c, kind, _now, input| CounterOps::call(c, kind, input),
    state: CounterOps::state,
    // Every counter state is one a counter can be in.
    from_state: |state, _last_call| Some(CounterRef::from_state(state)),
    explains: |c, kind, _now, input| c.call_explained(kind, input),
}

crate::block::block_ops! {
    impl[T: CounterInt] Counter<T>: Counters<T>,
    call: |c, kind, _now, input| CounterOps::call(c, kind, input),
    state: CounterOps::state,
    from_state: |state, _last_call| Some(Counter::from_state(state)),
}
