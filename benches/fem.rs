//! FEM hot paths: assembly (values on a fixed pattern), numeric refactorisation, and the full
//! pipeline (DOF map + pattern + AMD + factor + solve + recovery).
//!
//! Models: a ~200k-DOF cubic beam lattice (31³ cells, 196 608 DOF) and a ~2k-DOF flexure
//! chain (20 hinges × 2 × 8 segments, 1 938 DOF), plus a 15³-cell lattice (24 576 DOF) for the
//! factorisation path. The 200k factorisation takes tens of seconds on two cores, so its
//! factor/solve benches only run with `FLEXFEM_BENCH_BIG=1`.

use criterion::{criterion_group, criterion_main, Criterion};
use flexfem::fem::assembly::Pattern;
use flexfem::fem::constraints::DofMap;
use flexfem::fem::lattice::{cubic_lattice, flexure_chain};
use flexfem::fem::solve::{Factor, Parallelism, SymbolicFactor};
use flexfem::fem::{Model, Section, System};
use flexfem::material::Material;
use std::hint::black_box;
use std::time::Duration;

fn full(model: &Model) {
    let sys = System::new(model, &[], Parallelism::Rayon).expect("bench model solves");
    let cases: Vec<_> = model.load_cases.iter().collect();
    black_box(sys.solve_cases(model, &cases).expect("solve"));
}

fn pipeline(c: &mut Criterion, name: &str, model: &Model, with_factor: bool) {
    let map = DofMap::new(model, &[], None).expect("dof map");
    let pat = Pattern::new(model, &map).expect("pattern");
    let mut g = c.benchmark_group(name);
    g.sample_size(10)
        .measurement_time(Duration::from_secs(3))
        .warm_up_time(Duration::from_millis(500));
    g.bench_function("pattern", |b| {
        b.iter(|| Pattern::new(black_box(model), &map).expect("pattern"))
    });
    g.bench_function("assemble_values", |b| {
        b.iter(|| {
            pat.matrix(&pat.values(black_box(model), &map).expect("values"))
                .expect("csc")
        })
    });
    if with_factor {
        let k = pat.assemble(model, &map).expect("assemble");
        let sym = SymbolicFactor::new(pat.sparse()).expect("symbolic");
        let mut f = Factor::new(&sym, &k, Parallelism::Rayon).expect("factor");
        g.bench_function("symbolic_amd", |b| {
            b.iter(|| SymbolicFactor::new(pat.sparse()).expect("symbolic"))
        });
        g.bench_function("numeric_refactor", |b| {
            b.iter(|| f.refactor(black_box(&k)).expect("refactor"))
        });
        let rhs = vec![1.0; pat.n_eq()];
        g.bench_function("solve_1_rhs", |b| {
            b.iter(|| {
                let mut x = rhs.clone();
                f.solve_in_place(&mut x, 1).expect("solve");
                x
            })
        });
        g.bench_function("full_assembly_factor_solve_recovery", |b| {
            b.iter(|| full(black_box(model)))
        });
    }
    g.finish();
}

fn bench(c: &mut Criterion) {
    let big = cubic_lattice(31, 10.0, Section::Circle { d: 1.5 }, Material::AL7075, 1000.0);
    let run_big = std::env::var("FLEXFEM_BENCH_BIG").is_ok_and(|v| v == "1");
    pipeline(c, "lattice_200k", &big, run_big);
    drop(big);
    let mid = cubic_lattice(15, 10.0, Section::Circle { d: 1.5 }, Material::AL7075, 1000.0);
    pipeline(c, "lattice_25k", &mid, true);
    let chain = flexure_chain(20, 8, 0.5, 8.0, 5.0, 20.0, Material::AL7075);
    pipeline(c, "flexure_chain_2k", &chain, true);
}

criterion_group!(benches, bench);
criterion_main!(benches);
