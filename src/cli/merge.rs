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
//! The merged file holds one line per design, sorted by index, exactly as one unsharded
//! `flexfem sweep CASE --out OUT` writes it; the model notes the lines refer to go into
//! `OUT.notes.json`, gathered from the shards' notes files. When designs are missing, they are
//! listed and nothing is written (exit 1), unless `--allow-missing`, which writes the designs
//! that are there (still exit 1). A complete merge with error rows is written and exits 1,
//! like the sweep itself. Exit 0 only for a complete, consistent merge without error rows.

use super::resume::same_value;
use super::sweep::notes_path;
use super::targets::{check_replaceable, io_context, Kind, Stop};
use crate::case::sweep::Sweep;
use crate::design::sweep::{design_hash, load, Shard};
use crate::output::{write_atomic, EXIT_BAD_CASE, EXIT_FAILED};
use serde_json::{Map, Value};
use std::collections::BTreeMap;
use std::fs;
use std::io;
use std::path::{Path, PathBuf};
use std::process::ExitCode;

/// Command-line arguments of `flexfem merge`.
#[derive(Debug, Clone, clap::Args)]
pub struct MergeArgs {
    /// The merged file to write (one line per design, sorted by index).
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

/// One kept line.
struct Kept {
    text: String,
    value: Value,
    origin: Origin,
}

/// The lines of the shard files, checked against the sweep.
#[derive(Default)]
struct Merged {
    lines: BTreeMap<usize, Kept>,
    /// Identical duplicate lines (not kept).
    duplicates: usize,
    /// Model notes from the shards' notes files, by reference.
    notes: Map<String, Value>,
}

impl Merged {
    /// Adds the lines of `text` (the content of `file`); the first line that does not belong
    /// to `sweep` or conflicts with an earlier one is the error.
    fn add(&mut self, sweep: &Sweep, base_dir: Option<&Path>, file: &Path, text: &str) -> Result<(), String> {
        for (k, raw) in text.lines().enumerate() {
            if raw.trim().is_empty() {
                continue;
            }
            let origin = Origin {
                file: file.to_path_buf(),
                line: k + 1,
            };
            let value: Value = serde_json::from_str(raw).map_err(|e| {
                format!("{origin} is not a sweep line ({e}); a torn line of a killed task? rerun that shard (flexfem sweep … --out FILE resumes it)")
            })?;
            let index = value
                .get("index")
                .and_then(Value::as_u64)
                .ok_or_else(|| format!("{origin} has no \"index\"; it is not a flexfem sweep line"))?
                as usize;
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
            match self.lines.get(&index) {
                Some(first) if first.text == raw || same_value(&first.value, &value) => self.duplicates += 1,
                Some(first) => {
                    return Err(format!(
                        "design {index} has two different lines: {} and {origin}; remove the wrong file \
                         (or rerun its shard) and merge again",
                        first.origin
                    ))
                }
                None => {
                    self.lines.insert(
                        index,
                        Kept {
                            text: raw.to_string(),
                            value,
                            origin,
                        },
                    );
                }
            }
        }
        Ok(())
    }

    /// Adds the notes file of shard `file`, if there is one.
    fn add_notes(&mut self, file: &Path) -> Result<(), String> {
        let path = notes_path(file);
        let bytes = match fs::read(&path) {
            Ok(b) => b,
            Err(e) if e.kind() == io::ErrorKind::NotFound => return Ok(()),
            Err(e) => return Err(format!("cannot read {}: {e}", path.display())),
        };
        let Ok(Value::Object(map)) = serde_json::from_slice::<Value>(&bytes) else {
            return Err(format!(
                "{} is not a flexfem notes file (a JSON object)",
                path.display()
            ));
        };
        for (r, notes) in map {
            match self.notes.get(&r) {
                Some(old) if *old != notes => {
                    return Err(format!(
                        "{} holds other model notes under reference {r} than an earlier shard's notes file",
                        path.display()
                    ))
                }
                Some(_) => {}
                None => {
                    self.notes.insert(r, notes);
                }
            }
        }
        Ok(())
    }

    /// The notes the kept lines refer to, in order of first reference by index; a reference
    /// no notes file holds is an error.
    fn referenced_notes(&self) -> Result<Map<String, Value>, String> {
        let mut out = Map::new();
        for kept in self.lines.values() {
            let Some(r) = kept.value.pointer("/result/model_notes").and_then(Value::as_str) else {
                continue;
            };
            match self.notes.get(r) {
                Some(n) => {
                    out.entry(r.to_string()).or_insert_with(|| n.clone());
                }
                None => {
                    return Err(format!(
                        "{} refers to model notes {r}, which no shard's notes file holds (copy \
                         SHARD.jsonl.notes.json beside each shard file)",
                        kept.origin
                    ))
                }
            }
        }
        Ok(out)
    }
}

/// The missing indices, compactly: the first few, and the shard `K/N` they make up when they
/// are exactly one whole shard (N ≤ 64) — a task that never ran or did not finish.
fn describe_missing(missing: &[usize], len: usize) -> String {
    let mut text: Vec<String> = missing.iter().take(12).map(usize::to_string).collect();
    if missing.len() > 12 {
        text.push("…".into());
    }
    let mut s = text.join(", ");
    let whole = (2..=64.min(len)).find_map(|n| {
        let shard = Shard::new(missing[0] % n + 1, n).ok()?;
        (shard.count(len) == missing.len() && missing.iter().all(|&i| shard.contains(i))).then_some(shard)
    });
    if let Some(shard) = whole {
        s += &format!(
            " (all of shard {shard}: rerun it, e.g. flexfem sweep CASE --shard {shard} --out FILE, and merge again)"
        );
    }
    s
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
    for (label, p) in [("the case file", &args.case)]
        .into_iter()
        .chain(args.shards.iter().map(|s| ("a shard file", s)))
    {
        if crate::output::same_file(out, p) || crate::output::same_file(&out_notes, p) {
            return Err(Stop::Usage(format!(
                "{} is {label}; merge writes a new file — choose another OUT",
                p.display()
            )));
        }
    }
    check_replaceable("OUT", out, Kind::Jsonl, args.force)?;
    let _lock = crate::output::Lock::acquire(out).map_err(|e| io::Error::other(e.to_string()))?;

    let mut merged = Merged::default();
    for file in &args.shards {
        let text = fs::read_to_string(file).map_err(|e| Stop::Usage(format!("cannot read {}: {e}", file.display())))?;
        merged.add(&sweep, base_dir, file, &text).map_err(Stop::Usage)?;
        merged.add_notes(file).map_err(Stop::Usage)?;
    }
    let notes = merged.referenced_notes().map_err(Stop::Usage)?;
    let missing: Vec<usize> = (0..sweep.len()).filter(|i| !merged.lines.contains_key(i)).collect();
    let errors = merged.lines.values().filter(|k| k.value.get("error").is_some()).count();
    let summary = format!(
        "merge: {} of {} designs from {} files, {} identical duplicate lines dropped, {errors} error rows",
        merged.lines.len(),
        sweep.len(),
        args.shards.len(),
        merged.duplicates
    );
    if !missing.is_empty() {
        eprintln!("{summary}");
        eprintln!(
            "error: {} of {} designs missing: {}",
            missing.len(),
            sweep.len(),
            describe_missing(&missing, sweep.len())
        );
        if !args.allow_missing {
            eprintln!("error: nothing written (--allow-missing writes the designs that are there)");
            return Ok(EXIT_FAILED);
        }
    }
    let mut text = String::with_capacity(merged.lines.values().map(|k| k.text.len() + 1).sum());
    for kept in merged.lines.values() {
        text.push_str(&kept.text);
        text.push('\n');
    }
    if !notes.is_empty() {
        let body = serde_json::to_string_pretty(&notes).map_err(io::Error::other)?;
        write_atomic(&out_notes, body.as_bytes()).map_err(io_context("write", &out_notes))?;
    }
    write_atomic(out, text.as_bytes()).map_err(io_context("write", out))?;
    if missing.is_empty() {
        eprintln!("{summary} → {}", out.display());
    } else {
        eprintln!(
            "wrote the {} designs that are there to {}",
            merged.lines.len(),
            out.display()
        );
    }
    if errors > 0 {
        eprintln!("error: {errors} designs failed (their lines hold an \"error\"; exit code 1)");
    }
    Ok(if missing.is_empty() && errors == 0 {
        0
    } else {
        EXIT_FAILED
    })
}
