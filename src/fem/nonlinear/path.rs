//! Path control: load (and prescribed-displacement) stepping with adaptive step size, and the
//! stability of the converged points (arc length: [`super::arc`]).

use super::newton::{newton, NewtonOk, Predicted, StepFail};
use super::residual::{dot, norm};
use super::state::{fail, Assemble, CaseCtx, State};
use super::{NonlinearOptions, PathPoint};
use crate::fem::corot;
use crate::fem::error::FemError;

/// Largest rotation of a node within one accepted step, rad: larger converged increments
/// are cut, since a Newton iteration started that far from the solution can land on another
/// branch of the equilibrium path.
pub(super) const MAX_STEP_ROTATION: f64 = 0.5;

/// A converged step whose increment exceeds its tangent predictor this many times has
/// jumped (over a limit point, or onto another branch) and is cut.
pub(super) const MAX_JUMP: f64 = 4.0;

/// Halvings of the load step before a step that still jumps is accepted as a real
/// discontinuity of the path (snap-through) and flagged unstable.
pub(super) const JUMP_CUTS: u32 = 6;

/// Stability along the path: the first loss, bracketed by load factors, and the converged
/// states just before each change of stability (the seeds of [`super::critical`]).
#[derive(Default)]
pub(super) struct Stability {
    pub(super) bracket: Option<[f64; 2]>,
    pub(super) changes: Vec<Change>,
}

/// A change of stability between two converged points of the path: their states and load
/// factors (before, after), the stability before, the sense in which λ grew along the path at
/// the point before (+1 or −1), and (arc length only) the step's increment (equations).
pub(super) struct Change {
    pub(super) states: [State; 2],
    pub(super) lambdas: [f64; 2],
    pub(super) stable: bool,
    pub(super) sense: f64,
    pub(super) dq: Option<Vec<f64>>,
}

/// Changes of stability whose states are kept for locating the critical points.
pub(super) const MAX_CHANGES: usize = 4;

impl Stability {
    /// Records the step from `before` (at `lambda_prev`, of the stability of the last point)
    /// to a point at `lambda` of stability `stable`; `sense`: the sign of dλ along the path at
    /// `before`; `after`: the state reached; `dq`: the step's increment, when known.
    #[allow(clippy::too_many_arguments)]
    pub(super) fn record(
        &mut self,
        before: &State,
        after: &State,
        lambda_prev: f64,
        lambda: f64,
        stable: bool,
        sense: f64,
        dq: Option<&[f64]>,
    ) {
        if !stable && self.bracket.is_none() {
            self.bracket = Some([lambda_prev.min(lambda), lambda_prev.max(lambda)]);
        }
        let was = self.changes.len().is_multiple_of(2);
        if stable != was && self.changes.len() < MAX_CHANGES {
            self.changes.push(Change {
                states: [before.clone(), after.clone()],
                lambdas: [lambda_prev, lambda],
                stable: was,
                sense,
                dq: dq.map(<[f64]>::to_vec),
            });
        }
    }
}

/// Verdict on a converged load step.
pub(super) enum Judged {
    /// A continuous step; whether the end point is stable.
    Fine(bool),
    /// The step may have jumped (over a limit point, onto another branch): why.
    Suspicious(String),
}

/// How a load step starts its Newton iterations.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(super) enum Predictor {
    /// From the converged state with the prescribed DOFs moved: the first Newton correction is
    /// the tangent predictor (with the residual of that state, nonlinear in the prescribed
    /// move: the elements next to a prescribed DOF take all of it).
    Moved,
    /// From the linearised tangent predictor Δq = −K_T⁻¹ (∂r/∂λ) Δλ at the converged state
    /// (∂r/∂λ by a one-sided difference of 10⁻⁵ Δλ): exact to first order in Δλ however
    /// large the prescribed move, for long steps along a smooth path.
    Linear,
}

/// Relative load-factor difference of the linearised predictor's ∂r/∂λ.
const PREDICTOR_DIFFERENCE: f64 = 1e-5;

/// The linearised predictor of a step from the converged state `st` at `lambda` by `dl`: the
/// equation increment Δq = −K_T⁻¹ (∂r/∂λ) Δλ and its work |Δq·(∂r/∂λ) Δλ|.
fn linear_predictor(ctx: &CaseCtx, st: &State, lambda: f64, dl: f64) -> Result<(Vec<f64>, f64), StepFail> {
    let degenerate = || StepFail {
        residual: f64::NAN,
        reason: "degenerate element or non-finite internal force at the predictor".into(),
    };
    let ev = ctx.evaluate(st, lambda, ctx.newton_tangent()).ok_or_else(degenerate)?;
    let eps = PREDICTOR_DIFFERENCE * dl;
    let mut moved = st.clone();
    let dc: Vec<f64> = ctx.u_c.iter().map(|v| v * eps).collect();
    ctx.apply(&mut moved, &vec![0.0; ctx.n_eq()], Some(&dc));
    let (ev_e, _) = ctx.residual(&moved, lambda + eps).ok_or_else(degenerate)?;
    // −(∂r/∂λ) Δλ
    let rhs: Vec<f64> = ev_e.r.iter().zip(&ev.r).map(|(a, b)| -(a - b) / eps * dl).collect();
    let sol = ctx
        .solve(&ev.values, std::slice::from_ref(&rhs))
        .map_err(|reason| StepFail {
            residual: norm(&ev.r),
            reason,
        })?;
    let dq = sol.x.into_iter().next().unwrap_or_default();
    if dq.iter().any(|v| !v.is_finite()) {
        return Err(degenerate());
    }
    let work = dot(&dq, &rhs).abs();
    Ok((dq, work))
}

/// One load-controlled step from the converged state `st` at `lambda` to `target` (prescribed
/// values scaled alike), started as `predictor` says, judged: suspicious when a node rotates
/// more than [`MAX_STEP_ROTATION`], the increment exceeds [`MAX_JUMP`] times its tangent
/// predictor, or the iterations met an indefinite tangent between two stable states
/// (`prev_stable`).
#[allow(clippy::too_many_arguments)]
pub(super) fn load_step(
    ctx: &CaseCtx,
    st: &mut State,
    lambda: f64,
    target: f64,
    opts: &NonlinearOptions,
    internal: f64,
    prev_stable: bool,
    predictor: Predictor,
) -> Result<(NewtonOk, Judged), StepFail> {
    let saved = st.clone();
    let dc: Vec<f64> = ctx.u_c.iter().map(|v| v * (target - lambda)).collect();
    let nk = match predictor {
        Predictor::Moved => {
            ctx.apply(st, &vec![0.0; ctx.n_eq()], Some(&dc));
            newton(ctx, st, target, opts, internal, None)?
        }
        Predictor::Linear => {
            let (dq, work) = linear_predictor(ctx, st, lambda, target - lambda)?;
            ctx.apply(st, &dq, Some(&dc));
            newton(ctx, st, target, opts, internal, Some(Predicted { dq: &dq, work }))?
        }
    };
    let pd = match nk.positive_definite {
        Some(p) => p,
        None => ctx.positive_definite(st, target),
    };
    let rot = max_rotation_change(&saved, st);
    let jump = nk.first > 0.0 && nk.total > MAX_JUMP * nk.first;
    let crossed = prev_stable && pd && nk.met_indefinite;
    let judged = if rot > MAX_STEP_ROTATION {
        Judged::Suspicious(format!("a node rotates {rot:.3} rad in one step"))
    } else if jump {
        Judged::Suspicious(format!(
            "the increment is {:.1}× its tangent predictor",
            nk.total / nk.first
        ))
    } else if crossed {
        Judged::Suspicious("the iterations crossed an indefinite tangent".to_string())
    } else {
        Judged::Fine(pd)
    };
    Ok((nk, judged))
}

/// Largest rotation between two states' nodal rotations, rad.
pub(super) fn max_rotation_change(a: &State, b: &State) -> f64 {
    a.r.iter()
        .zip(&b.r)
        .map(|(ra, rb)| corot::rot_log(&(rb * ra.transpose())).norm())
        .fold(0.0, f64::max)
}

/// Load (and prescribed-displacement) control from `span[0]` to `span[1]` (either way: a
/// continuation may step back along the path). The load step starts at `dl0` (its largest
/// value; 1/steps for a solve from the unloaded state) and adapts: halved when Newton fails, when the converged
/// increment rotates a node by more than [`MAX_STEP_ROTATION`] or exceeds [`MAX_JUMP`] times
/// its tangent predictor, or when an iteration met an indefinite tangent between two stable
/// states (a jump over an unstable stretch); halved for the next step after a slow one (≥ 12
/// iterations), doubled back after a fast one (≤ 4). Every converged point is checked for
/// stability (positive definite symmetric tangent). Each step starts as `predictor` says.
/// Returns (iterations, steps, cuts, λ).
#[allow(clippy::too_many_arguments)]
pub(super) fn load_control(
    ctx: &CaseCtx,
    st: &mut State,
    span: [f64; 2],
    dl0: f64,
    opts: &NonlinearOptions,
    name: &str,
    path: &mut Vec<PathPoint>,
    step0: usize,
    stab: &mut Stability,
    predictor: Predictor,
) -> Result<(usize, usize, usize, f64), FemError> {
    let [lambda0, end] = span;
    let sense = if end < lambda0 { -1.0 } else { 1.0 };
    let dl_jump = dl0 / f64::from(1u32 << JUMP_CUTS);
    let dl_min = dl0 * 0.5f64.powi(opts.max_cuts.min(60) as i32);
    // Steps allowed: the nominal count 10 times over (slow convergence halves the step).
    let max_steps = 10 * opts.steps.max(10);
    let mut dl = dl0;
    let mut lambda = lambda0;
    let mut prev_stable = path.last().is_none_or(|p| p.stable);
    let mut internal = ctx.evaluate(st, lambda0, Assemble::None).map_or(0.0, |ev| ev.internal);
    let (mut iterations, mut steps, mut cuts, mut cut_run) = (0, 0, 0, 0);
    while sense * (end - lambda) > 1e-12 {
        let target = if sense * (end - lambda) < dl + 1e-9 {
            end
        } else {
            lambda + sense * dl
        };
        let saved = st.clone();
        let outcome =
            load_step(ctx, st, lambda, target, opts, internal, prev_stable, predictor).and_then(|(nk, judged)| {
                match judged {
                    Judged::Suspicious(why) if dl > dl_jump * (1.0 + 1e-9) => Err(StepFail {
                        residual: nk.residuals.last().copied().unwrap_or(f64::NAN),
                        reason: format!("step too large: {why}"),
                    }),
                    Judged::Suspicious(_) => Ok((nk, false)),
                    Judged::Fine(pd) => Ok((nk, pd)),
                }
            });
        match outcome {
            Ok((nk, stable)) => {
                iterations += nk.iterations;
                steps += 1;
                internal = nk.internal;
                stab.record(&saved, st, lambda, target, stable, sense, None);
                lambda = target;
                cut_run = 0;
                prev_stable = stable;
                ctx.accept_point(path, st, lambda, stable, nk.residuals, &opts.track, name)?;
                if dl < dl0 && nk.iterations <= 4 {
                    dl = (dl * 2.0).min(dl0);
                } else if nk.iterations >= 12 && dl * 0.5 >= dl_min {
                    dl *= 0.5;
                    cuts += 1;
                }
                if steps > max_steps || cuts > opts.max_total_cuts {
                    return Err(fail(
                        name,
                        step0 + steps,
                        lambda,
                        path.last().and_then(|p| p.residuals.last()).copied().unwrap_or(f64::NAN),
                        format!("{steps} load steps and {cuts} step cuts (Δλ = {dl:.3e}) without reaching λ = {end}: Newton converges too slowly"),
                    ));
                }
            }
            Err(f) => {
                *st = saved;
                cuts += 1;
                cut_run += 1;
                dl *= 0.5;
                if cut_run > opts.max_cuts || cuts > opts.max_total_cuts || dl < dl_min * (1.0 - 1e-9) {
                    let lost = match stab.bracket {
                        Some([lo, hi]) => format!(" (the path already lost stability between λ = {lo:.4} and {hi:.4})"),
                        None => String::new(),
                    };
                    let hint = if lambda > 0.0 {
                        format!("; no equilibrium found just beyond λ = {lambda:.6}: a limit point (snap-through) or a bifurcation is likely there{lost}; arc-length control can follow a limit point")
                    } else {
                        String::new()
                    };
                    return Err(fail(
                        name,
                        step0 + steps + 1,
                        lambda,
                        f.residual,
                        format!(
                            "{} after {} step cuts ({} in a row; last step Δλ = {:.3e}){hint}",
                            f.reason,
                            cuts - 1,
                            cut_run - 1,
                            2.0 * dl
                        ),
                    ));
                }
            }
        }
    }
    Ok((iterations, steps, cuts, lambda))
}

pub(super) fn one_step(opts: &NonlinearOptions) -> NonlinearOptions {
    NonlinearOptions {
        steps: 1,
        ..opts.clone()
    }
}
