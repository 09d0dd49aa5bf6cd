//! Four-node flat shell: data, checks and global stiffness (see [`crate::fem::shell`]).

use super::check_shell;
use crate::fem::error::FemError;
use crate::fem::shell::{shell_stiffness, Mat24};
use crate::material::Material;

/// Four-node flat shell (see [`crate::fem::shell`]): membrane with drilling rotation + MITC4
/// bending/shear, lumped mass with tile rotary inertia. Nodes in order around the element (the normal follows the right-hand rule).
#[derive(Debug, Clone, PartialEq)]
pub struct Shell4 {
    pub nodes: [usize; 4],
    /// Thickness, mm.
    pub t: f64,
    pub material: Material,
}

/// A global shell element matrix (stiffness or mass) on its four nodes.
#[derive(Debug, Clone, PartialEq)]
pub struct ShellMatrix {
    pub nodes: [usize; 4],
    pub k: Mat24,
}

impl Shell4 {
    /// Checks material and thickness (`ie`: the element's index, for errors).
    pub fn check(&self, ie: usize) -> Result<(), FemError> {
        check_shell(ie, self.t, &self.material)
    }

    /// The error for nodes that do not form a convex quadrilateral.
    pub(crate) fn bad_quad(ie: usize, nodes: [usize; 4]) -> FemError {
        FemError::BadElement {
            element: ie,
            reason: format!(
                "shell nodes {nodes:?} do not form a convex quadrilateral (zero area, repeated nodes or crossed order)"
            ),
        }
    }

    /// Global 24×24 stiffness at node coordinates `x` (mm).
    pub fn matrix(&self, ie: usize, x: &[[f64; 3]; 4]) -> Result<ShellMatrix, FemError> {
        let k = shell_stiffness(x, self.t, &self.material).ok_or_else(|| Self::bad_quad(ie, self.nodes))?;
        Ok(ShellMatrix { nodes: self.nodes, k })
    }
}
