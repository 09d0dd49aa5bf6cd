//! Quadrature convergence and structural checks of the flexibility integration.

use flexfem::hinge::integrate::{flex_integrals, BlankRestraint, Moduli, Quadrature};
use flexfem::hinge::{segment_compliance, HingeSpec};
use flexfem::material::Material;

mod common;
use common::fixtures;

/// A quadrature three times finer than the default, for convergence checks.
const FINE: Quadrature = Quadrature {
    arc_panels: 24,
    linear_panels: 8,
};

fn specs() -> Vec<HingeSpec> {
    vec![
        fixtures::ruiz2019_revolute_hinge(),
        HingeSpec::CircularNotch {
            r: 10.0,
            t: 0.01,
            w: 5.0,
            h: 30.0,
            blank_length: 5.0,
        },
        HingeSpec::EllipticalNotch {
            ax: 6.0,
            ay: 2.0,
            t: 0.5,
            w: 8.0,
            h: 4.0,
            blank_length: 10.0,
        },
        fixtures::pantilt_corner_filleted_hinge(),
        HingeSpec::Leaf {
            l: 10.0,
            t: 0.5,
            w: 10.0,
            h: 5.0,
            blank_length: 10.0,
        },
        fixtures::ruiz2019_spherical_hinge(),
        HingeSpec::SphericalNeck {
            l: 1.0,
            t: 0.3,
            r: 6.0,
            h: 8.0,
            blank_length: 5.0,
        },
    ]
}

#[test]
fn quadrature_converged_to_1e_6() {
    // Brief: the default panels must agree with an 8× refined quadrature to 1e-6 (relative to
    // each diagonal term; off-diagonals relative to √(C_ii C_jj)).
    let m = Material::AL7075;
    let mo = Moduli {
        e: m.e,
        e_bend: m.e,
        g: m.shear_modulus(),
        nu: m.nu,
        shear: true,
        notch_half: 0.0,
        e_bend_fillet: m.e,
        fillet_from: 0.0,
        e_axial: m.e,
        e_axial_fillet: m.e,
        blank: BlankRestraint::default(),
    };
    for spec in specs() {
        let p = spec.profile().unwrap();
        let half = p.half_length();
        let c0 = flex_integrals(&p, &mo, -half, half, Quadrature::default()).compliance();
        let c1 = flex_integrals(&p, &mo, -half, half, FINE).compliance();
        for i in 0..6 {
            for j in 0..6 {
                let scale = (c1[(i, i)] * c1[(j, j)]).sqrt();
                let d = (c0[(i, j)] - c1[(i, j)]).abs() / scale;
                assert!(d < 1e-6, "{spec:?} C[{i}][{j}] differs by {d:e}");
            }
        }
    }
}

#[test]
fn compliance_is_symmetric_positive_definite() {
    // Maxwell–Betti: C = Cᵀ; strain energy positive: C SPD.
    for spec in specs() {
        let p = spec.profile().unwrap();
        let half = p.half_length();
        let c = segment_compliance(&p, &Material::AL7075, -half, half);
        assert!((c - c.transpose()).norm() <= 1e-14 * c.norm());
        assert!(c.cholesky().is_some(), "{spec:?}");
    }
}

#[test]
fn prismatic_cantilever_matches_timoshenko() {
    // Leaf with blank 0 is a prismatic Timoshenko cantilever of length l:
    // u_z/F_z = l³/(3EI) + l/(κGA), θ/M = l/(EI), θ_y/F_z = −l²/(2EI) (textbook, e.g. Gere).
    let (l, t, w) = (12.0, 1.0, 1.0);
    let spec = HingeSpec::Leaf {
        l,
        t,
        w,
        h: 4.0,
        blank_length: 0.0,
    };
    let m = Material::AL7075;
    // Plain beam idealisation: no load spreading, no solid-model factors (a prismatic leaf
    // between rigid faces; w = t so that no plane-strain factor applies either).
    let p = spec.profile().unwrap().spread(0.0);
    let c = segment_compliance(&p, &m, -l / 2.0, l / 2.0);
    let ei = m.e * w * t.powi(3) / 12.0;
    let kappa = 10.0 * (1.0 + m.nu) / (12.0 + 11.0 * m.nu);
    let gas = m.shear_modulus() * kappa * w * t;
    let r = |a: f64, b: f64| (a - b).abs() / b.abs();
    assert!(r(c[(2, 2)], l.powi(3) / (3.0 * ei) + l / gas) < 1e-12);
    assert!(r(c[(4, 4)], l / ei) < 1e-12);
    assert!(r(c[(2, 4)], -l * l / (2.0 * ei)) < 1e-12);
    assert!(r(c[(0, 0)], l / (m.e * w * t)) < 1e-12);
}

#[test]
fn segments_compose_to_whole() {
    // Flexibility of [a, c] = flexibility of [b, c] + that of [a, b] transported to c
    // (rigid transfer over c − b), so the stage builder may chain segment elements.
    let spec = fixtures::ruiz2019_revolute_hinge();
    let p = spec.profile().unwrap();
    let m = Material::AL7075;
    let (a, b, c) = (-p.half_length(), 1.3, p.half_length());
    let whole = segment_compliance(&p, &m, a, c);
    let c1 = segment_compliance(&p, &m, a, b);
    let c2 = segment_compliance(&p, &m, b, c);
    // Load at c → load at b: forces equal, M_b = M_c + r × F with r = (c − b) e_x.
    let mut tr = nalgebra::Matrix6::<f64>::identity();
    let d = c - b;
    tr[(4, 2)] = -d; // M_y(b) = M_y − d F_z
    tr[(5, 1)] = d; // M_z(b) = M_z + d F_y
    let composed = tr.transpose() * c1 * tr + c2;
    assert!((composed - whole).norm() < 1e-9 * whole.norm());
}

/// The axial flexibility is additive along the hinge, so segments cut anywhere, across the notch
/// end where the axial load's spreading changes slope (`Profile::axial`), sum to the whole: for a
/// leaf (the spreading starts at the notch end), a short wide corner-filleted hinge in a tall
/// blank and a turned neck, cut at the notch end, just inside and just outside it and in the
/// blank, to 1e-12 of the whole (each has the axial load's own, faster spreading beyond the
/// notch).
#[test]
fn axial_segments_compose_across_the_notch_end() {
    use flexfem::hinge::HingeSpec;
    let m = Material::AL7075;
    for hinge in [
        r#"{"type": "leaf", "l": 3, "t": 1, "w": 5, "h": 8, "blank_length": 6}"#,
        r#"{"type": "corner_filleted", "l": 2.4, "R": 0.65, "t": 1.2, "w": 20.9, "h": 11.75, "blank_length": 7.5}"#,
        r#"{"type": "spherical_neck", "l": 2, "t": 2, "R": 3, "h": 10, "blank_length": 10}"#,
    ] {
        let spec: HingeSpec = serde_json::from_str(hinge).unwrap();
        let p = spec.profile().unwrap();
        let (hn, half) = (p.half_notch, p.half_length());
        let whole = segment_compliance(&p, &m, -half, half)[(0, 0)];
        let cuts = [
            -half,
            -0.5 * (hn + half),
            -hn,
            -0.9 * hn,
            0.0,
            0.95 * hn,
            hn,
            1.05 * hn,
            0.5 * (hn + half),
            half,
        ];
        let sum: f64 = cuts
            .windows(2)
            .map(|w| segment_compliance(&p, &m, w[0], w[1])[(0, 0)])
            .sum();
        assert!((sum / whole - 1.0).abs() < 1e-12, "{hinge}: {sum} vs {whole}");
        let bending_spread = p.axial().expect("the default spreading");
        assert!(
            bending_spread.spread.unwrap().blank_slope > p.spread.unwrap().blank_slope,
            "{hinge}"
        );
    }
}
