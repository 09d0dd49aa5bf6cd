//! Shear-deformable (Timoshenko) beam mass: bending frequencies of a simply supported round bar
//! against Timoshenko's closed form, convergence under refinement, and the Euler–Bernoulli mass
//! unchanged when shear is off.
//!
//! Closed form (S. P. Timoshenko, "On the correction for shear of the differential equation for
//! transverse vibrations of prismatic bars", Phil. Mag. 41 (1921) 744–746; S. M. Han,
//! H. Benaroya, T. Wei, "Dynamics of transversely vibrating beams using four engineering
//! theories", J. Sound Vib. 225 (1999) 935–988, simply supported Timoshenko beam): with
//! w = W sin(kₙx), ψ = Ψ cos(kₙx), kₙ = nπ/L, the two equations of motion give for every n
//!
//! ```text
//! (ρ²I/(κG)) ω⁴ − [ρA + ρI kₙ² (1 + E/(κG))] ω² + E I kₙ⁴ = 0,
//! ```
//! a quadratic in ω² whose smaller root is the bending (first-spectrum) frequency of mode n.
//! κ is the shear coefficient the solver uses for a solid circle (G. R. Cowper, J. Appl. Mech.
//! 33 (1966) 335–340): κ = 6(1+ν)/(7+6ν).

use flexfem::fem::mass::{beam_local_mass, beam_local_mass_shear};
use flexfem::fem::modal::{solve_modal, ModalOptions};
use flexfem::fem::{Beam, Dof, Model, Section, Support};
use flexfem::material::Material;
use std::f64::consts::PI;

mod common;
use common::materials::STEEL;

/// Timoshenko's simply supported frequency of mode n (Hz), smaller root of the quadratic in ω².
fn timoshenko_ss_hz(n: usize, l: f64, d: f64, mat: &Material) -> f64 {
    let (e, rho, nu) = (mat.e, mat.density, mat.nu);
    let g = e / (2.0 * (1.0 + nu));
    let kappa = 6.0 * (1.0 + nu) / (7.0 + 6.0 * nu);
    let a = PI * d * d / 4.0;
    let i = PI * d.powi(4) / 64.0;
    let k = n as f64 * PI / l;
    let qa = rho * rho * i / (kappa * g);
    let qb = rho * a + rho * i * k * k * (1.0 + e / (kappa * g));
    let qc = e * i * k.powi(4);
    // Smaller root without cancellation: ω² = 2c / (b + √(b² − 4ac)).
    let w2 = 2.0 * qc / (qb + (qb * qb - 4.0 * qa * qc).sqrt());
    w2.sqrt() / (2.0 * PI)
}

/// Round bar along x, `ne` shear-deformable beams, simply supported (uy = 0 at both ends) and
/// kept to x–y bending: ux, uz, rx, ry fixed at every node (axial and torsional motion is
/// uncoupled from bending in linear theory, so this removes only the other families).
fn ss_bar(l: f64, d: f64, ne: usize) -> Model {
    let mut m = Model::new();
    for i in 0..=ne {
        m.add_node([l * i as f64 / ne as f64, 0.0, 0.0]);
    }
    for i in 0..ne {
        m.add_beam(Beam::new(i, i + 1, Section::Circle { d }, STEEL, [0.0, 0.0, 1.0]));
    }
    for i in 0..=ne {
        let mut dofs = vec![Dof::Ux, Dof::Uz, Dof::Rx, Dof::Ry];
        if i == 0 || i == ne {
            dofs.push(Dof::Uy);
        }
        m.supports.push(Support::dofs(i, &dofs));
    }
    m
}

/// Relative errors of the first four bending modes.
fn errors(l: f64, d: f64, ne: usize) -> [f64; 4] {
    let r = solve_modal(&ss_bar(l, d, ne), &ModalOptions::new(4)).unwrap();
    std::array::from_fn(|k| {
        let f = r.modes[k].frequency_hz;
        let f_ref = timoshenko_ss_hz(k + 1, l, d, &STEEL);
        eprintln!(
            "L/d {:.0}, {ne} elements, mode {}: {f:.2} Hz vs {f_ref:.2} Hz ({:+.4} %)",
            l / d,
            k + 1,
            100.0 * (f - f_ref) / f_ref
        );
        (f - f_ref) / f_ref
    })
}

#[test]
fn simply_supported_round_bar_matches_timoshenko_closed_form() {
    // The reproducer: L 200, d 25 (L/d 8), 64 elements; the Euler–Bernoulli mass gave
    // −0.03/−0.36/−1.47/−3.62 % on modes 1–4. Also L/d 6 (L 150) and 12 (L 300).
    for l in [150.0, 200.0, 300.0] {
        for (k, e) in errors(l, 25.0, 64).iter().enumerate() {
            assert!(e.abs() < 1e-3, "L/d {}, mode {}: {:+.4} %", l / 25.0, k + 1, 100.0 * e);
        }
    }
}

#[test]
fn timoshenko_frequencies_converge_under_refinement() {
    // L/d 8: the error of every mode shrinks from 16 to 32 to 64 elements (the element is
    // exact in statics, so what is left is the mass discretisation, O(h²) or better), and
    // the finest mesh is within 0.1 %.
    let e: Vec<[f64; 4]> = [16, 32, 64].iter().map(|&ne| errors(200.0, 25.0, ne)).collect();
    for k in 0..4 {
        assert!(
            e[1][k].abs() < 0.5 * e[0][k].abs() && e[2][k].abs() < 0.5 * e[1][k].abs(),
            "mode {}: {:?}",
            k + 1,
            e.iter().map(|x| x[k]).collect::<Vec<_>>()
        );
        assert!(e[2][k].abs() < 1e-3, "mode {}: {}", k + 1, e[2][k]);
    }
}

#[test]
fn zero_shear_parameter_is_the_euler_bernoulli_mass_bit_for_bit() {
    // Przemieniecki eqs. 11.18, 11.25 written out for one element (the x–y plane on v, θz and
    // the x–z plane on w, θy with the L terms negated), compared exactly.
    let (rho, a, iy, iz, l) = (7.85e-9, 12.0, 9.0, 16.0, 7.3);
    let m0 = beam_local_mass_shear(rho, a, iy, iz, l, 0.0, 0.0);
    assert_eq!(m0, beam_local_mass(rho, a, iy, iz, l));
    let ma = rho * a * l;
    let tr = |i: usize, j: usize, s: f64| -> f64 {
        let t = [
            [156.0, 22.0 * l * s, 54.0, -13.0 * l * s],
            [22.0 * l * s, 4.0 * l * l, 13.0 * l * s, -3.0 * l * l],
            [54.0, 13.0 * l * s, 156.0, -22.0 * l * s],
            [-13.0 * l * s, -3.0 * l * l, -22.0 * l * s, 4.0 * l * l],
        ];
        t[i][j]
    };
    let ro = |i: usize, j: usize, s: f64| -> f64 {
        let t = [
            [36.0, 3.0 * l * s, -36.0, 3.0 * l * s],
            [3.0 * l * s, 4.0 * l * l, -3.0 * l * s, -l * l],
            [-36.0, -3.0 * l * s, 36.0, -3.0 * l * s],
            [3.0 * l * s, -l * l, -3.0 * l * s, 4.0 * l * l],
        ];
        t[i][j]
    };
    for (dv, dr, s, inertia) in [(1, 5, 1.0, iz), (2, 4, -1.0, iy)] {
        let idx = [dv, dr, 6 + dv, 6 + dr];
        for i in 0..4 {
            for j in 0..4 {
                let want = ma / 420.0 * tr(i, j, s) + rho * inertia / (30.0 * l) * ro(i, j, s);
                assert_eq!(m0[(idx[i], idx[j])], want, "entry ({}, {})", idx[i], idx[j]);
            }
        }
    }
    assert_eq!(m0[(0, 0)], ma / 6.0 * 2.0);
    assert_eq!(m0[(0, 6)], ma / 6.0);
    assert_eq!(m0[(3, 9)], rho * (iy + iz) * l / 6.0);
}

#[test]
fn shear_mass_keeps_the_rigid_body_kinetic_energy() {
    // Any Φ: a rigid translation v carries the mass ρAL, a rigid rotation about z (v = x θ,
    // θz = θ) the inertia ρA L³/3 + ρ Iz L about node 1 — the interpolation reproduces rigid
    // motion exactly (Friedman & Kosmatka 1993), so the consistent mass must too.
    let (rho, a, iy, iz, l) = (7.85e-9, 490.0, 19175.0, 19175.0, 3.125);
    for phi in [0.0, 0.3, 2.0, 40.0] {
        let m = beam_local_mass_shear(rho, a, iy, iz, l, phi, phi);
        let mut v = nalgebra::SVector::<f64, 12>::zeros();
        v[1] = 1.0;
        v[7] = 1.0;
        let mt = (v.transpose() * m * v)[(0, 0)];
        assert!((mt / (rho * a * l) - 1.0).abs() < 1e-12, "Φ {phi}: translation {mt}");
        let mut r = nalgebra::SVector::<f64, 12>::zeros();
        r[5] = 1.0;
        r[11] = 1.0;
        r[7] = l;
        let jr = (r.transpose() * m * r)[(0, 0)];
        let want = rho * a * l.powi(3) / 3.0 + rho * iz * l;
        assert!((jr / want - 1.0).abs() < 1e-12, "Φ {phi}: rotation {jr} vs {want}");
    }
}
