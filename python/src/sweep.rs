//! `flexfem.sweep`: the designs of a sweep run on a thread of their own through the batch
//! driver `flexfem sweep` uses ([`flexfem::design::sweep::run_sweep_formatted`], rayon workers,
//! the same route and the same lines as the command line's); the iterator hands out their rows
//! in index order as they finish, waiting without the GIL, as [`Row`]s over the lines (values
//! become Python objects when they are read), and the table as numpy columns ([`columns`]).

use crate::columns;
use crate::errors;
use crate::input::CaseInput;
use crate::row::{Row, Stored};
use flexfem::analysis::units::UnitOf;
use flexfem::analysis::{self, Case};
use flexfem::case::sweep::Sweep;
use flexfem::case::CaseError;
use flexfem::design::sweep::{run_sweep_formatted, LineFormat, Shard, Tally};
use flexfem::design::table;
use pyo3::prelude::*;
use pyo3::types::PyList;
use serde_json::{Map, Value};
use std::collections::{BTreeMap, HashSet};
use std::io;
use std::path::PathBuf;
use std::sync::mpsc::{channel, Receiver};
use std::sync::{Arc, Mutex};
use std::thread::JoinHandle;

/// One finished design: its index, whether it is an error row and its JSON line.
type Finished = (usize, bool, String);

/// A running sweep (the native half of `flexfem.Sweep`).
#[pyclass(module = "flexfem._flexfem")]
pub struct SweepRun {
    /// Lines as the workers finish them.
    finished: Mutex<Receiver<Finished>>,
    /// Lines that arrived before a smaller index.
    early: BTreeMap<usize, Finished>,
    /// The next index to hand out.
    next: usize,
    /// Number of designs.
    len: usize,
    /// Error rows handed out so far.
    failed: usize,
    /// The lines handed out, in index order (the rows' text, and the table's).
    lines: Vec<Arc<Stored>>,
    /// The varied paths (the table's first columns).
    axes: Vec<String>,
    /// The analysis of the base case (the table's units).
    kind: Option<String>,
    /// The thread running the designs, until it is joined.
    worker: Option<JoinHandle<io::Result<Tally>>>,
}

/// The sweep of `case` (a sweep case, or with `vary` a base case), built as `flexfem sweep`
/// builds a sweep case's; errors name the path in that sweep case (`vary.…`, `base.…`).
fn build(case: &CaseInput, vary: Option<Value>) -> Result<Sweep, CaseError> {
    let value = match (vary, case) {
        (None, _) => None,
        (Some(vary), CaseInput::Value(base)) => Some((base.clone(), vary)),
        (Some(vary), CaseInput::File(path)) => {
            let text = std::fs::read_to_string(path)
                .map_err(|e| CaseError::new(".", format!("cannot read case file {}: {e}", path.display())))?;
            let base = serde_json::from_str(&text).map_err(|e| CaseError::new(".", format!("not valid JSON: {e}")))?;
            Some((base, vary))
        }
        (Some(_), CaseInput::Invalid(e)) => return Err(e.clone()),
    };
    let parsed = match value {
        Some((base, vary)) => {
            let mut m = Map::new();
            m.insert("analysis".into(), "sweep".into());
            m.insert("base".into(), base);
            m.insert("vary".into(), vary);
            analysis::case_file::parse_resolved(Value::Object(m), case.base_dir(), true)?
        }
        None => case.parse()?,
    };
    match parsed.case {
        Case::Sweep(s) => s.build(),
        other => Err(CaseError::value(
            "analysis",
            format!("\"{}\"", other.analysis()),
            "flexfem.sweep needs a sweep case (\"analysis\": \"sweep\"), or a base case and vary={...}",
        )),
    }
}

#[pymethods]
impl SweepRun {
    /// Starts the sweep: `case` a sweep case, or a base case with `vary` ({path: values});
    /// `fields`, `full` as `flexfem sweep --fields/--full`; `threads` worker threads.
    #[new]
    #[pyo3(signature = (case, vary=None, fields=None, full=false, threads=None))]
    fn new(
        py: Python<'_>,
        case: &Bound<'_, PyAny>,
        vary: Option<&Bound<'_, PyAny>>,
        fields: Option<Vec<String>>,
        full: bool,
        threads: Option<usize>,
    ) -> PyResult<SweepRun> {
        let input = CaseInput::extract(case)?;
        let vary: Option<Value> = match vary {
            Some(v) => Some(pythonize::depythonize(v).map_err(|e| {
                pyo3::exceptions::PyTypeError::new_err(format!("vary must be a dict of path → values: {e}"))
            })?),
            None => None,
        };
        let sweep = py
            .detach(|| build(&input, vary))
            .map_err(|e| errors::to_py(py, &analysis::RunError::Case(e)))?;
        if let Some(f) = &fields {
            LineFormat::parse_fields(&f.join(",")).map_err(pyo3::exceptions::PyValueError::new_err)?;
        }
        if threads == Some(0) {
            return Err(pyo3::exceptions::PyValueError::new_err(
                "threads = 0: give a number of worker threads ≥ 1, or None for one per core",
            ));
        }
        let kind = sweep.base.get("analysis").and_then(Value::as_str).map(str::to_string);
        let format = LineFormat::of_sweep(kind.as_deref(), fields, full, false);
        let base_dir: Option<PathBuf> = input.base_dir().map(PathBuf::from);
        let (len, axes) = (sweep.len(), sweep.axes.iter().map(|(p, _)| p.clone()).collect());
        let (tx, rx) = channel::<Finished>();
        let worker = std::thread::spawn(move || {
            let run = || {
                run_sweep_formatted(
                    &sweep,
                    base_dir.as_deref(),
                    Shard::ALL,
                    &HashSet::new(),
                    &format,
                    // No JSON values: the route `flexfem sweep` takes to stdout (the typed
                    // route where the kind has one), the lines only; rows parse them on demand.
                    false,
                    |line| {
                        tx.send((line.index, line.failed, line.text.to_string()))
                            .map_err(|_| io::Error::other("the sweep's iterator was dropped"))
                    },
                )
            };
            match threads {
                Some(n) => rayon::ThreadPoolBuilder::new()
                    .num_threads(n)
                    .build()
                    .map_err(io::Error::other)
                    .and_then(|pool| pool.install(run)),
                None => run(),
            }
        });
        Ok(SweepRun {
            finished: Mutex::new(rx),
            early: BTreeMap::new(),
            next: 0,
            len,
            failed: 0,
            lines: Vec::with_capacity(len),
            axes,
            kind,
            worker: Some(worker),
        })
    }

    /// Number of designs.
    fn __len__(&self) -> usize {
        self.len
    }

    /// Error rows handed out so far.
    #[getter]
    fn failed(&self) -> usize {
        self.failed
    }

    /// The varied paths, in the order of the design index (last fastest).
    #[getter]
    fn axes(&self) -> Vec<String> {
        self.axes.clone()
    }

    /// The next designs' rows (index order): every row finished and not yet handed out, at
    /// least one (waiting without the GIL); an empty list after the last.
    fn next_rows<'py>(&mut self, py: Python<'py>) -> PyResult<Bound<'py, PyList>> {
        if self.next >= self.len {
            self.join(py)?;
            return PyList::new(py, Vec::<Row>::new());
        }
        while !self.early.contains_key(&self.next) {
            let rx = &self.finished;
            // Everything finished by now, waiting for the first only when nothing is.
            let got = py.detach(|| {
                let rx = rx.lock().map_err(|_| ())?;
                let mut got = vec![rx.recv().map_err(|_| ())?];
                got.extend(rx.try_iter());
                Ok::<_, ()>(got)
            });
            match got {
                Ok(finished) => {
                    for f in finished {
                        self.early.insert(f.0, f);
                    }
                }
                Err(()) => {
                    self.join(py)?;
                    return Err(errors::internal(&format!(
                        "the sweep stopped before design {} of {}",
                        self.next, self.len
                    )));
                }
            }
        }
        PyList::new(py, self.hand_out())
    }

    /// The rows of every design not yet handed out (index order), after the last design ran:
    /// waits for the sweep's thread without the GIL and without waking for each line.
    fn rest_rows<'py>(&mut self, py: Python<'py>) -> PyResult<Bound<'py, PyList>> {
        self.join(py)?;
        let rx = self
            .finished
            .lock()
            .map_err(|_| errors::internal(&"the sweep's lines were poisoned"))?;
        for f in rx.try_iter() {
            self.early.insert(f.0, f);
        }
        drop(rx);
        let rows = self.hand_out();
        if self.next < self.len {
            return Err(errors::internal(&format!(
                "the sweep stopped before design {} of {}",
                self.next, self.len
            )));
        }
        PyList::new(py, rows)
    }

    /// The table of [`Self::table_csv`] as columns: (names, names with units, a numpy array
    /// per column) of the rows handed out so far (see [`columns`]).
    #[allow(clippy::type_complexity)]
    fn columns<'py>(&self, py: Python<'py>) -> PyResult<(Vec<String>, Vec<String>, Bound<'py, PyList>)> {
        columns::columns(py, &self.axes, &self.lines, self.units())
    }

    /// The CSV table `flexfem sweep --csv` writes (parameters and scalar results with units)
    /// of the rows handed out so far, in index order.
    fn table_csv(&self) -> String {
        let axes: Vec<&str> = self.axes.iter().map(String::as_str).collect();
        let refs: Vec<&str> = self.lines.iter().map(|l| l.text.as_str()).collect();
        table::csv_with_units(&axes, &refs, self.units())
    }
}

impl SweepRun {
    /// The finished rows from the next index on, in order, moved to the handed-out lines.
    fn hand_out(&mut self) -> Vec<Row> {
        let mut rows = Vec::new();
        while let Some((_, failed, line)) = self.early.remove(&self.next) {
            self.next += 1;
            self.failed += usize::from(failed);
            let stored = Arc::new(Stored::new(line));
            self.lines.push(Arc::clone(&stored));
            rows.push(Row::of_line(stored));
        }
        rows
    }

    /// The column units of the sweep's analysis kind.
    fn units(&self) -> Option<(UnitOf, UnitOf)> {
        self.kind
            .as_deref()
            .and_then(analysis::registry::find)
            .and_then(|a| a.column_units())
    }

    /// Waits for the worker thread (without the GIL); a sink or pool error becomes a
    /// `RuntimeError`.
    fn join(&mut self, py: Python<'_>) -> PyResult<()> {
        let Some(worker) = self.worker.take() else {
            return Ok(());
        };
        match py.detach(|| worker.join()) {
            Ok(Ok(_)) => Ok(()),
            Ok(Err(e)) => Err(errors::internal(&e)),
            Err(_) => Err(errors::internal(&"the sweep's thread panicked")),
        }
    }
}
