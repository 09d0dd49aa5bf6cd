//! Degrees of freedom: six per node, `ux uy uz rx ry rz` in global axes.

use std::fmt;

/// One of the six nodal degrees of freedom (translations in mm, rotations in rad).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub enum Dof {
    Ux = 0,
    Uy = 1,
    Uz = 2,
    Rx = 3,
    Ry = 4,
    Rz = 5,
}

impl Dof {
    /// All six DOFs in storage order.
    pub const ALL: [Dof; 6] = [Dof::Ux, Dof::Uy, Dof::Uz, Dof::Rx, Dof::Ry, Dof::Rz];

    /// Index 0..6 inside a node's DOF block.
    pub fn index(self) -> usize {
        self as usize
    }

    /// The DOF with index `i` (0..6), `None` otherwise.
    pub fn from_index(i: usize) -> Option<Dof> {
        Self::ALL.get(i).copied()
    }

    /// Lower-case name as used in case files: `"ux"` … `"rz"`.
    pub fn name(self) -> &'static str {
        ["ux", "uy", "uz", "rx", "ry", "rz"][self.index()]
    }

    /// Parses `"ux"` … `"rz"` (case-insensitive).
    pub fn parse(s: &str) -> Option<Dof> {
        Self::ALL
            .into_iter()
            .find(|d| d.name().eq_ignore_ascii_case(s))
    }
}

impl fmt::Display for Dof {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(self.name())
    }
}

/// A DOF of a given node (0-based node index).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub struct NodeDof {
    pub node: usize,
    pub dof: Dof,
}

impl NodeDof {
    /// Global DOF index `6·node + dof`.
    pub fn global(self) -> usize {
        6 * self.node + self.dof.index()
    }

    /// Inverse of [`NodeDof::global`].
    pub fn from_global(g: usize) -> NodeDof {
        NodeDof {
            node: g / 6,
            dof: Dof::ALL[g % 6],
        }
    }
}

impl fmt::Display for NodeDof {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "node {} {}", self.node, self.dof)
    }
}

/// Formats a list of node DOFs grouped per node: `"node 3 rx, ry; node 4 uz"`.
pub fn describe(dofs: &[NodeDof]) -> String {
    let mut v = dofs.to_vec();
    v.sort();
    v.dedup();
    let mut out = String::new();
    let mut i = 0;
    while i < v.len() {
        let node = v[i].node;
        if !out.is_empty() {
            out.push_str("; ");
        }
        out.push_str(&format!("node {node} "));
        let mut first = true;
        while i < v.len() && v[i].node == node {
            if !first {
                out.push_str(", ");
            }
            out.push_str(v[i].dof.name());
            first = false;
            i += 1;
        }
    }
    out
}
