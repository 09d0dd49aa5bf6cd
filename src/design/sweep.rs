//! `flexfem sweep`: full-factorial batch runs.
//!
//! Designs run in parallel on rayon. Each finished design becomes one JSON line,
//! `{"index", "params", "design_hash", "result"}` or `{"index", "params", "design_hash",
//! "error"}`, handed whole to a sink as soon as it is ready; a failing design is an error row
//! and the others go on. A sweep with any error row exits 1.
//!
//! `design_hash` is a 128-bit FNV-1a hash of the design's full resolved case: the base case
//! with the varied values set, as canonical JSON (object keys sorted, compact), followed by
//! the bytes of the mesh file it names, if any. It ties a line to everything that produced it.
//!
//! With `--out FILE.jsonl` the lines stream to `FILE.jsonl.partial` (appended, one write per
//! line). A re-run skips every design whose line is already in `FILE.jsonl` or the partial file
//! (complete, parseable lines whose `params` and `design_hash` match this sweep; a torn last
//! line is ignored). A line whose hash differs (the base case or its mesh changed) is stale
//! and its design runs again; error rows run again too unless `--keep-errors`. At the end all
//! lines, sorted by index, replace `FILE.jsonl` atomically and the partial file is removed.
//! So a killed sweep resumes where it stopped and never loses finished designs.
//!
//! The output is locked while the sweep runs (`FILE.jsonl.lock`, see [`crate::output::Lock`]):
//! a second sweep on the same `--out` — another shard, say — is refused instead of losing
//! designs. flexfem only replaces a `--out` file that is its own sweep output (every complete
//! line a sweep line) unless `--force`.
//!
//! A line holds nothing run-dependent (no timing), so shards `1/N … N/N` concatenated are the
//! same set of lines as one unsharded run.

use super::table;
use crate::analysis::{self, RunError};
use crate::case::sweep::Sweep;
use crate::case::{self, Case, CaseError};
use crate::output::write_atomic;
use rayon::prelude::*;
use serde::Deserialize;
use serde_json::{Map, Value};
use std::collections::{BTreeMap, HashMap, HashSet};
use std::fmt;
use std::fs::{self, File};
use std::io::{self, IsTerminal, Read, Seek, SeekFrom, Write};
use std::panic::{self, AssertUnwindSafe};
use std::path::{Path, PathBuf};
use std::process::ExitCode;
use std::str::FromStr;
use std::sync::atomic::{AtomicBool, AtomicUsize, Ordering};
use std::sync::Mutex;
use std::time::{Duration, Instant};

/// Command-line arguments of `flexfem sweep`.
#[derive(Debug, Clone)]
pub struct SweepArgs {
    /// The sweep case file.
    pub case: PathBuf,
    /// `K/N`: run only designs with index ≡ K−1 (mod N).
    pub shard: Option<String>,
    /// JSON-lines output file (stdout when `None`).
    pub out: Option<PathBuf>,
    /// Optional CSV output.
    pub csv: Option<PathBuf>,
    /// Replace `out`/`csv` even when they are not flexfem's own output.
    pub force: bool,
    /// Keep earlier error rows on resume instead of running those designs again.
    pub keep_errors: bool,
}

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
                out.write(Value::String(k.clone()).to_string().as_bytes());
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
        scalar => out.write(scalar.to_string().as_bytes()),
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
fn evaluate(sweep: &Sweep, base_dir: Option<&Path>, index: usize) -> Result<Value, String> {
    let design = sweep.design(index).map_err(|e| case_text(&e))?;
    let case = case::parse_value(design, base_dir).map_err(|e| case_text(&e))?;
    if let Case::Sweep(_) = case {
        return Err("analysis: a sweep cannot vary another sweep".into());
    }
    analysis::run(&case).map(|o| o.json).map_err(|e| error_text(&e))
}

/// Runs design `index` of `sweep` into its JSON line. Never panics: a panic inside the
/// analysis becomes an error row too.
pub fn run_design(sweep: &Sweep, base_dir: Option<&Path>, index: usize) -> Row {
    let outcome = panic::catch_unwind(AssertUnwindSafe(|| evaluate(sweep, base_dir, index)))
        .unwrap_or_else(|p| Err(panic_text(p.as_ref())));
    let mut m = Map::with_capacity(4);
    m.insert("index".into(), index.into());
    m.insert("params".into(), Value::Object(sweep.params(index)));
    if let Some(h) = design_hash(sweep, base_dir, index) {
        m.insert("design_hash".into(), Value::String(h));
    }
    let failed = outcome.is_err();
    match outcome {
        Ok(result) => m.insert("result".into(), result),
        Err(msg) => m.insert("error".into(), Value::String(msg)),
    };
    Row {
        index,
        failed,
        line: Value::Object(m).to_string(),
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
    let run = AtomicUsize::new(0);
    let failed = AtomicUsize::new(0);
    let stop = AtomicBool::new(false);
    let first_error: Mutex<Option<io::Error>> = Mutex::new(None);
    (0..shard.count(sweep.len()))
        .into_par_iter()
        .map(|j| shard.index(j))
        .filter(|i| !skip.contains(i))
        .for_each(|i| {
            if stop.load(Ordering::Relaxed) {
                return;
            }
            let row = run_design(sweep, base_dir, i);
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
fn same_value(a: &Value, b: &Value) -> bool {
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
            let want = hashes
                .entry(i)
                .or_insert_with(|| design_hash(sweep, accept.base_dir, i));
            if head.design_hash.is_none() || head.design_hash != *want {
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
        let mut f = Finished::default();
        for path in files {
            match fs::read(path) {
                Ok(bytes) => f.add_text(sweep, accept, &bytes),
                Err(e) if e.kind() == io::ErrorKind::NotFound => {}
                Err(e) => return Err(io::Error::new(e.kind(), format!("cannot read {}: {e}", path.display()))),
            }
        }
        Ok(f)
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

pub use crate::output::with_suffix;

/// Opens the partial file for appending; if it ends in a torn line, starts a new line so the
/// next row is not glued to the fragment (the fragment stays unreadable and is ignored).
fn open_partial(path: &Path) -> io::Result<File> {
    let mut f = crate::output::open_append_no_follow(path)?;
    let len = f.metadata()?.len();
    if len > 0 {
        f.seek(SeekFrom::Start(len - 1))?;
        let mut last = [0u8; 1];
        f.read_exact(&mut last)?;
        if last[0] != b'\n' {
            f.write_all(b"\n")?;
        }
    }
    Ok(f)
}

fn io_context(what: &'static str, path: &Path) -> impl FnOnce(io::Error) -> io::Error {
    let path = path.to_path_buf();
    move |e| io::Error::new(e.kind(), format!("cannot {what} {}: {e}", path.display()))
}

/// Where finished lines go during the run.
enum Stream {
    Stdout(io::Stdout),
    File(File),
}

struct SinkState {
    stream: Stream,
    /// Lines kept for the CSV when they are not in a file.
    kept: Option<Vec<(usize, String)>>,
    buf: Vec<u8>,
}

fn progress_bar(len: usize) -> indicatif::ProgressBar {
    use indicatif::{ProgressBar, ProgressDrawTarget, ProgressStyle};
    if !io::stderr().is_terminal() {
        return ProgressBar::hidden();
    }
    let pb = ProgressBar::with_draw_target(Some(len as u64), ProgressDrawTarget::stderr());
    if let Ok(style) =
        ProgressStyle::with_template("{spinner} [{elapsed_precise}] {bar:40} {pos}/{len} designs  {per_sec}  ETA {eta}")
    {
        pb.set_style(style);
    }
    pb
}

fn bad_case(e: &CaseError) -> ExitCode {
    eprintln!("error: {e}");
    ExitCode::from(crate::output::EXIT_BAD_CASE)
}

fn failed(msg: impl fmt::Display) -> ExitCode {
    eprintln!("error: {msg}");
    ExitCode::from(crate::output::EXIT_FAILED)
}

/// Loads and builds the sweep of a case file (errors are bad-case errors, exit 2).
pub fn load(path: &Path) -> Result<Sweep, CaseError> {
    match case::load(path)? {
        Case::Sweep(s) => s.build(),
        other => Err(CaseError::value(
            "analysis",
            format!("\"{}\"", other.analysis()),
            "`flexfem sweep` needs a sweep case (\"analysis\": \"sweep\"); run other cases with `flexfem run`",
        )),
    }
}

/// Runs a sweep; returns the exit code: 0 when every design succeeded, 1 when any design
/// failed (error rows) or the output could not be written, 2 for a bad case file or arguments.
pub fn run_cli(args: SweepArgs) -> ExitCode {
    let shard = match args.shard.as_deref().map(|s| (s, s.parse::<Shard>())) {
        None => Shard::ALL,
        Some((_, Ok(s))) => s,
        Some((text, Err(msg))) => {
            eprintln!("error: invalid --shard `{text}`: {msg}");
            return ExitCode::from(crate::output::EXIT_BAD_CASE);
        }
    };
    let sweep = match load(&args.case) {
        Ok(s) => s,
        Err(e) => return bad_case(&e),
    };
    let base_dir = args.case.parent();
    match execute(&sweep, base_dir, shard, &args) {
        Ok(0) => ExitCode::SUCCESS,
        Ok(_) => ExitCode::from(crate::output::EXIT_FAILED),
        Err(Stop::Usage(msg)) => {
            eprintln!("error: {msg}");
            ExitCode::from(crate::output::EXIT_BAD_CASE)
        }
        Err(Stop::Io(e)) => failed(e),
    }
}

/// Why a sweep did not finish.
enum Stop {
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
enum Kind {
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
fn check_replaceable(label: &str, path: &Path, kind: Kind, force: bool) -> Result<bool, Stop> {
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
struct Targets {
    out: Option<PathBuf>,
    partial: Option<PathBuf>,
    csv: Option<PathBuf>,
    stage_csv: Option<PathBuf>,
    stage_svg: Option<PathBuf>,
}

impl Targets {
    fn new(sweep: &Sweep, args: &SweepArgs) -> Result<Self, Stop> {
        let stage = sweep.base.get("analysis").and_then(Value::as_str) == Some("stage");
        let out = args.out.clone();
        let t = Targets {
            partial: out.as_deref().map(|p| with_suffix(p, ".partial")),
            stage_svg: out.as_deref().filter(|_| stage).map(|p| p.with_extension("svg")),
            stage_csv: out
                .as_deref()
                .filter(|_| stage && args.csv.is_none())
                .map(|p| p.with_extension("csv")),
            csv: args.csv.clone(),
            out,
        };
        let lock = t.out.as_deref().map(|p| with_suffix(p, ".lock"));
        let named: Vec<(&str, &Path)> = [
            ("the case file", Some(args.case.as_path())),
            ("--out", t.out.as_deref()),
            ("--csv", t.csv.as_deref()),
            ("the partial file", t.partial.as_deref()),
            ("the lock file", lock.as_deref()),
            ("the stage plot", t.stage_svg.as_deref()),
            ("the stage table", t.stage_csv.as_deref()),
        ]
        .into_iter()
        .filter_map(|(l, p)| p.map(|p| (l, p)))
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

/// Runs the sweep; returns the number of failed designs (error rows in the output).
fn execute(sweep: &Sweep, base_dir: Option<&Path>, shard: Shard, args: &SweepArgs) -> Result<usize, Stop> {
    let start = Instant::now();
    let in_shard = shard.count(sweep.len());
    let targets = Targets::new(sweep, args)?;
    let partial = targets.partial.as_deref();
    // One sweep per output file at a time: held until this function returns.
    let _lock = match &targets.out {
        Some(out) => Some(crate::output::Lock::acquire(out).map_err(|e| io::Error::other(e.to_string()))?),
        None => None,
    };
    let mut sources: Vec<&Path> = Vec::new();
    if let (Some(out), Some(partial)) = (&targets.out, partial) {
        if check_replaceable("--out", out, Kind::Jsonl, args.force)? {
            sources.push(out);
        }
        if crate::output::is_symlink(partial) {
            return Err(Stop::Io(io::Error::other(format!(
                "{} is a symbolic link; flexfem does not write through links (remove it)",
                partial.display()
            ))));
        }
        if check_replaceable("the partial file", partial, Kind::Jsonl, args.force)? {
            sources.push(partial);
        } else if args.force && partial.exists() {
            fs::remove_file(partial).map_err(io_context("remove", partial))?;
        }
    }
    for (label, path, kind) in [
        ("--csv", targets.csv.as_deref(), Kind::Csv),
        ("the stage table", targets.stage_csv.as_deref(), Kind::Csv),
        ("the stage plot", targets.stage_svg.as_deref(), Kind::Svg),
    ] {
        if let Some(p) = path {
            check_replaceable(label, p, kind, args.force)?;
        }
    }

    let accept = Accept {
        base_dir,
        keep_errors: args.keep_errors,
    };
    let (done, stream) = match partial {
        Some(partial) => {
            let done = Finished::read(sweep, accept, &sources)?;
            let file = open_partial(partial).map_err(io_context("open", partial))?;
            (done, Stream::File(file))
        }
        None => (Finished::default(), Stream::Stdout(io::stdout())),
    };
    let skip: HashSet<usize> = done.lines.keys().copied().filter(|&i| shard.contains(i)).collect();
    let to_run = in_shard - skip.len();
    let keep_for_csv = args.csv.is_some() && args.out.is_none();
    let state = Mutex::new(SinkState {
        stream,
        kept: keep_for_csv.then(Vec::new),
        buf: Vec::with_capacity(4096),
    });
    let pb = progress_bar(to_run);
    let stdout_tty = args.out.is_none() && io::stdout().is_terminal();
    let tally = run_sweep(sweep, base_dir, shard, &skip, |row: Row| {
        let mut st = state.lock().unwrap_or_else(|p| p.into_inner());
        let SinkState { stream, kept, buf } = &mut *st;
        buf.clear();
        buf.extend_from_slice(row.line.as_bytes());
        buf.push(b'\n');
        match stream {
            Stream::File(f) => f
                .write_all(buf)
                .map_err(|e| io_context("append to", partial.unwrap_or(Path::new("")))(e))?,
            Stream::Stdout(s) => {
                let write = || -> io::Result<()> {
                    let mut lock = s.lock();
                    lock.write_all(buf)?;
                    lock.flush()
                };
                let write = || write().map_err(|e| io::Error::new(e.kind(), format!("cannot write to stdout: {e}")));
                if stdout_tty {
                    pb.suspend(write)?
                } else {
                    write()?
                }
            }
        }
        if let Some(k) = kept {
            k.push((row.index, row.line));
        }
        pb.inc(1);
        Ok(())
    });
    pb.finish_and_clear();
    let tally = tally?;
    let state = state.into_inner().unwrap_or_else(|p| p.into_inner());
    drop(state.stream);

    let mut failed_total = tally.failed + done.failed.iter().filter(|&&i| shard.contains(i)).count();
    let csv_lines: Option<Vec<String>> = match (&targets.out, partial) {
        (Some(out), Some(partial)) => {
            // Oldest first, so the lines just written replace retried or stale ones.
            sources.retain(|p| *p != partial);
            sources.push(partial);
            let all = Finished::read(
                sweep,
                Accept {
                    keep_errors: true,
                    ..accept
                },
                &sources,
            )?;
            failed_total = all.failed.iter().filter(|&&i| shard.contains(i)).count();
            write_atomic(out, &all.to_jsonl()).map_err(io_context("write", out))?;
            fs::remove_file(partial).or_else(|e| match e.kind() {
                io::ErrorKind::NotFound => Ok(()),
                _ => Err(e),
            })?;
            if all.in_shard(shard) != in_shard {
                eprintln!(
                    "warning: {} holds {} of the {in_shard} designs",
                    out.display(),
                    all.in_shard(shard)
                );
            }
            // Stage sweeps: a CSV and an SVG plot beside the JSON lines.
            let lines: Vec<String> = all.lines.values().cloned().collect();
            if let Some(p) = &targets.stage_svg {
                if let Some(svg) = super::plots::stage_sweep_svg(&lines) {
                    write_atomic(p, svg.as_bytes()).map_err(io_context("write", p))?;
                }
            }
            if let Some(p) = &targets.stage_csv {
                let axes: Vec<&str> = sweep.axes.iter().map(|(p, _)| p.as_str()).collect();
                let refs: Vec<&str> = lines.iter().map(String::as_str).collect();
                write_atomic(p, table::csv(&axes, &refs).as_bytes()).map_err(io_context("write", p))?;
            }
            args.csv.as_ref().map(|_| lines)
        }
        _ => state.kept.map(|mut k| {
            k.sort_unstable_by_key(|(i, _)| *i);
            k.into_iter().map(|(_, l)| l).collect()
        }),
    };
    if let (Some(csv), Some(lines)) = (&args.csv, csv_lines) {
        let axes: Vec<&str> = sweep.axes.iter().map(|(p, _)| p.as_str()).collect();
        let lines: Vec<&str> = lines.iter().map(String::as_str).collect();
        let text = table::csv(&axes, &lines);
        write_atomic(csv, text.as_bytes()).map_err(io_context("write", csv))?;
    }

    let secs = start.elapsed().as_secs_f64();
    let shard_note = if shard == Shard::ALL {
        String::new()
    } else {
        format!(" (shard {shard} of {})", sweep.len())
    };
    let mut note = String::new();
    if done.foreign > 0 || done.unreadable > 0 {
        note = format!(
            "; ignored {} earlier lines of other designs and {} unreadable",
            done.foreign, done.unreadable
        );
    }
    if done.stale > 0 {
        note += &format!(
            "; reran {} designs whose earlier lines were stale (base case, mesh file or line format changed)",
            done.stale
        );
    }
    if done.errors > 0 {
        note += &format!("; retried {} earlier error rows", done.errors);
    }
    let kept_errors = done.failed.iter().filter(|&&i| shard.contains(i)).count();
    if kept_errors > 0 {
        note += &format!("; kept {kept_errors} earlier error rows (--keep-errors)");
    }
    eprintln!(
        "sweep: {in_shard} designs{shard_note}, {} already done, {} run, {} failed, {:.2} s ({:.0} designs/s){note}",
        skip.len(),
        tally.run,
        tally.failed,
        secs,
        rate(tally.run, start.elapsed()),
    );
    if failed_total > 0 {
        eprintln!("error: {failed_total} of {in_shard} designs failed (their lines hold an \"error\"; exit code 1)");
    }
    Ok(failed_total)
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
        let case = case::parse_value(design, base_dir).map_err(located)?;
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

fn rate(n: usize, d: Duration) -> f64 {
    let s = d.as_secs_f64();
    if s > 0.0 {
        n as f64 / s
    } else {
        0.0
    }
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
