//! Sparse symmetric positive definite solve — the only file that names faer types.
//!
//! Structure and values are kept apart (faer 0.24): [`SparsePattern`] holds the lower-triangle
//! pattern and the argsort that sums duplicate triplets; [`SymbolicFactor`] holds the
//! fill-reducing ordering (AMD or nested dissection) and elimination structure (cheap to clone,
//! reusable for every model with the same pattern); [`Factor`] holds the numeric L of LLᵀ and
//! can be refactorised in place.

use super::error::FemError;
pub use super::nd::FillOrdering;
use super::nd::{nested_dissection, ND_MIN_N};
use faer::dyn_stack::{MemBuffer, MemStack};
use faer::linalg::cholesky::llt::factor::{LltError, LltRegularization};
use faer::perm::PermRef;
use faer::sparse::linalg::cholesky::simplicial::SimplicialLltRef;
use faer::sparse::linalg::cholesky::supernodal::SupernodalLltRef;
use faer::sparse::linalg::cholesky::{
    factorize_symbolic_cholesky, CholeskySymbolicParams, LltRef, SymbolicCholesky, SymbolicCholeskyRaw,
    SymmetricOrdering,
};
use faer::sparse::linalg::lu::{factorize_symbolic_lu, NumericLu, SymbolicLu};
use faer::sparse::linalg::SupernodalThreshold;
use faer::sparse::{Argsort, Pair, SparseColMat, SymbolicSparseColMat};
use faer::{Conj, MatMut, Par, Side};
use std::io::Write;
use std::sync::Arc;

/// Threading of the factorisation and solves. Use `Sequential` when designs already run in
/// parallel on rayon, so the two levels do not fight.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum Parallelism {
    Sequential,
    /// faer's supernodal kernels on the global rayon pool.
    #[default]
    Rayon,
}

impl Parallelism {
    fn par(self) -> Par {
        match self {
            Parallelism::Sequential => Par::Seq,
            Parallelism::Rayon => Par::rayon(0),
        }
    }
}

/// Lower-triangle sparsity pattern of an n×n symmetric matrix plus the order in which triplet
/// values are summed into it.
#[derive(Debug, Clone)]
pub struct SparsePattern {
    symbolic: SymbolicSparseColMat<usize>,
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
    mat: SparseColMat<usize, f64>,
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
    /// [`super::assembly::Pattern`] guarantees).
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

/// Ordering and elimination structure of the sparse Cholesky factor (fill-reducing ordering
/// AMD or nested dissection, see [`FillOrdering`]; faer picks simplicial or supernodal). Cheap
/// to clone (reference-counted).
#[derive(Debug, Clone)]
pub struct SymbolicFactor {
    inner: Arc<SymbolicCholesky<usize>>,
    ordering: FillOrdering,
}

impl SymbolicFactor {
    /// Symbolic analysis of a pattern (once per topology), ordering chosen automatically
    /// ([`FillOrdering::Auto`]).
    pub fn new(pattern: &SparsePattern) -> Result<SymbolicFactor, FemError> {
        Self::with_ordering(pattern, FillOrdering::Auto)
    }

    /// Symbolic analysis with the given fill-reducing ordering.
    pub fn with_ordering(pattern: &SparsePattern, ordering: FillOrdering) -> Result<SymbolicFactor, FemError> {
        let n = pattern.n();
        match ordering {
            FillOrdering::Amd => Self::amd(pattern),
            FillOrdering::Nd => Self::nd(pattern),
            FillOrdering::Auto if n < ND_MIN_N => Self::amd(pattern),
            FillOrdering::Auto => {
                let amd = Self::amd(pattern)?;
                match Self::nd(pattern) {
                    Ok(nd) if nd.nnz_l() < amd.nnz_l() => Ok(nd),
                    _ => Ok(amd),
                }
            }
        }
    }

    /// Symbolic analysis with a given fill-reducing permutation (new equation i is original
    /// equation `perm[i]`), e.g. another solver's ordering of the same matrix; reported as
    /// [`FillOrdering::Nd`].
    pub fn with_permutation(pattern: &SparsePattern, perm: &[usize]) -> Result<SymbolicFactor, FemError> {
        let n = pattern.n();
        let mut iperm = vec![usize::MAX; n];
        for (i, &p) in perm.iter().enumerate() {
            if p < n && iperm[p] == usize::MAX {
                iperm[p] = i;
            }
        }
        if perm.len() != n || iperm.contains(&usize::MAX) {
            return Err(FemError::Solver(format!("not a permutation of 0..{n}")));
        }
        let perm = PermRef::new_checked(perm, &iperm, n);
        Self::analyse(pattern, SymmetricOrdering::Custom(perm), FillOrdering::Nd)
    }

    fn amd(pattern: &SparsePattern) -> Result<SymbolicFactor, FemError> {
        Self::analyse(pattern, SymmetricOrdering::Amd, FillOrdering::Amd)
    }

    fn nd(pattern: &SparsePattern) -> Result<SymbolicFactor, FemError> {
        let sym = pattern.symbolic.as_ref();
        let (perm, iperm) = nested_dissection(sym.col_ptr(), sym.row_idx())?;
        let perm = PermRef::new_checked(&perm, &iperm, pattern.n());
        Self::analyse(pattern, SymmetricOrdering::Custom(perm), FillOrdering::Nd)
    }

    fn analyse(
        pattern: &SparsePattern,
        order: SymmetricOrdering<'_, usize>,
        ordering: FillOrdering,
    ) -> Result<SymbolicFactor, FemError> {
        let inner = factorize_symbolic_cholesky(pattern.symbolic.as_ref(), Side::Lower, order, Default::default())
            .map_err(|e| FemError::Solver(format!("symbolic factorisation: {e:?}")))?;
        Ok(SymbolicFactor {
            inner: Arc::new(inner),
            ordering,
        })
    }

    /// Entries of L counted from the elimination tree (no explicit zeros of amalgamated
    /// supernodes, which [`SymbolicFactor::nnz_l`] includes), to compare the fill of orderings
    /// with other solvers. Runs a simplicial symbolic analysis of `pattern` with this ordering.
    pub fn structural_nnz_l(&self, pattern: &SparsePattern) -> Result<usize, FemError> {
        let params = CholeskySymbolicParams {
            supernodal_flop_ratio_threshold: SupernodalThreshold::FORCE_SIMPLICIAL,
            ..Default::default()
        };
        let order = match self.inner.perm() {
            Some(p) => SymmetricOrdering::Custom(p),
            None => SymmetricOrdering::Identity,
        };
        factorize_symbolic_cholesky(pattern.symbolic.as_ref(), Side::Lower, order, params)
            .map(|s| s.len_val())
            .map_err(|e| FemError::Solver(format!("symbolic factorisation: {e:?}")))
    }

    /// The ordering used: [`FillOrdering::Amd`] or [`FillOrdering::Nd`] (never `Auto`).
    pub fn ordering(&self) -> FillOrdering {
        self.ordering
    }

    /// The fill-reducing permutation: new equation i is original equation `perm()[i]`.
    pub fn perm(&self) -> Vec<usize> {
        match self.inner.perm() {
            Some(p) => p.arrays().0.to_vec(),
            None => (0..self.n()).collect(),
        }
    }

    /// Dimension.
    pub fn n(&self) -> usize {
        self.inner.nrows()
    }

    /// Number of stored values of L.
    pub fn nnz_l(&self) -> usize {
        self.inner.len_val()
    }
}

/// Why a numeric factorisation failed.
#[derive(Debug, Clone, PartialEq)]
pub enum FactorError {
    /// K is not positive definite: a mechanism (or a negative stiffness).
    NotPositiveDefinite,
    /// Anything else (memory, dimension mismatch).
    Other(String),
}

/// Numeric LLᵀ factor.
#[derive(Debug, Clone)]
pub struct Factor {
    symbolic: SymbolicFactor,
    l_values: Vec<f64>,
    par: Parallelism,
}

impl Factor {
    /// Numeric factorisation of `k` (which must have the pattern the symbolic factor was built
    /// from).
    pub fn new(symbolic: &SymbolicFactor, k: &SparseMatrix, par: Parallelism) -> Result<Factor, FactorError> {
        let mut f = Factor {
            symbolic: symbolic.clone(),
            l_values: Vec::new(),
            par,
        };
        f.refactor(k)?;
        Ok(f)
    }

    /// Numeric refactorisation with new values on the same pattern (no symbolic work, buffer
    /// reused).
    pub fn refactor(&mut self, k: &SparseMatrix) -> Result<(), FactorError> {
        let sym = &self.symbolic.inner;
        if k.n() != sym.nrows() {
            return Err(FactorError::Other(format!(
                "matrix is {}×{}, factor is {}×{}",
                k.n(),
                k.n(),
                sym.nrows(),
                sym.nrows()
            )));
        }
        if self.l_values.len() != sym.len_val() {
            // A zeroed allocation, whose pages are mapped on first write: faer's numeric
            // factorisation overwrites every value of L (the supernodal one zeroes them first),
            // so writing zeros here too would cost a pass over the whole factor.
            self.l_values = vec![0.0; sym.len_val()];
        }
        let par = self.par.par();
        let req = sym.factorize_numeric_llt_scratch::<f64>(par, Default::default());
        let mut mem = MemBuffer::try_new(req).map_err(|_| FactorError::Other("out of memory".into()))?;
        let res = sym.factorize_numeric_llt::<f64>(
            &mut self.l_values,
            k.mat.as_ref(),
            Side::Lower,
            LltRegularization::default(),
            par,
            MemStack::new(&mut mem),
            Default::default(),
        );
        match res {
            Ok(_) => Ok(()),
            Err(LltError::NonPositivePivot { .. }) => Err(FactorError::NotPositiveDefinite),
        }
    }

    /// Dimension.
    pub fn n(&self) -> usize {
        self.symbolic.n()
    }

    /// Pivots of the factor, L_jj², in the original (unpermuted) equation order: the stiffness
    /// left on each equation after eliminating the ones ordered before it.
    pub fn pivots(&self) -> Vec<f64> {
        let sym = &self.symbolic.inner;
        let n = sym.nrows();
        let mut piv_perm = vec![0.0; n];
        match sym.raw() {
            SymbolicCholeskyRaw::Simplicial(s) => {
                let l = SimplicialLltRef::<'_, usize, f64>::new(s, &self.l_values);
                let (cp, ri) = (s.col_ptr(), s.row_idx());
                let vals = l.values();
                for (j, p) in piv_perm.iter_mut().enumerate() {
                    for k in cp[j]..cp[j + 1] {
                        if ri[k] == j {
                            *p = vals[k] * vals[k];
                        }
                    }
                }
            }
            SymbolicCholeskyRaw::Supernodal(s) => {
                let l = SupernodalLltRef::<'_, usize, f64>::new(s, &self.l_values);
                for sn in 0..s.n_supernodes() {
                    let node = l.supernode(sn);
                    let (start, m) = (node.start(), node.val());
                    for k in 0..m.ncols() {
                        let v = m[(k, k)];
                        piv_perm[start + k] = v * v;
                    }
                }
            }
        }
        match sym.perm() {
            Some(perm) => {
                let fwd = perm.arrays().0;
                let mut piv = vec![0.0; n];
                for (i, &f) in fwd.iter().enumerate() {
                    piv[f] = piv_perm[i];
                }
                piv
            }
            None => piv_perm,
        }
    }

    /// The symbolic factor (to reuse on another model with the same pattern).
    pub fn symbolic(&self) -> &SymbolicFactor {
        &self.symbolic
    }

    /// Solves K·X = B in place for `ncols` right-hand sides stored column-major in `rhs`.
    pub fn solve_in_place(&self, rhs: &mut [f64], ncols: usize) -> Result<(), FemError> {
        let n = self.n();
        if rhs.len() != n * ncols {
            return Err(FemError::PatternMismatch(format!(
                "right-hand side has {} values, expected {n}×{ncols}",
                rhs.len()
            )));
        }
        if n == 0 || ncols == 0 {
            return Ok(());
        }
        let par = self.par.par();
        let sym = &self.symbolic.inner;
        let mut mem = MemBuffer::try_new(sym.solve_in_place_scratch::<f64>(ncols, par))
            .map_err(|_| FemError::Solver("out of memory".into()))?;
        let llt = LltRef::<'_, usize, f64>::new(sym, &self.l_values);
        llt.solve_in_place_with_conj(
            Conj::No,
            MatMut::from_column_major_slice_mut(rhs, n, ncols),
            par,
            MemStack::new(&mut mem),
        );
        Ok(())
    }
}

/// Pattern of a general (non-symmetric) n×n sparse matrix with its symbolic LU factorisation
/// (COLAMD column ordering, faer's supernodal or simplicial LU with partial pivoting). Used for
/// the consistent, non-symmetric tangent of geometrically nonlinear steps and for indefinite
/// tangents (past limit points), where Cholesky does not apply.
#[derive(Debug, Clone)]
pub struct LuPattern {
    symbolic: SymbolicSparseColMat<usize>,
    argsort: Argsort<usize>,
    n_triplets: usize,
    lu: Arc<SymbolicLu<usize>>,
}

impl LuPattern {
    /// Pattern from (row, col) index pairs anywhere in the matrix; duplicates allowed (their
    /// values are summed).
    pub fn new(n: usize, pairs: &[(usize, usize)]) -> Result<LuPattern, FemError> {
        if let Some(&(r, c)) = pairs.iter().find(|&&(r, c)| r >= n || c >= n) {
            return Err(FemError::PatternMismatch(format!(
                "entry ({r}, {c}) is outside a {n}×{n} matrix"
            )));
        }
        let idx: Vec<Pair<usize, usize>> = pairs.iter().map(|&(row, col)| Pair { row, col }).collect();
        let (symbolic, argsort) = SymbolicSparseColMat::try_new_from_indices(n, n, &idx)
            .map_err(|e| FemError::Solver(format!("pattern: {e:?}")))?;
        let lu = factorize_symbolic_lu(symbolic.as_ref(), Default::default())
            .map_err(|e| FemError::Solver(format!("symbolic LU: {e:?}")))?;
        Ok(LuPattern {
            symbolic,
            argsort,
            n_triplets: pairs.len(),
            lu: Arc::new(lu),
        })
    }

    /// The pattern of a symmetric matrix given by its lower-triangle pairs, both triangles
    /// stored: the pairs are `lower` followed by the mirror (c, r) of every off-diagonal pair,
    /// so [`LuPattern::mirror_values`] turns lower-triangle values into values for this pattern.
    pub fn from_lower(n: usize, lower: &[(usize, usize)]) -> Result<LuPattern, FemError> {
        let mut pairs = lower.to_vec();
        pairs.extend(lower.iter().filter(|(r, c)| r != c).map(|&(r, c)| (c, r)));
        LuPattern::new(n, &pairs)
    }

    /// Values for a pattern built by [`LuPattern::from_lower`] from the same lower pairs.
    pub fn mirror_values(lower: &[(usize, usize)], values: &[f64]) -> Vec<f64> {
        let mut out = values.to_vec();
        out.extend(lower.iter().zip(values).filter(|((r, c), _)| r != c).map(|(_, v)| *v));
        out
    }

    /// Number of triplets the pattern was built from (= length of a value vector).
    pub fn n_triplets(&self) -> usize {
        self.n_triplets
    }

    /// Solves K·X = B in place (`ncols` right-hand sides, column-major in `rhs`) with K summed
    /// from triplet `values` in the order of the pairs. Fails on a singular K (zero pivot or a
    /// non-finite solution).
    pub fn solve_in_place(
        &self,
        values: &[f64],
        rhs: &mut [f64],
        ncols: usize,
        par: Parallelism,
    ) -> Result<(), FemError> {
        let n = self.symbolic.nrows();
        if values.len() != self.n_triplets || rhs.len() != n * ncols {
            return Err(FemError::PatternMismatch(format!(
                "{} values / {} right-hand-side entries for a {n}×{n} pattern of {} triplets",
                values.len(),
                rhs.len(),
                self.n_triplets
            )));
        }
        if n == 0 || ncols == 0 {
            return Ok(());
        }
        let k = SparseColMat::new_from_argsort(self.symbolic.clone(), &self.argsort, values)
            .map_err(|e| FemError::Solver(format!("fill: {e:?}")))?;
        let par = par.par();
        let mut numeric = NumericLu::<usize, f64>::new();
        let mut mem = MemBuffer::try_new(self.lu.factorize_numeric_lu_scratch::<f64>(par, Default::default()))
            .map_err(|_| FemError::Solver("out of memory".into()))?;
        let lu = self
            .lu
            .factorize_numeric_lu::<f64>(
                &mut numeric,
                k.as_ref(),
                par,
                MemStack::new(&mut mem),
                Default::default(),
            )
            .map_err(|e| FemError::Solver(format!("LU: {e:?}")))?;
        let mut mem = MemBuffer::try_new(self.lu.solve_in_place_scratch::<f64>(ncols, par))
            .map_err(|_| FemError::Solver("out of memory".into()))?;
        lu.solve_in_place_with_conj(
            Conj::No,
            MatMut::from_column_major_slice_mut(rhs, n, ncols),
            par,
            MemStack::new(&mut mem),
        );
        if rhs.iter().all(|v| v.is_finite()) {
            Ok(())
        } else {
            Err(FemError::Solver("matrix is singular (LU)".into()))
        }
    }
}
