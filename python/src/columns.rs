//! `Sweep.columns()` and `Sweep.to_pandas()`: the table of `flexfem sweep --csv` (`index`,
//! each varied path, every scalar leaf of the result under its dotted name, `error`; the leaves
//! as the library's CSV table finds them) as one numpy array per column, built on the Rust side
//! from the lines ([`leaves`]: read in parallel, without the GIL, no JSON value) instead of
//! through a dict per row.
//!
//! A column's type follows its cells, as `pandas.read_csv` of the CSV table infers it: integers
//! everywhere → int64; numbers with some cells empty (null or missing) or not integral →
//! float64 (empty cells NaN); booleans everywhere → bool; no cell at all → float64 of NaN;
//! anything else (text, mixed kinds) → an object array of Python values (empty cells `None`).

use crate::leaves::{self, Cell, Flat};
use crate::row::Stored;
use flexfem::analysis::units::UnitOf;
use numpy::PyArray1;
use pyo3::prelude::*;
use pyo3::types::PyList;
use rayon::prelude::*;
use std::collections::HashMap;
use std::sync::Arc;

/// One column's cells, typed.
enum Column {
    Int(Vec<i64>),
    Float(Vec<f64>),
    Bool(Vec<bool>),
    Object(Vec<Cell>),
}

impl Column {
    /// The column of the cells `cell(0..n)` (missing and null: empty), read in one pass when
    /// they are numbers (a second for integers, booleans and text).
    fn of<'a>(n: usize, cell: impl Fn(usize) -> &'a Cell) -> Column {
        let mut floats = Vec::with_capacity(n);
        let (mut ints, mut numbers, mut bools) = (true, true, true);
        for r in 0..n {
            match cell(r) {
                Cell::Int(i) => {
                    bools = false;
                    floats.push(*i as f64);
                }
                Cell::Float(x) => {
                    (ints, bools) = (false, false);
                    floats.push(*x);
                }
                Cell::Null | Cell::Missing => {
                    (ints, bools) = (false, false);
                    floats.push(f64::NAN);
                }
                Cell::Bool(_) => (ints, numbers) = (false, false),
                Cell::Text(_) | Cell::Other(_) => (ints, numbers, bools) = (false, false, false),
            }
        }
        if ints {
            return Column::Int(
                (0..n)
                    .map(|r| if let Cell::Int(i) = cell(r) { *i } else { 0 })
                    .collect(),
            );
        }
        if numbers {
            return Column::Float(floats);
        }
        if bools {
            return Column::Bool((0..n).map(|r| matches!(cell(r), Cell::Bool(true))).collect());
        }
        Column::Object((0..n).map(|r| cell(r).clone()).collect())
    }

    fn into_numpy<'py>(self, py: Python<'py>) -> PyResult<Bound<'py, PyAny>> {
        Ok(match self {
            Column::Int(v) => PyArray1::from_vec(py, v).into_any(),
            Column::Float(v) => PyArray1::from_vec(py, v).into_any(),
            Column::Bool(v) => PyArray1::from_vec(py, v).into_any(),
            Column::Object(cells) => {
                let objects = cells
                    .into_iter()
                    .map(|c| {
                        Ok(match c {
                            Cell::Missing | Cell::Null => py.None(),
                            Cell::Bool(b) => b.into_pyobject(py)?.to_owned().into_any().unbind(),
                            Cell::Int(i) => i.into_pyobject(py)?.into_any().unbind(),
                            Cell::Float(x) => x.into_pyobject(py)?.into_any().unbind(),
                            Cell::Text(s) => s.into_pyobject(py)?.into_any().unbind(),
                            Cell::Other(v) => crate::errors::pythonize(py, &v)?,
                        })
                    })
                    .collect::<PyResult<Vec<Py<PyAny>>>>()?;
                PyArray1::from_vec(py, objects).into_any()
            }
        })
    }
}

/// The cell of a row that has no such leaf.
static MISSING: Cell = Cell::Missing;

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
    // The lines read and the cells gathered into columns without the GIL; Python objects after.
    let (names, typed) = py.detach(|| {
        let flats: Vec<Flat> = rows.par_iter().filter_map(|r| leaves::flat(&r.text)).collect();
        let n = flats.len();
        // Columns in order of first appearance, assigned once per distinct sequence of names
        // (a row of the previous row's shape needs no look-up).
        let mut result_names: Vec<String> = Vec::new();
        let mut column_of: HashMap<String, usize> = HashMap::new();
        let mut shape_of: HashMap<&str, usize> = HashMap::new();
        let mut shapes: Vec<Vec<usize>> = Vec::new();
        let mut shape_ids: Vec<usize> = Vec::with_capacity(n);
        let mut last: Option<(&str, usize)> = None;
        for f in &flats {
            let names = f.names.as_str();
            let id = match last {
                Some((prev, id)) if prev == names => id,
                _ => *shape_of.entry(names).or_insert_with(|| {
                    let cols = names
                        .lines()
                        .map(|name| {
                            *column_of.entry(name.to_string()).or_insert_with(|| {
                                result_names.push(name.to_string());
                                result_names.len() - 1
                            })
                        })
                        .collect();
                    shapes.push(cols);
                    shapes.len() - 1
                }),
            };
            last = Some((names, id));
            shape_ids.push(id);
        }
        // Where each column's cell is in a row of each shape.
        let position: Vec<Vec<Option<usize>>> = shapes
            .iter()
            .map(|cols| {
                let mut at = vec![None; result_names.len()];
                cols.iter().enumerate().for_each(|(k, &c)| at[c] = Some(k));
                at
            })
            .collect();
        let param = |f: &Flat, a: &str| Cell::of(f.params.as_ref().and_then(|p| p.get(a)));
        let mut top: Vec<Vec<Cell>> = vec![flats.iter().map(|f| Cell::of(f.index.as_ref())).collect()];
        top.extend(
            axes.iter()
                .map(|a| flats.iter().map(|f| param(f, a)).collect::<Vec<_>>()),
        );
        top.push(flats.iter().map(|f| Cell::of(f.error.as_ref())).collect());
        let error = top.pop().unwrap_or_default();
        // Each column gathered and typed on its own (in parallel): no table of cells.
        let result = (0..result_names.len()).into_par_iter().map(|c| {
            Column::of(n, |r| {
                position[shape_ids[r]][c].map_or(&MISSING, |k| &flats[r].cells[k])
            })
        });
        let of = |cells: &Vec<Cell>| Column::of(cells.len(), |r| &cells[r]);
        let mut typed: Vec<Column> = top.iter().map(of).collect();
        typed.extend(result.collect::<Vec<_>>());
        typed.push(of(&error));
        (result_names, typed)
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
        .map(|c| c.into_numpy(py))
        .collect::<PyResult<Vec<_>>>()?;
    Ok((plain, with_units, PyList::new(py, arrays)?))
}
