//! The `buckling` case through the binary: bad input refused with its JSON path (exit 2),
//! failures with context (exit 1), reversed multipliers flagged, the VTK file of the shapes.

use serde_json::{json, Value};

mod common;

use common::{code, run_case_text, run_in, stderr, stdout, tempdir};

/// Cantilever column (5 beams along x, clamped at node 0), 1 N axial compression at the top.
fn base() -> Value {
    json!({
        "analysis": "buckling",
        "materials": {"steel": "steel"},
        "sections": {"bar": {"shape": "rect", "w": 10, "h": 20}},
        "nodes": [[0, 0, 0], [200, 0, 0], [400, 0, 0], [600, 0, 0], [800, 0, 0], [1000, 0, 0]],
        "elements": (0..5).map(|i| json!({"type": "beam", "nodes": [i, i + 1], "section": "bar", "material": "steel", "up": [0, 0, 1], "shear": false})).collect::<Vec<_>>(),
        "supports": [{"node": 0, "fix": ["ux", "uy", "uz", "rx", "ry", "rz"]}],
        "load_cases": [{"name": "axial", "forces": [{"node": 5, "F": [-1, 0, 0, 0, 0, 0]}]}],
        "modes": 2
    })
}

/// Runs `v` and expects exit `want` with every string of `needles` in stderr.
fn refused(name: &str, v: &Value, want: i32, needles: &[&str]) {
    let out = run_case_text(name, &v.to_string());
    let err = stderr(&out);
    assert_eq!(code(&out), Some(want), "{name}: {err}");
    for n in needles {
        assert!(err.contains(n), "{name}: stderr lacks {n:?}: {err}");
    }
    assert!(!stdout(&out).contains("NaN"), "{name}");
}

#[test]
fn bad_buckling_input_is_refused_with_its_path() {
    let mut v = base();
    v["modes"] = json!(0);
    refused("modes0", &v, 2, &["`modes`", "1 to 1000"]);
    let mut v = base();
    v.as_object_mut().unwrap().remove("modes");
    refused("modes_missing", &v, 2, &["`modes`", "missing"]);
    let mut v = base();
    v["load_cases"] = json!([]);
    refused("no_case", &v, 2, &["`load_cases`", "reference load"]);
    let mut v = base();
    v.as_object_mut().unwrap().remove("load_cases");
    refused("no_case_field", &v, 2, &["`load_cases`"]);
    let mut v = base();
    let lc = v["load_cases"][0].clone();
    v["load_cases"] = json!([lc.clone(), lc]);
    refused("two_cases", &v, 2, &["`load_cases`", "exactly one"]);
    let mut v = base();
    v["nonlinear"] = json!(true);
    refused("nonlinear", &v, 2, &["`nonlinear`"]);
    let mut v = base();
    v["load_cases"][0]["forces"][0]["node"] = json!(9);
    refused("bad_node", &v, 2, &["load_cases[0].forces[0].node"]);
    // A shell: refused naming the case element.
    let mut v = base();
    v["sections"]["plate"] = json!({"shape": "shell", "t": 1.0});
    v["nodes"].as_array_mut().unwrap().push(json!([0, 100, 0]));
    v["nodes"].as_array_mut().unwrap().push(json!([200, 100, 0]));
    v["elements"]
        .as_array_mut()
        .unwrap()
        .push(json!({"type": "shell4", "nodes": [0, 1, 7, 6], "section": "plate", "material": "steel"}));
    refused("shell", &v, 2, &["`elements[5]`", "shell4"]);
}

#[test]
fn failures_carry_context() {
    // A load that stresses nothing (the top node on a ground spring, no beam loaded): no
    // geometric stiffness, exit 1 naming the load case.
    let mut v = base();
    v["nodes"].as_array_mut().unwrap().push(json!([0, 500, 0]));
    v["elements"]
        .as_array_mut()
        .unwrap()
        .push(json!({"type": "spring", "nodes": [6], "k": [1, 1, 1, 1, 1, 1]}));
    v["load_cases"][0]["forces"][0]["node"] = json!(6);
    refused("no_kg", &v, 1, &["load_cases[0]", "no geometric stiffness"]);
    // Unsupported: a mechanism, exit 1 naming a free DOF.
    let mut v = base();
    v["supports"] = json!([{"node": 0, "fix": ["ux", "uy", "uz"]}]);
    refused("mechanism", &v, 1, &["node 0"]);
}

/// A tensile reference load: the multipliers are negative, flagged `reversed` and warned about;
/// `--out` writes the shapes with their load factors.
#[test]
fn reversed_load_and_vtk() {
    let mut v = base();
    v["load_cases"][0]["forces"][0]["F"] = json!([1, 0, 0, 0, 0, 0]);
    let d = tempdir("buckling_reversed");
    std::fs::write(d.join("case.json"), v.to_string()).unwrap();
    let out = run_in(&d, &["run", "case.json", "--out", "o"]);
    assert_eq!(code(&out), Some(0), "{}", stderr(&out));
    let r: Value = serde_json::from_str(&std::fs::read_to_string(d.join("o/result.json")).unwrap()).unwrap();
    let modes = r["buckling"].as_array().unwrap();
    assert_eq!(modes.len(), 2);
    for m in modes {
        assert!(
            m["load_factor"].as_f64().unwrap() < 0.0 && m["reversed"] == json!(true),
            "{m}"
        );
    }
    let warns = r["warnings"].as_array().unwrap();
    assert!(
        warns
            .iter()
            .any(|w| w.as_str().unwrap().contains("reversed reference load")),
        "{warns:?}"
    );
    let vtu = std::fs::read_to_string(d.join("o/buckling_modes.vtu")).unwrap();
    assert!(vtu.contains("load_factor") && vtu.contains("mode_2_translation_mm"));
}
