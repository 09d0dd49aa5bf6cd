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
    /// Gravity: acceleration [gx, gy, gz], mm/s², global axes (e.g. `[0, 0, -9810]`); every
    /// element with mass and every point mass takes M·g with the mass matrices of the modal
    /// analysis (the consistent load ρ·A·g on beams, the lumped mass × g on shells).
    #[serde(default)]
    pub gravity: Option<[f64; 3]>,
    /// Uniform line loads over whole beam elements (consistent nodal loads q·L/2, q·L²/12).
    #[serde(default)]
    pub line_loads: Vec<LineLoadSpec>,
    /// Total forces (and moments about the group's centroid) spread over a node group.
    #[serde(default)]
    pub group_forces: Vec<GroupForceSpec>,
    /// Nonlinear only: `load` (default: load steps to λ = 1) or `arc_length` (Crisfield's
    /// continuation through limit points until λ first reaches 1; loads only).
    #[serde(default)]
    pub control: Option<Control>,
    /// Nonlinear with `"control": "arc_length"`: the arc-length parameters.
    #[serde(default)]
    pub arc_length: Option<ArcLengthSpec>,
    /// Nonlinear only: the DOF `{"node": n, "dof": "uz"}` whose value along the path is the
    /// load–displacement curve (result `trace`; `NAME_path.csv` and `NAME_path.svg` with
    /// `--out`).
    #[serde(default)]
    pub trace: Option<TraceSpec>,
}

/// Axes of a line load.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default, Deserialize, schemars::JsonSchema)]
#[serde(rename_all = "lowercase")]
pub enum LineAxes {
    /// Global x, y, z.
    #[default]
    Global,
    /// The beam's local x (node 1 → node 2), y, z (local z = the component of `up` normal to the
    /// axis).
    Local,
}

/// A uniform load per unit length over the whole length of one beam element.
#[derive(Debug, Clone, Deserialize, schemars::JsonSchema)]
#[serde(deny_unknown_fields)]
pub struct LineLoadSpec {
    /// Index (in `elements`) of a `beam` element.
    pub element: usize,
    /// Force per length [qx, qy, qz], N/mm, in `axes`.
    pub q: [f64; 3],
    /// `global` (default) or `local` (the beam's axes).
    #[serde(default)]
    pub axes: LineAxes,
}

/// A total force and moment spread over a node group: a Gmsh physical group (weights: the
/// tributary length or area of each node of its lines or surfaces, equal for points) or a node
/// list (equal weights). The moment acts about the group's weighted centroid and is carried by
/// the forces of a rigid rotation of the group (weighted like the force); its part about an
/// axis the group has no lever arm for (one node, the direction of a straight edge) is applied
/// as nodal moments. The nodal loads sum to exactly `F`.
#[derive(Debug, Clone, Deserialize, schemars::JsonSchema)]
#[serde(deny_unknown_fields)]
pub struct GroupForceSpec {
    /// Name of a Gmsh physical group listed in `gmsh.groups` (`.msh` meshes only; a group may
    /// be listed with no fields, `{}`, just to be loaded).
    #[serde(default)]
    pub group: Option<String>,
    /// Node indices (instead of `group`).
    #[serde(default)]
    pub nodes: Vec<usize>,
    /// Total [Fx, Fy, Fz (N), Mx, My, Mz (N·mm)], global axes.
    #[serde(rename = "F")]
    pub f: [f64; 6],
}

/// A uniform pressure on shell elements, given by element list and/or Gmsh physical group.
#[derive(Debug, Clone, Deserialize, schemars::JsonSchema)]
#[serde(deny_unknown_fields)]
pub struct PressureSpec {
    /// Pressure, MPa (N/mm²). Positive acts along each element's normal n: the right-hand rule
    /// over the node order (n = +z for nodes listed counter-clockwise seen from +z; for a
    /// warped quad, the normal of its mean plane).
    pub p: f64,
    /// Indices (in `elements`) of the `shell4` and `shell9` elements loaded.
    #[serde(default)]
    pub elements: Vec<usize>,
    /// Name of a Gmsh physical group (listed in `gmsh.groups`) whose shell elements are loaded
    /// (`.msh` meshes only).
    #[serde(default)]
    pub group: Option<String>,
}

/// A uniform load along an edge of a shell: two adjacent nodes of a `shell4`, or two corners of
/// one edge of a `shell9` (whose midpoint node takes its share).
#[derive(Debug, Clone, Deserialize, schemars::JsonSchema)]
#[serde(deny_unknown_fields)]
pub struct EdgeLoadSpec {
    /// The edge's end nodes: two nodes adjacent in some `shell4` element's node list, or the two
    /// corners of an edge of a `shell9`.
    pub nodes: [usize; 2],
    /// Force per length [qx, qy, qz], N/mm, global axes.
    #[serde(default)]
    pub q: [f64; 3],
    /// Moment per length [mx, my, mz], N·mm/mm, global axes.
    #[serde(default)]
    pub m: [f64; 3],
}

/// How a nonlinear load case follows its path.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default, Deserialize, schemars::JsonSchema)]
#[serde(rename_all = "snake_case")]
pub enum Control {
    /// Load steps λ = 0 → 1 (adaptive), the default.
    #[default]
    Load,
    /// Crisfield's arc-length continuation through limit points until λ first reaches 1 (loads
    /// only: no prescribed displacements).
    ArcLength,
}

/// The arc-length constraint's shape.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default, Deserialize, schemars::JsonSchema)]
#[serde(rename_all = "snake_case")]
pub enum Constraint {
    /// ‖Δq‖ only (ψ = 0), the default.
    #[default]
    Cylindrical,
    /// ‖Δq‖ and the load increment (ψ = 1).
    Spherical,
}

/// Parameters of `"control": "arc_length"`. Arc lengths are dimensionless, in units of the
/// linear response to the full load (0.05 = 5 % of the displacement vector the undeformed
/// structure takes under the load case's loads).
#[derive(Debug, Clone, Default, Deserialize, schemars::JsonSchema)]
#[serde(deny_unknown_fields)]
pub struct ArcLengthSpec {
    /// First arc length, > 0 (default 1/steps).
    #[schemars(range(min = 0))]
    pub initial: Option<f64>,
    /// Smallest arc length, > 0, at most `initial`: steps are halved down to it before the
    /// solve fails (default 10⁻⁴ × initial).
    #[schemars(range(min = 0))]
    pub min: Option<f64>,
    /// Largest arc length, at least `initial` (default 20 × initial; raised to `initial` when
    /// smaller).
    #[schemars(range(min = 0))]
    pub max: Option<f64>,
    /// Newton iterations per step the arc length adapts to, 1 … 50 (default 5).
    #[schemars(range(min = 1, max = 50))]
    pub target_iterations: Option<usize>,
    /// Constraint: `cylindrical` (default) or `spherical`.
    #[serde(default)]
    pub constraint: Constraint,
    /// Steps before the solve fails without reaching λ = 1, 1 … 100000 (default 500).
    #[schemars(range(min = 1, max = 100000))]
    pub max_steps: Option<usize>,
}

/// The DOF whose value along the path is written as the load–displacement curve.
#[derive(Debug, Clone, Deserialize, schemars::JsonSchema)]
#[serde(deny_unknown_fields)]
pub struct TraceSpec {
    /// Node index.
    pub node: usize,
    /// `ux`, `uy`, `uz` (mm) or `rx`, `ry`, `rz` (rotation-vector component, degrees), global.
    pub dof: DofName,
}
