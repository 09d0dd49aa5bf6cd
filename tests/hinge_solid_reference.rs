//! Hinge models against converged solid finite-element models of the same geometry.
//!
//! The issue's accuracy bands refer to converged quadratic-tetrahedron (C3D10) solid models.
//! The references below were computed with `tools/solid_reference.py`: the exact geometry of
//! the hinge built in gmsh 4.15 (OpenCASCADE), meshed with 10-node tetrahedra whose size is the
//! local thickness / n (n = 5 here, 4 for the thinnest notches), solved with scikit-fem 12
//! (P2 Lagrange, isoparametric) and CHOLMOD; one blank end face clamped, the other rigid
//! (six unit rigid motions → 6×6 face stiffness → compliance at the face centre); peak
//! nodal-averaged von Mises stress under a pure compliant-axis moment. Raw results:
//! `tools/solid_reference_results.jsonl`.
//!
//! That pipeline reproduces the independent references it can be checked against: Ruiz et al.'s
//! turned neck l5/t3/R4 32.60 N·m/rad vs ANSYS 32.67 (−0.2 %); the 8R pan-tilt's corner-filleted
//! hinge 232.58 N·mm/rad = 4.059 N·mm/° vs the converged solid value 4.05 (+0.2 %).
//! Mesh convergence on the Ruiz et al. notch: n = 3 → 5 changes k_bend by −0.55 %, on the
//! corner-filleted hinge by −0.6 %.
//!
//! These references are ours (computed here), so every comparison below is a cross-check of
//! the beam model against our own solid models, not an independent validation.
//!
//! flexfem's beam model uses solid-calibrated ingredients (load spreading at slope 1/2, the
//! short-notch factor G, the plane-strain factor P — `hinge::solid_effects` —, the turned
//! neck's K_t — `hinge::stress` —, and the torsion load spreading), all found on the rows of
//! [`FITTED`] (commit "hinge: solid-calibrated beam model …" and the torsion commit after it):
//! 36 of the 41 circular notches, 5 of the 7 necks and the pan-tilt corner-filleted hinge.
//! Their errors are fit residuals, reported and asserted apart from those of [`HELD_OUT`]:
//! 9 models computed after the fits and never used in one (5 circular notches, 2 necks, an
//! elliptical notch, a leaf). Nine rows are few; they show that the laws carry over to those
//! geometries, no more.

use flexfem::hinge::{characterise, HingeSpec};
use flexfem::material::Material;

struct Ref {
    hinge: &'static str,
    /// Young's modulus, MPa.
    e: f64,
    nu: f64,
    /// Solid-model compliant-axis bending stiffness, N·mm/rad.
    k_bend: f64,
    /// Solid-model torsional stiffness, N·mm/rad.
    k_torsion: f64,
    /// Solid-model axial stiffness, N/mm.
    k_axial: f64,
    /// Solid-model peak von Mises stress per unit compliant-axis moment, MPa/(N·mm).
    spm: f64,
}

/// Rows used to fit the solid-calibrated ingredients (commit "hinge: solid-calibrated beam
/// model"): the short-notch factor G and the plane-strain factor P on the circular notches, the
/// neck's K_t on the necks, the torsion load spreading on the circular notches and the
/// corner-filleted hinge. Errors on these rows are fit residuals, not accuracy.
const FITTED: &[Ref] = &[
    // Ruiz et al. (2019) revolute notch, n = 5 (n = 3: 96449).
    Ref {
        hinge: r#"{"type": "circular_notch", "R": 8.0, "t": 2.0, "w": 10.0, "h": 10.0, "blank_length": 20.0}"#,
        e: 72000.0,
        nu: 0.33,
        k_bend: 95922.3,
        k_torsion: 196427.0,
        k_axial: 84453.4,
        spm: 0.151083,
    },
    Ref {
        hinge: r#"{"type": "circular_notch", "R": 8.0, "t": 4.0, "w": 10.0, "h": 10.0, "blank_length": 20.0}"#,
        e: 72000.0,
        nu: 0.33,
        k_bend: 416003.0,
        k_torsion: 443819.0,
        k_axial: 110521.0,
        spm: 0.0395016,
    },
    Ref {
        hinge: r#"{"type": "circular_notch", "R": 8.0, "t": 3.0, "w": 10.0, "h": 10.0, "blank_length": 20.0}"#,
        e: 72000.0,
        nu: 0.33,
        k_bend: 234511.0,
        k_torsion: 327731.0,
        k_axial: 98853.0,
        spm: 0.0683839,
    },
    Ref {
        hinge: r#"{"type": "circular_notch", "R": 8.0, "t": 1.0, "w": 10.0, "h": 10.0, "blank_length": 20.0}"#,
        e: 72000.0,
        nu: 0.33,
        k_bend: 18624.5,
        k_torsion: 70657.5,
        k_axial: 64194.5,
        spm: 0.598664,
    },
    Ref {
        hinge: r#"{"type": "spherical_neck", "l": 5.0, "t": 3.0, "R": 4.0, "h": 10.0, "blank_length": 20.0}"#,
        e: 72000.0,
        nu: 0.33,
        k_bend: 32602.7,
        k_torsion: 24677.5,
        k_axial: 38308.3,
        spm: 0.390483,
    },
    Ref {
        hinge: r#"{"type": "circular_notch", "R": 8.0, "t": 1.5, "w": 10.0, "h": 10.0, "blank_length": 20.0}"#,
        e: 72000.0,
        nu: 0.33,
        k_bend: 49111.8,
        k_torsion: 130480.0,
        k_axial: 75431.3,
        spm: 0.267739,
    },
    Ref {
        hinge: r#"{"type": "circular_notch", "R": 4.0, "t": 1.5, "w": 6.0, "h": 7.9, "blank_length": 10.0}"#,
        e: 72000.0,
        nu: 0.33,
        k_bend: 39265.5,
        k_torsion: 75094.8,
        k_axial: 68318.3,
        spm: 0.452178,
    },
    Ref {
        hinge: r#"{"type": "circular_notch", "R": 4.0, "t": 2.0, "w": 6.0, "h": 8.4, "blank_length": 10.0}"#,
        e: 72000.0,
        nu: 0.33,
        k_bend: 76552.4,
        k_torsion: 112657.0,
        k_axial: 78759.2,
        spm: 0.260706,
    },
    Ref {
        hinge: r#"{"type": "circular_notch", "R": 4.0, "t": 1.0, "w": 6.0, "h": 7.4, "blank_length": 10.0}"#,
        e: 72000.0,
        nu: 0.33,
        k_bend: 15079.5,
        k_torsion: 41310.7,
        k_axial: 56460.7,
        spm: 1.00582,
    },
    Ref {
        hinge: r#"{"type": "circular_notch", "R": 8.0, "t": 2.0, "w": 3.0, "h": 10.0, "blank_length": 20.0}"#,
        e: 72000.0,
        nu: 0.33,
        k_bend: 27495.5,
        k_torsion: 16192.5,
        k_axial: 25196.0,
        spm: 0.519802,
    },
    Ref {
        hinge: r#"{"type": "circular_notch", "R": 8.0, "t": 4.0, "w": 3.0, "h": 10.0, "blank_length": 20.0}"#,
        e: 72000.0,
        nu: 0.33,
        k_bend: 122282.0,
        k_torsion: 29471.4,
        k_axial: 32979.3,
        spm: 0.136745,
    },
    Ref {
        hinge: r#"{"type": "spherical_neck", "l": 3.0, "t": 3.0, "R": 2.0, "h": 10.0, "blank_length": 10.0}"#,
        e: 72000.0,
        nu: 0.33,
        k_bend: 49636.3,
        k_torsion: 38127.1,
        k_axial: 59551.7,
        spm: 0.397183,
    },
    Ref {
        hinge: r#"{"type": "spherical_neck", "l": 6.0, "t": 2.0, "R": 3.0, "h": 8.0, "blank_length": 10.0}"#,
        e: 72000.0,
        nu: 0.33,
        k_bend: 6593.37,
        k_torsion: 4986.26,
        k_axial: 20716.6,
        spm: 1.32677,
    },
    Ref {
        hinge: r#"{"type": "spherical_neck", "l": 4.0, "t": 4.0, "R": 2.0, "h": 10.0, "blank_length": 10.0}"#,
        e: 72000.0,
        nu: 0.33,
        k_bend: 121682.0,
        k_torsion: 93479.7,
        k_axial: 82095.2,
        spm: 0.168451,
    },
    Ref {
        hinge: r#"{"type": "circular_notch", "R": 4.0, "t": 0.5, "w": 6.0, "h": 6.9, "blank_length": 10.0}"#,
        e: 72000.0,
        nu: 0.33,
        k_bend: 2831.16,
        k_torsion: 14297.1,
        k_axial: 41372.7,
        spm: 3.93819,
    },
    Ref {
        hinge: r#"{"type": "spherical_neck", "l": 10.0, "t": 2.0, "R": 2.0, "h": 6.0, "blank_length": 10.0}"#,
        e: 72000.0,
        nu: 0.33,
        k_bend: 4615.95,
        k_torsion: 3484.24,
        k_axial: 15188.3,
        spm: 1.32583,
    },
    Ref {
        hinge: r#"{"type": "circular_notch", "R": 8.0, "t": 0.5, "w": 10.0, "h": 10.0, "blank_length": 20.0}"#,
        e: 72000.0,
        nu: 0.33,
        k_bend: 3419.85,
        k_torsion: 23825.2,
        k_axial: 48315.8,
        spm: 2.36524,
    },
    Ref {
        hinge: r#"{"type": "circular_notch", "R": 4.0, "t": 0.25, "w": 1.0, "h": 3.45, "blank_length": 6.9}"#,
        e: 72000.0,
        nu: 0.0,
        k_bend: 78.0205,
        k_torsion: 133.195,
        k_axial: 4907.83,
        spm: 97.259,
    },
    Ref {
        hinge: r#"{"type": "circular_notch", "R": 4.0, "t": 0.25, "w": 1.0, "h": 6.25, "blank_length": 12.5}"#,
        e: 72000.0,
        nu: 0.0,
        k_bend: 78.2039,
        k_torsion: 132.972,
        k_axial: 4686.08,
        spm: 97.1041,
    },
    Ref {
        hinge: r#"{"type": "circular_notch", "R": 4.0, "t": 0.5, "w": 1.0, "h": 3.7, "blank_length": 7.4}"#,
        e: 72000.0,
        nu: 0.0,
        k_bend: 428.772,
        k_torsion: 447.746,
        k_axial: 6555.2,
        spm: 24.5549,
    },
    Ref {
        hinge: r#"{"type": "circular_notch", "R": 4.0, "t": 0.25, "w": 1.0, "h": 8.09, "blank_length": 16.18}"#,
        e: 72000.0,
        nu: 0.0,
        k_bend: 78.2351,
        k_torsion: 132.834,
        k_axial: 4611.18,
        spm: 97.2343,
    },
    Ref {
        hinge: r#"{"type": "circular_notch", "R": 4.0, "t": 0.5, "w": 1.0, "h": 6.5, "blank_length": 13.0}"#,
        e: 72000.0,
        nu: 0.0,
        k_bend: 433.464,
        k_torsion: 444.81,
        k_axial: 6186.26,
        spm: 24.5564,
    },
    Ref {
        hinge: r#"{"type": "circular_notch", "R": 4.0, "t": 0.5, "w": 1.0, "h": 8.34, "blank_length": 16.68}"#,
        e: 72000.0,
        nu: 0.0,
        k_bend: 434.36,
        k_torsion: 443.239,
        k_axial: 6061.38,
        spm: 24.5563,
    },
    Ref {
        hinge: r#"{"type": "circular_notch", "R": 4.0, "t": 1.0, "w": 1.0, "h": 4.2, "blank_length": 8.4}"#,
        e: 72000.0,
        nu: 0.0,
        k_bend: 2236.93,
        k_torsion: 1009.29,
        k_axial: 8563.28,
        spm: 6.28071,
    },
    Ref {
        hinge: r#"{"type": "circular_notch", "R": 4.0, "t": 1.0, "w": 1.0, "h": 7.0, "blank_length": 14.0}"#,
        e: 72000.0,
        nu: 0.0,
        k_bend: 2334.37,
        k_torsion: 992.824,
        k_axial: 8003.95,
        spm: 6.27454,
    },
    Ref {
        hinge: r#"{"type": "circular_notch", "R": 4.0, "t": 1.0, "w": 1.0, "h": 8.84, "blank_length": 17.68}"#,
        e: 72000.0,
        nu: 0.0,
        k_bend: 2355.9,
        k_torsion: 985.73,
        k_axial: 7811.77,
        spm: 6.27296,
    },
    Ref {
        hinge: r#"{"type": "circular_notch", "R": 4.0, "t": 1.5, "w": 1.0, "h": 4.7, "blank_length": 9.4}"#,
        e: 72000.0,
        nu: 0.0,
        k_bend: 5581.05,
        k_torsion: 1366.93,
        k_axial: 9867.89,
        spm: 2.84769,
    },
    Ref {
        hinge: r#"{"type": "circular_notch", "R": 4.0, "t": 1.5, "w": 1.0, "h": 7.5, "blank_length": 15.0}"#,
        e: 72000.0,
        nu: 0.0,
        k_bend: 6060.59,
        k_torsion: 1335.86,
        k_axial: 9196.88,
        spm: 2.85092,
    },
    Ref {
        hinge: r#"{"type": "circular_notch", "R": 4.0, "t": 1.5, "w": 1.0, "h": 9.34, "blank_length": 18.68}"#,
        e: 72000.0,
        nu: 0.0,
        k_bend: 6182.87,
        k_torsion: 1322.54,
        k_axial: 8961.48,
        spm: 2.84761,
    },
    Ref {
        hinge: r#"{"type": "circular_notch", "R": 4.0, "t": 2.0, "w": 1.0, "h": 5.2, "blank_length": 10.4}"#,
        e: 72000.0,
        nu: 0.0,
        k_bend: 10315.4,
        k_torsion: 1618.83,
        k_axial: 10822.4,
        spm: 1.63365,
    },
    Ref {
        hinge: r#"{"type": "circular_notch", "R": 4.0, "t": 2.0, "w": 1.0, "h": 8.0, "blank_length": 16.0}"#,
        e: 72000.0,
        nu: 0.0,
        k_bend: 11641.6,
        k_torsion: 1570.16,
        k_axial: 10085.3,
        spm: 1.63034,
    },
    Ref {
        hinge: r#"{"type": "circular_notch", "R": 4.0, "t": 2.0, "w": 1.0, "h": 9.84, "blank_length": 19.68}"#,
        e: 72000.0,
        nu: 0.0,
        k_bend: 12025.4,
        k_torsion: 1552.3,
        k_axial: 9821.58,
        spm: 1.63106,
    },
    Ref {
        hinge: r#"{"type": "circular_notch", "R": 4.0, "t": 0.5, "w": 0.5, "h": 6.5, "blank_length": 13.0}"#,
        e: 72000.0,
        nu: 0.33,
        k_bend: 216.858,
        k_torsion: 71.8912,
        k_axial: 3104.56,
        spm: 48.9838,
    },
    Ref {
        hinge: r#"{"type": "circular_notch", "R": 4.0, "t": 0.5, "w": 1.5, "h": 6.5, "blank_length": 13.0}"#,
        e: 72000.0,
        nu: 0.33,
        k_bend: 659.851,
        k_torsion: 757.733,
        k_axial: 9319.6,
        spm: 16.2281,
    },
    Ref {
        hinge: r#"{"type": "circular_notch", "R": 4.0, "t": 1.0, "w": 1.0, "h": 7.0, "blank_length": 14.0}"#,
        e: 72000.0,
        nu: 0.33,
        k_bend: 2337.78,
        k_torsion: 765.096,
        k_axial: 8044.44,
        spm: 6.24575,
    },
    Ref {
        hinge: r#"{"type": "circular_notch", "R": 4.0, "t": 0.5, "w": 4.0, "h": 6.5, "blank_length": 13.0}"#,
        e: 72000.0,
        nu: 0.33,
        k_bend: 1850.78,
        k_torsion: 5383.72,
        k_axial: 24959.6,
        spm: 6.0441,
    },
    Ref {
        hinge: r#"{"type": "circular_notch", "R": 4.0, "t": 1.0, "w": 3.0, "h": 7.0, "blank_length": 14.0}"#,
        e: 72000.0,
        nu: 0.33,
        k_bend: 7172.12,
        k_torsion: 8926.81,
        k_axial: 24178.5,
        spm: 2.06039,
    },
    Ref {
        hinge: r#"{"type": "circular_notch", "R": 4.0, "t": 2.0, "w": 2.0, "h": 8.0, "blank_length": 16.0}"#,
        e: 72000.0,
        nu: 0.33,
        k_bend: 23373.8,
        k_torsion: 7750.59,
        k_axial: 20313.3,
        spm: 0.813046,
    },
    Ref {
        hinge: r#"{"type": "circular_notch", "R": 4.0, "t": 1.0, "w": 8.0, "h": 7.0, "blank_length": 14.0}"#,
        e: 72000.0,
        nu: 0.33,
        k_bend: 20139.3,
        k_torsion: 74577.2,
        k_axial: 65085.4,
        spm: 0.737996,
    },
    Ref {
        hinge: r#"{"type": "circular_notch", "R": 4.0, "t": 2.0, "w": 6.0, "h": 8.0, "blank_length": 16.0}"#,
        e: 72000.0,
        nu: 0.33,
        k_bend: 72326.6,
        k_torsion: 95359.9,
        k_axial: 61221.6,
        spm: 0.257865,
    },
    Ref {
        hinge: r#"{"type": "circular_notch", "R": 4.0, "t": 2.0, "w": 16.0, "h": 8.0, "blank_length": 16.0}"#,
        e: 72000.0,
        nu: 0.33,
        k_bend: 201488.0,
        k_torsion: 705213.0,
        k_axial: 165688.0,
        spm: 0.0940747,
    },
    Ref {
        hinge: r#"{"type": "corner_filleted", "l": 5.0, "R": 1.75, "t": 0.6, "w": 10.0, "h": 15.0, "blank_length": 15.0}"#,
        e: 3300.0,
        nu: 0.33,
        k_bend: 232.582,
        k_torsion: 2307.76,
        k_axial: 3362.34,
        spm: 1.63574,
    },
];

/// Rows computed after the fits and never used in one: the only evidence of accuracy on unseen
/// geometry. Nine models — five circular notches, two necks, one elliptical notch, one leaf —
/// a small set; the figures below are what it shows, no more.
const HELD_OUT: &[Ref] = &[
    Ref {
        hinge: r#"{"type": "circular_notch", "R": 8.0, "t": 2.0, "w": 10.0, "h": 10.0, "blank_length": 0.0}"#,
        e: 72000.0,
        nu: 0.33,
        k_bend: 103794.0,
        k_torsion: 258405.0,
        k_axial: 170052.0,
        spm: 0.151449,
    },
    Ref {
        hinge: r#"{"type": "circular_notch", "R": 6.0, "t": 1.2, "w": 8.0, "h": 9.0, "blank_length": 5.0}"#,
        e: 72000.0,
        nu: 0.33,
        k_bend: 26560.2,
        k_torsion: 79218.4,
        k_axial: 87363.5,
        spm: 0.524126,
    },
    Ref {
        hinge: r#"{"type": "circular_notch", "R": 3.0, "t": 1.2, "w": 5.0, "h": 6.0, "blank_length": 12.0}"#,
        e: 72000.0,
        nu: 0.33,
        k_bend: 20897.3,
        k_torsion: 38993.2,
        k_axial: 47236.0,
        spm: 0.853235,
    },
    Ref {
        hinge: r#"{"type": "circular_notch", "R": 5.0, "t": 2.5, "w": 5.0, "h": 12.0, "blank_length": 10.0}"#,
        e: 72000.0,
        nu: 0.33,
        k_bend: 100435.0,
        k_torsion: 102145.0,
        k_axial: 73412.0,
        spm: 0.204396,
    },
    Ref {
        hinge: r#"{"type": "spherical_neck", "l": 3.0, "t": 2.0, "R": 1.0, "h": 6.0, "blank_length": 10.0}"#,
        e: 72000.0,
        nu: 0.33,
        k_bend: 11944.9,
        k_torsion: 9141.0,
        k_axial: 31555.3,
        spm: 1.35538,
    },
    Ref {
        hinge: r#"{"type": "spherical_neck", "l": 2.0, "t": 2.0, "R": 3.0, "h": 8.0, "blank_length": 10.0}"#,
        e: 72000.0,
        nu: 0.33,
        k_bend: 12357.3,
        k_torsion: 9391.91,
        k_axial: 32695.1,
        spm: 1.31554,
    },
    Ref {
        hinge: r#"{"type": "elliptical_notch", "ax": 6.0, "ay": 3.0, "t": 1.0, "w": 6.0, "h": 6.0, "blank_length": 10.0}"#,
        e: 72000.0,
        nu: 0.33,
        k_bend: 9098.66,
        k_torsion: 17681.9,
        k_axial: 40507.8,
        spm: 1.01575,
    },
    Ref {
        hinge: r#"{"type": "leaf", "l": 10.0, "t": 1.0, "w": 5.0, "h": 8.0, "blank_length": 10.0}"#,
        e: 72000.0,
        nu: 0.33,
        k_bend: 2911.48,
        k_torsion: 4673.46,
        k_axial: 25227.9,
        spm: 1.22173,
    },
    Ref {
        hinge: r#"{"type": "circular_notch", "R": 10.0, "t": 0.8, "w": 12.0, "h": 12.0, "blank_length": 20.0}"#,
        e: 72000.0,
        nu: 0.33,
        k_bend: 11755.0,
        k_torsion: 62215.3,
        k_axial: 67772.4,
        spm: 0.775791,
    },
];

struct Row {
    spec: HingeSpec,
    /// Errors of flexfem against the solid model, %.
    bend: f64,
    torsion: f64,
    axial: f64,
    spm: f64,
}

fn rows(refs: &[Ref]) -> Vec<Row> {
    refs.iter()
        .map(|r| {
            let spec: HingeSpec = serde_json::from_str(r.hinge).unwrap_or_else(|e| panic!("{}: {e}", r.hinge));
            let m = Material {
                e: r.e,
                nu: r.nu,
                ..Material::AL7075
            };
            let h = characterise(&spec, &m)
                .unwrap_or_else(|e| panic!("{}: {e}", r.hinge))
                .hinge;
            let pct = |a: f64, b: f64| 100.0 * (a - b) / b;
            let row = Row {
                spec,
                bend: pct(h.k_bend, r.k_bend),
                torsion: pct(h.k_torsion, r.k_torsion),
                axial: pct(h.k_axial, r.k_axial),
                spm: pct(h.stress_per_moment, r.spm),
            };
            println!(
                "{:<100} nu {:.2}: bend {:+6.2} %  torsion {:+6.2} %  axial {:+6.2} %  stress/moment {:+6.2} %",
                r.hinge, r.nu, row.bend, row.torsion, row.axial, row.spm
            );
            row
        })
        .collect()
}

fn circular(r: &Row) -> bool {
    matches!(r.spec, HingeSpec::CircularNotch { .. })
}

fn neck(r: &Row) -> bool {
    matches!(r.spec, HingeSpec::SphericalNeck { .. })
}

/// Prints the range of each error over `rows` under `label` (the figures the README quotes) and
/// returns the largest |error| per quantity, %: (bending, torsion, axial, stress per moment).
fn report(label: &str, rows: &[&Row]) -> [f64; 4] {
    let range = |f: fn(&Row) -> f64| {
        let v: Vec<f64> = rows.iter().map(|r| f(r)).collect();
        let lo = v.iter().copied().fold(f64::INFINITY, f64::min);
        let hi = v.iter().copied().fold(f64::NEG_INFINITY, f64::max);
        (lo, hi, lo.abs().max(hi.abs()))
    };
    let q = [range(|r| r.bend), range(|r| r.torsion), range(|r| r.axial), range(|r| r.spm)];
    println!(
        "{label} (n = {}): bending {:+.2} … {:+.2} %, torsion {:+.2} … {:+.2} %, axial {:+.2} … {:+.2} %, \
         peak stress per moment {:+.2} … {:+.2} %",
        rows.len(),
        q[0].0,
        q[0].1,
        q[1].0,
        q[1].1,
        q[2].0,
        q[2].1,
        q[3].0,
        q[3].1
    );
    q.map(|(_, _, m)| m)
}

/// Asserts |error| < tolerance per quantity (bending, torsion, axial, stress per moment, %).
fn check(label: &str, worst: [f64; 4], tol: [f64; 4]) {
    // zip-checked: three [_; 4] arrays.
    for ((w, t), q) in worst.iter().zip(tol).zip(["bending", "torsion", "axial", "stress per moment"]) {
        assert!(*w < t, "{label}: {q} off by up to {w:.2} %, tolerance {t} %");
    }
}

// Fit residuals: how closely the calibrated laws reproduce the rows they were fitted on. A
// regression pin, not accuracy: asserted at 1.05–2.5× the measured residual (in the comments)
// so that a change in the hinge model shows.

/// Circular notches used in the fits (36 of 41), t/R 0.06–0.5, w/t 0.5–20, ν = 0 and 0.33.
/// Torsion for t/R ≥ 0.1 only (below, the warping restraint of a very thin waist is beyond the
/// beam model). Measured: bending −0.71 … +1.86 %, torsion −11.44 … +4.21 %, axial
/// +0.90 … +3.78 %, peak stress per moment −1.72 … +5.28 %.
const CIRCULAR_FIT_TOL: [f64; 4] = [2.5, 12.0, 4.0, 6.0];
/// The five turned necks used to fit the neck's K_t = 1 + 0.041√(t/R). Measured: bending
/// −1.77 … +0.79 %, torsion −4.11 … −0.06 %, axial −2.73 … +0.29 %, stress −0.82 … +0.04 %.
const NECK_FIT_TOL: [f64; 4] = [3.0, 5.0, 3.0, 2.0];

// Held out: computed after the fits, never used in one. Few rows (5 + 2 + 2): what they show
// is agreement on those geometries, not a statistical accuracy.

/// The five held-out circular notches (R3–R10, t/R 0.13–0.5, one without blanks). Measured:
/// bending −0.38 … +0.71 %, torsion −10.42 … −2.30 %, axial +0.85 … +3.41 %, stress
/// −1.67 … +3.38 %.
const CIRCULAR_HELD_OUT_TOL: [f64; 4] = [2.0, 12.0, 4.0, 6.0];
/// The two held-out necks (l/t 1 and 1.5, t/R 2 and 0.67). Measured: bending −2.00 … +1.06 %,
/// torsion −4.01 … −0.11 %, axial −2.28 … −0.16 %, stress −0.61 … +0.02 %.
const NECK_HELD_OUT_TOL: [f64; 4] = [3.0, 5.0, 3.0, 2.0];

#[test]
fn circular_notches_fit_residual() {
    let all = rows(FITTED);
    let rows: Vec<&Row> = all.iter().filter(|r| circular(r)).collect();
    assert_eq!(rows.len(), 36);
    let worst = report("circular notches, fit residual", &rows);
    let thick: Vec<&Row> = rows
        .iter()
        .copied()
        .filter(|r| matches!(r.spec, HingeSpec::CircularNotch { r: rad, t, .. } if t / rad >= 0.1))
        .collect();
    let torsion = report("circular notches t/R ≥ 0.1, fit residual", &thick)[1];
    check("fitted circular notches", [worst[0], torsion, worst[2], worst[3]], CIRCULAR_FIT_TOL);
}

#[test]
fn circular_notches_held_out() {
    let all = rows(HELD_OUT);
    let rows: Vec<&Row> = all.iter().filter(|r| circular(r)).collect();
    assert_eq!(rows.len(), 5);
    let worst = report("circular notches, HELD OUT", &rows);
    check("held-out circular notches", worst, CIRCULAR_HELD_OUT_TOL);
}

#[test]
fn turned_necks_fit_residual() {
    let all = rows(FITTED);
    let rows: Vec<&Row> = all.iter().filter(|r| neck(r)).collect();
    assert_eq!(rows.len(), 5);
    for r in &rows {
        let HingeSpec::SphericalNeck { l, t, .. } = r.spec else { unreachable!() };
        assert!(l / t >= 1.0, "{:?}", r.spec);
    }
    let worst = report("turned necks, fit residual", &rows);
    check("fitted necks", worst, NECK_FIT_TOL);
}

#[test]
fn turned_necks_held_out() {
    let all = rows(HELD_OUT);
    let rows: Vec<&Row> = all.iter().filter(|r| neck(r)).collect();
    assert_eq!(rows.len(), 2);
    let worst = report("turned necks, HELD OUT", &rows);
    check("held-out necks", worst, NECK_HELD_OUT_TOL);
}

/// Other families, one row each: the elliptical notch and the leaf (held out), the 8R pan-tilt
/// corner-filleted hinge (used to fit the torsion load spreading; its bending is also checked
/// against 4.05 N·mm/° in tests/hinge_seeds.rs). The leaf's sharp re-entrant corners are beyond
/// beam theory; the solid's peak stress there is singular and not compared. Measured (bending,
/// torsion, axial): elliptical −0.67, −7.40, +2.44 %; corner-filleted +2.04, −13.89, −6.13 %;
/// leaf −4.67, −12.66, −4.29 %.
#[test]
fn other_families_match_solid_models() {
    let fitted = rows(FITTED);
    let held_out = rows(HELD_OUT);
    let mut n = 0;
    for r in fitted.iter().chain(&held_out) {
        // (bending, torsion, axial) tolerances, %.
        let tol = match r.spec {
            HingeSpec::EllipticalNotch { .. } => [1.0, 15.0, 4.0],
            HingeSpec::CornerFilleted { .. } => [2.5, 15.0, 8.0],
            HingeSpec::Leaf { .. } => [5.0, 15.0, 6.0],
            _ => continue,
        };
        n += 1;
        assert!(r.bend.abs() < tol[0], "{:?}: bending {:+.2} %", r.spec, r.bend);
        assert!(r.torsion.abs() < tol[1], "{:?}: torsion {:+.2} %", r.spec, r.torsion);
        assert!(r.axial.abs() < tol[2], "{:?}: axial {:+.2} %", r.spec, r.axial);
    }
    assert_eq!(n, 3);
}

/// Provenance: every reference above is one line of the solid tool's raw output
/// (`tools/solid_reference_results.jsonl`: same geometry and ν, the four quantities to the 6
/// digits copied here). The Ruiz et al. R8/t2 notch (k_bend 95922.3 N·mm/rad) was missing from
/// that file; it was recomputed with the tool (n = 5; scipy's sparse LU in place of CHOLMOD)
/// and gave the same digits.
#[test]
fn every_reference_is_a_line_of_the_raw_results() {
    let text = std::fs::read_to_string(concat!(env!("CARGO_MANIFEST_DIR"), "/tools/solid_reference_results.jsonl")).unwrap();
    let lines: Vec<serde_json::Value> = text.lines().map(|l| serde_json::from_str(l).unwrap()).collect();
    assert_eq!(lines.len(), 52);
    let close = |a: &serde_json::Value, b: f64| a.as_f64().is_some_and(|a| (a / b - 1.0).abs() < 1e-5);
    for r in FITTED.iter().chain(HELD_OUT) {
        let spec: serde_json::Value = serde_json::from_str(r.hinge).unwrap();
        let matches = lines
            .iter()
            .filter(|l| spec.as_object().unwrap().iter().all(|(k, v)| l[k] == *v) && l["nu"] == r.nu)
            .filter(|l| {
                close(&l["k_bend"], r.k_bend)
                    && close(&l["k_torsion"], r.k_torsion)
                    && close(&l["k_axial"], r.k_axial)
                    && close(&l["stress_per_moment"], r.spm)
                    && l["E"] == r.e
            })
            .count();
        assert_eq!(matches, 1, "{} (ν = {}): {matches} matching lines", r.hinge, r.nu);
    }
}
