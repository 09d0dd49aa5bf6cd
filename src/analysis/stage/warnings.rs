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
    let peak = hinges
        .iter()
        .flat_map(|(_, legs)| legs.iter().copied())
        .fold(f64::NEG_INFINITY, f64::max);
    // Every hinge at the peak (to 1e-9: a symmetric stage under a symmetric load has several,
    // equal to rounding, and naming one of them would depend on the rounding).
    let (mut at, mut count) = (Vec::new(), 0);
    for (kind, legs) in hinges {
        let at_peak: Vec<String> = (0..legs.len())
            .filter(|&leg| legs[leg] >= peak * (1.0 - 1e-9))
            .map(|leg| (leg + 1).to_string())
            .collect();
        count += at_peak.len();
        match at_peak.as_slice() {
            [] => {}
            [one] => at.push(format!("the {kind} hinge of leg {one}")),
            [first @ .., last] => at.push(format!("the {kind} hinges of legs {} and {last}", first.join(", "))),
        }
    }
    let mut at = at.join(" and ");
    let mut verb = if count > 1 { "are" } else { "is" };
    // The peak is a hinge's unless a leg beam is more stressed (the hinge peaks are ≤ the maximum).
    if peak < c.max_von_mises * (1.0 - 1e-9) {
        at = format!(
            "a leg beam (the most stressed hinge, {at}, {verb} at {} MPa)",
            sig(peak, 5)
        );
        verb = "is";
    }
    Some(format!(
        "load_cases[{ic}] (\"{}\"): {at} {verb} above the allowable stress: von Mises {} MPa against {} MPa, utilisation {}",
        c.name,
        sig(c.max_von_mises, 5),
        sig(c.max_von_mises * c.factor_at_allowable, 5),
        sig(1.0 / c.factor_at_allowable, 4),
    ))
}
