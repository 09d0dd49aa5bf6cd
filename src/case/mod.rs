//! Case files: serde shapes only, plus validation that names JSON paths.
//!
//! A case file is read by [`crate::analysis::parse`] (the list of kinds lives with the
//! analyses); the shapes here are deserialised through [`from_value`], so that every error
//! carries its JSON path, with unknown fields refused.

pub mod design;
pub mod error;
pub mod fatigue;
pub mod fem_case;
pub(crate) mod fields;
pub mod gmsh;
pub mod hinge;
pub mod kinematics;
pub mod limits;
pub mod material;
pub mod mesh;
pub mod numbers;
pub mod pantilt;
pub mod prs_stiffness;
pub mod stage;
pub mod sweep;

pub use error::CaseError;
pub use material::MaterialSpec;

use serde::de::DeserializeOwned;
use serde_json::Value;
use std::path::{Path, PathBuf};

/// Deserialises `value` into `T`, turning serde errors into [`CaseError`]s under `prefix`.
pub fn from_value<T: DeserializeOwned>(value: Value, prefix: &str) -> Result<T, CaseError> {
    serde_path_to_error::deserialize(value).map_err(|e| {
        let path = e.path().to_string();
        CaseError::new(
            if path == "." { String::new() } else { path },
            e.into_inner().to_string(),
        )
        .under(prefix)
    })
}

/// Refuses a model (a JSON object with `nodes`) with more nodes than [`limits::Limits::nodes`],
/// before the nodes are built.
fn check_node_count(field: &str, model: &Value) -> Result<(), CaseError> {
    match model.get("nodes").and_then(Value::as_array) {
        Some(a) => limits::check_nodes(field, a.len()),
        None => Ok(()),
    }
}

/// Resolves a file named in a case: relative to `base` if it exists there, else as given.
pub fn resolve_file(name: &str, base: Option<&Path>) -> PathBuf {
    let p = Path::new(name);
    match base {
        Some(b) if p.is_relative() && b.join(p).exists() => b.join(p),
        _ => p.to_path_buf(),
    }
}

fn read_json(path_field: &str, name: &str, base: Option<&Path>) -> Result<Value, CaseError> {
    let file = resolve_file(name, base);
    let bytes = limits::read_file(path_field, "mesh file", &format!("\"{name}\""), &file)?;
    serde_json::from_slice(&bytes).map_err(|e| {
        CaseError::value(
            path_field,
            format!("\"{name}\""),
            format!("{} is not valid JSON: {e}", file.display()),
        )
    })
}

/// A value shortened for messages.
pub fn short(v: &Value) -> String {
    let s = v.to_string();
    if s.chars().count() > 60 {
        format!("{}…", s.chars().take(60).collect::<String>())
    } else {
        s
    }
}
