//! Mass matrices: beams (consistent, translational + rotary inertia), shells (lumped), point
//! masses.
//! Units: tonne, tonne·mm² (with mm, N, s: forces N = t·mm/s²).

use super::error::FemError;
use super::model::{Element, ElementMatrix, Model, ShellMatrix};
use super::shell::shell_mass;
use super::transform::{t12, Mat12};
use nalgebra::Matrix6;

/// Local consistent mass of a prismatic two-node Euler–Bernoulli beam (cubic Hermite bending,
/// linear axial and torsion; J. S. Przemieniecki, Theory of Matrix Structural Analysis, 1968,
/// eqs. 11.18, 11.25), d = [u₁ v₁ w₁ θx₁ θy₁ θz₁ u₂ …]:
///
/// ```text
/// axial     ρAL/6 [2 1; 1 2]                     torsion  ρ(Iy+Iz)L/6 [2 1; 1 2]
/// x–y plane ρAL/420 [156 22L 54 −13L; 22L 4L² 13L −3L²; 54 13L 156 −22L; −13L −3L² −22L 4L²]
///         + ρIz/(30L) [36 3L −36 3L; 3L 4L² −3L −L²; −36 −3L 36 −3L; 3L −L² −3L 4L²]   (rotary)
/// x–z plane the same with Iy and the signs of the L terms flipped (θy = −dw/dx)
/// ```
/// ρ in t/mm³, A in mm², I in mm⁴, L in mm. This is [`beam_local_mass_shear`] with Φ = 0.
pub fn beam_local_mass(rho: f64, a: f64, iy: f64, iz: f64, l: f64) -> Mat12 {
    beam_local_mass_shear(rho, a, iy, iz, l, 0.0, 0.0)
}

/// Local consistent mass of a prismatic two-node Timoshenko (shear-deformable) beam, from the
/// interdependent interpolation that makes [`super::element::beam_local_stiffness`] exact
/// (J. S. Przemieniecki, Theory of Matrix Structural Analysis, 1968, eq. 11.41; Z. Friedman,
/// J. B. Kosmatka, "An improved two-node Timoshenko beam finite element", Computers & Structures
/// 47 (1993) 473–481). Per bending plane, on (v₁, θz₁, v₂, θz₂), with Φ the plane's shear
/// parameter (Φy = 12 E Iz/(G Asy L²) for x–y, Φz = 12 E Iy/(G Asz L²) for x–z):
///
/// ```text
/// translation  ρAL/(420 (1+Φ)²) ·
///   [ 156+294Φ+140Φ²        (22+38.5Φ+17.5Φ²)L    54+126Φ+70Φ²         −(13+31.5Φ+17.5Φ²)L ]
///   [                       (4+7Φ+3.5Φ²)L²        (13+31.5Φ+17.5Φ²)L   −(3+7Φ+3.5Φ²)L²     ]
///   [                                             156+294Φ+140Φ²       −(22+38.5Φ+17.5Φ²)L ]
///   [ sym.                                                             (4+7Φ+3.5Φ²)L²      ]
/// rotary       ρI/(30L (1+Φ)²) ·
///   [ 36   (3−15Φ)L          −36    (3−15Φ)L        ]
///   [      (4+5Φ+10Φ²)L²     (−3+15Φ)L   (−1−5Φ+5Φ²)L² ]
///   [                        36     (−3+15Φ)L       ]
///   [ sym.                          (4+5Φ+10Φ²)L²   ]
/// ```
/// x–z plane: the same on (w₁, θy₁, w₂, θy₂) with Iy, Φz and the signs of the L terms flipped.
/// Axial and torsion as in [`beam_local_mass`]. Φ = 0 gives [`beam_local_mass`] bit for bit.
pub fn beam_local_mass_shear(rho: f64, a: f64, iy: f64, iz: f64, l: f64, phi_y: f64, phi_z: f64) -> Mat12 {
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
    let plane = |m: &mut Mat12, dv: usize, dr: usize, s: f64, inertia: f64, f: f64| {
        let q = (1.0 + f) * (1.0 + f);
        let c = ma / 420.0 / q;
        let r = rho * inertia / (30.0 * l) / q;
        let f2 = f * f;
        let idx = [dv, dr, 6 + dv, 6 + dr];
        let t11 = 156.0 + 294.0 * f + 140.0 * f2;
        let t12 = (22.0 + 38.5 * f + 17.5 * f2) * l * s;
        let t13 = 54.0 + 126.0 * f + 70.0 * f2;
        let t14 = (13.0 + 31.5 * f + 17.5 * f2) * l * s;
        let t22 = (4.0 + 7.0 * f + 3.5 * f2) * l * l;
        let t24 = (3.0 + 7.0 * f + 3.5 * f2) * l * l;
        let tr = [
            [t11, t12, t13, -t14],
            [t12, t22, t14, -t24],
            [t13, t14, t11, -t12],
            [-t14, -t24, -t12, t22],
        ];
        let r12 = (3.0 - 15.0 * f) * l * s;
        let r22 = (4.0 + 5.0 * f + 10.0 * f2) * l * l;
        let r24 = (-1.0 - 5.0 * f + 5.0 * f2) * l * l;
        let ro = [
            [36.0, r12, -36.0, r12],
            [r12, r22, -r12, r24],
            [-36.0, -r12, 36.0, -r12],
            [r12, r24, -r12, r22],
        ];
        for i in 0..4 {
            for j in 0..4 {
                m[(idx[i], idx[j])] += c * tr[i][j] + r * ro[i][j];
            }
        }
    };
    plane(&mut m, 1, 5, 1.0, iz, phi_y);
    plane(&mut m, 2, 4, -1.0, iy, phi_z);
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

/// Global mass of a two-node element (beams, with the shear-deformable mass when the beam has
/// shear on; flexibility elements and springs are massless —
/// model their mass with point masses). `None` for shells (four- and nine-node).
pub fn element_mass(model: &Model, ie: usize) -> Result<Option<ElementMatrix>, FemError> {
    match model.elements.get(ie) {
        Some(Element::Beam(b)) => {
            let (p, e, g) = model.beam_props(ie)?;
            let (lam, l) = model.element_frame(ie)?;
            let rho = checked_density(ie, b.material.density)?;
            // Same shear parameters as the stiffness (Φ = 0 without shear: Euler–Bernoulli).
            let phi = |i: f64, a_s: Option<f64>| match (b.shear, a_s) {
                (true, Some(a_s)) => 12.0 * e * i / (g * a_s * l * l),
                _ => 0.0,
            };
            let m = beam_local_mass_shear(rho, p.a, p.iy, p.iz, l, phi(p.iz, p.asy), phi(p.iy, p.asz));
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
        Some(Element::Shell4(_) | Element::Shell9(_)) => Ok(None),
        Some(Element::Matrix(m)) => m.matrix(ie, true).map(Some),
        None => Err(FemError::BadInput(format!("no element {ie}"))),
    }
}

/// `rho` (tonne/mm³) if finite and non-negative, else the error of element `ie`.
pub(crate) fn checked_density(ie: usize, rho: f64) -> Result<f64, FemError> {
    if !(rho.is_finite() && rho >= 0.0) {
        return Err(FemError::BadElement {
            element: ie,
            reason: format!("density must be finite and non-negative, got {rho}"),
        });
    }
    Ok(rho)
}

/// Global (lumped) mass of shell element `ie` (24×24).
pub fn shell_mass_matrix(model: &Model, ie: usize) -> Result<ShellMatrix, FemError> {
    let (s, x) = model.shell_checked(ie)?;
    let rho = checked_density(ie, s.material.density)?;
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
