//! Design problems of any mechanism: parameters → named responses, with one Table-1
//! sensitivity and one requirement-driven optimiser for all of them.
//!
//! A [`Problem`] names its parameters and responses and evaluates the responses of one set of
//! parameter values; everything else — each parameter increased in turn ([`sensitivity`]),
//! requirements and an objective over a box of bounds ([`optimise`]), the Jacobian at a design
//! ([`jacobian`]) — is written once here. The 3-PRS stage (five hinge dimensions, responses η,
//! d, T) and any static mesh case with parameters and metrics implement it.
//!
//! Evaluations run in parallel on rayon: each rayon worker owns a [`Problem::Worker`] (a solver
//! cache, so designs of one topology are refactorised numerically only), passed explicitly.

mod optimise;
mod sensitivity;

pub use optimise::{constraints, optimise, Constraint, HistoryEntry, Objective, Outcome, Requirement, Sense};
pub use sensitivity::{bin, sensitivity, Row};

use rayon::prelude::*;
use serde::Serialize;

/// d response / d parameter: `jacobian[i][k]` is the derivative of response `i` with respect
/// to parameter `k`, in the response's unit per parameter unit.
pub type Jacobian = Vec<Vec<f64>>;

/// A design problem: named parameters in, named responses out.
pub trait Problem: Sync {
    /// Per-worker state (solver caches); one per rayon worker.
    type Worker: Send;

    /// Parameter names, in the order of every parameter vector.
    fn parameters(&self) -> &[String];
    /// Response names, in the order [`Self::evaluate`] returns them.
    fn responses(&self) -> &[String];
    /// A fresh worker.
    fn worker(&self) -> Self::Worker;
    /// The responses at parameter values `p` (one per name of [`Self::responses`]); a design
    /// that cannot be built or solved, or whose responses are not finite, is an `Err` naming why.
    fn evaluate(&self, w: &mut Self::Worker, p: &[f64]) -> Result<Vec<f64>, String>;
    /// The Jacobian of the responses at `p` if the problem can compute it itself (adjoint or
    /// analytic derivatives plug in here); `None` (the default) lets the callers use central
    /// differences of [`Self::evaluate`].
    fn gradient(&self, _w: &mut Self::Worker, _p: &[f64]) -> Option<Result<Jacobian, String>> {
        None
    }
}

/// How a Jacobian was obtained.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize)]
#[serde(rename_all = "snake_case")]
pub enum GradientMethod {
    /// Central differences of the responses, one-sided at a bound (see [`jacobian`]).
    CentralDifferences,
    /// The problem's own [`Problem::gradient`]: for a mesh mechanism, the direct method through
    /// the element matrices ([`crate::gradient::Linear`]); serialised `"direct"`.
    #[serde(rename = "direct")]
    Problem,
}

/// Relative step of the finite-difference Jacobian: a fraction of each parameter's bound width.
pub const JACOBIAN_STEP: f64 = 1e-3;

/// The Jacobian of `problem` at `p` within `bounds`: the problem's own
/// ([`Problem::gradient`]) if it has one, else central differences with the step
/// h_k = [`JACOBIAN_STEP`]·(hi_k − lo_k), each side clamped to the bounds (one-sided at a bound).
pub fn jacobian<P: Problem>(problem: &P, p: &[f64], bounds: &[[f64; 2]]) -> Result<(Jacobian, GradientMethod), String> {
    if let Some(j) = problem.gradient(&mut problem.worker(), p) {
        return j.map(|j| (j, GradientMethod::Problem));
    }
    let columns: Result<Vec<Vec<f64>>, String> = (0..p.len())
        .into_par_iter()
        .map_init(
            || problem.worker(),
            |w, k| {
                let h = JACOBIAN_STEP * (bounds[k][1] - bounds[k][0]);
                let (mut up, mut um) = (p.to_vec(), p.to_vec());
                up[k] = (p[k] + h).min(bounds[k][1]);
                um[k] = (p[k] - h).max(bounds[k][0]);
                let name = &problem.parameters()[k];
                let rp = problem
                    .evaluate(w, &up)
                    .map_err(|e| format!("{name} = {}: {e}", up[k]))?;
                let rm = problem
                    .evaluate(w, &um)
                    .map_err(|e| format!("{name} = {}: {e}", um[k]))?;
                let dp = up[k] - um[k];
                Ok(rp.iter().zip(&rm).map(|(a, b)| (a - b) / dp).collect())
            },
        )
        .collect();
    let columns = columns?;
    let n = problem.responses().len();
    Ok((
        (0..n).map(|i| columns.iter().map(|c| c[i]).collect()).collect(),
        GradientMethod::CentralDifferences,
    ))
}
