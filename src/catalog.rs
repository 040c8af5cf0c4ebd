//! The block catalog: one table that names every block, its aliases, its family, its inputs,
//! outputs and preset. The command-line tool, the test vectors, the diagrams and the tests derive
//! their block lists from it, so a block is named in one place.
//!
//! ```
//! use plc_timers::catalog::{Block, Family, ValueKind};
//!
//! let sd = Block::lookup("sd").expect("the STL alias of S_ODT");
//! assert_eq!((sd, sd.family()), (Block::SOdt, Family::S5Timer));
//! let names: Vec<&str> = sd.inputs().iter().map(|i| i.name).collect();
//! assert_eq!(names, ["S", "R", "FR", "TV"]);
//! assert_eq!(sd.outputs()[2].name, "BCD");
//! assert_eq!(sd.outputs()[2].kind, ValueKind::Word);
//! assert_eq!(sd.preset().map(|p| p.option), Some("tv"));
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
/// assert_eq!(Block::SCu.preset().map(|p| p.kind), Some(PresetKind::S5Count));
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
/// let kinds: Vec<ValueKind> = Block::Ton.outputs().iter().map(|o| o.kind).collect();
/// assert_eq!(kinds, [ValueKind::Bool, ValueKind::Int]);
/// ```
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum ValueKind {
    /// A boolean signal, written `0`/`1`.
    Bool,
    /// A preset (TV, PT, PV).
    Preset(PresetKind),
    /// An integer (BI, ET, CV), written in decimal.
    Int,
    /// A 16-bit word (BCD, CV_BCD), written `W#16#XXXX`.
    Word,
}

/// One input or output of a block.
///
/// ```
/// use plc_timers::catalog::{Block, ValueKind};
/// let r = Block::Tonr.inputs()[1];
/// assert_eq!((r.name, r.kind), ("R", ValueKind::Bool));
/// ```
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub struct Port {
    /// The name as the manual's box writes it (`S`, `TV`, `IN`, `PT`, `CU`, `Q`, `ET`, …).
    pub name: &'static str,
    /// Its kind.
    pub kind: ValueKind,
}

/// A preset input and how the command line may give it for every row.
///
/// ```
/// use plc_timers::catalog::{Block, PresetKind};
/// let pt = Block::Tp.preset().expect("every block has a preset");
/// assert_eq!((pt.name, pt.option, pt.kind), ("PT", "pt", PresetKind::Time));
/// ```
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub struct Preset {
    /// The input's name (`TV`, `PT`, `PV`).
    pub name: &'static str,
    /// The command-line option without dashes (`tv`, `pt`, `pv`).
    pub option: &'static str,
    /// What it is.
    pub kind: PresetKind,
}

const fn b(name: &'static str) -> Port {
    Port {
        name,
        kind: ValueKind::Bool,
    }
}

const fn p(name: &'static str, kind: PresetKind) -> Port {
    Port {
        name,
        kind: ValueKind::Preset(kind),
    }
}

const fn o(name: &'static str, kind: ValueKind) -> Port {
    Port { name, kind }
}

const TV: Port = p("TV", PresetKind::S5Time);
const PT: Port = p("PT", PresetKind::Time);
const PV_INT: Port = p("PV", PresetKind::Integer);
const PV_S5: Port = p("PV", PresetKind::S5Count);

const S5_TIMER_IN: &[Port] = &[b("S"), b("R"), b("FR"), TV];
const IEC_TIMER_IN: &[Port] = &[b("IN"), PT];
const TONR_IN: &[Port] = &[b("IN"), b("R"), PT];
const CTU_IN: &[Port] = &[b("CU"), b("R"), PV_INT];
const CTD_IN: &[Port] = &[b("CD"), b("LD"), PV_INT];
const CTUD_IN: &[Port] = &[b("CU"), b("CD"), b("R"), b("LD"), PV_INT];
const S_CU_IN: &[Port] = &[b("CU"), b("S"), b("R"), b("FR"), PV_S5];
const S_CD_IN: &[Port] = &[b("CD"), b("S"), b("R"), b("FR"), PV_S5];
const S_CUD_IN: &[Port] = &[b("CU"), b("CD"), b("S"), b("R"), b("FR"), PV_S5];

const S5_TIMER_OUT: &[Port] = &[
    o("Q", ValueKind::Bool),
    o("BI", ValueKind::Int),
    o("BCD", ValueKind::Word),
];
const IEC_TIMER_OUT: &[Port] = &[o("Q", ValueKind::Bool), o("ET", ValueKind::Int)];
const CTU_CTD_OUT: &[Port] = &[o("Q", ValueKind::Bool), o("CV", ValueKind::Int)];
const CTUD_OUT: &[Port] = &[
    o("QU", ValueKind::Bool),
    o("QD", ValueKind::Bool),
    o("CV", ValueKind::Int),
];
const S5_COUNTER_OUT: &[Port] = &[
    o("Q", ValueKind::Bool),
    o("CV", ValueKind::Int),
    o("CV_BCD", ValueKind::Word),
];

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

    /// The preset input and its command-line option. Every block has one.
    pub const fn preset(self) -> Option<Preset> {
        let inputs = self.inputs();
        let mut i = 0;
        while i < inputs.len() {
            if let ValueKind::Preset(kind) = inputs[i].kind {
                let option = match kind {
                    PresetKind::S5Time => "tv",
                    PresetKind::Time => "pt",
                    PresetKind::Integer | PresetKind::S5Count => "pv",
                };
                return Some(Preset {
                    name: inputs[i].name,
                    option,
                    kind,
                });
            }
            i += 1;
        }
        None
    }

    /// The position of the input called `name` (exact, upper-case) in [`Block::inputs`].
    pub fn input_index(self, name: &str) -> Option<usize> {
        self.inputs().iter().position(|i| i.name == name)
    }

    /// Whether a trace of this block needs the CPU time (`t_ms`).
    pub const fn requires_time(self) -> bool {
        self.family().is_timer()
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
