//! Forces on a node group: tributary weights of points, lines and surfaces, and a total force
//! and moment spread over the group's nodes (the rule is stated in the documentation of
//! [`crate::fem::loads`]).

use crate::fem::error::FemError;
use crate::fem::model::Model;
use crate::fem::shell_loads::pressure_loads;
use nalgebra::{Matrix3, SymmetricEigen, Vector3};
use std::collections::BTreeMap;

fn dist(a: [f64; 3], b: [f64; 3]) -> f64 {
    (Vector3::from(b) - Vector3::from(a)).norm()
}

/// Tributary weights of the nodes of a group of cells, each cell a node list: 1 node (a point:
/// weight 1), 2 nodes (a line: L/2 per end), 3 nodes (a triangle: A/3 per corner) or 4 nodes (a
/// quadrilateral, also [a, b, c, c] for a triangle: ∫Nᵢ dA of the bilinear element over its mean
/// plane, exact for linear and flat bilinear elements). The cells must all be of one dimension
/// (points, lines or surfaces). Returns (node, weight) sorted by node.
pub fn tributary_weights(model: &Model, cells: &[Vec<usize>]) -> Result<Vec<(usize, f64)>, FemError> {
    let mut w: BTreeMap<usize, f64> = BTreeMap::new();
    let dim = |c: &Vec<usize>| match c.len() {
        1 => 0,
        2 => 1,
        _ => 2,
    };
    for (i, c) in cells.iter().enumerate() {
        for &n in c {
            if n >= model.nodes.len() {
                return Err(FemError::NodeOutOfRange {
                    what: format!("group cell {i}"),
                    node: n,
                    n_nodes: model.nodes.len(),
                });
            }
        }
        if dim(c) != dim(&cells[0]) {
            return Err(FemError::BadInput(format!(
                "group cell {i} has {} nodes, cell 0 has {}: a group spreads a load over points, lines or surfaces, not a mix",
                c.len(),
                cells[0].len()
            )));
        }
        let x = |k: usize| model.nodes[c[k]];
        match c.len() {
            1 => *w.entry(c[0]).or_default() += 1.0,
            2 => {
                let h = 0.5 * dist(x(0), x(1));
                *w.entry(c[0]).or_default() += h;
                *w.entry(c[1]).or_default() += h;
            }
            3 => {
                let a = (Vector3::from(x(1)) - Vector3::from(x(0)))
                    .cross(&(Vector3::from(x(2)) - Vector3::from(x(0))))
                    .norm()
                    / 6.0;
                for &n in c {
                    *w.entry(n).or_default() += a;
                }
            }
            4 => {
                // |p·n ∫Nᵢ dA| with p = 1: the area share of each corner.
                let f = pressure_loads(&[x(0), x(1), x(2), x(3)], 1.0).ok_or_else(|| {
                    FemError::BadInput(format!(
                        "group cell {i}: nodes {c:?} do not form a convex quadrilateral"
                    ))
                })?;
                for (k, &n) in c.iter().enumerate() {
                    *w.entry(n).or_default() += Vector3::new(f[k][0], f[k][1], f[k][2]).norm();
                }
            }
            n => {
                return Err(FemError::BadInput(format!(
                    "group cell {i} has {n} nodes; cells have 1 to 4 nodes"
                )))
            }
        }
    }
    if w.values().any(|v| !(v.is_finite() && *v > 0.0)) {
        let zero: Vec<usize> = w
            .iter()
            .filter(|(_, v)| !(v.is_finite() && **v > 0.0))
            .map(|(n, _)| *n)
            .collect();
        return Err(FemError::BadInput(format!(
            "group nodes {zero:?} have no tributary length or area (zero-length or degenerate cells)"
        )));
    }
    Ok(w.into_iter().collect())
}

/// Spreads the total `total` = [Fx, Fy, Fz (N), Mx, My, Mz (N·mm), moment about the weighted
/// centroid] over the nodes with `weights` (see the module documentation). Returns one load
/// per node, in the order of `weights`.
pub fn spread_total(
    model: &Model,
    weights: &[(usize, f64)],
    total: [f64; 6],
) -> Result<Vec<(usize, [f64; 6])>, FemError> {
    if weights.is_empty() {
        return Err(FemError::BadInput("a group load needs at least one node".into()));
    }
    if total.iter().any(|v| !v.is_finite()) {
        return Err(FemError::BadInput(format!("group load {total:?} must be finite")));
    }
    for &(n, w) in weights {
        if n >= model.nodes.len() {
            return Err(FemError::NodeOutOfRange {
                what: "group load".into(),
                node: n,
                n_nodes: model.nodes.len(),
            });
        }
        if !(w.is_finite() && w > 0.0) {
            return Err(FemError::BadInput(format!(
                "group load: node {n} has weight {w}; weights must be positive"
            )));
        }
    }
    let wsum: f64 = weights.iter().map(|(_, w)| w).sum();
    let c = Vector3::from(centroid(model, weights));
    let r: Vec<Vector3<f64>> = weights
        .iter()
        .map(|&(n, _)| Vector3::from(model.nodes[n]) - c)
        .collect();
    let j = weights.iter().zip(&r).fold(Matrix3::zeros(), |s, (&(_, w), ri)| {
        s + (Matrix3::identity() * ri.norm_squared() - ri * ri.transpose()) * w
    });
    let f = Vector3::new(total[0], total[1], total[2]);
    let m = Vector3::new(total[3], total[4], total[5]);
    // Split M into the part carried by forces (range of J) and the rest (nodal moments).
    let eig = SymmetricEigen::new(j);
    let tol = 1e-12 * eig.eigenvalues.amax();
    let mut a = Vector3::zeros();
    let mut m_nodal = m;
    for k in 0..3 {
        let lam = eig.eigenvalues[k];
        if lam > tol && lam > 0.0 {
            let v = eig.eigenvectors.column(k);
            let mk = v.dot(&m);
            a += v * (mk / lam);
            m_nodal -= v * mk;
        }
    }
    let mut out: Vec<(usize, [f64; 6])> = weights
        .iter()
        .zip(&r)
        .map(|(&(n, w), ri)| {
            let fi = f * (w / wsum) + a.cross(ri) * w;
            let mi = m_nodal * (w / wsum);
            (n, [fi.x, fi.y, fi.z, mi.x, mi.y, mi.z])
        })
        .collect();
    // Round-off remainder on the largest-weight node: Σ fᵢ = F and Σ (rᵢ × fᵢ + mᵢ) = M.
    let big = (0..weights.len())
        .max_by(|&p, &q| weights[p].1.total_cmp(&weights[q].1))
        .unwrap_or(0);
    let (mut sf, mut sm) = (Vector3::zeros(), Vector3::zeros());
    for (k, (_, l)) in out.iter().enumerate() {
        if k != big {
            let fi = Vector3::new(l[0], l[1], l[2]);
            sf += fi;
            sm += r[k].cross(&fi) + Vector3::new(l[3], l[4], l[5]);
        }
    }
    let fb = f - sf;
    let mb = m - sm - r[big].cross(&fb);
    out[big].1 = [fb.x, fb.y, fb.z, mb.x, mb.y, mb.z];
    Ok(out)
}

/// Weighted centroid Σ wᵢ xᵢ / Σ wᵢ of the nodes with `weights` (the point about which
/// [`spread_total`] takes the moment).
pub fn centroid(model: &Model, weights: &[(usize, f64)]) -> [f64; 3] {
    let wsum: f64 = weights.iter().map(|(_, w)| w).sum();
    let c = weights
        .iter()
        .fold(Vector3::zeros(), |s, &(n, w)| s + Vector3::from(model.nodes[n]) * w)
        / wsum;
    [c.x, c.y, c.z]
}
