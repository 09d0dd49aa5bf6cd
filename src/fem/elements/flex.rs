//! Flexibility (compliance) element: data, local and tip stiffness (see
//! [`crate::fem::element::flex_local_stiffness`]).

use crate::fem::element::{flex_local_stiffness, flex_tip_stiffness};
use crate::fem::error::FemError;
use crate::fem::memo::{remembered, Ring};
use crate::fem::transform::Mat12;
use nalgebra::Matrix6;
use std::cell::RefCell;

/// Two-node element given by its cantilever tip compliance (see
/// [`crate::fem::element::flex_local_stiffness`]). Local axes as for [`super::Beam`]; the
/// length is the node distance.
#[derive(Debug, Clone, PartialEq)]
pub struct FlexElement {
    pub nodes: [usize; 2],
    /// 6×6 compliance of node 2 relative to clamped node 1, local axes at node 2, order
    /// u v w θx θy θz (mm/N, rad/N, rad/(N·mm)); symmetric positive definite.
    pub compliance: [[f64; 6]; 6],
    /// Orientation vector, as for beams.
    pub up: [f64; 3],
}

impl FlexElement {
    fn compliance_matrix(&self) -> Matrix6<f64> {
        Matrix6::from_fn(|i, j| self.compliance[i][j])
    }

    fn bad(ie: usize) -> FemError {
        FemError::BadElement {
            element: ie,
            reason: "compliance must be finite, symmetric and positive definite".into(),
        }
    }

    /// The memo key: `extra`'s bits first, then the compliance's. Keys of one model's
    /// elements mostly share the compliance and differ in the length, so the length first lets
    /// a miss stop at the first word.
    fn key<const N: usize>(&self, extra: Option<f64>) -> [u64; N] {
        let mut k = [0u64; N];
        for (slot, c) in k
            .iter_mut()
            .zip(extra.iter().chain(self.compliance.as_flattened().iter()))
        {
            *slot = c.to_bits();
        }
        k
    }

    /// Local 12×12 stiffness for length `l` (mm) (`ie`: the element's index, for errors).
    pub fn local_stiffness(&self, ie: usize, l: f64) -> Result<Mat12, FemError> {
        remembered(&LOCAL, self.key(Some(l)), || {
            flex_local_stiffness(&self.compliance_matrix(), l).ok_or_else(|| Self::bad(ie))
        })
    }

    /// Tip stiffness C⁻¹ (local axes at node 2).
    pub fn tip_stiffness(&self, ie: usize) -> Result<Matrix6<f64>, FemError> {
        remembered(&TIP, self.key(None), || {
            flex_tip_stiffness(&self.compliance_matrix()).ok_or_else(|| Self::bad(ie))
        })
    }
}

// Stiffnesses already computed from a compliance, remembered per thread (keyed by the exact
// bits of the input). Validation, assembly and recovery each ask for every element's
// stiffness, and a model's flex elements repeat few compliances (a stage's three legs share
// theirs): the inverse is computed once. The local stiffness is keyed by the length too, and
// node distances that are equal on paper differ in their last bits (a pan-tilt mechanism's 8
// hinges of 4 segments each hold 32 (compliance, length) pairs): 48 slots keep a model's pairs
// from evicting each other between validation, assembly and recovery.
thread_local! {
    static LOCAL: RefCell<Ring<[u64; 37], Mat12, 48>> = const { RefCell::new(Ring::new()) };
    static TIP: RefCell<Ring<[u64; 36], Matrix6<f64>, 8>> = const { RefCell::new(Ring::new()) };
}
