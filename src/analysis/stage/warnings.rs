//! Warnings of a `stage` result: stresses above the allowable.

/// `stage` load case `ic`: a warning when its peak stress is above the allowable
/// (`factor_at_allowable` < 1), naming the hinge (kind and leg) or the leg beams that carry it.
/// Nothing is formatted (nor allocated) when the case is within its allowable.
pub fn stage_allowable_warning(ic: usize, c: &super::StageRow) -> Option<String> {
    if !(0.0..1.0).contains(&c.factor_at_allowable) || c.max_von_mises <= 0.0 {
        return None;
    }
    let sig = crate::report::markdown::sig;
    let hinges = [
        ("revolute", c.hinge_stress.revolute),
        ("spherical", c.hinge_stress.spherical),
    ];
    let (mut at, mut peak) = (String::new(), f64::NEG_INFINITY);
    for (kind, legs) in hinges {
        for (leg, s) in legs.iter().enumerate() {
            if *s > peak {
                peak = *s;
                at = format!("the {kind} hinge of leg {}", leg + 1);
            }
        }
    }
    // The peak is a hinge's unless a leg beam is more stressed (the hinge peaks are ≤ the maximum).
    if peak < c.max_von_mises * (1.0 - 1e-9) {
        at = format!("a leg beam (the most stressed hinge, {at}, is at {} MPa)", sig(peak, 5));
    }
    Some(format!(
        "load_cases[{ic}] (\"{}\"): {at} is above the allowable stress: von Mises {} MPa against {} MPa, utilisation {}",
        c.name,
        sig(c.max_von_mises, 5),
        sig(c.max_von_mises * c.factor_at_allowable, 5),
        sig(1.0 / c.factor_at_allowable, 4),
    ))
}
