//! Modal hot path: the 20 lowest modes of a ~100k-DOF shell model (simply supported square
//! plate, 128×128 Shell4 elements, 16 641 nodes, 99 846 DOF before supports), including
//! assembly of K and M, the factorisation of K − σM and the block shift-invert Lanczos.

use criterion::{criterion_group, criterion_main, Criterion};
use flexfem::fem::modal::{solve_modal, ModalOptions};
use std::hint::black_box;
use std::time::Duration;

#[path = "common/plate.rs"]
mod common_plate;
use common_plate::plate;

fn bench(c: &mut Criterion) {
    let model = plate(128);
    let mut g = c.benchmark_group("modal_shell_100k");
    g.sample_size(10)
        .measurement_time(Duration::from_secs(20))
        .warm_up_time(Duration::from_millis(100));
    g.bench_function("20_modes", |b| {
        b.iter(|| solve_modal(black_box(&model), &ModalOptions::new(20)).expect("modal"))
    });
    g.finish();
}

criterion_group!(benches, bench);
criterion_main!(benches);
