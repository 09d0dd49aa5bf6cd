//! IKP and FKP speed. Target (issue 2): FKP from home to a 1 mm pose in under 5 µs.

use criterion::{criterion_group, criterion_main, Criterion};
use flexfem::kinematics::{workspace, PoseBox};
use std::hint::black_box;

#[path = "../tests/common/fixtures.rs"]
mod fixtures;

fn bench(c: &mut Criterion) {
    let prs = fixtures::ruiz2019_prs(0.0);
    let (psi, theta) = (0.1f64.to_radians(), -0.15f64.to_radians());
    let target = prs.ikp(1.0, psi, theta).expect("reachable");
    c.bench_function("ikp_one_pose", |b| {
        b.iter(|| prs.ikp(black_box(1.0), black_box(psi), black_box(theta)))
    });
    c.bench_function("fkp_home_to_1mm_pose", |b| {
        b.iter(|| prs.fkp(black_box(target.s), None))
    });
    let r = 0.2f64.to_radians();
    let bx = PoseBox {
        z: [-2.0, 2.0],
        psi: [-r, r],
        theta: [-r, r],
        steps: 9,
    };
    c.bench_function("workspace_729_poses", |b| {
        b.iter(|| workspace::sweep(&prs, black_box(&bx)))
    });
}

criterion_group! {
    name = benches;
    config = Criterion::default().sample_size(30).measurement_time(std::time::Duration::from_secs(2)).warm_up_time(std::time::Duration::from_millis(500));
    targets = bench
}
criterion_main!(benches);
