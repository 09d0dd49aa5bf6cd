//! Shell pressure loads (`pressures` in static load cases): Navier's series for the simply
//! supported plate (S. Timoshenko, S. Woinowsky-Krieger, Theory of Plates and Shells, 2nd ed.,
//! McGraw-Hill 1959, §30, eqs. (131)–(134) and Table 8), and pressure by Gmsh physical group.

use serde_json::{json, Value};

mod common;

fn run(case: Value) -> Value {
    let c = flexfem::analysis::parse_value(case, None).expect("valid case");
    flexfem::analysis::run(&c).expect("analysis runs").json
}

fn f(v: &Value) -> f64 {
    v.as_f64().expect("number")
}

/// Navier's double series at the centre of a simply supported square plate of side a under
/// uniform q (Kirchhoff): w = Σ w_mn sin(mπ/2) sin(nπ/2) with w_mn = 16q/(π⁶ D m n (m²/a² +
/// n²/a²)²), m, n odd; Mx = Σ w_mn D ((mπ/a)² + ν (nπ/a)²) sin sin. Returns (w, Mx).
fn navier(a: f64, q: f64, d: f64, nu: f64) -> (f64, f64) {
    let pi = std::f64::consts::PI;
    let (mut w, mut mx) = (0.0, 0.0);
    for m in (1..400).step_by(2) {
        for n in (1..400).step_by(2) {
            let (mf, nf) = (m as f64, n as f64);
            let s = if ((m + n) / 2 - 1) % 2 == 0 { 1.0 } else { -1.0 };
            let wmn = 16.0 * q / (pi.powi(6) * d * mf * nf * ((mf * mf + nf * nf) / (a * a)).powi(2));
            w += s * wmn;
            mx += s * wmn * d * ((mf * pi / a).powi(2) + nu * (nf * pi / a).powi(2));
        }
    }
    (w, mx)
}

/// Simply supported square plate, a = 1000 mm, t = 10 mm (a/t = 100), steel, q = 0.01 MPa,
/// quarter model (16×16 elements, symmetry on x = y = a/2; "hard" support: w = 0 and the
/// rotation about the edge normal held). Centre deflection and top-surface σxx = 6Mx/t²
/// within 1 % of Navier's series (Timoshenko: w = 0.00406 q a⁴/D, Mx = 0.0479 q a² for
/// ν = 0.3; the series here to m, n < 400). Reissner–Mindlin shear adds ≈ 0.06 % at a/t = 100.
/// Relative tolerances on the centre deflection and the top stress against the Navier series
/// (measured +0.071 % and +0.0014 %).
const NAVIER_W_TOL: f64 = 2e-3;
const NAVIER_STRESS_TOL: f64 = 5e-5;

#[test]
fn simply_supported_plate_under_pressure_matches_navier() {
    let (a, t, q): (f64, f64, f64) = (1000.0, 10.0, 0.01);
    let (e, nu): (f64, f64) = (210000.0, 0.3);
    let n = 16;
    let h = 0.5 * a;
    let (nodes, elements) = common::meshes::shell_grid_json((n, n), "s", "m", |i, j| {
        [h * i as f64 / n as f64, h * j as f64 / n as f64, 0.0]
    });
    let id = common::meshes::grid_id(n);
    let mut supports = Vec::new();
    for j in 0..=n {
        for i in 0..=n {
            let mut fix: Vec<&str> = Vec::new();
            if i == 0 {
                fix.extend(["uz", "rx"]);
            }
            if j == 0 {
                fix.extend(["uz", "ry"]);
            }
            if i == n {
                fix.extend(["ux", "ry", "rz"]);
            }
            if j == n {
                fix.extend(["uy", "rx", "rz"]);
            }
            fix.sort();
            fix.dedup();
            if !fix.is_empty() {
                supports.push(json!({"node": id(i, j), "fix": fix}));
            }
        }
    }
    let all: Vec<usize> = (0..n * n).collect();
    let case = json!({
        "analysis": "static",
        "materials": {"m": {"E": e, "nu": nu, "density": 7.85e-9, "yield": 1e9, "allowable": 1e9}},
        "sections": {"s": {"shape": "shell", "t": t}},
        "nodes": nodes,
        "elements": elements,
        "supports": supports,
        "load_cases": [{"name": "q", "pressures": [{"p": q, "elements": all}]}]
    });
    let r = run(case);
    let lc = &r["load_cases"][0];
    let d = e * t.powi(3) / (12.0 * (1.0 - nu * nu));
    let (w_ref, mx_ref) = navier(a, q, d, nu);
    // Timoshenko's table, as a check of the series itself.
    assert!((w_ref / (q * a.powi(4) / d) - 0.00406).abs() < 5e-6);
    assert!((mx_ref / (q * a * a) - 0.0479).abs() < 5e-5);
    let c = id(n, n);
    let w = f(&lc["displacements"][c][2]);
    let s_top = f(&lc["shell_stress"]["top"][c][0]);
    let s_ref = 6.0 * mx_ref / (t * t);
    eprintln!(
        "SS plate: w = {w:.6} vs {w_ref:.6} ({:+.3} %), σxx top = {s_top:.4} vs {s_ref:.4} ({:+.5} %)",
        100.0 * (w - w_ref) / w_ref,
        100.0 * (s_top - s_ref) / s_ref
    );
    assert!(((w - w_ref) / w_ref).abs() < NAVIER_W_TOL);
    assert!(((s_top - s_ref) / s_ref).abs() < NAVIER_STRESS_TOL);
    // Reactions carry the whole pressure load q·(a/2)².
    let fz: f64 = lc["reactions"].as_array().unwrap().iter().map(|r| f(&r[2])).sum();
    assert!((fz + q * h * h).abs() < 1e-9 * q * h * h, "ΣFz = {fz}");
}

/// The Gmsh clamped plate (cases/gmsh_plate_quads.json, 100 × 100 mm, 16×16 quads, group
/// "plate"): a pressure on the group equals the same pressure on the element list, and the
/// reactions carry p·A.
#[test]
fn pressure_by_gmsh_group_equals_element_list() {
    let root = std::path::PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("cases");
    let text = std::fs::read_to_string(root.join("gmsh_plate_quads.json")).unwrap();
    let mut v: Value = serde_json::from_str(&text).unwrap();
    let p = -0.02;
    let all: Vec<usize> = (0..256).collect();
    v["load_cases"] = json!([
        {"name": "group", "pressures": [{"p": p, "group": "plate"}]},
        {"name": "list", "pressures": [{"p": p, "elements": all}]}
    ]);
    let c = flexfem::analysis::parse_value(v.clone(), Some(&root)).unwrap();
    let r = flexfem::analysis::run(&c).unwrap().json;
    let a = &r["load_cases"][0];
    let b = &r["load_cases"][1];
    assert_eq!(a["displacements"], b["displacements"]);
    let fz: f64 = a["reactions"].as_array().unwrap().iter().map(|r| f(&r[2])).sum();
    assert!((fz + p * 100.0 * 100.0).abs() < 1e-9 * 200.0, "ΣFz = {fz}");
    // An unknown group is a case error naming its path.
    v["load_cases"] = json!([{"name": "g", "pressures": [{"p": p, "group": "edgee"}]}]);
    let err = flexfem::analysis::parse_value(v, Some(&root))
        .and_then(|c| flexfem::analysis::check(&c))
        .unwrap_err();
    assert!(err.to_string().contains("load_cases[0].pressures[0].group"), "{err}");
}

/// Pressure and edge-load input errors name the JSON path and what is allowed.
#[test]
fn shell_load_errors_name_the_path() {
    let base = json!({
        "analysis": "static",
        "materials": {"m": "steel"},
        "sections": {"s": {"shape": "shell", "t": 1.0}, "r": {"shape": "rect", "w": 1.0, "h": 1.0}},
        "nodes": [[0, 0, 0], [10, 0, 0], [10, 10, 0], [0, 10, 0]],
        "elements": [{"type": "shell4", "nodes": [0, 1, 2, 3], "section": "s", "material": "m"},
                     {"type": "beam", "nodes": [0, 2], "section": "r", "material": "m", "up": [0, 0, 1]}],
        "supports": [{"node": 0, "fix": ["ux", "uy", "uz", "rx", "ry", "rz"]}],
    });
    let check = |lc: Value, path: &str| {
        let mut v = base.clone();
        v["load_cases"] = json!([lc]);
        let err = flexfem::analysis::parse_value(v, None)
            .and_then(|c| flexfem::analysis::check(&c))
            .unwrap_err();
        assert!(err.to_string().contains(path), "{err}");
    };
    check(
        json!({"name": "a", "pressures": [{"p": 1.0, "elements": [1]}]}),
        "load_cases[0].pressures[0].elements[0]",
    );
    check(
        json!({"name": "a", "pressures": [{"p": 1.0, "elements": [5]}]}),
        "load_cases[0].pressures[0].elements[0]",
    );
    check(
        json!({"name": "a", "pressures": [{"p": 1.0, "group": "x"}]}),
        "load_cases[0].pressures[0].group",
    );
    check(
        json!({"name": "a", "pressures": [{"p": 1.0}]}),
        "load_cases[0].pressures[0]",
    );
    check(
        json!({"name": "a", "edge_loads": [{"nodes": [0, 2], "q": [1, 0, 0]}]}),
        "load_cases[0].edge_loads[0].nodes",
    );
    check(
        json!({"name": "a", "edge_loads": [{"nodes": [0, 9], "q": [1, 0, 0]}]}),
        "load_cases[0].edge_loads[0].nodes[1]",
    );
}
