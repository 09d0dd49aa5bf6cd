//! The `transient` analysis kind: prescribed-motion histories against the closed form of a
//! base-excited oscillator, per-element damping equal to the same Rayleigh damping, the
//! bundled stage case (hinge elements, rigid links, slider frames) against its own statics,
//! and case errors that name their JSON path.

use flexfem::analysis::{load, parse, run, run_with_files};
use serde_json::{json, Value};
use std::f64::consts::PI;

/// A steel bar along x (EA/L = 2100 N/mm, massless) with a 1e-3 t point mass at its end:
/// ω² = 2.1e6 (rad/s)², T = 4.336 ms. Axial motion only (the mass's other DOFs are held).
fn bar_case(extra: Value) -> Value {
    let mut c = json!({
        "analysis": "transient",
        "materials": {"s": {"E": 210000, "nu": 0.3, "density": 0}},
        "sections": {"sq": {"shape": "rect", "w": 1, "h": 1}},
        "nodes": [[0, 0, 0], [100, 0, 0]],
        "elements": [
            {"type": "beam", "nodes": [0, 1], "section": "sq", "material": "s", "up": [0, 0, 1]},
            {"type": "mass", "node": 1, "mass": 1e-3, "inertia": [1e-3, 1e-3, 1e-3]}
        ],
        "supports": [{"node": 0, "fix": ["uy", "uz", "rx", "ry", "rz"]}, {"node": 1, "fix": ["uy", "uz", "rx", "ry", "rz"]}],
        "record": [{"node": 1, "dof": "ux"}],
        "histories": true
    });
    for (k, v) in extra.as_object().unwrap() {
        c[k] = v.clone();
    }
    c
}

fn series(out: &Value, k: usize) -> (Vec<f64>, Vec<f64>) {
    let t: Vec<f64> = serde_json::from_value(out["time_s"].clone()).unwrap();
    let u: Vec<f64> = serde_json::from_value(out["records"][k]["series"].clone()).unwrap();
    (t, u)
}

fn run_json(c: &Value) -> Value {
    run(&parse(&c.to_string()).unwrap()).unwrap().json
}

#[test]
fn base_motion_matches_the_base_excited_oscillator() {
    // u_b = A sin Ωt at the base (Ω = ω/3), from rest: u = A ω²/(ω² − Ω²) (sin Ωt − (Ω/ω) sin ωt)
    // (A. K. Chopra, Dynamics of Structures, 4th ed., §3.1, undamped harmonic excitation).
    let (w, a) = ((2.1e6f64).sqrt(), 0.01);
    let f = w / 3.0 / (2.0 * PI);
    let dt = 2.0 * PI / w / 200.0;
    let c = bar_case(json!({
        "dt": dt, "steps": 1000,
        "motions": [{"node": 0, "dof": "ux", "value": a, "history": {"type": "sine", "frequency_hz": f}}]
    }));
    let out = run_json(&c);
    let (t, u) = series(&out, 0);
    let big = w / 3.0;
    let exact = |t: f64| a * w * w / (w * w - big * big) * ((big * t).sin() - big / w * (w * t).sin());
    assert_eq!(t.len(), u.len());
    let err = t.iter().zip(&u).map(|(t, u)| (u - exact(*t)).abs()).fold(0.0, f64::max);
    let peak = u.iter().fold(0.0f64, |m, v| m.max(v.abs()));
    eprintln!(
        "base motion: max error {:.3e} mm of peak {peak:.4} mm ({:.3} %)",
        err,
        100.0 * err / peak
    );
    // 200 steps per period over 5 periods: Newmark's period error (ωΔt)²/12 = 8e-5 per
    // period keeps the error well under 1 % of the peak.
    assert!(err < 0.01 * peak, "{err} vs {peak}");
}

#[test]
fn element_damping_equals_rayleigh_beta() {
    let base = json!({
        "dt": 1e-4, "steps": 400,
        "loads": [{"node": 1, "force": [1, 0, 0, 0, 0, 0], "history": {"type": "step"}}]
    });
    let mut rayleigh = bar_case(base.clone());
    rayleigh["damping"] = json!({"beta": 2e-4});
    rayleigh["supports"][0]["fix"] = json!(["ux", "uy", "uz", "rx", "ry", "rz"]);
    let mut element = rayleigh.clone();
    element["damping"] = json!({"elements": [{"element": 0, "beta": 2e-4}]});
    assert_eq!(rayleigh["damping"], json!({"beta": 2e-4}));
    let (_, u1) = series(&run_json(&rayleigh), 0);
    let (_, u2) = series(&run_json(&element), 0);
    assert_eq!(u1.len(), u2.len());
    let diff = u1.iter().zip(&u2).map(|(a, b)| (a - b).abs()).fold(0.0, f64::max);
    // The bar is the only element: C = beta K either way (to roundoff).
    assert!(diff < 1e-12, "{diff}");
    // And the damping acts: the response settles to the static F/k = 1/2100 mm within 0.5 %.
    let last = *u1.last().unwrap();
    assert!((last * 2100.0 - 1.0).abs() < 5e-3, "{last}");
}

#[test]
fn stage_step_response_settles_to_its_statics() {
    // The bundled stage step (hinge elements in a mesh, rigid platform, slider frames): with
    // sliders 2 and 3 held and slider 1 moved 0.01 mm, the platform must settle to the static
    // response of the same mesh to the same strokes; after 0.1 s at ζ ≈ 2 % the rest of the
    // oscillation is < 1 % of the overshoot. Static reference: a `static` run of the mesh.
    let case = load(std::path::Path::new("cases/ruiz2019_stage_step.json")).unwrap();
    let dynamic = run(&case).unwrap().json;
    let mesh: Value =
        serde_json::from_str(&std::fs::read_to_string("meshes/ruiz2019_stage_dynamic.json").unwrap()).unwrap();
    let frame = |node: u64| {
        mesh["supports"]
            .as_array()
            .unwrap()
            .iter()
            .find(|s| s["node"] == node)
            .unwrap()["frame"]
            .clone()
    };
    let stroke = |node: u64, value: f64| json!({"node": node, "dof": "ux", "value": value, "frame": frame(node)});
    let stat = json!({
        "analysis": "static",
        "mesh": "meshes/ruiz2019_stage_dynamic.json",
        "load_cases": [{"name": "stroke", "displacements": [stroke(1, 0.01), stroke(8, 0.0), stroke(15, 0.0)]}]
    });
    let s = run(&parse(&stat.to_string()).unwrap()).unwrap().json;
    let uz_static = s["load_cases"][0]["displacements"][0][2].as_f64().unwrap();
    let rec = &dynamic["records"][2];
    assert_eq!(rec["dof"], "uz");
    let (fin, max) = (rec["final_value"].as_f64().unwrap(), rec["max"].as_f64().unwrap());
    eprintln!("stage step: platform uz final {fin:.6} mm, static {uz_static:.6} mm, peak {max:.6} mm");
    assert!(max > 1.05 * uz_static, "a step overshoots: {max} vs {uz_static}");
    assert!((fin / uz_static - 1.0).abs() < 0.05, "{fin} vs {uz_static}");
    // --out files: histories CSV, one SVG per recorded DOF, the .pvd collection and its frames.
    let files = run_with_files(&case).unwrap().files;
    let names: Vec<&str> = files.iter().map(|(n, _)| n.as_str()).collect();
    for want in [
        "transient_histories.csv",
        "transient_n0_uz.svg",
        "transient.pvd",
        "transient_0000.vtu",
    ] {
        assert!(names.contains(&want), "{want} missing from {names:?}");
    }
    let pvd = String::from_utf8(files.iter().find(|f| f.0 == "transient.pvd").unwrap().1.clone()).unwrap();
    let frames = names.iter().filter(|n| n.ends_with(".vtu")).count();
    assert_eq!(pvd.matches("<DataSet").count(), frames);
}

#[test]
fn case_errors_name_their_path() {
    let cases = [
        (json!({"dt": 0, "steps": 10}), "dt"),
        (
            json!({"dt": 1e-4, "steps": 10, "motions": [{"node": 0, "dof": "ux", "value": 1, "history": {"type": "step"}}]}),
            "motions[0].history",
        ),
        (
            json!({"dt": 1e-4, "steps": 10, "loads": [{"node": 9, "force": [1, 0, 0, 0, 0, 0], "history": {"type": "step"}}]}),
            "loads[0].node",
        ),
        (
            json!({"dt": 1e-4, "steps": 10, "loads": [{"node": 1, "force": [1, 0, 0, 0, 0, 0], "history": {"type": "ramp", "start": 1, "end": 0}}]}),
            "loads[0].history",
        ),
        (
            json!({"dt": 1e-4, "steps": 10, "scheme": "hht", "hht_alpha": -0.5}),
            "hht_alpha",
        ),
        (
            json!({"dt": 1e-4, "steps": 10, "damping": {"elements": [{"element": 7, "beta": 1}]}}),
            "damping.elements[0].element",
        ),
    ];
    for (extra, path) in cases {
        let err = match parse(&bar_case(extra).to_string()) {
            Err(e) => e,
            Ok(c) => flexfem::analysis::check(&c).unwrap_err(),
        };
        assert_eq!(err.path, path, "{err}");
    }
}
