//! The bundled parameterised pan-tilt (`meshes/pantilt_8r_parameters.json`: the 8 hinges of
//! `meshes/pantilt_8r.json` as one `hinge_types` entry driven by `$t` and `$R`, the platform
//! height `$H` moving four nodes) and its sweep (`cases/pantilt_8r_parameters_sweep.json`).
//!
//! Sources of the expectations: the literal mesh file (the parameterised one at its defaults
//! must be the same model, bit for bit), and the bending stress of a leaf σ = 6M/(w t²)
//! (S. T. Smith, Flexures: Elements of Elastic Mechanisms, Gordon and Breach, 2000, ch. 2):
//! every hinge thinned alike carries nearly the same moment, so the peak utilisation scales
//! as 1/t².

mod common;
use common::*;
use flexfem::analysis::{self, Case};
use flexfem::design::sweep::run_design;
use serde_json::{json, Value};

fn sweep() -> flexfem::case::sweep::Sweep {
    let Case::Sweep(s) = analysis::load(&root().join("cases/pantilt_8r_parameters_sweep.json")).unwrap() else {
        panic!("a sweep case")
    };
    s.build().unwrap()
}

/// Design `i`'s result.
fn design(s: &flexfem::case::sweep::Sweep, i: usize) -> Value {
    let row = run_design(s, Some(&root().join("cases")), i);
    assert!(!row.failed, "design {i}: {}", row.line);
    row.value["result"].clone()
}

/// The design t = 0.6, R = 1.75, H = 70 (the mesh file's defaults, design 9) gives the load
/// case of the literal `meshes/pantilt_8r.json` under the same moment, every number identical.
#[test]
fn parameterised_pantilt_at_its_defaults_is_the_literal_mesh() {
    let s = sweep();
    assert_eq!(s.len(), 18);
    let p = &s.params(9);
    assert_eq!(
        (
            p["parameters.t"].as_f64(),
            p["parameters.R"].as_f64(),
            p["parameters.H"].as_f64()
        ),
        (Some(0.6), Some(1.75), Some(70.0))
    );
    let got = design(&s, 9);
    let mut literal = s.base.clone();
    literal["mesh"] = json!("../meshes/pantilt_8r.json");
    literal.as_object_mut().unwrap().remove("parameters");
    literal["load_cases"][0]["forces"][0]["F"] = json!([0, 0, 0, 10.0, 10.0, 0]);
    let parsed = analysis::case_file::parse_resolved(literal, Some(&root().join("cases")), true).unwrap();
    let want = analysis::run(&parsed.case).unwrap().json;
    assert_eq!(got["load_cases"].to_string(), want["load_cases"].to_string());
}

/// Peak utilisation at t = 0.5 and 0.6 against t = 0.8 (R = 1.25, H = 65): the 1/t² of a
/// leaf's bending stress within 6 % (measured 2.65 % and 1.66 % low after the corner hinges'
/// fillets got the short-notch factor; 4.4 % and 2.4 % were quoted here before: the moment
/// shares shift a little as the hinges stiffen against the links).
#[test]
fn peak_utilisation_scales_as_one_over_t_squared() {
    let s = sweep();
    // Row-major, H fastest: t index × 6 + R index × 2 + H index.
    let util = |i: usize| {
        design(&s, i)["load_cases"][0]["max_utilisation"]["value"]
            .as_f64()
            .unwrap()
    };
    let thick = util(12);
    for (i, t) in [(0, 0.5), (6, 0.6)] {
        let ratio = util(i) / thick;
        let want = (0.8f64 / t).powi(2);
        eprintln!(
            "t = {t}: ratio {ratio:.4}, 1/t² {want:.4} ({:+.2} %)",
            100.0 * (ratio / want - 1.0)
        );
        assert!(
            (ratio / want - 1.0).abs() < 0.06,
            "t = {t}: ratio {ratio}, 1/t² gives {want}"
        );
    }
}

/// Regression (found by `tests/fuzz.rs` on the bundled sweep with `parameters.H` = 2⁶⁴ − 1): an
/// element of the mesh file's model made too short for the model's size by parameter-driven
/// node coordinates was reported at `elements[0].nodes`, a path the case file does not have; it
/// is reported at `mesh`, naming the file and the path inside it.
#[test]
fn mesh_model_error_from_parameters_is_reported_at_mesh() {
    let mut case = sweep().base.clone();
    case["parameters"]["H"] = json!(1.8446744073709552e19);
    let parsed = analysis::case_file::parse_resolved(case, Some(&root().join("cases")), true).unwrap();
    let e = match parsed.locate_run(analysis::run(&parsed.case).map(|_| ()).unwrap_err()) {
        analysis::RunError::Case(e) => e,
        other => panic!("a case error, not {other}"),
    };
    assert_eq!(e.path, "mesh");
    assert!(
        e.message.contains("pantilt_8r_parameters.json") && e.message.contains("`elements[0].nodes`"),
        "{}",
        e.message
    );
}
