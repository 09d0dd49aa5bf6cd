//! Peak stress of a hinge under a compliant-axis moment.
//!
//! Beam theory gives the nominal stress at the waist; the notch raises it by a
//! stress-concentration factor. For circular notches in flat bending we use the fit
//! K_t = (1 + t/(2ρ))^{9/20}, ρ the notch root radius, which Tian, Shirinzadeh & Zhang
//! (Precision Engineering 34 (2010) 92–100, after Pilkey's *Peterson's Stress Concentration
//! Factors*) and Chen et al. use for circular and filleted flexure hinges; for the
//! corner-filleted notch solid models call for a smaller exponent ([`stress_concentration`]). Root radius:
//! R for circular notches, a_x²/a_y for the ellipse (its curvature radius
//! at the waist), R for the turned neck (the same fit applied to the groove of a round bar — an
//! approximation, noted in the result's `model`). A leaf has K_t = 1 (beam stress; the clamped
//! re-entrant corners are not modelled).

use std::f64::consts::PI;

use super::profile::{Contour, Profile};

/// Exponent of the corner-filleted notch's K_t = (1 + t/(2R))^e (see [`stress_concentration`]).
pub const CORNER_KT_EXPONENT: f64 = 0.27;

/// Notch stress-concentration factor K_t (≥ 1).
///
/// Corner-filleted notch: the waist is a flat of constant thickness and the fillets are
/// shoulders (the peak sits where a fillet meets the flat, as in Peterson's stepped flat bar in
/// bending: Pilkey & Pilkey, *Peterson's Stress Concentration Factors*, 3rd ed., 2008), well
/// below the circular notch whose minimum section lies under the curvature: the same
/// form with exponent 0.27, K_t = (1 + t/(2R))^{0.27}, the minimax fit over the 44
/// corner-filleted FIT rows of tests/hinge_ccx_reference.rs against converged CalculiX peaks
/// (nodal-averaged von Mises stress, mesh sized by the fillet radius: `tools/ccx_peak_stress.py`,
/// R/t 0.5–2.5, w/t 1–20), checked on 40 rows held out of the fit. The 9/20 fit was 5–17 %
/// conservative there; the earlier exponent 1/5, fitted on peaks of meshes sized by the
/// thickness (up to 9 % low on small fillets), read the converged peaks up to 8 % low.
///
/// Flat notches: the Tian et al. fit above. Turned neck: the neck is a round bar with a
/// shoulder fillet, whose bending K_t (Peterson's stepped-shaft charts) is far below the
/// flat-notch fit once the fillet radius is comparable with the diameter; converged solid
/// models (`tools/solid_reference.py`, necks with R/t = 0.5–1.5, l/t ≥ 1) give
/// K_t = 1 + 0.041·√(t/R) within 1 % (1.035–1.058 there), where the flat-notch fit gave
/// 1.14–1.37 — 9–29 % conservative.
pub fn stress_concentration(profile: &Profile) -> f64 {
    let (t, rho) = match profile.contour {
        Contour::Circular { r, t } => (t, r),
        Contour::Elliptical { ax, ay, t } => (t, ax * ax / ay),
        Contour::CornerFilleted { r, t, .. } => return (1.0 + t / (2.0 * r)).powf(CORNER_KT_EXPONENT),
        Contour::SphericalNeck { t, r, .. } => return 1.0 + 0.041 * (t / r).sqrt(),
        Contour::Leaf { .. } => return 1.0,
    };
    (1.0 + t / (2.0 * rho)).powf(0.45)
}

/// Factor on the nominal beam stress at the waist giving the peak von Mises stress: K_t,
/// divided for flat notches by √P, P the plane-strain factor of the waist
/// ([`super::solid_effects::plane_strain_factor`]). A waist held straight across its width
/// carries σ_y = ν σ_x inside (von Mises 0.88 σ_x) and sheds load from its free edges, so its
/// peak von Mises stress per unit moment drops below the beam value as the restraint grows;
/// 1/√P matches converged solid models within 6 % up to w/t = 20 (without it, wide notches
/// were up to 10 % conservative).
pub fn stress_factor(profile: &Profile, nu: f64) -> f64 {
    stress_concentration(profile) / super::solid_effects::plane_strain_factor(profile, nu).sqrt()
}

/// Nominal (beam) peak bending stress at the waist per unit compliant-axis moment, MPa/(N·mm):
/// 6/(w t²) for rectangles, 32/(π t³) for the turned neck (diameter t).
pub fn nominal_stress_per_moment(profile: &Profile) -> f64 {
    let t = profile.t_min();
    match profile.contour {
        Contour::SphericalNeck { .. } => 32.0 / (PI * t.powi(3)),
        _ => 6.0 / (profile.w * t * t),
    }
}
