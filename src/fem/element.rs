//! Element matrices in textbook notation: lower-case local (`k`, `d`, `f`), upper-case global
//! (`K = Tᵀ k T`). DOF order per node: u v w θx θy θz (local) / ux uy uz rx ry rz (global).

use super::section::SectionProps;
use super::transform::{rigid_arm, Mat12};
use nalgebra::{Matrix6, SMatrix, Vector3};

/// 6×12 matrix.
pub type Mat6x12 = SMatrix<f64, 6, 12>;

/// Local stiffness of a prismatic two-node 3D beam, exact for the Timoshenko beam
/// (J. S. Przemieniecki, Theory of Matrix Structural Analysis, 1968, eq. 5.116; PyNite
/// `Member3D.k`), with d = [u₁ v₁ w₁ θx₁ θy₁ θz₁ u₂ v₂ w₂ θx₂ θy₂ θz₂]:
///
/// ```text
/// axial      k = EA/L  · [ 1 −1; −1 1]                       on (u₁, u₂)
/// torsion    k = GJ/L  · [ 1 −1; −1 1]                       on (θx₁, θx₂)
/// x–y plane  k = EIz/(L³(1+Φy)) ·                             on (v₁, θz₁, v₂, θz₂)
///              [ 12     6L         −12    6L        ]
///              [ 6L   (4+Φy)L²     −6L   (2−Φy)L²   ]
///              [ −12   −6L          12   −6L        ]
///              [ 6L   (2−Φy)L²     −6L   (4+Φy)L²   ]
/// x–z plane  same with Iz→Iy, Φy→Φz and the signs of the 6L terms flipped, on (w₁, θy₁, w₂, θy₂)
///            (θy = −dw/dx)
/// Φy = 12 E Iz/(G Asy L²),  Φz = 12 E Iy/(G Asz L²)
/// ```
/// `shear = false` or a missing shear area gives Φ = 0 (Euler–Bernoulli).
/// E, G in MPa, L in mm; forces in N, moments in N·mm.
pub fn beam_local_stiffness(e: f64, g: f64, p: &SectionProps, l: f64, shear: bool) -> Mat12 {
    let phi = |i: f64, a_s: Option<f64>| match (shear, a_s) {
        (true, Some(a_s)) => 12.0 * e * i / (g * a_s * l * l),
        _ => 0.0,
    };
    let phi_y = phi(p.iz, p.asy);
    let phi_z = phi(p.iy, p.asz);
    let mut k = Mat12::zeros();
    let ea = e * p.a / l;
    let gj = g * p.j / l;
    k[(0, 0)] = ea;
    k[(6, 6)] = ea;
    k[(0, 6)] = -ea;
    k[(3, 3)] = gj;
    k[(9, 9)] = gj;
    k[(3, 9)] = -gj;
    // x–y plane: v (1, 7), θz (5, 11)
    let c = e * p.iz / (l.powi(3) * (1.0 + phi_y));
    k[(1, 1)] = 12.0 * c;
    k[(1, 5)] = 6.0 * l * c;
    k[(1, 7)] = -12.0 * c;
    k[(1, 11)] = 6.0 * l * c;
    k[(5, 5)] = (4.0 + phi_y) * l * l * c;
    k[(5, 7)] = -6.0 * l * c;
    k[(5, 11)] = (2.0 - phi_y) * l * l * c;
    k[(7, 7)] = 12.0 * c;
    k[(7, 11)] = -6.0 * l * c;
    k[(11, 11)] = (4.0 + phi_y) * l * l * c;
    // x–z plane: w (2, 8), θy (4, 10)
    let c = e * p.iy / (l.powi(3) * (1.0 + phi_z));
    k[(2, 2)] = 12.0 * c;
    k[(2, 4)] = -6.0 * l * c;
    k[(2, 8)] = -12.0 * c;
    k[(2, 10)] = -6.0 * l * c;
    k[(4, 4)] = (4.0 + phi_z) * l * l * c;
    k[(4, 8)] = 6.0 * l * c;
    k[(4, 10)] = (2.0 - phi_z) * l * l * c;
    k[(8, 8)] = 12.0 * c;
    k[(8, 10)] = 6.0 * l * c;
    k[(10, 10)] = (4.0 + phi_z) * l * l * c;
    for i in 0..12 {
        for j in 0..i {
            k[(i, j)] = k[(j, i)];
        }
    }
    k
}

/// Closed-form 6×6 tip compliance of a prismatic cantilever (node 2 relative to clamped node 1,
/// local axes), order u v w θx θy θz:
///
/// ```text
/// c_uu = L/EA,  c_θxθx = L/GJ,
/// c_vv = L³/3EIz + L/(G Asy),  c_vθz =  L²/2EIz,  c_θzθz = L/EIz,
/// c_ww = L³/3EIy + L/(G Asz),  c_wθy = −L²/2EIy,  c_θyθy = L/EIy
/// ```
/// (shear terms dropped when `shear` is false or the shear area is `None`). Units: mm/N,
/// 1/N (mixed), rad/(N·mm).
pub fn cantilever_compliance(
    e: f64,
    g: f64,
    p: &SectionProps,
    l: f64,
    shear: bool,
) -> Matrix6<f64> {
    let s = |a_s: Option<f64>| match (shear, a_s) {
        (true, Some(a)) => l / (g * a),
        _ => 0.0,
    };
    let mut c = Matrix6::zeros();
    c[(0, 0)] = l / (e * p.a);
    c[(3, 3)] = l / (g * p.j);
    c[(1, 1)] = l.powi(3) / (3.0 * e * p.iz) + s(p.asy);
    c[(1, 5)] = l * l / (2.0 * e * p.iz);
    c[(5, 1)] = c[(1, 5)];
    c[(5, 5)] = l / (e * p.iz);
    c[(2, 2)] = l.powi(3) / (3.0 * e * p.iy) + s(p.asz);
    c[(2, 4)] = -l * l / (2.0 * e * p.iy);
    c[(4, 2)] = c[(2, 4)];
    c[(4, 4)] = l / (e * p.iy);
    c
}

/// Equilibrium (kinematic) matrix of a two-node element of length L on its local x axis:
/// B = [−R(L·eₓ), I] so that δ = B·d is the motion of node 2 relative to node 1 carried
/// rigidly to node 2 (δ = 0 for every rigid-body motion). Its transpose distributes the node-2
/// force f₂ to both ends: f₁ = −R(L·eₓ)ᵀ f₂ (force −F₂, moment −(M₂ + L eₓ × F₂)).
pub fn flex_b(l: f64) -> Mat6x12 {
    let mut b = Mat6x12::zeros();
    let r = rigid_arm(&Vector3::new(l, 0.0, 0.0));
    b.fixed_view_mut::<6, 6>(0, 0).copy_from(&(-r));
    b.fixed_view_mut::<6, 6>(0, 6)
        .copy_from(&Matrix6::identity());
    b
}

/// Local stiffness of a flexibility element from its cantilever tip compliance C (node 2
/// relative to clamped node 1, local axes at node 2):
///
/// ```text
/// k = Bᵀ C⁻¹ B,   B = [−R(L eₓ)  I],   R(a) = [[I, −[a×]], [0, I]]
/// ```
/// k is symmetric, positive semi-definite with exactly the six rigid-body modes in its null
/// space, and reproduces [`beam_local_stiffness`] when C is [`cantilever_compliance`].
/// Returns `None` when C is not symmetric positive definite.
pub fn flex_local_stiffness(c: &Matrix6<f64>, l: f64) -> Option<Mat12> {
    let kc = flex_tip_stiffness(c)?;
    let b = flex_b(l);
    let k = b.transpose() * kc * b;
    Some((k + k.transpose()) * 0.5)
}

/// C⁻¹ by Cholesky, after checking symmetry (relative 1e-9) and positive definiteness.
pub fn flex_tip_stiffness(c: &Matrix6<f64>) -> Option<Matrix6<f64>> {
    let scale = c.amax();
    if !(scale > 0.0 && scale.is_finite()) {
        return None;
    }
    if (c - c.transpose()).amax() > 1e-9 * scale {
        return None;
    }
    let sym = (c + c.transpose()) * 0.5;
    let ch = sym.cholesky()?;
    let inv = ch.inverse();
    Some((inv + inv.transpose()) * 0.5)
}
