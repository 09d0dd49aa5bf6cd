//! What an analysis hands back: its errors ([`AnalysisError`], exit 1; [`RunError`]), its
//! views ([`Report`], [`Files`]) and the finished [`Outcome`], with the finiteness check every
//! result goes through ([`to_checked_json`]).

use crate::case::CaseError;
use std::fmt;

/// A failed analysis (exit code 1): where it failed and why.
#[derive(Debug, Clone, PartialEq)]
pub struct AnalysisError {
    /// Which query or load case failed, e.g. `fkp[2]`.
    pub context: String,
    /// What went wrong.
    pub message: String,
}

impl AnalysisError {
    /// An error in `context`.
    pub fn new(context: impl Into<String>, message: impl Into<String>) -> Self {
        AnalysisError {
            context: context.into(),
            message: message.into(),
        }
    }
}

impl fmt::Display for AnalysisError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "analysis failed at `{}`: {}", self.context, self.message)
    }
}

impl std::error::Error for AnalysisError {}

/// Why a case did not produce a result.
#[derive(Debug, Clone, PartialEq)]
pub enum RunError {
    /// The case file is wrong (exit 2).
    Case(CaseError),
    /// The analysis failed (exit 1).
    Analysis(AnalysisError),
}

impl fmt::Display for RunError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            RunError::Case(e) => e.fmt(f),
            RunError::Analysis(e) => e.fmt(f),
        }
    }
}

impl std::error::Error for RunError {}

impl From<CaseError> for RunError {
    fn from(e: CaseError) -> Self {
        RunError::Case(e)
    }
}
impl From<AnalysisError> for RunError {
    fn from(e: AnalysisError) -> Self {
        RunError::Analysis(e)
    }
}

/// Human-readable views of a result.
#[derive(Debug, Clone, Default)]
pub struct Report {
    /// Markdown report.
    pub markdown: String,
    /// CSV table of the main rows.
    pub csv: String,
}

/// Extra output files: (file name, contents).
pub type Files = Vec<(String, Vec<u8>)>;

/// A finished analysis: the JSON result plus its reports and extra files (name, contents).
#[derive(Debug, Clone)]
pub struct Outcome {
    /// The JSON result; its top-level `warnings` holds [`Outcome::warnings`].
    pub json: serde_json::Value,
    /// Things the user must know about the result (e.g. a hinge outside the range its solid
    /// calibration covers); also listed in the JSON (`warnings`) and the Markdown report.
    pub warnings: Vec<String>,
    /// Markdown and CSV views.
    pub report: Report,
    /// Extra output files (e.g. `.vtu`, `.svg`), written by `--out`.
    pub files: Files,
}

impl Outcome {
    /// Echoes the case's resolved parameters (name → value) in the result as `parameters` and
    /// in the Markdown report; nothing when the case declares none.
    pub fn echo_parameters(&mut self, parameters: &crate::case::params::Parameters) {
        if parameters.is_empty() {
            return;
        }
        if let serde_json::Value::Object(m) = &mut self.json {
            let echo = parameters.iter().map(|(k, v)| (k.clone(), serde_json::Value::from(*v)));
            m.insert("parameters".into(), serde_json::Value::Object(echo.collect()));
        }
        if !self.report.markdown.is_empty() {
            let list: Vec<String> = parameters.iter().map(|(k, v)| format!("`{k}` = {v}")).collect();
            self.report.markdown += &format!("\nParameters: {}.\n", list.join(", "));
        }
    }
}

/// The JSON value of a result, refusing any non-finite number: serde_json would write NaN and
/// ±∞ as `null` silently. The error's context is the JSON path of the first offending number
/// (e.g. `load_cases[0].max_von_mises`). Every analysis result goes through it; batch drivers
/// (sweeps) call it on each row.
pub fn to_checked_json<T: serde::Serialize>(v: &T) -> Result<serde_json::Value, AnalysisError> {
    check_finite(v)?;
    serde_json::to_value(v).map_err(|e| AnalysisError::new("output", e.to_string()))
}

/// The check of [`to_checked_json`] alone (no allocation when every number is finite).
pub fn check_finite<T: serde::Serialize>(v: &T) -> Result<(), AnalysisError> {
    super::finite::first_non_finite(v).map_err(|(path, msg)| {
        AnalysisError::new(
            if path.is_empty() || path == "." { "output".to_string() } else { path },
            format!("the computed number is not finite ({msg}): the input is outside the range the model can represent (overflow) or the model is degenerate"),
        )
    })
}

/// The `## Warnings` section of the Markdown report (empty when there are none).
pub fn warnings_markdown(warnings: &[String]) -> String {
    if warnings.is_empty() {
        return String::new();
    }
    let mut md = String::from("\n## Warnings\n\n");
    for w in warnings {
        md += &format!("- {w}\n");
    }
    md
}
