//! The `sensitivity` and `design` cases (the design guidelines of Table 1 and Fig. 11 of
//! Ruiz et al. (2019), kinematic design and experimental validation of a 3-PRS compliant
//! parallel stage).

use super::error::{check, CaseError};
use super::fatigue::CyclicSpec;
use super::fields::case_struct;
use super::stage::StageSpec;
use crate::stage::sizing::{self as stage_design, Requirements, PARAMETERS};
use crate::stage::{StageDesign, ValidStage};
use serde::Deserialize;

/// Schema of the `stage` of a sizing case: a circular-notch revolute and a spherical-neck
/// spherical hinge (the families the sizing varies).
fn notch_and_neck() -> serde_json::Value {
    serde_json::json!({
        "revolute": {"properties": {"type": {"const": "circular_notch"}}},
        "spherical": {"properties": {"type": {"const": "spherical_neck"}}}
    })
}

case_struct! {
    /// `"analysis": "sensitivity"`.
    #[derive(Debug, Clone, Deserialize, schemars::JsonSchema)]
    #[serde(deny_unknown_fields)]
    pub struct SensitivityCase {
        include material;
        /// The base design (circular-notch revolute, spherical-neck spherical hinges).
        #[schemars(extend("properties" = notch_and_neck()))]
        pub stage: StageSpec,
        /// Relative increase of each parameter, in (0, 2] (0.5 = +50 %; default 0.1).
        #[serde(default = "default_increment")]
        #[schemars(extend("exclusiveMinimum" = 0, "maximum" = 2))]
        pub increment: f64,
        /// Kinematic requirement box for the hinge rotation demand: z travel ±, mm, > 0 (default 2).
        #[serde(default = "default_z")]
        #[schemars(extend("exclusiveMinimum" = 0))]
        pub z_travel: f64,
        /// Tilt ±, degrees, in [0, 10] (default 0.2).
        #[serde(default = "default_tilt")]
        #[schemars(range(min = 0, max = 10))]
        pub tilt_deg: f64,
        /// The load cycle of the stage's `"fatigue"` block (the material needs fatigue data):
        /// adds the fatigue-limited Δz d_f to the responses and its ratio, bin and elasticity
        /// to each row.
        #[serde(default)]
        pub fatigue: Option<CyclicSpec>,
    }
}

fn default_increment() -> f64 {
    0.1
}
fn default_z() -> f64 {
    2.0
}
fn default_tilt() -> f64 {
    0.2
}

/// Requirements of a `design` case.
#[derive(Debug, Clone, Deserialize, schemars::JsonSchema)]
#[serde(deny_unknown_fields)]
pub struct RequirementsSpec {
    /// Platform z travel (±) to reach at the allowable stress, mm, > 0.
    #[schemars(extend("exclusiveMinimum" = 0))]
    pub z_travel: f64,
    /// Allowable stress, MPa, > 0 (default: the material's).
    #[serde(default)]
    #[schemars(extend("exclusiveMinimum" = 0))]
    pub allowable: Option<f64>,
    /// Range [min, max] of T = σ_sph/σ_rev, min > 0 (default [0.8, 1.2]).
    #[serde(rename = "T", default = "default_t")]
    #[schemars(extend("prefixItems" = [{"type": "number", "exclusiveMinimum": 0}, {"type": "number"}]))]
    pub t: [f64; 2],
    /// Platform tilt (±) the hinges must allow, degrees, in [0, 10] (default 0.2).
    #[serde(default = "default_tilt")]
    #[schemars(range(min = 0, max = 10))]
    pub tilt_deg: f64,
    /// Fatigue: the load cycle of the stage's `"fatigue"` block (the material needs fatigue
    /// data); the platform Δz at which the first hinge reaches fatigue utilisation 1 under pure
    /// z (the peak of the cycle) must reach `z_travel` too (constraint `z_travel_fatigue`).
    #[serde(default)]
    pub fatigue: Option<CyclicSpec>,
}

fn default_t() -> [f64; 2] {
    [0.8, 1.2]
}

/// Bounds of the design parameters, mm: `[min, max]` each, min > 0.
#[derive(Debug, Clone, Deserialize, schemars::JsonSchema)]
#[serde(deny_unknown_fields)]
pub struct BoundsSpec {
    /// Revolute notch minimum thickness.
    #[schemars(extend("prefixItems" = [{"type": "number", "exclusiveMinimum": 0}, {"type": "number"}]))]
    pub t_rev: [f64; 2],
    /// Revolute notch radius.
    #[serde(rename = "R_rev")]
    #[schemars(extend("prefixItems" = [{"type": "number", "exclusiveMinimum": 0}, {"type": "number"}]))]
    pub r_rev: [f64; 2],
    /// Spherical neck diameter.
    #[schemars(extend("prefixItems" = [{"type": "number", "exclusiveMinimum": 0}, {"type": "number"}]))]
    pub t_sph: [f64; 2],
    /// Spherical neck fillet radius.
    #[serde(rename = "R_sph")]
    #[schemars(extend("prefixItems" = [{"type": "number", "exclusiveMinimum": 0}, {"type": "number"}]))]
    pub r_sph: [f64; 2],
    /// Spherical neck length.
    #[schemars(extend("prefixItems" = [{"type": "number", "exclusiveMinimum": 0}, {"type": "number"}]))]
    pub l_sph: [f64; 2],
}

case_struct! {
    /// `"analysis": "design"`.
    #[derive(Debug, Clone, Deserialize, schemars::JsonSchema)]
    #[serde(deny_unknown_fields)]
    pub struct DesignCase {
        include material;
        /// The starting design (its geometry L, b, α₀, γ and leg are kept; circular-notch revolute,
        /// spherical-neck spherical hinges).
        #[schemars(extend("properties" = notch_and_neck()))]
        pub stage: StageSpec,
        /// Requirements.
        pub requirements: RequirementsSpec,
        /// Parameter bounds.
        pub bounds: BoundsSpec,
        /// Quasi-random designs sampled before the local search, 1 … 100000 (default 256).
        #[serde(default = "default_samples")]
        #[schemars(range(min = 1, max = 100000))]
        pub samples: usize,
    }
}

fn default_samples() -> usize {
    256
}

fn check_loop_design(d: &StageDesign) -> Result<(), CaseError> {
    stage_design::params_of(d).map_err(|m| {
        let field = if matches!(d.revolute, crate::hinge::HingeSpec::CircularNotch { .. }) {
            "stage.spherical.type"
        } else {
            "stage.revolute.type"
        };
        CaseError::new(field, m)
    })?;
    Ok(())
}

/// Checks a `fatigue` block (at `path`) of a sizing or sensitivity on design `d`: its fields,
/// the material's fatigue data, and hinges to assess.
fn check_fatigue(f: Option<&CyclicSpec>, path: &str, d: &StageDesign) -> Result<(), CaseError> {
    let Some(f) = f else { return Ok(()) };
    if d.ideal_joints {
        return Err(CaseError::new(
            path,
            "with \"ideal_joints\": true the stage has no hinges to assess: drop the fatigue block or `ideal_joints`",
        ));
    }
    f.validate(path, "material", &d.material).map(|_| ())
}

impl SensitivityCase {
    /// Validates before solving.
    pub fn validate(&self) -> Result<StageDesign, CaseError> {
        self.validated().map(ValidStage::into_design)
    }

    /// Validates before solving, keeping the validated design.
    pub fn validated(&self) -> Result<ValidStage, CaseError> {
        let v = self.stage.valid_design(&self.material)?;
        let d = v.design();
        check_loop_design(d)?;
        if !d.material.allowable.is_finite() {
            return Err(CaseError::new(
                "material",
                "the material has no `allowable` stress (MPa), and the sensitivity ranks the parameters by the platform z at the allowable stress: give a material with `allowable`",
            ));
        }
        if !(self.increment.is_finite() && self.increment > 0.0 && self.increment <= 2.0) {
            return Err(CaseError::value(
                "increment",
                self.increment,
                "must be a relative increase in (0, 2] (0.1 = +10 %)",
            ));
        }
        // The increased design must still be buildable.
        let p = stage_design::params_of(d).map_err(|m| CaseError::new("stage", m))?;
        for (k, name) in PARAMETERS.iter().enumerate() {
            let mut q = p;
            q[k] *= 1.0 + self.increment;
            stage_design::with_params(d, &q).validate().map_err(|e| {
                CaseError::value(
                    "increment",
                    self.increment,
                    format!("increasing {name} to {} gives an invalid stage: {e}", q[k]),
                )
            })?;
        }
        check::positive("z_travel", self.z_travel, "mm")?;
        check::within("tilt_deg", self.tilt_deg, 0.0, 10.0, "degrees")?;
        check_fatigue(self.fatigue.as_ref(), "fatigue", d)?;
        Ok(v)
    }
}

impl DesignCase {
    /// Validates before solving.
    pub fn validate(&self) -> Result<(StageDesign, [[f64; 2]; 5], Requirements), CaseError> {
        self.validated().map(|(v, b, r)| (v.into_design(), b, r))
    }

    /// Validates before solving, keeping the validated design.
    pub fn validated(&self) -> Result<(ValidStage, [[f64; 2]; 5], Requirements), CaseError> {
        let d = self.stage.valid_design(&self.material)?;
        check_loop_design(&d)?;
        let r = &self.requirements;
        check::positive("requirements.z_travel", r.z_travel, "mm")?;
        let allowable = r.allowable.unwrap_or(d.material.allowable);
        check::positive("requirements.allowable", allowable, "MPa")?;
        check::range("requirements.T", r.t)?;
        check::positive("requirements.T[0]", r.t[0], "")?;
        check::within("requirements.tilt_deg", r.tilt_deg, 0.0, 10.0, "degrees")?;
        check_fatigue(r.fatigue.as_ref(), "requirements.fatigue", &d)?;
        let b = &self.bounds;
        let bounds = [b.t_rev, b.r_rev, b.t_sph, b.r_sph, b.l_sph];
        let names = [
            "bounds.t_rev",
            "bounds.R_rev",
            "bounds.t_sph",
            "bounds.R_sph",
            "bounds.l_sph",
        ];
        for (name, bd) in names.iter().zip(&bounds) {
            check::range(name, *bd)?;
            check::positive(format_args!("{name}[0]"), bd[0], "mm")?;
        }
        if !(1..=100_000).contains(&self.samples) {
            return Err(CaseError::value("samples", self.samples, "must be in 1..=100000"));
        }
        Ok((
            d,
            bounds,
            Requirements {
                z_travel: r.z_travel,
                allowable,
                t_range: r.t,
                tilt: r.tilt_deg.to_radians(),
                fatigue: r.fatigue.is_some(),
            },
        ))
    }
}
