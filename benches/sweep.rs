//! Sweep throughput through the library entry point: 1,000 circular-notch designs
//! (t × R = 20 × 50) per iteration, rows discarded. Brief target: ≥ 5,000 hinge designs per
//! second on 2 cores, end to end (parse, analyse, format the JSON line). Also the bundled
//! 256-design stage sweep with the lines `flexfem sweep --out` writes (compact stage line,
//! notes by reference). And 10,000 parameterised pan-tilt designs (`meshes/pantilt_8r_parameters.json`:
//! 8 corner-filleted hinges of one `hinge_types` entry driven by `$t`, `$R`, the platform height
//! `$H` moving 4 nodes; linear static) with the lines `flexfem sweep --out` writes, into a file:
//! the compiled route of parameterised cases (case and mesh file resolved and parsed once,
//! each design's parameter values set in a parsed case; see `flexfem::design::sweep`).

use criterion::{criterion_group, criterion_main, Criterion, Throughput};
use flexfem::analysis::{self, Case};
use flexfem::design::sweep::{
    load, omitted_fields, run_design, run_sweep, run_sweep_formatted, takes_compiled_route, LineFormat, Shard,
};
use std::collections::HashSet;
use std::hint::black_box;
use std::io::Write;
use std::path::Path;
use std::sync::Mutex;

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

    pantilt(c, &none);

    let mut g = c.benchmark_group("sweep_one_design");
    g.throughput(Throughput::Elements(1));
    g.bench_function("hinge_design_line", |b| {
        b.iter(|| run_design(&sweep, None, black_box(517)))
    });
    g.finish();
}

/// The bundled parameterised pan-tilt sweep widened to t × R × H = 25 × 20 × 20 designs.
fn pantilt(c: &mut Criterion, none: &HashSet<usize>) {
    let mesh = std::fs::canonicalize("meshes/pantilt_8r_parameters.json").expect("bundled mesh");
    let json = format!(
        r#"{{"analysis": "sweep",
            "base": {{"analysis": "static", "mesh": {mesh:?}, "parameters": {{"M": 10.0}},
                      "load_cases": [{{"name": "tilt", "forces": [{{"node": 13, "F": [0, 0, 0, "$M", "$M", 0]}}]}}]}},
            "vary": {{"parameters.t": {{"from": 0.4, "to": 0.9, "steps": 25}},
                      "parameters.R": {{"from": 1.0, "to": 2.4, "steps": 20}},
                      "parameters.H": {{"from": 62, "to": 78, "steps": 20}}}}}}"#
    );
    let Ok(Case::Sweep(s)) = analysis::parse(&json) else {
        panic!("pan-tilt bench sweep does not parse");
    };
    let sweep = s.build().expect("pan-tilt bench sweep builds");
    assert_eq!(sweep.len(), 10_000);
    // As `flexfem sweep --out`: static line format, every line and its newline written to a file.
    let format = LineFormat {
        fields: None,
        notes_by_ref: true,
        omit: omitted_fields("static").iter().map(|p| p.to_string()).collect(),
        loaded_displacements: true,
    };
    assert!(
        takes_compiled_route(&sweep, None, &format),
        "the compiled route is taken"
    );
    let out = std::env::temp_dir().join(format!("flexfem-bench-pantilt-{}.jsonl", std::process::id()));
    let tally = run_sweep_formatted(&sweep, None, Shard::ALL, none, &format, false, |_| Ok(())).expect("no sink error");
    assert_eq!((tally.run, tally.failed), (10_000, 0), "every design runs");
    let mut g = c.benchmark_group("sweep_pantilt");
    g.sample_size(10);
    g.throughput(Throughput::Elements(sweep.len() as u64));
    g.bench_function("pantilt_10000_designs_rayon", |b| {
        b.iter(|| {
            let file = Mutex::new(std::io::BufWriter::new(
                std::fs::File::create(&out).expect("bench output"),
            ));
            run_sweep_formatted(&sweep, None, Shard::ALL, none, &format, false, |row| {
                let mut f = file.lock().expect("one writer");
                f.write_all(row.text.as_bytes())?;
                f.write_all(b"\n")
            })
            .expect("bench output writable")
        })
    });
    g.finish();
    let _ = std::fs::remove_file(&out);
}

criterion_group!(benches, bench);
criterion_main!(benches);
