//! Analyses: validated case → typed result → JSON/Markdown/CSV views.

pub mod common;
pub mod design;
pub mod dispatch;
pub mod fem_static;
pub mod fem_vs_fkp;
pub mod hinge;
pub mod kinematics;
pub mod modal;
pub mod stage;

use dispatch::registry::analysis_modules;
dispatch::kinds_list::analyses!(analysis_modules);

pub use common::kind::{Analysis, Ctx};
pub use common::warn::{hinge_warnings, SMALL_STRAIN};
pub use dispatch::case_file::{load, load_resolved, parse, parse_in, parse_value, schema, Case, Parsed, ANALYSES};
pub use dispatch::entry::DynAnalysis;

// The module paths of the flat layout (before one folder per kind), kept for code written
// against them; new code names the folders.
pub use common::{finite, kind, line, units, vtu, warn};
pub use dispatch::{case_file, export, kinds, kinds_list, registry};
pub use fem_static::{compliance, nonlinear_path as fem_path, path_rows, track};
pub use frf::{files as frf_files, result as frf_result};
pub use hinge::fatigue as hinge_fatigue;
pub use stage::{report as stage_report, sweep_plot};

use crate::case::{CaseError, MaterialSpec};
use crate::fem::SolverCache;
use crate::material::Material;
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
    common::finite::first_non_finite(v).map_err(|(path, msg)| {
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

/// Refuses a case whose kind has no registered analysis (a build error caught by the tests).
fn unregistered(case: &Case) -> CaseError {
    kind_refused(
        case,
        "no analysis of this kind is registered in this build (please report)",
    )
}

/// An error at `analysis` naming the case's kind and why it is refused.
pub(crate) fn kind_refused(case: &Case, rule: &str) -> CaseError {
    CaseError::value("analysis", format!("\"{}\"", case.analysis()), rule)
}

/// Validates a case (everything checked before solving).
pub fn check(case: &Case) -> Result<(), CaseError> {
    dispatch::registry::find(case.analysis())
        .and_then(|e| e.check(case))
        .unwrap_or_else(|| Err(unregistered(case)))
}

/// Validates and runs a case.
///
/// Output files (VTK, SVG) are rendered only with [`run_with_files`]: batch runs skip them.
pub fn run(case: &Case) -> Result<Outcome, RunError> {
    run_with(case, &mut Ctx::new(&mut SolverCache::new(), false))
}

/// [`run`] plus the extra output files (`.vtu` meshes, `.svg` plots) that `--out` writes.
pub fn run_with_files(case: &Case) -> Result<Outcome, RunError> {
    run_with(case, &mut Ctx::new(&mut SolverCache::new(), true))
}

/// [`run`] with the caller's context (a batch driver passes its worker's solver cache).
pub fn run_with(case: &Case, ctx: &mut Ctx) -> Result<Outcome, RunError> {
    let Some(e) = dispatch::registry::find(case.analysis()) else {
        return Err(unregistered(case).into());
    };
    let mut out = e.run(case, ctx).unwrap_or_else(|| Err(unregistered(case).into()))?;
    let materials = e.materials(case);
    if let serde_json::Value::Object(m) = &mut out.json {
        match materials.as_slice() {
            [(key, spec, mat)] if key.is_empty() => {
                m.insert("material".into(), material_json(spec, mat));
            }
            [] => {}
            all => {
                let map = all.iter().map(|(k, spec, mat)| (k.clone(), material_json(spec, mat)));
                m.insert("materials".into(), serde_json::Value::Object(map.collect()));
            }
        }
        m.insert("warnings".into(), serde_json::Value::from(out.warnings.clone()));
    }
    if ctx.with_report {
        out.report.markdown += &materials_markdown(&materials);
        out.report.markdown += &warnings_markdown(&out.warnings);
    }
    Ok(out)
}

/// The material as used, echoed in the result: `{"name", "E" (MPa), "nu", "density" (t/mm³),
/// "yield" (MPa), "allowable" (MPa)}`; `name` is the built-in name or `"custom"`; an unlimited
/// yield or allowable stress is `null`.
fn material_json(spec: &MaterialSpec, m: &Material) -> serde_json::Value {
    serde_json::to_value(common::line::MaterialEcho::of(spec, m)).unwrap_or(serde_json::Value::Null)
}

/// One Markdown line per material used.
fn materials_markdown(materials: &[(String, MaterialSpec, Material)]) -> String {
    let mut s = String::new();
    for (key, spec, m) in materials {
        let name = match spec {
            MaterialSpec::Name(n) => n.clone(),
            MaterialSpec::Custom(_) => "custom".to_string(),
        };
        let strength = |v: f64| {
            if v.is_finite() {
                format!("{v} MPa")
            } else {
                "unlimited".into()
            }
        };
        let label = if key.is_empty() {
            String::new()
        } else {
            format!("`{key}` = ")
        };
        s += &format!(
            "\nMaterial: {label}{name} (E {} MPa, ν {}, density {:e} t/mm³, yield {}, allowable {}).\n",
            m.e,
            m.nu,
            m.density,
            strength(m.yield_strength),
            strength(m.allowable)
        );
    }
    s
}
