//! Case files: serde shapes only, plus validation that names JSON paths.
//!
//! A case file is read by [`crate::analysis::parse`] (the list of kinds lives with the
//! analyses); the shapes here are deserialised through [`from_value`], so that every error
//! carries its JSON path, with unknown fields refused.

pub mod design;
pub mod design_mesh;
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
pub mod params;
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

/// Where a case is read from: the folder its file references resolve against, and the JSON
/// mesh file it names when that was read already (with its parameters resolved, see
/// [`params::resolve_case`]), so the model reader does not read it again.
#[derive(Debug, Default)]
pub struct Source<'a> {
    /// The case file's folder (`None`: the working folder).
    pub dir: Option<&'a Path>,
    mesh: std::cell::RefCell<Option<(String, Value)>>,
    /// The `hinge_types` name each hinge element's `hinge` was given by (element index →
    /// name), for the warnings about them ([`mesh::MeshSpec::hinge_type_names`]).
    hinge_types: std::collections::BTreeMap<usize, String>,
}

impl<'a> Source<'a> {
    /// A case read from a file in `dir`.
    pub fn new(dir: Option<&'a Path>) -> Self {
        Source {
            dir,
            mesh: Default::default(),
            hinge_types: Default::default(),
        }
    }

    /// [`Self::new`] with the mesh file `name` already read and resolved as `content`.
    pub fn with_mesh(dir: Option<&'a Path>, mesh: Option<(String, Value)>) -> Self {
        Source {
            dir,
            mesh: std::cell::RefCell::new(mesh),
            hinge_types: Default::default(),
        }
    }

    /// `self` with the hinge types the hinge elements were given by (element index → name).
    pub fn with_hinge_types(self, hinge_types: std::collections::BTreeMap<usize, String>) -> Self {
        Source { hinge_types, ..self }
    }

    /// The hinge types the hinge elements were given by ([`Self::with_hinge_types`]).
    pub(crate) fn hinge_types(&self) -> &std::collections::BTreeMap<usize, String> {
        &self.hinge_types
    }

    /// The content of mesh file `name` if it was read already (taken: a case reads its mesh
    /// once).
    fn take_mesh(&self, name: &str) -> Option<Value> {
        let mut slot = self.mesh.borrow_mut();
        match slot.take() {
            Some((n, v)) if n == name => Some(v),
            other => {
                *slot = other;
                None
            }
        }
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

pub(crate) fn read_json(path_field: &str, name: &str, base: Option<&Path>) -> Result<Value, CaseError> {
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
