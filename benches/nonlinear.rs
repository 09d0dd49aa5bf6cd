//! Geometrically nonlinear stage load case (Ruiz et al. (2019) Table 4 row 1 strokes), 20 load steps,
//! co-rotational hinges and legs (target < 100 ms).

use criterion::{criterion_group, criterion_main, Criterion};
use flexfem::stage::Drive;
use std::hint::black_box;

#[path = "../tests/common/fixtures.rs"]
mod fixtures;

fn bench(c: &mut Criterion) {
    let design = fixtures::ruiz2019_stage_design();
    let s = design.build().expect("builds");
    let strokes = vec![("row1".to_string(), Drive::Strokes([1.395, 1.531, 1.306]))];
    c.bench_function("stage_nonlinear_row1_20_steps", |b| {
        b.iter(|| s.solve_nonlinear(black_box(&strokes), 20).expect("solves"))
    });
    let opts = s.nonlinear_options(20);
    c.bench_function("stage_nonlinear_row1_20_steps_8_hinge_segments", |b| {
        b.iter(|| {
            s.solve_nonlinear_segments(black_box(&strokes), &opts, 8)
                .expect("solves")
        })
    });
    let forces = vec![("F40".to_string(), Drive::Forces([40.0, 40.0, 40.0]))];
    c.bench_function("stage_nonlinear_f40_20_steps", |b| {
        b.iter(|| s.solve_nonlinear(black_box(&forces), 20).expect("solves"))
    });
}

criterion_group! {
    name = benches;
    config = Criterion::default().sample_size(10).measurement_time(std::time::Duration::from_secs(3)).warm_up_time(std::time::Duration::from_millis(500));
    targets = bench
}
criterion_main!(benches);
