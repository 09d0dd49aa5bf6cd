//! Warnings where the answer is not to be trusted, each in the JSON `warnings` and in the
//! Markdown report: an element above its allowable stress (named with its load case), a linear
//! run beyond the small-displacement range (a node rotating by more than 5°, an element chord
//! stretching by more than 1 %: run it nonlinear), and a Young's modulus or density implausible
//! in the case-file units (MPa, t/mm³) in every analysis kind that takes a material.
//! Regression: a hinge at utilisation 4.6 and 10.6° of rotation in a linear run, `E: 72` (GPa
//! typed as MPa: 1166° of rotation) and `E: 72e9` (Pa) all ran with `warnings: []`, and only
//! `modal` checked densities.
//!
//! Sources: the hinge's rotation under a moment is linear in the moment (linear statics), so
//! the 5° threshold is placed by scaling the moment of a measured run; the allowable of Al7075
//! is 400 MPa (built-in); E of aluminium 72 000 MPa = 72 GPa = 7.2e10 Pa, density 2810 kg/m³ =
//! 2.81e-9 t/mm³.

use flexfem::analysis::{self, Outcome};
use serde_json::{json, Value};

fn run(case: Value) -> Outcome {
    let c = analysis::parse_value(case, None).unwrap_or_else(|e| panic!("{e}"));
    analysis::run(&c).unwrap_or_else(|e| panic!("{e}"))
}

fn warnings(out: &Outcome) -> Vec<String> {
    let w: Vec<String> = out.json["warnings"]
        .as_array()
        .unwrap()
        .iter()
        .map(|w| w.as_str().unwrap().to_string())
        .collect();
    assert_eq!(w, out.warnings);
    // Every warning is in the report too.
    for x in &w {
        assert!(out.report.markdown.contains(x.as_str()), "not in the report: {x}");
    }
    w
}

/// The warnings containing `what`.
fn with<'a>(w: &'a [String], what: &str) -> Vec<&'a String> {
    w.iter().filter(|x| x.contains(what)).collect()
}

/// A circular-notch hinge (R 8, t, w 10, h 10) clamped at node 0, 40 mm long, moment `m`
/// (N·mm) about its compliant axis at node 1; material `al`.
fn hinge(t: f64, m: f64, al: Value) -> Value {
    json!({
        "analysis": "static",
        "materials": {"al": al},
        "nodes": [[0, 0, 0], [40, 0, 0]],
        "elements": [{"type": "hinge", "nodes": [0, 1], "material": "al", "up": [0, 0, 1],
                      "hinge": {"type": "circular_notch", "R": 8, "t": t, "w": 10, "h": 10}}],
        "supports": [{"node": 0, "fix": ["ux", "uy", "uz", "rx", "ry", "rz"]}],
        "load_cases": [{"name": "moment", "forces": [{"node": 1, "F": [0, 0, 0, 0, m, 0]}]}]
    })
}

fn rotation(out: &Outcome) -> f64 {
    out.json["load_cases"][0]["hinges"][0]["rotation_deg"].as_f64().unwrap()
}

/// A 0.8 mm notch under 2000 N·mm: utilisation 4.6 and 10.6° — both warned, naming element 0
/// and the load case; a 2 mm notch under the same moment (0.77, 1.17°) gives no warning.
#[test]
fn utilisation_above_one_and_large_linear_rotation_are_warned() {
    let out = run(hinge(0.8, 2000.0, json!("Al7075")));
    let w = warnings(&out);
    assert_eq!(w.len(), 2, "{w:?}");
    let over = with(&w, "above its allowable stress");
    assert_eq!(over.len(), 1, "{w:?}");
    assert!(over[0].contains("load_cases[0] (\"moment\")") && over[0].contains("element 0 (hinge)"));
    assert!(over[0].contains("utilisation 4.607"), "{}", over[0]);
    let rot = with(&w, "in a linear run");
    assert_eq!(rot.len(), 1, "{w:?}");
    assert!((rotation(&out) / 10.59 - 1.0).abs() < 1e-3, "{}", rotation(&out));
    assert!(rot[0].contains("node 1 rotates by 10.59°") && rot[0].contains("\"nonlinear\": true"));
    // The summary of the load case carries both.
    let summary = &out.report.markdown[..out.report.markdown.find("## Node displacements").unwrap()];
    assert_eq!(summary.matches("> **Warning**").count(), 2, "{summary}");

    let ok = run(hinge(2.0, 2000.0, json!("Al7075")));
    assert_eq!(warnings(&ok), Vec::<String>::new());
    assert!((ok.json["load_cases"][0]["max_utilisation"]["value"].as_f64().unwrap() / 0.7713 - 1.0).abs() < 1e-3);
}

/// The rotation threshold is 5°: the 2 mm notch (1.1661° per 2000 N·mm) at 4.5° has no
/// warning, at 5.5° it has one (and is still below its allowable).
#[test]
fn linear_rotation_threshold_is_five_degrees() {
    let per = rotation(&run(hinge(2.0, 2000.0, json!("Al7075")))) / 2000.0;
    assert!((per * 2000.0 / 1.16609 - 1.0).abs() < 1e-4, "{per}");
    let below = run(hinge(2.0, 4.5 / per, json!({"E": 72000, "nu": 0.33})));
    assert!((rotation(&below) - 4.5).abs() < 1e-9);
    assert_eq!(warnings(&below), Vec::<String>::new());
    let above = run(hinge(2.0, 5.5 / per, json!({"E": 72000, "nu": 0.33})));
    let w = warnings(&above);
    assert_eq!(w.len(), 1, "{w:?}");
    assert!(w[0].contains("rotates by 5.500°"), "{}", w[0]);
}

/// E typed in GPa (72) and in Pa (7.2e10): each warned at `materials.al.E` with the likely unit
/// and the value in MPa (72000); E: 72 also rotates the hinge 1000× further (1166°), warned as
/// a likely unit slip. A density in kg/m³ (2810) is warned in `static` as in `modal`.
#[test]
fn implausible_modulus_and_density_are_warned_in_static() {
    let gpa = run(hinge(2.0, 2000.0, json!({"E": 72, "nu": 0.33, "allowable": 400})));
    assert!((rotation(&gpa) / 1166.09 - 1.0).abs() < 1e-4, "{}", rotation(&gpa));
    let w = warnings(&gpa);
    let e = with(&w, "materials.al.E = 72 MPa");
    assert_eq!(e.len(), 1, "{w:?}");
    assert!(e[0].contains("GPa") && e[0].contains("72000"), "{}", e[0]);
    let slip = with(&w, "unit slip");
    assert_eq!(slip.len(), 1, "{w:?}");
    assert!(slip[0].contains("rotates by 1166°"), "{}", slip[0]);

    let pa = run(hinge(2.0, 2000.0, json!({"E": 72e9, "nu": 0.33, "density": 2810})));
    let w = warnings(&pa);
    assert_eq!(w.len(), 2, "{w:?}");
    let e = with(&w, "materials.al.E = 7.2e10 MPa");
    assert_eq!(e.len(), 1, "{w:?}");
    assert!(e[0].contains("looks like Pa") && e[0].contains("72000"), "{}", e[0]);
    let rho = with(&w, "materials.al.density");
    assert_eq!(rho.len(), 1, "{w:?}");
    assert!(rho[0].contains("kg/m³") && rho[0].contains("2.810e-9"), "{}", rho[0]);

    let ok = run(hinge(2.0, 2000.0, json!({"E": 72000, "nu": 0.33, "density": 2.81e-9})));
    assert_eq!(warnings(&ok), Vec::<String>::new());
}

/// The same check in the `hinge` analysis (one material, `material`) and in `modal`.
#[test]
fn implausible_modulus_is_warned_in_every_kind_with_a_material() {
    let h = run(json!({
        "analysis": "hinge",
        "material": {"E": 72, "nu": 0.33},
        "hinge": {"type": "circular_notch", "R": 8, "t": 2, "w": 10, "h": 10, "blank_length": 20}
    }));
    let w = warnings(&h);
    assert_eq!(with(&w, "material.E = 72 MPa").len(), 1, "{w:?}");
    let h = run(json!({
        "analysis": "hinge",
        "material": "Al7075",
        "hinge": {"type": "circular_notch", "R": 8, "t": 2, "w": 10, "h": 10, "blank_length": 20}
    }));
    assert_eq!(with(&warnings(&h), "MPa is outside").len(), 0);

    let mut m = hinge(2.0, 0.0, json!({"E": 72e9, "nu": 0.33, "density": 2.81e-9}));
    m["analysis"] = json!("modal");
    m["modes"] = json!(2);
    m.as_object_mut().unwrap().remove("load_cases");
    let w = warnings(&run(m));
    assert_eq!(with(&w, "materials.al.E = 7.2e10 MPa").len(), 1, "{w:?}");
}

/// `stage`: a load case above the allowable is named with the hinge that carries it and its
/// utilisation; the cases within it are not. Source: stage linear statics scale with the
/// forces, so the utilisation of the 60 N case of `cases/ruiz2019_stage.json` is the stage's
/// own σ_max / 400 MPa (Al7075 built-in allowable) = 1/factor_at_allowable, and the 20 N and
/// 40 N cases are at a third and two thirds of it (0.45, 0.89). Regression: the stage ran at
/// utilisation 1.33 with `warnings: []`.
#[test]
fn stage_above_allowable_is_named_with_its_hinge() {
    let text = std::fs::read_to_string("cases/ruiz2019_stage.json").unwrap();
    let out = run(serde_json::from_str(&text).unwrap());
    let w = warnings(&out);
    let over = with(&w, "above the allowable stress");
    assert_eq!(over.len(), 1, "{w:?}");
    let cases = out.json["load_cases"].as_array().unwrap();
    assert_eq!(cases.len(), 3);
    let f60 = &cases[2];
    let smax = f60["max_von_mises"].as_f64().unwrap();
    let utilisation = smax / 400.0;
    assert!((utilisation - 1.335).abs() < 0.002, "utilisation {utilisation}");
    assert!(
        (utilisation * f60["factor_at_allowable"].as_f64().unwrap() - 1.0).abs() < 1e-12,
        "factor_at_allowable"
    );
    let w60 = over[0];
    assert!(
        w60.starts_with("load_cases[2] (\"F60\"): the revolute hinges of legs 1, 2 and 3 are above"),
        "{w60}"
    );
    assert!(w60.contains(&format!("utilisation {utilisation:.3}")), "{w60}");
    assert!(w60.contains("against 400.00 MPa"), "{w60}");
    for (i, k) in [(0, 1.0 / 3.0), (1, 2.0 / 3.0)] {
        let u = cases[i]["max_von_mises"].as_f64().unwrap() / 400.0;
        assert!((u - utilisation * k).abs() < 1e-9 * utilisation, "case {i}: {u}");
    }
}
