//! `plc-timers`: runs CSV traces through the reference semantics of the Siemens S7 timers and
//! counters, checks other implementations' outputs, writes test vectors, timing diagrams and
//! VCD files, and converts time literals. The contract is `spec/cli.md`.

use std::fs::File;
use std::io::{self, BufWriter, Read, Write};
use std::path::PathBuf;
use std::process::ExitCode;

use clap::{Arg, ArgMatches, Args, FromArgMatches, Parser, Subcommand, ValueEnum};
use plc_timers::catalog::Block;
use plc_timers::time::{S5Time, Time};
use plc_timers_cli::trace::diagram::{self, Window};
use plc_timers_cli::trace::family::block_names;
use plc_timers_cli::trace::{
    check, run, run_explained, vcd, vectors, BlockSpec, Error, Implementation, IntType, Location,
    TraceError,
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
        /// Draw from this time on (ms).
        #[arg(long)]
        from: Option<u64>,
        /// Draw up to this time (ms).
        #[arg(long)]
        to: Option<u64>,
        /// The output format.
        #[arg(long, value_enum, default_value_t = Format::Svg)]
        format: Format,
        /// Where to write it (`-`: standard output).
        #[arg(short, long)]
        output: PathBuf,
    },
    /// Write a trace with the reference outputs as a VCD file (GTKWave, Surfer), time in ms.
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
    /// Convert a TIME literal: prints `<ms> <T# literal>`.
    Time {
        /// `T#…`, `TIME#…` or whole milliseconds (may be negative).
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
    format!("The block (ASCII case ignored): {}", block_names())
}

#[derive(Args, Debug)]
struct BlockArgs {
    #[arg(help = block_help())]
    block: String,
    /// The trace (CSV); standard input when absent or `-`.
    file: Option<PathBuf>,
    #[command(flatten)]
    presets: Presets,
    /// IEC counters: the integer type of CV and PV (default INT).
    #[arg(long = "type", help = format!("IEC counters: the integer type of CV and PV: {} (default INT)", IntType::names()))]
    int_type: Option<String>,
    /// Drive the optimized implementation instead of the reference.
    #[arg(long)]
    optimized: bool,
}

/// The preset options, one per preset kind of the catalog (`--tv`, `--pt`, `--pv`).
#[derive(Debug, Default)]
struct Presets(Vec<(&'static str, String)>);

/// Each preset option of the catalog with its input's name and the blocks that take it.
fn preset_options() -> Vec<(&'static str, &'static str, Vec<&'static str>)> {
    let mut options: Vec<(&'static str, &'static str, Vec<&'static str>)> = Vec::new();
    for block in Block::ALL {
        let Some(p) = block.preset() else { continue };
        match options.iter_mut().find(|o| o.0 == p.option) {
            Some(o) => o.2.push(block.name()),
            None => options.push((p.option, p.name, vec![block.name()])),
        }
    }
    options
}

impl FromArgMatches for Presets {
    fn from_arg_matches(m: &ArgMatches) -> Result<Self, clap::Error> {
        let mut v = Vec::new();
        for (option, ..) in preset_options() {
            if let Some(value) = m.get_one::<String>(option) {
                v.push((option, value.clone()));
            }
        }
        Ok(Presets(v))
    }

    fn update_from_arg_matches(&mut self, m: &ArgMatches) -> Result<(), clap::Error> {
        *self = Presets::from_arg_matches(m)?;
        Ok(())
    }
}

impl Args for Presets {
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
        Presets::augment_args(cmd)
    }
}

impl BlockArgs {
    fn spec(&self) -> Result<BlockSpec, TraceError> {
        let implementation = if self.optimized {
            Implementation::Optimized
        } else {
            Implementation::Reference
        };
        Ok(BlockSpec::parse(&self.block, self.int_type.as_deref())?.with(implementation))
    }

    fn presets(&self) -> Vec<(&str, &str)> {
        self.presets
            .0
            .iter()
            .map(|(o, v)| (*o, v.as_str()))
            .collect()
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

fn main() -> ExitCode {
    let cli = match Cli::try_parse() {
        Ok(cli) => cli,
        Err(e) => {
            let code = if e.use_stderr() { BAD_INPUT } else { 0 };
            let _ = e.print();
            return ExitCode::from(code);
        }
    };
    let result: Result<ExitCode, Error> = match cli.command {
        Command::S5time { value } => match value.parse::<S5Time>() {
            // The word uses the automatic base.
            Ok(t) => match S5Time::from_millis(u64::from(t.as_millis())) {
                Ok(auto) => say(&format!(
                    "W#16#{:04X} {} {}\n",
                    auto.to_word(),
                    auto.as_millis(),
                    auto
                ))
                .map(|()| ExitCode::SUCCESS),
                Err(e) => return fail(e),
            },
            Err(e) => return fail(e),
        },
        Command::Time { value } => match value.parse::<Time>() {
            Ok(t) => say(&format!("{} {}\n", t.as_millis(), t)).map(|()| ExitCode::SUCCESS),
            Err(e) => return fail(e),
        },
        Command::Vectors { dir } => match write_vectors(&dir) {
            Ok(n) => say(&format!("wrote {n} vector files under {}\n", dir.display()))
                .map(|()| ExitCode::SUCCESS),
            Err(e) => return fail(e),
        },
        Command::Run {
            block: args,
            explain,
        } => (|| {
            let spec = args.spec()?;
            let input = args.input()?;
            if explain {
                run_explained(spec, &args.presets(), input, raw_stdout())?;
            } else {
                run(spec, &args.presets(), input, raw_stdout())?;
            }
            Ok(ExitCode::SUCCESS)
        })(),
        Command::Check {
            block: args,
            outputs,
        } => (|| {
            let spec = args.spec()?;
            let input = args.input()?;
            let names: Option<Vec<&str>> = outputs
                .as_ref()
                .map(|o| o.iter().map(String::as_str).collect());
            let report = check(spec, &args.presets(), names.as_deref(), input)?;
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
        })(),
        Command::Diagram {
            block: args,
            from,
            to,
            format,
            output: path,
        } => (|| {
            let spec = args.spec()?;
            if let (Some(f), Some(t)) = (from, to) {
                if f > t {
                    return Err(Error::Input(TraceError::new(
                        Location::Option("from"),
                        format!("--from {f} is after --to {t}"),
                    )));
                }
            }
            let input = args.input()?;
            let out = output(&path)?;
            match format {
                Format::Svg => {
                    diagram::svg(spec, &args.presets(), input, Window { from, to }, out)?;
                }
                Format::Vcd => {
                    vcd::export(spec, &args.presets(), input, out)?;
                }
            }
            Ok(ExitCode::SUCCESS)
        })(),
        Command::Vcd {
            block: args,
            output: path,
        } => (|| {
            let spec = args.spec()?;
            let input = args.input()?;
            vcd::export(spec, &args.presets(), input, output(&path)?)?;
            Ok(ExitCode::SUCCESS)
        })(),
    };
    result.unwrap_or_else(finish)
}
