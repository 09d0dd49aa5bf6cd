//! The load-case shapes of a `static` case or mesh file, and the DOF names they share with
//! supports: plain serde structs.

use crate::fem::Dof;
use serde::Deserialize;

/// A DOF name.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Deserialize, schemars::JsonSchema)]
#[serde(rename_all = "lowercase")]
pub enum DofName {
    /// Translation x.
    Ux,
    /// Translation y.
    Uy,
    /// Translation z.
    Uz,
    /// Rotation about x.
    Rx,
    /// Rotation about y.
    Ry,
    /// Rotation about z.
    Rz,
}

impl DofName {
    /// The FE model's DOF.
    pub fn dof(self) -> Dof {
        match self {
            DofName::Ux => Dof::Ux,
            DofName::Uy => Dof::Uy,
            DofName::Uz => Dof::Uz,
            DofName::Rx => Dof::Rx,
            DofName::Ry => Dof::Ry,
            DofName::Rz => Dof::Rz,
        }
    }
}

/// A nodal load.
#[derive(Debug, Clone, Deserialize, schemars::JsonSchema)]
#[serde(deny_unknown_fields)]
pub struct ForceSpec {
    /// Node index.
    pub node: usize,
    /// [Fx, Fy, Fz (N), Mx, My, Mz (N·mm)], global axes.
    #[serde(rename = "F")]
    pub f: [f64; 6],
    /// Local frame: three orthonormal, right-handed rows (local x, y, z in global axes); the
    /// DOF names (components) are then local.
    #[serde(default)]
    pub frame: Option<[[f64; 3]; 3]>,
    /// One direction instead of `frame`: `ux` (`rx`) is then along it.
    #[serde(default)]
    pub axis: Option<[f64; 3]>,
}

/// A prescribed displacement.
#[derive(Debug, Clone, Deserialize, schemars::JsonSchema)]
#[serde(deny_unknown_fields)]
pub struct DisplacementSpec {
    /// Node index.
    pub node: usize,
    /// Which DOF.
    pub dof: DofName,
    /// Value: mm for `ux`, `uy`, `uz`; degrees for `rx`, `ry`, `rz` (rotation about the global
    /// axis, or the local one with `frame`/`axis`, right-handed).
    pub value: f64,
    /// Local frame: three orthonormal, right-handed rows (local x, y, z in global axes); the
    /// DOF names (components) are then local.
    #[serde(default)]
    pub frame: Option<[[f64; 3]; 3]>,
    /// One direction instead of `frame`: `ux` (`rx`) is then along it.
    #[serde(default)]
    pub axis: Option<[f64; 3]>,
}

/// A load case.
#[derive(Debug, Clone, Deserialize, schemars::JsonSchema)]
#[serde(deny_unknown_fields)]
pub struct LoadCaseSpec {
    /// Name shown in results and used for the load case's output file (`NAME.vtu`); unique
    /// within the case, also after characters other than letters, digits, `-` and `_` are
    /// replaced by `_` for the file name.
    pub name: String,
    /// Nodal loads.
    #[serde(default)]
    pub forces: Vec<ForceSpec>,
    /// Prescribed displacements (mm) and rotations (degrees).
    #[serde(default)]
    pub displacements: Vec<DisplacementSpec>,
    /// Uniform pressures on shell elements (consistent nodal loads).
    #[serde(default)]
    pub pressures: Vec<PressureSpec>,
    /// Uniform loads along shell edges (consistent nodal loads).
    #[serde(default)]
    pub edge_loads: Vec<EdgeLoadSpec>,
}

/// A uniform pressure on shell elements, given by element list and/or Gmsh physical group.
#[derive(Debug, Clone, Deserialize, schemars::JsonSchema)]
#[serde(deny_unknown_fields)]
pub struct PressureSpec {
    /// Pressure, MPa (N/mm²). Positive acts along each element's normal n: the right-hand rule
    /// over the node order (n = +z for nodes listed counter-clockwise seen from +z; for a
    /// warped quad, the normal of its mean plane).
    pub p: f64,
    /// Indices (in `elements`) of the `shell4` elements loaded.
    #[serde(default)]
    pub elements: Vec<usize>,
    /// Name of a Gmsh physical group (listed in `gmsh.groups`) whose shell elements are loaded
    /// (`.msh` meshes only).
    #[serde(default)]
    pub group: Option<String>,
}

/// A uniform load along the straight edge between two nodes of one `shell4` element.
#[derive(Debug, Clone, Deserialize, schemars::JsonSchema)]
#[serde(deny_unknown_fields)]
pub struct EdgeLoadSpec {
    /// The edge's end nodes: two nodes adjacent in some `shell4` element's node list.
    pub nodes: [usize; 2],
    /// Force per length [qx, qy, qz], N/mm, global axes.
    #[serde(default)]
    pub q: [f64; 3],
    /// Moment per length [mx, my, mz], N·mm/mm, global axes.
    #[serde(default)]
    pub m: [f64; 3],
}
