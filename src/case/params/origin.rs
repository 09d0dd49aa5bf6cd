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
    /// The JSON mesh file the case names and the top-level keys of the case as written: an
    /// error at a path under another key is in the mesh file's model and is reported at `mesh`,
    /// naming the file (a path such as `elements[3].nodes` is not in the case as written).
    mesh: Option<(String, Vec<String>)>,
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

    /// Errors under the model of the JSON mesh file `name` (the case as written has
    /// the top-level keys `case_keys`) are reported at `mesh` ([`Self::locate`]).
    pub(super) fn set_mesh(&mut self, name: &str, case_keys: Vec<String>) {
        self.mesh = Some((name.to_string(), case_keys));
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

    /// `e` at `mesh` when its path is in the model of the JSON mesh file (its first
    /// key is not one of the case as written); otherwise `e` unchanged.
    fn in_mesh(&self, e: CaseError) -> CaseError {
        let Some((name, case_keys)) = &self.mesh else {
            return e;
        };
        let first = e.path.split(['.', '[']).next().unwrap_or_default();
        if first.is_empty() || case_keys.iter().any(|k| k == first) {
            return e;
        }
        CaseError::new(
            "mesh",
            format!("in mesh file \"{name}\" at `{}`: {}", e.path, e.message),
        )
    }
}
