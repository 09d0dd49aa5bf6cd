//! Local frames of supports, prescribed displacements and forces (`"frame"` or `"axis"`), and
//! the one node frame each node may carry (shared with joint elements).

use super::load_shapes::DofName;
use super::lookup::{norm, unit_direction, Ctx};
use crate::case::error::CaseError;

/// A validated local frame: rows local x, y, z in global axes; `axis_only` when given by
/// `"axis"` (then only the x direction is the user's).
#[derive(Debug, Clone, Copy)]
pub(super) struct Local {
    pub rows: [[f64; 3]; 3],
    pub axis_only: bool,
}

/// The local frame of an entry at JSON path `p` (`None`: global axes).
pub(super) fn local(p: &str, frame: Option<[[f64; 3]; 3]>, axis: Option<[f64; 3]>) -> Result<Option<Local>, CaseError> {
    match (frame, axis) {
        (None, None) => Ok(None),
        (Some(_), Some(_)) => Err(CaseError::new(
            format!("{p}.axis"),
            "give either `frame` (three rows) or `axis` (one direction), not both",
        )),
        (Some(f), None) => {
            let dot = |a: [f64; 3], b: [f64; 3]| a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
            let mut worst: f64 = 0.0;
            for i in 0..3 {
                for j in 0..3 {
                    let target = if i == j { 1.0 } else { 0.0 };
                    worst = worst.max((dot(f[i], f[j]) - target).abs());
                }
            }
            let det = dot(f[0], cross(f[1], f[2]));
            if !(worst <= 1e-9 && det > 0.0) {
                return Err(CaseError::value(
                    format!("{p}.frame"),
                    format!("{f:?}"),
                    format!("the rows must be orthonormal (to 1e-9; off by {worst:.3e}) and right-handed (determinant {det:.6})"),
                ));
            }
            Ok(Some(Local {
                rows: f,
                axis_only: false,
            }))
        }
        (None, Some(a)) => {
            let x = unit_direction(format!("{p}.axis"), a)?;
            let t = if x[0].abs() < 0.9 {
                [1.0, 0.0, 0.0]
            } else {
                [0.0, 1.0, 0.0]
            };
            let y = cross(x, t);
            let y = y.map(|c| c / norm(y));
            Ok(Some(Local {
                rows: [x, y, cross(x, y)],
                axis_only: true,
            }))
        }
    }
}

/// With `"axis"` only `ux` and `rx` have a direction of the user's; `uy` with `uz` (and `ry`
/// with `rz`) together are the plane across the axis, the same in any perpendicular pair.
pub(super) fn check_axis_dofs(p: &str, dofs: &[DofName]) -> Result<(), CaseError> {
    let has = |d: DofName| dofs.contains(&d);
    for (a, b) in [(DofName::Uy, DofName::Uz), (DofName::Ry, DofName::Rz)] {
        if has(a) != has(b) {
            return Err(CaseError::value(
                p,
                format!("{dofs:?}"),
                "with `axis` only ux and rx (along the axis) are defined on their own; uy and uz (ry and rz) go together — give `frame` to name one direction across the axis",
            ));
        }
    }
    Ok(())
}

/// Gives `node` the frame `rows` (owner: the JSON path that asks for it); a node carries one
/// frame, so a different frame already there is refused, naming its owner.
pub(super) fn set_node_frame(cx: &mut Ctx, path: &str, node: usize, rows: [[f64; 3]; 3]) -> Result<(), CaseError> {
    if let Some(g) = cx.model.frames.get(&node) {
        let diff = (0..9)
            .map(|k| (g[k / 3][k % 3] - rows[k / 3][k % 3]).abs())
            .fold(0.0, f64::max);
        if diff > 1e-12 {
            let owner = cx.frame_owner.get(&node).cloned().unwrap_or_default();
            return Err(CaseError::value(
                path,
                format!("{rows:?}"),
                format!("node {node} already has the frame {g:?} (from `{owner}`); a node carries one frame: use a coincident node joined by a joint, or the same frame"),
            ));
        }
        return Ok(());
    }
    cx.model.set_frame(node, rows);
    cx.frame_owner.insert(node, path.to_string());
    Ok(())
}

/// A 6-vector (force, moment) given in `rows`' local axes, in global axes.
pub(super) fn to_global(rows: &[[f64; 3]; 3], v: [f64; 6]) -> [f64; 6] {
    let mut g = [0.0; 6];
    for k in 0..3 {
        for c in 0..3 {
            g[c] += rows[k][c] * v[k];
            g[3 + c] += rows[k][c] * v[3 + k];
        }
    }
    g
}

pub(super) fn cross(a: [f64; 3], b: [f64; 3]) -> [f64; 3] {
    [
        a[1] * b[2] - a[2] * b[1],
        a[2] * b[0] - a[0] * b[2],
        a[0] * b[1] - a[1] * b[0],
    ]
}
