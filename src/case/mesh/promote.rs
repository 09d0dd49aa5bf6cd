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
    // A quadrangle the four-node shell refuses (not convex, zero area, non-finite corners): left
    // as written, so that the build names what is wrong with it.
    if quads
        .iter()
        .any(|(_, q)| crate::fem::shell::shell_geometry(&q.map(|a| spec.nodes[a])).is_none())
    {
        return Ok(());
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

/// The prescribed value of an added edge midpoint in one DOF, from the value `this` one end of
/// its edge prescribes and what the other end does: the mean with the value it prescribes
/// (`other`), or with 0 where it holds the DOF (`other_held`); none where it is free (the
/// midpoint is then free too).
pub fn midpoint_value(this: f64, other: Option<f64>, other_held: bool) -> Option<f64> {
    match other {
        Some(y) => Some(0.5 * (this + y)),
        None => other_held.then_some(0.5 * this),
    }
}

/// One prescription an added edge midpoint takes from its edge's ends.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct EdgePrescription {
    /// The added midpoint.
    pub midpoint: usize,
    /// The item prescribed at one end of the edge.
    pub item: usize,
    /// The other end.
    pub other: usize,
    /// The item prescribing the same DOF at the other end, if one does.
    pub paired: Option<usize>,
}

/// For each added edge midpoint, the items of `n` (`key(i)`: the node and the DOF an item
/// prescribes) prescribed at either end of its edge; an item paired with one at the other end
/// comes once, as the lower index. Shared by the static prescribed displacements and the
/// transient motions.
pub fn edge_prescriptions<K: PartialEq>(
    promoted: &Promoted,
    n: usize,
    key: impl Fn(usize) -> (usize, K),
) -> Vec<EdgePrescription> {
    let mut out = Vec::new();
    for (midpoint, a, b) in promoted.midpoints() {
        for item in 0..n {
            let (node, dof) = key(item);
            if node != a && node != b {
                continue;
            }
            let other = if node == a { b } else { a };
            let paired = (0..n).find(|&j| {
                let (o, d) = key(j);
                o == other && d == dof
            });
            if paired.is_some_and(|j| j < item) {
                continue;
            }
            out.push(EdgePrescription {
                midpoint,
                item,
                other,
                paired,
            });
        }
    }
    out
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
        let ds = &c.displacements;
        let added: Vec<_> = edge_prescriptions(promoted, ds.len(), |i| {
            (ds[i].node, (ds[i].dof, ds[i].frame, ds[i].axis))
        })
        .into_iter()
        .filter_map(|e| {
            let d = &ds[e.item];
            let held = holds(supports, e.other, d.dof, (d.frame, d.axis));
            let value = midpoint_value(d.value, e.paired.map(|j| ds[j].value), held)?;
            let mut p = d.clone();
            p.node = e.midpoint;
            p.value = value;
            Some(p)
        })
        .collect();
        c.displacements.extend(added);
    }
}
