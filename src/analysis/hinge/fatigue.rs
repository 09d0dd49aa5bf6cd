//! High-cycle fatigue of a `hinge` under a cyclic rotation about its compliant axis (stress-life
//! approach of Budynas & Nisbett, Shigley's Mechanical Engineering Design, 10th ed. (2015), ch. 6).

use crate::case::fatigue::{FatigueSpec, MeanStressMethod};
use crate::fatigue::{notch_sensitivity, size_factor, surface_factor_machined, MaterialFatigue};
use crate::hinge::{Contour, HingeResult, Profile};
use crate::material::Material;
use crate::report::markdown::{sig, Table};
use serde::Serialize;

/// Fatigue assessment of the hinge (`"fatigue"` only).
#[derive(Debug, Clone, Serialize)]
pub struct FatigueOut {
    /// Fatigue utilisation at the required cycles: σ_a/S_f(N) + σ_m/S_ut (Goodman) or
    /// σ_m/S_y (Soderberg); ≤ 1 passes.
    pub fatigue_utilisation: f64,
    /// Predicted life, cycles (absent when `infinite_life`).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub life_cycles: Option<f64>,
    /// The stroke is within the endurance limit (no `life_cycles`).
    pub infinite_life: bool,
    /// Alternating rotation about the compliant axis at which the utilisation at infinite
    /// life is 1, given the mean rotation, degrees (0: the mean alone exhausts it).
    pub stroke_infinite_life: f64,
    /// Elastic stress-concentration factor K_t of the notch (the hinge result's).
    pub kt: f64,
    /// Peterson's notch sensitivity q = 1/(1 + a/r).
    pub notch_sensitivity: f64,
    /// Fatigue notch factor K_f = 1 + q (K_t − 1).
    pub kf: f64,
    /// Notch root radius r used for q, mm (`null`: no notch, leaf hinge).
    pub notch_radius_mm: Option<f64>,
    /// Marin surface (machined) and size factors k_a, k_b.
    pub marin_surface: f64,
    pub marin_size: f64,
    /// Corrected endurance limit S_e = k_a k_b S_e', MPa.
    pub endurance_corrected: f64,
    /// Fatigue stress per radian of compliant-axis rotation at the notch root, K_f × nominal, MPa/rad.
    pub stress_per_rad: f64,
    /// Alternating and mean fatigue stresses of the case, MPa.
    pub stress_alternating: f64,
    pub stress_mean: f64,
    /// What was applied.
    pub method: String,
}

/// Notch root radius of the contour for Peterson's q, mm (`None`: no notch).
pub fn notch_radius(c: &Contour) -> Option<f64> {
    match *c {
        Contour::Circular { r, .. } | Contour::CornerFilleted { r, .. } | Contour::SphericalNeck { r, .. } => Some(r),
        // Curvature radius of the ellipse at its vertex: a_x²/a_y.
        Contour::Elliptical { ax, ay, .. } => Some(ax * ax / ay),
        Contour::Leaf { .. } => None,
    }
}

/// Equivalent diameter d_e of the waist in non-rotating bending, mm (Shigley 10th ed.
/// eqs. (6-24): round, 0.370 d; (6-25): rectangle, 0.808 √(h b)).
fn equivalent_diameter(p: &Profile) -> f64 {
    match p.contour {
        Contour::SphericalNeck { t, .. } => 0.370 * t,
        _ => 0.808 * (p.thickness(0.0) * p.w).sqrt(),
    }
}

/// Assesses the case's stroke on the hinge characterised in `r`.
pub fn assess(spec: &FatigueSpec, m: &Material, f: &MaterialFatigue, p: &Profile, r: &HingeResult) -> FatigueOut {
    let kt = r.stress_concentration;
    let radius = notch_radius(&p.contour);
    let q = radius.map_or(1.0, |rr| notch_sensitivity(f.peterson_a(), rr));
    let kf = 1.0 + q * (kt - 1.0);
    let ka = surface_factor_machined(f.ultimate);
    let kb = size_factor(equivalent_diameter(p));
    let se = ka * kb * f.endurance;
    // Peak stress per radian is stress_per_moment × k_bend (it includes K_t); nominal × K_f.
    let c = r.hinge.stress_per_moment * r.hinge.k_bend / kt * kf;
    let sa = c * spec.stroke.to_radians();
    let sm = c * spec.mean.abs().to_radians();
    let s_mean_limit = match spec.method {
        MeanStressMethod::Goodman => f.ultimate,
        MeanStressMethod::Soderberg => m.yield_strength,
    };
    let b = f.basquin_exponent();
    // Fatigue strength at the required cycles: S_e (N/N_e)^b below the knee, S_e beyond.
    let sf = se * (spec.cycles / f.sn_cycles).min(1.0).powf(b);
    let fatigue_utilisation = sa / sf + sm / s_mean_limit;
    // Fully reversed equivalent amplitude (Shigley eq. (6-59)) and Basquin life.
    let ratio = 1.0 - sm / s_mean_limit;
    let life_cycles = if ratio <= 0.0 {
        Some(0.0)
    } else {
        let s_ar = sa / ratio;
        (s_ar > se).then(|| f.sn_cycles * (s_ar / se).powf(1.0 / b))
    };
    let stroke_infinite_life = (se * ratio.max(0.0) / c).to_degrees();
    FatigueOut {
        fatigue_utilisation,
        infinite_life: life_cycles.is_none(),
        life_cycles,
        stroke_infinite_life,
        kt,
        notch_sensitivity: q,
        kf,
        notch_radius_mm: radius,
        marin_surface: ka,
        marin_size: kb,
        endurance_corrected: se,
        stress_per_rad: c,
        stress_alternating: sa,
        stress_mean: sm,
        method: format!(
            "stress-life (Shigley 10th ed. ch. 6): K_f = 1 + q (K_t − 1), Peterson q = 1/(1 + a/r) with a = {:.4} mm; S_e = k_a k_b S_e' with k_a machined (eq. 6-19), k_b bending size factor (eq. 6-20, d_e from eqs. 6-24/6-25, clamped to 2.79…51 mm), k_c = k_d = k_e = 1 (bending, room temperature, 50 % reliability); K_f on alternating and mean stress; {} mean-stress line; Basquin exponent b = {:.4} from S_e at N_e = {:e} cycles",
            f.peterson_a(),
            match spec.method {
                MeanStressMethod::Goodman => "modified Goodman",
                MeanStressMethod::Soderberg => "Soderberg",
            },
            b,
            f.sn_cycles
        ),
    }
}

/// Markdown section of the fatigue assessment.
pub fn report(o: &FatigueOut) -> String {
    let mut t = Table::new(&["quantity", "value", "unit"]);
    let life = o.life_cycles.map_or("infinite".to_string(), |n| sig(n, 4));
    for (name, v, unit) in [
        ("fatigue utilisation", sig(o.fatigue_utilisation, 4), "-"),
        ("life", life, "cycles"),
        ("stroke at infinite life", sig(o.stroke_infinite_life, 4), "deg"),
        (
            "K_t / q / K_f",
            format!("{:.4} / {:.4} / {:.4}", o.kt, o.notch_sensitivity, o.kf),
            "-",
        ),
        (
            "k_a / k_b",
            format!("{:.4} / {:.4}", o.marin_surface, o.marin_size),
            "-",
        ),
        ("S_e (corrected)", sig(o.endurance_corrected, 4), "MPa"),
        (
            "σ_a / σ_m",
            format!("{} / {}", sig(o.stress_alternating, 4), sig(o.stress_mean, 4)),
            "MPa",
        ),
    ] {
        t.row(vec![name.into(), v, unit.into()]);
    }
    format!("\n## Fatigue\n\nMethod: {}.\n\n{}", o.method, t.render())
}
