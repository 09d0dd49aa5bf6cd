//! The element kinds, one file each with its data and its matrices: [`Beam`], [`FlexElement`],
//! [`Spring`], [`Shell4`], [`Shell9`], [`MatrixElement`]. [`super::model::Model`] dispatches to them by [`Element`].

pub mod beam;
pub mod flex;
pub mod matrix;
pub mod shell4;
pub mod shell9;
pub mod spring;

pub use beam::Beam;
pub use flex::FlexElement;
pub use matrix::MatrixElement;
pub use shell4::{Shell4, ShellMatrix};
pub use shell9::{Shell9, Shell9Matrix};
pub use spring::{Spring, SpringAxes};

use super::error::FemError;
use super::transform::Mat12;
use crate::material::Material;

/// Elements that contribute stiffness.
#[derive(Debug, Clone, PartialEq)]
pub enum Element {
    Beam(Beam),
    Flex(FlexElement),
    Spring(Spring),
    Shell4(Shell4),
    /// Nine-node flat shell.
    Shell9(Shell9),
    /// Given stiffness and mass matrices (superelement pieces); boxed, it is large.
    Matrix(Box<MatrixElement>),
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
            Element::Shell9(s) => s.nodes.to_vec(),
            Element::Matrix(m) => m.nodes[..m.n_nodes].to_vec(),
        }
    }

    /// The two end nodes of a two-node element (a ground spring repeats its node; a shell gives
    /// its first two nodes).
    pub fn end_nodes(&self) -> [usize; 2] {
        match self {
            Element::Beam(b) => b.nodes,
            Element::Flex(f) => f.nodes,
            Element::Spring(s) => [s.a, s.b.unwrap_or(s.a)],
            Element::Shell4(s) => [s.nodes[0], s.nodes[1]],
            Element::Shell9(s) => [s.nodes[0], s.nodes[1]],
            Element::Matrix(m) if m.n_nodes == 2 => m.nodes,
            Element::Matrix(m) => [m.nodes[0]; 2],
        }
    }
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

/// Checks a shell element `ie`: its material and a positive, finite thickness `t` (mm).
pub(crate) fn check_shell(ie: usize, t: f64, m: &Material) -> Result<(), FemError> {
    check_material(ie, m)?;
    if !(t.is_finite() && t > 0.0) {
        return Err(FemError::BadElement {
            element: ie,
            reason: format!("shell thickness must be positive and finite, got {t}"),
        });
    }
    Ok(())
}

/// Checks an isotropic material of element `ie`: E > 0 and −1 < ν < 0.5.
pub(crate) fn check_material(ie: usize, m: &Material) -> Result<(), FemError> {
    if !(m.e.is_finite() && m.e > 0.0 && m.nu.is_finite() && m.nu > -1.0 && m.nu < 0.5) {
        return Err(FemError::BadElement {
            element: ie,
            reason: format!("material needs E > 0 and −1 < ν < 0.5 (E = {}, ν = {})", m.e, m.nu),
        });
    }
    Ok(())
}
