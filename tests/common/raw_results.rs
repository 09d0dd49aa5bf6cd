//! The raw-results check of the solid-reference tests (tests/hinge_ccx_reference.rs,
//! tests/hinge_solid_reference.rs): every reference value copied into a test is one line of the
//! reference tool's JSON-lines output under `tools/`.

/// The lines of `tools/<file>`, one JSON object each.
pub fn json_lines(file: &str) -> Vec<serde_json::Value> {
    let path = format!("{}/tools/{file}", env!("CARGO_MANIFEST_DIR"));
    let text = std::fs::read_to_string(&path).unwrap_or_else(|e| panic!("{path}: {e}"));
    text.lines().map(|l| serde_json::from_str(l).unwrap()).collect()
}

/// The indices of the lines of `lines` with the geometry of `hinge` (its JSON fields), Young's
/// modulus `e`, Poisson's ratio `nu`, every `(field, value)` of `values` to 1e-5 relative and
/// `extra` true.
pub fn matching_lines(
    lines: &[serde_json::Value],
    hinge: &str,
    e: f64,
    nu: f64,
    values: &[(&str, f64)],
    extra: impl Fn(&serde_json::Value) -> bool,
) -> Vec<usize> {
    let spec: serde_json::Value = serde_json::from_str(hinge).unwrap();
    let close = |a: &serde_json::Value, b: f64| a.as_f64().is_some_and(|a| (a / b - 1.0).abs() < 1e-5);
    (0..lines.len())
        .filter(|&i| {
            let l = &lines[i];
            spec.as_object().unwrap().iter().all(|(k, v)| l[k] == *v)
                && l["nu"] == nu
                && l["E"] == e
                && values.iter().all(|&(k, v)| close(&l[k], v))
                && extra(l)
        })
        .collect()
}
