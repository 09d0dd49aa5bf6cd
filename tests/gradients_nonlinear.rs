//! Gradients through the nonlinear path ([`flexfem::gradient::nonlinear`]): every gradient at a
//! converged co-rotational state against central differences of full nonlinear runs at p ± h
//! (each reference state polished to round-off, so the reference is good to ~1e-8), on three
//! mechanisms: the parameterised parallelogram guide at 2 mm stroke, the lever amplifier at
//! 1 mm input stroke, and the 8-hinge pan-tilt at its 10° pitch case.

mod common;
use common::root;
use flexfem::fem::{Dof, NonlinearOptions};
use flexfem::gradient::nonlinear::{at_state, Gradients, ParamCase, Quantity, Settings, Site};
use serde_json::{json, Value};

type Values = Vec<(String, f64)>;

fn opts() -> NonlinearOptions {
    NonlinearOptions {
        steps: 8,
        tol_residual: 1e-10,
        locate_critical: false,
        ..Default::default()
    }
}

/// The case (relative files against `cases/`).
fn param_case(v: Value) -> ParamCase {
    ParamCase::new(v, Some(&root().join("cases"))).unwrap()
}

/// Gradients (or, with no parameters, the polished values) at the state solved at `values`.
fn grads(case: &ParamCase, values: &Values, scale: f64, params: &[String], q: &[Quantity]) -> Gradients {
    let (_, state) = case.solve(values, 0, scale, &opts()).unwrap();
    at_state(case, values, 0, scale, &state, params, q, &Settings::default()).unwrap()
}

fn with(values: &Values, name: &str, x: f64) -> Values {
    let mut v: Values = values.iter().filter(|(n, _)| n != name).cloned().collect();
    v.push((name.to_string(), x));
    v
}

/// The load scale at which the utilisation of `site` is 1: Newton on the scale with the path
/// rate dU/dλ of the gradient module (the stroke is `scale` times the case's value), from a
/// bracket [lo, hi] with U(lo) < 1 < U(hi), bisecting whenever a Newton step leaves it.
fn scale_at_allowable(case: &ParamCase, values: &Values, site: Site, mut lo: f64, mut hi: f64) -> f64 {
    let u = Quantity::Utilisation(site);
    let mut s = 0.5 * (lo + hi);
    for _ in 0..60 {
        let g = grads(case, values, s, &[], &[u]);
        let (f, df) = (g.values[0] - 1.0, g.path_rates[0] / s);
        // U carries round-off of ~1e-13 (the polished state's residual floor).
        if f.abs() < 1e-12 || hi - lo < 1e-13 * s {
            return s;
        }
        if f < 0.0 {
            lo = s;
        } else {
            hi = s;
        }
        let next = s - f / df;
        s = if next > lo && next < hi { next } else { 0.5 * (lo + hi) };
    }
    panic!("no stroke at the allowable in [{lo}, {hi}]");
}

/// Compares every gradient with central differences of full nonlinear runs, Richardson-
/// extrapolated from steps h and 2h, h = 1e-3·max(|p|, 1) (truncation ~h⁴ ~ 1e-12; the polished
/// states carry round-off of ~1e-11 of their forces, ~1e-8 of the difference). Entries are
/// compared as logarithmic sensitivities p_k·dQ/dp_k (one unit per quantity) against the row's
/// largest: an entry that is zero by physics (a displacement under a prescribed stroke does not
/// depend on the hinge width w) is then judged at the scale of its row, where round-off puts it.
/// Returns the worst of these errors and the worst plain relative error over the entries above
/// 1e-2 of their row.
fn compare(name: &str, case: &ParamCase, values: &Values, scale: f64, q: &[Quantity], params: &[&str]) -> (f64, f64) {
    let params: Vec<String> = params.iter().map(|s| s.to_string()).collect();
    let g = grads(case, values, scale, &params, q);
    assert_eq!(g.gradients.len(), q.len());
    // The round-off floor of the co-rotational residual: ε times the stiffest element's force
    // at unit relative error (EA/L of the notch segments) over the reactions.
    assert!(g.residual < 1e-9, "{name}: polished residual {:e}", g.residual);
    let p_of = |n: &str| {
        values
            .iter()
            .find(|(m, _)| m == n)
            .map(|v| v.1)
            .unwrap_or(case.defaults[n])
    };
    let mut refs = vec![vec![0.0; params.len()]; q.len()];
    for (k, n) in params.iter().enumerate() {
        let p = p_of(n);
        let h = 1e-3 * p.abs().max(1.0);
        let d = |h: f64| {
            let vp = grads(case, &with(values, n, p + h), scale, &[], q).values;
            let vm = grads(case, &with(values, n, p - h), scale, &[], q).values;
            assert_eq!(vp.len(), q.len());
            vp.iter().zip(&vm).map(|(a, b)| (a - b) / (2.0 * h)).collect::<Vec<_>>()
        };
        let (d1, d2) = (d(h), d(2.0 * h));
        assert_eq!(d1.len(), d2.len());
        for i in 0..q.len() {
            refs[i][k] = (4.0 * d1[i] - d2[i]) / 3.0;
        }
    }
    worst(name, &params, &p_of, q, &g.gradients, &refs)
}

fn worst(
    name: &str,
    params: &[String],
    p_of: &dyn Fn(&str) -> f64,
    q: &[Quantity],
    got: &[Vec<f64>],
    want: &[Vec<f64>],
) -> (f64, f64) {
    let (mut norm_err, mut rel_err) = (0.0f64, 0.0f64);
    assert_eq!(got.len(), want.len());
    for i in 0..q.len() {
        assert_eq!(got[i].len(), params.len());
        let row = (0..params.len())
            .map(|k| (p_of(&params[k]) * want[i][k]).abs())
            .fold(0.0, f64::max);
        assert!(row > 0.0, "{name}: {:?} does not depend on any parameter", q[i]);
        for k in 0..params.len() {
            let p = p_of(&params[k]);
            let e = (p * (got[i][k] - want[i][k])).abs() / row;
            eprintln!(
                "{name}: d{:?}/d{} = {:.10e} (central differences {:.10e}), error {e:.1e} of the row",
                q[i], params[k], got[i][k], want[i][k]
            );
            norm_err = norm_err.max(e);
            if (p * want[i][k]).abs() > 1e-2 * row {
                rel_err = rel_err.max(((got[i][k] - want[i][k]) / want[i][k]).abs());
            }
        }
    }
    (norm_err, rel_err)
}

/// The parameterised parallelogram guide (`meshes/parallelogram_parameters.json`, t = 0.8 mm)
/// driven by a prescribed stroke of node 8 along x (1 mm per unit of scale).
fn parallelogram() -> ParamCase {
    param_case(json!({
        "analysis": "static",
        "mesh": "../meshes/parallelogram_parameters.json",
        "nonlinear": true,
        "steps": 8,
        "parameters": {"t": 0.8},
        "load_cases": [{"name": "stroke", "displacements": [{"node": 8, "dof": "ux", "value": 1.0}]}]
    }))
}

const PARALLELOGRAM_PARAMS: [&str; 5] = ["t", "R", "L", "B", "w"];

/// Parallelogram at 2 mm stroke: the parasitic y drift of the stage (node 8), the peak stress of
/// each hinge and the tangent stiffness of the stage along y, against central differences of
/// full nonlinear runs, to 1e-6 (measured: see the eprintln log; worst ~1e-8).
#[test]
fn parallelogram_drift_stress_and_stiffness_match_central_differences() {
    let case = parallelogram();
    let q = [
        Quantity::Displacement { node: 8, dof: Dof::Uy },
        Quantity::Stress(Site::Hinge(0)),
        Quantity::Stress(Site::Hinge(2)),
        Quantity::Stress(Site::Hinge(3)),
        Quantity::Stress(Site::Hinge(5)),
        Quantity::TangentStiffness { node: 8, dof: Dof::Uy },
    ];
    let (norm, rel) = compare("parallelogram", &case, &vec![], 2.0, &q, &PARALLELOGRAM_PARAMS);
    eprintln!("parallelogram: worst error {norm:.2e} of the row, worst relative {rel:.2e}");
    assert!(norm < 1e-6, "worst error {norm:e} of the row");
    assert!(rel < 1e-6, "worst relative error {rel:e}");
}

/// Parallelogram: the stroke at the allowable stress of its most stressed hinge (utilisation 1
/// found along the path by bracketing and Newton/bisection on the stroke) and the load factor
/// there, against central differences of the stroke found the same way in full nonlinear runs
/// at p ± h, p ± 2h, to 1e-6 of the row (entries above 1e-2 of their row: 1e-6 relative). The
/// two agree with each other: ds*/dp = s*·dλ*/dp (prescribed stroke, λ scales it) to 1e-12.
#[test]
fn parallelogram_stroke_at_allowable_matches_central_differences() {
    let case = parallelogram();
    let none = Values::new();
    // The most stressed hinge at 2 mm.
    let sites = [0, 2, 3, 5].map(Site::Hinge);
    let q: Vec<Quantity> = sites.iter().map(|s| Quantity::Utilisation(*s)).collect();
    let u = grads(&case, &none, 2.0, &[], &q).values;
    assert_eq!(u.len(), sites.len());
    let k = (0..u.len()).max_by(|a, b| u[*a].total_cmp(&u[*b])).unwrap();
    let site = sites[k];
    assert!(u[k] > 0.3 && u[k] < 3.0, "utilisation {} at 2 mm", u[k]);
    let star = |values: &Values| scale_at_allowable(&case, values, site, 0.1, 20.0);
    let s0 = star(&none);
    eprintln!(
        "stroke at the allowable: {s0:.9} mm (hinge {site:?}, utilisation {:.4} at 2 mm)",
        u[k]
    );
    let params: Vec<String> = PARALLELOGRAM_PARAMS.iter().map(|s| s.to_string()).collect();
    let q = [
        Quantity::StrokeAtAllowable {
            site,
            node: 8,
            dof: Dof::Ux,
        },
        Quantity::LoadFactorAtAllowable(site),
    ];
    let g = grads(&case, &none, s0, &params, &q);
    assert!((g.values[0] - s0).abs() < 1e-12 * s0, "stroke {} vs {s0}", g.values[0]);
    assert_eq!(g.gradients[0].len(), params.len());
    for (k, name) in params.iter().enumerate() {
        let (ds, dl) = (g.gradients[0][k], g.gradients[1][k]);
        assert!(
            (ds - s0 * dl).abs() <= 1e-12 * ds.abs().max(1e-9),
            "{name}: {ds} vs {}",
            s0 * dl
        );
    }
    let p_of = |n: &str| case.defaults[n];
    let mut want = vec![vec![0.0; params.len()]];
    for (k, n) in params.iter().enumerate() {
        let p = p_of(n);
        let h = 1e-3 * p.abs().max(1.0);
        let d = |h: f64| (star(&with(&none, n, p + h)) - star(&with(&none, n, p - h))) / (2.0 * h);
        want[0][k] = (4.0 * d(h) - d(2.0 * h)) / 3.0;
    }
    let (norm, rel) = worst("stroke at allowable", &params, &p_of, &q[..1], &g.gradients[..1], &want);
    eprintln!("stroke at allowable: worst error {norm:.2e} of the row, worst relative {rel:.2e}");
    assert!(norm < 1e-6, "worst error {norm:e} of the row");
    assert!(rel < 1e-6, "worst relative error {rel:e}");
}

/// The lever amplifier of `cases/lever_amplifier.json` with its geometry as parameters
/// (`meshes/lever_gradients_nl.json`: notch t, R, input-hinge offset a, output arm Lo, hinge
/// height d; the nodes at a and Lo are rigid-link slaves, so these move the links' arms), at
/// 1 mm input stroke (lever rotation ~0.1 rad): the output motion along y, its parasitic x
/// motion, the pivot hinge's peak stress and the tangent stiffness at the output, against
/// central differences of full nonlinear runs to 1e-6.
#[test]
fn lever_amplifier_gradients_match_central_differences() {
    let case = param_case(json!({
        "analysis": "static",
        "mesh": "../meshes/lever_gradients_nl.json",
        "nonlinear": true,
        "steps": 8,
        "load_cases": [{"name": "stroke", "displacements": [{"node": 2, "dof": "uy", "value": 1.0}]}]
    }));
    let q = [
        Quantity::Displacement { node: 4, dof: Dof::Uy },
        Quantity::Displacement { node: 4, dof: Dof::Ux },
        Quantity::Stress(Site::Hinge(0)),
        Quantity::Stress(Site::Hinge(1)),
        Quantity::TangentStiffness { node: 4, dof: Dof::Uy },
    ];
    let (norm, rel) = compare("lever", &case, &vec![], 1.0, &q, &["t", "R", "a", "Lo", "d"]);
    eprintln!("lever: worst error {norm:.2e} of the row, worst relative {rel:.2e}");
    assert!(norm < 1e-6, "worst error {norm:e} of the row");
    assert!(rel < 1e-6, "worst relative error {rel:e}");
}

/// The 8-hinge pan-tilt (`meshes/pantilt_gradients_nl.json`: `meshes/pantilt_8r.json` with the
/// notch thickness t of all eight hinges, the platform hinge height zp and the link width wl as
/// parameters) at the bundled 10° pitch / 45° phase case: the platform's motion (node 13: z
/// drift, rotation about x), the platform hinge's peak stress and the platform's tangent
/// stiffness about z, against central differences of full nonlinear runs to 1e-6. At this
/// rotation the linear gradient of the platform's z drift (central differences of linear runs)
/// is off by far more than that (measured in the test, asserted above 1 %).
#[test]
fn pantilt_gradients_match_central_differences_and_differ_from_linear() {
    let mut v: Value =
        serde_json::from_str(&std::fs::read_to_string(root().join("cases/pantilt_8r.json")).unwrap()).unwrap();
    v["mesh"] = json!("../meshes/pantilt_gradients_nl.json");
    let case = param_case(v);
    let q = [
        Quantity::Displacement { node: 13, dof: Dof::Uz },
        Quantity::Displacement { node: 13, dof: Dof::Rx },
        Quantity::Stress(Site::Hinge(6)),
        Quantity::TangentStiffness { node: 13, dof: Dof::Rz },
    ];
    let params = ["t", "zp", "wl"];
    let (norm, rel) = compare("pantilt", &case, &vec![], 1.0, &q, &params);
    eprintln!("pantilt: worst error {norm:.2e} of the row, worst relative {rel:.2e}");
    assert!(norm < 1e-6, "worst error {norm:e} of the row");
    assert!(rel < 1e-6, "worst relative error {rel:e}");

    // The linear gradient of the z drift: central differences of linear solves.
    let names: Vec<String> = params.iter().map(|s| s.to_string()).collect();
    let g = grads(&case, &vec![], 1.0, &names, &q[..1]);
    let linear_uz = |values: &Values| {
        let b = case.build(values, 0, 1.0).unwrap();
        flexfem::fem::solve_static(&b.model).unwrap().load_cases[0].displacements[13][2]
    };
    assert_eq!(g.gradients[0].len(), params.len());
    let mut differ = 0.0f64;
    for (k, n) in params.iter().enumerate() {
        let p = case.defaults[*n];
        let h = 1e-3 * p.abs().max(1.0);
        let lin = (linear_uz(&with(&vec![], n, p + h)) - linear_uz(&with(&vec![], n, p - h))) / (2.0 * h);
        let nl = g.gradients[0][k];
        eprintln!("pantilt: d(uz of node 13)/d{n}: nonlinear {nl:.6e}, linear {lin:.6e}");
        differ = differ.max(((lin - nl) / nl).abs());
    }
    eprintln!(
        "pantilt: the linear gradient of the z drift differs by up to {:.1} %",
        100.0 * differ
    );
    assert!(differ > 0.01, "linear and nonlinear gradients agree to {differ:e}");
}
