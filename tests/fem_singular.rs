//! Singular models: every kind of missing support is reported with node and direction.

use flexfem::fem::solve::Parallelism;
use flexfem::fem::{Beam, Dof, Element, FemError, LoadCase, Model, NodeDof, Section, Spring, Support, System};
use flexfem::material::Material;

const STEEL: Material = Material::STEEL;

fn beam_line(n: usize) -> Model {
    let mut m = Model::new();
    for i in 0..=n {
        m.add_node([20.0 * i as f64, 0.0, 0.0]);
    }
    for i in 0..n {
        m.add_beam(Beam::new(
            i,
            i + 1,
            Section::Rect { w: 3.0, h: 2.0 },
            STEEL,
            [0.0, 0.0, 1.0],
        ));
    }
    m
}

/// A one-element bar clamped at node 0, plus two unconnected nodes at `a` and `b`; their indices.
fn clamped_bar_with(a: [f64; 3], b: [f64; 3]) -> (Model, usize, usize) {
    let mut m = beam_line(1);
    m.supports.push(Support::clamp(0));
    let (a, b) = (m.add_node(a), m.add_node(b));
    (m, a, b)
}

fn err(m: &Model) -> FemError {
    System::new(m, &[], Parallelism::Sequential).unwrap_err()
}

fn nd(node: usize, dof: Dof) -> NodeDof {
    NodeDof { node, dof }
}

#[test]
fn single_dof_without_stiffness_names_node_and_direction() {
    // Node 2 hangs on a spring with no rz stiffness: "node 2 rz is unconstrained (mechanism)".
    let mut m = beam_line(1);
    m.supports.push(Support::clamp(0));
    let n2 = m.add_node([20.0, 0.0, 0.0]);
    m.add_element(Element::Spring(Spring::global(
        1,
        Some(n2),
        [1e3, 1e3, 1e3, 1e3, 1e3, 0.0],
    )));
    let e = err(&m);
    assert_eq!(e.to_string(), "node 2 rz is unconstrained (mechanism)");
    assert!(matches!(e, FemError::Unconstrained { ref dofs } if dofs == &[nd(2, Dof::Rz)]));
}

#[test]
fn isolated_node_has_all_six_dofs_unconstrained() {
    let mut m = beam_line(2);
    m.supports.push(Support::clamp(0));
    m.add_node([5.0, 5.0, 5.0]);
    let e = err(&m).to_string();
    assert_eq!(e, "node 3 ux, uy, uz, rx, ry, rz are unconstrained (mechanism)");
}

#[test]
fn unsupported_part_is_a_free_body() {
    let (mut m, a, b) = clamped_bar_with([0.0, 10.0, 0.0], [20.0, 10.0, 0.0]);
    m.add_beam(Beam::new(a, b, Section::Circle { d: 2.0 }, STEEL, [0.0, 0.0, 1.0]));
    match err(&m) {
        FemError::FreeBody { nodes } => assert_eq!(nodes, vec![a, b]),
        e => panic!("{e}"),
    }
    // No support at all.
    let m = beam_line(2);
    assert!(matches!(err(&m), FemError::FreeBody { nodes } if nodes == vec![0, 1, 2]));
}

#[test]
fn missing_torsional_support_is_a_mechanism_in_rx() {
    // Root fixes everything but rx: the whole bar spins about its axis.
    let mut m = beam_line(3);
    m.supports
        .push(Support::dofs(0, &[Dof::Ux, Dof::Uy, Dof::Uz, Dof::Ry, Dof::Rz]));
    match err(&m) {
        FemError::Mechanism { dofs } => {
            assert_eq!(dofs, (0..4).map(|n| nd(n, Dof::Rx)).collect::<Vec<_>>());
        }
        e => panic!("{e}"),
    }
}

#[test]
fn missing_translation_support_is_a_mechanism_in_that_direction() {
    // Pinned–roller line that can slide along x: all ux free.
    let mut m = beam_line(2);
    m.supports.push(Support::dofs(0, &[Dof::Uy, Dof::Uz, Dof::Rx]));
    m.supports.push(Support::dofs(2, &[Dof::Uy, Dof::Uz]));
    match err(&m) {
        FemError::Mechanism { dofs } => {
            assert_eq!(dofs, (0..3).map(|n| nd(n, Dof::Ux)).collect::<Vec<_>>());
            let msg = FemError::Mechanism { dofs }.to_string();
            assert!(msg.contains("node 0 ux; node 1 ux; node 2 ux"), "{msg}");
        }
        e => panic!("{e}"),
    }
}

#[test]
fn pin_inside_a_chain_is_a_mechanism_naming_the_swinging_part() {
    // Clamp – beam – pin (spring with kry = 0 between coincident nodes) – beam – free end:
    // the outer beam swings about y: node 2 ry, node 3 uz and ry take part.
    let (mut m, a, b) = clamped_bar_with([20.0, 0.0, 0.0], [40.0, 0.0, 0.0]);
    m.add_element(Element::Spring(Spring::global(
        1,
        Some(a),
        [1e6, 1e6, 1e6, 1e9, 0.0, 1e9],
    )));
    m.add_beam(Beam::new(
        a,
        b,
        Section::Rect { w: 3.0, h: 2.0 },
        STEEL,
        [0.0, 0.0, 1.0],
    ));
    match err(&m) {
        FemError::Mechanism { dofs } => {
            for d in [nd(2, Dof::Ry), nd(3, Dof::Uz), nd(3, Dof::Ry)] {
                assert!(dofs.contains(&d), "{dofs:?} lacks {d}");
            }
            assert!(!dofs.iter().any(|d| d.node < 2), "{dofs:?}");
        }
        e => panic!("{e}"),
    }
}

#[test]
fn ground_springs_alone_are_a_valid_support() {
    let mut m = beam_line(1);
    for n in 0..2 {
        m.add_element(Element::Spring(Spring::global(n, None, [1e3; 6])));
    }
    m.load_cases = vec![LoadCase::new("F").force(1, [1.0, 2.0, 3.0, 4.0, 5.0, 6.0])];
    let r = flexfem::fem::solve_static(&m).unwrap();
    assert!(r.load_cases[0].statics.is_balanced(1e-9, 20.0));
    assert!(r.load_cases[0].reactions.is_empty());
}
