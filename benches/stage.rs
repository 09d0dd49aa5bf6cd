//! Full 3-PRS compliant stage: build + factorise + solve one load case (target < 5 ms).

use criterion::{criterion_group, criterion_main, Criterion};
use flexfem::case::{self, Case};
use flexfem::stage::Drive;
use std::hint::black_box;

const CASE: &str = r#"{"analysis": "stage", "material": "Al7075",
  "stage": {"L": 109.215, "b": 47.91, "alpha0_deg": 45, "gamma_deg": 0, "leg": {"w": 10, "h": 10},
            "revolute": {"type": "circular_notch", "R": 8, "t": 2},
            "spherical": {"type": "spherical_neck", "l": 5, "t": 3, "R": 4}},
  "load_cases": [{"name": "F20", "actuator_forces": [20, 20, 20]}]}"#;

fn bench(c: &mut Criterion) {
    let Ok(Case::Stage(sc)) = case::parse(CASE) else {
        panic!("bench case must parse")
    };
    let (design, drives) = sc.validate().expect("valid");
    c.bench_function("stage_build_factor_solve_one_case", |b| {
        b.iter(|| {
            let s = design.build().expect("builds");
            s.solve(black_box(&drives)).expect("solves")
        })
    });
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
