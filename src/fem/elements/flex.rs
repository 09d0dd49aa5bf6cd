//! Flexibility (compliance) element: data, local and tip stiffness (see
//! [`crate::fem::element::flex_local_stiffness`]).

use crate::fem::element::{flex_local_stiffness, flex_tip_stiffness};
use crate::fem::error::FemError;
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

    /// The compliance's bits (the memo key), then `extra`.
    fn key<const N: usize>(&self, extra: Option<f64>) -> [u64; N] {
        let mut k = [0u64; N];
        for (slot, c) in k
            .iter_mut()
            .zip(self.compliance.as_flattened().iter().chain(extra.iter()))
        {
            *slot = c.to_bits();
        }
        k
    }

    /// Local 12×12 stiffness for length `l` (mm) (`ie`: the element's index, for errors).
    pub fn local_stiffness(&self, ie: usize, l: f64) -> Result<Mat12, FemError> {
        LOCAL
            .with_borrow_mut(|m| m.get_or(self.key(Some(l)), || flex_local_stiffness(&self.compliance_matrix(), l)))
            .ok_or_else(|| Self::bad(ie))
    }

    /// Tip stiffness C⁻¹ (local axes at node 2).
    pub fn tip_stiffness(&self, ie: usize) -> Result<Matrix6<f64>, FemError> {
        TIP.with_borrow_mut(|m| m.get_or(self.key(None), || flex_tip_stiffness(&self.compliance_matrix())))
            .ok_or_else(|| Self::bad(ie))
    }
}

/// Stiffnesses already computed from a compliance, remembered per thread. Validation,
/// assembly and recovery each ask for every element's stiffness, and a model's flex elements
/// repeat few compliances (a stage's three legs share theirs): the inverse is computed once.
/// The key is the exact bits of the input, so a remembered value is the value computed afresh.
struct Memo<const N: usize, M: Copy> {
    keys: [[u64; N]; SLOTS],
    values: [Option<M>; SLOTS],
    next: usize,
}

/// Entries of a [`Memo`] (replaced oldest first).
const SLOTS: usize = 8;

impl<const N: usize, M: Copy> Memo<N, M> {
    const fn new() -> Self {
        Memo {
            keys: [[0; N]; SLOTS],
            values: [None; SLOTS],
            next: 0,
        }
    }

    /// The value of `key`, computed by `f` (and remembered) unless known; failures are not
    /// remembered.
    fn get_or(&mut self, key: [u64; N], f: impl FnOnce() -> Option<M>) -> Option<M> {
        let known = (0..SLOTS).find(|&i| self.values[i].is_some() && self.keys[i] == key);
        if let Some(i) = known {
            return self.values[i];
        }
        let v = f()?;
        self.keys[self.next] = key;
        self.values[self.next] = Some(v);
        self.next = (self.next + 1) % SLOTS;
        Some(v)
    }
}

thread_local! {
    static LOCAL: RefCell<Memo<37, Mat12>> = const { RefCell::new(Memo::new()) };
    static TIP: RefCell<Memo<36, Matrix6<f64>>> = const { RefCell::new(Memo::new()) };
}
