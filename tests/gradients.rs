//! Gradients of metrics with respect to case parameters (`flexfem::gradient`, `"gradients":
//! true`): every entry against central differences of full runs (`flexfem run` of the case at
//! p ± δ, p ± 2δ, fourth-order stencil [1, −8, 8, −1]/(12δ), δ = 3e-3·max(|p|, 1): truncation
//! δ⁴ f⁽⁵⁾/30 ≈ 1e-11 and round-off ≈ κ/δ ≈ 1.5e-8 of the values with κ ≈ 3e-11 the relative
//! round-off of a full run (measured: the difference changes by that much between δ = 1e-2 and
//! 1e-3), so the reference is good to ≈ 1e-8), on the parallelogram guide, the lever amplifier and the pan-tilt; and the
//! parallelogram's stiffness elasticities against the closed form of the thin circular notch
//! (J. M. Paros, L. Weisbord, "How to design flexure hinges", Machine Design 37, 1965:
//! k = 2 E w t^{5/2} / (9 π R^{1/2})), K = 4k/L² for the guide.
//!
//! Tolerance: |g − g_fd| ≤ 1e-6 · max(|g_fd|, floor), floor = 1e-2 · max_k |g_fd,k · p_k| / |p_j|:
//! entries more than a hundred times below the metric's largest sensitivity to a relative
//! change of a parameter are compared at that absolute floor (1e-8 of the largest; the full
//! runs resolve no better).

mod common;
use common::root;
use flexfem::analysis;
use flexfem::case::params::tangent::Written;
use flexfem::gradient::{Gradients, Linear, Target};
use serde_json::{json, Value};
use std::sync::Arc;

/// Where a target's value is in a full run's JSON.
enum Probe {
    /// `metrics.NAME` (a stroke's `stroke`).
    Metric(String),
    /// `load_cases[CASE].hinges[i].peak_von_mises` of case element `element`.
    HingeVonMises(usize, usize),
    /// Mode `n`'s `frequency_hz` of the same model run as `modal`.
    Frequency(usize),
}

fn run_json(case: &Value, dir: &std::path::Path) -> Value {
    let c = analysis::parse_value(case.clone(), Some(dir)).unwrap_or_else(|e| panic!("{e}"));
    analysis::run(&c).unwrap_or_else(|e| panic!("{e}")).json
}

/// The value of `probe` from full runs of `case` with `params` set.
fn full(case: &Value, dir: &std::path::Path, probe: &Probe) -> f64 {
    match probe {
        Probe::Metric(n) => {
            let out = run_json(case, dir);
            let m = &out["metrics"][n];
            m.as_f64()
                .or_else(|| m["stroke"].as_f64())
                .unwrap_or_else(|| panic!("{n}: {m}"))
        }
        Probe::HingeVonMises(lc, e) => {
            let out = run_json(case, dir);
            let hs = out["load_cases"][*lc]["hinges"].as_array().unwrap().clone();
            let h = hs.iter().find(|h| h["element"] == json!(e)).unwrap();
            h["peak_von_mises"].as_f64().unwrap()
        }
        Probe::Frequency(n) => {
            let mut m = case.clone();
            let o = m.as_object_mut().unwrap();
            for k in ["load_cases", "metrics", "gradients", "output"] {
                o.remove(k);
            }
            o.insert("analysis".into(), json!("modal"));
            o.insert("modes".into(), json!(n + 1));
            o.insert("shapes".into(), json!(false));
            let out = run_json(&m, dir);
            out["modes"][n - 1]["frequency_hz"].as_f64().unwrap()
        }
    }
}

/// d probe / d `name` by the fourth-order central difference of full runs.
fn central(case: &Value, dir: &std::path::Path, probe: &Probe, name: &str, p: f64) -> f64 {
    let d = 3e-3 * p.abs().max(1.0);
    let at = |x: f64| {
        let mut c = case.clone();
        c["parameters"][name] = json!(x);
        full(&c, dir, probe)
    };
    (at(p - 2.0 * d) - 8.0 * at(p - d) + 8.0 * at(p + d) - at(p + 2.0 * d)) / (12.0 * d)
}

/// Checks every entry of `g` against full-run differences; returns the largest error relative
/// to the tolerance's scale.
fn check(g: &Gradients, case: &Value, dir: &std::path::Path, probes: &[Probe], params: &[(&str, f64)]) -> f64 {
    assert_eq!(g.targets.len(), probes.len(), "{:?}", g.targets);
    assert_eq!(g.parameters.len(), params.len(), "{:?}", g.parameters);
    let mut worst = 0.0f64;
    for (i, probe) in probes.iter().enumerate() {
        let fd: Vec<f64> = params.iter().map(|&(n, p)| central(case, dir, probe, n, p)).collect();
        let scale = params
            .iter()
            .zip(&fd)
            .map(|((_, p), f)| (f * p).abs())
            .fold(0.0, f64::max);
        for (j, &(name, p)) in params.iter().enumerate() {
            let got = g.get(&g.targets[i], name).unwrap();
            let floor = 1e-2 * scale / p.abs().max(1e-300);
            let err = (got - fd[j]).abs() / fd[j].abs().max(floor);
            println!(
                "{:>24} / {name:<3}: {got:+.10e} vs {:+.10e} (rel {err:.1e})",
                g.targets[i], fd[j]
            );
            assert!(
                err <= 1e-6,
                "d {} / d {name}: gradient {got:e}, full-run difference {:e} (relative {err:.2e})",
                g.targets[i],
                fd[j]
            );
            worst = worst.max(err);
        }
    }
    worst
}

fn written(case: &Value, dir: &std::path::Path) -> Arc<Written> {
    let c = analysis::case_file::parse_resolved(case.clone(), Some(dir), true).unwrap_or_else(|e| panic!("{e}"));
    match c.case {
        analysis::Case::Static(s) => s.written.clone().expect("kept for gradients"),
        _ => panic!("a static case"),
    }
}

fn parallelogram() -> Value {
    json!({
        "analysis": "static",
        "mesh": "parallelogram_parameters.json",
        "parameters": {"t": 0.8, "F": 1.0},
        "load_cases": [
            {"name": "push_x", "forces": [{"node": 8, "F": ["$F", "0.2*$F", 0, 0, 0, "3*$F"]}]},
            {"name": "stroke_1mm", "displacements": [{"node": 8, "dof": "ux", "value": 1}]}
        ],
        "metrics": [
            {"name": "k_x", "kind": "stiffness", "node": 8, "dof": "ux"},
            {"name": "c_rz", "kind": "compliance", "node": 2, "dof": "rz"},
            {"name": "u_x", "kind": "displacement", "node": 8, "dof": "ux", "load_case": "push_x"},
            {"name": "theta", "kind": "hinge_rotation", "element": 0, "load_case": "push_x"},
            {"name": "util", "kind": "max_utilisation", "load_case": "stroke_1mm"},
            {"name": "stroke", "kind": "stroke_at_allowable", "node": 8, "dof": "ux", "load_case": "stroke_1mm"}
        ],
        "gradients": true
    })
}

/// The parallelogram guide (four circular notches of one hinge type, rigid links between them):
/// stiffness, compliance at a rigid-link slave, displacement, hinge rotation, utilisation,
/// stroke at allowable, a hinge's peak stress and the first two frequencies, with respect to the
/// notch t, R, the leg length L (node coordinates and rigid-link arms), the span B, the width w
/// and the load F.
#[test]
fn parallelogram_gradients_match_full_run_differences() {
    let dir = root().join("meshes");
    let case = parallelogram();
    let mut targets: Vec<Target> = ["k_x", "c_rz", "u_x", "theta", "util", "stroke"]
        .iter()
        .map(|n| Target::Metric(n.to_string()))
        .collect();
    targets.push(Target::VonMises {
        load_case: "push_x".into(),
        element: 2,
    });
    targets.push(Target::Frequency { mode: 1 });
    targets.push(Target::Frequency { mode: 2 });
    let params = [
        ("B", 40.0),
        ("F", 1.0),
        ("L", 100.0),
        ("R", 5.0),
        ("t", 0.8),
        ("w", 10.0),
    ];
    let g = Linear::new(written(&case, &dir), targets)
        .evaluate(&Default::default(), &mut flexfem::fem::SolverCache::new())
        .unwrap_or_else(|e| panic!("{e}"));
    let mut probes: Vec<Probe> = ["k_x", "c_rz", "u_x", "theta", "util", "stroke"]
        .iter()
        .map(|n| Probe::Metric(n.to_string()))
        .collect();
    probes.extend([Probe::HingeVonMises(0, 2), Probe::Frequency(1), Probe::Frequency(2)]);
    let worst = check(&g, &case, &dir, &probes, &params);
    println!("worst {worst:.2e} of the tolerance scale");
}
