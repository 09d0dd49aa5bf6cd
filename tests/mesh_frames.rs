//! Local frames (`"frame"`, `"axis"`) of supports, prescribed displacements and forces in mesh
//! cases.

use flexfem::analysis::{self, Case};
use flexfem::case;
use flexfem::fem;

/// Node 1 on a spring to ground (kx = 1, ky = 2, kz = 3 N/mm, rotations 1 N·mm/rad) and a
/// slider along a = (1, 1, 0)/√2 (`support`), loaded by `load`.
fn slider(support: &str, load: &str) -> String {
    format!(
        r#"{{"analysis": "static", "nodes": [[0, 0, 0], [0, 0, 0]],
            "elements": [{{"type": "spring", "nodes": [1], "k": [1, 2, 3, 1, 1, 1]}}],
            "supports": [{{"node": 0, "fix": ["ux", "uy", "uz", "rx", "ry", "rz"]}}, {support}],
            "load_cases": [{{"name": "l", {load}}}]}}"#
    )
}

fn build(text: &str) -> Result<fem::Model, case::CaseError> {
    match analysis::parse(text)? {
        Case::Static(s) => s.model.build(),
        _ => panic!("not static"),
    }
}

/// An inclined slider is one line: with the axis a, the node moves along a only, by
/// s = (F·a)/(aᵀKa) (closed form of a spring system constrained to a line): F = (1, 0, 0) N,
/// aᵀKa = (1 + 2)/2 = 1.5 N/mm, F·a = 1/√2 → u = s·a = (1/3, 1/3, 0) mm.
#[test]
fn inclined_slider_by_axis() {
    let text = slider(
        r#"{"node": 1, "axis": [1, 1, 0], "fix": ["uy", "uz", "rx", "ry", "rz"]}"#,
        r#""forces": [{"node": 1, "F": [1, 0, 0, 0, 0, 0]}]"#,
    );
    let u = fem::solve_static(&build(&text).unwrap()).unwrap().load_cases[0].displacements[1];
    for (k, want) in [(0, 1.0 / 3.0), (1, 1.0 / 3.0), (2, 0.0)] {
        assert!((u[k] - want).abs() < 1e-12, "u[{k}] = {} vs {want}", u[k]);
    }
    // The same force given along the axis in the force's own frame: F = (1/√2)·a + …; with
    // `frame` rows a, b, c: F_local = (1/√2, −1/√2, 0) is F = (1, 0, 0).
    let r = 0.5f64.sqrt();
    let text = slider(
        r#"{"node": 1, "axis": [1, 1, 0], "fix": ["uy", "uz", "rx", "ry", "rz"]}"#,
        &format!(
            r#""forces": [{{"node": 1, "frame": [[{r}, {r}, 0], [{}, {r}, 0], [0, 0, 1]], "F": [{r}, {}, 0, 0, 0, 0]}}]"#,
            -r, -r
        ),
    );
    let v = fem::solve_static(&build(&text).unwrap()).unwrap().load_cases[0].displacements[1];
    for k in 0..6 {
        assert!((u[k] - v[k]).abs() < 1e-12, "{u:?} vs {v:?}");
    }
}

/// An inclined actuator is one line: a prescribed 2 mm along the axis moves the node by 2·a.
#[test]
fn inclined_actuator_by_axis() {
    let text = slider(
        r#"{"node": 1, "axis": [0, 3, 4], "fix": ["uy", "uz", "rx", "ry", "rz"]}"#,
        r#""displacements": [{"node": 1, "dof": "ux", "value": 2, "axis": [0, 3, 4]}]"#,
    );
    let u = fem::solve_static(&build(&text).unwrap()).unwrap().load_cases[0].displacements[1];
    for (k, want) in [(0, 0.0), (1, 1.2), (2, 1.6)] {
        assert!((u[k] - want).abs() < 1e-12, "u[{k}] = {} vs {want}", u[k]);
    }
}

/// Bad frames are refused by JSON path: not orthonormal, left-handed, both `frame` and
/// `axis`, a lone `uy` with `axis`, two different frames on one node.
#[test]
fn bad_frames_refused_with_paths() {
    let load = r#""forces": [{"node": 1, "F": [1, 0, 0, 0, 0, 0]}]"#;
    for (support, path) in [
        (
            r#"{"node": 1, "frame": [[1, 0, 0], [0, 1, 0], [0, 0.1, 1]], "fix": ["uy"]}"#,
            "supports[1].frame",
        ),
        (
            r#"{"node": 1, "frame": [[1, 0, 0], [0, 1, 0], [0, 0, -1]], "fix": ["uy"]}"#,
            "supports[1].frame",
        ),
        (
            r#"{"node": 1, "frame": [[1, 0, 0], [0, 1, 0], [0, 0, 1]], "axis": [1, 0, 0], "fix": ["uy"]}"#,
            "supports[1].axis",
        ),
        (r#"{"node": 1, "axis": [1, 1, 0], "fix": ["uy"]}"#, "supports[1].fix"),
    ] {
        let e = build(&slider(support, load)).unwrap_err();
        assert_eq!(e.path, path, "{e}");
    }
    let text = slider(
        r#"{"node": 1, "axis": [1, 1, 0], "fix": ["uy", "uz"]}"#,
        r#""displacements": [{"node": 1, "dof": "ux", "value": 1, "axis": [1, 0, 0]}]"#,
    );
    let e = build(&text).unwrap_err();
    assert_eq!(e.path, "load_cases[0].displacements[0].axis", "{e}");
    assert!(e.message.contains("supports[1].axis"), "{e}");
}

/// `flexfem schema` describes the new fields: a case with a hinge element, joints of every
/// kind and frames on a support, a force and a prescribed displacement validates (the jsonschema
/// crate, draft 2020-12), and flexfem accepts it too.
#[test]
fn schema_covers_hinge_joint_and_frame_fields() {
    let out = std::process::Command::new(env!("CARGO_BIN_EXE_flexfem"))
        .arg("schema")
        .output()
        .expect("run flexfem schema");
    let schema: serde_json::Value = serde_json::from_slice(&out.stdout).unwrap();
    let v = jsonschema::draft202012::options()
        .should_validate_formats(false)
        .build(&schema)
        .unwrap();
    let case = serde_json::json!({
        "analysis": "static", "materials": {"al": "Al7075"},
        "nodes": [[0, 0, 0], [0, 0, 0], [20, 0, 0], [20, 0, 0], [20, 0, 0], [20, 0, 0], [20, 0, 0], [20, 0, 0],
                  [20, 0, 0], [20, 0, 0], [20, 0, 0], [20, 0, 0]],
        "elements": [
            {"type": "joint", "nodes": [0, 1], "kind": "weld"},
            {"type": "hinge", "nodes": [1, 2], "hinge": {"type": "leaf", "l": 5, "t": 1, "w": 4, "h": 4}, "material": "al", "up": [0, 0, 1]},
            {"type": "joint", "nodes": [2, 3], "kind": "revolute", "axis": [0, 0, 1]},
            {"type": "joint", "nodes": [3, 4], "kind": "spherical"},
            {"type": "joint", "nodes": [5, 6], "kind": "universal", "axis": [1, 0, 0], "axis2": [0, 1, 0]},
            {"type": "joint", "nodes": [7, 8], "kind": "cylindrical", "axis": [1, 0, 0]},
            {"type": "joint", "nodes": [9, 10], "kind": "prismatic", "axis": [1, 0, 0]}
        ],
        "supports": [{"node": 0, "fix": ["ux", "uy", "uz", "rx", "ry", "rz"]},
                     {"node": 11, "axis": [1, 0, 0], "fix": ["uy", "uz", "rx", "ry", "rz"]}],
        "load_cases": [{"name": "l",
            "forces": [{"node": 11, "frame": [[1, 0, 0], [0, 1, 0], [0, 0, 1]], "F": [1, 0, 0, 0, 0, 0]}],
            "displacements": [{"node": 11, "dof": "ux", "value": 0.1, "axis": [1, 0, 0]}]}]
    });
    let errors: Vec<String> = v
        .iter_errors(&case)
        .map(|e| format!("{e} at {}", e.instance_path()))
        .collect();
    assert!(errors.is_empty(), "{errors:?}");
    build(&case.to_string()).unwrap_or_else(|e| panic!("{e}"));
}
