//! An inline `static` case of an n×n×n-cell beam lattice (as `fem::lattice::cubic_lattice`):
//! (n+1)³ nodes 20 mm apart, 3n(n+1)² Ø2 mm Al7075 struts, the bottom face clamped, one force
//! (0.1, 0.2, −1) N per top node: 6n(n+1)² equations (n = 11: 9 504; n = 25: 101 400).
//! Shared by `tests/case_reading.rs` and `benches/case_reading.rs`.

use serde_json::{json, Value};

/// The lattice case with n cells a side.
pub fn lattice_case(n: usize) -> Value {
    let m = n + 1;
    let id = |i: usize, j: usize, k: usize| (k * m + j) * m + i;
    let mut nodes = Vec::new();
    let mut elements = Vec::new();
    for k in 0..m {
        for j in 0..m {
            for i in 0..m {
                nodes.push(json!([i as f64 * 20.0, j as f64 * 20.0, k as f64 * 20.0]));
                let a = id(i, j, k);
                let beam = |b: usize, up: [f64; 3]| json!({"type": "beam", "nodes": [a, b], "section": "strut", "material": "al", "up": up});
                if i + 1 < m {
                    elements.push(beam(id(i + 1, j, k), [0.0, 0.0, 1.0]));
                }
                if j + 1 < m {
                    elements.push(beam(id(i, j + 1, k), [0.0, 0.0, 1.0]));
                }
                if k + 1 < m {
                    elements.push(beam(id(i, j, k + 1), [1.0, 0.0, 0.0]));
                }
            }
        }
    }
    let supports: Vec<Value> = (0..m * m)
        .map(|a| json!({"node": a, "fix": ["ux", "uy", "uz", "rx", "ry", "rz"]}))
        .collect();
    let forces: Vec<Value> = (0..m * m)
        .map(|a| json!({"node": n * m * m + a, "F": [0.1, 0.2, -1.0, 0, 0, 0]}))
        .collect();
    json!({
        "analysis": "static",
        "materials": {"al": "Al7075"},
        "sections": {"strut": {"shape": "circle", "d": 2}},
        "nodes": nodes,
        "elements": elements,
        "supports": supports,
        "load_cases": [{"name": "top", "forces": forces}]
    })
}
