//! The `sensitivity` and `design` analyses.

pub mod mesh;
pub mod problem;

use super::{AnalysisError, Report, RunError};
use crate::analysis::stage::SizingFatigue;
use crate::case::design::{DesignCase, SensitivityCase};
use crate::case::fatigue::CyclicSpec;
use crate::case::stage::stage_warnings;
use crate::report::markdown::{sig, Table};
use crate::stage::sizing::{self as stage_design, DesignOutcome, Responses, SensitivityRow, PARAMETERS};
use crate::stage::StageDesign;
use serde::Serialize;

/// Result of `sensitivity`.
#[derive(Debug, Clone, Serialize)]
pub struct SensitivityResult {
    /// Responses of the base design.
    pub base: Responses,
    /// Relative increment applied.
    pub increment: f64,
    /// One row per parameter, Table-1 order.
    pub rows: Vec<SensitivityRow>,
    /// Idealisations.
    pub model: Vec<String>,
}

/// Runs a `sensitivity` case.
pub fn run_sensitivity(c: &SensitivityCase) -> Result<SensitivityResult, RunError> {
    run_sensitivity_warned(c).map(|(r, _)| r)
}

/// Runs a `sensitivity` case, with the calibration warnings of the validated stage design.
pub fn run_sensitivity_warned(c: &SensitivityCase) -> Result<(SensitivityResult, Vec<String>), RunError> {
    let v = c.validated()?;
    Ok((sensitivity_of(c, v.design())?, stage_warnings(&v)))
}

/// The fatigue assessment of a sizing or sensitivity with a `fatigue` block (validated with
/// the case: the material has fatigue data).
fn sizing_fatigue(spec: Option<&CyclicSpec>, d: &StageDesign) -> Option<SizingFatigue> {
    spec.zip(d.material.fatigue)
        .map(|(&spec, data)| SizingFatigue { spec, data })
}

/// The model note of d_f.
const FATIGUE_NOTE: &str = "d_f (z_at_fatigue_limit) = platform z at which the first hinge reaches fatigue utilisation 1 under pure z, the peak of the load cycle: the chain of the `stage` analysis's `at_fatigue_limit` (hinge fatigue stress = peak stress × K_f/K_t, Shigley 10th ed. ch. 6), rebuilt for each design";

fn sensitivity_of(c: &SensitivityCase, d: &StageDesign) -> Result<SensitivityResult, RunError> {
    let demand = stage_design::rotation_demand(d, c.z_travel, c.tilt_deg.to_radians())
        .map_err(|e| AnalysisError::new("stage", e.to_string()))?;
    let fatigue = sizing_fatigue(c.fatigue.as_ref(), d);
    let (base, rows) = stage_design::sensitivity(d, c.increment, &demand, fatigue.as_ref().map(|f| f as _))
        .map_err(|m| AnalysisError::new("sensitivity", m))?;
    let mut model = vec![
        "responses from the linear full-stage FE model under a pure-z stroke set (see `stage`)".to_string(),
        "d = platform z at which the peak hinge stress reaches the allowable; T = σ_sph,max/σ_rev,max".into(),
    ];
    if fatigue.is_some() {
        model.push(FATIGUE_NOTE.into());
    }
    Ok(SensitivityResult {
        base,
        increment: c.increment,
        rows,
        model,
    })
}

/// Markdown in Table 1's layout.
pub fn sensitivity_report(r: &SensitivityResult) -> Report {
    let mut md = format!(
        "# Influence of the design parameters (Ruiz et al. (2019) Table 1 layout)\n\nBase design: η = {} N/mm, d = {} mm, T = {}. Each parameter increased by {:.0} %.\n\n",
        sig(r.base.eta, 5),
        sig(r.base.z_at_allowable, 4),
        sig(r.base.t_ratio, 4),
        r.increment * 100.0
    );
    let mut t = Table::columns("positive increase | η_{i+1}/η_i | d_{i+1}/d_i | T_{i+1}/T_i | elasticities (η, d, T)");
    let mut csv =
        String::from("parameter,base_mm,increased_mm,stiffness_ratio,displacement_ratio,stress_ratio_ratio\n");
    let mut md_fatigue = String::new();
    for row in &r.rows {
        t.row(vec![
            format!(
                "{} ({} → {} mm)",
                row.parameter,
                sig(row.base, 3),
                sig(row.increased, 3)
            ),
            format!("{:.3} ({})", row.stiffness_ratio, row.bins.stiffness),
            format!("{:.3} ({})", row.displacement_ratio, row.bins.displacement),
            format!("{:.3} ({})", row.stress_ratio_ratio, row.bins.stress_ratio),
            format!(
                "{:+.2}, {:+.2}, {:+.2}",
                row.elasticity[0], row.elasticity[1], row.elasticity[2]
            ),
        ]);
        if let (Some(ratio), Some(b)) = (row.fatigue_displacement_ratio, row.bins.fatigue_displacement) {
            md_fatigue += &format!("- {}: d_f ratio {ratio:.3} ({b})\n", row.parameter);
        }
        csv += &format!(
            "{},{},{},{},{},{}\n",
            row.parameter, row.base, row.increased, row.stiffness_ratio, row.displacement_ratio, row.stress_ratio_ratio
        );
    }
    md += &t.render();
    if let Some(zf) = r.base.z_at_fatigue_limit {
        md += &format!(
            "\nFatigue-limited Δz of the base design d_f = {} mm; d_f_(i+1)/d_f_i per parameter:\n\n{md_fatigue}",
            sig(zf, 4)
        );
    }
    Report { markdown: md, csv }
}

/// Result of `design`.
#[derive(Debug, Clone, Serialize)]
pub struct DesignResult {
    /// The five parameters, mm (Table-1 order).
    pub design: serde_json::Map<String, serde_json::Value>,
    /// Whether every requirement is met.
    pub meets: bool,
    /// Responses of the design.
    pub responses: Responses,
    /// Constraint values and violations.
    pub constraints: Vec<stage_design::Constraint>,
    /// Active or violated constraints.
    pub binding: Vec<String>,
    /// Explanation when no design meets the requirements.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub message: Option<String>,
    /// Hinge rotations demanded by the kinematics, degrees: revolute, βm, βn, βl.
    pub rotation_demand_deg: [f64; 4],
    /// Designs evaluated.
    pub evaluations: usize,
    /// Samples and local-search steps.
    pub history: Vec<stage_design::HistoryEntry>,
}

/// Runs a `design` case.
pub fn run_design(c: &DesignCase) -> Result<DesignResult, RunError> {
    run_design_warned(c).map(|(r, _)| r)
}

/// Runs a `design` case, with the calibration warnings of the hinges of the design found
/// (derived from the validated base design with the found parameters).
pub fn run_design_warned(c: &DesignCase) -> Result<(DesignResult, Vec<String>), RunError> {
    let (d, bounds, req) = c.validated()?;
    let fatigue = sizing_fatigue(c.requirements.fatigue.as_ref(), d.design());
    let out: DesignOutcome = stage_design::optimise(&d, &bounds, &req, c.samples, fatigue.as_ref().map(|f| f as _))
        .map_err(|m| AnalysisError::new("design", m))?;
    let message = if out.meets {
        None
    } else {
        let worst = out
            .constraints
            .iter()
            .max_by(|a, b| a.violation.total_cmp(&b.violation));
        worst.map(|w| {
            format!(
                "no design within the bounds meets the requirements: `{}` cannot be met (best {} {} required {} {})",
                w.name,
                sig(w.value, 4),
                if w.sense == ">=" { "<" } else { ">" },
                w.sense,
                sig(w.limit, 4)
            )
        })
    };
    let dm = out.demand;
    let warnings = stage_design::with_params(&d, &out.params)
        .validate()
        .map(|found| stage_warnings(&found))
        .unwrap_or_default()
        .into_iter()
        .map(|w| format!("design found, {w}"))
        .collect();
    let r = DesignResult {
        design: PARAMETERS
            .iter()
            .zip(out.params)
            .map(|(k, v)| (k.to_string(), serde_json::Value::from(v)))
            .collect(),
        meets: out.meets,
        responses: out.responses,
        constraints: out.constraints,
        binding: out.binding,
        message,
        rotation_demand_deg: [dm.revolute, dm.spherical_m, dm.spherical_n, dm.spherical_l].map(f64::to_degrees),
        evaluations: out.evaluations,
        history: out.history,
    };
    Ok((r, warnings))
}

/// The opening of a design report (stage or mesh): the title, whether the design meets every
/// requirement, and the optimiser's message if any.
fn verdict(title: &str, meets: bool, message: Option<&str>) -> String {
    let mut md = format!("{title}\n\n");
    md += if meets {
        "**The design meets every requirement.**\n\n"
    } else {
        "**No design meets the requirements.**\n\n"
    };
    if let Some(m) = message {
        md += &format!("{m}\n\n");
    }
    md
}

/// Markdown/CSV of a design result.
pub fn design_report(r: &DesignResult) -> Report {
    let mut md = verdict(
        "# Stage sizing (Ruiz et al. (2019) Fig. 11 loop)",
        r.meets,
        r.message.as_deref(),
    );
    let mut t = Table::new(&["parameter", "value (mm)"]);
    for (k, v) in &r.design {
        t.row(vec![k.to_string(), format!("{:.4}", v.as_f64().unwrap_or(f64::NAN))]);
    }
    md += &t.render();
    md += &format!(
        "\nη = {} N/mm, d = {} mm at the allowable stress, T = {}.\n\n",
        sig(r.responses.eta, 5),
        sig(r.responses.z_at_allowable, 4),
        sig(r.responses.t_ratio, 4)
    );
    if let Some(zf) = r.responses.z_at_fatigue_limit {
        md += &format!(
            "d_f = {} mm at the fatigue limit (first hinge at fatigue utilisation 1).\n\n",
            sig(zf, 4)
        );
    }
    let mut c = Table::new(&["constraint", "value", "limit", "violation"]);
    for k in &r.constraints {
        c.row(vec![
            k.name.to_string(),
            sig(k.value, 5),
            format!("{} {}", k.sense, sig(k.limit, 4)),
            format!("{:+.4}", k.violation),
        ]);
    }
    md += &c.render();
    md += &format!("\n{} designs evaluated.\n", r.evaluations);
    let mut csv = String::from(
        "phase,t_rev_mm,R_rev_mm,t_sph_mm,R_sph_mm,l_sph_mm,eta_N_per_mm,z_at_allowable_mm,T,max_violation\n",
    );
    for h in &r.history {
        let p = h.params;
        csv += &format!(
            "{},{},{},{},{},{},{},{},{},{}\n",
            h.phase, p[0], p[1], p[2], p[3], p[4], h.eta, h.z_at_allowable, h.t_ratio, h.max_violation
        );
    }
    Report { markdown: md, csv }
}

/// Result of `sensitivity`: the stage's Table 1 or a mesh case's.
#[derive(Debug, Clone, Serialize)]
#[serde(untagged)]
pub enum SensitivityOut {
    /// The 3-PRS stage.
    Stage(SensitivityResult),
    /// A static mesh case.
    Mesh(mesh::MeshSensitivityResult),
}

/// Result of `design`: the stage sizing or a mesh case's design.
#[derive(Debug, Clone, Serialize)]
#[serde(untagged)]
pub enum DesignOut {
    /// The 3-PRS stage.
    Stage(DesignResult),
    /// A static mesh case.
    Mesh(mesh::MeshDesignResult),
}
