//! The `hinge` analysis: stiffness, compliance, stress and closed forms of one flexure hinge.

use super::Report;
use crate::case::hinge::{hinge_error, HingeCase};
use crate::case::CaseError;
use crate::hinge::{characterise, HingeResult};
use crate::report::markdown::{sig, Table};

/// Characterises the hinge of the case.
pub fn solve(case: &HingeCase) -> Result<HingeResult, super::RunError> {
    let m = case.validate()?;
    characterise(&case.hinge, &m).map_err(|e| {
        let ce: CaseError = hinge_error(&e, "hinge", "material");
        super::RunError::Case(ce)
    })
}

/// Markdown/CSV views.
pub fn report(r: &HingeResult) -> Report {
    let mut md = String::from("# Flexure hinge\n\n");
    let mut t = Table::new(&["quantity", "hinge in blank", "notch alone", "unit"]);
    let h = &r.hinge;
    let n = &r.notch_only;
    for (name, a, b, unit) in [
        ("k_bend (compliant axis)", h.k_bend, n.k_bend, "N·mm/rad"),
        ("k_bend_off", h.k_bend_off, n.k_bend_off, "N·mm/rad"),
        ("k_torsion (warping restrained)", h.k_torsion, n.k_torsion, "N·mm/rad"),
        (
            "k_torsion (Saint-Venant)",
            h.k_torsion_saint_venant,
            n.k_torsion_saint_venant,
            "N·mm/rad",
        ),
        ("k_axial", h.k_axial, n.k_axial, "N/mm"),
        (
            "stress per moment",
            h.stress_per_moment,
            n.stress_per_moment,
            "MPa/(N·mm)",
        ),
        (
            "max rotation at allowable",
            h.max_rotation_deg,
            n.max_rotation_deg,
            "deg",
        ),
    ] {
        t.row(vec![name.into(), sig(a, 5), sig(b, 5), unit.into()]);
    }
    md += &t.render();
    md += &format!(
        "\nStress-concentration factor applied: {:.4}.\n\n## Closed forms (notch alone, compliant axis)\n\n",
        r.stress_concentration
    );
    let mut c = Table::new(&["formula", "k_bend (N·mm/rad)", "vs flexfem notch"]);
    for (k, v) in &r.closed_form {
        c.row(vec![
            k.to_string(),
            sig(*v, 5),
            format!("{:+.2}%", (v / n.k_bend - 1.0) * 100.0),
        ]);
    }
    md += &c.render();
    md += "\n## Model\n\n";
    for note in &r.model {
        md += &format!("- {note}\n");
    }
    let csv = format!(
        "k_bend,k_bend_off,k_torsion,k_axial,stress_per_moment,max_rotation_deg\n{},{},{},{},{},{}\n",
        h.k_bend, h.k_bend_off, h.k_torsion, h.k_axial, h.stress_per_moment, h.max_rotation_deg
    );
    Report { markdown: md, csv }
}
