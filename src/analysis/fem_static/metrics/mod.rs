//! The `"metrics"` of a `static` result: the named scalars a case asks for
//! ([`crate::case::mesh::MetricRequest`]), evaluated from the solved load cases and, for
//! stiffness and compliance, the node compliance with the model's supports; natural
//! frequencies and buckling margins from a modal and a linear buckling solve of the model
//! ([`eigen`]); the stroke at the allowable along the nonlinear path by a bracketed secant
//! search over independent nonlinear solves ([`stroke`]).

mod eigen;
mod stroke;

use super::{AnalysisError, StaticResult};
use crate::case::mesh::{BuiltHinge, MetricKind, MetricRequest};
use crate::fem::{self, Model};
use serde::ser::SerializeMap;

pub use stroke::STROKE_TOL;

/// Where a load case, scaled, brings the largest utilisation to 1 (`stroke_at_allowable`).
#[derive(Debug, Clone, Copy, PartialEq, serde::Serialize)]
pub struct StrokeAtAllowable {
    /// Displacement of the node along the DOF, mm (degrees for rx, ry, rz; nonlinear runs: the
    /// rotation-vector component).
    pub stroke: f64,
    /// The load there: the reaction of the prescribed DOF, or the applied force, N (N·mm).
    pub load: f64,
    /// Index in the case's `elements` of the element that reaches its allowable first.
    pub element: usize,
    /// The linear estimate of `stroke` (the load case scaled by 1 / its linear utilisation),
    /// mm (degrees).
    pub linear_estimate: f64,
    /// The largest utilisation at the reported point (1 to [`STROKE_TOL`] in nonlinear runs;
    /// exactly 1 in linear ones).
    pub utilisation: f64,
    /// Nonlinear solves of the search (0 in linear runs).
    pub solves: usize,
}

/// One metric's value.
#[derive(Debug, Clone, Copy, PartialEq, serde::Serialize)]
#[serde(untagged)]
pub enum MetricValue {
    /// A number, `null` when unbounded or undefined (a stiffness along a supported DOF, a
    /// utilisation without any allowable stress).
    Number(Option<f64>),
    /// `stroke_at_allowable`.
    Stroke(StrokeAtAllowable),
}

impl MetricValue {
    /// The number of the metric: a scalar's value, a stroke's `stroke` (`None` for a `null`).
    pub fn number(&self) -> Option<f64> {
        match self {
            MetricValue::Number(v) => *v,
            MetricValue::Stroke(s) => Some(s.stroke),
        }
    }
}

/// Named metric values in the order the case lists them.
#[derive(Debug, Clone, Default, PartialEq)]
pub struct Metrics(pub Vec<(String, MetricValue)>);

impl Metrics {
    /// No metric was asked for.
    pub fn is_empty(&self) -> bool {
        self.0.is_empty()
    }

    /// The value named `name`.
    pub fn get(&self, name: &str) -> Option<MetricValue> {
        self.0.iter().find(|(n, _)| n == name).map(|(_, v)| *v)
    }
}

impl serde::Serialize for Metrics {
    fn serialize<S: serde::Serializer>(&self, s: S) -> Result<S::Ok, S::Error> {
        let mut m = s.serialize_map(Some(self.0.len()))?;
        for (k, v) in &self.0 {
            m.serialize_entry(k, v)?;
        }
        m.end()
    }
}

/// What the metrics of a nonlinear run need to solve the model again: the nominal load steps
/// and the hinge and element maps of the build ([`crate::case::mesh::MeshSpec::build_indexed`]).
#[derive(Debug, Clone, Copy)]
pub struct NonlinearRun<'a> {
    /// Nominal load steps of the case (`steps`).
    pub steps: usize,
    /// The model's hinge elements.
    pub hinges: &'a [BuiltHinge],
    /// The model element of each case element.
    pub case_index: &'a [Option<usize>],
    /// The run's final state of each load case (the searches continue from it).
    pub raw: &'a fem::StaticResults,
}

/// Evaluates `reqs` (validated when the case was parsed, against `spec`) on the linear result
/// `r` of `model`.
pub fn evaluate(
    model: &Model,
    spec: &crate::case::mesh::MeshSpec,
    reqs: &[MetricRequest],
    r: &StaticResult,
) -> Result<Metrics, AnalysisError> {
    evaluate_in(model, spec, reqs, r, None)
}

/// [`evaluate`] on the result of a linear (`nonlinear: None`) or nonlinear run.
pub fn evaluate_in(
    model: &Model,
    spec: &crate::case::mesh::MeshSpec,
    reqs: &[MetricRequest],
    r: &StaticResult,
    nonlinear: Option<NonlinearRun<'_>>,
) -> Result<Metrics, AnalysisError> {
    let needs_system = reqs
        .iter()
        .any(|m| matches!(m.kind, MetricKind::Stiffness | MetricKind::Compliance));
    let sys = if needs_system {
        Some(
            fem::System::new(model, &[], fem::solve::Parallelism::Rayon)
                .map_err(|e| AnalysisError::new("metrics", e.to_string()))?,
        )
    } else {
        None
    };
    let frequencies = eigen::frequencies(model, reqs)?;
    let mut out = Vec::with_capacity(reqs.len());
    for (i, m) in reqs.iter().enumerate() {
        let at = || format!("metrics[{i}]");
        let missing = || AnalysisError::new(at(), "names no result of the model (checked when parsed)");
        let case = || {
            m.load_case
                .as_deref()
                .and_then(|n| r.load_cases.iter().find(|c| c.name == n))
                .ok_or_else(missing)
        };
        let node_dof = || m.node.zip(m.dof()).ok_or_else(missing);
        let value = match m.kind {
            MetricKind::Stiffness | MetricKind::Compliance => {
                let (node, dof) = node_dof()?;
                let c = sys
                    .as_ref()
                    .ok_or_else(missing)?
                    .node_compliance(model, node)
                    .map_err(|e| AnalysisError::new(at(), e.to_string()))?;
                let c = c[(dof.index(), dof.index())];
                MetricValue::Number(match m.kind {
                    MetricKind::Compliance => Some(c),
                    _ => (c > 0.0).then(|| 1.0 / c),
                })
            }
            MetricKind::Displacement | MetricKind::Parasitic => {
                let (node, dof) = node_dof()?;
                let d = case()?.displacements.get(node).ok_or_else(missing)?;
                MetricValue::Number(Some(d[dof.index()]))
            }
            MetricKind::HingeRotation => {
                let h = case()?.hinges.iter().find(|h| Some(h.element) == m.element);
                MetricValue::Number(Some(h.ok_or_else(missing)?.rotation_deg))
            }
            MetricKind::MaxUtilisation => MetricValue::Number(case()?.max_utilisation.as_ref().map(|u| u.value)),
            MetricKind::StrokeAtAllowable => {
                let (node, dof) = node_dof()?;
                let c = case()?;
                let ic = model
                    .load_cases
                    .iter()
                    .position(|l| l.name == c.name)
                    .ok_or_else(missing)?;
                let drive = stroke::Drive { ic, node, dof };
                let s = match nonlinear {
                    None => stroke::linear(model, spec, &drive, c),
                    Some(run) => stroke::nonlinear(model, spec, &drive, c, &run),
                };
                s.map_err(|e| within(at(), e))?
                    .map_or(MetricValue::Number(None), MetricValue::Stroke)
            }
            MetricKind::FatigueStroke => {
                let (node, dof) = node_dof()?;
                let c = case()?;
                let ic = model
                    .load_cases
                    .iter()
                    .position(|l| l.name == c.name)
                    .ok_or_else(missing)?;
                stroke::fatigue_linear(model, &stroke::Drive { ic, node, dof }, c)
                    .map_err(|e| within(at(), e))?
                    .map_or(MetricValue::Number(None), MetricValue::Stroke)
            }
            MetricKind::Frequency => {
                let f = m.mode.and_then(|n| frequencies.get(n - 1).copied());
                MetricValue::Number(Some(f.ok_or_else(missing)?))
            }
            MetricKind::BucklingMargin => {
                let name = m.load_case.as_deref().ok_or_else(missing)?;
                let ic = model
                    .load_cases
                    .iter()
                    .position(|l| l.name == name)
                    .ok_or_else(missing)?;
                MetricValue::Number(Some(eigen::buckling_margin(model, ic).map_err(|e| within(at(), e))?))
            }
        };
        let numbers = match value {
            MetricValue::Number(v) => [v, None, None],
            MetricValue::Stroke(s) => [Some(s.stroke), Some(s.load), Some(s.linear_estimate)],
        };
        if let Some(v) = numbers.into_iter().flatten().find(|v| !v.is_finite()) {
            return Err(AnalysisError::new(at(), format!("evaluates to {v}")));
        }
        out.push((m.key().into_owned(), value));
    }
    Ok(Metrics(out))
}

/// The `model` notes of the metrics `reqs` of a linear or (`nonlinear`) nonlinear run: how a
/// nonlinear `stroke_at_allowable` was found.
pub fn notes(reqs: &[MetricRequest], nonlinear: bool) -> Vec<String> {
    let stroke = reqs.iter().any(|m| m.kind == MetricKind::StrokeAtAllowable);
    if !(stroke && nonlinear) {
        return Vec::new();
    }
    vec![format!(
        "stroke_at_allowable: the load case scaled by s until the largest utilisation is 1 (|U - 1| <= {STROKE_TOL:e}), by a bracketed secant search on s from the linear estimate and the run's own point; each nonlinear solve continues the equilibrium path from the nearest converged stable state (the run's final state, then earlier solves) by load control in one step, cut as any step is, every state checked for equilibrium and stability"
    )]
}

/// `e` under the metric's path.
fn within(at: String, e: AnalysisError) -> AnalysisError {
    AnalysisError::new(at, format!("{}: {}", e.context, e.message))
}
