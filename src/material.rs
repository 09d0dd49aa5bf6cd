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
    /// Yield 80 MPa (typical datasheet value, dry), allowable 50 MPa.
    ///
    /// Fatigue (unnotched specimens; a polymer has no true endurance limit, so the "endurance"
    /// is the strength at the stated 10⁷ cycles, and the Basquin line is not continued beyond):
    /// S_e' = 5200 psi = 35.85 MPa at 10⁷ cycles, nylon 6/6 unreinforced, ASTM D671 flexural
    /// fatigue (constant force amplitude) at 1800 cycles/min, room temperature (Plasco Inc.,
    /// "Fatigue endurance of reinforced thermoplastics", design archive table: 6500, 5900,
    /// 5300, 5200 psi at 10⁴, 10⁵, 10⁶, 10⁷ cycles); b = log₁₀(5200/6500)/3 = −0.0323, the
    /// line through the 10⁴ and 10⁷ points. Dry as moulded: Toray Amilan technical data
    /// (nylon 66 tension–compression fatigue, 30 Hz, Table 9) gives 35 MPa at 0 % water and
    /// 21 MPa at 2.5 % (conditioned): conditioned parts need a material object. S_ut 85 MPa:
    /// the dry ISO 527 yield stress of DuPont Zytel 103HSL NC010 (PA66) datasheet, the largest
    /// engineering stress of the tensile test of unreinforced PA66. Peterson's a: no published
    /// value for nylon; the default (Shigley eq. (6-35a), a fit to steels) is extrapolated.
    pub const NYLON66: Material = Material {
        e: 3_300.0,
        nu: 0.33,
        density: 1.15e-9,
        yield_strength: 80.0,
        allowable: 50.0,
        fatigue: Some(MaterialFatigue {
            endurance: 35.85,
            ultimate: 85.0,
            sn_cycles: 1e7,
            basquin_b: Some(-0.0323),
            peterson_a_mm: None,
        }),
    };
    /// Titanium Ti-6Al-4V, ASTM grade 5, annealed (ASM Aerospace Specification Metals / MatWeb,
    /// "Titanium Ti-6Al-4V (Grade 5), Annealed", ASM Material Data Sheet): E = 113.8 GPa,
    /// ν = 0.342, ρ = 4.43 g/cm³, yield 880 MPa, S_ut 950 MPa; allowable 700 MPa (0.8 × yield
    /// rounded down to 10 MPa, the rule that gives Al 7075-T6's 400 MPa from 503). Fatigue: S_e' = 510 MPa, unnotched, 10⁷ cycles (same
    /// sheet); Basquin b and Peterson's a not published there: the defaults (Shigley 10th ed.
    /// §6-7 line from 0.9 S_ut at 10³ cycles; eq. (6-35a), a fit to steels, S_ut within its
    /// range).
    pub const TI6AL4V: Material = Material {
        e: 113_800.0,
        nu: 0.342,
        density: 4.43e-9,
        yield_strength: 880.0,
        allowable: 700.0,
        fatigue: Some(MaterialFatigue {
            endurance: 510.0,
            ultimate: 950.0,
            sn_cycles: 1e7,
            basquin_b: None,
            peterson_a_mm: None,
        }),
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
    pub const BUILTIN_NAMES: [&'static str; 4] = ["Al7075", "nylon66", "steel", "Ti6Al4V"];

    /// Looks up a built-in material by name (case-insensitive).
    pub fn builtin(name: &str) -> Option<Material> {
        // Letter case ignored without lowering a copy (no allocation: sweeps resolve it per design).
        [
            ("al7075", Self::AL7075),
            ("nylon66", Self::NYLON66),
            ("steel", Self::STEEL),
            ("ti6al4v", Self::TI6AL4V),
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
