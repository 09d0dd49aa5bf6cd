//! The `pantilt` case: pseudo-rigid-body model of the 8R compliant parallel pan-tilt of J. Yu,
//! D. Lu and G. Hao, "Design and analysis of a compliant parallel pan-tilt platform", Meccanica
//! (2016). Every field has that paper's value as
//! its default (with the limb azimuth reading documented in [`crate::kinematics::pantilt`]).

use super::error::{check, num, CaseError};
use crate::kinematics::pantilt::{circle, JointSprings, PanTilt, PanTiltGeometry, PathSample, Pointing, JOINTS};
use serde::Deserialize;
use std::f64::consts::PI;

/// A `pantilt` case.
#[derive(Debug, Clone, Deserialize, schemars::JsonSchema)]
#[serde(deny_unknown_fields)]
pub struct PanTiltCase {
    /// Mechanism geometry (default: Yu et al. (2016)).
    #[serde(default)]
    pub mechanism: MechanismSpec,
    /// Joint stiffness and damping of the PRBM (default: Yu et al. (2016) §4, K = 4.78 N·mm/°,
    /// D = 0.226 N·mm·s/° on all joints).
    #[serde(default)]
    pub joints: JointsSpec,
    /// Platform path for joint histories and torques (omitted: none).
    #[serde(default)]
    pub path: Option<PathSpec>,
    /// Inverse-kinematics queries.
    #[serde(default)]
    pub ik: Vec<PoseSpec>,
    /// Forward-kinematics queries.
    #[serde(default)]
    pub fk: Vec<FkSpec>,
}

/// Geometry of the 8R mechanism (all angles in degrees; limbs numbered 1–3).
#[derive(Debug, Clone, Deserialize, schemars::JsonSchema)]
#[serde(deny_unknown_fields)]
pub struct MechanismSpec {
    /// θ₀: angle between each middle joint axis and the top (platform) axis, degrees, (0, 180).
    #[serde(default = "default_theta0")]
    #[schemars(extend("exclusiveMinimum" = 0, "exclusiveMaximum" = 180))]
    pub theta0_deg: f64,
    /// δ: angle between the bottom and middle joint axes of a limb, degrees, (0, 180).
    #[serde(default = "default_delta")]
    #[schemars(extend("exclusiveMinimum" = 0, "exclusiveMaximum" = 180))]
    pub delta_deg: f64,
    /// Azimuths ε of limbs 1–3 (their vertical planes), degrees. Default [−90, 150, 30].
    #[serde(default = "default_azimuths")]
    pub azimuths_deg: [f64; 3],
    /// The RR (two-joint) limb, 1–3. Default 2.
    #[serde(default = "default_rr")]
    #[schemars(range(min = 1, max = 3))]
    pub rr_limb: usize,
    /// The two limbs whose bottom joints are actuated, 1–3. Default [1, 2] (J1, J2).
    #[serde(default = "default_actuated")]
    #[schemars(extend("items" = {"type": "integer", "minimum": 1, "maximum": 3}))]
    pub actuated: [usize; 2],
}

fn default_theta0() -> f64 {
    60.0
}
fn default_delta() -> f64 {
    90.0
}
fn default_azimuths() -> [f64; 3] {
    [-90.0, 150.0, 30.0]
}
fn default_rr() -> usize {
    2
}
fn default_actuated() -> [usize; 2] {
    [1, 2]
}

impl Default for MechanismSpec {
    fn default() -> Self {
        Self {
            theta0_deg: default_theta0(),
            delta_deg: default_delta(),
            azimuths_deg: default_azimuths(),
            rr_limb: default_rr(),
            actuated: default_actuated(),
        }
    }
}

/// One value for all eight joints or one per joint J1–J8.
#[derive(Debug, Clone, Deserialize, schemars::JsonSchema)]
#[serde(untagged)]
pub enum PerJoint {
    /// The same value on every joint.
    All(f64),
    /// J1–J8.
    Each([f64; JOINTS]),
}

impl PerJoint {
    fn values(&self) -> [f64; JOINTS] {
        match self {
            PerJoint::All(v) => [*v; JOINTS],
            PerJoint::Each(v) => *v,
        }
    }
}

/// Torsional stiffness and viscous damping of the PRBM joints.
#[derive(Debug, Clone, Deserialize, schemars::JsonSchema)]
#[serde(deny_unknown_fields)]
pub struct JointsSpec {
    /// Stiffness K, N·mm/degree (≥ 0): a number for all joints or eight values J1–J8.
    #[serde(rename = "K", default = "default_k")]
    pub k: PerJoint,
    /// Damping D, N·mm·s/degree (≥ 0): a number for all joints or eight values J1–J8.
    #[serde(rename = "D", default = "default_d")]
    pub d: PerJoint,
}

fn default_k() -> PerJoint {
    PerJoint::All(4.78)
}
fn default_d() -> PerJoint {
    PerJoint::All(0.226)
}

impl Default for JointsSpec {
    fn default() -> Self {
        Self {
            k: default_k(),
            d: default_d(),
        }
    }
}

/// Direction of a circular path.
#[derive(Debug, Clone, Copy, Deserialize, schemars::JsonSchema, PartialEq, Eq)]
#[serde(rename_all = "snake_case")]
pub enum Direction {
    /// φ increases with time (counter-clockwise seen from above).
    Ccw,
    /// φ decreases with time.
    Cw,
}

/// A prescribed platform path.
#[derive(Debug, Clone, Deserialize, schemars::JsonSchema)]
#[serde(tag = "type", rename_all = "snake_case", deny_unknown_fields)]
pub enum PathSpec {
    /// Uniform circular motion: constant pitch, φ over one full turn in `period` seconds,
    /// sampled at `points` equally spaced times t = 0, T/N, …, (N−1)T/N.
    Circle {
        /// Pitch γ, degrees, [0, 80].
        gamma_deg: f64,
        /// Phase at t = 0, degrees (default 0).
        #[serde(default)]
        phi0_deg: f64,
        /// Period T, s (default 1).
        #[serde(default = "default_period")]
        period: f64,
        /// Number of samples, 2–100000 (default 360).
        #[serde(default = "default_points")]
        #[schemars(range(min = 2, max = 100000))]
        points: usize,
        /// `ccw` (default, φ increasing) or `cw`.
        #[serde(default = "default_direction")]
        direction: Direction,
    },
    /// Samples of γ(t), φ(t); rates by second-order finite differences in time (one-sided at
    /// the ends), φ unwrapped across ±180°.
    Samples {
        /// At least 3 samples with strictly increasing t.
        samples: Vec<SampleSpec>,
    },
}

fn default_period() -> f64 {
    1.0
}
fn default_points() -> usize {
    360
}
fn default_direction() -> Direction {
    Direction::Ccw
}

/// One sample of a prescribed path.
#[derive(Debug, Clone, Copy, Deserialize, schemars::JsonSchema)]
#[serde(deny_unknown_fields)]
pub struct SampleSpec {
    /// Time, s.
    pub t: f64,
    /// Pitch γ, degrees, [0, 80].
    pub gamma_deg: f64,
    /// Phase φ, degrees.
    pub phi_deg: f64,
}

/// A platform pose (pitch γ, phase φ), degrees.
#[derive(Debug, Clone, Copy, Deserialize, schemars::JsonSchema)]
#[serde(deny_unknown_fields)]
pub struct PoseSpec {
    /// Pitch γ, degrees, [0, 80].
    pub gamma_deg: f64,
    /// Phase φ, degrees.
    pub phi_deg: f64,
}

/// A forward-kinematics query.
#[derive(Debug, Clone, Copy, Deserialize, schemars::JsonSchema)]
#[serde(deny_unknown_fields)]
pub struct FkSpec {
    /// Actuated joint rotations from home, degrees.
    pub theta_deg: [f64; 2],
    /// Newton start pose (default: home).
    #[serde(default)]
    pub start: Option<PoseSpec>,
}

/// Largest pitch accepted anywhere, degrees: the regular coordinates (r₇ₓ, r₇ᵧ) need γ < 90°.
pub const MAX_GAMMA_DEG: f64 = 80.0;

/// A validated `pantilt` case.
#[derive(Debug, Clone)]
pub struct ValidPanTilt {
    /// The mechanism.
    pub model: PanTilt,
    /// Its geometry as given (degrees, 1-based limbs), for the echo in results.
    pub spec: MechanismSpec,
    /// Joint springs and dampers (per radian).
    pub springs: JointSprings,
    /// Path samples (empty without a path).
    pub path: Vec<PathSample>,
    /// IK queries.
    pub ik: Vec<Pointing>,
    /// FK queries: actuated angles (rad) and Newton start.
    pub fk: Vec<([f64; 2], Option<Pointing>)>,
}

fn pose(path: &str, gamma_deg: f64, phi_deg: f64) -> Result<Pointing, CaseError> {
    check::within(
        format_args!("{path}.gamma_deg"),
        gamma_deg,
        0.0,
        MAX_GAMMA_DEG,
        "degrees",
    )?;
    check::finite(format_args!("{path}.phi_deg"), phi_deg)?;
    Ok(Pointing::from_deg(gamma_deg, phi_deg))
}

impl MechanismSpec {
    /// Validates and builds the mechanism; `path` is the JSON path of this object.
    pub fn build(&self, path: &str) -> Result<PanTilt, CaseError> {
        let p = |f: &str| format!("{path}.{f}");
        for (f, v) in [("theta0_deg", self.theta0_deg), ("delta_deg", self.delta_deg)] {
            if !(v.is_finite() && v > 0.0 && v < 180.0) {
                return Err(CaseError::value(p(f), num(v), "must lie in (0, 180) degrees"));
            }
        }
        for (i, a) in self.azimuths_deg.iter().enumerate() {
            check::finite(format_args!("{path}.azimuths_deg[{i}]"), *a)?;
        }
        if !(1..=3).contains(&self.rr_limb) {
            return Err(CaseError::value(p("rr_limb"), self.rr_limb, "must be 1, 2 or 3"));
        }
        for (i, a) in self.actuated.iter().enumerate() {
            if !(1..=3).contains(a) {
                return Err(CaseError::value(
                    format!("{path}.actuated[{i}]"),
                    a,
                    "must be 1, 2 or 3",
                ));
            }
        }
        if self.actuated[0] == self.actuated[1] {
            return Err(CaseError::value(
                p("actuated"),
                format!("{:?}", self.actuated),
                "the two actuated limbs must differ",
            ));
        }
        let g = PanTiltGeometry {
            theta0: self.theta0_deg.to_radians(),
            delta: self.delta_deg.to_radians(),
            azimuths: self.azimuths_deg.map(f64::to_radians),
            rr_limb: self.rr_limb - 1,
            actuated: self.actuated.map(|a| a - 1),
        };
        PanTilt::new(g).map_err(|e| CaseError::new(path, e.to_string()))
    }
}

impl JointsSpec {
    fn build(&self, path: &str) -> Result<JointSprings, CaseError> {
        for (name, spec, unit) in [("K", &self.k, "N·mm/degree"), ("D", &self.d, "N·mm·s/degree")] {
            match spec {
                PerJoint::All(v) => check::non_negative(format_args!("{path}.{name}"), *v, unit)?,
                PerJoint::Each(vs) => {
                    for (i, v) in vs.iter().enumerate() {
                        check::non_negative(format_args!("{path}.{name}[{i}]"), *v, unit)?;
                    }
                }
            }
        }
        let (k, d) = (self.k.values(), self.d.values());
        let to_rad = 180.0 / PI;
        Ok(JointSprings {
            stiffness: k.map(|v| v * to_rad),
            damping: d.map(|v| v * to_rad),
        })
    }
}

impl PathSpec {
    fn build(&self, path: &str) -> Result<Vec<PathSample>, CaseError> {
        match self {
            PathSpec::Circle {
                gamma_deg,
                phi0_deg,
                period,
                points,
                direction,
            } => {
                let start = pose(path, *gamma_deg, *phi0_deg)
                    .map_err(|e| CaseError::new(e.path.replace(".phi_deg", ".phi0_deg"), e.message))?;
                check::positive(format_args!("{path}.period"), *period, "s")?;
                if !(2..=100_000).contains(points) {
                    return Err(CaseError::value(
                        format!("{path}.points"),
                        points,
                        "must lie in 2..=100000",
                    ));
                }
                Ok(circle(
                    start.gamma,
                    start.phi,
                    *period,
                    *points,
                    *direction == Direction::Cw,
                ))
            }
            PathSpec::Samples { samples } => {
                if samples.len() < 3 {
                    return Err(CaseError::value(
                        format!("{path}.samples"),
                        format!("{} samples", samples.len()),
                        "give at least 3 samples (rates need finite differences)",
                    ));
                }
                let mut poses = Vec::with_capacity(samples.len());
                for (i, s) in samples.iter().enumerate() {
                    let at = format!("{path}.samples[{i}]");
                    check::finite(format_args!("{at}.t"), s.t)?;
                    if i > 0 && s.t <= samples[i - 1].t {
                        return Err(CaseError::value(
                            format!("{at}.t"),
                            num(s.t),
                            format!("times must increase strictly (previous {})", num(samples[i - 1].t)),
                        ));
                    }
                    poses.push(pose(&at, s.gamma_deg, s.phi_deg)?);
                }
                Ok(sampled_rates(samples, &poses))
            }
        }
    }
}

/// Rates of sampled γ(t), φ(t) by the three-point (second-order, non-uniform) difference
/// formula, one-sided at the ends; φ is unwrapped so a step across ±180° is not a jump.
fn sampled_rates(samples: &[SampleSpec], poses: &[Pointing]) -> Vec<PathSample> {
    let n = samples.len();
    let t: Vec<f64> = samples.iter().map(|s| s.t).collect();
    let g: Vec<f64> = poses.iter().map(|p| p.gamma).collect();
    let mut phi: Vec<f64> = poses.iter().map(|p| p.phi).collect();
    for i in 1..n {
        let d = (phi[i] - phi[i - 1] + PI).rem_euclid(2.0 * PI) - PI;
        phi[i] = phi[i - 1] + d;
    }
    // Derivative at t[i] of the parabola through samples a, b, c.
    let d3 = |y: &[f64], i: usize, a: usize, b: usize, c: usize| {
        let (ta, tb, tc, x) = (t[a], t[b], t[c], t[i]);
        y[a] * ((x - tb) + (x - tc)) / ((ta - tb) * (ta - tc))
            + y[b] * ((x - ta) + (x - tc)) / ((tb - ta) * (tb - tc))
            + y[c] * ((x - ta) + (x - tb)) / ((tc - ta) * (tc - tb))
    };
    (0..n)
        .map(|i| {
            let (a, b, c) = if i == 0 {
                (0, 1, 2)
            } else if i == n - 1 {
                (n - 3, n - 2, n - 1)
            } else {
                (i - 1, i, i + 1)
            };
            PathSample {
                t: t[i],
                pose: poses[i],
                gamma_rate: d3(&g, i, a, b, c),
                phi_rate: d3(&phi, i, a, b, c),
            }
        })
        .collect()
}

impl PanTiltCase {
    /// Validates everything that can be checked before solving.
    pub fn validate(&self) -> Result<ValidPanTilt, CaseError> {
        let model = self.mechanism.build("mechanism")?;
        let springs = self.joints.build("joints")?;
        let path = match &self.path {
            Some(p) => p.build("path")?,
            None => Vec::new(),
        };
        let ik = self
            .ik
            .iter()
            .enumerate()
            .map(|(i, q)| pose(&format!("ik[{i}]"), q.gamma_deg, q.phi_deg))
            .collect::<Result<Vec<_>, _>>()?;
        let mut fk = Vec::with_capacity(self.fk.len());
        for (i, q) in self.fk.iter().enumerate() {
            for (k, v) in q.theta_deg.iter().enumerate() {
                check::within(format_args!("fk[{i}].theta_deg[{k}]"), *v, -90.0, 90.0, "degrees")?;
            }
            let start = match &q.start {
                Some(s) => Some(pose(&format!("fk[{i}].start"), s.gamma_deg, s.phi_deg)?),
                None => None,
            };
            fk.push((q.theta_deg.map(f64::to_radians), start));
        }
        if path.is_empty() && ik.is_empty() && fk.is_empty() {
            return Err(CaseError::new(
                ".",
                "nothing to compute: give a `path`, `ik` queries or `fk` queries",
            ));
        }
        Ok(ValidPanTilt {
            model,
            spec: self.mechanism.clone(),
            springs,
            path,
            ik,
            fk,
        })
    }
}
