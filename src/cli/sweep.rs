//! `flexfem sweep` on the command line: output files, resume, locking, progress, exit codes.
//!
//! The designs run through the batch driver [`crate::design::sweep`]. With `--out FILE.jsonl`
//! the lines stream to `FILE.jsonl.partial` (appended, one write per line); a re-run skips the
//! designs already finished ([`super::resume`]). At the end all lines, sorted by index, replace
//! `FILE.jsonl` atomically and the partial file is removed. So a killed sweep resumes where it
//! stopped and never loses finished designs.
//!
//! The output is locked while the sweep runs (`FILE.jsonl.lock`, see [`crate::output::Lock`]):
//! a second sweep on the same `--out` — another shard, say — is refused instead of losing
//! designs. flexfem only replaces a `--out` file that is its own sweep output (every complete
//! line a sweep line) unless `--force`. A sweep with any error row exits 1.

use super::resume::{Accept, Finished};
use super::sweep_finish::{finish, Output, Written};
use super::targets::{check_replaceable, io_context, Kind, Stop, Targets};
use crate::case::sweep::Sweep;
use crate::case::CaseError;
use crate::design::sweep::{load, run_sweep_formatted, Line, LineFormat, Shard};
use crate::design::table;
use crate::output::write_atomic;
use serde_json::Value;
use std::collections::HashSet;
use std::fmt;
use std::fs::{self, File};
use std::io::{self, IsTerminal, Read, Seek, SeekFrom, Write};
use std::path::{Path, PathBuf};
use std::process::ExitCode;
use std::sync::Mutex;
use std::time::{Duration, Instant};

/// Command-line arguments of `flexfem sweep`.
#[derive(Debug, Clone, clap::Args)]
pub struct SweepArgs {
    /// The sweep case file (`"analysis": "sweep"`).
    pub case: PathBuf,
    /// Run only the designs whose index ≡ K−1 (mod N).
    #[arg(long, value_name = "K/N")]
    pub shard: Option<String>,
    /// Take the shard K/N from a Slurm job-array task's variables: K = SLURM_ARRAY_TASK_ID
    /// (1-based ids; 0-based when SLURM_ARRAY_TASK_MIN is 0, K = id + 1), N =
    /// SLURM_ARRAY_TASK_COUNT or --shard-count.
    #[arg(long, conflicts_with = "shard")]
    pub shard_from_env: bool,
    /// With --shard-from-env: the number of shards N (e.g. when rerunning one task of an array).
    #[arg(long, value_name = "N", requires = "shard_from_env")]
    pub shard_count: Option<usize>,
    /// Write the JSON lines to FILE (resumable) instead of stdout. FILE must be new or
    /// flexfem sweep output; anything else is refused unless --force.
    #[arg(long, value_name = "FILE.jsonl")]
    pub out: Option<PathBuf>,
    /// Also write a CSV table of parameters and scalar results.
    #[arg(long, value_name = "FILE.csv")]
    pub csv: Option<PathBuf>,
    /// Replace --out/--csv files that are not flexfem's own output. The case file itself
    /// is never overwritten.
    #[arg(long)]
    pub force: bool,
    /// On resume, keep earlier error rows instead of running those designs again.
    #[arg(long)]
    pub keep_errors: bool,
    /// Keep only these result fields in each line: comma-separated dotted paths, e.g.
    /// `stiffness_z,at_allowable.force,load_cases.0.platform`.
    #[arg(long, value_name = "a,b.c")]
    pub fields: Option<String>,
    /// Keep every result field in each line. By default a stage sweep's lines leave out the
    /// 6×6 platform compliance, the material echo and the per-hinge stresses (their maximum
    /// stays), a static sweep's keep the displacements of the loaded, prescribed and named
    /// (`compliance`, `metrics`) nodes only, without per-element stress lists, and a modal
    /// sweep's leave out the mode shapes: see `flexfem::design::sweep::omitted_fields`.
    #[arg(long, conflicts_with = "fields")]
    pub full: bool,
}

pub use super::sweep_notes::notes_path;
use super::sweep_notes::NotesFile;

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

thread_local! {
    /// Each sweep thread's copy of the line it is writing, with its newline.
    static LINE: std::cell::RefCell<Vec<u8>> = const { std::cell::RefCell::new(Vec::new()) };
}

/// Where finished lines go during the run.
enum Stream {
    Stdout(io::Stdout),
    File(File),
}

/// What the sink keeps under its lock (the lines themselves are written outside it).
struct SinkState {
    /// Rows kept for the CSV when they are not in a file (the values they were written from).
    kept: Option<Vec<(usize, Value)>>,
    /// With `--out` onto an output that held nothing: this run's lines ([`Written`]).
    written: Option<Written>,
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

/// Runs a sweep; returns the exit code: 0 when every design succeeded, 1 when any design
/// failed (error rows) or the output could not be written, 2 for a bad case file or arguments.
pub fn run_cli(args: SweepArgs) -> ExitCode {
    let from_env = args
        .shard_from_env
        .then(|| super::shard_env::shard_from(|v| std::env::var(v).ok(), args.shard_count));
    let shard = match args.shard.as_deref().map(|s| (s, s.parse::<Shard>())) {
        None => match from_env {
            None => Shard::ALL,
            Some(Ok(s)) => s,
            Some(Err(msg)) => {
                eprintln!("error: {msg}");
                return ExitCode::from(crate::output::EXIT_BAD_CASE);
            }
        },
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

/// Runs the sweep; returns the number of failed designs (error rows in the output).
fn execute(sweep: &Sweep, base_dir: Option<&Path>, shard: Shard, args: &SweepArgs) -> Result<usize, Stop> {
    let start = Instant::now();
    let in_shard = shard.count(sweep.len());
    let targets = Targets::new(sweep, &args.case, args.out.as_deref(), args.csv.as_deref())?;
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
    if let Some(p) = targets.csv.as_deref() {
        check_replaceable("--csv", p, Kind::Csv, args.force)?;
    }
    // Tables first, then plots (the order of the refusals).
    let mut extras: Vec<&(crate::analysis::kind::SweepFile, PathBuf)> = targets.extras.iter().collect();
    extras.sort_by_key(|(f, _)| !f.table);
    for (file, p) in extras {
        check_replaceable(file.label, p, Kind::of(file), args.force)?;
    }

    let accept = Accept {
        base_dir,
        keep_errors: args.keep_errors,
    };
    // Model notes go once into the sidecar of a --out file; on stdout they stay in the lines.
    let notes = match &targets.out {
        Some(out) => Some(NotesFile::open(notes_path(out), args.force)?),
        None => None,
    };
    let (done, stream) = match partial {
        Some(partial) => {
            let done = Finished::read(sweep, accept, &sources)?;
            let file = open_partial(partial).map_err(io_context("open", partial))?;
            (done, Stream::File(file))
        }
        None => (Finished::default(), Stream::Stdout(io::stdout())),
    };
    let fresh = partial.is_some() && done.is_nothing();
    let skip: HashSet<usize> = done.lines.keys().copied().filter(|&i| shard.contains(i)).collect();
    let to_run = in_shard - skip.len();
    let keep_for_csv = args.csv.is_some() && args.out.is_none();
    let fields = match args.fields.as_deref().map(LineFormat::parse_fields) {
        None => None,
        Some(Ok(f)) => Some(f),
        Some(Err(msg)) => return Err(Stop::Usage(format!("invalid --fields: {msg}"))),
    };
    let kind = sweep.base.get("analysis").and_then(Value::as_str);
    let format = LineFormat::of_sweep(kind, fields, args.full, notes.is_some());
    let state = Mutex::new(SinkState {
        kept: keep_for_csv.then(Vec::new),
        written: fresh.then(Written::default),
    });
    // With --out: the notes sidecar (a new reference is added in place, under its own lock).
    let notes = notes.map(Mutex::new);
    let pb = progress_bar(to_run);
    let stdout_tty = args.out.is_none() && io::stdout().is_terminal();
    let tally = run_sweep_formatted(sweep, base_dir, shard, &skip, &format, keep_for_csv, |row: Line| {
        // The notes entry goes in before the first line that refers to it.
        if let (Some(file), Some((r, json))) = (&notes, row.notes) {
            file.lock().unwrap_or_else(|p| p.into_inner()).add(r, json)?;
        }
        // One write per line, without a lock of ours: the partial file is opened for appending
        // (each write lands whole at the end), stdout has its own lock. The line and its newline
        // are copied into this thread's buffer, kept from line to line.
        LINE.with_borrow_mut(|buf| -> io::Result<()> {
            buf.clear();
            buf.extend_from_slice(row.text.as_bytes());
            buf.push(b'\n');
            match &stream {
                Stream::File(f) => (&mut &*f)
                    .write_all(buf)
                    .map_err(|e| io_context("append to", partial.unwrap_or(Path::new("")))(e)),
                Stream::Stdout(s) => {
                    let write = || -> io::Result<()> {
                        let mut lock = s.lock();
                        lock.write_all(buf)?;
                        lock.flush()
                    };
                    let write =
                        || write().map_err(|e| io::Error::new(e.kind(), format!("cannot write to stdout: {e}")));
                    if stdout_tty {
                        pb.suspend(write)
                    } else {
                        write()
                    }
                }
            }
        })?;
        let mut st = state.lock().unwrap_or_else(|p| p.into_inner());
        if let Some(k) = &mut st.kept {
            k.push((row.index, row.value.cloned().unwrap_or(Value::Null)));
        }
        if let Some(w) = &mut st.written {
            w.push(row.index, row.failed, row.text);
        }
        drop(st);
        pb.inc(1);
        Ok(())
    });
    pb.finish_and_clear();
    let tally = tally?;
    let state = state.into_inner().unwrap_or_else(|p| p.into_inner());
    drop(stream);
    drop(notes);

    let mut failed_total = tally.failed + done.failed.iter().filter(|&&i| shard.contains(i)).count();
    let csv_text: Option<String> = match (&targets.out, partial) {
        (Some(out), Some(partial)) => {
            let output = Output {
                out,
                partial,
                sources,
                accept,
                written: state.written,
            };
            let (failed, csv) = finish(sweep, shard, output, &targets.extras, args.csv.is_some())?;
            failed_total = failed;
            csv
        }
        // Rows of this run only, in memory: the table reads the values the lines were written
        // from (no round trip through the text).
        _ => state.kept.map(|mut k| {
            let axes: Vec<&str> = sweep.axes.iter().map(|(p, _)| p.as_str()).collect();
            k.sort_unstable_by_key(|(i, _)| *i);
            let rows: Vec<Value> = k.into_iter().map(|(_, v)| v).collect();
            table::csv_of_rows_with_units(&axes, &rows, super::sweep_finish::units_of(sweep))
        }),
    };
    if let (Some(csv), Some(text)) = (&args.csv, csv_text) {
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

fn rate(n: usize, d: Duration) -> f64 {
    let s = d.as_secs_f64();
    if s > 0.0 {
        n as f64 / s
    } else {
        0.0
    }
}
