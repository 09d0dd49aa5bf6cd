//! Path control: load (and prescribed-displacement) stepping with adaptive step size, Crisfield's
//! cylindrical arc-length method, and the stability of the converged points.

use super::newton::{bound, newton, StepFail};
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

/// Stability along the path: the first loss, bracketed by load factors.
#[derive(Debug, Default)]
pub(super) struct Stability {
    pub(super) bracket: Option<[f64; 2]>,
}

impl Stability {
    pub(super) fn record(&mut self, lambda_prev: f64, lambda: f64, stable: bool) {
        if !stable && self.bracket.is_none() {
            self.bracket = Some([lambda_prev.min(lambda), lambda_prev.max(lambda)]);
        }
    }
}

/// Largest rotation between two states' nodal rotations, rad.
pub(super) fn max_rotation_change(a: &State, b: &State) -> f64 {
    a.r.iter()
        .zip(&b.r)
        .map(|(ra, rb)| corot::rot_log(&(rb * ra.transpose())).norm())
        .fold(0.0, f64::max)
}

/// Load (and prescribed-displacement) control from `lambda0` to 1. The load step starts at
/// 1/steps (its largest value) and adapts: halved when Newton fails, when the converged
/// increment rotates a node by more than [`MAX_STEP_ROTATION`] or exceeds [`MAX_JUMP`] times
/// its tangent predictor, or when an iteration met an indefinite tangent between two stable
/// states (a jump over an unstable stretch); halved for the next step after a slow one (≥ 12
/// iterations), doubled back after a fast one (≤ 4). Every converged point is checked for
/// stability (positive definite symmetric tangent). Returns (iterations, steps, cuts, λ).
#[allow(clippy::too_many_arguments)]
pub(super) fn load_control(
    ctx: &CaseCtx,
    st: &mut State,
    lambda0: f64,
    opts: &NonlinearOptions,
    name: &str,
    path: &mut Vec<PathPoint>,
    step0: usize,
    stab: &mut Stability,
) -> Result<(usize, usize, usize, f64), FemError> {
    let dl0 = 1.0 / opts.steps as f64;
    let dl_jump = dl0 / f64::from(1u32 << JUMP_CUTS);
    let dl_min = dl0 * 0.5f64.powi(opts.max_cuts.min(60) as i32);
    // Steps allowed: the nominal count 10 times over (slow convergence halves the step).
    let max_steps = 10 * opts.steps.max(10);
    let mut dl = dl0;
    let mut lambda = lambda0;
    let mut prev_stable = path.last().is_none_or(|p| p.stable);
    let mut internal = ctx.evaluate(st, lambda0, Assemble::None).map_or(0.0, |ev| ev.internal);
    let (mut iterations, mut steps, mut cuts, mut cut_run) = (0, 0, 0, 0);
    while lambda < 1.0 - 1e-12 {
        let target = if lambda + dl > 1.0 - 1e-9 { 1.0 } else { lambda + dl };
        let saved = st.clone();
        let dc: Vec<f64> = ctx.u_c.iter().map(|v| v * (target - lambda)).collect();
        ctx.apply(st, &vec![0.0; ctx.n_eq()], Some(&dc));
        let outcome = newton(ctx, st, target, opts, internal).and_then(|nk| {
            let pd = match nk.positive_definite {
                Some(p) => p,
                None => ctx.positive_definite(st, target),
            };
            let rot = max_rotation_change(&saved, st);
            let jump = nk.first > 0.0 && nk.total > MAX_JUMP * nk.first;
            let crossed = prev_stable && pd && nk.met_indefinite;
            let suspicious = rot > MAX_STEP_ROTATION || jump || crossed;
            if suspicious && dl > dl_jump * (1.0 + 1e-9) {
                let why = if rot > MAX_STEP_ROTATION {
                    format!("a node rotates {rot:.3} rad in one step")
                } else if jump {
                    format!("the increment is {:.1}× its tangent predictor", nk.total / nk.first)
                } else {
                    "the iterations crossed an indefinite tangent".to_string()
                };
                return Err(StepFail {
                    residual: nk.residuals.last().copied().unwrap_or(f64::NAN),
                    reason: format!("step too large: {why}"),
                });
            }
            Ok((nk, pd && !suspicious))
        });
        match outcome {
            Ok((nk, stable)) => {
                iterations += nk.iterations;
                steps += 1;
                internal = nk.internal;
                stab.record(lambda, target, stable);
                lambda = target;
                cut_run = 0;
                prev_stable = stable;
                path.push(PathPoint {
                    lambda,
                    values: ctx.tracked(st, &opts.track),
                    stable,
                    residuals: nk.residuals,
                });
                ctx.record_step(st, lambda, path.len() - 1)?;
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
                        format!("{steps} load steps and {cuts} step cuts (Δλ = {dl:.3e}) without reaching λ = 1: Newton converges too slowly"),
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

/// Crisfield's cylindrical arc length (ψ = 0) until λ reaches 1; the last piece is load
/// controlled so the path ends at λ = 1 exactly.
pub(super) fn arc_length(
    ctx: &CaseCtx,
    st: &mut State,
    opts: &NonlinearOptions,
    name: &str,
    path: &mut Vec<PathPoint>,
    stab: &mut Stability,
) -> Result<(usize, usize, usize, f64), FemError> {
    let arms = ctx.arms(st);
    let f_red_full = ctx.to_independent(&arms, &ctx.f_ext);
    let f_red: Vec<f64> = ctx.map.eq_dof.iter().map(|&g| f_red_full[g]).collect();
    let mut lambda = 0.0;
    let (mut iterations, mut steps, mut cuts) = (0usize, 0usize, 0usize);
    let mut prev: Option<Vec<f64>> = None;
    let mut dl_arc = 0.0;
    let mut cut_run = 0;
    let max_steps = 50 * opts.steps.max(10);
    while steps < max_steps {
        let saved = st.clone();
        let ev = ctx
            .evaluate(st, lambda, ctx.newton_tangent())
            .ok_or_else(|| fail(name, steps + 1, lambda, f64::NAN, "degenerate configuration"))?;
        let scale = ev.internal.max(ev.load);
        let dt = ctx
            .solve(&ev.values, std::slice::from_ref(&f_red))
            .map_err(|r| fail(name, steps + 1, lambda, norm(&ev.r), r))?
            .x
            .remove(0);
        let dtn = norm(&dt);
        if !(dtn > 0.0 && dtn.is_finite()) {
            return Err(fail(name, steps + 1, lambda, norm(&ev.r), "no load to follow"));
        }
        if dl_arc == 0.0 {
            dl_arc = dtn / opts.steps as f64;
        }
        let sign = match &prev {
            Some(p) if dot(p, &dt) < 0.0 => -1.0,
            _ => 1.0,
        };
        let dlam = sign * dl_arc / dtn;
        if lambda + dlam >= 1.0 - 1e-12 {
            let (it, s, c, l) = load_control(ctx, st, lambda, &one_step(opts), name, path, steps, stab)?;
            return Ok((iterations + it, steps + s, cuts + c, l));
        }
        // Predictor.
        let mut dq: Vec<f64> = dt.iter().map(|v| v * dlam).collect();
        ctx.apply(st, &dq, None);
        let mut lam = lambda + dlam;
        let mut ok = None;
        let mut last_res = f64::NAN;
        let mut residuals = Vec::new();
        let mut pd = None;
        for it in 1..=opts.max_iterations {
            let Some(ev) = ctx.evaluate(st, lam, ctx.newton_tangent()) else {
                break;
            };
            let rn = norm(&ev.r);
            last_res = rn;
            residuals.push(rn);
            let scale = scale.max(ev.load);
            if rn <= bound(ctx, opts.tol_residual, scale) || scale == 0.0 && ev.internal == 0.0 {
                ok = Some(it);
                break;
            }
            let neg: Vec<f64> = ev.r.iter().map(|v| -v).collect();
            let Ok(sol) = ctx.solve(&ev.values, &[neg, f_red.clone()]) else {
                break;
            };
            pd = sol.positive_definite;
            let sol = sol.x;
            let (dr, dtt) = (&sol[0], &sol[1]);
            let s: Vec<f64> = dq.iter().zip(dr).map(|(a, b)| a + b).collect();
            let a = dot(dtt, dtt);
            let b = 2.0 * dot(dtt, &s);
            let c = dot(&s, &s) - dl_arc * dl_arc;
            let disc = b * b - 4.0 * a * c;
            if !(disc >= 0.0 && a > 0.0) {
                break;
            }
            let roots = [(-b + disc.sqrt()) / (2.0 * a), (-b - disc.sqrt()) / (2.0 * a)];
            let score = |x: f64| {
                dq.iter()
                    .zip(&s)
                    .zip(dtt)
                    .map(|((p, si), ti)| p * (si + x * ti))
                    .sum::<f64>()
            };
            let dlm = if score(roots[0]) >= score(roots[1]) {
                roots[0]
            } else {
                roots[1]
            };
            let corr: Vec<f64> = dr.iter().zip(dtt).map(|(r, t)| r + dlm * t).collect();
            ctx.apply(st, &corr, None);
            lam += dlm;
            for (d, c) in dq.iter_mut().zip(&corr) {
                *d += c;
            }
        }
        match ok {
            Some(it) => {
                iterations += it;
                steps += 1;
                let stable = match pd {
                    Some(p) => p,
                    None => ctx.positive_definite(st, lam),
                };
                stab.record(lambda, lam, stable);
                lambda = lam;
                cut_run = 0;
                prev = Some(dq);
                path.push(PathPoint {
                    lambda,
                    values: ctx.tracked(st, &opts.track),
                    stable,
                    residuals,
                });
                ctx.record_step(st, lambda, path.len() - 1)?;
            }
            None => {
                *st = saved;
                cuts += 1;
                cut_run += 1;
                dl_arc *= 0.5;
                if cut_run > opts.max_cuts || cuts > opts.max_total_cuts {
                    return Err(fail(
                        name,
                        steps + 1,
                        lambda,
                        last_res,
                        format!("arc length did not converge after {} cuts", opts.max_cuts),
                    ));
                }
            }
        }
    }
    Err(fail(name, steps, lambda, f64::NAN, "arc length: too many steps"))
}

pub(super) fn one_step(opts: &NonlinearOptions) -> NonlinearOptions {
    NonlinearOptions {
        steps: 1,
        ..opts.clone()
    }
}
