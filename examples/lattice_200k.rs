//! Timing of the 200k-DOF cubic lattice (31³ cells, Ø1.5 mm struts, 1000 N): model build,
//! sparsity pattern, values, CSC sum, AMD symbolic and numeric factorisation, solve, relative
//! residual, Matrix Market output and `solve_static` end to end. Not a test (it asserts
//! nothing and its figures depend on the machine):
//!
//!     cargo run --release --example lattice_200k [-- OUT.mtx]   (default: lattice200k.mtx in the temp dir)

use flexfem::fem::assembly::Pattern;
use flexfem::fem::constraints::DofMap;
use flexfem::fem::lattice::cubic_lattice;
use flexfem::fem::solve::{Factor, Parallelism, SymbolicFactor};
use flexfem::fem::{solve_static, Section};
use flexfem::material::Material;
use std::time::Instant;

fn main() {
    let out = std::env::args().nth(1).map_or_else(
        || std::env::temp_dir().join("lattice200k.mtx"),
        std::path::PathBuf::from,
    );
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
    let mut file = std::io::BufWriter::new(std::fs::File::create(&out).unwrap());
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
