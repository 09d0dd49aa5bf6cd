//! The `kinematics` analysis: IKP, FKP and the requirement sweep, with results in degrees.

use super::{AnalysisError, Report};
use crate::case::kinematics::KinematicsCase;
use crate::kinematics::{workspace, Pose, Prs};
use crate::report::markdown::{dms, Table};
use serde::Serialize;

/// One inverse-kinematics answer.
#[derive(Debug, Clone, Serialize)]
pub struct IkpRow {
    /// Requested z from home, mm.
    pub z: f64,
    /// Requested ψ, degrees.
    pub psi_deg: f64,
    /// Requested θ, degrees.
    pub theta_deg: f64,
    /// Actuator strokes, mm.
    pub s: [f64; 3],
    /// Parasitic x of the platform centre, mm.
    pub x: f64,
    /// Parasitic y of the platform centre, mm.
    pub y: f64,
    /// Parasitic rotation φ, degrees.
    pub phi_deg: f64,
    /// Revolute angles αᵢ between slider and leg, degrees.
    pub revolute_deg: [f64; 3],
    /// Spherical joint angles [βm, βn, βl] per leg, degrees.
    pub spherical_deg: [[f64; 3]; 3],
    /// ∂sᵢ/∂(z, ψ, θ): rows per actuator; mm/mm, mm/deg, mm/deg.
    pub jacobian: [[f64; 3]; 3],
}

/// One forward-kinematics answer.
#[derive(Debug, Clone, Serialize)]
pub struct FkpRow {
    /// Input strokes, mm.
    pub s: [f64; 3],
    /// z from home, mm.
    pub z: f64,
    /// ψ, degrees.
    pub psi_deg: f64,
    /// θ, degrees.
    pub theta_deg: f64,
    /// Parasitic x, mm.
    pub x: f64,
    /// Parasitic y, mm.
    pub y: f64,
    /// Parasitic φ, degrees.
    pub phi_deg: f64,
    /// Newton iterations.
    pub iterations: usize,
}

/// Ranges over the requirement box; each `[min, max]`.
#[derive(Debug, Clone, Serialize)]
pub struct WorkspaceRow {
    /// Strokes, mm.
    pub s: [f64; 2],
    /// Revolute rotation from home, degrees.
    pub revolute_delta_deg: [f64; 2],
    /// Spherical βm, degrees.
    pub spherical_m_deg: [f64; 2],
    /// Spherical βn, degrees.
    pub spherical_n_deg: [f64; 2],
    /// Spherical βl, degrees.
    pub spherical_l_deg: [f64; 2],
    /// Poses evaluated.
    pub poses: usize,
}

/// Result of the `kinematics` analysis.
#[derive(Debug, Clone, Serialize)]
pub struct KinematicsResult {
    /// Derived geometry: base radius a, home height z0 (mm), α₀ (degrees).
    pub geometry: Geometry,
    /// IKP answers in query order.
    pub ikp: Vec<IkpRow>,
    /// FKP answers in query order.
    pub fkp: Vec<FkpRow>,
    /// Requirement ranges, if a workspace box was given.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub workspace: Option<WorkspaceRow>,
    /// Idealisations of this analysis.
    pub model: Vec<&'static str>,
}

/// Derived geometry.
#[derive(Debug, Clone, Serialize)]
pub struct Geometry {
    /// Base radius a, mm.
    pub a: f64,
    /// Home height of P above the slider plane, mm.
    pub z0: f64,
    /// α₀, degrees.
    pub alpha0_deg: f64,
    /// γ, degrees.
    pub gamma_deg: f64,
}

fn deg2(r: [f64; 2]) -> [f64; 2] {
    [r[0].to_degrees(), r[1].to_degrees()]
}

fn fkp_row(s: [f64; 3], p: &Pose, iterations: usize) -> FkpRow {
    FkpRow {
        s,
        z: p.z,
        psi_deg: p.psi.to_degrees(),
        theta_deg: p.theta.to_degrees(),
        x: p.x,
        y: p.y,
        phi_deg: p.phi.to_degrees(),
        iterations,
    }
}

/// Solves every query of the case.
pub fn solve(
    case: &KinematicsCase,
    prs: &Prs,
    bx: Option<&workspace::PoseBox>,
) -> Result<KinematicsResult, AnalysisError> {
    let mut ikp = Vec::with_capacity(case.ikp.len());
    for (i, q) in case.ikp.iter().enumerate() {
        let ctx = |e: crate::kinematics::KinematicsError| AnalysisError::new(format!("ikp[{i}]"), e.to_string());
        let (psi, theta) = (q.psi_deg.to_radians(), q.theta_deg.to_radians());
        let sol = prs.ikp(q.z, psi, theta).map_err(ctx)?;
        let j = prs.actuation_jacobian(q.z, psi, theta).map_err(ctx)?;
        let per_deg = std::f64::consts::PI / 180.0;
        ikp.push(IkpRow {
            z: q.z,
            psi_deg: q.psi_deg,
            theta_deg: q.theta_deg,
            s: sol.s,
            x: sol.pose.x,
            y: sol.pose.y,
            phi_deg: sol.pose.phi.to_degrees(),
            revolute_deg: sol.alpha.map(f64::to_degrees),
            spherical_deg: sol.spherical.map(|b| b.map(f64::to_degrees)),
            jacobian: [0, 1, 2].map(|r| [j[(r, 0)], j[(r, 1)] * per_deg, j[(r, 2)] * per_deg]),
        });
    }
    let mut fkp = Vec::with_capacity(case.fkp.len());
    for (i, q) in case.fkp.iter().enumerate() {
        let start = q
            .start
            .map(|p| prs.complete_pose(p.z, p.psi_deg.to_radians(), p.theta_deg.to_radians()));
        let sol = prs
            .fkp(q.s, start.as_ref())
            .map_err(|e| AnalysisError::new(format!("fkp[{i}]"), e.to_string()))?;
        fkp.push(fkp_row(q.s, &sol.pose, sol.iterations));
    }
    let workspace = match bx {
        Some(bx) => {
            let r = workspace::sweep(prs, bx).map_err(|e| AnalysisError::new("workspace", e.to_string()))?;
            Some(WorkspaceRow {
                s: r.s,
                revolute_delta_deg: deg2(r.revolute_delta),
                spherical_m_deg: deg2(r.spherical_m),
                spherical_n_deg: deg2(r.spherical_n),
                spherical_l_deg: deg2(r.spherical_l),
                poses: r.poses,
            })
        }
        None => None,
    };
    Ok(KinematicsResult {
        geometry: Geometry {
            a: prs.a,
            z0: prs.z0,
            alpha0_deg: prs.alpha0().to_degrees(),
            gamma_deg: prs.gamma.to_degrees(),
        },
        ikp,
        fkp,
        workspace,
        model: vec![
            "rigid-body 3-PRS: ideal prismatic, revolute and spherical joints, rigid legs and platform (Ruiz et al. (2019) §3)",
        ],
    })
}

/// A CSV row of the kinematics table: `kind`, strokes (mm), then z (mm), ψ, θ (°), x, y (mm), φ (°).
fn csv_row(kind: &str, s: [f64; 3], [z, psi, theta, x, y, phi]: [f64; 6]) -> String {
    format!("{kind},{},{},{},{z},{psi},{theta},{x},{y},{phi}\n", s[0], s[1], s[2])
}

/// Markdown and CSV views of the result.
pub fn report(r: &KinematicsResult) -> Report {
    let mut md = String::from("# 3-PRS rigid-body kinematics\n\n");
    let g = &r.geometry;
    md += &format!(
        "Geometry: a = {:.3} mm, home height z₀ = {:.3} mm, α₀ = {:.3}°, γ = {:.3}°.\n\n",
        g.a, g.z0, g.alpha0_deg, g.gamma_deg
    );
    // One header for the fkp and ikp rows (both give strokes and the full pose).
    let mut csv = String::from("kind,s1_mm,s2_mm,s3_mm,z_mm,psi_deg,theta_deg,x_mm,y_mm,phi_deg\n");
    if !r.fkp.is_empty() {
        md += "## Forward kinematics\n\n";
        let mut t =
            Table::columns("Δs₁ (µm) | Δs₂ (µm) | Δs₃ (µm) | Δz (µm) | ψ (DMS) | θ (DMS) | x (µm) | y (µm) | φ (DMS)");
        for f in &r.fkp {
            let um = |v: f64| format!("{:.0}", v * 1000.0);
            t.row(vec![
                um(f.s[0]),
                um(f.s[1]),
                um(f.s[2]),
                format!("{:.1}", f.z * 1000.0),
                dms(f.psi_deg),
                dms(f.theta_deg),
                format!("{:.2}", f.x * 1000.0),
                format!("{:.2}", f.y * 1000.0),
                dms(f.phi_deg),
            ]);
            csv += &csv_row("fkp", f.s, [f.z, f.psi_deg, f.theta_deg, f.x, f.y, f.phi_deg]);
        }
        md += &t.render();
        md += "\n";
    }
    if !r.ikp.is_empty() {
        md += "## Inverse kinematics\n\n";
        let mut t = Table::columns("z (mm) | ψ (°) | θ (°) | s₁ (mm) | s₂ (mm) | s₃ (mm) | x (µm) | y (µm) | φ (DMS)");
        for q in &r.ikp {
            let pose = [q.z, q.psi_deg, q.theta_deg, q.s[0], q.s[1], q.s[2]];
            let mut row: Vec<String> = pose.iter().map(|v| format!("{v:.4}")).collect();
            row.extend([
                format!("{:.2}", q.x * 1000.0),
                format!("{:.2}", q.y * 1000.0),
                dms(q.phi_deg),
            ]);
            t.row(row);
            csv += &csv_row("ikp", q.s, [q.z, q.psi_deg, q.theta_deg, q.x, q.y, q.phi_deg]);
        }
        md += &t.render();
        md += "\n";
    }
    if let Some(w) = &r.workspace {
        md += &format!("## Requirement ranges over {} poses\n\n", w.poses);
        let mut t = Table::new(&["quantity", "min", "max"]);
        t.row(vec![
            "stroke sᵢ (mm)".into(),
            format!("{:.3}", w.s[0]),
            format!("{:.3}", w.s[1]),
        ]);
        for (name, v) in [
            ("revolute Δαᵢ (°)", w.revolute_delta_deg),
            ("spherical βm (°)", w.spherical_m_deg),
            ("spherical βn (°)", w.spherical_n_deg),
            ("spherical βl (°)", w.spherical_l_deg),
        ] {
            t.row(vec![name.into(), format!("{:.3}", v[0]), format!("{:.3}", v[1])]);
        }
        md += &t.render();
    }
    if r.fkp.is_empty() && r.ikp.is_empty() {
        csv.clear(); // workspace ranges only: no rows
    }
    Report { markdown: md, csv }
}
