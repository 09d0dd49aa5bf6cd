//! Hinge profiles t(x) / r(x) per family and their validation.
//!
//! x runs along the hinge, x = 0 at the hinge centre; the notch region is |x| ≤ `half_notch`,
//! followed on each side by `blank_length` of full blank section. Thickness profiles are capped
//! at the blank height h: a notch contour that would be thicker than the blank simply ends on
//! the blank face ("capped at h"); a contour that ends thinner than h (t + 2R < h)
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

/// Load spreading from the notch into the thicker sections beside it (see [`Profile::spread`]).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Spread {
    /// |x| from which the effective half-size grows linearly, mm.
    pub from: f64,
    /// Half-size (half-thickness, or neck radius) at `from`, mm.
    pub size0: f64,
    /// Growth of the effective half-size per unit length (tan of the spreading half-angle).
    pub slope: f64,
}

/// Spreading slope: the effective half-size grows by at most 1/2 per unit length (half-angle
/// atan(1/2) = 26.6°). See [`Profile::spread`] for where it comes from.
pub const SPREAD_SLOPE: f64 = 0.5;

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
    /// Load spreading (None: every section fully effective, the plain beam idealisation).
    pub spread: Option<Spread>,
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
    /// Linear taper of the effective half-size: size(x) = size0 + slope·(x − origin) (slope < 0
    /// on the mirrored side), parameterised by ψ = ln(size/size0) so that the power-law
    /// integrands 1/size^p become smooth exponentials.
    Taper {
        /// x where the effective half-size is `size0`.
        origin: f64,
        /// Half-size at `origin`, mm.
        size0: f64,
        /// d(size)/dx.
        slope: f64,
    },
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
pub const MAX_PIECES: usize = 10;

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

fn contour_t(c: &Contour) -> f64 {
    match *c {
        Contour::Circular { t, .. }
        | Contour::Elliptical { t, .. }
        | Contour::CornerFilleted { t, .. }
        | Contour::Leaf { t, .. }
        | Contour::SphericalNeck { t, .. } => t,
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
                positive("t", t)
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
                        format!("must be <= l/2 = {} (two fillets fit in the notch length l)", l / 2.0),
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
                return Err(geom("type", f64::NAN, "spherical_neck is built with Profile::neck"))
            }
        };
        if 2.0 * (half_notch + blank) < super::error::MIN_LENGTH {
            // A notch so shallow against its radius that its length rounds to nothing.
            return Err(geom(
                "t",
                contour_t(&contour),
                format!(
                    "the hinge is shorter than {:e} mm: the notch depth (h − t)/2 is too shallow to give it a length; make t smaller than h or give blank_length > 0",
                    super::error::MIN_LENGTH
                ),
            ));
        }
        Ok(Profile {
            contour,
            w,
            h,
            blank,
            half_notch,
            spread: None,
        }
        .spread(SPREAD_SLOPE))
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
        positive("t", t)?;
        Ok(Profile {
            contour: Contour::SphericalNeck { l, t, r },
            w: h,
            h,
            blank,
            half_notch: l / 2.0 + r,
            spread: None,
        }
        .spread(SPREAD_SLOPE))
    }

    /// The same geometry with load spreading of the given slope (0 or less: none).
    ///
    /// Beam theory takes every cross-section as fully effective, right where the contour
    /// widens. In the solid, stress flows out of the thin waist into the flanks, shoulders and
    /// blank gradually: a section much larger than its neighbours is not fully stressed. The
    /// model keeps the geometric section while the contour's half-size grows slower than
    /// `slope` per unit length; from the first point where it grows faster (`from`: on a
    /// circular arc of radius R at u = slope·R/√(1 + slope²); at a step, the step) the
    /// *effective* half-size grows linearly at `slope` until it meets the real section again
    /// (the blank). Bending, shear, axial and torsion then integrate the effective section.
    /// `slope` = 1/2 ([`SPREAD_SLOPE`]) was found by comparing with converged quadratic-tetrahedron
    /// solid models (`tools/solid_reference.py`) of turned necks, where this one effect
    /// explains the beam model's over-stiffness (axial up to 19 %, bending up to 12 % for short
    /// necks with small fillets) to about 2–3 %; it is the classical load-spreading cone of
    /// St-Venant's principle with a half-angle of 26.6°.
    pub fn spread(mut self, slope: f64) -> Profile {
        self.spread = None;
        if slope.is_nan() || slope <= 0.0 {
            return self;
        }
        let hn = self.half_notch;
        let on_arc = |start: f64, ext: f64, depth: f64| -> f64 {
            // Half-size t/2 + depth(1 − √(1 − (v/ext)²)) has slope (depth/ext)·q/√(1 − q²),
            // q = v/ext; it reaches `slope` at q = k/√(1 + k²), k = slope·ext/depth.
            let k = slope * ext / depth;
            start + ext * k / (1.0 + k * k).sqrt()
        };
        let from = match self.contour {
            Contour::Circular { r, .. } => on_arc(0.0, r, r),
            Contour::Elliptical { ax, ay, .. } => on_arc(0.0, ax, ay),
            Contour::CornerFilleted { l, r, .. } => on_arc(l / 2.0 - r, r, r),
            Contour::Leaf { l, .. } => l / 2.0,
            Contour::SphericalNeck { l, r, .. } => on_arc(l / 2.0, r, r),
        };
        let (from, size0) = if from < hn {
            (from, self.half_size(from))
        } else {
            // The contour never grows faster than `slope`; only a step to the blank (a contour
            // that ends below the blank) needs spreading.
            let inside = self.half_size(hn * (1.0 - 1e-12));
            if inside >= self.far_half_size() * (1.0 - 1e-9) {
                return self;
            }
            (hn, inside)
        };
        self.spread = Some(Spread { from, size0, slope });
        self
    }

    /// Geometric half-size at |x| = u: half-thickness for rectangular families, neck radius
    /// (infinite in the blank) for the turned neck.
    fn half_size(&self, u: f64) -> f64 {
        match self.contour {
            Contour::SphericalNeck { .. } if u >= self.half_notch => f64::INFINITY,
            Contour::SphericalNeck { l, t, r } => {
                if u <= l / 2.0 {
                    t / 2.0
                } else {
                    let v = (u - l / 2.0).min(r);
                    t / 2.0 + r - (r * r - v * v).max(0.0).sqrt()
                }
            }
            _ => 0.5 * self.thickness(u),
        }
    }

    /// Half-size at which a section is the full blank (h/2; h/√2 for the neck's square).
    fn far_half_size(&self) -> f64 {
        match self.contour {
            Contour::SphericalNeck { .. } => self.h / std::f64::consts::SQRT_2,
            _ => 0.5 * self.h,
        }
    }

    /// |x| up to which load spreading makes sections less than fully effective: where the
    /// spreading taper meets the full blank (at least the notch half-length). A mechanism
    /// model should give the hinge's flexibility to this region, not only to the notch.
    pub fn spread_reach(&self) -> f64 {
        match self.spread {
            Some(sp) => (sp.from + (self.far_half_size() - sp.size0) / sp.slope).max(self.half_notch),
            None => self.half_notch,
        }
    }

    /// Half-length over which the thickness stays below twice the waist thickness (the whole
    /// notch if it never doubles), mm: the length scale of the compliant region.
    pub fn compliant_half_length(&self) -> f64 {
        let target = 2.0 * self.t_min();
        let hn = self.half_notch;
        if self.thickness(hn * (1.0 - 1e-12)) < target {
            return hn;
        }
        let (mut lo, mut hi) = (0.0, hn);
        for _ in 0..60 {
            let mid = 0.5 * (lo + hi);
            if self.thickness(mid) < target {
                lo = mid;
            } else {
                hi = mid;
            }
        }
        0.5 * (lo + hi)
    }

    /// Effective half-size at x (see [`Profile::spread`]).
    pub fn effective_half_size(&self, x: f64) -> f64 {
        let u = x.abs();
        let s = self.half_size(u);
        match self.spread {
            Some(sp) if u > sp.from => s.min(sp.size0 + sp.slope * (u - sp.from)),
            _ => s,
        }
    }

    /// Effective thickness (rectangular families) or neck diameter at x.
    pub fn effective_thickness(&self, x: f64) -> f64 {
        (2.0 * self.effective_half_size(x)).min(self.h)
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
            // Diameter 2 r(x), capped at h like the rectangular contours.
            Contour::SphericalNeck { .. } => (2.0 * self.half_size(u)).min(h),
        }
    }

    /// Effective cross-section at x (Poisson's ratio for the shear coefficients): the geometric
    /// section, reduced where load spreading limits it ([`Profile::spread`]).
    pub fn section(&self, x: f64, nu: f64) -> Section {
        match self.contour {
            Contour::SphericalNeck { .. } => clipped_disk(self.effective_half_size(x), self.h, nu),
            _ => rectangle(self.w, self.effective_thickness(x), nu),
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
        match self.spread {
            Some(sp) => self.spread_pieces(&p, sp),
            None => p,
        }
    }

    /// Replaces the pieces beyond `sp.from` by the linear taper of the effective half-size
    /// (split where its section function has kinks and at the notch end) and the blank.
    fn spread_pieces(&self, geometric: &Pieces, sp: Spread) -> Pieces {
        let end = self.half_length();
        let mut p = Pieces::new();
        for piece in geometric.as_slice() {
            if piece.x0 < sp.from {
                p.push(piece.x0, piece.x1.min(sp.from), piece.map);
            }
        }
        // Where the taper reaches the given half-sizes.
        let reach = |s: f64| sp.from + (s - sp.size0) / sp.slope;
        let full = reach(self.far_half_size());
        let mut cuts: [f64; 4] = [self.half_notch, full, f64::INFINITY, f64::INFINITY];
        if let Contour::SphericalNeck { .. } = self.contour {
            cuts[2] = reach(self.h / 2.0);
        }
        cuts.sort_by(|a, b| a.total_cmp(b));
        let taper = Map::Taper {
            origin: sp.from,
            size0: sp.size0,
            slope: sp.slope,
        };
        let mut x0 = sp.from;
        for &c in cuts.iter().filter(|&&c| c > sp.from && c.is_finite()) {
            let c = c.min(end);
            // The effective section follows the taper until `full`, then the blank (or, for a
            // contour that never steps, the geometry, which is then never below the taper).
            let map = if x0 < full { taper } else { Map::Linear };
            p.push(x0, c, map);
            x0 = x0.max(c);
        }
        p.push(x0, end, Map::Linear);
        p
    }
}
