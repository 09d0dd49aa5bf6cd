//! The stage sizing as a design problem of [`crate::problem`]: the five hinge dimensions of
//! [`super::PARAMETERS`] in, the [`Responses`] of a unit pure-z stroke out.

use super::{evaluate_with, with_params, FatigueLimit, Responses, RotationDemand, PARAMETERS};
use crate::fem::SolverCache;
use crate::problem::Problem;
use crate::stage::StageDesign;

/// Names of the responses in [`Responses::to_vec`] order (the JSON keys of [`Responses`]).
pub const RESPONSES: [&str; 7] = [
    "eta",
    "z_at_allowable",
    "T",
    "revolute_stress_per_mm",
    "spherical_stress_per_mm",
    "revolute_stress_at_demand",
    "spherical_stress_at_demand",
];

/// Name of the response after [`RESPONSES`] when the problem has a [`FatigueLimit`].
pub const FATIGUE_RESPONSE: &str = "z_at_fatigue_limit";

impl Responses {
    /// The responses in [`RESPONSES`] order, then [`FATIGUE_RESPONSE`] if computed.
    pub fn to_vec(&self) -> Vec<f64> {
        let mut v = vec![
            self.eta,
            self.z_at_allowable,
            self.t_ratio,
            self.revolute_stress_per_mm,
            self.spherical_stress_per_mm,
            self.revolute_stress_at_demand,
            self.spherical_stress_at_demand,
        ];
        v.extend(self.z_at_fatigue_limit);
        v
    }

    /// The responses from a vector in [`Self::to_vec`] order.
    pub fn from_slice(r: &[f64]) -> Responses {
        Responses {
            eta: r[0],
            z_at_allowable: r[1],
            t_ratio: r[2],
            revolute_stress_per_mm: r[3],
            spherical_stress_per_mm: r[4],
            revolute_stress_at_demand: r[5],
            spherical_stress_at_demand: r[6],
            z_at_fatigue_limit: r.get(7).copied(),
        }
    }
}

/// The base design with the rotation demand its hinges must meet.
pub struct StageProblem<'a> {
    base: &'a StageDesign,
    demand: RotationDemand,
    fatigue: Option<&'a dyn FatigueLimit>,
    parameters: Vec<String>,
    responses: Vec<String>,
}

impl<'a> StageProblem<'a> {
    /// The problem of varying the hinges of `base` (circular notch + spherical neck).
    pub fn new(base: &'a StageDesign, demand: RotationDemand) -> Self {
        StageProblem {
            base,
            demand,
            fatigue: None,
            parameters: PARAMETERS.map(String::from).to_vec(),
            responses: RESPONSES.map(String::from).to_vec(),
        }
    }

    /// The problem with the fatigue-limited Δz d_f as a further response ([`FATIGUE_RESPONSE`]).
    pub fn with_fatigue(mut self, fatigue: Option<&'a dyn FatigueLimit>) -> Self {
        if fatigue.is_some() {
            self.responses.push(FATIGUE_RESPONSE.to_string());
        }
        self.fatigue = fatigue;
        self
    }
}

impl Problem for StageProblem<'_> {
    type Worker = SolverCache;

    fn parameters(&self) -> &[String] {
        &self.parameters
    }
    fn responses(&self) -> &[String] {
        &self.responses
    }
    fn worker(&self) -> SolverCache {
        SolverCache::new()
    }
    fn evaluate(&self, w: &mut SolverCache, p: &[f64]) -> Result<Vec<f64>, String> {
        let p: super::Params = p
            .try_into()
            .map_err(|_| format!("the stage has {} parameters, {} given", PARAMETERS.len(), p.len()))?;
        let r = evaluate_with(w, &with_params(self.base, &p), &self.demand, self.fatigue).map_err(|e| e.to_string())?;
        if !(r.eta.is_finite() && r.z_at_allowable.is_finite() && r.t_ratio.is_finite()) {
            return Err(format!(
                "the design gives η = {}, d = {}, T = {} (not finite)",
                r.eta, r.z_at_allowable, r.t_ratio
            ));
        }
        if let Some(zf) = r.z_at_fatigue_limit.filter(|z| !z.is_finite()) {
            return Err(format!("the design gives a fatigue-limited Δz d_f = {zf} (not finite)"));
        }
        Ok(r.to_vec())
    }
}
