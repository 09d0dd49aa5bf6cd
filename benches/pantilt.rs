//! Pan-tilt PRBM speed. Target (issue 17): quasi-static actuator torques over 3,600 path points
//! in under 10 ms.

use criterion::{criterion_group, criterion_main, Criterion};
use flexfem::kinematics::pantilt::{circle, JointSprings, PanTilt, PanTiltGeometry};
use std::hint::black_box;

fn bench(c: &mut Criterion) {
    let pt = PanTilt::new(PanTiltGeometry::default()).expect("Yu, Lu and Hao (2016) geometry");
    // Yu, Lu and Hao (2016) §4.2: γ = 10° circle, period 1 s, K = 4.78 N·mm/°, D = 0.226 N·mm·s/°.
    let path = circle(10f64.to_radians(), 0.0, 1.0, 3600, false);
    let springs = JointSprings::uniform_per_degree(4.78, 0.226);
    c.bench_function("pantilt_torques_3600_points", |b| {
        b.iter(|| pt.path(black_box(&path), black_box(&springs)))
    });
}

criterion_group! {
    name = benches;
    config = Criterion::default().sample_size(30).measurement_time(std::time::Duration::from_secs(2)).warm_up_time(std::time::Duration::from_millis(500));
    targets = bench
}
criterion_main!(benches);
