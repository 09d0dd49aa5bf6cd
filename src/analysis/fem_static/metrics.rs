//! The `"metrics"` of a `static` result: the named scalars a case asks for
//! ([`crate::case::mesh::MetricRequest`]), evaluated from the solved load cases and, for
//! stiffness and compliance, the node compliance with the model's supports.

use super::{AnalysisError, StaticResult};
use crate::case::mesh::{MetricKind, MetricRequest};
use crate::fem::{self, Model};
use serde::ser::SerializeMap;

/// Named metric values in the order the case lists them (`null`: unbounded or undefined — a
/// stiffness along a supported DOF, a utilisation without any allowable stress).
#[derive(Debug, Clone, Default, PartialEq)]
pub struct Metrics(pub Vec<(String, Option<f64>)>);

impl Metrics {
    /// No metric was asked for.
    pub fn is_empty(&self) -> bool {
        self.0.is_empty()
    }

    /// The value named `name`.
    pub fn get(&self, name: &str) -> Option<Option<f64>> {
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

/// Evaluates `reqs` (validated when the case was parsed) on the result `r` of `model`.
pub fn evaluate(model: &Model, reqs: &[MetricRequest], r: &StaticResult) -> Result<Metrics, AnalysisError> {
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
                match m.kind {
                    MetricKind::Compliance => Some(c),
                    _ => (c > 0.0).then(|| 1.0 / c),
                }
            }
            MetricKind::Displacement => {
                let (node, dof) = node_dof()?;
                let d = case()?.displacements.get(node).ok_or_else(missing)?;
                Some(d[dof.index()])
            }
            MetricKind::HingeRotation => {
                let h = case()?.hinges.iter().find(|h| Some(h.element) == m.element);
                Some(h.ok_or_else(missing)?.rotation_deg)
            }
            MetricKind::MaxUtilisation => case()?.max_utilisation.as_ref().map(|u| u.value),
        };
        if let Some(v) = value.filter(|v| !v.is_finite()) {
            return Err(AnalysisError::new(at(), format!("evaluates to {v}")));
        }
        out.push((m.name.clone(), value));
    }
    Ok(Metrics(out))
}
