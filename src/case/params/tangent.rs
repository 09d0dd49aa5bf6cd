//! Derivatives of the declared parameters along one of them: the direction in which a case is
//! moved to differentiate its results ([`super::resolve_case_in`] with an [`Along`]).
//!
//! A parameter declared as a number is independent; one declared as an expression follows
//! the others, so its derivative with respect to an independent parameter `p` comes from the
//! chain rule through its expression ([`Expr::eval_tangent`], exact: no difference quotient).

use super::expr::{Expr, ExprError};
use super::{expr_error, Declared, Parameters};
use crate::case::CaseError;
use serde_json::Value;
use std::collections::BTreeMap;

/// A case as written (before its parameters are resolved), with the JSON mesh file it names
/// read once: resolved again for other parameter values, or along a parameter, without reading
/// any file.
#[derive(Debug, Clone, PartialEq)]
pub struct Written {
    /// The case object.
    pub value: Value,
    /// The JSON mesh file it names (name as written, content as read).
    pub mesh: Option<(String, Value)>,
    /// The folder other files it names resolve against.
    pub dir: Option<std::path::PathBuf>,
}

/// A step along parameter `name`: every number the parameters set moves by `step` times its
/// derivative with respect to `name` (units of `name` per unit step).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Along<'a> {
    /// The independent parameter (declared as a number).
    pub name: &'a str,
    /// The step, in the units of the parameter.
    pub step: f64,
}

/// d(value)/d(`wrt`) of every declared parameter, for the values `values` (resolved by
/// [`super::resolve_table`], which also refused cycles and unknown names).
pub fn table(declared: &BTreeMap<String, Declared>, values: &Parameters, wrt: &str) -> Result<Parameters, CaseError> {
    let mut out = Parameters::new();
    for name in declared.keys() {
        derivative(name, declared, values, wrt, &mut out)?;
    }
    Ok(out)
}

fn derivative(
    name: &str,
    declared: &BTreeMap<String, Declared>,
    values: &Parameters,
    wrt: &str,
    done: &mut Parameters,
) -> Result<f64, CaseError> {
    if let Some(d) = done.get(name) {
        return Ok(*d);
    }
    let d = match declared.get(name).map(|d| (&d.raw, d)) {
        _ if name == wrt => 1.0,
        Some((Value::String(text), decl)) => {
            let e = Expr::parse(text).map_err(|e| expr_error(&decl.path, text, &e))?;
            let r = e.eval_tangent(&mut |n: &str| -> Result<(f64, f64), Stop> {
                let v = values.get(n).copied().ok_or(Stop::Unknown)?;
                let dv = derivative(n, declared, values, wrt, done).map_err(Stop::Case)?;
                Ok((v, dv))
            });
            match r {
                Ok((_, d)) => d,
                Err(Stop::Case(e)) => return Err(e),
                Err(Stop::Expr(e)) => return Err(expr_error(&decl.path, text, &e)),
                Err(Stop::Unknown) => unreachable!("resolve_table refused unknown parameters"),
            }
        }
        _ => 0.0,
    };
    done.insert(name.to_string(), d);
    Ok(d)
}

enum Stop {
    Case(CaseError),
    Expr(ExprError),
    Unknown,
}

impl From<ExprError> for Stop {
    fn from(e: ExprError) -> Self {
        Stop::Expr(e)
    }
}

/// The parameters declared as numbers (the independent ones), by name.
pub fn independent(declared: &BTreeMap<String, Declared>) -> Vec<String> {
    declared
        .iter()
        .filter(|(_, d)| d.raw.is_number())
        .map(|(n, _)| n.clone())
        .collect()
}

#[cfg(test)]
mod tests {
    use super::super::{resolve_table, take_declared};
    use super::*;

    /// Derivatives of expressions against their closed forms: d(a·b)/da = b, d(a/b)/db =
    /// −a/b², d sqrt(x)/dx = 1/(2 sqrt x), d sin(x°)/dx = (π/180) cos(x°), chained.
    #[test]
    fn tangents_match_closed_forms() {
        let mut case = serde_json::json!({"parameters": {
            "a": 3.0, "b": 2.0, "x": 30.0,
            "p": "$a*$b", "q": "$a/$b", "r": "sqrt($p)", "s": "sin($x)*$a", "u": "2*$r - $q"
        }});
        let declared = take_declared(&mut case).unwrap();
        let values = resolve_table(&declared).unwrap();
        let da = table(&declared, &values, "a").unwrap();
        let db = table(&declared, &values, "b").unwrap();
        let dx = table(&declared, &values, "x").unwrap();
        let close = |x: f64, y: f64| assert!((x - y).abs() <= 1e-14 * y.abs().max(1.0), "{x} vs {y}");
        close(da["p"], 2.0);
        close(db["q"], -3.0 / 4.0);
        close(da["r"], 2.0 / (2.0 * 6f64.sqrt()));
        close(dx["s"], 3.0 * std::f64::consts::PI / 180.0 * 30f64.to_radians().cos());
        close(da["u"], 2.0 * da["r"] - 0.5);
        close(da["a"], 1.0);
        close(da["b"], 0.0);
        assert_eq!(independent(&declared), ["a", "b", "x"]);
    }

    /// A step along a parameter moves each site by its derivative; unmoved sites keep integers.
    #[test]
    fn fill_along_moves_sites_by_their_derivative() {
        let t = super::super::Template::new(serde_json::json!({"x": "$a*$a", "n": "$k - 1"})).unwrap();
        let p: Parameters = [("a".into(), 3.0), ("k".into(), 4.0)].into();
        let d: Parameters = [("a".into(), 1.0), ("k".into(), 0.0)].into();
        let v = t.fill_along(&p, &d, 1e-3).unwrap();
        assert!((v["x"].as_f64().unwrap() - (9.0 + 6e-3)).abs() < 1e-14, "{v}");
        assert!(v["n"].is_u64(), "{v}");
    }
}
