//! CSV view of sweep lines: `index`, each varied path, every scalar leaf of the result under
//! its dotted name, then `error`.
//!
//! With the units of the sweep's analysis kind ([`crate::analysis::units`]) a column whose path
//! has a unit is headed `name [unit]` (`stiffness_z [N/mm]`, `hinge.t [mm]`, `T [-]`); text,
//! flag and `index`/`error` columns keep their bare names.
//!
//! Numbers, booleans, strings and nulls are leaves. Arrays of at most [`MAX_ARRAY`] elements
//! are flattened by position (`compliance.2.4`, `load_cases.0.name`); longer arrays
//! (per-node displacements, mode shapes) and arrays of strings (notes) are left out.

pub use super::table_cells::MAX_ARRAY;
use super::table_cells::{header, push_cell};
use crate::analysis::units::UnitOf;
use rayon::prelude::*;
use serde_json::Value;
use std::collections::HashMap;
use std::fmt::Write as _;

/// Calls `f(dotted name, leaf)` for every scalar leaf of `v`, `name` holding the prefix (it is
/// used as the working buffer and restored on return).
pub fn visit_leaves<'v>(name: &mut String, v: &'v Value, f: &mut impl FnMut(&str, &'v Value)) {
    let enter = |name: &mut String, key: &dyn std::fmt::Display| {
        let len = name.len();
        if len > 0 {
            name.push('.');
        }
        let _ = write!(name, "{key}");
        len
    };
    match v {
        Value::Object(m) => {
            for (k, x) in m {
                let len = enter(name, k);
                visit_leaves(name, x, f);
                name.truncate(len);
            }
        }
        Value::Array(a) => {
            if a.len() > MAX_ARRAY || a.iter().any(Value::is_string) {
                return;
            }
            for (i, x) in a.iter().enumerate() {
                let len = enter(name, &i);
                visit_leaves(name, x, f);
                name.truncate(len);
            }
        }
        scalar => f(name, scalar),
    }
}

/// The scalar leaves of `v` under `prefix` as (dotted name, cell text).
pub fn flatten(prefix: &str, v: &Value, out: &mut Vec<(String, String)>) {
    let mut name = prefix.to_string();
    visit_leaves(&mut name, v, &mut |n, x| {
        let mut text = String::new();
        push_cell(&mut text, Some(x));
        out.push((n.to_string(), text));
    });
}

/// The CSV table of sweep `lines` (already in index order) for a sweep varying `axes`.
/// Result columns are the union of the rows' leaves, in order of first appearance.
/// Lines are parsed and rendered in parallel (rayon); unparseable lines are skipped.
pub fn csv(axes: &[&str], lines: &[&str]) -> String {
    csv_with_units(axes, lines, None)
}

/// [`csv`] with the column units `(result units, case units)` of the sweep's analysis kind
/// ([`crate::analysis::Analysis::column_units`]).
pub fn csv_with_units(axes: &[&str], lines: &[&str], units: Option<(UnitOf, UnitOf)>) -> String {
    super::table_lines::csv_of_lines(axes, lines, units)
}

/// [`csv`] of sweep rows already in memory (the JSON objects of their lines, in index order;
/// non-objects are skipped).
pub fn csv_of_rows(axes: &[&str], rows: &[Value]) -> String {
    csv_of_rows_with_units(axes, rows, None)
}

/// [`csv_of_rows`] with column units (see [`csv_with_units`]).
pub fn csv_of_rows_with_units(axes: &[&str], rows: &[Value], units: Option<(UnitOf, UnitOf)>) -> String {
    let rows: Vec<&Value> = rows.iter().filter(|r| r.is_object()).collect();

    // Columns in order of first appearance; each row's leaves as (column, value).
    let mut columns: Vec<String> = Vec::new();
    let mut column_of: HashMap<String, usize> = HashMap::new();
    let mut name = String::new();
    let leaves: Vec<Vec<(usize, &Value)>> = rows
        .iter()
        .map(|row| {
            let mut cells = Vec::new();
            if let Some(result) = row.get("result") {
                name.clear();
                visit_leaves(&mut name, result, &mut |n, x| {
                    let c = match column_of.get(n) {
                        Some(&c) => c,
                        None => {
                            column_of.insert(n.to_string(), columns.len());
                            columns.push(n.to_string());
                            columns.len() - 1
                        }
                    };
                    cells.push((c, x));
                });
            }
            cells
        })
        .collect();

    let mut out = header(axes, columns.iter().map(String::as_str), units);
    let body: Vec<String> = rows
        .par_iter()
        .zip(&leaves)
        .map(|(row, cells)| {
            let mut by_column: Vec<Option<&Value>> = vec![None; columns.len()];
            for &(c, x) in cells {
                by_column[c] = Some(x);
            }
            let params = row.get("params");
            let mut line = String::with_capacity(24 * (by_column.len() + axes.len() + 2));
            push_cell(&mut line, row.get("index"));
            for a in axes {
                line.push(',');
                push_cell(&mut line, params.and_then(|p| p.get(*a)));
            }
            for x in by_column {
                line.push(',');
                push_cell(&mut line, x);
            }
            line.push(',');
            push_cell(&mut line, row.get("error"));
            line.push('\n');
            line
        })
        .collect();
    out.reserve(body.iter().map(String::len).sum());
    for line in body {
        out.push_str(&line);
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;
    use serde_json::json;

    #[test]
    fn flattens_scalars_small_arrays_and_skips_big_ones_and_strings() {
        let v = json!({"k": 1.5, "ok": true, "c": [[1, 2], [3, 4]], "big": vec![0; 17],
                       "notes": ["a", "b"], "lc": [{"name": "F20", "z": 0.9}], "n": null});
        let mut out = Vec::new();
        flatten("", &v, &mut out);
        let names: Vec<&str> = out.iter().map(|(n, _)| n.as_str()).collect();
        assert_eq!(
            names,
            [
                "k",
                "ok",
                "c.0.0",
                "c.0.1",
                "c.1.0",
                "c.1.1",
                "lc.0.name",
                "lc.0.z",
                "n"
            ]
        );
        assert_eq!(out[0].1, "1.5");
        assert_eq!(out[6].1, "F20");
    }

    #[test]
    fn csv_unions_columns_and_quotes() {
        let lines = [
            r#"{"index":0,"params":{"a":1},"error":"a: bad, very"}"#,
            r#"{"index":1,"params":{"a":2},"result":{"x":3,"y":{"z":4}}}"#,
        ];
        let t = csv(&["a"], &lines);
        assert_eq!(t, "index,a,x,y.z,error\n0,1,,,\"a: bad, very\"\n1,2,3,4,\n");
    }
}
