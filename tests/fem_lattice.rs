//! Lattice generator, Matrix Market output and the 200k-DOF timing run (ignored by default:
//! `cargo test --release --test fem_lattice -- --ignored --nocapture`).

use flexfem::fem::assembly::Pattern;
use flexfem::fem::constraints::DofMap;
use flexfem::fem::lattice::{cubic_lattice, flexure_chain};
use flexfem::fem::solve::{Factor, Parallelism, SymbolicFactor};
use flexfem::fem::{solve_static, Section, System};
use flexfem::material::Material;
use std::time::Instant;

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
#[ignore]
fn lattice_200k_timing_and_matrix_market() {
    let t = Instant::now();
    let m = cubic_lattice(31, 10.0, Section::Circle { d: 1.5 }, Material::AL7075, 1000.0);
    println!("build model: {:?}, {} DOF", t.elapsed(), m.n_dofs());
    let t = Instant::now();
    let map = DofMap::new(&m, &[], None).unwrap();
    let pat = Pattern::new(&m, &map).unwrap();
    println!(
        "pattern: {:?} ({} eqs, {} triplets, {} nnz)",
        t.elapsed(),
        pat.n_eq(),
        pat.n_triplets(),
        pat.nnz()
    );
    let t = Instant::now();
    let vals = pat.values(&m, &map).unwrap();
    println!("values: {:?}", t.elapsed());
    let t = Instant::now();
    let k = pat.matrix(&vals).unwrap();
    println!("sum into CSC: {:?}", t.elapsed());
    let t = Instant::now();
    let sym = SymbolicFactor::new(pat.sparse()).unwrap();
    println!("symbolic (AMD): {:?}, nnz(L) = {}", t.elapsed(), sym.nnz_l());
    let t = Instant::now();
    let f = Factor::new(&sym, &k, Parallelism::Rayon).unwrap();
    println!("numeric factor: {:?}", t.elapsed());
    let t = Instant::now();
    let mut rhs = vec![1.0; pat.n_eq()];
    f.solve_in_place(&mut rhs, 1).unwrap();
    println!("solve: {:?}", t.elapsed());
    let kx = k.mul_vec(&rhs);
    let res = kx.iter().map(|v| (v - 1.0).powi(2)).sum::<f64>().sqrt() / (pat.n_eq() as f64).sqrt();
    println!("relative residual: {res:e}");
    let t = Instant::now();
    let mut file = std::io::BufWriter::new(std::fs::File::create("/tmp/lattice200k.mtx").unwrap());
    k.write_matrix_market(&mut file).unwrap();
    println!("mtx written: {:?}", t.elapsed());
    let t = Instant::now();
    let r = solve_static(&m).unwrap();
    println!(
        "solve_static end to end (incl. recovery): {:?}, max vM {:?}",
        t.elapsed(),
        r.load_cases[0].max_von_mises
    );
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
    for (x, y) in ua.iter().flatten().zip(ub.iter().flatten()) {
        assert!((x - y).abs() <= 1e-9 * scale);
    }
    // Statics: the 100 N resultant (with 10 % and 20 % side components) is carried to the base.
    let res = a.load_cases[0].statics.residual();
    assert!(res.iter().all(|v| v.abs() < 1e-6 * 100.0 * 60.0), "{res:?}");
}
