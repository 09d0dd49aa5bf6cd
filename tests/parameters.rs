//! Case parameters, expressions and named hinge types (`parameters`, `"$NAME"`, `hinge_types`):
//! a parameterised case is the literal case, one parameter drives every hinge, sweeps over
//! `parameters.NAME` of a case whose model is in a mesh file, and the errors of the command line.

mod common;
use common::*;
use flexfem::analysis::{self, Case};
use flexfem::case::sweep::Sweep;
use flexfem::design::sweep::{hash_design, run_design};
use serde_json::{json, Value};

fn read(path: &str) -> Value {
    serde_json::from_str(&std::fs::read_to_string(root().join(path)).unwrap()).unwrap()
}

/// The result JSON of a case value read from `cases/` (relative file names as there), with the
/// parameters echoed as `flexfem run` does.
fn result_of(case: Value) -> Value {
    let parsed = analysis::case_file::parse_resolved(case, Some(&root().join("cases")), true).unwrap();
    let mut out = analysis::run(&parsed.case).unwrap();
    out.echo_parameters(&parsed.parameters);
    out.json
}

/// (a) The bundled parameterised guide with `t` = 1 (the mesh file's default) is the literal
/// `parallelogram_guide.json` (same nodes, hinges and loads written as numbers): every number of
/// the result is identical, bit for bit (compared as text: shortest round-trip form).
#[test]
fn parameterised_case_is_the_literal_case_bit_for_bit() {
    let mut p = read("cases/parallelogram_parameters.json");
    p["parameters"]["t"] = json!(1.0);
    p["load_cases"][0]["name"] = json!("push_x_1N");
    let mut got = result_of(p);
    let echoed = got.as_object_mut().unwrap().remove("parameters").unwrap();
    assert_eq!(
        echoed,
        json!({"B": 40.0, "F": 1.0, "L": 100.0, "R": 5.0, "s": 7.5, "t": 1.0, "w": 10.0})
    );
    let want = result_of(read("cases/parallelogram_guide.json"));
    assert_eq!(got.to_string(), want.to_string());

    // A case without a mesh file: the Ruiz et al. (2019) revolute hinge with R = 4t,
    // blank_length = 10t.
    let literal = read("cases/ruiz2019_hinge_revolute.json");
    let parameterised = json!({
        "analysis": "hinge",
        "material": "Al7075",
        "parameters": {"t": 2, "R": "4*$t", "w": 10},
        "hinge": {"type": "circular_notch", "R": "$R", "t": "$t", "w": "$w", "h": "$w", "blank_length": "10*$t"}
    });
    let mut got = result_of(parameterised);
    assert_eq!(
        got.as_object_mut().unwrap().remove("parameters"),
        Some(json!({"R": 8.0, "t": 2.0, "w": 10.0}))
    );
    assert_eq!(got.to_string(), result_of(literal).to_string());
}

/// (b) One parameter drives all four hinges through `hinge_types`: every parsed hinge has
/// t = `$t`, and under the same force every hinge's rotation grows as t^(-5/2), the
/// Paros–Weisbord compliance of a thin circular notch, C = 9πR^(1/2)/(2Ebt^(5/2)) (Paros &
/// Weisbord (1965), How to design flexure hinges, Machine Design 37:151–156), within 3 %
/// (measured ratio 1.722 against (1/0.8)^2.5 = 1.747: the blank and the solid calibration take
/// the rest).
#[test]
fn one_parameter_drives_every_hinge() {
    let rotations = |t: f64| {
        let mut c = read("cases/parallelogram_parameters.json");
        c["parameters"]["t"] = json!(t);
        let Case::Static(sc) = analysis::parse_value(c.clone(), Some(&root().join("cases"))).unwrap() else {
            panic!("a static case")
        };
        let hinges: Vec<f64> = sc
            .model
            .elements
            .iter()
            .filter_map(|e| match e {
                flexfem::case::mesh::ElementSpec::Hinge { hinge, .. } => hinge["t"].as_f64(),
                _ => None,
            })
            .collect();
        assert_eq!(hinges, [t; 4], "every hinge element takes t from the hinge type");
        let r = result_of(c);
        let rot: Vec<f64> = r["load_cases"][0]["hinges"]
            .as_array()
            .unwrap()
            .iter()
            .map(|h| h["rotation_deg"].as_f64().unwrap())
            .collect();
        rot
    };
    let (thin, thick) = (rotations(0.8), rotations(1.0));
    assert_eq!(thin.len(), 4);
    assert_eq!(thick.len(), 4);
    let want = (1.0f64 / 0.8).powf(2.5);
    for (i, (a, b)) in thin.iter().zip(&thick).enumerate() {
        let ratio = a / b;
        assert!(
            (ratio / want - 1.0).abs() < 0.03,
            "hinge {i}: rotation ratio {ratio}, Paros–Weisbord {want}"
        );
    }
}

fn bundled_sweep() -> Sweep {
    let Case::Sweep(s) = analysis::load(&root().join("cases/parallelogram_parameters_sweep.json")).unwrap() else {
        panic!("a sweep case")
    };
    s.build().unwrap()
}

/// (c) A sweep over `parameters.t` of a case whose model is in a mesh file: each design's row
/// holds the result of running that design as a plain case (the base with `parameters.t` set),
/// parameters echoed included; the four designs differ.
#[test]
fn sweep_over_a_mesh_parameter_equals_plain_runs() {
    let sweep = bundled_sweep();
    assert_eq!(sweep.len(), 4);
    let dir = root().join("cases");
    let mut stiffness = Vec::new();
    for (i, t) in [0.6, 0.8, 1.0, 1.2].into_iter().enumerate() {
        let row = run_design(&sweep, Some(&dir), i);
        assert!(!row.failed, "design {i}: {}", row.line);
        let mut plain = sweep.base.clone();
        plain["parameters"]["t"] = json!(t);
        let want = result_of(plain);
        assert_eq!(row.value["result"].to_string(), want.to_string(), "design {i}");
        assert_eq!(row.value["result"]["parameters"]["t"], json!(t));
        let ux = row.value["result"]["load_cases"][0]["displacements"][8][0]
            .as_f64()
            .unwrap();
        stiffness.push(1.0 / ux);
    }
    assert!(
        stiffness.windows(2).all(|w| w[1] > w[0]),
        "a thicker notch is stiffer: {stiffness:?}"
    );
}

/// (c) The design hash covers the mesh file: editing a default in the mesh file changes every
/// design's hash; the same files give the same hash.
#[test]
fn design_hash_changes_with_the_mesh_file() {
    let d = tempdir("param_hash");
    std::fs::create_dir_all(d.join("cases")).unwrap();
    std::fs::create_dir_all(d.join("meshes")).unwrap();
    let mesh = std::fs::read_to_string(root().join("meshes/parallelogram_parameters.json")).unwrap();
    std::fs::write(d.join("meshes/parallelogram_parameters.json"), &mesh).unwrap();
    let sweep = bundled_sweep();
    let dir = d.join("cases");
    let hashes = || -> Vec<String> {
        (0..sweep.len())
            .map(|i| hash_design(&sweep.design(i).unwrap(), Some(&dir)))
            .collect()
    };
    let before = hashes();
    assert_eq!(before, hashes());
    let edited = mesh.replace("\"R\": 5.0", "\"R\": 5.5");
    assert_ne!(edited, mesh);
    std::fs::write(d.join("meshes/parallelogram_parameters.json"), edited).unwrap();
    let after = hashes();
    assert_eq!(before.len(), after.len());
    for (b, a) in before.iter().zip(&after) {
        assert_ne!(b, a);
    }
}

/// (d) Each error kind exits 2 from `run` and from `check`, naming the JSON path and quoting
/// the expression.
#[test]
fn parameter_errors_exit_2_naming_path_and_expression() {
    let hinge = |params: Value, t: &str| {
        json!({
            "analysis": "hinge",
            "material": "Al7075",
            "parameters": params,
            "hinge": {"type": "circular_notch", "R": 8, "t": t, "w": 10, "h": 10, "blank_length": 20}
        })
        .to_string()
    };
    let cases = [
        (
            "unknown",
            hinge(json!({"t": 2}), "$tt"),
            "`hinge.t`",
            "\"$tt\"",
            "unknown parameter `$tt`",
        ),
        (
            "cycle",
            hinge(json!({"a": "$b", "b": "2*$a"}), "$a"),
            "`parameters.a`",
            "\"$b\"",
            "cycle: $a → $b → $a",
        ),
        (
            "division",
            hinge(json!({"a": 2, "b": 2}), "1/($a - $b)"),
            "`hinge.t`",
            "\"1/($a - $b)\"",
            "division by zero",
        ),
        (
            "non_finite",
            hinge(json!({"a": 1e300}), "$a*$a"),
            "`hinge.t`",
            "\"$a*$a\"",
            "not a finite number",
        ),
        (
            "syntax",
            hinge(json!({"R": 4}), "2*$R +"),
            "`hinge.t`",
            "\"2*$R +\"",
            "syntax error at character 7",
        ),
        (
            "sqrt",
            hinge(json!({"R": 4}), "sqrt(1 - $R)"),
            "`hinge.t`",
            "\"sqrt(1 - $R)\"",
            "sqrt of the negative",
        ),
        (
            "hinge_type",
            json!({"analysis": "hinge", "material": "Al7075", "hinge": "flex"}).to_string(),
            "`hinge`",
            "\"flex\"",
            "hinge_types",
        ),
    ];
    for (name, text, path, expr, why) in cases {
        let d = tempdir(&format!("param_err_{name}"));
        std::fs::write(d.join("c.json"), &text).unwrap();
        for cmd in ["run", "check"] {
            let out = run_in(&d, &[cmd, "c.json"]);
            let err = stderr(&out);
            assert_eq!(out.status.code(), Some(2), "{name} {cmd}: {err}");
            assert!(
                err.contains(&format!("case file error at {path}")),
                "{name} {cmd}: path {path} in {err}"
            );
            assert!(
                err.contains(expr) && err.contains(why),
                "{name} {cmd}: {expr} / {why} in {err}"
            );
            assert!(!err.contains("panicked"), "{name}: {err}");
        }
    }
}

/// (d) An error inside the mesh file names `mesh`, the file and the path inside it.
#[test]
fn mesh_file_expression_errors_name_the_file() {
    let d = tempdir("param_mesh_err");
    let mesh = read("meshes/parallelogram_parameters.json");
    let mut bad = mesh.clone();
    bad["nodes"][3][1] = json!("$L + $ss");
    std::fs::write(d.join("m.json"), bad.to_string()).unwrap();
    let case = json!({"analysis": "static", "mesh": "m.json",
        "load_cases": [{"name": "x", "forces": [{"node": 8, "F": [1, 0, 0, 0, 0, 0]}]}]});
    std::fs::write(d.join("c.json"), case.to_string()).unwrap();
    let out = run_in(&d, &["run", "c.json"]);
    let err = stderr(&out);
    assert_eq!(out.status.code(), Some(2), "{err}");
    assert!(
        err.contains("case file error at `mesh`") && err.contains("nodes[3][1]") && err.contains("\"$L + $ss\""),
        "{err}"
    );
}

/// A value that fails validation inside the mesh file, set by a case parameter through a hinge
/// type, is reported at the parameter (`parameters.t`), naming the place in the mesh file and
/// the expression; the same from `check`, `run` and a sweep design's error row.
#[test]
fn validation_errors_of_parameter_values_name_the_parameter() {
    let d = tempdir("param_locate");
    let mut case = read("cases/parallelogram_parameters.json");
    case["mesh"] = json!(root().join("meshes/parallelogram_parameters.json"));
    case["parameters"]["t"] = json!(0.0);
    std::fs::write(d.join("c.json"), case.to_string()).unwrap();
    for cmd in ["check", "run"] {
        let out = run_in(&d, &[cmd, "c.json"]);
        let err = stderr(&out);
        assert_eq!(out.status.code(), Some(2), "{cmd}: {err}");
        assert!(
            err.contains("case file error at `parameters.t`")
                && err.contains("elements[0].hinge.t")
                && err.contains("\"$t\"")
                && err.contains("value 0 is not allowed"),
            "{cmd}: {err}"
        );
    }
    let mut sweep = bundled_sweep();
    sweep.axes[0].1[0] = json!(0.0);
    let row = run_design(&sweep, Some(&root().join("cases")), 0);
    assert!(row.failed);
    let msg = row.value["error"].as_str().unwrap();
    assert!(msg.starts_with("parameters.t: at `elements[0].hinge.t`"), "{msg}");
}
