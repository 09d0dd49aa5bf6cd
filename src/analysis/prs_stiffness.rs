//! `"analysis": "prs_stiffness"`: Jacobian stiffness of a 3-PRS with compliant legs at chosen
//! poses and over a (ψ, θ) grid at fixed height, with the stiffness-limited workspace.
//!
//! The model, its sign and unit conventions are those of
//! [`crate::kinematics::prs_stiffness`]. Case files give angles in degrees; outputs give angles in
//! degrees, derivatives and stiffnesses per radian (K in N/mm, N and N·mm/rad).

use super::kind::{Analysis, Ctx};
use super::{AnalysisError, Files, Report, RunError};
use crate::case::prs_stiffness::{metric_unit, FrameSpec, MapSpec, PrsStiffnessCase, WorkspaceSpec};
use crate::case::CaseError;
use crate::kinematics::prs_stiffness::{map, scaled_eigen, stiffness_limited, Grid, MapCell};
use crate::report::markdown::{sig, Table};
use nalgebra::{Vector3, Vector6};
use serde::Serialize;

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
    /// Stiffness about the tool point (N/mm, N, N·mm/rad); absent when a leg is rigid.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub stiffness: Option<[[f64; 6]; 6]>,
    /// Compliance about the tool point (mm/N, rad/N, rad/(N·mm)).
    pub compliance: [[f64; 6]; 6],
    /// Directional stiffness 1/C_ii (N/mm, N·mm/rad); "unbounded" where rigid.
    #[serde(serialize_with = "unbounded_list")]
    pub directional: [Option<f64>; 6],
    /// Stiffness on (p_z, ψ, θ): Jᵀ·diag(k_a)·J.
    pub independent: [[f64; 3]; 3],
    /// Length-scaled eigen-decomposition of the 3×3 `independent`.
    pub eigen_independent: EigenOut,
    /// Length-scaled eigen-decomposition of the 6×6 K; absent when a leg is rigid.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub eigen: Option<EigenOut>,
    /// Deformation for the case's load.
    #[serde(skip_serializing_if = "Option::is_none")]
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
    /// Metric values (empty when unreachable, "unbounded" where a rigid leg makes it infinite).
    #[serde(serialize_with = "unbounded_list")]
    pub values: Vec<Option<f64>>,
    /// In the stiffness-limited workspace.
    #[serde(skip_serializing_if = "Option::is_none")]
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
    /// Minimum and maximum of each metric over reachable cells ("unbounded" if no cell has a finite value).
    #[serde(serialize_with = "unbounded_list")]
    pub ranges: Vec<Option<[f64; 2]>>,
    /// Cells, ψ outer, θ inner.
    pub cells: Vec<CellOut>,
    /// Stiffness-limited workspace summary.
    #[serde(skip_serializing_if = "Option::is_none")]
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
    #[serde(skip_serializing_if = "Option::is_none")]
    pub map: Option<MapOut>,
}

/// Serialises `None` entries as the string "unbounded" (never null).
fn unbounded_list<'a, T, I, S>(v: I, s: S) -> Result<S::Ok, S::Error>
where
    T: Serialize + 'a,
    I: IntoIterator<Item = &'a Option<T>>,
    S: serde::Serializer,
{
    use serde::ser::SerializeSeq;
    let items: Vec<&Option<T>> = v.into_iter().collect();
    let mut seq = s.serialize_seq(Some(items.len()))?;
    for it in items {
        match it {
            Some(x) => seq.serialize_element(x)?,
            None => seq.serialize_element("unbounded")?,
        }
    }
    seq.end()
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
            values: if c.ok { c.values[..k].to_vec() } else { Vec::new() },
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
        let mut t = Table::columns("p_z (mm) | ψ (°) | θ (°) | φ (°) | pₓ (mm) | p_y (mm) | 1/C_xx (N/mm) | 1/C_yy | 1/C_zz | λ_min,3 (N/mm) | λ_max,3 (N/mm) | |δp| (mm)");
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
        // `kind`: reachable, unreachable, or workspace (reachable and in the stiffness-limited
        // workspace); metric columns carry their unit.
        csv += "psi_deg,theta_deg,kind,px_mm,py_mm,phi_deg";
        for (name, unit) in m.metrics.iter().zip(&m.units) {
            let suffix = if unit == "N/mm" { "N_per_mm" } else { "Nmm_per_rad" };
            csv += &format!(",{name}_{suffix}");
        }
        csv += "\n";
        for c in &m.cells {
            let kind = match (c.reachable, c.in_workspace) {
                (false, _) => "unreachable",
                (true, Some(true)) => "workspace",
                (true, _) => "reachable",
            };
            csv += &format!("{},{},{kind},{},{},{}", c.psi_deg, c.theta_deg, c.px, c.py, c.phi_deg);
            for j in 0..m.metrics.len() {
                let v = c.values.get(j).copied().flatten();
                csv += &format!(",{}", v.map_or(String::new(), |x| x.to_string()));
            }
            csv += "\n";
        }
    } else {
        csv += "pz_mm,psi_deg,theta_deg,phi_deg,px_mm,py_mm,s1_mm,s2_mm,s3_mm,lambda_min_independent_N_per_mm,lambda_max_independent_N_per_mm\n";
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
                    c.values.get(j).copied().flatten().map(|v| {
                        let (x, y) = if par { (c.px, c.py) } else { (c.psi_deg, c.theta_deg) };
                        (x, y, v, c.in_workspace.unwrap_or(true))
                    })
                })
                .collect()
        };
        if pts(false).is_empty() {
            continue;
        }
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

/// `prs_stiffness`: the registered analysis kind.
pub struct PrsStiffnessAnalysis;

impl Analysis for PrsStiffnessAnalysis {
    type Case = PrsStiffnessCase;
    type Result = PrsStiffnessResult;

    fn check(case: &Self::Case) -> Result<(), CaseError> {
        case.validate().map(|_| ())
    }
    fn run(case: &Self::Case, ctx: &mut Ctx) -> Result<Self::Result, RunError> {
        let r = solve(case)?;
        if ctx.with_files {
            ctx.files.extend(files(&r));
        }
        Ok(r)
    }
    fn report(r: &Self::Result) -> Report {
        report(r)
    }
}
