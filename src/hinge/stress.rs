//! Peak stress of a hinge under a compliant-axis moment.
//!
//! Beam theory gives the nominal stress at the waist; the notch raises it by a
//! stress-concentration factor. For circular notches in flat bending we use the fit
//! K_t = (1 + t/(2ρ))^{9/20}, ρ the notch root radius, which Tian, Shirinzadeh & Zhang
//! (Precision Engineering 34 (2010) 92–100, after Pilkey's *Peterson's Stress Concentration
//! Factors*) and Chen et al. use for circular and filleted flexure hinges; the corner-filleted
//! notch takes its own law, fitted on converged CalculiX peaks ([`stress_concentration`],
//! [`stress_factor`]). Root radius:
//! R for circular notches, a_x²/a_y for the ellipse (its curvature radius
//! at the waist), R for the turned neck (the same fit applied to the groove of a round bar — an
//! approximation, noted in the result's `model`). A leaf has K_t = 1 (beam stress; the clamped
//! re-entrant corners are not modelled).

use std::f64::consts::PI;

use super::profile::{Contour, Profile};

/// Slope of the corner-filleted notch's K_t = 1 + 0.24·t/(2R) (see [`stress_concentration`]).
pub const CORNER_KT_SLOPE: f64 = 0.24;

/// Share of the waist's plane-strain stiffening P − 1 that lowers a corner-filleted notch's peak
/// von Mises stress: 1 − 0.71·(P − 1) (see [`stress_factor`]).
pub const CORNER_RESTRAINT_SHARE: f64 = 0.71;

/// Size of a corner-filleted leaf's [`root_amplification`] (its limit for a long, wide leaf with
/// sharp fillets).
pub const ROOT_AMPLIFICATION_SIZE: f64 = 0.22;
/// w/t at and below which there is no [`root_amplification`].
pub const ROOT_AMPLIFICATION_W_OVER_T: f64 = 3.4;
/// Flat length, in widths, over which the [`root_amplification`] builds up (its e-folding
/// length: 63 % at a flat of 2 w).
pub const ROOT_AMPLIFICATION_FLAT_OVER_W: f64 = 2.0;
/// R/t at and above which there is no [`root_amplification`]; it is whole at
/// [`ROOT_AMPLIFICATION_SHARP`] and below.
pub const ROOT_AMPLIFICATION_R_OVER_T: f64 = 1.12;
/// R/t at and below which the [`root_amplification`] is whole: the sharpest fillet of the
/// calibrated range (not fitted).
pub const ROOT_AMPLIFICATION_SHARP: f64 = 0.5;

/// Notch stress-concentration factor K_t (≥ 1).
///
/// Corner-filleted notch: the waist is a flat of constant thickness and the fillets are
/// shoulders (the peak sits where a fillet meets the flat, as in Peterson's stepped flat bar in
/// bending: Pilkey & Pilkey, *Peterson's Stress Concentration Factors*, 3rd ed., 2008), well
/// below the circular notch whose minimum section lies under the curvature. K_t here is the
/// narrow notch's (w/t ≤ 1, no plane-strain restraint): K_t = 1 + 0.24·t/(2R), within 1.5 % of
/// converged CalculiX peaks of 16 narrow notches (w = t, R/t 0.5–2.5, flat/t 0.5–8:
/// `tools/ccx_peak_sweep.py`). The width's effects are [`stress_factor`]'s. The earlier
/// (1 + t/(2R))^0.27, fitted with the plane-strain 1/√P over notches of every width, read those
/// narrow notches up to 3.6 % low, and the long mid-width leaves with sharp fillets up to 5.3 %
/// low on the CalculiX designs and 10.2 % low on the sweep.
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
        Contour::CornerFilleted { r, t, .. } => return 1.0 + CORNER_KT_SLOPE * t / (2.0 * r),
        Contour::SphericalNeck { t, r, .. } => return 1.0 + 0.041 * (t / r).sqrt(),
        Contour::Leaf { .. } => return 1.0,
    };
    (1.0 + t / (2.0 * rho)).powf(0.45)
}

/// Factor on the nominal beam stress at the waist giving the peak von Mises stress.
///
/// Circular and elliptical notches: K_t divided by √P, P the plane-strain factor of the waist
/// ([`super::solid_effects::plane_strain_factor`]). A waist held straight across its width
/// carries σ_y = ν σ_x inside (von Mises 0.88 σ_x) and sheds load from its free edges, so its
/// peak von Mises stress per unit moment drops below the beam value as the restraint grows;
/// 1/√P matches converged solid models within 6 % up to w/t = 20 (without it, wide notches
/// were up to 10 % conservative).
///
/// Corner-filleted notches: K_t·(1 − 0.71·(P − 1))·A, A the [`root_amplification`] of a long
/// leaf, an empirical law. Its six numbers (K_t's slope 0.24, the restraint's share 0.71 and A's
/// four) are the minimax fit over the 85 converged CalculiX peaks of
/// `tools/ccx_peak_sweep_k12.jsonl` (R/t 0.5–2.5, flat/t 0.5–20, w/t 1–20, one dimension at a
/// time around R/t = 0.5, flat/t = 5, w/t = 6; ν = 0.33) and the 224 corner-filleted geometries
/// of tests/hinge_ccx_reference.rs then compared (the 204 of its first twelve designs and the 20
/// of its first calibration): within 1.7 % of the sweep and 2.0 % of the designs, where
/// K_t^0.27/√P read −10.2 … +3.0 % and −5.3 … +3.9 %. The restraint's factor never falls below
/// 1/P (it would only for ν ≲ −0.77, far outside the fit).
pub fn stress_factor(profile: &Profile, nu: f64) -> f64 {
    let p = super::solid_effects::plane_strain_factor(profile, nu);
    match profile.contour {
        Contour::CornerFilleted { .. } => {
            let restraint = (1.0 - CORNER_RESTRAINT_SHARE * (p - 1.0)).max(1.0 / p);
            stress_concentration(profile) * restraint * root_amplification(profile)
        }
        _ => stress_concentration(profile) / p.sqrt(),
    }
}

/// The amplification A ≥ 1 of a corner-filleted leaf's peak stress where a long flat meets the
/// blank (1 for the other families), an empirical law fitted on the converged CalculiX peaks of
/// `tools/ccx_peak_sweep_k12.jsonl` (see [`stress_factor`]):
/// A = 1 + 0.22·q·s·(1 − exp(−(f/w)/2)), f the flat's length l − 2R, q = clamp((1.12 − R/t)/(1.12
/// − 0.5), 0, 1) (sharp fillets only), s = max(0, 1 − 3.4 t/w).
///
/// What it stands for (our reading of the peaks, not a derivation): far from the blank a long
/// flat bends anticlastically (κ_y = −ν κ_x); the blank holds its root straight across the
/// width, and the moment gathers towards the middle of the root, where the peak then sits.
/// Against the narrow notch's CalculiX peak at R/t = 0.5, the peaks of leaves with flats of
/// 1.3–2 w read 1.023 at w/t = 6, 1.044 at w/t = 9 and 1.060 at w/t = 14 (short notches of those
/// widths 7–9 % below it); leaves with w/t ≤ 4 stay at or below it, and rounder fillets (R/t ≥
/// 1.5) show none of the rise.
pub fn root_amplification(profile: &Profile) -> f64 {
    let Contour::CornerFilleted { l, r, t } = profile.contour else {
        return 1.0;
    };
    let sharp = ((ROOT_AMPLIFICATION_R_OVER_T - r / t) / (ROOT_AMPLIFICATION_R_OVER_T - ROOT_AMPLIFICATION_SHARP))
        .clamp(0.0, 1.0);
    let wide = (1.0 - ROOT_AMPLIFICATION_W_OVER_T * t / profile.w).max(0.0);
    let long = 1.0 - (-(l - 2.0 * r) / profile.w / ROOT_AMPLIFICATION_FLAT_OVER_W).exp();
    1.0 + ROOT_AMPLIFICATION_SIZE * sharp * wide * long
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
