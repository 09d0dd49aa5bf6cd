//! The raw-results check and the scikit-fem values of tests/hinge_ccx_reference.rs.

use super::raw_results::{json_lines, matching_lines};
use super::references::CcxRef;

/// The hinges computed with both solid pipelines: the scikit-fem P2 results of
/// `tools/solid_reference_results.jsonl` (n = 5: k_bend, k_torsion, k_axial, nodal-averaged peak
/// stress per moment) against the CalculiX rows of the same geometry (n = 4).
pub const SCIKIT_FEM: [(&str, [f64; 4]); 3] = [
    (
        r#"{"type": "circular_notch", "R": 8.0, "t": 2.0, "w": 10.0, "h": 10.0, "blank_length": 20.0}"#,
        [95922.3, 196427.0, 84453.4, 0.151083],
    ),
    (
        r#"{"type": "spherical_neck", "l": 5.0, "t": 3.0, "R": 4.0, "h": 10.0, "blank_length": 20.0}"#,
        [32602.7, 24677.5, 38308.3, 0.390483],
    ),
    (
        r#"{"type": "corner_filleted", "l": 6.0, "R": 2.0, "t": 1.5, "w": 6.0, "h": 8.0, "blank_length": 10.0}"#,
        [28551.6, 57445.6, 65542.3, 0.453389],
    ),
];

/// Checks that every reference of `refs` is exactly one line of `tools/<file>` (geometry, E, ν
/// and the five quantities to 6 digits, at n = 4) and that the file has no other line, and that
/// its n = 3 values are the line of `tools/ccx_refine_n3_results.jsonl` re-solving that line
/// (same geometry, E, ν and blank size cap); returns the number of lines.
pub fn raw_lines_matched(file: &str, refs: &[&CcxRef]) -> usize {
    let lines = json_lines(file);
    let n3 = json_lines("ccx_refine_n3_results.jsonl");
    assert_eq!(lines.len(), refs.len(), "{file}");
    let ccx = |l: &serde_json::Value| l["solver"].as_str().is_some_and(|s| s.starts_with("ccx 2.20 C3D10"));
    for r in refs {
        let values = [
            ("k_bend", r.k_bend),
            ("k_torsion", r.k_torsion),
            ("k_axial", r.k_axial),
            ("stress_per_moment_nodal", r.spm_nodal),
            ("stress_per_moment_ip", r.spm_ip),
        ];
        let matches = matching_lines(&lines, r.hinge, r.e, r.nu, &values, |l| ccx(l) && l["n"] == 4.0);
        assert_eq!(
            matches.len(),
            1,
            "{} (ν = {}): {} matching lines",
            r.hinge,
            r.nu,
            matches.len()
        );
        let [kb, kt, ka, spm] = r.n3;
        let values = [
            ("k_bend", kb),
            ("k_torsion", kt),
            ("k_axial", ka),
            ("stress_per_moment_nodal", spm),
        ];
        let coarse = matching_lines(&n3, r.hinge, r.e, r.nu, &values, |l| {
            ccx(l)
                && l["n"] == 3.0
                && l["source"] == file
                && l["index"] == matches[0]
                && l["hmax"] == lines[matches[0]]["hmax"]
        });
        assert_eq!(coarse.len(), 1, "{}: {} matching n = 3 lines", r.hinge, coarse.len());
    }
    lines.len()
}
