//! flexfem's errors as the Python exceptions of the package: a bad case raises
//! `flexfem.CaseError(path, message)` (what `flexfem run` exits 2 for, with the same JSON path),
//! a failed analysis `flexfem.AnalysisError(context, message)` (exit 1).

use flexfem::analysis::RunError;
use pyo3::prelude::*;

/// The exception class `name` of the Python package `flexfem`.
fn class<'py>(py: Python<'py>, name: &str) -> PyResult<Bound<'py, PyAny>> {
    py.import("flexfem")?.getattr(name)
}

/// The Python exception of a run's error.
pub fn to_py(py: Python<'_>, e: &RunError) -> PyErr {
    let (name, context, message) = match e {
        RunError::Case(c) => ("CaseError", c.path.as_str(), c.message.as_str()),
        RunError::Analysis(a) => ("AnalysisError", a.context.as_str(), a.message.as_str()),
    };
    match class(py, name).and_then(|c| c.call1((context, message))) {
        Ok(exc) => PyErr::from_value(exc),
        Err(import_failed) => import_failed,
    }
}

/// An error that is flexfem's fault (please report), as `RuntimeError`.
pub fn internal(e: &dyn std::fmt::Display) -> PyErr {
    pyo3::exceptions::PyRuntimeError::new_err(format!("internal error (please report): {e}"))
}

/// A result value as Python objects (dict, list, float, int, str, bool, None), built directly.
pub fn pythonize(py: Python<'_>, value: &serde_json::Value) -> PyResult<Py<PyAny>> {
    pythonize::pythonize(py, value)
        .map(Bound::unbind)
        .map_err(|e| internal(&e))
}
