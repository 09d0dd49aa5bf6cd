//! The CSV table of [`super::table`] straight from sweep lines, without a JSON value per line:
//! each line is walked once by a serde visitor (lines in parallel) that keeps its result's leaves
//! as cell text, and columns are assigned once per distinct sequence of leaf names (the designs
//! of a sweep share a handful), so the serial part of the table is one map look-up a line.
//! The text equals [`super::table::csv_of_rows_with_units`] of the parsed lines.

use super::table_cells::{header, push_cell, push_text, MAX_ARRAY};
use crate::analysis::units::UnitOf;
use rayon::prelude::*;
use serde::de::{DeserializeSeed, Deserializer, IgnoredAny, MapAccess, SeqAccess, Visitor};
use serde_json::Value;
use std::borrow::Cow;
use std::collections::HashMap;
use std::fmt::{self, Write as _};

/// One line: its `index`, `params` and `error` as values, its result's leaves as text.
#[derive(Default)]
struct Flat {
    index: Option<Value>,
    params: Option<Value>,
    error: Option<Value>,
    /// The leaves' dotted names, each followed by `\n`.
    names: String,
    /// The leaves' cell texts, one after the other; `ends[k]` ends leaf k's.
    cells: String,
    ends: Vec<usize>,
}

impl Flat {
    fn cell(&self, k: usize) -> &str {
        let start = if k == 0 { 0 } else { self.ends[k - 1] };
        &self.cells[start..self.ends[k]]
    }
}

/// The result's leaves of `flat` below dotted name `name` (see [`super::table::visit_leaves`]).
struct Leaves<'a> {
    flat: &'a mut Flat,
    name: &'a mut String,
    /// Set when the value is a string (an array element: the array then gives no leaves).
    string: Option<&'a mut bool>,
}

impl Leaves<'_> {
    fn leaf(self, text: impl FnOnce(&mut String)) {
        self.flat.names.push_str(self.name);
        self.flat.names.push('\n');
        text(&mut self.flat.cells);
        self.flat.ends.push(self.flat.cells.len());
    }
}

impl<'de> DeserializeSeed<'de> for Leaves<'_> {
    type Value = ();
    fn deserialize<D: Deserializer<'de>>(self, d: D) -> Result<(), D::Error> {
        d.deserialize_any(self)
    }
}

/// Appends `.key` (or `key` at the top) to a dotted name; returns the length to cut back to.
fn enter(name: &mut String, key: &str) -> usize {
    let len = name.len();
    if len > 0 {
        name.push('.');
    }
    name.push_str(key);
    len
}

/// [`enter`] of an array index.
fn enter_index(name: &mut String, i: usize) -> usize {
    let len = name.len();
    if len > 0 {
        name.push('.');
    }
    let _ = write!(name, "{i}");
    len
}

/// A key appended to the dotted name as it is read (no copy of the key).
struct Key<'a>(&'a mut String);

impl<'de> DeserializeSeed<'de> for Key<'_> {
    type Value = usize;
    fn deserialize<D: Deserializer<'de>>(self, d: D) -> Result<usize, D::Error> {
        d.deserialize_str(self)
    }
}

impl Visitor<'_> for Key<'_> {
    type Value = usize;
    fn expecting(&self, f: &mut fmt::Formatter) -> fmt::Result {
        f.write_str("a key")
    }
    fn visit_str<E: serde::de::Error>(self, k: &str) -> Result<usize, E> {
        Ok(enter(self.0, k))
    }
}

impl<'de> Visitor<'de> for Leaves<'_> {
    type Value = ();
    fn expecting(&self, f: &mut fmt::Formatter) -> fmt::Result {
        f.write_str("a JSON value")
    }
    fn visit_bool<E: serde::de::Error>(self, v: bool) -> Result<(), E> {
        self.leaf(|c| push_text(c, if v { "true" } else { "false" }));
        Ok(())
    }
    fn visit_u64<E: serde::de::Error>(self, v: u64) -> Result<(), E> {
        self.leaf(|c| push_cell(c, Some(&Value::from(v))));
        Ok(())
    }
    fn visit_i64<E: serde::de::Error>(self, v: i64) -> Result<(), E> {
        self.leaf(|c| push_cell(c, Some(&Value::from(v))));
        Ok(())
    }
    fn visit_f64<E: serde::de::Error>(self, v: f64) -> Result<(), E> {
        self.leaf(|c| {
            if let Some(n) = serde_json::Number::from_f64(v) {
                let _ = write!(c, "{n}");
            }
        });
        Ok(())
    }
    fn visit_str<E: serde::de::Error>(mut self, v: &str) -> Result<(), E> {
        if let Some(s) = self.string.take() {
            *s = true;
        }
        self.leaf(|c| push_text(c, v));
        Ok(())
    }
    fn visit_unit<E: serde::de::Error>(self) -> Result<(), E> {
        self.leaf(|_| {});
        Ok(())
    }
    fn visit_map<A: MapAccess<'de>>(self, mut m: A) -> Result<(), A::Error> {
        while let Some(len) = m.next_key_seed(Key(self.name))? {
            m.next_value_seed(Leaves {
                flat: self.flat,
                name: self.name,
                string: None,
            })?;
            self.name.truncate(len);
        }
        Ok(())
    }
    /// Arrays of more than [`MAX_ARRAY`] elements, or holding a string, give no leaves.
    fn visit_seq<A: SeqAccess<'de>>(self, mut s: A) -> Result<(), A::Error> {
        let mark = (self.flat.names.len(), self.flat.cells.len(), self.flat.ends.len());
        let mut keep = true;
        let mut i = 0;
        loop {
            let len = enter_index(self.name, i);
            let mut string = false;
            let next = if keep {
                let leaves = Leaves {
                    flat: self.flat,
                    name: self.name,
                    string: Some(&mut string),
                };
                s.next_element_seed(leaves)?
            } else {
                s.next_element::<IgnoredAny>()?.map(|_| ())
            };
            self.name.truncate(len);
            if next.is_none() {
                break;
            }
            // A string element: the array gives no leaves.
            keep &= !string;
            i += 1;
            if i > MAX_ARRAY {
                keep = false;
            }
        }
        if !keep {
            self.flat.names.truncate(mark.0);
            self.flat.cells.truncate(mark.1);
            self.flat.ends.truncate(mark.2);
        }
        Ok(())
    }
}

/// A whole line: an object whose `result` is flattened and whose other cells are kept.
struct Line;

impl<'de> Visitor<'de> for Line {
    type Value = Flat;
    fn expecting(&self, f: &mut fmt::Formatter) -> fmt::Result {
        f.write_str("a sweep line")
    }
    fn visit_map<A: MapAccess<'de>>(self, mut m: A) -> Result<Flat, A::Error> {
        let mut flat = Flat::default();
        while let Some(key) = m.next_key::<Cow<'de, str>>()? {
            match &*key {
                "index" => flat.index = Some(m.next_value()?),
                "params" => flat.params = Some(m.next_value()?),
                "error" => flat.error = Some(m.next_value()?),
                "result" => {
                    // A later `result` replaces an earlier one, as in a parsed object.
                    (flat.names, flat.cells, flat.ends) = Default::default();
                    let mut name = String::new();
                    m.next_value_seed(Leaves {
                        flat: &mut flat,
                        name: &mut name,
                        string: None,
                    })?;
                }
                _ => {
                    m.next_value::<IgnoredAny>()?;
                }
            }
        }
        Ok(flat)
    }
}

/// [`super::table::csv_with_units`] of lines (in index order).
pub fn csv_of_lines(axes: &[&str], lines: &[&str], units: Option<(UnitOf, UnitOf)>) -> String {
    let flats: Vec<Flat> = lines
        .par_iter()
        .filter_map(|l| {
            let mut d = serde_json::Deserializer::from_str(l);
            let flat = d.deserialize_map(Line).ok()?;
            d.end().ok().map(|()| flat)
        })
        .collect();
    // Columns in order of first appearance, assigned once per distinct sequence of names.
    let mut columns: Vec<&str> = Vec::new();
    let mut column_of: HashMap<&str, usize> = HashMap::new();
    let mut shapes: HashMap<&str, Vec<usize>> = HashMap::new();
    for f in &flats {
        if shapes.contains_key(f.names.as_str()) {
            continue;
        }
        let cols = f
            .names
            .lines()
            .map(|n| {
                *column_of.entry(n).or_insert_with(|| {
                    columns.push(n);
                    columns.len() - 1
                })
            })
            .collect();
        shapes.insert(f.names.as_str(), cols);
    }
    let mut out = header(axes, columns.iter().copied(), units);
    let body: Vec<String> = flats
        .par_iter()
        .map(|f| {
            let mut by_column: Vec<Option<&str>> = vec![None; columns.len()];
            for (k, &c) in shapes[f.names.as_str()].iter().enumerate() {
                by_column[c] = Some(f.cell(k));
            }
            let mut line = String::with_capacity(24 * (by_column.len() + axes.len() + 2));
            push_cell(&mut line, f.index.as_ref());
            for a in axes {
                line.push(',');
                push_cell(&mut line, f.params.as_ref().and_then(|p| p.get(*a)));
            }
            for x in by_column {
                line.push(',');
                line.push_str(x.unwrap_or(""));
            }
            line.push(',');
            push_cell(&mut line, f.error.as_ref());
            line.push('\n');
            line
        })
        .collect();
    out.reserve(body.iter().map(String::len).sum());
    body.iter().for_each(|l| out.push_str(l));
    out
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::design::table::csv_of_rows_with_units;

    /// The table from the lines equals the table of the parsed lines: nested objects, small and
    /// long arrays, arrays holding strings (left out, also when the string comes last), nulls,
    /// booleans, integers, floats, quoting, error rows, rows of different shapes (columns in
    /// order of first appearance), a non-object line and an unparseable one (both skipped).
    #[test]
    fn lines_give_the_parsed_rows_table() {
        let lines = [
            r#"{"index":0,"params":{"a":1.5,"b":"x,y"},"design_hash":"h","result":{"k":1.0,"c":[[1,2],[3,4]],"big":[0,0,0,0,0,0,0,0,0,0,0,0,0,0,0,0,0],"notes":["a","b"],"late":[1,2,"s"],"lc":[{"name":"F \"20\"","z":-0.5e-7,"ok":true,"n":null}],"e":[]}}"#,
            r#"{"index":1,"params":{"a":2,"b":"z"},"error":"hinge.t: value 12 is not allowed: must be < h"}"#,
            r#"{"index":2,"params":{"a":[1,2],"b":null},"result":{"extra":{"deep":{"x":1e300}},"k":-3,"c":[[5,6],[7,8]]}}"#,
            r#"[1, 2]"#,
            r#"{"index":3, "result": {"#,
            r#"{"index":4,"params":{"a":3,"b":"w"},"result":{"k":2.25,"c":[[1,2],[3,4]],"notes":["a"],"late":[1,2,"s"],"lc":[{"name":"G","z":1,"ok":false,"n":null}],"e":[]}}"#,
        ];
        let rows: Vec<Value> = lines.iter().filter_map(|l| serde_json::from_str(l).ok()).collect();
        let units: Option<(UnitOf, UnitOf)> =
            Some((|p: &[&str]| (p == ["k"]).then_some("N/mm"), |_: &[&str]| Some("mm")));
        for u in [None, units] {
            let want = csv_of_rows_with_units(&["a", "b"], &rows, u);
            assert_eq!(csv_of_lines(&["a", "b"], &lines, u), want);
        }
        assert_eq!(
            csv_of_lines(&["a"], &lines[..1], None).lines().next().unwrap(),
            "index,a,k,c.0.0,c.0.1,c.1.0,c.1.1,lc.0.name,lc.0.z,lc.0.ok,lc.0.n,error"
        );
    }
}
