//! The `hinge` analysis: stiffness, compliance, stress and closed forms of one flexure hinge.

use super::Report;
use crate::case::hinge::{hinge_error, HingeCase};
use crate::case::CaseError;
use crate::fem::{Element, FlexElement, LoadCase, Model, Support};
use crate::hinge::{characterise, HingeResult};
use crate::material::Material;
use crate::report::markdown::{sig, Table};
use serde::Serialize;

pub mod fatigue;
pub mod pivot;
mod units;

/// Result of the `hinge` analysis: the characterisation, plus the large-rotation curve when
/// the case asks for it.
#[derive(Debug, Clone, Serialize)]
pub struct HingeOut {
    #[serde(flatten)]
    pub result: HingeResult,
    /// Large-rotation response (`"nonlinear": true` only).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub large_rotation: Option<LargeRotation>,
    /// Pivot shift along the large-rotation curve (`"nonlinear": true` only).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub pivot_shift: Option<pivot::PivotShift>,
    /// Identified joint damping (`"damping"` only).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub damping: Option<DampingOut>,
    /// Fatigue assessment (`"fatigue"` only).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub fatigue: Option<fatigue::FatigueOut>,
}

/// The joint damping identified from a simulated step response (Yu, Lu and Hao (2016), §4.1).
#[derive(Debug, Clone, Serialize)]
pub struct DampingOut {
    /// How it was found.
    pub method: String,
    /// Rotational stiffness K about the compliant axis (statics), N·mm/rad.
    pub k_nmm_per_rad: f64,
    /// The same, N·mm/°.
    pub k_nmm_per_deg: f64,
    /// Identified joint damping D, N·mm·s/rad.
    pub d_nmm_s_per_rad: f64,
    /// The same, N·mm·s/°.
    pub d_nmm_s_per_deg: f64,
    /// D/K, s (equals the stiffness-proportional material damping when the response is
    /// dominated by the compliant-axis rotation).
    pub d_over_k_s: f64,
    /// Identified rotary inertia J, tonne·mm² (0: first-order fit).
    pub j_t_mm2: f64,
    /// RMS of simulated − fitted rotation, relative to the static rotation.
    pub fit_residual: f64,
    /// Time step, s, and number of steps.
    pub dt_s: f64,
    pub steps: usize,
    /// (time s, simulated rotation °, fitted rotation °) for the files of `--out`.
    #[serde(skip)]
    pub history: Vec<[f64; 3]>,
}

/// One point of the large-rotation curve.
#[derive(Debug, Clone, Serialize)]
pub struct LargeRotationPoint {
    /// Transverse end force, N.
    pub force: f64,
    /// Moment about the compliant axis at the notch centre, deformed configuration, N·mm.
    pub moment: f64,
    /// Compliant-axis rotation of the loaded blank end face, degrees.
    pub rotation_deg: f64,
    /// The linear FE rotation for the same force, degrees.
    pub linear_rotation_deg: f64,
    /// Peak von Mises stress in the notch, MPa.
    pub max_stress: f64,
}

/// Moment–rotation curve of the hinge in its blank at large rotation.
#[derive(Debug, Clone, Serialize)]
pub struct LargeRotation {
    /// How the hinge is loaded.
    pub load: String,
    /// Points, increasing force, up to (just past) the allowable stress.
    pub points: Vec<LargeRotationPoint>,
    /// Rotation at the allowable stress (linear interpolation between points), degrees.
    pub rotation_at_allowable_deg: Option<f64>,
    /// The same from the linear FE model, degrees.
    pub linear_rotation_at_allowable_deg: Option<f64>,
}

/// The warning of the hinge's rigid end faces where their torsion term is extrapolated
/// ([`crate::hinge::calibration::end_face_warning`]), prefixed `hinge: `.
pub fn end_face_warnings(case: &HingeCase, r: &HingeOut) -> Vec<String> {
    // Most hinges' end faces change nothing (checked without a solve, nor the material).
    let p = match case.hinge.profile().map(|p| p.with_rigid_end_faces()) {
        Ok(p) if crate::hinge::torsion::end_face_acts(&p) => p,
        _ => return Vec::new(),
    };
    let Ok(m) = case.validate() else {
        return Vec::new();
    };
    crate::hinge::calibration::end_face_warning(&p, r.result.hinge.k_torsion, &m)
        .map(|w| format!("hinge: {w}"))
        .into_iter()
        .collect()
}

/// Characterises the hinge of the case.
pub fn solve(case: &HingeCase) -> Result<HingeOut, super::RunError> {
    let m = case.validate()?;
    let result = characterise(&case.hinge, &m).map_err(|e| {
        let ce: CaseError = hinge_error(&e, "hinge", "material");
        super::RunError::Case(ce)
    })?;
    let (large_rotation, pivot_shift) = match (case.nonlinear, case.steps) {
        (true, steps) => {
            let (lr, ps) = large_rotation(case, &m, &result, steps.unwrap_or(20))?;
            (Some(lr), Some(ps))
        }
        _ => (None, None),
    };
    let damping = match &case.damping {
        Some(spec) => {
            let run = spec.run()?;
            let profile = case
                .hinge
                .profile()
                .map_err(|e| super::RunError::Case(hinge_error(&e, "hinge", "material")))?;
            let jd = crate::hinge::damping::identify_damping(&profile, &m, &run)
                .map_err(|e| super::RunError::Analysis(super::AnalysisError::new("hinge damping", e.to_string())))?;
            let deg = std::f64::consts::PI / 180.0;
            Some(DampingOut {
                method: "step moment about the compliant axis on the hinge in its blank (16-segment flexibility chain, lumped mass), Newmark average acceleration, Rayleigh material damping; least-squares fit of J θ(t) + D ∫θ + K ∬θ = M t²/2 with K from statics".into(),
                k_nmm_per_rad: jd.k,
                k_nmm_per_deg: jd.k * deg,
                d_nmm_s_per_rad: jd.d,
                d_nmm_s_per_deg: jd.d * deg,
                d_over_k_s: jd.d / jd.k,
                j_t_mm2: jd.j,
                fit_residual: jd.residual,
                dt_s: jd.dt,
                steps: run.steps,
                history: (0..jd.time.len())
                    .map(|i| [jd.time[i], jd.rotation[i] / deg, jd.fitted[i] / deg])
                    .collect(),
            })
        }
        None => None,
    };
    let fatigue = match &case.fatigue {
        Some(spec) => {
            let f = spec.validate("material", &m)?;
            let profile = case
                .hinge
                .profile()
                .map_err(|e| super::RunError::Case(hinge_error(&e, "hinge", "material")))?;
            Some(fatigue::assess(spec, &m, &f, &profile, &result))
        }
        None => None,
    };
    Ok(HingeOut {
        result,
        large_rotation,
        pivot_shift,
        damping,
        fatigue,
    })
}

/// `hinge_step_response.csv` and `.svg` of an identified damping.
pub fn damping_files(d: &DampingOut) -> super::Files {
    let mut csv = String::from("time_s,rotation_deg,fitted_deg\n");
    for h in &d.history {
        csv += &format!("{},{},{}\n", h[0], h[1], h[2]);
    }
    let sim: Vec<(f64, f64)> = d.history.iter().map(|h| (h[0], h[1])).collect();
    let fit: Vec<(f64, f64)> = d.history.iter().map(|h| (h[0], h[2])).collect();
    let svg = crate::report::svg::lines(
        &format!("Hinge step response: D = {} N·mm·s/°", sig(d.d_nmm_s_per_deg, 4)),
        "time (s)",
        "rotation (°)",
        &[("FE (transient)", &sim), ("fitted second-order model", &fit)],
    );
    vec![
        ("hinge_step_response.csv".into(), csv.into_bytes()),
        ("hinge_step_response.svg".into(), svg.into_bytes()),
    ]
}

/// Markdown section of an identified damping.
pub fn damping_report(d: &DampingOut) -> String {
    let mut t = Table::new(&["quantity", "value", "unit"]);
    for (name, v, unit) in [
        ("K (statics)", d.k_nmm_per_deg, "N·mm/°"),
        ("D (fitted)", d.d_nmm_s_per_deg, "N·mm·s/°"),
        ("D/K", d.d_over_k_s, "s"),
        ("J (fitted)", d.j_t_mm2, "t·mm²"),
        ("fit residual (RMS / static rotation)", d.fit_residual, "-"),
    ] {
        t.row(vec![name.into(), sig(v, 5), unit.into()]);
    }
    format!("\n## Joint damping\n\nMethod: {}.\n\n{}", d.method, t.render())
}

/// The hinge in its blank as a chain of co-rotational flexibility elements along x (blank,
/// 16 notch segments, blank; compliances of the sub-intervals), clamped at x = −half-length,
/// loaded at the other end face by a force along z fixed in direction (bending about the
/// compliant axis y). Each force level is solved from the undeformed state in `steps` steps.
fn large_rotation(
    case: &HingeCase,
    m: &Material,
    r: &HingeResult,
    steps: usize,
) -> Result<(LargeRotation, pivot::PivotShift), super::RunError> {
    let err = |e: crate::fem::FemError| super::RunError::Analysis(super::AnalysisError::new("hinge", e.to_string()));
    let profile = case
        .hinge
        .profile()
        .map_err(|e| super::RunError::Case(hinge_error(&e, "hinge", "material")))?;
    let n = 16;
    let (xs, chain) = crate::hinge::flex_chain(&profile, m, n);
    let mut model = Model::new();
    for &x in &xs {
        model.add_node([x, 0.0, 0.0]);
    }
    let first_notch = usize::from(profile.blank > 0.0);
    for (i, compliance) in chain.into_iter().enumerate() {
        model.add_element(Element::Flex(FlexElement {
            nodes: [i, i + 1],
            compliance,
            up: [0.0, 0.0, 1.0],
        }));
    }
    let last_notch = first_notch + n - 1;
    let tip = xs.len() - 1;
    let centre = first_notch + n / 2;
    model.supports.push(Support::clamp(0));
    let neck = matches!(profile.contour, crate::hinge::Contour::SphericalNeck { .. });
    let kt = r.stress_concentration;
    let peak = |fe: &crate::fem::CaseResult| {
        let sf = [
            fe.elements[first_notch].section_forces[0],
            fe.elements[last_notch].section_forces[1],
        ];
        crate::hinge::hinge_peak_stress(&profile, m.nu, kt, &sf, neck)
    };
    // Linear response to a unit force: rotation and stress per newton.
    model.load_cases = vec![LoadCase::new("unit").force(tip, [0.0, 0.0, 1.0, 0.0, 0.0, 0.0])];
    let lin = crate::fem::solve_static_with(&model, crate::fem::solve::Parallelism::Sequential).map_err(err)?;
    let lin = &lin.load_cases[0];
    let rot1 = lin.displacements[tip][4];
    let sig1 = peak(lin);
    if !(sig1 > 0.0 && rot1.is_finite()) {
        return Err(err(crate::fem::FemError::BadInput(
            "hinge: no bending stress under a transverse force".into(),
        )));
    }
    let f_allow = m.allowable / sig1;
    let levels: Vec<f64> = (1..=12).map(|k| 1.2 * f_allow * k as f64 / 12.0).collect();
    model.load_cases = levels
        .iter()
        .enumerate()
        .map(|(k, f)| LoadCase::new(format!("F{k}")).force(tip, [0.0, 0.0, *f, 0.0, 0.0, 0.0]))
        .collect();
    let opts = crate::fem::NonlinearOptions {
        steps,
        ..Default::default()
    };
    let nl = crate::fem::solve_nonlinear(&model, &opts).map_err(err)?;
    let points: Vec<LargeRotationPoint> = nl
        .load_cases
        .iter()
        .zip(&levels)
        .map(|(c, &f)| {
            let d = &c.fe.displacements;
            let dx = (xs[tip] + d[tip][0]) - (xs[centre] + d[centre][0]);
            LargeRotationPoint {
                force: f,
                moment: f * dx.abs(),
                rotation_deg: d[tip][4].abs().to_degrees(),
                linear_rotation_deg: (f * rot1).abs().to_degrees(),
                max_stress: peak(&c.fe),
            }
        })
        .collect();
    let at_allowable = |get: &dyn Fn(&LargeRotationPoint) -> f64, stress: &dyn Fn(&LargeRotationPoint) -> f64| {
        let mut prev: Option<&LargeRotationPoint> = None;
        for p in &points {
            if stress(p) >= m.allowable {
                return Some(match prev {
                    None => get(p) * m.allowable / stress(p),
                    Some(q) => {
                        let t = (m.allowable - stress(q)) / (stress(p) - stress(q));
                        get(q) + t * (get(p) - get(q))
                    }
                });
            }
            prev = Some(p);
        }
        None
    };
    let mut poses = vec![([xs[tip], 0.0, 0.0], [0.0; 3])];
    for c in &nl.load_cases {
        let d = &c.fe.displacements[tip];
        poses.push(([xs[tip] + d[0], d[1], d[2]], [d[3], d[4], d[5]]));
    }
    let pivot = pivot::pivot_shift(xs[centre], &poses);
    let rotation_at_allowable_deg = at_allowable(&|p| p.rotation_deg, &|p| p.max_stress);
    let linear_rotation_at_allowable_deg = at_allowable(&|p| p.linear_rotation_deg, &|p| p.force * sig1);
    Ok((LargeRotation {
        load: format!(
            "transverse end force (fixed direction) at the blank end face, {:.3} mm from the notch centre; clamped opposite face; 16 co-rotational flexibility elements over the notch",
            profile.half_length()
        ),
        points,
        rotation_at_allowable_deg,
        linear_rotation_at_allowable_deg,
    }, pivot))
}

/// Markdown/CSV views.
pub fn report(r: &HingeResult) -> Report {
    let mut md = String::from("# Flexure hinge\n\n");
    let mut t = Table::new(&["quantity", "hinge in blank", "notch alone", "unit"]);
    let h = &r.hinge;
    let n = &r.notch_only;
    for (name, a, b, unit) in [
        ("k_bend (compliant axis)", h.k_bend, n.k_bend, "N·mm/rad"),
        ("k_bend_off", h.k_bend_off, n.k_bend_off, "N·mm/rad"),
        ("k_torsion (warping restrained)", h.k_torsion, n.k_torsion, "N·mm/rad"),
        (
            "k_torsion (Saint-Venant)",
            h.k_torsion_saint_venant,
            n.k_torsion_saint_venant,
            "N·mm/rad",
        ),
        ("k_axial", h.k_axial, n.k_axial, "N/mm"),
        (
            "stress per moment",
            h.stress_per_moment,
            n.stress_per_moment,
            "MPa/(N·mm)",
        ),
        (
            "max rotation at allowable",
            h.max_rotation_deg,
            n.max_rotation_deg,
            "deg",
        ),
    ] {
        t.row(vec![name.into(), sig(a, 5), sig(b, 5), unit.into()]);
    }
    md += &t.render();
    md += &format!(
        "\nStress-concentration factor applied: {:.4}.\n\n## Closed forms (notch alone, compliant axis)\n\n",
        r.stress_concentration
    );
    let mut c = Table::new(&["formula", "k_bend (N·mm/rad)", "vs flexfem notch"]);
    for (k, v) in &r.closed_form {
        c.row(vec![
            k.to_string(),
            sig(*v, 5),
            format!("{:+.2}%", (v / n.k_bend - 1.0) * 100.0),
        ]);
    }
    md += &c.render();
    md += "\n## Model\n\n";
    for note in &r.model {
        md += &format!("- {note}\n");
    }
    let csv = format!(
        "k_bend_Nmm_per_rad,k_bend_off_Nmm_per_rad,k_torsion_Nmm_per_rad,k_axial_N_per_mm,stress_per_moment_MPa_per_Nmm,max_rotation_deg\n{},{},{},{},{},{}\n",
        h.k_bend, h.k_bend_off, h.k_torsion, h.k_axial, h.stress_per_moment, h.max_rotation_deg
    );
    Report { markdown: md, csv }
}

/// Markdown section of the large-rotation curve.
pub fn large_rotation_report(lr: &LargeRotation) -> String {
    let mut md = format!("\n## Large rotation\n\nLoad: {}.\n\n", lr.load);
    let mut t = Table::columns("F (N) | M centre (N·mm) | θ nonlinear (°) | θ linear (°) | σ_max (MPa)");
    for p in &lr.points {
        t.row(vec![
            sig(p.force, 5),
            sig(p.moment, 5),
            format!("{:.4}", p.rotation_deg),
            format!("{:.4}", p.linear_rotation_deg),
            format!("{:.1}", p.max_stress),
        ]);
    }
    md += &t.render();
    if let (Some(a), Some(b)) = (lr.rotation_at_allowable_deg, lr.linear_rotation_at_allowable_deg) {
        md += &format!("\nRotation at the allowable stress: {a:.4}° (linear FE {b:.4}°).\n");
    }
    md
}
