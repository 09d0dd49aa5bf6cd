//! The `frequency`, `buckling_margin` and `parasitic` metrics of `static` cases, default metric
//! names, metrics as sweep columns, and the requests `check` refuses.
//!
//! Sources: clamped–free Euler–Bernoulli beam, f₁ = (β₁L)²/(2πL²)·√(EI/(ρA)), β₁L = 1.875104
//! (Blevins, Formulas for Natural Frequency and Mode Shape, 1979, Table 8-1); Euler's column,
//! clamped–free, P_cr = π²EI/(4L²) (Timoshenko & Gere, Theory of Elastic Stability, 1961,
//! §2.1); rigid-link parallelogram, Δy = L − √(L² − x²) (Howell, Compliant Mechanisms, 2001,
//! §5.3: the pseudo-rigid-body model of a parallel guide).

mod common;
use common::*;
use flexfem::analysis;
use serde_json::{json, Value};

fn run(case: Value) -> Value {
    let c = analysis::parse_value(case, None).unwrap_or_else(|e| panic!("{e}"));
    analysis::run(&c).unwrap_or_else(|e| panic!("{e}")).json
}

fn refused(case: Value) -> String {
    match analysis::parse_value(case, None) {
        Ok(_) => panic!("accepted"),
        Err(e) => e.to_string(),
    }
}

fn num(v: &Value) -> f64 {
    v.as_f64().unwrap_or_else(|| panic!("not a number: {v}"))
}

/// `cases/buckling_euler_column.json` (steel, 1000 mm, 10 × 20 mm, 10 Euler–Bernoulli elements,
/// clamped at node 0, 1 N compression at node 10) as a `static` case with `metrics`.
fn column(metrics: Value) -> Value {
    let mut c: Value =
        serde_json::from_str(&std::fs::read_to_string("cases/buckling_euler_column.json").unwrap()).unwrap();
    let o = c.as_object_mut().unwrap();
    o.remove("modes");
    o.remove("description");
    c["analysis"] = json!("static");
    c["metrics"] = metrics;
    c
}

const E: f64 = 210_000.0;
const RHO: f64 = 7.85e-9;
const L: f64 = 1000.0;
/// Weak-axis second moment of the 10 × 20 mm bar, mm⁴, and its area, mm².
const I_WEAK: f64 = 20.0 * 1000.0 / 12.0;
const AREA: f64 = 200.0;

#[test]
fn frequency_matches_the_cantilever_closed_form_and_the_modal_run() {
    let out = run(column(
        json!([{"kind": "frequency", "mode": 1}, {"kind": "frequency", "mode": 3}]),
    ));
    let m = &out["metrics"];
    let f1 = num(&m["frequency_1"]);
    let closed = 1.875104_f64.powi(2) / (2.0 * std::f64::consts::PI * L * L) * (E * I_WEAK / (RHO * AREA)).sqrt();
    // 10 Hermite elements with consistent mass and rotary inertia (Rayleigh's correction,
    // (r/L)² ≈ 8e-6): measured −1.8e-5.
    assert!(
        (f1 / closed - 1.0).abs() < 1e-4,
        "f1 {f1} Hz vs closed form {closed} Hz"
    );
    let mut modal = column(json!([]));
    let o = modal.as_object_mut().unwrap();
    for k in ["metrics", "load_cases"] {
        o.remove(k);
    }
    modal["analysis"] = json!("modal");
    modal["modes"] = json!(3);
    let modes = run(modal);
    let modes = modes["modes"].as_array().unwrap();
    assert_eq!(modes.len(), 3);
    for (name, k) in [("frequency_1", 0), ("frequency_3", 2)] {
        let (a, b) = (num(&m[name]), num(&modes[k]["frequency_hz"]));
        assert!((a / b - 1.0).abs() < 1e-9, "{name} {a} Hz vs modal {b} Hz");
    }
}

#[test]
fn buckling_margin_matches_euler_and_the_buckling_run() {
    let metrics = json!([{"kind": "buckling_margin", "load_case": "axial"}]);
    let out = run(column(metrics.clone()));
    let lam = num(&out["metrics"]["buckling_margin_axial"]);
    let euler = std::f64::consts::PI.powi(2) * E * I_WEAK / (4.0 * L * L);
    // The load case applies 1 N: the margin is the critical load in N (10 elements: measured 8.4e-7).
    assert!((lam / euler - 1.0).abs() < 1e-5, "λ {lam} vs Euler {euler} N");
    let b: Value = serde_json::from_str(&std::fs::read_to_string("cases/buckling_euler_column.json").unwrap()).unwrap();
    let b = run(b);
    let first = num(&b["buckling"][0]["load_factor"]);
    assert!((lam / first - 1.0).abs() < 1e-9, "metric {lam} vs buckling run {first}");
    // The same linear buckling of the undeformed reference in a nonlinear run.
    let mut nl = column(metrics);
    nl["nonlinear"] = json!(true);
    let lam_nl = num(&run(nl)["metrics"]["buckling_margin_axial"]);
    assert!((lam_nl / lam - 1.0).abs() < 1e-9, "{lam_nl} vs {lam}");
}

/// The parallelogram of `meshes/parallelogram_parameters.json` (pivots L = 100 mm apart) with the
/// notch thickness `t`, nonlinear, platform (node 8) moved by ux = 2 mm: the parasitic uy.
fn parallelogram_drift(t: f64) -> f64 {
    let mut mesh: Value =
        serde_json::from_str(&std::fs::read_to_string("meshes/parallelogram_parameters.json").unwrap()).unwrap();
    mesh["parameters"]["t"] = json!(t);
    mesh["analysis"] = json!("static");
    mesh["nonlinear"] = json!(true);
    mesh["load_cases"] = json!([{"name": "x2", "displacements": [{"node": 8, "dof": "ux", "value": 2.0}]}]);
    mesh["metrics"] = json!([{"name": "dy", "kind": "parasitic", "node": 8, "dof": "uy", "load_case": "x2"}]);
    let out = run(mesh);
    let dy = num(&out["metrics"]["dy"]);
    assert_eq!(dy, num(&out["load_cases"][0]["displacements"][8][1]));
    dy
}

/// The platform drops (uy < 0) by nearly the rigid-link Δy = L − √(L² − x²) = 0.020002 mm.
/// Hinge-compliance correction: the FE drift is below it by c·√(t/R) (measured −1.693 %,
/// −1.182 %, −0.851 % at t = 1, 0.5, 0.25 mm, R = 5 mm: c = 0.0379 ± 0.3 %), the notch's
/// compliant zone having a length ∝ √(R·t) (Paros & Weisbord, Machine Design 37 (1965)
/// 151–156); extrapolated to t → 0 (a point pivot) the drift is the rigid-link value within 0.1 %.
#[test]
fn parallelogram_parasitic_drift_tends_to_the_rigid_link_closed_form() {
    let rigid = 100.0 - (100.0_f64 * 100.0 - 4.0).sqrt();
    let d1 = -parallelogram_drift(1.0);
    let e1 = d1 / rigid - 1.0;
    assert!(
        (-0.02..-0.014).contains(&e1),
        "t = 1: {d1} mm vs rigid {rigid} mm ({e1:e})"
    );
    let (dh, dq) = (-parallelogram_drift(0.5), -parallelogram_drift(0.25));
    // Linear in √t: two thicknesses a factor 2 apart extrapolate to t = 0.
    let (eh, eq) = (dh / rigid - 1.0, dq / rigid - 1.0);
    let r = std::f64::consts::SQRT_2;
    let e0 = eq - (eh - eq) / (r - 1.0);
    assert!(
        e0.abs() < 1e-3,
        "extrapolated {e0:e} (t = 0.5: {eh:e}, t = 0.25: {eq:e})"
    );
    // The three deviations scale as √t: c = e/√(t/R) agrees to 2 %.
    let c: Vec<f64> = [(e1, 1.0), (eh, 0.5), (eq, 0.25)]
        .iter()
        .map(|(e, t)| e / (t / 5.0_f64).sqrt())
        .collect();
    assert_eq!(c.len(), 3);
    for ci in &c {
        assert!((ci / c[0] - 1.0).abs() < 0.02, "{c:?}");
    }
}

#[test]
fn metric_names_default_to_the_kind_and_its_fields() {
    let out = run(column(json!([
        {"kind": "frequency", "mode": 2},
        {"kind": "displacement", "node": 10, "dof": "ux", "load_case": "axial"},
        {"name": "k", "kind": "stiffness", "node": 10, "dof": "ux"}
    ])));
    let m = out["metrics"].as_object().unwrap();
    let keys: Vec<&str> = m.keys().map(String::as_str).collect();
    assert_eq!(keys.len(), 3, "{keys:?}");
    for k in ["frequency_2", "displacement_10_ux_axial", "k"] {
        assert!(keys.contains(&k), "{keys:?}");
    }
    // 1 N of compression shortens the column by L/(EA).
    let u = num(&m["displacement_10_ux_axial"]);
    assert!((u / (-L / (E * AREA)) - 1.0).abs() < 1e-9, "{u}");
}

#[test]
fn unevaluable_metric_requests_are_refused_with_their_path() {
    let guide = |metrics: Value| {
        json!({
            "analysis": "static",
            "mesh": "meshes/parallelogram_parameters.json",
            "load_cases": [{"name": "x2", "displacements": [{"node": 8, "dof": "ux", "value": 2.0}]},
                           {"name": "f", "forces": [{"node": 8, "F": [1, 0, 0, 0, 0, 0]}]}],
            "metrics": metrics
        })
    };
    let cases = [
        (
            column(json!([{"kind": "frequency", "mode": 0}])),
            "metrics[0].mode",
            "from 1",
        ),
        (
            column(json!([{"kind": "frequency", "mode": 67}])),
            "metrics[0].mode",
            "to 66",
        ),
        (column(json!([{"kind": "frequency"}])), "metrics[0].mode", "required"),
        (
            column(json!([{"kind": "frequency", "mode": 1, "node": 3}])),
            "metrics[0].node",
            "not used",
        ),
        (
            column(json!([{"kind": "buckling_margin", "load_case": "push"}])),
            "metrics[0].load_case",
            "must name a load case: axial",
        ),
        (
            column(json!([{"kind": "frequency", "mode": 1}, {"kind": "frequency", "mode": 1}])),
            "metrics[1].name",
            "\"frequency_1\"",
        ),
        (
            guide(json!([{"kind": "parasitic", "node": 8, "dof": "ux", "load_case": "x2"}])),
            "metrics[0].dof",
            "is driven at node 8",
        ),
        (
            guide(json!([{"kind": "parasitic", "node": 8, "dof": "ux", "load_case": "f"}])),
            "metrics[0].dof",
            "is driven at node 8",
        ),
        (
            guide(json!([{"kind": "parasitic", "node": 0, "dof": "uy", "load_case": "x2"}])),
            "metrics[0].dof",
            "fixed at node 0 by a support",
        ),
        (
            guide(json!([{"kind": "stroke_at_allowable", "node": 8, "dof": "uy", "load_case": "x2"}])),
            "metrics[0].load_case",
            "must prescribe a non-zero uy of node 8",
        ),
    ];
    for (case, path, why) in cases {
        let e = refused(case);
        assert!(e.contains(path) && e.contains(why), "{e}");
    }
}

/// A shell model (`meshes/plate_shell_ss.json`) has no linear buckling: `buckling_margin` is refused at `check` (exit 2).
#[test]
fn buckling_margin_of_a_shell_model_is_refused_by_check() {
    let mesh = root().join("meshes/plate_shell_ss.json");
    let c = json!({
        "analysis": "static",
        "mesh": mesh.to_str().unwrap(),
        "metrics": [{"kind": "buckling_margin", "load_case": "centre"}]
    });
    let d = tempdir("metric_kinds_shell");
    let file = write(&d, "shell.json", &c.to_string());
    let o = run_in(&d, &["check", file.to_str().unwrap()]);
    exits_2(&o, &["metrics[0].kind", "buckling_margin", "shell"]);
    cleanup(&d);
}

/// Metrics are sweep columns: `metrics.NAME` (and `metrics.NAME.stroke` for a stroke), equal to
/// the single runs' values.
#[test]
fn metrics_are_sweep_columns() {
    let d = tempdir("metric_kinds_sweep");
    let base = column(json!([
        {"kind": "frequency", "mode": 1},
        {"kind": "buckling_margin", "load_case": "axial"},
        {"name": "s", "kind": "stroke_at_allowable", "node": 10, "dof": "ux", "load_case": "axial"}
    ]));
    let sweep_case = json!({"analysis": "sweep", "base": base.clone(), "vary": {"sections.bar.w": [10.0, 12.0]}});
    let file = write(&d, "sweep.json", &sweep_case.to_string());
    let csv_path = d.join("out.csv");
    let o = sweep(&d, &[file.to_str().unwrap(), "--csv", csv_path.to_str().unwrap()]);
    assert_eq!(o.status.code(), Some(0), "{}", stderr(&o));
    let csv = std::fs::read_to_string(&csv_path).unwrap();
    let head = cells(csv.lines().next().unwrap());
    let first = cells(csv.lines().nth(1).unwrap());
    assert_eq!(head.len(), first.len());
    let single = run(base);
    for (column, value) in [
        ("metrics.frequency_1", &single["metrics"]["frequency_1"]),
        (
            "metrics.buckling_margin_axial",
            &single["metrics"]["buckling_margin_axial"],
        ),
        ("metrics.s.stroke", &single["metrics"]["s"]["stroke"]),
    ] {
        let k = head
            .iter()
            .position(|h| h == column)
            .unwrap_or_else(|| panic!("no {column} in {head:?}"));
        let cell: f64 = first[k].parse().unwrap();
        assert!((cell / num(value) - 1.0).abs() < 1e-12, "{column}: {cell} vs {value}");
    }
    cleanup(&d);
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
