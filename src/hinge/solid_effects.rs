//! Two three-dimensional effects that a beam model of a notch hinge misses, as factors on the
//! compliant-axis bending modulus of the notch region, and on its axial modulus.
//!
//! Both were measured against converged quadratic-tetrahedron solid models of the exact
//! geometry (gmsh OpenCASCADE geometry, 10-node tetrahedra, scikit-fem, rigid end faces:
//! `tools/solid_reference.py`; tests/hinge_solid_reference.rs holds the reference values), after
//! load spreading ([`super::Profile::spread`]) had been taken into account:
//!
//! * **Short notch** (ν = 0 runs, where no Poisson effect exists): even with load spreading,
//!   beam theory stays too stiff by a factor that grows with the waist thickness over the
//!   contour's curvature radius ρ at the waist and saturates:
//!   G = 1 + 0.068·(1 − exp(−(t/ρ)/0.15)) — 2.3 % at t/ρ = 1/16, 5.5 % at 1/4, 6.6 % at 1/2
//!   (circular R8…R4 notches, notch depths 0.4–1.0 R, residual ≤ 0.3 %). Plane sections do
//!   not stay plane where the thickness changes over a length comparable with itself. Applied
//!   to circular (ρ = R) and elliptical (ρ = a_x²/a_y) notches over the whole notch; to the
//!   corner-filleted hinge on its two fillet arcs only (ρ = R, t the flat's thickness): the
//!   flat keeps its thickness and bends as a beam, the missing compliance is where the
//!   thickness changes, i.e. in the fillets. No number was refitted for this: the same G, with
//!   the fillet radius as ρ. Against CalculiX models (tests/hinge_ccx_reference.rs) it took the
//!   corner-filleted bending errors of the 44 rows then known from −1.50 … +4.84 % to
//!   −3.60 … +0.13 % (applying G to the whole corner-filleted profile over-corrected every
//!   row, by −7 … −1 %). The leaf and the turned neck get none (the neck agrees with solid
//!   models within 2 % once load spreading is modelled).
//! * **Plane-strain restraint** (ν ≠ 0): a wide waist cannot take its anticlastic
//!   curvature — the blanks on both sides hold the width straight — so it bends with a modulus
//!   between E and E/(1 − ν²). The restrained share grows with the width over the compliant
//!   length ℓ (half-length over which the thickness stays below 2t, √(Rt) for a circular notch),
//!   and free edge layers of about t in all stay in plane stress:
//!   P = 1 + (1/(1 − ν²) − 1)·(1 − exp(−(w/ℓ / 3.26)^1.29))·max(0, 1 − t/w).
//!   Fitted on 20 solid models (w/ℓ 0.35–5.7, w/t 0.5–20): residual ≤ 1.1 %.
//!
//! The compliant-axis bending modulus of the notch region becomes E·P/G (corner-filleted: E·P
//! on the flat, E·P/G on the fillets).
//!
//! * **Axial.** Both effects reach the axial modulus too, which becomes E·P_a/G over the same
//!   regions, with P_a = 1 + 0.6·(P − 1): the same short-notch G (plane sections do not stay
//!   plane in tension either), and a share of the bending's plane-strain restraint (the blanks
//!   hold a wide waist's width against its Poisson contraction, but in tension the material
//!   beside the waist contracts too, so the restraint is partial). One number, the share 0.6,
//!   the minimax fit on the 94 circular and corner-filleted FIT rows of the CalculiX models
//!   (tests/hinge_ccx_reference.rs) on a 0.05 grid: axial errors −0.56 … +3.25 % (circular)
//!   and −3.23 … +1.10 % (corner-filleted), from −0.65 … +4.28 % and −4.30 … +2.43 % with E
//!   alone (narrow hinges were too stiff by the missing G, wide corner-filleted ones too soft by
//!   the missing restraint); with the full P, circular notches read up to +5.3 %.
//!
//! These are fitted laws, valid in the ranges above; they are reported in the result's `model`
//! notes.

use super::profile::{Contour, Profile};

/// Short-notch over-stiffness G ≥ 1 of beam theory (see the module docs).
pub fn short_notch_factor(profile: &Profile) -> f64 {
    let rho = match profile.contour {
        Contour::Circular { r, .. } => r,
        Contour::Elliptical { ax, ay, .. } => ax * ax / ay,
        _ => return 1.0,
    };
    short_notch_g(profile.t_min() / rho)
}

/// The short-notch factor G of the corner fillets (ρ = R), applied to the fillet arcs only;
/// 1 for the other families (see the module docs).
pub fn fillet_factor(profile: &Profile) -> f64 {
    match profile.contour {
        Contour::CornerFilleted { r, t, .. } => short_notch_g(t / r),
        _ => 1.0,
    }
}

/// |x| from which [`fillet_factor`] applies (to the notch end): the start of the corner
/// fillets, mm; the notch half-length for the other families (no fillet region).
pub fn fillet_from(profile: &Profile) -> f64 {
    match profile.contour {
        Contour::CornerFilleted { l, r, .. } => l / 2.0 - r,
        _ => profile.half_notch,
    }
}

/// Share of the plane-strain stiffening P − 1 that the axial modulus takes (see the module docs;
/// the one number fitted for the axial law).
pub const AXIAL_RESTRAINT_SHARE: f64 = 0.6;

/// The axial stiffening P_a = 1 + 0.6·(P − 1) of a waist whose bending stiffening is
/// `p` = P ([`plane_strain_factor`]; see the module docs); 1 where P is 1 (the turned neck).
pub fn axial_restraint(p: f64) -> f64 {
    1.0 + AXIAL_RESTRAINT_SHARE * (p - 1.0)
}

/// G = 1 + 0.068·(1 − exp(−(t/ρ)/0.15)).
fn short_notch_g(t_over_rho: f64) -> f64 {
    1.0 + 0.068 * (1.0 - (-t_over_rho / 0.15).exp())
}

/// Plane-strain stiffening P ≥ 1 of a wide waist (see the module docs); 1 for the turned neck.
pub fn plane_strain_factor(profile: &Profile, nu: f64) -> f64 {
    if let Contour::SphericalNeck { .. } = profile.contour {
        return 1.0;
    }
    let (w, t) = (profile.w, profile.t_min());
    let z = w / profile.compliant_half_length();
    let restrained = (1.0 - (-(z / 3.26).powf(1.29)).exp()) * (1.0 - t / w).max(0.0);
    1.0 + (1.0 / (1.0 - nu * nu) - 1.0) * restrained
}
