//! Result, report and files of the `transient` analysis: recorded histories (JSON peaks,
//! CSV, SVG plots) and the VTK time series (`transient.pvd` collecting `transient_NNNN.vtu`).

use super::TransientCase;
use crate::analysis::{Files, Report, RunError};
use crate::fem::transient::{TransientOptions, TransientResults};
use crate::fem::Model;
use crate::report::markdown::{sig, Table};
use serde::Serialize;

/// One recorded DOF: displacement in mm (translations) or degrees (rotations).
#[derive(Debug, Clone, Serialize)]
pub struct RecordOut {
    pub node: usize,
    pub dof: String,
    /// `mm` or `deg`.
    pub unit: String,
    /// Largest value and its time, s.
    pub max: f64,
    pub t_max_s: f64,
    /// Smallest value and its time, s.
    pub min: f64,
    pub t_min_s: f64,
    /// Value at the last step.
    pub final_value: f64,
    /// Every step's value (only with `"histories": true`).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub series: Option<Vec<f64>>,
}

/// Damping used.
#[derive(Debug, Clone, Serialize)]
pub struct DampingOut {
    /// Mass-proportional, 1/s.
    pub alpha: f64,
    /// Stiffness-proportional, s.
    pub beta: f64,
    /// Model elements with their own stiffness-proportional damping.
    pub damped_elements: usize,
}

/// Result of the `transient` analysis.
#[derive(Debug, Clone, Serialize)]
pub struct TransientResult {
    /// Time integration used.
    pub scheme: String,
    pub dt_s: f64,
    pub steps: usize,
    /// Equations of the reduced system (one factorisation for the whole run when linear).
    pub n_eq: usize,
    /// The mechanics: linear, or the geometrically nonlinear model and its approximations.
    pub model: String,
    /// Nonlinear only: the largest dynamic equilibrium residual of an accepted step relative
    /// to its force scale (applied load, or inertia and internal forces when larger); every
    /// step is checked to 1e-6 of it (plus a round-off floor of the stiffest element).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub equilibrium_residual: Option<f64>,
    pub damping: DampingOut,
    pub records: Vec<RecordOut>,
    /// Times of the series, s (only with `"histories": true`).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub time_s: Option<Vec<f64>>,
}

/// Scale to output units: degrees for rotations.
fn scale(dof: crate::fem::Dof) -> (f64, &'static str) {
    if dof.index() >= 3 {
        (180.0 / std::f64::consts::PI, "deg")
    } else {
        (1.0, "mm")
    }
}

/// The typed result.
pub fn result(case: &TransientCase, opts: &TransientOptions, raw: &TransientResults) -> TransientResult {
    let records = opts
        .record
        .iter()
        .zip(&raw.displacement)
        .map(|(r, s)| {
            let (f, unit) = scale(r.dof);
            let (mut imax, mut imin) = (0, 0);
            for (i, v) in s.iter().enumerate() {
                if *v > s[imax] {
                    imax = i;
                }
                if *v < s[imin] {
                    imin = i;
                }
            }
            RecordOut {
                node: r.node,
                dof: r.dof.name().into(),
                unit: unit.into(),
                max: f * s[imax],
                t_max_s: raw.time[imax],
                min: f * s[imin],
                t_min_s: raw.time[imin],
                final_value: f * s.last().copied().unwrap_or(0.0),
                series: case.histories.then(|| s.iter().map(|v| f * v).collect()),
            }
        })
        .collect();
    TransientResult {
        scheme: opts.scheme.describe(),
        dt_s: opts.dt,
        steps: opts.steps,
        n_eq: raw.n_eq,
        model: if case.nonlinear {
            crate::fem::nonlinear::NONLINEAR_TRANSIENT_MODEL.into()
        } else {
            "linear (small displacements)".into()
        },
        equilibrium_residual: raw.equilibrium,
        damping: DampingOut {
            alpha: opts.damping.alpha,
            beta: opts.damping.beta,
            damped_elements: opts.damping.element_beta.len(),
        },
        records,
        time_s: case.histories.then(|| raw.time.clone()),
    }
}

/// Markdown (records table) and CSV (one row, five columns per recorded DOF).
pub fn report(r: &TransientResult) -> Report {
    let mut md = format!(
        "# Transient response\n\nScheme: {}; dt = {} s, {} steps; {} equations; Rayleigh damping alpha = {} 1/s, beta = {} s; {} elements with their own damping.\n\n",
        r.scheme,
        sig(r.dt_s, 6),
        r.steps,
        r.n_eq,
        r.damping.alpha,
        r.damping.beta,
        r.damping.damped_elements
    );
    let mut t = Table::new(&["node", "dof", "max", "t max (s)", "min", "t min (s)", "final", "unit"]);
    let (mut head, mut row) = (Vec::new(), Vec::new());
    for rec in &r.records {
        t.row(vec![
            rec.node.to_string(),
            rec.dof.clone(),
            sig(rec.max, 5),
            sig(rec.t_max_s, 5),
            sig(rec.min, 5),
            sig(rec.t_min_s, 5),
            sig(rec.final_value, 5),
            rec.unit.clone(),
        ]);
        let (p, u) = (format!("n{}_{}", rec.node, rec.dof), &rec.unit);
        head.extend([
            format!("{p}_max_{u}"),
            format!("{p}_t_max_s"),
            format!("{p}_min_{u}"),
            format!("{p}_t_min_s"),
            format!("{p}_final_{u}"),
        ]);
        row.extend([rec.max, rec.t_max_s, rec.min, rec.t_min_s, rec.final_value].map(|v| v.to_string()));
    }
    md += &t.render();
    // One row: per recorded DOF its peaks and final value, units in the column names.
    let csv = format!("{}\n{}\n", head.join(","), row.join(","));
    Report { markdown: md, csv }
}

/// `transient_histories.csv` (time, then displacement, velocity and acceleration of each
/// recorded DOF), one SVG plot per recorded DOF, and the VTK time series: frames as the
/// `static` `.vtu` (displacements, element von Mises stress of beams and shells — 0 for hinge
/// and spring elements, whose stresses the frames do not recover) collected with their times
/// in `transient.pvd`.
pub fn files(model: &Model, opts: &TransientOptions, raw: &TransientResults) -> Result<Files, RunError> {
    let mut out: Files = Vec::new();
    if !opts.record.is_empty() {
        let mut csv = String::from("time_s");
        for r in &opts.record {
            let (_, unit) = scale(r.dof);
            let name = format!("n{}_{}", r.node, r.dof.name());
            csv += &format!(",{name}_{unit},{name}_{unit}_per_s,{name}_{unit}_per_s2");
        }
        csv.push('\n');
        for (i, t) in raw.time.iter().enumerate() {
            csv += &t.to_string();
            for (k, r) in opts.record.iter().enumerate() {
                let (f, _) = scale(r.dof);
                for s in [&raw.displacement, &raw.velocity, &raw.acceleration] {
                    csv += &format!(",{}", f * s[k][i]);
                }
            }
            csv.push('\n');
        }
        out.push(("transient_histories.csv".into(), csv.into_bytes()));
        for (k, r) in opts.record.iter().enumerate() {
            let (f, unit) = scale(r.dof);
            let pts: Vec<(f64, f64)> = raw.time.iter().zip(&raw.displacement[k]).map(|(t, v)| (*t, f * v)).collect();
            let name = format!("node {} {}", r.node, r.dof.name());
            let svg = crate::report::svg::lines(
                &format!("Transient response: {name}"),
                "time (s)",
                &format!("{} ({unit})", r.dof.name()),
                &[(name.as_str(), &pts)],
            );
            out.push((format!("transient_n{}_{}.svg", r.node, r.dof.name()), svg.into_bytes()));
        }
    }
    if !raw.snapshots.is_empty() {
        let mut pvd = String::from(
            "<?xml version=\"1.0\"?>\n<VTKFile type=\"Collection\" version=\"0.1\" byte_order=\"LittleEndian\">\n  <Collection>\n",
        );
        for (k, (t, u)) in raw.snapshots.iter().enumerate() {
            let name = format!("transient_{k:04}.vtu");
            let flat: Vec<f64> = u.concat();
            let vm: Vec<f64> = (0..model.elements.len())
                .map(|ie| {
                    crate::fem::recovery::element_result(model, ie, &flat)
                        .ok()
                        .and_then(|r| r.max_von_mises())
                        .unwrap_or(0.0)
                })
                .collect();
            let vtu = crate::analysis::common::vtu::static_vtu(model, u, &|ie| vm[ie], &Default::default())?;
            pvd += &format!("    <DataSet timestep=\"{t}\" group=\"\" part=\"0\" file=\"{name}\"/>\n");
            out.push((name, vtu.into_bytes()));
        }
        pvd += "  </Collection>\n</VTKFile>\n";
        out.push(("transient.pvd".into(), pvd.into_bytes()));
    }
    Ok(out)
}

