//! The `pantilt` analysis: PRBM kinematics and quasi-static actuation torques of the 8R
//! compliant parallel pan-tilt of J. Yu, D. Lu and G. Hao, "Design and analysis of a compliant
//! parallel pan-tilt platform", Meccanica (2016).
//! Results in degrees, N·mm and s.

use super::kind::{Analysis, Ctx};
use super::{AnalysisError, Report, RunError};
use crate::case::pantilt::{PanTiltCase, ValidPanTilt};
use crate::case::CaseError;
use crate::kinematics::pantilt::{PanTilt, PanTiltError, PathState, JOINTS};
use crate::report::markdown::{sig, Table};
use crate::report::svg;
use serde::Serialize;

/// Pitch below which the (γ, φ) inverse Jacobian is reported as singular (φ undefined at γ = 0),
/// degrees.
pub const POLE_WARNING_DEG: f64 = 1.0;

/// Fraction of the home actuation-Jacobian determinant below which a path point is reported as
/// close to an actuation singularity.
pub const NEAR_SINGULAR_FRACTION: f64 = 0.1;

/// Names of the eight joints, in result order.
pub const JOINT_NAMES: [&str; JOINTS] = ["J1", "J2", "J3", "J4", "J5", "J6", "J7", "J8"];

/// Derived geometry, echoed.
#[derive(Debug, Clone, Serialize)]
pub struct GeometryOut {
    /// θ₀, degrees.
    pub theta0_deg: f64,
    /// δ, degrees.
    pub delta_deg: f64,
    /// Home elevation β of the middle joint axes, degrees.
    pub beta_deg: f64,
    /// Limb azimuths ε, degrees.
    pub azimuths_deg: [f64; 3],
    /// The RR limb (1-based).
    pub rr_limb: usize,
    /// The actuated limbs (1-based); their bottom joints are the actuators.
    pub actuated: [usize; 2],
    /// What each of J1–J8 is (limb and position).
    pub joints: Vec<String>,
}

/// One IK answer.
#[derive(Debug, Clone, Serialize)]
pub struct IkRow {
    /// Pitch γ, degrees.
    pub gamma_deg: f64,
    /// Phase φ, degrees.
    pub phi_deg: f64,
    /// Actuated joint rotations θ from home, degrees.
    pub theta_deg: [f64; 2],
    /// All eight joint rotations from home, degrees.
    pub joints_deg: [f64; JOINTS],
    /// The inverse Jacobian ∂θ/∂(γ, φ) (deg/deg; Yu et al. Eq. 17), rows per actuator. Its φ
    /// column vanishes at γ = 0 (φ undefined there).
    pub inverse_jacobian: [[f64; 2]; 2],
    /// Its determinant (∝ sin γ).
    pub inverse_jacobian_det: f64,
    /// True within `POLE_WARNING_DEG` of γ = 0, where the inverse Jacobian is singular.
    pub pole_singular: bool,
}

/// One FK answer.
#[derive(Debug, Clone, Serialize)]
pub struct FkRow {
    /// Actuated joint rotations, degrees.
    pub theta_deg: [f64; 2],
    /// Pitch γ, degrees.
    pub gamma_deg: f64,
    /// Phase φ, degrees (0 at γ = 0, where it is undefined).
    pub phi_deg: f64,
}

/// One path point.
#[derive(Debug, Clone, Serialize)]
pub struct PathRow {
    /// Time, s.
    pub t: f64,
    /// Pitch γ, degrees.
    pub gamma_deg: f64,
    /// Phase φ, degrees.
    pub phi_deg: f64,
    /// Joint rotations J1–J8 from home, degrees.
    pub joints_deg: [f64; JOINTS],
    /// Joint rates, degrees/s.
    pub joint_rates_deg_per_s: [f64; JOINTS],
    /// Actuator torques with the springs only, N·mm.
    pub torque_undamped: [f64; 2],
    /// Actuator torques with springs and dampers, N·mm.
    pub torque_damped: [f64; 2],
}

/// A maximum of |value| along the path and where it occurs.
#[derive(Debug, Clone, Copy, Serialize)]
pub struct Peak {
    /// Largest |value|.
    pub max_abs: f64,
    /// The signed value there.
    pub value: f64,
    /// Time, s.
    pub t: f64,
    /// Phase φ there, degrees.
    pub phi_deg: f64,
}

/// Path results: maxima and rows.
#[derive(Debug, Clone, Serialize)]
pub struct PathOut {
    /// Number of points.
    pub points: usize,
    /// Largest |rotation| per joint J1–J8, degrees.
    pub max_joint_rotation_deg: Vec<Peak>,
    /// Largest |torque| per actuator, springs only, N·mm.
    pub max_torque_undamped: Vec<Peak>,
    /// Largest |torque| per actuator, springs and dampers, N·mm.
    pub max_torque_damped: Vec<Peak>,
    /// Largest |damped − undamped| torque per actuator (the damper share), N·mm.
    pub max_torque_damping_share: Vec<Peak>,
    /// Smallest pitch on the path, degrees.
    pub min_gamma_deg: f64,
    /// Smallest |det ∂θ_a/∂(r₇ₓ, r₇ᵧ)| on the path relative to its home value.
    pub min_actuation_det_ratio: f64,
    /// Per-point rows.
    pub rows: Vec<PathRow>,
}

/// Result of the `pantilt` analysis.
#[derive(Debug, Clone, Serialize)]
pub struct PanTiltResult {
    /// Geometry.
    pub geometry: GeometryOut,
    /// Joint stiffness K, N·mm/degree, J1–J8.
    pub stiffness_per_deg: [f64; JOINTS],
    /// Joint damping D, N·mm·s/degree, J1–J8.
    pub damping_per_deg: [f64; JOINTS],
    /// IK answers in query order.
    pub ik: Vec<IkRow>,
    /// FK answers in query order.
    pub fk: Vec<FkRow>,
    /// Path results, if a path was given.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub path: Option<PathOut>,
    /// Idealisations of this analysis.
    pub model: Vec<&'static str>,
}

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

/// Markdown and CSV views of the result (the CSV holds the path rows).
pub fn report(r: &PanTiltResult) -> Report {
    let g = &r.geometry;
    let mut md = String::from("# 8R compliant pan-tilt: pseudo-rigid-body model\n\n");
    md += &format!(
        "Geometry: θ₀ = {}°, δ = {}°, β = {}°, limb azimuths {}°, {}°, {}°; RR limb {}; actuated limbs {} and {}.\n\n",
        sig(g.theta0_deg, 6),
        sig(g.delta_deg, 6),
        sig(g.beta_deg, 6),
        sig(g.azimuths_deg[0], 6),
        sig(g.azimuths_deg[1], 6),
        sig(g.azimuths_deg[2], 6),
        g.rr_limb,
        g.actuated[0],
        g.actuated[1]
    );
    let mut t = Table::new(&["Joint", "What", "K (N·mm/°)", "D (N·mm·s/°)"]);
    for (i, (name, what)) in JOINT_NAMES.iter().zip(&g.joints).enumerate() {
        t.row(vec![
            (*name).into(),
            what.clone(),
            sig(r.stiffness_per_deg[i], 6),
            sig(r.damping_per_deg[i], 6),
        ]);
    }
    md += &t.render();
    if !r.ik.is_empty() {
        md += "\n## Inverse kinematics\n\n";
        let mut t = Table::new(&["γ (°)", "φ (°)", "θ₁ (°)", "θ₂ (°)", "det J (γ, φ)"]);
        for q in &r.ik {
            t.row(vec![
                sig(q.gamma_deg, 6),
                sig(q.phi_deg, 6),
                format!("{:.4}", q.theta_deg[0]),
                format!("{:.4}", q.theta_deg[1]),
                if q.pole_singular {
                    format!("{} (singular: γ ≈ 0)", sig(q.inverse_jacobian_det, 3))
                } else {
                    sig(q.inverse_jacobian_det, 5)
                },
            ]);
        }
        md += &t.render();
    }
    if !r.fk.is_empty() {
        md += "\n## Forward kinematics\n\n";
        let mut t = Table::new(&["θ₁ (°)", "θ₂ (°)", "γ (°)", "φ (°)"]);
        for q in &r.fk {
            t.row(vec![
                sig(q.theta_deg[0], 6),
                sig(q.theta_deg[1], 6),
                format!("{:.6}", q.gamma_deg),
                format!("{:.6}", q.phi_deg),
            ]);
        }
        md += &t.render();
    }
    let mut csv = String::from("t_s,gamma_deg,phi_deg");
    for n in JOINT_NAMES {
        csv += &format!(",{n}_deg");
    }
    for n in JOINT_NAMES {
        csv += &format!(",{n}_rate_deg_per_s");
    }
    csv += ",torque1_undamped_Nmm,torque2_undamped_Nmm,torque1_damped_Nmm,torque2_damped_Nmm\n";
    if let Some(p) = &r.path {
        md += &format!("\n## Path ({} points)\n\n", p.points);
        let mut t = Table::new(&["Joint", "largest |rotation| (°)", "at t (s)", "at φ (°)"]);
        for (i, pk) in p.max_joint_rotation_deg.iter().enumerate() {
            t.row(vec![
                JOINT_NAMES[i].into(),
                format!("{:.4}", pk.max_abs),
                sig(pk.t, 6),
                sig(pk.phi_deg, 6),
            ]);
        }
        md += &t.render();
        md += "\n";
        let mut t = Table::columns("Actuator | largest |τ| undamped (N·mm) | largest |τ| damped (N·mm) | largest damper share (N·mm)");
        for a in 0..2 {
            t.row(vec![
                format!("limb {} (J{})", g.actuated[a], g.actuated[a]),
                format!("{:.2}", p.max_torque_undamped[a].max_abs),
                format!("{:.2}", p.max_torque_damped[a].max_abs),
                format!("{:.2}", p.max_torque_damping_share[a].max_abs),
            ]);
        }
        md += &t.render();
        for row in &p.rows {
            let mut line = format!("{},{},{}", row.t, row.gamma_deg, row.phi_deg);
            for v in row.joints_deg.iter().chain(row.joint_rates_deg_per_s.iter()) {
                line += &format!(",{v}");
            }
            for v in row.torque_undamped.iter().chain(row.torque_damped.iter()) {
                line += &format!(",{v}");
            }
            csv += &line;
            csv += "\n";
        }
    }
    Report { markdown: md, csv }
}

/// At most this many points per plotted series (the SVG draws a marker per point).
const PLOT_POINTS: usize = 200;

fn thin(rows: &[PathRow], f: impl Fn(&PathRow) -> f64) -> Vec<(f64, f64)> {
    let step = rows.len().div_ceil(PLOT_POINTS).max(1);
    rows.iter().step_by(step).map(|r| (r.t, f(r))).collect()
}

/// SVG plots of the path histories: joint rotations (bottom, middle, top joints) and actuator
/// torques against time. Empty without a path.
pub fn plots(r: &PanTiltResult) -> Vec<(String, Vec<u8>)> {
    let Some(p) = &r.path else {
        return Vec::new();
    };
    let mut files = Vec::new();
    for (name, title, idx) in [
        (
            "pantilt_bottom_joints.svg",
            "Bottom joint rotations",
            &[0usize, 1, 2][..],
        ),
        ("pantilt_middle_joints.svg", "Middle joint rotations", &[3, 4, 5][..]),
        ("pantilt_top_joints.svg", "Top joint rotations", &[6, 7][..]),
    ] {
        let series: Vec<(String, Vec<(f64, f64)>)> = idx
            .iter()
            .map(|&i| (JOINT_NAMES[i].to_string(), thin(&p.rows, |row| row.joints_deg[i])))
            .collect();
        let refs: Vec<(&str, &[(f64, f64)])> = series.iter().map(|(n, s)| (n.as_str(), s.as_slice())).collect();
        files.push((
            name.to_string(),
            svg::scatter(title, "time (s)", "rotation (°)", &refs).into_bytes(),
        ));
    }
    let a = r.geometry.actuated;
    let series: Vec<(String, Vec<(f64, f64)>)> = vec![
        (
            format!("J{} undamped", a[0]),
            thin(&p.rows, |row| row.torque_undamped[0]),
        ),
        (
            format!("J{} undamped", a[1]),
            thin(&p.rows, |row| row.torque_undamped[1]),
        ),
        (format!("J{} damped", a[0]), thin(&p.rows, |row| row.torque_damped[0])),
        (format!("J{} damped", a[1]), thin(&p.rows, |row| row.torque_damped[1])),
    ];
    let refs: Vec<(&str, &[(f64, f64)])> = series.iter().map(|(n, s)| (n.as_str(), s.as_slice())).collect();
    files.push((
        "pantilt_torques.svg".to_string(),
        svg::scatter("Actuator torques", "time (s)", "torque (N·mm)", &refs).into_bytes(),
    ));
    files
}

/// `pantilt`: the 8R pan-tilt PRBM.
pub struct PanTiltKind;

impl Analysis for PanTiltKind {
    type Case = PanTiltCase;
    type Result = PanTiltResult;

    fn check(case: &Self::Case) -> Result<(), CaseError> {
        case.validate().map(|_| ())
    }
    fn run(case: &Self::Case, ctx: &mut Ctx) -> Result<Self::Result, RunError> {
        let r = solve(&case.validate()?)?;
        if ctx.with_files {
            ctx.files.extend(plots(&r));
        }
        Ok(r)
    }
    fn report(r: &Self::Result) -> Report {
        report(r)
    }
    fn result_warnings(_case: &Self::Case, r: &Self::Result) -> Vec<String> {
        warnings(r)
    }
}
