//! Rigid-body kinematics of the 3-PRS parallel mechanism (Ruiz et al. 2019, §3).
//!
//! Fixed frame {x, y, z} at the base centre O, z up; moving frame {u, v, w} at the platform
//! centre P. Orientation `R = Ry(θ)·Rx(ψ)·Rz(φ)`. Leg i lies in the vertical plane through O
//! and `dᵢ = [cos ξᵢ, sin ξᵢ, 0]`, ξᵢ = 0°, 120°, 240°. The slider moves along
//! `eᵢ = −cos γ·dᵢ + sin γ·z` from `Aᵢ = a·dᵢ` (zero stroke); the revolute joint centre is
//! `Cᵢ = Aᵢ + sᵢ·eᵢ`, the spherical joint `Bᵢ = p + R·(b dᵢ)`, and `|Bᵢ − Cᵢ| = L`.
//!
//! The revolute joints keep each `Bᵢ` in its leg plane; this fixes the parasitic motions
//! `φ = atan2(sψ·sθ, cψ + cθ)`, `pₓ = (b/2)(uₓ − v_y)`, `p_y = −b·u_y` (Ruiz et al. (2019) Eqs. 13–15).
//!
//! All poses in this module's public API are measured from the home pose (ψ = θ = φ = 0,
//! `p = [0, 0, z₀]`): `z` is the platform's vertical displacement from home, in mm.
//!
//! Files: this one holds the geometry ([`Prs`], leg directions and joint points), the pose and
//! solution types and the errors; `prs/rotation.rs` the rotation matrices, `prs/position.rs` the
//! inverse and forward kinematics, `prs/jacobian.rs` the Jacobians.

mod jacobian;
mod position;
mod rotation;

use nalgebra::{Matrix3, Vector3};
pub use rotation::{intrinsic_xyz, orientation, parasitic_phi, rot_x, rot_y, rot_z};
use thiserror::Error;

/// Leg plane angles ξᵢ, rad.
pub(crate) const XI: [f64; 3] = [
    0.0,
    2.0 * std::f64::consts::FRAC_PI_3,
    4.0 * std::f64::consts::FRAC_PI_3,
];

/// Unit radial direction dᵢ = Rz(ξᵢ)·[1, 0, 0] of leg `i` (0-based).
pub fn radial(i: usize) -> Vector3<f64> {
    Vector3::new(XI[i].cos(), XI[i].sin(), 0.0)
}

/// Unit slider direction eᵢ = −cos γ·dᵢ + sin γ·z of leg `i` for actuator inclination `gamma` (rad).
pub(crate) fn slider_dir(gamma: f64, i: usize) -> Vector3<f64> {
    -gamma.cos() * radial(i) + gamma.sin() * Vector3::z()
}

/// Revolute axis mᵢ = Rz(ξᵢ)·[0, 1, 0] of leg `i` (normal of the leg plane).
pub fn revolute_axis(i: usize) -> Vector3<f64> {
    Vector3::new(-XI[i].sin(), XI[i].cos(), 0.0)
}

/// Errors of the rigid-body kinematics.
#[derive(Debug, Error, Clone, PartialEq)]
pub enum KinematicsError {
    /// The geometry is not a valid 3-PRS.
    #[error("invalid 3-PRS geometry: {0}")]
    Geometry(String),
    /// A pose that no stroke can reach (a leg is too short).
    #[error("pose unreachable: leg {leg} cannot reach its spherical joint (needs {needed:.6} mm of leg in the slider plane, has L = {length} mm)")]
    Unreachable {
        /// Leg number, 1-based.
        leg: usize,
        /// Distance needed, mm.
        needed: f64,
        /// Leg length L, mm.
        length: f64,
    },
    /// The forward kinematics did not converge.
    #[error("forward kinematics did not converge for strokes {strokes:?} mm after {iterations} Newton iterations (residual {residual:.3e} mm): {reason}")]
    NoConvergence {
        /// Actuator strokes, mm.
        strokes: [f64; 3],
        /// Iterations performed.
        iterations: usize,
        /// Final residual of the leg-length equations, mm.
        residual: f64,
        /// Why it stopped.
        reason: String,
    },
    /// The Jacobian is singular (a singular configuration of the mechanism).
    #[error("singular configuration at z = {z:.6} mm, ψ = {psi_deg:.6}°, θ = {theta_deg:.6}°: the actuation Jacobian has determinant {det:.3e}")]
    Singular {
        /// Platform z displacement from home, mm.
        z: f64,
        /// ψ, degrees.
        psi_deg: f64,
        /// θ, degrees.
        theta_deg: f64,
        /// Determinant of ∂f/∂(z, ψ, θ).
        det: f64,
    },
}

/// Geometry of a 3-PRS mechanism.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Prs {
    /// Leg length L (revolute centre to spherical centre), mm.
    pub l: f64,
    /// Platform radius b (P to each spherical joint centre), mm.
    pub b: f64,
    /// Base radius a (O to each slider's zero-stroke point Aᵢ), mm.
    pub a: f64,
    /// Actuator inclination γ, rad (0 = horizontal radially inward, π/2 = vertical).
    pub gamma: f64,
    /// Home height z₀ of the platform centre above the plane of the Aᵢ, mm.
    pub z0: f64,
}

/// A platform pose measured from home: displacements in mm, angles in rad.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct Pose {
    /// x displacement of P, mm.
    pub x: f64,
    /// y displacement of P, mm.
    pub y: f64,
    /// z displacement of P from home, mm.
    pub z: f64,
    /// Rotation ψ about x, rad.
    pub psi: f64,
    /// Rotation θ about y, rad.
    pub theta: f64,
    /// Rotation φ about z, rad.
    pub phi: f64,
}

/// Inverse kinematics solution at one pose.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct IkpSolution {
    /// Actuator strokes sᵢ, mm (0 at home).
    pub s: [f64; 3],
    /// Full pose including the parasitic x, y, φ.
    pub pose: Pose,
    /// Revolute angles αᵢ = arccos(eᵢ·lᵢ), rad.
    pub alpha: [f64; 3],
    /// Spherical joint angles [βm, βn, βl] per leg, rad (intrinsic m-n-l sequence).
    pub spherical: [[f64; 3]; 3],
}

/// Forward kinematics solution.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct FkpSolution {
    /// Platform pose (parasitic components included).
    pub pose: Pose,
    /// Newton iterations used.
    pub iterations: usize,
}

impl Prs {
    /// The 3-PRS of Ruiz et al. (2019) §3 with `a = b + L·cos α₀`, home height `z₀ = L·sin α₀`.
    ///
    /// `l`, `b` in mm; `alpha0` (leg angle to the horizontal at home) and `gamma` in rad.
    pub fn new(l: f64, b: f64, alpha0: f64, gamma: f64) -> Result<Self, KinematicsError> {
        Self::check_common(l, b, gamma)?;
        if !(alpha0 > 0.0 && alpha0 < std::f64::consts::FRAC_PI_2) {
            return Err(KinematicsError::Geometry(format!(
                "alpha0 = {}° must lie in (0°, 90°)",
                alpha0.to_degrees()
            )));
        }
        let prs = Prs {
            l,
            b,
            a: b + l * alpha0.cos(),
            gamma,
            z0: l * alpha0.sin(),
        };
        prs.check_actuation()?;
        Ok(prs)
    }

    /// A 3-PRS given the base radius `a` instead of α₀: home height `z₀ = √(L² − (a − b)²)`.
    pub fn with_base_radius(l: f64, b: f64, a: f64, gamma: f64) -> Result<Self, KinematicsError> {
        Self::check_common(l, b, gamma)?;
        if !(a.is_finite() && a > 0.0) {
            return Err(KinematicsError::Geometry(format!("a = {a} mm must be positive")));
        }
        let h2 = l * l - (a - b) * (a - b);
        if h2 <= 0.0 {
            return Err(KinematicsError::Geometry(format!(
                "L = {l} mm is too short to reach from the base circle (a = {a} mm) to the platform circle (b = {b} mm): L must exceed |a − b| = {} mm",
                (a - b).abs()
            )));
        }
        let prs = Prs {
            l,
            b,
            a,
            gamma,
            z0: h2.sqrt(),
        };
        prs.check_actuation()?;
        Ok(prs)
    }

    fn check_common(l: f64, b: f64, gamma: f64) -> Result<(), KinematicsError> {
        if !(l.is_finite() && l > 0.0) {
            return Err(KinematicsError::Geometry(format!("L = {l} mm must be positive")));
        }
        if !(b.is_finite() && b > 0.0) {
            return Err(KinematicsError::Geometry(format!("b = {b} mm must be positive")));
        }
        if !(gamma.is_finite() && gamma.abs() <= std::f64::consts::FRAC_PI_2 + 1e-12) {
            return Err(KinematicsError::Geometry(format!(
                "gamma = {}° must lie in [−90°, 90°]",
                gamma.to_degrees()
            )));
        }
        Ok(())
    }

    /// Refuses layouts where the slider is (nearly) perpendicular to the leg at home:
    /// there the actuator cannot move the platform (an actuation singularity).
    fn check_actuation(&self) -> Result<(), KinematicsError> {
        let c = self.e(0).dot(&self.leg_home(0)) / self.l;
        if c < 0.05 {
            return Err(KinematicsError::Geometry(format!(
                "the slider direction is within {:.1}° of perpendicular to the leg at home (α₀ − γ ≈ ±90°): actuation singularity",
                90.0 - c.clamp(-1.0, 1.0).acos().to_degrees()
            )));
        }
        Ok(())
    }

    /// The leg angle to the horizontal at home, α₀, rad.
    pub fn alpha0(&self) -> f64 {
        self.z0.atan2(self.a - self.b)
    }

    /// Unit radial direction dᵢ of leg `i` (0-based).
    pub fn d(&self, i: usize) -> Vector3<f64> {
        radial(i)
    }

    /// Unit slider direction eᵢ = −cos γ·dᵢ + sin γ·z.
    pub fn e(&self, i: usize) -> Vector3<f64> {
        slider_dir(self.gamma, i)
    }

    /// Revolute axis mᵢ = Rz(ξᵢ)·[0, 1, 0].
    pub fn m(&self, i: usize) -> Vector3<f64> {
        revolute_axis(i)
    }

    /// Zero-stroke slider point Aᵢ = a·dᵢ, mm.
    pub fn a_point(&self, i: usize) -> Vector3<f64> {
        self.a * self.d(i)
    }

    /// Revolute joint centre Cᵢ = Aᵢ + sᵢ·eᵢ, mm.
    pub fn c_point(&self, i: usize, s: f64) -> Vector3<f64> {
        self.a_point(i) + s * self.e(i)
    }

    /// Spherical joint centre Bᵢ at the home pose, mm.
    pub fn b_home(&self, i: usize) -> Vector3<f64> {
        self.b * self.d(i) + self.z0 * Vector3::z()
    }

    /// Platform centre P at the home pose, mm.
    pub fn p_home(&self) -> Vector3<f64> {
        self.z0 * Vector3::z()
    }

    fn leg_home(&self, i: usize) -> Vector3<f64> {
        self.b_home(i) - self.a_point(i)
    }

    /// Leg frame Fᵢ₀ = [mᵢ₀ nᵢ₀ lᵢ₀] for a leg direction `l` (unit, C→B).
    fn leg_frame(&self, i: usize, l: &Vector3<f64>) -> Matrix3<f64> {
        let m = self.m(i);
        let n = l.cross(&m);
        Matrix3::from_columns(&[m, n, *l])
    }

    /// Full pose (with parasitic x, y, φ) for independent coordinates measured from home.
    pub fn complete_pose(&self, z: f64, psi: f64, theta: f64) -> Pose {
        let phi = parasitic_phi(psi, theta);
        let r = orientation(psi, theta, phi);
        Pose {
            x: 0.5 * self.b * (r[(0, 0)] - r[(1, 1)]),
            y: -self.b * r[(1, 0)],
            z,
            psi,
            theta,
            phi,
        }
    }

    /// Absolute platform centre and rotation of a pose.
    pub fn placement(&self, pose: &Pose) -> (Vector3<f64>, Matrix3<f64>) {
        (
            Vector3::new(pose.x, pose.y, self.z0 + pose.z),
            orientation(pose.psi, pose.theta, pose.phi),
        )
    }

    /// Spherical joint centre Bᵢ = p + R·(b dᵢ) for a full pose, mm.
    pub fn b_point(&self, i: usize, pose: &Pose) -> Vector3<f64> {
        let (p, r) = self.placement(pose);
        p + r * (self.b * self.d(i))
    }
}
