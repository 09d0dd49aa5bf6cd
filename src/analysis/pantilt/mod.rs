//! The `pantilt` analysis: PRBM kinematics and quasi-static actuation torques of the 8R
//! compliant parallel pan-tilt of J. Yu, D. Lu and G. Hao, "Design and analysis of a compliant
//! parallel pan-tilt platform", Meccanica (2016).
//! Results in degrees, N·mm and s.
//!
//! Files: this one holds the result types and the analysis kind; `pantilt/solve.rs` the
//! solution of a case and its warnings, `pantilt/report.rs` the report and plots.

mod report;
mod solve;

use crate::analysis::common::kind::{Analysis, Ctx};
use super::{Report, RunError};
use crate::case::pantilt::PanTiltCase;
use crate::case::CaseError;
use crate::kinematics::pantilt::JOINTS;
pub use report::{plots, report};
use serde::Serialize;
pub use solve::{solve, warnings};

/// Pitch below which the (γ, φ) inverse Jacobian is reported as singular (φ undefined at γ = 0),
/// degrees.
pub const POLE_WARNING_DEG: f64 = 1.0;

/// Fraction of the home actuation-Jacobian determinant below which a path point is reported as
/// close to an actuation singularity.
pub const NEAR_SINGULAR_FRACTION: f64 = 0.1;

/// Names of the eight joints, in result order.
pub const JOINT_NAMES: [&str; JOINTS] = ["J1", "J2", "J3", "J4", "J5", "J6", "J7", "J8"];

/// Derived geometry, echoed.
#[derive(Debug, Clone, Serialize)]
pub struct GeometryOut {
    /// θ₀, degrees.
    pub theta0_deg: f64,
    /// δ, degrees.
    pub delta_deg: f64,
    /// Home elevation β of the middle joint axes, degrees.
    pub beta_deg: f64,
    /// Limb azimuths ε, degrees.
    pub azimuths_deg: [f64; 3],
    /// The RR limb (1-based).
    pub rr_limb: usize,
    /// The actuated limbs (1-based); their bottom joints are the actuators.
    pub actuated: [usize; 2],
    /// What each of J1–J8 is (limb and position).
    pub joints: Vec<String>,
}

/// One IK answer.
#[derive(Debug, Clone, Serialize)]
pub struct IkRow {
    /// Pitch γ, degrees.
    pub gamma_deg: f64,
    /// Phase φ, degrees.
    pub phi_deg: f64,
    /// Actuated joint rotations θ from home, degrees.
    pub theta_deg: [f64; 2],
    /// All eight joint rotations from home, degrees.
    pub joints_deg: [f64; JOINTS],
    /// The inverse Jacobian ∂θ/∂(γ, φ) (deg/deg; Yu et al. Eq. 17), rows per actuator. Its φ
    /// column vanishes at γ = 0 (φ undefined there).
    pub inverse_jacobian: [[f64; 2]; 2],
    /// Its determinant (∝ sin γ).
    pub inverse_jacobian_det: f64,
    /// True within `POLE_WARNING_DEG` of γ = 0, where the inverse Jacobian is singular.
    pub pole_singular: bool,
}

/// One FK answer.
#[derive(Debug, Clone, Serialize)]
pub struct FkRow {
    /// Actuated joint rotations, degrees.
    pub theta_deg: [f64; 2],
    /// Pitch γ, degrees.
    pub gamma_deg: f64,
    /// Phase φ, degrees (0 at γ = 0, where it is undefined).
    pub phi_deg: f64,
}

/// One path point.
#[derive(Debug, Clone, Serialize)]
pub struct PathRow {
    /// Time, s.
    pub t: f64,
    /// Pitch γ, degrees.
    pub gamma_deg: f64,
    /// Phase φ, degrees.
    pub phi_deg: f64,
    /// Joint rotations J1–J8 from home, degrees.
    pub joints_deg: [f64; JOINTS],
    /// Joint rates, degrees/s.
    pub joint_rates_deg_per_s: [f64; JOINTS],
    /// Actuator torques with the springs only, N·mm.
    pub torque_undamped: [f64; 2],
    /// Actuator torques with springs and dampers, N·mm.
    pub torque_damped: [f64; 2],
}

/// A maximum of |value| along the path and where it occurs.
#[derive(Debug, Clone, Copy, Serialize)]
pub struct Peak {
    /// Largest |value|.
    pub max_abs: f64,
    /// The signed value there.
    pub value: f64,
    /// Time, s.
    pub t: f64,
    /// Phase φ there, degrees.
    pub phi_deg: f64,
}

/// Path results: maxima and rows.
#[derive(Debug, Clone, Serialize)]
pub struct PathOut {
    /// Number of points.
    pub points: usize,
    /// Largest |rotation| per joint J1–J8, degrees.
    pub max_joint_rotation_deg: Vec<Peak>,
    /// Largest |torque| per actuator, springs only, N·mm.
    pub max_torque_undamped: Vec<Peak>,
    /// Largest |torque| per actuator, springs and dampers, N·mm.
    pub max_torque_damped: Vec<Peak>,
    /// Largest |damped − undamped| torque per actuator (the damper share), N·mm.
    pub max_torque_damping_share: Vec<Peak>,
    /// Smallest pitch on the path, degrees.
    pub min_gamma_deg: f64,
    /// Smallest |det ∂θ_a/∂(r₇ₓ, r₇ᵧ)| on the path relative to its home value.
    pub min_actuation_det_ratio: f64,
    /// Per-point rows.
    pub rows: Vec<PathRow>,
}

/// Result of the `pantilt` analysis.
#[derive(Debug, Clone, Serialize)]
pub struct PanTiltResult {
    /// Geometry.
    pub geometry: GeometryOut,
    /// Joint stiffness K, N·mm/degree, J1–J8.
    pub stiffness_per_deg: [f64; JOINTS],
    /// Joint damping D, N·mm·s/degree, J1–J8.
    pub damping_per_deg: [f64; JOINTS],
    /// IK answers in query order.
    pub ik: Vec<IkRow>,
    /// FK answers in query order.
    pub fk: Vec<FkRow>,
    /// Path results, if a path was given.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub path: Option<PathOut>,
    /// Idealisations of this analysis.
    pub model: Vec<&'static str>,
}

/// `pantilt`: the 8R pan-tilt PRBM.
pub struct PanTiltKind;

impl Analysis for PanTiltKind {
    type Case = PanTiltCase;
    type Result = PanTiltResult;

    fn check(case: &Self::Case) -> Result<(), CaseError> {
        case.validate().map(|_| ())
    }
    fn run(case: &Self::Case, ctx: &mut Ctx) -> Result<Self::Result, RunError> {
        let r = solve(&case.validate()?)?;
        if ctx.with_files {
            ctx.files.extend(plots(&r));
        }
        Ok(r)
    }
    fn report(r: &Self::Result) -> Report {
        report(r)
    }
    fn result_warnings(_case: &Self::Case, r: &Self::Result) -> Vec<String> {
        warnings(r)
    }
}
