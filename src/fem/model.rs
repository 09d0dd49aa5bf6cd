//! The model: nodes, elements, supports, rigid links, point masses and load cases (plain data,
//! no JSON). [`Model::validate`] checks it; the analysis validates again before solving.

use super::dof::{Dof, NodeDof};
use super::element::{beam_local_stiffness, flex_local_stiffness, flex_tip_stiffness};
use super::error::FemError;
use super::section::{Section, SectionProps};
use super::shell::{shell_stiffness, Mat24};
use super::transform::{beam_frame, frame_from_x_up, rigid_arm, t12, t6, Mat12};
use crate::material::Material;
use nalgebra::{Matrix3, Matrix6, SMatrix, Vector3};

/// Two-node 3D beam (Timoshenko unless `shear` is false).
#[derive(Debug, Clone, PartialEq)]
pub struct Beam {
    /// First and second node; local x runs from `nodes[0]` to `nodes[1]`.
    pub nodes: [usize; 2],
    pub section: Section,
    pub material: Material,
    /// Orientation vector (global): local z is its component normal to the axis.
    pub up: [f64; 3],
    /// Include shear deformation (Timoshenko). `false` = Euler–Bernoulli.
    pub shear: bool,
}

impl Beam {
    /// Timoshenko beam from `n1` to `n2`.
    pub fn new(n1: usize, n2: usize, section: Section, material: Material, up: [f64; 3]) -> Beam {
        Beam {
            nodes: [n1, n2],
            section,
            material,
            up,
            shear: true,
        }
    }

    /// Same beam, Euler–Bernoulli.
    pub fn euler_bernoulli(mut self) -> Beam {
        self.shear = false;
        self
    }
}

/// Two-node element given by its cantilever tip compliance (see
/// [`super::element::flex_local_stiffness`]). Local axes as for [`Beam`]; the length is the
/// node distance.
#[derive(Debug, Clone, PartialEq)]
pub struct FlexElement {
    pub nodes: [usize; 2],
    /// 6×6 compliance of node 2 relative to clamped node 1, local axes at node 2, order
    /// u v w θx θy θz (mm/N, rad/N, rad/(N·mm)); symmetric positive definite.
    pub compliance: [[f64; 6]; 6],
    /// Orientation vector, as for beams.
    pub up: [f64; 3],
}

/// Axes in which a spring's six stiffnesses act.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum SpringAxes {
    /// Global x, y, z.
    Global,
    /// Rows are the spring's local x, y, z axes in global coordinates (orthonormal,
    /// right-handed). Build with [`SpringAxes::from_x_up`].
    Frame([[f64; 3]; 3]),
}

impl SpringAxes {
    /// Local x along `x`, local z = component of `up` normal to x, y = z × x.
    /// `None` if `up` is parallel to `x` or a vector is zero.
    pub fn from_x_up(x: [f64; 3], up: [f64; 3]) -> Option<SpringAxes> {
        let lam = frame_from_x_up(Vector3::from(x), Vector3::from(up))?;
        let mut rows = [[0.0; 3]; 3];
        for (i, row) in rows.iter_mut().enumerate() {
            for (j, v) in row.iter_mut().enumerate() {
                *v = lam[(i, j)];
            }
        }
        Some(SpringAxes::Frame(rows))
    }
}

/// Six uncoupled springs (translational N/mm, rotational N·mm/rad) between two nodes, or
/// between a node and the ground. Between two nodes the spring acts at their midpoint through
/// rigid arms, so it is equilibrium-consistent even when the nodes do not coincide.
#[derive(Debug, Clone, PartialEq)]
pub struct Spring {
    pub a: usize,
    /// Second node, `None` = ground.
    pub b: Option<usize>,
    /// [kx, ky, kz, krx, kry, krz] in `axes`.
    pub k: [f64; 6],
    pub axes: SpringAxes,
}

/// Four-node flat shell (see [`super::shell`]): membrane with drilling rotation + MITC4
/// bending/shear (stabilized shear), lumped mass. Nodes in order around the element (the normal follows the right-hand rule).
#[derive(Debug, Clone, PartialEq)]
pub struct Shell4 {
    pub nodes: [usize; 4],
    /// Thickness, mm.
    pub t: f64,
    pub material: Material,
}

/// Elements that contribute stiffness.
#[derive(Debug, Clone, PartialEq)]
pub enum Element {
    Beam(Beam),
    Flex(FlexElement),
    Spring(Spring),
    Shell4(Shell4),
}

impl Element {
    /// Nodes of the element (1 for a ground spring).
    pub fn nodes(&self) -> Vec<usize> {
        match self {
            Element::Beam(b) => b.nodes.to_vec(),
            Element::Flex(f) => f.nodes.to_vec(),
            Element::Spring(s) => match s.b {
                Some(b) => vec![s.a, b],
                None => vec![s.a],
            },
            Element::Shell4(s) => s.nodes.to_vec(),
        }
    }
}

/// Fixed DOFs of a node (zero displacement unless prescribed in a load case).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Support {
    pub node: usize,
    /// `fix[i]` for ux uy uz rx ry rz.
    pub fix: [bool; 6],
}

impl Support {
    /// All six DOFs fixed (clamp).
    pub fn clamp(node: usize) -> Support {
        Support { node, fix: [true; 6] }
    }
    /// The given DOFs fixed.
    pub fn dofs(node: usize, dofs: &[Dof]) -> Support {
        let mut fix = [false; 6];
        for d in dofs {
            fix[d.index()] = true;
        }
        Support { node, fix }
    }
}

/// Rigid link: all six DOFs of each slave follow the master rigidly
/// (u_s = u_m + θ_m × (x_s − x_m), θ_s = θ_m), eliminated from the system.
#[derive(Debug, Clone, PartialEq)]
pub struct RigidLink {
    pub master: usize,
    pub slaves: Vec<usize>,
}

/// A tie between two coincident nodes: the listed DOFs of `b` equal those of `a` (in the
/// nodes' common frame, see [`Model::frames`]); the others stay independent. An exact joint
/// release (a revolute joint ties all but one rotation, a spherical joint the translations),
/// eliminated from the system like a rigid link: no penalty.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Tie {
    pub a: usize,
    pub b: usize,
    /// Tied DOFs in order ux uy uz rx ry rz (of the frame).
    pub dofs: [bool; 6],
}

/// Lumped mass at a node (stored for modal analysis).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct PointMass {
    pub node: usize,
    /// Mass, tonne.
    pub mass: f64,
    /// Rotary inertia about global x, y, z through the node, tonne·mm².
    pub inertia: [f64; 3],
}

/// Nodal force/moment in global axes: [Fx, Fy, Fz (N), Mx, My, Mz (N·mm)].
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct NodalLoad {
    pub node: usize,
    pub f: [f64; 6],
}

/// Prescribed displacement (mm) or rotation (rad) of one DOF in one load case.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Prescribed {
    pub node: usize,
    pub dof: Dof,
    pub value: f64,
}

/// A load case: nodal loads plus prescribed displacements.
#[derive(Debug, Clone, PartialEq, Default)]
pub struct LoadCase {
    pub name: String,
    pub forces: Vec<NodalLoad>,
    pub displacements: Vec<Prescribed>,
}

impl LoadCase {
    /// Empty load case.
    pub fn new(name: impl Into<String>) -> LoadCase {
        LoadCase {
            name: name.into(),
            ..Default::default()
        }
    }
    /// Adds a nodal load (builder style).
    pub fn force(mut self, node: usize, f: [f64; 6]) -> LoadCase {
        self.forces.push(NodalLoad { node, f });
        self
    }
    /// Adds a prescribed displacement (builder style).
    pub fn displacement(mut self, node: usize, dof: Dof, value: f64) -> LoadCase {
        self.displacements.push(Prescribed { node, dof, value });
        self
    }
}

/// A complete beam model.
#[derive(Debug, Clone, PartialEq, Default)]
pub struct Model {
    /// Node coordinates, mm.
    pub nodes: Vec<[f64; 3]>,
    pub elements: Vec<Element>,
    pub supports: Vec<Support>,
    pub rigid_links: Vec<RigidLink>,
    pub masses: Vec<PointMass>,
    pub load_cases: Vec<LoadCase>,
    /// Node frames: rows are the node's local x, y, z axes in global coordinates (orthonormal,
    /// right-handed). Supports, prescribed displacements and ties of a framed node act on its
    /// local DOFs (skew supports, sliders on inclined guides); loads, displacements and
    /// reactions in results stay global.
    pub frames: std::collections::BTreeMap<usize, [[f64; 3]; 3]>,
    /// Ties (exact joint releases) between coincident nodes.
    pub ties: Vec<Tie>,
}

/// A global shell element matrix (stiffness or mass) on its four nodes.
#[derive(Debug, Clone, PartialEq)]
pub struct ShellMatrix {
    pub nodes: [usize; 4],
    pub k: Mat24,
}

/// A global element matrix on its nodes (`n_nodes` = 1 or 2; for 1 only the top-left 6×6 is
/// used).
#[derive(Debug, Clone, PartialEq)]
pub struct ElementMatrix {
    pub nodes: [usize; 2],
    pub n_nodes: usize,
    /// Global stiffness, N/mm, N, N·mm/rad.
    pub k: Mat12,
}

impl Model {
    /// Empty model.
    pub fn new() -> Model {
        Model::default()
    }
    /// Adds a node (mm) and returns its index.
    pub fn add_node(&mut self, x: [f64; 3]) -> usize {
        self.nodes.push(x);
        self.nodes.len() - 1
    }
    /// Adds an element and returns its index.
    pub fn add_element(&mut self, e: Element) -> usize {
        self.elements.push(e);
        self.elements.len() - 1
    }
    /// Adds a beam and returns its element index.
    pub fn add_beam(&mut self, b: Beam) -> usize {
        self.add_element(Element::Beam(b))
    }
    /// Gives `node` a frame (rows: local x, y, z in global coordinates).
    pub fn set_frame(&mut self, node: usize, rows: [[f64; 3]; 3]) {
        self.frames.insert(node, rows);
    }
    /// Number of global DOFs (6 per node).
    pub fn n_dofs(&self) -> usize {
        6 * self.nodes.len()
    }

    fn check_node(&self, what: impl FnOnce() -> String, node: usize) -> Result<(), FemError> {
        if node < self.nodes.len() {
            Ok(())
        } else {
            Err(FemError::NodeOutOfRange {
                what: what(),
                node,
                n_nodes: self.nodes.len(),
            })
        }
    }

    /// Checks indices, geometry, sections, materials, compliances and loads (not constraints;
    /// those are checked by [`super::constraints::DofMap::new`]).
    pub fn validate(&self) -> Result<(), FemError> {
        for (i, x) in self.nodes.iter().enumerate() {
            if x.iter().any(|v| !v.is_finite()) {
                return Err(FemError::BadNode { node: i });
            }
        }
        for (ie, e) in self.elements.iter().enumerate() {
            match e {
                Element::Shell4(_) => {
                    self.shell_matrix(ie)?;
                }
                _ => {
                    self.element_matrix(ie)?;
                }
            }
        }
        for (i, s) in self.supports.iter().enumerate() {
            self.check_node(|| format!("support {i}"), s.node)?;
        }
        for (i, l) in self.rigid_links.iter().enumerate() {
            self.check_node(|| format!("rigid link {i} (master)"), l.master)?;
            for &s in &l.slaves {
                self.check_node(|| format!("rigid link {i} (slave)"), s)?;
            }
        }
        for (&node, f) in &self.frames {
            self.check_node(|| "node frame".to_string(), node)?;
            let m = nalgebra::Matrix3::from_row_slice(&[
                f[0][0], f[0][1], f[0][2], f[1][0], f[1][1], f[1][2], f[2][0], f[2][1], f[2][2],
            ]);
            let err = (m * m.transpose() - nalgebra::Matrix3::identity()).norm();
            if !(err < 1e-9 && m.determinant() > 0.0) {
                return Err(FemError::BadInput(format!(
                    "node {node}: its frame must be orthonormal and right-handed (rows {f:?})"
                )));
            }
        }
        for (i, t) in self.ties.iter().enumerate() {
            self.check_node(|| format!("tie {i}"), t.a)?;
            self.check_node(|| format!("tie {i}"), t.b)?;
            if t.a == t.b {
                return Err(FemError::BadInput(format!("tie {i}: ties node {} to itself", t.a)));
            }
            let (xa, xb) = (self.nodes[t.a], self.nodes[t.b]);
            let dist = ((xa[0] - xb[0]).powi(2) + (xa[1] - xb[1]).powi(2) + (xa[2] - xb[2]).powi(2)).sqrt();
            let scale = xa.iter().chain(xb.iter()).fold(1.0f64, |m, v| m.max(v.abs()));
            if dist > 1e-9 * scale {
                return Err(FemError::BadInput(format!(
                    "tie {i}: nodes {} and {} are {dist} mm apart; a tie joins coincident nodes",
                    t.a, t.b
                )));
            }
            let fa = self.frames.get(&t.a);
            let fb = self.frames.get(&t.b);
            let same = match (fa, fb) {
                (None, None) => true,
                (Some(x), Some(y)) => x
                    .iter()
                    .flatten()
                    .zip(y.iter().flatten())
                    .all(|(p, q)| (p - q).abs() < 1e-12),
                _ => false,
            };
            if !same {
                return Err(FemError::BadInput(format!(
                    "tie {i}: nodes {} and {} must have the same frame (or none)",
                    t.a, t.b
                )));
            }
        }
        for (i, m) in self.masses.iter().enumerate() {
            self.check_node(|| format!("point mass {i}"), m.node)?;
            if !(m.mass.is_finite() && m.mass >= 0.0 && m.inertia.iter().all(|v| v.is_finite() && *v >= 0.0)) {
                return Err(FemError::BadInput(format!(
                    "point mass {i}: mass and inertia must be finite and non-negative"
                )));
            }
        }
        for case in &self.load_cases {
            self.validate_case(case)?;
        }
        Ok(())
    }

    /// Checks one load case (node indices, finite values, no DOF prescribed twice).
    pub fn validate_case(&self, case: &LoadCase) -> Result<(), FemError> {
        let err = |reason: String| FemError::LoadCase {
            case: case.name.clone(),
            reason,
        };
        for (i, f) in case.forces.iter().enumerate() {
            self.check_node(|| format!("load case {:?} force {i}", case.name), f.node)?;
            if f.f.iter().any(|v| !v.is_finite()) {
                return Err(err(format!("force {i} has a non-finite component")));
            }
        }
        let mut seen: Vec<NodeDof> = Vec::new();
        for (i, p) in case.displacements.iter().enumerate() {
            self.check_node(|| format!("load case {:?} displacement {i}", case.name), p.node)?;
            if !p.value.is_finite() {
                return Err(err(format!("displacement {i} is not finite")));
            }
            let nd = NodeDof {
                node: p.node,
                dof: p.dof,
            };
            if seen.contains(&nd) {
                return Err(err(format!("{nd} is prescribed twice")));
            }
            seen.push(nd);
        }
        Ok(())
    }

    fn coords(&self, n: usize) -> Vector3<f64> {
        Vector3::from(self.nodes[n])
    }

    /// Direction cosines Λ and length of a two-node beam or flexibility element.
    pub fn element_frame(&self, ie: usize) -> Result<(Matrix3<f64>, f64), FemError> {
        let (nodes, up) = match self.elements.get(ie) {
            Some(Element::Beam(b)) => (b.nodes, b.up),
            Some(Element::Flex(f)) => (f.nodes, f.up),
            _ => return Err(FemError::BadInput(format!("element {ie} has no beam frame"))),
        };
        for &n in &nodes {
            self.check_node(|| format!("element {ie}"), n)?;
        }
        let (x1, x2) = (self.nodes[nodes[0]], self.nodes[nodes[1]]);
        let d = Vector3::from(x2) - Vector3::from(x1);
        if d.norm().is_nan() || d.norm() <= 0.0 {
            return Err(FemError::BadElement {
                element: ie,
                reason: format!("zero length (nodes {} and {} coincide)", nodes[0], nodes[1]),
            });
        }
        beam_frame(x1, x2, up).ok_or(FemError::UpParallel {
            element: ie,
            n1: nodes[0],
            n2: nodes[1],
        })
    }

    /// Section properties, E and G of beam `ie`.
    pub fn beam_props(&self, ie: usize) -> Result<(SectionProps, f64, f64), FemError> {
        let Some(Element::Beam(b)) = self.elements.get(ie) else {
            return Err(FemError::BadInput(format!("element {ie} is not a beam")));
        };
        b.section
            .validate()
            .map_err(|reason| FemError::BadElement { element: ie, reason })?;
        let m = &b.material;
        if !(m.e.is_finite() && m.e > 0.0 && m.nu.is_finite() && m.nu > -1.0 && m.nu < 0.5) {
            return Err(FemError::BadElement {
                element: ie,
                reason: format!("material needs E > 0 and −1 < ν < 0.5 (E = {}, ν = {})", m.e, m.nu),
            });
        }
        Ok((b.section.properties(m.nu), m.e, m.shear_modulus()))
    }

    /// Local stiffness k and transformation T (d_local = T d_global) of a beam or flexibility
    /// element.
    pub fn element_local(&self, ie: usize) -> Result<(Mat12, Mat12), FemError> {
        let (lam, l) = self.element_frame(ie)?;
        let k = match &self.elements[ie] {
            Element::Beam(b) => {
                let (p, e, g) = self.beam_props(ie)?;
                beam_local_stiffness(e, g, &p, l, b.shear)
            }
            Element::Flex(f) => {
                let c = Matrix6::from_fn(|i, j| f.compliance[i][j]);
                flex_local_stiffness(&c, l).ok_or_else(|| FemError::BadElement {
                    element: ie,
                    reason: "compliance must be finite, symmetric and positive definite".into(),
                })?
            }
            Element::Spring(_) | Element::Shell4(_) => {
                return Err(FemError::BadInput(format!("element {ie} is not a beam")))
            }
        };
        Ok((k, t12(&lam)))
    }

    /// For a spring: B (6×12, only the first 6 columns used for a ground spring) with
    /// δ = B·d the relative motion in spring axes, and the diagonal stiffness.
    pub fn spring_b(&self, ie: usize) -> Result<(SMatrix<f64, 6, 12>, [f64; 6], usize), FemError> {
        let Some(Element::Spring(s)) = self.elements.get(ie) else {
            return Err(FemError::BadInput(format!("element {ie} is not a spring")));
        };
        self.check_node(|| format!("element {ie} (spring)"), s.a)?;
        if let Some(b) = s.b {
            self.check_node(|| format!("element {ie} (spring)"), b)?;
        }
        if s.k.iter().any(|k| !(k.is_finite() && *k >= 0.0)) {
            return Err(FemError::BadElement {
                element: ie,
                reason: "spring stiffnesses must be finite and non-negative".into(),
            });
        }
        let lam = match s.axes {
            SpringAxes::Global => Matrix3::identity(),
            SpringAxes::Frame(rows) => {
                let lam = Matrix3::from_fn(|i, j| rows[i][j]);
                let ortho = (lam * lam.transpose() - Matrix3::identity()).amax();
                if ortho.is_nan() || ortho >= 1e-9 || lam.determinant().is_nan() || lam.determinant() <= 0.0 {
                    return Err(FemError::BadElement {
                        element: ie,
                        reason: "spring axes must be orthonormal and right-handed".into(),
                    });
                }
                lam
            }
        };
        let l6 = t6(&lam);
        let mut bm = SMatrix::<f64, 6, 12>::zeros();
        match s.b {
            None => {
                bm.fixed_view_mut::<6, 6>(0, 0).copy_from(&l6);
                Ok((bm, s.k, 1))
            }
            Some(b) => {
                let (xa, xb) = (self.coords(s.a), self.coords(b));
                let mid = (xa + xb) * 0.5;
                bm.fixed_view_mut::<6, 6>(0, 0)
                    .copy_from(&(-l6 * rigid_arm(&(mid - xa))));
                bm.fixed_view_mut::<6, 6>(0, 6)
                    .copy_from(&(l6 * rigid_arm(&(mid - xb))));
                Ok((bm, s.k, 2))
            }
        }
    }

    /// Global stiffness of element `ie`: K = Tᵀ k T (beams, flexibility elements),
    /// K = Bᵀ diag(k) B (springs).
    pub fn element_matrix(&self, ie: usize) -> Result<ElementMatrix, FemError> {
        match self.elements.get(ie) {
            None => Err(FemError::BadInput(format!("no element {ie}"))),
            Some(Element::Spring(s)) => {
                let (b, k, n) = self.spring_b(ie)?;
                let kd = Matrix6::from_diagonal(&nalgebra::Vector6::from(k));
                Ok(ElementMatrix {
                    nodes: [s.a, s.b.unwrap_or(s.a)],
                    n_nodes: n,
                    k: b.transpose() * kd * b,
                })
            }
            Some(Element::Shell4(_)) => Err(FemError::BadInput(format!(
                "element {ie} is a shell (use Model::shell_matrix)"
            ))),
            Some(e) => {
                let (k, t) = self.element_local(ie)?;
                let nodes = match e {
                    Element::Beam(b) => b.nodes,
                    Element::Flex(f) => f.nodes,
                    Element::Spring(s) => [s.a, s.b.unwrap_or(s.a)],
                    Element::Shell4(s) => [s.nodes[0], s.nodes[1]],
                };
                // t = diag(Λ, Λ, Λ, Λ): rotate block-wise.
                let lam: nalgebra::Matrix3<f64> = t.fixed_view::<3, 3>(0, 0).into_owned();
                Ok(ElementMatrix {
                    nodes,
                    n_nodes: 2,
                    k: super::transform::rotate12(&k, &lam),
                })
            }
        }
    }

    /// Checks a shell element (nodes, thickness, material) and returns it with its node
    /// coordinates.
    pub fn shell_checked(&self, ie: usize) -> Result<(&Shell4, [[f64; 3]; 4]), FemError> {
        let Some(Element::Shell4(s)) = self.elements.get(ie) else {
            return Err(FemError::BadInput(format!("element {ie} is not a shell")));
        };
        for &n in &s.nodes {
            self.check_node(|| format!("element {ie} (shell)"), n)?;
        }
        let m = &s.material;
        if !(m.e.is_finite() && m.e > 0.0 && m.nu.is_finite() && m.nu > -1.0 && m.nu < 0.5) {
            return Err(FemError::BadElement {
                element: ie,
                reason: format!("material needs E > 0 and −1 < ν < 0.5 (E = {}, ν = {})", m.e, m.nu),
            });
        }
        if !(s.t.is_finite() && s.t > 0.0) {
            return Err(FemError::BadElement {
                element: ie,
                reason: format!("shell thickness must be positive and finite, got {}", s.t),
            });
        }
        Ok((s, s.nodes.map(|n| self.nodes[n])))
    }

    fn bad_quad(ie: usize, nodes: [usize; 4]) -> FemError {
        FemError::BadElement {
            element: ie,
            reason: format!(
                "shell nodes {nodes:?} do not form a convex quadrilateral (zero area, repeated nodes or crossed order)"
            ),
        }
    }

    /// Global stiffness of shell element `ie` (24×24).
    pub fn shell_matrix(&self, ie: usize) -> Result<ShellMatrix, FemError> {
        let (s, x) = self.shell_checked(ie)?;
        let k = shell_stiffness(&x, s.t, &s.material).ok_or_else(|| Self::bad_quad(ie, s.nodes))?;
        Ok(ShellMatrix { nodes: s.nodes, k })
    }

    /// Tip stiffness C⁻¹ of a flexibility element (local axes at node 2).
    pub fn flex_tip_stiffness(&self, ie: usize) -> Result<Matrix6<f64>, FemError> {
        let Some(Element::Flex(f)) = self.elements.get(ie) else {
            return Err(FemError::BadInput(format!("element {ie} is not a flexibility element")));
        };
        let c = Matrix6::from_fn(|i, j| f.compliance[i][j]);
        flex_tip_stiffness(&c).ok_or_else(|| FemError::BadElement {
            element: ie,
            reason: "compliance must be finite, symmetric and positive definite".into(),
        })
    }
}
