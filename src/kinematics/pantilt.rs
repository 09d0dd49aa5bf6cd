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
    fn axis_derivatives(&self) -> [Vector3<f64>; 2] {
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

impl PanTilt {
    /// Validates a geometry. δ and θ₀ in (0°, 180°), a home pose must exist
    /// (|cos θ₀| < sin δ), azimuths pairwise distinct, limb indices in 0..3, the actuated limbs
    /// distinct, and the actuation Jacobian regular at home.
    pub fn new(geometry: PanTiltGeometry) -> Result<Self, PanTiltError> {
        let g = &geometry;
        let finite = g.theta0.is_finite() && g.delta.is_finite();
        if !finite || g.theta0 <= 0.0 || g.theta0 >= PI {
            return Err(PanTiltError::Geometry(format!(
                "θ₀ = {}° must lie in (0°, 180°)",
                g.theta0.to_degrees()
            )));
        }
        if g.delta <= 0.0 || g.delta >= PI {
            return Err(PanTiltError::Geometry(format!(
                "δ = {}° must lie in (0°, 180°)",
                g.delta.to_degrees()
            )));
        }
        let s = g.theta0.cos() / g.delta.sin();
        if s.abs() >= 1.0 - 1e-9 {
            return Err(PanTiltError::Geometry(format!(
                "no home pose: cos θ₀ / sin δ = {s} (θ₀ = {}°, δ = {}°) must lie strictly inside (−1, 1)",
                g.theta0.to_degrees(),
                g.delta.to_degrees()
            )));
        }
        for (i, e) in g.azimuths.iter().enumerate() {
            if !e.is_finite() {
                return Err(PanTiltError::Geometry(format!(
                    "azimuth of limb {} is not finite",
                    i + 1
                )));
            }
        }
        for i in 0..3 {
            for j in i + 1..3 {
                if wrap(g.azimuths[i] - g.azimuths[j]).abs() < 1e-6 {
                    return Err(PanTiltError::Geometry(format!(
                        "limbs {} and {} share the azimuth {}°",
                        i + 1,
                        j + 1,
                        g.azimuths[i].to_degrees()
                    )));
                }
            }
        }
        if g.rr_limb > 2 {
            return Err(PanTiltError::Geometry(format!(
                "RR limb {} must be 1, 2 or 3",
                g.rr_limb + 1
            )));
        }
        if g.actuated.iter().any(|&a| a > 2) || g.actuated[0] == g.actuated[1] {
            return Err(PanTiltError::Geometry(format!(
                "actuated limbs {:?} must be two distinct limbs of 1, 2, 3",
                g.actuated.map(|a| a + 1)
            )));
        }
        let mut rrr = [0usize; 2];
        let mut k = 0;
        for j in 0..3 {
            if j != g.rr_limb {
                rrr[k] = j;
                k += 1;
            }
        }
        let mut model = Self {
            geometry,
            beta: s.asin(),
            rrr,
            home_mid: [0.0; 3],
            home_top: [0.0; 2],
        };
        let home = Pointing { gamma: 0.0, phi: 0.0 };
        let (mid, top) = model.raw_angles(&model.limbs(&home)?, &home.axis());
        model.home_mid = mid;
        model.home_top = top;
        model.actuation_jacobian(&home)?;
        Ok(model)
    }

    /// The geometry.
    pub fn geometry(&self) -> &PanTiltGeometry {
        &self.geometry
    }

    /// Home elevation β of the middle axes, rad.
    pub fn beta(&self) -> f64 {
        self.beta
    }

    /// The two RRR limbs (0-based, ascending); their top joints are J7 and J8.
    pub fn rrr_limbs(&self) -> [usize; 2] {
        self.rrr
    }

    /// Closed-form IK of the three limbs (Yu et al. Eqs. 1–11 generalised to any δ): for each
    /// limb, `A cos α + B sin α = C` with `A = sin δ (h·r₇)`, `B = sin δ r₇z`,
    /// `C = cos θ₀ − cos δ (u·r₇)`, solved as `α = asin(C/R) − atan2(A, B)`, R = √(A² + B²):
    /// the branch through the home pose (α = β at γ = 0), continuous until the two branches meet.
    fn limbs(&self, pose: &Pointing) -> Result<[Limb; 3], PanTiltError> {
        let r7 = pose.axis();
        let (sd, cd) = self.geometry.delta.sin_cos();
        let ct0 = self.geometry.theta0.cos();
        let z = Vector3::z();
        let mut out = [Limb {
            u: z,
            m: z,
            m_alpha: z,
            alpha: 0.0,
            dalpha: z,
        }; 3];
        for (j, limb) in out.iter_mut().enumerate() {
            let (se, ce) = self.geometry.azimuths[j].sin_cos();
            let u = Vector3::new(se, -ce, 0.0);
            let h = Vector3::new(ce, se, 0.0);
            let a = sd * h.dot(&r7);
            let b = sd * r7.z;
            let c = ct0 - cd * u.dot(&r7);
            let r = a.hypot(b);
            let ratio = c / r;
            if !ratio.is_finite() || ratio.abs() > 1.0 {
                return Err(PanTiltError::Unreachable {
                    limb: j + 1,
                    gamma_deg: pose.gamma.to_degrees(),
                    phi_deg: pose.phi.to_degrees(),
                    ratio,
                });
            }
            let alpha = wrap(ratio.asin() - a.atan2(b));
            let (sa, ca) = alpha.sin_cos();
            let m = cd * u + sd * (ca * h + sa * z);
            let m_alpha = sd * (-sa * h + ca * z);
            let den = r7.dot(&m_alpha);
            if den.abs() < 1e-12 {
                return Err(PanTiltError::LimbSingular {
                    limb: j + 1,
                    gamma_deg: pose.gamma.to_degrees(),
                    phi_deg: pose.phi.to_degrees(),
                    den,
                });
            }
            *limb = Limb {
                u,
                m,
                m_alpha,
                alpha,
                // m·r₇ = cos θ₀ ⇒ (r₇·m_α) dα + m·dr₇ = 0 (Yu et al. Eq. 15).
                dalpha: -m / den,
            };
        }
        Ok(out)
    }

    /// Raw (not home-referenced) middle and top joint angles.
    fn raw_angles(&self, limbs: &[Limb; 3], r7: &Vector3<f64>) -> ([f64; 3], [f64; 2]) {
        let cd = self.geometry.delta.cos();
        let ct0 = self.geometry.theta0.cos();
        let mut mid = [0.0; 3];
        for (j, l) in limbs.iter().enumerate() {
            let (y, x) = angle_parts(&l.m, &l.u, r7, cd * ct0);
            mid[j] = y.atan2(x);
        }
        let p = &limbs[self.geometry.rr_limb].m;
        let mut top = [0.0; 2];
        for (k, &j) in self.rrr.iter().enumerate() {
            let (y, x) = angle_parts(r7, &limbs[j].m, p, ct0 * ct0);
            top[k] = y.atan2(x);
        }
        (mid, top)
    }

    /// Actuated joint angles (θ₁, θ₂ of the actuated limbs), rad, by the closed-form IK.
    pub fn inverse_kinematics(&self, pose: &Pointing) -> Result<[f64; 2], PanTiltError> {
        let limbs = self.limbs(pose)?;
        let [a, b] = self.geometry.actuated;
        Ok([wrap(limbs[a].alpha - self.beta), wrap(limbs[b].alpha - self.beta)])
    }

    /// All eight joint rotations from home and their gradients.
    ///
    /// Middle joint j (J4–J6): rotation of the outer body (upper link, or the platform for the
    /// RR limb) relative to the lower link about mⱼ, i.e. the change of the signed angle from uⱼ to
    /// r₇ about mⱼ. Top joint (J7, J8): rotation of the platform relative to the upper link about
    /// r₇, the change of the signed angle from mⱼ to the platform-fixed m_RR about r₇.
    pub fn joint_state(&self, pose: &Pointing) -> Result<JointState, PanTiltError> {
        let limbs = self.limbs(pose)?;
        let r7 = pose.axis();
        let cd = self.geometry.delta.cos();
        let ct0 = self.geometry.theta0.cos();
        // Tangents of r₇: s = (r₇ₓ, r₇ᵧ) and x = (γ, φ).
        let ts = regular_tangents(&r7);
        let tx = pose.axis_derivatives();
        let mut q = [0.0; JOINTS];
        let mut grad_s = [Vector2::zeros(); JOINTS];
        let mut grad_x = [Vector2::zeros(); JOINTS];
        // d(angle) along a tangent dr of r₇, per joint.
        let dq = |dr: &Vector3<f64>| -> [f64; JOINTS] {
            let mut d = [0.0; JOINTS];
            let dm = limbs.map(|l| l.m_alpha * l.dalpha.dot(dr));
            for (j, l) in limbs.iter().enumerate() {
                d[j] = l.dalpha.dot(dr);
                let (y, x) = angle_parts(&l.m, &l.u, &r7, cd * ct0);
                let dy = dm[j].dot(&l.u.cross(&r7)) + l.m.dot(&l.u.cross(dr));
                let dx = l.u.dot(dr);
                d[3 + j] = datan2(y, x, dy, dx);
            }
            let rr = self.geometry.rr_limb;
            let p = &limbs[rr].m;
            for (k, &j) in self.rrr.iter().enumerate() {
                let mj = &limbs[j].m;
                let (y, x) = angle_parts(&r7, mj, p, ct0 * ct0);
                let dy = dr.dot(&mj.cross(p)) + r7.dot(&dm[j].cross(p)) + r7.dot(&mj.cross(&dm[rr]));
                let dx = dm[j].dot(p) + mj.dot(&dm[rr]);
                d[6 + k] = datan2(y, x, dy, dx);
            }
            d
        };
        let ds = [dq(&ts[0]), dq(&ts[1])];
        let dx = [dq(&tx[0]), dq(&tx[1])];
        let (mid, top) = self.raw_angles(&limbs, &r7);
        for j in 0..3 {
            q[j] = wrap(limbs[j].alpha - self.beta);
            q[3 + j] = wrap(mid[j] - self.home_mid[j]);
        }
        for k in 0..2 {
            q[6 + k] = wrap(top[k] - self.home_top[k]);
        }
        for i in 0..JOINTS {
            grad_s[i] = Vector2::new(ds[0][i], ds[1][i]);
            grad_x[i] = Vector2::new(dx[0][i], dx[1][i]);
        }
        Ok(JointState { q, grad_s, grad_x })
    }

    /// The paper's 2×2 inverse Jacobian J with θ̇_a = J·[γ̇, φ̇] (Yu et al. Eqs. 15–17:
    /// row j = [Qⱼ/Pⱼ, Rⱼ/Pⱼ]). Its second column is ∝ sin γ: at γ = 0 (the home pose) it is
    /// singular because φ is undefined there, which is a singularity of the (γ, φ) coordinates,
    /// not of the mechanism (see [`PanTilt::actuation_jacobian`]). Returns
    /// [`PanTiltError::PoleSingular`] when |sin γ| < 1e-12.
    pub fn inverse_jacobian(&self, pose: &Pointing) -> Result<Matrix2<f64>, PanTiltError> {
        if pose.gamma.sin().abs() < 1e-12 {
            return Err(PanTiltError::PoleSingular {
                gamma_deg: pose.gamma.to_degrees(),
            });
        }
        let limbs = self.limbs(pose)?;
        let tx = pose.axis_derivatives();
        let [a, b] = self.geometry.actuated;
        Ok(Matrix2::new(
            limbs[a].dalpha.dot(&tx[0]),
            limbs[a].dalpha.dot(&tx[1]),
            limbs[b].dalpha.dot(&tx[0]),
            limbs[b].dalpha.dot(&tx[1]),
        ))
    }

    /// The actuation Jacobian ∂θ_a/∂s in the regular coordinates s = (r₇ₓ, r₇ᵧ), regular at
    /// γ = 0; an error if it is singular (the actuators lose control of the platform).
    pub fn actuation_jacobian(&self, pose: &Pointing) -> Result<Matrix2<f64>, PanTiltError> {
        let limbs = self.limbs(pose)?;
        self.actuation_jacobian_of(pose, &limbs)
    }

    fn actuation_jacobian_of(&self, pose: &Pointing, limbs: &[Limb; 3]) -> Result<Matrix2<f64>, PanTiltError> {
        let r7 = pose.axis();
        let ts = regular_tangents(&r7);
        let [a, b] = self.geometry.actuated;
        let j = Matrix2::new(
            limbs[a].dalpha.dot(&ts[0]),
            limbs[a].dalpha.dot(&ts[1]),
            limbs[b].dalpha.dot(&ts[0]),
            limbs[b].dalpha.dot(&ts[1]),
        );
        regular_actuation(pose, j)
    }

    /// Forward kinematics by Newton's method on the closed-form IK in the regular coordinates
    /// s = (r₇ₓ, r₇ᵧ), started from `start` (the home pose if `None`), so the solution found is
    /// the assembly continuous from the start. Returns γ, φ (φ = 0 at γ = 0). Converges when the
    /// IK residual is below 1e-14 rad.
    pub fn forward_kinematics(&self, theta: [f64; 2], start: Option<Pointing>) -> Result<Pointing, PanTiltError> {
        const MAX_ITER: usize = 50;
        let start = start.unwrap_or(Pointing { gamma: 0.0, phi: 0.0 });
        let r0 = start.axis();
        let mut s = Vector2::new(r0.x, r0.y);
        let target = Vector2::new(theta[0], theta[1]);
        let fail = |iterations: usize, residual: f64, reason: &str| PanTiltError::NoConvergence {
            theta_deg: theta.map(f64::to_degrees),
            iterations,
            residual,
            reason: reason.to_string(),
        };
        let mut residual = f64::INFINITY;
        for it in 0..MAX_ITER {
            let pose = Self::pose_of(&s)
                .ok_or_else(|| fail(it, residual, "the iterate left the upper hemisphere (γ ≥ 90°)"))?;
            let limbs = self.limbs(&pose).map_err(|e| fail(it, residual, &e.to_string()))?;
            let [a, b] = self.geometry.actuated;
            let f = Vector2::new(
                wrap(limbs[a].alpha - self.beta - target[0]),
                wrap(limbs[b].alpha - self.beta - target[1]),
            );
            residual = f.amax();
            if residual < 1e-14 {
                return Ok(pose);
            }
            let j = self
                .actuation_jacobian_of(&pose, &limbs)
                .map_err(|e| fail(it, residual, &e.to_string()))?;
            let step = j
                .try_inverse()
                .ok_or_else(|| fail(it, residual, "singular Newton matrix"))?
                * f;
            if step.amax() < 1e-16 && residual < 1e-12 {
                // Round-off floor: the Newton step no longer moves the iterate.
                return Ok(pose);
            }
            s -= step;
        }
        Err(fail(MAX_ITER, residual, "iteration limit"))
    }

    /// Pose of the regular coordinates s = (r₇ₓ, r₇ᵧ), `None` outside the open upper hemisphere.
    fn pose_of(s: &Vector2<f64>) -> Option<Pointing> {
        let n2 = s.norm_squared();
        if !n2.is_finite() || n2 >= 1.0 {
            return None;
        }
        let sg = n2.sqrt();
        let gamma = sg.atan2((1.0 - n2).sqrt());
        let phi = if sg > 0.0 { s.y.atan2(s.x) } else { 0.0 };
        Some(Pointing { gamma, phi })
    }

    /// Joint rotations, joint rates and quasi-static actuator torques at one path sample.
    pub fn path_state(&self, sample: &PathSample, springs: &JointSprings) -> Result<PathState, PanTiltError> {
        let js = self.joint_state(&sample.pose)?;
        let [a, b] = self.geometry.actuated;
        let jac = regular_actuation(
            &sample.pose,
            Matrix2::new(js.grad_s[a][0], js.grad_s[a][1], js.grad_s[b][0], js.grad_s[b][1]),
        )?;
        let det = jac.determinant();
        let xdot = Vector2::new(sample.gamma_rate, sample.phi_rate);
        let mut q_rate = [0.0; JOINTS];
        let mut gk = Vector2::zeros();
        let mut gd = Vector2::zeros();
        for (i, rate) in q_rate.iter_mut().enumerate() {
            *rate = js.grad_x[i].dot(&xdot);
            gk += js.grad_s[i] * (springs.stiffness[i] * js.q[i]);
            gd += js.grad_s[i] * (springs.damping[i] * *rate);
        }
        // τ = J_s⁻ᵀ G_sᵀ f: solve J_sᵀ τ = G_sᵀ f.
        let jt_inv = Matrix2::new(jac[(1, 1)], -jac[(1, 0)], -jac[(0, 1)], jac[(0, 0)]) / det;
        let tk = jt_inv * gk;
        let td = jt_inv * gd;
        Ok(PathState {
            sample: *sample,
            q: js.q,
            q_rate,
            torque_stiffness: [tk[0], tk[1]],
            torque_damping: [td[0], td[1]],
            det_actuation: det,
        })
    }

    /// [`PanTilt::path_state`] at every sample; stops at the first failing sample.
    pub fn path(&self, samples: &[PathSample], springs: &JointSprings) -> Result<Vec<PathState>, PanTiltError> {
        samples.iter().map(|s| self.path_state(s, springs)).collect()
    }
}
