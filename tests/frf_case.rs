//! The `frf` analysis end to end on a single mass on a 6-DOF spring to ground (closed forms),
//! and its case errors (JSON paths, exit 2).

mod common;

use serde_json::{json, Value};

/// A 1 kg (1e-3 t) point mass on a grounded spring: kx = 1000 N/mm, ky = 2000 N/mm,
/// krz = 6000 N·mm/rad, Izz = 3 t·mm². Inputs: a unit x force, a unit force along local x of a
/// frame turned 90° about z (= global y), a unit moment about z. Outputs: ux, uy, rz.
fn sdof() -> Value {
    json!({
        "analysis": "frf", "modes": 6,
        "damping": {"alpha": 20},
        "frequencies": {"from_hz": 10, "to_hz": 400, "points": 5, "spacing": "linear"},
        "inputs": [
            {"name": "push", "node": 0, "force": [1, 0, 0]},
            {"name": "side", "node": 0, "force": [1, 0, 0], "frame": [[0, 1, 0], [-1, 0, 0], [0, 0, 1]]},
            {"name": "twist", "node": 0, "moment": [0, 0, 1]}
        ],
        "outputs": [{"name": "mass", "node": 0, "dofs": ["ux", "uy", "rz"]}],
        "nodes": [[0, 0, 0]],
        "elements": [
            {"type": "spring", "nodes": [0], "k": [1000, 2000, 3000, 4000, 5000, 6000]},
            {"type": "mass", "node": 0, "mass": 0.001, "inertia": [1, 2, 3]}
        ]
    })
}

fn run(v: &Value) -> Value {
    let c = flexfem::analysis::parse(&v.to_string()).unwrap_or_else(|e| panic!("{e}"));
    flexfem::analysis::run(&c).unwrap_or_else(|e| panic!("{e}")).json
}

/// H(ω) = 1/(k − mω² + icω) with c = αm (Rayleigh mass-proportional damping; any structural
/// dynamics text, e.g. A. K. Chopra, Dynamics of Structures, 4th ed., 2012, §3.2) for each
/// uncoupled direction: magnitude and phase at 5 frequencies to 1e-9 (every mode retained, so
/// the modal sum is exact); rotations in degrees per N·mm; the static gain is 1/k; the input
/// frame turns the `side` force onto global y. The direct check agrees to 1e-12.
#[test]
fn single_mass_closed_form() {
    let r = run(&sdof());
    let (alpha, pi) = (20.0, std::f64::consts::PI);
    // (input, output, k, m, scale to output units)
    let pairs = [
        (0, 0, 1000.0, 1e-3, 1.0),
        (1, 1, 2000.0, 1e-3, 1.0),
        (2, 2, 6000.0, 3.0, 180.0 / pi),
    ];
    let freqs: Vec<f64> = r["frequencies_hz"]
        .as_array()
        .unwrap()
        .iter()
        .map(|v| v.as_f64().unwrap())
        .collect();
    for (j, k_out, k, m, scale) in pairs {
        let pair = r["response"]
            .as_array()
            .unwrap()
            .iter()
            .find(|p| p["input"] == r["inputs"][j] && p["output"] == r["outputs"][k_out]["name"])
            .unwrap();
        let g = r["static_gain"][k_out][j].as_f64().unwrap();
        assert!((g - scale / k).abs() < 1e-12 * scale / k, "static gain {g}");
        for (i, f) in freqs.iter().enumerate() {
            let w = 2.0 * pi * f;
            let (re, im) = (k - m * w * w, alpha * m * w);
            let mag = scale / (re * re + im * im).sqrt();
            let phase = (-im).atan2(re).to_degrees();
            let got_mag = pair["magnitude"][i].as_f64().unwrap();
            let got_phase = pair["phase_deg"][i].as_f64().unwrap();
            assert!(
                (got_mag - mag).abs() < 1e-9 * mag,
                "{j}->{k_out} at {f} Hz: |H| {got_mag} vs {mag}"
            );
            assert!(
                (got_phase - phase).abs() < 1e-7,
                "{j}->{k_out} at {f} Hz: phase {got_phase} vs {phase}"
            );
        }
    }
    let d = r["direct"]["max_relative_difference"].as_f64().unwrap();
    assert!(d < 1e-12, "direct check {d}");
    assert_eq!(r["state_space"]["states"], 12);
}

/// A constant modal damping ratio has no sparse damping matrix: the direct check is left out
/// (null) with a note, the modal damping ratios are ζ.
#[test]
fn modal_damping_ratio_has_no_direct_check() {
    let mut v = sdof();
    v["damping"] = json!({"zeta": 0.02});
    let r = run(&v);
    assert!(r["direct"].is_null());
    assert!(r["model"].to_string().contains("no direct check"));
    for m in r["modes"].as_array().unwrap() {
        assert_eq!(m["damping_ratio"].as_f64().unwrap(), 0.02);
    }
}

/// Bad input names its JSON path, the value and what is allowed; `flexfem run` exits 2.
#[test]
fn case_errors_name_their_paths() {
    type Edit = Box<dyn Fn(&mut Value)>;
    let cases: Vec<(&str, Edit)> = vec![
        ("inputs[0].node", Box::new(|v| v["inputs"][0]["node"] = json!(5))),
        ("outputs[0].node", Box::new(|v| v["outputs"][0]["node"] = json!(1))),
        ("frequencies.to_hz", Box::new(|v| v["frequencies"]["to_hz"] = json!(5))),
        (
            "frequencies.from_hz",
            Box::new(|v| {
                v["frequencies"]["spacing"] = json!("log");
                v["frequencies"]["from_hz"] = json!(0);
            }),
        ),
        (
            "frequencies.points",
            Box::new(|v| v["frequencies"]["points"] = json!(1)),
        ),
        ("damping.zeta", Box::new(|v| v["damping"] = json!({"zeta": 1.0}))),
        ("damping.alpha", Box::new(|v| v["damping"] = json!({"alpha": -1.0}))),
        (
            "inputs[1].force",
            Box::new(|v| v["inputs"][1]["force"] = json!([0, 0, 0])),
        ),
        (
            "inputs[1].frame",
            Box::new(|v| v["inputs"][1]["frame"] = json!([[1, 1, 0], [0, 1, 0], [0, 0, 1]])),
        ),
        ("outputs[0].dofs", Box::new(|v| v["outputs"][0]["dofs"] = json!([]))),
        ("modes", Box::new(|v| v["modes"] = json!(0))),
        ("modez", Box::new(|v| v["modez"] = json!(3))),
    ];
    for (path, edit) in cases {
        let mut v = sdof();
        edit(&mut v);
        let o = common::run_case_text("frf_errors", &v.to_string());
        let err = common::stderr(&o);
        assert_eq!(o.status.code(), Some(2), "{path}: {err}");
        assert!(err.contains(&format!("`{path}`")), "{path}: {err}");
    }
}
