//! The `static` analysis on a generic beam model.

use super::AnalysisError;
use crate::fem::{self, Model};

pub use compliance::{compliance_row, ComplianceRow};

pub mod compliance;
mod equilibrium;
pub mod fatigue;
mod headline;
pub mod inner_nodes;
pub mod metrics;
pub mod nonlinear_path;
pub mod path_rows;
pub mod picture;
pub mod pivot;
mod report;
mod rows;
mod summary;
pub mod track;
pub mod warnings;

pub use headline::add_headlines;
pub use inner_nodes::hide_in_shapes;
pub use metrics::MetricValue;
pub use report::{file_stem, report, von_mises_of, vtu, vtu_files};
pub use rows::{
    BeamForcesRow, HingeRow, ShellForcesRow, ShellStressRow, ShellVonMises, StaticCaseRow, StaticResult, StressAt,
    Units, Utilisation,
};

/// Solves every load case of the model.
pub fn solve(model: &Model) -> Result<(StaticResult, fem::StaticResults), AnalysisError> {
    solve_with(model, &mut fem::SolverCache::new())
}

/// [`solve`] reusing the systems of the worker's solver cache where the topology matches.
pub fn solve_with(
    model: &Model,
    cache: &mut fem::SolverCache,
) -> Result<(StaticResult, fem::StaticResults), AnalysisError> {
    let res = fem::solve_static_cached(model, fem::solve::Parallelism::Rayon, cache)
        .map_err(|e| AnalysisError::new("model", e.to_string()))?;
    result_of(model, res, true)
}

/// The linear result of `model` from its load cases `res`, shell stresses added; `checked`:
/// each is checked for equilibrium (a solution; the gradients evaluate results along a
/// first-order path in displacement, which balances the loads to second order only).
pub fn result_of(
    model: &Model,
    res: fem::StaticResults,
    checked: bool,
) -> Result<(StaticResult, fem::StaticResults), AnalysisError> {
    let (shell4, shell9) = model.shell_kinds();
    let rows = res
        .load_cases
        .iter()
        .map(|c| {
            if checked {
                equilibrium::check(model, c)?;
            }
            let mut r = row(c);
            let in_case = |e: fem::FemError| AnalysisError::new(format!("load case `{}`", c.name), e.to_string());
            let field = fem::shell_recovery::shell_field(model, &c.displacements).map_err(in_case)?;
            let spr = if shell9 {
                None
            } else {
                Some(fem::shell_spr::spr_field(model, &c.displacements, &field).map_err(in_case)?)
            };
            add_shell_field(&mut r, field, spr);
            Ok(r)
        })
        .collect::<Result<_, AnalysisError>>()?;
    let mut notes = vec![
        "linear statics, small displacements".to_string(),
        "beams: 2-node exact Timoshenko (Euler–Bernoulli where \"shear\": false); stresses at section critical points"
            .to_string(),
    ];
    // The four-node note stands for every model but one of nine-node shells alone.
    if shell4 || !shell9 {
        notes.push("shells: 4-node flat shell (membrane with drilling rotation, MITC4 bending and transverse shear); von Mises at the element centre, max of top/mid/bottom".to_string());
    }
    if shell9 {
        notes.push(SHELL9_NOTE.to_string());
    }
    notes.extend(fem::superelement::notes(model));
    Ok((
        StaticResult {
            load_cases: rows,
            units: Units {
                displacements: "mm, mm, mm, deg, deg, deg",
                reactions: "N, N, N, N·mm, N·mm, N·mm",
            },
            model: notes,
            compliance: Vec::new(),
            metrics: Default::default(),
            gradients: None,
        },
        res,
    ))
}

/// The model note of nine-node shells (statics).
pub const SHELL9_NOTE: &str = "shells: 9-node flat shell (shell9: biquadratic membrane with drilling rotation, MITC9 bending and transverse shear; flat elements only); von Mises the largest over the element centre and its 3×3 Gauss points, max of top/mid/bottom; surface stresses at the nodes extrapolated from the Gauss points; no patch recovery (no `shell_stress.recovered`)";

/// Geometrically nonlinear statics of every load case in `steps` load steps. Rotations in the
/// output are the components of each node's rotation vector (degrees). Also returns the final
/// state of each load case in the linear result's shape (for the `.vtu` files).
pub fn solve_nonlinear(model: &Model, steps: usize) -> Result<(StaticResult, fem::StaticResults), AnalysisError> {
    solve_nonlinear_tracked(model, steps, None)
}

/// [`solve_nonlinear`] with the quantities `track` asks for at every accepted load step.
pub fn solve_nonlinear_tracked(
    model: &Model,
    steps: usize,
    track: Option<&crate::case::mesh::TrackRequest>,
) -> Result<(StaticResult, fem::StaticResults), AnalysisError> {
    let (step_track, strokes) = track.map(|t| track::options(model, t)).unwrap_or_default();
    let opts = fem::NonlinearOptions {
        steps,
        track: strokes.clone(),
        step_track,
        ..Default::default()
    };
    solve_nonlinear_each(model, &vec![opts; model.load_cases.len()], track).map(|(r, raw, _)| (r, raw))
}

/// The path and critical points of each load case of a nonlinear solve.
pub type Paths = Vec<(Vec<fem::PathPoint>, Vec<fem::CriticalPoint>)>;

/// [`solve_nonlinear`] with options per load case (their `step_track` and `track` as
/// [`track::options`] gives them when `track` is asked for; the stroke DOFs may follow
/// other tracked DOFs); also returns each case's path and critical points.
pub fn solve_nonlinear_each(
    model: &Model,
    opts: &[fem::NonlinearOptions],
    track: Option<&crate::case::mesh::TrackRequest>,
) -> Result<(StaticResult, fem::StaticResults, Paths), AnalysisError> {
    let res = fem::solve_nonlinear_each(model, opts).map_err(|e| AnalysisError::new("model", e.to_string()))?;
    Ok(nonlinear_result(model, res, opts, track))
}

/// The result of the nonlinear solves `res` of `model`'s load cases with `opts` (as
/// [`solve_nonlinear_each`] returns it).
pub fn nonlinear_result(
    model: &Model,
    res: fem::NonlinearResults,
    opts: &[fem::NonlinearOptions],
    track: Option<&crate::case::mesh::TrackRequest>,
) -> (StaticResult, fem::StaticResults, Paths) {
    let steps = opts.first().map_or(0, |o| o.steps);
    let rows = res
        .load_cases
        .iter()
        .zip(&model.load_cases)
        .zip(opts)
        .map(|((c, lc), o)| StaticCaseRow {
            stable: Some(c.stable),
            path_equilibrium_residual: Some(c.equilibrium),
            critical_load_factor: c.critical_load_factor,
            track: track.map(|t| track::row(t, lc, c, &o.track)),
            centre_of_rotation: if o.track.ends_with(&pivot::tracks(model)) {
                pivot::rows(model, &c.path)
            } else {
                Vec::new()
            },
            ..row(&c.fe)
        })
        .collect();
    let mut paths = Paths::new();
    let raw = fem::StaticResults {
        load_cases: res
            .load_cases
            .into_iter()
            .map(|c| {
                paths.push((c.path, c.critical_points));
                c.fe
            })
            .collect(),
    };
    let result = StaticResult {
        load_cases: rows,
        units: Units {
            displacements: "mm, mm, mm, deg, deg, deg (rotation vector)",
            reactions: "N, N, N, N·mm, N·mm, N·mm",
        },
        model: vec![
            format!("geometrically nonlinear statics (large displacements and rotations, small strains), Newton-Raphson in adaptive load steps (at most 1/{steps} of the load each); loads fixed in direction; every state checked for equilibrium and stability"),
            "beams and flexibility elements: co-rotational, local linear element (exact Timoshenko); rigid links exact under finite rotation; springs linear (small rotations)".to_string(),
            "stresses from the section forces in the deformed element frames".to_string(),
        ],
        compliance: Vec::new(),
        metrics: Default::default(),
        gradients: None,
    };
    (result, raw, paths)
}

/// A warning when shells sharing an edge have opposite normals (their top/bottom stresses mix
/// in the nodal averages; see [`fem::shell_recovery::orientation_conflicts`]).
pub fn shell_orientation_warnings(model: &Model) -> Vec<String> {
    let c = fem::shell_recovery::orientation_conflicts(model);
    let Some((a, b, e)) = c.first() else {
        return Vec::new();
    };
    vec![format!(
        "{} shell edge(s) are shared by elements with opposite normals (first: elements {a} and {b} along nodes {}–{}): `shell_stress` top/bottom follow each element's normal, so the nodal averages there mix the two surfaces; list the nodes of every shell in the same sense",
        c.len(),
        e[0],
        e[1]
    )]
}

/// Puts a model's shell stresses into its load-case row (nothing without shells).
fn add_shell_field(r: &mut StaticCaseRow, f: fem::shell_recovery::ShellField, spr: Option<fem::shell_spr::SprField>) {
    if f.forces.is_empty() {
        return;
    }
    r.shell_forces = f
        .forces
        .iter()
        .map(|(element, s)| ShellForcesRow {
            element: *element,
            axes: s.axes,
            n: s.n,
            m: s.m,
            q: s.q,
        })
        .collect();
    r.shell_stress = Some(ShellStressRow {
        top: f.top,
        mid: f.mid,
        bottom: f.bottom,
        recovered: spr.map(rows::ShellRecoveredRow::of),
    });
}

fn row(c: &fem::CaseResult) -> StaticCaseRow {
    StaticCaseRow {
        name: c.name.clone(),
        displacements: c.displacements.iter().map(crate::report::numbers::mm_deg).collect(),
        reactions: c.reactions.iter().map(|(_, r)| *r).collect(),
        reaction_nodes: c.reactions.iter().map(|(n, _)| *n).collect(),
        max_von_mises: c.max_von_mises,
        max_von_mises_at: None,
        max_utilisation: None,
        total_reaction: c.statics.reactions,
        element_von_mises: c.elements.iter().map(|e| e.max_von_mises()).collect(),
        shell_von_mises: c
            .elements
            .iter()
            .enumerate()
            .filter_map(|(element, e)| {
                e.shell.map(|s| ShellVonMises {
                    element,
                    top: s.von_mises[0],
                    mid: s.von_mises[1],
                    bottom: s.von_mises[2],
                })
            })
            .collect(),
        equilibrium_residual: c.statics.residual(),
        path_equilibrium_residual: None,
        stable: None,
        critical_load_factor: None,
        critical_points: Vec::new(),
        trace: None,
        centre_of_rotation: Vec::new(),
        shell_stress: None,
        shell_forces: Vec::new(),
        hinges: Vec::new(),
        beam_forces: Vec::new(),
        track: None,
        loaded_nodes: Vec::new(),
        warnings: Vec::new(),
    }
}

/// Adds the section forces of every beam element to each load case (`raw` in the order of
/// `r.load_cases`).
pub fn add_beam_forces(r: &mut StaticResult, model: &Model, raw: &fem::StaticResults) {
    for (row, c) in r.load_cases.iter_mut().zip(&raw.load_cases) {
        row.beam_forces = model
            .elements
            .iter()
            .enumerate()
            .filter(|(_, e)| matches!(e, fem::Element::Beam(_)))
            .map(|(ie, _)| BeamForcesRow {
                element: ie,
                section_forces: c.elements[ie].section_forces,
            })
            .collect();
    }
}

/// The node compliances `reqs` asks for (linear, undeformed model, its supports only).
pub fn node_compliances(
    model: &Model,
    reqs: &[crate::case::mesh::ComplianceRequest],
) -> Result<Vec<ComplianceRow>, AnalysisError> {
    if reqs.is_empty() {
        return Ok(Vec::new());
    }
    let sys = fem::System::new(model, &[], fem::solve::Parallelism::Rayon)
        .map_err(|e| AnalysisError::new("compliance", e.to_string()))?;
    reqs.iter()
        .enumerate()
        .map(|(i, q)| {
            let c = sys
                .node_compliance(model, q.node)
                .map_err(|e| AnalysisError::new(format!("compliance[{i}]"), e.to_string()))?;
            Ok(compliance_row(q.node, q.frame, &c))
        })
        .collect()
}

/// Adds the per-hinge results of every load case (`raw`: the solver's results in the order
/// of `r.load_cases`; `nonlinear`: rotations are finite rotation vectors).
pub fn add_hinges(
    r: &mut StaticResult,
    model: &Model,
    raw: &fem::StaticResults,
    hinges: &[crate::case::mesh::BuiltHinge],
    nonlinear: bool,
) -> Result<(), AnalysisError> {
    if hinges.is_empty() {
        return Ok(());
    }
    for (row, c) in r.load_cases.iter_mut().zip(&raw.load_cases) {
        row.hinges = hinges
            .iter()
            .map(|h| hinge_row(model, c, h, nonlinear))
            .collect::<Result<_, _>>()?;
    }
    Ok(())
}

/// The results of hinge element `h` in load case `c`.
pub fn hinge_row(
    model: &Model,
    c: &fem::CaseResult,
    h: &crate::case::mesh::BuiltHinge,
    nonlinear: bool,
) -> Result<HingeRow, AnalysisError> {
    use nalgebra::Vector3;
    let err = |e: fem::FemError| AnalysisError::new(format!("elements[{}]", h.case_element), e.to_string());
    let (lam, _) = model.element_frame(h.element).map_err(err)?;
    // A hinge of several segments runs from the first segment's node a to the last one's b.
    let nodes = h
        .end_nodes(model)
        .ok_or_else(|| AnalysisError::new(format!("elements[{}]", h.case_element), "not a hinge element"))?;
    let rot = |n: usize| {
        let d = &c.displacements[n];
        Vector3::new(d[3], d[4], d[5])
    };
    let (ta, tb) = (rot(nodes[0]), rot(nodes[1]));
    let rel = if nonlinear {
        let ra = fem::corot::rot_exp(&ta);
        let rb = fem::corot::rot_exp(&tb);
        fem::corot::rot_log(&(ra.transpose() * rb))
    } else {
        tb - ta
    };
    let ey = Vector3::new(lam[(1, 0)], lam[(1, 1)], lam[(1, 2)]);
    let rotation_deg = ey.dot(&rel).to_degrees();
    let sf = [
        c.elements[h.element].section_forces[0],
        c.elements[h.last].section_forces[1],
    ];
    let peak = h.region.peak_stress(&sf);
    Ok(HingeRow {
        element: h.case_element,
        model_element: h.element,
        rotation_deg,
        end_forces: sf,
        peak_von_mises: peak,
        utilisation: peak / h.allowable,
        remaining_rotation_deg: rotation_deg * (h.allowable / peak - 1.0),
        fatigue: None,
    })
}

/// The warning (plain text, for the result's `warnings`) for a nonlinear load case whose path
/// lost stability.
pub fn stability_text(name: &str, stable: Option<bool>, bracket: Option<[f64; 2]>) -> Option<String> {
    match (stable, bracket) {
        (Some(false), Some([lo, hi])) => Some(format!(
            "load case `{name}`: the equilibrium path lost stability between load factors {lo:.4} and {hi:.4} (the tangent stiffness stopped being positive definite, or the solution jumped over a limit point). The reported state may be unstable or reached by a snap; check for buckling or snap-through (arc length, an imperfection)."
        )),
        (Some(false), None) => Some(format!("load case `{name}`: the equilibrium path is not stable.")),
        _ => None,
    }
}

/// The Markdown callout of [`stability_text`], shown at the load case.
pub fn stability_warning(name: &str, stable: Option<bool>, bracket: Option<[f64; 2]>) -> Option<String> {
    stability_text(name, stable, bracket).map(|w| format!("> **Warning** ({w})\n\n"))
}
