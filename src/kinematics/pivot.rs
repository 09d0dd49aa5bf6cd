//! Pivot shift: where a rigid body turns about, from two of its poses.
//!
//! A rigid displacement from pose 1 to pose 2 (a body point at p₁, p₂; orientations R₁, R₂ from
//! rotation vectors, global axes) is a screw (Chasles): a rotation φ about an axis of direction n
//! through a point c, with a slide s along n. With R = R₂R₁ᵀ and d = p₂ − R p₁ (the displacement
//! of the point of the body that pose 1 puts at the origin),
//!   n, φ from R (axis–angle), s = n·d, d⊥ = d − s n,
//!   c₀ = ½ (d⊥ + cot(φ/2) n × d⊥)   (the axis point nearest the origin),
//! and the point returned is the axis point nearest a reference r: c = c₀ + n (n·(r − c₀)).
//! Between consecutive states of a load path this is the instantaneous screw axis to O(Δφ²)
//! at the mid state; for planar motion c is the instantaneous centre of rotation (the pole).
//! (J. M. McCarthy, G. S. Soh, Geometric Design of Linkages, 2nd ed., Springer 2011, §3.5.)
//!
//! For a leaf (or any straight flexure along x from its root at the origin), the end's
//! `axis_crossing` — where the end body's x-axis, carried along, crosses the undeformed axis —
//! is the characteristic pivot of the pseudo-rigid-body model: under a pure moment (constant
//! curvature, end angle θ) it lies L·tan(θ/2)/θ from the root; the instantaneous centre of the
//! end is at (L(1 − cos θ)/θ², L(θ − sin θ)/θ²) in (along, across) the leaf (differentiating the
//! arc x = L sin θ/θ, z = L(1 − cos θ)/θ; both start at L/2; C. Iandiorio, P. Salvini,
//! Elasto-kinematics and instantaneous invariants of compliant mechanisms based on flexure
//! hinges, Micromachines 14 (2023) 783).

use nalgebra::{Rotation3, Vector3};

/// The screw of a finite rigid displacement.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Screw {
    /// Unit axis direction (right-handed with `angle`).
    pub axis: [f64; 3],
    /// Rotation about the axis, rad (> 0).
    pub angle: f64,
    /// Point of the axis nearest the reference, mm.
    pub point: [f64; 3],
    /// Slide along the axis, mm.
    pub slide: f64,
}

/// The screw taking a body from pose (`p1` mm, rotation vector `r1` rad) to (`p2`, `r2`); the
/// axis point nearest `reference`. `None` when the rotation is below `1e-12` rad (a pure
/// translation: the centre is at infinity).
pub fn screw_between(p1: [f64; 3], r1: [f64; 3], p2: [f64; 3], r2: [f64; 3], reference: [f64; 3]) -> Option<Screw> {
    let rot = |r: [f64; 3]| Rotation3::from_scaled_axis(Vector3::from(r));
    let rel = rot(r2) * rot(r1).inverse();
    let sa = rel.scaled_axis();
    let phi = sa.norm();
    if phi.is_nan() || phi <= 1e-12 {
        return None;
    }
    let n = sa / phi;
    let d = Vector3::from(p2) - rel * Vector3::from(p1);
    let s = n.dot(&d);
    let dp = d - n * s;
    let c0 = (dp + n.cross(&dp) / (0.5 * phi).tan()) * 0.5;
    let c = c0 + n * n.dot(&(Vector3::from(reference) - c0));
    Some(Screw {
        axis: n.into(),
        angle: phi,
        point: c.into(),
        slide: s,
    })
}

/// Where the line through `end` (mm) along the body's axis `dir` (unit, global) crosses the
/// line through `root` along `along` (unit): the distance from `root` along `along` of the
/// point of that line closest to the body line, mm. `None` when the lines are parallel.
pub fn axis_crossing(root: [f64; 3], along: [f64; 3], end: [f64; 3], dir: [f64; 3]) -> Option<f64> {
    let (a, u) = (Vector3::from(root), Vector3::from(along));
    let (b, v) = (Vector3::from(end), Vector3::from(dir));
    let w = a - b;
    let (uu, uv, vv) = (u.dot(&u), u.dot(&v), v.dot(&v));
    let den = uu * vv - uv * uv;
    if den.is_nan() || den <= 1e-14 * uu * vv {
        return None;
    }
    // Closest points a + s u, b + t v: s = (uv·(v·w) − vv·(u·w)) / den.
    Some((uv * v.dot(&w) - vv * u.dot(&w)) / den)
}

/// The body's x-axis in global coordinates after the rotation vector `r` (rad).
pub fn rotated_x(r: [f64; 3]) -> [f64; 3] {
    (Rotation3::from_scaled_axis(Vector3::from(r)) * Vector3::x()).into()
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A body turned by 0.3 rad about the axis through (2, 5, 0) along z, slid 0.1 along it:
    /// the screw gives back the axis, angle, slide and the axis point nearest (0, 0, 7) —
    /// (2, 5, 7) — to 1e-12.
    #[test]
    fn screw_recovers_a_known_motion() {
        let c = Vector3::new(2.0, 5.0, 0.0);
        let r = Rotation3::from_scaled_axis(Vector3::new(0.0, 0.0, 0.3));
        let p1 = Vector3::new(7.0, -1.0, 3.0);
        let p2 = r * (p1 - c) + c + Vector3::new(0.0, 0.0, 0.1);
        let r1 = [0.1, -0.2, 0.05];
        let r2: [f64; 3] = (r * Rotation3::from_scaled_axis(Vector3::from(r1)))
            .scaled_axis()
            .into();
        let s = screw_between(p1.into(), r1, p2.into(), r2, [0.0, 0.0, 7.0]).unwrap();
        assert!(
            (s.angle - 0.3).abs() < 1e-12 && (s.axis[2] - 1.0).abs() < 1e-12,
            "{s:?}"
        );
        assert!((s.slide - 0.1).abs() < 1e-12, "{s:?}");
        for (k, v) in [2.0, 5.0, 7.0].iter().enumerate() {
            assert!((s.point[k] - v).abs() < 1e-12, "{s:?}");
        }
    }

    /// Tangent crossing of a circular arc of length L = 1 bent to θ = 0.5 rad in the x–z plane:
    /// L·tan(θ/2)/θ from the root, to 1e-12.
    #[test]
    fn arc_end_tangent_crosses_at_tan_half_angle() {
        let th: f64 = 0.5;
        let end = [th.sin() / th, 0.0, (1.0 - th.cos()) / th];
        let dir = [th.cos(), 0.0, th.sin()];
        let x = axis_crossing([0.0; 3], [1.0, 0.0, 0.0], end, dir).unwrap();
        assert!((x - (0.5 * th).tan() / th).abs() < 1e-12, "{x}");
    }
}
