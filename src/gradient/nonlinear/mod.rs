//! Gradients through the nonlinear path: derivatives of quantities of a converged,
//! geometrically nonlinear static state with respect to the case's declared parameters.
//!
//! At the converged state u* of a load case, R(u*, p, λ) = 0 with R = f_int(u, p) − λ f the
//! reduced residual (N, N·mm) on the equations of the co-rotational solver
//! ([`crate::fem::nonlinear`]), the state moves with a parameter p as
//!
//! du*/dp = −K_T⁻¹ ∂R/∂p,  du*/dλ = −K_T⁻¹ ∂R/∂λ,
//!
//! with K_T = ∂R/∂u the consistent (non-symmetric) tangent at u*, factorised once (sparse LU)
//! for every parameter and the path direction (the direct method: one solve per parameter,
//! right-hand sides solved together). "u" are the free translations and the spatial spins of the
//! rotations; a rigid-link slave follows its master, so a parameter that moves nodes moves the
//! reference geometry and the links' arms, both included.
//!
//! * ∂R/∂p at fixed u: central differences of the reduced residual of the case rebuilt at
//!   p ± h (every element, link arm and section recomputed from the parameters), at the same
//!   independent-node translations and rotations, h = [`Settings::step`]·max(|p|, 1), with the
//!   fourth-order stencil at ±h, ±2h (truncation O(h⁴)). The residual of a co-rotational
//!   state carries round-off of ~1e-11 of its forces (positions minus reference in the element
//!   frames), amplified by 1/h: h = 3e-4 balances the two (measured on the parallelogram,
//!   lever and pan-tilt: ≤ 4e-8 of the largest logarithmic sensitivity; h = 1e-3 leaves 1e-6
//!   of truncation for a 70 mm coordinate moving 1 mm notches, h = 1e-4 leaves 6e-8 of
//!   round-off; a second-order difference would need h ~ 1e-5 and leave ~1e-6).
//!   Hinge elements included: the analytic compliance derivative of
//!   [`crate::hinge::tangent`] serves the linear direct method ([`super::linear`]) only; here
//!   it would enter through the co-rotational element's local force Bᵀ C⁻¹ δ
//!   (∂/∂p = −Bᵀ C⁻¹ (dC/dp) C⁻¹ δ), which the rebuilt-residual difference still covers.
//! * A quantity Q(u, p) (displacements, stresses, tangent stiffness) changes by
//!   dQ/dp = ∂Q/∂p + ∂Q/∂u·du*/dp, taken as one directional central difference along
//!   (du*/dp, 1) at the same step (the quantity is evaluated on the rebuilt model at the moved
//!   configuration), the same stencil; along the path likewise with (du*/dλ, 1) and the
//!   prescribed values.
//! * Stroke and load at the allowable stress (utilisation U = 1 at s*): by the implicit-function
//!   theorem, dλ*/dp = −(dU/dp)/(dU/dλ) and ds*/dp = ds/dp + ds/dλ·dλ*/dp.
//!
//! The gradient is exact to the accuracy of the state: [`at_state`] first polishes the given
//! state with Newton iterations on the consistent tangent until the residual stops falling
//! (typically 1e-15 of the internal forces; [`Gradients::residual`] reports it).

mod design;
mod quantity;

pub use design::{Built, ParamCase};
pub use quantity::{Quantity, Site};

use crate::case::CaseError;
use crate::fem::nonlinear::probe::{Configuration, Elements, Probe};
use crate::fem::{FemError, NonlinearCase};

/// Why a gradient could not be computed.
#[derive(Debug, thiserror::Error)]
pub enum GradientError {
    /// The case (at some parameter values) is not valid.
    #[error("{0}")]
    Case(#[from] CaseError),
    /// A solve failed.
    #[error("{0}")]
    Fem(#[from] FemError),
    /// A request that does not fit the case (names the field and what is allowed).
    #[error("{0}")]
    Input(String),
}

/// Steps of the differences (see the module docs; the cost is four model builds per parameter).
#[derive(Debug, Clone, PartialEq)]
pub struct Settings {
    /// Parameter step relative to max(|p|, 1) (units of p): 3e-4.
    pub step: f64,
    /// Load-factor step of the path direction: 1e-3.
    pub lambda_step: f64,
    /// Newton iterations at most when polishing the given state: 8.
    pub polish: usize,
}

impl Default for Settings {
    fn default() -> Self {
        Settings {
            step: 3e-4,
            lambda_step: 1e-3,
            polish: 8,
        }
    }
}

/// Gradients of the quantities at one converged state.
#[derive(Debug, Clone, PartialEq, serde::Serialize)]
pub struct Gradients {
    /// The parameters differentiated, in order.
    pub parameters: Vec<String>,
    /// Value of each quantity at the state (its unit).
    pub values: Vec<f64>,
    /// `gradients[i][k]` = dQᵢ/dp_k (unit of Qᵢ per unit of p_k).
    pub gradients: Vec<Vec<f64>>,
    /// dQᵢ/dλ along the path (per unit of the case's load scale; 0 for the "at allowable" kinds).
    pub path_rates: Vec<f64>,
    /// Residual of the polished state relative to its internal forces.
    pub residual: f64,
    /// How the gradients were computed (for the result's `model` notes).
    pub model: Vec<String>,
}

/// Gradients of `quantities` with respect to `parameters` (declared names) at the converged
/// state `state` of load case `load_case` of `case` solved at the parameter values `values`
/// (the rest at the case's own) and load scale `scale`, λ = 1 (as [`ParamCase::solve`] gives).
#[allow(clippy::too_many_arguments)]
pub fn at_state(
    case: &ParamCase,
    values: &[(String, f64)],
    load_case: usize,
    scale: f64,
    state: &NonlinearCase,
    parameters: &[String],
    quantities: &[Quantity],
    settings: &Settings,
) -> Result<Gradients, GradientError> {
    let lambda = 1.0;
    let base = case.build(values, load_case, scale)?;
    let base_elems = Elements::new(&base.model)?;
    let probe = Probe::new(&base.model, &base_elems, 0)?;
    let mut cfg = probe.rebase(&Configuration::from_case(state));
    let residual = probe.polish(&mut cfg, lambda, settings.polish)?;

    // Models at p ± h.
    let mut steps = Vec::with_capacity(parameters.len());
    let mut sides = Vec::with_capacity(OFFSETS.len() * parameters.len());
    for name in parameters {
        let p = values
            .iter()
            .find(|(n, _)| n == name)
            .map(|(_, v)| *v)
            .or_else(|| case.defaults.get(name).copied())
            .ok_or_else(|| GradientError::Input(format!("parameters.{name}: not a declared parameter")))?;
        let h = settings.step * p.abs().max(1.0);
        steps.push(h);
        for off in OFFSETS {
            let mut v: Vec<(String, f64)> = values.iter().filter(|(n, _)| n != name).cloned().collect();
            v.push((name.clone(), p + off * h));
            let b = case.build(&v, load_case, scale)?;
            let e = Elements::new(&b.model)?;
            sides.push((b, e));
        }
    }
    let probes = sides
        .iter()
        .map(|(b, e)| Probe::new(&b.model, e, 0))
        .collect::<Result<Vec<_>, _>>()?;

    // Right-hand sides: −∂R/∂p_k, then −∂R/∂λ.
    let mut rhs = Vec::with_capacity(parameters.len() + 1);
    for (k, h) in steps.iter().enumerate() {
        let r = (0..OFFSETS.len())
            .map(|j| {
                let pr = &probes[OFFSETS.len() * k + j];
                pr.residual(&pr.rebase(&cfg), lambda)
            })
            .collect::<Result<Vec<_>, _>>()?;
        rhs.push(stencil_vec(&r, -*h));
    }
    let el = settings.lambda_step;
    let zero = vec![0.0; probe.n_eq()];
    let r = OFFSETS
        .iter()
        .map(|off| probe.residual(&probe.moved(&cfg, &zero, off * el), lambda + off * el))
        .collect::<Result<Vec<_>, _>>()?;
    rhs.push(stencil_vec(&r, -el));
    let z = probe.tangent_solve(&cfg, lambda, &rhs)?;
    let z_lambda = &z[parameters.len()];

    // dQ/dp_k and dQ/dλ by directional differences.
    let scaled = |v: &[f64], s: f64| v.iter().map(|x| x * s).collect::<Vec<_>>();
    let rate = |q: &Quantity| -> Result<(f64, Vec<f64>, f64), GradientError> {
        let q0 = quantity::value(&base, &probe, &cfg, lambda, q)?;
        let mut g = Vec::with_capacity(parameters.len());
        for (k, h) in steps.iter().enumerate() {
            let mut at = [0.0; OFFSETS.len()];
            for (j, off) in OFFSETS.iter().enumerate() {
                let (pr, (b, _)) = (&probes[OFFSETS.len() * k + j], &sides[OFFSETS.len() * k + j]);
                let c = pr.moved(&pr.rebase(&cfg), &scaled(&z[k], off * h), 0.0);
                at[j] = quantity::value(b, pr, &c, lambda, q)?;
            }
            g.push(stencil(&at, *h));
        }
        let mut at = [0.0; OFFSETS.len()];
        for (j, off) in OFFSETS.iter().enumerate() {
            let c = probe.moved(&cfg, &scaled(z_lambda, off * el), off * el);
            at[j] = quantity::value(&base, &probe, &c, lambda + off * el, q)?;
        }
        Ok((q0, g, stencil(&at, el)))
    };
    let mut out = Gradients {
        parameters: parameters.to_vec(),
        values: Vec::with_capacity(quantities.len()),
        gradients: Vec::with_capacity(quantities.len()),
        path_rates: Vec::with_capacity(quantities.len()),
        residual,
        model: notes(settings, residual),
    };
    for q in quantities {
        let (v, g, r) = match *q {
            Quantity::StrokeAtAllowable { site, .. } | Quantity::LoadFactorAtAllowable(site) => {
                let (_, gu, ru) = rate(&Quantity::Utilisation(site))?;
                if ru.abs() <= f64::EPSILON * gu.iter().fold(1.0, |m: f64, v| m.max(v.abs())) {
                    return Err(GradientError::Input(format!(
                        "{q:?}: the utilisation does not change along the path here (dU/dλ = {ru:e}): the stroke at the allowable is not defined by this state"
                    )));
                }
                let dl: Vec<f64> = gu.iter().map(|d| -d / ru).collect();
                if let Quantity::LoadFactorAtAllowable(_) = q {
                    (lambda, dl, 0.0)
                } else {
                    let (s, gs, rs) = rate(q)?;
                    (s, gs.iter().zip(&dl).map(|(a, b)| a + rs * b).collect(), 0.0)
                }
            }
            _ => rate(q)?,
        };
        out.values.push(v);
        out.gradients.push(g);
        out.path_rates.push(r);
    }
    Ok(out)
}

/// Offsets (in steps) of the differences: the fourth-order central stencil.
const OFFSETS: [f64; 4] = [1.0, -1.0, 2.0, -2.0];

/// df/dx ≈ (8(f(h) − f(−h)) − (f(2h) − f(−2h)))/(12h) from the values at [`OFFSETS`]·h
/// (error h⁴f⁽⁵⁾/30).
fn stencil(f: &[f64; 4], h: f64) -> f64 {
    (8.0 * (f[0] - f[1]) - (f[2] - f[3])) / (12.0 * h)
}

/// [`stencil`] entry by entry for vectors at [`OFFSETS`]·h.
fn stencil_vec(f: &[Vec<f64>], h: f64) -> Vec<f64> {
    (0..f[0].len())
        .map(|i| stencil(&[f[0][i], f[1][i], f[2][i], f[3][i]], h))
        .collect()
}

fn notes(s: &Settings, residual: f64) -> Vec<String> {
    vec![
        format!("gradients through the nonlinear path by the direct method at the converged state (polished by Newton iterations on the consistent tangent to a relative residual of {residual:.1e}): du/dp = -K_T^-1 dR/dp with the consistent non-symmetric tangent (sparse LU)"),
        format!("dR/dp at fixed displacements and rotations by fourth-order central differences (p +/- h, p +/- 2h) of the residual of the case rebuilt at those values (reference geometry, rigid-link arms and sections included), h = {:e} max(|p|, 1); quantity derivatives as directional differences along (du/dp, 1) with the same stencil", s.step),
        "stroke and load at the allowable by the implicit-function theorem: dlambda*/dp = -(dU/dp)/(dU/dlambda), ds*/dp = ds/dp + ds/dlambda dlambda*/dp".to_string(),
    ]
}
