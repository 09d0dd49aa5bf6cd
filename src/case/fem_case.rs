//! `static` and `modal` cases: plain serde shapes (their options and the model), and the
//! reading of a case's model from inline fields, a JSON mesh file or a Gmsh `.msh` file.

use super::error::CaseError;
use super::fields::case_struct;
use super::gmsh::{self, GmshMapping};
use super::mesh::promote::{self, ShellElements};
use super::mesh::MeshSpec;
use super::stage::{self, nonlinear_true, steps_given};
use super::{check_node_count, from_value, limits, read_json, resolve_file};
use serde::Deserialize;
use serde_json::{Map, Value};

/// `"analysis": "modal"`: the lowest `modes` natural frequencies and mass-normalised shapes of
/// a model given as for `static` (supports optional: a free body gives six rigid-body modes
/// first; load cases are ignored).
#[derive(Debug, Clone, schemars::JsonSchema)]
#[serde(deny_unknown_fields)]
#[schemars(extend("allOf" = model_rules(false)))]
pub struct ModalCase {
    /// Mesh file, as for `static`: a JSON mesh file or a Gmsh `.msh` file.
    pub mesh: Option<String>,
    /// Physical-group mapping of a Gmsh `.msh` mesh (only with a `.msh` mesh, which needs it).
    pub gmsh: Option<GmshMapping>,
    /// Number of modes (the lowest), 1 … 1000.
    #[schemars(range(min = 1, max = 1000))]
    pub modes: usize,
    /// Optional shift frequency f, Hz (σ = (2πf)²): the modes nearest above it are found instead of
    /// the lowest; ≥ 0. Default: 0 (a small negative shift for free bodies).
    #[schemars(range(min = 0))]
    pub shift_hz: Option<f64>,
    /// Mode shapes in the JSON result (default true). `false` leaves them out (a 100k-DOF model
    /// would write tens of MB); `modes.vtu` (with `--out`) always holds them.
    #[serde(default = "shapes_default")]
    pub shapes: bool,
    /// The model.
    #[serde(flatten)]
    pub model: MeshSpec,
}

/// Mode shapes are in the JSON result unless `"shapes": false`.
pub(crate) fn shapes_default() -> bool {
    true
}

case_struct! {
    /// `"analysis": "static"`: a model inline or from a `mesh` file, plus load cases.
    #[derive(Debug, Clone, schemars::JsonSchema)]
    #[serde(deny_unknown_fields)]
    #[schemars(extend("allOf" = model_rules(true)))]
    pub struct StaticCase {
        include model_source {
            /// Free text saying what the model is (not used by the analysis).
            description,
            /// Path of a JSON mesh file (relative to the case file's folder, then to the working folder)
            /// holding `materials`, `sections`, `nodes`, `elements`, `supports` and optionally `load_cases`.
            mesh,
            /// Physical-group mapping of a Gmsh `.msh` mesh (only with a `.msh` mesh, which needs it):
            /// `{"groups": {"NAME": {"section", "material", "up"} or {"fix": [...]}}}`.
            gmsh,
            /// The inline model (or additions to the mesh: materials, sections, load cases).
            model,
        }
        include nonlinear_steps {
            /// Geometrically nonlinear statics (co-rotational beams, Newton–Raphson in load steps).
            nonlinear,
            /// Load steps of the nonlinear analysis, 1 … 10000 (default 20; only with
            /// `"nonlinear": true`). After parsing: the steps to use when nonlinear, `None` when linear.
            steps,
        }
        /// Optional result fields: `{"section_forces": true}` adds the section forces of every beam.
        #[serde(default)]
        pub output: super::mesh::StaticOutput,
        /// Nodes whose 6×6 compliance (with the model's supports, undeformed) the result lists:
        /// `[{"node": n, "frame": [[..], [..], [..]]}]` (frame optional, default global axes).
        #[serde(default)]
        pub compliance: Vec<super::mesh::ComplianceRequest>,
        /// Nonlinear only: natural frequencies and node compliances at every accepted load step,
        /// with the tangent stiffness of the deformed state: `{"modes": N, "compliance": [{"node":
        /// n}]}`.
        #[serde(default)]
        pub track: Option<super::mesh::TrackRequest>,
        /// Named scalar results, listed in the result's `metrics` as `{"NAME": value}`:
        /// `[{"name", "kind": "stiffness" | "compliance" | "displacement" | "hinge_rotation" |
        /// "max_utilisation" | "stroke_at_allowable" | "parasitic" | "frequency" |
        /// "buckling_margin", "node", "dof", "load_case", "element", "mode"}]` (each kind takes
        /// the fields its documentation names; `name` defaults to the kind and its fields).
        #[serde(default)]
        pub metrics: Vec<super::mesh::MetricRequest>,
        /// `true`: the result also lists `"gradients": {"METRIC": {"PARAM": d metric / d param}}`,
        /// the derivative of every metric with respect to every parameter declared as a number
        /// (in the units of the metric per unit of the parameter), by the direct method (linear
        /// runs only; needs `metrics` and `parameters`). Default false.
        #[serde(default)]
        pub gradients: bool,
        /// High-cycle fatigue of the `hinge` elements (their materials need `"fatigue"` data):
        /// every load case is the peak of a load cycle `{"cycles", "load_ratio", "method"}`;
        /// each hinge row gets its fatigue utilisation and life, and `fatigue_stroke` metrics
        /// become available (linear runs).
        #[serde(default)]
        pub fatigue: Option<super::fatigue::CyclicSpec>,
        /// The case as written (parameters unresolved), kept when `gradients` asks for it.
        #[serde(skip)]
        #[schemars(skip)]
        pub written: Option<std::sync::Arc<super::params::tangent::Written>>,
    }
}

/// Schema rules of a `static` (`need_loads`) or `modal` case that relate fields: the model is
/// inline (at least one node; static: at least one load case) or comes from `mesh` (then no
/// inline nodes, elements, supports or rigid links); a `.msh` mesh needs `gmsh` and `gmsh` needs
/// a `.msh` mesh; `steps` and `track` only with `"nonlinear": true`.
pub fn model_rules(need_loads: bool) -> serde_json::Value {
    let mut rules = mesh_rules(need_loads);
    if let Some(a) = rules.as_array_mut() {
        a.push(serde_json::json!({"if": steps_given(), "then": nonlinear_true()}));
        a.push(serde_json::json!({
            "if": {"required": ["track"], "properties": {"track": {"type": "object"}}},
            "then": nonlinear_true()
        }));
    }
    rules
}

/// The rules on how the model is given (a mesh file, a Gmsh file with its mapping, or inline
/// nodes), without the nonlinear-path rules of `static` cases: for kinds whose `steps` means
/// something else (time steps of `transient`).
pub fn mesh_rules(need_loads: bool) -> serde_json::Value {
    let mut inline = serde_json::json!({"required": ["nodes"], "properties": {"nodes": {"minItems": 1}}});
    if need_loads {
        inline = serde_json::json!({"allOf": [inline, {"required": ["load_cases"], "properties": {"load_cases": {"minItems": 1}}}]});
    }
    let empty = serde_json::json!({"maxItems": 0});
    serde_json::json!([
        {
            "if": {"required": ["mesh"], "properties": {"mesh": {"type": "string"}}},
            "then": {"properties": {"nodes": empty, "elements": empty, "supports": empty, "rigid_links": empty}},
            "else": inline
        },
        {
            "if": {"required": ["mesh"], "properties": {"mesh": {"type": "string", "pattern": "\\.msh$"}}},
            "then": {"required": ["gmsh"], "properties": {"gmsh": {"type": "object"}}},
            "else": {"properties": {"gmsh": {"type": "null"}}}
        }
    ])
}

/// The options of a `static` case besides its model, as in the case file.
#[derive(Debug, Clone, Deserialize)]
#[serde(deny_unknown_fields)]
struct StaticOptions {
    #[serde(default)]
    description: Option<String>,
    #[serde(default)]
    mesh: Option<String>,
    #[serde(default)]
    gmsh: Option<GmshMapping>,
    #[serde(default)]
    nonlinear: Option<bool>,
    #[serde(default)]
    steps: Option<usize>,
    #[serde(default)]
    output: super::mesh::StaticOutput,
    #[serde(default)]
    compliance: Vec<super::mesh::ComplianceRequest>,
    #[serde(default)]
    track: Option<super::mesh::TrackRequest>,
    #[serde(default)]
    metrics: Vec<super::mesh::MetricRequest>,
    #[serde(default)]
    gradients: bool,
    #[serde(default)]
    fatigue: Option<super::fatigue::CyclicSpec>,
}

/// The options of a `modal` (or `buckling`) case besides its model, as in the case file (each
/// kind splits off only the fields it takes).
#[derive(Debug, Clone, Deserialize)]
#[serde(deny_unknown_fields)]
pub(crate) struct ModalOptions {
    pub(crate) description: Option<String>,
    pub(crate) mesh: Option<String>,
    pub(crate) gmsh: Option<GmshMapping>,
    pub(crate) modes: Option<usize>,
    pub(crate) shift_hz: Option<f64>,
    pub(crate) shapes: Option<bool>,
}

/// The top-level fields of a `static` or `modal` case that are the model's (those of
/// [`MeshSpec`]).
pub const MODEL_FIELDS: [&str; 9] = [
    "materials",
    "sections",
    "nodes",
    "elements",
    "rigid_links",
    "supports",
    "load_cases",
    "ordering",
    "shell_elements",
];

const STATIC_OWN: [&str; 12] = [
    "analysis",
    "description",
    "mesh",
    "gmsh",
    "nonlinear",
    "steps",
    "output",
    "compliance",
    "track",
    "metrics",
    "gradients",
    "fatigue",
];
const MODAL_OWN: [&str; 6] = ["analysis", "mesh", "gmsh", "modes", "shift_hz", "shapes"];

/// Splits a case object into its options (the fields in `own`) and its model (the rest).
pub fn split(mut value: Value, own: &[&str]) -> (Value, Value) {
    let mut options = Map::new();
    if let Value::Object(map) = &mut value {
        map.remove("analysis");
        for k in own {
            if let Some(v) = map.remove(*k) {
                options.insert((*k).to_string(), v);
            }
        }
    }
    (Value::Object(options), value)
}

/// Parses a `static` case (the object without `analysis` checks); files it names resolve
/// against `base` first.
pub fn parse_static(value: Value, base: &crate::case::Source<'_>) -> Result<StaticCase, CaseError> {
    unknown_model_field(&value, "static")?;
    let (options, model) = split(value, &STATIC_OWN);
    let mut o: StaticOptions = from_value(options, "")?;
    super::mesh::metrics::name_metrics(&mut o.metrics);
    let nonlinear = o.nonlinear.unwrap_or(false);
    let steps = stage::check_steps("steps", o.steps, nonlinear)?;
    let model = read_model(model, o.mesh.as_deref(), o.gmsh.as_ref(), base)?;
    super::mesh::requests::check_compliance(&o.compliance, model.nodes.len())?;
    super::mesh::requests::check_picture(&o.output.picture, &model.load_cases)?;
    super::mesh::requests::check_track(o.track.as_ref(), nonlinear, model.nodes.len())?;
    super::mesh::metrics::check_metrics(&o.metrics, &model, nonlinear)?;
    check_gradients(o.gradients, nonlinear, &o.metrics)?;
    if let Some(f) = &o.fatigue {
        f.check("fatigue")?;
    }
    super::mesh::metrics::check_fatigue_metrics(&o.metrics, o.fatigue.is_some(), nonlinear)?;
    for (i, c) in model.load_cases.iter().enumerate() {
        super::mesh::path_control::check(&format!("load_cases[{i}]"), c, steps, model.nodes.len())?;
    }
    Ok(StaticCase {
        description: o.description,
        mesh: o.mesh,
        gmsh: o.gmsh,
        model,
        nonlinear,
        steps,
        output: o.output,
        compliance: o.compliance,
        track: o.track,
        metrics: o.metrics,
        gradients: o.gradients,
        fatigue: o.fatigue,
        written: None,
    })
}

/// `"gradients": true` needs a linear run with metrics (the parameters are checked where the
/// case is read: [`crate::case::params::tangent::Written`]).
fn check_gradients(gradients: bool, nonlinear: bool, metrics: &[super::mesh::MetricRequest]) -> Result<(), CaseError> {
    if !gradients {
        return Ok(());
    }
    if nonlinear {
        return Err(CaseError::value(
            "gradients",
            true,
            "gradients are computed for linear runs only: remove \"nonlinear\": true or \"gradients\"",
        ));
    }
    if metrics.is_empty() {
        return Err(CaseError::value(
            "gradients",
            true,
            "needs \"metrics\": the gradients are those of the metrics",
        ));
    }
    Ok(())
}

/// Parses a `modal` case, as [`parse_static`].
pub fn parse_modal(value: Value, base: &crate::case::Source<'_>) -> Result<ModalCase, CaseError> {
    unknown_model_field(&value, "modal")?;
    let (options, model) = split(value, &MODAL_OWN);
    let o: ModalOptions = from_value(options, "")?;
    let modes = modes_of(o.modes, "modes")?;
    if let Some(f) = o.shift_hz {
        if !(f.is_finite() && f >= 0.0) {
            return Err(CaseError::value("shift_hz", f, "must be a frequency ≥ 0, Hz"));
        }
    }
    let model = read_model(model, o.mesh.as_deref(), o.gmsh.as_ref(), base)?;
    Ok(ModalCase {
        mesh: o.mesh,
        gmsh: o.gmsh,
        modes,
        shift_hz: o.shift_hz,
        shapes: o.shapes.unwrap_or(true),
        model,
    })
}

/// The checked `modes` of a `modal` or `buckling` case: 1 … 1000, required (`what` names them
/// in the message).
pub(crate) fn modes_of(modes: Option<usize>, what: &str) -> Result<usize, CaseError> {
    match modes {
        Some(k) if (1..=1000).contains(&k) => Ok(k),
        Some(k) => Err(CaseError::value("modes", k, "must be an integer from 1 to 1000")),
        None => Err(CaseError::new(
            "modes",
            format!("missing field `modes` (number of {what} wanted)"),
        )),
    }
}

/// A `kind` case whose own fields `own` sit beside the model's ([`MODEL_FIELDS`]): refuses any
/// other field (listing the allowed ones), parses the own fields less `ignore` as `O`, and reads
/// the model from the rest with the `mesh` file and `gmsh` mapping that `source` takes from `O`.
pub fn parse_with_model<O: serde::de::DeserializeOwned>(
    value: Value,
    kind: &str,
    own: &[&str],
    ignore: &[&str],
    base: &crate::case::Source<'_>,
    source: impl FnOnce(&O) -> (Option<&str>, Option<&GmshMapping>),
) -> Result<(O, MeshSpec), CaseError> {
    let known = |k: &str| own.contains(&k) || MODEL_FIELDS.contains(&k);
    if let Some(key) = value.as_object().and_then(|m| m.keys().find(|k| !known(k))) {
        let expected: Vec<String> = own
            .iter()
            .chain(MODEL_FIELDS.iter())
            .map(|f| format!("`{f}`"))
            .collect();
        return Err(CaseError::new(
            key.clone(),
            format!(
                "unknown field `{key}` in a `{kind}` case, expected one of {}",
                expected.join(", ")
            ),
        ));
    }
    let (mut options, model) = split(value, own);
    if let Value::Object(m) = &mut options {
        m.retain(|k, _| !ignore.contains(&k.as_str()));
    }
    let o: O = from_value(options, "")?;
    let (mesh, gmsh) = source(&o);
    let model = read_model(model, mesh, gmsh, base)?;
    Ok((o, model))
}

/// The model of a case: the inline fields `value`, merged into the `mesh` file's model if one
/// is named (a JSON mesh file, or a Gmsh `.msh` file read through the `gmsh` mapping).
pub fn read_model(
    value: Value,
    mesh_name: Option<&str>,
    gmsh_map: Option<&GmshMapping>,
    base: &crate::case::Source<'_>,
) -> Result<MeshSpec, CaseError> {
    check_node_count("nodes", &value)?;
    let inline: MeshSpec = from_value(value, "")?;
    let mut spec = match mesh_name {
        Some(name) if name.ends_with(".msh") => {
            let Some(mapping) = gmsh_map else {
                return Err(CaseError::new(
                    "gmsh",
                    "a .msh mesh needs a `gmsh` mapping: {\"groups\": {\"NAME\": {\"section\", \"material\"} or {\"fix\": [...]}}}",
                ));
            };
            let file = resolve_file(name, base.dir);
            let bytes = limits::read_file("mesh", "mesh file", &format!("\"{name}\""), &file)?;
            let text = gmsh::msh_text(&bytes)
                .map_err(|e| CaseError::new(e.path.clone(), format!("in {name}: {}", e.message)))?;
            let (from_file, _notes, origin) = gmsh::parse_msh_traced(text, mapping)
                .map_err(|e| CaseError::new(e.path.clone(), format!("in {name}: {}", e.message)))?;
            let mut merged = MeshSpec::merge_inline(from_file, inline)?;
            // Errors in elements built from the .msh belong to the user's group mapping.
            merged
                .build_model(false)
                .map_err(|e| gmsh::group_error(e, &origin, name))?;
            promote_asked(&mut merged, |e| gmsh::group_error(e, &origin, name))?;
            merged
        }
        Some(_) | None if gmsh_map.is_some() => {
            return Err(CaseError::new(
                "gmsh",
                "a `gmsh` mapping is only used with a .msh mesh file",
            ))
        }
        Some(name) => {
            let mut mv = match base.take_mesh(name) {
                Some(v) => v,
                None => read_json("mesh", name, base.dir)?,
            };
            check_node_count("mesh", &mv)?;
            if let Value::Object(m) = &mut mv {
                m.remove("analysis");
            }
            let from_file: MeshSpec = from_value(mv, "").map_err(|e| super::params::in_mesh_file(name, e))?;
            let mut merged = MeshSpec::merge_inline(from_file, inline)?;
            merged.mesh_file = Some(name.to_string());
            merged
        }
        None => inline,
    };
    super::mesh::superelement::load_files(&mut spec, base.dir)?;
    if spec.promoted.is_none() {
        let file = spec.mesh_file.clone();
        promote_asked(&mut spec, |e| match &file {
            Some(name) => super::params::in_mesh_file(name, e),
            None => e,
        })?;
    }
    spec.hinge_type_names = base.hinge_types().clone();
    Ok(spec)
}

/// Promotes the shells of `spec` when it asks for `"shell_elements": "shell9"`, its errors
/// placed by `place` (a Gmsh group, a mesh file); the added nodes count against the node limit.
fn promote_asked(spec: &mut MeshSpec, place: impl Fn(CaseError) -> CaseError) -> Result<(), CaseError> {
    if spec.shell_elements != Some(ShellElements::Shell9) {
        return Ok(());
    }
    promote::promote(spec).map_err(place)?;
    limits::check_nodes("shell_elements", spec.nodes.len())
}

/// Refuses a top-level field that a `static` or `modal` case does not take, listing all it does.
fn unknown_model_field(value: &Value, analysis: &str) -> Result<(), CaseError> {
    let Some(map) = value.as_object() else {
        return Ok(());
    };
    let (own, other, other_fields): (&[&str], &str, &[&str]) = if analysis == "static" {
        (&STATIC_OWN, "modal", &["modes", "shift_hz", "shapes"])
    } else {
        (&MODAL_OWN, "static", &["nonlinear", "steps"])
    };
    let Some(key) = map
        .keys()
        .find(|k| !own.contains(&k.as_str()) && !MODEL_FIELDS.contains(&k.as_str()))
    else {
        return Ok(());
    };
    let expected: Vec<String> = own
        .iter()
        .chain(MODEL_FIELDS.iter())
        .map(|f| format!("`{f}`"))
        .collect();
    let hint = if other_fields.contains(&key.as_str()) {
        format!(" (`{key}` belongs to a `{other}` case)")
    } else {
        String::new()
    };
    Err(CaseError::new(
        key.clone(),
        format!(
            "unknown field `{key}` in a `{analysis}` case{hint}, expected one of {}",
            expected.join(", ")
        ),
    ))
}
