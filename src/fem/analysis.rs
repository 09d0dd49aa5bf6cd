//! Linear static analysis: one factorisation per set of constrained DOFs, many load cases per
//! factorisation, singular-model diagnosis, node compliance.

use super::assembly::Pattern;
use super::constraints::{DofMap, NONE};
pub use super::diagnose::{check_free_bodies, PIVOT_TOL, REFINE_TOL, RIGID_TOL};
use super::diagnose::{check_singular, check_unconstrained, diagnose_mechanism, has_tiny_pivot};
use super::dof::NodeDof;
use super::error::FemError;
use super::model::{LoadCase, Model};
use super::recovery;
pub use super::results::{CaseResult, StaticResults};
use super::solve::{Factor, FactorError, Parallelism, SparseMatrix, SymbolicFactor};
use nalgebra::Matrix6;

/// The reduced, factorised system for one set of constrained DOFs: DOF map, pattern, matrix,
/// factor. Solve any number of load cases whose prescribed DOFs are exactly `prescribed`.
#[derive(Debug, Clone)]
pub struct System {
    map: DofMap,
    prescribed: Vec<NodeDof>,
    pattern: Pattern,
    k: SparseMatrix,
    factor: Factor,
    /// The factor had tiny pivots of a stiff-and-soft model: every solve's roundoff is
    /// estimated by a step of iterative refinement (see [`REFINE_TOL`]).
    refine: bool,
}

/// Prescribed DOFs of a load case, sorted.
pub fn prescribed_dofs(case: &LoadCase) -> Vec<NodeDof> {
    let mut v: Vec<NodeDof> = case
        .displacements
        .iter()
        .map(|p| NodeDof {
            node: p.node,
            dof: p.dof,
        })
        .collect();
    v.sort();
    v.dedup();
    v
}

impl System {
    /// Validates the model, numbers the DOFs (supports + `prescribed` constrained, rigid links
    /// eliminated), assembles, checks for unconstrained DOFs and free bodies, and factorises.
    pub fn new(model: &Model, prescribed: &[NodeDof], par: Parallelism) -> Result<System, FemError> {
        model.validate()?;
        let map = DofMap::new(model, prescribed, None)?;
        let pattern = Pattern::new(model, &map)?;
        let symbolic = SymbolicFactor::with_ordering(pattern.sparse(), model.ordering)?;
        Self::build(model, map, prescribed, pattern, &symbolic, par)
    }

    /// Like [`System::new`] but reusing the pattern and symbolic factorisation of `other`
    /// (same topology, e.g. another design of a sweep): only values and the numeric factor are
    /// computed. Errors with `PatternMismatch` if the topology differs.
    pub fn with_topology_of(other: &System, model: &Model, par: Parallelism) -> Result<System, FemError> {
        model.validate()?;
        let map = DofMap::new(model, &other.prescribed, None)?;
        if !other.pattern.matches(model, &map) || map.eq_dof != other.map.eq_dof {
            return Err(FemError::PatternMismatch(
                "model topology differs from the reused system".into(),
            ));
        }
        Self::build(
            model,
            map,
            &other.prescribed,
            other.pattern.clone(),
            other.factor.symbolic(),
            par,
        )
    }

    fn build(
        model: &Model,
        map: DofMap,
        prescribed: &[NodeDof],
        pattern: Pattern,
        symbolic: &SymbolicFactor,
        par: Parallelism,
    ) -> Result<System, FemError> {
        let k = pattern.assemble(model, &map)?;
        check_unconstrained(&map, &k)?;
        check_free_bodies(model, &map)?;
        let factor = match Factor::new(symbolic, &k, par) {
            Ok(f) => f,
            Err(FactorError::NotPositiveDefinite) => return Err(diagnose_mechanism(model, &map, &k, symbolic, par)),
            Err(FactorError::Other(s)) => return Err(FemError::Solver(s)),
        };
        let refine = has_tiny_pivot(&factor, &k);
        if refine {
            if let Some(e) = check_singular(model, &map, &k, &factor, par) {
                return Err(e);
            }
        }
        Ok(System {
            map,
            prescribed: prescribed.to_vec(),
            pattern,
            k,
            factor,
            refine,
        })
    }

    /// New element values (e.g. changed sections or materials, same topology and coordinates
    /// topology-wise): reassemble on the same pattern and refactorise numerically.
    pub fn refactor(&mut self, model: &Model) -> Result<(), FemError> {
        let map = DofMap::new(model, &self.prescribed, None)?;
        if map.eq_dof != self.map.eq_dof {
            return Err(FemError::PatternMismatch("equation numbering changed".into()));
        }
        let k = self.pattern.assemble(model, &map)?;
        self.refine = false;
        match self.factor.refactor(&k) {
            Ok(()) if has_tiny_pivot(&self.factor, &k) => {
                if let Some(e) = check_singular(model, &map, &k, &self.factor, Parallelism::Sequential) {
                    return Err(e);
                }
                self.refine = true;
            }
            Ok(()) => {}
            Err(FactorError::NotPositiveDefinite) => {
                return Err(diagnose_mechanism(
                    model,
                    &map,
                    &k,
                    self.factor.symbolic(),
                    Parallelism::Sequential,
                ))
            }
            Err(FactorError::Other(s)) => return Err(FemError::Solver(s)),
        }
        self.map = map;
        self.k = k;
        Ok(())
    }

    /// DOF map (equation numbering).
    pub fn dof_map(&self) -> &DofMap {
        &self.map
    }
    /// Reduced stiffness (lower triangle).
    pub fn matrix(&self) -> &SparseMatrix {
        &self.k
    }
    /// Pattern (reusable for sweeps).
    pub fn pattern(&self) -> &Pattern {
        &self.pattern
    }
    /// Numeric factor.
    pub fn factor(&self) -> &Factor {
        &self.factor
    }
    /// Prescribed DOFs this system was built for.
    pub fn prescribed(&self) -> &[NodeDof] {
        &self.prescribed
    }

    /// Solves several load cases with one batched solve. Each case must prescribe exactly the
    /// DOFs of this system (values may differ).
    pub fn solve_cases(&self, model: &Model, cases: &[&LoadCase]) -> Result<Vec<CaseResult>, FemError> {
        let n = self.map.n_eq();
        let nd = model.n_dofs();
        let mut rhs = Vec::with_capacity(n * cases.len());
        let mut u_c_all = Vec::with_capacity(cases.len());
        let mut f_all = Vec::with_capacity(cases.len());
        for case in cases {
            model.validate_case(case)?;
            if prescribed_dofs(case) != self.prescribed {
                return Err(FemError::LoadCase {
                    case: case.name.clone(),
                    reason: "its prescribed DOFs differ from the system's (use solve_static to group cases)".into(),
                });
            }
            let mut f = vec![0.0; nd];
            for l in &case.forces {
                for d in 0..6 {
                    f[6 * l.node + d] += l.f[d];
                }
            }
            let mut u_c = vec![0.0; nd];
            for p in &case.displacements {
                u_c[6 * p.node + p.dof.index()] = p.value;
            }
            // f_red = Aᵀ (f − K u_c) with u_c expanded to slaves (none can be prescribed).
            let u_c_full = self.map.expand(&vec![0.0; n], &u_c);
            let mut g = f.clone();
            if u_c_full.iter().any(|&v| v != 0.0) {
                let ku = recovery::internal_forces(model, &u_c_full)?;
                for (gi, ki) in g.iter_mut().zip(&ku) {
                    *gi -= ki;
                }
            }
            rhs.extend(self.map.reduce(&g));
            u_c_all.push(u_c);
            f_all.push(f);
        }
        self.solve_checked(&mut rhs, cases.len())?;
        cases
            .iter()
            .enumerate()
            .map(|(i, case)| {
                let u = self.map.expand(&rhs[i * n..(i + 1) * n], &u_c_all[i]);
                recovery::case_result(model, &self.map, &case.name, &u, &f_all[i])
            })
            .collect()
    }

    /// Solves K X = B in place (`ncols` columns). After a factorisation with tiny pivots (a
    /// stiff-and-soft model) the roundoff left in the answer is estimated by one step of
    /// iterative refinement, ΔX = K⁻¹(B − K X) (not applied: in working precision it does not
    /// make a contrast-limited answer more accurate); above [`REFINE_TOL`] of the answer
    /// (energy norm) the stiffness contrast is beyond double precision and the solve is refused.
    pub fn solve_checked(&self, rhs: &mut [f64], ncols: usize) -> Result<(), FemError> {
        let b = if self.refine { rhs.to_vec() } else { Vec::new() };
        self.factor.solve_in_place(rhs, ncols)?;
        if !self.refine {
            return Ok(());
        }
        let n = self.map.n_eq();
        let mut r = Vec::with_capacity(rhs.len());
        for (x, bc) in rhs.chunks(n).zip(b.chunks(n)) {
            let kx = self.k.mul_vec(x);
            r.extend(bc.iter().zip(&kx).map(|(bi, ki)| bi - ki));
        }
        self.factor.solve_in_place(&mut r, ncols)?;
        let d = self.k.diagonal();
        let norm = |v: &[f64]| v.iter().zip(&d).map(|(vi, di)| vi * vi * di.abs()).sum::<f64>().sqrt();
        for (x, dx) in rhs.chunks(n).zip(r.chunks(n)) {
            let (nx, ndx) = (norm(x), norm(dx));
            let eta = if nx > 0.0 { ndx / nx } else { 0.0 };
            if eta.is_nan() || eta > REFINE_TOL {
                let worst = (0..n)
                    .max_by(|&i, &j| (dx[i].abs() * d[i].abs().sqrt()).total_cmp(&(dx[j].abs() * d[j].abs().sqrt())))
                    .map(|i| self.map.describe_eq(i).to_string())
                    .unwrap_or_default();
                return Err(FemError::Solver(format!(
                    "the stiffness contrast is beyond double precision: the answer is uncertain by \
                     {eta:.1e} of itself (one step of iterative refinement would change it by that much, \
                     most at {worst}; at most {REFINE_TOL:.0e} accepted); make the stiff parts less stiff \
                     or the soft parts stiffer"
                )));
            }
        }
        Ok(())
    }

    /// 6×6 compliance of `node` (displacement/rotation of the node per unit force/moment at the
    /// node, global axes; mm/N, rad/N, rad/(N·mm)) with this system's constraints (prescribed
    /// DOFs held at zero). Rows/columns of constrained DOFs are zero.
    pub fn node_compliance(&self, model: &Model, node: usize) -> Result<Matrix6<f64>, FemError> {
        if node >= model.nodes.len() {
            return Err(FemError::NodeOutOfRange {
                what: "node compliance".into(),
                node,
                n_nodes: model.nodes.len(),
            });
        }
        let n = self.map.n_eq();
        let nd = model.n_dofs();
        let mut rhs = Vec::with_capacity(6 * n);
        for d in 0..6 {
            let mut f = vec![0.0; nd];
            f[6 * node + d] = 1.0;
            rhs.extend(self.map.reduce(&f));
        }
        self.solve_checked(&mut rhs, 6)?;
        let zero = vec![0.0; nd];
        let mut c = Matrix6::zeros();
        for j in 0..6 {
            let u = self.map.expand(&rhs[j * n..(j + 1) * n], &zero);
            for i in 0..6 {
                c[(i, j)] = u[6 * node + i];
            }
        }
        Ok((c + c.transpose()) * 0.5)
    }

    /// 6×6 stiffness of `node` = inverse of [`System::node_compliance`]. Errors if any DOF of
    /// the node is constrained (the compliance is then singular).
    pub fn node_stiffness(&self, model: &Model, node: usize) -> Result<Matrix6<f64>, FemError> {
        let c = self.node_compliance(model, node)?;
        let rep = self.map.rep[node];
        let fixed: Vec<NodeDof> = (0..6)
            .filter(|&d| self.map.eq[6 * rep + d] == NONE)
            .map(|d| NodeDof::from_global(6 * rep + d))
            .collect();
        if !fixed.is_empty() {
            return Err(FemError::BadInput(format!(
                "node {node}: no stiffness matrix, {} constrained",
                super::dof::describe(&fixed)
            )));
        }
        c.cholesky()
            .map(|ch| ch.inverse())
            .ok_or_else(|| FemError::Solver(format!("node {node}: compliance not positive definite")))
    }

    /// Writes the reduced stiffness in Matrix Market format.
    pub fn write_matrix_market(&self, path: &std::path::Path) -> Result<(), FemError> {
        let mut f = std::fs::File::create(path)?;
        self.k.write_matrix_market(&mut f)?;
        Ok(())
    }
}
