//! The 3-PRS of X. Han, Y. Wang, J. Shi, "Stiffness Modeling of 3-PRS Mechanism" (Tables I–III) as a
//! `static` frame mesh case with IDEAL joints — links as Euler–Bernoulli beams (rect 60 × 120 mm:
//! A = 7200 mm², I_lateral = 8.64e6 mm⁴, the readings of cases/prs_stiffness_han_fsw.json), lead
//! screws as axial bars of the screw stiffness at the current nut position (Han et al. Eq. 8,
//! fixed–fixed, k = A·E·ℓ/(a·(ℓ − a)), a = stroke), `joint` elements of kind spherical
//! (platform–link) and revolute (link–slider, axis along the revolute axis mᵢ), sliders supported
//! in the joint frame with only the rail free — against the `prs_stiffness` model: the 6×6
//! platform compliance (the `static` case's `"compliance": [{"node": 0}]`) and the
//! deformation under the published load (F = [100, 50, 50] kN in the platform frame,
//! p_z = −400 mm, β = 0/5/10°). The joints tie by elimination (no penalty); the one stiff part is
//! the platform, a star of beams 1e5 times stiffer than steel (a joint cannot tie a rigid-link
//! slave), which leaves a relative error ≈ 1e-7 (at E×1e3 it is 3.8e-6: first order in 1/E).
//! The bundled case cases/prs_stiffness_han_fsw_frame.json is the β = 0 instance (yield and
//! allowable 355 MPa, S355 steel per EN 10025-2, are not from the paper: only for the stress report).

#[path = "common/references.rs"]
mod references;

use flexfem::kinematics::prs::revolute_axis;
use flexfem::kinematics::prs_stiffness::PrsStiffness;
use nalgebra::{Matrix6, Vector3, Vector6};
use serde_json::{json, Value};

/// Han et al.'s 3-PRS with the paper's I_y = 8.64e6 mm⁴ out of plane (the shared reference).
fn han() -> PrsStiffness {
    references::han(8.64e6)
}

/// The platform's stiff beams: square side (mm) and Young's modulus (MPa).
const PLAT_W: f64 = 600.0;
const PLAT_E: f64 = 2.1e10;

/// The frame case at p_z = −400 mm, ψ = 0, θ = β: the published load at P and the compliance of P.
fn frame_case(m: &PrsStiffness, beta: f64) -> Value {
    let round = |v: Vector3<f64>| -> [f64; 3] { [v[0], v[1], v[2]].map(|x| (x * 1e9).round() / 1e9) };
    let ps = m.at(-400.0, 0.0, beta, &Vector3::zeros()).unwrap();
    let st = ps.state;
    let mut nodes: Vec<[f64; 3]> = vec![round(st.p())];
    // The platform: a star of stiff beams from P to the Bᵢ (a rigid link cannot be used: a joint
    // cannot tie a rigid-link slave).
    let mut elements: Vec<Value> = (0..3)
        .map(|i| json!({"type": "beam", "nodes": [0, 1 + i], "section": "platform", "material": "platform", "up": [0.0, 0.0, 1.0], "shear": false}))
        .collect();
    for i in 0..3 {
        nodes.push(round(st.b_pts[i])); // platform side of the spherical joint: 1..3
    }
    for i in 0..3 {
        nodes.push(round(st.b_pts[i])); // link end at the spherical joint: 4..6
    }
    for i in 0..3 {
        nodes.push(round(st.c_pts[i])); // link end at the revolute joint: 7..9
    }
    for i in 0..3 {
        nodes.push(round(st.c_pts[i])); // slider: 10..12
    }
    for i in 0..3 {
        let mv = revolute_axis(i);
        let mi: [f64; 3] = mv.into();
        elements.push(json!({"type": "joint", "nodes": [4 + i, 1 + i], "kind": "spherical"}));
        elements.push(json!({"type": "beam", "nodes": [4 + i, 7 + i], "section": "link", "material": "steel", "up": mi, "shear": false}));
        elements.push(json!({"type": "joint", "nodes": [7 + i, 10 + i], "kind": "revolute", "axis": mi}));
    }
    // The screws: Han et al. Eq. 8, fixed–fixed, nut a = sᵢ from the first bearing, as an axial
    // bar along the rail (rect 10 × 10 mm, steel) from the slider to a clamped node, of the length
    // that gives k = E·A/ℓ_bar (a bar, not a `spring`, so the result has stresses everywhere).
    for i in 0..3 {
        let a = st.s[i];
        let ks = 183.5 * 231_000.0 * 600.0 / (a * (600.0 - a));
        let bar = 210_000.0 * 100.0 / ks;
        nodes.push(round(st.c_pts[i] - bar * Vector3::z())); // screw bearing: 13..15
        elements.push(json!({"type": "beam", "nodes": [13 + i, 10 + i], "section": "screw", "material": "steel", "up": [1.0, 0.0, 0.0], "shear": false}));
    }
    // The slider carries the revolute joint's frame (x = mᵢ, y = unit(mᵢ × x̂) = ±z along the
    // rail since mᵢ is horizontal, z = x × y); its support acts in that frame: free along the rail.
    let supports: Vec<Value> = (0..3)
        .map(|i| {
            let mv = revolute_axis(i);
            assert!(mv[0].abs() < 0.9 && mv[2] == 0.0 && mv[1].abs() > 0.1);
            let y = mv.cross(&Vector3::x()).normalize();
            let rows: [[f64; 3]; 3] = [mv.into(), y.into(), mv.cross(&y).into()];
            json!({"node": 10 + i, "frame": rows, "fix": ["ux", "uz", "rx", "ry", "rz"]})
        })
        .chain((13..16).map(|n| json!({"node": n, "fix": ["ux", "uy", "uz", "rx", "ry", "rz"]})))
        .collect();
    let f = ps.state.r * Vector3::new(100e3, 50e3, 50e3);
    let [fx, fy, fz] = round(f);
    let load_cases = vec![json!({"name": "han_table_iv", "forces": [{"node": 0, "F": [fx, fy, fz, 0.0, 0.0, 0.0]}]})];
    json!({
        "analysis": "static",
        "materials": {"steel": {"E": 210000.0, "nu": 0.3, "yield": 355.0, "allowable": 355.0}, "platform": {"E": PLAT_E, "nu": 0.3, "yield": 355.0, "allowable": 355.0}},
        "sections": {"link": {"shape": "rect", "w": 60, "h": 120}, "platform": {"shape": "rect", "w": PLAT_W, "h": PLAT_W}, "screw": {"shape": "rect", "w": 10, "h": 10}},
        "nodes": nodes,
        "elements": elements,
        "supports": supports,
        "load_cases": load_cases,
        "compliance": [{"node": 0}]
    })
}

/// Platform-centre displacement [mm; rad] under the load case and the node compliance of P
/// (the case's `"compliance"` field: mm/N, rad/N, rad/(N·mm) blocks, global axes).
fn run_frame(case: Value) -> (Vector6<f64>, Matrix6<f64>) {
    let parsed = flexfem::analysis::parse_value(case, None).unwrap();
    let out = flexfem::analysis::run(&parsed).unwrap();
    let d: Vec<f64> = out.json["load_cases"][0]["displacements"][0]
        .as_array()
        .unwrap()
        .iter()
        .map(|x| x.as_f64().unwrap())
        .collect();
    let c = &out.json["compliance"][0]["matrix"];
    let c = Matrix6::from_fn(|i, j| c[i][j].as_f64().unwrap());
    (Vector6::from_fn(|i, _| if i < 3 { d[i] } else { d[i].to_radians() }), c)
}

/// (compliance rel. diff, deformation rel. diff) of the frame case against `prs_stiffness`.
fn compare(m: &PrsStiffness, beta: f64, case: Value) -> (f64, f64) {
    let ps = m.at(-400.0, 0.0, beta, &Vector3::zeros()).unwrap();
    let (d, c_fe) = run_frame(case);
    // Rotations count through ℓ = 1000 mm so that the mixed-unit blocks weigh alike.
    let ell = 1000.0;
    let s = Matrix6::from_diagonal(&Vector6::new(1.0, 1.0, 1.0, ell, ell, ell));
    let (a, b) = (s * c_fe * s, s * ps.compliance * s);
    let rel = (a - b).norm() / b.norm();
    let f = ps.state.r * Vector3::new(100e3, 50e3, 50e3);
    let want = ps.deformation(&Vector6::new(f[0], f[1], f[2], 0.0, 0.0, 0.0));
    let rel_d = (d - want).norm() / want.norm();
    eprintln!(
        "β = {:.0}°: compliance rel. diff {rel:.2e}, deformation rel. diff {rel_d:.2e}, |δp| FE {:.6} mm, model {:.6} mm",
        beta.to_degrees(),
        d.fixed_rows::<3>(0).norm(),
        want.fixed_rows::<3>(0).norm()
    );
    (rel, rel_d)
}

/// Ideal-joint frame FE and `prs_stiffness` agree to 1e-6 relative on the 6×6 compliance and on
/// the deformation under Han et al.'s load at β = 0/5/10° (same idealisation: round-off only).
#[test]
fn han_ideal_joint_frame_matches_prs_stiffness() {
    let m = han();
    for beta_deg in [0.0f64, 5.0, 10.0] {
        let beta = beta_deg.to_radians();
        let (rel, rel_d) = compare(&m, beta, frame_case(&m, beta));
        assert!(rel < 1e-6, "β = {beta_deg}°: compliance differs by {rel:e}");
        assert!(rel_d < 1e-6, "β = {beta_deg}°: deformation differs by {rel_d:e}");
    }
}

/// The bundled case is the β = 0 instance of the generated frame and agrees likewise.
#[test]
fn bundled_han_frame_case_matches_prs_stiffness() {
    let m = han();
    let path = concat!(env!("CARGO_MANIFEST_DIR"), "/cases/prs_stiffness_han_fsw_frame.json");
    let text = std::fs::read_to_string(path).unwrap_or_default();
    let bundled: Value = serde_json::from_str(&text).unwrap_or(Value::Null);
    let generated = frame_case(&m, 0.0);
    assert_eq!(
        bundled,
        generated,
        "bundled case differs from the generated one; generated:\n{}",
        serde_json::to_string(&generated).unwrap()
    );
    let (rel, rel_d) = compare(&m, 0.0, bundled);
    assert!(rel < 1e-6 && rel_d < 1e-6, "compliance {rel:e}, deformation {rel_d:e}");
}
