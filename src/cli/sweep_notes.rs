//! The model-notes sidecar of `flexfem sweep --out FILE.jsonl`: `FILE.jsonl.notes.json`, a
//! JSON object from each `model_notes` reference in the lines to the notes.
//!
//! The object is written one entry per line, so a new entry is added in place (the closing
//! brace overwritten, then written again after the entry) instead of rewriting the whole file:
//! a sweep whose designs each have notes of their own (a hinge's notes quote its calibration
//! factors) stays linear in time. An entry is written before the first line that refers to it,
//! so a run killed in the middle of an entry leaves a torn last entry that no line refers to;
//! the next run keeps the complete entries and writes the file afresh.

use super::targets::{io_context, Stop};
use serde_json::{Map, Value};
use std::collections::HashSet;
use std::fs::{self, File, OpenOptions};
use std::io;
#[cfg(not(unix))]
use std::io::{Seek, SeekFrom, Write};
use std::path::{Path, PathBuf};

/// The sidecar of `--out FILE.jsonl`: `FILE.jsonl.notes.json`.
pub fn notes_path(out: &Path) -> PathBuf {
    crate::output::with_suffix(out, ".notes.json")
}

/// The sidecar during a run.
pub(super) struct NotesFile {
    path: PathBuf,
    /// References already in the file.
    known: HashSet<String>,
    /// The file, open for writing once this run has written it; `end` is where its closing
    /// `\n}\n` starts.
    open: Option<(File, u64)>,
}

/// One entry's text: `"ref":[…]`, from the notes' compact JSON.
fn entry(r: &str, json: &[u8]) -> io::Result<Vec<u8>> {
    let mut out = serde_json::to_vec(r).map_err(io::Error::other)?;
    out.push(b':');
    out.extend_from_slice(json);
    Ok(out)
}

/// The compact JSON of `notes`.
fn json_of(notes: &Value) -> io::Result<Vec<u8>> {
    serde_json::to_vec(notes).map_err(io::Error::other)
}

/// The entries of a sidecar whose text does not parse as a whole (a torn last entry): each
/// complete entry line, or `None` when the text is not laid out as a sidecar.
fn recover(text: &str) -> Option<Map<String, Value>> {
    let mut lines = text.lines().map(str::trim).filter(|l| !l.is_empty());
    if lines.next() != Some("{") {
        return None;
    }
    let mut m = Map::new();
    for line in lines {
        let line = line.strip_suffix(',').unwrap_or(line);
        if line == "}" {
            break;
        }
        if let Ok(Value::Object(e)) = serde_json::from_str::<Value>(&format!("{{{line}}}")) {
            m.extend(e.into_iter().filter(|(_, v)| v.is_array()));
        }
    }
    Some(m)
}

/// Writes `text` at `offset` (one positioned write on Unix, seek and write elsewhere).
fn write_at(file: &mut File, text: &[u8], offset: u64) -> io::Result<()> {
    #[cfg(unix)]
    {
        std::os::unix::fs::FileExt::write_all_at(file, text, offset)
    }
    #[cfg(not(unix))]
    {
        file.seek(SeekFrom::Start(offset))?;
        file.write_all(text)
    }
}

impl NotesFile {
    /// The sidecar `path`: the notes already in it are kept (a torn last entry dropped); a file
    /// that is not a notes object is refused unless `force` (then replaced).
    pub(super) fn open(path: PathBuf, force: bool) -> Result<Self, Stop> {
        let notes = match fs::read(&path) {
            Ok(bytes) => {
                let text = String::from_utf8_lossy(&bytes);
                match serde_json::from_str::<Value>(&text) {
                    Ok(Value::Object(m)) if m.values().all(Value::is_array) => Some(m),
                    Ok(_) => None,
                    Err(_) => recover(&text),
                }
                .or_else(|| force.then(Map::new))
                .ok_or_else(|| {
                    Stop::Usage(format!(
                        "{} exists and is not a flexfem notes file; remove it or give --force",
                        path.display()
                    ))
                })?
            }
            Err(e) if e.kind() == io::ErrorKind::NotFound => Map::new(),
            Err(e) => return Err(Stop::Io(io_context("read", &path)(e))),
        };
        let mut f = NotesFile {
            path,
            known: HashSet::new(),
            open: None,
        };
        if !notes.is_empty() {
            f.rewrite(&notes).map_err(Stop::Io)?;
        }
        Ok(f)
    }

    /// Writes the whole file (atomically) with `notes`, then keeps it open for adding.
    fn rewrite(&mut self, notes: &Map<String, Value>) -> io::Result<()> {
        let mut text = vec![b'{'];
        for (k, (r, n)) in notes.iter().enumerate() {
            text.extend_from_slice(if k == 0 { b"\n" } else { b",\n" });
            text.extend_from_slice(&entry(r, &json_of(n)?)?);
        }
        text.extend_from_slice(b"\n}\n");
        crate::output::write_atomic(&self.path, &text).map_err(io_context("write", &self.path))?;
        let file = OpenOptions::new()
            .write(true)
            .open(&self.path)
            .map_err(io_context("open", &self.path))?;
        self.known = notes.keys().cloned().collect();
        self.open = Some((file, text.len() as u64 - 3));
        Ok(())
    }

    /// Adds the notes of reference `r`, given as compact JSON, unless the file has them already
    /// (then nothing is allocated).
    pub(super) fn add(&mut self, r: &str, json: &str) -> io::Result<()> {
        if self.known.contains(r) {
            return Ok(());
        }
        let Some((file, end)) = self.open.as_mut() else {
            let mut m = Map::new();
            m.insert(r.to_string(), serde_json::from_str(json).map_err(io::Error::other)?);
            return self.rewrite(&m);
        };
        let mut text = b",\n".to_vec();
        text.extend_from_slice(&entry(r, json.as_bytes())?);
        text.extend_from_slice(b"\n}\n");
        write_at(file, &text, *end).map_err(io_context("write", &self.path))?;
        *end += text.len() as u64 - 3;
        self.known.insert(r.to_string());
        Ok(())
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A torn last entry is dropped, the complete ones kept; text of another layout is refused.
    #[test]
    fn recover_keeps_complete_entries() {
        let torn = "{\n\"a\":[\"x\"],\n\"b\":[\"y\"],\n\"c\":[\"z";
        let m = recover(torn).unwrap();
        assert_eq!(m.len(), 2);
        assert_eq!(m["b"], serde_json::json!(["y"]));
        assert!(recover("[1, 2]").is_none());
    }
}
