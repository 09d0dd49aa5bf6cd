//! High-cycle fatigue of a `hinge` under a cyclic rotation about its compliant axis (stress-life
//! approach of Budynas & Nisbett, Shigley's Mechanical Engineering Design, 10th ed. (2015), ch. 6).

use crate::analysis::common::fatigue::FatigueChain;
use crate::case::fatigue::FatigueSpec;
use crate::fatigue::MaterialFatigue;
use crate::hinge::{HingeResult, Profile};
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

/// Assesses the case's stroke on the hinge characterised in `r`.
pub fn assess(spec: &FatigueSpec, m: &Material, f: &MaterialFatigue, p: &Profile, r: &HingeResult) -> FatigueOut {
    let ch = FatigueChain::new(spec.cycles, spec.method, m, f, p, r.stress_concentration);
    // Peak stress per radian is stress_per_moment × k_bend (it includes K_t); nominal × K_f.
    let c = r.hinge.stress_per_moment * r.hinge.k_bend / ch.kt * ch.kf;
    let sa = c * spec.stroke.to_radians();
    let sm = c * spec.mean.abs().to_radians();
    let life_cycles = ch.life(sa, sm);
    FatigueOut {
        fatigue_utilisation: ch.utilisation(sa, sm),
        infinite_life: life_cycles.is_none(),
        life_cycles,
        stroke_infinite_life: (ch.infinite_life_amplitude(sm) / c).to_degrees(),
        kt: ch.kt,
        notch_sensitivity: ch.q,
        kf: ch.kf,
        notch_radius_mm: ch.notch_radius,
        marin_surface: ch.ka,
        marin_size: ch.kb,
        endurance_corrected: ch.se,
        stress_per_rad: c,
        stress_alternating: sa,
        stress_mean: sm,
        method: ch.describe(),
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
