//! Critical points of the equilibrium path: each change of stability found along the path
//! (a converged point of one stability followed by one of the other) is located by bisection
//! in the load factor, and its critical mode computed.
//!
//! From the converged state before the change, load-controlled probes step λ in the sense the
//! path was taking there: a probe that converges continuously ([`super::path::load_step`]: no
//! jump over a limit point) to a state of the same stability becomes the new base; one that
//! fails, jumps (lands farther from the start than twice the state on the other side of the
//! change) or changes stability bounds the bracket. Past a limit point no equilibrium is
//! near, so the probes fail; past a bifurcation they converge on the primary branch with the
//! other stability. The bracket [lo, hi] is halved until hi − lo ≤ [`CRITICAL_TOL`]·|λ|.
//!
//! The critical mode is the eigenvector of the tangent stiffness whose eigenvalue is nearest
//! zero at the last base (inverse iteration), the direction in which the structure loses (or
//! regains) stiffness. Its work on the load, |φ·f|/(‖φ‖‖f‖), tells the kind (P. Wriggers &
//! J. C. Simo, "A general procedure for the direct computation of turning and bifurcation
//! points", IJNME 30 (1990) 155–176): a limit (turning) point where the mode works on the load,
//! a bifurcation where it is orthogonal to it (below [`BIFURCATION_WORK`]).

use super::path::{load_step, Change, Judged, Predictor};
use super::residual::{dot, norm};
use super::state::{CaseCtx, State};
use super::NonlinearOptions;
use crate::fem::dof::NodeDof;

/// Relative width of the located load-factor bracket.
pub const CRITICAL_TOL: f64 = 1e-4;

/// Below this work of the critical mode on the load (|φ·f|/(‖φ‖‖f‖)) the point is a
/// bifurcation, above it a limit point.
pub const BIFURCATION_WORK: f64 = 1e-3;

/// Newton iterations allowed per probe (at least).
const PROBE_ITERATIONS: usize = 100;

/// Probes allowed for one critical point.
const MAX_PROBES: usize = 80;

/// Kind of a critical point.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum CriticalKind {
    /// Limit (turning) point: the load factor has an extremum along the path (snap-through
    /// under load control).
    Limit,
    /// Bifurcation: another branch crosses the path (buckling of a perfect structure).
    Bifurcation,
}

/// A located change of stability along the path.
#[derive(Debug, Clone, PartialEq)]
pub struct CriticalPoint {
    /// Middle of `bracket`.
    pub load_factor: f64,
    /// Load factors [lo, hi] between which the change lies: one end a converged state of the
    /// stability before the change, the other a failed or changed probe; hi − lo ≤
    /// [`CRITICAL_TOL`]·|λ|.
    pub bracket: [f64; 2],
    /// Stability lost (true) or regained (false) along the path.
    pub lost: bool,
    /// Limit point or bifurcation.
    pub kind: CriticalKind,
    /// |φ·f|/(‖φ‖‖f‖) of the mode φ on the load f (equations).
    pub load_work: f64,
    /// Tracked values ([`NonlinearOptions::track`]) at the state next to the critical point.
    pub values: Vec<f64>,
    /// Displacements at the state next to the critical point, per node [ux, uy, uz (mm),
    /// rotation vector (rad)], global.
    pub displacements: Vec<[f64; 6]>,
    /// Critical mode per node [ux, uy, uz, rx, ry, rz] (rotations in rad per unit of the
    /// translations), global, scaled to a largest translation of 1 (positive).
    pub mode: Vec<[f64; 6]>,
}

/// Locates the change of stability `c` (`None` when its base state does not have the
/// stability recorded, e.g. the end of a jump, or the probes fail to bracket it).
pub(super) fn locate(ctx: &CaseCtx, c: &Change, opts: &NonlinearOptions, track: &[NodeDof]) -> Option<CriticalPoint> {
    // Probes start from the stable side: from the state before a loss, from the one after a
    // regain (towards the critical point, against the sense λ takes there along the path).
    let (mut base, mut lb, sense) = if c.stable {
        (
            c.states[0].clone(),
            c.lambdas[0],
            if c.sense < 0.0 { -1.0 } else { 1.0 },
        )
    } else {
        let dq = c.dq.as_ref()?;
        let ev = ctx.evaluate(&c.states[1], c.lambdas[1], ctx.newton_tangent())?;
        let t = ctx
            .solve(&ev.values, &[ctx.reduced_load(&c.states[1])])
            .ok()?
            .x
            .remove(0);
        (
            c.states[1].clone(),
            c.lambdas[1],
            if dot(dq, &t) < 0.0 { 1.0 } else { -1.0 },
        )
    };
    // A probe that lands farther from the start than twice the other state of the change has
    // jumped (over a limit point onto a remote branch), whatever its stability.
    let other = if c.stable { &c.states[1] } else { &c.states[0] };
    let start = base.clone();
    let reach = distance(&start, other);
    let continuous = |s: &State| {
        let d = distance(&start, s);
        d.0 <= 2.0 * reach.0 + 1e-9 && d.1 <= 2.0 * reach.1 + 1e-9
    };
    if !ctx.positive_definite(&base, lb) {
        return None;
    }
    let mut internal = ctx.evaluate(&base, lb, super::state::Assemble::None)?.internal;
    // Newton converges only linearly next to a limit point (a near-double root): allow more.
    let opts = &NonlinearOptions {
        max_iterations: opts.max_iterations.max(PROBE_ITERATIONS),
        ..opts.clone()
    };
    let mut t = (c.lambdas[1] - c.lambdas[0]).abs().max(1e-3 * lb.abs()).max(1e-9);
    let mut hi: Option<f64> = None;
    for _ in 0..MAX_PROBES {
        if let Some(h) = hi {
            if h <= CRITICAL_TOL * lb.abs().max(1e-12) {
                break;
            }
            t = 0.5 * h;
        }
        let mut trial = base.clone();
        let res = load_step(
            ctx,
            &mut trial,
            lb,
            lb + sense * t,
            opts,
            internal,
            true,
            Predictor::Moved,
        );
        let same = match res {
            Ok((nk, Judged::Fine(true))) if continuous(&trial) => Some(nk.internal),
            _ => None,
        };
        match same {
            Some(int) => {
                base = trial;
                lb += sense * t;
                internal = int;
                hi = match hi {
                    Some(h) => Some(h - t),
                    None => {
                        t *= 2.0;
                        None
                    }
                };
                if hi.is_none() && t > 1.0 + lb.abs() {
                    return None;
                }
            }
            None => hi = Some(t),
        }
    }
    let h = hi?;
    let other = lb + sense * h;
    let bracket = [lb.min(other), lb.max(other)];
    let (mode_eq, load_work) = critical_mode(ctx, &base, lb)?;
    Some(CriticalPoint {
        load_factor: 0.5 * (bracket[0] + bracket[1]),
        bracket,
        lost: c.stable,
        kind: if load_work < BIFURCATION_WORK {
            CriticalKind::Bifurcation
        } else {
            CriticalKind::Limit
        },
        load_work,
        values: ctx.tracked(&base, track),
        displacements: (0..base.u.len())
            .map(|n| {
                let r = crate::fem::corot::rot_log(&base.r[n]);
                [base.u[n][0], base.u[n][1], base.u[n][2], r[0], r[1], r[2]]
            })
            .collect(),
        mode: per_node(ctx, &base, &mode_eq),
    })
}

/// Largest translation (mm) and rotation (rad) between two states' nodes.
fn distance(a: &State, b: &State) -> (f64, f64) {
    let t = a.u.iter().zip(&b.u).map(|(x, y)| (x - y).norm()).fold(0.0, f64::max);
    (t, super::path::max_rotation_change(a, b))
}

/// The eigenvector of the Newton tangent at `st` whose eigenvalue is nearest zero (inverse
/// iteration from a fixed non-symmetric start), and its work on the load. Next to a critical
/// point that eigenvalue is the critical one unless the model has DOFs softer still (a
/// limitation: members of negligible bending stiffness can take its place).
fn critical_mode(ctx: &CaseCtx, st: &State, lambda: f64) -> Option<(Vec<f64>, f64)> {
    let ev = ctx.evaluate(st, lambda, ctx.newton_tangent())?;
    let n = ctx.n_eq();
    // A start with components in every symmetry class of the model.
    let mut x: Vec<f64> = (0..n).map(|i| 1.0 + 0.5 * (0.7 * i as f64 + 0.3).sin()).collect();
    for _ in 0..30 {
        let y = ctx.solve(&ev.values, &[x.clone()]).ok()?.x.remove(0);
        let (ny, nx) = (norm(&y), norm(&x));
        if !(ny > 0.0 && ny.is_finite()) {
            return None;
        }
        let s = if dot(&y, &x) < 0.0 { -1.0 } else { 1.0 };
        let y: Vec<f64> = y.iter().map(|v| s * v / ny).collect();
        let change = norm(&y.iter().zip(&x).map(|(a, b)| a - b / nx).collect::<Vec<_>>());
        x = y;
        if change < 1e-10 {
            break;
        }
    }
    let f = ctx.reduced_load(st);
    let nf = norm(&f);
    let work = if nf > 0.0 {
        dot(&x, &f).abs() / (norm(&x) * nf)
    } else {
        0.0
    };
    Some((x, work))
}

/// Equation values `q` of an increment as per-node global increments (slaves and framed nodes
/// through the current increment maps), scaled to a largest translation of +1.
fn per_node(ctx: &CaseCtx, st: &State, q: &[f64]) -> Vec<[f64; 6]> {
    let d = ctx.map.scatter(q, None);
    let arms = ctx.arms(st);
    let mut out: Vec<[f64; 6]> = (0..st.u.len())
        .map(|n| {
            let m = ctx.map.rep[n];
            let v = nalgebra::Vector6::from_column_slice(&d[6 * m..6 * m + 6]);
            let v = match &arms[n] {
                Some(a) => a * v,
                None => v,
            };
            std::array::from_fn(|i| v[i])
        })
        .collect();
    let big = |k: std::ops::Range<usize>| {
        out.iter()
            .flat_map(|r| r[k.clone()].iter().copied())
            .fold(0.0f64, |a, v| if v.abs() > a.abs() { v } else { a })
    };
    let mut s = big(0..3);
    if s == 0.0 {
        s = big(3..6);
    }
    if s != 0.0 {
        for r in &mut out {
            for v in r.iter_mut() {
                *v /= s;
            }
        }
    }
    out
}
