//! `"analysis": "prs_stiffness"`: Jacobian stiffness of a 3-PRS with compliant legs at chosen
//! poses and over a (ψ, θ) grid at fixed height, with the stiffness-limited workspace.
//!
//! The model, its sign and unit conventions are those of
//! [`crate::kinematics::prs_stiffness`]. Case files give angles in degrees; outputs give angles in
//! degrees, derivatives and stiffnesses per radian (K in N/mm, N and N·mm/rad).

use super::{AnalysisError, Files, Report, RunError};
use crate::case::error::{check, CaseError};
use crate::kinematics::prs_stiffness::{
    map, scaled_eigen, stiffness_limited, Branch, Grid, LegModel, Link, MapCell, MapMetric, PrsLayout, PrsStiffness,
    Screw, ScrewMount,
};
use crate::report::markdown::{sig, Table};
use nalgebra::{Vector3, Vector6};
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
    /// joint along the revolute axis, N/mm; empty = rigid).
    Chain {
        /// Actuation-chain stiffnesses, N/mm.
        actuation: Vec<f64>,
        /// Constraint-chain stiffnesses, N/mm.
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

fn metric_unit(s: &str) -> &'static str {
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
        check::positive(&format!("{path}[{j}]"), *k, "N/mm")?;
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
            check::finite(&format!("tool[{j}]"), *t)?;
        }
        for (i, p) in self.poses.iter().enumerate() {
            check::finite(&format!("poses[{i}].pz"), p.pz)?;
            check::within(&format!("poses[{i}].psi_deg"), p.psi_deg, -90.0, 90.0, "degrees")?;
            check::within(&format!("poses[{i}].theta_deg"), p.theta_deg, -90.0, 90.0, "degrees")?;
        }
        if let Some(l) = &self.load {
            for j in 0..3 {
                check::finite(&format!("load.force[{j}]"), l.force[j])?;
                check::finite(&format!("load.moment[{j}]"), l.moment[j])?;
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
                    check::within(&format!("{name}[{j}]"), *v, -90.0, 90.0, "degrees")?;
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

/// Eigen-decomposition in the result (length-scaled, N/mm).
#[derive(Debug, Clone, Serialize)]
pub struct EigenOut {
    /// ℓ, mm.
    pub length_mm: f64,
    /// Ascending eigenvalues, N/mm.
    pub values: Vec<f64>,
    /// Unit eigenvectors (one per value) in [δp (mm); ℓ·δα (mm)] coordinates.
    pub vectors: Vec<Vec<f64>>,
}

/// Deformation at the tool point.
#[derive(Debug, Clone, Serialize)]
pub struct DeformationOut {
    /// Applied wrench in the fixed frame [f (N); m (N·mm)].
    pub wrench_fixed: [f64; 6],
    /// Translation of the tool point, mm (fixed frame).
    pub translation_mm: [f64; 3],
    /// |translation|, mm.
    pub translation_norm_mm: f64,
    /// Rotation vector, degrees (fixed frame).
    pub rotation_deg: [f64; 3],
}

/// One pose's results.
#[derive(Debug, Clone, Serialize)]
pub struct PoseOut {
    /// Absolute height, mm.
    pub pz: f64,
    /// ψ, degrees.
    pub psi_deg: f64,
    /// θ, degrees.
    pub theta_deg: f64,
    /// Parasitic φ, degrees.
    pub phi_deg: f64,
    /// Parasitic pₓ, mm.
    pub px: f64,
    /// Parasitic p_y, mm.
    pub py: f64,
    /// Strokes from Aᵢ, mm.
    pub strokes: [f64; 3],
    /// Tool point in the fixed frame, mm.
    pub point: [f64; 3],
    /// ∂s/∂(p_z, ψ, θ) rows, mm/mm and mm/rad.
    pub jacobian: [[f64; 3]; 3],
    /// Wrench matrix G about the tool point (rows: f_x, f_y, f_z, m_x, m_y, m_z; columns:
    /// actuation 1–3, constraint 1–3).
    pub g: [[f64; 6]; 6],
    /// Leg compliances [c_a1, c_a2, c_a3, c_c1, c_c2, c_c3], mm/N.
    pub leg_compliance: [f64; 6],
    /// Stiffness about the tool point (N/mm, N, N·mm/rad); null when a leg is rigid.
    pub stiffness: Option<[[f64; 6]; 6]>,
    /// Compliance about the tool point (mm/N, rad/N, rad/(N·mm)).
    pub compliance: [[f64; 6]; 6],
    /// Directional stiffness 1/C_ii (N/mm, N·mm/rad); null where rigid.
    pub directional: [Option<f64>; 6],
    /// Stiffness on (p_z, ψ, θ): Jᵀ·diag(k_a)·J.
    pub independent: [[f64; 3]; 3],
    /// Length-scaled eigen-decomposition of the 3×3 `independent`.
    pub eigen_independent: EigenOut,
    /// Length-scaled eigen-decomposition of the 6×6 K; null when a leg is rigid.
    pub eigen: Option<EigenOut>,
    /// Deformation for the case's load.
    pub deformation: Option<DeformationOut>,
}

/// One map cell.
#[derive(Debug, Clone, Serialize)]
pub struct CellOut {
    /// ψ, degrees.
    pub psi_deg: f64,
    /// θ, degrees.
    pub theta_deg: f64,
    /// Reachable and non-singular.
    pub reachable: bool,
    /// Parasitic pₓ, mm (0 when unreachable).
    pub px: f64,
    /// Parasitic p_y, mm.
    pub py: f64,
    /// Parasitic φ, degrees.
    pub phi_deg: f64,
    /// Metric values (null when unreachable or unbounded).
    pub values: Vec<Option<f64>>,
    /// In the stiffness-limited workspace.
    pub in_workspace: Option<bool>,
}

/// Map results.
#[derive(Debug, Clone, Serialize)]
pub struct MapOut {
    /// Absolute height, mm.
    pub pz: f64,
    /// Points per axis.
    pub n: usize,
    /// Metric names.
    pub metrics: Vec<String>,
    /// Metric units.
    pub units: Vec<String>,
    /// Minimum and maximum of each metric over reachable cells (null if none).
    pub ranges: Vec<Option<[f64; 2]>>,
    /// Cells, ψ outer, θ inner.
    pub cells: Vec<CellOut>,
    /// Stiffness-limited workspace summary.
    pub workspace: Option<WorkspaceOut>,
}

/// Stiffness-limited workspace summary.
#[derive(Debug, Clone, Serialize)]
pub struct WorkspaceOut {
    /// Metric.
    pub metric: String,
    /// Threshold.
    pub threshold: f64,
    /// Fraction of the reachable cells kept.
    pub fraction: f64,
    /// Cells kept.
    pub cells: usize,
}

/// The `prs_stiffness` result.
#[derive(Debug, Clone, Serialize)]
pub struct PrsStiffnessResult {
    /// Moment convention, stated.
    pub conventions: String,
    /// Poses.
    pub poses: Vec<PoseOut>,
    /// Map.
    pub map: Option<MapOut>,
}

fn rows6(m: &nalgebra::Matrix6<f64>) -> [[f64; 6]; 6] {
    std::array::from_fn(|i| std::array::from_fn(|j| m[(i, j)]))
}
fn rows3(m: &nalgebra::Matrix3<f64>) -> [[f64; 3]; 3] {
    std::array::from_fn(|i| std::array::from_fn(|j| m[(i, j)]))
}
fn eig_out(e: crate::kinematics::prs_stiffness::ScaledEigen) -> EigenOut {
    EigenOut {
        length_mm: e.length,
        values: e.values,
        vectors: e.vectors,
    }
}

const CONVENTIONS: &str = "twists [v (mm); ω (rad)] of the tool point, wrenches [f (N); m (N·mm)] about the tool point with m = r × f (r from the tool point to the point of application), fixed frame; K = G·diag(k_a, k_c)·Gᵀ; eigenvalues of T·K·T with T = diag(1, 1, 1, 1/ℓ, 1/ℓ, 1/ℓ)";

/// Runs a case.
pub fn solve(case: &PrsStiffnessCase) -> Result<PrsStiffnessResult, RunError> {
    let v = case.validate()?;
    let tool = Vector3::from(case.tool);
    let ell = case.eigen_length;
    let mut poses = Vec::new();
    for (i, p) in case.poses.iter().enumerate() {
        let ps = v
            .model
            .at(p.pz, p.psi_deg.to_radians(), p.theta_deg.to_radians(), &tool)
            .map_err(|e| AnalysisError::new(format!("poses[{i}]"), e.to_string()))?;
        let st = &ps.state;
        let deformation = case.load.as_ref().map(|l| {
            let (f, m) = match l.frame {
                FrameSpec::Fixed => (Vector3::from(l.force), Vector3::from(l.moment)),
                FrameSpec::Platform => (st.r * Vector3::from(l.force), st.r * Vector3::from(l.moment)),
            };
            let w = Vector6::new(f[0], f[1], f[2], m[0], m[1], m[2]);
            let d = ps.deformation(&w);
            DeformationOut {
                wrench_fixed: w.into(),
                translation_mm: [d[0], d[1], d[2]],
                translation_norm_mm: d.fixed_rows::<3>(0).norm(),
                rotation_deg: [d[3].to_degrees(), d[4].to_degrees(), d[5].to_degrees()],
            }
        });
        poses.push(PoseOut {
            pz: p.pz,
            psi_deg: p.psi_deg,
            theta_deg: p.theta_deg,
            phi_deg: st.phi.to_degrees(),
            px: st.px,
            py: st.py,
            strokes: st.s,
            point: ps.point.into(),
            jacobian: rows3(&ps.jacobian),
            g: rows6(&ps.g),
            leg_compliance: ps.leg_compliance,
            stiffness: ps.stiffness.as_ref().map(rows6),
            compliance: rows6(&ps.compliance),
            directional: std::array::from_fn(|j| ps.directional(j)),
            independent: rows3(&ps.independent),
            eigen_independent: eig_out(scaled_eigen(&ps.independent, 1, ell)),
            eigen: ps.stiffness.as_ref().map(|k| eig_out(scaled_eigen(k, 3, ell))),
            deformation,
        });
    }
    let map_out = match &case.map {
        None => None,
        Some(mp) => {
            let grid = Grid {
                pz: mp.pz,
                psi: [mp.psi_deg[0].to_radians(), mp.psi_deg[1].to_radians()],
                theta: [mp.theta_deg[0].to_radians(), mp.theta_deg[1].to_radians()],
                n: mp.n,
            };
            let cells =
                map(&v.model, &grid, &tool, &v.metrics, ell).map_err(|e| AnalysisError::new("map", e.to_string()))?;
            if !cells.iter().any(|c| c.ok) {
                return Err(AnalysisError::new(
                    "map",
                    "no cell of the map is reachable and non-singular: check p_z and the angle ranges",
                )
                .into());
            }
            let ws = match (&mp.workspace, v.workspace) {
                (Some(w), Some(idx)) => {
                    let (mask, frac) = stiffness_limited(&cells, idx, w.threshold);
                    Some((w, mask, frac))
                }
                _ => None,
            };
            Some(map_result(mp, &cells, ws))
        }
    };
    Ok(PrsStiffnessResult {
        conventions: CONVENTIONS.into(),
        poses,
        map: map_out,
    })
}

fn map_result(mp: &MapSpec, cells: &[MapCell], ws: Option<(&WorkspaceSpec, Vec<bool>, f64)>) -> MapOut {
    let k = mp.metrics.len();
    let ranges = (0..k)
        .map(|j| {
            cells
                .iter()
                .filter_map(|c| c.values[j])
                .fold(None, |acc: Option<[f64; 2]>, v| {
                    Some(acc.map_or([v, v], |[lo, hi]| [lo.min(v), hi.max(v)]))
                })
        })
        .collect();
    let out_cells = cells
        .iter()
        .enumerate()
        .map(|(i, c)| CellOut {
            psi_deg: c.psi.to_degrees(),
            theta_deg: c.theta.to_degrees(),
            reachable: c.ok,
            px: c.px,
            py: c.py,
            phi_deg: c.phi.to_degrees(),
            values: c.values[..k].to_vec(),
            in_workspace: ws.as_ref().map(|w| w.1[i]),
        })
        .collect();
    MapOut {
        pz: mp.pz,
        n: mp.n,
        metrics: mp.metrics.clone(),
        units: mp.metrics.iter().map(|m| metric_unit(m).to_string()).collect(),
        ranges,
        cells: out_cells,
        workspace: ws.map(|(w, mask, frac)| WorkspaceOut {
            metric: w.metric.clone(),
            threshold: w.threshold,
            fraction: frac,
            cells: mask.iter().filter(|&&b| b).count(),
        }),
    }
}

fn opt(v: Option<f64>) -> String {
    v.map_or_else(|| "∞".into(), |x| sig(x, 6))
}

/// Markdown and CSV views.
pub fn report(r: &PrsStiffnessResult) -> Report {
    let mut md = String::from("# 3-PRS stiffness\n\n");
    md += &format!("Conventions: {}.\n\n", r.conventions);
    if !r.poses.is_empty() {
        let mut t = Table::new(&[
            "p_z (mm)",
            "ψ (°)",
            "θ (°)",
            "φ (°)",
            "pₓ (mm)",
            "p_y (mm)",
            "1/C_xx (N/mm)",
            "1/C_yy",
            "1/C_zz",
            "λ_min,3 (N/mm)",
            "λ_max,3 (N/mm)",
            "|δp| (mm)",
        ]);
        for p in &r.poses {
            t.row(vec![
                sig(p.pz, 6),
                sig(p.psi_deg, 6),
                sig(p.theta_deg, 6),
                sig(p.phi_deg, 6),
                sig(p.px, 6),
                sig(p.py, 6),
                opt(p.directional[0]),
                opt(p.directional[1]),
                opt(p.directional[2]),
                sig(p.eigen_independent.values[0], 6),
                sig(p.eigen_independent.values[2], 6),
                p.deformation
                    .as_ref()
                    .map_or("—".into(), |d| sig(d.translation_norm_mm, 6)),
            ]);
        }
        md += "## Poses\n\n";
        md += &t.render();
        md += "\n";
    }
    let mut csv = String::new();
    if let Some(m) = &r.map {
        md += &format!("## Map at p_z = {} mm, {}×{} cells\n\n", m.pz, m.n, m.n);
        let mut t = Table::new(&["metric", "unit", "min", "max"]);
        for (j, name) in m.metrics.iter().enumerate() {
            let (lo, hi) = m.ranges[j].map_or(("—".into(), "—".into()), |[a, b]| (sig(a, 6), sig(b, 6)));
            t.row(vec![name.clone(), m.units[j].clone(), lo, hi]);
        }
        md += &t.render();
        if let Some(w) = &m.workspace {
            md += &format!(
                "\nStiffness-limited workspace: {} > {} keeps {} cells ({:.1} % of the reachable ones).\n",
                w.metric,
                w.threshold,
                w.cells,
                100.0 * w.fraction
            );
        }
        csv += "psi_deg,theta_deg,reachable,px_mm,py_mm,phi_deg";
        for name in &m.metrics {
            csv += &format!(",{name}");
        }
        if m.workspace.is_some() {
            csv += ",in_workspace";
        }
        csv += "\n";
        for c in &m.cells {
            csv += &format!(
                "{},{},{},{},{},{}",
                c.psi_deg, c.theta_deg, c.reachable, c.px, c.py, c.phi_deg
            );
            for v in &c.values {
                csv += &format!(",{}", v.map_or(String::new(), |x| x.to_string()));
            }
            if let Some(b) = c.in_workspace {
                csv += &format!(",{b}");
            }
            csv += "\n";
        }
    } else {
        csv += "pz_mm,psi_deg,theta_deg,phi_deg,px_mm,py_mm,s1_mm,s2_mm,s3_mm,lambda_min_indep,lambda_max_indep\n";
        for p in &r.poses {
            csv += &format!(
                "{},{},{},{},{},{},{},{},{},{},{}\n",
                p.pz,
                p.psi_deg,
                p.theta_deg,
                p.phi_deg,
                p.px,
                p.py,
                p.strokes[0],
                p.strokes[1],
                p.strokes[2],
                p.eigen_independent.values[0],
                p.eigen_independent.values[2]
            );
        }
    }
    Report { markdown: md, csv }
}

/// SVG heat maps of each metric over (ψ, θ) and over the parasitic (pₓ, p_y).
pub fn files(r: &PrsStiffnessResult) -> Files {
    let mut out = Files::new();
    let Some(m) = &r.map else { return out };
    for (j, name) in m.metrics.iter().enumerate() {
        let label = format!("{name} ({})", m.units[j]);
        let pts = |par: bool| -> Vec<(f64, f64, f64, bool)> {
            m.cells
                .iter()
                .filter_map(|c| {
                    c.values[j].map(|v| {
                        let (x, y) = if par { (c.px, c.py) } else { (c.psi_deg, c.theta_deg) };
                        (x, y, v, c.in_workspace.unwrap_or(true))
                    })
                })
                .collect()
        };
        let title = format!("{name} at p_z = {} mm", m.pz);
        out.push((
            format!("prs_stiffness_{name}.svg"),
            crate::report::svg::scatter_coloured(&title, "ψ (°)", "θ (°)", &pts(false), &label, None).into_bytes(),
        ));
        out.push((
            format!("prs_stiffness_{name}_parasitic.svg"),
            crate::report::svg::scatter_coloured(&title, "pₓ (mm)", "p_y (mm)", &pts(true), &label, None).into_bytes(),
        ));
    }
    out
}
