//! Views of a pan-tilt result: the Markdown and CSV report and the SVG plots of the path.

use super::{PanTiltResult, PathRow, JOINT_NAMES};
use crate::analysis::Report;
use crate::report::markdown::{sig, Table};
use crate::report::svg;

/// Markdown and CSV views of the result (the CSV holds the path rows).
pub fn report(r: &PanTiltResult) -> Report {
    let g = &r.geometry;
    let mut md = String::from("# 8R compliant pan-tilt: pseudo-rigid-body model\n\n");
    md += &format!(
        "Geometry: θ₀ = {}°, δ = {}°, β = {}°, limb azimuths {}°, {}°, {}°; RR limb {}; actuated limbs {} and {}.\n\n",
        sig(g.theta0_deg, 6),
        sig(g.delta_deg, 6),
        sig(g.beta_deg, 6),
        sig(g.azimuths_deg[0], 6),
        sig(g.azimuths_deg[1], 6),
        sig(g.azimuths_deg[2], 6),
        g.rr_limb,
        g.actuated[0],
        g.actuated[1]
    );
    let mut t = Table::new(&["Joint", "What", "K (N·mm/°)", "D (N·mm·s/°)"]);
    for (i, (name, what)) in JOINT_NAMES.iter().zip(&g.joints).enumerate() {
        t.row(vec![
            (*name).into(),
            what.clone(),
            sig(r.stiffness_per_deg[i], 6),
            sig(r.damping_per_deg[i], 6),
        ]);
    }
    md += &t.render();
    if !r.ik.is_empty() {
        md += "\n## Inverse kinematics\n\n";
        let mut t = Table::new(&["γ (°)", "φ (°)", "θ₁ (°)", "θ₂ (°)", "det J (γ, φ)"]);
        for q in &r.ik {
            t.row(vec![
                sig(q.gamma_deg, 6),
                sig(q.phi_deg, 6),
                format!("{:.4}", q.theta_deg[0]),
                format!("{:.4}", q.theta_deg[1]),
                if q.pole_singular {
                    format!("{} (singular: γ ≈ 0)", sig(q.inverse_jacobian_det, 3))
                } else {
                    sig(q.inverse_jacobian_det, 5)
                },
            ]);
        }
        md += &t.render();
    }
    if !r.fk.is_empty() {
        md += "\n## Forward kinematics\n\n";
        let mut t = Table::new(&["θ₁ (°)", "θ₂ (°)", "γ (°)", "φ (°)"]);
        for q in &r.fk {
            t.row(vec![
                sig(q.theta_deg[0], 6),
                sig(q.theta_deg[1], 6),
                format!("{:.6}", q.gamma_deg),
                format!("{:.6}", q.phi_deg),
            ]);
        }
        md += &t.render();
    }
    let mut csv = String::from("t_s,gamma_deg,phi_deg");
    for n in JOINT_NAMES {
        csv += &format!(",{n}_deg");
    }
    for n in JOINT_NAMES {
        csv += &format!(",{n}_rate_deg_per_s");
    }
    csv += ",torque1_undamped_Nmm,torque2_undamped_Nmm,torque1_damped_Nmm,torque2_damped_Nmm\n";
    if let Some(p) = &r.path {
        md += &format!("\n## Path ({} points)\n\n", p.points);
        let mut t = Table::new(&["Joint", "largest |rotation| (°)", "at t (s)", "at φ (°)"]);
        for (i, pk) in p.max_joint_rotation_deg.iter().enumerate() {
            t.row(vec![
                JOINT_NAMES[i].into(),
                format!("{:.4}", pk.max_abs),
                sig(pk.t, 6),
                sig(pk.phi_deg, 6),
            ]);
        }
        md += &t.render();
        md += "\n";
        let mut t = Table::columns("Actuator | largest |τ| undamped (N·mm) | largest |τ| damped (N·mm) | largest damper share (N·mm)");
        for a in 0..2 {
            t.row(vec![
                format!("limb {} (J{})", g.actuated[a], g.actuated[a]),
                format!("{:.2}", p.max_torque_undamped[a].max_abs),
                format!("{:.2}", p.max_torque_damped[a].max_abs),
                format!("{:.2}", p.max_torque_damping_share[a].max_abs),
            ]);
        }
        md += &t.render();
        for row in &p.rows {
            let mut line = format!("{},{},{}", row.t, row.gamma_deg, row.phi_deg);
            for v in row.joints_deg.iter().chain(row.joint_rates_deg_per_s.iter()) {
                line += &format!(",{v}");
            }
            for v in row.torque_undamped.iter().chain(row.torque_damped.iter()) {
                line += &format!(",{v}");
            }
            csv += &line;
            csv += "\n";
        }
    }
    Report { markdown: md, csv }
}

/// At most this many points per plotted series (the SVG draws a marker per point).
const PLOT_POINTS: usize = 200;

fn thin(rows: &[PathRow], f: impl Fn(&PathRow) -> f64) -> Vec<(f64, f64)> {
    let step = rows.len().div_ceil(PLOT_POINTS).max(1);
    rows.iter().step_by(step).map(|r| (r.t, f(r))).collect()
}

/// SVG plots of the path histories: joint rotations (bottom, middle, top joints) and actuator
/// torques against time. Empty without a path.
pub fn plots(r: &PanTiltResult) -> Vec<(String, Vec<u8>)> {
    let Some(p) = &r.path else {
        return Vec::new();
    };
    let mut files = Vec::new();
    for (name, title, idx) in [
        (
            "pantilt_bottom_joints.svg",
            "Bottom joint rotations",
            &[0usize, 1, 2][..],
        ),
        ("pantilt_middle_joints.svg", "Middle joint rotations", &[3, 4, 5][..]),
        ("pantilt_top_joints.svg", "Top joint rotations", &[6, 7][..]),
    ] {
        let series: Vec<(String, Vec<(f64, f64)>)> = idx
            .iter()
            .map(|&i| (JOINT_NAMES[i].to_string(), thin(&p.rows, |row| row.joints_deg[i])))
            .collect();
        let refs: Vec<(&str, &[(f64, f64)])> = series.iter().map(|(n, s)| (n.as_str(), s.as_slice())).collect();
        files.push((
            name.to_string(),
            svg::lines(title, "time (s)", "rotation (°)", &refs).into_bytes(),
        ));
    }
    let a = r.geometry.actuated;
    let series: Vec<(String, Vec<(f64, f64)>)> = vec![
        (
            format!("J{} undamped", a[0]),
            thin(&p.rows, |row| row.torque_undamped[0]),
        ),
        (
            format!("J{} undamped", a[1]),
            thin(&p.rows, |row| row.torque_undamped[1]),
        ),
        (format!("J{} damped", a[0]), thin(&p.rows, |row| row.torque_damped[0])),
        (format!("J{} damped", a[1]), thin(&p.rows, |row| row.torque_damped[1])),
    ];
    let refs: Vec<(&str, &[(f64, f64)])> = series.iter().map(|(n, s)| (n.as_str(), s.as_slice())).collect();
    files.push((
        "pantilt_torques.svg".to_string(),
        svg::lines("Actuator torques", "time (s)", "torque (N·mm)", &refs).into_bytes(),
    ));
    files
}
