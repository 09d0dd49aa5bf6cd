//! The `pantilt` case and analysis: the bundled case reproduces J. Yu, D. Lu and G. Hao,
//! "Design and analysis of a compliant parallel pan-tilt platform", Meccanica 51 (2016)
//! 1559–1570, doi:10.1007/s11012-015-0116-1 (worked example, Tables 4 and 5), and bad input is
//! refused with its JSON path.

#[path = "common/references.rs"]
mod references;

use flexfem::analysis::pantilt::{plots, report, solve, warnings, PanTiltResult};
use flexfem::case::pantilt::PanTiltCase;
use flexfem::case::CaseError;
use references::PT_TABLE4_MAX_ROTATION_DEG;
use serde_json::{json, Value};

fn parse(mut v: Value) -> Result<PanTiltCase, CaseError> {
    v.as_object_mut().unwrap().remove("analysis");
    flexfem::case::from_value(v, "")
}

fn bundled() -> Value {
    let text = std::fs::read_to_string(concat!(env!("CARGO_MANIFEST_DIR"), "/cases/pantilt_prbm.json")).unwrap();
    serde_json::from_str(&text).unwrap()
}

fn run(v: Value) -> PanTiltResult {
    solve(&parse(v).unwrap().validate().unwrap()).unwrap()
}

#[test]
fn bundled_case_reproduces_the_worked_example_and_tables_4_and_5() {
    // Yu et al. (2016): worked example θ₁ = 7.36°, θ₂ = 3.09° (±0.005°); Table 4 largest joint
    // rotations as printed, 10.00, 9.998, 9.998, 11.57, 11.56, 11.56, 10.84, 10.84° (±half a unit
    // of the last digit: the case samples the circle every 0.01 s like the paper); Table 5
    // largest torques 303.7 / 255.6 N·mm undamped, 312.9 / 266.4 N·mm damped (±1 %).
    let r = run(bundled());
    assert!((r.ik[0].theta_deg[0] - 7.36).abs() <= 0.005);
    assert!((r.ik[0].theta_deg[1] - 3.09).abs() <= 0.005);
    let p = r.path.as_ref().unwrap();
    assert_eq!(p.points, 100);
    let printed = PT_TABLE4_MAX_ROTATION_DEG;
    for (i, (e, tol)) in printed.iter().enumerate() {
        let got = p.max_joint_rotation_deg[i].max_abs;
        assert!((got - e).abs() <= *tol, "J{}: {got}", i + 1);
    }
    for (got, want) in [
        (p.max_torque_undamped[0].max_abs, 303.7),
        (p.max_torque_undamped[1].max_abs, 255.6),
        (p.max_torque_damped[0].max_abs, 312.9),
        (p.max_torque_damped[1].max_abs, 266.4),
    ] {
        assert!(((got - want) / want).abs() <= 0.01, "{got} vs {want}");
    }
    // FK of the printed (rounded) θ returns to the example's pose within the rounding:
    // 0.005° on θ moves the pose by well under 0.05°.
    assert!((r.fk[0].gamma_deg - 10.0).abs() < 0.05, "{}", r.fk[0].gamma_deg);
    assert!((r.fk[0].phi_deg - 45.0).abs() < 0.3, "{}", r.fk[0].phi_deg);
}

#[test]
fn pole_query_is_flagged_and_warned() {
    // An IK query at the home pose γ = 0: the (γ, φ) inverse Jacobian of Yu et al. Eq. (17) is
    // singular there (zero φ column), flagged, and a warning names the query; the γ = 10° query's
    // Jacobian is regular. (The bundled case has no such query: bundled results carry no
    // warnings.)
    let r = run(json!({"analysis": "pantilt", "ik": [
        {"gamma_deg": 10, "phi_deg": 45}, {"gamma_deg": 0, "phi_deg": 0}]}));
    assert!(warnings(&run(bundled())).is_empty());
    assert!(r.ik[1].pole_singular && r.ik[1].inverse_jacobian_det == 0.0);
    assert!(r.ik[1].inverse_jacobian.iter().all(|row| row[1] == 0.0));
    assert!(!r.ik[0].pole_singular && r.ik[0].inverse_jacobian_det.abs() > 1e-3);
    let w = warnings(&r);
    assert_eq!(w.len(), 1, "{w:?}");
    assert!(w[0].contains("ik[1]") && w[0].contains("γ = 0"), "{w:?}");
}

#[test]
fn path_through_the_pole_warns_but_torques_stay_finite() {
    // A straight pass of the pointing direction through γ = 0 (φ jumps by 180°): the regular
    // coordinates keep every torque finite, the report warns about the (γ, φ) singularity.
    let mut samples = Vec::new();
    for k in 0..21 {
        let t = k as f64 * 0.05;
        let g = (t - 0.5) * 20.0;
        samples.push(json!({"t": t, "gamma_deg": g.abs(), "phi_deg": if g < 0.0 { 180.0 } else { 0.0 }}));
    }
    let r = run(json!({"analysis": "pantilt", "path": {"type": "samples", "samples": samples}}));
    let p = r.path.as_ref().unwrap();
    assert!(p.min_gamma_deg < 1e-9);
    assert!(p.rows.iter().all(|row| row.torque_damped.iter().all(|t| t.is_finite())));
    assert!(warnings(&r).iter().any(|w| w.contains("within")), "{:?}", warnings(&r));
}

#[test]
fn report_csv_and_plots_carry_the_path() {
    // One CSV line per path point plus the header; four SVG plots (bottom, middle, top joints,
    // torques); the Markdown shows the Table 5 peaks to 0.01 N·mm.
    let r = run(bundled());
    let rep = report(&r);
    assert_eq!(rep.csv.lines().count(), 101);
    assert!(rep.csv.starts_with("t_s,gamma_deg,phi_deg,J1_deg"));
    let peak = format!("{:.2}", r.path.as_ref().unwrap().max_torque_undamped[0].max_abs);
    assert!(rep.markdown.contains(&peak), "{}", rep.markdown);
    let files = plots(&r);
    assert_eq!(files.len(), 4);
    assert!(files.iter().all(|(n, b)| n.ends_with(".svg") && b.starts_with(b"<svg")));
}

#[test]
fn bad_input_names_the_json_path() {
    // Each bad field is refused with its JSON path before solving (exit code 2 at the CLI).
    let cases = [
        (
            json!({"mechanism": {"theta0_deg": 0}, "ik": [{"gamma_deg": 1, "phi_deg": 0}]}),
            "mechanism.theta0_deg",
        ),
        (
            json!({"mechanism": {"rr_limb": 4}, "ik": [{"gamma_deg": 1, "phi_deg": 0}]}),
            "mechanism.rr_limb",
        ),
        (
            json!({"mechanism": {"actuated": [2, 2]}, "ik": [{"gamma_deg": 1, "phi_deg": 0}]}),
            "mechanism.actuated",
        ),
        (
            json!({"joints": {"K": -1}, "ik": [{"gamma_deg": 1, "phi_deg": 0}]}),
            "joints.K",
        ),
        (
            json!({"joints": {"D": [0, 0, 0, 0, 0, 0, 0, -1]}, "ik": [{"gamma_deg": 1, "phi_deg": 0}]}),
            "joints.D[7]",
        ),
        (json!({"ik": [{"gamma_deg": 95, "phi_deg": 0}]}), "ik[0].gamma_deg"),
        (
            json!({"path": {"type": "circle", "gamma_deg": 10, "period": 0}}),
            "path.period",
        ),
        (
            json!({"path": {"type": "circle", "gamma_deg": 10, "points": 1}}),
            "path.points",
        ),
        (
            json!({"path": {"type": "samples", "samples": [
            {"t": 0, "gamma_deg": 1, "phi_deg": 0}, {"t": 0, "gamma_deg": 1, "phi_deg": 0},
            {"t": 1, "gamma_deg": 1, "phi_deg": 0}]}}),
            "path.samples[1].t",
        ),
        (json!({"fk": [{"theta_deg": [100, 0]}]}), "fk[0].theta_deg[0]"),
        (json!({}), "."),
    ];
    for (v, path) in cases {
        let mut v = v;
        v.as_object_mut().unwrap().insert("analysis".into(), json!("pantilt"));
        let e = parse(v.clone()).and_then(|c| c.validate().map(|_| ())).unwrap_err();
        assert_eq!(e.path, path, "{v}: {e}");
    }
    let e = parse(json!({"analysis": "pantilt", "mechanism": {"theta_0": 60}})).unwrap_err();
    assert!(e.path.starts_with("mechanism"), "{e}");
}

#[test]
fn sampled_path_rates_match_the_circle() {
    // The bundled circle (100 points) given as samples: the second-order finite-difference rates
    // reproduce the exact circle torques within 0.1 % (h = 3.6° of φ, O(h²) ≈ 1e-3 of the damper
    // share, itself under 30 % of the torque).
    let n = 100;
    let samples: Vec<Value> = (0..=n)
        .map(|k| json!({"t": k as f64 / n as f64, "gamma_deg": 10.0, "phi_deg": 360.0 * k as f64 / n as f64}))
        .collect();
    let r_s = run(json!({"analysis": "pantilt", "path": {"type": "samples", "samples": samples}}));
    let r_c = run(bundled());
    let (ps, pc) = (r_s.path.unwrap(), r_c.path.unwrap());
    for a in 0..2 {
        let (s, c) = (ps.max_torque_damped[a].max_abs, pc.max_torque_damped[a].max_abs);
        assert!(((s - c) / c).abs() < 1e-3, "{s} vs {c}");
    }
}

#[test]
fn cli_runs_the_bundled_case_and_refuses_a_bad_one_with_exit_2() {
    // `flexfem run cases/pantilt_prbm.json --out DIR` writes result.json, report.md, result.csv
    // and the four SVG plots; a bad field exits 2 naming its JSON path.
    let exe = env!("CARGO_BIN_EXE_flexfem");
    let dir = std::path::PathBuf::from(env!("CARGO_TARGET_TMPDIR")).join("pantilt_cli");
    let _ = std::fs::remove_dir_all(&dir);
    let case = concat!(env!("CARGO_MANIFEST_DIR"), "/cases/pantilt_prbm.json");
    let out = std::process::Command::new(exe)
        .args(["run", case, "--out", dir.to_str().unwrap()])
        .output()
        .unwrap();
    assert_eq!(out.status.code(), Some(0), "{}", String::from_utf8_lossy(&out.stderr));
    for f in [
        "result.json",
        "report.md",
        "result.csv",
        "pantilt_bottom_joints.svg",
        "pantilt_middle_joints.svg",
        "pantilt_top_joints.svg",
        "pantilt_torques.svg",
    ] {
        assert!(dir.join(f).is_file(), "{f} missing");
    }
    let bad = dir.join("bad.json");
    std::fs::write(
        &bad,
        r#"{"analysis": "pantilt", "path": {"type": "circle", "gamma_deg": -5}}"#,
    )
    .unwrap();
    let out = std::process::Command::new(exe)
        .args(["run", bad.to_str().unwrap()])
        .output()
        .unwrap();
    assert_eq!(out.status.code(), Some(2));
    assert!(String::from_utf8_lossy(&out.stderr).contains("path.gamma_deg"));
}
