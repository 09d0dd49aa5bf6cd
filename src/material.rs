//! Linear-elastic isotropic materials and the built-in library.

use crate::fatigue::MaterialFatigue;
use serde::{Deserialize, Serialize};

/// A linear-elastic isotropic material in the mm–N–MPa–tonne system.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize, schemars::JsonSchema)]
#[serde(deny_unknown_fields)]
pub struct Material {
    /// Young's modulus E, MPa (N/mm²), > 0.
    #[serde(rename = "E")]
    #[schemars(extend("exclusiveMinimum" = 0))]
    pub e: f64,
    /// Poisson's ratio ν, dimensionless, in (−1, 0.5).
    #[schemars(extend("exclusiveMinimum" = -1, "exclusiveMaximum" = 0.5))]
    pub nu: f64,
    /// Density ρ, tonne/mm³ (Al 7075: 2.81e-9), ≥ 0 (default 0: massless).
    #[serde(default)]
    #[schemars(range(min = 0))]
    pub density: f64,
    /// Tensile yield strength, MPa, > 0 (default: none, unlimited).
    #[serde(default = "default_strength", rename = "yield")]
    #[schemars(transform = no_default)]
    #[schemars(extend("exclusiveMinimum" = 0))]
    pub yield_strength: f64,
    /// Allowable (design) stress, MPa, > 0 (default: none, unlimited).
    #[serde(default = "default_strength")]
    #[schemars(transform = no_default)]
    #[schemars(extend("exclusiveMinimum" = 0))]
    pub allowable: f64,
    /// High-cycle fatigue data (`null`/absent: none; a case with a `"fatigue"` block needs it).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub fatigue: Option<MaterialFatigue>,
}

/// The default "unlimited" (infinity) has no JSON spelling: the schema states it in words.
fn no_default(schema: &mut schemars::Schema) {
    schema.remove("default");
}

fn default_strength() -> f64 {
    f64::INFINITY
}

impl Material {
    /// Aluminium 7075-T6 as used by Ruiz et al. (2019, §4–5): E = 72 GPa, ν = 0.33,
    /// ρ = 2.81 g/cm³, yield 503 MPa, allowable 400 MPa. Fatigue: S_ut 572 MPa, S_e' 159 MPa
    /// (R. R. Moore rotating beam, 5·10⁸ cycles; ASM Handbook vol. 2 / MIL-HDBK-5), Peterson's
    /// a = 0.635 mm for aluminium alloys (Peterson, Stress Concentration Factors, 1974).
    pub const AL7075: Material = Material {
        e: 72_000.0,
        nu: 0.33,
        density: 2.81e-9,
        yield_strength: 503.0,
        allowable: 400.0,
        fatigue: Some(MaterialFatigue {
            endurance: 159.0,
            ultimate: 572.0,
            sn_cycles: 5e8,
            basquin_b: None,
            peterson_a_mm: Some(0.635),
        }),
    };
    /// Nylon 66 as used for the 8R pan-tilt mechanism (8R pan-tilt paper): E = 3.3 GPa, ν = 0.33, ρ = 1.15 g/cm³.
    /// Yield 80 MPa (typical datasheet value, dry), allowable 50 MPa. No fatigue data built in.
    pub const NYLON66: Material = Material {
        e: 3_300.0,
        nu: 0.33,
        density: 1.15e-9,
        yield_strength: 80.0,
        allowable: 50.0,
        fatigue: None,
    };
    /// Generic structural steel: E = 210 GPa (Han et al.), ν = 0.3, ρ = 7.85 g/cm³, yield 355 MPa, allowable 235 MPa.
    /// Fatigue: S_ut 470 MPa (minimum of EN 10025-2 S355), S_e' = 0.5 S_ut at 10⁶ cycles
    /// (Shigley 10th ed. eq. (6-8)), Peterson's a from eq. (6-35a).
    pub const STEEL: Material = Material {
        e: 210_000.0,
        nu: 0.3,
        density: 7.85e-9,
        yield_strength: 355.0,
        allowable: 235.0,
        fatigue: Some(MaterialFatigue {
            endurance: 235.0,
            ultimate: 470.0,
            sn_cycles: 1e6,
            basquin_b: None,
            peterson_a_mm: None,
        }),
    };

    /// Names accepted for built-in materials.
    pub const BUILTIN_NAMES: [&'static str; 3] = ["Al7075", "nylon66", "steel"];

    /// Looks up a built-in material by name (case-insensitive).
    pub fn builtin(name: &str) -> Option<Material> {
        // Letter case ignored without lowering a copy (no allocation: sweeps resolve it per design).
        [
            ("al7075", Self::AL7075),
            ("nylon66", Self::NYLON66),
            ("steel", Self::STEEL),
        ]
        .into_iter()
        .find(|(n, _)| n.eq_ignore_ascii_case(name))
        .map(|(_, m)| m)
    }

    /// Shear modulus G = E / (2(1 + ν)), MPa.
    pub fn shear_modulus(&self) -> f64 {
        self.e / (2.0 * (1.0 + self.nu))
    }
}
