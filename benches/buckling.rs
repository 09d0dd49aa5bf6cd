//! Linear buckling hot path: the 10 smallest load multipliers of a ~100k-DOF 3-D frame (cubic
//! lattice of 25³ cells, 17 576 nodes, 105 456 DOF before supports, 48 750 beams, bottom face
//! clamped, compression plus a lateral push on the top face), including the reference solve
//! (assembly, factorisation of K), the geometric stiffness and the block shift-invert Lanczos.

use criterion::{criterion_group, criterion_main, Criterion};
use flexfem::fem::buckling::{solve_buckling, BucklingOptions};
use flexfem::fem::lattice::cubic_lattice;
use flexfem::fem::Section;
use flexfem::material::Material;
use std::hint::black_box;
use std::time::Duration;

fn bench(c: &mut Criterion) {
    let model = cubic_lattice(25, 10.0, Section::Rect { w: 1.0, h: 1.0 }, Material::AL7075, 1000.0);
    let mut g = c.benchmark_group("buckling_frame_100k");
    g.sample_size(10)
        .measurement_time(Duration::from_secs(20))
        .warm_up_time(Duration::from_millis(100));
    g.bench_function("10_modes", |b| {
        b.iter(|| solve_buckling(black_box(&model), 0, &BucklingOptions::new(10)).expect("buckling"))
    });
    g.finish();
}

criterion_group!(benches, bench);
criterion_main!(benches);
