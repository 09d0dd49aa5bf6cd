//! The `prs_stiffness` case: Jacobian stiffness of a 3-PRS with compliant legs (see
//! [`crate::kinematics::prs_stiffness`] for the model and its conventions). Angles in degrees.

use super::error::{check, CaseError};
use crate::kinematics::prs_stiffness::{Branch, LegModel, Link, MapMetric, PrsLayout, PrsStiffness, Screw, ScrewMount};
use serde::{Deserialize, Serialize};

/// The `prs_stiffness` case.
#[derive(Debug, Clone, Deserialize, schemars::JsonSchema)]
#[serde(deny_unknown_fields)]
pub struct PrsStiffnessCase {
    /// 3-PRS geometry.
    pub mechanism: LayoutSpec,
    /// Per-leg stiffness model (all three legs alike).
    pub legs: LegSpec,
    /// Characteristic length ℓ (mm) of the eigenvalues of the mixed stiffness matrix: rotations
    /// are scaled to ℓ·δα. Default 1000 mm (SI: metres of arc per radian).
    #[serde(default = "default_length")]
    pub eigen_length: f64,
    /// Reference (tool) point in the platform frame {u, v, w} relative to P, mm. Default P.
    #[serde(default)]
    pub tool: [f64; 3],
    /// Poses to report in full.
    #[serde(default)]
    pub poses: Vec<PoseSpec>,
    /// Load wrench applied at the tool point, for the deformation twist of each pose.
    #[serde(default)]
    pub load: Option<LoadSpec>,
    /// A (ψ, θ) map at fixed height.
    #[serde(default)]
    pub map: Option<MapSpec>,
}

fn default_length() -> f64 {
    1000.0
}

/// Geometry: absolute heights, strokes from the zero-stroke points Aᵢ.
#[derive(Debug, Clone, Deserialize, schemars::JsonSchema)]
#[serde(deny_unknown_fields)]
pub struct LayoutSpec {
    /// Base radius a (O to the zero-stroke slider points Aᵢ), mm.
    pub a: f64,
    /// Platform radius b (P to the spherical joints), mm.
    pub b: f64,
    /// Leg length L (revolute to spherical joint), mm.
    #[serde(rename = "L")]
    pub l: f64,
    /// Actuator inclination γ, degrees in [−90, 90]: 0 horizontal inward, 90 vertical up,
    /// negative inward-down.
    pub gamma_deg: f64,
    /// IKP branch: "minus" (leg along +e from C to B, the usual one) or "plus".
    #[serde(default)]
    pub branch: BranchSpec,
}

/// IKP branch.
#[derive(Debug, Clone, Copy, Default, Deserialize, Serialize, schemars::JsonSchema)]
#[serde(rename_all = "snake_case")]
pub enum BranchSpec {
    /// sᵢ = eᵢ·Dᵢ − √disc.
    #[default]
    Minus,
    /// sᵢ = eᵢ·Dᵢ + √disc.
    Plus,
}

/// Per-leg stiffness model.
#[derive(Debug, Clone, Deserialize, schemars::JsonSchema)]
#[serde(tag = "model", rename_all = "snake_case", deny_unknown_fields)]
pub enum LegSpec {
    /// One actuator stiffness on the stroke, N/mm; constraint directions rigid.
    Actuator {
        /// k, N/mm.
        k: f64,
    },
    /// Series chains: actuation (on the stroke, N/mm) and constraint (lateral at the spherical
    /// joint along the revolute axis, N/mm; empty = rigid). Every leg has the same chains; a
    /// list holds the springs in series of one chain (any number), not one value per leg.
    Chain {
        /// Actuation-chain stiffnesses in series (carriage, revolute, limb …), N/mm.
        actuation: Vec<f64>,
        /// Constraint-chain stiffnesses in series, N/mm.
        #[serde(default)]
        constraint: Vec<f64>,
    },
    /// Lead screw + link.
    ScrewLink {
        /// The screw.
        screw: ScrewSpec,
        /// The link.
        link: LinkSpec,
    },
}

/// Lead screw.
#[derive(Debug, Clone, Deserialize, schemars::JsonSchema)]
#[serde(deny_unknown_fields)]
pub struct ScrewSpec {
    /// Cross-section area, mm².
    pub area: f64,
    /// Young's modulus, MPa.
    #[serde(rename = "E")]
    pub e: f64,
    /// "fixed_free" or "fixed_fixed".
    pub mount: MountSpec,
    /// Bearing distance for fixed–fixed, mm.
    #[serde(default)]
    pub length: Option<f64>,
    /// Distance from the (first) fixed bearing to the nut at zero stroke, mm.
    pub nut_at_zero_stroke: f64,
    /// Nut axial stiffness, N/mm (omit for a rigid nut).
    #[serde(default)]
    pub nut_k: Option<f64>,
}

/// Screw mounting.
#[derive(Debug, Clone, Copy, Deserialize, Serialize, schemars::JsonSchema)]
#[serde(rename_all = "snake_case")]
pub enum MountSpec {
    /// Fixed–free (or fixed–supported).
    FixedFree,
    /// Fixed–fixed.
    FixedFixed,
}

/// Link.
#[derive(Debug, Clone, Deserialize, schemars::JsonSchema)]
#[serde(deny_unknown_fields)]
pub struct LinkSpec {
    /// Cross-section area, mm².
    pub area: f64,
    /// Young's modulus, MPa.
    #[serde(rename = "E")]
    pub e: f64,
    /// Second moment of area for bending out of the leg plane, mm⁴.
    #[serde(rename = "I_lateral")]
    pub i_lateral: f64,
}

/// One pose.
#[derive(Debug, Clone, Deserialize, schemars::JsonSchema)]
#[serde(deny_unknown_fields)]
pub struct PoseSpec {
    /// Absolute height of the platform centre above the plane of the Aᵢ, mm.
    pub pz: f64,
    /// ψ (about x), degrees.
    pub psi_deg: f64,
    /// θ (about y), degrees.
    pub theta_deg: f64,
}

/// Load wrench at the tool point.
#[derive(Debug, Clone, Deserialize, schemars::JsonSchema)]
#[serde(deny_unknown_fields)]
pub struct LoadSpec {
    /// Force, N.
    pub force: [f64; 3],
    /// Moment about the tool point, N·mm.
    #[serde(default)]
    pub moment: [f64; 3],
    /// Frame of the components: "fixed" (default) or "platform".
    #[serde(default)]
    pub frame: FrameSpec,
}

/// Frame of load components.
#[derive(Debug, Clone, Copy, Default, Deserialize, Serialize, schemars::JsonSchema)]
#[serde(rename_all = "snake_case")]
pub enum FrameSpec {
    /// Fixed frame {x, y, z}.
    #[default]
    Fixed,
    /// Platform frame {u, v, w}.
    Platform,
}

/// A (ψ, θ) map at fixed height.
#[derive(Debug, Clone, Deserialize, schemars::JsonSchema)]
#[serde(deny_unknown_fields)]
pub struct MapSpec {
    /// Absolute platform height, mm.
    pub pz: f64,
    /// ψ range, degrees.
    pub psi_deg: [f64; 2],
    /// θ range, degrees.
    pub theta_deg: [f64; 2],
    /// Points per axis, 2 to 401.
    pub n: usize,
    /// Metrics: `K_x`…`K_rz` (diagonal of K), `dir_x`…`dir_rz` (1/C_ii), `lambda_min`,
    /// `lambda_max` (6×6, length-scaled), `lambda_min_independent`, `lambda_max_independent`
    /// (3×3 on p_z, ψ, θ). 1 to 8 of them.
    pub metrics: Vec<String>,
    /// Stiffness-limited workspace: cells whose `metric` exceeds `threshold`.
    #[serde(default)]
    pub workspace: Option<WorkspaceSpec>,
}

/// Stiffness-limited workspace.
#[derive(Debug, Clone, Deserialize, schemars::JsonSchema)]
#[serde(deny_unknown_fields)]
pub struct WorkspaceSpec {
    /// One of the map's metrics.
    pub metric: String,
    /// Threshold, in the metric's unit.
    pub threshold: f64,
}

const AXES: [&str; 6] = ["x", "y", "z", "rx", "ry", "rz"];

fn parse_metric(s: &str) -> Option<MapMetric> {
    if let Some(ax) = s.strip_prefix("K_") {
        return AXES.iter().position(|a| *a == ax).map(MapMetric::Diagonal);
    }
    if let Some(ax) = s.strip_prefix("dir_") {
        return AXES.iter().position(|a| *a == ax).map(MapMetric::Directional);
    }
    match s {
        "lambda_min" => Some(MapMetric::LambdaMin),
        "lambda_max" => Some(MapMetric::LambdaMax),
        "lambda_min_independent" => Some(MapMetric::IndependentLambdaMin),
        "lambda_max_independent" => Some(MapMetric::IndependentLambdaMax),
        _ => None,
    }
}

/// The unit of a map metric.
pub fn metric_unit(s: &str) -> &'static str {
    match s {
        "K_rx" | "K_ry" | "K_rz" | "dir_rx" | "dir_ry" | "dir_rz" => "N·mm/rad",
        _ => "N/mm",
    }
}

/// The validated model of a case.
pub struct Validated {
    /// The stiffness model.
    pub model: PrsStiffness,
    /// Map metrics.
    pub metrics: Vec<MapMetric>,
    /// Index of the workspace metric in `metrics`.
    pub workspace: Option<usize>,
}

fn positive_list(path: &str, v: &[f64]) -> Result<(), CaseError> {
    for (j, k) in v.iter().enumerate() {
        check::positive(format_args!("{path}[{j}]"), *k, "N/mm")?;
    }
    Ok(())
}

impl PrsStiffnessCase {
    /// Validates everything before solving.
    pub fn validate(&self) -> Result<Validated, CaseError> {
        let m = &self.mechanism;
        check::positive("mechanism.a", m.a, "mm")?;
        check::positive("mechanism.b", m.b, "mm")?;
        check::positive("mechanism.L", m.l, "mm")?;
        check::within("mechanism.gamma_deg", m.gamma_deg, -90.0, 90.0, "degrees")?;
        let branch = match m.branch {
            BranchSpec::Minus => Branch::Minus,
            BranchSpec::Plus => Branch::Plus,
        };
        let layout = PrsLayout::new(m.a, m.b, m.l, m.gamma_deg.to_radians(), branch)
            .map_err(|e| CaseError::new("mechanism", e.to_string()))?;
        let leg = match &self.legs {
            LegSpec::Actuator { k } => {
                check::positive("legs.k", *k, "N/mm")?;
                LegModel::Actuator { k: *k }
            }
            LegSpec::Chain { actuation, constraint } => {
                if actuation.is_empty() {
                    return Err(CaseError::value(
                        "legs.actuation",
                        "[]",
                        "needs at least one stiffness (N/mm)",
                    ));
                }
                positive_list("legs.actuation", actuation)?;
                positive_list("legs.constraint", constraint)?;
                LegModel::Chain {
                    actuation: actuation.clone(),
                    constraint: constraint.clone(),
                }
            }
            LegSpec::ScrewLink { screw, link } => {
                check::positive("legs.screw.area", screw.area, "mm²")?;
                check::positive("legs.screw.E", screw.e, "MPa")?;
                check::finite("legs.screw.nut_at_zero_stroke", screw.nut_at_zero_stroke)?;
                if let Some(k) = screw.nut_k {
                    check::positive("legs.screw.nut_k", k, "N/mm")?;
                }
                let mount = match (screw.mount, screw.length) {
                    (MountSpec::FixedFree, None) => ScrewMount::FixedFree {
                        nut_at_zero_stroke: screw.nut_at_zero_stroke,
                    },
                    (MountSpec::FixedFree, Some(l)) => {
                        return Err(CaseError::value(
                            "legs.screw.length",
                            l,
                            "only a fixed_fixed screw has a bearing distance; omit it",
                        ))
                    }
                    (MountSpec::FixedFixed, Some(l)) => {
                        check::positive("legs.screw.length", l, "mm")?;
                        ScrewMount::FixedFixed {
                            length: l,
                            nut_at_zero_stroke: screw.nut_at_zero_stroke,
                        }
                    }
                    (MountSpec::FixedFixed, None) => {
                        return Err(CaseError::new(
                            "legs.screw.length",
                            "missing: a fixed_fixed screw needs the bearing distance (mm)",
                        ))
                    }
                };
                check::positive("legs.link.area", link.area, "mm²")?;
                check::positive("legs.link.E", link.e, "MPa")?;
                check::positive("legs.link.I_lateral", link.i_lateral, "mm⁴")?;
                LegModel::ScrewLink {
                    screw: Screw {
                        area: screw.area,
                        e: screw.e,
                        mount,
                        nut_k: screw.nut_k,
                    },
                    link: Link {
                        area: link.area,
                        e: link.e,
                        i_lateral: link.i_lateral,
                    },
                }
            }
        };
        check::positive("eigen_length", self.eigen_length, "mm")?;
        for (j, t) in self.tool.iter().enumerate() {
            check::finite(format_args!("tool[{j}]"), *t)?;
        }
        for (i, p) in self.poses.iter().enumerate() {
            check::finite(format_args!("poses[{i}].pz"), p.pz)?;
            check::within(format_args!("poses[{i}].psi_deg"), p.psi_deg, -90.0, 90.0, "degrees")?;
            check::within(
                format_args!("poses[{i}].theta_deg"),
                p.theta_deg,
                -90.0,
                90.0,
                "degrees",
            )?;
        }
        if let Some(l) = &self.load {
            for j in 0..3 {
                check::finite(format_args!("load.force[{j}]"), l.force[j])?;
                check::finite(format_args!("load.moment[{j}]"), l.moment[j])?;
            }
        }
        if self.poses.is_empty() && self.map.is_none() {
            return Err(CaseError::new(".", "nothing to compute: give `poses`, `map` or both"));
        }
        let mut metrics = Vec::new();
        let mut workspace = None;
        if let Some(mp) = &self.map {
            check::finite("map.pz", mp.pz)?;
            check::range("map.psi_deg", mp.psi_deg)?;
            check::range("map.theta_deg", mp.theta_deg)?;
            for (name, r) in [("map.psi_deg", mp.psi_deg), ("map.theta_deg", mp.theta_deg)] {
                for (j, v) in r.iter().enumerate() {
                    check::within(format_args!("{name}[{j}]"), *v, -90.0, 90.0, "degrees")?;
                }
            }
            if !(2..=401).contains(&mp.n) {
                return Err(CaseError::value("map.n", mp.n, "must be 2 to 401 points per axis"));
            }
            if mp.metrics.is_empty() || mp.metrics.len() > 8 {
                return Err(CaseError::value("map.metrics", mp.metrics.len(), "give 1 to 8 metrics"));
            }
            for (j, s) in mp.metrics.iter().enumerate() {
                metrics.push(parse_metric(s).ok_or_else(|| {
                    CaseError::value(
                        format!("map.metrics[{j}]"),
                        format!("\"{s}\""),
                        "must be K_x, K_y, K_z, K_rx, K_ry, K_rz, dir_x … dir_rz, lambda_min, lambda_max, lambda_min_independent or lambda_max_independent",
                    )
                })?);
            }
            if let Some(w) = &mp.workspace {
                let idx = mp.metrics.iter().position(|m| *m == w.metric).ok_or_else(|| {
                    CaseError::value(
                        "map.workspace.metric",
                        format!("\"{}\"", w.metric),
                        format!("must be one of the map's metrics ({})", mp.metrics.join(", ")),
                    )
                })?;
                check::finite("map.workspace.threshold", w.threshold)?;
                workspace = Some(idx);
            }
        }
        let model = PrsStiffness::new(layout, leg).map_err(|e| CaseError::new("legs", e.to_string()))?;
        Ok(Validated {
            model,
            metrics,
            workspace,
        })
    }
}
