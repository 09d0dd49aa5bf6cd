//! `flexfem sweep`: full-factorial batch runs (INTERFACE.md "sweep").

use std::path::PathBuf;
use std::process::ExitCode;

/// Command-line arguments of `flexfem sweep`.
#[derive(Debug, Clone)]
pub struct SweepArgs {
    /// The sweep case file.
    pub case: PathBuf,
    /// `K/N`: run only designs with index ≡ K−1 (mod N).
    pub shard: Option<String>,
    /// JSON-lines output file (stdout when `None`).
    pub out: Option<PathBuf>,
    /// Optional CSV output.
    pub csv: Option<PathBuf>,
}

/// Runs a sweep; returns the exit code.
pub fn run_cli(args: SweepArgs) -> ExitCode {
    eprintln!("error: sweep is not implemented yet ({})", args.case.display());
    ExitCode::from(1)
}
