//! Builds the load cases of a model from their shapes ([`super::load_shapes`]).

use super::frames;
use super::load_shapes::DofName;
use super::load_shapes::LoadCaseSpec;
use super::lookup::Ctx;
use crate::case::error::{check, CaseError};
use crate::fem;

/// Builds load case `c` (at JSON path `p`) on the model built so far.
pub(super) fn load_case(cx: &mut Ctx, p: &str, c: &LoadCaseSpec) -> Result<fem::LoadCase, CaseError> {
    let mut lc = fem::LoadCase::new(c.name.clone());
    for (i, f) in c.forces.iter().enumerate() {
        let node = cx.node(format!("{p}.forces[{i}].node"), f.node)?;
        for (k, v) in f.f.iter().enumerate() {
            check::finite(format_args!("{p}.forces[{i}].F[{k}]"), *v)?;
        }
        let fp = format!("{p}.forces[{i}]");
        let f = match frames::local(&fp, f.frame, f.axis)? {
            Some(l) => frames::to_global(&l.rows, f.f),
            None => f.f,
        };
        lc = lc.force(node, f);
    }
    for (i, d) in c.displacements.iter().enumerate() {
        let node = cx.node(format!("{p}.displacements[{i}].node"), d.node)?;
        check::finite(format_args!("{p}.displacements[{i}].value"), d.value)?;
        let dp = format!("{p}.displacements[{i}]");
        match frames::local(&dp, d.frame, d.axis)? {
            Some(l) => {
                if l.axis_only && !matches!(d.dof, DofName::Ux | DofName::Rx) {
                    return Err(CaseError::value(
                        format!("{dp}.dof"),
                        format!("{:?}", d.dof).to_lowercase(),
                        "with `axis` only ux (along it) or rx (about it) is defined; give `frame` for another direction",
                    ));
                }
                let at = format!("{dp}.{}", if l.axis_only { "axis" } else { "frame" });
                if !cx.model.frames.contains_key(&node)
                    && cx
                        .model
                        .supports
                        .iter()
                        .any(|s| s.node == node && s.fix.iter().filter(|&&x| x).count() < 6)
                {
                    return Err(CaseError::value(
                        at,
                        format!("{:?}", l.rows),
                        format!("node {node} has a partial support in global axes, which this frame would turn: give the support the same frame"),
                    ));
                }
                frames::set_node_frame(cx, &at, node, l.rows)?;
            }
            None if cx.model.frames.contains_key(&node) => {
                let owner = cx.frame_owner.get(&node).cloned().unwrap_or_default();
                return Err(CaseError::value(
                    format!("{dp}.node"),
                    node,
                    format!("this node carries the frame of `{owner}`, in which a prescribed DOF would act: give the displacement that `frame`, or prescribe it at another node"),
                ));
            }
            None => {}
        }
        // Case files give rotations in degrees; the model works in radians.
        let value = match d.dof {
            DofName::Rx | DofName::Ry | DofName::Rz => d.value.to_radians(),
            DofName::Ux | DofName::Uy | DofName::Uz => d.value,
        };
        lc = lc.displacement(node, d.dof.dof(), value);
    }
    for (i, pr) in c.pressures.iter().enumerate() {
        let pp = format!("{p}.pressures[{i}]");
        check::finite(format_args!("{pp}.p"), pr.p)?;
        let mut list: Vec<(String, usize)> = Vec::new();
        for (k, &e) in pr.elements.iter().enumerate() {
            let at = format!("{pp}.elements[{k}]");
            let me = cx.model_index.get(e).copied().flatten();
            match me.and_then(|m| cx.model.elements.get(m)) {
                Some(fem::Element::Shell4(_) | fem::Element::Shell9(_)) => list.push((at, me.unwrap_or(e))),
                Some(_) => {
                    return Err(CaseError::value(
                        at,
                        e,
                        "a pressure acts on shell4 and shell9 elements only",
                    ))
                }
                None if e < cx.spec.elements.len() => {
                    return Err(CaseError::value(
                        at,
                        e,
                        "a pressure acts on shell4 and shell9 elements only",
                    ))
                }
                None => {
                    return Err(CaseError::value(
                        at,
                        e,
                        format!(
                            "element index must be < {} (the number of elements)",
                            cx.spec.elements.len()
                        ),
                    ))
                }
            }
        }
        if let Some(gname) = &pr.group {
            let at = format!("{pp}.group");
            if cx.spec.element_groups.is_empty() {
                return Err(CaseError::value(
                    at,
                    format!("\"{gname}\""),
                    "a group names a Gmsh physical group: only with a .msh mesh; give `elements` otherwise",
                ));
            }
            let before = list.len();
            for (e, groups) in cx.spec.element_groups.iter().enumerate() {
                let Some(me) = cx.model_index.get(e).copied().flatten() else {
                    continue;
                };
                if groups.iter().any(|g| g == gname)
                    && matches!(
                        cx.model.elements.get(me),
                        Some(fem::Element::Shell4(_) | fem::Element::Shell9(_))
                    )
                {
                    list.push((at.clone(), me));
                }
            }
            if list.len() == before {
                return Err(CaseError::value(
                    at,
                    format!("\"{gname}\""),
                    "no shell element of the model belongs to this group (it must be listed in `gmsh.groups` and hold triangles or quadrangles)",
                ));
            }
        }
        if list.is_empty() {
            return Err(CaseError::new(
                pp,
                "give the loaded shells by `elements` and/or `group`",
            ));
        }
        for (at, e) in list {
            match cx.model.elements.get(e) {
                Some(fem::Element::Shell4(sh)) => {
                    let x = sh.nodes.map(|n| cx.model.nodes[n]);
                    let f = fem::shell_loads::pressure_loads(&x, pr.p)
                        .ok_or_else(|| CaseError::value(at, e, "degenerate shell geometry"))?;
                    for (k, &n) in sh.nodes.iter().enumerate() {
                        lc = lc.force(n, f[k]);
                    }
                }
                Some(fem::Element::Shell9(sh)) => {
                    let x = sh.nodes.map(|n| cx.model.nodes[n]);
                    let f = fem::shell9::shell9_pressure_loads(&x, pr.p)
                        .map_err(|err| CaseError::value(at, e, err.to_string()))?;
                    for (k, &n) in sh.nodes.iter().enumerate() {
                        lc = lc.force(n, f[k]);
                    }
                }
                _ => continue,
            }
        }
    }
    for (i, el) in c.edge_loads.iter().enumerate() {
        let pe = format!("{p}.edge_loads[{i}]");
        let a = cx.node(format!("{pe}.nodes[0]"), el.nodes[0])?;
        let b = cx.node(format!("{pe}.nodes[1]"), el.nodes[1])?;
        for (k, v) in el.q.iter().chain(&el.m).enumerate() {
            let name = if k < 3 {
                format!("q[{k}]")
            } else {
                format!("m[{}]", k - 3)
            };
            check::finite(format_args!("{pe}.{name}"), *v)?;
        }
        // A four-node shell's edge, or two corners of a nine-node shell's edge (its midpoint).
        let on_edge = |nodes: &[usize]| (0..4).find(|&k| same_edge(nodes[k], nodes[(k + 1) % 4], a, b));
        let edge: Option<Option<usize>> = cx.model.elements.iter().find_map(|e| match e {
            fem::Element::Shell4(sh) => on_edge(&sh.nodes).map(|_| None),
            fem::Element::Shell9(sh) => on_edge(&sh.nodes).map(|k| Some(sh.nodes[4 + k])),
            _ => None,
        });
        match edge {
            None => {
                return Err(CaseError::value(
                    format!("{pe}.nodes"),
                    format!("[{a}, {b}]"),
                    "must be two nodes adjacent in the node list of a shell4 element, or two corners of one edge of a shell9 element (its midpoint node is loaded too)",
                ))
            }
            Some(None) => {
                let f = fem::shell_loads::edge_loads(cx.model.nodes[a], cx.model.nodes[b], el.q, el.m);
                lc = lc.force(a, f[0]).force(b, f[1]);
            }
            Some(Some(mid)) => {
                let x = &cx.model.nodes;
                let f = fem::shell_loads::edge_loads3(x[a], x[mid], x[b], el.q, el.m);
                lc = lc.force(a, f[0]).force(mid, f[1]).force(b, f[2]);
            }
        }
    }
    super::build_body_loads::body_loads(cx, p, c, &mut lc)?;
    Ok(lc)
}

/// Whether the element edge x–y (distinct nodes) joins `a` and `b`, in either direction.
fn same_edge(x: usize, y: usize, a: usize, b: usize) -> bool {
    x != y && ((x, y) == (a, b) || (x, y) == (b, a))
}
