//! Linear buckling of a column standing on a notch hinge (mesh `hinge` element).

use flexfem::analysis::{self, Case};
use flexfem::fem::buckling::{solve_buckling, BucklingOptions};
use flexfem::fem::Model;

/// A circular notch hinge (R = 5, t = 1, w = h = 10 mm, Al 7075) from the clamped node 0 to
/// node 1 (x = 10 mm: the notch, no blank), then a 10 × 10 mm bar of length 100 mm along x
/// (4 beams), free top, 1 N axial compression at the top. The hinge as `segments` co-rotational
/// flexibility elements.
fn hinge_column(segments: usize) -> Model {
    let text = format!(
        r#"{{"analysis": "static", "materials": {{"al": "Al7075"}},
            "sections": {{"bar": {{"shape": "rect", "w": 10, "h": 10}}}},
            "nodes": [[0, 0, 0], [10, 0, 0], [35, 0, 0], [60, 0, 0], [85, 0, 0], [110, 0, 0]],
            "elements": [
              {{"type": "hinge", "nodes": [0, 1], "segments": {segments}, "material": "al", "up": [0, 0, 1],
                "hinge": {{"type": "circular_notch", "R": 5, "t": 1, "w": 10, "h": 10}}}},
              {{"type": "beam", "nodes": [1, 2], "section": "bar", "material": "al", "up": [0, 0, 1]}},
              {{"type": "beam", "nodes": [2, 3], "section": "bar", "material": "al", "up": [0, 0, 1]}},
              {{"type": "beam", "nodes": [3, 4], "section": "bar", "material": "al", "up": [0, 0, 1]}},
              {{"type": "beam", "nodes": [4, 5], "section": "bar", "material": "al", "up": [0, 0, 1]}}],
            "supports": [{{"node": 0, "fix": ["ux", "uy", "uz", "rx", "ry", "rz"]}}],
            "load_cases": [{{"name": "axial", "forces": [{{"node": 5, "F": [-1, 0, 0, 0, 0, 0]}}]}}]}}"#
    );
    match analysis::parse(&text).unwrap_or_else(|e| panic!("{e}")) {
        Case::Static(s) => s.model.build().unwrap_or_else(|e| panic!("{e}")),
        _ => panic!("not static"),
    }
}

/// The notch hinge as one flexibility element (its co-rotational chord carries the geometric
/// stiffness) against the same notch as a chain of 48 flexibility elements over equal lengths,
/// each with the compliance of its slice of the same (solid-calibrated) notch profile
/// (`hinge::split_flex`): the chain resolves the bending-moment growth P·w(x) inside the notch
/// that one element's chord only averages, so it is the refined beam model of the same notch.
/// Within 5 %. Closed-form sanity check (printed): a rigid bar on a rotational spring,
/// P = k_θ/L_arm (Timoshenko & Gere 1961, §2.1, the inverted pendulum), with k_θ = 1/c_θθ of
/// the hinge and the arm from the hinge centre to the top.
#[test]
fn notch_hinge_column_matches_the_segmented_notch() {
    let one = solve_buckling(&hinge_column(1), 0, &BucklingOptions::new(1)).unwrap();
    let refined = solve_buckling(&hinge_column(48), 0, &BucklingOptions::new(1)).unwrap();
    let (p1, p48) = (one.modes[0].load_factor, refined.modes[0].load_factor);
    let model = hinge_column(1);
    let flexfem::fem::Element::Flex(f) = &model.elements[0] else {
        panic!("element 0 is the hinge")
    };
    // Bending in the x–z plane (thinning along z = local z): rotation about local y.
    let closed = 1.0 / (f.compliance[4][4] * 105.0);
    eprintln!(
        "hinge column: one element {p1:.3} N, 48 segments {p48:.3} N ({:+.3} %), rigid bar on k_θ/L {closed:.3} N",
        100.0 * (p1 - p48) / p48
    );
    // Measured +1.73 %.
    assert!(((p1 - p48) / p48).abs() < 0.03, "{p1} vs {p48}");
    // The mode: the bar tilts (the top moves along z, the thin direction of the notch).
    let top = one.modes[0].shape[5];
    assert!((top[2].abs() - 1.0).abs() < 1e-9, "{top:?}");
}
