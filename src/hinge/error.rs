//! Typed errors of the hinge library.

use thiserror::Error;

/// Why a hinge could not be characterised.
///
/// Every variant names the offending parameter (with the case-file spelling), its value and
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

/// Smallest hinge length accepted, mm (1 nm): below it the section properties (t³, t⁴) leave
/// the range where double precision keeps the stiffness finite, and no machined flexure is
/// that thin.
pub const MIN_LENGTH: f64 = 1e-6;
/// Largest hinge length accepted, mm (1 km): beyond it products such as R², E·w·h³ and the
/// closed forms overflow long before any physical hinge is reached.
pub const MAX_LENGTH: f64 = 1e6;

fn length_range() -> String {
    format!("must be a length between {MIN_LENGTH:e} and {MAX_LENGTH:e} mm")
}

/// `value` must be finite and > 0, within [`MIN_LENGTH`, `MAX_LENGTH`].
pub(crate) fn positive(param: &'static str, value: f64) -> Result<(), HingeError> {
    if !(value.is_finite() && value > 0.0) {
        Err(geom(param, value, "must be a finite number > 0"))
    } else if !(MIN_LENGTH..=MAX_LENGTH).contains(&value) {
        Err(geom(param, value, length_range()))
    } else {
        Ok(())
    }
}

/// `value` must be finite and ≥ 0, at most [`MAX_LENGTH`].
pub(crate) fn non_negative(param: &'static str, value: f64) -> Result<(), HingeError> {
    if !(value.is_finite() && value >= 0.0) {
        Err(geom(param, value, "must be a finite number >= 0"))
    } else if value > MAX_LENGTH {
        Err(geom(param, value, format!("must be 0 or {}", length_range())))
    } else {
        Ok(())
    }
}
