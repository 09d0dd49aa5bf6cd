//! `flexfem.Row`: one design's line of a sweep as a read-only mapping over the line's text.
//!
//! A sweep hands out 10,000 rows of ~150 numbers each in a fraction of a second; building a
//! dict of Python objects for every value of every row took three times as long as the solves.
//! A row keeps the line `flexfem sweep` printed; the line is parsed (once) the first time a
//! key is read, and a value becomes a Python object only when it is asked for: a nested
//! object is another row over the same line, numbers, strings, booleans, null and lists are
//! the values `json.loads` gives. `to_dict()` gives the whole row as plain dicts and lists.

use crate::errors;
use pyo3::basic::CompareOp;
use pyo3::exceptions::PyKeyError;
use pyo3::prelude::*;
use pyo3::types::{PyBool, PyDict, PyIterator, PyList, PyString, PyTuple};
use serde_json::{Map, Value};
use std::sync::{Arc, OnceLock};

/// A design's line and, once a key of it was read, the line's JSON value.
pub struct Stored {
    /// The line as `flexfem sweep` writes it (no newline).
    pub text: String,
    value: OnceLock<Value>,
}

impl Stored {
    pub fn new(text: String) -> Stored {
        Stored {
            text,
            value: OnceLock::new(),
        }
    }

    /// The line's value, parsed on first use (`Null` for a line that is not JSON, which the
    /// sweep's writers never produce: reading such a row raises an internal error).
    pub fn value(&self) -> &Value {
        self.value
            .get_or_init(|| serde_json::from_str(&self.text).unwrap_or(Value::Null))
    }
}

/// One design's row of a sweep: a read-only mapping over the line `flexfem sweep` printed for
/// it (`index`, `params`, `design_hash`, `result` or `error`), or over an object in that line.
///
/// The line is parsed the first time a key is read, and a value becomes a Python object only
/// when it is read: `row["result"]["k_bend"]` converts one number. Nested objects are rows
/// too; numbers, strings, booleans, None and lists are what `json.loads` gives. A row supports
/// `row[key]`, `key in row`, `len`, iteration over its keys, `keys()`, `values()`, `items()`,
/// `get()` and `==` (with rows and dicts); it is a `collections.abc.Mapping` (`dict(row)`
/// keeps nested rows). `to_dict()` gives plain dicts and lists all the way down (for
/// `json.dumps`, or a copy to change); a row pickles and copies as that plain dict.
#[pyclass(module = "flexfem._flexfem", name = "Row", frozen, mapping)]
pub struct Row {
    stored: Arc<Stored>,
    /// The keys from the line down to this object.
    path: Box<[Box<str>]>,
}

impl Row {
    /// The row of a whole line.
    pub fn of_line(stored: Arc<Stored>) -> Row {
        Row {
            stored,
            path: Box::new([]),
        }
    }

    /// The object this row stands for.
    fn object(&self) -> PyResult<&Map<String, Value>> {
        let mut v = self.stored.value();
        for k in &self.path {
            v = v.get(&**k).unwrap_or(&Value::Null);
        }
        v.as_object().ok_or_else(|| {
            errors::internal(&format!(
                "a sweep line that is not a JSON object: {:.120}",
                self.stored.text
            ))
        })
    }

    /// The value at `key` as a Python object: an object is a row over the same line.
    fn to_py(&self, py: Python<'_>, key: &str, v: &Value) -> PyResult<Py<PyAny>> {
        if v.is_object() {
            let mut path = self.path.to_vec();
            path.push(key.into());
            let row = Row {
                stored: Arc::clone(&self.stored),
                path: path.into_boxed_slice(),
            };
            return Ok(Py::new(py, row)?.into_any());
        }
        errors::pythonize(py, v)
    }
}

#[pymethods]
impl Row {
    /// The value at `key`; `KeyError` when the row has no such key.
    fn __getitem__(&self, py: Python<'_>, key: &Bound<'_, PyAny>) -> PyResult<Py<PyAny>> {
        let found = match key.cast::<PyString>() {
            Ok(k) => {
                let k = k.to_str()?;
                self.object()?.get(k).map(|v| (k, v))
            }
            Err(_) => None,
        };
        match found {
            Some((k, v)) => self.to_py(py, k, v),
            None => Err(PyKeyError::new_err(key.clone().unbind())),
        }
    }

    fn __contains__(&self, key: &Bound<'_, PyAny>) -> PyResult<bool> {
        match key.cast::<PyString>() {
            Ok(k) => Ok(self.object()?.contains_key(k.to_str()?)),
            Err(_) => Ok(false),
        }
    }

    fn __len__(&self) -> PyResult<usize> {
        Ok(self.object()?.len())
    }

    /// Iterates over the keys, in the line's order.
    fn __iter__<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyIterator>> {
        self.keys(py)?.into_any().try_iter()
    }

    /// The keys, in the line's order.
    fn keys<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyList>> {
        PyList::new(py, self.object()?.keys())
    }

    /// The values, in the keys' order.
    fn values<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyList>> {
        let values = self
            .object()?
            .iter()
            .map(|(k, v)| self.to_py(py, k, v))
            .collect::<PyResult<Vec<_>>>()?;
        PyList::new(py, values)
    }

    /// The (key, value) pairs, in the line's order.
    fn items<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyList>> {
        let items = self
            .object()?
            .iter()
            .map(|(k, v)| PyTuple::new(py, [k.into_pyobject(py)?.into_any().unbind(), self.to_py(py, k, v)?]))
            .collect::<PyResult<Vec<_>>>()?;
        PyList::new(py, items)
    }

    /// The value at `key`, or `default` when the row has no such key.
    #[pyo3(signature = (key, default=None))]
    fn get(&self, py: Python<'_>, key: &Bound<'_, PyAny>, default: Option<Py<PyAny>>) -> PyResult<Py<PyAny>> {
        if self.__contains__(key)? {
            self.__getitem__(py, key)
        } else {
            Ok(default.unwrap_or_else(|| py.None()))
        }
    }

    /// The row as plain Python values: dicts, lists, float, int, str, bool, None (what
    /// `json.loads` of the line gives).
    fn to_dict<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyDict>> {
        let d = errors::pythonize(py, &Value::Object(self.object()?.clone()))?;
        Ok(d.into_bound(py).cast_into::<PyDict>()?)
    }

    /// Rows are equal when their values are; a row equals a mapping equal to its `to_dict()`.
    fn __richcmp__(&self, py: Python<'_>, other: &Bound<'_, PyAny>, op: CompareOp) -> PyResult<Py<PyAny>> {
        let want_eq = matches!(op, CompareOp::Eq);
        let eq = match op {
            CompareOp::Eq | CompareOp::Ne => {
                if let Ok(o) = other.cast::<Row>() {
                    self.object()? == o.get().object()?
                } else if other.is_instance_of::<PyDict>() || other.hasattr("keys")? {
                    self.to_dict(py)?.eq(other)?
                } else {
                    return Ok(py.NotImplemented());
                }
            }
            _ => return Ok(py.NotImplemented()),
        };
        Ok(PyBool::new(py, eq == want_eq).to_owned().into_any().unbind())
    }

    /// Pickles (and copies) as its plain dict (`to_dict()`), so rows cross process boundaries.
    fn __reduce__<'py>(&self, py: Python<'py>) -> PyResult<(Bound<'py, PyAny>, (Bound<'py, PyDict>,))> {
        Ok((py.get_type::<PyDict>().into_any(), (self.to_dict(py)?,)))
    }

    /// As the dict's repr.
    fn __repr__(&self, py: Python<'_>) -> PyResult<String> {
        Ok(self.to_dict(py)?.repr()?.to_string())
    }
}
