//! Symbolic analysis of the sparse Cholesky factor: the choice of fill-reducing ordering (AMD,
//! or nested dissection from [`crate::fem::nd`], or the smaller factor of the two) and the
//! elimination structure, [`SymbolicFactor`].

use super::matrix::SparsePattern;
use crate::fem::error::FemError;
use crate::fem::nd::{nested_dissection, FillOrdering, ND_MIN_N};
use faer::perm::PermRef;
use faer::sparse::linalg::cholesky::{
    factorize_symbolic_cholesky, CholeskySymbolicParams, SymbolicCholesky, SymmetricOrdering,
};
use faer::sparse::linalg::SupernodalThreshold;
use faer::Side;
use std::sync::Arc;

/// Ordering and elimination structure of the sparse Cholesky factor (fill-reducing ordering
/// AMD or nested dissection, see [`FillOrdering`]; faer picks simplicial or supernodal). Cheap
/// to clone (reference-counted).
#[derive(Debug, Clone)]
pub struct SymbolicFactor {
    pub(super) inner: Arc<SymbolicCholesky<usize>>,
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
