//! `flexfem merge OUT.jsonl SHARD.jsonl … --case CASE.json`: the shard files of a sweep (e.g.
//! the tasks of a Slurm job array) combined into one file, checked against the sweep case.
//!
//! Every line of every shard file must be a line of this sweep: its `index` in range, its
//! `params` those of that design, and its `design_hash` the hash of that design as the case
//! and its mesh file are now (see [`crate::design::sweep`]). A line of another sweep, of another
//! base case or mesh file, or of an older line format, or a line that is not a sweep line at
//! all, is refused, naming the file and line; nothing is written (exit 2). A design found in
//! two lines is a duplicate: identical lines (same text, or the same JSON values to 1e-12
//! relative) are counted and one is kept; different lines are refused, naming both (exit 2).
//!
//! The shard files are read as they come, one line of each at a time (a k-way merge by index),
//! so memory stays small for sweeps of any size: each file must be sorted by index, as every
//! finished `flexfem sweep --out` file is. An unfinished shard's `.partial` file is not (its
//! lines are in completion order): it is refused, naming the line — rerun that shard, which
//! resumes from it, and merge the finished file.
//!
//! The merged file holds one line per design, sorted by index, exactly as one unsharded
//! `flexfem sweep CASE --out OUT` writes it; the model notes the lines refer to go into
//! `OUT.notes.json`, gathered from the shards' notes files. When designs are missing, they are
//! listed and nothing is written (exit 1), unless `--allow-missing`, which writes the designs
//! that are there (still exit 1). A complete merge with error rows is written and exits 1,
//! like the sweep itself. Exit 0 only for a complete, consistent merge without error rows.

mod gather;

use super::resume::same_value;
use super::sweep::notes_path;
use super::targets::{check_replaceable, io_context, Kind, Stop};
use crate::case::sweep::Sweep;
use crate::design::sweep::{design_hash, load};
use crate::output::{write_atomic, EXIT_BAD_CASE, EXIT_FAILED};
use gather::{Missing, Notes};
use serde_json::Value;
use std::cmp::Reverse;
use std::collections::BinaryHeap;
use std::fs::{self, File};
use std::io::{self, BufRead, BufReader, BufWriter, Write};
use std::path::{Path, PathBuf};
use std::process::ExitCode;

/// Command-line arguments of `flexfem merge`.
#[derive(Debug, Clone, clap::Args)]
pub struct MergeArgs {
    /// The merged file to write (one line per design, sorted by index).
    #[arg(value_name = "OUT.jsonl")]
    pub out: PathBuf,
    /// The shard files, e.g. shard_1.jsonl … shard_N.jsonl (each `flexfem sweep --out` output).
    #[arg(required = true, value_name = "SHARD.jsonl")]
    pub shards: Vec<PathBuf>,
    /// The sweep case the shards were run from (gives the designs and their hashes).
    #[arg(long, value_name = "CASE.json")]
    pub case: PathBuf,
    /// Write the designs that are there even when some are missing (the exit status stays 1).
    #[arg(long)]
    pub allow_missing: bool,
    /// Replace OUT even when it is not flexfem's own sweep output.
    #[arg(long)]
    pub force: bool,
}

/// Where a line came from: file and 1-based line number.
#[derive(Debug, Clone)]
struct Origin {
    file: PathBuf,
    line: usize,
}

impl std::fmt::Display for Origin {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        write!(f, "{} line {}", self.file.display(), self.line)
    }
}

/// One checked line of a shard file.
struct Line {
    index: usize,
    text: String,
    value: Value,
    origin: Origin,
}

/// Checks `raw` (line `origin` of a shard file) against `sweep`: index in range, the params
/// of that design, and its design hash as the case now is.
fn check_line(sweep: &Sweep, base_dir: Option<&Path>, raw: String, origin: Origin) -> Result<Line, String> {
    let value: Value = serde_json::from_str(&raw).map_err(|e| {
        format!("{origin} is not a sweep line ({e}); a torn line of a killed task? rerun that shard (flexfem sweep … --out FILE resumes it)")
    })?;
    let index = value
        .get("index")
        .and_then(Value::as_u64)
        .ok_or_else(|| format!("{origin} has no \"index\"; it is not a flexfem sweep line"))? as usize;
    let params = value.get("params").cloned().unwrap_or(Value::Null);
    if index >= sweep.len() || !same_value(&params, &Value::Object(sweep.params(index))) {
        return Err(format!(
            "{origin} (index {index}, params {params}) is not a design of this sweep ({} designs): \
             a line of another sweep case",
            sweep.len()
        ));
    }
    let want = design_hash(sweep, base_dir, index);
    let got = value.get("design_hash").and_then(Value::as_str);
    if got != want.as_deref() {
        return Err(format!(
            "{origin} (index {index}) has design_hash {} but this case's design {index} hashes to {}: \
             the line was written from another base case or mesh file, or by an older flexfem \
             (stale); rerun that shard",
            got.unwrap_or("(none)"),
            want.as_deref().unwrap_or("(none: the design cannot be built)")
        ));
    }
    Ok(Line {
        index,
        text: raw,
        value,
        origin,
    })
}

/// A shard file read line by line, checked, in index order.
struct Reader<'a> {
    file: &'a Path,
    lines: io::Lines<BufReader<File>>,
    number: usize,
    last: Option<usize>,
}

impl<'a> Reader<'a> {
    fn open(file: &'a Path) -> Result<Self, String> {
        let f = File::open(file).map_err(|e| format!("cannot read {}: {e}", file.display()))?;
        Ok(Reader {
            file,
            lines: BufReader::new(f).lines(),
            number: 0,
            last: None,
        })
    }

    /// The next non-blank line, checked; refuses a line whose index is below the previous one.
    fn next(&mut self, sweep: &Sweep, base_dir: Option<&Path>) -> Result<Option<Line>, String> {
        for raw in self.lines.by_ref() {
            self.number += 1;
            let origin = Origin {
                file: self.file.to_path_buf(),
                line: self.number,
            };
            let raw = raw.map_err(|e| format!("cannot read {origin}: {e}"))?;
            if raw.trim().is_empty() {
                continue;
            }
            let line = check_line(sweep, base_dir, raw, origin)?;
            if let Some(last) = self.last.filter(|&l| l > line.index) {
                return Err(format!(
                    "{} (index {}) follows index {last}: the file is not sorted by index, as a finished \
                     sweep file is (an unfinished shard's .partial file?) — rerun that shard (it resumes) \
                     and merge its finished file",
                    line.origin, line.index
                ));
            }
            self.last = Some(line.index);
            return Ok(Some(line));
        }
        Ok(None)
    }
}

/// What the merge found.
struct Tally {
    lines: usize,
    duplicates: usize,
    errors: usize,
    missing: Missing,
}

/// Merges the shard files into `sink` by index; every line checked (see the module notes).
fn merge_into(
    sweep: &Sweep,
    base_dir: Option<&Path>,
    files: &[PathBuf],
    notes: &mut Notes,
    sink: &mut impl Write,
) -> Result<Tally, Stop> {
    let usage = Stop::Usage;
    let mut readers = files
        .iter()
        .map(|f| Reader::open(f))
        .collect::<Result<Vec<_>, _>>()
        .map_err(usage)?;
    let mut heads: Vec<Option<Line>> = Vec::with_capacity(readers.len());
    let mut heap = BinaryHeap::new();
    for (k, r) in readers.iter_mut().enumerate() {
        let head = r.next(sweep, base_dir).map_err(usage)?;
        if let Some(l) = &head {
            heap.push(Reverse((l.index, k)));
        }
        heads.push(head);
    }
    let mut tally = Tally {
        lines: 0,
        duplicates: 0,
        errors: 0,
        missing: Missing::new(),
    };
    let mut prev: Option<Line> = None;
    let mut expect = 0;
    while let Some(Reverse((index, k))) = heap.pop() {
        let Some(line) = heads[k].take() else { continue };
        heads[k] = readers[k].next(sweep, base_dir).map_err(usage)?;
        if let Some(l) = &heads[k] {
            heap.push(Reverse((l.index, k)));
        }
        if let Some(p) = prev.as_ref().filter(|p| p.index == index) {
            if p.text == line.text || same_value(&p.value, &line.value) {
                tally.duplicates += 1;
                continue;
            }
            return Err(usage(format!(
                "design {index} has two different lines: {} and {}; remove the wrong file (or rerun \
                 its shard) and merge again",
                p.origin, line.origin
            )));
        }
        for m in expect..index {
            tally.missing.add(m, sweep.len());
        }
        expect = index + 1;
        notes.use_in(&line.value, &line.origin).map_err(usage)?;
        tally.lines += 1;
        tally.errors += usize::from(line.value.get("error").is_some());
        sink.write_all(line.text.as_bytes())?;
        sink.write_all(b"\n")?;
        prev = Some(line);
    }
    for m in expect..sweep.len() {
        tally.missing.add(m, sweep.len());
    }
    Ok(tally)
}

/// Runs `flexfem merge`; returns the exit code.
pub fn run_cli(args: MergeArgs) -> ExitCode {
    match merge(&args) {
        Ok(code) => ExitCode::from(code),
        Err(Stop::Usage(msg)) => {
            eprintln!("error: {msg}");
            ExitCode::from(EXIT_BAD_CASE)
        }
        Err(Stop::Io(e)) => {
            eprintln!("error: {e}");
            ExitCode::from(EXIT_FAILED)
        }
    }
}

fn merge(args: &MergeArgs) -> Result<u8, Stop> {
    let sweep = load(&args.case).map_err(|e| Stop::Usage(format!("{}: {e}", args.case.display())))?;
    let base_dir = args.case.parent();
    let out = &args.out;
    let out_notes = notes_path(out);
    let inputs = [("the case file", &args.case)]
        .into_iter()
        .chain(args.shards.iter().map(|s| ("a shard file", s)));
    for (label, p) in inputs {
        if crate::output::same_file(out, p) || crate::output::same_file(&out_notes, p) {
            return Err(Stop::Usage(format!(
                "{} is {label}; merge writes a new file — choose another OUT",
                p.display()
            )));
        }
    }
    check_replaceable("OUT", out, Kind::Jsonl, args.force)?;
    let _lock = crate::output::Lock::acquire(out).map_err(|e| io::Error::other(e.to_string()))?;

    let mut notes = Notes::default();
    for file in &args.shards {
        notes.add(file).map_err(Stop::Usage)?;
    }
    // Into a temporary file beside OUT, renamed over it at the end: OUT is untouched unless
    // the merge is written.
    let (tmp_file, tmp) = crate::output::create_temp(out).map_err(io_context("create a file beside", out))?;
    let mut sink = BufWriter::new(tmp_file);
    let merged = merge_into(&sweep, base_dir, &args.shards, &mut notes, &mut sink);
    let finish = |tally: &Tally| -> Result<bool, Stop> {
        if tally.missing.count > 0 && !args.allow_missing {
            return Ok(false);
        }
        let f = sink.into_inner().map_err(|e| e.into_error())?;
        f.sync_all()?;
        drop(f);
        if !notes.used.is_empty() {
            let body = serde_json::to_string_pretty(&notes.used).map_err(io::Error::other)?;
            write_atomic(&out_notes, body.as_bytes()).map_err(io_context("write", &out_notes))?;
        }
        fs::rename(&tmp, out).map_err(io_context("write", out))?;
        Ok(true)
    };
    let written = merged.and_then(|t| finish(&t).map(|w| (t, w)));
    let (tally, written) = match written {
        Ok(x) => x,
        Err(e) => {
            let _ = fs::remove_file(&tmp);
            return Err(e);
        }
    };
    if !written {
        let _ = fs::remove_file(&tmp);
    }
    let summary = format!(
        "merge: {} of {} designs from {} files, {} identical duplicate lines dropped, {} error rows",
        tally.lines,
        sweep.len(),
        args.shards.len(),
        tally.duplicates,
        tally.errors
    );
    let missing = tally.missing.count;
    if missing == 0 {
        eprintln!("{summary} → {}", out.display());
    } else {
        eprintln!("{summary}");
        eprintln!(
            "error: {missing} of {} designs missing: {}",
            sweep.len(),
            tally.missing.describe(sweep.len())
        );
        if written {
            eprintln!("wrote the {} designs that are there to {}", tally.lines, out.display());
        } else {
            eprintln!("error: nothing written (--allow-missing writes the designs that are there)");
        }
    }
    if tally.errors > 0 {
        eprintln!(
            "error: {} designs failed (their lines hold an \"error\"; exit code 1)",
            tally.errors
        );
    }
    Ok(if missing == 0 && tally.errors == 0 {
        0
    } else {
        EXIT_FAILED
    })
}
