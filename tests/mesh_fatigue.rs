//! High-cycle fatigue of the `hinge` elements of a `static` model (`"fatigue"` of the case) and
//! the `fatigue_stroke` metric, against the `hinge` analysis's fatigue of the same hinge under
//! the same moment (Budynas & Nisbett, Shigley's Mechanical Engineering Design, 10th ed.
//! (2015), ch. 6, as in `tests/hinge_fatigue.rs`); the errors of the block and the metric.
//!
//! The hinge: the Ruiz et al. (2019) revolute notch, Al 7075-T6, R = 8 mm, t = 2 mm,
//! w = h = 10 mm, 20 mm of blank on each side in both analyses (the mesh element spans
//! 16 + 2 × 20 = 56 mm, so its compliance is that of the hinge analysis), clamped at one end,
//! a moment M = 2000 N·mm about the compliant axis at the other. Both evaluate the same
//! closed-form steps on the same stress model in different code: they agree to ~1e-15;
//! `TOL` = 1e-9.

mod common;

const TOL: f64 = 1e-9;
const MOMENT: f64 = 2000.0;

fn rel(a: f64, b: f64) -> f64 {
    (a / b - 1.0).abs()
}

fn num(v: &serde_json::Value) -> f64 {
    v.as_f64().unwrap_or_else(|| panic!("not a number: {v}"))
}

fn mesh_case(material: &str, fatigue: &str, metrics: &str, extra: &str) -> String {
    format!(
        r#"{{"analysis": "static", "materials": {{"m": {material}}},
            "nodes": [[0, 0, 0], [56, 0, 0]],
            "elements": [{{"type": "hinge", "nodes": [0, 1], "material": "m", "up": [0, 0, 1],
                "hinge": {{"type": "circular_notch", "R": 8, "t": 2, "w": 10, "h": 10}}}}],
            "supports": [{{"node": 0, "fix": ["ux", "uy", "uz", "rx", "ry", "rz"]}}],
            "load_cases": [{{"name": "bend", "forces": [{{"node": 1, "F": [0, 0, 0, 0, {MOMENT}, 0]}}]}}],
            "metrics": {metrics}{fatigue}{extra}}}"#
    )
}

fn run_ok(name: &str, text: &str) -> serde_json::Value {
    let o = common::run_case_text(name, text);
    assert!(o.status.success(), "{}", common::stderr(&o));
    serde_json::from_slice(&o.stdout).unwrap()
}

/// The `hinge` analysis of the same hinge with a rotation `stroke` (degrees) and `cycles`.
fn hinge_analysis(stroke: Option<f64>, cycles: f64) -> serde_json::Value {
    let fatigue = stroke.map_or(String::new(), |s| {
        format!(r#", "fatigue": {{"cycles": {cycles:e}, "stroke": {s:e}, "mean": 0}}"#)
    });
    run_ok(
        "mesh_fatigue_hinge",
        &format!(
            r#"{{"analysis": "hinge", "material": "Al7075",
                "hinge": {{"type": "circular_notch", "R": 8, "t": 2, "w": 10, "h": 10, "blank_length": 20}}{fatigue}}}"#
        ),
    )
}

#[test]
fn hinge_element_fatigue_matches_hinge_analysis_under_the_same_moment() {
    let cycles = 1e9; // beyond N_e = 5e8: S_f = S_e, so the metric is the stroke at infinite life
    let k_bend = num(&hinge_analysis(None, cycles)["k_bend"]);
    // The rotation of the hinge analysis under M, degrees (its fatigue stress is proportional).
    let theta = (MOMENT / k_bend).to_degrees();
    let h = hinge_analysis(Some(theta), cycles);
    let metrics = r#"[{"name": "fs", "kind": "fatigue_stroke", "node": 1, "dof": "ry", "load_case": "bend"}]"#;
    let m = run_ok(
        "mesh_fatigue",
        &mesh_case(
            "\"Al7075\"",
            &format!(r#", "fatigue": {{"cycles": {cycles:e}, "load_ratio": -1}}"#),
            metrics,
            "",
        ),
    );
    let row = &m["load_cases"][0]["hinges"][0];
    // Same hinge, same moment: the same fatigue utilisation (fully reversed: σ_a = the peak,
    // σ_m = 0; the hinge analysis's stress is stress_per_moment × k_bend × θ = ... × M).
    let u_mesh = num(&row["fatigue"]["utilisation"]);
    let u_hinge = num(&h["fatigue"]["fatigue_utilisation"]);
    assert!(
        rel(u_mesh, u_hinge) < TOL,
        "utilisation {u_mesh} vs hinge analysis {u_hinge}"
    );
    assert!(rel(num(&row["fatigue"]["kf"]), num(&h["fatigue"]["kf"])) < TOL, "K_f");
    // The metric's load: the moment at fatigue utilisation 1 (cycles beyond the knee: infinite
    // life), = the hinge analysis's stroke at infinite life times its k_bend.
    let load = num(&m["metrics"]["fs"]["load"]);
    let want = num(&h["fatigue"]["stroke_infinite_life"]).to_radians() * k_bend;
    assert!(
        rel(load, want) < TOL,
        "fatigue_stroke load {load} N·mm vs hinge analysis {want} N·mm"
    );
    assert_eq!(m["metrics"]["fs"]["element"].as_u64(), Some(0));
    // Its stroke: the element's own rotation scaled by the same factor (the element's
    // compliance, not the hinge analysis's k_bend: they differ by 0.34 % here, see the report).
    let fs = num(&m["metrics"]["fs"]["stroke"]);
    let rot = num(&row["rotation_deg"]);
    assert!(
        rel(fs.abs(), rot.abs() / u_mesh) < TOL,
        "fatigue_stroke {fs}° vs {rot}°/{u_mesh}"
    );
}

#[test]
fn mesh_fatigue_errors_name_the_path() {
    let metric = r#"[{"kind": "fatigue_stroke", "node": 1, "dof": "ry", "load_case": "bend"}]"#;
    let block = r#", "fatigue": {"cycles": 1e7}"#;
    for (text, needles) in [
        // The metric without the block.
        (
            mesh_case("\"Al7075\"", "", metric, ""),
            vec!["metrics[0].kind", "\"fatigue\" block"],
        ),
        // In a nonlinear run.
        (
            mesh_case("\"Al7075\"", block, metric, r#", "nonlinear": true"#),
            vec!["metrics[0].kind", "linear runs only"],
        ),
        // A hinge material without fatigue data.
        (
            mesh_case(r#"{"E": 3300, "nu": 0.33, "yield": 80}"#, block, "[]", ""),
            vec!["elements[0].material.fatigue"],
        ),
        // A stress ratio outside [−1, 1).
        (
            mesh_case(
                "\"Al7075\"",
                r#", "fatigue": {"cycles": 1e7, "load_ratio": -2}"#,
                "[]",
                "",
            ),
            vec!["fatigue.load_ratio"],
        ),
    ] {
        let dir = common::tempdir("mesh_fatigue_errors");
        let path = common::write(&dir, "case.json", &text);
        let p = path.to_str().unwrap();
        common::exits_2(&common::run(&["run", p]), &needles);
        common::exits_2(&common::run(&["check", p]), &needles);
        common::cleanup(&dir);
    }
}

/// `sensitivity` rows through the `fatigue_stroke` metric (the lever amplifier of
/// `meshes/lever_parameters.json`, +10 % on the notch t and R): the fatigue limit and the static
/// limit scale with the same hinge stress per stroke, and differ only through K_f/K_t and the
/// size factor (both functions of t and R), so their elasticities agree to 0.02 (measured:
/// R +0.4953 vs +0.4918, t −0.5034 vs −0.4972), and follow the thin-notch closed form of the
/// rotation at a stress limit, θ ∝ √R/√t (elasticity +0.5 in R, −0.5 in t; Paros & Weisbord,
/// "How to design flexure hinges", Machine Design 37 (1965) 151–156) to 0.02.
#[test]
fn sensitivity_rows_through_the_fatigue_metric() {
    let mesh = common::root().join("meshes/lever_parameters.json");
    let text = format!(
        r#"{{"analysis": "sensitivity",
            "case": {{"analysis": "static", "mesh": {mesh:?},
                "load_cases": [{{"name": "s", "displacements": [{{"node": 2, "dof": "uy", "value": 0.01}}]}}],
                "fatigue": {{"cycles": 1e7, "load_ratio": 0}},
                "metrics": [
                    {{"name": "static", "kind": "stroke_at_allowable", "node": 2, "dof": "uy", "load_case": "s"}},
                    {{"name": "fatigue", "kind": "fatigue_stroke", "node": 2, "dof": "uy", "load_case": "s"}}]}},
            "parameters": {{"t": {{}}, "R": {{}}}}, "increment": 0.1}}"#
    );
    let r = run_ok("mesh_fatigue_sensitivity", &text);
    let rows = r["rows"].as_array().unwrap();
    assert_eq!(rows.len(), 2);
    for row in rows {
        let e = &row["elasticity"];
        let (st, fa) = (num(&e["static"]), num(&e["fatigue"]));
        let closed_form = if row["parameter"] == "t" { -0.5 } else { 0.5 };
        assert!(
            (st - fa).abs() < 0.02,
            "{}: static {st} vs fatigue {fa}",
            row["parameter"]
        );
        assert!(
            (fa - closed_form).abs() < 0.02,
            "{}: fatigue {fa} vs {closed_form}",
            row["parameter"]
        );
    }
}

/// A mesh `design` with a `fatigue_stroke` requirement: the parallelogram guide of
/// `meshes/parallelogram_parameters.json` (t, L varied) made as stiff out of plane (k_z) as
/// possible for a fatigue-limited stroke ≥ 2 mm at 10⁷ cycles of R = 0. The requirement binds;
/// the design rerun as a plain static case has the reported fatigue-limited stroke (the same
/// computation, `RERUN_TOL` 1e-9 relative) and meets it; the direct-method gradient of the
/// metric in t (K_t, Peterson's q and the size factor move with t) matches central differences
/// of full static runs (h = 1e-4 mm, truncation ~1e-8; `GRADIENT_TOL` 1e-5 relative, measured
/// 2.5e-8).
#[test]
fn mesh_design_with_a_fatigue_stroke_requirement_meets_it_when_rerun() {
    const RERUN_TOL: f64 = 1e-9;
    const GRADIENT_TOL: f64 = 1e-5;
    let mesh = common::root().join("meshes/parallelogram_parameters.json");
    let inner = |params: &str| {
        format!(
            r#"{{"analysis": "static", "mesh": {mesh:?}, "parameters": {{{params}}},
                "load_cases": [{{"name": "stroke_1mm", "displacements": [{{"node": 8, "dof": "ux", "value": 1}}]}}],
                "fatigue": {{"cycles": 1e7, "load_ratio": 0, "method": "goodman"}},
                "metrics": [
                    {{"name": "stroke_fatigue", "kind": "fatigue_stroke", "node": 8, "dof": "ux", "load_case": "stroke_1mm"}},
                    {{"name": "k_z", "kind": "stiffness", "node": 8, "dof": "uz"}}]}}"#
        )
    };
    let design = format!(
        r#"{{"analysis": "design", "case": {},
            "parameters": {{"t": {{"bounds": [0.5, 2.0]}}, "L": {{"bounds": [50.0, 120.0]}}}},
            "requirements": [{{"metric": "stroke_fatigue", "min": 2.0}}],
            "objective": {{"maximise": "k_z"}}, "samples": 8}}"#,
        inner("")
    );
    let v = run_ok("mesh_design_fatigue", &design);
    assert_eq!(v["meets"], true, "{}", v["message"]);
    assert_eq!(
        v["binding"],
        serde_json::json!(["stroke_fatigue_min"]),
        "{}",
        v["binding"]
    );
    assert_eq!(v["gradients"]["method"], "direct");
    let (t, l) = (num(&v["design"]["t"]), num(&v["design"]["L"]));
    let stroke_at = |t: f64| {
        let r = run_ok(
            "mesh_design_fatigue_rerun",
            &inner(&format!(r#""t": {t:e}, "L": {l:e}"#)),
        );
        num(&r["metrics"]["stroke_fatigue"]["stroke"])
    };
    let rerun = stroke_at(t);
    let reported = num(&v["metrics"]["stroke_fatigue"]);
    assert!(
        (rerun / reported - 1.0).abs() < RERUN_TOL,
        "rerun {rerun} mm vs design {reported} mm"
    );
    assert!(rerun >= 2.0, "fatigue-limited stroke {rerun} mm < 2 mm");
    let h = 1e-4;
    let fd = (stroke_at(t + h) - stroke_at(t - h)) / (2.0 * h);
    let g = num(&v["gradients"]["values"]["stroke_fatigue"]["t"]);
    assert!(
        (g / fd - 1.0).abs() < GRADIENT_TOL,
        "d stroke_fatigue / dt: direct {g} vs central differences {fd}"
    );
}
