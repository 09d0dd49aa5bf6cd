//! Bundled mechanisms built from `hinge` elements and rigid links in `static` mesh cases: the
//! parallelogram guide (against the rigid four-bar linkage with the hinge's own stiffness), and
//! Yu, Lu and Hao's (2016) 8R spherical pan-tilt (against the PRBM kinematics and the FEM of its Table 3).
//!
//! The geometry of every model comes from `tests/common/mechanisms.rs`; the bundled files must
//! equal what it writes (`FLEXFEM_BLESS=1` rewrites them).

#[path = "common/mechanisms.rs"]
mod mechanisms;

use flexfem::hinge::{characterise, HingeSpec};
use flexfem::material::Material;
use mechanisms::*;
use serde_json::{json, Value};
use std::path::PathBuf;

fn root() -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR"))
}

/// Runs a case given as a JSON value (relative `mesh` paths resolve against `cases/`).
fn run_value(case: &Value) -> Value {
    let text = serde_json::to_string(case).unwrap();
    let parsed = flexfem::analysis::parse_in(&text, Some(&root().join("cases")))
        .unwrap_or_else(|e| panic!("case does not load: {e}"));
    flexfem::analysis::run(&parsed)
        .unwrap_or_else(|e| panic!("analysis fails: {e}"))
        .json
}

fn read_json(rel: &str) -> Value {
    let text = std::fs::read_to_string(root().join(rel)).unwrap_or_else(|e| panic!("{rel}: {e}"));
    serde_json::from_str(&text).unwrap()
}

/// Displacement row [ux, uy, uz, rx, ry, rz] of `node` in load case `lc` of a static result.
fn disp(result: &Value, lc: usize, node: usize) -> [f64; 6] {
    let row = &result["load_cases"][lc]["displacements"][node];
    std::array::from_fn(|k| row[k].as_f64().unwrap())
}

/// A mesh file's model with the case's fields added (an inline model).
fn inline(mesh: &Value, case: Value) -> Value {
    let mut c = mesh.clone();
    for (k, v) in case.as_object().unwrap() {
        c[k] = v.clone();
    }
    c
}

/// The bundled files are exactly what the generator writes.
#[test]
fn bundled_mechanism_files_match_their_generator() {
    let pt = pantilt_mesh(&PanTilt::standard());
    let files: Vec<(&str, Value)> = vec![
        ("meshes/parallelogram_notch.json", parallelogram_mesh()),
        ("cases/parallelogram_guide.json", parallelogram_case()),
        ("cases/lever_amplifier.json", lever_case()),
        ("meshes/pantilt_8r.json", pt.mesh.clone()),
        ("cases/pantilt_8r.json", pantilt_case(&pt)),
        ("cases/pantilt_8r_modal.json", pantilt_modal_case()),
        ("cases/han2019_prs_head.json", prs_head_case(0.0)),
    ];
    let bless = std::env::var_os("FLEXFEM_BLESS").is_some_and(|v| v == "1");
    for (rel, want) in files {
        if bless {
            let text = flexfem::report::json::pretty(&want);
            std::fs::write(root().join(rel), format!("{text}\n")).unwrap();
            continue;
        }
        assert_eq!(
            read_json(rel),
            want,
            "{rel} differs from tests/common/mechanisms.rs (FLEXFEM_BLESS=1 rewrites it)"
        );
    }
}

/// Yu, Lu and Hao (2016), §3: the PRBM inverse kinematics for pitch γ = 10°, phase φ = 45° gives θ₁ = 7.36°,
/// θ₂ = 3.09° (printed to 0.01°). The joint-axis layout of `pantilt_axes` reproduces both.
#[test]
fn pantilt_axes_reproduce_the_papers_inverse_kinematics() {
    let th = pantilt_ikp(10.0, 45.0);
    assert!((th[0] - 7.36).abs() < 0.005, "θ1 = {}", th[0]);
    assert!((th[1] - 3.09).abs() < 0.005, "θ2 = {}", th[1]);
    // The home pose is the zero of both.
    let h = pantilt_ikp(0.0, 0.0);
    assert!(h[0].abs() < 1e-12 && h[1].abs() < 1e-12, "{h:?}");
}

/// The hinge of the parallelogram (and the lever) as the `hinge` analysis sees it: the
/// element's notch with the element's blank on either side.
fn para_spec() -> HingeSpec {
    HingeSpec::CircularNotch {
        r: PARA_R,
        t: PARA_T,
        w: PARA_W,
        h: PARA_H,
        blank_length: (PARA_HINGE_LEN - 2.0 * PARA_R) / 2.0,
    }
}

fn parallelogram_hinge_stiffness() -> f64 {
    characterise(&para_spec(), &Material::AL7075).unwrap().hinge.k_bend
}

/// Parallelogram guide: lateral stiffness of the rigid four-bar with two torsion springs per
/// leg at the notch centres, k = 4·k_θ/L² (each leg, guided at both ends, turns both hinges by
/// δ/L: energy 2·½k_θ(δ/L)² per leg), k_θ the compliant-axis stiffness of the `hinge`
/// analysis of the same hinge (its notch plus the element's blanks), L = 50 mm between notch
/// centres. Within 2 %: the remainder is the hinges' transverse (shear and bending-over-length)
/// compliance, which the point-spring linkage lacks.
/// The parallelogram case with legs of `leg` mm (the bundled one: `PARA_LEG`).
fn parallelogram(leg: f64) -> Value {
    if leg == PARA_LEG {
        return read_json("cases/parallelogram_guide.json");
    }
    let mut case = parallelogram_case();
    case.as_object_mut().unwrap().shift_remove("mesh");
    inline(&parallelogram_mesh_with(leg), case)
}

#[test]
fn parallelogram_lateral_stiffness_is_four_k_theta_over_l_squared() {
    for leg in [PARA_LEG, 50.0] {
        let res = run_value(&parallelogram(leg));
        let ux = disp(&res, 0, PARA_BAR_NODE)[0];
        let k_fe = 1.0 / ux;
        let k_theta = parallelogram_hinge_stiffness();
        let k_ref = 4.0 * k_theta / (leg * leg);
        let rel = k_fe / k_ref - 1.0;
        eprintln!("parallelogram L = {leg}: k_theta = {k_theta:.6} N·mm/rad, k_FE = {k_fe:.6} N/mm, 4k/L² = {k_ref:.6} N/mm, rel {rel:+.4e}");
        assert!(
            rel.abs() < 0.02,
            "L = {leg}: k_FE = {k_fe}, 4 k_θ/L² = {k_ref} ({rel:+.3e})"
        );
        // The bar translates without turning (a parallelogram).
        let d = disp(&res, 0, PARA_BAR_NODE);
        // (Up to the legs' unequal axial stretch under the push's overturning moment.)
        assert!(d[5].abs() < 1e-2 * (ux / leg).to_degrees(), "bar rotation {} deg", d[5]);
    }
}

/// ∫ f(1 − f) ds over a hinge element, f(s) the fraction of its compliant-axis compliance
/// between its first end and s (mm): how far the hinge's rotation is from a point pivot.
fn pivot_spread(spec: &HingeSpec) -> f64 {
    let profile = spec.profile().unwrap();
    let half = profile.half_length();
    let n = 4000;
    let dx = 2.0 * half / n as f64;
    let c: Vec<f64> = (0..n)
        .map(|i| {
            let x0 = -half + dx * i as f64;
            flexfem::hinge::segment_compliance(&profile, &Material::AL7075, x0, x0 + dx)[(4, 4)]
        })
        .collect();
    let total: f64 = c.iter().sum();
    let mut acc = 0.0;
    let mut integral = 0.0;
    for ci in &c {
        // Midpoint rule on f(1 − f).
        let f = (acc + 0.5 * ci) / total;
        integral += f * (1.0 - f) * dx;
        acc += ci;
    }
    integral
}

/// Parallelogram guide at a 1 mm stroke, geometrically nonlinear: the parasitic drop of the
/// moving bar.
///
/// Reference: the linkage's L − √(L² − δ²) (each leg a rigid link between pivots at the notch
/// centres), within 2 % (the must-show) for the bundled L = 100 mm. The remainder is physical: a
/// notch turns its leg over a few millimetres, not at a point. With θ(s) = θ₀·f(s) through a
/// hinge (f the running fraction of its compliant-axis compliance), δ = θ₀L is unchanged but
/// ½∫θ² ds shrinks by the factor 1 − 2·∫f(1 − f)ds / L (the "refined linkage": −1.45 % at
/// L = 100 mm, −2.9 % at 50 mm); the FE drop is asserted within 0.5 % (L = 100) and 1 %
/// (L = 50) of that. Measured with 8 segments per hinge: −1.69 % / −0.25 % (L = 100),
/// −3.58 % / −0.71 % (L = 50) against the linkage / refined linkage.
///
/// With ONE co-rotational segment per hinge (`"segments": 1`; nonlinear runs default to 4) the drop is that of a point-pivot linkage of length
/// L − L_e/2 (the element measures deformation from its chord, whose length stays fixed to first
/// order: 7.6 % short at L = 100 mm); asserted within 0.5 % of that chord model, so the warning
/// the static analysis gives for single-segment hinges in nonlinear runs stays true.
#[test]
fn parallelogram_parasitic_drop() {
    let spec = para_spec();
    let spread = pivot_spread(&spec);
    let drop_at = |l: f64, segments: usize| {
        let mut case = parallelogram_case();
        case.as_object_mut().unwrap().shift_remove("mesh");
        let mut mesh = parallelogram_mesh_with(l);
        for e in mesh["elements"].as_array_mut().unwrap() {
            if e["type"] == "hinge" {
                e["segments"] = json!(segments);
            }
        }
        let mut case = inline(&mesh, case);
        case["nonlinear"] = json!(true);
        case["steps"] = json!(4);
        let res = run_value(&case);
        let d = disp(&res, 1, PARA_BAR_NODE);
        assert!((d[0] - 1.0).abs() < 1e-12);
        -d[1]
    };
    for (l, tol_refined) in [(PARA_LEG, 5e-3), (50.0, 1e-2)] {
        let linkage = l - (l * l - 1.0).sqrt();
        let refined = linkage * (1.0 - 2.0 * spread / l);
        let drop = drop_at(l, PARA_SEGMENTS);
        let rel = |x: f64| drop / x - 1.0;
        eprintln!(
            "parallelogram L = {l}, drop at 1 mm: FE {drop:.6e} mm; linkage {linkage:.6e} ({:+.4e}); refined {refined:.6e} (∫f(1−f) = {spread:.4} mm, {:+.4e})",
            rel(linkage),
            rel(refined)
        );
        if l == PARA_LEG {
            assert!(rel(linkage).abs() < 0.02, "L = {l}: drop {drop} vs linkage {linkage}");
        }
        assert!(
            rel(refined).abs() < tol_refined,
            "L = {l}: drop {drop} vs refined {refined}"
        );
        let single = drop_at(l, 1);
        let chord = linkage * (1.0 - PARA_HINGE_LEN / (2.0 * l));
        assert!(
            (single / chord - 1.0).abs() < 5e-3,
            "L = {l}: single-segment drop {single} vs chord model {chord}"
        );
    }
}

/// Pitch and phase of the pan-tilt driven to the PRBM angles (nonlinear).
fn pantilt_pose(p: &PanTilt, theta: [f64; 2], nonlinear: bool) -> (f64, f64) {
    let m = pantilt_mesh(p);
    let mut case = json!({"analysis": "static", "load_cases": [pantilt_drive(&m, theta)]});
    if nonlinear {
        case["nonlinear"] = json!(true);
        case["steps"] = json!(4);
    }
    let res = run_value(&inline(&m.mesh, case));
    let d = disp(&res, 0, m.platform);
    pitch_phase([d[3], d[4], d[5]])
}

/// Yu, Lu and Hao (2016), Table 3 (ANSYS FEM of the 8R compliant pan-tilt at θ₁ = 7.36°, θ₂ = 3.09°): the
/// platform pitch and phase for the standard hinge and five variants (and without the passive
/// limb). Printed beside the paper's; asserted: every pose is near the PRBM target (pitch
/// within 2.5° of 10°, phase within 7° of 45°, the paper's spread), and the extremes of the
/// paper's ordering by deviation — variant 4 (δ = 1) deviates most, variant 1 (t = 15) least —
/// for pitch and phase. (Why the deviations are smaller than the paper's: see the report.)
#[test]
fn pantilt_table3_pitch_and_phase() {
    let mut rows = Vec::new();
    for (name, p, pitch_paper, phase_paper) in PanTilt::table3() {
        let (pitch, phase) = pantilt_pose(&p, PT_THETA, true);
        eprintln!("{name:24} pitch {pitch:7.3} (paper {pitch_paper:6.3})  phase {phase:7.3} (paper {phase_paper:6.2})");
        rows.push((name, pitch, phase, pitch_paper, phase_paper));
    }
    for &(name, pitch, phase, ..) in &rows {
        assert!(
            (pitch - 10.0).abs() < 2.5 && (phase - 45.0).abs() < 7.0,
            "{name}: {pitch} / {phase}"
        );
    }
    // The paper's ordering by deviation from the PRBM target at both ends, over the standard
    // hinge and its five variants (rows 0–5): variant 4 (row 4) most, variant 1 (row 1) least,
    // for the pitch (relative deviation) and the phase (absolute deviation) alike.
    let table = &rows[..6];
    let extremes = |dev: &dyn Fn(f64, f64) -> f64, ours: bool| {
        let d: Vec<f64> = table
            .iter()
            .map(|r| if ours { dev(r.1, r.2) } else { dev(r.3, r.4) })
            .collect();
        let most = (0..6).max_by(|&a, &b| d[a].total_cmp(&d[b])).unwrap();
        let least = (0..6).min_by(|&a, &b| d[a].total_cmp(&d[b])).unwrap();
        (most, least)
    };
    let pitch_dev = |pitch: f64, _: f64| (10.0 - pitch).abs();
    let phase_dev = |_: f64, phase: f64| (phase - 45.0).abs();
    for (what, dev) in [("pitch", &pitch_dev as &dyn Fn(f64, f64) -> f64), ("phase", &phase_dev)] {
        assert_eq!(extremes(dev, false), (4, 1), "the paper's {what} ordering");
        assert_eq!(extremes(dev, true), (4, 1), "{what}: (most, least) deviating rows");
    }
}

/// Lever amplifier: output/input displacement against the lumped lever. Rigid linkage: ratio
/// b/a = `LEVER_OUT / LEVER_IN` = 5. Lumped elastic lever (pivots at the notch centres; each
/// hinge a rotational spring k_θ and an axial spring k_a, both from the `hinge` analysis of the
/// same hinge): the lever turns by θ and both hinges bend by θ, so the strut force is
/// P = 2k_θθ/a; it stretches the fulcrum (the lever rises by v₀ = P/k_a) and shortens the strut
/// by P/k_a. Input u = aθ + 2P/k_a, output bθ + P/k_a: ratio (b + g)/(a + 2g), g = 2k_θ/(a·k_a).
/// The elastic departure from the ideal 5 is 0.71 %; the FE matches the lumped lever to −7.7e-6,
/// asserted within `LEVER_TOL` (≈ 3× that), and stays below the ideal 5.
const LEVER_TOL: f64 = 2.5e-5;

#[test]
fn lever_amplifier_ratio_matches_the_lumped_lever() {
    let res = run_value(&read_json("cases/lever_amplifier.json"));
    let u_out = disp(&res, 0, LEVER_OUTPUT_NODE)[1];
    let ratio = u_out / LEVER_STROKE;
    let spec = para_spec();
    let hr = characterise(&spec, &Material::AL7075).unwrap().hinge;
    let (a, b) = (LEVER_IN, LEVER_OUT);
    let g = 2.0 * hr.k_bend / (a * hr.k_axial);
    let lumped = (b + g) / (a + 2.0 * g);
    let rel = ratio / lumped - 1.0;
    eprintln!(
        "lever: FE ratio {ratio:.6}, lumped {lumped:.6} (ideal {}), rel {rel:+.4e}",
        b / a
    );
    assert!(
        ratio < b / a,
        "ratio {ratio} must fall below the rigid-linkage {}",
        b / a
    );
    assert!(rel.abs() < LEVER_TOL, "ratio {ratio} vs lumped {lumped} ({rel:+.3e})");
}

/// X. Han, Y. Wang and J. Shi, "Stiffness modeling of 3-PRS mechanism", Table IV:
/// deformation of the FSW head under F = [100, 50, 50] kN at z = −0.4 m, α = 0, β = 0/5/10°:
/// 0.25/0.47/0.69 mm (their analytic model: link beams + lead screws, ideal joints) and
/// 0.21/0.42/0.61 mm (their ANSYS). The same idealisation here (beams, axial springs, ideal
/// joints, stiff platform), the load at the platform centre. Printed beside the paper; asserted:
/// the deformation grows with β as in both of the paper's columns. The magnitudes are not
/// asserted: the paper gives neither the tool length (the load's lever arm below the platform)
/// nor the link orientation, and the deflection depends on the first strongly (at β = 0:
/// 0.109 mm with the load at the platform centre, 0.231 mm 100 mm below it, 0.462 mm 200 mm
/// below).
#[test]
fn prs_head_deformation_against_han2019() {
    let paper_analytic = [0.25, 0.47, 0.69];
    let paper_fea = [0.21, 0.42, 0.61];
    let mut ours = Vec::new();
    for (k, beta) in [0.0, 5.0, 10.0].into_iter().enumerate() {
        let case = if beta == 0.0 {
            read_json("cases/han2019_prs_head.json")
        } else {
            prs_head_case(beta)
        };
        let res = run_value(&case);
        let d = disp(&res, 0, PRS_TOOL_NODE);
        let mag = (d[0] * d[0] + d[1] * d[1] + d[2] * d[2]).sqrt();
        eprintln!(
            "3-PRS head β = {beta:4}°: |u| = {mag:.4} mm (u = [{:.4}, {:.4}, {:.4}]); paper analytic {} FEA {}",
            d[0], d[1], d[2], paper_analytic[k], paper_fea[k]
        );
        ours.push(mag);
    }
    assert!(ours[0] < ours[1] && ours[1] < ours[2], "{ours:?}");
}

/// Yu, Lu and Hao (2016), Table 1: the 8R compliant mechanism's lowest frequencies 24.4,
/// 27.4, 79.9, 132.7, 146.0, 200.2 Hz, read there as proof of two DOFs: "the first and the
/// second natural frequencies are closer and far less than the third". Printed beside the
/// paper (our model carries no platform or camera mass, which the paper does not give, so the
/// values differ); asserted: the same two-DOF signature — f2/f1 < 1.2 (paper 1.12) and
/// f3 > 2.5·f2 (paper 2.9).
#[test]
fn pantilt_modes_show_two_dofs() {
    let paper = [24.4, 27.4, 79.9, 132.7, 146.0, 200.2];
    let res = run_value(&read_json("cases/pantilt_8r_modal.json"));
    let f: Vec<f64> = res["modes"]
        .as_array()
        .unwrap()
        .iter()
        .map(|m| m["frequency_hz"].as_f64().unwrap())
        .collect();
    eprintln!("pan-tilt modes {f:.1?} Hz; paper {paper:?} Hz");
    assert_eq!(f.len(), 6);
    assert!(f[1] / f[0] < 1.2, "{f:?}");
    assert!(f[2] > 2.5 * f[1], "{f:?}");
}

/// Why variant 5 (blank height h = 10) of Yu, Lu and Hao's (2016) Table 3 deviates more than the standard
/// hinge (paper: pitch 8.710° against 9.195°): h leaves the notch's compliant-axis, torsional
/// and axial stiffness alike (the blank is ~10³ times stiffer than the notch per length) and
/// acts through the links, whose section is the blank's (w × h). With rigid links the two
/// poses agree within 0.01°; with the nylon links variant 5 lies more than 0.1° further from
/// the target pitch. (Closed-form reasoning, no published number: the check that the model's
/// explanation of the ordering holds.)
#[test]
fn pantilt_variant5_acts_through_the_links() {
    let s = PanTilt::standard();
    let v5 = PanTilt { h: 10.0, ..s };
    let rigid = |p: PanTilt| {
        pantilt_pose(
            &PanTilt {
                links: Links::Rigid,
                ..p
            },
            PT_THETA,
            true,
        )
    };
    let (ps, _) = rigid(s);
    let (p5, _) = rigid(v5);
    assert!((ps - p5).abs() < 0.01, "rigid links: standard {ps}, variant 5 {p5}");
    let (ns, _) = pantilt_pose(&s, PT_THETA, true);
    let (n5, _) = pantilt_pose(&v5, PT_THETA, true);
    eprintln!("pitch, rigid links: standard {ps:.4}, h = 10 {p5:.4}; nylon links: {ns:.4}, {n5:.4}");
    assert!(
        (10.0 - n5) - (10.0 - ns) > 0.1,
        "nylon links: standard {ns}, variant 5 {n5}"
    );
}
