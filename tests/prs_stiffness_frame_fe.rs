//! The 3-PRS of X. Han, Y. Wang, J. Shi, "Stiffness Modeling of 3-PRS Mechanism" (Tables I–III) as a
//! frame finite-element model — links as Euler–Bernoulli beams, lead screws as axial springs at the
//! current nut position, ideal revolute and spherical joints — against the `prs_stiffness` model:
//! the 6×6 platform compliance and the deformation under the published load (F = [100, 50, 50] kN in
//! the platform frame at p_z = −400 mm, β = 0/5/10°). Same readings as in tests/prs_stiffness.rs.
//!
//! Joints in the frame model: the spherical joint is a translational penalty spring (rotations
//! free) between the link end and the rigid platform; the revolute joint is a 100 mm stub beam
//! along the revolute axis, penalty-stiff except in torsion; the slider node is supported in every
//! direction but the rail, where a spring of the screw stiffness holds it. The penalty error is
//! first order in 1/p: two runs (p, 2p) are extrapolated, d = 2·d(2p) − d(p).

#[path = "common/references.rs"]
mod references;

use flexfem::kinematics::prs::revolute_axis;
use flexfem::kinematics::prs_stiffness::PrsStiffness;
use nalgebra::{Matrix6, Vector3, Vector6};
use serde_json::{json, Value};

/// The frame case at one pose with the given load cases at P ([F (N); M (N·mm)] each).
fn frame_case(m: &PrsStiffness, beta: f64, loads: &[Vector6<f64>], p: f64) -> Value {
    let stub = 100.0;
    let big = p * 1e6;
    let ps = m.at(-400.0, 0.0, beta, &Vector3::zeros()).unwrap();
    let st = ps.state;
    let mut nodes: Vec<[f64; 3]> = vec![st.p().into()];
    let mut elements = vec![json!({"type": "rigid", "master": 0, "slaves": [1, 2, 3]})];
    for i in 0..3 {
        nodes.push(st.b_pts[i].into());
    }
    for i in 0..3 {
        nodes.push(st.b_pts[i].into()); // link end at the spherical joint: 4..6
    }
    for i in 0..3 {
        nodes.push(st.c_pts[i].into()); // link end at the revolute joint: 7..9
    }
    for i in 0..3 {
        nodes.push((st.c_pts[i] + stub * revolute_axis(i)).into()); // slider: 10..12
    }
    for i in 0..3 {
        let mi: [f64; 3] = revolute_axis(i).into();
        let li: [f64; 3] = st.legs[i].into();
        elements.push(json!({"type": "spring", "nodes": [1 + i, 4 + i], "k": [big, big, big, 0, 0, 0]}));
        elements.push(json!({"type": "beam", "nodes": [4 + i, 7 + i], "section": "link", "material": "steel", "up": mi, "shear": false}));
        elements.push(json!({"type": "beam", "nodes": [7 + i, 10 + i], "section": "pin", "material": "steel", "up": li, "shear": false}));
        // Han et al. Eq. 8, fixed–fixed screw with the nut a = sᵢ from the first bearing.
        let a = st.s[i];
        let ks = 183.5 * 231_000.0 * 600.0 / (a * (600.0 - a));
        elements.push(json!({"type": "spring", "nodes": [10 + i], "k": [0, 0, ks, 0, 0, 0]}));
    }
    let load_cases: Vec<Value> = loads
        .iter()
        .enumerate()
        .map(|(k, w)| json!({"name": format!("l{k}"), "forces": [{"node": 0, "F": [w[0], w[1], w[2], w[3], w[4], w[5]]}]}))
        .collect();
    json!({
        "analysis": "static",
        "materials": {"steel": {"E": 210000.0, "nu": 0.3}},
        "sections": {
            "link": {"shape": "general", "A": 7200.0, "Iy": 8.64e6, "Iz": 2.16e6, "J": 1.296e6},
            "pin": {"shape": "general", "A": big * stub / 210_000.0, "Iy": p * 3e10 * stub / 210_000.0, "Iz": p * 3e10 * stub / 210_000.0, "J": 1e-3}
        },
        "nodes": nodes,
        "elements": elements,
        "supports": (10..13).map(|n| json!({"node": n, "fix": ["ux", "uy", "rx", "ry", "rz"]})).collect::<Vec<_>>(),
        "load_cases": load_cases
    })
}

/// Platform-centre displacement [mm; rad] of each load case.
fn run_frame(case: Value) -> Vec<Vector6<f64>> {
    let parsed = flexfem::analysis::parse_value(case, None).unwrap();
    let out = flexfem::analysis::run(&parsed).unwrap();
    out.json["load_cases"]
        .as_array()
        .unwrap()
        .iter()
        .map(|lc| {
            let d: Vec<f64> = lc["displacements"][0]
                .as_array()
                .unwrap()
                .iter()
                .map(|x| x.as_f64().unwrap())
                .collect();
            Vector6::from_fn(|i, _| if i < 3 { d[i] } else { d[i].to_radians() })
        })
        .collect()
}

/// Frame FE and `prs_stiffness` agree to 1e-6 relative on the 6×6 compliance (unit loads, scaled
/// so that rotations count through ℓ = 1000 mm) and on the deformation under Han et al.'s load.
#[test]
fn han_frame_fe_matches_prs_stiffness() {
    let m = references::han(8.64e6);
    let ell = 1000.0;
    for beta_deg in [0.0f64, 5.0, 10.0] {
        let beta = beta_deg.to_radians();
        let ps = m.at(-400.0, 0.0, beta, &Vector3::zeros()).unwrap();
        let mut loads: Vec<Vector6<f64>> = (0..6)
            .map(|k| {
                let mut w = Vector6::zeros();
                w[k] = if k < 3 { 1e4 } else { 1e4 * ell };
                w
            })
            .collect();
        let f = ps.state.r * Vector3::new(100e3, 50e3, 50e3);
        loads.push(Vector6::new(f[0], f[1], f[2], 0.0, 0.0, 0.0));
        let d1 = run_frame(frame_case(&m, beta, &loads, 1e4));
        let d2 = run_frame(frame_case(&m, beta, &loads, 2e4));
        assert_eq!(d1.len(), d2.len());
        let d: Vec<Vector6<f64>> = d1.iter().zip(&d2).map(|(a, b)| 2.0 * b - a).collect();
        let mut c_fe = Matrix6::zeros();
        for k in 0..6 {
            c_fe.set_column(k, &(d[k] / loads[k][k]));
        }
        let s = Matrix6::from_diagonal(&Vector6::new(1.0, 1.0, 1.0, ell, ell, ell));
        let (a, b) = (s * c_fe * s, s * ps.compliance * s);
        let rel = (a - b).norm() / b.norm();
        let want = ps.deformation(&loads[6]);
        let rel_d = (d[6] - want).norm() / want.norm();
        eprintln!("β = {beta_deg}°: compliance rel. diff {rel:.2e}, deformation rel. diff {rel_d:.2e}, |δp| FE {:.6} mm, model {:.6} mm", d[6].fixed_rows::<3>(0).norm(), want.fixed_rows::<3>(0).norm());
        assert!(rel < 1e-6, "β = {beta_deg}°: compliance differs by {rel:e}");
        assert!(rel_d < 1e-6, "β = {beta_deg}°: deformation differs by {rel_d:e}");
    }
}
