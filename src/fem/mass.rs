//! Mass matrices: beams (consistent, translational + rotary inertia), shells (lumped), point
//! masses.
//! Units: tonne, tonne·mm² (with mm, N, s: forces N = t·mm/s²).

use super::error::FemError;
use super::model::{Element, ElementMatrix, Model, ShellMatrix};
use super::shell::shell_mass;
use super::transform::{t12, Mat12};
use nalgebra::Matrix6;

/// Local consistent mass of a prismatic two-node beam (cubic Hermite bending, linear axial and
/// torsion; J. S. Przemieniecki, Theory of Matrix Structural Analysis, 1968, eqs. 11.18, 11.25),
/// d = [u₁ v₁ w₁ θx₁ θy₁ θz₁ u₂ …]:
///
/// ```text
/// axial     ρAL/6 [2 1; 1 2]                     torsion  ρ(Iy+Iz)L/6 [2 1; 1 2]
/// x–y plane ρAL/420 [156 22L 54 −13L; 22L 4L² 13L −3L²; 54 13L 156 −22L; −13L −3L² −22L 4L²]
///         + ρIz/(30L) [36 3L −36 3L; 3L 4L² −3L −L²; −36 −3L 36 −3L; 3L −L² −3L 4L²]   (rotary)
/// x–z plane the same with Iy and the signs of the L terms flipped (θy = −dw/dx)
/// ```
/// ρ in t/mm³, A in mm², I in mm⁴, L in mm.
pub fn beam_local_mass(rho: f64, a: f64, iy: f64, iz: f64, l: f64) -> Mat12 {
    let mut m = Mat12::zeros();
    let ma = rho * a * l;
    let mt = rho * (iy + iz) * l;
    for (i, j, v) in [(0, 0, 2.0), (0, 6, 1.0), (6, 6, 2.0)] {
        m[(i, j)] = ma / 6.0 * v;
    }
    for (i, j, v) in [(3, 3, 2.0), (3, 9, 1.0), (9, 9, 2.0)] {
        m[(i, j)] = mt / 6.0 * v;
    }
    // One bending plane on (v-like dof dv, rotation dr); s = sign of the L terms.
    let plane = |m: &mut Mat12, dv: usize, dr: usize, s: f64, inertia: f64| {
        let c = ma / 420.0;
        let r = rho * inertia / (30.0 * l);
        let idx = [dv, dr, 6 + dv, 6 + dr];
        let tr = [
            [156.0, 22.0 * l * s, 54.0, -13.0 * l * s],
            [22.0 * l * s, 4.0 * l * l, 13.0 * l * s, -3.0 * l * l],
            [54.0, 13.0 * l * s, 156.0, -22.0 * l * s],
            [-13.0 * l * s, -3.0 * l * l, -22.0 * l * s, 4.0 * l * l],
        ];
        let ro = [
            [36.0, 3.0 * l * s, -36.0, 3.0 * l * s],
            [3.0 * l * s, 4.0 * l * l, -3.0 * l * s, -l * l],
            [-36.0, -3.0 * l * s, 36.0, -3.0 * l * s],
            [3.0 * l * s, -l * l, -3.0 * l * s, 4.0 * l * l],
        ];
        for i in 0..4 {
            for j in 0..4 {
                m[(idx[i], idx[j])] += c * tr[i][j] + r * ro[i][j];
            }
        }
    };
    plane(&mut m, 1, 5, 1.0, iz);
    plane(&mut m, 2, 4, -1.0, iy);
    for i in 0..12 {
        for j in 0..i {
            // Only the upper entry of the axial/torsion pairs was written.
            let v = if m[(i, j)] != 0.0 { m[(i, j)] } else { m[(j, i)] };
            m[(i, j)] = v;
            m[(j, i)] = v;
        }
    }
    m
}

/// Global mass of a two-node element (beams; flexibility elements and springs are massless —
/// model their mass with point masses). `None` for shells.
pub fn element_mass(model: &Model, ie: usize) -> Result<Option<ElementMatrix>, FemError> {
    match model.elements.get(ie) {
        Some(Element::Beam(b)) => {
            let (p, _, _) = model.beam_props(ie)?;
            let (lam, l) = model.element_frame(ie)?;
            let rho = b.material.density;
            if !(rho.is_finite() && rho >= 0.0) {
                return Err(FemError::BadElement {
                    element: ie,
                    reason: format!("density must be finite and non-negative, got {rho}"),
                });
            }
            let m = beam_local_mass(rho, p.a, p.iy, p.iz, l);
            let t = t12(&lam);
            Ok(Some(ElementMatrix {
                nodes: b.nodes,
                n_nodes: 2,
                k: t.transpose() * m * t,
            }))
        }
        Some(Element::Flex(f)) => Ok(Some(ElementMatrix {
            nodes: f.nodes,
            n_nodes: 2,
            k: Mat12::zeros(),
        })),
        Some(Element::Spring(s)) => Ok(Some(ElementMatrix {
            nodes: [s.a, s.b.unwrap_or(s.a)],
            n_nodes: if s.b.is_some() { 2 } else { 1 },
            k: Mat12::zeros(),
        })),
        Some(Element::Shell4(_)) => Ok(None),
        None => Err(FemError::BadInput(format!("no element {ie}"))),
    }
}

/// Global (lumped) mass of shell element `ie` (24×24).
pub fn shell_mass_matrix(model: &Model, ie: usize) -> Result<ShellMatrix, FemError> {
    let (s, x) = model.shell_checked(ie)?;
    let rho = s.material.density;
    if !(rho.is_finite() && rho >= 0.0) {
        return Err(FemError::BadElement {
            element: ie,
            reason: format!("density must be finite and non-negative, got {rho}"),
        });
    }
    let k = shell_mass(&x, s.t, rho).ok_or_else(|| FemError::BadElement {
        element: ie,
        reason: format!("shell nodes {:?} do not form a convex quadrilateral", s.nodes),
    })?;
    Ok(ShellMatrix { nodes: s.nodes, k })
}

/// 6×6 mass of point mass `i` (global axes): diag(m, m, m, Ix, Iy, Iz).
pub fn point_mass(model: &Model, i: usize) -> Matrix6<f64> {
    let pm = &model.masses[i];
    Matrix6::from_diagonal(&nalgebra::Vector6::new(
        pm.mass,
        pm.mass,
        pm.mass,
        pm.inertia[0],
        pm.inertia[1],
        pm.inertia[2],
    ))
}
