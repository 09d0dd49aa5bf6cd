//! Continuation of one load case along its equilibrium path: solves of the load case scaled by
//! other load factors λ, each started from the nearest converged state already on the path
//! (the unloaded state, a run's final state, earlier solves) instead of from the unloaded
//! state. The case's fixed data (DOF map, sparsity pattern, symbolic factorisation) are built
//! once for all of them.
//!
//! Each solve is load control from that state ([`super::path::load_control`]), every step
//! started from the linearised tangent predictor ([`super::path::Predictor::Linear`]: exact to
//! first order however far the prescribed values move, so a smooth stretch of the path is one
//! step of a few Newton iterations), with the same judgement of every step as a solve from
//! zero: a step is cut when Newton fails, when a node
//! rotates more than [`super::path::MAX_STEP_ROTATION`], when the increment jumps past
//! [`super::path::MAX_JUMP`] times its tangent predictor, or when an iteration crosses an
//! indefinite tangent; every accepted state is checked for equilibrium and stability. Only
//! stable states become starting points of later solves, so each answer is joined to the
//! unloaded state by a chain of judged, stable steps.

use super::load_case::{case_ctx, case_vectors};
use super::path::{load_control, Predictor, Stability};
use super::probe::Elements;
use super::recover::finish;
use super::state::{CaseCtx, State};
use super::{NonlinearCase, NonlinearOptions, PathPoint};
use crate::fem::analysis::prescribed_dofs;
use crate::fem::corot;
use crate::fem::error::FemError;
use crate::fem::model::Model;
use crate::fem::results::CaseResult;
use nalgebra::{Matrix3, Vector3};

/// Solves of one load case at load factors λ along its path (see the module docs).
pub struct Continuation<'a> {
    ctx: CaseCtx<'a>,
    opts: NonlinearOptions,
    name: String,
    /// Converged stable states on the path with their load factors, the unloaded one first.
    known: Vec<(f64, State)>,
}

impl<'a> Continuation<'a> {
    /// The continuation of load case `load_case` of `model` (`elems` from the same model):
    /// `opts` as for a solve from zero (the tangent, tolerances, step cuts; `steps`: see
    /// [`Self::solve_at`]). Starts with the unloaded state.
    pub fn new(
        model: &'a Model,
        elems: &'a Elements,
        load_case: usize,
        opts: &NonlinearOptions,
    ) -> Result<Continuation<'a>, FemError> {
        let case = model
            .load_cases
            .get(load_case)
            .ok_or_else(|| FemError::BadInput(format!("load case {load_case} does not exist")))?;
        model.validate_case(case)?;
        let nn = model.nodes.len();
        let (f_ext, u_c) = case_vectors(nn, case);
        let ctx = case_ctx(
            model,
            &elems.0,
            &prescribed_dofs(case),
            &case.name,
            f_ext,
            u_c,
            opts,
            &[],
        )?;
        let zero = State {
            u: vec![Vector3::zeros(); nn],
            r: vec![Matrix3::identity(); nn],
        };
        Ok(Continuation {
            ctx,
            opts: NonlinearOptions {
                locate_critical: false,
                ..opts.clone()
            },
            name: case.name.clone(),
            known: vec![(0.0, zero)],
        })
    }

    /// Adds the final state `c` of a solve of the same load case at load factor `lambda` (its
    /// displacements and rotation vectors, rad) as a starting point. The caller vouches that
    /// it is a converged state on the stable path (e.g. a run whose every step was stable).
    pub fn add_state(&mut self, c: &CaseResult, lambda: f64) {
        let mut st = State {
            u: c.displacements.iter().map(|d| Vector3::new(d[0], d[1], d[2])).collect(),
            r: c.displacements
                .iter()
                .map(|d| corot::rot_exp(&Vector3::new(d[3], d[4], d[5])))
                .collect(),
        };
        self.ctx.update_slaves(&mut st);
        self.known.push((lambda, st));
    }

    /// The load case scaled by `lambda`, solved from the known state with the nearest load
    /// factor by load control in steps of at most `max_step` (in λ; `None`: one step over the
    /// whole span; cut and grown back as a solve from zero does). Returns the solve (its path
    /// starts at the starting point) with `stable` false when a step lost stability; stable
    /// answers become starting points.
    pub fn solve_at(&mut self, lambda: f64, max_step: Option<f64>) -> Result<NonlinearCase, FemError> {
        let (lambda0, start) = self
            .known
            .iter()
            .min_by(|a, b| (a.0 - lambda).abs().total_cmp(&(b.0 - lambda).abs()))
            .map(|(l, s)| (*l, s.clone()))
            .ok_or_else(|| FemError::BadInput("continuation without a starting state".into()))?;
        let span = (lambda - lambda0).abs();
        let mut st = start;
        let mut path = vec![PathPoint {
            lambda: lambda0,
            values: self.ctx.tracked(&st, &self.opts.track),
            stable: true,
            residuals: Vec::new(),
            equilibrium: 0.0,
        }];
        let mut stab = Stability::default();
        let (iterations, steps, cuts, reached) = load_control(
            &self.ctx,
            &mut st,
            [lambda0, lambda],
            max_step.unwrap_or(span).min(span).max(1e-12 * lambda.abs().max(1.0)),
            &self.opts,
            &self.name,
            &mut path,
            0,
            &mut stab,
            Predictor::Linear,
        )?;
        let mut out = finish(&self.ctx, &st, &self.name, reached, path, iterations, steps, cuts)?;
        out.stable = stab.bracket.is_none();
        out.critical_load_factor = stab.bracket;
        if out.stable {
            self.known.push((reached, st));
        }
        Ok(out)
    }
}
