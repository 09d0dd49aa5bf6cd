//! Newton–Raphson iterations of one load step; the convergence test is
//! [`super::convergence::Convergence`].

use super::convergence::{Convergence, Iterate, Verdict};
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

/// A predictor the iterations start from: the equation increment already applied to the state
/// and its work on the linearised residual of the step (the reference of the energy test, as
/// the first correction's is without a predictor).
pub(super) struct Predicted<'a> {
    pub(super) dq: &'a [f64],
    pub(super) work: f64,
}

/// Newton iterations at fixed λ from the current state.
/// `converged_internal`: ‖f_int‖ (reactions included) of the last converged state.
/// `predicted`: the predictor the state was moved by; then [`NewtonOk::first`] is its norm and
/// [`NewtonOk::total`] that of the predictor plus the corrections.
pub(super) fn newton(
    ctx: &CaseCtx,
    st: &mut State,
    lambda: f64,
    opts: &NonlinearOptions,
    converged_internal: f64,
    predicted: Option<Predicted<'_>>,
) -> Result<NewtonOk, StepFail> {
    let mut test = Convergence::new(
        opts.tol_residual,
        opts.tol_energy,
        ctx.round,
        opts.max_iterations,
        converged_internal,
    );
    let mut last_dq: Option<Vec<f64>> = None;
    let mut acc = predicted
        .as_ref()
        .map_or_else(|| vec![0.0; ctx.n_eq()], |p| p.dq.to_vec());
    if let Some(p) = &predicted {
        test.first_correction(p.work);
    }
    let mut out = NewtonOk {
        iterations: 0,
        positive_definite: None,
        met_indefinite: false,
        first: predicted.as_ref().map_or(0.0, |p| norm(p.dq)),
        total: 0.0,
        residuals: Vec::new(),
        internal: 0.0,
    };
    let mode = ctx.newton_tangent();
    let degenerate = |residual: f64| StepFail {
        residual,
        reason: "degenerate element or non-finite internal force".into(),
    };
    for it in 0..=opts.max_iterations {
        // The residual first, keeping each element's linearisation: the tangent is formed
        // from it only when the iteration goes on (the converged state never assembles one,
        // and no iteration evaluates the element kinematics twice).
        let (ev, lins) = ctx.residual(st, lambda).ok_or_else(|| degenerate(f64::NAN))?;
        let rn = norm(&ev.r);
        out.residuals.push(rn);
        let iterate = Iterate::after(&ev.r, ev.load, ev.internal, last_dq.as_deref(), &acc);
        match test.check(&iterate) {
            Verdict::Converged => {
                return Ok(NewtonOk {
                    iterations: it,
                    total: norm(&acc),
                    internal: ev.internal,
                    ..out
                })
            }
            Verdict::NoConvergence => {
                return Err(StepFail {
                    residual: rn,
                    reason: format!("no convergence in {} iterations", opts.max_iterations),
                })
            }
            Verdict::Diverges => {
                return Err(StepFail {
                    residual: rn,
                    reason: "residual diverges".into(),
                })
            }
            Verdict::Continue => {}
        }
        let values = ctx.tangent_values(st, &ev, &lins, mode).ok_or_else(|| degenerate(rn))?;
        let neg: Vec<f64> = ev.r.iter().map(|v| -v).collect();
        let sol = ctx
            .solve(&values, &[neg])
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
        if it == 0 && predicted.is_none() {
            test.first_correction(dot(&dq, &ev.r).abs());
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
