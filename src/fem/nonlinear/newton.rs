//! Newton–Raphson iterations of one load step, with the convergence test.

use super::residual::{dot, norm};
use super::state::{CaseCtx, State};
use super::NonlinearOptions;

/// Outcome of a failed step (for the error message).
pub(super) struct StepFail {
    pub(super) residual: f64,
    pub(super) reason: String,
}

/// A converged Newton step.
pub(super) struct NewtonOk {
    pub(super) iterations: usize,
    /// Definiteness of the last factorised tangent after the first correction (a state within
    /// one quadratically converging correction of the converged one); `None` when unknown
    /// (full LU, or converged after one correction).
    pub(super) positive_definite: Option<bool>,
    /// Whether some iteration met an indefinite symmetric tangent.
    pub(super) met_indefinite: bool,
    /// Norm of the first correction (the tangent predictor of the step) and of the sum of all.
    pub(super) first: f64,
    pub(super) total: f64,
    /// Residual norm per iteration.
    pub(super) residuals: Vec<f64>,
    /// ‖f_int‖ at the converged state.
    pub(super) internal: f64,
}

/// Acceptance bound of a Newton iteration: `tol` relative to the step's force scale (the
/// applied load at the step's λ and the internal forces — reactions — of the last converged
/// state), plus the model's round-off floor [`CaseCtx::round`].
pub(super) fn bound(ctx: &CaseCtx, tol: f64, scale: f64) -> f64 {
    tol * scale + ctx.round
}

/// Newton iterations at fixed λ from the current state.
/// `converged_internal`: ‖f_int‖ (reactions included) of the last converged state.
pub(super) fn newton(
    ctx: &CaseCtx,
    st: &mut State,
    lambda: f64,
    opts: &NonlinearOptions,
    converged_internal: f64,
) -> Result<NewtonOk, StepFail> {
    let mut e0: f64 = 0.0;
    let mut last_dq: Option<Vec<f64>> = None;
    let mut r0 = f64::NAN;
    let mut scale = 0.0;
    let mut r_prev = f64::INFINITY;
    let (mut best, mut stall) = (f64::INFINITY, 0);
    let mut acc = vec![0.0; ctx.n_eq()];
    let mut out = NewtonOk {
        iterations: 0,
        positive_definite: None,
        met_indefinite: false,
        first: 0.0,
        total: 0.0,
        residuals: Vec::new(),
        internal: 0.0,
    };
    let mode = ctx.newton_tangent();
    for it in 0..=opts.max_iterations {
        let ev = ctx.evaluate(st, lambda, mode).ok_or_else(|| StepFail {
            residual: f64::NAN,
            reason: "degenerate element or non-finite internal force".into(),
        })?;
        let rn = norm(&ev.r);
        out.residuals.push(rn);
        if it == 0 {
            r0 = rn;
            scale = ev.load.max(converged_internal);
        }
        let done = |out: NewtonOk| {
            Ok(NewtonOk {
                iterations: it,
                total: norm(&acc),
                internal: ev.internal,
                ..out
            })
        };
        let force_ok = rn <= bound(ctx, opts.tol_residual, scale) || ev.load == 0.0 && ev.internal == 0.0;
        let energy_ok = match &last_dq {
            None => rn == 0.0 || ev.load == 0.0 && ev.internal == 0.0,
            Some(dq) => dot(dq, &ev.r).abs() <= opts.tol_energy * e0.max(f64::MIN_POSITIVE),
        };
        if force_ok && (energy_ok || rn <= bound(ctx, 1e-3 * opts.tol_residual, scale)) {
            return done(out);
        }
        // Displacement + energy: for mechanisms moving almost force-free (ideal joints), the
        // force scale is itself round-off, so converge on the corrections instead — but never
        // above the final equilibrium bound.
        let disp_ok = last_dq.as_ref().is_some_and(|dq| norm(dq) <= 1e-10 * norm(&acc));
        let near = rn <= bound(ctx, 1e-7, scale);
        if energy_ok && disp_ok && near {
            return done(out);
        }
        // Round-off floor: accept when the correction's energy is negligible and the residual
        // no longer decreases, if it is within the final equilibrium bound.
        if energy_ok && it > 1 && rn > 0.1 * r_prev && near {
            return done(out);
        }
        if rn < 0.5 * best {
            best = rn;
            stall = 0;
        } else {
            stall += 1;
        }
        if stall >= 3 && near {
            return done(out);
        }
        r_prev = rn;
        if it == opts.max_iterations {
            return Err(StepFail {
                residual: rn,
                reason: format!("no convergence in {} iterations", opts.max_iterations),
            });
        }
        if it > 2 && rn > 1e6 * r0.max(opts.tol_residual * scale) {
            return Err(StepFail {
                residual: rn,
                reason: "residual diverges".into(),
            });
        }
        let neg: Vec<f64> = ev.r.iter().map(|v| -v).collect();
        let sol = ctx
            .solve(&ev.values, &[neg])
            .map_err(|reason| StepFail { residual: rn, reason })?;
        // The tangent of iteration 0 belongs to the previous converged state: it says nothing
        // about the new one.
        if it > 0 {
            out.positive_definite = sol.positive_definite;
        }
        out.met_indefinite |= it > 0 && sol.positive_definite == Some(false);
        let dq = sol.x.into_iter().next().unwrap_or_default();
        if dq.iter().any(|v| !v.is_finite()) {
            return Err(StepFail {
                residual: rn,
                reason: "non-finite correction".into(),
            });
        }
        if it == 0 {
            e0 = dot(&dq, &ev.r).abs();
            out.first = norm(&dq);
        }
        ctx.apply(st, &dq, None);
        for (a, d) in acc.iter_mut().zip(&dq) {
            *a += d;
        }
        last_dq = Some(dq);
    }
    Err(StepFail {
        residual: f64::NAN,
        reason: "no convergence".into(),
    })
}
