//! The ~100k-DOF shell plate of the modal and transient benches: a simply supported square
//! aluminium plate, 1000 mm, 5 mm thick, n×n Shell4 elements (n = 128: 16 641 nodes, 99 846 DOF
//! before supports).

use flexfem::fem::{Dof, Element, Model, Shell4, Support};
use flexfem::material::Material;

/// The plate with n×n elements.
pub fn plate(n: usize) -> Model {
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
