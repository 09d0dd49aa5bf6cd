//! How a design's result goes into its sweep line: the fields kept (`--fields`), the fields
//! left out by default, and the model notes taken out into the sidecar.

use super::hash::{canonical, Fnv128};
use crate::case::mesh::MeshSpec;
use serde_json::{Map, Value};

/// How a design's result goes into its line.
#[derive(Debug, Clone, Default, PartialEq)]
pub struct LineFormat {
    /// Result fields kept, as dotted paths (`stiffness_z`, `at_allowable.force`,
    /// `load_cases.0.platform`); `None` keeps every field.
    pub fields: Option<Vec<String>>,
    /// Take the model notes (`result.model`, text that is the same for every design of a
    /// sweep) out of the line: the line's result holds `model_notes`, the notes' 8-digit
    /// FNV hash, and the notes go once into a sidecar file ([`Row::notes`]).
    pub notes_by_ref: bool,
    /// Result fields left out of the line when [`Self::fields`] is `None`, as dotted paths in
    /// which `*` matches any key or array index (see [`omitted_fields`]).
    pub omit: Vec<String>,
    /// When [`Self::fields`] is `None`: each load case's `displacements` keeps only the nodes
    /// its loads and prescribed displacements act on and the nodes the case names in
    /// `compliance` and `metrics` ([`line_nodes`]), as an object keyed by
    /// node index (`load_cases.0.displacements.8`, the path of that row in the full result).
    /// For `static` sweeps by default.
    pub loaded_displacements: bool,
}

/// Per load case, the nodes whose displacements a static sweep line keeps ([`loaded_nodes`]).
pub type LoadedNodes = Vec<Vec<usize>>;

/// The nodes each load case of a static model loads (`forces`, `group_forces` given by node)
/// or prescribes (`displacements`), sorted: the displacements a sweep line keeps by default
/// (with the nodes the case names as outputs: [`line_nodes`]).
pub fn loaded_nodes(model: &MeshSpec) -> LoadedNodes {
    line_nodes(model, &[])
}

/// [`loaded_nodes`] of every load case with the `named` nodes added (the nodes of the case's
/// `compliance` requests and `metrics`), sorted, without repeats.
pub fn line_nodes(model: &MeshSpec, named: &[usize]) -> LoadedNodes {
    model
        .load_cases
        .iter()
        .map(|c| {
            let forces = c.forces.iter().map(|f| f.node);
            let groups = c.group_forces.iter().flat_map(|g| g.nodes.iter().copied());
            let mut nodes: Vec<usize> = forces
                .chain(groups)
                .chain(c.displacements.iter().map(|d| d.node))
                .chain(named.iter().copied())
                .collect();
            nodes.sort_unstable();
            nodes.dedup();
            nodes
        })
        .collect()
}

/// Replaces `load_cases[k].displacements` (one row per node) by the rows of `nodes[k]`, keyed
/// by node index.
fn keep_loaded_displacements(result: &mut Value, nodes: &[Vec<usize>]) {
    let Some(cases) = result.get_mut("load_cases").and_then(Value::as_array_mut) else {
        return;
    };
    for (case, keep) in cases.iter_mut().zip(nodes) {
        let Some(rows) = case.get_mut("displacements") else {
            continue;
        };
        let Value::Array(all) = rows.take() else { continue };
        let kept: Map<String, Value> = keep
            .iter()
            .filter_map(|&n| all.get(n).map(|row| (n.to_string(), row.clone())))
            .collect();
        *rows = Value::Object(kept);
    }
}

/// The result fields a sweep of analysis `kind` leaves out of its lines by default
/// (`flexfem sweep --full` keeps them, `--fields` picks from the full result). A stage line
/// keeps every scalar response; it leaves out the 6×6 platform compliance (its eigenvalues
/// stay), the echoes of the case (material, its allowable stress under `at_allowable`, the
/// actuator forces, the `nonlinear` flag) and the per-hinge stresses (their maximum,
/// `max_von_mises`, stays): ~2,100 → ~940 bytes a line. A static line leaves out the
/// per-element von Mises lists (`max_von_mises`, `max_utilisation` with its element, and each
/// hinge's peak stress and utilisation stay), the hinges' end forces and the echo of the
/// materials, and keeps the displacements of the loaded nodes and of the nodes the case names
/// in `compliance` and `metrics` only ([`LineFormat::loaded_displacements`]); the `compliance`
/// blocks and `metrics` stay. A modal line keeps every mode's frequency, eigenvalue and
/// effective mass fractions and leaves out the mode shapes and the echo of the materials.
pub fn omitted_fields(kind: &str) -> &'static [&'static str] {
    match kind {
        "static" => &[
            "load_cases.*.element_von_mises",
            "load_cases.*.shell_von_mises",
            "load_cases.*.hinges.*.end_forces",
            "materials",
        ],
        "modal" => &["modes.*.shape", "materials"],
        "stage" => &[
            "platform_stiffness.compliance",
            "material",
            "at_allowable.allowable",
            "load_cases.*.forces",
            "load_cases.*.hinge_stress",
            "nonlinear",
        ],
        _ => &[],
    }
}

/// Removes the values at a dotted path whose `*` parts match any key or index.
fn remove_path(v: &mut Value, path: &[&str]) {
    let Some((first, rest)) = path.split_first() else {
        return;
    };
    match v {
        Value::Object(m) if rest.is_empty() => {
            if *first == "*" {
                m.clear();
            } else {
                m.shift_remove(*first);
            }
        }
        Value::Object(m) if *first == "*" => m.values_mut().for_each(|x| remove_path(x, rest)),
        Value::Object(m) => {
            if let Some(x) = m.get_mut(*first) {
                remove_path(x, rest);
            }
        }
        Value::Array(a) if *first == "*" && !rest.is_empty() => a.iter_mut().for_each(|x| remove_path(x, rest)),
        Value::Array(a) if !rest.is_empty() => {
            if let Some(x) = first.parse::<usize>().ok().and_then(|i| a.get_mut(i)) {
                remove_path(x, rest);
            }
        }
        _ => {}
    }
}

impl LineFormat {
    /// [`Self::omit`] split into path segments, as the typed line writers take it.
    pub fn omit_segments(&self) -> Vec<Vec<String>> {
        self.omit
            .iter()
            .map(|p| p.split('.').map(str::to_string).collect())
            .collect()
    }

    /// The lines of `flexfem sweep` for a base case of analysis `kind`: only `fields` when
    /// given (`--fields`), else everything but [`omitted_fields`] of the kind unless `full`
    /// (`--full`), and a static sweep's displacements at its loaded and named nodes only.
    pub fn of_sweep(kind: Option<&str>, fields: Option<Vec<String>>, full: bool, notes_by_ref: bool) -> LineFormat {
        let omit = match (&fields, full, kind) {
            (None, false, Some(kind)) => omitted_fields(kind),
            _ => &[],
        };
        LineFormat {
            loaded_displacements: fields.is_none() && !full && kind == Some("static"),
            fields,
            notes_by_ref,
            omit: omit.iter().map(|p| p.to_string()).collect(),
        }
    }

    /// Parses `--fields a,b.c` (empty names are refused).
    pub fn parse_fields(text: &str) -> Result<Vec<String>, String> {
        let fields: Vec<String> = text.split(',').map(|f| f.trim().to_string()).collect();
        if fields.iter().any(|f| f.is_empty() || f.split('.').any(str::is_empty)) {
            return Err(
                "give comma-separated result fields as dotted paths, e.g. stiffness_z,at_allowable.force".into(),
            );
        }
        Ok(fields)
    }

    /// The reference of model notes in a line (see [`Self::notes_by_ref`]).
    pub fn notes_ref(notes: &Value) -> String {
        let mut h = Fnv128::new();
        canonical(notes, &mut h);
        format!("{:08x}", (h.0 >> 96) as u32)
    }

    /// [`Self::notes_ref`] of notes whose compact JSON is `json`: when they hold no object
    /// (notes are an array of strings) the canonical text is that JSON, hashed as it stands.
    fn notes_ref_of(notes: &Value, json: &str) -> String {
        fn has_object(v: &Value) -> bool {
            match v {
                Value::Object(_) => true,
                Value::Array(a) => a.iter().any(has_object),
                _ => false,
            }
        }
        if has_object(notes) {
            return Self::notes_ref(notes);
        }
        let mut h = Fnv128::new();
        h.write(json.as_bytes());
        format!("{:08x}", (h.0 >> 96) as u32)
    }

    /// Applies the format to a design's result; returns the notes taken out, as (reference,
    /// notes, their compact JSON).
    pub(super) fn apply(&self, result: &mut Value, loaded: Option<&[Vec<usize>]>) -> Option<(String, Value, String)> {
        let notes = match (self.notes_by_ref, result.as_object_mut()) {
            (true, Some(m)) => {
                // `model_notes` takes the place of `model` (the typed route writes it there).
                let at = m.keys().position(|k| k == "model");
                m.shift_remove("model").zip(at).map(|(notes, at)| {
                    // Serialised once: hashed for the reference and written to the sidecar.
                    let json = serde_json::to_string(&notes).unwrap_or_else(|_| notes.to_string());
                    let r = Self::notes_ref_of(&notes, &json);
                    m.shift_insert(at, "model_notes".into(), Value::String(r.clone()));
                    (r, notes, json)
                })
            }
            _ => None,
        };
        if self.fields.is_none() {
            for p in &self.omit {
                remove_path(result, &p.split('.').collect::<Vec<_>>());
            }
            if let Some(nodes) = loaded.filter(|_| self.loaded_displacements) {
                keep_loaded_displacements(result, nodes);
            }
        }
        if let Some(fields) = &self.fields {
            let mut kept = Value::Object(Map::new());
            for f in fields {
                let path: Vec<&str> = f.split('.').collect();
                if let Some(v) = pointer(result, &path) {
                    insert_path(&mut kept, &path, v.clone());
                }
            }
            *result = kept;
        }
        notes
    }
}

/// The value at a dotted path (object keys, array indices).
pub(super) fn pointer<'a>(v: &'a Value, path: &[&str]) -> Option<&'a Value> {
    path.iter().try_fold(v, |v, key| match v {
        Value::Object(m) => m.get(*key),
        Value::Array(a) => key.parse::<usize>().ok().and_then(|i| a.get(i)),
        _ => None,
    })
}

/// Sets `path` in `out` (objects created as needed; array indices become object keys).
fn insert_path(out: &mut Value, path: &[&str], v: Value) {
    let Some((last, head)) = path.split_last() else { return };
    let mut cur = out;
    for key in head {
        let Value::Object(m) = cur else { return };
        cur = m.entry(key.to_string()).or_insert_with(|| Value::Object(Map::new()));
    }
    if let Value::Object(m) = cur {
        m.insert(last.to_string(), v);
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The reference hashed from the notes' JSON equals the canonical one (escapes, non-ASCII
    /// and numbers included), and notes holding an object still sort its keys.
    #[test]
    fn notes_reference_from_json_is_the_canonical_one() {
        for notes in [
            serde_json::json!(["a \"quoted\" note", "K_t = 1.2345", "é\n\t", 1.5e-300, -0.0]),
            serde_json::json!([{"z": 1, "a": 2}, "x"]),
        ] {
            let json = serde_json::to_string(&notes).unwrap();
            assert_eq!(LineFormat::notes_ref_of(&notes, &json), LineFormat::notes_ref(&notes));
        }
    }
}
