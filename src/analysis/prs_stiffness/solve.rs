//! Running a `prs_stiffness` case: the Jacobian stiffness at each pose, the (ψ, θ) map and the
//! stiffness-limited workspace, gathered into a [`PrsStiffnessResult`].

use super::{CellOut, DeformationOut, EigenOut, MapOut, PoseOut, PrsStiffnessResult, WorkspaceOut};
use crate::analysis::{AnalysisError, RunError};
use crate::case::prs_stiffness::{metric_unit, FrameSpec, MapSpec, PrsStiffnessCase, WorkspaceSpec};
use crate::kinematics::prs_stiffness::{map, scaled_eigen, stiffness_limited, Grid, MapCell};
use nalgebra::{Vector3, Vector6};

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
