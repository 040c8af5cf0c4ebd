//! The block catalog: one table that names every block, its aliases, its family, its inputs,
//! outputs and preset. The command-line tool, the test vectors, the diagrams and the tests derive
//! their block lists from it, so a block is named in one place.
//!
//! ```
//! use plc_timers::catalog::{Block, Family, Port, ValueKind};
//!
//! let sd = Block::lookup("sd").expect("the STL alias of S_ODT");
//! assert_eq!((sd, sd.family()), (Block::SOdt, Family::S5Timer));
//! let names: Vec<&str> = sd.inputs().iter().map(|i| i.name()).collect();
//! assert_eq!(names, ["S", "R", "FR", "TV"]);
//! assert_eq!(sd.outputs()[2], Port::Bcd);
//! assert_eq!(sd.outputs()[2].kind(), ValueKind::Word);
//! assert_eq!(sd.preset().port, Port::Tv);
//! ```

use crate::counter::s5::S5CounterKind;
use crate::counter::CounterKind;
use crate::iec::IecKind;
use crate::s5::S5Kind;

/// The four families of blocks.
///
/// ```
/// use plc_timers::catalog::{Block, Family};
/// assert_eq!(Block::Tonr.family(), Family::IecTimer);
/// assert!(Family::S5Timer.is_timer() && !Family::S5Counter.is_timer());
/// ```
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Family {
    /// S5 timers of S7-300/400 ([`crate::s5`]).
    S5Timer,
    /// IEC timers of S7-1200/1500 ([`crate::iec`]).
    IecTimer,
    /// IEC counters over the integer types ([`crate::counter`]).
    IecCounter,
    /// S5 counters of S7-300/400 ([`crate::counter::s5`]).
    S5Counter,
}

impl Family {
    /// Whether the family's blocks need the CPU time (`t_ms`): the timers do.
    pub const fn is_timer(self) -> bool {
        matches!(self, Family::S5Timer | Family::IecTimer)
    }
}

/// What a preset is, and how it is written.
///
/// ```
/// use plc_timers::catalog::{Block, PresetKind};
/// assert_eq!(Block::SCu.preset().kind, PresetKind::S5Count);
/// ```
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum PresetKind {
    /// An S5TIME (`TV`): `S5T#…`, `S5TIME#…`, `W#16#…`.
    S5Time,
    /// A TIME (`PT`): `T#…`, `TIME#…`, whole milliseconds.
    Time,
    /// An IEC counter preset (`PV`): an integer of the counter's type.
    Integer,
    /// An S5 counter preset (`PV`): `C#0`..`C#999`, 0..=999, `W#16#0xyz`.
    S5Count,
}

/// What kind of value an input or output carries.
///
/// ```
/// use plc_timers::catalog::{Block, ValueKind};
/// let kinds: Vec<ValueKind> = Block::Ton.outputs().iter().map(|o| o.kind()).collect();
/// assert_eq!(kinds, [ValueKind::Bool, ValueKind::Int]);
/// ```
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum ValueKind {
    /// A boolean signal, written `0`/`1`.
    Bool,
    /// A preset (TV, PT, PV); what it is depends on the block ([`Block::preset`]).
    Preset,
    /// An integer (BI, ET, CV), written in decimal.
    Int,
    /// A 16-bit word (BCD, CV_BCD), written `W#16#XXXX`.
    Word,
}

macro_rules! ports {
    ($($port:ident = $name:literal, $kind:ident, $doc:literal;)*) => {
        /// An input or output of a block, named as the manual's box writes it. Code addresses
        /// a pin by this enum, so that a misspelt pin does not compile; only a reader of text
        /// (a CSV header) looks a name up.
        ///
        /// ```
        /// use plc_timers::catalog::{Block, Port, ValueKind};
        /// assert_eq!(Block::Tonr.inputs(), [Port::In, Port::R, Port::Pt]);
        /// assert_eq!((Port::CvBcd.name(), Port::CvBcd.kind()), ("CV_BCD", ValueKind::Word));
        /// assert!(Block::Tonr.has_input(Port::R) && !Block::Ton.has_input(Port::R));
        /// ```
        #[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, PartialOrd, Ord)]
        pub enum Port {
            $(
                #[doc = $doc]
                $port,
            )*
        }

        impl Port {
            /// Every port, the inputs (and the `RT` coil) first.
            pub const ALL: [Port; 19] = [$(Port::$port),*];

            /// The name as the manual's box writes it (`S`, `TV`, `IN`, `CV_BCD`, …).
            pub const fn name(self) -> &'static str {
                match self {
                    $(Port::$port => $name,)*
                }
            }

            /// The kind of value it carries.
            pub const fn kind(self) -> ValueKind {
                match self {
                    $(Port::$port => ValueKind::$kind,)*
                }
            }
        }
    };
}

ports! {
    S = "S", Bool, "`S`: start (S5 timers), set (S5 counters).";
    R = "R", Bool, "`R`: reset.";
    Fr = "FR", Bool, "`FR`: enable (STL `FR T n`, `FR C n`).";
    In = "IN", Bool, "`IN`: the IEC timers' input.";
    Cu = "CU", Bool, "`CU`: count up.";
    Cd = "CD", Bool, "`CD`: count down.";
    Ld = "LD", Bool, "`LD` (`LOAD`): load PV into CV.";
    Rt = "RT", Bool, "`RT`: the `-(RT)-` coil on the IEC timer's instance data (IEC-RT-01), run \
        before the box in the same scan; not a box input but one of the block's \
        [`Block::coils`], so a trace may leave its column out (absent means 0).";
    Tv = "TV", Preset, "`TV`: the S5 timers' time value (an S5TIME).";
    Pt = "PT", Preset, "`PT`: the IEC timers' preset time (a TIME).";
    Pv = "PV", Preset, "`PV`: the counters' preset value.";
    Q = "Q", Bool, "`Q`: the status output.";
    Qu = "QU", Bool, "`QU`: CTUD's up status (CV >= PV).";
    Qd = "QD", Bool, "`QD`: CTUD's down status (CV <= 0).";
    Bi = "BI", Int, "`BI` (`DUAL`): the S5 timers' remaining time value in binary.";
    Bcd = "BCD", Word, "`BCD` (`DEZ`): the S5 timers' remaining time with its base, in BCD.";
    Et = "ET", Int, "`ET`: the IEC timers' elapsed time (ms).";
    Cv = "CV", Int, "`CV`: the count.";
    CvBcd = "CV_BCD", Word, "`CV_BCD`: the S5 counters' count in BCD.";
}

/// A preset input and the kind of value it takes.
///
/// ```
/// use plc_timers::catalog::{Block, Port, PresetKind};
/// let pt = Block::Tp.preset();
/// assert_eq!((pt.port, pt.kind), (Port::Pt, PresetKind::Time));
/// ```
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub struct Preset {
    /// The input (`TV`, `PT`, `PV`).
    pub port: Port,
    /// What it is.
    pub kind: PresetKind,
}

use Port::{Bcd, Bi, Cd, Cu, Cv, CvBcd, Et, Fr, In, Ld, Pt, Pv, Qd, Qu, Rt, Tv, Q, R, S};

const S5_TIMER_IN: &[Port] = &[S, R, Fr, Tv];
const IEC_TIMER_IN: &[Port] = &[In, Pt];
const TONR_IN: &[Port] = &[In, R, Pt];
const IEC_TIMER_COILS: &[Port] = &[Rt];
const CTU_IN: &[Port] = &[Cu, R, Pv];
const CTD_IN: &[Port] = &[Cd, Ld, Pv];
const CTUD_IN: &[Port] = &[Cu, Cd, R, Ld, Pv];
const S_CU_IN: &[Port] = &[Cu, S, R, Fr, Pv];
const S_CD_IN: &[Port] = &[Cd, S, R, Fr, Pv];
const S_CUD_IN: &[Port] = &[Cu, Cd, S, R, Fr, Pv];

const S5_TIMER_OUT: &[Port] = &[Q, Bi, Bcd];
const IEC_TIMER_OUT: &[Port] = &[Q, Et];
const CTU_CTD_OUT: &[Port] = &[Q, Cv];
const CTUD_OUT: &[Port] = &[Qu, Qd, Cv];
const S5_COUNTER_OUT: &[Port] = &[Q, Cv, CvBcd];

/// Every block of the crate.
///
/// ```
/// use plc_timers::catalog::Block;
/// let names: Vec<&str> = Block::ALL.iter().map(|b| b.name()).collect();
/// assert_eq!(names[..5], ["S_PULSE", "S_PEXT", "S_ODT", "S_ODTS", "S_OFFDT"]);
/// assert_eq!(Block::lookup("ctud"), Some(Block::Ctud));
/// assert_eq!(Block::lookup("SE"), Some(Block::SPext)); // English SE, not German SE
/// assert_eq!(Block::lookup("nope"), None);
/// ```
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub enum Block {
    /// `S_PULSE` (STL `SP`, German `SI`).
    SPulse,
    /// `S_PEXT` (STL `SE`, German `SV`).
    SPext,
    /// `S_ODT` (STL `SD`, German `SE`).
    SOdt,
    /// `S_ODTS` (STL `SS`).
    SOdts,
    /// `S_OFFDT` (STL `SF`, German `SA`).
    SOffdt,
    /// `TP`.
    Tp,
    /// `TON`.
    Ton,
    /// `TOF`.
    Tof,
    /// `TONR`.
    Tonr,
    /// `CTU`.
    Ctu,
    /// `CTD`.
    Ctd,
    /// `CTUD`.
    Ctud,
    /// `S_CU` (German `Z_VORW`).
    SCu,
    /// `S_CD` (German `Z_RUECK`).
    SCd,
    /// `S_CUD` (German `ZAEHLER`).
    SCud,
}

impl Block {
    /// Every block, family by family, in manual order.
    pub const ALL: [Block; 15] = [
        Block::SPulse,
        Block::SPext,
        Block::SOdt,
        Block::SOdts,
        Block::SOffdt,
        Block::Tp,
        Block::Ton,
        Block::Tof,
        Block::Tonr,
        Block::Ctu,
        Block::Ctd,
        Block::Ctud,
        Block::SCu,
        Block::SCd,
        Block::SCud,
    ];

    /// The canonical (box) name.
    pub const fn name(self) -> &'static str {
        match self.kind() {
            Kind::S5Timer(k) => k.name(),
            Kind::IecTimer(k) => k.name(),
            Kind::IecCounter(k) => k.name(),
            Kind::S5Counter(k) => k.name(),
        }
    }

    /// Other names the command line accepts: the international STL mnemonics of the S5
    /// timers (`SP`, `SE`, `SD`, `SS`, `SF`). The German mnemonics are not accepted, since
    /// German `SE` is the international `SD`.
    pub const fn aliases(self) -> &'static [&'static str] {
        match self {
            Block::SPulse => &["SP"],
            Block::SPext => &["SE"],
            Block::SOdt => &["SD"],
            Block::SOdts => &["SS"],
            Block::SOffdt => &["SF"],
            _ => &[],
        }
    }

    /// The block called `name` or one of its aliases, ignoring ASCII case.
    pub fn lookup(name: &str) -> Option<Block> {
        Block::ALL.into_iter().find(|b| {
            b.name().eq_ignore_ascii_case(name)
                || b.aliases().iter().any(|a| a.eq_ignore_ascii_case(name))
        })
    }

    /// The block's family.
    pub const fn family(self) -> Family {
        match self.kind() {
            Kind::S5Timer(_) => Family::S5Timer,
            Kind::IecTimer(_) => Family::IecTimer,
            Kind::IecCounter(_) => Family::IecCounter,
            Kind::S5Counter(_) => Family::S5Counter,
        }
    }

    /// The block as its family's kind.
    pub const fn kind(self) -> Kind {
        match self {
            Block::SPulse => Kind::S5Timer(S5Kind::SPulse),
            Block::SPext => Kind::S5Timer(S5Kind::SPext),
            Block::SOdt => Kind::S5Timer(S5Kind::SOdt),
            Block::SOdts => Kind::S5Timer(S5Kind::SOdts),
            Block::SOffdt => Kind::S5Timer(S5Kind::SOffdt),
            Block::Tp => Kind::IecTimer(IecKind::Tp),
            Block::Ton => Kind::IecTimer(IecKind::Ton),
            Block::Tof => Kind::IecTimer(IecKind::Tof),
            Block::Tonr => Kind::IecTimer(IecKind::Tonr),
            Block::Ctu => Kind::IecCounter(CounterKind::Ctu),
            Block::Ctd => Kind::IecCounter(CounterKind::Ctd),
            Block::Ctud => Kind::IecCounter(CounterKind::Ctud),
            Block::SCu => Kind::S5Counter(S5CounterKind::SCu),
            Block::SCd => Kind::S5Counter(S5CounterKind::SCd),
            Block::SCud => Kind::S5Counter(S5CounterKind::SCud),
        }
    }

    /// The inputs, in the order the catalog lists them (booleans first, the preset last);
    /// `t_ms` is not among them.
    pub const fn inputs(self) -> &'static [Port] {
        match self {
            Block::SPulse | Block::SPext | Block::SOdt | Block::SOdts | Block::SOffdt => {
                S5_TIMER_IN
            }
            Block::Tp | Block::Ton | Block::Tof => IEC_TIMER_IN,
            Block::Tonr => TONR_IN,
            Block::Ctu => CTU_IN,
            Block::Ctd => CTD_IN,
            Block::Ctud => CTUD_IN,
            Block::SCu => S_CU_IN,
            Block::SCd => S_CD_IN,
            Block::SCud => S_CUD_IN,
        }
    }

    /// The coils that act on the block's instance data, besides its box inputs: `[RT]` for the
    /// IEC timers (the `-(RT)-` coil, IEC-RT-01), none for the other blocks. A trace may carry
    /// a column for each (absent means 0); a row with a coil at 1 runs the coil before the box
    /// call, as a network above the box's network would. They are not among
    /// [`Block::inputs`], which are the box's own.
    ///
    /// ```
    /// use plc_timers::catalog::{Block, Port};
    /// assert_eq!(Block::Tof.coils(), [Port::Rt]);
    /// assert!(!Block::Tof.has_input(Port::Rt)); // a coil, not a box input
    /// assert!(Block::SOdt.coils().is_empty() && Block::Ctu.coils().is_empty());
    /// ```
    pub const fn coils(self) -> &'static [Port] {
        match self.family() {
            Family::IecTimer => IEC_TIMER_COILS,
            _ => &[],
        }
    }

    /// The outputs, in output order.
    pub const fn outputs(self) -> &'static [Port] {
        match self.family() {
            Family::S5Timer => S5_TIMER_OUT,
            Family::IecTimer => IEC_TIMER_OUT,
            Family::IecCounter => match self {
                Block::Ctud => CTUD_OUT,
                _ => CTU_CTD_OUT,
            },
            Family::S5Counter => S5_COUNTER_OUT,
        }
    }

    /// The preset input and its kind (every block has one).
    pub const fn preset(self) -> Preset {
        let (port, kind) = match self.family() {
            Family::S5Timer => (Tv, PresetKind::S5Time),
            Family::IecTimer => (Pt, PresetKind::Time),
            Family::IecCounter => (Pv, PresetKind::Integer),
            Family::S5Counter => (Pv, PresetKind::S5Count),
        };
        Preset { port, kind }
    }

    /// The data types the block runs on: S5TIME for the S5 timers, TIME and LTIME for the IEC
    /// timers, the eight integer types for the IEC counters, WORD for the S5 counters.
    pub const fn data_types(self) -> &'static [DataType] {
        match self.family() {
            Family::S5Timer => S5_TIMER_TYPES,
            Family::IecTimer => IEC_TIMER_TYPES,
            Family::IecCounter => IEC_COUNTER_TYPES,
            Family::S5Counter => S5_COUNTER_TYPES,
        }
    }

    /// The data type taken when none is selected: INT for the IEC counters (TIA Portal's
    /// default), TIME for the IEC timers, the only one for the S5 blocks.
    pub const fn default_data_type(self) -> DataType {
        match self.family() {
            Family::IecCounter => DataType::Int,
            _ => self.data_types()[0],
        }
    }

    /// Whether `port` is one of the block's inputs.
    pub const fn has_input(self, port: Port) -> bool {
        let inputs = self.inputs();
        let mut i = 0;
        while i < inputs.len() {
            if inputs[i] as u8 == port as u8 {
                return true;
            }
            i += 1;
        }
        false
    }

    /// Whether a trace of this block needs the CPU time (`t_ms`).
    pub const fn requires_time(self) -> bool {
        self.family().is_timer()
    }
}

/// The data type an instruction runs on, as TIA Portal selects it below the box (`TON` of
/// `LTIME`, `CTU` of `DINT`); [`Block::data_types`] lists a block's,
/// [`Block::default_data_type`] names the one taken when none is selected.
///
/// ```
/// use plc_timers::catalog::{Block, DataType};
/// assert_eq!(Block::Tof.data_types(), [DataType::Time, DataType::LTime]);
/// assert_eq!(DataType::lookup("ltime"), Some(DataType::LTime));
/// assert_eq!(Block::Ctud.default_data_type(), DataType::Int);
/// ```
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub enum DataType {
    /// `S5TIME`: the S5 timers' time value (their only type).
    S5Time,
    /// `WORD`: the S5 counters' count value, three BCD digits (their only type).
    Word,
    /// `TIME`: signed 32-bit ms, the `IEC_TIMER` (S7-1200/1500).
    Time,
    /// `LTIME`: signed 64-bit ns, the `IEC_LTIMER` (S7-1500).
    LTime,
    /// `SINT`: 8-bit signed.
    SInt,
    /// `INT`: 16-bit signed.
    Int,
    /// `DINT`: 32-bit signed.
    DInt,
    /// `LINT`: 64-bit signed.
    LInt,
    /// `USINT`: 8-bit unsigned.
    USInt,
    /// `UINT`: 16-bit unsigned.
    UInt,
    /// `UDINT`: 32-bit unsigned.
    UDInt,
    /// `ULINT`: 64-bit unsigned.
    ULInt,
}

const S5_TIMER_TYPES: &[DataType] = &[DataType::S5Time];
const S5_COUNTER_TYPES: &[DataType] = &[DataType::Word];
const IEC_TIMER_TYPES: &[DataType] = &[DataType::Time, DataType::LTime];
const IEC_COUNTER_TYPES: &[DataType] = &[
    DataType::SInt,
    DataType::Int,
    DataType::DInt,
    DataType::LInt,
    DataType::USInt,
    DataType::UInt,
    DataType::UDInt,
    DataType::ULInt,
];

impl DataType {
    /// Every data type.
    pub const ALL: [DataType; 12] = [
        DataType::S5Time,
        DataType::Word,
        DataType::Time,
        DataType::LTime,
        DataType::SInt,
        DataType::Int,
        DataType::DInt,
        DataType::LInt,
        DataType::USInt,
        DataType::UInt,
        DataType::UDInt,
        DataType::ULInt,
    ];

    /// The name as the manual writes it.
    pub const fn name(self) -> &'static str {
        match self {
            DataType::S5Time => "S5TIME",
            DataType::Word => "WORD",
            DataType::Time => "TIME",
            DataType::LTime => "LTIME",
            DataType::SInt => "SINT",
            DataType::Int => "INT",
            DataType::DInt => "DINT",
            DataType::LInt => "LINT",
            DataType::USInt => "USINT",
            DataType::UInt => "UINT",
            DataType::UDInt => "UDINT",
            DataType::ULInt => "ULINT",
        }
    }

    /// The data type called `name` (ASCII case ignored).
    pub fn lookup(name: &str) -> Option<DataType> {
        DataType::ALL
            .into_iter()
            .find(|t| t.name().eq_ignore_ascii_case(name))
    }
}

impl core::fmt::Display for DataType {
    fn fmt(&self, f: &mut core::fmt::Formatter<'_>) -> core::fmt::Result {
        f.write_str(self.name())
    }
}

/// A block as the kind enum of its family: what the family's `call` takes.
///
/// ```
/// use plc_timers::catalog::{Block, Kind};
/// use plc_timers::iec::IecKind;
/// assert_eq!(Block::Tof.kind(), Kind::IecTimer(IecKind::Tof));
/// ```
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Kind {
    /// An S5 timer.
    S5Timer(S5Kind),
    /// An IEC timer.
    IecTimer(IecKind),
    /// An IEC counter.
    IecCounter(CounterKind),
    /// An S5 counter.
    S5Counter(S5CounterKind),
}

impl core::fmt::Display for Block {
    fn fmt(&self, f: &mut core::fmt::Formatter<'_>) -> core::fmt::Result {
        f.write_str(self.name())
    }
}
