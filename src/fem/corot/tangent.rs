//! Closed-form geometric part of the co-rotational tangent, K_σ = ∂(Bᵀ f₇)/∂d at fixed local
//! forces f₇ = [N, m̄₁, m̄₂], after J.-M. Battini & C. Pacoste, "Co-rotational beam elements
//! with warping effects in instability problems", CMAME 191 (2002) 1755–1789, eqs. (40)–(48)
//! (and M. A. Crisfield, CMAME 81 (1990) 131–150), in the notation of the parent module.
//!
//! With mᵢ = Ts⁻ᵀ(θ̄ᵢ) m̄ᵢ (the moments conjugate to the local spins) the force is
//! f = rᵀN + E Σᵢ Pᵢᵀ mᵢ, and its variation at fixed f₇ has four parts, all assembled in the
//! co-rotated frame (K_σ = E k_σ Eᵀ, d_l = Eᵀ d):
//!
//! ```text
//! δr N          → N D,         D = (1/lₙ)[[A 0 −A 0]; 0; [−A 0 A 0]; 0],  A = diag(0, 1, 1)
//! δE n          → −Q Gᵀ,       n = Σ Pᵢᵀ mᵢ,  Q = [[n₁×]; [n₂×]; [n₃×]; [n₄×]] (3-blocks of n)
//! −δG (m₁+m₂)   → the variation of G through lₙ (δlₙ = [−e₁ 0 e₁ 0]·d_l) and through
//!                 η, ηᵢⱼ:  δqᵢ = −[qᵢ×] Pᵢ d_l (local components), δq = ½(δq₁ + δq₂),
//!                 δη = (δq_x − η δq_y)/q_y,  δηᵢⱼ = (δ(qᵢ)ⱼ − ηᵢⱼ δq_y)/q_y
//! δmᵢ           → Pᵢᵀ K_hᵢ Pᵢ,   K_hᵢ = H(θ̄ᵢ, m̄ᵢ) Ts⁻¹(θ̄ᵢ),  H = ∂(Ts⁻ᵀ(θ) v)/∂θ
//! ```
//!
//! Battini & Pacoste's term E G a r keeps only the variation of G through lₙ; here the
//! variations of η and ηᵢⱼ are kept as well, so the tangent is the exact derivative of the
//! internal force (checked against central differences in `tests/corot_tangent.rs`).
//! With Ts⁻ᵀ(θ) v = a v + b θ(θᵀv) + ½ θ×v, a = (t/2)cot(t/2), b = (1 − a)/t², t = |θ|:
//!
//! ```text
//! H = (a'/t) v θᵀ + (b'/t)(θᵀv) θ θᵀ + b((θᵀv) I + θ vᵀ) − ½[v×]
//! ```

use super::{kinematics, kinematics_aux, rot_exp, Aux, CorotGeometry, Kinematics, NodeState, Vec12, Vec7};
use crate::fem::transform::{skew, Mat12};
use nalgebra::{Matrix3, SMatrix, Vector3};

type Mat3x12 = SMatrix<f64, 3, 12>;
type Row12 = SMatrix<f64, 1, 12>;

/// Geometric part ∂(Bᵀ f₇)/∂d of the tangent at fixed local forces `f7` = [N, M₁, M₂] in
/// closed form (see the module docs), global, not symmetrised. `None` for a degenerate
/// configuration.
pub fn geometric_tangent(g: &CorotGeometry, n1: &NodeState, n2: &NodeState, f7: &Vec7) -> Option<Mat12> {
    let (kin, aux) = kinematics_aux(g, n1, n2)?;
    let k = to_global(&geometric_local(&aux, &kin, f7), &kin.rr);
    k.iter().all(|v| v.is_finite()).then_some(k)
}

/// E k Eᵀ: every 3×3 block rotated from the co-rotated frame `rr` to global axes.
pub(super) fn to_global(kl: &Mat12, rr: &Matrix3<f64>) -> Mat12 {
    let rrt = rr.transpose();
    let mut k = Mat12::zeros();
    for i in 0..4 {
        for j in 0..4 {
            let blk = rr * kl.fixed_view::<3, 3>(3 * i, 3 * j) * rrt;
            k.fixed_view_mut::<3, 3>(3 * i, 3 * j).copy_from(&blk);
        }
    }
    k
}

/// a'/t, b and b'/t of Ts⁻ᵀ (module docs) at t² = |θ|²: Taylor series below t = 0.05,
/// closed form above.
fn ts_coefficients(t2: f64) -> (f64, f64, f64) {
    if t2 < 0.0025 {
        ts_series(t2)
    } else {
        ts_closed(t2)
    }
}

/// From x cot x = 1 − x²/3 − x⁴/45 − 2x⁶/945 − x⁸/4725 − 2x¹⁰/93555 − … (x = t/2); the
/// first omitted terms are below 1e-14 relative for t ≤ 0.05.
fn ts_series(t2: f64) -> (f64, f64, f64) {
    let ap = -1.0 / 6.0 - t2 / 180.0 - t2 * t2 / 5040.0 - t2 * t2 * t2 / 151_200.0;
    let b = 1.0 / 12.0 + t2 / 720.0 + t2 * t2 / 30_240.0 + t2 * t2 * t2 / 1_209_600.0;
    let bp = 1.0 / 360.0 + t2 / 7560.0 + t2 * t2 / 201_600.0;
    (ap, b, bp)
}

/// Closed form. At t = 0.05 cancellation costs a'/t and b ~1e-12 relative and b'/t ~1e-8;
/// b'/t multiplies (θᵀv)θθᵀ = O(t³|v|), so H stays within ~1e-14 |v| (the unit test).
fn ts_closed(t2: f64) -> (f64, f64, f64) {
    let t = t2.sqrt();
    let h = 0.5 * t;
    let a = h / h.tan();
    let s = h.sin();
    let ap = (a / t - 0.25 * t / (s * s)) / t;
    let b = (1.0 - a) / t2;
    let bp = -(ap + 2.0 * b) / t2;
    (ap, b, bp)
}

/// H = ∂(Ts⁻ᵀ(θ) v)/∂θ (module docs).
fn h_matrix(theta: &Vector3<f64>, v: &Vector3<f64>) -> Matrix3<f64> {
    h_with(ts_coefficients(theta.norm_squared()), theta, v)
}

fn h_with((ap, b, bp): (f64, f64, f64), theta: &Vector3<f64>, v: &Vector3<f64>) -> Matrix3<f64> {
    let tv = theta.dot(v);
    v * theta.transpose() * ap
        + theta * theta.transpose() * (bp * tv)
        + (Matrix3::identity() * tv + theta * v.transpose()) * b
        - skew(v) * 0.5
}

/// The geometric tangent in the co-rotated frame, k_σ (module docs).
pub(super) fn geometric_local(aux: &Aux, kin: &Kinematics, f7: &Vec7) -> Mat12 {
    let ln = kin.ln;
    let mbar = [f7.fixed_rows::<3>(1).into_owned(), f7.fixed_rows::<3>(4).into_owned()];
    let p: [Mat3x12; 2] = std::array::from_fn(|i| {
        let mut pi = aux.mgt;
        for k in 0..3 {
            pi[(k, 3 + 6 * i + k)] += 1.0;
        }
        pi
    });
    let m: [Vector3<f64>; 2] = std::array::from_fn(|i| aux.ts[i].tr_mul(&mbar[i]));
    let mut k = Mat12::zeros();
    // N D.
    let c = f7[0] / ln;
    for (a, b, s) in [(0, 0, c), (0, 6, -c), (6, 0, -c), (6, 6, c)] {
        k[(a + 1, b + 1)] += s;
        k[(a + 2, b + 2)] += s;
    }
    // The terms right-multiplied by −Gᵀ (= mgt) share one 12×3·3×12 product, x·mgt:
    // δE n = −Q Gᵀ d_l gives the 3-blocks [nⱼ×] of x, and Σ Pᵢᵀ K_hᵢ Pᵢ (Pᵢ = Iᵢ + mgt, Iᵢ the
    // spin block of node i) = (Σ Iᵢᵀ K_hᵢ + mgtᵀ Σ K_hᵢ)·mgt + Σ Pᵢᵀ K_hᵢ Iᵢ.
    let n = p[0].tr_mul(&m[0]) + p[1].tr_mul(&m[1]);
    let mut x = SMatrix::<f64, 12, 3>::zeros();
    for j in 0..4 {
        let nj = Vector3::new(n[3 * j], n[3 * j + 1], n[3 * j + 2]);
        x.fixed_view_mut::<3, 3>(3 * j, 0).copy_from(&skew(&nj));
    }
    let kh: [Matrix3<f64>; 2] = std::array::from_fn(|i| h_matrix(&aux.th[i], &mbar[i]) * aux.ts[i]);
    x += aux.mgt.tr_mul(&(kh[0] + kh[1]));
    for (i, khi) in kh.iter().enumerate() {
        let mut blk = x.fixed_view_mut::<3, 3>(3 + 6 * i, 0);
        blk += khi;
        let mut cols = k.fixed_view_mut::<12, 3>(0, 3 + 6 * i);
        cols += p[i].tr_mul(khi);
    }
    k += x * aux.mgt;
    // −δG (m₁ + m₂): η, ηᵢⱼ (rows 0, 1 of δqᵢ = −[qᵢ×] Pᵢ d_l) and lₙ.
    let ms = m[0] + m[1];
    let jq: [SMatrix<f64, 2, 12>; 2] =
        std::array::from_fn(|i| -skew(&aux.qil[i]).fixed_rows::<2>(0).into_owned() * p[i]);
    let jm = (jq[0] + jq[1]) * 0.5;
    let jy: Row12 = jm.row(1).into_owned();
    let qy = aux.q_y;
    let de = |i: usize, c: usize| (jq[i].row(c) - jy * aux.eij[i][c]) * (0.5 * ms[0] / qy);
    let mut deta = (jm.row(0) - jy * aux.eta) * (ms[0] / (qy * ln));
    let dl = aux.eta * ms[0] / (ln * ln);
    deta[0] += dl;
    deta[6] -= dl;
    for (row, s, d) in [
        (2, -1.0, deta),
        (8, 1.0, deta),
        (3, -1.0, de(0, 1)),
        (4, 1.0, de(0, 0)),
        (9, -1.0, de(1, 1)),
        (10, 1.0, de(1, 0)),
    ] {
        let mut r = k.row_mut(row);
        r += d * s;
    }
    // g₁, g₂ (rows 1, 2 of Gᵀ) scale with 1/lₙ; δlₙ = d₆ − d₀ (local components).
    let g12 = (aux.mgt.row(1) * ms[1] + aux.mgt.row(2) * ms[2]) / ln;
    for r in 0..12 {
        k[(r, 0)] += g12[r];
        k[(r, 6)] -= g12[r];
    }
    k
}

/// `n` moved by `h` along DOF `j` (0–2: translation, mm; 3–5: spatial spin, rad,
/// R ← exp([h eⱼ₋₃×])R): the variations the tangent is the derivative for.
pub fn perturbed(n: &NodeState, j: usize, h: f64) -> NodeState {
    let mut m = *n;
    if j < 3 {
        m.u[j] += h;
    } else {
        let mut w = Vector3::zeros();
        w[j - 3] = h;
        m.r = rot_exp(&w) * n.r;
    }
    m
}

/// Geometric part ∂(Bᵀ f₇)/∂d of the tangent at fixed local forces `f7` = [N, M₁, M₂] by
/// central differences of the closed-form B (relative error ~1e-10; 24 evaluations of B),
/// global, not symmetrised: the check of the closed form [`geometric_tangent`]. `None` for a
/// degenerate configuration.
pub fn geometric_tangent_fd(g: &CorotGeometry, n1: &NodeState, n2: &NodeState, f7: &Vec7) -> Option<Mat12> {
    let mut k = Mat12::zeros();
    let ht = 1e-6 * g.l0.max(1e-12);
    let hr = 1e-6;
    for j in 0..12 {
        let (node, dof) = (j / 6, j % 6);
        let h = if dof < 3 { ht } else { hr };
        let mut cols = [Vec12::zeros(); 2];
        for (s, col) in [h, -h].iter().zip(cols.iter_mut()) {
            let (a, b) = if node == 0 {
                (perturbed(n1, dof, *s), *n2)
            } else {
                (*n1, perturbed(n2, dof, *s))
            };
            let kp = kinematics(g, &a, &b)?;
            *col = kp.b.transpose() * f7;
        }
        k.set_column(j, &((cols[0] - cols[1]) / (2.0 * h)));
    }
    Some(k)
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The series and the closed form give the same H = ∂(Ts⁻ᵀ(θ) v)/∂θ at the switch,
    /// t = 0.05, to 1e-13 of |v| (its ½[v×] term is ½|v|).
    #[test]
    fn series_meets_closed_form() {
        let v = Vector3::new(0.3, -1.2, 0.7);
        for dir in [Vector3::new(1.0, 2.0, -2.0), Vector3::new(-0.2, 0.1, 0.9)] {
            let theta = dir.normalize() * 0.05;
            let t2 = theta.norm_squared();
            let d = h_with(ts_series(t2), &theta, &v) - h_with(ts_closed(t2), &theta, &v);
            assert!(d.amax() < 1e-13 * v.norm(), "{d}");
        }
    }
}
