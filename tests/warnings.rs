//! Every result carries a top-level `warnings` list; hinges outside the range their solid
//! calibration covers are warned about in the result and the report.
//!
//! Calibration ranges (tests/hinge_solid_reference.rs and tests/hinge_ccx_reference.rs,
//! converged quadratic-tetrahedron solid models): circular notches t/R 0.06–0.5, w/t 0.5–20;
//! turned necks l/t 1–5, t/R 0.67–2; corner-filleted hinges l/t 2–10, R/t 0.5–2.5, w/t 1–20,
//! h/t 2.6–10. A mechanism's hinge elements are checked as the `hinge` analysis's hinges are.

mod common;

use common::{root, run, run_case_text, tempdir};
use flexfem::analysis;

/// Runs the bundled `cases/FILE` (in-process) after `edit` changes its JSON.
fn run_bundled_with(file: &str, edit: impl FnOnce(&mut serde_json::Value)) -> analysis::Outcome {
    let base = std::fs::read_to_string(root().join("cases").join(file)).unwrap();
    let mut c: serde_json::Value = serde_json::from_str(&base).unwrap();
    edit(&mut c);
    analysis::run(&analysis::parse(&c.to_string()).unwrap()).unwrap()
}

/// `out` has a warning starting with `prefix`, and its JSON lists every warning.
fn assert_warns(out: &analysis::Outcome, prefix: &str) {
    let w = &out.warnings;
    assert!(w.iter().any(|s| s.starts_with(prefix)), "{w:?}");
    assert_eq!(out.json["warnings"].as_array().unwrap().len(), w.len());
}

fn json(o: &std::process::Output) -> serde_json::Value {
    assert_eq!(
        o.status.code(),
        Some(0),
        "stderr: {}",
        String::from_utf8_lossy(&o.stderr)
    );
    serde_json::from_slice(&o.stdout).unwrap()
}

fn warnings(v: &serde_json::Value) -> Vec<String> {
    v["warnings"]
        .as_array()
        .expect("top-level `warnings` array")
        .iter()
        .map(|w| w.as_str().expect("warnings are strings").to_string())
        .collect()
}

/// Bundled cases whose warnings are true statements about them, with one phrase each warning
/// must contain (in order): stresses above the allowable of two mechanisms driven to their
/// stroke and of the stage's 60 N case (utilisation 1.34 linear, 1.38 nonlinear), and two deliberate stand-ins (a pendulum bar of 1e-4 steel's density so its tip
/// mass dominates, a 1e5× stiff platform standing in for a rigid one), and the pan-tilt hinge of
/// Yu, Lu and Hao, whose blank (h/t 25) is taller than any CalculiX design's (the sixteenth
/// design's leaves at h/t 10.3–13.7 read torsion −10.7 … +19.7 %; our scikit-fem model of this
/// very hinge reads it within 3.3 %) and whose fillets (R/t 2.92) are blunter than any
/// design's (0.5–2.5): in the `hinge` analysis and as the eight hinge elements of the 8R
/// mechanism.
const KNOWN: [(&str, &[&str]); 10] = [
    (
        "pantilt_hinge_corner_filleted.json",
        &["corner_filleted h/t = 25 is outside the solid-calibrated range 2.6–10", "corner_filleted R/t = 2.9167 is outside the solid-calibrated range 0.5–2.5"],
    ),
    (
        "pantilt_hinge_damping.json",
        &["corner_filleted h/t = 25 is outside the solid-calibrated range 2.6–10", "corner_filleted R/t = 2.9167 is outside the solid-calibrated range 0.5–2.5"],
    ),
    (
        "leaf_guide_track.json",
        &[
            "(\"stroke_plus\"): element 0 (beam) is above its allowable",
            "(\"stroke_minus\"): element 10 (beam) is above its allowable",
        ],
    ),
    (
        "pantilt_8r.json",
        &[
            "element 4 (hinge) is above its allowable stress",
            "mesh: in mesh file \"../meshes/pantilt_8r.json\" at `elements[0].hinge` (likewise elements 1–7): corner_filleted h/t = 25",
            "mesh: in mesh file \"../meshes/pantilt_8r.json\" at `elements[0].hinge` (likewise elements 1–7): corner_filleted R/t = 2.9167",
        ],
    ),
    // The same eight hinges in free vibration.
    (
        "pantilt_8r_modal.json",
        &[
            "mesh: in mesh file \"../meshes/pantilt_8r.json\" at `elements[0].hinge` (likewise elements 1–7): corner_filleted h/t = 25",
            "mesh: in mesh file \"../meshes/pantilt_8r.json\" at `elements[0].hinge` (likewise elements 1–7): corner_filleted R/t = 2.9167",
        ],
    ),
    // Equal actuator forces load the three legs alike: the leg named is the one whose stress is
    // largest by rounding (it moved with the torsion recalibration of the hinges).
    (
        "ruiz2019_stage.json",
        &["load_cases[2] (\"F60\"): the revolute hinges of legs 1, 2 and 3 are above the allowable stress"],
    ),
    (
        "ruiz2019_stage_nonlinear.json",
        // F60 pushes all three legs alike: their revolute stresses agree to 1e-13 relative
        // (551.43 MPa), and the warning names every hinge within 1e-9 of the peak.
        &["load_cases[2] (\"F60\"): the revolute hinges of legs 1, 2 and 3 are above the allowable stress"],
    ),
    (
        "pendulum_nonlinear_transient.json",
        &["materials.light_steel.density = 7.85e-13"],
    ),
    (
        "prs_stiffness_han_fsw_frame.json",
        &["materials.platform.E = 2.1e10 MPa"],
    ),
    // A 10×10 plate: modes 2–6 have 3–4.5 elements per bending half-wave (mode 4, the diagonal
    // (2,2) wave, reads −5.6 % against Navier; tests/shell_coarse_mesh.rs).
    (
        "modal_plate_shell.json",
        &["coarse shell mesh: the shells that carry these modes' strain energy have few elements per bending half-wave, and the four-node shell's frequencies can read low by about the figures given (mode 2: 4.5 elements per half-wave, about 3.4 %"],
    ),
];

/// Every bundled case that `run` accepts has `warnings`: empty (the bundled hinges are inside
/// their calibration, bar the pan-tilt hinge) but for the [`KNOWN`] ones.
#[test]
fn every_bundled_result_has_an_empty_warnings_list() {
    let mut n = 0;
    for entry in std::fs::read_dir(root().join("cases")).unwrap() {
        let p = entry.unwrap().path();
        let c = analysis::load(&p).unwrap();
        if matches!(c, analysis::Case::Sweep(_)) {
            continue;
        }
        let out = analysis::run(&c).unwrap_or_else(|e| panic!("{}: {e}", p.display()));
        // The snap-through case exists to lose stability (at its upper limit point): its one
        // warning says so.
        if p.ends_with("shallow_arch_arc_length.json") {
            let w = warnings(&out.json);
            assert!(w.len() == 1 && w[0].contains("lost stability"), "{w:?}");
            n += 1;
            continue;
        }
        if let Some((_, phrases)) = KNOWN.iter().find(|(f, _)| p.ends_with(f)) {
            let w = warnings(&out.json);
            assert_eq!(w.len(), phrases.len(), "{}: {w:?}", p.display());
            for (w, phrase) in w.iter().zip(phrases.iter()) {
                assert!(w.contains(phrase), "{}: {w}", p.display());
            }
            n += 1;
            continue;
        }
        assert_eq!(
            out.json["warnings"],
            serde_json::json!([]),
            "{}: {:?}",
            p.display(),
            out.warnings
        );
        assert!(!out.report.markdown.contains("## Warnings"));
        n += 1;
    }
    assert!(n >= 10, "{n} cases");
}

/// A circular notch with t/R = 0.025 (below 0.06) and one with t/R = 1.25 are warned about,
/// naming the ratio and the range; the warning is in the Markdown report too.
#[test]
fn circular_notch_outside_calibration_warns() {
    for (r, t, w, ratio) in [(8.0, 0.2, 4.0, "t/R = 0.025"), (8.0, 9.99, 10.0, "t/R = 1.2488")] {
        let text = format!(
            r#"{{"analysis": "hinge", "hinge": {{"type": "circular_notch", "R": {r}, "t": {t}, "w": {w}, "h": 10.5, "blank_length": 20}}}}"#
        );
        let v = json(&run_case_text("warn_circ", &text));
        let w = warnings(&v);
        assert_eq!(w.len(), 1, "{w:?}");
        assert!(w[0].starts_with("hinge: circular_notch"), "{w:?}");
        assert!(w[0].contains(ratio) && w[0].contains("0.06–0.5"), "{w:?}");
        let d = tempdir("warn_md");
        std::fs::write(d.join("case.json"), &text).unwrap();
        let o = common::run_in(&d, &["run", "case.json", "--format", "md"]);
        let md = String::from_utf8_lossy(&o.stdout);
        assert!(md.contains("## Warnings") && md.contains(ratio), "{md}");
    }
}

/// The checked regimes of `flexfem::hinge::calibration::known_bias` warn only with a band that
/// leaves its target. The short wide corner-filleted leaf warned until the axial load's
/// spreading into the blank (its axial band was −7.48 … +1.36 % over 93 CalculiX models, now
/// −3.98 … +2.24 %): the seventh design's worst such leaf (l3.15/R0.7/t1.35/w22.75: l/t 2.33, w/l
/// 7.2) now runs without a warning, as do a leaf just outside the regime (l/t 2.8) and a narrow
/// circular notch (R11.15/t3.25/w2.6: w/t 0.8, a regime that warned until compact waists
/// stopped carrying warping restraint); exit 0.
#[test]
fn known_bias_regimes_warn_only_beyond_the_targets() {
    use flexfem::hinge::calibration::SHORT_WIDE_LEAF;
    let leaf = |l: f64| {
        format!(
            r#"{{"type": "corner_filleted", "l": {l}, "R": 0.7, "t": 1.35, "w": 22.75, "h": 7.5, "blank_length": 5.8}}"#
        )
    };
    let notch = |w: f64| {
        format!(r#"{{"type": "circular_notch", "R": 11.15, "t": 3.25, "w": {w}, "h": 24.7, "blank_length": 18.5}}"#)
    };
    // No band of the regime leaves its target (asserted against its CalculiX models by
    // tests/hinge_ccx_reference.rs).
    assert_eq!(SHORT_WIDE_LEAF.bands, [None, None, None]);
    let profile = |h: &str| {
        serde_json::from_str::<flexfem::hinge::HingeSpec>(h)
            .unwrap()
            .profile()
            .unwrap()
    };
    assert_eq!(
        flexfem::hinge::calibration::known_bias(&profile(&leaf(3.15))).map(|b| b.regime),
        Some(SHORT_WIDE_LEAF.regime)
    );
    for hinge in [leaf(3.15), leaf(3.78), notch(2.6)] {
        let v = json(&run_case_text(
            "warn_bias",
            &format!(r#"{{"analysis": "hinge", "hinge": {hinge}}}"#),
        ));
        let w = warnings(&v);
        assert!(w.is_empty(), "{hinge}: {w:?}");
    }
}

/// The rigid end faces' reach into the blank for the torque (`flexfem::hinge::torsion::
/// TORSION_FACE_SLOPE`) was fitted on CalculiX designs: it acts on their corner-filleted leaves,
/// up to +17.1 %, inside a box (blank length ≥ 0.5 h, h/t ≤ 10, ...), and on none of their
/// circular notches (`flexfem::hinge::calibration::end_face_extrapolation`). A `hinge` analysis
/// beyond that warns that its torsion is extrapolated, quoting how much the term stiffens it; the
/// number quoted is the `hinge` analysis's torsion over that of the same region as a mechanism's
/// hinge element (continuous ends, no face term), to its one decimal. Warned: a leaf of the
/// thirteenth design's kind (l2.2/R0.85/t1.1/w12.15/h9.9) in a blank 0.3 h long (+26.6 %, naming
/// blank_length/h); a circular notch R2/t1/w20/h22/b11, inside the circular notches' ranges
/// (+22.9 %, a review's example); a corner-filleted hinge inside the box whose term exceeds
/// 17.1 % (l2/R0.5/t1/w5/h10/b5, +29.6 %, a review's example); a leaf with no CalculiX design (the
/// `leaf` family). Not warned: the first leaf in a blank 0.6 h long, and the fifteenth design's
/// l4.7/R1.0/t1.95/w17.9/h17.05/b9.45, the largest term on a CalculiX design.
#[test]
fn end_face_torsion_warns_where_it_is_extrapolated() {
    use flexfem::hinge::{hinge_element, HingeSpec};
    use flexfem::material::Material;
    let corner = |b: f64| {
        format!(
            r#"{{"type": "corner_filleted", "l": 2.2, "R": 0.85, "t": 1.1, "w": 12.15, "h": 9.9, "blank_length": {b}}}"#
        )
    };
    let face = |w: &[String]| w.iter().find(|s| s.contains("rigid blank end faces")).cloned();
    let run_hinge = |hinge: &str| {
        json(&run_case_text(
            "warn_face",
            &format!(r#"{{"analysis": "hinge", "material": "al7075", "hinge": {hinge}}}"#),
        ))
    };
    // The warning's quoted gain against the hinge analysis's torsion over the element's.
    let check_quoted = |hinge: &str, v: &serde_json::Value, w: &str| -> f64 {
        let quoted: f64 = w
            .split("stiffens the torsion by ")
            .nth(1)
            .unwrap()
            .split(' ')
            .next()
            .unwrap()
            .parse()
            .unwrap();
        let spec: HingeSpec = serde_json::from_str(hinge).unwrap();
        let p = spec.profile().unwrap();
        let element = hinge_element(&spec, &Material::AL7075, 2.0 * p.half_length()).unwrap();
        let gain = 100.0 * (v["k_torsion"].as_f64().unwrap() * element.compliance()[3][3] - 1.0);
        assert!((quoted - gain).abs() <= 0.051, "quoted {quoted} %, measured {gain} %");
        gain
    };
    let warned = [
        (corner(2.97), "here blank_length/h = 0.3 is below 0.5", 26.0),
        (
            r#"{"type": "circular_notch", "R": 2, "t": 1, "w": 20, "h": 22, "blank_length": 11}"#.to_string(),
            "is nil on every circular one",
            20.0,
        ),
        (
            r#"{"type": "corner_filleted", "l": 2, "R": 0.5, "t": 1, "w": 5, "h": 10, "blank_length": 5}"#.to_string(),
            "on the CalculiX designs it stiffens the torsion by at most 17.11 %",
            25.0,
        ),
        (
            r#"{"type": "leaf", "l": 2.2, "t": 1.1, "w": 12.15, "h": 9.9, "blank_length": 5.94}"#.to_string(),
            "the leaf family has no CalculiX design",
            1.0,
        ),
    ];
    for (hinge, why, at_least) in &warned {
        let v = run_hinge(hinge);
        let w = face(&warnings(&v)).unwrap_or_else(|| panic!("{hinge}: no end-face warning"));
        assert!(w.starts_with("hinge: the rigid blank end faces' "), "{w}");
        assert!(w.contains(why) && w.ends_with(": torsion extrapolated"), "{w}");
        let gain = check_quoted(hinge, &v, &w);
        assert!(gain > *at_least, "{hinge}: {gain}");
    }
    let doe15 =
        r#"{"type": "corner_filleted", "l": 4.7, "R": 1.0, "t": 1.95, "w": 17.9, "h": 17.05, "blank_length": 9.45}"#;
    for hinge in [corner(5.94), doe15.to_string()] {
        assert_eq!(face(&warnings(&run_hinge(&hinge))), None, "{hinge}");
    }
}

/// Beyond the CalculiX designs that meet the targets the sixteenth design's leaves miss them
/// (tests/hinge_ccx_reference.rs): its leaf in a blank 13.4 t tall (l4.05/R1.45/t1.9/w30.2/
/// h25.4/b23.95, torsion −10.74 %) warns that corner-filleted h/t is outside 2.6–10, and its
/// leaf in a blank 0.32 h long (l2.5/R0.9/t1.25/w23.9/h10.35/b3.35, axial −5.82 %) that
/// blank_length/h is below 0.5; the fifteenth design's leaf l2.2/R0.8/t1.1/w14.55/h7.95/b5.8
/// (h/t 7.2, 0.73 h) gets no range warning.
#[test]
fn tall_or_short_blanks_warn_that_they_are_extrapolated() {
    let run_hinge = |hinge: &str| {
        warnings(&json(&run_case_text(
            "warn_range",
            &format!(r#"{{"analysis": "hinge", "material": "al7075", "hinge": {hinge}}}"#),
        )))
    };
    let tall = run_hinge(
        r#"{"type": "corner_filleted", "l": 4.05, "R": 1.45, "t": 1.9, "w": 30.2, "h": 25.4, "blank_length": 23.95}"#,
    );
    assert!(
        tall.iter().any(|w| w.starts_with("hinge: corner_filleted h/t = 13.3684 is outside the solid-calibrated range 2.6–10")),
        "{tall:?}"
    );
    let short = run_hinge(
        r#"{"type": "corner_filleted", "l": 2.5, "R": 0.9, "t": 1.25, "w": 23.9, "h": 10.35, "blank_length": 3.35}"#,
    );
    assert!(
        short
            .iter()
            .any(|w| w.starts_with("hinge: blank_length/h = 0.3237 is below 0.5, the CalculiX designs'")),
        "{short:?}"
    );
    let inside = run_hinge(
        r#"{"type": "corner_filleted", "l": 2.2, "R": 0.8, "t": 1.1, "w": 14.55, "h": 7.95, "blank_length": 5.8}"#,
    );
    assert!(inside.is_empty(), "{inside:?}");
}

/// Inside the range (Ruiz et al. notch R8/t2, t/R = 0.25, w/t = 5): no warning.
#[test]
fn calibrated_hinge_has_no_warning() {
    let v = json(&run(&["run", "cases/ruiz2019_hinge_revolute.json"]));
    assert!(warnings(&v).is_empty());
}

/// A turned neck with l/t = 8 (above 5) warns; so do a wide leaf (w/t = 40 > 20) and a narrow
/// corner-filleted one (w/t = 0.8 < 1).
#[test]
fn neck_and_leaf_outside_calibration_warn() {
    let v = json(&run_case_text(
        "warn_neck",
        r#"{"analysis": "hinge", "hinge": {"type": "spherical_neck", "l": 16, "t": 2, "R": 2, "h": 10, "blank_length": 10}}"#,
    ));
    let w = warnings(&v);
    assert!(
        w.len() == 1 && w[0].contains("l/t = 8") && w[0].contains("1–5"),
        "{w:?}"
    );
    let v = json(&run_case_text(
        "warn_leaf",
        r#"{"analysis": "hinge", "hinge": {"type": "leaf", "l": 5, "t": 0.5, "w": 20, "h": 8, "blank_length": 10}}"#,
    ));
    let w = warnings(&v);
    assert!(w.len() == 1 && w[0].contains("w/t = 40"), "{w:?}");
    // A corner-filleted leaf narrower than any CalculiX design's (w/t 0.8 < 1; the plane-strain
    // factor's 0.5 does not cover its torsion law).
    let v = json(&run_case_text(
        "warn_narrow_leaf",
        r#"{"analysis": "hinge", "hinge": {"type": "corner_filleted", "l": 5, "R": 1, "t": 1, "w": 0.8, "h": 6, "blank_length": 6}}"#,
    ));
    assert_eq!(
        warnings(&v),
        ["hinge: corner_filleted w/t = 0.8 is outside the solid-calibrated range 1–20 (CalculiX designs): extrapolated"]
    );
}

/// The stage evaluates its hinges: a revolute notch outside the range is warned about with its
/// place in the case file (`stage.revolute`).
#[test]
fn stage_hinge_outside_calibration_warns() {
    // t/R = 0.5/16 = 0.031 < 0.06.
    let out = run_bundled_with("ruiz2019_stage.json", |c| {
        c["stage"]["revolute"]["R"] = serde_json::json!(16.0);
        c["stage"]["revolute"]["t"] = serde_json::json!(0.5);
    });
    assert_warns(&out, "stage.revolute: circular_notch t/R = 0.0313");
    assert!(out.report.markdown.contains("## Warnings"));
}

/// Sensitivity evaluates the base design's hinges; design the hinges it found: both warn
/// when those hinges leave the calibrated range (turned neck l/t > 5 here).
#[test]
fn sensitivity_and_design_warn_about_their_hinges() {
    // l/t = 18/3 = 6 > 5.
    let out = run_bundled_with("ruiz2019_sensitivity.json", |c| {
        c["stage"]["spherical"]["l"] = serde_json::json!(18.0);
    });
    assert!(
        out.warnings
            .iter()
            .any(|w| w.starts_with("stage.spherical: spherical_neck l/t = 6 ")),
        "{:?}",
        out.warnings
    );

    // Every neck inside these bounds has l/t ≥ 13/2.4 = 5.4 > 5.
    let out = run_bundled_with("ruiz2019_design.json", |c| {
        c["bounds"]["l_sph"] = serde_json::json!([13, 14]);
        c["bounds"]["t_sph"] = serde_json::json!([2, 2.4]);
    });
    assert_warns(&out, "design found, stage.spherical: spherical_neck l/t");
}

/// Geometrically nonlinear statics within small strains (a cantilever under a tip force
/// bending it by ~20°): no warning; pulled to 2 % axial strain: one warning naming the load
/// case and the element. (Al7075's properties without its allowable stress: at these loads the
/// bars are far above it, which is warned about separately.)
#[test]
fn nonlinear_static_warns_beyond_small_strain() {
    let case = |fx: f64, fz: f64| {
        format!(
            r#"{{"analysis": "static", "nonlinear": true, "steps": 10,
  "materials": {{"al": {{"E": 72000, "nu": 0.33, "density": 2.81e-9}}}},
  "sections": {{"leg": {{"shape": "rect", "w": 10, "h": 10}}}},
  "nodes": [[0, 0, 0], [50, 0, 0], [100, 0, 0]],
  "elements": [
    {{"type": "beam", "nodes": [0, 1], "section": "leg", "material": "al", "up": [0, 0, 1]}},
    {{"type": "beam", "nodes": [1, 2], "section": "leg", "material": "al", "up": [0, 0, 1]}}
  ],
  "supports": [{{"node": 0, "fix": ["ux", "uy", "uz", "rx", "ry", "rz"]}}],
  "load_cases": [{{"name": "tip", "forces": [{{"node": 2, "F": [{fx}, 0, {fz}, 0, 0, 0]}}]}}]}}"#
        )
    };
    // EI = 72000·10⁴/12 = 6e7 N·mm²; F L²/(2EI) = 0.35 rad at F = 4200 N.
    let v = json(&run_case_text("nl_small", &case(0.0, -4200.0)));
    assert!(warnings(&v).is_empty(), "{:?}", warnings(&v));
    // Axial: ε = F/(EA) = 144000/(72000·100) = 2 %.
    let v = json(&run_case_text("nl_stretch", &case(144_000.0, 0.0)));
    let w = warnings(&v);
    assert_eq!(w.len(), 1, "{w:?}");
    assert!(
        w[0].starts_with("load_cases[0] (\"tip\"): element") && w[0].contains("by +2.00 %"),
        "{w:?}"
    );
}

/// A mechanism's `hinge` elements are checked against the calibrated ranges as the `hinge`
/// analysis's hinges are (`hinge::calibration::calibration_warnings`; their ends are continuous
/// material, so not the blank's), in every analysis of the model: one warning per distinct
/// finding, naming the elements it applies to. The bundled lever's two circular notches (t/R
/// 0.2, w/t 10) are inside the ranges and warn about nothing; the kinds other than `static`
/// and `modal` take the same hook (`Analysis::mesh_model`), checked here through `frf`.
#[test]
fn mesh_hinge_elements_warn_outside_calibration() {
    // One leaf longer (l/t 10.5) and with sharper fillets (R/t 0.3) than any CalculiX design's.
    let out = run_bundled_with("lever_amplifier.json", |c| {
        c["elements"][1]["hinge"] = serde_json::json!(
            {"type": "corner_filleted", "l": 10.5, "R": 0.3, "t": 1.0, "w": 10.0, "h": 8.0}
        );
    });
    assert_eq!(
        out.warnings,
        [
            "elements[1].hinge: corner_filleted l/t = 10.5 is outside the solid-calibrated range 2–10 (CalculiX designs): extrapolated",
            "elements[1].hinge: corner_filleted R/t = 0.3 is outside the solid-calibrated range 0.5–2.5 (CalculiX designs): extrapolated",
        ]
    );
    assert_eq!(out.json["warnings"].as_array().unwrap().len(), 2);
    // Both notches too thick for their radius (t/R 0.6): one warning naming both, in the
    // static and in the modal analysis of the model.
    for modal in [false, true] {
        let out = run_bundled_with("lever_amplifier.json", |c| {
            for e in [0, 1] {
                c["elements"][e]["hinge"]["t"] = serde_json::json!(3.0);
            }
            if modal {
                c["analysis"] = serde_json::json!("modal");
                c["modes"] = serde_json::json!(2);
                c.as_object_mut().unwrap().remove("load_cases");
            }
        });
        assert_eq!(
            out.warnings,
            ["elements[0].hinge (likewise elements 1): circular_notch t/R = 0.6 is outside the solid-calibrated range 0.06–0.5 (41 circular notches): extrapolated"],
            "modal: {modal}"
        );
    }
    // The notches given by name (`hinge_types` of the case): the warning names the types, in
    // order of first use, with the elements each was given to, and still each element once.
    let notch = |t: f64| serde_json::json!({"type": "circular_notch", "R": 5.0, "t": t, "w": 20.0, "h": 12.0});
    let out = run_bundled_with("lever_amplifier.json", |c| {
        c["hinge_types"] = serde_json::json!({"a": notch(3.0), "b": notch(3.0), "ok": notch(1.0)});
        for (e, name) in [(0, "b"), (1, "a")] {
            c["elements"][e]["hinge"] = serde_json::json!(name);
        }
    });
    assert_eq!(
        out.warnings,
        ["elements[0].hinge (likewise elements 1; hinge type \"b\" on element 0, \"a\" on element 1): circular_notch t/R = 0.6 is outside the solid-calibrated range 0.06–0.5 (41 circular notches): extrapolated"]
    );
    // One element given by name, the other inline: the name is credited to its element only.
    let out = run_bundled_with("lever_amplifier.json", |c| {
        c["hinge_types"] = serde_json::json!({"thick": notch(3.0)});
        c["elements"][0]["hinge"] = notch(3.0);
        c["elements"][1]["hinge"] = serde_json::json!("thick");
    });
    assert_eq!(
        out.warnings,
        ["elements[0].hinge (likewise elements 1; hinge type \"thick\" on element 1): circular_notch t/R = 0.6 is outside the solid-calibrated range 0.06–0.5 (41 circular notches): extrapolated"]
    );
    let out = run_bundled_with("lever_amplifier.json", |c| {
        c["hinge_types"] = serde_json::json!({"thick": notch(3.0), "ok": notch(1.0)});
        for (e, name) in [(0, "ok"), (1, "thick")] {
            c["elements"][e]["hinge"] = serde_json::json!(name);
        }
    });
    assert_eq!(
        out.warnings,
        ["elements[1].hinge (hinge type \"thick\"): circular_notch t/R = 0.6 is outside the solid-calibrated range 0.06–0.5 (41 circular notches): extrapolated"]
    );
    // The frequency response of the stage's FE model: one of its twelve hinge elements, its
    // first revolute notch, too thick for its radius (t/R 5/8).
    let out = run_bundled_with("ruiz2019_stage_frf.json", |c| {
        c["elements"][0]["hinge"]["t"] = serde_json::json!(5.0);
    });
    assert_eq!(
        out.warnings,
        ["elements[0].hinge: circular_notch t/R = 0.625 is outside the solid-calibrated range 0.06–0.5 (41 circular notches): extrapolated"]
    );
}

/// A mesh `sensitivity` warns about the hinge elements of its base design and a mesh `design`
/// about those of the design it found (the stage's do the same, above), naming the mesh file
/// the elements are in, as errors there are (`case.mesh: in mesh file "F" at `elements[0].hinge``).
#[test]
fn mesh_sensitivity_and_design_warn_about_their_hinge_elements() {
    // The lever's notches at t = 3, R = 5: t/R 0.6 > 0.5.
    let out = run_bundled_with("lever_sensitivity.json", |c| {
        c["case"]["parameters"] = serde_json::json!({"t": 3.0});
        c["case"]["mesh"] = serde_json::json!(root().join("meshes/lever_parameters.json"));
    });
    assert_eq!(
        out.warnings,
        [format!(
            "case.mesh: in mesh file \"{}\" at `elements[0].hinge` (hinge type \"notch\"; likewise elements 1): circular_notch t/R = 0.6 is outside the solid-calibrated range 0.06–0.5 (41 circular notches): extrapolated",
            root().join("meshes/lever_parameters.json").display()
        )]
    );
    // Every parallelogram within these bounds has t/R ≥ 2.6/5 = 0.52 > 0.5.
    let out = run_bundled_with("parallelogram_design.json", |c| {
        c["parameters"]["t"] = serde_json::json!({"bounds": [2.6, 3.0]});
        c["parameters"]["R"] = serde_json::json!({"bounds": [2.0, 5.0]});
        c["case"]["mesh"] = serde_json::json!(root().join("meshes/parallelogram_parameters.json"));
        c["case"]["parameters"] = serde_json::json!({"t": 2.8, "R": 4.0});
    });
    assert!(!out.warnings.is_empty());
    for w in &out.warnings {
        assert!(
            w.starts_with(&format!(
                "design found, case.mesh: in mesh file \"{}\" at `elements[0].hinge` (hinge type \"flex\"; likewise elements ",
                root().join("meshes/parallelogram_parameters.json").display()
            )),
            "{w}"
        );
        assert!(w.contains("circular_notch t/R = "), "{w}");
    }
}

/// A hinge element's calibration warnings are those of its notch with no blank
/// (`MeshSpec::hinge_warnings`): they depend on the blank's section, not on its length, which
/// the node distance sets. Checked on hinges with findings in h/t and R/t, in l/t and R/t, in
/// t/R, in l/t of a turned neck, and on calibrated ones (a short wide leaf among them, the
/// checked regime with no band).
#[test]
fn calibration_warnings_do_not_depend_on_the_blank_length() {
    use flexfem::hinge::{calibration::calibration_warnings, HingeSpec};
    for json in [
        r#"{"type": "corner_filleted", "l": 5, "R": 1.75, "t": 0.6, "w": 10, "h": 15}"#,
        r#"{"type": "corner_filleted", "l": 2.5, "R": 1, "t": 1, "w": 12, "h": 8}"#,
        r#"{"type": "corner_filleted", "l": 10.5, "R": 0.3, "t": 1, "w": 10, "h": 8}"#,
        r#"{"type": "circular_notch", "R": 5, "t": 3, "w": 10, "h": 12}"#,
        r#"{"type": "circular_notch", "R": 5, "t": 1, "w": 10, "h": 10}"#,
        r#"{"type": "spherical_neck", "l": 18, "R": 3, "t": 3, "h": 12}"#,
    ] {
        let mut v: serde_json::Value = serde_json::from_str(json).unwrap();
        let at = |v: &mut serde_json::Value, b: f64| {
            v["blank_length"] = serde_json::json!(b);
            let spec: HingeSpec = serde_json::from_value(v.clone()).unwrap();
            calibration_warnings(&spec.profile().unwrap())
        };
        let none = at(&mut v, 0.0);
        for b in [0.5, 3.0, 20.0, 200.0] {
            assert_eq!(at(&mut v, b), none, "{json}, blank {b}");
        }
    }
}

/// Many different hinge elements each a little outside a range: the first
/// `MAX_HINGE_WARNINGS` (20) distinct findings are listed, and one line counts the rest and
/// names their elements (runs of indices as `a–b`), so a model of thousands of such hinges gets
/// 21 lines, not thousands. Thirty corner-filleted leaves, t = 0.6 … 0.6029 mm: two findings
/// each (h/t ≈ 25, R/t ≈ 2.9), all distinct.
#[test]
fn many_distinct_hinge_findings_are_summarised() {
    use flexfem::case::mesh::hinge::MAX_HINGE_WARNINGS;
    let n = 30;
    let nodes: Vec<serde_json::Value> = (0..2 * n)
        .map(|k| serde_json::json!([20.0 * (k / 2) as f64 + 15.0 * (k % 2) as f64, 0.0, 0.0]))
        .collect();
    let elements: Vec<serde_json::Value> = (0..n)
        .map(|i| {
            serde_json::json!({"type": "hinge", "nodes": [2 * i, 2 * i + 1], "material": "m", "up": [0, 0, 1],
                "hinge": {"type": "corner_filleted", "l": 5, "R": 1.75, "t": 0.6 + 1e-4 * i as f64, "w": 10, "h": 15}})
        })
        .collect();
    let spec: flexfem::case::mesh::MeshSpec =
        serde_json::from_value(serde_json::json!({"nodes": nodes, "elements": elements})).unwrap();
    let w = spec.hinge_warnings();
    assert_eq!(MAX_HINGE_WARNINGS, 20);
    assert_eq!(w.len(), MAX_HINGE_WARNINGS + 1, "{w:#?}");
    assert!(
        w[0].starts_with("elements[0].hinge: corner_filleted h/t = 25 "),
        "{}",
        w[0]
    );
    assert!(
        w[19].starts_with("elements[9].hinge: corner_filleted R/t = "),
        "{}",
        w[19]
    );
    assert_eq!(
        w[20],
        "hinge elements: 40 more calibration warnings, not listed, on elements 10–29"
    );
    // The same elements read from a mesh file, given by one hinge type: every listed line names
    // the file and the type, the count of the rest names the file.
    let mut spec = spec;
    spec.mesh_file = Some("leaves.json".into());
    spec.hinge_type_names = (0..n).map(|i| (i, "leaf".to_string())).collect();
    let w = spec.hinge_warnings();
    assert!(
        w[0].starts_with("mesh: in mesh file \"leaves.json\" at `elements[0].hinge` (hinge type \"leaf\"): corner_filleted h/t = 25 "),
        "{}",
        w[0]
    );
    assert_eq!(
        w[20],
        "mesh: in mesh file \"leaves.json\", hinge elements: 40 more calibration warnings, not listed, on elements 10–29"
    );
    // Five equal leaves, each given by its own type: one line, three names and a count.
    let elements: Vec<serde_json::Value> = (0..5)
        .map(|i| {
            serde_json::json!({"type": "hinge", "nodes": [2 * i, 2 * i + 1], "material": "m", "up": [0, 0, 1],
                "hinge": {"type": "corner_filleted", "l": 5, "R": 1.75, "t": 0.6, "w": 10, "h": 15}})
        })
        .collect();
    let mut spec: flexfem::case::mesh::MeshSpec =
        serde_json::from_value(serde_json::json!({"nodes": nodes[..10], "elements": elements})).unwrap();
    spec.hinge_type_names = (0..5).map(|i| (i, format!("t{i}"))).collect();
    let w = spec.hinge_warnings();
    assert!(
        w[0].starts_with("elements[0].hinge (likewise elements 1–4; hinge type \"t0\" on element 0, \"t1\" on element 1, \"t2\" on element 2, 2 more): corner_filleted h/t = 25 "),
        "{w:#?}"
    );
}

/// `flexfem check` lists the warnings a run gives that depend on the case alone
/// (`analysis::check_warnings`): on every bundled case they are the run's own, in its order
/// (the pan-tilt hinges' calibration warnings, the two deliberately implausible materials of
/// [`KNOWN`]); `check` prints each on
/// stderr as `warning: …`, `ok` alone on stdout, exit 0; a case whose run warns only about its
/// results (the stage's stresses) checks silently.
#[test]
fn check_lists_the_warnings_that_depend_on_the_case_alone() {
    let mut with = Vec::new();
    for entry in std::fs::read_dir(root().join("cases")).unwrap() {
        let p = entry.unwrap().path();
        let c = analysis::load(&p).unwrap();
        if matches!(c, analysis::Case::Sweep(_)) {
            continue;
        }
        let checked = analysis::check_warnings(&c);
        let run = analysis::run(&c).unwrap().warnings;
        let mut at = run.iter();
        for w in &checked {
            assert!(
                at.any(|r| r == w),
                "{}: `{w}` not among the run's warnings in order: {run:?}",
                p.display()
            );
        }
        if !checked.is_empty() {
            with.push(p.file_name().unwrap().to_string_lossy().into_owned());
        }
    }
    with.sort();
    assert_eq!(
        with,
        [
            "pantilt_8r.json",
            "pantilt_8r_modal.json",
            "pantilt_hinge_corner_filleted.json",
            "pantilt_hinge_damping.json",
            "pendulum_nonlinear_transient.json",
            "prs_stiffness_han_fsw_frame.json",
        ],
        "bundled cases with case-only warnings"
    );
    let o = std::process::Command::new(env!("CARGO_BIN_EXE_flexfem"))
        .args(["check", "cases/pantilt_8r.json"])
        .current_dir(root())
        .output()
        .unwrap();
    assert_eq!(o.status.code(), Some(0));
    assert_eq!(
        String::from_utf8_lossy(&o.stdout),
        "ok: static case cases/pantilt_8r.json\n"
    );
    let err = String::from_utf8_lossy(&o.stderr);
    let lines: Vec<&str> = err.lines().collect();
    assert_eq!(lines.len(), 2, "{err}");
    assert!(lines[0].starts_with("warning: mesh: in mesh file \"../meshes/pantilt_8r.json\" at `elements[0].hinge` (likewise elements 1–7): corner_filleted h/t = 25 "), "{err}");
    assert!(lines[1].contains("corner_filleted R/t = 2.9167"), "{err}");
    let o = std::process::Command::new(env!("CARGO_BIN_EXE_flexfem"))
        .args(["check", "cases/ruiz2019_stage.json"])
        .current_dir(root())
        .output()
        .unwrap();
    assert_eq!(
        (o.status.code(), o.stderr.len()),
        (Some(0), 0),
        "{}",
        String::from_utf8_lossy(&o.stderr)
    );
}
