//! Shell drilling rotations must not create modes of their own.
//!
//! A plate that is free in its own plane has, below its first membrane (in-plane) mode, exactly
//! the bending spectrum of the same plate with the in-plane DOFs (u, v, θz) held: plate bending
//! and membrane action are uncoupled for a flat plate, and the drilling rotation θz is not a
//! physical degree of freedom of a Reissner–Mindlin shell (it only couples to the in-plane
//! rotation ½(∂v/∂x − ∂u/∂y) of the membrane). The test plate is the clamped 45° rhombic plate of
//! side 10 m (steel) at t/a = 0.1 and 0.05: an earlier drilling formulation, with rotary inertia
//! ρt³/12 on θz against a 10⁻³·G penalty, put mesh-independent spurious θz "modes" at 54–72 Hz,
//! below the first bending mode (133 Hz).

use flexfem::fem::modal::{solve_modal, ModalOptions, ModalResults};
use flexfem::fem::{Dof, Model, Support};

mod common;

use common::materials::STEEL;

/// Clamped 45° rhombus of side `a` (mm), `n`×`n` shells of thickness `t`; with `in_plane_held`
/// every node also has u, v, θz fixed.
fn rhombus(n: usize, a: f64, t: f64, in_plane_held: bool) -> Model {
    let (c, s) = (std::f64::consts::FRAC_1_SQRT_2, std::f64::consts::FRAC_1_SQRT_2);
    let mut m = Model::new();
    let id = common::meshes::skew_grid(&mut m, n, a, (c, s), t, STEEL);
    common::meshes::each_node(n, |i, j, edge| {
        if edge {
            m.supports.push(Support::clamp(id(i, j)));
        } else if in_plane_held {
            m.supports.push(Support::dofs(id(i, j), &[Dof::Ux, Dof::Uy, Dof::Rz]));
        }
    });
    m
}

/// Share of a mode's (lumped, per-node) kinetic energy in the in-plane translations u, v and
/// in the drilling rotation θz.
fn in_plane_and_drilling_share(r: &ModalResults, k: usize, t: f64) -> (f64, f64) {
    let rot = t * t / 12.0;
    let (mut inplane, mut drill, mut total) = (0.0, 0.0, 0.0);
    for d in &r.modes[k].shape {
        let e = [
            d[0] * d[0],
            d[1] * d[1],
            d[2] * d[2],
            rot * d[3] * d[3],
            rot * d[4] * d[4],
            rot * d[5] * d[5],
        ];
        inplane += e[0] + e[1];
        drill += e[5];
        total += e.iter().sum::<f64>();
    }
    (inplane / total, drill / total)
}

fn check(t: f64) {
    let (n, a, nev) = (12, 10_000.0, 8);
    let free = solve_modal(&rhombus(n, a, t, false), &ModalOptions::new(nev)).unwrap();
    let held = solve_modal(&rhombus(n, a, t, true), &ModalOptions::new(nev)).unwrap();
    let mut matched = 0;
    for k in 0..nev {
        let (inplane, drill) = in_plane_and_drilling_share(&free, k, t);
        let f = free.modes[k].frequency_hz;
        eprintln!(
            "t/a = {}: mode {}: {f:.2} Hz (in-plane {inplane:.3}, drilling {drill:.3}); held bending {:.2} Hz",
            t / a,
            k + 1,
            held.modes[k].frequency_hz
        );
        // No mode dominated by the drilling rotation, anywhere in the computed band.
        assert!(drill < 0.5, "mode {} at {f} Hz is a drilling mode", k + 1);
        if inplane > 0.5 {
            break; // the first membrane mode: the bending spectrum below it is compared
        }
        let fb = held.modes[matched].frequency_hz;
        assert!(
            (f / fb - 1.0).abs() < 0.01,
            "mode {}: {f} Hz vs bending {fb} Hz with in-plane DOFs held",
            k + 1
        );
        matched += 1;
    }
    // The band below the first membrane mode holds several bending modes (at least the first
    // four); a spurious mode anywhere there would have shifted the comparison.
    assert!(
        matched >= 4,
        "only {matched} bending modes below the first membrane mode"
    );
}

#[test]
fn thick_rhombic_plate_has_only_the_bending_spectrum_below_membrane_modes() {
    check(1_000.0); // t/a = 0.1
}

#[test]
fn moderately_thick_rhombic_plate_has_only_the_bending_spectrum_below_membrane_modes() {
    check(500.0); // t/a = 0.05
}

/// The spectrum check: a mode whose strain energy rests on the drilling penalty is reported.
/// A rotary inertia about the plate normal at the centre of a clamped plate turns that node
/// about the normal, which only the (artificial) drilling stiffness resists: its mode must be
/// flagged; the plate's own bending modes must not.
#[test]
fn drilling_dominated_modes_are_flagged() {
    use flexfem::analysis::modal::drilling_warnings;
    use flexfem::fem::PointMass;
    let t = 500.0;
    let plain = rhombus(8, 10_000.0, t, false);
    let r = solve_modal(&plain, &ModalOptions::new(6)).unwrap();
    assert!(
        drilling_warnings(&plain, &r).is_empty(),
        "{:?}",
        drilling_warnings(&plain, &r)
    );

    let mut spun = rhombus(8, 10_000.0, t, false);
    let centre = 4 * 9 + 4;
    // About the normal: 1 % of the plate's polar rotary inertia, no translational mass.
    let plate_mass = STEEL.density * t * 10_000.0 * 10_000.0 * std::f64::consts::FRAC_1_SQRT_2;
    spun.masses.push(PointMass {
        node: centre,
        mass: 0.0,
        inertia: [0.0, 0.0, 0.01 * plate_mass * 10_000.0f64.powi(2) / 6.0],
    });
    let r = solve_modal(&spun, &ModalOptions::new(6)).unwrap();
    let w = drilling_warnings(&spun, &r);
    eprintln!("{w:?}");
    assert_eq!(w.len(), 1, "one drilling-dominated mode expected: {w:?}");
    assert!(w[0].contains("drilling rotation"), "{w:?}");
}
