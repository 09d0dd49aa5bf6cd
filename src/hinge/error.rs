//! Typed errors of the hinge library.

use thiserror::Error;

/// Why a hinge could not be characterised.
///
/// Every variant names the offending parameter (with the INTERFACE.md spelling), its value and
/// what is allowed, so a case-file front end can point at the field.
#[derive(Debug, Clone, PartialEq, Error)]
pub enum HingeError {
    /// A geometry parameter is outside its physical range.
    #[error("hinge parameter `{param}` = {value} is not allowed: {allowed}")]
    InvalidGeometry {
        /// Parameter name as spelled in case files (`R`, `t`, `w`, `h`, `ax`, `ay`, `l`, `blank_length`).
        param: &'static str,
        /// The value given.
        value: f64,
        /// What is allowed, in words (e.g. "must be > 0 and < h = 10").
        allowed: String,
    },
    /// A material constant is outside its physical range.
    #[error("material parameter `{param}` = {value} is not allowed: {allowed}")]
    InvalidMaterial {
        /// `E`, `nu` or `allowable`.
        param: &'static str,
        /// The value given.
        value: f64,
        /// What is allowed, in words.
        allowed: String,
    },
}

pub(crate) fn geom(param: &'static str, value: f64, allowed: impl Into<String>) -> HingeError {
    HingeError::InvalidGeometry {
        param,
        value,
        allowed: allowed.into(),
    }
}

/// `value` must be finite and > 0.
pub(crate) fn positive(param: &'static str, value: f64) -> Result<(), HingeError> {
    if value.is_finite() && value > 0.0 {
        Ok(())
    } else {
        Err(geom(param, value, "must be a finite number > 0"))
    }
}

/// `value` must be finite and ≥ 0.
pub(crate) fn non_negative(param: &'static str, value: f64) -> Result<(), HingeError> {
    if value.is_finite() && value >= 0.0 {
        Ok(())
    } else {
        Err(geom(param, value, "must be a finite number >= 0"))
    }
}
