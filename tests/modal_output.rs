//! Modal output a user can handle: `"shapes": false` leaves the mode shapes out of the JSON
//! (they stay in `modes.vtu`), rigid-body modes are flagged (`rigid_body`, frequency 0), and an
//! implausible density (a unit slip) is warned about.

use serde_json::{json, Value};

mod common;

fn f(v: &Value) -> f64 {
    v.as_f64().expect("number")
}

/// A free (unsupported) steel plate 100 × 60 × 2 mm, 10×6 shells.
fn free_plate(density: Value, shapes: Option<bool>, modes: usize) -> Value {
    let (nx, ny) = (10, 6);
    let (nodes, elements) =
        common::meshes::shell_grid_json((nx, ny), "s", "steel", |i, j| [10.0 * i as f64, 10.0 * j as f64, 0.0]);
    let mut case = json!({
        "analysis": "modal",
        "modes": modes,
        "materials": {"steel": {"E": 210000.0, "nu": 0.3, "density": density, "yield": 500.0, "allowable": 300.0}},
        "sections": {"s": {"shape": "shell", "t": 2.0}},
        "nodes": nodes,
        "elements": elements,
    });
    if let Some(s) = shapes {
        case["shapes"] = json!(s);
    }
    case
}

fn run(case: Value) -> flexfem::analysis::Outcome {
    let c = flexfem::analysis::parse_value(case, None).expect("valid case");
    flexfem::analysis::run_with_files(&c).expect("analysis runs")
}

/// Free plate: six rigid-body modes (ω² ≈ 0 from roundoff, some slightly negative) flagged
/// `rigid_body` with frequency exactly 0, then elastic modes not flagged; `"shapes": false`
/// drops `shape` from every mode but `modes.vtu` still has all of them.
#[test]
fn free_plate_rigid_modes_and_shapes_false() {
    let out = run(free_plate(json!(7.85e-9), Some(false), 8));
    let modes = out.json["modes"].as_array().unwrap();
    assert_eq!(modes.len(), 8);
    for (k, m) in modes.iter().enumerate() {
        eprintln!(
            "mode {}: eigenvalue {:e}, f = {} Hz, rigid {}",
            k + 1,
            f(&m["eigenvalue"]),
            f(&m["frequency_hz"]),
            m["rigid_body"]
        );
        assert!(m.get("shape").is_none(), "shape present with shapes: false");
        let rigid = m["rigid_body"].as_bool().unwrap();
        assert_eq!(rigid, k < 6, "mode {}", k + 1);
        if rigid {
            assert_eq!(f(&m["frequency_hz"]), 0.0);
        } else {
            assert!(f(&m["frequency_hz"]) > 100.0, "{m}");
        }
    }
    let vtu = out.files.iter().find(|(n, _)| n == "modes.vtu").expect("modes.vtu");
    let text = String::from_utf8_lossy(&vtu.1);
    assert!(text.contains("mode_8_translation_mm"));
    assert!(out.report.markdown.contains("rigid body"));
    // Default: shapes in the JSON.
    let out = run(free_plate(json!(7.85e-9), None, 7));
    assert_eq!(out.json["modes"][6]["shape"].as_array().map(|s| s.len()), Some(77));
    // Anything but a boolean is a case error.
    let mut bad = free_plate(json!(7.85e-9), None, 7);
    bad["shapes"] = json!("no");
    let err = flexfem::analysis::parse_value(bad, None).unwrap_err();
    assert!(err.to_string().contains("shapes"), "{err}");
}

/// A clamped plate has no rigid-body mode: even its lowest mode is not flagged.
#[test]
fn supported_plate_has_no_rigid_modes() {
    let mut case = free_plate(json!(7.85e-9), Some(false), 3);
    case["supports"] = json!((0..7)
        .map(|j| json!({"node": j * 11, "fix": ["ux", "uy", "uz", "rx", "ry", "rz"]}))
        .collect::<Vec<_>>());
    let out = run(case);
    for m in out.json["modes"].as_array().unwrap() {
        assert_eq!(m["rigid_body"], json!(false), "{m}");
        assert!(f(&m["frequency_hz"]) > 10.0);
    }
    assert_eq!(out.json["warnings"], json!([]));
}

/// Steel's density typed in kg/m³ (7850 instead of 7.85e-9 t/mm³) makes the frequencies
/// √(1e12) = 10⁶× too low: a warning names the material and the likely unit; the plausible
/// value gives none.
#[test]
fn implausible_density_is_warned() {
    let out = run(free_plate(json!(7850.0), Some(false), 7));
    let w = out.json["warnings"].as_array().unwrap();
    assert_eq!(w.len(), 1, "{w:?}");
    let w = w[0].as_str().unwrap();
    assert!(w.contains("materials.steel.density") && w.contains("kg/m³"), "{w}");
    assert!(out.report.markdown.contains("materials.steel.density"));
    let ok = run(free_plate(json!(7.85e-9), Some(false), 7));
    // The 7th mode's frequency scales as 1/√ρ: 10⁶ between the two.
    let ratio = f(&ok.json["modes"][6]["frequency_hz"]) / f(&out.json["modes"][6]["frequency_hz"]);
    assert!((ratio / 1e6 - 1.0).abs() < 1e-6, "{ratio}");
    let out = run(free_plate(json!(7.85), Some(false), 7));
    let w = out.json["warnings"][0].as_str().unwrap_or("");
    assert!(w.contains("g/cm³"), "{w}");
}
