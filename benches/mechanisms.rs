//! Mechanisms built from `hinge` elements in mesh cases: the parallelogram guide and seed
//! 002's 8R pan-tilt, linear and nonlinear (parse + build + solve of the whole case), and a
//! 10,000-design sweep over the pan-tilt's hinge parameters (linear, through the library with
//! rayon: a `sweep` case cannot vary one parameter of all eight hinge elements together, since
//! each element carries its own hinge spec and every `vary` path is an independent axis).

#[path = "../tests/common/mechanisms.rs"]
mod mechanisms;

use criterion::{criterion_group, criterion_main, Criterion};
use mechanisms::*;
use rayon::prelude::*;
use serde_json::{json, Value};
use std::hint::black_box;

fn root() -> std::path::PathBuf {
    std::path::PathBuf::from(env!("CARGO_MANIFEST_DIR"))
}

fn inline(mesh: &Value, case: Value) -> Value {
    let mut c = mesh.clone();
    for (k, v) in case.as_object().unwrap() {
        c[k] = v.clone();
    }
    c
}

fn run_text(text: &str) -> Value {
    let parsed = flexfem::analysis::parse_in(text, Some(&root().join("cases"))).expect("case loads");
    flexfem::analysis::run(&parsed).expect("analysis runs").json
}

/// The pan-tilt driven to the PRBM angles, as case text.
fn pantilt_text(p: &PanTilt, nonlinear: bool) -> String {
    let m = pantilt_mesh(p);
    let mut case = json!({"analysis": "static", "load_cases": [pantilt_drive(&m, PT_THETA)]});
    if nonlinear {
        case["nonlinear"] = json!(true);
        case["steps"] = json!(4);
    }
    serde_json::to_string(&inline(&m.mesh, case)).unwrap()
}

fn bench(c: &mut Criterion) {
    let para: Value =
        serde_json::from_str(&std::fs::read_to_string(root().join("cases/parallelogram_guide.json")).unwrap()).unwrap();
    let para_lin = serde_json::to_string(&para).unwrap();
    let mut nl = para.clone();
    nl["nonlinear"] = json!(true);
    nl["steps"] = json!(4);
    let para_nl = serde_json::to_string(&nl).unwrap();
    c.bench_function("parallelogram_linear", |b| b.iter(|| run_text(black_box(&para_lin))));
    c.bench_function("parallelogram_nonlinear_4_steps", |b| {
        b.iter(|| run_text(black_box(&para_nl)))
    });
    let std_hinge = PanTilt::standard();
    let pt_lin = pantilt_text(&std_hinge, false);
    let pt_nl = pantilt_text(&std_hinge, true);
    c.bench_function("pantilt_linear", |b| b.iter(|| run_text(black_box(&pt_lin))));
    c.bench_function("pantilt_nonlinear_4_steps", |b| b.iter(|| run_text(black_box(&pt_nl))));

    // 10 × 10 × 10 × 10 designs: δ, l, R, width (h = 15 fixed), each a full linear `static`
    // case of the pan-tilt (text → parse → build → solve → JSON result).
    let mut designs = Vec::with_capacity(10_000);
    for i in 0..10 {
        for j in 0..10 {
            for k in 0..10 {
                for m in 0..10 {
                    designs.push(PanTilt {
                        delta: 0.4 + 0.08 * i as f64,
                        l: 4.5 + 0.4 * j as f64,
                        r: 1.0 + 0.1 * k as f64,
                        width: 6.0 + 1.0 * m as f64,
                        ..std_hinge
                    });
                }
            }
        }
    }
    let mut g = c.benchmark_group("pantilt_sweep");
    g.throughput(criterion::Throughput::Elements(designs.len() as u64));
    g.sample_size(10);
    g.bench_function("10000_designs_linear", |b| {
        b.iter(|| {
            designs
                .par_iter()
                .map(|p| {
                    let out = run_text(&pantilt_text(p, false));
                    out["load_cases"][0]["max_von_mises"].as_f64().unwrap_or(0.0)
                })
                .reduce(|| 0.0, f64::max)
        })
    });
    g.finish();
}

criterion_group!(benches, bench);
criterion_main!(benches);
