//! Case files: serde shapes only, plus validation that names JSON paths.
//!
//! Parsing is two-step so that every error carries its path: the text is read into a JSON
//! value, `analysis` picks the shape, and the rest is deserialised through
//! `serde_path_to_error` with unknown fields refused.

pub mod design;
pub mod error;
pub mod fem_case;
pub mod gmsh;
pub mod hinge;
pub mod kinds;
pub mod kinematics;
pub mod limits;
pub mod material;
pub mod mesh;
pub mod stage;
pub mod sweep;

pub use error::CaseError;
use kinds::case_side;
pub use kinds::OfCase;
pub use material::MaterialSpec;

use serde::de::DeserializeOwned;
use serde_json::Value;
use std::path::{Path, PathBuf};

kinds::analyses!(case_side);

/// Deserialises `value` into `T`, turning serde errors into [`CaseError`]s under `prefix`.
pub fn from_value<T: DeserializeOwned>(value: Value, prefix: &str) -> Result<T, CaseError> {
    serde_path_to_error::deserialize(value).map_err(|e| {
        let path = e.path().to_string();
        CaseError::new(
            if path == "." { String::new() } else { path },
            e.into_inner().to_string(),
        )
        .under(prefix)
    })
}

/// Reads and parses a case file; files it refers to (`mesh`) are looked up beside it.
pub fn load(path: &Path) -> Result<Case, CaseError> {
    let shown = format!("\"{}\"", path.display());
    let bytes = limits::read_file(".", "case file", &shown, path)?;
    let text = String::from_utf8(bytes).map_err(|e| {
        CaseError::new(
            ".",
            format!("cannot read case file {}: not UTF-8 text ({e})", path.display()),
        )
    })?;
    parse_in(&text, path.parent())
}

/// Refuses a model (a JSON object with `nodes`) with more nodes than [`limits::Limits::nodes`],
/// before the nodes are built.
fn check_node_count(field: &str, model: &Value) -> Result<(), CaseError> {
    match model.get("nodes").and_then(Value::as_array) {
        Some(a) => limits::check_nodes(field, a.len()),
        None => Ok(()),
    }
}

/// Parses case-file text (relative file references resolve against the working folder).
pub fn parse(text: &str) -> Result<Case, CaseError> {
    parse_in(text, None)
}

/// Parses case-file text; relative file references resolve against `base` first.
pub fn parse_in(text: &str, base: Option<&Path>) -> Result<Case, CaseError> {
    let value: Value = serde_json::from_str(text).map_err(|e| CaseError::new(".", format!("not valid JSON: {e}")))?;
    parse_value(value, base)
}

/// Resolves a file named in a case: relative to `base` if it exists there, else as given.
pub fn resolve_file(name: &str, base: Option<&Path>) -> PathBuf {
    let p = Path::new(name);
    match base {
        Some(b) if p.is_relative() && b.join(p).exists() => b.join(p),
        _ => p.to_path_buf(),
    }
}

fn read_json(path_field: &str, name: &str, base: Option<&Path>) -> Result<Value, CaseError> {
    let file = resolve_file(name, base);
    let bytes = limits::read_file(path_field, "mesh file", &format!("\"{name}\""), &file)?;
    serde_json::from_slice(&bytes).map_err(|e| {
        CaseError::value(
            path_field,
            format!("\"{name}\""),
            format!("{} is not valid JSON: {e}", file.display()),
        )
    })
}

/// Parses a case already read as JSON.
pub fn parse_value(mut value: Value, base: Option<&Path>) -> Result<Case, CaseError> {
    if !value.is_object() {
        return Err(CaseError::value(
            ".",
            short(&value),
            "a case file must be a JSON object",
        ));
    }
    refuse_positional(&value)?;
    let Value::Object(map) = &mut value else {
        unreachable!("checked above");
    };
    let analysis = match map.remove("analysis") {
        Some(Value::String(s)) => s,
        Some(other) => {
            return Err(CaseError::value(
                "analysis",
                short(&other),
                format!("must be one of {}", ANALYSES.join(", ")),
            ))
        }
        None => {
            return Err(CaseError::new(
                "analysis",
                format!("missing field `analysis`; one of {}", ANALYSES.join(", ")),
            ))
        }
    };
    parse_kind(&analysis, value, base).unwrap_or_else(|| {
        Err(CaseError::value(
            "analysis",
            format!("\"{analysis}\""),
            format!("must be one of {}", ANALYSES.join(", ")),
        ))
    })
}

/// Refuses an array where the case schema allows only an object.
///
/// serde also reads a struct from the array of its field values in declaration order
/// (`"leg": [10, 10]`, `"hinge": ["leaf", 5, 1, …]`). Case files do not take that form: the schema
/// refuses it, and the errors about such a value would name fields (`hinge.t`) that the file
/// does not have.
fn refuse_positional(value: &Value) -> Result<(), CaseError> {
    static SCHEMA: std::sync::OnceLock<Value> = std::sync::OnceLock::new();
    let schema = SCHEMA.get_or_init(schema);
    let defs = schema.get("$defs").and_then(Value::as_object);
    let mut roots = Vec::new();
    expand(schema, defs, &mut roots, 0);
    positional(value, &roots, defs, String::new())
}

/// The schema nodes that `node` stands for: itself if it says something about types, and what
/// its `$ref`, `anyOf`, `oneOf` and `allOf` lead to (`if`/`then`/`else` and `not` are skipped:
/// they only add constraints).
fn expand<'a>(
    node: &'a Value,
    defs: Option<&'a serde_json::Map<String, Value>>,
    out: &mut Vec<&'a Value>,
    depth: usize,
) {
    let Some(m) = node.as_object() else {
        return;
    };
    if depth > 32 {
        return;
    }
    let typed = [
        "type",
        "properties",
        "additionalProperties",
        "items",
        "prefixItems",
        "enum",
        "const",
    ];
    if typed.iter().any(|k| m.contains_key(*k)) {
        out.push(node);
    }
    if let Some(r) = m.get("$ref").and_then(Value::as_str) {
        if let Some(d) = r.strip_prefix("#/$defs/").and_then(|n| defs.and_then(|d| d.get(n))) {
            expand(d, defs, out, depth + 1);
        }
    }
    for k in ["anyOf", "oneOf", "allOf"] {
        for b in m.get(k).and_then(Value::as_array).into_iter().flatten() {
            expand(b, defs, out, depth + 1);
        }
    }
}

fn allows_array(node: &Value) -> bool {
    match node.get("type") {
        Some(Value::String(t)) => t == "array",
        Some(Value::Array(ts)) => ts.iter().any(|t| t == "array"),
        _ => {
            !(node.get("properties").is_some()
                || node.get("additionalProperties").is_some_and(Value::is_object)
                || node.get("enum").is_some()
                || node.get("const").is_some())
        }
    }
}

fn positional(
    value: &Value,
    candidates: &[&Value],
    defs: Option<&serde_json::Map<String, Value>>,
    path: String,
) -> Result<(), CaseError> {
    if candidates.is_empty() {
        return Ok(());
    }
    let mut children: Vec<&Value> = Vec::new();
    match value {
        Value::Array(items) => {
            if !candidates.iter().any(|c| allows_array(c)) {
                return Err(CaseError::value(
                    if path.is_empty() { "." } else { &path },
                    short(value),
                    "an object is expected here: give its fields by name, {\"field\": value, …}",
                ));
            }
            for (i, item) in items.iter().enumerate() {
                children.clear();
                for c in candidates {
                    let node = c
                        .get("prefixItems")
                        .and_then(|p| p.get(i))
                        .or_else(|| c.get("items").filter(|x| x.is_object()));
                    if let Some(n) = node {
                        expand(n, defs, &mut children, 0);
                    }
                }
                positional(item, &children, defs, format!("{path}[{i}]"))?;
            }
        }
        Value::Object(map) => {
            for (k, item) in map {
                children.clear();
                for c in candidates {
                    let node = c
                        .get("properties")
                        .and_then(|p| p.get(k))
                        .or_else(|| c.get("additionalProperties").filter(|x| x.is_object()));
                    if let Some(n) = node {
                        expand(n, defs, &mut children, 0);
                    }
                }
                let p = if path.is_empty() {
                    k.clone()
                } else {
                    format!("{path}.{k}")
                };
                positional(item, &children, defs, p)?;
            }
        }
        _ => {}
    }
    Ok(())
}

/// A value shortened for messages.
pub fn short(v: &Value) -> String {
    let s = v.to_string();
    if s.chars().count() > 60 {
        format!("{}…", s.chars().take(60).collect::<String>())
    } else {
        s
    }
}

/// The JSON Schema of case files.
pub fn schema() -> Value {
    serde_json::to_value(schemars::schema_for!(Case)).unwrap_or(Value::Null)
}
