//! Shell stress recovery: stress resultants at the element centre and surface stresses at the
//! nodes, averaged over the shells that meet there.
//!
//! Per element, the strains of the four-node shell ([`super::shell`]) are evaluated at its
//! 2×2 Gauss points — membrane strains ε including the condensed incompatible modes (their
//! amplitudes α = −K_ii⁻¹ K_ciᵀ d recovered as in the condensation), curvatures κ, and the MITC4
//! transverse shear strains γ — and extrapolated bilinearly to the corner nodes (the Gauss
//! points are the corners of a square of half-side 1/√3 in (ξ, η), so node i takes
//! Σ_g ¼(1 + √3 ξᵢξ_g')(1 + √3 ηᵢη_g') v_g with ξ_g' = ±1; O. C. Zienkiewicz, R. L. Taylor,
//! The Finite Element Method, vol. 1, 5th ed., §14.3). Surface stresses in the element axes are
//! σ(z) = C(ε + zκ) at z = +t/2 (top), 0 (mid) and −t/2 (bottom), plane stress; the transverse
//! shear stresses are zero on the faces and at the mid-surface the peak of the parabolic
//! distribution, τ = 1.5·Q/t with Q = κ_s·G·t·γ. The tensor is rotated to global axes and
//! averaged over the elements at the node (unweighted).
//!
//! Stress resultants at the centre in element axes: N = C·t·ε (N/mm), M = C·t³/12·κ
//! (N·mm/mm), Q = κ_s·G·t·γ (N/mm); the incompatible modes have zero derivatives at the centre.
//! Sign conventions follow [`super::shell`]: u(z) = u + zθy, v(z) = v − zθx, so Mxx > 0
//! stretches the top (z = +t/2) surface.

use super::error::FemError;
use super::model::{Element, Model};
use super::shell::{
    cartesian, curvature_b, membrane_rows, mitc_shear_b, plane_stress, shell_geometry, transverse_shear_stiffness,
    Vec24, ETA, G2, XI,
};
use crate::material::Material;
use nalgebra::{Matrix3, SMatrix, SVector, Vector2, Vector3};
use rayon::prelude::*;

/// Stress resultants at the centre of a shell element, in the element's axes.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ShellForces {
    /// Element axes: rows are local x, y, z (normal) in global coordinates.
    pub axes: [[f64; 3]; 3],
    /// Membrane forces [Nxx, Nyy, Nxy], N/mm.
    pub n: [f64; 3],
    /// Moments [Mxx, Myy, Mxy], N·mm/mm (Mxx > 0 puts the top surface in tension).
    pub m: [f64; 3],
    /// Transverse shear forces [Qx, Qy], N/mm.
    pub q: [f64; 2],
}

impl ShellForces {
    /// Resultants N, M, Q of an element with axes `lam` (rows: local x, y, z in global axes).
    fn new(lam: &Matrix3<f64>, n: &Vector3<f64>, m: &Vector3<f64>, q: &Vector2<f64>) -> ShellForces {
        let row = |r: usize| [lam[(r, 0)], lam[(r, 1)], lam[(r, 2)]];
        ShellForces {
            axes: [row(0), row(1), row(2)],
            n: [n.x, n.y, n.z],
            m: [m.x, m.y, m.z],
            q: [q.x, q.y],
        }
    }
}

/// Global stress tensors [top, mid, bottom] at a point of a shell with membrane strains `e`,
/// curvatures `k` and transverse shear strains `gm` (element axes `lam`): σ(z) = C(ε + zκ) at
/// z = +t/2, 0, −t/2, plane stress, and at the mid-surface the shear peak 1.5·Q/t with
/// Q = `ds`·γ (`ds` = κ_s·G·t, N/mm). Shared by the four- and nine-node shells.
fn surface_tensors(
    c: &Matrix3<f64>,
    e: &Vector3<f64>,
    k: &Vector3<f64>,
    gm: &Vector2<f64>,
    t: f64,
    ds: f64,
    lam: &Matrix3<f64>,
) -> [[f64; 6]; 3] {
    let mut out = [[0.0; 6]; 3];
    for (s, z) in [0.5 * t, 0.0, -0.5 * t].into_iter().enumerate() {
        let sp = c * (e + k * z);
        let (txz, tyz) = if s == 1 {
            (1.5 * ds / t * gm.x, 1.5 * ds / t * gm.y)
        } else {
            (0.0, 0.0)
        };
        let local = tensor(&[sp.x, sp.y, 0.0, sp.z, tyz, txz]);
        out[s] = voigt(&(lam.transpose() * local * lam));
    }
    out
}

/// One element's recovery: centre resultants and, per corner node, the global stress tensor
/// [sxx, syy, szz, sxy, syz, szx] (MPa) on the top, mid and bottom surfaces.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ShellRecovery {
    /// Centre resultants, element axes.
    pub forces: ShellForces,
    /// `nodal[i][s]`: node i of the element, surface s (0 top, 1 mid, 2 bottom).
    pub nodal: [[[f64; 6]; 3]; 4],
}

/// Local membrane (u v θz) and plate (w θx θy) DOFs of the 24 local element DOFs.
fn split(d: &Vec24) -> (SVector<f64, 12>, SVector<f64, 12>) {
    let mut dm = SVector::<f64, 12>::zeros();
    let mut dp = SVector::<f64, 12>::zeros();
    for i in 0..4 {
        for (k, (&a, &b)) in [0, 1, 5].iter().zip([2, 3, 4].iter()).enumerate() {
            dm[3 * i + k] = d[6 * i + a];
            dp[3 * i + k] = d[6 * i + b];
        }
    }
    (dm, dp)
}

/// Symmetric 3×3 from [xx, yy, zz, xy, yz, zx].
fn tensor(s: &[f64; 6]) -> Matrix3<f64> {
    Matrix3::new(s[0], s[3], s[5], s[3], s[1], s[4], s[5], s[4], s[2])
}

fn voigt(m: &Matrix3<f64>) -> [f64; 6] {
    [m[(0, 0)], m[(1, 1)], m[(2, 2)], m[(0, 1)], m[(1, 2)], m[(2, 0)]]
}

/// Principal stresses of [sxx, syy, szz, sxy, syz, szx], ascending.
pub fn principal(s: &[f64; 6]) -> [f64; 3] {
    let mut e: Vec<f64> = tensor(s).symmetric_eigenvalues().iter().copied().collect();
    e.sort_by(f64::total_cmp);
    [e[0], e[1], e[2]]
}

/// Strains at the 2×2 Gauss points (order of the nodes: (−,−), (+,−), (+,+), (−,+)/√3) from
/// the local element DOFs: membrane ε (with the condensed incompatible modes), curvatures κ,
/// MITC4 shear strains γ, and det J.
pub(crate) struct GaussStrains {
    pub(crate) eps: [Vector3<f64>; 4],
    pub(crate) kap: [Vector3<f64>; 4],
    pub(crate) gam: [Vector2<f64>; 4],
    pub(crate) det: [f64; 4],
}

pub(crate) fn gauss_strains(xy: &[[f64; 2]; 4], t: f64, c: &Matrix3<f64>, d: &Vec24) -> Option<GaussStrains> {
    let (dm, dp) = split(d);
    let ct = c * t;
    // Incompatible-mode amplitudes, as condensed in the stiffness.
    let mut kci = SMatrix::<f64, 12, 4>::zeros();
    let mut kii = SMatrix::<f64, 4, 4>::zeros();
    let mut rows = Vec::with_capacity(4);
    for gp in 0..4 {
        let (b, bi, det) = membrane_rows(xy, XI[gp] * G2, ETA[gp] * G2)?;
        kci += b.transpose() * ct * bi * det;
        kii += bi.transpose() * ct * bi * det;
        rows.push((b, bi, det));
    }
    let alpha = -(kii.try_inverse()? * kci.transpose() * dm);
    let mut out = GaussStrains {
        eps: [Vector3::zeros(); 4],
        kap: [Vector3::zeros(); 4],
        gam: [Vector2::zeros(); 4],
        det: [0.0; 4],
    };
    for gp in 0..4 {
        let (xi, eta) = (XI[gp] * G2, ETA[gp] * G2);
        let (b, bi, det) = &rows[gp];
        out.eps[gp] = b * dm + bi * alpha;
        out.det[gp] = *det;
        let (_, dx, dy, _, ji) = cartesian(xy, xi, eta)?;
        out.kap[gp] = curvature_b(&dx, &dy) * dp;
        out.gam[gp] = mitc_shear_b(xy, xi, eta, &ji) * dp;
    }
    Some(out)
}

/// Recovery of one shell element with nodes at `x` from its global displacements (24 values:
/// six per node, mm and rad). `None` for a degenerate quadrilateral.
pub fn shell_recovery(x: &[[f64; 3]; 4], t: f64, mat: &Material, d_global: &Vec24) -> Option<ShellRecovery> {
    let g = shell_geometry(x)?;
    let d = g.t * d_global;
    let (dm, dp) = split(&d);
    let c = plane_stress(mat.e, mat.nu);
    let ct = c * t;
    // Transverse shear stiffness per unit width, N/mm: the element's own (MITC4),
    // so that Q balances the nodal forces; the shear stress is its parabolic peak 1.5·Q/t.
    let ds = transverse_shear_stiffness(t, mat);
    let GaussStrains {
        eps: eps_g,
        kap: kap_g,
        gam: gam_g,
        ..
    } = gauss_strains(&g.xy, t, &c, &d)?;
    // Centre resultants.
    let (_, dx0, dy0, _, ji0) = cartesian(&g.xy, 0.0, 0.0)?;
    let (b0, _, _) = membrane_rows(&g.xy, 0.0, 0.0)?;
    let n = ct * (b0 * dm);
    let m = c * (t * t * t / 12.0) * (curvature_b(&dx0, &dy0) * dp);
    let q = mitc_shear_b(&g.xy, 0.0, 0.0, &ji0) * dp * ds;
    // Extrapolation to the corners and rotation to global axes.
    let r3 = 3f64.sqrt();
    let mut nodal = [[[0.0; 6]; 3]; 4];
    for i in 0..4 {
        let (mut e, mut k, mut gm) = (Vector3::zeros(), Vector3::zeros(), Vector2::zeros());
        for gp in 0..4 {
            let w = 0.25 * (1.0 + r3 * XI[i] * XI[gp]) * (1.0 + r3 * ETA[i] * ETA[gp]);
            e += eps_g[gp] * w;
            k += kap_g[gp] * w;
            gm += gam_g[gp] * w;
        }
        nodal[i] = surface_tensors(&c, &e, &k, &gm, t, ds, &g.lam);
    }
    Some(ShellRecovery {
        forces: ShellForces::new(&g.lam, &n, &m, &q),
        nodal,
    })
}

/// Recovery of one nine-node shell ([`super::shell9`]) from its global displacements (54 values):
/// centre resultants and, per node, the surface stresses. Strains at the 3×3 Gauss points
/// (membrane, curvatures, MITC9 shear) are extrapolated to the nodes by the biquadratic through
/// them (node at ξ takes the quadratic Lagrange weights through −√⅗, 0, √⅗ at ξ); otherwise as
/// [`shell_recovery`].
pub fn shell9_recovery(
    x: &[[f64; 3]; 9],
    t: f64,
    mat: &Material,
    d_global: &nalgebra::DVector<f64>,
) -> Option<(ShellForces, [[[f64; 6]; 3]; 9])> {
    use super::shell9::{
        cartesian9, curvature_b as curv9, lagrange, membrane_b, mitc9_shear_b, shell9_geometry, tying, G3,
    };
    let g = shell9_geometry(x).ok()?;
    let d = &g.t * d_global;
    let mut dm = SVector::<f64, 27>::zeros();
    let mut dp = SVector::<f64, 27>::zeros();
    for i in 0..9 {
        for (k, (&a, &b)) in [0, 1, 5].iter().zip([2, 3, 4].iter()).enumerate() {
            dm[3 * i + k] = d[6 * i + a];
            dp[3 * i + k] = d[6 * i + b];
        }
    }
    let c = plane_stress(mat.e, mat.nu);
    let ds = transverse_shear_stiffness(t, mat);
    let tie = tying(&g.xy);
    let strains = |xi: f64, eta: f64| {
        let (_, dx, dy, _, ji) = cartesian9(&g.xy, xi, eta)?;
        Some((
            membrane_b(&dx, &dy) * dm,
            curv9(&dx, &dy) * dp,
            mitc9_shear_b(&tie, xi, eta, &ji) * dp,
        ))
    };
    let (e0, k0, g0) = strains(0.0, 0.0)?;
    let n = c * t * e0;
    let m = c * (t * t * t / 12.0) * k0;
    let q = g0 * ds;
    let pts = [-G3, 0.0, G3];
    let mut at = Vec::with_capacity(9);
    for &eta in &pts {
        for &xi in &pts {
            at.push(strains(xi, eta)?);
        }
    }
    let mut nodal = [[[0.0; 6]; 3]; 9];
    for (i, node) in nodal.iter_mut().enumerate() {
        // Lagrange weights through the Gauss abscissae: l(ξ) through −1, 0, 1 at ξ/√⅗.
        let (wx, _) = lagrange(super::shell9::NODE_XI[i] / G3);
        let (we, _) = lagrange(super::shell9::NODE_ETA[i] / G3);
        let (mut e, mut k, mut gm) = (Vector3::zeros(), Vector3::zeros(), Vector2::zeros());
        for (b, w_eta) in we.iter().enumerate() {
            for (a, w_xi) in wx.iter().enumerate() {
                let (ea, ka, ga) = &at[3 * b + a];
                let w = w_xi * w_eta;
                e += ea * w;
                k += ka * w;
                gm += ga * w;
            }
        }
        *node = surface_tensors(&c, &e, &k, &gm, t, ds, &g.lam);
    }
    Some((ShellForces::new(&g.lam, &n, &m, &q), nodal))
}

/// Shell stresses of a whole model for one displacement field.
#[derive(Debug, Clone, Default, PartialEq)]
pub struct ShellField {
    /// Per node, global [sxx, syy, szz, sxy, syz, szx] (MPa) on the top surface, averaged over
    /// the shells at the node; `None` for nodes without shells.
    pub top: Vec<Option<[f64; 6]>>,
    /// As `top`, mid-surface (with the transverse shear peak 1.5·Q/t).
    pub mid: Vec<Option<[f64; 6]>>,
    /// As `top`, bottom surface.
    pub bottom: Vec<Option<[f64; 6]>>,
    /// Per shell element (model order): element index and centre resultants.
    pub forces: Vec<(usize, ShellForces)>,
}

/// Recovers every shell of `model` for the displacements `u` (one [ux, uy, uz, rx, ry, rz]
/// row per node, mm and rad, global axes; extra rows are ignored). Empty for models without
/// shells.
pub fn shell_field(model: &Model, u: &[[f64; 6]]) -> Result<ShellField, FemError> {
    let shells: Vec<usize> = (0..model.elements.len())
        .filter(|&ie| matches!(model.elements[ie], Element::Shell4(_) | Element::Shell9(_)))
        .collect();
    if shells.is_empty() {
        return Ok(ShellField::default());
    }
    let nn = model.nodes.len();
    if u.len() < nn {
        return Err(FemError::BadInput(format!(
            "{} displacement rows for {nn} nodes",
            u.len()
        )));
    }
    // One element's recovery: a four-node shell's inline (most models), a nine-node shell's
    // nodal stresses boxed (so the list of four-node ones stays as small as before).
    // Four-node shells are the bulk: boxing their recovery would cost an allocation each.
    #[allow(clippy::large_enum_variant)]
    enum Rec {
        Four(usize, [usize; 4], ShellRecovery),
        Nine(usize, [usize; 9], ShellForces, Box<[[[f64; 6]; 3]; 9]>),
    }
    let rec: Vec<Rec> = shells
        .par_iter()
        .map(|&ie| {
            let degenerate = || FemError::BadElement {
                element: ie,
                reason: "degenerate shell geometry".into(),
            };
            match &model.elements[ie] {
                Element::Shell4(sh) => {
                    let x = sh.nodes.map(|n| model.nodes[n]);
                    let mut d = Vec24::zeros();
                    for (k, &n) in sh.nodes.iter().enumerate() {
                        for i in 0..6 {
                            d[6 * k + i] = u[n][i];
                        }
                    }
                    shell_recovery(&x, sh.t, &sh.material, &d)
                        .map(|r| Rec::Four(ie, sh.nodes, r))
                        .ok_or_else(degenerate)
                }
                Element::Shell9(sh) => {
                    let x = sh.nodes.map(|n| model.nodes[n]);
                    let d = nalgebra::DVector::from_iterator(54, sh.nodes.iter().flat_map(|&n| u[n]));
                    shell9_recovery(&x, sh.t, &sh.material, &d)
                        .map(|(f, nodal)| Rec::Nine(ie, sh.nodes, f, Box::new(nodal)))
                        .ok_or_else(degenerate)
                }
                _ => unreachable!("filtered to shells"),
            }
        })
        .collect::<Result<_, _>>()?;
    let mut sum = vec![[[0.0; 6]; 3]; nn];
    let mut count = vec![0.0f64; nn];
    let mut forces = Vec::with_capacity(rec.len());
    for r in &rec {
        let (ie, nodes, r_forces, r_nodal): (usize, &[usize], &ShellForces, &[[[f64; 6]; 3]]) = match r {
            Rec::Four(ie, nodes, r) => (*ie, nodes, &r.forces, &r.nodal),
            Rec::Nine(ie, nodes, f, nodal) => (*ie, nodes, f, &nodal[..]),
        };
        // A triangle [a, b, c, c] gives node c the mean of its two corner values.
        let tri = nodes.len() == 4 && nodes[3] == nodes[2];
        for (k, &n) in nodes.iter().enumerate() {
            let w = if tri && k >= 2 { 0.5 } else { 1.0 };
            for (acc, v) in sum[n].iter_mut().zip(&r_nodal[k]) {
                for (a, b) in acc.iter_mut().zip(v) {
                    *a += w * b;
                }
            }
            count[n] += w;
        }
        forces.push((ie, *r_forces));
    }
    let mut field = ShellField {
        forces,
        ..Default::default()
    };
    for (s, c) in sum.iter().zip(&count) {
        let avg = |k: usize| (*c > 0.0).then(|| s[k].map(|v| v / c));
        field.top.push(avg(0));
        field.mid.push(avg(1));
        field.bottom.push(avg(2));
    }
    Ok(field)
}

/// Pairs of shells that share an edge but run it in the same direction, so their normals
/// (right-hand rule over the node order) point to opposite sides: (element, element, edge
/// nodes). Their "top" surfaces are on opposite sides, and nodal averages at their nodes mix
/// top and bottom.
pub fn orientation_conflicts(model: &Model) -> Vec<(usize, usize, [usize; 2])> {
    let mut seen: std::collections::HashMap<(usize, usize), usize> = std::collections::HashMap::new();
    let mut out = Vec::new();
    let mut pairs = std::collections::HashSet::new();
    for (ie, e) in model.elements.iter().enumerate() {
        // Edges in the element's order: a nine-node shell's by halves (corner to midpoint to
        // corner), so that it meets a four-node shell on a half edge too.
        let mut edges = [(0, 0); 8];
        let count = match e {
            Element::Shell4(sh) => {
                for (k, edge) in edges.iter_mut().take(4).enumerate() {
                    *edge = (sh.nodes[k], sh.nodes[(k + 1) % 4]);
                }
                4
            }
            Element::Shell9(sh) => {
                for k in 0..4 {
                    edges[2 * k] = (sh.nodes[k], sh.nodes[4 + k]);
                    edges[2 * k + 1] = (sh.nodes[4 + k], sh.nodes[(k + 1) % 4]);
                }
                8
            }
            _ => continue,
        };
        for &(a, b) in &edges[..count] {
            if a == b {
                continue;
            }
            match seen.get(&(a, b)) {
                // One entry per pair of elements (two nine-node shells share two half edges).
                Some(&other) if other != ie && pairs.insert((other, ie)) => out.push((other, ie, [a, b])),
                Some(_) => {}
                _ => {
                    seen.insert((a, b), ie);
                }
            }
        }
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::fem::shell::shell_local_stiffness;

    /// The recovered strains are the element's own: for fields without drilling-penalty
    /// energy, Σ_g (εᵀCtε + κᵀDκ + γᵀκ_sGtγ)·det J_g equals dᵀkd of the element stiffness
    /// (to 1e-10) — on a distorted quad for plate fields (w θx θy arbitrary), and on a
    /// rectangle for in-plane bending u = κxy, v = 0 with θz = −κx/2 (the drilling rotation
    /// ½(∂v/∂x − ∂u/∂y) exactly, so the penalty is idle; the incompatible modes are active).
    /// Fails if the element formulation and this recovery drift apart.
    #[test]
    fn recovered_strains_carry_the_element_energy() {
        let mat = Material::STEEL;
        let t = 3.0;
        let c = plane_stress(mat.e, mat.nu);
        let energy = |xy: &[[f64; 2]; 4], d: &Vec24| {
            let s = gauss_strains(xy, t, &c, d).unwrap();
            let gs = transverse_shear_stiffness(t, &mat);
            (0..4)
                .map(|g| {
                    (s.eps[g].dot(&(c * t * s.eps[g]))
                        + s.kap[g].dot(&(c * (t * t * t / 12.0) * s.kap[g]))
                        + gs * s.gam[g].norm_squared())
                        * s.det[g]
                })
                .sum::<f64>()
        };
        let skew = [[0.0, 0.0], [12.0, 1.5], [10.0, 9.0], [-1.0, 7.0]];
        let mut d = Vec24::zeros();
        for i in 0..4 {
            d[6 * i + 2] = 0.01 * (i as f64 + 1.0) * if i % 2 == 0 { 1.0 } else { -0.7 };
            d[6 * i + 3] = 0.003 * (i as f64 - 1.5);
            d[6 * i + 4] = -0.002 * (i as f64 * i as f64 - 2.0);
        }
        let k = shell_local_stiffness(&skew, t, &mat).unwrap();
        let (a, b) = (energy(&skew, &d), d.dot(&(k * d)));
        assert!((a - b).abs() < 1e-10 * b, "plate: {a} vs {b}");
        let rect = [[0.0, 0.0], [8.0, 0.0], [8.0, 5.0], [0.0, 5.0]];
        let kappa = 1e-4;
        let mut d = Vec24::zeros();
        for (i, p) in rect.iter().enumerate() {
            let (x, y) = (p[0] - 4.0, p[1] - 2.5);
            d[6 * i] = kappa * x * y;
            d[6 * i + 5] = -0.5 * kappa * x;
        }
        let k = shell_local_stiffness(&rect, t, &mat).unwrap();
        let (a, b) = (energy(&rect, &d), d.dot(&(k * d)));
        assert!((a - b).abs() < 1e-10 * b, "membrane: {a} vs {b}");
    }
}
