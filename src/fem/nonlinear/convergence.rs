//! The convergence test of the Newton iterations of one load step, apart from the solver so
//! that each acceptance rule can be tested on hand-made iterates.

/// What the convergence test sees of one Newton iterate.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(super) struct Iterate {
    /// Residual norm ‖r‖ of the iterate.
    pub(super) residual: f64,
    /// Norm of the applied load at the step's λ.
    pub(super) load: f64,
    /// ‖f_int‖ of the iterate.
    pub(super) internal: f64,
    /// Of the last correction Δq (`None` before the first): its work |Δq·r| on the new
    /// residual, its norm ‖Δq‖, and the norm of the sum of all corrections of the step.
    pub(super) correction: Option<Correction>,
}

impl Iterate {
    /// The iterate of residual `r` (equations) after the correction `last` (`None` before the
    /// first) of a step whose corrections sum to `total`.
    pub(super) fn after(r: &[f64], load: f64, internal: f64, last: Option<&[f64]>, total: &[f64]) -> Iterate {
        use super::residual::{dot, norm};
        Iterate {
            residual: norm(r),
            load,
            internal,
            correction: last.map(|c| Correction {
                energy: dot(c, r).abs(),
                norm: norm(c),
                total: norm(total),
            }),
        }
    }
}

/// The last Newton correction as the convergence test sees it.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(super) struct Correction {
    /// |Δq·r|: work of the last correction on the new residual.
    pub(super) energy: f64,
    /// ‖Δq‖.
    pub(super) norm: f64,
    /// ‖Σ Δq‖ over the step.
    pub(super) total: f64,
}

/// Decision of the convergence test on one iterate.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(super) enum Verdict {
    /// Accept the iterate.
    Converged,
    /// Iterate again.
    Continue,
    /// The iteration budget is spent.
    NoConvergence,
    /// The residual grew beyond 10⁶ times its start (after the third iteration).
    Diverges,
}

/// Convergence test of the Newton iterations of one load step (Crisfield, *Non-linear Finite
/// Element Analysis of Solids and Structures*, Vol. 1, Wiley 1991, §3.5: force and energy norms).
/// An iterate is accepted when
/// 1. its residual is within `tol_force` of the step's force scale (plus the round-off floor)
///    and the work of the last correction on it is within `tol_energy` of the first
///    correction's (or the residual is 10⁻³ times tighter still); or
/// 2. the corrections have vanished (‖Δq‖ ≤ 10⁻¹⁰ ‖ΣΔq‖), the energy test holds and the
///    residual is within 10⁻⁷ of the force scale (mechanisms moving almost force-free); or
/// 3. the residual is within 10⁻⁷ of the force scale and no longer decreases: the energy test
///    holds and it fell by less than a factor 10 (after the second iteration), or it has not
///    halved its best value for three iterations (round-off floor).
///
/// The force scale is max(applied load, ‖f_int‖ of the last converged state), fixed at the first
/// iterate.
#[derive(Debug, Clone)]
pub(super) struct Convergence {
    /// Relative residual bound (of the force scale).
    pub(super) tol_force: f64,
    /// Relative bound of the correction's work (of the first correction's).
    pub(super) tol_energy: f64,
    /// Absolute round-off floor of the residual (N).
    pub(super) round: f64,
    /// Iterations allowed after the first evaluation.
    pub(super) max_iterations: usize,
    /// ‖f_int‖ of the last converged state (part of the force scale).
    converged_internal: f64,
    it: usize,
    scale: f64,
    r0: f64,
    e0: f64,
    r_prev: f64,
    best: f64,
    stall: usize,
}

impl Convergence {
    /// Test for a step starting from a state with internal-force norm `converged_internal`.
    pub(super) fn new(
        tol_force: f64,
        tol_energy: f64,
        round: f64,
        max_iterations: usize,
        converged_internal: f64,
    ) -> Convergence {
        Convergence {
            tol_force,
            tol_energy,
            round,
            max_iterations,
            converged_internal,
            it: 0,
            scale: 0.0,
            r0: f64::NAN,
            e0: 0.0,
            r_prev: f64::INFINITY,
            best: f64::INFINITY,
            stall: 0,
        }
    }

    /// Residual bound `tol` of the force scale plus the round-off floor.
    fn bound(&self, tol: f64) -> f64 {
        tol * self.scale + self.round
    }

    /// Records |Δq·r| of the first correction (the reference of the energy test).
    pub(super) fn first_correction(&mut self, energy: f64) {
        self.e0 = energy;
    }

    /// Judges the next iterate (the first call is iteration 0, before any correction).
    pub(super) fn check(&mut self, x: &Iterate) -> Verdict {
        let it = self.it;
        self.it += 1;
        let rn = x.residual;
        if it == 0 {
            self.r0 = rn;
            self.scale = x.load.max(self.converged_internal);
        }
        let unloaded = x.load == 0.0 && x.internal == 0.0;
        let force_ok = rn <= self.bound(self.tol_force) || unloaded;
        let energy_ok = match &x.correction {
            None => rn == 0.0 || unloaded,
            Some(c) => c.energy <= self.tol_energy * self.e0.max(f64::MIN_POSITIVE),
        };
        if force_ok && (energy_ok || rn <= self.bound(1e-3 * self.tol_force)) {
            return Verdict::Converged;
        }
        let disp_ok = x.correction.is_some_and(|c| c.norm <= 1e-10 * c.total);
        let near = rn <= self.bound(1e-7);
        if energy_ok && disp_ok && near {
            return Verdict::Converged;
        }
        if energy_ok && it > 1 && rn > 0.1 * self.r_prev && near {
            return Verdict::Converged;
        }
        if rn < 0.5 * self.best {
            self.best = rn;
            self.stall = 0;
        } else {
            self.stall += 1;
        }
        if self.stall >= 3 && near {
            return Verdict::Converged;
        }
        self.r_prev = rn;
        if it == self.max_iterations {
            return Verdict::NoConvergence;
        }
        if it > 2 && rn > 1e6 * self.r0.max(self.tol_force * self.scale) {
            return Verdict::Diverges;
        }
        Verdict::Continue
    }
}

#[cfg(test)]
mod tests {
    //! The acceptance rules stated on [`Convergence`], each checked on hand-made iterates.
    use super::*;

    const TOL: f64 = 1e-8;

    fn test(max_iterations: usize) -> Convergence {
        // Force scale 100 N, no round-off floor: the force bound is 1e-6 N.
        Convergence::new(TOL, 1e-12, 0.0, max_iterations, 100.0)
    }

    fn iterate(residual: f64, correction: Option<Correction>) -> Iterate {
        Iterate {
            residual,
            load: 50.0,
            internal: 80.0,
            correction,
        }
    }

    fn corr(energy: f64, norm: f64, total: f64) -> Option<Correction> {
        Some(Correction { energy, norm, total })
    }

    #[test]
    fn initial_iterate_in_equilibrium_needs_a_zero_residual() {
        // Before any correction the energy test holds only for r = 0, so a residual inside the
        // force bound (1e-6 N) but above 10⁻³ of it is iterated on; r = 0 is accepted.
        assert_eq!(test(10).check(&iterate(5e-7, None)), Verdict::Continue);
        assert_eq!(test(10).check(&iterate(0.0, None)), Verdict::Converged);
        // A residual 10⁻³ times tighter than the force bound (1e-9 N) is accepted on its own.
        assert_eq!(test(10).check(&iterate(5e-10, None)), Verdict::Converged);
    }

    #[test]
    fn unloaded_structure_converges_at_once() {
        // No load and no internal force: nothing to balance.
        let mut c = Convergence::new(TOL, 1e-12, 0.0, 10, 0.0);
        let x = Iterate {
            residual: 1.0,
            load: 0.0,
            internal: 0.0,
            correction: None,
        };
        assert_eq!(c.check(&x), Verdict::Converged);
    }

    #[test]
    fn force_and_energy_tests_must_both_hold() {
        let mut c = test(10);
        assert_eq!(c.check(&iterate(1.0, None)), Verdict::Continue);
        c.first_correction(1.0);
        // Residual inside the force bound, correction work 1e-11 > 1e-12·e0: iterate again.
        assert_eq!(c.check(&iterate(5e-7, corr(1e-11, 1.0, 1.0))), Verdict::Continue);
        // Both inside: accept.
        assert_eq!(c.check(&iterate(5e-7, corr(1e-13, 1e-3, 1.0))), Verdict::Converged);
    }

    #[test]
    fn energy_alone_does_not_accept_a_large_residual() {
        let mut c = test(10);
        assert_eq!(c.check(&iterate(1.0, None)), Verdict::Continue);
        c.first_correction(1.0);
        // Work negligible but residual 1e-2 N ≫ 1e-5 N (the 10⁻⁷ bound): continue.
        assert_eq!(c.check(&iterate(1e-2, corr(0.0, 1.0, 1.0))), Verdict::Continue);
    }

    #[test]
    fn vanished_corrections_accept_within_the_loose_bound() {
        let mut c = test(10);
        assert_eq!(c.check(&iterate(1.0, None)), Verdict::Continue);
        c.first_correction(1.0);
        // Residual 5e-6 N: outside the force bound (1e-6) but inside 1e-7·100 = 1e-5; the
        // correction is 1e-11 of the accumulated one and does no work: accept.
        assert_eq!(c.check(&iterate(5e-6, corr(0.0, 1e-11, 1.0))), Verdict::Converged);
        // The same with a correction of 1e-9 of the accumulated one: continue.
        let mut c = test(10);
        c.check(&iterate(1.0, None));
        c.first_correction(1.0);
        assert_eq!(c.check(&iterate(5e-6, corr(0.0, 1e-9, 1.0))), Verdict::Continue);
    }

    #[test]
    fn stalled_residual_is_accepted_at_the_round_off_floor() {
        // From the third iteration, a residual that fell by less than 10× with negligible
        // correction work is accepted when within the 1e-5 N bound.
        let mut c = test(10);
        c.check(&iterate(1.0, None));
        c.first_correction(1.0);
        assert_eq!(c.check(&iterate(8e-6, corr(1.0, 1.0, 1.0))), Verdict::Continue);
        assert_eq!(c.check(&iterate(7e-6, corr(0.0, 1.0, 1.0))), Verdict::Converged);
    }

    #[test]
    fn residual_that_stops_halving_for_three_iterations_is_accepted_when_near() {
        let mut c = test(20);
        c.check(&iterate(1.0, None));
        c.first_correction(1.0);
        // Work stays large, so only the stall rule can accept: best = 9e-6 at iteration 1,
        // then three iterations without halving it.
        let mut verdicts = Vec::new();
        for _ in 0..4 {
            verdicts.push(c.check(&iterate(9e-6, corr(1.0, 1.0, 1.0))));
        }
        assert_eq!(
            verdicts,
            [
                Verdict::Continue,
                Verdict::Continue,
                Verdict::Continue,
                Verdict::Converged
            ]
        );
    }

    #[test]
    fn budget_is_spent_after_max_iterations() {
        // A residual falling from 1 N by 0.4 per iteration stays far outside every bound; the
        // last allowed iteration (index max_iterations = 3) reports no convergence.
        let mut c = test(3);
        c.check(&iterate(1.0, None));
        c.first_correction(1.0);
        let v: Vec<Verdict> = [0.4, 0.16, 0.064]
            .iter()
            .map(|&r| c.check(&iterate(r, corr(1.0, 1.0, 1.0))))
            .collect();
        assert_eq!(v, [Verdict::Continue, Verdict::Continue, Verdict::NoConvergence]);
    }

    #[test]
    fn divergence_is_reported_after_the_third_iteration() {
        // r0 = 1 N: a residual above 1e6·r0 is divergence only from iteration 3 on.
        let mut c = test(30);
        c.check(&iterate(1.0, None));
        c.first_correction(1.0);
        assert_eq!(c.check(&iterate(2e6, corr(1.0, 1.0, 1.0))), Verdict::Continue);
        assert_eq!(c.check(&iterate(2e6, corr(1.0, 1.0, 1.0))), Verdict::Continue);
        assert_eq!(c.check(&iterate(2e6, corr(1.0, 1.0, 1.0))), Verdict::Diverges);
    }

    #[test]
    fn round_off_floor_widens_every_bound() {
        // With a floor of 1e-3 N a residual of 5e-4 N passes the force test (1e-6 + 1e-3)
        // and, 10⁻³-tighter bound included (1e-9 + 1e-3), is accepted before any correction.
        let mut c = Convergence::new(TOL, 1e-12, 1e-3, 10, 100.0);
        assert_eq!(c.check(&iterate(5e-4, None)), Verdict::Converged);
    }
}
