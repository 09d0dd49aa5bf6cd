//! Requirement-driven sizing of the stage hinges (Ruiz et al. (2019) §4–5): constraints of a
//! design and the bounded optimiser.

use super::{evaluate_with, params_of, rotation_demand, with_params, Params, Responses, RotationDemand};
use crate::fem::SolverCache;
use crate::stage::StageDesign;
use rayon::prelude::*;
use serde::Serialize;

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
}

/// One constraint at a design: `value` must satisfy the `limit` in the `sense` given.
#[derive(Debug, Clone, Serialize)]
pub struct Constraint {
    /// Name.
    pub name: &'static str,
    /// Value at the design.
    pub value: f64,
    /// Limit.
    pub limit: f64,
    /// `">="` or `"<="`.
    pub sense: &'static str,
    /// Normalised violation (≤ 0 when met).
    pub violation: f64,
}

/// The constraints of `r` (normalised so that ≤ 0 is met).
pub fn constraints(r: &Responses, req: &Requirements) -> Vec<Constraint> {
    let c = |name, value: f64, limit: f64, ge: bool| Constraint {
        name,
        value,
        limit,
        sense: if ge { ">=" } else { "<=" },
        violation: if ge {
            (limit - value) / limit.abs().max(1e-12)
        } else {
            (value - limit) / limit.abs().max(1e-12)
        },
    };
    vec![
        c("z_travel", r.z_at_allowable, req.z_travel, true),
        c("T_min", r.t_ratio, req.t_range[0], true),
        c("T_max", r.t_ratio, req.t_range[1], false),
        c(
            "revolute_rotation_stress",
            r.revolute_stress_at_demand,
            req.allowable,
            false,
        ),
        c(
            "spherical_rotation_stress",
            r.spherical_stress_at_demand,
            req.allowable,
            false,
        ),
    ]
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
    pub binding: Vec<&'static str>,
    /// Kinematic rotation demand used, rad.
    pub demand: RotationDemand,
    /// Designs evaluated.
    pub evaluations: usize,
    /// Samples and local iterations.
    pub history: Vec<HistoryEntry>,
}

struct Eval {
    p: Params,
    r: Option<Responses>,
    viol: f64,
    merit_eta: f64,
}

fn eval_point(
    cache: &mut SolverCache,
    base: &StageDesign,
    p: &Params,
    demand: &RotationDemand,
    req: &Requirements,
) -> Eval {
    match evaluate_with(cache, &with_params(base, p), demand) {
        Ok(r) if r.eta.is_finite() && r.z_at_allowable.is_finite() && r.t_ratio.is_finite() => {
            let viol = constraints(&r, req)
                .iter()
                .map(|c| c.violation)
                .fold(f64::NEG_INFINITY, f64::max);
            Eval {
                p: *p,
                r: Some(r),
                viol,
                merit_eta: r.eta,
            }
        }
        _ => Eval {
            p: *p,
            r: None,
            viol: f64::INFINITY,
            merit_eta: 0.0,
        },
    }
}

fn better(a: &Eval, b: &Eval) -> bool {
    // Feasible beats infeasible; among feasible, stiffer; among infeasible, less violated.
    match (a.viol <= 0.0, b.viol <= 0.0) {
        (true, false) => true,
        (false, true) => false,
        (true, true) => a.merit_eta > b.merit_eta,
        (false, false) => a.viol < b.viol,
    }
}

/// Halton point `i` in [0, 1)^5.
fn halton(mut i: usize, base: usize) -> f64 {
    let (mut f, mut r) = (1.0, 0.0);
    i += 1;
    while i > 0 {
        f /= base as f64;
        r += f * (i % base) as f64;
        i /= base;
    }
    r
}

/// Requirement-driven sizing: maximise η subject to the requirements within `bounds` (mm).
///
/// Method: `samples` quasi-random (Halton) designs over the box, then a bounded local search
/// from the best one — projected gradient descent on −ln η + μ·Σ max(0, g)² in normalised
/// coordinates, gradients by central finite differences, backtracking line search, μ raised
/// from 10 to 10⁴ — keeping the best design seen.
pub fn optimise(
    base: &StageDesign,
    bounds: &[[f64; 2]; 5],
    req: &Requirements,
    samples: usize,
) -> Result<DesignOutcome, String> {
    let mut base = base.clone();
    base.material.allowable = req.allowable;
    params_of(&base)?;
    let demand = rotation_demand(&base, req.z_travel, req.tilt).map_err(|e| e.to_string())?;
    let to_p =
        |u: &[f64; 5]| -> Params { std::array::from_fn(|k| bounds[k][0] + u[k] * (bounds[k][1] - bounds[k][0])) };
    let primes = [2, 3, 5, 7, 11];
    let pts: Vec<[f64; 5]> = (0..samples.max(1))
        .map(|i| std::array::from_fn(|k| halton(i, primes[k])))
        .collect();
    let evals: Vec<Eval> = pts
        .par_iter()
        .map_init(SolverCache::new, |cache, u| {
            eval_point(cache, &base, &to_p(u), &demand, req)
        })
        .collect();
    let mut history: Vec<HistoryEntry> = evals.iter().map(|e| entry("sample", e)).collect();
    let mut evaluations = evals.len();
    let mut best_i = 0;
    for (i, e) in evals.iter().enumerate() {
        if better(e, &evals[best_i]) {
            best_i = i;
        }
    }
    let mut u = pts[best_i];
    let mut cache = SolverCache::new();
    let mut best = eval_point(&mut cache, &base, &to_p(&u), &demand, req);
    evaluations += 1;
    let merit = |e: &Eval, mu: f64| -> f64 {
        match &e.r {
            None => f64::INFINITY,
            Some(r) => {
                let pen: f64 = constraints(r, req).iter().map(|c| c.violation.max(0.0).powi(2)).sum();
                -r.eta.ln() + mu * pen
            }
        }
    };
    let h = 1e-3;
    for mu in [10.0, 100.0, 1e3, 1e4] {
        let mut step = 0.1;
        for _ in 0..15 {
            let cur = eval_point(&mut cache, &base, &to_p(&u), &demand, req);
            let f0 = merit(&cur, mu);
            if !f0.is_finite() {
                break;
            }
            let grads: Vec<f64> = (0..5)
                .into_par_iter()
                .map_init(SolverCache::new, |cache, k| {
                    let mut up = u;
                    let mut um = u;
                    up[k] = (up[k] + h).min(1.0);
                    um[k] = (um[k] - h).max(0.0);
                    let fp = merit(&eval_point(cache, &base, &to_p(&up), &demand, req), mu);
                    let fm = merit(&eval_point(cache, &base, &to_p(&um), &demand, req), mu);
                    if fp.is_finite() && fm.is_finite() && up[k] > um[k] {
                        (fp - fm) / (up[k] - um[k])
                    } else {
                        0.0
                    }
                })
                .collect();
            evaluations += 10;
            let gn = grads.iter().map(|g| g * g).sum::<f64>().sqrt();
            if gn < 1e-9 {
                break;
            }
            let mut moved = false;
            while step > 1e-4 {
                let trial: [f64; 5] = std::array::from_fn(|k| (u[k] - step * grads[k] / gn).clamp(0.0, 1.0));
                let e = eval_point(&mut cache, &base, &to_p(&trial), &demand, req);
                evaluations += 1;
                if merit(&e, mu) < f0 {
                    u = trial;
                    history.push(entry("local", &e));
                    if better(&e, &best) {
                        best = e;
                    }
                    step *= 1.5;
                    moved = true;
                    break;
                }
                step *= 0.5;
            }
            if !moved {
                break;
            }
        }
    }
    let r = best
        .r
        .ok_or_else(|| "no design in the bounds could be built and solved".to_string())?;
    let cons = constraints(&r, req);
    let binding = cons.iter().filter(|c| c.violation > -0.01).map(|c| c.name).collect();
    Ok(DesignOutcome {
        params: best.p,
        meets: best.viol <= 0.0,
        responses: r,
        constraints: cons,
        binding,
        demand,
        evaluations,
        history,
    })
}

fn entry(phase: &'static str, e: &Eval) -> HistoryEntry {
    let (eta, z, t) = e.r.map_or((0.0, 0.0, 0.0), |r| (r.eta, r.z_at_allowable, r.t_ratio));
    HistoryEntry {
        phase,
        params: e.p,
        eta,
        z_at_allowable: z,
        t_ratio: t,
        max_violation: if e.viol.is_finite() { e.viol } else { 1e9 },
    }
}
