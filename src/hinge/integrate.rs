//! Flexibility of a variable-section Timoshenko beam by Gauss–Legendre quadrature.
//!
//! A segment [x0, x1] of the hinge is a cantilever clamped at x0 and loaded at the centre of
//! its end face x1 (through a rigid face). A load P = (F_x, F_y, F_z, M_x, M_y, M_z) at x1
//! gives the section forces at x (Castigliano / unit-load method)
//!
//! N = F_x, V_y = F_y, V_z = F_z, T = M_x, M_y(x) = M_y − (x1 − x) F_z, M_z(x) = M_z + (x1 − x) F_y,
//!
//! i.e. s(x) = B(x) P, and the complementary energy gives the exact 6×6 end compliance of the
//! variable-section Timoshenko beam
//!
//! C = ∫ Bᵀ diag(1/EA, 1/(G A_sy), 1/(G A_sz), 1/(G J), 1/(E I_y), 1/(E I_z)) B dx.
//!
//! Only ten scalar integrals are needed (∫f, ∫(x1−x)f, ∫(x1−x)²f for the two bending
//! flexibilities, and the four plain ones), accumulated in one pass over fixed-order Gauss
//! points: no allocation. This is "an exact variable-section element with numerically
//! integrated flexibility" (Neuenhofer & Filippou 1998 flexibility formulation) — exact for the
//! beam idealisation up to the quadrature error, which is < 1e-9 with the default panels (see
//! `tests/hinge_integration.rs`).

use nalgebra::Matrix6;

use super::pieces::Map;
use super::profile::{Contour, Profile, SectionMemo};

/// 8-point Gauss–Legendre abscissae on [−1, 1] (positive half).
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

/// Quadrature settings: number of equal 8-point panels per smooth piece (in the mapped
/// variable). Straight pieces of constant section are integrated exactly with one panel.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Quadrature {
    /// Panels on arc pieces.
    pub arc_panels: usize,
    /// Panels on linear pieces whose section varies (none in the present families; kept for
    /// refinement studies).
    pub linear_panels: usize,
}

impl Default for Quadrature {
    fn default() -> Self {
        Quadrature {
            arc_panels: 3,
            linear_panels: 1,
        }
    }
}

/// Elastic constants used by the integration; `e_bend` (compliant-axis bending in the notch
/// region) and `e_axial` differ from `e` by the notch's solid-model factors, and in the blank's
/// spreading zone by its plane-strain restraint ([`super::solid_effects`]).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Moduli {
    /// Young's modulus for stiff-axis bending, and for everything beyond the notch but the
    /// compliant-axis bending and axial moduli of the blank's spreading zone ([`Moduli::blank`]),
    /// MPa.
    pub e: f64,
    /// Effective modulus for compliant-axis bending, MPa.
    pub e_bend: f64,
    /// Shear modulus, MPa.
    pub g: f64,
    /// Poisson's ratio (shear coefficients).
    pub nu: f64,
    /// Include shear deformation (Timoshenko) or not (Euler–Bernoulli).
    pub shear: bool,
    /// `e_bend` applies for |x| < `notch_half` (the notch region), `e` beyond, mm.
    pub notch_half: f64,
    /// Effective modulus for compliant-axis bending on the corner fillets, MPa.
    pub e_bend_fillet: f64,
    /// `e_bend_fillet` applies for `fillet_from` ≤ |x| < `notch_half` (`notch_half`: nowhere), mm.
    pub fillet_from: f64,
    /// Effective axial modulus in the notch region (where `e_bend` applies), MPa.
    pub e_axial: f64,
    /// Effective axial modulus on the corner fillets (where `e_bend_fillet` applies), MPa.
    pub e_axial_fillet: f64,
    /// The plane-strain restraint of the blank's spreading zone
    /// ([`super::solid_effects::plane_strain_restraint`]; 0: none), with the hinge's width `w`
    /// and blank height `h` (mm) that [`super::solid_effects::blank_restraint`] takes.
    pub blank: BlankRestraint,
}

/// The plane-strain restraint of a hinge's blank beyond the notch
/// ([`super::solid_effects::blank_restraint`]).
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct BlankRestraint {
    /// [`super::solid_effects::plane_strain_restraint`] of the hinge (0: none).
    pub restraint: f64,
    /// Width, mm.
    pub w: f64,
    /// Blank height, mm.
    pub h: f64,
}

impl Moduli {
    /// The compliant-axis bending and the axial modulus at x, where the effective section is
    /// `size` thick ([`super::Profile::section_size`]), MPa.
    #[inline]
    pub fn bend_axial_at(&self, x: f64, size: f64) -> (f64, f64) {
        let u = x.abs();
        if u >= self.notch_half {
            let b = self.blank;
            if b.restraint == 0.0 {
                return (self.e, self.e);
            }
            let p = super::solid_effects::blank_restraint(b.restraint, size, b.w, b.h);
            (self.e * p, self.e * super::solid_effects::axial_restraint(p))
        } else if u >= self.fillet_from {
            (self.e_bend_fillet, self.e_axial_fillet)
        } else {
            (self.e_bend, self.e_axial)
        }
    }
}

/// The ten flexibility integrals of a segment (units: 1/N, 1/(N·mm), mm/N …).
#[derive(Debug, Clone, Copy, Default, PartialEq)]
pub struct FlexIntegrals {
    /// ∫ 1/EA.
    pub axial: f64,
    /// ∫ 1/(G A_sy).
    pub shear_y: f64,
    /// ∫ 1/(G A_sz).
    pub shear_z: f64,
    /// ∫ 1/GJ.
    pub torsion: f64,
    /// ∫ a^k/(E I_y), k = 0, 1, 2, a = x1 − x.
    pub bend: [f64; 3],
    /// ∫ a^k/(E I_z), k = 0, 1, 2.
    pub bend_off: [f64; 3],
}

impl FlexIntegrals {
    /// Assembles C = ∫BᵀDB dx (DOF order ux, uy, uz, rx, ry, rz).
    pub fn compliance(&self) -> Matrix6<f64> {
        let mut c = Matrix6::zeros();
        c[(0, 0)] = self.axial;
        c[(1, 1)] = self.shear_y + self.bend_off[2];
        c[(1, 5)] = self.bend_off[1];
        c[(5, 1)] = self.bend_off[1];
        c[(5, 5)] = self.bend_off[0];
        c[(2, 2)] = self.shear_z + self.bend[2];
        c[(2, 4)] = -self.bend[1];
        c[(4, 2)] = -self.bend[1];
        c[(4, 4)] = self.bend[0];
        c[(3, 3)] = self.torsion;
        c
    }
}

/// The 8-point Gauss–Legendre rule on `n` equal panels of [lo, hi]: calls `f(t, weight)` at
/// each point, in order of panel, then node pair (t = mid ∓ d).
#[inline]
fn gl8_panels(lo: f64, hi: f64, n: usize, mut f: impl FnMut(f64, f64)) {
    let hl = (hi - lo) / n as f64;
    for p in 0..n {
        let mid = lo + (p as f64 + 0.5) * hl;
        for k in 0..4 {
            let d = 0.5 * hl * GL8_X[k];
            let w = 0.5 * hl * GL8_W[k];
            f(mid - d, w);
            f(mid + d, w);
        }
    }
}

/// Calls `f(x, weight)` at the quadrature points of [a, b] (a < b) on a piece with `map`.
#[inline]
pub(crate) fn quadrature_points(a: f64, b: f64, map: Map, panels: usize, mut f: impl FnMut(f64, f64)) {
    match map {
        Map::Linear => {
            gl8_panels(a, b, panels.max(1), f);
        }
        Map::Taper { origin, size0, slope } => {
            // x = origin + (size0/slope)(e^ψ − 1): size = size0 e^ψ. Orientation as for arcs.
            let psi_of = |x: f64| (1.0 + slope * (x - origin) / size0).max(1e-300).ln();
            let (pa, pb) = (psi_of(a), psi_of(b));
            let (lo, hi, orient) = if pa <= pb { (pa, pb, 1.0) } else { (pb, pa, -1.0) };
            let scale = size0 / slope;
            gl8_panels(lo, hi, panels.max(1) * 2, |psi, w| {
                let ex = psi.exp();
                f(origin + scale * (ex - 1.0), orient * w * scale * ex);
            });
        }
        Map::Arc { origin, radius, c } => {
            // φ = arc angle, x = origin + radius sin φ. Near the waist (φ < PEAK·c) use
            // φ = c tan ψ; beyond, φ itself (smooth there). ∫_a^b f dx = ∫ f x'(p) dp holds for
            // either orientation of the parameter, so mirrored pieces (radius < 0) need no care.
            let phi_of = |x: f64| ((x - origin) / radius).clamp(-1.0, 1.0).asin();
            let (fa, fb) = (phi_of(a), phi_of(b));
            let split = PEAK * c;
            let n = panels.max(1);
            let tan_part = |p0: f64, p1: f64, f: &mut dyn FnMut(f64, f64)| {
                let (q0, q1) = ((p0 / c).atan(), (p1 / c).atan());
                gl8_panels(q0, q1, n, |ps, w| {
                    let tp = ps.tan();
                    let phi = c * tp;
                    let x = origin + radius * phi.sin();
                    let dxdpsi = radius * phi.cos() * c * (1.0 + tp * tp);
                    f(x, w * dxdpsi);
                });
            };
            let phi_part = |p0: f64, p1: f64, f: &mut dyn FnMut(f64, f64)| {
                gl8_panels(p0, p1, n, |phi, w| {
                    f(origin + radius * phi.sin(), w * radius * phi.cos())
                });
            };
            let (lo, hi) = if fa <= fb { (fa, fb) } else { (fb, fa) };
            // Integrate over [lo, hi] in φ, then fix the orientation sign.
            let orient = if fa <= fb { 1.0 } else { -1.0 };
            let mut g = |x: f64, wgt: f64| f(x, orient * wgt);
            if hi <= split {
                tan_part(lo, hi, &mut g);
            } else if lo >= split {
                phi_part(lo, hi, &mut g);
            } else {
                tan_part(lo, split, &mut g);
                phi_part(split, hi, &mut g);
            }
        }
    }
}

/// Arc pieces switch from the tan map to plain φ at φ = PEAK · c.
pub(crate) const PEAK: f64 = 6.0;

impl FlexIntegrals {
    /// Adds one quadrature point: `f` = weight × (1/EA, 1/(G A_sy), 1/(G A_sz), 1/GJ, 1/(E I_y),
    /// 1/(E I_z)) at the point, `a` = x1 − x its lever arm to the loaded end.
    #[inline]
    fn add(&mut self, f: &[f64; 6], a: f64, shear: bool) {
        self.axial += f[0];
        if shear {
            self.shear_y += f[1];
            self.shear_z += f[2];
        }
        self.torsion += f[3];
        let (fb, fo) = (f[4], f[5]);
        self.bend[0] += fb;
        self.bend[1] += fb * a;
        self.bend[2] += fb * a * a;
        self.bend_off[0] += fo;
        self.bend_off[1] += fo * a;
        self.bend_off[2] += fo * a * a;
    }
}

/// Flexibility integrals of the segment [x0, x1] (any order; x may be negative — the profile
/// is symmetric) loaded at x1.
pub fn flex_integrals(profile: &Profile, m: &Moduli, x0: f64, x1: f64, q: Quadrature) -> FlexIntegrals {
    integrate(profile, m, x0, x1, q, None)
}

/// The flexibility integrals of the whole profile (between its two end faces, loaded at
/// +half-length) and, from the same quadrature points, those of the notch alone (the same
/// profile with no blank, between ±`half_notch`, loaded at +`half_notch`): the notch's pieces
/// are the first pieces of the profile in the same order with the same points, so both come from
/// one evaluation of each section and equal [`flex_integrals`] of each profile bit for bit.
pub fn flex_integrals_with_notch(profile: &Profile, m: &Moduli, q: Quadrature) -> (FlexIntegrals, FlexIntegrals) {
    let half = profile.half_length();
    let mut notch = FlexIntegrals::default();
    let whole = integrate(profile, m, -half, half, q, Some(&mut notch));
    (whole, notch)
}

/// [`flex_integrals`], also accumulating the notch alone into `notch` when given
/// ([`flex_integrals_with_notch`]). The axial integral follows the profile the axial load sees
/// ([`Profile::axial`]); it differs from `profile` only beyond the notch, so the notch alone's
/// axial integral is the same either way.
fn integrate(
    profile: &Profile,
    m: &Moduli,
    x0: f64,
    x1: f64,
    q: Quadrature,
    mut notch: Option<&mut FlexIntegrals>,
) -> FlexIntegrals {
    let mut acc = FlexIntegrals::default();
    let (lo, hi) = if x0 <= x1 { (x0, x1) } else { (x1, x0) };
    let hn = profile.half_notch;
    // Blanks and prismatic parts are one section each: evaluated once.
    let mut memo = SectionMemo::new(profile, m.nu);
    // The axial profile differs from `profile` only beyond the notch: its notch part is kept.
    let axial = profile.axial();
    let mut axial_in_notch = 0.0;
    each_point(profile, lo, hi, q, |x, wgt, in_notch| {
        let size = profile.section_size(x);
        let s = memo.of_size(size);
        let (e_bend, e_axial) = m.bend_axial_at(x, size);
        let f = [
            wgt / (e_axial * s.area),
            wgt / (m.g * s.shear_area_bend_off),
            wgt / (m.g * s.shear_area_bend),
            wgt / (m.g * s.j),
            wgt / (e_bend * s.i_bend),
            wgt / (m.e * s.i_bend_off),
        ];
        acc.add(&f, x1 - x, m.shear);
        if in_notch {
            axial_in_notch += f[0];
            if let Some(n) = notch.as_deref_mut() {
                n.add(&f, hn - x, m.shear);
            }
        }
    });
    if let Some(axial) = axial {
        // Beyond the notch, the area alone (a rectangle's w × size; the neck's clipped disk).
        let mut beyond = 0.0;
        each_point(&axial, lo, hi, q, |x, wgt, in_notch| {
            if !in_notch {
                let size = axial.section_size(x);
                let area = match axial.contour {
                    Contour::SphericalNeck { .. } => super::section::clipped_disk_area(size, axial.h),
                    _ => axial.w * size,
                };
                beyond += wgt / (m.bend_axial_at(x, size).1 * area);
            }
        });
        acc.axial = axial_in_notch + beyond;
    }
    acc
}

/// Every quadrature point of `profile`'s pieces (and their mirrors) within [lo, hi]: `f(x,
/// weight, in_notch)`, `in_notch` for the points of pieces inside the notch region.
fn each_point(profile: &Profile, lo: f64, hi: f64, q: Quadrature, mut f: impl FnMut(f64, f64, bool)) {
    let hn = profile.half_notch;
    for piece in profile.pieces().as_slice() {
        let panels = match piece.map {
            Map::Linear => q.linear_panels,
            Map::Arc { .. } | Map::Taper { .. } => q.arc_panels,
        };
        let in_notch = piece.x1 <= hn;
        // Right half [piece.x0, piece.x1] and its mirror [−piece.x1, −piece.x0].
        for sign in [1.0, -1.0] {
            let (pa, pb) = if sign > 0.0 {
                (piece.x0, piece.x1)
            } else {
                (-piece.x1, -piece.x0)
            };
            let a = pa.max(lo);
            let b = pb.min(hi);
            if b > a {
                let map = match piece.map {
                    Map::Linear => Map::Linear,
                    Map::Arc { origin, radius, c } => Map::Arc {
                        origin: sign * origin,
                        radius: sign * radius,
                        c,
                    },
                    Map::Taper { origin, size0, slope } => Map::Taper {
                        origin: sign * origin,
                        size0,
                        slope: sign * slope,
                    },
                };
                quadrature_points(a, b, map, panels, |x: f64, wgt: f64| f(x, wgt, in_notch));
            }
        }
    }
}
