//! `stroke_at_allowable` along the nonlinear path, per design: the parallelogram guide of
//! circular notch hinges (`meshes/parallelogram_parameters.json`, 8 segments a hinge, 20
//! nominal load steps), a `static` nonlinear run of one 1 mm stroke load case with the metric,
//! against the same run without it (the difference is the metric's search); and one design of a
//! design loop (`sensitivity`/`design` with this case as `case`, the parameter t varied): the
//! case parsed at the design and run for its metrics only, each load case continued to its end
//! in one load step instead of the 20 nominal ones, then the search. Target ≤ 5 ms per design.

use criterion::{criterion_group, criterion_main, Criterion};
use flexfem::analysis;
use flexfem::analysis::design::problem::validate;
use flexfem::analysis::kinds::Static;
use flexfem::case::design_mesh::{Inner, ParameterRange};
use flexfem::problem::Problem;
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

/// One design's `stroke` as a design loop evaluates it (the parameter t at its declared value).
fn design_evaluation(c: &mut Criterion) {
    let inner = Inner {
        value: json!({
            "analysis": "static",
            "mesh": "meshes/parallelogram_parameters.json",
            "nonlinear": true,
            "load_cases": [{"name": "x1", "displacements": [{"node": 8, "dof": "ux", "value": 1.0}]}],
            "metrics": [{"name": "stroke", "kind": "stroke_at_allowable", "node": 8, "dof": "ux", "load_case": "x1"}]
        }),
        dir: None,
    };
    let ranges = std::collections::BTreeMap::from([(
        "t".to_string(),
        ParameterRange {
            bounds: Some([0.8, 1.2]),
        },
    )]);
    let v = validate::<Static>(&inner, &ranges, None).expect("validates");
    let mut worker = v.problem.worker();
    c.bench_function("parallelogram_stroke_at_allowable_design_evaluation", |b| {
        b.iter(|| v.problem.evaluate(&mut worker, black_box(&v.base)).expect("evaluates"))
    });
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

criterion_group!(benches, bench, design_evaluation);
criterion_main!(benches);
