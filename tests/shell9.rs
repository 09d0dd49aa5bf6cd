//! The nine-node flat shell (`shell9`: MITC9 plate, biquadratic membrane, consistent mass)
//! against closed forms and published plate values: coarse-mesh frequencies of clamped square
//! and 45° skew plates, the clamped plate under pressure, constant-strain and constant-moment
//! patches on a distorted mesh, a leaf's root stress, and the refusals of curved and folded
//! geometry.

use flexfem::fem::modal::{solve_modal, ModalOptions};
use flexfem::fem::{self, Element, LoadCase, Model, Shell9, Support};
use flexfem::material::Material;

mod common;

const A: f64 = 100.0;

/// Clamped square plate, thin-plate theory: A. W. Leissa, Vibration of Plates, NASA SP-160
/// (1969), Table 4.23 (the reference of `tests/shell_coarse_mesh.rs`).
const SQUARE: [f64; 6] = [35.992, 73.413, 73.413, 108.27, 131.64, 132.24];
/// Clamped 45° rhombic plate: the converged reference of `tests/shell_coarse_mesh.rs`
/// (Richardson extrapolation of the four-node shell from 32×32 and 64×64, a discretization
/// independent of this element).
const SKEW45: [f64; 6] = [65.642, 106.489, 148.300, 157.226, 196.743, 229.464];

/// The clamped-plate family of these tests: the skewed square of side A (node (i, j) of its
/// (2ne+1)² grid at u = A·i/2ne, v = A·j/2ne, x = u + v·sin φ, y = v·cos φ; φ = 0: square) on
/// `ne`×`ne` nine-node shells, each boundary node held by `edge(node)`. Returns the model and the
/// node id function of the grid.
fn plate9(
    ne: usize,
    skew_deg: f64,
    t: f64,
    mat: Material,
    edge: impl Fn(usize) -> Support,
) -> (Model, impl Fn(usize, usize) -> usize) {
    let n = 2 * ne;
    let (sn, cs) = (skew_deg.to_radians().sin(), skew_deg.to_radians().cos());
    let mut m = Model::new();
    common::meshes::each_node(n, |i, j, _| {
        let (u, v) = (A * i as f64 / n as f64, A * j as f64 / n as f64);
        m.add_node([u + v * sn, v * cs, 0.0]);
    });
    let id = move |i: usize, j: usize| j * (n + 1) + i;
    add_elements9(&mut m, (ne, ne), &id, t, mat);
    common::meshes::each_node(n, |i, j, on_edge| {
        if on_edge {
            m.supports.push(edge(id(i, j)));
        }
    });
    (m, id)
}

/// Adds the `nx`×`ny` nine-node shells of a (2nx+1)×(2ny+1) node grid whose node (i, j) is
/// `id(i, j)`: corners around each element, then its edge midpoints, then its centre.
fn add_elements9(m: &mut Model, (nx, ny): (usize, usize), id: &impl Fn(usize, usize) -> usize, t: f64, mat: Material) {
    for nodes in common::meshes::nine_node_cells(nx, ny, id) {
        m.add_element(Element::Shell9(Shell9 {
            nodes,
            t,
            material: mat,
        }));
    }
}

/// λ = ωa²√(ρt/D) of modes 1–6 of the clamped plate, `ne`×`ne` nine-node elements, a = 100,
/// t = 0.1 (a/t = 1000: thin-plate theory), Al 7075.
fn clamped_plate(ne: usize, skew_deg: f64) -> Vec<f64> {
    clamped_plate_solved(ne, skew_deg).0
}

/// [`clamped_plate`] with the model and the modal results.
fn clamped_plate_solved(ne: usize, skew_deg: f64) -> (Vec<f64>, Model, flexfem::fem::modal::ModalResults) {
    let (t, mat) = (0.1, Material::AL7075);
    let (m, _) = plate9(ne, skew_deg, t, mat, Support::clamp);
    let r = solve_modal(&m, &ModalOptions::new(6)).unwrap();
    let d = mat.e * t.powi(3) / (12.0 * (1.0 - mat.nu * mat.nu));
    let lam = r
        .modes
        .iter()
        .map(|md| 2.0 * std::f64::consts::PI * md.frequency_hz * A * A * (mat.density * t / d).sqrt())
        .collect();
    (lam, m, r)
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
fn clamped_plates_at_8x8_nine_node_elements_well_within_5_percent() {
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
        let c = pressure_deflection(ne, t, mat, q) / (q * A.powi(4) / d);
        let err = c / 0.0012653 - 1.0;
        eprintln!(
            "shell9 clamped plate {ne}x{ne} under pressure: w = {c:.8} q a^4/D ({:+.2} %)",
            100.0 * err
        );
        assert!(err.abs() < tol, "{ne}x{ne}: w = {c} q a^4/D ({:+.2} %)", 100.0 * err);
    }
}

/// Centre deflection (mm, downward positive) of the clamped square plate (side A, thickness
/// `t`) under the pressure `q` (MPa) on `ne`×`ne` nine-node shells, shell9's own consistent
/// pressure loads.
fn pressure_deflection(ne: usize, t: f64, mat: Material, q: f64) -> f64 {
    let (mut m, id) = plate9(ne, 0.0, t, mat, Support::clamp);
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
    -r.load_cases[0].displacements[id(ne, ne)][2]
}

/// A 5×5-node patch of 2×2 nine-node elements on [0, 10]² whose inner corner sits at
/// (5.7, 4.4): corners of the elements from that 3×3 grid, edge midpoints and centres where the
/// bilinear map of each element puts them (straight edges), so every quadratic field of x and y
/// lies in the element space. Returns the model and the boundary flags of its nodes.
fn distorted_patch(t: f64, mat: Material) -> (Model, Vec<bool>) {
    let c = |i: usize, j: usize| -> [f64; 2] {
        if (i, j) == (1, 1) {
            [5.7, 4.4]
        } else {
            [5.0 * i as f64, 5.0 * j as f64]
        }
    };
    let mut m = Model::new();
    let mut boundary = Vec::new();
    for j in 0..5 {
        for i in 0..5 {
            let (i0, j0) = (i / 2, j / 2);
            let (i1, j1) = (i0 + i % 2, j0 + j % 2);
            let p = [c(i0, j0), c(i1, j0), c(i0, j1), c(i1, j1)];
            let x = 0.25 * (p[0][0] + p[1][0] + p[2][0] + p[3][0]);
            let y = 0.25 * (p[0][1] + p[1][1] + p[2][1] + p[3][1]);
            m.add_node([x, y, 0.0]);
            boundary.push(i == 0 || j == 0 || i == 4 || j == 4);
        }
    }
    let id = |i: usize, j: usize| j * 5 + i;
    add_elements9(&mut m, (2, 2), &id, t, mat);
    (m, boundary)
}

/// Patch tests on the distorted patch: a linear membrane field (with the drilling rotation of
/// the field on the boundary) and a quadratic deflection (constant curvature, zero transverse
/// shear) prescribed on the boundary nodes are reproduced at the inner nodes to round-off, and
/// every element's membrane forces and moments are the constant C·t·ε and D·κ.
#[test]
fn patch_tests_on_a_distorted_mesh() {
    use flexfem::fem::Dof;
    let (t, mat) = (0.5, Material::AL7075);
    let (ex, ey, gxy) = (1e-3, 0.8e-3, 0.2e-3);
    // u = ex·x + gxy/2·y − ω·y, v = gxy/2·x + ey·y + ω·x (a rigid rotation ω added), θz = ω.
    let omega = 1e-3;
    let field_m = |p: [f64; 3]| {
        let u = ex * p[0] + (0.5 * gxy - omega) * p[1];
        let v = (0.5 * gxy + omega) * p[0] + ey * p[1];
        [u, v, omega]
    };
    // w = ½(a x² + b y² + c x y): θx = ∂w/∂y, θy = −∂w/∂x; κ = (−a, −b, −c).
    let (a, b, cc) = (2e-4, -1e-4, 3e-4);
    let field_b = |p: [f64; 3]| {
        let (x, y) = (p[0], p[1]);
        [
            0.5 * (a * x * x + b * y * y + cc * x * y),
            b * y + 0.5 * cc * x,
            -(a * x + 0.5 * cc * y),
        ]
    };
    let (mut m, boundary) = distorted_patch(t, mat);
    let mut lc = LoadCase::new("patch");
    for (k, &on) in boundary.iter().enumerate() {
        let (fm, fb) = (field_m(m.nodes[k]), field_b(m.nodes[k]));
        if on {
            m.supports.push(Support::clamp(k));
            // zip-checked: three DOFs, three field values.
            for (d, v) in [Dof::Ux, Dof::Uy, Dof::Rz].into_iter().zip(fm) {
                lc = lc.displacement(k, d, v);
            }
            // zip-checked: three DOFs, three field values.
            for (d, v) in [Dof::Uz, Dof::Rx, Dof::Ry].into_iter().zip(fb) {
                lc = lc.displacement(k, d, v);
            }
        }
    }
    m.load_cases.push(lc);
    let r = fem::solve_static(&m).unwrap();
    let u = &r.load_cases[0].displacements;
    let mut worst: f64 = 0.0;
    for (k, &on) in boundary.iter().enumerate() {
        if on {
            continue;
        }
        let (fm, fb) = (field_m(m.nodes[k]), field_b(m.nodes[k]));
        let got = [u[k][0], u[k][1], u[k][5], u[k][2], u[k][3], u[k][4]];
        let want: Vec<f64> = fm.iter().chain(&fb).copied().collect();
        assert_eq!(got.len(), want.len());
        for (got, want) in got.iter().zip(&want) {
            worst = worst.max((got - want).abs() / 1e-2);
        }
    }
    assert!(
        worst < 1e-9,
        "inner nodes off the patch field by {worst:e} (relative to 0.01)"
    );
    let c = flexfem::fem::shell::plane_stress(mat.e, mat.nu);
    let n_want = c * nalgebra::Vector3::new(ex, ey, gxy) * t;
    let m_want = c * nalgebra::Vector3::new(-a, -b, -cc) * (t * t * t / 12.0);
    // Element axes: x along g₁ = ½(x₁ + x₂ − x₀ − x₃) of the corners, y = z × x.
    let local = |v: nalgebra::Vector3<f64>, ie: usize| {
        let Element::Shell9(s) = &m.elements[ie] else {
            unreachable!()
        };
        let p = |k: usize| m.nodes[s.nodes[k]];
        let g = [
            p(1)[0] + p(2)[0] - p(0)[0] - p(3)[0],
            p(1)[1] + p(2)[1] - p(0)[1] - p(3)[1],
        ];
        let (c, sn) = (g[0] / g[0].hypot(g[1]), g[1] / g[0].hypot(g[1]));
        let t = nalgebra::Matrix2::new(v[0], v[2], v[2], v[1]);
        let r = nalgebra::Matrix2::new(c, sn, -sn, c);
        let tl = r * t * r.transpose();
        nalgebra::Vector3::new(tl[(0, 0)], tl[(1, 1)], tl[(0, 1)])
    };
    for (ie, er) in r.load_cases[0].elements.iter().enumerate() {
        let s = er.shell.expect("shell stresses");
        let (n_want, m_want) = (local(n_want, ie), local(m_want, ie));
        for k in 0..3 {
            assert!(
                (s.n[k] - n_want[k]).abs() < 1e-8 * n_want.norm(),
                "element {ie} n[{k}] = {} vs {}",
                s.n[k],
                n_want[k]
            );
            assert!(
                (s.m[k] - m_want[k]).abs() < 1e-8 * m_want.norm(),
                "element {ie} m[{k}] = {} vs {}",
                s.m[k],
                m_want[k]
            );
        }
    }
}

/// A flexure leaf as nine-node shells: steel, 20 × 4 × 0.5 mm, clamped at x = 0, moment M about
/// y at the free end (edge moment M/b, consistent weights 1/6, 4/6, 1/6 per element edge).
/// Beam theory: σ = 6M/(bt²) at the root. The top-surface σxx recovered at the root nodes
/// (3×3 Gauss values extrapolated, averaged over the elements at the node), 8 × 2 elements,
/// averaged over the width (Simpson): within 3 % of the beam value. Measured: +1.10 %; at
/// mid-width +14.70 % (the clamped root holds the leaf's anticlastic curvature, so the root
/// moment peaks at mid-width: plate behaviour that beam theory averages out, as in
/// `tests/shell_spr.rs`).
#[test]
fn leaf_root_stress_against_the_beam_value() {
    let (l, b, t, mt) = (20.0, 4.0, 0.5, 10.0);
    let mat = Material::STEEL;
    let (nx, ny) = (8, 2);
    let mut m = Model::new();
    let (gx, gy) = (2 * nx, 2 * ny);
    for j in 0..=gy {
        for i in 0..=gx {
            m.add_node([l * i as f64 / gx as f64, b * j as f64 / gy as f64, 0.0]);
        }
    }
    let id = |i: usize, j: usize| j * (gx + 1) + i;
    add_elements9(&mut m, (nx, ny), &id, t, mat);
    for j in 0..=gy {
        m.supports.push(Support::clamp(id(0, j)));
    }
    let h = b / ny as f64;
    let mut lc = LoadCase::new("M");
    for j in 0..=gy {
        let w = if j % 2 == 1 {
            4.0 / 6.0
        } else if j == 0 || j == gy {
            1.0 / 6.0
        } else {
            2.0 / 6.0
        };
        lc = lc.force(id(gx, j), [0.0, 0.0, 0.0, 0.0, -mt / b * h * w, 0.0]);
    }
    m.load_cases.push(lc);
    let r = fem::solve_static(&m).unwrap();
    let u: Vec<[f64; 6]> = r.load_cases[0].displacements.clone();
    let field = flexfem::fem::shell_recovery::shell_field(&m, &u).unwrap();
    let beam = 6.0 * mt / (b * t * t);
    let sxx = |j: usize| field.top[id(0, j)].unwrap()[0];
    // Width average by Simpson's rule on each element edge (weights 1, 4, 1 over 6).
    let mean = (0..=gy)
        .map(|j| {
            let w = if j % 2 == 1 {
                4.0
            } else if j == 0 || j == gy {
                1.0
            } else {
                2.0
            };
            w * sxx(j)
        })
        .sum::<f64>()
        / (6.0 * ny as f64);
    let (err_mean, err_mid) = (mean.abs() / beam - 1.0, sxx(gy / 2).abs() / beam - 1.0);
    eprintln!(
        "shell9 leaf {nx}x{ny} root σxx (top): width average {mean:.4} MPa ({:+.2} %), mid-width {:.4} MPa ({:+.2} %); beam 6M/(bt²) = {beam:.4} MPa",
        100.0 * err_mean,
        sxx(gy / 2),
        100.0 * err_mid
    );
    assert!(
        err_mean.abs() < 0.03,
        "root stress width average {mean} vs {beam} ({:+.2} %)",
        100.0 * err_mean
    );
}

/// Curved geometry is refused with the node, its offset and the limit: a nine-node element on a
/// cylinder of radius 50 over a 20 mm arc (its edge midpoints 1 mm off the corners' plane).
#[test]
fn curved_geometry_is_refused() {
    let mut m = Model::new();
    let r = 50.0;
    let pt = |s: f64, z: f64| {
        let a = s / r;
        [r * a.sin(), z, r * (1.0 - a.cos())]
    };
    for (s, z) in [
        (-10.0, 0.0),
        (10.0, 0.0),
        (10.0, 20.0),
        (-10.0, 20.0),
        (0.0, 0.0),
        (10.0, 10.0),
        (0.0, 20.0),
        (-10.0, 10.0),
        (0.0, 10.0),
    ] {
        m.add_node(pt(s, z));
    }
    m.add_element(Element::Shell9(Shell9 {
        nodes: std::array::from_fn(|k| k),
        t: 1.0,
        material: Material::STEEL,
    }));
    let e = m.validate().unwrap_err().to_string();
    assert!(e.contains("flat element") && e.contains("four-node shells"), "{e}");
}

/// Simply supported square plate (a = 100, t = 1, Al 7075; w, u, v held on the edges) on
/// `ne`×`ne` nine-node squares: its modes are standing waves sin(mπx/a)·sin(nπy/a), sums of
/// Bloch waves, so against Navier's thin-plate frequencies π²(m² + n²)/a²·√(D/ρt) (Timoshenko &
/// Woinowsky-Krieger 1959, §8; Leissa NASA SP-160 §4.1) the element's error is its Bloch ratio
/// at (a, b) = (mπh/a, nπh/a), h = a/ne (`square_mesh_frequency_ratio9`, computed from the
/// element's matrices), plus the Reissner–Mindlin plate's own shift (−(qt)²/24·(1 + 2/(κ(1 − ν)))
/// to first order: −0.04…−0.19 % for these modes). Measured at 4×4, (1,1) (1,2) (2,2) (1,3):
/// −0.014 / +0.762 / +0.818 / +4.434 % against Bloch + Mindlin +0.028 / +0.786 / +0.855 /
/// +4.457 %: within 0.05 %.
#[test]
fn simply_supported_plate_errors_are_the_bloch_ratio() {
    use flexfem::fem::shell9::square_mesh_frequency_ratio9;
    use flexfem::fem::Dof;
    let (t, mat, ne) = (1.0, Material::AL7075, 4);
    let (m, _) = plate9(ne, 0.0, t, mat, |node| {
        Support::dofs(node, &[Dof::Ux, Dof::Uy, Dof::Uz])
    });
    let r = solve_modal(&m, &ModalOptions::new(6)).unwrap();
    let d = mat.e * t.powi(3) / (12.0 * (1.0 - mat.nu * mat.nu));
    let navier = |mm: f64, nn: f64| {
        std::f64::consts::PI.powi(2) * (mm * mm + nn * nn) / (A * A) * (d / (mat.density * t)).sqrt()
    };
    let h = A / ne as f64;
    let kappa = 5.0 / 6.0;
    for (k, (mm, nn)) in [(1.0, 1.0), (1.0, 2.0), (2.0, 1.0), (2.0, 2.0), (1.0, 3.0), (3.0, 1.0)]
        .into_iter()
        .enumerate()
    {
        let omega = 2.0 * std::f64::consts::PI * r.modes[k].frequency_hz;
        let measured = omega / navier(mm, nn) - 1.0;
        let (a, b) = (mm * std::f64::consts::PI * h / A, nn * std::f64::consts::PI * h / A);
        let bloch = square_mesh_frequency_ratio9(a, b, mat.nu).unwrap() - 1.0;
        let q2 = (mm * mm + nn * nn) * (std::f64::consts::PI / A).powi(2);
        let mindlin = -q2 * t * t / 24.0 * (1.0 + 2.0 / (kappa * (1.0 - mat.nu)));
        eprintln!(
            "shell9 SS ({mm}, {nn}) {ne}x{ne}: measured {:+.3} %, Bloch {:+.3} %, Mindlin {:+.3} %",
            100.0 * measured,
            100.0 * bloch,
            100.0 * mindlin
        );
        assert!(
            (measured - bloch - mindlin).abs() < 5e-4,
            "({mm}, {nn}): measured {measured}, Bloch {bloch} + Mindlin {mindlin}"
        );
    }
}

/// The modal analysis's coarse-shell estimate for nine-node shells
/// (`shell_dispersion_estimates`, the element's Bloch ratio in the worse of a wave along a mesh
/// line and a diagonal, at the wave's qh): against the measured errors of the clamped square and
/// 45° skew plates at 4×4, 6×6 and 8×8 (skewed elements judged as squares of their longest
/// side). It is at or above every one but two, the square's modes 5–6 at 4×4 (1.04 elements per
/// half-wave), where it reads 10.90 / 10.97 % against 11.01 / 11.03 % (the clamped plate's modes
/// are not plane waves): held to within 1 % of the measured error there, above it elsewhere.
/// Flagged (estimate above 2 %): square 4×4 modes 2–6, skew 4×4 all six, skew 6×6 modes 3–6, square 6×6
/// modes 5–6 (2.38 / 2.40 % against 1.87 / 1.89 %), skew 8×8 mode 6 (2.27 % against 1.25 %);
/// none of the square's at 8×8. Below one element per half-wave (skew 4×4 modes 5–6) the wave
/// aliases on the mesh and the estimate (97 %, 99 %) only says that the mesh cannot carry it.
#[test]
fn coarse_shell_estimate_of_nine_node_shells_bounds_the_measured_error() {
    use flexfem::analysis::modal::{coarse_shell_warnings, shell_dispersion_estimates};
    for (ne, skew, reference) in [
        (4, 0.0, &SQUARE),
        (4, 45.0, &SKEW45),
        (6, 0.0, &SQUARE),
        (6, 45.0, &SKEW45),
        (8, 0.0, &SQUARE),
        (8, 45.0, &SKEW45),
    ] {
        let (lam, model, raw) = clamped_plate_solved(ne, skew);
        let est = shell_dispersion_estimates(&model, &raw);
        assert_eq!((lam.len(), est.len()), (6, 6));
        let mut flagged = 0;
        for k in 0..6 {
            let (error, per_half_wave) = est[k].expect("a bending mode of an all-shell model");
            let measured = (lam[k] / reference[k] - 1.0).abs();
            eprintln!(
                "shell9 {ne}x{ne} skew {skew}° mode {}: measured {:.2} %, estimate {:.2} %, {per_half_wave:.2} elements per half-wave",
                k + 1,
                100.0 * measured,
                100.0 * error
            );
            assert!(
                measured <= 1.01 * error,
                "{ne}x{ne} skew {skew}° mode {}: measured {measured} above {error}",
                k + 1
            );
            flagged += usize::from(error > 0.02);
        }
        let warnings = coarse_shell_warnings(&model, &raw);
        assert_eq!(warnings.len(), usize::from(flagged > 0));
        if let Some(w) = warnings.first() {
            assert!(w.contains("nine-node shell's frequencies can read high"), "{w}");
        }
        let expected = match (ne, skew == 0.0) {
            (4, true) => 5,
            (4, false) => 6,
            (6, false) => 4,
            (6, true) => 2,
            (8, true) => 0,
            _ => 1,
        };
        assert_eq!(flagged, expected, "{ne}x{ne} skew {skew}°: modes flagged");
    }
}

/// Against an independent MITC9 plate written in Python from Bucalem & Bathe (IJNME 36 (1993)
/// 3729) and Bathe's Finite Element Procedures (2014, §5.4) by someone who did not read this
/// element (`tools/mitc9_reference/`: its own rotation convention, assembly and eigensolver):
/// λ of modes 1–6 of the clamped square and 45° rhombic plates (t = 0.1) at 4×4, 6×6, 8×8, and
/// the clamped plate's centre deflection under pressure (t = 1) at 4×4, 8×8, 16×16, printed there
/// to six digits. Measured: every λ within 3.5e-6 relative, every deflection within 2.5e-6 (the
/// printed digits).
#[test]
fn agrees_with_an_independent_mitc9() {
    const SQUARE_REF: [(usize, [f64; 6]); 3] = [
        (4, [36.0921, 75.0684, 75.0684, 110.936, 146.130, 146.821]),
        (6, [36.0051, 73.7173, 73.7173, 108.719, 134.105, 134.741]),
        (8, [35.9911, 73.4954, 73.4954, 108.370, 132.386, 133.015]),
    ];
    const SKEW_REF: [(usize, [f64; 6]); 3] = [
        (4, [66.2590, 111.628, 163.078, 164.191, 235.437, 269.873]),
        (6, [65.7811, 107.583, 151.580, 158.802, 204.921, 237.917]),
        (8, [65.6892, 106.850, 149.402, 157.765, 199.507, 232.335]),
    ];
    let mut worst: f64 = 0.0;
    for (skew, table) in [(0.0, &SQUARE_REF), (45.0, &SKEW_REF)] {
        for (ne, reference) in table.iter() {
            let lam = clamped_plate(*ne, skew);
            assert_eq!(lam.len(), reference.len());
            for (l, r) in lam.iter().zip(reference) {
                worst = worst.max((l / r - 1.0).abs());
            }
        }
    }
    eprintln!("shell9 against the independent MITC9: λ within {worst:.2e}");
    assert!(worst < 1e-5, "λ differs by {worst:e}");
    let (t, mat, q) = (1.0, Material::AL7075, 1e-3);
    let d = mat.e * t * t * t / (12.0 * (1.0 - mat.nu * mat.nu));
    for (ne, reference) in [(4, 0.00127872), (8, 0.00126853), (16, 0.00126799)] {
        let c = pressure_deflection(ne, t, mat, q) / (q * A.powi(4) / d);
        let err = (c / reference - 1.0).abs();
        eprintln!("shell9 against the independent MITC9: {ne}x{ne} w = {c:.8} ({err:.2e})");
        assert!(err < 1e-5, "{ne}x{ne}: w = {c} against {reference}");
    }
}

/// The Bloch ratio at small qh: solved, the wave's eigenvalue is 10⁻¹⁵ of the shear modes' at
/// qh = 0.05 and double precision gave ω_h/ω − 1 = −3.0 % along a mesh line and +1.8 % along a
/// diagonal (−0.16 % / +0.10 % at qh = 0.1), so the coarse-shell warning told a plate of 59
/// elements per half-wave it could read 2.8 % high. Below qh = 1 the error is now the element's
/// leading order, (qh)⁴ times its value at qh = 1. Checked: that value's coefficient against the
/// solved one at qh = 1.5 (1.97 against 1.88 · 10⁻³ along a line, 4.33 against 4.32 · 10⁻⁴ along a
/// diagonal: within 5 %), and at qh = 0.05, 0.1 the errors below 10⁻⁶ (1.2e-8 / 2.0e-7 along a line).
#[test]
fn bloch_ratio_at_long_waves_is_its_quartic_law() {
    let b = fem::shell9::Shell9Bloch::new(0.33).unwrap();
    let d = std::f64::consts::FRAC_1_SQRT_2;
    for (name, dir) in [("along a mesh line", (1.0, 0.0)), ("along a diagonal", (d, d))] {
        let coef = |qh: f64| (b.ratio(dir.0 * qh, dir.1 * qh).unwrap() - 1.0) / qh.powi(4);
        let (c1, c15) = (coef(1.0), coef(1.5));
        eprintln!("{name}: (ω_h/ω − 1)/(qh)⁴ = {c1:.4e} at qh = 1, {c15:.4e} at 1.5");
        assert!(c1 > 0.0 && (c15 / c1 - 1.0).abs() < 0.05, "{name}: {c1} vs {c15}");
        for qh in [0.05, 0.1] {
            let e = b.ratio(dir.0 * qh, dir.1 * qh).unwrap() - 1.0;
            assert!(e.abs() < 1e-6, "{name} qh {qh}: {e}");
        }
    }
}
