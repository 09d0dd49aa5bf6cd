//! Beam cross-sections: properties (A, Iy, Iz, J, shear areas) and stress points.
//!
//! Local axes as in the case-file reference of the README: x along the beam, `Rect { w, h }` has `h` along local z and
//! `w` along local y, so `Iy = w·h³/12` (bending about y, deflection along z).
//!
//! Shear areas use Cowper's ν-dependent shear coefficients (G. R. Cowper, "The shear coefficient
//! in Timoshenko's beam theory", J. Appl. Mech. 33 (1966) 335–340, Table 1):
//! rectangle κ = 10(1+ν)/(12+11ν), solid circle κ = 6(1+ν)/(7+6ν),
//! hollow circle κ = 6(1+ν)(1+m²)² / ((7+6ν)(1+m²)² + (20+12ν)m²), m = d_in/d_out.

use crate::fem::memo::{remembered, Ring};
use std::f64::consts::PI;

/// ζ(5), Apéry-like constant used by the rectangle torsion series.
const ZETA5: f64 = 1.036_927_755_143_37;
/// Catalan's constant G = Σ (−1)ᵏ/(2k+1)².
const CATALAN: f64 = 0.915_965_594_177_219;

/// A beam cross-section (dimensions in mm).
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Section {
    /// Solid rectangle: `w` along local y, `h` along local z (mm).
    Rect { w: f64, h: f64 },
    /// Solid circle of diameter `d` (mm).
    Circle { d: f64 },
    /// Circular tube, outer and inner diameter (mm).
    Tube { d_out: f64, d_in: f64 },
    /// Given properties: area `a` (mm²), second moments `iy`, `iz` (mm⁴), torsion constant `j`
    /// (mm⁴) and optional shear areas `asy`, `asz` (mm²; `None` = no shear deformation in that
    /// plane). No stress points: stresses are not recovered for general sections.
    General {
        a: f64,
        iy: f64,
        iz: f64,
        j: f64,
        asy: Option<f64>,
        asz: Option<f64>,
    },
}

/// Section properties in local axes.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct SectionProps {
    /// Area A, mm².
    pub a: f64,
    /// Second moment about local y (∫z² dA), mm⁴ — bending in the x–z plane.
    pub iy: f64,
    /// Second moment about local z (∫y² dA), mm⁴ — bending in the x–y plane.
    pub iz: f64,
    /// Saint-Venant torsion constant J, mm⁴.
    pub j: f64,
    /// Shear area for shear force along local y (κ·A), mm²; `None` = rigid in shear.
    pub asy: Option<f64>,
    /// Shear area for shear force along local z, mm²; `None` = rigid in shear.
    pub asz: Option<f64>,
}

impl SectionProps {
    /// Axisymmetric section of area `a`, second moment `i` about every diameter (J = 2I) and
    /// shear coefficient `kappa` in both directions.
    fn round(a: f64, i: f64, kappa: f64) -> SectionProps {
        SectionProps {
            a,
            iy: i,
            iz: i,
            j: 2.0 * i,
            asy: Some(kappa * a),
            asz: Some(kappa * a),
        }
    }
}

/// A point of the cross-section where stresses are evaluated, with stress coefficients per unit
/// section force. Normal stress σ = N/A + My·z/Iy − Mz·y/Iz (from the props); shear
/// τxy = T·`t_xy` + Vy·`vy_xy`, τxz = T·`t_xz` + Vz·`vz_xz`; on round sections the transverse
/// shear is instead `round_shear`·(1 − s²)·(Vy, Vz), s = cosine between the point direction and
/// V (Jourawski for the resultant shear force, which is not linear in Vy, Vz separately).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct StressPoint {
    /// Local y coordinate, mm.
    pub y: f64,
    /// Local z coordinate, mm.
    pub z: f64,
    /// τxy per unit torque, 1/mm³.
    pub t_xy: f64,
    /// τxz per unit torque, 1/mm³.
    pub t_xz: f64,
    /// τxy per unit Vy, 1/mm².
    pub vy_xy: f64,
    /// τxz per unit Vz, 1/mm².
    pub vz_xz: f64,
    /// Round sections: neutral-axis shear per unit resultant V (V·Q/(I·b)), 1/mm²; else 0.
    pub round_shear: f64,
}

/// Rectangle torsion by the Saint-Venant series (Timoshenko & Goodier, Theory of Elasticity,
/// 3rd ed., §109, eqs. (168)–(171)), long side `a`, short side `b`.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct RectTorsion {
    /// J = β·a·b³, with β = ⅓(1 − (192/π⁵)(b/a) Σ_{n odd} tanh(nπa/2b)/n⁵), mm⁴.
    pub j: f64,
    /// β of J = β a b³.
    pub beta: f64,
    /// Shear at the middle of the long sides per unit torque (τmax = T/(α a b²)), 1/mm³:
    /// τ = Gθ′b(1 − (8/π²) Σ_{n odd} 1/(n² cosh(nπa/2b))), T = GJθ′.
    pub tau_long: f64,
    /// α of τmax = T/(α a b²).
    pub alpha: f64,
    /// Shear at the middle of the short sides per unit torque, 1/mm³:
    /// τ = Gθ′b (8/π²) Σ_{n odd} (−1)^((n−1)/2) tanh(nπa/2b)/n².
    pub tau_short: f64,
}

/// Saint-Venant torsion of an `a`×`b` rectangle (any order of sides), series summed to machine
/// precision (the slowly converging parts are summed in closed form through ζ(5) and Catalan's
/// constant; the remainders decay like e^(−nπa/b)).
pub fn rect_torsion(s1: f64, s2: f64) -> RectTorsion {
    // Designs reuse a few leg sections many times: remember the last 16 results on this
    // thread (no heap allocation).
    thread_local! {
        static MEMO: std::cell::RefCell<Ring<(u64, u64), RectTorsion, 16>> =
            const { std::cell::RefCell::new(Ring::new()) };
    }
    let Ok(out) = remembered(&MEMO, (s1.to_bits(), s2.to_bits()), || {
        Ok::<_, std::convert::Infallible>(rect_torsion_series(s1, s2))
    });
    out
}

fn rect_torsion_series(s1: f64, s2: f64) -> RectTorsion {
    let (a, b) = if s1 >= s2 { (s1, s2) } else { (s2, s1) };
    let r = a / b;
    // Σ_{n odd} tanh(nπr/2)/n⁵ = (31/32)ζ(5) − Σ_{n odd} (1 − tanh)/n⁵
    let mut s5 = 31.0 / 32.0 * ZETA5;
    let mut s_cosh = 0.0;
    let mut s_short = CATALAN;
    let mut n = 1.0_f64;
    let mut sign = 1.0;
    loop {
        let x = n * PI * r / 2.0;
        let e2 = (-2.0 * x).exp();
        let one_minus_tanh = 2.0 * e2 / (1.0 + e2);
        let sech = 2.0 * (-x).exp() / (1.0 + e2);
        s5 -= one_minus_tanh / n.powi(5);
        s_cosh += sech / (n * n);
        s_short -= sign * one_minus_tanh / (n * n);
        if sech < 1e-18 {
            break;
        }
        n += 2.0;
        sign = -sign;
    }
    let beta = (1.0 - 192.0 / PI.powi(5) / r * s5) / 3.0;
    let j = beta * a * b.powi(3);
    let tau_long = b * (1.0 - 8.0 / (PI * PI) * s_cosh) / j;
    let tau_short = b * 8.0 / (PI * PI) * s_short / j;
    RectTorsion {
        j,
        beta,
        tau_long,
        alpha: 1.0 / (tau_long * a * b * b),
        tau_short,
    }
}

impl Section {
    /// Checks dimensions; the message says what is wrong.
    pub fn validate(&self) -> Result<(), String> {
        let pos = |name: &str, v: f64| {
            (v.is_finite() && v > 0.0)
                .then_some(())
                .ok_or_else(|| format!("section {name} must be positive and finite, got {v}"))
        };
        match *self {
            Section::Rect { w, h } => {
                pos("w", w)?;
                pos("h", h)
            }
            Section::Circle { d } => pos("d", d),
            Section::Tube { d_out, d_in } => {
                pos("d_out", d_out)?;
                if !(d_in.is_finite() && d_in >= 0.0 && d_in < d_out) {
                    return Err(format!("tube d_in must satisfy 0 ≤ d_in < d_out = {d_out}, got {d_in}"));
                }
                Ok(())
            }
            Section::General { a, iy, iz, j, asy, asz } => {
                pos("A", a)?;
                pos("Iy", iy)?;
                pos("Iz", iz)?;
                pos("J", j)?;
                if let Some(v) = asy {
                    pos("Asy", v)?;
                }
                if let Some(v) = asz {
                    pos("Asz", v)?;
                }
                Ok(())
            }
        }
    }

    /// Section properties; `nu` (Poisson's ratio) enters Cowper's shear coefficients.
    pub fn properties(&self, nu: f64) -> SectionProps {
        match *self {
            Section::Rect { w, h } => {
                let a = w * h;
                let kappa = 10.0 * (1.0 + nu) / (12.0 + 11.0 * nu);
                SectionProps {
                    a,
                    iy: w * h.powi(3) / 12.0,
                    iz: h * w.powi(3) / 12.0,
                    j: rect_torsion(w, h).j,
                    asy: Some(kappa * a),
                    asz: Some(kappa * a),
                }
            }
            Section::Circle { d } => {
                let a = PI * d * d / 4.0;
                let i = PI * d.powi(4) / 64.0;
                let kappa = 6.0 * (1.0 + nu) / (7.0 + 6.0 * nu);
                SectionProps::round(a, i, kappa)
            }
            Section::Tube { d_out, d_in } => {
                let a = PI * (d_out * d_out - d_in * d_in) / 4.0;
                let i = PI * (d_out.powi(4) - d_in.powi(4)) / 64.0;
                let m2 = (d_in / d_out).powi(2);
                let p = (1.0 + m2).powi(2);
                let kappa = 6.0 * (1.0 + nu) * p / ((7.0 + 6.0 * nu) * p + (20.0 + 12.0 * nu) * m2);
                SectionProps::round(a, i, kappa)
            }
            Section::General { a, iy, iz, j, asy, asz } => SectionProps { a, iy, iz, j, asy, asz },
        }
    }

    /// True for circle and tube: their critical bending point depends on the moment direction
    /// (see [`Section::round_point`]).
    pub fn is_round(&self) -> bool {
        matches!(self, Section::Circle { .. } | Section::Tube { .. })
    }

    /// Fixed stress points (empty for [`Section::General`]). Rectangle: the four corners (peak
    /// biaxial bending) and the four mid-sides (peak torsional and transverse shear; elementary
    /// parabolic shear 3V/2A). Round sections: 36 points on the outer circumference; the exact
    /// peak-bending points are added by the recovery from the moment direction.
    pub fn stress_points(&self) -> Vec<StressPoint> {
        match *self {
            Section::Rect { w, h } => rect_stress_points(w, h).to_vec(),
            Section::Circle { .. } | Section::Tube { .. } => (0..36)
                .filter_map(|k| {
                    let phi = k as f64 * PI / 18.0;
                    self.round_point(phi.cos(), phi.sin())
                })
                .collect(),
            Section::General { .. } => Vec::new(),
        }
    }

    /// Stress point on the outer circumference of a round section in direction (cy, cz)
    /// (normalised here). Torsion τ = T·r/J tangential; transverse shear by Jourawski,
    /// τ = V·Q/(I·b) on the neutral axis (4V/3A for the solid circle) times (1 − s²) with s the
    /// normalised distance from the neutral axis of that shear force. `None` for other sections.
    pub fn round_point(&self, cy: f64, cz: f64) -> Option<StressPoint> {
        let (ro, ri) = match *self {
            Section::Circle { d } => (d / 2.0, 0.0),
            Section::Tube { d_out, d_in } => (d_out / 2.0, d_in / 2.0),
            _ => return None,
        };
        let n = (cy * cy + cz * cz).sqrt();
        if n == 0.0 || !n.is_finite() {
            return None;
        }
        let (ey, ez) = (cy / n, cz / n);
        let i = PI * (ro.powi(4) - ri.powi(4)) / 4.0;
        let j = 2.0 * i;
        let q = 2.0 * (ro.powi(3) - ri.powi(3)) / 3.0;
        let b = 2.0 * (ro - ri);
        let tau_na = q / (i * b);
        let (y, z) = (ro * ey, ro * ez);
        Some(StressPoint {
            y,
            z,
            t_xy: -z / j,
            t_xz: y / j,
            vy_xy: 0.0,
            vz_xz: 0.0,
            round_shear: tau_na,
        })
    }
}

/// [`Section::stress_points`] of a `w` × `h` rectangle, without allocating: the four corners,
/// then for s = −1, +1 the mid-points of the faces y = s·w/2 and z = s·h/2.
pub fn rect_stress_points(w: f64, h: f64) -> [StressPoint; 8] {
    let t = rect_torsion(w, h);
    // Torsional shear on the faces y = ±w/2 (length h) and z = ±h/2 (length w).
    let (tau_yface, tau_zface) = if h >= w {
        (t.tau_long, t.tau_short)
    } else {
        (t.tau_short, t.tau_long)
    };
    let a = w * h;
    let point = |y: f64, z: f64| StressPoint {
        y,
        z,
        t_xy: 0.0,
        t_xz: 0.0,
        vy_xy: 0.0,
        vz_xz: 0.0,
        round_shear: 0.0,
    };
    let corner = |sy: f64, sz: f64| point(sy * w / 2.0, sz * h / 2.0);
    let side = |s: f64| {
        // Face y = s·w/2: torsional shear along z, direction (−z, y) ⇒ +s; face z = s·h/2:
        // torsional shear along −y·s.
        [
            StressPoint {
                t_xz: s * tau_yface,
                vz_xz: 1.5 / a,
                ..point(s * w / 2.0, 0.0)
            },
            StressPoint {
                t_xy: -s * tau_zface,
                vy_xy: 1.5 / a,
                ..point(0.0, s * h / 2.0)
            },
        ]
    };
    let [n0, n1] = side(-1.0);
    let [p0, p1] = side(1.0);
    [
        corner(-1.0, -1.0),
        corner(-1.0, 1.0),
        corner(1.0, -1.0),
        corner(1.0, 1.0),
        n0,
        n1,
        p0,
        p1,
    ]
}
