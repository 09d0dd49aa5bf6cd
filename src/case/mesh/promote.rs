//! `"shell_elements": "shell9"`: every four-node shell of a model becomes a nine-node shell on
//! the same corners, so a mesh written for `shell4` (a JSON mesh, a Gmsh quadrangle mesh) is
//! solved with the nine-node element without being meshed again.
//!
//! Each edge shared by shells gets one midpoint node and each shell a centre node (the mean of
//! its corners), numbered after the model's own nodes, edges in the order they are first met
//! and then the centres; element indices do not change, so `pressures` and results keep theirs.
//! A new node inherits what its parents share:
//! - **supports**: a midpoint is held in the DOFs both ends of its edge are held in (the same
//!   `frame`/`axis`); a centre is never held;
//! - **rigid links**: a midpoint whose two ends belong to one link (as master or slave) becomes a
//!   slave of it, and a centre whose four corners do;
//! - **prescribed displacements**: a midpoint whose two ends prescribe one DOF (the same
//!   `frame`/`axis`) prescribes the mean of the two values (linear along the edge), and so does
//!   one whose other end holds that DOF (counted as 0) — [`midpoint_value`]; a transient's
//!   `motions` alike when both ends share a history.
//!
//! An edge that a `shell9` of the model has already keeps that element's midpoint.
//!
//! Refused, with the element's JSON path: triangles (`[a, b, c, c]`), warped quadrangles (the
//! nine-node shell is flat), shells with a node in a `joint` (the ties would have to be
//! repeated on the new nodes). Edge loads stay on their edges (a nine-node shell's edge takes
//! them through its midpoint too). The coordinates of the new nodes are kept as the mean of
//! their parents' at every build ([`Promoted::place`]), so a parameter sweep that moves corners
//! moves them too.

use std::collections::{BTreeMap, BTreeSet};

use super::load_shapes::DofName;
use super::shapes::{ElementSpec, MeshSpec, RigidSpec, SupportSpec};
pub use super::shapes::{Promoted, ShellElements};
use crate::case::CaseError;

/// Promotes the `shell4` elements of `spec` to `shell9` (module docs); does nothing when no
/// element is a `shell4` or when one names a node that does not exist (the build reports it).
pub fn promote(spec: &mut MeshSpec) -> Result<(), CaseError> {
    let n = spec.nodes.len();
    let quads: Vec<(usize, [usize; 4])> = spec
        .elements
        .iter()
        .enumerate()
        .filter_map(|(i, e)| match e {
            ElementSpec::Shell4 { nodes, .. } => Some((i, *nodes)),
            _ => None,
        })
        .collect();
    if quads.is_empty() || quads.iter().any(|(_, q)| q.iter().any(|&a| a >= n)) {
        return Ok(());
    }
    let joined: BTreeSet<usize> = spec
        .elements
        .iter()
        .filter_map(|e| match e {
            ElementSpec::Joint { nodes, .. } => Some(*nodes),
            _ => None,
        })
        .flatten()
        .collect();
    // A quadrangle the four-node shell refuses (not convex, zero area, non-finite corners): left
    // as written, so that the build names what is wrong with it.
    if quads.iter().any(|(_, q)| {
        let distinct = q.iter().collect::<BTreeSet<_>>().len() == 4;
        distinct && crate::fem::shell::shell_geometry(&q.map(|a| spec.nodes[a])).is_none()
    }) {
        return Ok(());
    }
    for &(i, q) in &quads {
        let p = format!("elements[{i}].nodes");
        let distinct: BTreeSet<usize> = q.iter().copied().collect();
        if distinct.len() < 4 {
            return Err(CaseError::value(
                p,
                serde_json::json!(q),
                "\"shell_elements\": \"shell9\" turns quadrangles into nine-node shells and this is a triangle (a repeated node): mesh it with quadrangles, or keep \"shell_elements\": \"as_given\"",
            ));
        }
        if let Some(a) = q.iter().find(|a| joined.contains(a)) {
            return Err(CaseError::value(
                p,
                serde_json::json!(q),
                format!("\"shell_elements\": \"shell9\": node {a} of this shell is in a `joint`, whose ties are not carried to the nodes added on its edges; join the shells by a rigid link or a beam, or keep \"shell_elements\": \"as_given\""),
            ));
        }
    }
    // Midpoints, edges in the order first met, then centres; an edge a nine-node shell of the
    // model has already keeps its midpoint.
    let mut edge_node: BTreeMap<(usize, usize), usize> = BTreeMap::new();
    for e in &spec.elements {
        if let ElementSpec::Shell9 { nodes, .. } = e {
            for k in 0..4 {
                let (a, b) = (nodes[k], nodes[(k + 1) % 4]);
                edge_node.insert((a.min(b), a.max(b)), nodes[4 + k]);
            }
        }
    }
    let mut parents: Vec<Vec<usize>> = Vec::new();
    for &(_, q) in &quads {
        for k in 0..4 {
            let (a, b) = (q[k], q[(k + 1) % 4]);
            edge_node.entry((a.min(b), a.max(b))).or_insert_with(|| {
                parents.push(vec![a, b]);
                n + parents.len() - 1
            });
        }
    }
    let first_centre = n + parents.len();
    parents.extend(quads.iter().map(|(_, q)| q.to_vec()));
    let promoted = Promoted {
        first_node: n,
        parents,
        shells: quads.len(),
        first_support: spec.supports.len(),
    };
    spec.nodes.resize(n + promoted.parents.len(), [0.0; 3]);
    promoted.place(&mut spec.nodes);
    for (c, &(i, q)) in quads.iter().enumerate() {
        let mid = |k: usize| {
            let (a, b) = (q[k], q[(k + 1) % 4]);
            edge_node[&(a.min(b), a.max(b))]
        };
        let nodes = [q[0], q[1], q[2], q[3], mid(0), mid(1), mid(2), mid(3), first_centre + c];
        let x: [[f64; 3]; 9] = std::array::from_fn(|k| spec.nodes[nodes[k]]);
        if let Err(e) = crate::fem::shell9::shell9_geometry(&x) {
            return Err(CaseError::new(
                format!("elements[{i}]"),
                format!("\"shell_elements\": \"shell9\": this four-node shell cannot become a nine-node shell: {e} (node 8 is the centre added at the mean of the corners); keep \"shell_elements\": \"as_given\" for curved or warped shells"),
            ));
        }
        let ElementSpec::Shell4 { section, material, .. } = &spec.elements[i] else {
            unreachable!("quads holds shell4 elements only")
        };
        spec.elements[i] = ElementSpec::Shell9 {
            nodes,
            section: section.clone(),
            material: material.clone(),
        };
    }
    inherit(spec, &promoted);
    spec.promoted = Some(promoted);
    Ok(())
}

/// A node's axes as a support gives them: (`frame`, `axis`), both `None` for global axes.
pub type Axes = (Option<[[f64; 3]; 3]>, Option<[f64; 3]>);

/// Whether `node` is held in `dof` of the axes `axes` by a support.
pub fn holds(supports: &[SupportSpec], node: usize, dof: DofName, axes: Axes) -> bool {
    supports
        .iter()
        .any(|s| s.node == node && (s.frame, s.axis) == axes && s.fix.contains(&dof))
}

/// The axes the supports give `node` (the first framed support's; global without one).
pub fn node_axes(supports: &[SupportSpec], node: usize) -> Axes {
    supports
        .iter()
        .find(|s| s.node == node && (s.frame.is_some() || s.axis.is_some()))
        .map_or((None, None), |s| (s.frame, s.axis))
}

/// The prescribed value of an added edge midpoint in one DOF, from what its ends prescribe
/// (`a`, `b`: `Some` where prescribed) or hold (`held_a`, `held_b`, as 0): the mean when both
/// ends are prescribed, or one prescribed and the other held; none otherwise (both held: the
/// midpoint inherits the support; one free: the midpoint is free).
pub fn midpoint_value(a: Option<f64>, b: Option<f64>, held_a: bool, held_b: bool) -> Option<f64> {
    match (a, b) {
        (Some(x), Some(y)) => Some(0.5 * (x + y)),
        (Some(x), None) if held_b => Some(0.5 * x),
        (None, Some(y)) if held_a => Some(0.5 * y),
        _ => None,
    }
}

/// Supports, rigid links and prescribed displacements of the added nodes (module docs).
fn inherit(spec: &mut MeshSpec, promoted: &Promoted) {
    let mut supports = Vec::new();
    for (m, a, b) in promoted.midpoints() {
        for sa in spec.supports.iter().filter(|s| s.node == a) {
            for sb in spec
                .supports
                .iter()
                .filter(|s| s.node == b && s.frame == sa.frame && s.axis == sa.axis)
            {
                let fix: Vec<_> = sa.fix.iter().filter(|d| sb.fix.contains(d)).copied().collect();
                if !fix.is_empty() {
                    supports.push(SupportSpec {
                        node: m,
                        fix,
                        frame: sa.frame,
                        axis: sa.axis,
                    });
                }
            }
        }
    }
    // One support per node and frame: the union of what the pairs gave.
    let mut merged: Vec<SupportSpec> = Vec::new();
    for s in supports {
        match merged
            .iter_mut()
            .find(|t| t.node == s.node && t.frame == s.frame && t.axis == s.axis)
        {
            Some(t) => {
                for d in s.fix {
                    if !t.fix.contains(&d) {
                        t.fix.push(d);
                    }
                }
            }
            None => merged.push(s),
        }
    }
    spec.supports.extend(merged);
    let grow = |r: &mut RigidSpec| {
        let body: BTreeSet<usize> = r.slaves.iter().copied().chain(std::iter::once(r.master)).collect();
        for (k, ps) in promoted.parents.iter().enumerate() {
            if ps.iter().all(|p| body.contains(p)) {
                r.slaves.push(promoted.first_node + k);
            }
        }
    };
    spec.rigid_links.iter_mut().for_each(grow);
    for e in &mut spec.elements {
        if let ElementSpec::Rigid { master, slaves } = e {
            let mut r = RigidSpec {
                master: *master,
                slaves: std::mem::take(slaves),
            };
            grow(&mut r);
            *slaves = r.slaves;
        }
    }
    let supports = &spec.supports[..promoted.first_support];
    for c in &mut spec.load_cases {
        let mut added = Vec::new();
        for (m, a, b) in promoted.midpoints() {
            // Each DOF (and frame) prescribed at either end.
            for d in c.displacements.iter().filter(|d| d.node == a || d.node == b) {
                let (other, this_a) = if d.node == a { (b, true) } else { (a, false) };
                let at_other = c
                    .displacements
                    .iter()
                    .find(|o| o.node == other && o.dof == d.dof && o.frame == d.frame && o.axis == d.axis);
                // A pair prescribed at both ends is taken once, from its `a` end.
                if at_other.is_some() && !this_a {
                    continue;
                }
                let held = holds(supports, other, d.dof, (d.frame, d.axis));
                let (va, vb) = if this_a {
                    (Some(d.value), at_other.map(|o| o.value))
                } else {
                    (at_other.map(|o| o.value), Some(d.value))
                };
                let (ha, hb) = if this_a { (false, held) } else { (held, false) };
                if let Some(v) = midpoint_value(va, vb, ha, hb) {
                    let mut p = d.clone();
                    p.node = m;
                    p.value = v;
                    added.push(p);
                }
            }
        }
        c.displacements.extend(added);
    }
}
