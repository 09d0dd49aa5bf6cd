//! The `joint` element of mesh cases: an ideal joint between two coincident nodes, by
//! elimination (a [`fem::Tie`] in a node frame whose local x is the joint axis).

use super::frames::{cross, set_node_frame};
use super::lookup::{norm, unit_direction, Ctx};
use super::shapes::JointKind;
use crate::case::error::CaseError;
use crate::fem;

pub(super) use crate::fem::model::{model_size, COINCIDENT};

/// Builds a `joint` element at JSON path `p`.
///
/// The DOFs the joint does not release are tied in the joint frame (rows: x = `axis`, y =
/// `axis2` for a universal joint or a perpendicular, z = x × y; or `full_frame` as given). Both nodes get that frame;
/// a node has one frame, so a node already framed by another joint with other axes is refused
/// (give each joint its own coincident node, joined to the body by a rigid link or stiff beam —
/// the link's master, not a slave, since slaves cannot carry frames). Spherical and weld joints
/// tie whole vectors, the same in every frame: they need no axis and adopt a frame present.
pub(super) fn joint_element(
    cx: &mut Ctx,
    p: &str,
    nodes: [usize; 2],
    kind: JointKind,
    [axis, axis2]: [Option<[f64; 3]>; 2],
    full_frame: Option<[[f64; 3]; 3]>,
) -> Result<(), CaseError> {
    let (a, b) = cx.two_nodes(p, nodes, "joint")?;
    let (xa, xb) = (cx.spec.nodes[a], cx.spec.nodes[b]);
    let d = norm([xb[0] - xa[0], xb[1] - xa[1], xb[2] - xa[2]]);
    let tol = COINCIDENT * model_size(&cx.spec.nodes);
    if d > tol {
        return Err(CaseError::value(
            format!("{p}.nodes"),
            format!("[{a}, {b}]"),
            format!("the nodes are {d} mm apart; a joint joins coincident nodes (within {COINCIDENT} of the model size, {tol} mm)"),
        ));
    }
    let name = format!("{kind:?}").to_lowercase();
    let (needs_axis, needs_axis2) = match kind {
        JointKind::Revolute | JointKind::Cylindrical | JointKind::Prismatic => (true, false),
        JointKind::Universal => (true, true),
        JointKind::Spherical | JointKind::Weld => (false, false),
    };
    let given = match full_frame {
        Some(f) => {
            if let Some((field, _)) = [("axis", axis.is_some()), ("axis2", axis2.is_some())]
                .into_iter()
                .find(|(_, g)| *g)
            {
                return Err(CaseError::new(
                    format!("{p}.{field}"),
                    "give either `frame` (three rows, joint axis = local x) or `axis`/`axis2`, not both",
                ));
            }
            super::frames::local(p, Some(f), None)?.map(|l| l.rows)
        }
        None => None,
    };
    let (x, y) = if given.is_some() {
        (None, None)
    } else {
        (
            unit_axis(p, "axis", axis, needs_axis, &name)?,
            unit_axis(p, "axis2", axis2, needs_axis2, &name)?,
        )
    };
    let frame = given.or(match (x, y) {
        (Some(x), Some(y)) => {
            let c = x[0] * y[0] + x[1] * y[1] + x[2] * y[2];
            if c.abs() > 1e-6 {
                return Err(CaseError::value(
                    format!("{p}.axis2"),
                    format!("{:?}", axis2.unwrap_or_default()),
                    format!("must be perpendicular to `axis` (cosine {c})"),
                ));
            }
            let y = unit([y[0] - c * x[0], y[1] - c * x[1], y[2] - c * x[2]]);
            Some([x, y, cross(x, y)])
        }
        (Some(x), None) => {
            let t = if x[0].abs() < 0.9 {
                [1.0, 0.0, 0.0]
            } else {
                [0.0, 1.0, 0.0]
            };
            let y = unit(cross(x, t));
            Some([x, y, cross(x, y)])
        }
        _ => None,
    });
    let free: &[usize] = match kind {
        JointKind::Revolute => &[3],
        JointKind::Spherical => &[3, 4, 5],
        JointKind::Universal => &[3, 4],
        JointKind::Cylindrical => &[0, 3],
        JointKind::Prismatic => &[0],
        JointKind::Weld => &[],
    };
    let frame = frame.or_else(|| cx.model.frames.get(&a).or(cx.model.frames.get(&b)).copied());
    if let Some(f) = frame {
        let at = format!("{p}.nodes");
        set_node_frame(cx, &at, a, f)?;
        set_node_frame(cx, &at, b, f)?;
    }
    let mut dofs = [true; 6];
    for &k in free {
        dofs[k] = false;
    }
    cx.model.ties.push(fem::Tie { a, b, dofs });
    cx.tie_paths.push(p.to_string());
    Ok(())
}

/// The unit vector of an optional axis field: required when `needed`, refused otherwise.
fn unit_axis(
    p: &str,
    field: &str,
    v: Option<[f64; 3]>,
    needed: bool,
    kind: &str,
) -> Result<Option<[f64; 3]>, CaseError> {
    match (v, needed) {
        (None, false) => Ok(None),
        (None, true) => Err(CaseError::new(
            format!("{p}.{field}"),
            format!("missing field `{field}`: a {kind} joint needs it (a direction [x, y, z])"),
        )),
        (Some(v), false) => Err(CaseError::value(
            format!("{p}.{field}"),
            format!("{v:?}"),
            format!("a {kind} joint takes no `{field}`"),
        )),
        (Some(v), true) => unit_direction(format!("{p}.{field}"), v).map(Some),
    }
}

fn unit(v: [f64; 3]) -> [f64; 3] {
    let n = norm(v);
    v.map(|c| c / n)
}
