//! The parts of `flexfem merge` that gather as the lines go by: the model notes the merged
//! lines refer to, and the missing designs.

use super::super::sweep::notes_path;
use crate::design::sweep::Shard;
use serde_json::{Map, Value};
use std::fmt;
use std::fs;
use std::io;
use std::path::Path;

/// Model notes from the shards' notes files, by reference.
#[derive(Default)]
pub(super) struct Notes {
    all: Map<String, Value>,
    /// The ones the merged lines refer to, in order of first reference by index.
    pub(super) used: Map<String, Value>,
}

impl Notes {
    /// Adds the notes file of shard `file`, if there is one.
    pub(super) fn add(&mut self, file: &Path) -> Result<(), String> {
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
            match self.all.get(&r) {
                Some(old) if *old != notes => {
                    return Err(format!(
                        "{} holds other model notes under reference {r} than an earlier shard's notes file",
                        path.display()
                    ))
                }
                Some(_) => {}
                None => {
                    self.all.insert(r, notes);
                }
            }
        }
        Ok(())
    }

    /// Records the notes the line `value` (at `origin`) refers to; a reference no notes file
    /// holds is an error.
    pub(super) fn use_in(&mut self, value: &Value, origin: &dyn fmt::Display) -> Result<(), String> {
        let Some(r) = value.pointer("/result/model_notes").and_then(Value::as_str) else {
            return Ok(());
        };
        if self.used.contains_key(r) {
            return Ok(());
        }
        match self.all.get(r) {
            Some(n) => {
                self.used.insert(r.to_string(), n.clone());
                Ok(())
            }
            None => Err(format!(
                "{} refers to model notes {r}, which no shard's notes file holds (copy \
                 SHARD.jsonl.notes.json beside each shard file)",
                origin
            )),
        }
    }
}

/// The missing designs, counted as they are found: the first few, and for each shard count
/// N ≤ 64 whether all of them so far lie in one shard of N.
pub(super) struct Missing {
    pub(super) count: usize,
    first: Vec<usize>,
    /// (N, residue of the first missing index) for the N still possible.
    one_shard: Vec<(usize, usize)>,
}

impl Missing {
    pub(super) fn new() -> Self {
        Missing {
            count: 0,
            first: Vec::new(),
            one_shard: Vec::new(),
        }
    }

    pub(super) fn add(&mut self, index: usize, len: usize) {
        if self.count == 0 {
            self.one_shard = (2..=64.min(len)).map(|n| (n, index % n)).collect();
        }
        self.count += 1;
        if self.first.len() < 12 {
            self.first.push(index);
        }
        self.one_shard.retain(|&(n, r)| index % n == r);
    }

    /// The missing indices, compactly: the first few, and the shard `K/N` they make up when
    /// they are exactly one whole shard — a task that never ran or did not finish.
    pub(super) fn describe(&self, len: usize) -> String {
        let mut text: Vec<String> = self.first.iter().map(usize::to_string).collect();
        if self.count > self.first.len() {
            text.push("…".into());
        }
        let mut s = text.join(", ");
        let whole = self.one_shard.iter().find_map(|&(n, r)| {
            let shard = Shard::new(r + 1, n).ok()?;
            (shard.count(len) == self.count).then_some(shard)
        });
        if let Some(shard) = whole {
            s += &format!(
                " (all of shard {shard}: rerun it, e.g. flexfem sweep CASE --shard {shard} --out FILE, and merge again)"
            );
        }
        s
    }
}
