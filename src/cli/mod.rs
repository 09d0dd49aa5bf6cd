//! Command line: `run`, `check`, `schema`, `sweep`, `merge`.

pub mod merge;
pub mod resume;
pub mod shard_env;
pub mod sweep;
mod sweep_finish;
mod sweep_notes;
mod targets;

use crate::analysis::{self, RunError};
use crate::case::CaseError;
use clap::{Parser, Subcommand, ValueEnum};
use std::path::{Path, PathBuf};
use std::process::ExitCode;

/// flexfem — fast, validated beam/shell FEM for compliant mechanisms.
#[derive(Debug, Parser)]
#[command(name = "flexfem", version, about)]
pub struct Cli {
    #[command(subcommand)]
    command: Command,
    /// Worker threads (sparse factorisation and solves of big models, modal products, the
    /// designs of a sweep — one thread per design). Default: RAYON_NUM_THREADS, else one per core.
    #[arg(long, global = true, value_name = "N", value_parser = clap::value_parser!(u16).range(1..=4096))]
    threads: Option<u16>,
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
        /// Write result.json, report.md, result.csv and any plots/VTK files into DIR. DIR must
        /// be new, empty, or an earlier flexfem output folder (it holds result.json and
        /// report.md); anything else is refused unless --force.
        #[arg(long, value_name = "DIR")]
        out: Option<PathBuf>,
        /// What to print on stdout.
        #[arg(long, value_enum, default_value = "json")]
        format: Format,
        /// Write into --out DIR even when it is not a flexfem output folder (files of the same
        /// names are replaced). The case file itself is never overwritten.
        #[arg(long)]
        force: bool,
        /// Also write the reduced stiffness and mass (`K.mtx`, `M.mtx`, Matrix Market) and the
        /// node and DOF of each equation (`dofs.csv`) into --out DIR (static, modal and frf
        /// cases).
        #[arg(long, requires = "out")]
        export_matrices: bool,
    },
    /// Validate a case file without solving.
    Check {
        /// The case file.
        case: PathBuf,
    },
    /// Print the JSON Schema of case files.
    Schema,
    /// Batch runs: the full factorial of a `sweep` case, as JSON lines.
    #[command(after_help = "Exit status: 0 when every design succeeded; 1 when any design failed \
(the summary line on stderr gives the count, and each failed design is a line with an \"error\"), \
or when the output could not be written or is locked by another sweep; 2 for a bad case file or \
arguments, or an output path that would replace the case file or a file that is not flexfem's \
own output.\n\n\
Resume: with --out FILE, a re-run keeps the lines already in FILE (and FILE.partial) whose \
design_hash still matches the design (base case with the varied values, and its mesh file), \
reruns stale ones, and retries error rows unless --keep-errors. While it runs, FILE.lock \
stops a second sweep (e.g. another shard) from writing the same FILE at the same time: run \
shards one after another (their lines accumulate in FILE) or give each its own --out.\n\n\
Slurm job arrays: `--shard-from-env` takes K/N from the array task (see scripts/slurm_sweep.sh); \
`flexfem merge` combines the shard files.")]
    Sweep(sweep::SweepArgs),
    /// Combine the shard files of a sweep (e.g. a Slurm job array's) into one, checked against
    /// the case.
    #[command(
        after_help = "Exit status: 0 when every design of the case is there exactly once (identical \
duplicate lines are dropped and counted) and none is an error row; 1 when designs are missing \
(listed; nothing is written unless --allow-missing) or any design's line is an error row (the file \
is written), or OUT could not be written; 2 for bad arguments, an unreadable shard file, or a line \
that is not this sweep's as the case now is (another sweep, another base case or mesh file, an \
older line format: stale), or two different lines for one design — the file and line are named \
and nothing is written.\n\n\
Each shard file must be sorted by index, as a finished `flexfem sweep --out` file is (the files \
are read line by line, so memory does not grow with the sweep); an unfinished shard's .partial file \
is refused — rerun that shard (it resumes) and merge its finished file. The model notes go into \
OUT.notes.json. Afterwards `flexfem sweep CASE --out OUT` runs no design and writes the table and \
plot of the base case's analysis beside OUT."
    )]
    Merge(merge::MergeArgs),
}

pub use crate::output::{EXIT_BAD_CASE, EXIT_FAILED};

fn read_case_resolved(path: &Path) -> Result<analysis::Parsed, CaseError> {
    analysis::load_resolved(path)
}

fn fail(e: &RunError) -> ExitCode {
    eprintln!("error: {e}");
    ExitCode::from(match e {
        RunError::Case(_) => EXIT_BAD_CASE,
        RunError::Analysis(_) => EXIT_FAILED,
    })
}

/// The fixed file names `run --out DIR` writes (plus the analysis' own files).
const RUN_FILES: [&str; 3] = ["result.json", "report.md", "result.csv"];

/// True when `dir` is a flexfem output folder: it holds a `result.json` that is a JSON object
/// and a `report.md`, as `run --out` writes them.
fn is_flexfem_dir(dir: &Path) -> bool {
    let result = std::fs::read(dir.join("result.json"))
        .ok()
        .and_then(|b| serde_json::from_slice::<serde_json::Value>(&b).ok());
    matches!(result, Some(serde_json::Value::Object(_))) && dir.join("report.md").is_file()
}

/// Refuses `run --out DIR` when DIR is a file, or an existing, non-empty folder that is not
/// flexfem output (unless `force`), or when an output would replace the case file.
fn check_out_dir(dir: &Path, case: &Path, force: bool) -> Result<(), String> {
    for name in RUN_FILES {
        refuse_case_file(&dir.join(name), case)?;
    }
    match std::fs::metadata(dir) {
        Err(_) => Ok(()),
        Ok(m) if !m.is_dir() => Err(format!(
            "--out {} exists and is not a folder; --out names a folder for result.json, report.md …",
            dir.display()
        )),
        Ok(_) => {
            let empty = std::fs::read_dir(dir).map(|mut d| d.next().is_none()).unwrap_or(false);
            if empty || force || is_flexfem_dir(dir) {
                Ok(())
            } else {
                Err(format!(
                    "--out {} is a folder that is neither empty nor a flexfem output folder (one holding \
                     result.json and report.md); flexfem will not write into it — choose another folder \
                     or pass --force",
                    dir.display()
                ))
            }
        }
    }
}

fn refuse_case_file(path: &Path, case: &Path) -> Result<(), String> {
    if crate::output::same_file(path, case) {
        Err(format!(
            "{} is the case file; flexfem never overwrites it — choose another --out",
            path.display()
        ))
    } else {
        Ok(())
    }
}

fn write_outputs(dir: &Path, outcome: &analysis::Outcome) -> std::io::Result<()> {
    std::fs::create_dir_all(dir)?;
    let json = crate::report::json::pretty(&outcome.json);
    write_atomic(&dir.join("result.json"), json.as_bytes())?;
    let markdown = with_picture(&outcome.report.markdown, &outcome.files);
    write_atomic(&dir.join("report.md"), markdown.as_bytes())?;
    if !outcome.report.csv.is_empty() {
        write_atomic(&dir.join("result.csv"), outcome.report.csv.as_bytes())?;
    }
    for (name, bytes) in &outcome.files {
        write_atomic(&dir.join(name), bytes)?;
    }
    Ok(())
}

/// The report with the picture of the model (`model.svg`, when the run wrote one) embedded
/// under its title line.
fn with_picture(markdown: &str, files: &analysis::Files) -> String {
    if markdown.contains("](model.svg)") || !files.iter().any(|(name, _)| name == "model.svg") {
        return markdown.to_string();
    }
    let image = "![The model: undeformed in grey, deformed on top (model.svg)](model.svg)\n";
    match markdown.split_once('\n') {
        Some((title, rest)) if title.starts_with('#') => format!("{title}\n\n{image}{rest}"),
        _ => format!("{image}\n{markdown}"),
    }
}

/// Writes `bytes` to `path` atomically, through a safely created temporary file
/// ([`crate::output::write_atomic`]).
pub fn write_atomic(path: &Path, bytes: &[u8]) -> std::io::Result<()> {
    crate::output::write_atomic(path, bytes)
}

/// Prints `text` on stdout; a closed or full stdout is an error (exit 1), not a panic.
fn emit(text: &str) -> ExitCode {
    match crate::output::stdout_write(text) {
        Ok(()) => ExitCode::SUCCESS,
        Err(e) => {
            eprintln!("error: {e}");
            ExitCode::from(EXIT_FAILED)
        }
    }
}

/// Runs the command line; returns the process exit code.
pub fn run(cli: Cli) -> ExitCode {
    if let Some(n) = cli.threads {
        // Fails only if the global pool already exists (a second `run` in one process): then
        // that pool is kept.
        let _ = rayon::ThreadPoolBuilder::new()
            .num_threads(usize::from(n))
            .build_global();
    }
    match cli.command {
        Command::Sweep(args) => sweep::run_cli(args),
        Command::Merge(args) => merge::run_cli(args),
        Command::Schema => emit(&format!(
            "{}\n",
            serde_json::to_string_pretty(&analysis::schema()).unwrap_or_default()
        )),
        Command::Check { case } => {
            let checked = read_case_resolved(&case).and_then(|p| match &p.case {
                analysis::Case::Sweep(s) => {
                    let sweep = s.build()?;
                    let n = crate::design::sweep::check(&sweep, case.parent())?;
                    Ok(format!(
                        "ok: sweep case {} ({} designs; base case and varied paths checked on {n} of them)\n",
                        case.display(),
                        sweep.len()
                    ))
                }
                c => analysis::check(c)
                    .map(|_| {
                        // What a run would warn about the case alone, on stderr: `ok` stays the
                        // one line on stdout.
                        for w in analysis::check_warnings(c) {
                            eprintln!("warning: {w}");
                        }
                        format!("ok: {} case {}\n", c.analysis(), case.display())
                    })
                    .map_err(|e| p.locate(e)),
            });
            match checked {
                Ok(msg) => emit(&msg),
                Err(e) => fail(&RunError::Case(e)),
            }
        }
        Command::Run {
            case,
            out,
            format,
            force,
            export_matrices,
        } => {
            if let Some(dir) = &out {
                if let Err(msg) = check_out_dir(dir, &case, force) {
                    eprintln!("error: {msg}");
                    return ExitCode::from(EXIT_BAD_CASE);
                }
            }
            let resolved = match read_case_resolved(&case) {
                Ok(p) => p,
                Err(e) => return fail(&RunError::Case(e)),
            };
            let parsed = &resolved.case;
            if export_matrices {
                if let Err(e) = analysis::export::check_exportable(parsed) {
                    return fail(&RunError::Case(e));
                }
            }
            let run = if out.is_some() {
                analysis::run_with_files
            } else {
                analysis::run
            };
            let mut outcome = match run(parsed) {
                Ok(o) => o,
                Err(e) => return fail(&resolved.locate_run(e)),
            };
            outcome.echo_parameters(&resolved.parameters);
            if export_matrices {
                match analysis::export::matrix_files(parsed) {
                    Ok(files) => outcome.files.extend(files),
                    Err(e) => return fail(&e),
                }
            }
            if let Some(dir) = &out {
                // report.md and `--format md` both show the picture the folder holds.
                outcome.report.markdown = with_picture(&outcome.report.markdown, &outcome.files);
                for (name, _) in &outcome.files {
                    if let Err(msg) = refuse_case_file(&dir.join(name), &case) {
                        eprintln!("error: {msg}");
                        return ExitCode::from(EXIT_BAD_CASE);
                    }
                }
                if let Err(e) = write_outputs(dir, &outcome) {
                    eprintln!("error: cannot write outputs to {}: {e}", dir.display());
                    return ExitCode::from(EXIT_FAILED);
                }
            }
            match format {
                Format::Json if out.is_none() => emit(&format!("{}\n", crate::report::json::pretty(&outcome.json))),
                Format::Json => {
                    eprintln!(
                        "wrote {}",
                        out.as_deref().unwrap_or(Path::new(".")).join("result.json").display()
                    );
                    ExitCode::SUCCESS
                }
                Format::Md => emit(&outcome.report.markdown),
                Format::Csv => emit(&outcome.report.csv),
            }
        }
    }
}
