//! Materials shared by the tests that are not among the library's named ones.
#![allow(dead_code)]

use flexfem::material::Material;

/// Structural steel for the closed-form vibration checks: E = 210 GPa, ν = 0.3,
/// ρ = 7850 kg/m³ (7.85e-9 tonne/mm³), no stress limit.
pub const STEEL: Material = Material {
    e: 210_000.0,
    nu: 0.3,
    density: 7.85e-9,
    yield_strength: f64::INFINITY,
    allowable: f64::INFINITY,
    fatigue: None,
};
