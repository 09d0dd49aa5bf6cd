//! Torsion: rectangle J and Γ, Vlasov and Benscoter FE against closed-form solutions.

use flexfem::hinge::section::{cowper_rect, rect_torsion_constant, rect_warping_constant};
use flexfem::hinge::torsion::{
    benscoter_torsion_stiffness, torsion_fe, vlasov_torsion_stiffness, TorsionMesh, WarpingShear,
};
use flexfem::hinge::{Contour, Profile};
use std::f64::consts::PI;

fn rel(a: f64, b: f64) -> f64 {
    (a - b).abs() / b.abs()
}

#[test]
fn square_torsion_constant() {
    // Timoshenko & Goodier (1970) §109 table: J = 0.1406 a⁴ for a square (k₁ = 0.141);
    // series value 0.140577.
    assert!(rel(rect_torsion_constant(2.0, 2.0), 0.140_577 * 16.0) < 1e-5);
    // Thin strip: J → B T³/3 (1 − 0.630 T/B).
    assert!(rel(rect_torsion_constant(100.0, 1.0), 100.0 / 3.0 * (1.0 - 0.630_2 / 100.0)) < 1e-4);
}

/// Γ from the same warping function but with the series along the *long* side (slowly
/// converging, summed to 400 000 terms): an independent check of the derivation, since the
/// exact Γ cannot depend on which side carries the series.
fn warping_long_series(b: f64, c: f64) -> f64 {
    let (long, short) = if b >= c { (b, c) } else { (c, b) };
    let a = long / 2.0;
    let d = short / 2.0;
    let mut g = 4.0 * a.powi(3) * d.powi(3) / 9.0;
    for k in 0..400_000 {
        let n = (2 * k + 1) as f64;
        let kn = n * PI / (2.0 * a);
        let x = kn * d;
        let bracket = if x < 1e-2 {
            // Series of d(2 + sech²x) − 3 tanh(x)/k for small x: −(2/5) k⁴ d⁵ + (34/105) k⁶ d⁷.
            -0.4 * kn.powi(4) * d.powi(5) + 34.0 / 105.0 * kn.powi(6) * d.powi(7)
        } else if x > 20.0 {
            2.0 * d - 3.0 / kn
        } else {
            d * (2.0 + 1.0 / x.cosh().powi(2)) - 3.0 * x.tanh() / kn
        };
        g -= 16.0 / (a * kn.powi(6)) * bracket;
    }
    g
}

#[test]
fn warping_constant_is_orientation_independent() {
    for &(b, c) in &[(2.0, 1.0), (3.0, 1.0), (10.0, 0.6), (1.3, 1.0)] {
        let g1 = rect_warping_constant(b, c);
        let g2 = warping_long_series(b, c);
        assert!(rel(g1, g2) < 1e-6, "{b}×{c}: {g1} vs {g2}");
    }
}

#[test]
fn warping_constant_thin_limit() {
    // Timoshenko & Gere (1961): narrow rectangle Γ = b³t³/144.
    assert!(rel(rect_warping_constant(100.0, 1.0), 100f64.powi(3) / 144.0) < 1e-3);
    assert!(rel(rect_warping_constant(1.0, 50.0), 50f64.powi(3) / 144.0) < 2e-3);
}

#[test]
fn prismatic_bar_both_ends_warping_restrained() {
    // Closed-form Vlasov solution, θ' = 0 at both ends (e.g. Pilkey 2002 ch. 6):
    // T/θ = GJ / (L − 2 tanh(kL/2)/k), k = √(GJ/EΓ).
    let (e, g) = (72_000.0, 27_067.7);
    let (w, t, l) = (10.0, 0.6, 5.0);
    let gj = g * rect_torsion_constant(w, t);
    let eg = e * rect_warping_constant(w, t);
    let k = (gj / eg).sqrt();
    let exact = gj / (l - 2.0 * (k * l / 2.0).tanh() / k);
    // Through the hinge code path: a leaf with no blank is that prismatic bar.
    let p = Profile::rectangular(Contour::Leaf { l, t }, w, 2.0, 0.0).unwrap();
    let fe = vlasov_torsion_stiffness(&p, e, g, TorsionMesh::default());
    assert!(rel(fe, exact) < 1e-4, "{fe} vs {exact}");
    // And the bare FE on a uniform mesh.
    let xs: Vec<f64> = (0..=40).map(|i| l * i as f64 / 40.0).collect();
    assert!(rel(torsion_fe(&xs, |_| (gj, eg)), exact) < 1e-6);
}

#[test]
fn prismatic_bar_with_warping_shear() {
    // Closed-form Benscoter (1954) solution, warping amplitude ψ = 0 at both ends: with
    // K = GJ·S/(GJ + S), S = κ G J_r, μ = √(K/EΓ), ψ solves −EΓ ψ″ + K ψ = K T/GJ and
    // θ/T = L/(GJ + S) + (K/GJ²)(L − 2 tanh(μL/2)/μ) (the Vlasov form when S → ∞).
    let (e, g) = (72_000.0, 27_067.7);
    let nu = e / (2.0 * g) - 1.0;
    let (w, t, l) = (10.0, 0.6, 5.0);
    let j = rect_torsion_constant(w, t);
    let (gj, eg) = (g * j, e * rect_warping_constant(w, t));
    let p = Profile::rectangular(Contour::Leaf { l, t }, w, 2.0, 0.0).unwrap();
    let vlasov = vlasov_torsion_stiffness(&p, e, g, TorsionMesh::default());
    // J_r of the Saint-Venant mode (I_p − J) and of the plate mode (t·w³/12).
    // Measured softening against Vlasov: 3.476 % (Saint-Venant mode), 3.442 % (plate mode).
    let modes = [
        (0.0, w * t * (w * w + t * t) / 12.0 - j, 0.03476),
        (1.0, t * w.powi(3) / 12.0, 0.03442),
    ];
    for (plate, jr, measured) in modes {
        let kappa = cowper_rect(nu);
        let s = kappa * g * jr;
        let k = gj * s / (gj + s);
        let mu = (k / eg).sqrt();
        let exact = 1.0 / (l / (gj + s) + k / (gj * gj) * (l - 2.0 * (mu * l / 2.0).tanh() / mu));
        let shear = WarpingShear { kappa, plate };
        let fe = benscoter_torsion_stiffness(&p, None, e, g, shear, TorsionMesh::default());
        assert!(rel(fe, exact) < 1e-4, "plate {plate}: {fe} vs {exact}");
        // The warping shear softens this short wide bar (L/w = 0.5) by ≈ 3.5 %.
        let soft = 1.0 - fe / vlasov;
        assert!((soft - measured).abs() < 2e-4, "plate {plate}: softer by {soft}");
    }
}

#[test]
fn long_leaf_tends_to_saint_venant() {
    // Warping restraint only acts within ~1/k of the ends: k_Vlasov/(GJ/L) → 1 as L grows.
    let (e, g) = (72_000.0, 27_067.7);
    let (w, t) = (10.0, 1.0);
    let gj = g * rect_torsion_constant(w, t);
    let mut last = f64::INFINITY;
    for &l in &[20.0, 200.0, 2000.0] {
        let p = Profile::rectangular(Contour::Leaf { l, t }, w, 4.0, 0.0).unwrap();
        let ratio = vlasov_torsion_stiffness(&p, e, g, TorsionMesh::default()) / (gj / l);
        assert!(ratio > 1.0 && ratio < last);
        last = ratio;
    }
    assert!(last - 1.0 < 5e-3, "{last}");
}

#[test]
fn torsion_mesh_converged() {
    // The default mesh against a 4× finer one, Ruiz et al. notch in its blanks: < 1e-4.
    let p = Profile::rectangular(Contour::Circular { r: 8.0, t: 2.0 }, 10.0, 10.0, 20.0).unwrap();
    let (e, g) = (72_000.0, 27_067.7);
    let k0 = vlasov_torsion_stiffness(&p, e, g, TorsionMesh::default());
    let k1 = vlasov_torsion_stiffness(
        &p,
        e,
        g,
        TorsionMesh {
            per_piece: 32,
            per_blank: 30,
        },
    );
    assert!(rel(k0, k1) < 1e-4, "{k0} vs {k1}");
}
