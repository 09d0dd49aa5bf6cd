//! Geometry and quadrature of the load-spreading model (`Profile::spread`): the effective
//! half-size follows the contour until its slope reaches 1/2, then grows linearly at 1/2 until
//! it meets the blank. Expected values are worked by hand from the families' contours.

use flexfem::hinge::integrate::{flex_integrals, BlankRestraint, Moduli, Quadrature};
use flexfem::hinge::profile::SPREAD_SLOPE;
use flexfem::hinge::{Contour, Profile};

/// A quadrature three times finer than the default, for convergence checks.
const FINE: Quadrature = Quadrature {
    arc_panels: 24,
    linear_panels: 8,
};

#[test]
fn leaf_spreads_from_its_step() {
    // Leaf l = 10, t = 1 in an h = 8 blank: the step at x = 5 spreads at 1/2 per mm from
    // t/2 = 0.5 to h/2 = 4, i.e. over 7 mm: reach 12 mm; at x = 6 the effective t is 1 + 2·0.5.
    let p = Profile::rectangular(Contour::Leaf { l: 10.0, t: 1.0 }, 5.0, 8.0, 10.0).unwrap();
    assert_eq!(SPREAD_SLOPE, 0.5);
    assert!((p.spread_reach() - 12.0).abs() < 1e-12);
    assert!((p.effective_thickness(6.0) - 2.0).abs() < 1e-12);
    assert!((p.effective_thickness(4.0) - 1.0).abs() < 1e-12);
    assert!((p.effective_thickness(13.0) - 8.0).abs() < 1e-12);
    // Without spreading the section is the geometry.
    let g = p.spread(0.0);
    assert!((g.effective_thickness(6.0) - 8.0).abs() < 1e-12);
}

#[test]
fn circular_notch_spreads_from_the_tangent_point() {
    // R = 8, t = 2, h = 10: half-size 1 + 8 − √(64 − u²) has slope u/√(64 − u²) = 1/2 at
    // u* = 8·0.5/√1.25 = 3.5777; there s = 9 − √(64 − 12.8) = 1.8446; the taper meets h/2 = 5 at
    // u* + (5 − 1.8446)/0.5 = 9.8885 mm, beyond the notch end √(64 − 25) = 6.245 mm.
    let p = Profile::rectangular(Contour::Circular { r: 8.0, t: 2.0 }, 10.0, 10.0, 20.0).unwrap();
    let sp = p.spread.expect("spreads");
    let u = 4.0 / 1.25f64.sqrt();
    assert!((sp.from - u).abs() < 1e-12);
    assert!((sp.size0 - (9.0 - (64.0 - u * u).sqrt())).abs() < 1e-12);
    assert!((p.spread_reach() - (u + (5.0 - sp.size0) / 0.5)).abs() < 1e-12);
    // Below the tangent point the geometry; beyond it the taper, below the geometry.
    assert!((p.effective_thickness(2.0) - p.thickness(2.0)).abs() < 1e-12);
    let x = 5.0;
    let taper = 2.0 * (sp.size0 + 0.5 * (x - u));
    assert!((p.effective_thickness(x) - taper).abs() < 1e-12 && taper < p.thickness(x));
    // A shallow notch that never gets steeper than 1/2 does not spread: R = 50, t = 2, h = 3.
    let q = Profile::rectangular(Contour::Circular { r: 50.0, t: 2.0 }, 10.0, 3.0, 5.0).unwrap();
    assert!(q.spread.is_none());
}

#[test]
fn quadrature_of_tapers_is_converged() {
    // The taper pieces (log-parameterised Gauss) against 8× the panels, for every family.
    let m = Moduli {
        e: 72000.0,
        e_bend: 72000.0,
        g: 72000.0 / 2.66,
        nu: 0.33,
        shear: true,
        notch_half: 0.0,
        e_bend_fillet: 72000.0,
        fillet_from: 0.0,
        e_axial: 72000.0,
        e_axial_fillet: 72000.0,
        blank: BlankRestraint::default(),
    };
    let profiles = [
        Profile::rectangular(Contour::Circular { r: 8.0, t: 2.0 }, 10.0, 10.0, 20.0).unwrap(),
        Profile::rectangular(
            Contour::Elliptical {
                ax: 6.0,
                ay: 3.0,
                t: 1.0,
            },
            6.0,
            6.0,
            10.0,
        )
        .unwrap(),
        Profile::rectangular(
            Contour::CornerFilleted {
                l: 5.0,
                r: 1.75,
                t: 0.6,
            },
            10.0,
            15.0,
            15.0,
        )
        .unwrap(),
        Profile::rectangular(Contour::Leaf { l: 10.0, t: 1.0 }, 5.0, 8.0, 10.0).unwrap(),
        Profile::neck(5.0, 3.0, 4.0, 10.0, 20.0).unwrap(),
        Profile::neck(3.0, 2.0, 1.0, 6.0, 10.0).unwrap(),
    ];
    for p in profiles {
        let half = p.half_length();
        let a = flex_integrals(&p, &m, -half, half, Quadrature::default()).compliance();
        let b = flex_integrals(&p, &m, -half, half, FINE).compliance();
        let err = (a - b).norm() / b.norm();
        assert!(err < 1e-8, "{:?}: {err:e}", p.contour);
        for i in 0..6 {
            assert!((a[(i, i)] / b[(i, i)] - 1.0).abs() < 1e-8, "{:?} [{i}]", p.contour);
        }
    }
}
