//! Quantities along the path (opt-in, [`StepTrack`]): at every accepted point, the lowest
//! natural frequencies of the *current* state and the 6×6 compliance of chosen nodes.
//!
//! Both use the symmetric part of the consistent co-rotational tangent at the converged state
//! — the material stiffness in the deformed element frames plus the geometric stiffness of
//! the current element forces and of the rigid links' rotating arms — reduced with the
//! constraints of the load case (supports, and the DOFs it prescribes, which stay held: a
//! stroke imposed by an ideal actuator). The mass matrix is the undeformed one rotated with
//! each element's co-rotated frame (beams: consistent mass in the element axes; point masses:
//! rotary inertia R·I·Rᵀ with the node's rotation), carried to the independent nodes with the
//! current rigid-link arms. The eigenproblem K_T φ = ω² M φ is solved by the shift-invert
//! Lanczos of [`crate::fem::modal`]; an unstable state (K_T indefinite) has negative ω².

use super::residual::for_each_pair_in;
use super::state::{CaseCtx, ElemData, State, Tracker};
use super::{PathPoint, StepQuantities, StepTrack};
use crate::fem::constraints::DofMap;
use crate::fem::dof::NodeDof;
use crate::fem::error::FemError;
use crate::fem::mass::{element_mass, point_mass};
use crate::fem::modal::{factor_shifted, lanczos, median_ratio};
use crate::fem::model::{Element, Model};
use crate::fem::solve::{SparsePattern, SymbolicFactor};
use crate::fem::transform::Mat12;
use nalgebra::{Matrix3, Matrix6, Vector6};
use std::cell::RefCell;

impl Tracker {
    /// `None` when nothing is tracked. `k_pairs`: the tangent's lower pairs (pattern order).
    pub(super) fn new(
        model: &Model,
        elems: &[ElemData],
        map: &DofMap,
        k_pairs: &[(usize, usize)],
        req: &StepTrack,
    ) -> Result<Option<Tracker>, FemError> {
        if req.is_empty() {
            return Ok(None);
        }
        if let Some(&n) = req.compliance.iter().find(|&&n| n >= model.nodes.len()) {
            return Err(FemError::NodeOutOfRange {
                what: "tracked compliance".into(),
                node: n,
                n_nodes: model.nodes.len(),
            });
        }
        let mut beams = Vec::new();
        for (ie, e) in elems.iter().enumerate() {
            if let (ElemData::Corot { .. }, Some(Element::Beam(_))) = (e, model.elements.get(ie)) {
                if let Some(m) = element_mass(model, ie)? {
                    beams.push((ie, Box::new(m.k)));
                }
            }
        }
        let mut pairs = k_pairs.to_vec();
        for (ie, _) in &beams {
            let eqs = beam_eqs(elems, map, *ie);
            for_each_pair_in(true, &eqs, 12, |_, _, r, c| pairs.push((r, c)));
        }
        for pm in &model.masses {
            let eqs = map.element_eqs([map.rep[pm.node]; 2], 1);
            for_each_pair_in(true, &eqs, 6, |_, _, r, c| pairs.push((r, c)));
        }
        pairs.extend((0..map.n_eq()).map(|i| (i, i)));
        let pattern = SparsePattern::new(map.n_eq(), &pairs)?;
        let symbolic = SymbolicFactor::new(&pattern)?;
        Ok(Some(Tracker {
            req: req.clone(),
            beams,
            pattern,
            symbolic,
            n_k: k_pairs.len(),
            steps: RefCell::new(Vec::new()),
        }))
    }
}

fn beam_eqs(elems: &[ElemData], map: &DofMap, ie: usize) -> [usize; 12] {
    let ElemData::Corot { nodes, .. } = &elems[ie] else {
        return [crate::fem::constraints::NONE; 12];
    };
    map.element_eqs([map.rep[nodes[0]], map.rep[nodes[1]]], 2)
}

impl CaseCtx<'_> {
    /// Appends the accepted state `st` at load factor `lambda` to `path` (the values of `track`,
    /// its stability and the Newton iteration log `residuals` of the step that reached it) and
    /// records the tracked quantities there ([`Self::record_step`]), once the state passed the
    /// equilibrium check of the final state ([`super::recover::verify_point`]; fails naming
    /// load case `name` and the point otherwise).
    #[allow(clippy::too_many_arguments)]
    pub(super) fn accept_point(
        &self,
        path: &mut Vec<PathPoint>,
        st: &State,
        lambda: f64,
        stable: bool,
        residuals: Vec<f64>,
        track: &[NodeDof],
        name: &str,
    ) -> Result<(), FemError> {
        let equilibrium = super::recover::verify_point(self, st, name, path.len(), lambda)?;
        path.push(PathPoint {
            equilibrium,
            lambda,
            values: self.tracked(st, track),
            stable,
            residuals,
        });
        self.record_step(st, lambda, path.len() - 1)
    }

    /// Evaluates and records the tracked quantities at the accepted state `st` (path point
    /// `point`, load factor `lambda`); nothing when no tracking was asked.
    pub(super) fn record_step(&self, st: &State, lambda: f64, point: usize) -> Result<(), FemError> {
        let Some(t) = &self.tracker else {
            return Ok(());
        };
        let q = self.step_quantities(t, st, lambda, point).map_err(|e| {
            FemError::Solver(format!(
                "tracking along the path at point {point} (λ = {lambda:.6}): {e}"
            ))
        })?;
        t.steps.borrow_mut().push(q);
        Ok(())
    }

    fn step_quantities(&self, t: &Tracker, st: &State, lambda: f64, point: usize) -> Result<StepQuantities, String> {
        let ev = self
            .evaluate(st, lambda, super::state::Assemble::Symmetric)
            .ok_or("degenerate configuration")?;
        let compliance = t
            .req
            .compliance
            .iter()
            .map(|&n| self.node_compliance(st, &ev.values, n))
            .collect::<Result<Vec<_>, _>>()?;
        let eigenvalues = if t.req.modes > 0 {
            self.eigenvalues(t, st, &ev.values)?
        } else {
            Vec::new()
        };
        Ok(StepQuantities {
            point,
            lambda,
            eigenvalues,
            compliance,
        })
    }

    /// 6×6 compliance of `node` with the symmetric tangent `values` (global axes).
    fn node_compliance(&self, st: &State, values: &[f64], node: usize) -> Result<[[f64; 6]; 6], String> {
        let arms = self.arms(st);
        let nn = self.model.nodes.len();
        let rhs: Vec<Vec<f64>> = (0..6)
            .map(|d| {
                let mut f = vec![0.0; 6 * nn];
                f[6 * node + d] = 1.0;
                let fi = self.to_independent(&arms, &f);
                self.map.eq_dof.iter().map(|&g| fi[g]).collect()
            })
            .collect();
        let x = self.solve_symmetric(values, &rhs)?.x;
        let m = self.map.rep[node];
        let mut c = Matrix6::zeros();
        for (j, q) in x.iter().enumerate() {
            let d = self.map.scatter(q, None);
            let v = Vector6::from_column_slice(&d[6 * m..6 * m + 6]);
            let g = arms[node].map_or(v, |a| a * v);
            c.set_column(j, &g);
        }
        let c = (c + c.transpose()) * 0.5;
        Ok(std::array::from_fn(|i| std::array::from_fn(|j| c[(i, j)])))
    }

    /// Mass values (the mass pairs of the tracker's pattern) at the state `st`.
    fn mass_values(&self, t: &Tracker, st: &State) -> Result<Vec<f64>, String> {
        let arms = self.arms(st);
        let mut values = Vec::with_capacity(t.pattern.n_triplets() - t.n_k);
        for (ie, m0) in &t.beams {
            let ElemData::Corot { nodes, geom, .. } = &self.elems[*ie] else {
                return Err(format!("element {ie} is not a beam"));
            };
            let (_, r) = self
                .corot_response(st, *ie, false)
                .ok_or_else(|| format!("element {ie} degenerate"))?;
            // Undeformed → current element axes.
            let q = r.rr * geom.r0.transpose();
            let mut tq = Mat12::zeros();
            for b in 0..4 {
                tq.fixed_view_mut::<3, 3>(3 * b, 3 * b).copy_from(&q);
            }
            let mut ta = Mat12::identity();
            for s in 0..2 {
                if let Some(a) = &arms[nodes[s]] {
                    ta.fixed_view_mut::<6, 6>(6 * s, 6 * s).copy_from(a);
                }
            }
            let mc = ta.transpose() * tq * **m0 * tq.transpose() * ta;
            let eqs = beam_eqs(self.elems, &self.map, *ie);
            for_each_pair_in(true, &eqs, 12, |a, b, _, _| values.push(mc[(a, b)]));
        }
        for (i, pm) in self.model.masses.iter().enumerate() {
            let mut m6 = point_mass(self.model, i);
            let r = st.r[pm.node];
            let inertia: Matrix3<f64> = m6.fixed_view::<3, 3>(3, 3).into_owned();
            m6.fixed_view_mut::<3, 3>(3, 3)
                .copy_from(&(r * inertia * r.transpose()));
            let mp = arms[pm.node].map_or(m6, |a| a.transpose() * m6 * a);
            let mut m12 = Mat12::zeros();
            m12.fixed_view_mut::<6, 6>(0, 0).copy_from(&mp);
            let eqs = self.map.element_eqs([self.map.rep[pm.node]; 2], 1);
            for_each_pair_in(true, &eqs, 6, |a, b, _, _| values.push(m12[(a, b)]));
        }
        values.resize(values.len() + self.n_eq(), 0.0);
        Ok(values)
    }

    /// The lowest eigenvalues ω² of K_T φ = ω² M φ at `st` (`kv`: symmetric tangent values).
    fn eigenvalues(&self, t: &Tracker, st: &State, kv: &[f64]) -> Result<Vec<f64>, String> {
        let n = self.n_eq();
        if t.req.modes > n {
            return Err(format!("{} modes asked, the model has {n} free DOFs", t.req.modes));
        }
        let mv = self.mass_values(t, st)?;
        let (nk, nm) = (t.n_k, mv.len());
        let mut kall = kv.to_vec();
        kall.resize(nk + nm, 0.0);
        let mut mall = vec![0.0; nk];
        mall.extend(mv);
        let err = |e: FemError| e.to_string();
        let k = t.pattern.matrix(&kall).map_err(err)?;
        let m = t.pattern.matrix(&mall).map_err(err)?;
        let (kd, md) = (k.diagonal(), m.diagonal());
        if md.iter().all(|&v| v <= 0.0) {
            return Err("the model has no mass (give materials a density or add point masses)".into());
        }
        let med = median_ratio(&kd, &md);
        // σ = 0 on a stable state; below the lowest (negative) eigenvalue on an unstable one.
        let shifts = [0.0, -1e-6 * med, -1e-3 * med, -med, -1e3 * med];
        let (shift, factor) = factor_shifted(&k, &m, &t.symbolic, &shifts, self.par)
            .map_err(err)?
            .ok_or("K_T − σM is singular for every shift tried: a massless mechanism")?;
        let (theta, _, _) = lanczos(&factor, &m.full(), n, t.req.modes, 1e-8).map_err(err)?;
        let mut lam: Vec<f64> = theta.iter().map(|th| shift + 1.0 / th).collect();
        lam.sort_by(f64::total_cmp);
        Ok(lam)
    }
}
