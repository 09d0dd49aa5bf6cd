//! The summary that opens the Markdown report of a `static` result: per load case the headline
//! stress and utilisation with the element that carries each, the displacements of the loaded
//! and prescribed nodes, the total reaction and the load case's warnings.

use super::{StaticCaseRow, StaticResult};
use crate::report::markdown::{num, Table};

/// Significant digits of the report's numbers.
pub const DIGITS: usize = 5;

/// Loaded and prescribed nodes listed in a load case's summary (the rest: the node table).
const LISTED_NODES: usize = 12;

/// The header of a node displacement table.
pub const NODE_HEADER: [&str; 7] = ["node", "ux (mm)", "uy (mm)", "uz (mm)", "rx (°)", "ry (°)", "rz (°)"];

/// One row of a node displacement table.
pub fn node_row(node: usize, d: &[f64; 6]) -> Vec<String> {
    std::iter::once(node.to_string())
        .chain(d.iter().map(|v| num(*v, DIGITS)))
        .collect()
}

/// The `## Summary` section: one subsection per load case.
pub fn section(r: &StaticResult) -> String {
    let mut md = String::from("## Summary\n\n");
    for c in &r.load_cases {
        md += &load_case(c);
    }
    md
}

fn load_case(c: &StaticCaseRow) -> String {
    let mut md = format!("### Load case `{}`\n\n", c.name);
    md += &match &c.max_von_mises_at {
        Some(t) => format!(
            "- Maximum von Mises stress: {} MPa at element {} ({}).\n",
            num(t.von_mises, DIGITS),
            t.element,
            t.kind
        ),
        None => "- Maximum von Mises stress: none (no element of the model carries a stress: springs, joints, rigid links, superelements only).\n".to_string(),
    };
    md += &match &c.max_utilisation {
        Some(u) => format!(
            "- Maximum utilisation (von Mises / allowable): {} at element {} ({}; {} MPa against {} MPa){}.\n",
            num(u.value, 4),
            u.element,
            u.kind,
            num(u.von_mises, DIGITS),
            num(u.allowable, DIGITS),
            if u.value > 1.0 {
                ", **above the allowable stress**"
            } else {
                ""
            }
        ),
        None => {
            "- Maximum utilisation: not defined (no stressed element's material has an allowable stress).\n".to_string()
        }
    };
    md += "\n";
    md += &principal_extremes(c);
    if c.loaded_nodes.is_empty() {
        md += "No nodal loads or prescribed displacements (distributed loads only).\n\n";
    } else {
        md += "Displacements of the loaded and prescribed nodes:\n\n";
        let mut t = Table::new(&NODE_HEADER);
        for &n in c.loaded_nodes.iter().take(LISTED_NODES) {
            if let Some(d) = c.displacements.get(n) {
                t.row(node_row(n, d));
            }
        }
        md += &t.render();
        if c.loaded_nodes.len() > LISTED_NODES {
            md += &format!(
                "\n({} more loaded or prescribed nodes: see the node displacements.)\n",
                c.loaded_nodes.len() - LISTED_NODES
            );
        }
        md += "\n";
    }
    // The prescribed nodes carry the force that imposes their motion: listed before the total
    // (supports, ground springs and prescribed DOFs, which balances the applied loads).
    md += "Reactions (the prescribed nodes', and the total of supports, ground springs and prescribed DOFs about the global origin):\n\n";
    let mut t = Table::new(&[
        "node",
        "Fx (N)",
        "Fy (N)",
        "Fz (N)",
        "Mx (N·mm)",
        "My (N·mm)",
        "Mz (N·mm)",
    ]);
    for (n, r) in c.reaction_nodes.iter().zip(&c.reactions) {
        if c.loaded_nodes.binary_search(n).is_ok() {
            t.row(node_row(*n, r));
        }
    }
    t.row(
        std::iter::once("total".to_string())
            .chain(c.total_reaction.iter().map(|v| num(*v, DIGITS)))
            .collect(),
    );
    md += &t.render();
    md += "\n";
    for w in &c.warnings {
        md += &format!("> **Warning**: {w}\n\n");
    }
    md
}

/// Markdown lines with the largest and smallest principal shell stresses of a load case and
/// where they occur (node, surface); empty without shells.
fn principal_extremes(c: &StaticCaseRow) -> String {
    let Some(ss) = &c.shell_stress else {
        return String::new();
    };
    let mut hi: Option<(f64, usize, &str)> = None;
    let mut lo: Option<(f64, usize, &str)> = None;
    for (name, list) in [("top", &ss.top), ("mid", &ss.mid), ("bottom", &ss.bottom)] {
        for (node, s) in list.iter().enumerate() {
            let Some(s) = s else { continue };
            let p = crate::fem::shell_recovery::principal(s);
            if hi.is_none_or(|h| p[2] > h.0) {
                hi = Some((p[2], node, name));
            }
            if lo.is_none_or(|l| p[0] < l.0) {
                lo = Some((p[0], node, name));
            }
        }
    }
    match (hi, lo) {
        (Some(h), Some(l)) => format!(
            "Shells, extreme principal stresses (nodal averages): largest σ₁ = {} MPa at node {} ({} surface); smallest σ₃ = {} MPa at node {} ({} surface).\n\n",
            num(h.0, DIGITS), h.1, h.2, num(l.0, DIGITS), l.1, l.2
        ),
        _ => String::new(),
    }
}
