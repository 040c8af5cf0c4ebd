//! The example traces of `examples/traces/`, embedded when the engine is built. The first line of
//! each is the command that runs it, exactly as the README writes it
//! (`# cargo run --release -- run TON --pt T#500ms examples/traces/ton.csv`); the block, its
//! preset and the file are read from that line, so the examples name their own settings.

use plc_timers::block::Instruction;
use plc_timers::catalog::Block;

use super::family::BlockSpec;

mod files {
    include!(concat!(env!("OUT_DIR"), "/examples.rs"));
}

/// How each example's first line begins.
pub const COMMAND_PREFIX: &str = "# cargo run --release -- ";

/// The directory of the examples, from the repository's root.
pub const DIR: &str = "examples/traces";

/// One example trace.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Example {
    /// The file stem (`ton`).
    pub stem: &'static str,
    /// The command of its first line, after `cargo run --release -- ` (`run TON --pt T#500ms
    /// examples/traces/ton.csv`).
    pub command: &'static str,
    /// The block and `--type`.
    pub spec: BlockSpec,
    /// The preset as the command writes it (`T#500ms`), if the command gives one; checked to
    /// be one of the block's.
    pub preset: Option<&'static str>,
    /// The whole text.
    pub text: &'static str,
}

/// Reads an example's first line.
fn parse(stem: &'static str, text: &'static str) -> Result<Example, String> {
    let first = text.lines().next().unwrap_or_default();
    let command = first
        .strip_prefix(COMMAND_PREFIX)
        .ok_or_else(|| format!("{stem}.csv: the first line must start with `{COMMAND_PREFIX}`"))?;
    let words: Vec<&'static str> = command.split_whitespace().collect();
    let [run, block, rest @ ..] = words.as_slice() else {
        return Err(format!("{stem}.csv: `{command}` is not `run BLOCK …`"));
    };
    let file = format!("{DIR}/{stem}.csv");
    if *run != "run" || rest.last() != Some(&file.as_str()) {
        return Err(format!(
            "{stem}.csv: `{command}` must be `run BLOCK … {file}`"
        ));
    }
    let mut preset_text = None;
    let mut int_type = None;
    let options = &rest[..rest.len() - 1];
    for pair in options.chunks(2) {
        match pair {
            ["--type", t] => int_type = Some(*t),
            [o, v] if o.starts_with("--") => preset_text = Some((&o[2..], *v)),
            _ => {
                return Err(format!(
                    "{stem}.csv: cannot read the options of `{command}`"
                ))
            }
        }
    }
    let spec = BlockSpec::parse(block, int_type).map_err(|e| format!("{stem}.csv: {e}"))?;
    let option = super::engine::preset_option(spec.block());
    let preset = match preset_text {
        Some((o, _)) if o != option => {
            return Err(format!(
                "{stem}.csv: {} takes --{option}, not --{o}",
                spec.block()
            ))
        }
        Some((_, v)) => {
            spec.preset_literal(v)
                .map_err(|e| format!("{stem}.csv: --{option} {v}: {e}"))?;
            Some(v)
        }
        None => None,
    };
    Ok(Example {
        stem,
        command,
        spec,
        preset,
        text,
    })
}

/// Every example, in file order.
pub fn all() -> Result<Vec<Example>, String> {
    files::FILES
        .iter()
        .map(|&(stem, text)| parse(stem, text))
        .collect()
}

/// The example of `block` on its default data type.
pub fn of(block: Block) -> Option<Example> {
    of_instruction(Instruction::of(block))
}

/// The example of `instruction`, if it has one (every block on its default data type has).
pub fn of_instruction(instruction: Instruction) -> Option<Example> {
    all()
        .ok()?
        .into_iter()
        .find(|e| e.spec.instruction == instruction)
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Every catalog block has exactly one example on its default data type, named after it,
    /// whose first line is its command and gives its preset; an example on another data type
    /// is named after the block and the type (`ton_ltime`).
    #[test]
    fn one_example_per_block() {
        let all = all().expect("every example's first line is its command");
        for block in Block::ALL {
            let mine: Vec<&Example> = all
                .iter()
                .filter(|e| e.spec.instruction == Instruction::of(block))
                .collect();
            assert_eq!(mine.len(), 1, "{block}");
            assert_eq!(mine[0].stem, block.name().to_ascii_lowercase());
            assert!(mine[0].preset.is_some(), "{block}");
        }
        for e in &all {
            let i = e.spec.instruction;
            let stem = if i == Instruction::of(i.block()) {
                i.block().name().to_ascii_lowercase()
            } else {
                format!("{}_{}", i.block().name(), i.data_type().name()).to_ascii_lowercase()
            };
            assert_eq!(e.stem, stem);
            assert_eq!(all.iter().filter(|o| o.spec.instruction == i).count(), 1);
        }
        assert!(all.len() >= Block::ALL.len());
        assert!(parse("x", "# cargo run --release -- run TON x.csv\n").is_err());
        assert!(parse("x", "t_ms,IN\n").is_err());
    }

    /// The options of an example's command: `--type` chooses the integer type, any other
    /// `--NAME VALUE` is the preset, anything else is an error.
    #[test]
    fn command_options() {
        let e = parse(
            "x",
            "# cargo run --release -- run CTU --type usint --pv 3 examples/traces/x.csv\n",
        )
        .expect("a CTU command");
        assert_eq!(
            e.spec,
            BlockSpec::parse("CTU", Some("usint")).expect("USINT")
        );
        assert_eq!(e.preset, Some("3"));
        assert!(parse(
            "x",
            "# cargo run --release -- run CTU --tv 3 examples/traces/x.csv\n"
        )
        .is_err());
        assert!(parse(
            "x",
            "# cargo run --release -- run CTU pv 3 examples/traces/x.csv\n"
        )
        .is_err());
    }
}
