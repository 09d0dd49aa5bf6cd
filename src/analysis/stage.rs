//! The `stage` and `fem_vs_fkp` analyses.

use super::{AnalysisError, Report, RunError};
use crate::case::stage::{stage_error, FemVsFkpCase, StageCase};
use crate::kinematics::Pose;
use crate::report::markdown::{dms, sig, Table};
use crate::report::svg;
use crate::stage::{self, Drive, StageCaseResult, StageModel};
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

/// One stage load case.
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
    /// σ_sph,max / σ_rev,max (`null` when the case stresses no revolute hinge).
    #[serde(rename = "T", serialize_with = "crate::report::numbers::ratio_or_null")]
    pub t: f64,
    /// Load factor on this case that brings the peak stress to the allowable (`null`: the case
    /// stresses nothing, or the material has no allowable).
    #[serde(serialize_with = "crate::report::numbers::unbounded_as_null")]
    pub factor_at_allowable: f64,
    /// Nonlinear only: whether every converged point of the equilibrium path was stable
    /// (positive definite tangent stiffness, no jump over a limit point).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub stable: Option<bool>,
    /// Nonlinear and not stable: load factors [lo, hi] bracketing the first loss of stability.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub critical_load_factor: Option<[f64; 2]>,
}

/// What the stage reaches at the allowable stress under equal actuator forces (pure z).
#[derive(Debug, Clone, Serialize)]
///
/// All four are `null` when the material has no allowable stress (unbounded).
pub struct AtAllowable {
    /// Allowable stress used, MPa.
    #[serde(serialize_with = "crate::report::numbers::unbounded_as_null")]
    pub allowable: f64,
    /// Actuator force each, N.
    #[serde(serialize_with = "crate::report::numbers::unbounded_as_null")]
    pub force: f64,
    /// Stroke, mm (mean of the three).
    #[serde(serialize_with = "crate::report::numbers::unbounded_as_null")]
    pub stroke: f64,
    /// Platform z, mm.
    #[serde(serialize_with = "crate::report::numbers::unbounded_as_null")]
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
    /// Were the load cases solved geometrically nonlinear?
    pub nonlinear: bool,
    /// Natural frequencies and shapes (when the case asks for `modes`).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub modes: Option<Vec<super::modal::ModeRow>>,
    /// Solid-calibration warnings of the validated design's hinges (reported with the case's
    /// warnings, not in this object).
    #[serde(skip)]
    pub calibration_warnings: Vec<String>,
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
        stable: r.stability.map(|s| s.0),
        critical_load_factor: r.stability.and_then(|s| s.1),
    }
}

fn fem_err(e: stage::StageError) -> RunError {
    match e {
        stage::StageError::Geometry { .. } | stage::StageError::Hinge { .. } => RunError::Case(stage_error(e)),
        stage::StageError::Fem(f) => RunError::Analysis(AnalysisError::new("stage", f.to_string())),
    }
}

/// Model notes shared by the stage analyses.
pub fn model_notes(s: &StageModel) -> Vec<String> {
    let mut v = vec![
        "linear statics, small displacements (geometric nonlinearity not included)".to_string(),
        "legs: prismatic Timoshenko beams; hinges: one flexibility element each over the notch and its load-spreading zone in the leg, exact variable-section Timoshenko flexibility with the solid-calibrated 3-D factors of the hinge analysis (load spreading, short-notch G, plane-strain P), warping-restrained (Vlasov) torsion for rectangular notches".to_string(),
        "sliders: rigid bodies guided along e_i; platform: rigid body (rigid link)".to_string(),
        "hinge stress: beam stress along the hinge x notch factor (K_t/sqrt(P) flat notches, 1 + 0.041 sqrt(t/R) turned neck), torsion tau = T c / J, von Mises combining the peaks (conservative)".to_string(),
    ];
    if s.design.ideal_joints {
        v.push("ideal joints: hinges replaced by exact releases, legs and platform 1e6 x stiffer".into());
    }
    v
}

fn platform_stiffness(c: nalgebra::Matrix6<f64>) -> PlatformStiffness {
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
    PlatformStiffness {
        compliance: std::array::from_fn(|i| std::array::from_fn(|j| c[(i, j)])),
        translational_eigen: eig(ct),
        rotational_eigen: eig(cr),
    }
}

/// Runs a `stage` case.
pub fn run_stage(case: &StageCase) -> Result<StageResult, RunError> {
    Ok(run_stage_inner(case, false)?.0)
}

/// Runs a `stage` case and renders one `.vtu` per load case (deformed stage, displacements,
/// von Mises per element with the hinge peak stresses on the hinge elements).
pub fn run_stage_with_files(case: &StageCase) -> Result<(StageResult, super::Files), RunError> {
    run_stage_inner(case, true)
}

fn run_stage_inner(case: &StageCase, files: bool) -> Result<(StageResult, super::Files), RunError> {
    let (design, mut drives) = case.validated()?;
    let s = design.build();
    let allowable = design.material.allowable;
    // One linear pass: the user's cases, a unit force on every actuator (reach at the allowable)
    // and a unit pure-z stroke set (structural stiffness), plus the platform compliance.
    let j = design
        .prs
        .actuation_jacobian(0.0, 0.0, 0.0)
        .map_err(|e| AnalysisError::new("stage", e.to_string()))?;
    let unit_z = [j[(0, 0)], j[(1, 0)], j[(2, 0)]];
    let user = drives.clone();
    drives.push(("unit_force".into(), Drive::Forces([1.0; 3])));
    drives.push(("unit_z".into(), Drive::Strokes(unit_z)));
    let mut a = s.analyse(&drives, true).map_err(fem_err)?;
    let z = a
        .cases
        .pop()
        .ok_or_else(|| AnalysisError::new("stage", "unit-z case missing"))?;
    let u = a
        .cases
        .pop()
        .ok_or_else(|| AnalysisError::new("stage", "unit-force case missing"))?;
    let u = &u;
    let stiffness_z = z.forces.iter().sum::<f64>() / (unit_z.iter().sum::<f64>() / 3.0);
    let results = match case.nonlinear_steps() {
        Some(steps) => s.solve_nonlinear(&user, steps).map_err(fem_err)?,
        None => std::mem::take(&mut a.cases),
    };
    let k = allowable / u.max_von_mises;
    let at_allowable = AtAllowable {
        allowable,
        force: k,
        stroke: k * u.strokes.iter().sum::<f64>() / 3.0,
        z: k * u.platform.z,
    };
    let compliance = a
        .compliance
        .ok_or_else(|| AnalysisError::new("stage", "no platform compliance"))?;
    let mut out_files = Vec::new();
    let drawn = drawn_bodies(&s);
    if files {
        for c in &results {
            let mut cell = Vec::new();
            for (i, leg) in s.legs.iter().enumerate() {
                // Ideal joints have no hinge element (and no stress cell).
                if let Some(el) = leg.rev_element {
                    cell.push((el, c.revolute_stress[i]));
                }
                if let Some(el) = leg.sph_element {
                    cell.push((el, c.spherical_stress[i]));
                }
            }
            // The nonlinear solve splits each hinge into co-rotational segments (nodes added
            // after the model's own): the file shows the model's nodes, a hinge as one line.
            let vm = super::fem_static::von_mises_of(&c.fe, &cell);
            let text = super::vtu::static_vtu(&s.model, &c.fe.displacements, &vm, &drawn)?;
            out_files.push((
                format!("stage_{}.vtu", super::fem_static::file_stem(&c.name)),
                text.into_bytes(),
            ));
        }
    }
    let mut model = model_notes(&s);
    if let Some(steps) = case.nonlinear_steps() {
        model[0] = format!("load cases: geometrically nonlinear statics (co-rotational legs and hinges, rigid platform exact under finite rotation, Newton-Raphson in {steps} load steps); stiffness_z, at_allowable and platform_stiffness stay linear");
    }
    let result = StageResult {
        load_cases: results.iter().map(|r| row(r, allowable)).collect(),
        stiffness_z,
        at_allowable,
        platform_stiffness: platform_stiffness(compliance),
        model,
        nonlinear: case.nonlinear,
        modes: match case.modes {
            Some(n) => {
                let (rows, model, raw) = stage_modes_with_model(case, &s, n)?;
                if files {
                    let modes: Vec<(f64, &[[f64; 6]])> =
                        raw.modes.iter().map(|m| (m.frequency_hz, m.shape.as_slice())).collect();
                    out_files.push(("modes.vtu".to_string(), super::vtu::modes_vtu(&model, &modes, &drawn)?));
                }
                Some(rows)
            }
            None => None,
        },
        calibration_warnings: crate::case::stage::stage_warnings(&design),
    };
    Ok((result, out_files))
}

/// Rigid bodies drawn in `.vtu` files: the platform as the triangle through the three neck tops
/// (it also has the rigid-link lines from its centre) and each slider as a line from its node
/// along −eᵢ, two leg heights long (the slider is a rigid body guided along eᵢ with its
/// rotations fixed, so the whole line translates with its node).
fn drawn_bodies(s: &StageModel) -> super::vtu::Drawn {
    let tops = s.legs.map(|leg| leg.sph_top);
    super::vtu::Drawn {
        cells: vec![crate::report::vtk::Cell::Triangle(tops)],
        lines: s
            .legs
            .iter()
            .map(|leg| {
                let x = nalgebra::Vector3::from(s.model.nodes[leg.slider]) - 2.0 * s.design.leg_h * leg.e;
                super::vtu::BodyLine {
                    node: leg.slider,
                    point: [x[0], x[1], x[2]],
                }
            })
            .collect(),
    }
}

/// Modes of the stage with the actuators locked. Platform: point mass at P, a disc of radius
/// b and thickness t (default 10 mm) unless `platform_mass` is given: m = ρπb²t,
/// Ixx = Iyy = m(3b² + t²)/12, Izz = mb²/2 (platform normal = global z at home).
pub fn stage_modes(case: &StageCase, s: &stage::StageModel, n: usize) -> Result<Vec<super::modal::ModeRow>, RunError> {
    Ok(stage_modes_with_model(case, s, n)?.0)
}

/// [`stage_modes`] plus the model solved (sliders clamped, platform mass added) and the raw
/// modal results (for the mode-shape `.vtu`).
fn stage_modes_with_model(
    case: &StageCase,
    s: &stage::StageModel,
    n: usize,
) -> Result<
    (
        Vec<super::modal::ModeRow>,
        crate::fem::Model,
        crate::fem::modal::ModalResults,
    ),
    RunError,
> {
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
    let (r, raw) = super::modal::solve(&model, n, None)?;
    Ok((r.modes, model, raw))
}

/// Markdown/CSV of a stage result.
pub fn stage_report(r: &StageResult) -> Report {
    let mut md = format!(
        "# 3-PRS compliant stage ({} FEM)\n\n",
        if r.nonlinear {
            "geometrically nonlinear"
        } else {
            "linear"
        }
    );
    for c in &r.load_cases {
        if let Some(w) = super::fem_static::stability_warning(&c.name, c.stable, c.critical_load_factor) {
            md += &w;
        }
    }
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
    // Platform translations in µm in the CSV as in the Markdown table; `kind` = load_case or
    // mode (natural frequencies, when the case asks for `modes`).
    let mut csv = String::from(
        "kind,name,F1_N,F2_N,F3_N,s1_mm,s2_mm,s3_mm,x_um,y_um,z_um,psi_deg,theta_deg,phi_deg,max_von_mises_MPa,T,frequency_hz\n",
    );
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
            finite_or_dash(c.t, |t| format!("{t:.3}")),
        ]);
        let p = &c.platform;
        csv += &format!(
            "load_case,{},{},{},{},{},{},{},{},{},{},{},{},{},{},{},\n",
            c.name,
            c.forces[0],
            c.forces[1],
            c.forces[2],
            c.strokes[0],
            c.strokes[1],
            c.strokes[2],
            p.x * 1000.0,
            p.y * 1000.0,
            p.z * 1000.0,
            p.psi_deg,
            p.theta_deg,
            p.phi_deg,
            c.max_von_mises,
            finite_or_dash(c.t, |t| t.to_string()).replace('—', "")
        );
    }
    md += &t.render();
    let a = &r.at_allowable;
    let reach = if [a.allowable, a.force, a.stroke, a.z].iter().all(|v| v.is_finite()) {
        format!(
            "At the allowable stress {} MPa under equal forces: F = {} N per actuator, stroke {} mm, Δz = {} mm.",
            a.allowable,
            sig(a.force, 5),
            sig(a.stroke, 5),
            sig(a.z, 5)
        )
    } else {
        "No allowable stress bounds the stroke (the material has none, or equal forces stress no hinge).".to_string()
    };
    md += &format!(
        "\nStructural stiffness (total actuator force per mm of pure-z stroke): **{} N/mm**.\n\n{reach}\n\nPlatform stiffness at P (sliders held): translational eigenvalues {}…{} N/mm, rotational {}…{} N·mm/rad.\n",
        sig(r.stiffness_z, 5),
        sig(r.platform_stiffness.translational_eigen[0], 4),
        sig(r.platform_stiffness.translational_eigen[1], 4),
        sig(r.platform_stiffness.rotational_eigen[0], 4),
        sig(r.platform_stiffness.rotational_eigen[1], 4),
    );
    if let Some(modes) = &r.modes {
        md += "\n## Natural frequencies (actuators locked)\n\n";
        let mut t = Table::new(&["mode", "f (Hz)", "x", "y", "z", "rx", "ry", "rz"]);
        for m in modes {
            let e = m.effective_mass_fraction;
            let mut row = vec![m.mode.to_string(), format!("{:.2}", m.frequency_hz)];
            row.extend([e.x, e.y, e.z, e.rx, e.ry, e.rz].iter().map(|v| format!("{v:.4}")));
            t.row(row);
            csv += &format!("mode,mode_{},,,,,,,,,,,,,,,{}\n", m.mode, m.frequency_hz);
        }
        md += "Effective mass fractions per direction after the frequency.\n\n";
        md += &t.render();
        md += "\nMode shapes: `modes.vtu` (with `--out`).\n";
    }
    md += "\n## Model\n\n";
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
    let mut t = Table::new(&[
        "Δs₁ (µm)",
        "Δs₂ (µm)",
        "Δs₃ (µm)",
        "Δz linear FEM (µm)",
        "Δz nonlinear FEM (µm)",
        "Δz FKP (µm)",
        "ψ linear FEM",
        "ψ nonlinear FEM",
        "ψ FKP",
        "θ linear FEM",
        "θ nonlinear FEM",
        "θ FKP",
    ]);
    let mut d = Table::new(&[
        "Δs₁ (µm)",
        "Δs₂ (µm)",
        "Δs₃ (µm)",
        "|Δz lin − FKP| (µm)",
        "|Δz nl − FKP| (µm)",
        "|ψ lin − FKP|",
        "|ψ nl − FKP|",
        "|θ lin − FKP|",
        "|θ nl − FKP|",
    ]);
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

/// `f(v)` for a finite `v`, "—" for an undefined or unbounded value (documented `null`s).
fn finite_or_dash(v: f64, f: impl Fn(f64) -> String) -> String {
    if v.is_finite() {
        f(v)
    } else {
        "—".to_string()
    }
}
