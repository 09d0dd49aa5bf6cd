//! Markdown/CSV views and `.vtu` files of a `static` result.

use super::summary::{self, DIGITS};
use super::{ComplianceRow, StaticCaseRow, StaticResult};
use crate::analysis::{AnalysisError, Report};
use crate::fem::{self, Model};
use crate::report::markdown::{num, Table};

/// Markdown/CSV views: the summary of every load case first, then the per-load-case details
/// (hinge elements, path tracking), the node compliances and last the node displacements.
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
    md += &summary::section(r);
    for c in &r.load_cases {
        let details = hinge_table(c)
            + &c.track.as_ref().map(super::track::markdown).unwrap_or_default()
            + &super::path_rows::markdown(&c.name, &c.critical_points, c.trace.as_ref());
        if !details.is_empty() {
            md += &format!("## Load case `{}`\n\n{details}", c.name);
        }
    }
    md += &compliance_section(&r.compliance);
    let (nodes, csv) = node_section(r);
    md += &nodes;
    Report { markdown: md, csv }
}

/// The `## Node displacements` section (the last of the report) and the CSV of every node.
fn node_section(r: &StaticResult) -> (String, String) {
    let mut md = format!("## Node displacements\n\nGlobal axes; {}.\n\n", r.units.displacements);
    let mut csv = String::from("load_case,node,ux_mm,uy_mm,uz_mm,rx_deg,ry_deg,rz_deg\n");
    for c in &r.load_cases {
        md += &format!("### Load case `{}`\n\n", c.name);
        let mut t = Table::new(&summary::NODE_HEADER);
        for (i, d) in c.displacements.iter().enumerate() {
            t.row(summary::node_row(i, d));
            csv += &format!("{},{i},{},{},{},{},{},{}\n", c.name, d[0], d[1], d[2], d[3], d[4], d[5]);
        }
        if c.displacements.len() <= 200 {
            md += &t.render();
        } else {
            md += &format!("({} nodes: see result.csv)\n", c.displacements.len());
        }
        md += "\n";
    }
    (md, csv)
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
            "### Node {}\n\nFrame rows (local x, y, z): {:?}. Translational eigenvalues {} … {} mm/N; rotational {} … {} rad/(N·mm).\n\n",
            c.node,
            c.frame,
            num(c.translational_eigen[0], DIGITS),
            num(c.translational_eigen[1], DIGITS),
            num(c.rotational_eigen[0], DIGITS),
            num(c.rotational_eigen[1], DIGITS)
        );
        let mut t = Table::new(&["", "Fx (N)", "Fy (N)", "Fz (N)", "Mx (N·mm)", "My (N·mm)", "Mz (N·mm)"]);
        for (i, name) in ["ux (mm)", "uy (mm)", "uz (mm)", "rx (rad)", "ry (rad)", "rz (rad)"]
            .iter()
            .enumerate()
        {
            let mut row = vec![name.to_string()];
            row.extend(c.matrix[i].iter().map(|v| num(*v, DIGITS)));
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
    let mut t = Table::columns("element | rotation (°) | peak von Mises (MPa) | utilisation (–) | remaining rotation (°) | My a (N·mm) | My b (N·mm)");
    for h in &c.hinges {
        let rem = if h.remaining_rotation_deg.is_finite() {
            num(h.remaining_rotation_deg, DIGITS)
        } else {
            "unbounded".to_string()
        };
        t.row(vec![
            h.element.to_string(),
            num(h.rotation_deg, DIGITS),
            num(h.peak_von_mises, DIGITS),
            num(h.utilisation, 4),
            rem,
            num(h.end_forces[0][4], DIGITS),
            num(h.end_forces[1][4], DIGITS),
        ]);
    }
    format!(
        "Hinge elements (rotation about the compliant axis, local y; remaining rotation to the allowable stress by linear extrapolation):\n\n{}\n",
        t.render()
    )
}

/// A `.vtu` of one load case (see [`crate::analysis::vtu`]): the undeformed model with displacement and
/// rotation point data, shell stresses and stress resultants
/// ([`crate::analysis::common::vtu::static_vtu_with_shells`]) and von Mises per cell (the element's maximum over its ends / shell
/// surfaces; `cell_stress` overrides it for given elements, e.g. hinge peak stresses; 0 where
/// none).
pub fn vtu(model: &Model, case: &fem::CaseResult, cell_stress: &[(usize, f64)]) -> Result<String, AnalysisError> {
    let shells = fem::shell_recovery::shell_field(model, &case.displacements)
        .map_err(|e| AnalysisError::new(format!("load case `{}`", case.name), e.to_string()))?;
    crate::analysis::common::vtu::static_vtu_with_shells(
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
