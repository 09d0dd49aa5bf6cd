//! The explicit per-worker solver cache (`fem::SolverCache`): a model of the same topology
//! reuses the cached pattern and symbolic factorisation and gets the same answer as a fresh
//! solve; a model of another topology is solved afresh.

use flexfem::fem::solve::Parallelism;
use flexfem::fem::{solve_static, solve_static_cached, Beam, LoadCase, Model, Section, SolverCache, Support};
use flexfem::material::Material;

/// Cantilever along +x of `n` rectangular elements (width w, height h), tip force 1 N along z.
fn cantilever(n: usize, w: f64, h: f64) -> Model {
    let mut m = Model::new();
    for i in 0..=n {
        m.add_node([100.0 * i as f64 / n as f64, 0.0, 0.0]);
    }
    for i in 0..n {
        m.add_beam(Beam::new(
            i,
            i + 1,
            Section::Rect { w, h },
            Material::STEEL,
            [0.0, 0.0, 1.0],
        ));
    }
    m.supports.push(Support::clamp(0));
    m.load_cases = vec![LoadCase::new("tip").force(n, [0.0, 0.0, 1.0, 0.0, 0.0, 0.0])];
    m
}

/// Same topology, other section: reused, and bit-for-bit the fresh solve (the numeric
/// factorisation on the same symbolic one is the same computation).
#[test]
fn same_topology_reuses_the_symbolic_factorisation_with_identical_results() {
    let mut cache = SolverCache::new();
    let a = cantilever(4, 10.0, 5.0);
    let b = cantilever(4, 12.0, 3.0);
    let ra = solve_static_cached(&a, Parallelism::Sequential, &mut cache).unwrap();
    assert_eq!(cache.counts(), (0, 1));
    let rb = solve_static_cached(&b, Parallelism::Sequential, &mut cache).unwrap();
    assert_eq!(cache.counts(), (1, 1));
    assert_eq!(ra, solve_static(&a).unwrap());
    assert_eq!(rb, solve_static(&b).unwrap());
    // The reused system holds b's own values, not a's: the tip deflections differ.
    assert_ne!(ra.load_cases[0].displacements[4], rb.load_cases[0].displacements[4]);
}

/// Another topology (more elements): not reused (the pattern check refuses it), solved afresh.
#[test]
fn other_topology_is_solved_afresh() {
    let mut cache = SolverCache::new();
    solve_static_cached(&cantilever(4, 10.0, 5.0), Parallelism::Sequential, &mut cache).unwrap();
    let c = cantilever(6, 10.0, 5.0);
    let rc = solve_static_cached(&c, Parallelism::Sequential, &mut cache).unwrap();
    assert_eq!(cache.counts(), (0, 2));
    assert_eq!(rc, solve_static(&c).unwrap());
}
