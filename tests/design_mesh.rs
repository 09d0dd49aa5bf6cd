//! `sensitivity` and `design` of static mesh cases (`"case"`): the design found meets its
//! requirements when rerun as a plain static case, sensitivity ratios follow the scaling laws
//! of the mechanism, and bad cases are refused with the JSON path (exit 2, `run` and `check`).

mod common;
use common::*;
use serde_json::{json, Value};

fn mesh(name: &str) -> String {
    root().join("meshes").join(name).to_string_lossy().into_owned()
}

fn run_value(name: &str, case: &Value) -> Value {
    let out = run_case_text(name, &case.to_string());
    assert_eq!(out.status.code(), Some(0), "{}", stderr(&out));
    serde_json::from_str(&stdout(&out)).unwrap()
}

fn num(v: &Value) -> f64 {
    v.as_f64().unwrap_or_else(|| panic!("not a number: {v}"))
}

/// The parallelogram guide with a stroke and two stiffness metrics (node 8 is the stage).
fn guide_case(t: f64) -> Value {
    json!({
        "analysis": "static",
        "mesh": mesh("parallelogram_parameters.json"),
        "parameters": {"t": t},
        "load_cases": [{"name": "stroke_1mm", "displacements": [{"node": 8, "dof": "ux", "value": 1}]}],
        "metrics": [
            {"name": "stroke", "kind": "stroke_at_allowable", "node": 8, "dof": "ux", "load_case": "stroke_1mm"},
            {"name": "k_x", "kind": "stiffness", "node": 8, "dof": "ux"},
            {"name": "k_z", "kind": "stiffness", "node": 8, "dof": "uz"}
        ]
    })
}

/// Relative agreement of a rerun with the design's own metrics: the same computation on the
/// same numbers.
const RERUN_TOL: f64 = 1e-9;

/// `cases/parallelogram_design.json`: the reported design, rerun as a plain static case with
/// those parameter values, meets every requirement (stroke ≥ 2 mm at the allowable, k_z ≥
/// 250 N/mm) and gives the metrics the design reports.
#[test]
fn parallelogram_design_rerun_as_a_static_case_meets_every_requirement() {
    let out = run(&["run", "cases/parallelogram_design.json"]);
    assert_eq!(out.status.code(), Some(0), "{}", stderr(&out));
    let d: Value = serde_json::from_str(&stdout(&out)).unwrap();
    assert_eq!(d["meets"], true, "{}", d["message"]);
    // A linear case with stiffness and stroke metrics: the sizing uses the direct-method
    // gradients (crate::gradient::Linear), checked against full-run differences in tests/gradients.rs.
    assert_eq!(d["gradients"]["method"], "direct");
    let mut case = guide_case(0.0);
    for k in ["t", "R", "L"] {
        case["parameters"][k] = d["design"][k].clone();
    }
    let r = run_value("design_mesh_rerun", &case);
    let stroke = num(&r["metrics"]["stroke"]["stroke"]);
    let k_z = num(&r["metrics"]["k_z"]);
    assert!(stroke >= 2.0, "stroke {stroke} mm < 2 mm");
    assert!(k_z >= 250.0, "k_z {k_z} N/mm < 250 N/mm");
    for (got, key) in [(stroke, "stroke"), (k_z, "k_z"), (num(&r["metrics"]["k_x"]), "k_x")] {
        let want = num(&d["metrics"][key]);
        assert!(
            ((got - want) / want).abs() < RERUN_TOL,
            "{key}: rerun {got} vs design {want}"
        );
    }
    // Each requirement reported at its limit or above.
    let cons = d["constraints"].as_array().unwrap();
    assert_eq!(cons.len(), 2);
    for c in cons {
        assert!(num(&c["violation"]) <= 0.0, "{c}");
    }
    // The gradients at the design (the local search's last Jacobian when it was taken there)
    // are those of the rerun with `"gradients": true` at the design's parameter values.
    case["gradients"] = json!(true);
    let g = run_value("design_mesh_rerun_gradients", &case);
    let mut compared = 0;
    for metric in ["stroke", "k_x", "k_z"] {
        for p in ["t", "R", "L"] {
            let (got, want) = (
                num(&d["gradients"]["values"][metric][p]),
                num(&g["gradients"][metric][p]),
            );
            assert!(
                (got - want).abs() <= RERUN_TOL * want.abs(),
                "d {metric}/d {p}: design {got} vs rerun {want}"
            );
            compared += 1;
        }
    }
    assert_eq!(compared, 9);
}

/// Relative tolerance of the ratios against the ideal-pivot parallelogram (hinge centres L
/// apart): k_x = 4 k_θ / L² and stroke = L·θ_allow, so +10 % on L gives k_x × 1/1.21 and
/// stroke × 1.1. The notch's own shear and axial compliance is what departs (measured 8e-5
/// and 2e-5).
const PIVOT_TOL: f64 = 1e-3;

/// Relative tolerance against the thin-notch scaling of Paros & Weisbord (1965), "How to design
/// flexure hinges", Machine Design 37(27), 151–156: k_θ = 2Ewt^{5/2}/(9πR^{1/2}) and, with the
/// peak stress σ = 6M/(wt²), θ_allow ∝ R^{1/2} t^{−1/2}. At t/R = 0.1 the full formula departs
/// from the limit by 0.1–0.5 % per 10 % step (measured 0.44 % for k_x under t).
const THIN_NOTCH_TOL: f64 = 0.01;

/// Sensitivity of the parallelogram guide (t = 0.5, R = 5, L = 100 mm): the ratio of each
/// metric under +10 % of L, t and R against the scaling laws above.
#[test]
fn parallelogram_sensitivity_follows_the_pivot_and_notch_scaling() {
    let case = json!({
        "analysis": "sensitivity",
        "case": guide_case(0.5),
        "parameters": {"t": {}, "R": {}, "L": {}},
        "increment": 0.1
    });
    let v = run_value("design_mesh_sensitivity", &case);
    let rows = v["rows"].as_array().unwrap();
    assert_eq!(rows.len(), 3);
    let ratio = |p: &str, m: &str| {
        let row = rows.iter().find(|r| r["parameter"] == p).unwrap();
        num(&row["ratios"][m])
    };
    let check = |got: f64, want: f64, tol: f64, what: &str| {
        assert!(((got - want) / want).abs() < tol, "{what}: {got} vs {want}");
    };
    let s = 1.1f64;
    check(ratio("L", "k_x"), 1.0 / (s * s), PIVOT_TOL, "k_x under L");
    check(ratio("L", "stroke"), s, PIVOT_TOL, "stroke under L");
    check(ratio("t", "k_x"), s.powf(2.5), THIN_NOTCH_TOL, "k_x under t");
    check(ratio("t", "stroke"), s.powf(-0.5), THIN_NOTCH_TOL, "stroke under t");
    check(ratio("R", "k_x"), s.powf(-0.5), THIN_NOTCH_TOL, "k_x under R");
    check(ratio("R", "stroke"), s.powf(0.5), THIN_NOTCH_TOL, "stroke under R");
}

/// Tolerance on the lever's kinematic ratios: the output of a rigid lever is b/a times the
/// input, and its input stiffness Σk_θ/a²; the notches' own translation departs by < 0.2 %
/// (measured 7e-5 for b, 1.4e-3 for k_in under a).
const LEVER_KINEMATIC_TOL: f64 = 2e-3;

/// `cases/lever_sensitivity.json`: +10 % on the output arm b scales the output by 1.1 and leaves
/// the input side alone; +10 % on the input arm a scales the input stiffness by 1/1.21.
#[test]
fn lever_sensitivity_follows_the_lever_arms() {
    let out = run(&["run", "cases/lever_sensitivity.json"]);
    assert_eq!(out.status.code(), Some(0), "{}", stderr(&out));
    let v: Value = serde_json::from_str(&stdout(&out)).unwrap();
    let rows = v["rows"].as_array().unwrap();
    assert_eq!(rows.len(), 4);
    let ratio = |p: &str, m: &str| num(&rows.iter().find(|r| r["parameter"] == p).unwrap()["ratios"][m]);
    assert!((ratio("b", "output_uy") / 1.1 - 1.0).abs() < LEVER_KINEMATIC_TOL);
    assert!((ratio("b", "k_in") - 1.0).abs() < LEVER_KINEMATIC_TOL);
    assert!((ratio("a", "k_in") * 1.21 - 1.0).abs() < LEVER_KINEMATIC_TOL);
    // The base output is the bundled lever's (same model): 0.0496497 mm per 10 µm of input.
    assert!((num(&v["base"]["output_uy"]) / 0.049649688287002815 - 1.0).abs() < 1e-12);
}

fn design_case() -> Value {
    json!({
        "analysis": "design",
        "case": guide_case(1.0),
        "parameters": {"t": {"bounds": [0.5, 2.0]}, "L": {"bounds": [60.0, 120.0]}},
        "requirements": [{"metric": "stroke", "min": 2.0}],
        "objective": {"minimise": "k_x"},
        "samples": 4
    })
}

/// Each bad design case is refused by `run` and `check` alike, exit 2, at the JSON path.
#[test]
fn bad_design_cases_are_refused_with_the_path() {
    let mut cases: Vec<(Value, &str, &str)> = Vec::new();
    let mut c = design_case();
    c["parameters"]["zz"] = json!({"bounds": [1, 2]});
    cases.push((c, "parameters.zz", "not a parameter of the case"));
    let mut c = design_case();
    c["requirements"][0]["metric"] = json!("strok");
    cases.push((c, "requirements[0].metric", "must name a metric"));
    let mut c = design_case();
    c["objective"] = json!({"maximise": "k_q"});
    cases.push((c, "objective.maximise", "must name a metric"));
    let mut c = design_case();
    c["parameters"]["t"]["bounds"] = json!([2.0, 2.0]);
    cases.push((c, "parameters.t.bounds", "lo < hi"));
    let mut c = design_case();
    c["parameters"]["t"]["bounds"] = json!([1.5, 2.0]);
    cases.push((c, "parameters.t.bounds", "declared value t = 1"));
    let mut c = design_case();
    c["case"]["analysis"] = json!("modal");
    cases.push((c, "case.analysis", "must be a \"static\" case"));
    let mut c = design_case();
    c["case"].as_object_mut().unwrap().remove("metrics");
    cases.push((c, "case.metrics", "no metrics"));
    let mut c = design_case();
    c["parameters"]["t"].as_object_mut().unwrap().remove("bounds");
    cases.push((c, "parameters.t.bounds", "is required"));
    assert_eq!(cases.len(), 8);
    for (i, (case, path, needle)) in cases.iter().enumerate() {
        let d = tempdir(&format!("design_mesh_bad_{i}"));
        let p = write(&d, "case.json", &case.to_string());
        for cmd in ["run", "check"] {
            let o = run_in(&d, &[cmd, p.to_str().unwrap()]);
            let err = exits_2(&o, &[path, needle]);
            assert!(!err.contains("panicked"), "{err}");
        }
        cleanup(&d);
    }
}

/// A sensitivity case names its parameters like a design (unknown name → exit 2 at the path).
#[test]
fn sensitivity_of_an_unknown_parameter_is_refused() {
    let case = json!({
        "analysis": "sensitivity",
        "case": guide_case(0.5),
        "parameters": {"thickness": {}}
    });
    let o = run_case_text("design_mesh_sens_unknown", &case.to_string());
    exits_2(&o, &["parameters.thickness", "declared: B, L, R, s, t, w"]);
}

/// Relative tolerance on the thickness recovered by `match_compliance`: the target is the
/// guide's own compliance at t = 0.8 mm, so the least-squares optimum is t = 0.8 exactly; the
/// search stops within its finite-difference and line-search resolution.
const MATCH_TOL: f64 = 0.01;

/// `match_compliance` recovers the notch thickness whose 6×6 compliance at the stage is the
/// target (computed by a plain static run at t = 0.8 mm).
#[test]
fn match_compliance_recovers_the_thickness_of_the_target() {
    let mut probe = guide_case(0.8);
    probe["compliance"] = json!([{"node": 8}]);
    let r = run_value("design_mesh_match_probe", &probe);
    let target = r["compliance"][0]["matrix"].clone();
    assert_eq!(target.as_array().map(Vec::len), Some(6));
    let case = json!({
        "analysis": "design",
        "case": guide_case(1.0),
        "parameters": {"t": {"bounds": [0.5, 1.5]}},
        "objective": {"match_compliance": {"node": 8, "target": target}},
        "samples": 8
    });
    let d = run_value("design_mesh_match", &case);
    let t = num(&d["design"]["t"]);
    assert!((t / 0.8 - 1.0).abs() < MATCH_TOL, "t = {t} mm, target made at 0.8 mm");
    assert!(num(&d["compliance_error"]) < 1e-3, "J = {}", d["compliance_error"]);
}

/// The five parameters of `cases/parallelogram_design_5.json`, in its order.
const DESIGN_5: [&str; 5] = ["t", "R", "w", "L", "B"];

/// The guide of `meshes/parallelogram_platform.json` (a 0.1 kg platform on the stage, node 8)
/// with the parameter values `params` and the metrics of `cases/parallelogram_design_5.json`.
fn platform_case(params: Value) -> Value {
    json!({
        "analysis": "static",
        "mesh": mesh("parallelogram_platform.json"),
        "parameters": params,
        "load_cases": [{"name": "stroke_1mm", "displacements": [{"node": 8, "dof": "ux", "value": 1}]}],
        "metrics": [
            {"name": "stroke", "kind": "stroke_at_allowable", "node": 8, "dof": "ux", "load_case": "stroke_1mm"},
            {"name": "k_x", "kind": "stiffness", "node": 8, "dof": "ux"},
            {"name": "k_z", "kind": "stiffness", "node": 8, "dof": "uz"},
            {"name": "f_1", "kind": "frequency", "mode": 1}
        ]
    })
}

/// Relative agreement of the `frequency` metric with mode 1 of a `modal` run of the same
/// model: two runs of the same eigen-solver at its convergence tolerance.
const MODAL_TOL: f64 = 1e-6;

/// `cases/parallelogram_design_5.json`: the reported design, rerun as a plain static case and as
/// a modal case with its five parameter values, meets every requirement (stroke ≥ 2 mm at the
/// allowable, k_z ≥ 250 N/mm, first frequency ≥ 40 Hz) and gives the metrics the design
/// reports; the search was driven by the direct-method gradients (the frequency by its
/// eigenvalue derivative).
#[test]
fn parallelogram_design_5_rerun_as_static_and_modal_cases_meets_every_requirement() {
    let out = run(&["run", "cases/parallelogram_design_5.json"]);
    assert_eq!(out.status.code(), Some(0), "{}", stderr(&out));
    let d: Value = serde_json::from_str(&stdout(&out)).unwrap();
    assert_eq!(d["meets"], true, "{}", d["message"]);
    assert_eq!(d["gradients"]["method"], "direct");
    assert!(
        d["gradients"]["values"]["f_1"]["L"].as_f64().is_some(),
        "{}",
        d["gradients"]
    );
    let params: serde_json::Map<String, Value> = DESIGN_5
        .iter()
        .map(|k| (k.to_string(), d["design"][k].clone()))
        .collect();
    let r = run_value("design_mesh_5_rerun", &platform_case(Value::Object(params.clone())));
    let stroke = num(&r["metrics"]["stroke"]["stroke"]);
    let (k_z, f_1) = (num(&r["metrics"]["k_z"]), num(&r["metrics"]["f_1"]));
    assert!(stroke >= 2.0, "stroke {stroke} mm < 2 mm");
    assert!(k_z >= 250.0, "k_z {k_z} N/mm < 250 N/mm");
    assert!(f_1 >= 40.0, "f_1 {f_1} Hz < 40 Hz");
    for (got, key) in [
        (stroke, "stroke"),
        (k_z, "k_z"),
        (f_1, "f_1"),
        (num(&r["metrics"]["k_x"]), "k_x"),
    ] {
        let want = num(&d["metrics"][key]);
        assert!(
            ((got - want) / want).abs() < RERUN_TOL,
            "{key}: rerun {got} vs design {want}"
        );
    }
    let modal = json!({
        "analysis": "modal",
        "mesh": mesh("parallelogram_platform.json"),
        "parameters": params,
        "modes": 2,
        "shapes": false
    });
    let m = run_value("design_mesh_5_modal", &modal);
    let f = num(&m["modes"][0]["frequency_hz"]);
    assert!(f >= 40.0, "modal f_1 {f} Hz < 40 Hz");
    assert!(((f - f_1) / f_1).abs() < MODAL_TOL, "modal {f} Hz vs metric {f_1} Hz");
    let cons = d["constraints"].as_array().unwrap();
    assert_eq!(cons.len(), 3);
    for c in cons {
        assert!(num(&c["violation"]) <= 0.0, "{c}");
    }
}

/// Values per parameter of the grid search: the bounds and two interior points, 4⁵ = 1024
/// designs.
const GRID: usize = 4;

/// The gradient-driven sizing of `cases/parallelogram_design_5.json` is at least as good as a
/// coarse grid search over the same bounds (4 evenly spaced values per parameter, bounds
/// included, run by `flexfem sweep`): its k_x is at most the least k_x among the grid designs
/// that meet every requirement.
#[test]
fn parallelogram_design_5_beats_a_coarse_grid_search() {
    let file: Value =
        serde_json::from_str(&std::fs::read_to_string(root().join("cases/parallelogram_design_5.json")).unwrap())
            .unwrap();
    let mut vary = serde_json::Map::new();
    for k in DESIGN_5 {
        let b = &file["parameters"][k]["bounds"];
        let (lo, hi) = (num(&b[0]), num(&b[1]));
        let values: Vec<f64> = (0..GRID)
            .map(|i| lo + (hi - lo) * i as f64 / (GRID - 1) as f64)
            .collect();
        vary.insert(format!("parameters.{k}"), json!(values));
    }
    let declared = json!({"t": 1.0, "R": 5.0, "w": 10.0, "L": 100.0, "B": 40.0});
    let sweep_case = json!({"analysis": "sweep", "base": platform_case(declared), "vary": vary});
    let dir = tempdir("design_mesh_5_grid");
    let p = write(&dir, "grid.json", &sweep_case.to_string());
    let o = sweep(&dir, &[p.to_str().unwrap()]);
    assert_eq!(o.status.code(), Some(0), "{}", stderr(&o));
    let lines = parse_lines(&stdout(&o));
    assert_eq!(lines.len(), GRID.pow(5));
    let feasible: Vec<f64> = lines
        .iter()
        .map(|l| &l["result"]["metrics"])
        .filter(|m| num(&m["stroke"]["stroke"]) >= 2.0 && num(&m["k_z"]) >= 250.0 && num(&m["f_1"]) >= 40.0)
        .map(|m| num(&m["k_x"]))
        .collect();
    assert!(!feasible.is_empty(), "no grid design meets the requirements");
    let grid_best = feasible.iter().copied().fold(f64::INFINITY, f64::min);
    let out = run(&["run", "cases/parallelogram_design_5.json"]);
    assert_eq!(out.status.code(), Some(0), "{}", stderr(&out));
    let d: Value = serde_json::from_str(&stdout(&out)).unwrap();
    let k_x = num(&d["metrics"]["k_x"]);
    println!(
        "design k_x {k_x} N/mm; grid: {} of {} designs feasible, best k_x {grid_best} N/mm",
        feasible.len(),
        lines.len()
    );
    assert!(k_x <= grid_best, "design k_x {k_x} N/mm > grid best {grid_best} N/mm");
    cleanup(&dir);
}

/// A square cantilever's first two bending modes are one repeated eigenvalue: its frequency
/// has no gradient (only one-sided derivatives), so the design's gradients fall back to central
/// differences of full runs and a model note says why. Side a ∈ [5, 15] mm, f_1 ≥ 500 Hz, least
/// tip compliance along x (its axis: any positive metric will do).
#[test]
fn repeated_mode_gradients_fall_back_to_central_differences() {
    let beam = |n: [usize; 2]| json!({"type": "beam", "nodes": n, "section": "sq", "material": "al", "up": [0, 0, 1]});
    let case = json!({
        "analysis": "design",
        "case": {
            "analysis": "static",
            "parameters": {"a": 10.0},
            "materials": {"al": "Al7075"},
            "sections": {"sq": {"shape": "rect", "w": "$a", "h": "$a"}},
            "nodes": [[0, 0, 0], [50, 0, 0], [100, 0, 0]],
            "elements": [beam([0, 1]), beam([1, 2])],
            "supports": [{"node": 0, "fix": ["ux", "uy", "uz", "rx", "ry", "rz"]}],
            "load_cases": [{"name": "tip", "forces": [{"node": 2, "F": [0, 0, -10, 0, 0, 0]}]}],
            "metrics": [
                {"name": "f_1", "kind": "frequency", "mode": 1},
                {"name": "k_ax", "kind": "stiffness", "node": 2, "dof": "ux"}
            ]
        },
        "parameters": {"a": {"bounds": [5.0, 15.0]}},
        "requirements": [{"metric": "f_1", "min": 500.0}],
        "objective": {"minimise": "k_ax"},
        "samples": 4
    });
    let d = run_value("design_mesh_repeated_mode", &case);
    assert_eq!(d["gradients"]["method"], "central_differences", "{}", d["gradients"]);
    let notes = d["model"].as_array().unwrap();
    assert!(
        notes.iter().any(|n| n.as_str().unwrap().contains("mode is repeated")),
        "{notes:?}"
    );
    assert!(num(&d["metrics"]["f_1"]) >= 500.0, "{}", d["metrics"]);
}
