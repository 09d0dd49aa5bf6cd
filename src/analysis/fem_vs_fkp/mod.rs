//! The `fem_vs_fkp` analysis: the stage's FE platform pose against the rigid-body forward
//! kinematics for given stroke sets.

use super::stage::{fem_err, model_notes, PoseOut};
use super::{AnalysisError, Report, RunError};
use crate::case::stage::FemVsFkpCase;
use crate::report::markdown::{dms, Table};
use crate::report::svg;
use crate::stage::Drive;
use serde::Serialize;

/// One stroke set of the FEM-vs-FKP comparison.
#[derive(Debug, Clone, Serialize)]
pub struct FkpRow {
    /// Strokes, mm.
    pub strokes: [f64; 3],
    /// Rigid-body forward kinematics.
    pub fkp: PoseOut,
    /// Linear FEM.
    pub fem_linear: PoseOut,
    /// Geometrically nonlinear FEM (co-rotational; angles from the platform rotation matrix).
    pub fem_nonlinear: Option<PoseOut>,
    /// fem_linear − fkp.
    pub linear_minus_fkp: PoseOut,
    /// fem_nonlinear − fkp.
    pub nonlinear_minus_fkp: Option<PoseOut>,
}

/// Result of `fem_vs_fkp`.
#[derive(Debug, Clone, Serialize)]
pub struct FemVsFkpResult {
    /// Rows in input order.
    pub rows: Vec<FkpRow>,
    /// How `fem_nonlinear` was computed.
    pub fem_nonlinear_note: String,
    /// Idealisations.
    pub model: Vec<String>,
    /// Solid-calibration warnings of the validated design's hinges (reported with the case's
    /// warnings, not in this object).
    #[serde(skip)]
    pub calibration_warnings: Vec<String>,
}

fn diff(a: PoseOut, b: PoseOut) -> PoseOut {
    PoseOut {
        x: a.x - b.x,
        y: a.y - b.y,
        z: a.z - b.z,
        psi_deg: a.psi_deg - b.psi_deg,
        theta_deg: a.theta_deg - b.theta_deg,
        phi_deg: a.phi_deg - b.phi_deg,
    }
}

/// Runs a `fem_vs_fkp` case.
pub fn run_fem_vs_fkp(case: &FemVsFkpCase) -> Result<FemVsFkpResult, RunError> {
    let design = case.validated()?;
    let s = design.build();
    let drives: Vec<(String, Drive)> = case
        .strokes
        .iter()
        .enumerate()
        .map(|(i, st)| (format!("strokes[{i}]"), Drive::Strokes(*st)))
        .collect();
    let fem = s.solve(&drives).map_err(fem_err)?;
    let steps = case.nonlinear_steps();
    let fem_nl = s.solve_nonlinear(&drives, steps).map_err(fem_err)?;
    let mut rows = Vec::with_capacity(case.strokes.len());
    for (i, ((st, f), g)) in case.strokes.iter().zip(&fem).zip(&fem_nl).enumerate() {
        let k = design
            .prs
            .fkp(*st, None)
            .map_err(|e| AnalysisError::new(format!("strokes[{i}]"), e.to_string()))?;
        let fkp: PoseOut = k.pose.into();
        let lin: PoseOut = f.platform.into();
        let nl: PoseOut = g.platform.into();
        rows.push(FkpRow {
            strokes: *st,
            fkp,
            fem_linear: lin,
            fem_nonlinear: Some(nl),
            linear_minus_fkp: diff(lin, fkp),
            nonlinear_minus_fkp: Some(diff(nl, fkp)),
        });
    }
    Ok(FemVsFkpResult {
        rows,
        model: {
            let mut m = model_notes(&s);
            m[0] = "fem_linear: linear statics, small displacements; fem_nonlinear: geometrically nonlinear statics of the same model (co-rotational legs and hinges, rigid platform exact under finite rotation)".to_string();
            m
        },
        calibration_warnings: crate::case::stage::stage_warnings(&design),
        fem_nonlinear_note: format!(
            "co-rotational FEM (large rotations, small strains), same hinge and leg model as the linear FEM, Newton-Raphson in {steps} stroke steps; platform angles from its rotation matrix R = Ry(θ)·Rx(ψ)·Rz(φ)"
        ),
    })
}

/// Markdown report laid out like Ruiz et al. (2019) Tables 4–6 (linear FEM, nonlinear FEM and FKP side
/// by side), CSV, and the SVG plot of |FEM − FKP| for both FEM columns.
pub fn fem_vs_fkp_report(r: &FemVsFkpResult) -> (Report, super::Files) {
    let mut md = String::from(
        "# FEM versus rigid-body forward kinematics (Ruiz et al. (2019) Tables 4–6 layout)\n\n## Predictions\n\n",
    );
    let mut t = Table::columns("Δs₁ (µm) | Δs₂ (µm) | Δs₃ (µm) | Δz linear FEM (µm) | Δz nonlinear FEM (µm) | Δz FKP (µm) | ψ linear FEM | ψ nonlinear FEM | ψ FKP | θ linear FEM | θ nonlinear FEM | θ FKP");
    let mut d = Table::columns("Δs₁ (µm) | Δs₂ (µm) | Δs₃ (µm) | |Δz lin − FKP| (µm) | |Δz nl − FKP| (µm) | |ψ lin − FKP| | |ψ nl − FKP| | |θ lin − FKP| | |θ nl − FKP|");
    let mut csv = String::from(
        "s1_um,s2_um,s3_um,z_fem_um,z_fem_nl_um,z_fkp_um,psi_fem_deg,psi_fem_nl_deg,psi_fkp_deg,theta_fem_deg,theta_fem_nl_deg,theta_fkp_deg\n",
    );
    let um = |v: f64| format!("{:.0}", v * 1000.0);
    let opt = |v: Option<f64>, f: &dyn Fn(f64) -> String| v.map_or_else(|| "–".to_string(), f);
    let z1 = |v: f64| format!("{:.1}", v * 1000.0);
    let mut pts = Vec::new();
    let mut pts_nl = Vec::new();
    for row in &r.rows {
        let s = row.strokes;
        let nl = row.fem_nonlinear;
        let nd = row.nonlinear_minus_fkp;
        t.row(vec![
            um(s[0]),
            um(s[1]),
            um(s[2]),
            z1(row.fem_linear.z),
            opt(nl.map(|p| p.z), &z1),
            z1(row.fkp.z),
            dms(row.fem_linear.psi_deg),
            opt(nl.map(|p| p.psi_deg), &dms),
            dms(row.fkp.psi_deg),
            dms(row.fem_linear.theta_deg),
            opt(nl.map(|p| p.theta_deg), &dms),
            dms(row.fkp.theta_deg),
        ]);
        d.row(vec![
            um(s[0]),
            um(s[1]),
            um(s[2]),
            z1(row.linear_minus_fkp.z.abs()),
            opt(nd.map(|p| p.z.abs()), &z1),
            dms(row.linear_minus_fkp.psi_deg.abs()),
            opt(nd.map(|p| p.psi_deg.abs()), &dms),
            dms(row.linear_minus_fkp.theta_deg.abs()),
            opt(nd.map(|p| p.theta_deg.abs()), &dms),
        ]);
        // Strokes and Δz in µm, as in the Markdown tables.
        let num = |v: Option<f64>| v.map_or_else(String::new, |x| x.to_string());
        let to_um = |v: f64| v * 1000.0;
        csv += &format!(
            "{},{},{},{},{},{},{},{},{},{},{},{}\n",
            to_um(s[0]),
            to_um(s[1]),
            to_um(s[2]),
            to_um(row.fem_linear.z),
            num(nl.map(|p| to_um(p.z))),
            to_um(row.fkp.z),
            row.fem_linear.psi_deg,
            num(nl.map(|p| p.psi_deg)),
            row.fkp.psi_deg,
            row.fem_linear.theta_deg,
            num(nl.map(|p| p.theta_deg)),
            row.fkp.theta_deg
        );
        let mean = (s[0] + s[1] + s[2]) / 3.0;
        pts.push((mean, (row.linear_minus_fkp.z * 1000.0).abs()));
        if let Some(p) = nd {
            pts_nl.push((mean, (p.z * 1000.0).abs()));
        }
    }
    md += &t.render();
    md += "\n## Differences to the FKP (linear and nonlinear FEM)\n\n";
    md += &d.render();
    md += &format!(
        "\nNonlinear FEM: {}.\n\n![|FEM − FKP| in z against mean stroke](fem_vs_fkp.svg)\n\n## Model\n\n",
        r.fem_nonlinear_note
    );
    for n in &r.model {
        md += &format!("- {n}\n");
    }
    let plot = svg::scatter(
        "|Δz FEM − Δz FKP| against mean stroke",
        "mean stroke (mm)",
        "|Δz FEM − FKP| (µm)",
        &[("linear FEM", &pts), ("nonlinear FEM", &pts_nl)],
    );
    (
        Report { markdown: md, csv },
        vec![("fem_vs_fkp.svg".into(), plot.into_bytes())],
    )
}
