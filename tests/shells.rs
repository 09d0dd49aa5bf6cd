//! Shell benchmarks (MacNeal & Harder, "A proposed standard set of problems to test finite
//! element accuracy", Finite Elements in Analysis and Design 1 (1985) 3–20; Belytschko et al.,
//! "Stress projection for membrane and shear locking in shell finite elements", CMAME 51 (1985)
//! 221–258), and Timoshenko's clamped plate. Meshes and errors are stated per test.

use common::meshes::{area_load, with_loads};
use flexfem::fem::{self, Dof, Element, LoadCase, Model, Support};
use flexfem::material::Material;

mod common;

fn mat(e: f64, nu: f64) -> Material {
    Material {
        e,
        nu,
        density: 1.0,
        yield_strength: f64::INFINITY,
        allowable: f64::INFINITY,
        fatigue: None,
    }
}

/// Structured grid of (nx+1)×(ny+1) nodes placed by `f(s, r)` with s, r ∈ [0, 1]; returns the
/// node index function.
fn grid(m: &mut Model, nx: usize, ny: usize, t: f64, mat: Material, f: impl Fn(f64, f64) -> [f64; 3]) -> Vec<usize> {
    let id = common::meshes::shell_grid(m, (nx, ny), t, mat, |i, j| {
        f(i as f64 / nx as f64, j as f64 / ny as f64)
    });
    (0..=ny).flat_map(|j| (0..=nx).map(move |i| id(i, j))).collect()
}

fn fix(m: &mut Model, node: usize, dofs: &[Dof]) {
    m.supports.push(Support::dofs(node, dofs));
}

use Dof::*;

/// Asserts `got` within `tol` (relative) of `reference`, printing the error.
fn within(what: &str, got: f64, reference: f64, tol: f64) {
    let err = got / reference - 1.0;
    eprintln!("{what} = {got:.6e}, error {:.2} %", 100.0 * err);
    assert!(err.abs() < tol, "{what} = {got} vs {reference}");
}

fn clamped_plate(n: usize) -> f64 {
    let (a, t, e, nu, q) = (100.0, 0.1, 1.0e5, 0.3, 1e-3);
    let mut m = Model::new();
    let ids = grid(&mut m, n, n, t, mat(e, nu), |s, r| [a * s, a * r, 0.0]);
    common::meshes::each_node(n, |i, j, edge| {
        if edge {
            m.supports.push(Support::clamp(ids[j * (n + 1) + i]));
        }
    });
    let f = area_load(&m, [0.0, 0.0, -q]);
    let m = with_loads(m, &f);
    let r = fem::solve_static(&m).unwrap();
    let w = -r.load_cases[0].displacements[ids[(n / 2) * (n + 1) + n / 2]][2];
    let d = e * t.powi(3) / (12.0 * (1.0 - nu * nu));
    w / (q * a.powi(4) / d)
}

/// Clamped square plate, uniform pressure: w_max = 0.00126 q a⁴/D (S. Timoshenko,
/// S. Woinowsky-Krieger, Theory of Plates and Shells, 2nd ed., 1959, Table 35: 0.00126).
/// Full plate, 16×16 mesh, a/t = 1000: 0.0012617 (+0.13 %; the stabilized shear, α = 0.05, gave
/// 0.001271, +0.91 %).
#[test]
fn clamped_square_plate_timoshenko() {
    within("clamped plate 16x16: w / (q a^4/D)", clamped_plate(16), 0.00126, 0.004);
}

/// Scordelis–Lo roof: R = 25, L = 50, 2×40° arc, t = 0.25, E = 4.32e8, ν = 0, gravity 90 per
/// unit area, rigid diaphragms at the curved ends (uy = uz = 0). Reference vertical
/// displacement at the midside of the free edge 0.3024 (MacNeal & Harder 1985; Belytschko et
/// al. 1985). Full roof, `n`×`n` mesh.
fn scordelis_lo(n: usize) -> f64 {
    let (r, l, t) = (25.0, 50.0, 0.25);
    let phi0 = 40f64.to_radians();
    let mut m = Model::new();
    let ids = grid(&mut m, n, n, t, mat(4.32e8, 0.0), |s, q| {
        let phi = -phi0 + 2.0 * phi0 * q;
        [l * s, r * phi.sin(), r * phi.cos()]
    });
    for j in 0..=n {
        fix(&mut m, ids[j * (n + 1)], &[Uy, Uz]);
        fix(&mut m, ids[j * (n + 1) + n], &[Uy, Uz]);
    }
    fix(&mut m, ids[0], &[Ux, Uy, Uz]);
    let f = area_load(&m, [0.0, 0.0, -90.0]);
    let m = with_loads(m, &f);
    let res = fem::solve_static(&m).unwrap();
    -res.load_cases[0].displacements[ids[n / 2]][2]
}

#[test]
fn scordelis_lo_roof() {
    // 16×16 elements on the full roof (an 8×8 quarter): 0.30385 (+0.48 %; the stabilized shear,
    // α = 0.05, gave 0.30586, +1.14 %); 8×8 0.31597, 32×32 0.30165.
    within("Scordelis-Lo 16x16: w", scordelis_lo(16), 0.3024, 0.007);
}

/// Pinched cylinder with rigid end diaphragms: R = 300, L = 600, t = 3, E = 3e6, ν = 0.3,
/// two opposite loads P = 1 at midspan; radial displacement under the load 1.8248e-5
/// (MacNeal & Harder 1985; Belytschko et al. 1985). One octant, `n`×`n` mesh, P/4 on it.
fn pinched_cylinder(n: usize) -> f64 {
    let (r, l, t) = (300.0, 600.0, 3.0);
    let mut m = Model::new();
    let ids = grid(&mut m, n, n, t, mat(3e6, 0.3), |s, q| {
        let phi = std::f64::consts::FRAC_PI_2 * q;
        [0.5 * l * s, r * phi.cos(), r * phi.sin()]
    });
    let id = |i: usize, j: usize| ids[j * (n + 1) + i];
    for j in 0..=n {
        fix(&mut m, id(0, j), &[Uy, Uz, Rx]); // diaphragm
        fix(&mut m, id(n, j), &[Ux, Ry, Rz]); // symmetry x = L/2
    }
    for i in 0..=n {
        fix(&mut m, id(i, 0), &[Uz, Rx, Ry]); // symmetry z = 0
        fix(&mut m, id(i, n), &[Uy, Rx, Rz]); // symmetry y = 0
    }
    let mut f = vec![[0.0; 6]; m.nodes.len()];
    f[id(n, n)][2] = -0.25;
    let m = with_loads(m, &f);
    let res = fem::solve_static(&m).unwrap();
    -res.load_cases[0].displacements[id(n, n)][2]
}

#[test]
fn pinched_cylinder_with_diaphragms() {
    // Octant 32×32: 1.8054e-5 (−1.06 %; OpenSees ASDShellQ4 on the same mesh 1.8054e-5); MITC4
    // converges from below under the point load, 16×16 is −7 %, so 32×32 is needed.
    within(
        "pinched cylinder octant 32x32: w",
        pinched_cylinder(32),
        1.8248e-5,
        0.02,
    );
}

/// Pinched hemisphere with an 18° hole: R = 10, t = 0.04, E = 6.825e7, ν = 0.3, alternating
/// radial loads ±2 on the equator; displacement under the load 0.094 (MacNeal & Harder 1985).
/// Quarter model (loads ±1), `n`×`n` mesh.
fn pinched_hemisphere(n: usize) -> (f64, f64) {
    let (r, t) = (10.0, 0.04);
    let mut m = Model::new();
    let ids = grid(&mut m, n, n, t, mat(6.825e7, 0.3), |s, q| {
        let polar = std::f64::consts::FRAC_PI_2 - (72f64.to_radians()) * q; // equator → hole
        let az = std::f64::consts::FRAC_PI_2 * s;
        [r * polar.sin() * az.cos(), r * polar.sin() * az.sin(), r * polar.cos()]
    });
    let id = |i: usize, j: usize| ids[j * (n + 1) + i];
    for j in 0..=n {
        fix(&mut m, id(0, j), &[Uy, Rx, Rz]); // y = 0 plane
        fix(&mut m, id(n, j), &[Ux, Ry, Rz]); // x = 0 plane
    }
    fix(&mut m, id(0, 0), &[Uz]);
    let mut f = vec![[0.0; 6]; m.nodes.len()];
    f[id(0, 0)][0] = 1.0;
    f[id(n, 0)][1] = -1.0;
    let m = with_loads(m, &f);
    let res = fem::solve_static(&m).unwrap();
    let d = &res.load_cases[0].displacements;
    (d[id(0, 0)][0], -d[id(n, 0)][1])
}

#[test]
fn pinched_hemisphere_18deg_hole() {
    // Quarter 16×16: 0.09309 (−0.97 %; OpenSees ASDShellQ4 on the same mesh 0.09309; the
    // stabilized shear, α = 0.05, gave 0.09389). MITC4 converges to 0.0936 (0.4 % below the
    // reference; `curved_shells_extrapolated_match_opensees`).
    let (ux, uy) = pinched_hemisphere(16);
    let err = (ux - 0.094) / 0.094;
    eprintln!(
        "pinched hemisphere 16x16: ux = {ux:.5}, uy = {uy:.5}, error {:.2} %",
        100.0 * err
    );
    // The reference is printed to two digits (±0.5 %), the mesh 0.6 % from converged: 1.2 %.
    assert!(err.abs() < 0.012, "ux = {ux}");
    assert!((ux - uy).abs() < 1e-3 * ux);
}

/// Twisted beam (MacNeal & Harder 1985, thick version): L = 12, width 1.1, t = 0.32, 90°
/// pretwist, E = 29e6, ν = 0.22, unit tip load; tip displacement along the load 5.424e-3
/// (in-plane: along the tip's width) and 1.754e-3 (out-of-plane). Mesh 2×12 (MacNeal's).
fn twisted_beam(nw: usize, nl: usize, load_dir: usize) -> f64 {
    twisted_beam_t(nw, nl, load_dir, 0.32, 1.0)
}

fn twisted_beam_t(nw: usize, nl: usize, load_dir: usize, t: f64, p: f64) -> f64 {
    let (l, w) = (12.0, 1.1);
    let mut m = Model::new();
    let ids = grid(&mut m, nl, nw, t, mat(29e6, 0.22), |s, q| {
        let a = std::f64::consts::FRAC_PI_2 * s;
        let y = w * (q - 0.5);
        [l * s, y * a.cos(), y * a.sin()]
    });
    let id = |i: usize, j: usize| ids[j * (nl + 1) + i];
    for j in 0..=nw {
        m.supports.push(Support::clamp(id(0, j)));
    }
    let mut f = vec![[0.0; 6]; m.nodes.len()];
    for j in 0..=nw {
        let share = if j == 0 || j == nw { 0.5 } else { 1.0 } / nw as f64;
        f[id(nl, j)][load_dir] = p * share;
    }
    let m = with_loads(m, &f);
    let res = fem::solve_static(&m).unwrap();
    let d = &res.load_cases[0].displacements;
    (0..=nw).map(|j| d[id(nl, j)][load_dir]).sum::<f64>() / (nw + 1) as f64
}

#[test]
fn twisted_beam_thick() {
    // 2×12: 5.4101e-3 (−0.26 %) and 1.7580e-3 (+0.23 %).
    let inplane = twisted_beam(2, 12, 2);
    let outplane = twisted_beam(2, 12, 1);
    let e1 = (inplane - 5.424e-3) / 5.424e-3;
    let e2 = (outplane - 1.754e-3) / 1.754e-3;
    eprintln!(
        "twisted beam 2x12: in-plane {inplane:.5e} ({:.2} %), out-of-plane {outplane:.5e} ({:.2} %)",
        100.0 * e1,
        100.0 * e2
    );
    assert!(e1.abs() < 0.02 && e2.abs() < 0.02);
}

/// Relative error of the 32×32 Scordelis–Lo roof allowed (measured −0.25 %: the element
/// converges to 0.30127, as OpenSees does, 0.37 % below the reference's 0.3024; see
/// `curved_shells_extrapolated_match_opensees`).
const ROOF_32_TOL: f64 = 3e-3;

/// Scordelis–Lo roof under refinement, full roof 8×8 → 16×16 → 32×32: +4.49 %, +0.48 %,
/// −0.25 % against 0.3024 (MacNeal & Harder 1985): the error falls at each refinement and the
/// finest mesh is within `ROOF_32_TOL`.
#[test]
fn scordelis_lo_roof_converges() {
    let err: Vec<f64> = [8, 16, 32]
        .iter()
        .map(|&n| {
            let w = scordelis_lo(n);
            let e = w / 0.3024 - 1.0;
            eprintln!("Scordelis-Lo {n}x{n}: w = {w:.5} ({:+.3} %)", 100.0 * e);
            e
        })
        .collect();
    assert!(err[1].abs() < err[0].abs() && err[2].abs() < err[1].abs(), "{err:?}");
    assert!(err[2].abs() < ROOF_32_TOL, "{err:?}");
}

/// Gmsh MSH 4.1 import (bundled `meshes/plate_clamped_{quads,tris}.msh`, 16×16 square plate
/// a = 100, t = 1, Al 7075, edges clamped through the physical group "edge", P = 100 N at the
/// centre): the quad mesh must reproduce the directly built model exactly, and both approach
/// Timoshenko's clamped plate under a central load, w = 0.00560 P a²/D (Timoshenko &
/// Woinowsky-Krieger 1959, Table 55; 16×16: quads +1.1 %, see the printed error). Triangles
/// are degenerate quads (stiffer).
#[test]
fn gmsh_import_clamped_plate() {
    use flexfem::analysis;
    let root = std::path::PathBuf::from(env!("CARGO_MANIFEST_DIR"));
    let al = Material::AL7075;
    let d = al.e / (12.0 * (1.0 - al.nu * al.nu));
    let w_ref = 0.00560 * 100.0 * 100.0f64.powi(2) / d;
    let mut w = Vec::new();
    for name in ["gmsh_plate_quads", "gmsh_plate_tris"] {
        let c = analysis::load(&root.join(format!("cases/{name}.json"))).unwrap();
        let out = analysis::run(&c).unwrap();
        let wc = -out.json["load_cases"][0]["displacements"][144][2].as_f64().unwrap();
        eprintln!(
            "{name}: w = {wc:.5} mm vs {w_ref:.5} ({:.2} %)",
            100.0 * (wc - w_ref) / w_ref
        );
        w.push(wc);
    }
    // Direct model, same mesh.
    let n = 16;
    let mut m = Model::new();
    let ids = grid(&mut m, n, n, 1.0, al, |s, r| [100.0 * s, 100.0 * r, 0.0]);
    common::meshes::each_node(n, |i, j, edge| {
        if edge {
            m.supports.push(Support::clamp(ids[j * (n + 1) + i]));
        }
    });
    m.load_cases
        .push(LoadCase::new("c").force(144, [0.0, 0.0, -100.0, 0.0, 0.0, 0.0]));
    let direct = -fem::solve_static(&m).unwrap().load_cases[0].displacements[144][2];
    assert!((w[0] - direct).abs() < 1e-9 * direct, "{} vs {direct}", w[0]);
    assert!(((w[0] - w_ref) / w_ref).abs() < 0.03, "quads {}", w[0]);
    assert!(w[1] < w[0] && w[1] > 0.5 * w_ref, "triangles {}", w[1]);
}

/// Bad mapping names its JSON path.
#[test]
fn gmsh_unknown_group_is_a_case_error() {
    let root = std::path::PathBuf::from(env!("CARGO_MANIFEST_DIR"));
    let text = std::fs::read_to_string(root.join("cases/gmsh_plate_quads.json"))
        .unwrap()
        .replace("\"edge\"", "\"edges\"");
    let err = flexfem::analysis::parse_in(&text, Some(&root.join("cases"))).unwrap_err();
    assert!(err.to_string().contains("gmsh.groups.edges"), "{err}");
}

/// Stress recovery: a cantilever strip (L = 100, b = 20, t = 2, 20×4 mesh) under a tip moment
/// M = 100 N·mm about the width axis is in pure bending: σx = ∓6M/(b t²) on the top and
/// bottom surfaces (beam theory; the free edges leave σy ≈ 0 away from the clamp) and zero at
/// mid-surface. Checked at an element half-way along.
#[test]
fn shell_surface_stresses_in_pure_bending() {
    let (l, b, t, mm) = (100.0, 20.0, 2.0, 100.0);
    let (nx, ny) = (20, 4);
    let mut m = Model::new();
    let ids = grid(&mut m, nx, ny, t, Material::AL7075, |s, r| [l * s, b * r, 0.0]);
    for j in 0..=ny {
        m.supports.push(Support::clamp(ids[j * (nx + 1)]));
    }
    let mut lc = LoadCase::new("M");
    for j in 0..=ny {
        let share = if j == 0 || j == ny { 0.5 } else { 1.0 } / ny as f64;
        lc = lc.force(ids[j * (nx + 1) + nx], [0.0, 0.0, 0.0, 0.0, mm * share, 0.0]);
    }
    m.load_cases.push(lc);
    let r = fem::solve_static(&m).unwrap();
    let sigma = 6.0 * mm / (b * t * t);
    let e = &r.load_cases[0].elements[(ny / 2) * nx + nx / 2];
    let s = e.shell.unwrap();
    eprintln!(
        "pure bending: vM top/mid/bottom = {:?}, beam theory {sigma}",
        s.von_mises
    );
    assert!((s.von_mises[0] - sigma).abs() < 0.01 * sigma);
    assert!((s.von_mises[2] - sigma).abs() < 0.01 * sigma);
    assert!(s.von_mises[1] < 1e-6 * sigma);
    // Moment resultant m_xx = M/b.
    assert!((s.m[0].abs() - mm / b).abs() < 0.01 * mm / b, "m = {:?}", s.m);
}

/// Thin twisted beam (t = 0.0032, P = 1e-6; T. Belytschko, B. L. Wong, H. Stolarski, IJNME 28
/// (1989) 385: 5.256e-3 in-plane, 1.294e-3 out-of-plane). 2×12: 5.2818e-3 (+0.49 %),
/// 1.2996e-3 (+0.43 %); 4×24: 5.2599e-3 (+0.07 %), 1.2951e-3 (+0.09 %) — no locking at
/// L/t = 3750.
#[test]
fn twisted_beam_thin() {
    for (nw, nl) in [(2, 12), (4, 24)] {
        let a = twisted_beam_t(nw, nl, 2, 0.0032, 1e-6);
        let b = twisted_beam_t(nw, nl, 1, 0.0032, 1e-6);
        eprintln!(
            "thin twisted beam {nw}x{nl}: {a:.5e} ({:.2} %), {b:.5e} ({:.2} %)",
            100.0 * (a - 5.256e-3) / 5.256e-3,
            100.0 * (b - 1.294e-3) / 1.294e-3
        );
        assert!(((a - 5.256e-3) / 5.256e-3).abs() < 0.02 && ((b - 1.294e-3) / 1.294e-3).abs() < 0.02);
    }
}

/// Shells, beams, a ground spring and rigid links in one model: a square plate stiffened by a
/// beam joined through rigid links, clamped on one edge, with a spring under a free corner.
/// Loads and reactions balance (PyNite-style statics check) and every shell has stresses.
#[test]
fn mixed_shell_beam_spring_rigid_statics() {
    let n = 6;
    let mut m = Model::new();
    let ids = grid(&mut m, n, n, 2.0, Material::AL7075, |s, r| [60.0 * s, 60.0 * r, 0.0]);
    let b0 = m.add_node([0.0, 30.0, 6.0]);
    let b1 = m.add_node([60.0, 30.0, 6.0]);
    m.add_beam(fem::Beam::new(
        b0,
        b1,
        fem::Section::Rect { w: 3.0, h: 8.0 },
        Material::AL7075,
        [0.0, 0.0, 1.0],
    ));
    m.rigid_links.push(fem::RigidLink {
        master: ids[3 * (n + 1)],
        slaves: vec![b0],
    });
    m.rigid_links.push(fem::RigidLink {
        master: ids[3 * (n + 1) + n],
        slaves: vec![b1],
    });
    m.add_element(Element::Spring(fem::Spring {
        a: ids[n * (n + 1) + n],
        b: None,
        k: [0.0, 0.0, 50.0, 0.0, 0.0, 0.0],
        axes: fem::SpringAxes::Global,
    }));
    for j in 0..=n {
        m.supports.push(Support::clamp(ids[j * (n + 1)]));
    }
    m.load_cases.push(
        LoadCase::new("tip")
            .force(ids[n], [0.0, 0.0, -20.0, 0.0, 0.0, 0.0])
            .force(b1, [5.0, 0.0, -10.0, 0.0, 100.0, 0.0]),
    );
    let r = fem::solve_static(&m).unwrap();
    let c = &r.load_cases[0];
    assert!(c.statics.is_balanced(1e-8, 60.0), "{:?}", c.statics);
    assert!(c.elements.iter().filter(|e| e.shell.is_some()).count() == n * n);
    assert!(c.max_von_mises.unwrap() > 0.0);
}

/// OpenSees 3.7.1 (openseespy 3.7.1.2; `tools/opensees_shell.py`, the same meshes, supports and
/// nodal loads): the displacement each builder above returns, on the meshes n = 32 and 64, for
/// ShellMITC4 and ASDShellQ4.
const OPENSEES: [(&str, [f64; 2], [f64; 2]); 3] = [
    (
        "Scordelis-Lo",
        [0.298_337_609_0, 0.300_521_302_7],
        [0.301_655_885_4, 0.301_370_510_5],
    ),
    (
        "pinched cylinder",
        [1.802_466_65e-5, 1.836_510_03e-5],
        [1.805_388_03e-5, 1.837_231_09e-5],
    ),
    (
        "pinched hemisphere",
        [0.093_080_466_8, 0.093_472_415_5],
        [0.093_388_202_9, 0.093_526_679_6],
    ),
];

/// The curved benchmarks converged: Richardson (4u₆₄ − u₃₂)/3 of `scordelis_lo` (full roof),
/// `pinched_cylinder` (octant) and `pinched_hemisphere` (quarter) against the same extrapolation
/// of both OpenSees elements, within 0.3 % (measured: roof 0.301273, +0.01 % / −0.00 %;
/// cylinder 1.84784e-5, −0.00 % / −0.00 %; hemisphere 0.093573, −0.03 % / −0.00 %).
#[test]
fn curved_shells_extrapolated_match_opensees() {
    let ours: [fn(usize) -> f64; 3] = [scordelis_lo, pinched_cylinder, |n| pinched_hemisphere(n).0];
    let ext = |u: [f64; 2]| (4.0 * u[1] - u[0]) / 3.0;
    // zip-checked: both are arrays of 3, fixed by their types.
    for ((name, mitc4, asdq4), f) in OPENSEES.iter().zip(ours) {
        let e = ext([f(32), f(64)]);
        within(&format!("{name} extrapolated vs ShellMITC4"), e, ext(*mitc4), 3e-3);
        within(&format!("{name} extrapolated vs ASDShellQ4"), e, ext(*asdq4), 3e-3);
    }
}
