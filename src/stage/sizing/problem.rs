//! The stage sizing as a design problem of [`crate::problem`]: the five hinge dimensions of
//! [`super::PARAMETERS`] in, the [`Responses`] of a unit pure-z stroke out.

use super::{evaluate_with, with_params, Responses, RotationDemand, PARAMETERS};
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

impl Responses {
    /// The responses in [`RESPONSES`] order.
    pub fn to_vec(&self) -> Vec<f64> {
        vec![
            self.eta,
            self.z_at_allowable,
            self.t_ratio,
            self.revolute_stress_per_mm,
            self.spherical_stress_per_mm,
            self.revolute_stress_at_demand,
            self.spherical_stress_at_demand,
        ]
    }

    /// The responses from a vector in [`RESPONSES`] order.
    pub fn from_slice(r: &[f64]) -> Responses {
        Responses {
            eta: r[0],
            z_at_allowable: r[1],
            t_ratio: r[2],
            revolute_stress_per_mm: r[3],
            spherical_stress_per_mm: r[4],
            revolute_stress_at_demand: r[5],
            spherical_stress_at_demand: r[6],
        }
    }
}

/// The base design with the rotation demand its hinges must meet.
pub struct StageProblem<'a> {
    base: &'a StageDesign,
    demand: RotationDemand,
    parameters: Vec<String>,
    responses: Vec<String>,
}

impl<'a> StageProblem<'a> {
    /// The problem of varying the hinges of `base` (circular notch + spherical neck).
    pub fn new(base: &'a StageDesign, demand: RotationDemand) -> Self {
        StageProblem {
            base,
            demand,
            parameters: PARAMETERS.map(String::from).to_vec(),
            responses: RESPONSES.map(String::from).to_vec(),
        }
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
        let r = evaluate_with(w, &with_params(self.base, &p), &self.demand).map_err(|e| e.to_string())?;
        if !(r.eta.is_finite() && r.z_at_allowable.is_finite() && r.t_ratio.is_finite()) {
            return Err(format!(
                "the design gives η = {}, d = {}, T = {} (not finite)",
                r.eta, r.z_at_allowable, r.t_ratio
            ));
        }
        Ok(r.to_vec())
    }
}
