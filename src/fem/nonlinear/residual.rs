//! Residual and tangent at a configuration: co-rotational element responses, assembly of the
//! reduced residual and the symmetric or full tangent, and the linear solves (Cholesky, LU).

use super::state::{Assemble, CaseCtx, ElemData, Eval, Solution, State};
use crate::fem::assembly::for_each_pair;
use crate::fem::constraints::{frame_block, NONE};
use crate::fem::corot;
use crate::fem::dof::NodeDof;
use crate::fem::solve::{Factor, LuPattern};
use crate::fem::transform::{skew, Mat12};
use nalgebra::{Matrix3, Matrix6, SMatrix, Vector3, Vector6};

impl CaseCtx<'_> {
    /// Element internal forces (global, on its nodes) and tangents.
    /// Co-rotational response of beam or flexibility element `ie` (`None` for a spring or a
    /// degenerate element), with its nodes.
    pub(super) fn corot_response(
        &self,
        st: &State,
        ie: usize,
        tangent: bool,
    ) -> Option<([usize; 2], corot::CorotResponse)> {
        let ElemData::Corot { nodes, geom, k_local } = &self.elems[ie] else {
            return None;
        };
        let r = corot::response(
            geom,
            k_local,
            &Self::node_state(st, nodes[0]),
            &Self::node_state(st, nodes[1]),
            tangent,
        )?;
        Some((*nodes, r))
    }

    /// Spring DOFs d = [u, rotation vector] of its `n_nodes` nodes (12 values; zero beyond).
    pub(super) fn spring_motion(st: &State, nodes: &[usize; 2], n_nodes: usize) -> SMatrix<f64, 12, 1> {
        let mut d = SMatrix::<f64, 12, 1>::zeros();
        for (s, &n) in nodes.iter().enumerate().take(n_nodes) {
            let rv = corot::rot_log(&st.r[n]);
            for j in 0..3 {
                d[6 * s + j] = st.u[n][j];
                d[6 * s + 3 + j] = rv[j];
            }
        }
        d
    }

    pub(super) fn element_response(
        &self,
        st: &State,
        ie: usize,
        tangent: bool,
    ) -> Option<([usize; 2], usize, Mat12, [f64; 12])> {
        match &self.elems[ie] {
            ElemData::Corot { .. } => {
                let (nodes, r) = self.corot_response(st, ie, tangent)?;
                Some((nodes, 2, r.k, std::array::from_fn(|i| r.f[i])))
            }
            ElemData::Spring { nodes, n_nodes, b, k } => {
                let d = Self::spring_motion(st, nodes, *n_nodes);
                let kd = Matrix6::from_diagonal(&Vector6::from(*k));
                let km = b.transpose() * kd * **b;
                let f = km * d;
                Some((*nodes, *n_nodes, km, std::array::from_fn(|i| f[i])))
            }
        }
    }

    /// The tangent the Newton iterations use.
    pub(super) fn newton_tangent(&self) -> Assemble {
        if self.full.is_some() {
            Assemble::Full
        } else {
            Assemble::Symmetric
        }
    }

    /// Residual, tangent and force norms at load factor `lambda`.
    pub(super) fn evaluate(&self, st: &State, lambda: f64, mode: Assemble) -> Option<Eval> {
        let (mut ev, lin) = self.residual(st, lambda)?;
        if mode != Assemble::None {
            ev.values = self.tangent_values(st, &ev, &lin, mode)?;
        }
        Some(ev)
    }

    /// Residual and force norms at load factor `lambda` (no tangent values), with the
    /// co-rotational elements' linearisations for [`Self::tangent_values`] at the same state.
    pub(super) fn residual(&self, st: &State, lambda: f64) -> Option<(Eval, Vec<Option<corot::Linearisation>>)> {
        let nn = self.model.nodes.len();
        let arms = self.arms(st);
        let mut f_int = vec![0.0; 6 * nn];
        let mut lins = Vec::with_capacity(self.elems.len());
        for ie in 0..self.elems.len() {
            let mut add = |nodes: &[usize; 2], n_nodes: usize, f: &[f64]| {
                for s in 0..n_nodes {
                    for d in 0..6 {
                        f_int[6 * nodes[s] + d] += f[6 * s + d];
                    }
                }
            };
            match &self.elems[ie] {
                ElemData::Corot { nodes, geom, k_local } => {
                    let lin = corot::linearise(
                        geom,
                        k_local,
                        &Self::node_state(st, nodes[0]),
                        &Self::node_state(st, nodes[1]),
                    )?;
                    add(nodes, 2, lin.force().as_slice());
                    lins.push(Some(lin));
                }
                ElemData::Spring { .. } => {
                    let (nodes, n_nodes, _, f) = self.element_response(st, ie, false)?;
                    add(&nodes, n_nodes, &f);
                    lins.push(None);
                }
            }
        }
        let net: Vec<f64> = f_int.iter().zip(&self.f_ext).map(|(a, b)| a - lambda * b).collect();
        let net_i = self.to_independent(&arms, &net);
        let r: Vec<f64> = self.map.eq_dof.iter().map(|&g| net_i[g]).collect();
        let fi = self.to_independent(&arms, &f_int);
        let fe = self.to_independent(&arms, &self.f_ext);
        let (internal, load) = (norm(&fi), lambda.abs() * norm(&fe));
        if r.iter().any(|v| !v.is_finite()) {
            return None;
        }
        let ev = Eval {
            r,
            values: Vec::new(),
            load,
            internal,
            net,
            arms,
        };
        Some((ev, lins))
    }

    /// Tangent values (pattern order, see [`Eval::values`]) at the state `ev` and `lins` were
    /// evaluated at ([`Self::residual`]).
    pub(super) fn tangent_values(
        &self,
        st: &State,
        ev: &Eval,
        lins: &[Option<corot::Linearisation>],
        mode: Assemble,
    ) -> Option<Vec<f64>> {
        let sym = mode == Assemble::Symmetric;
        let (arms, net) = (&ev.arms, &ev.net);
        let mut values = Vec::with_capacity(self.pattern.n_triplets());
        for (ie, lin) in lins.iter().enumerate() {
            let (nodes, n_nodes, k) = match (lin, &self.elems[ie]) {
                (Some(lin), ElemData::Corot { nodes, .. }) => (*nodes, 2, lin.tangent()?),
                _ => {
                    let (nodes, n_nodes, k, _) = self.element_response(st, ie, true)?;
                    (nodes, n_nodes, k)
                }
            };
            let mut kp = if sym { (k + k.transpose()) * 0.5 } else { k };
            // Tᵀ K T with T = diag(arm of each node), block by block (most arms are identities).
            for s in 0..n_nodes {
                if let Some(a) = &arms[nodes[s]] {
                    for c in 0..n_nodes {
                        let rows = a.tr_mul(&kp.fixed_view::<6, 6>(6 * s, 6 * c));
                        kp.fixed_view_mut::<6, 6>(6 * s, 6 * c).copy_from(&rows);
                        let cols = kp.fixed_view::<6, 6>(6 * c, 6 * s) * a;
                        kp.fixed_view_mut::<6, 6>(6 * c, 6 * s).copy_from(&cols);
                    }
                }
            }
            let reps = [self.map.rep[nodes[0]], self.map.rep[nodes[1]]];
            let eqs = self.map.element_eqs(reps, n_nodes);
            for_each_pair_in(sym, &eqs, 6 * n_nodes, |a, b, _, _| values.push(kp[(a, b)]));
        }
        // Rigid links: δ(a × F_s) = [F_s×][a×] δw_m (a = R_m a₀), symmetrised for Cholesky.
        for &m in &self.masters {
            let mut g = Matrix3::zeros();
            for n in 0..self.model.nodes.len() {
                if self.map.rep[n] == m && n != m {
                    let fs = Vector3::new(net[6 * n], net[6 * n + 1], net[6 * n + 2]);
                    let a = st.r[m] * self.arm0[n];
                    g += skew(&fs) * skew(&a);
                }
            }
            let mut g6 = Matrix6::zeros();
            let gs = if sym { (g + g.transpose()) * 0.5 } else { g };
            g6.fixed_view_mut::<3, 3>(3, 3).copy_from(&gs);
            if let Some(f) = self.model.frames.get(&m) {
                let fb = frame_block(f);
                g6 = fb.transpose() * g6 * fb;
            }
            let mut k12 = Mat12::zeros();
            k12.fixed_view_mut::<6, 6>(0, 0).copy_from(&g6);
            let eqs = self.map.element_eqs([m, m], 1);
            for_each_pair_in(sym, &eqs, 6, |a, b, _, _| values.push(k12[(a, b)]));
        }
        values.resize(values.len() + self.n_eq(), 0.0);
        values.iter().all(|v| v.is_finite()).then_some(values)
    }

    /// Solves K x = b for several right-hand sides with the tangent of [`Self::evaluate`] in
    /// the Newton mode: the full tangent by sparse LU, or the symmetric one by sparse Cholesky
    /// and, when that is not positive definite (past a limit point, near a bifurcation), by
    /// sparse LU.
    pub(super) fn solve(&self, values: &[f64], rhs: &[Vec<f64>]) -> Result<Solution, String> {
        let n = self.n_eq();
        let mut buf: Vec<f64> = rhs.iter().flatten().copied().collect();
        let split = |buf: Vec<f64>| buf.chunks(n.max(1)).map(|c| c.to_vec()).collect::<Vec<_>>();
        if let Some(full) = &self.full {
            full.solve_in_place(values, &mut buf, rhs.len(), self.par)
                .map_err(|e| format!("tangent stiffness: {e}"))?;
            return Ok(Solution {
                x: split(buf),
                positive_definite: None,
            });
        }
        self.solve_symmetric(values, rhs)
    }

    /// Solves with the symmetric tangent (lower values in pattern order): sparse Cholesky, or
    /// sparse LU when it is not positive definite.
    pub(super) fn solve_symmetric(&self, values: &[f64], rhs: &[Vec<f64>]) -> Result<Solution, String> {
        let n = self.n_eq();
        let mut buf: Vec<f64> = rhs.iter().flatten().copied().collect();
        let split = |buf: Vec<f64>| buf.chunks(n.max(1)).map(|c| c.to_vec()).collect::<Vec<_>>();
        if let Some(f) = self.cholesky(values)? {
            f.solve_in_place(&mut buf, rhs.len()).map_err(|e| e.to_string())?;
            return Ok(Solution {
                x: split(buf),
                positive_definite: Some(true),
            });
        }
        let mirror = self
            .mirror
            .get_or_init(|| LuPattern::from_lower(n, &self.lower_pairs).map_err(|e| e.to_string()))
            .as_ref()
            .map_err(|e| e.clone())?;
        let vals = LuPattern::mirror_values(&self.lower_pairs, values);
        mirror
            .solve_in_place(&vals, &mut buf, rhs.len(), self.par)
            .map_err(|e| format!("tangent stiffness is singular: {e}"))?;
        Ok(Solution {
            x: split(buf),
            positive_definite: Some(false),
        })
    }

    /// Cholesky factor of the symmetric tangent (lower values), `None` when it is not
    /// positive definite (a pivot at or below [`crate::fem::diagnose::PIVOT_TOL`] of its diagonal).
    pub(super) fn cholesky(&self, values: &[f64]) -> Result<Option<Factor>, String> {
        let k = self.pattern.matrix(values).map_err(|e| e.to_string())?;
        let Ok(f) = Factor::new(&self.symbolic, &k, self.par) else {
            return Ok(None);
        };
        let diag = k.diagonal();
        let ok = f
            .pivots()
            .iter()
            .zip(&diag)
            .all(|(p, d)| p.is_finite() && *p > crate::fem::diagnose::PIVOT_TOL * d);
        Ok(ok.then_some(f))
    }

    /// Whether the symmetric tangent at `st` is positive definite.
    pub(super) fn positive_definite(&self, st: &State, lambda: f64) -> bool {
        self.evaluate(st, lambda, Assemble::Symmetric)
            .and_then(|ev| self.cholesky(&ev.values).ok())
            .is_some_and(|f| f.is_some())
    }

    pub(super) fn tracked(&self, st: &State, track: &[NodeDof]) -> Vec<f64> {
        track
            .iter()
            .map(|nd| {
                let i = nd.dof.index();
                if nd.node >= st.u.len() {
                    f64::NAN
                } else if i < 3 {
                    st.u[nd.node][i]
                } else {
                    corot::rot_log(&st.r[nd.node])[i - 3]
                }
            })
            .collect()
    }
}

/// Euclidean norm, scaled by the largest entry so that it neither overflows (entries beyond
/// ~1e154 would square to ∞ and make every convergence test pass as ∞ ≤ ∞) nor underflows.
pub(super) fn norm(v: &[f64]) -> f64 {
    let m = v.iter().fold(0.0f64, |a, x| a.max(x.abs()));
    if m == 0.0 || !m.is_finite() {
        return m;
    }
    m * v.iter().map(|x| (x / m) * (x / m)).sum::<f64>().sqrt()
}

pub(super) fn dot(a: &[f64], b: &[f64]) -> f64 {
    a.iter().zip(b).map(|(x, y)| x * y).sum()
}

/// [`for_each_pair`] (`lower`, the order of [`crate::fem::assembly`]) or every pair of free DOFs (the full non-symmetric pattern).
#[inline]
pub(super) fn for_each_pair_in(
    lower: bool,
    eqs: &[usize; 12],
    n: usize,
    mut f: impl FnMut(usize, usize, usize, usize),
) {
    if lower {
        return for_each_pair(eqs, n, f);
    }
    for a in 0..n {
        let ea = eqs[a];
        if ea == NONE {
            continue;
        }
        for (b, &eb) in eqs.iter().enumerate().take(n) {
            if eb != NONE {
                f(a, b, ea, eb);
            }
        }
    }
}
