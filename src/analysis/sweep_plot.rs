//! Plots of sweep results over an analysis kind (rendered from the sweep's JSON lines).

use crate::report::svg;

/// Stage-sweep plot: structural stiffness against Δz reachable at the allowable stress,
/// coloured by T; designs meeting the requirements of Ruiz et al. (2019) §4 (Δz ≥ 2 mm, T ∈ [0.8, 1.2]) filled. `None` if no line
/// holds a stage result.
pub fn stage_sweep_svg(lines: &[String]) -> Option<String> {
    let mut pts = Vec::new();
    for l in lines {
        let Ok(v) = serde_json::from_str::<serde_json::Value>(l) else {
            continue;
        };
        let r = &v["result"];
        let (Some(k), Some(z), Some(t)) = (
            r["stiffness_z"].as_f64(),
            r["at_allowable"]["z"].as_f64(),
            r["load_cases"][0]["T"].as_f64(),
        ) else {
            continue;
        };
        pts.push((k, z, t, z >= 2.0 && (0.8..=1.2).contains(&t)));
    }
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
