//! `Sweep.columns()` and `Sweep.to_pandas()`: the table of `flexfem sweep --csv` (`index`,
//! each varied path, every scalar leaf of the result under its dotted name, `error`; the leaves
//! as [`table::visit_leaves`] finds them) as one numpy array per column, built on the Rust side
//! from the lines (parsed in parallel, without the GIL) instead of through a dict per row.
//!
//! A column's type follows its cells, as `pandas.read_csv` of the CSV table infers it: integers
//! everywhere → int64; numbers with some cells empty (null or missing) or not integral →
//! float64 (empty cells NaN); booleans everywhere → bool; no cell at all → float64 of NaN;
//! anything else (text, mixed kinds) → an object array of Python values (empty cells `None`).

use crate::row::Stored;
use flexfem::analysis::units::UnitOf;
use flexfem::design::table::visit_leaves;
use numpy::PyArray1;
use pyo3::prelude::*;
use pyo3::types::PyList;
use rayon::prelude::*;
use serde_json::Value;
use std::collections::HashMap;
use std::sync::Arc;

/// One column's cells, typed.
enum Column<'a> {
    Int(Vec<i64>),
    Float(Vec<f64>),
    Bool(Vec<bool>),
    Object(Vec<Option<&'a Value>>),
}

impl<'a> Column<'a> {
    /// The column of `cells` (`None` and null: empty).
    fn of(cells: Vec<Option<&'a Value>>) -> Column<'a> {
        let present = || cells.iter().flatten().filter(|v| !v.is_null());
        if present().all(|v| v.is_number()) {
            if cells.iter().all(|c| c.is_some_and(|v| v.is_i64())) {
                return Column::Int(cells.iter().map(|c| c.and_then(Value::as_i64).unwrap_or(0)).collect());
            }
            let nan = |c: &Option<&Value>| c.and_then(Value::as_f64).unwrap_or(f64::NAN);
            return Column::Float(cells.iter().map(nan).collect());
        }
        if cells.iter().all(|c| c.is_some_and(Value::is_boolean)) {
            return Column::Bool(
                cells
                    .iter()
                    .map(|c| c.and_then(Value::as_bool).unwrap_or(false))
                    .collect(),
            );
        }
        Column::Object(cells)
    }

    fn to_numpy<'py>(self, py: Python<'py>) -> PyResult<Bound<'py, PyAny>> {
        Ok(match self {
            Column::Int(v) => PyArray1::from_vec(py, v).into_any(),
            Column::Float(v) => PyArray1::from_vec(py, v).into_any(),
            Column::Bool(v) => PyArray1::from_vec(py, v).into_any(),
            Column::Object(cells) => {
                let objects = cells
                    .into_iter()
                    .map(|c| match c {
                        Some(v) => crate::errors::pythonize(py, v),
                        None => Ok(py.None()),
                    })
                    .collect::<PyResult<Vec<Py<PyAny>>>>()?;
                PyArray1::from_vec(py, objects).into_any()
            }
        })
    }
}

/// `name [unit]` when `unit_of` gives the dotted path `name` a unit (the CSV table's header).
fn headed(name: &str, unit_of: Option<UnitOf>) -> String {
    let path: Vec<&str> = name.split('.').collect();
    match unit_of.and_then(|f| f(&path)) {
        Some(u) => format!("{name} [{u}]"),
        None => name.to_string(),
    }
}

/// The columns of `rows` (in index order) of a sweep varying `axes`: (names, names with
/// units, one numpy array per column). Rows that are not objects are left out, as in the CSV.
pub fn columns<'py>(
    py: Python<'py>,
    axes: &[String],
    rows: &[Arc<Stored>],
    units: Option<(UnitOf, UnitOf)>,
) -> PyResult<(Vec<String>, Vec<String>, Bound<'py, PyList>)> {
    // Parsing and the cells of each column, without the GIL; Python objects after.
    let (names, typed) = py.detach(|| {
        let values: Vec<&Value> = rows.par_iter().map(|r| r.value()).filter(|v| v.is_object()).collect();
        let n = values.len();
        // Each row's result leaves: their names (one per line) and values.
        let leaves: Vec<(String, Vec<&Value>)> = values
            .par_iter()
            .map(|row| {
                let (mut names, mut cells) = (String::new(), Vec::new());
                if let Some(result) = row.get("result") {
                    let mut name = String::new();
                    visit_leaves(&mut name, result, &mut |n, x| {
                        names.push_str(n);
                        names.push('\n');
                        cells.push(x);
                    });
                }
                (names, cells)
            })
            .collect();
        // Columns in order of first appearance, assigned once per distinct sequence of names.
        let mut result_names: Vec<&str> = Vec::new();
        let mut column_of: HashMap<&str, usize> = HashMap::new();
        let mut shapes: HashMap<&str, Vec<usize>> = HashMap::new();
        for (names, _) in &leaves {
            if shapes.contains_key(names.as_str()) {
                continue;
            }
            let cols = names
                .lines()
                .map(|name| {
                    *column_of.entry(name).or_insert_with(|| {
                        result_names.push(name);
                        result_names.len() - 1
                    })
                })
                .collect();
            shapes.insert(names.as_str(), cols);
        }
        let mut cells: Vec<Vec<Option<&Value>>> = vec![vec![None; n]; result_names.len()];
        for (r, (names, values)) in leaves.iter().enumerate() {
            for (&c, &v) in shapes[names.as_str()].iter().zip(values) {
                cells[c][r] = Some(v);
            }
        }
        let top = |key: &str| values.iter().map(|v| v.get(key)).collect::<Vec<_>>();
        let param = |a: &str| values.iter().map(|v| v.get("params").and_then(|p| p.get(a))).collect();
        let mut all: Vec<Vec<Option<&Value>>> = vec![top("index")];
        all.extend(axes.iter().map(|a| param(a)));
        all.extend(cells);
        all.push(top("error"));
        let names: Vec<String> = result_names.iter().map(|s| s.to_string()).collect();
        let typed: Vec<Column> = all.into_par_iter().map(Column::of).collect();
        (names, typed)
    });
    let (result_unit, input_unit) = (units.map(|u| u.0), units.map(|u| u.1));
    let mut plain = vec!["index".to_string()];
    let mut with_units = plain.clone();
    for a in axes {
        plain.push(a.clone());
        with_units.push(headed(a, input_unit));
    }
    for r in &names {
        plain.push(r.clone());
        with_units.push(headed(r, result_unit));
    }
    plain.push("error".into());
    with_units.push("error".into());
    let arrays = typed
        .into_iter()
        .map(|c| c.to_numpy(py))
        .collect::<PyResult<Vec<_>>>()?;
    Ok((plain, with_units, PyList::new(py, arrays)?))
}
