//! High-cycle fatigue of the `hinge` elements of a `static` model (`"fatigue"` of the case):
//! each load case is the peak of a load cycle of stress ratio R; the chain of
//! [`crate::analysis::common::fatigue`] (Budynas & Nisbett, Shigley's Mechanical Engineering
//! Design, 10th ed. (2015), ch. 6) on the hinge's peak stress with K_f in place of K_t — the
//! same hinge under the same moment as in the `hinge` analysis gives the same numbers.

use super::rows::{HingeFatigue, StaticResult};
use crate::analysis::common::fatigue::FatigueChain;
use crate::case::fatigue::CyclicSpec;
use crate::case::mesh::BuiltHinge;

/// Adds the fatigue of every hinge row of `r` (`hinges`: the model's hinge elements, in the
/// order of each row's `hinges`; materials checked by [`CyclicSpec::check_hinges`]).
pub fn add(r: &mut StaticResult, hinges: &[BuiltHinge], spec: &CyclicSpec) {
    let chains: Vec<Option<FatigueChain>> = hinges
        .iter()
        .map(|h| {
            let f = h.material.fatigue?;
            Some(FatigueChain::new(
                spec.cycles,
                spec.method,
                &h.material,
                &f,
                &h.region.profile,
                h.region.kt,
            ))
        })
        .collect();
    let (a, m) = spec.shares();
    for row in &mut r.load_cases {
        for h in &mut row.hinges {
            let Some(c) = hinges
                .iter()
                .position(|b| b.case_element == h.element)
                .and_then(|k| chains[k].as_ref())
            else {
                continue;
            };
            let s = h.peak_von_mises * c.kf / c.kt;
            let (sa, sm) = (a * s, m * s);
            h.fatigue = Some(HingeFatigue {
                utilisation: c.utilisation(sa, sm),
                life_cycles: crate::analysis::common::fatigue::Life(c.life(sa, sm)),
                stress_alternating: sa,
                stress_mean: sm,
                kf: c.kf,
                endurance_corrected: c.se,
                strength_at_cycles: c.sf,
            });
        }
    }
    if let Some(c) = chains.iter().flatten().next() {
        r.model.push(format!(
            "fatigue of the hinge elements: every load case is the peak of a cycle of stress ratio R = {}, {:e} cycles; fatigue stress = peak stress x K_f/K_t; {}",
            spec.load_ratio,
            spec.cycles,
            c.describe()
        ));
    }
}
