//! Platform pointings, joint states, path samples and joint springs of the pan-tilt PRBM.

use super::JOINTS;
use nalgebra::{Vector2, Vector3};
use std::f64::consts::PI;

/// A platform pose: pitch γ and phase φ, rad.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Pointing {
    /// Pitch γ (angle of r₇ from z), rad.
    pub gamma: f64,
    /// Phase φ (azimuth of r₇), rad.
    pub phi: f64,
}

impl Pointing {
    /// Pose from degrees.
    pub fn from_deg(gamma_deg: f64, phi_deg: f64) -> Self {
        Self {
            gamma: gamma_deg.to_radians(),
            phi: phi_deg.to_radians(),
        }
    }

    /// The platform axis r₇.
    pub fn axis(&self) -> Vector3<f64> {
        let (sg, cg) = self.gamma.sin_cos();
        let (sp, cp) = self.phi.sin_cos();
        Vector3::new(sg * cp, sg * sp, cg)
    }

    /// ∂r₇/∂γ and ∂r₇/∂φ.
    pub(super) fn axis_derivatives(&self) -> [Vector3<f64>; 2] {
        let (sg, cg) = self.gamma.sin_cos();
        let (sp, cp) = self.phi.sin_cos();
        [
            Vector3::new(cg * cp, cg * sp, -sg),
            Vector3::new(-sg * sp, sg * cp, 0.0),
        ]
    }
}

/// Joint angles and their gradients at one pose.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct JointState {
    /// Rotations of J1–J8 from home, rad.
    pub q: [f64; JOINTS],
    /// ∂qᵢ/∂s, s = (r₇ₓ, r₇ᵧ) (the regular coordinates), rad per unit.
    pub grad_s: [Vector2<f64>; JOINTS],
    /// ∂qᵢ/∂(γ, φ), rad/rad.
    pub grad_x: [Vector2<f64>; JOINTS],
}

/// A prescribed point of a platform path with its rates.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct PathSample {
    /// Time, s.
    pub t: f64,
    /// Pose, rad.
    pub pose: Pointing,
    /// γ̇, rad/s.
    pub gamma_rate: f64,
    /// φ̇, rad/s.
    pub phi_rate: f64,
}

/// A uniform circle of constant pitch: φ = φ₀ ± 2π t/T, `n` samples over one period
/// (t = 0, T/n, …, (n−1)T/n). `clockwise` runs φ downwards.
pub fn circle(gamma: f64, phi0: f64, period: f64, n: usize, clockwise: bool) -> Vec<PathSample> {
    let sign = if clockwise { -1.0 } else { 1.0 };
    let rate = sign * 2.0 * PI / period;
    (0..n)
        .map(|k| {
            let t = period * k as f64 / n as f64;
            PathSample {
                t,
                pose: Pointing {
                    gamma,
                    phi: phi0 + rate * t,
                },
                gamma_rate: 0.0,
                phi_rate: rate,
            }
        })
        .collect()
}

/// Per-joint torsional stiffness and viscous damping of the PRBM, SI-like internal units.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct JointSprings {
    /// Kᵢ, N·mm/rad.
    pub stiffness: [f64; JOINTS],
    /// Dᵢ, N·mm·s/rad.
    pub damping: [f64; JOINTS],
}

impl JointSprings {
    /// The same K (N·mm/°) and D (N·mm·s/°) on every joint, converted to per-radian.
    pub fn uniform_per_degree(k_per_deg: f64, d_per_deg: f64) -> Self {
        let to_rad = 180.0 / PI;
        Self {
            stiffness: [k_per_deg * to_rad; JOINTS],
            damping: [d_per_deg * to_rad; JOINTS],
        }
    }
}

/// The state of the mechanism at one path sample.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct PathState {
    /// The prescribed sample.
    pub sample: PathSample,
    /// Joint rotations from home, rad.
    pub q: [f64; JOINTS],
    /// Joint rates, rad/s.
    pub q_rate: [f64; JOINTS],
    /// Actuator torques from the springs alone (no damping), N·mm.
    pub torque_stiffness: [f64; 2],
    /// Actuator torques from the dampers alone, N·mm (total with damping = sum of the two).
    pub torque_damping: [f64; 2],
    /// det ∂θ_a/∂(r₇ₓ, r₇ᵧ) (the regular actuation Jacobian).
    pub det_actuation: f64,
}

impl PathState {
    /// Actuator torques with damping, N·mm.
    pub fn torque_total(&self) -> [f64; 2] {
        [
            self.torque_stiffness[0] + self.torque_damping[0],
            self.torque_stiffness[1] + self.torque_damping[1],
        ]
    }
}
