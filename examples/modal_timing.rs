//! Phase timings of the 100k-DOF modal benchmark model (see benches/modal.rs).
use flexfem::fem::assembly::{MatrixKind, Pattern};
use flexfem::fem::constraints::DofMap;
use flexfem::fem::modal::{solve_modal, ModalOptions};
use flexfem::fem::solve::{Factor, Parallelism, SymbolicFactor};
use flexfem::fem::{Dof, Element, Model, Shell4, Support};
use flexfem::material::Material;
use std::time::Instant;

fn main() {
    let n = 128;
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
            m.add_element(Element::Shell4(Shell4 { nodes: [id(i, j), id(i + 1, j), id(i + 1, j + 1), id(i, j + 1)], t: 5.0, material: Material::AL7075 }));
        }
    }
    for j in 0..=n {
        for i in 0..=n {
            if i == 0 || j == 0 || i == n || j == n {
                m.supports.push(Support::dofs(id(i, j), &[Dof::Ux, Dof::Uy, Dof::Uz]));
            }
        }
    }
    let t = Instant::now();
    let map = DofMap::new(&m, &[], None).unwrap();
    let pat = Pattern::new(&m, &map).unwrap();
    println!("pattern {:?}", t.elapsed());
    let t = Instant::now();
    let k = pat.matrix(&pat.values_of(&m, &map, MatrixKind::Stiffness).unwrap()).unwrap();
    println!("assemble K {:?}", t.elapsed());
    let t = Instant::now();
    let sym = SymbolicFactor::new(pat.sparse()).unwrap();
    println!("symbolic {:?} nnz(L) {}", t.elapsed(), sym.nnz_l());
    let t = Instant::now();
    let f = Factor::new(&sym, &k, Parallelism::Rayon).unwrap();
    println!("numeric {:?}", t.elapsed());
    let t = Instant::now();
    let mut rhs = vec![1.0; 6 * map.n_eq()];
    f.solve_in_place(&mut rhs, 6).unwrap();
    println!("6 solves {:?}", t.elapsed());
    let t = Instant::now();
    let r = solve_modal(&m, &ModalOptions::new(20)).unwrap();
    println!("modal total {:?}, solves {}", t.elapsed(), r.lanczos_steps);
}
