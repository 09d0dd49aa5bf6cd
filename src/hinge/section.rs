//! Cross-section properties of hinge sections (mm, mm², mm⁴, mm⁶).
//!
//! Axes: x along the hinge, z across the notch (the direction in which the notch thins the
//! blank: thickness `t(x)`, blank height `h`), y across the width `w`. The *compliant axis* is
//! y: "bend" quantities belong to bending about y (moment M_y, which thins `t`), "bend_off" to
//! bending about z (the stiff in-plane axis of a rectangular notch). For the turned neck both
//! are equal.

use std::f64::consts::PI;

/// Properties of one cross-section.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Section {
    /// Area A, mm².
    pub area: f64,
    /// Second moment about the compliant axis y, I_y = ∫z² dA, mm⁴.
    pub i_bend: f64,
    /// Second moment about the stiff axis z, I_z = ∫y² dA, mm⁴.
    pub i_bend_off: f64,
    /// Saint-Venant torsion constant J, mm⁴.
    pub j: f64,
    /// Warping constant Γ = ∫ω² dA about the shear centre, mm⁶ (0 for the disk).
    pub warping: f64,
    /// Shear area for the transverse force along z (the force that accompanies M_y), mm².
    pub shear_area_bend: f64,
    /// Shear area for the transverse force along y, mm².
    pub shear_area_bend_off: f64,
}

/// Σ_{n odd} n^{-5} = (1 − 2⁻⁵) ζ(5).
const LAMBDA5: f64 = 1.004_523_762_795_139_8;
/// Σ_{n odd} n^{-6} = (1 − 2⁻⁶) ζ(6) = π⁶/960.
const LAMBDA6: f64 = 1.001_447_077_927_100_8;
/// Σ_{n odd} n^{-7} = (1 − 2⁻⁷) ζ(7).
const LAMBDA7: f64 = 1.000_471_548_559_921_2;

/// Number of odd harmonics summed explicitly in the rectangle series (n = 1, 3, …, 2·N−1);
/// the rest is added in closed form with tanh = 1, sech = 0, which is exact to < 1e-12 there
/// because n π (long/short)/2 ≥ 20 for n ≥ 13.
const N_TERMS: usize = 7;

/// Saint-Venant torsion constant of a solid rectangle `b × c` (any order), mm⁴.
///
/// Timoshenko & Goodier, *Theory of Elasticity* (3rd ed., 1970) §109, eq. (167):
/// J = (1/3) B T³ [1 − (192/π⁵)(T/B) Σ_{n odd} tanh(nπB/(2T))/n⁵], B ≥ T.
pub fn rect_torsion_constant(b: f64, c: f64) -> f64 {
    let (long, short) = if b >= c { (b, c) } else { (c, b) };
    let r = long / short;
    let mut sum = 0.0;
    let mut partial = 0.0;
    for k in 0..N_TERMS {
        let n = (2 * k + 1) as f64;
        let n5 = n.powi(5);
        let arg = n * PI * r / 2.0;
        sum += if arg > 20.0 { 1.0 } else { arg.tanh() } / n5;
        partial += 1.0 / n5;
    }
    sum += LAMBDA5 - partial;
    long * short.powi(3) / 3.0 * (1.0 - 192.0 / PI.powi(5) / r * sum)
}

/// Warping constant Γ = ∫ω² dA of a solid rectangle `b × c`, mm⁶, from the exact Saint-Venant
/// warping function.
///
/// With half-sides a (short, along η) and d (long, along ζ), the warping function of the
/// rectangle is ω = ηζ − Σ c_n sin(k_n η) sinh(k_n ζ), k_n = nπ/(2a), n odd, with
/// c_n = 4(−1)^{(n−1)/2}/(a k_n³ cosh(k_n d)) (Timoshenko & Goodier §109: the harmonic
/// correction that restores ∂ω/∂n = ζ n_η − η n_ζ on the short sides). Integrating ω² in
/// closed form term by term (orthogonality of sin(k_n η) on (−a, a)) gives
///
/// Γ = 4a³d³/9 − Σ_{n odd} 16/(a k_n⁶) · [d (2 + sech²(k_n d)) − 3 tanh(k_n d)/k_n].
///
/// Thin limit (a ≪ d): Γ → 4a³d³/9 = B³T³/144, the narrow-rectangle value of Timoshenko & Gere,
/// *Theory of Elastic Stability* (2nd ed., 1961) §5.3. The series runs along the short side so
/// that k_n d ≥ π/2 and the terms fall as n⁻⁶.
pub fn rect_warping_constant(b: f64, c: f64) -> f64 {
    let (long, short) = if b >= c { (b, c) } else { (c, b) };
    let a = short / 2.0;
    let d = long / 2.0;
    let mut corr = 0.0;
    let mut p6 = 0.0;
    let mut p7 = 0.0;
    for k in 0..N_TERMS {
        let n = (2 * k + 1) as f64;
        let kn = n * PI / (2.0 * a);
        let arg = kn * d;
        let (th, sech2) = if arg > 20.0 {
            (1.0, 0.0)
        } else {
            let ch = arg.cosh();
            (arg.tanh(), 1.0 / (ch * ch))
        };
        corr += 16.0 / (a * kn.powi(6)) * (d * (2.0 + sech2) - 3.0 * th / kn);
        p6 += 1.0 / n.powi(6);
        p7 += 1.0 / n.powi(7);
    }
    // Tail n ≥ 2N+1 with tanh = 1, sech = 0: Σ 16/(a k⁶)(2d − 3/k).
    let k1 = PI / (2.0 * a);
    corr += 16.0 / (a * k1.powi(6)) * (2.0 * d * (LAMBDA6 - p6) - 3.0 / k1 * (LAMBDA7 - p7));
    (4.0 * a.powi(3) * d.powi(3) / 9.0 - corr).max(0.0)
}

/// Cowper's (1966) shear coefficient of a solid rectangle, κ = 10(1+ν)/(12+11ν).
pub fn cowper_rect(nu: f64) -> f64 {
    10.0 * (1.0 + nu) / (12.0 + 11.0 * nu)
}

/// Cowper's (1966) shear coefficient of a solid circle, κ = 6(1+ν)/(7+6ν).
pub fn cowper_circle(nu: f64) -> f64 {
    6.0 * (1.0 + nu) / (7.0 + 6.0 * nu)
}

/// Solid rectangle: `width` along y, `thickness` along z (the notch direction).
pub fn rectangle(width: f64, thickness: f64, nu: f64) -> Section {
    let area = width * thickness;
    let kappa = cowper_rect(nu);
    Section {
        area,
        i_bend: width * thickness.powi(3) / 12.0,
        i_bend_off: thickness * width.powi(3) / 12.0,
        j: rect_torsion_constant(width, thickness),
        warping: rect_warping_constant(width, thickness),
        shear_area_bend: kappa * area,
        shear_area_bend_off: kappa * area,
    }
}

/// J of a square of side h divided by Saint-Venant's estimate A⁴/(4π² I_p) = 6h⁴/(4π²).
fn square_j_ratio() -> f64 {
    rect_torsion_constant(1.0, 1.0) / (6.0 / (4.0 * PI * PI))
}

/// Disk of radius `r` intersected with the centred square of side `h` (turned neck in its
/// square blank).
///
/// Area and second moments are exact: the disk minus four circular segments beyond |y| = h/2
/// and |z| = h/2, which do not overlap while r < h/√2. With c = h/2 and α = acos(c/r):
/// segment area r²(α − sin 2α/2); a segment beyond z = c contributes (r⁴/2)(α/2 − sin 4α/8) to
/// ∫z²dA, one beyond y = c contributes (2/3) r⁴ (3α/8 − sin 2α/4 + sin 4α/32).
///
/// Torsion: for r ≤ h/2 the disk's polar moment (exact). For h/2 < r < h/√2 no closed form
/// exists; Saint-Venant's approximation J ≈ A⁴/(4π² I_p) is exact for the disk and 8 % high for
/// the square, so it is scaled by a factor blended linearly (in r) from 1 at r = h/2 to
/// J_square/(A⁴/(4π² I_p))_square = 0.925 at r = h/√2. J is then continuous in r and exact at
/// both ends. The shear coefficient is blended the same way between Cowper's circle and
/// rectangle values.
pub fn clipped_disk(r: f64, h: f64, nu: f64) -> Section {
    let c = h / 2.0;
    if r <= c {
        let area = PI * r * r;
        let i = PI * r.powi(4) / 4.0;
        let a_s = cowper_circle(nu) * area;
        return Section {
            area,
            i_bend: i,
            i_bend_off: i,
            j: 2.0 * i,
            warping: 0.0,
            shear_area_bend: a_s,
            shear_area_bend_off: a_s,
        };
    }
    if r >= c * std::f64::consts::SQRT_2 {
        let mut s = rectangle(h, h, nu);
        s.warping = 0.0;
        return s;
    }
    let alpha = (c / r).acos();
    let r2 = r * r;
    let r4 = r2 * r2;
    let seg_area = r2 * (alpha - (2.0 * alpha).sin() / 2.0);
    let area = PI * r2 - 4.0 * seg_area;
    let seg_perp = r4 / 2.0 * (alpha / 2.0 - (4.0 * alpha).sin() / 8.0);
    let seg_par =
        2.0 / 3.0 * r4 * (3.0 * alpha / 8.0 - (2.0 * alpha).sin() / 4.0 + (4.0 * alpha).sin() / 32.0);
    let i = PI * r4 / 4.0 - 2.0 * seg_perp - 2.0 * seg_par;
    let ip = 2.0 * i;
    let s = (r - c) / (c * (std::f64::consts::SQRT_2 - 1.0));
    let factor = 1.0 + s * (square_j_ratio() - 1.0);
    let j = factor * area.powi(4) / (4.0 * PI * PI * ip);
    let kappa = cowper_circle(nu) + s * (cowper_rect(nu) - cowper_circle(nu));
    Section {
        area,
        i_bend: i,
        i_bend_off: i,
        j,
        warping: 0.0,
        shear_area_bend: kappa * area,
        shear_area_bend_off: kappa * area,
    }
}
