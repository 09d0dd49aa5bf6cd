//! Linear static analysis: one factorisation per set of constrained DOFs, many load cases per
//! factorisation, singular-model diagnosis, node compliance.

use super::assembly::Pattern;
use super::constraints::{DofMap, NONE};
use super::dof::NodeDof;
use super::error::FemError;
use super::model::{Element, LoadCase, Model};
use super::recovery;
pub use super::recovery::CaseResult;
use super::solve::{Factor, FactorError, Parallelism, SparseMatrix, SymbolicFactor};
use nalgebra::Matrix6;

/// Results of all load cases of a model, in model order.
#[derive(Debug, Clone, PartialEq)]
pub struct StaticResults {
    pub load_cases: Vec<CaseResult>,
}

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
        let symbolic = SymbolicFactor::new(pattern.sparse())?;
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

/// Relative pivot below which the factorisation is examined for a mechanism: L_jj² < PIVOT_TOL·K_jj
/// means the DOF kept less than 1e-11 of its own stiffness after elimination. That is either a
/// zero-energy mode at roundoff level or a legitimate stiff-and-soft contrast (a soft spring in
/// series with one 10¹² stiffer): the lowest mode of K then decides (see [`RIGID_TOL`]), and
/// the solves of an accepted model are checked for roundoff ([`REFINE_TOL`]).
pub const PIVOT_TOL: f64 = 1e-11;

/// The lowest mode x of K (against diag K) is a mechanism when its strain energy, summed
/// element by element, is at roundoff level against its own roundoff scale:
/// Σ xₑᵀKₑxₑ ≤ RIGID_TOL · Σ |xₑ|ᵀ|Kₑ||xₑ| (|·| entrywise; the right side bounds the roundoff of
/// the left, a few ε ≈ 1e-16, whatever the units and the stiffness of the rest of the model).
/// Mechanisms give ≤ 1e-16 (rigid motion of every element); stiff-and-soft models accepted by
/// [`REFINE_TOL`] give ≥ 1e-14 (8.9e-15 for a steel cantilever segment carrying one 10¹² stiffer).
pub const RIGID_TOL: f64 = 5e-16;

/// Largest roundoff estimate accepted for a stiff-and-soft model: the relative size (energy
/// norm) of one step of iterative refinement (see [`System::solve_checked`]; N. J. Higham,
/// Accuracy and Stability of Numerical Algorithms, 2nd ed., 2002, ch. 12), which overestimates
/// the actual error here by 7–20×. A steel cantilever segment carrying one 10¹² stiffer
/// estimates 7e-4 (actual error 4e-5) and solves; a 0.1 mm leaf carrying a block whose
/// translational stiffness is 10¹⁵ its own estimates 0.14 (actual 2 %) and is refused.
pub const REFINE_TOL: f64 = 1e-2;

fn has_tiny_pivot(f: &Factor, k: &SparseMatrix) -> bool {
    f.pivots()
        .iter()
        .zip(k.diagonal())
        .any(|(p, d)| p.is_nan() || *p <= PIVOT_TOL * d)
}

/// Free equations whose diagonal stiffness is zero, relative to the largest diagonal of the
/// same kind (translations and rotations have different units) at the same node: a DOF is
/// judged against its own node's scale, never against the stiffest part of the model, so a
/// thin leaf next to a block 10⁶× stiffer is not mistaken for a free DOF.
fn check_unconstrained(map: &DofMap, k: &SparseMatrix) -> Result<(), FemError> {
    let d = k.diagonal();
    // Slot of equation i: (node, translation 0 / rotation 1).
    let slot = |i: usize| 2 * (map.eq_dof[i] / 6) + usize::from(map.eq_dof[i] % 6 >= 3);
    let mut max = vec![0.0_f64; map.eq_dof.iter().map(|g| 2 * (g / 6) + 2).max().unwrap_or(0)];
    for (i, &v) in d.iter().enumerate() {
        max[slot(i)] = max[slot(i)].max(v.abs());
    }
    let dofs: Vec<NodeDof> = d
        .iter()
        .enumerate()
        .filter(|&(i, &v)| v.is_nan() || v <= 0.0 || v <= 1e-13 * max[slot(i)])
        .map(|(i, _)| map.describe_eq(i))
        .collect();
    if dofs.is_empty() {
        Ok(())
    } else {
        Err(FemError::Unconstrained { dofs })
    }
}

/// After a factorisation with tiny pivots: `None` if the lowest mode of K deforms the model (a
/// stiff-and-soft model, the factor is kept), else the mechanism.
fn check_singular(model: &Model, map: &DofMap, k: &SparseMatrix, f: &Factor, par: Parallelism) -> Option<FemError> {
    match classify(model, map, k, Some(f), f.symbolic(), par) {
        Low::WellPosed => None,
        low => Some(low.error()),
    }
}

/// What the lowest mode of K says about a model whose factorisation failed or had tiny pivots.
enum Low {
    /// Deforms the model (strain energy above roundoff): a stiff-and-soft model.
    WellPosed,
    /// Roundoff-level energy ([`RIGID_TOL`]): the DOFs of the mechanism.
    Mechanism(Vec<NodeDof>),
    /// No factor of K + εD could be formed.
    Unknown,
}

impl Low {
    fn error(self) -> FemError {
        match self {
            Low::Mechanism(dofs) => FemError::Mechanism { dofs },
            Low::WellPosed | Low::Unknown => FemError::Solver(
                "stiffness matrix is not positive definite (a negative stiffness, or a stiffness \
                 contrast beyond double precision)"
                    .into(),
            ),
        }
    }
}

/// The lowest mode of the pencil (K, D), D = diag K, by inverse iteration (D-normalised): with
/// the factor of K itself when it exists (8 steps; the ratio of a roundoff-level eigenvalue to
/// the next is tiny), else with the first of K + εD, ε = 1e-15 … 1e-6, that factorises (30
/// steps). `None` if no factor could be formed.
fn lowest_mode(
    k: &SparseMatrix,
    factor: Option<&Factor>,
    symbolic: &SymbolicFactor,
    par: Parallelism,
) -> Option<Vec<f64>> {
    let d = k.diagonal();
    let n = d.len();
    let iterate = |f: &Factor, steps: usize| -> Option<Vec<f64>> {
        // Deterministic pseudo-random start (no zero components).
        let mut x: Vec<f64> = (0..n).map(|i| 1.0 + ((i as f64) * 0.618_033_988_75).fract()).collect();
        for _ in 0..steps {
            let mut y: Vec<f64> = x.iter().zip(&d).map(|(xi, di)| xi * di).collect();
            f.solve_in_place(&mut y, 1).ok()?;
            let norm = y.iter().zip(&d).map(|(yi, di)| yi * yi * di).sum::<f64>().sqrt();
            if !(norm > 0.0 && norm.is_finite()) {
                return None;
            }
            x = y.iter().map(|v| v / norm).collect();
        }
        Some(x)
    };
    factor.and_then(|f| iterate(f, 8)).or_else(|| {
        [1e-15, 1e-14, 1e-13, 1e-12, 1e-10, 1e-8, 1e-6].iter().find_map(|&eps| {
            let f = Factor::new(symbolic, &k.shifted_scaled(eps), par).ok()?;
            iterate(&f, 30)
        })
    })
}

/// Strain energy of the reduced motion `x` summed element by element, Σ xₑᵀKₑxₑ, and its
/// roundoff scale Σ |xₑ|ᵀ|Kₑ||xₑ| (|·| entrywise).
fn mode_energy(model: &Model, map: &DofMap, x: &[f64]) -> (f64, f64) {
    let at = |e: usize| if e == NONE { 0.0 } else { x[e] };
    let (mut e, mut s) = (0.0, 0.0);
    let mut add = |k: &dyn Fn(usize, usize) -> f64, eqs: &[usize]| {
        for (a, &ea) in eqs.iter().enumerate() {
            for (b, &eb) in eqs.iter().enumerate() {
                let v = k(a, b) * at(ea) * at(eb);
                e += v;
                s += v.abs();
            }
        }
    };
    for (ie, el) in model.elements.iter().enumerate() {
        if let Element::Shell4(_) = el {
            let Ok(em) = model.shell_matrix(ie) else { continue };
            let (reps, k) = map.shell_on_independent(&em);
            add(&|a, b| k[(a, b)], &map.nodes_eqs(&reps));
        } else {
            let Ok(em) = model.element_matrix(ie) else { continue };
            let (reps, k) = map.element_on_independent(&em);
            let eqs = map.element_eqs(reps, em.n_nodes);
            add(&|a, b| k[(a, b)], &eqs[..6 * em.n_nodes]);
        }
    }
    (e, s)
}

/// Classifies the lowest mode x of (K, diag K) (see [`lowest_mode`]) by its strain energy against
/// its roundoff scale ([`mode_energy`], [`RIGID_TOL`]). The DOFs reported for a mechanism are
/// the translations, and rotations times the model size, with at least 1 % of the largest
/// amplitude (so a thin leaf's rotation counts as much as the swing of the block it carries).
fn classify(
    model: &Model,
    map: &DofMap,
    k: &SparseMatrix,
    factor: Option<&Factor>,
    symbolic: &SymbolicFactor,
    par: Parallelism,
) -> Low {
    let Some(x) = lowest_mode(k, factor, symbolic, par) else {
        return Low::Unknown;
    };
    let (e, scale) = mode_energy(model, map, &x);
    if e > RIGID_TOL * scale {
        return Low::WellPosed;
    }
    let size = model_size(model);
    let amp: Vec<f64> = x
        .iter()
        .enumerate()
        .map(|(i, xi)| xi.abs() * if map.eq_dof[i] % 6 >= 3 { size } else { 1.0 })
        .collect();
    let max = amp.iter().cloned().fold(0.0, f64::max);
    Low::Mechanism(
        amp.iter()
            .enumerate()
            .filter(|&(_, &a)| a >= 1e-2 * max)
            .map(|(i, _)| map.describe_eq(i))
            .collect(),
    )
}

fn find(parent: &mut [usize], mut i: usize) -> usize {
    while parent[i] != i {
        parent[i] = parent[parent[i]];
        i = parent[i];
    }
    i
}

/// Connected parts (through elements, rigid links and ties) without any support, prescribed DOF or
/// ground spring.
pub fn check_free_bodies(model: &Model, map: &DofMap) -> Result<(), FemError> {
    let n = model.nodes.len();
    let mut parent: Vec<usize> = (0..n).collect();
    let mut grounded = vec![false; n];
    for e in &model.elements {
        let nodes = e.nodes();
        if let Element::Spring(s) = e {
            if s.b.is_none() {
                if s.k.iter().any(|&k| k > 0.0) {
                    grounded[map.rep[s.a]] = true;
                }
                continue;
            }
        }
        for w in nodes.windows(2) {
            let (a, b) = (find(&mut parent, map.rep[w[0]]), find(&mut parent, map.rep[w[1]]));
            parent[a] = b;
        }
    }
    for t in &model.ties {
        if t.dofs.iter().any(|&d| d) {
            let (a, b) = (find(&mut parent, map.rep[t.a]), find(&mut parent, map.rep[t.b]));
            parent[a] = b;
        }
    }
    for &g in &map.constrained {
        grounded[g / 6] = true;
    }
    let mut comp_grounded = vec![false; n];
    for (i, _) in grounded.iter().enumerate().filter(|(_, g)| **g) {
        let r = find(&mut parent, i);
        comp_grounded[r] = true;
    }
    let mut free: Vec<usize> = Vec::new();
    let mut first_root = NONE;
    for i in 0..n {
        let r = find(&mut parent, map.rep[i]);
        if !comp_grounded[r] && (first_root == NONE || first_root == r) {
            first_root = r;
            free.push(i);
        }
    }
    if free.is_empty() {
        Ok(())
    } else {
        Err(FemError::FreeBody { nodes: free })
    }
}

/// After a failed factorisation: the mechanism from the lowest mode of K; if that mode deforms
/// the model, K has a negative direction or a contrast beyond double precision.
fn diagnose_mechanism(
    model: &Model,
    map: &DofMap,
    k: &SparseMatrix,
    symbolic: &SymbolicFactor,
    par: Parallelism,
) -> FemError {
    classify(model, map, k, None, symbolic, par).error()
}

/// Diagonal of the nodes' bounding box, mm (1 if all nodes coincide): converts rotations to
/// comparable displacements.
fn model_size(model: &Model) -> f64 {
    let mut lo = [f64::INFINITY; 3];
    let mut hi = [f64::NEG_INFINITY; 3];
    for x in &model.nodes {
        for c in 0..3 {
            lo[c] = lo[c].min(x[c]);
            hi[c] = hi[c].max(x[c]);
        }
    }
    let s = (0..3).map(|c| (hi[c] - lo[c]).powi(2)).sum::<f64>().sqrt();
    if s > 0.0 && s.is_finite() {
        s
    } else {
        1.0
    }
}
