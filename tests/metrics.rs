//! `"metrics"` of `static` cases: named stiffness, compliance, displacement, hinge rotation and
//! utilisation values, checked against closed forms and against the result fields they name;
//! bad requests are refused at parse time with their JSON path.
//!
//! Sources: Timoshenko cantilever tip compliance L³/(3EI) + L/(κGA), κ = 10(1+ν)/(12+11ν) for a
//! rectangle (Cowper 1966, J. Appl. Mech. 33(2):335–340), tip rotation per moment L/(EI)
//! (Gere & Timoshenko, Mechanics of Materials, cantilever table); linear statics: a unit force's
//! displacement is the compliance's diagonal term.

use flexfem::analysis;
use serde_json::{json, Value};

fn run(case: Value) -> Value {
    let c = analysis::parse_value(case, None).unwrap_or_else(|e| panic!("{e}"));
    analysis::run(&c).unwrap_or_else(|e| panic!("{e}")).json
}

fn refused(case: Value) -> String {
    match analysis::parse_value(case, None) {
        Ok(_) => panic!("accepted"),
        Err(e) => e.to_string(),
    }
}

const E: f64 = 200_000.0;
const NU: f64 = 0.3;
const L: f64 = 50.0;
const A: f64 = 3.0;

/// A steel cantilever of a 3×3 mm square section, L = 50 mm along x, clamped at node 0, a 1 N
/// force along z at the tip (node 1), with `metrics`.
fn cantilever(metrics: Value) -> Value {
    json!({
        "analysis": "static",
        "materials": {"steel": {"E": E, "nu": NU}},
        "sections": {"sq": {"shape": "rect", "w": A, "h": A}},
        "nodes": [[0, 0, 0], [L, 0, 0]],
        "elements": [{"type": "beam", "nodes": [0, 1], "section": "sq", "material": "steel", "up": [0, 0, 1]}],
        "supports": [{"node": 0, "fix": ["ux", "uy", "uz", "rx", "ry", "rz"]}],
        "load_cases": [{"name": "tip", "forces": [{"node": 1, "F": [0, 0, 1, 0, 0, 0]}]}],
        "metrics": metrics
    })
}

#[test]
fn cantilever_tip_stiffness_and_compliance_match_timoshenko() {
    let out = run(cantilever(json!([
        {"name": "k_z", "kind": "stiffness", "node": 1, "dof": "uz"},
        {"name": "c_ry", "kind": "compliance", "node": 1, "dof": "ry"},
        {"name": "k_root", "kind": "stiffness", "node": 0, "dof": "uz"},
        {"name": "w_tip", "kind": "displacement", "node": 1, "dof": "uz", "load_case": "tip"},
        {"name": "u", "kind": "max_utilisation", "load_case": "tip"}
    ])));
    let m = &out["metrics"];
    let keys: Vec<&String> = m.as_object().unwrap().keys().collect();
    assert_eq!(keys.len(), 5, "{m}");
    let i = A.powi(4) / 12.0;
    let g = E / (2.0 * (1.0 + NU));
    let kappa = 10.0 * (1.0 + NU) / (12.0 + 11.0 * NU);
    let c_z = L.powi(3) / (3.0 * E * i) + L / (kappa * g * A * A);
    let k_z = m["k_z"].as_f64().unwrap();
    assert!((k_z * c_z - 1.0).abs() < 1e-9, "k_z {k_z} N/mm vs {}", 1.0 / c_z);
    let c_ry = m["c_ry"].as_f64().unwrap();
    assert!((c_ry / (L / (E * i)) - 1.0).abs() < 1e-9, "c_ry {c_ry} rad/(N·mm)");
    // The clamped node: compliance 0, stiffness unbounded (null).
    assert!(m["k_root"].is_null(), "{m}");
    // A unit force's displacement is the compliance.
    let w = m["w_tip"].as_f64().unwrap();
    assert_eq!(w, out["load_cases"][0]["displacements"][1][2].as_f64().unwrap());
    assert!((w / c_z - 1.0).abs() < 1e-9, "w {w} mm vs {c_z}");
    // No allowable stress in a custom material without one: null, as the load case's own field.
    assert!(
        m["u"].is_null() && out["load_cases"][0]["max_utilisation"].is_null(),
        "{m}"
    );
}

/// The parallelogram of notch hinges: its lateral stiffness is the inverse of the ux term of
/// the compliance block the case asks for, and the 1 N push moves it by that compliance; the
/// hinge rotation and utilisation metrics are the load case's own fields.
#[test]
fn parallelogram_lateral_stiffness_matches_its_compliance_block() {
    let mut case: Value =
        serde_json::from_str(&std::fs::read_to_string("cases/parallelogram_guide.json").unwrap()).unwrap();
    case["mesh"] = json!("meshes/parallelogram_notch.json");
    case["compliance"] = json!([{"node": 8}]);
    case["metrics"] = json!([
        {"name": "k_lat", "kind": "stiffness", "node": 8, "dof": "ux"},
        {"name": "theta0", "kind": "hinge_rotation", "element": 0, "load_case": "stroke_1mm"},
        {"name": "util", "kind": "max_utilisation", "load_case": "stroke_1mm"},
        {"name": "push", "kind": "displacement", "node": 8, "dof": "ux", "load_case": "push_x_1N"}
    ]);
    let out = run(case);
    let m = &out["metrics"];
    let c = out["compliance"][0]["matrix"][0][0].as_f64().unwrap();
    let k = m["k_lat"].as_f64().unwrap();
    assert!((k * c - 1.0).abs() < 1e-12, "k_lat {k} N/mm, compliance {c} mm/N");
    assert!((m["push"].as_f64().unwrap() / c - 1.0).abs() < 1e-9, "{m}");
    let lc = &out["load_cases"][1];
    let h0 = lc["hinges"]
        .as_array()
        .unwrap()
        .iter()
        .find(|h| h["element"] == 0)
        .unwrap();
    assert_eq!(m["theta0"], h0["rotation_deg"]);
    assert!(h0["rotation_deg"].as_f64().unwrap().abs() > 0.1, "{h0}");
    assert_eq!(m["util"], lc["max_utilisation"]["value"]);
}

#[test]
fn bad_metric_requests_name_their_path() {
    let cases = [
        (
            json!([{"name": "a", "kind": "stiffness", "node": 7, "dof": "ux"}]),
            "metrics[0].node",
            "below 2",
        ),
        (
            json!([{"name": "a", "kind": "stiffness", "node": 1, "dof": "uw"}]),
            "metrics[0].dof",
            "ux, uy, uz",
        ),
        (
            json!([{"name": "a", "kind": "displacement", "node": 1, "dof": "ux", "load_case": "push"}]),
            "metrics[0].load_case",
            "tip",
        ),
        (
            json!([{"name": "a", "kind": "compliance", "node": 1, "dof": "ux"},
                   {"name": "a", "kind": "stiffness", "node": 1, "dof": "ux"}]),
            "metrics[1].name",
            "metrics[0] has the same name",
        ),
        (
            json!([{"name": "a", "kind": "hinge_rotation", "element": 0, "load_case": "tip"}]),
            "metrics[0].element",
            "hinge",
        ),
        (
            json!([{"name": "a", "kind": "stiffness", "node": 1}]),
            "metrics[0].dof",
            "required",
        ),
        (
            json!([{"name": "a", "kind": "max_utilisation", "load_case": "tip", "node": 1}]),
            "metrics[0].node",
            "not used",
        ),
    ];
    for (metrics, path, why) in cases {
        let e = refused(cantilever(metrics));
        assert!(e.contains(path) && e.contains(why), "{e}");
    }
}

/// The parallelogram guide, linear: the stroke at the allowable is the hand value allowable /
/// (σ per mm of stroke) from its own 1 mm load case, with the load scaled the same way and the
/// limiting hinge named; driven by the 1 N force instead, the same stroke and load (linear
/// statics: prescribing ux alone, the other DOFs free, is the same as applying its reaction).
#[test]
fn parallelogram_stroke_at_allowable_is_the_linear_hand_value() {
    let mut case: Value =
        serde_json::from_str(&std::fs::read_to_string("cases/parallelogram_guide.json").unwrap()).unwrap();
    case["mesh"] = json!("meshes/parallelogram_notch.json");
    case["metrics"] = json!([
        {"name": "stroke", "kind": "stroke_at_allowable", "node": 8, "dof": "ux", "load_case": "stroke_1mm"},
        {"name": "pushed", "kind": "stroke_at_allowable", "node": 8, "dof": "ux", "load_case": "push_x_1N"}
    ]);
    let out = run(case);
    let lc = &out["load_cases"][1];
    let u = &lc["max_utilisation"];
    let sigma_per_mm = u["von_mises"].as_f64().unwrap() / 1.0;
    let hand = u["allowable"].as_f64().unwrap() / sigma_per_mm;
    let s = &out["metrics"]["stroke"];
    let stroke = s["stroke"].as_f64().unwrap();
    assert!(
        (stroke / hand - 1.0).abs() < 1e-9,
        "stroke {stroke} mm vs hand {hand} mm"
    );
    assert!((2.5..3.0).contains(&stroke), "{stroke}");
    assert_eq!(s["linear_estimate"], s["stroke"]);
    assert_eq!(s["element"], u["element"]);
    let reaction = lc["reactions"][2][0].as_f64().unwrap();
    assert_eq!(lc["reaction_nodes"][2], 8);
    assert!(
        (s["load"].as_f64().unwrap() / (reaction * hand) - 1.0).abs() < 1e-9,
        "{s}"
    );
    let p = &out["metrics"]["pushed"];
    assert!(
        (p["stroke"].as_f64().unwrap() / stroke - 1.0).abs() < 1e-9,
        "{p} vs {s}"
    );
    assert!(
        (p["load"].as_f64().unwrap() / s["load"].as_f64().unwrap() - 1.0).abs() < 1e-9,
        "{p} vs {s}"
    );

    // A load case that does not drive the node along the DOF is refused.
    let e = refused(cantilever(json!([
        {"name": "s", "kind": "stroke_at_allowable", "node": 1, "dof": "ux", "load_case": "tip"}
    ])));
    assert!(
        e.contains("metrics[0].load_case") && e.contains("must prescribe a non-zero ux of node 1"),
        "{e}"
    );
}
