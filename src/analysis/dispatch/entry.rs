//! The object-safe view of the [`Analysis`](crate::analysis::Analysis) kinds: [`DynAnalysis`], implemented for each line
//! of the list of kinds by [`Entry`] (the registry holds one per kind). It names the parsed
//! [`Case`] enum, which the list of kinds generates, so it sits above the kinds, beside the list.

use super::case_file::{Case, CaseOf};
use crate::analysis::common::kind::{case_only_warnings, run_typed, Ctx, SweepFile, Typed, UsedMaterial};
use crate::analysis::common::line::{Echoed, LineTarget, MaterialEcho, MaterialsEcho};
use crate::analysis::common::units::UnitOf;
use crate::analysis::RunError;
use crate::case::CaseError;

/// The object-safe view of an [`Analysis`], as the registry holds it.
pub trait DynAnalysis: Sync {
    /// [`CaseOf::KIND`](super::case_file::CaseOf::KIND).
    fn kind(&self) -> &'static str;
    /// [`Analysis::check`] of a parsed case of this kind (`None` if the case is another kind).
    fn check(&self, case: &Case) -> Option<Result<(), CaseError>>;
    /// The warnings of a checked case of this kind that depend on the case alone
    /// ([`crate::analysis::common::kind::case_only_warnings`]; `None` if another kind).
    fn case_warnings(&self, case: &Case) -> Option<Vec<String>>;
    /// Runs a parsed case of this kind into its outcome (`None` if the case is another kind).
    fn run(&self, case: &Case, ctx: &mut Ctx) -> Option<Result<crate::analysis::Outcome, RunError>>;
    /// [`Analysis::materials`].
    fn materials(&self, case: &Case) -> Vec<UsedMaterial>;
    /// [`Analysis::sweep_files`].
    fn sweep_files(&self) -> &'static [SweepFile];
    /// [`Analysis::render_sweep_file`].
    fn render_sweep_file(&self, file: &SweepFile, lines: &[String]) -> Option<String>;
    /// [`Analysis::column_units`].
    fn column_units(&self) -> Option<(UnitOf, UnitOf)>;
    /// [`Analysis::number_mut`] of a parsed case of this kind.
    fn number_mut<'c>(&self, case: &'c mut Case, path: &[&str]) -> Option<&'c mut f64>;
    /// Runs a case of this kind and appends its result, as a run writes it (with the `material`
    /// or `materials`, `warnings` and `parameters` echoes), to the line of `to` as its spec
    /// keeps it — without a JSON value and, on the
    /// paths of the kinds that give [`Analysis::number_mut`], without allocating. `None`: the
    /// kind does not write lines this way.
    fn write_result(&self, case: &Case, ctx: &mut Ctx, to: LineTarget) -> Option<Result<(), RunError>>;
}

/// The registry entry of analysis `A`.
pub struct Entry<A>(std::marker::PhantomData<fn() -> A>);

impl<A> Entry<A> {
    /// The entry (a zero-sized value).
    pub const fn new() -> Self {
        Entry(std::marker::PhantomData)
    }
}

impl<A> Default for Entry<A> {
    fn default() -> Self {
        Self::new()
    }
}

impl<A: CaseOf> DynAnalysis for Entry<A> {
    fn kind(&self) -> &'static str {
        A::KIND
    }
    fn check(&self, case: &Case) -> Option<Result<(), CaseError>> {
        A::case_of(case).map(A::check)
    }
    fn case_warnings(&self, case: &Case) -> Option<Vec<String>> {
        A::case_of(case).map(case_only_warnings::<A>)
    }
    fn run(&self, case: &Case, ctx: &mut Ctx) -> Option<Result<crate::analysis::Outcome, RunError>> {
        let c = A::case_of(case)?;
        Some(run_typed::<A>(c, ctx).and_then(|t| {
            Ok(crate::analysis::Outcome {
                json: crate::analysis::to_checked_json(&t.result)?,
                warnings: t.warnings,
                report: t.report,
                files: t.files,
            })
        }))
    }
    fn materials(&self, case: &Case) -> Vec<UsedMaterial> {
        A::case_of(case).map(A::materials).unwrap_or_default()
    }
    fn sweep_files(&self) -> &'static [SweepFile] {
        A::sweep_files()
    }
    fn render_sweep_file(&self, file: &SweepFile, lines: &[String]) -> Option<String> {
        A::render_sweep_file(file, lines)
    }
    fn column_units(&self) -> Option<(UnitOf, UnitOf)> {
        A::column_units()
    }
    fn number_mut<'c>(&self, case: &'c mut Case, path: &[&str]) -> Option<&'c mut f64> {
        A::number_mut(A::case_of_mut(case)?, path)
    }
    fn write_result(&self, case: &Case, ctx: &mut Ctx, to: LineTarget) -> Option<Result<(), RunError>> {
        let c = A::case_of(case)?;
        let spec_material = A::material_of(c);
        // A map echoes as `materials` when every entry resolves under a non-empty key (else
        // `run_with` leaves some out or names the one material `material`).
        let map = A::material_map(c).filter(|m| !m.is_empty());
        match (spec_material, map) {
            (Some(_), _) => {}
            (None, Some(m)) => {
                if m.iter().any(|(k, spec)| k.is_empty() || spec.resolve(k).is_err()) {
                    return None;
                }
            }
            (None, None) => {
                if !A::materials(c).is_empty() {
                    return None;
                }
            }
        }
        let mut run = || -> Result<(), RunError> {
            // The sweep's context renders no report and no files: only the result and warnings.
            let Typed { result, warnings, .. } = run_typed::<A>(c, ctx)?;
            crate::analysis::check_finite(&result)?;
            let material = match spec_material {
                Some(spec) => Some((spec, spec.resolve("material")?)),
                None => None,
            };
            let echoed = Echoed {
                result: &result,
                material: material.as_ref().map(|(spec, m)| MaterialEcho::of(spec, m)),
                materials: spec_material.is_none().then_some(map).flatten().map(MaterialsEcho),
                warnings: &warnings,
                parameters: to.parameters.filter(|p| !p.is_empty()),
            };
            to.line
                .write(&echoed, to.spec)
                .map_err(|e| crate::analysis::AnalysisError::new("output", e.to_string()).into())
        };
        Some(run())
    }
}
