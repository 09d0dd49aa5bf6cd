use clap::Parser;
use std::process::ExitCode;

fn main() -> ExitCode {
    flexfem::cli::run(flexfem::cli::Cli::parse())
}
