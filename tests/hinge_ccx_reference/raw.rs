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

pub fn json_lines(file: &str) -> Vec<serde_json::Value> {
    let path = format!("{}/tools/{file}", env!("CARGO_MANIFEST_DIR"));
    let text = std::fs::read_to_string(&path).unwrap_or_else(|e| panic!("{path}: {e}"));
    text.lines().map(|l| serde_json::from_str(l).unwrap()).collect()
}

/// Checks that every reference of `refs` is exactly one line of `tools/<file>` (geometry, E, ν
/// and the five quantities to 6 digits, at n = 4) and that the file has no other line, and that
/// its n = 3 values are the line of `tools/ccx_refine_n3_results.jsonl` re-solving that line
/// (same geometry, E, ν and blank size cap); returns the number of lines.
pub fn raw_lines_matched(file: &str, refs: &[&CcxRef]) -> usize {
    let lines = json_lines(file);
    let n3 = json_lines("ccx_refine_n3_results.jsonl");
    assert_eq!(lines.len(), refs.len(), "{file}");
    let close = |a: &serde_json::Value, b: f64| a.as_f64().is_some_and(|a| (a / b - 1.0).abs() < 1e-5);
    for r in refs {
        let spec: serde_json::Value = serde_json::from_str(r.hinge).unwrap();
        let same = |l: &&serde_json::Value| {
            spec.as_object().unwrap().iter().all(|(k, v)| l[k] == *v)
                && l["nu"] == r.nu
                && l["E"] == r.e
                && l["solver"].as_str().is_some_and(|s| s.starts_with("ccx 2.20 C3D10"))
        };
        let matches: Vec<usize> = (0..lines.len())
            .filter(|&i| same(&&lines[i]))
            .filter(|&i| {
                let l = &lines[i];
                close(&l["k_bend"], r.k_bend)
                    && close(&l["k_torsion"], r.k_torsion)
                    && close(&l["k_axial"], r.k_axial)
                    && close(&l["stress_per_moment_nodal"], r.spm_nodal)
                    && close(&l["stress_per_moment_ip"], r.spm_ip)
                    && l["n"].as_f64() == Some(4.0)
            })
            .collect();
        assert_eq!(matches.len(), 1, "{} (ν = {}): {} matching lines", r.hinge, r.nu, matches.len());
        let coarse: Vec<&serde_json::Value> = n3
            .iter()
            .filter(|l| l["source"] == file && l["index"].as_u64() == Some(matches[0] as u64))
            .filter(same)
            .filter(|l| l["n"].as_f64() == Some(3.0) && l["hmax"] == lines[matches[0]]["hmax"])
            .collect();
        assert_eq!(coarse.len(), 1, "{}: n = 3 lines", r.hinge);
        let keys = ["k_bend", "k_torsion", "k_axial", "stress_per_moment_nodal"];
        for (key, v) in keys.iter().zip(r.n3) {
            assert!(close(&coarse[0][key], v), "{}: n = 3 {key} = {v}", r.hinge);
        }
    }
    lines.len()
}
