//! Seed hinges against their published / reference stiffnesses.

use flexfem::hinge::characterise;
use flexfem::material::Material;

mod common;
use common::fixtures;

fn pct(got: f64, reference: f64) -> f64 {
    100.0 * (got - reference) / reference
}

/// Ruiz et al. (2019) material: Al 7075, E = 72000 MPa, ν = 0.33.
fn al() -> Material {
    Material::AL7075
}

#[test]
fn ruiz2019_revolute_circular_notch() {
    // Ruiz et al. (2019) §5: R = 8, t = 2 in the 10×10 leg, 20 mm blank each side;
    // ANSYS K = 98.37 N·m/rad = 98370 N·mm/rad about the compliant axis.
    let spec = fixtures::ruiz2019_revolute_hinge();
    let r = characterise(&spec, &al()).unwrap();
    let e = pct(r.hinge.k_bend, 98_370.0);
    assert!(e.abs() < 5.0, "k_bend {} ({e:.2} %)", r.hinge.k_bend);
    // Saint-Venant torsion of a short rectangular notch is 23–92 % too soft;
    // restrained warping must stiffen it into that band.
    let gain = r.hinge.k_torsion / r.hinge.k_torsion_saint_venant;
    assert!(gain > 1.2 && gain < 2.0, "Vlasov/Saint-Venant = {gain}");
    // Ruiz et al. (2019) §4 ask the revolute joint to reach ±1.7° below 400 MPa. This model's
    // notch reaches 1.546° at 400 MPa (its peak stress per unit moment is conservative: the
    // Table 2 stresses come out 3–5 % above ANSYS's), so the requirement is not met here; the
    // value is pinned, not claimed.
    eprintln!(
        "revolute notch: k_bend {e:+.2} %, rotation at the allowable {}°",
        r.hinge.max_rotation_deg
    );
    assert!(
        (r.hinge.max_rotation_deg - 1.546).abs() < 0.005,
        "{}°",
        r.hinge.max_rotation_deg
    );
}

#[test]
fn ruiz2019_spherical_neck() {
    // Ruiz et al. (2019) §5: l = 5, t = 3, R = 4 in the 10×10 leg, 20 mm blank each side;
    // ANSYS bending 32.67 N·m/rad, torsion 24.46 N·m/rad; measured +0.6 %, +0.7 % (2 % asserted).
    let spec = fixtures::ruiz2019_spherical_hinge();
    let r = characterise(&spec, &al()).unwrap();
    let eb = pct(r.hinge.k_bend, 32_670.0);
    let et = pct(r.hinge.k_torsion, 24_460.0);
    eprintln!("neck: bending {eb:+.2} %, torsion {et:+.2} %");
    assert!(eb.abs() < 2.0, "bending {} ({eb:.2} %)", r.hinge.k_bend);
    assert!(et.abs() < 2.0, "torsion {} ({et:.2} %)", r.hinge.k_torsion);
    // Axisymmetric waist: both bending axes equal (geometry).
    assert!((r.hinge.k_bend - r.hinge.k_bend_off).abs() < 1e-9 * r.hinge.k_bend);
}

#[test]
fn yu2016_corner_filleted_nylon() {
    // The 8R pan-tilt paper: l = 5, R = 1.75, δ = t = 0.6, width 10, blank height 15, nylon 66 (E = 3300,
    // ν = 0.33), 15 mm blank each side. Reference 4.05 N·mm/deg: converged 3-D solid FEM of the
    // stated geometry. The published 4.78 N·mm/deg does not follow from the stated
    // dimensions (plane-strain FEM gives 4.13), so it is not used.
    let spec = fixtures::pantilt_corner_filleted_hinge();
    let r = characterise(&spec, &Material::NYLON66).unwrap();
    let per_deg = r.hinge.k_bend.to_radians();
    let e = pct(per_deg, 4.05);
    assert!(e.abs() < 5.0, "k_bend {per_deg} N·mm/deg ({e:.2} %)");
}

#[test]
fn result_serialises_with_interface_names() {
    // The hinge result's field names.
    let spec = fixtures::ruiz2019_revolute_hinge();
    let r = characterise(&spec, &al()).unwrap();
    let v = serde_json::to_value(&r).unwrap();
    for key in [
        "k_bend",
        "k_bend_off",
        "k_torsion",
        "k_axial",
        "compliance",
        "stress_per_moment",
        "max_rotation_deg",
        "closed_form",
        "notch_only",
        "model",
    ] {
        assert!(v.get(key).is_some(), "missing {key}");
    }
    assert_eq!(v["compliance"].as_array().unwrap().len(), 6);
    assert!(v["notch_only"]["k_bend"].as_f64().unwrap() > r.hinge.k_bend);
}
