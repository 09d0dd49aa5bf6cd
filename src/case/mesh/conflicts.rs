//! Checks of a built model that the solver would otherwise find only at `run`: conflicting
//! constraints (rigid links, joints, supports, prescribed displacements) and elements too short
//! for the model's size. Each error names the JSON path of the later of the two conflicting
//! items. The solver's own checks ([`crate::fem::constraints::DofMap::new`]) stay as a backstop
//! for models built in code; these are the same rules, located in the case file.

use super::lookup::{norm, Ctx};
use super::shapes::ElementSpec;
use crate::case::error::CaseError;
use crate::fem::{self, NodeDof};
use std::collections::BTreeMap;

/// Length, relative to the model size (bounding-box diagonal), below which an element between
/// two nodes is refused: its stiffness ~1/L³ would swamp the rest of the model in f64.
pub const SHORTEST: f64 = 1e-9;

/// Refuses an element whose nodes (two of them at least: beam, hinge, shell4 edge) are closer
/// than [`SHORTEST`] of the model size `size`, mm. Springs and joints join coincident nodes by
/// definition, and a triangle given as `[a, b, c, c]` repeats its last node, so those pairs
/// are not checked.
pub(super) fn element_length(cx: &Ctx, p: &str, e: &ElementSpec, size: f64) -> Result<(), CaseError> {
    let pairs: Vec<(usize, usize)> = match e {
        ElementSpec::Beam { nodes, .. } | ElementSpec::Hinge { nodes, .. } => vec![(nodes[0], nodes[1])],
        ElementSpec::Shell4 { nodes, .. } => (0..4)
            .map(|k| (nodes[k], nodes[(k + 1) % 4]))
            .filter(|(a, b)| a != b)
            .collect(),
        // Each half edge: corner to midpoint to corner.
        ElementSpec::Shell9 { nodes, .. } => (0..4)
            .flat_map(|k| [(nodes[k], nodes[4 + k]), (nodes[4 + k], nodes[(k + 1) % 4])])
            .collect(),
        _ => Vec::new(),
    };
    let tol = SHORTEST * size;
    for (a, b) in pairs {
        let (Some(xa), Some(xb)) = (cx.spec.nodes.get(a), cx.spec.nodes.get(b)) else {
            continue; // an index out of range is named by the element's own check
        };
        if a == b {
            continue;
        }
        let len = norm([xb[0] - xa[0], xb[1] - xa[1], xb[2] - xa[2]]);
        if len < tol {
            return Err(CaseError::value(
                format!("{p}.nodes"),
                format!("[{a}, {b}]"),
                format!(
                    "nodes {a} and {b} are {len:e} mm apart; an element must be at least {SHORTEST:e} of the model size ({tol:e} mm) long"
                ),
            ));
        }
    }
    Ok(())
}

/// Refuses conflicting constraints of `model`: `rigid_paths` and `tie_paths` are the JSON paths
/// of its rigid links and ties, in model order; the supports from `first_support` on and the
/// displacements of load cases are those of the case (`supports[i]`,
/// `load_cases[c].displacements[k]`), in order (the supports before are a superelement's, on
/// its own modal nodes).
pub(super) fn constraint_conflicts(
    model: &fem::Model,
    rigid_paths: &[String],
    tie_paths: &[String],
    first_support: usize,
) -> Result<(), CaseError> {
    let at = |paths: &[String], i: usize| paths.get(i).cloned().unwrap_or_else(|| "elements".into());
    // Rigid links: a slave follows one master, which is not itself a slave.
    let mut slave_of: BTreeMap<usize, usize> = BTreeMap::new();
    for (il, link) in model.rigid_links.iter().enumerate() {
        for (k, &s) in link.slaves.iter().enumerate() {
            let here = format!("{}.slaves[{k}]", at(rigid_paths, il));
            if s == link.master {
                return Err(CaseError::value(
                    here,
                    s,
                    "the link's master cannot be its own slave: list only the nodes that follow it",
                ));
            }
            if let Some(&other) = slave_of.get(&s) {
                let why = if other == il {
                    "this node is listed twice as a slave of this link: list each slave once".to_string()
                } else {
                    format!(
                        "this node is already a slave of `{}` (master {}); a node follows one master",
                        at(rigid_paths, other),
                        model.rigid_links[other].master
                    )
                };
                return Err(CaseError::value(here, s, why));
            }
            slave_of.insert(s, il);
        }
    }
    for (il, link) in model.rigid_links.iter().enumerate() {
        if let Some(&other) = slave_of.get(&link.master) {
            return Err(CaseError::value(
                format!("{}.master", at(rigid_paths, il)),
                link.master,
                format!(
                    "this node is a slave of `{}` (master {}); chained rigid links are not resolved: list these slaves under master {} instead",
                    at(rigid_paths, other),
                    model.rigid_links[other].master,
                    model.rigid_links[other].master
                ),
            ));
        }
    }
    let slave_rule = |node: usize, what: &str| {
        let il = slave_of[&node];
        format!(
            "node {node} is a slave of `{}`, whose master {} fixes its motion: {what} the master instead",
            at(rigid_paths, il),
            model.rigid_links[il].master
        )
    };
    // Ties (joints): not on slaves, each DOF tied once.
    let mut tied_by: BTreeMap<usize, usize> = BTreeMap::new();
    for (it, t) in model.ties.iter().enumerate() {
        let here = format!("{}.nodes", at(tie_paths, it));
        for node in [t.a, t.b] {
            if slave_of.contains_key(&node) {
                return Err(CaseError::value(
                    here,
                    format!("[{}, {}]", t.a, t.b),
                    slave_rule(node, "join"),
                ));
            }
        }
        for d in (0..6).filter(|&d| t.dofs[d]) {
            if let Some(other) = tied_by.insert(6 * t.b + d, it) {
                return Err(CaseError::value(
                    here,
                    format!("[{}, {}]", t.a, t.b),
                    format!(
                        "{} is already joined by `{}`: one joint per node pair (redundant joints)",
                        NodeDof::from_global(6 * t.b + d),
                        at(tie_paths, other)
                    ),
                ));
            }
        }
    }
    let tied_rule = |g: usize| {
        let it = tied_by[&g];
        let t = &model.ties[it];
        format!(
            "{} is tied to node {} by `{}`: constrain node {} instead (a tied DOF follows it)",
            NodeDof::from_global(g),
            t.a,
            at(tie_paths, it),
            t.a
        )
    };
    for (i, s) in model.supports.iter().skip(first_support).enumerate() {
        if slave_of.contains_key(&s.node) {
            return Err(CaseError::value(
                format!("supports[{i}].node"),
                s.node,
                slave_rule(s.node, "support"),
            ));
        }
        if let Some(g) = (0..6)
            .filter(|&d| s.fix[d])
            .map(|d| 6 * s.node + d)
            .find(|g| tied_by.contains_key(g))
        {
            return Err(CaseError::value(format!("supports[{i}].node"), s.node, tied_rule(g)));
        }
    }
    for (ic, c) in model.load_cases.iter().enumerate() {
        for (k, d) in c.displacements.iter().enumerate() {
            let here = format!("load_cases[{ic}].displacements[{k}]");
            let g = 6 * d.node + d.dof.index();
            if slave_of.contains_key(&d.node) {
                return Err(CaseError::value(
                    format!("{here}.node"),
                    d.node,
                    slave_rule(d.node, "prescribe"),
                ));
            }
            if tied_by.contains_key(&g) {
                return Err(CaseError::value(format!("{here}.node"), d.node, tied_rule(g)));
            }
            if let Some(j) = c.displacements[..k]
                .iter()
                .position(|e| e.node == d.node && e.dof == d.dof)
            {
                return Err(CaseError::value(
                    format!("{here}.dof"),
                    d.dof,
                    format!(
                        "{} is already prescribed by `load_cases[{ic}].displacements[{j}]`: prescribe each DOF once per load case",
                        NodeDof::from_global(g)
                    ),
                ));
            }
        }
    }
    Ok(())
}
