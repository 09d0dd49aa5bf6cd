//! A result written straight into a sweep line: the typed result serialised once, through a
//! JSON formatter that leaves out the omitted fields and takes the model notes out, into a
//! buffer the worker reuses — no JSON value in between, no allocation.
//!
//! The text equals what the value route of [`crate::design::sweep`] writes for the same result:
//! the result object, then `material` and `warnings` (the echoes every run adds), with the
//! fields of [`LineSpec::omit`] removed and, with [`LineSpec::notes_by_ref`], the `model` entry
//! replaced in place by `"model_notes":"REF"` (REF: the first 8 hex digits of the 128-bit FNV-1a
//! hash of the notes' compact JSON, which go to [`ResultLine::notes`]).

use crate::case::params::Parameters;
use crate::case::MaterialSpec;
use serde::Serialize;
use serde_json::ser::{CharEscape, CompactFormatter, Formatter};
use std::collections::BTreeMap;
use std::io;

/// What the line keeps of a result.
#[derive(Debug, Clone, Copy)]
pub struct LineSpec<'a> {
    /// Result fields left out, as paths of keys (`*` matches any key or array index).
    pub omit: &'a [Vec<String>],
    /// Take the top-level `model` notes out (see the module docs).
    pub notes_by_ref: bool,
    /// Each `load_cases[K].displacements` array (one row per node) written as an object of the
    /// rows `keyed_rows[K]` (node indices, ascending) keyed by node index, as a static sweep line
    /// keeps them; a load case without an entry keeps its array (`None`: every array kept).
    pub keyed_rows: Option<&'a [Vec<usize>]>,
}

/// Where [`crate::analysis::DynAnalysis::write_result`] writes: a worker's line and what it keeps.
#[derive(Debug)]
pub struct LineTarget<'a> {
    /// The worker's buffers.
    pub line: &'a mut ResultLine,
    /// What the line keeps of the result.
    pub spec: LineSpec<'a>,
    /// The parameter values of a parameterised case, echoed after the warnings as
    /// `parameters` (`None` or empty: no echo).
    pub parameters: Option<&'a Parameters>,
}

/// The buffers a worker reuses for its lines.
#[derive(Debug, Default)]
pub struct ResultLine {
    /// The line being written (the result is appended).
    pub out: Vec<u8>,
    /// The model notes taken out of the last result, as compact JSON (empty: none).
    pub notes: Vec<u8>,
    /// Their reference (8 hex digits), when [`Self::notes`] is not empty.
    pub notes_ref: [u8; 8],
    /// The notes held an object (their reference is then not the hash of this text: the
    /// caller takes the value route).
    pub notes_hold_object: bool,
}

/// 128-bit FNV-1a of `bytes` from state `h` (Fowler, Noll & Vo).
pub fn fnv128(mut h: u128, bytes: &[u8]) -> u128 {
    const PRIME: u128 = 0x0000_0000_0100_0000_0000_0000_0000_013b;
    for &b in bytes {
        h ^= u128::from(b);
        h = h.wrapping_mul(PRIME);
    }
    h
}

/// FNV-1a 128 offset basis.
pub const FNV128_OFFSET: u128 = 0x6c62_272e_07bb_0142_62b8_2175_6295_c58d;

/// Most nesting the filter follows (deeper values are written, never matched).
const MAX_DEPTH: usize = 16;

#[derive(Debug, Clone, Copy, Default)]
struct Frame<'a> {
    /// An object (else an array).
    object: bool,
    /// Something of this container is in the output (so the next entry needs a comma).
    emitted: bool,
    /// Object: where the current entry starts (its comma, if any) and its key's text.
    entry: usize,
    key: (usize, usize),
    /// Array: index of the current element.
    index: usize,
    /// An array written as an object of these rows keyed by index ([`LineSpec::keyed_rows`]).
    keyed: Option<&'a [usize]>,
}

/// The formatter: writes to `out` (the serializer's own writer is a sink) and filters.
struct Filter<'a> {
    out: &'a mut Vec<u8>,
    spec: LineSpec<'a>,
    frames: [Frame<'a>; MAX_DEPTH],
    depth: usize,
    /// Inside a left-out value: the containers opened in it.
    skip: Option<usize>,
    /// The left-out value is an element of a keyed array (it ends with the element).
    skip_element: bool,
    /// The next array opened is written keyed, keeping these rows.
    keyed_next: Option<&'a [usize]>,
    /// Capturing the top-level `model` value, from this offset.
    model: Option<usize>,
    notes: &'a mut Vec<u8>,
    notes_ref: &'a mut [u8; 8],
    notes_object: &'a mut bool,
}

impl<'a> Filter<'a> {
    /// The key path of the current entry, from the result's top level, matches an omitted path.
    fn omitted(&self) -> bool {
        if self.depth > MAX_DEPTH {
            return false;
        }
        let path = &self.frames[..self.depth];
        self.spec.omit.iter().any(|p| {
            p.len() == path.len()
                && p.iter().zip(path).all(|(seg, f)| {
                    seg == "*"
                        || if f.object {
                            seg.as_bytes() == &self.out[f.key.0..f.key.1]
                        } else {
                            seg.parse::<usize>() == Ok(f.index)
                        }
                })
        })
    }

    fn top(&mut self) -> Option<&mut Frame<'a>> {
        match self.depth {
            0 => None,
            d if d <= MAX_DEPTH => Some(&mut self.frames[d - 1]),
            _ => None,
        }
    }

    /// Opens an object or array (`bracket`: its opening character).
    fn open(&mut self, object: bool, bracket: u8) -> io::Result<()> {
        if let Some(n) = &mut self.skip {
            *n += 1;
            return Ok(());
        }
        if self.model.is_some() && object {
            *self.notes_object = true;
        }
        let keyed = self.keyed_next.take().filter(|_| !object);
        if self.depth < MAX_DEPTH {
            self.frames[self.depth] = Frame {
                object,
                keyed,
                ..Frame::default()
            };
        }
        self.depth += 1;
        self.out.push(if keyed.is_some() { b'{' } else { bracket });
        Ok(())
    }

    /// Closes the innermost object or array (`bracket`: its closing character).
    fn close(&mut self, bracket: u8) -> io::Result<()> {
        if let Some(n) = &mut self.skip {
            *n -= 1;
            return Ok(());
        }
        let keyed = self.top().is_some_and(|f| f.keyed.is_some());
        self.depth -= 1;
        self.out.push(if keyed { b'}' } else { bracket });
        Ok(())
    }

    /// The entry just keyed is `load_cases[K].displacements`: its rows to keep, when keyed.
    fn keyed_rows(&self) -> Option<&'a [usize]> {
        let rows = self.spec.keyed_rows?;
        let [cases, case, field] = self.frames.get(..self.depth)? else {
            return None;
        };
        let named = |f: &Frame, name: &[u8]| f.object && &self.out[f.key.0..f.key.1] == name;
        let at =
            (named(cases, b"load_cases") && !case.object && named(field, b"displacements")).then_some(case.index)?;
        rows.get(at).map(Vec::as_slice)
    }
}

/// Each writing method of the formatter: nothing while skipping, else the compact form into
/// `out`.
macro_rules! pass {
    ($($name:ident($($arg:ident: $t:ty),*);)*) => {
        $(
            fn $name<W: ?Sized + io::Write>(&mut self, _w: &mut W $(, $arg: $t)*) -> io::Result<()> {
                if self.skip.is_some() {
                    return Ok(());
                }
                CompactFormatter.$name(&mut *self.out $(, $arg)*)
            }
        )*
    };
}

/// The opening and closing methods: [`Filter::open`] and [`Filter::close`] with the bracket.
macro_rules! brackets {
    ($($name:ident => $call:ident($($arg:expr),*),)*) => {
        $(
            fn $name<W: ?Sized + io::Write>(&mut self, _w: &mut W) -> io::Result<()> {
                self.$call($($arg),*)
            }
        )*
    };
}

impl Formatter for Filter<'_> {
    brackets! {
        begin_array => open(false, b'['),
        end_array => close(b']'),
        begin_object => open(true, b'{'),
        end_object => close(b'}'),
    }

    pass! {
        write_null();
        write_bool(v: bool);
        write_i8(v: i8);
        write_i16(v: i16);
        write_i32(v: i32);
        write_i64(v: i64);
        write_i128(v: i128);
        write_u8(v: u8);
        write_u16(v: u16);
        write_u32(v: u32);
        write_u64(v: u64);
        write_u128(v: u128);
        write_f32(v: f32);
        write_f64(v: f64);
        write_number_str(v: &str);
        begin_string();
        end_string();
        write_string_fragment(v: &str);
        write_char_escape(v: CharEscape);
        write_byte_array(v: &[u8]);
        write_raw_fragment(v: &str);
    }

    fn begin_array_value<W: ?Sized + io::Write>(&mut self, _w: &mut W, first: bool) -> io::Result<()> {
        if self.skip.is_some() {
            return Ok(());
        }
        let Some(f) = self.top() else {
            if !first {
                self.out.push(b',');
            }
            return Ok(());
        };
        if !first {
            f.index += 1;
        }
        let Some(keep) = f.keyed else {
            if !first {
                self.out.push(b',');
            }
            return Ok(());
        };
        // A keyed array: the kept rows as `"INDEX":ROW`, the others left out.
        let (index, emitted) = (f.index, f.emitted);
        if keep.binary_search(&index).is_err() {
            self.skip = Some(0);
            self.skip_element = true;
            return Ok(());
        }
        f.emitted = true;
        if emitted {
            self.out.push(b',');
        }
        self.out.push(b'"');
        CompactFormatter.write_u64(&mut *self.out, index as u64)?;
        self.out.extend_from_slice(b"\":");
        Ok(())
    }

    fn end_array_value<W: ?Sized + io::Write>(&mut self, _w: &mut W) -> io::Result<()> {
        if self.skip_element && self.skip == Some(0) {
            self.skip = None;
            self.skip_element = false;
        }
        Ok(())
    }

    fn begin_object_key<W: ?Sized + io::Write>(&mut self, _w: &mut W, _first: bool) -> io::Result<()> {
        if self.skip.is_some() {
            return Ok(());
        }
        let at = self.out.len();
        let emitted = self.top().is_some_and(|f| f.emitted);
        if emitted {
            self.out.push(b',');
        }
        let key_start = self.out.len() + 1;
        if let Some(f) = self.top() {
            f.entry = at;
            f.key = (key_start, key_start);
        }
        Ok(())
    }

    fn end_object_key<W: ?Sized + io::Write>(&mut self, _w: &mut W) -> io::Result<()> {
        if self.skip.is_some() {
            return Ok(());
        }
        let end = self.out.len() - 1;
        let depth = self.depth;
        let Some(f) = self.top() else { return Ok(()) };
        f.key.1 = end;
        let (entry, key) = (f.entry, f.key);
        if self.omitted() {
            self.out.truncate(entry);
            self.skip = Some(0);
        } else if depth == 1 && self.spec.notes_by_ref && &self.out[key.0..key.1] == b"model" {
            self.model = Some(self.out.len() + 1);
        } else if depth == 3 {
            self.keyed_next = self.keyed_rows();
        }
        Ok(())
    }

    fn begin_object_value<W: ?Sized + io::Write>(&mut self, _w: &mut W) -> io::Result<()> {
        if self.skip.is_none() {
            self.out.push(b':');
        }
        Ok(())
    }

    fn end_object_value<W: ?Sized + io::Write>(&mut self, _w: &mut W) -> io::Result<()> {
        match self.skip {
            Some(0) => {
                self.skip = None;
                return Ok(());
            }
            Some(_) => return Ok(()),
            None => {}
        }
        self.keyed_next = None;
        if let (Some(start), 1) = (self.model, self.depth) {
            self.model = None;
            self.notes.clear();
            self.notes.extend_from_slice(&self.out[start..]);
            let h = fnv128(FNV128_OFFSET, self.notes);
            // The reference of the value route (`LineFormat::notes_ref`): the top 32 bits in hex.
            io::Write::write_fmt(&mut &mut self.notes_ref[..], format_args!("{:08x}", (h >> 96) as u32))?;
            let f = self.frames[0];
            self.out.truncate(f.key.0 - 1);
            self.out.extend_from_slice(b"\"model_notes\":\"");
            self.out.extend_from_slice(&self.notes_ref[..]);
            self.out.push(b'"');
        }
        if let Some(f) = self.top() {
            f.emitted = true;
        }
        Ok(())
    }
}

/// The result echoed as every run writes it: the result's fields, then `material` (or a mesh
/// case's `materials`) and `warnings`, and a parameterised case's `parameters`.
#[derive(Serialize)]
pub struct Echoed<'a, R: Serialize> {
    #[serde(flatten)]
    pub result: &'a R,
    #[serde(skip_serializing_if = "Option::is_none")]
    pub material: Option<MaterialEcho<'a>>,
    #[serde(skip_serializing_if = "Option::is_none")]
    pub materials: Option<MaterialsEcho<'a>>,
    pub warnings: &'a [String],
    /// The parameter values (see [`crate::analysis::Outcome::echo_parameters`]).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub parameters: Option<&'a Parameters>,
}

/// A mesh case's materials echoed by key, each as [`MaterialEcho`] (every one must resolve:
/// see [`crate::analysis::run_with`], which leaves out those that do not).
pub struct MaterialsEcho<'a>(pub &'a BTreeMap<String, MaterialSpec>);

impl Serialize for MaterialsEcho<'_> {
    fn serialize<S: serde::Serializer>(&self, s: S) -> Result<S::Ok, S::Error> {
        use serde::ser::{Error, SerializeMap};
        let mut map = s.serialize_map(Some(self.0.len()))?;
        for (key, spec) in self.0 {
            let m = spec.resolve(key).map_err(|e| S::Error::custom(e.message))?;
            map.serialize_entry(key, &MaterialEcho::of(spec, &m))?;
        }
        map.end()
    }
}

/// The material as echoed in a result (see [`crate::analysis::run_with`]).
#[derive(Serialize)]
pub struct MaterialEcho<'a> {
    pub name: &'a str,
    #[serde(rename = "E")]
    pub e: f64,
    pub nu: f64,
    pub density: f64,
    #[serde(rename = "yield")]
    pub yield_strength: Option<f64>,
    pub allowable: Option<f64>,
}

impl<'a> MaterialEcho<'a> {
    /// The echo of material `m` given as `spec` (the same numbers as [`crate::analysis::run_with`]).
    pub fn of(spec: &'a crate::case::MaterialSpec, m: &crate::material::Material) -> Self {
        MaterialEcho {
            name: match spec {
                crate::case::MaterialSpec::Name(n) => n.as_str(),
                crate::case::MaterialSpec::Custom(_) => "custom",
            },
            e: m.e,
            nu: m.nu,
            density: m.density,
            yield_strength: m.yield_strength.is_finite().then_some(m.yield_strength),
            allowable: m.allowable.is_finite().then_some(m.allowable),
        }
    }
}

impl ResultLine {
    /// Appends `value` to [`Self::out`] as `spec` keeps it; the notes it takes out go to
    /// [`Self::notes`].
    pub fn write<T: Serialize + ?Sized>(&mut self, value: &T, spec: LineSpec) -> serde_json::Result<()> {
        self.notes.clear();
        self.notes_hold_object = false;
        let filter = Filter {
            out: &mut self.out,
            spec,
            frames: [Frame::default(); MAX_DEPTH],
            depth: 0,
            skip: None,
            skip_element: false,
            keyed_next: None,
            model: None,
            notes: &mut self.notes,
            notes_ref: &mut self.notes_ref,
            notes_object: &mut self.notes_hold_object,
        };
        let mut ser = serde_json::Serializer::with_formatter(io::sink(), filter);
        value.serialize(&mut ser)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use serde_json::json;

    /// Omitted paths (with `*` over arrays and keys, first and last entries included) and the
    /// notes reference give the same text as removing them from the value.
    #[test]
    fn filter_matches_value_editing() {
        let v = json!({"a": 1, "model": ["x \"q\"", "y"], "b": {"c": [1, 2], "d": 3},
                       "l": [{"f": 1, "g": 2}, {"f": 3, "g": 4}], "z": null});
        let omit: Vec<Vec<String>> = [vec!["a"], vec!["b", "d"], vec!["l", "*", "f"], vec!["z"]]
            .iter()
            .map(|p| p.iter().map(|s| s.to_string()).collect())
            .collect();
        let mut line = ResultLine::default();
        let spec = LineSpec {
            omit: &omit,
            notes_by_ref: true,
            keyed_rows: None,
        };
        line.write(&v, spec).unwrap();
        let notes = br#"["x \"q\"","y"]"#;
        let h = fnv128(FNV128_OFFSET, notes);
        let r = format!("{:08x}", (h >> 96) as u32);
        let want = format!(r#"{{"model_notes":"{r}","b":{{"c":[1,2]}},"l":[{{"g":2}},{{"g":4}}]}}"#);
        assert_eq!(String::from_utf8(line.out).unwrap(), want);
        assert_eq!(&line.notes[..], &notes[..]);
    }
}
