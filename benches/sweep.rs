//! Sweep throughput through the library entry point: 1,000 circular-notch designs
//! (t × R = 20 × 50) per iteration, rows discarded. Brief target: ≥ 5,000 hinge designs per
//! second on 2 cores, end to end (parse, analyse, format the JSON line). Also the bundled
//! 256-design stage sweep with the lines `flexfem sweep --out` writes (compact stage line,
//! notes by reference).

use criterion::{criterion_group, criterion_main, Criterion, Throughput};
use flexfem::analysis::{self, Case};
use flexfem::design::sweep::{load, omitted_fields, run_design, run_sweep, run_sweep_formatted, LineFormat, Shard};
use std::collections::HashSet;
use std::hint::black_box;
use std::path::Path;

const SWEEP: &str = r#"{"analysis": "sweep",
 "base": {"analysis": "hinge", "material": "Al7075",
          "hinge": {"type": "circular_notch", "R": 8, "t": 2, "w": 10, "h": 10, "blank_length": 20}},
 "vary": {"hinge.t": {"from": 1, "to": 3, "steps": 20}, "hinge.R": {"from": 3, "to": 12, "steps": 50}}}"#;

fn bench(c: &mut Criterion) {
    let Ok(Case::Sweep(s)) = analysis::parse(SWEEP) else {
        panic!("bench sweep does not parse");
    };
    let sweep = s.build().expect("bench sweep builds");
    let none = HashSet::new();

    let mut g = c.benchmark_group("sweep");
    g.sample_size(10);
    g.throughput(Throughput::Elements(sweep.len() as u64));
    g.bench_function("hinge_1000_designs_rayon", |b| {
        b.iter(|| {
            run_sweep(&sweep, None, Shard::ALL, &none, |row| {
                black_box(row);
                Ok(())
            })
            .expect("sink never fails")
        })
    });
    g.finish();

    let stage = load(Path::new("cases/ruiz2019_stage_sweep.json")).expect("bundled stage sweep loads");
    let format = LineFormat {
        fields: None,
        notes_by_ref: true,
        omit: omitted_fields("stage").iter().map(|p| p.to_string()).collect(),
        loaded_displacements: false,
    };
    let mut g = c.benchmark_group("sweep_stage");
    g.sample_size(10);
    g.throughput(Throughput::Elements(stage.len() as u64));
    g.bench_function("stage_256_designs_rayon", |b| {
        b.iter(|| {
            run_sweep_formatted(
                &stage,
                Some(Path::new("cases")),
                Shard::ALL,
                &none,
                &format,
                false,
                |row| {
                    black_box(row);
                    Ok(())
                },
            )
            .expect("sink never fails")
        })
    });
    g.finish();

    let mut g = c.benchmark_group("sweep_one_design");
    g.throughput(Throughput::Elements(1));
    g.bench_function("hinge_design_line", |b| {
        b.iter(|| run_design(&sweep, None, black_box(517)))
    });
    g.finish();
}

criterion_group!(benches, bench);
criterion_main!(benches);
