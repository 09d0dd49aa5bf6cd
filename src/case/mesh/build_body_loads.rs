//! Builds gravity, beam line loads and group forces of a load case ([`super::load_shapes`])
//! with [`crate::fem::loads`].

use super::load_shapes::{LineAxes, LoadCaseSpec};
use super::lookup::Ctx;
use crate::case::error::{check, CaseError};
use crate::fem::{self, loads};

/// Adds the `gravity`, `line_loads` and `group_forces` of load case `c` (JSON path `p`).
pub(super) fn body_loads(cx: &Ctx, p: &str, c: &LoadCaseSpec, lc: &mut fem::LoadCase) -> Result<(), CaseError> {
    if let Some(g) = c.gravity {
        for (k, v) in g.iter().enumerate() {
            check::finite(format_args!("{p}.gravity[{k}]"), *v)?;
        }
        let at = format!("{p}.gravity");
        let f = loads::gravity_loads(&cx.model, g).map_err(|e| CaseError::new(at.clone(), e.to_string()))?;
        if g.iter().any(|v| *v != 0.0) && f.iter().flatten().all(|v| *v == 0.0) {
            return Err(CaseError::value(
                at,
                format!("{g:?}"),
                "the model has no mass to weigh (give the materials a density or add point masses)",
            ));
        }
        loads::add_to_case(lc, f.into_iter().enumerate());
    }
    for (i, ll) in c.line_loads.iter().enumerate() {
        let pl = format!("{p}.line_loads[{i}]");
        for (k, v) in ll.q.iter().enumerate() {
            check::finite(format_args!("{pl}.q[{k}]"), *v)?;
        }
        let at = format!("{pl}.element");
        let n = cx.spec.elements.len();
        if ll.element >= n {
            return Err(CaseError::value(
                at,
                ll.element,
                format!("element index must be < {n} (the number of elements)"),
            ));
        }
        let me = cx.model_index.get(ll.element).copied().flatten();
        let Some(ie) = me.filter(|&m| matches!(cx.model.elements.get(m), Some(fem::Element::Beam(_)))) else {
            return Err(CaseError::value(
                at,
                ll.element,
                "a line load acts on beam elements only",
            ));
        };
        let axes = match ll.axes {
            LineAxes::Global => loads::LoadAxes::Global,
            LineAxes::Local => loads::LoadAxes::Local,
        };
        let f =
            loads::beam_line_load(&cx.model, ie, ll.q, axes).map_err(|e| CaseError::new(pl.clone(), e.to_string()))?;
        let fem::Element::Beam(b) = &cx.model.elements[ie] else {
            continue;
        };
        loads::add_to_case(lc, [(b.nodes[0], f[0]), (b.nodes[1], f[1])]);
    }
    for (i, gf) in c.group_forces.iter().enumerate() {
        let pg = format!("{p}.group_forces[{i}]");
        for (k, v) in gf.f.iter().enumerate() {
            check::finite(format_args!("{pg}.F[{k}]"), *v)?;
        }
        let cells: Vec<Vec<usize>> = match (&gf.group, gf.nodes.is_empty()) {
            (Some(_), false) | (None, true) => {
                return Err(CaseError::new(
                    pg,
                    "give the loaded nodes by `group` or by `nodes` (exactly one)",
                ))
            }
            (None, false) => {
                let mut cells = Vec::with_capacity(gf.nodes.len());
                for (k, &n) in gf.nodes.iter().enumerate() {
                    let at = format!("{pg}.nodes[{k}]");
                    let n = cx.node(at.clone(), n)?;
                    if gf.nodes[..k].contains(&n) {
                        return Err(CaseError::value(at, n, "each node once"));
                    }
                    cells.push(vec![n]);
                }
                cells
            }
            (Some(gname), true) => {
                let at = format!("{pg}.group");
                if cx.spec.group_cells.is_empty() && cx.spec.element_groups.is_empty() {
                    return Err(CaseError::value(
                        at,
                        format!("\"{gname}\""),
                        "a group names a Gmsh physical group: only with a .msh mesh; give `nodes` otherwise",
                    ));
                }
                match cx.spec.group_cells.get(gname) {
                    Some(c) => c.clone(),
                    None if cx.spec.element_groups.iter().any(|g| g.iter().any(|n| n == gname)) => {
                        return Err(CaseError::value(
                            at,
                            format!("\"{gname}\""),
                            "the group holds only second-order elements (nine-node quadrangles, three-node lines): a group force is spread over points, first-order lines, triangles and quadrangles only; load it with `pressures` or nodal `forces`",
                        ));
                    }
                    None => {
                        let known: Vec<&String> = cx.spec.group_cells.keys().collect();
                        return Err(CaseError::value(
                            at,
                            format!("\"{gname}\""),
                            format!(
                                "no points, first-order lines, triangles or quadrangles of a group of that name; list the group in `gmsh.groups` (`{{}}` is enough); loadable groups: {known:?}"
                            ),
                        ));
                    }
                }
            }
        };
        let spread = loads::tributary_weights(&cx.model, &cells)
            .and_then(|w| loads::spread_total(&cx.model, &w, gf.f))
            .map_err(|e| CaseError::new(pg.clone(), e.to_string()))?;
        loads::add_to_case(lc, spread);
    }
    Ok(())
}
