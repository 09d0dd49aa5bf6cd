//! Gradient hot path: 5 metrics (stiffness, compliance, displacement, hinge rotation, largest
//! utilisation) of the parallelogram guide (`meshes/parallelogram_parameters.json`, four
//! 8-segment circular notches, rigid links) with respect to 5 parameters (t, R, L, B, w), by
//! the direct method ([`flexfem::gradient::Linear`]): the case as written is kept in memory, the
//! solver cache keeps the symbolic factorisation between calls.

use criterion::{criterion_group, criterion_main, Criterion};
use flexfem::analysis::{self, Case};
use flexfem::gradient::{Linear, Target};
use serde_json::json;
use std::hint::black_box;
use std::path::Path;
use std::time::Duration;

fn bench(c: &mut Criterion) {
    let dir = Path::new(env!("CARGO_MANIFEST_DIR")).join("meshes");
    let case = json!({
        "analysis": "static",
        "mesh": "parallelogram_parameters.json",
        "load_cases": [{"name": "push_x", "forces": [{"node": 8, "F": [1, 0, 0, 0, 0, 0]}]}],
        "metrics": [
            {"name": "k_x", "kind": "stiffness", "node": 8, "dof": "ux"},
            {"name": "c_rz", "kind": "compliance", "node": 8, "dof": "rz"},
            {"name": "u_x", "kind": "displacement", "node": 8, "dof": "ux", "load_case": "push_x"},
            {"name": "theta", "kind": "hinge_rotation", "element": 0, "load_case": "push_x"},
            {"name": "util", "kind": "max_utilisation", "load_case": "push_x"}
        ],
        "gradients": true
    });
    let parsed = analysis::case_file::parse_resolved(case, Some(&dir), true).expect("case");
    let Case::Static(s) = parsed.case else {
        panic!("a static case")
    };
    let targets = s.metrics.iter().map(|m| Target::Metric(m.name.clone())).collect();
    let grad = Linear::new(s.written.clone().expect("kept"), targets)
        .with_parameters(["t", "R", "L", "B", "w"].map(String::from).to_vec());
    let mut cache = flexfem::fem::SolverCache::new();
    let mut g = c.benchmark_group("gradient_parallelogram");
    g.sample_size(10)
        .measurement_time(Duration::from_secs(5))
        .warm_up_time(Duration::from_millis(200));
    g.bench_function("5_metrics_5_parameters", |b| {
        b.iter(|| {
            grad.evaluate(black_box(&Default::default()), &mut cache)
                .expect("gradients")
        })
    });
    g.finish();
}

criterion_group!(benches, bench);
criterion_main!(benches);
