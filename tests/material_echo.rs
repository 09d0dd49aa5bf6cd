//! Every result echoes the material it used, with its properties, so a reader of a result file
//! never has to guess which "steel" or "Al7075" a number came from. Built-in properties: Al 7075-T6
//! as in Ruiz et al. (2019), Experimental validation of the kinematic design of 3PRS compliant
//! parallel mechanisms: E 72000 MPa, ν 0.33, ρ 2.81e-9 t/mm³, yield 503, allowable 400 MPa.

use flexfem::analysis::parse;
use flexfem::analysis::run;
use serde_json::Value;
use std::path::PathBuf;

fn root() -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR"))
}

fn run_file(name: &str) -> (Value, String) {
    let c = flexfem::analysis::load(&root().join(name)).unwrap();
    let out = run(&c).unwrap();
    (out.json, out.report.markdown)
}

#[test]
fn hinge_result_echoes_the_built_in_material() {
    let (json, md) = run_file("cases/ruiz2019_hinge_revolute.json");
    let m = &json["material"];
    assert_eq!(m["name"], "Al7075");
    assert_eq!(m["E"].as_f64(), Some(72_000.0));
    assert_eq!(m["nu"].as_f64(), Some(0.33));
    assert_eq!(m["density"].as_f64(), Some(2.81e-9));
    assert_eq!(m["yield"].as_f64(), Some(503.0));
    assert_eq!(m["allowable"].as_f64(), Some(400.0));
    assert!(md.contains("Material: Al7075 (E 72000 MPa, ν 0.33"), "{md}");
}

#[test]
fn stage_result_echoes_the_material() {
    let (json, _) = run_file("cases/ruiz2019_stage.json");
    assert_eq!(json["material"]["name"], "Al7075");
    assert_eq!(json["material"]["allowable"].as_f64(), Some(400.0));
}

#[test]
fn mesh_result_echoes_each_named_material() {
    let (json, md) = run_file("cases/static_cantilever.json");
    assert_eq!(json["materials"]["al"]["name"], "Al7075");
    assert_eq!(json["materials"]["al"]["E"].as_f64(), Some(72_000.0));
    assert!(md.contains("Material: `al` = Al7075"), "{md}");
}

#[test]
fn custom_material_without_strengths_echoes_null_limits() {
    let case = r#"{"analysis": "hinge", "material": {"E": 3300, "nu": 0.33},
        "hinge": {"type": "circular_notch", "R": 8, "t": 2, "w": 10, "h": 10, "blank_length": 20}}"#;
    let c = parse(case).unwrap();
    let out = run(&c).unwrap();
    let m = &out.json["material"];
    assert_eq!(m["name"], "custom");
    assert_eq!(m["E"].as_f64(), Some(3_300.0));
    assert!(m["yield"].is_null() && m["allowable"].is_null(), "{m}");
    assert!(out.report.markdown.contains("allowable unlimited"));
}

/// A material without an allowable stress and a load case that stresses nothing: the report
/// says so in words, never "NaN" or "inf" (the JSON has the documented `null`s).
#[test]
fn stage_report_without_allowable_or_load_has_no_nan_text() {
    let text = std::fs::read_to_string(root().join("cases/ruiz2019_stage.json")).unwrap();
    let mut v: Value = serde_json::from_str(&text).unwrap();
    v["material"] = serde_json::json!({"E": 72000, "nu": 0.33});
    v["load_cases"] = serde_json::json!([{"name": "zero", "actuator_forces": [0, 0, 0]}]);
    let c = flexfem::analysis::parse_value(v, Some(&root().join("cases"))).unwrap();
    let out = run(&c).unwrap();
    for text in [&out.report.markdown, &out.report.csv] {
        for bad in ["NaN", "inf"] {
            assert!(!text.contains(bad), "{bad} in report:\n{text}");
        }
    }
    assert!(out.report.markdown.contains("No allowable stress bounds the stroke"));
    assert!(out.json["load_cases"][0]["T"].is_null());
}
