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
//!   shear stiffness κGt (no stabilization).
//! * **Mass**: lumped (row sums of ρt∫NᵢNⱼ dA on u v w and of ρt³/12∫NᵢNⱼ dA on θx θy) plus the
//!   rotary inertia of each node's tributary tile on θx θy ([`shell_local_mass`]), none on the
//!   drilling rotation.
//!
//! Coarse meshes in free vibration. With bilinear w and θ and the shear tied to zero along each
//! edge in the thin limit, an edge's mean rotation equals its chord slope. For a wave w = sin qx
//! on elements of length h this makes the rotations tan(s)/s times too large (s = qh/2) and the
//! strain energy tan²s·sin²s/s⁴ ≈ 1 + s²/3 times too high; the consistent bilinear mass
//! underestimates the kinetic energy by (2 + cos 2s)/3 ≈ 1 − 2s²/3. Together the frequency is
//! ≈ (1 + s²/2) too high: at 8×8 on a clamped square plate (modes 5–6, about 2.7 elements per
//! half wave) +28 %, and up to +48 % on a 45° skew plate. Both errors are of the discretization,
//! not of an implementation defect (MITC4 with consistent mass converges to Leissa's values
//! from above at O(h²)). The lumped mass keeps the kinetic energy of the sampled wave and the
//! tiles add the ≈ s²/3 that balances the stiffness excess of a wave along one direction. For a
//! plane wave at angle φ to the lines of a mesh of squares the whole error is, to O((qh)²),
//! ω_h/ω − 1 = (qh)²/8·[1/3 − (13 + ν)/24·sin²2φ − α], α the mass's share (0 lumped, 1/3 with the
//! tiles, −2/3 consistent): the bilinear rotations across an oblique wave lower its excess. A mass
//! built from the element's geometry adds the same α in every direction on such a mesh, so none
//! balances both (Bloch analysis and the Kirchhoff-cubic, blended and HRZ masses measured in
//! `tests/shell_coarse_mesh.rs`).
//! Measured, λ = ωa²√(ρt/D), modes 1–6 at 8×8, error against converged values: clamped square
//! consistent MITC4 +4…+28 %, lumped −0.1…+11.7 %, lumped + tiles −7.1…+0.8 % (12×12 −3.1…+0.4 %);
//! clamped 45° skew +7…+47 %, +3…+20 %, +0.6…+7.1 % (12×12 +0.0…+2.9 %)
//! (`tests/shell_coarse_mesh.rs`). A shear stabilization κGt·t²/(t² + α h_K²) (M. Lyly,
//! R. Stenberg, T. Vihinen, CMAME 110 (1993) 343) with α = 0.05 chosen on these plates put them
//! within ±5 % at 8×8 but made thin folded and curved shells 0.4–0.7 % too flexible even after
//! extrapolation, and 5 % off plain MITC4 on a distorted plate mesh: the statics are plain MITC4
//! again (`tests/shell_opensees.rs`).
//! * **Warped quads**: the element works on the mean plane through the node centroid (normal
//!   g₁ × g₂ of the diagonals' mid-lines); each node is joined to its projection by a rigid arm
//!   of length z_i (MacNeal's rigid-link warping correction), d_proj = R(−z_i n) d_node.
//!
//! Local axes: x along g₁ = ½(x₂ + x₃ − x₁ − x₄), z = normal, y = z × x. Rotations are right-handed
//! about the local axes, so the in-plane displacements through the thickness are
//! u(z) = u + z·θy, v(z) = v − z·θx; curvatures κ = (∂θy/∂x, −∂θx/∂y, ∂θy/∂y − ∂θx/∂x),
//! shear strains γxz = ∂w/∂x + θy, γyz = ∂w/∂y − θx.
//!
//! Files: this one holds the geometry, shape functions and the assembled element matrices;
//! `shell/membrane.rs` the membrane and drilling parts, `shell/plate.rs` the MITC4 plate part,
//! `shell/stress.rs` the stress recovery.

use super::transform::{rigid_arm, t6};
use crate::material::Material;
use nalgebra::{Matrix2, Matrix3, SMatrix, SVector, Vector3};

mod membrane;
mod plate;
mod stress;

use membrane::membrane;
pub(crate) use membrane::membrane_rows;
pub use membrane::shell_drilling_stiffness;
use plate::plate_k;
pub use plate::transverse_shear_stiffness;
pub(crate) use plate::{curvature_b, mitc_shear_b};
pub(crate) use stress::stress_from_strains;
pub use stress::{shell_stress, von_mises_plane, ShellStress};

/// 24×24 matrix (four nodes × six DOFs).
pub type Mat24 = SMatrix<f64, 24, 24>;
/// 24-vector.
pub type Vec24 = SVector<f64, 24>;

pub(crate) const XI: [f64; 4] = [-1.0, 1.0, 1.0, -1.0];
pub(crate) const ETA: [f64; 4] = [-1.0, -1.0, 1.0, 1.0];
pub(crate) const G2: f64 = 0.577_350_269_189_625_8;
/// Shear correction factor of the Reissner–Mindlin plate.
pub(crate) const KAPPA: f64 = 5.0 / 6.0;

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

/// Jacobian J = [[x_ξ, y_ξ], [x_η, y_η]] of an `N`-node map (four- and nine-node shells).
pub(crate) fn jacobian<const N: usize>(xy: &[[f64; 2]; N], dxi: &[f64; N], deta: &[f64; N]) -> Matrix2<f64> {
    let mut j = Matrix2::zeros();
    for i in 0..N {
        j[(0, 0)] += dxi[i] * xy[i][0];
        j[(0, 1)] += dxi[i] * xy[i][1];
        j[(1, 0)] += deta[i] * xy[i][0];
        j[(1, 1)] += deta[i] * xy[i][1];
    }
    j
}

/// N, ∂N/∂x, ∂N/∂y, det J and J⁻¹ at one point of an `N`-node element.
pub(crate) type Cartesian<const N: usize> = ([f64; N], [f64; N], [f64; N], f64, Matrix2<f64>);

/// Cartesian derivatives (∂N/∂x, ∂N/∂y) and det J at (ξ, η); `None` for a degenerate map.
pub(crate) fn cartesian(xy: &[[f64; 2]; 4], xi: f64, eta: f64) -> Option<Cartesian<4>> {
    let (n, dxi, deta) = shape(xi, eta);
    to_cartesian(xy, n, &dxi, &deta)
}

/// Shape functions `n` with natural derivatives (`dxi`, `deta`) of an `N`-node map to its
/// Cartesian derivatives, det J and J⁻¹; `None` where det J ≤ 0 (a folded or degenerate map).
pub(crate) fn to_cartesian<const N: usize>(
    xy: &[[f64; 2]; N],
    n: [f64; N],
    dxi: &[f64; N],
    deta: &[f64; N],
) -> Option<Cartesian<N>> {
    let j = jacobian(xy, dxi, deta);
    let det = j.determinant();
    if !(det > 0.0 && det.is_finite()) {
        return None;
    }
    let ji = j.try_inverse()?;
    let mut dx = [0.0; N];
    let mut dy = [0.0; N];
    for i in 0..N {
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

/// Lumped local mass with the rotary inertia of each node's tributary tile, tonne, tonne·mm².
///
/// * u v w: row sums ρt∫NᵢNⱼ dA (for the bilinear element the HRZ diagonal on parallelograms,
///   positive on any convex quadrilateral).
/// * θx θy: ρt³/12∫NᵢNⱼ dA (the plate's own rotary inertia) plus the second moments of the
///   node's tile Ωᵢ, the quarter of the element nearest node i (the image of the natural
///   quadrant between ξ = 0 and ξᵢ, η = 0 and ηᵢ), about the node: the lumped mass ρt|Ωᵢ| is
///   not a point but the tile, and a tile that tilts with the normal (w − wᵢ = θx·Δy − θy·Δx in
///   the thin limit) carries the kinetic energy ½ρt∫(θx·Δy − θy·Δx)² dA, i.e. the 2×2 block
///   ρt [[∫Δy², −∫ΔxΔy], [−∫ΔxΔy, ∫Δx²]] on (θx, θy) (positive semi-definite). It vanishes as
///   O(h²) under refinement, so the converged frequencies are those of the consistent mass.
/// * θz: none (below).
///
/// Why the tiles (coarse meshes). For a wave w = sin qx on elements of length h (s = qh/2) the
/// thin-limit MITC4 rotation is tan(s)/s times the slope and the strain energy
/// tan²s·sin²s/s⁴ ≈ 1 + s²/3 times too high (module notes); the translational lumped mass keeps
/// the kinetic energy of the sampled wave, and the tiles (∫Δx² = h²/12 per unit area on a
/// uniform mesh) add tan²s/3 ≈ s²/3 to it: stiffness and mass excess cancel to O(s⁴), with no
/// constant to choose. The same idea as the rotary inertia of lumped shell masses in
/// K. S. Surana, "Lumped mass matrices with non-zero inertia for general shell and axisymmetric
/// shell elements", IJNME 12 (1978) 1635–1650.
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
        let [jxx, jyy, jxy] = tile_moments(xy, i)?;
        m[(6 * i + 3, 6 * i + 3)] += mt * jyy;
        m[(6 * i + 4, 6 * i + 4)] += mt * jxx;
        m[(6 * i + 3, 6 * i + 4)] -= mt * jxy;
        m[(6 * i + 4, 6 * i + 3)] -= mt * jxy;
    }
    Some(m)
}

/// Second moments [∫Δx², ∫Δy², ∫ΔxΔy] (mm⁴) about node `i` of its tile: the image of the natural
/// quadrant ξ ∈ [0, ξᵢ], η ∈ [0, ηᵢ]. 2×2 Gauss on the quadrant is exact (bilinear map).
fn tile_moments(xy: &[[f64; 2]; 4], i: usize) -> Option<[f64; 3]> {
    let mut out = [0.0; 3];
    for &a in &[-G2, G2] {
        for &b in &[-G2, G2] {
            let (xi, eta) = (0.5 * XI[i] * (1.0 + a), 0.5 * ETA[i] * (1.0 + b));
            let (n, _, _, det, _) = cartesian(xy, xi, eta)?;
            let x: f64 = (0..4).map(|k| n[k] * xy[k][0]).sum::<f64>() - xy[i][0];
            let y: f64 = (0..4).map(|k| n[k] * xy[k][1]).sum::<f64>() - xy[i][1];
            // Quadrant → element: dξ dη = ¼ da db.
            let w = 0.25 * det;
            out[0] += w * x * x;
            out[1] += w * y * y;
            out[2] += w * x * y;
        }
    }
    Some(out)
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
