//! Warnings of a `static` result: strains and rotations beyond the range of the run
//! (small-strain, small-displacement) and stresses above the allowable.

use super::{StaticCaseRow, Utilisation};
use crate::analysis::common::warn::{percent, worst_stretch, SMALL_ROTATION_DEG, SMALL_STRAIN};

/// Nonlinear run, load case `ic`: a warning when a two-node element's chord stretches or shortens by
/// more than [`SMALL_STRAIN`] (naming the worst element).
pub fn stretch_warning(model: &crate::fem::Model, ic: usize, c: &StaticCaseRow) -> Option<String> {
    let (ie, strain) = worst_stretch(model, &c.displacements)?;
    Some(format!(
        "load_cases[{ic}] (\"{}\"): element {ie} changes length by {} %, beyond the small-strain assumption of the co-rotational elements (|strain| <= {} %): the displacements are those of a linear-elastic material at that strain",
        c.name,
        percent(strain),
        SMALL_STRAIN * 100.0
    ))
}

/// Linear run, load case `ic`: a warning when a node rotates by more than
/// [`SMALL_ROTATION_DEG`] or a two-node element's chord stretches by more than [`SMALL_STRAIN`]
/// (model element index) — the answer of a linear run is then not to be trusted.
pub fn linear_range_warning(model: &crate::fem::Model, ic: usize, c: &StaticCaseRow) -> Option<String> {
    let rotation = c
        .displacements
        .iter()
        .enumerate()
        .map(|(n, d)| (n, (d[3] * d[3] + d[4] * d[4] + d[5] * d[5]).sqrt()))
        .filter(|(_, r)| *r > SMALL_ROTATION_DEG)
        .fold(None, |w: Option<(usize, f64)>, (n, r)| match w {
            Some((_, wr)) if wr >= r => w,
            _ => Some((n, r)),
        });
    let stretch = worst_stretch(model, &c.displacements);
    let mut what = Vec::new();
    if let Some((n, r)) = rotation {
        what.push(format!("node {n} rotates by {}°", crate::report::markdown::sig(r, 4)));
    }
    if let Some((ie, strain)) = stretch {
        what.push(format!("element {ie} changes length by {} %", percent(strain)));
    }
    if what.is_empty() {
        return None;
    }
    let slip = if rotation.is_some_and(|(_, r)| r > 90.0) {
        " (rotations this large in a linear run usually mean a unit slip: check E in MPa and the loads in N, N·mm)"
    } else {
        ""
    };
    Some(format!(
        "load_cases[{ic}] (\"{}\"): {} in a linear run, beyond the small-displacement range (rotations <= {SMALL_ROTATION_DEG}°, strains <= {} %){slip}: the linear displacements and stresses are not to be trusted; run it nonlinear (\"nonlinear\": true)",
        c.name,
        what.join(" and "),
        SMALL_STRAIN * 100.0
    ))
}

/// Load case `ic`: a warning naming the elements above their allowable stress, `over`
/// (utilisation > 1), worst first; `None` when there are none.
pub fn allowable_warning(ic: usize, name: &str, over: &[Utilisation]) -> Option<String> {
    let (worst, rest) = over.split_first()?;
    let others = if rest.is_empty() {
        String::new()
    } else {
        const LISTED: usize = 5;
        let list: Vec<String> = rest
            .iter()
            .take(LISTED)
            .map(|u| {
                format!(
                    "{} ({}, {})",
                    u.element,
                    u.kind,
                    crate::report::markdown::sig(u.value, 3)
                )
            })
            .collect();
        let more = rest.len().saturating_sub(LISTED);
        let more = if more > 0 {
            format!(" and {more} more")
        } else {
            String::new()
        };
        format!(
            "; also above it: element{} {}{more}",
            if rest.len() > 1 { "s" } else { "" },
            list.join(", ")
        )
    };
    Some(format!(
        "load_cases[{ic}] (\"{name}\"): element {} ({}) is above its allowable stress: von Mises {} MPa against {} MPa, utilisation {}{others}",
        worst.element,
        worst.kind,
        crate::report::markdown::sig(worst.von_mises, 5),
        crate::report::markdown::sig(worst.allowable, 5),
        crate::report::markdown::sig(worst.value, 4),
    ))
}
