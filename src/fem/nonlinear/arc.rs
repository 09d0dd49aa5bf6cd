//! Crisfield's arc-length continuation (M. A. Crisfield, "A fast incremental/iterative solution
//! procedure that handles snap-through", Computers & Structures 13 (1981) 55–62; after E. Riks,
//! "An incremental approach to the solution of snapping and buckling problems", IJSS 15 (1979)
//! 529–551), cylindrical (ψ = 0) or spherical (ψ = 1).
//!
//! Each step of arc length Δs finds the increments (Δq, Δλ) from the last converged point with
//! ‖Δq‖²/q_ref² + ψ²Δλ² = Δs², q_ref = ‖K₀⁻¹f‖ the linear response to the full load (so Δs is
//! dimensionless: Δs = 0.05 is 5 % of that response). Predictor along the tangent K⁻¹f, its
//! sense continuing the previous increment (a positive product with it); corrector: Newton
//! iterations on the residual and the constraint, whose quadratic's root is the one closest in
//! angle to the increment so far (Crisfield's rule); complex roots cut the step. A converged
//! increment that turns back (negative product with the previous one) or rotates a node by more
//! than [`MAX_STEP_ROTATION`] is cut too, so the path never reverses onto itself. Every step is
//! accepted by the convergence test of the load steps ([`Convergence`]: force and energy
//! norms); Δs adapts to the iterations taken (×√(target/iterations), between ×½ and ×2,
//! within [min, max]). The path ends where λ first reaches 1: the last piece is load controlled.

use super::convergence::{Convergence, Iterate, Verdict};
use super::path::{load_control, max_rotation_change, one_step, Predictor, Stability, MAX_STEP_ROTATION};
use super::residual::{dot, norm};
use super::state::{fail, CaseCtx, State};
use super::{ArcLength, NonlinearOptions, PathPoint};
use crate::fem::error::FemError;

/// A converged arc-length step.
struct ArcStep {
    dq: Vec<f64>,
    dlam: f64,
    /// Sign of the predictor's Δλ: the sense of λ along the path at the step's start.
    sense: f64,
    iterations: usize,
    residuals: Vec<f64>,
    positive_definite: Option<bool>,
    internal: f64,
}

/// The arc metric: ‖a‖²/q_ref² + ψ² products of the load parts.
struct Metric {
    q2: f64,
    psi2: f64,
}

impl Metric {
    fn dot(&self, a: &[f64], la: f64, b: &[f64], lb: f64) -> f64 {
        dot(a, b) / self.q2 + self.psi2 * la * lb
    }
}

/// Arc-length continuation from λ = 0 until λ reaches 1. Returns (iterations, steps, cuts, λ).
pub(super) fn arc_length(
    ctx: &CaseCtx,
    st: &mut State,
    opts: &NonlinearOptions,
    name: &str,
    path: &mut Vec<PathPoint>,
    stab: &mut Stability,
) -> Result<(usize, usize, usize, f64), FemError> {
    let a = opts.arc.resolved(opts.steps);
    if !(a.min <= a.initial && a.initial <= a.max) {
        return Err(fail(
            name,
            1,
            0.0,
            f64::NAN,
            format!(
                "arc length: the bounds are inconsistent (min {:e} ≤ initial {:e} ≤ max {:e} is needed)",
                a.min, a.initial, a.max
            ),
        ));
    }
    if ctx.n_eq() == 0 {
        return Err(fail(
            name,
            1,
            0.0,
            0.0,
            "arc length: the model has no free degree of freedom (every DOF is supported, prescribed or tied): there is no path to follow; use load control",
        ));
    }
    let f_red = ctx.reduced_load(st);
    let ev0 = ctx
        .evaluate(st, 0.0, ctx.newton_tangent())
        .ok_or_else(|| fail(name, 1, 0.0, f64::NAN, "degenerate configuration"))?;
    let t0 = ctx
        .solve(&ev0.values, std::slice::from_ref(&f_red))
        .map_err(|r| fail(name, 1, 0.0, norm(&ev0.r), r))?
        .x
        .into_iter()
        .next()
        .ok_or_else(|| {
            fail(
                name,
                1,
                0.0,
                norm(&ev0.r),
                "arc length: the tangent solve returned no solution",
            )
        })?;
    let qref = norm(&t0);
    if !(qref > 0.0 && qref.is_finite()) {
        return Err(fail(name, 1, 0.0, norm(&ev0.r), "arc length: no load to follow"));
    }
    let m = Metric {
        q2: qref * qref,
        psi2: if a.spherical { 1.0 } else { 0.0 },
    };
    let mut ds = a.initial;
    let mut lambda = 0.0;
    let mut internal = ev0.internal;
    let mut prev: Option<(Vec<f64>, f64)> = None;
    let (mut iterations, mut steps, mut cuts, mut cut_run) = (0usize, 0usize, 0usize, 0usize);
    while steps < a.max_steps {
        let saved = st.clone();
        let outcome = arc_step(ctx, st, lambda, ds, &m, &f_red, prev.as_ref(), opts, internal).and_then(|s| {
            let back = prev
                .as_ref()
                .is_some_and(|(pq, pl)| m.dot(pq, *pl, &s.dq, s.dlam) < 0.0);
            let rot = max_rotation_change(&saved, st);
            if back {
                Err("the increment turns back along the path".to_string())
            } else if rot > MAX_STEP_ROTATION {
                Err(format!("a node rotates {rot:.3} rad in one step"))
            } else {
                Ok(s)
            }
        });
        match outcome {
            Ok(s) if lambda + s.dlam >= 1.0 => {
                // λ = 1 lies on this step: reach it by load control from the last point.
                *st = saved;
                let (it, n, c, l) = load_control(
                    ctx,
                    st,
                    [lambda, 1.0],
                    1.0,
                    &one_step(opts),
                    name,
                    path,
                    steps,
                    stab,
                    Predictor::Moved,
                )?;
                return Ok((iterations + s.iterations + it, steps + n, cuts + c, l));
            }
            Ok(s) => {
                let stable = match s.positive_definite {
                    Some(p) => p,
                    None => ctx.positive_definite(st, lambda + s.dlam),
                };
                stab.record(&saved, st, lambda, lambda + s.dlam, stable, s.sense, Some(&s.dq));
                lambda += s.dlam;
                iterations += s.iterations;
                steps += 1;
                cut_run = 0;
                internal = s.internal;
                ctx.accept_point(path, st, lambda, stable, s.residuals, &opts.track, name)?;
                let grow = (a.target_iterations as f64 / s.iterations.max(1) as f64).sqrt();
                ds = (ds * grow.clamp(0.5, 2.0)).clamp(a.min, a.max);
                prev = Some((s.dq, s.dlam));
            }
            Err(reason) => {
                *st = saved;
                cuts += 1;
                cut_run += 1;
                ds *= 0.5;
                if ds < a.min || cut_run > opts.max_cuts || cuts > opts.max_total_cuts {
                    return Err(fail(
                        name,
                        steps + 1,
                        lambda,
                        f64::NAN,
                        format!(
                            "arc length: {reason}; {cuts} cuts ({cut_run} in a row), arc length down to {:.3e} (min {:.3e})",
                            2.0 * ds,
                            a.min
                        ),
                    ));
                }
            }
        }
    }
    Err(fail(
        name,
        steps,
        lambda,
        f64::NAN,
        format!(
            "arc length: λ = 1 not reached in {} steps (max_steps; the path ended at λ = {lambda:.6})",
            a.max_steps
        ),
    ))
}

/// One arc-length step of length `ds` from the converged state `st` at `lambda`; on failure the
/// state is left modified (the caller restores it).
#[allow(clippy::too_many_arguments)]
fn arc_step(
    ctx: &CaseCtx,
    st: &mut State,
    lambda: f64,
    ds: f64,
    m: &Metric,
    f_red: &[f64],
    prev: Option<&(Vec<f64>, f64)>,
    opts: &NonlinearOptions,
    internal: f64,
) -> Result<ArcStep, String> {
    let ev = ctx
        .evaluate(st, lambda, ctx.newton_tangent())
        .ok_or("degenerate configuration")?;
    let dt = ctx
        .solve(&ev.values, &[f_red.to_vec()])?
        .x
        .into_iter()
        .next()
        .ok_or("the tangent solve returned no solution")?;
    let tn = m.dot(&dt, 1.0, &dt, 1.0).sqrt();
    if !(tn > 0.0 && tn.is_finite()) {
        return Err("the tangent is singular".into());
    }
    let sense = match prev {
        Some((pq, pl)) if m.dot(pq, *pl, &dt, 1.0) < 0.0 => -1.0,
        _ => 1.0,
    };
    let mut dlam = sense * ds / tn;
    let mut dq: Vec<f64> = dt.iter().map(|v| v * dlam).collect();
    ctx.apply(st, &dq, None);
    let mut test = Convergence::new(
        opts.tol_residual,
        opts.tol_energy,
        ctx.round,
        opts.max_iterations,
        internal,
    );
    let mut last: Option<Vec<f64>> = None;
    let mut residuals = Vec::new();
    let mut pd = None;
    for it in 0..=opts.max_iterations {
        let lam = lambda + dlam;
        let ev = ctx
            .evaluate(st, lam, ctx.newton_tangent())
            .ok_or("degenerate element")?;
        let rn = norm(&ev.r);
        residuals.push(rn);
        let iterate = Iterate::after(&ev.r, ev.load, ev.internal, last.as_deref(), &dq);
        match test.check(&iterate) {
            Verdict::Converged => {
                return Ok(ArcStep {
                    dq,
                    dlam,
                    sense,
                    iterations: it,
                    residuals,
                    positive_definite: pd,
                    internal: ev.internal,
                })
            }
            Verdict::NoConvergence => return Err(format!("no convergence in {} iterations", opts.max_iterations)),
            Verdict::Diverges => return Err("residual diverges".into()),
            Verdict::Continue => {}
        }
        let neg: Vec<f64> = ev.r.iter().map(|v| -v).collect();
        let sol = ctx.solve(&ev.values, &[neg, f_red.to_vec()])?;
        if it > 0 {
            pd = sol.positive_definite;
        }
        let (dr, dtt) = (&sol.x[0], &sol.x[1]);
        // ‖s + x·δt‖² + ψ²(Δλ + x)² = Δs² with s = Δq + δr.
        let s: Vec<f64> = dq.iter().zip(dr).map(|(a, b)| a + b).collect();
        let qa = m.dot(dtt, 1.0, dtt, 1.0);
        let qb = 2.0 * m.dot(dtt, 1.0, &s, dlam);
        let qc = m.dot(&s, dlam, &s, dlam) - ds * ds;
        let disc = qb * qb - 4.0 * qa * qc;
        if !(disc >= 0.0 && qa > 0.0 && disc.is_finite()) {
            return Err("the constraint has no real root (complex roots)".into());
        }
        // Crisfield's rule: the root whose increment is closest in angle to the one so far.
        let x = [(-qb + disc.sqrt()) / (2.0 * qa), (-qb - disc.sqrt()) / (2.0 * qa)]
            .into_iter()
            .map(|x| {
                let nq: Vec<f64> = s.iter().zip(dtt).map(|(si, ti)| si + x * ti).collect();
                (m.dot(&dq, dlam, &nq, dlam + x), x)
            })
            .fold((f64::NEG_INFINITY, 0.0), |a, b| if b.0 > a.0 { b } else { a })
            .1;
        let corr: Vec<f64> = dr.iter().zip(dtt).map(|(r, t)| r + x * t).collect();
        if corr.iter().any(|v| !v.is_finite()) {
            return Err("non-finite correction".into());
        }
        if it == 0 {
            test.first_correction(dot(&corr, &ev.r).abs());
        }
        ctx.apply(st, &corr, None);
        dlam += x;
        for (d, c) in dq.iter_mut().zip(&corr) {
            *d += c;
        }
        last = Some(corr);
    }
    Err("no convergence".into())
}

impl ArcLength {
    /// The arc lengths `[initial, min, max]` with defaults filled in for `steps` nominal load
    /// steps (dimensionless, as [`ArcLength`]); the solve needs min ≤ initial ≤ max.
    pub fn bounds(&self, steps: usize) -> [f64; 3] {
        let initial = self.initial.unwrap_or(1.0 / steps.max(1) as f64);
        [
            initial,
            self.min.unwrap_or(initial * 1e-4),
            self.max.unwrap_or(initial * 20.0).max(initial),
        ]
    }

    /// The parameters with defaults filled in for `steps` nominal load steps.
    pub(super) fn resolved(&self, steps: usize) -> ResolvedArc {
        let [initial, min, max] = self.bounds(steps);
        ResolvedArc {
            initial,
            min,
            max,
            target_iterations: self.target_iterations,
            spherical: self.spherical,
            max_steps: self.max_steps,
        }
    }
}

/// [`ArcLength`] with its defaults resolved.
pub(super) struct ResolvedArc {
    initial: f64,
    min: f64,
    max: f64,
    target_iterations: usize,
    spherical: bool,
    max_steps: usize,
}
