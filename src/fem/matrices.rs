//! The reduced (constrained) stiffness and mass matrices of a model as [`sprs::CsMat`], with
//! the DOF behind each equation, and their export in Matrix Market format (`K.mtx`, `M.mtx`,
//! `dofs.csv`) through `sprs::io`.
//!
//! The equations are those of the static and modal solves: supported DOFs removed, rigid-link
//! slaves eliminated onto their masters, tied DOFs merged, DOFs of framed nodes in the node's
//! frame. Units: K in N/mm, N/rad, N·mm/rad; M in tonne (and tonne·mm² for rotations).

use super::assembly::{MatrixKind, Pattern};
use super::constraints::DofMap;
use super::dof::NodeDof;
use super::error::FemError;
use super::model::Model;
use super::solve::SparseMatrix;
use std::path::Path;

/// K and M on the equations of a [`DofMap`], in the solver's storage (lower triangle, one
/// shared pattern).
#[derive(Debug, Clone)]
pub struct Reduced {
    /// The DOF numbering.
    pub map: DofMap,
    /// Stiffness.
    pub k: SparseMatrix,
    /// Consistent mass.
    pub m: SparseMatrix,
}

impl Reduced {
    /// Assembles K and M of `model` with its supports (no prescribed DOFs).
    pub fn new(model: &Model) -> Result<Reduced, FemError> {
        model.validate()?;
        let map = DofMap::new(model, &[], None)?;
        let pattern = Pattern::new(model, &map)?;
        let k = pattern.matrix(&pattern.values_of(model, &map, MatrixKind::Stiffness)?)?;
        let m = pattern.matrix(&pattern.values_of(model, &map, MatrixKind::Mass)?)?;
        Ok(Reduced { map, k, m })
    }

    /// The matrices as [`ReducedMatrices`] (both triangles, compressed rows).
    pub fn matrices(&self) -> ReducedMatrices {
        ReducedMatrices {
            k: self.k.to_csmat(),
            m: self.m.to_csmat(),
            dofs: (0..self.map.n_eq()).map(|i| self.map.describe_eq(i)).collect(),
            node_frame: (0..self.map.n_eq())
                .map(|i| self.map.framed.contains(&(self.map.eq_dof[i] / 6)))
                .collect(),
        }
    }
}

/// The reduced stiffness and mass of a model, for use outside flexfem.
#[derive(Debug, Clone, PartialEq)]
pub struct ReducedMatrices {
    /// Stiffness (symmetric, both triangles stored).
    pub k: sprs::CsMat<f64>,
    /// Consistent mass (symmetric, both triangles stored).
    pub m: sprs::CsMat<f64>,
    /// Node and DOF of each equation (row/column of K and M).
    pub dofs: Vec<NodeDof>,
    /// Whether the equation's DOF is in its node's frame (else in global axes).
    pub node_frame: Vec<bool>,
}

/// The file names [`ReducedMatrices::write`] writes.
pub const MATRIX_FILES: [&str; 3] = ["K.mtx", "M.mtx", "dofs.csv"];

/// The reduced K, M and DOF map of `model` (see the module docs).
pub fn reduced_matrices(model: &Model) -> Result<ReducedMatrices, FemError> {
    Ok(Reduced::new(model)?.matrices())
}

impl ReducedMatrices {
    /// `dofs.csv`: one line per equation (0-based, as the rows of K and M less one):
    /// `equation,node,dof,axes` with axes `global` or `node` (the node's frame).
    pub fn dofs_csv(&self) -> String {
        let mut s = String::from("equation,node,dof,axes\n");
        for (i, (d, framed)) in self.dofs.iter().zip(&self.node_frame).enumerate() {
            let axes = if *framed { "node" } else { "global" };
            s += &format!("{i},{},{},{axes}\n", d.node, d.dof.name());
        }
        s
    }

    /// Matrix Market text (`coordinate real general`, both triangles, each value written to
    /// round-trip exactly) by `sprs::io`.
    pub fn matrix_market(m: &sprs::CsMat<f64>) -> Result<Vec<u8>, FemError> {
        let mut out = Vec::new();
        sprs::io::write_matrix_market_to_bufwrite(&mut out, m)?;
        Ok(out)
    }

    /// The three files (`K.mtx`, `M.mtx`, `dofs.csv`) as (name, contents).
    pub fn files(&self) -> Result<Vec<(String, Vec<u8>)>, FemError> {
        Ok(vec![
            (MATRIX_FILES[0].to_string(), Self::matrix_market(&self.k)?),
            (MATRIX_FILES[1].to_string(), Self::matrix_market(&self.m)?),
            (MATRIX_FILES[2].to_string(), self.dofs_csv().into_bytes()),
        ])
    }

    /// Writes the three files into `dir`.
    pub fn write(&self, dir: &Path) -> Result<(), FemError> {
        for (name, bytes) in self.files()? {
            std::fs::write(dir.join(name), bytes)?;
        }
        Ok(())
    }
}
