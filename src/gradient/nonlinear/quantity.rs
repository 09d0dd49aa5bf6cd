//! The quantities whose gradients [`super::at_state`] gives, and their values at a
//! configuration of a probed model.

use super::design::Built;
use super::GradientError;
use crate::fem::nonlinear::probe::{Configuration, Probe};
use crate::fem::{Dof, Element};

/// Where a stress is read.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Site {
    /// A beam of the FE model (model element index): the larger von Mises stress of its two end
    /// sections, MPa.
    Element(usize),
    /// A hinge element of the case (its index in the case's `elements`): the peak von Mises
    /// stress of the notch, MPa, from the end section forces of its segment chain with the
    /// hinge's stress model, as the `static` analysis reports `hinges[].peak_von_mises`.
    Hinge(usize),
}

/// A quantity of the converged state.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Quantity {
    /// Displacement of `node` along `dof`, global axes: mm (translations) or rad (the
    /// rotation-vector component). The parasitic motion at a stroke is one.
    Displacement { node: usize, dof: Dof },
    /// Von Mises stress at the site, MPa.
    Stress(Site),
    /// Von Mises stress over the allowable stress of the site's material (dimensionless).
    Utilisation(Site),
    /// Tangent stiffness at `node` along `dof` with every other free DOF free: 1/(eᵀK_T⁻¹e),
    /// N/mm (translations) or N·mm/rad (rotations). The DOF must be free.
    TangentStiffness { node: usize, dof: Dof },
    /// The stroke at the allowable stress: the displacement of `node` along `dof` (mm or rad)
    /// at the state where the utilisation of `site` is 1. The state given to
    /// [`super::at_state`] must be that state (found by the caller along the path); the
    /// gradient follows the implicit-function theorem, ds*/dp = ∂s/∂p + ∂s/∂λ·dλ*/dp with
    /// dλ*/dp = −(dU/dp)/(dU/dλ).
    StrokeAtAllowable { site: Site, node: usize, dof: Dof },
    /// The load factor at the allowable stress, λ* (1 at the given state, per unit of the
    /// case's loads and prescribed values times the scale): its gradient is dλ*/dp.
    LoadFactorAtAllowable(Site),
}

/// Von Mises stress (MPa) and allowable stress (MPa) of `site` at `cfg`.
pub(super) fn stress(
    built: &Built,
    probe: &Probe,
    cfg: &Configuration,
    site: Site,
) -> Result<(f64, f64), GradientError> {
    match site {
        Site::Element(ie) => {
            let Some(Element::Beam(b)) = built.model.elements.get(ie) else {
                return Err(GradientError::Input(format!(
                    "element {ie}: not a beam of the model (use a hinge site for hinge elements)"
                )));
            };
            let vm = probe
                .element_result(cfg, ie)
                .and_then(|r| r.max_von_mises())
                .ok_or_else(|| GradientError::Input(format!("element {ie}: no stress at this state")))?;
            Ok((vm, b.material.allowable))
        }
        Site::Hinge(k) => {
            let h = built
                .hinges
                .iter()
                .find(|h| h.case_element == k)
                .ok_or_else(|| GradientError::Input(format!("elements[{k}]: not a hinge element")))?;
            let end = |ie: usize| {
                probe
                    .element_result(cfg, ie)
                    .ok_or_else(|| GradientError::Input(format!("elements[{k}]: a segment is degenerate")))
            };
            let sf = [end(h.element)?.section_forces[0], end(h.last)?.section_forces[1]];
            Ok((h.region.peak_stress(&sf), h.allowable))
        }
    }
}

/// Value of a quantity that depends on the configuration alone (the "at allowable" kinds are
/// combinations: their parts are evaluated).
pub(super) fn value(
    built: &Built,
    probe: &Probe,
    cfg: &Configuration,
    lambda: f64,
    q: &Quantity,
) -> Result<f64, GradientError> {
    Ok(match *q {
        Quantity::Displacement { node, dof } | Quantity::StrokeAtAllowable { node, dof, .. } => {
            Probe::node_value(cfg, node, dof.index())
        }
        Quantity::Stress(site) => stress(built, probe, cfg, site)?.0,
        Quantity::Utilisation(site) => {
            let (s, a) = stress(built, probe, cfg, site)?;
            s / a
        }
        Quantity::TangentStiffness { node, dof } => {
            let e = probe.unit_load(cfg, node, dof.index());
            if e.iter().all(|v| *v == 0.0) {
                return Err(GradientError::Input(format!(
                    "tangent stiffness at node {node} along {dof:?}: the DOF is held"
                )));
            }
            let x = probe.tangent_solve(cfg, lambda, std::slice::from_ref(&e))?;
            let c: f64 = e.iter().zip(&x[0]).map(|(a, b)| a * b).sum();
            1.0 / c
        }
        Quantity::LoadFactorAtAllowable(_) => lambda,
    })
}
