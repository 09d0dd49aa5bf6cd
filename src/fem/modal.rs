//! Modal analysis: the lowest eigenpairs of K φ = ω² M φ on the reduced (constrained) system by
//! shift-invert Lanczos with full M-reorthogonalisation (B. N. Parlett, The Symmetric
//! Eigenvalue Problem, 1980, §13; T. Ericsson, A. Ruhe, Math. Comp. 35 (1980) 1251).
//!
//! The operator S = (K − σM)⁻¹ M is self-adjoint in the M inner product; its largest
//! eigenvalues θ = 1/(λ − σ) are the eigenvalues λ = ω² closest to σ from above. K − σM is
//! factorised once by the sparse Cholesky of [`super::solve`]. A model without supports (free
//! body) gets a small negative shift so that K − σM is positive definite and the six rigid-body
//! modes come out first at λ ≈ 0.

use super::assembly::MatrixKind;
use super::constraints::DofMap;
use super::diagnose::check_free_bodies;
use super::error::FemError;
pub(crate) use super::lanczos::RitzPairs;
use super::lanczos::{dot, Pencil};
use super::model::Model;
use super::solve::{Factor, FactorError, FullSymmetric, Parallelism, SparseMatrix};
use nalgebra::{Vector3, Vector6};

/// Options of [`solve_modal`].
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ModalOptions {
    /// Number of modes wanted (the lowest).
    pub n_modes: usize,
    /// Shift σ in (rad/s)²; `None` = 0 for supported models, a small negative value for free
    /// bodies.
    pub shift: Option<f64>,
    /// Relative residual tolerance of the Ritz pairs.
    pub tol: f64,
    /// Solver parallelism.
    pub par: Parallelism,
}

impl ModalOptions {
    /// `n` lowest modes with default settings.
    pub fn new(n: usize) -> ModalOptions {
        ModalOptions {
            n_modes: n,
            shift: None,
            tol: 1e-6,
            par: Parallelism::Rayon,
        }
    }
}

/// One mode.
#[derive(Debug, Clone, PartialEq)]
pub struct Mode {
    /// Eigenvalue ω², (rad/s)² (≈ 0, possibly slightly negative, for rigid-body modes).
    pub eigenvalue: f64,
    /// Natural frequency √max(ω², 0)/2π, Hz.
    pub frequency_hz: f64,
    /// Mass-normalised shape (φᵀMφ = 1), per node [ux uy uz rx ry rz], global axes; largest
    /// component positive.
    pub shape: Vec<[f64; 6]>,
    /// Participation factors Γ = φᵀ M r for unit rigid motions r along global x, y, z and
    /// about global x, y, z (through the origin), √tonne or √tonne·mm.
    pub participation: [f64; 6],
    /// Effective mass fractions Γ²/(rᵀ M r) per direction.
    pub effective_mass_fraction: [f64; 6],
}

/// Results of [`solve_modal`].
#[derive(Debug, Clone, PartialEq)]
pub struct ModalResults {
    /// Modes by increasing eigenvalue.
    pub modes: Vec<Mode>,
    /// rᵀ M r per direction (free DOFs only): mass, tonne, and rotary inertia about the global
    /// axes through the origin, tonne·mm².
    pub total_mass: [f64; 6],
    /// The shift used, (rad/s)².
    pub shift: f64,
    /// Lanczos steps (= linear solves) taken.
    pub lanczos_steps: usize,
    /// Number of equations of the reduced system.
    pub n_eq: usize,
}

/// Rigid-body motion vectors in equation space: unit translation along global x, y, z and unit
/// rotation about the global axes through the origin (zero on superelement modal nodes).
fn rigid_vectors(model: &Model, map: &DofMap) -> [Vec<f64>; 6] {
    let modal = model.modal_node_flags();
    std::array::from_fn(|d| {
        map.eq_dof
            .iter()
            .map(|&g| {
                let node = g / 6;
                if modal[node] {
                    return 0.0;
                }
                let x = Vector3::from(model.nodes[node]);
                let mut r = Vector6::zeros();
                if d < 3 {
                    r[d] = 1.0;
                } else {
                    let mut axis = Vector3::zeros();
                    axis[d - 3] = 1.0;
                    let u = axis.cross(&x);
                    r.fixed_rows_mut::<3>(0).copy_from(&u);
                    r[d] = 1.0;
                }
                if map.framed.contains(&node) {
                    if let Some(t) = &map.arm[node] {
                        r = t.transpose() * r;
                    }
                }
                r[g % 6]
            })
            .collect()
    })
}

/// The `n_modes` lowest modes of the model (supports and rigid links as in statics; load cases
/// are ignored). Errors if the model has no mass, or if K − σM is singular (a massless
/// mechanism).
pub fn solve_modal(model: &Model, opts: &ModalOptions) -> Result<ModalResults, FemError> {
    solve_modal_cached(model, opts, &mut super::cache::SolverCache::new())
}

/// [`solve_modal`] reusing the pattern and symbolic factorisation of `cache` where the topology
/// matches (see [`super::cache`]).
pub fn solve_modal_cached(
    model: &Model,
    opts: &ModalOptions,
    cache: &mut super::cache::SolverCache,
) -> Result<ModalResults, FemError> {
    model.validate()?;
    if opts.n_modes == 0 {
        return Err(FemError::BadInput("modal analysis needs at least one mode".into()));
    }
    let map = DofMap::new(model, &[], None)?;
    let pattern = cache.modal_pattern(model, &map)?;
    let k = pattern.matrix(&pattern.values_of(model, &map, MatrixKind::Stiffness)?)?;
    let m = pattern.matrix(&pattern.values_of(model, &map, MatrixKind::Mass)?)?;
    let n = map.n_eq();
    if n == 0 {
        return Err(FemError::BadInput("every DOF is constrained: no modes".into()));
    }
    let (kd, md) = (k.diagonal(), m.diagonal());
    if md.iter().all(|&v| v <= 0.0) {
        return Err(FemError::BadInput(
            "the model has no mass (give materials a density or add point masses)".into(),
        ));
    }
    let negative_shift = || -1e-6 * median_ratio(&kd, &md);
    let shifts = match opts.shift {
        Some(s) if s.is_finite() => vec![s],
        Some(s) => return Err(FemError::BadInput(format!("modal shift must be finite, got {s}"))),
        // Supported: σ = 0, and if K turns out singular (a mechanism with mass, which has a
        // legitimate 0 Hz mode) a small negative shift. Free body: the negative shift at once.
        None if check_free_bodies(model, &map).is_ok() => vec![0.0, negative_shift()],
        None => vec![negative_shift()],
    };
    let symbolic = cache.modal_symbolic(&pattern, model.ordering)?;
    let Some((shift, factor)) = factor_shifted(&k, &m, &symbolic, &shifts, opts.par)? else {
        return Err(singular(&map, &k));
    };
    let (theta, x, steps) = lanczos(&factor, &m.full(), n, opts.n_modes.min(n), opts.tol)?;
    let rigid = rigid_vectors(model, &map);
    let mr: Vec<Vec<f64>> = rigid.iter().map(|r| m.mul_vec(r)).collect();
    let total_mass: [f64; 6] = std::array::from_fn(|d| dot(&rigid[d], &mr[d]));
    let zero = vec![0.0; model.n_dofs()];
    let mut modes: Vec<Mode> = theta
        .iter()
        .zip(x)
        .map(|(&th, mut q)| {
            let lam = shift + 1.0 / th;
            let imax = q
                .iter()
                .enumerate()
                .fold(
                    (0, 0.0),
                    |(bi, bv), (i, v)| if v.abs() > bv { (i, v.abs()) } else { (bi, bv) },
                )
                .0;
            if q.get(imax).is_some_and(|v| *v < 0.0) {
                q.iter_mut().for_each(|v| *v = -*v);
            }
            let participation: [f64; 6] = std::array::from_fn(|d| dot(&q, &mr[d]));
            let effective_mass_fraction = std::array::from_fn(|d| {
                if total_mass[d] > 0.0 {
                    participation[d].powi(2) / total_mass[d]
                } else {
                    0.0
                }
            });
            let u = map.expand(&q, &zero);
            Mode {
                eigenvalue: lam,
                frequency_hz: lam.max(0.0).sqrt() / (2.0 * std::f64::consts::PI),
                shape: (0..model.nodes.len())
                    .map(|i| std::array::from_fn(|d| u[6 * i + d]))
                    .collect(),
                participation,
                effective_mass_fraction,
            }
        })
        .collect();
    modes.sort_by(|a, b| a.eigenvalue.total_cmp(&b.eigenvalue));
    Ok(ModalResults {
        modes,
        total_mass,
        shift,
        lanczos_steps: steps,
        n_eq: n,
    })
}

/// Median of Kᵢᵢ/Mᵢᵢ over the DOFs where both are positive (1 without any): the scale of the
/// eigenvalues, for choosing shifts.
pub(crate) fn median_ratio(kd: &[f64], md: &[f64]) -> f64 {
    let mut ratios: Vec<f64> = kd
        .iter()
        .zip(md)
        .filter(|(k, m)| **k > 0.0 && **m > 0.0)
        .map(|(k, m)| k / m)
        .collect();
    ratios.sort_by(f64::total_cmp);
    ratios.get(ratios.len() / 2).copied().unwrap_or(1.0)
}

/// K − σM factorised (sparse Cholesky) for the first shift σ of `shifts` that makes it positive
/// definite with every pivot above [`super::diagnose::PIVOT_TOL`] of its diagonal; `None` when
/// none does. K and M share one pattern.
pub(crate) fn factor_shifted(
    k: &SparseMatrix,
    m: &SparseMatrix,
    symbolic: &super::solve::SymbolicFactor,
    shifts: &[f64],
    par: Parallelism,
) -> Result<Option<(f64, Factor)>, FemError> {
    for &shift in shifts {
        let a = k
            .lin_comb(1.0, m, -shift)
            .ok_or_else(|| FemError::PatternMismatch("K and M patterns differ".into()))?;
        match Factor::new(symbolic, &a, par) {
            Ok(f) => {
                let tiny = f
                    .pivots()
                    .iter()
                    .zip(a.diagonal())
                    .any(|(p, d)| p.is_nan() || *p <= super::diagnose::PIVOT_TOL * d);
                if !tiny {
                    return Ok(Some((shift, f)));
                }
            }
            Err(FactorError::NotPositiveDefinite) => {}
            Err(FactorError::Other(s)) => return Err(FemError::Solver(s)),
        }
    }
    Ok(None)
}

fn singular(map: &DofMap, k: &SparseMatrix) -> FemError {
    let d = k.diagonal();
    let dofs: Vec<_> = d
        .iter()
        .enumerate()
        .filter(|(_, v)| **v <= 0.0)
        .map(|(i, _)| map.describe_eq(i))
        .collect();
    if !dofs.is_empty() {
        return FemError::Unconstrained { dofs };
    }
    FemError::Solver("K − σM is singular: a mechanism without mass, or a massless DOF without stiffness".into())
}

/// Block shift-invert Lanczos on S = A⁻¹M in the M inner product ([`super::lanczos`]): the
/// `nev` largest θ (descending, all positive), their M-orthonormal Ritz vectors and the number
/// of linear solves.
pub(crate) fn lanczos(a: &Factor, m: &FullSymmetric, n: usize, nev: usize, tol: f64) -> Result<RitzPairs, FemError> {
    let pencil = Pencil {
        a,
        w: m,
        b: None,
        what: "modes with mass",
        positive: true,
    };
    super::lanczos::lanczos(&pencil, n, nev, tol)
}
