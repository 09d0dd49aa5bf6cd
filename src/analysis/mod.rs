//! Analyses: validated case → typed result → JSON/Markdown/CSV views.
//!
//! One room per analysis kind; the folder reads top-down:
//!
//! ```text
//! mod.rs        the drivers: run, check (through the registry), the material echo
//! dispatch/     the list of kinds (kinds_list.rs) and what it generates: the Case enum and the
//!               case-file reader (case_file.rs), the registry (registry.rs) of DynAnalysis
//!               entries (entry.rs), the Analysis impls of the older kinds (kinds.rs),
//!               --export-matrices over any case (export.rs)
//! kinematics/ hinge/ stage/ fem_vs_fkp/ design/ fem_static/ modal/ pantilt/ prs_stiffness/
//! transient/ buckling/ constraints/ frf/ craig_bampton/
//!               one folder per kind: its run, typed result, report and files
//! common/       the shared floor: the Analysis trait and Ctx (kind.rs), errors, reports and the
//!               finiteness check (outcome.rs, finite.rs), units of sweep columns (units.rs),
//!               warnings (warn.rs), sweep lines (line.rs), .vtu files (vtu.rs), the array
//!               check of case files (case_shape.rs)
//! ```
//!
//! Kinds use the floor; the floor names no kind and nothing above it; a kind names neither the
//! dispatch nor the drivers, and from another kind only what that kind names at its root
//! (`K/mod.rs`), never a file inside it (`tests/layering.rs`, `analysis_reads_top_down`). The
//! arrows between kinds, each through the other kind's root:
//!
//! - `stage` → `modal`: the stage's natural modes are a modal solve of the stage model
//!   ([`modal::solve`], [`modal::ModeRow`]).
//! - `stage` → `fem_static`: the stage's `.vtu` files and load-case file names reuse the static
//!   ones ([`fem_static::von_mises_of`], [`fem_static::file_stem`]); its report the stability
//!   warning of nonlinear cases ([`fem_static::stability_warning`]).
//! - `fem_vs_fkp` → `stage`: the comparison runs the stage model ([`stage::fem_err`],
//!   [`stage::model_notes`], [`stage::PoseOut`]).
//! - `design` → `fem_static`: a design of a mesh mechanism runs its static case and reads the
//!   metrics ([`fem_static::StaticResult`], [`fem_static::MetricValue`]).
//! - `design` → `stage`: the stage sizing and sensitivity with a `fatigue` block assess each
//!   design's hinges as the stage's `at_fatigue_limit` does ([`stage::SizingFatigue`]).
//! - `buckling` → `fem_static`: buckling shapes hide the inner nodes of segmented hinges as static
//!   results do ([`fem_static::hide_in_shapes`]).
//!
//! The module paths of the flat layout that preceded the folders (`analysis::warn`,
//! `analysis::stage_report`, `analysis::fem_path`, …) are kept as re-exports below.

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
pub use common::outcome::{
    check_finite, to_checked_json, warnings_markdown, AnalysisError, Files, Outcome, Report, RunError,
};
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

/// The warnings a run of a checked case lists that depend on the case alone (hinges outside
/// their calibrated ranges, implausible materials, …), which `flexfem check` prints; a run lists
/// them too, after its own.
pub fn check_warnings(case: &Case) -> Vec<String> {
    dispatch::registry::find(case.analysis())
        .and_then(|e| e.case_warnings(case))
        .unwrap_or_default()
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
