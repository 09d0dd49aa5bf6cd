//! Structured meshes shared by the shell tests. Each test keeps its own node placement (the
//! formula, so the coordinates are the very doubles it always used); these helpers only number
//! the grid and connect it: node (i, j), i ∈ 0..=nx, j ∈ 0..=ny, is `j(nx + 1) + i`, quad (i, j)
//! joins (i, j), (i + 1, j), (i + 1, j + 1), (i, j + 1).
#![allow(dead_code)]

use flexfem::fem::{Beam, Element, LoadCase, Model, Section, Shell4, Support};
use flexfem::material::Material;
use serde_json::{json, Value};

/// Index of node (i, j) in a grid `nx` quads wide.
pub fn grid_id(nx: usize) -> impl Fn(usize, usize) -> usize + Copy {
    move |i, j| j * (nx + 1) + i
}

/// The four corners of quad (i, j), counter-clockwise.
fn quad(id: impl Fn(usize, usize) -> usize, i: usize, j: usize) -> [usize; 4] {
    [id(i, j), id(i + 1, j), id(i + 1, j + 1), id(i, j + 1)]
}

/// Adds an (nx+1)×(ny+1) grid of nodes at `at(i, j)` after the nodes already in `m`, and
/// nx×ny four-node shells of thickness `t` on it; the index of node (i, j) in `m`.
pub fn shell_grid(
    m: &mut Model,
    (nx, ny): (usize, usize),
    t: f64,
    material: Material,
    at: impl Fn(usize, usize) -> [f64; 3],
) -> impl Fn(usize, usize) -> usize + Copy {
    let base = m.nodes.len();
    for j in 0..=ny {
        for i in 0..=nx {
            m.add_node(at(i, j));
        }
    }
    let local = grid_id(nx);
    let id = move |i: usize, j: usize| base + local(i, j);
    for j in 0..ny {
        for i in 0..nx {
            m.add_element(Element::Shell4(Shell4 {
                nodes: quad(id, i, j),
                t,
                material,
            }));
        }
    }
    id
}

/// The same grid as case-file JSON: the nodes at `at(i, j)` and `shell4` elements naming
/// `section` and `material`.
pub fn shell_grid_json(
    (nx, ny): (usize, usize),
    section: &str,
    material: &str,
    at: impl Fn(usize, usize) -> [f64; 3],
) -> (Vec<[f64; 3]>, Vec<Value>) {
    let mut nodes = Vec::new();
    for j in 0..=ny {
        for i in 0..=nx {
            nodes.push(at(i, j));
        }
    }
    let id = grid_id(nx);
    let mut elements = Vec::new();
    for j in 0..ny {
        for i in 0..nx {
            elements.push(json!({"type": "shell4", "nodes": quad(id, i, j), "section": section, "material": material}));
        }
    }
    (nodes, elements)
}

/// Visits the nodes (i, j) of an `n`×`n` grid, row by row, telling whether each is on the
/// boundary (i or j is 0 or `n`).
pub fn each_node(n: usize, mut visit: impl FnMut(usize, usize, bool)) {
    for j in 0..=n {
        for i in 0..=n {
            visit(i, j, i == 0 || j == 0 || i == n || j == n);
        }
    }
}

/// [`shell_grid`] of an `n`×`n` skew plate of side `a` (mm) with skew angle φ given as
/// `(sin φ, cos φ)` (φ = 0: square): node (i, j) at x = u + v·sin φ, y = v·cos φ with u = a·i/n,
/// v = a·j/n.
pub fn skew_grid(
    m: &mut Model,
    n: usize,
    a: f64,
    (sin, cos): (f64, f64),
    t: f64,
    material: Material,
) -> impl Fn(usize, usize) -> usize + Copy {
    shell_grid(m, (n, n), t, material, move |i, j| {
        let (u, v) = (a * i as f64 / n as f64, a * j as f64 / n as f64);
        [u + v * sin, v * cos, 0.0]
    })
}

/// Two vertical leaves of a parallel leaf-spring guide, at x = `xs[0]` and `xs[1]` (y = 0), each of
/// `n` Euler–Bernoulli beams from z = 0 to z = `l` (node i at z = l·i/n), a `w` × `t` rectangle
/// with its thickness t along global x, clamped at the base; the indices of the two top nodes.
pub fn clamped_leaves(
    m: &mut Model,
    xs: [f64; 2],
    l: f64,
    n: usize,
    (w, t): (f64, f64),
    material: Material,
) -> [usize; 2] {
    xs.map(|x| {
        let base = m.nodes.len();
        for i in 0..=n {
            m.add_node([x, 0.0, l * i as f64 / n as f64]);
        }
        for i in 0..n {
            let section = Section::Rect { w, h: t };
            m.add_beam(Beam::new(base + i, base + i + 1, section, material, [1.0, 0.0, 0.0]).euler_bernoulli());
        }
        m.supports.push(Support::clamp(base));
        base + n
    })
}

/// Nodal loads of a uniform pressure/traction `q` (vector per unit area) on every shell: ¼ of
/// each element's area to each node (consistent on parallelograms).
pub fn area_load(m: &Model, q: [f64; 3]) -> Vec<[f64; 6]> {
    let mut f = vec![[0.0; 6]; m.nodes.len()];
    for e in &m.elements {
        if let Element::Shell4(s) = e {
            let p: Vec<nalgebra::Vector3<f64>> = s.nodes.iter().map(|&n| nalgebra::Vector3::from(m.nodes[n])).collect();
            let area = 0.5 * (p[2] - p[0]).cross(&(p[3] - p[1])).norm();
            for &n in &s.nodes {
                for d in 0..3 {
                    f[n][d] += q[d] * area / 4.0;
                }
            }
        }
    }
    f
}

/// `m` with one load case "load" of the nodal forces `f` (one 6-vector per node; zeros skipped).
pub fn with_loads(mut m: Model, f: &[[f64; 6]]) -> Model {
    let mut lc = LoadCase::new("load");
    for (n, v) in f.iter().enumerate() {
        if v.iter().any(|x| *x != 0.0) {
            lc = lc.force(n, *v);
        }
    }
    m.load_cases.push(lc);
    m
}

/// The node lists of the `nx`×`ny` nine-node quadrangles on a (2nx+1)×(2ny+1) node grid whose
/// node (i, j) is `id(i, j)`: corners around each element, then its edge midpoints (edges 0–1,
/// 1–2, 2–3, 3–0), then its centre; elements row by row.
pub fn nine_node_cells(nx: usize, ny: usize, id: impl Fn(usize, usize) -> usize) -> Vec<[usize; 9]> {
    let mut cells = Vec::with_capacity(nx * ny);
    for ej in 0..ny {
        for ei in 0..nx {
            let (i, j) = (2 * ei, 2 * ej);
            cells.push([
                id(i, j),
                id(i + 2, j),
                id(i + 2, j + 2),
                id(i, j + 2),
                id(i + 1, j),
                id(i + 2, j + 1),
                id(i + 1, j + 2),
                id(i, j + 1),
                id(i + 1, j + 1),
            ]);
        }
    }
    cells
}
