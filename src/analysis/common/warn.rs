//! Warnings shared by the analyses: hinge calibration ranges, the small-strain and
//! small-displacement limits, modes fewer than asked, segmented hinges (unit slips of materials:
//! [`crate::case::material::plausibility_warnings`]). The warnings that read one kind's result
//! rows live with that kind (`fem_static/warnings.rs`, `stage/warnings.rs`).

/// Calibration-range warnings of a hinge, prefixed with where it sits in the case file (the
/// `hinge` analysis adds those of its rigid end faces from its result:
/// [`crate::hinge::calibration::end_face_warning`]).
pub fn hinge_warnings(at: &str, spec: &crate::hinge::HingeSpec) -> Vec<String> {
    match spec.profile() {
        Ok(p) => crate::hinge::calibration::calibration_warnings(&p)
            .into_iter()
            .chain(crate::hinge::calibration::short_blank_warning(&p))
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
pub fn worst_stretch(model: &crate::fem::Model, displacements: &[[f64; 6]]) -> Option<(usize, f64)> {
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
pub fn percent(strain: f64) -> String {
    let pct = strain * 100.0;
    if pct.abs() < 1e4 {
        format!("{pct:+.2}")
    } else {
        format!("{pct:+.3e}")
    }
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
