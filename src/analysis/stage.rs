//! The `stage` and `fem_vs_fkp` analyses.

use super::{AnalysisError, Report, RunError};
use crate::case::stage::{stage_error, FemVsFkpCase, StageCase};
use crate::kinematics::Pose;
use crate::report::markdown::{dms, sig, Table};
use crate::report::svg;
use crate::stage::{self, Drive, PoseChange, StageCaseResult, StageModel};
use serde::Serialize;

/// A platform pose in output units: mm and degrees.
#[derive(Debug, Clone, Copy, Serialize, PartialEq)]
pub struct PoseOut {
    /// mm.
    pub x: f64,
    /// mm.
    pub y: f64,
    /// mm.
    pub z: f64,
    /// degrees.
    pub psi_deg: f64,
    /// degrees.
    pub theta_deg: f64,
    /// degrees.
    pub phi_deg: f64,
}

impl From<PoseChange> for PoseOut {
    fn from(p: PoseChange) -> Self {
        PoseOut {
            x: p.x,
            y: p.y,
            z: p.z,
            psi_deg: p.psi.to_degrees(),
            theta_deg: p.theta.to_degrees(),
            phi_deg: p.phi.to_degrees(),
        }
    }
}

impl From<Pose> for PoseOut {
    fn from(p: Pose) -> Self {
        PoseOut {
            x: p.x,
            y: p.y,
            z: p.z,
            psi_deg: p.psi.to_degrees(),
            theta_deg: p.theta.to_degrees(),
            phi_deg: p.phi.to_degrees(),
        }
    }
}

/// Peak hinge stresses per leg, MPa.
#[derive(Debug, Clone, Serialize)]
pub struct HingeStress {
    /// Revolute hinges, MPa.
    pub revolute: [f64; 3],
    /// Spherical hinges, MPa.
    pub spherical: [f64; 3],
}

/// One stage load case (INTERFACE.md).
#[derive(Debug, Clone, Serialize)]
pub struct StageRow {
    /// Name.
    pub name: String,
    /// Strokes, mm.
    pub strokes: [f64; 3],
    /// Actuator forces, N.
    pub forces: [f64; 3],
    /// Platform pose change.
    pub platform: PoseOut,
    /// Largest von Mises stress in the stage, MPa.
    pub max_von_mises: f64,
    /// Peak stress per hinge, MPa.
    pub hinge_stress: HingeStress,
    /// σ_sph,max / σ_rev,max.
    #[serde(rename = "T")]
    pub t: f64,
    /// Load factor on this case that brings the peak stress to the allowable.
    pub factor_at_allowable: f64,
}

/// What the stage reaches at the allowable stress under equal actuator forces (pure z).
#[derive(Debug, Clone, Serialize)]
pub struct AtAllowable {
    /// Allowable stress used, MPa.
    pub allowable: f64,
    /// Actuator force each, N.
    pub force: f64,
    /// Stroke, mm (mean of the three).
    pub stroke: f64,
    /// Platform z, mm.
    pub z: f64,
}

/// Platform stiffness summary at P with the sliders held.
#[derive(Debug, Clone, Serialize)]
pub struct PlatformStiffness {
    /// 6×6 compliance at P (mm, N, rad): rows/cols x, y, z, rx, ry, rz.
    pub compliance: [[f64; 6]; 6],
    /// Smallest and largest eigenvalue of the translational stiffness block (inverse of the
    /// translational compliance block), N/mm.
    pub translational_eigen: [f64; 2],
    /// Smallest and largest eigenvalue of the rotational stiffness block, N·mm/rad.
    pub rotational_eigen: [f64; 2],
}

/// Result of the `stage` analysis.
#[derive(Debug, Clone, Serialize)]
pub struct StageResult {
    /// Load cases in input order.
    pub load_cases: Vec<StageRow>,
    /// Total actuator force per mm of pure-z stroke, N/mm.
    pub stiffness_z: f64,
    /// Reach at the allowable stress under equal forces.
    pub at_allowable: AtAllowable,
    /// Platform stiffness.
    pub platform_stiffness: PlatformStiffness,
    /// Idealisations.
    pub model: Vec<String>,
    /// Natural frequencies and shapes (when the case asks for `modes`).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub modes: Option<Vec<super::modal::ModeRow>>,
}

fn row(r: &StageCaseResult, allowable: f64) -> StageRow {
    StageRow {
        name: r.name.clone(),
        strokes: r.strokes,
        forces: r.forces,
        platform: r.platform.into(),
        max_von_mises: r.max_von_mises,
        hinge_stress: HingeStress {
            revolute: r.revolute_stress,
            spherical: r.spherical_stress,
        },
        t: r.t_ratio(),
        factor_at_allowable: if r.max_von_mises > 0.0 {
            allowable / r.max_von_mises
        } else {
            f64::INFINITY
        },
    }
}

fn fem_err(e: stage::StageError) -> RunError {
    match e {
        stage::StageError::Geometry { .. } => RunError::Case(stage_error(e)),
        stage::StageError::Fem(f) => RunError::Analysis(AnalysisError::new("stage", f.to_string())),
    }
}

/// Model notes shared by the stage analyses.
pub fn model_notes(s: &StageModel) -> Vec<String> {
    let mut v = vec![
        "linear statics, small displacements (geometric nonlinearity not included)".to_string(),
        "legs: prismatic Timoshenko beams; hinges: one flexibility element each, exact variable-section Timoshenko flexibility of the notch, warping-restrained (Vlasov) torsion for rectangular notches".to_string(),
        "sliders: rigid bodies guided along e_i; platform: rigid body (rigid link)".to_string(),
        "hinge stress: beam stress along the notch x notch factor K_t, torsion tau = T c / J, von Mises combining the peaks (conservative)".to_string(),
    ];
    if s.design.ideal_joints {
        v.push("ideal joints: hinges replaced by exact releases, legs and platform 1e6 x stiffer".into());
    }
    v
}

fn platform_stiffness(s: &StageModel) -> Result<PlatformStiffness, RunError> {
    let c = s.platform_compliance().map_err(fem_err)?;
    let eig = |m: nalgebra::Matrix3<f64>| -> [f64; 2] {
        match m.try_inverse() {
            Some(k) => {
                let ev = nalgebra::SymmetricEigen::new((k + k.transpose()) * 0.5).eigenvalues;
                [ev.min(), ev.max()]
            }
            None => [0.0, 0.0],
        }
    };
    let ct = c.fixed_view::<3, 3>(0, 0).into_owned();
    let cr = c.fixed_view::<3, 3>(3, 3).into_owned();
    Ok(PlatformStiffness {
        compliance: std::array::from_fn(|i| std::array::from_fn(|j| c[(i, j)])),
        translational_eigen: eig(ct),
        rotational_eigen: eig(cr),
    })
}

/// Runs a `stage` case.
pub fn run_stage(case: &StageCase) -> Result<StageResult, RunError> {
    let (design, drives) = case.validate()?;
    let s = design.build().map_err(fem_err)?;
    let allowable = design.material.allowable;
    let results = s.solve(&drives).map_err(fem_err)?;
    let (stiffness_z, _) = stage::stiffness_z(&s).map_err(fem_err)?;
    let unit = s
        .solve(&[("unit_force".into(), Drive::Forces([1.0; 3]))])
        .map_err(fem_err)?;
    let u = &unit[0];
    let k = allowable / u.max_von_mises;
    let at_allowable = AtAllowable {
        allowable,
        force: k,
        stroke: k * u.strokes.iter().sum::<f64>() / 3.0,
        z: k * u.platform.z,
    };
    Ok(StageResult {
        load_cases: results.iter().map(|r| row(r, allowable)).collect(),
        stiffness_z,
        at_allowable,
        platform_stiffness: platform_stiffness(&s)?,
        model: model_notes(&s),
        modes: match case.modes {
            Some(n) => Some(stage_modes(case, &s, n)?),
            None => None,
        },
    })
}

/// Modes of the stage with the actuators locked. Platform: point mass at P, a disc of radius
/// b and thickness t (default 10 mm) unless `platform_mass` is given: m = ρπb²t,
/// Ixx = Iyy = m(3b² + t²)/12, Izz = mb²/2 (platform normal = global z at home).
pub fn stage_modes(case: &StageCase, s: &stage::StageModel, n: usize) -> Result<Vec<super::modal::ModeRow>, RunError> {
    let mut model = s.model.clone();
    for leg in &s.legs {
        model.supports.push(crate::fem::Support::clamp(leg.slider));
    }
    let rho = s.design.material.density;
    let b = s.design.prs.b;
    let t = case.platform_thickness.unwrap_or(10.0);
    let mass = case.platform_mass.unwrap_or(rho * std::f64::consts::PI * b * b * t);
    let ixx = mass * (3.0 * b * b + t * t) / 12.0;
    model.masses.push(crate::fem::PointMass {
        node: s.platform,
        mass,
        inertia: [ixx, ixx, mass * b * b / 2.0],
    });
    let (r, _) = super::modal::solve(&model, n, None)?;
    Ok(r.modes)
}

/// Markdown/CSV of a stage result.
pub fn stage_report(r: &StageResult) -> Report {
    let mut md = String::from("# 3-PRS compliant stage (linear FEM)\n\n");
    let mut t = Table::new(&[
        "load case",
        "F₁, F₂, F₃ (N)",
        "s₁, s₂, s₃ (mm)",
        "Δz (µm)",
        "ψ",
        "θ",
        "σ_rev (MPa)",
        "σ_sph (MPa)",
        "σ_max (MPa)",
        "T",
    ]);
    let mut csv = String::from("name,F1,F2,F3,s1,s2,s3,x,y,z,psi_deg,theta_deg,phi_deg,max_von_mises,T\n");
    let f3 = |v: [f64; 3], d: usize| format!("{:.d$}, {:.d$}, {:.d$}", v[0], v[1], v[2]);
    for c in &r.load_cases {
        let mx = |v: [f64; 3]| v.iter().cloned().fold(0.0, f64::max);
        t.row(vec![
            c.name.clone(),
            f3(c.forces, 2),
            f3(c.strokes, 4),
            format!("{:.1}", c.platform.z * 1000.0),
            dms(c.platform.psi_deg),
            dms(c.platform.theta_deg),
            format!("{:.2}", mx(c.hinge_stress.revolute)),
            format!("{:.2}", mx(c.hinge_stress.spherical)),
            format!("{:.2}", c.max_von_mises),
            format!("{:.3}", c.t),
        ]);
        let p = &c.platform;
        csv += &format!(
            "{},{},{},{},{},{},{},{},{},{},{},{},{},{},{}\n",
            c.name,
            c.forces[0],
            c.forces[1],
            c.forces[2],
            c.strokes[0],
            c.strokes[1],
            c.strokes[2],
            p.x,
            p.y,
            p.z,
            p.psi_deg,
            p.theta_deg,
            p.phi_deg,
            c.max_von_mises,
            c.t
        );
    }
    md += &t.render();
    md += &format!(
        "\nStructural stiffness (total actuator force per mm of pure-z stroke): **{} N/mm**.\n\nAt the allowable stress {} MPa under equal forces: F = {} N per actuator, stroke {} mm, Δz = {} mm.\n\nPlatform stiffness at P (sliders held): translational eigenvalues {}…{} N/mm, rotational {}…{} N·mm/rad.\n\n## Model\n\n",
        sig(r.stiffness_z, 5),
        r.at_allowable.allowable,
        sig(r.at_allowable.force, 5),
        sig(r.at_allowable.stroke, 5),
        sig(r.at_allowable.z, 5),
        sig(r.platform_stiffness.translational_eigen[0], 4),
        sig(r.platform_stiffness.translational_eigen[1], 4),
        sig(r.platform_stiffness.rotational_eigen[0], 4),
        sig(r.platform_stiffness.rotational_eigen[1], 4),
    );
    for n in &r.model {
        md += &format!("- {n}\n");
    }
    Report { markdown: md, csv }
}

/// One stroke set of the FEM-vs-FKP comparison.
#[derive(Debug, Clone, Serialize)]
pub struct FkpRow {
    /// Strokes, mm.
    pub strokes: [f64; 3],
    /// Rigid-body forward kinematics.
    pub fkp: PoseOut,
    /// Linear FEM.
    pub fem_linear: PoseOut,
    /// Geometrically nonlinear FEM (`null` until available).
    pub fem_nonlinear: Option<PoseOut>,
    /// fem_linear − fkp.
    pub linear_minus_fkp: PoseOut,
}

/// Result of `fem_vs_fkp`.
#[derive(Debug, Clone, Serialize)]
pub struct FemVsFkpResult {
    /// Rows in input order.
    pub rows: Vec<FkpRow>,
    /// Why `fem_nonlinear` is null.
    pub fem_nonlinear_note: &'static str,
    /// Idealisations.
    pub model: Vec<String>,
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
    let design = case.validate()?;
    let s = design.build().map_err(fem_err)?;
    let drives: Vec<(String, Drive)> = case
        .strokes
        .iter()
        .enumerate()
        .map(|(i, st)| (format!("strokes[{i}]"), Drive::Strokes(*st)))
        .collect();
    let fem = s.solve(&drives).map_err(fem_err)?;
    let mut rows = Vec::with_capacity(case.strokes.len());
    for (i, (st, f)) in case.strokes.iter().zip(&fem).enumerate() {
        let k = design
            .prs
            .fkp(*st, None)
            .map_err(|e| AnalysisError::new(format!("strokes[{i}]"), e.to_string()))?;
        let fkp: PoseOut = k.pose.into();
        let lin: PoseOut = f.platform.into();
        rows.push(FkpRow {
            strokes: *st,
            fkp,
            fem_linear: lin,
            fem_nonlinear: None,
            linear_minus_fkp: diff(lin, fkp),
        });
    }
    Ok(FemVsFkpResult {
        rows,
        fem_nonlinear_note: "geometrically nonlinear FEM is not available in this version",
        model: model_notes(&s),
    })
}

/// Markdown report laid out like seed 000 Tables 4–6, CSV, and the SVG plot.
pub fn fem_vs_fkp_report(r: &FemVsFkpResult) -> (Report, Vec<(String, Vec<u8>)>) {
    let mut md =
        String::from("# FEM versus rigid-body forward kinematics (seed 000 Tables 4–6 layout)\n\n## Predictions\n\n");
    let mut t = Table::new(&[
        "Δs₁ (µm)",
        "Δs₂ (µm)",
        "Δs₃ (µm)",
        "Δz FEM (µm)",
        "Δz FKP (µm)",
        "ψ FEM",
        "ψ FKP",
        "θ FEM",
        "θ FKP",
    ]);
    let mut d = Table::new(&[
        "Δs₁ (µm)",
        "Δs₂ (µm)",
        "Δs₃ (µm)",
        "|Δz FEM − FKP| (µm)",
        "|ψ FEM − FKP|",
        "|θ FEM − FKP|",
    ]);
    let mut csv = String::from("s1,s2,s3,z_fem,z_fkp,psi_fem_deg,psi_fkp_deg,theta_fem_deg,theta_fkp_deg\n");
    let um = |v: f64| format!("{:.0}", v * 1000.0);
    let mut pts = Vec::new();
    for row in &r.rows {
        let s = row.strokes;
        t.row(vec![
            um(s[0]),
            um(s[1]),
            um(s[2]),
            format!("{:.1}", row.fem_linear.z * 1000.0),
            format!("{:.1}", row.fkp.z * 1000.0),
            dms(row.fem_linear.psi_deg),
            dms(row.fkp.psi_deg),
            dms(row.fem_linear.theta_deg),
            dms(row.fkp.theta_deg),
        ]);
        d.row(vec![
            um(s[0]),
            um(s[1]),
            um(s[2]),
            format!("{:.1}", (row.linear_minus_fkp.z * 1000.0).abs()),
            dms(row.linear_minus_fkp.psi_deg.abs()),
            dms(row.linear_minus_fkp.theta_deg.abs()),
        ]);
        csv += &format!(
            "{},{},{},{},{},{},{},{},{}\n",
            s[0],
            s[1],
            s[2],
            row.fem_linear.z,
            row.fkp.z,
            row.fem_linear.psi_deg,
            row.fkp.psi_deg,
            row.fem_linear.theta_deg,
            row.fkp.theta_deg
        );
        pts.push(((s[0] + s[1] + s[2]) / 3.0, (row.linear_minus_fkp.z * 1000.0).abs()));
    }
    md += &t.render();
    md += "\n## Differences (linear FEM vs FKP)\n\n";
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
        &[("linear FEM", &pts)],
    );
    (
        Report { markdown: md, csv },
        vec![("fem_vs_fkp.svg".into(), plot.into_bytes())],
    )
}
