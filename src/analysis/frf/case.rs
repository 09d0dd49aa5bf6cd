//! The `frf` case: its shape (for the JSON Schema), its parser and its validation into the
//! input of the run ([`ValidFrf`]).

use crate::case::error::{check, CaseError};
use crate::case::fem_case::{read_model, split, MODEL_FIELDS};
use crate::case::fields::case_struct;
use crate::case::from_value;
use crate::case::mesh::load_shapes::DofName;
use crate::case::mesh::requests::check_node_frame;
use crate::case::mesh::MeshSpec;
use crate::fem::Model;
use serde::Deserialize;
use serde_json::Value;

/// `"analysis": "frf"`.
#[derive(Debug, Clone, schemars::JsonSchema)]
#[serde(deny_unknown_fields)]
pub struct FrfCase {
    /// Free text saying what the model is (not used by the analysis).
    pub description: Option<String>,
    /// Mesh file, as for `static` (a JSON mesh file; the inline fields add to it).
    pub mesh: Option<String>,
    /// Number of retained modes (the lowest), 1 … 1000.
    #[schemars(range(min = 1, max = 1000))]
    pub modes: usize,
    /// Viscous damping (default none).
    #[serde(default)]
    pub damping: DampingSpec,
    /// The frequencies of the response.
    pub frequencies: FrequencySpec,
    /// Inputs: nodal loads per unit input.
    pub inputs: Vec<InputSpec>,
    /// Outputs: nodal DOFs.
    pub outputs: Vec<OutputSpec>,
    /// Also solve (K − ω²M + iωC) directly at every frequency and report the largest
    /// difference to the modal result (default true; Rayleigh damping only).
    #[serde(default = "yes")]
    pub direct: bool,
    /// The model.
    #[serde(flatten)]
    pub model: MeshSpec,
}

fn yes() -> bool {
    true
}

case_struct! {
    /// Viscous damping: Rayleigh C = αM + βK and/or a constant modal damping ratio ζ (each mode's
    /// ratio is ζ + α/(2ω) + βω/2).
    #[derive(Debug, Clone, Copy, Default, PartialEq, Deserialize, schemars::JsonSchema)]
    #[serde(deny_unknown_fields)]
    pub struct DampingSpec {
        include rayleigh;
        /// Constant modal damping ratio 0 ≤ ζ < 1 (modal superposition only: no direct check).
        #[serde(default)]
        pub zeta: f64,
    }
}

/// Frequencies: `points` values from `from_hz` to `to_hz`, log or linear spacing.
#[derive(Debug, Clone, Copy, PartialEq, Deserialize, schemars::JsonSchema)]
#[serde(deny_unknown_fields)]
pub struct FrequencySpec {
    /// Lowest frequency, Hz (> 0 with log spacing, ≥ 0 with linear).
    pub from_hz: f64,
    /// Highest frequency, Hz.
    pub to_hz: f64,
    /// Number of frequencies, 2 … 100000.
    #[schemars(range(min = 2, max = 100000))]
    pub points: usize,
    /// `"log"` (default) or `"linear"`.
    #[serde(default)]
    pub spacing: Spacing,
}

/// Spacing of the frequencies.
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq, Deserialize, schemars::JsonSchema)]
#[serde(rename_all = "snake_case")]
pub enum Spacing {
    /// Logarithmic.
    #[default]
    Log,
    /// Linear.
    Linear,
}

impl FrequencySpec {
    /// The frequencies, Hz.
    pub fn values(&self) -> Vec<f64> {
        let n = self.points;
        (0..n)
            .map(|i| {
                let t = i as f64 / (n - 1) as f64;
                match self.spacing {
                    Spacing::Log => self.from_hz * (self.to_hz / self.from_hz).powf(t),
                    Spacing::Linear => self.from_hz + (self.to_hz - self.from_hz) * t,
                }
            })
            .collect()
    }
}

/// One input: a load at a node per unit input, in the input's frame: `F` (as in a `static` load
/// case), or its aliases `force` and `moment` (not with `F`).
#[derive(Debug, Clone, PartialEq, Deserialize, schemars::JsonSchema)]
#[serde(deny_unknown_fields)]
#[schemars(extend("oneOf" = [
    {"required": ["F"], "properties": {"force": {"type": "null"}, "moment": {"type": "null"}}},
    {"anyOf": [{"required": ["force"]}, {"required": ["moment"]}], "properties": {"F": {"type": "null"}}}
]))]
pub struct InputSpec {
    /// Name in results and plots (default `node N`).
    pub name: Option<String>,
    /// The node loaded.
    pub node: usize,
    /// Load per unit input [Fx, Fy, Fz (N), Mx, My, Mz (N·mm)] in the frame (the `F` of a
    /// `static` load).
    #[serde(rename = "F", default)]
    pub f: Option<[f64; 6]>,
    /// Alias of `F`'s first three components: force per unit input, N, in the frame (default zero).
    #[serde(default)]
    pub force: Option<[f64; 3]>,
    /// Alias of `F`'s last three components: moment per unit input, N·mm, in the frame (default
    /// zero).
    #[serde(default)]
    pub moment: Option<[f64; 3]>,
    /// Axes of `force` and `moment`: three orthonormal right-handed rows (local x, y, z in
    /// global coordinates); default the global axes.
    pub frame: Option<[[f64; 3]; 3]>,
}

impl InputSpec {
    /// The load per unit input [Fx, Fy, Fz (N), Mx, My, Mz (N·mm)] in the input's frame, from `F`
    /// or from its aliases `force` and `moment` (`p` is the input's JSON path).
    pub fn load(&self, p: &str) -> Result<[f64; 6], CaseError> {
        match (self.f, self.force, self.moment) {
            (Some(f), None, None) => Ok(f),
            (Some(_), ..) => Err(CaseError::new(p, "give the load as `F` or as its aliases `force` and `moment`, not both")),
            (None, force, moment) => {
                let (f, m) = (force.unwrap_or_default(), moment.unwrap_or_default());
                Ok([f[0], f[1], f[2], m[0], m[1], m[2]])
            }
        }
    }
}

/// One output entry: DOFs of a node, in the entry's frame (one output per DOF).
#[derive(Debug, Clone, PartialEq, Deserialize, schemars::JsonSchema)]
#[serde(deny_unknown_fields)]
pub struct OutputSpec {
    /// Name prefix in results and plots (default `node N`).
    pub name: Option<String>,
    /// The node.
    pub node: usize,
    /// The DOFs (`ux` … `rz`): displacements in mm, rotations in degrees.
    pub dofs: Vec<DofName>,
    /// Axes of the DOFs: three orthonormal right-handed rows; default the global axes.
    pub frame: Option<[[f64; 3]; 3]>,
}

/// The case fields of an `frf` case besides its model.
const OWN: [&str; 9] = [
    "analysis",
    "description",
    "mesh",
    "modes",
    "damping",
    "frequencies",
    "inputs",
    "outputs",
    "direct",
];

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct Options {
    #[serde(default)]
    description: Option<String>,
    #[serde(default)]
    mesh: Option<String>,
    modes: usize,
    #[serde(default)]
    damping: DampingSpec,
    frequencies: FrequencySpec,
    inputs: Vec<InputSpec>,
    outputs: Vec<OutputSpec>,
    #[serde(default = "yes")]
    direct: bool,
}

/// Parses an `frf` case; a mesh file it names resolves against `base` first.
pub fn parse_frf(value: Value, base: &crate::case::Source<'_>) -> Result<FrfCase, CaseError> {
    if let Some(key) = value
        .as_object()
        .and_then(|m| m.keys().find(|k| !OWN.contains(&k.as_str()) && !MODEL_FIELDS.contains(&k.as_str())))
    {
        return Err(CaseError::new(
            key.clone(),
            format!("unknown field `{key}` in an `frf` case, expected one of the model's fields or {OWN:?}"),
        ));
    }
    let (options, model) = split(value, &OWN);
    let o: Options = from_value(options, "")?;
    let model = read_model(model, o.mesh.as_deref(), None, base)?;
    let case = FrfCase {
        description: o.description,
        mesh: o.mesh,
        modes: o.modes,
        damping: o.damping,
        frequencies: o.frequencies,
        inputs: o.inputs,
        outputs: o.outputs,
        direct: o.direct,
        model,
    };
    Ok(case)
}

/// An `frf` case with its options checked and its model built: what [`run`] takes, so a run
/// validates the case once ([`FrfCase::validate`]).
pub struct ValidFrf<'a> {
    /// The case.
    pub case: &'a FrfCase,
    /// Its model.
    pub model: Model,
}

impl FrfCase {
    /// Validates the case once (options, then the model): the input of [`run`].
    pub fn validate(&self) -> Result<ValidFrf<'_>, CaseError> {
        self.check_options()?;
        let model = self.model.build_model(false)?;
        Ok(ValidFrf { case: self, model })
    }

    /// Validates everything but the model (which [`MeshSpec::build_model`] checks).
    pub fn check_options(&self) -> Result<(), CaseError> {
        if !(1..=1000).contains(&self.modes) {
            return Err(CaseError::value("modes", self.modes, "must be an integer from 1 to 1000"));
        }
        crate::case::limits::check_modal(self.modes, self.model.nodes.len())?;
        let d = &self.damping;
        check::non_negative("damping.alpha", d.alpha, "1/s")?;
        check::non_negative("damping.beta", d.beta, "s")?;
        if !(d.zeta.is_finite() && (0.0..1.0).contains(&d.zeta)) {
            return Err(CaseError::value("damping.zeta", d.zeta, "must be a ratio from 0 up to (not including) 1"));
        }
        let f = &self.frequencies;
        let lo = if f.spacing == Spacing::Log { "> 0" } else { "≥ 0" };
        if !(f.from_hz.is_finite() && (f.from_hz > 0.0 || (f.spacing == Spacing::Linear && f.from_hz == 0.0))) {
            return Err(CaseError::value("frequencies.from_hz", f.from_hz, format!("must be a frequency {lo}, Hz")));
        }
        if !(f.to_hz.is_finite() && f.to_hz > f.from_hz) {
            return Err(CaseError::value("frequencies.to_hz", f.to_hz, "must be a frequency above `from_hz`, Hz"));
        }
        if !(2..=100_000).contains(&f.points) {
            return Err(CaseError::value("frequencies.points", f.points, "must be an integer from 2 to 100000"));
        }
        if self.inputs.is_empty() {
            return Err(CaseError::new("inputs", "give at least one input"));
        }
        if self.outputs.is_empty() {
            return Err(CaseError::new("outputs", "give at least one output"));
        }
        let n = self.model.nodes.len();
        for (i, s) in self.inputs.iter().enumerate() {
            let p = format!("inputs[{i}]");
            check_node_frame(&p, s.node, s.frame, n)?;
            let f = s.load(&p)?;
            for (k, v) in f.iter().enumerate() {
                match s.f {
                    Some(_) => check::finite(format_args!("{p}.F[{k}]"), *v)?,
                    None => check::finite(format_args!("{p}.{}[{}]", if k < 3 { "force" } else { "moment" }, k % 3), *v)?,
                }
            }
            if f.iter().all(|v| *v == 0.0) {
                let field = if s.f.is_some() { "F" } else { "force" };
                return Err(CaseError::new(format!("{p}.{field}"), "the input loads nothing: give a nonzero `F` (or `force`, `moment`)"));
            }
        }
        for (i, s) in self.outputs.iter().enumerate() {
            let p = format!("outputs[{i}]");
            check_node_frame(&p, s.node, s.frame, n)?;
            if s.dofs.is_empty() {
                return Err(CaseError::new(format!("{p}.dofs"), "give at least one DOF (ux, uy, uz, rx, ry, rz)"));
            }
        }
        Ok(())
    }
}
