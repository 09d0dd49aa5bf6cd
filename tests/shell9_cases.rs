//! The nine-node shell through case files: the bundled cases against Leissa's and Timoshenko's
//! plate values, a Gmsh nine-node quadrangle mesh against the same model written as JSON, an
//! edge load on a nine-node edge (membrane patch test), and the refusals (curved, repeated
//! nodes, a beam section, buckling, nonlinear statics, an edge load on half an edge) with their
//! JSON paths.

use serde_json::{json, Value};

mod common;
use common::*;

fn run_value(case: Value) -> Value {
    let c = flexfem::analysis::parse_value(case, None).expect("valid case");
    flexfem::analysis::run(&c).expect("analysis runs").json
}

fn mesh() -> Value {
    serde_json::from_slice(&std::fs::read(root().join("meshes/plate_shell9_clamped.json")).unwrap()).unwrap()
}

/// Al 7075 as built in: E 72000 MPa, ν 0.33, ρ 2.81e-9 t/mm³; t = 1, a = 100.
fn plate_d() -> f64 {
    72_000.0 / (12.0 * (1.0 - 0.33 * 0.33))
}

/// `cases/static_plate_shell9_pressure.json` (clamped square plate a = 100, t = 1, q = 0.01 MPa,
/// 8×8 nine-node shells): centre deflection against the thin-plate 0.0012653 q a⁴/D
/// (Timoshenko & Woinowsky-Krieger 1959, Table 35). Measured +0.26 % (the Reissner–Mindlin
/// shift at a/t = 100 is ≈ +0.2 %). `cases/modal_plate_shell9.json`: λ₁ = ωa²√(ρt/D) against
/// Leissa's 35.992 (NASA SP-160, Table 4.23), measured −0.12 % (a/t = 100: the Mindlin plate
/// is slightly softer).
#[test]
fn bundled_shell9_cases_match_the_plate_references() {
    let (dir, r) = run_out("cases/static_plate_shell9_pressure.json", "shell9_static");
    let w = -r["load_cases"][0]["displacements"][8 * 17 + 8][2].as_f64().unwrap();
    let c = w / (0.01 * 1e8 / plate_d());
    let err = c / 0.0012653 - 1.0;
    eprintln!("shell9 case: w = {c:.7} q a^4/D ({:+.2} %)", 100.0 * err);
    assert!(err.abs() < 0.003, "w = {c} q a^4/D");
    let notes = r["model"].to_string();
    assert!(notes.contains("9-node flat shell"), "{notes}");
    cleanup(&dir);
    let (dir, r) = run_out("cases/modal_plate_shell9.json", "shell9_modal");
    let f1 = r["modes"][0]["frequency_hz"].as_f64().unwrap();
    let lam = 2.0 * std::f64::consts::PI * f1 * 1e4 * (2.81e-9 / plate_d()).sqrt();
    let err = lam / 35.992 - 1.0;
    eprintln!("shell9 case: λ1 = {lam:.4} ({:+.2} %)", 100.0 * err);
    assert!(err.abs() < 0.002, "λ1 = {lam}");
    cleanup(&dir);
}

/// `cases/gmsh_plate_quad9.json` reads `meshes/plate_clamped_quad9.msh` (8×8 nine-node
/// quadrangles, edge lines as three-node lines) into `shell9` elements: its displacements equal
/// those of the same model given as JSON (`meshes/plate_shell9_clamped.json`, the same node
/// numbering) to round-off.
#[test]
fn gmsh_nine_node_quadrangles_are_shell9() {
    let (dir, g) = run_out("cases/gmsh_plate_quad9.json", "shell9_gmsh");
    let mut m = mesh();
    m["analysis"] = json!("static");
    m["load_cases"] = json!([{"name": "centre", "forces": [{"node": 144, "F": [0, 0, -100, 0, 0, 0]}]}]);
    let j = run_value(m);
    let (a, b) = (
        &g["load_cases"][0]["displacements"],
        &j["load_cases"][0]["displacements"],
    );
    let wc = b[144][2].as_f64().unwrap();
    assert!(wc < 0.0, "centre moves down: {wc}");
    let mut worst: f64 = 0.0;
    assert_eq!(a.as_array().unwrap().len(), b.as_array().unwrap().len());
    for (ra, rb) in a.as_array().unwrap().iter().zip(b.as_array().unwrap()) {
        for k in 0..6 {
            worst = worst.max((ra[k].as_f64().unwrap() - rb[k].as_f64().unwrap()).abs());
        }
    }
    assert_eq!(a.as_array().unwrap().len(), 289);
    assert!(
        worst <= 1e-12 * wc.abs() * 1e3,
        "Gmsh and JSON models differ by {worst:e}"
    );
    cleanup(&dir);
}

/// A small static case with one nine-node shell (clamped along one edge) for the refusals.
fn one_panel(nodes: Vec<[f64; 3]>) -> Value {
    let supports: Vec<Value> = [0, 3, 7]
        .iter()
        .map(|&n| json!({"node": n, "fix": ["ux", "uy", "uz", "rx", "ry", "rz"]}))
        .collect();
    json!({
        "analysis": "static",
        "materials": {"al": "Al7075"},
        "sections": {"plate": {"shape": "shell", "t": 1.0}, "bar": {"shape": "rect", "w": 1.0, "h": 1.0}},
        "nodes": nodes,
        "elements": [{"type": "shell9", "nodes": [0, 1, 2, 3, 4, 5, 6, 7, 8], "section": "plate", "material": "al"}],
        "supports": supports,
        "load_cases": [{"name": "tip", "forces": [{"node": 5, "F": [0, 0, -1, 0, 0, 0]}]}]
    })
}

fn flat() -> Vec<[f64; 3]> {
    let p = |x: f64, y: f64| [x, y, 0.0];
    vec![
        p(0., 0.),
        p(20., 0.),
        p(20., 20.),
        p(0., 20.),
        p(10., 0.),
        p(20., 10.),
        p(10., 20.),
        p(0., 10.),
        p(10., 10.),
    ]
}

fn refused(name: &str, case: &Value, needles: &[&str]) {
    let o = run_case_text(name, &serde_json::to_string_pretty(case).unwrap());
    exits_2(&o, needles);
}

#[test]
fn shell9_refusals_name_the_json_path() {
    // The flat panel runs.
    let o = run_case_text("shell9_ok", &one_panel(flat()).to_string());
    assert!(o.status.success(), "{}", stderr(&o));
    // Curved: the edge midpoints 1 mm off the corners' plane (a cylinder of radius 50).
    let r = 50.0;
    let curved: Vec<[f64; 3]> = flat()
        .into_iter()
        .map(|p| {
            let a = (p[0] - 10.0) / r;
            [10.0 + r * a.sin(), p[1], r * (1.0 - a.cos())]
        })
        .collect();
    refused(
        "shell9_curved",
        &one_panel(curved),
        &["`elements[0].nodes`", "flat element", "four-node shells"],
    );
    // Repeated nodes.
    let mut c = one_panel(flat());
    c["elements"][0]["nodes"][8] = json!(4);
    refused("shell9_repeated", &c, &["`elements[0].nodes`", "nine different nodes"]);
    // A beam section.
    let mut c = one_panel(flat());
    c["elements"][0]["section"] = json!("bar");
    refused(
        "shell9_section",
        &c,
        &["`elements[0]", "shell9 needs a section", "\"shell\""],
    );
    // Folded order (two midpoints swapped).
    let mut c = one_panel(flat());
    c["elements"][0]["nodes"] = json!([0, 1, 2, 3, 5, 4, 6, 7, 8]);
    refused(
        "shell9_folded",
        &c,
        &["`elements[0].nodes`", "do not form a valid quadrilateral"],
    );
    // Buckling and nonlinear statics have no nine-node shell.
    let mut c = one_panel(flat());
    c["analysis"] = json!("buckling");
    c["modes"] = json!(1);
    refused("shell9_buckling", &c, &["`elements[0]`", "shell9", "linear buckling"]);
    let mut c = one_panel(flat());
    c["nonlinear"] = json!(true);
    refused(
        "shell9_nonlinear",
        &c,
        &["`elements[0]`", "shell9", "geometrically nonlinear statics"],
    );
    let d = tempdir("shell9_nonlinear_check");
    let p = write(&d, "case.json", &c.to_string());
    exits_2(
        &run_in(&d, &["check", p.to_str().unwrap()]),
        &["`elements[0]`", "shell9"],
    );
    cleanup(&d);
    // An edge load names two corners of an edge, not a corner and a midpoint.
    let mut c = one_panel(flat());
    c["load_cases"][0]["edge_loads"] = json!([{"nodes": [1, 5], "q": [0, 0, -0.1]}]);
    refused(
        "shell9_edge_load",
        &c,
        &["edge_loads[0].nodes", "two corners of one edge of a shell9 element"],
    );
}

/// An edge load on a nine-node shell's edge is spread by the edge's quadratic shape functions
/// (ends L/6, midpoint 2L/3): a membrane patch test. The 20 × 20 × 1 panel, its edge x = 0 held
/// in ux (and the corner at the origin in uy; every node in uz, rx, ry), pulled by q = 2 N/mm
/// along its edge x = 20: the exact plane-stress field ux = q·x/(E·t), uy = −ν·q·y/(E·t) at every
/// node to 1e-9, and the reaction −q·L. (The split of a two-node edge, q·L/2 at each corner and
/// nothing at the midpoint, gives the loaded corners 2.26 times the exact ux and the midpoint
/// 0.37 times: measured.)
#[test]
fn edge_load_on_a_nine_node_edge_passes_the_membrane_patch_test() {
    let mut c = one_panel(flat());
    let (q, e, nu, t) = (2.0, 72_000.0, 0.33, 1.0);
    let x = flat();
    let mut supports = Vec::new();
    for (k, p) in x.iter().enumerate() {
        let mut fix = vec!["uz", "rx", "ry"];
        if p[0] == 0.0 {
            fix.push("ux");
        }
        if k == 0 {
            fix.push("uy");
        }
        supports.push(json!({"node": k, "fix": fix}));
    }
    c["supports"] = json!(supports);
    c["load_cases"] = json!([{"name": "pull", "edge_loads": [{"nodes": [1, 2], "q": [q, 0, 0]}]}]);
    let r = run_value(c);
    let u = &r["load_cases"][0]["displacements"];
    let scale = q * 20.0 / (e * t);
    for (k, p) in x.iter().enumerate() {
        let want = [q * p[0] / (e * t), -nu * q * p[1] / (e * t)];
        for (d, w) in want.iter().enumerate() {
            let got = u[k][d].as_f64().unwrap();
            assert!((got - w).abs() < 1e-9 * scale, "node {k} dof {d}: {got} vs {w}");
        }
    }
    let fx = r["load_cases"][0]["total_reaction"][0].as_f64().unwrap();
    assert!((fx + q * 20.0).abs() < 1e-9 * q * 20.0, "reaction {fx}");
}

/// A static run of a model with nine-node shells has no `shell_stress.recovered` (patch recovery
/// of the four-node shell's Gauss points), not a recovery of part of the model, and the model
/// notes say so.
#[test]
fn no_patch_recovery_with_nine_node_shells() {
    let r = run_value(one_panel(flat()));
    let ss = &r["load_cases"][0]["shell_stress"];
    assert!(ss["top"].is_array() && ss.get("recovered").is_none(), "{ss}");
    assert!(r["model"].to_string().contains("no `shell_stress.recovered`"));
}

/// A nine-node shell whose node order runs against its four-node neighbours' is named in the
/// orientation warning: the edges are compared by halves (corner to midpoint), so a nine-node
/// shell meets a four-node one on a half edge.
#[test]
fn opposite_normals_of_a_nine_node_and_a_four_node_shell_are_named() {
    let mut c = one_panel(flat());
    // Two four-node shells along the nine-node panel's right edge (x = 20): nodes 1, 5, 2 shared.
    for p in [[30.0, 0.0, 0.0], [30.0, 10.0, 0.0], [30.0, 20.0, 0.0]] {
        c["nodes"].as_array_mut().unwrap().push(json!(p));
    }
    let quad = |n: [usize; 4]| json!({"type": "shell4", "nodes": n, "section": "plate", "material": "al"});
    c["elements"].as_array_mut().unwrap().push(quad([1, 9, 10, 5]));
    c["elements"].as_array_mut().unwrap().push(quad([5, 10, 11, 2]));
    let r = run_value(c.clone());
    assert_eq!(r["warnings"].as_array().unwrap().len(), 0, "{}", r["warnings"]);
    // The nine-node panel reversed (corners 0 3 2 1): its normal points the other way.
    c["elements"][0]["nodes"] = json!([0, 3, 2, 1, 7, 6, 5, 4, 8]);
    let r = run_value(c);
    let w = r["warnings"].to_string();
    assert!(w.contains("elements 0 and 1 along nodes 5–1"), "{w}");
}

/// A `group_forces` entry on a Gmsh group of nine-node quadrangles is refused with what to do
/// instead (such a group has no first-order cells to spread the force over).
#[test]
fn group_force_on_a_second_order_group_says_why() {
    let mut c: Value =
        serde_json::from_slice(&std::fs::read(root().join("cases/gmsh_plate_quad9.json")).unwrap()).unwrap();
    c["mesh"] = json!(root().join("meshes/plate_clamped_quad9.msh").to_str().unwrap());
    c["load_cases"][0]["group_forces"] = json!([{"group": "plate", "F": [0, 0, -100, 0, 0, 0]}]);
    let o = run_case_text("shell9_group_force", &c.to_string());
    exits_2(&o, &["group_forces[0].group", "second-order", "pressures"]);
}
