//! Shell stress recovery against the static solve on a ~100k-DOF shell model (simply supported
//! square plate, 128×128 Shell4 elements, 16 641 nodes, 99 846 DOF before supports) under
//! uniform pressure: `solve` is the linear static solve (assembly, factorisation, solve and the
//! element results), `recovery` the nodal surface stresses and centre resultants of all shells
//! (`fem::shell_recovery::shell_field`) from its displacements. Target: recovery < 10 % of
//! the solve.

use criterion::{criterion_group, criterion_main, Criterion};
use flexfem::fem::shell_loads::pressure_loads;
use flexfem::fem::shell_recovery::shell_field;
use flexfem::fem::{solve_static, Dof, Element, LoadCase, Model, Shell4, Support};
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
    let mut lc = LoadCase::new("p");
    for j in 0..n {
        for i in 0..n {
            let nodes = [id(i, j), id(i + 1, j), id(i + 1, j + 1), id(i, j + 1)];
            let x = nodes.map(|k| m.nodes[k]);
            let f = pressure_loads(&x, 0.01).expect("flat quad");
            for (k, &node) in nodes.iter().enumerate() {
                lc = lc.force(node, f[k]);
            }
            m.add_element(Element::Shell4(Shell4 {
                nodes,
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
    m.load_cases.push(lc);
    m
}

fn bench(c: &mut Criterion) {
    let model = plate(128);
    let res = solve_static(&model).expect("static");
    let u = res.load_cases[0].displacements.clone();
    let mut g = c.benchmark_group("shell_stress_100k");
    g.sample_size(10)
        .measurement_time(Duration::from_secs(10))
        .warm_up_time(Duration::from_millis(100));
    g.bench_function("solve", |b| b.iter(|| solve_static(black_box(&model)).expect("static")));
    g.bench_function("recovery", |b| {
        b.iter(|| shell_field(black_box(&model), black_box(&u)).expect("recovery"))
    });
    g.finish();
}

criterion_group!(benches, bench);
criterion_main!(benches);
