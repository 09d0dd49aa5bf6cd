//! CSV view of sweep lines: `index`, each varied path, every scalar leaf of the result under
//! its dotted name, then `error`.
//!
//! Numbers, booleans, strings and nulls are leaves. Arrays of at most [`MAX_ARRAY`] elements
//! are flattened by position (`compliance.2.4`, `load_cases.0.name`); longer arrays
//! (per-node displacements, mode shapes) and arrays of strings (notes) are left out.

use serde_json::{Map, Value};
use std::collections::HashMap;

/// Longest array flattened into columns.
pub const MAX_ARRAY: usize = 16;

/// Appends the scalar leaves of `v` under `prefix` to `out` as (dotted name, text).
pub fn flatten(prefix: &str, v: &Value, out: &mut Vec<(String, String)>) {
    let key = |k: &str| {
        if prefix.is_empty() {
            k.to_string()
        } else {
            format!("{prefix}.{k}")
        }
    };
    match v {
        Value::Object(m) => {
            for (k, x) in m {
                flatten(&key(k), x, out);
            }
        }
        Value::Array(a) => {
            if a.len() > MAX_ARRAY || a.iter().any(Value::is_string) {
                return;
            }
            for (i, x) in a.iter().enumerate() {
                flatten(&key(&i.to_string()), x, out);
            }
        }
        scalar => out.push((prefix.to_string(), cell(scalar))),
    }
}

/// A parameter or leaf as cell text: strings bare, everything else as JSON.
fn cell(v: &Value) -> String {
    match v {
        Value::String(s) => s.clone(),
        Value::Null => String::new(),
        other => other.to_string(),
    }
}

/// Quotes a CSV field when it needs it (RFC 4180).
fn quote(s: &str) -> String {
    if s.contains([',', '"', '\n', '\r']) {
        format!("\"{}\"", s.replace('"', "\"\""))
    } else {
        s.to_string()
    }
}

/// The CSV table of sweep `lines` (already in index order) for a sweep varying `axes`.
/// Result columns are the union of the rows' leaves, in order of first appearance.
pub fn csv<'a>(axes: &[&str], lines: impl IntoIterator<Item = &'a str>) -> String {
    let mut columns: Vec<String> = Vec::new();
    let mut column_of: HashMap<String, usize> = HashMap::new();
    let mut rows: Vec<(String, Vec<String>, Vec<(usize, String)>, String)> = Vec::new();
    for line in lines {
        let Ok(Value::Object(m)) = serde_json::from_str::<Value>(line) else {
            continue;
        };
        let index = m.get("index").map(cell).unwrap_or_default();
        let empty = Map::new();
        let params = m.get("params").and_then(Value::as_object).unwrap_or(&empty);
        let params: Vec<String> = axes
            .iter()
            .map(|a| params.get(*a).map(cell).unwrap_or_default())
            .collect();
        let mut leaves = Vec::new();
        if let Some(result) = m.get("result") {
            flatten("", result, &mut leaves);
        }
        let cells = leaves
            .into_iter()
            .map(|(name, text)| {
                let next = columns.len();
                let c = *column_of.entry(name.clone()).or_insert(next);
                if c == next {
                    columns.push(name);
                }
                (c, text)
            })
            .collect();
        let error = m.get("error").map(cell).unwrap_or_default();
        rows.push((index, params, cells, error));
    }

    let mut out = String::new();
    let header: Vec<String> = std::iter::once("index")
        .chain(axes.iter().copied())
        .chain(columns.iter().map(String::as_str))
        .chain(std::iter::once("error"))
        .map(quote)
        .collect();
    out += &header.join(",");
    out.push('\n');
    for (index, params, cells, error) in rows {
        let mut result = vec![String::new(); columns.len()];
        for (c, text) in cells {
            result[c] = text;
        }
        let fields: Vec<String> = std::iter::once(index)
            .chain(params)
            .chain(result)
            .chain(std::iter::once(error))
            .map(|s| quote(&s))
            .collect();
        out += &fields.join(",");
        out.push('\n');
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
        let t = csv(&["a"], lines);
        assert_eq!(t, "index,a,x,y.z,error\n0,1,,,\"a: bad, very\"\n1,2,3,4,\n");
    }
}
