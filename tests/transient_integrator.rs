//! Transient dynamics (`fem::transient`) against closed forms and published properties of the
//! integrators:
//! - a damped cantilever's tip step response against its modal closed form (the step response of
//!   each damped mode, A. K. Chopra, Dynamics of Structures, 4th ed., 2012, eq. 4.3.3 and §13.1,
//!   with the static correction of the modes left out);
//! - exact energy conservation of undamped Newmark average acceleration (N. M. Newmark, J. Eng.
//!   Mech. Div. ASCE 85 (1959) 67–94: the trapezoidal rule conserves the energy of linear
//!   undamped free vibration);
//! - HHT-α numerical damping for α = −0.05 (H. M. Hilber, T. J. R. Hughes, R. L. Taylor,
//!   Earthquake Eng. Struct. Dyn. 5 (1977) 283–292): spectral radius (1 + α)/(1 − α) = 0.9048 as
//!   Δt/T → ∞, and second-order accuracy (algorithmic damping of low modes vanishing as Ω³,
//!   Ω = 2π Δt/T).

use flexfem::fem::modal::{solve_modal, ModalOptions};
use flexfem::fem::transient::{solve_transient, Damping, History, Scheme, TransientLoad, TransientOptions};
use flexfem::fem::{solve_static, Beam, Dof, LoadCase, Model, NodeDof, PointMass, Section, Support};
use nalgebra::Matrix3;
use std::f64::consts::PI;

mod common;

use common::materials::STEEL;

/// Steel cantilever along x, 1000 mm, 10×10 mm, `ne` Euler–Bernoulli elements, clamped at x = 0,
/// with a tip point mass `tip` (tonne, rotary inertia 1e-6 t·mm² so that M is definite).
fn cantilever(ne: usize, tip: f64) -> Model {
    let mut m = Model::new();
    for i in 0..=ne {
        m.add_node([1000.0 * i as f64 / ne as f64, 0.0, 0.0]);
    }
    for i in 0..ne {
        m.add_beam(Beam::new(i, i + 1, Section::Rect { w: 10.0, h: 10.0 }, STEEL, [0.0, 0.0, 1.0]).euler_bernoulli());
    }
    m.supports.push(Support::clamp(0));
    if tip > 0.0 {
        m.masses.push(PointMass {
            node: ne,
            mass: tip,
            inertia: [1e-6; 3],
        });
    }
    m
}

/// Unit step response of a damped oscillator (Chopra eq. 4.3.3; ζ < 1), times 1/ω².
fn step(zeta: f64, w: f64, t: f64) -> f64 {
    let wd = w * (1.0 - zeta * zeta).sqrt();
    (1.0 - (-zeta * w * t).exp() * ((wd * t).cos() + zeta / (1.0 - zeta * zeta).sqrt() * (wd * t).sin())) / (w * w)
}

/// Extremes (time, value) of a sampled series, refined by the parabola through three samples.
fn extremes(t: &[f64], u: &[f64]) -> Vec<(f64, f64)> {
    let dt = t[1] - t[0];
    (1..u.len() - 1)
        .filter(|&i| (u[i] - u[i - 1]) * (u[i + 1] - u[i]) < 0.0)
        .map(|i| {
            let (a, b, c) = (u[i - 1], u[i], u[i + 1]);
            let d = 0.5 * (a - c) / (a - 2.0 * b + c);
            (t[i] + d * dt, b - 0.25 * (a - c) * d)
        })
        .collect()
}

#[test]
fn damped_cantilever_step_matches_modal_closed_form() {
    // Tip mass = the beam's mass (0.785e-3 t), so the first mode carries most of the response.
    let ne = 10;
    let model = cantilever(ne, 7.85e-4);
    let f = 1.0;
    let modal = solve_modal(&model, &ModalOptions::new(20)).unwrap();
    let w1 = modal.modes[0].eigenvalue.sqrt();
    // Rayleigh damping: ζ = 2 % at modes 1 and 3 (the first two z-bending modes).
    let (zeta, w3) = (0.02, modal.modes[2].eigenvalue.sqrt());
    let (ra, rb) = (2.0 * zeta * w1 * w3 / (w1 + w3), 2.0 * zeta / (w1 + w3));
    let wd1 = w1 * (1.0 - zeta * zeta).sqrt();
    let dt = 2.0 * PI / wd1 / 40.0;
    let steps = 5 * 40;
    let mut opts = TransientOptions::new(dt, steps);
    opts.damping = Damping {
        alpha: ra,
        beta: rb,
        element_beta: vec![],
    };
    opts.record = vec![NodeDof { node: ne, dof: Dof::Uz }];
    let load = TransientLoad {
        node: ne,
        f: [0.0, 0.0, f, 0.0, 0.0, 0.0],
        history: History::Step { start: 0.0 },
    };
    let r = solve_transient(&model, &[load], &[], &opts).unwrap();
    // Closed form: the 20 modes with ζ < 1, plus the static correction of the others.
    let mut sm = model.clone();
    sm.load_cases = vec![LoadCase::new("tip").force(ne, [0.0, 0.0, f, 0.0, 0.0, 0.0])];
    let u_static = solve_static(&sm).unwrap().load_cases[0].displacements[ne][2];
    let modes: Vec<(f64, f64, f64)> = modal
        .modes
        .iter()
        .map(|md| {
            let w = md.eigenvalue.sqrt();
            let phi = md.shape[ne][2];
            (w, ra / (2.0 * w) + rb * w / 2.0, phi * phi * f)
        })
        .filter(|m| m.1 < 1.0)
        .collect();
    let residual = u_static - modes.iter().map(|(w, _, g)| g / (w * w)).sum::<f64>();
    let exact = |t: f64| residual + modes.iter().map(|(w, z, g)| g * step(*z, *w, t)).sum::<f64>();
    let t_fine: Vec<f64> = (0..=steps * 400).map(|i| i as f64 * dt / 400.0).collect();
    let u_fine: Vec<f64> = t_fine.iter().map(|&t| exact(t)).collect();
    let (num, ex) = (extremes(&r.time, &r.displacement[0]), extremes(&t_fine, &u_fine));
    assert!(
        num.len() >= 9 && ex.len() >= 9,
        "{} and {} extremes",
        num.len(),
        ex.len()
    );
    let mut worst = (0.0f64, 0.0f64);
    // zip-checked: both have ≥ 9 extremes (asserted above), nine compared.
    for ((tn, un), (te, ue)) in num.iter().zip(&ex).take(9) {
        // Amplitude: the excursion from the static deflection; phase: the time of the extreme.
        let amp = ((un - u_static) / (ue - u_static) - 1.0).abs();
        let phase = (tn / te - 1.0).abs();
        worst = (worst.0.max(amp), worst.1.max(phase));
    }
    eprintln!(
        "cantilever step, 40 steps per period, 5 periods: amplitude error {:.3} %, phase error {:.3} %",
        100.0 * worst.0,
        100.0 * worst.1
    );
    assert!(worst.0 < 0.005 && worst.1 < 0.005, "{worst:?}");
}

#[test]
fn undamped_average_acceleration_conserves_energy() {
    let ne = 10;
    let model = cantilever(ne, 0.0);
    // Initial state: the static deflection under a tip force, at rest.
    let mut sm = model.clone();
    sm.load_cases = vec![LoadCase::new("tip").force(ne, [0.0, 20.0, 50.0, 0.0, 0.0, 0.0])];
    let u0: Vec<f64> = solve_static(&sm).unwrap().load_cases[0].displacements.concat();
    let w1 = solve_modal(&model, &ModalOptions::new(1)).unwrap().modes[0]
        .eigenvalue
        .sqrt();
    let mut opts = TransientOptions::new(2.0 * PI / w1 / 20.0, 1000);
    opts.energy = true;
    opts.initial = Some((u0.clone(), vec![0.0; u0.len()]));
    let r = solve_transient(&model, &[], &[], &opts).unwrap();
    let e: Vec<f64> = r.energy.iter().map(|e| e.kinetic + e.strain).collect();
    let drift = e.iter().map(|x| (x / e[0] - 1.0).abs()).fold(0.0, f64::max);
    let kin = r.energy.iter().map(|e| e.kinetic).fold(0.0, f64::max);
    eprintln!(
        "energy drift over 1000 steps: {drift:.2e} (peak kinetic / total {:.3})",
        kin / e[0]
    );
    assert!(kin > 0.5 * e[0], "the energy must move between strain and kinetic");
    assert!(drift < 1e-6, "{drift}");
    // HHT-α with α = −0.05 is dissipative: the same run loses energy (guards the test above).
    opts.scheme = Scheme::Hht { alpha: -0.05 };
    let r = solve_transient(&model, &[], &[], &opts).unwrap();
    let last = r.energy.last().map(|e| e.kinetic + e.strain).unwrap();
    assert!(last < 0.99 * e[0], "HHT energy {last} vs {}", e[0]);
}

/// Axial bar (EA/L = k) with a tip point mass m: one decoupled DOF, ω² = k/m. Returns the
/// scaled state sequences (u, v Δt, a Δt²) from the initial state (u0, v0).
fn sdof(scheme: Scheme, dt_over_t: f64, steps: usize, u0: f64, v0: f64) -> (Vec<[f64; 3]>, f64) {
    let mut model = Model::new();
    model.add_node([0.0, 0.0, 0.0]);
    model.add_node([100.0, 0.0, 0.0]);
    let mut mat = STEEL;
    mat.density = 0.0;
    model.add_beam(Beam::new(0, 1, Section::Rect { w: 1.0, h: 1.0 }, mat, [0.0, 0.0, 1.0]).euler_bernoulli());
    model.supports.push(Support::clamp(0));
    let mass = 1e-3;
    model.masses.push(PointMass {
        node: 1,
        mass,
        inertia: [1e-3; 3],
    });
    let w = (STEEL.e * 1.0 / 100.0 / mass).sqrt();
    let dt = dt_over_t * 2.0 * PI / w;
    let mut opts = TransientOptions::new(dt, steps);
    opts.scheme = scheme;
    opts.record = vec![NodeDof { node: 1, dof: Dof::Ux }];
    let (mut u, mut v) = (vec![0.0; 12], vec![0.0; 12]);
    u[6] = u0;
    v[6] = v0;
    opts.initial = Some((u, v));
    let r = solve_transient(&model, &[], &[], &opts).unwrap();
    let states = (0..=steps)
        .map(|i| {
            [
                r.displacement[0][i],
                r.velocity[0][i] * dt,
                r.acceleration[0][i] * dt * dt,
            ]
        })
        .collect();
    (states, w)
}

/// The one-step amplification matrix A (x_{n+1} = A x_n on scaled states) from three
/// independent state transitions of the solver.
fn amplification(scheme: Scheme, dt_over_t: f64) -> Matrix3<f64> {
    let (s1, _) = sdof(scheme, dt_over_t, 8, 1.0, 0.0);
    let (s2, _) = sdof(scheme, dt_over_t, 8, 0.0, 1.0);
    let col = |x: [f64; 3]| nalgebra::Vector3::from(x);
    let x0 = Matrix3::from_columns(&[col(s1[0]), col(s2[0]), col(s1[3])]);
    let x1 = Matrix3::from_columns(&[col(s1[1]), col(s2[1]), col(s1[4])]);
    x1 * x0.try_inverse().expect("independent states")
}

/// Algorithmic damping ratio of free vibration at `dt_over_t`, from the decay of the positive
/// peaks over 20 periods (log decrement).
fn low_mode_damping(scheme: Scheme, dt_over_t: f64) -> f64 {
    let steps = (20.0 / dt_over_t).round() as usize;
    let (s, _) = sdof(scheme, dt_over_t, steps, 1.0, 0.0);
    let u: Vec<f64> = s.iter().map(|x| x[0]).collect();
    let t: Vec<f64> = (0..u.len()).map(|i| i as f64).collect();
    let peaks: Vec<(f64, f64)> = extremes(&t, &u).into_iter().filter(|p| p.1 > 0.0).collect();
    let (first, last) = (peaks[0], peaks[peaks.len() - 1]);
    (first.1 / last.1).ln() / (2.0 * PI * (peaks.len() - 1) as f64)
}

#[test]
fn hht_alpha_numerical_damping_as_published() {
    let alpha = -0.05;
    let hht = Scheme::Hht { alpha };
    // Δt/T → ∞ (here 1000): spectral radius (1 + α)/(1 − α) (Hilber, Hughes & Taylor 1977).
    let rho = |a: Matrix3<f64>| a.complex_eigenvalues().iter().map(|l| l.norm()).fold(0.0, f64::max);
    let rho_inf = rho(amplification(hht, 1000.0));
    let published = (1.0 + alpha) / (1.0 - alpha);
    eprintln!("HHT alpha = -0.05: spectral radius at dt/T = 1000: {rho_inf:.5} (published {published:.5})");
    assert!((rho_inf / published - 1.0).abs() < 1e-3, "{rho_inf}");
    // Average acceleration: no numerical damping at any Δt/T (spectral radius 1). Its
    // acceleration is the equilibrium one, a = −ω² u, so the state is (u, v Δt).
    let (s1, _) = sdof(Scheme::AverageAcceleration, 1000.0, 1, 1.0, 0.0);
    let (s2, _) = sdof(Scheme::AverageAcceleration, 1000.0, 1, 0.0, 1.0);
    let v = s2[0][1];
    let a = nalgebra::Matrix2::new(s1[1][0], s2[1][0] / v, s1[1][1], s2[1][1] / v);
    let rho_aa = a.complex_eigenvalues().iter().map(|l| l.norm()).fold(0.0, f64::max);
    assert!((rho_aa - 1.0).abs() < 1e-6, "{rho_aa}");
    // Low modes: HHT keeps second-order accuracy (Hilber, Hughes & Taylor 1977), so its
    // algorithmic damping ratio vanishes as Ω³: doubling Δt/T from 0.01 to 0.02 multiplies the
    // damping ratio (log decrement of free vibration over the run) by 8.
    let (xi1, xi2) = (low_mode_damping(hht, 0.01), low_mode_damping(hht, 0.02));
    eprintln!(
        "HHT alpha = -0.05: damping ratio {xi1:.4e} at dt/T = 0.01, {xi2:.4e} at 0.02 (ratio {:.3})",
        xi2 / xi1
    );
    assert!(xi1 > 0.0 && xi1 < 1e-5, "{xi1}");
    assert!((xi2 / xi1 / 8.0 - 1.0).abs() < 0.05, "{xi1} {xi2}");
}
