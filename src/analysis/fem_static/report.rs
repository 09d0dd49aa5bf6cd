//! Markdown/CSV views and `.vtu` files of a `static` result.

use super::{stability_warning, ComplianceRow, StaticCaseRow, StaticResult};
use crate::analysis::{AnalysisError, Report};
use crate::fem::{self, Model};
use crate::report::markdown::Table;

/// Markdown/CSV views.
pub fn report(r: &StaticResult) -> Report {
    let nonlinear = r
        .model
        .first()
        .is_some_and(|m| m.starts_with("geometrically nonlinear"));
    let mut md = String::from(if nonlinear {
        "# Geometrically nonlinear static analysis\n\n"
    } else {
        "# Linear static analysis\n\n"
    });
    let mut csv = String::from("load_case,node,ux_mm,uy_mm,uz_mm,rx_deg,ry_deg,rz_deg\n");
    for c in &r.load_cases {
        md += &format!("## Load case `{}`\n\n", c.name);
        if let Some(w) = stability_warning(&c.name, c.stable, c.critical_load_factor) {
            md += &w;
        }
        if let Some(s) = c.max_von_mises {
            md += &format!("Maximum von Mises stress: {s:.3} MPa.\n\n");
        }
        md += &principal_extremes(c);
        let mut t = Table::new(&["node", "ux (mm)", "uy (mm)", "uz (mm)", "rx (°)", "ry (°)", "rz (°)"]);
        for (i, d) in c.displacements.iter().enumerate() {
            let mut row = vec![i.to_string()];
            row.extend(d.iter().map(|v| format!("{v:.6e}")));
            t.row(row);
            csv += &format!("{},{i},{},{},{},{},{},{}\n", c.name, d[0], d[1], d[2], d[3], d[4], d[5]);
        }
        if c.displacements.len() <= 200 {
            md += &t.render();
        } else {
            md += &format!("({} nodes: see result.csv)\n", c.displacements.len());
        }
        md += "\n";
        md += &hinge_table(c);
        if let Some(t) = &c.track {
            md += &crate::analysis::track::markdown(t);
        }
        md += &crate::analysis::path_rows::markdown(&c.name, &c.critical_points, c.trace.as_ref());
    }
    md += &compliance_section(&r.compliance);
    Report { markdown: md, csv }
}

/// The Markdown section of the requested node compliances (empty without).
fn compliance_section(rows: &[ComplianceRow]) -> String {
    if rows.is_empty() {
        return String::new();
    }
    let mut md = String::from(
        "## Node compliance\n\nLinear, undeformed model with its supports; C[i][j] = displacement i per unit load j, [ux, uy, uz, rx, ry, rz] × [Fx, Fy, Fz, Mx, My, Mz] in the given frame: mm/N, mm/(N·mm), rad/N, rad/(N·mm).\n\n",
    );
    for c in rows {
        md += &format!(
            "### Node {}\n\nFrame rows (local x, y, z): {:?}. Translational eigenvalues {:.6e} … {:.6e} mm/N; rotational {:.6e} … {:.6e} rad/(N·mm).\n\n",
            c.node,
            c.frame,
            c.translational_eigen[0],
            c.translational_eigen[1],
            c.rotational_eigen[0],
            c.rotational_eigen[1]
        );
        let mut t = Table::new(&["", "Fx", "Fy", "Fz", "Mx", "My", "Mz"]);
        for (i, name) in ["ux", "uy", "uz", "rx", "ry", "rz"].iter().enumerate() {
            let mut row = vec![name.to_string()];
            row.extend(c.matrix[i].iter().map(|v| format!("{v:.6e}")));
            t.row(row);
        }
        md += &t.render();
        md += "\n";
    }
    md
}

/// The Markdown table of a load case's hinge elements (empty without hinges).
fn hinge_table(c: &StaticCaseRow) -> String {
    if c.hinges.is_empty() {
        return String::new();
    }
    let mut t = Table::columns("element | rotation (°) | peak von Mises (MPa) | utilisation | remaining rotation (°) | My a (N·mm) | My b (N·mm)");
    for h in &c.hinges {
        let rem = if h.remaining_rotation_deg.is_finite() {
            format!("{:.4}", h.remaining_rotation_deg)
        } else {
            "unbounded".to_string()
        };
        t.row(vec![
            h.element.to_string(),
            format!("{:.6}", h.rotation_deg),
            format!("{:.4}", h.peak_von_mises),
            format!("{:.4}", h.utilisation),
            rem,
            format!("{:.6e}", h.end_forces[0][4]),
            format!("{:.6e}", h.end_forces[1][4]),
        ]);
    }
    format!(
        "Hinge elements (rotation about the compliant axis, local y; remaining rotation to the allowable stress by linear extrapolation):\n\n{}\n",
        t.render()
    )
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
            let p = fem::shell_recovery::principal(s);
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
            "Shells, extreme principal stresses (nodal averages): largest σ₁ = {:.4} MPa at node {} ({} surface); smallest σ₃ = {:.4} MPa at node {} ({} surface).\n\n",
            h.0, h.1, h.2, l.0, l.1, l.2
        ),
        _ => String::new(),
    }
}

/// A `.vtu` of one load case (see [`crate::analysis::vtu`]): the undeformed model with displacement and
/// rotation point data, shell stresses and stress resultants
/// ([`crate::analysis::vtu::static_vtu_with_shells`]) and von Mises per cell (the element's maximum over its ends / shell
/// surfaces; `cell_stress` overrides it for given elements, e.g. hinge peak stresses; 0 where
/// none).
pub fn vtu(model: &Model, case: &fem::CaseResult, cell_stress: &[(usize, f64)]) -> Result<String, AnalysisError> {
    let shells = fem::shell_recovery::shell_field(model, &case.displacements)
        .map_err(|e| AnalysisError::new(format!("load case `{}`", case.name), e.to_string()))?;
    crate::analysis::vtu::static_vtu_with_shells(
        model,
        &case.displacements,
        &von_mises_of(case, cell_stress),
        &Default::default(),
        Some(&shells),
    )
}

/// Von Mises of element `ie` (MPa): `cell_stress` if it lists the element, else the element's
/// own maximum, else 0.
pub fn von_mises_of<'a>(case: &'a fem::CaseResult, cell_stress: &'a [(usize, f64)]) -> impl Fn(usize) -> f64 + 'a {
    move |ie| {
        cell_stress
            .iter()
            .find(|(i, _)| *i == ie)
            .map(|(_, v)| *v)
            .or_else(|| case.elements.get(ie).and_then(|r| r.max_von_mises()))
            .unwrap_or(0.0)
    }
}

/// One `.vtu` per load case, named after the load case (names are unique as file names: the
/// case validation refuses duplicates).
pub fn vtu_files(model: &Model, res: &fem::StaticResults) -> Result<crate::analysis::Files, AnalysisError> {
    res.load_cases
        .iter()
        .map(|c| Ok((format!("{}.vtu", file_stem(&c.name)), vtu(model, c, &[])?.into_bytes())))
        .collect()
}

/// A file name made of the safe characters of `name`.
pub fn file_stem(name: &str) -> String {
    crate::report::vtk::file_stem(name)
}
