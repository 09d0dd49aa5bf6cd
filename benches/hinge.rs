//! Hinge characterisation throughput: one design at a time, and 10,000 designs with rayon.
//! Brief target: ≥ 5,000 characterisations per second on 2 cores.

use criterion::{criterion_group, criterion_main, Criterion, Throughput};
use flexfem::hinge::{characterise, profile_stiffness, HingeSpec};
use flexfem::material::Material;
use rayon::prelude::*;
use std::hint::black_box;

#[path = "../tests/common/fixtures.rs"]
mod fixtures;

/// 10,000 circular-notch and spherical-neck designs over the Ruiz et al. design box.
fn designs() -> Vec<HingeSpec> {
    (0..10_000)
        .map(|i| {
            let a = (i % 100) as f64 / 99.0;
            let b = (i / 100) as f64 / 99.0;
            if i % 2 == 0 {
                HingeSpec::CircularNotch {
                    r: 3.0 + 9.0 * a,
                    t: 1.0 + 2.0 * b,
                    w: 10.0,
                    h: 10.0,
                    blank_length: 20.0,
                }
            } else {
                HingeSpec::SphericalNeck {
                    l: 2.0 + 8.0 * a,
                    t: 2.0 + 2.0 * b,
                    r: 2.0 + 4.0 * a,
                    h: 10.0,
                    blank_length: 20.0,
                }
            }
        })
        .collect()
}

fn bench(c: &mut Criterion) {
    let al = Material::AL7075;
    let circ = fixtures::ruiz2019_revolute_hinge();
    let neck = fixtures::ruiz2019_spherical_hinge();
    let mut g = c.benchmark_group("hinge");
    g.throughput(Throughput::Elements(1));
    g.bench_function("characterise_circular_notch", |b| {
        b.iter(|| characterise(black_box(&circ), &al).unwrap())
    });
    g.bench_function("characterise_spherical_neck", |b| {
        b.iter(|| characterise(black_box(&neck), &al).unwrap())
    });
    // The other families (comparable geometry in the same blank).
    for spec in fixtures::hinge_families()[1..4].iter().copied() {
        let name = format!(
            "characterise_{}",
            serde_json::to_value(spec).unwrap()["type"].as_str().unwrap()
        );
        g.bench_function(name.as_str(), |b| {
            b.iter(|| characterise(black_box(&spec), &al).unwrap())
        });
    }
    // Only the hinge in its blank (no notch-alone configuration, no text).
    let circ_profile = circ.profile().unwrap();
    g.bench_function("stiffness_circular_notch", |b| {
        b.iter(|| profile_stiffness(black_box(&circ_profile), &al).unwrap())
    });
    let ds = designs();
    g.throughput(Throughput::Elements(ds.len() as u64));
    g.sample_size(10);
    g.bench_function("sweep_10000_single_thread", |b| {
        b.iter(|| {
            ds.iter()
                .map(|d| characterise(d, &al).unwrap().hinge.k_bend)
                .sum::<f64>()
        })
    });
    g.bench_function("sweep_10000_rayon", |b| {
        b.iter(|| {
            ds.par_iter()
                .map(|d| characterise(d, &al).unwrap().hinge.k_bend)
                .sum::<f64>()
        })
    });
    g.finish();
}

criterion_group!(benches, bench);
criterion_main!(benches);
