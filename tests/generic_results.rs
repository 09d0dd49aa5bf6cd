//! Results for generic `static` models: per-hinge results against the `hinge` analysis.

use flexfem::analysis;
use flexfem::analysis::Case;
use flexfem::hinge::{self, HingeSpec};
use serde_json::Value;

const CIRCULAR: &str = r#"{"type": "circular_notch", "R": 8, "t": 2, "w": 10, "h": 10}"#;
const D: f64 = 40.0;

/// A hinge element from node 0 (clamped) to node 1 along x (notch thinning along z, compliant
/// axis y), loaded at node 1 by `load` = [Fx, Fy, Fz, Mx, My, Mz].
fn hinge_case(load: [f64; 6], nonlinear: bool) -> Case {
    hinge_case_along([D, 0.0, 0.0], load, nonlinear)
}

/// As [`hinge_case`] with node 1 at `b` (up = z).
fn hinge_case_along(b: [f64; 3], load: [f64; 6], nonlinear: bool) -> Case {
    let text = format!(
        r#"{{"analysis": "static", "materials": {{"al": "Al7075"}}, "nonlinear": {nonlinear},
            "nodes": [[0, 0, 0], {b:?}],
            "elements": [{{"type": "hinge", "nodes": [0, 1], "hinge": {CIRCULAR}, "material": "al", "up": [0, 0, 1]}}],
            "supports": [{{"node": 0, "fix": ["ux", "uy", "uz", "rx", "ry", "rz"]}}],
            "load_cases": [{{"name": "m", "forces": [{{"node": 1, "F": {load:?}}}]}}]}}"#
    );
    analysis::parse(&text).unwrap_or_else(|e| panic!("{e}"))
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

/// A cantilever along x of length L = 100 mm in 4 Euler–Bernoulli beams (rect w = 10 along
/// local y, h = 5 along local z, up = z), clamped at node 0; a tip force `f`, plus the
/// case-level extras `extra`.
fn cantilever(f: [f64; 6], extra: &str) -> analysis::Outcome {
    let text = format!(
        r#"{{"analysis": "static", "materials": {{"al": "Al7075"}},
            "sections": {{"s": {{"shape": "rect", "w": 10, "h": 5}}}},
            "nodes": [[0, 0, 0], [25, 0, 0], [50, 0, 0], [75, 0, 0], [100, 0, 0]],
            "elements": [
              {{"type": "beam", "nodes": [0, 1], "section": "s", "material": "al", "up": [0, 0, 1], "shear": false}},
              {{"type": "beam", "nodes": [1, 2], "section": "s", "material": "al", "up": [0, 0, 1], "shear": false}},
              {{"type": "beam", "nodes": [2, 3], "section": "s", "material": "al", "up": [0, 0, 1], "shear": false}},
              {{"type": "beam", "nodes": [3, 4], "section": "s", "material": "al", "up": [0, 0, 1], "shear": false}}],
            "supports": [{{"node": 0, "fix": ["ux", "uy", "uz", "rx", "ry", "rz"]}}],
            "load_cases": [{{"name": "tip", "forces": [{{"node": 4, "F": {f:?}}}]}}]{extra}}}"#
    );
    analysis::run(&analysis::parse(&text).unwrap_or_else(|e| panic!("{e}"))).unwrap_or_else(|e| panic!("{e}"))
}

fn result(out: &analysis::Outcome) -> &Value {
    if out.json["result"].is_object() {
        &out.json["result"]
    } else {
        &out.json
    }
}

/// Statics of a cantilever under a tip force F_z (positive-face convention: the part beyond
/// the section acts on the part before it): V_z = F and M_y = −F·(L − x) at every section,
/// all other section forces zero, to 1e-9 of F and F·L. Without `"output"` no `beam_forces`.
#[test]
fn beam_section_forces_of_a_cantilever() {
    let (l, f) = (100.0, 3.0);
    let plain = cantilever([0.0, 0.0, f, 0.0, 0.0, 0.0], "");
    assert!(result(&plain)["load_cases"][0].get("beam_forces").is_none());
    let out = cantilever([0.0, 0.0, f, 0.0, 0.0, 0.0], r#", "output": {"section_forces": true}"#);
    let bf = result(&out)["load_cases"][0]["beam_forces"].as_array().unwrap().clone();
    assert_eq!(bf.len(), 4);
    for (k, b) in bf.iter().enumerate() {
        assert_eq!(b["element"].as_u64(), Some(k as u64));
        for end in 0..2 {
            let x = 25.0 * (k + end) as f64;
            let s: Vec<f64> = (0..6).map(|i| b["section_forces"][end][i].as_f64().unwrap()).collect();
            let want = [0.0, 0.0, f, 0.0, -f * (l - x), 0.0];
            for i in 0..6 {
                let scale = if i < 3 { f } else { f * l };
                assert!(
                    (s[i] - want[i]).abs() <= 1e-9 * scale,
                    "element {k} end {end} (x = {x}): component {i} = {} vs {}",
                    s[i],
                    want[i]
                );
            }
        }
    }
}

/// Tip compliance of the Euler–Bernoulli cantilever (closed forms): uz/Fz = L³/(3EI_y),
/// uy/Fy = L³/(3EI_z), ux/Fx = L/(EA), ry/My = L/(EI_y), |uz/My| = L²/(2EI_y), to 1e-9; in a frame
/// turned 90° about z the first row is the global y one; the translational eigen extremes are
/// the smallest and largest of the three translational diagonal entries (uncoupled block), and a
/// clamped node has zero compliance.
#[test]
fn node_compliance_of_a_cantilever_tip() {
    let al = flexfem::material::Material::builtin("Al7075").unwrap();
    let (l, w, h): (f64, f64, f64) = (100.0, 10.0, 5.0);
    let (iy, iz, a) = (w * h.powi(3) / 12.0, h * w.powi(3) / 12.0, w * h);
    let out = cantilever(
        [0.0, 0.0, 1.0, 0.0, 0.0, 0.0],
        r#", "compliance": [{"node": 4}, {"node": 4, "frame": [[0, 1, 0], [-1, 0, 0], [0, 0, 1]]}, {"node": 0}]"#,
    );
    let c = &result(&out)["compliance"];
    let m = |k: usize, i: usize, j: usize| c[k]["matrix"][i][j].as_f64().unwrap();
    let e = al.e;
    let close = |got: f64, want: f64, what: &str| {
        assert!((got - want).abs() <= 1e-9 * want.abs(), "{what}: {got} vs {want}");
    };
    close(m(0, 2, 2), l.powi(3) / (3.0 * e * iy), "uz/Fz");
    close(m(0, 1, 1), l.powi(3) / (3.0 * e * iz), "uy/Fy");
    close(m(0, 0, 0), l / (e * a), "ux/Fx");
    close(m(0, 4, 4), l / (e * iy), "ry/My");
    close(m(0, 2, 4).abs(), l * l / (2.0 * e * iy), "|uz/My|");
    close(m(1, 0, 0), l.powi(3) / (3.0 * e * iz), "frame: u'x/F'x = uy/Fy");
    close(m(1, 1, 1), l / (e * a), "frame: u'y/F'y = ux/Fx");
    let ev = |k: usize, i: usize| c[k]["translational_eigen"][i].as_f64().unwrap();
    close(ev(0, 0), l / (e * a), "smallest translational eigenvalue");
    close(ev(0, 1), l.powi(3) / (3.0 * e * iy), "largest translational eigenvalue");
    for i in 0..6 {
        for j in 0..6 {
            assert_eq!(m(2, i, j), 0.0, "clamped node: C[{i}][{j}]");
        }
    }
}

/// A compliance request naming a node outside the model, or a frame that is not orthonormal,
/// is refused at parse time naming its JSON path.
#[test]
fn compliance_request_errors_name_the_path() {
    let base = r#"{"analysis": "static", "materials": {"al": "Al7075"},
        "sections": {"s": {"shape": "rect", "w": 10, "h": 5}},
        "nodes": [[0, 0, 0], [25, 0, 0]],
        "elements": [{"type": "beam", "nodes": [0, 1], "section": "s", "material": "al", "up": [0, 0, 1]}],
        "supports": [{"node": 0, "fix": ["ux", "uy", "uz", "rx", "ry", "rz"]}],
        "load_cases": [{"name": "tip", "forces": [{"node": 1, "F": [0, 0, 1, 0, 0, 0]}]}],
        "compliance": "#;
    let e = analysis::parse(&format!("{base}[{{\"node\": 1}}, {{\"node\": 7}}]}}")).unwrap_err();
    assert!(e.to_string().contains("compliance[1].node"), "{e}");
    let e = analysis::parse(&format!(
        "{base}[{{\"node\": 1, \"frame\": [[1, 0, 0], [1, 0, 0], [0, 0, 1]]}}]}}"
    ))
    .unwrap_err();
    assert!(e.to_string().contains("compliance[0].frame"), "{e}");
}

/// The rotation is taken about the element's own local y: a hinge along global y (local
/// y = z × y = −x) under a moment M about −x turns by C_ry,My·M (the `hinge` analysis's
/// compliance) to 1e-9, and a moment about its stiff axis (global z = local z) gives a rotation
/// about the compliant axis of zero (to 1e-12 of the compliant one).
#[test]
fn hinge_rotation_follows_the_element_axes() {
    let m = 500.0;
    let (r, _) = reference();
    let want = (r.hinge.compliance[4][4] * m).to_degrees();
    let out = analysis::run(&hinge_case_along([0.0, D, 0.0], [0.0, 0.0, 0.0, -m, 0.0, 0.0], false)).unwrap();
    let rot = hinge_row(&out)["rotation_deg"].as_f64().unwrap();
    assert!((rot - want).abs() <= 1e-9 * want, "{rot} vs {want}");
    let out = analysis::run(&hinge_case_along([0.0, D, 0.0], [0.0, 0.0, 0.0, 0.0, 0.0, m], false)).unwrap();
    let rot = hinge_row(&out)["rotation_deg"].as_f64().unwrap();
    assert!(rot.abs() <= 1e-12 * want, "{rot}");
}

/// An unloaded hinge has no stress: utilisation 0 and the remaining rotation unbounded, written
/// as `null` (0·∞ is undefined), not NaN (the result's finite check would refuse it).
#[test]
fn unloaded_hinge_has_unbounded_remaining_rotation() {
    let out = analysis::run(&hinge_case([0.0; 6], false)).unwrap_or_else(|e| panic!("{e}"));
    let h = hinge_row(&out);
    assert_eq!(h["utilisation"].as_f64(), Some(0.0), "{h}");
    assert!(h["remaining_rotation_deg"].is_null(), "{h}");
}
