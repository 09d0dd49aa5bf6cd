//! The `hinge` element of mesh cases against the `hinge` analysis.

use flexfem::analysis::{self, Case};
use flexfem::fem;
use flexfem::hinge::{self, HingeSpec};

/// The five hinge families (without blank_length), and a node distance longer than the notch.
const FAMILIES: [(&str, f64); 5] = [
    (r#"{"type": "circular_notch", "R": 8, "t": 2, "w": 10, "h": 10}"#, 40.0),
    (
        r#"{"type": "elliptical_notch", "ax": 6, "ay": 4, "t": 1.5, "w": 8, "h": 10}"#,
        25.0,
    ),
    (
        r#"{"type": "corner_filleted", "l": 5, "R": 1.75, "t": 0.6, "w": 10, "h": 15}"#,
        20.0,
    ),
    (r#"{"type": "leaf", "l": 5, "t": 1, "w": 4, "h": 4}"#, 9.0),
    (r#"{"type": "spherical_neck", "l": 5, "t": 3, "R": 4, "h": 10}"#, 30.0),
];

/// A static case: the hinge element from node 0 (clamped) to node 1 along x, notch thinning
/// along z (`up`), six unit load cases at node 1.
fn case_text(hinge: &str, d: f64) -> String {
    let loads: Vec<String> = (0..6)
        .map(|k| {
            let mut f = [0.0; 6];
            f[k] = 1.0;
            format!(r#"{{"name": "u{k}", "forces": [{{"node": 1, "F": {f:?}}}]}}"#)
        })
        .collect();
    format!(
        r#"{{"analysis": "static", "materials": {{"al": "Al7075"}},
            "nodes": [[0, 0, 0], [{d}, 0, 0]],
            "elements": [{{"type": "hinge", "nodes": [0, 1], "hinge": {hinge}, "material": "al", "up": [0, 0, 1]}}],
            "supports": [{{"node": 0, "fix": ["ux", "uy", "uz", "rx", "ry", "rz"]}}],
            "load_cases": [{}]}}"#,
        loads.join(", ")
    )
}

fn model_of(text: &str) -> fem::Model {
    match analysis::parse(text).unwrap_or_else(|e| panic!("{e}")) {
        Case::Static(s) => s.model.build().unwrap_or_else(|e| panic!("{e}")),
        _ => panic!("not static"),
    }
}

/// The 6×6 tip compliance of the FE model (columns: the displacements under each unit load) is
/// the `hinge` analysis's compliance for blank_length = (node distance − notch length)/2 (its
/// blank per side), to 1e-9 relative to the largest entry of each column's diagonal scale, bar
/// the torsion entry: the `hinge` analysis clamps and loads the hinge through rigid end faces,
/// whose section reaches back into a short blank for the torque, while a mesh element's ends are
/// nodes in continuous material. Its torsion entry is that of the same region with continuous
/// ends ([`hinge::flex_region`]), and never stiffer than the `hinge` analysis's (for the pan-tilt
/// leaf, h/t 25, at 20 mm: a blank 7.5 mm = 0.5 h long, the torsional compliance is 5.0 %
/// larger).
#[test]
fn hinge_element_reproduces_the_hinge_analysis_compliance() {
    let al = flexfem::material::Material::builtin("Al7075").unwrap();
    for (h, d) in FAMILIES {
        let model = model_of(&case_text(h, d));
        let res = fem::solve_static(&model).unwrap();
        let mut v: serde_json::Value = serde_json::from_str(h).unwrap();
        let notch: HingeSpec = {
            v["blank_length"] = 0.0.into();
            serde_json::from_value(v.clone()).unwrap()
        };
        let half_notch = notch.profile().unwrap().half_notch;
        v["blank_length"] = ((d - 2.0 * half_notch) / 2.0).into();
        let spec: HingeSpec = serde_json::from_value(v).unwrap();
        let mut reference = hinge::characterise(&spec, &al).unwrap().hinge.compliance;
        let continuous = hinge::flex_region(&spec.profile().unwrap(), &al).unwrap().compliance();
        assert!(continuous[3][3] >= reference[3][3], "{h}");
        reference[3][3] = continuous[3][3];
        for j in 0..6 {
            let u = res.load_cases[j].displacements[1];
            for i in 0..6 {
                let scale = (reference[i][i] * reference[j][j]).sqrt();
                let err = (u[i] - reference[i][j]).abs() / scale;
                assert!(
                    err < 1e-9,
                    "{h}: C[{i}][{j}] FE {} vs hinge analysis {} ({err:e})",
                    u[i],
                    reference[i][j]
                );
            }
        }
    }
}

/// A node distance shorter than the notch is refused, naming the element's nodes, the distance
/// and the notch length; a `blank_length` in the element's hinge is refused by path.
#[test]
fn short_hinge_and_blank_length_refused() {
    let text = case_text(FAMILIES[3].0, 3.0);
    let e = match analysis::parse(&text).unwrap() {
        Case::Static(s) => s.model.build().unwrap_err(),
        _ => panic!(),
    };
    assert_eq!(e.path, "elements[0].nodes", "{e}");
    // Leaf of length l = 5 mm between nodes 3 mm apart.
    assert!(e.message.contains("3 mm") && e.message.contains("5 mm"), "{e}");
    let text = case_text(
        r#"{"type": "leaf", "l": 5, "t": 1, "w": 4, "h": 4, "blank_length": 1}"#,
        9.0,
    );
    let e = match analysis::parse(&text).unwrap() {
        Case::Static(s) => s.model.build().unwrap_err(),
        _ => panic!(),
    };
    assert_eq!(e.path, "elements[0].hinge.blank_length", "{e}");
    let text = case_text(r#"{"type": "leaf", "l": 5, "t": 9, "w": 4, "h": 4}"#, 9.0);
    let e = match analysis::parse(&text).unwrap() {
        Case::Static(s) => s.model.build().unwrap_err(),
        _ => panic!(),
    };
    assert_eq!(e.path, "elements[0].hinge.t", "{e}");
}

/// Nonlinear: a small tip moment about the compliant axis rotates the tip by M·C[4][4] (the
/// linear compliance, to 1e-6 at 1e-4 rad), and the element's mass (for modal analysis) is
/// the density times the geometric volume of notch and blank, half at each node.
#[test]
fn hinge_element_nonlinear_and_modal() {
    let (h, d) = FAMILIES[0];
    let al = flexfem::material::Material::builtin("Al7075").unwrap();
    let model = model_of(&case_text(h, d));
    let c44 = fem::solve_static(&model).unwrap().load_cases[4].displacements[1][4];
    let m = 1e-4 / c44;
    let mut nl = model.clone();
    nl.load_cases = vec![fem::LoadCase::new("m").force(1, [0.0, 0.0, 0.0, 0.0, m, 0.0])];
    let opts = fem::nonlinear::NonlinearOptions::default();
    let r = fem::nonlinear::solve_nonlinear(&nl, &opts).unwrap();
    let ry = r.load_cases[0].fe.displacements[1][4];
    assert!((ry / 1e-4 - 1.0).abs() < 1e-6, "{ry}");
    // Mass: a leaf l = 5, t = 1 in a w = 4, h = 4 blank over 9 mm has the volume
    // w·(h·9 − l·(h − t)) = 84 mm³, half of its mass lumped at each node.
    let (h, d) = FAMILIES[3];
    let model = model_of(&case_text(h, d));
    let vol = 4.0 * (4.0 * 9.0 - 5.0 * 3.0);
    let lumped: f64 = model.masses.iter().filter(|p| p.node == 1).map(|p| p.mass).sum();
    assert!((lumped / (al.density * vol / 2.0) - 1.0).abs() < 1e-6, "{lumped}");
}
