//! The typed analysis layer: one [`Analysis`] implementation per `analysis` kind (its case
//! type, validation, run, typed result, reports and files), registered once in
//! [`crate::analysis::dispatch::registry::REGISTRY`]. Drivers (`flexfem run`, `flexfem check`, sweeps) reach every
//! kind through the object-safe [`DynAnalysis`] view of the registry and never name a kind.
//!
//! Adding an analysis kind: one module implementing [`Analysis`] and one line in the list of
//! kinds, [`crate::analysis::dispatch::kinds_list`].

use super::outcome::{Files, Report, RunError};
use super::units::UnitOf;
use crate::case::{CaseError, MaterialSpec};
use crate::fem::SolverCache;
use crate::material::Material;
use serde::Serialize;

/// What a run hands back besides its typed result, and what it may reuse.
pub struct Ctx<'a> {
    /// The worker's solver cache (a fresh one for a single run; one per worker in a sweep).
    pub cache: &'a mut SolverCache,
    /// Render the extra output files (`.vtu`, `.svg`): only `run --out` writes them.
    pub with_files: bool,
    /// Extra output files (file name, contents), pushed by the run when `with_files`.
    pub files: Files,
    /// Warnings found while running (before [`Analysis::case_warnings`]).
    pub warnings: Vec<String>,
    /// Render the Markdown/CSV report (a sweep, which writes only the JSON, turns it off).
    pub with_report: bool,
    /// Only the result's `metrics` and `compliance` are read (a design loop's evaluation of one
    /// design): a nonlinear `static` case may then reach each load case's final state without
    /// its nominal load steps (the model notes say how).
    pub metrics_only: bool,
}

impl<'a> Ctx<'a> {
    /// A context using `cache`.
    pub fn new(cache: &'a mut SolverCache, with_files: bool) -> Self {
        Ctx {
            cache,
            with_files,
            files: Vec::new(),
            warnings: Vec::new(),
            with_report: true,
            metrics_only: false,
        }
    }
}

/// A resolved material of a case: (key, spec, material); the key is empty for the one material
/// of a hinge/stage/design case.
pub type UsedMaterial = (String, MaterialSpec, Material);

/// The materials of a mesh model's `materials` map that resolve, by key.
pub fn named_materials(specs: &std::collections::BTreeMap<String, MaterialSpec>) -> Vec<UsedMaterial> {
    specs
        .iter()
        .filter_map(|(k, spec)| spec.resolve(k).ok().map(|m| (k.clone(), spec.clone(), m)))
        .collect()
}

/// One analysis kind.
///
/// Its `analysis` name is given once, by its line in the list of kinds
/// ([`CaseOf::KIND`](crate::analysis::dispatch::case_file::CaseOf::KIND)).
pub trait Analysis: 'static {
    /// The parsed case (a serde shape, one variant of [`Case`]).
    type Case;
    /// The typed result; its JSON is the `result.json` of a run and the `result` of a sweep line.
    type Result: Serialize;

    /// Validates the case (everything checked before solving).
    fn check(case: &Self::Case) -> Result<(), CaseError>;
    /// Validates and runs the case; extra files and run warnings go into `ctx`.
    fn run(case: &Self::Case, ctx: &mut Ctx) -> Result<Self::Result, RunError>;
    /// Markdown and CSV views of the result.
    fn report(result: &Self::Result) -> Report;
    /// Warnings that depend only on the case (e.g. hinge calibration ranges), listed after the
    /// run's own.
    fn case_warnings(_case: &Self::Case) -> Vec<String> {
        Vec::new()
    }
    /// The model of a mesh case (`static`, `modal`, ...), whose hinge elements' calibration
    /// warnings ([`crate::case::mesh::MeshSpec::hinge_warnings`]) every run lists after
    /// [`Self::case_warnings`]; `None` for the kinds without one and for `constraints`, which
    /// takes hinges as rigid or as ideal joints and never uses their stiffness.
    fn mesh_model(_case: &Self::Case) -> Option<&crate::case::mesh::MeshSpec> {
        None
    }
    /// Warnings that depend on the case and its result, listed after [`Self::case_warnings`].
    fn result_warnings(_case: &Self::Case, _result: &Self::Result) -> Vec<String> {
        Vec::new()
    }
    /// The materials the case uses, resolved (echoed in the result and the report).
    fn materials(_case: &Self::Case) -> Vec<UsedMaterial> {
        Vec::new()
    }
    /// Files a sweep over this kind writes beside its `--out FILE.jsonl`.
    fn sweep_files() -> &'static [SweepFile] {
        &[]
    }
    /// Renders one of [`Self::sweep_files`] that is not the table from the sweep's finished
    /// lines (in index order), `None` when there is nothing to show.
    fn render_sweep_file(_file: &SweepFile, _lines: &[String]) -> Option<String> {
        None
    }
    /// The units of the result's and the case's numbers, for the columns of sweep tables
    /// (`None`: bare column names); see [`super::units`].
    fn column_units() -> Option<(UnitOf, UnitOf)> {
        None
    }
    /// The number at a case path (object keys and array indices, as in a sweep's `vary`), for
    /// sweeps that set each design's numbers in a parsed case instead of parsing the design;
    /// `None` (the default) sends sweeps of this kind through JSON values. A kind that gives it
    /// must also give [`Self::material_of`] when it has [`Self::materials`].
    fn number_mut<'c>(_case: &'c mut Self::Case, _path: &[&str]) -> Option<&'c mut f64> {
        None
    }
    /// The one material of the case, echoed as `material` (see [`Self::number_mut`]).
    fn material_of(_case: &Self::Case) -> Option<&MaterialSpec> {
        None
    }
    /// A mesh case's materials by key, echoed as `materials`: the specs of [`Self::materials`],
    /// for results written straight into sweep lines without resolving them into a list.
    fn material_map(_case: &Self::Case) -> Option<&std::collections::BTreeMap<String, MaterialSpec>> {
        None
    }
}

/// A file a sweep over some analysis kind writes beside its JSON lines.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct SweepFile {
    /// Extension replacing `.jsonl` (`"csv"`, `"svg"`).
    pub extension: &'static str,
    /// How messages name the file (`"the stage plot"`).
    pub label: &'static str,
    /// The sweep's CSV table (written by the driver, only when no `--csv` is given); else a
    /// file rendered by [`Analysis::render_sweep_file`].
    pub table: bool,
}

/// The typed result of a run plus its views, before the JSON is made.
pub struct Typed<R> {
    /// The typed result.
    pub result: R,
    /// Markdown and CSV views.
    pub report: Report,
    /// Run, case, mesh hinge element, material and result warnings, in that order.
    pub warnings: Vec<String>,
    /// Extra output files.
    pub files: Files,
}

/// Runs `case` as analysis `A`.
pub fn run_typed<A: Analysis>(case: &A::Case, ctx: &mut Ctx) -> Result<Typed<A::Result>, RunError> {
    let result = A::run(case, ctx)?;
    let mut warnings = std::mem::take(&mut ctx.warnings);
    warnings.extend(case_only_warnings::<A>(case));
    warnings.extend(A::result_warnings(case, &result));
    Ok(Typed {
        report: if ctx.with_report {
            A::report(&result)
        } else {
            Report::default()
        },
        warnings,
        files: std::mem::take(&mut ctx.files),
        result,
    })
}

/// The warnings a run of `case` lists that depend on the case alone, in the run's order: the
/// kind's [`Analysis::case_warnings`], the mesh's hinge elements' calibration warnings, the
/// materials' plausibility warnings (`flexfem check` lists them too).
pub fn case_only_warnings<A: Analysis>(case: &A::Case) -> Vec<String> {
    let mut warnings = A::case_warnings(case);
    warnings.extend(A::mesh_model(case).map(|m| m.hinge_warnings()).unwrap_or_default());
    warnings.extend(material_warnings::<A>(case));
    warnings
}

/// The unit-slip warnings (Young's modulus, density; [`crate::case::material::plausibility_warnings`])
/// of the materials a case of kind `A` uses: the one check of every kind that takes a material.
fn material_warnings<A: Analysis>(case: &A::Case) -> Vec<String> {
    use crate::case::material::plausibility_warnings;
    match A::material_of(case) {
        // Built-in materials are plausible; resolving the name would cost every design of a
        // sweep an allocation.
        Some(MaterialSpec::Name(_)) => Vec::new(),
        Some(MaterialSpec::Custom(m)) => plausibility_warnings("material", m),
        None => A::materials(case)
            .iter()
            .flat_map(|(key, _, m)| {
                let at = if key.is_empty() {
                    "material".to_string()
                } else {
                    format!("materials.{key}")
                };
                plausibility_warnings(&at, m)
            })
            .collect(),
    }
}
