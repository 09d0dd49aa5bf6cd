//! The 6×6 compliance of a node as the results list it (static `compliance`, and per load step
//! with `track`).

use serde::Serialize;

/// The 6×6 compliance of one node (result field `compliance`).
#[derive(Debug, Clone, Serialize)]
pub struct ComplianceRow {
    /// The node.
    pub node: usize,
    /// Axes of the matrix: rows are the local x, y, z in global coordinates.
    pub frame: [[f64; 3]; 3],
    /// C[i][j] = displacement i per unit load j at the node, order [ux, uy, uz, rx, ry, rz] ×
    /// [Fx, Fy, Fz, Mx, My, Mz] in `frame`: mm/N (translation/force), mm/(N·mm)
    /// (translation/moment), rad/N (rotation/force), rad/(N·mm) (rotation/moment). Symmetric;
    /// rows and columns of supported DOFs are zero.
    pub matrix: [[f64; 6]; 6],
    /// Smallest and largest eigenvalue of the translational 3×3 block, mm/N.
    pub translational_eigen: [f64; 2],
    /// Smallest and largest eigenvalue of the rotational 3×3 block, rad/(N·mm).
    pub rotational_eigen: [f64; 2],
}

/// The [`ComplianceRow`] of `node` from its compliance `c` in global axes, turned into
/// `frame` (rows: local x, y, z; default the global axes).
pub fn compliance_row(node: usize, frame: Option<[[f64; 3]; 3]>, c: &nalgebra::Matrix6<f64>) -> ComplianceRow {
    use nalgebra::{Matrix3, Matrix6};
    let frame = frame.unwrap_or([[1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0]]);
    let f = Matrix3::from_fn(|a, b| frame[a][b]);
    let mut t = Matrix6::zeros();
    t.fixed_view_mut::<3, 3>(0, 0).copy_from(&f);
    t.fixed_view_mut::<3, 3>(3, 3).copy_from(&f);
    let cl = t * c * t.transpose();
    let cl = (cl + cl.transpose()) * 0.5;
    let extremes = |k: usize| {
        let b: Matrix3<f64> = cl.fixed_view::<3, 3>(k, k).into_owned();
        let ev = b.symmetric_eigenvalues();
        [ev.min(), ev.max()]
    };
    ComplianceRow {
        node,
        frame,
        matrix: std::array::from_fn(|a| std::array::from_fn(|b| cl[(a, b)])),
        translational_eigen: extremes(0),
        rotational_eigen: extremes(3),
    }
}
