//! Hinge elements in geometrically nonlinear runs default to a segmentation that converges
//! their finite-rotation response: the bundled parallelogram guide and lever amplifier, run
//! nonlinear with default settings (no `segments`), agree with the same models at 16
//! co-rotational segments per hinge to 1 % in parasitic motion, rotation and peak stress.
//!
//! Reference: the converged discretisation (16 segments; 8 → 16 changes the parallelogram's
//! drop by 0.09 %). Measured (default = 4 segments; the old default, one segment, in brackets):
//! - parallelogram, 1 mm stroke: bar drop 4.9081 µm vs 4.9200 µm, −0.24 % (4.6201 µm, −6.10 %);
//!   hinge rotation −0.572337° both (same); peak von Mises 143.047 vs 143.057 MPa, −0.007 %
//!   (142.812 MPa, −0.17 %);
//! - lever, 1 mm input (5.7° per hinge): output ux (parasitic) −0.963232 vs −0.963244 mm,
//!   −0.001 % (−0.963993 mm, +0.08 %); output uy 4.91993 vs 4.91935 mm, +0.012 % (4.93448 mm,
//!   +0.31 %); rotation 5.678445° vs 5.678464°, −3e-6 (5.678923°, +8e-5); peak von Mises
//!   1533.42 vs 1536.81 MPa, −0.22 % (1451.46 MPa, −5.55 %).
//!
//! So the old default failed the 1 % requirement on the parallelogram's parasitic drop and the
//! lever's peak stress; [`old_single_segment_default_misses_by_six_percent`] keeps that claim
//! executable (with `"segments": 1`, what a hinge element got before).

use serde_json::{json, Value};
use std::path::PathBuf;

fn root() -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR"))
}

fn read_json(rel: &str) -> Value {
    let text = std::fs::read_to_string(root().join(rel)).unwrap_or_else(|e| panic!("{rel}: {e}"));
    serde_json::from_str(&text).unwrap()
}

fn run_value(case: &Value) -> Value {
    let text = serde_json::to_string(case).unwrap();
    let parsed = flexfem::analysis::parse_in(&text, Some(&root().join("cases")))
        .unwrap_or_else(|e| panic!("case does not load: {e}"));
    flexfem::analysis::run(&parsed)
        .unwrap_or_else(|e| panic!("analysis fails: {e}"))
        .json
}

/// Sets (`Some`) or removes (`None`) `segments` on every hinge element of `elements`.
fn set_segments(elements: &mut Value, segments: Option<usize>) {
    for e in elements.as_array_mut().unwrap() {
        if e["type"] == "hinge" {
            match segments {
                Some(n) => e["segments"] = json!(n),
                None => {
                    e.as_object_mut().unwrap().remove("segments");
                }
            }
        }
    }
}

/// What is compared: the parasitic displacement, the first hinge's rotation (deg) and the peak
/// hinge von Mises stress (MPa), plus the model notes.
struct Response {
    parasitic: f64,
    main: f64,
    rotation: f64,
    peak: f64,
    notes: Vec<String>,
}

fn response(result: &Value, node: usize, parasitic: usize, main: usize) -> Response {
    let lc = &result["load_cases"][0];
    let d = |k: usize| lc["displacements"][node][k].as_f64().unwrap();
    let hinges = lc["hinges"].as_array().unwrap();
    Response {
        parasitic: d(parasitic),
        main: d(main),
        rotation: hinges[0]["rotation_deg"].as_f64().unwrap(),
        peak: hinges
            .iter()
            .map(|h| h["peak_von_mises"].as_f64().unwrap())
            .fold(f64::NEG_INFINITY, f64::max),
        notes: result["model"]
            .as_array()
            .unwrap()
            .iter()
            .map(|n| n.as_str().unwrap().to_string())
            .collect(),
    }
}

/// `cases/parallelogram_guide.json`'s model (bundled mesh, its hinges' `segments` replaced),
/// stroked 1 mm along x at the bar, nonlinear with default settings: the bar (node 8).
fn parallelogram(segments: Option<usize>) -> Response {
    let mut mesh = read_json("meshes/parallelogram_notch.json");
    set_segments(&mut mesh["elements"], segments);
    let mut case = mesh;
    case["analysis"] = json!("static");
    case["nonlinear"] = json!(true);
    case["load_cases"] = json!([{"name": "stroke_1mm", "displacements": [{"node": 8, "dof": "ux", "value": 1}]}]);
    let r = run_value(&case);
    // Guided along x; the parasitic motion is the drop along y.
    response(&r, 8, 1, 0)
}

/// `cases/lever_amplifier.json` driven 1 mm at its input (5.7° per hinge, not the bundled
/// 10 µm), nonlinear with default settings: the output (node 4).
fn lever(segments: Option<usize>) -> Response {
    let mut case = read_json("cases/lever_amplifier.json");
    set_segments(&mut case["elements"], segments);
    case["nonlinear"] = json!(true);
    case["load_cases"][0]["displacements"][0]["value"] = json!(1.0);
    let r = run_value(&case);
    // The output moves along y; the parasitic motion is along x.
    response(&r, 4, 0, 1)
}

fn rel(a: f64, b: f64) -> f64 {
    a / b - 1.0
}

#[test]
fn parallelogram_default_segments_match_sixteen() {
    let (def, fine) = (parallelogram(None), parallelogram(Some(16)));
    let (drop, rot, peak) = (
        rel(def.parasitic, fine.parasitic),
        rel(def.rotation, fine.rotation),
        rel(def.peak, fine.peak),
    );
    eprintln!(
        "parallelogram: drop {:.6e} vs {:.6e} ({drop:+.3e}); rotation {:.6}° vs {:.6}° ({rot:+.1e}); peak {:.3} vs {:.3} MPa ({peak:+.3e})",
        -def.parasitic, -fine.parasitic, def.rotation, fine.rotation, def.peak, fine.peak
    );
    // The requirement (1 %) and the measured level (−0.24 %, 0, −0.007 %).
    assert!(drop.abs() < 0.01 && drop.abs() < 3e-3, "drop {drop}");
    assert!(rot.abs() < 0.01 && rot.abs() < 1e-6, "rotation {rot}");
    assert!(peak.abs() < 0.01 && peak.abs() < 3e-4, "peak stress {peak}");
    assert!((def.main - 1.0).abs() < 1e-9, "stroke {}", def.main);
    assert!(
        def.notes
            .iter()
            .any(|n| n.contains("split into 4 co-rotational segments")),
        "no model note on the default segmentation: {:?}",
        def.notes
    );
    assert!(
        !fine.notes.iter().any(|n| n.contains("no \"segments\" given")),
        "{:?}",
        fine.notes
    );
}

#[test]
fn lever_default_segments_match_sixteen() {
    let (def, fine) = (lever(None), lever(Some(16)));
    let (par, out, rot, peak) = (
        rel(def.parasitic, fine.parasitic),
        rel(def.main, fine.main),
        rel(def.rotation, fine.rotation),
        rel(def.peak, fine.peak),
    );
    eprintln!(
        "lever: ux {:.6} vs {:.6} ({par:+.2e}); uy {:.6} vs {:.6} ({out:+.2e}); rotation {:.6}° vs {:.6}° ({rot:+.1e}); peak {:.2} vs {:.2} MPa ({peak:+.3e})",
        def.parasitic, fine.parasitic, def.main, fine.main, def.rotation, fine.rotation, def.peak, fine.peak
    );
    // The requirement (1 %) and the measured level (−0.001 %, +0.012 %, −3e-6, −0.22 %).
    assert!(par.abs() < 0.01 && par.abs() < 1e-4, "parasitic {par}");
    assert!(out.abs() < 0.01 && out.abs() < 5e-4, "output {out}");
    assert!(rot.abs() < 0.01 && rot.abs() < 1e-5, "rotation {rot}");
    assert!(peak.abs() < 0.01 && peak.abs() < 3e-3, "peak stress {peak}");
    assert!(
        def.notes
            .iter()
            .any(|n| n.contains("split into 4 co-rotational segments")),
        "{:?}",
        def.notes
    );
}

/// The old default (one co-rotational segment per hinge element) against 16 segments: the
/// parallelogram's drop −6.10 % (the chord of each notch keeps its length), the lever's peak
/// stress −5.55 % at 5.7°; both outside the 1 % the default now meets.
#[test]
fn old_single_segment_default_misses_by_six_percent() {
    let (p1, p16) = (parallelogram(Some(1)), parallelogram(Some(16)));
    let drop = rel(p1.parasitic, p16.parasitic);
    let (l1, l16) = (lever(Some(1)), lever(Some(16)));
    let peak = rel(l1.peak, l16.peak);
    eprintln!("one segment: parallelogram drop {drop:+.4e}, lever peak stress {peak:+.4e}");
    assert!((drop + 0.0610).abs() < 1e-3, "drop {drop}");
    assert!((peak + 0.0555).abs() < 1e-3, "peak {peak}");
}

/// A linear run keeps one element per hinge (no inner nodes: the displacement rows are the
/// case's 9 nodes) and carries no segmentation note.
#[test]
fn linear_run_keeps_single_element_hinges() {
    let mut mesh = read_json("meshes/parallelogram_notch.json");
    set_segments(&mut mesh["elements"], None);
    let mut case = mesh;
    case["analysis"] = json!("static");
    case["load_cases"] = json!([{"name": "push", "forces": [{"node": 8, "F": [1, 0, 0, 0, 0, 0]}]}]);
    let r = run_value(&case);
    let rows = r["load_cases"][0]["displacements"].as_array().unwrap().len();
    assert_eq!(rows, 9);
    let notes = r["model"].as_array().unwrap();
    assert!(
        !notes
            .iter()
            .any(|n| n.as_str().unwrap().contains("co-rotational segments")),
        "{notes:?}"
    );
}
