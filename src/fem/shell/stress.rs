//! Stress recovery of the shell element at its centre: von Mises at the top, middle and bottom
//! surfaces, membrane forces and moments, [`ShellStress`].

use super::{cartesian, plane_stress, shell_geometry, Vec24};
use crate::material::Material;
use nalgebra::{Matrix3, Vector3};

/// Stresses at the element centre, local axes (MPa): von Mises at the top (z = +t/2), middle
/// and bottom surfaces, plus the membrane forces n = (nxx, nyy, nxy) (N/mm) and moments
/// m = (mxx, myy, mxy) (N·mm/mm).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ShellStress {
    /// Von Mises stress [top, mid, bottom], MPa.
    pub von_mises: [f64; 3],
    /// Membrane forces per unit length, N/mm.
    pub n: [f64; 3],
    /// Bending moments per unit length, N·mm/mm.
    pub m: [f64; 3],
}

/// Plane-stress von Mises √(σx² − σxσy + σy² + 3τ²).
pub fn von_mises_plane(s: &[f64; 3]) -> f64 {
    (s[0] * s[0] - s[0] * s[1] + s[1] * s[1] + 3.0 * s[2] * s[2])
        .max(0.0)
        .sqrt()
}

/// Centre stresses from the global element displacements (24). The incompatible modes have
/// zero derivatives at the centre, so they do not enter.
pub fn shell_stress(x: &[[f64; 3]; 4], t: f64, mat: &Material, d_global: &Vec24) -> Option<ShellStress> {
    let g = shell_geometry(x)?;
    let d = g.t * d_global;
    let (_, dx, dy, _, _) = cartesian(&g.xy, 0.0, 0.0)?;
    let mut eps = Vector3::zeros();
    let mut kap = Vector3::zeros();
    for i in 0..4 {
        let (u, v) = (d[6 * i], d[6 * i + 1]);
        let (tx, ty) = (d[6 * i + 3], d[6 * i + 4]);
        eps += Vector3::new(dx[i] * u, dy[i] * v, dy[i] * u + dx[i] * v);
        kap += Vector3::new(dx[i] * ty, -dy[i] * tx, dy[i] * ty - dx[i] * tx);
    }
    Some(stress_from_strains(&plane_stress(mat.e, mat.nu), &eps, &kap, t))
}

/// The [`ShellStress`] of membrane strains `eps` and curvatures `kap` (local axes) of a shell of
/// thickness `t` (mm) with plane-stress elasticity `c` (MPa). Shared by the four- and nine-node
/// shells.
pub(crate) fn stress_from_strains(c: &Matrix3<f64>, eps: &Vector3<f64>, kap: &Vector3<f64>, t: f64) -> ShellStress {
    let sm = c * eps;
    let sb = c * kap * (t / 2.0);
    let arr = |v: Vector3<f64>| [v.x, v.y, v.z];
    ShellStress {
        von_mises: [
            von_mises_plane(&arr(sm + sb)),
            von_mises_plane(&arr(sm)),
            von_mises_plane(&arr(sm - sb)),
        ],
        n: arr(sm * t),
        m: arr(c * kap * (t * t * t / 12.0)),
    }
}
