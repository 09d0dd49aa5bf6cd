//! Diagnosis of a singular or ill-conditioned stiffness: unconstrained DOFs, free bodies,
//! mechanisms (the lowest mode of K and its strain energy) and the roundoff bounds of a
//! stiff-and-soft model. Used by the static solve ([`super::analysis`]) and the modal analysis.

use super::constraints::{DofMap, NONE};
use super::dof::NodeDof;
use super::error::FemError;
use super::model::{Element, Model};
use super::solve::{Factor, Parallelism, SparseMatrix, SymbolicFactor};

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
/// norm) of one step of iterative refinement (see [`crate::fem::analysis::System::solve_checked`]; N. J. Higham,
/// Accuracy and Stability of Numerical Algorithms, 2nd ed., 2002, ch. 12), which overestimates
/// the actual error here by 7–20×. A steel cantilever segment carrying one 10¹² stiffer
/// estimates 7e-4 (actual error 4e-5) and solves; a 0.1 mm leaf carrying a block whose
/// translational stiffness is 10¹⁵ its own estimates 0.14 (actual 2 %) and is refused.
pub const REFINE_TOL: f64 = 1e-2;

pub(crate) fn has_tiny_pivot(f: &Factor, k: &SparseMatrix) -> bool {
    f.pivots()
        .iter()
        .zip(k.diagonal())
        .any(|(p, d)| p.is_nan() || *p <= PIVOT_TOL * d)
}

/// Free equations whose diagonal stiffness is zero, relative to the largest diagonal of the
/// same kind (translations and rotations have different units) at the same node: a DOF is
/// judged against its own node's scale, never against the stiffest part of the model, so a
/// thin leaf next to a block 10⁶× stiffer is not mistaken for a free DOF.
pub(crate) fn check_unconstrained(map: &DofMap, k: &SparseMatrix) -> Result<(), FemError> {
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
pub(crate) fn check_singular(
    model: &Model,
    map: &DofMap,
    k: &SparseMatrix,
    f: &Factor,
    par: Parallelism,
) -> Option<FemError> {
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
            add(&|a, b| k[(a, b)], &map.nodes_eqs(&reps)[..24]);
        } else if let Element::Shell9(_) = el {
            let Ok(em) = model.shell9_matrix(ie) else { continue };
            let (reps, k) = map.shell9_on_independent(&em);
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
pub(crate) fn diagnose_mechanism(
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
    let (lo, hi) = model.bounding_box();
    let s = (0..3).map(|c| (hi[c] - lo[c]).powi(2)).sum::<f64>().sqrt();
    if s > 0.0 && s.is_finite() {
        s
    } else {
        1.0
    }
}
