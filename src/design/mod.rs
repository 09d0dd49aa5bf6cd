//! Design drivers: batch sweeps (and, later, sensitivities and optimisation).

pub mod sweep;
pub mod table;
