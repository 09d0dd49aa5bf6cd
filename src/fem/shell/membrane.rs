//! Membrane part of the shell element: Q4 strain rows with Wilson's incompatible modes
//! (Taylor's correction), their static condensation, and the Hughes–Brezzi drilling penalty (see
//! the module documentation of [`crate::fem::shell`]).

use super::{cartesian, mem, plane_stress, shell_geometry, Mat24, G2};
use crate::material::Material;
use nalgebra::{SMatrix, SVector};

/// Weight of the fully integrated drilling penalty, relative to γ = G.
const DRILL_STAB: f64 = 1e-3;

/// Compatible (3×12) and incompatible-mode (3×4) membrane strain rows at (ξ, η), with det J:
/// incompatible modes P₁ = 1−ξ², P₂ = 1−η², derivatives through J₀ scaled by det J₀/det J
/// (Taylor's constant-Jacobian correction of Wilson's modes). Shared by the stiffness and the
/// stress recovery.
pub(crate) type MemRows = (SMatrix<f64, 3, 12>, SMatrix<f64, 3, 4>, f64);

pub(crate) fn membrane_rows(xy: &[[f64; 2]; 4], xi: f64, eta: f64) -> Option<MemRows> {
    let (_, _, _, det0, ji0) = cartesian(xy, 0.0, 0.0)?;
    let (_, dx, dy, det, _) = cartesian(xy, xi, eta)?;
    let mut b = SMatrix::<f64, 3, 12>::zeros();
    for i in 0..4 {
        b[(0, 3 * i)] = dx[i];
        b[(1, 3 * i + 1)] = dy[i];
        b[(2, 3 * i)] = dy[i];
        b[(2, 3 * i + 1)] = dx[i];
    }
    let s = det0 / det;
    let pn = [(-2.0 * xi, 0.0), (0.0, -2.0 * eta)];
    let mut bi = SMatrix::<f64, 3, 4>::zeros();
    for (k, (pxi, peta)) in pn.iter().enumerate() {
        let px = s * (ji0[(0, 0)] * pxi + ji0[(0, 1)] * peta);
        let py = s * (ji0[(1, 0)] * pxi + ji0[(1, 1)] * peta);
        bi[(0, k)] = px;
        bi[(2, k)] = py;
        bi[(1, 2 + k)] = py;
        bi[(2, 2 + k)] = px;
    }
    Some((b, bi, det))
}

/// Membrane stiffness (12 DOFs u v θz per node, condensed incompatible modes, drilling).
pub(super) fn membrane(xy: &[[f64; 2]; 4], t: f64, mat: &Material) -> Option<SMatrix<f64, 12, 12>> {
    let c = plane_stress(mat.e, mat.nu) * t;
    let mut kcc = SMatrix::<f64, 12, 12>::zeros();
    let mut kci = SMatrix::<f64, 12, 4>::zeros();
    let mut kii = SMatrix::<f64, 4, 4>::zeros();
    for &xi in &[-G2, G2] {
        for &eta in &[-G2, G2] {
            let (b, bi, det) = membrane_rows(xy, xi, eta)?;
            kcc += b.transpose() * c * b * det;
            kci += b.transpose() * c * bi * det;
            kii += bi.transpose() * c * bi * det;
        }
    }
    let kii_inv = kii.try_inverse()?;
    let k = kcc - kci * kii_inv * kci.transpose() + drilling(xy, t, mat)?;
    Some((k + k.transpose()) * 0.5)
}

/// Drilling penalty over (u v θz) × 4: γ·t∫(θz − ½(∂v/∂x − ∂u/∂y))² dA with γ = G at the
/// centre (area 4 det J₀) plus the weak 2×2 part with 10⁻³·G, which removes the zero-energy θz
/// patterns the centre point leaves (linear and checkerboard ω with zero mean).
fn drilling(xy: &[[f64; 2]; 4], t: f64, mat: &Material) -> Option<SMatrix<f64, 12, 12>> {
    let g = mat.shear_modulus();
    let row = |xi: f64, eta: f64| {
        let (n, dx, dy, det, _) = cartesian(xy, xi, eta)?;
        let mut r = SVector::<f64, 12>::zeros();
        for i in 0..4 {
            r[3 * i] = 0.5 * dy[i];
            r[3 * i + 1] = -0.5 * dx[i];
            r[3 * i + 2] = n[i];
        }
        Some((r, det))
    };
    let (r0, det0) = row(0.0, 0.0)?;
    let mut k = r0 * r0.transpose() * (g * t * 4.0 * det0);
    for &xi in &[-G2, G2] {
        for &eta in &[-G2, G2] {
            let (r, det) = row(xi, eta)?;
            k += r * r.transpose() * (DRILL_STAB * g * t * det);
        }
    }
    Some(k)
}

/// Global drilling-penalty stiffness Tᵀ k_d T of a shell element (24×24): the part of its
/// stiffness that rests on the artificial drilling rotation. A mode or a deformation whose
/// strain energy sits mostly here is not governed by shell theory.
pub fn shell_drilling_stiffness(x: &[[f64; 3]; 4], t: f64, mat: &Material) -> Option<Mat24> {
    let g = shell_geometry(x)?;
    let kd = drilling(&g.xy, t, mat)?;
    let mut k = Mat24::zeros();
    for a in 0..12 {
        for b in 0..12 {
            k[(mem(a / 3, a % 3), mem(b / 3, b % 3))] = kd[(a, b)];
        }
    }
    Some(g.t.transpose() * k * g.t)
}
