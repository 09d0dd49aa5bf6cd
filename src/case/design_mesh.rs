//! `sensitivity` and `design` of any mechanism: a static mesh case with parameters and
//! metrics (`"case"`), the parameters varied with their bounds, requirements on the metrics and
//! an objective. Beside the stage form of [`super::design`], told apart by the `case` field.
//!
//! ```json
//! {"analysis": "design",
//!  "case": "parallelogram_parameters.json",
//!  "parameters": {"t": {"bounds": [0.4, 1.5]}, "R": {"bounds": [2, 8]}},
//!  "requirements": [{"metric": "stroke", "min": 2}, {"metric": "k_out", "min": 50}],
//!  "objective": {"minimise": "k_x"}}
//! ```

use super::design::{DesignCase, SensitivityCase};
use super::error::{check, CaseError};
use super::{from_value, short, Source};
use serde::Deserialize;
use serde_json::Value;
use std::collections::BTreeMap;
use std::path::PathBuf;

/// A varied parameter.
#[derive(Debug, Clone, Deserialize, schemars::JsonSchema)]
#[serde(deny_unknown_fields)]
pub struct ParameterRange {
    /// `[lo, hi]`, lo < hi, in the parameter's unit; the declared value must lie inside.
    /// Required by `design`; optional for `sensitivity`.
    #[serde(default)]
    pub bounds: Option<[f64; 2]>,
}

/// A requirement on one metric: `min` and/or `max`.
#[derive(Debug, Clone, Deserialize, schemars::JsonSchema)]
#[serde(deny_unknown_fields)]
pub struct MetricRequirement {
    /// Name of a metric of the case (a `stroke_at_allowable` metric is its `stroke`).
    pub metric: String,
    /// The metric must be at least this (the metric's unit).
    #[serde(default)]
    pub min: Option<f64>,
    /// The metric must be at most this.
    #[serde(default)]
    pub max: Option<f64>,
}

/// Match a node's 6×6 compliance.
#[derive(Debug, Clone, Deserialize, schemars::JsonSchema)]
#[serde(deny_unknown_fields)]
pub struct MatchCompliance {
    /// The node of the case (its compliance with the case's supports, global axes).
    pub node: usize,
    /// Target compliance, rows [ux, uy, uz, rx, ry, rz] × columns [Fx, Fy, Fz, Mx, My, Mz]:
    /// mm/N, mm/(N·mm), rad/N, rad/(N·mm).
    pub target: [[f64; 6]; 6],
    /// Weight of each entry, ≥ 0 (default: w_ij = 1/(C_ii C_jj) of the target, 0 where a
    /// diagonal entry is 0: each entry counts relative to its natural scale √(C_ii C_jj)).
    #[serde(default)]
    pub weights: Option<[[f64; 6]; 6]>,
}

/// What the design improves.
#[derive(Debug, Clone, Deserialize, schemars::JsonSchema)]
#[serde(rename_all = "snake_case", deny_unknown_fields)]
pub enum ObjectiveSpec {
    /// Maximise a metric (positive at every design).
    Maximise(String),
    /// Minimise a metric (positive at every design).
    Minimise(String),
    /// Least squares on a node compliance: minimise Σ w (C − C_target)² / Σ w C_target².
    MatchCompliance(Box<MatchCompliance>),
}

/// The mechanism: an inline static case, or the path of a case file (relative to this case).
#[derive(Debug, Clone, Deserialize, schemars::JsonSchema)]
#[serde(untagged)]
pub enum CaseRef {
    /// Path of a `static` case file.
    Path(String),
    /// A `static` case with `parameters` and `metrics`.
    Inline(serde_json::Map<String, Value>),
}

/// `"analysis": "sensitivity"` of a mesh case.
#[derive(Debug, Clone, Deserialize, schemars::JsonSchema)]
#[serde(deny_unknown_fields)]
pub struct MeshSensitivityCase {
    /// Free text.
    #[serde(default)]
    pub description: Option<String>,
    /// The mechanism: a static case with parameters and metrics.
    pub case: CaseRef,
    /// Parameters to vary (declared in the case or its mesh file), each increased in turn.
    pub parameters: BTreeMap<String, ParameterRange>,
    /// Relative increase of each parameter, in (0, 2] (default 0.1).
    #[serde(default = "default_increment")]
    #[schemars(extend("exclusiveMinimum" = 0, "maximum" = 2))]
    pub increment: f64,
    /// The static case as read, and the folder its file references resolve against.
    #[serde(skip)]
    #[schemars(skip)]
    pub inner: Inner,
}

/// `"analysis": "design"` of a mesh case.
#[derive(Debug, Clone, Deserialize, schemars::JsonSchema)]
#[serde(deny_unknown_fields)]
pub struct MeshDesignCase {
    /// Free text.
    #[serde(default)]
    pub description: Option<String>,
    /// The mechanism: a static case with parameters and metrics.
    pub case: CaseRef,
    /// Parameters to vary with their bounds (declared in the case or its mesh file).
    pub parameters: BTreeMap<String, ParameterRange>,
    /// Requirements on the metrics.
    #[serde(default)]
    pub requirements: Vec<MetricRequirement>,
    /// What to improve among the designs that meet the requirements.
    pub objective: ObjectiveSpec,
    /// Quasi-random designs sampled before the local search, 1 … 100000 (default 64).
    #[serde(default = "default_samples")]
    #[schemars(range(min = 1, max = 100000))]
    pub samples: usize,
    /// See [`MeshSensitivityCase::inner`].
    #[serde(skip)]
    #[schemars(skip)]
    pub inner: Inner,
}

/// The static case of a mesh design problem as read.
#[derive(Debug, Clone, Default)]
pub struct Inner {
    /// The case object (parameters not yet resolved).
    pub value: Value,
    /// The folder its relative file references resolve against.
    pub dir: Option<PathBuf>,
}

fn default_increment() -> f64 {
    0.1
}
fn default_samples() -> usize {
    64
}

/// `sensitivity`: the stage form or the mesh form (with `case`).
#[derive(Debug, Clone)]
pub enum SensitivitySpec {
    /// Table 1 of the 3-PRS stage.
    Stage(SensitivityCase),
    /// Any static mesh case with parameters and metrics.
    Mesh(MeshSensitivityCase),
}

/// `design`: the stage form or the mesh form (with `case`).
#[derive(Debug, Clone)]
pub enum DesignSpec {
    /// Sizing of the 3-PRS stage hinges.
    Stage(DesignCase),
    /// Any static mesh case with parameters and metrics.
    Mesh(MeshDesignCase),
}

/// The inline schema of `T` with the `analysis` tag among its properties (each form refuses
/// unknown fields, and the tag is one of the case's fields).
fn tagged<T: schemars::JsonSchema>(g: &mut schemars::SchemaGenerator) -> Value {
    let mut s = serde_json::to_value(T::json_schema(g)).unwrap_or(Value::Null);
    if let Some(props) = s.get_mut("properties").and_then(Value::as_object_mut) {
        props.insert("analysis".into(), serde_json::json!({"type": "string"}));
    }
    s
}

impl schemars::JsonSchema for SensitivitySpec {
    fn schema_name() -> std::borrow::Cow<'static, str> {
        "SensitivitySpec".into()
    }
    fn json_schema(g: &mut schemars::SchemaGenerator) -> schemars::Schema {
        let (stage, mesh) = (tagged::<SensitivityCase>(g), tagged::<MeshSensitivityCase>(g));
        schemars::json_schema!({
            "description": "The 3-PRS stage (`stage`) or a static mesh case with parameters and metrics (`case`).",
            "anyOf": [stage, mesh]
        })
    }
}

impl schemars::JsonSchema for DesignSpec {
    fn schema_name() -> std::borrow::Cow<'static, str> {
        "DesignSpec".into()
    }
    fn json_schema(g: &mut schemars::SchemaGenerator) -> schemars::Schema {
        let (stage, mesh) = (tagged::<DesignCase>(g), tagged::<MeshDesignCase>(g));
        schemars::json_schema!({
            "description": "The 3-PRS stage (`stage`) or a static mesh case with parameters and metrics (`case`).",
            "anyOf": [stage, mesh]
        })
    }
}

/// True for the mesh form of a `sensitivity`/`design` case value (it has `case`); such a case
/// is not resolved as a whole: its `parameters` are ranges, and the inner case is resolved per
/// design.
pub fn is_mesh_form(value: &Value) -> bool {
    matches!(
        value.get("analysis").and_then(Value::as_str),
        Some("sensitivity" | "design")
    ) && value.get("case").is_some()
}

/// Reads the inner case: inline, or the file named (relative to the case's folder).
fn inner_of(case: &CaseRef, base: &Source<'_>) -> Result<Inner, CaseError> {
    match case {
        CaseRef::Inline(m) => Ok(Inner {
            value: Value::Object(m.clone()),
            dir: base.dir.map(PathBuf::from),
        }),
        CaseRef::Path(name) => {
            let value = super::read_json("case", name, base.dir)?;
            let file = super::resolve_file(name, base.dir);
            if !value.is_object() {
                return Err(CaseError::value(
                    "case",
                    format!("\"{name}\""),
                    format!("{} must hold a case object, not {}", file.display(), short(&value)),
                ));
            }
            Ok(Inner {
                value,
                dir: file.parent().map(PathBuf::from),
            })
        }
    }
}

/// The parser of `sensitivity` case values.
pub fn parse_sensitivity(value: Value, base: &Source<'_>) -> Result<SensitivitySpec, CaseError> {
    if value.get("case").is_none() {
        return from_value(value, "").map(SensitivitySpec::Stage);
    }
    let mut c: MeshSensitivityCase = from_value(value, "")?;
    c.inner = inner_of(&c.case, base)?;
    Ok(SensitivitySpec::Mesh(c))
}

/// The parser of `design` case values.
pub fn parse_design(value: Value, base: &Source<'_>) -> Result<DesignSpec, CaseError> {
    if value.get("case").is_none() {
        return from_value(value, "").map(DesignSpec::Stage);
    }
    let mut c: MeshDesignCase = from_value(value, "")?;
    c.inner = inner_of(&c.case, base)?;
    Ok(DesignSpec::Mesh(c))
}

/// Checks the ranges of `parameters` (paths `parameters.NAME.bounds`): at least one parameter;
/// lo < hi, finite; bounds required when `need_bounds`.
pub fn check_ranges(parameters: &BTreeMap<String, ParameterRange>, need_bounds: bool) -> Result<(), CaseError> {
    if parameters.is_empty() {
        return Err(CaseError::new(
            "parameters",
            "name at least one parameter of the case to vary: {\"NAME\": {\"bounds\": [lo, hi]}}",
        ));
    }
    for (name, r) in parameters {
        let at = format!("parameters.{name}.bounds");
        match r.bounds {
            Some(b) if b.iter().all(|v| v.is_finite()) && b[0] < b[1] => {}
            Some(b) => {
                return Err(CaseError::value(
                    at,
                    format!("[{}, {}]", b[0], b[1]),
                    "bounds must be finite [lo, hi] with lo < hi",
                ))
            }
            None if need_bounds => return Err(CaseError::new(at, "is required: [lo, hi] with lo < hi")),
            None => {}
        }
    }
    Ok(())
}

impl MeshSensitivityCase {
    /// The checks that need no model: ranges and increment.
    pub fn check_fields(&self) -> Result<(), CaseError> {
        check_ranges(&self.parameters, false)?;
        if !(self.increment.is_finite() && self.increment > 0.0 && self.increment <= 2.0) {
            return Err(CaseError::value(
                "increment",
                self.increment,
                "must be a relative increase in (0, 2] (0.1 = +10 %)",
            ));
        }
        Ok(())
    }
}

impl MeshDesignCase {
    /// The checks that need no model: ranges, requirement limits, samples.
    pub fn check_fields(&self) -> Result<(), CaseError> {
        check_ranges(&self.parameters, true)?;
        for (i, r) in self.requirements.iter().enumerate() {
            let at = format!("requirements[{i}]");
            match (r.min, r.max) {
                (None, None) => return Err(CaseError::new(at, "needs `min` and/or `max`")),
                (Some(lo), Some(hi)) => check::range(&at, [lo, hi])?,
                _ => {}
            }
            for (k, v) in [("min", r.min), ("max", r.max)] {
                if let Some(v) = v.filter(|v| !v.is_finite()) {
                    return Err(CaseError::value(format!("{at}.{k}"), v, "must be a finite number"));
                }
            }
        }
        if let ObjectiveSpec::MatchCompliance(m) = &self.objective {
            let at = "objective.match_compliance";
            if m.target.iter().flatten().any(|v| !v.is_finite()) || m.target.iter().flatten().all(|v| *v == 0.0) {
                return Err(CaseError::new(
                    format!("{at}.target"),
                    "must be finite numbers, not all zero (mm/N, rad/(N·mm) …)",
                ));
            }
            if let Some(w) = &m.weights {
                if w.iter().flatten().any(|v| !(v.is_finite() && *v >= 0.0)) {
                    return Err(CaseError::new(format!("{at}.weights"), "must be finite and ≥ 0"));
                }
                let den: f64 = w
                    .iter()
                    .flatten()
                    .zip(m.target.iter().flatten())
                    .map(|(w, t)| w * t * t)
                    .sum();
                if den <= 0.0 {
                    return Err(CaseError::new(
                        format!("{at}.weights"),
                        "must weigh at least one non-zero target entry",
                    ));
                }
            }
        }
        if !(1..=100_000).contains(&self.samples) {
            return Err(CaseError::value("samples", self.samples, "must be in 1..=100000"));
        }
        Ok(())
    }
}
