//! The one generic adapter between a trace row and a block: each family of the core is driven
//! through its interface trait ([`S5TimerOps`], [`IecTimerOps`], [`CounterOps`],
//! [`S5CounterOps`]), so the same code drives the reference and the optimized implementation.
//! [`dispatch`] picks the family, the implementation and (IEC counters) the integer type from a
//! [`BlockSpec`]; everything else is generic over [`Adapter`].
//!
//! The rules that decided a step come from the core's references ([`Adapter::call_explained`],
//! through [`Explains`]): the tool has no copy of the semantics.

use std::fmt;
use std::marker::PhantomData;

use plc_timers::catalog::{Block, Kind, Port, PresetKind};
use plc_timers::counter::s5::{
    CounterPreset, S5Counter, S5CounterInput, S5CounterKind, S5CounterOps, S5CounterOutput,
    S5CounterRef, S5CounterState,
};
use plc_timers::counter::{
    Counter, CounterInput, CounterInt, CounterKind, CounterOps, CounterOutput, CounterRef,
    CounterState,
};
use plc_timers::iec::{IecInput, IecKind, IecOutput, IecState, IecTimer, IecTimerOps, IecTimerRef};
use plc_timers::rule::{Explained, RuleSet, MAX_OUTPUTS as RULE_OUTPUTS};
use plc_timers::s5::{S5Input, S5Kind, S5Output, S5State, S5Timer, S5TimerOps, S5TimerRef};
use plc_timers::time::{CpuTime, S5Time, Time, TimeBase};

use super::error::{Location, TraceError};

/// The most outputs a block has (checked against the catalog by a test).
pub const MAX_OUTPUTS: usize = 3;

/// One output value.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Value {
    /// A boolean (Q, QU, QD), written `0`/`1`.
    Bool(bool),
    /// An integer (BI, ET, CV), written in decimal.
    Int(i128),
    /// A 16-bit word (BCD, CV_BCD), written `W#16#XXXX`.
    Word(u16),
}

impl fmt::Display for Value {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match *self {
            Value::Bool(b) => f.write_str(if b { "1" } else { "0" }),
            Value::Int(i) => write!(f, "{i}"),
            Value::Word(w) => write!(f, "W#16#{w:04X}"),
        }
    }
}

/// The outputs of one step, in the catalog's output order.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Outputs {
    values: [Value; MAX_OUTPUTS],
    len: usize,
}

/// Fills the unused places of [`Outputs`].
const NONE: Value = Value::Bool(false);

impl Outputs {
    #[inline]
    fn two(a: Value, b: Value) -> Outputs {
        Outputs {
            values: [a, b, NONE],
            len: 2,
        }
    }

    #[inline]
    fn three(a: Value, b: Value, c: Value) -> Outputs {
        Outputs {
            values: [a, b, c],
            len: 3,
        }
    }

    /// The values.
    pub fn as_slice(&self) -> &[Value] {
        &self.values[..self.len]
    }
}

/// The boolean inputs of a row, one bit per [`Port`]: what a block's adapter reads by port.
///
/// ```
/// use plc_timers::catalog::Port;
/// use plc_timers_trace::Signals;
/// let on = Signals::of(&[Port::Cu, Port::R]);
/// assert!(on.get(Port::Cu) && on.get(Port::R) && !on.get(Port::Cd));
/// ```
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct Signals(u32);

impl Signals {
    /// No input at 1.
    pub const NONE: Signals = Signals(0);

    /// `port`'s bit.
    #[inline(always)]
    const fn bit(port: Port) -> u32 {
        1 << port as u32
    }

    /// The inputs `ports` at 1, every other at 0.
    pub fn of(ports: &[Port]) -> Signals {
        ports.iter().fold(Signals::NONE, |s, &p| s.with(p))
    }

    /// These signals with `port` at 1.
    #[inline(always)]
    #[must_use]
    pub const fn with(self, port: Port) -> Signals {
        Signals(self.0 | Signals::bit(port))
    }

    /// Whether `port` is at 1.
    #[inline(always)]
    pub const fn get(self, port: Port) -> bool {
        self.0 & Signals::bit(port) != 0
    }
}

// A port's bit must fit.
const _: () = assert!(Port::ALL.len() <= 32);

/// An implementation's explained call: the references give their rules
/// (`call_explained`), the optimized forms none (they are proven equal to the reference, which
/// is the one that explains).
pub trait Explains<K, I, O> {
    /// Whether [`Explains::explained`] gives the reference's rules.
    const EXPLAINS: bool;
    /// One call with the rules that decided it.
    fn explained(&mut self, kind: K, now: CpuTime, input: I) -> Explained<O>;
}

/// A call's outputs without rules (the optimized forms).
fn unexplained<O>(output: O) -> Explained<O> {
    Explained {
        output,
        outputs: [RuleSet::EMPTY; RULE_OUTPUTS],
        state: RuleSet::EMPTY,
        written: 0,
    }
}

/// Implements [`Explains`] for a reference (`$explains` true, through `call_explained`) or an
/// optimized form (false, through `call`).
macro_rules! explains {
    ($([$($g:tt)*] $t:ty: $k:ty, $i:ty, $o:ty, $explains:literal, |$x:ident, $kind:ident, $now:ident, $input:ident| $body:expr;)*) => {
        $(impl<$($g)*> Explains<$k, $i, $o> for $t {
            const EXPLAINS: bool = $explains;
            fn explained(&mut self, $kind: $k, $now: CpuTime, $input: $i) -> Explained<$o> {
                let $x = self;
                $body
            }
        })*
    };
}

explains! {
    [] S5TimerRef: S5Kind, S5Input, S5Output, true,
        |t, kind, now, input| t.call_explained(kind, now, input);
    [] S5Timer: S5Kind, S5Input, S5Output, false,
        |t, kind, now, input| unexplained(t.call(kind, now, input));
    [] IecTimerRef<u32>: IecKind, IecInput, IecOutput<u32>, true,
        |t, kind, now, input| t.call_explained(kind, now, input);
    [] IecTimer: IecKind, IecInput, IecOutput<u32>, false,
        |t, kind, now, input| unexplained(t.call(kind, now, input));
    [N: CounterInt] CounterRef<N>: CounterKind, CounterInput<N>, CounterOutput<N>, true,
        |t, kind, _now, input| t.call_explained(kind, input);
    [N: CounterInt] Counter<N>: CounterKind, CounterInput<N>, CounterOutput<N>, false,
        |t, kind, _now, input| unexplained(t.call(kind, input));
    [] S5CounterRef: S5CounterKind, S5CounterInput, S5CounterOutput, true,
        |t, kind, _now, input| t.call_explained(kind, input);
    [] S5Counter: S5CounterKind, S5CounterInput, S5CounterOutput, false,
        |t, kind, _now, input| unexplained(t.call(kind, input));
}

/// The `-(RT)-` coil of an IEC timer before the box call of the same row, explained as
/// [`Explains`] explains a call: the reference gives its explanation
/// ([`IecTimerRef::reset_timer_then_call_explained`]), the optimized form none.
pub trait ExplainsRt {
    /// The coil with power flow, then the box call, explained.
    fn reset_then_call_explained(
        &mut self,
        kind: IecKind,
        now: CpuTime,
        input: IecInput,
    ) -> Explained<IecOutput<u32>>;
}

impl ExplainsRt for IecTimerRef<u32> {
    fn reset_then_call_explained(
        &mut self,
        kind: IecKind,
        now: CpuTime,
        input: IecInput,
    ) -> Explained<IecOutput<u32>> {
        self.reset_timer_then_call_explained(kind, now, input)
    }
}

impl ExplainsRt for IecTimer {
    fn reset_then_call_explained(
        &mut self,
        kind: IecKind,
        now: CpuTime,
        input: IecInput,
    ) -> Explained<IecOutput<u32>> {
        self.reset_timer();
        unexplained(self.call(kind, now, input))
    }
}

/// Which implementation of a block to drive.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub enum Implementation {
    /// The reference semantics.
    #[default]
    Reference,
    /// The optimized implementation, through the same interface.
    Optimized,
}

macro_rules! int_types {
    ($($variant:ident = $t:ty),* $(,)?) => {
        /// The integer type of an IEC counter (`--type`); the names are the core's
        /// [`CounterInt::NAME`].
        #[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
        pub enum IntType {
            $(
                #[doc = concat!("`", stringify!($t), "`.")]
                $variant,
            )*
        }

        impl IntType {
            /// Every type.
            pub const ALL: [IntType; 8] = [$(IntType::$variant),*];

            /// The type's name (`SINT`, `INT`, …).
            pub fn name(self) -> &'static str {
                match self { $(IntType::$variant => <$t as CounterInt>::NAME,)* }
            }

            /// The smallest and the largest value.
            pub fn limits(self) -> (i128, i128) {
                match self {
                    $(IntType::$variant => (
                        <$t as CounterInt>::MIN.to_i128(),
                        <$t as CounterInt>::MAX.to_i128(),
                    ),)*
                }
            }

            fn dispatch<V: Visit>(self, block: Block, kind: CounterKind, imp: Implementation, v: V) -> V::Out {
                match self { $(IntType::$variant => counter::<$t, V>(block, kind, imp, v),)* }
            }
        }
    };
}

int_types!(
    SInt = i8,
    Int = i16,
    DInt = i32,
    LInt = i64,
    USInt = u8,
    UInt = u16,
    UDInt = u32,
    ULInt = u64
);

impl IntType {
    /// The type called `name` (ASCII case ignored).
    pub fn lookup(name: &str) -> Option<IntType> {
        IntType::ALL
            .into_iter()
            .find(|t| t.name().eq_ignore_ascii_case(name))
    }

    /// The type called `name`, or the error that lists the types (the value parser of
    /// `--type`).
    pub fn parse(name: &str) -> Result<IntType, String> {
        IntType::lookup(name).ok_or_else(|| {
            format!(
                "unknown integer type `{}`; --type takes one of {}",
                super::error::show(name.as_bytes()),
                IntType::names()
            )
        })
    }

    /// Every name, separated by blanks.
    pub fn names() -> String {
        let names: Vec<&str> = IntType::ALL.iter().map(|t| t.name()).collect();
        names.join(" ")
    }
}

impl IntType {
    /// INT, the default of `--type`.
    pub const DEFAULT: IntType = IntType::Int;
}

/// A block as the command line asks for it.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct BlockSpec {
    /// The block.
    pub block: Block,
    /// The integer type (IEC counters only; INT otherwise).
    pub int_type: IntType,
    /// The implementation to drive.
    pub implementation: Implementation,
}

impl BlockSpec {
    /// The reference of `block` (INT for an IEC counter).
    pub fn new(block: Block) -> BlockSpec {
        BlockSpec {
            block,
            int_type: IntType::DEFAULT,
            implementation: Implementation::Reference,
        }
    }

    /// The block called `name` (case-insensitive, aliases accepted), with `--type`: the
    /// checks of the command line's parser, for a command read from text (the examples).
    pub fn parse(name: &str, int_type: Option<&str>) -> Result<BlockSpec, TraceError> {
        let block = parse_block(name).map_err(|e| TraceError::new(Location::Command, e))?;
        let int_type = int_type
            .map(IntType::parse)
            .transpose()
            .map_err(|e| TraceError::new(Location::Option("type"), e))?;
        BlockSpec::typed(block, int_type).map_err(|e| TraceError::new(Location::Option("type"), e))
    }

    /// `block` with the integer type `int_type`, which only the IEC counters take.
    pub fn typed(block: Block, int_type: Option<IntType>) -> Result<BlockSpec, String> {
        let mut spec = BlockSpec::new(block);
        if let Some(t) = int_type {
            if !matches!(block.kind(), Kind::IecCounter(_)) {
                return Err(format!(
                    "--type applies to the IEC counters ({}) only, not to {block}",
                    names_of(|b| matches!(b.kind(), Kind::IecCounter(_)))
                ));
            }
            spec.int_type = t;
        }
        Ok(spec)
    }

    /// This spec with `implementation`.
    pub fn with(self, implementation: Implementation) -> BlockSpec {
        BlockSpec {
            implementation,
            ..self
        }
    }
}

/// The block called `name` (ASCII case ignored, aliases accepted), or the error that lists the
/// blocks (the value parser of the command line's block).
pub fn parse_block(name: &str) -> Result<Block, String> {
    Block::lookup(name).ok_or_else(|| {
        format!(
            "unknown block `{}`; the blocks are {}",
            super::error::show(name.as_bytes()),
            block_names()
        )
    })
}

/// A preset as a value of its kind, block-independent: what the command line's parser hands to
/// the engine, and what a diagram's title shows. [`PresetValue::parse`] reads one for a block;
/// its `Display` is the literal (`S5T#50MS`, `T#500MS`, `4`, `C#5`).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum PresetValue {
    /// An S5TIME (TV).
    S5Time(S5Time),
    /// A TIME (PT).
    Time(Time),
    /// An IEC counter's PV (checked against the counter's type when it is used).
    Integer(i128),
    /// An S5 counter's PV.
    S5Count(CounterPreset),
}

impl PresetValue {
    /// The preset `text` of the block of `spec`, read as a preset cell is: the error says
    /// what the block's preset may be.
    pub fn parse(spec: BlockSpec, text: &str) -> Result<PresetValue, String> {
        struct V<'a>(&'a str);
        impl Visit for V<'_> {
            type Out = Result<PresetValue, String>;
            fn visit<F: Adapter>(self, family: F) -> Self::Out {
                let preset = family.parse_preset(self.0.trim())?;
                Ok(family.preset_value(preset))
            }
        }
        dispatch(spec, V(text))
    }

    /// Its kind.
    pub fn kind(self) -> PresetKind {
        match self {
            PresetValue::S5Time(_) => PresetKind::S5Time,
            PresetValue::Time(_) => PresetKind::Time,
            PresetValue::Integer(_) => PresetKind::Integer,
            PresetValue::S5Count(_) => PresetKind::S5Count,
        }
    }
}

impl fmt::Display for PresetValue {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            PresetValue::S5Time(t) => write!(f, "{t}"),
            PresetValue::Time(t) => write!(f, "{t}"),
            PresetValue::Integer(i) => write!(f, "{i}"),
            PresetValue::S5Count(c) => write!(f, "C#{}", c.value()),
        }
    }
}

/// The error of a preset of another kind than `block`'s (a library caller's mistake: the
/// command line's parser reads the preset for the block).
fn wrong_kind(block: Block, value: PresetValue) -> String {
    let p = block.preset();
    format!(
        "{value} is not a preset of {block}; its preset {} is {}",
        p.port.name(),
        match p.kind {
            PresetKind::S5Time => "an S5TIME",
            PresetKind::Time => "a TIME",
            PresetKind::Integer => "an integer",
            PresetKind::S5Count => "an S5 count",
        }
    )
}

/// [`Adapter::parse_preset`], [`Adapter::preset_value`] and [`Adapter::preset`] of an adapter
/// whose preset parses with its `FromStr` and is carried as is by the [`PresetValue`] variant
/// `$variant`.
macro_rules! preset_conversions {
    ($variant:ident, $preset:ty) => {
        fn parse_preset(&self, text: &str) -> Result<$preset, String> {
            text.parse::<$preset>().map_err(|e| e.to_string())
        }

        fn preset_value(&self, preset: $preset) -> PresetValue {
            PresetValue::$variant(preset)
        }

        fn preset(&self, value: PresetValue) -> Result<$preset, String> {
            match value {
                PresetValue::$variant(preset) => Ok(preset),
                other => Err(wrong_kind(self.block, other)),
            }
        }
    };
}

/// The names of the blocks for which `pick` holds, separated by blanks.
pub fn names_of(pick: impl Fn(Block) -> bool) -> String {
    let names: Vec<&str> = Block::ALL
        .into_iter()
        .filter(|b| pick(*b))
        .map(Block::name)
        .collect();
    names.join(" ")
}

/// Every block name with its aliases, as messages and help texts list them.
pub fn block_names() -> String {
    let names: Vec<String> = Block::ALL
        .into_iter()
        .map(|b| match b.aliases() {
            [] => b.name().to_string(),
            aliases => format!("{} ({})", b.name(), aliases.join(" ")),
        })
        .collect();
    names.join(", ")
}

/// A block family driven through its core interface (the catalog's family of the block is
/// [`Block::family`]; this is the adapter that drives it).
pub trait Adapter {
    /// The preset's type (TV, PT, PV).
    type Preset: Copy + PartialEq + fmt::Debug;
    /// The state the core reports.
    type State: Copy + fmt::Debug;
    /// The core's output struct.
    type Output: Copy;
    /// The block.
    fn block(&self) -> Block;
    /// Parses a preset; the error says what is allowed.
    fn parse_preset(&self, text: &str) -> Result<Self::Preset, String>;
    /// The preset as a [`PresetValue`].
    fn preset_value(&self, preset: Self::Preset) -> PresetValue;
    /// The preset given as a [`PresetValue`]; the error says what is allowed.
    fn preset(&self, value: PresetValue) -> Result<Self::Preset, String>;
    /// The preset in the unit of the block's integer output (PT in ms, TV in units, PV), for
    /// the preset line of a diagram.
    fn preset_mark(&self, preset: Self::Preset) -> i128;
    /// One call of the block at CPU time `now`.
    fn call(&mut self, now: u64, signals: Signals, preset: Self::Preset) -> Self::Output;
    /// The state.
    fn state(&self) -> Self::State;
    /// The output values in catalog order.
    fn values(&self, output: &Self::Output) -> Outputs;
    /// Milliseconds per unit of the integer output while it runs (ET: 1, BI: the time base),
    /// `None` when it does not change with time (CV).
    fn ramp(&self, output: &Self::Output) -> Option<u64>;
    /// [`Adapter::call`], explained by the reference ([`Explained`]: the rules that decided
    /// each output and acted on the state); the optimized forms give no rules.
    fn call_explained(
        &mut self,
        now: u64,
        signals: Signals,
        preset: Self::Preset,
    ) -> Explained<Self::Output>;
    /// Whether [`Adapter::call_explained`] gives the reference's rules (the optimized forms
    /// give none).
    fn explains(&self) -> bool;
    /// The boolean inputs and coils the adapter reads (of the family: TON has no R, which
    /// TONR's adapter reads).
    fn reads(&self) -> &'static [Port];
}

/// What is done with a family once [`dispatch`] has chosen it.
pub trait Visit {
    /// The result.
    type Out;
    /// Does it with `family`.
    fn visit<F: Adapter>(self, family: F) -> Self::Out;
}

/// Builds the family adapter of `spec` and hands it to `v`.
pub fn dispatch<V: Visit>(spec: BlockSpec, v: V) -> V::Out {
    use Implementation::{Optimized, Reference};
    let block = spec.block;
    match (block.kind(), spec.implementation) {
        (Kind::S5Timer(k), Reference) => v.visit(S5Adapter::new(block, k, S5TimerRef::new())),
        (Kind::S5Timer(k), Optimized) => v.visit(S5Adapter::new(block, k, S5Timer::new())),
        (Kind::IecTimer(k), Reference) => v.visit(IecAdapter::new(block, k, IecTimerRef::new())),
        (Kind::IecTimer(k), Optimized) => v.visit(IecAdapter::new(block, k, IecTimer::new())),
        (Kind::IecCounter(k), imp) => spec.int_type.dispatch(block, k, imp, v),
        (Kind::S5Counter(k), Reference) => {
            v.visit(S5CounterAdapter::new(block, k, S5CounterRef::new()))
        }
        (Kind::S5Counter(k), Optimized) => {
            v.visit(S5CounterAdapter::new(block, k, S5Counter::new()))
        }
    }
}

fn counter<N: CounterInt, V: Visit>(
    block: Block,
    kind: CounterKind,
    imp: Implementation,
    v: V,
) -> V::Out {
    match imp {
        Implementation::Reference => {
            v.visit(CounterAdapter::new(block, kind, CounterRef::<N>::new()))
        }
        Implementation::Optimized => v.visit(CounterAdapter::new(block, kind, Counter::<N>::new())),
    }
}

// ---------------------------------------------------------------------------------------------
// S5 timers

/// An S5 timer (reference or packed) as a trace drives it.
pub struct S5Adapter<T> {
    timer: T,
    block: Block,
    kind: S5Kind,
}

impl<T: S5TimerOps> S5Adapter<T> {
    /// The core's input struct of a row.
    #[inline]
    fn input(&self, signals: Signals, tv: S5Time) -> S5Input {
        S5Input::new(signals.get(Port::S), signals.get(Port::R), tv).with_fr(signals.get(Port::Fr))
    }

    fn new(block: Block, kind: S5Kind, timer: T) -> S5Adapter<T> {
        S5Adapter { timer, block, kind }
    }
}

impl<T: S5TimerOps + Explains<S5Kind, S5Input, S5Output>> Adapter for S5Adapter<T> {
    type Preset = S5Time;
    type State = S5State;
    type Output = S5Output;

    fn block(&self) -> Block {
        self.block
    }

    preset_conversions!(S5Time, S5Time);

    fn preset_mark(&self, tv: S5Time) -> i128 {
        i128::from(tv.units())
    }

    #[inline]
    fn call(&mut self, now: u64, signals: Signals, tv: S5Time) -> S5Output {
        let input = self.input(signals, tv);
        self.timer.call(self.kind, CpuTime::from_millis(now), input)
    }

    fn call_explained(&mut self, now: u64, signals: Signals, tv: S5Time) -> Explained<S5Output> {
        let input = self.input(signals, tv);
        self.timer
            .explained(self.kind, CpuTime::from_millis(now), input)
    }

    fn explains(&self) -> bool {
        T::EXPLAINS
    }

    fn state(&self) -> S5State {
        self.timer.state()
    }

    #[inline]
    fn values(&self, o: &S5Output) -> Outputs {
        Outputs::three(
            Value::Bool(o.q),
            Value::Int(i128::from(o.bi)),
            Value::Word(o.bcd),
        )
    }

    fn ramp(&self, o: &S5Output) -> Option<u64> {
        Some(u64::from(
            TimeBase::from_bits((o.bcd >> 12 & 3) as u8).millis(),
        ))
    }

    fn reads(&self) -> &'static [Port] {
        &[Port::S, Port::R, Port::Fr]
    }
}

// ---------------------------------------------------------------------------------------------
// IEC timers

/// An IEC timer (reference or 16-byte structure) as a trace drives it, on the 32-bit clock.
pub struct IecAdapter<T> {
    timer: T,
    block: Block,
    kind: IecKind,
}

impl<T: IecTimerOps<u32>> IecAdapter<T> {
    /// The core's input struct of a row.
    #[inline]
    fn input(&self, signals: Signals, pt: Time) -> IecInput {
        IecInput::new(signals.get(Port::In), pt).with_reset(signals.get(Port::R))
    }

    fn new(block: Block, kind: IecKind, timer: T) -> IecAdapter<T> {
        IecAdapter { timer, block, kind }
    }
}

impl<T: IecTimerOps<u32> + Explains<IecKind, IecInput, IecOutput<u32>> + ExplainsRt> Adapter
    for IecAdapter<T>
{
    type Preset = Time;
    type State = IecState<u32>;
    type Output = IecOutput<u32>;

    fn block(&self) -> Block {
        self.block
    }

    preset_conversions!(Time, Time);

    fn preset_mark(&self, pt: Time) -> i128 {
        i128::from(pt.clamp_negative())
    }

    /// A row with `RT` = 1 runs the `-(RT)-` coil first (a network above the box's), then
    /// the box (spec/cli.md, "Traces").
    #[inline]
    fn call(&mut self, now: u64, signals: Signals, pt: Time) -> IecOutput<u32> {
        if signals.get(Port::Rt) {
            self.timer.reset_timer();
        }
        let input = self.input(signals, pt);
        self.timer.call(self.kind, CpuTime::from_millis(now), input)
    }

    /// [`Adapter::call`] explained: a row with `RT` = 1 is the coil and the call explained
    /// as one ([`IecTimerRef::reset_timer_then_call_explained`]).
    fn call_explained(
        &mut self,
        now: u64,
        signals: Signals,
        pt: Time,
    ) -> Explained<IecOutput<u32>> {
        let input = self.input(signals, pt);
        let now = CpuTime::from_millis(now);
        if signals.get(Port::Rt) {
            self.timer.reset_then_call_explained(self.kind, now, input)
        } else {
            self.timer.explained(self.kind, now, input)
        }
    }

    fn explains(&self) -> bool {
        T::EXPLAINS
    }

    fn state(&self) -> IecState<u32> {
        self.timer.state()
    }

    #[inline]
    fn values(&self, o: &IecOutput<u32>) -> Outputs {
        Outputs::two(Value::Bool(o.q), Value::Int(i128::from(o.et)))
    }

    fn ramp(&self, _: &IecOutput<u32>) -> Option<u64> {
        Some(1)
    }

    fn reads(&self) -> &'static [Port] {
        &[Port::In, Port::R, Port::Rt]
    }
}

// ---------------------------------------------------------------------------------------------
// IEC counters

/// An IEC counter (reference or packed) of integer type `N` as a trace drives it.
pub struct CounterAdapter<N, C> {
    counter: C,
    block: Block,
    kind: CounterKind,
    int: PhantomData<N>,
}

impl<N: CounterInt, C: CounterOps<N>> CounterAdapter<N, C> {
    /// The core's input struct of a row.
    #[inline]
    fn input(&self, signals: Signals, pv: N) -> CounterInput<N> {
        CounterInput::new(signals.get(Port::Cu), signals.get(Port::Cd), pv)
            .with_r(signals.get(Port::R))
            .with_ld(signals.get(Port::Ld))
    }

    fn new(block: Block, kind: CounterKind, counter: C) -> CounterAdapter<N, C> {
        CounterAdapter {
            counter,
            block,
            kind,
            int: PhantomData,
        }
    }
}

/// What an IEC counter's PV may be.
fn int_preset_error<N: CounterInt>() -> String {
    format!(
        "not a valid {} preset; PV is a whole number from {} to {}",
        N::NAME,
        N::MIN.to_i128(),
        N::MAX.to_i128()
    )
}

impl<
        N: CounterInt,
        C: CounterOps<N> + Explains<CounterKind, CounterInput<N>, CounterOutput<N>>,
    > Adapter for CounterAdapter<N, C>
{
    type Preset = N;
    type State = CounterState<N>;
    type Output = CounterOutput<N>;

    fn block(&self) -> Block {
        self.block
    }

    fn parse_preset(&self, text: &str) -> Result<N, String> {
        let value: i128 = text.trim().parse().map_err(|_| int_preset_error::<N>())?;
        self.preset(PresetValue::Integer(value))
    }

    fn preset_value(&self, pv: N) -> PresetValue {
        PresetValue::Integer(pv.to_i128())
    }

    fn preset(&self, value: PresetValue) -> Result<N, String> {
        match value {
            PresetValue::Integer(pv) => N::from_i128(pv).ok_or_else(int_preset_error::<N>),
            other => Err(wrong_kind(self.block, other)),
        }
    }

    fn preset_mark(&self, pv: N) -> i128 {
        pv.to_i128()
    }

    #[inline]
    fn call(&mut self, _now: u64, signals: Signals, pv: N) -> CounterOutput<N> {
        let input = self.input(signals, pv);
        self.counter.call(self.kind, input)
    }

    fn call_explained(&mut self, now: u64, signals: Signals, pv: N) -> Explained<CounterOutput<N>> {
        let input = self.input(signals, pv);
        self.counter
            .explained(self.kind, CpuTime::from_millis(now), input)
    }

    fn explains(&self) -> bool {
        C::EXPLAINS
    }

    fn state(&self) -> CounterState<N> {
        self.counter.state()
    }

    #[inline]
    fn values(&self, o: &CounterOutput<N>) -> Outputs {
        let cv = Value::Int(o.cv.to_i128());
        match self.kind {
            CounterKind::Ctu => Outputs::two(Value::Bool(o.qu), cv),
            CounterKind::Ctd => Outputs::two(Value::Bool(o.qd), cv),
            CounterKind::Ctud => Outputs::three(Value::Bool(o.qu), Value::Bool(o.qd), cv),
        }
    }

    fn ramp(&self, _: &CounterOutput<N>) -> Option<u64> {
        None
    }

    fn reads(&self) -> &'static [Port] {
        &[Port::Cu, Port::Cd, Port::R, Port::Ld]
    }
}

// ---------------------------------------------------------------------------------------------
// S5 counters

/// An S5 counter (reference or packed word) as a trace drives it.
pub struct S5CounterAdapter<C> {
    counter: C,
    block: Block,
    kind: S5CounterKind,
}

impl<C: S5CounterOps> S5CounterAdapter<C> {
    /// The core's input struct of a row.
    #[inline]
    fn input(&self, signals: Signals, pv: CounterPreset) -> S5CounterInput {
        S5CounterInput::new(signals.get(Port::Cu), signals.get(Port::Cd), pv)
            .with_s(signals.get(Port::S))
            .with_r(signals.get(Port::R))
            .with_fr(signals.get(Port::Fr))
    }

    fn new(block: Block, kind: S5CounterKind, counter: C) -> S5CounterAdapter<C> {
        S5CounterAdapter {
            counter,
            block,
            kind,
        }
    }
}

impl<C: S5CounterOps + Explains<S5CounterKind, S5CounterInput, S5CounterOutput>> Adapter
    for S5CounterAdapter<C>
{
    type Preset = CounterPreset;
    type State = S5CounterState;
    type Output = S5CounterOutput;

    fn block(&self) -> Block {
        self.block
    }

    preset_conversions!(S5Count, CounterPreset);

    fn preset_mark(&self, pv: CounterPreset) -> i128 {
        i128::from(pv.value())
    }

    #[inline]
    fn call(&mut self, _now: u64, signals: Signals, pv: CounterPreset) -> S5CounterOutput {
        let input = self.input(signals, pv);
        self.counter.call(self.kind, input)
    }

    fn call_explained(
        &mut self,
        now: u64,
        signals: Signals,
        pv: CounterPreset,
    ) -> Explained<S5CounterOutput> {
        let input = self.input(signals, pv);
        self.counter
            .explained(self.kind, CpuTime::from_millis(now), input)
    }

    fn explains(&self) -> bool {
        C::EXPLAINS
    }

    fn state(&self) -> S5CounterState {
        self.counter.state()
    }

    #[inline]
    fn values(&self, o: &S5CounterOutput) -> Outputs {
        Outputs::three(
            Value::Bool(o.q),
            Value::Int(i128::from(o.cv)),
            Value::Word(o.cv_bcd),
        )
    }

    fn ramp(&self, _: &S5CounterOutput) -> Option<u64> {
        None
    }

    fn reads(&self) -> &'static [Port] {
        &[Port::Cu, Port::Cd, Port::S, Port::R, Port::Fr]
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use plc_timers::catalog::ValueKind;

    /// `with` chooses the implementation and keeps the block and type.
    #[test]
    fn with_sets_the_implementation() {
        let spec = BlockSpec::parse("CTU", Some("usint")).expect("CTU of USINT");
        for i in [Implementation::Optimized, Implementation::Reference] {
            let chosen = spec.with(i);
            assert_eq!(chosen.implementation, i);
            assert_eq!((chosen.block, chosen.int_type), (spec.block, spec.int_type));
        }
    }

    /// Records what a visit saw.
    struct Probe;
    impl Visit for Probe {
        type Out = (Block, Vec<Value>, &'static [Port], PresetValue);
        fn visit<F: Adapter>(self, mut f: F) -> Self::Out {
            let block = f.block();
            let text = match block.preset().kind {
                PresetKind::S5Time => "S5T#10MS",
                PresetKind::Time => "T#10MS",
                PresetKind::Integer | PresetKind::S5Count => "1",
            };
            let p = f.parse_preset(text).expect("a valid preset");
            assert_eq!(
                f.preset(f.preset_value(p)),
                Ok(p),
                "{block}: the value round-trips"
            );
            let out = f.call(0, Signals::NONE, p);
            (
                block,
                f.values(&out).as_slice().to_vec(),
                f.reads(),
                f.preset_value(p),
            )
        }
    }

    /// Every block's adapter gives as many outputs as the catalog lists, of the catalog's kinds,
    /// reads every boolean input the catalog lists, and reads presets of the catalog's kind.
    #[test]
    fn adapters_follow_the_catalog() {
        for block in Block::ALL {
            for imp in [Implementation::Reference, Implementation::Optimized] {
                let (b, values, reads, preset) = dispatch(BlockSpec::new(block).with(imp), Probe);
                assert_eq!(b, block);
                let kinds: Vec<ValueKind> = values
                    .iter()
                    .map(|v| match v {
                        Value::Bool(_) => ValueKind::Bool,
                        Value::Int(_) => ValueKind::Int,
                        Value::Word(_) => ValueKind::Word,
                    })
                    .collect();
                let catalog: Vec<ValueKind> = block.outputs().iter().map(|p| p.kind()).collect();
                assert_eq!(kinds, catalog, "{block}");
                for port in block.inputs() {
                    assert_eq!(
                        port.kind() == ValueKind::Bool,
                        reads.contains(port),
                        "{block}: the adapter reads {port:?} exactly when it is a boolean input"
                    );
                }
                for port in block.coils() {
                    assert!(reads.contains(port), "{block}: the adapter reads {port:?}");
                    assert_eq!(port.kind(), ValueKind::Bool);
                }
                assert!(reads.iter().all(|p| p.kind() == ValueKind::Bool));
                assert_eq!(preset.kind(), block.preset().kind, "{block}");
                assert!(block.outputs().len() <= MAX_OUTPUTS);
            }
        }
    }

    /// A preset reads as the block's preset cell does, and prints as its literal; another
    /// kind's preset is refused with the block's.
    #[test]
    fn preset_values() {
        let spec = |b| BlockSpec::new(b);
        let tv = PresetValue::parse(spec(Block::SOffdt), "S5T#50ms").expect("a TV");
        assert_eq!(tv.to_string(), "S5T#50MS");
        let pt = PresetValue::parse(spec(Block::Ton), " T#500ms ").expect("a PT");
        assert_eq!(pt.to_string(), "T#500MS");
        assert_eq!(
            PresetValue::parse(spec(Block::Ctu), "4"),
            Ok(PresetValue::Integer(4))
        );
        assert_eq!(
            PresetValue::parse(spec(Block::SCu), "5").map(|v| v.to_string()),
            Ok("C#5".to_string())
        );
        let e = PresetValue::parse(spec(Block::Ctu), "40000").expect_err("beyond INT");
        assert!(e.contains("from -32768 to 32767"), "{e}");
        struct Convert(PresetValue);
        impl Visit for Convert {
            type Out = Result<(), String>;
            fn visit<F: Adapter>(self, f: F) -> Self::Out {
                f.preset(self.0).map(|_| ())
            }
        }
        let e = dispatch(spec(Block::Ton), Convert(tv)).expect_err("a TV is not a PT");
        assert_eq!(
            e,
            "S5T#50MS is not a preset of TON; its preset PT is a TIME"
        );
    }

    #[test]
    fn int_types_and_block_specs() {
        assert_eq!(
            IntType::names(),
            "SINT INT DINT LINT USINT UINT UDINT ULINT"
        );
        assert_eq!(IntType::lookup("udint"), Some(IntType::UDInt));
        assert_eq!(IntType::ULInt.limits(), (0, i128::from(u64::MAX)));
        assert_eq!(IntType::SInt.limits(), (-128, 127));
        assert_eq!(
            BlockSpec::parse("sd", None).map(|s| s.block),
            Ok(Block::SOdt)
        );
        let e = BlockSpec::parse("TON", Some("INT")).expect_err("no --type for TON");
        assert_eq!(e.location, Location::Option("type"));
        let e = BlockSpec::parse("CTU", Some("INT8")).expect_err("unknown type");
        assert!(e.message.contains("SINT INT DINT"), "{e}");
        let e = BlockSpec::parse("NOPE", None).expect_err("unknown block");
        assert!(e.message.contains("S_PULSE (SP)"), "{e}");
        assert_eq!(
            BlockSpec::parse("ctud", Some("ulint")).map(|s| s.int_type),
            Ok(IntType::ULInt)
        );
    }
}
