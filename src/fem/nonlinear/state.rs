//! The state of a nonlinear solve: nodal positions and rotation matrices, the fixed data of a
//! load case, and the finite-rotation constraint map (framed nodes, ties, rigid links) acting on
//! increments.

use crate::fem::constraints::{frame_block, DofMap};
use crate::fem::corot::{self, CorotGeometry, NodeState};
use crate::fem::error::FemError;
use crate::fem::model::{Beam, Element, FlexElement, Model};
use crate::fem::solve::{LuPattern, Parallelism, SparsePattern, SymbolicFactor};
use crate::fem::transform::{rigid_arm, Mat12};
use nalgebra::{Matrix3, Matrix6, SMatrix, Vector3, Vector6};

/// Precomputed element data.
#[derive(Debug, Clone)]
pub(super) enum ElemData {
    Corot {
        nodes: [usize; 2],
        geom: CorotGeometry,
        k_local: Box<Mat12>,
    },
    Spring {
        nodes: [usize; 2],
        n_nodes: usize,
        b: Box<SMatrix<f64, 6, 12>>,
        k: [f64; 6],
    },
}

pub(super) fn element_data(model: &Model) -> Result<Vec<ElemData>, FemError> {
    (0..model.elements.len())
        .map(|ie| match &model.elements[ie] {
            Element::Shell4(_) | Element::Shell9(_) => Err(FemError::BadInput(format!(
                "element {ie} is a shell: the geometrically nonlinear solver handles beams, flexibility elements (hinges) and springs"
            ))),
            Element::Matrix(_) => Err(FemError::BadInput(format!(
                "element {ie} is a piece of a superelement (given matrices, linear): the geometrically nonlinear solver handles beams, flexibility elements (hinges) and springs"
            ))),
            Element::Spring(s) => {
                let (b, k, n) = model.spring_b(ie)?;
                Ok(ElemData::Spring {
                    nodes: [s.a, s.b.unwrap_or(s.a)],
                    n_nodes: n,
                    b: Box::new(b),
                    k,
                })
            }
            Element::Beam(Beam { nodes, .. }) | Element::Flex(FlexElement { nodes, .. }) => {
                let nodes = *nodes;
                let (lam, l) = model.element_frame(ie)?;
                let (k_local, _) = model.element_local(ie)?;
                Ok(ElemData::Corot {
                    nodes,
                    geom: CorotGeometry {
                        x1: Vector3::from(model.nodes[nodes[0]]),
                        x2: Vector3::from(model.nodes[nodes[1]]),
                        r0: lam.transpose(),
                        l0: l,
                    },
                    k_local: Box::new(k_local),
                })
            }
        })
        .collect()
}

/// Nodal state: translations and rotation matrices.
#[derive(Debug, Clone)]
pub(super) struct State {
    pub(super) u: Vec<Vector3<f64>>,
    pub(super) r: Vec<Matrix3<f64>>,
}

/// Everything fixed for one load case.
pub(super) struct CaseCtx<'a> {
    pub(super) model: &'a Model,
    pub(super) elems: &'a [ElemData],
    pub(super) map: DofMap,
    /// Initial arm X_s − X_m of each slave (zero for independent nodes).
    pub(super) arm0: Vec<Vector3<f64>>,
    /// Applied loads (6 per node, global).
    pub(super) f_ext: Vec<f64>,
    /// Prescribed values (6 per node; local for framed nodes).
    pub(super) u_c: Vec<f64>,
    pub(super) pattern: SparsePattern,
    pub(super) symbolic: SymbolicFactor,
    /// Lower-triangle pairs of `pattern` (for the LU of an indefinite symmetric tangent).
    pub(super) lower_pairs: Vec<(usize, usize)>,
    /// Both triangles of `pattern`, built on first need.
    pub(super) mirror: std::cell::OnceCell<Result<LuPattern, String>>,
    /// Pattern of the full non-symmetric tangent when the Newton iterations use it.
    pub(super) full: Option<LuPattern>,
    /// Round-off floor of the residual, N (N·mm): the co-rotated frames and deformations come
    /// from nodal positions and rotations, so a balanced state's residual is ~ε times the
    /// stiffest element's force at unit relative error (EA, and 4EI/L per radian); 1e-13 of
    /// it leaves a margin of ~50 ε.
    pub(super) round: f64,
    /// Master nodes of rigid links (their 6×6 blocks carry the link geometric stiffness).
    pub(super) masters: Vec<usize>,
    pub(super) par: Parallelism,
    /// Quantities evaluated at every accepted point ([`super::StepTrack`]), when asked.
    pub(super) tracker: Option<Tracker>,
}

/// The fixed data of the tracking of one load case, and what it recorded.
pub(super) struct Tracker {
    pub(super) req: super::StepTrack,
    /// Beams (element index) with their undeformed global mass.
    pub(super) beams: Vec<(usize, Box<Mat12>)>,
    /// Tangent pairs then mass pairs (lower triangle): K and M on one pattern.
    pub(super) pattern: SparsePattern,
    pub(super) symbolic: SymbolicFactor,
    pub(super) n_k: usize,
    pub(super) steps: std::cell::RefCell<Vec<super::StepQuantities>>,
}

/// Residual, tangent values and force norms at one configuration.
pub(super) struct Eval {
    /// Reduced residual r = f_int − λ f_ext (equations).
    pub(super) r: Vec<f64>,
    /// Tangent triplet values in pattern order (lower triangle of the symmetric part, or the
    /// full non-symmetric tangent in the full pattern's order).
    pub(super) values: Vec<f64>,
    /// ‖λ f_ext‖ carried to the independent nodes.
    pub(super) load: f64,
    /// ‖f_int‖ carried to the independent nodes (constrained DOFs included: the reactions).
    pub(super) internal: f64,
    /// f_int − λ f_ext per node (6 each, global).
    pub(super) net: Vec<f64>,
    /// The increment maps of [`CaseCtx::arms`] at this configuration.
    pub(super) arms: Vec<Option<Matrix6<f64>>>,
}

/// Which tangent [`CaseCtx::evaluate`] assembles.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(super) enum Assemble {
    None,
    /// Lower triangle of the symmetric part.
    Symmetric,
    /// The consistent non-symmetric tangent.
    Full,
}

/// Linear solution of one Newton/arc-length iteration.
pub(super) struct Solution {
    pub(super) x: Vec<Vec<f64>>,
    /// Whether the symmetric tangent was positive definite (`None` when the full tangent was
    /// factorised by LU and definiteness is unknown).
    pub(super) positive_definite: Option<bool>,
}

pub(super) fn fail(case: &str, step: usize, lambda: f64, residual: f64, reason: impl Into<String>) -> FemError {
    FemError::NonConvergence {
        case: case.to_string(),
        step,
        lambda,
        residual,
        reason: reason.into(),
    }
}

impl CaseCtx<'_> {
    pub(super) fn n_eq(&self) -> usize {
        self.map.n_eq()
    }

    /// Current 6×6 increment map of each node onto its independent node (None = identity).
    pub(super) fn arms(&self, st: &State) -> Vec<Option<Matrix6<f64>>> {
        let map = &self.map;
        (0..self.model.nodes.len())
            .map(|n| {
                let m = map.rep[n];
                if m == n {
                    map.arm[n]
                } else {
                    let mut a = rigid_arm(&(st.r[m] * self.arm0[n]));
                    if let Some(f) = self.model.frames.get(&m) {
                        a *= frame_block(f);
                    }
                    Some(a)
                }
            })
            .collect()
    }

    /// Full per-node vector carried to the independent nodes with the current arms, ties
    /// folded onto their roots.
    pub(super) fn to_independent(&self, arms: &[Option<Matrix6<f64>>], v: &[f64]) -> Vec<f64> {
        let mut out = vec![0.0; v.len()];
        for (n, arm) in arms.iter().enumerate() {
            let m = self.map.rep[n];
            let vn = Vector6::from_column_slice(&v[6 * n..6 * n + 6]);
            let t = match arm {
                Some(a) => a.transpose() * vn,
                None => vn,
            };
            for d in 0..6 {
                out[6 * m + d] += t[d];
            }
        }
        for &(g, root) in &self.map.alias {
            out[root] += out[g];
            out[g] = 0.0;
        }
        out
    }

    /// The applied load f (at λ = 1) on the equations, carried with the current arms.
    pub(super) fn reduced_load(&self, st: &State) -> Vec<f64> {
        let full = self.to_independent(&self.arms(st), &self.f_ext);
        self.map.eq_dof.iter().map(|&g| full[g]).collect()
    }

    /// Slaves follow their masters exactly.
    pub(super) fn update_slaves(&self, st: &mut State) {
        for n in 0..self.model.nodes.len() {
            let m = self.map.rep[n];
            if m != n {
                st.u[n] = st.u[m] + st.r[m] * self.arm0[n] - self.arm0[n];
                st.r[n] = st.r[m];
            }
        }
    }

    /// Applies equation increments `q` and constrained increments `dc` (6 per node, node
    /// frame for framed nodes; read at constrained DOFs only).
    pub(super) fn apply(&self, st: &mut State, q: &[f64], dc: Option<&[f64]>) {
        let map = &self.map;
        let d = map.scatter(q, dc);
        for n in 0..self.model.nodes.len() {
            if map.rep[n] != n {
                continue;
            }
            let mut v = Vector6::from_column_slice(&d[6 * n..6 * n + 6]);
            if let Some(a) = &map.arm[n] {
                v = a * v;
            }
            st.u[n] += Vector3::new(v[0], v[1], v[2]);
            let w = Vector3::new(v[3], v[4], v[5]);
            if w != Vector3::zeros() {
                st.r[n] = corot::rot_exp(&w) * st.r[n];
            }
        }
        self.update_slaves(st);
    }

    pub(super) fn node_state(st: &State, n: usize) -> NodeState {
        NodeState { u: st.u[n], r: st.r[n] }
    }
}
