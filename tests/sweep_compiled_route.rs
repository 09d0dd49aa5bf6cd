//! The compiled route of `flexfem sweep` over a parameterised mesh case (case and mesh file
//! compiled once, each design's parameter values set in a parsed case) against the value route
//! (each design built as JSON, its mesh file read, resolved and parsed): the same lines, byte
//! for byte, over the parameterised pan-tilt mechanism with hinge dimensions varied and the
//! platform height `$H` moving four nodes, designs whose hinge is invalid and designs whose
//! parameter expression divides by zero (error rows), in the default and full line formats.
//!
//! Source of the expectation: the value route is the reference (it is what earlier outputs
//! hold, so resumed sweeps keep matching).

use flexfem::analysis::{self, Case};
use flexfem::case::sweep::Sweep;
use flexfem::design::sweep::{
    omitted_fields, run_design_formatted, run_sweep_formatted, takes_compiled_route, LineFormat, Shard,
};
use flexfem::fem::SolverCache;
use std::collections::HashSet;
use std::sync::Mutex;

fn sweep(json: &str) -> Sweep {
    match analysis::parse(json) {
        Ok(Case::Sweep(s)) => s.build().expect("sweep builds"),
        other => panic!("not a sweep: {other:?}"),
    }
}

/// The format `flexfem sweep --out` uses for a static sweep (`full`: `--full`).
fn format(full: bool, notes_by_ref: bool) -> LineFormat {
    LineFormat {
        fields: None,
        notes_by_ref,
        omit: if full {
            Vec::new()
        } else {
            omitted_fields("static").iter().map(|p| p.to_string()).collect()
        },
        loaded_displacements: !full,
    }
}

/// Every line of the sweep by index, with its notes, as the sweep driver writes them.
fn driver_lines(s: &Sweep, format: &LineFormat) -> Vec<(usize, String, Option<String>)> {
    let rows = Mutex::new(Vec::new());
    run_sweep_formatted(s, None, Shard::ALL, &HashSet::new(), format, false, |l| {
        let notes = l.notes.map(|(r, json)| format!("{r}={json}"));
        rows.lock().unwrap().push((l.index, l.text.to_string(), notes));
        Ok(())
    })
    .expect("sink never fails");
    let mut rows = rows.into_inner().unwrap();
    rows.sort();
    rows
}

/// Every line of the sweep on the value route, design by design.
fn value_lines(s: &Sweep, format: &LineFormat) -> Vec<(usize, String, Option<String>)> {
    let mut cache = SolverCache::new();
    (0..s.len())
        .map(|i| {
            let row = run_design_formatted(s, None, i, &mut cache, format);
            let notes = row.notes_json.map(|json| format!("{}={json}", row.notes.unwrap().0));
            (i, row.line, notes)
        })
        .collect()
}

const PANTILT: &str = r#"{"analysis": "sweep",
  "base": {"analysis": "static", "mesh": "meshes/pantilt_8r_parameters.json",
           "parameters": {"M": "10 * 8 / ($H - 70)"},
           "load_cases": [{"name": "tilt", "forces": [{"node": 13, "F": [0, 0, 0, "$M", "$M", 0]}]}]},
  "vary": {"parameters.t": [0.5, -0.2, 0.8],
           "parameters.R": [1.25, 2.25],
           "parameters.H": [62.0, 70.0, 78]}}"#;

/// Same lines on both routes, the compiled route taken, the invalid designs error rows: 18
/// designs, 6 with t = −0.2 mm (no hinge) and 4 more with H = 70 mm (M divides by zero).
#[test]
fn compiled_route_gives_the_value_route_lines() {
    let s = sweep(PANTILT);
    assert_eq!(s.len(), 18);
    for (full, by_ref) in [(false, true), (true, false)] {
        let f = format(full, by_ref);
        assert!(takes_compiled_route(&s, None, &f), "the compiled route is taken");
        let driver = driver_lines(&s, &f);
        let value = value_lines(&s, &f);
        assert_eq!(driver.len(), value.len());
        assert_eq!(driver.len(), 18);
        for (d, v) in driver.iter().zip(&value) {
            assert_eq!(d, v, "design {} (full {full}, notes by reference {by_ref})", v.0);
        }
        let errors: Vec<usize> = value
            .iter()
            .filter(|(_, l, _)| l.contains("\"error\":"))
            .map(|r| r.0)
            .collect();
        assert_eq!(errors, [1, 4, 6, 7, 8, 9, 10, 11, 13, 16], "error rows");
        assert!(value[4].1.contains("parameters.M"), "{}", value[4].1);
        // $H moves the platform nodes: the loaded node's displacement differs between heights.
        let tilt = |i: usize| value[i].1.split("\"displacements\":").nth(1).unwrap()[..60].to_string();
        assert_ne!(tilt(0), tilt(2));
    }
}

/// The route is not taken where it cannot give the same lines: a varied path that is not a
/// parameter, and a case without parameters.
#[test]
fn compiled_route_only_for_parameter_axes() {
    let hinge_path = PANTILT.replace(
        "\"parameters.R\": [1.25, 2.25]",
        "\"load_cases.0.name\": [\"a\", \"b\"]",
    );
    let s = sweep(&hinge_path);
    assert_eq!(s.len(), 18);
    assert!(!takes_compiled_route(&s, None, &format(false, true)));
    let plain = r#"{"analysis": "sweep",
      "base": {"analysis": "static", "nodes": [[0, 0, 0], [100, 0, 0]],
               "materials": {"al": "Al7075"}, "sections": {"s": {"shape": "rect", "w": 10, "h": 5}},
               "elements": [{"type": "beam", "nodes": [0, 1], "section": "s", "material": "al", "up": [0, 0, 1]}],
               "supports": [{"node": 0, "fix": ["ux", "uy", "uz", "rx", "ry", "rz"]}],
               "load_cases": [{"name": "tip", "forces": [{"node": 1, "F": [0, 0, 1, 0, 0, 0]}]}]},
      "vary": {"load_cases.0.forces.0.F.2": [1, 2]}}"#;
    let s = sweep(plain);
    assert_eq!(s.len(), 2);
    assert!(!takes_compiled_route(&s, None, &format(false, true)));
}

/// Lines written straight from the result (no JSON value) against the value route: two load
/// cases loading different nodes, a compliance request and a metric naming two more nodes, so
/// each load case's displacements keep their own rows (tilt: nodes 13, 14, 15; push: 9, 12, 14,
/// 15), with the materials and parameters echoed (`--full`); 12 designs, byte for byte.
#[test]
fn compiled_lines_keep_each_load_case_rows() {
    let s = sweep(
        r#"{"analysis": "sweep",
      "base": {"analysis": "static", "mesh": "meshes/pantilt_8r_parameters.json",
               "parameters": {"M": 10.0},
               "compliance": [{"node": 15}],
               "metrics": [{"name": "k_x", "kind": "stiffness", "node": 14, "dof": "ux"}],
               "load_cases": [{"name": "tilt", "forces": [{"node": 13, "F": [0, 0, 0, "$M", "$M", 0]}]},
                              {"name": "push", "forces": [{"node": 12, "F": [1, 0, 0, 0, 0, 0]},
                                                          {"node": 9, "F": [0, 0, "$M", 0, 0, 0]}]}]},
      "vary": {"parameters.t": [0.5, 0.8], "parameters.R": [1.25, 2.25], "parameters.H": [62.0, 70.0, 78]}}"#,
    );
    assert_eq!(s.len(), 12);
    for (full, by_ref) in [(false, true), (false, false), (true, true)] {
        let f = format(full, by_ref);
        assert!(takes_compiled_route(&s, None, &f), "the compiled route is taken");
        let driver = driver_lines(&s, &f);
        let value = value_lines(&s, &f);
        assert_eq!(driver.len(), 12);
        assert_eq!(value.len(), 12);
        for (d, v) in driver.iter().zip(&value) {
            assert_eq!(d, v, "design {} (full {full}, notes by reference {by_ref})", v.0);
            assert!(!v.1.contains("\"error\":"), "{}", v.1);
        }
        let line: serde_json::Value = serde_json::from_str(&value[0].1).unwrap();
        let result = &line["result"];
        assert_eq!(result["parameters"]["H"], 62.0);
        assert_eq!(result["materials"]["nylon"]["name"].as_str(), full.then_some("nylon66"));
        if !full {
            let rows = |k: usize| -> Vec<String> {
                let d = result["load_cases"][k]["displacements"].as_object().unwrap();
                d.keys().cloned().collect()
            };
            assert_eq!(rows(0), ["13", "14", "15"]);
            assert_eq!(rows(1), ["9", "12", "14", "15"]);
        }
    }
}
