//! The headline of a `static` load case — `max_von_mises`, the element that carries it and
//! `max_utilisation` — covers every stressed element: beams, shells and `hinge` elements (their
//! notch peak stress). Regression: a lone hinge under a moment reported `max_von_mises: null`
//! while its own `peak_von_mises` was 1843 MPa (utilisation 4.6), and the stage's own mesh case
//! (`stage_mesh.json`, written by `flexfem run cases/ruiz2019_stage.json --out`) run as `static`
//! reported a maximum 28× below the stage's, which counts its hinges.
//!
//! Sources: the hinge element's `peak_von_mises` is the stress model of the `hinge` analysis
//! and the stage (`tests/stage_mesh.rs` ties the two to 1e-9); the stage's `max_von_mises` is
//! the reference for its own FE model; Al7075's allowable stress is 400 MPa (built-in).

mod common;
use common::*;
use flexfem::analysis;
use serde_json::{json, Value};

/// Al7075's allowable stress, MPa (the built-in material).
const AL_ALLOWABLE: f64 = 400.0;

fn f(v: &Value) -> f64 {
    v.as_f64().unwrap_or_else(|| panic!("not a number: {v}"))
}

fn run_json(case: Value) -> Value {
    let case = analysis::parse(&case.to_string()).unwrap_or_else(|e| panic!("{e}"));
    analysis::run(&case).unwrap_or_else(|e| panic!("{e}")).json
}

/// A circular-notch hinge (R 8, w 10, h 10, thickness `t`) from node 0 (clamped) to node 1 at
/// 40 mm along x, the moment `m` (N·mm) about its compliant axis at node 1; `beam`: a 2×2 mm
/// beam from node 1 to node 2 (40 mm further) of the given material, loaded at node 2 by the
/// given force (N, N·mm).
fn hinge_case(t: f64, m: f64, materials: Value, beam: Option<(&str, [f64; 6])>) -> Value {
    let mut case = json!({
        "analysis": "static",
        "materials": materials,
        "sections": {"bar": {"shape": "rect", "w": 2, "h": 2}},
        "nodes": [[0, 0, 0], [40, 0, 0], [80, 0, 0]],
        "elements": [{"type": "hinge", "nodes": [0, 1], "material": "al", "up": [0, 0, 1],
                      "hinge": {"type": "circular_notch", "R": 8, "t": t, "w": 10, "h": 10}}],
        "supports": [{"node": 0, "fix": ["ux", "uy", "uz", "rx", "ry", "rz"]}],
        "load_cases": [{"name": "moment", "forces": [{"node": 1, "F": [0, 0, 0, 0, m, 0]}]}]
    });
    match beam {
        Some((mat, tip)) => {
            case["elements"]
                .as_array_mut()
                .unwrap()
                .push(json!({"type": "beam", "nodes": [1, 2], "section": "bar", "material": mat, "up": [0, 0, 1]}));
            case["load_cases"][0]["forces"]
                .as_array_mut()
                .unwrap()
                .push(json!({"node": 2, "F": tip}));
        }
        None => {
            case["nodes"].as_array_mut().unwrap().pop();
        }
    }
    case
}

/// A lone hinge under 2000 N·mm: the headline is its peak von Mises (it was `null`), at
/// element 0, kind "hinge", and its utilisation is peak / 400 MPa — the hinge row's own, 4.6.
#[test]
fn lone_hinge_headline_is_its_peak_stress() {
    let r = run_json(hinge_case(0.8, 2000.0, json!({"al": "Al7075"}), None));
    let c = &r["load_cases"][0];
    let peak = f(&c["hinges"][0]["peak_von_mises"]);
    // The peak of a 0.8 mm notch under 2 N·m: ~1843 MPa (nominal 6M/(w·t²) = 1875 MPa).
    assert!((peak / 1843.0 - 1.0).abs() < 1e-3, "{peak}");
    assert!((f(&c["max_von_mises"]) - peak).abs() <= 1e-12 * peak, "{c}");
    assert_eq!(c["max_von_mises_at"]["element"], json!(0));
    assert_eq!(c["max_von_mises_at"]["kind"], json!("hinge"));
    let u = &c["max_utilisation"];
    assert_eq!(u["element"], json!(0), "{u}");
    assert_eq!(u["kind"], json!("hinge"), "{u}");
    assert!((f(&u["value"]) - peak / AL_ALLOWABLE).abs() <= 1e-12, "{u}");
    assert!(
        (f(&u["value"]) - f(&c["hinges"][0]["utilisation"])).abs() <= 1e-12,
        "{u}"
    );
    assert!((f(&u["value"]) / 4.607 - 1.0).abs() < 1e-3, "{u}");
    assert_eq!(f(&u["allowable"]), AL_ALLOWABLE);
}

/// A hinge and a beam in series, the beam more stressed: the headline stress is the beam's own
/// (its `element_von_mises`, element 1), but when the beam's material has no allowable the
/// utilisation is the hinge's — elements without an allowable count in `max_von_mises` only —
/// and `max_utilisation` is `null` when no material has one.
#[test]
fn headline_covers_beams_and_utilisation_needs_an_allowable() {
    let soft = json!({"E": 72000, "nu": 0.33});
    let both = json!({"al": "Al7075", "free": soft});
    // 20 N across a 2×2 mm bar 40 mm long; the hinge (t = 2) carries 20 N · 80 mm = 1600 N·mm
    // (308.5 MPa per 2000 N·mm).
    let r = run_json(hinge_case(
        2.0,
        0.0,
        both.clone(),
        Some(("free", [0.0, 0.0, -20.0, 0.0, 0.0, 0.0])),
    ));
    let c = &r["load_cases"][0];
    let beam = f(&c["element_von_mises"][1]);
    // Bending at the beam's root: M = 20 N · 40 mm, σ = 6M/(b h²) = 600 MPa (von Mises with
    // shear at the same point: the section's critical point, ≥ 600).
    assert!((beam / 600.0 - 1.0).abs() < 0.02, "{beam}");
    let hinge = f(&c["hinges"][0]["peak_von_mises"]);
    assert!(beam > hinge, "{beam} vs {hinge}");
    assert!((f(&c["max_von_mises"]) - beam).abs() <= 1e-12 * beam);
    assert_eq!(c["max_von_mises_at"]["kind"], json!("beam"));
    assert_eq!(c["max_von_mises_at"]["element"], json!(1));
    let u = &c["max_utilisation"];
    assert_eq!(u["kind"], json!("hinge"), "{u}");
    assert!((f(&u["value"]) - hinge / AL_ALLOWABLE).abs() <= 1e-12, "{u}");

    // The beam in Al7075 too: its 600 MPa is the utilisation (1.5).
    let r = run_json(hinge_case(
        2.0,
        0.0,
        json!({"al": "Al7075"}),
        Some(("al", [0.0, 0.0, -20.0, 0.0, 0.0, 0.0])),
    ));
    let u = &r["load_cases"][0]["max_utilisation"];
    assert_eq!(
        (u["kind"].as_str(), u["element"].as_u64()),
        (Some("beam"), Some(1)),
        "{u}"
    );
    assert!((f(&u["value"]) - beam / AL_ALLOWABLE).abs() <= 1e-9, "{u}");

    // No material with an allowable: no utilisation.
    let r = run_json(hinge_case(2.0, 2000.0, json!({"al": soft}), None));
    let c = &r["load_cases"][0];
    assert_eq!(c["max_utilisation"], Value::Null, "{c}");
    assert!((f(&c["max_von_mises"]) / 308.54 - 1.0).abs() < 1e-4, "{c}");
}

/// `stage_mesh.json` (the stage as a `static` mesh case) reports the stage's own headline: per
/// load case its `max_von_mises` equals the `stage` analysis' to 1e-9 relative (measured
/// 1.0e-12), carried by a hinge, with utilisation = that stress / 400 MPa.
#[test]
fn stage_mesh_headline_is_the_stage_maximum() {
    let (stage_dir, stage) = run_out("cases/ruiz2019_stage.json", "headline-stage");
    let mesh = stage_dir.join("stage_mesh.json");
    let (_, stat) = run_out(mesh.to_str().unwrap(), "headline-mesh");
    let (s_rows, m_rows) = (
        stage["load_cases"].as_array().unwrap(),
        stat["load_cases"].as_array().unwrap(),
    );
    assert_eq!(s_rows.len(), 3);
    assert_eq!(s_rows.len(), m_rows.len());
    for (s, m) in s_rows.iter().zip(m_rows) {
        let want = f(&s["max_von_mises"]);
        let got = f(&m["max_von_mises"]);
        let rel = (got / want - 1.0).abs();
        eprintln!("{}: stage {want} MPa, static {got} MPa ({rel:.1e})", s["name"]);
        assert!(rel < 1e-9, "{}: stage {want} vs static {got}", s["name"]);
        assert_eq!(m["max_von_mises_at"]["kind"], json!("hinge"));
        assert!((f(&m["max_utilisation"]["value"]) - want / AL_ALLOWABLE).abs() < 1e-9);
    }
}
