//! Command line: `run`, `check`, `schema` (INTERFACE.md).

use crate::analysis::{self, RunError};
use crate::case::{self, CaseError};
use clap::{Parser, Subcommand, ValueEnum};
use std::path::{Path, PathBuf};
use std::process::ExitCode;

/// flexfem — fast, validated beam/shell FEM for compliant mechanisms.
#[derive(Debug, Parser)]
#[command(name = "flexfem", version, about)]
pub struct Cli {
    #[command(subcommand)]
    command: Command,
}

/// Output format of `run` on stdout.
#[derive(Debug, Clone, Copy, PartialEq, Eq, ValueEnum)]
pub enum Format {
    /// The JSON result.
    Json,
    /// A Markdown report.
    Md,
    /// A CSV table.
    Csv,
}

#[derive(Debug, Subcommand)]
enum Command {
    /// Run the case's analysis; the JSON result goes to stdout (or DIR/result.json).
    Run {
        /// The case file.
        case: PathBuf,
        /// Write result.json, report.md, result.csv and any plots/VTK files into DIR.
        #[arg(long, value_name = "DIR")]
        out: Option<PathBuf>,
        /// What to print on stdout.
        #[arg(long, value_enum, default_value = "json")]
        format: Format,
    },
    /// Validate a case file without solving.
    Check {
        /// The case file.
        case: PathBuf,
    },
    /// Print the JSON Schema of case files.
    Schema,
    /// Batch runs: the full factorial of a `sweep` case, as JSON lines.
    Sweep {
        /// The sweep case file (`"analysis": "sweep"`).
        case: PathBuf,
        /// Run only the designs whose index ≡ K−1 (mod N).
        #[arg(long, value_name = "K/N")]
        shard: Option<String>,
        /// Write the JSON lines to FILE (resumable) instead of stdout.
        #[arg(long, value_name = "FILE.jsonl")]
        out: Option<PathBuf>,
        /// Also write a CSV table of parameters and scalar results.
        #[arg(long, value_name = "FILE.csv")]
        csv: Option<PathBuf>,
    },
}

/// Exit code for a bad case file.
pub const EXIT_BAD_CASE: u8 = 2;
/// Exit code for a failed analysis.
pub const EXIT_FAILED: u8 = 1;

fn read_case(path: &Path) -> Result<case::Case, CaseError> {
    case::load(path)
}

fn fail(e: &RunError) -> ExitCode {
    eprintln!("error: {e}");
    ExitCode::from(match e {
        RunError::Case(_) => EXIT_BAD_CASE,
        RunError::Analysis(_) => EXIT_FAILED,
    })
}

fn write_outputs(dir: &Path, outcome: &analysis::Outcome) -> std::io::Result<()> {
    std::fs::create_dir_all(dir)?;
    let json = crate::report::json::pretty(&outcome.json);
    write_atomic(&dir.join("result.json"), json.as_bytes())?;
    write_atomic(&dir.join("report.md"), outcome.report.markdown.as_bytes())?;
    if !outcome.report.csv.is_empty() {
        write_atomic(&dir.join("result.csv"), outcome.report.csv.as_bytes())?;
    }
    for (name, bytes) in &outcome.files {
        write_atomic(&dir.join(name), bytes)?;
    }
    Ok(())
}

/// Writes `bytes` to `path` through a temporary file and a rename.
pub fn write_atomic(path: &Path, bytes: &[u8]) -> std::io::Result<()> {
    let tmp = path.with_extension("tmp~");
    std::fs::write(&tmp, bytes)?;
    std::fs::rename(&tmp, path)
}

/// Runs the command line; returns the process exit code.
pub fn run(cli: Cli) -> ExitCode {
    match cli.command {
        Command::Sweep { case, shard, out, csv } => {
            crate::design::sweep::run_cli(crate::design::sweep::SweepArgs { case, shard, out, csv })
        }
        Command::Schema => {
            println!("{}", serde_json::to_string_pretty(&case::schema()).unwrap_or_default());
            ExitCode::SUCCESS
        }
        Command::Check { case } => match read_case(&case).and_then(|c| analysis::check(&c).map(|_| c)) {
            Ok(c) => {
                println!("ok: {} case {}", c.analysis(), case.display());
                ExitCode::SUCCESS
            }
            Err(e) => fail(&RunError::Case(e)),
        },
        Command::Run { case, out, format } => {
            let parsed = match read_case(&case) {
                Ok(c) => c,
                Err(e) => return fail(&RunError::Case(e)),
            };
            let run = if out.is_some() {
                analysis::run_with_files
            } else {
                analysis::run
            };
            let outcome = match run(&parsed) {
                Ok(o) => o,
                Err(e) => return fail(&e),
            };
            if let Some(dir) = &out {
                if let Err(e) = write_outputs(dir, &outcome) {
                    eprintln!("error: cannot write outputs to {}: {e}", dir.display());
                    return ExitCode::from(EXIT_FAILED);
                }
            }
            match format {
                Format::Json if out.is_none() => {
                    println!("{}", crate::report::json::pretty(&outcome.json))
                }
                Format::Json => eprintln!(
                    "wrote {}",
                    out.as_deref().unwrap_or(Path::new(".")).join("result.json").display()
                ),
                Format::Md => print!("{}", outcome.report.markdown),
                Format::Csv => print!("{}", outcome.report.csv),
            }
            ExitCode::SUCCESS
        }
    }
}
