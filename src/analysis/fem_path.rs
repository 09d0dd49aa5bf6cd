//! The equilibrium path of nonlinear `static` load cases: the traced load–displacement curve
//! (result `trace`, `NAME_path.csv`, `NAME_path.svg`) and the located critical points (result
//! `critical_points`, `NAME_critical.vtu`).

use super::fem_static::{self, file_stem, StaticCaseRow, StaticResult};
use super::{AnalysisError, Files};
use crate::case::mesh::{path_control, StaticCase};
use crate::fem::{self, CriticalKind, CriticalPoint, Model, PathPoint};
use crate::report::markdown::Table;
use serde::Serialize;

/// The traced DOF along the path of one load case.
#[derive(Debug, Clone, Serialize)]
pub struct TraceRow {
    /// The node.
    pub node: usize,
    /// The DOF (`ux` … `rz`, global; rotations: rotation-vector component).
    pub dof: String,
    /// Unit of `value`: `mm` or `deg`.
    pub unit: &'static str,
    /// Load factor λ of each converged point, from 0 (loads = λ × the case's loads).
    pub load_factor: Vec<f64>,
    /// The DOF's value at each point.
    pub value: Vec<f64>,
    /// Whether each point is stable (positive definite tangent stiffness).
    pub stable: Vec<bool>,
}

/// A located change of stability along the path.
#[derive(Debug, Clone, Serialize)]
pub struct CriticalPointRow {
    /// Middle of `bracket`.
    pub load_factor: f64,
    /// Load factors [lo, hi] bracketing the critical point, hi − lo ≤ 1e-4·|λ|.
    pub bracket: [f64; 2],
    /// `limit` (the load has an extremum: snap-through under load control) or `bifurcation`
    /// (another branch crosses the path: buckling).
    pub kind: &'static str,
    /// `lost` or `regained` along the path.
    pub stability: &'static str,
    /// |φ·f|/(‖φ‖‖f‖): work of the critical mode φ on the load f (≈ 0 at a bifurcation).
    pub load_work: f64,
    /// The traced DOF at the critical point (`trace` units), when the load case traces one.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub trace_value: Option<f64>,
    /// Critical mode per node [ux, uy, uz, rx, ry, rz], global, largest translation 1
    /// (rotations in degrees per unit translation).
    pub mode: Vec<[f64; 6]>,
}

/// The solver options of each load case of `case` with `steps` nominal steps.
pub fn options(case: &StaticCase, steps: usize) -> Vec<fem::NonlinearOptions> {
    case.model
        .load_cases
        .iter()
        .map(|c| path_control::options(c, steps))
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
    let (mut r, raw, paths) = fem_static::solve_nonlinear_each(model, &options(case, steps))?;
    let mut files = Files::new();
    for ((row, spec), (path, critical)) in r.load_cases.iter_mut().zip(&case.model.load_cases).zip(&paths) {
        let trace = spec.trace.as_ref().map(|t| trace_row(t, path));
        row.critical_points = critical.iter().map(|c| critical_row(c, trace.is_some())).collect();
        if with_files {
            let stem = file_stem(&row.name);
            if let Some(t) = &trace {
                files.push((format!("{stem}_path.csv"), path_csv(t).into_bytes()));
                files.push((format!("{stem}_path.svg"), path_svg(&row.name, t).into_bytes()));
            }
            if !critical.is_empty() {
                let modes: Vec<(f64, &[[f64; 6]])> =
                    critical.iter().map(|c| (c.load_factor, c.mode.as_slice())).collect();
                let vtu = super::vtu::modes_vtu_labelled(model, &modes, &Default::default(), "load_factor")?;
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

fn critical_row(c: &CriticalPoint, traced: bool) -> CriticalPointRow {
    let deg = |m: &[f64; 6]| {
        [
            m[0],
            m[1],
            m[2],
            m[3].to_degrees(),
            m[4].to_degrees(),
            m[5].to_degrees(),
        ]
    };
    // The traced value: the one tracked DOF, in the trace's unit (a rotation's unit follows the
    // trace row: convert here as it does).
    CriticalPointRow {
        load_factor: c.load_factor,
        bracket: c.bracket,
        kind: match c.kind {
            CriticalKind::Limit => "limit",
            CriticalKind::Bifurcation => "bifurcation",
        },
        stability: if c.lost { "lost" } else { "regained" },
        load_work: c.load_work,
        trace_value: if traced { c.values.first().copied() } else { None },
        mode: c.mode.iter().map(deg).collect(),
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
        "load factor λ",
        &[("path", &pts)],
    )
}

/// The Markdown section of a load case's critical points and traced path (empty without).
pub fn markdown(c: &StaticCaseRow) -> String {
    let mut md = String::new();
    if !c.critical_points.is_empty() {
        md += "Critical points along the path (load factor bracketed to 1e-4):\n\n";
        let mut t = Table::new(&["load factor", "bracket", "kind", "stability", "mode work on load"]);
        for p in &c.critical_points {
            t.row(vec![
                format!("{:.6}", p.load_factor),
                format!("[{:.6}, {:.6}]", p.bracket[0], p.bracket[1]),
                p.kind.to_string(),
                p.stability.to_string(),
                format!("{:.2e}", p.load_work),
            ]);
        }
        md += &t.render();
        md += "\n";
    }
    if let Some(t) = &c.trace {
        let lo = t.load_factor.iter().copied().fold(f64::INFINITY, f64::min);
        let hi = t.load_factor.iter().copied().fold(f64::NEG_INFINITY, f64::max);
        md += &format!(
            "Traced path: {} points, {} of node {} from {:.6} to {:.6} {}, load factor between {lo:.6} and {hi:.6} (`{}_path.csv`, `{}_path.svg` with `--out`).\n\n",
            t.value.len(),
            t.dof,
            t.node,
            t.value.first().copied().unwrap_or(0.0),
            t.value.last().copied().unwrap_or(0.0),
            t.unit,
            file_stem(&c.name),
            file_stem(&c.name)
        );
    }
    md
}
