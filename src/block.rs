//! The one block interface every front end is written against.
//!
//! Every family (S5 timers, IEC timers on `TIME` and on `LTIME`, IEC counters, S5 counters)
//! describes itself once, as a [`Family`]: its kind, input, output, state and preset types, the
//! unit of its clock, and how the catalog's ports ([`Port`]) map onto its input and output
//! structs. Both implementations of a family, the reference and the optimized form, implement
//! [`BlockOps`]: `call(kind, now, input)` (a counter ignores `now`), the explained call (the
//! reference says which rules decided each output; the optimized form gives no rules, being
//! proven equal to the reference), the state, and a row's step through the ports
//! ([`BlockOps::step`], which also runs a family's coils such as the IEC timers' `-(RT)-`).
//!
//! A catalog row ([`Block`]) and a data type ([`DataType`]) make an [`Instruction`]; its
//! [`Instruction::visit`] picks the family and the implementation and hands a fresh instance
//! to a [`Visit`]or, generic over [`BlockOps`]. That match is the only place where the families
//! are listed: the trace engine, the bindings, the benchmarks and the proofs' shared drivers are
//! written once, against these traits.
//!
//! ```
//! use plc_timers::block::{BlockOps, Implementation, Instruction, Signals, Value, Visit};
//! use plc_timers::catalog::{Block, DataType, Port};
//! use plc_timers::time::CpuTime;
//!
//! /// Runs IN = 1 for 2 units of the block's clock and reads its outputs: the same code for
//! /// every block, data type and implementation.
//! struct TwoTicks;
//! impl Visit for TwoTicks {
//!     type Out = Vec<Value>;
//!     fn visit<B: BlockOps>(self, mut block: B, kind: B::Kind) -> Vec<Value> {
//!         let pt = B::parse_preset("2").ok().expect("2 units");
//!         let on = Signals::of(&[Port::In]);
//!         block.step(kind, CpuTime::from_ticks(0), on, pt);
//!         let out = block.step(kind, CpuTime::from_ticks(2), on, pt);
//!         B::values(kind, &out).as_slice().to_vec()
//!     }
//! }
//! for data_type in [DataType::Time, DataType::LTime] {
//!     let ton = Instruction::new(Block::Ton, data_type).expect("TON takes TIME and LTIME");
//!     for imp in [Implementation::Reference, Implementation::Optimized] {
//!         assert_eq!(ton.visit(imp, TwoTicks), [Value::Bool(true), Value::Int(2)]);
//!     }
//! }
//! ```

use core::fmt::{Debug, Display};

use crate::catalog::{Block, DataType, Kind, Port};
use crate::rule::{Explained, RuleSet, MAX_OUTPUTS as RULE_OUTPUTS};
use crate::time::{CpuTime, LTime, Time, TimeUnit};

/// The most outputs a block has.
pub const MAX_OUTPUTS: usize = 3;

/// The boolean inputs and coils of one call, one bit per [`Port`]: what a family reads by port.
///
/// ```
/// use plc_timers::block::Signals;
/// use plc_timers::catalog::Port;
/// let on = Signals::of(&[Port::Cu, Port::R]);
/// assert!(on.get(Port::Cu) && on.get(Port::R) && !on.get(Port::Cd));
/// ```
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash)]
pub struct Signals(u32);

// A port's bit must fit.
const _: () = assert!(Port::ALL.len() <= 32);

impl Signals {
    /// No input at 1.
    pub const NONE: Signals = Signals(0);

    /// `port`'s bit.
    #[inline(always)]
    const fn bit(port: Port) -> u32 {
        1 << port as u32
    }

    /// The inputs `ports` at 1, every other at 0.
    pub const fn of(ports: &[Port]) -> Signals {
        let mut s = Signals::NONE;
        let mut i = 0;
        while i < ports.len() {
            s = s.with(ports[i]);
            i += 1;
        }
        s
    }

    /// These signals with `port` at 1.
    #[inline(always)]
    #[must_use]
    pub const fn with(self, port: Port) -> Signals {
        Signals(self.0 | Signals::bit(port))
    }

    /// These signals with `port` at `on`.
    #[inline(always)]
    #[must_use]
    pub const fn set(self, port: Port, on: bool) -> Signals {
        Signals(self.0 & !Signals::bit(port) | (on as u32) << port as u32)
    }

    /// Whether `port` is at 1.
    #[inline(always)]
    pub const fn get(self, port: Port) -> bool {
        self.0 & Signals::bit(port) != 0
    }
}

/// One output value, of the kinds the catalog gives outputs ([`crate::catalog::ValueKind`]).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Value {
    /// A boolean (Q, QU, QD), written `0`/`1`.
    Bool(bool),
    /// An integer (BI, ET, CV), written in decimal; ET in the unit of the block's clock.
    Int(i128),
    /// A 16-bit word (BCD, CV_BCD), written `W#16#XXXX`.
    Word(u16),
}

impl Display for Value {
    fn fmt(&self, f: &mut core::fmt::Formatter<'_>) -> core::fmt::Result {
        match *self {
            Value::Bool(b) => f.write_str(if b { "1" } else { "0" }),
            Value::Int(i) => write!(f, "{i}"),
            Value::Word(w) => write!(f, "W#16#{w:04X}"),
        }
    }
}

/// The outputs of one call, in the catalog's output order ([`Block::outputs`]).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub struct Outputs {
    values: [Value; MAX_OUTPUTS],
    len: u8,
}

impl Outputs {
    /// Two outputs.
    #[inline]
    pub const fn two(a: Value, b: Value) -> Outputs {
        Outputs {
            values: [a, b, Value::Bool(false)],
            len: 2,
        }
    }

    /// Three outputs.
    #[inline]
    pub const fn three(a: Value, b: Value, c: Value) -> Outputs {
        Outputs {
            values: [a, b, c],
            len: 3,
        }
    }

    /// The values.
    pub fn as_slice(&self) -> &[Value] {
        &self.values[..usize::from(self.len)]
    }
}

impl Value {
    /// The flag, `None` for a number or a word.
    pub const fn as_bool(self) -> Option<bool> {
        match self {
            Value::Bool(b) => Some(b),
            _ => None,
        }
    }

    /// The number, `None` for a flag or a word.
    pub const fn as_int(self) -> Option<i128> {
        match self {
            Value::Int(i) => Some(i),
            _ => None,
        }
    }
}

/// The most members a state has ([`Family::state_fields`]).
pub const MAX_FIELDS: usize = 7;

/// A state's members as values, in the order of its struct ([`Family::state_fields`]): what a
/// front end saves of an instance (Python's pickle) to rebuild it with
/// [`Family::state_from_fields`] and [`BlockOps::from_state`].
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub struct Fields {
    values: [Value; MAX_FIELDS],
    len: u8,
}

impl Fields {
    /// The members `values` (at most [`MAX_FIELDS`], checked when compiled).
    pub const fn of<const N: usize>(values: [Value; N]) -> Fields {
        const { assert!(N <= MAX_FIELDS) };
        let mut all = [Value::Bool(false); MAX_FIELDS];
        let mut i = 0;
        while i < N {
            all[i] = values[i];
            i += 1;
        }
        Fields {
            values: all,
            len: N as u8,
        }
    }

    /// The values.
    pub fn as_slice(&self) -> &[Value] {
        &self.values[..usize::from(self.len)]
    }
}

/// What a program does to a block's instance data apart from the box call
/// ([`BlockOps::access`]): the IEC timers' structure is read and written by coils
/// (IEC-ACCESS-01, IEC-RT-01).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Access<P> {
    /// Reads the member `port` (`Q`, `ET`), after the update an access makes.
    Read(Port),
    /// The `-(RT)-` coil with power flow: resets the timer data.
    Reset,
    /// The `-(PT)-` coil with power flow: loads the preset.
    Preset(P),
    /// A RUN-STOP-RUN transition of a retentive (`true`) or non-retentive structure.
    RunStopRun(bool),
}

/// The block has no such [`Access`] to its instance data (every family but the IEC timers).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct NoAccess;

impl Display for NoAccess {
    fn fmt(&self, f: &mut core::fmt::Formatter<'_>) -> core::fmt::Result {
        f.write_str("the block's instance data have no such member or coil")
    }
}

/// A family of blocks described once: its types and how the catalog's ports map onto them.
/// Implemented by a marker type per family ([`crate::s5::S5Timers`],
/// [`crate::iec::IecTimers`], [`crate::counter::Counters`], [`crate::counter::s5::S5Counters`]).
pub trait Family {
    /// The instruction (`S_ODT`, `TON`, `CTU`, …) as the family's kind enum.
    type Kind: Copy + Eq + Debug + 'static;
    /// The box inputs of one call.
    type Input: Copy + Debug;
    /// The box outputs of one call.
    type Output: Copy + Debug + PartialEq;
    /// The observable state both implementations map to (what the proofs compare).
    type State: Copy + Debug + PartialEq;
    /// The preset (`TV`, `PT`, `PV`).
    type Preset: Copy + Debug + PartialEq + Display;
    /// What was wrong with a preset's text, and what is allowed.
    type PresetError: Display + Debug;
    /// The unit of the CPU clock the family's calls take (milliseconds but for `LTIME`).
    type Unit: TimeUnit;

    /// The family's kind of `block`, or `None` when `block` is of another family.
    fn kind(block: Block) -> Option<Self::Kind>;
    /// The input struct of a call with the boolean inputs `signals` and the preset `preset`.
    fn input(signals: Signals, preset: Self::Preset) -> Self::Input;
    /// The outputs of `kind` in the catalog's order.
    fn values(kind: Self::Kind, output: &Self::Output) -> Outputs;
    /// Reads a preset (a literal of the preset's data type, or a plain number in its unit).
    fn parse_preset(text: &str) -> Result<Self::Preset, Self::PresetError>;
    /// The preset in the unit of the block's integer output (PT in clock units, TV in units of
    /// its time base, PV), for the preset line of a diagram.
    fn preset_units(preset: Self::Preset) -> i128;
    /// Clock units per unit of the integer output while it runs (ET: 1, BI: the time base in
    /// ms), `None` when it does not change with time (CV).
    fn ramp(output: &Self::Output) -> Option<u64>;
    /// The state's members in the order of its struct: a flag as [`Value::Bool`], a number as
    /// [`Value::Int`] (an S5 time base in ms; the IEC timers' last instruction as 0 before the
    /// first call, else 1 + its index in [`IecKind::ALL`](crate::iec::IecKind::ALL)).
    fn state_fields(state: &Self::State) -> Fields;
    /// The state whose members are `fields` ([`Family::state_fields`] read back), `None` when
    /// they are not (a count, kind of value or number that no state has); whether an instance
    /// can be in it is [`BlockOps::from_state`]'s check.
    fn state_from_fields(fields: &[Value]) -> Option<Self::State>;
}

/// One implementation (reference or optimized) of a [`Family`]: what every front end calls.
///
/// An instance is plain data (`Copy`, `Send`, `'static`), so a front end may keep the one
/// [`Instruction::visit`] hands it behind a single object of its own.
pub trait BlockOps: Default + Copy + Debug + Send + Sync + 'static {
    /// The family described once.
    type Family: Family<
        Kind = Self::Kind,
        Input = Self::Input,
        Output = Self::Output,
        State = Self::State,
        Preset = Self::Preset,
    >;
    /// [`Family::Kind`] (plain data as the instance is, so that a front end may hold both).
    type Kind: Copy + Eq + Debug + Send + Sync + 'static;
    /// [`Family::Input`].
    type Input: Copy + Debug;
    /// [`Family::Output`].
    type Output: Copy + Debug + PartialEq;
    /// [`Family::State`].
    type State: Copy + Debug + PartialEq;
    /// [`Family::Preset`] (plain data, as the kind).
    type Preset: Copy + Debug + PartialEq + Display + Send + Sync + 'static;
    /// Whether [`BlockOps::call_explained`] gives the reference's rules (the optimized forms
    /// give none: they are proven equal to the reference, which is the one that explains).
    const EXPLAINS: bool;

    /// Executes `kind` at CPU time `now` with `input` (a counter ignores `now`).
    fn call(&mut self, kind: Self::Kind, now: Now<Self>, input: Self::Input) -> Self::Output;
    /// [`BlockOps::call`] with the rules that decided each output and acted on the state (none
    /// from an optimized form).
    fn call_explained(
        &mut self,
        kind: Self::Kind,
        now: Now<Self>,
        input: Self::Input,
    ) -> Explained<Self::Output>;
    /// The observable state.
    fn state(&self) -> Self::State;
    /// The CPU time of the previous call, which the ticks of the next one count from: the S5
    /// timers keep it beside their state; 0 for the others, whose state holds all they need.
    #[inline]
    fn last_call(&self) -> Now<Self> {
        CpuTime::from_ticks(0)
    }
    /// An instance in `state` whose previous call was at `last_call` (ignored by the families
    /// that keep no such time): the round trip of [`BlockOps::state`] and
    /// [`BlockOps::last_call`], through the family's checking constructor; `None` when no
    /// instance can be in `state`.
    ///
    /// ```
    /// use plc_timers::block::{BlockOps, Family, Implementation, Instruction, Signals, Visit};
    /// use plc_timers::catalog::{Block, Port};
    /// use plc_timers::time::CpuTime;
    ///
    /// /// Saves an instance half-way through its members and rebuilds it: it goes on as the
    /// /// original does.
    /// struct Resume;
    /// impl Visit for Resume {
    ///     type Out = bool;
    ///     fn visit<B: BlockOps>(self, mut block: B, kind: B::Kind) -> bool {
    ///         // 3 units, or 30 ms for an S5TIME (whose plain number is a word).
    ///         let preset = B::parse_preset("3").or_else(|_| B::parse_preset("S5T#30MS"));
    ///         let preset = preset.ok().expect("a preset");
    ///         let (on, off) = (Signals::of(&Port::ALL), Signals::NONE);
    ///         block.step(kind, CpuTime::from_ticks(5), on, preset);
    ///         let fields = B::Family::state_fields(&block.state());
    ///         let state = B::Family::state_from_fields(fields.as_slice()).expect("its own");
    ///         let mut copy = B::from_state(state, block.last_call()).expect("a state it was in");
    ///         (6..40).all(|t| {
    ///             let signals = if t % 7 < 3 { on } else { off };
    ///             let now = CpuTime::from_ticks(t * 10);
    ///             block.step(kind, now, signals, preset) == copy.step(kind, now, signals, preset)
    ///         })
    ///     }
    /// }
    /// for block in Block::ALL {
    ///     for imp in [Implementation::Reference, Implementation::Optimized] {
    ///         assert!(Instruction::of(block).visit(imp, Resume), "{block}");
    ///     }
    /// }
    /// ```
    fn from_state(state: Self::State, last_call: Now<Self>) -> Option<Self>;
    /// Reads or writes the instance data apart from the box call ([`Access`]) at `now`: the
    /// member read, `None` for a coil or a mode change; [`NoAccess`] when the block's data
    /// have no such member or coil (every family but the IEC timers).
    ///
    /// ```
    /// use plc_timers::block::{Access, BlockOps, NoAccess, Value};
    /// use plc_timers::catalog::Port;
    /// use plc_timers::counter::CounterRef;
    /// use plc_timers::iec::{IecInput, IecKind, IecTimer};
    /// use plc_timers::time::CpuTime;
    /// let mut ton = IecTimer::new();
    /// let pt = plc_timers::time!("T#10MS");
    /// BlockOps::call(&mut ton, IecKind::Ton, CpuTime::from_millis(0), IecInput::new(true, pt));
    /// let q = ton.access(CpuTime::from_millis(10), Access::Read(Port::Q)); // update on access
    /// assert_eq!(q, Ok(Some(Value::Bool(true))));
    /// assert_eq!(ton.access(CpuTime::from_millis(10), Access::Reset), Ok(None)); // -(RT)-
    /// assert_eq!(ton.access(CpuTime::from_millis(10), Access::Read(Port::Et)), Ok(Some(Value::Int(0))));
    /// let mut ctu = CounterRef::<i16>::new();
    /// assert_eq!(ctu.access(CpuTime::from_millis(0), Access::Reset), Err(NoAccess));
    /// ```
    #[inline]
    fn access(
        &mut self,
        now: Now<Self>,
        access: Access<Self::Preset>,
    ) -> Result<Option<Value>, NoAccess> {
        let _ = (now, access);
        Err(NoAccess)
    }

    /// One row through the ports: the coils that are at 1 in `signals` (a family's, such as
    /// the IEC timers' `-(RT)-`, as a network above the box's), then the box call with the
    /// boolean inputs of `signals` and `preset`.
    #[inline]
    fn step(
        &mut self,
        kind: Self::Kind,
        now: Now<Self>,
        signals: Signals,
        preset: Self::Preset,
    ) -> Self::Output {
        self.call(kind, now, <Self::Family as Family>::input(signals, preset))
    }

    /// [`BlockOps::step`], explained as one call.
    fn step_explained(
        &mut self,
        kind: Self::Kind,
        now: Now<Self>,
        signals: Signals,
        preset: Self::Preset,
    ) -> Explained<Self::Output> {
        self.call_explained(kind, now, <Self::Family as Family>::input(signals, preset))
    }

    /// [`Family::values`].
    #[inline]
    fn values(kind: Self::Kind, output: &Self::Output) -> Outputs {
        <Self::Family as Family>::values(kind, output)
    }

    /// [`Family::parse_preset`].
    fn parse_preset(text: &str) -> Result<Self::Preset, <Self::Family as Family>::PresetError> {
        <Self::Family as Family>::parse_preset(text)
    }
}

/// The CPU time a call of `B` takes, in its family's unit.
pub type Now<B> = CpuTime<<<B as BlockOps>::Family as Family>::Unit>;

/// A call's outputs without rules: the explained call of an optimized form.
pub fn unexplained<O>(output: O) -> Explained<O> {
    Explained {
        output,
        outputs: [RuleSet::EMPTY; RULE_OUTPUTS],
        state: RuleSet::EMPTY,
        written: 0,
    }
}

/// Which implementation of a block to run.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash)]
pub enum Implementation {
    /// The reference semantics.
    #[default]
    Reference,
    /// The optimized implementation, through the same interface.
    Optimized,
}

/// What is done with a block once [`Instruction::visit`] has chosen its family and
/// implementation.
pub trait Visit {
    /// The result.
    type Out;
    /// Does it with a fresh (initial) instance `block` executing `kind`.
    fn visit<B: BlockOps>(self, block: B, kind: B::Kind) -> Self::Out;
}

/// A block with its data type selected, as TIA Portal shows an instruction (`TON` of `LTIME`,
/// `CTU` of `DINT`): what a front end runs.
///
/// ```
/// use plc_timers::block::Instruction;
/// use plc_timers::catalog::{Block, DataType};
/// assert_eq!(Instruction::of(Block::Ton).data_type(), DataType::Time);
/// let e = Instruction::new(Block::Ctu, DataType::LTime).expect_err("CTU counts integers");
/// assert_eq!(e.to_string(), "CTU does not take the data type LTIME; it takes SINT INT DINT LINT USINT UINT UDINT ULINT");
/// ```
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub struct Instruction {
    block: Block,
    data_type: DataType,
}

/// A data type the block does not take ([`Instruction::new`]).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct DataTypeError {
    /// The block.
    pub block: Block,
    /// The data type asked for.
    pub data_type: DataType,
}

impl Display for DataTypeError {
    fn fmt(&self, f: &mut core::fmt::Formatter<'_>) -> core::fmt::Result {
        write!(
            f,
            "{} does not take the data type {}; it takes",
            self.block,
            self.data_type.name()
        )?;
        for t in self.block.data_types() {
            write!(f, " {}", t.name())?;
        }
        Ok(())
    }
}

#[cfg(feature = "std")]
impl std::error::Error for DataTypeError {}

impl Instruction {
    /// `block` on its default data type ([`Block::default_data_type`]).
    pub const fn of(block: Block) -> Instruction {
        Instruction {
            block,
            data_type: block.default_data_type(),
        }
    }

    /// `block` on `data_type`, or the error that lists the data types it takes.
    pub fn new(block: Block, data_type: DataType) -> Result<Instruction, DataTypeError> {
        if block.data_types().contains(&data_type) {
            Ok(Instruction { block, data_type })
        } else {
            Err(DataTypeError { block, data_type })
        }
    }

    /// The block.
    pub const fn block(self) -> Block {
        self.block
    }

    /// The data type.
    pub const fn data_type(self) -> DataType {
        self.data_type
    }

    /// The unit of the clock this instruction's calls take: `ns` for `LTIME`, else `ms`.
    pub const fn clock_unit(self) -> &'static str {
        match self.data_type {
            DataType::LTime => <crate::time::Nanos as TimeUnit>::SYMBOL,
            _ => <crate::time::Millis as TimeUnit>::SYMBOL,
        }
    }

    /// Hands a fresh instance of the implementation `imp` of this instruction to `v`: the one
    /// table of the families, their implementations and data types.
    pub fn visit<V: Visit>(self, imp: Implementation, v: V) -> V::Out {
        use crate::counter::{s5::S5Counter, s5::S5CounterRef, Counter, CounterRef};
        use crate::iec::{IecTimerOf, IecTimerRef};
        use crate::s5::{S5Timer, S5TimerRef};
        use Implementation::{Optimized, Reference};
        /// Both implementations of one family member.
        fn pick<R: BlockOps, O: BlockOps<Kind = R::Kind>, V: Visit>(
            imp: Implementation,
            kind: R::Kind,
            v: V,
        ) -> V::Out {
            match imp {
                Reference => v.visit(R::default(), kind),
                Optimized => v.visit(O::default(), kind),
            }
        }
        match (self.block.kind(), self.data_type) {
            (Kind::S5Timer(k), _) => pick::<S5TimerRef, S5Timer, V>(imp, k, v),
            (Kind::IecTimer(k), DataType::LTime) => {
                pick::<IecTimerRef<u64, LTime>, IecTimerOf<u64, LTime>, V>(imp, k, v)
            }
            (Kind::IecTimer(k), _) => {
                pick::<IecTimerRef<u32, Time>, IecTimerOf<u32, Time>, V>(imp, k, v)
            }
            (Kind::IecCounter(k), t) => {
                macro_rules! counter {
                    ($($variant:ident => $n:ty),*) => {
                        match t {
                            $(DataType::$variant => pick::<CounterRef<$n>, Counter<$n>, V>(imp, k, v),)*
                            _ => pick::<CounterRef<i16>, Counter<i16>, V>(imp, k, v),
                        }
                    };
                }
                counter!(SInt => i8, DInt => i32, LInt => i64, USInt => u8, UInt => u16, UDInt => u32, ULInt => u64)
            }
            (Kind::S5Counter(k), _) => pick::<S5CounterRef, S5Counter, V>(imp, k, v),
        }
    }
}

impl Display for Instruction {
    /// The block's name, with the data type when the block takes more than one: `TON`,
    /// `TON LTIME`, `CTU DINT`.
    fn fmt(&self, f: &mut core::fmt::Formatter<'_>) -> core::fmt::Result {
        f.write_str(self.block.name())?;
        if self.block.data_types().len() > 1 {
            write!(f, " {}", self.data_type.name())?;
        }
        Ok(())
    }
}

/// Implements [`BlockOps`] for an implementation `$t` of the family `$family`, whose own
/// operations trait gives `call` and `state`: with the reference's explained call
/// (`explains: |t, kind, now, input| ...`) or none (`unexplained`, an optimized form); `from_state`
/// rebuilds one from its state and last call, `last_call` gives it when the family keeps one.
macro_rules! block_ops {
    (@types $family:ty) => {
        type Family = $family;
        type Kind = <$family as $crate::block::Family>::Kind;
        type Input = <$family as $crate::block::Family>::Input;
        type Output = <$family as $crate::block::Family>::Output;
        type State = <$family as $crate::block::Family>::State;
        type Preset = <$family as $crate::block::Family>::Preset;
    };
    (
        impl[$($g:tt)*] $t:ty: $family:ty,
        call: |$s:ident, $kind:ident, $now:ident, $input:ident| $call:expr,
        state: $state:path,
        from_state: |$fs:ident, $fl:ident| $from:expr,
        $(last_call: $last:path,)?
        explains: |$es:ident, $ek:ident, $en:ident, $ei:ident| $explained:expr $(,)?
    ) => {
        impl<$($g)*> $crate::block::BlockOps for $t {
            $crate::block::block_ops!(@types $family);
            const EXPLAINS: bool = true;
            #[inline]
            fn call(&mut self, $kind: Self::Kind, $now: $crate::block::Now<Self>, $input: Self::Input) -> Self::Output {
                let $s = self;
                $call
            }
            fn call_explained(&mut self, $ek: Self::Kind, $en: $crate::block::Now<Self>, $ei: Self::Input) -> $crate::rule::Explained<Self::Output> {
                let $es = self;
                $explained
            }
            fn state(&self) -> Self::State {
                $state(self)
            }
            #[allow(unused_variables)]
            fn from_state($fs: Self::State, $fl: $crate::block::Now<Self>) -> Option<Self> {
                $from
            }
            $(
                fn last_call(&self) -> $crate::block::Now<Self> {
                    $last(self)
                }
            )?
        }
    };
    (
        impl[$($g:tt)*] $t:ty: $family:ty,
        call: |$s:ident, $kind:ident, $now:ident, $input:ident| $call:expr,
        state: $state:path,
        from_state: |$fs:ident, $fl:ident| $from:expr
        $(, last_call: $last:path)? $(,)?
    ) => {
        impl<$($g)*> $crate::block::BlockOps for $t {
            $crate::block::block_ops!(@types $family);
            const EXPLAINS: bool = false;
            #[inline]
            fn call(&mut self, $kind: Self::Kind, $now: $crate::block::Now<Self>, $input: Self::Input) -> Self::Output {
                let $s = self;
                $call
            }
            fn call_explained(&mut self, kind: Self::Kind, now: $crate::block::Now<Self>, input: Self::Input) -> $crate::rule::Explained<Self::Output> {
                $crate::block::unexplained($crate::block::BlockOps::call(self, kind, now, input))
            }
            fn state(&self) -> Self::State {
                $state(self)
            }
            #[allow(unused_variables)]
            fn from_state($fs: Self::State, $fl: $crate::block::Now<Self>) -> Option<Self> {
                $from
            }
            $(
                fn last_call(&self) -> $crate::block::Now<Self> {
                    $last(self)
                }
            )?
        }
    };
}
pub(crate) use block_ops;
