//! Rotation matrices of the platform orientation `R = Ry(θ)·Rx(ψ)·Rz(φ)`, their derivatives,
//! the parasitic rotation φ and the intrinsic x-y-z angles of a rotation.

use nalgebra::Matrix3;

/// Rotation about x by `a` rad.
pub fn rot_x(a: f64) -> Matrix3<f64> {
    let (s, c) = a.sin_cos();
    Matrix3::new(1.0, 0.0, 0.0, 0.0, c, -s, 0.0, s, c)
}
/// Rotation about y by `a` rad.
pub fn rot_y(a: f64) -> Matrix3<f64> {
    let (s, c) = a.sin_cos();
    Matrix3::new(c, 0.0, s, 0.0, 1.0, 0.0, -s, 0.0, c)
}
/// Rotation about z by `a` rad.
pub fn rot_z(a: f64) -> Matrix3<f64> {
    let (s, c) = a.sin_cos();
    Matrix3::new(c, -s, 0.0, s, c, 0.0, 0.0, 0.0, 1.0)
}
pub(super) fn drot_x(a: f64) -> Matrix3<f64> {
    let (s, c) = a.sin_cos();
    Matrix3::new(0.0, 0.0, 0.0, 0.0, -s, -c, 0.0, c, -s)
}
pub(super) fn drot_y(a: f64) -> Matrix3<f64> {
    let (s, c) = a.sin_cos();
    Matrix3::new(-s, 0.0, c, 0.0, 0.0, 0.0, -c, 0.0, -s)
}
pub(super) fn drot_z(a: f64) -> Matrix3<f64> {
    let (s, c) = a.sin_cos();
    Matrix3::new(-s, -c, 0.0, c, -s, 0.0, 0.0, 0.0, 0.0)
}

/// Platform orientation `R = Ry(θ)·Rx(ψ)·Rz(φ)`.
pub fn orientation(psi: f64, theta: f64, phi: f64) -> Matrix3<f64> {
    rot_y(theta) * rot_x(psi) * rot_z(phi)
}

/// Parasitic rotation φ = atan2(sψ·sθ, cψ + cθ), rad (Ruiz et al. (2019) Eq. 13).
pub fn parasitic_phi(psi: f64, theta: f64) -> f64 {
    (psi.sin() * theta.sin()).atan2(psi.cos() + theta.cos())
}

/// Angles [a, b, c] of the intrinsic x-y-z sequence `M = Rx(a)·Ry(b)·Rz(c)`, rad.
pub fn intrinsic_xyz(m: &Matrix3<f64>) -> [f64; 3] {
    let b = m[(0, 2)].clamp(-1.0, 1.0).asin();
    let a = (-m[(1, 2)]).atan2(m[(2, 2)]);
    let c = (-m[(0, 1)]).atan2(m[(0, 0)]);
    [a, b, c]
}
