//! Arc-length control and critical points through case files: `"control": "arc_length"`,
//! `"arc_length"` parameters and `"trace"` on nonlinear load cases, the result's `trace` and
//! `critical_points`, the path files written with `--out`, and the case-file errors.

mod common;
use common::{run_case_text, run_in, stderr, tempdir};

fn json_file(p: &std::path::Path) -> serde_json::Value {
    serde_json::from_str(&std::fs::read_to_string(p).unwrap_or_default()).unwrap_or_else(|e| panic!("{p:?}: {e}"))
}

fn f(v: &serde_json::Value) -> f64 {
    v.as_f64().unwrap_or(f64::NAN)
}

/// The shallow two-bar (von Mises) truss of tests/nonlinear_critical.rs as a case file (half
/// span 100, rise 5, A 10, E 70000, I 1e-3, crown load 2 P_max), with `extra` load-case fields.
fn truss_case(extra: &str, nonlinear: bool) -> String {
    format!(
        r#"{{"analysis": "static", "nonlinear": {nonlinear},
        "materials": {{"m": {{"E": 70000, "nu": 0.3}}}},
        "sections": {{"bar": {{"shape": "general", "A": 10, "Iy": 0.001, "Iz": 0.001, "J": 1}}}},
        "nodes": [[-100, 0, 0], [0, 0, 5], [100, 0, 0]],
        "elements": [{{"type": "beam", "nodes": [0, 1], "section": "bar", "material": "m", "up": [0, 1, 0], "shear": false}},
                     {{"type": "beam", "nodes": [1, 2], "section": "bar", "material": "m", "up": [0, 1, 0], "shear": false}}],
        "supports": [{{"node": 0, "fix": ["ux", "uy", "uz", "rx", "rz"]}}, {{"node": 2, "fix": ["ux", "uy", "uz", "rx", "rz"]}},
                     {{"node": 1, "fix": ["uy", "rx", "rz"]}}],
        "load_cases": [{{"name": "P", "forces": [{{"node": 1, "F": [0, 0, {}, 0, 0, 0]}}]{extra}}}]}}"#,
        -2.0 * p_max()
    )
}

/// P_max of the pin-jointed truss: 2EA·u*(1/L* − 1/L₀), L* = (a²L₀)^(1/3), u* = √(L*² − a²)
/// (Z. P. Bažant & L. Cedolin, "Stability of Structures", Oxford UP 1991, §2.1).
fn p_max() -> f64 {
    let (a, h, ea) = (100.0f64, 5.0f64, 7e5);
    let l0 = (a * a + h * h).sqrt();
    let ls = (a * a * l0).cbrt();
    let us = (ls * ls - a * a).sqrt();
    2.0 * ea * us * (1.0 / ls - 1.0 / l0)
}

/// Through the CLI the truss is traced by arc length through both limit points, located within
/// 1 % of ±P_max (closed form above), and the path files are written.
#[test]
fn truss_case_traced_through_both_limits() {
    let d = tempdir("arc_truss");
    let extra = r#", "control": "arc_length", "arc_length": {"initial": 0.02, "constraint": "spherical"}, "trace": {"node": 1, "dof": "uz"}"#;
    std::fs::write(d.join("truss.json"), truss_case(extra, true)).unwrap_or_else(|e| panic!("{e}"));
    let out = run_in(&d, &["run", "truss.json", "--out", "out"]);
    assert_eq!(out.status.code(), Some(0), "{}", stderr(&out));
    let v = json_file(&d.join("out/result.json"));
    let c = &v["load_cases"][0];
    let cps = c["critical_points"].as_array().cloned().unwrap_or_default();
    assert_eq!(cps.len(), 2, "{}", c["critical_points"]);
    let p = 2.0 * p_max();
    for (cp, want, stability) in [(&cps[0], p_max(), "lost"), (&cps[1], -p_max(), "regained")] {
        let got = f(&cp["load_factor"]) * p;
        println!("limit {got:.5} N vs {want:.5} N");
        assert!((got / want - 1.0).abs() < 0.01, "{got} vs {want}");
        assert_eq!(cp["kind"], "limit");
        assert_eq!(cp["stability"], stability);
        assert_eq!(cp["mode"].as_array().map(Vec::len), Some(3));
    }
    let t = &c["trace"];
    assert_eq!(
        (t["node"].as_u64(), t["dof"].as_str(), t["unit"].as_str()),
        (Some(1), Some("uz"), Some("mm"))
    );
    let n = t["load_factor"].as_array().map_or(0, Vec::len);
    assert!(n > 10 && t["value"].as_array().map(Vec::len) == Some(n));
    assert!((f(&t["load_factor"][n - 1]) - 1.0).abs() < 1e-12);
    let csv = std::fs::read_to_string(d.join("out/P_path.csv")).unwrap_or_default();
    assert!(
        csv.starts_with("step,load_factor,uz_1_mm,stable\n") && csv.lines().count() == n + 1,
        "{csv}"
    );
    let svg = std::fs::read_to_string(d.join("out/P_path.svg")).unwrap_or_default();
    assert!(svg.contains("<polyline") && svg.contains("load factor"));
    let vtu = std::fs::read_to_string(d.join("out/P_critical.vtu")).unwrap_or_default();
    assert!(vtu.contains("mode_2_translation_mm") && vtu.contains("load_factor"));
    let md = std::fs::read_to_string(d.join("out/report.md")).unwrap_or_default();
    assert!(md.contains("Critical points") && md.contains("regained"), "{md}");
}

/// The bundled snap-through case: two limit points (lost, regained); each located load factor
/// is the extremum of the traced path next to it (the path's sampled points stay on their side:
/// below the upper limit before it, above the lower limit after it, within the 1e-4 bracket).
#[test]
fn bundled_shallow_arch_limits_bound_the_traced_path() {
    let d = tempdir("arc_arch");
    let case = common::root().join("cases/shallow_arch_arc_length.json");
    let out = run_in(&d, &["run", case.to_str().unwrap_or(""), "--out", "out"]);
    assert_eq!(out.status.code(), Some(0), "{}", stderr(&out));
    let v = json_file(&d.join("out/result.json"));
    let c = &v["load_cases"][0];
    let cps = c["critical_points"].as_array().cloned().unwrap_or_default();
    assert_eq!(cps.len(), 2);
    let (up, down) = (f(&cps[0]["load_factor"]), f(&cps[1]["load_factor"]));
    let lam: Vec<f64> = c["trace"]["load_factor"]
        .as_array()
        .map(|a| a.iter().map(f).collect())
        .unwrap_or_default();
    let stable: Vec<bool> = c["trace"]["stable"]
        .as_array()
        .map(|a| a.iter().map(|b| b.as_bool() == Some(true)).collect())
        .unwrap_or_default();
    let first_unstable = stable.iter().position(|s| !s).unwrap_or(lam.len());
    let max_before = lam[..first_unstable].iter().copied().fold(f64::NEG_INFINITY, f64::max);
    assert_eq!(stable.len(), lam.len(), "one stability flag per trace point");
    let min_unstable = lam[first_unstable..]
        .iter()
        .zip(&stable[first_unstable..])
        .filter(|(_, s)| !**s)
        .map(|(l, _)| *l)
        .fold(f64::INFINITY, f64::min);
    println!("arch: limits {up:.6} / {down:.6}; path max before {max_before:.6}, min while unstable {min_unstable:.6}");
    assert!(max_before <= up * (1.0 + 1e-4) && max_before > 0.9 * up);
    assert!(min_unstable >= down * (1.0 - 1e-4) && min_unstable < 1.2 * down);
    for name in ["crown_path.csv", "crown_path.svg", "crown_critical.vtu", "crown.vtu"] {
        assert!(d.join("out").join(name).is_file(), "{name}");
    }
}

/// Case-file errors name the JSON path, the value and the rule (exit 2).
#[test]
fn path_control_errors_name_the_field() {
    let disp = r#", "displacements": [{"node": 1, "dof": "ux", "value": 0.1}], "control": "arc_length""#;
    for (extra, nonlinear, path) in [
        (r#", "control": "arc_length""#, false, "load_cases[0].control"),
        (r#", "trace": {"node": 1, "dof": "uz"}"#, false, "load_cases[0].trace"),
        (r#", "arc_length": {"initial": 0.1}"#, true, "load_cases[0].arc_length"),
        (
            r#", "control": "arc_length", "arc_length": {"initial": -1}"#,
            true,
            "load_cases[0].arc_length.initial",
        ),
        (
            r#", "control": "arc_length", "arc_length": {"initial": 0.1, "min": 0.5}"#,
            true,
            "load_cases[0].arc_length.min",
        ),
        (
            r#", "control": "arc_length", "arc_length": {"target_iterations": 0}"#,
            true,
            "load_cases[0].arc_length.target_iterations",
        ),
        (
            r#", "trace": {"node": 7, "dof": "uz"}"#,
            true,
            "load_cases[0].trace.node",
        ),
        (disp, true, "load_cases[0].control"),
        (r#", "control": "snap""#, true, "control"),
    ] {
        let out = run_case_text("arc_bad", &truss_case(extra, nonlinear));
        assert_eq!(out.status.code(), Some(2), "{extra}: {}", stderr(&out));
        assert!(stderr(&out).contains(path), "{extra}: {}", stderr(&out));
    }
}

/// Arc-length bounds the solve cannot use (min above max or above the initial arc length,
/// given or defaulted: initial 1/steps, max 20 × initial) are refused by `check` and `run` alike
/// with exit 2 at `arc_length.min`, naming the bound. Before: `check` passed them and `run`
/// panicked in `f64::clamp` (exit 101).
#[test]
fn arc_length_bounds_refused_at_check() {
    let arc = |a: &str| format!(r#", "control": "arc_length", "arc_length": {a}"#);
    for (extra, steps, rule) in [
        (arc(r#"{"min": 0.5, "max": 0.1}"#), None, "must not exceed `max` (0.1)"),
        // steps 50: initial 0.02, max 0.4 by default.
        (
            arc(r#"{"min": 0.5}"#),
            Some(50),
            "must not exceed the default `max` (20 × initial = 4e-1)",
        ),
        (
            arc(r#"{"min": 0.5, "max": 1}"#),
            None,
            "must not exceed the default `initial` (1/steps = 5e-2)",
        ),
    ] {
        let mut text = truss_case(&extra, true);
        if let Some(n) = steps {
            text = text.replacen(
                r#""nonlinear": true,"#,
                &format!(r#""nonlinear": true, "steps": {n},"#),
                1,
            );
        }
        let d = tempdir("arc_bounds");
        let p = d.join("case.json");
        std::fs::write(&p, &text).unwrap();
        for cmd in ["check", "run"] {
            let out = run_in(&d, &[cmd, p.to_str().unwrap()]);
            let err = stderr(&out);
            assert_eq!(out.status.code(), Some(2), "{cmd} {extra}: {err}");
            assert!(err.contains("load_cases[0].arc_length.min"), "{cmd} {extra}: {err}");
            assert!(err.contains("0.5") && err.contains(rule), "{cmd} {extra}: {err}");
        }
        common::cleanup(&d);
    }
}

/// Arc length on a model with every DOF supported: a clear analysis error naming the load case
/// and step (exit 1), not a panic (before: `Vec::remove(0)` on the empty solution, exit 101).
#[test]
fn arc_length_without_free_dof_is_an_error() {
    let text = truss_case(r#", "control": "arc_length""#, true).replace(
        r#"{"node": 1, "fix": ["uy", "rx", "rz"]}"#,
        r#"{"node": 1, "fix": ["ux", "uy", "uz", "rx", "ry", "rz"]}, {"node": 0, "fix": ["ry"]}, {"node": 2, "fix": ["ry"]}"#,
    );
    let out = run_case_text("arc_no_dof", &text);
    let err = stderr(&out);
    assert_eq!(out.status.code(), Some(1), "{err}");
    assert!(err.contains("load case \"P\"") && err.contains("step 1"), "{err}");
    assert!(err.contains("no free degree of freedom"), "{err}");
}
