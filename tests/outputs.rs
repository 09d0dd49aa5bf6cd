//! Output files and units: `.vtu` files (undeformed points, point data named with units, VTK
//! cell types, the stage's platform/sliders/rigid links), degrees for every angle read or
//! written, unique load-case names, CSV headers with units, and every bundled case run with
//! `--out DIR` and `--format md`. Runs the real binary on bundled and inline cases.

mod common;
use common::*;
use serde_json::Value;
use std::path::{Path, PathBuf};

/// A `.vtu` file read back: counts, points, cells and named data arrays.
struct Vtu {
    points: Vec<[f64; 3]>,
    connectivity: Vec<usize>,
    offsets: Vec<usize>,
    types: Vec<u8>,
    text: String,
}

impl Vtu {
    fn read(path: &Path) -> Vtu {
        let text = std::fs::read_to_string(path).unwrap_or_else(|e| panic!("{}: {e}", path.display()));
        assert!(
            text.starts_with("<?xml") && text.trim_end().ends_with("</VTKFile>"),
            "{}: not a complete VTK XML file",
            path.display()
        );
        let np = attr(&text, "NumberOfPoints");
        let nc = attr(&text, "NumberOfCells");
        let p = numbers(&text, "Points");
        assert_eq!(p.len(), 3 * np, "{}: point coordinates", path.display());
        let points = p.chunks(3).map(|c| [c[0], c[1], c[2]]).collect();
        let ints = |name| numbers(&text, name).iter().map(|v| *v as usize).collect::<Vec<_>>();
        let v = Vtu {
            points,
            connectivity: ints("connectivity"),
            offsets: ints("offsets"),
            types: numbers(&text, "types").iter().map(|v| *v as u8).collect(),
            text,
        };
        assert_eq!(v.offsets.len(), nc, "{}: offsets", path.display());
        assert_eq!(v.types.len(), nc, "{}: types", path.display());
        assert_eq!(v.offsets.last().copied().unwrap_or(0), v.connectivity.len());
        for (i, t) in v.types.iter().enumerate() {
            let n = v.cell(i).len();
            let expect = match t {
                3 => 2,
                5 => 3,
                9 => 4,
                _ => panic!("{}: cell type {t} is not line/triangle/quad", path.display()),
            };
            assert_eq!(n, expect, "{}: cell {i} of type {t} has {n} points", path.display());
            let c = v.cell(i);
            assert!(c.iter().all(|&k| k < np), "{}: cell {i} {c:?}", path.display());
            for a in 0..n {
                for b in 0..a {
                    assert_ne!(c[a], c[b], "{}: degenerate cell {i} {c:?}", path.display());
                }
            }
        }
        v
    }

    fn cell(&self, i: usize) -> &[usize] {
        let start = if i == 0 { 0 } else { self.offsets[i - 1] };
        &self.connectivity[start..self.offsets[i]]
    }

    /// A 3-component point array, one row per point.
    fn vectors(&self, name: &str) -> Vec<[f64; 3]> {
        let v = numbers(&self.text, name);
        assert_eq!(v.len(), 3 * self.points.len(), "{name}: one vector per point");
        v.chunks(3).map(|c| [c[0], c[1], c[2]]).collect()
    }

    /// A scalar cell array.
    fn cell_scalars(&self, name: &str) -> Vec<f64> {
        let v = numbers(&self.text, name);
        assert_eq!(v.len(), self.types.len(), "{name}: one value per cell");
        v
    }

    fn has(&self, name: &str) -> bool {
        self.text.contains(&format!("Name=\"{name}\""))
    }
}

fn attr(text: &str, name: &str) -> usize {
    let key = format!("{name}=\"");
    let i = text.find(&key).unwrap_or_else(|| panic!("no {name}")) + key.len();
    text[i..].split('"').next().unwrap().parse().unwrap()
}

/// The numbers of the DataArray named `name`.
fn numbers(text: &str, name: &str) -> Vec<f64> {
    let key = format!("Name=\"{name}\"");
    let i = text.find(&key).unwrap_or_else(|| panic!("no DataArray {name}"));
    let body = &text[i..];
    let start = body.find('>').unwrap() + 1;
    let end = body.find("</DataArray>").unwrap();
    body[start..end]
        .split_whitespace()
        .map(|s| s.parse().unwrap_or_else(|_| panic!("{name}: {s} is not a number")))
        .collect()
}

/// Runs `flexfem run CASE --out DIR` (case given as a path) and returns DIR.
fn run_out(name: &str, case: &Path) -> PathBuf {
    let d = tempdir(name);
    let out = run_in(&d, &["run", case.to_str().unwrap(), "--out", "o"]);
    assert_eq!(out.status.code(), Some(0), "{}: {}", case.display(), stderr(&out));
    d.join("o")
}

/// Writes `text` as `case.json` in a temp dir, runs it with `--out`, returns the output dir.
fn run_text_out(name: &str, text: &str) -> PathBuf {
    let d = tempdir(&format!("{name}_case"));
    let p = d.join("case.json");
    std::fs::write(&p, text).unwrap();
    run_out(name, &p)
}

fn json_file(p: &Path) -> Value {
    serde_json::from_str(&std::fs::read_to_string(p).unwrap()).unwrap()
}

fn f(v: &Value) -> f64 {
    v.as_f64().unwrap_or_else(|| panic!("not a number: {v}"))
}

fn close(a: f64, b: f64, rel: f64, what: &str) {
    assert!(
        (a - b).abs() <= rel * b.abs().max(1e-300),
        "{what}: {a} vs {b} (rel. tol. {rel})"
    );
}

/// The points of a static `.vtu` are the case's undeformed node coordinates; displacements
/// (mm) and rotations (degrees) are point data equal to the JSON result, whose tip values match
/// the Euler–Bernoulli cantilever: δ = PL³/(3EI), θ = PL²/(2EI) (Gere & Timoshenko, Mechanics
/// of Materials, App. G, case 1).
#[test]
fn static_vtu_points_are_undeformed_with_unit_named_point_data() {
    let case = root().join("cases/static_cantilever.json");
    let dir = run_out("static_vtu", &case);
    let vtu = Vtu::read(&dir.join("tip.vtu"));
    let nodes = json_file(&case)["nodes"].as_array().unwrap().clone();
    assert_eq!(vtu.points.len(), nodes.len());
    for (p, n) in vtu.points.iter().zip(&nodes) {
        for k in 0..3 {
            assert_eq!(p[k], f(&n[k]), "point {p:?} is not the node {n}");
        }
    }
    assert!(vtu.has("displacement_mm") && vtu.has("rotation_deg") && vtu.has("von_mises_MPa"));
    assert!(
        !vtu.has("displacement") && !vtu.has("rotation"),
        "unit-less array names"
    );
    let res = json_file(&dir.join("result.json"));
    let rows = res["load_cases"][0]["displacements"].as_array().unwrap();
    let (u, r) = (vtu.vectors("displacement_mm"), vtu.vectors("rotation_deg"));
    for (i, row) in rows.iter().enumerate() {
        for k in 0..3 {
            assert!((u[i][k] - f(&row[k])).abs() <= 1e-12 * (1.0 + f(&row[k]).abs()));
            assert!((r[i][k] - f(&row[k + 3])).abs() <= 1e-12 * (1.0 + f(&row[k + 3]).abs()));
        }
    }
    let ei = 72_000.0 * 10f64.powi(4) / 12.0;
    let (p, l) = (10.0, 100.0_f64);
    close(u[2][2], -p * l.powi(3) / (3.0 * ei), 1e-9, "tip uz (mm)");
    close(r[2][1], (p * l * l / (2.0 * ei)).to_degrees(), 1e-9, "tip ry (deg)");
}

/// A prescribed rotation in a case file is in degrees. Clamped Euler–Bernoulli cantilever,
/// L = 100 mm, 10×10 mm Al 7075 (EI = 6·10⁷ N·mm²), end rotation θ = 1° prescribed:
/// with the end free to translate the beam bends uniformly, M = EIθ/L at the root and the end
/// deflects θL/2; with the end also held (uz = 0) the root carries M = 2EIθ/L and shear
/// V = 6EIθ/L² (slope-deflection equations, e.g. Hibbeler, Structural Analysis, §11.2).
#[test]
fn prescribed_rotation_is_read_in_degrees() {
    let text = r#"{"analysis": "static",
      "materials": {"al": "Al7075"},
      "sections": {"s": {"shape": "rect", "w": 10, "h": 10}},
      "nodes": [[0, 0, 0], [50, 0, 0], [100, 0, 0]],
      "elements": [
        {"type": "beam", "nodes": [0, 1], "section": "s", "material": "al", "up": [0, 0, 1], "shear": false},
        {"type": "beam", "nodes": [1, 2], "section": "s", "material": "al", "up": [0, 0, 1], "shear": false}],
      "supports": [{"node": 0, "fix": ["ux", "uy", "uz", "rx", "ry", "rz"]}],
      "load_cases": [
        {"name": "free", "displacements": [{"node": 2, "dof": "ry", "value": 1}]},
        {"name": "held", "displacements": [{"node": 2, "dof": "ry", "value": 1}, {"node": 2, "dof": "uz", "value": 0}]}]}"#;
    let dir = run_text_out("prescribed_rotation", text);
    let res = json_file(&dir.join("result.json"));
    let ei = 72_000.0 * 10f64.powi(4) / 12.0;
    let (l, theta) = (100.0, 1f64.to_radians());
    let free = &res["load_cases"][0];
    assert_eq!(
        f(&free["displacements"][2][4]),
        1.0,
        "the prescribed rotation is echoed in degrees"
    );
    close(
        f(&free["displacements"][2][2]).abs(),
        theta * l / 2.0,
        1e-9,
        "free end deflection (mm)",
    );
    assert_eq!(free["reaction_nodes"][0], 0);
    close(
        f(&free["reactions"][0][4]).abs(),
        ei * theta / l,
        1e-9,
        "root moment, free end (N·mm)",
    );
    assert!(f(&free["reactions"][0][2]).abs() < 1e-6, "no shear with a free end");
    let held = &res["load_cases"][1];
    close(
        f(&held["reactions"][0][4]).abs(),
        2.0 * ei * theta / l,
        1e-9,
        "root moment, held end (N·mm)",
    );
    close(
        f(&held["reactions"][0][2]).abs(),
        6.0 * ei * theta / (l * l),
        1e-9,
        "root shear, held end (N)",
    );
    // The .vtu carries the same rotation in degrees.
    let vtu = Vtu::read(&dir.join("free.vtu"));
    close(vtu.vectors("rotation_deg")[2][1], 1.0, 1e-12, "rotation_deg at the end");
}

/// Mode-shape rotations are in degrees (JSON and `.vtu`). First bending mode of a clamped
/// Euler–Bernoulli cantilever, φ(x) = cosh βx − cos βx − σ(sinh βx − sin βx), β₁L = 1.8751041,
/// σ = (cosh β₁L + cos β₁L)/(sinh β₁L + sin β₁L) (Blevins, Formulas for Natural Frequency and
/// Mode Shape, Table 8-1): the tip slope over the tip deflection is φ′(L)/φ(L), so
/// |ry/uz| at the tip = φ′(L)/φ(L) · 180/π degrees per mm. 20 elements, slender (L/h = 100)
/// so rotary inertia changes the ratio by ~1e-4.
#[test]
fn mode_shape_rotations_are_in_degrees() {
    let n = 20;
    let l = 500.0;
    let nodes: Vec<String> = (0..=n)
        .map(|i| format!("[{}, 0, 0]", l * i as f64 / n as f64))
        .collect();
    let elems: Vec<String> = (0..n)
        .map(|i| {
            format!(
                r#"{{"type": "beam", "nodes": [{i}, {}], "section": "s", "material": "al", "up": [0, 0, 1], "shear": false}}"#,
                i + 1
            )
        })
        .collect();
    let text = format!(
        r#"{{"analysis": "modal", "modes": 1, "materials": {{"al": "Al7075"}},
          "sections": {{"s": {{"shape": "rect", "w": 10, "h": 5}}}},
          "nodes": [{}], "elements": [{}],
          "supports": [{{"node": 0, "fix": ["ux", "uy", "uz", "rx", "ry", "rz"]}}]}}"#,
        nodes.join(", "),
        elems.join(", ")
    );
    let dir = run_text_out("mode_degrees", &text);
    let bl: f64 = 1.875_104_068_711_961;
    let sigma = (bl.cosh() + bl.cos()) / (bl.sinh() + bl.sin());
    let phi = bl.cosh() - bl.cos() - sigma * (bl.sinh() - bl.sin());
    let dphi = (bl / l) * (bl.sinh() + bl.sin() - sigma * (bl.cosh() - bl.cos()));
    let expect = (dphi / phi).to_degrees(); // degrees per mm
    let res = json_file(&dir.join("result.json"));
    let tip = &res["modes"][0]["shape"][n];
    let ratio = (f(&tip[4]) / f(&tip[2])).abs();
    close(ratio, expect, 1e-3, "JSON |ry/uz| at the tip of mode 1 (deg/mm)");
    let vtu = Vtu::read(&dir.join("modes.vtu"));
    let t = vtu.vectors("mode_1_translation_mm");
    let r = vtu.vectors("mode_1_rotation_deg");
    close(
        (r[n][1] / t[n][2]).abs(),
        expect,
        1e-3,
        "VTU |ry/uz| at the tip of mode 1 (deg/mm)",
    );
    close(
        numbers(&vtu.text, "frequency_hz")[0],
        f(&res["modes"][0]["frequency_hz"]),
        1e-12,
        "frequency_hz field data",
    );
}

/// Shells given as triangles ([a, b, c, c]) are written as VTK triangles (type 5), not as
/// degenerate quads; quads stay type 9.
#[test]
fn triangles_are_vtk_triangles() {
    for (case, ty) in [("gmsh_plate_tris", 5u8), ("gmsh_plate_quads", 9u8)] {
        let dir = run_out(case, &root().join(format!("cases/{case}.json")));
        let vtu = Vtu::read(&dir.join("centre.vtu"));
        let part = vtu.cell_scalars("part");
        assert_eq!(vtu.types.len(), part.len());
        let shells: Vec<u8> = vtu
            .types
            .iter()
            .zip(&part)
            .filter(|(_, p)| **p == 4.0)
            .map(|(t, _)| *t)
            .collect();
        assert!(!shells.is_empty(), "{case}: no shell cells");
        assert!(shells.iter().all(|t| *t == ty), "{case}: shell cell types {shells:?}");
    }
}

/// The stage `.vtu` shows the whole stage: 3 × (revolute hinge, 4 leg beams, spherical neck)
/// = 18 element cells, 3 rigid-link lines from the platform centre to the neck tops, the
/// platform as the triangle through the neck tops and 3 slider lines (one extra point each);
/// the platform centre's displacement equals the JSON platform z.
#[test]
fn stage_vtu_shows_platform_sliders_and_rigid_links() {
    let dir = run_out("stage_vtu", &root().join("cases/ruiz2019_stage.json"));
    let vtu = Vtu::read(&dir.join("stage_F20.vtu"));
    assert_eq!(vtu.types.len(), 25);
    let part = vtu.cell_scalars("part");
    let count = |p: f64| part.iter().filter(|v| **v == p).count();
    assert_eq!(
        (count(1.0), count(2.0), count(5.0), count(6.0)),
        (12, 6, 3, 4),
        "{part:?}"
    );
    let tri: Vec<usize> = (0..part.len()).filter(|&i| vtu.types[i] == 5).collect();
    assert_eq!(tri.len(), 1, "one platform triangle");
    assert_eq!(part[tri[0]], 6.0);
    assert_eq!(vtu.types.iter().filter(|t| **t == 3).count(), 24, "the rest are lines");
    let rigid: Vec<&[usize]> = (0..part.len())
        .filter(|&i| part[i] == 5.0)
        .map(|i| vtu.cell(i))
        .collect();
    let centre = rigid[0][0];
    assert!(
        rigid.iter().all(|c| c[0] == centre),
        "rigid links from the platform centre"
    );
    let mut tops: Vec<usize> = rigid.iter().map(|c| c[1]).collect();
    let mut plate = vtu.cell(tri[0]).to_vec();
    tops.sort();
    plate.sort();
    assert_eq!(tops, plate, "the platform triangle joins the neck tops");
    let element = vtu.cell_scalars("element");
    assert!((0..part.len()).all(|i| (element[i] < 0.0) == (part[i] >= 5.0)));
    let res = json_file(&dir.join("result.json"));
    let z = f(&res["load_cases"][0]["platform"]["z"]);
    close(
        vtu.vectors("displacement_mm")[centre][2],
        z,
        1e-9,
        "platform centre uz (mm)",
    );
    // Slider lines translate with their slider: both ends have the same displacement.
    let u = vtu.vectors("displacement_mm");
    for i in (0..part.len()).filter(|&i| part[i] == 6.0 && vtu.types[i] == 3) {
        let c = vtu.cell(i);
        assert_eq!(u[c[0]], u[c[1]]);
        assert!(u[c[0]].iter().any(|v| v.abs() > 0.1), "the slider moved: {:?}", u[c[0]]);
    }
}

/// `ruiz2019_stage_nonlinear --out` writes one `.vtu` per load case (it used to exit 1 with
/// "displacement has 40 entries for 22 points": the nonlinear solve splits the hinges).
#[test]
fn nonlinear_stage_out_writes_vtu() {
    let dir = run_out("stage_nl", &root().join("cases/ruiz2019_stage_nonlinear.json"));
    let res = json_file(&dir.join("result.json"));
    for (i, name) in ["row1", "row4", "F60"].iter().enumerate() {
        let vtu = Vtu::read(&dir.join(format!("stage_{name}.vtu")));
        assert_eq!(vtu.types.len(), 25, "{name}");
        let part = vtu.cell_scalars("part");
        let centre = vtu.cell((0..part.len()).find(|&k| part[k] == 5.0).unwrap())[0];
        let z = f(&res["load_cases"][i]["platform"]["z"]);
        close(vtu.vectors("displacement_mm")[centre][2], z, 1e-9, name);
    }
}

/// A nonlinear `static` case with `--out` writes its `.vtu` (it used to write none).
#[test]
fn nonlinear_static_out_writes_vtu() {
    let text = r#"{"analysis": "static", "nonlinear": true, "steps": 5,
      "materials": {"al": "Al7075"},
      "sections": {"s": {"shape": "rect", "w": 10, "h": 10}},
      "nodes": [[0, 0, 0], [50, 0, 0], [100, 0, 0]],
      "elements": [
        {"type": "beam", "nodes": [0, 1], "section": "s", "material": "al", "up": [0, 0, 1]},
        {"type": "beam", "nodes": [1, 2], "section": "s", "material": "al", "up": [0, 0, 1]}],
      "supports": [{"node": 0, "fix": ["ux", "uy", "uz", "rx", "ry", "rz"]}],
      "load_cases": [{"name": "tip", "forces": [{"node": 2, "F": [0, 0, -1000, 0, 0, 0]}]}]}"#;
    let dir = run_text_out("nl_static", text);
    let vtu = Vtu::read(&dir.join("tip.vtu"));
    let res = json_file(&dir.join("result.json"));
    let row = &res["load_cases"][0]["displacements"][2];
    close(vtu.vectors("displacement_mm")[2][2], f(&row[2]), 1e-12, "tip uz");
    close(vtu.vectors("rotation_deg")[2][1], f(&row[4]), 1e-12, "tip ry");
    assert_eq!(vtu.points[2], [100.0, 0.0, 0.0], "undeformed point");
}

/// Two load cases with the same name (or names giving the same file name) would overwrite each
/// other's `.vtu`: refused at validation, exit 2, naming the later one's JSON path.
#[test]
fn duplicate_load_case_names_are_refused() {
    let stat = |a: &str, b: &str| {
        format!(
            r#"{{"analysis": "static", "materials": {{"al": "Al7075"}},
          "sections": {{"s": {{"shape": "rect", "w": 10, "h": 10}}}},
          "nodes": [[0, 0, 0], [100, 0, 0]],
          "elements": [{{"type": "beam", "nodes": [0, 1], "section": "s", "material": "al", "up": [0, 0, 1]}}],
          "supports": [{{"node": 0, "fix": ["ux", "uy", "uz", "rx", "ry", "rz"]}}],
          "load_cases": [{{"name": "{a}", "forces": [{{"node": 1, "F": [0, 0, 1, 0, 0, 0]}}]}},
                         {{"name": "other", "forces": [{{"node": 1, "F": [0, 1, 0, 0, 0, 0]}}]}},
                         {{"name": "{b}", "forces": [{{"node": 1, "F": [1, 0, 0, 0, 0, 0]}}]}}]}}"#
        )
    };
    let modal = stat("tip", "tip").replace("\"static\"", "\"modal\", \"modes\": 1");
    let stage: Value =
        serde_json::from_str(&std::fs::read_to_string(root().join("cases/ruiz2019_stage.json")).unwrap()).unwrap();
    let mut stage = stage;
    stage["load_cases"][2]["name"] = "F20".into();
    let texts = [
        ("static_same", stat("tip", "tip"), "same name"),
        ("static_file", stat("tip 1", "tip_1"), "tip_1.vtu"),
        ("modal_same", modal, "same name"),
        ("stage_same", stage.to_string(), "same name"),
    ];
    for (name, text, why) in texts {
        let d = tempdir(&format!("dup_{name}"));
        std::fs::write(d.join("c.json"), &text).unwrap();
        for cmd in ["check", "run"] {
            let out = run_in(&d, &[cmd, "c.json", "--out", "o"][..if cmd == "run" { 4 } else { 2 }]);
            let err = stderr(&out);
            assert_eq!(out.status.code(), Some(2), "{cmd} {name}: {err}");
            assert!(
                err.contains("`load_cases[2].name`") && err.contains(why),
                "{cmd} {name}: {err}"
            );
        }
        assert!(!d.join("o").exists(), "{name}: wrote outputs");
    }
}

/// `ruiz2019_stage_modal --out` writes the mode shapes (`modes.vtu`) and lists the
/// frequencies of the JSON result in the Markdown report and the CSV.
#[test]
fn stage_modal_writes_mode_shapes_and_reports_frequencies() {
    let dir = run_out("stage_modal", &root().join("cases/ruiz2019_stage_modal.json"));
    let res = json_file(&dir.join("result.json"));
    let modes = res["modes"].as_array().unwrap();
    assert_eq!(modes.len(), 6);
    let vtu = Vtu::read(&dir.join("modes.vtu"));
    let fz = numbers(&vtu.text, "frequency_hz");
    let md = std::fs::read_to_string(dir.join("report.md")).unwrap();
    let csv = std::fs::read_to_string(dir.join("result.csv")).unwrap();
    let header: Vec<&str> = csv.lines().next().unwrap().split(',').collect();
    let col = header.iter().position(|h| *h == "frequency_hz").unwrap();
    let rows: Vec<Vec<&str>> = csv
        .lines()
        .filter(|l| l.starts_with("mode,"))
        .map(|l| l.split(',').collect())
        .collect();
    assert_eq!(rows.len(), 6);
    for (k, m) in modes.iter().enumerate() {
        let hz = f(&m["frequency_hz"]);
        close(fz[k], hz, 1e-12, "modes.vtu frequency_hz");
        assert!(vtu.has(&format!("mode_{}_translation_mm", k + 1)));
        assert!(vtu.has(&format!("mode_{}_rotation_deg", k + 1)));
        close(rows[k][col].parse().unwrap(), hz, 1e-12, "CSV frequency_hz");
        assert!(
            md.contains(&format!("| {} | {:.2} |", k + 1, hz)),
            "report.md lacks mode {}: {md}",
            k + 1
        );
    }
    // Mode shapes on the stage: platform centre (first rigid-link master) moves in mode 1.
    let part = vtu.cell_scalars("part");
    let centre = vtu.cell((0..part.len()).find(|&k| part[k] == 5.0).unwrap())[0];
    let t = vtu.vectors("mode_1_translation_mm");
    assert!(t[centre].iter().any(|v| v.abs() > 0.0));
}

/// Units every CSV column may carry (suffix), or a dimensionless/label column.
fn has_unit(col: &str) -> bool {
    const UNITS: &[&str] = &[
        "_mm",
        "_um",
        "_deg",
        "_N",
        "_MPa",
        "_hz",
        "_Nmm_per_rad",
        "_N_per_mm",
        "_MPa_per_Nmm",
        "_s",
        "_deg_per_s",
        "_Nmm",
        "_mm_per_N",
        "_deg_per_N",
        "_mm_per_input",
        "_deg_per_input",
    ];
    const PLAIN: &[&str] = &[
        "kind",
        "name",
        "load_case",
        "node",
        "mode",
        "parameter",
        "phase",
        "T",
        "max_violation",
        "stiffness_ratio",
        "displacement_ratio",
        "stress_ratio_ratio",
        "load_factor",
        "reversed",
        "metric",
        "ratio",
        "bin",
        "elasticity",
    ];
    UNITS.iter().any(|u| col.ends_with(u)) || PLAIN.contains(&col) || col.starts_with("mef_")
}

fn bundled_cases() -> Vec<PathBuf> {
    let mut v: Vec<PathBuf> = std::fs::read_dir(root().join("cases"))
        .unwrap()
        .map(|e| e.unwrap().path())
        .filter(|p| p.extension().and_then(|e| e.to_str()) == Some("json"))
        .filter(|p| !p.file_name().unwrap().to_str().unwrap().contains("sweep")) // run with `flexfem sweep` (tests/sweep.rs)
        .collect();
    v.sort();
    v
}

/// Every bundled case (but sweeps) runs with `--out DIR --format md`: exit 0, a Markdown
/// report on stdout equal to `report.md`, `result.json`, and every `.vtu` complete and
/// consistent (points, cell types, one value per point/cell in every array, undeformed points
/// in static files). Every CSV column names its unit (or is a label or a ratio).
#[test]
fn every_bundled_case_runs_with_out_and_markdown() {
    let cases = bundled_cases();
    assert!(cases.len() >= 15);
    for case in cases {
        let stem = case.file_stem().unwrap().to_str().unwrap().to_string();
        let d = tempdir(&format!("all_{stem}"));
        let out = run_in(&d, &["run", case.to_str().unwrap(), "--out", "o", "--format", "md"]);
        assert_eq!(out.status.code(), Some(0), "{stem}: {}", stderr(&out));
        let md = stdout(&out);
        assert!(md.starts_with("# "), "{stem}: stdout is not the Markdown report");
        assert_eq!(md, std::fs::read_to_string(d.join("o/report.md")).unwrap(), "{stem}");
        json_file(&d.join("o/result.json"));
        if let Ok(csv) = std::fs::read_to_string(d.join("o/result.csv")) {
            let header: Vec<&str> = csv.lines().next().unwrap().split(',').collect();
            for col in &header {
                assert!(has_unit(col), "{stem}: CSV column `{col}` names no unit");
            }
            for l in csv.lines().skip(1) {
                assert_eq!(l.split(',').count(), header.len(), "{stem}: CSV row {l}");
            }
        }
        for e in std::fs::read_dir(d.join("o")).unwrap() {
            let p = e.unwrap().path();
            if p.extension().and_then(|e| e.to_str()) == Some("vtu") {
                let vtu = Vtu::read(&p);
                if vtu.has("displacement_mm") {
                    vtu.vectors("displacement_mm");
                    vtu.vectors("rotation_deg");
                    vtu.cell_scalars("von_mises_MPa");
                }
            }
        }
    }
}

/// Stage platform z: the CSV's `z_um` and the Markdown table's Δz (µm) are the same number.
#[test]
fn stage_z_has_one_unit_in_csv_and_markdown() {
    let dir = run_out("stage_units", &root().join("cases/ruiz2019_stage.json"));
    let csv = std::fs::read_to_string(dir.join("result.csv")).unwrap();
    let md = std::fs::read_to_string(dir.join("report.md")).unwrap();
    let header: Vec<&str> = csv.lines().next().unwrap().split(',').collect();
    let zc = header.iter().position(|h| *h == "z_um").expect("z_um column");
    assert!(md.contains("Δz (µm)"));
    let res = json_file(&dir.join("result.json"));
    for (i, line) in csv.lines().skip(1).enumerate() {
        let z_um: f64 = line.split(',').nth(zc).unwrap().parse().unwrap();
        close(
            z_um,
            1000.0 * f(&res["load_cases"][i]["platform"]["z"]),
            1e-12,
            "z_um vs JSON z (mm)",
        );
        let name = line.split(',').nth(1).unwrap();
        let row = md.lines().find(|l| l.starts_with(&format!("| {name} |"))).unwrap();
        let cell = row.split('|').nth(4).unwrap().trim();
        assert_eq!(cell, format!("{z_um:.1}"), "Markdown Δz of {name}");
    }
}

/// Kinematics CSV: fkp and ikp rows share one header, so every value sits under its column
/// (ikp rows used to be written z-first under the fkp header). Each value equals the JSON.
#[test]
fn kinematics_csv_rows_match_their_header() {
    let dir = run_out("kin_csv", &root().join("cases/ruiz2019_kinematics.json"));
    let res = json_file(&dir.join("result.json"));
    let csv = std::fs::read_to_string(dir.join("result.csv")).unwrap();
    let header: Vec<&str> = csv.lines().next().unwrap().split(',').collect();
    let mut seen = [0usize; 2];
    for line in csv.lines().skip(1) {
        let cells: Vec<&str> = line.split(',').collect();
        let kind = if cells[0] == "fkp" { 0 } else { 1 };
        let j = &res[cells[0]][seen[kind]];
        seen[kind] += 1;
        assert_eq!(cells.len(), header.len(), "{line}");
        for (h, c) in header.iter().zip(&cells).skip(1) {
            let key = h.trim_end_matches("_mm");
            let expect = match key {
                "s1" | "s2" | "s3" => f(&j["s"][key[1..].parse::<usize>().unwrap() - 1]),
                _ => f(&j[key]),
            };
            let v: f64 = c.parse().unwrap();
            assert!(
                (v - expect).abs() <= 1e-12 * expect.abs(),
                "{} row {}: column {h}: {v} vs {expect}",
                cells[0],
                seen[kind]
            );
        }
    }
    assert_eq!(seen, [4, 2], "rows written");
}
