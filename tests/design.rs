//! The design loop: Table 1 sensitivities (Ruiz et al. (2019)) and requirement-driven sizing.

mod common;
use common::*;

fn run_json_text(name: &str, text: &str) -> (Option<i32>, serde_json::Value, String) {
    let out = run_case_text(name, text);
    let v = serde_json::from_str(&stdout(&out)).unwrap_or(serde_json::Value::Null);
    (out.status.code(), v, stderr(&out))
}

fn row<'a>(v: &'a serde_json::Value, p: &str) -> &'a serde_json::Value {
    v["rows"]
        .as_array()
        .unwrap()
        .iter()
        .find(|r| r["parameter"] == p)
        .unwrap()
}

fn f(v: &serde_json::Value) -> f64 {
    v.as_f64().unwrap()
}

/// Ruiz et al. (2019) Table 1 and §5 text: "an increase in the thickness of the revolute joint
/// causes a significant increment in the stiffness of the structure, by a factor greater than
/// 1.5, while the Z displacement and the relation of maximum stresses in the joints suffer a
/// slighter reduction with a factor of 0.8. By contrast, an increase in the length of the
/// spherical joint causes a tinier reduction of the structural stiffness, an important increase
/// of the Z displacement and a notable reduction of the relation of maximum stresses."
///
/// The entries this model reproduces from the paper's design (each parameter +50 %), asserted
/// as the paper states them. The two it does not (T under t_rev ↑, d under l_sph ↑) are pinned
/// in the tests below.
#[test]
fn table1_directions_from_the_paper_design() {
    let out = run(&["run", "cases/ruiz2019_sensitivity.json"]);
    assert_eq!(out.status.code(), Some(0), "{}", stderr(&out));
    let v: serde_json::Value = serde_json::from_str(&stdout(&out)).unwrap();
    let t = row(&v, "t_rev");
    assert_eq!(t["bins"]["stiffness"], "> 1.5", "{t}");
    assert_eq!(t["bins"]["displacement"], "0.8-1", "{t}");
    assert_eq!(t["bins"]["stress_ratio"], "0.8-1", "{t}");
    let l = row(&v, "l_sph");
    assert_eq!(l["bins"]["stiffness"], "0.8-1", "{l}");
    assert!(f(&l["stiffness_ratio"]) > 0.9, "lowers η only a little: {l}");
    assert!(f(&l["stress_ratio_ratio"]) < 0.85, "lowers T notably: {l}");
}

/// Absolute tolerance on the pinned ratios below (they are computed to ~1e-12; the pin shows a
/// change of the model, not noise).
const TABLE1_PIN_TOL: f64 = 0.005;

/// Table 1 entries this model does NOT reproduce, pinned at what it gives (regressions, not
/// claims; the README says which and why):
/// - t_rev ↑: T × 0.984 (bin 0.8–1 as printed, but not the text's "factor of 0.8");
/// - l_sph ↑: d × 1.005, not 1.2–1.5. In this model the revolute notch is already the most
///   stressed hinge of the paper's design (T = 0.948), and d is the Δz at which the most
///   stressed hinge reaches the allowable: unloading the neck cannot raise it.
#[test]
fn table1_entries_not_reproduced() {
    let out = run(&["run", "cases/ruiz2019_sensitivity.json"]);
    assert_eq!(out.status.code(), Some(0), "{}", stderr(&out));
    let v: serde_json::Value = serde_json::from_str(&stdout(&out)).unwrap();
    let pin = |what: &str, got: f64, want: f64| {
        eprintln!("{what}: {got:.4} (pinned {want})");
        assert!((got - want).abs() < TABLE1_PIN_TOL, "{what}: {got} vs pinned {want}");
    };
    pin("base T", f(&v["base"]["T"]), 0.948);
    pin("t_rev ↑: T ratio", f(&row(&v, "t_rev")["stress_ratio_ratio"]), 0.984);
    pin("l_sph ↑: d ratio", f(&row(&v, "l_sph")["displacement_ratio"]), 1.005);
    assert_eq!(row(&v, "l_sph")["bins"]["displacement"], "1-1.2");
}

/// The paper's "important increase" of d with l_sph (bin 1.2–1.5) is not reached even from a
/// design whose neck is clearly critical: with t_sph = 5 mm (T = 1.156) a neck 50 % longer
/// raises d by 1.170 (bin 1–1.2), lowers T notably (× 0.838) and η a little — the gain is capped
/// near the base T, where the revolute notch becomes the most stressed hinge. (With t_sph = 4:
/// T = 1.081, d × 1.088.) Pinned, not claimed.
#[test]
fn lengthening_a_critical_neck_raises_d_but_not_into_the_papers_bin() {
    let text = std::fs::read_to_string(root().join("cases/ruiz2019_sensitivity.json")).unwrap();
    let text = text.replace("\"t\": 3,", "\"t\": 5,");
    let (code, v, err) = run_json_text("critical_neck", &text);
    assert_eq!(code, Some(0), "{err}");
    let l = row(&v, "l_sph");
    eprintln!("t_sph 5: base T {}, l_sph ↑: {l}", v["base"]["T"]);
    assert!((f(&v["base"]["T"]) - 1.156).abs() < TABLE1_PIN_TOL, "{}", v["base"]);
    assert!((f(&l["displacement_ratio"]) - 1.170).abs() < TABLE1_PIN_TOL, "{l}");
    assert_eq!(l["bins"]["displacement"], "1-1.2", "{l}");
    assert!(f(&l["stress_ratio_ratio"]) < 0.85, "{l}");
    assert_eq!(l["bins"]["stiffness"], "0.8-1", "{l}");
}

#[test]
fn design_meets_the_paper_requirements_verified_by_a_stage_run() {
    // Ruiz et al. (2019) §4: Δz ≥ ±2 mm with σ ≤ 400 MPa, T ∈ [0.8, 1.2], hinges reaching the joint
    // rotations of the requirement sweep below 400 MPa.
    let out = run(&["run", "cases/ruiz2019_design.json"]);
    assert_eq!(out.status.code(), Some(0), "{}", stderr(&out));
    let v: serde_json::Value = serde_json::from_str(&stdout(&out)).unwrap();
    assert_eq!(v["meets"], true, "{}", v["message"]);
    let d = &v["design"];
    // Re-run the returned design through the `stage` analysis.
    let stage = fixtures::ruiz2019_stage_with(|case| {
        let s = &mut case["stage"];
        s["revolute"] = serde_json::json!({"type": "circular_notch", "R": d["R_rev"], "t": d["t_rev"]});
        s["spherical"] =
            serde_json::json!({"type": "spherical_neck", "l": d["l_sph"], "t": d["t_sph"], "R": d["R_sph"]});
        case["load_cases"] = serde_json::json!([{"name": "F", "actuator_forces": [20, 20, 20]}]);
    });
    let (code, s, err) = run_json_text("verify_design", &stage);
    assert_eq!(code, Some(0), "{err}");
    let z = f(&s["at_allowable"]["z"]);
    assert!(z >= 2.0 - 1e-9, "Δz at 400 MPa {z}");
    let t = f(&s["load_cases"][0]["T"]);
    assert!((0.8..=1.2).contains(&t), "T {t}");
    // The stage run and the design loop agree on the responses.
    assert!((z / f(&v["responses"]["z_at_allowable"]) - 1.0).abs() < 1e-6);
    assert!((f(&s["stiffness_z"]) / f(&v["responses"]["eta"]) - 1.0).abs() < 1e-6);
    // It is stiffer than the paper's own design (68.4 N/mm in this model), which misses d ≥ 2.
    assert!(f(&v["responses"]["eta"]) > 68.4);
}

#[test]
fn impossible_requirements_name_the_binding_constraint() {
    let text = std::fs::read_to_string(root().join("cases/ruiz2019_design.json")).unwrap();
    let text = text
        .replace("\"z_travel\": 2", "\"z_travel\": 20")
        .replace("\"allowable\": 400", "\"allowable\": 400, \"tilt_deg\": 0.2");
    let text = text.replace(
        "{\"analysis\": \"design\",",
        "{\"analysis\": \"design\", \"samples\": 64,",
    );
    let (code, v, err) = run_json_text("impossible", &text);
    assert_eq!(code, Some(0), "{err}");
    assert_eq!(v["meets"], false);
    let msg = v["message"].as_str().unwrap();
    assert!(msg.contains("z_travel") || msg.contains("rotation_stress"), "{msg}");
}

#[test]
fn stage_sweep_writes_lines_csv_and_plot() {
    // Issue 7: stage sweeps through `flexfem sweep`, `--out` gives CSV plus an SVG plot.
    let d = tempdir("stage_sweep");
    let case = root().join("cases/ruiz2019_stage_sweep.json");
    run_ok_in(&d, &["sweep", case.to_str().unwrap(), "--out", "s.jsonl"]);
    let lines = std::fs::read_to_string(d.join("s.jsonl")).unwrap();
    assert_eq!(lines.lines().count(), 256);
    // The design with the paper's hinges (t_rev 2, R_rev 8, t_sph 3, l_sph 5) equals a direct
    // stage run: 68.4 N/mm (see tests/stage.rs for the Table 2 comparison).
    let paper = lines
        .lines()
        .map(|l| serde_json::from_str::<serde_json::Value>(l).unwrap())
        .find(|v| {
            let p = &v["params"];
            p["stage.revolute.t"] == 2.0
                && p["stage.revolute.R"] == 8
                && p["stage.spherical.t"] == 3.0
                && p["stage.spherical.l"] == 5
        })
        .unwrap();
    let direct = run(&["run", "cases/ruiz2019_stage.json"]);
    let dv: serde_json::Value = serde_json::from_str(&stdout(&direct)).unwrap();
    assert!((f(&paper["result"]["stiffness_z"]) / f(&dv["stiffness_z"]) - 1.0).abs() < 1e-9);
    let csv = std::fs::read_to_string(d.join("s.csv")).unwrap();
    assert_eq!(csv.lines().count(), 257);
    assert!(csv.lines().next().unwrap().contains("stiffness_z"));
    let svg = std::fs::read_to_string(d.join("s.svg")).unwrap();
    assert!(svg.starts_with("<svg") && svg.matches("<circle").count() == 256);
}
