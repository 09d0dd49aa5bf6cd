//! Validation of the inputs of a transient solve.

use super::{TransientLoad, TransientOptions};
use crate::fem::error::FemError;
use crate::fem::model::Model;

fn check_options(model: &Model, opts: &TransientOptions) -> Result<(), FemError> {
    let bad = |s: String| Err(FemError::BadInput(s));
    if !super::DT_RANGE.contains(&opts.dt) || opts.steps == 0 {
        return bad(format!(
            "transient: time step {} s and {} steps: the step must be from {:e} to {:e} s and the steps > 0",
            opts.dt,
            opts.steps,
            super::DT_RANGE.start(),
            super::DT_RANGE.end()
        ));
    }
    let (a, _, _) = opts.scheme.parameters();
    if !(-1.0 / 3.0..=0.0).contains(&a) {
        return bad(format!("HHT alpha {a} must be in [-1/3, 0]"));
    }
    let d = &opts.damping;
    let coeffs = [d.alpha, d.beta].into_iter().chain(d.element_beta.iter().map(|e| e.1));
    if coeffs.clone().any(|c| !(c.is_finite() && c >= 0.0)) {
        return bad("damping coefficients must be finite and ≥ 0".into());
    }
    if let Some(&(ie, _)) = d.element_beta.iter().find(|e| e.0 >= model.elements.len()) {
        return bad(format!(
            "element damping names element {ie}; the model has {}",
            model.elements.len()
        ));
    }
    if let Some(r) = opts.record.iter().find(|r| r.node >= model.nodes.len()) {
        return bad(format!("recorded DOF {r}: no such node ({} nodes)", model.nodes.len()));
    }
    match &opts.initial {
        Some((u, v)) if u.len() != model.n_dofs() || v.len() != model.n_dofs() => bad(format!(
            "initial state: {} and {} values for {} DOFs",
            u.len(),
            v.len(),
            model.n_dofs()
        )),
        _ => Ok(()),
    }
}

/// Validates the model, the options and the loads of a transient solve.
pub(crate) fn check_inputs(model: &Model, loads: &[TransientLoad], opts: &TransientOptions) -> Result<(), FemError> {
    model.validate()?;
    check_options(model, opts)?;
    for l in loads {
        l.history.validate()?;
        if l.node >= model.nodes.len() || l.f.iter().any(|v| !v.is_finite()) {
            return Err(FemError::BadInput(format!(
                "transient load at node {}: no such node or a non-finite value",
                l.node
            )));
        }
    }
    Ok(())
}
