//! Plate part of the shell element: Reissner–Mindlin curvature rows and the MITC4 transverse
//! shear (see the module documentation of [`crate::fem::shell`]).

use super::{cartesian, jacobian, plane_stress, shape, G2, KAPPA};
use crate::material::Material;
use nalgebra::{Matrix2, SMatrix};

/// MITC4 covariant shear rows at a tying point: (γ_ξ, γ_η) as rows over (w θx θy) × 4.
fn covariant_shear(xy: &[[f64; 2]; 4], xi: f64, eta: f64) -> SMatrix<f64, 2, 12> {
    let (n, dxi, deta) = shape(xi, eta);
    let j = jacobian(xy, &dxi, &deta);
    let mut b = SMatrix::<f64, 2, 12>::zeros();
    for i in 0..4 {
        // γ_ξ = w_ξ + θy x_ξ − θx y_ξ
        b[(0, 3 * i)] = dxi[i];
        b[(0, 3 * i + 1)] = -n[i] * j[(0, 1)];
        b[(0, 3 * i + 2)] = n[i] * j[(0, 0)];
        b[(1, 3 * i)] = deta[i];
        b[(1, 3 * i + 1)] = -n[i] * j[(1, 1)];
        b[(1, 3 * i + 2)] = n[i] * j[(1, 0)];
    }
    b
}

/// Curvature rows B_b (κxx, κyy, κxy over (w θx θy) × 4).
pub(crate) fn curvature_b(dx: &[f64; 4], dy: &[f64; 4]) -> SMatrix<f64, 3, 12> {
    let mut b = SMatrix::<f64, 3, 12>::zeros();
    for i in 0..4 {
        b[(0, 3 * i + 2)] = dx[i];
        b[(1, 3 * i + 1)] = -dy[i];
        b[(2, 3 * i + 1)] = -dx[i];
        b[(2, 3 * i + 2)] = dy[i];
    }
    b
}

/// MITC4 shear rows (γxz, γyz) at (ξ, η).
pub(crate) fn mitc_shear_b(xy: &[[f64; 2]; 4], xi: f64, eta: f64, ji: &Matrix2<f64>) -> SMatrix<f64, 2, 12> {
    let b_b = covariant_shear(xy, 0.0, -1.0);
    let b_d = covariant_shear(xy, 0.0, 1.0);
    let b_a = covariant_shear(xy, -1.0, 0.0);
    let b_c = covariant_shear(xy, 1.0, 0.0);
    let mut cov = SMatrix::<f64, 2, 12>::zeros();
    for k in 0..12 {
        cov[(0, k)] = 0.5 * (1.0 - eta) * b_b[(0, k)] + 0.5 * (1.0 + eta) * b_d[(0, k)];
        cov[(1, k)] = 0.5 * (1.0 - xi) * b_a[(1, k)] + 0.5 * (1.0 + xi) * b_c[(1, k)];
    }
    ji * cov
}

/// Transverse shear stiffness of the MITC4 plate part per unit width, N/mm: κGt.
pub fn transverse_shear_stiffness(t: f64, mat: &Material) -> f64 {
    KAPPA * mat.shear_modulus() * t
}

/// Plate stiffness (bending + MITC4 shear) over (w θx θy) × 4.
pub(super) fn plate_k(xy: &[[f64; 2]; 4], t: f64, mat: &Material) -> Option<SMatrix<f64, 12, 12>> {
    let db = plane_stress(mat.e, mat.nu) * (t * t * t / 12.0);
    let ds = transverse_shear_stiffness(t, mat);
    let mut k = SMatrix::<f64, 12, 12>::zeros();
    for &xi in &[-G2, G2] {
        for &eta in &[-G2, G2] {
            let (_, dx, dy, det, ji) = cartesian(xy, xi, eta)?;
            let bb = curvature_b(&dx, &dy);
            let bs = mitc_shear_b(xy, xi, eta, &ji);
            k += (bb.transpose() * db * bb + bs.transpose() * bs * ds) * det;
        }
    }
    Some((k + k.transpose()) * 0.5)
}
