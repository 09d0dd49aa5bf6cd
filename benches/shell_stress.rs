//! Shell stress recovery against the static solve on a ~100k-DOF shell model (simply supported
//! square plate, 128×128 Shell4 elements, 16 641 nodes, 99 846 DOF before supports) under
//! uniform pressure: `solve` is the linear static solve (assembly, factorisation, solve and the
//! element results), `recovery` the nodal surface stresses and centre resultants of all shells
//! (`fem::shell_recovery::shell_field`) from its displacements. Target: recovery < 10 % of
//! the solve.

use criterion::{criterion_group, criterion_main, Criterion};
use flexfem::fem::shell_loads::pressure_loads;
use flexfem::fem::shell_recovery::shell_field;
use flexfem::fem::{solve_static, LoadCase, Model};
use std::hint::black_box;
use std::time::Duration;

#[path = "common/plate.rs"]
mod common_plate;

/// The shared plate (benches/common/plate.rs) under 0.01 MPa uniform pressure.
fn plate(n: usize) -> Model {
    let mut m = common_plate::plate(n);
    let id = |i: usize, j: usize| j * (n + 1) + i;
    let mut lc = LoadCase::new("p");
    for j in 0..n {
        for i in 0..n {
            let nodes = [id(i, j), id(i + 1, j), id(i + 1, j + 1), id(i, j + 1)];
            let x = nodes.map(|k| m.nodes[k]);
            let f = pressure_loads(&x, 0.01).expect("flat quad");
            for (k, &node) in nodes.iter().enumerate() {
                lc = lc.force(node, f[k]);
            }
        }
    }
    m.load_cases.push(lc);
    m
}

fn bench(c: &mut Criterion) {
    let model = plate(128);
    let res = solve_static(&model).expect("static");
    let u = res.load_cases[0].displacements.clone();
    let mut g = c.benchmark_group("shell_stress_100k");
    g.sample_size(10)
        .measurement_time(Duration::from_secs(10))
        .warm_up_time(Duration::from_millis(100));
    g.bench_function("solve", |b| b.iter(|| solve_static(black_box(&model)).expect("static")));
    g.bench_function("recovery", |b| {
        b.iter(|| shell_field(black_box(&model), black_box(&u)).expect("recovery"))
    });
    g.finish();
}

criterion_group!(benches, bench);
criterion_main!(benches);
