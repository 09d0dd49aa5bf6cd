//! Frequency response of the stage at 1,000 frequencies (the bundled
//! `cases/ruiz2019_stage_frf.json`: actuator 1 to the platform pose, 6 retained modes, 99
//! equations): modal superposition with static correction (modal solve, static solve and 1,000
//! evaluations) and the direct solve (1,000 sparse LU factorisations of the 198 × 198 real block
//! system).

use criterion::{criterion_group, criterion_main, Criterion};
use flexfem::analysis::Case;
use flexfem::fem::frf::{modal_frf, Damping, DirectFrf};
use flexfem::fem::SolverCache;
use std::hint::black_box;
use std::time::Duration;

fn bench(c: &mut Criterion) {
    let root = std::path::PathBuf::from(env!("CARGO_MANIFEST_DIR"));
    let Ok(Case::Frf(case)) = flexfem::analysis::load(&root.join("cases/ruiz2019_stage_frf.json")) else {
        panic!("cases/ruiz2019_stage_frf.json is not an frf case")
    };
    let model = case.model.build_model(false).unwrap();
    let (ports, _, _) = flexfem::analysis::frf::ports(&case, &model);
    let d = case.damping;
    let damping = Damping {
        alpha: d.alpha,
        beta: d.beta,
        zeta: d.zeta,
    };
    let mut spec = case.frequencies;
    spec.points = 1000;
    let freqs = spec.values();
    let mut g = c.benchmark_group("frf");
    g.sample_size(10).measurement_time(Duration::from_secs(5));
    g.bench_function("stage_modal_1000_frequencies", |b| {
        b.iter(|| {
            let m = modal_frf(&model, &ports, case.modes, &mut SolverCache::new()).unwrap();
            let h: Vec<_> = freqs.iter().map(|&f| m.response(f, &damping)).collect();
            black_box(h)
        })
    });
    g.bench_function("stage_direct_1000_frequencies", |b| {
        b.iter(|| {
            let direct = DirectFrf::new(&model, &ports, damping).unwrap();
            let h: Vec<_> = freqs.iter().map(|&f| direct.response(f).unwrap()).collect();
            black_box(h)
        })
    });
    g.finish();
}

criterion_group!(benches, bench);
criterion_main!(benches);
