//! Four-node flat shell, six DOFs per node (u v w θx θy θz), in textbook notation.
//!
//! * **Membrane**: bilinear Q4 with Wilson's incompatible modes 1−ξ², 1−η² (Taylor's
//!   constant-Jacobian correction, so the patch test passes; E. L. Wilson et al. 1973,
//!   R. L. Taylor et al., IJNME 10 (1976) 1211), condensed statically, plus the drilling rotation
//!   by Hughes–Brezzi penalty γ·t∫(θz − ½(∂v/∂x − ∂u/∂y))² dA with γ = G evaluated at the centre
//!   (T. J. R. Hughes, F. Brezzi, CMAME 72 (1989) 105; one point, so it cannot lock) plus the
//!   same penalty 2×2-integrated with 10⁻³·G, which removes the zero-energy θz patterns (linear
//!   and checkerboard) that one point leaves free.
//! * **Bending and transverse shear**: MITC4 (E. N. Dvorkin, K.-J. Bathe, Eng. Comput. 1 (1984)
//!   77): Reissner–Mindlin curvatures from bilinear rotations, 2×2 Gauss; covariant transverse
//!   shear strains tied at the edge midpoints (γ_ξ at (0, ±1), γ_η at (±1, 0)), shear factor 5/6,
//!   with the shear stiffness stabilized as κGt·t²/(t² + α h_K²), α = 0.05, h_K the longer
//!   diagonal (M. Lyly, R. Stenberg, T. Vihinen, CMAME 110 (1993) 343).
//! * **Mass**: lumped (row sums of ρt∫NᵢNⱼ dA on u v w and of ρt³/12∫NᵢNⱼ dA on θx θy), none on
//!   the drilling rotation.
//!
//! Why the stabilization and the lumped mass (coarse meshes). With bilinear w and θ and the
//! shear tied to zero along each edge in the thin limit, an edge's mean rotation equals its chord
//! slope. For a wave w = sin qx on elements of length h this makes the rotations tan(s)/s times
//! too large (s = qh/2) and the strain energy tan²s·sin²s/s⁴ ≈ 1 + s²/3 times too high; the
//! consistent bilinear mass underestimates the kinetic energy by (2 + cos 2s)/3 ≈ 1 − 2s²/3.
//! Together the frequency is ≈ (1 + s²/2) too high: at 8×8 on a clamped square plate
//! (modes 5–6, about 2.7 elements per half wave) +28 %, and up to +48 % on a 45° skew plate.
//! Both errors are of the discretization, not of an implementation defect (pure MITC4 with
//! consistent mass converges to Leissa's values from above at O(h²)). A shear compliance that
//! grows with h² (MacNeal's residual bending flexibility; in the stabilized form above) counters
//! the stiffness excess — for a Timoshenko beam of linear elements, 1/(κGt) + h²/(12D) makes the
//! element exact; α = 0.05 on h_K² is about a third of that on square elements — and a diagonal
//! mass keeps the nodal kinetic energy of the sampled wave.
//! Measured, λ = ωa²√(ρt/D), modes 1–6 at 8×8, error against converged values: clamped square
//! consistent MITC4 +4…+28 %, lumped MITC4 −0.4…+11 %, stabilized + lumped −4.5…+4.9 %;
//! clamped 45° skew +7…+47 %, +3…+20 %, −4.7…+0.0 % (`tests/shell_coarse_mesh.rs`).
//! * **Warped quads**: the element works on the mean plane through the node centroid (normal
//!   g₁ × g₂ of the diagonals' mid-lines); each node is joined to its projection by a rigid arm
//!   of length z_i (MacNeal's rigid-link warping correction), d_proj = R(−z_i n) d_node.
//!
//! Local axes: x along g₁ = ½(x₂ + x₃ − x₁ − x₄), z = normal, y = z × x. Rotations are right-handed
//! about the local axes, so the in-plane displacements through the thickness are
//! u(z) = u + z·θy, v(z) = v − z·θx; curvatures κ = (∂θy/∂x, −∂θx/∂y, ∂θy/∂y − ∂θx/∂x),
//! shear strains γxz = ∂w/∂x + θy, γyz = ∂w/∂y − θx.

use super::transform::{rigid_arm, t6};
use crate::material::Material;
use nalgebra::{Matrix2, Matrix3, SMatrix, SVector, Vector3};

/// 24×24 matrix (four nodes × six DOFs).
pub type Mat24 = SMatrix<f64, 24, 24>;
/// 24-vector.
pub type Vec24 = SVector<f64, 24>;

pub(crate) const XI: [f64; 4] = [-1.0, 1.0, 1.0, -1.0];
pub(crate) const ETA: [f64; 4] = [-1.0, -1.0, 1.0, 1.0];
pub(crate) const G2: f64 = 0.577_350_269_189_625_8;
/// Shear correction factor of the Reissner–Mindlin plate.
pub(crate) const KAPPA: f64 = 5.0 / 6.0;
/// Weight of the fully integrated drilling penalty, relative to γ = G.
const DRILL_STAB: f64 = 1e-3;
/// Shear stabilization α of the MITC4 plate part: transverse shear stiffness
/// κGt·t²/(t² + α h_K²) (M. Lyly, R. Stenberg, T. Vihinen, CMAME 110 (1993) 343). Chosen with
/// numbers on clamped square and 45° skew plates with the lumped mass (see the module notes):
/// α = 0.05 puts modes 1–6 of both within ±5 % at 8×8 and ±2.5 % at 12×12; 0.04 leaves the
/// square's modes 5–6 above +5 %, 0.06 puts the skew plate's mode 4 below −6 %.
const SHEAR_STAB: f64 = 0.05;

/// Geometry of one element: local frame, projected node coordinates, warping offsets.
#[derive(Debug, Clone, PartialEq)]
pub struct ShellGeometry {
    /// Rows: local x, y, z (normal) in global coordinates.
    pub lam: Matrix3<f64>,
    /// Centroid of the four nodes, global.
    pub centre: Vector3<f64>,
    /// Local (x, y) of the projected nodes, mm.
    pub xy: [[f64; 2]; 4],
    /// Signed distance of each node from the mean plane (warping), mm.
    pub warp: [f64; 4],
    /// Transformation d_local = T d_global (frame + warping arms).
    pub t: Mat24,
}

/// Shape functions and their natural derivatives at (ξ, η).
fn shape(xi: f64, eta: f64) -> ([f64; 4], [f64; 4], [f64; 4]) {
    let mut n = [0.0; 4];
    let mut dxi = [0.0; 4];
    let mut deta = [0.0; 4];
    for i in 0..4 {
        n[i] = 0.25 * (1.0 + xi * XI[i]) * (1.0 + eta * ETA[i]);
        dxi[i] = 0.25 * XI[i] * (1.0 + eta * ETA[i]);
        deta[i] = 0.25 * ETA[i] * (1.0 + xi * XI[i]);
    }
    (n, dxi, deta)
}

/// Jacobian J = [[x_ξ, y_ξ], [x_η, y_η]].
fn jacobian(xy: &[[f64; 2]; 4], dxi: &[f64; 4], deta: &[f64; 4]) -> Matrix2<f64> {
    let mut j = Matrix2::zeros();
    for i in 0..4 {
        j[(0, 0)] += dxi[i] * xy[i][0];
        j[(0, 1)] += dxi[i] * xy[i][1];
        j[(1, 0)] += deta[i] * xy[i][0];
        j[(1, 1)] += deta[i] * xy[i][1];
    }
    j
}

/// N, ∂N/∂x, ∂N/∂y, det J and J⁻¹ at one point.
type Cartesian = ([f64; 4], [f64; 4], [f64; 4], f64, Matrix2<f64>);

/// Cartesian derivatives (∂N/∂x, ∂N/∂y) and det J at (ξ, η); `None` for a degenerate map.
pub(crate) fn cartesian(xy: &[[f64; 2]; 4], xi: f64, eta: f64) -> Option<Cartesian> {
    let (n, dxi, deta) = shape(xi, eta);
    let j = jacobian(xy, &dxi, &deta);
    let det = j.determinant();
    if !(det > 0.0 && det.is_finite()) {
        return None;
    }
    let ji = j.try_inverse()?;
    let mut dx = [0.0; 4];
    let mut dy = [0.0; 4];
    for i in 0..4 {
        dx[i] = ji[(0, 0)] * dxi[i] + ji[(0, 1)] * deta[i];
        dy[i] = ji[(1, 0)] * dxi[i] + ji[(1, 1)] * deta[i];
    }
    Some((n, dx, dy, det, ji))
}

/// Local frame and projection of a (possibly warped) quadrilateral; `None` if degenerate
/// (zero area, nodes out of order so that the Jacobian changes sign).
pub fn shell_geometry(x: &[[f64; 3]; 4]) -> Option<ShellGeometry> {
    let p: Vec<Vector3<f64>> = x.iter().map(|v| Vector3::from(*v)).collect();
    let centre = (p[0] + p[1] + p[2] + p[3]) * 0.25;
    let g1 = (p[1] + p[2] - p[0] - p[3]) * 0.5;
    let g2 = (p[2] + p[3] - p[0] - p[1]) * 0.5;
    let nrm = g1.cross(&g2);
    let nn = nrm.norm();
    if !(nn > 0.0 && nn.is_finite()) || g1.norm() <= 0.0 {
        return None;
    }
    let ez = nrm / nn;
    let ex = (g1 - ez * g1.dot(&ez)).normalize();
    let ey = ez.cross(&ex);
    let lam = Matrix3::from_rows(&[ex.transpose(), ey.transpose(), ez.transpose()]);
    let mut xy = [[0.0; 2]; 4];
    let mut warp = [0.0; 4];
    let mut t = Mat24::zeros();
    let l6 = t6(&lam);
    for i in 0..4 {
        let d = lam * (p[i] - centre);
        xy[i] = [d.x, d.y];
        warp[i] = d.z;
        let arm = rigid_arm(&(-ez * d.z));
        t.fixed_view_mut::<6, 6>(6 * i, 6 * i).copy_from(&(l6 * arm));
    }
    for &(xi, eta) in &[(-G2, -G2), (G2, -G2), (G2, G2), (-G2, G2), (0.0, 0.0)] {
        cartesian(&xy, xi, eta)?;
    }
    Some(ShellGeometry {
        lam,
        centre,
        xy,
        warp,
        t,
    })
}

/// Plane-stress elasticity E/(1−ν²)·[[1, ν, 0], [ν, 1, 0], [0, 0, (1−ν)/2]], MPa.
pub fn plane_stress(e: f64, nu: f64) -> Matrix3<f64> {
    let c = e / (1.0 - nu * nu);
    Matrix3::new(c, c * nu, 0.0, c * nu, c, 0.0, 0.0, 0.0, c * (1.0 - nu) / 2.0)
}

/// Local DOF index (in the 24 of the element) of membrane DOF `k` (u v θz) of node `i`.
fn mem(i: usize, k: usize) -> usize {
    6 * i + [0, 1, 5][k]
}
/// Local DOF index of plate DOF `k` (w θx θy) of node `i`.
fn plate(i: usize, k: usize) -> usize {
    6 * i + [2, 3, 4][k]
}

/// Compatible (3×12) and incompatible-mode (3×4) membrane strain rows at (ξ, η), with det J:
/// incompatible modes P₁ = 1−ξ², P₂ = 1−η², derivatives through J₀ scaled by det J₀/det J
/// (Taylor's constant-Jacobian correction of Wilson's modes). Shared by the stiffness and the
/// stress recovery.
pub(crate) type MemRows = (SMatrix<f64, 3, 12>, SMatrix<f64, 3, 4>, f64);

pub(crate) fn membrane_rows(xy: &[[f64; 2]; 4], xi: f64, eta: f64) -> Option<MemRows> {
    let (_, _, _, det0, ji0) = cartesian(xy, 0.0, 0.0)?;
    let (_, dx, dy, det, _) = cartesian(xy, xi, eta)?;
    let mut b = SMatrix::<f64, 3, 12>::zeros();
    for i in 0..4 {
        b[(0, 3 * i)] = dx[i];
        b[(1, 3 * i + 1)] = dy[i];
        b[(2, 3 * i)] = dy[i];
        b[(2, 3 * i + 1)] = dx[i];
    }
    let s = det0 / det;
    let pn = [(-2.0 * xi, 0.0), (0.0, -2.0 * eta)];
    let mut bi = SMatrix::<f64, 3, 4>::zeros();
    for (k, (pxi, peta)) in pn.iter().enumerate() {
        let px = s * (ji0[(0, 0)] * pxi + ji0[(0, 1)] * peta);
        let py = s * (ji0[(1, 0)] * pxi + ji0[(1, 1)] * peta);
        bi[(0, k)] = px;
        bi[(2, k)] = py;
        bi[(1, 2 + k)] = py;
        bi[(2, 2 + k)] = px;
    }
    Some((b, bi, det))
}

/// Membrane stiffness (12 DOFs u v θz per node, condensed incompatible modes, drilling).
fn membrane(xy: &[[f64; 2]; 4], t: f64, mat: &Material) -> Option<SMatrix<f64, 12, 12>> {
    let c = plane_stress(mat.e, mat.nu) * t;
    let mut kcc = SMatrix::<f64, 12, 12>::zeros();
    let mut kci = SMatrix::<f64, 12, 4>::zeros();
    let mut kii = SMatrix::<f64, 4, 4>::zeros();
    for &xi in &[-G2, G2] {
        for &eta in &[-G2, G2] {
            let (b, bi, det) = membrane_rows(xy, xi, eta)?;
            kcc += b.transpose() * c * b * det;
            kci += b.transpose() * c * bi * det;
            kii += bi.transpose() * c * bi * det;
        }
    }
    let kii_inv = kii.try_inverse()?;
    let k = kcc - kci * kii_inv * kci.transpose() + drilling(xy, t, mat)?;
    Some((k + k.transpose()) * 0.5)
}

/// Drilling penalty over (u v θz) × 4: γ·t∫(θz − ½(∂v/∂x − ∂u/∂y))² dA with γ = G at the
/// centre (area 4 det J₀) plus the weak 2×2 part with 10⁻³·G, which removes the zero-energy θz
/// patterns the centre point leaves (linear and checkerboard ω with zero mean).
fn drilling(xy: &[[f64; 2]; 4], t: f64, mat: &Material) -> Option<SMatrix<f64, 12, 12>> {
    let g = mat.shear_modulus();
    let row = |xi: f64, eta: f64| {
        let (n, dx, dy, det, _) = cartesian(xy, xi, eta)?;
        let mut r = SVector::<f64, 12>::zeros();
        for i in 0..4 {
            r[3 * i] = 0.5 * dy[i];
            r[3 * i + 1] = -0.5 * dx[i];
            r[3 * i + 2] = n[i];
        }
        Some((r, det))
    };
    let (r0, det0) = row(0.0, 0.0)?;
    let mut k = r0 * r0.transpose() * (g * t * 4.0 * det0);
    for &xi in &[-G2, G2] {
        for &eta in &[-G2, G2] {
            let (r, det) = row(xi, eta)?;
            k += r * r.transpose() * (DRILL_STAB * g * t * det);
        }
    }
    Some(k)
}

/// Global drilling-penalty stiffness Tᵀ k_d T of a shell element (24×24): the part of its
/// stiffness that rests on the artificial drilling rotation. A mode or a deformation whose
/// strain energy sits mostly here is not governed by shell theory.
pub fn shell_drilling_stiffness(x: &[[f64; 3]; 4], t: f64, mat: &Material) -> Option<Mat24> {
    let g = shell_geometry(x)?;
    let kd = drilling(&g.xy, t, mat)?;
    let mut k = Mat24::zeros();
    for a in 0..12 {
        for b in 0..12 {
            k[(mem(a / 3, a % 3), mem(b / 3, b % 3))] = kd[(a, b)];
        }
    }
    Some(g.t.transpose() * k * g.t)
}

/// MITC4 covariant shear rows at a tying point: (γ_ξ, γ_η) as rows over (w θx θy) × 4.
fn covariant_shear(xy: &[[f64; 2]; 4], xi: f64, eta: f64) -> SMatrix<f64, 2, 12> {
    let (n, dxi, deta) = shape(xi, eta);
    let j = jacobian(xy, &dxi, &deta);
    let mut b = SMatrix::<f64, 2, 12>::zeros();
    for i in 0..4 {
        // γ_ξ = w_ξ + θy x_ξ − θx y_ξ
        b[(0, 3 * i)] = dxi[i];
        b[(0, 3 * i + 1)] = -n[i] * j[(0, 1)];
        b[(0, 3 * i + 2)] = n[i] * j[(0, 0)];
        b[(1, 3 * i)] = deta[i];
        b[(1, 3 * i + 1)] = -n[i] * j[(1, 1)];
        b[(1, 3 * i + 2)] = n[i] * j[(1, 0)];
    }
    b
}

/// Curvature rows B_b (κxx, κyy, κxy over (w θx θy) × 4).
pub(crate) fn curvature_b(dx: &[f64; 4], dy: &[f64; 4]) -> SMatrix<f64, 3, 12> {
    let mut b = SMatrix::<f64, 3, 12>::zeros();
    for i in 0..4 {
        b[(0, 3 * i + 2)] = dx[i];
        b[(1, 3 * i + 1)] = -dy[i];
        b[(2, 3 * i + 1)] = -dx[i];
        b[(2, 3 * i + 2)] = dy[i];
    }
    b
}

/// MITC4 shear rows (γxz, γyz) at (ξ, η).
pub(crate) fn mitc_shear_b(xy: &[[f64; 2]; 4], xi: f64, eta: f64, ji: &Matrix2<f64>) -> SMatrix<f64, 2, 12> {
    let b_b = covariant_shear(xy, 0.0, -1.0);
    let b_d = covariant_shear(xy, 0.0, 1.0);
    let b_a = covariant_shear(xy, -1.0, 0.0);
    let b_c = covariant_shear(xy, 1.0, 0.0);
    let mut cov = SMatrix::<f64, 2, 12>::zeros();
    for k in 0..12 {
        cov[(0, k)] = 0.5 * (1.0 - eta) * b_b[(0, k)] + 0.5 * (1.0 + eta) * b_d[(0, k)];
        cov[(1, k)] = 0.5 * (1.0 - xi) * b_a[(1, k)] + 0.5 * (1.0 + xi) * b_c[(1, k)];
    }
    ji * cov
}

/// Element diameter h_K: the longer diagonal of the projected quadrilateral, mm.
fn diameter(xy: &[[f64; 2]; 4]) -> f64 {
    let d = |a: usize, b: usize| (xy[a][0] - xy[b][0]).hypot(xy[a][1] - xy[b][1]);
    d(0, 2).max(d(1, 3))
}

/// Transverse shear stiffness of the stabilized MITC4, N/mm: κGt · t²/(t² + α h_K²).
pub fn stabilized_shear_stiffness(xy: &[[f64; 2]; 4], t: f64, mat: &Material) -> f64 {
    let hk = diameter(xy);
    KAPPA * mat.shear_modulus() * t * t * t / (t * t + SHEAR_STAB * hk * hk)
}

/// Plate stiffness (bending + stabilized MITC4 shear) over (w θx θy) × 4.
fn plate_k(xy: &[[f64; 2]; 4], t: f64, mat: &Material) -> Option<SMatrix<f64, 12, 12>> {
    let db = plane_stress(mat.e, mat.nu) * (t * t * t / 12.0);
    let ds = stabilized_shear_stiffness(xy, t, mat);
    let mut k = SMatrix::<f64, 12, 12>::zeros();
    for &xi in &[-G2, G2] {
        for &eta in &[-G2, G2] {
            let (_, dx, dy, det, ji) = cartesian(xy, xi, eta)?;
            let bb = curvature_b(&dx, &dy);
            let bs = mitc_shear_b(xy, xi, eta, &ji);
            k += (bb.transpose() * db * bb + bs.transpose() * bs * ds) * det;
        }
    }
    Some((k + k.transpose()) * 0.5)
}

/// Local 24×24 stiffness of the flat element on its projected nodes.
pub fn shell_local_stiffness(xy: &[[f64; 2]; 4], t: f64, mat: &Material) -> Option<Mat24> {
    let km = membrane(xy, t, mat)?;
    let kp = plate_k(xy, t, mat)?;
    let mut k = Mat24::zeros();
    for a in 0..12 {
        for b in 0..12 {
            k[(mem(a / 3, a % 3), mem(b / 3, b % 3))] += km[(a, b)];
            k[(plate(a / 3, a % 3), plate(b / 3, b % 3))] += kp[(a, b)];
        }
    }
    Some(k)
}

/// Lumped local mass: row sums of ρt∫NᵢNⱼ dA on u v w and of ρt³/12∫NᵢNⱼ dA on θx θy (for the
/// bilinear element these equal the HRZ diagonal on parallelograms and stay positive on any
/// convex quadrilateral), none on the drilling rotation θz. tonne, tonne·mm².
///
/// Lumped rather than consistent: with the stabilized shear the consistent mass would put the
/// coarse-mesh error back (the module notes; clamped square 8×8 modes 5–6 +8 %, 45° skew up to
/// +12 %, against ±5 % lumped).
///
/// θz is not a degree of freedom of Reissner–Mindlin shell theory: it only ties to the membrane's
/// in-plane rotation through the drilling penalty. Rotary inertia on it made the θz patterns
/// that only the weak (10⁻³·G) part of that penalty resists into spurious modes at
/// f ≈ √(12·10⁻³·G/(ρt²))/2π, independent of the mesh and below the first bending mode of thick
/// plates (a clamped rhombic plate, t/a = 0.1: 103 Hz against 141 Hz; `tests/shell_drilling.rs`).
/// Without it those patterns have no mass and no mode: shift-invert Lanczos never sees them.
pub fn shell_local_mass(xy: &[[f64; 2]; 4], t: f64, rho: f64) -> Option<Mat24> {
    let mut nn = SMatrix::<f64, 4, 4>::zeros();
    for &xi in &[-G2, G2] {
        for &eta in &[-G2, G2] {
            let (n, _, _, det, _) = cartesian(xy, xi, eta)?;
            for i in 0..4 {
                for j in 0..4 {
                    nn[(i, j)] += n[i] * n[j] * det;
                }
            }
        }
    }
    let mut m = Mat24::zeros();
    let (mt, mr) = (rho * t, rho * t * t * t / 12.0);
    for i in 0..4 {
        let share: f64 = (0..4).map(|j| nn[(i, j)]).sum();
        for d in 0..5 {
            m[(6 * i + d, 6 * i + d)] = share * if d < 3 { mt } else { mr };
        }
    }
    Some(m)
}

/// Global stiffness K = Tᵀ k T of a shell element with nodes at `x`.
pub fn shell_stiffness(x: &[[f64; 3]; 4], t: f64, mat: &Material) -> Option<Mat24> {
    let g = shell_geometry(x)?;
    let k = shell_local_stiffness(&g.xy, t, mat)?;
    let kg = g.t.transpose() * k * g.t;
    Some((kg + kg.transpose()) * 0.5)
}

/// Global lumped mass M = Tᵀ m T (not diagonal in global axes for warped quads: the rigid
/// arms couple translations and rotations).
pub fn shell_mass(x: &[[f64; 3]; 4], t: f64, rho: f64) -> Option<Mat24> {
    let g = shell_geometry(x)?;
    let m = shell_local_mass(&g.xy, t, rho)?;
    let mg = g.t.transpose() * m * g.t;
    Some((mg + mg.transpose()) * 0.5)
}

/// Stresses at the element centre, local axes (MPa): von Mises at the top (z = +t/2), middle
/// and bottom surfaces, plus the membrane forces n = (nxx, nyy, nxy) (N/mm) and moments
/// m = (mxx, myy, mxy) (N·mm/mm).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ShellStress {
    /// Von Mises stress [top, mid, bottom], MPa.
    pub von_mises: [f64; 3],
    /// Membrane forces per unit length, N/mm.
    pub n: [f64; 3],
    /// Bending moments per unit length, N·mm/mm.
    pub m: [f64; 3],
}

/// Plane-stress von Mises √(σx² − σxσy + σy² + 3τ²).
pub fn von_mises_plane(s: &[f64; 3]) -> f64 {
    (s[0] * s[0] - s[0] * s[1] + s[1] * s[1] + 3.0 * s[2] * s[2])
        .max(0.0)
        .sqrt()
}

/// Centre stresses from the global element displacements (24). The incompatible modes have
/// zero derivatives at the centre, so they do not enter.
pub fn shell_stress(x: &[[f64; 3]; 4], t: f64, mat: &Material, d_global: &Vec24) -> Option<ShellStress> {
    let g = shell_geometry(x)?;
    let d = g.t * d_global;
    let (_, dx, dy, _, _) = cartesian(&g.xy, 0.0, 0.0)?;
    let mut eps = Vector3::zeros();
    let mut kap = Vector3::zeros();
    for i in 0..4 {
        let (u, v) = (d[6 * i], d[6 * i + 1]);
        let (tx, ty) = (d[6 * i + 3], d[6 * i + 4]);
        eps += Vector3::new(dx[i] * u, dy[i] * v, dy[i] * u + dx[i] * v);
        kap += Vector3::new(dx[i] * ty, -dy[i] * tx, dy[i] * ty - dx[i] * tx);
    }
    let c = plane_stress(mat.e, mat.nu);
    let sm = c * eps;
    let sb = c * kap * (t / 2.0);
    let top = sm + sb;
    let bot = sm - sb;
    let arr = |v: Vector3<f64>| [v.x, v.y, v.z];
    Some(ShellStress {
        von_mises: [
            von_mises_plane(&arr(top)),
            von_mises_plane(&arr(sm)),
            von_mises_plane(&arr(bot)),
        ],
        n: arr(sm * t),
        m: arr(c * kap * (t * t * t / 12.0)),
    })
}
