//! Gravity, beam line loads and group loads (flexfem::fem::loads) against closed forms:
//! cantilever under self-weight, simply supported and clamped beams under a uniform load, and
//! plate strips under edge loads spread over a node group. Closed forms: S. Timoshenko, J. Gere,
//! Mechanics of Materials (beam deflection tables); consistent loads of the beam element give
//! nodal displacements exact to round-off (Euler–Bernoulli and Timoshenko), so beam tolerances
//! are 1e-9 relative.

use flexfem::fem::loads::{
    add_to_case, beam_line_load, centroid, gravity_loads, resultant, spread_total, tributary_weights, LoadAxes,
};
use flexfem::fem::{solve_static, Beam, Dof, Element, LoadCase, Model, Section, Shell4, Support};
use flexfem::material::Material;

const STEEL: Material = Material::STEEL;
const L: f64 = 100.0;
const W: f64 = 10.0;
const H: f64 = 5.0;

fn rel(a: f64, b: f64) -> f64 {
    (a - b).abs() / b.abs()
}

/// Beam of `n` elements along `dir` (unit), rectangle W × H with H along local z.
fn beam_line(n: usize, dir: [f64; 3], up: [f64; 3], shear: bool) -> Model {
    let mut m = Model::new();
    for i in 0..=n {
        let s = L * i as f64 / n as f64;
        m.add_node([s * dir[0], s * dir[1], s * dir[2]]);
    }
    for i in 0..n {
        let mut b = Beam::new(i, i + 1, Section::Rect { w: W, h: H }, STEEL, up);
        b.shear = shear;
        m.add_beam(b);
    }
    m
}

fn iy() -> f64 {
    W * H.powi(3) / 12.0
}

/// Cantilever under its own weight: tip deflection qL⁴/(8EI) (+ qL²/(2 κGA) with shear),
/// root moment qL²/2 and root force qL, q = ρ A g.
#[test]
fn cantilever_self_weight() {
    let g = 9810.0;
    let q = STEEL.density * W * H * g;
    for shear in [false, true] {
        let mut m = beam_line(10, [1.0, 0.0, 0.0], [0.0, 0.0, 1.0], shear);
        m.supports.push(Support::clamp(0));
        let loads = gravity_loads(&m, [0.0, 0.0, -g]).unwrap();
        let mut case = LoadCase::new("g");
        add_to_case(&mut case, loads.iter().copied().enumerate());
        // Resultant = total mass × g.
        let r = resultant(&m, &loads.iter().copied().enumerate().collect::<Vec<_>>(), [0.0; 3]);
        assert!(rel(r[2], -q * L) < 1e-12, "{r:?}");
        m.load_cases.push(case);
        let res = &solve_static(&m).unwrap().load_cases[0];
        let p = Section::Rect { w: W, h: H }.properties(STEEL.nu);
        let mut w_exact = q * L.powi(4) / (8.0 * STEEL.e * iy());
        if shear {
            w_exact += q * L * L / (2.0 * STEEL.shear_modulus() * p.asz.unwrap());
        }
        let w = -res.displacements[10][2];
        eprintln!("self-weight cantilever shear {shear}: tip rel {:.3e}", rel(w, w_exact));
        assert!(rel(w, w_exact) < 1e-9, "shear {shear}: tip {w} vs {w_exact}");
        let (node, reac) = res.reactions[0];
        assert_eq!(node, 0);
        assert!(rel(reac[2], q * L) < 1e-9, "{reac:?}");
        // The support holds the weight at arm L/2: My = −qL²/2 (z down at +x).
        assert!(rel(reac[4], -q * L * L / 2.0) < 1e-9, "{reac:?}");
    }
}

/// Simply supported beam under a uniform line load: midspan 5qL⁴/(384EI); clamped–clamped:
/// qL⁴/(384EI). The beam runs along an inclined axis; the load is given in local axes (local
/// z) and, equivalently, in global axes.
#[test]
fn uniformly_loaded_beams() {
    let dir = [0.6, 0.0, 0.8];
    let up = [-0.8, 0.0, 0.6]; // local z = up (normal to the axis)
    let q = -0.7;
    for clamped in [false, true] {
        for axes in [LoadAxes::Local, LoadAxes::Global] {
            let mut m = beam_line(8, dir, up, false);
            if clamped {
                m.supports.push(Support::clamp(0));
                m.supports.push(Support::clamp(8));
            } else {
                m.supports
                    .push(Support::dofs(0, &[Dof::Ux, Dof::Uy, Dof::Uz, Dof::Rx, Dof::Rz]));
                // Roller normal to the inclined axis: node frame (x along the beam, z = up).
                m.set_frame(8, [dir, [0.0, 1.0, 0.0], up]);
                m.supports.push(Support::dofs(8, &[Dof::Uy, Dof::Uz]));
            }
            let qv = match axes {
                LoadAxes::Local => [0.0, 0.0, q],
                LoadAxes::Global => [up[0] * q, up[1] * q, up[2] * q],
            };
            let mut case = LoadCase::new("q");
            for ie in 0..8 {
                let f = beam_line_load(&m, ie, qv, axes).unwrap();
                let Element::Beam(b) = &m.elements[ie] else {
                    unreachable!()
                };
                add_to_case(&mut case, [(b.nodes[0], f[0]), (b.nodes[1], f[1])]);
            }
            let total = resultant(
                &m,
                &case.forces.iter().map(|l| (l.node, l.f)).collect::<Vec<_>>(),
                [0.0; 3],
            );
            for k in 0..3 {
                assert!((total[k] - up[k] * q * L).abs() < 1e-12 * L, "{total:?}");
            }
            m.load_cases.push(case);
            let res = &solve_static(&m).unwrap().load_cases[0];
            let d = res.displacements[4];
            let w = d[0] * up[0] + d[1] * up[1] + d[2] * up[2];
            let k = if clamped { 1.0 } else { 5.0 };
            let exact = k * q * L.powi(4) / (384.0 * STEEL.e * iy());
            eprintln!("uniform beam clamped {clamped} {axes:?}: rel {:.3e}", rel(w, exact));
            assert!(rel(w, exact) < 1e-9, "clamped {clamped} {axes:?}: {w} vs {exact}");
        }
    }
}

/// Flat plate strip in the x–y plane, `nx` × `ny` four-node shells, L × B × t, ν as given.
fn plate(nx: usize, ny: usize, b: f64, t: f64, nu: f64) -> (Model, Vec<Vec<usize>>) {
    let mut m = Model::new();
    let id = |i: usize, j: usize| j * (nx + 1) + i;
    for j in 0..=ny {
        for i in 0..=nx {
            m.add_node([L * i as f64 / nx as f64, b * j as f64 / ny as f64, 0.0]);
        }
    }
    let mat = Material { nu, ..STEEL };
    for j in 0..ny {
        for i in 0..nx {
            m.add_element(Element::Shell4(Shell4 {
                nodes: [id(i, j), id(i + 1, j), id(i + 1, j + 1), id(i, j + 1)],
                t,
                material: mat,
            }));
        }
    }
    let tip: Vec<Vec<usize>> = (0..ny).map(|j| vec![id(nx, j), id(nx, j + 1)]).collect();
    (m, tip)
}

fn group_case(m: &Model, cells: &[Vec<usize>], total: [f64; 6]) -> LoadCase {
    let w = tributary_weights(m, cells).unwrap();
    let f = spread_total(m, &w, total).unwrap();
    let c = centroid(m, &w);
    let r = resultant(m, &f, c);
    for k in 0..6 {
        assert!(
            (r[k] - total[k]).abs() <= 1e-12 * total.iter().fold(1.0f64, |a, v| a.max(v.abs())),
            "{r:?}"
        );
    }
    let mut case = LoadCase::new("edge");
    add_to_case(&mut case, f);
    case
}

/// Membrane stretch of a plate strip by a total edge force F spread over the loaded edge by
/// tributary length: uniform stress, end displacement F L/(E B t) — a constant-strain state the
/// shell's membrane reproduces exactly, so 1e-9.
#[test]
fn plate_edge_stretch() {
    let (b, t, f) = (20.0, 1.0, 150.0);
    let (nx, ny) = (5, 4);
    let (mut m, tip) = plate(nx, ny, b, t, 0.3);
    for n in 0..m.nodes.len() {
        let x = m.nodes[n];
        let mut fix = vec![Dof::Uz, Dof::Rx, Dof::Ry];
        if x[0] == 0.0 {
            fix.push(Dof::Ux);
            if x[1] == 0.0 {
                fix.push(Dof::Uy);
            }
        }
        m.supports.push(Support::dofs(n, &fix));
    }
    m.load_cases.push(group_case(&m, &tip, [f, 0.0, 0.0, 0.0, 0.0, 0.0]));
    let res = &solve_static(&m).unwrap().load_cases[0];
    let exact = f * L / (STEEL.e * b * t);
    for line in &tip {
        for &n in line {
            let u = res.displacements[n][0];
            eprintln!("plate stretch node {n}: rel {:.3e}", rel(u, exact));
            assert!(rel(u, exact) < 1e-9, "node {n}: {u} vs {exact}");
        }
    }
}

/// Cantilever plate strip (ν = 0, so the strip bends as a beam with I = B t³/12) clamped along
/// x = 0: a tip edge shear P spread over the tip edge gives w = PL³/(3EI) + PL/(κGA); a tip
/// edge moment M (about y, applied as nodal moments: a straight edge has no lever arm about its
/// own direction) gives w = ML²/(2EI). Measured: shear 4.8e-4 (MITC4 discretisation at 20 × 2
/// elements; tolerance 1e-3), moment 1e-10 (pure bending is exact; tolerance 1e-8).
#[test]
fn plate_strip_tip_loads() {
    let (b, t) = (10.0, 1.0);
    let (mut m, tip) = plate(20, 2, b, t, 0.0);
    for n in 0..m.nodes.len() {
        if m.nodes[n][0] == 0.0 {
            m.supports.push(Support::clamp(n));
        }
    }
    let ei = STEEL.e * b * t.powi(3) / 12.0;
    let ga = STEEL.e / 2.0 * b * t * 5.0 / 6.0;
    let (p, mom) = (-0.2, 30.0);
    m.load_cases.push(group_case(&m, &tip, [0.0, 0.0, p, 0.0, 0.0, 0.0]));
    let mut mc = group_case(&m, &tip, [0.0, 0.0, 0.0, 0.0, mom, 0.0]);
    mc.name = "moment".into();
    m.load_cases.push(mc);
    let res = solve_static(&m).unwrap();
    let mid = tip[0][1];
    let w = res.load_cases[0].displacements[mid][2];
    let exact = p * L.powi(3) / (3.0 * ei) + p * L / ga;
    eprintln!("plate strip tip shear: {w:e} vs {exact:e}, rel {:.3e}", rel(w, exact));
    assert!(rel(w, exact) < 1e-3, "shear: {w} vs {exact} ({:.2e})", rel(w, exact));
    // +My bends the tip down (θy = −dw/dx).
    let w = res.load_cases[1].displacements[mid][2];
    let exact = -mom * L * L / (2.0 * ei);
    eprintln!("plate strip tip moment: {w:e} vs {exact:e}, rel {:.3e}", rel(w, exact));
    assert!(rel(w, exact) < 1e-8, "moment: {w} vs {exact} ({:.2e})", rel(w, exact));
}

/// Cantilever plate strip (ν = 0) under its own weight: the shells' lumped mass gives nodal
/// forces only (no consistent end moments), so the tip deflection converges to
/// qL⁴/(8EI) + qL²/(2κGA), q = ρ B t g, at O(h²): measured 1.3e-4 at 40 × 2 elements, tolerance
/// 1e-3. The resultant is the total mass × g to 1e-12.
#[test]
fn plate_strip_self_weight() {
    let (b, t, g) = (10.0, 1.0, 9810.0);
    let (mut m, tip) = plate(40, 2, b, t, 0.0);
    for n in 0..m.nodes.len() {
        if m.nodes[n][0] == 0.0 {
            m.supports.push(Support::clamp(n));
        }
    }
    let loads: Vec<(usize, [f64; 6])> = gravity_loads(&m, [0.0, 0.0, -g])
        .unwrap()
        .into_iter()
        .enumerate()
        .collect();
    let q = STEEL.density * b * t * g;
    let r = resultant(&m, &loads, [0.0; 3]);
    assert!(rel(r[2], -q * L) < 1e-12, "{r:?}");
    let mut case = LoadCase::new("g");
    add_to_case(&mut case, loads);
    m.load_cases.push(case);
    let res = &solve_static(&m).unwrap().load_cases[0];
    let ei = STEEL.e * b * t.powi(3) / 12.0;
    let ga = STEEL.e / 2.0 * b * t * 5.0 / 6.0;
    let exact = -(q * L.powi(4) / (8.0 * ei) + q * L * L / (2.0 * ga));
    let w = res.displacements[tip[0][1]][2];
    eprintln!("plate strip self-weight: {w:e} vs {exact:e}, rel {:.3e}", rel(w, exact));
    assert!(rel(w, exact) < 1e-3, "{w} vs {exact}");
}
