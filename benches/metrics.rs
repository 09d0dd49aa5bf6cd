//! `stroke_at_allowable` along the nonlinear path, per design: the parallelogram guide of
//! circular notch hinges (`meshes/parallelogram_parameters.json`, 8 segments a hinge, 20
//! nominal load steps), a `static` nonlinear run of one 1 mm stroke load case with the metric,
//! against the same run without it (the difference is the metric's search). Target ≤ 5 ms.

use criterion::{criterion_group, criterion_main, Criterion};
use flexfem::analysis;
use serde_json::json;
use std::hint::black_box;

fn case(with_metric: bool) -> analysis::Case {
    let metrics = if with_metric {
        json!([{"name": "stroke", "kind": "stroke_at_allowable", "node": 8, "dof": "ux", "load_case": "x1"}])
    } else {
        json!([])
    };
    let v = json!({
        "analysis": "static",
        "mesh": "meshes/parallelogram_parameters.json",
        "nonlinear": true,
        "load_cases": [{"name": "x1", "displacements": [{"node": 8, "dof": "ux", "value": 1.0}]}],
        "metrics": metrics
    });
    analysis::parse_value(v, None).expect("parses")
}

fn bench(c: &mut Criterion) {
    let with = case(true);
    let without = case(false);
    c.bench_function("parallelogram_nonlinear_stroke_at_allowable", |b| {
        b.iter(|| analysis::run(black_box(&with)).expect("runs"))
    });
    c.bench_function("parallelogram_nonlinear_run_without_metrics", |b| {
        b.iter(|| analysis::run(black_box(&without)).expect("runs"))
    });
}

criterion_group!(benches, bench);
criterion_main!(benches);
