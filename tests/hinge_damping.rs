//! Joint damping of a flexure hinge identified from a simulated step response (Yu, Lu and Hao
//! (2016), "Design and analysis of an 8R compliant parallel pan-tilt", §4.1): the nylon 66
//! corner-filleted hinge (L = 15 mm blank, h = 15 mm, t = 10 mm width, l = 5 mm, R = 1.75 mm,
//! δ = 0.6 mm; density 1150 kg/m³, material damping 0.05).
//!
//! With stiffness-proportional material damping C = β K every mode of the hinge is heavily
//! overdamped (ζᵢ = β ωᵢ/2 ≫ 1) and its slow pole is −1/β, so the fitted second-order joint has
//! D/K = β: the test asserts it within `DK_TOL` (measured −1.2e-11 at β = 0.05, −6.5e-9 at 0.01).
//!
//! Against the paper (K = 4.78 N·mm/°, D = 0.226 N·mm·s/°, so D/K = 0.0473 s): our D is
//! 0.2018 N·mm·s/°, 10.7 % lower. Two reasons, both asserted below: (1) our K from the hinge's
//! beam model is 4.035 N·mm/°, 15.6 % below the paper's ANSYS solid value (4.142 N·mm/°,
//! 13.3 % below, before the corner fillets got the short-notch factor, which CalculiX models of
//! corner-filleted hinges support: tests/hinge_ccx_reference.rs), and D scales with K;
//! (2) the paper's D/K is 5.4 % below its material damping 0.05 — most likely because it took
//! the closest of a family of drawn step-response curves (its steps (3)–(4)) rather than a
//! least-squares fit, which recovers β exactly here; the two effects partly cancel
//! (0.844 × 0.05/0.0473 = 0.892).

use flexfem::hinge::damping::{identify_damping, DampingRun};
use flexfem::hinge::HingeSpec;
use flexfem::material::Material;

fn paper_hinge() -> flexfem::hinge::Profile {
    let spec: HingeSpec = serde_json::from_value(serde_json::json!({
        "type": "corner_filleted", "l": 5, "R": 1.75, "t": 0.6, "w": 10, "h": 15, "blank_length": 15
    }))
    .unwrap();
    spec.profile().unwrap()
}

fn run(beta: f64) -> DampingRun {
    DampingRun {
        alpha: 0.0,
        beta,
        duration: 8.0 * beta,
        steps: 800,
        moment: 1.0,
    }
}

/// Relative tolerance on D/K = β.
const DK_TOL: f64 = 2e-8;

#[test]
fn stiffness_proportional_damping_is_identified() {
    let p = paper_hinge();
    for beta in [0.05, 0.01] {
        let d = identify_damping(&p, &Material::NYLON66, &run(beta)).unwrap();
        let ratio = d.d / d.k;
        eprintln!(
            "beta = {beta} s: K = {:.4} N·mm/°, D = {:.4} N·mm·s/°, D/K = {ratio:.6} s, J = {:.3e} t·mm², residual {:.2e}",
            d.k.to_radians(),
            d.d.to_radians(),
            d.j,
            d.residual
        );
        eprintln!("D/K / beta − 1 = {:+.2e}", ratio / beta - 1.0);
        assert!((ratio / beta - 1.0).abs() < DK_TOL, "D/K = {ratio} for beta = {beta}");
        // The second-order model reproduces the simulated response (RMS < 0.1 % of static).
        assert!(d.residual < 1e-3, "residual {}", d.residual);
    }
}

#[test]
fn damping_compared_with_the_paper() {
    let d = identify_damping(&paper_hinge(), &Material::NYLON66, &run(0.05)).unwrap();
    let (k_deg, d_deg) = (d.k.to_radians(), d.d.to_radians());
    let (k_paper, d_paper) = (4.78, 0.226);
    // (1) K from the beam model of the hinge is 15.6 % below the paper's (within 0.5 points).
    assert!((k_deg / k_paper - 0.844).abs() < 0.005, "K = {k_deg} N·mm/°");
    // (2) Our D/K is the material's 0.05 s; the paper's curve-picking gave 0.0473 s.
    assert!((d_paper / k_paper / 0.05 - 0.946).abs() < 0.001);
    // So D is the paper's × 0.844 × 0.05/0.0473 = 0.892 (within 0.5 points).
    assert!((d_deg / d_paper - 0.892).abs() < 0.005, "D = {d_deg} N·mm·s/°");
}
