//! The resume store of `flexfem sweep --out FILE.jsonl`: which designs earlier output already
//! holds.
//!
//! A re-run skips every design whose line is already in `FILE.jsonl` or its partial file
//! (complete, parseable lines whose `params` and `design_hash` match this sweep; a torn last
//! line is ignored). A line whose hash differs (the base case or its mesh changed) is stale and
//! its design runs again; error rows run again too unless `--keep-errors`. Lines are read from
//! disk as JSON: that is the file format.

use crate::case::sweep::Sweep;
use crate::design::sweep::{design_hash, Shard};
use serde::Deserialize;
use serde_json::{Map, Value};
use std::collections::{BTreeMap, HashMap, HashSet};
use std::fs;
use std::io;
use std::path::Path;

/// The leading fields of a sweep line (the rest is skipped, though still checked as JSON).
#[derive(Deserialize)]
struct Head {
    index: usize,
    params: Map<String, Value>,
    #[serde(default)]
    design_hash: Option<String>,
    #[serde(default)]
    error: Option<serde::de::IgnoredAny>,
}

/// How earlier lines are judged.
#[derive(Debug, Clone, Copy)]
pub struct Accept<'a> {
    /// Folder of the sweep file (mesh files resolve against it for the design hash).
    pub base_dir: Option<&'a Path>,
    /// Keep error rows (else they are dropped, so those designs run again).
    pub keep_errors: bool,
}

/// Finished lines found in earlier output.
#[derive(Debug, Clone, Default)]
pub struct Finished {
    /// index → line (no newline), as found; a later line for the same index replaces an
    /// earlier one (files are read oldest first). Lines of every shard of this sweep are kept,
    /// so shards run one after another into the same file accumulate there.
    pub lines: BTreeMap<usize, String>,
    /// Indices whose kept line is an error row.
    pub failed: HashSet<usize>,
    /// Complete lines not kept: another sweep (index out of range or other parameters).
    pub foreign: usize,
    /// Lines of this sweep's designs whose `design_hash` differs or is missing: the base case,
    /// a mesh file or flexfem's line format changed since they were written.
    pub stale: usize,
    /// Error rows not kept (their designs run again).
    pub errors: usize,
    /// Lines that are not a sweep line at all (e.g. a torn last line).
    pub unreadable: usize,
}

/// Numbers compare to 1e-12 relative: a value read back from a file may differ from the
/// sweep's own in the last bit (serde_json does not round-trip every float exactly).
pub(super) fn same_value(a: &Value, b: &Value) -> bool {
    match (a, b) {
        (Value::Number(x), Value::Number(y)) => match (x.as_f64(), y.as_f64()) {
            (Some(x), Some(y)) => x == y || (x - y).abs() <= 1e-12 * x.abs().max(y.abs()),
            _ => x == y,
        },
        (Value::Array(x), Value::Array(y)) => x.len() == y.len() && x.iter().zip(y).all(|(a, b)| same_value(a, b)),
        (Value::Object(x), Value::Object(y)) => {
            x.len() == y.len() && x.iter().all(|(k, a)| y.get(k).is_some_and(|b| same_value(a, b)))
        }
        _ => a == b,
    }
}

/// The non-blank lines of `text`, a final `\r` dropped.
fn lines_of(text: &[u8]) -> impl Iterator<Item = &[u8]> {
    text.split(|&b| b == b'\n')
        .filter(|raw| !raw.iter().all(u8::is_ascii_whitespace))
        .map(|raw| raw.strip_suffix(b"\r").unwrap_or(raw))
}

fn head(raw: &[u8]) -> Option<(&str, Head)> {
    let line = std::str::from_utf8(raw).ok()?;
    serde_json::from_str::<Head>(line).ok().map(|h| (line, h))
}

/// True when `text` is flexfem sweep output: every complete line is a sweep line
/// (`{"index", "params", …}`); a torn last line (no newline) is allowed. Empty text counts.
/// On `false`, also returns the 1-based number of the first foreign line.
pub fn is_sweep_output(text: &[u8]) -> Result<(), usize> {
    let all = text.split(|&b| b == b'\n').count();
    let ends_in_newline = text.last() == Some(&b'\n');
    for (k, raw) in text.split(|&b| b == b'\n').enumerate() {
        if raw.iter().all(u8::is_ascii_whitespace) || (k + 1 == all && !ends_in_newline) {
            continue;
        }
        if head(raw.strip_suffix(b"\r").unwrap_or(raw)).is_none() {
            return Err(k + 1);
        }
    }
    Ok(())
}

impl Finished {
    /// Collects the lines of `text` that belong to `sweep`.
    pub fn add_text(&mut self, sweep: &Sweep, accept: Accept, text: &[u8]) {
        self.add_text_trusting(sweep, accept, text, &|_| false);
    }

    /// [`Self::add_text`], taking the `design_hash` of the designs `trusted(index)` names as
    /// right without computing it (lines the caller knows it wrote, or checked already).
    fn add_text_trusting(&mut self, sweep: &Sweep, accept: Accept, text: &[u8], trusted: &dyn Fn(usize) -> bool) {
        let mut hashes: HashMap<usize, Option<String>> = HashMap::new();
        for raw in lines_of(text) {
            let Some((line, head)) = head(raw) else {
                self.unreadable += 1;
                continue;
            };
            let i = head.index;
            let ours = i < sweep.len() && same_value(&Value::Object(head.params), &Value::Object(sweep.params(i)));
            if !ours {
                self.foreign += 1;
                continue;
            }
            let stale = head.design_hash.is_none()
                || (!trusted(i)
                    && head.design_hash
                        != *hashes
                            .entry(i)
                            .or_insert_with(|| design_hash(sweep, accept.base_dir, i)));
            if stale {
                self.stale += 1;
                continue;
            }
            let is_error = head.error.is_some();
            if is_error && !accept.keep_errors {
                self.errors += 1;
                continue;
            }
            if is_error {
                self.failed.insert(i);
            } else {
                self.failed.remove(&i);
            }
            self.lines.insert(i, line.to_string());
        }
    }

    /// Collects the lines of each file that exists, in order (a later file's line for an
    /// index replaces an earlier one).
    pub fn read(sweep: &Sweep, accept: Accept, files: &[&Path]) -> io::Result<Self> {
        Self::read_trusting(sweep, accept, files, &|_| false)
    }

    /// [`Self::read`] trusting the `design_hash` of the designs `trusted(index)` names. A sweep
    /// merging its output at the end trusts the designs of its shard: each of their lines was
    /// either written by this run or checked when the run started (the output is locked), and
    /// any line found wrong then was run again and is replaced by the new one.
    pub fn read_trusting(
        sweep: &Sweep,
        accept: Accept,
        files: &[&Path],
        trusted: &dyn Fn(usize) -> bool,
    ) -> io::Result<Self> {
        let mut f = Finished::default();
        for path in files {
            match fs::read(path) {
                Ok(bytes) => f.add_text_trusting(sweep, accept, &bytes, trusted),
                Err(e) if e.kind() == io::ErrorKind::NotFound => {}
                Err(e) => return Err(io::Error::new(e.kind(), format!("cannot read {}: {e}", path.display()))),
            }
        }
        Ok(f)
    }

    /// True when nothing at all was found (no line, not even a foreign or unreadable one).
    pub fn is_nothing(&self) -> bool {
        self.lines.is_empty() && self.foreign == 0 && self.stale == 0 && self.errors == 0 && self.unreadable == 0
    }

    /// How many of the kept lines belong to `shard`.
    pub fn in_shard(&self, shard: Shard) -> usize {
        self.lines.keys().filter(|&&i| shard.contains(i)).count()
    }

    /// The lines sorted by index, one per line with a final newline.
    pub fn to_jsonl(&self) -> Vec<u8> {
        let mut out = Vec::with_capacity(self.lines.values().map(|l| l.len() + 1).sum());
        for line in self.lines.values() {
            out.extend_from_slice(line.as_bytes());
            out.push(b'\n');
        }
        out
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn sweep_output_recognition() {
        assert_eq!(is_sweep_output(b""), Ok(()));
        assert_eq!(
            is_sweep_output(b"{\"index\":0,\"params\":{}}\n{\"index\":1,\"params\":{}"),
            Ok(())
        );
        assert_eq!(is_sweep_output(b"{\"index\":0,\"params\":{}}\nhello\n"), Err(2));
        assert_eq!(is_sweep_output(b"{\"a\":1}\n"), Err(1));
    }
}
