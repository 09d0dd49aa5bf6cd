//! Typed errors of the FEM core. Messages name nodes, elements and DOFs.

use super::dof::{describe, NodeDof};
use thiserror::Error;

/// Everything that can go wrong between a [`super::Model`] and its results.
#[derive(Debug, Error)]
pub enum FemError {
    /// A node index outside `0..n_nodes`.
    #[error("{what} refers to node {node}, but the model has {n_nodes} nodes")]
    NodeOutOfRange { what: String, node: usize, n_nodes: usize },
    /// Non-finite coordinate.
    #[error("node {node} has a non-finite coordinate")]
    BadNode { node: usize },
    /// Element input that makes no sense (zero length, bad section, bad material …).
    #[error("element {element}: {reason}")]
    BadElement { element: usize, reason: String },
    /// The `up` vector of a beam is (nearly) parallel to its axis.
    #[error("element {element}: `up` vector is (nearly) parallel to the element axis (nodes {n1} → {n2}); give an `up` normal to the axis")]
    UpParallel { element: usize, n1: usize, n2: usize },
    /// Bad point mass, support, load … (with a description of the item).
    #[error("{0}")]
    BadInput(String),
    /// Conflicting or redundant constraints (rigid links vs supports, prescribed displacements).
    #[error("over-constrained: {0}")]
    OverConstrained(String),
    /// DOFs with no stiffness at all.
    #[error("{} {} unconstrained (mechanism)", describe(.dofs), if .dofs.len() == 1 { "is" } else { "are" })]
    Unconstrained { dofs: Vec<NodeDof> },
    /// A connected part of the structure has no support.
    #[error("nodes {nodes:?} form a part that is not connected to any support (free body)")]
    FreeBody { nodes: Vec<usize> },
    /// The factorisation found a mechanism; `dofs` are the DOFs that move in the null-space mode.
    #[error("the stiffness matrix is singular (mechanism); the free motion involves {}", describe(.dofs))]
    Mechanism { dofs: Vec<NodeDof> },
    /// Load-case problems (e.g. two prescribed values for one DOF).
    #[error("load case {case:?}: {reason}")]
    LoadCase { case: String, reason: String },
    /// Sparse solver failure that is not a mechanism (out of memory, bad pattern).
    #[error("sparse solver: {0}")]
    Solver(String),
    /// The values given do not fit the pattern (model topology changed).
    #[error("pattern mismatch: {0}")]
    PatternMismatch(String),
    /// The nonlinear solver could not reach equilibrium (after all step cuts), or the
    /// configuration became degenerate.
    #[error(
        "nonlinear solve, load case {case:?}: {reason} (step {step}, load factor {lambda:.6}, residual {residual:.3e})"
    )]
    NonConvergence {
        case: String,
        step: usize,
        lambda: f64,
        residual: f64,
        reason: String,
    },
    /// File output.
    #[error("i/o: {0}")]
    Io(#[from] std::io::Error),
}
