//! Reading a case file: the text becomes a JSON value, `analysis` picks the kind from the list
//! of kinds ([`super::kinds_list`]), and the rest is deserialised into that kind's case shape
//! with every error under its JSON path.

use super::kinds_list::analyses;
#[allow(unused_imports)]
use crate::analysis::*; // the modules the list's paths start from
use crate::case::params::{self, Parameters};
use crate::case::{from_value, limits, short, CaseError, Source};
use serde_json::Value;
use std::path::Path;

/// The analysis `Self` of one line of the list of kinds: its case inside a parsed [`Case`].
pub trait CaseOf: crate::analysis::Analysis {
    /// The `analysis` name in case files (the line's `"name"`).
    const KIND: &'static str;
    /// The case of this kind inside a parsed case file, if it is one.
    fn case_of(case: &Case) -> Option<&Self::Case>;
    /// [`Self::case_of`], mutable (a sweep sets each design's numbers in its worker's case).
    fn case_of_mut(case: &mut Case) -> Option<&mut Self::Case>;
}

/// The parser of a plain case shape: serde with unknown fields refused, errors under their
/// JSON path.
pub fn shape<T: serde::de::DeserializeOwned>(value: Value, _base: &Source<'_>) -> Result<T, CaseError> {
    from_value(value, "")
}

/// The parser of a line of the list: its `parse PATH`, else [`shape`].
macro_rules! parser {
    () => {
        shape
    };
    ($parse:path) => {
        $parse
    };
}

/// Expands [`analyses!`] into the [`Case`] enum and its dispatch.
macro_rules! case_side {
    ($($(#[$attr:meta])* $variant:ident = $name:literal #$rank:literal, $(mod $module:ident,)? analysis $analysis:path $(, parse $parse:path)?;)*) => {
        /// A parsed case file (not yet validated).
        #[derive(Debug, Clone, schemars::JsonSchema)]
        #[serde(tag = "analysis", rename_all = "snake_case")]
        pub enum Case {
            $(
                $(#[$attr])*
                $variant(<$analysis as Analysis>::Case),
            )*
        }

        /// The `analysis` names this build understands.
        pub const ANALYSES: &[&str] = &{
            let mut names = [""; [$($name),*].len()];
            $(names[$rank] = $name;)*
            names
        };

        impl Case {
            /// The `analysis` name.
            pub fn analysis(&self) -> &'static str {
                match self {
                    $(Case::$variant(_) => $name,)*
                }
            }
        }

        $(
            impl CaseOf for $analysis {
                const KIND: &'static str = $name;
                fn case_of(case: &Case) -> Option<&Self::Case> {
                    match case {
                        Case::$variant(c) => Some(c),
                        #[allow(unreachable_patterns)]
                        _ => None,
                    }
                }
                fn case_of_mut(case: &mut Case) -> Option<&mut Self::Case> {
                    match case {
                        Case::$variant(c) => Some(c),
                        #[allow(unreachable_patterns)]
                        _ => None,
                    }
                }
            }
        )*

        /// The case of kind `analysis` from the rest of its JSON object (`None`: no such kind).
        fn parse_kind(analysis: &str, value: Value, base: &Source<'_>) -> Option<Result<Case, CaseError>> {
            match analysis {
                $($name => Some(parser!($($parse)?)(value, base).map(Case::$variant)),)*
                _ => None,
            }
        }
    };
}

analyses!(case_side);

/// A parsed case with the values of its parameters (see [`crate::case::params`]).
#[derive(Debug, Clone)]
pub struct Parsed {
    /// The case.
    pub case: Case,
    /// Every declared parameter (the case's and its mesh file's) with its resolved value;
    /// results echo them as `parameters`.
    pub parameters: Parameters,
    /// Where values outside the case as written (in its mesh file, in hinges given by type
    /// name) came from.
    pub origins: params::Origins,
}

impl Parsed {
    /// A case error of the parsed case's validation or run moved to where the case file sets
    /// the value ([`params::Origins::locate`]); other errors unchanged.
    pub fn locate(&self, e: CaseError) -> CaseError {
        self.origins.locate(e)
    }

    /// [`Self::locate`] for the error of a run.
    pub fn locate_run(&self, e: crate::analysis::RunError) -> crate::analysis::RunError {
        match e {
            crate::analysis::RunError::Case(c) => crate::analysis::RunError::Case(self.locate(c)),
            other => other,
        }
    }
}

/// Reads and parses a case file; files it refers to (`mesh`) are looked up beside it.
pub fn load(path: &Path) -> Result<Case, CaseError> {
    load_resolved(path).map(|p| p.case)
}

/// [`load`] with the case's parameter values.
pub fn load_resolved(path: &Path) -> Result<Parsed, CaseError> {
    let shown = format!("\"{}\"", path.display());
    let bytes = limits::read_file(".", "case file", &shown, path)?;
    let text = String::from_utf8(bytes).map_err(|e| {
        CaseError::new(
            ".",
            format!("cannot read case file {}: not UTF-8 text ({e})", path.display()),
        )
    })?;
    let value: Value = serde_json::from_str(&text).map_err(|e| CaseError::new(".", format!("not valid JSON: {e}")))?;
    parse_resolved(value, path.parent(), true)
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

/// Parses a case already read as JSON.
pub fn parse_value(value: Value, base: Option<&Path>) -> Result<Case, CaseError> {
    parse_resolved(value, base, true).map(|p| p.case)
}

/// The check of [`parse_value`] that refuses an array given where the schema wants an object
/// (see [`crate::analysis::common::case_shape`]). It depends only on where the case has arrays, so a batch driver
/// whose designs differ from one already checked only in scalar values may skip it
/// ([`parse_resolved`] with `check_arrays` false).
pub fn check_shape(value: &Value) -> Result<(), CaseError> {
    crate::analysis::common::case_shape::refuse_positional(value, schema)
}

/// [`parse_value`] without [`check_shape`], for a value whose arrays were checked already.
pub fn parse_value_shaped(value: Value, base: Option<&Path>) -> Result<Case, CaseError> {
    parse_resolved(value, base, false).map(|p| p.case)
}

/// Parses a case already read as JSON, with its parameter values: resolves parameters,
/// hinge types and expressions ([`params::resolve_case`]), checks the arrays of the resolved
/// value if `check_arrays` ([`check_shape`]) and deserialises it into its kind's shape. A
/// `sweep` case is not resolved: each of its designs is, as a case of its own; nor is a
/// `sensitivity`/`design` of a mesh case (its inner case is resolved per design).
pub fn parse_resolved(mut value: Value, base: Option<&Path>, check_arrays: bool) -> Result<Parsed, CaseError> {
    let resolved = if value.get("analysis").and_then(Value::as_str) == Some("sweep")
        || crate::case::design_mesh::is_mesh_form(&value)
    {
        params::Resolved::default()
    } else {
        let mesh = params::read_mesh(&value, base);
        let written = (value.get("gradients") == Some(&Value::Bool(true))).then(|| params::tangent::Written {
            value: value.clone(),
            mesh: mesh.clone(),
            dir: base.map(Path::to_path_buf),
        });
        let resolved = params::resolve_case_in(&mut value, mesh, None)?;
        if check_arrays && value.is_object() {
            check_shape(&value)?;
        }
        let mut parsed = parse_with(value, base, resolved)?;
        if let (Case::Static(s), Some(w)) = (&mut parsed.case, written) {
            if parsed.parameters.is_empty() {
                return Err(CaseError::value(
                    "gradients",
                    true,
                    "needs \"parameters\" (in the case or its mesh file): the gradients are with respect to them",
                ));
            }
            s.written = Some(std::sync::Arc::new(w));
        }
        return Ok(parsed);
    };
    if check_arrays && value.is_object() {
        check_shape(&value)?;
    }
    parse_with(value, base, resolved)
}

/// The typed parse of a case value resolved as `resolved` says ([`params::resolve_case_in`]).
pub fn parse_with(value: Value, base: Option<&Path>, resolved: params::Resolved) -> Result<Parsed, CaseError> {
    let source = Source::with_mesh(base, resolved.mesh).with_hinge_types(resolved.origins.element_hinge_types());
    let case = parse_shaped(value, &source).map_err(|e| resolved.origins.locate(e))?;
    Ok(Parsed {
        case,
        parameters: resolved.parameters,
        origins: resolved.origins,
    })
}

/// The typed parse of a resolved case value.
fn parse_shaped(mut value: Value, base: &Source<'_>) -> Result<Case, CaseError> {
    if !value.is_object() {
        return Err(CaseError::value(
            ".",
            short(&value),
            "a case file must be a JSON object",
        ));
    }
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

/// What `load_cases` means to each analysis whose model part (the shared mesh fields) carries
/// it: the field's doc comment is written once, on the mesh.
const LOAD_CASES: [(&str, &str); 7] = [
    ("static", "Load cases (at least one, inline or in the mesh file)."),
    (
        "buckling",
        "Exactly one load case: the reference load whose multipliers λ are the results.",
    ),
    (
        "constraints",
        "Load cases: their prescribed displacements (drives) count as constraints; forces are not used.",
    ),
    (
        "modal",
        "Not used by `modal` (accepted, so a `static` model runs unchanged).",
    ),
    (
        "transient",
        "Not used by `transient`: its loads are `loads` and `motions` (accepted, so a `static` model runs unchanged).",
    ),
    (
        "frf",
        "Not used by `frf`: its loads are `inputs` (accepted, so a `static` model runs unchanged).",
    ),
    (
        "craig_bampton",
        "Not used by `craig_bampton` (accepted, so a `static` model runs unchanged).",
    ),
];

/// Sets the `load_cases` description of each analysis' schema from [`LOAD_CASES`].
fn describe_load_cases(schema: &mut Value) {
    let Some(arms) = schema.get_mut("oneOf").and_then(Value::as_array_mut) else {
        return;
    };
    for arm in arms {
        let kind = arm
            .pointer("/properties/analysis/const")
            .and_then(Value::as_str)
            .map(str::to_string);
        let Some((_, text)) = kind.and_then(|k| LOAD_CASES.iter().find(|(a, _)| *a == k)) else {
            continue;
        };
        if let Some(field) = arm.pointer_mut("/properties/load_cases").and_then(Value::as_object_mut) {
            field.insert("description".into(), Value::from(*text));
        }
    }
}

/// The JSON Schema of case files.
pub fn schema() -> Value {
    let mut schema = serde_json::to_value(schemars::schema_for!(Case)).unwrap_or(Value::Null);
    describe_load_cases(&mut schema);
    // The sweep's `base` names any kind but `sweep` (see `crate::case::sweep`).
    let names: Vec<&str> = ANALYSES.iter().copied().filter(|a| *a != "sweep").collect();
    if let Some(defs) = schema.get_mut("$defs").and_then(Value::as_object_mut) {
        defs.insert(
            crate::case::sweep::BASE_KIND_DEF.into(),
            serde_json::json!({"type": "string", "enum": names}),
        );
    }
    schema
}
