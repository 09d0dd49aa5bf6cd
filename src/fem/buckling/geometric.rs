//! Geometric stiffness K_G of the reference state, linear in its stress resultants.
//!
//! **Beams and flexibility elements (hinges)**: the geometric part of the co-rotational tangent
//! ([`crate::fem::corot::geometric_tangent`], J.-M. Battini & C. Pacoste, CMAME 191 (2002)
//! 1755–1789, eqs. (40)–(48)) at the undeformed configuration, with the element's local end
//! forces f₇ = [N, M₁, M₂] of the linear reference solution held fixed, symmetrised. It holds
//! the string term N/L(I − e₁e₁ᵀ) of the chord and the end-moment terms of the rotating
//! element frame; its symmetric part treats the end moments as semitangential (J. H. Argyris,
//! P. C. Dunne, D. W. Scharpf, "On large displacement–small strain analysis of structures with
//! rotational degrees of freedom", CMAME 14 (1978) 401–451). This is "the derivative of the
//! co-rotational tangent along the reference solution": d/dλ K_T(λu₀) at λ = 0.
//!
//! **Beams** add the element's own second-order (bowing) terms of the axial force N (tension
//! positive) for the cubic Hermite interpolation of v and w, less the string term already in
//! the chord part, and the Wagner term of the twist (Y.-B. Yang & W. McGuire, "Stiffness matrix
//! for geometric nonlinear analysis", J. Struct. Eng. 112 (1986) 853–877; W. McGuire,
//! R. H. Gallagher, R. D. Ziemian, Matrix Structural Analysis, 2nd ed., 2000, eq. (9.19)):
//!
//! ```text
//! v-plane (v₁ θz₁ v₂ θz₂):  N/(30L)·[ 6  3L −6  3L;  3L 4L² −3L −L²; −6 −3L 6 −3L;  3L −L² −3L 4L²]
//! w-plane (w₁ θy₁ w₂ θy₂):  N/(30L)·[ 6 −3L −6 −3L; −3L 4L²  3L −L²; −6  3L 6  3L; −3L −L²  3L 4L²]
//! twist  (θx₁ θx₂):         N·(Iy + Iz)/(A·L)·[1 −1; −1 1]
//! ```
//! With the string term N/L this is the consistent geometric stiffness 6N/(5L), N/10, 2NL/15,
//! −NL/30, exact to O(h⁴) in the buckling load. The within-element coupling of the end moments
//! with twist and curvature (Yang & McGuire's moment terms) enters through the rotating element
//! frame of the co-rotational part; it converges with the mesh (the lateral–torsional buckling
//! test shows the rate). Shear-deformable (Timoshenko) beams use the same Hermite interpolation
//! for K_G; shear enters through K. Flexibility elements carry only the co-rotational part (the
//! bowing of a short hinge is left out; it converges when the hinge is split into segments).
//!
//! **Rigid links**: [F_s×][a×] at the master (F_s the force the slave passes to the link,
//! a the arm), symmetrised, as in the co-rotational solver. **Springs** have none (linear in
//! the nodal rotation vectors). **Shells** are refused.

use crate::fem::constraints::DofMap;
use crate::fem::corot::{geometric_tangent, CorotGeometry, NodeState, Vec7, LOCAL_IDX};
use crate::fem::error::FemError;
use crate::fem::model::{Element, LoadCase, Model};
use crate::fem::recovery::internal_forces;
use crate::fem::solve::{SparseMatrix, SparsePattern};
use crate::fem::transform::{rotate12, skew, Mat12};
use nalgebra::{Matrix3, Matrix6, Vector3};
use rayon::prelude::*;

/// Bowing and Wagner terms of a beam of length `l` under axial force `n` (tension positive), in
/// local axes (see the module docs).
pub fn beam_bowing(n: f64, l: f64, a: f64, ip: f64) -> Mat12 {
    let c = n / (30.0 * l);
    let plane = |s: f64| {
        [
            [6.0, s * 3.0 * l, -6.0, s * 3.0 * l],
            [s * 3.0 * l, 4.0 * l * l, -s * 3.0 * l, -l * l],
            [-6.0, -s * 3.0 * l, 6.0, -s * 3.0 * l],
            [s * 3.0 * l, -l * l, -s * 3.0 * l, 4.0 * l * l],
        ]
    };
    let mut k = Mat12::zeros();
    for (idx, s) in [([1usize, 5, 7, 11], 1.0), ([2usize, 4, 8, 10], -1.0)] {
        let m = plane(s);
        for i in 0..4 {
            for j in 0..4 {
                k[(idx[i], idx[j])] = c * m[i][j];
            }
        }
    }
    let kt = n * ip / (a * l);
    k[(3, 3)] = kt;
    k[(9, 9)] = kt;
    k[(3, 9)] = -kt;
    k[(9, 3)] = -kt;
    k
}

fn elem_u(u: &[f64], nodes: [usize; 2]) -> nalgebra::SVector<f64, 12> {
    nalgebra::SVector::<f64, 12>::from_fn(|i, _| u[6 * nodes[i / 6] + i % 6])
}

/// Global 12×12 geometric stiffness of element `ie` for the global displacements `u` of the
/// reference state; `None` for springs (no geometric stiffness). Errors for shells.
pub fn element_geometric(model: &Model, ie: usize, u: &[f64]) -> Result<Option<Mat12>, FemError> {
    let nodes = match &model.elements[ie] {
        Element::Spring(_) => return Ok(None),
        Element::Shell4(_) => {
            return Err(FemError::BadInput(format!(
                "element {ie} is a shell (shell4): linear buckling has the geometric stiffness of beams, hinge (flexibility) elements, springs and rigid links only"
            )))
        }
        Element::Shell9(_) => {
            return Err(FemError::BadInput(format!(
                "element {ie} is a shell (shell9): linear buckling has the geometric stiffness of beams, hinge (flexibility) elements, springs and rigid links only"
            )))
        }
        Element::Matrix(_) => {
            return Err(FemError::BadInput(format!(
                "element {ie} is a piece of a superelement: linear buckling has the geometric stiffness of beams, hinge (flexibility) elements, springs and rigid links only (a reduced superelement has none)"
            )))
        }
        e => e.end_nodes(),
    };
    let (lam, l) = model.element_frame(ie)?;
    let (k, t) = model.element_local(ie)?;
    let f = k * (t * elem_u(u, nodes));
    let f7 = Vec7::from_fn(|i, _| f[LOCAL_IDX[i]]);
    let geom = CorotGeometry {
        x1: Vector3::from(model.nodes[nodes[0]]),
        x2: Vector3::from(model.nodes[nodes[1]]),
        r0: lam.transpose(),
        l0: l,
    };
    let rest = NodeState::default();
    let kc = geometric_tangent(&geom, &rest, &rest, &f7).ok_or_else(|| FemError::BadElement {
        element: ie,
        reason: "degenerate geometry for the geometric stiffness".into(),
    })?;
    let mut kg = (kc + kc.transpose()) * 0.5;
    if let Element::Beam(_) = &model.elements[ie] {
        let (p, _, _) = model.beam_props(ie)?;
        kg += rotate12(&beam_bowing(f[6], l, p.a, p.iy + p.iz), &lam);
    }
    Ok(Some(kg))
}

/// Geometric stiffness of the rigid links at their masters (global 6×6, rotations only).
fn link_geometric(model: &Model, u: &[f64], case: &LoadCase) -> Result<Vec<(usize, Matrix6<f64>)>, FemError> {
    if model.rigid_links.is_empty() {
        return Ok(Vec::new());
    }
    let mut net = internal_forces(model, u)?;
    for l in &case.forces {
        for d in 0..3 {
            net[6 * l.node + d] -= l.f[d];
        }
    }
    Ok(model
        .rigid_links
        .iter()
        .map(|link| {
            let xm = Vector3::from(model.nodes[link.master]);
            let mut g = Matrix3::zeros();
            for &s in &link.slaves {
                let fs = Vector3::new(net[6 * s], net[6 * s + 1], net[6 * s + 2]);
                let a = Vector3::from(model.nodes[s]) - xm;
                g += skew(&fs) * skew(&a);
            }
            let mut g6 = Matrix6::zeros();
            g6.fixed_view_mut::<3, 3>(3, 3).copy_from(&((g + g.transpose()) * 0.5));
            (link.master, g6)
        })
        .collect())
}

/// The reduced geometric stiffness K_G (equations of `map`) of the reference state with global
/// displacements `u` under `case`, and its largest entry in magnitude.
pub fn assemble_geometric(
    model: &Model,
    map: &DofMap,
    u: &[f64],
    case: &LoadCase,
) -> Result<(SparseMatrix, f64), FemError> {
    let mats: Vec<Option<Mat12>> = (0..model.elements.len())
        .into_par_iter()
        .map(|ie| element_geometric(model, ie, u))
        .collect::<Result<_, _>>()?;
    let mut pairs = Vec::new();
    let mut values = Vec::new();
    let mut push = |eqs: &[usize], n: usize, k: &dyn Fn(usize, usize) -> f64| {
        crate::fem::assembly::for_each_pair(eqs, n, |a, b, ea, eb| {
            pairs.push((ea, eb));
            values.push(k(a, b));
        });
    };
    for (ie, m) in mats.iter().enumerate() {
        let Some(kg) = m else { continue };
        let em = crate::fem::elements::ElementMatrix {
            nodes: model.elements[ie].end_nodes(),
            n_nodes: 2,
            k: *kg,
        };
        let (reps, k) = map.element_on_independent(&em);
        push(&map.element_eqs(reps, 2), 12, &|a, b| k[(a, b)]);
    }
    for (master, g6) in link_geometric(model, u, case)? {
        let (rep, g) = map.node_on_independent(master, &g6);
        push(&map.nodes_eqs(&[rep]), 6, &|a, b| g[(a, b)]);
    }
    let n = map.n_eq();
    pairs.extend((0..n).map(|i| (i, i)));
    let largest = values.iter().fold(0.0f64, |m, v| m.max(v.abs()));
    values.resize(pairs.len(), 0.0);
    Ok((SparsePattern::new(n, &pairs)?.matrix(&values)?, largest))
}

#[cfg(test)]
mod tests {
    use super::*;

    /// With the chord's string term N/L on v, w the bowing terms give the consistent geometric
    /// stiffness of the cubic Hermite beam (Przemieniecki, Theory of Matrix Structural Analysis,
    /// 1968, eq. (15.27)): 6N/(5L), N/10, 2NL/15, −NL/30.
    #[test]
    fn bowing_plus_string_is_the_consistent_matrix() {
        let (n, l) = (-7.0, 3.0);
        let k = beam_bowing(n, l, 1.0, 0.0);
        let string = n / l;
        assert!((k[(1, 1)] + string - 6.0 * n / (5.0 * l)).abs() < 1e-12);
        assert!((k[(1, 5)] - n / 10.0).abs() < 1e-12);
        assert!((k[(5, 5)] - 2.0 * n * l / 15.0).abs() < 1e-12);
        assert!((k[(5, 11)] + n * l / 30.0).abs() < 1e-12);
        assert!((k[(2, 4)] + n / 10.0).abs() < 1e-12);
        // A rigid rotation about local z (v = θ x, θz = θ) has no bowing: k·d = 0.
        let mut d = nalgebra::SVector::<f64, 12>::zeros();
        d[5] = 1.0;
        d[11] = 1.0;
        d[7] = l;
        assert!((k * d).amax() < 1e-12);
    }
}
