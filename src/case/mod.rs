//! Case files: serde shapes only, plus validation that names JSON paths (INTERFACE.md).
//!
//! Parsing is two-step so that every error carries its path: the text is read into a JSON
//! value, `analysis` picks the shape, and the rest is deserialised through
//! `serde_path_to_error` with unknown fields refused.

pub mod error;
pub mod kinematics;
pub mod material;

pub use error::CaseError;
pub use material::MaterialSpec;

use serde::de::DeserializeOwned;
use serde_json::Value;

/// A parsed case file (not yet validated).
#[derive(Debug, Clone, schemars::JsonSchema)]
#[serde(tag = "analysis", rename_all = "snake_case")]
pub enum Case {
    /// 3-PRS rigid-body kinematics.
    Kinematics(kinematics::KinematicsCase),
}

/// The `analysis` names this build understands.
pub const ANALYSES: &[&str] = &["kinematics"];

impl Case {
    /// The `analysis` name.
    pub fn analysis(&self) -> &'static str {
        match self {
            Case::Kinematics(_) => "kinematics",
        }
    }
}

/// Deserialises `value` into `T`, turning serde errors into [`CaseError`]s under `prefix`.
pub fn from_value<T: DeserializeOwned>(value: Value, prefix: &str) -> Result<T, CaseError> {
    serde_path_to_error::deserialize(value).map_err(|e| {
        let path = e.path().to_string();
        CaseError::new(
            if path == "." { String::new() } else { path },
            e.into_inner().to_string(),
        )
        .under(prefix)
    })
}

/// Parses case-file text.
pub fn parse(text: &str) -> Result<Case, CaseError> {
    let value: Value = serde_json::from_str(text).map_err(|e| CaseError::new(".", format!("not valid JSON: {e}")))?;
    parse_value(value)
}

/// Parses a case already read as JSON.
pub fn parse_value(mut value: Value) -> Result<Case, CaseError> {
    let Value::Object(map) = &mut value else {
        return Err(CaseError::value(
            ".",
            short(&value),
            "a case file must be a JSON object",
        ));
    };
    let analysis = match map.remove("analysis") {
        Some(Value::String(s)) => s,
        Some(other) => {
            return Err(CaseError::value(
                "analysis",
                short(&other),
                format!("must be one of {}", ANALYSES.join(", ")),
            ))
        }
        None => {
            return Err(CaseError::new(
                "analysis",
                format!("missing field `analysis`; one of {}", ANALYSES.join(", ")),
            ))
        }
    };
    match analysis.as_str() {
        "kinematics" => Ok(Case::Kinematics(from_value(value, "")?)),
        other => Err(CaseError::value(
            "analysis",
            format!("\"{other}\""),
            format!("must be one of {}", ANALYSES.join(", ")),
        )),
    }
}

/// A value shortened for messages.
pub fn short(v: &Value) -> String {
    let s = v.to_string();
    if s.chars().count() > 60 {
        format!("{}…", s.chars().take(60).collect::<String>())
    } else {
        s
    }
}

/// The JSON Schema of case files.
pub fn schema() -> Value {
    serde_json::to_value(schemars::schema_for!(Case)).unwrap_or(Value::Null)
}
