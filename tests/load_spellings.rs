//! A nodal load is `F` [Fx, Fy, Fz (N), Mx, My, Mz (N·mm)] in every analysis, as in a `static`
//! load case; the earlier spellings stay aliases: `force` [6] in a `transient` load, `force` [3]
//! and `moment` [3] in an `frf` input. Each spelling gives the same result, byte for byte, and
//! giving both is refused naming the load's JSON path (exit 2).

mod common;

use serde_json::{json, Value};

fn run(v: &Value) -> Value {
    let c = flexfem::analysis::parse(&v.to_string()).unwrap_or_else(|e| panic!("{e}"));
    flexfem::analysis::run(&c).unwrap_or_else(|e| panic!("{e}")).json
}

/// A 1e-3 t point mass on a grounded spring kx = 1000 N/mm (the other DOFs stiff), undamped.
fn spring_mass(extra: Value) -> Value {
    let mut c = json!({
        "nodes": [[0, 0, 0]],
        "elements": [
            {"type": "spring", "nodes": [0], "k": [1000, 2000, 3000, 4000, 5000, 6000]},
            {"type": "mass", "node": 0, "mass": 0.001, "inertia": [1, 2, 3]}
        ]
    });
    for (k, v) in extra.as_object().unwrap() {
        c[k] = v.clone();
    }
    c
}

/// Transient: a 2 N step along x on the undamped oscillator (ω = 1000 rad/s, T = 6.283 ms), as
/// `F` and as `force`: identical results; the peak is the dynamic amplification 2 of the static
/// 2/1000 mm (any structural dynamics text, e.g. A. K. Chopra, Dynamics of Structures, §4.3) to
/// 0.2 % (Newmark average acceleration, 100 steps per period: the sampled peak lies within
/// 1 − cos(π/100) = 5e-4 of the true one).
#[test]
fn transient_load_as_f_or_force_gives_the_same_response() {
    let case = |load: Value| {
        spring_mass(json!({
            "analysis": "transient", "dt": 6.283185307179586e-5, "steps": 200,
            "loads": [load], "record": [{"node": 0, "dof": "ux"}]
        }))
    };
    let step = json!({"type": "step"});
    let f = run(&case(json!({"node": 0, "F": [2, 0, 0, 0, 0, 0], "history": step})));
    let alias = run(&case(json!({"node": 0, "force": [2, 0, 0, 0, 0, 0], "history": step})));
    assert_eq!(f, alias);
    let peak = f["records"][0]["max"]
        .as_f64()
        .unwrap_or_else(|| panic!("{}", f["records"][0]));
    assert!((peak / 4e-3 - 1.0).abs() < 2e-3, "peak {peak} mm vs 2·F/k = 0.004 mm");
}

/// FRF: a unit x force and a unit z moment as `F` [6] and as `force` + `moment`: identical
/// results; the static gains are 1/kx = 1e-3 mm/N and (180/π)/krz deg/(N·mm) to 1e-12.
#[test]
fn frf_input_as_f_or_force_and_moment_gives_the_same_response() {
    let case = |inputs: Value| {
        spring_mass(json!({
            "analysis": "frf", "modes": 6, "damping": {"alpha": 20},
            "frequencies": {"from_hz": 10, "to_hz": 400, "points": 5, "spacing": "linear"},
            "inputs": inputs,
            "outputs": [{"name": "mass", "node": 0, "dofs": ["ux", "rz"]}]
        }))
    };
    let f = run(&case(json!([
        {"name": "push", "node": 0, "F": [1, 0, 0, 0, 0, 0]},
        {"name": "twist", "node": 0, "F": [0, 0, 0, 0, 0, 1]}
    ])));
    let alias = run(&case(json!([
        {"name": "push", "node": 0, "force": [1, 0, 0]},
        {"name": "twist", "node": 0, "moment": [0, 0, 1]}
    ])));
    assert_eq!(f, alias);
    let g = |o: usize, i: usize| f["static_gain"][o][i].as_f64().unwrap();
    assert!((g(0, 0) - 1e-3).abs() < 1e-15, "{}", g(0, 0));
    let rz = 180.0 / std::f64::consts::PI / 6000.0;
    assert!((g(1, 1) - rz).abs() < 1e-12 * rz, "{}", g(1, 1));
}

/// Both spellings at once, or none, is refused naming the load (exit 2).
#[test]
fn both_spellings_are_refused_naming_the_load() {
    let transient =
        |load: Value| spring_mass(json!({"analysis": "transient", "dt": 1e-4, "steps": 5, "loads": [load]}));
    let frf = |input: Value| {
        spring_mass(json!({
            "analysis": "frf", "modes": 6,
            "frequencies": {"from_hz": 10, "to_hz": 400, "points": 5},
            "inputs": [input], "outputs": [{"node": 0, "dofs": ["ux"]}]
        }))
    };
    let step = json!({"type": "step"});
    let cases = [
        (
            "loads[0]",
            transient(json!({"node": 0, "F": [1, 0, 0, 0, 0, 0], "force": [1, 0, 0, 0, 0, 0], "history": step})),
        ),
        ("loads[0]", transient(json!({"node": 0, "history": step}))),
        (
            "inputs[0]",
            frf(json!({"node": 0, "F": [1, 0, 0, 0, 0, 0], "moment": [0, 0, 1]})),
        ),
        ("inputs[0].F", frf(json!({"node": 0, "F": [0, 0, 0, 0, 0, 0]}))),
    ];
    for (path, v) in cases {
        for cmd in ["run", "check"] {
            let d = common::tempdir("load_spellings");
            let p = common::write(&d, "case.json", &v.to_string());
            let o = common::run_in(&d, &[cmd, p.to_str().unwrap()]);
            common::cleanup(&d);
            let err = common::stderr(&o);
            assert_eq!(o.status.code(), Some(2), "{cmd} {path}: {err}");
            assert!(err.contains(&format!("`{path}`")), "{cmd} {path}: {err}");
        }
    }
}
