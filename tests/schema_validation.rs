//! `flexfem schema` checked with an independent JSON Schema validator (the `jsonschema` crate,
//! draft 2020-12, the dialect the schema declares):
//!
//! * every bundled case in `cases/` validates;
//! * every case of the invalid corpus `tests/data/invalid_cases/*.json` (why each is invalid:
//!   `tests/data/invalid_cases/WHY.json`) is refused by `flexfem check` with exit code 2, and the
//!   schema refuses every one whose error a JSON Schema can express. The others (cross-field or
//!   cross-reference rules) are listed in [`NOT_EXPRESSIBLE`] with the reason; the schema must
//!   accept those (so the list stays honest).

mod common;

use serde_json::Value;
use std::collections::BTreeMap;
use std::path::{Path, PathBuf};
use std::process::Command;

/// Corpus cases whose error a JSON Schema cannot express, with the reason.
const NOT_EXPRESSIBLE: &[(&str, &str)] = &[
    ("static_tube_wall_too_thick.json", "t < d/2 relates two fields"),
    (
        "static_node_index_out_of_range.json",
        "a node index must be < the length of `nodes`",
    ),
    (
        "static_unknown_section_ref.json",
        "a section name must be a key of `sections`",
    ),
    (
        "static_beam_up_parallel.json",
        "`up` must not be parallel to the axis between two nodes' coordinates",
    ),
    (
        "static_metric_parasitic_on_driven_dof.json",
        "whether the load case drives a node's DOF relates a metric to a load case",
    ),
    (
        "static_metric_buckling_margin_missing_load_case.json",
        "a load case name must be the name of one of `load_cases`",
    ),
    (
        "kinematics_fkp_stroke_exceeds_L.json",
        "|s| <= L relates a query to the mechanism",
    ),
    (
        "kinematics_workspace_reversed_range.json",
        "min <= max within one array",
    ),
    ("hinge_t_ge_h.json", "t < h relates two fields"),
    ("hinge_corner_R_too_large.json", "R <= l/2 relates two fields"),
    (
        "stage_hinges_do_not_fit.json",
        "the hinge lengths (computed) must fit in the leg length L",
    ),
    ("design_bounds_reversed.json", "min <= max within one array"),
    ("sweep_path_missing.json", "a varied path must exist in `base`"),
];

fn root() -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR"))
}

fn read_json(p: &Path) -> Value {
    let text = std::fs::read_to_string(p).unwrap_or_else(|e| panic!("{}: {e}", p.display()));
    serde_json::from_str(&text).unwrap_or_else(|e| panic!("{}: {e}", p.display()))
}

/// The schema exactly as the binary prints it.
fn schema() -> Value {
    let out = Command::new(env!("CARGO_BIN_EXE_flexfem"))
        .arg("schema")
        .output()
        .expect("run flexfem schema");
    assert!(out.status.success(), "flexfem schema failed: {:?}", out);
    serde_json::from_slice(&out.stdout).expect("flexfem schema prints JSON")
}

fn validator() -> jsonschema::Validator {
    let s = schema();
    assert_eq!(
        s["$schema"], "https://json-schema.org/draft/2020-12/schema",
        "the schema declares its dialect"
    );
    // Building the validator also checks the schema against the 2020-12 meta-schema.
    jsonschema::draft202012::options()
        .should_validate_formats(false)
        .build(&s)
        .unwrap_or_else(|e| panic!("flexfem schema is not a valid JSON Schema: {e}"))
}

fn json_files(dir: &Path) -> Vec<PathBuf> {
    let mut v: Vec<PathBuf> = std::fs::read_dir(dir)
        .unwrap_or_else(|e| panic!("{}: {e}", dir.display()))
        .map(|e| e.unwrap().path())
        .filter(|p| p.extension().is_some_and(|x| x == "json"))
        .collect();
    v.sort();
    v
}

fn name(p: &Path) -> String {
    p.file_name().unwrap().to_string_lossy().into_owned()
}

#[test]
fn every_bundled_case_validates() {
    let v = validator();
    let files = json_files(&root().join("cases"));
    assert!(files.len() >= 19, "bundled cases found: {}", files.len());
    let mut bad = Vec::new();
    for f in &files {
        let mut case = read_json(f);
        // Parameters, expressions and hinge types are resolved before validation (the schema
        // describes the resolved case: numbers where numbers go).
        // A sensitivity/design of a mesh case is not resolved as a whole either: its inner case
        // is, once per design.
        if case.get("analysis").and_then(Value::as_str) != Some("sweep")
            && !flexfem::case::design_mesh::is_mesh_form(&case)
        {
            flexfem::case::params::resolve_case(&mut case, f.parent()).unwrap_or_else(|e| panic!("{}: {e}", name(f)));
        }
        let errors: Vec<String> = v
            .iter_errors(&case)
            .map(|e| format!("{e} at {}", e.instance_path()))
            .collect();
        if !errors.is_empty() {
            bad.push(format!("{}: {}", name(f), errors.join("; ")));
        }
    }
    assert!(bad.is_empty(), "bundled cases the schema refuses:\n{}", bad.join("\n"));
}

#[test]
fn invalid_corpus_is_refused_by_flexfem_and_by_the_schema() {
    let v = validator();
    let dir = root().join("tests/data/invalid_cases");
    let why: BTreeMap<String, String> =
        serde_json::from_value(read_json(&dir.join("WHY.json"))).expect("WHY.json: name → reason");
    let files: Vec<PathBuf> = json_files(&dir).into_iter().filter(|p| name(p) != "WHY.json").collect();
    assert!(
        files.len() >= 30,
        "the corpus has {} cases, at least 30 wanted",
        files.len()
    );
    let names: Vec<String> = files.iter().map(|p| name(p)).collect();
    for n in &names {
        assert!(why.contains_key(n), "{n} has no reason in WHY.json");
    }
    for n in why.keys() {
        assert!(names.contains(n), "WHY.json lists {n}, which is not in the corpus");
    }
    for (n, _) in NOT_EXPRESSIBLE {
        assert!(
            names.contains(&n.to_string()),
            "NOT_EXPRESSIBLE lists {n}, which is not in the corpus"
        );
    }
    let mut failures = Vec::new();
    let mut expressible = 0;
    for f in &files {
        let n = name(f);
        // flexfem itself refuses it as a case-file error (exit 2) naming a JSON path.
        let out = Command::new(env!("CARGO_BIN_EXE_flexfem"))
            .arg("check")
            .arg(f)
            .output()
            .expect("run flexfem check");
        let stderr = String::from_utf8_lossy(&out.stderr);
        if out.status.code() != Some(2) || !stderr.contains("case file error at `") {
            failures.push(format!(
                "{n}: flexfem check gave {:?}, stderr {stderr}",
                out.status.code()
            ));
        }
        let case = read_json(f);
        let schema_ok = v.is_valid(&case);
        match NOT_EXPRESSIBLE.iter().find(|(m, _)| *m == n) {
            Some((_, reason)) => {
                if !schema_ok {
                    failures.push(format!(
                        "{n} is listed as not expressible ({reason}) but the schema refuses it: move it out of NOT_EXPRESSIBLE"
                    ));
                }
            }
            None => {
                expressible += 1;
                if schema_ok {
                    failures.push(format!("{n}: the schema accepts it ({})", why[&n]));
                }
            }
        }
    }
    assert!(failures.is_empty(), "{}", failures.join("\n"));
    assert!(expressible >= 30, "schema-expressible corpus cases: {expressible}");
}

/// Descriptions are written for users: no references to internal documents or seed papers by
/// number, no Rust intra-doc links.
#[test]
fn descriptions_use_no_internal_wording() {
    fn walk(v: &Value, path: &str, bad: &mut Vec<String>) {
        match v {
            Value::Object(m) => {
                for (k, x) in m {
                    if k == "description" {
                        if let Value::String(d) = x {
                            for word in ["SPEC", "INTERFACE", "seed", "[`", "super::", "crate::"] {
                                if d.contains(word) {
                                    bad.push(format!("{path}: {word:?} in {d:?}"));
                                }
                            }
                        }
                    }
                    walk(x, &format!("{path}/{k}"), bad);
                }
            }
            Value::Array(a) => {
                for (i, x) in a.iter().enumerate() {
                    walk(x, &format!("{path}/{i}"), bad);
                }
            }
            _ => {}
        }
    }
    let mut bad = Vec::new();
    walk(&schema(), "#", &mut bad);
    assert!(
        bad.is_empty(),
        "internal wording in schema descriptions:\n{}",
        bad.join("\n")
    );
}

/// The built-in material names are an enumeration (editors offer them), and any letter case
/// is accepted as flexfem does.
#[test]
fn material_names_are_enumerated() {
    let v = validator();
    let hinge = |m: Value| {
        serde_json::json!({
            "analysis": "hinge", "material": m,
            "hinge": {"type": "circular_notch", "R": 8, "t": 2, "w": 10, "h": 10, "blank_length": 20}
        })
    };
    for ok in ["Al7075", "nylon66", "steel", "AL7075", "Steel", "Ti6Al4V", "ti6al4v"] {
        assert!(v.is_valid(&hinge(ok.into())), "{ok} refused");
        assert!(
            flexfem::analysis::parse(&hinge(ok.into()).to_string()).is_ok(),
            "{ok} refused by flexfem"
        );
    }
    for bad in ["Al 7075", "titanium", ""] {
        assert!(!v.is_valid(&hinge(bad.into())), "{bad:?} accepted by the schema");
        let c = flexfem::analysis::parse(&hinge(bad.into()).to_string()).unwrap();
        assert!(flexfem::analysis::check(&c).is_err(), "{bad:?} accepted by flexfem");
    }
    let s = schema().to_string();
    assert!(
        s.contains(r#""enum":["Al7075","nylon66","steel","Ti6Al4V"]"#),
        "no enum of built-in names"
    );
}

/// An unknown top-level field of a static or modal case is refused with the full list of the
/// fields such a case takes (before: only the model fields, not `mesh`, `nonlinear`…).
#[test]
fn unknown_static_or_modal_field_lists_every_accepted_field() {
    let static_case = serde_json::json!({"analysis": "static", "nodes": [[0, 0, 0]], "nonlinar": true});
    let e = flexfem::analysis::parse(&static_case.to_string()).unwrap_err();
    assert_eq!(e.path, "nonlinar");
    let fields = "analysis mesh gmsh nonlinear steps materials sections nodes elements rigid_links supports load_cases";
    for f in fields.split(' ') {
        assert!(
            e.message.contains(&format!("`{f}`")),
            "`{f}` missing from: {}",
            e.message
        );
    }
    let modal_case = serde_json::json!({"analysis": "modal", "modes": 2, "nodes": [[0, 0, 0]], "steps": 3});
    let e = flexfem::analysis::parse(&modal_case.to_string()).unwrap_err();
    assert_eq!(e.path, "steps");
    for f in ["modes", "shift_hz", "mesh", "gmsh", "nodes", "load_cases"] {
        assert!(
            e.message.contains(&format!("`{f}`")),
            "`{f}` missing from: {}",
            e.message
        );
    }
    assert!(
        e.message.contains("static"),
        "no hint that `steps` is for static: {}",
        e.message
    );
}

/// serde would read a struct from the array of its field values (`"leg": [10, 10]`); flexfem
/// refuses that form, as the schema does, naming the array's own path (before: the case ran, or
/// an error named a field such as `hinge.R` that the file does not have).
#[test]
fn positional_arrays_for_objects_are_refused_like_the_schema_does() {
    let v = validator();
    let stage = |leg: Value| {
        let mut case = common::fixtures::ruiz2019_stage_json();
        case["stage"]["leg"] = leg;
        case
    };
    let named = stage(serde_json::json!({"w": 10, "h": 10}));
    assert!(v.is_valid(&named));
    assert!(flexfem::analysis::parse(&named.to_string()).is_ok());
    let positional = stage(serde_json::json!([10, 10]));
    assert!(!v.is_valid(&positional));
    let e = flexfem::analysis::parse(&positional.to_string()).unwrap_err();
    assert_eq!(e.path, "stage.leg", "{e}");
    let hinge = serde_json::json!({"analysis": "hinge", "hinge": ["corner_filleted", 5, 15, 0.6, 10, 15, 15]});
    assert!(!v.is_valid(&hinge));
    let e = flexfem::analysis::parse(&hinge.to_string()).unwrap_err();
    assert_eq!(e.path, "hinge", "{e}");
    let section = serde_json::json!({
        "analysis": "static", "sections": {"leg": ["rect", 10, 10]}, "nodes": [[0, 0, 0]],
        "load_cases": [{"name": "x"}]
    });
    assert!(!v.is_valid(&section));
    let e = flexfem::analysis::parse(&section.to_string()).unwrap_err();
    assert_eq!(e.path, "sections.leg", "{e}");
}

/// Each analysis' `load_cases` says what that analysis does with them: before, every mesh-based
/// analysis repeated the `static` text ("`static`: at least one … `modal` ignores them").
#[test]
fn load_cases_description_is_the_analysis_own() {
    let s = schema();
    let arms = s["oneOf"].as_array().unwrap();
    let described = |kind: &str| -> String {
        let arm = arms
            .iter()
            .find(|a| a["properties"]["analysis"]["const"] == kind)
            .unwrap();
        arm["properties"]["load_cases"]["description"]
            .as_str()
            .unwrap()
            .to_string()
    };
    let mut texts = std::collections::BTreeSet::new();
    for (kind, needle) in [
        ("static", "at least one"),
        ("modal", "Not used by `modal`"),
        ("transient", "`loads` and `motions`"),
        ("frf", "`inputs`"),
        ("buckling", "reference load"),
        ("constraints", "prescribed displacements"),
        ("craig_bampton", "Not used by `craig_bampton`"),
    ] {
        let d = described(kind);
        assert!(d.contains(needle), "{kind}: {d}");
        texts.insert(d);
    }
    assert_eq!(texts.len(), 7, "two analyses share a load_cases text: {texts:?}");
    // The transient load and the frf input document `F` and its aliases.
    let defs = &s["$defs"];
    let with_alias = defs.as_object().unwrap().values().filter(|d| {
        let p = &d["properties"];
        p.get("F").is_some()
            && p.get("force").is_some()
            && p["force"]["description"]
                .as_str()
                .is_some_and(|t| t.contains("Alias of `F`"))
    });
    assert_eq!(with_alias.count(), 2, "the transient load and the frf input");
}
