//! The bundled FE mesh case of the 8R compliant pan-tilt of G. Yu, Q. Lu and G. Hao (2016) —
//! cases/pantilt_8r.json, driven (nonlinear, hinge elements) to the paper's PRBM inputs
//! θ₁ = 7.36°, θ₂ = 3.09° — against the library's PRBM (`kinematics::pantilt`, the paper's
//! geometry θ₀ = 60°, δ = 90°): the forward kinematics of the same inputs and the paper's target
//! pose (pitch γ = 10°, phase φ = 45°). The FE platform axis is r₇ = R·z with R the platform
//! node's rotation (rotation vector, Rodrigues).

#[path = "common/mechanisms.rs"]
mod mechanisms;

use flexfem::kinematics::pantilt::{PanTilt, PanTiltGeometry, Pointing};
use mechanisms::{pantilt_mesh, pitch_phase, PanTilt as PanTiltMesh};
use std::path::PathBuf;

fn root() -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR"))
}

/// FE pitch and phase of the bundled case, degrees.
fn fe_pose() -> (f64, f64) {
    let parsed = flexfem::analysis::load(&root().join("cases/pantilt_8r.json")).unwrap();
    let res = flexfem::analysis::run(&parsed).unwrap().json;
    let node = pantilt_mesh(&PanTiltMesh::standard()).platform;
    let row = &res["load_cases"][0]["displacements"][node];
    pitch_phase(std::array::from_fn(|k| row[3 + k].as_f64().unwrap()))
}

/// Measured: the PRBM's forward kinematics of (7.36°, 3.09°) is pitch 10.0007°, phase 44.9986°
/// (the paper's example, to its printed 0.01°); the FE pose (hinges in co-rotational segments)
/// is pitch 9.680°, phase 46.052°: FE − PRBM = −0.321° in pitch, +1.054° in phase (with the
/// short-notch factor on the corner hinges' fillets; −0.328°, +1.079° before it, −0.342°,
/// +1.133° before the hinges' Benscoter torsion). The FE's
/// notch hinges are not ideal pivots: their rotation centres shift and they bend and twist off their compliant axes under the
/// closed-loop forces (the passive limb's two hinges and the platform joints fight the drive),
/// so the platform axis lands short in pitch and turned in phase — the same direction of
/// deviation as the paper's own ANSYS results (Yu et al., Table 3, standard hinge: 9.195°, 47.68°;
/// pitch below 10°, phase above 45°). Asserted: each difference within ±0.05° of the measured one.
#[test]
fn pantilt_fe_pose_against_prbm() {
    let prbm = PanTilt::new(PanTiltGeometry::default()).unwrap();
    let fk = prbm
        .forward_kinematics(
            [7.36f64.to_radians(), 3.09f64.to_radians()],
            Some(Pointing::from_deg(10.0, 45.0)),
        )
        .unwrap();
    let (g, f) = (fk.gamma.to_degrees(), fk.phi.to_degrees());
    let (pitch, phase) = fe_pose();
    eprintln!(
        "PRBM FK: pitch {g:.4}°, phase {f:.4}°; FE: pitch {pitch:.4}°, phase {phase:.4}°; FE − PRBM: {:+.4}°, {:+.4}°",
        pitch - g,
        phase - f
    );
    assert!((g - 10.0).abs() < 0.01 && (f - 45.0).abs() < 0.05, "PRBM FK {g} {f}");
    assert!(((pitch - g) - -0.3207).abs() < 0.05, "pitch FE − PRBM = {}", pitch - g);
    assert!(((phase - f) - 1.0536).abs() < 0.05, "phase FE − PRBM = {}", phase - f);
}
