//! `flexfem sweep`: full-factorial batch runs (INTERFACE.md "sweep", SPEC §8).
//!
//! Designs run in parallel on rayon. Each finished design becomes one JSON line,
//! `{"index", "params", "result"}` or `{"index", "params", "error"}`, handed whole to a sink
//! as soon as it is ready; a failing design is an error row and the others go on.
//!
//! With `--out FILE.jsonl` the lines stream to `FILE.jsonl.partial` (appended, one write per
//! line). A re-run skips every design whose line is already in `FILE.jsonl` or the partial file
//! (complete, parseable lines whose `params` match this sweep; a torn last line is ignored), and
//! at the end all lines, sorted by index, replace `FILE.jsonl` atomically and the partial file
//! is removed. So a killed sweep resumes where it stopped and never loses finished designs.
//!
//! A line holds nothing run-dependent (no timing), so shards `1/N … N/N` concatenated are the
//! same set of lines as one unsharded run.

use super::table;
use crate::analysis::{self, RunError};
use crate::case::sweep::Sweep;
use crate::case::{self, Case, CaseError};
use rayon::prelude::*;
use serde::Deserialize;
use serde_json::{Map, Value};
use std::collections::{BTreeMap, HashSet};
use std::ffi::OsString;
use std::fmt;
use std::fs::{self, File, OpenOptions};
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
    let mut m = Map::with_capacity(3);
    m.insert("index".into(), index.into());
    m.insert("params".into(), Value::Object(sweep.params(index)));
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
}

/// Finished lines found in earlier output.
#[derive(Debug, Clone, Default)]
pub struct Finished {
    /// index → line (no newline), as found.
    pub lines: BTreeMap<usize, String>,
    /// Complete lines not kept: another shard, another sweep (index out of range or other
    /// parameters), or a repeated index.
    pub foreign: usize,
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

impl Finished {
    /// Collects the lines of `text` that belong to `shard` of `sweep` (first one per index wins).
    pub fn add_text(&mut self, sweep: &Sweep, shard: Shard, text: &[u8]) {
        for raw in text.split(|&b| b == b'\n') {
            if raw.iter().all(u8::is_ascii_whitespace) {
                continue;
            }
            let Ok(line) = std::str::from_utf8(raw) else {
                self.unreadable += 1;
                continue;
            };
            let line = line.trim_end_matches('\r');
            let Ok(head) = serde_json::from_str::<Head>(line) else {
                self.unreadable += 1;
                continue;
            };
            let i = head.index;
            let ours = i < sweep.len()
                && shard.contains(i)
                && !self.lines.contains_key(&i)
                && same_value(&Value::Object(head.params), &Value::Object(sweep.params(i)));
            if ours {
                self.lines.insert(i, line.to_string());
            } else {
                self.foreign += 1;
            }
        }
    }

    /// Collects the lines of each file that exists.
    pub fn read(sweep: &Sweep, shard: Shard, files: &[&Path]) -> io::Result<Self> {
        let mut f = Finished::default();
        for path in files {
            match fs::read(path) {
                Ok(bytes) => f.add_text(sweep, shard, &bytes),
                Err(e) if e.kind() == io::ErrorKind::NotFound => {}
                Err(e) => return Err(io::Error::new(e.kind(), format!("cannot read {}: {e}", path.display()))),
            }
        }
        Ok(f)
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

/// `path` with `suffix` appended to its file name (`a.jsonl` → `a.jsonl.partial`).
pub fn with_suffix(path: &Path, suffix: &str) -> PathBuf {
    let mut s: OsString = path.as_os_str().to_owned();
    s.push(suffix);
    PathBuf::from(s)
}

/// Writes `bytes` to `path` through `path.tmp` and a rename.
fn write_atomic(path: &Path, bytes: &[u8]) -> io::Result<()> {
    let tmp = with_suffix(path, ".tmp");
    let mut f = File::create(&tmp)?;
    f.write_all(bytes)?;
    f.sync_all()?;
    drop(f);
    fs::rename(&tmp, path)
}

/// Opens the partial file for appending; if it ends in a torn line, starts a new line so the
/// next row is not glued to the fragment (the fragment stays unreadable and is ignored).
fn open_partial(path: &Path) -> io::Result<File> {
    let mut f = OpenOptions::new().read(true).append(true).create(true).open(path)?;
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
    ExitCode::from(crate::cli::EXIT_BAD_CASE)
}

fn failed(msg: impl fmt::Display) -> ExitCode {
    eprintln!("error: {msg}");
    ExitCode::from(crate::cli::EXIT_FAILED)
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

/// Runs a sweep; returns the exit code.
pub fn run_cli(args: SweepArgs) -> ExitCode {
    let shard = match args.shard.as_deref().map(|s| (s, s.parse::<Shard>())) {
        None => Shard::ALL,
        Some((_, Ok(s))) => s,
        Some((text, Err(msg))) => {
            eprintln!("error: invalid --shard `{text}`: {msg}");
            return ExitCode::from(crate::cli::EXIT_BAD_CASE);
        }
    };
    let sweep = match load(&args.case) {
        Ok(s) => s,
        Err(e) => return bad_case(&e),
    };
    let base_dir = args.case.parent();
    match execute(&sweep, base_dir, shard, &args) {
        Ok(()) => ExitCode::SUCCESS,
        Err(e) => failed(e),
    }
}

fn execute(sweep: &Sweep, base_dir: Option<&Path>, shard: Shard, args: &SweepArgs) -> io::Result<()> {
    let start = Instant::now();
    let in_shard = shard.count(sweep.len());
    let partial = args.out.as_deref().map(|p| with_suffix(p, ".partial"));
    let (done, stream) = match (&args.out, &partial) {
        (Some(out), Some(partial)) => {
            let done = Finished::read(sweep, shard, &[out, partial])?;
            let file = open_partial(partial).map_err(io_context("open", partial))?;
            (done, Stream::File(file))
        }
        _ => (Finished::default(), Stream::Stdout(io::stdout())),
    };
    let skip: HashSet<usize> = done.lines.keys().copied().collect();
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
                .map_err(|e| io_context("append to", partial.as_deref().unwrap_or(Path::new("")))(e))?,
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

    let csv_lines: Option<Vec<String>> = match (&args.out, &partial) {
        (Some(out), Some(partial)) => {
            let all = Finished::read(sweep, shard, &[out, partial])?;
            write_atomic(out, &all.to_jsonl()).map_err(io_context("write", out))?;
            fs::remove_file(partial).or_else(|e| match e.kind() {
                io::ErrorKind::NotFound => Ok(()),
                _ => Err(e),
            })?;
            if all.lines.len() != in_shard {
                eprintln!(
                    "warning: {} holds {} of the {in_shard} designs",
                    out.display(),
                    all.lines.len()
                );
            }
            // Stage sweeps: a CSV and an SVG plot beside the JSON lines.
            if sweep.base.get("analysis").and_then(|a| a.as_str()) == Some("stage") {
                let lines: Vec<String> = all.lines.values().cloned().collect();
                if let Some(svg) = super::plots::stage_sweep_svg(&lines) {
                    let p = out.with_extension("svg");
                    write_atomic(&p, svg.as_bytes()).map_err(io_context("write", &p))?;
                }
                if args.csv.is_none() {
                    let p = out.with_extension("csv");
                    let axes: Vec<&str> = sweep.axes.iter().map(|(p, _)| p.as_str()).collect();
                    let refs: Vec<&str> = lines.iter().map(String::as_str).collect();
                    write_atomic(&p, table::csv(&axes, &refs).as_bytes()).map_err(io_context("write", &p))?;
                }
            }
            args.csv.as_ref().map(|_| all.lines.into_values().collect())
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
    eprintln!(
        "sweep: {in_shard} designs{shard_note}, {} already done, {} run, {} failed, {:.2} s ({:.0} designs/s){note}",
        skip.len(),
        tally.run,
        tally.failed,
        secs,
        rate(tally.run, start.elapsed()),
    );
    Ok(())
}

fn rate(n: usize, d: Duration) -> f64 {
    let s = d.as_secs_f64();
    if s > 0.0 {
        n as f64 / s
    } else {
        0.0
    }
}
