//! Model generators for benchmarks and tests.

use super::model::{Beam, LoadCase, Model, Support};
use super::section::Section;
use crate::material::Material;

/// Cubic space-frame lattice of n×n×n cells of edge `cell` (mm): (n+1)³ nodes, 3n(n+1)² beams
/// along the cell edges, all nodes of the bottom face (z = 0) clamped, one load case `"top"`
/// with a total force `(0.1, 0.2, −1)·total` (N) spread over the top face nodes.
/// DOFs: 6(n+1)³ (n = 31 gives 196 608).
pub fn cubic_lattice(
    n: usize,
    cell: f64,
    section: Section,
    material: Material,
    total: f64,
) -> Model {
    let m = n + 1;
    let id = |i: usize, j: usize, k: usize| (k * m + j) * m + i;
    let mut model = Model::new();
    for k in 0..m {
        for j in 0..m {
            for i in 0..m {
                model.add_node([i as f64 * cell, j as f64 * cell, k as f64 * cell]);
            }
        }
    }
    for k in 0..m {
        for j in 0..m {
            for i in 0..m {
                let a = id(i, j, k);
                if i + 1 < m {
                    model.add_beam(Beam::new(
                        a,
                        id(i + 1, j, k),
                        section,
                        material,
                        [0.0, 0.0, 1.0],
                    ));
                }
                if j + 1 < m {
                    model.add_beam(Beam::new(
                        a,
                        id(i, j + 1, k),
                        section,
                        material,
                        [0.0, 0.0, 1.0],
                    ));
                }
                if k + 1 < m {
                    model.add_beam(Beam::new(
                        a,
                        id(i, j, k + 1),
                        section,
                        material,
                        [1.0, 0.0, 0.0],
                    ));
                }
            }
        }
        if k == 0 {
            for j in 0..m {
                for i in 0..m {
                    model.supports.push(Support::clamp(id(i, j, 0)));
                }
            }
        }
    }
    let per = total / (m * m) as f64;
    let mut case = LoadCase::new("top");
    for j in 0..m {
        for i in 0..m {
            case = case.force(id(i, j, n), [0.1 * per, 0.2 * per, -per, 0.0, 0.0, 0.0]);
        }
    }
    model.load_cases.push(case);
    model
}

/// A chain of `n_hinges` leaf flexures (rect `t`×`w`, length `l_hinge`) alternating with rigid
/// links (rect `w`×`w`, length `l_link`), each discretised into `seg` beams, clamped at the
/// start, tip load case `"tip"` (1 N along −z and 10 N·mm about y). Flexure width `w` along
/// local y, thickness `t` along local z (compliant about y). Nodes = n_hinges·2·seg + 1.
pub fn flexure_chain(
    n_hinges: usize,
    seg: usize,
    t: f64,
    w: f64,
    l_hinge: f64,
    l_link: f64,
    material: Material,
) -> Model {
    let mut model = Model::new();
    let mut x = 0.0;
    let mut prev = model.add_node([0.0, 0.0, 0.0]);
    model.supports.push(Support::clamp(prev));
    let seg = seg.max(1);
    for _ in 0..n_hinges {
        for (len, sec) in [
            (l_hinge, Section::Rect { w, h: t }),
            (l_link, Section::Rect { w, h: w }),
        ] {
            for _ in 0..seg {
                x += len / seg as f64;
                let nn = model.add_node([x, 0.0, 0.0]);
                model.add_beam(Beam::new(prev, nn, sec, material, [0.0, 0.0, 1.0]));
                prev = nn;
            }
        }
    }
    model
        .load_cases
        .push(LoadCase::new("tip").force(prev, [0.0, 0.0, -1.0, 0.0, 10.0, 0.0]));
    model
}
