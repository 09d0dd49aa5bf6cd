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
        material_fatigue(material_path, m, self.method)
    }
}

/// `"fatigue"` of a `stage` or `static` case: every load case is the peak of a load cycle of
/// stress ratio `load_ratio`, repeated `cycles` times (stress proportional to the load: linear
/// runs; nonlinear runs assess each solved peak as it stands).
#[derive(Debug, Clone, Copy, PartialEq, Deserialize, schemars::JsonSchema)]
#[serde(deny_unknown_fields)]
pub struct CyclicSpec {
    /// Required life, cycles, ≥ 1.
    #[schemars(range(min = 1))]
    pub cycles: f64,
    /// Stress ratio R = minimum / maximum load of the cycle, −1 ≤ R < 1 (default −1: fully
    /// reversed; 0: from zero to the load case). Alternating = (1 − R)/2 × peak, mean =
    /// (1 + R)/2 × peak.
    #[serde(default = "fully_reversed")]
    #[schemars(extend("minimum" = -1, "exclusiveMaximum" = 1))]
    pub load_ratio: f64,
    /// Mean-stress criterion (default `"goodman"`).
    #[serde(default)]
    pub method: MeanStressMethod,
}

fn fully_reversed() -> f64 {
    -1.0
}

impl CyclicSpec {
    /// Checks the block (`path`: its JSON path) and the fatigue data of material `m` (at
    /// `material_path`); returns the fatigue data.
    pub fn validate(&self, path: &str, material_path: &str, m: &Material) -> Result<MaterialFatigue, CaseError> {
        self.check(path)?;
        material_fatigue(material_path, m, self.method)
    }

    /// Checks the block's own fields (`path`: its JSON path).
    pub fn check(&self, path: &str) -> Result<(), CaseError> {
        check::within(format_args!("{path}.cycles"), self.cycles, 1.0, 1e15, "cycles")?;
        if !(self.load_ratio >= -1.0 && self.load_ratio < 1.0) {
            return Err(CaseError::value(
                format!("{path}.load_ratio"),
                self.load_ratio,
                "must lie in [−1, 1) (minimum / maximum load of the cycle)",
            ));
        }
        Ok(())
    }

    /// Checks that a `static` model has hinge elements and that each one's material has
    /// fatigue data (paths `elements[i].material`).
    pub fn check_hinges(&self, hinges: &[super::mesh::BuiltHinge]) -> Result<(), CaseError> {
        if hinges.is_empty() {
            return Err(CaseError::new(
                "fatigue",
                "the model has no `hinge` element to assess (fatigue is assessed on hinge elements)",
            ));
        }
        for h in hinges {
            material_fatigue(
                &format!("elements[{}].material", h.case_element),
                &h.material,
                self.method,
            )?;
        }
        Ok(())
    }

    /// (alternating, mean) share of the peak load: ((1 − R)/2, (1 + R)/2).
    pub fn shares(&self) -> (f64, f64) {
        (0.5 * (1.0 - self.load_ratio), 0.5 * (1.0 + self.load_ratio))
    }
}

/// The fatigue data of material `m` (at `material_path`), checked, for `method`.
pub fn material_fatigue(
    material_path: &str,
    m: &Material,
    method: MeanStressMethod,
) -> Result<MaterialFatigue, CaseError> {
    let f = m.fatigue.ok_or_else(|| {
        CaseError::value(
            format!("{material_path}.fatigue"),
            "none",
            "a \"fatigue\" block needs material fatigue data {\"endurance\", \"ultimate\"} (MPa); built-in materials with fatigue data: Al7075, nylon66, steel, Ti6Al4V",
        )
    })?;
    validate_material_fatigue(material_path, &f)?;
    if method == MeanStressMethod::Soderberg && !m.yield_strength.is_finite() {
        return Err(CaseError::value(
            format!("{material_path}.yield"),
            "none",
            "\"method\": \"soderberg\" needs a yield strength (MPa)",
        ));
    }
    Ok(f)
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
