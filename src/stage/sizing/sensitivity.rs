//! Table 1 of Ruiz et al. (2019): each design parameter increased in turn, the ratios of the
//! responses binned as in the paper, and local elasticities — the generic
//! [`crate::problem::sensitivity`] on the [`StageProblem`], reported for η, d and T (and the
//! fatigue-limited Δz d_f with a [`FatigueLimit`]).

use super::{params_of, FatigueLimit, Responses, RotationDemand, StageProblem, PARAMETERS};
use crate::problem;
use crate::stage::StageDesign;
use serde::Serialize;

pub use crate::problem::bin;

/// Table-1 bins of the three ratios.
#[derive(Debug, Clone, Serialize)]
pub struct Bins {
    /// η_{i+1}/η_i bin.
    pub stiffness: &'static str,
    /// d_{i+1}/d_i bin.
    pub displacement: &'static str,
    /// T_{i+1}/T_i bin.
    pub stress_ratio: &'static str,
    /// d_f,{i+1}/d_f,i bin (with a `fatigue` block).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub fatigue_displacement: Option<&'static str>,
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
    /// d_f,{i+1}/d_f,i: the fatigue-limited Δz (with a `fatigue` block).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub fatigue_displacement_ratio: Option<f64>,
    /// ∂ln d_f/∂ln p at the base design (with a `fatigue` block).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub fatigue_elasticity: Option<f64>,
}

/// Table 1: each parameter increased by `increment` (relative) from the base design; the d_f
/// column too when `fatigue` is given.
pub fn sensitivity(
    base: &StageDesign,
    increment: f64,
    demand: &RotationDemand,
    fatigue: Option<&dyn FatigueLimit>,
) -> Result<(Responses, Vec<SensitivityRow>), String> {
    let p0 = params_of(base)?;
    let problem = StageProblem::new(base, *demand).with_fatigue(fatigue);
    let (r0, rows) = problem::sensitivity(&problem, &p0, increment)?;
    // Responses 0, 1, 2 are η, d, T (`super::RESPONSES`), 7 is d_f.
    let rows = rows
        .into_iter()
        .zip(PARAMETERS)
        .map(|(row, name)| SensitivityRow {
            parameter: name,
            base: row.base,
            increased: row.increased,
            stiffness_ratio: row.ratios[0],
            displacement_ratio: row.ratios[1],
            stress_ratio_ratio: row.ratios[2],
            bins: Bins {
                stiffness: row.bins[0],
                displacement: row.bins[1],
                stress_ratio: row.bins[2],
                fatigue_displacement: row.bins.get(7).copied(),
            },
            elasticity: [row.elasticity[0], row.elasticity[1], row.elasticity[2]],
            fatigue_displacement_ratio: row.ratios.get(7).copied(),
            fatigue_elasticity: row.elasticity.get(7).copied(),
        })
        .collect();
    Ok((Responses::from_slice(&r0), rows))
}
