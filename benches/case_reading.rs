//! Reading a case against running it: `flexfem check` and `flexfem run` of the inline beam
//! lattice (`tests/common/lattice_case.rs`) at 9 504 and 101 400 equations, each from its case
//! file on disk, as the commands do (check: read, resolve, parse, validate; run: the same, then
//! analyse and write the JSON result text `run` prints). Brief target: check ≤ 5 % of run.

use criterion::{criterion_group, criterion_main, Criterion};
use flexfem::analysis;
use std::hint::black_box;
use std::path::Path;

#[path = "../tests/common/lattice_case.rs"]
mod lattice;

/// What `flexfem check CASE` does for a non-sweep case.
fn check(path: &Path) {
    let parsed = analysis::load_resolved(path).expect("lattice case loads");
    analysis::check(&parsed.case).expect("lattice case checks");
    black_box(parsed);
}

/// What `flexfem run CASE` does (without `--out`): the result text it prints.
fn run(path: &Path) -> String {
    let parsed = analysis::load_resolved(path).expect("lattice case loads");
    let mut outcome = analysis::run(&parsed.case).expect("lattice case runs");
    outcome.echo_parameters(&parsed.parameters);
    flexfem::report::json::pretty(&outcome.json)
}

fn bench(c: &mut Criterion) {
    let dir = std::env::temp_dir().join(format!("flexfem-bench-case-reading-{}", std::process::id()));
    std::fs::create_dir_all(&dir).expect("temp dir");
    for (n, label) in [(11, "lattice_10k"), (25, "lattice_100k")] {
        let path = dir.join(format!("{label}.json"));
        let text = serde_json::to_string_pretty(&lattice::lattice_case(n)).expect("case serialises");
        std::fs::write(&path, text).expect("case written");
        let mut g = c.benchmark_group(format!("case_reading_{label}"));
        g.sample_size(10);
        g.bench_function("check", |b| b.iter(|| check(&path)));
        g.bench_function("run", |b| b.iter(|| black_box(run(&path).len())));
        g.finish();
    }
    let _ = std::fs::remove_dir_all(&dir);
}

criterion_group!(benches, bench);
criterion_main!(benches);
