//! Orientation invariance (proptest): the same model rotated by a random rigid rotation, and
//! with every element's node order reversed, gives the same results transformed (beams, a
//! spring, a rigid link and a nine-node shell panel in a tilted plane).

use flexfem::fem::{
    solve_static, Beam, Element, LoadCase, Model, RigidLink, Section, Shell9, Spring, SpringAxes, Support,
};
use flexfem::material::Material;
use nalgebra::{Matrix3, Rotation3, Vector3};
use proptest::prelude::*;

fn base() -> Model {
    let mut m = Model::new();
    for p in [
        [0.0, 0.0, 0.0],
        [60.0, 0.0, 0.0],
        [60.0, 40.0, 0.0],
        [60.0, 40.0, 30.0],
        [70.0, 45.0, 30.0],
        [80.0, 40.0, 30.0],
    ] {
        m.add_node(p);
    }
    let al = Material::AL7075;
    m.add_beam(Beam::new(0, 1, Section::Rect { w: 6.0, h: 3.0 }, al, [0.0, 0.3, 1.0]));
    m.add_beam(Beam::new(1, 2, Section::Circle { d: 4.0 }, al, [0.0, 0.0, 1.0]));
    m.add_beam(Beam::new(2, 3, Section::Tube { d_out: 5.0, d_in: 3.0 }, al, [1.0, 0.0, 0.0]).euler_bernoulli());
    m.rigid_links.push(RigidLink {
        master: 3,
        slaves: vec![4],
    });
    m.add_element(Element::Spring(Spring {
        a: 4,
        b: Some(5),
        k: [1e3, 2e3, 3e3, 1e5, 2e5, 3e5],
        axes: SpringAxes::from_x_up([1.0, -0.5, 0.0], [0.0, 0.0, 1.0]).unwrap(),
    }));
    // A nine-node shell panel in a tilted plane, hung from node 2 (corner 0).
    let (p, e1, e2) = (
        Vector3::new(60.0, 40.0, 0.0),
        Vector3::new(10.0, 0.0, 0.0),
        Vector3::new(0.0, 8.0, 6.0),
    );
    let mut panel = [2usize; 9];
    for (k, (a, b)) in [
        (1.0, 0.0),
        (1.0, 1.0),
        (0.0, 1.0),
        (0.5, 0.0),
        (1.0, 0.5),
        (0.5, 1.0),
        (0.0, 0.5),
        (0.5, 0.5),
    ]
    .into_iter()
    .enumerate()
    {
        let x = p + e1 * a + e2 * b;
        panel[k + 1] = m.add_node([x.x, x.y, x.z]);
    }
    m.add_element(Element::Shell9(Shell9 {
        nodes: panel,
        t: 1.0,
        material: al,
    }));
    m.supports.push(Support::clamp(0));
    m.load_cases.push(
        LoadCase::new("a")
            .force(3, [1.0, -2.0, 3.0, 20.0, -10.0, 5.0])
            .force(5, [0.5, 0.5, -1.0, 0.0, 0.0, 10.0])
            .force(panel[2], [0.5, -0.3, 1.0, 5.0, 0.0, -2.0]),
    );
    m
}

fn rot6(q: &Matrix3<f64>, f: [f64; 6]) -> [f64; 6] {
    let a = q * Vector3::new(f[0], f[1], f[2]);
    let b = q * Vector3::new(f[3], f[4], f[5]);
    [a.x, a.y, a.z, b.x, b.y, b.z]
}

fn rotate(m: &Model, q: &Matrix3<f64>) -> Model {
    let mut r = m.clone();
    let rv = |v: [f64; 3]| {
        let w = q * Vector3::from(v);
        [w.x, w.y, w.z]
    };
    for x in &mut r.nodes {
        *x = rv(*x);
    }
    for e in &mut r.elements {
        match e {
            Element::Beam(b) => b.up = rv(b.up),
            Element::Flex(f) => f.up = rv(f.up),
            Element::Spring(s) => {
                if let SpringAxes::Frame(rows) = &mut s.axes {
                    for row in rows.iter_mut() {
                        *row = rv(*row);
                    }
                }
            }
            Element::Shell4(_) | Element::Shell9(_) => {}
            // Given matrices in global axes turn with the model: K' = T K Tᵀ, T = diag(q, q, q, q).
            Element::Matrix(me) => {
                let mut t = nalgebra::SMatrix::<f64, 12, 12>::zeros();
                for b in 0..4 {
                    t.fixed_view_mut::<3, 3>(3 * b, 3 * b).copy_from(q);
                }
                me.k = t * me.k * t.transpose();
                me.m = t * me.m * t.transpose();
            }
        }
    }
    for c in &mut r.load_cases {
        for f in &mut c.forces {
            f.f = rot6(q, f.f);
        }
    }
    r
}

fn reverse(m: &Model) -> Model {
    let mut r = m.clone();
    for e in &mut r.elements {
        match e {
            Element::Beam(b) => b.nodes.reverse(),
            Element::Flex(f) => f.nodes.reverse(),
            Element::Spring(s) => {
                if let Some(b) = s.b {
                    s.b = Some(s.a);
                    s.a = b;
                    // Spring axes are fixed in space: reversing the nodes flips δ's sign only.
                }
            }
            // Reversed orientation: the normal flips, the physics must not.
            Element::Shell4(s) => s.nodes = [s.nodes[0], s.nodes[3], s.nodes[2], s.nodes[1]],
            // Corners 0 3 2 1, edges 3–0, 2–3, 1–2, 0–1, the centre.
            Element::Shell9(s) => {
                let n = s.nodes;
                s.nodes = [n[0], n[3], n[2], n[1], n[7], n[6], n[5], n[4], n[8]];
            }
            // Swapping the two nodes swaps the 6×6 blocks of the given matrices.
            Element::Matrix(me) if me.n_nodes == 2 => {
                me.nodes.reverse();
                let swap = |a: &nalgebra::SMatrix<f64, 12, 12>| {
                    nalgebra::SMatrix::<f64, 12, 12>::from_fn(|i, j| a[((i + 6) % 12, (j + 6) % 12)])
                };
                (me.k, me.m) = (swap(&me.k), swap(&me.m));
            }
            Element::Matrix(_) => {}
        }
    }
    r
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(32))]
    #[test]
    fn rotated_and_reversed_models_agree(ax in -1.0f64..1.0, ay in -1.0f64..1.0, az in -1.0f64..1.0, angle in -3.1f64..3.1, rev in any::<bool>()) {
        let axis = Vector3::new(ax, ay, az);
        prop_assume!(axis.norm() > 0.1);
        let q = *Rotation3::from_axis_angle(&nalgebra::Unit::new_normalize(axis), angle).matrix();
        let m0 = base();
        let mut m1 = rotate(&m0, &q);
        if rev {
            m1 = reverse(&m1);
        }
        let (r0, r1) = (solve_static(&m0).unwrap(), solve_static(&m1).unwrap());
        let (c0, c1) = (&r0.load_cases[0], &r1.load_cases[0]);
        let scale = c0.displacements.iter().flat_map(|u| u.iter()).fold(0.0f64, |a, v| a.max(v.abs()));
        prop_assert_eq!(c0.displacements.len(), c1.displacements.len());
        for (u0, u1) in c0.displacements.iter().zip(&c1.displacements) {
            let expect = rot6(&q, *u0);
            for d in 0..6 {
                prop_assert!((u1[d] - expect[d]).abs() <= 1e-9 * scale, "dof {d}: {} vs {}", u1[d], expect[d]);
            }
        }
        let (v0, v1) = (c0.max_von_mises.unwrap(), c1.max_von_mises.unwrap());
        prop_assert!((v0 - v1).abs() <= 1e-9 * v0);
        prop_assert_eq!(c0.elements.len(), c1.elements.len());
        for (e0, e1) in c0.elements.iter().zip(&c1.elements) {
            prop_assert!((e0.strain_energy - e1.strain_energy).abs() <= 1e-9 * e0.strain_energy.abs().max(1e-12));
        }
        let r = rot6(&q, c0.reactions[0].1);
        // zip-checked: two [f64; 6] reactions.
        for (a, b) in c1.reactions[0].1.iter().zip(&r) {
            prop_assert!((a - b).abs() <= 1e-9 * 1000.0);
        }
        prop_assert!(c1.statics.is_balanced(1e-9, 100.0));
    }
}
