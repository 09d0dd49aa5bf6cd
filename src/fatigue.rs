//! Fatigue data of a material and the high-cycle fatigue relations used to assess notch
//! hinges (Budynas & Nisbett, Shigley's Mechanical Engineering Design, 10th ed. (2015), ch. 6).
//!
//! Stress-life approach: the endurance limit of the polished rotating-beam specimen S_e' is
//! reduced by Marin factors to S_e; the notch's fatigue factor K_f = 1 + q (K_t − 1) with
//! Peterson's notch sensitivity q = 1/(1 + a/r); a mean stress enters through the Goodman or
//! Soderberg line; below S_e' the life follows Basquin's S = S_e (N / N_e)^b.

use serde::{Deserialize, Serialize};

/// Fatigue data of a material (`"fatigue"` of a material object), MPa.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize, schemars::JsonSchema)]
#[serde(deny_unknown_fields)]
pub struct MaterialFatigue {
    /// Endurance limit S_e' of the unnotched, polished rotating-beam specimen, fully
    /// reversed, at `sn_cycles` cycles, MPa, > 0.
    #[schemars(extend("exclusiveMinimum" = 0))]
    pub endurance: f64,
    /// Ultimate tensile strength S_ut, MPa, > `endurance`.
    #[schemars(extend("exclusiveMinimum" = 0))]
    pub ultimate: f64,
    /// Cycles N_e at which `endurance` is stated (the knee of the S–N curve), ≥ 1e4 (default
    /// 1e6, steels).
    #[serde(default = "default_sn_cycles")]
    #[schemars(range(min = 10000))]
    pub sn_cycles: f64,
    /// Basquin exponent b of S_f = S_e (N / N_e)^b for N < N_e, in (−0.5, 0) (default: the
    /// straight line on log–log axes from 0.9 S_ut at 10³ cycles to S_e' at N_e, Shigley
    /// 10th ed. §6-7, Fig. 6-18 with f = 0.9).
    #[serde(default)]
    pub basquin_b: Option<f64>,
    /// Peterson's notch-sensitivity length a, mm, > 0 (q = 1/(1 + a/r)); default: Shigley
    /// 10th ed. eq. (6-35a) from S_ut, a relation fitted to steels.
    #[serde(default)]
    pub peterson_a_mm: Option<f64>,
}

fn default_sn_cycles() -> f64 {
    1e6
}

/// Load factor of the low-cycle anchor of the default Basquin line (Shigley Fig. 6-18).
pub const LOW_CYCLE_FRACTION: f64 = 0.9;

impl MaterialFatigue {
    /// Basquin exponent b (given, or the Shigley two-point line).
    pub fn basquin_exponent(&self) -> f64 {
        self.basquin_b.unwrap_or_else(|| {
            (self.endurance / (LOW_CYCLE_FRACTION * self.ultimate)).log10() / (self.sn_cycles / 1e3).log10()
        })
    }

    /// Peterson's length a, mm (given, or Shigley eq. (6-35a): √a = 0.246 − 3.08e-3 S_ut
    /// + 1.51e-5 S_ut² − 2.67e-8 S_ut³ with S_ut in kpsi and √a in √in).
    pub fn peterson_a(&self) -> f64 {
        self.peterson_a_mm.unwrap_or_else(|| {
            let s = self.ultimate / 6.894_757; // MPa → kpsi
            let sqrt_a = 0.246 - 3.08e-3 * s + 1.51e-5 * s * s - 2.67e-8 * s * s * s;
            sqrt_a.max(0.0).powi(2) * 25.4
        })
    }
}

/// Peterson's notch sensitivity q = 1/(1 + a/r) (r notch root radius, a Peterson's length, mm);
/// 1 for an infinite radius.
pub fn notch_sensitivity(a_mm: f64, r_mm: f64) -> f64 {
    1.0 / (1.0 + a_mm / r_mm)
}

/// Marin surface factor k_a = 4.51 S_ut^−0.265 (S_ut in MPa; machined or cold-drawn surface,
/// Shigley 10th ed. eq. (6-19), Table 6-2), at most 1.
pub fn surface_factor_machined(s_ut: f64) -> f64 {
    (4.51 * s_ut.powf(-0.265)).min(1.0)
}

/// Marin size factor in bending k_b = 1.24 d_e^−0.107 (Shigley 10th ed. eq. (6-20)) for the
/// equivalent diameter d_e, mm, clamped to the equation's range 2.79 … 51 mm.
pub fn size_factor(d_e: f64) -> f64 {
    1.24 * d_e.clamp(2.79, 51.0).powf(-0.107)
}
