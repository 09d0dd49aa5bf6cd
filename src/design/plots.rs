//! Plots of sweep results: the stage-sweep plot belongs to the `stage` analysis
//! ([`crate::analysis::sweep_plot`]); this path is kept for library callers.

pub use crate::analysis::sweep_plot::stage_sweep_svg;
