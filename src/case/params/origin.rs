//! Where a resolved value came from. Validation runs on the resolved case, so an error may name
//! a place the case file does not have as written: inside the mesh file, or inside a hinge
//! given by type name. [`Origins::locate`] moves such an error to where the value is set (the
//! parameter's declaration, the hinge type, or `mesh`), keeping the place it was found and the
//! expression in the message.

use crate::case::CaseError;

/// One expression site or hinge-type use outside the case as written.
#[derive(Debug, Clone)]
struct Origin {
    /// JSON path of the resolved value (in the case or its mesh file).
    at: String,
    /// What was written there: the expression, or the hinge type's name.
    written: String,
    /// Where the error is reported instead.
    target: String,
    /// The mesh file it is in (`None`: the case).
    file: Option<String>,
    /// True for a hinge-type use (errors anywhere inside it are its).
    hinge: bool,
}

/// The origins of a resolved case's values (see the module docs).
#[derive(Debug, Clone, Default)]
pub struct Origins {
    all: Vec<Origin>,
    /// The JSON mesh file the case names and which top-level keys each side writes: an error at
    /// a path the mesh file's model has and the case as written has not is reported at `mesh`,
    /// naming the file (a path such as `elements[3].nodes` is not in the case as written).
    mesh: Option<MeshKeys>,
}

/// What the case and its JSON mesh file each write ([`Origins::set_mesh`]).
#[derive(Debug, Clone)]
struct MeshKeys {
    /// The mesh file's name as the case writes it.
    name: String,
    /// Top-level keys of the case as written (with its `parameters` and `hinge_types`).
    case: Vec<String>,
    /// Top-level keys of the mesh file's model.
    mesh: Vec<String>,
    /// `materials.NAME` and `sections.NAME` the mesh file defines and the case does not (the
    /// model takes both sides' entries, the case's where both define a name), and the keys
    /// whose list the case writes empty (the model then takes the mesh file's).
    mesh_only: Vec<String>,
}

impl Origins {
    /// A value at `at` written as `written`, reported at `target`.
    pub(super) fn add(&mut self, at: String, written: &str, target: String, file: Option<&str>, hinge: bool) {
        self.all.push(Origin {
            at,
            written: written.to_string(),
            target,
            file: file.map(str::to_string),
            hinge,
        });
    }

    /// The hinge type each hinge element's `hinge` names, by element index (the uses at
    /// `elements[i].hinge`, in the case's inline model or in its mesh file).
    pub fn element_hinge_types(&self) -> std::collections::BTreeMap<usize, String> {
        self.all
            .iter()
            .filter(|o| o.hinge)
            .filter_map(|o| {
                let i = o.at.strip_prefix("elements[")?.strip_suffix("].hinge")?;
                Some((i.parse().ok()?, o.written.clone()))
            })
            .collect()
    }

    /// Errors in the model of the JSON mesh file `name`, whose content is `mesh` (the case as
    /// written is `case`, `taken` the keys taken out of it before: `parameters`, `hinge_types`),
    /// are reported at `mesh` ([`Self::locate`]).
    pub(super) fn set_mesh(&mut self, name: &str, case: &serde_json::Value, taken: &[&str], mesh: &serde_json::Value) {
        use serde_json::Value;
        let keys = |v: &Value| -> Vec<String> { v.as_object().into_iter().flat_map(|m| m.keys().cloned()).collect() };
        let mut mesh_only = Vec::new();
        for field in ["materials", "sections"] {
            let (in_case, in_mesh) = (keys(&case[field]), keys(&mesh[field]));
            mesh_only.extend(
                in_mesh
                    .into_iter()
                    .filter(|n| !in_case.contains(n))
                    .map(|n| format!("{field}.{n}")),
            );
        }
        // An empty list in the case (`"load_cases": []`, `"elements": []`) leaves the mesh
        // file's in the model.
        let empty = case.as_object().into_iter().flatten();
        mesh_only.extend(
            empty
                .filter(|(_, v)| v.as_array().is_some_and(Vec::is_empty))
                .map(|(k, _)| k.clone()),
        );
        let mut case_keys = keys(case);
        case_keys.extend(taken.iter().map(|k| k.to_string()));
        self.mesh = Some(MeshKeys {
            name: name.to_string(),
            case: case_keys,
            // The model reader ignores a mesh file's `analysis`.
            mesh: keys(mesh).into_iter().filter(|k| k != "analysis").collect(),
            mesh_only,
        });
    }

    /// `e` moved to where the value at its path is set, if that path is one recorded (an
    /// expression site first, else inside a hinge-type use), or to `mesh` if it lies in the
    /// model of the JSON mesh file (e.g. an element made too short by node coordinates
    /// written as expressions); otherwise `e` unchanged.
    pub fn locate(&self, e: CaseError) -> CaseError {
        let inside = |o: &Origin| {
            e.path == o.at
                || (o.hinge
                    && e.path
                        .strip_prefix(o.at.as_str())
                        .is_some_and(|r| r.starts_with(['.', '['])))
        };
        let Some(o) = self
            .all
            .iter()
            .find(|o| !o.hinge && e.path == o.at)
            .or_else(|| self.all.iter().find(|o| inside(o)))
        else {
            return self.in_mesh(e);
        };
        let file = o
            .file
            .as_ref()
            .map(|f| format!(" of mesh file \"{f}\""))
            .unwrap_or_default();
        let what = if o.hinge { "hinge type" } else { "expression" };
        CaseError::new(
            o.target.clone(),
            format!("at `{}`{file} ({what} \"{}\"): {}", e.path, o.written, e.message),
        )
    }

    /// `e` at `mesh` when its path is in the model of the JSON mesh file: its first key is one
    /// the mesh file writes and the case as written does not, or an entry of `materials` or
    /// `sections` only the mesh file defines (or a list the case writes empty);
    /// otherwise `e` unchanged (an error at a key neither writes, a missing `modes` say, stays
    /// the case's).
    fn in_mesh(&self, e: CaseError) -> CaseError {
        let Some(m) = &self.mesh else {
            return e;
        };
        let first = e.path.split(['.', '[']).next().unwrap_or_default();
        let has = |keys: &[String], k: &str| keys.iter().any(|x| x == k);
        if first.is_empty() || !has(&m.mesh, first) {
            return e;
        }
        // An entry's path is the entry or under it (names may hold dots: `materials.PA6.6.E`).
        let under = |entry: &String| {
            e.path
                .strip_prefix(entry.as_str())
                .is_some_and(|r| r.is_empty() || r.starts_with(['.', '[']))
        };
        if has(&m.case, first) && !m.mesh_only.iter().any(under) {
            return e;
        }
        super::in_mesh_file(&m.name, e)
    }
}
