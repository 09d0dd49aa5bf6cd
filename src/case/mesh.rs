//! The generic beam model (`static`, `modal`): inline or from `meshes/*.json`.

use super::error::{check, CaseError};
use super::material::MaterialSpec;
use crate::fem::{self, Dof};
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
    fn dof(self) -> Dof {
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
    /// 4-node flat shell (a triangle as the degenerate quad [a, b, c, c]).
    Shell4 {
        /// Node indices.
        nodes: [usize; 4],
        /// Section name (a `shell` section).
        section: String,
        /// Material name.
        material: String,
    },
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
    /// axis, right-handed).
    pub value: f64,
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
    /// Load cases (`static`: at least one, inline or in the mesh file; `modal` ignores them).
    #[serde(default)]
    pub load_cases: Vec<LoadCaseSpec>,
    /// Gmsh meshes: the mapped physical groups of each element (filled by the `.msh` reader;
    /// not a case-file field).
    #[serde(skip)]
    #[schemars(skip)]
    pub element_groups: Vec<Vec<String>>,
}

/// `"analysis": "modal"`: the lowest `modes` natural frequencies and mass-normalised shapes of
/// a model given as for `static` (supports optional: a free body gives six rigid-body modes
/// first; load cases are ignored).
#[derive(Debug, Clone, schemars::JsonSchema)]
#[serde(deny_unknown_fields)]
#[schemars(extend("allOf" = model_rules(false)))]
pub struct ModalCase {
    /// Mesh file, as for `static`: a JSON mesh file or a Gmsh `.msh` file.
    pub mesh: Option<String>,
    /// Physical-group mapping of a Gmsh `.msh` mesh (only with a `.msh` mesh, which needs it).
    pub gmsh: Option<GmshMapping>,
    /// Number of modes (the lowest), 1 … 1000.
    #[schemars(range(min = 1, max = 1000))]
    pub modes: usize,
    /// Optional shift frequency f, Hz (σ = (2πf)²): the modes nearest above it are found instead of
    /// the lowest; ≥ 0. Default: 0 (a small negative shift for free bodies).
    #[schemars(range(min = 0))]
    pub shift_hz: Option<f64>,
    /// Mode shapes in the JSON result (default true). `false` leaves them out (a 100k-DOF model
    /// would write tens of MB); `modes.vtu` (with `--out`) always holds them.
    #[serde(default = "shapes_default")]
    pub shapes: bool,
    /// The model.
    #[serde(flatten)]
    pub model: MeshSpec,
}

/// Mode shapes are in the JSON result unless `"shapes": false`.
fn shapes_default() -> bool {
    true
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

/// `"analysis": "static"`: a model inline or from a `mesh` file, plus load cases.
#[derive(Debug, Clone, schemars::JsonSchema)]
#[serde(deny_unknown_fields)]
#[schemars(extend("allOf" = model_rules(true)))]
pub struct StaticCase {
    /// Path of a JSON mesh file (relative to the case file's folder, then to the working folder)
    /// holding `materials`, `sections`, `nodes`, `elements`, `supports` and optionally `load_cases`.
    pub mesh: Option<String>,
    /// Physical-group mapping of a Gmsh `.msh` mesh (only with a `.msh` mesh, which needs it):
    /// `{"groups": {"NAME": {"section", "material", "up"} or {"fix": [...]}}}`.
    pub gmsh: Option<GmshMapping>,
    /// The inline model (or additions to the mesh: materials, sections, load cases).
    #[serde(flatten)]
    pub model: MeshSpec,
    /// Geometrically nonlinear statics (co-rotational beams, Newton–Raphson in load steps).
    #[serde(default)]
    pub nonlinear: bool,
    /// Load steps of the nonlinear analysis, 1 … 10000 (default 20; only with
    /// `"nonlinear": true`). After parsing: the steps to use when nonlinear, `None` when linear.
    #[serde(default)]
    #[schemars(range(min = 1, max = 10000))]
    pub steps: Option<usize>,
}

/// Schema rules of a `static` (`need_loads`) or `modal` case that relate fields: the model is
/// inline (at least one node; static: at least one load case) or comes from `mesh` (then no
/// inline nodes, elements, supports or rigid links); a `.msh` mesh needs `gmsh` and `gmsh` needs
/// a `.msh` mesh; `steps` only with `"nonlinear": true`.
fn model_rules(need_loads: bool) -> serde_json::Value {
    let mut inline = serde_json::json!({"required": ["nodes"], "properties": {"nodes": {"minItems": 1}}});
    if need_loads {
        inline = serde_json::json!({"allOf": [inline, {"required": ["load_cases"], "properties": {"load_cases": {"minItems": 1}}}]});
    }
    let empty = serde_json::json!({"maxItems": 0});
    serde_json::json!([
        {
            "if": {"required": ["mesh"], "properties": {"mesh": {"type": "string"}}},
            "then": {"properties": {"nodes": empty, "elements": empty, "supports": empty, "rigid_links": empty}},
            "else": inline
        },
        {
            "if": {"required": ["mesh"], "properties": {"mesh": {"type": "string", "pattern": "\\.msh$"}}},
            "then": {"required": ["gmsh"], "properties": {"gmsh": {"type": "object"}}},
            "else": {"properties": {"gmsh": {"type": "null"}}}
        },
        {
            "if": steps_given(),
            "then": nonlinear_true()
        }
    ])
}

impl MeshSpec {
    /// Combines a mesh file's model with inline additions: inline materials and sections are
    /// added (inline wins on equal names), inline load cases replace the mesh's.
    pub fn merge_inline(mut mesh: MeshSpec, inline: MeshSpec) -> Result<MeshSpec, CaseError> {
        for (field, given) in [
            ("nodes", !inline.nodes.is_empty()),
            ("elements", !inline.elements.is_empty()),
            ("supports", !inline.supports.is_empty()),
            ("rigid_links", !inline.rigid_links.is_empty()),
        ] {
            if given {
                return Err(CaseError::new(
                    field,
                    "the model comes from `mesh`: give nodes, elements, supports and rigid links there, not inline",
                ));
            }
        }
        mesh.materials.extend(inline.materials);
        mesh.sections.extend(inline.sections);
        if !inline.load_cases.is_empty() {
            mesh.load_cases = inline.load_cases;
        }
        Ok(mesh)
    }

    /// Validates every reference and value and builds the FE model (at least one load case).
    pub fn build(&self) -> Result<fem::Model, CaseError> {
        self.build_model(true)
    }

    /// As [`MeshSpec::build`]; `need_loads = false` accepts a model without load cases (modal).
    pub fn build_model(&self, need_loads: bool) -> Result<fem::Model, CaseError> {
        let mut materials = BTreeMap::new();
        for (k, m) in &self.materials {
            materials.insert(k.as_str(), m.resolve(&format!("materials.{k}"))?);
        }
        let mut sections = BTreeMap::new();
        for (k, s) in &self.sections {
            sections.insert(k.as_str(), section(s, &format!("sections.{k}"))?);
        }
        if self.nodes.is_empty() {
            return Err(CaseError::new("nodes", "the model has no nodes"));
        }
        let n = self.nodes.len();
        let node_ref = |path: String, i: usize| -> Result<usize, CaseError> {
            if i < n {
                Ok(i)
            } else {
                Err(CaseError::value(
                    path,
                    i,
                    format!("node index must be < {n} (the number of nodes)"),
                ))
            }
        };
        let mut model = fem::Model::new();
        for (i, x) in self.nodes.iter().enumerate() {
            for (k, v) in x.iter().enumerate() {
                check::finite(&format!("nodes[{i}][{k}]"), *v)?;
            }
            model.add_node(*x);
        }
        let mut rigid: Vec<(String, RigidSpec)> = self
            .rigid_links
            .iter()
            .enumerate()
            .map(|(i, r)| (format!("rigid_links[{i}]"), r.clone()))
            .collect();
        // Model element index of each case element (masses and rigid links are no elements).
        let mut model_index: Vec<Option<usize>> = Vec::with_capacity(self.elements.len());
        for (ie, e) in self.elements.iter().enumerate() {
            let p = format!("elements[{ie}]");
            let before = model.elements.len();
            match e {
                ElementSpec::Beam {
                    nodes,
                    section,
                    material,
                    up,
                    shear,
                } => {
                    let a = node_ref(format!("{p}.nodes[0]"), nodes[0])?;
                    let b = node_ref(format!("{p}.nodes[1]"), nodes[1])?;
                    if a == b {
                        return Err(CaseError::value(
                            format!("{p}.nodes"),
                            format!("[{a}, {b}]"),
                            "a beam needs two different nodes",
                        ));
                    }
                    let sec = *sections.get(section.as_str()).ok_or_else(|| {
                        CaseError::value(
                            format!("{p}.section"),
                            format!("\"{section}\""),
                            format!("unknown section; defined: {}", keys(&self.sections)),
                        )
                    })?;
                    let Some(sec) = sec else {
                        return Err(CaseError::value(
                            format!("{p}.section"),
                            format!("\"{section}\""),
                            "a shell section cannot be used by a beam",
                        ));
                    };
                    let mat = *materials.get(material.as_str()).ok_or_else(|| {
                        CaseError::value(
                            format!("{p}.material"),
                            format!("\"{material}\""),
                            format!("unknown material; defined: {}", keys(&self.materials)),
                        )
                    })?;
                    let xa = self.nodes[a];
                    let xb = self.nodes[b];
                    let axis = [xb[0] - xa[0], xb[1] - xa[1], xb[2] - xa[2]];
                    let len = norm(axis);
                    if len <= 1e-12 {
                        return Err(CaseError::value(
                            format!("{p}.nodes"),
                            format!("[{a}, {b}]"),
                            "the two nodes coincide (zero-length beam)",
                        ));
                    }
                    let un = norm(*up);
                    let cross = norm([
                        axis[1] * up[2] - axis[2] * up[1],
                        axis[2] * up[0] - axis[0] * up[2],
                        axis[0] * up[1] - axis[1] * up[0],
                    ]);
                    if !(un.is_finite() && un > 0.0 && cross > 1e-6 * len * un) {
                        return Err(CaseError::value(
                            format!("{p}.up"),
                            format!("{up:?}"),
                            "must be a non-zero vector not parallel to the beam axis",
                        ));
                    }
                    let mut beam = fem::Beam::new(a, b, sec, mat, *up);
                    if !shear {
                        beam = beam.euler_bernoulli();
                    }
                    model.add_beam(beam);
                }
                ElementSpec::Spring { nodes, k } => {
                    if nodes.is_empty() || nodes.len() > 2 {
                        return Err(CaseError::value(
                            format!("{p}.nodes"),
                            format!("{nodes:?}"),
                            "a spring has one node (to ground) or two",
                        ));
                    }
                    for (i, kv) in k.iter().enumerate() {
                        check::non_negative(&format!("{p}.k[{i}]"), *kv, "N/mm or N·mm/rad")?;
                    }
                    let a = node_ref(format!("{p}.nodes[0]"), nodes[0])?;
                    let b = match nodes.get(1) {
                        Some(&b) => Some(node_ref(format!("{p}.nodes[1]"), b)?),
                        None => None,
                    };
                    model.add_element(fem::Element::Spring(fem::Spring {
                        a,
                        b,
                        k: *k,
                        axes: fem::SpringAxes::Global,
                    }));
                }
                ElementSpec::Mass { node, mass, inertia } => {
                    let node = node_ref(format!("{p}.node"), *node)?;
                    check::non_negative(&format!("{p}.mass"), *mass, "tonne")?;
                    for (i, v) in inertia.iter().enumerate() {
                        check::non_negative(&format!("{p}.inertia[{i}]"), *v, "tonne·mm²")?;
                    }
                    model.masses.push(fem::PointMass {
                        node,
                        mass: *mass,
                        inertia: *inertia,
                    });
                }
                ElementSpec::Rigid { master, slaves } => {
                    rigid.push((
                        p,
                        RigidSpec {
                            master: *master,
                            slaves: slaves.clone(),
                        },
                    ));
                }
                ElementSpec::Shell4 {
                    nodes,
                    section,
                    material,
                } => {
                    let mut ns = [0usize; 4];
                    for (k, &nd) in nodes.iter().enumerate() {
                        ns[k] = node_ref(format!("{p}.nodes[{k}]"), nd)?;
                    }
                    // A triangle may be given as a degenerate quad [a, b, c, c].
                    for a in 0..4 {
                        for b in 0..a {
                            if ns[a] == ns[b] && !(a == 3 && b == 2) {
                                return Err(CaseError::value(
                                    format!("{p}.nodes"),
                                    format!("{ns:?}"),
                                    "a shell4 needs four different nodes (or [a, b, c, c] for a triangle)",
                                ));
                            }
                        }
                    }
                    let t = match self.sections.get(section.as_str()) {
                        Some(SectionSpec::Shell { t }) => *t,
                        Some(_) => {
                            return Err(CaseError::value(
                                format!("{p}.section"),
                                format!("\"{section}\""),
                                "a shell4 needs a section with \"shape\": \"shell\"",
                            ))
                        }
                        None => {
                            return Err(CaseError::value(
                                format!("{p}.section"),
                                format!("\"{section}\""),
                                format!("unknown section; defined: {}", keys(&self.sections)),
                            ))
                        }
                    };
                    let mat = *materials.get(material.as_str()).ok_or_else(|| {
                        CaseError::value(
                            format!("{p}.material"),
                            format!("\"{material}\""),
                            format!("unknown material; defined: {}", keys(&self.materials)),
                        )
                    })?;
                    let x = ns.map(|i| self.nodes[i]);
                    if fem::shell::shell_geometry(&x).is_none() {
                        return Err(CaseError::value(
                            format!("{p}.nodes"),
                            format!("{ns:?}"),
                            "the four nodes must form a convex quadrilateral, listed around it (not crossed, no zero area)",
                        ));
                    }
                    model.add_element(fem::Element::Shell4(fem::Shell4 {
                        nodes: ns,
                        t,
                        material: mat,
                    }));
                }
            }
            model_index.push((model.elements.len() > before).then_some(before));
        }
        for (p, r) in rigid {
            let master = node_ref(format!("{p}.master"), r.master)?;
            let mut slaves = Vec::with_capacity(r.slaves.len());
            for (i, s) in r.slaves.iter().enumerate() {
                slaves.push(node_ref(format!("{p}.slaves[{i}]"), *s)?);
            }
            model.rigid_links.push(fem::RigidLink { master, slaves });
        }
        for (i, s) in self.supports.iter().enumerate() {
            let node = node_ref(format!("supports[{i}].node"), s.node)?;
            let dofs: Vec<Dof> = s.fix.iter().map(|d| d.dof()).collect();
            model.supports.push(fem::Support::dofs(node, &dofs));
        }
        if need_loads && self.load_cases.is_empty() {
            return Err(CaseError::new("load_cases", "at least one load case is needed"));
        }
        unique_load_case_names(self.load_cases.iter().map(|c| c.name.as_str()))?;
        for (ic, c) in self.load_cases.iter().enumerate() {
            let p = format!("load_cases[{ic}]");
            let mut lc = fem::LoadCase::new(c.name.clone());
            for (i, f) in c.forces.iter().enumerate() {
                let node = node_ref(format!("{p}.forces[{i}].node"), f.node)?;
                for (k, v) in f.f.iter().enumerate() {
                    check::finite(&format!("{p}.forces[{i}].F[{k}]"), *v)?;
                }
                lc = lc.force(node, f.f);
            }
            for (i, d) in c.displacements.iter().enumerate() {
                let node = node_ref(format!("{p}.displacements[{i}].node"), d.node)?;
                check::finite(&format!("{p}.displacements[{i}].value"), d.value)?;
                // Case files give rotations in degrees; the model works in radians.
                let value = match d.dof {
                    DofName::Rx | DofName::Ry | DofName::Rz => d.value.to_radians(),
                    DofName::Ux | DofName::Uy | DofName::Uz => d.value,
                };
                lc = lc.displacement(node, d.dof.dof(), value);
            }
            for (i, pr) in c.pressures.iter().enumerate() {
                let pp = format!("{p}.pressures[{i}]");
                check::finite(&format!("{pp}.p"), pr.p)?;
                let mut list: Vec<(String, usize)> = Vec::new();
                for (k, &e) in pr.elements.iter().enumerate() {
                    let at = format!("{pp}.elements[{k}]");
                    let me = model_index.get(e).copied().flatten();
                    match me.and_then(|m| model.elements.get(m)) {
                        Some(fem::Element::Shell4(_)) => list.push((at, me.unwrap_or(e))),
                        Some(_) => return Err(CaseError::value(at, e, "a pressure acts on shell4 elements only")),
                        None if e < self.elements.len() => {
                            return Err(CaseError::value(at, e, "a pressure acts on shell4 elements only"))
                        }
                        None => {
                            return Err(CaseError::value(
                                at,
                                e,
                                format!(
                                    "element index must be < {} (the number of elements)",
                                    self.elements.len()
                                ),
                            ))
                        }
                    }
                }
                if let Some(gname) = &pr.group {
                    let at = format!("{pp}.group");
                    if self.element_groups.is_empty() {
                        return Err(CaseError::value(
                            at,
                            format!("\"{gname}\""),
                            "a group names a Gmsh physical group: only with a .msh mesh; give `elements` otherwise",
                        ));
                    }
                    let before = list.len();
                    for (e, groups) in self.element_groups.iter().enumerate() {
                        let Some(me) = model_index.get(e).copied().flatten() else {
                            continue;
                        };
                        if groups.iter().any(|g| g == gname)
                            && matches!(model.elements.get(me), Some(fem::Element::Shell4(_)))
                        {
                            list.push((at.clone(), me));
                        }
                    }
                    if list.len() == before {
                        return Err(CaseError::value(
                            at,
                            format!("\"{gname}\""),
                            "no shell element of the model belongs to this group (it must be listed in `gmsh.groups` and hold triangles or quadrangles)",
                        ));
                    }
                }
                if list.is_empty() {
                    return Err(CaseError::new(
                        pp,
                        "give the loaded shells by `elements` and/or `group`",
                    ));
                }
                for (at, e) in list {
                    let Some(fem::Element::Shell4(sh)) = model.elements.get(e) else {
                        continue;
                    };
                    let x = sh.nodes.map(|n| model.nodes[n]);
                    let f = fem::shell_loads::pressure_loads(&x, pr.p)
                        .ok_or_else(|| CaseError::value(at, e, "degenerate shell geometry"))?;
                    for (k, &n) in sh.nodes.iter().enumerate() {
                        lc = lc.force(n, f[k]);
                    }
                }
            }
            for (i, el) in c.edge_loads.iter().enumerate() {
                let pe = format!("{p}.edge_loads[{i}]");
                let a = node_ref(format!("{pe}.nodes[0]"), el.nodes[0])?;
                let b = node_ref(format!("{pe}.nodes[1]"), el.nodes[1])?;
                for (k, v) in el.q.iter().chain(&el.m).enumerate() {
                    let name = if k < 3 {
                        format!("q[{k}]")
                    } else {
                        format!("m[{}]", k - 3)
                    };
                    check::finite(&format!("{pe}.{name}"), *v)?;
                }
                let is_edge = model.elements.iter().any(|e| match e {
                    fem::Element::Shell4(sh) => (0..4).any(|k| {
                        let (x, y) = (sh.nodes[k], sh.nodes[(k + 1) % 4]);
                        x != y && ((x, y) == (a, b) || (x, y) == (b, a))
                    }),
                    _ => false,
                });
                if !is_edge {
                    return Err(CaseError::value(
                        format!("{pe}.nodes"),
                        format!("[{a}, {b}]"),
                        "must be two nodes adjacent in the node list of a shell4 element (an element edge)",
                    ));
                }
                let f = fem::shell_loads::edge_loads(model.nodes[a], model.nodes[b], el.q, el.m);
                lc = lc.force(a, f[0]).force(b, f[1]);
            }
            model.load_cases.push(lc);
        }
        Ok(model)
    }
}

/// Refuses two load cases with the same name, or with names that give the same output file
/// name (each load case writes `NAME.vtu`): the error names `load_cases[i].name` of the later.
pub fn unique_load_case_names<'a>(names: impl Iterator<Item = &'a str>) -> Result<(), CaseError> {
    let mut seen: BTreeMap<String, (usize, &str)> = BTreeMap::new();
    for (i, name) in names.enumerate() {
        let stem = crate::report::vtk::file_stem(name);
        if let Some((j, first)) = seen.get(&stem) {
            let why = if *first == name {
                format!("load_cases[{j}] has the same name; load case names must be unique")
            } else {
                format!(
                    "load_cases[{j}] (\"{first}\") gives the same output file name `{stem}.vtu`; load case names must differ in letters, digits, `-` or `_`"
                )
            };
            return Err(CaseError::value(
                format!("load_cases[{i}].name"),
                format!("\"{name}\""),
                why,
            ));
        }
        seen.insert(stem, (i, name));
    }
    Ok(())
}

fn keys<V>(m: &BTreeMap<String, V>) -> String {
    if m.is_empty() {
        "none".into()
    } else {
        m.keys().map(|k| format!("\"{k}\"")).collect::<Vec<_>>().join(", ")
    }
}

fn norm(v: [f64; 3]) -> f64 {
    (v[0] * v[0] + v[1] * v[1] + v[2] * v[2]).sqrt()
}

/// Validates a section; `None` for a shell section.
fn section(s: &SectionSpec, p: &str) -> Result<Option<fem::Section>, CaseError> {
    let f = |k: &str| format!("{p}.{k}");
    Ok(Some(match *s {
        SectionSpec::Rect { w, h } => {
            check::positive(&f("w"), w, "mm")?;
            check::positive(&f("h"), h, "mm")?;
            fem::Section::Rect { w, h }
        }
        SectionSpec::Circle { d } => {
            check::positive(&f("d"), d, "mm")?;
            fem::Section::Circle { d }
        }
        SectionSpec::Tube { d, t } => {
            check::positive(&f("d"), d, "mm")?;
            check::positive(&f("t"), t, "mm")?;
            if 2.0 * t >= d {
                return Err(CaseError::value(
                    f("t"),
                    t,
                    format!("the wall must be thinner than half the diameter ({} mm)", d / 2.0),
                ));
            }
            fem::Section::Tube {
                d_out: d,
                d_in: d - 2.0 * t,
            }
        }
        SectionSpec::General { a, iy, iz, j, asy, asz } => {
            check::positive(&f("A"), a, "mm²")?;
            check::positive(&f("Iy"), iy, "mm⁴")?;
            check::positive(&f("Iz"), iz, "mm⁴")?;
            check::positive(&f("J"), j, "mm⁴")?;
            if let Some(v) = asy {
                check::positive(&f("Asy"), v, "mm²")?;
            }
            if let Some(v) = asz {
                check::positive(&f("Asz"), v, "mm²")?;
            }
            fem::Section::General { a, iy, iz, j, asy, asz }
        }
        SectionSpec::Shell { t } => {
            check::positive(&f("t"), t, "mm")?;
            return Ok(None);
        }
    }))
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

/// Schema: `steps` is given as a number.
pub(crate) fn steps_given() -> serde_json::Value {
    serde_json::json!({"required": ["steps"], "properties": {"steps": {"type": "integer"}}})
}

/// Schema: `"nonlinear": true`.
pub(crate) fn nonlinear_true() -> serde_json::Value {
    serde_json::json!({"required": ["nonlinear"], "properties": {"nonlinear": {"const": true}}})
}
