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
pub(crate) const LAMBDA5: f64 = 1.004_523_762_795_139_8;
/// Σ_{n odd} n^{-6} = (1 − 2⁻⁶) ζ(6) = π⁶/960.
const LAMBDA6: f64 = 1.001_447_077_927_100_8;
/// Σ_{n odd} n^{-7} = (1 − 2⁻⁷) ζ(7).
const LAMBDA7: f64 = 1.000_471_548_559_921_2;

/// 1/n⁵, 1/n⁶, 1/n⁷ for n = 1, 3, …, 13.
pub(crate) const INV_N5: [f64; 7] = inv_odd_powers(5);
const INV_N6: [f64; 7] = inv_odd_powers(6);
const INV_N7: [f64; 7] = inv_odd_powers(7);

const fn inv_odd_powers(p: u32) -> [f64; 7] {
    let mut out = [0.0; 7];
    let mut k = 0;
    while k < 7 {
        let n = (2 * k + 1) as f64;
        let mut np = 1.0;
        let mut i = 0;
        while i < p {
            np *= n;
            i += 1;
        }
        out[k] = 1.0 / np;
        k += 1;
    }
    out
}

/// The Saint-Venant series of a solid rectangle in closed form but for exponentially small
/// corrections, both from one `exp`.
///
/// Both series of the rectangle (torsion constant and warping constant) need tanh(n x) and
/// sech²(n x) for odd n, x = π r/2, r = long/short ≥ 1. With q = e^{−2x} = e^{−π r} ≤ e^{−π}
/// = 0.0432 they are 1 − tanh(n x) = 2qⁿ/(1 + qⁿ) and sech²(n x) = 4qⁿ/(1 + qⁿ)², so every
/// term comes from powers of one exponential instead of a `tanh`/`cosh` per term, and the sums
/// split into their all-tanh-equal-1 limits (the constants λ₅, λ₆, λ₇) plus
///
/// e = Σ_{n odd} (1 − tanh n x)/n⁵,  s₆ = Σ sech²(n x)/n⁶,  e₇ = Σ (1 − tanh n x)/n⁷.
///
/// Truncation bound: the terms stop once qⁿ < 1e−18; everything left is below
/// Σ_{m ≥ n} 4qᵐ ≤ 4qⁿ/(1 − q²) < 4.1e−18, under a twentieth of an ulp of the sums' leading
/// terms (≥ 1, resp. the λ's), so the series are exact to double rounding. For r ≥ 12.8
/// (π r > 40) already q < 1e−17 and no `exp` is taken at all.
#[derive(Debug, Clone, Copy)]
struct RectSeries {
    /// Σ (1 − tanh n x)/n⁵.
    e5: f64,
    /// Σ sech²(n x)/n⁶.
    s6: f64,
    /// Σ (1 − tanh n x)/n⁷.
    e7: f64,
}

impl RectSeries {
    fn new(r: f64) -> Self {
        let mut out = RectSeries {
            e5: 0.0,
            s6: 0.0,
            e7: 0.0,
        };
        let arg = PI * r;
        if arg > 40.0 {
            return out;
        }
        let q = (-arg).exp();
        let q2 = q * q;
        let mut qn = q;
        // qⁿ ≤ e^{−π n} < 1e−18 for n ≥ 15: at most the 7 terms n = 1, 3, …, 13.
        for k in 0..7 {
            if qn < 1e-18 {
                break;
            }
            let inv = 1.0 / (1.0 + qn);
            let e = 2.0 * qn * inv;
            out.e5 += e * INV_N5[k];
            out.s6 += 2.0 * e * inv * INV_N6[k];
            out.e7 += e * INV_N7[k];
            qn *= q2;
        }
        out
    }
}

/// Long and short side of a `b × c` rectangle.
fn long_short(b: f64, c: f64) -> (f64, f64) {
    if b >= c {
        (b, c)
    } else {
        (c, b)
    }
}

/// 64/π⁵.
pub(crate) const C_J: f64 = 64.0 / (PI * PI * PI * PI * PI);
/// 32/π⁶.
const C_GAMMA: f64 = 32.0 / (PI * PI * PI * PI * PI * PI);
/// 3/π.
const C_K: f64 = 3.0 / PI;

/// J from the sides (long ≥ short) and the series (see [`rect_torsion_constant`]):
/// (1/3) B T³ − (64/π⁵) T⁴ Σ tanh/n⁵, the series' prefactor (192/π⁵)(T/B) multiplied out.
fn torsion_from(long: f64, short: f64, s: &RectSeries) -> f64 {
    let s3 = short * short * short;
    long * s3 / 3.0 - C_J * (s3 * short) * (LAMBDA5 - s.e5)
}

/// Γ from the sides (long ≥ short) and the series (see [`rect_warping_constant`]): with
/// a = T/2, d = B/2, k₁ = π/T, 16/(a k₁⁶) = 32 T⁵/π⁶ and 1/k₁ = T/π multiplied out.
fn warping_from(long: f64, short: f64, s: &RectSeries) -> f64 {
    let d = long / 2.0;
    let s2 = short * short;
    let s5 = s2 * s2 * short;
    // Σ_{n odd} [d (2 + sech²) − 3 tanh/k_n]/n⁶ with tanh = 1 − (1 − tanh).
    let sum = d * (2.0 * LAMBDA6 + s.s6) - C_K * short * (LAMBDA7 - s.e7);
    let corr = C_GAMMA * s5 * sum;
    let l3 = long * long * long;
    ((s2 * short) * l3 / 144.0 - corr).max(0.0)
}

/// Saint-Venant torsion constant of a solid rectangle `b × c` (any order), mm⁴.
///
/// Timoshenko & Goodier, *Theory of Elasticity* (3rd ed., 1970) §109, eq. (167):
/// J = (1/3) B T³ [1 − (192/π⁵)(T/B) Σ_{n odd} tanh(nπB/(2T))/n⁵], B ≥ T; the series is summed
/// as λ₅ − Σ (1 − tanh)/n⁵ from one exponential, exact to double rounding (`RectSeries`).
pub fn rect_torsion_constant(b: f64, c: f64) -> f64 {
    let (long, short) = long_short(b, c);
    torsion_from(long, short, &RectSeries::new(long / short))
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
/// that k_n d ≥ π/2 and the terms fall as n⁻⁶; it is summed as λ₆, λ₇ plus exponentially small
/// corrections from one exponential, exact to double rounding (`RectSeries`).
pub fn rect_warping_constant(b: f64, c: f64) -> f64 {
    let (long, short) = long_short(b, c);
    warping_from(long, short, &RectSeries::new(long / short))
}

/// Torsion and warping constants (J mm⁴, Γ mm⁶) of a solid rectangle `b × c` together: one
/// exponential for both ([`rect_torsion_constant`], [`rect_warping_constant`]).
pub fn rect_torsion_warping(b: f64, c: f64) -> (f64, f64) {
    let (long, short) = long_short(b, c);
    let s = RectSeries::new(long / short);
    (torsion_from(long, short, &s), warping_from(long, short, &s))
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
    let (j, warping) = rect_torsion_warping(width, thickness);
    Section {
        area,
        i_bend: width * (thickness * thickness * thickness) / 12.0,
        i_bend_off: thickness * (width * width * width) / 12.0,
        j,
        warping,
        shear_area_bend: kappa * area,
        shear_area_bend_off: kappa * area,
    }
}

/// J of a square of side h divided by Saint-Venant's estimate A⁴/(4π² I_p) = 6h⁴/(4π²)
/// (computed once).
pub(crate) fn square_j_ratio() -> f64 {
    static RATIO: std::sync::OnceLock<f64> = std::sync::OnceLock::new();
    *RATIO.get_or_init(|| rect_torsion_constant(1.0, 1.0) / (6.0 / (4.0 * PI * PI)))
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
    clipped_disk_full(r, h, nu)
}

/// The area of [`clipped_disk`] alone, mm² (the axial integral needs no more).
pub fn clipped_disk_area(r: f64, h: f64) -> f64 {
    let c = h / 2.0;
    if r <= c {
        PI * r * r
    } else if r >= c * std::f64::consts::SQRT_2 {
        h * h
    } else {
        // The same operations as `clipped_disk_full`, so the same bits.
        let alpha = (c / r).acos();
        let r2 = r * r;
        let seg_area = r2 * (alpha - (2.0 * alpha).sin() / 2.0);
        PI * r2 - 4.0 * seg_area
    }
}

fn clipped_disk_full(r: f64, h: f64, nu: f64) -> Section {
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
    let seg_par = 2.0 / 3.0 * r4 * (3.0 * alpha / 8.0 - (2.0 * alpha).sin() / 4.0 + (4.0 * alpha).sin() / 32.0);
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

#[cfg(test)]
mod tests {
    use super::*;

    /// [`clipped_disk_area`] is [`clipped_disk`]'s area, bit for bit, for radii from inside the
    /// square (a whole disk) through the clipped range to beyond its corners (the square).
    #[test]
    fn clipped_disk_area_is_the_sections_area() {
        let h = 10.0;
        for k in 1..=40 {
            let r = 0.2 * k as f64;
            let full = clipped_disk(r, h, 0.3).area;
            assert_eq!(clipped_disk_area(r, h), full, "r = {r}");
        }
    }
}
