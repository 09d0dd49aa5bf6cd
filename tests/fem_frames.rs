//! Node frames (skew supports) and ties (exact joint releases).

use flexfem::fem::{self, Beam, Dof, LoadCase, Model, Section, Support, Tie};
use flexfem::material::Material;

const E: f64 = 72_000.0;

fn mat() -> Material {
    Material {
        e: E,
        nu: 0.3,
        ..Material::AL7075
    }
}

/// A cantilever along the direction `dir` (unit), length 100, 10×10, tip force along `f`.
fn inclined_cantilever(dir: [f64; 3], up: [f64; 3]) -> Model {
    let mut m = Model::new();
    let a = m.add_node([0.0, 0.0, 0.0]);
    let b = m.add_node([100.0 * dir[0], 100.0 * dir[1], 100.0 * dir[2]]);
    m.add_beam(Beam::new(a, b, Section::Rect { w: 10.0, h: 10.0 }, mat(), up).euler_bernoulli());
    m.supports.push(Support::clamp(a));
    m
}

#[test]
fn skew_roller_gives_the_textbook_propped_cantilever() {
    // A cantilever along x with a roller at the tip that only stops motion along local z of a
    // frame rotated 30° about x: under a tip force along that same local z the roller takes it
    // all (tip displacement along the roller normal is exactly zero), and a force normal to it
    // (local y) bends the beam freely: δ = P L³/(3 E I_z) (Euler–Bernoulli cantilever).
    let c = 30f64.to_radians().cos();
    let s = 30f64.to_radians().sin();
    let mut m = inclined_cantilever([1.0, 0.0, 0.0], [0.0, 0.0, 1.0]);
    m.set_frame(1, [[1.0, 0.0, 0.0], [0.0, c, s], [0.0, -s, c]]);
    m.supports.push(Support::dofs(1, &[Dof::Uz]));
    m.load_cases
        .push(LoadCase::new("along_y_local").force(1, [0.0, 10.0 * c, 10.0 * s, 0.0, 0.0, 0.0]));
    m.load_cases
        .push(LoadCase::new("along_z_local").force(1, [0.0, -10.0 * s, 10.0 * c, 0.0, 0.0, 0.0]));
    let r = fem::solve_static(&m).unwrap();
    let i = 10.0f64.powi(4) / 12.0;
    let free = 10.0 * 100f64.powi(3) / (3.0 * E * i);
    let u = r.load_cases[0].displacements[1];
    // displacement along local y (global components)
    let along_y = u[1] * c + u[2] * s;
    let along_z = -u[1] * s + u[2] * c;
    assert!((along_y / free - 1.0).abs() < 1e-9, "{along_y} vs {free}");
    assert!(along_z.abs() < 1e-12 * free);
    let u = r.load_cases[1].displacements[1];
    assert!((-u[1] * s + u[2] * c).abs() < 1e-12 * free);
    // Reactions are reported in global axes and balance the load.
    let res = r.load_cases[1].statics.residual();
    assert!(res.iter().all(|v| v.abs() < 1e-8), "{res:?}");
    let tip = r.load_cases[1].reactions.iter().find(|(n, _)| *n == 1).unwrap().1;
    // The roller carries the whole load along its normal (the tip can't move that way) minus
    // what the clamp takes: for a propped cantilever under a tip load at the prop the prop
    // takes all of it.
    assert!(((tip[1] * (-s) + tip[2] * c) + 10.0).abs() < 1e-9, "{tip:?}");
}

#[test]
fn prescribed_displacement_in_a_node_frame() {
    // A slider on an inclined guide: the tip of a cantilever along x gets a frame whose x is
    // (1,1,0)/√2, the other five local DOFs fixed and local ux prescribed to δ: the tip moves
    // exactly δ·(1,1,0)/√2.
    let mut m = inclined_cantilever([1.0, 0.0, 0.0], [0.0, 0.0, 1.0]);
    let h = std::f64::consts::FRAC_1_SQRT_2;
    m.set_frame(1, [[h, h, 0.0], [-h, h, 0.0], [0.0, 0.0, 1.0]]);
    m.supports
        .push(Support::dofs(1, &[Dof::Uy, Dof::Uz, Dof::Rx, Dof::Ry, Dof::Rz]));
    m.load_cases.push(LoadCase::new("slide").displacement(1, Dof::Ux, 0.01));
    let r = fem::solve_static(&m).unwrap();
    let u = r.load_cases[0].displacements[1];
    assert!((u[0] - 0.01 * h).abs() < 1e-15 && (u[1] - 0.01 * h).abs() < 1e-15 && u[2].abs() < 1e-15);
    // The guide force along its direction does the work: ½ F δ = strain energy (Clapeyron).
    let (n, rr) = r.load_cases[0].reactions.iter().find(|(n, _)| *n == 1).unwrap();
    assert_eq!(*n, 1);
    let f_along = rr[0] * h + rr[1] * h;
    let energy: f64 = r.load_cases[0].elements.iter().map(|e| e.strain_energy).sum();
    assert!(
        (0.5 * f_along * 0.01 - energy).abs() < 1e-9 * energy,
        "{f_along} {energy}"
    );
}

/// Two 100 mm Euler–Bernoulli beams (10 × 10 mm) a–b1 and b2–c along x, b1 and b2 coincident
/// at x = 100 and not yet connected, clamped at a; returns the model and [a, b1, b2, c].
fn split_cantilever() -> (Model, [usize; 4]) {
    let mut m = Model::new();
    let a = m.add_node([0.0, 0.0, 0.0]);
    let b1 = m.add_node([100.0, 0.0, 0.0]);
    let b2 = m.add_node([100.0, 0.0, 0.0]);
    let c = m.add_node([200.0, 0.0, 0.0]);
    let sec = Section::Rect { w: 10.0, h: 10.0 };
    m.add_beam(Beam::new(a, b1, sec, mat(), [0.0, 0.0, 1.0]).euler_bernoulli());
    m.add_beam(Beam::new(b2, c, sec, mat(), [0.0, 0.0, 1.0]).euler_bernoulli());
    m.supports.push(Support::clamp(a));
    (m, [a, b1, b2, c])
}

#[test]
fn tie_of_all_dofs_equals_a_shared_node() {
    // Two beams meeting at coincident nodes tied in all six DOFs behave as one continuous
    // cantilever: tip deflection P L³/(3EI) with L = 200 (Euler–Bernoulli).
    let (mut m, [_, b1, b2, c]) = split_cantilever();
    m.ties.push(Tie {
        a: b1,
        b: b2,
        dofs: [true; 6],
    });
    m.load_cases
        .push(LoadCase::new("tip").force(c, [0.0, 0.0, -10.0, 0.0, 0.0, 0.0]));
    let r = fem::solve_static(&m).unwrap();
    let i = 10.0f64.powi(4) / 12.0;
    let expect = -10.0 * 200f64.powi(3) / (3.0 * E * i);
    assert!((r.load_cases[0].displacements[c][2] / expect - 1.0).abs() < 1e-9);
    assert_eq!(r.load_cases[0].displacements[b1], r.load_cases[0].displacements[b2]);
}

#[test]
fn hinge_tie_releases_one_rotation() {
    // A beam clamped at both ends with an exact hinge (rotation about y released) at mid-span,
    // loaded at the hinge: two equal cantilevers in parallel, δ = P L³/(3EI)/2 with L = 100, and
    // the two sides rotate by ∓(P/2) L²/(2EI) (Euler–Bernoulli).
    let (mut m, [_, h1, h2, c]) = split_cantilever();
    m.supports.push(Support::clamp(c));
    m.ties.push(Tie {
        a: h1,
        b: h2,
        dofs: [true, true, true, true, false, true],
    });
    m.load_cases
        .push(LoadCase::new("mid").force(h1, [0.0, 0.0, -10.0, 0.0, 0.0, 0.0]));
    let r = fem::solve_static(&m).unwrap();
    let i = 10.0f64.powi(4) / 12.0;
    let expect = -10.0 * 100f64.powi(3) / (3.0 * E * i) / 2.0;
    let u = &r.load_cases[0].displacements;
    assert!((u[h1][2] / expect - 1.0).abs() < 1e-9, "{} vs {expect}", u[h1][2]);
    // the two sides of the hinge rotate in opposite directions by P L²/(2EI)/2
    let rot = 10.0 / 2.0 * 100f64.powi(2) / (2.0 * E * i);
    assert!((u[h1][4] - rot).abs() < 1e-9 * rot && (u[h2][4] + rot).abs() < 1e-9 * rot);
}

#[test]
fn bad_frames_and_ties_are_refused() {
    let mut m = inclined_cantilever([1.0, 0.0, 0.0], [0.0, 0.0, 1.0]);
    m.set_frame(1, [[1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, -1.0]]);
    m.load_cases
        .push(LoadCase::new("x").force(1, [1.0, 0.0, 0.0, 0.0, 0.0, 0.0]));
    let e = fem::solve_static(&m).unwrap_err().to_string();
    assert!(e.contains("right-handed"), "{e}");
    let mut m = inclined_cantilever([1.0, 0.0, 0.0], [0.0, 0.0, 1.0]);
    let extra = m.add_node([50.0, 0.0, 0.0]);
    m.ties.push(Tie {
        a: 1,
        b: extra,
        dofs: [true; 6],
    });
    m.load_cases
        .push(LoadCase::new("x").force(1, [1.0, 0.0, 0.0, 0.0, 0.0, 0.0]));
    let e = fem::solve_static(&m).unwrap_err().to_string();
    assert!(e.contains("coincident"), "{e}");
}
