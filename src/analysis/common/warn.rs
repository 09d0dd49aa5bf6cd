//! Warnings of the analyses: hinge calibration ranges, the small-strain and small-displacement
//! assumptions, stresses above the allowable (unit slips of materials: [`crate::case::material::plausibility_warnings`]).

use crate::analysis::fem_static::{StaticCaseRow, Utilisation};

/// Calibration-range warnings of a hinge, prefixed with where it sits in the case file.
pub fn hinge_warnings(at: &str, spec: &crate::hinge::HingeSpec) -> Vec<String> {
    match spec.profile() {
        Ok(p) => crate::hinge::calibration::calibration_warnings(&p)
            .into_iter()
            .map(|w| format!("{at}: {w}"))
            .collect(),
        Err(_) => Vec::new(),
    }
}

/// The warning when an eigen-analysis computed fewer modes than `modes` asked for: a model with
/// `n_eq` equations (free DOFs) has at most that many modes, fewer when some DOFs carry no mass
/// (or, in buckling, no geometric stiffness). The run keeps the modes there are and says so.
pub fn fewer_modes(asked: usize, got: usize, n_eq: Option<usize>) -> Option<String> {
    (got < asked).then(|| {
        let eqs = n_eq.map(|n| format!(" (it has {n} equations)")).unwrap_or_default();
        format!("`modes`: {asked} asked for, but the model has only {got}{eqs}: {got} computed")
    })
}

/// Largest element stretch in a geometrically nonlinear result above which it is reported: the
/// co-rotational elements assume small strains (a linear-elastic element at 1 % strain is at
/// the end of the elastic range of every structural metal).
pub const SMALL_STRAIN: f64 = 0.01;

/// Largest rotation of a node in a linear run, degrees, above which a warning asks for the
/// nonlinear analysis: at 5° the second-order displacements a linear run leaves out
/// ((1 − cos θ)·L against sin θ·L) reach θ/2 = 4.4 % of the first-order ones, and parasitic
/// motions of flexure mechanisms are of that order.
pub const SMALL_ROTATION_DEG: f64 = 5.0;

/// The two-node element (beam or hinge segment, model index) whose chord stretches or shortens
/// most, by more than [`SMALL_STRAIN`], under `displacements` (mm, degrees): (element, strain).
fn worst_stretch(model: &crate::fem::Model, displacements: &[[f64; 6]]) -> Option<(usize, f64)> {
    let mut worst: Option<(usize, f64)> = None;
    for (ie, e) in model.elements.iter().enumerate() {
        let [a, b] = match e {
            crate::fem::Element::Beam(b) => b.nodes,
            crate::fem::Element::Flex(f) => f.nodes,
            _ => continue,
        };
        let (Some(da), Some(db)) = (displacements.get(a), displacements.get(b)) else {
            continue;
        };
        let (xa, xb) = (model.nodes[a], model.nodes[b]);
        let l0 = (0..3).map(|k| (xb[k] - xa[k]).powi(2)).sum::<f64>().sqrt();
        let l = (0..3)
            .map(|k| ((xb[k] + db[k]) - (xa[k] + da[k])).powi(2))
            .sum::<f64>()
            .sqrt();
        let strain = l / l0 - 1.0;
        if strain.abs() > SMALL_STRAIN && worst.is_none_or(|(_, w)| strain.abs() > w.abs()) {
            worst = Some((ie, strain));
        }
    }
    worst
}

/// A strain in percent, signed, plain up to 10⁴ %.
fn percent(strain: f64) -> String {
    let pct = strain * 100.0;
    if pct.abs() < 1e4 {
        format!("{pct:+.2}")
    } else {
        format!("{pct:+.3e}")
    }
}

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

/// In a nonlinear run, the `hinge` elements of one co-rotational segment (one warning naming
/// them): a single co-rotational element measures its deformation from its chord, so the
/// second-order shortening inside the notch is lost — the parasitic drop of the parallelogram
/// guide of `cases/parallelogram_guide.json` at a 1 mm stroke reads 7.6 % below the linkage's
/// with one segment and 1.7 % below with 8 (`tests/mechanisms.rs`).
pub fn single_segment_hinge_warnings(hinges: &[crate::case::mesh::BuiltHinge]) -> Vec<String> {
    let single: Vec<String> = hinges
        .iter()
        .filter(|h| h.segments == 1)
        .map(|h| h.case_element.to_string())
        .collect();
    if single.is_empty() {
        return Vec::new();
    }
    vec![format!(
        "hinge elements {} are single co-rotational segments in a nonlinear run (\"segments\": 1): their rotations are right, but the shortening along a bent notch is that of its chord (second-order parasitic motions too small, e.g. 6 % on a parallelogram guide; peak stresses low by as much at degrees of rotation); remove \"segments\" (4 by default in nonlinear runs) or give 4 or more",
        single.join(", ")
    )]
}

/// `stage` load case `ic`: a warning when its peak stress is above the allowable
/// (`factor_at_allowable` < 1), naming the hinge (kind and leg) or the leg beams that carry it.
/// Nothing is formatted (nor allocated) when the case is within its allowable.
pub fn stage_allowable_warning(ic: usize, c: &crate::analysis::stage::StageRow) -> Option<String> {
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

/// The model note of a nonlinear run whose `hinge` elements (some or all) took the default
/// segmentation ([`crate::hinge::NONLINEAR_SEGMENTS`]), or `None`.
pub fn default_segments_note(hinges: &[crate::case::mesh::BuiltHinge]) -> Option<String> {
    let given: Vec<String> = hinges
        .iter()
        .filter(|h| h.default_segments)
        .map(|h| h.case_element.to_string())
        .collect();
    (!given.is_empty()).then(|| {
        format!(
            "hinge elements {} (no \"segments\" given): each split into {} co-rotational segments for the nonlinear run (parasitic motions and peak stresses within 1 % of 16 segments; one segment loses ~6 %); inner nodes and elements follow the case's own",
            given.join(", "),
            crate::hinge::NONLINEAR_SEGMENTS
        )
    })
}

/// A warning when a nonlinear state was accepted on the round-off floor of the stiffest element
/// rather than within 1e-6 of its load (`what` names the load case or run, `relative` is its
/// largest relative equilibrium residual): its forces and reactions are only that accurate.
pub fn equilibrium_floor_warning(what: &str, relative: Option<f64>) -> Option<String> {
    relative.filter(|e| *e > 1e-6).map(|e| {
        format!(
            "{what}: equilibrium verified only to {e:.1e} of the load (above 1e-6, within the round-off floor of the stiffest element): reactions and element forces are no more accurate than that; very stiff or very short elements cause it"
        )
    })
}
