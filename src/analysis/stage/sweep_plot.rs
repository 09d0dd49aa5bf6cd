//! Plots of sweep results over an analysis kind (rendered from the sweep's JSON lines).

use crate::report::svg;
use rayon::prelude::*;
use serde::Deserialize;

/// The fields of a stage sweep line the plot reads (a field of another type makes the line
/// unreadable, as for a line that is not JSON).
#[derive(Deserialize)]
struct PlotLine {
    result: Option<PlotResult>,
}

#[derive(Deserialize)]
struct PlotResult {
    stiffness_z: Option<f64>,
    at_allowable: Option<PlotReach>,
    load_cases: Option<Vec<PlotCase>>,
}

#[derive(Deserialize)]
struct PlotReach {
    z: Option<f64>,
}

#[derive(Deserialize)]
struct PlotCase {
    #[serde(rename = "T")]
    t: Option<f64>,
}

/// Stage-sweep plot: structural stiffness against Δz reachable at the allowable stress,
/// coloured by T; designs meeting the requirements of Ruiz et al. (2019) §4 (Δz ≥ 2 mm, T ∈ [0.8, 1.2]) filled. `None` if no line
/// holds a stage result.
pub fn stage_sweep_svg(lines: &[String]) -> Option<String> {
    // Only the three numbers plotted are read (the rest of a line is skipped unparsed into
    // values), lines in parallel, in order.
    let pts: Vec<(f64, f64, f64, bool)> = lines
        .par_iter()
        .filter_map(|l| {
            let r = serde_json::from_str::<PlotLine>(l).ok()?.result?;
            let (k, z, t) = (r.stiffness_z?, r.at_allowable?.z?, r.load_cases?.first()?.t?);
            Some((k, z, t, z >= 2.0 && (0.8..=1.2).contains(&t)))
        })
        .collect();
    if pts.is_empty() {
        return None;
    }
    Some(svg::scatter_coloured(
        "Stage designs: stiffness against reachable Δz",
        "structural stiffness η (N/mm)",
        "Δz at the allowable stress (mm)",
        &pts,
        "T = σsph/σrev",
        Some((2.0, "Δz = 2 mm requirement")),
    ))
}
