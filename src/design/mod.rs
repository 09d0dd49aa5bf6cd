//! Design drivers: batch sweeps (and, later, sensitivities and optimisation).

pub mod plots;
pub mod stage_design;
pub mod sweep;
pub mod table;
