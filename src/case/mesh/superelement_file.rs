//! The superelement file a `superelement` element of a mesh case reads (the `result.json` of a
//! `craig_bampton` analysis; see [`super::superelement`]): its shape and its reader.

use crate::case::error::CaseError;
use crate::case::{from_value, limits, resolve_file};
use serde::Deserialize;
use std::path::Path;

/// An interface node of a superelement file.
#[derive(Debug, Clone, Deserialize)]
pub struct FileNode {
    pub node: usize,
    /// Coordinates, mm.
    pub x: [f64; 3],
    /// Node frame (rows: local x, y, z); its boundary DOFs are then local.
    #[serde(default)]
    pub frame: Option<[[f64; 3]; 3]>,
}

/// A boundary coordinate of a superelement file.
#[derive(Debug, Clone, Deserialize)]
pub struct FileDof {
    pub node: usize,
    pub dof: String,
}

/// The fields of a `craig_bampton` result a superelement needs (others are ignored).
#[derive(Debug, Clone, Deserialize)]
pub struct SuperelementFile {
    pub interface_nodes: Vec<FileNode>,
    pub boundary: Vec<FileDof>,
    pub modes: usize,
    pub k: Vec<Vec<f64>>,
    pub m: Vec<Vec<f64>>,
}

/// Reads superelement file `name` (JSON path `at`), resolved against `base`.
pub fn read(at: &str, name: &str, base: Option<&Path>) -> Result<SuperelementFile, CaseError> {
    let file = resolve_file(name, base);
    let shown = format!("\"{name}\"");
    let bytes = limits::read_file(at, "superelement file", &shown, &file)?;
    let wrong = |why: String| {
        CaseError::value(
            at,
            &shown,
            format!(
                "{} is not a superelement file (the result.json of a `craig_bampton` analysis): {why}",
                file.display()
            ),
        )
    };
    let v: serde_json::Value = serde_json::from_slice(&bytes).map_err(|e| wrong(format!("not valid JSON: {e}")))?;
    from_value(v, "").map_err(|e| wrong(format!("at `{}`: {}", e.path, e.message)))
}
