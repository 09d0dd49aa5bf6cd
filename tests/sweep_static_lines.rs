//! The default line and CSV of a `static` sweep: the displacements of the nodes each load case
//! loads or prescribes (not of every node), peak stresses and utilisations, without the
//! per-element lists; `--full` keeps the whole result.

mod common;
use common::*;
use serde_json::{json, Value};

/// The parallelogram guide (`cases/parallelogram_guide.json`): load case 0 pushes node 8 along x
/// with F = 1, 2 N; load case 1 prescribes ux = 1 mm at node 8.
fn guide_sweep() -> String {
    let mut base: Value =
        serde_json::from_str(&std::fs::read_to_string(root().join("cases/parallelogram_guide.json")).unwrap()).unwrap();
    base["mesh"] = json!(root().join("meshes/parallelogram_notch.json").to_str().unwrap());
    json!({"analysis": "sweep", "base": base, "vary": {"load_cases.0.forces.0.F.0": [1, 2]}}).to_string()
}

/// The cells of a CSV line (quoted cells may hold commas; no quotes inside them here).
fn cells(line: &str) -> Vec<String> {
    let (mut out, mut cur, mut quoted) = (Vec::new(), String::new(), false);
    for c in line.chars() {
        match c {
            '"' => quoted = !quoted,
            ',' if !quoted => out.push(std::mem::take(&mut cur)),
            _ => cur.push(c),
        }
    }
    out.push(cur);
    out
}

/// The CSV cell of `column` in data row `row`.
fn cell(csv: &str, row: usize, column: &str) -> f64 {
    let head = cells(csv.lines().next().unwrap());
    let k = head
        .iter()
        .position(|h| h == column)
        .unwrap_or_else(|| panic!("no column {column} in {head:?}"));
    let line = cells(csv.lines().nth(row + 1).unwrap());
    assert_eq!(line.len(), head.len());
    line[k].parse().unwrap()
}

/// Default: node 8's six displacements per load case are columns (equal to the full result's row
/// 8), no other node's are; the lateral compliance is 0.10620 mm/N (the README's parallelogram
/// guide: 1/0.10620 = 9.4165 N/mm), so F = 2 N gives twice that (linear) to 1e-12. Lines lose the
/// per-element stress lists and hinge end forces but keep each hinge's peak stress and
/// utilisation, and are less than half the `--full` line.
#[test]
fn static_sweep_keeps_the_loaded_nodes_displacements() {
    let d = tempdir("static_lines");
    let case = write(&d, "sweep.json", &guide_sweep());
    let csv_path = d.join("out.csv");
    let o = sweep(&d, &[case.to_str().unwrap(), "--csv", csv_path.to_str().unwrap()]);
    assert_eq!(o.status.code(), Some(0), "{}", stderr(&o));
    let lines = parse_lines(&stdout(&o));
    let full = parse_lines(&stdout(&sweep(&d, &[case.to_str().unwrap(), "--full"])));
    assert_eq!((lines.len(), full.len()), (2, 2));
    let csv = std::fs::read_to_string(&csv_path).unwrap();
    let head = csv.lines().next().unwrap();
    let displacement_columns = head.split(',').filter(|h| h.contains(".displacements.")).count();
    assert_eq!(displacement_columns, 2 * 6, "{head}");
    for (row, f) in [1.0, 2.0].into_iter().enumerate() {
        let ux = cell(&csv, row, "load_cases.0.displacements.8.0");
        assert!((ux / (0.106196 * f) - 1.0).abs() < 1e-4, "ux(8) = {ux} mm at F = {f} N");
        let line = lines.iter().find(|l| l["index"] == row).unwrap();
        let whole = full.iter().find(|l| l["index"] == row).unwrap();
        for (k, node_row) in whole["result"]["load_cases"].as_array().unwrap().iter().enumerate() {
            assert_eq!(
                line["result"]["load_cases"][k]["displacements"],
                json!({"8": node_row["displacements"][8]})
            );
        }
        let stroke = cell(&csv, row, "load_cases.1.displacements.8.0");
        assert!((stroke - 1.0).abs() < 1e-12, "prescribed ux(8) = {stroke}");
        let lc = &line["result"]["load_cases"][0];
        assert!(lc.get("element_von_mises").is_none() && lc["hinges"][0].get("end_forces").is_none());
        assert_eq!(
            lc["hinges"][0]["utilisation"],
            whole["result"]["load_cases"][0]["hinges"][0]["utilisation"]
        );
        let (short, long) = (line.to_string().len(), whole.to_string().len());
        // Measured 3,884 B against 6,529 B (0.59): the full line no longer carries the hinges'
        // inner segment nodes (hidden by default), so the gap is the per-element stress lists and
        // hinge end forces the default line leaves out.
        assert!(
            (short as f64) < 0.62 * long as f64,
            "default line {short} B vs full {long} B"
        );
    }
    cleanup(&d);
}

/// The nodes a case names as outputs are kept too: with a `compliance` request at node 5 and a
/// displacement metric at node 3, every load case's line keeps the rows of nodes 3, 5 and 8
/// (the loaded one), each equal to the full result's row; the `compliance` block and `metrics`
/// stay whole and the echo of the materials goes.
#[test]
fn static_sweep_keeps_the_nodes_named_as_outputs() {
    let d = tempdir("static_named_nodes");
    let mut s: Value = serde_json::from_str(&guide_sweep()).unwrap();
    s["base"]["compliance"] = json!([{"node": 5}]);
    s["base"]["metrics"] =
        json!([{"name": "d3", "kind": "displacement", "node": 3, "dof": "ux", "load_case": "push_x_1N"}]);
    let case = write(&d, "sweep.json", &s.to_string());
    let o = sweep(&d, &[case.to_str().unwrap()]);
    assert_eq!(o.status.code(), Some(0), "{}", stderr(&o));
    let lines = parse_lines(&stdout(&o));
    let full = parse_lines(&stdout(&sweep(&d, &[case.to_str().unwrap(), "--full"])));
    assert_eq!((lines.len(), full.len()), (2, 2));
    for line in &lines {
        let whole = full.iter().find(|l| l["index"] == line["index"]).unwrap();
        let (r, w) = (&line["result"], &whole["result"]);
        let cases = w["load_cases"].as_array().unwrap();
        assert_eq!(cases.len(), 2);
        for (k, case) in cases.iter().enumerate() {
            let rows = &case["displacements"];
            assert_eq!(
                r["load_cases"][k]["displacements"],
                json!({"3": rows[3], "5": rows[5], "8": rows[8]}),
                "load case {k}"
            );
        }
        assert_eq!(r["compliance"], w["compliance"]);
        assert_eq!(r["metrics"], w["metrics"]);
        let d3 = r["metrics"]["d3"].as_f64().unwrap();
        assert!((d3 - w["load_cases"][0]["displacements"][3][0].as_f64().unwrap()).abs() <= 1e-15 * d3.abs());
        assert!(r.get("materials").is_none() && w.get("materials").is_some());
    }
    cleanup(&d);
}

/// A modal sweep's default line keeps every mode's frequency (the first one of a clamped
/// steel bar, 10 Euler–Bernoulli elements, within 0.1 % of f₁ = (1.8751²/2π)·√(EI/(ρAL⁴)),
/// S. P. Timoshenko, D. H. Young, W. Weaver, Vibration Problems in Engineering, 4th ed., Wiley
/// 1974, §5.3) and leaves out the mode shapes and the echo of the materials (`--full` keeps them).
#[test]
fn modal_sweep_line_keeps_frequencies_not_shapes() {
    let d = tempdir("modal_lines");
    let nodes: Vec<Value> = (0..=10).map(|i| json!([20.0 * i as f64, 0, 0])).collect();
    let elements: Vec<Value> = (0..10)
        .map(|i| json!({"type": "beam", "nodes": [i, i + 1], "section": "bar", "material": "steel", "up": [0, 0, 1], "shear": false}))
        .collect();
    let s = json!({"analysis": "sweep",
        "base": {"analysis": "modal", "modes": 2, "shapes": true, "materials": {"steel": "steel"},
                 "sections": {"bar": {"shape": "rect", "w": 10, "h": 2}},
                 "nodes": nodes, "elements": elements,
                 "supports": [{"node": 0, "fix": ["ux", "uy", "uz", "rx", "ry", "rz"]}]},
        "vary": {"sections.bar.h": [2, 3]}});
    let case = write(&d, "sweep.json", &s.to_string());
    let o = sweep(&d, &[case.to_str().unwrap()]);
    assert_eq!(o.status.code(), Some(0), "{}", stderr(&o));
    let lines = parse_lines(&stdout(&o));
    let full = parse_lines(&stdout(&sweep(&d, &[case.to_str().unwrap(), "--full"])));
    assert_eq!((lines.len(), full.len()), (2, 2));
    for line in &lines {
        let h = line["params"]["sections.bar.h"].as_f64().unwrap();
        let whole = full.iter().find(|l| l["index"] == line["index"]).unwrap();
        let (r, w) = (&line["result"], &whole["result"]);
        let modes = r["modes"].as_array().unwrap();
        assert_eq!(modes.len(), 2);
        for (k, m) in modes.iter().enumerate() {
            assert!(m.get("shape").is_none() && w["modes"][k].get("shape").is_some());
            assert_eq!(m["frequency_hz"], w["modes"][k]["frequency_hz"]);
        }
        assert!(r.get("materials").is_none());
        let steel = &w["materials"]["steel"];
        let (e, rho) = (steel["E"].as_f64().unwrap(), steel["density"].as_f64().unwrap());
        // Bending about the weaker axis (thickness h along the `up` axis z).
        let (b, l) = (10.0, 200.0f64);
        let (area, i) = (b * h, b * h * h * h / 12.0);
        let f1 = 1.8751f64.powi(2) / (2.0 * std::f64::consts::PI) * (e * i / (rho * area * l.powi(4))).sqrt();
        let got = modes[0]["frequency_hz"].as_f64().unwrap();
        assert!(
            (got / f1 - 1.0).abs() < 1e-3,
            "h = {h}: f1 = {got} Hz, Euler–Bernoulli {f1} Hz"
        );
    }
    cleanup(&d);
}
