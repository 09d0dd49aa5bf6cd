//! The typed route of a sweep: each worker parses the base case once and sets every design's
//! varied numbers in its parsed case ([`DynAnalysis::number_mut`]); the result is written
//! straight into the worker's line buffer ([`DynAnalysis::write_result`]); the design hash is
//! the FNV-1a state of the base case's canonical text, continued over each varied value's text.
//! No JSON value is built and, for hinge and stage sweeps, nothing is allocated per design.
//!
//! The route is taken only where it gives the very lines of the value route ([`super`]): every
//! varied path holds a number in the base case and gets numbers, the kind reaches those numbers
//! in its parsed case, no `--fields`, no mesh file, no parameters or hinge types (whose values
//! the value route resolves and echoes); and the parsed case with the numbers set
//! must equal the parsed design (checked on three designs before the run). A design that fails
//! or panics, or whose notes the route cannot reference, is run again on the value route, so
//! error rows are the value route's too.

use super::format::pointer;
use super::hash::HashTemplate;
use super::{Line, LineFormat, Shapes};
use crate::analysis::line::{LineSpec, LineTarget, ResultLine};
use crate::analysis::{self, Case, Ctx, DynAnalysis};
use crate::case::sweep::Sweep;
use crate::fem::SolverCache;
use serde_json::Value;
use std::io::Write;
use std::path::Path;

/// A sweep ready for the typed route.
pub(super) struct Typed<'s> {
    sweep: &'s Sweep,
    kind: &'static dyn DynAnalysis,
    /// The parsed case of design 0 (every varied number is set again for each design).
    base: Case,
    /// Each axis's path, split at the dots.
    paths: Vec<Vec<&'s str>>,
    /// Each axis's values as numbers and as the JSON text the lines and the hash hold.
    numbers: Vec<Vec<f64>>,
    texts: Vec<Vec<Vec<u8>>>,
    /// Each axis's `"path":` in the line's `params`.
    keys: Vec<Vec<u8>>,
    /// The design hash around the varied values.
    hash: HashTemplate,
    omit: Vec<Vec<String>>,
    notes_by_ref: bool,
}

/// A worker's reused state on the typed route.
pub(super) struct Worker {
    case: Case,
    line: ResultLine,
    /// Value index per axis of the current design.
    picks: Vec<usize>,
}

impl<'s> Typed<'s> {
    /// The typed route of `sweep` written in `format`, when it gives the same lines as the value
    /// route (see the module docs).
    pub(super) fn new(sweep: &'s Sweep, base_dir: Option<&Path>, format: &LineFormat, shapes: &Shapes) -> Option<Self> {
        let resolved = ["mesh", "parameters", "hinge_types"];
        if format.fields.is_some() || sweep.is_empty() || resolved.iter().any(|k| sweep.base.get(k).is_some()) {
            return None;
        }
        let kind = analysis::registry::find(sweep.base.get("analysis")?.as_str()?)?;
        let paths: Vec<Vec<&str>> = sweep.axes.iter().map(|(p, _)| p.split('.').collect()).collect();
        let mut numbers = Vec::with_capacity(paths.len());
        for (path, (_, values)) in paths.iter().zip(&sweep.axes) {
            pointer(&sweep.base, path)?.as_f64()?;
            numbers.push(values.iter().map(Value::as_f64).collect::<Option<Vec<f64>>>()?);
        }
        let parse = |i: usize| shapes.parse(sweep.design(i).ok()?, base_dir).ok().map(|p| p.case);
        let base = parse(0)?;
        let typed = Typed {
            sweep,
            kind,
            paths,
            texts: sweep
                .axes
                .iter()
                .map(|(_, vals)| vals.iter().map(|v| serde_json::to_vec(v).ok()).collect())
                .collect::<Option<_>>()?,
            keys: param_keys(sweep)?,
            numbers,
            hash: HashTemplate::default(),
            omit: format.omit_segments(),
            notes_by_ref: format.notes_by_ref,
            base,
        };
        let typed = Typed {
            hash: HashTemplate::new(sweep)?,
            ..typed
        };
        // The numbers set in the parsed case must give the parsed design.
        let mut w = typed.worker();
        for i in [0, sweep.len() / 2, sweep.len() - 1] {
            let parsed = parse(i)?;
            typed.set(&mut w, i)?;
            if format!("{:?}", w.case) != format!("{parsed:?}") {
                return None;
            }
        }
        Some(typed)
    }

    /// A worker's state.
    pub(super) fn worker(&self) -> Worker {
        Worker {
            case: self.base.clone(),
            line: line_buffers(),
            picks: vec![0; self.paths.len()],
        }
    }

    /// Sets design `index`'s numbers in the worker's case.
    fn set(&self, w: &mut Worker, index: usize) -> Option<()> {
        self.sweep.picks(index, &mut w.picks);
        for (k, path) in self.paths.iter().enumerate() {
            *self.kind.number_mut(&mut w.case, path)? = self.numbers[k][w.picks[k]];
        }
        Some(())
    }

    /// Writes design `index`'s line into the worker's buffer ([`Worker::finished`] gives it);
    /// `None` when the design must take the value route.
    pub(super) fn line(&self, w: &mut Worker, index: usize, cache: &mut SolverCache) -> Option<()> {
        self.set(w, index)?;
        let h = self.hash.state(&self.texts, &w.picks);
        line_head(&mut w.line.out, index, &self.keys, &self.texts, &w.picks, h)?;
        let mut ctx = Ctx::new(cache, false);
        ctx.with_report = false;
        let spec = LineSpec {
            omit: &self.omit,
            notes_by_ref: self.notes_by_ref,
            keyed_rows: None,
        };
        let to = LineTarget {
            line: &mut w.line,
            spec,
            parameters: None,
        };
        self.kind.write_result(&w.case, &mut ctx, to)?.ok()?;
        close_line(&mut w.line)
    }
}

impl Worker {
    /// The line [`Typed::line`] wrote for design `index`.
    pub(super) fn finished(&self, index: usize) -> Line<'_> {
        finished(&self.line, index)
    }
}

/// Each axis's `"path":` in a line's `params`.
pub(super) fn param_keys(sweep: &Sweep) -> Option<Vec<Vec<u8>>> {
    sweep
        .axes
        .iter()
        .map(|(p, _)| {
            let mut k = serde_json::to_vec(p).ok()?;
            k.push(b':');
            Some(k)
        })
        .collect()
}

/// Starts a line in `out` (cleared): `{"index":I,"params":{…},"design_hash":"…","result":`, the
/// value on axis k being `texts[k][picks[k]]`, as the value route writes it.
pub(super) fn line_head(
    out: &mut Vec<u8>,
    index: usize,
    keys: &[Vec<u8>],
    texts: &[Vec<Vec<u8>>],
    picks: &[usize],
    hash: u128,
) -> Option<()> {
    out.clear();
    out.extend_from_slice(b"{\"index\":");
    write!(out, "{index},\"params\":{{").ok()?;
    for (k, key) in keys.iter().enumerate() {
        if k > 0 {
            out.push(b',');
        }
        out.extend_from_slice(key);
        out.extend_from_slice(&texts[k][picks[k]]);
    }
    write!(out, "}},\"design_hash\":\"{hash:032x}\",\"result\":").ok()
}

/// Closes a line whose result was written ([`crate::analysis::DynAnalysis::write_result`]);
/// `None` when its notes need the value route (they hold an object).
pub(super) fn close_line(line: &mut ResultLine) -> Option<()> {
    if line.notes_hold_object {
        return None;
    }
    line.out.push(b'}');
    // serde_json writes UTF-8; checked here once so that `finished` cannot fail.
    std::str::from_utf8(&line.out).ok()?;
    std::str::from_utf8(&line.notes).ok()?;
    Some(())
}

/// The line `line` holds for design `index` ([`close_line`] checked it).
pub(super) fn finished(line: &ResultLine, index: usize) -> Line<'_> {
    fn text(b: &[u8]) -> &str {
        std::str::from_utf8(b).unwrap_or("")
    }
    Line {
        index,
        failed: false,
        text: text(&line.out),
        value: None,
        notes: (!line.notes.is_empty()).then(|| (text(&line.notes_ref), text(&line.notes))),
    }
}

/// A worker's line buffers, with room for a line and its notes from the start (a longer line
/// grows them once).
pub(super) fn line_buffers() -> ResultLine {
    ResultLine {
        out: Vec::with_capacity(8192),
        notes: Vec::with_capacity(4096),
        ..ResultLine::default()
    }
}
