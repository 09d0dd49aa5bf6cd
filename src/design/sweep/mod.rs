//! `flexfem sweep`'s batch driver: full-factorial runs of a base case, one row per design.
//!
//! Designs run in parallel on rayon, each worker with its own solver cache (designs of one
//! sweep share the topology, so their systems are refactorised numerically only). Each finished
//! design becomes one JSON line, `{"index", "params", "design_hash", "result"}` or `{"index",
//! "params", "design_hash", "error"}`, handed whole to a sink as soon as it is ready (with the
//! JSON value it was written from); a failing design is an error row and the others go on.
//!
//! `design_hash` is a 128-bit FNV-1a hash of the design's full resolved case: the base case
//! with the varied values set, as canonical JSON (object keys sorted, compact), followed by
//! the bytes of the mesh file it names, if any. It ties a line to everything that produced it.
//!
//! A line holds nothing run-dependent (no timing), so shards `1/N … N/N` concatenated are the
//! same set of lines as one unsharded run. The command-line half (output files, resume, locking,
//! progress, exit codes) is [`crate::cli::sweep`]'s.

mod check;
mod compiled;
mod format;
mod hash;
mod shard;
mod typed;

pub use check::{check, load, with_suffix};
pub use format::{line_nodes, loaded_nodes, omitted_fields, LineFormat};
pub use hash::{design_hash, hash_design};
pub use shard::Shard;

use crate::analysis::Case;
use crate::analysis::{self, Ctx, RunError};
use crate::case::sweep::Sweep;
use crate::case::CaseError;
use crate::fem::SolverCache;
use serde_json::{Map, Value};
use std::collections::HashSet;
use std::io;
use std::panic::{self, AssertUnwindSafe};
use std::path::Path;
use std::sync::atomic::{AtomicBool, AtomicUsize, Ordering};
use std::sync::Mutex;

/// One finished design: its JSON line (no newline) and whether it is an error row.
#[derive(Debug, Clone, PartialEq)]
pub struct Row {
    /// Design index (row-major over the axes, last axis fastest).
    pub index: usize,
    /// True for an `error` row.
    pub failed: bool,
    /// `{"index","params","result"}` or `{"index","params","error"}`, compact JSON.
    pub line: String,
    /// The JSON value `line` was written from (the CSV table reads its cells from it).
    pub value: Value,
    /// With [`LineFormat::notes_by_ref`]: the model notes taken out of the line, as
    /// (`model_notes` reference, notes).
    pub notes: Option<(String, Value)>,
    /// The notes of [`Self::notes`] as compact JSON (what the sidecar holds).
    pub notes_json: Option<String>,
}

impl Row {
    /// The row as handed to a sink.
    pub fn as_line(&self) -> Line<'_> {
        Line {
            index: self.index,
            failed: self.failed,
            text: &self.line,
            value: Some(&self.value),
            notes: self
                .notes_json
                .as_deref()
                .zip(self.notes.as_ref())
                .map(|(json, (r, _))| (r.as_str(), json)),
        }
    }
}

/// One finished design as a sweep hands it to its sink, borrowed from the worker that wrote it.
#[derive(Debug, Clone, Copy)]
pub struct Line<'a> {
    /// Design index.
    pub index: usize,
    /// True for an `error` row.
    pub failed: bool,
    /// The JSON line (no newline).
    pub text: &'a str,
    /// The JSON value the line was written from, on the value route (`None` on the typed
    /// route, which builds no value: see [`run_sweep_formatted`]'s `want_values`).
    pub value: Option<&'a Value>,
    /// With [`LineFormat::notes_by_ref`]: the model notes taken out of the line, as
    /// (`model_notes` reference, their compact JSON).
    pub notes: Option<(&'a str, &'a str)>,
}

/// What [`run_sweep`] did.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub struct Tally {
    /// Designs run (and handed to the sink).
    pub run: usize,
    /// Of those, error rows.
    pub failed: usize,
}

/// The message of an error row: `path: message` for case errors (so the JSON path of the
/// offending parameter leads), the full text for analysis failures.
fn error_text(e: &RunError) -> String {
    match e {
        RunError::Case(c) => case_text(c),
        RunError::Analysis(a) => a.to_string(),
    }
}

fn case_text(e: &CaseError) -> String {
    format!("{}: {}", e.path, e.message)
}

fn panic_text(p: &(dyn std::any::Any + Send)) -> String {
    let msg = p
        .downcast_ref::<&str>()
        .map(|s| s.to_string())
        .or_else(|| p.downcast_ref::<String>().cloned())
        .unwrap_or_else(|| "unknown panic".into());
    format!("internal error (please report): {msg}")
}

/// Runs one design: `base` with the varied paths set, parsed with `base_dir` for file
/// references, then analysed.
/// The design's hash goes into `hash` as soon as the design is built.
fn evaluate(
    sweep: &Sweep,
    base_dir: Option<&Path>,
    index: usize,
    cache: &mut SolverCache,
    shapes: &Shapes,
    format: &LineFormat,
    hash: &mut Option<String>,
) -> Result<(Value, Option<format::LoadedNodes>), String> {
    let design = sweep.design(index).map_err(|e| case_text(&e))?;
    *hash = Some(hash_design(&design, base_dir));
    let parsed = shapes.parse(design, base_dir).map_err(|e| case_text(&e))?;
    if let Case::Sweep(_) = &parsed.case {
        return Err("analysis: a sweep cannot vary another sweep".into());
    }
    let loaded = loaded_nodes_of(&parsed.case, format.loaded_displacements);
    let mut ctx = Ctx::new(cache, false);
    // Only the JSON goes into the line: no Markdown/CSV report.
    ctx.with_report = false;
    analysis::run_with(&parsed.case, &mut ctx)
        .map(|mut o| {
            o.echo_parameters(&parsed.parameters);
            (o.json, loaded)
        })
        .map_err(|e| error_text(&parsed.locate_run(e)))
}

/// With `loaded_displacements` ([`LineFormat::loaded_displacements`]): the nodes whose
/// displacements the line of a static case keeps ([`format::line_nodes`]).
fn loaded_nodes_of(case: &Case, loaded_displacements: bool) -> Option<format::LoadedNodes> {
    match case {
        Case::Static(c) if loaded_displacements => {
            let named: Vec<usize> = c
                .compliance
                .iter()
                .map(|r| r.node)
                .chain(c.metrics.iter().filter_map(|m| m.node))
                .collect();
            Some(format::line_nodes(&c.model, &named))
        }
        _ => None,
    }
}

/// The compiled route and a worker's state on it ([`compiled`]).
type RouteWorker<'a, 's> = Option<(&'a compiled::Route<'s>, &'a mut compiled::Worker)>;

/// The array check of a sweep's designs ([`analysis::case_file::check_shape`]), done once per
/// run when every varied value is a scalar: the designs then differ only in scalar values,
/// which the check does not look at, so they all pass or fail it alike.
struct Shapes {
    scalar_axes: bool,
    checked: AtomicBool,
}

impl Shapes {
    fn new(sweep: &Sweep) -> Self {
        let scalar = |v: &Value| !(v.is_array() || v.is_object());
        Shapes {
            scalar_axes: sweep.axes.iter().all(|(_, vals)| vals.iter().all(scalar)),
            checked: AtomicBool::new(false),
        }
    }

    /// [`analysis::parse_value`] of a design with its parameter values, skipping the array
    /// check once a design passed it.
    fn parse(&self, design: Value, base_dir: Option<&Path>) -> Result<analysis::Parsed, CaseError> {
        let check = !(self.scalar_axes && self.checked.load(Ordering::Relaxed)) && design.is_object();
        let parsed = analysis::case_file::parse_resolved(design, base_dir, check)?;
        if check {
            self.checked.store(true, Ordering::Relaxed);
        }
        Ok(parsed)
    }
}

/// Runs design `index` of `sweep` into its JSON line. Never panics: a panic inside the
/// analysis becomes an error row too.
pub fn run_design(sweep: &Sweep, base_dir: Option<&Path>, index: usize) -> Row {
    run_design_with(sweep, base_dir, index, &mut SolverCache::new())
}

/// [`run_design`] with the worker's solver cache.
pub fn run_design_with(sweep: &Sweep, base_dir: Option<&Path>, index: usize, cache: &mut SolverCache) -> Row {
    run_design_formatted(sweep, base_dir, index, cache, &LineFormat::default())
}

/// [`run_design_with`] writing the line in `format`.
pub fn run_design_formatted(
    sweep: &Sweep,
    base_dir: Option<&Path>,
    index: usize,
    cache: &mut SolverCache,
    format: &LineFormat,
) -> Row {
    run_design_in(sweep, base_dir, index, cache, format, &Shapes::new(sweep), None)
}

fn run_design_in(
    sweep: &Sweep,
    base_dir: Option<&Path>,
    index: usize,
    cache: &mut SolverCache,
    format: &LineFormat,
    shapes: &Shapes,
    route: RouteWorker,
) -> Row {
    let mut hash = None;
    let outcome = panic::catch_unwind(AssertUnwindSafe(|| {
        // The compiled route first, where the sweep has one; the value route for the rest.
        if let Some((json, loaded, h)) = route.and_then(|(r, w)| r.design(w, index, cache)) {
            hash = Some(h);
            return Ok((json, loaded));
        }
        evaluate(sweep, base_dir, index, cache, shapes, format, &mut hash)
    }))
    .unwrap_or_else(|p| {
        // A panic may have left the cache half-updated: start the worker afresh.
        *cache = SolverCache::new();
        Err(panic_text(p.as_ref()))
    });
    let mut m = Map::with_capacity(4);
    m.insert("index".into(), index.into());
    m.insert("params".into(), Value::Object(sweep.params(index)));
    if let Some(h) = hash.or_else(|| design_hash(sweep, base_dir, index)) {
        m.insert("design_hash".into(), Value::String(h));
    }
    let failed = outcome.is_err();
    let mut notes = None;
    let mut notes_json = None;
    match outcome {
        Ok((mut result, loaded)) => {
            if let Some((r, n, json)) = format.apply(&mut result, loaded.as_deref()) {
                notes = Some((r, n));
                notes_json = Some(json);
            }
            m.insert("result".into(), result)
        }
        Err(msg) => m.insert("error".into(), Value::String(msg)),
    };
    let value = Value::Object(m);
    // Straight into a byte buffer: `Value`'s `Display` (the same compact text) goes through
    // `fmt::Formatter`, several times slower on number-heavy lines.
    let line = serde_json::to_string(&value).unwrap_or_else(|_| value.to_string());
    Row {
        index,
        failed,
        line,
        value,
        notes,
        notes_json,
    }
}

/// Runs every design of `shard` not in `skip`, in parallel, handing each finished row to
/// `sink` (called from worker threads, one row at a time per call; rows arrive in completion
/// order). The first sink error stops the sweep (designs already started finish) and is
/// returned.
pub fn run_sweep<S>(
    sweep: &Sweep,
    base_dir: Option<&Path>,
    shard: Shard,
    skip: &HashSet<usize>,
    sink: S,
) -> io::Result<Tally>
where
    S: Fn(Line) -> io::Result<()> + Sync,
{
    run_sweep_formatted(sweep, base_dir, shard, skip, &LineFormat::default(), false, sink)
}

/// [`run_sweep`] writing the lines in `format`.
///
/// Designs take the typed route (no JSON value, no allocation per design: see [`typed`]) where
/// it gives the very lines of the value route, unless `want_values` (a sink that needs each
/// line's [`Line::value`]).
pub fn run_sweep_formatted<S>(
    sweep: &Sweep,
    base_dir: Option<&Path>,
    shard: Shard,
    skip: &HashSet<usize>,
    format: &LineFormat,
    want_values: bool,
    sink: S,
) -> io::Result<Tally>
where
    S: Fn(Line) -> io::Result<()> + Sync,
{
    let run = AtomicUsize::new(0);
    let failed = AtomicUsize::new(0);
    let stop = AtomicBool::new(false);
    let first_error: Mutex<Option<io::Error>> = Mutex::new(None);
    let shapes = Shapes::new(sweep);
    let typed = (!want_values)
        .then(|| typed::Typed::new(sweep, base_dir, format, &shapes))
        .flatten();
    // Parameterised cases, which the typed route leaves to the value route: compiled once.
    let route = match typed {
        None => compiled::Route::new(sweep, base_dir, format, &shapes, want_values),
        Some(_) => None,
    };
    // One worker per thread (its solver cache, its parsed case and line buffers), taking the
    // next design from a shared counter until none is left: a worker is set up once per thread,
    // not once per piece of a split range, and designs finish roughly in index order.
    let next = AtomicUsize::new(0);
    let count = shard.count(sweep.len());
    rayon::broadcast(|_| {
        let mut cache = SolverCache::new();
        let mut worker = typed.as_ref().map(typed::Typed::worker);
        let mut route_worker = route.as_ref().map(compiled::Route::worker);
        loop {
            let j = next.fetch_add(1, Ordering::Relaxed);
            if j >= count || stop.load(Ordering::Relaxed) {
                return;
            }
            let i = shard.index(j);
            if skip.contains(&i) {
                continue;
            }
            // A line written straight from the result (typed or compiled route), else `None`.
            let mut attempt = |write: &mut dyn FnMut(&mut SolverCache) -> bool| {
                let done = panic::catch_unwind(AssertUnwindSafe(|| write(&mut cache)));
                if done.is_err() {
                    // A panic may have left the cache half-updated: start the worker afresh.
                    cache = SolverCache::new();
                }
                done.unwrap_or(false)
            };
            let fast = match (&typed, worker.as_mut(), &route, route_worker.as_mut()) {
                (Some(t), Some(w), _, _) => attempt(&mut |c| t.line(w, i, c).is_some()),
                (_, _, Some(r), Some(w)) => attempt(&mut |c| r.line(w, i, c).is_some()),
                _ => false,
            };
            let row;
            let (line, row_failed) = match (fast, worker.as_ref(), route_worker.as_ref()) {
                (true, Some(w), _) => (w.finished(i), false),
                (true, None, Some(w)) => (w.finished(i), false),
                _ => {
                    let on_route = route.as_ref().zip(route_worker.as_mut());
                    row = run_design_in(sweep, base_dir, i, &mut cache, format, &shapes, on_route);
                    (row.as_line(), row.failed)
                }
            };
            match sink(line) {
                Ok(()) => {
                    run.fetch_add(1, Ordering::Relaxed);
                    if row_failed {
                        failed.fetch_add(1, Ordering::Relaxed);
                    }
                }
                Err(e) => {
                    stop.store(true, Ordering::Relaxed);
                    let mut slot = first_error.lock().unwrap_or_else(|p| p.into_inner());
                    slot.get_or_insert(e);
                }
            }
        }
    });
    if let Some(e) = first_error.into_inner().unwrap_or_else(|p| p.into_inner()) {
        return Err(e);
    }
    Ok(Tally {
        run: run.into_inner(),
        failed: failed.into_inner(),
    })
}

/// True when the designs of `sweep` written in `format` take the compiled route of
/// parameterised cases ([`compiled`]; the value route otherwise): for tests and benches.
pub fn takes_compiled_route(sweep: &Sweep, base_dir: Option<&Path>, format: &LineFormat) -> bool {
    let shapes = Shapes::new(sweep);
    typed::Typed::new(sweep, base_dir, format, &shapes).is_none()
        && compiled::Route::new(sweep, base_dir, format, &shapes, false).is_some()
}
