//! Lattice generator and Matrix Market output. The 200k-DOF timing run is an example:
//! `cargo run --release --example lattice_200k`.

use flexfem::fem::lattice::{cubic_lattice, flexure_chain};
use flexfem::fem::solve::Parallelism;
use flexfem::fem::{solve_static, Section, System};
use flexfem::material::Material;

#[test]
fn small_lattice_is_balanced_and_symmetric() {
    let m = cubic_lattice(3, 10.0, Section::Circle { d: 1.0 }, Material::AL7075, 100.0);
    assert_eq!(m.nodes.len(), 64);
    assert_eq!(m.elements.len(), 3 * 3 * 16);
    let r = solve_static(&m).unwrap();
    let c = &r.load_cases[0];
    assert!(c.statics.is_balanced(1e-9, 30.0), "{:?}", c.statics);
    // Total vertical reaction = applied load 100 N.
    let fz: f64 = c.reactions.iter().map(|r| r.1[2]).sum();
    assert!((fz - 100.0).abs() < 1e-9 * 100.0);
    // Matrix Market header and entry count.
    let sys = System::new(&m, &[], Parallelism::Sequential).unwrap();
    let mut buf = Vec::new();
    sys.matrix().write_matrix_market(&mut buf).unwrap();
    let text = String::from_utf8(buf).unwrap();
    let mut lines = text.lines();
    assert_eq!(lines.next(), Some("%%MatrixMarket matrix coordinate real symmetric"));
    let size: Vec<usize> = lines
        .find(|l| !l.starts_with('%'))
        .unwrap()
        .split_whitespace()
        .map(|v| v.parse().unwrap())
        .collect();
    assert_eq!(size, vec![48 * 6, 48 * 6, sys.matrix().nnz()]);
}

#[test]
fn refactor_on_the_same_pattern_matches_a_fresh_solve() {
    // Sweep habit: change the section, reuse pattern + symbolic factor.
    let m1 = flexure_chain(4, 3, 0.5, 8.0, 5.0, 20.0, Material::AL7075);
    let m2 = flexure_chain(4, 3, 0.7, 8.0, 5.0, 20.0, Material::AL7075);
    let s1 = System::new(&m1, &[], Parallelism::Sequential).unwrap();
    let s2 = System::with_topology_of(&s1, &m2, Parallelism::Sequential).unwrap();
    let mut s3 = s1.clone();
    s3.refactor(&m2).unwrap();
    let fresh = solve_static(&m2).unwrap();
    let cases: Vec<_> = m2.load_cases.iter().collect();
    for s in [&s2, &s3] {
        let r = s.solve_cases(&m2, &cases).unwrap();
        let (a, b) = (&r[0].displacements, &fresh.load_cases[0].displacements);
        let n = a.len() - 1;
        assert!((a[n][2] - b[n][2]).abs() <= 1e-9 * b[n][2].abs());
    }
    // A different topology is refused.
    let m3 = flexure_chain(5, 3, 0.5, 8.0, 5.0, 20.0, Material::AL7075);
    assert!(System::with_topology_of(&s1, &m3, Parallelism::Sequential).is_err());
}

#[test]
fn bundled_lattice_mesh_is_the_generator_model() {
    // meshes/lattice_3x3x3.json is `cubic_lattice(3, 20 mm, Ø2 mm struts, Al 7075, 100 N)`
    // written out in the case format: running it through `static` gives the generator's answer.
    use flexfem::analysis::{self, Case};
    let root = std::path::Path::new(env!("CARGO_MANIFEST_DIR"));
    let Case::Static(sc) = analysis::load(&root.join("cases/static_lattice.json")).unwrap() else {
        panic!()
    };
    let from_file = sc.model.build().unwrap();
    let generated = flexfem::fem::lattice::cubic_lattice(
        3,
        20.0,
        flexfem::fem::Section::Circle { d: 2.0 },
        flexfem::material::Material::AL7075,
        100.0,
    );
    let a = flexfem::fem::solve_static(&from_file).unwrap();
    let b = flexfem::fem::solve_static(&generated).unwrap();
    let (ua, ub) = (&a.load_cases[0].displacements, &b.load_cases[0].displacements);
    assert_eq!(ua.len(), 64);
    let scale = ub.iter().flatten().fold(0.0f64, |m, v| m.max(v.abs()));
    assert_eq!(ub.len(), ua.len());
    for (x, y) in ua.iter().flatten().zip(ub.iter().flatten()) {
        assert!((x - y).abs() <= 1e-9 * scale);
    }
    // Statics: the 100 N resultant (with 10 % and 20 % side components) is carried to the base.
    let res = a.load_cases[0].statics.residual();
    assert!(res.iter().all(|v| v.abs() < 1e-6 * 100.0 * 60.0), "{res:?}");
}
