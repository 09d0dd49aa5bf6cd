//! Nine-node flat shell, six DOFs per node (u v w θx θy θz): the MITC9 plate with a
//! biquadratic membrane, for coarse meshes of flat plates and leaves in free vibration.
//!
//! * **Geometry**: a flat element. Nodes in the order of gmsh's nine-node quadrangle: corners
//!   0–3 around the element (ξ, η) = (−1, −1), (1, −1), (1, 1), (−1, 1), edge midpoints 4–7 on
//!   the edges 0–1, 1–2, 2–3, 3–0, node 8 at the centre. The local frame is that of the four-node
//!   shell on the corners ([`super::shell`]); a node off the plane by more than
//!   [`MAX_WARP`]·(the longer diagonal) is refused (a curved surface needs a curved element, and
//!   this is not one), a smaller offset is joined to the plane by a rigid arm as in the
//!   four-node shell.
//! * **Membrane**: nine-node Lagrange plane stress, 3×3 Gauss, plus the Hughes–Brezzi drilling
//!   penalty γ·t∫(θz − ½(∂v/∂x − ∂u/∂y))² dA with γ = G at the 2×2 Gauss points and 10⁻³·G at
//!   the 3×3 points (the weak part removes the θz patterns that 2×2 leaves free), as in the
//!   four-node shell.
//! * **Bending and transverse shear**: MITC9 (M. L. Bucalem, K.-J. Bathe, "Higher-order MITC
//!   general shell elements", IJNME 36 (1993) 3729–3754; K.-J. Bathe, Finite Element Procedures,
//!   2nd ed. (2014), §5.4.2): curvatures from biquadratic rotations, 3×3 Gauss; the covariant
//!   shear γ_ξ tied at ξ = ±a, η ∈ {−b, 0, b} and interpolated linearly in ξ, quadratically in η
//!   (γ_η likewise with ξ and η exchanged), a = 1/√3, b = √(3/5); shear factor 5/6, κGt, no
//!   stabilization.
//! * **Mass**: consistent, ρt∫NᵢNⱼ dA on u v w, ρt³/12∫NᵢNⱼ dA on θx θy (3×3 Gauss, exact on a
//!   parallelogram), none on θz (as the four-node shell: the drilling rotation is not a DOF of
//!   shell theory).
//!
//! Why: the four-node shell's frequency error on coarse meshes depends on the direction of the
//! wave across the mesh (its module notes), so no mass balances it; the biquadratic element
//! interpolates a wave well enough that the consistent mass needs no balancing. Clamped square
//! and 45° skew plates, modes 1–6, at 8×8 and 4×4 (the node grid of the four-node shell's 8×8):
//! `tests/shell9.rs`, with an independent MITC9 written from the papers
//! (`tools/mitc9_reference/`).
//!
//! Local axes and sign conventions are those of [`super::shell`]: u(z) = u + z·θy,
//! v(z) = v − z·θx; κ = (∂θy/∂x, −∂θx/∂y, ∂θy/∂y − ∂θx/∂x), γxz = ∂w/∂x + θy, γyz = ∂w/∂y − θx.

use super::shell::{jacobian, plane_stress, stress_from_strains, to_cartesian, Cartesian, ShellStress, KAPPA};
use super::transform::{rigid_arm, t6};
use crate::material::Material;
use nalgebra::{DMatrix, DVector, Matrix2, Matrix3, SMatrix, Vector3};

/// Largest offset of a node from the element's plane, relative to its longer diagonal.
pub const MAX_WARP: f64 = 1e-3;

/// Natural coordinates of the nine nodes (gmsh order).
pub const NODE_XI: [f64; 9] = [-1.0, 1.0, 1.0, -1.0, 0.0, 1.0, 0.0, -1.0, 0.0];
/// See [`NODE_XI`].
pub const NODE_ETA: [f64; 9] = [-1.0, -1.0, 1.0, 1.0, -1.0, 0.0, 1.0, 0.0, 0.0];

const G2: f64 = 0.577_350_269_189_625_8;
pub(crate) const G3: f64 = 0.774_596_669_241_483_4;
const GAUSS3: [(f64, f64); 3] = [(-G3, 5.0 / 9.0), (0.0, 8.0 / 9.0), (G3, 5.0 / 9.0)];
/// Weak part of the drilling penalty, relative to γ = G (as the four-node shell).
const DRILL_STAB: f64 = 1e-3;

/// Quadratic Lagrange polynomials through −1, 0, 1 and their derivatives.
pub(crate) fn lagrange(s: f64) -> ([f64; 3], [f64; 3]) {
    (
        [0.5 * s * (s - 1.0), 1.0 - s * s, 0.5 * s * (s + 1.0)],
        [s - 0.5, -2.0 * s, s + 0.5],
    )
}

/// Index 0, 1, 2 of a natural coordinate −1, 0, 1.
pub(crate) fn slot(c: f64) -> usize {
    (c + 1.0).round() as usize
}

/// Shape functions and their natural derivatives at (ξ, η).
pub fn shape9(xi: f64, eta: f64) -> ([f64; 9], [f64; 9], [f64; 9]) {
    let (lx, dx) = lagrange(xi);
    let (ly, dy) = lagrange(eta);
    let mut n = [0.0; 9];
    let mut dxi = [0.0; 9];
    let mut deta = [0.0; 9];
    for i in 0..9 {
        let (a, b) = (slot(NODE_XI[i]), slot(NODE_ETA[i]));
        n[i] = lx[a] * ly[b];
        dxi[i] = dx[a] * ly[b];
        deta[i] = lx[a] * dy[b];
    }
    (n, dxi, deta)
}

/// Cartesian derivatives at (ξ, η); `None` where det J ≤ 0 (a folded or degenerate map).
pub(crate) fn cartesian9(xy: &[[f64; 2]; 9], xi: f64, eta: f64) -> Option<Cartesian<9>> {
    let (n, dxi, deta) = shape9(xi, eta);
    to_cartesian(xy, n, &dxi, &deta)
}

/// Local frame and projected coordinates of a nine-node element.
#[derive(Debug, Clone, PartialEq)]
pub struct Shell9Geometry {
    /// Rows: local x, y, z (normal) in global coordinates.
    pub lam: Matrix3<f64>,
    /// Mean of the nine nodes, global, mm.
    pub centre: Vector3<f64>,
    /// Local (x, y) of the projected nodes, mm.
    pub xy: [[f64; 2]; 9],
    /// Signed distance of each node from the plane, mm.
    pub warp: [f64; 9],
    /// d_local = T d_global (frame + rigid arms), 54×54.
    pub t: DMatrix<f64>,
}

/// Why a nine-node element's geometry is refused.
#[derive(Debug, Clone, PartialEq)]
pub enum Shell9GeometryError {
    /// Node `node` (0–8, element order) lies `offset` mm off the element's plane; `limit` mm is
    /// allowed.
    NotFlat { node: usize, offset: f64, limit: f64 },
    /// Zero area, repeated nodes, or an order that folds the element (det J ≤ 0 somewhere).
    Degenerate,
}

impl std::fmt::Display for Shell9GeometryError {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self {
            Shell9GeometryError::NotFlat { node, offset, limit } => write!(
                f,
                "shell9 is a flat element: its node {node} (of 0–8) lies {offset:.4e} mm off the element's plane, more than {limit:.4e} mm ({MAX_WARP} × the longer diagonal); model curved surfaces with four-node shells"
            ),
            Shell9GeometryError::Degenerate => write!(
                f,
                "the nine nodes do not form a valid quadrilateral (zero area, repeated nodes, or an order that folds it: corners 0–3 around the element, then the midpoints of edges 0–1, 1–2, 2–3, 3–0, then the centre)"
            ),
        }
    }
}

/// Frame, projection and transformation of a nine-node element.
pub fn shell9_geometry(x: &[[f64; 3]; 9]) -> Result<Shell9Geometry, Shell9GeometryError> {
    let p: Vec<Vector3<f64>> = x.iter().map(|v| Vector3::from(*v)).collect();
    let centre = p.iter().sum::<Vector3<f64>>() / 9.0;
    let g1 = (p[1] + p[2] - p[0] - p[3]) * 0.5;
    let g2 = (p[2] + p[3] - p[0] - p[1]) * 0.5;
    let nrm = g1.cross(&g2);
    let nn = nrm.norm();
    if !(nn > 0.0 && nn.is_finite()) || g1.norm() <= 0.0 {
        return Err(Shell9GeometryError::Degenerate);
    }
    let ez = nrm / nn;
    let ex = (g1 - ez * g1.dot(&ez)).normalize();
    let ey = ez.cross(&ex);
    let lam = Matrix3::from_rows(&[ex.transpose(), ey.transpose(), ez.transpose()]);
    let diag = (p[2] - p[0]).norm().max((p[3] - p[1]).norm());
    let limit = MAX_WARP * diag;
    let mut xy = [[0.0; 2]; 9];
    let mut warp = [0.0; 9];
    let mut t = DMatrix::zeros(54, 54);
    let l6 = t6(&lam);
    for i in 0..9 {
        let d = lam * (p[i] - centre);
        xy[i] = [d.x, d.y];
        warp[i] = d.z;
        let arm = rigid_arm(&(-ez * d.z));
        t.view_mut((6 * i, 6 * i), (6, 6)).copy_from(&(l6 * arm));
    }
    // The plane through the centroid with the corners' normal: offsets are relative to it.
    let mean = warp.iter().sum::<f64>() / 9.0;
    if let Some((node, &offset)) = warp
        .iter()
        .enumerate()
        .max_by(|a, b| (a.1 - mean).abs().total_cmp(&(b.1 - mean).abs()))
    {
        if (offset - mean).abs() > limit || !offset.is_finite() {
            return Err(Shell9GeometryError::NotFlat {
                node,
                offset: (offset - mean).abs(),
                limit,
            });
        }
    }
    // det J > 0 at every integration and node point (a folded map fails somewhere among these).
    for &(xi, _) in &GAUSS3 {
        for &(eta, _) in &GAUSS3 {
            cartesian9(&xy, xi, eta).ok_or(Shell9GeometryError::Degenerate)?;
        }
    }
    for i in 0..9 {
        cartesian9(&xy, NODE_XI[i], NODE_ETA[i]).ok_or(Shell9GeometryError::Degenerate)?;
    }
    Ok(Shell9Geometry {
        lam,
        centre,
        xy,
        warp,
        t,
    })
}

/// Local DOF (of 54) of membrane DOF `k` (u v θz) of node `i`.
fn mem(i: usize, k: usize) -> usize {
    6 * i + [0, 1, 5][k]
}
/// Local DOF (of 54) of plate DOF `k` (w θx θy) of node `i`.
fn plate(i: usize, k: usize) -> usize {
    6 * i + [2, 3, 4][k]
}

/// Membrane strain rows (εxx, εyy, γxy) over (u v θz) × 9.
pub(crate) fn membrane_b(dx: &[f64; 9], dy: &[f64; 9]) -> SMatrix<f64, 3, 27> {
    let mut b = SMatrix::<f64, 3, 27>::zeros();
    for i in 0..9 {
        b[(0, 3 * i)] = dx[i];
        b[(1, 3 * i + 1)] = dy[i];
        b[(2, 3 * i)] = dy[i];
        b[(2, 3 * i + 1)] = dx[i];
    }
    b
}

/// Curvature rows (κxx, κyy, κxy) over (w θx θy) × 9.
pub(crate) fn curvature_b(dx: &[f64; 9], dy: &[f64; 9]) -> SMatrix<f64, 3, 27> {
    let mut b = SMatrix::<f64, 3, 27>::zeros();
    for i in 0..9 {
        b[(0, 3 * i + 2)] = dx[i];
        b[(1, 3 * i + 1)] = -dy[i];
        b[(2, 3 * i + 1)] = -dx[i];
        b[(2, 3 * i + 2)] = dy[i];
    }
    b
}

/// Covariant shear rows (γ_ξ, γ_η) at (ξ, η) over (w θx θy) × 9 (direct, untied).
fn covariant_shear(xy: &[[f64; 2]; 9], xi: f64, eta: f64) -> SMatrix<f64, 2, 27> {
    let (n, dxi, deta) = shape9(xi, eta);
    let j = jacobian(xy, &dxi, &deta);
    let mut b = SMatrix::<f64, 2, 27>::zeros();
    for i in 0..9 {
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

/// Linear interpolation through ±a and quadratic through −b, 0, b (MITC9 tying functions).
fn tie_weights(s_lin: f64, s_quad: f64) -> [[f64; 3]; 2] {
    let (a, b) = (G2, G3);
    let lin = [0.5 * (1.0 - s_lin / a), 0.5 * (1.0 + s_lin / a)];
    let quad = [
        s_quad * (s_quad - b) / (2.0 * b * b),
        1.0 - s_quad * s_quad / (b * b),
        s_quad * (s_quad + b) / (2.0 * b * b),
    ];
    let w = |l: f64| quad.map(|q| l * q);
    [w(lin[0]), w(lin[1])]
}

/// The twelve tying rows, computed once per element: `[ξ-rows, η-rows]`, each `[lin][quad]`.
pub(crate) struct Tying {
    xi: [[SMatrix<f64, 1, 27>; 3]; 2],
    eta: [[SMatrix<f64, 1, 27>; 3]; 2],
}

pub(crate) fn tying(xy: &[[f64; 2]; 9]) -> Tying {
    let (a, b) = (G2, G3);
    let lin = [-a, a];
    let quad = [-b, 0.0, b];
    let row = |p: f64, q: f64, r: usize| covariant_shear(xy, p, q).fixed_rows::<1>(r).into_owned();
    Tying {
        xi: lin.map(|l| quad.map(|q| row(l, q, 0))),
        eta: lin.map(|l| quad.map(|q| row(q, l, 1))),
    }
}

/// MITC9 shear rows (γxz, γyz) at (ξ, η).
pub(crate) fn mitc9_shear_b(tie: &Tying, xi: f64, eta: f64, ji: &Matrix2<f64>) -> SMatrix<f64, 2, 27> {
    let wx = tie_weights(xi, eta);
    let we = tie_weights(eta, xi);
    let mut cov = SMatrix::<f64, 2, 27>::zeros();
    for l in 0..2 {
        for q in 0..3 {
            for k in 0..27 {
                cov[(0, k)] += wx[l][q] * tie.xi[l][q][k];
                cov[(1, k)] += we[l][q] * tie.eta[l][q][k];
            }
        }
    }
    ji * cov
}

/// Local 54×54 stiffness on the projected nodes.
pub fn shell9_local_stiffness(xy: &[[f64; 2]; 9], t: f64, mat: &Material) -> Option<DMatrix<f64>> {
    let c = plane_stress(mat.e, mat.nu);
    let (cm, cb) = (c * t, c * (t * t * t / 12.0));
    let ds = KAPPA * mat.shear_modulus() * t;
    let tie = tying(xy);
    let mut km = SMatrix::<f64, 27, 27>::zeros();
    let mut kp = SMatrix::<f64, 27, 27>::zeros();
    for &(xi, wx) in &GAUSS3 {
        for &(eta, we) in &GAUSS3 {
            let (_, dx, dy, det, ji) = cartesian9(xy, xi, eta)?;
            let w = wx * we * det;
            let bm = membrane_b(&dx, &dy);
            km += bm.transpose() * cm * bm * w;
            let bb = curvature_b(&dx, &dy);
            let bs = mitc9_shear_b(&tie, xi, eta, &ji);
            kp += (bb.transpose() * cb * bb + bs.transpose() * bs * ds) * w;
        }
    }
    km += drilling9(xy, t, mat)?;
    let mut k = DMatrix::zeros(54, 54);
    for a in 0..27 {
        for b in 0..27 {
            k[(mem(a / 3, a % 3), mem(b / 3, b % 3))] += km[(a, b)];
            k[(plate(a / 3, a % 3), plate(b / 3, b % 3))] += kp[(a, b)];
        }
    }
    Some((&k + k.transpose()) * 0.5)
}

/// Drilling penalty over (u v θz) × 9: γ = G at the 2×2 points, 10⁻³·G at the 3×3 points.
fn drilling9(xy: &[[f64; 2]; 9], t: f64, mat: &Material) -> Option<SMatrix<f64, 27, 27>> {
    let g = mat.shear_modulus();
    let row = |xi: f64, eta: f64| {
        let (n, dx, dy, det, _) = cartesian9(xy, xi, eta)?;
        let mut r = SMatrix::<f64, 27, 1>::zeros();
        for i in 0..9 {
            r[3 * i] = 0.5 * dy[i];
            r[3 * i + 1] = -0.5 * dx[i];
            r[3 * i + 2] = n[i];
        }
        Some((r, det))
    };
    let mut k = SMatrix::<f64, 27, 27>::zeros();
    for &xi in &[-G2, G2] {
        for &eta in &[-G2, G2] {
            let (r, det) = row(xi, eta)?;
            k += r * r.transpose() * (g * t * det);
        }
    }
    for &(xi, wx) in &GAUSS3 {
        for &(eta, we) in &GAUSS3 {
            let (r, det) = row(xi, eta)?;
            k += r * r.transpose() * (DRILL_STAB * g * t * det * wx * we);
        }
    }
    Some(k)
}

/// Global drilling-penalty stiffness Tᵀ k_d T (54×54): the part of the stiffness that rests on
/// the artificial drilling rotation (as [`super::shell::shell_drilling_stiffness`]); `None` for a
/// refused geometry.
pub fn shell9_drilling_stiffness(x: &[[f64; 3]; 9], t: f64, mat: &Material) -> Option<DMatrix<f64>> {
    let g = shell9_geometry(x).ok()?;
    let kd = drilling9(&g.xy, t, mat)?;
    let mut k = DMatrix::zeros(54, 54);
    for a in 0..27 {
        for b in 0..27 {
            k[(mem(a / 3, a % 3), mem(b / 3, b % 3))] = kd[(a, b)];
        }
    }
    Some(g.t.transpose() * k * &g.t)
}

/// Consistent local mass (54×54), tonne, tonne·mm².
pub fn shell9_local_mass(xy: &[[f64; 2]; 9], t: f64, rho: f64) -> Option<DMatrix<f64>> {
    let mut nn = SMatrix::<f64, 9, 9>::zeros();
    for &(xi, wx) in &GAUSS3 {
        for &(eta, we) in &GAUSS3 {
            let (n, _, _, det, _) = cartesian9(xy, xi, eta)?;
            for i in 0..9 {
                for j in 0..9 {
                    nn[(i, j)] += n[i] * n[j] * det * wx * we;
                }
            }
        }
    }
    let (mt, mr) = (rho * t, rho * t * t * t / 12.0);
    let mut m = DMatrix::zeros(54, 54);
    for i in 0..9 {
        for j in 0..9 {
            for d in 0..5 {
                m[(6 * i + d, 6 * j + d)] = nn[(i, j)] * if d < 3 { mt } else { mr };
            }
        }
    }
    Some(m)
}

/// Nodal loads [Fx, Fy, Fz (N), Mx, My, Mz (N·mm)] (global axes) of a uniform pressure `p`
/// (MPa) along the element normal (local z, +z for corners listed counter-clockwise seen from
/// +z): fᵢ = p·n∫Nᵢ dA (3×3 Gauss; on a rectangle the corners take A/36, the edge midpoints
/// 4A/36, the centre 16A/36), carried to the nodes through the element's transformation.
pub fn shell9_pressure_loads(x: &[[f64; 3]; 9], p: f64) -> Result<[[f64; 6]; 9], Shell9GeometryError> {
    let g = shell9_geometry(x)?;
    let mut f = DVector::zeros(54);
    for &(xi, wx) in &GAUSS3 {
        for &(eta, we) in &GAUSS3 {
            let (n, _, _, det, _) = cartesian9(&g.xy, xi, eta).ok_or(Shell9GeometryError::Degenerate)?;
            for i in 0..9 {
                f[6 * i + 2] += p * n[i] * det * wx * we;
            }
        }
    }
    let fg = g.t.transpose() * f;
    Ok(std::array::from_fn(|i| std::array::from_fn(|d| fg[6 * i + d])))
}

/// Global stiffness Tᵀ k T (54×54).
pub fn shell9_stiffness(x: &[[f64; 3]; 9], t: f64, mat: &Material) -> Result<DMatrix<f64>, Shell9GeometryError> {
    let g = shell9_geometry(x)?;
    let k = shell9_local_stiffness(&g.xy, t, mat).ok_or(Shell9GeometryError::Degenerate)?;
    let kg = g.t.transpose() * k * &g.t;
    Ok((&kg + kg.transpose()) * 0.5)
}

/// Global consistent mass Tᵀ m T (54×54).
pub fn shell9_mass(x: &[[f64; 3]; 9], t: f64, rho: f64) -> Result<DMatrix<f64>, Shell9GeometryError> {
    let g = shell9_geometry(x)?;
    let m = shell9_local_mass(&g.xy, t, rho).ok_or(Shell9GeometryError::Degenerate)?;
    let mg = g.t.transpose() * m * &g.t;
    Ok((&mg + mg.transpose()) * 0.5)
}

/// The element's stresses (local axes: von Mises at the top, middle and bottom surfaces,
/// membrane forces and moments) from its global displacements (54) at the point of its 3×3
/// Gauss points (the centre among them) with the largest von Mises; the centre on a tie.
/// Geometry and local displacements are computed once for the nine points.
pub fn shell9_largest_stress(
    x: &[[f64; 3]; 9],
    t: f64,
    mat: &Material,
    d_global: &DVector<f64>,
) -> Result<ShellStress, Shell9GeometryError> {
    let g = shell9_geometry(x)?;
    let d = &g.t * d_global;
    let c = plane_stress(mat.e, mat.nu);
    let at = |xi: f64, eta: f64| {
        let (_, dx, dy, _, _) = cartesian9(&g.xy, xi, eta).ok_or(Shell9GeometryError::Degenerate)?;
        let mut eps = Vector3::zeros();
        let mut kap = Vector3::zeros();
        for i in 0..9 {
            let (u, v) = (d[6 * i], d[6 * i + 1]);
            let (tx, ty) = (d[6 * i + 3], d[6 * i + 4]);
            eps += Vector3::new(dx[i] * u, dy[i] * v, dy[i] * u + dx[i] * v);
            kap += Vector3::new(dx[i] * ty, -dy[i] * tx, dy[i] * ty - dx[i] * tx);
        }
        Ok(stress_from_strains(&c, &eps, &kap, t))
    };
    let largest = |s: &ShellStress| s.von_mises.iter().copied().fold(0.0, f64::max);
    let mut best = at(0.0, 0.0)?;
    for &(xi, _) in &GAUSS3 {
        for &(eta, _) in &GAUSS3 {
            if (xi, eta) == (0.0, 0.0) {
                continue;
            }
            let s = at(xi, eta)?;
            if largest(&s) > largest(&best) {
                best = s;
            }
        }
    }
    Ok(best)
}

/// The qh below which [`Shell9Bloch::ratio`] scales its error from this qh by (qh)⁴ instead of
/// solving (see there).
pub const BLOCH_QUARTIC_BELOW: f64 = 1.0;

/// ω_h/ω of a thin-plate bending wave w = W·exp(i(ax + by)/h) with phase steps (a, b) per
/// element on a mesh of squares of side h of nine-node shells ([`Shell9Bloch::ratio`]).
pub fn square_mesh_frequency_ratio9(a: f64, b: f64, nu: f64) -> Option<f64> {
    Shell9Bloch::new(nu)?.ratio(a, b)
}

/// Bloch analysis of the nine-node shell's plate part on a mesh of unit squares: the periodic
/// element's corner, the two kinds of edge midpoint and its centre carry one (w, θx, θy) each;
/// t/h = 10⁻², where the Reissner–Mindlin shift of the wave is below 10⁻⁴; consistent mass.
/// The element matrices are built once, for one ν.
#[derive(Debug, Clone)]
pub struct Shell9Bloch {
    /// Plate stiffness and mass over (w θx θy) × 9 of the unit square.
    k: DMatrix<f64>,
    m: DMatrix<f64>,
    /// Class of each node (0 corner, 1 midpoint of a horizontal edge, 2 of a vertical edge,
    /// 3 the centre) and its offset in elements from the class's representative.
    class: [(usize, f64, f64); 9],
    /// Bending stiffness D of the unit-modulus plate, N·mm.
    d: f64,
    t: f64,
}

impl Shell9Bloch {
    /// The element of Poisson's ratio `nu`; `None` if its matrices cannot be built.
    pub fn new(nu: f64) -> Option<Shell9Bloch> {
        let mat = Material {
            e: 1.0,
            nu,
            density: 1.0,
            ..Material::AL7075
        };
        let t = 1e-2;
        let xy: [[f64; 2]; 9] = std::array::from_fn(|k| [0.5 * (NODE_XI[k] + 1.0), 0.5 * (NODE_ETA[k] + 1.0)]);
        let k54 = shell9_local_stiffness(&xy, t, &mat)?;
        let m54 = shell9_local_mass(&xy, t, 1.0)?;
        let plate_part =
            |a: &DMatrix<f64>| DMatrix::from_fn(27, 27, |r, c| a[(plate(r / 3, r % 3), plate(c / 3, c % 3))]);
        let class = std::array::from_fn(|node| {
            let (x, y) = (xy[node][0], xy[node][1]);
            let c = match (x == 0.5, y == 0.5) {
                (false, false) => 0,
                (true, false) => 1,
                (false, true) => 2,
                (true, true) => 3,
            };
            (c, f64::from(u8::from(x == 1.0)), f64::from(u8::from(y == 1.0)))
        });
        Some(Shell9Bloch {
            k: plate_part(&k54),
            m: plate_part(&m54),
            class,
            d: t * t * t / (12.0 * (1.0 - nu * nu)),
            t,
        })
    }

    /// ω_h/ω for the phase steps (a, b) per element; `None` if the reduced mass is not positive
    /// definite. Below qh = √(a² + b²) = [`BLOCH_QUARTIC_BELOW`] the wave's eigenvalue is too
    /// small beside the shear modes' for double precision (10⁻¹⁵ of them at qh = 0.05: the
    /// computed error there is −3 %), so ω_h/ω − 1 is taken at that qh in the same direction and
    /// scaled by (qh/[`BLOCH_QUARTIC_BELOW`])⁴, the element's leading order. The coefficient
    /// (ω_h/ω − 1)/(qh)⁴ as solved: along a mesh line 1.99, 1.97, 1.88 · 10⁻³ at qh = 0.75, 1,
    /// 1.5; along a diagonal 4.22, 4.33, 4.32 · 10⁻⁴ (`tests/shell9.rs`).
    pub fn ratio(&self, a: f64, b: f64) -> Option<f64> {
        let q = (a * a + b * b).sqrt();
        if q < BLOCH_QUARTIC_BELOW {
            let s = BLOCH_QUARTIC_BELOW / q.max(f64::MIN_POSITIVE);
            let (a0, b0) = if q > 0.0 {
                (a * s, b * s)
            } else {
                (BLOCH_QUARTIC_BELOW, 0.0)
            };
            let r0 = self.ratio_computed(a0, b0)?;
            return Some(1.0 + (r0 - 1.0) * (q / BLOCH_QUARTIC_BELOW).powi(4));
        }
        self.ratio_computed(a, b)
    }

    /// [`Shell9Bloch::ratio`] as the eigenvalue problem gives it, at any qh.
    fn ratio_computed(&self, a: f64, b: f64) -> Option<f64> {
        use nalgebra::Complex;
        let mut p = DMatrix::<Complex<f64>>::zeros(27, 12);
        for (node, &(c, i, j)) in self.class.iter().enumerate() {
            let phase = Complex::new(0.0, a * i + b * j).exp();
            for d in 0..3 {
                p[(3 * node + d, 3 * c + d)] = phase;
            }
        }
        let reduce = |h: &DMatrix<f64>| {
            let hc = h.map(|v| Complex::new(v, 0.0));
            let r = p.adjoint() * hc * &p;
            // The Hermitian matrix as a real symmetric one of twice the size: [[Re, −Im], [Im, Re]].
            DMatrix::<f64>::from_fn(24, 24, |i, j| {
                let v = r[(i % 12, j % 12)];
                match (i < 12, j < 12) {
                    (true, true) | (false, false) => v.re,
                    (true, false) => -v.im,
                    (false, true) => v.im,
                }
            })
        };
        let l = reduce(&self.m).cholesky()?.l();
        let li = l.try_inverse()?;
        let a_sym = &li * reduce(&self.k) * li.transpose();
        let a_sym = (&a_sym + a_sym.transpose()) * 0.5;
        let lowest = a_sym
            .symmetric_eigenvalues()
            .iter()
            .copied()
            .fold(f64::INFINITY, f64::min);
        let q2 = a * a + b * b;
        Some((lowest.max(0.0) / (self.d * q2 * q2 / self.t)).sqrt())
    }
}
