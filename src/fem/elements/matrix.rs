//! A general linear element: given symmetric stiffness and mass matrices on one or two nodes
//! (12×12, global axes, d = [u₁ v₁ w₁ θx₁ θy₁ θz₁ u₂ …]; one node: the top-left 6×6 block).
//! The pieces a superelement is assembled from ([`crate::fem::superelement`]); no stresses, no
//! geometric stiffness, linear analyses only.

use super::ElementMatrix;
use crate::fem::error::FemError;
use crate::fem::transform::Mat12;

/// Stiffness and mass given as matrices.
#[derive(Debug, Clone, PartialEq)]
pub struct MatrixElement {
    /// Nodes (`n_nodes` = 1: only `nodes[0]`).
    pub nodes: [usize; 2],
    pub n_nodes: usize,
    /// Stiffness, N/mm, N, N·mm/rad (global axes).
    pub k: Mat12,
    /// Mass, tonne, tonne·mm (global axes).
    pub m: Mat12,
}

impl MatrixElement {
    /// Checks finite, symmetric matrices (to 1e-9 of their largest entry) and 1 or 2 nodes.
    pub fn check(&self, ie: usize) -> Result<(), FemError> {
        if !(1..=2).contains(&self.n_nodes) {
            return Err(FemError::BadElement {
                element: ie,
                reason: format!("a matrix element has 1 or 2 nodes, not {}", self.n_nodes),
            });
        }
        for (what, a) in [("stiffness", &self.k), ("mass", &self.m)] {
            let scale = a.amax();
            if a.iter().any(|v| !v.is_finite()) || (a - a.transpose()).amax() > 1e-9 * scale {
                return Err(FemError::BadElement {
                    element: ie,
                    reason: format!("the {what} matrix must be finite and symmetric"),
                });
            }
        }
        Ok(())
    }

    /// Its stiffness (`mass = false`) or mass as an element matrix.
    pub fn matrix(&self, ie: usize, mass: bool) -> Result<ElementMatrix, FemError> {
        self.check(ie)?;
        Ok(ElementMatrix {
            nodes: self.nodes,
            n_nodes: self.n_nodes,
            k: if mass { self.m } else { self.k },
        })
    }
}

/// Where a superelement attached to a model lives (its matrices are [`MatrixElement`] pieces;
/// see [`crate::fem::superelement`]).
#[derive(Debug, Clone, Default, PartialEq)]
pub struct Attached {
    /// Name for notes (the case's JSON path and file).
    pub label: String,
    /// Interface nodes of the model, in the superelement's order.
    pub interface: Vec<usize>,
    /// Number of modal coordinates.
    pub modes: usize,
    /// Auxiliary modal nodes: modal coordinate `j` is DOF `j % 3` (ux, uy, uz) of
    /// `modal_nodes[j / 3]`.
    pub modal_nodes: Vec<usize>,
    /// The model elements of its pieces (contiguous).
    pub elements: std::ops::Range<usize>,
}
