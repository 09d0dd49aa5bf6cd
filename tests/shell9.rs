//! The nine-node flat shell (`shell9`: MITC9 plate, biquadratic membrane, consistent mass)
//! against closed forms and published plate values: coarse-mesh frequencies of clamped square
//! and 45° skew plates, the clamped plate under pressure, constant-strain and constant-moment
//! patches on a distorted mesh, a leaf's root stress, and the refusals of curved and folded
//! geometry.

use flexfem::fem::modal::{solve_modal, ModalOptions};
use flexfem::fem::{self, Element, LoadCase, Model, Shell9, Support};
use flexfem::material::Material;

const A: f64 = 100.0;

/// Clamped square plate, thin-plate theory: A. W. Leissa, Vibration of Plates, NASA SP-160
/// (1969), Table 4.23 (the reference of `tests/shell_coarse_mesh.rs`).
const SQUARE: [f64; 6] = [35.992, 73.413, 73.413, 108.27, 131.64, 132.24];
/// Clamped 45° rhombic plate: the converged reference of `tests/shell_coarse_mesh.rs`
/// (Richardson extrapolation of the four-node shell from 32×32 and 64×64, a discretization
/// independent of this element).
const SKEW45: [f64; 6] = [65.642, 106.489, 148.300, 157.226, 196.743, 229.464];

/// A (2ne+1)² node grid of `ne`×`ne` nine-node elements over the skewed square of side `a`
/// (node (i, j) at u = a·i/2ne, v = a·j/2ne, x = u + v·sin φ, y = v·cos φ, then `map`);
/// returns the node id function of the grid.
fn grid9(
    m: &mut Model,
    ne: usize,
    a: [f64; 2],
    skew_deg: f64,
    t: f64,
    mat: Material,
    map: impl Fn([f64; 3]) -> [f64; 3],
) -> impl Fn(usize, usize) -> usize {
    let n = 2 * ne;
    let (sn, cs) = (skew_deg.to_radians().sin(), skew_deg.to_radians().cos());
    let base = m.nodes.len();
    for j in 0..=n {
        for i in 0..=n {
            let (u, v) = (a[0] * i as f64 / n as f64, a[1] * j as f64 / n as f64);
            m.add_node(map([u + v * sn, v * cs, 0.0]));
        }
    }
    let id = move |i: usize, j: usize| base + j * (n + 1) + i;
    for ej in 0..ne {
        for ei in 0..ne {
            let (i, j) = (2 * ei, 2 * ej);
            let nodes = [
                id(i, j),
                id(i + 2, j),
                id(i + 2, j + 2),
                id(i, j + 2),
                id(i + 1, j),
                id(i + 2, j + 1),
                id(i + 1, j + 2),
                id(i, j + 1),
                id(i + 1, j + 1),
            ];
            m.add_element(Element::Shell9(Shell9 {
                nodes,
                t,
                material: mat,
            }));
        }
    }
    id
}

/// λ = ωa²√(ρt/D) of modes 1–6 of the clamped plate, `ne`×`ne` nine-node elements, a = 100,
/// t = 0.1 (a/t = 1000: thin-plate theory), Al 7075.
fn clamped_plate(ne: usize, skew_deg: f64) -> Vec<f64> {
    let (t, mat) = (0.1, Material::AL7075);
    let mut m = Model::new();
    let id = grid9(&mut m, ne, [A, A], skew_deg, t, mat, |x| x);
    let n = 2 * ne;
    for j in 0..=n {
        for i in 0..=n {
            if i == 0 || j == 0 || i == n || j == n {
                m.supports.push(Support::clamp(id(i, j)));
            }
        }
    }
    let r = solve_modal(&m, &ModalOptions::new(6)).unwrap();
    let d = mat.e * t.powi(3) / (12.0 * (1.0 - mat.nu * mat.nu));
    r.modes
        .iter()
        .map(|md| 2.0 * std::f64::consts::PI * md.frequency_hz * A * A * (mat.density * t / d).sqrt())
        .collect()
}

fn errors(ne: usize, skew_deg: f64, reference: &[f64; 6]) -> Vec<f64> {
    let lam = clamped_plate(ne, skew_deg);
    assert_eq!(lam.len(), 6);
    let err: Vec<f64> = lam.iter().zip(reference).map(|(l, r)| l / r - 1.0).collect();
    eprintln!(
        "shell9 skew {skew_deg}° {ne}x{ne}: {}",
        err.iter()
            .map(|e| format!("{:+.2} %", 100.0 * e))
            .collect::<Vec<_>>()
            .join(", ")
    );
    err
}

/// Coarse-mesh frequencies, modes 1–6, 8×8 elements: the ±5 % the four-node shell misses at
/// 8×8 (its −7.07 % / +7.08 %, `tests/shell_coarse_mesh.rs`). Measured: square −0.00 +0.11 +0.11
/// +0.09 +0.57 +0.59 %, skew +0.07 +0.34 +0.74 +0.34 +1.41 +1.25 %, converging from above
/// (consistent mass) — held to 1 % and 2 %, and none below −0.1 %.
///
/// The price, stated: an 8×8 nine-node mesh has the 17×17 nodes of a 16×16 four-node mesh. On
/// the 9×9 nodes of the four-node 8×8 (4×4 nine-node) it reads +0.28…+11.03 % (square) and
/// +0.94…+19.67 % (skew), worse than the four-node shell's −7.07…+0.77 % and +0.65…+7.08 %; on
/// the 13×13 nodes of the four-node 12×12 (6×6) +0.04…+1.89 % and +0.21…+4.16 % against
/// −3.1…+0.4 % and +0.0…+2.9 %. Pinned below, so that a change of either is seen.
#[test]
fn clamped_plates_within_5_percent_at_8x8_nine_node_elements() {
    for (skew, reference, tol) in [(0.0, SQUARE, 0.01), (45.0, SKEW45, 0.02)] {
        for (k, e) in errors(8, skew, &reference).iter().enumerate() {
            assert!(
                *e < tol && *e > -0.001,
                "skew {skew}° 8x8 mode {}: {:+.2} % (allowed −0.1 … +{} %)",
                k + 1,
                100.0 * e,
                100.0 * tol
            );
        }
    }
}

/// The equal-node comparison of the test above, pinned (measured worst mode: 4×4 square
/// +11.03 %, skew +19.67 %; 6×6 square +1.89 %, skew +4.16 %).
#[test]
fn clamped_plates_on_the_four_node_shells_node_grids() {
    for (ne, skew, reference, worst) in [
        (4, 0.0, SQUARE, 0.1103),
        (4, 45.0, SKEW45, 0.1967),
        (6, 0.0, SQUARE, 0.0189),
        (6, 45.0, SKEW45, 0.0416),
    ] {
        let w = errors(ne, skew, &reference).into_iter().fold(f64::MIN, f64::max);
        assert!(
            (w - worst).abs() < 0.002,
            "{ne}x{ne} skew {skew}°: worst mode {:+.2} %, measured {:+.2} %",
            100.0 * w,
            100.0 * worst
        );
    }
}

/// Clamped square plate (a = 100, t = 1, a/t = 100) under uniform pressure q, consistent
/// nodal loads (shell9's own pressure loads): centre deflection against the thin-plate value
/// w = 0.0012653 q a⁴/D (S. Timoshenko, S. Woinowsky-Krieger, Theory of Plates and Shells, 2nd
/// ed., 1959, §44, Table 35: 0.00126; the series to five digits). The Reissner–Mindlin plate at
/// a/t = 100 is about 0.2 % more flexible (the shear part scales with (t/a)²: 0.00150 at
/// t/a = 0.1). Measured: 4×4 0.0012787 (+1.06 %), 8×8 0.0012685 (+0.26 %), 16×16 0.0012680
/// (+0.21 %): converged to the Mindlin value, no locking at a/t = 100.
#[test]
fn clamped_square_plate_under_pressure() {
    let (t, mat, q) = (1.0, Material::AL7075, 1e-3);
    let d = mat.e * t * t * t / (12.0 * (1.0 - mat.nu * mat.nu));
    for (ne, tol) in [(4, 0.012), (8, 0.003), (16, 0.003)] {
        let mut m = Model::new();
        let id = grid9(&mut m, ne, [A, A], 0.0, t, mat, |x| x);
        let n = 2 * ne;
        for j in 0..=n {
            for i in 0..=n {
                if i == 0 || j == 0 || i == n || j == n {
                    m.supports.push(Support::clamp(id(i, j)));
                }
            }
        }
        let mut f = vec![[0.0; 6]; m.nodes.len()];
        for e in &m.elements {
            let Element::Shell9(s) = e else { unreachable!() };
            let x = s.nodes.map(|k| m.nodes[k]);
            let fe = fem::shell9::shell9_pressure_loads(&x, -q).unwrap();
            for (k, &node) in s.nodes.iter().enumerate() {
                for c in 0..6 {
                    f[node][c] += fe[k][c];
                }
            }
        }
        let lc = f
            .iter()
            .enumerate()
            .fold(LoadCase::new("q"), |lc, (k, v)| lc.force(k, *v));
        m.load_cases.push(lc);
        let r = fem::solve_static(&m).unwrap();
        let c = -r.load_cases[0].displacements[id(ne, ne)][2] / (q * A.powi(4) / d);
        let err = c / 0.0012653 - 1.0;
        eprintln!(
            "shell9 clamped plate {ne}x{ne} under pressure: w = {c:.8} q a^4/D ({:+.2} %)",
            100.0 * err
        );
        assert!(err.abs() < tol, "{ne}x{ne}: w = {c} q a^4/D ({:+.2} %)", 100.0 * err);
    }
}
