//! Exact condensation of serial chains (flexfem::fem::chain): a model solved with its chains
//! condensed to two-node flexibility elements and the inner nodes recovered equals the model
//! solved as meshed, to 1e-10 of the largest value of each quantity (roundoff: condensation is
//! exact for linear statics, Przemieniecki 1968 §6.5).

use flexfem::fem::chain::{find_chains, Condensed};
use flexfem::fem::solve::Parallelism;
use flexfem::fem::{
    Beam, CaseResult, Dof, Element, FlexElement, LoadCase, Model, NodeDof, RigidLink, Section, Support, System,
};
use flexfem::material::Material;

/// A 3-D frame exercising every rule: a branch node of three elements, a loaded inner node
/// (splits a chain), an element pointing backwards, a flexibility element inside a chain, a
/// rigid link, a framed support with a prescribed displacement, inclined elements.
fn frame() -> (Model, Vec<LoadCase>) {
    // Leg 1: 0 → 1 → 2 → 3 → 4 (node 2 loaded in case "mid"); leg 2: 4 → 5 → 6 → 7 → 8 down
    // to a framed slider; a branch at node 4: 4 → 9 → 10, node 10 a rigid-link master of node
    // 11, tied by the chain 11 → 12 → 13 to the ground node 13.
    const NODES: [[f64; 3]; 14] = [
        [0.0, 0.0, 0.0],
        [10.0, 1.0, 2.0],
        [20.0, 3.0, 3.0],
        [31.0, 4.0, 5.0],
        [40.0, 4.0, 10.0],
        [50.0, -5.0, 8.0],
        [60.0, -10.0, 5.0],
        [70.0, -12.0, 2.0],
        [80.0, -15.0, 0.0],
        [40.0, 14.0, 12.0],
        [40.0, 24.0, 14.0],
        [45.0, 24.0, 14.0],
        [45.0, 34.0, 8.0],
        [45.0, 44.0, 0.0],
    ];
    let mut m = Model::new();
    NODES.iter().for_each(|&p| {
        m.add_node(p);
    });
    let al = Material::AL7075;
    let rect = Section::Rect { w: 6.0, h: 4.0 };
    let c = [
        [1e-3, 0.0, 0.0, 0.0, 0.0, 0.0],
        [0.0, 2e-2, 0.0, 0.0, 0.0, 1e-3],
        [0.0, 0.0, 3e-2, 0.0, -2e-3, 0.0],
        [0.0, 0.0, 0.0, 1e-4, 0.0, 0.0],
        [0.0, 0.0, -2e-3, 0.0, 4e-4, 0.0],
        [0.0, 1e-3, 0.0, 0.0, 0.0, 3e-4],
    ];
    let flex = |nodes: [usize; 2], up: [f64; 3]| {
        Element::Flex(FlexElement {
            nodes,
            compliance: c,
            up,
        })
    };
    // (element, kind): beams with their `up`, one backwards (2 → 1), one Euler–Bernoulli (5 → 6),
    // a circular one (2 → 3) and two flexibility elements.
    let (x, y, z) = ([1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0]);
    let beams: [(usize, usize, [f64; 3]); 7] = [
        (0, 1, z),
        (2, 1, [0.0, 1.0, 1.0]),
        (4, 5, z),
        (6, 7, z),
        (4, 9, x),
        (9, 10, x),
        (11, 12, x),
    ];
    for (k, &(a, b, up)) in beams.iter().enumerate() {
        m.add_beam(Beam::new(a, b, rect, al, up));
        match k {
            1 => {
                m.add_beam(Beam::new(2, 3, Section::Circle { d: 5.0 }, al, z));
                m.add_element(flex([3, 4], y));
            }
            2 => {
                m.add_beam(Beam::new(5, 6, rect, al, [1.0, 0.0, 1.0]).euler_bernoulli());
            }
            3 => {
                m.add_element(flex([7, 8], z));
            }
            _ => {}
        }
    }
    m.add_beam(Beam::new(12, 13, rect, al, x));
    m.rigid_links.push(RigidLink {
        master: 10,
        slaves: vec![11],
    });
    m.supports.push(Support::clamp(0));
    m.supports.push(Support::clamp(13));
    let s = 0.5f64.sqrt();
    m.set_frame(8, [[s, s, 0.0], [-s, s, 0.0], [0.0, 0.0, 1.0]]);
    m.supports
        .push(Support::dofs(8, &[Dof::Uy, Dof::Uz, Dof::Rx, Dof::Ry, Dof::Rz]));
    let cases = vec![
        LoadCase::new("mid")
            .force(2, [3.0, -2.0, 5.0, 10.0, -20.0, 7.0])
            .force(10, [0.0, 0.0, -4.0, 0.0, 0.0, 0.0]),
        LoadCase::new("tip")
            .force(4, [1.0, 2.0, -3.0, 0.0, 15.0, 0.0])
            .force(8, [2.0, 2.0, 0.0, 0.0, 0.0, 0.0]),
    ];
    (m, cases)
}

/// Largest |value| of a list.
fn scale<'a>(v: impl Iterator<Item = &'a f64>) -> f64 {
    v.fold(0.0f64, |m, x| m.max(x.abs()))
}

fn assert_same(full: &CaseResult, cond: &CaseResult) {
    let su = scale(full.displacements.iter().flatten());
    assert_eq!(full.displacements.len(), cond.displacements.len());
    for (n, (a, b)) in full.displacements.iter().zip(&cond.displacements).enumerate() {
        for i in 0..6 {
            assert!(
                (a[i] - b[i]).abs() <= 1e-10 * su,
                "node {n} dof {i}: {} vs {}",
                b[i],
                a[i]
            );
        }
    }
    assert_eq!(full.reactions.len(), cond.reactions.len());
    let sr = scale(full.reactions.iter().flat_map(|r| r.1.iter()));
    for (a, b) in full.reactions.iter().zip(&cond.reactions) {
        assert_eq!(a.0, b.0);
        for i in 0..6 {
            assert!(
                (a.1[i] - b.1[i]).abs() <= 1e-10 * sr,
                "reaction at {}: {:?} vs {:?}",
                a.0,
                b.1,
                a.1
            );
        }
    }
    let sf = scale(full.elements.iter().flat_map(|e| e.section_forces.iter().flatten()));
    assert_eq!(full.elements.len(), cond.elements.len());
    for (ie, (a, b)) in full.elements.iter().zip(&cond.elements).enumerate() {
        for k in 0..2 {
            for i in 0..6 {
                let (x, y) = (a.section_forces[k][i], b.section_forces[k][i]);
                assert!(
                    (x - y).abs() <= 1e-10 * sf,
                    "element {ie} section force {k},{i}: {y} vs {x}"
                );
            }
        }
        assert!((a.strain_energy - b.strain_energy).abs() <= 1e-10 * a.strain_energy.abs().max(1e-300) + 1e-300);
    }
    let (va, vb) = (full.max_von_mises.expect("beams"), cond.max_von_mises.expect("beams"));
    assert!((va - vb).abs() <= 1e-10 * va);
}

fn solve(model: &Model, case: &LoadCase, prescribed: &[NodeDof]) -> CaseResult {
    let sys = System::new(model, prescribed, Parallelism::Sequential).expect("solves");
    sys.solve_cases(model, &[case]).expect("case").remove(0)
}

#[test]
fn chains_found_are_the_serial_runs_between_pinned_and_branch_nodes() {
    let (m, cases) = frame();
    let refs: Vec<&LoadCase> = cases.iter().collect();
    let mut chains = find_chains(&m, &refs, &[]);
    chains.sort();
    // 0–1–2 (node 2 loaded), 2–3–4 (flex 3–4), 4–5–6–7–8, 4–9–10, 11–12–13; node 4 is a branch.
    let ends: Vec<(usize, usize, usize)> = chains
        .iter()
        .map(|(n, e)| (*n.first().unwrap(), *n.last().unwrap(), e.len()))
        .collect();
    let mut norm: Vec<(usize, usize, usize)> = ends.iter().map(|&(a, b, k)| (a.min(b), a.max(b), k)).collect();
    norm.sort();
    assert_eq!(norm, vec![(0, 2, 2), (2, 4, 2), (4, 8, 4), (4, 10, 2), (11, 13, 2)]);
    // A kept node splits its chain.
    assert_eq!(find_chains(&m, &refs, &[6]).len(), 6);
}

#[test]
fn condensed_frame_equals_the_meshed_frame_to_1e_10() {
    let (m, cases) = frame();
    let refs: Vec<&LoadCase> = cases.iter().collect();
    let cond = Condensed::new(&m, &refs, &[]).expect("condenses");
    assert_eq!(cond.model.nodes.len(), m.nodes.len() - 7);
    for case in &cases {
        let full = solve(&m, case, &[]);
        let r = solve(&cond.model, &cond.case(case), &[]);
        assert_same(&full, &cond.expand(&m, r).expect("expands"));
    }
    // With a prescribed displacement of the slider (framed node 8, local ux).
    let case = LoadCase::new("stroke")
        .displacement(8, Dof::Ux, 0.3)
        .force(2, [0.0, 1.0, 0.0, 0.0, 0.0, 0.0]);
    let p = [NodeDof { node: 8, dof: Dof::Ux }];
    let cond = Condensed::new(&m, &[&case], &[]).expect("condenses");
    let pr = [NodeDof {
        node: cond.node(8).expect("kept"),
        dof: Dof::Ux,
    }];
    let full = solve(&m, &case, &p);
    let r = solve(&cond.model, &cond.case(&case), &pr);
    assert_same(&full, &cond.expand(&m, r).expect("expands"));
}
