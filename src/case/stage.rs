//! The `stage` and `fem_vs_fkp` cases: the monolithic 3-PRS compliant stage.

use super::error::{check, CaseError};
use super::fields::case_struct;
use super::kinematics::MechanismSpec;
use super::material::MaterialSpec;
use crate::fem::inline_vec::InlineVec;
use crate::hinge::{Contour, HingeError, HingeSpec};
use crate::stage::{Drive, StageDesign, StageError, ValidStage};
use serde::Deserialize;

/// Leg cross-section.
#[derive(Debug, Clone, Copy, Deserialize, schemars::JsonSchema)]
#[serde(deny_unknown_fields)]
pub struct LegSpec {
    /// Width along the revolute axis, mm, > 0.
    #[schemars(extend("exclusiveMinimum" = 0))]
    pub w: f64,
    /// Height across it (the direction the revolute notch thins), mm, > 0.
    #[schemars(extend("exclusiveMinimum" = 0))]
    pub h: f64,
}

/// A hinge of the stage, by `type`: the hinge family and notch contour; its width and blank
/// come from the leg.
pub type StageHinge = Contour;

/// The full hinge spec of a stage joint in a w × h leg (the neck in a square of the smaller
/// leg side), blank length 0.
pub fn stage_hinge_spec(c: &StageHinge, leg: &LegSpec) -> HingeSpec {
    let h = if c.is_neck() { leg.w.min(leg.h) } else { leg.h };
    HingeSpec::in_blank(*c, leg.w, h, 0.0)
}

case_struct! {
    /// The `stage` object: 3-PRS geometry, leg section and hinges. Give either `alpha0_deg` or `a`.
    #[derive(Debug, Clone, Deserialize, schemars::JsonSchema)]
    #[serde(deny_unknown_fields)]
    #[schemars(extend("oneOf" = super::kinematics::alpha0_or_a()))]
    pub struct StageSpec {
        include prs_geometry;
        /// Leg section, mm.
        pub leg: LegSpec,
        /// Revolute hinge at Cᵢ (compliant axis = revolute axis): any notch type but
        /// `spherical_neck`.
        #[schemars(extend("not" = {"properties": {"type": {"const": "spherical_neck"}}}))]
        pub revolute: StageHinge,
        /// Spherical hinge at Bᵢ: a `spherical_neck` (turned neck).
        #[schemars(extend("properties" = {"type": {"const": "spherical_neck"}}))]
        pub spherical: StageHinge,
        /// Replace hinges by exact joints, legs and platform stiff (consistency check with FKP).
        #[serde(default)]
        pub ideal_joints: bool,
        /// Beam elements per leg, 1 … 1000 (default 4).
        #[serde(default = "default_leg_elements")]
        #[schemars(range(min = 1, max = 1000))]
        pub leg_elements: usize,
    }
}

fn default_leg_elements() -> usize {
    4
}

/// One load case: actuator forces or strokes (exactly one of the two).
#[derive(Debug, Clone, Deserialize, schemars::JsonSchema)]
#[serde(deny_unknown_fields)]
#[schemars(extend("oneOf" = [
    {"required": ["actuator_forces"], "properties": {"actuator_forces": {"type": "array"}, "actuator_strokes": {"type": "null"}}},
    {"required": ["actuator_strokes"], "properties": {"actuator_strokes": {"type": "array"}, "actuator_forces": {"type": "null"}}}
]))]
pub struct StageLoadSpec {
    /// Name shown in results and used for the load case's output file (`stage_NAME.vtu`);
    /// unique within the case, also after characters other than letters, digits, `-` and `_`
    /// are replaced by `_` for the file name.
    pub name: std::sync::Arc<str>,
    /// Actuator forces along the slider directions, N.
    #[serde(default)]
    pub actuator_forces: Option<[f64; 3]>,
    /// Prescribed strokes along the slider directions, mm.
    #[serde(default)]
    pub actuator_strokes: Option<[f64; 3]>,
}

case_struct! {
    /// `"analysis": "stage"`.
    #[derive(Debug, Clone, Deserialize, schemars::JsonSchema)]
    #[serde(deny_unknown_fields)]
    #[schemars(extend("if" = steps_given(), "then" = nonlinear_true()))]
    pub struct StageCase {
        include material;
        /// The stage.
        pub stage: StageSpec,
        /// Load cases (at least one).
        #[schemars(length(min = 1))]
        pub load_cases: Vec<StageLoadSpec>,
        include nonlinear_steps {
            /// Geometrically nonlinear analysis (co-rotational FEM, Newton–Raphson with load steps).
            nonlinear,
            /// Load steps of the nonlinear analysis, 1 … 10000 (default 20; only with
            /// `"nonlinear": true`).
            steps,
        }
        /// Also compute this many natural frequencies (actuators locked: sliders fixed on their
        /// rails). Legs carry their consistent beam mass, hinges are massless, the platform is a
        /// rigid body with its mass and inertia lumped at P. 1 … 1000.
        #[serde(default)]
        #[schemars(range(min = 1, max = 1000))]
        pub modes: Option<usize>,
        /// Platform mass, tonne, > 0 (default: a disc of radius `b` and `platform_thickness` of
        /// the stage material).
        #[serde(default)]
        #[schemars(extend("exclusiveMinimum" = 0))]
        pub platform_mass: Option<f64>,
        /// Thickness of the disc platform, mm, > 0 (default 10), used when `platform_mass` is
        /// absent.
        #[serde(default)]
        #[schemars(extend("exclusiveMinimum" = 0))]
        pub platform_thickness: Option<f64>,
        /// High-cycle fatigue of the hinges (the material needs `"fatigue"` data): every load
        /// case is the peak of a load cycle; per hinge the fatigue utilisation and life, and the
        /// stage's fatigue-limited stroke beside `at_allowable`.
        #[serde(default)]
        pub fatigue: Option<super::fatigue::CyclicSpec>,
    }
}

/// Schema: `steps` is given as a number.
pub(crate) fn steps_given() -> serde_json::Value {
    serde_json::json!({"required": ["steps"], "properties": {"steps": {"type": "integer"}}})
}

/// Schema: `"nonlinear": true`.
pub(crate) fn nonlinear_true() -> serde_json::Value {
    serde_json::json!({"required": ["nonlinear"], "properties": {"nonlinear": {"const": true}}})
}

/// Default number of nonlinear load steps.
pub const DEFAULT_STEPS: usize = 20;

/// Checks an optional `steps` field (JSON path `path`): 1..=10000, and only when `nonlinear`.
pub fn check_steps(path: &str, steps: Option<usize>, nonlinear: bool) -> Result<Option<usize>, CaseError> {
    match (steps, nonlinear) {
        (Some(n), _) if !(1..=10_000).contains(&n) => Err(CaseError::value(
            path,
            n,
            "the number of load steps must be in 1..=10000",
        )),
        (Some(_), false) => Err(CaseError::new(
            path,
            "load steps apply to a nonlinear analysis only: add \"nonlinear\": true or remove \"steps\"",
        )),
        (s, true) => Ok(Some(s.unwrap_or(DEFAULT_STEPS))),
        (None, false) => Ok(None),
    }
}

case_struct! {
    /// `"analysis": "fem_vs_fkp"`.
    #[derive(Debug, Clone, Deserialize, schemars::JsonSchema)]
    #[serde(deny_unknown_fields)]
    pub struct FemVsFkpCase {
        include material;
        /// The stage.
        pub stage: StageSpec,
        /// Stroke sets, mm (at least one).
        #[schemars(length(min = 1))]
        pub strokes: Vec<[f64; 3]>,
        /// Load steps of the nonlinear FEM column, 1 … 10000 (default 20).
        #[serde(default)]
        #[schemars(range(min = 1, max = 10000))]
        pub steps: Option<usize>,
    }
}

/// Maps a stage-builder error to a case error: design parameters under `stage`, hinge
/// parameters under `stage.revolute` / `stage.spherical`, material constants under `material`.
pub fn stage_error(e: StageError) -> CaseError {
    match e {
        StageError::Geometry { field, message } => CaseError::new(format!("stage.{field}"), message),
        StageError::Hinge { joint, source } => match source {
            HingeError::InvalidGeometry { param, value, allowed } => CaseError::new(
                format!("stage.{}.{param}", joint.name()),
                format!("value {value} is not allowed: {allowed}"),
            ),
            HingeError::InvalidMaterial { param, value, allowed } => CaseError::new(
                format!("material.{param}"),
                format!("value {value} is not allowed: {allowed}"),
            ),
        },
        StageError::Fem(f) => CaseError::new("stage", f.to_string()),
    }
}

/// Solid-calibration warnings of a validated stage's hinges, under their JSON paths
/// (`stage.revolute: …`, `stage.spherical: …`).
pub fn stage_warnings(v: &ValidStage) -> Vec<String> {
    let [rev, sph] = v.calibration_warnings();
    let at = |path: &'static str| move |w: String| format!("{path}: {w}");
    rev.into_iter()
        .map(at("stage.revolute"))
        .chain(sph.into_iter().map(at("stage.spherical")))
        .collect()
}

impl StageSpec {
    /// Validates and builds the design.
    pub fn design(&self, material: &MaterialSpec) -> Result<StageDesign, CaseError> {
        self.valid_design(material).map(ValidStage::into_design)
    }

    /// Validates the design once, into the value the stage builder takes.
    pub fn valid_design(&self, material: &MaterialSpec) -> Result<ValidStage, CaseError> {
        let material = material.resolve("material")?;
        let mech = MechanismSpec {
            l: self.l,
            b: self.b,
            alpha0_deg: self.alpha0_deg,
            a: self.a,
            gamma_deg: self.gamma_deg,
        };
        let prs = mech.build("stage")?;
        check::positive("stage.leg.w", self.leg.w, "mm")?;
        check::positive("stage.leg.h", self.leg.h, "mm")?;
        if !self.revolute.fits_revolute() {
            return Err(CaseError::value("stage.revolute.type", "\"spherical_neck\"", "the revolute joint needs a notch with one compliant axis: circular_notch, elliptical_notch, corner_filleted or leaf"));
        }
        if !self.spherical.fits_spherical() {
            return Err(CaseError::value(
                "stage.spherical.type",
                "(a notch type)",
                "the spherical joint must be a spherical_neck (turned neck)",
            ));
        }
        let d = StageDesign {
            prs,
            leg_w: self.leg.w,
            leg_h: self.leg.h,
            revolute: stage_hinge_spec(&self.revolute, &self.leg),
            spherical: stage_hinge_spec(&self.spherical, &self.leg),
            material,
            ideal_joints: self.ideal_joints,
            leg_elements: self.leg_elements,
        };
        d.validate().map_err(stage_error)
    }
}

impl StageCase {
    /// Validates everything before solving.
    pub fn validate(&self) -> Result<(StageDesign, Vec<(String, Drive)>), CaseError> {
        self.validated().map(|(d, drives)| (d.into_design(), drives))
    }

    /// Validates everything before solving, keeping the validated design for the builder.
    pub fn validated(&self) -> Result<(ValidStage, Vec<(String, Drive)>), CaseError> {
        let (d, drives) = self.validated_drives()?;
        let named = self.load_cases.iter().zip(drives.iter());
        Ok((d, named.map(|(lc, drive)| (lc.name.to_string(), *drive)).collect()))
    }

    /// [`Self::validated`] with the drives of the load cases in order, names left in the case
    /// (no allocation for up to four load cases: a sweep validates every design).
    pub fn validated_drives(&self) -> Result<(ValidStage, InlineVec<Drive, 4>), CaseError> {
        let d = self.stage.valid_design(&self.material)?;
        check_steps("steps", self.steps, self.nonlinear)?;
        if let Some(n) = self.modes {
            if !(1..=1000).contains(&n) {
                return Err(CaseError::value("modes", n, "must be an integer from 1 to 1000"));
            }
        }
        if let Some(m) = self.platform_mass {
            super::error::check::positive("platform_mass", m, "tonne")?;
        }
        if let Some(t) = self.platform_thickness {
            super::error::check::positive("platform_thickness", t, "mm")?;
        }
        if let Some(f) = &self.fatigue {
            if d.ideal_joints {
                return Err(CaseError::new(
                    "fatigue",
                    "with \"ideal_joints\": true the stage has no hinges to assess: drop `fatigue` or `ideal_joints`",
                ));
            }
            f.validate("fatigue", "material", &d.material)?;
        }
        if self.load_cases.is_empty() {
            return Err(CaseError::new("load_cases", "at least one load case is needed"));
        }
        super::mesh::unique_load_case_names(self.load_cases.iter().map(|c| &*c.name))?;
        let mut drives = InlineVec::new();
        for (i, lc) in self.load_cases.iter().enumerate() {
            let drive = match (lc.actuator_forces, lc.actuator_strokes) {
                (Some(f), None) => {
                    if d.ideal_joints {
                        return Err(CaseError::new(
                            format!("load_cases[{i}].actuator_forces"),
                            "with \"ideal_joints\": true the stage is a mechanism under actuator forces (the sliders are free): give `actuator_strokes`",
                        ));
                    }
                    for (k, v) in f.iter().enumerate() {
                        check::finite(format_args!("load_cases[{i}].actuator_forces[{k}]"), *v)?;
                    }
                    Drive::Forces(f)
                }
                (None, Some(s)) => {
                    for (k, v) in s.iter().enumerate() {
                        let why = "a linear stage analysis takes strokes well below the leg length";
                        check_stroke(format_args!("load_cases[{i}].actuator_strokes[{k}]"), *v, d.prs.l, why)?;
                    }
                    Drive::Strokes(s)
                }
                (Some(_), Some(_)) => {
                    return Err(CaseError::new(
                        format!("load_cases[{i}]"),
                        "give either `actuator_forces` or `actuator_strokes`, not both",
                    ))
                }
                (None, None) => {
                    return Err(CaseError::new(
                        format!("load_cases[{i}]"),
                        "missing `actuator_forces` or `actuator_strokes`",
                    ))
                }
            };
            drives.push(drive);
        }
        Ok((d, drives))
    }
}

/// A stroke at `path` (mm): finite and at most half the leg length `l` (else refused with `why`).
fn check_stroke(path: std::fmt::Arguments, v: f64, l: f64, why: &str) -> Result<(), CaseError> {
    check::finite(path, v)?;
    if v.abs() > 0.5 * l {
        return Err(CaseError::value(path.to_string(), v, why));
    }
    Ok(())
}

impl StageCase {
    /// Load steps when the analysis is nonlinear, `None` for linear.
    pub fn nonlinear_steps(&self) -> Option<usize> {
        self.nonlinear.then(|| self.steps.unwrap_or(DEFAULT_STEPS))
    }
}

impl FemVsFkpCase {
    /// Load steps of the nonlinear FEM column.
    pub fn nonlinear_steps(&self) -> usize {
        self.steps.unwrap_or(DEFAULT_STEPS)
    }

    /// Validates everything before solving.
    pub fn validate(&self) -> Result<StageDesign, CaseError> {
        self.validated().map(ValidStage::into_design)
    }

    /// Validates everything before solving, keeping the validated design for the builder.
    pub fn validated(&self) -> Result<ValidStage, CaseError> {
        let d = self.stage.valid_design(&self.material)?;
        check_steps("steps", self.steps, true)?;
        if self.strokes.is_empty() {
            return Err(CaseError::new("strokes", "give at least one stroke set"));
        }
        for (i, s) in self.strokes.iter().enumerate() {
            for (k, v) in s.iter().enumerate() {
                check_stroke(
                    format_args!("strokes[{i}][{k}]"),
                    *v,
                    d.prs.l,
                    "strokes must be well below the leg length",
                )?;
            }
        }
        Ok(d)
    }
}
