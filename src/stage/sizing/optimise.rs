//! Requirement-driven sizing of the stage hinges (Ruiz et al. (2019) §4–5): the requirements
//! as constraints on the [`StageProblem`]'s responses, solved by the generic
//! [`crate::problem::optimise`] maximising η.

use super::{params_of, rotation_demand, FatigueLimit, Params, Responses, RotationDemand, StageProblem};
use crate::problem::{self, Objective, Requirement, Sense};
use crate::stage::StageDesign;
use serde::Serialize;

pub use crate::problem::Constraint;

/// Requirements of the sizing problem.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct Requirements {
    /// Platform z travel to reach at the allowable stress (±), mm.
    pub z_travel: f64,
    /// Allowable stress, MPa.
    pub allowable: f64,
    /// Allowed range of T.
    #[serde(rename = "T")]
    pub t_range: [f64; 2],
    /// Platform tilt range of the kinematic sweep (±), rad.
    pub tilt: f64,
    /// Whether the fatigue-limited Δz d_f must reach `z_travel` too (`"fatigue"` requirement;
    /// the [`FatigueLimit`] is handed to [`optimise`]).
    pub fatigue: bool,
}

/// The requirements as constraints on the responses (indices of [`super::RESPONSES`]).
pub fn requirements(req: &Requirements) -> Vec<Requirement> {
    let c = |name: &str, response, limit, sense| Requirement {
        name: name.to_string(),
        response,
        sense,
        limit,
    };
    let mut out = vec![
        c("z_travel", 1, req.z_travel, Sense::AtLeast),
        c("T_min", 2, req.t_range[0], Sense::AtLeast),
        c("T_max", 2, req.t_range[1], Sense::AtMost),
        c("revolute_rotation_stress", 5, req.allowable, Sense::AtMost),
        c("spherical_rotation_stress", 6, req.allowable, Sense::AtMost),
    ];
    if req.fatigue {
        // Response 7: d_f, after the seven of `super::RESPONSES`.
        out.push(c("z_travel_fatigue", 7, req.z_travel, Sense::AtLeast));
    }
    out
}

/// The constraints of `r` (normalised so that ≤ 0 is met).
pub fn constraints(r: &Responses, req: &Requirements) -> Vec<Constraint> {
    problem::constraints(&r.to_vec(), &requirements(req))
}

/// A point visited by the optimiser.
#[derive(Debug, Clone, Serialize)]
pub struct HistoryEntry {
    /// `"sample"` or `"local"`.
    pub phase: &'static str,
    /// Parameters, mm ([`super::PARAMETERS`] order).
    pub params: Params,
    /// η, N/mm (0 if the design failed).
    pub eta: f64,
    /// d, mm.
    pub z_at_allowable: f64,
    /// T.
    #[serde(rename = "T")]
    pub t_ratio: f64,
    /// Largest normalised constraint violation (≤ 0: feasible).
    pub max_violation: f64,
}

/// Outcome of [`optimise`].
#[derive(Debug, Clone, Serialize)]
pub struct DesignOutcome {
    /// Best design found, mm ([`super::PARAMETERS`] order).
    pub params: Params,
    /// Whether it meets every requirement.
    pub meets: bool,
    /// Its responses.
    pub responses: Responses,
    /// Its constraints.
    pub constraints: Vec<Constraint>,
    /// Names of active (within 1 %) or violated constraints.
    pub binding: Vec<String>,
    /// Kinematic rotation demand used, rad.
    pub demand: RotationDemand,
    /// Designs evaluated.
    pub evaluations: usize,
    /// Samples and local iterations.
    pub history: Vec<HistoryEntry>,
}

fn params(p: &[f64]) -> Params {
    std::array::from_fn(|k| p[k])
}

/// Requirement-driven sizing: maximise η subject to the requirements within `bounds` (mm), by
/// [`crate::problem::optimise`] (Halton samples, then projected gradient descent on
/// −ln η + μ·Σ max(0, g)² with central finite differences). `fatigue` gives d_f; it is needed
/// (and used) when `req.fatigue` is set.
pub fn optimise(
    base: &StageDesign,
    bounds: &[[f64; 2]; 5],
    req: &Requirements,
    samples: usize,
    fatigue: Option<&dyn FatigueLimit>,
) -> Result<DesignOutcome, String> {
    if req.fatigue && fatigue.is_none() {
        return Err("a fatigue requirement needs the hinges' fatigue chain".into());
    }
    let mut base = base.clone();
    base.material.allowable = req.allowable;
    params_of(&base)?;
    let demand = rotation_demand(&base, req.z_travel, req.tilt).map_err(|e| e.to_string())?;
    let out = problem::optimise(
        &StageProblem::new(&base, demand).with_fatigue(fatigue),
        bounds,
        &requirements(req),
        &Objective::Maximise(0),
        samples,
    )?;
    let history = out
        .history
        .iter()
        .map(|h| {
            let (eta, z, t) = match h.responses.as_slice() {
                [eta, z, t, ..] => (*eta, *z, *t),
                _ => (0.0, 0.0, 0.0),
            };
            HistoryEntry {
                phase: h.phase,
                params: params(&h.params),
                eta,
                z_at_allowable: z,
                t_ratio: t,
                max_violation: h.max_violation,
            }
        })
        .collect();
    Ok(DesignOutcome {
        params: params(&out.params),
        meets: out.meets,
        responses: Responses::from_slice(&out.responses),
        constraints: out.constraints,
        binding: out.binding,
        demand,
        evaluations: out.evaluations,
        history,
    })
}
