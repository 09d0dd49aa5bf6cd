//! `design_hash`: a 128-bit FNV-1a hash of a design's canonical JSON and of the mesh file it
//! names (see [`super`]).

use crate::analysis::line::{fnv128, FNV128_OFFSET};
use crate::case;
use crate::case::sweep::{set_path, Sweep};
use serde_json::Value;
use std::fs;
use std::io;
use std::path::Path;

/// 128-bit FNV-1a (Fowler, Noll & Vo; IETF draft-eastlake-fnv): not cryptographic, only a
/// change detector for resumed sweeps.
#[derive(Clone, Copy)]
pub(super) struct Fnv128(pub(super) u128);

impl io::Write for Fnv128 {
    fn write(&mut self, bytes: &[u8]) -> io::Result<usize> {
        Fnv128::write(self, bytes);
        Ok(bytes.len())
    }

    fn flush(&mut self) -> io::Result<()> {
        Ok(())
    }
}

impl Fnv128 {
    pub(super) fn new() -> Self {
        Fnv128(FNV128_OFFSET)
    }

    pub(super) fn write(&mut self, bytes: &[u8]) {
        self.0 = fnv128(self.0, bytes);
    }
}

/// Canonical JSON: object keys sorted, no whitespace; numbers and strings as serde_json
/// writes them.
pub(super) fn canonical<W: io::Write>(v: &Value, out: &mut W) {
    match v {
        Value::Object(m) => {
            let mut keys: Vec<&String> = m.keys().collect();
            keys.sort_unstable();
            let _ = out.write_all(b"{");
            for (i, k) in keys.into_iter().enumerate() {
                if i > 0 {
                    let _ = out.write_all(b",");
                }
                // serde_json's string form of the key (escapes as in `Value::String`).
                let _ = serde_json::to_writer(&mut *out, k);
                let _ = out.write_all(b":");
                canonical(&m[k], out);
            }
            let _ = out.write_all(b"}");
        }
        Value::Array(a) => {
            let _ = out.write_all(b"[");
            for (i, x) in a.iter().enumerate() {
                if i > 0 {
                    let _ = out.write_all(b",");
                }
                canonical(x, out);
            }
            let _ = out.write_all(b"]");
        }
        scalar => {
            let _ = serde_json::to_writer(&mut *out, scalar);
        }
    }
}

/// The `design_hash` of a resolved design case (see the module notes), 32 hex digits.
pub fn hash_design(design: &Value, base_dir: Option<&Path>) -> String {
    let mut h = Fnv128::new();
    canonical(design, &mut h);
    if let Some(name) = design.get("mesh").and_then(Value::as_str) {
        h.0 = with_mesh(h.0, fs::read(case::resolve_file(name, base_dir)).ok().as_deref());
    }
    format!("{:032x}", h.0)
}

/// The canonical text of a sweep's base case split at the varied values: the hash of a design
/// continues the state of the text before the first varied value over each value's text and
/// the text after it, without building the design.
#[derive(Debug, Clone, Default)]
pub(super) struct HashTemplate {
    /// The hash state after the text before the first varied value.
    head: u128,
    /// (axis whose value comes next, the canonical text after it), in the text's order.
    parts: Vec<(usize, Vec<u8>)>,
}

impl HashTemplate {
    /// The template of `sweep`'s base case; `None` when a varied path is not found exactly once.
    pub(super) fn new(sweep: &Sweep) -> Option<Self> {
        let mark = |k: usize| format!("\u{1}flexfem-axis-{k}\u{1}");
        let mut base = sweep.base.clone();
        for (k, (path, _)) in sweep.axes.iter().enumerate() {
            set_path(&mut base, path, Value::String(mark(k))).ok()?;
        }
        let mut text = Vec::new();
        canonical(&base, &mut text);
        let marks: Vec<Vec<u8>> = (0..sweep.axes.len())
            .map(|k| serde_json::to_vec(&mark(k)).ok())
            .collect::<Option<_>>()?;
        let mut at: Vec<(usize, usize)> = Vec::new();
        for (k, m) in marks.iter().enumerate() {
            let hits: Vec<usize> = text
                .windows(m.len())
                .enumerate()
                .filter(|(_, w)| w == m)
                .map(|(i, _)| i)
                .collect();
            let [i] = hits[..] else { return None };
            at.push((i, k));
        }
        at.sort_unstable();
        let mut end = at.first().map_or(text.len(), |&(i, _)| i);
        let mut t = HashTemplate {
            head: fnv128(FNV128_OFFSET, &text[..end]),
            parts: Vec::new(),
        };
        for (n, &(i, k)) in at.iter().enumerate() {
            let from = i + marks[k].len();
            end = at.get(n + 1).map_or(text.len(), |&(j, _)| j);
            t.parts.push((k, text[from..end].to_vec()));
        }
        Some(t)
    }

    /// The hash state after the canonical text of the design whose value on axis k is
    /// `texts[k][picks[k]]` (each value's JSON text).
    pub(super) fn state(&self, texts: &[Vec<Vec<u8>>], picks: &[usize]) -> u128 {
        let mut h = self.head;
        for (k, after) in &self.parts {
            h = fnv128(h, &texts[*k][picks[*k]]);
            h = fnv128(h, after);
        }
        h
    }
}

/// [`hash_design`]'s tail for a design naming a mesh file, after its canonical text: the
/// file's bytes (`None`: unreadable).
pub(super) fn with_mesh(mut h: u128, bytes: Option<&[u8]>) -> u128 {
    h = fnv128(h, b"\0mesh\0");
    fnv128(h, bytes.unwrap_or(b"unreadable"))
}

/// The `design_hash` of design `index`, or `None` when the design cannot be built.
pub fn design_hash(sweep: &Sweep, base_dir: Option<&Path>, index: usize) -> Option<String> {
    sweep.design(index).ok().map(|d| hash_design(&d, base_dir))
}

#[cfg(test)]
mod tests {
    use super::*;

    /// FNV-1a 128 test vector (draft-eastlake-fnv, "a"): d228cb696f1a8caf78912b704e4a8964.
    #[test]
    fn fnv128_matches_the_published_vector() {
        let mut h = Fnv128::new();
        h.write(b"a");
        assert_eq!(format!("{:032x}", h.0), "d228cb696f1a8caf78912b704e4a8964");
    }

    /// The hash ignores key order and whitespace (canonical JSON) but sees any value change,
    /// nested or not.
    #[test]
    fn design_hash_is_canonical() {
        let a: Value = serde_json::from_str(r#"{"x": 1, "y": {"p": [1, 2], "q": "s"}}"#).unwrap();
        let b: Value = serde_json::from_str(r#"{"y":{"q":"s","p":[1,2]},"x":1}"#).unwrap();
        let c: Value = serde_json::from_str(r#"{"x": 1, "y": {"p": [1, 3], "q": "s"}}"#).unwrap();
        assert_eq!(hash_design(&a, None), hash_design(&b, None));
        assert_ne!(hash_design(&a, None), hash_design(&c, None));
    }

    /// The hash streams keys and scalars into the hasher; it must equal the hash of the
    /// canonical text built as strings (`Value::to_string` of each key and scalar), which
    /// earlier sweep outputs hold, so their lines stay resumable.
    #[test]
    fn streamed_canonical_equals_the_string_form() {
        fn text(v: &Value, out: &mut String) {
            match v {
                Value::Object(m) => {
                    let mut keys: Vec<&String> = m.keys().collect();
                    keys.sort_unstable();
                    out.push('{');
                    for (i, k) in keys.into_iter().enumerate() {
                        if i > 0 {
                            out.push(',');
                        }
                        out.push_str(&Value::String(k.clone()).to_string());
                        out.push(':');
                        text(&m[k], out);
                    }
                    out.push('}');
                }
                Value::Array(a) => {
                    out.push('[');
                    for (i, x) in a.iter().enumerate() {
                        if i > 0 {
                            out.push(',');
                        }
                        text(x, out);
                    }
                    out.push(']');
                }
                scalar => out.push_str(&scalar.to_string()),
            }
        }
        let v: Value = serde_json::from_str(
            r#"{"z\"q": [1.5e-300, -0.0, 2, "a\u00e9\n"], "b": {"y": null, "x": true}, "é": 0.1}"#,
        )
        .unwrap();
        let mut s = String::new();
        text(&v, &mut s);
        let mut h = Fnv128::new();
        h.write(s.as_bytes());
        assert_eq!(hash_design(&v, None), format!("{:032x}", h.0));
    }
}
