//! Block shift-invert Lanczos with full W-reorthogonalisation for the symmetric pencils of
//! [`super::modal`] and [`super::buckling`] (B. N. Parlett, The Symmetric Eigenvalue Problem,
//! 1980, §13; T. Ericsson, A. Ruhe, Math. Comp. 35 (1980) 1251).
//!
//! The operator S = A⁻¹B (A factorised by the sparse Cholesky of [`super::solve`]) is
//! self-adjoint in the W inner product when W A⁻¹ B is symmetric: modal analysis takes
//! W = B = M (S = (K − σM)⁻¹M), buckling W = K, B = K_G (S = K⁻¹K_G). The Ritz values θ of
//! largest magnitude (or, for modal, the largest) are returned with W-orthonormal vectors.

use super::error::FemError;
use super::solve::{Factor, FullSymmetric};
use nalgebra::DMatrix;
use rayon::prelude::*;

/// The pencil of [`lanczos`]: S = A⁻¹B, self-adjoint in the W inner product.
pub(crate) struct Pencil<'a> {
    /// The factorised A.
    pub a: &'a Factor,
    /// The inner-product matrix W (positive semidefinite).
    pub w: &'a FullSymmetric,
    /// B; `None` when B = W.
    pub b: Option<&'a FullSymmetric>,
    /// How messages name the eigenvectors ("modes with mass").
    pub what: &'a str,
    /// Only positive θ are wanted (the largest); otherwise the largest |θ| of either sign.
    pub positive: bool,
}

/// Deterministic pseudo-random vector (splitmix64) in [−1, 1).
pub(crate) fn random_vec(n: usize, seed: u64) -> Vec<f64> {
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

pub(crate) fn dot(a: &[f64], b: &[f64]) -> f64 {
    a.par_chunks(CHUNK)
        .zip(b.par_chunks(CHUNK))
        .map(|(x, y)| x.iter().zip(y).map(|(p, q)| p * q).sum::<f64>())
        .sum()
}

pub(crate) fn axpy(y: &mut [f64], a: f64, x: &[f64]) {
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

pub(crate) fn lanczos(pencil: &Pencil, n: usize, nev: usize, tol: f64) -> Result<RitzPairs, FemError> {
    let (m, what) = (pencil.w, pencil.what);
    let p = BLOCK.min(n);
    // S·v = A⁻¹(B v); with B = W callers pass W v (stored with the basis) or W·random.
    let apply = |vs: &[Vec<f64>], wvs: &[Vec<f64>]| -> Result<Vec<Vec<f64>>, FemError> {
        let mut rhs = Vec::with_capacity(n * vs.len());
        for (v, wv) in vs.iter().zip(wvs) {
            match pencil.b {
                Some(b) => rhs.extend_from_slice(&b.mul_vec(v)),
                None => rhs.extend_from_slice(wv),
            }
        }
        pencil.a.solve_in_place(&mut rhs, vs.len())?;
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
    // Start block: S·random (removes W-null components).
    let rs = randoms(p);
    let mr: Vec<Vec<f64>> = rs.iter().map(|r| m.mul_vec(r)).collect();
    let start = orthonormalise(m, &basis, &mbasis, apply(&rs, &mr)?);
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
                "Lanczos: only {done_cols} {what} exist, {nev} requested"
            )));
        }
        let images = apply(&basis[done_cols..], &mbasis[done_cols..])?;
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
            let key = |c: usize| {
                let th = eig.eigenvalues[c];
                if pencil.positive {
                    th
                } else {
                    th.abs()
                }
            };
            order.sort_by(|&a, &b| key(b).total_cmp(&key(a)));
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
                        "Lanczos: only {k} {what} exist, {nev} requested"
                    )));
                }
                let thetas: Vec<f64> = wanted.iter().map(|&c| eig.eigenvalues[c]).collect();
                let bad = |th: f64| th.is_nan() || if pencil.positive { th <= 0.0 } else { th == 0.0 };
                if let Some(bad) = thetas.iter().find(|&&th| bad(th)) {
                    return Err(FemError::Solver(format!(
                        "Lanczos found a transformed eigenvalue {bad}; fewer {what} than requested?"
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
            let rs = randoms(p);
            let mr: Vec<Vec<f64>> = rs.iter().map(|r| m.mul_vec(r)).collect();
            let fresh = orthonormalise(m, &basis, &mbasis, apply(&rs, &mr)?);
            solves += p;
            if fresh.vecs.is_empty() {
                return Err(FemError::Solver(format!(
                    "Lanczos: only {} {what} exist, {nev} requested",
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
