//! Evaluations at a given configuration of one load case, for derivatives of a converged
//! nonlinear state (the direct and adjoint methods of design sensitivity): the reduced residual
//! r = f_int(u) − λ f, the consistent tangent K_T = ∂r/∂q and solves with it, moves of the
//! configuration by equation increments q (translations, spatial spins) and by the prescribed
//! values, and element results.
//!
//! A [`Configuration`] holds the independent nodes' translations and rotation matrices; a
//! [`Probe`] of another model with the same topology (the same case at other parameter values)
//! re-derives the rigid-link slaves from them ([`Probe::rebase`]), so a residual of the other
//! model at the same configuration is the residual "at fixed displacements".

use super::load_case::{case_ctx, case_vectors};
use super::residual::norm;
use super::state::{element_data, Assemble, CaseCtx, ElemData, State};
use super::{NonlinearCase, NonlinearOptions, Tangent};
use crate::fem::analysis::prescribed_dofs;
use crate::fem::corot;
use crate::fem::error::FemError;
use crate::fem::model::Model;
use crate::fem::recovery;
use crate::fem::results::ElementResult;
use nalgebra::{Matrix3, Vector3};

/// The element data of a model for the nonlinear solver (co-rotational geometry and local
/// stiffness of each beam and flexibility element, springs).
#[derive(Debug, Clone)]
pub struct Elements(pub(super) Vec<ElemData>);

impl Elements {
    /// The element data of `model` (fails for shells and superelement pieces).
    pub fn new(model: &Model) -> Result<Elements, FemError> {
        element_data(model).map(Elements)
    }
}

/// Nodal translations (mm, global) and rotation matrices of a configuration.
#[derive(Debug, Clone)]
pub struct Configuration(State);

impl Configuration {
    /// The final state of a nonlinear solve.
    pub fn from_case(c: &NonlinearCase) -> Configuration {
        Configuration(State {
            u: c.fe
                .displacements
                .iter()
                .map(|d| Vector3::new(d[0], d[1], d[2]))
                .collect(),
            r: c.rotations.iter().map(|r| Matrix3::from_fn(|i, j| r[i][j])).collect(),
        })
    }
}

/// Evaluations at configurations of load case `load_case` of a model (see the module docs).
pub struct Probe<'a> {
    ctx: CaseCtx<'a>,
    name: String,
}

impl<'a> Probe<'a> {
    /// The probe of load case `load_case` of `model` (`elems` from the same model). The tangent
    /// is always the consistent non-symmetric one (sparse LU), exact also where moments act.
    pub fn new(model: &'a Model, elems: &'a Elements, load_case: usize) -> Result<Probe<'a>, FemError> {
        let case = model
            .load_cases
            .get(load_case)
            .ok_or_else(|| FemError::BadInput(format!("load case {load_case} does not exist")))?;
        model.validate_case(case)?;
        let (f_ext, u_c) = case_vectors(model.nodes.len(), case);
        let opts = NonlinearOptions {
            tangent: Tangent::Full,
            ..Default::default()
        };
        let ctx = case_ctx(
            model,
            &elems.0,
            &prescribed_dofs(case),
            &case.name,
            f_ext,
            u_c,
            &opts,
            &[],
        )?;
        Ok(Probe {
            ctx,
            name: case.name.clone(),
        })
    }

    /// Number of equations (the length of residuals and increments).
    pub fn n_eq(&self) -> usize {
        self.ctx.n_eq()
    }

    /// `cfg` with every rigid-link slave placed by this model's arms (independent nodes kept).
    pub fn rebase(&self, cfg: &Configuration) -> Configuration {
        let mut st = cfg.0.clone();
        self.ctx.update_slaves(&mut st);
        Configuration(st)
    }

    /// Reduced residual r = f_int − λ f on the equations (N, N·mm).
    pub fn residual(&self, cfg: &Configuration, lambda: f64) -> Result<Vec<f64>, FemError> {
        self.ctx
            .residual(&cfg.0, lambda)
            .map(|(ev, _)| ev.r)
            .ok_or_else(|| self.degenerate(lambda))
    }

    /// Solves K_T x = b for each right-hand side `rhs` with the consistent tangent at `cfg`.
    pub fn tangent_solve(&self, cfg: &Configuration, lambda: f64, rhs: &[Vec<f64>]) -> Result<Vec<Vec<f64>>, FemError> {
        let ev = self
            .ctx
            .evaluate(&cfg.0, lambda, Assemble::Full)
            .ok_or_else(|| self.degenerate(lambda))?;
        self.ctx
            .solve(&ev.values, rhs)
            .map(|s| s.x)
            .map_err(|e| self.fail(lambda, e))
    }

    /// `cfg` moved by the equation increments `q` (translations mm, spatial spins rad; node
    /// frames as the equations) and the prescribed DOFs by `dlambda` times their values.
    pub fn moved(&self, cfg: &Configuration, q: &[f64], dlambda: f64) -> Configuration {
        let mut st = cfg.0.clone();
        let dc: Vec<f64> = self.ctx.u_c.iter().map(|v| v * dlambda).collect();
        self.ctx.apply(&mut st, q, Some(&dc));
        Configuration(st)
    }

    /// Newton iterations with the consistent tangent at fixed λ, until the residual stops
    /// falling (at most `iterations`): tightens a converged state to round-off. Returns the
    /// last residual norm relative to the internal forces (N over N).
    pub fn polish(&self, cfg: &mut Configuration, lambda: f64, iterations: usize) -> Result<f64, FemError> {
        let scale = |ev: &super::state::Eval| ev.internal.max(ev.load).max(f64::MIN_POSITIVE);
        let mut ev = self
            .ctx
            .evaluate(&cfg.0, lambda, Assemble::Full)
            .ok_or_else(|| self.degenerate(lambda))?;
        let mut rel = norm(&ev.r) / scale(&ev);
        for _ in 0..iterations {
            let mut q = self
                .ctx
                .solve(&ev.values, std::slice::from_ref(&ev.r))
                .map_err(|e| self.fail(lambda, e))?
                .x
                .remove(0);
            q.iter_mut().for_each(|v| *v = -*v);
            let mut st = cfg.0.clone();
            self.ctx.apply(&mut st, &q, None);
            let Some(next) = self.ctx.evaluate(&st, lambda, Assemble::Full) else {
                break;
            };
            let r = norm(&next.r) / scale(&next);
            if r >= rel {
                break;
            }
            (cfg.0, ev, rel) = (st, next, r);
        }
        Ok(rel)
    }

    /// Value of DOF `dof` (0..6: ux, uy, uz mm; rotation-vector components rad, global) of
    /// node `node` at `cfg`.
    pub fn node_value(cfg: &Configuration, node: usize, dof: usize) -> f64 {
        if dof < 3 {
            cfg.0.u[node][dof]
        } else {
            corot::rot_log(&cfg.0.r[node])[dof - 3]
        }
    }

    /// The reduced load vector of a unit force (N) or moment (N·mm) along global DOF `dof` of
    /// node `node` (zero when that DOF is held).
    pub fn unit_load(&self, cfg: &Configuration, node: usize, dof: usize) -> Vec<f64> {
        let mut v = vec![0.0; 6 * self.ctx.model.nodes.len()];
        v[6 * node + dof] = 1.0;
        let full = self.ctx.to_independent(&self.ctx.arms(&cfg.0), &v);
        self.ctx.map.eq_dof.iter().map(|&g| full[g]).collect()
    }

    /// Result of element `ie` at `cfg`: end and section forces in its co-rotated frame and
    /// stresses, as the nonlinear solve reports them (`None` for springs and degenerate
    /// elements).
    pub fn element_result(&self, cfg: &Configuration, ie: usize) -> Option<ElementResult> {
        match self.ctx.elems.get(ie)? {
            ElemData::Corot { .. } => {
                let (_, r) = self.ctx.corot_response(&cfg.0, ie, false)?;
                Some(recovery::from_local_end_forces(
                    &self.ctx.model.elements[ie],
                    r.f_local.as_slice(),
                    0.5 * r.d_local.dot(&r.f_local),
                ))
            }
            ElemData::Spring { .. } => None,
        }
    }

    /// Largest |translation| (mm) and |rotation vector| (rad) over the nodes of `cfg` (scales
    /// for finite-difference steps).
    pub fn motion_scale(cfg: &Configuration) -> (f64, f64) {
        let t = cfg.0.u.iter().map(|u| u.norm()).fold(0.0, f64::max);
        let r = cfg.0.r.iter().map(|r| corot::rot_log(r).norm()).fold(0.0, f64::max);
        (t, r)
    }

    fn degenerate(&self, lambda: f64) -> FemError {
        self.fail(lambda, "an element is degenerate at this configuration")
    }

    fn fail(&self, lambda: f64, reason: impl Into<String>) -> FemError {
        FemError::NonConvergence {
            case: self.name.clone(),
            step: 0,
            lambda,
            residual: f64::NAN,
            reason: reason.into(),
        }
    }
}
