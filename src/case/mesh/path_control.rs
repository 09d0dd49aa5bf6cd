//! Path control of a nonlinear load case (`"control"`, `"arc_length"`, `"trace"`; shapes in
//! [`super::load_shapes`]): their checks and the solver options they give.

use super::load_shapes::LoadCaseSpec;
pub use super::load_shapes::{ArcLengthSpec, Constraint, Control, TraceSpec};
use crate::case::error::CaseError;
use crate::fem::{self, NodeDof};

/// Checks the path-control fields of load case `c` (JSON path `p`) for a model of `nodes`
/// nodes; `steps`: the nominal load steps of a nonlinear case, `None` for a linear one (the
/// fields are refused then).
pub fn check(p: &str, c: &LoadCaseSpec, steps: Option<usize>, nodes: usize) -> Result<(), CaseError> {
    let nonlinear = steps.is_some();
    let given = [
        ("control", c.control.is_some()),
        ("arc_length", c.arc_length.is_some()),
        ("trace", c.trace.is_some()),
    ];
    if let Some((k, _)) = given.iter().find(|(_, g)| *g).filter(|_| !nonlinear) {
        return Err(CaseError::new(
            format!("{p}.{k}"),
            format!("`{k}` applies to nonlinear load cases only: add \"nonlinear\": true"),
        ));
    }
    let arc = c.control == Some(Control::ArcLength);
    if c.arc_length.is_some() && !arc {
        return Err(CaseError::new(
            format!("{p}.arc_length"),
            "`arc_length` parameters need \"control\": \"arc_length\"",
        ));
    }
    if arc && !c.displacements.is_empty() {
        return Err(CaseError::value(
            format!("{p}.control"),
            "\"arc_length\"",
            "arc-length control follows loads only: this load case prescribes displacements (use load control)",
        ));
    }
    if let Some(a) = &c.arc_length {
        let at = |k: &str| format!("{p}.arc_length.{k}");
        for (k, v) in [("initial", a.initial), ("min", a.min), ("max", a.max)] {
            if let Some(v) = v {
                if !(v.is_finite() && v > 0.0 && v <= 1e6) {
                    return Err(CaseError::value(at(k), v, "must be an arc length > 0 and ≤ 1e6"));
                }
            }
        }
        if let (Some(min), Some(i)) = (a.min, a.initial) {
            if min > i {
                return Err(CaseError::value(
                    at("min"),
                    min,
                    format!("must not exceed `initial` ({i})"),
                ));
            }
        }
        if let (Some(max), Some(i)) = (a.max, a.initial) {
            if max < i {
                return Err(CaseError::value(
                    at("max"),
                    max,
                    format!("must be at least `initial` ({i})"),
                ));
            }
        }
        // With the defaults filled in (initial 1/steps, min 1e-4 × initial, max 20 × initial)
        // the solve needs min ≤ initial ≤ max.
        let [initial, min, max] = a.resolve().bounds(steps.unwrap_or(1));
        let given = |k: &str, v: Option<f64>, d: &str, resolved: f64| match v {
            Some(v) => format!("`{k}` ({v})"),
            None => format!("the default `{k}` ({d} = {resolved:e})"),
        };
        if min > max {
            return Err(CaseError::value(
                at("min"),
                min,
                format!("must not exceed {}", given("max", a.max, "20 × initial", max)),
            ));
        }
        if min > initial {
            return Err(CaseError::value(
                at("min"),
                min,
                format!("must not exceed {}", given("initial", a.initial, "1/steps", initial)),
            ));
        }
        if let Some(t) = a.target_iterations.filter(|t| !(1..=50).contains(t)) {
            return Err(CaseError::value(
                at("target_iterations"),
                t,
                "must be an integer from 1 to 50",
            ));
        }
        if let Some(s) = a.max_steps.filter(|s| !(1..=100_000).contains(s)) {
            return Err(CaseError::value(
                at("max_steps"),
                s,
                "must be an integer from 1 to 100000",
            ));
        }
    }
    if let Some(t) = &c.trace {
        if t.node >= nodes {
            return Err(CaseError::value(
                format!("{p}.trace.node"),
                t.node,
                format!("no such node (the model has {nodes})"),
            ));
        }
    }
    Ok(())
}

impl ArcLengthSpec {
    /// The solver's parameters (`initial` only when given; the solver's defaults otherwise).
    pub fn resolve(&self) -> fem::ArcLength {
        let d = fem::ArcLength::default();
        fem::ArcLength {
            initial: self.initial,
            min: self.min,
            max: self.max,
            target_iterations: self.target_iterations.unwrap_or(d.target_iterations),
            spherical: self.constraint == Constraint::Spherical,
            max_steps: self.max_steps.unwrap_or(d.max_steps),
        }
    }
}

/// The nonlinear options of load case `c` (checked by [`check`]) with `steps` nominal steps.
pub fn options(c: &LoadCaseSpec, steps: usize) -> fem::NonlinearOptions {
    fem::NonlinearOptions {
        steps,
        arc_length: c.control == Some(Control::ArcLength),
        arc: c.arc_length.as_ref().map(ArcLengthSpec::resolve).unwrap_or_default(),
        track: c
            .trace
            .iter()
            .map(|t| NodeDof {
                node: t.node,
                dof: t.dof.dof(),
            })
            .collect(),
        ..Default::default()
    }
}
