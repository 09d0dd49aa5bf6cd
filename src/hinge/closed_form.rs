//! Published closed-form compliant-axis stiffnesses (N·mm/rad) of notch hinges, notch alone.
//!
//! All are Euler–Bernoulli results: M_y/θ_y of the notch clamped at one end and loaded by a
//! pure moment at the other, ignoring shear and the blanks. Notation: E Young's modulus, w
//! width, t minimum thickness, R notch radius, β = t/(2R), s = R/t.
//!
//! Derivation (circular notch). With x = R sin φ, t(φ) = t + 2R(1 − cos φ) = 2R(1 + β − cos φ),
//! dx = R cos φ dφ, the rotation compliance over the full semicircular notch is
//!
//! θ/M = ∫ 12/(E w t(x)³) dx = 3/(2 E w R²) · I₃(β),  I₃ = ∫_{−π/2}^{π/2} cos φ/(1 + β − cos φ)³ dφ.
//!
//! The half-angle substitution gives (checked symbolically)
//! I₃ = (3 + 4β + 2β²)/((1 + β)(2β + β²)²) + 6(1 + β)/(2β + β²)^{5/2} · atan √((2 + β)/β),
//! which is Paros & Weisbord's (1965) exact formula. Wu & Zhou (2002) write the same integral in
//! s = R/t as θ/M = 12/(E w R²) · f(s),
//! f = 2s³(6s² + 4s + 1)/((2s + 1)(4s + 1)²) + 12s⁴(2s + 1)/(4s + 1)^{5/2} · atan √(4s + 1).
//! For β → 0 both tend to Paros & Weisbord's simplified law θ/M = 9π√R/(2 E w t^{5/2}).
//!
//! Elliptical notch (Smith, Badami, Dale & Xu 1997; Lobontiu, *Compliant Mechanisms: Design of
//! Flexure Hinges*, 2002, ch. 2): x = a_x sin φ, t(φ) = 2a_y(β_e + 1 − cos φ), β_e = t/(2a_y),
//! so θ/M = 3 a_x/(2 E w a_y³) · I₃(β_e) — the circular result with R → a_y, stretched by a_x/a_y.
//!
//! Corner-filleted (Lobontiu, Paine, Garcia & Goldfarb 2001): straight part of length l − 2R
//! plus two quarter-circle fillets, which together form one full circular notch:
//! θ/M = 12(l − 2R)/(E w t³) + 3/(2 E w R²) · I₃(t/(2R)).
//!
//! Leaf: θ/M = 12 l/(E w t³) (exact Euler–Bernoulli).
//!
//! Turned neck of circular cross-section (diameter d(x), I = πd⁴/64), Paros & Weisbord's
//! two-axis hinge: over the full arc θ/M = ∫ 64/(Eπ d(x)⁴) dx = 4/(Eπ R³) · I₄(β) with
//! I₄ = ∫ cos φ/(1 + β − cos φ)⁴ dφ
//!    = (6β⁴ + 24β³ + 46β² + 44β + 15)/(3 q³ (1 + β)²) + 2(4β² + 8β + 5)/q^{7/2} · atan √((2 + β)/β),
//! q = 2β + β² (derived here by the same substitution); plus 64 l/(Eπ t⁴) for a straight neck
//! of length l. Small-d/R law (Paros & Weisbord 1965): θ/M = 20√R/(E t^{7/2}).
//!
//! Formulas not included: Tseytlin (2002) and Schotborgh et al. (2005) are empirical/effective
//! fits whose published coefficients could not be verified from the sources available here;
//! rather than ship an unverifiable formula, they are left out.

use std::f64::consts::PI;

/// I₃(β) = ∫_{−π/2}^{π/2} cos φ/(1 + β − cos φ)³ dφ.
pub fn i3(beta: f64) -> f64 {
    let q = 2.0 * beta + beta * beta;
    (3.0 + 4.0 * beta + 2.0 * beta * beta) / ((1.0 + beta) * q * q)
        + 6.0 * (1.0 + beta) / q.powf(2.5) * ((2.0 + beta) / beta).sqrt().atan()
}

/// I₄(β) = ∫_{−π/2}^{π/2} cos φ/(1 + β − cos φ)⁴ dφ.
pub fn i4(beta: f64) -> f64 {
    let b = beta;
    let q = 2.0 * b + b * b;
    (6.0 * b.powi(4) + 24.0 * b.powi(3) + 46.0 * b * b + 44.0 * b + 15.0)
        / (3.0 * q.powi(3) * (1.0 + b).powi(2))
        + 2.0 * (4.0 * b * b + 8.0 * b + 5.0) / q.powf(3.5) * ((2.0 + b) / b).sqrt().atan()
}

/// Paros & Weisbord (1965), exact circular notch: K = [3/(2EwR²) · I₃(t/2R)]⁻¹.
pub fn paros_weisbord_full(r: f64, t: f64, w: f64, e: f64) -> f64 {
    1.0 / (3.0 / (2.0 * e * w * r * r) * i3(t / (2.0 * r)))
}

/// Paros & Weisbord (1965), simplified for t ≪ R: K = 2 E w t^{5/2}/(9π√R).
pub fn paros_weisbord_simplified(r: f64, t: f64, w: f64, e: f64) -> f64 {
    2.0 * e * w * t.powf(2.5) / (9.0 * PI * r.sqrt())
}

/// Wu & Zhou (2002), circular notch in s = R/t: K = E w R²/(12 f(s)).
pub fn wu_zhou(r: f64, t: f64, w: f64, e: f64) -> f64 {
    let s = r / t;
    let f = 2.0 * s.powi(3) * (6.0 * s * s + 4.0 * s + 1.0) / ((2.0 * s + 1.0) * (4.0 * s + 1.0).powi(2))
        + 12.0 * s.powi(4) * (2.0 * s + 1.0) / (4.0 * s + 1.0).powf(2.5) * (4.0 * s + 1.0).sqrt().atan();
    e * w * r * r / (12.0 * f)
}

/// Smith et al. (1997) / Lobontiu (2002), elliptical notch over the full half-ellipse.
pub fn smith_lobontiu_elliptical(ax: f64, ay: f64, t: f64, w: f64, e: f64) -> f64 {
    1.0 / (3.0 * ax / (2.0 * e * w * ay.powi(3)) * i3(t / (2.0 * ay)))
}

/// Lobontiu et al. (2001), corner-filleted: straight part plus one full circular notch.
pub fn lobontiu_corner_filleted(l: f64, r: f64, t: f64, w: f64, e: f64) -> f64 {
    let straight = 12.0 * (l - 2.0 * r) / (e * w * t.powi(3));
    1.0 / (straight + 1.0 / paros_weisbord_full(r, t, w, e))
}

/// Leaf (prismatic): K = E w t³/(12 l).
pub fn leaf(l: f64, t: f64, w: f64, e: f64) -> f64 {
    e * w * t.powi(3) / (12.0 * l)
}

/// Paros & Weisbord circular-section (two-axis) hinge, exact full-arc integral plus a straight
/// neck of length l: K = [64 l/(Eπt⁴) + 4/(EπR³) I₄(t/2R)]⁻¹.
pub fn paros_weisbord_circular_section(l: f64, t: f64, r: f64, e: f64) -> f64 {
    let straight = 64.0 * l / (e * PI * t.powi(4));
    1.0 / (straight + 4.0 / (e * PI * r.powi(3)) * i4(t / (2.0 * r)))
}

/// Paros & Weisbord small-t/R law for the circular-section hinge, plus the straight neck:
/// K = [64 l/(Eπt⁴) + 20√R/(E t^{7/2})]⁻¹.
pub fn paros_weisbord_circular_section_simplified(l: f64, t: f64, r: f64, e: f64) -> f64 {
    let straight = 64.0 * l / (e * PI * t.powi(4));
    1.0 / (straight + 20.0 * r.sqrt() / (e * t.powf(3.5)))
}
