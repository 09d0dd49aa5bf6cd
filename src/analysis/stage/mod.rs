//! The `stage` analysis (the `fem_vs_fkp` comparison is [`super::fem_vs_fkp`]).

pub mod fatigue;
mod modes;
pub mod report;
pub mod sweep_plot;
mod units;
pub mod warnings;

use super::{AnalysisError, RunError};
use crate::case::stage::{stage_error, StageCase};
use crate::fem::inline_vec::InlineVec;
use crate::kinematics::Pose;
use crate::stage::{self, Drive, StageCaseResult, StageModel, StageResponse};
pub use fatigue::SizingFatigue;
pub use modes::stage_modes;
use modes::stage_modes_with_model;
use serde::Serialize;
use std::sync::Arc;

/// A platform pose in output units: mm and degrees.
#[derive(Debug, Clone, Copy, Serialize, PartialEq, Default)]
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
#[derive(Debug, Clone, Serialize, Default)]
pub struct HingeStress {
    /// Revolute hinges, MPa.
    pub revolute: [f64; 3],
    /// Spherical hinges, MPa.
    pub spherical: [f64; 3],
}

/// One stage load case.
#[derive(Debug, Clone, Serialize, Default)]
pub struct StageRow {
    /// Name (shared with the case: no copy per design).
    pub name: Arc<str>,
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
    /// Fatigue of the hinges, the case as the peak of the load cycle (`"fatigue"` only).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub fatigue: Option<fatigue::CaseFatigue>,
}

/// What the stage reaches at the allowable stress under equal actuator forces (pure z).
#[derive(Debug, Clone, Serialize)]
///
/// All four are `null` when the material has no allowable stress (unbounded); force, stroke and
/// z are `null` with ideal joints (no hinge stress bounds them).
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
    /// Load cases in input order (inline up to four: a sweep builds one result per design).
    pub load_cases: InlineVec<StageRow, 4>,
    /// Total actuator force per mm of pure-z stroke, N/mm.
    pub stiffness_z: f64,
    /// Reach at the allowable stress under equal forces.
    pub at_allowable: AtAllowable,
    /// Reach at the fatigue limit under equal forces (`"fatigue"` only).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub at_fatigue_limit: Option<fatigue::AtFatigueLimit>,
    /// Platform stiffness.
    pub platform_stiffness: PlatformStiffness,
    /// Idealisations (text made when written or iterated).
    pub model: StageNotes,
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
    row_of(Arc::from(r.name.as_str()), &r.response(), r.stability, allowable)
}

fn row_of(name: Arc<str>, r: &StageResponse, stability: Option<(bool, Option<[f64; 2]>)>, allowable: f64) -> StageRow {
    StageRow {
        name,
        strokes: r.strokes,
        forces: r.forces,
        platform: r.platform.into(),
        max_von_mises: r.max_von_mises,
        hinge_stress: HingeStress {
            revolute: r.hinge_stress[0],
            spherical: r.hinge_stress[1],
        },
        t: r.t_ratio(),
        factor_at_allowable: if r.max_von_mises > 0.0 {
            allowable / r.max_von_mises
        } else {
            f64::INFINITY
        },
        stable: stability.map(|s| s.0),
        critical_load_factor: stability.and_then(|s| s.1),
        fatigue: None,
    }
}

pub(super) fn fem_err(e: stage::StageError) -> RunError {
    match e {
        stage::StageError::Geometry { .. } | stage::StageError::Hinge { .. } => RunError::Case(stage_error(e)),
        stage::StageError::Fem(f) => RunError::Analysis(AnalysisError::new("stage", f.to_string())),
    }
}

/// Model notes shared by the stage analyses.
pub fn model_notes(s: &StageModel) -> Vec<String> {
    StageNotes::of(&s.design).into_iter().collect()
}

/// The model notes of a stage result, kept as what they depend on until written (JSON: an array
/// of strings; iterating gives the lines).
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct StageNotes {
    /// Load steps of a nonlinear analysis (`None`: linear).
    pub nonlinear_steps: Option<usize>,
    /// Hinges replaced by ideal joints.
    pub ideal_joints: bool,
}

const LINEAR_NOTE: &str = "linear statics, small displacements (geometric nonlinearity not included)";
const STAGE_NOTES: [&str; 3] = [
    "legs: prismatic Timoshenko beams; hinges: one flexibility element each over the notch and its load-spreading zone in the leg, exact variable-section Timoshenko flexibility with the solid-calibrated 3-D factors of the hinge analysis (load spreading, short-notch G, plane-strain P), warping-restrained (Vlasov) torsion for rectangular notches",
    "sliders: rigid bodies guided along e_i; platform: rigid body (rigid link)",
    "hinge stress: beam stress along the hinge x notch factor (K_t/sqrt(P) flat notches, 1 + 0.041 sqrt(t/R) turned neck), torsion tau = T c / J, von Mises combining the peaks (conservative)",
];
const IDEAL_NOTE: &str = "ideal joints: hinges replaced by exact releases, legs and platform 1e6 x stiffer";

/// The first note of a nonlinear analysis.
struct NonlinearNote(usize);

impl std::fmt::Display for NonlinearNote {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        write!(f, "load cases: geometrically nonlinear statics (co-rotational legs and hinges, rigid platform exact under finite rotation, Newton-Raphson in {} load steps); stiffness_z, at_allowable and platform_stiffness stay linear", self.0)
    }
}

impl StageNotes {
    /// The notes of a linear analysis of design `d`.
    pub fn of(d: &stage::StageDesign) -> StageNotes {
        StageNotes {
            nonlinear_steps: None,
            ideal_joints: d.ideal_joints,
        }
    }

    /// Each line, as text written to `f` (one call per line, in order).
    fn each(&self, mut f: impl FnMut(&dyn std::fmt::Display)) {
        match self.nonlinear_steps {
            Some(steps) => f(&NonlinearNote(steps)),
            None => f(&LINEAR_NOTE),
        }
        STAGE_NOTES.iter().for_each(|n| f(n));
        if self.ideal_joints {
            f(&IDEAL_NOTE);
        }
    }
}

impl IntoIterator for &StageNotes {
    type Item = String;
    type IntoIter = std::vec::IntoIter<String>;
    fn into_iter(self) -> Self::IntoIter {
        let mut v = Vec::new();
        self.each(|l| v.push(l.to_string()));
        v.into_iter()
    }
}

/// An array of strings, written without allocating (`collect_str`).
impl Serialize for StageNotes {
    fn serialize<S: serde::Serializer>(&self, s: S) -> Result<S::Ok, S::Error> {
        use serde::ser::SerializeSeq;
        struct Line<'a>(&'a dyn std::fmt::Display);
        impl Serialize for Line<'_> {
            fn serialize<S: serde::Serializer>(&self, s: S) -> Result<S::Ok, S::Error> {
                s.collect_str(self.0)
            }
        }
        let mut seq = s.serialize_seq(None)?;
        let mut err = None;
        self.each(|l| {
            if err.is_none() {
                err = seq.serialize_element(&Line(l)).err();
            }
        });
        match err {
            Some(e) => Err(e),
            None => seq.end(),
        }
    }
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

/// Reach at the allowable stress from the response `u` to a unit force on every actuator.
fn at_allowable(allowable: f64, u: &StageResponse) -> AtAllowable {
    let k = allowable / u.max_von_mises;
    AtAllowable {
        allowable,
        force: k,
        stroke: k * u.strokes.iter().sum::<f64>() / 3.0,
        z: k * u.platform.z,
    }
}

/// Runs a `stage` case.
pub fn run_stage(case: &StageCase) -> Result<StageResult, RunError> {
    Ok(run_stage_with(case, false, &mut crate::fem::SolverCache::new())?.0)
}

/// Runs a `stage` case and renders one `.vtu` per load case (deformed stage, displacements,
/// von Mises per element with the hinge peak stresses on the hinge elements).
pub fn run_stage_with_files(case: &StageCase) -> Result<(StageResult, super::Files), RunError> {
    run_stage_with(case, true, &mut crate::fem::SolverCache::new())
}

/// Runs a `stage` case with the worker's solver cache, rendering the `.vtu` files if `files`.
pub fn run_stage_with(
    case: &StageCase,
    files: bool,
    cache: &mut crate::fem::SolverCache,
) -> Result<(StageResult, super::Files), RunError> {
    let (design, user_drives) = case.validated_drives()?;
    let allowable = design.material.allowable;
    // One linear pass: the user's cases, a unit force on every actuator (reach at the allowable)
    // and a unit pure-z stroke set (structural stiffness), plus the platform compliance.
    let j = design
        .prs
        .actuation_jacobian(0.0, 0.0, 0.0)
        .map_err(|e| AnalysisError::new("stage", e.to_string()))?;
    let unit_z = [j[(0, 0)], j[(1, 0)], j[(2, 0)]];
    let n = user_drives.len();
    // The user's drives and the two of the linear pass, in that order.
    let all_drives = || {
        let units = [Drive::Forces([1.0; 3]), Drive::Strokes(unit_z)];
        user_drives.iter().copied().chain(units)
    };
    // The linear numbers come from the stage solved on its condensed form without an FE model
    // (stage::LinearStage), else (ideal joints, or a failure the FE model then reports) from
    // the FE model; the model is built only for that, files, modes or nonlinear cases.
    let condensed = design.linear().map(|l| {
        let r: InlineVec<StageResponse, 6> = all_drives().map(|d| l.response(d)).collect();
        (r, l.compliance())
    });
    let condensed = condensed.filter(|(r, c)| {
        let finite = |v: &[f64]| v.iter().all(|x| x.is_finite());
        r.iter()
            .all(|r| finite(&r.forces) && finite(&[r.max_von_mises, r.platform.z]))
            && finite(c.as_slice())
    });
    let nonlinear = case.nonlinear_steps();
    let s = (files || case.modes.is_some() || nonlinear.is_some() || condensed.is_none()).then(|| design.build());
    // The user's cases named, for the FE model (only when it is built: off the sweep's hot path).
    let user: Vec<(String, Drive)> = match &s {
        Some(_) => {
            let names = case.load_cases.iter().map(|lc| lc.name.to_string());
            names.zip(user_drives.iter().copied()).collect()
        }
        None => Vec::new(),
    };
    // The FE results of the user's cases (with files: the .vtu are drawn from them).
    let mut fe_cases = Vec::new();
    let (responses, compliance) = match (condensed, &s) {
        (Some(c), Some(s)) if files && nonlinear.is_none() => {
            fe_cases = s.analyse_with(cache, &user, false).map_err(fem_err)?.cases;
            c
        }
        (Some(c), _) => c,
        (None, Some(s)) => {
            let mut drives = user.clone();
            // With ideal joints the free sliders make actuator forces a mechanism: no unit-force
            // case (and no hinge stress to reach the allowable).
            if !design.ideal_joints {
                drives.push(("unit_force".into(), Drive::Forces([1.0; 3])));
            }
            drives.push(("unit_z".into(), Drive::Strokes(unit_z)));
            let mut a = s.analyse_with(cache, &drives, true).map_err(fem_err)?;
            let compliance = a
                .compliance
                .ok_or_else(|| AnalysisError::new("stage", "no platform compliance"))?;
            let r = a.cases.iter().map(StageCaseResult::response).collect();
            a.cases.truncate(n);
            fe_cases = a.cases;
            (r, compliance)
        }
        (None, None) => unreachable!("the FE model is built when there is no condensed solution"),
    };
    let z = &responses[responses.len() - 1];
    let stiffness_z = z.forces.iter().sum::<f64>() / (unit_z.iter().sum::<f64>() / 3.0);
    let at_allowable = if design.ideal_joints {
        AtAllowable {
            allowable,
            force: f64::INFINITY,
            stroke: f64::INFINITY,
            z: f64::INFINITY,
        }
    } else {
        at_allowable(allowable, &responses[n])
    };
    let nonlinear_cases = match (nonlinear, &s) {
        (Some(steps), Some(s)) => Some(s.solve_nonlinear(&user, steps).map_err(fem_err)?),
        _ => None,
    };
    let mut load_cases: InlineVec<StageRow, 4> = match &nonlinear_cases {
        Some(cases) => cases.iter().map(|r| row(r, allowable)).collect(),
        None => case
            .load_cases
            .iter()
            .zip(responses.iter())
            .map(|(lc, r)| row_of(lc.name.clone(), r, None, allowable))
            .collect(),
    };
    // Fatigue: checked with the case (material data, no ideal joints).
    let at_fatigue_limit = match (&case.fatigue, design.material.fatigue) {
        (Some(spec), Some(f)) if !design.ideal_joints => {
            let sf = fatigue::StageFatigue::new(spec, &design, &f);
            sf.add_to(&mut load_cases);
            Some(sf.at_limit(&responses[n]))
        }
        _ => None,
    };
    let model = StageNotes {
        nonlinear_steps: nonlinear,
        ..StageNotes::of(&design)
    };
    // What needs the FE model: the .vtu and stage_mesh.json files and the modes.
    let mut out_files = Vec::new();
    let mut modes = None;
    if let Some(s) = &s {
        let results = nonlinear_cases.as_ref().unwrap_or(&fe_cases);
        let drawn = drawn_bodies(s);
        if files {
            for c in results {
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
                let text = crate::analysis::common::vtu::static_vtu(&s.model, &c.fe.displacements, &vm, &drawn)?;
                out_files.push((
                    format!("stage_{}.vtu", super::fem_static::file_stem(&c.name)),
                    text.into_bytes(),
                ));
            }
            if let Some(c) = results.first() {
                out_files.push(stage_picture(s, c, &drawn, allowable));
            }
            // The same model as a `static` case (none with ideal joints, see StageModel::mesh_case).
            if let Some(mesh) = s.mesh_case(&user, nonlinear) {
                let text = serde_json::to_string_pretty(&mesh)
                    .map_err(|e| AnalysisError::new("stage", format!("stage_mesh.json: {e}")))?;
                out_files.push(("stage_mesh.json".to_string(), text.into_bytes()));
            }
        }
        if let Some(n) = case.modes {
            let (rows, model, raw) = stage_modes_with_model(case, s, n)?;
            if files {
                let modes: Vec<(f64, &[[f64; 6]])> =
                    raw.modes.iter().map(|m| (m.frequency_hz, m.shape.as_slice())).collect();
                out_files.push((
                    "modes.vtu".to_string(),
                    crate::analysis::common::vtu::modes_vtu(&model, &modes, &drawn)?,
                ));
            }
            modes = Some(rows);
        }
    }
    let result = StageResult {
        load_cases,
        stiffness_z,
        at_allowable,
        at_fatigue_limit,
        platform_stiffness: platform_stiffness(compliance),
        model,
        nonlinear: case.nonlinear,
        modes,
        calibration_warnings: crate::case::stage::stage_warnings(&design),
    };
    Ok((result, out_files))
}

/// `model.svg` of the stage: load case `c` deformed over the undeformed ghost (isometric, like
/// Fig. 1 of Ruiz et al. 2019), the platform and sliders shaded, each leg's revolute and
/// spherical hinge coloured by its peak stress over `allowable` (the `hinge_stress` of the
/// result's load case).
fn stage_picture(
    s: &StageModel,
    c: &StageCaseResult,
    drawn: &crate::analysis::common::vtu::Drawn,
    allowable: f64,
) -> (String, Vec<u8>) {
    use crate::analysis::common::picture::{self, HingeMark, Scene};
    let mut marks = Vec::new();
    for (i, leg) in s.legs.iter().enumerate() {
        let hinges = [
            (leg.rev_element, c.revolute_stress[i], "revolute"),
            (leg.sph_element, c.spherical_stress[i], "spherical"),
        ];
        for (el, stress, kind) in hinges {
            if let Some(crate::fem::Element::Flex(f)) = el.map(|e| &s.model.elements[e]) {
                marks.push(HingeMark {
                    label: format!("leg {} {kind}", i + 1),
                    nodes: f.nodes,
                    utilisation: allowable.is_finite().then(|| stress / allowable),
                });
            }
        }
    }
    let scene = Scene {
        model: &s.model,
        displacements: Some(&c.fe.displacements),
        marks,
        drawn,
        load_case: s.model.load_cases.iter().find(|l| l.name == c.name),
        title: "flexfem stage: the 3-PRS stage".to_string(),
        what: format!("load case \"{}\"", c.name),
        name: c.name.to_string(),
        mode: false,
    };
    let text = picture::render(&scene, &Default::default());
    ("model.svg".to_string(), text.into_bytes())
}

/// Rigid bodies drawn in `.vtu` files: the platform as the triangle through the three neck tops
/// (it also has the rigid-link lines from its centre) and each slider as a line from its node
/// along −eᵢ, two leg heights long (the slider is a rigid body guided along eᵢ with its
/// rotations fixed, so the whole line translates with its node).
fn drawn_bodies(s: &StageModel) -> crate::analysis::common::vtu::Drawn {
    let tops = s.legs.map(|leg| leg.sph_top);
    crate::analysis::common::vtu::Drawn {
        cells: vec![crate::report::vtk::Cell::Triangle(tops)],
        lines: s
            .legs
            .iter()
            .map(|leg| {
                let x = nalgebra::Vector3::from(s.model.nodes[leg.slider]) - 2.0 * s.design.leg_h * leg.e;
                crate::analysis::common::vtu::BodyLine {
                    node: leg.slider,
                    point: [x[0], x[1], x[2]],
                }
            })
            .collect(),
    }
}
