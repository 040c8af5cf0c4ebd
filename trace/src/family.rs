//! A block as a front end asks for it: the instruction (block and data type, the core's
//! [`Instruction`]) and the implementation, with the parsers of the command line's names. The
//! families themselves are the core's: [`BlockSpec::visit`] hands a fresh instance of the
//! chosen implementation to a [`Visit`]or, generic over [`BlockOps`], so the engine is written
//! once for every block, data type and implementation.

use plc_timers::block::{BlockOps, Instruction, Visit};
use plc_timers::catalog::{Block, DataType};

use super::error::{show, Location, TraceError};

pub use plc_timers::block::{Implementation, Outputs, Signals, Value, MAX_OUTPUTS};

/// A block as the command line asks for it: the instruction and the implementation to drive.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct BlockSpec {
    /// The block with its data type (`TON` of `LTIME`, `CTU` of `DINT`).
    pub instruction: Instruction,
    /// The implementation to drive.
    pub implementation: Implementation,
}

impl BlockSpec {
    /// The reference of `block` on its default data type (TIME for an IEC timer, INT for an
    /// IEC counter).
    pub fn new(block: Block) -> BlockSpec {
        BlockSpec {
            instruction: Instruction::of(block),
            implementation: Implementation::Reference,
        }
    }

    /// The block.
    pub fn block(self) -> Block {
        self.instruction.block()
    }

    /// The data type.
    pub fn data_type(self) -> DataType {
        self.instruction.data_type()
    }

    /// The block called `name` (case-insensitive, aliases and instance-type names such as
    /// `TON_LTIME` accepted), with `--type`: the checks of the command line's parser, for a
    /// command read from text (the examples, the Python package).
    pub fn parse(name: &str, data_type: Option<&str>) -> Result<BlockSpec, TraceError> {
        let (block, named) =
            parse_instruction(name).map_err(|e| TraceError::new(Location::Command, e))?;
        let option = |e| TraceError::new(Location::Option("type"), e);
        let data_type = data_type.map(parse_data_type).transpose().map_err(option)?;
        BlockSpec::typed(block, merge_data_types(named, data_type).map_err(option)?).map_err(option)
    }

    /// `block` on `data_type` (its default when `None`); the error lists what the block takes.
    pub fn typed(block: Block, data_type: Option<DataType>) -> Result<BlockSpec, String> {
        let instruction = match data_type {
            Some(t) => Instruction::new(block, t).map_err(|e| e.to_string())?,
            None => Instruction::of(block),
        };
        Ok(BlockSpec {
            instruction,
            implementation: Implementation::Reference,
        })
    }

    /// This spec with `implementation`.
    pub fn with(self, implementation: Implementation) -> BlockSpec {
        BlockSpec {
            implementation,
            ..self
        }
    }

    /// Hands a fresh instance of this spec's implementation to `v` ([`Instruction::visit`]).
    pub fn visit<V: Visit>(self, v: V) -> V::Out {
        self.instruction.visit(self.implementation, v)
    }

    /// The name of the time column: `t_` and the unit of the block's clock (`t_ms`; `t_ns` on
    /// LTIME).
    pub fn time_column(self) -> &'static str {
        time_column(self.instruction.clock_unit())
    }

    /// The preset `text` read as the block's preset cell is, written back as its literal
    /// (`S5T#50MS`, `T#500MS`, `LT#1MS_500US`, `4`, `C#5`); the error says what the block's
    /// preset may be.
    ///
    /// ```
    /// use plc_timers::catalog::{Block, DataType};
    /// use plc_timers_trace::BlockSpec;
    /// let ton = BlockSpec::typed(Block::Ton, Some(DataType::LTime)).expect("TON takes LTIME");
    /// assert_eq!(ton.preset_literal(" LT#1ms500us ").as_deref(), Ok("LT#1MS_500US"));
    /// assert!(BlockSpec::new(Block::Ctu).preset_literal("40000").is_err());
    /// ```
    pub fn preset_literal(self, text: &str) -> Result<String, String> {
        struct V<'a>(&'a str);
        impl Visit for V<'_> {
            type Out = Result<String, String>;
            fn visit<B: BlockOps>(self, _: B, _: B::Kind) -> Self::Out {
                parse_preset::<B>(self.0).map(|p| p.to_string())
            }
        }
        self.visit(V(text))
    }
}

/// The time column of a clock in `unit` (`ms`, `ns`).
pub fn time_column(unit: &str) -> &'static str {
    match unit {
        "ns" => "t_ns",
        _ => "t_ms",
    }
}

/// Every time column a trace may have, whichever block it is for.
pub const TIME_COLUMNS: [&str; 2] = ["t_ms", "t_ns"];

/// `named` (from an instance-type name such as `TON_LTIME`) and `option` (from `--type`) as
/// one data type; they must agree when both are given.
pub fn merge_data_types(
    named: Option<DataType>,
    option: Option<DataType>,
) -> Result<Option<DataType>, String> {
    match (named, option) {
        (Some(a), Some(b)) if a != b => Err(format!(
            "the instance type names the data type {a}; --type {b} contradicts it"
        )),
        (a, b) => Ok(a.or(b)),
    }
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

/// The block called `name` (ASCII case ignored, aliases accepted), or the error that lists the
/// blocks.
pub fn parse_block(name: &str) -> Result<Block, String> {
    parse_instruction(name).map(|(block, _)| block)
}

/// The block called `name`, or named by its instance type as TIA Portal writes it: the block,
/// `_` and one of its data types (`TON_LTIME`, `TP_TIME`, `CTU_DINT`), which gives the data
/// type too (the value parser of the command line's block).
///
/// ```
/// use plc_timers::catalog::{Block, DataType};
/// use plc_timers_trace::family::parse_instruction;
/// assert_eq!(parse_instruction("ton_ltime"), Ok((Block::Ton, Some(DataType::LTime))));
/// assert_eq!(parse_instruction("SD"), Ok((Block::SOdt, None)));
/// assert!(parse_instruction("CTU_LTIME").is_err());
/// ```
pub fn parse_instruction(name: &str) -> Result<(Block, Option<DataType>), String> {
    if let Some(block) = Block::lookup(name) {
        return Ok((block, None));
    }
    let typed = name.rsplit_once('_').and_then(|(b, t)| {
        let block = Block::lookup(b)?;
        let data_type = DataType::lookup(t)?;
        block
            .data_types()
            .contains(&data_type)
            .then_some((block, Some(data_type)))
    });
    typed.ok_or_else(|| {
        format!(
            "unknown block `{}`; the blocks are {}",
            show(name.as_bytes()),
            block_names()
        )
    })
}

/// The data type called `name` (ASCII case ignored), or the error that lists the data types
/// `--type` takes (the value parser of `--type`).
pub fn parse_data_type(name: &str) -> Result<DataType, String> {
    DataType::lookup(name).ok_or_else(|| {
        let names: Vec<&str> = Block::ALL
            .iter()
            .filter(|b| b.data_types().len() > 1)
            .flat_map(|b| b.data_types())
            .fold(Vec::new(), |mut v, t| {
                if !v.contains(&t.name()) {
                    v.push(t.name());
                }
                v
            });
        format!(
            "unknown data type `{}`; --type takes {}",
            show(name.as_bytes()),
            names.join(" ")
        )
    })
}

/// The preset of `B` parsed from `text`; the error says what is allowed.
pub(crate) fn parse_preset<B: BlockOps>(text: &str) -> Result<B::Preset, String> {
    B::parse_preset(text).map_err(|e| e.to_string())
}

#[cfg(test)]
mod tests {
    use super::*;
    use plc_timers::catalog::{Port, PresetKind, ValueKind};
    use plc_timers::time::CpuTime;

    /// `with` chooses the implementation and keeps the instruction.
    #[test]
    fn with_sets_the_implementation() {
        let spec = BlockSpec::parse("CTU", Some("usint")).expect("CTU of USINT");
        for i in [Implementation::Optimized, Implementation::Reference] {
            let chosen = spec.with(i);
            assert_eq!(chosen.implementation, i);
            assert_eq!(chosen.instruction, spec.instruction);
        }
    }

    /// Records what a visit saw: the block's outputs from one call with no input at 1.
    struct Probe(&'static str);
    impl Visit for Probe {
        type Out = Vec<Value>;
        fn visit<B: BlockOps>(self, mut b: B, kind: B::Kind) -> Self::Out {
            let p = parse_preset::<B>(self.0).expect("a valid preset");
            let out = b.step(kind, CpuTime::from_ticks(0), Signals::NONE, p);
            B::values(kind, &out).as_slice().to_vec()
        }
    }

    /// Every instruction gives as many outputs as the catalog lists, of the catalog's kinds.
    #[test]
    fn outputs_follow_the_catalog() {
        for block in Block::ALL {
            for &t in block.data_types() {
                for imp in [Implementation::Reference, Implementation::Optimized] {
                    let spec = BlockSpec::typed(block, Some(t)).expect("a type of the block");
                    let preset = match block.preset().kind {
                        PresetKind::S5Time => "S5T#10MS",
                        _ => "1",
                    };
                    let values = spec.with(imp).visit(Probe(preset));
                    let kinds: Vec<ValueKind> = values
                        .iter()
                        .map(|v| match v {
                            Value::Bool(_) => ValueKind::Bool,
                            Value::Int(_) => ValueKind::Int,
                            Value::Word(_) => ValueKind::Word,
                        })
                        .collect();
                    let catalog: Vec<ValueKind> =
                        block.outputs().iter().map(|p| p.kind()).collect();
                    assert_eq!(kinds, catalog, "{block} {t}");
                    assert!(block.outputs().len() <= MAX_OUTPUTS);
                    assert!(block.coils().iter().all(|p| p.kind() == ValueKind::Bool));
                    assert!(!block.inputs().contains(&Port::Rt));
                }
            }
        }
    }

    /// A preset reads as the block's preset cell does, and prints as its literal.
    #[test]
    fn preset_literals() {
        let lit = |b, text| BlockSpec::new(b).preset_literal(text);
        assert_eq!(lit(Block::SOffdt, "S5T#50ms").as_deref(), Ok("S5T#50MS"));
        assert_eq!(lit(Block::Ton, " T#500ms ").as_deref(), Ok("T#500MS"));
        assert_eq!(lit(Block::Ctu, "4").as_deref(), Ok("4"));
        assert_eq!(lit(Block::SCu, "5").as_deref(), Ok("C#5"));
        let e = lit(Block::Ctu, "40000").expect_err("beyond INT");
        assert!(e.contains("from -32768 to 32767"), "{e}");
        let e = lit(Block::Ton, "LT#1S").expect_err("an LTIME literal is no TIME");
        assert!(!e.is_empty());
    }

    #[test]
    fn data_types_and_block_specs() {
        assert_eq!(
            BlockSpec::parse("sd", None).map(|s| s.block()),
            Ok(Block::SOdt)
        );
        let e = BlockSpec::parse("TON", Some("INT")).expect_err("TON takes no INT");
        assert_eq!(e.location, Location::Option("type"));
        assert_eq!(
            e.message,
            "TON does not take the data type INT; it takes TIME LTIME"
        );
        let e = BlockSpec::parse("CTU", Some("INT8")).expect_err("unknown type");
        assert!(e.message.contains("TIME LTIME SINT INT DINT"), "{e}");
        let e = BlockSpec::parse("NOPE", None).expect_err("unknown block");
        assert!(e.message.contains("S_PULSE (SP)"), "{e}");
        assert_eq!(
            BlockSpec::parse("ctud", Some("ulint")).map(|s| s.data_type()),
            Ok(DataType::ULInt)
        );
        for (name, t) in [
            ("TON_LTIME", Some("ltime")),
            ("tp_ltime", None),
            ("TOF", Some("LTIME")),
        ] {
            let spec = BlockSpec::parse(name, t).expect("an LTIME timer");
            assert_eq!(spec.data_type(), DataType::LTime, "{name}");
            assert_eq!(spec.time_column(), "t_ns");
        }
        let e = BlockSpec::parse("TON_LTIME", Some("TIME")).expect_err("contradicts");
        assert!(e.message.contains("contradicts"), "{e}");
        assert_eq!(BlockSpec::new(Block::Ton).time_column(), "t_ms");
    }
}
