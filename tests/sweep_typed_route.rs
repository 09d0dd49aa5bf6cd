//! The typed route of `flexfem sweep` (each worker sets the varied numbers in its parsed case
//! and writes the result straight into its line buffer) against the value route (each design
//! built as JSON, parsed, its result made a JSON value and edited): the same lines, byte for
//! byte, over whole sweeps of hinges and stages — every family, varied loads and geometry,
//! failing designs, default and full line formats, notes in the line or by reference — and no
//! heap allocation per design on the typed route.
//!
//! Source of the expectation: the value route is the reference (it is what earlier outputs
//! hold, so resumed sweeps keep matching); the allocation count is the issue's requirement.

use flexfem::analysis::{self, Case};
use flexfem::case::sweep::Sweep;
use flexfem::design::sweep::{omitted_fields, run_sweep_formatted, LineFormat, Shard};
use std::collections::HashSet;
use std::sync::atomic::{AtomicUsize, Ordering};
use std::sync::Mutex;

#[path = "common/counting_alloc.rs"]
mod counting;

fn sweep(json: &str) -> Sweep {
    match analysis::parse(json) {
        Ok(Case::Sweep(s)) => s.build().expect("sweep builds"),
        other => panic!("not a sweep: {other:?}"),
    }
}

/// The format `flexfem sweep --out` uses for a sweep of `kind` (`full`: `--full`).
fn format(kind: &str, full: bool, notes_by_ref: bool) -> LineFormat {
    LineFormat {
        fields: None,
        notes_by_ref,
        omit: if full {
            Vec::new()
        } else {
            omitted_fields(kind).iter().map(|p| p.to_string()).collect()
        },
        loaded_displacements: !full && kind == "static",
    }
}

/// Every line of the sweep by index, and how many came without a JSON value (typed route).
fn lines(s: &Sweep, format: &LineFormat, want_values: bool) -> (Vec<(usize, String, Option<String>)>, usize) {
    let rows = Mutex::new(Vec::new());
    let typed = AtomicUsize::new(0);
    run_sweep_formatted(s, None, Shard::ALL, &HashSet::new(), format, want_values, |l| {
        if l.value.is_none() {
            typed.fetch_add(1, Ordering::Relaxed);
        }
        let notes = l.notes.map(|(r, json)| format!("{r}={json}"));
        rows.lock().unwrap().push((l.index, l.text.to_string(), notes));
        Ok(())
    })
    .expect("sink never fails");
    let mut rows = rows.into_inner().unwrap();
    rows.sort();
    (rows, typed.into_inner())
}

/// Both routes give the same lines; returns (designs, typed-route lines, error rows).
fn same_lines(json: &str, kind: &str) -> (usize, usize, usize) {
    let s = sweep(json);
    let mut seen = (s.len(), usize::MAX, 0);
    for (full, by_ref) in [(false, true), (true, false), (false, false)] {
        let f = format(kind, full, by_ref);
        let (value_route, none) = lines(&s, &f, true);
        assert_eq!(none, 0, "want_values: every line has its value");
        let (typed_route, typed) = lines(&s, &f, false);
        assert_eq!(value_route.len(), s.len());
        for (v, t) in value_route.iter().zip(&typed_route) {
            assert_eq!(v, t, "design {} (full {full}, notes by reference {by_ref})", v.0);
        }
        let errors = value_route.iter().filter(|(_, l, _)| l.contains("\"error\":")).count();
        seen = (s.len(), typed.min(seen.1), errors);
    }
    seen
}

/// Every hinge family, dimensions and blank varied, some designs invalid (t ≥ h).
#[test]
fn hinge_sweeps_give_the_value_route_lines() {
    let families = [
        r#"{"type": "circular_notch", "R": 8, "t": 2, "w": 10, "h": 10, "blank_length": 20}"#,
        r#"{"type": "elliptical_notch", "ax": 6, "ay": 3, "t": 2, "w": 10, "h": 10, "blank_length": 5}"#,
        r#"{"type": "corner_filleted", "l": 10, "R": 2, "t": 2, "w": 10, "h": 10, "blank_length": 5}"#,
        r#"{"type": "leaf", "l": 8, "t": 1, "w": 10, "h": 10, "blank_length": 5}"#,
        r#"{"type": "spherical_neck", "l": 5, "t": 3, "R": 4, "h": 10, "blank_length": 5}"#,
    ];
    for hinge in families {
        let json = format!(
            r#"{{"analysis": "sweep", "base": {{"analysis": "hinge", "material": "steel", "hinge": {hinge}}},
                "vary": {{"hinge.t": [0.5, 1.5, 2.5, 9, 12], "hinge.blank_length": [0, 7.5], "hinge.h": [10, 11.25]}}}}"#
        );
        let (n, typed, errors) = same_lines(&json, "hinge");
        assert_eq!(n, 20);
        // t = 12 > h: refused by validation (value-route error rows); the rest typed.
        assert!(errors >= 4, "{hinge}: {errors} error rows");
        assert_eq!(typed, n - errors, "{hinge}: every valid design takes the typed route");
    }
}

/// Stage sweeps: hinge dimensions, leg section, geometry, load-case forces and strokes.
#[test]
fn stage_sweeps_give_the_value_route_lines() {
    let json = r#"{"analysis": "sweep",
        "base": {"analysis": "stage", "material": "Al7075",
            "stage": {"L": 109.215, "b": 47.91, "alpha0_deg": 45, "gamma_deg": 0, "leg": {"w": 10, "h": 10},
                      "revolute": {"type": "corner_filleted", "l": 10, "R": 2, "t": 2},
                      "spherical": {"type": "spherical_neck", "l": 5, "t": 3, "R": 4}},
            "load_cases": [{"name": "F20", "actuator_forces": [20, 20, 20]},
                           {"name": "tilt", "actuator_strokes": [0.1, -0.1, 0.0]}]},
        "vary": {"stage.revolute.t": [1.5, 3], "stage.leg.h": [9, 12], "stage.alpha0_deg": [40, 55],
                 "stage.spherical.R": [2, 5], "load_cases.0.actuator_forces.1": [5, 30.5],
                 "load_cases.1.actuator_strokes.2": [0, 0.2], "stage.revolute.l": [3, 10]}}"#;
    let (n, typed, errors) = same_lines(json, "stage");
    assert_eq!(n, 128);
    // revolute l = 3 < 2R = 4: refused (value-route error rows); the rest typed.
    assert_eq!(errors, 64);
    assert_eq!(typed, 64);
}

/// The bundled sweeps take the typed route for every design.
#[test]
fn bundled_sweeps_take_the_typed_route() {
    for (file, kind) in [
        ("ruiz2019_hinge_sweep.json", "hinge"),
        ("ruiz2019_stage_sweep.json", "stage"),
    ] {
        let text = std::fs::read_to_string(format!("{}/cases/{file}", env!("CARGO_MANIFEST_DIR"))).unwrap();
        let (n, typed, errors) = same_lines(&text, kind);
        assert_eq!((typed, errors), (n, 0), "{file}");
    }
}

/// Allocations made between the first and the last line of a sweep run on one worker thread
/// (every design but the first, set-up excluded), with a sink that keeps nothing; and the lines.
fn allocations(s: &Sweep, f: &LineFormat) -> (usize, usize) {
    let pool = rayon::ThreadPoolBuilder::new().num_threads(1).build().unwrap();
    pool.install(|| {
        let first = Mutex::new(None);
        let last = AtomicUsize::new(0);
        let n = AtomicUsize::new(0);
        run_sweep_formatted(s, None, Shard::ALL, &HashSet::new(), f, false, |l| {
            // The sink runs on the worker thread: its own count (other threads of the test
            // process, e.g. the harness reporting another test, are not counted).
            let now = counting::allocations();
            assert!(l.value.is_none() && !l.failed, "{}", l.text);
            first.lock().unwrap().get_or_insert(now);
            last.store(now, Ordering::Relaxed);
            n.fetch_add(1, Ordering::Relaxed);
            Ok(())
        })
        .unwrap();
        let first = first.into_inner().unwrap().expect("lines");
        (last.into_inner() - first, n.into_inner())
    })
}

#[test]
fn typed_route_allocates_nothing_per_design() {
    let hinge = |n: usize| {
        format!(
            r#"{{"analysis": "sweep", "base": {{"analysis": "hinge", "material": "Al7075",
                 "hinge": {{"type": "circular_notch", "R": 8, "t": 2, "w": 10, "h": 10, "blank_length": 20}}}},
                 "vary": {{"hinge.t": {{"from": 1, "to": 3, "steps": {n}}}, "hinge.R": [8, 10, 12, 16]}}}}"#
        )
    };
    let stage = |n: usize| {
        format!(
            r#"{{"analysis": "sweep", "base": {{"analysis": "stage", "material": "Al7075",
                 "stage": {{"L": 109.215, "b": 47.91, "alpha0_deg": 45, "gamma_deg": 0, "leg": {{"w": 10, "h": 10}},
                            "revolute": {{"type": "circular_notch", "R": 8, "t": 2}},
                            "spherical": {{"type": "spherical_neck", "l": 5, "t": 3, "R": 4}}}},
                 "load_cases": [{{"name": "F20", "actuator_forces": [20, 20, 20]}}]}},
                 "vary": {{"stage.revolute.t": {{"from": 1.5, "to": 3, "steps": {n}}}, "stage.spherical.l": [3, 5, 7, 9]}}}}"#
        )
    };
    for (kind, make) in [("hinge", &hinge as &dyn Fn(usize) -> String), ("stage", &stage)] {
        for by_ref in [true, false] {
            let f = format(kind, false, by_ref);
            let (count, lines) = allocations(&sweep(&make(50)), &f);
            assert_eq!(lines, 200);
            assert_eq!(
                count, 0,
                "{kind} (notes by reference {by_ref}): {count} allocations in 199 designs"
            );
        }
    }
}
