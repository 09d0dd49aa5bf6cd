//! `"metrics"` of a `static` case: named scalar results (stiffness, compliance, displacement,
//! hinge rotation, utilisation, stroke at the allowable stress, parasitic motion, natural
//! frequency, buckling margin) that the result lists under `"metrics": {"NAME": value}`.

mod check;

use crate::fem::Dof;
use serde::Deserialize;
use std::borrow::Cow;

pub use check::{check_fatigue_metrics, check_metrics};

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
    /// The displacement of `node` along `dof` (mm; degrees for rx, ry, rz) at which the load
    /// case, scaled, brings the largest utilisation to 1 — along the nonlinear path in
    /// nonlinear runs; `load_case` prescribes that DOF (global axes) or applies a force along
    /// it at the node (no `frame`/`axis`). Reports `{stroke, load, element, linear_estimate,
    /// utilisation, solves}`.
    StrokeAtAllowable,
    /// The motion of `node` along `dof` (mm; degrees for rx, ry, rz) in a `load_case` that
    /// drives other DOFs (it neither prescribes nor loads this one): the drift of a guided
    /// platform, along the nonlinear path in nonlinear runs.
    Parasitic,
    /// The displacement of `node` along `dof` (mm; degrees for rx, ry, rz) at which the load
    /// case, scaled, brings the largest hinge fatigue utilisation (the case's `"fatigue"`
    /// block: the load case as the peak of its load cycle) to 1; `load_case` drives that DOF as
    /// for `stroke_at_allowable`. Linear runs only (the utilisation is proportional to the
    /// scale). Reports `{stroke, load, element, ...}` like `stroke_at_allowable`.
    FatigueStroke,
    /// Natural frequency of mode `mode` (1 = the lowest) of the case's model with its
    /// supports, undeformed, Hz (the mass model of the `modal` analysis).
    Frequency,
    /// The first (smallest |λ|) linear buckling load factor of `load_case` as the reference
    /// load (the `buckling` analysis of that load case); negative: the reversed load buckles.
    BucklingMargin,
}

/// One entry of `"metrics"`.
#[derive(Debug, Clone, PartialEq, Deserialize, schemars::JsonSchema)]
#[serde(deny_unknown_fields)]
pub struct MetricRequest {
    /// Key of the value in the result's `metrics` (unique). Optional: by default the kind and
    /// its fields joined by `_`, e.g. `frequency_1`, `stiffness_8_ux`,
    /// `parasitic_8_uy_drive`.
    #[serde(default)]
    pub name: String,
    /// What it measures.
    pub kind: MetricKind,
    /// Node (stiffness, compliance, displacement, stroke_at_allowable, fatigue_stroke, parasitic).
    #[serde(default)]
    pub node: Option<usize>,
    /// `"ux"`, `"uy"`, `"uz"`, `"rx"`, `"ry"` or `"rz"`, global axes (stiffness, compliance,
    /// displacement, stroke_at_allowable, parasitic).
    #[serde(default)]
    pub dof: Option<String>,
    /// Name of a load case (displacement, hinge_rotation, max_utilisation,
    /// stroke_at_allowable, parasitic, buckling_margin).
    #[serde(default)]
    pub load_case: Option<String>,
    /// Index of a `hinge` element in `elements` (hinge_rotation).
    #[serde(default)]
    pub element: Option<usize>,
    /// Mode number, 1 = the lowest (frequency).
    #[serde(default)]
    #[schemars(range(min = 1))]
    pub mode: Option<usize>,
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
            MetricKind::FatigueStroke => "fatigue_stroke",
            MetricKind::Parasitic => "parasitic",
            MetricKind::Frequency => "frequency",
            MetricKind::BucklingMargin => "buckling_margin",
        }
    }

    /// Which of `node`, `dof`, `load_case`, `element`, `mode` the kind takes.
    fn fields(self) -> [bool; 5] {
        match self {
            MetricKind::Stiffness | MetricKind::Compliance => [true, true, false, false, false],
            MetricKind::Displacement
            | MetricKind::StrokeAtAllowable
            | MetricKind::FatigueStroke
            | MetricKind::Parasitic => [true, true, true, false, false],
            MetricKind::HingeRotation => [false, false, true, true, false],
            MetricKind::MaxUtilisation | MetricKind::BucklingMargin => [false, false, true, false, false],
            MetricKind::Frequency => [false, false, false, false, true],
        }
    }
}

impl MetricRequest {
    /// The DOF (validated by [`check_metrics`]).
    pub fn dof(&self) -> Option<Dof> {
        self.dof.as_deref().and_then(Dof::parse)
    }

    /// The key of the value: `name`, or [`MetricRequest::default_name`] when it is empty.
    pub fn key(&self) -> Cow<'_, str> {
        if self.name.is_empty() {
            Cow::Owned(self.default_name())
        } else {
            Cow::Borrowed(&self.name)
        }
    }

    /// The kind and the fields given, joined by `_`: `frequency_1`, `stiffness_8_ux`,
    /// `hinge_rotation_push_0`, `buckling_margin_push`.
    pub fn default_name(&self) -> String {
        let mut s = self.kind.name().to_string();
        let parts = [
            self.node.map(|n| n.to_string()),
            self.dof.clone(),
            self.load_case.clone(),
            self.element.map(|e| e.to_string()),
            self.mode.map(|m| m.to_string()),
        ];
        for p in parts.into_iter().flatten() {
            s.push('_');
            s.push_str(&p);
        }
        s
    }
}

/// Gives every metric without a name its [`MetricRequest::default_name`].
pub fn name_metrics(reqs: &mut [MetricRequest]) {
    for m in reqs.iter_mut().filter(|m| m.name.is_empty()) {
        m.name = m.default_name();
    }
}
