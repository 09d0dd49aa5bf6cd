//! Sparse matrix storage for the solve: [`SparsePattern`] (the lower-triangle pattern and the
//! argsort that sums duplicate triplets), [`SparseMatrix`] (a symmetric matrix stored as its
//! lower triangle, with products, diagonal and export) and [`FullSymmetric`] (both triangles by
//! rows, for parallel products).

use crate::fem::error::FemError;
use faer::sparse::{Argsort, Pair, SparseColMat, SymbolicSparseColMat};
use std::io::Write;

/// Lower-triangle sparsity pattern of an n×n symmetric matrix plus the order in which triplet
/// values are summed into it.
#[derive(Debug, Clone)]
pub struct SparsePattern {
    pub(super) symbolic: SymbolicSparseColMat<usize>,
    argsort: Argsort<usize>,
    n_triplets: usize,
}

impl SparsePattern {
    /// Pattern from (row, col) index pairs with row ≥ col (lower triangle); duplicates allowed
    /// (their values are summed).
    pub fn new(n: usize, pairs: &[(usize, usize)]) -> Result<SparsePattern, FemError> {
        if let Some(&(r, c)) = pairs.iter().find(|&&(r, c)| r < c || r >= n) {
            return Err(FemError::PatternMismatch(format!(
                "entry ({r}, {c}) is not in the lower triangle of a {n}×{n} matrix"
            )));
        }
        let idx: Vec<Pair<usize, usize>> = pairs.iter().map(|&(row, col)| Pair { row, col }).collect();
        let (symbolic, argsort) = SymbolicSparseColMat::try_new_from_indices(n, n, &idx)
            .map_err(|e| FemError::Solver(format!("pattern: {e:?}")))?;
        Ok(SparsePattern {
            symbolic,
            argsort,
            n_triplets: pairs.len(),
        })
    }

    /// Matrix dimension.
    pub fn n(&self) -> usize {
        self.symbolic.nrows()
    }

    /// Stored (unique) entries of the lower triangle.
    pub fn nnz(&self) -> usize {
        self.symbolic.compute_nnz()
    }

    /// Number of triplets the pattern was built from (= length of a value vector).
    pub fn n_triplets(&self) -> usize {
        self.n_triplets
    }

    /// Sums triplet values (in the order of the pairs given to [`SparsePattern::new`]) into a
    /// matrix with this pattern.
    pub fn matrix(&self, values: &[f64]) -> Result<SparseMatrix, FemError> {
        if values.len() != self.n_triplets {
            return Err(FemError::PatternMismatch(format!(
                "{} values for a pattern built from {} triplets",
                values.len(),
                self.n_triplets
            )));
        }
        let mat = SparseColMat::new_from_argsort(self.symbolic.clone(), &self.argsort, values)
            .map_err(|e| FemError::Solver(format!("fill: {e:?}")))?;
        Ok(SparseMatrix { mat })
    }
}

/// Symmetric matrix stored as its lower triangle (compressed sparse columns).
#[derive(Debug, Clone)]
pub struct SparseMatrix {
    pub(super) mat: SparseColMat<usize, f64>,
}

impl SparseMatrix {
    /// Dimension.
    pub fn n(&self) -> usize {
        self.mat.nrows()
    }

    /// Stored entries (lower triangle).
    pub fn nnz(&self) -> usize {
        self.mat.val().len()
    }

    fn for_each(&self, mut f: impl FnMut(usize, usize, f64)) {
        let sym = self.mat.symbolic();
        let (cp, ri) = (sym.col_ptr(), sym.row_idx());
        let val = self.mat.val();
        for j in 0..self.n() {
            for p in cp[j]..cp[j + 1] {
                f(ri[p], j, val[p]);
            }
        }
    }

    /// Diagonal entries.
    pub fn diagonal(&self) -> Vec<f64> {
        let mut d = vec![0.0; self.n()];
        self.for_each(|i, j, v| {
            if i == j {
                d[i] += v;
            }
        });
        d
    }

    /// y = K·x using the symmetric lower storage.
    pub fn mul_vec(&self, x: &[f64]) -> Vec<f64> {
        let mut y = vec![0.0; self.n()];
        self.for_each(|i, j, v| {
            y[i] += v * x[j];
            if i != j {
                y[j] += v * x[i];
            }
        });
        y
    }

    /// Both triangles in compressed rows, for fast parallel products (e.g. M·v in Lanczos).
    pub fn full(&self) -> FullSymmetric {
        let n = self.n();
        let mut count = vec![0usize; n + 1];
        self.for_each(|i, j, _| {
            count[i + 1] += 1;
            if i != j {
                count[j + 1] += 1;
            }
        });
        for k in 0..n {
            count[k + 1] += count[k];
        }
        let mut next = count.clone();
        let mut col = vec![0usize; count[n]];
        let mut val = vec![0.0; count[n]];
        self.for_each(|i, j, v| {
            col[next[i]] = j;
            val[next[i]] = v;
            next[i] += 1;
            if i != j {
                col[next[j]] = i;
                val[next[j]] = v;
                next[j] += 1;
            }
        });
        FullSymmetric {
            row_ptr: count,
            col,
            val,
        }
    }

    /// a·self + b·other for two matrices on the same pattern (e.g. K − σM from one
    /// [`SparsePattern`]); `None` if the patterns differ.
    pub fn lin_comb(&self, a: f64, other: &SparseMatrix, b: f64) -> Option<SparseMatrix> {
        let (s1, s2) = (self.mat.symbolic(), other.mat.symbolic());
        if s1.col_ptr() != s2.col_ptr() || s1.row_idx() != s2.row_idx() {
            return None;
        }
        let mut out = self.clone();
        for (v, w) in out.mat.val_mut().iter_mut().zip(other.mat.val()) {
            *v = a * *v + b * w;
        }
        Some(out)
    }

    /// K + eps·diag(K) (the pattern must hold the diagonal, which
    /// [`crate::fem::assembly::Pattern`] guarantees).
    pub fn shifted_scaled(&self, eps: f64) -> SparseMatrix {
        let mut out = self.clone();
        let sym = self.mat.symbolic();
        let (cp, ri) = (sym.col_ptr().to_vec(), sym.row_idx().to_vec());
        let val = out.mat.val_mut();
        for j in 0..cp.len().saturating_sub(1) {
            for p in cp[j]..cp[j + 1] {
                if ri[p] == j {
                    val[p] *= 1.0 + eps;
                }
            }
        }
        out
    }

    /// The stored lower-triangle entries as (row, column, value), column by column.
    pub fn lower_triplets(&self) -> Vec<(usize, usize, f64)> {
        let mut out = Vec::with_capacity(self.nnz());
        self.for_each(|i, j, v| out.push((i, j, v)));
        out
    }

    /// Both triangles as a [`sprs::CsMat`] (compressed rows), the type flexfem hands sparse
    /// matrices to other Rust code in.
    pub fn to_csmat(&self) -> sprs::CsMat<f64> {
        let mut tri = sprs::TriMat::with_capacity((self.n(), self.n()), 2 * self.nnz());
        self.for_each(|i, j, v| {
            tri.add_triplet(i, j, v);
            if i != j {
                tri.add_triplet(j, i, v);
            }
        });
        tri.to_csr()
    }

    /// Writes the lower triangle in Matrix Market coordinate format (`real symmetric`,
    /// 1-based), e.g. to compare against CHOLMOD.
    pub fn write_matrix_market(&self, w: &mut impl Write) -> std::io::Result<()> {
        let mut w = std::io::BufWriter::new(w);
        writeln!(w, "%%MatrixMarket matrix coordinate real symmetric")?;
        writeln!(w, "% flexfem reduced stiffness (lower triangle)")?;
        writeln!(w, "{} {} {}", self.n(), self.n(), self.nnz())?;
        let mut res = Ok(());
        self.for_each(|i, j, v| {
            if res.is_ok() {
                res = writeln!(w, "{} {} {:e}", i + 1, j + 1, v);
            }
        });
        res?;
        w.flush()
    }
}

/// A symmetric matrix with both triangles stored by rows (plain CSR, no faer types).
#[derive(Debug, Clone)]
pub struct FullSymmetric {
    row_ptr: Vec<usize>,
    col: Vec<usize>,
    val: Vec<f64>,
}

impl FullSymmetric {
    /// y = A·x, rows in parallel (rayon).
    pub fn mul_vec(&self, x: &[f64]) -> Vec<f64> {
        use rayon::prelude::*;
        let n = self.row_ptr.len().saturating_sub(1);
        (0..n)
            .into_par_iter()
            .with_min_len(512)
            .map(|i| {
                let (a, b) = (self.row_ptr[i], self.row_ptr[i + 1]);
                self.col[a..b].iter().zip(&self.val[a..b]).map(|(&j, v)| v * x[j]).sum()
            })
            .collect()
    }
}
