//! Design of a mesh mechanism end to end: `cases/parallelogram_design_5.json`, the gradient
//! sizing of the parallelogram guide carrying a platform (five parameters t, R, w, L, B;
//! requirements on the stroke at the allowable, the out-of-plane stiffness and the first
//! frequency; least actuation stiffness), as `flexfem run` runs it: the case read, the Halton
//! samples on rayon, the local search on direct-method gradients (the frequency by its
//! eigenvalue derivative), the gradients at the design. Beside it, the three-parameter sizing
//! of `cases/parallelogram_design.json` (no platform, no frequency).

use criterion::{criterion_group, criterion_main, Criterion};
use flexfem::analysis;
use std::hint::black_box;
use std::path::Path;
use std::time::Duration;

fn bench(c: &mut Criterion) {
    let cases = Path::new(env!("CARGO_MANIFEST_DIR")).join("cases");
    let mut g = c.benchmark_group("design_parallelogram");
    g.sample_size(10)
        .measurement_time(Duration::from_secs(10))
        .warm_up_time(Duration::from_millis(200));
    for (name, file) in [
        ("5_parameters_end_to_end", "parallelogram_design_5.json"),
        ("3_parameters_end_to_end", "parallelogram_design.json"),
    ] {
        let file = cases.join(file);
        g.bench_function(name, |b| {
            b.iter(|| {
                let case = analysis::case_file::load(black_box(&file)).expect("case");
                analysis::run(&case).expect("design")
            })
        });
    }
    g.finish();
}

criterion_group!(benches, bench);
criterion_main!(benches);
