//! A reduced superelement (e.g. the Craig–Bampton reduction of [`super::craig_bampton`]: R. R.
//! Craig, M. C. C. Bampton, "Coupling of substructures for dynamic analyses", AIAA Journal 6
//! (1968) 1313–1319) attached to a model: its stiffness and mass on [u_B; η] — six DOFs of
//! each interface node (global axes of the model it is attached to) followed by its modal
//! coordinates η — are assembled like any element.
//!
//! The FE core numbers six DOFs per node, so the modal coordinates ride on auxiliary **modal
//! nodes** appended to the model: each carries [`MODES_PER_NODE`] modal coordinates in its `ux
//! uy uz` slots, its other slots fixed by a support. Only the translation slots are used so
//! that a modal coordinate reads back unchanged in every output (rotations are printed in
//! degrees). A modal node sits at the first interface node's position (no geometry is derived
//! from it) and is excluded from rigid-body vectors (total and effective masses) and gravity:
//! a rigid motion of the interface is reproduced by the constraint modes with η = 0.
//!
//! The matrices are split into [`MatrixElement`] pieces: one per node with its diagonal 6×6
//! block and one per node pair with the coupling blocks (all-zero pieces are skipped), so the
//! assembly's element-by-element pattern takes them unchanged.

pub use super::elements::matrix::Attached;
use super::elements::MatrixElement;
use super::error::FemError;
use super::model::{Element, Model, Support};
use super::transform::Mat12;
use nalgebra::DMatrix;

/// Modal coordinates per modal node (its `ux uy uz` slots).
pub const MODES_PER_NODE: usize = 3;

/// Attaches a superelement with stiffness `k` and mass `m` to `model` (symmetric, of order
/// 6 × the interface nodes plus the modes; rows `ux uy uz rx ry rz` of each interface node, then
/// the modal coordinates; units N, mm, tonne, s, rad): adds its modal nodes, their supports and
/// its pieces, and records it in [`Model::superelements`].
pub fn attach(
    model: &mut Model,
    label: impl Into<String>,
    interface: &[usize],
    k: &DMatrix<f64>,
    m: &DMatrix<f64>,
) -> Result<Attached, FemError> {
    let nb = 6 * interface.len();
    let n = k.nrows();
    if interface.is_empty() || n < nb || k.shape() != (n, n) || m.shape() != (n, n) {
        return Err(FemError::BadInput(format!(
            "a superelement on {} interface nodes needs square K and M of the same order ≥ {nb}, got {:?} and {:?}",
            interface.len(),
            k.shape(),
            m.shape()
        )));
    }
    for (i, &a) in interface.iter().enumerate() {
        model.check_node(|| "superelement interface".into(), a)?;
        if interface[..i].contains(&a) {
            return Err(FemError::BadInput(format!(
                "superelement interface node {a} is named twice"
            )));
        }
    }
    let modes = n - nb;
    let at = model.nodes[interface[0]];
    let modal_nodes: Vec<usize> = (0..modes.div_ceil(MODES_PER_NODE))
        .map(|q| {
            let node = model.add_node(at);
            let used = (modes - MODES_PER_NODE * q).min(MODES_PER_NODE);
            model.supports.push(Support {
                node,
                fix: std::array::from_fn(|d| d >= used),
            });
            node
        })
        .collect();
    let nodes: Vec<usize> = interface.iter().chain(&modal_nodes).copied().collect();
    // Row of DOF d of the j-th node of `nodes`, if it carries one.
    let row = |j: usize, d: usize| -> Option<usize> {
        if j < interface.len() {
            Some(6 * j + d)
        } else {
            let r = nb + MODES_PER_NODE * (j - interface.len()) + d;
            (d < MODES_PER_NODE && r < n).then_some(r)
        }
    };
    let first = model.elements.len();
    for a in 0..nodes.len() {
        for b in a..nodes.len() {
            let two = b != a;
            let (mut ke, mut me) = (Mat12::zeros(), Mat12::zeros());
            let slots = if two { [a, b] } else { [a, a] };
            for (s, &j) in slots.iter().enumerate().take(if two { 2 } else { 1 }) {
                for (t, &l) in slots.iter().enumerate().take(if two { 2 } else { 1 }) {
                    // A pair piece carries only the coupling blocks; diagonal blocks are the
                    // one-node pieces'.
                    if two && s == t {
                        continue;
                    }
                    for d in 0..6 {
                        for e in 0..6 {
                            if let (Some(r), Some(c)) = (row(j, d), row(l, e)) {
                                ke[(6 * s + d, 6 * t + e)] = k[(r, c)];
                                me[(6 * s + d, 6 * t + e)] = m[(r, c)];
                            }
                        }
                    }
                }
            }
            if ke.iter().chain(me.iter()).all(|v| *v == 0.0) {
                continue;
            }
            model.add_element(Element::Matrix(Box::new(MatrixElement {
                nodes: [nodes[a], nodes[b]],
                n_nodes: if two { 2 } else { 1 },
                k: ke,
                m: me,
            })));
        }
    }
    let attached = Attached {
        label: label.into(),
        interface: interface.to_vec(),
        modal_nodes,
        modes,
        elements: first..model.elements.len(),
    };
    model.superelements.push(attached.clone());
    Ok(attached)
}

impl Model {
    /// `true` for each node that is a superelement's modal node (see [`attach`]).
    pub fn modal_node_flags(&self) -> Vec<bool> {
        let mut f = vec![false; self.nodes.len()];
        for s in &self.superelements {
            for &n in &s.modal_nodes {
                if let Some(x) = f.get_mut(n) {
                    *x = true;
                }
            }
        }
        f
    }
}

/// One result note per attached superelement: what it is, its interface and which nodes carry
/// its modal coordinates.
pub fn notes(model: &Model) -> Vec<String> {
    model
        .superelements
        .iter()
        .map(|s| {
            let modal = match (s.modal_nodes.first(), s.modal_nodes.last()) {
                (Some(a), Some(b)) => format!(
                    "; its modal coordinates η1…η{} (mass-normalised, not displacements) are the ux, uy, uz of auxiliary modal nodes {a}…{b} in the node outputs (other DOFs fixed)",
                    s.modes
                ),
                _ => " (Guyan static condensation)".into(),
            };
            format!(
                "the model contains a reduced superelement {}: Craig–Bampton (R. R. Craig, M. C. C. Bampton, \"Coupling of substructures for dynamic analyses\", AIAA J. 6(7), 1968) on interface nodes {:?} with {} fixed-interface modes{modal}",
                s.label, s.interface, s.modes
            )
        })
        .collect()
}
