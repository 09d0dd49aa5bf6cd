//! Modal hot path: the 20 lowest modes of a ~100k-DOF shell model (simply supported square
//! plate, 128×128 Shell4 elements, 16 641 nodes, 99 846 DOF before supports), including
//! assembly of K and M, the factorisation of K − σM and the block shift-invert Lanczos.

use criterion::{criterion_group, criterion_main, Criterion};
use flexfem::fem::modal::{solve_modal, ModalOptions};
use flexfem::fem::{Dof, Element, Model, Shell4, Support};
use flexfem::material::Material;
use std::hint::black_box;
use std::time::Duration;

fn plate(n: usize) -> Model {
    let a = 1000.0;
    let mut m = Model::new();
    for j in 0..=n {
        for i in 0..=n {
            m.add_node([a * i as f64 / n as f64, a * j as f64 / n as f64, 0.0]);
        }
    }
    let id = |i: usize, j: usize| j * (n + 1) + i;
    for j in 0..n {
        for i in 0..n {
            m.add_element(Element::Shell4(Shell4 {
                nodes: [id(i, j), id(i + 1, j), id(i + 1, j + 1), id(i, j + 1)],
                t: 5.0,
                material: Material::AL7075,
            }));
        }
    }
    for j in 0..=n {
        for i in 0..=n {
            if i == 0 || j == 0 || i == n || j == n {
                m.supports.push(Support::dofs(id(i, j), &[Dof::Ux, Dof::Uy, Dof::Uz]));
            }
        }
    }
    m
}

fn bench(c: &mut Criterion) {
    let model = plate(128);
    let mut g = c.benchmark_group("modal_shell_100k");
    g.sample_size(10)
        .measurement_time(Duration::from_secs(20))
        .warm_up_time(Duration::from_millis(100));
    g.bench_function("20_modes", |b| {
        b.iter(|| solve_modal(black_box(&model), &ModalOptions::new(20)).expect("modal"))
    });
    g.finish();
}

criterion_group!(benches, bench);
criterion_main!(benches);
