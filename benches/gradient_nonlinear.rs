//! Gradients through the nonlinear path: the parallelogram guide's stroke at the allowable
//! stress (`meshes/parallelogram_parameters.json`, t = 0.8 mm, hinges in 8 co-rotational
//! segments) differentiated with respect to its 5 parameters (t, R, L, B, w) at the converged
//! state where its most stressed hinge reaches utilisation 1, against the nonlinear solve of
//! that state alone.

use criterion::{criterion_group, criterion_main, Criterion};
use flexfem::fem::{Dof, NonlinearOptions};
use flexfem::gradient::nonlinear::{at_state, ParamCase, Quantity, Settings, Site};
use serde_json::json;
use std::hint::black_box;
use std::path::Path;

fn bench(c: &mut Criterion) {
    let base = Path::new(env!("CARGO_MANIFEST_DIR")).join("cases");
    let case = ParamCase::new(
        json!({
            "analysis": "static",
            "mesh": "../meshes/parallelogram_parameters.json",
            "nonlinear": true,
            "parameters": {"t": 0.8},
            "load_cases": [{"name": "stroke", "displacements": [{"node": 8, "dof": "ux", "value": 1.0}]}]
        }),
        Some(&base),
    )
    .expect("case");
    let opts = NonlinearOptions {
        steps: 8,
        tol_residual: 1e-10,
        locate_critical: false,
        ..Default::default()
    };
    let site = Site::Hinge(0);
    let none: Vec<(String, f64)> = Vec::new();
    let settings = Settings::default();
    // The stroke at the allowable by Newton on the stroke with the path rate dU/dλ.
    let mut s = 3.0;
    for _ in 0..8 {
        let (_, st) = case.solve(&none, 0, s, &opts).expect("solves");
        let g = at_state(&case, &none, 0, s, &st, &[], &[Quantity::Utilisation(site)], &settings).expect("utilisation");
        s -= (g.values[0] - 1.0) * s / g.path_rates[0];
    }
    let params: Vec<String> = ["t", "R", "L", "B", "w"].iter().map(|p| p.to_string()).collect();
    let q = [Quantity::StrokeAtAllowable {
        site,
        node: 8,
        dof: Dof::Ux,
    }];
    let (_, state) = case.solve(&none, 0, s, &opts).expect("solves");
    let g = at_state(&case, &none, 0, s, &state, &params, &q, &settings).expect("gradient");
    eprintln!(
        "parallelogram: stroke at the allowable {s:.6} mm, ds*/d(t, R, L, B, w) = {:.6?}",
        g.gradients[0]
    );
    c.bench_function("parallelogram_stroke_at_allowable_gradient_5_parameters", |b| {
        b.iter(|| at_state(black_box(&case), &none, 0, s, &state, &params, &q, &settings).expect("gradient"))
    });
    c.bench_function("parallelogram_nonlinear_solve_at_allowable", |b| {
        b.iter(|| case.solve(black_box(&none), 0, s, &opts).expect("solves"))
    });
}

criterion_group!(benches, bench);
criterion_main!(benches);
