//! Joint damping of a flexure hinge from a simulated step response, after the procedure of
//! Yu, Lu and Hao (2016), 8R compliant parallel pan-tilt, §4.1: (1) the rotational stiffness K
//! from statics, (2) the step response of the hinge in its blank to a moment about the compliant
//! axis from a transient FE run with the material's damping, (3)–(4) the second-order model
//! J θ̈ + D θ̇ + K θ = M (K fixed) that fits the response best gives the joint damping D.
//!
//! The hinge in its blank is the chain of flexibility elements of the large-rotation model
//! ([`super::flex_chain`], 16 notch segments), clamped at one blank end, with the mass of each
//! segment lumped at its two nodes (translational mass and the rotary inertia of the half
//! segment about the node). The material damping is Rayleigh damping C = a M + b K.
//!
//! The fit is linear least squares on the twice-integrated equation of motion from rest,
//! J θ(t) + D ∫θ + K ∬θ = M t²/2, over every step (J ≥ 0; J = 0, a first-order fit, when the
//! free fit gives J < 0); its residual is the RMS difference between the simulated rotation and
//! the fitted model's step response, relative to the static rotation.

use super::profile::Profile;
use crate::fem::transient::{solve_transient, Damping, History, Scheme, TransientLoad, TransientOptions};
use crate::fem::{Dof, Element, FemError, FlexElement, LoadCase, Model, NodeDof, PointMass, Support};
use crate::material::Material;

/// Inputs of [`identify_damping`].
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct DampingRun {
    /// Mass-proportional Rayleigh coefficient of the material, 1/s.
    pub alpha: f64,
    /// Stiffness-proportional Rayleigh coefficient of the material, s.
    pub beta: f64,
    /// Simulated time, s.
    pub duration: f64,
    /// Time steps.
    pub steps: usize,
    /// Step moment about the compliant axis, N·mm.
    pub moment: f64,
}

/// The identified second-order joint model.
#[derive(Debug, Clone, PartialEq)]
pub struct JointDamping {
    /// Rotational stiffness about the compliant axis from statics, N·mm/rad.
    pub k: f64,
    /// Identified joint damping, N·mm·s/rad.
    pub d: f64,
    /// Identified rotary inertia, tonne·mm² (0 when the fit is first order).
    pub j: f64,
    /// RMS of (simulated − fitted) rotation over the run, relative to the static rotation.
    pub residual: f64,
    /// Static rotation M/K, rad.
    pub static_rotation: f64,
    /// Time step, s.
    pub dt: f64,
    /// Simulated (time s, rotation rad) of the loaded blank end.
    pub time: Vec<f64>,
    pub rotation: Vec<f64>,
    /// The fitted model's rotation at the same times, rad.
    pub fitted: Vec<f64>,
}

/// The hinge in its blank along x with lumped masses, clamped at the first node; returns the
/// model and the loaded (last) node.
fn hinge_model(profile: &Profile, m: &Material) -> (Model, usize) {
    let (xs, chain) = super::flex_chain(profile, m, 16);
    let mut model = Model::new();
    for &x in &xs {
        model.add_node([x, 0.0, 0.0]);
    }
    let mut lumped = vec![(0.0f64, [0.0f64; 3]); xs.len()];
    for (i, compliance) in chain.into_iter().enumerate() {
        model.add_element(Element::Flex(FlexElement {
            nodes: [i, i + 1],
            compliance,
            up: [0.0, 0.0, 1.0],
        }));
        // Half segment per node: Simpson mass and the rotary inertia of a prism of the mean
        // section (thickness along z, width along y) about the node.
        let (x0, x1) = (xs[i], xs[i + 1]);
        let area = |x: f64| profile.section(x, m.nu).area;
        let a_mean = (area(x0) + 4.0 * area(0.5 * (x0 + x1)) + area(x1)) / 6.0;
        let half = 0.5 * (x1 - x0);
        let mass = m.density * a_mean * half;
        let t = profile.thickness(0.5 * (x0 + x1));
        let w = a_mean / t.max(f64::MIN_POSITIVE);
        let arm = half * half / 3.0;
        let inertia = [
            mass * (t * t + w * w) / 12.0,
            mass * (t * t / 12.0 + arm),
            mass * (w * w / 12.0 + arm),
        ];
        for node in [i, i + 1] {
            lumped[node].0 += mass;
            for (acc, v) in lumped[node].1.iter_mut().zip(inertia) {
                *acc += v;
            }
        }
    }
    for (node, (mass, inertia)) in lumped.into_iter().enumerate() {
        model.masses.push(PointMass { node, mass, inertia });
    }
    model.supports.push(Support::clamp(0));
    let tip = xs.len() - 1;
    (model, tip)
}

/// Step response of the second-order model J θ̈ + D θ̇ + K θ = M from rest (J = 0: first
/// order), rad.
fn second_order_step(j: f64, d: f64, k: f64, moment: f64, t: f64) -> f64 {
    let st = moment / k;
    if j <= 0.0 {
        return st * (1.0 - (-k * t / d).exp());
    }
    let disc = d * d - 4.0 * j * k;
    if disc > 0.0 {
        let q = disc.sqrt();
        let (s1, s2) = ((-d + q) / (2.0 * j), (-d - q) / (2.0 * j));
        st * (1.0 + (s2 * (s1 * t).exp() - s1 * (s2 * t).exp()) / (s1 - s2))
    } else {
        let wn = (k / j).sqrt();
        let z = d / (2.0 * (j * k).sqrt());
        let wd = wn * (1.0 - z * z).max(1e-300).sqrt();
        st * (1.0 - (-z * wn * t).exp() * ((wd * t).cos() + z * wn / wd * (wd * t).sin()))
    }
}

/// Runs the procedure on the hinge `profile` of material `m` (see the module docs).
pub fn identify_damping(profile: &Profile, m: &Material, run: &DampingRun) -> Result<JointDamping, FemError> {
    let (mut model, tip) = hinge_model(profile, m);
    let moment = [0.0, 0.0, 0.0, 0.0, run.moment, 0.0];
    model.load_cases = vec![LoadCase::new("moment").force(tip, moment)];
    let st = crate::fem::solve_static_with(&model, crate::fem::solve::Parallelism::Sequential)?;
    let static_rotation = st.load_cases[0].displacements[tip][4];
    if !(static_rotation.is_finite() && static_rotation > 0.0) {
        return Err(FemError::BadInput("hinge damping: no rotation under the moment".into()));
    }
    let k = run.moment / static_rotation;
    let dt = run.duration / run.steps as f64;
    let mut opts = TransientOptions::new(dt, run.steps);
    opts.scheme = Scheme::AverageAcceleration;
    opts.damping = Damping {
        alpha: run.alpha,
        beta: run.beta,
        element_beta: Vec::new(),
    };
    opts.record = vec![NodeDof {
        node: tip,
        dof: Dof::Ry,
    }];
    opts.par = crate::fem::solve::Parallelism::Sequential;
    let load = TransientLoad {
        node: tip,
        f: moment,
        history: History::Step { start: 0.0 },
    };
    let r = solve_transient(&model, &[load], &[], &opts)?;
    let (time, rotation) = (r.time, r.displacement.into_iter().next().unwrap_or_default());
    // ∫θ and ∬θ by the trapezoidal rule.
    let (mut i1, mut i2) = (vec![0.0; time.len()], vec![0.0; time.len()]);
    for n in 1..time.len() {
        i1[n] = i1[n - 1] + 0.5 * dt * (rotation[n] + rotation[n - 1]);
        i2[n] = i2[n - 1] + 0.5 * dt * (i1[n] + i1[n - 1]);
    }
    // Least squares [θ ∫θ] [J D]ᵀ = M t²/2 − K ∬θ.
    let rhs: Vec<f64> = time
        .iter()
        .zip(&i2)
        .map(|(t, q)| run.moment * t * t / 2.0 - k * q)
        .collect();
    let dot = |a: &[f64], b: &[f64]| a.iter().zip(b).map(|(x, y)| x * y).sum::<f64>();
    let (a11, a12, a22) = (dot(&rotation, &rotation), dot(&rotation, &i1), dot(&i1, &i1));
    let (b1, b2) = (dot(&rotation, &rhs), dot(&i1, &rhs));
    let det = a11 * a22 - a12 * a12;
    let (mut j, mut d) = ((b1 * a22 - b2 * a12) / det, (a11 * b2 - a12 * b1) / det);
    if !(j.is_finite() && j >= 0.0) {
        (j, d) = (0.0, b2 / a22);
    }
    if !(d.is_finite() && d > 0.0) {
        return Err(FemError::Solver(format!(
            "hinge damping: the fitted damping is {d} N·mm·s/rad; give the material damping (beta > 0) and a run of a few time constants"
        )));
    }
    let fitted: Vec<f64> = time
        .iter()
        .map(|&t| second_order_step(j, d, k, run.moment, t))
        .collect();
    let residual = (rotation.iter().zip(&fitted).map(|(a, b)| (a - b).powi(2)).sum::<f64>() / time.len() as f64).sqrt()
        / static_rotation;
    Ok(JointDamping {
        k,
        d,
        j,
        residual,
        static_rotation,
        dt,
        time,
        rotation,
        fitted,
    })
}
