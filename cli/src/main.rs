//! `plc-timers`: runs CSV traces through the reference semantics of the Siemens S7 timers and
//! counters, checks other implementations' outputs, writes test vectors, timing diagrams and
//! VCD files, and converts time literals. The contract is `spec/cli.md`.

use std::fs::File;
use std::io::{self, BufWriter, Read, Write};
use std::path::PathBuf;
use std::process::ExitCode;

use clap::error::ErrorKind;
use clap::{Arg, ArgMatches, Args, FromArgMatches, Parser, Subcommand, ValueEnum};
use plc_timers::catalog::{Block, DataType};
use plc_timers::time::{LTime, S5Time, Time};
use plc_timers_trace::diagram::{self, Window};
use plc_timers_trace::family::{block_names, merge_data_types};
use plc_timers_trace::{
    check, parse_data_type, parse_instruction, preset_option, run, run_explained, vcd, vectors,
    BlockSpec, Error, Implementation, Location, TraceError,
};

/// Exit status: the check found a difference.
const DIFFERENT: u8 = 1;
/// Exit status: bad input, a bad option, or an output that cannot be written.
const BAD_INPUT: u8 = 2;

/// Siemens S7 timers and counters: the reference semantics for CSV traces.
#[derive(Parser, Debug)]
#[command(name = "plc-timers", version, about, long_about = None)]
struct Cli {
    #[command(subcommand)]
    command: Command,
}

#[derive(Subcommand, Debug)]
enum Command {
    /// Run a CSV trace through a block; write the trace with the block's outputs appended.
    Run {
        #[command(flatten)]
        block: BlockArgs,
        /// Add a column `rules`: the IDs of the requirements that decided each row's outputs.
        #[arg(long)]
        explain: bool,
    },
    /// Compare a trace that carries outputs (another implementation's) with the reference;
    /// exit status 1 at the first difference, with the rule that decides it.
    Check {
        #[command(flatten)]
        block: BlockArgs,
        /// The outputs to compare, e.g. `Q,ET` (default: every output of the block, each of
        /// which the trace must have).
        #[arg(long, value_delimiter = ',')]
        outputs: Option<Vec<String>>,
    },
    /// Draw a trace as a timing diagram (SVG; or VCD with --format vcd).
    Diagram {
        #[command(flatten)]
        block: BlockArgs,
        /// Draw from this time on (in the time column's unit: ms, ns on LTIME).
        #[arg(long)]
        from: Option<u64>,
        /// Draw up to this time (in the time column's unit).
        #[arg(long)]
        to: Option<u64>,
        /// The output format.
        #[arg(long, value_enum, default_value_t = Format::Svg)]
        format: Format,
        /// Where to write it (`-`: standard output).
        #[arg(short, long)]
        output: PathBuf,
    },
    /// Write a trace with the reference outputs as a VCD file (GTKWave, Surfer), time in ms
    /// (ns on LTIME).
    Vcd {
        #[command(flatten)]
        block: BlockArgs,
        /// Where to write it (`-`: standard output).
        #[arg(short, long)]
        output: PathBuf,
    },
    /// Write test vectors: per block, CSV traces with the reference outputs.
    Vectors {
        /// The directory to create (or fill).
        dir: PathBuf,
    },
    /// Convert an S5TIME literal or word: prints `W#16#XXXX <ms> <S5T# literal>`.
    #[command(name = "s5time")]
    S5time {
        /// `S5T#…`, `S5TIME#…` or `W#16#…`.
        #[arg(allow_hyphen_values = true)]
        value: String,
    },
    /// Convert a TIME literal: prints `<ms> <T# literal>`; an LTIME literal (`LT#…`):
    /// `<ns> <LT# literal>`.
    Time {
        /// `T#…`, `TIME#…` or whole milliseconds (may be negative); `LT#…` or `LTIME#…`.
        #[arg(allow_hyphen_values = true)]
        value: String,
    },
}

#[derive(Clone, Copy, Debug, PartialEq, Eq, ValueEnum)]
enum Format {
    Svg,
    Vcd,
}

fn block_help() -> String {
    format!(
        "The block (ASCII case ignored): {}; or an instance type such as TON_LTIME (the block \
         with --type LTIME)",
        block_names()
    )
}

/// The block as named on the command line, with the data type an instance-type name gives.
#[derive(Clone, Copy, Debug)]
struct Named {
    block: Block,
    data_type: Option<DataType>,
}

/// The value parser of the block: [`parse_instruction`].
fn parse_named(name: &str) -> Result<Named, String> {
    parse_instruction(name).map(|(block, data_type)| Named { block, data_type })
}

fn type_help() -> String {
    let counters: Vec<&str> = Block::Ctu.data_types().iter().map(|t| t.name()).collect();
    format!(
        "The data type: IEC timers TIME (default) or LTIME (time column t_ns, PT and ET in ns); \
         IEC counters the integer type of CV and PV: {} (default INT)",
        counters.join(" ")
    )
}

#[derive(Args, Debug)]
struct BlockArgs {
    /// The preset option (`--tv`, `--pt`, `--pv`), read for the block. First: the derived
    /// parser takes each field's values out of the matches in this order, and this one reads
    /// the block's and `--type`'s.
    #[command(flatten)]
    preset: PresetArg,
    #[arg(help = block_help(), value_parser = parse_named)]
    block: Named,
    /// The trace (CSV: `t_ms` (`t_ns` on LTIME), the block's inputs and preset; the IEC timers
    /// also take `RT`, the -(RT)- coil, run before the box call of its row); standard input
    /// when absent or `-`.
    file: Option<PathBuf>,
    #[arg(long = "type", value_name = "TYPE", value_parser = parse_data_type, help = type_help())]
    data_type: Option<DataType>,
    /// Drive the optimized implementation instead of the reference.
    #[arg(long)]
    optimized: bool,
}

/// The preset given on the command line, read for the block: one option per preset kind of the
/// catalog (`--tv`, `--pt`, `--pv`). The parser refuses an option the block does not take,
/// naming the block's, and a value the block's preset cell would refuse; it also makes the
/// block's spec, whose data type the block's name and `--type` give together.
#[derive(Debug, Default)]
struct PresetArg {
    spec: Option<BlockSpec>,
    text: Option<String>,
}

/// Each preset option of the catalog with its input's name and the blocks that take it.
fn preset_options() -> Vec<(&'static str, &'static str, Vec<&'static str>)> {
    let mut options: Vec<(&'static str, &'static str, Vec<&'static str>)> = Vec::new();
    for block in Block::ALL {
        let option = preset_option(block);
        match options.iter_mut().find(|o| o.0 == option) {
            Some(o) => o.2.push(block.name()),
            None => options.push((option, block.preset().port.name(), vec![block.name()])),
        }
    }
    options
}

/// The argument parser's error for `message`.
fn refuse(kind: ErrorKind, message: String) -> clap::Error {
    clap::Error::raw(kind, message)
}

impl FromArgMatches for PresetArg {
    fn from_arg_matches(m: &ArgMatches) -> Result<Self, clap::Error> {
        // The block and --type are read by their own value parsers; they share these matches.
        let Some(&Named { block, data_type }) = m.get_one::<Named>("block") else {
            return Ok(PresetArg::default());
        };
        let option = m.get_one::<DataType>("data_type").copied();
        let conflict = |e| refuse(ErrorKind::ArgumentConflict, e);
        let data_type = merge_data_types(data_type, option).map_err(conflict)?;
        let spec = BlockSpec::typed(block, data_type).map_err(conflict)?;
        let preset = block.preset();
        let mut value = None;
        for (option, ..) in preset_options() {
            let Some(text) = m.get_one::<String>(option) else {
                continue;
            };
            if option != preset_option(block) {
                return Err(refuse(
                    ErrorKind::ArgumentConflict,
                    format!(
                        "option --{option} does not apply to {block}; its preset {} is given \
                         with --{}",
                        preset.port.name(),
                        preset_option(block)
                    ),
                ));
            }
            spec.preset_literal(text).map_err(|e| {
                refuse(
                    ErrorKind::ValueValidation,
                    format!("option --{option}: `{}`: {e}", text.trim()),
                )
            })?;
            value = Some(text.clone());
        }
        Ok(PresetArg {
            spec: Some(spec),
            text: value,
        })
    }

    fn update_from_arg_matches(&mut self, m: &ArgMatches) -> Result<(), clap::Error> {
        *self = PresetArg::from_arg_matches(m)?;
        Ok(())
    }
}

impl Args for PresetArg {
    fn augment_args(mut cmd: clap::Command) -> clap::Command {
        for (option, name, blocks) in preset_options() {
            cmd = cmd.arg(
                Arg::new(option)
                    .long(option)
                    .value_name(name)
                    .allow_hyphen_values(true)
                    .help(format!(
                        "The preset {name} of {} when the trace has no {name} column",
                        blocks.join(" ")
                    )),
            );
        }
        cmd
    }

    fn augment_args_for_update(cmd: clap::Command) -> clap::Command {
        PresetArg::augment_args(cmd)
    }
}

impl BlockArgs {
    fn spec(&self) -> BlockSpec {
        let implementation = if self.optimized {
            Implementation::Optimized
        } else {
            Implementation::Reference
        };
        // The preset's parser made the spec; it is absent only where clap reads no block.
        self.preset
            .spec
            .unwrap_or_else(|| BlockSpec::new(self.block.block))
            .with(implementation)
    }

    fn input(&self) -> Result<Box<dyn Read>, TraceError> {
        match &self.file {
            None => Ok(Box::new(io::stdin().lock())),
            Some(p) if p.as_os_str() == "-" => Ok(Box::new(io::stdin().lock())),
            Some(p) => File::open(p)
                .map(|f| Box::new(f) as Box<dyn Read>)
                .map_err(|e| {
                    TraceError::new(
                        Location::Command,
                        format!("cannot open {}: {e}", p.display()),
                    )
                }),
        }
    }
}

fn output(path: &PathBuf) -> Result<Box<dyn Write>, Error> {
    if path.as_os_str() == "-" {
        return Ok(Box::new(io::stdout().lock()));
    }
    File::create(path)
        .map(|f| Box::new(BufWriter::new(f)) as Box<dyn Write>)
        .map_err(|e| {
            Error::Input(TraceError::new(
                Location::Command,
                format!("cannot create {}: {e}", path.display()),
            ))
        })
}

/// Writes every vector and a README under `dir`; returns the number of files.
fn write_vectors(dir: &std::path::Path) -> Result<usize, String> {
    let all = vectors::all().map_err(|e| e.to_string())?;
    let io = |p: &std::path::Path, e: io::Error| format!("cannot write {}: {e}", p.display());
    std::fs::create_dir_all(dir).map_err(|e| io(dir, e))?;
    let readme = dir.join("README.txt");
    std::fs::write(&readme, vectors::readme()).map_err(|e| io(&readme, e))?;
    for v in &all {
        let sub = dir.join(&v.dir);
        std::fs::create_dir_all(&sub).map_err(|e| io(&sub, e))?;
        let path = sub.join(&v.file);
        std::fs::write(&path, &v.csv).map_err(|e| io(&path, e))?;
    }
    Ok(all.len())
}

/// The exit status of an error: a closed pipe ends quietly (the reader has what it wanted).
fn finish(e: Error) -> ExitCode {
    match e {
        Error::Output(e) if e.kind() == io::ErrorKind::BrokenPipe => ExitCode::SUCCESS,
        e => fail(e),
    }
}

fn fail(e: impl std::fmt::Display) -> ExitCode {
    eprintln!("plc-timers: {e}");
    ExitCode::from(BAD_INPUT)
}

/// Standard output without its line buffer (`run` writes in large blocks of whole lines).
fn raw_stdout() -> Box<dyn Write> {
    use std::os::fd::AsFd;
    match io::stdout().as_fd().try_clone_to_owned() {
        Ok(fd) => Box::new(File::from(fd)),
        Err(_) => Box::new(io::stdout().lock()),
    }
}

/// Prints `text` to standard output; a closed pipe is not an error.
fn say(text: &str) -> Result<(), Error> {
    let mut out = io::stdout().lock();
    out.write_all(text.as_bytes())?;
    out.flush()?;
    Ok(())
}

/// `s5time`: the value as a word of the automatic base, its milliseconds and its literal.
fn s5time(value: &str) -> Result<ExitCode, Error> {
    let t = value.parse::<S5Time>().map_err(bad_value)?.to_automatic();
    say(&format!("W#16#{:04X} {} {t}\n", t.to_word(), t.as_millis()))?;
    Ok(ExitCode::SUCCESS)
}

/// `time`: the value's milliseconds and its literal; for an LTIME literal (`LT#`, `LTIME#`)
/// its nanoseconds and its literal.
fn time(value: &str) -> Result<ExitCode, Error> {
    let upper = value.to_ascii_uppercase();
    if upper.starts_with("LT#") || upper.starts_with("LTIME#") {
        let t = value.parse::<LTime>().map_err(bad_value)?;
        say(&format!("{} {t}\n", t.as_nanos()))?;
    } else {
        let t = value.parse::<Time>().map_err(bad_value)?;
        say(&format!("{} {t}\n", t.as_millis()))?;
    }
    Ok(ExitCode::SUCCESS)
}

/// A value the command refuses, as bad input.
fn bad_value(e: impl std::fmt::Display) -> Error {
    Error::Input(TraceError::new(Location::Command, e.to_string()))
}

/// `vectors`: every vector under `dir`.
fn vectors_into(dir: &std::path::Path) -> Result<ExitCode, Error> {
    let n = write_vectors(dir).map_err(|e| Error::Input(TraceError::new(Location::Command, e)))?;
    say(&format!("wrote {n} vector files under {}\n", dir.display()))?;
    Ok(ExitCode::SUCCESS)
}

/// `run`: the trace with the reference outputs (and with `--explain` the deciding rules), to
/// standard output.
fn run_trace(args: &BlockArgs, explain: bool) -> Result<ExitCode, Error> {
    let (spec, preset, input) = (args.spec(), args.preset.text.as_deref(), args.input()?);
    if explain {
        run_explained(spec, preset, input, raw_stdout())?;
    } else {
        run(spec, preset, input, raw_stdout())?;
    }
    Ok(ExitCode::SUCCESS)
}

/// `check`: the first difference from the reference, or how many rows agree.
fn check_trace(args: &BlockArgs, outputs: Option<&[String]>) -> Result<ExitCode, Error> {
    let names: Option<Vec<&str>> = outputs.map(|o| o.iter().map(String::as_str).collect());
    let report = check(
        args.spec(),
        args.preset.text.as_deref(),
        names.as_deref(),
        args.input()?,
    )?;
    match report.difference {
        None => {
            say(&format!(
                "OK: {} rows of {}: {} agree with the reference\n",
                report.rows,
                report.block,
                report.compared.join(", ")
            ))?;
            Ok(ExitCode::SUCCESS)
        }
        Some(d) => {
            say(&d.to_string())?;
            Ok(ExitCode::from(DIFFERENT))
        }
    }
}

/// `diagram`: the trace as an SVG timing diagram, or as VCD.
fn draw(
    args: &BlockArgs,
    window: Window,
    format: Format,
    path: &PathBuf,
) -> Result<ExitCode, Error> {
    if let (Some(f), Some(t)) = (window.from, window.to) {
        if f > t {
            return Err(Error::Input(TraceError::new(
                Location::Option("from"),
                format!("--from {f} is after --to {t}"),
            )));
        }
    }
    let input = args.input()?;
    let out = output(path)?;
    match format {
        Format::Svg => {
            diagram::svg(args.spec(), args.preset.text.as_deref(), input, window, out)?;
        }
        Format::Vcd => {
            vcd::export(args.spec(), args.preset.text.as_deref(), input, out)?;
        }
    }
    Ok(ExitCode::SUCCESS)
}

/// `vcd`: the trace with the reference outputs as VCD.
fn export_vcd(args: &BlockArgs, path: &PathBuf) -> Result<ExitCode, Error> {
    let input = args.input()?;
    vcd::export(
        args.spec(),
        args.preset.text.as_deref(),
        input,
        output(path)?,
    )?;
    Ok(ExitCode::SUCCESS)
}

fn main() -> ExitCode {
    let cli = match Cli::try_parse() {
        Ok(cli) => cli,
        Err(e) => {
            let code = if e.use_stderr() { BAD_INPUT } else { 0 };
            let _ = e.print();
            return ExitCode::from(code);
        }
    };
    let result = match &cli.command {
        Command::S5time { value } => s5time(value),
        Command::Time { value } => time(value),
        Command::Vectors { dir } => vectors_into(dir),
        Command::Run { block, explain } => run_trace(block, *explain),
        Command::Check { block, outputs } => check_trace(block, outputs.as_deref()),
        Command::Diagram {
            block,
            from,
            to,
            format,
            output,
        } => draw(
            block,
            Window {
                from: *from,
                to: *to,
            },
            *format,
            output,
        ),
        Command::Vcd { block, output } => export_vcd(block, output),
    };
    result.unwrap_or_else(finish)
}
