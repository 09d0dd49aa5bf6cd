//! Transient hot path: 1,000 linear steps (Newmark average acceleration, Rayleigh damping, one
//! factorisation, one solve and two sparse products per step) of
//! - the 3-PRS stage (the bundled `cases/ruiz2019_stage_step.json`: the stage mesh with hinge
//!   elements, slider frames and a platform mass; actuator 1 ramped, 96 equations), the whole
//!   run including parsing and assembly;
//! - the ~100k-DOF shell plate (128×128 Shell4, simply supported) under a step force at its
//!   centre, assembly and factorisation included.

use criterion::{criterion_group, criterion_main, Criterion};
use flexfem::fem::transient::{solve_transient, Damping, History, TransientLoad, TransientOptions};
use flexfem::fem::{Dof, NodeDof};
use std::hint::black_box;
use std::time::Duration;

#[path = "common/plate.rs"]
mod common_plate;
use common_plate::plate;

fn bench(c: &mut Criterion) {
    let root = std::path::Path::new(env!("CARGO_MANIFEST_DIR"));
    let case = flexfem::analysis::load(&root.join("cases/ruiz2019_stage_step.json")).expect("stage case");
    let mut g = c.benchmark_group("transient");
    g.sample_size(10).warm_up_time(Duration::from_millis(500));
    g.bench_function("stage_1000_steps", |b| {
        b.iter(|| flexfem::analysis::run(black_box(&case)).expect("stage transient"))
    });
    let n = 128;
    let model = plate(n);
    let centre = (n / 2) * (n + 1) + n / 2;
    let load = TransientLoad {
        node: centre,
        f: [0.0, 0.0, 100.0, 0.0, 0.0, 0.0],
        history: History::Step { start: 0.0 },
    };
    let mut opts = TransientOptions::new(1e-4, 1000);
    opts.damping = Damping {
        alpha: 0.0,
        beta: 1e-5,
        element_beta: Vec::new(),
    };
    opts.record = vec![NodeDof {
        node: centre,
        dof: Dof::Uz,
    }];
    g.measurement_time(Duration::from_secs(60));
    g.bench_function("shell_100k_1000_steps", |b| {
        b.iter(|| solve_transient(black_box(&model), std::slice::from_ref(&load), &[], &opts).expect("plate transient"))
    });
    g.finish();
}

criterion_group!(benches, bench);
criterion_main!(benches);
