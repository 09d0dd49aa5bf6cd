//! Requirement-driven design of any [`Problem`]: requirements on responses, an objective, a box
//! of bounds; quasi-random sampling then a bounded local search (the sizing loop of Ruiz et al.
//! (2019) §4–5, Fig. 11, generalised).

use super::{Jacobian, Problem};
use rayon::prelude::*;
use serde::Serialize;

/// `≥` or `≤`.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Sense {
    /// The response must be at least the limit.
    AtLeast,
    /// The response must be at most the limit.
    AtMost,
}

/// A requirement: response `response` (index) must meet `limit` in `sense`.
#[derive(Debug, Clone, PartialEq)]
pub struct Requirement {
    /// Name reported in constraints and `binding`.
    pub name: String,
    /// Index of the response.
    pub response: usize,
    /// `≥` or `≤`.
    pub sense: Sense,
    /// The limit, in the response's unit.
    pub limit: f64,
}

impl Requirement {
    /// Normalised violation of `value`: (limit − value)/|limit| for `≥`, (value − limit)/|limit|
    /// for `≤` (|limit| at least 10⁻¹²); ≤ 0 when met.
    pub fn violation(&self, value: f64) -> f64 {
        match self.sense {
            Sense::AtLeast => (self.limit - value) / self.limit.abs().max(1e-12),
            Sense::AtMost => (value - self.limit) / self.limit.abs().max(1e-12),
        }
    }

    /// d violation / d value.
    fn slope(&self) -> f64 {
        let s = 1.0 / self.limit.abs().max(1e-12);
        match self.sense {
            Sense::AtLeast => -s,
            Sense::AtMost => s,
        }
    }
}

/// What the optimiser improves among designs that meet the requirements.
#[derive(Debug, Clone, PartialEq)]
pub enum Objective {
    /// Maximise a response (index): the local search minimises −ln r, so the response must be
    /// positive (a design where it is not counts as failed).
    Maximise(usize),
    /// Minimise a positive response (index): the local search minimises ln r.
    Minimise(usize),
    /// Least squares: minimise J = Σ w_i (r_i − t_i)² / Σ w_i t_i² over the responses
    /// `responses` (indices) with targets `targets` and weights `weights` (≥ 0, not all zero
    /// where the targets are): the weighted squared error relative to the weighted target.
    LeastSquares {
        /// Indices of the responses.
        responses: Vec<usize>,
        /// Target of each.
        targets: Vec<f64>,
        /// Weight of each.
        weights: Vec<f64>,
    },
}

impl Objective {
    /// The term the local search minimises (`None`: not defined at `r`).
    fn merit(&self, r: &[f64]) -> Option<f64> {
        let m = match self {
            Objective::Maximise(i) => -r[*i].ln(),
            Objective::Minimise(i) => r[*i].ln(),
            Objective::LeastSquares { .. } => self.least_squares(r),
        };
        m.is_finite().then_some(m)
    }

    /// Lower is better among feasible designs.
    fn score(&self, r: &[f64]) -> f64 {
        match self {
            Objective::Maximise(i) => -r[*i],
            Objective::Minimise(i) => r[*i],
            Objective::LeastSquares { .. } => self.least_squares(r),
        }
    }

    fn least_squares(&self, r: &[f64]) -> f64 {
        let Objective::LeastSquares {
            responses,
            targets,
            weights,
        } = self
        else {
            return f64::NAN;
        };
        let (mut num, mut den) = (0.0, 0.0);
        for (k, &i) in responses.iter().enumerate() {
            num += weights[k] * (r[i] - targets[k]).powi(2);
            den += weights[k] * targets[k] * targets[k];
        }
        num / den
    }

    /// d merit / d r_i added into `g`.
    fn add_slope(&self, r: &[f64], g: &mut [f64]) {
        match self {
            Objective::Maximise(i) => g[*i] -= 1.0 / r[*i],
            Objective::Minimise(i) => g[*i] += 1.0 / r[*i],
            Objective::LeastSquares {
                responses,
                targets,
                weights,
            } => {
                let den: f64 = weights.iter().zip(targets).map(|(w, t)| w * t * t).sum();
                for (k, &i) in responses.iter().enumerate() {
                    g[i] += 2.0 * weights[k] * (r[i] - targets[k]) / den;
                }
            }
        }
    }
}

/// One requirement at a design.
#[derive(Debug, Clone, Serialize)]
pub struct Constraint {
    /// Name.
    pub name: String,
    /// Value at the design.
    pub value: f64,
    /// Limit.
    pub limit: f64,
    /// `">="` or `"<="`.
    pub sense: &'static str,
    /// Normalised violation (≤ 0 when met).
    pub violation: f64,
}

/// The constraints of responses `r`.
pub fn constraints(r: &[f64], reqs: &[Requirement]) -> Vec<Constraint> {
    reqs.iter()
        .map(|q| Constraint {
            name: q.name.clone(),
            value: r[q.response],
            limit: q.limit,
            sense: match q.sense {
                Sense::AtLeast => ">=",
                Sense::AtMost => "<=",
            },
            violation: q.violation(r[q.response]),
        })
        .collect()
}

/// A point visited by the optimiser.
#[derive(Debug, Clone, Serialize)]
pub struct HistoryEntry {
    /// `"sample"` or `"local"`.
    pub phase: &'static str,
    /// Parameter values.
    pub params: Vec<f64>,
    /// Responses (empty if the design failed).
    pub responses: Vec<f64>,
    /// Largest normalised requirement violation (≤ 0: feasible; 10⁹ if the design failed).
    pub max_violation: f64,
}

/// Outcome of [`optimise`].
#[derive(Debug, Clone, Serialize)]
pub struct Outcome {
    /// Best design found.
    pub params: Vec<f64>,
    /// Whether it meets every requirement.
    pub meets: bool,
    /// Its responses.
    pub responses: Vec<f64>,
    /// Its requirements.
    pub constraints: Vec<Constraint>,
    /// Names of active (within 1 %) or violated requirements.
    pub binding: Vec<String>,
    /// Designs evaluated.
    pub evaluations: usize,
    /// Samples and local iterations.
    pub history: Vec<HistoryEntry>,
    /// The problem's own Jacobian ([`Problem::gradient`]) at the best design, when the local
    /// search computed it there (not serialised).
    #[serde(skip)]
    pub jacobian: Option<Jacobian>,
}

#[derive(Clone)]
struct Eval {
    p: Vec<f64>,
    r: Option<Vec<f64>>,
    viol: f64,
    score: f64,
}

struct Setup<'a, P> {
    problem: &'a P,
    reqs: &'a [Requirement],
    objective: &'a Objective,
}

impl<P: Problem> Setup<'_, P> {
    fn eval(&self, w: &mut P::Worker, p: &[f64]) -> Eval {
        match self.problem.evaluate(w, p) {
            Ok(r) if r.iter().all(|x| x.is_finite()) && self.objective.merit(&r).is_some() => {
                let viol = self
                    .reqs
                    .iter()
                    .map(|q| q.violation(r[q.response]))
                    .fold(f64::NEG_INFINITY, f64::max);
                Eval {
                    p: p.to_vec(),
                    score: self.objective.score(&r),
                    r: Some(r),
                    viol,
                }
            }
            _ => Eval {
                p: p.to_vec(),
                r: None,
                viol: f64::INFINITY,
                score: f64::INFINITY,
            },
        }
    }

    /// Objective term + μ·Σ max(0, g)².
    fn merit(&self, e: &Eval, mu: f64) -> f64 {
        match &e.r {
            None => f64::INFINITY,
            Some(r) => {
                let pen: f64 = self
                    .reqs
                    .iter()
                    .map(|q| q.violation(r[q.response]).max(0.0).powi(2))
                    .sum();
                self.objective.merit(r).unwrap_or(f64::INFINITY) + mu * pen
            }
        }
    }

    /// d merit / d u (normalised coordinates) from the Jacobian `j` at responses `r`.
    fn merit_gradient(&self, r: &[f64], j: &Jacobian, mu: f64, bounds: &[[f64; 2]]) -> Vec<f64> {
        let mut g = vec![0.0; r.len()];
        self.objective.add_slope(r, &mut g);
        for q in self.reqs {
            let v = q.violation(r[q.response]);
            if v > 0.0 {
                g[q.response] += mu * 2.0 * v * q.slope();
            }
        }
        (0..bounds.len())
            .map(|k| (0..r.len()).map(|i| g[i] * j[i][k]).sum::<f64>() * (bounds[k][1] - bounds[k][0]))
            .collect()
    }
}

fn better(a: &Eval, b: &Eval) -> bool {
    // Feasible beats infeasible; among feasible, the better objective; among infeasible, less violated.
    match (a.viol <= 0.0, b.viol <= 0.0) {
        (true, false) => true,
        (false, true) => false,
        (true, true) => a.score < b.score,
        (false, false) => a.viol < b.viol,
    }
}

/// Element `i` of the van der Corput sequence in base `base` (Halton coordinate), in [0, 1).
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

/// The first `n` primes (the Halton bases).
fn primes(n: usize) -> Vec<usize> {
    let mut out: Vec<usize> = Vec::with_capacity(n);
    let mut c = 2;
    while out.len() < n {
        if out.iter().all(|p| c % p != 0) {
            out.push(c);
        }
        c += 1;
    }
    out
}

/// Requirement-driven design: the best design for `objective` subject to `reqs` within `bounds`.
///
/// Method: `samples` quasi-random (Halton) designs over the box, then a bounded local search
/// from the best one — projected gradient descent on objective + μ·Σ max(0, g)² (g: normalised
/// violations, [`Requirement::violation`]) in coordinates normalised to the box, gradients from
/// [`Problem::gradient`] or else central finite differences (step 10⁻³ of the box), backtracking
/// line search, μ raised from 10 to 10⁴ — keeping the best design seen (feasible beats
/// infeasible; then the objective; then the violation).
pub fn optimise<P: Problem>(
    problem: &P,
    bounds: &[[f64; 2]],
    reqs: &[Requirement],
    objective: &Objective,
    samples: usize,
) -> Result<Outcome, String> {
    let n = bounds.len();
    let s = Setup {
        problem,
        reqs,
        objective,
    };
    let to_p = |u: &[f64]| -> Vec<f64> {
        (0..n)
            .map(|k| bounds[k][0] + u[k] * (bounds[k][1] - bounds[k][0]))
            .collect()
    };
    let bases = primes(n);
    let pts: Vec<Vec<f64>> = (0..samples.max(1))
        .map(|i| bases.iter().map(|&b| halton(i, b)).collect())
        .collect();
    let evals: Vec<Eval> = pts
        .par_iter()
        .map_init(|| problem.worker(), |w, u| s.eval(w, &to_p(u)))
        .collect();
    let mut history: Vec<HistoryEntry> = evals.iter().map(|e| entry("sample", e)).collect();
    let mut evaluations = evals.len();
    let mut best_i = 0;
    for (i, e) in evals.iter().enumerate() {
        if better(e, &evals[best_i]) {
            best_i = i;
        }
    }
    let mut u = pts[best_i].clone();
    let mut w = problem.worker();
    // The design at `u`, kept from its evaluation (each design is evaluated once).
    let mut cur = s.eval(&mut w, &to_p(&u));
    evaluations += 1;
    let mut best = cur.clone();
    let h = 1e-3;
    // The problem's own Jacobian at the last design it was computed at.
    let mut known: Option<(Vec<f64>, Jacobian)> = None;
    for mu in [10.0, 100.0, 1e3, 1e4] {
        let mut step = 0.1;
        for _ in 0..15 {
            let f0 = s.merit(&cur, mu);
            if !f0.is_finite() {
                break;
            }
            // The Jacobian does not depend on μ: one per design, reused when a stage ends
            // where the next starts.
            if cur.r.is_some() && known.as_ref().is_none_or(|(p, _)| *p != cur.p) {
                known = match problem.gradient(&mut w, &cur.p) {
                    Some(Ok(j)) => Some((cur.p.clone(), j)),
                    _ => None,
                };
            }
            let own = match (&cur.r, &known) {
                (Some(r), Some((p, j))) if *p == cur.p => Some(s.merit_gradient(r, j, mu, bounds)),
                _ => None,
            };
            let grads: Vec<f64> = match own {
                Some(g) => g,
                None => {
                    evaluations += 2 * n;
                    (0..n)
                        .into_par_iter()
                        .map_init(
                            || problem.worker(),
                            |w, k| {
                                let mut up = u.clone();
                                let mut um = u.clone();
                                up[k] = (up[k] + h).min(1.0);
                                um[k] = (um[k] - h).max(0.0);
                                let fp = s.merit(&s.eval(w, &to_p(&up)), mu);
                                let fm = s.merit(&s.eval(w, &to_p(&um)), mu);
                                if fp.is_finite() && fm.is_finite() && up[k] > um[k] {
                                    (fp - fm) / (up[k] - um[k])
                                } else {
                                    0.0
                                }
                            },
                        )
                        .collect()
                }
            };
            let gn = grads.iter().map(|g| g * g).sum::<f64>().sqrt();
            if gn < 1e-9 {
                break;
            }
            let mut moved = false;
            while step > 1e-4 {
                let trial: Vec<f64> = (0..n).map(|k| (u[k] - step * grads[k] / gn).clamp(0.0, 1.0)).collect();
                let e = s.eval(&mut w, &to_p(&trial));
                evaluations += 1;
                if s.merit(&e, mu) < f0 {
                    u = trial;
                    history.push(entry("local", &e));
                    if better(&e, &best) {
                        best = e.clone();
                    }
                    cur = e;
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
    let cons = constraints(&r, reqs);
    let binding = cons
        .iter()
        .filter(|c| c.violation > -0.01)
        .map(|c| c.name.clone())
        .collect();
    let jacobian = known.filter(|(p, _)| *p == best.p).map(|(_, j)| j);
    Ok(Outcome {
        jacobian,
        params: best.p,
        meets: best.viol <= 0.0,
        responses: r,
        constraints: cons,
        binding,
        evaluations,
        history,
    })
}

fn entry(phase: &'static str, e: &Eval) -> HistoryEntry {
    HistoryEntry {
        phase,
        params: e.p.clone(),
        responses: e.r.clone().unwrap_or_default(),
        max_violation: if e.viol.is_finite() { e.viol } else { 1e9 },
    }
}
