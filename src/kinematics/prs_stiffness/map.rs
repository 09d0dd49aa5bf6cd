//! Stiffness metrics over a grid of poses and the stiffness-limited workspace.

use super::{PoseStiffness, PrsStiffness, StiffnessError};
use nalgebra::Vector3;

/// A quantity mapped over a (ψ, θ) grid.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum MapMetric {
    /// Diagonal term K_ii of the 6×6 stiffness (0-based, order x, y, z, rx, ry, rz).
    Diagonal(usize),
    /// Directional stiffness 1/C_ii.
    Directional(usize),
    /// Smallest eigenvalue of the length-scaled 6×6 K̃ (N/mm).
    LambdaMin,
    /// Largest eigenvalue of the length-scaled 6×6 K̃ (N/mm).
    LambdaMax,
    /// Smallest eigenvalue of the length-scaled 3×3 stiffness on (p_z, ψ, θ) (N/mm).
    IndependentLambdaMin,
    /// Largest eigenvalue of the length-scaled 3×3 stiffness on (p_z, ψ, θ) (N/mm).
    IndependentLambdaMax,
}

impl MapMetric {
    /// Evaluates the metric; `None` when it is unbounded (rigid legs).
    pub fn eval(&self, ps: &PoseStiffness, length: f64) -> Option<f64> {
        eval_metrics(std::slice::from_ref(self), ps, length)[0]
    }
}

/// Evaluates up to 8 metrics at one pose, each eigen-decomposition at most once.
fn eval_metrics(metrics: &[MapMetric], ps: &PoseStiffness, length: f64) -> [Option<f64>; 8] {
    let mut out = [None; 8];
    let mut full: Option<(f64, f64)> = None;
    let mut indep: Option<(f64, f64)> = None;
    for (o, m) in out.iter_mut().zip(metrics) {
        *o = match *m {
            MapMetric::Diagonal(i) => ps.stiffness.map(|k| k[(i, i)]),
            MapMetric::Directional(i) => ps.directional(i),
            MapMetric::LambdaMin | MapMetric::LambdaMax => {
                let (lo, hi) = *full.get_or_insert_with(|| {
                    // Eigenvalues of K̃ are the reciprocals of those of C̃ = T⁻¹CT⁻¹; using C
                    // keeps rigid legs (λ = ∞) out.
                    let mut cs = ps.compliance;
                    for j in 0..6 {
                        for k in 0..6 {
                            let f = if j >= 3 { length } else { 1.0 } * if k >= 3 { length } else { 1.0 };
                            cs[(j, k)] *= f;
                        }
                    }
                    let ev = cs.symmetric_eigenvalues();
                    ev.iter()
                        .fold((f64::INFINITY, f64::NEG_INFINITY), |(a, b), &x| (a.min(x), b.max(x)))
                });
                if matches!(m, MapMetric::LambdaMin) {
                    (hi > 0.0).then(|| 1.0 / hi)
                } else {
                    (lo > 1e-300).then(|| 1.0 / lo)
                }
            }
            MapMetric::IndependentLambdaMin | MapMetric::IndependentLambdaMax => {
                let (lo, hi) = *indep.get_or_insert_with(|| {
                    let mut k = ps.independent;
                    for j in 0..3 {
                        for c in 0..3 {
                            let f = if j >= 1 { 1.0 / length } else { 1.0 } * if c >= 1 { 1.0 / length } else { 1.0 };
                            k[(j, c)] *= f;
                        }
                    }
                    let ev = k.symmetric_eigenvalues();
                    ev.iter()
                        .fold((f64::INFINITY, f64::NEG_INFINITY), |(a, b), &x| (a.min(x), b.max(x)))
                });
                Some(if matches!(m, MapMetric::IndependentLambdaMin) {
                    lo
                } else {
                    hi
                })
            }
        };
    }
    out
}

/// One cell of a stiffness map.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct MapCell {
    /// ψ, rad.
    pub psi: f64,
    /// θ, rad.
    pub theta: f64,
    /// Parasitic pₓ, mm (NaN-free: 0 when unreachable).
    pub px: f64,
    /// Parasitic p_y, mm.
    pub py: f64,
    /// Parasitic φ, rad.
    pub phi: f64,
    /// Metric values in the order of the requested metrics; `None` when the pose is
    /// unreachable/singular or the metric unbounded.
    pub values: [Option<f64>; 8],
    /// Whether the pose was reachable and non-singular.
    pub ok: bool,
}

/// A (ψ, θ) grid at fixed height.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Grid {
    /// Absolute platform height, mm.
    pub pz: f64,
    /// ψ range, rad.
    pub psi: [f64; 2],
    /// θ range, rad.
    pub theta: [f64; 2],
    /// Points per axis (≥ 2).
    pub n: usize,
}

impl Grid {
    /// The k-th of n equally spaced values in [lo, hi].
    fn at(range: [f64; 2], k: usize, n: usize) -> f64 {
        range[0] + (range[1] - range[0]) * k as f64 / (n - 1) as f64
    }
}

/// Maps up to 8 metrics over a (ψ, θ) grid (row-major: ψ outer, θ inner), in parallel.
/// `length` is the characteristic length ℓ of the eigenvalue metrics, mm.
pub fn map(
    model: &PrsStiffness,
    grid: &Grid,
    tool: &Vector3<f64>,
    metrics: &[MapMetric],
    length: f64,
) -> Result<Vec<MapCell>, StiffnessError> {
    use rayon::prelude::*;
    if grid.n < 2 || metrics.len() > 8 || metrics.is_empty() {
        return Err(StiffnessError::Input(format!(
            "a map needs n ≥ 2 points per axis (got {}) and 1 to 8 metrics (got {})",
            grid.n,
            metrics.len()
        )));
    }
    let n = grid.n;
    Ok((0..n * n)
        .into_par_iter()
        .map(|idx| {
            let psi = Grid::at(grid.psi, idx / n, n);
            let theta = Grid::at(grid.theta, idx % n, n);
            let mut cell = MapCell {
                psi,
                theta,
                px: 0.0,
                py: 0.0,
                phi: 0.0,
                values: [None; 8],
                ok: false,
            };
            if let Ok(ps) = model.at(grid.pz, psi, theta, tool) {
                cell.px = ps.state.px;
                cell.py = ps.state.py;
                cell.phi = ps.state.phi;
                cell.ok = true;
                cell.values = eval_metrics(metrics, &ps, length);
            }
            cell
        })
        .collect())
}

/// Stiffness-limited workspace: which cells of a map have metric `which` (index into the
/// metrics of [`map`]) above `threshold`. Returns the mask and the fraction of reachable cells kept.
pub fn stiffness_limited(cells: &[MapCell], which: usize, threshold: f64) -> (Vec<bool>, f64) {
    let mask: Vec<bool> = cells
        .iter()
        .map(|c| c.ok && c.values.get(which).copied().flatten().is_some_and(|v| v > threshold))
        .collect();
    let reachable = cells.iter().filter(|c| c.ok).count();
    let kept = mask.iter().filter(|&&b| b).count();
    (
        mask,
        if reachable == 0 {
            0.0
        } else {
            kept as f64 / reachable as f64
        },
    )
}
