//! Natural modes of the stage (the `modes` of a `stage` case), actuators locked.

use crate::analysis::RunError;
use crate::case::stage::StageCase;
use crate::stage;

/// Modes of the stage with the actuators locked. Platform: point mass at P, a disc of radius
/// b and thickness t (default 10 mm) unless `platform_mass` is given: m = ρπb²t,
/// Ixx = Iyy = m(3b² + t²)/12, Izz = mb²/2 (platform normal = global z at home).
pub fn stage_modes(
    case: &StageCase,
    s: &stage::StageModel,
    n: usize,
) -> Result<Vec<crate::analysis::modal::ModeRow>, RunError> {
    Ok(stage_modes_with_model(case, s, n)?.0)
}

/// [`stage_modes`] plus the model solved (sliders clamped, platform mass added) and the raw
/// modal results (for the mode-shape `.vtu`).
pub(super) fn stage_modes_with_model(
    case: &StageCase,
    s: &stage::StageModel,
    n: usize,
) -> Result<
    (
        Vec<crate::analysis::modal::ModeRow>,
        crate::fem::Model,
        crate::fem::modal::ModalResults,
    ),
    RunError,
> {
    let mut model = s.model.clone();
    for leg in &s.legs {
        model.supports.push(crate::fem::Support::clamp(leg.slider));
    }
    let rho = s.design.material.density;
    let b = s.design.prs.b;
    let t = case.platform_thickness.unwrap_or(10.0);
    let mass = case.platform_mass.unwrap_or(rho * std::f64::consts::PI * b * b * t);
    let ixx = mass * (3.0 * b * b + t * t) / 12.0;
    model.masses.push(crate::fem::PointMass {
        node: s.platform,
        mass,
        inertia: [ixx, ixx, mass * b * b / 2.0],
    });
    let (r, raw) = crate::analysis::modal::solve(&model, n, None)?;
    Ok((r.modes, model, raw))
}
