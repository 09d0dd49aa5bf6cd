//! Pivot shift of a hinge along its large-rotation curve (result `pivot_shift`): the
//! instantaneous centre of rotation of the loaded end face between consecutive force levels and
//! where the end face's axis crosses the undeformed hinge axis, relative to the notch centre
//! ([`crate::kinematics::pivot`]).

use crate::kinematics::pivot::{axis_crossing, rotated_x, screw_between};
use serde::Serialize;

/// The pivot of the hinge at one level of the large-rotation curve.
#[derive(Debug, Clone, Serialize)]
pub struct PivotPoint {
    /// End-face rotation at this level, degrees.
    pub rotation_deg: f64,
    /// Instantaneous centre of rotation of the end face between the previous level (the
    /// undeformed state for the first) and this one, relative to the notch centre: [along the
    /// hinge axis, along the load (z)], mm.
    pub centre: [f64; 2],
    /// Where the end face's axis crosses the undeformed hinge axis, measured from the notch
    /// centre along it, mm (the pseudo-rigid-body pivot); `null` while the axes are parallel.
    pub axis_crossing: Option<f64>,
}

/// The pivot shift along the curve.
#[derive(Debug, Clone, Serialize)]
pub struct PivotShift {
    /// What the numbers are.
    pub method: &'static str,
    /// One point per level of the large-rotation curve.
    pub points: Vec<PivotPoint>,
    /// Largest distance of the instantaneous centre from the notch centre, mm.
    pub drift: f64,
}

/// The pivot shift from the end poses: `centre_x` the notch centre on the x axis (mm), `poses`
/// the end face's position (mm) and rotation vector (rad) per level, the undeformed first.
pub fn pivot_shift(centre_x: f64, poses: &[([f64; 3], [f64; 3])]) -> PivotShift {
    let mut points = Vec::new();
    for w in poses.windows(2) {
        let ((p0, r0), (p1, r1)) = (w[0], w[1]);
        let Some(s) = screw_between(p0, r0, p1, r1, [centre_x, 0.0, 0.0]) else {
            continue;
        };
        let crossing = axis_crossing([centre_x, 0.0, 0.0], [1.0, 0.0, 0.0], p1, rotated_x(r1));
        let angle = nalgebra::Vector3::from(r1).norm();
        points.push(PivotPoint {
            rotation_deg: angle.to_degrees(),
            centre: [s.point[0] - centre_x, s.point[2]],
            axis_crossing: crossing,
        });
    }
    let drift = points
        .iter()
        .map(|p| p.centre[0].hypot(p.centre[1]))
        .fold(0.0, f64::max);
    PivotShift {
        method: "instantaneous centre: screw axis of the end face between consecutive converged levels (chord of the path; exact to O(Δθ²) at the mid rotation); axis crossing: the end face's axis against the undeformed hinge axis",
        points,
        drift,
    }
}
