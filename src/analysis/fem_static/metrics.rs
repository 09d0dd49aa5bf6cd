//! The `"metrics"` of a `static` result: the named scalars a case asks for
//! ([`crate::case::mesh::MetricRequest`]), evaluated from the solved load cases and, for
//! stiffness and compliance, the node compliance with the model's supports.

use super::{AnalysisError, StaticResult};
use crate::case::mesh::{MetricKind, MetricRequest};
use crate::fem::{self, Model};
use serde::ser::SerializeMap;

/// Where a load case, scaled, brings the largest utilisation to 1 (`stroke_at_allowable`).
#[derive(Debug, Clone, Copy, PartialEq, serde::Serialize)]
pub struct StrokeAtAllowable {
    /// Displacement of the node along the DOF, mm (degrees for rx, ry, rz).
    pub stroke: f64,
    /// The load there: the reaction of the prescribed DOF, or the applied force, N (N·mm).
    pub load: f64,
    /// Index in the case's `elements` of the element that reaches its allowable first.
    pub element: usize,
    /// The linear estimate of `stroke` (the load case scaled by 1 / its utilisation), mm (degrees).
    pub linear_estimate: f64,
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
    /// The number of a scalar metric (`None` for a stroke or a `null`).
    pub fn number(&self) -> Option<f64> {
        match self {
            MetricValue::Number(v) => *v,
            MetricValue::Stroke(_) => None,
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

/// Evaluates `reqs` (validated when the case was parsed, against `spec`) on the result `r` of `model`.
pub fn evaluate(
    model: &Model,
    spec: &crate::case::mesh::MeshSpec,
    reqs: &[MetricRequest],
    r: &StaticResult,
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
            MetricKind::Displacement => {
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
                let lc = spec.load_cases.iter().find(|l| l.name == c.name).ok_or_else(missing)?;
                match c.max_utilisation.as_ref().filter(|u| u.value > 0.0) {
                    None => MetricValue::Number(None),
                    Some(u) => {
                        let d = c.displacements.get(node).ok_or_else(missing)?[dof.index()];
                        let prescribed = lc.displacements.iter().any(|p| p.node == node && p.dof.dof() == dof);
                        let load = if prescribed {
                            let k = c.reaction_nodes.iter().position(|&n| n == node).ok_or_else(missing)?;
                            c.reactions[k][dof.index()]
                        } else {
                            lc.forces
                                .iter()
                                .filter(|f| f.node == node)
                                .map(|f| f.f[dof.index()])
                                .sum()
                        };
                        let stroke = d / u.value;
                        MetricValue::Stroke(StrokeAtAllowable {
                            stroke,
                            load: load / u.value,
                            element: u.element,
                            linear_estimate: stroke,
                        })
                    }
                }
            }
        };
        let numbers = match value {
            MetricValue::Number(v) => [v, None, None],
            MetricValue::Stroke(s) => [Some(s.stroke), Some(s.load), Some(s.linear_estimate)],
        };
        if let Some(v) = numbers.into_iter().flatten().find(|v| !v.is_finite()) {
            return Err(AnalysisError::new(at(), format!("evaluates to {v}")));
        }
        out.push((m.name.clone(), value));
    }
    Ok(Metrics(out))
}
