//! The model shapes of a `static`/`modal` case or mesh file: plain serde structs, no
//! validation (that is [`super::build`]'s job). Load-case shapes are in [`super::load_shapes`].

use super::load_shapes::{DofName, LoadCaseSpec};
use crate::case::material::MaterialSpec;
use serde::Deserialize;
use std::collections::BTreeMap;

/// A cross-section, by `shape`.
#[derive(Debug, Clone, Deserialize, schemars::JsonSchema)]
#[serde(tag = "shape", rename_all = "snake_case", deny_unknown_fields)]
pub enum SectionSpec {
    /// Solid rectangle: `h` along local z, `w` along local y (Iy = w·h³/12), mm.
    Rect {
        /// Width along local y, mm, > 0.
        #[schemars(extend("exclusiveMinimum" = 0))]
        w: f64,
        /// Height along local z, mm, > 0.
        #[schemars(extend("exclusiveMinimum" = 0))]
        h: f64,
    },
    /// Solid circle of diameter `d`, mm.
    Circle {
        /// Diameter, mm, > 0.
        #[schemars(extend("exclusiveMinimum" = 0))]
        d: f64,
    },
    /// Circular tube: outer diameter `d`, wall thickness `t`, mm.
    Tube {
        /// Outer diameter, mm, > 0.
        #[schemars(extend("exclusiveMinimum" = 0))]
        d: f64,
        /// Wall thickness, mm, > 0 and < d/2.
        #[schemars(extend("exclusiveMinimum" = 0))]
        t: f64,
    },
    /// Explicit properties (mm², mm⁴); omitted shear areas mean no shear deformation.
    General {
        /// Area, mm², > 0.
        #[schemars(extend("exclusiveMinimum" = 0))]
        #[serde(rename = "A")]
        a: f64,
        /// Second moment about local y, mm⁴, > 0.
        #[schemars(extend("exclusiveMinimum" = 0))]
        #[serde(rename = "Iy")]
        iy: f64,
        /// Second moment about local z, mm⁴, > 0.
        #[schemars(extend("exclusiveMinimum" = 0))]
        #[serde(rename = "Iz")]
        iz: f64,
        /// Torsion constant, mm⁴, > 0.
        #[schemars(extend("exclusiveMinimum" = 0))]
        #[serde(rename = "J")]
        j: f64,
        /// Shear area for local y, mm², > 0.
        #[serde(rename = "Asy", default)]
        #[schemars(extend("exclusiveMinimum" = 0))]
        asy: Option<f64>,
        /// Shear area for local z, mm², > 0.
        #[serde(rename = "Asz", default)]
        #[schemars(extend("exclusiveMinimum" = 0))]
        asz: Option<f64>,
    },
    /// Shell of thickness `t`, mm (shell elements).
    Shell {
        /// Thickness, mm, > 0.
        #[schemars(extend("exclusiveMinimum" = 0))]
        t: f64,
    },
}

/// An element, by `type`.
#[derive(Debug, Clone, Deserialize, schemars::JsonSchema)]
#[serde(tag = "type", rename_all = "snake_case", deny_unknown_fields)]
pub enum ElementSpec {
    /// 2-node 3D beam (Timoshenko; `"shear": false` for Euler–Bernoulli).
    Beam {
        /// Node indices (0-based).
        nodes: [usize; 2],
        /// Section name (key of `sections`).
        section: String,
        /// Material name (key of `materials`).
        material: String,
        /// Vector fixing local z (its component normal to the axis).
        up: [f64; 3],
        /// Include shear deformation (default true).
        #[serde(default = "yes")]
        shear: bool,
    },
    /// 6-DOF spring between two nodes, or from one node to ground; stiffness in global axes
    /// (N/mm, N·mm/rad).
    Spring {
        /// One node (to ground) or two.
        #[schemars(length(min = 1, max = 2))]
        nodes: Vec<usize>,
        /// [kx, ky, kz, krx, kry, krz], each ≥ 0.
        #[schemars(extend("items" = {"type": "number", "minimum": 0}))]
        k: [f64; 6],
    },
    /// Point mass, tonne (rotary inertia tonne·mm² optional).
    Mass {
        /// Node index.
        node: usize,
        /// Mass, tonne, ≥ 0.
        #[schemars(range(min = 0))]
        mass: f64,
        /// Rotary inertia about x, y, z, tonne·mm², each ≥ 0.
        #[serde(default)]
        #[schemars(extend("items" = {"type": "number", "minimum": 0}))]
        inertia: [f64; 3],
    },
    /// Rigid link: every slave moves with the master as a rigid body.
    Rigid {
        /// Master node.
        master: usize,
        /// Slave nodes.
        slaves: Vec<usize>,
    },
    /// Flexure hinge from `nodes[0]` to `nodes[1]` (local x): the notch of `hinge` centred at the
    /// midpoint, blank of the hinge's section on both sides up to the nodes; one flexibility
    /// element with the compliance of the `hinge` analysis (blank_length = (distance − notch
    /// length)/2). Local axes as for beams: the notch thins along local z (`up`), the compliant
    /// axis is local y.
    Hinge {
        /// Node indices (0-based); their distance must be at least the notch length.
        nodes: [usize; 2],
        /// The hinge, as the `hinge` object of a `hinge` case without `blank_length`.
        #[schemars(schema_with = "super::hinge::element_hinge_schema")]
        hinge: serde_json::Value,
        /// Material name (key of `materials`).
        material: String,
        /// Vector fixing local z (the direction the notch thins along).
        up: [f64; 3],
        /// Co-rotational flexibility elements the hinge is made of, 1 … 64 (default 1; 4 in
        /// geometrically nonlinear runs, which converges the parasitic motions and stresses to
        /// within 1 % of 16 segments, where one segment loses ~6 %): the
        /// region split into equal lengths (compliances of the sub-intervals, torsion scaled to
        /// keep the single element's), so a hinge bending through degrees is followed more
        /// closely in nonlinear analyses; the linear response is that of one element up to the
        /// quadrature. Inner nodes (and the further elements) come after the case's own.
        #[serde(default)]
        #[schemars(range(min = 1, max = 64))]
        segments: Option<usize>,
    },
    /// Ideal joint between two coincident nodes, by elimination (no penalty): the DOFs the joint
    /// does not release are tied in the joint frame (local x along `axis`).
    Joint {
        /// The two coincident nodes.
        nodes: [usize; 2],
        /// The joint kind.
        kind: JointKind,
        /// Joint axis (revolute, cylindrical, prismatic; universal: the first pin).
        #[serde(default)]
        axis: Option<[f64; 3]>,
        /// Second pin of a universal joint, perpendicular to `axis`.
        #[serde(default)]
        axis2: Option<[f64; 3]>,
        /// The joint frame in full instead of `axis`/`axis2`: three orthonormal, right-handed
        /// rows; the joint axis is local x (universal: the second pin local y). For a node that
        /// also carries a support or prescribed DOF in this frame (a slider with a hinge).
        #[serde(default)]
        frame: Option<[[f64; 3]; 3]>,
    },
    /// 4-node flat shell (a triangle as the degenerate quad [a, b, c, c]).
    Shell4 {
        /// Node indices.
        nodes: [usize; 4],
        /// Section name (a `shell` section).
        section: String,
        /// Material name.
        material: String,
    },
    /// 9-node flat shell (MITC9 plate, biquadratic membrane, consistent mass): corners around
    /// the element, then the midpoints of edges 0–1, 1–2, 2–3, 3–0, then the centre (gmsh's
    /// nine-node quadrangle). Flat only: a node more than 10⁻³ of the longer diagonal off the
    /// element's plane is refused. Linear analyses (static, modal, frf, transient,
    /// craig_bampton); no buckling or geometrically nonlinear solve.
    Shell9 {
        /// Node indices.
        nodes: [usize; 9],
        /// Section name (a `shell` section).
        section: String,
        /// Material name.
        material: String,
    },
    /// A reduced superelement: the `result.json` of a `craig_bampton` analysis (stiffness and
    /// mass on the six DOFs of each interface node plus its fixed-interface modal coordinates)
    /// attached to `nodes` (linear analyses: static, modal, transient, frf).
    Superelement {
        /// The superelement file (a `craig_bampton` result JSON), relative to the case file.
        file: String,
        /// Host node indices, one per interface node of the superelement, in its order
        /// (`interface_nodes` of the file); each must coincide with its interface node after
        /// `placement`.
        #[schemars(length(min = 1))]
        nodes: Vec<usize>,
        /// Where the superelement's model sits in this one (default: as it was reduced).
        #[serde(default)]
        placement: Option<PlacementSpec>,
        /// The file's content (read with the case; not a case-file field).
        #[serde(skip)]
        #[schemars(skip)]
        loaded: Option<std::sync::Arc<super::superelement_file::SuperelementFile>>,
    },
}

/// Placement of a superelement's model in the host model: x_host = R·x + `translation`, R the
/// right-handed rotation by `angle` about `axis`.
#[derive(Debug, Clone, Deserialize, schemars::JsonSchema)]
#[serde(deny_unknown_fields)]
pub struct PlacementSpec {
    /// Translation, mm (default [0, 0, 0]).
    #[serde(default)]
    pub translation: [f64; 3],
    /// Rotation axis (any length > 0; default [0, 0, 1]).
    #[serde(default)]
    pub axis: Option<[f64; 3]>,
    /// Rotation angle about `axis`, degrees (default 0).
    #[serde(default)]
    pub angle: f64,
}

/// Kind of an ideal joint: what it releases.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Deserialize, schemars::JsonSchema)]
#[serde(rename_all = "snake_case")]
pub enum JointKind {
    /// Rotation about `axis` free.
    Revolute,
    /// All rotations free.
    Spherical,
    /// Rotations about `axis` and `axis2` free.
    Universal,
    /// Rotation about and translation along `axis` free.
    Cylindrical,
    /// Translation along `axis` free.
    Prismatic,
    /// Nothing free.
    Weld,
}

fn yes() -> bool {
    true
}

/// A support.
#[derive(Debug, Clone, Deserialize, schemars::JsonSchema)]
#[serde(deny_unknown_fields)]
pub struct SupportSpec {
    /// Node index.
    pub node: usize,
    /// DOFs fixed.
    pub fix: Vec<DofName>,
    /// Local frame: three orthonormal, right-handed rows (local x, y, z in global axes); the
    /// DOF names (components) are then local.
    #[serde(default)]
    pub frame: Option<[[f64; 3]; 3]>,
    /// One direction instead of `frame`: `ux` (`rx`) is then along it.
    #[serde(default)]
    pub axis: Option<[f64; 3]>,
}

/// The model part of a `static` or `modal` case (also the content of a mesh file).
#[derive(Debug, Clone, Default, Deserialize, schemars::JsonSchema)]
#[serde(deny_unknown_fields)]
pub struct MeshSpec {
    /// Named materials.
    #[serde(default)]
    pub materials: BTreeMap<String, MaterialSpec>,
    /// Named sections.
    #[serde(default)]
    pub sections: BTreeMap<String, SectionSpec>,
    /// Node coordinates, mm.
    #[serde(default)]
    pub nodes: Vec<[f64; 3]>,
    /// Elements.
    #[serde(default)]
    pub elements: Vec<ElementSpec>,
    /// Rigid links (also accepted as elements of type `rigid`).
    #[serde(default)]
    pub rigid_links: Vec<RigidSpec>,
    /// Supports.
    #[serde(default)]
    pub supports: Vec<SupportSpec>,
    /// Load cases (`static`: at least one, inline or in the mesh file; what they mean to the
    /// other analyses is set per analysis in the case-file schema).
    #[serde(default)]
    pub load_cases: Vec<LoadCaseSpec>,
    /// Fill-reducing ordering of the sparse Cholesky factor: `"auto"` (default: AMD for small
    /// models, else the smaller factor of AMD and nested dissection), `"amd"` (approximate
    /// minimum degree) or `"nd"` (nested dissection, METIS).
    #[serde(default)]
    pub ordering: Option<OrderingSpec>,
    /// `"as_given"` (default) or `"shell9"`: every `shell4` becomes a nine-node `shell9` on the
    /// same corners (a node added at each edge midpoint and element centre; supports, rigid
    /// links and prescribed displacements carried to them; triangles and warped quadrangles
    /// refused). Given in the case, it overrides the mesh file's.
    #[serde(default)]
    pub shell_elements: Option<ShellElements>,
    /// What `"shell_elements": "shell9"` added (set by the case reader; not a case-file field).
    #[serde(skip)]
    #[schemars(skip)]
    pub promoted: Option<Promoted>,
    /// Gmsh meshes: the mapped physical groups of each element (filled by the `.msh` reader;
    /// not a case-file field).
    #[serde(skip)]
    #[schemars(skip)]
    pub element_groups: Vec<Vec<String>>,
    /// Gmsh meshes: the cells (node lists of points, 2-node lines, 3-node triangles and 4-node
    /// quadrangles) of every mapped physical group, for group loads (filled by the `.msh`
    /// reader; not a case-file field).
    #[serde(skip)]
    #[schemars(skip)]
    pub group_cells: BTreeMap<String, Vec<Vec<usize>>>,
    /// The JSON mesh file the nodes and elements come from, as the case names it (set by the
    /// case reader; not a case-file field): warnings about its elements name it, as errors in it
    /// do, since a path such as `elements[0].hinge` is not in the case as written.
    #[serde(skip)]
    #[schemars(skip)]
    pub mesh_file: Option<String>,
    /// The `hinge_types` name each hinge element's `hinge` was given by, by element index (set
    /// by the case reader; not a case-file field): warnings about the element name it.
    #[serde(skip)]
    #[schemars(skip)]
    pub hinge_type_names: BTreeMap<usize, String>,
}

/// `"ordering"`: the fill-reducing ordering of the sparse Cholesky factor.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Deserialize, schemars::JsonSchema)]
#[serde(rename_all = "lowercase", try_from = "serde_json::Value")]
#[schemars(extend("type" = "string", "enum" = ["auto", "amd", "nd"]))]
pub enum OrderingSpec {
    /// AMD for small models, else whichever of AMD and nested dissection fills less.
    Auto,
    /// Approximate minimum degree.
    Amd,
    /// Nested dissection (METIS).
    Nd,
}

impl TryFrom<serde_json::Value> for OrderingSpec {
    type Error = String;
    fn try_from(v: serde_json::Value) -> Result<OrderingSpec, String> {
        match v.as_str() {
            Some("auto") => Ok(OrderingSpec::Auto),
            Some("amd") => Ok(OrderingSpec::Amd),
            Some("nd") => Ok(OrderingSpec::Nd),
            _ => Err(format!("{v} is not an ordering: expected \"auto\", \"amd\" or \"nd\"")),
        }
    }
}

impl OrderingSpec {
    /// The FE solver's ordering.
    pub fn fill_ordering(self) -> crate::fem::solve::FillOrdering {
        use crate::fem::solve::FillOrdering;
        match self {
            OrderingSpec::Auto => FillOrdering::Auto,
            OrderingSpec::Amd => FillOrdering::Amd,
            OrderingSpec::Nd => FillOrdering::Nd,
        }
    }
}

/// A rigid link.
#[derive(Debug, Clone, Deserialize, schemars::JsonSchema)]
#[serde(deny_unknown_fields)]
pub struct RigidSpec {
    /// Master node.
    pub master: usize,
    /// Slave nodes.
    pub slaves: Vec<usize>,
}

/// What a physical group becomes.
#[derive(Debug, Clone, Deserialize, schemars::JsonSchema)]
#[serde(deny_unknown_fields)]
pub struct GroupSpec {
    /// Section name (a `shell` section for triangles/quads, a beam section for lines).
    #[serde(default)]
    pub section: Option<String>,
    /// Material name.
    #[serde(default)]
    pub material: Option<String>,
    /// Beam orientation vector (lines).
    #[serde(default)]
    pub up: Option<[f64; 3]>,
    /// Fixed DOFs of every node of the group.
    #[serde(default)]
    pub fix: Vec<DofName>,
}

/// The `gmsh` mapping of a case with a `.msh` mesh.
#[derive(Debug, Clone, Deserialize, schemars::JsonSchema)]
#[serde(deny_unknown_fields)]
pub struct GmshMapping {
    /// Physical group name → what it becomes.
    pub groups: BTreeMap<String, GroupSpec>,
}

/// `"shell_elements"`: which element the model's shells are solved with.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default, Deserialize, schemars::JsonSchema)]
#[serde(rename_all = "snake_case")]
pub enum ShellElements {
    /// As written: `shell4` four-node, `shell9` nine-node (the default).
    #[default]
    AsGiven,
    /// Every `shell4` becomes a `shell9` on the same corners, a node added at each edge midpoint
    /// and element centre.
    Shell9,
}

impl MeshSpec {
    /// The model note of `"shell_elements": "shell9"`, if the model was promoted.
    pub fn promotion_note(&self) -> Option<String> {
        self.promoted.as_ref().map(Promoted::note)
    }
}

/// What the promotion added to a model.
#[derive(Debug, Clone, PartialEq, Default)]
pub struct Promoted {
    /// Index of the first added node (the model's own nodes come before).
    pub first_node: usize,
    /// Parents of each added node, in node order: the two ends of an edge or four corners.
    pub parents: Vec<Vec<usize>>,
    /// Number of four-node shells that became nine-node shells.
    pub shells: usize,
    /// Index of the first support the added nodes inherited (`supports` written in the case
    /// come before).
    pub first_support: usize,
}

impl Promoted {
    /// Sets every added node of `nodes` (mm) to the mean of its parents.
    pub fn place(&self, nodes: &mut [[f64; 3]]) {
        for (k, parents) in self.parents.iter().enumerate() {
            let mut x = [0.0; 3];
            for &p in parents {
                for c in 0..3 {
                    x[c] += nodes[p][c] / parents.len() as f64;
                }
            }
            nodes[self.first_node + k] = x;
        }
    }

    /// Each added edge midpoint with the two ends of its edge: (midpoint, a, b).
    pub fn midpoints(&self) -> impl Iterator<Item = (usize, usize, usize)> + '_ {
        self.parents
            .iter()
            .enumerate()
            .filter(|(_, ps)| ps.len() == 2)
            .map(|(k, ps)| (self.first_node + k, ps[0], ps[1]))
    }

    /// The model note of a promoted model.
    pub fn note(&self) -> String {
        let shells = match self.shells {
            1 => "the four-node shell was solved as a nine-node shell".to_string(),
            n => format!("the {n} four-node shells were solved as nine-node shells"),
        };
        format!(
            "\"shell_elements\": \"shell9\": {shells} on the same corners ({} nodes added, numbered from {}: edge midpoints, then element centres)",
            self.parents.len(),
            self.first_node
        )
    }
}
