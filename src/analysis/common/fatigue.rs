//! The stress-life chain of a notch hinge shared by every fatigue assessment (the `hinge`
//! analysis, the `stage`, the hinge elements of `static` models): Budynas & Nisbett, Shigley's
//! Mechanical Engineering Design, 10th ed. (2015), ch. 6.
//!
//! The hinge's elastic notch factor K_t (the factor its stress model puts on the nominal
//! bending stress) becomes the fatigue notch factor K_f = 1 + q (K_t − 1) with Peterson's notch
//! sensitivity q = 1/(1 + a/r); the endurance limit S_e' of the material becomes
//! S_e = k_a k_b S_e' (machined surface, bending size factor); the fatigue strength at N cycles
//! is S_f = S_e (N/N_e)^b below the knee N_e, S_e beyond; a mean stress enters through the
//! modified Goodman or the Soderberg line.

use crate::case::fatigue::MeanStressMethod;
use crate::fatigue::{notch_sensitivity, size_factor, surface_factor_machined, MaterialFatigue};
use crate::hinge::{Contour, Profile};
use crate::material::Material;

/// The chain of one hinge for one required life: every factor and strength of the assessment.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct FatigueChain {
    /// Elastic notch factor K_t of the hinge's stress model.
    pub kt: f64,
    /// Peterson's notch sensitivity q = 1/(1 + a/r) (1 without a notch).
    pub q: f64,
    /// Fatigue notch factor K_f = 1 + q (K_t − 1).
    pub kf: f64,
    /// Notch root radius r used for q, mm (`None`: no notch, leaf hinge).
    pub notch_radius: Option<f64>,
    /// Marin surface (machined) and size factors k_a, k_b.
    pub ka: f64,
    pub kb: f64,
    /// Corrected endurance limit S_e = k_a k_b S_e', MPa.
    pub se: f64,
    /// Fatigue strength at the required cycles S_f, MPa.
    pub sf: f64,
    /// Strength of the mean-stress line: S_ut (Goodman) or S_y (Soderberg), MPa.
    pub mean_limit: f64,
    /// Basquin exponent b.
    pub b: f64,
    /// Knee of the S–N curve N_e, cycles.
    pub sn_cycles: f64,
    /// Peterson's length a, mm.
    pub peterson_a: f64,
    /// Mean-stress criterion.
    pub method: MeanStressMethod,
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

impl FatigueChain {
    /// The chain of the hinge `p` of material `m` (fatigue data `f`) whose stress model puts
    /// `kt` on the nominal bending stress, for a life of `cycles` by `method`.
    pub fn new(
        cycles: f64,
        method: MeanStressMethod,
        m: &Material,
        f: &MaterialFatigue,
        p: &Profile,
        kt: f64,
    ) -> FatigueChain {
        let radius = notch_radius(&p.contour);
        let q = radius.map_or(1.0, |rr| notch_sensitivity(f.peterson_a(), rr));
        let ka = surface_factor_machined(f.ultimate);
        let kb = size_factor(equivalent_diameter(p));
        let se = ka * kb * f.endurance;
        let b = f.basquin_exponent();
        FatigueChain {
            kt,
            q,
            kf: 1.0 + q * (kt - 1.0),
            notch_radius: radius,
            ka,
            kb,
            se,
            sf: se * (cycles / f.sn_cycles).min(1.0).powf(b),
            mean_limit: match method {
                MeanStressMethod::Goodman => f.ultimate,
                MeanStressMethod::Soderberg => m.yield_strength,
            },
            b,
            sn_cycles: f.sn_cycles,
            peterson_a: f.peterson_a(),
            method,
        }
    }

    /// Fatigue utilisation σ_a/S_f + σ_m/S_mean of the fatigue stresses (K_f applied) σ_a, σ_m, MPa.
    pub fn utilisation(&self, sa: f64, sm: f64) -> f64 {
        sa / self.sf + sm / self.mean_limit
    }

    /// 1 − σ_m/S_mean: the share of the endurance left for the amplitude.
    fn mean_ratio(&self, sm: f64) -> f64 {
        1.0 - sm / self.mean_limit
    }

    /// Predicted life, cycles, from the fully reversed equivalent amplitude (Shigley eq. (6-59))
    /// and Basquin's line; `None`: infinite (within the endurance limit); 0 when the mean alone
    /// exhausts the line.
    pub fn life(&self, sa: f64, sm: f64) -> Option<f64> {
        let ratio = self.mean_ratio(sm);
        if ratio <= 0.0 {
            Some(0.0)
        } else {
            let s_ar = sa / ratio;
            (s_ar > self.se).then(|| self.sn_cycles * (s_ar / self.se).powf(1.0 / self.b))
        }
    }

    /// The alternating fatigue stress at infinite life given the mean σ_m, MPa.
    pub fn infinite_life_amplitude(&self, sm: f64) -> f64 {
        self.se * self.mean_ratio(sm).max(0.0)
    }

    /// The method in words.
    pub fn describe(&self) -> String {
        format!(
            "stress-life (Shigley 10th ed. ch. 6): K_f = 1 + q (K_t − 1), Peterson q = 1/(1 + a/r) with a = {:.4} mm; S_e = k_a k_b S_e' with k_a machined (eq. 6-19), k_b bending size factor (eq. 6-20, d_e from eqs. 6-24/6-25, clamped to 2.79…51 mm), k_c = k_d = k_e = 1 (bending, room temperature, 50 % reliability); K_f on alternating and mean stress; {} mean-stress line; Basquin exponent b = {:.4} from S_e at N_e = {:e} cycles; below S_e the life is reported infinite — S_e' is the material's strength at N_e, so for materials without a true endurance limit (aluminium alloys, polymers) read infinite as at least N_e cycles; k_a, k_b and (when not given) Peterson's a are Shigley's fits to steel data, applied as they are to other metals and to polymers, where they are an estimate (k_b exceeds 1 for waists under 7.6 mm)",
            self.peterson_a,
            match self.method {
                MeanStressMethod::Goodman => "modified Goodman",
                MeanStressMethod::Soderberg => "Soderberg",
            },
            self.b,
            self.sn_cycles
        )
    }
}

/// A predicted life for results: a number of cycles, or `"infinite"` within the endurance limit.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct Life(pub Option<f64>);

impl serde::Serialize for Life {
    fn serialize<S: serde::Serializer>(&self, s: S) -> Result<S::Ok, S::Error> {
        match self.0 {
            Some(n) => s.serialize_f64(n),
            None => s.serialize_str("infinite"),
        }
    }
}
