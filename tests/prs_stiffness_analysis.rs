//! The `prs_stiffness` analysis: case validation, results against the library and the papers'
//! numbers, and its views.
//!
//! Sources: L. A. Khan et al., "Stiffness Analysis of 3-PRS Parallel Kinematic Mechanism",
//! Technical Journal, UET Taxila; H. Nigatu et al., "The Stiffness of 3-PRS PM Across Parasitic and
//! Orientational Workspace"; X. Han, Y. Wang, J. Shi, "Stiffness Modeling of 3-PRS Mechanism".

use flexfem::analysis::prs_stiffness::{files, report, solve, PrsStiffnessResult};
use flexfem::analysis::RunError;
use flexfem::case::prs_stiffness::PrsStiffnessCase;
use serde_json::{json, Value};

const DIR: &str = concat!(env!("CARGO_MANIFEST_DIR"), "/cases");

fn load(name: &str) -> Value {
    let text = std::fs::read_to_string(format!("{DIR}/{name}.json")).unwrap();
    serde_json::from_str(&text).unwrap()
}

fn parse(mut v: Value) -> PrsStiffnessCase {
    v.as_object_mut().unwrap().remove("analysis");
    serde_json::from_value(v).unwrap()
}

fn run(v: Value) -> Result<PrsStiffnessResult, RunError> {
    solve(&parse(v))
}

/// Khan et al. §III: k·λ_max = 155.49 kN/mm (to 0.01 %) at the published pose, in the bundled case.
#[test]
fn khan_case_reproduces_the_reconstruction() {
    let r = run(load("prs_stiffness_khan")).unwrap();
    let lmax = r.poses[0].eigen_independent.values[2];
    assert!((lmax / 155_490.0 - 1.0).abs() < 1e-4, "{lmax}");
    // Actuator-only legs: the constraint directions are rigid, K unbounded (null), C finite.
    assert!(r.poses[0].stiffness.is_none());
    assert!(r.poses[0].directional[2].unwrap() > 0.0);
    let m = r.map.as_ref().unwrap();
    assert_eq!(m.cells.len(), 21 * 21);
    let w = m.workspace.as_ref().unwrap();
    assert!(w.fraction > 0.0 && w.fraction <= 1.0);
}

/// Nigatu et al.: K_zz = 3·k_a everywhere for vertical rails (here in the map of the bundled case).
#[test]
fn sprint_case_kzz_map_is_flat() {
    let r = run(load("prs_stiffness_sprint_z3")).unwrap();
    let ka = 1.0 / (1.0 / 38_000.0 + 1.0 / 3.2e6 + 1.0 / 976_000.0);
    let m = r.map.as_ref().unwrap();
    let j = m.metrics.iter().position(|s| s == "K_z").unwrap();
    let [lo, hi] = m.ranges[j].unwrap();
    assert!((lo / (3.0 * ka) - 1.0).abs() < 1e-12 && (hi / (3.0 * ka) - 1.0).abs() < 1e-12);
    assert!(m.cells.iter().all(|c| c.reachable));
}

/// Han et al. Table IV under our readings: |δp| = 0.1089/0.1050/0.1011 mm (see tests/prs_stiffness.rs).
#[test]
fn han_case_deformations() {
    let r = run(load("prs_stiffness_han_fsw")).unwrap();
    let want = [0.10885477998706646, 0.10503016898976353, 0.10109718806903639];
    assert_eq!(r.poses.len(), want.len());
    for (p, w) in r.poses.iter().zip(want) {
        let d = p.deformation.as_ref().unwrap().translation_norm_mm;
        assert!((d / w - 1.0).abs() < 1e-9, "{d} vs {w}");
    }
}

/// The views: a CSV row per map cell, one SVG per metric over (ψ, θ) and one over (pₓ, p_y).
#[test]
fn views_have_one_row_per_cell_and_two_plots_per_metric() {
    let r = run(load("prs_stiffness_sprint_z3")).unwrap();
    let rep = report(&r);
    assert_eq!(rep.csv.lines().count(), 1 + 21 * 21);
    assert!(rep.markdown.contains("Stiffness-limited workspace"));
    let f = files(&r);
    assert_eq!(f.len(), 2 * 7);
    assert!(f.iter().all(|(n, b)| n.ends_with(".svg") && b.starts_with(b"<svg")));
}

fn err_path(v: Value) -> String {
    match run(v) {
        Err(RunError::Case(e)) => e.path,
        other => panic!("expected a case error, got {:?}", other.map(|_| ())),
    }
}

/// Bad input is refused with the JSON path of the field.
#[test]
fn bad_input_names_the_field() {
    let mut v = load("prs_stiffness_han_fsw");
    v["mechanism"]["gamma_deg"] = json!(120);
    assert_eq!(err_path(v), "mechanism.gamma_deg");
    let mut v = load("prs_stiffness_han_fsw");
    v["legs"]["screw"].as_object_mut().unwrap().remove("length");
    assert_eq!(err_path(v), "legs.screw.length");
    let mut v = load("prs_stiffness_sprint_z3");
    v["map"]["metrics"][1] = json!("K_q");
    assert_eq!(err_path(v), "map.metrics[1]");
    let mut v = load("prs_stiffness_sprint_z3");
    v["legs"]["actuation"][2] = json!(-1);
    assert_eq!(err_path(v), "legs.actuation[2]");
    let mut v = load("prs_stiffness_sprint_z3");
    v["map"]["workspace"]["metric"] = json!("dir_z");
    assert_eq!(err_path(v), "map.workspace.metric");
}

/// An unreachable pose is an analysis error naming the pose, not NaN.
#[test]
fn unreachable_pose_is_an_error() {
    let mut v = load("prs_stiffness_khan");
    v["poses"][0]["pz"] = json!(-5000);
    match run(v) {
        Err(RunError::Analysis(e)) => assert_eq!(e.context, "poses[0]"),
        other => panic!("{:?}", other.map(|_| ())),
    }
    // The nut leaving the screw is an analysis error too.
    let mut v = load("prs_stiffness_han_fsw");
    v["poses"][0]["pz"] = json!(-800);
    assert!(matches!(run(v), Err(RunError::Analysis(_))));
}

/// Nigatu et al. (Sprint Z3 3-PRS head, vertical actuators): the platform sits beyond the
/// revolute joints along +z, on the tool side, as in the real head; the other IKP branch is its
/// mirror image about the platform plane, with the sliders past the platform. The bundled case
/// states its branch, and at each of its poses and over the corners and centre of its map z(P)
/// exceeds every z(Cᵢ) (Cᵢ from the library's IKP).
#[test]
fn sprint_case_platform_is_above_the_revolute_joints() {
    let v = load("prs_stiffness_sprint_z3");
    assert_eq!(
        v["mechanism"]["branch"],
        json!("minus"),
        "the case must state its IKP branch"
    );
    let case = parse(v);
    let layout = case.validate().unwrap().model.layout;
    let m = case.map.as_ref().unwrap();
    let mut poses: Vec<(f64, f64, f64)> = case.poses.iter().map(|p| (p.pz, p.psi_deg, p.theta_deg)).collect();
    for psi in [m.psi_deg[0], 0.0, m.psi_deg[1]] {
        for theta in [m.theta_deg[0], 0.0, m.theta_deg[1]] {
            poses.push((m.pz, psi, theta));
        }
    }
    assert_eq!(poses.len(), case.poses.len() + 9);
    for (pz, psi, theta) in poses {
        let st = layout.pose(pz, psi.to_radians(), theta.to_radians()).unwrap();
        for (i, c) in st.c_pts.iter().enumerate() {
            // Home pose: z(P) = 250 mm, z(Cᵢ) = 250 − √(500² − 76.923²) = −244.0 mm (branch
            // `plus`: +744.0 mm, the platform hanging below the joints).
            assert!(
                st.pz > c.z,
                "pose ({pz}, {psi}°, {theta}°): z(P) = {} mm, z(C{}) = {} mm",
                st.pz,
                i + 1,
                c.z
            );
        }
    }
}
