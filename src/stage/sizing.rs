//! The stage design loop of Ruiz et al. (2019) §5 (Table 1, Fig. 11): responses of a design, Table-1
//! sensitivities, and requirement-driven sizing.
//!
//! Design parameters (mm): `t_rev`, `R_rev` (circular revolute notch), `t_sph`, `R_sph`, `l_sph`
//! (turned spherical neck). Responses:
//! * η — structural stiffness: total actuator force per mm of pure-z stroke, N/mm;
//! * d — platform Δz reached when the peak hinge stress reaches the allowable (pure z), mm;
//! * T = σ_sph,max / σ_rev,max.
//!
//! Requirements (Ruiz et al. 2019, §4): d ≥ z_travel, T ∈ [T_lo, T_hi], and each hinge able to
//! reach the joint rotations of the kinematic requirement sweep (revolute Δα, spherical βm, βn,
//! βl over z = ±z_travel, ψ, θ = ±tilt) below the allowable stress.

use crate::fem::SolverCache;
use crate::hinge::HingeSpec;
use crate::kinematics::{workspace, PoseBox};
use crate::stage::{Drive, StageDesign, StageError};
use rayon::prelude::*;
use serde::Serialize;
use std::f64::consts::PI;

/// The five design parameters in Table-1 order.
pub const PARAMETERS: [&str; 5] = ["t_rev", "R_rev", "t_sph", "R_sph", "l_sph"];

/// Values of the five parameters, mm, in [`PARAMETERS`] order.
pub type Params = [f64; 5];

/// Reads the parameters of a design (circular notch + spherical neck only).
pub fn params_of(d: &StageDesign) -> Result<Params, String> {
    let (t_rev, r_rev) = match d.revolute {
        HingeSpec::CircularNotch { r, t, .. } => (t, r),
        _ => return Err("the design loop varies a circular_notch revolute hinge".into()),
    };
    let (t_sph, r_sph, l_sph) = match d.spherical {
        HingeSpec::SphericalNeck { l, t, r, .. } => (t, r, l),
        _ => return Err("the design loop varies a spherical_neck spherical hinge".into()),
    };
    Ok([t_rev, r_rev, t_sph, r_sph, l_sph])
}

/// The design with its hinge parameters replaced by `p`.
pub fn with_params(d: &StageDesign, p: &Params) -> StageDesign {
    let mut out = d.clone();
    if let HingeSpec::CircularNotch { r, t, .. } = &mut out.revolute {
        *t = p[0];
        *r = p[1];
    }
    if let HingeSpec::SphericalNeck { t, r, l, .. } = &mut out.spherical {
        *t = p[2];
        *r = p[3];
        *l = p[4];
    }
    out
}

/// Joint rotations the hinges must reach (from the kinematic requirement sweep), rad.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct RotationDemand {
    /// Largest |Δα| of the revolute joints, rad.
    pub revolute: f64,
    /// Largest |βm|, rad.
    pub spherical_m: f64,
    /// Largest |βn|, rad.
    pub spherical_n: f64,
    /// Largest |βl|, rad.
    pub spherical_l: f64,
}

/// Sweeps the rigid-body kinematics over z = ±z_travel, ψ, θ = ±tilt (rad) for the rotations
/// the hinges must reach.
pub fn rotation_demand(d: &StageDesign, z_travel: f64, tilt: f64) -> Result<RotationDemand, StageError> {
    let bx = PoseBox {
        z: [-z_travel, z_travel],
        psi: [-tilt, tilt],
        theta: [-tilt, tilt],
        steps: 5,
    };
    let w = workspace::sweep(&d.prs, &bx).map_err(|e| StageError::Geometry {
        field: "L".into(),
        message: e.to_string(),
    })?;
    let m = |r: [f64; 2]| r[0].abs().max(r[1].abs());
    Ok(RotationDemand {
        revolute: m(w.revolute_delta),
        spherical_m: m(w.spherical_m),
        spherical_n: m(w.spherical_n),
        spherical_l: m(w.spherical_l),
    })
}

/// Responses of one design (pure-z motion, linear).
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct Responses {
    /// Structural stiffness η: total actuator force per mm of pure-z stroke, N/mm.
    pub eta: f64,
    /// Platform Δz reached at the allowable stress, mm.
    pub z_at_allowable: f64,
    /// T = σ_sph,max / σ_rev,max.
    #[serde(rename = "T")]
    pub t_ratio: f64,
    /// Peak revolute-hinge stress per mm of platform z, MPa/mm.
    pub revolute_stress_per_mm: f64,
    /// Peak spherical-hinge stress per mm of platform z, MPa/mm.
    pub spherical_stress_per_mm: f64,
    /// Revolute-notch stress at the demanded rotation Δα, MPa.
    pub revolute_stress_at_demand: f64,
    /// Spherical-neck von Mises stress at the demanded βm, βn, βl (taken together), MPa.
    pub spherical_stress_at_demand: f64,
}

/// Evaluates a design: one linear solve of a unit pure-z stroke set.
pub fn evaluate(d: &StageDesign, demand: &RotationDemand) -> Result<Responses, StageError> {
    evaluate_with(&mut SolverCache::new(), d, demand)
}

/// [`evaluate`] with the caller's solver cache (designs of one loop share the topology).
pub fn evaluate_with(
    cache: &mut SolverCache,
    d: &StageDesign,
    demand: &RotationDemand,
) -> Result<Responses, StageError> {
    let stage = d.build()?;
    let j = d
        .prs
        .actuation_jacobian(0.0, 0.0, 0.0)
        .map_err(|e| StageError::Geometry {
            field: "L".into(),
            message: e.to_string(),
        })?;
    let s = [j[(0, 0)], j[(1, 0)], j[(2, 0)]];
    let r = stage
        .solve_with(cache, &[("unit_z".to_string(), Drive::Strokes(s))])?
        .remove(0);
    let z = r.platform.z;
    let s_mean = (s[0] + s[1] + s[2]) / 3.0;
    let eta = r.forces.iter().sum::<f64>() / s_mean;
    let rev = r.revolute_stress.iter().cloned().fold(0.0, f64::max) / z.abs();
    let sph = r.spherical_stress.iter().cloned().fold(0.0, f64::max) / z.abs();
    let allowable = d.material.allowable;
    let rh = &stage.rev_hinge;
    let sh = &stage.sph_hinge;
    let rev_demand = rh.stress_per_moment * rh.k_bend * demand.revolute;
    let t_sph = match d.spherical {
        HingeSpec::SphericalNeck { t, .. } => t,
        _ => 1.0,
    };
    let sigma_b = sh.stress_per_moment * sh.k_bend * demand.spherical_m.hypot(demand.spherical_n);
    let tau = sh.k_torsion * demand.spherical_l * 16.0 / (PI * t_sph.powi(3));
    Ok(Responses {
        eta,
        z_at_allowable: allowable / rev.max(sph),
        t_ratio: sph / rev,
        revolute_stress_per_mm: rev,
        spherical_stress_per_mm: sph,
        revolute_stress_at_demand: rev_demand,
        spherical_stress_at_demand: (sigma_b * sigma_b + 3.0 * tau * tau).sqrt(),
    })
}

/// Table 1 bins of a ratio.
pub fn bin(ratio: f64) -> &'static str {
    match ratio {
        r if r < 0.5 => "< 0.5",
        r if r < 0.8 => "0.5-0.8",
        r if r < 1.0 => "0.8-1",
        r if r < 1.2 => "1-1.2",
        r if r <= 1.5 => "1.2-1.5",
        _ => "> 1.5",
    }
}

/// Table-1 bins of the three ratios.
#[derive(Debug, Clone, Serialize)]
pub struct Bins {
    /// η_{i+1}/η_i bin.
    pub stiffness: &'static str,
    /// d_{i+1}/d_i bin.
    pub displacement: &'static str,
    /// T_{i+1}/T_i bin.
    pub stress_ratio: &'static str,
}

/// One Table-1 row.
#[derive(Debug, Clone, Serialize)]
pub struct SensitivityRow {
    /// Parameter name.
    pub parameter: &'static str,
    /// Base value, mm.
    pub base: f64,
    /// Increased value, mm.
    pub increased: f64,
    /// η_{i+1}/η_i.
    pub stiffness_ratio: f64,
    /// d_{i+1}/d_i.
    pub displacement_ratio: f64,
    /// T_{i+1}/T_i.
    pub stress_ratio_ratio: f64,
    /// Bins as in Table 1.
    pub bins: Bins,
    /// Local elasticities ∂ln(η, d, T)/∂ln p at the base design (central differences, ±1 %).
    pub elasticity: [f64; 3],
}

/// Table 1: each parameter increased by `increment` (relative) from the base design.
pub fn sensitivity(
    base: &StageDesign,
    increment: f64,
    demand: &RotationDemand,
) -> Result<(Responses, Vec<SensitivityRow>), String> {
    let p0 = params_of(base)?;
    let r0 = evaluate(base, demand).map_err(|e| format!("base design: {e}"))?;
    let rows: Result<Vec<SensitivityRow>, String> = (0..5)
        .into_par_iter()
        .map_init(SolverCache::new, |cache, k| {
            let name = PARAMETERS[k];
            let mut eval = |f: f64| {
                let mut p = p0;
                p[k] *= f;
                evaluate_with(cache, &with_params(base, &p), demand).map_err(|e| format!("{name} × {f}: {e}"))
            };
            let r1 = eval(1.0 + increment)?;
            let (rp, rm) = (eval(1.01)?, eval(0.99)?);
            let el = |a: f64, b: f64| (a.ln() - b.ln()) / (1.01f64.ln() - 0.99f64.ln());
            let ratios = [
                r1.eta / r0.eta,
                r1.z_at_allowable / r0.z_at_allowable,
                r1.t_ratio / r0.t_ratio,
            ];
            Ok(SensitivityRow {
                parameter: name,
                base: p0[k],
                increased: p0[k] * (1.0 + increment),
                stiffness_ratio: ratios[0],
                displacement_ratio: ratios[1],
                stress_ratio_ratio: ratios[2],
                bins: Bins {
                    stiffness: bin(ratios[0]),
                    displacement: bin(ratios[1]),
                    stress_ratio: bin(ratios[2]),
                },
                elasticity: [
                    el(rp.eta, rm.eta),
                    el(rp.z_at_allowable, rm.z_at_allowable),
                    el(rp.t_ratio, rm.t_ratio),
                ],
            })
        })
        .collect();
    Ok((r0, rows?))
}

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
    /// Parameters, mm ([`PARAMETERS`] order).
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
    /// Best design found, mm ([`PARAMETERS`] order).
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
