//! `plc-timers`: runs traces through the reference semantics, checks other implementations'
//! outputs, and converts time literals. The contract is `shared/trace-format.md`.

use std::fs::File;
use std::io::{self, Read};
use std::path::PathBuf;
use std::process::ExitCode;

use clap::{Args, Parser, Subcommand};
use plc_timers::time::{S5Time, Time};
use plc_timers_cli::trace::{self, BlockOptions, Implementation, PresetOption, TraceError};

/// Siemens S7 timers and counters: reference semantics for traces.
#[derive(Parser, Debug)]
#[command(name = "plc-timers", version, about, long_about = None)]
struct Cli {
    #[command(subcommand)]
    command: Command,
}

#[derive(Subcommand, Debug)]
enum Command {
    /// Run a CSV trace through a block's reference semantics; write the trace with its outputs.
    Run(BlockArgs),
    /// Compare a trace that carries outputs (another implementation's) with the reference;
    /// exit status 1 at the first difference.
    Check(BlockArgs),
    /// Draw a trace as a timing diagram (SVG): inputs and Q as waveforms, ET/BI/CV as a ramp
    /// with the preset marked.
    Diagram {
        #[command(flatten)]
        block: BlockArgs,
        /// Where to write the SVG.
        #[arg(short, long)]
        output: PathBuf,
    },
    /// Write test vectors: for every block, a directory of CSV traces with reference outputs.
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

#[derive(Args, Debug)]
struct BlockArgs {
    /// The block: S_PULSE S_PEXT S_ODT S_ODTS S_OFFDT (SP SE SD SS SF), TP TON TOF TONR,
    /// CTU CTD CTUD, S_CU S_CD S_CUD (case-insensitive).
    block: String,
    /// The trace (CSV); standard input when absent or `-`.
    file: Option<PathBuf>,
    /// S5 timers: the time value TV used when the trace has no TV column (S5T#…, S5TIME#…, W#16#…).
    #[arg(long, allow_hyphen_values = true)]
    tv: Option<String>,
    /// IEC timers: the preset PT used when the trace has no PT column (T#…, TIME#…, or ms).
    #[arg(long, allow_hyphen_values = true)]
    pt: Option<String>,
    /// Counters: the preset PV used when the trace has no PV column.
    #[arg(long, allow_hyphen_values = true)]
    pv: Option<String>,
    /// IEC counters: the integer type of CV and PV: SINT INT DINT LINT USINT UINT UDINT ULINT.
    #[arg(long = "type")]
    int_type: Option<String>,
    /// Drive the optimized implementation instead of the reference (for comparison).
    #[arg(long)]
    optimized: bool,
}

impl BlockArgs {
    fn presets(&self) -> Vec<PresetOption<'_>> {
        [("tv", &self.tv), ("pt", &self.pt), ("pv", &self.pv)]
            .into_iter()
            .filter_map(|(name, value)| value.as_deref().map(|v| (name, v)))
            .collect()
    }

    fn input(&self) -> Result<Box<dyn Read>, TraceError> {
        match &self.file {
            None => Ok(Box::new(io::stdin().lock())),
            Some(p) if p.as_os_str() == "-" => Ok(Box::new(io::stdin().lock())),
            Some(p) => File::open(p)
                .map(|f| Box::new(f) as Box<dyn Read>)
                .map_err(|e| TraceError {
                    location: trace::Location::Command,
                    message: format!("cannot open {}: {e}", p.display()),
                }),
        }
    }

    fn block(&self) -> Result<Box<dyn trace::TraceBlock>, TraceError> {
        let options = BlockOptions {
            int_type: self.int_type.clone(),
            implementation: if self.optimized {
                Implementation::Optimized
            } else {
                Implementation::Reference
            },
        };
        trace::lookup(&self.block, &options)
    }
}

/// Writes every vector and a README under `dir`; returns the number of files.
fn write_vectors(dir: &std::path::Path) -> Result<usize, String> {
    let vectors = trace::vectors::all()?;
    let io = |p: &std::path::Path, e: std::io::Error| format!("cannot write {}: {e}", p.display());
    std::fs::create_dir_all(dir).map_err(|e| io(dir, e))?;
    let readme = dir.join("README.txt");
    std::fs::write(&readme, trace::vectors::README).map_err(|e| io(&readme, e))?;
    for v in &vectors {
        let sub = dir.join(&v.dir);
        std::fs::create_dir_all(&sub).map_err(|e| io(&sub, e))?;
        let path = sub.join(&v.file);
        std::fs::write(&path, &v.csv).map_err(|e| io(&path, e))?;
    }
    Ok(vectors.len())
}

/// Exit status for bad input, per the contract.
const BAD_INPUT: u8 = 2;

fn fail(e: impl std::fmt::Display) -> ExitCode {
    eprintln!("plc-timers: {e}");
    ExitCode::from(BAD_INPUT)
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
    match cli.command {
        Command::S5time { value } => match value.parse::<S5Time>() {
            // The word uses the automatic base (trace contract).
            Ok(t) => match S5Time::from_millis(u64::from(t.as_millis())) {
                Ok(auto) => {
                    println!("W#16#{:04X} {} {}", auto.to_word(), auto.as_millis(), auto);
                    ExitCode::SUCCESS
                }
                Err(e) => fail(e),
            },
            Err(e) => fail(e),
        },
        Command::Time { value } => match value.parse::<Time>() {
            Ok(t) => {
                println!("{} {}", t.as_millis(), t);
                ExitCode::SUCCESS
            }
            Err(e) => fail(e),
        },
        Command::Diagram {
            block: args,
            output,
        } => {
            let result = args.block().and_then(|mut block| {
                trace::record(block.as_mut(), args.input()?, &args.presets())
            });
            match result {
                Ok(rec) => match std::fs::write(&output, trace::diagram::svg(&rec)) {
                    Ok(()) => ExitCode::SUCCESS,
                    Err(e) => fail(format!("cannot write {}: {e}", output.display())),
                },
                Err(e) => fail(e),
            }
        }
        Command::Vectors { dir } => match write_vectors(&dir) {
            Ok(n) => {
                println!("wrote {n} vector files under {}", dir.display());
                ExitCode::SUCCESS
            }
            Err(e) => fail(e),
        },
        Command::Run(args) => {
            let result = args.block().and_then(|mut block| {
                let stdout = io::stdout().lock();
                trace::run(block.as_mut(), args.input()?, &args.presets(), stdout)
            });
            match result {
                Ok(()) => ExitCode::SUCCESS,
                Err(e) => fail(e),
            }
        }
        Command::Check(args) => {
            let result = args
                .block()
                .and_then(|mut block| trace::check(block.as_mut(), args.input()?, &args.presets()));
            match result {
                Ok(report) => match report.difference {
                    None => {
                        println!(
                            "OK: {} rows, outputs {} agree with the reference",
                            report.rows,
                            report.compared.join(", ")
                        );
                        ExitCode::SUCCESS
                    }
                    Some(d) => {
                        println!(
                            "DIFFERENT at line {}, column {} ({}): the reference gives {}, the trace has {}",
                            d.line, d.column, d.name, d.expected, d.found
                        );
                        ExitCode::from(1)
                    }
                },
                Err(e) => fail(e),
            }
        }
    }
}
