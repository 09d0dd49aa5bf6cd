//! Case parameters, expressions and named hinge types, resolved on the JSON value before the
//! typed parse.
//!
//! A case, and a JSON mesh file it loads, may declare `"parameters": {"NAME": value, …}`; a
//! value is a number or an expression of other parameters (`"2*$t"`), resolved in dependency
//! order (a cycle is an error naming it). The case's parameters override the mesh file's of the
//! same name: a mesh file declares defaults. Anywhere a number goes, a string holding `$` is an
//! expression ([`expr`]) replaced by its number. `"hinge_types": {"NAME": {<hinge spec>}}`
//! (case or mesh file; the case's override) names hinge definitions: a `"hinge"` (or a stage's
//! `"revolute"`/`"spherical"`) given as the string `"NAME"` is that definition, so one parameter
//! drives every hinge of the type.
//!
//! The resolved values are plain numbers, so the JSON Schema and serde see the case as if it
//! had been written with literal numbers (identical, bit for bit); `parameters` and
//! `hinge_types` are taken out before validation.

pub mod compiled;
pub mod expr;
pub mod origin;
pub mod tangent;
pub mod template;

use crate::case::{short, CaseError};
use expr::{Expr, ExprError};
pub use origin::Origins;
use serde_json::{Map, Value};
use std::collections::BTreeMap;
pub use tangent::Along;
pub use template::Template;

/// Resolved parameter values by name (no `$`), in the units of wherever they are used.
pub type Parameters = BTreeMap<String, f64>;

/// The case error for expression `text` at `path`.
pub(crate) fn expr_error(path: &str, text: &str, e: &ExprError) -> CaseError {
    CaseError::value(if path.is_empty() { "." } else { path }, format!("\"{text}\""), e)
}

/// A declared parameter: where (JSON path) and its value as written.
#[derive(Debug, Clone)]
pub struct Declared {
    /// JSON path of the declaration (`parameters.t`).
    pub path: String,
    /// A number or an expression string.
    pub raw: Value,
    /// The mesh file it is declared in (`None`: the case).
    pub file: Option<String>,
}

impl Declared {
    /// An error about this declaration: at its path, or at `mesh` naming the file and path.
    fn error(&self, e: CaseError) -> CaseError {
        match &self.file {
            Some(name) => in_mesh_file(name, e),
            None => e,
        }
    }
}

/// Takes `parameters` out of a case or mesh-file object: name → declaration. A name must be
/// a valid parameter name, a value a number or an expression string.
pub fn take_declared(value: &mut Value) -> Result<BTreeMap<String, Declared>, CaseError> {
    let Some(p) = value.as_object_mut().and_then(|m| m.remove("parameters")) else {
        return Ok(BTreeMap::new());
    };
    let Value::Object(map) = p else {
        return Err(CaseError::value(
            "parameters",
            short(&p),
            "must be an object {\"NAME\": number or expression, …}",
        ));
    };
    let mut out = BTreeMap::new();
    for (name, raw) in map {
        let path = format!("parameters.{name}");
        if !expr::is_name(&name) {
            return Err(CaseError::value(
                path,
                format!("\"{name}\""),
                "a parameter name is a letter or `_`, then letters, digits or `_` (used as `$NAME`)",
            ));
        }
        if !(raw.is_number() || raw.is_string()) {
            return Err(CaseError::value(
                path,
                short(&raw),
                "a parameter is a number or an expression string of other parameters (\"2*$t\")",
            ));
        }
        out.insert(name, Declared { path, raw, file: None });
    }
    Ok(out)
}

/// The values of declared parameters, each expression resolved from the others in dependency
/// order. Errors name the declaration's path: an unknown parameter, a cycle (listed), a syntax
/// error, a division by zero or a non-finite value.
pub fn resolve_table(declared: &BTreeMap<String, Declared>) -> Result<Parameters, CaseError> {
    let mut exprs: BTreeMap<&str, (Expr, &Declared)> = BTreeMap::new();
    for (name, d) in declared {
        let e = match &d.raw {
            Value::String(s) => Expr::parse(s).map_err(|e| d.error(expr_error(&d.path, s, &e)))?,
            v => Expr::Num(
                v.as_f64()
                    .filter(|x| x.is_finite())
                    .ok_or_else(|| d.error(CaseError::value(&d.path, short(v), "must be a finite number")))?,
            ),
        };
        exprs.insert(name, (e, d));
    }
    let mut done = Parameters::new();
    for name in exprs.keys() {
        let mut stack = Vec::new();
        value_of(name, &exprs, &mut done, &mut stack)?;
    }
    Ok(done)
}

/// Why a parameter's value could not be found (the error of the innermost declaration).
enum Stop {
    Case(CaseError),
    Unknown(String),
    Expr(ExprError),
}

impl From<ExprError> for Stop {
    fn from(e: ExprError) -> Self {
        Stop::Expr(e)
    }
}

fn value_of<'a>(
    name: &'a str,
    exprs: &'a BTreeMap<&'a str, (Expr, &'a Declared)>,
    done: &mut Parameters,
    stack: &mut Vec<&'a str>,
) -> Result<f64, CaseError> {
    if let Some(v) = done.get(name) {
        return Ok(*v);
    }
    let Some((key, (expr, d))) = exprs.get_key_value(name) else {
        unreachable!("value_of is called for declared names only");
    };
    if let Some(from) = stack.iter().position(|n| *n == name) {
        let cycle: Vec<String> = stack[from..].iter().chain([&name]).map(|n| format!("${n}")).collect();
        let first = &exprs[stack[from]].1;
        return Err(first.error(CaseError::value(
            &first.path,
            short(&first.raw),
            format!("parameters defined in a cycle: {}", cycle.join(" → ")),
        )));
    }
    stack.push(*key);
    let text = d.raw.as_str().unwrap_or_default();
    let v = expr
        .eval(&mut |n: &str| -> Result<f64, Stop> {
            match exprs.get_key_value(n) {
                Some((k, _)) => value_of(k, exprs, done, stack).map_err(Stop::Case),
                None => Err(Stop::Unknown(n.to_string())),
            }
        })
        .map_err(|s| match s {
            Stop::Case(e) => e,
            Stop::Expr(e) => d.error(expr_error(&d.path, text, &e)),
            Stop::Unknown(n) => {
                let names: Vec<String> = exprs.keys().map(|k| format!("${k}")).collect();
                d.error(CaseError::value(
                    &d.path,
                    format!("\"{text}\""),
                    format!("unknown parameter `${n}` (declared: {})", names.join(", ")),
                ))
            }
        })?;
    stack.pop();
    done.insert(name.to_string(), v);
    Ok(v)
}

/// Takes `hinge_types` out of a case or mesh-file object: name → hinge spec object.
pub fn take_hinge_types(value: &mut Value) -> Result<Map<String, Value>, CaseError> {
    let Some(h) = value.as_object_mut().and_then(|m| m.remove("hinge_types")) else {
        return Ok(Map::new());
    };
    let Value::Object(map) = h else {
        return Err(CaseError::value(
            "hinge_types",
            short(&h),
            "must be an object {\"NAME\": {<hinge spec>}, …}",
        ));
    };
    for (name, spec) in &map {
        if !spec.is_object() {
            return Err(CaseError::value(
                format!("hinge_types.{name}"),
                short(spec),
                "a hinge type is a hinge object {\"type\": \"circular_notch\", …}",
            ));
        }
    }
    Ok(map)
}

/// The fields whose value may name a hinge type.
const HINGE_FIELDS: [&str; 3] = ["hinge", "revolute", "spherical"];

/// Replaces every hinge field (`"hinge": "NAME"`, a stage's `"revolute"`/`"spherical"`) given as
/// a string by the hinge type of that name (its expressions are resolved afterwards, with the
/// rest of the value). `at` is the JSON path of `v` (a buffer: restored on return); each use is
/// listed in `used` as (JSON path, type name).
pub fn expand_hinge_types(
    v: &mut Value,
    types: &Map<String, Value>,
    at: &mut String,
    used: &mut Vec<(String, String)>,
) -> Result<(), CaseError> {
    let len = at.len();
    match v {
        Value::Object(m) => {
            for (k, x) in m.iter_mut() {
                if !at.is_empty() {
                    at.push('.');
                }
                at.push_str(k);
                match x {
                    Value::String(name) if HINGE_FIELDS.contains(&k.as_str()) => {
                        let Some(spec) = types.get(name.as_str()) else {
                            let known: Vec<&str> = types.keys().map(String::as_str).collect();
                            return Err(CaseError::value(
                                at.as_str(),
                                format!("\"{name}\""),
                                if known.is_empty() {
                                    "a hinge given by name needs `hinge_types` {\"NAME\": {<hinge spec>}} (none is declared)".to_string()
                                } else {
                                    format!("not a name of `hinge_types` (declared: {})", known.join(", "))
                                },
                            ));
                        };
                        used.push((at.clone(), std::mem::take(name)));
                        *x = spec.clone();
                    }
                    Value::Object(_) | Value::Array(_) => expand_hinge_types(x, types, at, used)?,
                    _ => {}
                }
                at.truncate(len);
            }
        }
        Value::Array(a) => {
            use std::fmt::Write;
            for (i, x) in a.iter_mut().enumerate() {
                if x.is_object() || x.is_array() {
                    let _ = write!(at, "[{i}]");
                    expand_hinge_types(x, types, at, used)?;
                    at.truncate(len);
                }
            }
        }
        _ => {}
    }
    Ok(())
}

/// A case value resolved: the parameters' values (the case's and its mesh file's) and the
/// mesh file's resolved content, when the case names a JSON mesh file.
#[derive(Debug, Clone, Default)]
pub struct Resolved {
    /// Every declared parameter's value (echoed in results as `parameters`).
    pub parameters: Parameters,
    /// The parameters declared as numbers (the others are expressions of them), by name.
    pub independent: Vec<String>,
    /// The JSON mesh file the case names, read and resolved: (name as written, content).
    pub mesh: Option<(String, Value)>,
    /// Where the values outside the case as written came from (for errors found later).
    pub origins: Origins,
}

/// Resolves a case object in place (see the module docs): takes out `parameters` and
/// `hinge_types`, reads the JSON mesh file the case names (if it can be read: if not, the
/// model reader reports it where it always did), resolves the parameters of both (the case's
/// override the mesh file's) and replaces every hinge-type name and expression by its value.
/// Errors in the mesh file are reported at `mesh`, naming the file and the path inside it.
pub fn resolve_case(value: &mut Value, base: Option<&std::path::Path>) -> Result<Resolved, CaseError> {
    let mesh = read_mesh(value, base);
    resolve_case_in(value, mesh, None)
}

/// The JSON mesh file a case object names, read as written (`None` when it names none, or a
/// `.msh` file, or when it cannot be read: the model reader reports that).
pub fn read_mesh(value: &Value, base: Option<&std::path::Path>) -> Option<(String, Value)> {
    let name = value
        .get("mesh")
        .and_then(Value::as_str)
        .filter(|n| !n.ends_with(".msh"))?;
    super::read_json("mesh", name, base).ok().map(|v| (name.to_string(), v))
}

/// [`resolve_case`] with the mesh file already read ([`read_mesh`]), optionally a step
/// `along` an independent parameter: every number the parameters set moves by the step times
/// its exact derivative ([`tangent`]).
pub fn resolve_case_in(
    value: &mut Value,
    mut mesh: Option<(String, Value)>,
    along: Option<Along<'_>>,
) -> Result<Resolved, CaseError> {
    if !value.is_object() {
        return Ok(Resolved::default());
    }
    let declared = take_declared(value)?;
    let case_types = take_hinge_types(value)?;
    let (mut all, mut types) = (BTreeMap::new(), Map::new());
    if let Some((name, mv)) = &mut mesh {
        let in_mesh = |e: CaseError| in_mesh_file(name, e);
        all = take_declared(mv).map_err(in_mesh)?;
        types = take_hinge_types(mv).map_err(in_mesh)?;
        for d in all.values_mut() {
            d.file = Some(name.clone());
        }
    }
    all.extend(declared);
    let case_type_names: std::collections::BTreeSet<String> = case_types.keys().cloned().collect();
    types.extend(case_types);
    let parameters = resolve_table(&all)?;
    let tangent = along.map(|a| tangent::table(&all, &parameters, a.name)).transpose()?;
    let fill = |t: Template| match (&tangent, along) {
        (Some(d), Some(a)) => t.fill_along(&parameters, d, a.step),
        _ => t.fill(&parameters),
    };
    if !types.is_empty() {
        // Each definition's expressions checked where it is written.
        for (name, spec) in &types {
            Template::new(spec.clone())
                .and_then(|t| t.fill(&parameters))
                .map_err(|e| {
                    let e = e.under(&format!("hinge_types.{name}"));
                    match &mesh {
                        Some((file, _)) if !case_type_names.contains(name) => in_mesh_file(file, e),
                        _ => e,
                    }
                })?;
        }
    }
    // Errors found after resolution at a place the case does not have as written go to the
    // parameter, the hinge type or the mesh file that set the value.
    let mut origins = Origins::default();
    let param_target = |n: Option<&str>| match n {
        Some(n) if all.get(n).is_some_and(|d| d.file.is_none()) => format!("parameters.{n}"),
        _ => "mesh".to_string(),
    };
    let type_target = |n: &str| {
        if case_type_names.contains(n) {
            format!("hinge_types.{n}")
        } else {
            "mesh".to_string()
        }
    };
    let mut used = Vec::new();
    expand_hinge_types(value, &types, &mut String::new(), &mut used)?;
    for (at, name) in &used {
        origins.add(at.clone(), name, type_target(name), None, true);
    }
    let template = Template::new(std::mem::take(value))?;
    for (at, text, first) in template.sites() {
        let in_use = used
            .iter()
            .any(|(u, _)| at.strip_prefix(u.as_str()).is_some_and(|r| r.starts_with('.')));
        if in_use {
            origins.add(at, text, param_target(first), None, false);
        }
    }
    *value = fill(template)?;
    if let Some((name, mv)) = &mut mesh {
        origins.set_mesh(name, value, &["parameters", "hinge_types"], mv);
        let in_mesh = |e: CaseError| in_mesh_file(name, e);
        let mut used = Vec::new();
        expand_hinge_types(mv, &types, &mut String::new(), &mut used).map_err(in_mesh)?;
        for (at, t) in &used {
            origins.add(at.clone(), t, type_target(t), Some(name), true);
        }
        let template = Template::new(std::mem::take(mv)).map_err(in_mesh)?;
        for (at, text, first) in template.sites() {
            origins.add(at, text, param_target(first), Some(name), false);
        }
        *mv = fill(template).map_err(in_mesh)?;
    }
    Ok(Resolved {
        independent: tangent::independent(&all),
        parameters,
        mesh,
        origins,
    })
}

/// An error inside mesh file `name`, reported at `mesh` (by the parameter resolution, the model
/// reader and [`Origins::locate`] alike).
pub(crate) fn in_mesh_file(name: &str, e: CaseError) -> CaseError {
    CaseError::new(
        "mesh",
        format!("in mesh file \"{name}\" at `{}`: {}", e.path, e.message),
    )
}

#[cfg(test)]
mod tests {
    use super::*;

    fn table(v: Value) -> Result<Parameters, CaseError> {
        let mut case = serde_json::json!({ "parameters": v });
        resolve_table(&take_declared(&mut case)?)
    }

    /// Parameters defined by expressions of others, in any order of declaration.
    #[test]
    fn parameters_of_parameters() {
        let p = table(serde_json::json!({"a": "2*$b + $c", "b": "$c/4", "c": 8})).unwrap();
        assert_eq!(p["c"], 8.0);
        assert_eq!(p["b"], 2.0);
        assert_eq!(p["a"], 12.0);
    }

    /// A cycle is refused, listed from the declaration where it starts.
    #[test]
    fn cycles_are_named() {
        let e = table(serde_json::json!({"a": "$b + 1", "b": "2*$c", "c": "$a", "d": 1})).unwrap_err();
        assert_eq!(e.path, "parameters.a");
        assert!(e.message.contains("$a → $b → $c → $a"), "{}", e.message);
        let e = table(serde_json::json!({"x": "$x"})).unwrap_err();
        assert!(e.message.contains("$x → $x"), "{}", e.message);
    }

    /// Unknown names, bad names and values that are neither numbers nor strings.
    #[test]
    fn declaration_errors() {
        let e = table(serde_json::json!({"a": "$zz*2"})).unwrap_err();
        assert_eq!(e.path, "parameters.a");
        assert!(e.message.contains("unknown parameter `$zz`"), "{}", e.message);
        assert_eq!(table(serde_json::json!({"2a": 1})).unwrap_err().path, "parameters.2a");
        assert_eq!(table(serde_json::json!({"a": [1]})).unwrap_err().path, "parameters.a");
        assert_eq!(
            table(serde_json::json!({"a": "1/($b - 1)", "b": 1})).unwrap_err().path,
            "parameters.a"
        );
    }

    /// A hinge field given by name becomes the hinge type's object; an unknown name is refused.
    #[test]
    fn hinge_types_expand() {
        let types: Map<String, Value> =
            serde_json::from_value(serde_json::json!({"flex": {"type": "leaf", "t": "$t"}})).unwrap();
        let mut v = serde_json::json!({"elements": [{"hinge": "flex"}, {"hinge": {"type": "leaf"}}]});
        let mut used = Vec::new();
        expand_hinge_types(&mut v, &types, &mut String::new(), &mut used).unwrap();
        assert_eq!(used, [("elements[0].hinge".to_string(), "flex".to_string())]);
        assert_eq!(
            v["elements"][0]["hinge"],
            serde_json::json!({"type": "leaf", "t": "$t"})
        );
        let mut w = serde_json::json!({"elements": [{"hinge": "flx"}]});
        let e = expand_hinge_types(&mut w, &types, &mut String::new(), &mut Vec::new()).unwrap_err();
        assert_eq!(e.path, "elements[0].hinge");
        assert!(e.message.contains("declared: flex"), "{}", e.message);
    }
}
