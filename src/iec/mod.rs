//! IEC timers of S7-1200/1500: `TP`, `TON`, `TOF`, `TONR`, the `-(RT)-` and `-(PT)-` coils,
//! update-on-access (S7-1200 manual, timer instructions; Strączyński lecture).
//!
//! One interface, [`IecTimerOps`], two implementations:
//! - [`IecTimerRef`]: the rules as the manual states them, one function per rule.
//! - [`IecTimer`] ([`IecTimerOf`] on the 32-bit clock): the 16-byte `IEC_TIMER` structure as a
//!   soft-PLC holds it, `#[repr(C)]`, flags packed in one byte.
//!
//! and [`TonBank`], thousands of TON timers scanned together.
//!
//! [`IecTimerOps::state`] maps either to the reference state; the proofs in `proofs/iec.rs` show
//! that every operation commutes with it.
//!
//! Both are generic over the width of the CPU clock word ([`ClockWord`]): `u32` is the S7-1200
//! clock; narrower words let the proof drivers enumerate every state. Every call takes a
//! [`CpuTime`], of which the timer sees the low bits.
//!
//! ```
//! use plc_timers::iec::{IecInput, IecKind, IecTimer, IecTimerOps, IecTimerRef};
//! use plc_timers::time::CpuTime;
//!
//! let pt = plc_timers::time!("T#500MS");
//! let at = CpuTime::from_millis;
//! let mut reference = IecTimerRef::new();
//! let mut optimized = IecTimer::new();
//! for t in [&mut reference as &mut dyn IecTimerOps<u32>, &mut optimized] {
//!     assert!(!t.call(IecKind::Ton, at(1_000), IecInput::new(true, pt)).q); // START = 1000
//!     assert!(!t.call(IecKind::Ton, at(1_499), IecInput::new(true, pt)).q);
//!     let out = t.call(IecKind::Ton, at(1_500), IecInput::new(true, pt)); // ET = PT: Q rises
//!     assert_eq!((out.q, out.et), (true, 500));
//! }
//! assert_eq!(reference.state(), optimized.state());
//! ```

pub mod bank;
pub mod reference;
pub mod structure;

use crate::time::clock::ClockWord;
use crate::time::{CpuTime, IecDuration, Time};

pub use bank::TonBank;
pub use reference::{IecLTimerRef, IecTimerRef};
pub use structure::{IecLTimer, IecTimer, IecTimerOf};

/// Which timer instruction runs on the structure.
///
/// ```
/// use plc_timers::iec::IecKind;
/// assert_eq!(IecKind::ALL.map(IecKind::name), ["TP", "TON", "TOF", "TONR"]);
/// ```
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
#[cfg_attr(kani, derive(kani::Arbitrary))]
#[cfg_attr(feature = "bolero", derive(bolero_generator::TypeGenerator))]
pub enum IecKind {
    /// `TP`, pulse: Q = 1 for PT after a rising IN; IN and PT changes while running have no effect.
    Tp,
    /// `TON`, on-delay: Q = 1 once IN has been 1 for PT; IN = 0 resets.
    Ton,
    /// `TOF`, off-delay: Q = 1 while IN = 1 and for PT after IN falls; IN = 1 resets.
    Tof,
    /// `TONR`, retentive on-delay: accumulates the time IN is 1; only R resets.
    Tonr,
}

impl IecKind {
    /// All four, in manual order.
    pub const ALL: [IecKind; 4] = [IecKind::Tp, IecKind::Ton, IecKind::Tof, IecKind::Tonr];

    /// The instruction's name as the manual writes it.
    pub const fn name(self) -> &'static str {
        match self {
            IecKind::Tp => "TP",
            IecKind::Ton => "TON",
            IecKind::Tof => "TOF",
            IecKind::Tonr => "TONR",
        }
    }
}

/// The box inputs of one call.
///
/// In C's layout with the two bits first: 8 bytes for TIME, and IN the low byte of the word
/// in which Rust passes the inputs by value, so that a call inlined into a loop tests IN
/// without taking it out of that word (with PT first, IN sat in bits 32-39 and each step
/// shifted it out and back: TP's step on square waves 1.21 → 1.15 ns, `benches/peers`).
///
/// ```
/// use plc_timers::iec::IecInput;
/// assert_eq!(size_of::<IecInput>(), 8);
/// let input = IecInput::new(true, plc_timers::time!("T#1S")).with_reset(true);
/// assert!(input.input && input.reset);
/// ```
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
#[cfg_attr(kani, derive(kani::Arbitrary))]
#[cfg_attr(feature = "bolero", derive(bolero_generator::TypeGenerator))]
#[repr(C)]
pub struct IecInput<D = Time> {
    /// `IN`.
    pub input: bool,
    /// `R` (TONR only; ignored by TP, TON and TOF).
    pub reset: bool,
    /// `PT`, the preset; negative values are taken as 0 (S7-1200 manual, Table 8-21 note 1).
    pub pt: D,
}

/// Every input 0, `PT` = `T#0MS`: the inputs of a box that nothing drives.
///
/// ```
/// use plc_timers::iec::IecInput;
/// use plc_timers::time::Time;
/// assert_eq!(IecInput::default(), IecInput::new(false, Time::ZERO));
/// ```
impl<D: IecDuration> Default for IecInput<D> {
    fn default() -> IecInput<D> {
        IecInput::new(false, D::ZERO)
    }
}

impl<D: IecDuration> IecInput<D> {
    /// `IN` and `PT`, with `R` = 0.
    ///
    /// ```
    /// use plc_timers::iec::IecInput;
    /// let input = IecInput::new(true, plc_timers::time!("T#2S"));
    /// assert!(input.input && !input.reset);
    /// ```
    pub const fn new(input: bool, pt: D) -> IecInput<D> {
        IecInput {
            input,
            pt,
            reset: false,
        }
    }

    /// These inputs with `R` = `reset`.
    #[must_use]
    pub const fn with_reset(self, reset: bool) -> IecInput<D> {
        IecInput { reset, ..self }
    }
}

/// The box outputs of one call.
///
/// ```
/// use plc_timers::iec::{IecInput, IecKind, IecOutput, IecTimer, IecTimerOps};
/// use plc_timers::time::CpuTime;
/// let mut tof = IecTimer::new();
/// let pt = plc_timers::time!("T#100MS");
/// tof.call(IecKind::Tof, CpuTime::from_millis(0), IecInput::new(true, pt));
/// let out = tof.call(IecKind::Tof, CpuTime::from_millis(30), IecInput::new(false, pt));
/// assert_eq!(out, IecOutput { q: true, et: 0 }); // the delay starts at the falling edge
/// ```
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct IecOutput<C = u32> {
    /// `Q`.
    pub q: bool,
    /// `ET`, the elapsed time in milliseconds, `0..=PT`.
    pub et: C,
}

/// The observable state of an IEC timer: what the proofs compare and the abstraction function
/// produces. Field names are the manual's structure members.
///
/// A plain description: any combination of fields can be written, and [`IecState::is_valid`]
/// says whether a timer can be in it; [`IecTimerRef`] and [`IecTimerOf`] take a state only
/// through their checking `from_state`.
///
/// ```
/// use plc_timers::iec::IecState;
/// assert!(IecState::<u32>::default().is_valid());
/// assert!(!IecState::<u32> { et: 5, pt: 4, ..Default::default() }.is_valid()); // ET > PT
/// ```
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, Default)]
pub struct IecState<C> {
    /// The instruction that last ran on the structure (`None` before the first call); needed
    /// by update-on-access, which must know how Q follows ET.
    pub kind: Option<IecKind>,
    /// `IN` as the last call saw it: the edge memory.
    pub input: bool,
    /// Whether the timer is timing.
    pub running: bool,
    /// `START`: the CPU clock when timing began (for TONR, shifted back by the accumulated time).
    pub start: C,
    /// `PT` as latched at the start (or loaded by the PT coil), negative taken as 0.
    pub pt: C,
    /// `ET` (`ELAPSED`).
    pub et: C,
    /// `Q`.
    pub q: bool,
}

/// Any valid state ([`IecState::is_valid`]): ET at most PT, START 0 unless running (feature
/// `bolero`).
#[cfg(feature = "bolero")]
impl<C: ClockWord + bolero_generator::TypeGenerator> bolero_generator::TypeGenerator
    for IecState<C>
{
    fn generate<D: bolero_generator::Driver>(driver: &mut D) -> Option<IecState<C>> {
        let running: bool = driver.produce()?;
        let start: C = driver.produce()?;
        let (a, b): (C, C) = (driver.produce()?, driver.produce()?);
        // ET = PT (a timer that has run out) as often as ET below it: two random words of a
        // wide clock are almost never equal.
        let at_pt: bool = driver.produce()?;
        Some(IecState {
            kind: driver.produce()?,
            input: driver.produce()?,
            running,
            start: if running { start } else { C::ZERO },
            pt: a.max(b),
            et: if at_pt { a.max(b) } else { a.min(b) },
            q: driver.produce()?,
        })
    }
}

impl<C: ClockWord> IecState<C> {
    /// The validity invariant every reachable state satisfies: `ET <= PT`; a stopped timer has
    /// no pending START (START is 0 when not running, so equal states are equal bytes).
    pub fn is_valid(&self) -> bool {
        self.et <= self.pt && (self.running || self.start == C::default())
    }
}

/// The operations of an IEC timer structure, common to the reference and the optimized one.
/// `now` is the CPU time; the timer computes with its low `C::BITS` bits, the wrapping clock.
///
/// ```
/// use plc_timers::iec::{IecInput, IecKind, IecTimer, IecTimerOps, IecTimerRef};
/// use plc_timers::time::CpuTime;
/// // One program against the interface, run on both implementations.
/// fn after_rt<T: IecTimerOps<u32>>(mut t: T) -> (bool, u32) {
///     let pt = plc_timers::time!("T#1S");
///     t.call(IecKind::Ton, CpuTime::from_millis(0), IecInput::new(true, pt));
///     t.reset_timer(); // the -(RT)- coil
///     (t.read_q(CpuTime::from_millis(2_000)), t.state().et)
/// }
/// assert_eq!(after_rt(IecTimerRef::new()), (false, 0));
/// assert_eq!(after_rt(IecTimer::new()), (false, 0));
/// ```
pub trait IecTimerOps<C: ClockWord, D: IecDuration = Time> {
    /// Executes the box (or coil) instruction `kind` with its inputs; returns `Q` and `ET`.
    fn call(&mut self, kind: IecKind, now: CpuTime<D::Unit>, input: IecInput<D>) -> IecOutput<C>;
    /// Reads the structure's `Q` member: an update at `now` happens first (IEC-ACCESS-01).
    fn read_q(&mut self, now: CpuTime<D::Unit>) -> bool;
    /// Reads the structure's `ELAPSED` member: an update at `now` happens first (IEC-ACCESS-01).
    fn read_et(&mut self, now: CpuTime<D::Unit>) -> C;
    /// The `-(RT)-` coil with power flow: resets the timer data (see `spec/iec.md`, IEC-RT-01).
    fn reset_timer(&mut self);
    /// The `-(PT)-` coil with power flow: loads `pt` into the structure's preset.
    fn preset_timer(&mut self, pt: D);
    /// A RUN-STOP-RUN transition: a non-retentive structure returns to its initial values; a
    /// retentive one keeps its data.
    fn run_stop_run(&mut self, retentive: bool);
    /// The observable state.
    fn state(&self) -> IecState<C>;
}

/// The IEC timers on the data type `D` (`TIME`, `LTIME`) over the clock word `C`, as one
/// [`Family`](crate::block::Family) of the block interface: `IN`, `R` (TONR) and `PT` in, the
/// `-(RT)-` coil, `Q` and `ET` out; the clock in `D`'s unit.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct IecTimers<C = u32, D = Time>(core::marker::PhantomData<(C, D)>);

impl<C: ClockWord, D: IecDuration> crate::block::Family for IecTimers<C, D> {
    type Kind = IecKind;
    type Input = IecInput<D>;
    type Output = IecOutput<C>;
    type State = IecState<C>;
    type Preset = D;
    type PresetError = crate::time::LiteralError;
    type Unit = D::Unit;

    fn kind(block: crate::catalog::Block) -> Option<IecKind> {
        match block.kind() {
            crate::catalog::Kind::IecTimer(k) => Some(k),
            _ => None,
        }
    }

    #[inline]
    fn input(signals: crate::block::Signals, pt: D) -> IecInput<D> {
        use crate::catalog::Port;
        IecInput::new(signals.get(Port::In), pt).with_reset(signals.get(Port::R))
    }

    #[inline]
    fn values(_: IecKind, o: &IecOutput<C>) -> crate::block::Outputs {
        use crate::block::{Outputs, Value};
        Outputs::two(Value::Bool(o.q), Value::Int(i128::from(o.et.to_u64())))
    }

    fn parse_preset(text: &str) -> Result<D, crate::time::LiteralError> {
        text.trim().parse()
    }

    fn preset_units(pt: D) -> i128 {
        i128::from(pt.units())
    }

    fn ramp(_: &IecOutput<C>) -> Option<u64> {
        Some(1)
    }

    fn state_fields(s: &IecState<C>) -> crate::block::Fields {
        use crate::block::{Fields, Value};
        let kind = s
            .kind
            .and_then(|k| IecKind::ALL.iter().position(|&a| a == k))
            .map_or(0, |i| i as i128 + 1);
        let word = |w: C| Value::Int(i128::from(w.to_u64()));
        Fields::of([
            Value::Int(kind),
            Value::Bool(s.input),
            Value::Bool(s.running),
            word(s.start),
            word(s.pt),
            word(s.et),
            Value::Bool(s.q),
        ])
    }

    fn state_from_fields(fields: &[crate::block::Value]) -> Option<IecState<C>> {
        let [kind, input, running, start, pt, et, q] = *fields else {
            return None;
        };
        // A clock word of `C`, not wider.
        let word = |v: crate::block::Value| {
            let v = u64::try_from(v.as_int()?).ok()?;
            (v <= C::MAX.to_u64()).then(|| C::from_u64_wrapping(v))
        };
        let kind = match usize::try_from(kind.as_int()?).ok()? {
            0 => None,
            i => Some(*IecKind::ALL.get(i - 1)?),
        };
        Some(IecState {
            kind,
            input: input.as_bool()?,
            running: running.as_bool()?,
            start: word(start)?,
            pt: word(pt)?,
            et: word(et)?,
            q: q.as_bool()?,
        })
    }
}

/// The state, its round trip and the access of [`BlockOps`](crate::block::BlockOps), the same
/// for both implementations `$t` (whose own `from_state` checks the state).
macro_rules! state_and_access {
    ($t:ident) => {
        fn state(&self) -> IecState<C> {
            IecTimerOps::state(self)
        }

        fn from_state(state: IecState<C>, _last_call: CpuTime<D::Unit>) -> Option<Self> {
            $t::from_state(state)
        }

        fn access(
            &mut self,
            now: CpuTime<D::Unit>,
            a: crate::block::Access<D>,
        ) -> Result<Option<crate::block::Value>, crate::block::NoAccess> {
            access(self, now, a)
        }
    };
}

/// [`BlockOps::access`](crate::block::BlockOps::access) of both implementations: the reads and
/// coils of [`IecTimerOps`].
fn access<C: ClockWord, D: IecDuration, T: IecTimerOps<C, D>>(
    timer: &mut T,
    now: CpuTime<D::Unit>,
    access: crate::block::Access<D>,
) -> Result<Option<crate::block::Value>, crate::block::NoAccess> {
    use crate::block::{Access, NoAccess, Value};
    use crate::catalog::Port;
    Ok(match access {
        Access::Read(Port::Q) => Some(Value::Bool(timer.read_q(now))),
        Access::Read(Port::Et) => Some(Value::Int(i128::from(timer.read_et(now).to_u64()))),
        Access::Read(_) => return Err(NoAccess),
        Access::Reset => {
            timer.reset_timer();
            None
        }
        Access::Preset(pt) => {
            timer.preset_timer(pt);
            None
        }
        Access::RunStopRun(retentive) => {
            timer.run_stop_run(retentive);
            None
        }
    })
}

/// The `-(RT)-` coil of a row (IEC-RT-01), run before the box call as a network above the
/// box's would.
fn rt(signals: crate::block::Signals) -> bool {
    signals.get(crate::catalog::Port::Rt)
}

/// [`crate::block::BlockOps::step`] of both IEC timer forms: the `-(RT)-` coil when its signal
/// is set, then the box call.
#[inline]
fn step<C: ClockWord, D: IecDuration>(
    timer: &mut impl IecTimerOps<C, D>,
    kind: IecKind,
    now: CpuTime<D::Unit>,
    signals: crate::block::Signals,
    pt: D,
) -> IecOutput<C> {
    if rt(signals) {
        timer.reset_timer();
    }
    let input = <IecTimers<C, D> as crate::block::Family>::input(signals, pt);
    timer.call(kind, now, input)
}

impl<C: ClockWord, D: IecDuration> crate::block::BlockOps for IecTimerRef<C, D> {
    crate::block::block_ops!(@types IecTimers<C, D>);
    const EXPLAINS: bool = true;

    #[inline]
    fn call(&mut self, kind: IecKind, now: CpuTime<D::Unit>, input: IecInput<D>) -> IecOutput<C> {
        IecTimerOps::call(self, kind, now, input)
    }

    fn call_explained(
        &mut self,
        kind: IecKind,
        now: CpuTime<D::Unit>,
        input: IecInput<D>,
    ) -> crate::rule::Explained<IecOutput<C>> {
        IecTimerRef::call_explained(self, kind, now, input)
    }

    state_and_access!(IecTimerRef);

    fn step(
        &mut self,
        kind: IecKind,
        now: CpuTime<D::Unit>,
        signals: crate::block::Signals,
        pt: D,
    ) -> IecOutput<C> {
        step(self, kind, now, signals, pt)
    }

    /// A row with `RT` = 1 is the coil and the call explained as one
    /// ([`IecTimerRef::reset_timer_then_call_explained`]).
    fn step_explained(
        &mut self,
        kind: IecKind,
        now: CpuTime<D::Unit>,
        signals: crate::block::Signals,
        pt: D,
    ) -> crate::rule::Explained<IecOutput<C>> {
        let input = <IecTimers<C, D> as crate::block::Family>::input(signals, pt);
        if rt(signals) {
            self.reset_timer_then_call_explained(kind, now, input)
        } else {
            IecTimerRef::call_explained(self, kind, now, input)
        }
    }
}

impl<C: ClockWord, D: IecDuration> crate::block::BlockOps for IecTimerOf<C, D> {
    crate::block::block_ops!(@types IecTimers<C, D>);
    const EXPLAINS: bool = false;

    #[inline]
    fn call(&mut self, kind: IecKind, now: CpuTime<D::Unit>, input: IecInput<D>) -> IecOutput<C> {
        IecTimerOps::call(self, kind, now, input)
    }

    fn call_explained(
        &mut self,
        kind: IecKind,
        now: CpuTime<D::Unit>,
        input: IecInput<D>,
    ) -> crate::rule::Explained<IecOutput<C>> {
        crate::block::unexplained(IecTimerOps::call(self, kind, now, input))
    }

    state_and_access!(IecTimerOf);

    #[inline]
    fn step(
        &mut self,
        kind: IecKind,
        now: CpuTime<D::Unit>,
        signals: crate::block::Signals,
        pt: D,
    ) -> IecOutput<C> {
        step(self, kind, now, signals, pt)
    }

    fn step_explained(
        &mut self,
        kind: IecKind,
        now: CpuTime<D::Unit>,
        signals: crate::block::Signals,
        pt: D,
    ) -> crate::rule::Explained<IecOutput<C>> {
        crate::block::unexplained(crate::block::BlockOps::step(self, kind, now, signals, pt))
    }
}
