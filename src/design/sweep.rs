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

use crate::analysis::Case;
use crate::analysis::{self, Ctx, RunError};
use crate::case::sweep::Sweep;
use crate::case::{self, CaseError};
use crate::fem::SolverCache;
use rayon::prelude::*;
use serde_json::{Map, Value};
use std::collections::HashSet;
use std::fmt;
use std::fs;
use std::io;
use std::panic::{self, AssertUnwindSafe};
use std::path::Path;
use std::str::FromStr;
use std::sync::atomic::{AtomicBool, AtomicUsize, Ordering};
use std::sync::Mutex;

/// Part `k` of `n` of a sweep: the designs whose index ≡ k−1 (mod n), 1 ≤ k ≤ n.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Shard {
    k: usize,
    n: usize,
}

impl Shard {
    /// The whole sweep (`1/1`).
    pub const ALL: Shard = Shard { k: 1, n: 1 };

    /// Shard `k` of `n`; needs 1 ≤ k ≤ n.
    pub fn new(k: usize, n: usize) -> Result<Self, String> {
        if n == 0 {
            return Err("N must be at least 1".into());
        }
        if k == 0 || k > n {
            return Err(format!("K must lie in 1..={n} (1 ≤ K ≤ N)"));
        }
        Ok(Shard { k, n })
    }

    /// `K` (1-based).
    pub fn k(&self) -> usize {
        self.k
    }

    /// `N`.
    pub fn n(&self) -> usize {
        self.n
    }

    /// True when design `index` belongs to this shard.
    pub fn contains(&self, index: usize) -> bool {
        index % self.n == self.k - 1
    }

    /// How many of the designs `0..len` belong to this shard.
    pub fn count(&self, len: usize) -> usize {
        (len + self.n - self.k) / self.n
    }

    /// The `j`-th design index of this shard.
    pub fn index(&self, j: usize) -> usize {
        self.k - 1 + j * self.n
    }
}

impl FromStr for Shard {
    type Err = String;

    fn from_str(s: &str) -> Result<Self, String> {
        let (k, n) = s.split_once('/').ok_or("must look like K/N, e.g. 2/3")?;
        let k: usize = k.trim().parse().map_err(|_| "K must be a whole number ≥ 1")?;
        let n: usize = n.trim().parse().map_err(|_| "N must be a whole number ≥ 1")?;
        Shard::new(k, n)
    }
}

impl fmt::Display for Shard {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "{}/{}", self.k, self.n)
    }
}

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
}

/// How a design's result goes into its line.
#[derive(Debug, Clone, Default, PartialEq)]
pub struct LineFormat {
    /// Result fields kept, as dotted paths (`stiffness_z`, `at_allowable.force`,
    /// `load_cases.0.platform`); `None` keeps every field.
    pub fields: Option<Vec<String>>,
    /// Take the model notes (`result.model`, text that is the same for every design of a
    /// sweep) out of the line: the line's result holds `model_notes`, the notes' 8-digit
    /// FNV hash, and the notes go once into a sidecar file ([`Row::notes`]).
    pub notes_by_ref: bool,
    /// Result fields left out of the line when [`Self::fields`] is `None`, as dotted paths in
    /// which `*` matches any key or array index (see [`omitted_fields`]).
    pub omit: Vec<String>,
}

/// The result fields a sweep of analysis `kind` leaves out of its lines by default
/// (`flexfem sweep --full` keeps them, `--fields` picks from the full result). A stage line
/// keeps every scalar response; it leaves out the 6×6 platform compliance (its eigenvalues
/// stay), the echo of the material and of the actuator forces (both in the case) and the
/// per-hinge stresses (their maximum, `max_von_mises`, stays): ~2,100 → ~980 bytes a line.
pub fn omitted_fields(kind: &str) -> &'static [&'static str] {
    match kind {
        "stage" => &[
            "platform_stiffness.compliance",
            "material",
            "load_cases.*.forces",
            "load_cases.*.hinge_stress",
        ],
        _ => &[],
    }
}

/// Removes the values at a dotted path whose `*` parts match any key or index.
fn remove_path(v: &mut Value, path: &[&str]) {
    let Some((first, rest)) = path.split_first() else {
        return;
    };
    match v {
        Value::Object(m) if rest.is_empty() => {
            if *first == "*" {
                m.clear();
            } else {
                m.shift_remove(*first);
            }
        }
        Value::Object(m) if *first == "*" => m.values_mut().for_each(|x| remove_path(x, rest)),
        Value::Object(m) => {
            if let Some(x) = m.get_mut(*first) {
                remove_path(x, rest);
            }
        }
        Value::Array(a) if *first == "*" && !rest.is_empty() => a.iter_mut().for_each(|x| remove_path(x, rest)),
        Value::Array(a) if !rest.is_empty() => {
            if let Some(x) = first.parse::<usize>().ok().and_then(|i| a.get_mut(i)) {
                remove_path(x, rest);
            }
        }
        _ => {}
    }
}

impl LineFormat {
    /// Parses `--fields a,b.c` (empty names are refused).
    pub fn parse_fields(text: &str) -> Result<Vec<String>, String> {
        let fields: Vec<String> = text.split(',').map(|f| f.trim().to_string()).collect();
        if fields.iter().any(|f| f.is_empty() || f.split('.').any(str::is_empty)) {
            return Err(
                "give comma-separated result fields as dotted paths, e.g. stiffness_z,at_allowable.force".into(),
            );
        }
        Ok(fields)
    }

    /// The reference of model notes in a line (see [`Self::notes_by_ref`]).
    pub fn notes_ref(notes: &Value) -> String {
        let mut h = Fnv128::new();
        canonical(notes, &mut h);
        format!("{:08x}", (h.0 >> 96) as u32)
    }

    /// Applies the format to a design's result; returns the notes taken out.
    fn apply(&self, result: &mut Value) -> Option<(String, Value)> {
        let notes = match (self.notes_by_ref, result.as_object_mut()) {
            (true, Some(m)) => m.remove("model").map(|notes| {
                let r = Self::notes_ref(&notes);
                m.insert("model_notes".into(), Value::String(r.clone()));
                (r, notes)
            }),
            _ => None,
        };
        if self.fields.is_none() {
            for p in &self.omit {
                remove_path(result, &p.split('.').collect::<Vec<_>>());
            }
        }
        if let Some(fields) = &self.fields {
            let mut kept = Value::Object(Map::new());
            for f in fields {
                let path: Vec<&str> = f.split('.').collect();
                if let Some(v) = pointer(result, &path) {
                    insert_path(&mut kept, &path, v.clone());
                }
            }
            *result = kept;
        }
        notes
    }
}

/// The value at a dotted path (object keys, array indices).
fn pointer<'a>(v: &'a Value, path: &[&str]) -> Option<&'a Value> {
    path.iter().try_fold(v, |v, key| match v {
        Value::Object(m) => m.get(*key),
        Value::Array(a) => key.parse::<usize>().ok().and_then(|i| a.get(i)),
        _ => None,
    })
}

/// Sets `path` in `out` (objects created as needed; array indices become object keys).
fn insert_path(out: &mut Value, path: &[&str], v: Value) {
    let Some((last, head)) = path.split_last() else { return };
    let mut cur = out;
    for key in head {
        let Value::Object(m) = cur else { return };
        cur = m.entry(key.to_string()).or_insert_with(|| Value::Object(Map::new()));
    }
    if let Value::Object(m) = cur {
        m.insert(last.to_string(), v);
    }
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

/// 128-bit FNV-1a (Fowler, Noll & Vo; IETF draft-eastlake-fnv): not cryptographic, only a
/// change detector for resumed sweeps.
#[derive(Clone, Copy)]
struct Fnv128(u128);

impl io::Write for Fnv128 {
    fn write(&mut self, bytes: &[u8]) -> io::Result<usize> {
        Fnv128::write(self, bytes);
        Ok(bytes.len())
    }

    fn flush(&mut self) -> io::Result<()> {
        Ok(())
    }
}

impl Fnv128 {
    const OFFSET: u128 = 0x6c62_272e_07bb_0142_62b8_2175_6295_c58d;
    const PRIME: u128 = 0x0000_0000_0100_0000_0000_0000_0000_013b;

    fn new() -> Self {
        Fnv128(Self::OFFSET)
    }

    fn write(&mut self, bytes: &[u8]) {
        for &b in bytes {
            self.0 ^= u128::from(b);
            self.0 = self.0.wrapping_mul(Self::PRIME);
        }
    }
}

/// Canonical JSON: object keys sorted, no whitespace; numbers and strings as serde_json
/// writes them.
fn canonical(v: &Value, out: &mut Fnv128) {
    match v {
        Value::Object(m) => {
            let mut keys: Vec<&String> = m.keys().collect();
            keys.sort_unstable();
            out.write(b"{");
            for (i, k) in keys.into_iter().enumerate() {
                if i > 0 {
                    out.write(b",");
                }
                // serde_json's string form of the key (escapes as in `Value::String`).
                let _ = serde_json::to_writer(&mut *out, k);
                out.write(b":");
                canonical(&m[k], out);
            }
            out.write(b"}");
        }
        Value::Array(a) => {
            out.write(b"[");
            for (i, x) in a.iter().enumerate() {
                if i > 0 {
                    out.write(b",");
                }
                canonical(x, out);
            }
            out.write(b"]");
        }
        scalar => {
            let _ = serde_json::to_writer(&mut *out, scalar);
        }
    }
}

/// The `design_hash` of a resolved design case (see the module notes), 32 hex digits.
pub fn hash_design(design: &Value, base_dir: Option<&Path>) -> String {
    let mut h = Fnv128::new();
    canonical(design, &mut h);
    if let Some(name) = design.get("mesh").and_then(Value::as_str) {
        h.write(b"\0mesh\0");
        match fs::read(case::resolve_file(name, base_dir)) {
            Ok(bytes) => h.write(&bytes),
            Err(_) => h.write(b"unreadable"),
        }
    }
    format!("{:032x}", h.0)
}

/// The `design_hash` of design `index`, or `None` when the design cannot be built.
pub fn design_hash(sweep: &Sweep, base_dir: Option<&Path>, index: usize) -> Option<String> {
    sweep.design(index).ok().map(|d| hash_design(&d, base_dir))
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
    hash: &mut Option<String>,
) -> Result<Value, String> {
    let design = sweep.design(index).map_err(|e| case_text(&e))?;
    *hash = Some(hash_design(&design, base_dir));
    let case = shapes.parse(design, base_dir).map_err(|e| case_text(&e))?;
    if let Case::Sweep(_) = case {
        return Err("analysis: a sweep cannot vary another sweep".into());
    }
    let mut ctx = Ctx::new(cache, false);
    // Only the JSON goes into the line: no Markdown/CSV report.
    ctx.with_report = false;
    analysis::run_with(&case, &mut ctx)
        .map(|o| o.json)
        .map_err(|e| error_text(&e))
}

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

    /// [`analysis::parse_value`] of a design, skipping the array check once a design passed it.
    fn parse(&self, design: Value, base_dir: Option<&Path>) -> Result<Case, CaseError> {
        let skip = self.scalar_axes && self.checked.load(Ordering::Relaxed);
        if !skip && design.is_object() {
            analysis::case_file::check_shape(&design)?;
            self.checked.store(true, Ordering::Relaxed);
        }
        analysis::case_file::parse_value_shaped(design, base_dir)
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
    run_design_in(sweep, base_dir, index, cache, format, &Shapes::new(sweep))
}

fn run_design_in(
    sweep: &Sweep,
    base_dir: Option<&Path>,
    index: usize,
    cache: &mut SolverCache,
    format: &LineFormat,
    shapes: &Shapes,
) -> Row {
    let mut hash = None;
    let outcome = panic::catch_unwind(AssertUnwindSafe(|| {
        evaluate(sweep, base_dir, index, cache, shapes, &mut hash)
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
    match outcome {
        Ok(mut result) => {
            notes = format.apply(&mut result);
            m.insert("result".into(), result)
        }
        Err(msg) => m.insert("error".into(), Value::String(msg)),
    };
    let value = Value::Object(m);
    Row {
        index,
        failed,
        line: value.to_string(),
        value,
        notes,
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
    S: Fn(Row) -> io::Result<()> + Sync,
{
    run_sweep_formatted(sweep, base_dir, shard, skip, &LineFormat::default(), sink)
}

/// [`run_sweep`] writing the lines in `format`.
pub fn run_sweep_formatted<S>(
    sweep: &Sweep,
    base_dir: Option<&Path>,
    shard: Shard,
    skip: &HashSet<usize>,
    format: &LineFormat,
    sink: S,
) -> io::Result<Tally>
where
    S: Fn(Row) -> io::Result<()> + Sync,
{
    let run = AtomicUsize::new(0);
    let failed = AtomicUsize::new(0);
    let stop = AtomicBool::new(false);
    let first_error: Mutex<Option<io::Error>> = Mutex::new(None);
    let shapes = Shapes::new(sweep);
    (0..shard.count(sweep.len()))
        .into_par_iter()
        .map(|j| shard.index(j))
        .filter(|i| !skip.contains(i))
        .for_each_init(SolverCache::new, |cache, i| {
            if stop.load(Ordering::Relaxed) {
                return;
            }
            let row = run_design_in(sweep, base_dir, i, cache, format, &shapes);
            let row_failed = row.failed;
            match sink(row) {
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
        });
    if let Some(e) = first_error.into_inner().unwrap_or_else(|p| p.into_inner()) {
        return Err(e);
    }
    Ok(Tally {
        run: run.into_inner(),
        failed: failed.into_inner(),
    })
}

pub use crate::output::with_suffix;

/// Loads and builds the sweep of a case file (errors are bad-case errors, exit 2).
pub fn load(path: &Path) -> Result<Sweep, CaseError> {
    match analysis::load(path)? {
        Case::Sweep(s) => s.build(),
        other => Err(CaseError::value(
            "analysis",
            format!("\"{}\"", other.analysis()),
            "`flexfem sweep` needs a sweep case (\"analysis\": \"sweep\"); run other cases with `flexfem run`",
        )),
    }
}

/// `flexfem check` of a sweep: the axes and design count ([`crate::case::sweep::SweepCase::build`]),
/// then design 0 and, for each varied path, the design with that path at its last value (the
/// others at their first) resolved and validated like a case of their own. Errors name the
/// JSON path in the sweep file: `vary.PATH` for a varied path, `base.PATH` otherwise.
pub fn check(sweep: &Sweep, base_dir: Option<&Path>) -> Result<usize, CaseError> {
    let mut indices = vec![0usize];
    let mut stride = 1usize;
    let mut per_axis = Vec::with_capacity(sweep.axes.len());
    for (_, vals) in sweep.axes.iter().rev() {
        per_axis.push((vals.len() - 1) * stride);
        stride = stride.saturating_mul(vals.len());
    }
    per_axis.reverse();
    indices.extend(per_axis.into_iter().filter(|&i| i != 0));
    for &i in &indices {
        let located = |e: CaseError| -> CaseError {
            let dotted = e.path.replace('[', ".").replace(']', "");
            let varied = sweep
                .axes
                .iter()
                .any(|(p, _)| dotted == *p || dotted.starts_with(&format!("{p}.")));
            let params = sweep
                .params(i)
                .iter()
                .map(|(p, v)| format!("{p} = {v}"))
                .collect::<Vec<_>>()
                .join(", ");
            let path = if varied {
                format!("vary.{dotted}")
            } else if e.path == "." {
                "base".to_string()
            } else {
                format!("base.{}", e.path)
            };
            CaseError::new(path, format!("design {i} ({params}): {}", e.message))
        };
        let design = sweep.design(i)?;
        let case = analysis::parse_value(design, base_dir).map_err(located)?;
        if let Case::Sweep(_) = case {
            return Err(CaseError::value(
                "base.analysis",
                "\"sweep\"",
                "a sweep cannot vary another sweep",
            ));
        }
        analysis::check(&case).map_err(located)?;
    }
    Ok(indices.len())
}

#[cfg(test)]
mod tests {
    use super::*;

    /// FNV-1a 128 test vector (draft-eastlake-fnv, "a"): d228cb696f1a8caf78912b704e4a8964.
    #[test]
    fn fnv128_matches_the_published_vector() {
        let mut h = Fnv128::new();
        h.write(b"a");
        assert_eq!(format!("{:032x}", h.0), "d228cb696f1a8caf78912b704e4a8964");
    }

    /// The hash ignores key order and whitespace (canonical JSON) but sees any value change,
    /// nested or not.
    #[test]
    fn design_hash_is_canonical() {
        let a: Value = serde_json::from_str(r#"{"x": 1, "y": {"p": [1, 2], "q": "s"}}"#).unwrap();
        let b: Value = serde_json::from_str(r#"{"y":{"q":"s","p":[1,2]},"x":1}"#).unwrap();
        let c: Value = serde_json::from_str(r#"{"x": 1, "y": {"p": [1, 3], "q": "s"}}"#).unwrap();
        assert_eq!(hash_design(&a, None), hash_design(&b, None));
        assert_ne!(hash_design(&a, None), hash_design(&c, None));
    }

    /// The hash streams keys and scalars into the hasher; it must equal the hash of the
    /// canonical text built as strings (`Value::to_string` of each key and scalar), which
    /// earlier sweep outputs hold, so their lines stay resumable.
    #[test]
    fn streamed_canonical_equals_the_string_form() {
        fn text(v: &Value, out: &mut String) {
            match v {
                Value::Object(m) => {
                    let mut keys: Vec<&String> = m.keys().collect();
                    keys.sort_unstable();
                    out.push('{');
                    for (i, k) in keys.into_iter().enumerate() {
                        if i > 0 {
                            out.push(',');
                        }
                        out.push_str(&Value::String(k.clone()).to_string());
                        out.push(':');
                        text(&m[k], out);
                    }
                    out.push('}');
                }
                Value::Array(a) => {
                    out.push('[');
                    for (i, x) in a.iter().enumerate() {
                        if i > 0 {
                            out.push(',');
                        }
                        text(x, out);
                    }
                    out.push(']');
                }
                scalar => out.push_str(&scalar.to_string()),
            }
        }
        let v: Value = serde_json::from_str(
            r#"{"z\"q": [1.5e-300, -0.0, 2, "a\u00e9\n"], "b": {"y": null, "x": true}, "é": 0.1}"#,
        )
        .unwrap();
        let mut s = String::new();
        text(&v, &mut s);
        let mut h = Fnv128::new();
        h.write(s.as_bytes());
        assert_eq!(hash_design(&v, None), format!("{:032x}", h.0));
    }
}
