//! The torsional stiffness of a rectangular-section hinge as converged solid models see it: the
//! Vlasov model of [`super`] with two corrections, both measured against CalculiX C3D10 solid
//! models of the exact geometry (`tools/ccx_reference.py`, tests/hinge_ccx_reference.rs; fitted
//! on the FIT rows there, checked on the HELD_OUT rows).
//!
//! * **Plate-mode warping of a wide waist.** Vlasov's warping mode is the Saint-Venant warping
//!   function ω of the local rectangle. A waist wider than about 1.5 times its thickness is a
//!   plate strip: held against warping it bends as a Kirchhoff plate with w(x, y) = θ(x)·y, whose
//!   warping displacement is u = −z·∂w/∂x = −yz·θ′ (the thin-strip ω = −yz, Γ = w³t³/144) and
//!   whose bimoment is carried by plate bending with the plate modulus E/(1 − ν²)
//!   (Timoshenko & Woinowsky-Krieger, *Theory of Plates and Shells*, 2nd ed., 1959: Kirchhoff
//!   plate bending). The Saint-Venant Γ of the rectangle falls well below w³t³/144 when
//!   w/t is small (0.37 of it at w/t = 2, 0.77 at 4, 0.96 at 10: the free edges relieve the
//!   free warping), which is why Vlasov's model was 8–18 % too soft in torsion for
//!   w/t = 2–10 while within 3 % for w/t ≤ 1.3. The warping modulus becomes
//!   E·F, F = (1 − s) + s·(w³t³/144)/Γ_SV(w, t)/(1 − ν²), s = 1 − exp(−((w/t)/1.5)¹²),
//!   w/t at the waist: the Saint-Venant mode below w/t ≈ 1.2, the plate mode above 1.7.
//! * **Torsional load spreading** into the flanks and the blank at slope 0.55 instead of the
//!   1/2 of bending ([`crate::hinge::Profile::spread`]): the torsional shear spreads into a
//!   thickening section faster than the bending stress does.
//!
//! Three fitted numbers (1.5, 12, 0.55), fitted (worst case) on the FIT rows of the CalculiX
//! models, circular notches (t/R 0.08–0.5, w/t 0.6–10) and corner-filleted hinges (l/t 2–10,
//! R/t 0.5–2.5, w/t 1–10), and on the fitted rows of the scikit-fem models
//! (tests/hinge_solid_reference.rs), and checked on the HELD_OUT rows of both; before them the
//! torsion of those hinges was 2–18 % too soft for w/t ≥ 2. The measured bands are in tests/hinge_ccx_reference.rs and the README's
//! validation table.

use super::{vlasov_torsion_pair, vlasov_torsion_stiffness, TorsionMesh};
use crate::hinge::profile::Profile;
use crate::hinge::section::rect_warping_constant;

/// Slope of the torsional load spreading (see the module docs).
pub const TORSION_SPREAD_SLOPE: f64 = 0.55;
/// Waist w/t at which the warping mode is half plate, half Saint-Venant.
const PLATE_RATIO: f64 = 1.5;
/// Sharpness of the change of warping mode with w/t.
const PLATE_SHARPNESS: f64 = 12.0;

/// Factor F ≥ 1 (for w/t ≥ 1.3) on Young's modulus in the warping stiffness EΓ of a
/// rectangular waist `w` × `t` (mm) of Poisson's ratio `nu` (see the module docs).
pub fn warping_modulus_factor(w: f64, t: f64, nu: f64) -> f64 {
    let plate = (w * t).powi(3) / 144.0 / rect_warping_constant(w, t);
    let s = 1.0 - (-(w / t / PLATE_RATIO).powf(PLATE_SHARPNESS)).exp();
    (1.0 - s) + s * plate / (1.0 - nu * nu)
}

/// Torsional stiffness T/θ (N·mm/rad) of a rectangular-section hinge between its blank end
/// faces, `e` in MPa: the Vlasov model with plate-mode warping and torsional load spreading.
pub fn solid_torsion_stiffness(profile: &Profile, e: f64, nu: f64) -> f64 {
    let f = warping_modulus_factor(profile.w, profile.t_min(), nu);
    let g = e / (2.0 * (1.0 + nu));
    vlasov_torsion_stiffness(&profile.spread(TORSION_SPREAD_SLOPE), f * e, g, TorsionMesh::default())
}

/// [`solid_torsion_stiffness`] of a hinge in its blank and of its notch alone (`notch`: the same
/// profile with no blank), sharing one mesh ([`vlasov_torsion_pair`]).
pub fn solid_torsion_pair(profile: &Profile, notch: &Profile, e: f64, nu: f64) -> (f64, f64) {
    let f = warping_modulus_factor(profile.w, profile.t_min(), nu);
    let g = e / (2.0 * (1.0 + nu));
    vlasov_torsion_pair(
        &profile.spread(TORSION_SPREAD_SLOPE),
        &notch.spread(TORSION_SPREAD_SLOPE),
        f * e,
        g,
        TorsionMesh::default(),
    )
}
