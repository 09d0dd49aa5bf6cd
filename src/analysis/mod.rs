//! Analyses: validated case → typed result → JSON/Markdown/CSV views.

pub mod design;
pub mod fem_static;
pub mod finite;
pub mod hinge;
pub mod kinematics;
pub mod modal;
pub mod prs_stiffness;
pub mod stage;
pub mod vtu;

use crate::case::{Case, CaseError, MaterialSpec};
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

/// The JSON value of a result, refusing any non-finite number: serde_json would write NaN and
/// ±∞ as `null` silently. The error's context is the JSON path of the first offending number
/// (e.g. `load_cases[0].max_von_mises`). Every analysis result goes through it; batch drivers
/// (sweeps) call it on each row.
pub fn to_checked_json<T: serde::Serialize>(v: &T) -> Result<serde_json::Value, AnalysisError> {
    finite::first_non_finite(v).map_err(|(path, msg)| {
        AnalysisError::new(
            if path.is_empty() || path == "." { "output".to_string() } else { path },
            format!("the computed number is not finite ({msg}): the input is outside the range the model can represent (overflow) or the model is degenerate"),
        )
    })?;
    serde_json::to_value(v).map_err(|e| AnalysisError::new("output", e.to_string()))
}

fn to_json<T: serde::Serialize>(v: &T) -> Result<serde_json::Value, AnalysisError> {
    to_checked_json(v)
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

/// Calibration-range warnings of a hinge, prefixed with where it sits in the case file.
pub fn hinge_warnings(at: &str, spec: &crate::hinge::HingeSpec) -> Vec<String> {
    match spec.profile() {
        Ok(p) => crate::hinge::calibration::calibration_warnings(&p)
            .into_iter()
            .map(|w| format!("{at}: {w}"))
            .collect(),
        Err(_) => Vec::new(),
    }
}

/// Calibration warnings of a stage design's two hinges.
fn stage_warnings(d: &crate::stage::StageDesign) -> Vec<String> {
    let mut w = hinge_warnings("stage.revolute", &d.revolute);
    w.extend(hinge_warnings("stage.spherical", &d.spherical));
    w
}

/// Largest element stretch in a geometrically nonlinear result above which it is reported: the
/// co-rotational elements assume small strains (a linear-elastic element at 1 % strain is at
/// the end of the elastic range of every structural metal).
pub const SMALL_STRAIN: f64 = 0.01;

/// Warnings for load cases in which a two-node element's chord stretches or shortens by more
/// than [`SMALL_STRAIN`] (one per load case, naming the worst element).
fn stretch_warnings(model: &crate::fem::Model, r: &fem_static::StaticResult) -> Vec<String> {
    let mut out = Vec::new();
    for (ic, c) in r.load_cases.iter().enumerate() {
        let mut worst: Option<(usize, f64)> = None;
        for (ie, e) in model.elements.iter().enumerate() {
            let [a, b] = match e {
                crate::fem::Element::Beam(b) => b.nodes,
                crate::fem::Element::Flex(f) => f.nodes,
                _ => continue,
            };
            let (Some(da), Some(db)) = (c.displacements.get(a), c.displacements.get(b)) else {
                continue;
            };
            let (xa, xb) = (model.nodes[a], model.nodes[b]);
            let l0 = (0..3).map(|k| (xb[k] - xa[k]).powi(2)).sum::<f64>().sqrt();
            let l = (0..3)
                .map(|k| ((xb[k] + db[k]) - (xa[k] + da[k])).powi(2))
                .sum::<f64>()
                .sqrt();
            let strain = l / l0 - 1.0;
            if strain.abs() > SMALL_STRAIN && worst.is_none_or(|(_, w)| strain.abs() > w.abs()) {
                worst = Some((ie, strain));
            }
        }
        if let Some((ie, strain)) = worst {
            let pct = strain * 100.0;
            let pct = if pct.abs() < 1e4 {
                format!("{pct:+.2}")
            } else {
                format!("{pct:+.3e}")
            };
            out.push(format!(
                "load_cases[{ic}] (\"{}\"): element {ie} changes length by {pct} %, beyond the small-strain assumption of the co-rotational elements (|strain| <= {} %): the displacements are those of a linear-elastic material at that strain",
                c.name,
                SMALL_STRAIN * 100.0
            ));
        }
    }
    out
}

/// Calibration warnings of the hinges of the design found by a `design` run.
fn design_warnings(case: &crate::case::design::DesignCase, r: &design::DesignResult) -> Vec<String> {
    use crate::stage::sizing::{with_params, PARAMETERS};
    let Ok((base, _, _)) = case.validate() else {
        return Vec::new();
    };
    let mut p = [0.0; 5];
    for (v, k) in p.iter_mut().zip(PARAMETERS) {
        match r.design.get(k).and_then(|v| v.as_f64()) {
            Some(x) => *v = x,
            None => return Vec::new(),
        }
    }
    stage_warnings(&with_params(&base, &p))
        .into_iter()
        .map(|w| format!("design found, {w}"))
        .collect()
}

/// Warnings that depend only on the case (hinge calibration ranges).
fn case_warnings(case: &Case) -> Vec<String> {
    match case {
        Case::Hinge(h) => hinge_warnings("hinge", &h.hinge),
        Case::Stage(s) => s.validate().map(|(d, _)| stage_warnings(&d)).unwrap_or_default(),
        Case::FemVsFkp(s) => s.validate().map(|d| stage_warnings(&d)).unwrap_or_default(),
        Case::Sensitivity(s) => s.validate().map(|d| stage_warnings(&d)).unwrap_or_default(),
        Case::Modal(m) => density_warnings(&m.model),
        _ => Vec::new(),
    }
}

/// Implausible densities (unit slips) of a modal model's materials.
fn density_warnings(spec: &crate::case::mesh::MeshSpec) -> Vec<String> {
    spec.materials
        .iter()
        .filter_map(|(k, m)| {
            let at = format!("materials.{k}");
            let mat = m.resolve(&at).ok()?;
            crate::case::material::density_warning(&at, &mat)
        })
        .collect()
}

/// Validates a case (everything checked before solving).
pub fn check(case: &Case) -> Result<(), CaseError> {
    match case {
        Case::Kinematics(k) => k.validate().map(|_| ()),
        Case::Static(s) => s.model.build().map(|_| ()),
        Case::Hinge(h) => h.validate().map(|_| ()),
        Case::Sweep(s) => s.build().map(|_| ()),
        Case::Stage(s) => s.validate().map(|_| ()),
        Case::FemVsFkp(s) => s.validate().map(|_| ()),
        Case::Sensitivity(s) => s.validate().map(|_| ()),
        Case::Design(s) => s.validate().map(|_| ()),
        Case::Modal(m) => {
            crate::case::limits::check_modal(m.modes, m.model.nodes.len())?;
            m.model.build_model(false).map(|_| ())
        }
    }
}

/// Validates and runs a case.
///
/// Output files (VTK, SVG) are rendered only with [`run_with_files`]: batch runs skip them.
pub fn run(case: &Case) -> Result<Outcome, RunError> {
    run_opts(case, false)
}

/// [`run`] plus the extra output files (`.vtu` meshes, `.svg` plots) that `--out` writes.
pub fn run_with_files(case: &Case) -> Result<Outcome, RunError> {
    run_opts(case, true)
}

fn run_opts(case: &Case, with_files: bool) -> Result<Outcome, RunError> {
    let mut out = run_analysis(case, with_files)?;
    out.warnings.extend(case_warnings(case));
    let materials = case_materials(case);
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
    out.report.markdown += &materials_markdown(&materials);
    out.report.markdown += &warnings_markdown(&out.warnings);
    Ok(out)
}

/// The materials a case uses, resolved: `("", spec, material)` for the one material of a
/// hinge/stage/design case, `(name, spec, material)` per named material of a mesh case.
fn case_materials(case: &Case) -> Vec<(String, MaterialSpec, Material)> {
    let one = |spec: &MaterialSpec| {
        spec.resolve("material")
            .map(|m| vec![(String::new(), spec.clone(), m)])
            .unwrap_or_default()
    };
    let named = |specs: &std::collections::BTreeMap<String, MaterialSpec>| {
        specs
            .iter()
            .filter_map(|(k, spec)| spec.resolve(k).ok().map(|m| (k.clone(), spec.clone(), m)))
            .collect()
    };
    match case {
        Case::Hinge(h) => one(&h.material),
        Case::Stage(s) => one(&s.material),
        Case::FemVsFkp(s) => one(&s.material),
        Case::Sensitivity(s) => one(&s.material),
        Case::Design(s) => one(&s.material),
        Case::Static(s) => named(&s.model.materials),
        Case::Modal(m) => named(&m.model.materials),
        Case::Kinematics(_) | Case::Sweep(_) => Vec::new(),
    }
}

/// The material as used, echoed in the result: `{"name", "E" (MPa), "nu", "density" (t/mm³),
/// "yield" (MPa), "allowable" (MPa)}`; `name` is the built-in name or `"custom"`; an unlimited
/// yield or allowable stress is `null`.
fn material_json(spec: &MaterialSpec, m: &Material) -> serde_json::Value {
    let name = match spec {
        MaterialSpec::Name(n) => n.as_str(),
        MaterialSpec::Custom(_) => "custom",
    };
    serde_json::json!({
        "name": name,
        "E": m.e,
        "nu": m.nu,
        "density": m.density,
        "yield": m.yield_strength.is_finite().then_some(m.yield_strength),
        "allowable": m.allowable.is_finite().then_some(m.allowable),
    })
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

fn run_analysis(case: &Case, with_files: bool) -> Result<Outcome, RunError> {
    let plain = |json, report| Outcome {
        json,
        warnings: Vec::new(),
        report,
        files: vec![],
    };
    match case {
        Case::Kinematics(k) => {
            let (prs, bx) = k.validate()?;
            let r = kinematics::solve(k, &prs, bx.as_ref())?;
            Ok(plain(to_json(&r)?, kinematics::report(&r)))
        }
        Case::Static(s) => {
            let model = s.model.build()?;
            let (r, raw) = match s.steps.filter(|_| s.nonlinear) {
                Some(steps) => fem_static::solve_nonlinear(&model, steps)?,
                None => fem_static::solve(&model)?,
            };
            let files = if with_files {
                fem_static::vtu_files(&model, &raw)?
            } else {
                Vec::new()
            };
            Ok(Outcome {
                json: to_json(&r)?,
                warnings: if s.nonlinear {
                    let mut w = stretch_warnings(&model, &r);
                    w.extend(
                        r.load_cases
                            .iter()
                            .filter_map(|c| fem_static::stability_text(&c.name, c.stable, c.critical_load_factor)),
                    );
                    w
                } else {
                    fem_static::shell_orientation_warnings(&model)
                },
                report: fem_static::report(&r),
                files,
            })
        }
        Case::Modal(m) => {
            crate::case::limits::check_modal(m.modes, m.model.nodes.len())?;
            let model = m.model.build_model(false)?;
            let (mut r, raw) = modal::solve(&model, m.modes, m.shift_hz)?;
            modal::mark_rigid_body(&model, &raw, &mut r);
            if !m.shapes {
                r.modes.iter_mut().for_each(|row| row.shape = None);
            }
            Ok(Outcome {
                json: to_json(&r)?,
                warnings: modal::drilling_warnings(&model, &raw),
                report: modal::report(&r),
                files: if with_files {
                    vec![("modes.vtu".to_string(), modal::vtu(&model, &raw)?)]
                } else {
                    Vec::new()
                },
            })
        }
        Case::Sweep(_) => Err(RunError::Case(CaseError::value(
            "analysis",
            "\"sweep\"",
            "a sweep runs with `flexfem sweep CASE.json`, not `flexfem run`",
        ))),
        Case::Stage(s) => {
            let (r, files) = if with_files {
                stage::run_stage_with_files(s)?
            } else {
                (stage::run_stage(s)?, Vec::new())
            };
            Ok(Outcome {
                json: to_json(&r)?,
                warnings: r
                    .load_cases
                    .iter()
                    .filter_map(|c| fem_static::stability_text(&c.name, c.stable, c.critical_load_factor))
                    .collect(),
                report: stage::stage_report(&r),
                files,
            })
        }
        Case::FemVsFkp(s) => {
            let r = stage::run_fem_vs_fkp(s)?;
            let (report, files) = stage::fem_vs_fkp_report(&r);
            Ok(Outcome {
                json: to_json(&r)?,
                warnings: Vec::new(),
                report,
                files,
            })
        }
        Case::Sensitivity(s) => {
            let r = design::run_sensitivity(s)?;
            Ok(plain(to_json(&r)?, design::sensitivity_report(&r)))
        }
        Case::Design(s) => {
            let r = design::run_design(s)?;
            let mut out = plain(to_json(&r)?, design::design_report(&r));
            out.warnings = design_warnings(s, &r);
            Ok(out)
        }
        Case::Hinge(h) => {
            let r = hinge::solve(h)?;
            let mut report = hinge::report(&r.result);
            if let Some(lr) = &r.large_rotation {
                report.markdown += &hinge::large_rotation_report(lr);
            }
            Ok(plain(to_json(&r)?, report))
        }
    }
}
