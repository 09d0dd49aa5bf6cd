//! Hinge profiles t(x) / r(x) per family (SPEC.md §4) and their validation.
//!
//! x runs along the hinge, x = 0 at the hinge centre; the notch region is |x| ≤ `half_notch`,
//! followed on each side by `blank_length` of full blank section. Thickness profiles are capped
//! at the blank height h: a notch contour that would be thicker than the blank simply ends on
//! the blank face (SPEC §4 "capped at h"); a contour that ends thinner than h (t + 2R < h)
//! steps up to the blank with a vertical wall, as a slot milled with a cutter of radius R.
//!
//! Each profile is cut into *pieces* between breakpoints (waist, end of a straight part, end of
//! a fillet, the cap or step, the blank) so that the integrands are smooth on every piece.
//! Arc pieces carry a mapping that makes Gauss–Legendre converge fast (see [`Map`]).

use super::error::{geom, non_negative, positive, HingeError};
use super::section::{clipped_disk, rectangle, Section};

/// The cross-section family and contour of a validated hinge.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Contour {
    /// t(x) = t + 2(R − √(R² − x²)), |x| ≤ R.
    Circular {
        /// Notch radius R.
        r: f64,
        /// Minimum thickness t.
        t: f64,
    },
    /// t(x) = t + 2a_y(1 − √(1 − x²/a_x²)), |x| ≤ a_x.
    Elliptical {
        /// Semi-axis along the hinge.
        ax: f64,
        /// Semi-axis across (depth direction).
        ay: f64,
        /// Minimum thickness t.
        t: f64,
    },
    /// Straight part l − 2R of thickness t, then quarter-circle fillets of radius R.
    CornerFilleted {
        /// Total notch length l.
        l: f64,
        /// Fillet radius R.
        r: f64,
        /// Thickness t.
        t: f64,
    },
    /// Prismatic leaf of length l and thickness t.
    Leaf {
        /// Length l.
        l: f64,
        /// Thickness t.
        t: f64,
    },
    /// Turned neck, diameter t over |x| ≤ l/2, fillets of radius R, inside an h × h blank.
    SphericalNeck {
        /// Straight neck length l.
        l: f64,
        /// Neck diameter t.
        t: f64,
        /// Fillet radius R.
        r: f64,
    },
}

/// A validated hinge geometry: contour, blank width `w` (rectangular families; `h` for the
/// neck), blank height `h` and blank length on each side.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Profile {
    /// Contour of the notch.
    pub contour: Contour,
    /// Width along y (constant), mm.
    pub w: f64,
    /// Blank height along z (side of the square blank for the neck), mm.
    pub h: f64,
    /// Blank length beyond each end of the notch region, mm.
    pub blank: f64,
    /// Half-length of the notch region (where the section differs from the blank), mm.
    pub half_notch: f64,
}

/// How a piece is parameterised for quadrature.
///
/// `Arc { origin, radius, c }`: x = origin + radius · sin(c · tan ψ), ψ uniform. For a circular
/// or elliptical arc with its waist at `origin`, φ = c tan ψ is the arc angle; near the waist
/// t(φ) ≈ t₀ + (const) φ², so 1/t³ is a Lorentzian-like peak of width ~c in φ which tan
/// flattens (the integrand in ψ behaves like cos⁴ψ), and sin removes the √ end singularity of
/// the arc. Converges to 1e-10 with a few 8-point panels for any t/R.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Map {
    /// x uniform.
    Linear,
    /// See the type documentation.
    Arc {
        /// x at the waist of the arc.
        origin: f64,
        /// x-extent of the full quarter arc (R or a_x).
        radius: f64,
        /// Angular width of the waist peak.
        c: f64,
    },
}

/// A smooth piece [x0, x1] (x0 < x1, both ≥ 0) of the half profile.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Piece {
    /// Start.
    pub x0: f64,
    /// End.
    pub x1: f64,
    /// Parameterisation.
    pub map: Map,
}

/// At most this many pieces per half profile.
pub const MAX_PIECES: usize = 6;

/// Pieces of the half profile x ≥ 0, in order.
#[derive(Debug, Clone, Copy)]
pub struct Pieces {
    /// Storage.
    pub items: [Piece; MAX_PIECES],
    /// Number of valid entries.
    pub len: usize,
}

impl Pieces {
    fn new() -> Self {
        Pieces {
            items: [Piece {
                x0: 0.0,
                x1: 0.0,
                map: Map::Linear,
            }; MAX_PIECES],
            len: 0,
        }
    }
    fn push(&mut self, x0: f64, x1: f64, map: Map) {
        if x1 > x0 {
            self.items[self.len] = Piece { x0, x1, map };
            self.len += 1;
        }
    }
    /// The valid pieces.
    pub fn as_slice(&self) -> &[Piece] {
        &self.items[..self.len]
    }
}

/// x at which an arc t + 2·depth·(1 − √(1 − (x/ext)²)) reaches the cap thickness h, if it does.
fn arc_cap(ext: f64, depth: f64, t: f64, h: f64) -> Option<f64> {
    if t + 2.0 * depth <= h {
        None
    } else {
        let q = 1.0 - (h - t) / (2.0 * depth);
        Some(ext * (1.0 - q * q).max(0.0).sqrt())
    }
}

impl Profile {
    /// Validates and builds a rectangular-section profile (all families but the neck).
    pub fn rectangular(contour: Contour, w: f64, h: f64, blank: f64) -> Result<Self, HingeError> {
        positive("w", w)?;
        positive("h", h)?;
        non_negative("blank_length", blank)?;
        let thin = |t: f64| -> Result<(), HingeError> {
            if t.is_finite() && t > 0.0 && t < h {
                Ok(())
            } else {
                Err(geom("t", t, format!("must be > 0 and < h = {h}")))
            }
        };
        let half_notch = match contour {
            Contour::Circular { r, t } => {
                positive("R", r)?;
                thin(t)?;
                arc_cap(r, r, t, h).unwrap_or(r)
            }
            Contour::Elliptical { ax, ay, t } => {
                positive("ax", ax)?;
                positive("ay", ay)?;
                thin(t)?;
                arc_cap(ax, ay, t, h).unwrap_or(ax)
            }
            Contour::CornerFilleted { l, r, t } => {
                positive("l", l)?;
                positive("R", r)?;
                thin(t)?;
                if 2.0 * r > l {
                    return Err(geom(
                        "R",
                        r,
                        format!(
                            "must be <= l/2 = {} (two fillets fit in the notch length l)",
                            l / 2.0
                        ),
                    ));
                }
                let straight = l / 2.0 - r;
                straight + arc_cap(r, r, t, h).unwrap_or(r)
            }
            Contour::Leaf { l, t } => {
                positive("l", l)?;
                thin(t)?;
                l / 2.0
            }
            Contour::SphericalNeck { .. } => {
                return Err(geom(
                    "type",
                    f64::NAN,
                    "spherical_neck is built with Profile::neck",
                ))
            }
        };
        Ok(Profile {
            contour,
            w,
            h,
            blank,
            half_notch,
        })
    }

    /// Validates and builds a turned (spherical) neck in an h × h blank.
    pub fn neck(l: f64, t: f64, r: f64, h: f64, blank: f64) -> Result<Self, HingeError> {
        non_negative("l", l)?;
        positive("R", r)?;
        positive("h", h)?;
        non_negative("blank_length", blank)?;
        if !(t.is_finite() && t > 0.0 && t < h) {
            return Err(geom("t", t, format!("neck diameter must be > 0 and < h = {h}")));
        }
        Ok(Profile {
            contour: Contour::SphericalNeck { l, t, r },
            w: h,
            h,
            blank,
            half_notch: l / 2.0 + r,
        })
    }

    /// Half of the total length (notch + one blank), mm.
    pub fn half_length(&self) -> f64 {
        self.half_notch + self.blank
    }

    /// Thickness t(x) of a rectangular profile (h in the blank); for the neck, the neck
    /// diameter 2 r(x) (h in the blank).
    pub fn thickness(&self, x: f64) -> f64 {
        let u = x.abs();
        if u >= self.half_notch {
            return self.h;
        }
        let h = self.h;
        let arc = |t: f64, depth: f64, ext: f64, v: f64| -> f64 {
            let s = (v / ext).min(1.0);
            (t + 2.0 * depth * (1.0 - (1.0 - s * s).sqrt())).min(h)
        };
        match self.contour {
            Contour::Circular { r, t } => arc(t, r, r, u),
            Contour::Elliptical { ax, ay, t } => arc(t, ay, ax, u),
            Contour::CornerFilleted { l, r, t } => {
                let straight = l / 2.0 - r;
                if u <= straight {
                    t
                } else {
                    arc(t, r, r, u - straight)
                }
            }
            Contour::Leaf { t, .. } => t,
            Contour::SphericalNeck { l, t, r } => {
                if u <= l / 2.0 {
                    t
                } else {
                    // Diameter; for the shoulder beyond u = R the blank follows (u ≥ half_notch).
                    arc(t, r, r, u - l / 2.0).max(t).min(f64::INFINITY)
                }
            }
        }
    }

    /// Cross-section at x (Poisson's ratio for the shear coefficients).
    pub fn section(&self, x: f64, nu: f64) -> Section {
        match self.contour {
            Contour::SphericalNeck { l, t, r } => {
                let u = x.abs();
                let rad = if u >= self.half_notch {
                    f64::INFINITY
                } else if u <= l / 2.0 {
                    t / 2.0
                } else {
                    let v = (u - l / 2.0).min(r);
                    t / 2.0 + r - (r * r - v * v).max(0.0).sqrt()
                };
                clipped_disk(rad, self.h, nu)
            }
            _ => rectangle(self.w, self.thickness(x), nu),
        }
    }

    /// Minimum thickness (neck: diameter), mm.
    pub fn t_min(&self) -> f64 {
        match self.contour {
            Contour::Circular { t, .. }
            | Contour::Elliptical { t, .. }
            | Contour::CornerFilleted { t, .. }
            | Contour::Leaf { t, .. }
            | Contour::SphericalNeck { t, .. } => t,
        }
    }

    /// Smooth pieces of the half profile x ∈ [0, half_length].
    pub fn pieces(&self) -> Pieces {
        let mut p = Pieces::new();
        let hn = self.half_notch;
        match self.contour {
            Contour::Circular { r, t } => {
                p.push(
                    0.0,
                    hn,
                    Map::Arc {
                        origin: 0.0,
                        radius: r,
                        c: (t / r).sqrt(),
                    },
                );
            }
            Contour::Elliptical { ax, ay, t } => {
                p.push(
                    0.0,
                    hn,
                    Map::Arc {
                        origin: 0.0,
                        radius: ax,
                        c: (t / ay).sqrt(),
                    },
                );
            }
            Contour::CornerFilleted { l, r, t } => {
                let s = l / 2.0 - r;
                p.push(0.0, s, Map::Linear);
                p.push(
                    s,
                    hn,
                    Map::Arc {
                        origin: s,
                        radius: r,
                        c: (t / r).sqrt(),
                    },
                );
            }
            Contour::Leaf { .. } => p.push(0.0, hn, Map::Linear),
            Contour::SphericalNeck { l, t, r } => {
                let s = l / 2.0;
                p.push(0.0, s, Map::Linear);
                // Kinks of the section functions where the disk meets the square faces
                // (r = h/2) and corners (r = h/√2).
                let map = Map::Arc {
                    origin: s,
                    radius: r,
                    c: (t / r).sqrt(),
                };
                let mut x0 = s;
                for rk in [self.h / 2.0, self.h / std::f64::consts::SQRT_2] {
                    // r(u) = t/2 + R − √(R² − u²) = rk  ⇒  u = √(R² − (t/2 + R − rk)²)
                    let q = t / 2.0 + r - rk;
                    if rk > t / 2.0 && q > 0.0 && q < r {
                        let xk = s + (r * r - q * q).sqrt();
                        p.push(x0, xk, map);
                        x0 = xk;
                    }
                }
                p.push(x0, hn, map);
            }
        }
        p.push(hn, hn + self.blank, Map::Linear);
        p
    }
}
