//! Assembly of the reduced stiffness: the pattern (which equation pairs an element touches) is
//! computed once per topology; values are refilled in parallel per design, on the same pattern
//! (fenris's connectivity/values split).
//!
//! Triplet order: element by element, for each element the lower-triangle pairs (eq_a ≥ eq_b)
//! of its free DOFs in local order a-major; then one zero diagonal slot per equation so every
//! diagonal entry exists in the pattern.

use super::constraints::{DofMap, NONE};
use super::error::FemError;
use super::model::Model;
use super::solve::{SparseMatrix, SparsePattern};
use rayon::prelude::*;

/// Sparsity pattern of the reduced stiffness for one model topology and DOF map.
#[derive(Debug, Clone)]
pub struct Pattern {
    /// Element node lists the pattern was built for (checked on refill).
    topology: Vec<[usize; 2]>,
    /// Start of each element's values in the triplet list (length n_elements + 1).
    offsets: Vec<usize>,
    n_eq: usize,
    sparse: SparsePattern,
}

/// Calls `f(a, b, eq_a, eq_b)` for every lower-triangle pair of free element DOFs.
#[inline]
fn for_each_pair(eqs: &[usize; 12], n: usize, mut f: impl FnMut(usize, usize, usize, usize)) {
    for a in 0..n {
        let ea = eqs[a];
        if ea == NONE {
            continue;
        }
        for (b, &eb) in eqs.iter().enumerate().take(n) {
            if eb != NONE && ea >= eb {
                f(a, b, ea, eb);
            }
        }
    }
}

fn element_topology(model: &Model) -> Result<Vec<[usize; 2]>, FemError> {
    let n = model.nodes.len();
    model
        .elements
        .iter()
        .enumerate()
        .map(|(ie, e)| {
            let nodes = e.nodes();
            for &node in &nodes {
                if node >= n {
                    return Err(FemError::NodeOutOfRange {
                        what: format!("element {ie}"),
                        node,
                        n_nodes: n,
                    });
                }
            }
            Ok(match nodes.len() {
                1 => [nodes[0], NONE],
                _ => [nodes[0], nodes[1]],
            })
        })
        .collect()
}

impl Pattern {
    /// Builds the pattern (sequential; once per topology).
    pub fn new(model: &Model, map: &DofMap) -> Result<Pattern, FemError> {
        let topology = element_topology(model)?;
        let n_eq = map.n_eq();
        let mut pairs: Vec<(usize, usize)> = Vec::new();
        let mut offsets = Vec::with_capacity(topology.len() + 1);
        for nodes in &topology {
            offsets.push(pairs.len());
            let (eqs, nn) = Self::eqs(map, nodes);
            for_each_pair(&eqs, 6 * nn, |_, _, r, c| pairs.push((r, c)));
        }
        offsets.push(pairs.len());
        pairs.extend((0..n_eq).map(|i| (i, i)));
        let sparse = SparsePattern::new(n_eq, &pairs)?;
        Ok(Pattern {
            topology,
            offsets,
            n_eq,
            sparse,
        })
    }

    fn eqs(map: &DofMap, nodes: &[usize; 2]) -> ([usize; 12], usize) {
        if nodes[1] == NONE {
            let r = map.rep[nodes[0]];
            (map.element_eqs([r, r], 1), 1)
        } else {
            (map.element_eqs([map.rep[nodes[0]], map.rep[nodes[1]]], 2), 2)
        }
    }

    /// Number of equations.
    pub fn n_eq(&self) -> usize {
        self.n_eq
    }

    /// Number of triplets (length of the value vector).
    pub fn n_triplets(&self) -> usize {
        self.sparse.n_triplets()
    }

    /// Unique stored entries (lower triangle).
    pub fn nnz(&self) -> usize {
        self.sparse.nnz()
    }

    /// The underlying sparse pattern.
    pub fn sparse(&self) -> &SparsePattern {
        &self.sparse
    }

    /// Does this pattern fit `model` (same element node lists and equation count)?
    pub fn matches(&self, model: &Model, map: &DofMap) -> bool {
        map.n_eq() == self.n_eq && element_topology(model).map(|t| t == self.topology).unwrap_or(false)
    }

    /// Triplet values in pattern order, element matrices computed in parallel (rayon).
    pub fn values(&self, model: &Model, map: &DofMap) -> Result<Vec<f64>, FemError> {
        if !self.matches(model, map) {
            return Err(FemError::PatternMismatch(
                "the model's elements or equations differ from the pattern's".into(),
            ));
        }
        let ne = self.topology.len();
        let mut vals = vec![0.0; self.n_triplets()];
        let mut chunks: Vec<&mut [f64]> = Vec::with_capacity(ne);
        let mut rest = &mut vals[..self.offsets[ne]];
        for e in 0..ne {
            let (c, r) = rest.split_at_mut(self.offsets[e + 1] - self.offsets[e]);
            chunks.push(c);
            rest = r;
        }
        chunks
            .into_par_iter()
            .enumerate()
            .try_for_each(|(ie, chunk)| -> Result<(), FemError> {
                let em = model.element_matrix(ie)?;
                let (reps, k) = map.element_on_independent(&em);
                let eqs = map.element_eqs(reps, em.n_nodes);
                let mut p = 0;
                for_each_pair(&eqs, 6 * em.n_nodes, |a, b, _, _| {
                    chunk[p] = k[(a, b)];
                    p += 1;
                });
                Ok(())
            })?;
        Ok(vals)
    }

    /// Sums triplet values into the reduced stiffness matrix.
    pub fn matrix(&self, values: &[f64]) -> Result<SparseMatrix, FemError> {
        self.sparse.matrix(values)
    }

    /// Values + matrix in one go.
    pub fn assemble(&self, model: &Model, map: &DofMap) -> Result<SparseMatrix, FemError> {
        self.matrix(&self.values(model, map)?)
    }
}
