//! The section properties of `hinge/section.rs` the flexibility integrals use (area, second
//! moments, Saint-Venant J, shear areas), with dual dimensions, and the solid-calibration
//! factors of `hinge/solid_effects.rs` (the compliant half-length by implicit differentiation
//! of its bisection).

use super::dual::Dual;
use super::geometry::{DContour, DProfile};
use crate::hinge::section::{cowper_circle, cowper_rect, square_j_ratio, C_J, INV_N5, LAMBDA5};
use std::f64::consts::PI;

/// The section properties of the flexibility integrals, mm², mm⁴.
#[derive(Debug, Clone, Copy)]
pub(super) struct DSection {
    pub area: Dual,
    pub i_bend: Dual,
    pub i_bend_off: Dual,
    pub j: Dual,
    pub shear_area_bend: Dual,
    pub shear_area_bend_off: Dual,
}

/// Saint-Venant J of a solid rectangle (`section::rect_torsion_constant`).
fn rect_j(b: Dual, c: Dual) -> Dual {
    let (long, short) = if b.v >= c.v { (b, c) } else { (c, b) };
    let arg = long / short * PI;
    let mut e5 = Dual::c(0.0);
    if arg.v <= 40.0 {
        let q = (-arg).exp();
        let q2 = q * q;
        let mut qn = q;
        for inv_n5 in INV_N5 {
            if qn.v < 1e-18 {
                break;
            }
            e5 = e5 + qn * 2.0 / (1.0 + qn) * inv_n5;
            qn = qn * q2;
        }
    }
    let s3 = short * short * short;
    long * s3 / 3.0 - s3 * short * C_J * (LAMBDA5 - e5)
}

/// `section::rectangle`.
fn rectangle(w: Dual, t: Dual, kappa: Dual) -> DSection {
    let area = w * t;
    DSection {
        area,
        i_bend: w * t * t * t / 12.0,
        i_bend_off: t * w * w * w / 12.0,
        j: rect_j(w, t),
        shear_area_bend: kappa * area,
        shear_area_bend_off: kappa * area,
    }
}

/// `section::clipped_disk`.
fn clipped_disk(r: Dual, h: Dual, nu: Dual) -> DSection {
    let c = h / 2.0;
    if r.v <= c.v {
        let area = r * r * PI;
        let i = r * r * r * r * (PI / 4.0);
        let a_s = kappa_circle(nu) * area;
        return DSection {
            area,
            i_bend: i,
            i_bend_off: i,
            j: i * 2.0,
            shear_area_bend: a_s,
            shear_area_bend_off: a_s,
        };
    }
    if r.v >= c.v * std::f64::consts::SQRT_2 {
        return rectangle(h, h, kappa_rect(nu));
    }
    let alpha = (c / r).acos();
    let r2 = r * r;
    let r4 = r2 * r2;
    let seg_area = r2 * (alpha - (alpha * 2.0).sin() / 2.0);
    let area = r2 * PI - seg_area * 4.0;
    let seg_perp = r4 / 2.0 * (alpha / 2.0 - (alpha * 4.0).sin() / 8.0);
    let seg_par = r4 * (2.0 / 3.0) * (alpha * (3.0 / 8.0) - (alpha * 2.0).sin() / 4.0 + (alpha * 4.0).sin() / 32.0);
    let i = r4 * (PI / 4.0) - seg_perp * 2.0 - seg_par * 2.0;
    let ip = i * 2.0;
    let s = (r - c) / (c * (std::f64::consts::SQRT_2 - 1.0));
    let factor = 1.0 + s * (square_j_ratio() - 1.0);
    let a2 = area * area;
    let j = factor * a2 * a2 / (ip * (4.0 * PI * PI));
    let kappa = kappa_circle(nu) + s * (kappa_rect(nu) - kappa_circle(nu));
    DSection {
        area,
        i_bend: i,
        i_bend_off: i,
        j,
        shear_area_bend: kappa * area,
        shear_area_bend_off: kappa * area,
    }
}

/// Cowper's rectangle coefficient 10(1+ν)/(12+11ν) (`section::cowper_rect`), differentiated.
fn kappa_rect(nu: Dual) -> Dual {
    let k = (nu + 1.0) * 10.0 / (nu * 11.0 + 12.0);
    debug_assert!((k.v - cowper_rect(nu.v)).abs() <= 1e-15);
    k
}

/// Cowper's circle coefficient 6(1+ν)/(7+6ν) (`section::cowper_circle`), differentiated.
fn kappa_circle(nu: Dual) -> Dual {
    let k = (nu + 1.0) * 6.0 / (nu * 6.0 + 7.0);
    debug_assert!((k.v - cowper_circle(nu.v)).abs() <= 1e-15);
    k
}

impl DProfile {
    /// The effective section of the given size (`Profile::section_of_size`).
    pub fn section_of_size(&self, size: Dual, nu: Dual) -> DSection {
        match self.contour {
            DContour::SphericalNeck { .. } => clipped_disk(size, self.h, nu),
            _ => rectangle(self.w, size, kappa_rect(nu)),
        }
    }

    /// `Profile::compliant_half_length`: the bisection's root u* of t(u) = 2 t_min moves as
    /// du* = −(∂t/∂σ − 2 dt_min)/(∂t/∂u) (implicit function theorem).
    fn compliant_half_length(&self, value: f64) -> Dual {
        let hn = self.half_notch;
        if (value - hn.v).abs() <= 0.0 {
            return hn;
        }
        let target = self.t_min() * 2.0;
        let moved = self.thickness(Dual::c(value));
        let fixed = self.frozen().thickness(Dual::new(value, 1.0));
        Dual::new(value, -(moved.d - target.d) / fixed.d)
    }

    /// The same profile with zero derivatives.
    fn frozen(&self) -> DProfile {
        let z = |x: Dual| Dual::c(x.v);
        let contour = match self.contour {
            DContour::Circular { r, t } => DContour::Circular { r: z(r), t: z(t) },
            DContour::Elliptical { ax, ay, t } => DContour::Elliptical {
                ax: z(ax),
                ay: z(ay),
                t: z(t),
            },
            DContour::CornerFilleted { l, r, t } => DContour::CornerFilleted {
                l: z(l),
                r: z(r),
                t: z(t),
            },
            DContour::Leaf { l, t } => DContour::Leaf { l: z(l), t: z(t) },
            DContour::SphericalNeck { l, t, r } => DContour::SphericalNeck {
                l: z(l),
                t: z(t),
                r: z(r),
            },
        };
        DProfile {
            contour,
            w: z(self.w),
            h: z(self.h),
            blank: z(self.blank),
            half_notch: z(self.half_notch),
            spread: self.spread.map(|(a, b)| (z(a), z(b))),
            blank_slope: self.blank_slope,
        }
    }

    /// `solid_effects::short_notch_factor`.
    pub fn short_notch_factor(&self) -> Dual {
        let rho = match self.contour {
            DContour::Circular { r, .. } => r,
            DContour::Elliptical { ax, ay, .. } => ax * ax / ay,
            _ => return Dual::c(1.0),
        };
        short_notch_g(self.t_min() / rho)
    }

    /// `solid_effects::fillet_factor`.
    pub fn fillet_factor(&self) -> Dual {
        match self.contour {
            DContour::CornerFilleted { r, t, .. } => short_notch_g(t / r),
            _ => Dual::c(1.0),
        }
    }

    /// `solid_effects::fillet_from`, mm.
    pub fn fillet_from(&self) -> Dual {
        match self.contour {
            DContour::CornerFilleted { l, r, .. } => l / 2.0 - r,
            _ => self.half_notch,
        }
    }

    /// `solid_effects::plane_strain_factor`, with the compliant half-length `value` computed
    /// by `Profile::compliant_half_length`.
    pub fn plane_strain_factor(&self, nu: Dual, compliant_half_length: f64) -> Dual {
        let (w, t) = (self.w, self.t_min());
        1.0 + self.plane_strain_restraint(nu, compliant_half_length) * (1.0 - t / w).max(Dual::c(0.0))
    }

    /// `solid_effects::plane_strain_restraint`, with the compliant half-length `value` computed
    /// by `Profile::compliant_half_length`.
    pub fn plane_strain_restraint(&self, nu: Dual, compliant_half_length: f64) -> Dual {
        if let DContour::SphericalNeck { .. } = self.contour {
            return Dual::c(0.0);
        }
        let z = self.w / self.compliant_half_length(compliant_half_length);
        (1.0 / (1.0 - nu * nu) - 1.0) * (1.0 - (-(z / 3.26).powf(1.29)).exp())
    }
}

/// `solid_effects::short_notch_g`.
fn short_notch_g(x: Dual) -> Dual {
    1.0 + (1.0 - (-x / 0.15).exp()) * 0.068
}
