//! Fill-reducing ordering of the sparse Cholesky: ordering + symbolic + numeric factorisation of
//! a 15³-cell cubic beam lattice (24 576 DOF) with AMD and with nested dissection (METIS).
//!
//! Report mode (the measurements of the ordering note; no criterion): with
//! `FLEXFEM_ORDERING_REPORT="MODEL SIZE ORDERING"` (MODEL `lattice` (cells per edge), `plate`
//! (Shell4 elements per edge), `frame` (storeys of a 10×10-bay frame); ORDERING `auto`, `amd` or
//! `nd`) the bench builds that model, times DOF map + pattern + assembly, ordering + symbolic
//! analysis, numeric factorisation and one solve (wall and process CPU seconds), prints one JSON
//! line with nnz(L), and with `FLEXFEM_ORDERING_MTX=FILE` writes K as Matrix Market. Threads:
//! `RAYON_NUM_THREADS`. `FLEXFEM_ORDERING_PERM=FILE` factorises with the permutation in FILE (one
//! 0-based original equation per line, in elimination order, e.g. CHOLMOD's `L->Perm` for the
//! Matrix Market file written above) instead of the ordering named, to time the numeric kernel
//! on another solver's ordering; `FLEXFEM_ORDERING_EXACT=1` also reports nnz(L) without the
//! explicit zeros of amalgamated supernodes.

use criterion::Criterion;
use flexfem::fem::assembly::Pattern;
use flexfem::fem::constraints::DofMap;
use flexfem::fem::lattice::cubic_lattice;
use flexfem::fem::solve::{Factor, FillOrdering, Parallelism, SymbolicFactor};
use flexfem::fem::{Beam, LoadCase, Model, Section, Support};
use flexfem::material::Material;
use std::hint::black_box;
use std::time::{Duration, Instant};

#[path = "common/plate.rs"]
mod common_plate;

/// A 10×10-bay, `storeys`-storey space frame (bays 6 m × 6 m, storeys 3.5 m; tubes d 300 mm):
/// columns and floor beams, base clamped, a lateral load at every top node.
fn frame(storeys: usize) -> Model {
    let (nb, m) = (10usize, 11usize);
    let id = |i: usize, j: usize, k: usize| (k * m + j) * m + i;
    let mut model = Model::new();
    for k in 0..=storeys {
        for j in 0..m {
            for i in 0..m {
                model.add_node([6000.0 * i as f64, 6000.0 * j as f64, 3500.0 * k as f64]);
            }
        }
    }
    let (s, mat) = (Section::Circle { d: 300.0 }, Material::AL7075);
    for k in 0..=storeys {
        for j in 0..m {
            for i in 0..m {
                if k == 0 {
                    model.supports.push(Support::clamp(id(i, j, 0)));
                    continue;
                }
                model.add_beam(Beam::new(id(i, j, k - 1), id(i, j, k), s, mat, [1.0, 0.0, 0.0]));
                if i < nb {
                    model.add_beam(Beam::new(id(i, j, k), id(i + 1, j, k), s, mat, [0.0, 0.0, 1.0]));
                }
                if j < nb {
                    model.add_beam(Beam::new(id(i, j, k), id(i, j + 1, k), s, mat, [0.0, 0.0, 1.0]));
                }
            }
        }
    }
    let mut case = LoadCase::new("wind");
    for j in 0..m {
        for i in 0..m {
            case = case.force(id(i, j, storeys), [100.0, 0.0, 0.0, 0.0, 0.0, 0.0]);
        }
    }
    model.load_cases.push(case);
    model
}

fn lattice(cells: usize) -> Model {
    cubic_lattice(cells, 10.0, Section::Circle { d: 1.5 }, Material::AL7075, 1000.0)
}

/// Process CPU time (user + system), s, from /proc/self/stat (clock ticks of 10 ms).
fn cpu_s() -> f64 {
    let stat = std::fs::read_to_string("/proc/self/stat").unwrap_or_default();
    let after = stat.rsplit_once(')').map(|(_, r)| r).unwrap_or("");
    let f: Vec<f64> = after.split_whitespace().filter_map(|w| w.parse().ok()).collect();
    // Fields after the command: state(skipped, not a number) ppid pgrp ... utime is field 14 of
    // the whole line, i.e. index 10 of the numeric fields that follow the state letter.
    f.get(10)
        .zip(f.get(11))
        .map(|(u, s)| (u + s) / 100.0)
        .unwrap_or(f64::NAN)
}

fn timed<T>(f: impl FnOnce() -> T) -> (T, f64, f64) {
    let (t, c) = (Instant::now(), cpu_s());
    let out = f();
    (out, t.elapsed().as_secs_f64(), cpu_s() - c)
}

/// A permutation written one 0-based index per line (new equation i is old equation line i).
fn read_perm(path: &str) -> Vec<usize> {
    let text = std::fs::read_to_string(path).expect("permutation file");
    text.lines()
        .map(|l| l.trim().parse().expect("permutation index"))
        .collect()
}

fn report(spec: &str) {
    let w: Vec<&str> = spec.split_whitespace().collect();
    let size: usize = w.get(1).and_then(|s| s.parse().ok()).expect("size");
    let ordering = match w.get(2).copied().unwrap_or("auto") {
        "amd" => FillOrdering::Amd,
        "nd" => FillOrdering::Nd,
        _ => FillOrdering::Auto,
    };
    let mut model = match w[0] {
        "plate" => {
            let mut p = common_plate::plate(size);
            let centre = (size / 2) * (size + 1) + size / 2;
            p.load_cases
                .push(LoadCase::new("centre").force(centre, [0.0, 0.0, -100.0, 0.0, 0.0, 0.0]));
            p
        }
        "frame" => frame(size),
        _ => lattice(size),
    };
    model.ordering = ordering;
    let ((map, pat, k), t_build, c_build) = timed(|| {
        let map = DofMap::new(&model, &[], None).expect("dof map");
        let pat = Pattern::new(&model, &map).expect("pattern");
        let k = pat.assemble(&model, &map).expect("assemble");
        (map, pat, k)
    });
    if let Ok(path) = std::env::var("FLEXFEM_ORDERING_MTX") {
        let mut f = std::fs::File::create(&path).expect("mtx file");
        k.write_matrix_market(&mut f).expect("write mtx");
    }
    let (sym, t_order, c_order) = timed(|| match std::env::var("FLEXFEM_ORDERING_PERM") {
        Ok(path) => SymbolicFactor::with_permutation(pat.sparse(), &read_perm(&path)).expect("symbolic"),
        Err(_) => SymbolicFactor::with_ordering(pat.sparse(), ordering).expect("symbolic"),
    });
    let exact = if std::env::var("FLEXFEM_ORDERING_EXACT").is_ok_and(|v| v == "1") {
        sym.structural_nnz_l(pat.sparse()).expect("structural nnz")
    } else {
        0
    };
    let (f, t_factor, c_factor) = timed(|| Factor::new(&sym, &k, Parallelism::Rayon).expect("factor"));
    let rhs = vec![1.0; map.n_eq()];
    let (x, t_solve, c_solve) = timed(|| {
        let mut x = rhs.clone();
        f.solve_in_place(&mut x, 1).expect("solve");
        x
    });
    let r: f64 = k
        .mul_vec(&x)
        .iter()
        .zip(&rhs)
        .map(|(a, b)| (a - b).powi(2))
        .sum::<f64>()
        .sqrt()
        / (rhs.len() as f64).sqrt();
    println!(
        "{{\"model\": \"{} {size}\", \"n\": {}, \"nnz_K_lower\": {}, \"ordering\": \"{}\", \"nnz_L\": {}, \"nnz_L_structural\": {exact}, \
         \"threads\": {}, \"build_s\": [{t_build:.3}, {c_build:.2}], \"order_s\": [{t_order:.3}, {c_order:.2}], \
         \"factor_s\": [{t_factor:.3}, {c_factor:.2}], \"solve_s\": [{t_solve:.3}, {c_solve:.2}], \"residual\": {r:.2e}}}",
        w[0],
        map.n_eq(),
        k.nnz(),
        sym.ordering().name(),
        sym.nnz_l(),
        rayon::current_num_threads(),
    );
}

fn bench(c: &mut Criterion) {
    let model = lattice(15);
    let map = DofMap::new(&model, &[], None).expect("dof map");
    let pat = Pattern::new(&model, &map).expect("pattern");
    let k = pat.assemble(&model, &map).expect("assemble");
    let mut g = c.benchmark_group("ordering_lattice_25k");
    g.sample_size(10)
        .measurement_time(Duration::from_secs(3))
        .warm_up_time(Duration::from_millis(500));
    for (name, ord) in [("amd", FillOrdering::Amd), ("nd", FillOrdering::Nd)] {
        g.bench_function(format!("order_factor_{name}"), |b| {
            b.iter(|| {
                let sym = SymbolicFactor::with_ordering(black_box(pat.sparse()), ord).expect("symbolic");
                Factor::new(&sym, &k, Parallelism::Rayon).expect("factor")
            })
        });
    }
    g.finish();
}

fn main() {
    if let Ok(spec) = std::env::var("FLEXFEM_ORDERING_REPORT") {
        report(&spec);
        return;
    }
    let mut c = Criterion::default().configure_from_args();
    bench(&mut c);
    c.final_summary();
}
