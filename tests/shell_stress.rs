//! Shell stress output (`shell_stress`, `shell_forces`): closed-form pure bending, the NAFEMS
//! LE5 Z-section cantilever, and equilibrium of the centre resultants on a free body. Cases run
//! through the case-file pipeline (JSON in, JSON result out).

use serde_json::{json, Value};

mod common;

/// Runs a case given as JSON; the JSON result.
fn run(case: Value) -> Value {
    let c = flexfem::analysis::parse_value(case, None).expect("valid case");
    flexfem::analysis::run(&c).expect("analysis runs").json
}

/// Structured flat strip [0, l] × [0, b] in z = 0, nx × ny quads (node (i, j) = j(nx+1) + i).
fn strip(l: f64, b: f64, nx: usize, ny: usize) -> (Vec<[f64; 3]>, Vec<Value>) {
    common::meshes::shell_grid_json((nx, ny), "s", "m", |i, j| {
        [l * i as f64 / nx as f64, b * j as f64 / ny as f64, 0.0]
    })
}

/// A `static` case of shells (section `s` of thickness `t`, material `m`) with one load case,
/// `name`, of edge loads.
fn shell_case(
    material: Value,
    t: f64,
    (nodes, elements): (Vec<[f64; 3]>, Vec<Value>),
    supports: Vec<Value>,
    edges: Vec<Value>,
    name: &str,
) -> Value {
    json!({
        "analysis": "static",
        "materials": {"m": material},
        "sections": {"s": {"shape": "shell", "t": t}},
        "nodes": nodes,
        "elements": elements,
        "supports": supports,
        "load_cases": [{"name": name, "edge_loads": edges}]
    })
}

/// The statically determinate strip in pure bending: `strip(l, b, nx, ny)` of thickness `t`
/// and `material`, end moment `mm` (about +y at x = l, −`mm` at x = 0) as edge moments
/// `mm`/b per length, held against rigid motion only.
fn bending_strip(l: f64, b: f64, t: f64, mm: f64, (nx, ny): (usize, usize), material: Value) -> Value {
    let (nodes, elements) = strip(l, b, nx, ny);
    let mut edges = Vec::new();
    for j in 0..ny {
        edges.push(json!({"nodes": [j * (nx + 1) + nx, (j + 1) * (nx + 1) + nx], "m": [0.0, mm / b, 0.0]}));
        edges.push(json!({"nodes": [j * (nx + 1), (j + 1) * (nx + 1)], "m": [0.0, -mm / b, 0.0]}));
    }
    let supports = vec![
        json!({"node": 0, "fix": ["ux", "uy", "uz"]}),
        json!({"node": nx, "fix": ["uy", "uz"]}),
        json!({"node": ny * (nx + 1), "fix": ["uz"]}),
    ];
    shell_case(material, t, (nodes, elements), supports, edges, "M")
}

fn f(v: &Value) -> f64 {
    v.as_f64().expect("number")
}

/// Strip under uniform end moments (closed form: σxx = ±6M/(bt²) on top/bottom, 0 at mid,
/// σyy = 0 with free long edges — anticlastic bending, plate theory). The moment M (N·mm,
/// about +y at x = L, −M at x = 0) is applied as edge moments M/b per length; supports are
/// statically determinate (no reactions), so the field is uniform and every node must give
/// the closed form: top σxx = +6M/(bt²) (u(z) = u + zθy: +My at x = L stretches the top).
#[test]
fn strip_end_moment_gives_6m_over_bt2() {
    let (l, b, t, mm) = (100.0, 20.0, 2.0, 1500.0);
    let (nx, ny) = (10, 4);
    let case = bending_strip(
        l,
        b,
        t,
        mm,
        (nx, ny),
        json!({"E": 70000.0, "nu": 0.3, "density": 2.7e-9, "yield": 500.0, "allowable": 300.0}),
    );
    let r = run(case);
    let lc = &r["load_cases"][0];
    let sigma = 6.0 * mm / (b * t * t);
    let ss = &lc["shell_stress"];
    for node in 0..(nx + 1) * (ny + 1) {
        let top = &ss["top"][node];
        let bot = &ss["bottom"][node];
        let mid = &ss["mid"][node];
        assert!(
            (f(&top[0]) - sigma).abs() < 1e-6 * sigma,
            "node {node}: top {top}, expected {sigma}"
        );
        assert!((f(&bot[0]) + sigma).abs() < 1e-6 * sigma, "node {node}: bottom {bot}");
        for k in 0..6 {
            assert!(f(&mid[k]).abs() < 1e-6 * sigma, "node {node}: mid {mid}");
            if k != 0 {
                assert!(f(&top[k]).abs() < 1e-6 * sigma, "node {node}: top {top}");
            }
        }
    }
    // Centre resultants: Mxx = M/b (N·mm/mm), nothing else.
    for e in lc["shell_forces"].as_array().unwrap() {
        let m = &e["M"];
        assert!((f(&m[0]) - mm / b).abs() < 1e-6 * mm / b, "{e}");
        assert!(f(&m[1]).abs() < 1e-6 * mm / b && f(&m[2]).abs() < 1e-6 * mm / b, "{e}");
    }
    // The extreme principal stresses are named in the report (checked through the JSON here).
    assert_eq!(lc["shell_forces"].as_array().unwrap().len(), nx * ny);
}

/// NAFEMS LE5 Z-section cantilever: L = 10 m, flanges 1 m wide, web 2 m deep (mid-surfaces),
/// t = 0.1 m, E = 210 GPa, ν = 0.3, clamped at x = 0; a torque of 1.2 MN·m at x = L applied as
/// two uniform edge shears of 0.6 MN on the flanges' end edges. Target: axial stress σxx at
/// the mid-surface at point A (x = 2.5 m, flange tip) = −108 MPa (NAFEMS, The Standard NAFEMS
/// Benchmarks, TNSB Rev. 3, 1990, test LE5). Vlasov's theory of restrained warping gives
/// 107.8 MPa there (ω = −0.75 m² at the tips about the centroid, I_ω = 0.04167 m⁶,
/// k = √(GJ/EI_ω) = 0.1109 /m; B(x) = (T/k)·sinh k(L−x)/cosh kL). Units here: mm, N.
/// The torque's sense is chosen so that A is in compression, as in the benchmark.
fn z_section(nf: usize, nw: usize, nx: usize) -> (f64, f64) {
    let (l, bf, h, t) = (10_000.0, 1_000.0, 2_000.0, 100.0);
    // Section polyline (y, z): top flange tip → top junction → web → bottom junction → tip.
    let mut sec: Vec<[f64; 2]> = Vec::new();
    for k in 0..nf {
        sec.push([bf * (1.0 - k as f64 / nf as f64), h / 2.0]);
    }
    for k in 0..nw {
        sec.push([0.0, h / 2.0 - h * k as f64 / nw as f64]);
    }
    for k in 0..=nf {
        sec.push([-bf * k as f64 / nf as f64, -h / 2.0]);
    }
    let ns = sec.len();
    let mut nodes = Vec::new();
    for i in 0..=nx {
        for p in &sec {
            nodes.push([l * i as f64 / nx as f64, p[0], p[1]]);
        }
    }
    let id = |i: usize, k: usize| i * ns + k;
    let mut elements = Vec::new();
    for i in 0..nx {
        for k in 0..ns - 1 {
            elements.push(
                json!({"type": "shell4", "nodes": [id(i, k), id(i + 1, k), id(i + 1, k + 1), id(i, k + 1)],
                                  "section": "s", "material": "m"}),
            );
        }
    }
    let supports: Vec<Value> = (0..ns)
        .map(|k| json!({"node": id(0, k), "fix": ["ux", "uy", "uz", "rx", "ry", "rz"]}))
        .collect();
    // Edge shears: 0.6 MN over 1 m of each flange, along y; opposite on the two flanges.
    let q = 0.6e6 / bf;
    let mut edges = Vec::new();
    for k in 0..nf {
        edges.push(json!({"nodes": [id(nx, k), id(nx, k + 1)], "q": [0.0, q, 0.0]}));
        let kb = nf + nw + k;
        edges.push(json!({"nodes": [id(nx, kb), id(nx, kb + 1)], "q": [0.0, -q, 0.0]}));
    }
    let steel = json!({"E": 210000.0, "nu": 0.3, "density": 7.85e-9, "yield": 1e9, "allowable": 1e9});
    let r = run(shell_case(steel, t, (nodes, elements), supports, edges, "torque"));
    let lc = &r["load_cases"][0];
    assert!(nx.is_multiple_of(4));
    let a_top = id(nx / 4, 0);
    let a_bot = id(nx / 4, ns - 1);
    let sxx = |n: usize| f(&lc["shell_stress"]["mid"][n][0]);
    (sxx(a_top), sxx(a_bot))
}

#[test]
fn z_section_cantilever_nafems_le5() {
    let target = -108.0;
    for (nf, nw, nx) in [(1, 2, 8), (2, 4, 16), (4, 8, 40)] {
        let (a, b) = z_section(nf, nw, nx);
        eprintln!("LE5 {nf}/{nw}/{nx}: σxx(A) = {a:.2} MPa (other flange tip {b:.2}); target {target}");
    }
    let (a, b) = z_section(4, 8, 40);
    assert!((a - target).abs() < 0.03 * target.abs(), "σxx(A) = {a}");
    // Point symmetry of the Z: the other flange's tip carries the same warping stress.
    assert!((a - b).abs() < 1e-6 * a.abs(), "{a} vs {b}");
}

/// Equilibrium of the centre resultants on a free body: a cantilever strip (clamped at x = 0)
/// loaded at x = L by edge loads with resultant P = (Px, Py, Pz). Cutting through the centres
/// of element column c (x = x_c) and keeping the part beyond, the resultants integrated across
/// the cut (centre value × element width, in the element axes given in the output) balance
/// the load: ∫(Nxx, Nxy, Qx) dy = P and ∫Mxx dy = −Pz·(L − x_c) (Mxx > 0 stretches the top).
/// Errors relative to |P| (moment: to Pz·L) per cut.
fn strip_free_body(nx: usize, ny: usize) -> Vec<[f64; 4]> {
    let (l, b, t) = (200.0, 20.0, 2.0);
    let p = [300.0, 40.0, 5.0];
    let (nodes, elements) = strip(l, b, nx, ny);
    let supports: Vec<Value> = (0..=ny)
        .map(|j| json!({"node": j * (nx + 1), "fix": ["ux", "uy", "uz", "rx", "ry", "rz"]}))
        .collect();
    let edges: Vec<Value> = (0..ny)
        .map(|j| json!({"nodes": [j * (nx + 1) + nx, (j + 1) * (nx + 1) + nx], "q": [p[0] / b, p[1] / b, p[2] / b]}))
        .collect();
    let r = run(shell_case(json!("steel"), t, (nodes, elements), supports, edges, "P"));
    let forces = r["load_cases"][0]["shell_forces"].as_array().unwrap().clone();
    let w = b / ny as f64;
    let mut err = Vec::new();
    for c in 0..nx {
        let xc = l * (c as f64 + 0.5) / nx as f64;
        let mut s = [0.0; 4];
        for j in 0..ny {
            let e = &forces[j * nx + c];
            assert_eq!(e["element"].as_u64(), Some((j * nx + c) as u64));
            let ax: Vec<[f64; 3]> = (0..3).map(|k| std::array::from_fn(|d| f(&e["axes"][k][d]))).collect();
            // Traction on the x-face in element axes (Nxx, Nxy, Qx), to global axes.
            let loc = [f(&e["N"][0]), f(&e["N"][2]), f(&e["Q"][0])];
            for d in 0..3 {
                s[d] += w * (0..3).map(|k| loc[k] * ax[k][d]).sum::<f64>();
            }
            s[3] += w * f(&e["M"][0]);
        }
        let pn = (p[0] * p[0] + p[1] * p[1] + p[2] * p[2]).sqrt();
        err.push([
            (s[0] - p[0]).abs() / pn,
            (s[1] - p[1]).abs() / pn,
            (s[2] - p[2]).abs() / pn,
            (s[3] + p[2] * (l - xc)).abs() / (p[2] * l),
        ]);
    }
    err
}

#[test]
fn shell_forces_balance_the_load_on_a_free_body() {
    for (nx, ny) in [(10, 2), (20, 4)] {
        let err = strip_free_body(nx, ny);
        let worst: [f64; 4] = std::array::from_fn(|k| err.iter().map(|e| e[k]).fold(0.0, f64::max));
        eprintln!("free body {nx}×{ny}: worst relative errors (Fx, Fy, Fz, My) = {worst:?}");
        // Axial force, transverse shear and bending moment balance to roundoff at every cut;
        // the in-plane shear Nxy (a parabola across the strip, element-wise constant in the
        // centre value) to 4e-4 of |P| (2e-4 at 10×2, 3.6e-4 at 20×4, largest next to the
        // clamp).
        for (c, e) in err.iter().enumerate() {
            for k in [0, 2, 3] {
                assert!(e[k] < 1e-8, "column {c}, component {k}: relative error {}", e[k]);
            }
            assert!(e[1] < 5e-4, "column {c}, Fy: relative error {}", e[1]);
        }
    }
}

/// The VTU of a shell load case carries the nodal stress tensors (6 components) and the
/// centre resultants and axes (3 components per cell), with units in the names; the Markdown
/// report names the extreme principal stresses with node and surface. Pure bending strip as
/// above: σ₁ = 6M/(bt²) on the top, σ₃ = −6M/(bt²) on the bottom.
#[test]
fn vtu_and_report_carry_shell_stresses() {
    let (l, b, t, mm) = (100.0, 20.0, 2.0, 1500.0);
    let (nx, ny) = (4, 2);
    let case = bending_strip(l, b, t, mm, (nx, ny), json!("Al7075"));
    let c = flexfem::analysis::parse_value(case, None).unwrap();
    let out = flexfem::analysis::run_with_files(&c).unwrap();
    let (_, vtu) = out.files.iter().find(|(n, _)| n == "M.vtu").expect("M.vtu");
    let vtu = String::from_utf8_lossy(vtu);
    for name in [
        "shell_stress_top_MPa",
        "shell_stress_mid_MPa",
        "shell_stress_bottom_MPa",
    ] {
        assert!(
            vtu.contains(&format!("Name=\"{name}\" NumberOfComponents=\"6\"")),
            "{name}"
        );
    }
    for name in [
        "shell_N_N_per_mm",
        "shell_M_Nmm_per_mm",
        "shell_Q_N_per_mm",
        "shell_axis_x",
        "shell_axis_y",
        "shell_axis_z",
    ] {
        assert!(
            vtu.contains(&format!("Name=\"{name}\" NumberOfComponents=\"3\"")),
            "{name}"
        );
    }
    let sigma = 6.0 * mm / (b * t * t);
    let md = &out.report.markdown;
    // The report writes five significant digits (`report::markdown::num`).
    let num = |v: f64| flexfem::report::markdown::num(v, 5);
    assert!(md.contains(&format!("largest σ₁ = {} MPa", num(sigma))), "{md}");
    assert!(md.contains("(top surface)") && md.contains("(bottom surface)"), "{md}");
    assert!(md.contains(&format!("smallest σ₃ = {} MPa", num(-sigma))), "{md}");
}

/// Two shells sharing an edge with opposite node orders (opposite normals) get a warning:
/// their top surfaces lie on opposite sides, so nodal averages would mix top and bottom.
/// Consistently oriented meshes (every test above) get none.
#[test]
fn opposite_shell_normals_are_warned() {
    let case = |flip: bool| {
        let second = if flip { json!([1, 4, 5, 2]) } else { json!([1, 2, 5, 4]) };
        json!({
            "analysis": "static",
            "materials": {"m": "steel"},
            "sections": {"s": {"shape": "shell", "t": 1.0}},
            "nodes": [[0, 0, 0], [10, 0, 0], [20, 0, 0], [0, 10, 0], [10, 10, 0], [20, 10, 0]],
            "elements": [{"type": "shell4", "nodes": [0, 1, 4, 3], "section": "s", "material": "m"},
                         {"type": "shell4", "nodes": second, "section": "s", "material": "m"}],
            "supports": [{"node": 0, "fix": ["ux", "uy", "uz", "rx", "ry", "rz"]},
                         {"node": 3, "fix": ["ux", "uy", "uz", "rx", "ry", "rz"]}],
            "load_cases": [{"name": "p", "forces": [{"node": 2, "F": [0, 0, 1, 0, 0, 0]}]}]
        })
    };
    let w = run(case(true))["warnings"].clone();
    assert!(w[0].as_str().unwrap_or("").contains("opposite normals"), "{w}");
    assert_eq!(run(case(false))["warnings"], json!([]));
}
