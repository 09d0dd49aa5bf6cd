//! A sweep line's table cells read straight from its text: one serde visitor walks the line once
//! and keeps its result's scalar leaves as typed cells (numbers as `f64`/`i64`, no JSON value,
//! no map per object), with their dotted names. The leaves are those of the library's CSV table
//! (`flexfem::design::table::visit_leaves`: scalars; arrays of at most 16 elements by position;
//! longer arrays and arrays holding text left out); `test_sweep_columns_equal_the_cli_csv_cells`
//! and the bundled sweeps' test check the columns against `flexfem sweep --csv`.

use flexfem::design::table::MAX_ARRAY;
use serde::de::{DeserializeSeed, Deserializer, IgnoredAny, MapAccess, SeqAccess, Visitor};
use serde_json::Value;
use std::borrow::Cow;
use std::fmt;

/// One cell of the table.
#[derive(Debug, Clone, Default)]
pub enum Cell {
    /// The row has no such leaf (another shape, or an error row).
    #[default]
    Missing,
    Null,
    Bool(bool),
    Int(i64),
    Float(f64),
    Text(Box<str>),
    /// Anything else (a varied value that is a list).
    Other(Box<Value>),
}

impl Cell {
    /// A top-level value (`index`, a varied value, `error`) as a cell.
    pub fn of(v: Option<&Value>) -> Cell {
        match v {
            None => Cell::Missing,
            Some(Value::Null) => Cell::Null,
            Some(Value::Bool(b)) => Cell::Bool(*b),
            Some(Value::Number(n)) => match (n.as_i64(), n.as_f64()) {
                (Some(i), _) => Cell::Int(i),
                (None, Some(x)) => Cell::Float(x),
                (None, None) => Cell::Other(Box::new(v.cloned().unwrap_or_default())),
            },
            Some(Value::String(s)) => Cell::Text(s.as_str().into()),
            Some(other) => Cell::Other(Box::new(other.clone())),
        }
    }
}

/// One line: `index`, `params` and `error` as values, the result's leaves as cells.
#[derive(Default)]
pub struct Flat {
    pub index: Option<Value>,
    pub params: Option<Value>,
    pub error: Option<Value>,
    /// The leaves' dotted names, each followed by `\n`.
    pub names: String,
    pub cells: Vec<Cell>,
}

/// The cells of a line (`None` for a line that is not a JSON object).
pub fn flat(line: &str) -> Option<Flat> {
    let mut d = serde_json::Deserializer::from_str(line);
    let flat = d.deserialize_map(Line).ok()?;
    d.end().ok().map(|()| flat)
}

/// The result's leaves below dotted name `name`.
struct Leaves<'a> {
    flat: &'a mut Flat,
    name: &'a mut String,
    /// Set when the value is a string (an array element: the array then gives no leaves).
    string: Option<&'a mut bool>,
}

impl Leaves<'_> {
    fn leaf(self, cell: Cell) {
        self.flat.names.push_str(self.name);
        self.flat.names.push('\n');
        self.flat.cells.push(cell);
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

/// A key appended to the dotted name as it is read.
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
        self.leaf(Cell::Bool(v));
        Ok(())
    }
    fn visit_u64<E: serde::de::Error>(self, v: u64) -> Result<(), E> {
        self.leaf(i64::try_from(v).map_or(Cell::Float(v as f64), Cell::Int));
        Ok(())
    }
    fn visit_i64<E: serde::de::Error>(self, v: i64) -> Result<(), E> {
        self.leaf(Cell::Int(v));
        Ok(())
    }
    fn visit_f64<E: serde::de::Error>(self, v: f64) -> Result<(), E> {
        self.leaf(Cell::Float(v));
        Ok(())
    }
    fn visit_str<E: serde::de::Error>(mut self, v: &str) -> Result<(), E> {
        if let Some(s) = self.string.take() {
            *s = true;
        }
        self.leaf(Cell::Text(v.into()));
        Ok(())
    }
    fn visit_unit<E: serde::de::Error>(self) -> Result<(), E> {
        self.leaf(Cell::Null);
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
        let mark = (self.flat.names.len(), self.flat.cells.len());
        let mut keep = true;
        let mut i = 0usize;
        loop {
            let len = self.name.len();
            if len > 0 {
                self.name.push('.');
            }
            self.name.push_str(itoa(i, &mut [0; 20]));
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
            keep &= !string;
            i += 1;
            if i > MAX_ARRAY {
                keep = false;
            }
        }
        if !keep {
            self.flat.names.truncate(mark.0);
            self.flat.cells.truncate(mark.1);
        }
        Ok(())
    }
}

/// The decimal digits of `i`, written into `buf`.
fn itoa(mut i: usize, buf: &mut [u8; 20]) -> &str {
    let mut at = buf.len();
    loop {
        at -= 1;
        buf[at] = b'0' + (i % 10) as u8;
        i /= 10;
        if i == 0 {
            break;
        }
    }
    std::str::from_utf8(&buf[at..]).unwrap_or("")
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
                    (flat.names, flat.cells) = Default::default();
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
