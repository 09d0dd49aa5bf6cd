//! Where the solid calibration of the hinge model holds, and warnings outside it.
//!
//! The three-dimensional factors of [`super::solid_effects`] are fitted laws and the torsion
//! model was checked against converged quadratic-tetrahedron solid models
//! (`tools/solid_reference.py`, tests/hinge_solid_reference.rs) over these ranges:
//!
//! * circular notches: t/R 0.06–0.5, w/t 0.5–20 (41 models: bending within 2.5 %, axial 4 %,
//!   peak stress 6 %, torsion 12 %);
//! * turned necks: l/t 1–5, t/R 0.67–2 (7 models);
//! * the short-notch factor G: t/ρ 1/16–1/2 (ρ the waist curvature radius: R for circular,
//!   a_x²/a_y for elliptical notches);
//! * the plane-strain factor P (every rectangular family): w/t 0.5–20.
//!
//! A second solver, CalculiX (ccx 2.20, C3D10, `tools/ccx_reference.py`; tests/hinge_ccx_reference.rs
//! with its fitted and held-out rows, 218 models, stiffnesses extrapolated from two meshes,
//! peak stresses converged on refined eighths), checks circular notches over t/R 0.08–0.5,
//! w/t 0.5–20 and corner-filleted hinges over l/t 2–10, R/t 0.5–2.5, w/t 1–20, blank w/h
//! 0.05–5 (held out: bending within 2.4 %, axial 3.9 % (corner-filleted 5.2 %), peak stress
//! 3.9 %, torsion 11.3 % (corner-filleted 14.0 %, on the shortest, widest leaves with sharp
//! fillets; 9.4 % elsewhere)); the torsion law of [`super::torsion::solid_torsion_stiffness`] and the corner-filleted K_t
//! ([`super::stress::stress_concentration`]) were fitted there. Corner-filleted hinges are
//! range-checked in w/t only (the bundled pan-tilt hinge, t/R = 0.34, w/t = 16.7, lies in the
//! scikit-fem set).
//!
//! Outside these ranges the model is extrapolated; the result still comes out, with a warning.

use super::profile::{Contour, Profile};

/// Slack on the published (rounded) range ends: t/R = 2/3 is inside "0.67–2".
const SLACK: f64 = 0.01;

/// One range check: the ratio's name, its value and the calibrated interval.
fn check(out: &mut Vec<String>, family: &str, name: &str, value: f64, lo: f64, hi: f64, what: &str) {
    if !(value >= lo * (1.0 - SLACK) && value <= hi * (1.0 + SLACK)) {
        out.push(format!(
            "{family} {name} = {} is outside the solid-calibrated range {lo}–{hi} ({what}): extrapolated",
            fmt(value)
        ));
    }
}

fn fmt(v: f64) -> String {
    if v != 0.0 && (v.abs() >= 1e4 || v.abs() < 1e-3) {
        format!("{v:.3e}")
    } else {
        format!("{}", (v * 1e4).round() / 1e4)
    }
}

/// Warnings for a hinge whose geometry lies outside the ranges its solid calibration covers
/// (see the module docs); empty inside them.
pub fn calibration_warnings(profile: &Profile) -> Vec<String> {
    let mut out = Vec::new();
    let (w, t) = (profile.w, profile.t_min());
    match profile.contour {
        Contour::Circular { r, .. } => {
            let what = "41 circular notches";
            check(&mut out, "circular_notch", "t/R", t / r, 0.06, 0.5, what);
            check(&mut out, "circular_notch", "w/t", w / t, 0.5, 20.0, what);
        }
        Contour::Elliptical { ax, ay, .. } => {
            let rho = ax * ax / ay;
            check(
                &mut out,
                "elliptical_notch",
                "t/ρ (ρ = ax²/ay)",
                t / rho,
                0.06,
                0.5,
                "factor G fitted on circular notches",
            );
            check(
                &mut out,
                "elliptical_notch",
                "w/t",
                w / t,
                0.5,
                20.0,
                "plane-strain factor P",
            );
        }
        Contour::CornerFilleted { .. } => {
            check(
                &mut out,
                "corner_filleted",
                "w/t",
                w / t,
                0.5,
                20.0,
                "plane-strain factor P",
            );
        }
        Contour::Leaf { .. } => {
            check(&mut out, "leaf", "w/t", w / t, 0.5, 20.0, "plane-strain factor P");
        }
        Contour::SphericalNeck { l, r, .. } => {
            let what = "7 turned necks";
            check(&mut out, "spherical_neck", "l/t", l / t, 1.0, 5.0, what);
            check(&mut out, "spherical_neck", "t/R", t / r, 0.67, 2.0, what);
        }
    }
    out
}
