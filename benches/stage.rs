//! Full 3-PRS compliant stage: build + factorise + solve one load case (target < 5 ms).

use criterion::{criterion_group, criterion_main, Criterion};
use flexfem::stage::Drive;
use std::hint::black_box;

#[path = "../tests/common/fixtures.rs"]
mod fixtures;

fn bench(c: &mut Criterion) {
    // The bundled case's first load case, F20 (equal 20 N actuator forces).
    let (design, mut drives) = fixtures::stage_case(fixtures::RUIZ2019_STAGE);
    drives.truncate(1);
    c.bench_function("stage_build_factor_solve_one_case", |b| {
        b.iter(|| {
            let s = design.build().expect("builds");
            s.solve(black_box(&drives)).expect("solves")
        })
    });
    // The same design and load case solved on the condensed stage without an FE model
    // (validation with the hinge regions, condensation, solve and recovery): what a linear
    // stage analysis and `flexfem sweep` run per design.
    let drive = drives[0].1;
    c.bench_function("stage_linear_design_one_case", |b| {
        b.iter(|| {
            let v = black_box(&design).validate().expect("valid");
            let s = v.linear().expect("condensed");
            s.response(black_box(drive))
        })
    });
    // A sweep of 1,000 stage designs (full `stage` analysis each: the load case, reach at the
    // allowable, structural stiffness, platform compliance); target ≥ 2,000 designs/s on 2 cores.
    let root = std::path::Path::new(env!("CARGO_MANIFEST_DIR"));
    let mut sweep = flexfem::design::sweep::load(&root.join("cases/ruiz2019_stage_sweep.json")).expect("bundled sweep");
    sweep.axes[0].1 = (0..10)
        .map(|k| serde_json::Value::from(1.5 + 0.15 * k as f64))
        .collect();
    sweep.axes[1].1 = (0..10).map(|k| serde_json::Value::from(5.0 + 0.7 * k as f64)).collect();
    sweep.axes[2].1 = (0..10)
        .map(|k| serde_json::Value::from(2.5 + 0.15 * k as f64))
        .collect();
    sweep.axes[3].1 = vec![serde_json::Value::from(5.0)];
    let skip = std::collections::HashSet::new();
    let mut g = c.benchmark_group("stage_sweep");
    g.throughput(criterion::Throughput::Elements(sweep.len() as u64));
    g.sample_size(10);
    g.bench_function("1000_designs", |b| {
        b.iter(|| {
            flexfem::design::sweep::run_sweep(
                &sweep,
                Some(root),
                flexfem::design::sweep::Shard::ALL,
                &skip,
                |_| Ok(()),
            )
            .expect("runs")
        })
    });
    g.finish();
    let s = design.build().expect("builds");
    let strokes = vec![("row1".to_string(), Drive::Strokes([1.395, 1.531, 1.306]))];
    c.bench_function("stage_solve_prebuilt_strokes", |b| {
        b.iter(|| s.solve(black_box(&strokes)).expect("solves"))
    });
}

criterion_group! {
    name = benches;
    config = Criterion::default().sample_size(20).measurement_time(std::time::Duration::from_secs(3)).warm_up_time(std::time::Duration::from_millis(500));
    targets = bench
}
criterion_main!(benches);
