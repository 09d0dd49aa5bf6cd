//! Pseudo-rigid-body model (PRBM) of the 8R (RRR–RR–RRR) spherical compliant parallel pan-tilt
//! platform of J. Yu, D. Lu and G. Hao, "Design and analysis of a compliant parallel pan-tilt
//! platform", Meccanica (2016) (§3 kinematics,
//! §4 joint damping and input torques).
//!
//! # Geometry
//! Fixed frame {x, y, z}, z up, origin at the common centre of all joint axes (a spherical
//! mechanism: every axis passes through it, so only directions matter and no length enters).
//! Three limbs at azimuths εⱼ (j = 1, 2, 3). Limb j has a horizontal bottom joint with axis
//! `uⱼ = [sin εⱼ, −cos εⱼ, 0]` (perpendicular to the limb's vertical plane) and a middle joint whose
//! axis makes the angle δ with uⱼ:
//!
//! `mⱼ = cos δ·uⱼ + sin δ·(cos αⱼ·hⱼ + sin αⱼ·z)`,  `hⱼ = [cos εⱼ, sin εⱼ, 0]`,  `αⱼ = βⱼ + θⱼ`,
//!
//! where θⱼ is the bottom joint rotation from home (positive raises mⱼ) and β the home elevation.
//! The platform direction (the axis of the top joints) is
//! `r₇ = [sin γ cos φ, sin γ sin φ, cos γ]` with pitch γ and phase φ, and every middle axis keeps
//! the angle θ₀ to it, `mⱼ·r₇ = cos θ₀` (Yu et al. Eq. 14). At home (r₇ = z) this fixes
//! `sin δ·sin β = cos θ₀`; the paper's δ = 90°, θ₀ = 60° give β = 30° (its β₁ = β₂ = π/6).
//!
//! Two limbs are RRR: bottom, middle and a top joint about r₇ (the two top joints are coaxial,
//! "R13 and R33 share the same axis"). The third limb is RR: its middle joint is fixed in the
//! platform, so it sets the platform's spin about r₇. The eight joints are numbered
//! J1–J3 bottom joints of limbs 1–3, J4–J6 middle joints of limbs 1–3, J7–J8 top joints of the
//! two RRR limbs in limb order. Bottom joints of two limbs are actuated (paper: J1 and J2).
//!
//! # Readings of the printed paper
//! * The printed azimuth ε₁ = π/2 gives θ₁ = −6.86° in the paper's worked example
//!   (γ = 10°, φ = 45°), not the printed θ₁ = +7.36°. The azimuth ε₁ = −π/2 (= 3π/2) with the
//!   printed ε₂ = 5π/6 reproduces both θ₁ = 7.36° and θ₂ = 3.09°, and puts the three limbs 120°
//!   apart (ε₃ = π/6): that is the default here.
//! * With limbs 1 and 2 actuated, the RR limb must be limb 2 (the actuated J2's own limb): the
//!   mechanism is then asymmetric and the quasi-static torques on the 10° circle peak at
//!   303.9 / 255.9 N·mm, matching the paper's Table 5 (303.7 / 255.6); an RR limb 3 would make the
//!   mechanism mirror-symmetric and the two peaks equal.
//!
//! # Torques
//! Quasi-static virtual work with a torsional spring Kᵢ and a viscous damper Dᵢ on every joint
//! i (all joint rotations measured from the unstressed home pose):
//! `τ·δθ_a = Σᵢ (Kᵢ qᵢ + Dᵢ q̇ᵢ) δqᵢ` for every motion δr₇ on the sphere, so
//! `τ = J_s⁻ᵀ G_sᵀ (K q + D q̇)` with G_s = ∂q/∂s and J_s = ∂θ_a/∂s in the regular coordinates
//! s = (r₇ₓ, r₇ᵧ) (valid for γ < 90°, no singularity at γ = 0). Inertia is not modelled (the paper
//! gives no masses); the paper's ADAMS inverse dynamics agree within 0.4 % (Table 5).
//!
//! The paper's circle (γ = 10°, period 1 s) was sampled every 0.01 s: Table 4's 9.998° and
//! 11.56° entries are the peaks of J2, J3, J5, J6 missed by 1.2° of φ, reproduced exactly on that
//! grid. Damping makes torques depend on the direction of travel; φ increasing with time
//! reproduces Table 5 (φ decreasing puts the damped J1 peak 1.7 % off).
//!
//! Units: radians, seconds, N·mm inside this module; degrees only at the I/O boundary.

use nalgebra::{Matrix2, Vector2, Vector3};
use std::f64::consts::PI;
use thiserror::Error;

mod fk;
mod ik;
mod pointing;

pub use pointing::{circle, JointSprings, JointState, PathSample, PathState, Pointing};

/// Number of joints of the 8R mechanism.
pub const JOINTS: usize = 8;

/// Errors of the pan-tilt PRBM.
#[derive(Debug, Error, Clone, PartialEq)]
pub enum PanTiltError {
    /// The geometry is not a valid 8R pan-tilt.
    #[error("invalid pan-tilt geometry: {0}")]
    Geometry(String),
    /// A platform direction that a limb cannot reach (|C/R| > 1 in its closed-form IK).
    #[error("pose unreachable: limb {limb} cannot keep its middle axis at θ₀ to the platform axis at γ = {gamma_deg:.6}°, φ = {phi_deg:.6}° (needs sin = {ratio:.6}, beyond ±1)")]
    Unreachable {
        /// Limb number, 1-based.
        limb: usize,
        /// Pitch γ, degrees.
        gamma_deg: f64,
        /// Phase φ, degrees.
        phi_deg: f64,
        /// The sine the closed form asks for.
        ratio: f64,
    },
    /// A limb at its own (serial) singularity: its two IK branches meet.
    #[error(
        "limb {limb} singular at γ = {gamma_deg:.6}°, φ = {phi_deg:.6}°: its IK branches meet (r₇·∂m/∂α = {den:.3e})"
    )]
    LimbSingular {
        /// Limb number, 1-based.
        limb: usize,
        /// Pitch γ, degrees.
        gamma_deg: f64,
        /// Phase φ, degrees.
        phi_deg: f64,
        /// r₇·∂m/∂α.
        den: f64,
    },
    /// The actuated joints cannot hold the platform (singular 2×2 actuation Jacobian in the
    /// regular coordinates).
    #[error("actuation singular at γ = {gamma_deg:.6}°, φ = {phi_deg:.6}°: det ∂θ_a/∂(r₇ₓ, r₇ᵧ) = {det:.3e}")]
    ActuationSingular {
        /// Pitch γ, degrees.
        gamma_deg: f64,
        /// Phase φ, degrees.
        phi_deg: f64,
        /// Determinant.
        det: f64,
    },
    /// The (γ, φ) inverse Jacobian is singular: at γ = 0 the phase φ is undefined.
    #[error("the (γ, φ) inverse Jacobian is singular at γ = {gamma_deg:.3e}° (φ is undefined at γ = 0)")]
    PoleSingular {
        /// Pitch γ, degrees.
        gamma_deg: f64,
    },
    /// The forward kinematics did not converge.
    #[error("forward kinematics did not converge for actuated angles {theta_deg:?}° after {iterations} Newton iterations (residual {residual:.3e} rad): {reason}")]
    NoConvergence {
        /// Actuated joint angles, degrees.
        theta_deg: [f64; 2],
        /// Iterations performed.
        iterations: usize,
        /// Final residual, rad.
        residual: f64,
        /// Why it stopped.
        reason: String,
    },
}

/// Geometry of the 8R pan-tilt (angles in rad).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct PanTiltGeometry {
    /// θ₀: angle between each middle axis and the top (platform) axis, rad. Paper: 60°.
    pub theta0: f64,
    /// δ: angle between the bottom and middle axes of a limb, rad. Paper: 90°.
    pub delta: f64,
    /// Limb azimuths εⱼ, rad. Default −90°, 150°, 30° (see the module doc for the reading).
    pub azimuths: [f64; 3],
    /// Index (0-based) of the RR limb. Default 1 (limb 2).
    pub rr_limb: usize,
    /// Indices (0-based) of the limbs whose bottom joints are actuated. Default [0, 1] (J1, J2).
    pub actuated: [usize; 2],
}

impl Default for PanTiltGeometry {
    /// The pan-tilt of Yu, Lu and Hao (2016): θ₀ = 60°, δ = 90°, ε = −90°/150°/30°, limb 2 RR,
    /// J1 and J2 actuated.
    fn default() -> Self {
        Self {
            theta0: PI / 3.0,
            delta: PI / 2.0,
            azimuths: [-PI / 2.0, 5.0 * PI / 6.0, PI / 6.0],
            rr_limb: 1,
            actuated: [0, 1],
        }
    }
}

/// The validated 8R pan-tilt PRBM.
#[derive(Debug, Clone, PartialEq)]
pub struct PanTilt {
    geometry: PanTiltGeometry,
    /// Home elevation β of every middle axis, rad.
    beta: f64,
    /// The two RRR limbs (0-based, ascending).
    rrr: [usize; 2],
    /// Home values of the raw middle-joint angles (J4–J6) and top-joint angles (J7–J8), rad.
    home_mid: [f64; 3],
    home_top: [f64; 2],
}

/// One limb solved at a pose.
#[derive(Debug, Clone, Copy)]
struct Limb {
    u: Vector3<f64>,
    m: Vector3<f64>,
    /// ∂m/∂α.
    m_alpha: Vector3<f64>,
    alpha: f64,
    /// ∂α/∂r₇ (gradient in ℝ³, to be contracted with a tangent of r₇).
    dalpha: Vector3<f64>,
}

/// The (y, x) pair of atan2 for the signed angle about the unit axis `a` from `v` to `w`, both
/// projected on the plane normal to `a`; `cos_prod` = (v·a)(w·a), constant for every joint here.
fn angle_parts(a: &Vector3<f64>, v: &Vector3<f64>, w: &Vector3<f64>, cos_prod: f64) -> (f64, f64) {
    (a.dot(&v.cross(w)), v.dot(w) - cos_prod)
}

/// d atan2(y, x) from dy and dx.
fn datan2(y: f64, x: f64, dy: f64, dx: f64) -> f64 {
    (x * dy - y * dx) / (x * x + y * y)
}

/// Tangents ∂r₇/∂s of the regular coordinates s = (r₇ₓ, r₇ᵧ), r₇z = √(1 − r₇ₓ² − r₇ᵧ²).
fn regular_tangents(r7: &Vector3<f64>) -> [Vector3<f64>; 2] {
    [
        Vector3::new(1.0, 0.0, -r7.x / r7.z),
        Vector3::new(0.0, 1.0, -r7.y / r7.z),
    ]
}

/// `j` = ∂θ_a/∂s if it is regular (|det| ≥ 1e-10‖j‖²), else the actuation-singularity error.
fn regular_actuation(pose: &Pointing, j: Matrix2<f64>) -> Result<Matrix2<f64>, PanTiltError> {
    let det = j.determinant();
    let scale = j.norm_squared().max(f64::MIN_POSITIVE);
    if !det.is_finite() || det.abs() < 1e-10 * scale {
        return Err(PanTiltError::ActuationSingular {
            gamma_deg: pose.gamma.to_degrees(),
            phi_deg: pose.phi.to_degrees(),
            det,
        });
    }
    Ok(j)
}

fn wrap(a: f64) -> f64 {
    (a + PI).rem_euclid(2.0 * PI) - PI
}
