//! `stroke_at_allowable`: the stroke (displacement of the driven DOF) and load at which a load
//! case, scaled by s, brings the largest utilisation (von Mises / allowable over every
//! stressed element, [`super::super::add_headlines`]) to 1.
//!
//! Linear runs: the utilisation is proportional to s, so s = 1 / u(1) exactly.
//!
//! Nonlinear runs: u(s) along the equilibrium path is found by nonlinear solves of the load
//! case scaled by s, each continuing the path ([`crate::fem::nonlinear::continuation`]) from
//! the nearest converged stable state — the run's own final state at s = 1, then the earlier
//! solves — in one load step from the linearised tangent predictor (cut as the solver judges;
//! in steps of the case's nominal size s/steps if that fails), every accepted state checked for
//! equilibrium and stability by the solver, a path that loses stability first an error. The
//! search starts from the run's own point u(1) and takes for s₁ the root of the parabola
//! through u(0) = 0 with the linear utilisation as its slope and through u(1); then steps to
//! the root of the parabola through the origin and the last two points (a secant step that
//! knows u(0) = 0; the plain secant where that fails), marching outwards at most ×2 a step
//! until u crosses 1; from then on a step that leaves the bracket (largest scale below 1,
//! smallest above) or does not halve the error falls back to regula falsi inside it (kept 10 %
//! off its ends). It stops when |u − 1| ≤ [`STROKE_TOL`] or two successive scales agree to it
//! (relative).

use super::super::{add_headlines, add_hinges, nonlinear_result, solve_with, StaticCaseRow};
use super::{NonlinearRun, StrokeAtAllowable};
use crate::analysis::AnalysisError;
use crate::case::mesh::{path_control, MeshSpec};
use crate::fem::nonlinear::continuation::Continuation;
use crate::fem::nonlinear::probe::Elements;
use crate::fem::{self, Dof, Model};

/// Relative tolerance of the nonlinear search: on the scale between successive iterates, or
/// on the utilisation.
pub const STROKE_TOL: f64 = 1e-7;

/// Nonlinear solves a search may take before it fails.
const MAX_SOLVES: usize = 40;

/// The load case (index `ic` in the model) and the DOF it drives.
#[derive(Debug, Clone, Copy)]
pub struct Drive {
    pub ic: usize,
    pub node: usize,
    pub dof: Dof,
}

/// One point of the search: the load case scaled by `s`.
#[derive(Debug, Clone, Copy)]
struct Point {
    s: f64,
    /// Largest utilisation and its element (index in the case's `elements`).
    u: f64,
    element: usize,
    /// Displacement of the driven DOF, mm (degrees).
    stroke: f64,
    /// Reaction of the prescribed DOF or the applied force, N (N·mm).
    load: f64,
}

/// Whether `spec`'s load case of `d` prescribes the DOF (else it applies a force along it).
fn prescribed(model: &Model, d: &Drive) -> bool {
    model.load_cases[d.ic]
        .displacements
        .iter()
        .any(|p| p.node == d.node && p.dof == d.dof)
}

/// The point of row `c` (load case scaled by `s`; `base_force`: the force of the unscaled case
/// along the DOF).
fn point(c: &StaticCaseRow, d: &Drive, s: f64, prescribed: bool, base_force: f64) -> Option<Point> {
    let u = c.max_utilisation.as_ref()?;
    let (stroke, load) = stroke_and_load(c, d, s, prescribed, base_force)?;
    Some(Point {
        s,
        u: u.value,
        element: u.element,
        stroke,
        load,
    })
}

/// The displacement of the driven DOF (mm, degrees) and the load along it (N, N·mm) in row `c`.
fn stroke_and_load(c: &StaticCaseRow, d: &Drive, s: f64, prescribed: bool, base_force: f64) -> Option<(f64, f64)> {
    let load = if prescribed {
        let k = c.reaction_nodes.iter().position(|&n| n == d.node)?;
        c.reactions[k][d.dof.index()]
    } else {
        base_force * s
    };
    Some((c.displacements.get(d.node)?[d.dof.index()], load))
}

/// `fatigue_stroke` in linear runs: the load case scaled by 1 / its largest hinge fatigue
/// utilisation (`c`: its solved row, hinge fatigue added). `None` when no hinge is stressed.
pub fn fatigue_linear(model: &Model, d: &Drive, c: &StaticCaseRow) -> Result<Option<StrokeAtAllowable>, AnalysisError> {
    let missing = || AnalysisError::new("load case", "the driven node has no result (checked when parsed)");
    let worst = c
        .hinges
        .iter()
        .filter_map(|h| Some((h.fatigue?.utilisation, h.element)))
        .fold(None, |w: Option<(f64, usize)>, (u, e)| match w {
            Some((wu, _)) if wu >= u => w,
            _ => Some((u, e)),
        });
    let Some((u, element)) = worst.filter(|(u, _)| *u > 0.0) else {
        return Ok(None);
    };
    let (stroke, load) = stroke_and_load(c, d, 1.0, prescribed(model, d), base_force(model, d)).ok_or_else(missing)?;
    Ok(Some(StrokeAtAllowable {
        stroke: stroke / u,
        load: load / u,
        element,
        linear_estimate: stroke / u,
        utilisation: 1.0,
        solves: 0,
    }))
}

/// The force of load case `d.ic` along the DOF at the node, N (N·mm).
fn base_force(model: &Model, d: &Drive) -> f64 {
    model.load_cases[d.ic]
        .forces
        .iter()
        .filter(|f| f.node == d.node)
        .map(|f| f.f[d.dof.index()])
        .sum()
}

/// Linear runs: the load case scaled by 1 / its utilisation (`c`: its solved row). `None`
/// when nothing is stressed or no element has an allowable stress.
pub fn linear(
    model: &Model,
    _spec: &MeshSpec,
    d: &Drive,
    c: &StaticCaseRow,
) -> Result<Option<StrokeAtAllowable>, AnalysisError> {
    let missing = || AnalysisError::new("load case", "the driven node has no result (checked when parsed)");
    if c.max_utilisation.as_ref().is_none_or(|u| u.value <= 0.0) {
        return Ok(None);
    }
    let p = point(c, d, 1.0, prescribed(model, d), base_force(model, d)).ok_or_else(missing)?;
    let stroke = p.stroke / p.u;
    Ok(Some(StrokeAtAllowable {
        stroke,
        load: p.load / p.u,
        element: p.element,
        linear_estimate: stroke,
        utilisation: 1.0,
        solves: 0,
    }))
}

/// The model with only load case `d.ic`, unscaled.
fn single_case(model: &Model, d: &Drive) -> Model {
    Model {
        load_cases: vec![model.load_cases[d.ic].clone()],
        ..model.clone()
    }
}

/// Nonlinear runs: the search of the module documentation, from `c`, the run's own row of the
/// load case (its point at scale 1). `None` when the linear run stresses nothing with an
/// allowable stress.
pub fn nonlinear(
    model: &Model,
    spec: &MeshSpec,
    d: &Drive,
    c: &StaticCaseRow,
    run: &NonlinearRun<'_>,
) -> Result<Option<StrokeAtAllowable>, AnalysisError> {
    let name = model.load_cases[d.ic].name.clone();
    let ctx = |s: f64| format!("load case \"{name}\" scaled by {s:.9e}");
    let missing = || AnalysisError::new(name.clone(), "the driven node has no result");
    let m = single_case(model, d);
    let (pres, force) = (prescribed(model, d), base_force(model, d));
    let one = Drive { ic: 0, ..*d };

    // The linear estimate.
    let (mut lin, raw) = solve_with(&m, &mut fem::SolverCache::new())?;
    add_hinges(&mut lin, &m, &raw, run.hinges, false)?;
    add_headlines(&mut lin, &m, run.case_index, run.hinges);
    let Some(p_lin) = point(&lin.load_cases[0], &one, 1.0, pres, force).filter(|p| p.u > 0.0) else {
        return Ok(None);
    };
    let linear_estimate = p_lin.stroke / p_lin.u;

    let spec_lc = spec.load_cases.iter().find(|c| c.name == name).ok_or_else(missing)?;
    let opts = fem::NonlinearOptions {
        locate_critical: false,
        track: Vec::new(),
        step_track: Default::default(),
        ..path_control::options(spec_lc, run.steps)
    };
    let fem_err = |s: f64, e: fem::FemError| AnalysisError::new(ctx(s), e.to_string());
    let elems = Elements::new(&m).map_err(|e| fem_err(1.0, e))?;
    let mut path = Continuation::new(&m, &elems, 0, &opts).map_err(|e| fem_err(1.0, e))?;
    // The run's final state is on the stable path: the nearest start for scales near 1.
    if c.stable != Some(false) {
        if let Some(state) = run.raw.load_cases.get(d.ic) {
            path.add_state(state, 1.0);
        }
    }
    let mut solves = 0;
    let mut probe = |s: f64| -> Result<Point, AnalysisError> {
        solves += 1;
        // One step from the nearest converged state (cut as the solver judges); the nominal
        // step of the case, s / steps, if that fails.
        let nl = path
            .solve_at(s, None)
            .or_else(|_| path.solve_at(s, Some(s.abs() / run.steps.max(1) as f64)))
            .map_err(|e| fem_err(s, e))?;
        let res = fem::NonlinearResults { load_cases: vec![nl] };
        let (mut r, raw, _) = nonlinear_result(&m, res, std::slice::from_ref(&opts), None);
        add_hinges(&mut r, &m, &raw, run.hinges, true)?;
        add_headlines(&mut r, &m, run.case_index, run.hinges);
        let c = &r.load_cases[0];
        if c.stable == Some(false) {
            return Err(AnalysisError::new(
                ctx(s),
                "the equilibrium path lost stability before the largest utilisation reached 1 (buckling or snap-through): the stroke at the allowable is not on a stable path",
            ));
        }
        // The scale the solve reached is the scale asked for (load control ends there); the
        // load of a force-driven case scales with it.
        point(c, &one, s, pres, force)
            .filter(|p| p.u.is_finite())
            .ok_or_else(|| AnalysisError::new(ctx(s), "no utilisation along the path"))
    };
    let start = point(c, d, 1.0, pres, force)
        .filter(|p| p.u > 0.0 && p.u.is_finite())
        .ok_or_else(|| AnalysisError::new(name.clone(), "no utilisation along the path of the run"))?;
    let found = search(start, quadratic_root(p_lin.u, start.u), &mut probe)?;
    Ok(Some(StrokeAtAllowable {
        stroke: found.stroke,
        load: found.load,
        element: found.element,
        linear_estimate,
        utilisation: found.u,
        solves,
    }))
}

/// The first trial scale: the root of u(s) = u₀·s + (u₁ − u₀)·s² = 1, the parabola through
/// u(0) = 0 with the linear slope u₀ (the tangent of the path at the unloaded state) and the
/// run's point u(1) = u₁; the secant 1/u₁ when it has no positive root.
fn quadratic_root(u0: f64, u1: f64) -> f64 {
    let c = u1 - u0;
    let disc = u0 * u0 + 4.0 * c;
    if c.abs() <= 1e-12 * u0 || disc < 0.0 {
        return 1.0 / u1;
    }
    // The root continuous in c → 0 (no cancellation): 2 / (u₀ + √(u₀² + 4c)).
    let s = 2.0 / (u0 + disc.sqrt());
    if s.is_finite() && s > 0.0 {
        s
    } else {
        1.0 / u1
    }
}

/// The root nearest `b.s` of u(s) = α·s + β·s² = 1, the parabola through the origin (u(0) = 0)
/// and the points `a` and `b`: a secant step that also knows the unloaded state, exact for a
/// quadratic u(s). `None` when the points do not determine it or it has no root near `b`.
fn through_origin(a: Point, b: Point) -> Option<f64> {
    // α·s + β·s² = u at a and b: Cramer's rule.
    let det = a.s * b.s * b.s - b.s * a.s * a.s;
    if det.abs() <= 1e-12 * (a.s * b.s * b.s).abs() {
        return None;
    }
    let alpha = (a.u * b.s * b.s - b.u * a.s * a.s) / det;
    let beta = (a.s * b.u - b.s * a.u) / det;
    let disc = alpha * alpha + 4.0 * beta;
    let s = 2.0 / (alpha + disc.sqrt());
    (disc >= 0.0 && s.is_finite() && s > 0.0 && (s - b.s).abs() <= b.s.abs()).then_some(s)
}

/// The bracketed secant search of u(s) = 1 from the point `first` and the trial scale `s1`
/// (module documentation).
fn search(
    first: Point,
    s1: f64,
    probe: &mut impl FnMut(f64) -> Result<Point, AnalysisError>,
) -> Result<Point, AnalysisError> {
    if (first.u - 1.0).abs() <= STROKE_TOL {
        return Ok(first);
    }
    let mut pts = vec![first, probe(s1)?];
    while pts.len() < MAX_SOLVES {
        let (a, b) = (pts[pts.len() - 2], pts[pts.len() - 1]);
        if (b.u - 1.0).abs() <= STROKE_TOL || (b.s - a.s).abs() <= STROKE_TOL * b.s.abs() {
            return Ok(b);
        }
        // The tightest bracket so far: the largest scale below 1, the smallest above.
        let lo = pts.iter().filter(|p| p.u < 1.0).max_by(|p, q| p.s.total_cmp(&q.s));
        let hi = pts.iter().filter(|p| p.u > 1.0).min_by(|p, q| p.s.total_cmp(&q.s));
        let slope = (b.u - a.u) / (b.s - a.s);
        let secant = through_origin(a, b).unwrap_or(b.s + (1.0 - b.u) / slope);
        let next = match (lo, hi) {
            (Some(lo), Some(hi)) => {
                let inside = secant > lo.s.min(hi.s) && secant < lo.s.max(hi.s);
                // A secant step that leaves the bracket, or one that did not halve the error
                // of the step before, falls back to regula falsi on the bracket.
                let slow = (b.u - 1.0).abs() > 0.5 * (a.u - 1.0).abs();
                if inside && !slow && slope.is_finite() {
                    secant
                } else {
                    let t = (1.0 - lo.u) / (hi.u - lo.u);
                    // Keep off the ends so a curved u(s) cannot stall regula falsi.
                    lo.s + t.clamp(0.1, 0.9) * (hi.s - lo.s)
                }
            }
            _ if slope > 0.0 && slope.is_finite() => secant.clamp(0.5 * b.s, 2.0 * b.s),
            _ => b.s / b.u,
        };
        pts.push(probe(next)?);
    }
    let b = pts[pts.len() - 1];
    Err(AnalysisError::new(
        "stroke_at_allowable",
        format!(
            "the search for utilisation 1 did not converge in {MAX_SOLVES} nonlinear solves (last: scale {:.9e}, utilisation {:.9})",
            b.s, b.u
        ),
    ))
}
