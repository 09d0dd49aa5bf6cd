//! Non-uniform (Vlasov) torsion of a rectangular-section hinge with restrained warping.
//!
//! Saint-Venant torsion (T = GJ θ') lets every section warp freely. In a short notch the thick
//! blanks on either side hardly warp, so the notch is held against warping and is stiffer than
//! 1-D Saint-Venant theory predicts (23–92 % too soft against solid FEM). Vlasov's
//! theory of non-uniform torsion (Vlasov, *Thin-walled elastic beams*, 1961; for solid
//! sections with the Saint-Venant warping function as the warping mode, e.g. Pilkey,
//! *Analysis and Design of Elastic Beams*, 2002, ch. 6) adds the bimoment term:
//!
//! (GJ(x) θ')' − (EΓ(x) θ'')'' = −m(x),
//!
//! with J(x) the Timoshenko–Goodier rectangle series and Γ(x) = ∫ω² dA of the rectangle
//! ([`super::section::rect_warping_constant`]). Both blank end faces are warping-restrained
//! (θ' = 0): the clamped face, and the loading face which is rigid. θ = 0 at the clamped face; a
//! torque T at the loaded face; k = T/θ(end).
//!
//! With no distributed torque the total torque is the same in every section,
//! GJ θ' − (EΓ θ'')' = T, so the rate of twist φ = θ' solves the second-order problem
//! −(EΓ φ')' + GJ φ = T, φ = 0 at both faces, and θ(end) = ∫φ dx. Solving for φ rather than θ
//! matters numerically: in θ a stiff blank in series with a thin notch is a chain of springs
//! whose elimination cancels (the soft compliance is lost below ε × the stiff one: NaN for a
//! 1 µm leaf between 10 mm blanks); in φ every section carries the torque itself and
//! neighbours are coupled only through EΓ.
//!
//! The solid-calibrated torsion ([`solid_torsion_stiffness`]) adds the shear strain of the
//! warping (Benscoter, [`benscoter_torsion_pair`]): the same problem for the warping amplitude
//! ψ, with GJ replaced by the series stiffness K and a direct term (see there).
//!
//! Discretisation: 3-node quadratic Lagrange elements for φ — C⁰, so φ' may jump where EΓ
//! jumps (the bimoment EΓφ' is what stays continuous); the same discrete space as Hermite
//! cubics in θ, so the same stiffness in exact arithmetic. GJ and EΓ sampled at 4 Gauss points
//! per interval (exact for piecewise-constant properties), nodes at every profile
//! breakpoint and graded towards the waist (the same tan mapping as the flexibility
//! quadrature) and, in the blanks, geometrically towards the notch, where the warping boundary
//! layer of length √(EΓ/GJ) sits. The stiffness is banded (half-bandwidth 2) and solved by a
//! banded Cholesky on the stack.

mod mesh;
mod solid;

use super::profile::Profile;
use super::section::rect_torsion_warping;
use mesh::half_nodes;
pub use mesh::TorsionMesh;
pub use solid::{
    continuous_ends, end_face_acts, solid_torsion_pair, solid_torsion_stiffness, warping_modulus_factor,
    TORSION_FACE_SLOPE, TORSION_SPREAD_SLOPE,
};

/// 4-point Gauss–Legendre on [0, 1].
const GL4_X: [f64; 4] = [
    0.069_431_844_202_973_71,
    0.330_009_478_207_571_9,
    0.669_990_521_792_428_1,
    0.930_568_155_797_026_3,
];
const GL4_W: [f64; 4] = [
    0.173_927_422_568_726_93,
    0.326_072_577_431_273_07,
    0.326_072_577_431_273_07,
    0.173_927_422_568_726_93,
];

/// Maximum number of nodes of the torsion mesh.
pub const MAX_NODES: usize = 320;

/// Torsional stiffness T/θ (N·mm/rad) of a rectangular-section hinge between its two blank end
/// faces, warping restrained at both faces. `e`, `g` in MPa.
pub fn vlasov_torsion_stiffness(profile: &Profile, e: f64, g: f64, mesh: TorsionMesh) -> f64 {
    let half = HalfMesh::new(profile, None, mesh, e, g, None);
    half.solve(half.n)
}

/// [`vlasov_torsion_stiffness`] with the shear strain of non-uniform warping (Benscoter's
/// theory, see [`benscoter_torsion_pair`]); `warping` as there.
pub fn benscoter_torsion_stiffness(
    profile: &Profile,
    warping: Option<&Profile>,
    e: f64,
    g: f64,
    shear: WarpingShear,
    mesh: TorsionMesh,
) -> f64 {
    let half = HalfMesh::new(profile, warping, mesh, e, g, Some(shear));
    half.solve(half.n)
}

/// The warping shear of [`benscoter_torsion_pair`]: its shear coefficient κ and the warping
/// mode, `plate` ∈ [0, 1] the weight of the plate mode ω = −yz against the Saint-Venant mode
/// (the weight s of [`warping_modulus_factor`]).
#[derive(Debug, Clone, Copy)]
pub struct WarpingShear {
    pub kappa: f64,
    pub plate: f64,
}

impl WarpingShear {
    /// J_r (mm⁴) of a rectangle `w` × `t` of Saint-Venant constant `j`: I_p − J for the
    /// Saint-Venant warping mode (∫|∇ω|² dA), t·w³/12 for the plate mode (the transverse shear
    /// γ_xz = y(θ′ − ψ) of a Mindlin plate strip), blended by `plate`.
    fn warping_shear_constant(&self, w: f64, t: f64, j: f64) -> f64 {
        let saint_venant = w * t * (w * w + t * t) / 12.0 - j;
        (1.0 - self.plate) * saint_venant + self.plate * t * w.powi(3) / 12.0
    }
}

/// Torsional stiffness of a hinge in its blank and of its notch alone (`notch`: the same
/// profile with no blank); the notch's mesh is the hinge's mesh inside the notch (the same
/// pieces give the same nodes), so its section properties are the hinge's, sampled once.
/// Vlasov's model ([`vlasov_torsion_stiffness`]) with the shear strain of non-uniform warping
/// (Benscoter, *A theory of torsion bending for multicell beams*, J. Appl. Mech. 21 (1954)
/// 25–34): the warping
/// displacement is ω(y, z)·ψ(x) with its own amplitude ψ instead of Vlasov's θ′, so the
/// section carries the Saint-Venant torque GJ θ′ plus a warping shear torque
/// S = κ G J_r (θ′ − ψ) ([`WarpingShear`]: J_r = ∫|∇ω|² dA = I_p − J for the Saint-Venant
/// mode, t·w³/12 for the plate mode; κ the shear coefficient); and the bimoment −EΓ ψ′
/// balances it, −(EΓ ψ′)′ = S. With
/// a torque T constant along x, ψ solves −(EΓ ψ′)′ + K ψ = K T/GJ, K = GJ·κGJ_r/(GJ + κGJ_r)
/// (ψ = 0 at both restrained faces), and θ(end) = ∫ T/(GJ + κGJ_r) dx + ∫ (K/GJ) ψ dx.
/// Vlasov's theory is the limit κGJ_r → ∞ (ψ = θ′).
///
/// `warping`: the same hinge with another load spreading into the blanks, whose thickness
/// beyond the notch gives the warping constant Γ there (the Saint-Venant J keeps `profile`'s);
/// `None`: `profile`'s for both.
pub fn benscoter_torsion_pair(
    profile: &Profile,
    warping: Option<&Profile>,
    notch: &Profile,
    e: f64,
    g: f64,
    shear: WarpingShear,
    mesh: TorsionMesh,
) -> (f64, f64) {
    let shear = Some(shear);
    let whole = HalfMesh::new(profile, warping, mesh, e, g, shear);
    let mut own = [0.0; MAX_NODES / 2];
    let nn = half_nodes(notch, mesh, e, g, &mut own);
    let k_notch = if nn <= whole.n && own[..nn] == whole.x[..nn] {
        whole.solve(nn)
    } else {
        let half = HalfMesh::new(notch, None, mesh, e, g, shear);
        half.solve(half.n)
    };
    (whole.solve(whole.n), k_notch)
}

/// Section properties at a quadrature point: GJ (N·mm²), EΓ (N·mm⁴) and r = GJ/(κ G J_r), the
/// ratio of the Saint-Venant to the warping shear stiffness (0: Vlasov).
type Props = (f64, f64, f64);

/// The nodes of the half mesh x ≥ 0 and (GJ, EΓ) at the 4 Gauss points of each of its
/// intervals: the profile is symmetric, so the mirrored half of the mesh takes the same values
/// (at the mirrored points, which agree with the directly computed ones to rounding).
struct HalfMesh {
    x: [f64; MAX_NODES / 2],
    n: usize,
    gp: [[Props; 4]; MAX_NODES / 2],
}

impl HalfMesh {
    fn new(
        profile: &Profile,
        warping: Option<&Profile>,
        mesh: TorsionMesh,
        e: f64,
        g: f64,
        shear: Option<WarpingShear>,
    ) -> Self {
        let mut x = [0.0; MAX_NODES / 2];
        let n = half_nodes(profile, mesh, e, g, &mut x);
        let w = profile.w;
        let warping = warping.unwrap_or(profile);
        // The last thicknesses (J's, Γ's) and their (GJ, EΓ, r): the blanks are one section each.
        let mut last = ((f64::NAN, f64::NAN), (0.0, 0.0, 0.0));
        let mut gp = [[(0.0, 0.0, 0.0); 4]; MAX_NODES / 2];
        for i in 0..n - 1 {
            for q in 0..4 {
                let xq = x[i] + GL4_X[q] * (x[i + 1] - x[i]);
                let (t, t_w) = if xq.abs() > profile.half_notch {
                    (profile.effective_thickness(xq), warping.effective_thickness(xq))
                } else {
                    let t = profile.thickness(xq);
                    (t, t)
                };
                if (t, t_w) != last.0 {
                    let (j, gamma) = rect_torsion_warping(w, t);
                    let gamma = if t_w == t {
                        gamma
                    } else {
                        rect_torsion_warping(w, t_w).1
                    };
                    let r = shear.map_or(0.0, |sh| j / (sh.kappa * sh.warping_shear_constant(w, t, j)));
                    last = ((t, t_w), (g * j, e * gamma, r));
                }
                gp[i][q] = last.1;
            }
        }
        HalfMesh { x, n, gp }
    }

    /// T/θ of the mirrored mesh of the first `nh` half nodes (warping restrained at ±x[nh − 1]).
    fn solve(&self, nh: usize) -> f64 {
        MIRROR.with_borrow_mut(|m| self.solve_in(nh, m))
    }

    fn solve_in(&self, nh: usize, mirror: &mut Mirror) -> f64 {
        let Mirror { xs, gp } = mirror;
        let mut n = 0;
        for i in (1..nh).rev() {
            xs[n] = -self.x[i];
            // Interval [−x[i], −x[i−1]] mirrors [x[i−1], x[i]]: Gauss points in reverse order.
            let h = self.gp[i - 1];
            gp[n] = [h[3], h[2], h[1], h[0]];
            n += 1;
        }
        for i in 0..nh {
            xs[n] = self.x[i];
            if i + 1 < nh {
                gp[n] = self.gp[i];
            }
            n += 1;
        }
        torsion_fe_sampled(&xs[..n], &gp[..])
    }
}

/// The mirrored mesh of [`HalfMesh::solve`], one per thread (written before it is read: kept
/// from call to call instead of zeroing 22 kB of stack per solve).
struct Mirror {
    xs: [f64; MAX_NODES],
    gp: [[Props; 4]; MAX_NODES],
}

/// The banded system of [`torsion_fe_sampled`], one per thread; only the rows in use are
/// cleared.
struct System {
    keep: [usize; MAX_NODES],
    k: [[f64; 4]; 2 * MAX_NODES],
    load: [f64; 2 * MAX_NODES],
}

thread_local! {
    static MIRROR: std::cell::RefCell<Box<Mirror>> = std::cell::RefCell::new(Box::new(Mirror {
        xs: [0.0; MAX_NODES],
        gp: [[(0.0, 0.0, 0.0); 4]; MAX_NODES],
    }));
    static SYSTEM: std::cell::RefCell<Box<System>> = std::cell::RefCell::new(Box::new(System {
        keep: [0; MAX_NODES],
        k: [[0.0; 4]; 2 * MAX_NODES],
        load: [0.0; 2 * MAX_NODES],
    }));
}

/// Shortest FE element relative to the local warping boundary-layer length √(EΓ/GJ).
///
/// An element of length l_e couples its nodes through EΓ/l_e next to GJ·l_e: when l_e ≪
/// √(EΓ/GJ) the element is nearly rigid and the banded Cholesky loses the rest of the system
/// to cancellation (L(i,i)² = K(i,i) − Σ L² ends at round-off: NaN for a notch of R ≈ 3e-4 mm,
/// or one that barely cuts the blank, t → h, whose graded nodes are ~1e-5 mm apart). The
/// solution varies on the scale √(EΓ/GJ), so shorter intervals of the node list are not given
/// their own element: they stay quadrature sub-intervals of a longer element (properties are
/// still sampled on every interval of the node list), which is consistent to O(l/√(EΓ/GJ)) and
/// keeps the coupling of neighbouring elements within a factor 1e3.
pub const MIN_ELEMENT_PER_LAYER: f64 = 1e-3;

/// Solves the Vlasov torsion problem on the node list `xs` with properties `props(x) = (GJ, EΓ)`;
/// θ = θ' = 0 at xs[0], θ' = 0 and a unit torque at the last node. Returns T/θ(end), from the
/// rate-of-twist form −(EΓ φ')' + GJ φ = T (module docs).
///
/// Every interval of `xs` is integrated with 4 Gauss points; intervals much shorter than the
/// local warping layer are merged into their neighbours' elements ([`MIN_ELEMENT_PER_LAYER`]).
pub fn torsion_fe(xs: &[f64], mut props: impl FnMut(f64) -> (f64, f64)) -> f64 {
    // Properties at the 4 Gauss points of every interval of xs (sampled once).
    let mut gp = [[(0.0f64, 0.0f64, 0.0f64); 4]; MAX_NODES];
    for i in 0..xs.len() - 1 {
        for q in 0..4 {
            let (gj, eg) = props(xs[i] + GL4_X[q] * (xs[i + 1] - xs[i]));
            gp[i][q] = (gj, eg, 0.0);
        }
    }
    torsion_fe_sampled(xs, &gp[..])
}

/// [`torsion_fe`] with the properties (GJ, EΓ) at the 4 Gauss points of interval i of `xs`
/// given in `gp[i]`.
fn torsion_fe_sampled(xs: &[f64], gp: &[[Props; 4]]) -> f64 {
    SYSTEM.with_borrow_mut(|sys| torsion_fe_in(xs, gp, sys))
}

fn torsion_fe_in(xs: &[f64], gp: &[[Props; 4]], sys: &mut System) -> f64 {
    let System { keep, k, load } = sys;
    // Element nodes: indices into xs, each element at least MIN_ELEMENT_PER_LAYER × the largest
    // warping layer √(EΓ/GJ) of the intervals it covers.
    let layer_of = |i: usize| -> f64 {
        // √ is monotone: the root of the largest ratio.
        gp[i]
            .iter()
            .fold(
                0.0f64,
                |m, &(gj, eg, _)| if gj > 0.0 && eg > 0.0 { m.max(eg / gj) } else { m },
            )
            .sqrt()
    };
    keep[0] = 0;
    let mut nk = 1;
    let mut layer = 0.0f64;
    for i in 1..xs.len() {
        layer = layer.max(layer_of(i - 1));
        if xs[i] - xs[keep[nk - 1]] >= MIN_ELEMENT_PER_LAYER * layer {
            keep[nk] = i;
            nk += 1;
            layer = 0.0;
        }
    }
    if keep[nk - 1] != xs.len() - 1 {
        // The last element is short: extend the previous one to the end instead.
        if nk > 1 {
            nk -= 1;
        }
        keep[nk] = xs.len() - 1;
        nk += 1;
    }
    let nn = nk;
    let ndof = 2 * nn - 1;
    // Symmetric band storage: k[i][d] = K(i, i + d), d = 0..=3; load vector ∫N dx (T = 1).
    k[..ndof].fill([0.0; 4]);
    load[..ndof].fill(0.0);
    // ∫ 1/(GJ + κGJ_r) dx: the twist of the shear path in parallel (0 for Vlasov).
    let mut direct = 0.0;
    for el in 0..nn - 1 {
        let (xa, xb) = (xs[keep[el]], xs[keep[el + 1]]);
        let inv_le = 1.0 / (xb - xa);
        let mut ke = [[0.0f64; 3]; 3];
        let mut fe = [0.0f64; 3];
        for sub in keep[el]..keep[el + 1] {
            let (s0, s1) = (xs[sub], xs[sub + 1]);
            for q in 0..4 {
                let x = s0 + GL4_X[q] * (s1 - s0);
                let xi = (x - xa) * inv_le;
                let (gj, eg, r) = gp[sub][q];
                let wq = GL4_W[q] * (s1 - s0);
                // K = GJ/(1 + r), the load K/GJ per unit torque (benscoter_torsion_pair).
                let (kk, c) = (gj / (1.0 + r), 1.0 / (1.0 + r));
                direct += wq * r / (gj * (1.0 + r));
                // Quadratic Lagrange shape functions for φ (start, middle, end) and their
                // x-derivatives.
                let n = [
                    (1.0 - xi) * (1.0 - 2.0 * xi),
                    4.0 * xi * (1.0 - xi),
                    xi * (2.0 * xi - 1.0),
                ];
                let d1 = [
                    (4.0 * xi - 3.0) * inv_le,
                    (4.0 - 8.0 * xi) * inv_le,
                    (4.0 * xi - 1.0) * inv_le,
                ];
                for a in 0..3 {
                    fe[a] += wq * c * n[a];
                    for b in a..3 {
                        ke[a][b] += wq * (eg * d1[a] * d1[b] + kk * n[a] * n[b]);
                    }
                }
            }
        }
        // Global order: φ(node 0), φ(middle 0), φ(node 1), φ(middle 1), …
        let base = 2 * el;
        for a in 0..3 {
            load[base + a] += fe[a];
            for b in a..3 {
                k[base + a][b - a] += ke[a][b];
            }
        }
    }
    // φ = 0 (warping restrained) at both end faces, by replacement with identity rows.
    for dof in [0usize, ndof - 1] {
        k[dof] = [0.0; 4];
        for d in 1..4 {
            if dof >= d {
                k[dof - d][d] = 0.0;
            }
        }
        k[dof][0] = 1.0;
        load[dof] = 0.0;
    }
    // Banded Cholesky K = L Lᵀ, L stored in place (l[i][d] = L(i + d, i), d ≥ 1) with the
    // reciprocal of the diagonal in l[i][0] (one division per row on the serial chain).
    for i in 0..ndof {
        let mut diag = k[i][0];
        for d in 1..4 {
            if i >= d {
                diag -= k[i - d][d] * k[i - d][d];
            }
        }
        let inv = 1.0 / diag.sqrt();
        k[i][0] = inv;
        for d in 1..4 {
            let r = i + d;
            if r >= ndof {
                break;
            }
            // L(r, i) = (K(r, i) − Σ_{m<i} L(r, m) L(i, m)) / L(i, i)
            let mut s = k[i][d];
            for e in 1..4 {
                if i >= e && d + e < 4 {
                    s -= k[i - e][d + e] * k[i - e][e];
                }
            }
            k[i][d] = s * inv;
        }
    }
    // θ(end) = ∫φ dx = loadᵀ φ = loadᵀ K⁻¹ load = |y|², y = L⁻¹ load (the compliance, > 0 for
    // an SPD system): forward substitution only.
    let f = load;
    let mut theta = direct;
    for i in 0..ndof {
        let mut s = f[i];
        for d in 1..4 {
            if i >= d {
                s -= k[i - d][d] * f[i - d];
            }
        }
        f[i] = s * k[i][0];
        theta += f[i] * f[i];
    }
    1.0 / theta
}
