//! Per-step tracking along the stage's nonlinear path (Ruiz et al. (2019) Table 4 row 1
//! strokes, 20 load steps, hinges in 4 co-rotational segments): the plain path against the
//! same path with the 6 lowest natural frequencies and the platform compliance evaluated at
//! every accepted step with the tangent stiffness of the deformed state.

use criterion::{criterion_group, criterion_main, Criterion};
use flexfem::fem::{self, PointMass, StepTrack};
use flexfem::stage::{Drive, NONLINEAR_HINGE_SEGMENTS};
use std::hint::black_box;

#[path = "../tests/common/fixtures.rs"]
mod fixtures;

fn bench(c: &mut Criterion) {
    let design = fixtures::ruiz2019_stage_design();
    let s = design.build().expect("builds");
    let strokes = vec![("row1".to_string(), Drive::Strokes([1.395, 1.531, 1.306]))];
    let (mut model, _) = s.nonlinear_model(&strokes, NONLINEAR_HINGE_SEGMENTS).expect("model");
    // Platform: an Al 7075 disc of radius b, 10 mm thick (as the stage's modal analysis).
    let (b, t) = (design.prs.b, 10.0);
    let mass = design.material.density * std::f64::consts::PI * b * b * t;
    let ixx = mass * (3.0 * b * b + t * t) / 12.0;
    model.masses.push(PointMass {
        node: s.platform,
        mass,
        inertia: [ixx, ixx, mass * b * b / 2.0],
    });
    let plain = s.nonlinear_options(20);
    let tracked = fem::NonlinearOptions {
        step_track: StepTrack {
            modes: 6,
            compliance: vec![s.platform],
        },
        ..plain.clone()
    };
    let r = fem::solve_nonlinear(&model, &tracked).expect("solves");
    let q = &r.load_cases[0].step_quantities;
    let (first, last) = (&q[0], q.last().expect("steps"));
    eprintln!(
        "stage row1: {} tracked points ({} DOFs); f1..f6 at λ = 0: {:.1?} Hz, at λ = 1: {:.1?} Hz; platform k_z {:.1} → {:.1} N/mm",
        q.len(),
        6 * model.nodes.len(),
        first.frequencies_hz(),
        last.frequencies_hz(),
        1.0 / first.compliance[0][2][2],
        1.0 / last.compliance[0][2][2]
    );
    c.bench_function("stage_nonlinear_row1_20_steps_plain", |bch| {
        bch.iter(|| fem::solve_nonlinear(black_box(&model), &plain).expect("solves"))
    });
    c.bench_function(
        "stage_nonlinear_row1_20_steps_tracked_6_modes_platform_compliance",
        |bch| bch.iter(|| fem::solve_nonlinear(black_box(&model), &tracked).expect("solves")),
    );
}

criterion_group! {
    name = benches;
    config = Criterion::default().sample_size(10).measurement_time(std::time::Duration::from_secs(3)).warm_up_time(std::time::Duration::from_millis(500));
    targets = bench
}
criterion_main!(benches);
