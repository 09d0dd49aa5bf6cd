//! The raw-results check and the scikit-fem values of tests/hinge_ccx_reference.rs.

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
/// and the five quantities to 6 digits) and that the file has no other line; returns the
/// number of lines.
pub fn raw_lines_matched(file: &str, refs: &[&CcxRef]) -> usize {
    let path = format!("{}/tools/{file}", env!("CARGO_MANIFEST_DIR"));
    let text = std::fs::read_to_string(&path).unwrap();
    let lines: Vec<serde_json::Value> = text.lines().map(|l| serde_json::from_str(l).unwrap()).collect();
    assert_eq!(lines.len(), refs.len(), "{file}");
    let close = |a: &serde_json::Value, b: f64| a.as_f64().is_some_and(|a| (a / b - 1.0).abs() < 1e-5);
    for r in refs {
        let spec: serde_json::Value = serde_json::from_str(r.hinge).unwrap();
        let matches = lines
            .iter()
            .filter(|l| spec.as_object().unwrap().iter().all(|(k, v)| l[k] == *v) && l["nu"] == r.nu)
            .filter(|l| {
                close(&l["k_bend"], r.k_bend)
                    && close(&l["k_torsion"], r.k_torsion)
                    && close(&l["k_axial"], r.k_axial)
                    && close(&l["stress_per_moment_nodal"], r.spm_nodal)
                    && close(&l["stress_per_moment_ip"], r.spm_ip)
                    && l["E"] == r.e
                    && l["solver"].as_str().is_some_and(|s| s.starts_with("ccx 2.20 C3D10"))
            })
            .count();
        assert_eq!(matches, 1, "{} (ν = {}): {matches} matching lines", r.hinge, r.nu);
    }
    lines.len()
}
