//! Rigid links, springs, supports and prescribed displacements (elimination, SPD).

use flexfem::fem::solve::Parallelism;
use flexfem::fem::{
    solve_static, Beam, Dof, Element, FemError, LoadCase, Model, RigidLink, Section, Spring, SpringAxes, Support,
    System,
};
use flexfem::material::Material;

const STEEL: Material = Material::STEEL;

fn close(a: f64, b: f64, rel: f64) -> bool {
    (a - b).abs() <= rel * b.abs().max(1e-300)
}

macro_rules! assert_close {
    ($a:expr, $b:expr) => {{
        let (a, b) = ($a, $b);
        assert!(close(a, b, 1e-6), "{} = {a:e}, expected {b:e}", stringify!($a));
    }};
}

fn spring(a: usize, b: Option<usize>, k: [f64; 6]) -> Element {
    Element::Spring(Spring::global(a, b, k))
}

/// A rigid link from `master` to the one node `slave`.
fn link(master: usize, slave: usize) -> RigidLink {
    RigidLink {
        master,
        slaves: vec![slave],
    }
}

#[test]
fn rigid_link_in_a_cantilever() {
    // Beam 0–1 (L1), rigid link 1 → 2 (length a along x), beam 2–3 (L2), tip load P along z.
    // Euler–Bernoulli: M1 = P(a+L2); w1 = P L1³/3EI + M1 L1²/2EI; θ1 = P L1²/2EI + M1 L1/EI;
    // w2 = w1 + θ1 a; w3 = w2 + θ1 L2 + P L2³/3EI (slopes as magnitudes, all in the same sense).
    let (l1, a, l2, p) = (60.0, 25.0, 40.0, 3.0);
    let sec = Section::Rect { w: 8.0, h: 4.0 };
    let mut m = Model::new();
    for x in [0.0, l1, l1 + a, l1 + a + l2] {
        m.add_node([x, 0.0, 0.0]);
    }
    m.add_beam(Beam::new(0, 1, sec, STEEL, [0.0, 0.0, 1.0]).euler_bernoulli());
    m.add_beam(Beam::new(2, 3, sec, STEEL, [0.0, 0.0, 1.0]).euler_bernoulli());
    m.rigid_links.push(link(1, 2));
    m.supports.push(Support::clamp(0));
    m.load_cases = vec![LoadCase::new("P").force(3, [0.0, 0.0, p, 0.0, 0.0, 0.0])];
    let r = solve_static(&m).unwrap();
    let ei = STEEL.e * 8.0 * 64.0 / 12.0;
    let m1 = p * (a + l2);
    let w1 = p * l1.powi(3) / (3.0 * ei) + m1 * l1 * l1 / (2.0 * ei);
    let th1 = p * l1 * l1 / (2.0 * ei) + m1 * l1 / ei;
    let w2 = w1 + th1 * a;
    let th3 = th1 + p * l2 * l2 / (2.0 * ei);
    let w3 = w2 + th1 * l2 + p * l2.powi(3) / (3.0 * ei);
    let u = &r.load_cases[0].displacements;
    assert_close!(u[1][2], w1);
    assert_close!(u[2][2], w2);
    assert_close!(u[3][2], w3);
    assert_close!(-u[3][4], th3);
    assert_close!(u[2][4], u[1][4]);
    // The system is SPD without penalty: the slave has no equations.
    let sys = System::new(&m, &[], Parallelism::Sequential).unwrap();
    assert_eq!(sys.dof_map().n_eq(), 6 * 3 - 6);
}

#[test]
fn load_on_a_rigid_link_slave_equals_force_plus_moment_at_master() {
    // Force F at slave offset r from master ⇔ F and r × F at the master; slave motion
    // u_s = u_m + θ_m × r.
    let sec = Section::Circle { d: 5.0 };
    let mut base = Model::new();
    base.add_node([0.0, 0.0, 0.0]);
    base.add_node([50.0, 0.0, 0.0]);
    base.add_beam(Beam::new(0, 1, sec, STEEL, [0.0, 0.0, 1.0]));
    base.supports.push(Support::clamp(0));
    let mut ml = base.clone();
    let s = ml.add_node([50.0, 10.0, -5.0]);
    ml.rigid_links.push(link(1, s));
    let f = [2.0, -1.0, 3.0];
    let rv = [0.0, 10.0, -5.0];
    let mom = [
        rv[1] * f[2] - rv[2] * f[1],
        rv[2] * f[0] - rv[0] * f[2],
        rv[0] * f[1] - rv[1] * f[0],
    ];
    ml.load_cases = vec![LoadCase::new("s").force(s, [f[0], f[1], f[2], 0.0, 0.0, 0.0])];
    base.load_cases = vec![LoadCase::new("m").force(1, [f[0], f[1], f[2], mom[0], mom[1], mom[2]])];
    let (rl, rb) = (solve_static(&ml).unwrap(), solve_static(&base).unwrap());
    let (ul, ub) = (&rl.load_cases[0].displacements, &rb.load_cases[0].displacements);
    for d in 0..6 {
        assert!((ul[1][d] - ub[1][d]).abs() < 1e-12 + 1e-9 * ub[1][d].abs());
    }
    let th = [ub[1][3], ub[1][4], ub[1][5]];
    let cross = [
        th[1] * rv[2] - th[2] * rv[1],
        th[2] * rv[0] - th[0] * rv[2],
        th[0] * rv[1] - th[1] * rv[0],
    ];
    for i in 0..3 {
        assert_close!(ul[s][i], ub[1][i] + cross[i]);
    }
    assert!(rl.load_cases[0].statics.is_balanced(1e-9, 50.0));
}

#[test]
fn springs_in_series_and_parallel_and_to_ground() {
    // Series: u = F(1/k1 + 1/k2); parallel: u = F/(k1 + k2); ground: u = F/k.
    let (k1, k2, f) = (200.0, 300.0, 12.0);
    let kk = |kx: f64| [kx, 1e6, 1e6, 1e6, 1e6, 1e6];
    let mut m = Model::new();
    for x in [0.0, 10.0, 20.0] {
        m.add_node([x, 0.0, 0.0]);
    }
    m.supports.push(Support::clamp(0));
    m.add_element(spring(0, Some(1), kk(k1)));
    m.add_element(spring(1, Some(2), kk(k2)));
    // Parallel pair 3–4, 4 on ground springs 4 (two in parallel).
    let n3 = m.add_node([30.0, 0.0, 0.0]);
    m.add_element(spring(n3, None, kk(k1)));
    m.add_element(spring(n3, None, kk(k2)));
    m.load_cases = vec![LoadCase::new("F")
        .force(2, [f, 0.0, 0.0, 0.0, 0.0, 0.0])
        .force(n3, [f, 0.0, 0.0, 0.0, 0.0, 0.0])];
    let r = solve_static(&m).unwrap();
    let u = &r.load_cases[0].displacements;
    assert_close!(u[2][0], f * (1.0 / k1 + 1.0 / k2));
    assert_close!(u[n3][0], f / (k1 + k2));
    assert!(r.load_cases[0].statics.is_balanced(1e-9, 30.0));
    // Spring force recovery: f in the spring axes.
    assert_close!(r.load_cases[0].elements[1].section_forces[1][0], f);
}

#[test]
fn spring_in_local_axes() {
    // Spring along the diagonal x' = (1,1,0)/√2 with kx' = k, all else 0 except rotations; a
    // force along x' gives u = F/k along x'.
    let k = 500.0;
    let mut m = Model::new();
    let a = m.add_node([0.0, 0.0, 0.0]);
    let b = m.add_node([0.0, 0.0, 0.0]);
    m.supports.push(Support::clamp(a));
    m.supports.push(Support::dofs(b, &[Dof::Uz, Dof::Rx, Dof::Ry, Dof::Rz]));
    m.add_element(Element::Spring(Spring {
        a,
        b: Some(b),
        k: [k, 4.0 * k, 0.0, 1.0, 1.0, 1.0],
        axes: SpringAxes::from_x_up([1.0, 1.0, 0.0], [0.0, 0.0, 1.0]).unwrap(),
    }));
    let s = 0.5f64.sqrt();
    let f = 10.0;
    m.load_cases = vec![
        LoadCase::new("x'").force(b, [f * s, f * s, 0.0, 0.0, 0.0, 0.0]),
        LoadCase::new("y'").force(b, [-f * s, f * s, 0.0, 0.0, 0.0, 0.0]),
    ];
    let r = solve_static(&m).unwrap();
    let u = r.load_cases[0].displacements[b];
    assert_close!(u[0], f / k * s);
    assert_close!(u[1], f / k * s);
    let u = r.load_cases[1].displacements[b];
    assert_close!(u[1], f / (4.0 * k) * s);
}

#[test]
fn prescribed_displacement_on_a_supported_dof_and_grouped_cases() {
    // Support settlement: a prescribed value on a supported DOF overrides the zero.
    // Cases with different prescribed DOF sets are grouped and solved on their own factors.
    let sec = Section::Rect { w: 5.0, h: 5.0 };
    let mut m = Model::new();
    for x in [0.0, 50.0, 100.0] {
        m.add_node([x, 0.0, 0.0]);
    }
    m.add_beam(Beam::new(0, 1, sec, STEEL, [0.0, 0.0, 1.0]).euler_bernoulli());
    m.add_beam(Beam::new(1, 2, sec, STEEL, [0.0, 0.0, 1.0]).euler_bernoulli());
    m.supports = vec![Support::clamp(0), Support::dofs(2, &[Dof::Uz])];
    m.load_cases = vec![
        LoadCase::new("settle").displacement(2, Dof::Uz, -0.5),
        LoadCase::new("tip").displacement(2, Dof::Uy, 0.2),
        LoadCase::new("settle2").displacement(2, Dof::Uz, -1.0),
        LoadCase::new("free"),
    ];
    let r = solve_static(&m).unwrap();
    assert_eq!(r.load_cases.len(), 4);
    assert_eq!(r.load_cases[1].name, "tip");
    assert_close!(r.load_cases[0].displacements[2][2], -0.5);
    assert_close!(
        r.load_cases[2].displacements[1][2],
        2.0 * r.load_cases[0].displacements[1][2]
    );
    assert_close!(r.load_cases[1].displacements[2][1], 0.2);
    // Propped cantilever settling by δ: reaction 3EIδ/L³ (Roark Table 8.1 case 1c).
    let ei = STEEL.e * 5f64.powi(4) / 12.0;
    let rz = r.load_cases[0].reactions.iter().find(|x| x.0 == 2).unwrap().1[2];
    assert_close!(rz, -3.0 * ei * 0.5 / 100f64.powi(3));
    assert!(r.load_cases[3]
        .displacements
        .iter()
        .all(|u| u.iter().all(|v| *v == 0.0)));
}

fn small_frame() -> Model {
    let mut m = Model::new();
    for x in [0.0, 10.0, 20.0, 30.0] {
        m.add_node([x, 0.0, 0.0]);
    }
    for i in 0..3 {
        m.add_beam(Beam::new(i, i + 1, Section::Circle { d: 2.0 }, STEEL, [0.0, 0.0, 1.0]));
    }
    m.supports.push(Support::clamp(0));
    m
}

fn over(m: &Model) -> String {
    match System::new(m, &[], Parallelism::Sequential) {
        Err(e @ FemError::OverConstrained(_)) => e.to_string(),
        other => panic!("expected OverConstrained, got {other:?}"),
    }
}

#[test]
fn conflicting_rigid_links_and_supports_are_named() {
    let mut m = small_frame();
    m.rigid_links = vec![link(1, 3), link(2, 3)];
    let e = over(&m);
    assert!(
        e.contains("node 3 is a slave of rigid link 0 (master 1) and of rigid link 1 (master 2)"),
        "{e}"
    );

    m.rigid_links = vec![link(1, 2), link(2, 3)];
    let e = over(&m);
    assert!(
        e.contains("node 2 is the master of rigid link 1 and a slave of rigid link 0"),
        "{e}"
    );

    m.rigid_links = vec![link(1, 1)];
    assert!(over(&m).contains("node 1 is listed as its own slave"));

    m.rigid_links = vec![link(2, 3)];
    m.supports.push(Support::dofs(3, &[Dof::Uz, Dof::Rx]));
    let e = over(&m);
    assert!(
        e.contains("node 3 uz, rx is supported but node 3 is a slave of rigid link 0"),
        "{e}"
    );

    m.supports.pop();
    m.load_cases = vec![LoadCase::new("c").displacement(3, Dof::Uy, 1.0)];
    let e = solve_static(&m).unwrap_err().to_string();
    assert!(
        e.contains("node 3 uy is prescribed in load case \"c\" but node 3 is a slave of rigid link 0"),
        "{e}"
    );

    m.load_cases = vec![LoadCase::new("c")
        .displacement(2, Dof::Uy, 1.0)
        .displacement(2, Dof::Uy, 2.0)];
    let e = solve_static(&m).unwrap_err().to_string();
    assert!(e.contains("node 2 uy is prescribed twice"), "{e}");
}
