//! Geometrically nonlinear statics (large displacements and rotations, small strains):
//! co-rotational beams and flexibility elements ([`super::corot`]), Newton–Raphson with load
//! (and prescribed-displacement) stepping, automatic step cutting, and Crisfield's arc-length
//! method for limit points (M. A. Crisfield, "A fast incremental/iterative solution procedure
//! that handles snap-through", Computers & Structures 13 (1981) 55–62; cylindrical form).
//!
//! Kinematics of the nodes: translations are additive, rotations are rotation matrices updated
//! multiplicatively, Rᵢ ← exp([δwᵢ×])Rᵢ, with the spatial spin δwᵢ (global components) as the
//! rotational increment. The equations are numbered by the linear [`DofMap`]; its maps act on
//! *increments*:
//!
//! * framed nodes (skew supports, sliders): increments in the node frame, d = F·d_local —
//!   exact, the frame is fixed;
//! * ties: equal increments of coincident nodes — exact for tied translations and for ties of
//!   all three rotations; a partial rotation tie (a revolute joint) equates spin components
//!   about the fixed frame axes, which is exact only while the joint axis does not rotate
//!   (approximation);
//! * rigid links: slave position x_s = x_m + R_m·(X_s − X_m) and R_s = R_m, **exact** for any
//!   finite rotation of the master; the arm in the increment map is the current one,
//!   δu_s = δu_m + δw_m × (R_m a₀), and the link's geometric stiffness [F_s×][a×] (from the
//!   rotating arm) is added to the master;
//! * springs: linear in the translations and the nodal rotation vectors, axes fixed
//!   (approximation: exact for small rotations of the spring's nodes only).
//!
//! Loads are fixed in space (no follower forces). The reported rotation of a node is its
//! rotation vector log(R) (|θ| ≤ π).
//!
//! Acceptance and stability:
//!
//! * a Newton iteration converges when its residual is below the tolerance relative to the
//!   applied load and the internal forces (reactions) of the last converged state — a scale
//!   fixed for the step, which a wandering iterate cannot inflate — plus a round-off floor from
//!   the stiffest element; every returned state is checked once more for nodal and global
//!   equilibrium (forces and moments at the deformed positions) to 1e-6 of the applied load,
//!   otherwise the solve fails naming the step;
//! * the tangent is the consistent one: non-symmetric (sparse LU) where moments are applied
//!   ([`Tangent`]), so Newton stays quadratic and the answer objective; symmetric (sparse
//!   Cholesky) elsewhere;
//! * the load step adapts (cut on failure, on a node rotating more than
//!   [`MAX_STEP_ROTATION`] in a step, on an increment [`MAX_JUMP`] times its predictor, on an
//!   iteration crossing an indefinite tangent; shrunk after slow and grown after fast steps),
//!   with caps on cuts and steps so a failing case stops quickly;
//! * each converged point is stable when the symmetric tangent of the reduced system is
//!   positive definite (Cholesky succeeds with every pivot above
//!   [`super::analysis::PIVOT_TOL`] of its diagonal) and it was reached without a jump; the
//!   first loss is bracketed by the load factors of the last stable and first unstable
//!   points. With applied moments this is the static (divergence) criterion on the symmetric
//!   part only.

use super::analysis::prescribed_dofs;
use super::constraints::{frame_block, DofMap, NONE};
use super::corot::{self, CorotGeometry, NodeState};
use super::dof::NodeDof;
use super::error::FemError;
use super::model::{Beam, Element, FlexElement, LoadCase, Model};
use super::recovery::CaseResult;
use super::recovery::{self, ElementResult, Statics};
use super::solve::{Factor, LuPattern, Parallelism, SparsePattern, SymbolicFactor};
use super::transform::{rigid_arm, skew, Mat12};
use nalgebra::{Matrix3, Matrix6, SMatrix, Vector3, Vector6};

/// Options of the nonlinear solver.
#[derive(Debug, Clone, PartialEq)]
pub struct NonlinearOptions {
    /// Number of equal load steps from λ = 0 to 1 (≥ 1). With arc length: the first step's
    /// load increment is 1/steps, which fixes the arc length.
    pub steps: usize,
    /// Newton iterations per step before the step is cut.
    pub max_iterations: usize,
    /// Residual tolerance, relative to the step's force scale: the larger of the applied loads
    /// (λ f) and the internal forces of the last converged state carried into the step
    /// (reactions included), Euclidean norms over the equations. The scale is fixed for the
    /// step, so it cannot grow with the error of a wandering iterate.
    pub tol_residual: f64,
    /// Energy tolerance: |δqₖ₋₁·rₖ| relative to |δq₀·r₀| of the step.
    pub tol_energy: f64,
    /// How many times a step may be halved (in a row) before the solve fails.
    pub max_cuts: usize,
    /// Step cuts allowed over the whole load case (so a failing case stops quickly).
    pub max_total_cuts: usize,
    /// Which tangent the Newton iterations factorise.
    pub tangent: Tangent,
    /// Crisfield's (cylindrical) arc-length control instead of load control. Only for cases
    /// without non-zero prescribed displacements.
    pub arc_length: bool,
    /// DOFs whose values are recorded along the path (translations in mm; rotations: the
    /// rotation-vector component, rad; global axes).
    pub track: Vec<NodeDof>,
    /// Threading of the sparse factorisation.
    pub parallelism: Parallelism,
}

impl Default for NonlinearOptions {
    fn default() -> Self {
        NonlinearOptions {
            steps: 20,
            max_iterations: 30,
            tol_residual: 1e-8,
            tol_energy: 1e-12,
            max_cuts: 12,
            max_total_cuts: 60,
            tangent: Tangent::Auto,
            arc_length: false,
            track: Vec::new(),
            parallelism: Parallelism::Sequential,
        }
    }
}

/// The tangent stiffness of the Newton iterations.
///
/// With the spatial spin as rotational increment, the consistent tangent is not symmetric
/// away from equilibrium, and at equilibrium its skew part is ½[M×] at every node carrying an
/// applied moment M (the moment of loads fixed in space does not derive from a potential in
/// the spin variables). Symmetrising it (Cholesky) keeps Newton quadratic only where no
/// moment is applied; under large moments not about a fixed axis the symmetrised iteration
/// converges slowly or not at all. The non-symmetric tangent needs a sparse LU.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum Tangent {
    /// Non-symmetric (LU) where the load case applies moments (directly, or as forces on
    /// rigid-link slaves, which load their master with a moment); symmetric (Cholesky)
    /// otherwise.
    #[default]
    Auto,
    /// Always the symmetric part (sparse Cholesky; LU only for indefinite tangents).
    Symmetric,
    /// Always the consistent non-symmetric tangent (sparse LU).
    Full,
}

/// One converged point of the equilibrium path.
#[derive(Debug, Clone, PartialEq)]
pub struct PathPoint {
    /// Load factor λ (loads and prescribed displacements are λ times the case's values).
    pub lambda: f64,
    /// Values of [`NonlinearOptions::track`] at λ.
    pub values: Vec<f64>,
    /// Whether the symmetric tangent stiffness of the reduced system is positive definite at
    /// this point (a stable equilibrium against static perturbations), and the step reaching
    /// it stayed on a continuous stable path (no jump over a limit point).
    pub stable: bool,
    /// Euclidean norms of the residual at each Newton iteration of the step that reached this
    /// point (N and N·mm mixed, as the equations), the last one converged: the iteration log.
    pub residuals: Vec<f64>,
}

/// Result of one load case.
#[derive(Debug, Clone, PartialEq)]
pub struct NonlinearCase {
    /// Final state in the linear result's shape: `displacements` per node = [ux, uy, uz (mm),
    /// rotation vector (rad)], global; reactions (global, at the deformed configuration);
    /// per-element end forces and section forces in the element's *deformed* (co-rotated)
    /// local frame, with stresses; statics about the origin at the deformed positions.
    pub fe: CaseResult,
    /// Final nodal rotation matrices (rows of R, global).
    pub rotations: Vec<[[f64; 3]; 3]>,
    /// Converged path, starting at λ = 0.
    pub path: Vec<PathPoint>,
    /// Newton iterations over all converged steps.
    pub iterations: usize,
    /// Converged steps.
    pub steps: usize,
    /// Step cuts (halvings) that were needed.
    pub cuts: usize,
    /// Whether every converged point of the path was stable ([`PathPoint::stable`]).
    pub stable: bool,
    /// When not stable: the load factors [lo, hi] between which stability was first lost (lo
    /// the last stable converged point, hi the first unstable one or the end of a jump).
    pub critical_load_factor: Option<[f64; 2]>,
    /// Co-rotated frame of each beam/flexibility element at the end (rows: local x, y, z in
    /// global coordinates; identity for springs).
    pub element_frames: Vec<[[f64; 3]; 3]>,
}

/// Results of all load cases, in model order.
#[derive(Debug, Clone, PartialEq)]
pub struct NonlinearResults {
    pub load_cases: Vec<NonlinearCase>,
}

/// Solves every load case of the model with geometric nonlinearity. Each case starts from the
/// undeformed configuration.
pub fn solve_nonlinear(model: &Model, opts: &NonlinearOptions) -> Result<NonlinearResults, FemError> {
    model.validate()?;
    if opts.steps == 0 || opts.max_iterations == 0 {
        return Err(FemError::BadInput(
            "nonlinear options: steps and max_iterations must be at least 1".into(),
        ));
    }
    let elems = element_data(model)?;
    let load_cases = model
        .load_cases
        .iter()
        .map(|case| solve_case(model, &elems, case, opts))
        .collect::<Result<Vec<_>, _>>()?;
    Ok(NonlinearResults { load_cases })
}

/// Precomputed element data.
#[derive(Debug, Clone)]
enum ElemData {
    Corot {
        nodes: [usize; 2],
        geom: CorotGeometry,
        k_local: Box<Mat12>,
    },
    Spring {
        nodes: [usize; 2],
        n_nodes: usize,
        b: Box<SMatrix<f64, 6, 12>>,
        k: [f64; 6],
    },
}

fn element_data(model: &Model) -> Result<Vec<ElemData>, FemError> {
    (0..model.elements.len())
        .map(|ie| match &model.elements[ie] {
            Element::Shell4(_) => Err(FemError::BadInput(format!(
                "element {ie} is a shell: the geometrically nonlinear solver handles beams, flexibility elements (hinges) and springs"
            ))),
            Element::Spring(s) => {
                let (b, k, n) = model.spring_b(ie)?;
                Ok(ElemData::Spring {
                    nodes: [s.a, s.b.unwrap_or(s.a)],
                    n_nodes: n,
                    b: Box::new(b),
                    k,
                })
            }
            Element::Beam(Beam { nodes, .. }) | Element::Flex(FlexElement { nodes, .. }) => {
                let nodes = *nodes;
                let (lam, l) = model.element_frame(ie)?;
                let (k_local, _) = model.element_local(ie)?;
                Ok(ElemData::Corot {
                    nodes,
                    geom: CorotGeometry {
                        x1: Vector3::from(model.nodes[nodes[0]]),
                        x2: Vector3::from(model.nodes[nodes[1]]),
                        r0: lam.transpose(),
                        l0: l,
                    },
                    k_local: Box::new(k_local),
                })
            }
        })
        .collect()
}

/// Nodal state: translations and rotation matrices.
#[derive(Debug, Clone)]
struct State {
    u: Vec<Vector3<f64>>,
    r: Vec<Matrix3<f64>>,
}

/// Everything fixed for one load case.
struct CaseCtx<'a> {
    model: &'a Model,
    elems: &'a [ElemData],
    map: DofMap,
    /// Initial arm X_s − X_m of each slave (zero for independent nodes).
    arm0: Vec<Vector3<f64>>,
    /// Applied loads (6 per node, global).
    f_ext: Vec<f64>,
    /// Prescribed values (6 per node; local for framed nodes).
    u_c: Vec<f64>,
    pattern: SparsePattern,
    symbolic: SymbolicFactor,
    /// Lower-triangle pairs of `pattern` (for the LU of an indefinite symmetric tangent).
    lower_pairs: Vec<(usize, usize)>,
    /// Both triangles of `pattern`, built on first need.
    mirror: std::cell::OnceCell<Result<LuPattern, String>>,
    /// Pattern of the full non-symmetric tangent when the Newton iterations use it.
    full: Option<LuPattern>,
    /// Round-off floor of the residual, N (N·mm): the co-rotated frames and deformations come
    /// from nodal positions and rotations, so a balanced state's residual is ~ε times the
    /// stiffest element's force at unit relative error (EA, and 4EI/L per radian); 1e-13 of
    /// it leaves a margin of ~50 ε.
    round: f64,
    /// Master nodes of rigid links (their 6×6 blocks carry the link geometric stiffness).
    masters: Vec<usize>,
    par: Parallelism,
}

/// Residual, tangent values and force norms at one configuration.
struct Eval {
    /// Reduced residual r = f_int − λ f_ext (equations).
    r: Vec<f64>,
    /// Tangent triplet values in pattern order (lower triangle of the symmetric part, or the
    /// full non-symmetric tangent in the full pattern's order).
    values: Vec<f64>,
    /// ‖λ f_ext‖ carried to the independent nodes.
    load: f64,
    /// ‖f_int‖ carried to the independent nodes (constrained DOFs included: the reactions).
    internal: f64,
}

/// Which tangent [`CaseCtx::evaluate`] assembles.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
enum Assemble {
    None,
    /// Lower triangle of the symmetric part.
    Symmetric,
    /// The consistent non-symmetric tangent.
    Full,
}

/// Linear solution of one Newton/arc-length iteration.
struct Solution {
    x: Vec<Vec<f64>>,
    /// Whether the symmetric tangent was positive definite (`None` when the full tangent was
    /// factorised by LU and definiteness is unknown).
    positive_definite: Option<bool>,
}

fn fail(case: &str, step: usize, lambda: f64, residual: f64, reason: impl Into<String>) -> FemError {
    FemError::NonConvergence {
        case: case.to_string(),
        step,
        lambda,
        residual,
        reason: reason.into(),
    }
}

impl CaseCtx<'_> {
    fn n_eq(&self) -> usize {
        self.map.n_eq()
    }

    /// Current 6×6 increment map of each node onto its independent node (None = identity).
    fn arms(&self, st: &State) -> Vec<Option<Matrix6<f64>>> {
        let map = &self.map;
        (0..self.model.nodes.len())
            .map(|n| {
                let m = map.rep[n];
                if m == n {
                    map.arm[n]
                } else {
                    let mut a = rigid_arm(&(st.r[m] * self.arm0[n]));
                    if let Some(f) = self.model.frames.get(&m) {
                        a *= frame_block(f);
                    }
                    Some(a)
                }
            })
            .collect()
    }

    /// Full per-node vector carried to the independent nodes with the current arms, ties
    /// folded onto their roots.
    fn to_independent(&self, arms: &[Option<Matrix6<f64>>], v: &[f64]) -> Vec<f64> {
        let mut out = vec![0.0; v.len()];
        for (n, arm) in arms.iter().enumerate() {
            let m = self.map.rep[n];
            let vn = Vector6::from_column_slice(&v[6 * n..6 * n + 6]);
            let t = match arm {
                Some(a) => a.transpose() * vn,
                None => vn,
            };
            for d in 0..6 {
                out[6 * m + d] += t[d];
            }
        }
        for &(g, root) in &self.map.alias {
            out[root] += out[g];
            out[g] = 0.0;
        }
        out
    }

    /// Slaves follow their masters exactly.
    fn update_slaves(&self, st: &mut State) {
        for n in 0..self.model.nodes.len() {
            let m = self.map.rep[n];
            if m != n {
                st.u[n] = st.u[m] + st.r[m] * self.arm0[n] - self.arm0[n];
                st.r[n] = st.r[m];
            }
        }
    }

    /// Applies equation increments `q` and constrained increments `dc` (6 per node, node
    /// frame for framed nodes; read at constrained DOFs only).
    fn apply(&self, st: &mut State, q: &[f64], dc: Option<&[f64]>) {
        let map = &self.map;
        let nd = 6 * self.model.nodes.len();
        let mut d = vec![0.0; nd];
        if let Some(dc) = dc {
            for &g in &map.constrained {
                d[g] = dc[g];
            }
        }
        for (i, &g) in map.eq_dof.iter().enumerate() {
            d[g] = q[i];
        }
        for &(g, root) in &map.alias {
            d[g] = d[root];
        }
        for n in 0..self.model.nodes.len() {
            if map.rep[n] != n {
                continue;
            }
            let mut v = Vector6::from_column_slice(&d[6 * n..6 * n + 6]);
            if let Some(a) = &map.arm[n] {
                v = a * v;
            }
            st.u[n] += Vector3::new(v[0], v[1], v[2]);
            let w = Vector3::new(v[3], v[4], v[5]);
            if w != Vector3::zeros() {
                st.r[n] = corot::rot_exp(&w) * st.r[n];
            }
        }
        self.update_slaves(st);
    }

    fn node_state(st: &State, n: usize) -> NodeState {
        NodeState { u: st.u[n], r: st.r[n] }
    }

    /// Element internal forces (global, on its nodes) and tangents.
    fn element_response(&self, st: &State, ie: usize, tangent: bool) -> Option<([usize; 2], usize, Mat12, [f64; 12])> {
        match &self.elems[ie] {
            ElemData::Corot { nodes, geom, k_local } => {
                let r = corot::response(
                    geom,
                    k_local,
                    &Self::node_state(st, nodes[0]),
                    &Self::node_state(st, nodes[1]),
                    tangent,
                )?;
                Some((*nodes, 2, r.k, std::array::from_fn(|i| r.f[i])))
            }
            ElemData::Spring { nodes, n_nodes, b, k } => {
                let mut d = SMatrix::<f64, 12, 1>::zeros();
                for (s, &n) in nodes.iter().enumerate().take(*n_nodes) {
                    let rv = corot::rot_log(&st.r[n]);
                    for j in 0..3 {
                        d[6 * s + j] = st.u[n][j];
                        d[6 * s + 3 + j] = rv[j];
                    }
                }
                let kd = Matrix6::from_diagonal(&Vector6::from(*k));
                let km = b.transpose() * kd * **b;
                let f = km * d;
                Some((*nodes, *n_nodes, km, std::array::from_fn(|i| f[i])))
            }
        }
    }

    /// The tangent the Newton iterations use.
    fn newton_tangent(&self) -> Assemble {
        if self.full.is_some() {
            Assemble::Full
        } else {
            Assemble::Symmetric
        }
    }

    /// Residual, tangent and force norms at load factor `lambda`.
    fn evaluate(&self, st: &State, lambda: f64, mode: Assemble) -> Option<Eval> {
        let tangent = mode != Assemble::None;
        let sym = mode == Assemble::Symmetric;
        let nn = self.model.nodes.len();
        let arms = self.arms(st);
        let mut f_int = vec![0.0; 6 * nn];
        let mut mats = Vec::with_capacity(self.elems.len());
        for ie in 0..self.elems.len() {
            let (nodes, n_nodes, k, f) = self.element_response(st, ie, tangent)?;
            for s in 0..n_nodes {
                for d in 0..6 {
                    f_int[6 * nodes[s] + d] += f[6 * s + d];
                }
            }
            mats.push((nodes, n_nodes, k));
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
        let mut values = Vec::with_capacity(self.pattern.n_triplets());
        if tangent {
            for (nodes, n_nodes, k) in &mats {
                let mut t = Mat12::identity();
                let mut any = false;
                for s in 0..*n_nodes {
                    if let Some(a) = &arms[nodes[s]] {
                        t.fixed_view_mut::<6, 6>(6 * s, 6 * s).copy_from(a);
                        any = true;
                    }
                }
                let ks = if sym { (k + k.transpose()) * 0.5 } else { *k };
                let kp = if any { t.transpose() * ks * t } else { ks };
                let reps = [self.map.rep[nodes[0]], self.map.rep[nodes[1]]];
                let eqs = self.map.element_eqs(reps, *n_nodes);
                for_each_pair_in(sym, &eqs, 6 * n_nodes, |a, b, _, _| values.push(kp[(a, b)]));
            }
            // Rigid links: δ(a × F_s) = [F_s×][a×] δw_m (a = R_m a₀), symmetrised for Cholesky.
            for &m in &self.masters {
                let mut g = Matrix3::zeros();
                for n in 0..nn {
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
            if values.iter().any(|v| !v.is_finite()) {
                return None;
            }
        }
        Some(Eval {
            r,
            values,
            load,
            internal,
        })
    }

    /// Solves K x = b for several right-hand sides with the tangent of [`Self::evaluate`] in
    /// the Newton mode: the full tangent by sparse LU, or the symmetric one by sparse Cholesky
    /// and, when that is not positive definite (past a limit point, near a bifurcation), by
    /// sparse LU.
    fn solve(&self, values: &[f64], rhs: &[Vec<f64>]) -> Result<Solution, String> {
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
    /// positive definite (a pivot at or below [`super::analysis::PIVOT_TOL`] of its diagonal).
    fn cholesky(&self, values: &[f64]) -> Result<Option<Factor>, String> {
        let k = self.pattern.matrix(values).map_err(|e| e.to_string())?;
        let Ok(f) = Factor::new(&self.symbolic, &k, self.par) else {
            return Ok(None);
        };
        let diag = k.diagonal();
        let ok = f
            .pivots()
            .iter()
            .zip(&diag)
            .all(|(p, d)| p.is_finite() && *p > super::analysis::PIVOT_TOL * d);
        Ok(ok.then_some(f))
    }

    /// Whether the symmetric tangent at `st` is positive definite.
    fn positive_definite(&self, st: &State, lambda: f64) -> bool {
        self.evaluate(st, lambda, Assemble::Symmetric)
            .and_then(|ev| self.cholesky(&ev.values).ok())
            .is_some_and(|f| f.is_some())
    }

    fn tracked(&self, st: &State, track: &[NodeDof]) -> Vec<f64> {
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
fn norm(v: &[f64]) -> f64 {
    let m = v.iter().fold(0.0f64, |a, x| a.max(x.abs()));
    if m == 0.0 || !m.is_finite() {
        return m;
    }
    m * v.iter().map(|x| (x / m) * (x / m)).sum::<f64>().sqrt()
}

fn dot(a: &[f64], b: &[f64]) -> f64 {
    a.iter().zip(b).map(|(x, y)| x * y).sum()
}

/// Same pair order as [`super::assembly`]: lower-triangle pairs of free DOFs, a-major.
#[inline]
fn for_each_pair(eqs: &[usize; 12], n: usize, mut f: impl FnMut(usize, usize, usize, usize)) {
    for a in 0..n {
        let ea = eqs[a];
        if ea == NONE {
            continue;
        }
        for (b, &eb) in eqs.iter().enumerate().take(n) {
            if eb != NONE && ea >= eb {
                f(a, b, ea, eb);
            }
        }
    }
}

/// [`for_each_pair`] (`lower`) or every pair of free DOFs (the full non-symmetric pattern).
#[inline]
fn for_each_pair_in(lower: bool, eqs: &[usize; 12], n: usize, mut f: impl FnMut(usize, usize, usize, usize)) {
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

/// Outcome of a failed step (for the error message).
struct StepFail {
    residual: f64,
    reason: String,
}

/// A converged Newton step.
struct NewtonOk {
    iterations: usize,
    /// Definiteness of the last factorised tangent after the first correction (a state within
    /// one quadratically converging correction of the converged one); `None` when unknown
    /// (full LU, or converged after one correction).
    positive_definite: Option<bool>,
    /// Whether some iteration met an indefinite symmetric tangent.
    met_indefinite: bool,
    /// Norm of the first correction (the tangent predictor of the step) and of the sum of all.
    first: f64,
    total: f64,
    /// Residual norm per iteration.
    residuals: Vec<f64>,
    /// ‖f_int‖ at the converged state.
    internal: f64,
}

/// Acceptance bound of a Newton iteration: `tol` relative to the step's force scale (the
/// applied load at the step's λ and the internal forces — reactions — of the last converged
/// state), plus the model's round-off floor [`CaseCtx::round`].
fn bound(ctx: &CaseCtx, tol: f64, scale: f64) -> f64 {
    tol * scale + ctx.round
}

/// Newton iterations at fixed λ from the current state.
/// `converged_internal`: ‖f_int‖ (reactions included) of the last converged state.
fn newton(
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

fn solve_case(
    model: &Model,
    elems: &[ElemData],
    case: &LoadCase,
    opts: &NonlinearOptions,
) -> Result<NonlinearCase, FemError> {
    model.validate_case(case)?;
    let prescribed = prescribed_dofs(case);
    let map = DofMap::new(model, &prescribed, Some(&case.name))?;
    let nn = model.nodes.len();
    let arm0: Vec<Vector3<f64>> = (0..nn)
        .map(|n| Vector3::from(model.nodes[n]) - Vector3::from(model.nodes[map.rep[n]]))
        .collect();
    let mut f_ext = vec![0.0; 6 * nn];
    for l in &case.forces {
        for d in 0..6 {
            f_ext[6 * l.node + d] += l.f[d];
        }
    }
    let mut u_c = vec![0.0; 6 * nn];
    for p in &case.displacements {
        u_c[6 * p.node + p.dof.index()] = p.value;
    }
    let mut masters: Vec<usize> = model.rigid_links.iter().map(|l| l.master).collect();
    masters.sort_unstable();
    masters.dedup();
    // Pattern: element pairs, master blocks, one diagonal slot per equation.
    let n_eq = map.n_eq();
    let pairs_of = |lower: bool| {
        let mut pairs = Vec::new();
        for e in elems {
            let (nodes, nn_e) = match e {
                ElemData::Corot { nodes, .. } => (*nodes, 2),
                ElemData::Spring { nodes, n_nodes, .. } => (*nodes, *n_nodes),
            };
            let eqs = map.element_eqs([map.rep[nodes[0]], map.rep[nodes[1]]], nn_e);
            for_each_pair_in(lower, &eqs, 6 * nn_e, |_, _, r, c| pairs.push((r, c)));
        }
        for &m in &masters {
            let eqs = map.element_eqs([m, m], 1);
            for_each_pair_in(lower, &eqs, 6, |_, _, r, c| pairs.push((r, c)));
        }
        pairs.extend((0..n_eq).map(|i| (i, i)));
        pairs
    };
    let pairs = pairs_of(true);
    let pattern = SparsePattern::new(n_eq, &pairs)?;
    let symbolic = SymbolicFactor::new(&pattern)?;
    // Moments applied at independent nodes, or forces on rigid-link slaves (a moment on the
    // master): the tangent's skew part survives at equilibrium ([`Tangent`]).
    let moments = (0..nn).any(|n| {
        let f = &f_ext[6 * n..6 * n + 6];
        f[3..].iter().any(|v| *v != 0.0) || (map.rep[n] != n && f[..3].iter().any(|v| *v != 0.0))
    });
    let full = match opts.tangent {
        Tangent::Full => true,
        Tangent::Symmetric => false,
        Tangent::Auto => moments,
    };
    let full = if full {
        Some(LuPattern::new(n_eq, &pairs_of(false))?)
    } else {
        None
    };
    let ctx = CaseCtx {
        model,
        elems,
        map,
        arm0,
        f_ext,
        u_c,
        pattern,
        symbolic,
        lower_pairs: pairs,
        mirror: std::cell::OnceCell::new(),
        round: 1e-14
            * elems
                .iter()
                .map(|e| match e {
                    ElemData::Corot { geom, k_local, .. } => {
                        let k = |i: usize| k_local[(i, i)].abs();
                        (0..3).map(k).fold(0.0, f64::max) * geom.l0 + (3..6).map(k).fold(0.0, f64::max)
                    }
                    ElemData::Spring { k, .. } => k.iter().fold(0.0f64, |m, v| m.max(v.abs())),
                })
                .fold(0.0, f64::max),
        full,
        masters,
        par: opts.parallelism,
    };
    let mut st = State {
        u: vec![Vector3::zeros(); nn],
        r: vec![Matrix3::identity(); nn],
    };
    let mut path = vec![PathPoint {
        lambda: 0.0,
        values: ctx.tracked(&st, &opts.track),
        stable: true,
        residuals: Vec::new(),
    }];
    let has_prescribed = ctx.u_c.iter().any(|&v| v != 0.0);
    let mut stab = Stability::default();
    let (iterations, steps, cuts, lambda) = if opts.arc_length {
        if has_prescribed {
            return Err(FemError::LoadCase {
                case: case.name.clone(),
                reason: "arc-length control needs a load-controlled case (no non-zero prescribed displacements)".into(),
            });
        }
        arc_length(&ctx, &mut st, opts, &case.name, &mut path, &mut stab)?
    } else {
        load_control(&ctx, &mut st, 0.0, opts, &case.name, &mut path, 0, &mut stab)?
    };
    let mut out = finish(&ctx, &st, &case.name, lambda, path, iterations, steps, cuts)?;
    out.stable = stab.bracket.is_none();
    out.critical_load_factor = stab.bracket;
    Ok(out)
}

/// Largest rotation of a node within one accepted step, rad: larger converged increments
/// are cut, since a Newton iteration started that far from the solution can land on another
/// branch of the equilibrium path.
const MAX_STEP_ROTATION: f64 = 0.5;

/// A converged step whose increment exceeds its tangent predictor this many times has
/// jumped (over a limit point, or onto another branch) and is cut.
const MAX_JUMP: f64 = 4.0;

/// Halvings of the load step before a step that still jumps is accepted as a real
/// discontinuity of the path (snap-through) and flagged unstable.
const JUMP_CUTS: u32 = 6;

/// Stability along the path: the first loss, bracketed by load factors.
#[derive(Debug, Default)]
struct Stability {
    bracket: Option<[f64; 2]>,
}

impl Stability {
    fn record(&mut self, lambda_prev: f64, lambda: f64, stable: bool) {
        if !stable && self.bracket.is_none() {
            self.bracket = Some([lambda_prev.min(lambda), lambda_prev.max(lambda)]);
        }
    }
}

/// Largest rotation between two states' nodal rotations, rad.
fn max_rotation_change(a: &State, b: &State) -> f64 {
    a.r.iter()
        .zip(&b.r)
        .map(|(ra, rb)| corot::rot_log(&(rb * ra.transpose())).norm())
        .fold(0.0, f64::max)
}

/// Load (and prescribed-displacement) control from `lambda0` to 1. The load step starts at
/// 1/steps (its largest value) and adapts: halved when Newton fails, when the converged
/// increment rotates a node by more than [`MAX_STEP_ROTATION`] or exceeds [`MAX_JUMP`] times
/// its tangent predictor, or when an iteration met an indefinite tangent between two stable
/// states (a jump over an unstable stretch); halved for the next step after a slow one (≥ 12
/// iterations), doubled back after a fast one (≤ 4). Every converged point is checked for
/// stability (positive definite symmetric tangent). Returns (iterations, steps, cuts, λ).
#[allow(clippy::too_many_arguments)]
fn load_control(
    ctx: &CaseCtx,
    st: &mut State,
    lambda0: f64,
    opts: &NonlinearOptions,
    name: &str,
    path: &mut Vec<PathPoint>,
    step0: usize,
    stab: &mut Stability,
) -> Result<(usize, usize, usize, f64), FemError> {
    let dl0 = 1.0 / opts.steps as f64;
    let dl_jump = dl0 / f64::from(1u32 << JUMP_CUTS);
    let dl_min = dl0 * 0.5f64.powi(opts.max_cuts.min(60) as i32);
    // Steps allowed: the nominal count 10 times over (slow convergence halves the step).
    let max_steps = 10 * opts.steps.max(10);
    let mut dl = dl0;
    let mut lambda = lambda0;
    let mut prev_stable = path.last().is_none_or(|p| p.stable);
    let mut internal = ctx.evaluate(st, lambda0, Assemble::None).map_or(0.0, |ev| ev.internal);
    let (mut iterations, mut steps, mut cuts, mut cut_run) = (0, 0, 0, 0);
    while lambda < 1.0 - 1e-12 {
        let target = if lambda + dl > 1.0 - 1e-9 { 1.0 } else { lambda + dl };
        let saved = st.clone();
        let dc: Vec<f64> = ctx.u_c.iter().map(|v| v * (target - lambda)).collect();
        ctx.apply(st, &vec![0.0; ctx.n_eq()], Some(&dc));
        let outcome = newton(ctx, st, target, opts, internal).and_then(|nk| {
            let pd = match nk.positive_definite {
                Some(p) => p,
                None => ctx.positive_definite(st, target),
            };
            let rot = max_rotation_change(&saved, st);
            let jump = nk.first > 0.0 && nk.total > MAX_JUMP * nk.first;
            let crossed = prev_stable && pd && nk.met_indefinite;
            let suspicious = rot > MAX_STEP_ROTATION || jump || crossed;
            if suspicious && dl > dl_jump * (1.0 + 1e-9) {
                let why = if rot > MAX_STEP_ROTATION {
                    format!("a node rotates {rot:.3} rad in one step")
                } else if jump {
                    format!("the increment is {:.1}× its tangent predictor", nk.total / nk.first)
                } else {
                    "the iterations crossed an indefinite tangent".to_string()
                };
                return Err(StepFail {
                    residual: nk.residuals.last().copied().unwrap_or(f64::NAN),
                    reason: format!("step too large: {why}"),
                });
            }
            Ok((nk, pd && !suspicious))
        });
        match outcome {
            Ok((nk, stable)) => {
                iterations += nk.iterations;
                steps += 1;
                internal = nk.internal;
                stab.record(lambda, target, stable);
                lambda = target;
                cut_run = 0;
                prev_stable = stable;
                path.push(PathPoint {
                    lambda,
                    values: ctx.tracked(st, &opts.track),
                    stable,
                    residuals: nk.residuals,
                });
                if dl < dl0 && nk.iterations <= 4 {
                    dl = (dl * 2.0).min(dl0);
                } else if nk.iterations >= 12 && dl * 0.5 >= dl_min {
                    dl *= 0.5;
                    cuts += 1;
                }
                if steps > max_steps || cuts > opts.max_total_cuts {
                    return Err(fail(
                        name,
                        step0 + steps,
                        lambda,
                        path.last().and_then(|p| p.residuals.last()).copied().unwrap_or(f64::NAN),
                        format!("{steps} load steps and {cuts} step cuts (Δλ = {dl:.3e}) without reaching λ = 1: Newton converges too slowly"),
                    ));
                }
            }
            Err(f) => {
                *st = saved;
                cuts += 1;
                cut_run += 1;
                dl *= 0.5;
                if cut_run > opts.max_cuts || cuts > opts.max_total_cuts || dl < dl_min * (1.0 - 1e-9) {
                    let lost = match stab.bracket {
                        Some([lo, hi]) => format!(" (the path already lost stability between λ = {lo:.4} and {hi:.4})"),
                        None => String::new(),
                    };
                    let hint = if lambda > 0.0 {
                        format!("; no equilibrium found just beyond λ = {lambda:.6}: a limit point (snap-through) or a bifurcation is likely there{lost}; arc-length control can follow a limit point")
                    } else {
                        String::new()
                    };
                    return Err(fail(
                        name,
                        step0 + steps + 1,
                        lambda,
                        f.residual,
                        format!(
                            "{} after {} step cuts ({} in a row; last step Δλ = {:.3e}){hint}",
                            f.reason,
                            cuts - 1,
                            cut_run - 1,
                            2.0 * dl
                        ),
                    ));
                }
            }
        }
    }
    Ok((iterations, steps, cuts, lambda))
}

/// Crisfield's cylindrical arc length (ψ = 0) until λ reaches 1; the last piece is load
/// controlled so the path ends at λ = 1 exactly.
fn arc_length(
    ctx: &CaseCtx,
    st: &mut State,
    opts: &NonlinearOptions,
    name: &str,
    path: &mut Vec<PathPoint>,
    stab: &mut Stability,
) -> Result<(usize, usize, usize, f64), FemError> {
    let arms = ctx.arms(st);
    let f_red_full = ctx.to_independent(&arms, &ctx.f_ext);
    let f_red: Vec<f64> = ctx.map.eq_dof.iter().map(|&g| f_red_full[g]).collect();
    let mut lambda = 0.0;
    let (mut iterations, mut steps, mut cuts) = (0usize, 0usize, 0usize);
    let mut prev: Option<Vec<f64>> = None;
    let mut dl_arc = 0.0;
    let mut cut_run = 0;
    let max_steps = 50 * opts.steps.max(10);
    while steps < max_steps {
        let saved = st.clone();
        let ev = ctx
            .evaluate(st, lambda, ctx.newton_tangent())
            .ok_or_else(|| fail(name, steps + 1, lambda, f64::NAN, "degenerate configuration"))?;
        let scale = ev.internal.max(ev.load);
        let dt = ctx
            .solve(&ev.values, std::slice::from_ref(&f_red))
            .map_err(|r| fail(name, steps + 1, lambda, norm(&ev.r), r))?
            .x
            .remove(0);
        let dtn = norm(&dt);
        if !(dtn > 0.0 && dtn.is_finite()) {
            return Err(fail(name, steps + 1, lambda, norm(&ev.r), "no load to follow"));
        }
        if dl_arc == 0.0 {
            dl_arc = dtn / opts.steps as f64;
        }
        let sign = match &prev {
            Some(p) if dot(p, &dt) < 0.0 => -1.0,
            _ => 1.0,
        };
        let dlam = sign * dl_arc / dtn;
        if lambda + dlam >= 1.0 - 1e-12 {
            let (it, s, c, l) = load_control(ctx, st, lambda, &one_step(opts), name, path, steps, stab)?;
            return Ok((iterations + it, steps + s, cuts + c, l));
        }
        // Predictor.
        let mut dq: Vec<f64> = dt.iter().map(|v| v * dlam).collect();
        ctx.apply(st, &dq, None);
        let mut lam = lambda + dlam;
        let mut ok = None;
        let mut last_res = f64::NAN;
        let mut residuals = Vec::new();
        let mut pd = None;
        for it in 1..=opts.max_iterations {
            let Some(ev) = ctx.evaluate(st, lam, ctx.newton_tangent()) else {
                break;
            };
            let rn = norm(&ev.r);
            last_res = rn;
            residuals.push(rn);
            let scale = scale.max(ev.load);
            if rn <= bound(ctx, opts.tol_residual, scale) || scale == 0.0 && ev.internal == 0.0 {
                ok = Some(it);
                break;
            }
            let neg: Vec<f64> = ev.r.iter().map(|v| -v).collect();
            let Ok(sol) = ctx.solve(&ev.values, &[neg, f_red.clone()]) else {
                break;
            };
            pd = sol.positive_definite;
            let sol = sol.x;
            let (dr, dtt) = (&sol[0], &sol[1]);
            let s: Vec<f64> = dq.iter().zip(dr).map(|(a, b)| a + b).collect();
            let a = dot(dtt, dtt);
            let b = 2.0 * dot(dtt, &s);
            let c = dot(&s, &s) - dl_arc * dl_arc;
            let disc = b * b - 4.0 * a * c;
            if !(disc >= 0.0 && a > 0.0) {
                break;
            }
            let roots = [(-b + disc.sqrt()) / (2.0 * a), (-b - disc.sqrt()) / (2.0 * a)];
            let score = |x: f64| {
                dq.iter()
                    .zip(&s)
                    .zip(dtt)
                    .map(|((p, si), ti)| p * (si + x * ti))
                    .sum::<f64>()
            };
            let dlm = if score(roots[0]) >= score(roots[1]) {
                roots[0]
            } else {
                roots[1]
            };
            let corr: Vec<f64> = dr.iter().zip(dtt).map(|(r, t)| r + dlm * t).collect();
            ctx.apply(st, &corr, None);
            lam += dlm;
            for (d, c) in dq.iter_mut().zip(&corr) {
                *d += c;
            }
        }
        match ok {
            Some(it) => {
                iterations += it;
                steps += 1;
                let stable = match pd {
                    Some(p) => p,
                    None => ctx.positive_definite(st, lam),
                };
                stab.record(lambda, lam, stable);
                lambda = lam;
                cut_run = 0;
                prev = Some(dq);
                path.push(PathPoint {
                    lambda,
                    values: ctx.tracked(st, &opts.track),
                    stable,
                    residuals,
                });
            }
            None => {
                *st = saved;
                cuts += 1;
                cut_run += 1;
                dl_arc *= 0.5;
                if cut_run > opts.max_cuts || cuts > opts.max_total_cuts {
                    return Err(fail(
                        name,
                        steps + 1,
                        lambda,
                        last_res,
                        format!("arc length did not converge after {} cuts", opts.max_cuts),
                    ));
                }
            }
        }
    }
    Err(fail(name, steps, lambda, f64::NAN, "arc length: too many steps"))
}

fn one_step(opts: &NonlinearOptions) -> NonlinearOptions {
    NonlinearOptions {
        steps: 1,
        ..opts.clone()
    }
}

fn resultant(x: Vector3<f64>, f: &[f64]) -> [f64; 6] {
    let fv = Vector3::new(f[0], f[1], f[2]);
    let m = x.cross(&fv);
    [f[0], f[1], f[2], m.x + f[3], m.y + f[4], m.z + f[5]]
}

#[allow(clippy::too_many_arguments)]
fn finish(
    ctx: &CaseCtx,
    st: &State,
    name: &str,
    lambda: f64,
    path: Vec<PathPoint>,
    iterations: usize,
    steps: usize,
    cuts: usize,
) -> Result<NonlinearCase, FemError> {
    let model = ctx.model;
    let nn = model.nodes.len();
    let arms = ctx.arms(st);
    let mut f_int = vec![0.0; 6 * nn];
    let mut elements = Vec::with_capacity(ctx.elems.len());
    let mut frames = Vec::with_capacity(ctx.elems.len());
    for (ie, e) in ctx.elems.iter().enumerate() {
        match e {
            ElemData::Corot { nodes, geom, k_local } => {
                let r = corot::response(
                    geom,
                    k_local,
                    &CaseCtx::node_state(st, nodes[0]),
                    &CaseCtx::node_state(st, nodes[1]),
                    false,
                )
                .ok_or_else(|| fail(name, steps, lambda, f64::NAN, format!("element {ie} degenerate")))?;
                for s in 0..2 {
                    for d in 0..6 {
                        f_int[6 * nodes[s] + d] += r.f[6 * s + d];
                    }
                }
                elements.push(recovery::from_local_end_forces(
                    &model.elements[ie],
                    r.f_local.as_slice(),
                    0.5 * r.d_local.dot(&r.f_local),
                ));
                let rt = r.rr.transpose();
                frames.push(std::array::from_fn(|i| std::array::from_fn(|j| rt[(i, j)])));
            }
            ElemData::Spring { nodes, n_nodes, b, k } => {
                let (_, _, _, f) = ctx
                    .element_response(st, ie, false)
                    .ok_or_else(|| fail(name, steps, lambda, f64::NAN, format!("element {ie} degenerate")))?;
                for s in 0..*n_nodes {
                    for d in 0..6 {
                        f_int[6 * nodes[s] + d] += f[6 * s + d];
                    }
                }
                let mut dvec = SMatrix::<f64, 12, 1>::zeros();
                for (s, &n) in nodes.iter().enumerate().take(*n_nodes) {
                    let rv = corot::rot_log(&st.r[n]);
                    for j in 0..3 {
                        dvec[6 * s + j] = st.u[n][j];
                        dvec[6 * s + 3 + j] = rv[j];
                    }
                }
                let delta = **b * dvec;
                let fs: [f64; 6] = std::array::from_fn(|i| k[i] * delta[i]);
                let energy = 0.5 * (0..6).map(|i| k[i] * delta[i] * delta[i]).sum::<f64>();
                let end_forces = if *n_nodes == 1 {
                    [fs, [0.0; 6]]
                } else {
                    [fs.map(|v| -v), fs]
                };
                elements.push(ElementResult {
                    end_forces,
                    section_forces: [fs, fs],
                    von_mises: None,
                    strain_energy: energy,
                    shell: None,
                });
                frames.push([[1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0]]);
            }
        }
    }
    let f_app: Vec<f64> = ctx.f_ext.iter().map(|v| v * lambda).collect();
    let net: Vec<f64> = f_int.iter().zip(&f_app).map(|(a, b)| a - b).collect();
    let gi = ctx.to_independent(&arms, &net);
    let mut reactions: Vec<(usize, [f64; 6])> = Vec::new();
    for &c in &ctx.map.constrained {
        let node = c / 6;
        if reactions.last().map(|r| r.0) != Some(node) {
            reactions.push((node, [0.0; 6]));
        }
        if let Some(r) = reactions.last_mut() {
            r.1[c % 6] = gi[c];
        }
    }
    for (node, r) in reactions.iter_mut() {
        if ctx.map.framed.contains(node) {
            if let Some(t) = &ctx.map.arm[*node] {
                let g = t * Vector6::from_column_slice(r);
                *r = std::array::from_fn(|i| g[i]);
            }
        }
    }
    let pos = |n: usize| Vector3::from(model.nodes[n]) + st.u[n];
    let mut statics = Statics {
        loads: [0.0; 6],
        reactions: [0.0; 6],
    };
    for n in 0..nn {
        let v = resultant(pos(n), &f_app[6 * n..6 * n + 6]);
        for (a, b) in statics.loads.iter_mut().zip(v) {
            *a += b;
        }
    }
    for (n, r) in &reactions {
        let v = resultant(pos(*n), r);
        for (a, b) in statics.reactions.iter_mut().zip(v) {
            *a += b;
        }
    }
    verify_equilibrium(ctx, st, name, steps, lambda, &f_int, &f_app, &gi, &reactions)?;
    let max_von_mises = elements
        .iter()
        .filter_map(|e| e.max_von_mises())
        .fold(None, |m: Option<f64>, v| Some(m.map_or(v, |m| m.max(v))));
    let displacements: Vec<[f64; 6]> = (0..nn)
        .map(|n| {
            let rv = corot::rot_log(&st.r[n]);
            [st.u[n][0], st.u[n][1], st.u[n][2], rv[0], rv[1], rv[2]]
        })
        .collect();
    let rotations =
        st.r.iter()
            .map(|r| std::array::from_fn(|i| std::array::from_fn(|j| r[(i, j)])))
            .collect();
    Ok(NonlinearCase {
        fe: CaseResult {
            name: name.to_string(),
            displacements,
            reactions,
            elements,
            max_von_mises,
            statics,
        },
        rotations,
        path,
        iterations,
        steps,
        cuts,
        stable: true,
        critical_load_factor: None,
        element_frames: frames,
    })
}

/// Relative equilibrium bound of an accepted state (of the applied load; of the reactions
/// when displacements are prescribed).
const EQUILIBRIUM_TOL: f64 = 1e-6;

/// Checks the accepted state: (1) the unbalanced force and moment at every free equation
/// (nodal equilibrium at the deformed positions, spins as rotational unknowns), and (2) the
/// global statics — applied loads, reactions and spring forces (springs count as supports:
/// their small-rotation moments are not objective) summed as forces and moments about the
/// origin at the deformed positions — both within [`EQUILIBRIUM_TOL`] of the applied load
/// (plus the reactions where displacements are prescribed), with a round-off allowance of
/// 1e-11 of the summed element forces. Fails naming the step otherwise.
#[allow(clippy::too_many_arguments)]
fn verify_equilibrium(
    ctx: &CaseCtx,
    st: &State,
    name: &str,
    step: usize,
    lambda: f64,
    f_int: &[f64],
    f_app: &[f64],
    gi: &[f64],
    reactions: &[(usize, [f64; 6])],
) -> Result<(), FemError> {
    let model = ctx.model;
    let nn = model.nodes.len();
    let pos = |n: usize| Vector3::from(model.nodes[n]) + st.u[n];
    let prescribed = ctx.u_c.iter().any(|v| *v != 0.0);
    // Spring forces on their nodes (to be moved to the "support" side of the balance).
    let mut f_spring = vec![0.0; 6 * nn];
    for (ie, e) in ctx.elems.iter().enumerate() {
        if let ElemData::Spring { nodes, n_nodes, .. } = e {
            if let Some((_, _, _, f)) = ctx.element_response(st, ie, false) {
                for s in 0..*n_nodes {
                    for d in 0..6 {
                        f_spring[6 * nodes[s] + d] += f[6 * s + d];
                    }
                }
            }
        }
    }
    let (mut sum, mut scale_f, mut scale_m) = ([0.0; 6], 0.0, 0.0);
    let mut add = |x: Vector3<f64>, f: &[f64], sign: f64, counts: bool| {
        let v = resultant(x, f);
        for (a, b) in sum.iter_mut().zip(v) {
            *a += sign * b;
        }
        if counts {
            let fv = Vector3::new(f[0], f[1], f[2]);
            scale_f += fv.norm();
            scale_m += Vector3::new(f[3], f[4], f[5]).norm();
        }
    };
    for n in 0..nn {
        add(pos(n), &f_app[6 * n..6 * n + 6], 1.0, true);
        add(pos(n), &f_spring[6 * n..6 * n + 6], -1.0, false);
    }
    for (n, r) in reactions {
        add(pos(*n), r, 1.0, prescribed);
    }
    let internal: f64 = f_int.iter().map(|v| v.abs()).sum();
    let arms = ctx.arms(st);
    let fi = norm(&ctx.to_independent(&arms, f_int));
    let residual: Vec<f64> = ctx.map.eq_dof.iter().map(|&g| gi[g]).collect();
    let rn = norm(&residual);
    let round = ctx.round + 1e-13 * internal;
    let nodal_ok = rn <= EQUILIBRIUM_TOL * norm(f_app).max(fi) + round;
    let fsum = Vector3::new(sum[0], sum[1], sum[2]).norm();
    let msum = Vector3::new(sum[3], sum[4], sum[5]).norm();
    // Moments about the origin: forces act on levers up to the model's extent from it.
    let lever = (0..nn).map(|n| pos(n).norm()).fold(0.0, f64::max).max(1.0);
    let force_ok = fsum <= EQUILIBRIUM_TOL * scale_f + round;
    let moment_ok = msum <= EQUILIBRIUM_TOL * (scale_m + lever * scale_f) + round * lever;
    if nodal_ok && force_ok && moment_ok {
        return Ok(());
    }
    Err(fail(
        name,
        step,
        lambda,
        rn,
        format!(
            "the accepted state is not in equilibrium: unbalanced force {fsum:.3e} N and moment {msum:.3e} N·mm (statics at the deformed positions, against applied loads of {scale_f:.3e} N); nodal residual {rn:.3e}"
        ),
    ))
}
