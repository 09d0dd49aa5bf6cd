//! Co-rotational kinematics of the two-node 3D beam and flexibility element (large rotations,
//! small strains), after J.-M. Battini & C. Pacoste, "Co-rotational beam elements with warping
//! effects in instability problems", CMAME 191 (2002) 1755–1789, §3, and M. A. Crisfield,
//! "A consistent co-rotational formulation for non-linear, three-dimensional, beam-elements",
//! CMAME 81 (1990) 131–150.
//!
//! The element's rigid motion is split off by the co-rotated frame Rr = [r₁ r₂ r₃]:
//!
//! ```text
//! r₁ = (x₂ − x₁)/lₙ,   q = ½(R₁R₀e₂ + R₂R₀e₂),   r₃ = r₁ × q/|r₁ × q|,   r₂ = r₃ × r₁
//! ū = lₙ − l₀,         θ̄ᵢ = log(Rrᵀ Rᵢ R₀)       (i = 1, 2)
//! ```
//! (R₀: columns are the initial local axes; Rᵢ: nodal rotations, updated multiplicatively
//! Rᵢ ← exp(δwᵢ)Rᵢ with the spatial spin δwᵢ as rotational increment). The seven local
//! deformations p = [ū, θ̄₁, θ̄₂] feed the element's *linear* local stiffness k (Timoshenko
//! beam [`super::element::beam_local_stiffness`] or flexibility element
//! [`super::element::flex_local_stiffness`]) on the DOFs (u₂; θx₁ θy₁ θz₁; θx₂ θy₂ θz₂), the
//! other five local DOFs being zero in the co-rotated frame (node 1 at the origin, node 2 on r₁).
//!
//! First variation δp = B δd (δd = [δu₁ δw₁ δu₂ δw₂], global):
//!
//! ```text
//! δū  = r·δd,  r = [−r₁ᵀ 0 r₁ᵀ 0]
//! δθ̄ᵢ = Ts⁻¹(θ̄ᵢ) Pᵢ Eᵀ δd,   P = [[0 I 0 0]; [0 0 0 I]] − [Gᵀ; Gᵀ],   E = diag(Rr, Rr, Rr, Rr)
//! Gᵀ = [[0 0 η/lₙ  η₁₂/2 −η₁₁/2 0  0 0 −η/lₙ  η₂₂/2 −η₂₁/2 0]
//!       [0 0 1/lₙ  0 0 0           0 0 −1/lₙ  0 0 0]
//!       [0 −1/lₙ 0 0 0 0           0 1/lₙ 0   0 0 0]]
//! Ts⁻¹(θ) = a I + (1 − a) e eᵀ − ½[θ×],  a = (θ/2)/tan(θ/2),  e = θ/|θ|
//! ```
//! with η = q₁/q₂, ηᵢⱼ = qᵢⱼ/q₂ (components of q and qᵢ = RᵢR₀e₂ in the co-rotated frame).
//! Internal force f = Bᵀ k₇ p (exact first variation of the strain energy ½ pᵀk₇p); tangent
//! K = Bᵀ k₇ B + ∂(Bᵀ f₇)/∂d|_{f₇ fixed}, both parts in closed form ([`tangent`]: the terms
//! D, Q, K_h of Battini–Pacoste eqs. (40)–(48), with the variation of G derived in full, η and
//! ηᵢⱼ included), so K is the exact consistent tangent. [`geometric_tangent_fd`] keeps the
//! former evaluation of the geometric part by central differences of B as a check.

use super::transform::{skew, Mat12};

mod tangent;
use nalgebra::{Matrix3, Rotation3, SMatrix, SVector, Vector3};
pub use tangent::{geometric_tangent, geometric_tangent_fd, perturbed};

/// 7×12 matrix.
pub type Mat7x12 = SMatrix<f64, 7, 12>;
/// 7×7 matrix.
pub type Mat7 = SMatrix<f64, 7, 7>;
/// 7-vector.
pub type Vec7 = SVector<f64, 7>;
/// 12-vector.
pub type Vec12 = SVector<f64, 12>;

/// Local DOFs (of the 12) that carry the co-rotational deformations [ū, θ̄₁, θ̄₂].
pub const LOCAL_IDX: [usize; 7] = [6, 3, 4, 5, 9, 10, 11];

/// Rotation matrix exp([θ×]) (Rodrigues).
pub fn rot_exp(theta: &Vector3<f64>) -> Matrix3<f64> {
    Rotation3::new(*theta).into_inner()
}

/// Rotation vector θ with exp([θ×]) = R (|θ| ≤ π). Accurate for small angles (from the skew
/// part, no arccos); near π the axis comes from the symmetric part.
pub fn rot_log(r: &Matrix3<f64>) -> Vector3<f64> {
    let ax = 0.5 * Vector3::new(r[(2, 1)] - r[(1, 2)], r[(0, 2)] - r[(2, 0)], r[(1, 0)] - r[(0, 1)]);
    let s = ax.norm();
    let c = 0.5 * (r.trace() - 1.0);
    let theta = s.atan2(c);
    let v = if c > -0.9 {
        // θ/sin θ → 1 as θ → 0.
        if s < 1e-300 {
            Vector3::zeros()
        } else {
            ax * (theta / s)
        }
    } else {
        // (R + Rᵀ)/2 = cos θ I + (1 − cos θ) n nᵀ.
        let b = (0.5 * (r + r.transpose()) - Matrix3::identity() * c) / (1.0 - c);
        let mut k = 0;
        for i in 1..3 {
            if b[(i, i)] > b[(k, k)] {
                k = i;
            }
        }
        let mut n = b.column(k).into_owned();
        let nn = n.norm();
        if nn > 0.0 {
            n /= nn;
        }
        if n.dot(&ax) < 0.0 {
            n = -n;
        }
        n * theta
    };
    if v.iter().all(|x| x.is_finite()) {
        v
    } else {
        Vector3::zeros()
    }
}

/// Ts⁻¹(θ): maps a spatial spin δw of R = exp(θ) to the additive variation δθ
/// (Battini–Pacoste 2002 eq. (14)).
pub fn ts_inv(theta: &Vector3<f64>) -> Matrix3<f64> {
    let t = theta.norm();
    if t < 1e-8 {
        return Matrix3::identity() - 0.5 * skew(theta);
    }
    let h = 0.5 * t;
    let a = h / h.tan();
    let e = theta / t;
    Matrix3::identity() * a + (1.0 - a) * e * e.transpose() - 0.5 * skew(theta)
}

/// Reference geometry of a co-rotational element.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct CorotGeometry {
    /// Initial node coordinates, mm.
    pub x1: Vector3<f64>,
    pub x2: Vector3<f64>,
    /// Initial local axes as columns (R₀ = Λᵀ).
    pub r0: Matrix3<f64>,
    /// Initial length, mm.
    pub l0: f64,
}

/// Current nodal state of an element: translations (mm) and rotation matrices.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct NodeState {
    pub u: Vector3<f64>,
    pub r: Matrix3<f64>,
}

impl Default for NodeState {
    fn default() -> Self {
        NodeState {
            u: Vector3::zeros(),
            r: Matrix3::identity(),
        }
    }
}

/// Kinematics of one element at one configuration.
#[derive(Debug, Clone, PartialEq)]
pub struct Kinematics {
    /// Co-rotated frame Rr (columns r₁ r₂ r₃).
    pub rr: Matrix3<f64>,
    /// Local deformations p = [ū, θ̄₁, θ̄₂].
    pub p: Vec7,
    /// δp = B δd.
    pub b: Mat7x12,
    /// Current length, mm.
    pub ln: f64,
}

/// Kinematics of the element (see the module docs). `None` for a degenerate configuration
/// (zero length, r₁ parallel to q, non-finite input).
pub fn kinematics(g: &CorotGeometry, n1: &NodeState, n2: &NodeState) -> Option<Kinematics> {
    kinematics_aux(g, n1, n2).map(|(k, _)| k)
}

/// What the closed-form tangent needs besides [`Kinematics`] (local components, co-rotated
/// frame): −Gᵀ, the nodal Ts⁻¹(θ̄ᵢ), and q, qᵢ (see the module docs).
#[derive(Debug, Clone)]
struct Aux {
    mgt: SMatrix<f64, 3, 12>,
    th: [Vector3<f64>; 2],
    ts: [Matrix3<f64>; 2],
    /// qᵢ in the co-rotated frame.
    qil: [Vector3<f64>; 2],
    /// Second local component of q (its third is zero).
    q_y: f64,
    eta: f64,
    /// ηᵢⱼ = (qᵢ)ⱼ/q₂ (j = first, second local component).
    eij: [[f64; 2]; 2],
}

fn kinematics_aux(g: &CorotGeometry, n1: &NodeState, n2: &NodeState) -> Option<(Kinematics, Aux)> {
    // (X₂ − X₁) + (u₂ − u₁): round-off relative to the element length, not to the coordinates.
    let x21 = (g.x2 - g.x1) + (n2.u - n1.u);
    let ln = x21.norm();
    if !(ln > 0.0 && ln.is_finite()) {
        return None;
    }
    let r1 = x21 / ln;
    let e2 = g.r0.column(1).into_owned();
    let q1 = n1.r * e2;
    let q2 = n2.r * e2;
    let q = 0.5 * (q1 + q2);
    let r3 = r1.cross(&q);
    let n3 = r3.norm();
    if !(n3 > 1e-12 && n3.is_finite()) {
        return None;
    }
    let r3 = r3 / n3;
    let r2 = r3.cross(&r1);
    let rr = Matrix3::from_columns(&[r1, r2, r3]);
    let rrt = rr.transpose();
    let th1 = rot_log(&(rrt * n1.r * g.r0));
    let th2 = rot_log(&(rrt * n2.r * g.r0));
    let ql = rrt * q;
    let q1l = rrt * q1;
    let q2l = rrt * q2;
    let eta = ql[0] / ql[1];
    let (e11, e12) = (q1l[0] / ql[1], q1l[1] / ql[1]);
    let (e21, e22) = (q2l[0] / ql[1], q2l[1] / ql[1]);
    // −Gᵀ (3×12, local components), built negated: every entry, zeros as −0, is exactly the
    // negation of Gᵀ (rounding is symmetric in sign); negating the matrix in the loop below
    // cost a third of this function.
    let mut mgt = SMatrix::<f64, 3, 12>::from_element(-0.0);
    mgt[(0, 2)] = -eta / ln;
    mgt[(0, 3)] = -0.5 * e12;
    mgt[(0, 4)] = 0.5 * e11;
    mgt[(0, 8)] = eta / ln;
    mgt[(0, 9)] = -0.5 * e22;
    mgt[(0, 10)] = 0.5 * e21;
    mgt[(1, 2)] = -1.0 / ln;
    mgt[(1, 8)] = 1.0 / ln;
    mgt[(2, 1)] = 1.0 / ln;
    mgt[(2, 7)] = -1.0 / ln;
    // P Eᵀ: Pᵢ = [spin of node i, local] − Gᵀ; Eᵀ rotates every 3-block to local.
    let mut b = Mat7x12::zeros();
    for j in 0..3 {
        b[(0, j)] = -r1[j];
        b[(0, 6 + j)] = r1[j];
    }
    let ts = [ts_inv(&th1), ts_inv(&th2)];
    for (i, tsi) in ts.iter().enumerate() {
        let mut pi = mgt;
        for k in 0..3 {
            pi[(k, 3 + 6 * i + k)] += 1.0;
        }
        // Pᵢ Eᵀ: column block c of Pᵢ times Rrᵀ.
        let mut pe = SMatrix::<f64, 3, 12>::zeros();
        for c in 0..4 {
            let blk = pi.fixed_view::<3, 3>(0, 3 * c) * rrt;
            pe.fixed_view_mut::<3, 3>(0, 3 * c).copy_from(&blk);
        }
        let rows = tsi * pe;
        b.fixed_view_mut::<3, 12>(1 + 3 * i, 0).copy_from(&rows);
    }
    let mut p = Vec7::zeros();
    // ū = (lₙ² − l₀²)/(lₙ + l₀) with lₙ² − l₀² = (2 X₂₁ + Δ)·Δ: no cancellation for small Δ.
    let dx = n2.u - n1.u;
    let x0 = g.x2 - g.x1;
    p[0] = (2.0 * x0 + dx).dot(&dx) / (ln + g.l0);
    p.fixed_rows_mut::<3>(1).copy_from(&th1);
    p.fixed_rows_mut::<3>(4).copy_from(&th2);
    let aux = Aux {
        mgt,
        th: [th1, th2],
        ts,
        qil: [q1l, q2l],
        q_y: ql[1],
        eta,
        eij: [[e11, e12], [e21, e22]],
    };
    Some((Kinematics { rr, p, b, ln }, aux))
}

/// The 7×7 block of a 12×12 local stiffness on [`LOCAL_IDX`].
pub fn k7_of(k: &Mat12) -> Mat7 {
    Mat7::from_fn(|i, j| k[(LOCAL_IDX[i], LOCAL_IDX[j])])
}

/// Local 12-vector d = [0 0 0 θ̄₁ ū 0 0 θ̄₂] of the deformations p.
pub fn local_d(p: &Vec7) -> Vec12 {
    let mut d = Vec12::zeros();
    for (i, &l) in LOCAL_IDX.iter().enumerate() {
        d[l] = p[i];
    }
    d
}

/// Internal force, tangent and local results of one element.
#[derive(Debug, Clone, PartialEq)]
pub struct CorotResponse {
    /// Global internal force on [node 1, node 2] (N, N·mm).
    pub f: Vec12,
    /// Consistent tangent (not symmetrised), global.
    pub k: Mat12,
    /// Local end forces f = k d of the linear local element in the co-rotated frame.
    pub f_local: Vec12,
    /// Local deformations.
    pub d_local: Vec12,
    /// Co-rotated frame.
    pub rr: Matrix3<f64>,
}

/// Internal force of a co-rotational element at one configuration, with what its tangent
/// needs: a Newton iteration forms the residual from [`Linearisation::force`] and the tangent
/// only when it goes on, without evaluating the kinematics twice.
#[derive(Debug, Clone)]
pub struct Linearisation {
    kin: Kinematics,
    aux: Aux,
    k7: Mat7,
    f7: Vec7,
    f: Vec12,
}

impl Linearisation {
    /// Global internal force on [node 1, node 2] (N, N·mm).
    pub fn force(&self) -> &Vec12 {
        &self.f
    }

    /// Local deformations p = [ū, θ̄₁, θ̄₂].
    pub fn deformations(&self) -> &Vec7 {
        &self.kin.p
    }

    /// Consistent tangent Bᵀ k₇ B + K_σ (not symmetrised), global; `None` when not finite.
    pub fn tangent(&self) -> Option<Mat12> {
        let kin = &self.kin;
        let ks = tangent::geometric_local(&self.aux, kin, &self.f7);
        let k = kin.b.tr_mul(&(self.k7 * kin.b)) + tangent::to_global(&ks, &kin.rr);
        k.iter().all(|v| v.is_finite()).then_some(k)
    }
}

/// The internal force (and, on demand, the tangent) of a co-rotational element with linear
/// local stiffness `k_local` (12×12, local axes of the initial frame). `None` for a degenerate
/// configuration or a non-finite force.
pub fn linearise(g: &CorotGeometry, k_local: &Mat12, n1: &NodeState, n2: &NodeState) -> Option<Linearisation> {
    let (kin, aux) = kinematics_aux(g, n1, n2)?;
    let k7 = k7_of(k_local);
    let f7 = k7 * kin.p;
    let f = kin.b.transpose() * f7;
    if f.iter().any(|v| !v.is_finite()) {
        return None;
    }
    Some(Linearisation { kin, aux, k7, f7, f })
}

/// Internal force and consistent tangent of a co-rotational element with linear local
/// stiffness `k_local` (12×12, local axes of the initial frame). `with_tangent = false`
/// skips the tangent (zero matrix). `None` for a degenerate configuration.
pub fn response(
    g: &CorotGeometry,
    k_local: &Mat12,
    n1: &NodeState,
    n2: &NodeState,
    with_tangent: bool,
) -> Option<CorotResponse> {
    let lin = linearise(g, k_local, n1, n2)?;
    let k = if with_tangent { lin.tangent()? } else { Mat12::zeros() };
    let d_local = local_d(&lin.kin.p);
    Some(CorotResponse {
        f: lin.f,
        k,
        f_local: k_local * d_local,
        d_local,
        rr: lin.kin.rr,
    })
}

#[cfg(test)]
mod tests;
