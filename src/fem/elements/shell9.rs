//! Nine-node flat shell: data, checks and global matrices (see [`crate::fem::shell9`]).

use super::check_shell;
use crate::fem::error::FemError;
use crate::fem::shell9::{shell9_mass, shell9_stiffness};
use crate::material::Material;
use nalgebra::DMatrix;

/// Nine-node flat shell (see [`crate::fem::shell9`]): biquadratic membrane with drilling
/// rotation + MITC9 bending/shear, consistent mass. Nodes in gmsh's order: corners around the
/// element, then the midpoints of edges 0–1, 1–2, 2–3, 3–0, then the centre.
#[derive(Debug, Clone, PartialEq)]
pub struct Shell9 {
    pub nodes: [usize; 9],
    /// Thickness, mm.
    pub t: f64,
    pub material: Material,
}

/// A global nine-node shell matrix (stiffness or mass, 54×54) on its nodes.
#[derive(Debug, Clone, PartialEq)]
pub struct Shell9Matrix {
    pub nodes: [usize; 9],
    /// N/mm, N, N·mm/rad (stiffness) or tonne, tonne·mm (mass).
    pub k: DMatrix<f64>,
}

impl Shell9 {
    /// Checks material and thickness (`ie`: the element's index, for errors).
    pub fn check(&self, ie: usize) -> Result<(), FemError> {
        check_shell(ie, self.t, &self.material)
    }

    fn bad(&self, ie: usize, e: crate::fem::shell9::Shell9GeometryError) -> FemError {
        FemError::BadElement {
            element: ie,
            reason: format!("shell9 nodes {:?}: {e}", self.nodes),
        }
    }

    /// Global 54×54 stiffness at node coordinates `x` (mm).
    pub fn matrix(&self, ie: usize, x: &[[f64; 3]; 9]) -> Result<Shell9Matrix, FemError> {
        let k = shell9_stiffness(x, self.t, &self.material).map_err(|e| self.bad(ie, e))?;
        Ok(Shell9Matrix { nodes: self.nodes, k })
    }

    /// Global 54×54 consistent mass at node coordinates `x` (mm).
    pub fn mass(&self, ie: usize, x: &[[f64; 3]; 9]) -> Result<Shell9Matrix, FemError> {
        let rho = crate::fem::mass::checked_density(ie, self.material.density)?;
        let k = shell9_mass(x, self.t, rho).map_err(|e| self.bad(ie, e))?;
        Ok(Shell9Matrix { nodes: self.nodes, k })
    }
}
