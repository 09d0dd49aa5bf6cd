//! Table-1 sensitivity of any design problem (the layout of Table 1 of Ruiz et al. (2019),
//! "Kinematic design and experimental validation of a 3-PRS compliant parallel stage"): each
//! parameter increased in turn by a relative increment, the ratio of every response binned as
//! in the paper, and local elasticities.

use super::Problem;
use rayon::prelude::*;
use serde::Serialize;

/// Table 1 bin of a ratio.
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

/// One parameter's row.
#[derive(Debug, Clone, Serialize)]
pub struct Row {
    /// Parameter name.
    pub parameter: String,
    /// Base value (the parameter's unit).
    pub base: f64,
    /// Increased value, base × (1 + increment).
    pub increased: f64,
    /// Each response at the increased value over its base value, in response order.
    pub ratios: Vec<f64>,
    /// [`bin`] of each ratio.
    pub bins: Vec<&'static str>,
    /// Local elasticities ∂ln|r|/∂ln p at the base design, central differences at ±1 %.
    pub elasticity: Vec<f64>,
}

/// Each parameter of `problem` increased by `increment` (relative) from `base`: the base
/// responses and one [`Row`] per parameter. Rows are computed in parallel, one worker each.
pub fn sensitivity<P: Problem>(problem: &P, base: &[f64], increment: f64) -> Result<(Vec<f64>, Vec<Row>), String> {
    let r0 = problem
        .evaluate(&mut problem.worker(), base)
        .map_err(|e| format!("base design: {e}"))?;
    let rows: Result<Vec<Row>, String> = (0..base.len())
        .into_par_iter()
        .map_init(
            || problem.worker(),
            |w, k| {
                let name = &problem.parameters()[k];
                let mut eval = |f: f64| {
                    let mut p = base.to_vec();
                    p[k] *= f;
                    problem.evaluate(w, &p).map_err(|e| format!("{name} × {f}: {e}"))
                };
                let r1 = eval(1.0 + increment)?;
                let (rp, rm) = (eval(1.01)?, eval(0.99)?);
                // |r|: a response of either sign (ln of a positive one is unchanged).
                let el = |a: f64, b: f64| (a.abs().ln() - b.abs().ln()) / (1.01f64.ln() - 0.99f64.ln());
                let ratios: Vec<f64> = r1.iter().zip(&r0).map(|(a, b)| a / b).collect();
                Ok(Row {
                    parameter: name.clone(),
                    base: base[k],
                    increased: base[k] * (1.0 + increment),
                    bins: ratios.iter().map(|&r| bin(r)).collect(),
                    ratios,
                    elasticity: rp.iter().zip(&rm).map(|(&a, &b)| el(a, b)).collect(),
                })
            },
        )
        .collect();
    Ok((r0, rows?))
}
