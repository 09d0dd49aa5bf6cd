//! High-cycle fatigue of the stage's six hinges (`"fatigue"` of a `stage` case): every load case
//! is the peak of a load cycle of stress ratio R; the chain of
//! [`crate::analysis::common::fatigue`] (Budynas & Nisbett, Shigley's Mechanical Engineering
//! Design, 10th ed. (2015), ch. 6).
//!
//! The fatigue stress of a hinge is its peak stress (the stage's stress model, notch factor
//! K_t on the bending stress) times K_f/K_t: K_f in place of K_t. That is exact for the bending
//! stress at the notch; the axial and torsional parts of the peak (no notch factor in the stress
//! model) are scaled by K_f/K_t ≤ 1 too, which a model note states. The stage is linear in the
//! load, so the load factor that brings the first hinge to fatigue utilisation 1 scales the
//! strokes: the fatigue-limited stroke is the unit-force response times that factor, like
//! `at_allowable`.

use super::{HingeStress, StageRow};
use crate::analysis::common::fatigue::{FatigueChain, Life};
use crate::case::fatigue::CyclicSpec;
use crate::fatigue::MaterialFatigue;
use crate::stage::sizing::FatigueLimit;
use crate::stage::{StageResponse, ValidStage};
use serde::Serialize;

/// Per hinge of one kind: revolute or spherical, per leg.
#[derive(Debug, Clone, Copy, Serialize, Default, PartialEq)]
pub struct PerHinge<T> {
    /// Revolute hinges, legs 1 … 3.
    pub revolute: [T; 3],
    /// Spherical hinges, legs 1 … 3.
    pub spherical: [T; 3],
}

/// Fatigue of the six hinges in one load case (the case is the peak of the cycle).
#[derive(Debug, Clone, Copy, Serialize, Default, PartialEq)]
pub struct CaseFatigue {
    /// Fatigue utilisation σ_a/S_f(N) + σ_m/S_mean at the required cycles; ≤ 1 passes.
    pub utilisation: PerHinge<f64>,
    /// Predicted life, cycles (`"infinite"` within the endurance limit).
    pub life_cycles: PerHinge<Life>,
    /// The largest utilisation.
    pub max_utilisation: f64,
    /// Load factor on this case that brings the first hinge to utilisation 1 (stress
    /// proportional to the load; `null`: nothing stressed).
    #[serde(serialize_with = "crate::report::numbers::unbounded_as_null")]
    pub factor_at_fatigue_limit: f64,
}

/// The chain of one hinge kind, for the result.
#[derive(Debug, Clone, Copy, Serialize, PartialEq)]
pub struct ChainOut {
    /// Notch factor K_t of the stress model, Peterson's q, fatigue notch factor K_f.
    pub kt: f64,
    pub notch_sensitivity: f64,
    pub kf: f64,
    /// Notch root radius used for q, mm.
    pub notch_radius_mm: Option<f64>,
    /// Marin surface (machined) and size factors.
    pub marin_surface: f64,
    pub marin_size: f64,
    /// Corrected endurance limit S_e, MPa.
    pub endurance_corrected: f64,
    /// Fatigue strength at the required cycles S_f, MPa.
    pub strength_at_cycles: f64,
}

impl From<&FatigueChain> for ChainOut {
    fn from(c: &FatigueChain) -> Self {
        ChainOut {
            kt: c.kt,
            notch_sensitivity: c.q,
            kf: c.kf,
            notch_radius_mm: c.notch_radius,
            marin_surface: c.ka,
            marin_size: c.kb,
            endurance_corrected: c.se,
            strength_at_cycles: c.sf,
        }
    }
}

/// What the stage reaches at the fatigue limit under equal actuator forces (pure z), beside
/// `at_allowable`: the peak of the cycle at which the first hinge reaches utilisation 1.
#[derive(Debug, Clone, Serialize)]
pub struct AtFatigueLimit {
    /// Required life, cycles, and the stress ratio of the cycle.
    pub cycles: f64,
    pub load_ratio: f64,
    /// Actuator force each at the peak of the cycle, N.
    #[serde(serialize_with = "crate::report::numbers::unbounded_as_null")]
    pub force: f64,
    /// Stroke at the peak of the cycle (mean of the three), mm: the fatigue-limited stroke.
    #[serde(serialize_with = "crate::report::numbers::unbounded_as_null")]
    pub stroke: f64,
    /// Platform z at the peak of the cycle, mm.
    #[serde(serialize_with = "crate::report::numbers::unbounded_as_null")]
    pub z: f64,
    /// The hinge that reaches utilisation 1 first: `"revolute"` or `"spherical"`, and its leg
    /// (1 … 3).
    pub hinge: &'static str,
    pub leg: usize,
    /// Stroke at the peak of the cycle at which the first hinge reaches the endurance line
    /// (infinite life, any number of cycles), mm.
    #[serde(serialize_with = "crate::report::numbers::unbounded_as_null")]
    pub stroke_infinite_life: f64,
    /// The chains of the revolute and spherical hinges.
    pub revolute: ChainOut,
    pub spherical: ChainOut,
    /// What was applied.
    pub method: String,
}

/// The two hinge chains of a stage design and the cycle.
#[derive(Debug, Clone, Copy)]
pub struct StageFatigue {
    spec: CyclicSpec,
    chains: [FatigueChain; 2],
}

impl StageFatigue {
    /// The chains of `s`'s revolute and spherical hinges (material fatigue data `f`).
    pub fn new(spec: &CyclicSpec, s: &ValidStage, f: &MaterialFatigue) -> StageFatigue {
        let chain = |r: &crate::hinge::HingeRegion| {
            FatigueChain::new(spec.cycles, spec.method, &s.material, f, &r.profile, r.kt)
        };
        StageFatigue {
            spec: *spec,
            chains: [chain(&s.revolute), chain(&s.spherical)],
        }
    }

    /// (σ_a, σ_m), MPa, of a hinge of kind `k` (0 revolute, 1 spherical) whose peak stress is
    /// `peak` at the peak of the cycle.
    fn stresses(&self, k: usize, peak: f64) -> (f64, f64) {
        let c = &self.chains[k];
        let s = peak * c.kf / c.kt;
        let (a, m) = self.spec.shares();
        (a * s, m * s)
    }

    /// The fatigue of one load case from its hinge peak stresses.
    pub fn case(&self, h: &HingeStress) -> CaseFatigue {
        let mut out = CaseFatigue::default();
        for (k, peaks) in [h.revolute, h.spherical].iter().enumerate() {
            for (i, &p) in peaks.iter().enumerate() {
                let (sa, sm) = self.stresses(k, p);
                let u = self.chains[k].utilisation(sa, sm);
                let life = self.chains[k].life(sa, sm);
                let (us, ls) = match k {
                    0 => (&mut out.utilisation.revolute, &mut out.life_cycles.revolute),
                    _ => (&mut out.utilisation.spherical, &mut out.life_cycles.spherical),
                };
                us[i] = u;
                ls[i] = Life(life);
                out.max_utilisation = out.max_utilisation.max(u);
            }
        }
        out.factor_at_fatigue_limit = if out.max_utilisation > 0.0 {
            1.0 / out.max_utilisation
        } else {
            f64::INFINITY
        };
        out
    }

    /// The largest hinge fatigue utilisation under the response `u` (the peak of the cycle).
    pub fn max_utilisation(&self, u: &StageResponse) -> f64 {
        let mut worst = 0.0_f64;
        for (k, peaks) in u.hinge_stress.iter().enumerate() {
            for &p in peaks {
                let (sa, sm) = self.stresses(k, p);
                worst = worst.max(self.chains[k].utilisation(sa, sm));
            }
        }
        worst
    }

    /// The fatigue limit from the response `u` to a unit force on every actuator.
    pub fn at_limit(&self, u: &StageResponse) -> AtFatigueLimit {
        let (mut worst, mut hinge, mut leg, mut worst_inf) = (0.0_f64, "revolute", 1, 0.0_f64);
        for (k, peaks) in u.hinge_stress.iter().enumerate() {
            let c = &self.chains[k];
            for (i, &p) in peaks.iter().enumerate() {
                let (sa, sm) = self.stresses(k, p);
                let uf = c.utilisation(sa, sm);
                if uf > worst {
                    (worst, hinge, leg) = (uf, ["revolute", "spherical"][k], i + 1);
                }
                // At infinite life: σ_a/S_e + σ_m/S_mean, also linear in the load.
                worst_inf = worst_inf.max(sa / c.se + sm / c.mean_limit);
            }
        }
        let k = 1.0 / worst;
        let stroke = u.strokes.iter().sum::<f64>() / 3.0;
        AtFatigueLimit {
            cycles: self.spec.cycles,
            load_ratio: self.spec.load_ratio,
            force: k,
            stroke: k * stroke,
            z: k * u.platform.z,
            hinge,
            leg,
            stroke_infinite_life: stroke / worst_inf,
            revolute: (&self.chains[0]).into(),
            spherical: (&self.chains[1]).into(),
            method: self.note(),
        }
    }

    /// Adds the fatigue of each row.
    pub fn add_to(&self, rows: &mut [StageRow]) {
        for r in rows {
            r.fatigue = Some(self.case(&r.hinge_stress));
        }
    }

    /// The method in words.
    fn note(&self) -> String {
        format!(
            "fatigue: every load case is the peak of a cycle of stress ratio R = {}, {:e} cycles; hinge fatigue stress = peak stress x K_f/K_t (exact for the notch bending stress; the axial and torsional parts are scaled by K_f/K_t <= 1 too); {}; the fatigue limit scales the unit-force response (linear: stress proportional to load)",
            self.spec.load_ratio,
            self.spec.cycles,
            self.chains[0].describe()
        )
    }
}

/// The fatigue of the stage sizing and sensitivity (`"fatigue"` of their requirements or
/// case): the chains rebuilt for each design's hinges (K_t, notch radius and size factor change
/// with the parameters), the same assessment as a `stage` case's `at_fatigue_limit`.
#[derive(Debug, Clone, Copy)]
pub struct SizingFatigue {
    /// The load cycle.
    pub spec: CyclicSpec,
    /// The material's fatigue data.
    pub data: MaterialFatigue,
}

impl FatigueLimit for SizingFatigue {
    fn max_utilisation(&self, v: &ValidStage, unit: &StageResponse) -> f64 {
        StageFatigue::new(&self.spec, v, &self.data).max_utilisation(unit)
    }
}
