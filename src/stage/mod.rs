//! The monolithic 3-PRS compliant stage as one beam FE model (Ruiz et al. 2019, §5).
//!
//! Leg i runs from the revolute centre Cᵢ to the spherical centre Bᵢ (home pose of
//! [`crate::kinematics::Prs`]). Along it, from the slider up:
//!
//! * the **slider**: a rigid body guided along eᵢ. Its node sits at the lower end of the
//!   revolute notch, Cᵢ − h_r·lᵢ, with a node frame (eᵢ, mᵢ, eᵢ × mᵢ): the five DOFs other than
//!   the translation along eᵢ are fixed; that one carries the actuator force or the prescribed
//!   stroke;
//! * the **revolute notch** centred at Cᵢ, compliant axis mᵢ (the notch thins along nᵢ = lᵢ × mᵢ),
//!   as one flexibility element whose 6×6 compliance is the exact variable-section Timoshenko
//!   flexibility of the notch with Vlasov (warping-restrained) torsion ([`crate::hinge`]);
//! * the **leg**: a prismatic w × h Timoshenko beam (w along mᵢ) from the top of the notch to
//!   the bottom of the neck, in `leg_elements` elements;
//! * the **spherical neck** centred at Bᵢ, one flexibility element;
//! * the **platform**: a rigid body (rigid link from the platform centre P to the three neck
//!   tops).
//!
//! With `ideal_joints` the hinges become exact releases (revolute: every DOF tied but the
//! rotation about mᵢ; spherical: translations tied) and legs and platform are made 10⁶ times
//! stiffer: the linear FE pose must then equal the linearised rigid-body kinematics.

mod build;
mod hinge_memo;
mod linear;
mod mesh_export;
mod nonlinear;
mod results;
pub mod sizing;
mod solve;

pub use crate::hinge::hinge_peak_stress;
use build::*;
pub use linear::{LinearStage, StageResponse};
pub use nonlinear::NONLINEAR_HINGE_SEGMENTS;
pub use solve::{stiffness_z, StageAnalysis};

use crate::fem::{self, FemError, Model};
use crate::hinge::{self, HingeError, HingeRegion, HingeSpec};
use crate::kinematics::Prs;
use crate::material::Material;
use nalgebra::{Matrix3, Vector3};
use thiserror::Error;

/// The two joints of a leg.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Joint {
    /// The revolute joint at Cᵢ ([`StageDesign::revolute`]).
    Revolute,
    /// The spherical joint at Bᵢ ([`StageDesign::spherical`]).
    Spherical,
}

impl Joint {
    /// `revolute` or `spherical`, the design parameter's name.
    pub fn name(self) -> &'static str {
        match self {
            Joint::Revolute => "revolute",
            Joint::Spherical => "spherical",
        }
    }
}

/// Errors of the stage builder and solver.
#[derive(Debug, Error)]
pub enum StageError {
    /// Non-physical stage geometry (names the design parameter).
    #[error("stage field `{field}`: {message}")]
    Geometry {
        /// Design parameter, e.g. `leg.w`, `L`, `revolute.type`.
        field: String,
        /// What is wrong and what is allowed.
        message: String,
    },
    /// A hinge (or the material it needs) is not physical; the [`HingeError`] names the hinge
    /// parameter (`t`, `R`, …) or material constant.
    #[error("{}", hinge_message(*joint, source))]
    Hinge {
        /// Which joint.
        joint: Joint,
        /// The hinge library's error.
        source: HingeError,
    },
    /// The FE model failed (singular, …).
    #[error("stage FE model: {0}")]
    Fem(#[from] FemError),
}

/// A stage design: geometry, hinges, material and modelling options.
#[derive(Debug, Clone, PartialEq)]
pub struct StageDesign {
    /// Rigid-body geometry (L, b, a, γ, home height).
    pub prs: Prs,
    /// Leg section width along the revolute axis mᵢ, mm.
    pub leg_w: f64,
    /// Leg section height along nᵢ, mm.
    pub leg_h: f64,
    /// Revolute notch (its w, h are the leg's; blank length 0).
    pub revolute: HingeSpec,
    /// Spherical neck (its h is the leg's; blank length 0).
    pub spherical: HingeSpec,
    /// Material of the monolithic stage.
    pub material: Material,
    /// Replace hinges by exact joints and make legs and platform stiff.
    pub ideal_joints: bool,
    /// Beam elements per leg (≥ 1).
    pub leg_elements: usize,
}

/// `stage field `revolute.t`: value … is not allowed: …` (`material.E` for the material).
fn hinge_message(joint: Joint, e: &HingeError) -> String {
    match e {
        HingeError::InvalidGeometry { param, value, allowed } => {
            format!(
                "stage field `{}.{param}`: value {value} is not allowed: {allowed}",
                joint.name()
            )
        }
        HingeError::InvalidMaterial { param, value, allowed } => {
            format!("stage field `material.{param}`: value {value} is not allowed: {allowed}")
        }
    }
}

/// A stage design that passed [`StageDesign::validate`] (the only way to make one), with its
/// two hinge regions (notch plus load-spreading zone) characterised: what [`ValidStage::build`]
/// takes, so building does not check again. Reads as the design through `Deref`.
#[derive(Debug, Clone, PartialEq)]
pub struct ValidStage {
    design: StageDesign,
    /// The revolute hinge region: profile, flexibility, stress model.
    pub revolute: HingeRegion,
    /// The spherical hinge region.
    pub spherical: HingeRegion,
}

impl ValidStage {
    /// The validated design.
    pub fn design(&self) -> &StageDesign {
        &self.design
    }

    /// The validated design, by value.
    pub fn into_design(self) -> StageDesign {
        self.design
    }

    /// Solid-calibration range warnings of the (revolute, spherical) hinges
    /// ([`hinge::calibration::calibration_warnings`]), without JSON paths.
    pub fn calibration_warnings(&self) -> [Vec<String>; 2] {
        [&self.design.revolute, &self.design.spherical].map(|spec| {
            spec.profile()
                .map(|p| hinge::calibration::calibration_warnings(&p))
                .unwrap_or_default()
        })
    }
}

impl std::ops::Deref for ValidStage {
    type Target = StageDesign;
    fn deref(&self) -> &StageDesign {
        &self.design
    }
}

/// Node and element numbers of one leg.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct LegIds {
    /// Slider node (bottom of the revolute notch).
    pub slider: usize,
    /// Top of the revolute notch.
    pub rev_top: usize,
    /// Bottom of the spherical neck.
    pub sph_bottom: usize,
    /// Top of the spherical neck (on the platform).
    pub sph_top: usize,
    /// Revolute hinge element (`None` with ideal joints).
    pub rev_element: Option<usize>,
    /// Spherical hinge element (`None` with ideal joints).
    pub sph_element: Option<usize>,
    /// Slider direction eᵢ.
    pub e: Vector3<f64>,
    /// Revolute axis mᵢ.
    pub m: Vector3<f64>,
    /// Leg axis lᵢ (C → B) at home.
    pub l: Vector3<f64>,
}

/// The FE model of a stage design plus what is needed to read results.
#[derive(Debug, Clone)]
pub struct StageModel {
    /// The design it was built from.
    pub design: StageDesign,
    /// The FE model (no load cases).
    pub model: Model,
    /// Platform centre node.
    pub platform: usize,
    /// Per-leg ids.
    pub legs: [LegIds; 3],
    /// The revolute hinge region (notch and load-spreading zone): profile, flexibility of the
    /// hinge elements, stress model.
    pub revolute: HingeRegion,
    /// The spherical hinge region.
    pub spherical: HingeRegion,
    /// Peak-stress tables of the (revolute, spherical) regions, for reading results.
    stress_tables: [hinge::PeakStressTable; 2],
}

/// How one load case drives the actuators.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Drive {
    /// Actuator forces along eᵢ, N.
    Forces([f64; 3]),
    /// Prescribed strokes along eᵢ, mm.
    Strokes([f64; 3]),
}

/// No load: zero actuator forces (a placeholder of inline storage).
impl Default for Drive {
    fn default() -> Self {
        Drive::Forces([0.0; 3])
    }
}

/// Platform pose change from home: the kinematics' [`Pose`](crate::kinematics::Pose) (x, y, z in
/// mm; ψ, θ, φ in rad — in linear analyses the small-rotation vector components, in nonlinear
/// ones the angles of R = Ry(θ)·Rx(ψ)·Rz(φ)).
pub type PoseChange = crate::kinematics::Pose;

/// Result of one stage load case.
#[derive(Debug, Clone, PartialEq)]
pub struct StageCaseResult {
    /// Load-case name.
    pub name: String,
    /// Slider strokes along eᵢ, mm.
    pub strokes: [f64; 3],
    /// Actuator forces along eᵢ, N.
    pub forces: [f64; 3],
    /// Platform pose change.
    pub platform: PoseChange,
    /// Peak von Mises stress in each revolute hinge, MPa.
    pub revolute_stress: [f64; 3],
    /// Peak von Mises stress in each spherical hinge, MPa.
    pub spherical_stress: [f64; 3],
    /// Largest von Mises stress anywhere (hinges and legs), MPa.
    pub max_von_mises: f64,
    /// Raw FE result.
    pub fe: fem::CaseResult,
    /// Nonlinear solves only: whether the equilibrium path stayed stable, and if not the
    /// load factors bracketing the first loss ([`fem::NonlinearCase::critical_load_factor`]).
    pub stability: Option<(bool, Option<[f64; 2]>)>,
}

impl StageCaseResult {
    /// T = max σ_sph / max σ_rev (Ruiz et al. (2019) §5).
    pub fn t_ratio(&self) -> f64 {
        self.response().t_ratio()
    }
}

/// Angles (ψ, θ, φ) of R = Ry(θ)·Rx(ψ)·Rz(φ) (the platform orientation of
/// [`crate::kinematics::prs::orientation`]), rad: row 2 of R is (cψ sφ, cψ cφ, −sψ) and its
/// column 3 is (sθ cψ, −sψ, cθ cψ).
pub fn pose_angles(r: &Matrix3<f64>) -> (f64, f64, f64) {
    let psi = (-r[(1, 2)]).atan2((r[(1, 0)].powi(2) + r[(1, 1)].powi(2)).sqrt());
    let phi = r[(1, 0)].atan2(r[(1, 1)]);
    let theta = r[(0, 2)].atan2(r[(2, 2)]);
    (psi, theta, phi)
}
