//! Case-file errors: every one names the JSON path, the value and what is allowed.

use std::fmt;

/// A problem with a case file. Maps to exit code 2.
#[derive(Debug, Clone, PartialEq)]
pub struct CaseError {
    /// JSON path of the offending field, e.g. `mechanism.L` or `fkp[2].s` (`.` for the root).
    pub path: String,
    /// What is wrong and what is allowed (includes the value).
    pub message: String,
}

impl CaseError {
    /// An error at `path`.
    pub fn new(path: impl Into<String>, message: impl Into<String>) -> Self {
        let path = path.into();
        CaseError {
            path: if path.is_empty() { ".".into() } else { path },
            message: message.into(),
        }
    }

    /// "value V is not allowed: RULE".
    pub fn value(path: impl Into<String>, value: impl fmt::Display, rule: impl fmt::Display) -> Self {
        Self::new(path, format!("value {value} is not allowed: {rule}"))
    }

    /// Prefixes the path with `prefix` (for errors produced inside a sub-object).
    pub fn under(mut self, prefix: &str) -> Self {
        if prefix.is_empty() {
            return self;
        }
        self.path = if self.path == "." {
            prefix.to_string()
        } else if self.path.starts_with('[') {
            format!("{prefix}{}", self.path)
        } else {
            format!("{prefix}.{}", self.path)
        };
        self
    }
}

impl fmt::Display for CaseError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "case file error at `{}`: {}", self.path, self.message)
    }
}

impl std::error::Error for CaseError {}

/// A number for messages: shortest round-trip form, in exponent form when very large or small
/// (`1e-300`, not three hundred zeros).
pub fn num(v: f64) -> String {
    if v != 0.0 && v.is_finite() && !(1e-4..1e16).contains(&v.abs()) {
        format!("{v:e}")
    } else {
        format!("{v}")
    }
}

/// Validation helpers: each returns an error naming `path` when the check fails. The path is
/// anything `Display` (`format_args!("{p}.E")`): it is made into text only for an error, so a
/// valid case is checked without allocating.
pub mod check {
    use super::{num, CaseError};
    use std::fmt::Display;

    /// `v` finite and > 0.
    pub fn positive(path: impl Display, v: f64, unit: &str) -> Result<(), CaseError> {
        if v.is_finite() && v > 0.0 {
            Ok(())
        } else {
            Err(CaseError::value(
                path.to_string(),
                num(v),
                format!("must be a positive number ({unit})"),
            ))
        }
    }

    /// `v` finite and ≥ 0.
    pub fn non_negative(path: impl Display, v: f64, unit: &str) -> Result<(), CaseError> {
        if v.is_finite() && v >= 0.0 {
            Ok(())
        } else {
            Err(CaseError::value(
                path.to_string(),
                num(v),
                format!("must be zero or positive ({unit})"),
            ))
        }
    }

    /// `v` finite and within [lo, hi].
    pub fn within(path: impl Display, v: f64, lo: f64, hi: f64, unit: &str) -> Result<(), CaseError> {
        if v.is_finite() && v >= lo && v <= hi {
            Ok(())
        } else {
            Err(CaseError::value(
                path.to_string(),
                num(v),
                format!("must lie in [{lo}, {hi}] {unit}"),
            ))
        }
    }

    /// `v` finite.
    pub fn finite(path: impl Display, v: f64) -> Result<(), CaseError> {
        if v.is_finite() {
            Ok(())
        } else {
            Err(CaseError::value(path.to_string(), num(v), "must be a finite number"))
        }
    }

    /// `r[0] ≤ r[1]`, both finite.
    pub fn range(path: impl Display, r: [f64; 2]) -> Result<(), CaseError> {
        finite(format_args!("{path}[0]"), r[0])?;
        finite(format_args!("{path}[1]"), r[1])?;
        if r[0] <= r[1] {
            Ok(())
        } else {
            Err(CaseError::value(
                path.to_string(),
                format!("[{}, {}]", r[0], r[1]),
                "a range must be [min, max] with min ≤ max",
            ))
        }
    }
}
