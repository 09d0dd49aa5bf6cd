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
//! * **Plane strain in the blank's spreading zone.** Beyond the notch, where load spreading
//!   ([`super::Profile::spread`]) keeps the blank's sections less than fully effective, the
//!   stressed core of the blank is as wide as the waist and held by the same material around it,
//!   so it too bends with the plane-strain modulus: E·P_b in bending and E·(1 + 0.6·(P_b − 1)) in
//!   tension, with P_b the waist's P with the section's effective thickness s(x) as its free edge
//!   layer, P_b = 1 + (1/(1 − ν²) − 1)·(1 − exp(−(w/ℓ / 3.26)^1.29))·max(0, 1 − s(x)/w), and no
//!   short-notch G (the blank's section does not change over a length comparable with itself).
//!   Where the spreading has reached the blank height the section is fully effective and takes E.
//!   **No number is fitted:** P's law and the axial share are the notch's. Until it was added the
//!   model read too soft on short wide corner-filleted leaves in tall blanks, where the spreading
//!   zone holds much of the compliance: against the converged CalculiX references of the first
//!   nine designs (tests/hinge_ccx_reference.rs), bending −3.94 … +0.54 % and axial
//!   −6.68 … −0.25 % over the 22 leaves with l/t ≤ 2.75 and w/l ≥ 4, the error growing with h/t;
//!   with it, −2.01 … +2.08 % and −3.56 … +1.36 %, every other corner-filleted hinge within
//!   −1.53 … +2.97 % and −2.46 … +1.89 %, and circular notches within −0.43 … +2.77 % and
//!   −0.96 … +3.95 % (they moved by at most +0.44 % and +0.89 %: their contour ends near the blank
//!   height, so their spreading zone is short). A tenth design, drawn and committed before this
//!   law and not compared with flexfem until it was committed, checks it.
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
/// Generic so that the tangent's dual numbers (`hinge::tangent`) take the same law.
pub fn axial_restraint<T>(p: T) -> T
where
    T: Copy + std::ops::Sub<f64, Output = T> + std::ops::Mul<f64, Output = T> + std::ops::Add<f64, Output = T>,
{
    (p - 1.0) * AXIAL_RESTRAINT_SHARE + 1.0
}

/// G = 1 + 0.068·(1 − exp(−(t/ρ)/0.15)).
fn short_notch_g(t_over_rho: f64) -> f64 {
    1.0 + 0.068 * (1.0 - (-t_over_rho / 0.15).exp())
}

/// Plane-strain stiffening P ≥ 1 of a wide waist (see the module docs); 1 for the turned neck.
pub fn plane_strain_factor(profile: &Profile, nu: f64) -> f64 {
    1.0 + plane_strain_restraint(profile, nu) * edge_share(profile.t_min(), profile.w)
}

/// P − 1 before the free edge layers are taken off, (1/(1 − ν²) − 1)·(1 − exp(−(w/ℓ/3.26)^1.29)):
/// the plane-strain stiffening of a section of nil thickness in this hinge (see the module docs);
/// 0 for the turned neck. [`plane_strain_factor`] is 1 + this × [`edge_share`] of the waist;
/// [`blank_restraint`] of a section of the blank's spreading zone.
pub fn plane_strain_restraint(profile: &Profile, nu: f64) -> f64 {
    if let Contour::SphericalNeck { .. } = profile.contour {
        return 0.0;
    }
    let z = profile.w / profile.compliant_half_length();
    (1.0 / (1.0 - nu * nu) - 1.0) * (1.0 - (-(z / 3.26).powf(1.29)).exp())
}

/// The share of a section `size` thick and `w` wide (mm) that is not in a free edge layer,
/// max(0, 1 − size/w) (see the module docs).
#[inline]
pub fn edge_share(size: f64, w: f64) -> f64 {
    (1.0 - size / w).max(0.0)
}

/// The plane-strain stiffening P_b ≥ 1 of a section of the blank's spreading zone, `size` thick
/// (its effective thickness, mm) in a hinge of [`plane_strain_restraint`] `restraint` and width
/// `w` (mm): P_b = 1 + restraint·[`edge_share`]`(size, w)` (see the module docs). 1 where the
/// section is fully effective (`size` ≥ the blank height `h`).
#[inline]
pub fn blank_restraint(restraint: f64, size: f64, w: f64, h: f64) -> f64 {
    if size < h {
        1.0 + restraint * edge_share(size, w)
    } else {
        1.0
    }
}
