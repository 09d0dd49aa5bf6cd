//! Sparse symmetric positive definite solve — the only module that names faer types (this file
//! and its children in `solve/`).
//!
//! Structure and values are kept apart (faer 0.24): [`SparsePattern`] holds the lower-triangle
//! pattern and the argsort that sums duplicate triplets; [`SymbolicFactor`] holds the
//! fill-reducing ordering (AMD or nested dissection) and elimination structure (cheap to clone,
//! reusable for every model with the same pattern); [`Factor`] holds the numeric L of LLᵀ and
//! can be refactorised in place.
//!
//! Files: `matrix.rs` (pattern and matrix storage), `symbolic.rs` (ordering choice and symbolic
//! analysis), `factor.rs` (numeric Cholesky and solves), `lu.rs` (sparse LU); this file holds
//! the threading choice, [`Parallelism`].

mod factor;
mod lu;
mod matrix;
mod symbolic;

pub use super::nd::FillOrdering;
pub use factor::{Factor, FactorError};
use faer::Par;
pub use lu::LuPattern;
pub use matrix::{FullSymmetric, SparseMatrix, SparsePattern};
pub use symbolic::SymbolicFactor;

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
