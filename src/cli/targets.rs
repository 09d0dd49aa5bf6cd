//! The files `flexfem sweep` writes, checked before anything runs: never the case file, never
//! one path twice, never a file that is not flexfem's own output (unless `--force`).

use super::resume::is_sweep_output;
use crate::analysis::kind::SweepFile;
use crate::case::sweep::Sweep;
use crate::design::sweep::with_suffix;
use serde_json::Value;
use std::fs;
use std::io;
use std::path::{Path, PathBuf};

/// Why a sweep did not finish.
pub(super) enum Stop {
    /// Refused before running anything (output paths): exit 2.
    Usage(String),
    /// Lock held, or reading/writing failed: exit 1.
    Io(io::Error),
}

impl From<io::Error> for Stop {
    fn from(e: io::Error) -> Self {
        Stop::Io(e)
    }
}

/// What an output file must look like for flexfem to replace it without `--force`.
#[derive(Clone, Copy)]
pub(super) enum Kind {
    /// Sweep JSON lines.
    Jsonl,
    /// A sweep CSV table (header starting with `index`).
    Csv,
    /// An SVG plot.
    Svg,
}

/// `Ok(())` when `text` looks like flexfem's own output of `kind`, else why not.
fn own_output(kind: Kind, text: &[u8]) -> Result<(), String> {
    match kind {
        Kind::Jsonl => is_sweep_output(text).map_err(|n| format!("line {n} is not a flexfem sweep line")),
        Kind::Csv => {
            if text.is_empty() || text.starts_with(b"index,") || text.starts_with(b"index\n") {
                Ok(())
            } else {
                Err("it is not a flexfem sweep table (header `index,…`)".into())
            }
        }
        Kind::Svg => {
            let t = text.trim_ascii_start();
            if text.is_empty() || t.starts_with(b"<svg") || t.starts_with(b"<?xml") {
                Ok(())
            } else {
                Err("it is not an SVG plot".into())
            }
        }
    }
}

/// Refuses to replace `path` when it exists and is not flexfem's own output of `kind`, unless
/// `force`. Returns true when the file exists and may be read as earlier output.
pub(super) fn check_replaceable(label: &str, path: &Path, kind: Kind, force: bool) -> Result<bool, Stop> {
    let meta = match fs::metadata(path) {
        Ok(m) => m,
        Err(e) if e.kind() == io::ErrorKind::NotFound => return Ok(false),
        Err(e) => return Err(io_context("read", path)(e).into()),
    };
    if !meta.is_file() {
        return Err(Stop::Usage(format!(
            "{label} {} exists and is not a regular file",
            path.display()
        )));
    }
    let text = fs::read(path).map_err(io_context("read", path))?;
    match own_output(kind, &text) {
        Ok(()) => Ok(true),
        Err(_) if force => {
            eprintln!("note: --force: replacing {}", path.display());
            Ok(false)
        }
        Err(why) => Err(Stop::Usage(format!(
            "{label} {} exists and {why}; flexfem replaces only its own output — choose another \
             file or pass --force to replace it",
            path.display()
        ))),
    }
}

/// The files a sweep writes, checked against each other and the case file.
pub(super) struct Targets {
    pub(super) out: Option<PathBuf>,
    pub(super) partial: Option<PathBuf>,
    pub(super) csv: Option<PathBuf>,
    /// The files the base case's analysis writes beside `--out` (e.g. a stage sweep's plot and
    /// table), with their paths.
    pub(super) extras: Vec<(SweepFile, PathBuf)>,
}

impl Kind {
    /// The kind of an extra file of a sweep.
    pub(super) fn of(file: &SweepFile) -> Kind {
        if file.table || file.extension == "csv" {
            Kind::Csv
        } else {
            Kind::Svg
        }
    }
}

impl Targets {
    /// The files of a sweep run on `case` with `--out` and `--csv` as given.
    pub(super) fn new(sweep: &Sweep, case: &Path, out: Option<&Path>, csv: Option<&Path>) -> Result<Self, Stop> {
        let files = sweep
            .base
            .get("analysis")
            .and_then(Value::as_str)
            .and_then(crate::analysis::registry::find)
            .map(|a| a.sweep_files())
            .unwrap_or(&[]);
        let out = out.map(Path::to_path_buf);
        let t = Targets {
            partial: out.as_deref().map(|p| with_suffix(p, ".partial")),
            extras: match out.as_deref() {
                Some(p) => files
                    .iter()
                    .filter(|f| !(f.table && csv.is_some()))
                    .map(|f| (*f, p.with_extension(f.extension)))
                    .collect(),
                None => Vec::new(),
            },
            csv: csv.map(Path::to_path_buf),
            out,
        };
        let lock = t.out.as_deref().map(|p| with_suffix(p, ".lock"));
        let named: Vec<(&str, &Path)> = [
            ("the case file", Some(case)),
            ("--out", t.out.as_deref()),
            ("--csv", t.csv.as_deref()),
            ("the partial file", t.partial.as_deref()),
            ("the lock file", lock.as_deref()),
        ]
        .into_iter()
        .filter_map(|(l, p)| p.map(|p| (l, p)))
        .chain(t.extras.iter().map(|(f, p)| (f.label, p.as_path())))
        .collect();
        for (k, (la, a)) in named.iter().enumerate() {
            for (lb, b) in &named[k + 1..] {
                if crate::output::same_file(a, b) {
                    return Err(Stop::Usage(format!(
                        "{la} and {lb} are the same file ({}); give different paths",
                        b.display()
                    )));
                }
            }
        }
        Ok(t)
    }
}

pub(super) fn io_context(what: &'static str, path: &Path) -> impl FnOnce(io::Error) -> io::Error {
    let path = path.to_path_buf();
    move |e| io::Error::new(e.kind(), format!("cannot {what} {}: {e}", path.display()))
}
