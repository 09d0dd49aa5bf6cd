//! Objectivity of the per-step quantities (`NonlinearOptions::step_track`): a cantilever with
//! a tip mass turned rigidly through 90° about z by its clamp (a prescribed rotation, no
//! deformation) must keep its natural frequencies, and its tip compliance must turn with it,
//! C(90°) = R·C(0)·Rᵀ (R the 6×6 block rotation). This holds only if the tangent stiffness and
//! the mass matrix both follow the rotated element frames (the beams' consistent mass and the
//! point mass's rotary inertia are anisotropic here), so it fails for a mass matrix left in the
//! undeformed axes. Exact up to the solver tolerances: checked to 1e-6 relative.

use flexfem::fem::{self, Beam, Dof, LoadCase, Model, NonlinearOptions, PointMass, Section, StepTrack, Support};
use flexfem::material::Material;
use nalgebra::{Matrix3, Matrix6};

#[test]
fn rigid_rotation_keeps_frequencies_and_turns_the_compliance() {
    let mat = Material {
        e: 70_000.0,
        nu: 0.33,
        density: 2.7e-9,
        yield_strength: 1e9,
        allowable: 1e9,
        fatigue: None,
    };
    let mut m = Model::new();
    let mut prev = m.add_node([0.0, 0.0, 0.0]);
    m.supports.push(Support::clamp(prev));
    for i in 1..=5 {
        let n = m.add_node([20.0 * i as f64, 0.0, 0.0]);
        m.add_beam(Beam::new(
            prev,
            n,
            Section::Rect { w: 2.0, h: 6.0 },
            mat,
            [0.3, 0.2, 1.0],
        ));
        prev = n;
    }
    let tip = prev;
    m.masses.push(PointMass {
        node: tip,
        mass: 1e-5,
        inertia: [1e-3, 4e-3, 9e-3],
    });
    m.load_cases = vec![LoadCase::new("turn").displacement(0, Dof::Rz, std::f64::consts::FRAC_PI_2)];
    let opts = NonlinearOptions {
        steps: 8,
        step_track: StepTrack {
            modes: 6,
            compliance: vec![tip],
        },
        ..Default::default()
    };
    let r = fem::solve_nonlinear(&m, &opts).expect("solves");
    let q = &r.load_cases[0].step_quantities;
    let (q0, q1) = (&q[0], q.last().unwrap());
    assert_eq!(q1.lambda, 1.0);
    assert_eq!(q0.frequencies_hz().len(), q1.frequencies_hz().len());
    for (a, b) in q0.frequencies_hz().iter().zip(q1.frequencies_hz()) {
        assert!((a / b - 1.0).abs() < 1e-6, "{a} Hz at 0°, {b} Hz at 90°");
    }
    let rz = Matrix3::new(0.0, -1.0, 0.0, 1.0, 0.0, 0.0, 0.0, 0.0, 1.0);
    let mut rr = Matrix6::zeros();
    rr.fixed_view_mut::<3, 3>(0, 0).copy_from(&rz);
    rr.fixed_view_mut::<3, 3>(3, 3).copy_from(&rz);
    let c0 = Matrix6::from_fn(|i, j| q0.compliance[0][i][j]);
    let c1 = Matrix6::from_fn(|i, j| q1.compliance[0][i][j]);
    let want = rr * c0 * rr.transpose();
    for i in 0..6 {
        for j in 0..6 {
            let scale = (want[(i, i)] * want[(j, j)]).abs().sqrt();
            assert!(
                (c1[(i, j)] - want[(i, j)]).abs() <= 1e-6 * scale,
                "C[{i}][{j}] = {} at 90°, R·C(0)·Rᵀ = {}",
                c1[(i, j)],
                want[(i, j)]
            );
        }
    }
}
