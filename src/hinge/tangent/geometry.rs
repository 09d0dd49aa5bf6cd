//! The hinge profile of [`crate::hinge::Profile`] with every dimension a [`Dual`]: notch
//! half-length, load-spreading start, thickness, effective section and the smooth pieces, as
//! `profile.rs` and `pieces.rs` compute them, differentiated along a [`Tangent`].

use super::dual::Dual;
use super::Tangent;
use crate::hinge::profile::{Contour, Profile, AXIAL_BLANK_SLOPE, SPREAD_SLOPE};

/// A family's contour dimensions with their derivatives, mm.
#[derive(Debug, Clone, Copy)]
pub(super) enum DContour {
    Circular { r: Dual, t: Dual },
    Elliptical { ax: Dual, ay: Dual, t: Dual },
    CornerFilleted { l: Dual, r: Dual, t: Dual },
    Leaf { l: Dual, t: Dual },
    SphericalNeck { l: Dual, t: Dual, r: Dual },
}

/// [`Profile`] with dual dimensions (the spreading slope is a constant).
#[derive(Debug, Clone, Copy)]
pub(super) struct DProfile {
    pub contour: DContour,
    pub w: Dual,
    pub h: Dual,
    pub blank: Dual,
    pub half_notch: Dual,
    /// (from, size0) of [`crate::hinge::profile::Spread`]; slope [`SPREAD_SLOPE`] in the notch.
    pub spread: Option<(Dual, Dual)>,
    /// The spreading's slope beyond the notch end (`Spread::blank_slope`, the knee at
    /// `half_notch`): [`SPREAD_SLOPE`], or [`AXIAL_BLANK_SLOPE`] for the profile the axial load
    /// sees ([`DProfile::axial`], `Profile::axial`).
    pub blank_slope: f64,
}

/// x at which an arc reaches the cap thickness h (`profile.rs`'s `arc_cap`).
fn arc_cap(ext: Dual, depth: Dual, t: Dual, h: Dual) -> Option<Dual> {
    if t.v + 2.0 * depth.v <= h.v {
        None
    } else {
        let q = 1.0 - (h - t) / (depth * 2.0);
        Some(ext * (1.0 - q * q).max(Dual::c(0.0)).sqrt())
    }
}

impl DProfile {
    /// `p` moving along `tg` (a tangent of the same family as `p`'s contour).
    pub fn new(p: &Profile, tg: &Tangent) -> DProfile {
        let d = Dual::new;
        let contour = match (p.contour, tg.contour) {
            (Contour::Circular { r, t }, Contour::Circular { r: dr, t: dt }) => DContour::Circular {
                r: d(r, dr),
                t: d(t, dt),
            },
            (Contour::Elliptical { ax, ay, t }, Contour::Elliptical { ax: a, ay: b, t: c }) => DContour::Elliptical {
                ax: d(ax, a),
                ay: d(ay, b),
                t: d(t, c),
            },
            (Contour::CornerFilleted { l, r, t }, Contour::CornerFilleted { l: a, r: b, t: c }) => {
                DContour::CornerFilleted {
                    l: d(l, a),
                    r: d(r, b),
                    t: d(t, c),
                }
            }
            (Contour::Leaf { l, t }, Contour::Leaf { l: a, t: b }) => DContour::Leaf { l: d(l, a), t: d(t, b) },
            (Contour::SphericalNeck { l, t, r }, Contour::SphericalNeck { l: a, t: b, r: c }) => {
                DContour::SphericalNeck {
                    l: d(l, a),
                    t: d(t, b),
                    r: d(r, c),
                }
            }
            _ => unreachable!("Tangent::of_family gives the profile's family"),
        };
        let h = d(p.h, tg.h);
        let half_notch = match contour {
            DContour::Circular { r, t } => arc_cap(r, r, t, h).unwrap_or(r),
            DContour::Elliptical { ax, ay, t } => arc_cap(ax, ay, t, h).unwrap_or(ax),
            DContour::CornerFilleted { l, r, t } => l / 2.0 - r + arc_cap(r, r, t, h).unwrap_or(r),
            DContour::Leaf { l, .. } => l / 2.0,
            DContour::SphericalNeck { l, r, .. } => l / 2.0 + r,
        };
        let mut out = DProfile {
            contour,
            w: d(p.w, tg.w),
            h,
            blank: d(p.blank, tg.blank),
            half_notch,
            spread: None,
            blank_slope: SPREAD_SLOPE,
        };
        if p.spread.is_some() {
            out.spread = out.spread_start();
        }
        out
    }

    /// The profile the axial load sees (`Profile::axial`): the spreading beyond the notch at
    /// [`AXIAL_BLANK_SLOPE`]; `None` without spreading.
    pub fn axial(&self) -> Option<DProfile> {
        self.spread.map(|_| DProfile {
            blank_slope: AXIAL_BLANK_SLOPE,
            ..*self
        })
    }

    /// The taper of the spreading that starts at (`from`, `size0`), at |x| = `u` ≥ `from`
    /// (`Spread::taper`: [`SPREAD_SLOPE`] up to the notch end, `blank_slope` beyond).
    pub fn taper(&self, u: Dual, from: Dual, size0: Dual) -> Dual {
        let hn = self.half_notch;
        if u.v <= hn.v {
            size0 + (u - from) * SPREAD_SLOPE
        } else {
            size0 + (hn - from) * SPREAD_SLOPE + (u - hn) * self.blank_slope
        }
    }

    /// |x| at which the taper reaches the half-size `s` (`Spread::reach`).
    pub fn reach(&self, s: Dual, from: Dual, size0: Dual) -> Dual {
        let hn = self.half_notch;
        let at_knee = self.taper(hn, from, size0);
        if s.v <= at_knee.v {
            from + (s - size0) / SPREAD_SLOPE
        } else {
            hn + (s - at_knee) / self.blank_slope
        }
    }

    /// (from, size0) of the load spreading (`Profile::spread` with [`SPREAD_SLOPE`]).
    fn spread_start(&self) -> Option<(Dual, Dual)> {
        let slope = SPREAD_SLOPE;
        let hn = self.half_notch;
        let on_arc = |start: Dual, ext: Dual, depth: Dual| -> Dual {
            let k = ext * slope / depth;
            start + ext * k / (1.0 + k * k).sqrt()
        };
        let from = match self.contour {
            DContour::Circular { r, .. } => on_arc(Dual::c(0.0), r, r),
            DContour::Elliptical { ax, ay, .. } => on_arc(Dual::c(0.0), ax, ay),
            DContour::CornerFilleted { l, r, .. } => on_arc(l / 2.0 - r, r, r),
            DContour::Leaf { l, .. } => l / 2.0,
            DContour::SphericalNeck { l, r, .. } => on_arc(l / 2.0, r, r),
        };
        if from.v < hn.v {
            Some((from, self.half_size(from)))
        } else {
            let inside = self.half_size(hn * (1.0 - 1e-12));
            if inside.v >= self.far_half_size().v * (1.0 - 1e-9) {
                None
            } else {
                Some((hn, inside))
            }
        }
    }

    /// Geometric half-size at |x| = u (`Profile::half_size`).
    pub fn half_size(&self, u: Dual) -> Dual {
        match self.contour {
            DContour::SphericalNeck { .. } if u.v >= self.half_notch.v => Dual::c(f64::INFINITY),
            DContour::SphericalNeck { l, t, r } => {
                if u.v <= l.v / 2.0 {
                    t / 2.0
                } else {
                    let v = (u - l / 2.0).min(r);
                    t / 2.0 + r - (r * r - v * v).max(Dual::c(0.0)).sqrt()
                }
            }
            _ => self.thickness(u) * 0.5,
        }
    }

    /// h/2 (h/√2 for the neck's square).
    pub fn far_half_size(&self) -> Dual {
        match self.contour {
            DContour::SphericalNeck { .. } => self.h / std::f64::consts::SQRT_2,
            _ => self.h * 0.5,
        }
    }

    /// Thickness t(x) (`Profile::thickness`).
    pub fn thickness(&self, x: Dual) -> Dual {
        let u = x.abs();
        if u.v >= self.half_notch.v {
            return self.h;
        }
        let h = self.h;
        let arc = |t: Dual, depth: Dual, ext: Dual, v: Dual| -> Dual {
            let s = (v / ext).min(Dual::c(1.0));
            (t + depth * 2.0 * (1.0 - (1.0 - s * s).sqrt())).min(h)
        };
        match self.contour {
            DContour::Circular { r, t } => arc(t, r, r, u),
            DContour::Elliptical { ax, ay, t } => arc(t, ay, ax, u),
            DContour::CornerFilleted { l, r, t } => {
                let straight = l / 2.0 - r;
                if u.v <= straight.v {
                    t
                } else {
                    arc(t, r, r, u - straight)
                }
            }
            DContour::Leaf { t, .. } => t,
            DContour::SphericalNeck { .. } => (self.half_size(u) * 2.0).min(h),
        }
    }

    /// Effective half-size (`Profile::effective_half_size`).
    pub fn effective_half_size(&self, x: Dual) -> Dual {
        let u = x.abs();
        let s = self.half_size(u);
        match self.spread {
            Some((from, size0)) if u.v > from.v => s.min(self.taper(u, from, size0)),
            _ => s,
        }
    }

    /// `Profile::section_size`: effective neck radius or effective thickness.
    pub fn section_size(&self, x: Dual) -> Dual {
        match self.contour {
            DContour::SphericalNeck { .. } => self.effective_half_size(x),
            _ => (self.effective_half_size(x) * 2.0).min(self.h),
        }
    }

    /// Waist thickness (neck diameter).
    pub fn t_min(&self) -> Dual {
        match self.contour {
            DContour::Circular { t, .. }
            | DContour::Elliptical { t, .. }
            | DContour::CornerFilleted { t, .. }
            | DContour::Leaf { t, .. }
            | DContour::SphericalNeck { t, .. } => t,
        }
    }

    /// Half of the total length.
    pub fn half_length(&self) -> Dual {
        self.half_notch + self.blank
    }
}
