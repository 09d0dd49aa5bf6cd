//! The smooth pieces of a hinge profile, each with the parameterisation that makes
//! Gauss–Legendre quadrature of its section integrands converge fast.

use super::profile::{Contour, Profile, Spread};

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

impl Profile {
    /// Smooth pieces of the half profile x ∈ [0, half_length].
    pub fn pieces(&self) -> Pieces {
        let mut p = Pieces::new();
        let hn = self.half_notch;
        match self.contour {
            // A notch arc about the centre over the whole half, c² = t/depth.
            Contour::Circular { r, t } => p.push(0.0, hn, arc(0.0, r, t / r)),
            Contour::Elliptical { ax, ay, t } => p.push(0.0, hn, arc(0.0, ax, t / ay)),
            Contour::CornerFilleted { l, r, t } => {
                let s = l / 2.0 - r;
                p.push(0.0, s, Map::Linear);
                p.push(s, hn, arc(s, r, t / r));
            }
            Contour::Leaf { .. } => p.push(0.0, hn, Map::Linear),
            Contour::SphericalNeck { l, t, r } => {
                let s = l / 2.0;
                p.push(0.0, s, Map::Linear);
                // Kinks of the section functions where the disk meets the square faces
                // (r = h/2) and corners (r = h/√2).
                let map = arc(s, r, t / r);
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
        let reach = |s: f64| sp.reach(s);
        let full = reach(self.far_half_size());
        let mut cuts: [f64; 4] = [self.half_notch, full, f64::INFINITY, f64::INFINITY];
        if let Contour::SphericalNeck { .. } = self.contour {
            cuts[2] = reach(self.h / 2.0);
        } else if self.w < self.h && self.w / 2.0 > sp.size0 {
            // Where the effective thickness reaches the width: the blank's plane-strain
            // restraint (`solid_effects::blank_restraint`) has a kink there.
            cuts[3] = reach(self.w / 2.0);
        }
        cuts.sort_by(|a, b| a.total_cmp(b));
        // The taper is linear in the notch and again beyond it (at `blank_slope`); the notch
        // end, `knee`, is one of the cuts.
        let taper = |x0: f64| {
            let (origin, slope) = if x0 < sp.knee {
                (sp.from, sp.slope)
            } else {
                (sp.knee, sp.blank_slope)
            };
            Map::Taper {
                origin,
                size0: sp.taper(origin),
                slope,
            }
        };
        let mut x0 = sp.from;
        for &c in cuts.iter().filter(|&&c| c > sp.from && c.is_finite()) {
            let c = c.min(end);
            // The effective section follows the taper until `full`, then the blank (or, for a
            // contour that never steps, the geometry, which is then never below the taper).
            let map = if x0 < full { taper(x0) } else { Map::Linear };
            p.push(x0, c, map);
            x0 = x0.max(c);
        }
        p.push(x0, end, Map::Linear);
        p
    }
}

/// The arc map with its waist at `origin`, x-extent `radius` and c² = `c2`.
fn arc(origin: f64, radius: f64, c2: f64) -> Map {
    Map::Arc {
        origin,
        radius,
        c: c2.sqrt(),
    }
}
