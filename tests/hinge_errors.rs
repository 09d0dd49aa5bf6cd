//! Non-physical geometry and materials are refused with the parameter, value and the rule
//!.

use flexfem::hinge::{characterise, HingeError, HingeSpec};
use flexfem::material::Material;

fn circ(r: f64, t: f64, w: f64, h: f64, blank: f64) -> HingeSpec {
    HingeSpec::CircularNotch {
        r,
        t,
        w,
        h,
        blank_length: blank,
    }
}

fn param_of(e: HingeError) -> &'static str {
    match e {
        HingeError::InvalidGeometry { param, .. } | HingeError::InvalidMaterial { param, .. } => param,
    }
}

#[test]
fn invalid_geometry_names_the_parameter() {
    let al = Material::AL7075;
    let cases: Vec<(HingeSpec, &str)> = vec![
        (circ(8.0, 0.0, 10.0, 10.0, 20.0), "t"),
        (circ(8.0, -1.0, 10.0, 10.0, 20.0), "t"),
        (circ(8.0, 10.0, 10.0, 10.0, 20.0), "t"), // t ≥ h
        (circ(0.0, 2.0, 10.0, 10.0, 20.0), "R"),
        (circ(-3.0, 2.0, 10.0, 10.0, 20.0), "R"),
        (circ(8.0, 2.0, 0.0, 10.0, 20.0), "w"),
        (circ(8.0, 2.0, 10.0, f64::NAN, 20.0), "h"),
        (circ(8.0, 2.0, 10.0, 10.0, -1.0), "blank_length"),
        (
            HingeSpec::EllipticalNotch {
                ax: 0.0,
                ay: 2.0,
                t: 1.0,
                w: 5.0,
                h: 5.0,
                blank_length: 1.0,
            },
            "ax",
        ),
        (
            HingeSpec::EllipticalNotch {
                ax: 2.0,
                ay: -2.0,
                t: 1.0,
                w: 5.0,
                h: 5.0,
                blank_length: 1.0,
            },
            "ay",
        ),
        // Two fillets longer than the notch.
        (
            HingeSpec::CornerFilleted {
                l: 3.0,
                r: 2.0,
                t: 0.5,
                w: 5.0,
                h: 5.0,
                blank_length: 1.0,
            },
            "R",
        ),
        (
            HingeSpec::Leaf {
                l: 0.0,
                t: 0.5,
                w: 5.0,
                h: 5.0,
                blank_length: 1.0,
            },
            "l",
        ),
        (
            HingeSpec::SphericalNeck {
                l: 5.0,
                t: 12.0,
                r: 4.0,
                h: 10.0,
                blank_length: 20.0,
            },
            "t",
        ),
        (
            HingeSpec::SphericalNeck {
                l: -1.0,
                t: 3.0,
                r: 4.0,
                h: 10.0,
                blank_length: 20.0,
            },
            "l",
        ),
    ];
    for (spec, want) in cases {
        let err = characterise(&spec, &al).expect_err(&format!("{spec:?} accepted"));
        let msg = err.to_string();
        assert_eq!(param_of(err), want, "{spec:?}: {msg}");
        assert!(msg.contains(want) && msg.contains("must"), "{msg}");
    }
}

#[test]
fn invalid_material_is_refused() {
    let spec = circ(8.0, 2.0, 10.0, 10.0, 20.0);
    for (nu, e, want) in [(0.5, 72e3, "nu"), (-1.0, 72e3, "nu"), (0.3, 0.0, "E"), (0.3, -5.0, "E")] {
        let m = Material {
            nu,
            e,
            ..Material::AL7075
        };
        let err = characterise(&spec, &m).unwrap_err();
        assert_eq!(param_of(err), want);
    }
}

#[test]
fn spec_deserialises_with_interface_names() {
    // The documented example: {"type": "circular_notch", "R": 8, "t": 2, "w": 10, "h": 10, "blank_length": 20}
    let s: HingeSpec =
        serde_json::from_str(r#"{"type": "circular_notch", "R": 8, "t": 2, "w": 10, "h": 10, "blank_length": 20}"#)
            .unwrap();
    assert_eq!(s, circ(8.0, 2.0, 10.0, 10.0, 20.0));
    let s: HingeSpec =
        serde_json::from_str(r#"{"type": "spherical_neck", "l": 5, "t": 3, "R": 4, "h": 10, "blank_length": 20}"#)
            .unwrap();
    assert!(matches!(s, HingeSpec::SphericalNeck { .. }));
    // Unknown fields are refused.
    assert!(serde_json::from_str::<HingeSpec>(
        r#"{"type": "leaf", "l": 5, "t": 1, "w": 4, "h": 4, "blank_length": 2, "r": 1}"#
    )
    .is_err());
}

#[test]
fn no_panic_on_odd_but_valid_geometry() {
    // Deep notches capped by the blank, tiny t/R, notch wider than deep: finite positive results.
    let al = Material::AL7075;
    for spec in [
        circ(0.5, 9.9, 10.0, 10.0, 0.0),
        circ(100.0, 1e-3, 10.0, 10.0, 1.0),
        HingeSpec::EllipticalNotch {
            ax: 0.1,
            ay: 50.0,
            t: 0.2,
            w: 1.0,
            h: 3.0,
            blank_length: 0.0,
        },
        HingeSpec::CornerFilleted {
            l: 2.0,
            r: 1.0,
            t: 0.1,
            w: 20.0,
            h: 1.0,
            blank_length: 0.0,
        },
        HingeSpec::SphericalNeck {
            l: 0.0,
            t: 9.9,
            r: 0.1,
            h: 10.0,
            blank_length: 0.0,
        },
    ] {
        let r = characterise(&spec, &al).unwrap();
        for k in [
            r.hinge.k_bend,
            r.hinge.k_bend_off,
            r.hinge.k_torsion,
            r.hinge.k_axial,
            r.notch_only.k_torsion,
        ] {
            assert!(k.is_finite() && k > 0.0, "{spec:?}: {k}");
        }
    }
}
