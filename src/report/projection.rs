//! Parallel projection of a 3-D model onto an SVG canvas (formatting only): viewing directions,
//! the fit of the points into a box, depth for painter's ordering, and convex hulls of projected
//! points.

/// A viewing direction: the viewer sits at azimuth `azimuth_deg` about global z from the +x
/// axis and `elevation_deg` above the x–y plane; global z points up on the screen (for
/// elevation ±90° the screen's up is global +y).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct View {
    /// Azimuth about global z from +x, degrees.
    pub azimuth_deg: f64,
    /// Elevation above the x–y plane, degrees.
    pub elevation_deg: f64,
}

impl View {
    /// The isometric view from the (+x, +y, +z) octant.
    pub const ISO: View = View {
        azimuth_deg: 45.0,
        elevation_deg: 35.264_389_682_754_654,
    };

    /// Screen right, screen up and the direction towards the viewer (unit vectors, global).
    fn axes(&self) -> ([f64; 3], [f64; 3], [f64; 3]) {
        let (a, e) = (self.azimuth_deg.to_radians(), self.elevation_deg.to_radians());
        let d = [e.cos() * a.cos(), e.cos() * a.sin(), e.sin()];
        let right = if e.cos().abs() < 1e-9 {
            // Looking straight down (or up): +x to the right, +y up on the screen.
            [1.0, 0.0, 0.0]
        } else {
            [-a.sin(), a.cos(), 0.0]
        };
        let up = cross(d, right);
        (right, up, d)
    }
}

fn cross(a: [f64; 3], b: [f64; 3]) -> [f64; 3] {
    [
        a[1] * b[2] - a[2] * b[1],
        a[2] * b[0] - a[0] * b[2],
        a[0] * b[1] - a[1] * b[0],
    ]
}

fn dot(a: [f64; 3], b: [f64; 3]) -> f64 {
    a[0] * b[0] + a[1] * b[1] + a[2] * b[2]
}

/// The projection onto a canvas: pixels per mm and the offset.
pub struct Projector {
    right: [f64; 3],
    up: [f64; 3],
    towards: [f64; 3],
    /// Canvas pixels per mm of the model.
    pub px_per_mm: f64,
    x0: f64,
    y0: f64,
}

impl Projector {
    /// The projection along `view` that fits the points `all` centred in the `w` × `h` px box
    /// whose top-left corner is at (`left`, `top`).
    pub fn new(view: View, all: &[[f64; 3]], w: f64, h: f64, left: f64, top: f64) -> Projector {
        let (right, up, towards) = view.axes();
        let (mut lo, mut hi) = ([f64::INFINITY; 2], [f64::NEG_INFINITY; 2]);
        for p in all {
            let s = [dot(*p, right), dot(*p, up)];
            for k in 0..2 {
                lo[k] = lo[k].min(s[k]);
                hi[k] = hi[k].max(s[k]);
            }
        }
        if !lo[0].is_finite() {
            (lo, hi) = ([0.0; 2], [1.0; 2]);
        }
        let span = [(hi[0] - lo[0]).max(1e-9), (hi[1] - lo[1]).max(1e-9)];
        let px_per_mm = (w / span[0]).min(h / span[1]);
        Projector {
            right,
            up,
            towards,
            px_per_mm,
            x0: left + 0.5 * (w - span[0] * px_per_mm) - lo[0] * px_per_mm,
            y0: top + 0.5 * (h - span[1] * px_per_mm) + hi[1] * px_per_mm,
        }
    }

    /// The canvas point (px) of model point `p` (mm).
    pub fn at(&self, p: [f64; 3]) -> (f64, f64) {
        (
            self.x0 + dot(p, self.right) * self.px_per_mm,
            self.y0 - dot(p, self.up) * self.px_per_mm,
        )
    }

    /// Distance of `p` towards the viewer, mm (larger: nearer).
    pub fn depth(&self, p: [f64; 3]) -> f64 {
        dot(p, self.towards)
    }

    /// A direction on the screen (unit, px axes), or `None` when it points at the viewer.
    pub fn direction(&self, d: [f64; 3]) -> Option<(f64, f64)> {
        let (x, y) = (dot(d, self.right), -dot(d, self.up));
        let n = x.hypot(y);
        (n > 1e-6 * (dot(d, d).sqrt() + 1e-300)).then(|| (x / n, y / n))
    }
}

/// Convex hull (screen points) by the monotone chain.
pub fn hull(mut p: Vec<(f64, f64)>) -> Vec<(f64, f64)> {
    p.sort_by(|a, b| a.0.total_cmp(&b.0).then(a.1.total_cmp(&b.1)));
    p.dedup_by(|a, b| (a.0 - b.0).abs() < 1e-9 && (a.1 - b.1).abs() < 1e-9);
    if p.len() < 3 {
        return p;
    }
    let turn = |o: (f64, f64), a: (f64, f64), b: (f64, f64)| (a.0 - o.0) * (b.1 - o.1) - (a.1 - o.1) * (b.0 - o.0);
    let mut h: Vec<(f64, f64)> = Vec::with_capacity(2 * p.len());
    for pass in 0..2 {
        let start = h.len();
        let iter: Box<dyn Iterator<Item = &(f64, f64)>> = if pass == 0 {
            Box::new(p.iter())
        } else {
            Box::new(p.iter().rev())
        };
        for &q in iter {
            while h.len() >= start + 2 && turn(h[h.len() - 2], h[h.len() - 1], q) <= 0.0 {
                h.pop();
            }
            h.push(q);
        }
        h.pop();
    }
    h
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn iso_view_axes_are_orthonormal_and_z_is_up() {
        let (r, u, d) = View::ISO.axes();
        for (a, b) in [(r, u), (u, d), (r, d)] {
            assert!(dot(a, b).abs() < 1e-12);
        }
        assert!((dot(d, d) - 1.0).abs() < 1e-12 && (dot(u, u) - 1.0).abs() < 1e-12);
        // Global z projects straight up the screen (positive screen-up component, no right one).
        assert!(dot([0.0, 0.0, 1.0], r).abs() < 1e-12);
        assert!((dot([0.0, 0.0, 1.0], u) - 35.264_389_682_754_654_f64.to_radians().cos()).abs() < 1e-12);
        // Top view: +x right, +y up.
        let (r, u, _) = View {
            azimuth_deg: 0.0,
            elevation_deg: 90.0,
        }
        .axes();
        assert!((r[0] - 1.0).abs() < 1e-12 && (u[1] - 1.0).abs() < 1e-12);
    }

    #[test]
    fn hull_of_a_square_with_an_inner_point() {
        let h = hull(vec![(0.0, 0.0), (1.0, 0.0), (0.5, 0.5), (1.0, 1.0), (0.0, 1.0)]);
        assert_eq!(h.len(), 4);
    }
}
