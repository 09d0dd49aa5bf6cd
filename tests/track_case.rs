//! `"track"` in case files: the bundled parallel leaf-spring guide (`cases/leaf_guide_track.json`)
//! end to end (JSON rows, Markdown table, CSV and SVG with `--out`), the consistency of the first
//! tracked point with the linear analyses, and the refusal of bad requests.

mod common;

use common::{run_case_text, run_in, stderr, tempdir};
use flexfem::fem::{self, Dof, Support};
use serde_json::Value;

fn bundled() -> Value {
    let text = std::fs::read_to_string(common::root().join("cases/leaf_guide_track.json")).unwrap();
    serde_json::from_str(&text).unwrap()
}

/// The bundled case: 11 tracked steps per stroke direction, the support stiffness along the
/// leaves dropping as the beam constraint model predicts (S. Awtar, A. H. Slocum, E. Sevincer,
/// "Characteristics of beam-based flexure modules", J. Mech. Des. 129(6) (2007) 625–639:
/// k_x(δ)/k_x(0) = 1/(1 + 12δ²/(700t²)) for leaves of thickness t, within 5 % up to δ = 0.2 L),
/// and the CSV and SVG files written with `--out`; the held (driven) axis is left out of the
/// stiffness, never `null`.
#[test]
fn bundled_leaf_guide_tracks_support_stiffness_and_frequencies() {
    let d = tempdir("track-bundled");
    let case = common::root().join("cases/leaf_guide_track.json");
    let out = run_in(&d, &["run", case.to_str().unwrap(), "--out", "out"]);
    assert!(out.status.success(), "{}", stderr(&out));
    let r: Value = serde_json::from_str(&std::fs::read_to_string(d.join("out/result.json")).unwrap()).unwrap();
    let t = 0.5;
    assert_eq!(r["load_cases"].as_array().unwrap().len(), 2);
    for (lc, sign) in r["load_cases"].as_array().unwrap().iter().zip([1.0, -1.0]) {
        let track = &lc["track"];
        assert_eq!(track["stroke"], "node 22 uy (mm)");
        let steps = track["steps"].as_array().unwrap();
        assert_eq!(steps.len(), 11);
        let k0 = steps[0]["compliance"][0]["stiffness"]["x"].as_f64().unwrap();
        // 2EA/L = 2·210000·5/50 N/mm (leaves in pure tension at zero stroke).
        assert!((k0 / 42_000.0 - 1.0).abs() < 1e-9, "k0 = {k0}");
        for s in steps {
            let delta = s["stroke"].as_f64().unwrap();
            assert!(delta * sign >= -1e-12);
            assert_eq!(s["frequencies_hz"].as_array().unwrap().len(), 3);
            assert!(s["compliance"][0]["stiffness"]["y"].is_null(), "the driven DOF is held");
            let k = s["compliance"][0]["stiffness"]["x"].as_f64().unwrap();
            let closed = 1.0 / (1.0 + 12.0 * delta * delta / (700.0 * t * t));
            assert!(
                (k / k0 / closed - 1.0).abs() < 0.05,
                "δ = {delta}: {} vs {closed}",
                k / k0
            );
        }
        let name = lc["name"].as_str().unwrap();
        let csv = std::fs::read_to_string(d.join(format!("out/track_{name}.csv"))).unwrap();
        assert_eq!(csv.lines().count(), 12);
        assert!(csv.starts_with("lambda,stroke,stable,f1_hz,f2_hz,f3_hz,node22_kx_n_per_mm,"));
        let svg = std::fs::read_to_string(d.join(format!("out/track_{name}.svg"))).unwrap();
        assert!(svg.contains("support stiffness along the path") && svg.contains("natural frequencies"));
    }
    let md = std::fs::read_to_string(d.join("out/report.md")).unwrap();
    assert!(md.contains("### Along the path") && md.contains("| held |"));
}

/// At λ = 0 the tangent is the linear stiffness: the first tracked point's frequencies equal
/// the linear modal analysis (`fem::solve_modal`) of the same model with the driven DOF
/// supported, to the Lanczos tolerance (1e-6), and its compliance the linear node compliance.
#[test]
fn first_point_equals_the_linear_modal_and_compliance() {
    let v = bundled();
    let parsed = flexfem::analysis::parse_value(v, None).expect("parses");
    let flexfem::analysis::Case::Static(case) = parsed else {
        panic!("a static case")
    };
    let model = case.model.build().expect("builds");
    let c = 22;
    let opts = fem::NonlinearOptions {
        steps: 10,
        step_track: fem::StepTrack {
            modes: 3,
            compliance: vec![c],
        },
        ..Default::default()
    };
    let nl = fem::solve_nonlinear(&model, &opts).expect("solves");
    let q0 = &nl.load_cases[0].step_quantities[0];
    let mut held = model.clone();
    held.supports.push(Support::dofs(c, &[Dof::Uy]));
    let modal = fem::modal::solve_modal(&held, &fem::modal::ModalOptions::new(3)).expect("modes");
    assert_eq!(q0.frequencies_hz().len(), modal.modes.len());
    for (a, b) in q0.frequencies_hz().iter().zip(&modal.modes) {
        assert!((a / b.frequency_hz - 1.0).abs() < 1e-6, "{a} vs {}", b.frequency_hz);
    }
    let sys = fem::System::new(&held, &[], fem::solve::Parallelism::Sequential).expect("system");
    let cl = sys.node_compliance(&held, c).expect("compliance");
    for i in 0..6 {
        for j in 0..6 {
            let (a, b) = (q0.compliance[0][i][j], cl[(i, j)]);
            assert!(
                (a - b).abs() <= 1e-9 * cl[(i, i)].abs().max(cl[(j, j)].abs()),
                "C[{i}][{j}]: {a} vs {b}"
            );
        }
    }
}

/// An edit of the bundled case.
type Edit = fn(&mut Value);

/// Bad requests are refused with the JSON path, exit code 2.
#[test]
fn bad_track_requests_name_their_path() {
    let cases: [(&str, Edit, &str); 4] = [
        ("linear", |v| v["nonlinear"] = Value::Bool(false), "track"),
        ("nothing", |v| v["track"] = serde_json::json!({}), "track"),
        (
            "node",
            |v| v["track"]["compliance"][0]["node"] = 99.into(),
            "track.compliance[0].node",
        ),
        ("modes", |v| v["track"]["modes"] = 101.into(), "track.modes"),
    ];
    for (name, edit, path) in cases {
        let mut v = bundled();
        if name == "linear" {
            v.as_object_mut().unwrap().remove("steps");
        }
        edit(&mut v);
        let out = run_case_text(&format!("track-bad-{name}"), &v.to_string());
        assert_eq!(out.status.code(), Some(2), "{name}: {}", stderr(&out));
        assert!(stderr(&out).contains(&format!("`{path}`")), "{name}: {}", stderr(&out));
    }
}
