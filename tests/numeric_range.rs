//! Numerical range: every number written is finite, or the run fails naming the quantity.
//!
//! Regressions of issue 12 ("Numerical range"): loads ≥ ~1e154 N gave NaN output with exit 0
//! (linear statics) and all-zero displacements with exit 0 (nonlinear); hinge torsion stiffness
//! was NaN for R ≤ 3e-4 mm or t close to h and jumped 2× near t = h; R = 1e300 gave `null`s.

mod common;

use common::run_case_text;
use flexfem::analysis::to_checked_json;
use flexfem::hinge::{characterise, HingeSpec};
use flexfem::material::Material;
use serde::Serialize;

fn cantilever(force: &str, extra: &str) -> String {
    format!(
        r#"{{
  "analysis": "static",{extra}
  "materials": {{"al": "Al7075"}},
  "sections": {{"leg": {{"shape": "rect", "w": 10, "h": 10}}}},
  "nodes": [[0, 0, 0], [50, 0, 0], [100, 0, 0]],
  "elements": [
    {{"type": "beam", "nodes": [0, 1], "section": "leg", "material": "al", "up": [0, 0, 1], "shear": false}},
    {{"type": "beam", "nodes": [1, 2], "section": "leg", "material": "al", "up": [0, 0, 1], "shear": false}}
  ],
  "supports": [{{"node": 0, "fix": ["ux", "uy", "uz", "rx", "ry", "rz"]}}],
  "load_cases": [{{"name": "tip", "forces": [{{"node": 2, "F": [0, 0, {force}, 0, 0, 0]}}]}}]
}}"#
    )
}

fn stdout(o: &std::process::Output) -> String {
    String::from_utf8_lossy(&o.stdout).into_owned()
}
fn stderr(o: &std::process::Output) -> String {
    String::from_utf8_lossy(&o.stderr).into_owned()
}

/// Was: stress σ = M c / I overflows to ∞ (M ~ 1e157 N·mm) and serde_json wrote `null`, exit 0.
#[test]
fn huge_load_linear_static_fails_naming_the_quantity() {
    let o = run_case_text("huge_static", &cantilever("-1e155", ""));
    assert_eq!(
        o.status.code(),
        Some(1),
        "stdout: {}\nstderr: {}",
        stdout(&o),
        stderr(&o)
    );
    let e = stderr(&o);
    assert!(e.contains("load_cases[0]."), "{e}");
    assert!(e.contains("not finite"), "{e}");
    assert!(!stdout(&o).contains("null"));
}

/// Was: the Newton residual norm squared its entries (1e155² = ∞), so ∞ ≤ tol·∞ passed as
/// converged at iteration 0 with zero displacements. Now the scaled norm sees the residual; the
/// co-rotational cantilever turns into the load and stretches by F L/(E A) (a bar along its
/// load: the closed form of axial elongation), here 1e155·100/(72000·100) = 1.3889e150 mm,
/// with a warning that such strains are outside the small-strain model.
#[test]
fn huge_load_nonlinear_is_not_silently_zero() {
    let o = run_case_text(
        "huge_nonlinear",
        &cantilever("-1e155", r#" "nonlinear": true, "steps": 5,"#),
    );
    let out = stdout(&o);
    match o.status.code() {
        Some(0) => {
            let v: serde_json::Value = serde_json::from_str(&out).unwrap();
            let tip = &v["load_cases"][0]["displacements"][2];
            let uz = tip[2].as_f64().expect("finite tip uz");
            let expected = -1e155 * 100.0 / (72_000.0 * 100.0);
            assert!((uz / expected - 1.0).abs() < 0.01, "tip uz {uz} vs F L/(EA) {expected}");
            assert!(!out.contains("null"));
            // A strain of 1e148 is far outside the small-strain co-rotational model: said so.
            let w = v["warnings"].as_array().unwrap();
            assert!(w.iter().any(|w| w.as_str().unwrap().contains("small-strain")), "{w:?}");
        }
        Some(1) => assert!(stderr(&o).contains("tip") || stderr(&o).contains("load_cases")),
        c => panic!("exit {c:?}: {}", stderr(&o)),
    }
}

/// Loads whose products overflow f64 (1e300 N × 100 mm) fail with exit 1 and a path, never
/// a `null`.
#[test]
fn overflowing_load_fails_nonlinear_too() {
    for extra in ["", r#" "nonlinear": true, "steps": 2,"#] {
        let o = run_case_text("overflow_load", &cantilever("-1e300", extra));
        assert_eq!(o.status.code(), Some(1), "{extra}: {}", stderr(&o));
        assert!(!stdout(&o).contains("null"));
    }
}

fn al() -> Material {
    Material::builtin("Al7075").unwrap()
}

fn circular(r: f64, t: f64, blank: f64) -> HingeSpec {
    HingeSpec::CircularNotch {
        r,
        t,
        w: 10.0,
        h: 10.0,
        blank_length: blank,
    }
}

/// Was NaN for R ≤ 3e-4 mm (Cholesky cancellation on elements ~1e-5 mm long next to a
/// warping layer of ~2.5 mm). As R → 0 the notch vanishes and k_torsion tends to the value
/// of the blank with the slot's load-spreading zone: successive values must be finite and
/// converge (Cauchy), and no value may differ from the R = 1e-2 mm one by more than 1 %.
/// Near R = 0, k_torsion is linear in R: each step changes k by [`LIPSCHITZ`] × ΔR at most
/// (measured 0.3145 per mm on every step, R = 1e-2 … 1e-6 mm; a jump or a NaN-adjacent
/// cancellation breaks it).
#[test]
fn torsion_finite_and_continuous_as_r_goes_to_zero() {
    let k = |r: f64| characterise(&circular(r, 2.0, 20.0), &al()).unwrap().hinge.k_torsion;
    let k_ref = k(1e-2);
    let (mut prev, mut r_prev) = (k_ref, 1e-2);
    for r in [3e-3, 1e-3, 5e-4, 3e-4, 1e-4, 3e-5, 1e-5, 1e-6] {
        let v = k(r);
        assert!(v.is_finite() && v > 0.0, "R = {r}: k_torsion = {v}");
        assert!((v / k_ref - 1.0).abs() < 0.01, "R = {r}: {v} vs {k_ref} at R = 0.01");
        let step = (v / prev - 1.0).abs() / (r_prev - r);
        assert!(step < LIPSCHITZ, "R = {r}: {v} after {prev}: {step} per mm");
        (prev, r_prev) = (v, r);
    }
}

/// Bound on |Δk/k| / ΔR (per mm) of [`torsion_finite_and_continuous_as_r_goes_to_zero`].
const LIPSCHITZ: f64 = 0.35;

/// Was NaN at t = h − 1e-8 and 2× too stiff at t = h − 1e-9 (R = 8, h = 10). As t → h the
/// notch disappears; k_torsion must approach the t = h − 1e-4 value smoothly: finite,
/// monotone non-decreasing within 1e-4 relative, and within 0.2 % of its neighbours.
#[test]
fn torsion_finite_and_continuous_as_t_goes_to_h() {
    let k = |t: f64| characterise(&circular(8.0, t, 20.0), &al()).unwrap().hinge.k_torsion;
    let mut prev = k(10.0 - 1e-4);
    for d in [1e-5, 1e-6, 1e-7, 1e-8, 3e-9, 1e-9, 1e-10, 1e-11, 1e-12] {
        let v = k(10.0 - d);
        assert!(v.is_finite(), "t = h − {d}: {v}");
        assert!((v / prev - 1.0).abs() < 2e-3, "t = h − {d}: {v} after {prev}");
        assert!(v >= prev * (1.0 - 1e-4), "t = h − {d}: {v} < {prev}");
        prev = v;
    }
}

/// R = 1e300 overflowed R² to ∞: `null`s, k_torsion 1.0, "NaN%" in the report. Geometry
/// beyond what double precision represents (and far beyond any hinge) is refused before
/// solving, with the JSON path (exit 2).
#[test]
fn absurd_hinge_length_is_refused_with_its_path() {
    for (field, hinge) in [
        (
            "hinge.R",
            r#"{"type": "circular_notch", "R": 1e300, "t": 2, "w": 10, "h": 10, "blank_length": 20}"#,
        ),
        (
            "hinge.w",
            r#"{"type": "circular_notch", "R": 8, "t": 2, "w": 1e300, "h": 10, "blank_length": 20}"#,
        ),
        (
            "hinge.t",
            r#"{"type": "circular_notch", "R": 8, "t": 1e-300, "w": 10, "h": 10, "blank_length": 20}"#,
        ),
        (
            "hinge.blank_length",
            r#"{"type": "leaf", "l": 8, "t": 1, "w": 10, "h": 10, "blank_length": 1e300}"#,
        ),
    ] {
        let o = run_case_text("absurd_hinge", &format!(r#"{{"analysis": "hinge", "hinge": {hinge}}}"#));
        assert_eq!(o.status.code(), Some(2), "{hinge}: {}", stderr(&o));
        let e = stderr(&o);
        assert!(e.contains(&format!("`{field}`")), "{e}");
        assert!(e.len() < 400, "message stays short: {e}");
    }
}

/// A tiny notch (R = 3e-4 mm) now runs: exit 0, no `null`, no NaN in the report.
#[test]
fn tiny_notch_runs_with_finite_output() {
    let o = run_case_text(
        "tiny_notch",
        r#"{"analysis": "hinge", "hinge": {"type": "circular_notch", "R": 0.0003, "t": 2, "w": 10, "h": 10, "blank_length": 20}}"#,
    );
    assert_eq!(o.status.code(), Some(0), "{}", stderr(&o));
    assert!(!stdout(&o).contains("null"), "{}", stdout(&o));
}

#[derive(Serialize)]
struct Row {
    name: &'static str,
    values: Vec<[f64; 2]>,
    maybe: Option<f64>,
}

/// The checked serialisation names the JSON path of the first non-finite number and leaves
/// genuine `None`s as `null`.
#[test]
fn checked_json_names_the_path() {
    let ok = Row {
        name: "a",
        values: vec![[1.0, 2.0]],
        maybe: None,
    };
    let v = to_checked_json(&ok).unwrap();
    assert!(v["maybe"].is_null());
    let bad = Row {
        name: "b",
        values: vec![[1.0, 2.0], [3.0, f64::NAN]],
        maybe: Some(1.0),
    };
    let e = to_checked_json(&bad).unwrap_err();
    assert_eq!(e.context, "values[1][1]");
    let inf = Row {
        name: "c",
        values: vec![],
        maybe: Some(f64::INFINITY),
    };
    assert_eq!(to_checked_json(&inf).unwrap_err().context, "maybe");
}

/// Unbounded or undefined quantities with a stated meaning are `null`, not a failure: a
/// material without an allowable stress has no rotation at the allowable (hinge) and no reach
/// at the allowable (stage); a stage load case of zero forces has no stress ratio T.
#[test]
fn documented_nulls_stay_runs() {
    let o = run_case_text(
        "no_allowable_hinge",
        r#"{"analysis": "hinge", "material": {"E": 72000, "nu": 0.33}, "hinge": {"type": "circular_notch", "R": 8, "t": 2, "w": 10, "h": 10, "blank_length": 20}}"#,
    );
    assert_eq!(o.status.code(), Some(0), "{}", stderr(&o));
    let v: serde_json::Value = serde_json::from_slice(&o.stdout).unwrap();
    assert!(v["max_rotation_deg"].is_null());
    assert!(v["k_bend"].as_f64().unwrap() > 0.0);

    let base = std::fs::read_to_string(common::root().join("cases/ruiz2019_stage.json")).unwrap();
    let mut c: serde_json::Value = serde_json::from_str(&base).unwrap();
    c["load_cases"] = serde_json::json!([{"name": "zero", "actuator_forces": [0, 0, 0]}]);
    let o = run_case_text("zero_stage", &c.to_string());
    assert_eq!(o.status.code(), Some(0), "{}", stderr(&o));
    let v: serde_json::Value = serde_json::from_slice(&o.stdout).unwrap();
    let row = &v["load_cases"][0];
    assert!(row["T"].is_null() && row["factor_at_allowable"].is_null(), "{row}");
    assert_eq!(row["max_von_mises"].as_f64(), Some(0.0));
}

/// Every family at the edges of its geometry (lengths from 1e-6 to 1e6 mm, t → h, tiny
/// notches): every stiffness, compliance entry, stress factor and closed form is finite, or the
/// geometry is refused naming a parameter (a notch whose length rounds to nothing).
#[test]
fn every_family_finite_at_geometric_extremes() {
    let m = al();
    let mut specs = Vec::new();
    for &t in &[1e-6, 1e-3, 0.5, 9.0, 10.0 - 1e-6, 10.0 - 1e-12] {
        for &r in &[1e-6, 3e-4, 1.0, 8.0, 1e3, 1e6] {
            for &blank in &[0.0, 20.0] {
                specs.push(HingeSpec::CircularNotch {
                    r,
                    t,
                    w: 10.0,
                    h: 10.0,
                    blank_length: blank,
                });
                specs.push(HingeSpec::EllipticalNotch {
                    ax: r,
                    ay: r,
                    t,
                    w: 10.0,
                    h: 10.0,
                    blank_length: blank,
                });
                let rc = r.min(4e5);
                specs.push(HingeSpec::CornerFilleted {
                    l: 2.5 * rc,
                    r: rc,
                    t,
                    w: 10.0,
                    h: 10.0,
                    blank_length: blank,
                });
                specs.push(HingeSpec::Leaf {
                    l: r,
                    t,
                    w: 10.0,
                    h: 10.0,
                    blank_length: blank,
                });
                specs.push(HingeSpec::SphericalNeck {
                    l: r,
                    t,
                    r,
                    h: 10.0,
                    blank_length: blank,
                });
            }
        }
    }
    let mut refused = 0;
    for s in &specs {
        let r = match characterise(s, &m) {
            Ok(r) => r,
            Err(flexfem::hinge::HingeError::InvalidGeometry { param, .. }) => {
                assert!(["t", "R", "l"].contains(&param), "{s:?}: {param}");
                refused += 1;
                continue;
            }
            Err(e) => panic!("{s:?}: {e}"),
        };
        for k in [&r.hinge, &r.notch_only] {
            let v = to_checked_json(k).unwrap_or_else(|e| panic!("{s:?}: {e}"));
            assert!(k.k_torsion > 0.0 && k.k_bend > 0.0, "{s:?}: {v}");
        }
        for (name, v) in &r.closed_form {
            assert!(v.is_finite(), "{s:?}: {name} = {v}");
        }
        assert!(r.stress_concentration.is_finite(), "{s:?}");
    }
    assert!(refused * 10 < specs.len(), "{refused} of {} refused", specs.len());
}

/// A 10 µm leaf (w = 10, l = 1) between two 10 × 10 blanks: GJ differs by 4e17 between them.
/// The blanks are rigid by comparison and hold the leaf's ends against warping, so the chain's
/// stiffness is the closed-form Vlasov stiffness of the leaf alone with both ends restrained,
/// T/θ = GJ / (L − 2 tanh(kL/2)/k), k = √(GJ/EΓ) (Pilkey, *Analysis and Design of Elastic
/// Beams*, 2002, ch. 6). Solving for θ, the stiff–soft–stiff chain lost the leaf below
/// round-off (NaN or garbage); the rate-of-twist form gets it to 1e-4.
#[test]
fn torsion_of_a_soft_leaf_between_rigid_blanks() {
    use flexfem::hinge::section::{rect_torsion_constant, rect_warping_constant};
    use flexfem::hinge::torsion::torsion_fe;
    let (e, g) = (72_000.0, 27_067.7);
    let (gj_b, eg_b) = (
        g * rect_torsion_constant(10.0, 10.0),
        e * rect_warping_constant(10.0, 10.0),
    );
    let (gj_l, eg_l) = (
        g * rect_torsion_constant(10.0, 1e-5),
        e * rect_warping_constant(10.0, 1e-5),
    );
    assert!(gj_b / gj_l > 1e17);
    let mut xs: Vec<f64> = (0..=20).map(|i| i as f64).collect();
    xs.extend((1..=40).map(|i| 20.0 + i as f64 / 40.0));
    xs.extend((1..=20).map(|i| 21.0 + i as f64));
    let k_fe = torsion_fe(&xs, |x| {
        if (20.0..21.0).contains(&x) {
            (gj_l, eg_l)
        } else {
            (gj_b, eg_b)
        }
    });
    let kk = (gj_l / eg_l).sqrt();
    let exact = gj_l / (1.0 - 2.0 * (kk / 2.0).tanh() / kk);
    assert!((k_fe / exact - 1.0).abs() < 1e-4, "{k_fe} vs {exact}");
}
