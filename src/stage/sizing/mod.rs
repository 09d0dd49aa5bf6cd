//! The stage design loop of Ruiz et al. (2019) §5 (Table 1, Fig. 11): responses of a design, Table-1
//! sensitivities, and requirement-driven sizing.
//!
//! Design parameters (mm): `t_rev`, `R_rev` (circular revolute notch), `t_sph`, `R_sph`, `l_sph`
//! (turned spherical neck). Responses:
//! * η — structural stiffness: total actuator force per mm of pure-z stroke, N/mm;
//! * d — platform Δz reached when the peak hinge stress reaches the allowable (pure z), mm;
//! * T = σ_sph,max / σ_rev,max.
//!
//! Requirements (Ruiz et al. 2019, §4): d ≥ z_travel, T ∈ [T_lo, T_hi], and each hinge able to
//! reach the joint rotations of the kinematic requirement sweep (revolute Δα, spherical βm, βn,
//! βl over z = ±z_travel, ψ, θ = ±tilt) below the allowable stress. With a [`FatigueLimit`]
//! (a `fatigue` block), a fourth response d_f — the platform Δz at which the first hinge reaches
//! fatigue utilisation 1 — and the requirement d_f ≥ z_travel.

mod optimise;
mod problem;
mod sensitivity;

pub use optimise::{constraints, optimise, requirements, Constraint, DesignOutcome, HistoryEntry, Requirements};
pub use problem::{StageProblem, FATIGUE_RESPONSE, RESPONSES};
pub use sensitivity::{bin, sensitivity, Bins, SensitivityRow};

use crate::fem::SolverCache;
use crate::hinge::HingeSpec;
use crate::kinematics::{workspace, PoseBox};
use crate::stage::{Drive, StageDesign, StageError, StageResponse, ValidStage};
use serde::Serialize;
use std::f64::consts::PI;

/// The five design parameters in Table-1 order.
pub const PARAMETERS: [&str; 5] = ["t_rev", "R_rev", "t_sph", "R_sph", "l_sph"];

/// Values of the five parameters, mm, in [`PARAMETERS`] order.
pub type Params = [f64; 5];

/// Reads the parameters of a design (circular notch + spherical neck only).
pub fn params_of(d: &StageDesign) -> Result<Params, String> {
    let (t_rev, r_rev) = match d.revolute {
        HingeSpec::CircularNotch { r, t, .. } => (t, r),
        _ => return Err("the design loop varies a circular_notch revolute hinge".into()),
    };
    let (t_sph, r_sph, l_sph) = match d.spherical {
        HingeSpec::SphericalNeck { l, t, r, .. } => (t, r, l),
        _ => return Err("the design loop varies a spherical_neck spherical hinge".into()),
    };
    Ok([t_rev, r_rev, t_sph, r_sph, l_sph])
}

/// The design with its hinge parameters replaced by `p`.
pub fn with_params(d: &StageDesign, p: &Params) -> StageDesign {
    let mut out = d.clone();
    if let HingeSpec::CircularNotch { r, t, .. } = &mut out.revolute {
        *t = p[0];
        *r = p[1];
    }
    if let HingeSpec::SphericalNeck { t, r, l, .. } = &mut out.spherical {
        *t = p[2];
        *r = p[3];
        *l = p[4];
    }
    out
}

/// Joint rotations the hinges must reach (from the kinematic requirement sweep), rad.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct RotationDemand {
    /// Largest |Δα| of the revolute joints, rad.
    pub revolute: f64,
    /// Largest |βm|, rad.
    pub spherical_m: f64,
    /// Largest |βn|, rad.
    pub spherical_n: f64,
    /// Largest |βl|, rad.
    pub spherical_l: f64,
}

/// Sweeps the rigid-body kinematics over z = ±z_travel, ψ, θ = ±tilt (rad) for the rotations
/// the hinges must reach.
pub fn rotation_demand(d: &StageDesign, z_travel: f64, tilt: f64) -> Result<RotationDemand, StageError> {
    let bx = PoseBox {
        z: [-z_travel, z_travel],
        psi: [-tilt, tilt],
        theta: [-tilt, tilt],
        steps: 5,
    };
    let w = workspace::sweep(&d.prs, &bx).map_err(|e| StageError::Geometry {
        field: "L".into(),
        message: e.to_string(),
    })?;
    let m = |r: [f64; 2]| r[0].abs().max(r[1].abs());
    Ok(RotationDemand {
        revolute: m(w.revolute_delta),
        spherical_m: m(w.spherical_m),
        spherical_n: m(w.spherical_n),
        spherical_l: m(w.spherical_l),
    })
}

/// The hinges' fatigue, handed in from above the stage layer (the stress-life chain belongs to
/// the cases' `fatigue` block): the largest hinge fatigue utilisation of the validated design
/// `v` under the response `unit`, the peak of the load cycle. The stage is linear, so the
/// utilisation is proportional to the load and 1 / it scales `unit` to the fatigue limit.
pub trait FatigueLimit: Sync {
    /// Largest hinge fatigue utilisation under `unit` (dimensionless).
    fn max_utilisation(&self, v: &ValidStage, unit: &StageResponse) -> f64;
}

/// Responses of one design (pure-z motion, linear).
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct Responses {
    /// Structural stiffness η: total actuator force per mm of pure-z stroke, N/mm.
    pub eta: f64,
    /// Platform Δz reached at the allowable stress, mm.
    pub z_at_allowable: f64,
    /// T = σ_sph,max / σ_rev,max.
    #[serde(rename = "T")]
    pub t_ratio: f64,
    /// Peak revolute-hinge stress per mm of platform z, MPa/mm.
    pub revolute_stress_per_mm: f64,
    /// Peak spherical-hinge stress per mm of platform z, MPa/mm.
    pub spherical_stress_per_mm: f64,
    /// Revolute-notch stress at the demanded rotation Δα, MPa.
    pub revolute_stress_at_demand: f64,
    /// Spherical-neck von Mises stress at the demanded βm, βn, βl (taken together), MPa.
    pub spherical_stress_at_demand: f64,
    /// d_f: platform Δz (pure z, the peak of the load cycle) at which the first hinge reaches
    /// fatigue utilisation 1, mm; only with a [`FatigueLimit`].
    #[serde(skip_serializing_if = "Option::is_none")]
    pub z_at_fatigue_limit: Option<f64>,
}

/// Evaluates a design: one linear solve of a unit pure-z stroke set.
pub fn evaluate(d: &StageDesign, demand: &RotationDemand) -> Result<Responses, StageError> {
    evaluate_with(&mut SolverCache::new(), d, demand, None)
}

/// [`evaluate`] with the caller's solver cache (designs of one loop share the topology), and
/// d_f when `fatigue` is given.
pub fn evaluate_with(
    cache: &mut SolverCache,
    d: &StageDesign,
    demand: &RotationDemand,
    fatigue: Option<&dyn FatigueLimit>,
) -> Result<Responses, StageError> {
    let valid = d.validate()?;
    let stage = valid.build();
    let j = d
        .prs
        .actuation_jacobian(0.0, 0.0, 0.0)
        .map_err(|e| StageError::Geometry {
            field: "L".into(),
            message: e.to_string(),
        })?;
    let s = [j[(0, 0)], j[(1, 0)], j[(2, 0)]];
    let r = stage
        .solve_with(cache, &[("unit_z".to_string(), Drive::Strokes(s))])?
        .remove(0);
    let z = r.platform.z;
    let s_mean = (s[0] + s[1] + s[2]) / 3.0;
    let eta = r.forces.iter().sum::<f64>() / s_mean;
    let rev = r.revolute_stress.iter().cloned().fold(0.0, f64::max) / z.abs();
    let sph = r.spherical_stress.iter().cloned().fold(0.0, f64::max) / z.abs();
    let allowable = d.material.allowable;
    let rh = &stage.revolute.stiffness;
    let sh = &stage.spherical.stiffness;
    let rev_demand = rh.stress_per_moment * rh.k_bend * demand.revolute;
    let t_sph = match d.spherical {
        HingeSpec::SphericalNeck { t, .. } => t,
        _ => 1.0,
    };
    let sigma_b = sh.stress_per_moment * sh.k_bend * demand.spherical_m.hypot(demand.spherical_n);
    let tau = sh.k_torsion * demand.spherical_l * 16.0 / (PI * t_sph.powi(3));
    Ok(Responses {
        eta,
        z_at_allowable: allowable / rev.max(sph),
        t_ratio: sph / rev,
        revolute_stress_per_mm: rev,
        spherical_stress_per_mm: sph,
        revolute_stress_at_demand: rev_demand,
        spherical_stress_at_demand: (sigma_b * sigma_b + 3.0 * tau * tau).sqrt(),
        z_at_fatigue_limit: fatigue.map(|f| z.abs() / f.max_utilisation(&valid, &r.response())),
    })
}
