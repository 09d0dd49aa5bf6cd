//! The flexibility integrals of `hinge/integrate.rs` with dual numbers: the same pieces, maps,
//! 8-point Gauss–Legendre panels and sections, each point and weight carrying its derivative.
//! The result is the exact derivative of the quadrature sum, so it agrees with the compliance
//! of [`crate::hinge::segment_compliance`] to rounding and with its difference quotients to
//! their truncation error.

use super::dual::Dual;
use super::geometry::{DContour, DProfile};
use super::pieces::DMap;
use crate::hinge::integrate::{Quadrature, PEAK};

/// 8-point Gauss–Legendre abscissae on [−1, 1] (positive half), as `hinge/integrate.rs`.
const GL8_X: [f64; 4] = [
    0.183_434_642_495_649_8,
    0.525_532_409_916_329,
    0.796_666_477_413_626_7,
    0.960_289_856_497_536_3,
];
/// 8-point Gauss–Legendre weights.
const GL8_W: [f64; 4] = [
    0.362_683_783_378_362,
    0.313_706_645_877_887_3,
    0.222_381_034_453_374_5,
    0.101_228_536_290_376_3,
];

/// The elastic constants (`hinge::integrate::Moduli`) with derivatives, MPa.
#[derive(Debug, Clone, Copy)]
pub(super) struct DModuli {
    pub e: Dual,
    pub e_bend: Dual,
    pub g: Dual,
    pub nu: Dual,
    pub notch_half: Dual,
    pub e_bend_fillet: Dual,
    pub fillet_from: Dual,
    pub e_axial: Dual,
    pub e_axial_fillet: Dual,
    /// `solid_effects::plane_strain_restraint` (the blank's spreading zone).
    pub blank_restraint: Dual,
}

/// The ten flexibility integrals with derivatives (`hinge::integrate::FlexIntegrals`).
#[derive(Debug, Clone, Copy)]
pub(super) struct DFlex {
    pub axial: Dual,
    pub shear_y: Dual,
    pub shear_z: Dual,
    pub torsion: Dual,
    pub bend: [Dual; 3],
    pub bend_off: [Dual; 3],
}

impl DFlex {
    fn zero() -> DFlex {
        let z = Dual::c(0.0);
        DFlex {
            axial: z,
            shear_y: z,
            shear_z: z,
            torsion: z,
            bend: [z; 3],
            bend_off: [z; 3],
        }
    }

    /// The compliance C = ∫BᵀDB dx (as `FlexIntegrals::compliance`) and its derivative.
    pub fn compliance(&self) -> [[Dual; 6]; 6] {
        let mut c = [[Dual::c(0.0); 6]; 6];
        c[0][0] = self.axial;
        c[1][1] = self.shear_y + self.bend_off[2];
        c[1][5] = self.bend_off[1];
        c[5][1] = self.bend_off[1];
        c[5][5] = self.bend_off[0];
        c[2][2] = self.shear_z + self.bend[2];
        c[2][4] = -self.bend[1];
        c[4][2] = -self.bend[1];
        c[4][4] = self.bend[0];
        c[3][3] = self.torsion;
        c
    }
}

fn gl8_panels(lo: Dual, hi: Dual, n: usize, f: &mut dyn FnMut(Dual, Dual)) {
    let hl = (hi - lo) / n as f64;
    for p in 0..n {
        let mid = lo + hl * (p as f64 + 0.5);
        for k in 0..4 {
            let d = hl * (0.5 * GL8_X[k]);
            let w = hl * (0.5 * GL8_W[k]);
            f(mid - d, w);
            f(mid + d, w);
        }
    }
}

/// `hinge::integrate::quadrature_points` with dual limits and map.
fn quadrature_points(a: Dual, b: Dual, map: DMap, panels: usize, f: &mut dyn FnMut(Dual, Dual)) {
    match map {
        DMap::Linear => gl8_panels(a, b, panels.max(1), f),
        DMap::Taper { origin, size0, slope } => {
            let psi_of = |x: Dual| ((x - origin) * slope / size0 + 1.0).max(Dual::c(1e-300)).ln();
            let (pa, pb) = (psi_of(a), psi_of(b));
            let (lo, hi, orient) = if pa.v <= pb.v { (pa, pb, 1.0) } else { (pb, pa, -1.0) };
            let scale = size0 / slope;
            gl8_panels(lo, hi, panels.max(1) * 2, &mut |psi, w| {
                let ex = psi.exp();
                f(origin + scale * (ex - 1.0), w * scale * ex * orient);
            });
        }
        DMap::Arc { origin, radius, c } => {
            let phi_of = |x: Dual| ((x - origin) / radius).clamp(-1.0, 1.0).asin();
            let (fa, fb) = (phi_of(a), phi_of(b));
            let split = c * PEAK;
            let n = panels.max(1);
            let orient = if fa.v <= fb.v { 1.0 } else { -1.0 };
            let (lo, hi) = if fa.v <= fb.v { (fa, fb) } else { (fb, fa) };
            let mut g = |x: Dual, w: Dual| f(x, w * orient);
            let tan_part = |p0: Dual, p1: Dual, g: &mut dyn FnMut(Dual, Dual)| {
                gl8_panels((p0 / c).atan(), (p1 / c).atan(), n, &mut |ps, w| {
                    let tp = ps.tan();
                    let phi = c * tp;
                    let x = origin + radius * phi.sin();
                    g(x, w * radius * phi.cos() * c * (1.0 + tp * tp));
                });
            };
            let phi_part = |p0: Dual, p1: Dual, g: &mut dyn FnMut(Dual, Dual)| {
                gl8_panels(p0, p1, n, &mut |phi, w| {
                    g(origin + radius * phi.sin(), w * radius * phi.cos())
                });
            };
            if hi.v <= split.v {
                tan_part(lo, hi, &mut g);
            } else if lo.v >= split.v {
                phi_part(lo, hi, &mut g);
            } else {
                tan_part(lo, split, &mut g);
                phi_part(split, hi, &mut g);
            }
        }
    }
}

/// The flexibility integrals of [x0, x1] loaded at x1 (`hinge::integrate::flex_integrals`; the
/// axial integral over the profile the axial load sees, [`DProfile::axial`]).
pub(super) fn flex_integrals(p: &DProfile, m: &DModuli, x0: Dual, x1: Dual, q: Quadrature) -> DFlex {
    let mut acc = DFlex::zero();
    let (lo, hi) = if x0.v <= x1.v { (x0, x1) } else { (x1, x0) };
    each_point(p, lo, hi, q, &mut |x, w| {
        let size = p.section_size(x);
        let s = p.section_of_size(size, m.nu);
        let (e_bend, e_axial) = moduli_at(p, m, x, size);
        acc.axial = acc.axial + w / (e_axial * s.area);
        acc.shear_y = acc.shear_y + w / (m.g * s.shear_area_bend_off);
        acc.shear_z = acc.shear_z + w / (m.g * s.shear_area_bend);
        acc.torsion = acc.torsion + w / (m.g * s.j);
        let (fb, fo) = (w / (e_bend * s.i_bend), w / (m.e * s.i_bend_off));
        let a = x1 - x;
        acc.bend[0] = acc.bend[0] + fb;
        acc.bend[1] = acc.bend[1] + fb * a;
        acc.bend[2] = acc.bend[2] + fb * a * a;
        acc.bend_off[0] = acc.bend_off[0] + fo;
        acc.bend_off[1] = acc.bend_off[1] + fo * a;
        acc.bend_off[2] = acc.bend_off[2] + fo * a * a;
    });
    if let Some(axial) = p.axial() {
        let mut sum = Dual::c(0.0);
        each_point(&axial, lo, hi, q, &mut |x, w| {
            let size = axial.section_size(x);
            // The area alone (a rectangle's w × size; the neck's clipped disk).
            let area = match axial.contour {
                DContour::SphericalNeck { .. } => axial.section_of_size(size, m.nu).area,
                _ => axial.w * size,
            };
            sum = sum + w / (moduli_at(&axial, m, x, size).1 * area);
        });
        acc.axial = sum;
    }
    acc
}

/// The compliant-axis bending and the axial modulus at x, where the effective section is `size`
/// (`Moduli::bend_axial_at`).
fn moduli_at(p: &DProfile, m: &DModuli, x: Dual, size: Dual) -> (Dual, Dual) {
    let u = x.v.abs();
    if u >= m.notch_half.v {
        // The blank's spreading zone is plane-strain restrained (`solid_effects::blank_restraint`)
        // until it is fully effective.
        if size.v < p.h.v && m.blank_restraint.v != 0.0 {
            let pb = 1.0 + m.blank_restraint * (1.0 - size / p.w).max(Dual::c(0.0));
            (m.e * pb, m.e * crate::hinge::solid_effects::axial_restraint(pb))
        } else {
            (m.e, m.e)
        }
    } else if u >= m.fillet_from.v {
        (m.e_bend_fillet, m.e_axial_fillet)
    } else {
        (m.e_bend, m.e_axial)
    }
}

/// Every quadrature point of `p`'s pieces (and their mirrors) within [lo, hi]: `f(x, weight)`
/// (`hinge::integrate::each_point`).
fn each_point(p: &DProfile, lo: Dual, hi: Dual, q: Quadrature, f: &mut dyn FnMut(Dual, Dual)) {
    for piece in p.pieces().as_slice() {
        let panels = match piece.map {
            DMap::Linear => q.linear_panels,
            DMap::Arc { .. } | DMap::Taper { .. } => q.arc_panels,
        };
        for sign in [1.0, -1.0] {
            let (pa, pb) = if sign > 0.0 {
                (piece.x0, piece.x1)
            } else {
                (-piece.x1, -piece.x0)
            };
            let (a, b) = (pa.max(lo), pb.min(hi));
            if b.v <= a.v {
                continue;
            }
            let map = match piece.map {
                DMap::Linear => DMap::Linear,
                DMap::Arc { origin, radius, c } => DMap::Arc {
                    origin: origin * sign,
                    radius: radius * sign,
                    c,
                },
                DMap::Taper { origin, size0, slope } => DMap::Taper {
                    origin: origin * sign,
                    size0,
                    slope: sign * slope,
                },
            };
            quadrature_points(a, b, map, panels, f);
        }
    }
}
