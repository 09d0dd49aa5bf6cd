//! The `hinge` case: one flexure hinge in its blank.

use super::error::CaseError;
use super::material::MaterialSpec;
use crate::hinge::{HingeError, HingeSpec};
use crate::material::Material;
use serde::Deserialize;

/// `"analysis": "hinge"`.
#[derive(Debug, Clone, Deserialize, schemars::JsonSchema)]
#[serde(deny_unknown_fields)]
pub struct HingeCase {
    /// Material (default Al7075).
    #[serde(default)]
    pub material: MaterialSpec,
    /// The hinge, by `type` (SPEC §4): lengths in mm.
    pub hinge: HingeSpec,
    /// Also trace the large-rotation response (geometrically nonlinear FE of the hinge in its
    /// blank under a transverse end force) up to the allowable stress.
    #[serde(default)]
    pub nonlinear: bool,
    /// Load steps per point of the nonlinear curve (default 20; only with `"nonlinear": true`).
    #[serde(default)]
    pub steps: Option<usize>,
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

impl HingeCase {
    /// Validates material and geometry (non-physical geometry is refused before solving).
    pub fn validate(&self) -> Result<Material, CaseError> {
        let m = self.material.resolve("material")?;
        super::stage::check_steps("steps", self.steps, self.nonlinear)?;
        self.hinge.profile().map_err(|e| hinge_error(&e, "hinge", "material"))?;
        Ok(m)
    }
}
