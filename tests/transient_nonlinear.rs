//! Geometrically nonlinear transient dynamics (`fem::nonlinear::solve_transient_nonlinear`:
//! co-rotational beams, Newmark average acceleration with Newton iterations per step):
//! - at small amplitude it is the linear transient solver's response (the nonlinear terms are
//!   O((u/L)²) of it);
//! - a large-amplitude pendulum (a stiff steel bar on a revolute pivot with a tip mass, released
//!   from rest at 60° under gravity) swings with the exact period of the simple pendulum,
//!   T = 4 K(sin(θ₀/2)) √(L/g) (the complete elliptic integral of the first kind; e.g.
//!   L. D. Landau, E. M. Lifshitz, Mechanics, 3rd ed., 1976, §11, problem 1), and conserves its
//!   energy (kinetic + strain − work of the constant gravity load) to a stated bound;
//! - a step too large for Newton's iterations is an error naming the step, never NaN.

use flexfem::fem::nonlinear::{solve_transient_nonlinear, NonlinearOptions};
use flexfem::fem::transient::{solve_transient, Damping, History, TransientLoad, TransientOptions};
use flexfem::fem::{Beam, Dof, Model, NodeDof, PointMass, Section, Support};
use flexfem::material::Material;
use std::f64::consts::PI;

mod common;

use common::materials::STEEL;

/// Steel cantilever along x (1000 mm, 10×10 mm, 10 Euler–Bernoulli elements, clamped at x = 0)
/// with a tip point mass of 1e-3 t (rotary inertia 1e-6 t·mm²).
fn cantilever() -> Model {
    let ne = 10;
    let mut m = Model::new();
    for i in 0..=ne {
        m.add_node([100.0 * i as f64, 0.0, 0.0]);
    }
    for i in 0..ne {
        m.add_beam(Beam::new(i, i + 1, Section::Rect { w: 10.0, h: 10.0 }, STEEL, [0.0, 0.0, 1.0]).euler_bernoulli());
    }
    m.supports.push(Support::clamp(0));
    m.masses.push(PointMass {
        node: ne,
        mass: 1e-3,
        inertia: [1e-6; 3],
    });
    m
}

/// (a) A damped cantilever under a small step force (tip deflection ~2e-4 mm, u/L ~ 2e-7) in x,
/// y and z with a tip moment: the tip's translation histories equal the linear solver's to 1e-6
/// of the largest tip translation, its rotation histories to 1e-6 of the largest tip rotation
/// (the nonlinear terms, e.g. the axial shortening ~ δ²/L, are ~1e-7 of them). Source: the
/// linear solver (the small-displacement limit).
#[test]
fn small_amplitude_equals_the_linear_transient() {
    let model = cantilever();
    let load = TransientLoad {
        node: 10,
        f: [1e-4, 1e-4, -5e-5, 0.0, 0.01, 0.0],
        history: History::Step { start: 0.0 },
    };
    let mut opts = TransientOptions::new(2e-4, 300);
    opts.damping = Damping {
        alpha: 2.0,
        beta: 1e-5,
        element_beta: vec![(0, 1e-5)],
    };
    opts.record = flexfem::fem::Dof::ALL.map(|dof| NodeDof { node: 10, dof }).to_vec();
    let lin = solve_transient(&model, std::slice::from_ref(&load), &[], &opts).unwrap();
    let nl = solve_transient_nonlinear(&model, &[load], &opts, &NonlinearOptions::default()).unwrap();
    let peak = |dofs: std::ops::Range<usize>| {
        lin.displacement[dofs]
            .iter()
            .flatten()
            .fold(0.0f64, |m, x| m.max(x.abs()))
    };
    let (pt, pr) = (peak(0..3), peak(3..6));
    assert_eq!(lin.displacement.len(), nl.displacement.len());
    for (d, (a, b)) in lin.displacement.iter().zip(&nl.displacement).enumerate() {
        let p = if d < 3 { pt } else { pr };
        assert_eq!(a.len(), b.len(), "DOF {d}: samples");
        let diff = a.iter().zip(b).fold(0.0f64, |m, (x, y)| m.max((x - y).abs()));
        eprintln!("DOF {d}: largest difference {:.3e} of the peak {p:.4e}", diff / p);
        assert!(p > 0.0 && diff <= 1e-6 * p, "DOF {d}: {diff} vs peak {p}");
    }
}

/// Complete elliptic integral of the first kind K(k) by the arithmetic–geometric mean,
/// K = π / (2 AGM(1, √(1 − k²))) (Abramowitz & Stegun 17.6).
fn elliptic_k(k: f64) -> f64 {
    let (mut a, mut b) = (1.0f64, (1.0 - k * k).sqrt());
    while (a - b).abs() > 1e-15 {
        (a, b) = (0.5 * (a + b), (a * b).sqrt());
    }
    PI / (2.0 * a)
}

const L: f64 = 1000.0;
const G: f64 = 9810.0;
const MASS: f64 = 1e-3;

/// The pendulum: a steel bar 10×10 mm, length L, 4 elements, pivot at the origin (translations
/// and rx, ry fixed: a revolute joint about z), tip at angle `theta0` from the downward
/// vertical with a 1e-3 t point mass; the bar's density is 1e-4 of steel's (bar mass 7.85e-8 t
/// = 7.85e-5 of the tip mass: the compound pendulum's equivalent length is L (1 − 1.3e-5)).
fn pendulum(theta0: f64) -> (Model, TransientLoad) {
    let ne = 4;
    let light = Material {
        density: STEEL.density * 1e-4,
        ..STEEL
    };
    let mut m = Model::new();
    for i in 0..=ne {
        let s = L * i as f64 / ne as f64;
        m.add_node([s * theta0.sin(), -s * theta0.cos(), 0.0]);
    }
    for i in 0..ne {
        m.add_beam(Beam::new(i, i + 1, Section::Rect { w: 10.0, h: 10.0 }, light, [0.0, 0.0, 1.0]).euler_bernoulli());
    }
    m.supports
        .push(Support::dofs(0, &[Dof::Ux, Dof::Uy, Dof::Uz, Dof::Rx, Dof::Ry]));
    m.masses.push(PointMass {
        node: ne,
        mass: MASS,
        inertia: [0.0; 3],
    });
    let gravity = TransientLoad {
        node: ne,
        f: [0.0, -MASS * G, 0.0, 0.0, 0.0, 0.0],
        history: History::Step { start: 0.0 },
    };
    (m, gravity)
}

/// (b), (c) The pendulum released from rest at θ₀ = 60°, 400 steps per small-amplitude period
/// over 3 large-amplitude periods: the period from the tip's crossings of the vertical equals
/// 4 K(sin 30°) √(L/g) = 1.07318 × 2π √(L/g) within 0.1 % (the elliptic-integral period; the
/// scheme's own period error is (ωΔt)²/12 ≈ 2e-5), and the energy stays within 1e-3 of the
/// swing energy m g L (1 − cos θ₀) (average acceleration conserves the energy of linear systems
/// exactly, of nonlinear ones only to O(Δt²); measured 1.5e-4, period error 6.1e-5).
#[test]
fn large_amplitude_pendulum_period_and_energy() {
    let theta0 = 60f64.to_radians();
    let (model, gravity) = pendulum(theta0);
    let t_small = 2.0 * PI * (L / G).sqrt();
    let t_exact = 4.0 * elliptic_k((0.5 * theta0).sin()) * (L / G).sqrt();
    let dt = t_small / 400.0;
    let steps = (3.0 * t_exact / dt).ceil() as usize + 20;
    let mut opts = TransientOptions::new(dt, steps);
    opts.record = vec![NodeDof { node: 4, dof: Dof::Ux }, NodeDof { node: 4, dof: Dof::Uy }];
    opts.energy = true;
    let res = solve_transient_nonlinear(
        &model,
        std::slice::from_ref(&gravity),
        &opts,
        &NonlinearOptions::default(),
    )
    .unwrap();
    // Tip abscissa x = L sin θ₀ + uₓ: its crossings of x = 0 (θ = 0) towards −x (the pendulum
    // starts at +θ₀), interpolated linearly; one period between successive crossings.
    let x: Vec<f64> = res.displacement[0].iter().map(|u| L * theta0.sin() + u).collect();
    let crossings: Vec<f64> = (1..x.len())
        .filter(|&i| x[i - 1] > 0.0 && x[i] <= 0.0)
        .map(|i| res.time[i - 1] + dt * x[i - 1] / (x[i - 1] - x[i]))
        .collect();
    assert!(crossings.len() >= 3, "{crossings:?}");
    let periods: Vec<f64> = crossings.windows(2).map(|w| w[1] - w[0]).collect();
    let period = (crossings[crossings.len() - 1] - crossings[0]) / (crossings.len() - 1) as f64;
    let rel = (period - t_exact) / t_exact;
    eprintln!(
        "pendulum 60°: period {period:.6} s (each {periods:?}), elliptic {t_exact:.6} s, small-amplitude {t_small:.6} s; relative error {rel:.3e}"
    );
    assert!(rel.abs() < 1e-3, "{rel}");
    // Energy: kinetic + strain − F·u (gravity is constant from t = 0; E(0) = 0).
    let swing = MASS * G * L * (1.0 - theta0.cos());
    assert_eq!(res.energy.len(), res.displacement[1].len());
    let worst = res
        .energy
        .iter()
        .zip(&res.displacement[1])
        .map(|(e, uy)| (e.kinetic + e.strain + MASS * G * uy).abs())
        .fold(0.0f64, f64::max);
    let peak_kinetic = res.energy.iter().map(|e| e.kinetic).fold(0.0f64, f64::max);
    eprintln!(
        "energy drift {:.3e} of the swing energy {swing:.1} N·mm (peak kinetic {peak_kinetic:.1})",
        worst / swing
    );
    assert!((peak_kinetic - swing).abs() < 1e-3 * swing, "{peak_kinetic} vs {swing}");
    assert!(worst < 1e-3 * swing, "{worst}");
}

/// A time step of a whole period on the 60° pendulum with 2 Newton iterations allowed: the
/// solve fails with an error naming the step and time, and suggesting a smaller step.
#[test]
fn newton_failure_is_an_error_with_context() {
    let (model, gravity) = pendulum(60f64.to_radians());
    let opts = TransientOptions::new(2.0, 3);
    let nl = NonlinearOptions {
        max_iterations: 2,
        ..NonlinearOptions::default()
    };
    let e = solve_transient_nonlinear(&model, &[gravity], &opts, &nl)
        .unwrap_err()
        .to_string();
    assert!(e.contains("step 1 (t = 2 s)") && e.contains("smaller time step"), "{e}");
}

/// The bundled case `cases/pendulum_nonlinear_transient.json` (the 60° pendulum as a case file,
/// `"nonlinear": true`): the tip turns at −60° (energy conservation of the exact pendulum:
/// uₓ = −2 L sin 60° = −1732.05 mm) within 1e-4, at half the elliptic-integral period (1.0764 s)
/// within one time step; the pivot has turned −120°. The nonlinear option refuses HHT and
/// prescribed motions (exit 2, naming the field).
#[test]
fn bundled_pendulum_case_and_refusals() {
    let (_, r) = common::run_out("cases/pendulum_nonlinear_transient.json", "pendulum_case");
    let rec = &r["records"];
    let (ux, t) = (rec[0]["min"].as_f64().unwrap(), rec[0]["t_min_s"].as_f64().unwrap());
    let exact = -2.0 * L * 60f64.to_radians().sin();
    let half = 2.0 * elliptic_k(0.5) * (L / G).sqrt();
    eprintln!("turning point ux = {ux} mm (exact {exact}) at t = {t} s (T/2 = {half})");
    assert!(((ux - exact) / exact).abs() < 1e-4, "{ux}");
    assert!((t - half).abs() <= 0.005, "{t}");
    assert!((rec[2]["min"].as_f64().unwrap() + 120.0).abs() < 0.01);
    assert!(r["model"].as_str().unwrap().starts_with("geometrically nonlinear"));
    let text = std::fs::read_to_string("cases/pendulum_nonlinear_transient.json").unwrap();
    for (edit, field) in [
        ("\"nonlinear\": true,\n  \"scheme\": \"hht\",", "scheme"),
        (
            "\"nonlinear\": true,\n  \"motions\": [{\"node\": 0, \"dof\": \"rz\", \"value\": 1, \"history\": {\"type\": \"ramp\", \"end\": 0.1}}],",
            "motions",
        ),
    ] {
        let o = common::run_case_text("pendulum_refused.json", &text.replace("\"nonlinear\": true,", edit));
        assert_eq!(o.status.code(), Some(2), "{}", common::stderr(&o));
        let e = common::stderr(&o);
        assert!(e.contains(&format!("`{field}`")) && e.contains("\"nonlinear\": true"), "{e}");
    }
}
