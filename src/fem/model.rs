//! The model: nodes, elements, supports, rigid links, point masses and load cases (plain data,
//! no JSON). [`Model::validate`] checks it; the analysis validates again before solving. The
//! element kinds and their matrices live in [`super::elements`]; `Model` dispatches to them.

mod validate;
pub use validate::{model_size, COINCIDENT};

use super::dof::Dof;
pub use super::elements::{
    Beam, Element, ElementMatrix, FlexElement, MatrixElement, Shell4, Shell9, Shell9Matrix, ShellMatrix, Spring,
    SpringAxes,
};
use super::error::FemError;
use super::section::SectionProps;
use super::transform::{beam_frame, rotate12, t12, Mat12};
use nalgebra::{Matrix3, Matrix6, SMatrix, Vector3};

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
    /// Fill-reducing ordering of the sparse Cholesky factor (default: chosen automatically).
    pub ordering: super::nd::FillOrdering,
    /// Attached superelements (their modal nodes and pieces; see [`super::superelement`]).
    pub superelements: Vec<super::elements::matrix::Attached>,
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
    /// Lower and upper corners of the nodes' axis-aligned bounding box, mm (±∞ without nodes).
    pub fn bounding_box(&self) -> ([f64; 3], [f64; 3]) {
        let mut lo = [f64::INFINITY; 3];
        let mut hi = [f64::NEG_INFINITY; 3];
        for x in &self.nodes {
            for c in 0..3 {
                lo[c] = lo[c].min(x[c]);
                hi[c] = hi[c].max(x[c]);
            }
        }
        (lo, hi)
    }
    /// Number of global DOFs (6 per node).
    pub fn n_dofs(&self) -> usize {
        6 * self.nodes.len()
    }

    pub(crate) fn check_node(&self, what: impl FnOnce() -> String, node: usize) -> Result<(), FemError> {
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
        b.props(ie)
    }

    /// Local stiffness k and direction cosines Λ of a beam or flexibility element.
    fn element_local_frame(&self, ie: usize) -> Result<(Mat12, Matrix3<f64>), FemError> {
        let (lam, l) = self.element_frame(ie)?;
        let k = match &self.elements[ie] {
            Element::Beam(b) => b.local_stiffness(ie, l)?,
            Element::Flex(f) => f.local_stiffness(ie, l)?,
            Element::Spring(_) | Element::Shell4(_) | Element::Shell9(_) | Element::Matrix(_) => {
                return Err(FemError::BadInput(format!("element {ie} is not a beam")))
            }
        };
        Ok((k, lam))
    }

    /// Local stiffness k and transformation T (d_local = T d_global) of a beam or flexibility
    /// element.
    pub fn element_local(&self, ie: usize) -> Result<(Mat12, Mat12), FemError> {
        let (k, lam) = self.element_local_frame(ie)?;
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
        let xa = self.coords(s.a);
        let xb = s.b.map_or(xa, |b| self.coords(b));
        let (bm, n) = s.b_matrix(ie, xa, xb)?;
        Ok((bm, s.k, n))
    }

    /// Global stiffness of element `ie`: K = Tᵀ k T (beams, flexibility elements),
    /// K = Bᵀ diag(k) B (springs).
    pub fn element_matrix(&self, ie: usize) -> Result<ElementMatrix, FemError> {
        match self.elements.get(ie) {
            None => Err(FemError::BadInput(format!("no element {ie}"))),
            Some(Element::Spring(s)) => {
                let (b, _, n) = self.spring_b(ie)?;
                Ok(s.matrix(&b, n))
            }
            Some(Element::Shell4(_)) => Err(FemError::BadInput(format!(
                "element {ie} is a shell (use Model::shell_matrix)"
            ))),
            Some(Element::Shell9(_)) => Err(FemError::BadInput(format!(
                "element {ie} is a nine-node shell (use Model::shell9_matrix)"
            ))),
            Some(Element::Matrix(m)) => {
                for &n in &m.nodes[..m.n_nodes.min(2)] {
                    self.check_node(|| format!("element {ie} (matrix)"), n)?;
                }
                m.matrix(ie, false)
            }
            Some(e) => {
                let (k, lam) = self.element_local_frame(ie)?;
                Ok(ElementMatrix {
                    nodes: e.end_nodes(),
                    n_nodes: 2,
                    k: rotate12(&k, &lam),
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
        s.check(ie)?;
        Ok((s, s.nodes.map(|n| self.nodes[n])))
    }

    /// Global stiffness of shell element `ie` (24×24).
    pub fn shell_matrix(&self, ie: usize) -> Result<ShellMatrix, FemError> {
        let (s, x) = self.shell_checked(ie)?;
        s.matrix(ie, &x)
    }

    /// Whether the model holds four-node and nine-node shells: (shell4, shell9).
    pub fn shell_kinds(&self) -> (bool, bool) {
        self.elements.iter().fold((false, false), |(four, nine), e| match e {
            Element::Shell4(_) => (true, nine),
            Element::Shell9(_) => (four, true),
            _ => (four, nine),
        })
    }

    /// Checks a nine-node shell element (nodes, thickness, material) and returns it with its
    /// node coordinates.
    pub fn shell9_checked(&self, ie: usize) -> Result<(&Shell9, [[f64; 3]; 9]), FemError> {
        let Some(Element::Shell9(s)) = self.elements.get(ie) else {
            return Err(FemError::BadInput(format!("element {ie} is not a nine-node shell")));
        };
        for &n in &s.nodes {
            self.check_node(|| format!("element {ie} (shell9)"), n)?;
        }
        s.check(ie)?;
        Ok((s, s.nodes.map(|n| self.nodes[n])))
    }

    /// Global stiffness of nine-node shell element `ie` (54×54).
    pub fn shell9_matrix(&self, ie: usize) -> Result<Shell9Matrix, FemError> {
        let (s, x) = self.shell9_checked(ie)?;
        s.matrix(ie, &x)
    }

    /// Global consistent mass of nine-node shell element `ie` (54×54).
    pub fn shell9_mass_matrix(&self, ie: usize) -> Result<Shell9Matrix, FemError> {
        let (s, x) = self.shell9_checked(ie)?;
        s.mass(ie, &x)
    }

    /// Tip stiffness C⁻¹ of a flexibility element (local axes at node 2).
    pub fn flex_tip_stiffness(&self, ie: usize) -> Result<Matrix6<f64>, FemError> {
        let Some(Element::Flex(f)) = self.elements.get(ie) else {
            return Err(FemError::BadInput(format!("element {ie} is not a flexibility element")));
        };
        f.tip_stiffness(ie)
    }
}
