//! The [`Analysis`] implementations of the built-in kinds: each wires a case shape of
//! [`crate::case`] to the run and report functions of its analysis module.

use crate::analysis::common::kind::{named_materials, Analysis, Ctx, SweepFile, UsedMaterial};
use crate::analysis::common::units::{self, UnitOf};
use crate::analysis::common::warn;
use crate::analysis::design::mesh as design_mesh;
use crate::analysis::stage::report as stage_report;
use crate::analysis::{design, fem_static, fem_vs_fkp, hinge, kinematics, modal, stage, Report, RunError};
use crate::case::{self, CaseError, MaterialSpec};

fn one_material(spec: &MaterialSpec) -> Vec<UsedMaterial> {
    spec.resolve("material")
        .map(|m| vec![(String::new(), spec.clone(), m)])
        .unwrap_or_default()
}

/// Stability warnings of nonlinear load cases (`stable`, critical load-factor bracket).
fn stability<'a>(cases: impl Iterator<Item = (&'a str, Option<bool>, Option<[f64; 2]>)>) -> Vec<String> {
    cases
        .filter_map(|(name, stable, bracket)| fem_static::stability_text(name, stable, bracket))
        .collect()
}

/// `kinematics`: 3-PRS rigid-body kinematics.
pub struct Kinematics;

impl Analysis for Kinematics {
    type Case = case::kinematics::KinematicsCase;
    type Result = kinematics::KinematicsResult;

    fn check(case: &Self::Case) -> Result<(), CaseError> {
        case.validate().map(|_| ())
    }
    fn run(case: &Self::Case, _ctx: &mut Ctx) -> Result<Self::Result, RunError> {
        let (prs, bx) = case.validate()?;
        Ok(kinematics::solve(case, &prs, bx.as_ref())?)
    }
    fn report(r: &Self::Result) -> Report {
        kinematics::report(r)
    }
}

/// `hinge`: one flexure hinge in its blank.
pub struct Hinge;

impl Analysis for Hinge {
    type Case = case::hinge::HingeCase;
    type Result = hinge::HingeOut;

    fn check(case: &Self::Case) -> Result<(), CaseError> {
        case.validate().map(|_| ())
    }
    fn run(case: &Self::Case, ctx: &mut Ctx) -> Result<Self::Result, RunError> {
        let out = hinge::solve(case)?;
        if let (true, Some(d)) = (ctx.with_files, &out.damping) {
            ctx.files.extend(hinge::damping_files(d));
        }
        Ok(out)
    }
    fn report(r: &Self::Result) -> Report {
        let mut report = hinge::report(&r.result);
        if let Some(lr) = &r.large_rotation {
            report.markdown += &hinge::large_rotation_report(lr);
        }
        if let Some(d) = &r.damping {
            report.markdown += &hinge::damping_report(d);
        }
        if let Some(f) = &r.fatigue {
            report.markdown += &crate::analysis::hinge::fatigue::report(f);
        }
        report
    }
    fn case_warnings(case: &Self::Case) -> Vec<String> {
        warn::hinge_warnings("hinge", &case.hinge)
    }
    fn result_warnings(case: &Self::Case, r: &Self::Result) -> Vec<String> {
        hinge::end_face_warnings(case, r)
    }
    fn materials(case: &Self::Case) -> Vec<UsedMaterial> {
        one_material(&case.material)
    }
    fn column_units() -> Option<(UnitOf, UnitOf)> {
        Some(units::of::<hinge::HingeOut>())
    }
    fn number_mut<'c>(case: &'c mut Self::Case, path: &[&str]) -> Option<&'c mut f64> {
        case.number_mut(path)
    }
    fn material_of(case: &Self::Case) -> Option<&MaterialSpec> {
        Some(&case.material)
    }
}

/// `stage`: the monolithic 3-PRS compliant stage.
pub struct Stage;

impl Analysis for Stage {
    type Case = case::stage::StageCase;
    type Result = stage::StageResult;

    fn check(case: &Self::Case) -> Result<(), CaseError> {
        case.validate().map(|_| ())
    }
    fn run(case: &Self::Case, ctx: &mut Ctx) -> Result<Self::Result, RunError> {
        let (r, files) = stage::run_stage_with(case, ctx.with_files, ctx.cache)?;
        ctx.files = files;
        ctx.warnings = stability(
            r.load_cases
                .iter()
                .map(|c| (&*c.name, c.stable, c.critical_load_factor)),
        );
        Ok(r)
    }
    fn report(r: &Self::Result) -> Report {
        stage_report::stage_report(r)
    }
    fn result_warnings(_case: &Self::Case, r: &Self::Result) -> Vec<String> {
        let mut w = r.calibration_warnings.clone();
        w.extend(
            r.load_cases
                .iter()
                .enumerate()
                .filter_map(|(ic, c)| stage::warnings::stage_allowable_warning(ic, c)),
        );
        w
    }
    fn materials(case: &Self::Case) -> Vec<UsedMaterial> {
        one_material(&case.material)
    }
    fn sweep_files() -> &'static [SweepFile] {
        &STAGE_SWEEP_FILES
    }
    fn render_sweep_file(_file: &SweepFile, lines: &[String]) -> Option<String> {
        crate::analysis::stage::sweep_plot::stage_sweep_svg(lines)
    }
    fn column_units() -> Option<(UnitOf, UnitOf)> {
        Some(units::of::<stage::StageResult>())
    }
    fn number_mut<'c>(case: &'c mut Self::Case, path: &[&str]) -> Option<&'c mut f64> {
        case.number_mut(path)
    }
    fn material_of(case: &Self::Case) -> Option<&MaterialSpec> {
        Some(&case.material)
    }
}

/// A stage sweep writes an SVG plot (stiffness against reach) and, without `--csv`, its CSV
/// table beside the JSON lines.
const STAGE_SWEEP_FILES: [SweepFile; 2] = [
    SweepFile {
        extension: "svg",
        label: "the stage plot",
        table: false,
    },
    SweepFile {
        extension: "csv",
        label: "the stage table",
        table: true,
    },
];

/// `fem_vs_fkp`: FEM versus rigid-body forward kinematics.
pub struct FemVsFkp;

impl Analysis for FemVsFkp {
    type Case = case::stage::FemVsFkpCase;
    type Result = fem_vs_fkp::FemVsFkpResult;

    fn check(case: &Self::Case) -> Result<(), CaseError> {
        case.validate().map(|_| ())
    }
    fn run(case: &Self::Case, ctx: &mut Ctx) -> Result<Self::Result, RunError> {
        let r = fem_vs_fkp::run_fem_vs_fkp(case)?;
        // The plot is part of the report's files; rendered whether or not they are written.
        ctx.files = fem_vs_fkp::fem_vs_fkp_report(&r).1;
        Ok(r)
    }
    fn report(r: &Self::Result) -> Report {
        fem_vs_fkp::fem_vs_fkp_report(r).0
    }
    fn result_warnings(_case: &Self::Case, r: &Self::Result) -> Vec<String> {
        r.calibration_warnings.clone()
    }
    fn materials(case: &Self::Case) -> Vec<UsedMaterial> {
        one_material(&case.material)
    }
}

/// `sensitivity`: sensitivities of the stage design to its hinge parameters, or of a static
/// mesh case's metrics to its parameters.
pub struct Sensitivity;

impl Analysis for Sensitivity {
    type Case = case::design_mesh::SensitivitySpec;
    type Result = design::SensitivityOut;

    fn check(case: &Self::Case) -> Result<(), CaseError> {
        match case {
            case::design_mesh::SensitivitySpec::Stage(c) => c.validate().map(|_| ()),
            case::design_mesh::SensitivitySpec::Mesh(c) => design_mesh::check_sensitivity::<Static>(c).map(|_| ()),
        }
    }
    fn run(case: &Self::Case, ctx: &mut Ctx) -> Result<Self::Result, RunError> {
        match case {
            case::design_mesh::SensitivitySpec::Stage(c) => {
                let (r, warnings) = design::run_sensitivity_warned(c)?;
                ctx.warnings = warnings;
                Ok(design::SensitivityOut::Stage(r))
            }
            case::design_mesh::SensitivitySpec::Mesh(c) => {
                let (r, warnings) = design_mesh::run_sensitivity::<Static>(c)?;
                ctx.warnings = warnings;
                Ok(design::SensitivityOut::Mesh(r))
            }
        }
    }
    fn report(r: &Self::Result) -> Report {
        match r {
            design::SensitivityOut::Stage(r) => design::sensitivity_report(r),
            design::SensitivityOut::Mesh(r) => design_mesh::sensitivity_report(r),
        }
    }
    fn materials(case: &Self::Case) -> Vec<UsedMaterial> {
        match case {
            case::design_mesh::SensitivitySpec::Stage(c) => one_material(&c.material),
            case::design_mesh::SensitivitySpec::Mesh(_) => Vec::new(),
        }
    }
}

/// `design`: requirement-driven sizing of the stage hinges, or of a static mesh case's parameters.
pub struct Design;

impl Analysis for Design {
    type Case = case::design_mesh::DesignSpec;
    type Result = design::DesignOut;

    fn check(case: &Self::Case) -> Result<(), CaseError> {
        match case {
            case::design_mesh::DesignSpec::Stage(c) => c.validate().map(|_| ()),
            case::design_mesh::DesignSpec::Mesh(c) => design_mesh::check_design::<Static>(c),
        }
    }
    fn run(case: &Self::Case, ctx: &mut Ctx) -> Result<Self::Result, RunError> {
        match case {
            case::design_mesh::DesignSpec::Stage(c) => {
                let (r, warnings) = design::run_design_warned(c)?;
                ctx.warnings = warnings;
                Ok(design::DesignOut::Stage(r))
            }
            case::design_mesh::DesignSpec::Mesh(c) => {
                let (r, warnings) = design_mesh::run_design::<Static>(c)?;
                ctx.warnings = warnings;
                Ok(design::DesignOut::Mesh(r))
            }
        }
    }
    fn report(r: &Self::Result) -> Report {
        match r {
            design::DesignOut::Stage(r) => design::design_report(r),
            design::DesignOut::Mesh(r) => design_mesh::design_report(r),
        }
    }
    fn materials(case: &Self::Case) -> Vec<UsedMaterial> {
        match case {
            case::design_mesh::DesignSpec::Stage(c) => one_material(&c.material),
            case::design_mesh::DesignSpec::Mesh(_) => Vec::new(),
        }
    }
}

/// `static`: linear (or nonlinear) statics of a generic beam/shell model.
pub struct Static;

impl design::problem::StaticAnalysis for Static {
    fn parse_static(
        value: serde_json::Value,
        dir: Option<&std::path::Path>,
        check_arrays: bool,
    ) -> Result<design::problem::ParsedStatic, CaseError> {
        let parsed = super::case_file::parse_resolved(value, dir, check_arrays)?;
        match parsed.case {
            super::case_file::Case::Static(case) => Ok(design::problem::ParsedStatic {
                case,
                parameters: parsed.parameters,
                origins: parsed.origins,
            }),
            _ => Err(CaseError::new("analysis", "must be \"static\"")),
        }
    }

    fn parse_static_in(
        mut value: serde_json::Value,
        mesh: Option<(String, serde_json::Value)>,
        dir: Option<&std::path::Path>,
    ) -> Result<design::problem::ParsedStatic, CaseError> {
        let resolved = crate::case::params::resolve_case_in(&mut value, mesh, None)?;
        let parsed = super::case_file::parse_with(value, dir, resolved)?;
        match parsed.case {
            super::case_file::Case::Static(case) => Ok(design::problem::ParsedStatic {
                case,
                parameters: parsed.parameters,
                origins: parsed.origins,
            }),
            _ => Err(CaseError::new("analysis", "must be \"static\"")),
        }
    }
}

impl Analysis for Static {
    type Case = case::mesh::StaticCase;
    type Result = fem_static::StaticResult;

    fn check(case: &Self::Case) -> Result<(), CaseError> {
        if case.nonlinear {
            case::mesh::superelement::refuse_in(&case.model, "geometrically nonlinear statics")?;
            case::mesh::superelement::refuse_shells_in(&case.model, "geometrically nonlinear statics")?;
        }
        let (_, hinges) = case.model.build_with_hinges(true, case.nonlinear)?;
        case.fatigue.as_ref().map_or(Ok(()), |f| f.check_hinges(&hinges))
    }
    fn run(case: &Self::Case, ctx: &mut Ctx) -> Result<Self::Result, RunError> {
        if case.nonlinear {
            case::mesh::superelement::refuse_in(&case.model, "geometrically nonlinear statics")?;
            case::mesh::superelement::refuse_shells_in(&case.model, "geometrically nonlinear statics")?;
        }
        let (model, hinges, case_index) = case.model.build_indexed(true, case.nonlinear)?;
        let (mut r, raw, path_files) = match case.steps.filter(|_| case.nonlinear) {
            Some(steps) if ctx.metrics_only && fem_static::nonlinear_path::direct_allowed(case) => {
                fem_static::nonlinear_path::solve_direct(&model, case, steps)
            }
            Some(steps) => crate::analysis::fem_static::nonlinear_path::solve(&model, case, steps, ctx.with_files),
            None => fem_static::solve_with(&model, ctx.cache).map(|(r, raw)| (r, raw, Vec::new())),
        }
        .map_err(|e| {
            fem_static::inner_nodes::label(crate::analysis::constraints::singular_hint(e, &case.model), &hinges)
        })?;
        fem_static::add_hinges(&mut r, &model, &raw, &hinges, case.nonlinear)?;
        if let Some(f) = &case.fatigue {
            f.check_hinges(&hinges)?;
            fem_static::fatigue::add(&mut r, &hinges, f);
        }
        fem_static::add_headlines(&mut r, &model, &case_index, &hinges);
        r.model.extend(warn::default_segments_note(&hinges));
        r.model.extend(case.model.promotion_note());
        if case.output.section_forces {
            fem_static::add_beam_forces(&mut r, &model, &raw);
        }
        r.compliance = fem_static::node_compliances(&model, &case.compliance)?;
        let run = case
            .steps
            .filter(|_| case.nonlinear)
            .map(|steps| fem_static::metrics::NonlinearRun {
                steps,
                hinges: &hinges,
                case_index: &case_index,
                raw: &raw,
            });
        r.metrics = fem_static::metrics::evaluate_in(&model, &case.model, &case.metrics, &r, run)?;
        r.model.extend(fem_static::metrics::notes(&case.metrics, run.is_some()));
        if case.gradients {
            let written = case.written.clone().ok_or_else(|| {
                CaseError::new(
                    "gradients",
                    "the case as written was not kept (read the case with analysis::parse_value or from its file)",
                )
            })?;
            let g = crate::gradient::linear(written)?;
            r.gradients = Some(g.table());
            r.model.extend(g.model);
        }
        if !case.output.internal_nodes {
            fem_static::inner_nodes::hide(&mut r, &model, &hinges, case.model.nodes.len());
        }
        if ctx.with_files {
            ctx.files = fem_static::vtu_files(&model, &raw)?;
            ctx.files.push(fem_static::picture::file(
                &model,
                &raw,
                &r,
                &hinges,
                &case.output.picture,
            )?);
            let tracked = r
                .load_cases
                .iter()
                .filter_map(|c| Some((c.name.as_str(), c.track.as_ref()?)));
            ctx.files.extend(crate::analysis::fem_static::track::files(tracked));
            ctx.files.extend(path_files);
        }
        for (ic, row) in r.load_cases.iter_mut().enumerate() {
            let w = if case.nonlinear {
                let stretch = fem_static::warnings::stretch_warning(&model, ic, row);
                let floor = warn::equilibrium_floor_warning(
                    &format!("load case \"{}\"", row.name),
                    row.path_equilibrium_residual,
                );
                stretch
                    .into_iter()
                    .chain(floor)
                    .chain(fem_static::stability_text(
                        &row.name,
                        row.stable,
                        row.critical_load_factor,
                    ))
                    .collect()
            } else {
                Vec::from_iter(fem_static::warnings::linear_range_warning(&model, ic, row))
            };
            row.warnings.extend(w);
        }
        ctx.warnings = r.load_cases.iter().flat_map(|c| c.warnings.iter().cloned()).collect();
        ctx.warnings.extend(if case.nonlinear {
            warn::single_segment_hinge_warnings(&hinges)
        } else {
            fem_static::shell_orientation_warnings(&model)
        });
        Ok(r)
    }
    fn report(r: &Self::Result) -> Report {
        fem_static::report(r)
    }
    fn materials(case: &Self::Case) -> Vec<UsedMaterial> {
        named_materials(&case.model.materials)
    }
    fn mesh_model(case: &Self::Case) -> Option<&case::mesh::MeshSpec> {
        Some(&case.model)
    }
    fn material_map(case: &Self::Case) -> Option<&std::collections::BTreeMap<String, MaterialSpec>> {
        Some(&case.model.materials)
    }
}

/// `modal`: natural frequencies and mode shapes of a generic beam/shell model.
pub struct Modal;

impl Analysis for Modal {
    type Case = case::mesh::ModalCase;
    type Result = modal::ModalResult;

    fn check(case: &Self::Case) -> Result<(), CaseError> {
        case::limits::check_modal(case.modes, case.model.nodes.len())?;
        case.model.build_model(false).map(|_| ())
    }
    fn run(case: &Self::Case, ctx: &mut Ctx) -> Result<Self::Result, RunError> {
        case::limits::check_modal(case.modes, case.model.nodes.len())?;
        let (model, hinges) = case.model.build_with_hinges(false, false)?;
        let (mut r, raw) = modal::solve_with(&model, case.modes, case.shift_hz, ctx.cache)?;
        modal::mark_rigid_body(&model, &raw, &mut r);
        r.model.extend(case.model.promotion_note());
        if !case.shapes {
            r.modes.iter_mut().for_each(|row| row.shape = None);
        }
        let shapes = r.modes.iter_mut().filter_map(|row| row.shape.as_mut());
        r.model.extend(fem_static::inner_nodes::hide_in_shapes(
            shapes,
            &model,
            &hinges,
            case.model.nodes.len(),
        ));
        ctx.warnings = modal::drilling_warnings(&model, &raw);
        ctx.warnings.extend(modal::coarse_shell_warnings(&model, &raw));
        ctx.warnings
            .extend(warn::fewer_modes(case.modes, raw.modes.len(), Some(raw.n_eq)));
        if ctx.with_files {
            ctx.files = vec![("modes.vtu".to_string(), modal::vtu(&model, &raw)?)];
            ctx.files.extend(modal::picture(&model, &raw, &hinges));
        }
        Ok(r)
    }
    fn report(r: &Self::Result) -> Report {
        modal::report(r)
    }
    fn materials(case: &Self::Case) -> Vec<UsedMaterial> {
        named_materials(&case.model.materials)
    }
    fn mesh_model(case: &Self::Case) -> Option<&case::mesh::MeshSpec> {
        Some(&case.model)
    }
}

/// `sweep`: checked here, run by `flexfem sweep` (a batch driver over the other kinds).
pub struct SweepKind;

impl Analysis for SweepKind {
    type Case = case::sweep::SweepCase;
    type Result = ();

    fn check(case: &Self::Case) -> Result<(), CaseError> {
        case.build().map(|_| ())
    }
    fn run(_case: &Self::Case, _ctx: &mut Ctx) -> Result<Self::Result, RunError> {
        Err(RunError::Case(CaseError::value(
            "analysis",
            "\"sweep\"",
            "a sweep runs with `flexfem sweep CASE.json`, not `flexfem run`",
        )))
    }
    fn report(_r: &Self::Result) -> Report {
        Report::default()
    }
}
