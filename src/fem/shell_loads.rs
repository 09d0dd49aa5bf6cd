//! Consistent nodal loads of distributed loads on four-node shells ([`super::shell`]).
//!
//! * Uniform pressure p (MPa) along the element normal: fᵢ = p·n∫Nᵢ dA over the element's mean
//!   plane (2×2 Gauss, exact for the bilinear map), carried to the nodes through the element's
//!   transformation (frame and warping arms: the force is parallel to each arm, so no moment).
//!   On a flat rectangle each node takes p·A/4; on a triangle [a, b, c, c] the two corners at c
//!   add up.
//! * Uniform edge loads q (N/mm) and edge moments m (N·mm/mm) along a straight edge of length
//!   L: each end node takes q·L/2 and m·L/2 (linear shape functions along the edge). On the
//!   three-node edge of a nine-node shell ([`edge_loads3`]) the quadratic shape functions give
//!   L/6, 2L/3, L/6 when the midpoint node is at the middle.

use super::shell::{cartesian, shell_geometry, Vec24, ETA, G2, XI};

/// Nodal loads [Fx, Fy, Fz (N), Mx, My, Mz (N·mm)] (global axes) of a uniform pressure `p`
/// (MPa) acting along the element normal n = (local z: g₁ × g₂ of the diagonals' mid-lines, so
/// +z for nodes listed counter-clockwise seen from +z) on the shell with corners `x`. `None`
/// for a degenerate quadrilateral.
pub fn pressure_loads(x: &[[f64; 3]; 4], p: f64) -> Option<[[f64; 6]; 4]> {
    let g = shell_geometry(x)?;
    let mut f = Vec24::zeros();
    for gp in 0..4 {
        let (n, _, _, det, _) = cartesian(&g.xy, XI[gp] * G2, ETA[gp] * G2)?;
        for i in 0..4 {
            f[6 * i + 2] += p * n[i] * det;
        }
    }
    let fg = g.t.transpose() * f;
    Some(std::array::from_fn(|i| std::array::from_fn(|d| fg[6 * i + d])))
}

/// Nodal loads of a uniform edge load `q` [qx, qy, qz] (N/mm) and edge moment `m` [mx, my, mz]
/// (N·mm/mm), global axes, on the straight edge from `a` to `b`: half of q·L and m·L at each
/// end.
pub fn edge_loads(a: [f64; 3], b: [f64; 3], q: [f64; 3], m: [f64; 3]) -> [[f64; 6]; 2] {
    let l = ((b[0] - a[0]).powi(2) + (b[1] - a[1]).powi(2) + (b[2] - a[2]).powi(2)).sqrt();
    let h = 0.5 * l;
    let f = [q[0] * h, q[1] * h, q[2] * h, m[0] * h, m[1] * h, m[2] * h];
    [f, f]
}

/// Nodal loads of a uniform edge load `q` [qx, qy, qz] (N/mm) and edge moment `m` [mx, my, mz]
/// (N·mm/mm), global axes, along the three-node edge `a`, `mid`, `b` of a nine-node shell:
/// fᵢ = ∫Nᵢ ds with the quadratic shape functions of the edge (Gauss, 4 points; exact on a
/// straight edge, where it is L/6, 2L/3, L/6 with the midpoint at the middle). Order: a, mid, b.
pub fn edge_loads3(a: [f64; 3], mid: [f64; 3], b: [f64; 3], q: [f64; 3], m: [f64; 3]) -> [[f64; 6]; 3] {
    const S: [f64; 4] = [
        -0.861_136_311_594_052_6,
        -0.339_981_043_584_856_3,
        0.339_981_043_584_856_3,
        0.861_136_311_594_052_6,
    ];
    const W: [f64; 4] = [
        0.347_854_845_137_453_9,
        0.652_145_154_862_546_1,
        0.652_145_154_862_546_1,
        0.347_854_845_137_453_9,
    ];
    let x = [a, mid, b];
    let mut w = [0.0; 3];
    for (s, wt) in S.iter().zip(W) {
        let n = [0.5 * s * (s - 1.0), 1.0 - s * s, 0.5 * s * (s + 1.0)];
        let dn = [s - 0.5, -2.0 * s, s + 0.5];
        let mut t = [0.0; 3];
        for (xi, di) in x.iter().zip(dn) {
            for c in 0..3 {
                t[c] += di * xi[c];
            }
        }
        let jac = (t[0] * t[0] + t[1] * t[1] + t[2] * t[2]).sqrt();
        for i in 0..3 {
            w[i] += wt * n[i] * jac;
        }
    }
    w.map(|wi| [q[0] * wi, q[1] * wi, q[2] * wi, m[0] * wi, m[1] * wi, m[2] * wi])
}
