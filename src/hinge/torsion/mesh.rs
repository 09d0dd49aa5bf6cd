//! The torsion model's mesh: nodes at every profile breakpoint, graded towards the waist (the
//! tan mapping of the flexibility quadrature) and, in the blanks, geometrically towards the
//! notch, where the warping boundary layer of length √(EΓ/GJ) sits.

use super::MAX_NODES;
use crate::hinge::integrate::PEAK;
use crate::hinge::pieces::Map;
use crate::hinge::profile::Profile;
use crate::hinge::section::rect_torsion_warping;

/// Mesh density of the torsion model.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct TorsionMesh {
    /// Elements per arc or straight notch piece (per half).
    pub per_piece: usize,
    /// Elements per blank (per side).
    pub per_blank: usize,
}

impl Default for TorsionMesh {
    fn default() -> Self {
        TorsionMesh {
            per_piece: 8,
            per_blank: 10,
        }
    }
}

/// Appends the nodes of [x0, x1] (x0 excluded, x1 included) with `ne` elements graded
/// geometrically from both ends towards the middle, first sizes `h0` (at x0) and `h1` (at x1).
fn graded(x0: f64, x1: f64, ne: usize, h0: f64, h1: f64, out: &mut [f64], n: &mut usize) {
    let len = x1 - x0;
    let ne = ne.max(2);
    let (nl, nr) = (ne / 2, ne - ne / 2);
    // Sizes of one side: h, h g, h g², … summing to `part`; g ≥ 1 by Newton's method on
    // f(g) = h (1 + g + … + g^{m−1}) − part, which is increasing and convex for g ≥ 1 with
    // f(1) ≤ 0: from a start above the root the iterates fall monotonically onto it (to
    // rounding, within a few ulps), where bisection took 50 evaluations. One element per side
    // (m = 1) needs no ratio.
    let ratio = |h: f64, m: usize, part: f64| -> f64 {
        if m <= 1 {
            return 1.0;
        }
        let h = h.min(part / m as f64);
        let f_df = |g: f64| {
            // Horner: s = Σ_{k<m} g^k and its derivative.
            let (mut s, mut ds) = (0.0f64, 0.0f64);
            for _ in 0..m {
                ds = ds * g + s;
                s = s * g + 1.0;
            }
            (h * s - part, h * ds)
        };
        let mut g = 2.0;
        while f_df(g).0 < 0.0 {
            g *= 2.0;
        }
        for _ in 0..200 {
            let (f, df) = f_df(g);
            if !(f > 0.0 && df > 0.0) {
                break;
            }
            // Never NaN: f64::max returns 1 for a NaN step.
            let next = (g - f / df).max(1.0);
            if next >= g {
                break;
            }
            g = next;
        }
        g
    };
    let xm = x0 + len * nl as f64 / ne as f64;
    let gl = ratio(h0, nl, xm - x0);
    let hl0 = h0.min((xm - x0) / nl as f64);
    let mut x = x0;
    let mut h = hl0;
    for i in 0..nl {
        x = if i + 1 == nl { xm } else { x + h };
        h *= gl;
        out[*n] = x;
        *n += 1;
    }
    // Right side, built from x1 backwards.
    let gr = ratio(h1, nr, x1 - xm);
    let hr0 = h1.min((x1 - xm) / nr as f64);
    let mut sizes = [0.0f64; 64];
    let mut hh = hr0;
    for s in sizes.iter_mut().take(nr) {
        *s = hh;
        hh *= gr;
    }
    let mut x = xm;
    for i in (0..nr).rev() {
        x = if i == 0 { x1 } else { x + sizes[i] };
        out[*n] = x;
        *n += 1;
    }
}

/// Warping boundary-layer length √(EΓ/GJ) of the rectangle w × t.
fn layer(w: f64, t: f64, e: f64, g: f64) -> f64 {
    let (j, warping) = rect_torsion_warping(w, t);
    (e * warping / (g * j)).sqrt()
}

/// Node coordinates of the half mesh x ≥ 0 (0 first); returns the count.
pub(super) fn half_nodes(
    profile: &Profile,
    mesh: TorsionMesh,
    e: f64,
    g: f64,
    out: &mut [f64; MAX_NODES / 2],
) -> usize {
    let mut n = 0;
    out[n] = 0.0;
    n += 1;
    let pieces = profile.pieces();
    let hn = profile.half_notch;
    for piece in pieces.as_slice() {
        let is_blank = piece.x0 >= hn;
        if is_blank {
            // Boundary layers at the notch side (of the thinner section's length) and at the
            // restrained end face.
            let lb = layer(profile.w, profile.h, e, g);
            let ln = layer(profile.w, profile.thickness(hn - 1e-9), e, g).min(lb);
            graded(piece.x0, piece.x1, mesh.per_blank, ln / 2.0, lb / 2.0, out, &mut n);
        } else {
            let ne = mesh.per_piece.max(1);
            match piece.map {
                Map::Linear | Map::Taper { .. } => {
                    let l = layer(profile.w, profile.thickness(0.5 * (piece.x0 + piece.x1)), e, g);
                    graded(piece.x0, piece.x1, ne, l / 2.0, l / 2.0, out, &mut n);
                }
                Map::Arc { origin, radius, c } => {
                    let phi = |x: f64| ((x - origin) / radius).clamp(-1.0, 1.0).asin();
                    let (f0, f1) = (phi(piece.x0), phi(piece.x1));
                    let split = (PEAK * c).clamp(f0, f1);
                    // Half the elements in the waist peak (tan map), half beyond (uniform φ).
                    let n_tan = if split > f0 && split < f1 {
                        ne / 2
                    } else if split >= f1 {
                        ne
                    } else {
                        0
                    };
                    let (q0, q1) = ((f0 / c).atan(), (split / c).atan());
                    for i in 1..=ne {
                        let p = if i <= n_tan {
                            c * (q0 + (q1 - q0) * i as f64 / n_tan as f64).tan()
                        } else {
                            split + (f1 - split) * (i - n_tan) as f64 / (ne - n_tan) as f64
                        };
                        out[n] = if i == ne { piece.x1 } else { origin + radius * p.sin() };
                        n += 1;
                    }
                }
            }
        }
    }
    n
}
