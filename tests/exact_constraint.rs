//! The `constraints` analysis (exact-constraint check) against the mobility counts of
//! Grübler–Kutzbach (M = 6·bodies − Σ constraints, e.g. K. J. Waldron, G. L. Kinzel,
//! *Kinematics, Dynamics and Design of Machinery*, 2nd ed., 2004, §1.6), made exact by the rank
//! of the constraint Jacobian: mobility = 6·bodies − rank, redundancy = constraints − rank, so
//! Grübler–Kutzbach = mobility − redundancy. The over-constraint of a planar linkage built in
//! 3D (three redundant out-of-plane constraints per closed loop) and the exactly constrained
//! alternatives are those of D. L. Blanding, *Exact Constraint: Machine Design Using Kinematic
//! Principles*, ASME Press, 1999, and of SPACAR's over-constraint check (J. P. Meijaard, D. M.
//! Brouwer, J. B. Jonker, Multibody Syst. Dyn. 23 (2010) 77–97).

mod common;

use common::{run_case_text, stderr};
use serde_json::{json, Value};

const Z: [f64; 3] = [0.0, 0.0, 1.0];

/// A 100 mm square parallelogram in the xy plane: four stiff bars (bar 0 along the x axis,
/// clamped at node 0; bars 1–3 around the square) joined at the corners by the joints `kinds`
/// (elements 4–7 at (100, 0), (100, 100), (0, 100), (0, 0)).
fn parallelogram(kinds: [Value; 4]) -> Value {
    let corner = |i: usize| [[0, 0, 0], [100, 0, 0], [100, 100, 0], [0, 100, 0]][i % 4];
    let nodes: Vec<[i32; 3]> = (0..4).flat_map(|i| [corner(i), corner(i + 1)]).collect();
    let mut elements: Vec<Value> = (0..4)
        .map(|i| json!({"type": "beam", "nodes": [2 * i, 2 * i + 1], "section": "bar", "material": "al", "up": Z}))
        .collect();
    // zip-checked: both sides are [_; 4] arrays.
    for ((a, b), mut k) in [(1, 2), (3, 4), (5, 6), (7, 0)].into_iter().zip(kinds) {
        k["type"] = json!("joint");
        k["nodes"] = json!([a, b]);
        elements.push(k);
    }
    json!({
        "analysis": "constraints",
        "materials": {"al": "Al7075"},
        "sections": {"bar": {"shape": "rect", "w": 5, "h": 5}},
        "nodes": nodes,
        "elements": elements,
        "supports": [{"node": 0, "fix": ["ux", "uy", "uz", "rx", "ry", "rz"]}]
    })
}

fn revolute() -> Value {
    json!({"kind": "revolute", "axis": Z})
}
fn spherical() -> Value {
    json!({"kind": "spherical"})
}
fn universal(axis2: [f64; 3]) -> Value {
    json!({"kind": "universal", "axis": Z, "axis2": axis2})
}

/// R-R-S-U: revolute joints at (100, 0) and (100, 100), a spherical joint at (0, 100), a
/// universal joint (pins z and `axis2`) at (0, 0).
fn rrsu(axis2: [f64; 3]) -> Value {
    parallelogram([revolute(), revolute(), spherical(), universal(axis2)])
}

/// Bar 1 alone on its revolute joint (about z at (100, 0)) to the clamped bar 0.
fn pendulum() -> Value {
    let mut c = rrrr();
    let els = c["elements"].as_array().unwrap().clone();
    c["elements"] = json!([els[0], els[1], els[4]]);
    c["nodes"] = json!(c["nodes"].as_array().unwrap()[..4]);
    c
}

/// The parallelogram of four revolute joints.
fn rrrr() -> Value {
    parallelogram([revolute(), revolute(), revolute(), revolute()])
}

/// The JSON result of a case.
fn run(case: &Value) -> Value {
    let parsed = flexfem::analysis::parse(&case.to_string()).expect("case parses");
    flexfem::analysis::run(&parsed).expect("analysis runs").json
}

fn counts(r: &Value) -> [i64; 5] {
    ["constraints", "rank", "grubler_kutzbach", "redundant", "mobility"].map(|k| r[k].as_i64().unwrap())
}

fn texts(r: &Value, key: &str) -> Vec<String> {
    r[key]
        .as_array()
        .unwrap()
        .iter()
        .map(|x| x["text"].as_str().unwrap().to_string())
        .collect()
}

/// Four revolute joints with parallel axes (a planar four-bar in 3D): 3 moving bars × 6 −
/// 4 × 5 = −2 by Grübler–Kutzbach, actual mobility 1, hence 3 redundant constraints: the
/// out-of-plane translation and the two out-of-plane rotations of the loop closure, named at
/// the joint that closes the loop; every constraint they depend on is out of plane too.
#[test]
fn planar_parallelogram_of_four_revolutes_has_three_redundancies() {
    let r = run(&rrrr());
    assert_eq!(counts(&r), [26, 23, -2, 3, 1]);
    let red = r["redundancies"].as_array().unwrap();
    let named: Vec<&str> = red.iter().map(|x| x["constraint"].as_str().unwrap()).collect();
    assert_eq!(
        named,
        [
            "elements[7] (revolute joint, nodes 0–7): translation along its axis [0, 0, 1]",
            "elements[7] (revolute joint, nodes 0–7): rotation about its first normal [0, 1, 0]",
            "elements[7] (revolute joint, nodes 0–7): rotation about its second normal [-1, 0, 0]",
        ]
    );
    assert!(red.iter().all(|x| x["path"] == "elements[7]"));
    for x in red {
        for w in x["with"].as_array().unwrap() {
            let w = w.as_str().unwrap();
            let out_of_plane = w.contains("translation along its axis [0, 0, 1]") || w.contains("rotation about its");
            assert!(
                out_of_plane && !w.contains("rotation about its axis"),
                "in-plane partner: {w}"
            );
        }
    }
}

/// The releases suggested for the parallelogram (a spherical joint, then a universal joint)
/// leave a mechanism with no redundancy and the same single free motion.
#[test]
fn following_the_suggested_releases_leaves_an_exactly_constrained_mechanism() {
    let r = run(&rrrr());
    let s: Vec<(&str, &str, i64)> = r["suggestions"]
        .as_array()
        .unwrap()
        .iter()
        .map(|x| {
            (
                x["path"].as_str().unwrap(),
                x["change"].as_str().unwrap(),
                x["redundant_after"].as_i64().unwrap(),
            )
        })
        .collect();
    assert_eq!(
        s,
        [
            ("elements[7]", "make elements[7] a spherical joint", 1),
            (
                "elements[6]",
                "make elements[6] a universal joint with axis [0, 0, 1] and axis2 [-1, 0, 0]",
                0
            ),
        ]
    );
    let fixed = run(&parallelogram([
        revolute(),
        revolute(),
        universal([-1.0, 0.0, 0.0]),
        spherical(),
    ]));
    assert_eq!(counts(&fixed), [23, 23, 1, 0, 1]);
}

/// R-R-S-U: 5 + 5 + 3 + 4 = 17 = 3·6 − 1 constraints, Grübler–Kutzbach 1, and the rank
/// confirms it (the universal joint's second pin, along x, is not the S–U line, so the last
/// bar cannot spin about that line). The free motion is the parallelogram's: both cranks rotate
/// about z through their ground pivots and the coupler translates along x (it stays parallel
/// to the ground bar) at 100 mm per radian of the cranks.
#[test]
fn rrsu_variant_is_exactly_constrained_with_the_parallelogram_motion() {
    let r = run(&rrsu([1.0, 0.0, 0.0]));
    assert_eq!(counts(&r), [23, 23, 1, 0, 1]);
    assert!(r["redundancies"].as_array().unwrap().is_empty());
    let m = &r["free_motions"][0]["bodies"];
    let l = 2f64.sqrt() * 100.0; // model size (bounding-box diagonal) scaling the angular rates
    let expect = [
        (1, "rotation", [0.0, 0.0, 1.0], Some([100.0, 0.0, 0.0]), 1.0),
        (2, "translation", [1.0, 0.0, 0.0], None, 100.0 / l),
        (3, "rotation", [0.0, 0.0, 1.0], Some([0.0, 0.0, 0.0]), 1.0),
    ];
    assert_eq!(m.as_array().unwrap().len(), 3);
    for (got, (body, motion, dir, point, rate)) in m.as_array().unwrap().iter().zip(expect) {
        assert_eq!(got["body"], body);
        assert_eq!(got["motion"], motion);
        for k in 0..3 {
            assert!((got["direction"][k].as_f64().unwrap() - dir[k]).abs() < 1e-12);
            if let Some(p) = point {
                assert!((got["point"][k].as_f64().unwrap() - p[k]).abs() < 1e-9, "{got}");
            }
        }
        assert!((got["share"].as_f64().unwrap().abs() - rate).abs() < 1e-12, "{got}");
    }
}

/// Too few constraints. A bar on one revolute joint to the clamped bar: mobility 1, the
/// rotation about the joint axis through the joint. R-R-S-S (16 constraints, Grübler–Kutzbach
/// 2): the four-bar motion plus the last bar's spin about the line through its two spherical
/// joints (x = 0, z = 0), named as a motion of that bar alone.
#[test]
fn too_few_constraints_name_the_free_motion() {
    let r = run(&pendulum());
    assert_eq!(counts(&r), [11, 11, 1, 0, 1]);
    assert_eq!(
        texts(&r, "free_motions"),
        ["body 1 (nodes 2, 3; elements[1]) rotation about [0, 0, 1] through [100, 0, 0]"]
    );

    let r = run(&parallelogram([revolute(), revolute(), spherical(), spherical()]));
    assert_eq!(counts(&r), [22, 22, 2, 0, 2]);
    assert_eq!(
        texts(&r, "free_motions")[1],
        "body 3 (nodes 6, 7; elements[3]) rotation about [0, 1, 0] through [0, 50, 0]"
    );
}

/// R-R-S-U with the universal joint's second pin along the S–U line: Grübler–Kutzbach 1 again,
/// but the bar spins about that line (mobility 2) and one constraint is redundant
/// (1 = 2 − 1): the count alone cannot tell.
#[test]
fn universal_pin_along_the_bar_is_a_singular_choice() {
    let r = run(&rrsu([0.0, 1.0, 0.0]));
    assert_eq!(counts(&r), [23, 22, 1, 1, 2]);
    assert_eq!(r["redundancies"][0]["path"], "elements[7]");
}

/// Prescribed displacements are drives: the crank rotation prescribed (about z, in the frame
/// of the crank's revolute joint, whose local x is its axis) takes the mobility of R-R-S-U to
/// 0; with `"drives": false` it is 1 again.
#[test]
fn prescribed_displacements_count_as_drives() {
    let mut c = rrsu([1.0, 0.0, 0.0]);
    c["load_cases"] = json!([{"name": "crank", "displacements": [{"node": 3, "dof": "rx", "value": 0.5, "frame": [[0, 0, 1], [0, 1, 0], [-1, 0, 0]]}]}]);
    assert_eq!(counts(&run(&c)), [24, 24, 0, 0, 0]);
    c["drives"] = json!(false);
    assert_eq!(counts(&run(&c)), [23, 23, 1, 0, 1]);
}

/// A beam listed as compliant joins nothing: the coupler of the revolute parallelogram taken
/// compliant opens the loop into two open chains of two revolute joints each, and a free node
/// at each coupler end (a body with only a revolute joint): 5 bodies, mobility 4, no
/// redundancy.
#[test]
fn a_compliant_element_opens_the_loop() {
    let mut c = rrrr();
    c["compliant"] = json!([2]);
    let r = run(&c);
    assert_eq!(r["bodies"], 5);
    assert_eq!(counts(&r), [26, 26, 4, 0, 4]);
}

/// The bundled notch-hinge parallelogram guide: with its hinges seen as revolute joints about
/// their compliant axes, the planar four-bar's 3 redundancies and the guided translation along
/// x of the platform (body of nodes 3, 7, 8); with the hinges rigid (default), one body on two
/// clamps: 6 redundant, no free motion.
#[test]
fn notch_hinge_guide_is_over_constrained_like_the_four_bar() {
    let case = common::root().join("cases/constraints_parallelogram_guide.json");
    let parsed = flexfem::analysis::load(&case).unwrap();
    let r = flexfem::analysis::run(&parsed).unwrap().json;
    assert_eq!(counts(&r), [32, 29, -2, 3, 1]);
    let platform = r["free_motions"][0]["bodies"]
        .as_array()
        .unwrap()
        .iter()
        .find(|b| b["motion"] == "translation")
        .expect("a translating body")
        .clone();
    assert_eq!(
        r["body_list"][platform["body"].as_u64().unwrap() as usize]["nodes"],
        json!([3, 7, 8])
    );
    assert_eq!(platform["direction"], json!([1.0, 0.0, 0.0]));

    let mut v: Value = serde_json::from_str(&std::fs::read_to_string(&case).unwrap()).unwrap();
    v.as_object_mut().unwrap().remove("hinges");
    let parsed = flexfem::analysis::parse_value(v, case.parent()).unwrap();
    let r = flexfem::analysis::run(&parsed).unwrap().json;
    assert_eq!(counts(&r), [12, 6, -6, 6, 0]);
}

/// A static solve that fails as a mechanism says what moves, in body terms.
#[test]
fn singular_static_solve_carries_the_diagnosis() {
    let mut c = pendulum();
    c["analysis"] = json!("static");
    c["load_cases"] = json!([{"name": "push", "forces": [{"node": 3, "F": [1, 0, 0, 0, 0, 0]}]}]);
    let o = run_case_text("exact-static", &c.to_string());
    assert_eq!(o.status.code(), Some(1));
    let err = stderr(&o);
    assert!(err.contains("stiffness matrix is singular"), "{err}");
    assert!(
        err.contains("1 free motion, 0 redundant constraints; free: body 1 (nodes 2, 3; elements[1]) rotation about [0, 0, 1] through [100, 0, 0]"),
        "{err}"
    );
}

/// A `compliant` entry that is not a beam, hinge, shell4 or shell9 element is refused with its
/// path.
#[test]
fn compliant_must_name_a_deformable_element() {
    for (bad, why) in [(9, "no such element"), (5, "only beam, hinge, shell4 and shell9")] {
        let mut c = rrrr();
        c["compliant"] = json!([bad]);
        let o = run_case_text("exact-compliant", &c.to_string());
        assert_eq!(o.status.code(), Some(2));
        let err = stderr(&o);
        assert!(err.contains("compliant[0]") && err.contains(why), "{err}");
    }
}
