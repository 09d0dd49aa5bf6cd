//! Linear (bifurcation) buckling: the load multipliers λ and mode shapes φ of
//!
//! ```text
//! (K + λ K_G) φ = 0
//! ```
//! with K the linear stiffness of the constrained model and K_G the geometric stiffness of the
//! linear reference solution under one load case ([`geometric`]). The reference load times λ
//! is the critical load; λ < 0 means the structure buckles under the *reversed* load.
//!
//! Solved as K_G φ = θ K φ, θ = −1/λ, by block shift-invert Lanczos ([`super::lanczos`]) on
//! S = K⁻¹K_G, self-adjoint in the K inner product (K positive definite: the model must be
//! supported); the θ of largest magnitude, of either sign, are the λ of smallest magnitude
//! (the "buckling mode" of R. G. Grimes, J. G. Lewis, H. D. Simon, "A shifted block Lanczos
//! algorithm for solving sparse symmetric generalized eigenproblems", SIAM J. Matrix Anal.
//! Appl. 15 (1994) 228–272, §2, with shift 0). K is the factorised system of the static
//! reference solve, reused.

pub mod geometric;

use super::analysis::{prescribed_dofs, System};
use super::error::FemError;
use super::lanczos::{lanczos, Pencil};
use super::model::Model;
use super::results::CaseResult;
use super::solve::Parallelism;

/// Options of [`solve_buckling`].
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct BucklingOptions {
    /// Number of load multipliers wanted (smallest |λ|).
    pub n_modes: usize,
    /// Relative residual tolerance of the Ritz pairs.
    pub tol: f64,
    /// Solver parallelism.
    pub par: Parallelism,
}

impl BucklingOptions {
    /// `n` modes with default settings.
    pub fn new(n: usize) -> BucklingOptions {
        BucklingOptions {
            n_modes: n,
            tol: 1e-6,
            par: Parallelism::Rayon,
        }
    }
}

/// One buckling mode.
#[derive(Debug, Clone, PartialEq)]
pub struct BucklingMode {
    /// Load multiplier λ: the reference load times λ buckles the structure (λ < 0: the
    /// reversed load).
    pub load_factor: f64,
    /// Mode shape per node [ux uy uz (mm), rx ry rz (rad)], global axes, scaled so that the
    /// largest translation is 1 mm (the largest rotation 1 rad if no node translates) and
    /// positive.
    pub shape: Vec<[f64; 6]>,
}

/// Results of [`solve_buckling`].
#[derive(Debug, Clone, PartialEq)]
pub struct BucklingResults {
    /// Modes by increasing |λ|.
    pub modes: Vec<BucklingMode>,
    /// The linear reference solution.
    pub reference: CaseResult,
    /// Lanczos steps (= linear solves).
    pub lanczos_steps: usize,
    /// Equations of the reduced system.
    pub n_eq: usize,
}

/// Scales a shape so that its largest translation (else rotation) is +1.
fn normalise(shape: &mut [[f64; 6]]) {
    let largest = |range: std::ops::Range<usize>| {
        shape
            .iter()
            .flat_map(|r| r[range.clone()].iter().copied())
            .fold(0.0f64, |m, v| if v.abs() > m.abs() { v } else { m })
    };
    let t = largest(0..3);
    let s = if t.abs() > 1e-12 * largest(3..6).abs() {
        t
    } else {
        largest(3..6)
    };
    if s != 0.0 && s.is_finite() {
        shape.iter_mut().flatten().for_each(|v| *v /= s);
    }
}

/// The `n_modes` smallest-magnitude load multipliers of load case `case` (index into
/// `model.load_cases`) and their mode shapes.
pub fn solve_buckling(model: &Model, case: usize, opts: &BucklingOptions) -> Result<BucklingResults, FemError> {
    model.validate()?;
    let Some(lc) = model.load_cases.get(case) else {
        return Err(FemError::BadInput(format!(
            "buckling needs a reference load case; the model has {} (index {case} requested)",
            model.load_cases.len()
        )));
    };
    if opts.n_modes == 0 {
        return Err(FemError::BadInput("buckling analysis needs at least one mode".into()));
    }
    if let Some(ie) = model
        .elements
        .iter()
        .position(|e| matches!(e, super::model::Element::Shell4(_) | super::model::Element::Shell9(_)))
    {
        return Err(geometric::element_geometric(model, ie, &[])
            .err()
            .unwrap_or_else(|| FemError::BadInput(format!("element {ie} is a shell: no geometric stiffness"))));
    }
    let sys = System::new(model, &prescribed_dofs(lc), opts.par)?;
    let reference = sys
        .solve_cases(model, &[lc])?
        .pop()
        .ok_or_else(|| FemError::Solver("no reference solution".into()))?;
    let u: Vec<f64> = reference.displacements.iter().flatten().copied().collect();
    let map = sys.dof_map();
    let (kg, scale) = geometric::assemble_geometric(model, map, &u, lc)?;
    let n = map.n_eq();
    if !(scale > 0.0 && scale.is_finite()) {
        return Err(FemError::BadInput(format!(
            "load case \"{}\" puts no axial force or moment into any beam, hinge or rigid link: there is no geometric stiffness, nothing can buckle",
            lc.name
        )));
    }
    let (kf, bf) = (sys.matrix().full(), kg.full());
    let pencil = Pencil {
        a: sys.factor(),
        w: &kf,
        b: Some(&bf),
        what: "buckling modes (non-zero geometric stiffness)",
        positive: false,
    };
    let (theta, x, steps) = lanczos(&pencil, n, opts.n_modes.min(n), opts.tol)?;
    let zero = vec![0.0; model.n_dofs()];
    let mut modes: Vec<BucklingMode> = theta
        .iter()
        .zip(x)
        .map(|(&th, q)| {
            let full = map.expand(&q, &zero);
            let mut shape: Vec<[f64; 6]> = full.chunks(6).map(|c| std::array::from_fn(|d| c[d])).collect();
            normalise(&mut shape);
            BucklingMode {
                load_factor: -1.0 / th,
                shape,
            }
        })
        .collect();
    if let Some(bad) = modes.iter().find(|m| !m.load_factor.is_finite()) {
        return Err(FemError::Solver(format!(
            "buckling: non-finite load factor {}",
            bad.load_factor
        )));
    }
    modes.sort_by(|a, b| a.load_factor.abs().total_cmp(&b.load_factor.abs()));
    Ok(BucklingResults {
        modes,
        reference,
        lanczos_steps: steps,
        n_eq: n,
    })
}
