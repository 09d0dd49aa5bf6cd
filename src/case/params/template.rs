//! A JSON value with its expression strings parsed once: the places ("sites") where a number
//! is computed from the parameters. Filling a template sets every site's number; a template
//! kept aside can be filled again for other parameter values without walking or parsing the
//! case again.

use super::expr::{Expr, ExprError};
use super::{expr_error, Parameters};
use crate::case::CaseError;
use serde_json::Value;

/// One step of the way to a site: an object key or an array index.
#[derive(Debug, Clone, PartialEq)]
pub enum Step {
    /// An object key.
    Key(String),
    /// An array index.
    Index(usize),
}

/// One expression string of the value.
#[derive(Debug, Clone)]
struct Site {
    /// The way from the root to the string.
    steps: Vec<Step>,
    /// The expression as written.
    text: String,
    expr: Expr,
}

/// Fields whose strings are free text, never expressions.
const TEXT_FIELDS: [&str; 2] = ["description", "name"];

/// A value with its expression sites (see the module docs).
#[derive(Debug, Clone)]
pub struct Template {
    value: Value,
    sites: Vec<Site>,
}

/// True for a string that is an expression: it names a parameter (`$`).
pub fn is_expression(s: &str) -> bool {
    s.contains('$')
}

impl Template {
    /// Finds and parses the expression strings of `value` (strings holding a `$`, outside the
    /// free-text fields `description` and `name`); a syntax error names the string's JSON path.
    pub fn new(value: Value) -> Result<Template, CaseError> {
        let mut sites = Vec::new();
        let mut steps: Vec<StepRef> = Vec::new();
        collect(&value, &mut steps, &mut sites)?;
        Ok(Template { value, sites })
    }

    /// Each site's JSON path, expression as written and the first parameter it uses.
    pub fn sites(&self) -> impl Iterator<Item = (String, &str, Option<&str>)> + '_ {
        self.sites.iter().map(|s| {
            let mut names = Vec::new();
            s.expr.names(&mut names);
            (path_of(borrowed(&s.steps)), s.text.as_str(), names.first().copied())
        })
    }

    /// Each site's way from the root and its expression, in the order [`Self::fill`] sets them.
    pub fn expressions(&self) -> impl Iterator<Item = (&[Step], &Expr)> + '_ {
        self.sites.iter().map(|s| (s.steps.as_slice(), &s.expr))
    }

    /// True when the value holds no expression.
    pub fn is_plain(&self) -> bool {
        self.sites.is_empty()
    }

    /// The value with every site set to its number for `params`.
    pub fn fill(mut self, params: &Parameters) -> Result<Value, CaseError> {
        set_all(&mut self.value, &self.sites, params)?;
        Ok(self.value)
    }

    /// [`Self::fill`] keeping the template (to fill it again for other values).
    pub fn instantiate(&self, params: &Parameters) -> Result<Value, CaseError> {
        let mut v = self.value.clone();
        set_all(&mut v, &self.sites, params)?;
        Ok(v)
    }

    /// The value with every site set to x + `step`·dx, x its number for `params` and dx its
    /// derivative when the parameters move by `tangent` (per unit of the direction; see
    /// [`super::tangent`]): the case a step along the exact tangent of its numbers.
    pub fn fill_along(mut self, params: &Parameters, tangent: &Parameters, step: f64) -> Result<Value, CaseError> {
        for site in &self.sites {
            let (x, dx) = site
                .expr
                .eval_tangent(&mut |name: &str| {
                    let v = params.get(name).copied();
                    v.map(|v| (v, tangent.get(name).copied().unwrap_or(0.0)))
                        .ok_or_else(|| Failure::Unknown(name.to_string()))
                })
                .map_err(|e| e.at(&path_of(borrowed(&site.steps)), &site.text, params))?;
            // Sites that do not move keep their plain number (integers stay integers: indices).
            *site_mut(&mut self.value, site) = if dx == 0.0 {
                number(x)
            } else {
                Value::from(x + step * dx)
            };
        }
        Ok(self.value)
    }
}

/// A step while walking: keys borrowed from the value (owned only for the sites found).
#[derive(Clone, Copy)]
enum StepRef<'v> {
    Key(&'v str),
    Index(usize),
}

impl StepRef<'_> {
    fn owned(self) -> Step {
        match self {
            StepRef::Key(k) => Step::Key(k.to_string()),
            StepRef::Index(i) => Step::Index(i),
        }
    }
}

/// The JSON path of `steps` as case errors write it (`elements[2].hinge.t`).
fn path_of<'s>(steps: impl IntoIterator<Item = StepRef<'s>>) -> String {
    let mut p = String::new();
    for s in steps {
        match s {
            StepRef::Key(k) if p.is_empty() => p.push_str(k),
            StepRef::Key(k) => {
                p.push('.');
                p.push_str(k);
            }
            StepRef::Index(i) => p.push_str(&format!("[{i}]")),
        }
    }
    p
}

fn borrowed(steps: &[Step]) -> impl Iterator<Item = StepRef<'_>> {
    steps.iter().map(|s| match s {
        Step::Key(k) => StepRef::Key(k),
        Step::Index(i) => StepRef::Index(*i),
    })
}

fn collect<'v>(v: &'v Value, steps: &mut Vec<StepRef<'v>>, sites: &mut Vec<Site>) -> Result<(), CaseError> {
    match v {
        Value::String(s) if is_expression(s) => {
            let expr = Expr::parse(s).map_err(|e| expr_error(&path_of(steps.iter().copied()), s, &e))?;
            sites.push(Site {
                steps: steps.iter().map(|s| s.owned()).collect(),
                text: s.clone(),
                expr,
            });
        }
        Value::Array(a) => {
            for (i, x) in a.iter().enumerate() {
                steps.push(StepRef::Index(i));
                collect(x, steps, sites)?;
                steps.pop();
            }
        }
        Value::Object(m) => {
            for (k, x) in m {
                if TEXT_FIELDS.contains(&k.as_str()) && x.is_string() {
                    continue;
                }
                steps.push(StepRef::Key(k));
                collect(x, steps, sites)?;
                steps.pop();
            }
        }
        _ => {}
    }
    Ok(())
}

fn set_all(root: &mut Value, sites: &[Site], params: &Parameters) -> Result<(), CaseError> {
    for site in sites {
        let x = evaluate(&site.expr, params).map_err(|e| e.at(&path_of(borrowed(&site.steps)), &site.text, params))?;
        *site_mut(root, site) = number(x);
    }
    Ok(())
}

/// The value at `site` inside `root`.
fn site_mut<'v>(root: &'v mut Value, site: &Site) -> &'v mut Value {
    let mut cur = root;
    for s in &site.steps {
        cur = match (s, cur) {
            (Step::Key(k), Value::Object(m)) => m.get_mut(k),
            (Step::Index(i), Value::Array(a)) => a.get_mut(*i),
            _ => None,
        }
        .expect("a site's steps lead to the string they were found at");
    }
    cur
}

/// The JSON number of `x`: an integer-valued result as an integer (node indices, counts), so
/// `"$n - 1"` is read where an index is expected; any other as a float.
pub fn number(x: f64) -> Value {
    if x.fract() == 0.0 && x.abs() < 9.0e15 {
        // Exact: |x| < 2^53, no fraction.
        Value::from(x as i64)
    } else {
        Value::from(x)
    }
}

/// Why a site's expression has no value.
pub(crate) enum Failure {
    /// A `$NAME` that is not declared.
    Unknown(String),
    /// Division by zero, sqrt of a negative number, overflow.
    Expr(ExprError),
}

impl From<ExprError> for Failure {
    fn from(e: ExprError) -> Self {
        Failure::Expr(e)
    }
}

impl Failure {
    /// The case error at `path` for the expression `text`.
    pub(super) fn at(self, path: &str, text: &str, params: &Parameters) -> CaseError {
        match self {
            Failure::Expr(e) => expr_error(path, text, &e),
            Failure::Unknown(name) => {
                let declared: Vec<String> = params.keys().map(|k| format!("${k}")).collect();
                let declared = if declared.is_empty() {
                    "none is declared".to_string()
                } else {
                    format!("declared: {}", declared.join(", "))
                };
                CaseError::value(
                    if path.is_empty() { "." } else { path },
                    format!("\"{text}\""),
                    format!("unknown parameter `${name}` ({declared}; parameters are given in `parameters` of the case or its mesh file)"),
                )
            }
        }
    }
}

/// The value of `expr` with the parameters `params`.
pub(crate) fn evaluate(expr: &Expr, params: &Parameters) -> Result<f64, Failure> {
    expr.eval(&mut |name: &str| {
        params
            .get(name)
            .copied()
            .ok_or_else(|| Failure::Unknown(name.to_string()))
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Every expression string is set to its number (integers as integers); plain strings and
    /// free text stay; the template fills again for other values.
    #[test]
    fn fills_every_site_and_refills() {
        let v = serde_json::json!({
            "description": "costs $5",
            "nodes": [[0, "$L/2", 0], ["-$L", 0, "sqrt($L)"]],
            "hinge": {"type": "circular_notch", "t": "$t", "R": "2*$t + 1"},
            "node": "$n - 1"
        });
        let t = Template::new(v).unwrap();
        let p: Parameters = [("L".into(), 16.0), ("t".into(), 0.75), ("n".into(), 3.0)].into();
        let out = t.instantiate(&p).unwrap();
        assert_eq!(out["nodes"], serde_json::json!([[0, 8, 0], [-16, 0, 4]]));
        assert_eq!(
            out["hinge"],
            serde_json::json!({"type": "circular_notch", "t": 0.75, "R": 2.5})
        );
        assert_eq!(out["node"], serde_json::json!(2));
        assert!(out["node"].is_u64());
        assert_eq!(out["description"], "costs $5");
        let q: Parameters = [("L".into(), 4.0), ("t".into(), 1.5), ("n".into(), 1.0)].into();
        let again = t.fill(&q).unwrap();
        assert_eq!(again["hinge"]["R"], serde_json::json!(4));
        assert_eq!(again["nodes"][1], serde_json::json!([-4, 0, 2]));
    }

    /// Errors name the JSON path of the string and quote the expression.
    #[test]
    fn errors_name_path_and_expression() {
        let e = Template::new(serde_json::json!({"a": [1, {"b": "2*$R +"}]})).unwrap_err();
        assert_eq!(e.path, "a[1].b");
        assert!(
            e.message.contains("\"2*$R +\"") && e.message.contains("syntax error"),
            "{}",
            e.message
        );
        let t = Template::new(serde_json::json!({"x": {"y": "$q/$z"}})).unwrap();
        let p: Parameters = [("z".into(), 0.0)].into();
        let e = t.instantiate(&p).unwrap_err();
        assert_eq!(e.path, "x.y");
        assert!(
            e.message.contains("unknown parameter `$q`") && e.message.contains("$z"),
            "{}",
            e.message
        );
        let p: Parameters = [("z".into(), 0.0), ("q".into(), 1.0)].into();
        let e = t.instantiate(&p).unwrap_err();
        assert!(
            e.message.contains("division by zero") && e.message.contains("\"$q/$z\""),
            "{}",
            e.message
        );
    }
}
