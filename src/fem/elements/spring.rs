//! Six-DOF spring between two nodes or a node and the ground: data, kinematic matrix B and
//! stiffness Bᵀ diag(k) B.

use super::ElementMatrix;
use crate::fem::error::FemError;
use crate::fem::transform::{frame_from_x_up, rigid_arm, t6};
use nalgebra::{Matrix3, Matrix6, SMatrix, Vector3};

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

impl Spring {
    /// Springs `k` = [kx, ky, kz, krx, kry, krz] along the global axes between nodes `a` and `b`
    /// (`None` = ground).
    pub fn global(a: usize, b: Option<usize>, k: [f64; 6]) -> Spring {
        Spring {
            a,
            b,
            k,
            axes: SpringAxes::Global,
        }
    }

    /// B (6×12, only the first 6 columns used for a ground spring) with δ = B·d the relative
    /// motion in spring axes, and the node count; `xa`, `xb`: coordinates of nodes `a` and `b`
    /// (`xb` unused for a ground spring). Checks stiffnesses and axes (`ie`: the element's
    /// index, for errors).
    pub fn b_matrix(
        &self,
        ie: usize,
        xa: Vector3<f64>,
        xb: Vector3<f64>,
    ) -> Result<(SMatrix<f64, 6, 12>, usize), FemError> {
        if self.k.iter().any(|k| !(k.is_finite() && *k >= 0.0)) {
            return Err(FemError::BadElement {
                element: ie,
                reason: "spring stiffnesses must be finite and non-negative".into(),
            });
        }
        let lam = match self.axes {
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
        match self.b {
            None => {
                bm.fixed_view_mut::<6, 6>(0, 0).copy_from(&l6);
                Ok((bm, 1))
            }
            Some(_) => {
                let mid = (xa + xb) * 0.5;
                bm.fixed_view_mut::<6, 6>(0, 0)
                    .copy_from(&(-l6 * rigid_arm(&(mid - xa))));
                bm.fixed_view_mut::<6, 6>(0, 6)
                    .copy_from(&(l6 * rigid_arm(&(mid - xb))));
                Ok((bm, 2))
            }
        }
    }

    /// Global stiffness K = Bᵀ diag(k) B from B of [`Spring::b_matrix`].
    pub fn matrix(&self, b: &SMatrix<f64, 6, 12>, n_nodes: usize) -> ElementMatrix {
        let kd = Matrix6::from_diagonal(&nalgebra::Vector6::from(self.k));
        ElementMatrix {
            nodes: [self.a, self.b.unwrap_or(self.a)],
            n_nodes,
            k: b.transpose() * kd * b,
        }
    }
}
