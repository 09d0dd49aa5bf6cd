//! Local frames and rigid-arm transfers (elements do not own their geometry transformation).

use nalgebra::{Matrix3, Matrix6, SMatrix, Vector3};

/// 12×12 matrix (two nodes × six DOFs).
pub type Mat12 = SMatrix<f64, 12, 12>;

/// Relative tolerance below which `up` counts as parallel to the element axis
/// (|up − (up·x)x| < 1e-6·|up|).
pub const PARALLEL_TOL: f64 = 1e-6;

/// Direction cosines Λ (rows = local x, y, z in global coordinates), v_local = Λ·v_global.
///
/// Local x runs from node 1 to node 2; local z is the component of `up` normal to x;
/// local y = z × x. Returns `None` when the length is zero or `up` is (nearly) parallel to x;
/// the caller names the element.
pub fn beam_frame(x1: [f64; 3], x2: [f64; 3], up: [f64; 3]) -> Option<(Matrix3<f64>, f64)> {
    let d = Vector3::from(x2) - Vector3::from(x1);
    let l = d.norm();
    if !(l > 0.0 && l.is_finite()) {
        return None;
    }
    let ex = d / l;
    frame_from_x_up(ex, Vector3::from(up)).map(|lam| (lam, l))
}

/// Orthonormal frame from an axis `x` and an `up` vector (see [`beam_frame`]).
pub fn frame_from_x_up(x: Vector3<f64>, up: Vector3<f64>) -> Option<Matrix3<f64>> {
    let xn = x.norm();
    let un = up.norm();
    if !(xn > 0.0 && un > 0.0 && xn.is_finite() && un.is_finite()) {
        return None;
    }
    let ex = x / xn;
    let ez_raw = up - ex * up.dot(&ex);
    if ez_raw.norm() < PARALLEL_TOL * un {
        return None;
    }
    let ez = ez_raw.normalize();
    let ey = ez.cross(&ex);
    Some(Matrix3::from_rows(&[ex.transpose(), ey.transpose(), ez.transpose()]))
}

/// T = diag(Λ, Λ, Λ, Λ): d_local = T·d_global for a two-node element; K = Tᵀ k T.
pub fn t12(lam: &Matrix3<f64>) -> Mat12 {
    let mut t = Mat12::zeros();
    for b in 0..4 {
        t.fixed_view_mut::<3, 3>(3 * b, 3 * b).copy_from(lam);
    }
    t
}

/// K = Tᵀ k T for T = diag(Λ, Λ, Λ, Λ), computed block by block (K_ij = Λᵀ k_ij Λ on the
/// sixteen 3×3 blocks): a quarter of the work of the full 12×12 products.
pub fn rotate12(k: &Mat12, lam: &Matrix3<f64>) -> Mat12 {
    let mut out = Mat12::zeros();
    let lt = lam.transpose();
    for bi in 0..4 {
        for bj in 0..4 {
            let blk: Matrix3<f64> = k.fixed_view::<3, 3>(3 * bi, 3 * bj).into_owned();
            out.fixed_view_mut::<3, 3>(3 * bi, 3 * bj).copy_from(&(lt * blk * lam));
        }
    }
    out
}

/// diag(Λ, Λ) for one node.
pub fn t6(lam: &Matrix3<f64>) -> Matrix6<f64> {
    let mut t = Matrix6::zeros();
    t.fixed_view_mut::<3, 3>(0, 0).copy_from(lam);
    t.fixed_view_mut::<3, 3>(3, 3).copy_from(lam);
    t
}

/// Skew matrix [a×] with [a×]·b = a × b.
pub fn skew(a: &Vector3<f64>) -> Matrix3<f64> {
    Matrix3::new(0.0, -a.z, a.y, a.z, 0.0, -a.x, -a.y, a.x, 0.0)
}

/// Rigid-arm transfer R(a): the motion of a point at offset `a` (mm) from a node moving with it
/// rigidly, under small rotations: u_p = u + θ × a, θ_p = θ, i.e.
/// R = [[I, −[a×]], [0, I]]. Its transpose moves a force/moment from the point to the node
/// (M_node = M + a × F).
pub fn rigid_arm(a: &Vector3<f64>) -> Matrix6<f64> {
    let mut r = Matrix6::identity();
    r.fixed_view_mut::<3, 3>(0, 3).copy_from(&(-skew(a)));
    r
}
