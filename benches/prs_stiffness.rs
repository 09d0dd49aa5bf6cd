//! 3-PRS stiffness maps. Target: a 101×101 (ψ, θ) orientation map in under 50 ms.

use criterion::{criterion_group, criterion_main, Criterion};
use flexfem::kinematics::prs_stiffness::{map, Branch, Grid, LegModel, MapMetric, PrsLayout, PrsStiffness};
use nalgebra::Vector3;
use std::hint::black_box;

fn bench(c: &mut Criterion) {
    // The Sprint Z3 of Nigatu et al. (vertical rails, r_b = 326.923 mm, r_a = 250 mm), series-chain
    // legs from their Tables I–II, over ψ, θ ∈ ±40°.
    let layout = PrsLayout::new(326.923, 250.0, 500.0, 90f64.to_radians(), Branch::Minus).expect("layout");
    let model = PrsStiffness::new(
        layout,
        LegModel::Chain {
            actuation: vec![3.8e4, 3.2e6, 9.76e5],
            constraint: vec![2.04e5, 1.79e5],
        },
    )
    .expect("model");
    let r = 40f64.to_radians();
    let grid = Grid {
        pz: 250.0,
        psi: [-r, r],
        theta: [-r, r],
        n: 101,
    };
    let metrics = [
        MapMetric::Diagonal(2),
        MapMetric::Directional(0),
        MapMetric::LambdaMin,
        MapMetric::LambdaMax,
    ];
    c.bench_function("prs_stiffness_one_pose", |b| {
        b.iter(|| {
            model
                .at(black_box(250.0), black_box(0.3), black_box(-0.2), &Vector3::zeros())
                .expect("pose")
        })
    });
    c.bench_function("prs_stiffness_map_101x101", |b| {
        b.iter(|| map(&model, black_box(&grid), &Vector3::zeros(), &metrics, 1000.0).expect("map"))
    });
}

criterion_group! {
    name = benches;
    config = Criterion::default().sample_size(10).measurement_time(std::time::Duration::from_secs(3)).warm_up_time(std::time::Duration::from_secs(1));
    targets = bench
}
criterion_main!(benches);
