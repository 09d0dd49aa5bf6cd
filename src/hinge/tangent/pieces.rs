//! The smooth pieces of a [`DProfile`] and their quadrature maps, as `hinge/pieces.rs` builds
//! them: breakpoints and map parameters move with the dimensions, so the quadrature points and
//! weights carry their derivatives (the Leibniz terms of moving integration limits).

use super::dual::Dual;
use super::geometry::{DContour, DProfile};
use crate::hinge::profile::SPREAD_SLOPE;

/// `hinge::pieces::Map` with dual parameters.
#[derive(Debug, Clone, Copy)]
pub(super) enum DMap {
    Linear,
    Taper { origin: Dual, size0: Dual, slope: f64 },
    Arc { origin: Dual, radius: Dual, c: Dual },
}

/// A smooth piece [x0, x1] of the half profile.
#[derive(Debug, Clone, Copy)]
pub(super) struct DPiece {
    pub x0: Dual,
    pub x1: Dual,
    pub map: DMap,
}

/// At most this many pieces per half profile (as `hinge::pieces::MAX_PIECES`).
const MAX: usize = crate::hinge::pieces::MAX_PIECES;

/// Pieces of the half profile, in order.
#[derive(Debug, Clone, Copy)]
pub(super) struct DPieces {
    items: [DPiece; MAX],
    len: usize,
}

impl DPieces {
    fn new() -> Self {
        DPieces {
            items: [DPiece {
                x0: Dual::c(0.0),
                x1: Dual::c(0.0),
                map: DMap::Linear,
            }; MAX],
            len: 0,
        }
    }

    fn push(&mut self, x0: Dual, x1: Dual, map: DMap) {
        if x1.v > x0.v {
            self.items[self.len] = DPiece { x0, x1, map };
            self.len += 1;
        }
    }

    /// The valid pieces.
    pub fn as_slice(&self) -> &[DPiece] {
        &self.items[..self.len]
    }
}

fn arc(origin: Dual, radius: Dual, c2: Dual) -> DMap {
    DMap::Arc {
        origin,
        radius,
        c: c2.sqrt(),
    }
}

impl DProfile {
    /// `Profile::pieces`.
    pub fn pieces(&self) -> DPieces {
        let mut p = DPieces::new();
        let hn = self.half_notch;
        let zero = Dual::c(0.0);
        match self.contour {
            DContour::Circular { r, t } => p.push(zero, hn, arc(zero, r, t / r)),
            DContour::Elliptical { ax, ay, t } => p.push(zero, hn, arc(zero, ax, t / ay)),
            DContour::CornerFilleted { l, r, t } => {
                let s = l / 2.0 - r;
                p.push(zero, s, DMap::Linear);
                p.push(s, hn, arc(s, r, t / r));
            }
            DContour::Leaf { .. } => p.push(zero, hn, DMap::Linear),
            DContour::SphericalNeck { l, t, r } => {
                let s = l / 2.0;
                p.push(zero, s, DMap::Linear);
                let map = arc(s, r, t / r);
                let mut x0 = s;
                for rk in [self.h / 2.0, self.h / std::f64::consts::SQRT_2] {
                    let q = t / 2.0 + r - rk;
                    if rk.v > t.v / 2.0 && q.v > 0.0 && q.v < r.v {
                        let xk = s + (r * r - q * q).sqrt();
                        p.push(x0, xk, map);
                        x0 = xk;
                    }
                }
                p.push(x0, hn, map);
            }
        }
        p.push(hn, hn + self.blank, DMap::Linear);
        match self.spread {
            Some((from, size0)) => self.spread_pieces(&p, from, size0),
            None => p,
        }
    }

    /// `Profile::spread_pieces`.
    fn spread_pieces(&self, geometric: &DPieces, from: Dual, size0: Dual) -> DPieces {
        let end = self.half_length();
        let mut p = DPieces::new();
        for piece in geometric.as_slice() {
            if piece.x0.v < from.v {
                p.push(piece.x0, piece.x1.min(from), piece.map);
            }
        }
        let reach = |s: Dual| self.reach(s, from, size0);
        let full = reach(self.far_half_size());
        let inf = Dual::c(f64::INFINITY);
        let mut cuts: [Dual; 4] = [self.half_notch, full, inf, inf];
        if let DContour::SphericalNeck { .. } = self.contour {
            cuts[2] = reach(self.h / 2.0);
        } else if self.w.v < self.h.v && self.w.v / 2.0 > size0.v {
            cuts[3] = reach(self.w / 2.0);
        }
        cuts.sort_by(|a, b| a.v.total_cmp(&b.v));
        // The taper is linear in the notch and again beyond it (at `blank_slope`); the notch
        // end is one of the cuts (`Profile::spread_pieces`).
        let taper = |x0: Dual| {
            if x0.v < self.half_notch.v {
                DMap::Taper {
                    origin: from,
                    size0,
                    slope: SPREAD_SLOPE,
                }
            } else {
                DMap::Taper {
                    origin: self.half_notch,
                    size0: self.taper(self.half_notch, from, size0),
                    slope: self.blank_slope,
                }
            }
        };
        let mut x0 = from;
        for &c in cuts.iter().filter(|c| c.v > from.v && c.v.is_finite()) {
            let c = c.min(end);
            let map = if x0.v < full.v { taper(x0) } else { DMap::Linear };
            p.push(x0, c, map);
            x0 = x0.max(c);
        }
        p.push(x0, end, DMap::Linear);
        p
    }
}
