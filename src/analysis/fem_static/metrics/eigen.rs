//! `frequency` and `buckling_margin` metrics: a modal solve of the model with its supports
//! (the `modal` analysis's mass model and Lanczos solver) and a linear buckling solve with a
//! load case as the reference load (the `buckling` analysis's geometric stiffness).

use super::super::AnalysisError;
use crate::case::mesh::{MetricKind, MetricRequest};
use crate::fem::buckling::{solve_buckling, BucklingOptions};
use crate::fem::modal::{solve_modal, ModalOptions};
use crate::fem::Model;

/// The natural frequencies (Hz, lowest first) up to the highest `mode` a `frequency` metric of
/// `reqs` asks for (none without such a metric): one modal solve of the undeformed model.
pub fn frequencies(model: &Model, reqs: &[MetricRequest]) -> Result<Vec<f64>, AnalysisError> {
    let n = reqs
        .iter()
        .filter(|m| m.kind == MetricKind::Frequency)
        .filter_map(|m| m.mode)
        .max()
        .unwrap_or(0);
    if n == 0 {
        return Ok(Vec::new());
    }
    let r = solve_modal(model, &ModalOptions::new(n))
        .map_err(|e| AnalysisError::new("frequency (modal solve of the model)", e.to_string()))?;
    if r.modes.len() < n {
        return Err(AnalysisError::new(
            "frequency",
            format!(
                "mode {n} asked for, the model has {} modes ({} equations)",
                r.modes.len(),
                r.n_eq
            ),
        ));
    }
    Ok(r.modes.iter().map(|m| m.frequency_hz).collect())
}

/// The first (smallest |λ|) buckling load factor of load case `ic` of `model` as the reference
/// load (negative: the reversed load buckles).
pub fn buckling_margin(model: &Model, ic: usize) -> Result<f64, AnalysisError> {
    let ctx = || {
        format!(
            "buckling_margin (linear buckling of load case \"{}\")",
            model.load_cases[ic].name
        )
    };
    let r =
        solve_buckling(model, ic, &BucklingOptions::new(1)).map_err(|e| AnalysisError::new(ctx(), e.to_string()))?;
    r.modes
        .first()
        .map(|m| m.load_factor)
        .ok_or_else(|| AnalysisError::new(ctx(), "no buckling mode found"))
}
