//! Design drivers: batch sweeps (and, later, sensitivities and optimisation).

pub mod plots;
pub mod sweep;
pub mod table;
mod table_cells;
mod table_lines;

/// The stage sizing and sensitivity code lives with the stage ([`crate::stage::sizing`]); this
/// path is kept for library callers.
pub use crate::stage::sizing as stage_design;
