//! Centres of rotation of the rigid bodies of a nonlinear `static` run (result
//! `load_cases[i].centre_of_rotation`): the instantaneous screw axis of every rigid body (a
//! `rigid` element: its master node's pose) between consecutive converged points of the path —
//! the chord of the path, which is the instantaneous axis at the mid state to O(Δλ²)
//! ([`crate::kinematics::pivot::screw_between`]) — and its drift along the path.

use crate::fem::{Dof, Model, NodeDof, PathPoint};
use crate::kinematics::pivot::screw_between;
use serde::Serialize;

/// Below this rotation (rad) between two converged points a body is translating: its centre is
/// at infinity and reported as `null`.
pub const TRANSLATION_BELOW: f64 = 1e-9;

/// The instantaneous centre of one rigid body over one step of the path.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct BodyPivotPoint {
    /// Load factor at the end of the step (−).
    pub load_factor: f64,
    /// The body's rotation angle from the undeformed state at the end of the step, degrees.
    pub rotation_deg: f64,
    /// The point of the step's screw axis nearest the body's master node as first placed, mm
    /// (global); absent when the body turned less than 1e-9 rad over the step (it translates).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub centre: Option<[f64; 3]>,
    /// Unit direction of the screw axis (global); absent with `centre`.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub axis: Option<[f64; 3]>,
    /// Slide along the axis over the step, mm; absent with `centre`.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub slide: Option<f64>,
}

/// The centres of rotation of one rigid body along a load case's path.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct BodyPivotRow {
    /// The body's master node (the `master` of its `rigid` element).
    pub body: usize,
    /// Its other nodes.
    pub slaves: Vec<usize>,
    /// One point per step of the path.
    pub points: Vec<BodyPivotPoint>,
    /// Largest distance of an instantaneous centre from the first one, mm; absent with fewer
    /// than two centres.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub drift: Option<f64>,
    /// The point nearest all of the path's screw axes (least squares): the fixed point of a
    /// spherical motion (a pan-tilt's remote centre); absent when fewer than two axes turn or
    /// they are (nearly) parallel, as in planar motion (see [`fixed_point`]).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub fixed_point: Option<FixedPoint>,
}

/// The point the screw axes of a path pass nearest to.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct FixedPoint {
    /// The point minimising the sum of squared distances to the axes, mm (global).
    pub point: [f64; 3],
    /// Largest distance of an axis from it, mm: 0 for a motion about a fixed point.
    pub scatter: f64,
}

/// Axes must spread by at least this much for their common point to be defined: the smallest
/// eigenvalue of the mean of (I − n nᵀ) over the axes, about sin² of their spread (1e-2: about
/// 6°). The point's position along nearly parallel axes is their perpendicular scatter divided
/// by the spread's sine, so below this it is not worth reporting; planar motion (parallel axes)
/// and a rotation about a nearly fixed axis have none.
pub const AXIS_SPREAD_BELOW: f64 = 1e-2;

/// The least-squares common point of lines (point `c`, unit direction `n`): the solution of
/// Σ(I − n nᵀ) x = Σ(I − n nᵀ) c, with the largest distance of a line from it; `None` with
/// fewer than two lines or when they spread less than [`AXIS_SPREAD_BELOW`].
pub fn fixed_point(lines: &[([f64; 3], [f64; 3])]) -> Option<FixedPoint> {
    use nalgebra::{Matrix3, Vector3};
    if lines.len() < 2 {
        return None;
    }
    let (mut a, mut b) = (Matrix3::zeros(), Vector3::zeros());
    for (c, n) in lines {
        let p = Matrix3::identity() - Vector3::from(*n) * Vector3::from(*n).transpose();
        a += p;
        b += p * Vector3::from(*c);
    }
    let eig = a.symmetric_eigen();
    if eig.eigenvalues.min() / (lines.len() as f64) < AXIS_SPREAD_BELOW {
        return None;
    }
    let x = a.cholesky()?.solve(&b);
    let scatter = lines
        .iter()
        .map(|(c, n)| {
            let d = x - Vector3::from(*c);
            (d - Vector3::from(*n) * Vector3::from(*n).dot(&d)).norm()
        })
        .fold(0.0, f64::max);
    Some(FixedPoint {
        point: [x[0], x[1], x[2]],
        scatter,
    })
}

/// The master-node DOFs to track along the path: six per rigid link, in link order.
pub fn tracks(model: &Model) -> Vec<NodeDof> {
    model
        .rigid_links
        .iter()
        .flat_map(|r| Dof::ALL.iter().map(move |&dof| NodeDof { node: r.master, dof }))
        .collect()
}

/// The rows of every rigid body from `path`, whose points' tracked values end with
/// [`tracks`] (six per rigid link).
pub fn rows(model: &Model, path: &[PathPoint]) -> Vec<BodyPivotRow> {
    let n = model.rigid_links.len();
    let Some(first) = path.first() else {
        return Vec::new();
    };
    let Some(base) = first.values.len().checked_sub(6 * n) else {
        return Vec::new();
    };
    model
        .rigid_links
        .iter()
        .enumerate()
        .map(|(k, link)| {
            let x0 = model.nodes[link.master];
            let pose = |p: &PathPoint| {
                let v = &p.values[base + 6 * k..base + 6 * k + 6];
                ([x0[0] + v[0], x0[1] + v[1], x0[2] + v[2]], [v[3], v[4], v[5]])
            };
            let points: Vec<BodyPivotPoint> = path
                .windows(2)
                .map(|w| {
                    let ((p0, r0), (p1, r1)) = (pose(&w[0]), pose(&w[1]));
                    let screw = screw_between(p0, r0, p1, r1, x0).filter(|s| s.angle >= TRANSLATION_BELOW);
                    BodyPivotPoint {
                        load_factor: w[1].lambda,
                        rotation_deg: nalgebra::Vector3::from(r1).norm().to_degrees(),
                        centre: screw.map(|s| s.point),
                        axis: screw.map(|s| s.axis),
                        slide: screw.map(|s| s.slide),
                    }
                })
                .collect();
            let centres: Vec<[f64; 3]> = points.iter().filter_map(|p| p.centre).collect();
            let drift = (centres.len() >= 2).then(|| {
                centres
                    .iter()
                    .map(|c| {
                        let d = [c[0] - centres[0][0], c[1] - centres[0][1], c[2] - centres[0][2]];
                        (d[0] * d[0] + d[1] * d[1] + d[2] * d[2]).sqrt()
                    })
                    .fold(0.0, f64::max)
            });
            let axes: Vec<([f64; 3], [f64; 3])> = points.iter().filter_map(|p| Some((p.centre?, p.axis?))).collect();
            BodyPivotRow {
                body: link.master,
                slaves: link.slaves.clone(),
                points,
                drift,
                fixed_point: fixed_point(&axes),
            }
        })
        .collect()
}

/// The `model` note of the rows.
pub const NOTE: &str = "centre_of_rotation: per rigid body (a `rigid` element, by its master node) and step of the path, the screw axis of the body between consecutive converged points (Chasles; the instantaneous axis at the step's middle to O(Δλ²)), given as its point nearest the master node's undeformed position; centre absent while the body only translates (< 1e-9 rad per step); fixed_point: the least-squares point nearest all the body's axes along the path (a spherical motion's centre) and the largest distance of an axis from it, given when the axes spread by more than about 6° (a nearly fixed axis leaves the point along it undetermined)";
