//! Table 1 of Ruiz et al. (2019): each design parameter increased in turn, the ratios of the
//! responses binned as in the paper, and local elasticities.

use super::{evaluate, evaluate_with, params_of, with_params, Responses, RotationDemand, PARAMETERS};
use crate::fem::SolverCache;
use crate::stage::StageDesign;
use rayon::prelude::*;
use serde::Serialize;

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
