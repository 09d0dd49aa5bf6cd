//! The `joint` element of mesh cases: ideal joints by elimination, against closed-form
//! kinematics.

use flexfem::analysis::{self, Case};
use flexfem::case;
use flexfem::fem;

/// Crank-rocker four-bar: ground pivots O2 = (0, 0) and O4 = (d, 0), crank a, coupler b,
/// rocker c (Grashof: a + b ≤ c + d), crank at θ2 = 60° initially.
const A: f64 = 20.0;
const B: f64 = 50.0;
const C: f64 = 40.0;
const D: f64 = 45.0;

/// Coupler pin B of the four-bar at crank angle θ2 (the open branch, B above the line A–O4):
/// intersection of the circles |B − A| = b and |B − O4| = c (the loop-closure, equivalent to
/// Freudenstein's equation, e.g. Norton, Design of Machinery, 5th ed., §4.5).
fn pin_b(t2: f64) -> [f64; 2] {
    let a = [A * t2.cos(), A * t2.sin()];
    let (dx, dy) = (D - a[0], -a[1]);
    let e = (dx * dx + dy * dy).sqrt();
    let along = (B * B - C * C + e * e) / (2.0 * e);
    let h = (B * B - along * along).sqrt();
    let (ux, uy) = (dx / e, dy / e);
    [a[0] + along * ux - h * uy, a[1] + along * uy + h * ux]
}

/// The four-bar of stiff beams and revolute joints about z; `drive`: the crank rotation
/// prescribed at the crank's middle node (degrees), or `None` (then a force at the coupler).
fn four_bar(drive: Option<f64>) -> String {
    let t2 = 60f64.to_radians();
    let a = [A * t2.cos(), A * t2.sin()];
    let b = pin_b(t2);
    let mid = [a[0] / 2.0, a[1] / 2.0];
    // Nodes: 0 ground O2, 1 crank at O2, 2 crank middle, 3 crank at A, 4 coupler at A,
    // 5 coupler at B, 6 rocker at B, 7 rocker at O4, 8 ground O4.
    let nodes = [[0.0, 0.0], [0.0, 0.0], mid, a, a, b, b, [D, 0.0], [D, 0.0]];
    let nodes: Vec<String> = nodes.iter().map(|p| format!("[{}, {}, 0]", p[0], p[1])).collect();
    let beam = |i: usize, j: usize| {
        format!(r#"{{"type": "beam", "nodes": [{i}, {j}], "section": "s", "material": "steel", "up": [0, 0, 1]}}"#)
    };
    let joint = |i: usize, j: usize| {
        format!(r#"{{"type": "joint", "nodes": [{i}, {j}], "kind": "revolute", "axis": [0, 0, 1]}}"#)
    };
    let elements = [
        beam(1, 2),
        beam(2, 3),
        beam(4, 5),
        beam(6, 7),
        joint(0, 1),
        joint(3, 4),
        joint(5, 6),
        joint(7, 8),
    ];
    let load = match drive {
        Some(deg) => format!(r#"{{"name": "drive", "displacements": [{{"node": 2, "dof": "rz", "value": {deg}}}]}}"#),
        None => r#"{"name": "push", "forces": [{"node": 5, "F": [1, 0, 0, 0, 0, 0]}]}"#.to_string(),
    };
    format!(
        r#"{{"analysis": "static", "nonlinear": true, "steps": 6, "materials": {{"steel": "steel"}},
            "sections": {{"s": {{"shape": "circle", "d": 8}}}},
            "nodes": [{}], "elements": [{}],
            "supports": [{{"node": 0, "fix": ["ux", "uy", "uz", "rx", "ry", "rz"]}},
                         {{"node": 8, "fix": ["ux", "uy", "uz", "rx", "ry", "rz"]}}],
            "load_cases": [{load}]}}"#,
        nodes.join(", "),
        elements.join(", ")
    )
}

fn model_of(text: &str) -> Result<fem::Model, case::CaseError> {
    match analysis::parse(text)? {
        Case::Static(s) => s.model.build(),
        _ => panic!("not static"),
    }
}

fn angle(p: [f64; 2], q: [f64; 2]) -> f64 {
    (q[1] - p[1]).atan2(q[0] - p[0])
}

/// A crank rotation of 30° (finite rotation, co-rotational solver) moves the coupler and
/// rocker as the rigid four-bar: their angles from the closed-form loop closure to 1e-9 rad.
#[test]
fn four_bar_of_revolute_joints_moves_as_the_rigid_linkage() {
    let model = model_of(&four_bar(Some(30.0))).unwrap();
    let opts = fem::NonlinearOptions {
        steps: 6,
        ..Default::default()
    };
    let r = fem::solve_nonlinear(&model, &opts).unwrap();
    let u = &r.load_cases[0].fe.displacements;
    let pos = |n: usize| [model.nodes[n][0] + u[n][0], model.nodes[n][1] + u[n][1]];
    let t2 = 90f64.to_radians();
    let a = [A * t2.cos(), A * t2.sin()];
    let b = pin_b(t2);
    let (coupler, rocker) = (angle(a, b), angle([D, 0.0], b));
    let fe_coupler = angle(pos(4), pos(5));
    let fe_rocker = angle(pos(7), pos(6));
    let fe_crank = angle(pos(1), pos(3));
    assert!((fe_crank - t2).abs() < 1e-9, "crank {fe_crank} vs {t2}");
    assert!((fe_coupler - coupler).abs() < 1e-9, "coupler {fe_coupler} vs {coupler}");
    assert!((fe_rocker - rocker).abs() < 1e-9, "rocker {fe_rocker} vs {rocker}");
    // The rotation of the rocker's nodes equals its angle change (rigid link).
    let rocker0 = angle([D, 0.0], pin_b(60f64.to_radians()));
    assert!(
        (u[6][5] - (rocker - rocker0)).abs() < 1e-9,
        "{} vs {}",
        u[6][5],
        rocker - rocker0
    );
}

/// Without the drive, a force on the coupler meets a mechanism: the solve is refused naming
/// the free motion (a joint node's rotation about the joint axis, its local rx).
#[test]
fn undriven_four_bar_is_a_mechanism() {
    let mut model = model_of(&four_bar(None)).unwrap();
    model.load_cases.truncate(1);
    let e = fem::solve_static(&model).unwrap_err().to_string();
    assert!(e.contains("mechanism") && e.contains("rx"), "{e}");
}

/// Bad joints: nodes apart, a missing axis, a non-perpendicular universal joint.
#[test]
fn bad_joints_refused_with_paths() {
    let ok = four_bar(Some(30.0));
    let far = ok.replace(
        r#""nodes": [3, 4], "kind": "revolute""#,
        r#""nodes": [2, 4], "kind": "revolute""#,
    );
    let e = model_of(&far).unwrap_err();
    assert_eq!(e.path, "elements[5].nodes", "{e}");
    assert!(e.message.contains("apart"), "{e}");
    let no_axis = ok.replace(
        r#""kind": "revolute", "axis": [0, 0, 1]}, {"type": "joint", "nodes": [5, 6]"#,
        r#""kind": "revolute"}, {"type": "joint", "nodes": [5, 6]"#,
    );
    let e = model_of(&no_axis).unwrap_err();
    assert_eq!(e.path, "elements[5].axis", "{e}");
    let bad_u = ok.replace(
        r#""nodes": [5, 6], "kind": "revolute", "axis": [0, 0, 1]"#,
        r#""nodes": [5, 6], "kind": "universal", "axis": [0, 0, 1], "axis2": [0, 1, 1]"#,
    );
    let e = model_of(&bad_u).unwrap_err();
    assert_eq!(e.path, "elements[6].axis2", "{e}");
}

/// Steel, E and G (built-in values).
fn steel() -> (f64, f64) {
    let m = flexfem::material::Material::builtin("steel").unwrap();
    (m.e, m.shear_modulus())
}

/// A spherical joint carries no moment: a beam (L = 100 mm, d = 8 mm, Euler–Bernoulli) hung
/// from a clamped node by a spherical joint and resting on a roller (uy, uz, and twist held)
/// at the other end is simply supported: mid-span deflection P L³ / (48 E I) (Roark, Table 8.1
/// case 1a), and the clamp's reaction has no moment.
#[test]
fn spherical_joint_is_a_pin() {
    let text = r#"{"analysis": "static", "materials": {"steel": "steel"},
        "sections": {"s": {"shape": "circle", "d": 8}},
        "nodes": [[0, 0, 0], [0, 0, 0], [50, 0, 0], [100, 0, 0]],
        "elements": [{"type": "joint", "nodes": [0, 1], "kind": "spherical"},
            {"type": "beam", "nodes": [1, 2], "section": "s", "material": "steel", "up": [0, 0, 1], "shear": false},
            {"type": "beam", "nodes": [2, 3], "section": "s", "material": "steel", "up": [0, 0, 1], "shear": false}],
        "supports": [{"node": 0, "fix": ["ux", "uy", "uz", "rx", "ry", "rz"]}, {"node": 3, "fix": ["uy", "uz", "rx"]}],
        "load_cases": [{"name": "p", "forces": [{"node": 2, "F": [0, 0, -10, 0, 0, 0]}]}]}"#;
    let model = model_of(text).unwrap();
    let r = &fem::solve_static(&model).unwrap().load_cases[0];
    let (e, _) = steel();
    let i = std::f64::consts::PI * 8f64.powi(4) / 64.0;
    let want = -10.0 * 100f64.powi(3) / (48.0 * e * i);
    let w = r.displacements[2][2];
    assert!((w / want - 1.0).abs() < 1e-9, "{w} vs {want}");
    let (_, reaction) = r.reactions.iter().find(|(n, _)| *n == 0).unwrap();
    assert!((reaction[2] - 5.0).abs() < 1e-9, "{reaction:?}");
    for k in 3..6 {
        assert!(reaction[k].abs() < 1e-9, "moment at the spherical joint: {reaction:?}");
    }
}

/// A universal joint (pins along y and z) transmits the torque about the shaft axis x: two
/// shafts of L = 50 mm in series, the output end on a bearing (uy, uz held), twist at the end
/// T (L₁ + L₂)/(G J) with J = π d⁴/32 (Saint-Venant, circular shaft), reaction torque −T;
/// it transmits no bending moment (statics of the pinned lever).
#[test]
fn universal_joint_transmits_torque() {
    let case = |m: [f64; 6]| {
        format!(
            r#"{{"analysis": "static", "materials": {{"steel": "steel"}},
            "sections": {{"s": {{"shape": "circle", "d": 8}}}},
            "nodes": [[0, 0, 0], [50, 0, 0], [50, 0, 0], [100, 0, 0]],
            "elements": [{{"type": "beam", "nodes": [0, 1], "section": "s", "material": "steel", "up": [0, 0, 1]}},
                {{"type": "joint", "nodes": [1, 2], "kind": "universal", "axis": [0, 1, 0], "axis2": [0, 0, 1]}},
                {{"type": "beam", "nodes": [2, 3], "section": "s", "material": "steel", "up": [0, 0, 1]}}],
            "supports": [{{"node": 0, "fix": ["ux", "uy", "uz", "rx", "ry", "rz"]}}, {{"node": 3, "fix": ["uy", "uz"]}}],
            "load_cases": [{{"name": "t", "forces": [{{"node": 3, "F": {m:?}}}]}}]}}"#
        )
    };
    let model = model_of(&case([0.0, 0.0, 0.0, 1000.0, 0.0, 0.0])).unwrap();
    let r = &fem::solve_static(&model).unwrap().load_cases[0];
    let (_, g) = steel();
    let j = std::f64::consts::PI * 8f64.powi(4) / 32.0;
    let want = 1000.0 * 100.0 / (g * j);
    let rx = r.displacements[3][3];
    assert!((rx / want - 1.0).abs() < 1e-9, "{rx} vs {want}");
    let (_, reaction) = r.reactions.iter().find(|(n, _)| *n == 0).unwrap();
    assert!((reaction[3] + 1000.0).abs() < 1e-9, "{reaction:?}");
    let model = model_of(&case([0.0, 0.0, 0.0, 0.0, 1000.0, 0.0])).unwrap();
    let r = &fem::solve_static(&model).unwrap().load_cases[0];
    // The pins carry no bending moment at the joint (element end moments there vanish), so
    // the output shaft is a lever: M = 1000 N·mm over L₂ = 50 mm, ±20 N at the joint and the
    // bearing, and the clamp takes 20 N with the moment 20 N × 50 mm.
    for (el, end) in [(0, 1), (1, 0)] {
        let f = r.elements[el].end_forces[end];
        assert!(f[4].abs() < 1e-9 && f[5].abs() < 1e-9, "moment at the joint: {f:?}");
    }
    let (_, reaction) = r.reactions.iter().find(|(n, _)| *n == 0).unwrap();
    assert!(
        (reaction[2] + 20.0).abs() < 1e-9 && (reaction[4] - 1000.0).abs() < 1e-9,
        "{reaction:?}"
    );
}
