//! Superconvergent patch recovery (SPR) of shell surface stresses, and the Zienkiewicz–Zhu
//! error indicator per element.
//!
//! The bilinear shell has, along each direction, a curvature that is constant per element
//! (κxx = ∂θy/∂x does not vary with x), so the extrapolation of its Gauss-point values to a
//! node ([`super::shell_recovery`]) returns the value at the element's centre line: at a
//! clamped edge, where the moment is largest and falls off steeply, that is the moment half an
//! element inside. Measured on a clamped square plate under pressure (edge-midpoint surface
//! stress against S. Timoshenko, S. Woinowsky-Krieger, Theory of Plates and Shells, 2nd ed.,
//! McGraw-Hill 1959, Table 35, M = −0.0513 q a², ν = 0.3): see `tests/shell_spr.rs`.
//!
//! SPR (O. C. Zienkiewicz, J. Z. Zhu, The superconvergent patch recovery and a posteriori error
//! estimates. Part 1: The recovery technique, IJNME 33 (1992) 1331–1364): around every interior
//! node, the patch of shells meeting there, the surface stresses at their centres — the
//! superconvergent points of the bilinear element (the mean of its 2×2 Gauss values; sampling
//! the 2×2 points instead fits a step per element and flattens the gradient: −12.9 % at the
//! 16×16 clamped edge) — are fitted by least squares with p = [1, x, y, xy] in the patch's
//! tangent plane, [1, x, y] where the bilinear term is not determined (one fit per component
//! of the global tensors on the top, mid and bottom surfaces). An interior node takes
//! its own patch's value; a node on the mesh boundary (an edge used by one shell only, or by more
//! than two) the mean of the fits of the interior patches that contain it, so that the edge
//! value is extrapolated over two elements instead of one. A boundary node in no interior patch
//! (strips one element wide) fits its own patch when that is well posed, else keeps the
//! extrapolated average. A node whose shells meet at a fold (normals more than 30° from the
//! patch mean) is treated as a boundary node: its patch is not one surface.
//!
//! Error indicator (O. C. Zienkiewicz, J. Z. Zhu, A simple error estimator and adaptive
//! procedure for practical engineering analysis, IJNME 24 (1987) 337–357): with σ* the recovered
//! nodal stresses interpolated bilinearly and σ_h the element's own, per element
//! ‖e‖²_e = ∫ t·(Δσ_mᵀ C⁻¹ Δσ_m + Δσ_bᵀ C⁻¹ Δσ_b / 3) dA (N·mm), Δσ_m, Δσ_b the membrane and
//! bending parts ((top ± bottom)/2) of σ* − σ_h in the element's plane (plane stress; the
//! transverse shear is left out), 2×2 Gauss. The global relative error is
//! η = √(Σ‖e‖²/(‖u‖² + Σ‖e‖²)) with ‖u‖² the same norm of σ_h, and the element indicator
//! ξ_e = ‖e‖_e / √((‖u‖² + Σ‖e‖²)/m) over m shells: ξ_e > η̄ marks an element to refine for a
//! target relative error η̄ (Zienkiewicz & Zhu 1987, eq. 27).

use super::error::FemError;
use super::model::{Element, Model};
use super::shell::{plane_stress, shell_geometry, transverse_shear_stiffness, Vec24, ETA, G2, XI};
use super::shell_recovery::{gauss_strains, ShellField};
use nalgebra::{Matrix3, SMatrix, Vector3};
use std::collections::HashMap;

/// Values fitted per sample: [sxx, syy, szz, sxy, syz, szx] on the top, mid and bottom surfaces.
type Sample = [f64; 18];

/// The recovered field of one displacement state.
#[derive(Debug, Clone, Default, PartialEq)]
pub struct SprField {
    /// Per node, recovered global [sxx, syy, szz, sxy, syz, szx] (MPa) on the top surface;
    /// `None` for nodes without shells.
    pub top: Vec<Option<[f64; 6]>>,
    /// As `top`, mid-surface.
    pub mid: Vec<Option<[f64; 6]>>,
    /// As `top`, bottom surface.
    pub bottom: Vec<Option<[f64; 6]>>,
    /// Per shell element (model order): (element, ‖e‖_e in √(N·mm), indicator ξ_e).
    pub elements: Vec<(usize, f64, f64)>,
    /// Global relative error η in the energy norm (0…1).
    pub relative_error: f64,
}

/// One shell's 2×2 Gauss points: global position, surface stresses, weight det J, and the
/// element axes (rows).
struct ShellSamples {
    nodes: [usize; 4],
    pos: [Vector3<f64>; 4],
    sigma: [Sample; 4],
    det: [f64; 4],
    lam: Matrix3<f64>,
    normal: Vector3<f64>,
    /// The element centre and its stresses (the mean of the Gauss-point values: the centre
    /// value on parallelograms), the superconvergent sample of the bilinear element.
    centre: Vector3<f64>,
    centre_sigma: Sample,
    t: f64,
    /// Plane-stress compliance C⁻¹, 1/MPa.
    compliance: Matrix3<f64>,
}

fn samples(model: &Model, ie: usize, u: &[[f64; 6]]) -> Option<ShellSamples> {
    let Element::Shell4(sh) = &model.elements[ie] else {
        return None;
    };
    let x = sh.nodes.map(|n| model.nodes[n]);
    let mut dg = Vec24::zeros();
    for (k, &n) in sh.nodes.iter().enumerate() {
        for i in 0..6 {
            dg[6 * k + i] = u[n][i];
        }
    }
    let g = shell_geometry(&x)?;
    let d = g.t * dg;
    let c = plane_stress(sh.material.e, sh.material.nu);
    let t = sh.t;
    let s = gauss_strains(&g.xy, t, &c, &d)?;
    let ds = transverse_shear_stiffness(t, &sh.material);
    let mut out = ShellSamples {
        nodes: sh.nodes,
        pos: [Vector3::zeros(); 4],
        sigma: [[0.0; 18]; 4],
        det: s.det,
        lam: g.lam,
        normal: g.lam.row(2).transpose(),
        centre: g.centre,
        centre_sigma: [0.0; 18],
        t,
        compliance: c.try_inverse()?,
    };
    for gp in 0..4 {
        let (xi, eta) = (XI[gp] * G2, ETA[gp] * G2);
        for (i, xn) in x.iter().enumerate() {
            let w = 0.25 * (1.0 + xi * XI[i]) * (1.0 + eta * ETA[i]);
            out.pos[gp] += Vector3::from(*xn) * w;
        }
        for (k, z) in [0.5 * t, 0.0, -0.5 * t].into_iter().enumerate() {
            let sp = c * (s.eps[gp] + s.kap[gp] * z);
            let (txz, tyz) = if k == 1 {
                (1.5 * ds / t * s.gam[gp].x, 1.5 * ds / t * s.gam[gp].y)
            } else {
                (0.0, 0.0)
            };
            let local = Matrix3::new(sp.x, sp.z, txz, sp.z, sp.y, tyz, txz, tyz, 0.0);
            let gl = g.lam.transpose() * local * g.lam;
            let v = [gl[(0, 0)], gl[(1, 1)], gl[(2, 2)], gl[(0, 1)], gl[(1, 2)], gl[(2, 0)]];
            out.sigma[gp][6 * k..6 * k + 6].copy_from_slice(&v);
        }
    }
    out.centre_sigma = std::array::from_fn(|k| out.sigma.iter().map(|s| s[k]).sum::<f64>() * 0.25);
    Some(out)
}

/// The distinct nodes of a shell (a triangle [a, b, c, c] has three).
fn distinct(nodes: &[usize; 4]) -> impl Iterator<Item = usize> + '_ {
    nodes
        .iter()
        .enumerate()
        .filter(|(k, n)| !nodes[..*k].contains(n))
        .map(|(_, &n)| n)
}

/// A least-squares fit over one patch: p = [1, x, y, xy] (or [1, x, y] when the bilinear term
/// is not determined) in the tangent plane at `centre` (normal `normal`), coordinates over the
/// patch size. `None` when even the linear fit is singular.
struct PatchFit {
    centre: Vector3<f64>,
    e1: Vector3<f64>,
    e2: Vector3<f64>,
    h: f64,
    bilinear: bool,
    coef: SMatrix<f64, 4, 18>,
}

impl PatchFit {
    fn basis(&self, x: &Vector3<f64>) -> [f64; 4] {
        let d = x - self.centre;
        let (a, b) = (d.dot(&self.e1) / self.h, d.dot(&self.e2) / self.h);
        [1.0, a, b, if self.bilinear { a * b } else { 0.0 }]
    }

    fn new(centre: Vector3<f64>, normal: Vector3<f64>, pts: &[(Vector3<f64>, &Sample)]) -> Option<PatchFit> {
        let h = pts.iter().map(|(p, _)| (p - centre).norm()).fold(0.0, f64::max);
        if h.is_nan() || h <= 0.0 {
            return None;
        }
        let trial = if normal.x.abs() < 0.9 {
            Vector3::x()
        } else {
            Vector3::y()
        };
        let e1 = (trial - normal * trial.dot(&normal)).normalize();
        let e2 = normal.cross(&e1);
        for bilinear in [true, false] {
            let mut fit = PatchFit {
                centre,
                e1,
                e2,
                h,
                bilinear,
                coef: SMatrix::zeros(),
            };
            let nb = if bilinear { 4 } else { 3 };
            let mut a = SMatrix::<f64, 4, 4>::zeros();
            let mut b = SMatrix::<f64, 4, 18>::zeros();
            for (p, s) in pts {
                let q = fit.basis(p);
                for i in 0..nb {
                    for j in 0..nb {
                        a[(i, j)] += q[i] * q[j];
                    }
                    for k in 0..18 {
                        b[(i, k)] += q[i] * s[k];
                    }
                }
            }
            if !bilinear {
                a[(3, 3)] = 1.0;
            }
            // Well posed: the smallest eigenvalue of the (scaled) normal matrix not negligible.
            let ev = a.symmetric_eigenvalues();
            let (lo, hi) = (ev.min(), ev.max());
            if lo > 1e-8 * hi {
                fit.coef = a.try_inverse()? * b;
                return Some(fit);
            }
        }
        None
    }

    fn eval(&self, x: &Vector3<f64>) -> Sample {
        let q = self.basis(x);
        std::array::from_fn(|k| (0..4).map(|i| q[i] * self.coef[(i, k)]).sum())
    }
}

/// SPR of every shell of `model` for displacements `u` (one [ux, uy, uz, rx, ry, rz] row per
/// node, mm and rad), with `averaged` (from [`super::shell_recovery::shell_field`]) as the
/// fallback of nodes no patch recovers. Empty for models without shells.
pub fn spr_field(model: &Model, u: &[[f64; 6]], averaged: &ShellField) -> Result<SprField, FemError> {
    let nn = model.nodes.len();
    let shells: Vec<ShellSamples> = (0..model.elements.len())
        .filter(|&ie| matches!(model.elements[ie], Element::Shell4(_)))
        .map(|ie| {
            samples(model, ie, u).ok_or_else(|| FemError::BadElement {
                element: ie,
                reason: "degenerate shell geometry".into(),
            })
        })
        .collect::<Result<_, _>>()?;
    let ids: Vec<usize> = (0..model.elements.len())
        .filter(|&ie| matches!(model.elements[ie], Element::Shell4(_)))
        .collect();
    if shells.is_empty() || u.len() < nn {
        return Ok(SprField::default());
    }
    // Patches and boundary nodes.
    let mut patch: Vec<Vec<usize>> = vec![Vec::new(); nn];
    let mut edges: HashMap<(usize, usize), usize> = HashMap::new();
    for (s, sh) in shells.iter().enumerate() {
        for n in distinct(&sh.nodes) {
            patch[n].push(s);
        }
        for k in 0..4 {
            let (a, b) = (sh.nodes[k], sh.nodes[(k + 1) % 4]);
            if a != b {
                *edges.entry((a.min(b), a.max(b))).or_default() += 1;
            }
        }
    }
    let mut boundary = vec![false; nn];
    for (&(a, b), &c) in &edges {
        if c != 2 {
            boundary[a] = true;
            boundary[b] = true;
        }
    }
    let normal_of = |n: usize| {
        let s: Vector3<f64> = patch[n].iter().map(|&s| shells[s].normal).sum();
        let m = s.norm();
        (m > 0.0).then(|| s / m)
    };
    let fold = 30f64.to_radians().cos();
    let sh_ref = &shells;
    let fit_of = |n: usize| -> Option<PatchFit> {
        let nrm = normal_of(n)?;
        if patch[n].iter().any(|&s| shells[s].normal.dot(&nrm) < fold) {
            return None;
        }
        let pts: Vec<(Vector3<f64>, &Sample)> = patch[n]
            .iter()
            .map(|&s| (sh_ref[s].centre, &sh_ref[s].centre_sigma))
            .collect();
        PatchFit::new(Vector3::from(model.nodes[n]), nrm, &pts)
    };
    let mut own: Vec<Option<Sample>> = vec![None; nn];
    let mut sum = vec![[0.0; 18]; nn];
    let mut count = vec![0usize; nn];
    for n in 0..nn {
        if patch[n].is_empty() || boundary[n] {
            continue;
        }
        let Some(fit) = fit_of(n) else {
            boundary[n] = true;
            continue;
        };
        own[n] = Some(fit.eval(&Vector3::from(model.nodes[n])));
        let mut around: Vec<usize> = patch[n].iter().flat_map(|&s| distinct(&shells[s].nodes)).collect();
        around.sort_unstable();
        around.dedup();
        for m in around.into_iter().filter(|&m| m != n) {
            let v = fit.eval(&Vector3::from(model.nodes[m]));
            for (a, b) in sum[m].iter_mut().zip(v) {
                *a += b;
            }
            count[m] += 1;
        }
    }
    let mut nodal: Vec<Option<Sample>> = vec![None; nn];
    for n in 0..nn {
        if patch[n].is_empty() {
            continue;
        }
        nodal[n] = if !boundary[n] {
            own[n]
        } else if count[n] > 0 {
            Some(sum[n].map(|v| v / count[n] as f64))
        } else if let Some(fit) = fit_of(n) {
            Some(fit.eval(&Vector3::from(model.nodes[n])))
        } else {
            let get = |f: &Vec<Option<[f64; 6]>>| f.get(n).copied().flatten();
            match (get(&averaged.top), get(&averaged.mid), get(&averaged.bottom)) {
                (Some(t), Some(m), Some(b)) => {
                    let mut v = [0.0; 18];
                    v[..6].copy_from_slice(&t);
                    v[6..12].copy_from_slice(&m);
                    v[12..].copy_from_slice(&b);
                    Some(v)
                }
                _ => None,
            }
        };
    }
    let mut field = SprField::default();
    for v in &nodal {
        let part = |k: usize| v.map(|v| std::array::from_fn(|i| v[6 * k + i]));
        field.top.push(part(0));
        field.mid.push(part(1));
        field.bottom.push(part(2));
    }
    // Error in the energy norm, per element and in all.
    let (mut e2, mut u2) = (Vec::with_capacity(shells.len()), 0.0);
    for sh in &shells {
        let (mut ee, mut uu) = (0.0, 0.0);
        for g in 0..4 {
            let (xi, eta) = (XI[g] * G2, ETA[g] * G2);
            let mut star = [0.0; 18];
            for (i, &n) in sh.nodes.iter().enumerate() {
                let w = 0.25 * (1.0 + xi * XI[i]) * (1.0 + eta * ETA[i]);
                if let Some(v) = nodal[n] {
                    for (a, b) in star.iter_mut().zip(v) {
                        *a += w * b;
                    }
                }
            }
            let energy = |s: &Sample| {
                let plane = |k: usize| {
                    let m = Matrix3::new(
                        s[6 * k],
                        s[6 * k + 3],
                        s[6 * k + 5],
                        s[6 * k + 3],
                        s[6 * k + 1],
                        s[6 * k + 4],
                        s[6 * k + 5],
                        s[6 * k + 4],
                        s[6 * k + 2],
                    );
                    let l = sh.lam * m * sh.lam.transpose();
                    Vector3::new(l[(0, 0)], l[(1, 1)], l[(0, 1)])
                };
                let (top, bot) = (plane(0), plane(2));
                let (sm, sb) = ((top + bot) * 0.5, (top - bot) * 0.5);
                sh.t * (sm.dot(&(sh.compliance * sm)) + sb.dot(&(sh.compliance * sb)) / 3.0)
            };
            let diff: Sample = std::array::from_fn(|k| star[k] - sh.sigma[g][k]);
            ee += energy(&diff) * sh.det[g];
            uu += energy(&sh.sigma[g]) * sh.det[g];
        }
        e2.push(ee);
        u2 += uu;
    }
    let total_e2: f64 = e2.iter().sum();
    let norm2 = u2 + total_e2;
    field.relative_error = if norm2 > 0.0 { (total_e2 / norm2).sqrt() } else { 0.0 };
    let mean = (norm2 / shells.len() as f64).sqrt();
    field.elements = ids
        .iter()
        .zip(&e2)
        .map(|(&ie, &ee)| (ie, ee.sqrt(), if mean > 0.0 { ee.sqrt() / mean } else { 0.0 }))
        .collect();
    Ok(field)
}
