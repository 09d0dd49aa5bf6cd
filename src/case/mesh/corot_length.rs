//! The shortest co-rotational element a geometrically nonlinear run accepts.

use super::shapes::{ElementSpec, MeshSpec};
use crate::case::error::CaseError;

/// Shortest beam or hinge segment of a geometrically nonlinear run, relative to the model size
/// (diagonal of the nodes' bounding box).
///
/// The nonlinear solve accepts a state when its residual is within 1e-6 of the load plus a
/// round-off floor of ~1e-14 of the stiffest element's force at unit strain or rotation; a
/// short beam's shear stiffness grows as 1/L³, so one short element lifts that floor above the
/// loads and unbalanced states pass. Measured on `cases/shallow_arch_arc_length.json` (200 mm,
/// 30 N) with one beam of length L added in series at a clamp: residual 0.022 N at L = 1e-3 mm
/// (5e-6 of the size), 174 N at 1e-4 mm, 3.1e4 N at 1e-6 mm; on `cases/leaf_guide_track.json`
/// (54 mm, reactions ~60 N): 1e-6 N at 1e-3 mm, 0.78 N at 1e-4 mm, 4.4e5 N at 1e-6 mm.
pub const NONLINEAR_MIN_RELATIVE_LENGTH: f64 = 1e-5;

/// Refuses (at `elements[i].nodes`) a beam or hinge element (per segment for a hinge of
/// several) shorter than [`NONLINEAR_MIN_RELATIVE_LENGTH`] of the model size; `segments` gives
/// the segments of each case element that is a hinge (`None` otherwise).
pub(super) fn check(spec: &MeshSpec, segments: impl Fn(usize) -> Option<usize>) -> Result<(), CaseError> {
    let mut lo = [f64::INFINITY; 3];
    let mut hi = [f64::NEG_INFINITY; 3];
    for x in &spec.nodes {
        for k in 0..3 {
            lo[k] = lo[k].min(x[k]);
            hi[k] = hi[k].max(x[k]);
        }
    }
    let size = (0..3).map(|k| (hi[k] - lo[k]).powi(2)).sum::<f64>().sqrt();
    for (i, e) in spec.elements.iter().enumerate() {
        let (nodes, what) = match e {
            ElementSpec::Beam { nodes, .. } => (nodes, "beam"),
            ElementSpec::Hinge { nodes, .. } => (nodes, "hinge segment"),
            _ => continue,
        };
        let (Some(a), Some(b)) = (spec.nodes.get(nodes[0]), spec.nodes.get(nodes[1])) else {
            continue;
        };
        let n = segments(i).unwrap_or(1) as f64;
        let len = (0..3).map(|k| (b[k] - a[k]).powi(2)).sum::<f64>().sqrt() / n;
        if len < NONLINEAR_MIN_RELATIVE_LENGTH * size {
            return Err(CaseError::value(
                format!("elements[{i}].nodes"),
                format!("[{}, {}]", nodes[0], nodes[1]),
                format!(
                    "a {what} of {len:.3e} mm in a model of {size:.3e} mm: a geometrically nonlinear run needs every beam and hinge segment at least {NONLINEAR_MIN_RELATIVE_LENGTH:e} of the model size (a shorter one's stiffness lifts the solver's round-off floor above the loads, so equilibrium cannot be verified); merge the nodes, join them by a rigid link, or lengthen the element"
                ),
            ));
        }
    }
    Ok(())
}
