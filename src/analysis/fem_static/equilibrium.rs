//! The statics check of a linear static solution (as PyNite's `_check_statics`): the summed
//! applied loads and reactions balance to 1e-6 of their magnitudes. Round-off swamps the
//! solution of a model whose element stiffnesses lie many orders of magnitude apart; such a
//! result is an error, not a file.

use super::AnalysisError;
use crate::fem::{self, Model};
use nalgebra::Vector3;

/// Relative tolerance of the check, of the summed magnitudes of the loads and reactions.
pub const EQUILIBRIUM_TOLERANCE: f64 = 1e-6;

/// Absolute floor of the check, N and N·mm (a model loaded only by prescribed displacements of
/// a free motion has no reactions to scale by).
const FLOOR: f64 = 1e-9;

/// Checks load case `c` of `model`.
pub fn check(model: &Model, c: &fem::CaseResult) -> Result<(), AnalysisError> {
    let mut magnitude = [0.0f64; 6];
    let mut add = |x: [f64; 3], v: &[f64; 6]| {
        let r = fem::results::resultant(Vector3::from(x), v);
        (0..6).for_each(|k| magnitude[k] += r[k].abs());
    };
    if let Some(lc) = model.load_cases.iter().find(|l| l.name == c.name) {
        lc.forces.iter().for_each(|f| add(model.nodes[f.node], &f.f));
    }
    c.reactions.iter().for_each(|(n, r)| add(model.nodes[*n], r));
    (0..6).for_each(|k| magnitude[k] += c.statics.reactions[k].abs());
    let size = fem::model::model_size(&model.nodes);
    let fscale = magnitude[..3].iter().copied().fold(0.0, f64::max);
    let mscale = magnitude[3..].iter().copied().fold(0.0, f64::max).max(fscale * size);
    let residual = c.statics.residual();
    let bad = (0..6).find(|&k| {
        let scale = if k < 3 { fscale } else { mscale };
        residual[k].is_nan() || residual[k].abs() > EQUILIBRIUM_TOLERANCE * scale + FLOOR
    });
    match bad {
        None => Ok(()),
        Some(k) => Err(AnalysisError::new(
            format!("load case `{}`", c.name),
            format!(
                "the solution does not balance the loads: equilibrium residual {:?} (N, N·mm), component {k} above {EQUILIBRIUM_TOLERANCE} of the loads and reactions ({:.3e}); round-off swamps the solution — element stiffnesses lie many orders of magnitude apart (check sections, materials and spring constants)",
                residual,
                if k < 3 { fscale } else { mscale }
            ),
        )),
    }
}
