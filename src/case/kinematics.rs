//! The `kinematics` case: rigid-body 3-PRS queries.

use super::error::{check, CaseError};
use super::fields::case_struct;
use crate::kinematics::{PoseBox, Prs};
use serde::Deserialize;

case_struct! {
    /// 3-PRS geometry. Give either `alpha0_deg` or the base radius `a`.
    #[derive(Debug, Clone, Deserialize, schemars::JsonSchema)]
    #[serde(deny_unknown_fields)]
    #[schemars(extend("oneOf" = alpha0_or_a()))]
    pub struct MechanismSpec {
        include prs_geometry;
    }
}

/// Schema of "exactly one of `alpha0_deg` and `a` is a number".
pub(crate) fn alpha0_or_a() -> serde_json::Value {
    serde_json::json!([
        {"required": ["alpha0_deg"], "properties": {"alpha0_deg": {"type": "number"}, "a": {"type": "null"}}},
        {"required": ["a"], "properties": {"a": {"type": "number"}, "alpha0_deg": {"type": "null"}}}
    ])
}

impl MechanismSpec {
    /// Validates and builds the mechanism; `path` is the JSON path of this object.
    pub fn build(&self, path: &str) -> Result<Prs, CaseError> {
        let p = |f: &str| format!("{path}.{f}");
        check::positive(format_args!("{path}.L"), self.l, "mm")?;
        check::positive(format_args!("{path}.b"), self.b, "mm")?;
        check::within(format_args!("{path}.gamma_deg"), self.gamma_deg, -90.0, 90.0, "degrees")?;
        let gamma = self.gamma_deg.to_radians();
        let prs = match (self.alpha0_deg, self.a) {
            (Some(al), None) => {
                if !(al.is_finite() && al > 0.0 && al < 90.0) {
                    return Err(CaseError::value(p("alpha0_deg"), al, "must lie in (0, 90) degrees"));
                }
                Prs::new(self.l, self.b, al.to_radians(), gamma).map_err(|e| CaseError::new(path, e.to_string()))?
            }
            (None, Some(a)) => {
                check::positive(format_args!("{path}.a"), a, "mm")?;
                Prs::with_base_radius(self.l, self.b, a, gamma).map_err(|e| CaseError::new(p("L"), e.to_string()))?
            }
            (Some(_), Some(_)) => {
                return Err(CaseError::new(path, "give either `alpha0_deg` or `a`, not both"));
            }
            (None, None) => {
                return Err(CaseError::new(
                    path,
                    "missing field `alpha0_deg` (or `a`, the base radius in mm)",
                ));
            }
        };
        Ok(prs)
    }
}

/// An inverse-kinematics query: the independent pose coordinates, from home.
#[derive(Debug, Clone, Copy, Deserialize, schemars::JsonSchema)]
#[serde(deny_unknown_fields)]
pub struct PoseQuery {
    /// Platform z displacement from home, mm.
    #[serde(default)]
    pub z: f64,
    /// Rotation ψ about x, degrees.
    #[serde(default)]
    pub psi_deg: f64,
    /// Rotation θ about y, degrees.
    #[serde(default)]
    pub theta_deg: f64,
}

/// A forward-kinematics query.
#[derive(Debug, Clone, Deserialize, schemars::JsonSchema)]
#[serde(deny_unknown_fields)]
pub struct FkpQuery {
    /// Actuator strokes s₁, s₂, s₃ from home, mm.
    pub s: [f64; 3],
    /// Newton start pose (default: home).
    #[serde(default)]
    pub start: Option<PoseQuery>,
}

/// A box of poses for the requirement sweep.
#[derive(Debug, Clone, Deserialize, schemars::JsonSchema)]
#[serde(deny_unknown_fields)]
pub struct WorkspaceSpec {
    /// z range [min, max] from home, mm.
    pub z: [f64; 2],
    /// ψ range [min, max], degrees, each in [−89, 89].
    #[schemars(extend("items" = {"type": "number", "minimum": -89, "maximum": 89}))]
    pub psi_deg: [f64; 2],
    /// θ range [min, max], degrees, each in [−89, 89].
    #[schemars(extend("items" = {"type": "number", "minimum": -89, "maximum": 89}))]
    pub theta_deg: [f64; 2],
    /// Values per axis, ends included (2–201; default 9).
    #[serde(default = "default_steps")]
    #[schemars(range(min = 2, max = 201))]
    pub steps: usize,
}

fn default_steps() -> usize {
    9
}

impl WorkspaceSpec {
    /// Validates and converts to radians.
    pub fn build(&self, path: &str) -> Result<PoseBox, CaseError> {
        let p = |f: &str| format!("{path}.{f}");
        check::range(p("z"), self.z)?;
        check::range(p("psi_deg"), self.psi_deg)?;
        check::range(p("theta_deg"), self.theta_deg)?;
        for (f, r) in [("psi_deg", self.psi_deg), ("theta_deg", self.theta_deg)] {
            for (k, v) in r.iter().enumerate() {
                check::within(format_args!("{}[{k}]", p(f)), *v, -89.0, 89.0, "degrees")?;
            }
        }
        if !(2..=201).contains(&self.steps) {
            return Err(CaseError::value(
                p("steps"),
                self.steps,
                "must be an integer in 2..=201",
            ));
        }
        let rad = |r: [f64; 2]| [r[0].to_radians(), r[1].to_radians()];
        Ok(PoseBox {
            z: self.z,
            psi: rad(self.psi_deg),
            theta: rad(self.theta_deg),
            steps: self.steps,
        })
    }
}

/// `"analysis": "kinematics"`: at least one of `ikp`, `fkp`, `workspace`.
#[derive(Debug, Clone, Deserialize, schemars::JsonSchema)]
#[serde(deny_unknown_fields)]
#[schemars(extend("anyOf" = [
    {"required": ["ikp"], "properties": {"ikp": {"minItems": 1}}},
    {"required": ["fkp"], "properties": {"fkp": {"minItems": 1}}},
    {"required": ["workspace"], "properties": {"workspace": {"type": "object"}}}
]))]
pub struct KinematicsCase {
    /// The mechanism geometry.
    pub mechanism: MechanismSpec,
    /// Inverse-kinematics queries (ψ and θ in [−89, 89] degrees).
    #[serde(default)]
    #[schemars(extend("items" = {"allOf": [
        {"$ref": "#/$defs/PoseQuery"},
        {"properties": {
            "psi_deg": {"minimum": -89, "maximum": 89},
            "theta_deg": {"minimum": -89, "maximum": 89}
        }}
    ]}))]
    pub ikp: Vec<PoseQuery>,
    /// Forward-kinematics queries.
    #[serde(default)]
    pub fkp: Vec<FkpQuery>,
    /// Requirement sweep over a box of poses.
    #[serde(default)]
    pub workspace: Option<WorkspaceSpec>,
}

impl KinematicsCase {
    /// Checks every field that the types do not (before anything is solved).
    pub fn validate(&self) -> Result<(Prs, Option<PoseBox>), CaseError> {
        let prs = self.mechanism.build("mechanism")?;
        for (i, q) in self.ikp.iter().enumerate() {
            check::finite(format_args!("ikp[{i}].z"), q.z)?;
            check::within(format_args!("ikp[{i}].psi_deg"), q.psi_deg, -89.0, 89.0, "degrees")?;
            check::within(format_args!("ikp[{i}].theta_deg"), q.theta_deg, -89.0, 89.0, "degrees")?;
        }
        for (i, q) in self.fkp.iter().enumerate() {
            for (k, v) in q.s.iter().enumerate() {
                check::finite(format_args!("fkp[{i}].s[{k}]"), *v)?;
                if v.abs() > prs.l {
                    return Err(CaseError::value(
                        format!("fkp[{i}].s[{k}]"),
                        v,
                        format!("|s| must not exceed the leg length L = {} mm", prs.l),
                    ));
                }
            }
        }
        let bx = self.workspace.as_ref().map(|w| w.build("workspace")).transpose()?;
        if self.ikp.is_empty() && self.fkp.is_empty() && bx.is_none() {
            return Err(CaseError::new(
                ".",
                "nothing to do: give at least one of `ikp`, `fkp`, `workspace`",
            ));
        }
        Ok((prs, bx))
    }
}
