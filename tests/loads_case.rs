//! The load-case keys `gravity`, `line_loads` and `group_forces` through the CLI: a Gmsh line
//! group loaded by a total force against the closed-form membrane stretch F·L/(E·B·t), and
//! input errors that name their JSON path (exit 2).

mod common;

use common::{run_case_text, run_in, stderr, tempdir};

/// Two 50 × 20 quads (plate 100 × 20, t = 1, Al7075) with the physical groups "plate"
/// (surface), "root" (line x = 0), "tip" (line x = 100) and "corner" (point at the origin).
const PLATE_MSH: &str = "$MeshFormat\n4.1 0 8\n$EndMeshFormat\n\
$PhysicalNames\n4\n0 1 \"corner\"\n1 2 \"root\"\n1 3 \"tip\"\n2 4 \"plate\"\n$EndPhysicalNames\n\
$Entities\n1 2 1 0\n1 0 0 0 1 1\n1 0 0 0 0 20 0 1 2 0\n2 100 0 0 100 20 0 1 3 0\n1 0 0 0 100 20 0 1 4 0\n$EndEntities\n\
$Nodes\n1 6 1 6\n2 1 0 6\n1\n2\n3\n4\n5\n6\n0 0 0\n50 0 0\n100 0 0\n0 20 0\n50 20 0\n100 20 0\n$EndNodes\n\
$Elements\n4 5 1 5\n0 1 15 1\n1 1\n1 1 1 1\n2 1 4\n1 2 1 1\n3 3 6\n2 1 3 2\n4 1 2 5 4\n5 2 3 6 5\n$EndElements\n";

fn plate_case(group_forces: &str) -> String {
    format!(
        r#"{{"analysis": "static", "mesh": "m.msh",
  "gmsh": {{"groups": {{"plate": {{"section": "s", "material": "al", "fix": ["uz", "rx", "ry"]}},
                       "root": {{"fix": ["ux"]}}, "corner": {{"fix": ["uy"]}}, "tip": {{}}}}}},
  "materials": {{"al": "Al7075"}},
  "sections": {{"s": {{"shape": "shell", "t": 1}}}},
  "load_cases": [{{"name": "pull", "group_forces": {group_forces}}}]}}"#
    )
}

fn run_plate(name: &str, group_forces: &str) -> (std::process::Output, std::path::PathBuf) {
    let d = tempdir(name);
    std::fs::write(d.join("m.msh"), PLATE_MSH).unwrap();
    std::fs::write(d.join("case.json"), plate_case(group_forces)).unwrap();
    (run_in(&d, &["run", "case.json", "--out", "out"]), d)
}

/// A total force of 100 N on the Gmsh line group "tip", spread by tributary length: uniform
/// stress, so both tip nodes move F·L/(E·B·t) = 100·100/(72000·20·1) (closed form of a bar in
/// tension, reproduced exactly by the membrane: 1e-9).
#[test]
fn gmsh_group_force_stretches_the_plate() {
    let (o, d) = run_plate("loads_group_msh", r#"[{"group": "tip", "F": [100, 0, 0, 0, 0, 0]}]"#);
    assert_eq!(o.status.code(), Some(0), "{}", stderr(&o));
    let r: serde_json::Value =
        serde_json::from_str(&std::fs::read_to_string(d.join("out/result.json")).unwrap()).unwrap();
    let disp = &r["load_cases"][0]["displacements"];
    let exact = 100.0 * 100.0 / (72000.0 * 20.0);
    for n in [2, 5] {
        let u = disp[n][0].as_f64().unwrap();
        assert!((u - exact).abs() < 1e-9 * exact, "node {n}: {u} vs {exact}");
    }
}

/// An unknown group names `load_cases[0].group_forces[0].group`.
#[test]
fn unknown_group_is_named() {
    let (o, _) = run_plate("loads_group_unknown", r#"[{"group": "tipp", "F": [1, 0, 0, 0, 0, 0]}]"#);
    assert_eq!(o.status.code(), Some(2), "{}", stderr(&o));
    assert!(
        stderr(&o).contains("load_cases[0].group_forces[0].group"),
        "{}",
        stderr(&o)
    );
}

const BEAM: &str = r#""analysis": "static",
  "materials": {"steel": "steel"},
  "sections": {"bar": {"shape": "rect", "w": 10, "h": 5}},
  "nodes": [[0, 0, 0], [100, 0, 0]],
  "elements": [
    {"type": "beam", "nodes": [0, 1], "section": "bar", "material": "steel", "up": [0, 0, 1]},
    {"type": "spring", "nodes": [1], "k": [1, 1, 1, 1, 1, 1]}
  ],
  "supports": [{"node": 0, "fix": ["ux", "uy", "uz", "rx", "ry", "rz"]}],"#;

fn beam_error(name: &str, case: &str) -> String {
    let o = run_case_text(name, &format!("{{{BEAM} \"load_cases\": [{case}]}}"));
    assert_eq!(o.status.code(), Some(2), "{}", stderr(&o));
    stderr(&o)
}

/// Line loads on a non-beam or a missing element, group forces with both or neither of
/// `group`/`nodes`, a node out of range, a group without a .msh mesh: exit 2 naming the path.
#[test]
fn load_errors_name_the_path() {
    for (name, case, path) in [
        (
            "ll_spring",
            r#"{"name": "a", "line_loads": [{"element": 1, "q": [0, 0, -1]}]}"#,
            "load_cases[0].line_loads[0].element",
        ),
        (
            "ll_missing",
            r#"{"name": "a", "line_loads": [{"element": 5, "q": [0, 0, -1], "axes": "local"}]}"#,
            "load_cases[0].line_loads[0].element",
        ),
        (
            "gf_neither",
            r#"{"name": "a", "group_forces": [{"F": [0, 0, -1, 0, 0, 0]}]}"#,
            "load_cases[0].group_forces[0]",
        ),
        (
            "gf_node",
            r#"{"name": "a", "group_forces": [{"nodes": [1, 7], "F": [0, 0, -1, 0, 0, 0]}]}"#,
            "load_cases[0].group_forces[0].nodes[1]",
        ),
        (
            "gf_group",
            r#"{"name": "a", "group_forces": [{"group": "tip", "F": [0, 0, -1, 0, 0, 0]}]}"#,
            "load_cases[0].group_forces[0].group",
        ),
    ] {
        let err = beam_error(&format!("loads_err_{name}"), case);
        assert!(err.contains(path), "{name}: {err}");
    }
}

/// Gravity on a model without mass is refused at `load_cases[0].gravity` (it would silently
/// load nothing).
#[test]
fn gravity_without_mass_is_refused() {
    let text = BEAM.replace(
        r#""steel": "steel""#,
        r#""steel": {"E": 210000, "nu": 0.3, "density": 0}"#,
    );
    let o = run_case_text(
        "loads_err_massless",
        &format!("{{{text} \"load_cases\": [{{\"name\": \"g\", \"gravity\": [0, 0, -9810]}}]}}"),
    );
    assert_eq!(o.status.code(), Some(2), "{}", stderr(&o));
    assert!(stderr(&o).contains("load_cases[0].gravity"), "{}", stderr(&o));
}

/// The bundled cases/static_self_weight.json against closed forms (steel, L = 100, 10 × 5
/// rectangle with h = 5 along z, I = 10·5³/12, Euler–Bernoulli, exact at the nodes: 1e-9):
/// self-weight q = ρ·A·g: tip qL⁴/(8EI), root force qL and moment qL²/2; line load 0.1 N/mm:
/// tip qL⁴/(8EI); 1 N spread equally over nodes 3 (x = 75) and 4 (x = 100): tip
/// 0.5·(75²(3L − 75) + 2L³)/(6EI).
#[test]
fn bundled_self_weight_case_matches_closed_forms() {
    let d = tempdir("loads_bundled");
    let case = common::root().join("cases/static_self_weight.json");
    let o = run_in(&d, &["run", case.to_str().unwrap(), "--out", "out"]);
    assert_eq!(o.status.code(), Some(0), "{}", stderr(&o));
    let r: serde_json::Value =
        serde_json::from_str(&std::fs::read_to_string(d.join("out/result.json")).unwrap()).unwrap();
    let (l, e, i) = (100.0f64, 210_000.0, 10.0 * 125.0 / 12.0);
    let q = 7.85e-9 * 50.0 * 9810.0;
    let tip = |c: usize| -r["load_cases"][c]["displacements"][4][2].as_f64().unwrap();
    let reac = |c: usize, k: usize| r["load_cases"][c]["reactions"][0][k].as_f64().unwrap();
    let close = |a: f64, b: f64| (a - b).abs() <= 1e-9 * b.abs();
    assert!(close(tip(0), q * l.powi(4) / (8.0 * e * i)), "{}", tip(0));
    assert!(close(reac(0, 2), q * l), "{}", reac(0, 2));
    assert!(close(reac(0, 4), -q * l * l / 2.0), "{}", reac(0, 4));
    assert!(close(tip(1), 0.1 * l.powi(4) / (8.0 * e * i)), "{}", tip(1));
    let exact = 0.5 * (75.0f64.powi(2) * (3.0 * l - 75.0) + 2.0 * l.powi(3)) / (6.0 * e * i);
    assert!(close(tip(2), exact), "{} vs {exact}", tip(2));
}
