//! Hinge models against converged solid finite-element models of the same geometry.
//!
//! The accuracy bands refer to converged quadratic-tetrahedron (C3D10) solid models.
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
//! 25 models computed after the fits and never used in one (12 circular notches, 6 necks, 3
//! elliptical notches, 2 corner-filleted hinges, 2 leaves; 16 of them computed for this split).
//! That is enough to show the laws carry over to other geometries, not a statistical accuracy.

use flexfem::hinge::{characterise, HingeSpec};
use flexfem::material::Material;

#[path = "hinge_solid_reference/references.rs"]
mod references;
use references::{Ref, FITTED, HELD_OUT};
#[path = "common/raw_results.rs"]
mod raw_results;
use raw_results::{json_lines, matching_lines};

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
    let q = [
        range(|r| r.bend),
        range(|r| r.torsion),
        range(|r| r.axial),
        range(|r| r.spm),
    ];
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

/// Asserts |error| < tolerance per quantity (bending, torsion, axial, stress per moment, %; the
/// first `tol.len()` of them).
fn check(label: &str, worst: &[f64], tol: &[f64]) {
    assert_eq!(worst.len(), tol.len());
    for ((w, t), q) in worst
        .iter()
        .zip(tol)
        .zip(["bending", "torsion", "axial", "stress per moment"])
    {
        assert!(w < t, "{label}: {q} off by up to {w:.2} %, tolerance {t} %");
    }
}

// Fit residuals: how closely the calibrated laws reproduce the rows they were fitted on. A
// regression pin, not accuracy: asserted at 1.05–2.5× the measured residual (in the comments)
// so that a change in the hinge model shows.

/// Circular notches used in the fits (36 of 41), t/R 0.06–0.5, w/t 0.5–20, ν = 0 and 0.33.
/// Torsion for t/R ≥ 0.1 only (below, the warping restraint of a very thin waist is beyond the
/// beam model). Measured: bending −0.71 … +1.86 %, torsion −8.56 … +2.72 % (−8.72 … +2.59 % with the torsion law's slopes 1.3 and 0.84; −8.72 … +8.98 % while compact waists carried warping restraint, the narrow w = 1 rows high; −8.76 … +8.99 % with the warping constant spread at 0.57 everywhere, −8.69 … +8.92 % at the bending's 1/2, −8.20 … +9.32 % before it took its own spreading; −11.44 … +4.21 %
/// before the plate-mode warping and torsional spreading of `hinge::torsion::solid_torsion_stiffness`,
/// whose first fit used these rows too; −2.85 … +9.54 % with it, before Benscoter's warping shear), axial +0.13 … +4.35 % (+0.08 … +4.18 % before the axial load's spreading into the blank at 0.56, `hinge::profile::AXIAL_BLANK_SLOPE`; +0.90 … +3.78 % before the axial modulus took G and
/// 0.6 of P; +4.08 % before the blank's plane-strain restraint: +4.35 % on R8/t0.5/w10, the largest (+4.18 % before the axial load's spreading into the blank), t/R 0.06, below the CalculiX-calibrated range), peak stress
/// per moment −1.72 … +5.28 %.
const CIRCULAR_FIT_TOL: [f64; 4] = [2.5, 9.0, 4.6, 6.0];
/// The five turned necks used to fit the neck's K_t = 1 + 0.041√(t/R). Measured: bending
/// −1.77 … +0.79 %, torsion −4.11 … −0.06 %, axial −0.99 … +0.83 % (−2.73 … +0.29 % before the axial load's spreading into the blank at 0.56), stress −0.82 … +0.04 %.
const NECK_FIT_TOL: [f64; 4] = [3.0, 5.0, 1.5, 2.0];

// Held out: computed after the fits, never used in one. 25 rows in all, tolerances about
// 1.2–2.5× the measured worst case: what they show is agreement on these geometries, with a
// sample too small for a statistical accuracy.

/// The 12 held-out circular notches: R 2.5–10, t/R 0.08–0.5, w/t 1.2–15, one with ν = 0, one
/// without blanks. Measured: bending −0.38 … +1.18 %, torsion −9.16 … −0.46 % (−9.22 … −0.56 % with the torsion law's slopes 1.3 and 0.84; +3.68 % while compact waists carried warping restraint, +3.62 % with the warping spread at 1/2, +3.87 % before the warping spreading change; −10.84 …
/// +0.73 % before the torsion corrections, −2.93 … +11.78 % before the warping shear), axial
/// −1.49 … +4.12 % (−1.49 … +3.95 % before the axial load's spreading into the blank at 0.56; +0.85 … +5.06 % before the axial modulus took G and 0.6 of P), stress
/// −1.67 … +3.38 %.
const CIRCULAR_HELD_OUT_TOL: [f64; 4] = [3.0, 9.5, 6.0, 5.0];
/// The 6 held-out necks: l/t 1–2.7, t/R 0.67–2. Measured: bending −2.00 … +1.06 %, torsion
/// −4.01 … −0.11 %, axial −0.79 … +0.65 % (−2.28 … −0.16 % before the axial load's spreading into the blank at 0.56), stress −1.31 … +0.26 %.
const NECK_HELD_OUT_TOL: [f64; 4] = [3.0, 5.0, 1.5, 3.0];

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
    check(
        "fitted circular notches",
        &[worst[0], torsion, worst[2], worst[3]],
        &CIRCULAR_FIT_TOL,
    );
}

#[test]
fn circular_notches_held_out() {
    let all = rows(HELD_OUT);
    let rows: Vec<&Row> = all.iter().filter(|r| circular(r)).collect();
    assert_eq!(rows.len(), 12);
    let worst = report("circular notches, HELD OUT", &rows);
    check("held-out circular notches", &worst, &CIRCULAR_HELD_OUT_TOL);
}

#[test]
fn turned_necks_fit_residual() {
    let all = rows(FITTED);
    let rows: Vec<&Row> = all.iter().filter(|r| neck(r)).collect();
    assert_eq!(rows.len(), 5);
    for r in &rows {
        let HingeSpec::SphericalNeck { l, t, .. } = r.spec else {
            unreachable!()
        };
        assert!(l / t >= 1.0, "{:?}", r.spec);
    }
    let worst = report("turned necks, fit residual", &rows);
    check("fitted necks", &worst, &NECK_FIT_TOL);
}

#[test]
fn turned_necks_held_out() {
    let all = rows(HELD_OUT);
    let rows: Vec<&Row> = all.iter().filter(|r| neck(r)).collect();
    assert_eq!(rows.len(), 6);
    let worst = report("turned necks, HELD OUT", &rows);
    check("held-out necks", &worst, &NECK_HELD_OUT_TOL);
}

/// The 8R pan-tilt corner-filleted hinge, used to fit the torsion load spreading (its bending is
/// also checked against 4.05 N·mm/° in tests/hinge_seeds.rs). Measured: bending −0.45 % (−0.59 % before the blank's plane-strain restraint, +2.04 %
/// before the corner fillets got the short-notch factor G), torsion
/// +3.32 % (+1.26 % with the torsion law's slopes 1.3 and 0.84, +0.69 % with the warping constant spread at 0.57 everywhere, −0.61 % at 1/2, +4.40 % before it took its own spreading, −13.89 % before the torsion corrections, −1.58 % before the warping shear), axial −1.57 % (−3.89 % before the axial load's spreading into the blank at 0.56, −4.86 % before the blank's plane-strain restraint, −6.13 % before the axial modulus took G and 0.6 of P), stress −1.50 % with the corner fillet's
/// peak law (+1.36 % with the K_t exponent 0.27, +0.24 % with 1/5, +4.28 % before it; the peak law
/// was fitted on converged CalculiX peaks: these scikit-fem peaks, on meshes sized by the
/// thickness, read fillets low as the n = 4 CalculiX ones do, tests/hinge_ccx_reference.rs).
/// Pinned at 2.5 / 6 / 2 / 6 % (axial measured −1.57 %).
const CORNER_FIT_TOL: [f64; 4] = [2.5, 6.0, 2.0, 6.0];

#[test]
fn corner_filleted_fit_residual() {
    let all = rows(FITTED);
    let rows: Vec<&Row> = all
        .iter()
        .filter(|r| matches!(r.spec, HingeSpec::CornerFilleted { .. }))
        .collect();
    assert_eq!(rows.len(), 1);
    let worst = report("pan-tilt corner-filleted hinge, fit residual", &rows);
    check("fitted corner-filleted hinge", &worst, &CORNER_FIT_TOL);
}

/// Held-out elliptical notches (3), corner-filleted hinges (2) and leaves (2), tolerances per
/// family (bending, torsion, axial, stress per moment, %). Measured: elliptical −0.67 … +0.26,
/// −4.48 … −2.47 (−4.49 … −2.49 with the torsion law's slopes 1.3 and 0.84), +0.90 … +2.13 (+0.80 … +2.05 before the axial load's spreading into the blank at 0.56, +2.44 … +2.63 before the axial modulus took G and 0.6 of P),
/// −1.58 … +0.78 %; corner-filleted −1.79 … −1.08 (−1.94 … −1.19 before the blank's plane-strain restraint, +0.19 … +1.81
/// before the fillets got the short-notch factor G), −3.13 …
/// −1.33 (−4.25 … −2.94 with the torsion law's slopes 1.3 and 0.84; −4.01 … −2.61 with the warping constant spread at 0.57 everywhere), +1.02 … +1.40 (−0.49 … +0.27 before the axial load's spreading into the blank at 0.56, −0.72 … +0.07 before the blank's plane-strain restraint, −0.44 … +0.77 before the axial change), +3.52 … +6.24 % with the peak law (+4.56 … +6.67 % with the exponent 0.27, +2.25 … +3.69 % with the K_t exponent 1/5; the
/// refitted 0.27 matches converged peaks, which meshes sized by the thickness read low; before
/// the torsion corrections and the corner K_t exponent 1/5: torsion −18.23 … −15.95, stress +10.72 … +14.75 %); leaf −5.61 … −4.53 (−5.92 … −4.67 before the blank's plane-strain restraint),
/// −0.94 … −0.68 (−3.34 … −2.13 with the torsion law's slopes 1.3 and 0.84; −4.15 … −3.04 with the warping spread at 0.57 everywhere, −4.52 … −3.40 at 1/2; −2.89 … −1.40 before the warping constant took its own load spreading;
/// before the torsion corrections −19.92 … −12.66, before the warping shear −13.71 … −8.45),
/// −1.70 … −0.81 % (−3.40 … −2.71 % before the axial load's spreading into the blank at 0.56, −3.55 … −3.01 % before the blank's plane-strain restraint, −4.29 … −3.91 % before the axial change). These scikit-fem references are single meshes (n = 5), which the CalculiX
/// refinement (tests/hinge_ccx_reference.rs) shows to be up to a few per cent stiff in torsion,
/// so flexfem's leaves read softer here than they are. Torsion tolerances tightened with the
/// warping shear. The leaf's sharp re-entrant corners are beyond beam
/// theory: the solid's peak stress there is singular and not compared.
const ELLIPTICAL_HELD_OUT_TOL: [f64; 4] = [1.0, 10.0, 4.0, 2.0];
const CORNER_HELD_OUT_TOL: [f64; 4] = [3.0, 7.0, 2.0, 20.0];
const LEAF_HELD_OUT_TOL: [f64; 3] = [8.0, 3.5, 2.5];

#[test]
fn other_families_held_out() {
    let all = rows(HELD_OUT);
    let pick = |f: fn(&Row) -> bool| all.iter().filter(|r| f(r)).collect::<Vec<&Row>>();
    let elliptical = pick(|r| matches!(r.spec, HingeSpec::EllipticalNotch { .. }));
    let corner = pick(|r| matches!(r.spec, HingeSpec::CornerFilleted { .. }));
    let leaf = pick(|r| matches!(r.spec, HingeSpec::Leaf { .. }));
    assert_eq!((elliptical.len(), corner.len(), leaf.len()), (3, 2, 2));
    check(
        "held-out elliptical notches",
        &report("elliptical notches, HELD OUT", &elliptical),
        &ELLIPTICAL_HELD_OUT_TOL,
    );
    check(
        "held-out corner-filleted hinges",
        &report("corner-filleted hinges, HELD OUT", &corner),
        &CORNER_HELD_OUT_TOL,
    );
    let w = report("leaves, HELD OUT (stress not compared)", &leaf);
    check("held-out leaves", &w[..3], &LEAF_HELD_OUT_TOL);
}
/// Provenance: every reference above is one line of the solid tool's raw output
/// (`tools/solid_reference_results.jsonl`: same geometry and ν, the four quantities to the 6
/// digits copied here). The Ruiz et al. R8/t2 notch (k_bend 95922.3 N·mm/rad) was missing from
/// that file; it was recomputed with the tool (n = 5; scipy's sparse LU in place of CHOLMOD)
/// and gave the same digits.
#[test]
fn every_reference_is_a_line_of_the_raw_results() {
    let lines = json_lines("solid_reference_results.jsonl");
    assert_eq!(lines.len(), 68);
    for r in FITTED.iter().chain(HELD_OUT) {
        let values = [
            ("k_bend", r.k_bend),
            ("k_torsion", r.k_torsion),
            ("k_axial", r.k_axial),
            ("stress_per_moment", r.spm),
        ];
        let matches = matching_lines(&lines, r.hinge, r.e, r.nu, &values, |_| true).len();
        assert_eq!(matches, 1, "{} (ν = {}): {matches} matching lines", r.hinge, r.nu);
    }
}
