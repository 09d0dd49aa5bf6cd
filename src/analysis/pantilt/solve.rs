//! Solving a pan-tilt case: inverse and forward kinematics queries and the actuation path
//! (joint rotations, torques and their peaks), and the warnings that depend on the result.

use super::{
    FkRow, GeometryOut, IkRow, PanTiltResult, PathOut, PathRow, Peak, NEAR_SINGULAR_FRACTION,
    POLE_WARNING_DEG,
};
use crate::analysis::AnalysisError;
use crate::case::pantilt::ValidPanTilt;
use crate::kinematics::pantilt::{PanTilt, PanTiltError, PathState, JOINTS};

fn joint_descriptions(m: &PanTilt) -> Vec<String> {
    let g = m.geometry();
    let mut out = Vec::with_capacity(JOINTS);
    for j in 0..3 {
        let act = if g.actuated.contains(&j) { ", actuated" } else { "" };
        out.push(format!("bottom joint of limb {}{act}", j + 1));
    }
    for j in 0..3 {
        let kind = if j == g.rr_limb {
            " (RR limb, fixed in the platform)"
        } else {
            ""
        };
        out.push(format!("middle joint of limb {}{kind}", j + 1));
    }
    for j in m.rrr_limbs() {
        out.push(format!("top joint of limb {} (about the platform axis)", j + 1));
    }
    out
}

fn err(ctx: String) -> impl Fn(PanTiltError) -> AnalysisError {
    move |e| AnalysisError::new(ctx.clone(), e.to_string())
}

fn peak(states: &[PathState], f: impl Fn(&PathState) -> f64, scale: f64) -> Peak {
    let mut best = Peak {
        max_abs: -1.0,
        value: 0.0,
        t: 0.0,
        phi_deg: 0.0,
    };
    for s in states {
        let v = f(s) * scale;
        if v.abs() > best.max_abs {
            best = Peak {
                max_abs: v.abs(),
                value: v,
                t: s.sample.t,
                phi_deg: s.sample.pose.phi.to_degrees(),
            };
        }
    }
    best
}

/// Solves every query of the case.
pub fn solve(v: &ValidPanTilt) -> Result<PanTiltResult, AnalysisError> {
    let m = &v.model;
    let g = m.geometry();
    let deg = 180.0 / std::f64::consts::PI;
    let mut ik = Vec::with_capacity(v.ik.len());
    for (i, x) in v.ik.iter().enumerate() {
        let e = err(format!("ik[{i}]"));
        let th = m.inverse_kinematics(x).map_err(&e)?;
        let js = m.joint_state(x).map_err(&e)?;
        // Rows of ∂θ_a/∂(γ, φ): the actuated joints' gradients (what `inverse_jacobian` gives,
        // which refuses γ = 0; here the vanishing φ column is shown and flagged instead).
        let jac = g.actuated.map(|a| [js.grad_x[a][0], js.grad_x[a][1]]);
        ik.push(IkRow {
            gamma_deg: x.gamma.to_degrees(),
            phi_deg: x.phi.to_degrees(),
            theta_deg: th.map(f64::to_degrees),
            joints_deg: js.q.map(f64::to_degrees),
            inverse_jacobian: jac,
            inverse_jacobian_det: jac[0][0] * jac[1][1] - jac[0][1] * jac[1][0],
            pole_singular: x.gamma.to_degrees() < POLE_WARNING_DEG,
        });
    }
    let mut fk = Vec::with_capacity(v.fk.len());
    for (i, (th, start)) in v.fk.iter().enumerate() {
        let x = m.forward_kinematics(*th, *start).map_err(err(format!("fk[{i}]")))?;
        fk.push(FkRow {
            theta_deg: th.map(f64::to_degrees),
            gamma_deg: x.gamma.to_degrees(),
            phi_deg: x.phi.to_degrees(),
        });
    }
    let path = if v.path.is_empty() {
        None
    } else {
        let mut states = Vec::with_capacity(v.path.len());
        for (i, s) in v.path.iter().enumerate() {
            states.push(
                m.path_state(s, &v.springs)
                    .map_err(err(format!("path point {i} (t = {} s)", s.t)))?,
            );
        }
        let home_det = m
            .actuation_jacobian(&crate::kinematics::pantilt::Pointing { gamma: 0.0, phi: 0.0 })
            .map_err(err("home".into()))?
            .determinant()
            .abs();
        let rows = states
            .iter()
            .map(|s| PathRow {
                t: s.sample.t,
                gamma_deg: s.sample.pose.gamma * deg,
                phi_deg: s.sample.pose.phi * deg,
                joints_deg: s.q.map(|q| q * deg),
                joint_rates_deg_per_s: s.q_rate.map(|q| q * deg),
                torque_undamped: s.torque_stiffness,
                torque_damped: s.torque_total(),
            })
            .collect();
        Some(PathOut {
            points: states.len(),
            max_joint_rotation_deg: (0..JOINTS).map(|i| peak(&states, |s| s.q[i], deg)).collect(),
            max_torque_undamped: (0..2).map(|a| peak(&states, |s| s.torque_stiffness[a], 1.0)).collect(),
            max_torque_damped: (0..2).map(|a| peak(&states, |s| s.torque_total()[a], 1.0)).collect(),
            max_torque_damping_share: (0..2).map(|a| peak(&states, |s| s.torque_damping[a], 1.0)).collect(),
            min_gamma_deg: states
                .iter()
                .map(|s| s.sample.pose.gamma * deg)
                .fold(f64::INFINITY, f64::min),
            min_actuation_det_ratio: states
                .iter()
                .map(|s| s.det_actuation.abs() / home_det)
                .fold(f64::INFINITY, f64::min),
            rows,
        })
    };
    Ok(PanTiltResult {
        geometry: GeometryOut {
            theta0_deg: v.spec.theta0_deg,
            delta_deg: v.spec.delta_deg,
            beta_deg: m.beta() * deg,
            azimuths_deg: v.spec.azimuths_deg,
            rr_limb: v.spec.rr_limb,
            actuated: v.spec.actuated,
            joints: joint_descriptions(m),
        },
        stiffness_per_deg: v.springs.stiffness.map(|k| k / deg),
        damping_per_deg: v.springs.damping.map(|d| d / deg),
        ik,
        fk,
        path,
        model: vec![
            "pseudo-rigid-body model: every flexure hinge an ideal revolute joint at the notch centre with a linear torsional spring K and a viscous damper D, rigid links (Yu et al. (2016) §3–4)",
            "quasi-static actuation torques by virtual work (no link inertia, no gravity); joint rotations measured from the unstressed home pose",
        ],
    })
}

/// Warnings that depend on the result: the γ = 0 singularity of the (γ, φ) inverse Jacobian
/// and closeness to an actuation singularity.
pub fn warnings(r: &PanTiltResult) -> Vec<String> {
    let mut w = Vec::new();
    let near_pole: Vec<String> =
        r.ik.iter()
            .enumerate()
            .filter(|(_, q)| q.pole_singular)
            .map(|(i, _)| format!("ik[{i}]"))
            .collect();
    if !near_pole.is_empty() {
        w.push(format!(
            "{} within {POLE_WARNING_DEG}° of γ = 0, where the (γ, φ) inverse Jacobian is singular (φ undefined): its determinant there is (nearly) zero and `pole_singular` is set (joint angles and torques are unaffected)",
            near_pole.join(", ")
        ));
    }
    if let Some(p) = &r.path {
        if p.min_gamma_deg < POLE_WARNING_DEG {
            w.push(format!(
                "the path comes within {:.4}° of γ = 0, where the (γ, φ) inverse Jacobian is singular (φ undefined); joint angles, rates and torques are computed in regular coordinates and stay valid, but a prescribed φ(t) there means a fast spin of the pointing direction",
                p.min_gamma_deg
            ));
        }
        if p.min_actuation_det_ratio < NEAR_SINGULAR_FRACTION {
            w.push(format!(
                "the path approaches an actuation singularity: |det ∂θ_a/∂(r₇ₓ, r₇ᵧ)| drops to {:.3} of its home value; torques grow without bound there",
                p.min_actuation_det_ratio
            ));
        }
    }
    w
}
