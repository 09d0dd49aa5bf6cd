//! Shared pieces of the geometrically nonlinear tests: an elastic material without a stress
//! limit, solver options by step count, and a deterministic random source.
#![allow(dead_code)]

use flexfem::fem::NonlinearOptions;
use flexfem::material::Material;

/// Linear-elastic material (E, ν in MPa) without mass and with stress limits far out of reach.
pub fn mat(e: f64, nu: f64) -> Material {
    Material {
        e,
        nu,
        density: 0.0,
        yield_strength: 1e9,
        allowable: 1e9,
        fatigue: None,
    }
}

/// Default nonlinear options with `steps` load steps.
pub fn opts(steps: usize) -> NonlinearOptions {
    NonlinearOptions {
        steps,
        ..Default::default()
    }
}

/// Deterministic 64-bit LCG (Knuth's MMIX constants), uniform in [0, 1).
pub struct Lcg(pub u64);

impl Lcg {
    pub fn next(&mut self) -> f64 {
        self.0 = self
            .0
            .wrapping_mul(6364136223846793005)
            .wrapping_add(1442695040888963407);
        (self.0 >> 11) as f64 / (1u64 << 53) as f64
    }

    /// Uniform in [a, b).
    pub fn range(&mut self, a: f64, b: f64) -> f64 {
        a + (b - a) * self.next()
    }
}
