//! Analytic derivatives of a hinge's compliance with respect to its dimensions and material.
//!
//! The hinge compliance C = ∫ Bᵀ D(x) B dx ([`super::integrate`]) depends on the dimensions
//! (t, R, a_x, a_y, l, w, h, blank length) through the section properties in the integrand,
//! through the integration limits and piece breakpoints (notch half-length, fillet ends, load
//! spreading start and reach: the Leibniz terms), through the quadrature maps, and through the
//! solid-calibration factors on the compliant-axis bending modulus (short-notch factor G and
//! plane-strain factor P with its compliant half-length). All of it is differentiated in
//! forward mode: every number of the quadrature is a [`dual::Dual`] carrying its derivative
//! along a [`Tangent`], so the result is the exact derivative of the same quadrature sum the
//! compliance is (no difference quotient). `tests/hinge_compliance_derivatives.rs` checks it
//! against high-order central differences of [`super::segment_compliance`] for every family.
//!
//! One entry is not differentiated here: the warping-restrained (Vlasov) torsion compliance
//! 1/k_torsion of rectangular families, which comes from a finite-element solve
//! ([`super::torsion`]); its derivative is given by the caller
//! ([`vlasov_compliance_derivative`] differences the solve along the tangent). The turned
//! neck's torsion is the integral ∫1/GJ, differentiated with the rest.
//!
//! Units: a derivative is in the units of the compliance entry (mm/N, 1/N, rad/(N·mm)) per
//! unit step along the tangent.

pub mod dual;
mod geometry;
mod integrate;
mod pieces;
mod section;

use super::integrate::Quadrature;
use super::profile::{Contour, Profile};
use super::Stiffness;
use crate::material::Material;
use dual::Dual;
use geometry::DProfile;
use integrate::DModuli;
use nalgebra::Matrix6;

/// A direction in which a hinge moves: the derivative of each dimension (mm per unit step;
/// `contour` of the profile's family holding the derivatives of its dimensions) and of the
/// material's E (MPa) and ν.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Tangent {
    /// d(contour dimensions), same family as the profile's contour.
    pub contour: Contour,
    /// dw.
    pub w: f64,
    /// dh.
    pub h: f64,
    /// d(blank length per side).
    pub blank: f64,
    /// dE, MPa.
    pub e: f64,
    /// dν.
    pub nu: f64,
}

impl Tangent {
    /// The zero tangent of `contour`'s family.
    pub fn zero(contour: &Contour) -> Tangent {
        let mut c = *contour;
        for key in ["R", "t", "l", "ax", "ay"] {
            if let Some(v) = c.number_mut(key) {
                *v = 0.0;
            }
        }
        Tangent {
            contour: c,
            w: 0.0,
            h: 0.0,
            blank: 0.0,
            e: 0.0,
            nu: 0.0,
        }
    }

    /// The tangent that takes `(a, ma)` to `(b, mb)` in a step `step`: (b − a)/step for every
    /// dimension and material constant (exact when both lie on a straight path, as the numbers
    /// of a case moved along a parameter do). `None` when the families differ.
    pub fn between(a: (&Profile, &Material), b: (&Profile, &Material), step: f64) -> Option<Tangent> {
        let d = |x: f64, y: f64| (y - x) / step;
        let mut c = a.0.contour;
        let mut other = b.0.contour;
        if std::mem::discriminant(&c) != std::mem::discriminant(&other) {
            return None;
        }
        for key in ["R", "t", "l", "ax", "ay"] {
            if let (Some(x), Some(y)) = (c.number_mut(key), other.number_mut(key)) {
                *x = d(*x, *y);
            }
        }
        Some(Tangent {
            contour: c,
            w: d(a.0.w, b.0.w),
            h: d(a.0.h, b.0.h),
            blank: d(a.0.blank, b.0.blank),
            e: d(a.1.e, b.1.e),
            nu: d(a.1.nu, b.1.nu),
        })
    }

    /// Whether every derivative is zero (the hinge does not move).
    pub fn is_zero(&self) -> bool {
        *self == Tangent::zero(&self.contour)
    }
}

/// The derivative of the notch half-length (`Profile::half_notch`) along `tangent`, mm per step.
pub fn half_notch_derivative(profile: &Profile, tangent: &Tangent) -> f64 {
    DProfile::new(profile, tangent).half_notch.d
}

/// The moduli of `hinge::moduli` (solid-calibration factors included) along the tangent.
fn moduli(p: &DProfile, profile: &Profile, m: &Material, tg: &Tangent) -> DModuli {
    let e = Dual::new(m.e, tg.e);
    let nu = Dual::new(m.nu, tg.nu);
    let restraint = p.plane_strain_restraint(nu, profile.compliant_half_length());
    let (ps, g, gf) = (
        p.plane_strain_factor(nu, profile.compliant_half_length()),
        p.short_notch_factor(),
        p.fillet_factor(),
    );
    let factor = ps / g;
    let axial = super::solid_effects::axial_restraint(ps) / g;
    DModuli {
        e,
        e_bend: e * factor,
        g: e / ((nu + 1.0) * 2.0),
        nu,
        notch_half: p.half_notch,
        e_bend_fillet: e * factor / gf,
        fillet_from: p.fillet_from(),
        e_axial: e * axial,
        e_axial_fillet: e * axial / gf,
        blank_restraint: restraint,
    }
}

/// The Timoshenko compliance (Saint-Venant torsion) of the segment [x0, x1] of `profile`, as
/// [`super::segment_compliance`], and its derivative along `tangent`; the limits move with
/// derivatives `x0.1`, `x1.1` (mm per step). Returns (C, dC).
pub fn segment_compliance_derivative(
    profile: &Profile,
    material: &Material,
    tangent: &Tangent,
    x0: (f64, f64),
    x1: (f64, f64),
) -> (Matrix6<f64>, Matrix6<f64>) {
    let p = DProfile::new(profile, tangent);
    let m = moduli(&p, profile, material, tangent);
    let f = integrate::flex_integrals(
        &p,
        &m,
        Dual::new(x0.0, x0.1),
        Dual::new(x1.0, x1.1),
        Quadrature::default(),
    );
    let c = f.compliance();
    (Matrix6::from_fn(|i, j| c[i][j].v), Matrix6::from_fn(|i, j| c[i][j].d))
}

/// The derivative of the warping-restrained torsion compliance 1/k_torsion of a rectangular
/// profile along `tangent`, rad/(N·mm) per step, by the fourth-order central difference
/// [1, −8, 8, −1]/(12 δ) of the Vlasov solve ([`super::torsion`]) at δ = `step` (the solve is a
/// finite-element model whose mesh follows the dimensions; not differentiated analytically).
/// `None` for the turned neck (its torsion is the integral) or when a moved profile is invalid.
pub fn vlasov_compliance_derivative(
    profile: &Profile,
    material: &Material,
    tangent: &Tangent,
    step: f64,
) -> Option<f64> {
    if let Contour::SphericalNeck { .. } = profile.contour {
        return None;
    }
    let mut sum = 0.0;
    for (s, w) in [(-2.0, 1.0), (-1.0, -8.0), (1.0, 8.0), (2.0, -1.0)] {
        let mut c = profile.contour;
        let mut dc = tangent.contour;
        for key in ["R", "t", "l", "ax", "ay"] {
            if let (Some(x), Some(dx)) = (c.number_mut(key), dc.number_mut(key)) {
                *x += s * step * *dx;
            }
        }
        let moved = Profile::rectangular(
            c,
            profile.w + s * step * tangent.w,
            profile.h + s * step * tangent.h,
            profile.blank + s * step * tangent.blank,
        )
        .ok()?;
        // The same ends as the profile (a rigid-faced hinge keeps its end-face term).
        let moved = Profile {
            end_faces: profile.end_faces,
            ..moved
        };
        let e = material.e + s * step * tangent.e;
        let nu = material.nu + s * step * tangent.nu;
        let k = super::torsion::solid_torsion_stiffness(&moved, e, nu);
        sum += w / k;
    }
    Some(sum / (12.0 * step))
}

/// The derivatives of the compliances of a hinge region modelled as `segments` flexibility
/// elements over equal lengths ([`super::chain_compliances`]; one element: the region's
/// compliance `single.compliance`), along `tangent`. `torsion` is the derivative of the single
/// element's torsion compliance `single.compliance[3][3]` for a rectangular family (Vlasov,
/// see [`vlasov_compliance_derivative`]); the neck's comes from the integral (`torsion`
/// ignored).
pub fn region_compliance_derivatives(
    profile: &Profile,
    material: &Material,
    single: &Stiffness,
    tangent: &Tangent,
    torsion: f64,
    segments: usize,
) -> Vec<[[f64; 6]; 6]> {
    let p = DProfile::new(profile, tangent);
    let m = moduli(&p, profile, material, tangent);
    let q = Quadrature::default();
    let half = p.half_length();
    let neck = matches!(profile.contour, Contour::SphericalNeck { .. });
    let to_array = |c: &[[Dual; 6]; 6]| c.map(|row| row.map(|x| x.d));
    // The whole region: the single element, or the neck's torsion compliance of a chain.
    let whole = (segments <= 1 || neck).then(|| integrate::flex_integrals(&p, &m, -half, half, q).compliance());
    let d_single33 = match &whole {
        Some(c) if neck => c[3][3].d,
        _ => torsion,
    };
    if let (Some(c), true) = (&whole, segments <= 1) {
        let mut out = to_array(c);
        out[3][3] = d_single33;
        return vec![out];
    }
    let n = segments as f64;
    let cs: Vec<[[Dual; 6]; 6]> = (0..segments)
        .map(|k| {
            let x0 = -half + half * (2.0 * k as f64 / n);
            let x1 = -half + half * (2.0 * (k + 1) as f64 / n);
            integrate::flex_integrals(&p, &m, x0, x1, q).compliance()
        })
        .collect();
    // The chain keeps the single element's torsion compliance: c₃₃ₖ = sₖ · S, S = c₃₃/Σ sⱼ.
    let sv = cs.iter().fold(Dual::c(0.0), |a, c| a + c[3][3]);
    let scale = Dual::new(single.compliance[3][3], d_single33) / sv;
    cs.iter()
        .map(|c| {
            let mut out = to_array(c);
            out[3][3] = (c[3][3] * scale).d;
            out
        })
        .collect()
}
