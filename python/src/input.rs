//! The case argument of every function: a dict (a case as Python values), a case file's path
//! (`str` or `os.PathLike`), or the JSON text of a case (a `str` starting with `{`).

use flexfem::analysis::{self, Parsed};
use flexfem::case::CaseError;
use pyo3::prelude::*;
use pyo3::types::{PyDict, PyString};
use serde_json::Value;
use std::path::{Path, PathBuf};

/// A case as given from Python, read into Rust values (so the solve can run without the GIL).
pub enum CaseInput {
    /// A case file: parsed as `flexfem run FILE` parses it (files it names are found beside it).
    File(PathBuf),
    /// A case value: files it names are found from the working folder.
    Value(Value),
    /// JSON text that is not valid JSON: the error `flexfem run` gives for such a file.
    Invalid(CaseError),
}

impl CaseInput {
    /// Reads the case argument; a type other than dict, str or path is a `TypeError`.
    pub fn extract(case: &Bound<'_, PyAny>) -> PyResult<CaseInput> {
        if case.is_instance_of::<PyDict>() {
            let value: Value = pythonize::depythonize(case).map_err(|e| {
                pyo3::exceptions::PyTypeError::new_err(format!(
                    "the case dict holds a value JSON cannot hold (use dict, list, str, int, float, bool, None): {e}"
                ))
            })?;
            return Ok(CaseInput::Value(value));
        }
        if case.is_instance_of::<PyString>() {
            let text: String = case.extract()?;
            if text.trim_start().starts_with('{') {
                return Ok(match serde_json::from_str(&text) {
                    Ok(v) => CaseInput::Value(v),
                    Err(e) => CaseInput::Invalid(CaseError::new(".", format!("not valid JSON: {e}"))),
                });
            }
            return Ok(CaseInput::File(PathBuf::from(text)));
        }
        match case.extract::<PathBuf>() {
            Ok(p) => Ok(CaseInput::File(p)),
            Err(_) => Err(pyo3::exceptions::PyTypeError::new_err(format!(
                "case must be a dict, a case file's path (str or pathlib.Path) or JSON text, not {}",
                case.get_type().name()?
            ))),
        }
    }

    /// Parses the case with its parameters resolved (as `flexfem run` and `check` do).
    pub fn parse(&self) -> Result<Parsed, CaseError> {
        match self {
            CaseInput::File(p) => analysis::load_resolved(p),
            CaseInput::Value(v) => analysis::case_file::parse_resolved(v.clone(), None, true),
            CaseInput::Invalid(e) => Err(e.clone()),
        }
    }

    /// Where the files the case names are looked up first (a case file's folder).
    pub fn base_dir(&self) -> Option<&Path> {
        match self {
            CaseInput::File(p) => p.parent(),
            _ => None,
        }
    }
}
