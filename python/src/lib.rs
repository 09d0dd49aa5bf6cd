//! `flexfem._flexfem`: the flexfem engine as a Python extension module (PyO3).
//!
//! Each function takes a case (a dict, a case file's path, or JSON text), runs it through the
//! library's own entry points (those `flexfem run | check | schema | sweep` call) with the GIL
//! released during the solve, and hands back Python objects: the result as a dict built
//! directly from the result value (no JSON text), sweep rows as read-only mappings over their
//! lines and the sweep table as numpy columns, matrices as numpy arrays and scipy.sparse
//! matrices over the Rust buffers. The idiomatic layer (docstrings, exceptions, `to_pandas`) is
//! the Python package `flexfem/` around this module.

mod arrays;
mod columns;
mod errors;
mod input;
mod leaves;
mod row;
mod sweep;

use flexfem::analysis::{self, Case};
use pyo3::prelude::*;
use pyo3::types::PyDict;

/// Runs `f` on `threads` worker threads (a pool of its own), else on rayon's global pool: one
/// thread per core unless RAYON_NUM_THREADS says otherwise, as `flexfem --threads` does.
pub(crate) fn with_threads<T: Send>(threads: Option<usize>, f: impl FnOnce() -> T + Send) -> PyResult<T> {
    match threads {
        None => Ok(f()),
        Some(0) => Err(pyo3::exceptions::PyValueError::new_err(
            "threads = 0: give a number of worker threads ≥ 1, or None for one per core",
        )),
        Some(n) => {
            let pool = rayon::ThreadPoolBuilder::new()
                .num_threads(n)
                .build()
                .map_err(|e| pyo3::exceptions::PyRuntimeError::new_err(format!("cannot start {n} threads: {e}")))?;
            Ok(pool.install(f))
        }
    }
}

/// run(case, threads=None) -> dict: the result `flexfem run CASE` prints.
#[pyfunction]
#[pyo3(signature = (case, threads=None))]
fn run(py: Python<'_>, case: &Bound<'_, PyAny>, threads: Option<usize>) -> PyResult<Py<PyAny>> {
    let source = input::CaseInput::extract(case)?;
    let outcome = py.detach(|| {
        with_threads(threads, || {
            let parsed = source.parse()?;
            let mut outcome = analysis::run(&parsed.case).map_err(|e| parsed.locate_run(e))?;
            outcome.echo_parameters(&parsed.parameters);
            Ok::<_, analysis::RunError>(outcome)
        })
    })?;
    let outcome = outcome.map_err(|e| errors::to_py(py, &e))?;
    errors::pythonize(py, &outcome.json)
}

/// check(case) -> str: validates without solving, as `flexfem check CASE`; returns the
/// analysis kind. The warnings `flexfem check` prints (those of a run that depend on the case
/// alone: hinges outside their calibrated ranges, implausible materials) are issued as Python
/// `UserWarning`s, one each.
#[pyfunction]
fn check(py: Python<'_>, case: &Bound<'_, PyAny>) -> PyResult<String> {
    let source = input::CaseInput::extract(case)?;
    let checked = py.detach(|| {
        let parsed = source.parse()?;
        let warnings = match &parsed.case {
            Case::Sweep(s) => {
                let sweep = s.build()?;
                flexfem::design::sweep::check(&sweep, source.base_dir())?;
                Vec::new()
            }
            c => {
                analysis::check(c).map_err(|e| parsed.locate(e))?;
                analysis::check_warnings(c)
            }
        };
        Ok::<_, flexfem::case::CaseError>((parsed.case.analysis().to_string(), warnings))
    });
    let (kind, warnings) = checked.map_err(|e| errors::to_py(py, &analysis::RunError::Case(e)))?;
    let category = py.get_type::<pyo3::exceptions::PyUserWarning>();
    for w in warnings {
        let text = std::ffi::CString::new(w).map_err(|e| errors::internal(&e))?;
        // Level 2: the caller of the package's `check` (this is called by its wrapper).
        PyErr::warn(py, &category, &text, 2)?;
    }
    Ok(kind)
}

/// schema() -> dict: the JSON Schema of case files, as `flexfem schema` prints it.
#[pyfunction]
fn schema(py: Python<'_>) -> PyResult<Py<PyAny>> {
    let value = serde_json::to_value(analysis::schema()).map_err(|e| errors::internal(&e))?;
    errors::pythonize(py, &value)
}

/// matrices(case, threads=None) -> (K, M, dofs, node_frame): the reduced stiffness and mass
/// as (data, indices, indptr, n) CSR buffers, the node and DOF name of each equation and
/// whether it is in its node's frame (`flexfem run --export-matrices`).
#[pyfunction]
#[pyo3(signature = (case, threads=None))]
fn matrices<'py>(py: Python<'py>, case: &Bound<'py, PyAny>, threads: Option<usize>) -> PyResult<Bound<'py, PyDict>> {
    let source = input::CaseInput::extract(case)?;
    let mats = py.detach(|| {
        with_threads(threads, || {
            let parsed = source.parse()?;
            analysis::export::matrices(&parsed.case).map_err(|e| parsed.locate_run(e))
        })
    })?;
    let mats = mats.map_err(|e| errors::to_py(py, &e))?;
    arrays::matrices_dict(py, mats)
}

/// state_space(case, threads=None) -> dict of A, B, C, D (numpy, Fortran order over the Rust
/// buffers), omega (rad/s) and zeta of an frf case.
#[pyfunction]
#[pyo3(signature = (case, threads=None))]
fn state_space<'py>(py: Python<'py>, case: &Bound<'py, PyAny>, threads: Option<usize>) -> PyResult<Bound<'py, PyDict>> {
    let source = input::CaseInput::extract(case)?;
    let ss = py.detach(|| {
        with_threads(threads, || {
            let parsed = source.parse()?;
            analysis::export::state_space(&parsed.case).map_err(|e| parsed.locate_run(e))
        })
    })?;
    let ss = ss.map_err(|e| errors::to_py(py, &e))?;
    arrays::state_space_dict(py, ss)
}

/// hinge(case) -> (result dict, 6×6 compliance): the `hinge` case's result as `run` gives it
/// and the compliance at the free end face from the typed result (numpy, no JSON).
#[pyfunction]
fn hinge<'py>(py: Python<'py>, case: &Bound<'py, PyAny>) -> PyResult<(Py<PyAny>, Bound<'py, PyAny>)> {
    let source = input::CaseInput::extract(case)?;
    let done = py.detach(|| {
        let parsed = source.parse()?;
        let Case::Hinge(h) = &parsed.case else {
            return Err(analysis::RunError::Case(flexfem::case::CaseError::value(
                "analysis",
                format!("\"{}\"", parsed.case.analysis()),
                "flexfem.hinge takes a hinge case",
            )));
        };
        let typed = analysis::hinge::solve(h).map_err(|e| parsed.locate_run(e))?;
        let mut outcome = analysis::run(&parsed.case).map_err(|e| parsed.locate_run(e))?;
        outcome.echo_parameters(&parsed.parameters);
        Ok((outcome, typed.result.hinge.compliance))
    });
    let (outcome, compliance) = done.map_err(|e| errors::to_py(py, &e))?;
    Ok((errors::pythonize(py, &outcome.json)?, arrays::square6(py, &compliance)?))
}

/// The extension module.
#[pymodule]
fn _flexfem(m: &Bound<'_, PyModule>) -> PyResult<()> {
    m.add_function(wrap_pyfunction!(run, m)?)?;
    m.add_function(wrap_pyfunction!(check, m)?)?;
    m.add_function(wrap_pyfunction!(schema, m)?)?;
    m.add_function(wrap_pyfunction!(matrices, m)?)?;
    m.add_function(wrap_pyfunction!(state_space, m)?)?;
    m.add_function(wrap_pyfunction!(hinge, m)?)?;
    m.add_class::<sweep::SweepRun>()?;
    m.add_class::<row::Row>()?;
    m.add("__version__", env!("CARGO_PKG_VERSION"))?;
    Ok(())
}
