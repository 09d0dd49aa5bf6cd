//! Sparse LU for general (non-symmetric or indefinite) matrices: [`LuPattern`].

use super::Parallelism;
use crate::fem::error::FemError;
use faer::dyn_stack::{MemBuffer, MemStack};
use faer::sparse::linalg::lu::{factorize_symbolic_lu, NumericLu, SymbolicLu};
use faer::sparse::{Argsort, Pair, SparseColMat, SymbolicSparseColMat};
use faer::{Conj, MatMut};
use std::sync::Arc;

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
