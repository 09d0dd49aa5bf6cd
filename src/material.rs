//! Linear-elastic isotropic materials and the built-in library.

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
    /// ρ = 2.81 g/cm³, yield 503 MPa, allowable 400 MPa.
    pub const AL7075: Material = Material {
        e: 72_000.0,
        nu: 0.33,
        density: 2.81e-9,
        yield_strength: 503.0,
        allowable: 400.0,
    };
    /// Nylon 66 as used for the 8R pan-tilt mechanism (8R pan-tilt paper): E = 3.3 GPa, ν = 0.33, ρ = 1.15 g/cm³.
    /// Yield 80 MPa (typical datasheet value, dry), allowable 50 MPa.
    pub const NYLON66: Material = Material {
        e: 3_300.0,
        nu: 0.33,
        density: 1.15e-9,
        yield_strength: 80.0,
        allowable: 50.0,
    };
    /// Generic structural steel: E = 210 GPa (Han et al.), ν = 0.3, ρ = 7.85 g/cm³, yield 355 MPa, allowable 235 MPa.
    pub const STEEL: Material = Material {
        e: 210_000.0,
        nu: 0.3,
        density: 7.85e-9,
        yield_strength: 355.0,
        allowable: 235.0,
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
