//! Views of a `prs_stiffness` result: the Markdown and CSV report and the SVG heat maps of the
//! map.

use super::PrsStiffnessResult;
use crate::analysis::{Files, Report};
use crate::report::markdown::{sig, Table};

fn opt(v: Option<f64>) -> String {
    v.map_or_else(|| "∞".into(), |x| sig(x, 6))
}

/// Markdown and CSV views.
pub fn report(r: &PrsStiffnessResult) -> Report {
    let mut md = String::from("# 3-PRS stiffness\n\n");
    md += &format!("Conventions: {}.\n\n", r.conventions);
    if !r.poses.is_empty() {
        let mut t = Table::columns("p_z (mm) | ψ (°) | θ (°) | φ (°) | pₓ (mm) | p_y (mm) | 1/C_xx (N/mm) | 1/C_yy | 1/C_zz | λ_min,3 (N/mm) | λ_max,3 (N/mm) | |δp| (mm)");
        for p in &r.poses {
            t.row(vec![
                sig(p.pz, 6),
                sig(p.psi_deg, 6),
                sig(p.theta_deg, 6),
                sig(p.phi_deg, 6),
                sig(p.px, 6),
                sig(p.py, 6),
                opt(p.directional[0]),
                opt(p.directional[1]),
                opt(p.directional[2]),
                sig(p.eigen_independent.values[0], 6),
                sig(p.eigen_independent.values[2], 6),
                p.deformation
                    .as_ref()
                    .map_or("—".into(), |d| sig(d.translation_norm_mm, 6)),
            ]);
        }
        md += "## Poses\n\n";
        md += &t.render();
        md += "\n";
    }
    let mut csv = String::new();
    if let Some(m) = &r.map {
        md += &format!("## Map at p_z = {} mm, {}×{} cells\n\n", m.pz, m.n, m.n);
        let mut t = Table::new(&["metric", "unit", "min", "max"]);
        for (j, name) in m.metrics.iter().enumerate() {
            let (lo, hi) = m.ranges[j].map_or(("—".into(), "—".into()), |[a, b]| (sig(a, 6), sig(b, 6)));
            t.row(vec![name.clone(), m.units[j].clone(), lo, hi]);
        }
        md += &t.render();
        if let Some(w) = &m.workspace {
            md += &format!(
                "\nStiffness-limited workspace: {} > {} keeps {} cells ({:.1} % of the reachable ones).\n",
                w.metric,
                w.threshold,
                w.cells,
                100.0 * w.fraction
            );
        }
        // `kind`: reachable, unreachable, or workspace (reachable and in the stiffness-limited
        // workspace); metric columns carry their unit.
        csv += "psi_deg,theta_deg,kind,px_mm,py_mm,phi_deg";
        for (name, unit) in m.metrics.iter().zip(&m.units) {
            let suffix = if unit == "N/mm" { "N_per_mm" } else { "Nmm_per_rad" };
            csv += &format!(",{name}_{suffix}");
        }
        csv += "\n";
        for c in &m.cells {
            let kind = match (c.reachable, c.in_workspace) {
                (false, _) => "unreachable",
                (true, Some(true)) => "workspace",
                (true, _) => "reachable",
            };
            csv += &format!("{},{},{kind},{},{},{}", c.psi_deg, c.theta_deg, c.px, c.py, c.phi_deg);
            for j in 0..m.metrics.len() {
                let v = c.values.get(j).copied().flatten();
                csv += &format!(",{}", v.map_or(String::new(), |x| x.to_string()));
            }
            csv += "\n";
        }
    } else {
        csv += "pz_mm,psi_deg,theta_deg,phi_deg,px_mm,py_mm,s1_mm,s2_mm,s3_mm,lambda_min_independent_N_per_mm,lambda_max_independent_N_per_mm\n";
        for p in &r.poses {
            csv += &format!(
                "{},{},{},{},{},{},{},{},{},{},{}\n",
                p.pz,
                p.psi_deg,
                p.theta_deg,
                p.phi_deg,
                p.px,
                p.py,
                p.strokes[0],
                p.strokes[1],
                p.strokes[2],
                p.eigen_independent.values[0],
                p.eigen_independent.values[2]
            );
        }
    }
    Report { markdown: md, csv }
}

/// SVG heat maps of each metric over (ψ, θ) and over the parasitic (pₓ, p_y).
pub fn files(r: &PrsStiffnessResult) -> Files {
    let mut out = Files::new();
    let Some(m) = &r.map else { return out };
    for (j, name) in m.metrics.iter().enumerate() {
        let label = format!("{name} ({})", m.units[j]);
        let pts = |par: bool| -> Vec<(f64, f64, f64, bool)> {
            m.cells
                .iter()
                .filter_map(|c| {
                    c.values.get(j).copied().flatten().map(|v| {
                        let (x, y) = if par { (c.px, c.py) } else { (c.psi_deg, c.theta_deg) };
                        (x, y, v, c.in_workspace.unwrap_or(true))
                    })
                })
                .collect()
        };
        if pts(false).is_empty() {
            continue;
        }
        let title = format!("{name} at p_z = {} mm", m.pz);
        out.push((
            format!("prs_stiffness_{name}.svg"),
            crate::report::svg::scatter_coloured(&title, "ψ (°)", "θ (°)", &pts(false), &label, None).into_bytes(),
        ));
        out.push((
            format!("prs_stiffness_{name}_parasitic.svg"),
            crate::report::svg::scatter_coloured(&title, "pₓ (mm)", "p_y (mm)", &pts(true), &label, None).into_bytes(),
        ));
    }
    out
}
