//! Prismatic beams against closed-form solutions (relative 1e-6 unless stated).

use flexfem::fem::element::{beam_local_stiffness, cantilever_compliance, flex_local_stiffness};
use flexfem::fem::section::rect_torsion;
use flexfem::fem::solve::Parallelism;
use flexfem::fem::{solve_static, Beam, Dof, Element, FlexElement, LoadCase, Model, NodeDof, Section, Support, System};
use flexfem::material::Material;
use std::f64::consts::PI;

const STEEL: Material = Material::STEEL;

fn close(a: f64, b: f64, rel: f64) -> bool {
    (a - b).abs() <= rel * b.abs().max(1e-300)
}

macro_rules! assert_close {
    ($a:expr, $b:expr) => {
        assert_close!($a, $b, 1e-6)
    };
    ($a:expr, $b:expr, $rel:expr) => {{
        let (a, b) = ($a, $b);
        assert!(
            close(a, b, $rel),
            "{} = {a:e}, expected {b:e} (rel {})",
            stringify!($a),
            $rel
        );
    }};
}

/// Cantilever along +x, `n` elements, clamped at node 0, tip = node n.
fn cantilever(n: usize, l: f64, section: Section, shear: bool) -> Model {
    let mut m = Model::new();
    for i in 0..=n {
        m.add_node([l * i as f64 / n as f64, 0.0, 0.0]);
    }
    for i in 0..n {
        let mut b = Beam::new(i, i + 1, section, STEEL, [0.0, 0.0, 1.0]);
        b.shear = shear;
        m.add_beam(b);
    }
    m.supports.push(Support::clamp(0));
    m
}

fn tip(m: &Model, f: [f64; 6]) -> [f64; 6] {
    let mut m = m.clone();
    let n = m.nodes.len() - 1;
    m.load_cases = vec![LoadCase::new("tip").force(n, f)];
    solve_static(&m).unwrap().load_cases[0].displacements[n]
}

const L: f64 = 100.0;
const W: f64 = 10.0;
const H: f64 = 5.0;
fn iy() -> f64 {
    W * H.powi(3) / 12.0
}
fn iz() -> f64 {
    H * W.powi(3) / 12.0
}

#[test]
fn cantilever_euler_bernoulli_tip_force_and_moment() {
    // Gere & Timoshenko, Mechanics of Materials, Table G-1 cases 4 and 6:
    // δ = PL³/3EI, θ = PL²/2EI (end force); θ = ML/EI, δ = ML²/2EI (end moment).
    let e = STEEL.e;
    for n in [1, 4] {
        let m = cantilever(n, L, Section::Rect { w: W, h: H }, false);
        let (p, mo) = (10.0, 500.0);
        let u = tip(&m, [0.0, 0.0, p, 0.0, 0.0, 0.0]);
        assert_close!(u[2], p * L.powi(3) / (3.0 * e * iy()));
        assert_close!(u[4], -p * L * L / (2.0 * e * iy())); // θy = −dw/dx
        let u = tip(&m, [0.0, p, 0.0, 0.0, 0.0, 0.0]);
        assert_close!(u[1], p * L.powi(3) / (3.0 * e * iz()));
        assert_close!(u[5], p * L * L / (2.0 * e * iz()));
        let u = tip(&m, [0.0, 0.0, 0.0, 0.0, mo, 0.0]);
        assert_close!(u[4], mo * L / (e * iy()));
        assert_close!(u[2], -mo * L * L / (2.0 * e * iy()));
        let u = tip(&m, [0.0, 0.0, 0.0, 0.0, 0.0, mo]);
        assert_close!(u[5], mo * L / (e * iz()));
        assert_close!(u[1], mo * L * L / (2.0 * e * iz()));
    }
}

#[test]
fn cantilever_timoshenko_adds_shear_term() {
    // Timoshenko & Gere: δ = PL³/3EI + PL/(κGA); κ = Cowper 10(1+ν)/(12+11ν) for a rectangle.
    let nu = STEEL.nu;
    let kappa = 10.0 * (1.0 + nu) / (12.0 + 11.0 * nu);
    let g = STEEL.shear_modulus();
    for n in [1, 3] {
        let m = cantilever(n, L, Section::Rect { w: W, h: H }, true);
        let u = tip(&m, [0.0, 0.0, 10.0, 0.0, 0.0, 0.0]);
        let exact = 10.0 * L.powi(3) / (3.0 * STEEL.e * iy()) + 10.0 * L / (kappa * g * W * H);
        assert_close!(u[2], exact);
        // Rotation unaffected by shear: PL²/2EI.
        assert_close!(u[4], -10.0 * L * L / (2.0 * STEEL.e * iy()));
    }
}

#[test]
fn short_shear_dominated_timoshenko_beam() {
    // L = h: shear term PL/(κGA) is a large part of the deflection (same closed form).
    let (l, h) = (8.0, 10.0);
    let nu = STEEL.nu;
    let kappa = 10.0 * (1.0 + nu) / (12.0 + 11.0 * nu);
    let g = STEEL.shear_modulus();
    let m = cantilever(2, l, Section::Rect { w: 10.0, h }, true);
    let u = tip(&m, [0.0, 0.0, 100.0, 0.0, 0.0, 0.0]);
    let i = 10.0 * h.powi(3) / 12.0;
    let bend = 100.0 * l.powi(3) / (3.0 * STEEL.e * i);
    let shear = 100.0 * l / (kappa * g * 10.0 * h);
    assert!(
        shear > 0.4 * bend,
        "shear part {shear} should dominate-ish vs bending {bend}"
    );
    assert_close!(u[2], bend + shear);
}

#[test]
fn torsion_of_rectangular_bar_series() {
    // Timoshenko & Goodier §109: J = β a b³, β = ⅓(1 − (192/π⁵)(b/a) Σ tanh(nπa/2b)/n⁵);
    // brute-force series (n ≤ 200001) as reference; table values β(1) = 0.1406,
    // β(2) = 0.229, β(10) = 0.312; α(1) = 0.208, α(2) = 0.246, α(10) = 0.312.
    for (r, beta_tab, alpha_tab) in [(1.0, 0.1406, 0.208), (2.0, 0.229, 0.246), (10.0, 0.312, 0.312)] {
        let (a, b) = (r * 3.0, 3.0);
        let t = rect_torsion(b, a);
        let mut s = 0.0;
        let mut n = 1.0f64;
        while n < 200_001.0 {
            s += (n * PI * r / 2.0).tanh() / n.powi(5);
            n += 2.0;
        }
        let beta = (1.0 - 192.0 / PI.powi(5) / r * s) / 3.0;
        assert_close!(t.beta, beta, 1e-12);
        assert_close!(t.j, beta * a * b.powi(3), 1e-12);
        assert_close!(t.beta, beta_tab, 2e-3);
        assert_close!(t.alpha, alpha_tab, 3e-3);
    }
    // Twist of a cantilever: θ = TL/(GJ); peak shear τ = T/(α a b²) ⇒ von Mises √3 τ.
    let (w, h, torque) = (4.0, 12.0, 1000.0);
    let m = cantilever(3, L, Section::Rect { w, h }, true);
    let u = tip(&m, [0.0, 0.0, 0.0, torque, 0.0, 0.0]);
    let t = rect_torsion(w, h);
    assert_close!(u[3], torque * L / (STEEL.shear_modulus() * t.j));
    let mut mm = m.clone();
    mm.load_cases = vec![LoadCase::new("T").force(3, [0.0, 0.0, 0.0, torque, 0.0, 0.0])];
    let r = solve_static(&mm).unwrap();
    let tau = torque / (t.alpha * h * w * w);
    assert_close!(r.load_cases[0].max_von_mises.unwrap(), 3f64.sqrt() * tau);
}

#[test]
fn torsion_of_circular_bar() {
    // θ = TL/(GJ), J = πd⁴/32; τ = 16T/(πd³).
    let (d, torque) = (6.0, 2000.0);
    let mut m = cantilever(2, L, Section::Circle { d }, true);
    let u = tip(&m, [0.0, 0.0, 0.0, torque, 0.0, 0.0]);
    let j = PI * d.powi(4) / 32.0;
    assert_close!(u[3], torque * L / (STEEL.shear_modulus() * j));
    m.load_cases = vec![LoadCase::new("T").force(2, [0.0, 0.0, 0.0, torque, 0.0, 0.0])];
    let r = solve_static(&m).unwrap();
    assert_close!(
        r.load_cases[0].max_von_mises.unwrap(),
        3f64.sqrt() * 16.0 * torque / (PI * d.powi(3))
    );
}

#[test]
fn axial_bar() {
    // u = PL/EA, σ = P/A.
    let mut m = cantilever(5, L, Section::Tube { d_out: 8.0, d_in: 6.0 }, true);
    let a = PI * (64.0 - 36.0) / 4.0;
    let u = tip(&m, [300.0, 0.0, 0.0, 0.0, 0.0, 0.0]);
    assert_close!(u[0], 300.0 * L / (STEEL.e * a));
    m.load_cases = vec![LoadCase::new("P").force(5, [300.0, 0.0, 0.0, 0.0, 0.0, 0.0])];
    let r = solve_static(&m).unwrap();
    assert_close!(r.load_cases[0].max_von_mises.unwrap(), 300.0 / a);
    assert_close!(r.load_cases[0].elements[0].section_forces[0][0], 300.0);
}

#[test]
fn fixed_fixed_beam_central_load() {
    // Roark, Table 8.1 case 1e: δ = PL³/(192 EI) (Euler–Bernoulli); with shear + PL/(4κGA).
    for shear in [false, true] {
        let mut m = Model::new();
        for i in 0..3 {
            m.add_node([L * i as f64 / 2.0, 0.0, 0.0]);
        }
        for i in 0..2 {
            let mut b = Beam::new(i, i + 1, Section::Rect { w: W, h: H }, STEEL, [0.0, 0.0, 1.0]);
            b.shear = shear;
            m.add_beam(b);
        }
        m.supports = vec![Support::clamp(0), Support::clamp(2)];
        let p = 50.0;
        m.load_cases = vec![LoadCase::new("c").force(1, [0.0, 0.0, -p, 0.0, 0.0, 0.0])];
        let r = solve_static(&m).unwrap();
        let nu = STEEL.nu;
        let kappa = 10.0 * (1.0 + nu) / (12.0 + 11.0 * nu);
        let mut exact = p * L.powi(3) / (192.0 * STEEL.e * iy());
        if shear {
            exact += p * L / (4.0 * kappa * STEEL.shear_modulus() * W * H);
        }
        assert_close!(-r.load_cases[0].displacements[1][2], exact);
        // Reactions: P/2 each, end moments PL/8.
        let (n0, r0) = r.load_cases[0].reactions[0];
        assert_eq!(n0, 0);
        assert_close!(r0[2], p / 2.0);
        assert_close!(r0[4].abs(), p * L / 8.0);
    }
}

#[test]
fn l_shaped_3d_frame_bending_plus_torsion() {
    // Member 1 along x (length a, clamped at the origin), member 2 along y (length b), tip load
    // P along −z at (a, b, 0). Euler–Bernoulli, circular section (I, J = 2I).
    // Castigliano: δ = P b³/3EI + P a³/3EI + P b² a/GJ (torsion T = Pb of member 1 twists it,
    // the tip moves by θ·b).
    let (a, b, d, p) = (80.0, 50.0, 6.0, 5.0);
    let mut m = Model::new();
    m.add_node([0.0, 0.0, 0.0]);
    m.add_node([a, 0.0, 0.0]);
    m.add_node([a, b, 0.0]);
    m.add_beam(Beam::new(0, 1, Section::Circle { d }, STEEL, [0.0, 0.0, 1.0]).euler_bernoulli());
    m.add_beam(Beam::new(1, 2, Section::Circle { d }, STEEL, [0.0, 0.0, 1.0]).euler_bernoulli());
    m.supports.push(Support::clamp(0));
    m.load_cases = vec![LoadCase::new("P").force(2, [0.0, 0.0, -p, 0.0, 0.0, 0.0])];
    let r = solve_static(&m).unwrap();
    let i = PI * d.powi(4) / 64.0;
    let j = 2.0 * i;
    let (e, g) = (STEEL.e, STEEL.shear_modulus());
    let exact = p * b.powi(3) / (3.0 * e * i) + p * a.powi(3) / (3.0 * e * i) + p * b * b * a / (g * j);
    assert_close!(-r.load_cases[0].displacements[2][2], exact);
    // Root: torque P·b about x, moment P·a about y (reactions).
    let r0 = r.load_cases[0].reactions[0].1;
    assert_close!(r0[2], p);
    assert_close!(r0[3], p * b);
    assert_close!(r0[4], -p * a);
}

#[test]
fn root_bending_stress_and_combined_stress() {
    // Rect: σ = Mc/I = 6PL/(w h²) at the root (corners and mid-faces carry no shear there).
    let p = 20.0;
    let mut m = cantilever(4, L, Section::Rect { w: W, h: H }, true);
    m.load_cases = vec![LoadCase::new("P").force(4, [0.0, 0.0, p, 0.0, 0.0, 0.0])];
    let r = solve_static(&m).unwrap();
    assert_close!(r.load_cases[0].max_von_mises.unwrap(), 6.0 * p * L / (W * H * H));
    assert_close!(r.load_cases[0].elements[0].section_forces[0][4], -p * L);
    // Circle under bending + torsion: σ_vM = √(σ² + 3τ²), σ = 32PL/πd³, τ = 16T/πd³.
    let (d, t) = (8.0, 300.0);
    let mut m = cantilever(2, L, Section::Circle { d }, true);
    m.load_cases = vec![LoadCase::new("PT").force(2, [0.0, p, p, t, 0.0, 0.0])];
    let r = solve_static(&m).unwrap();
    let sigma = 32.0 * p * L * 2f64.sqrt() / (PI * d.powi(3));
    let tau = 16.0 * t / (PI * d.powi(3));
    assert_close!(
        r.load_cases[0].max_von_mises.unwrap(),
        (sigma * sigma + 3.0 * tau * tau).sqrt()
    );
}

#[test]
fn reactions_and_statics_check_portal_frame() {
    // 3D portal: two columns, a beam, loads in all directions; Σ loads + Σ reactions = 0
    // (forces and moments about the origin).
    let mut m = Model::new();
    let pts = [
        [0.0, 0.0, 0.0],
        [0.0, 0.0, 100.0],
        [80.0, 30.0, 100.0],
        [80.0, 30.0, 0.0],
    ];
    for p in pts {
        m.add_node(p);
    }
    let s = Section::Rect { w: 6.0, h: 9.0 };
    m.add_beam(Beam::new(0, 1, s, STEEL, [1.0, 0.0, 0.0]));
    m.add_beam(Beam::new(1, 2, s, STEEL, [0.0, 0.0, 1.0]));
    m.add_beam(Beam::new(3, 2, s, STEEL, [0.0, 1.0, 0.0]));
    m.supports = vec![Support::clamp(0), Support::dofs(3, &[Dof::Ux, Dof::Uy, Dof::Uz])];
    m.load_cases = vec![LoadCase::new("mix")
        .force(1, [10.0, -5.0, 3.0, 100.0, 0.0, -50.0])
        .force(2, [0.0, 7.0, -20.0, 0.0, 40.0, 0.0])];
    let r = solve_static(&m).unwrap();
    let c = &r.load_cases[0];
    let res = c.statics.residual();
    for (i, v) in res.iter().enumerate() {
        let scale = if i < 3 { 20.0 } else { 2000.0 };
        assert!(v.abs() < 1e-9 * scale, "statics residual {res:?}");
    }
    assert!(c.statics.is_balanced(1e-9, 100.0));
    assert_eq!(c.reactions.len(), 2);
    // Pinned node 3 carries no moment reaction.
    assert_eq!(c.reactions[1].1[3..], [0.0, 0.0, 0.0]);
}

#[test]
fn multiple_load_cases_on_one_factorisation() {
    // Superposition: case C = 2·A − B, all solved with one factor.
    let mut m = cantilever(3, L, Section::Rect { w: W, h: H }, true);
    let fa = [1.0, 2.0, 3.0, 4.0, 5.0, 6.0];
    let fb = [-3.0, 1.0, 0.5, 0.0, -10.0, 2.0];
    let fc: [f64; 6] = std::array::from_fn(|i| 2.0 * fa[i] - fb[i]);
    m.load_cases = vec![
        LoadCase::new("A").force(3, fa),
        LoadCase::new("B").force(3, fb),
        LoadCase::new("C").force(3, fc),
    ];
    let sys = System::new(&m, &[], Parallelism::Sequential).unwrap();
    let cases: Vec<&LoadCase> = m.load_cases.iter().collect();
    let r = sys.solve_cases(&m, &cases).unwrap();
    for n in 0..4 {
        for d in 0..6 {
            let sup = 2.0 * r[0].displacements[n][d] - r[1].displacements[n][d];
            assert!((r[2].displacements[n][d] - sup).abs() <= 1e-9 * sup.abs().max(1e-9));
        }
    }
    // Same as solve_static.
    let s = solve_static(&m).unwrap();
    assert_eq!(s.load_cases[1].displacements, r[1].displacements);
}

#[test]
fn prescribed_displacement_equals_equivalent_force() {
    // Tip w = δ prescribed ⇔ tip force P = 3EIδ/L³ (Euler–Bernoulli); the reaction at the
    // prescribed DOF is P and the tip rotation matches.
    let m0 = cantilever(2, L, Section::Rect { w: W, h: H }, false);
    let delta = 0.7;
    let p = 3.0 * STEEL.e * iy() * delta / L.powi(3);
    let mut m = m0.clone();
    m.load_cases = vec![
        LoadCase::new("disp").displacement(2, Dof::Uz, delta),
        LoadCase::new("disp2").displacement(2, Dof::Uz, 2.0 * delta),
        LoadCase::new("force").force(2, [0.0, 0.0, p, 0.0, 0.0, 0.0]),
    ];
    let r = solve_static(&m).unwrap();
    let (ud, uf) = (&r.load_cases[0].displacements, &r.load_cases[2].displacements);
    for n in 0..3 {
        for d in 0..6 {
            assert!((ud[n][d] - uf[n][d]).abs() <= 1e-9 * uf[2][2].abs(), "node {n} dof {d}");
        }
    }
    let tip_reaction = r.load_cases[0].reactions.iter().find(|r| r.0 == 2).unwrap().1;
    assert_close!(tip_reaction[2], p);
    assert_close!(r.load_cases[1].displacements[1][2], 2.0 * ud[1][2]);
    assert_eq!(r.load_cases.len(), 3);
    assert_eq!(r.load_cases[2].name, "force");
}

#[test]
fn node_compliance_of_cantilever_tip_is_closed_form() {
    for shear in [false, true] {
        let sec = Section::Rect { w: W, h: H };
        let m = cantilever(3, L, sec, shear);
        let sys = System::new(&m, &[], Parallelism::Sequential).unwrap();
        let c = sys.node_compliance(&m, 3).unwrap();
        let p = sec.properties(STEEL.nu);
        let exact = cantilever_compliance(STEEL.e, STEEL.shear_modulus(), &p, L, shear);
        for i in 0..6 {
            for j in 0..6 {
                let scale = (exact[(i, i)] * exact[(j, j)]).sqrt();
                assert!(
                    (c[(i, j)] - exact[(i, j)]).abs() <= 1e-7 * scale,
                    "C[{i}][{j}] = {} vs {}",
                    c[(i, j)],
                    exact[(i, j)]
                );
            }
        }
        let k = sys.node_stiffness(&m, 3).unwrap();
        let id = k * c;
        assert!((id - nalgebra::Matrix6::identity()).amax() < 1e-6);
        // Constrained node: no stiffness.
        assert!(sys.node_stiffness(&m, 0).is_err());
    }
}

#[test]
fn flexibility_element_reproduces_prismatic_beam() {
    // k = Bᵀ C⁻¹ B with the closed-form cantilever compliance equals the Timoshenko beam k.
    for (sec, shear) in [
        (Section::Rect { w: W, h: H }, true),
        (Section::Circle { d: 4.0 }, false),
    ] {
        let p = sec.properties(STEEL.nu);
        let (e, g) = (STEEL.e, STEEL.shear_modulus());
        let c = cantilever_compliance(e, g, &p, L, shear);
        let kf = flex_local_stiffness(&c, L).unwrap();
        let kb = beam_local_stiffness(e, g, &p, L, shear);
        for i in 0..12 {
            for j in 0..12 {
                let scale = (kb[(i, i)] * kb[(j, j)]).sqrt();
                assert!((kf[(i, j)] - kb[(i, j)]).abs() <= 1e-9 * scale, "k[{i}][{j}]");
            }
        }
        // In a model, rotated in space: same tip motion as the beam.
        let mut mb = Model::new();
        mb.add_node([0.0, 0.0, 0.0]);
        mb.add_node([30.0, 40.0, 86.60254037844386]);
        let up = [1.0, 0.0, 0.0];
        let mut b = Beam::new(0, 1, sec, STEEL, up);
        b.shear = shear;
        mb.add_beam(b);
        mb.supports.push(Support::clamp(0));
        mb.load_cases = vec![LoadCase::new("x").force(1, [1.0, -2.0, 3.0, 40.0, 50.0, -60.0])];
        let mut mf = mb.clone();
        let cc: [[f64; 6]; 6] = std::array::from_fn(|i| std::array::from_fn(|j| c[(i, j)]));
        mf.elements = vec![Element::Flex(FlexElement {
            nodes: [0, 1],
            compliance: cc,
            up,
        })];
        // The flex element length is the node distance: 100.
        let (rb, rf) = (solve_static(&mb).unwrap(), solve_static(&mf).unwrap());
        for d in 0..6 {
            let (a, b) = (
                rf.load_cases[0].displacements[1][d],
                rb.load_cases[0].displacements[1][d],
            );
            assert!((a - b).abs() <= 1e-8 * b.abs().max(1e-6), "dof {d}: {a} vs {b}");
        }
        // End forces of the flexibility element: equilibrium with the tip load.
        let ef = &rf.load_cases[0].elements[0];
        let eb = &rb.load_cases[0].elements[0];
        for k in 0..2 {
            for i in 0..6 {
                assert!((ef.section_forces[k][i] - eb.section_forces[k][i]).abs() < 1e-6 * 100.0);
            }
        }
    }
}

#[test]
fn rigid_body_motions_give_zero_strain_energy() {
    // K·u_rigid = 0 for translations and small rotations about an arbitrary point.
    use flexfem::fem::transform::rigid_arm;
    use nalgebra::{SVector, Vector3};
    let mut m = Model::new();
    m.add_node([1.0, 2.0, 3.0]);
    m.add_node([40.0, -20.0, 35.0]);
    m.add_beam(Beam::new(
        0,
        1,
        Section::Rect { w: 3.0, h: 7.0 },
        STEEL,
        [0.3, 1.0, 0.2],
    ));
    let c = cantilever_compliance(
        STEEL.e,
        80000.0,
        &Section::Circle { d: 3.0 }.properties(0.3),
        60.0,
        true,
    );
    let cc: [[f64; 6]; 6] = std::array::from_fn(|i| std::array::from_fn(|j| c[(i, j)]));
    m.add_element(Element::Flex(FlexElement {
        nodes: [0, 1],
        compliance: cc,
        up: [0.0, 0.0, 1.0],
    }));
    m.add_element(Element::Spring(flexfem::fem::Spring {
        a: 0,
        b: Some(1),
        k: [1e3, 2e3, 3e3, 4e5, 5e5, 6e5],
        axes: flexfem::fem::SpringAxes::from_x_up([1.0, 1.0, 0.0], [0.0, 0.0, 1.0]).unwrap(),
    }));
    let centre = Vector3::new(-5.0, 7.0, 2.0);
    for mode in 0..6 {
        let mut q = SVector::<f64, 6>::zeros();
        q[mode] = 1.0;
        let mut d = SVector::<f64, 12>::zeros();
        for (k, &n) in [0usize, 1].iter().enumerate() {
            let a = Vector3::from(m.nodes[n]) - centre;
            d.fixed_rows_mut::<6>(6 * k).copy_from(&(rigid_arm(&a) * q));
        }
        for ie in 0..m.elements.len() {
            let em = m.element_matrix(ie).unwrap();
            let f = em.k * d;
            assert!(f.amax() < 1e-9 * em.k.amax(), "element {ie} mode {mode}: {}", f.amax());
        }
    }
}

#[test]
fn up_parallel_to_axis_is_an_error_naming_the_element() {
    let mut m = cantilever(2, L, Section::Circle { d: 2.0 }, true);
    if let Element::Beam(b) = &mut m.elements[1] {
        b.up = [1.0, 1e-9, 0.0];
    }
    let err = System::new(&m, &[], Parallelism::Sequential).unwrap_err().to_string();
    assert!(err.contains("element 1"), "{err}");
    assert!(err.contains("parallel"), "{err}");
    let _ = NodeDof { node: 0, dof: Dof::Ux };
}
