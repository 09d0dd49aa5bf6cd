//! The equilibrium path of nonlinear `static` load cases: the traced load–displacement curve
//! (result `trace`, `NAME_path.csv`, `NAME_path.svg`) and the located critical points (result
//! `critical_points`, `NAME_critical.vtu`).

pub use super::path_rows::{CriticalPointRow, TraceRow};
use crate::analysis::fem_static::{self, file_stem, StaticResult};
use crate::analysis::{AnalysisError, Files};
use crate::case::mesh::{path_control, StaticCase};
use crate::fem::{self, CriticalKind, CriticalPoint, Model, PathPoint};

/// The solver options of each load case of `case` (built as `model`) with `steps` nominal
/// steps: its path control and trace, then what `track` asks for.
pub fn options(model: &Model, case: &StaticCase, steps: usize) -> Vec<fem::NonlinearOptions> {
    let (step_track, strokes) = case
        .track
        .as_ref()
        .map(|t| super::track::options(model, t))
        .unwrap_or_default();
    case.model
        .load_cases
        .iter()
        .map(|c| {
            let mut o = path_control::options(c, steps);
            o.track.extend(strokes.iter().copied());
            o.step_track = step_track.clone();
            // Last: the rigid bodies' poses, for their centres of rotation (super::pivot).
            o.track.extend(super::pivot::tracks(model));
            o
        })
        .collect()
}

/// Nonlinear statics of `case` with its path controls: the result, the raw final states, and
/// (with `with_files`) the path files.
pub fn solve(
    model: &Model,
    case: &StaticCase,
    steps: usize,
    with_files: bool,
) -> Result<(StaticResult, fem::StaticResults, Files), AnalysisError> {
    let opts = options(model, case, steps);
    let (mut r, raw, paths) = fem_static::solve_nonlinear_each(model, &opts, case.track.as_ref())?;
    if case
        .model
        .load_cases
        .iter()
        .any(|c| c.control == Some(path_control::Control::ArcLength))
    {
        r.model.push("load cases with \"control\": \"arc_length\": Crisfield's arc-length continuation (Crisfield 1981, Riks 1979) through limit points until the load factor first reaches 1, every step accepted by the same equilibrium test".to_string());
    }
    if paths.iter().any(|(_, c)| !c.is_empty()) {
        r.model.push(format!(
        "changes of stability along the path located by bisection in the load factor to {:e} (relative), with the critical mode",
            fem::nonlinear::CRITICAL_TOL
        ));
    }
    if r.load_cases.iter().any(|c| !c.centre_of_rotation.is_empty()) {
        r.model.push(super::pivot::NOTE.to_string());
    }
    let mut files = Files::new();
    for ((row, spec), (path, critical)) in r.load_cases.iter_mut().zip(&case.model.load_cases).zip(&paths) {
        let trace = spec.trace.as_ref().map(|t| trace_row(t, path));
        row.critical_points = critical
            .iter()
            .map(|c| critical_row(c, spec.trace.as_ref().map(|t| is_rotation(t.dof.dof()))))
            .collect();
        if with_files {
            let stem = file_stem(&row.name);
            if let Some(t) = &trace {
                files.push((format!("{stem}_path.csv"), path_csv(t).into_bytes()));
                files.push((format!("{stem}_path.svg"), path_svg(&row.name, t).into_bytes()));
            }
            if !critical.is_empty() {
                let modes: Vec<(f64, &[[f64; 6]])> =
                    critical.iter().map(|c| (c.load_factor, c.mode.as_slice())).collect();
                let vtu =
                    crate::analysis::common::vtu::modes_vtu_named(model, &modes, &Default::default(), "load_factor")?;
                files.push((format!("{stem}_critical.vtu"), vtu));
            }
        }
        row.trace = trace;
    }
    Ok((r, raw, files))
}

/// Whether [`solve_direct`] may stand for [`solve`] when only the metrics are read: every load
/// case under load control, and nothing recorded along the path (no `trace`, no `track`).
pub fn direct_allowed(case: &StaticCase) -> bool {
    case.track.is_none()
        && case
            .model
            .load_cases
            .iter()
            .all(|c| c.control != Some(path_control::Control::ArcLength) && c.trace.is_none())
}

/// Nonlinear statics of `case` when only the final states are read (the metrics of a design
/// loop, [`crate::analysis::Ctx::metrics_only`]): each load case continued from the unloaded
/// state to λ = 1 in one load step from the linearised tangent predictor
/// ([`fem::nonlinear::continuation`]: cut as the solver judges; in the case's nominal steps of
/// 1/`steps` if that fails), every accepted state checked for equilibrium and stability. The
/// state of an elastic model under proportional loads does not depend on the stable path
/// that reaches it, so only the path's resolution is given up (`path` has its end points).
pub fn solve_direct(
    model: &Model,
    case: &StaticCase,
    steps: usize,
) -> Result<(StaticResult, fem::StaticResults, Files), AnalysisError> {
    let err = |e: fem::FemError| AnalysisError::new("model", e.to_string());
    let opts: Vec<fem::NonlinearOptions> = case
        .model
        .load_cases
        .iter()
        .map(|c| fem::NonlinearOptions {
            locate_critical: false,
            ..path_control::options(c, steps)
        })
        .collect();
    let elems = fem::nonlinear::probe::Elements::new(model).map_err(err)?;
    let load_cases = (0..model.load_cases.len())
        .map(|ic| {
            let mut path = fem::nonlinear::continuation::Continuation::new(model, &elems, ic, &opts[ic])?;
            path.solve_at(1.0, None)
                .or_else(|_| path.solve_at(1.0, Some(1.0 / steps.max(1) as f64)))
        })
        .collect::<Result<Vec<_>, _>>()
        .map_err(err)?;
    let (mut r, raw, _) = fem_static::nonlinear_result(model, fem::NonlinearResults { load_cases }, &opts, None);
    if let Some(first) = r.model.first_mut() {
        *first = format!("geometrically nonlinear statics (large displacements and rotations, small strains), evaluated for the metrics only: each load case solved from the unloaded state by Newton-Raphson in one load step from the linearised tangent predictor (cut as needed; in steps of 1/{steps} of the load if that fails) instead of the case's {steps} nominal steps, which set only the resolution of the reported path; loads fixed in direction; every state checked for equilibrium and stability");
    }
    Ok((r, raw, Files::new()))
}

fn is_rotation(dof: fem::Dof) -> bool {
    dof.index() >= 3
}

fn trace_row(t: &path_control::TraceSpec, path: &[PathPoint]) -> TraceRow {
    let rot = is_rotation(t.dof.dof());
    let v = |p: &PathPoint| {
        let x = p.values.first().copied().unwrap_or(f64::NAN);
        if rot {
            x.to_degrees()
        } else {
            x
        }
    };
    TraceRow {
        node: t.node,
        dof: format!("{:?}", t.dof).to_lowercase(),
        unit: if rot { "deg" } else { "mm" },
        load_factor: path.iter().map(|p| p.lambda).collect(),
        value: path.iter().map(v).collect(),
        stable: path.iter().map(|p| p.stable).collect(),
    }
}

/// The row of critical point `c`; `traced_rotation`: whether the traced DOF (if any) is a
/// rotation (its value then in degrees, as in the trace).
fn critical_row(c: &CriticalPoint, traced_rotation: Option<bool>) -> CriticalPointRow {
    CriticalPointRow {
        load_factor: c.load_factor,
        bracket: c.bracket,
        kind: match c.kind {
            CriticalKind::Limit => "limit",
            CriticalKind::Bifurcation => "bifurcation",
        },
        stability: if c.lost { "lost" } else { "regained" },
        load_work: c.load_work,
        trace_value: traced_rotation.and_then(|rot| {
            let v = c.values.first().copied()?;
            Some(if rot { v.to_degrees() } else { v })
        }),
        mode: c.mode.iter().map(crate::report::numbers::mm_deg).collect(),
    }
}

/// `step,load_factor,VALUE,stable` rows of the traced path.
fn path_csv(t: &TraceRow) -> String {
    let mut s = format!("step,load_factor,{}_{}_{},stable\n", t.dof, t.node, t.unit);
    for (i, ((l, v), st)) in t.load_factor.iter().zip(&t.value).zip(&t.stable).enumerate() {
        s += &format!("{i},{l},{v},{st}\n");
    }
    s
}

/// The load–displacement curve: λ against the traced value, in path order.
fn path_svg(name: &str, t: &TraceRow) -> String {
    let pts: Vec<(f64, f64)> = t.value.iter().copied().zip(t.load_factor.iter().copied()).collect();
    crate::report::svg::curve(
        &format!("Load case {name}: equilibrium path"),
        &format!("{} of node {} ({})", t.dof, t.node, t.unit),
        "load factor λ (–)",
        &[("path", &pts)],
    )
}
