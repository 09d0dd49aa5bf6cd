//! Results for generic `static` models: per-hinge results against the `hinge` analysis.

use flexfem::analysis;
use flexfem::case::{self, Case};
use flexfem::hinge::{self, HingeSpec};
use serde_json::Value;

const CIRCULAR: &str = r#"{"type": "circular_notch", "R": 8, "t": 2, "w": 10, "h": 10}"#;
const D: f64 = 40.0;

/// A hinge element from node 0 (clamped) to node 1 along x (notch thinning along z, compliant
/// axis y), loaded at node 1 by `load` = [Fx, Fy, Fz, Mx, My, Mz].
fn hinge_case(load: [f64; 6], nonlinear: bool) -> Case {
    let text = format!(
        r#"{{"analysis": "static", "materials": {{"al": "Al7075"}}, "nonlinear": {nonlinear},
            "nodes": [[0, 0, 0], [{D}, 0, 0]],
            "elements": [{{"type": "hinge", "nodes": [0, 1], "hinge": {CIRCULAR}, "material": "al", "up": [0, 0, 1]}}],
            "supports": [{{"node": 0, "fix": ["ux", "uy", "uz", "rx", "ry", "rz"]}}],
            "load_cases": [{{"name": "m", "forces": [{{"node": 1, "F": {load:?}}}]}}]}}"#
    );
    case::parse(&text).unwrap_or_else(|e| panic!("{e}"))
}

/// The element's hinge as the `hinge` analysis sees it: blank per side = (D − notch)/2.
fn reference() -> (hinge::HingeResult, flexfem::material::Material) {
    let al = flexfem::material::Material::builtin("Al7075").unwrap();
    let mut v: Value = serde_json::from_str(CIRCULAR).unwrap();
    v["blank_length"] = 0.0.into();
    let notch: HingeSpec = serde_json::from_value(v.clone()).unwrap();
    let half_notch = notch.profile().unwrap().half_notch;
    v["blank_length"] = ((D - 2.0 * half_notch) / 2.0).into();
    let spec: HingeSpec = serde_json::from_value(v).unwrap();
    (hinge::characterise(&spec, &al).unwrap(), al)
}

fn hinge_row(out: &analysis::Outcome) -> &Value {
    let h = &out.json["result"]["load_cases"][0]["hinges"];
    let h = if h.is_null() {
        &out.json["load_cases"][0]["hinges"]
    } else {
        h
    };
    assert_eq!(h.as_array().map(|a| a.len()), Some(1), "{h}");
    &h[0]
}

/// Linear: the rotation about the compliant axis under a tip moment M_y is C_ry,My·M (the
/// `hinge` analysis's 6×6 compliance, closed form of the element) to 1e-9; the peak stress is
/// the `hinge` analysis's stress per moment × M to 1e-9; utilisation = σ/allowable and the
/// remaining rotation = rotation·(allowable/σ − 1) (its definition) to 1e-12.
#[test]
fn hinge_rotation_and_stress_under_a_tip_moment() {
    let m = 2000.0;
    let out = analysis::run(&hinge_case([0.0, 0.0, 0.0, 0.0, m, 0.0], false)).unwrap();
    let h = hinge_row(&out);
    let (r, al) = reference();
    let want_rot = (r.hinge.compliance[4][4] * m).to_degrees();
    let rot = h["rotation_deg"].as_f64().unwrap();
    assert!((rot - want_rot).abs() <= 1e-9 * want_rot.abs(), "{rot} vs {want_rot}");
    let want_s = r.hinge.stress_per_moment * m;
    let s = h["peak_von_mises"].as_f64().unwrap();
    assert!((s - want_s).abs() <= 1e-9 * want_s, "{s} vs {want_s}");
    let u = h["utilisation"].as_f64().unwrap();
    assert!((u - s / al.allowable).abs() <= 1e-12 * u, "{u}");
    let rem = h["remaining_rotation_deg"].as_f64().unwrap();
    let want_rem = rot * (al.allowable / s - 1.0);
    assert!((rem - want_rem).abs() <= 1e-12 * want_rem.abs(), "{rem} vs {want_rem}");
    // End forces: the section moment is M at both ends (pure bending), element axes.
    for end in 0..2 {
        let my = h["end_forces"][end][4].as_f64().unwrap();
        assert!((my.abs() - m).abs() <= 1e-9 * m, "end {end}: My = {my}");
    }
    assert_eq!(h["element"].as_u64(), Some(0));
}
