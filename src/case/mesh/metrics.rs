//! `"metrics"` of a `static` case: named scalar results (stiffness, compliance, displacement,
//! hinge rotation, utilisation) that the result lists under `"metrics": {"NAME": value}`.

use super::shapes::{ElementSpec, MeshSpec};
use crate::case::error::CaseError;
use crate::fem::Dof;
use serde::Deserialize;

/// What a metric measures.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Deserialize, schemars::JsonSchema)]
#[serde(rename_all = "snake_case")]
pub enum MetricKind {
    /// 1 / the diagonal term of the node's 6×6 compliance along `dof` with the case's supports
    /// (undeformed): N/mm for ux, uy, uz; N·mm/rad for rx, ry, rz. Needs `node`, `dof`.
    Stiffness,
    /// The diagonal term of the node's compliance along `dof`: mm/N; rad/(N·mm). Needs `node`, `dof`.
    Compliance,
    /// Displacement of `node` along `dof` in `load_case`: mm; degrees for rx, ry, rz.
    Displacement,
    /// Rotation of the `hinge` element `element` (index in the case's `elements`) about its
    /// compliant axis in `load_case`, degrees.
    HingeRotation,
    /// The largest von Mises / allowable over the stressed elements in `load_case`.
    MaxUtilisation,
    /// Linear runs: the displacement of `node` along `dof` at which the load case, scaled,
    /// brings the largest utilisation to 1; `load_case` prescribes that DOF (global axes) or
    /// applies a force along it at the node (no `frame`/`axis`).
    StrokeAtAllowable,
}

/// One entry of `"metrics"`.
#[derive(Debug, Clone, PartialEq, Deserialize, schemars::JsonSchema)]
#[serde(deny_unknown_fields)]
pub struct MetricRequest {
    /// Key of the value in the result's `metrics` (unique, non-empty).
    pub name: String,
    /// What it measures.
    pub kind: MetricKind,
    /// Node (stiffness, compliance, displacement).
    #[serde(default)]
    pub node: Option<usize>,
    /// `"ux"`, `"uy"`, `"uz"`, `"rx"`, `"ry"` or `"rz"`, global axes (stiffness, compliance, displacement).
    #[serde(default)]
    pub dof: Option<String>,
    /// Name of a load case (displacement, hinge_rotation, max_utilisation).
    #[serde(default)]
    pub load_case: Option<String>,
    /// Index of a `hinge` element in `elements` (hinge_rotation).
    #[serde(default)]
    pub element: Option<usize>,
}

impl MetricKind {
    /// The case-file name.
    pub fn name(self) -> &'static str {
        match self {
            MetricKind::Stiffness => "stiffness",
            MetricKind::Compliance => "compliance",
            MetricKind::Displacement => "displacement",
            MetricKind::HingeRotation => "hinge_rotation",
            MetricKind::MaxUtilisation => "max_utilisation",
            MetricKind::StrokeAtAllowable => "stroke_at_allowable",
        }
    }

    /// Which of `node`, `dof`, `load_case`, `element` the kind takes.
    fn fields(self) -> [bool; 4] {
        match self {
            MetricKind::Stiffness | MetricKind::Compliance => [true, true, false, false],
            MetricKind::Displacement | MetricKind::StrokeAtAllowable => [true, true, true, false],
            MetricKind::HingeRotation => [false, false, true, true],
            MetricKind::MaxUtilisation => [false, false, true, false],
        }
    }
}

impl MetricRequest {
    /// The DOF (validated by [`check_metrics`]).
    pub fn dof(&self) -> Option<Dof> {
        self.dof.as_deref().and_then(Dof::parse)
    }
}

/// Validates `"metrics"` against the model (paths `metrics[i].…`): unique non-empty names, the
/// fields each kind needs (and no others), nodes, DOFs, load cases and hinge elements that exist.
pub fn check_metrics(reqs: &[MetricRequest], model: &MeshSpec, nonlinear: bool) -> Result<(), CaseError> {
    for (i, m) in reqs.iter().enumerate() {
        let at = |f: &str| format!("metrics[{i}].{f}");
        if m.name.is_empty() {
            return Err(CaseError::new(at("name"), "must not be empty"));
        }
        if let Some(j) = reqs[..i].iter().position(|o| o.name == m.name) {
            return Err(CaseError::value(
                at("name"),
                format!("\"{}\"", m.name),
                format!("metrics[{j}] has the same name; metric names must be unique"),
            ));
        }
        let given = [
            m.node.is_some(),
            m.dof.is_some(),
            m.load_case.is_some(),
            m.element.is_some(),
        ];
        for (k, field) in ["node", "dof", "load_case", "element"].into_iter().enumerate() {
            let kind = m.kind.name();
            match (m.kind.fields()[k], given[k]) {
                (true, false) => return Err(CaseError::new(at(field), format!("is required by kind \"{kind}\""))),
                (false, true) => return Err(CaseError::new(at(field), format!("is not used by kind \"{kind}\""))),
                _ => {}
            }
        }
        if let Some(n) = m.node {
            if n >= model.nodes.len() {
                let rule = format!("must be a node index below {}", model.nodes.len());
                return Err(CaseError::value(at("node"), n, rule));
            }
        }
        if let Some(d) = &m.dof {
            if Dof::parse(d).is_none() {
                return Err(CaseError::value(
                    at("dof"),
                    format!("\"{d}\""),
                    "must be one of ux, uy, uz, rx, ry, rz",
                ));
            }
        }
        if let Some(lc) = &m.load_case {
            if !model.load_cases.iter().any(|c| &c.name == lc) {
                let names: Vec<&str> = model.load_cases.iter().map(|c| c.name.as_str()).collect();
                let rule = format!("must name a load case: {}", names.join(", "));
                return Err(CaseError::value(at("load_case"), format!("\"{lc}\""), rule));
            }
        }
        if m.kind == MetricKind::StrokeAtAllowable {
            check_stroke(m, model, nonlinear).map_err(|e| e.under(&format!("metrics[{i}]")))?;
        }
        if let Some(e) = m.element {
            if !matches!(model.elements.get(e), Some(ElementSpec::Hinge { .. })) {
                return Err(CaseError::value(
                    at("element"),
                    e,
                    "must be the index of a hinge element in elements",
                ));
            }
        }
    }
    Ok(())
}

/// A `stroke_at_allowable` request: a linear run, and a load case that drives `node` along `dof`
/// (a prescribed displacement or a force component, both in global axes).
fn check_stroke(m: &MetricRequest, model: &MeshSpec, nonlinear: bool) -> Result<(), CaseError> {
    if nonlinear {
        return Err(CaseError::new(
            "kind",
            "\"stroke_at_allowable\" is evaluated in linear runs only (the stop at utilisation 1 along a nonlinear path is not available): remove \"nonlinear\": true",
        ));
    }
    let (Some(node), Some(dof), Some(name)) = (m.node, m.dof(), m.load_case.as_deref()) else {
        return Ok(());
    };
    let Some(lc) = model.load_cases.iter().find(|c| c.name == name) else {
        return Ok(());
    };
    let prescribed = lc
        .displacements
        .iter()
        .any(|d| d.node == node && d.dof.dof() == dof && d.frame.is_none() && d.axis.is_none() && d.value != 0.0);
    let forced = lc
        .forces
        .iter()
        .any(|f| f.node == node && f.frame.is_none() && f.axis.is_none() && f.f[dof.index()] != 0.0);
    if prescribed || forced {
        return Ok(());
    }
    Err(CaseError::value(
        "load_case",
        format!("\"{name}\""),
        format!("must prescribe a non-zero {dof} of node {node} or apply a force (moment) along it there, in global axes (no frame or axis)"),
    ))
}
