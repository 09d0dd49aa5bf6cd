//! The end of `flexfem sweep --out FILE.jsonl`: every line of the output (earlier ones and this
//! run's), sorted by index, replaces `FILE.jsonl` atomically; then the files of the base case's
//! analysis beside it (a stage sweep's table and plot) and the `--csv` table.

use super::resume::{Accept, Finished};
use super::targets::{io_context, Stop};
use crate::analysis::kind::SweepFile;
use crate::analysis::units::UnitOf;
use crate::case::sweep::Sweep;
use crate::design::sweep::Shard;
use crate::design::table;
use crate::output::write_atomic;
use serde_json::Value;
use std::fs;
use std::io;
use std::path::{Path, PathBuf};

/// The lines this run wrote, kept in memory when the output held nothing before the run: the
/// output is then exactly these lines, and reading the partial file back (parsing every line
/// again) is skipped. One text holds them all (no allocation per line).
#[derive(Debug, Default)]
pub(super) struct Written {
    text: String,
    /// (index, error row?, start and end of the line in `text`).
    rows: Vec<(usize, bool, usize, usize)>,
}

impl Written {
    /// Keeps line `text` of design `index`.
    pub(super) fn push(&mut self, index: usize, failed: bool, text: &str) {
        let start = self.text.len();
        self.text.push_str(text);
        self.rows.push((index, failed, start, self.text.len()));
    }
}

/// Where the output goes and what was there before the run.
pub(super) struct Output<'a> {
    pub out: &'a Path,
    pub partial: &'a Path,
    /// Earlier output files, oldest first (without the partial file).
    pub sources: Vec<&'a Path>,
    pub accept: Accept<'a>,
    /// This run's lines when the output held none before ([`Written`]).
    pub written: Option<Written>,
}

/// Writes the output file and the extra files; returns the number of error rows of `shard` in
/// the output and the `--csv` table when `want_csv`.
pub(super) fn finish(
    sweep: &Sweep,
    shard: Shard,
    o: Output,
    extras: &[(SweepFile, PathBuf)],
    want_csv: bool,
) -> Result<(usize, Option<String>), Stop> {
    let in_shard = shard.count(sweep.len());
    let all = match o.written {
        Some(written) => {
            let mut all = Finished::default();
            for &(i, failed, start, end) in &written.rows {
                if failed {
                    all.failed.insert(i);
                }
                all.lines.insert(i, written.text[start..end].to_string());
            }
            all
        }
        None => {
            // Oldest first, so the lines just written replace retried or stale ones.
            let mut sources = o.sources;
            sources.retain(|p| *p != o.partial);
            sources.push(o.partial);
            Finished::read_trusting(
                sweep,
                Accept {
                    keep_errors: true,
                    ..o.accept
                },
                &sources,
                &|i| shard.contains(i),
            )?
        }
    };
    let failed = all.failed.iter().filter(|&&i| shard.contains(i)).count();
    write_atomic(o.out, &all.to_jsonl()).map_err(io_context("write", o.out))?;
    fs::remove_file(o.partial).or_else(|e| match e.kind() {
        io::ErrorKind::NotFound => Ok(()),
        _ => Err(e),
    })?;
    let held = all.in_shard(shard);
    if held != in_shard {
        eprintln!("warning: {} holds {held} of the {in_shard} designs", o.out.display());
    }
    // Files of the base case's analysis beside the JSON lines (a stage sweep's plot and
    // table); the table is made once for them and for --csv.
    let lines: Vec<String> = all.lines.into_values().collect();
    let axes: Vec<&str> = sweep.axes.iter().map(|(p, _)| p.as_str()).collect();
    let table = (want_csv || extras.iter().any(|(f, _)| f.table)).then(|| {
        let refs: Vec<&str> = lines.iter().map(String::as_str).collect();
        table::csv_with_units(&axes, &refs, units_of(sweep))
    });
    for (file, p) in extras {
        let text = if file.table {
            table.clone()
        } else {
            sweep_kind(sweep).and_then(|a| a.render_sweep_file(file, &lines))
        };
        if let Some(text) = text {
            write_atomic(p, text.as_bytes()).map_err(io_context("write", p))?;
        }
    }
    Ok((failed, table.filter(|_| want_csv)))
}

/// The column units of the sweep's analysis kind ([`crate::analysis::Analysis::column_units`]).
pub(super) fn units_of(sweep: &Sweep) -> Option<(UnitOf, UnitOf)> {
    sweep_kind(sweep).and_then(|a| a.column_units())
}

/// The registered analysis of a sweep's base case.
fn sweep_kind(sweep: &Sweep) -> Option<&'static dyn crate::analysis::DynAnalysis> {
    sweep
        .base
        .get("analysis")
        .and_then(Value::as_str)
        .and_then(crate::analysis::registry::find)
}
