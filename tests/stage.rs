//! The monolithic 3-PRS compliant stage against Ruiz et al. (2019) Tables 2 and 4, and the
//! ideal-joint FE model against the rigid-body forward kinematics.

mod common;
use common::*;
use flexfem::kinematics::Prs;
use flexfem::stage::Drive;
use proptest::prelude::*;

fn run_json(path: &str) -> serde_json::Value {
    let out = run(&["run", path]);
    assert_eq!(out.status.code(), Some(0), "{}", stderr(&out));
    serde_json::from_str(&stdout(&out)).unwrap()
}

fn f(v: &serde_json::Value) -> f64 {
    v.as_f64().unwrap()
}

/// Relative tolerance on Δz at 400 MPa against Ruiz et al. (2019) §5 (measured −7.3 %).
const DZ_AT_ALLOWABLE_TOL: f64 = 0.10;

#[test]
fn table2_strokes_displacements_and_stress() {
    // Ruiz et al. (2019) Table 2 (ANSYS, equal forces on the three actuators):
    // F = 20/40/60 N → s = 0.935/1.899/2.865 mm, Δz = 0.933/1.896/2.859 mm,
    // σ_max = 169.25/344.01/518.78 MPa. Must show: strokes and Δz within 10 %, stress within 15 %.
    let v = run_json("cases/ruiz2019_stage.json");
    let rows = v["load_cases"].as_array().unwrap();
    let published = [(0.935, 0.933, 169.25), (1.899, 1.896, 344.01), (2.865, 2.859, 518.78)];
    assert_eq!(rows.len(), published.len(), "Table 2 rows");
    for (row, (s_ref, z_ref, sig_ref)) in rows.iter().zip(published) {
        for k in 0..3 {
            let s = f(&row["strokes"][k]);
            assert!(
                (s / s_ref - 1.0).abs() <= 0.10,
                "{}: stroke {s} vs {s_ref}",
                row["name"]
            );
        }
        let z = f(&row["platform"]["z"]);
        assert!((z / z_ref - 1.0).abs() <= 0.10, "{}: Δz {z} vs {z_ref}", row["name"]);
        let sig = f(&row["max_von_mises"]);
        assert!(
            (sig / sig_ref - 1.0).abs() <= 0.15,
            "{}: σ {sig} vs {sig_ref}",
            row["name"]
        );
        // Equal forces on a symmetric stage: pure z, no tilt.
        assert!(f(&row["platform"]["psi_deg"]).abs() < 1e-9 && f(&row["platform"]["theta_deg"]).abs() < 1e-9);
    }
    // The reach at 400 MPa is reported and is the linear scaling of the F = 20 N case.
    // Ruiz et al. (2019) §5 gives Δz = 2.205 mm at 400 MPa; we reach 2.043 mm (−7.3 %: our peak
    // stress per mm of stroke is about 8 % above ANSYS's, as in the Table 2 rows above).
    let z400 = f(&v["at_allowable"]["z"]);
    let z20 = f(&rows[0]["platform"]["z"]);
    let s20 = f(&rows[0]["max_von_mises"]);
    assert!((z400 - z20 * 400.0 / s20).abs() < 1e-9 * z400, "Δz at 400 MPa {z400}");
    eprintln!(
        "Δz at 400 MPa: {z400} mm vs 2.205 ({:+.2} %)",
        100.0 * (z400 / 2.205 - 1.0)
    );
    assert!(
        (z400 / 2.205 - 1.0).abs() <= DZ_AT_ALLOWABLE_TOL,
        "Δz at 400 MPa {z400}"
    );
    assert_eq!(f(&v["at_allowable"]["allowable"]), 400.0);
}

#[test]
fn table4_linear_fem_column_within_3um() {
    // Ruiz et al. (2019) Table 4, FEM column (linear ANSYS): Δz = 1408, 727, −624, −1478 µm;
    // measured 1409.4, 728.3, −624.8, −1479.0 µm (worst 1.4 µm; the table rounds to 1 µm).
    let v = run_json("cases/ruiz2019_fem_vs_fkp.json");
    let rows = v["rows"].as_array().unwrap();
    assert_eq!(rows.len(), 4, "Table 4 rows");
    for (row, z_ref) in rows.iter().zip([1408.0, 727.0, -624.0, -1478.0]) {
        let z = f(&row["fem_linear"]["z"]) * 1000.0;
        eprintln!("Table 4 linear FEM Δz {z:.1} µm vs {z_ref} µm");
        assert!((z - z_ref).abs() <= 3.0, "Δz {z} µm vs {z_ref} µm");
        // and the FKP column of the same table (1384, 722, −631, −1511 µm) to 2 µm
    }
    let fkp: Vec<f64> = rows.iter().map(|r| f(&r["fkp"]["z"]) * 1000.0).collect();
    for (z, z_ref) in fkp.iter().zip([1384.0, 722.0, -631.0, -1511.0]) {
        assert!((z - z_ref).abs() <= 2.0, "FKP Δz {z} vs {z_ref}");
    }
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(24))]
    #[test]
    fn ideal_joint_fem_equals_fkp(gamma in prop_oneof![Just(0.0), Just(30.0)], s in prop::array::uniform3(-0.01f64..0.01)) {
        // With exact joints and stiff legs the FE model is the rigid mechanism: at 10 µm strokes
        // its (linear) pose equals the FKP pose to 0.1 µm (second-order terms are ~1e-3 µm).
        let d = fixtures::ruiz2019_ideal_stage_design(gamma);
        let model = d.build().unwrap();
        let r = model.solve(&[("s".into(), Drive::Strokes(s))]).unwrap().remove(0);
        let prs: Prs = d.prs;
        let k = prs.fkp(s, None).unwrap().pose;
        let p = r.platform;
        prop_assert!((p.z - k.z).abs() < 1e-4, "z {} vs {}", p.z, k.z);
        prop_assert!((p.x - k.x).abs() < 1e-4 && (p.y - k.y).abs() < 1e-4);
        // rotations: 0.1 µm over the platform radius b
        let tol = 1e-4 / prs.b;
        prop_assert!((p.psi - k.psi).abs() < tol, "ψ {} vs {}", p.psi, k.psi);
        prop_assert!((p.theta - k.theta).abs() < tol, "θ {} vs {}", p.theta, k.theta);
        prop_assert!((p.phi - k.phi).abs() < tol);
        // zip-checked: two [f64; 3] stroke arrays.
        for (got, want) in r.strokes.iter().zip(s) {
            prop_assert!((got - want).abs() < 1e-12);
        }
    }
}
