//! `"fatigue"`: a high-cycle fatigue assessment of a cyclic stroke about the compliant axis.

use super::error::{check, CaseError};
use crate::fatigue::MaterialFatigue;
use crate::material::Material;
use serde::Deserialize;

/// How the mean stress enters (Shigley's Mechanical Engineering Design, 10th ed., §6-12).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default, Deserialize, schemars::JsonSchema)]
#[serde(rename_all = "snake_case")]
pub enum MeanStressMethod {
    /// Modified Goodman: σ_a/S_f + σ_m/S_ut = 1.
    #[default]
    Goodman,
    /// Soderberg: σ_a/S_f + σ_m/S_y = 1 (more conservative).
    Soderberg,
}

/// `"fatigue"` of a case: the cyclic rotation to assess.
#[derive(Debug, Clone, Copy, PartialEq, Deserialize, schemars::JsonSchema)]
#[serde(deny_unknown_fields)]
pub struct FatigueSpec {
    /// Required life, cycles, ≥ 1.
    #[schemars(range(min = 1))]
    pub cycles: f64,
    /// Alternating rotation (amplitude, half of peak-to-peak) about the compliant axis, degrees, ≥ 0.
    #[schemars(range(min = 0))]
    pub stroke: f64,
    /// Mean rotation about the compliant axis, degrees (default 0: fully reversed); its sign
    /// does not matter (one notch face is always in tension).
    #[serde(default)]
    pub mean: f64,
    /// Mean-stress criterion (default `"goodman"`).
    #[serde(default)]
    pub method: MeanStressMethod,
}

impl FatigueSpec {
    /// Checks the block and the material's fatigue data (`material_path`: the material's JSON
    /// path); returns the fatigue data.
    pub fn validate(&self, material_path: &str, m: &Material) -> Result<MaterialFatigue, CaseError> {
        check::within("fatigue.cycles", self.cycles, 1.0, 1e15, "cycles")?;
        check::non_negative("fatigue.stroke", self.stroke, "degrees")?;
        check::finite("fatigue.mean", self.mean)?;
        let f = m.fatigue.ok_or_else(|| {
            CaseError::value(
                format!("{material_path}.fatigue"),
                "none",
                "a \"fatigue\" block needs material fatigue data {\"endurance\", \"ultimate\"} (MPa); built-in materials with fatigue data: Al7075, steel",
            )
        })?;
        validate_material_fatigue(material_path, &f)?;
        if self.method == MeanStressMethod::Soderberg && !m.yield_strength.is_finite() {
            return Err(CaseError::value(
                format!("{material_path}.yield"),
                "none",
                "\"method\": \"soderberg\" needs a yield strength (MPa)",
            ));
        }
        Ok(f)
    }
}

/// Checks fatigue data under `{material_path}.fatigue`.
pub fn validate_material_fatigue(material_path: &str, f: &MaterialFatigue) -> Result<(), CaseError> {
    let p = format!("{material_path}.fatigue");
    check::positive(format_args!("{p}.endurance"), f.endurance, "MPa")?;
    check::positive(format_args!("{p}.ultimate"), f.ultimate, "MPa")?;
    if f.endurance >= f.ultimate {
        return Err(CaseError::value(
            format!("{p}.endurance"),
            f.endurance,
            format!("must be below the ultimate strength {} MPa", f.ultimate),
        ));
    }
    check::within(format_args!("{p}.sn_cycles"), f.sn_cycles, 1e4, 1e12, "cycles")?;
    if let Some(b) = f.basquin_b {
        if !(b > -0.5 && b < 0.0) {
            return Err(CaseError::value(format!("{p}.basquin_b"), b, "must lie in (−0.5, 0)"));
        }
    }
    if let Some(a) = f.peterson_a_mm {
        check::positive(format_args!("{p}.peterson_a_mm"), a, "mm")?;
    }
    Ok(())
}
