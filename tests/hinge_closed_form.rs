//! Published closed forms against the numerically integrated flexibility of the notch alone
//! (blank 0, Euler–Bernoulli, geometry inside each formula's assumptions).

use flexfem::hinge::closed_form as cf;
use flexfem::hinge::integrate::{flex_integrals, BlankRestraint, Moduli, Quadrature};
use flexfem::hinge::{Contour, HingeError, Profile};

const E: f64 = 72_000.0;

fn eb() -> Moduli {
    Moduli {
        e: E,
        e_bend: E,
        g: E / 2.66,
        nu: 0.33,
        shear: false,
        notch_half: 0.0,
        e_bend_fillet: E,
        fillet_from: 0.0,
        e_axial: E,
        e_axial_fillet: E,
        blank: BlankRestraint::default(),
    }
}

/// M_y/θ_y of the profile from the quadrature (Euler–Bernoulli), notch alone.
fn k_numeric(p: &Profile) -> f64 {
    let half = p.half_length();
    1.0 / flex_integrals(p, &eb(), -half, half, Quadrature::default()).bend[0]
}

fn rel(a: f64, b: f64) -> f64 {
    (a - b).abs() / b.abs()
}

/// Asserts that the closed form `kc` of an exact profile (no notch spreading) equals the
/// integrated bending stiffness to 1e-8.
fn closed_form_is_exact(p: Result<Profile, HingeError>, kc: f64, what: std::fmt::Arguments) {
    let k = k_numeric(&p.unwrap().spread(0.0));
    assert!(rel(kc, k) < 1e-8, "{what}: {kc} vs {k}");
}

/// Circular notches whose full semicircle fits in the blank (h = t + 2R): the closed forms
/// integrate exactly that geometry.
fn circular(r: f64, t: f64, w: f64) -> Profile {
    Profile::rectangular(Contour::Circular { r, t }, w, t + 2.0 * r + 1e-12, 0.0)
        .unwrap()
        .spread(0.0)
}

#[test]
fn circular_exact_forms_match_integration() {
    // Paros & Weisbord (1965) full, Wu & Zhou (2002) and the Smith/Lobontiu ellipse with
    // a_x = a_y = R are all the exact Euler–Bernoulli integral over the semicircular notch:
    // agreement to quadrature accuracy over t/R from 0.002 to 2.
    for &(r, t, w) in &[
        (8.0, 2.0, 10.0),
        (5.0, 0.01, 3.0),
        (1.0, 2.0, 7.0),
        (12.0, 0.3, 20.0),
        (2.0, 1.0, 1.0),
    ] {
        let k = k_numeric(&circular(r, t, w));
        for (name, kc) in [
            ("paros_weisbord_full", cf::paros_weisbord_full(r, t, w, E)),
            ("wu_zhou", cf::wu_zhou(r, t, w, E)),
            ("smith_lobontiu_ax_eq_ay", cf::smith_lobontiu_elliptical(r, r, t, w, E)),
        ] {
            assert!(rel(kc, k) < 1e-8, "{name} R={r} t={t}: {kc} vs {k}");
        }
    }
}

#[test]
fn paros_weisbord_simplified_holds_for_thin_notches() {
    // Paros & Weisbord's simplified law is the t/R → 0 limit; its error is O(√(t/R)) — here
    // it must be within 0.5 % at t/R = 1e-3 and within 5 % at t/R = 0.1.
    let (r, w) = (10.0, 5.0);
    let k = k_numeric(&circular(r, 0.01, w));
    assert!(rel(cf::paros_weisbord_simplified(r, 0.01, w, E), k) < 5e-3);
    let k = k_numeric(&circular(r, 1.0, w));
    assert!(rel(cf::paros_weisbord_simplified(r, 1.0, w, E), k) < 5e-2);
}

#[test]
fn elliptical_matches_integration() {
    // Smith et al. (1997) / Lobontiu (2002) full half-ellipse.
    for &(ax, ay, t) in &[(6.0, 3.0, 1.0), (2.0, 8.0, 0.5), (10.0, 10.0, 3.0)] {
        let p = Profile::rectangular(Contour::Elliptical { ax, ay, t }, 8.0, t + 2.0 * ay + 1e-12, 0.0);
        let kc = cf::smith_lobontiu_elliptical(ax, ay, t, 8.0, E);
        closed_form_is_exact(p, kc, format_args!("ax={ax} ay={ay}"));
    }
}

#[test]
fn corner_filleted_matches_integration() {
    // Lobontiu et al. (2001): straight part + one full circular notch; fillets complete
    // (t + 2R ≤ h).
    for &(l, r, t) in &[(5.0, 1.75, 0.6), (10.0, 1.0, 0.3), (4.0, 2.0, 1.0)] {
        let p = Profile::rectangular(Contour::CornerFilleted { l, r, t }, 10.0, 15.0, 0.0);
        let kc = cf::lobontiu_corner_filleted(l, r, t, 10.0, E);
        closed_form_is_exact(p, kc, format_args!("l={l} R={r} t={t}"));
    }
}

#[test]
fn leaf_is_exact() {
    // Prismatic Euler–Bernoulli: K = E w t³/(12 l), exact; the quadrature must give it to 1e-9.
    let p = Profile::rectangular(Contour::Leaf { l: 7.0, t: 0.5 }, 4.0, 3.0, 0.0)
        .unwrap()
        .spread(0.0);
    assert!(rel(k_numeric(&p), cf::leaf(7.0, 0.5, 4.0, E)) < 1e-9);
}

#[test]
fn turned_neck_matches_integration() {
    // Paros & Weisbord circular-section hinge: exact full-arc integral (+ straight neck), with a
    // blank large enough that the disk is never clipped (h ≥ √2 (t + 2R)).
    for &(l, t, r) in &[(5.0, 3.0, 4.0), (0.0, 1.0, 5.0), (2.0, 0.2, 3.0)] {
        let h = 1.5 * (t + 2.0 * r);
        let p = Profile::neck(l, t, r, h, 0.0).unwrap().spread(0.0);
        let k = k_numeric(&p);
        let kc = cf::paros_weisbord_circular_section(l, t, r, E);
        assert!(rel(kc, k) < 1e-8, "l={l} t={t} R={r}: {kc} vs {k}");
    }
    // Small-d/R law: within 1 % at t/R = 1e-3.
    let p = Profile::neck(0.0, 0.01, 10.0, 40.0, 0.0).unwrap().spread(0.0);
    assert!(
        rel(
            cf::paros_weisbord_circular_section_simplified(0.0, 0.01, 10.0, E),
            k_numeric(&p)
        ) < 1e-2
    );
}

#[test]
fn closed_forms_scale_as_length_cubed() {
    // Dimensional check (catches R vs R², t^{5/2} vs t^{3/2} typos): scaling every length by λ
    // scales a rotational stiffness E·L³ by λ³.
    let lam: f64 = 3.7;
    let l3 = lam.powi(3);
    type Scaled = Box<dyn Fn(f64) -> f64>;
    let checks: Vec<(&str, Scaled)> = vec![
        (
            "pw_full",
            Box::new(|s| cf::paros_weisbord_full(8.0 * s, 2.0 * s, 10.0 * s, E)),
        ),
        (
            "pw_simpl",
            Box::new(|s| cf::paros_weisbord_simplified(8.0 * s, 2.0 * s, 10.0 * s, E)),
        ),
        ("wu_zhou", Box::new(|s| cf::wu_zhou(8.0 * s, 2.0 * s, 10.0 * s, E))),
        (
            "ellipse",
            Box::new(|s| cf::smith_lobontiu_elliptical(6.0 * s, 3.0 * s, 1.0 * s, 10.0 * s, E)),
        ),
        (
            "corner",
            Box::new(|s| cf::lobontiu_corner_filleted(5.0 * s, 1.75 * s, 0.6 * s, 10.0 * s, E)),
        ),
        ("leaf", Box::new(|s| cf::leaf(5.0 * s, 0.6 * s, 10.0 * s, E))),
        (
            "neck",
            Box::new(|s| cf::paros_weisbord_circular_section(5.0 * s, 3.0 * s, 4.0 * s, E)),
        ),
        (
            "neck_simpl",
            Box::new(|s| cf::paros_weisbord_circular_section_simplified(5.0 * s, 3.0 * s, 4.0 * s, E)),
        ),
    ];
    for (name, f) in checks {
        assert!(rel(f(lam), l3 * f(1.0)) < 1e-12, "{name}");
    }
}
