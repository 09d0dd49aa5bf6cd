//! The `hinge` case: one flexure hinge in its blank.

use super::error::CaseError;
use super::fields::case_struct;
use crate::hinge::{HingeError, HingeSpec};
use crate::material::Material;
use serde::Deserialize;

case_struct! {
    /// `"analysis": "hinge"`.
    #[derive(Debug, Clone, Deserialize, schemars::JsonSchema)]
    #[serde(deny_unknown_fields)]
    #[schemars(extend("if" = super::stage::steps_given(), "then" = super::stage::nonlinear_true()))]
    pub struct HingeCase {
        include material;
        /// The hinge, by `type`: lengths in mm.
        pub hinge: HingeSpec,
        include nonlinear_steps {
            /// Also trace the large-rotation response (geometrically nonlinear FE of the hinge in its
            /// blank under a transverse end force) up to the allowable stress.
            nonlinear,
            /// Load steps per point of the nonlinear curve, 1 … 10000 (default 20; only with
            /// `"nonlinear": true`).
            steps,
        }
        /// Identify the joint damping D of the hinge (Yu, Lu and Hao (2016), 8R compliant parallel
        /// pan-tilt, §4.1): a transient FE run of the hinge in its blank under a step moment about
        /// the compliant axis, with the material's Rayleigh damping, fitted by J θ̈ + D θ̇ + K θ = M
        /// with K from statics.
        #[serde(default)]
        pub damping: Option<HingeDampingSpec>,
        /// High-cycle fatigue of a cyclic rotation about the compliant axis (the material needs
        /// `"fatigue"` data): utilisation, life, and the stroke at infinite life.
        #[serde(default)]
        pub fatigue: Option<super::fatigue::FatigueSpec>,
    }
}

impl HingeCase {
    /// Validates material and geometry (non-physical geometry is refused before solving).
    pub fn validate(&self) -> Result<Material, CaseError> {
        let m = self.material.resolve("material")?;
        super::stage::check_steps("steps", self.steps, self.nonlinear)?;
        if self.nonlinear && !m.allowable.is_finite() {
            return Err(CaseError::new(
                "material",
                "the material has no `allowable` stress (MPa), and the large-rotation curve of \"nonlinear\": true runs up to it: give a material with `allowable`, or drop `nonlinear`",
            ));
        }
        self.hinge.profile().map_err(|e| hinge_error(&e, "hinge", "material"))?;
        if let Some(d) = &self.damping {
            d.run()?;
        }
        if let Some(f) = &self.fatigue {
            f.validate("material", &m)?;
        }
        Ok(m)
    }
}

/// `"damping"` of a `hinge` case.
#[derive(Debug, Clone, Deserialize, schemars::JsonSchema)]
#[serde(deny_unknown_fields)]
pub struct HingeDampingSpec {
    /// Stiffness-proportional (Rayleigh β) material damping, s; > 0.
    #[schemars(range(min = 0))]
    pub beta: f64,
    /// Mass-proportional (Rayleigh α) material damping, 1/s; ≥ 0 (default 0).
    #[serde(default)]
    #[schemars(range(min = 0))]
    pub alpha: f64,
    /// Simulated time, s (default 8 × beta).
    pub duration: Option<f64>,
    /// Time steps, 10 … 100000 (default 800).
    #[schemars(range(min = 10, max = 100000))]
    pub steps: Option<usize>,
    /// Step moment about the compliant axis, N·mm (default 1; the model is linear).
    pub moment: Option<f64>,
}

impl HingeDampingSpec {
    /// The checked run parameters (errors under `damping.…`).
    pub fn run(&self) -> Result<crate::hinge::damping::DampingRun, CaseError> {
        if !(self.beta.is_finite() && self.beta > 0.0) {
            return Err(CaseError::value(
                "damping.beta",
                number(self.beta),
                "must be a damping time > 0, s",
            ));
        }
        if !(self.alpha.is_finite() && self.alpha >= 0.0) {
            return Err(CaseError::value(
                "damping.alpha",
                number(self.alpha),
                "must be ≥ 0, 1/s",
            ));
        }
        let duration = self.duration.unwrap_or(8.0 * self.beta);
        if !(duration.is_finite() && duration > 0.0) {
            return Err(CaseError::value(
                "damping.duration",
                number(duration),
                "must be a time > 0, s",
            ));
        }
        let steps = self.steps.unwrap_or(800);
        if !(10..=100_000).contains(&steps) {
            return Err(CaseError::value(
                "damping.steps",
                steps,
                "must be an integer from 10 to 100000",
            ));
        }
        let moment = self.moment.unwrap_or(1.0);
        if !(moment.is_finite() && moment != 0.0) {
            return Err(CaseError::value(
                "damping.moment",
                number(moment),
                "must be a non-zero moment, N·mm",
            ));
        }
        Ok(crate::hinge::damping::DampingRun {
            alpha: self.alpha,
            beta: self.beta,
            duration,
            steps,
            moment,
        })
    }
}

/// A number as typed in a case file: plain, or in exponent form when very large or small
/// (`1e300`, not 301 digits).
fn number(v: f64) -> String {
    if v.is_finite() && v != 0.0 && !(1e-4..1e9).contains(&v.abs()) {
        format!("{v:e}")
    } else {
        v.to_string()
    }
}

/// Maps a hinge-library error to the JSON path of the offending field.
pub fn hinge_error(e: &HingeError, hinge_path: &str, material_path: &str) -> CaseError {
    match e {
        HingeError::InvalidGeometry { param, value, allowed } => {
            CaseError::value(format!("{hinge_path}.{param}"), number(*value), allowed)
        }
        HingeError::InvalidMaterial { param, value, allowed } => {
            CaseError::value(format!("{material_path}.{param}"), number(*value), allowed)
        }
    }
}
