//! The parameterised case behind a nonlinear gradient: a geometrically nonlinear `static` case
//! (its model inline or in a JSON mesh file) whose declared `parameters` are set to given values
//! and built into an FE model holding one load case, scaled.

use super::GradientError;
use crate::analysis::case_file::{parse_resolved, Case};
use crate::case::mesh::BuiltHinge;
use crate::fem::{self, Model, NonlinearCase, NonlinearOptions};
use serde_json::{json, Value};
use std::path::{Path, PathBuf};

/// A nonlinear static case with declared parameters (see the module docs).
#[derive(Debug, Clone)]
pub struct ParamCase {
    value: Value,
    base: Option<PathBuf>,
    /// Declared parameters at the case's own values, by name.
    pub defaults: crate::case::params::Parameters,
}

/// The FE model of a [`ParamCase`] at some parameter values: one load case (the chosen one,
/// its loads and prescribed values times the scale) and the model's hinge elements.
#[derive(Debug, Clone)]
pub struct Built {
    pub model: Model,
    pub hinges: Vec<BuiltHinge>,
}

impl ParamCase {
    /// Reads a case value (relative file names against `base`); it must be a `static` case with
    /// `"nonlinear": true`.
    pub fn new(value: Value, base: Option<&Path>) -> Result<ParamCase, GradientError> {
        let parsed = parse_resolved(value.clone(), base, true)?;
        match parsed.case {
            Case::Static(s) if s.nonlinear => {}
            _ => {
                return Err(GradientError::Input(
                    "analysis: gradients through the nonlinear path need a \"static\" case with \"nonlinear\": true"
                        .into(),
                ))
            }
        }
        Ok(ParamCase {
            value,
            base: base.map(Path::to_path_buf),
            defaults: parsed.parameters,
        })
    }

    /// The model at the case's parameter values overridden by `values` (name, value), holding
    /// load case `load_case` only, its forces and prescribed values times `scale`.
    pub fn build(&self, values: &[(String, f64)], load_case: usize, scale: f64) -> Result<Built, GradientError> {
        let mut v = self.value.clone();
        if !v.get("parameters").is_some_and(Value::is_object) {
            v["parameters"] = json!({});
        }
        for (name, x) in values {
            if !self.defaults.contains_key(name) {
                return Err(GradientError::Input(format!(
                    "parameters.{name}: not a declared parameter (declared: {})",
                    self.defaults.keys().cloned().collect::<Vec<_>>().join(", ")
                )));
            }
            v["parameters"][name] = json!(x);
        }
        let Case::Static(case) = parse_resolved(v, self.base.as_deref(), false)?.case else {
            return Err(GradientError::Input("analysis: not a static case".into()));
        };
        let (mut model, hinges) = case.model.build_with_hinges(true, true)?;
        let n = model.load_cases.len();
        if load_case >= n {
            return Err(GradientError::Input(format!(
                "load case {load_case}: the case has {n} load case(s)"
            )));
        }
        let mut lc = model.load_cases.swap_remove(load_case);
        lc.forces
            .iter_mut()
            .for_each(|f| f.f.iter_mut().for_each(|x| *x *= scale));
        lc.displacements.iter_mut().for_each(|d| d.value *= scale);
        model.load_cases = vec![lc];
        Ok(Built { model, hinges })
    }

    /// [`Self::build`] and the nonlinear solve of its load case with `opts`.
    pub fn solve(
        &self,
        values: &[(String, f64)],
        load_case: usize,
        scale: f64,
        opts: &NonlinearOptions,
    ) -> Result<(Built, NonlinearCase), GradientError> {
        let built = self.build(values, load_case, scale)?;
        let mut res = fem::solve_nonlinear(&built.model, opts)?;
        let c = res.load_cases.remove(0);
        Ok((built, c))
    }
}
