//! Warnings of the analyses: hinge calibration ranges, the small-strain assumption, unit slips.

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

/// Largest element stretch in a geometrically nonlinear result above which it is reported: the
/// co-rotational elements assume small strains (a linear-elastic element at 1 % strain is at
/// the end of the elastic range of every structural metal).
pub const SMALL_STRAIN: f64 = 0.01;

/// Warnings for load cases in which a two-node element's chord stretches or shortens by more
/// than [`SMALL_STRAIN`] (one per load case, naming the worst element).
pub fn stretch_warnings(model: &crate::fem::Model, r: &super::fem_static::StaticResult) -> Vec<String> {
    let mut out = Vec::new();
    for (ic, c) in r.load_cases.iter().enumerate() {
        let mut worst: Option<(usize, f64)> = None;
        for (ie, e) in model.elements.iter().enumerate() {
            let [a, b] = match e {
                crate::fem::Element::Beam(b) => b.nodes,
                crate::fem::Element::Flex(f) => f.nodes,
                _ => continue,
            };
            let (Some(da), Some(db)) = (c.displacements.get(a), c.displacements.get(b)) else {
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
        if let Some((ie, strain)) = worst {
            let pct = strain * 100.0;
            let pct = if pct.abs() < 1e4 {
                format!("{pct:+.2}")
            } else {
                format!("{pct:+.3e}")
            };
            out.push(format!(
                "load_cases[{ic}] (\"{}\"): element {ie} changes length by {pct} %, beyond the small-strain assumption of the co-rotational elements (|strain| <= {} %): the displacements are those of a linear-elastic material at that strain",
                c.name,
                SMALL_STRAIN * 100.0
            ));
        }
    }
    out
}

/// Implausible densities (unit slips) of a modal model's materials.
pub fn density_warnings(spec: &crate::case::mesh::MeshSpec) -> Vec<String> {
    spec.materials
        .iter()
        .filter_map(|(k, m)| {
            let at = format!("materials.{k}");
            let mat = m.resolve(&at).ok()?;
            crate::case::material::density_warning(&at, &mat)
        })
        .collect()
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
