//! Plate part of the shell element: Reissner–Mindlin curvature rows and the MITC4 transverse
//! shear with the Lyly–Stenberg–Vihinen stabilization (see the module documentation of
//! [`crate::fem::shell`]).

use super::{cartesian, jacobian, plane_stress, shape, G2, KAPPA};
use crate::material::Material;
use nalgebra::{Matrix2, SMatrix};

/// Shear stabilization α of the MITC4 plate part: transverse shear stiffness
/// κGt·t²/(t² + α h_K²) (M. Lyly, R. Stenberg, T. Vihinen, CMAME 110 (1993) 343). Chosen with
/// numbers on clamped square and 45° skew plates with the lumped mass (see the module notes):
/// α = 0.05 puts modes 1–6 of both within ±5 % at 8×8 and ±2.5 % at 12×12; 0.04 leaves the
/// square's modes 5–6 above +5 %, 0.06 puts the skew plate's mode 4 below −6 %.
const SHEAR_STAB: f64 = 0.05;

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

/// Element diameter h_K: the longer diagonal of the projected quadrilateral, mm.
fn diameter(xy: &[[f64; 2]; 4]) -> f64 {
    let d = |a: usize, b: usize| (xy[a][0] - xy[b][0]).hypot(xy[a][1] - xy[b][1]);
    d(0, 2).max(d(1, 3))
}

/// Transverse shear stiffness of the stabilized MITC4, N/mm: κGt · t²/(t² + α h_K²).
pub fn stabilized_shear_stiffness(xy: &[[f64; 2]; 4], t: f64, mat: &Material) -> f64 {
    let hk = diameter(xy);
    KAPPA * mat.shear_modulus() * t * t * t / (t * t + SHEAR_STAB * hk * hk)
}

/// Plate stiffness (bending + stabilized MITC4 shear) over (w θx θy) × 4.
pub(super) fn plate_k(xy: &[[f64; 2]; 4], t: f64, mat: &Material) -> Option<SMatrix<f64, 12, 12>> {
    let db = plane_stress(mat.e, mat.nu) * (t * t * t / 12.0);
    let ds = stabilized_shear_stiffness(xy, t, mat);
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
