//! The `superelement` element of mesh cases: the steel cantilever of
//! cases/craig_bampton_cantilever.json (1000 mm, 10×6 mm, 20 Euler–Bernoulli elements, clamped
//! at x = 0) split at x = 500 mm; the outer half reduced by `craig_bampton` (R. R. Craig, M. C.
//! C. Bampton, "Coupling of substructures for dynamic analyses", AIAA J. 6 (1968) 1313–1319) to
//! its cut and tip nodes and attached to the inner half's 10 beams in a host case
//! (cases/craig_bampton_outer_half.json, cases/superelement_cantilever*.json), against the
//! unreduced model and closed forms; then the case errors (JSON paths, exit 2).

mod common;

use serde_json::{json, Value};
use std::path::{Path, PathBuf};

/// E I of the bending planes: E = 210 000 MPa (built-in steel), Iy = 10·6³/12 = 180 mm⁴ (uz),
/// Iz = 6·10³/12 = 500 mm⁴ (uy).
const EI_Z: f64 = 210_000.0 * 180.0;
const EI_Y: f64 = 210_000.0 * 500.0;

fn bundled(name: &str) -> Value {
    serde_json::from_slice(&std::fs::read(common::root().join("cases").join(name)).unwrap()).unwrap()
}

fn run(v: &Value) -> Value {
    let c = flexfem::analysis::parse(&v.to_string()).unwrap_or_else(|e| panic!("{e}"));
    flexfem::analysis::run(&c).unwrap_or_else(|e| panic!("{e}")).json
}

/// Reduces the outer half with `modes` fixed-interface modes (library run) and writes its
/// result to `dir/se_<modes>.json`; the path.
fn reduce(dir: &Path, modes: usize) -> PathBuf {
    let mut cb = bundled("craig_bampton_outer_half.json");
    cb["modes"] = json!(modes);
    let p = dir.join(format!("se_{modes}.json"));
    std::fs::write(&p, run(&cb).to_string()).unwrap();
    p
}

/// The bundled host case (`static` or `modal`) with its superelement file replaced by `file`.
fn host(bundled_name: &str, file: &Path) -> Value {
    let mut h = bundled(bundled_name);
    let e = h["elements"].as_array_mut().unwrap().last_mut().unwrap();
    assert_eq!(e["type"], "superelement");
    e["file"] = json!(file.to_str().unwrap());
    h
}

/// The unreduced 20-element cantilever as a `static` (tip loads Fz = 1 N, Fy = 1 N at node 20)
/// or `modal` case.
fn full(analysis: &str) -> Value {
    let mut v = bundled("craig_bampton_cantilever.json");
    let m = v.as_object_mut().unwrap();
    for k in ["interface", "modes", "description"] {
        m.remove(k);
    }
    m.insert("analysis".into(), json!(analysis));
    if analysis == "static" {
        m.insert(
            "load_cases".into(),
            json!([{"name": "tip_z", "forces": [{"node": 20, "F": [0, 0, 1, 0, 0, 0]}]},
                   {"name": "tip_y", "forces": [{"node": 20, "F": [0, 1, 0, 0, 0, 0]}]}]),
        );
    } else {
        m.insert("modes".into(), json!(3));
    }
    v
}

fn tip(r: &Value, case: usize, node: usize, dof: usize) -> f64 {
    r["load_cases"][case]["displacements"][node][dof].as_f64().unwrap()
}

fn eigenvalues(r: &Value) -> Vec<f64> {
    r["modes"]
        .as_array()
        .unwrap()
        .iter()
        .map(|m| m["eigenvalue"].as_f64().unwrap())
        .collect()
}

/// Static condensation is exact for loads at interface DOFs (R. J. Guyan, "Reduction of
/// stiffness and mass matrices", AIAA J. 3 (1965) 380): with 0 and with 10 modes, the host's
/// tip deflections under Fz = 1 N and Fy = 1 N equal the unreduced 20-element model's to 1e-9
/// relative, and the Euler–Bernoulli closed form F L³/(3 E I) (8.8183 mm, 3.1746 mm; cubic
/// Hermite elements are nodally exact for end loads) to 1e-9. Measured: ≤ 2.4e-11 for both.
#[test]
fn static_tip_deflection_is_exact() {
    let d = common::tempdir("se-static");
    let full = run(&full("static"));
    for modes in [0, 10] {
        let r = run(&host("superelement_cantilever.json", &reduce(&d, modes)));
        for (case, dof, ei) in [(0, 2, EI_Z), (1, 1, EI_Y)] {
            let (got, want) = (tip(&r, case, 11, dof), tip(&full, case, 20, dof));
            let closed = 1e9 / (3.0 * ei);
            let (e_full, e_closed) = ((got - want).abs() / want, (got - closed).abs() / closed);
            eprintln!("{modes} modes, case {case}: tip {got} mm, full {want}, closed form {closed}: {e_full:.2e}, {e_closed:.2e}");
            assert!(e_full <= 1e-9 && e_closed <= 1e-9, "{e_full} {e_closed}");
        }
        let notes = r["model"].to_string();
        assert!(
            notes.contains("reduced superelement") && notes.contains(&format!("with {modes} fixed-interface modes")),
            "{notes}"
        );
    }
    common::cleanup(&d);
}

/// The host's first three frequencies (ω²) against the unreduced model's (shift-invert Lanczos
/// on the 20 beams), for 0, 2, 5 and 10 fixed-interface modes: the largest relative error falls
/// with more modes and is below 1e-4 with 10 (Craig & Bampton 1968: the reduction converges to
/// the full model as modes are added). Measured max relative ω² errors: 0 modes 2.8e-3, 2 modes
/// 2.1e-3, 5 modes 8.1e-5, 10 modes 2.1e-6. The total mass in each direction (rᵀ M r over the
/// free DOFs, modal nodes excluded: a rigid motion of the interface is reproduced by the
/// constraint modes with η = 0) equals the full model's to 1e-12 relative.
#[test]
fn modal_frequencies_converge_with_modes() {
    let d = common::tempdir("se-modal");
    let full = run(&full("modal"));
    let reference = eigenvalues(&full);
    let mut last = f64::INFINITY;
    for modes in [0, 2, 5, 10] {
        let r = run(&host("superelement_cantilever_modal.json", &reduce(&d, modes)));
        let got = eigenvalues(&r);
        assert_eq!(got.len(), reference.len());
        let worst = got
            .iter()
            .zip(&reference)
            .map(|(a, b)| (a - b).abs() / b)
            .fold(0.0, f64::max);
        eprintln!("{modes} modes: max relative ω² error over 3 modes {worst:.3e}");
        assert!(worst < last, "{modes} modes: {worst} not below {last}");
        last = worst;
        for dir in ["x", "y", "z", "rx", "ry", "rz"] {
            let (got, want) = (
                r["total_mass"][dir].as_f64().unwrap(),
                full["total_mass"][dir].as_f64().unwrap(),
            );
            assert!((got - want).abs() <= 1e-12 * want, "total mass {dir}: {got} vs {want}");
        }
    }
    assert!(last < 1e-4, "{last}");
    common::cleanup(&d);
}

/// Transient: a step tip load Fz = 1 N (the `transient` default scheme, dt = 5 ms, 40 steps per
/// period of the first mode, 400 steps) on the host with a 10-mode superelement follows the
/// unreduced model's tip history (same scheme and steps): the largest difference over all steps
/// is below 1e-4 of the peak (the reduced model's first frequencies differ by ≤ 2.1e-6 on ω²;
/// the truncated high modes are barely excited). Measured: 2.8e-4 mm of a 17.57 mm peak
/// (1.6e-5).
#[test]
fn transient_step_response_follows_the_full_model() {
    let d = common::tempdir("se-transient");
    let transient = |mut v: Value, tip: usize| {
        let m = v.as_object_mut().unwrap();
        for k in ["load_cases", "modes", "description"] {
            m.remove(k);
        }
        m.insert("analysis".into(), json!("transient"));
        m.insert("dt".into(), json!(0.005));
        m.insert("steps".into(), json!(400));
        m.insert("histories".into(), json!(true));
        m.insert(
            "loads".into(),
            json!([{"node": tip, "force": [0, 0, 1, 0, 0, 0], "history": {"type": "step"}}]),
        );
        m.insert("record".into(), json!([{"node": tip, "dof": "uz"}]));
        let r = run(&v);
        assert!(r["model"].as_str().unwrap().contains(if tip == 11 {
            "with 10 fixed-interface modes"
        } else {
            "linear"
        }));
        r["records"][0]["series"]
            .as_array()
            .unwrap()
            .iter()
            .map(|x| x.as_f64().unwrap())
            .collect::<Vec<f64>>()
    };
    let reduced = transient(host("superelement_cantilever.json", &reduce(&d, 10)), 11);
    let reference = transient(full("static"), 20);
    let peak = reference.iter().fold(0.0f64, |s, v| s.max(v.abs()));
    assert_eq!(reduced.len(), reference.len());
    let worst = reduced
        .iter()
        .zip(&reference)
        .map(|(a, b)| (a - b).abs())
        .fold(0.0, f64::max);
    eprintln!(
        "transient: peak {peak} mm, largest difference {worst:.3e} mm ({:.3e} of the peak)",
        worst / peak
    );
    assert_eq!(reduced.len(), reference.len());
    assert!(worst <= 1e-4 * peak, "{worst} of {peak}");
    common::cleanup(&d);
}

/// Round trip through files with the CLI: `flexfem run` of the outer half's `craig_bampton`
/// case with `--out se`, then a host case in the same folder naming `se/result.json`
/// (relative to the case file). The tip deflection under Fz = 1 N equals F L³/(3 E I) to 1e-9.
/// The superelement placed by a 90° turn about z (the host cantilever along y) gives the same
/// deflections, the in-plane one now under Fx: the rotation of the interface DOFs is exact.
#[test]
fn round_trip_through_files_with_the_cli() {
    let d = common::tempdir("se-cli");
    let cb = common::write(&d, "cb.json", &bundled("craig_bampton_outer_half.json").to_string());
    common::run_ok_in(&d, &["run", cb.to_str().unwrap(), "--out", "se"]);
    let mut h = bundled("superelement_cantilever.json");
    h["elements"][10]["file"] = json!("se/result.json");
    let case = common::write(&d, "host.json", &h.to_string());
    let o = common::run_ok_in(&common::root(), &["run", case.to_str().unwrap()]);
    let r: Value = serde_json::from_slice(&o.stdout).unwrap();
    let closed = 1e9 / (3.0 * EI_Z);
    assert!(
        (tip(&r, 0, 11, 2) - closed).abs() <= 1e-9 * closed,
        "{}",
        tip(&r, 0, 11, 2)
    );
    // Turned: host along y, x_host = Rz(90°)·x.
    for n in h["nodes"].as_array_mut().unwrap() {
        *n = json!([0.0, n[0].as_f64().unwrap(), 0.0]);
    }
    h["elements"][10]["placement"] = json!({"axis": [0, 0, 1], "angle": 90});
    h["load_cases"][1]["forces"][0]["F"] = json!([1, 0, 0, 0, 0, 0]);
    let case = common::write(&d, "turned.json", &h.to_string());
    let o = common::run_ok_in(&d, &["run", case.to_str().unwrap()]);
    let r: Value = serde_json::from_slice(&o.stdout).unwrap();
    for (case, dof, ei) in [(0, 2, EI_Z), (1, 0, EI_Y)] {
        let closed = 1e9 / (3.0 * ei);
        let got = tip(&r, case, 11, dof);
        assert!(
            (got - closed).abs() <= 1e-9 * closed,
            "turned, case {case}: {got} vs {closed}"
        );
    }
    common::cleanup(&d);
}

/// An interface node with a node frame in the reduced model (a skew frame given by a support
/// that fixes nothing: its boundary DOFs are then local, and the file records the frame) is
/// turned back to global axes on attachment: the tip deflections equal F L³/(3 E I) to 1e-9.
#[test]
fn interface_node_frames_are_turned_back() {
    let d = common::tempdir("se-frame");
    let mut cb = bundled("craig_bampton_outer_half.json");
    cb["supports"] = json!([{"node": 10, "fix": [], "frame": [[0.6, 0.8, 0], [-0.8, 0.6, 0], [0, 0, 1]]}]);
    let reduced = run(&cb);
    assert_eq!(reduced["interface_nodes"][1]["frame"][0], json!([0.6, 0.8, 0.0]));
    let p = common::write(&d, "framed.json", &reduced.to_string());
    let r = run(&host("superelement_cantilever.json", &p));
    for (case, dof, ei) in [(0, 2, EI_Z), (1, 1, EI_Y)] {
        let closed = 1e9 / (3.0 * ei);
        let got = tip(&r, case, 11, dof);
        assert!((got - closed).abs() <= 1e-9 * closed, "case {case}: {got} vs {closed}");
    }
    common::cleanup(&d);
}

/// The bundled superelement (meshes/superelement_outer_half.json) is what the bundled
/// `craig_bampton` case writes: K and M entries agree to 1e-9 of each matrix's largest entry.
#[test]
fn bundled_superelement_is_current() {
    let committed: Value =
        serde_json::from_slice(&std::fs::read(common::root().join("meshes/superelement_outer_half.json")).unwrap())
            .unwrap();
    let fresh = run(&bundled("craig_bampton_outer_half.json"));
    for key in ["k", "m"] {
        let flat = |v: &Value| -> Vec<f64> {
            v[key]
                .as_array()
                .unwrap()
                .iter()
                .flat_map(|r| r.as_array().unwrap().iter().map(|x| x.as_f64().unwrap()))
                .collect()
        };
        let (a, b) = (flat(&committed), flat(&fresh));
        assert_eq!(a.len(), b.len());
        let scale = b.iter().fold(0.0f64, |s, v| s.max(v.abs()));
        let worst = a.iter().zip(&b).map(|(x, y)| (x - y).abs()).fold(0.0, f64::max);
        assert!(worst <= 1e-9 * scale, "{key}: {worst} of {scale}");
    }
}

/// Case errors name the JSON path and exit 2 (no panic): wrong node count, missing file, a file
/// that is not a superelement, a matrix of the wrong size, host nodes that do not coincide
/// with the interface nodes (also after a wrong placement), a node named twice, and analyses
/// that need more than linear matrices.
#[test]
fn bad_superelements_are_refused_with_their_path() {
    let d = common::tempdir("se-errors");
    let se = reduce(&d, 2);
    let case = |name: &str, edit: &dyn Fn(&mut Value)| {
        let mut h = host("superelement_cantilever.json", &se);
        edit(&mut h);
        common::run_case_text(name, &h.to_string())
    };
    let o = case("count", &|h| h["elements"][10]["nodes"] = json!([10]));
    common::exits_2(&o, &["elements[10].nodes", "2 interface nodes"]);
    let o = case("missing", &|h| {
        h["elements"][10]["file"] = json!("no_such_superelement.json")
    });
    common::exits_2(&o, &["elements[10].file", "no_such_superelement.json", "cannot read"]);
    let not_se = common::root().join("cases/static_cantilever.json");
    let o = case("format", &|h| {
        h["elements"][10]["file"] = json!(not_se.to_str().unwrap())
    });
    common::exits_2(&o, &["elements[10].file", "not a superelement file", "interface_nodes"]);
    let mut short: Value = serde_json::from_slice(&std::fs::read(&se).unwrap()).unwrap();
    short["k"].as_array_mut().unwrap().pop();
    let short_file = common::write(&d, "short.json", &short.to_string());
    let o = case("size", &|h| {
        h["elements"][10]["file"] = json!(short_file.to_str().unwrap())
    });
    common::exits_2(&o, &["elements[10].file", "`k` must be 14×14"]);
    let o = case("misplaced", &|h| h["elements"][10]["nodes"] = json!([9, 11]));
    common::exits_2(&o, &["elements[10].nodes[0]", "must coincide", "placement"]);
    let o = case("placement", &|h| {
        h["elements"][10]["placement"] = json!({"translation": [1, 0, 0]})
    });
    common::exits_2(&o, &["elements[10].nodes[0]", "must coincide"]);
    let o = case("twice", &|h| h["elements"][10]["nodes"] = json!([11, 11]));
    common::exits_2(&o, &["elements[10].nodes[1]", "named twice"]);
    // Linear matrices only: geometrically nonlinear statics and linear buckling are refused.
    let o = case("nonlinear", &|h| {
        h["nonlinear"] = json!(true);
        h["steps"] = json!(2);
    });
    common::exits_2(
        &o,
        &["elements[10]", "not available in geometrically nonlinear statics"],
    );
    let o = case("buckling", &|h| {
        h["analysis"] = json!("buckling");
        h["modes"] = json!(1);
        h["load_cases"].as_array_mut().unwrap().pop();
    });
    common::exits_2(&o, &["elements[10]", "not available in linear buckling"]);
    common::cleanup(&d);
}
