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
