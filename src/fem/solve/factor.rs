//! Numeric LLᵀ factorisation on a [`SymbolicFactor`]: [`Factor`] (refactorisation in place,
//! pivots, solves) and [`FactorError`].

use super::matrix::SparseMatrix;
use super::symbolic::SymbolicFactor;
use super::Parallelism;
use crate::fem::error::FemError;
use faer::dyn_stack::{MemBuffer, MemStack};
use faer::linalg::cholesky::llt::factor::{LltError, LltRegularization};
use faer::sparse::linalg::cholesky::simplicial::SimplicialLltRef;
use faer::sparse::linalg::cholesky::supernodal::SupernodalLltRef;
use faer::sparse::linalg::cholesky::{LltRef, SymbolicCholeskyRaw};
use faer::{Conj, MatMut, Side};

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
