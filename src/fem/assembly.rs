//! Assembly of the reduced stiffness: the pattern (which equation pairs an element touches) is
//! computed once per topology; values are refilled in parallel per design, on the same pattern
//! (fenris's connectivity/values split).
//!
//! Triplet order: element by element, for each element the lower-triangle pairs (eq_a ≥ eq_b)
//! of its free DOFs in local order a-major (12 DOFs for beams, 24 for shells, 54 for nine-node
//! shells); then the 6×6
//! node block of each point mass; then one zero diagonal slot per equation so every diagonal
//! entry exists in the pattern. Stiffness and mass share the pattern, so K − σM is a sum of
//! value vectors.

use super::constraints::{DofMap, NONE};
use super::error::FemError;
use super::mass::{element_mass, point_mass, shell_mass_matrix};
use super::model::{Element, ElementMatrix, Model};
use super::solve::{SparseMatrix, SparsePattern};
use rayon::prelude::*;

/// Sparsity pattern of the reduced stiffness for one model topology and DOF map.
#[derive(Debug, Clone)]
pub struct Pattern {
    /// Element node lists the pattern was built for (checked on refill), padded with NONE.
    topology: Vec<[usize; 9]>,
    /// Nodes of the point masses the pattern was built for.
    mass_nodes: Vec<usize>,
    /// Start of each element's (then each point mass's) values in the triplet list
    /// (length n_elements + n_masses + 1).
    offsets: Vec<usize>,
    n_eq: usize,
    sparse: SparsePattern,
}

/// Which matrix to assemble on the pattern.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum MatrixKind {
    /// Stiffness K (point masses contribute zeros).
    Stiffness,
    /// Consistent mass M (springs and flexibility elements contribute zeros).
    Mass,
}

/// Calls `f(a, b, eq_a, eq_b)` for every lower-triangle pair of free element DOFs.
#[inline]
pub(crate) fn for_each_pair(eqs: &[usize], n: usize, mut f: impl FnMut(usize, usize, usize, usize)) {
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

fn element_topology(model: &Model) -> Result<Vec<[usize; 9]>, FemError> {
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
            let mut t = [NONE; 9];
            for (slot, &n) in t.iter_mut().zip(&nodes) {
                *slot = n;
            }
            Ok(t)
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
        let mass_nodes: Vec<usize> = model.masses.iter().map(|m| m.node).collect();
        for &node in &mass_nodes {
            if node >= model.nodes.len() {
                return Err(FemError::NodeOutOfRange {
                    what: "point mass".into(),
                    node,
                    n_nodes: model.nodes.len(),
                });
            }
            offsets.push(pairs.len());
            let eqs = map.nodes_eqs(&[map.rep[node]]);
            for_each_pair(&eqs, 6, |_, _, r, c| pairs.push((r, c)));
        }
        offsets.push(pairs.len());
        pairs.extend((0..n_eq).map(|i| (i, i)));
        let sparse = SparsePattern::new(n_eq, &pairs)?;
        Ok(Pattern {
            topology,
            mass_nodes,
            offsets,
            n_eq,
            sparse,
        })
    }

    fn eqs(map: &DofMap, nodes: &[usize; 9]) -> ([usize; 54], usize) {
        let nn = nodes.iter().take_while(|&&n| n != NONE).count();
        let mut reps = [0usize; 9];
        for (r, &n) in reps.iter_mut().zip(&nodes[..nn]) {
            *r = map.rep[n];
        }
        (map.nodes_eqs(&reps[..nn]), nn)
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

    /// Range of element `ie`'s values in the triplet list (empty for an element index past the
    /// last element).
    pub fn element_values(&self, ie: usize) -> std::ops::Range<usize> {
        if ie < self.topology.len() {
            self.offsets[ie]..self.offsets[ie + 1]
        } else {
            0..0
        }
    }

    /// Does this pattern fit `model` (same element node lists and equation count)?
    pub fn matches(&self, model: &Model, map: &DofMap) -> bool {
        map.n_eq() == self.n_eq
            && element_topology(model).map(|t| t == self.topology).unwrap_or(false)
            && model.masses.len() == self.mass_nodes.len()
            && model.masses.iter().zip(&self.mass_nodes).all(|(m, &n)| m.node == n)
    }

    /// Stiffness triplet values in pattern order, element matrices computed in parallel (rayon).
    pub fn values(&self, model: &Model, map: &DofMap) -> Result<Vec<f64>, FemError> {
        self.values_of(model, map, MatrixKind::Stiffness)
    }

    /// Triplet values of K or M in pattern order (element matrices in parallel).
    pub fn values_of(&self, model: &Model, map: &DofMap, kind: MatrixKind) -> Result<Vec<f64>, FemError> {
        if !self.matches(model, map) {
            return Err(FemError::PatternMismatch(
                "the model's elements or equations differ from the pattern's".into(),
            ));
        }
        let ne = self.topology.len();
        let nm = self.mass_nodes.len();
        let mut vals = vec![0.0; self.n_triplets()];
        let mut chunks: Vec<&mut [f64]> = Vec::with_capacity(ne + nm);
        let mut rest = &mut vals[..self.offsets[ne + nm]];
        for e in 0..ne + nm {
            let (c, r) = rest.split_at_mut(self.offsets[e + 1] - self.offsets[e]);
            chunks.push(c);
            rest = r;
        }
        let fill = |(ie, chunk): (usize, &mut [f64])| -> Result<(), FemError> {
            if ie >= ne {
                if kind == MatrixKind::Mass {
                    let node = self.mass_nodes[ie - ne];
                    let (rep, m) = map.node_on_independent(node, &point_mass(model, ie - ne));
                    let eqs = map.nodes_eqs(&[rep]);
                    let mut p = 0;
                    for_each_pair(&eqs, 6, |a, b, _, _| {
                        chunk[p] = m[(a, b)];
                        p += 1;
                    });
                }
                return Ok(());
            }
            if let Element::Shell4(_) = model.elements[ie] {
                let em = match kind {
                    MatrixKind::Stiffness => model.shell_matrix(ie)?,
                    MatrixKind::Mass => shell_mass_matrix(model, ie)?,
                };
                let (reps, k) = map.shell_on_independent(&em);
                let eqs = map.nodes_eqs(&reps);
                let mut p = 0;
                for_each_pair(&eqs, 24, |a, b, _, _| {
                    chunk[p] = k[(a, b)];
                    p += 1;
                });
                return Ok(());
            }
            if let Element::Shell9(_) = model.elements[ie] {
                let em = match kind {
                    MatrixKind::Stiffness => model.shell9_matrix(ie)?,
                    MatrixKind::Mass => model.shell9_mass_matrix(ie)?,
                };
                let (reps, k) = map.shell9_on_independent(&em);
                let eqs = map.nodes_eqs(&reps);
                let mut p = 0;
                for_each_pair(&eqs, 54, |a, b, _, _| {
                    chunk[p] = k[(a, b)];
                    p += 1;
                });
                return Ok(());
            }
            let em = match kind {
                MatrixKind::Stiffness => model.element_matrix(ie)?,
                MatrixKind::Mass => match element_mass(model, ie)? {
                    Some(m) => m,
                    None => return Ok(()),
                },
            };
            let (reps, k) = map.element_on_independent(&em);
            let eqs = map.element_eqs(reps, em.n_nodes);
            let mut p = 0;
            for_each_pair(&eqs, 6 * em.n_nodes, |a, b, _, _| {
                chunk[p] = k[(a, b)];
                p += 1;
            });
            Ok(())
        };
        // Small models stay on the calling thread (handing a few elements to the pool costs more
        // than computing them).
        if ne + nm < super::recovery::PARALLEL_MIN {
            chunks.into_iter().enumerate().try_for_each(fill)?;
        } else {
            chunks.into_par_iter().enumerate().try_for_each(fill)?;
        }
        Ok(vals)
    }

    /// The triplet values [`Pattern::values`] puts in element `ie`'s range
    /// ([`Pattern::element_values`]) when the two-node element's global matrix is `em`, written
    /// to `out` (that range's length). Linear in `em.k`: a derivative of the element matrix
    /// scatters into the derivative of the values.
    pub fn element_values_of(&self, map: &DofMap, em: &ElementMatrix, out: &mut [f64]) {
        let (reps, k) = map.element_on_independent(em);
        let eqs = map.element_eqs(reps, em.n_nodes);
        let mut p = 0;
        for_each_pair(&eqs, 6 * em.n_nodes, |a, b, _, _| {
            out[p] = k[(a, b)];
            p += 1;
        });
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
