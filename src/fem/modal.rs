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
use super::model::Model;
use super::solve::{Factor, FactorError, FullSymmetric, Parallelism, SparseMatrix};
use nalgebra::{DMatrix, Vector3, Vector6};
use rayon::prelude::*;

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

/// Deterministic pseudo-random vector (splitmix64) in [−1, 1).
fn random_vec(n: usize, seed: u64) -> Vec<f64> {
    let mut s = seed.wrapping_mul(0x9E37_79B9_7F4A_7C15).wrapping_add(1);
    (0..n)
        .map(|_| {
            s = s.wrapping_add(0x9E37_79B9_7F4A_7C15);
            let mut z = s;
            z = (z ^ (z >> 30)).wrapping_mul(0xBF58_476D_1CE4_E5B9);
            z = (z ^ (z >> 27)).wrapping_mul(0x94D0_49BB_1331_11EB);
            z ^= z >> 31;
            (z >> 11) as f64 / (1u64 << 52) as f64 - 1.0
        })
        .collect()
}

const CHUNK: usize = 4096;

fn dot(a: &[f64], b: &[f64]) -> f64 {
    a.par_chunks(CHUNK)
        .zip(b.par_chunks(CHUNK))
        .map(|(x, y)| x.iter().zip(y).map(|(p, q)| p * q).sum::<f64>())
        .sum()
}

fn axpy(y: &mut [f64], a: f64, x: &[f64]) {
    y.par_chunks_mut(CHUNK).zip(x.par_chunks(CHUNK)).for_each(|(ys, xs)| {
        for (yi, xi) in ys.iter_mut().zip(xs) {
            *yi += a * xi;
        }
    });
}

/// Coefficients (M vᵢ)ᵀ x for every basis vector at once (one parallel pass per vector).
fn dots(mbasis: &[Vec<f64>], x: &[f64]) -> Vec<f64> {
    mbasis
        .par_iter()
        .map(|mv| mv.iter().zip(x).map(|(p, q)| p * q).sum())
        .collect()
}

/// x −= Σ cᵢ vᵢ, in parallel over chunks of x.
fn subtract(x: &mut [f64], basis: &[Vec<f64>], c: &[f64]) {
    x.par_chunks_mut(CHUNK).enumerate().for_each(|(k, xs)| {
        let (off, len) = (k * CHUNK, xs.len());
        for (v, &ci) in basis.iter().zip(c) {
            for (xi, vi) in xs.iter_mut().zip(&v[off..off + len]) {
                *xi -= ci * vi;
            }
        }
    });
}

/// Rigid-body motion vectors in equation space: unit translation along global x, y, z and unit
/// rotation about the global axes through the origin.
fn rigid_vectors(model: &Model, map: &DofMap) -> [Vec<f64>; 6] {
    std::array::from_fn(|d| {
        map.eq_dof
            .iter()
            .map(|&g| {
                let node = g / 6;
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
    let symbolic = cache.modal_symbolic(&pattern)?;
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

/// M-orthonormalises the columns of `x` (n × p, column-major) against the basis and among
/// themselves (classical Gram–Schmidt twice). Returns the new vectors, their M-images, and for
/// each column the coefficients on the old basis and on the new vectors; columns that vanish
/// are dropped (their coefficient rows are then missing).
struct Ortho {
    vecs: Vec<Vec<f64>>,
    mvecs: Vec<Vec<f64>>,
    /// coef_old[c][i]: coefficient of column c on basis vector i.
    coef_old: Vec<Vec<f64>>,
    /// coef_new[c][l]: coefficient of column c on new vector l.
    coef_new: Vec<Vec<f64>>,
}

fn orthonormalise(m: &FullSymmetric, basis: &[Vec<f64>], mbasis: &[Vec<f64>], mut cols: Vec<Vec<f64>>) -> Ortho {
    let p = cols.len();
    let nb = basis.len();
    let mut out = Ortho {
        vecs: Vec::new(),
        mvecs: Vec::new(),
        coef_old: vec![vec![0.0; nb]; p],
        coef_new: vec![Vec::new(); p],
    };
    let scale0: Vec<f64> = cols
        .iter()
        .map(|x| x.iter().fold(0.0f64, |s, v| s.max(v.abs())))
        .collect();
    // Against the old basis, the whole block at once (each basis vector read once per pass).
    for _ in 0..2 {
        if nb == 0 {
            break;
        }
        let h: Vec<Vec<f64>> = mbasis
            .par_iter()
            .map(|mv| {
                cols.iter()
                    .map(|x| mv.iter().zip(x).map(|(a, b)| a * b).sum())
                    .collect()
            })
            .collect();
        for (c, x) in cols.iter_mut().enumerate() {
            let hc: Vec<f64> = h.iter().map(|row| row[c]).collect();
            subtract(x, basis, &hc);
            for (ci, hi) in out.coef_old[c].iter_mut().zip(&hc) {
                *ci += hi;
            }
        }
    }
    // Within the block (Gram–Schmidt twice).
    for (c, mut x) in cols.into_iter().enumerate() {
        for _ in 0..2 {
            let h = dots(&out.mvecs, &x);
            subtract(&mut x, &out.vecs, &h);
            if out.coef_new[c].len() < h.len() {
                out.coef_new[c].resize(h.len(), 0.0);
            }
            for (ci, hi) in out.coef_new[c].iter_mut().zip(&h) {
                *ci += hi;
            }
        }
        let mx = m.mul_vec(&x);
        let nrm = dot(&x, &mx).max(0.0).sqrt();
        let scale = x.iter().fold(0.0f64, |s, v| s.max(v.abs()));
        out.coef_new[c].resize(out.vecs.len(), 0.0);
        if nrm.is_finite() && nrm > 0.0 && scale > 1e-9 * scale0[c] {
            out.coef_new[c].push(nrm);
            out.vecs.push(x.iter().map(|v| v / nrm).collect());
            out.mvecs.push(mx.iter().map(|v| v / nrm).collect());
        }
    }
    out
}

/// Block size of the Lanczos process: covers the six-fold rigid-body eigenvalue of a free body
/// and the repeated frequencies of symmetric structures.
const BLOCK: usize = 6;

/// Block shift-invert Lanczos (full reorthogonalisation, Rayleigh–Ritz on the whole basis):
/// returns the `nev` largest θ of S = A⁻¹M (descending), their M-orthonormal Ritz vectors,
/// and the number of linear solves.
/// Ritz values θ (descending), Ritz vectors and the number of solves.
pub(crate) type RitzPairs = (Vec<f64>, Vec<Vec<f64>>, usize);

pub(crate) fn lanczos(a: &Factor, m: &FullSymmetric, n: usize, nev: usize, tol: f64) -> Result<RitzPairs, FemError> {
    let p = BLOCK.min(n);
    // S·v = A⁻¹(M v); callers pass M v (stored with the basis) or M·random.
    let apply = |mvs: &[Vec<f64>]| -> Result<Vec<Vec<f64>>, FemError> {
        let mut rhs = Vec::with_capacity(n * mvs.len());
        for mv in mvs {
            rhs.extend_from_slice(mv);
        }
        a.solve_in_place(&mut rhs, mvs.len())?;
        Ok(rhs.chunks(n).map(|c| c.to_vec()).collect())
    };
    let mut seed = 1u64;
    let mut randoms = |k: usize| -> Vec<Vec<f64>> {
        (0..k)
            .map(|_| {
                seed += 1;
                random_vec(n, seed)
            })
            .collect()
    };
    let mut basis: Vec<Vec<f64>> = Vec::new();
    let mut mbasis: Vec<Vec<f64>> = Vec::new();
    // Start block: S·random (removes M-null components).
    let mr: Vec<Vec<f64>> = randoms(p).iter().map(|r| m.mul_vec(r)).collect();
    let start = orthonormalise(m, &basis, &mbasis, apply(&mr)?);
    basis.extend(start.vecs);
    mbasis.extend(start.mvecs);
    if basis.is_empty() {
        return Err(FemError::Solver("Lanczos: no start vector with mass".into()));
    }
    // T[(i, j)] = (M vᵢ)ᵀ S vⱼ for every j whose image is known.
    let mut t = DMatrix::<f64>::zeros(0, 0);
    let mut done_cols = 0;
    let mut solves = p;
    loop {
        let block: Vec<usize> = (done_cols..basis.len()).collect();
        if block.is_empty() {
            return Err(FemError::Solver(format!(
                "Lanczos: only {done_cols} modes with mass exist, {nev} requested"
            )));
        }
        let images = apply(&mbasis[done_cols..])?;
        solves += block.len();
        let orth = orthonormalise(m, &basis, &mbasis, images);
        let n_old = basis.len();
        let n_new = orth.vecs.len();
        let size = n_old + n_new;
        let mut t2 = DMatrix::<f64>::zeros(size, size);
        t2.view_mut((0, 0), (t.nrows(), t.ncols())).copy_from(&t);
        for (c, &j) in block.iter().enumerate() {
            for i in 0..n_old {
                t2[(i, j)] = orth.coef_old[c][i];
            }
            for (l, &h) in orth.coef_new[c].iter().enumerate() {
                t2[(n_old + l, j)] = h;
            }
        }
        t = t2;
        done_cols = n_old;
        basis.extend(orth.vecs);
        mbasis.extend(orth.mvecs);
        // Rayleigh–Ritz on the columns whose images are known.
        let k = done_cols;
        if k >= nev || n_new == 0 {
            let tk = t.view((0, 0), (k, k));
            let sym = (tk + tk.transpose()) * 0.5;
            let eig = sym.symmetric_eigen();
            let mut order: Vec<usize> = (0..k).collect();
            order.sort_by(|&a, &b| eig.eigenvalues[b].total_cmp(&eig.eigenvalues[a]));
            let wanted = &order[..nev.min(k)];
            let top = eig.eigenvalues[order[0]].abs();
            let residual = |col: usize| -> f64 {
                let mut r2 = 0.0;
                for row in k..t.nrows() {
                    let mut s = 0.0;
                    for j in 0..k {
                        s += t[(row, j)] * eig.eigenvectors[(j, col)];
                    }
                    r2 += s * s;
                }
                r2.sqrt()
            };
            let converged = wanted.len() == nev
                && wanted
                    .iter()
                    .all(|&c| residual(c) <= tol * eig.eigenvalues[c].abs().max(1e-12 * top));
            if converged || k >= n || (n_new == 0 && k >= nev) {
                if wanted.len() < nev {
                    return Err(FemError::Solver(format!(
                        "Lanczos: only {k} modes with mass exist, {nev} requested"
                    )));
                }
                let thetas: Vec<f64> = wanted.iter().map(|&c| eig.eigenvalues[c]).collect();
                if let Some(bad) = thetas.iter().find(|&&th| th.is_nan() || th <= 0.0) {
                    return Err(FemError::Solver(format!(
                        "Lanczos found a non-positive transformed eigenvalue {bad}; fewer modes with mass than requested?"
                    )));
                }
                let vecs = wanted
                    .iter()
                    .map(|&c| {
                        let mut q = vec![0.0; n];
                        for (i, v) in basis.iter().take(k).enumerate() {
                            axpy(&mut q, eig.eigenvectors[(i, c)], v);
                        }
                        q
                    })
                    .collect();
                return Ok((thetas, vecs, solves));
            }
        }
        if n_new == 0 {
            // Invariant subspace: continue from fresh random directions.
            let mr: Vec<Vec<f64>> = randoms(p).iter().map(|r| m.mul_vec(r)).collect();
            let fresh = orthonormalise(m, &basis, &mbasis, apply(&mr)?);
            solves += p;
            if fresh.vecs.is_empty() {
                return Err(FemError::Solver(format!(
                    "Lanczos: only {} modes with mass exist, {nev} requested",
                    basis.len()
                )));
            }
            let size = basis.len() + fresh.vecs.len();
            let mut t2 = DMatrix::<f64>::zeros(size, size);
            t2.view_mut((0, 0), (t.nrows(), t.ncols())).copy_from(&t);
            t = t2;
            basis.extend(fresh.vecs);
            mbasis.extend(fresh.mvecs);
        }
    }
}
