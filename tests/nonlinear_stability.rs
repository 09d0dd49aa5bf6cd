//! Step control and stability of nonlinear solves: a wrong branch is never returned silently,
//! and every converged point is checked for stability (positive definite tangent stiffness),
//! reported as `stable` and the bracketing `critical_load_factor`.

use flexfem::fem::{solve_nonlinear, Beam, Dof, LoadCase, Model, Section, Support};
use std::f64::consts::PI;

mod common;
use common::nonlinear::{mat, opts};

/// A straight leaf (L 50, 10 × 0.5, E 70000, 16 elements) clamped at the base, its top
/// guided (rotations and lateral translations of a parallel guide: rotations fixed, axial
/// and lateral translation free), compressed to 7 times its Euler load
/// P_E = π²EI/L² (clamped–guided column, effective length L; S. P. Timoshenko &
/// J. M. Gere, "Theory of elastic stability", 2nd ed. (1961) §2.3). A perfectly straight
/// leaf stays straight in Newton; the straight state past P_E is unstable and must be flagged
/// with the load factor bracketing 1/7.
#[test]
fn leaf_compressed_past_euler_is_flagged() {
    let (l, n, e, w, t) = (50.0, 16, 70000.0, 10.0, 0.5);
    let mut model = Model::new();
    for i in 0..=n {
        model.add_node([0.0, 0.0, l * i as f64 / n as f64]);
    }
    for i in 0..n {
        model.add_beam(Beam::new(i, i + 1, Section::Rect { w, h: t }, mat(e, 0.3), [1.0, 0.0, 0.0]).euler_bernoulli());
    }
    model.supports.push(Support::clamp(0));
    model
        .supports
        .push(Support::dofs(n, &[Dof::Uy, Dof::Rx, Dof::Ry, Dof::Rz]));
    // Weak axis: I = w t³/12.
    let i_weak = w * t.powi(3) / 12.0;
    let pe = PI * PI * e * i_weak / (l * l);
    model
        .load_cases
        .push(LoadCase::new("7PE").force(n, [0.0, 0.0, -7.0 * pe, 0.0, 0.0, 0.0]));
    let res = solve_nonlinear(&model, &opts(20)).unwrap_or_else(|e| panic!("{e}"));
    let c = &res.load_cases[0];
    println!(
        "leaf: stable {}, critical load factor {:?} (1/7 = {:.4}), top uz {:.4}, ux {:.3e}",
        c.stable,
        c.critical_load_factor,
        1.0 / 7.0,
        c.fe.displacements[n][2],
        c.fe.displacements[n][0]
    );
    assert!(!c.stable);
    let [lo, hi] = c.critical_load_factor.unwrap_or_else(|| panic!("no bracket"));
    // FE Euler load of 16 elements within 0.1 % of π²EI/L².
    assert!(
        lo <= 1.001 / 7.0 && hi >= 0.999 / 7.0 && hi - lo <= 0.05 + 1e-12,
        "[{lo}, {hi}]"
    );
    assert!(c.path.iter().any(|p| p.stable) && c.path.iter().any(|p| !p.stable));
}

/// A shallow clamped two-leg arch (span 200, rise 10, rect 10 wide × 1 deep, E 70000, 8
/// elements per leg) under a crown load P. Rise over radius of gyration 35: such a high
/// shallow arch bifurcates into an asymmetric mode before its symmetric limit point
/// (Y. L. Pi, M. A. Bradford & B. Uy, "In-plane stability of arches", IJSS 39 (2002)
/// 105–125); here the symmetric path loses positive definiteness at P ≈ 20–24 N and reaches
/// its limit (snap-through) near 75 N. At 15 N the path is stable (no false alarm); at 40 N the
/// symmetric state is returned flagged `stable: false` with the bracket at the bifurcation;
/// load control to 150 N must not return a snapped state as a silent success: an error naming
/// the step and the likely limit point, or `stable: false`.
#[test]
fn shallow_arch_snap_through_is_flagged() {
    let (a, h, n) = (100.0, 10.0, 8);
    let arch = |p: f64| {
        let mut model = Model::new();
        for i in 0..=2 * n {
            let x = -a + a * i as f64 / n as f64;
            model.add_node([x, 0.0, h * (1.0 - x.abs() / a)]);
        }
        for i in 0..2 * n {
            model.add_beam(
                Beam::new(
                    i,
                    i + 1,
                    Section::Rect { w: 10.0, h: 1.0 },
                    mat(70000.0, 0.3),
                    [0.0, 0.0, 1.0],
                )
                .euler_bernoulli(),
            );
        }
        model.supports.push(Support::clamp(0));
        model.supports.push(Support::clamp(2 * n));
        model
            .load_cases
            .push(LoadCase::new("P").force(n, [0.0, 0.0, -p, 0.0, 0.0, 0.0]));
        model
    };
    let low = solve_nonlinear(&arch(15.0), &opts(10)).unwrap_or_else(|e| panic!("15 N: {e}"));
    let c = &low.load_cases[0];
    println!(
        "arch, 15 N: stable {}, crown uz {:.4}",
        c.stable, c.fe.displacements[n][2]
    );
    assert!(c.stable && c.critical_load_factor.is_none());
    let mid = solve_nonlinear(&arch(40.0), &opts(10)).unwrap_or_else(|e| panic!("40 N: {e}"));
    let c = &mid.load_cases[0];
    println!("arch, 40 N: stable {}, critical {:?}", c.stable, c.critical_load_factor);
    assert!(!c.stable);
    let [lo, hi] = c.critical_load_factor.unwrap_or_else(|| panic!("no bracket"));
    assert!(lo >= 0.4 && hi <= 0.7 && hi - lo <= 0.1 + 1e-12, "[{lo}, {hi}]");
    match solve_nonlinear(&arch(150.0), &opts(10)) {
        Err(e) => {
            println!("arch, 150 N: {e}");
            let msg = e.to_string();
            assert!(msg.contains("(step ") && msg.contains("limit point"), "{msg}");
            // The failure comes at the symmetric limit, between 60 and 90 N (λ 0.4–0.6).
            assert!(
                msg.contains("load factor 0.4") || msg.contains("load factor 0.5"),
                "{msg}"
            );
        }
        Ok(r) => {
            let c = &r.load_cases[0];
            println!(
                "arch, 150 N: stable {}, critical {:?}",
                c.stable, c.critical_load_factor
            );
            assert!(!c.stable);
            let [lo, hi] = c.critical_load_factor.unwrap_or_else(|| panic!("no bracket"));
            assert!(lo >= 0.1 && hi <= 0.2, "[{lo}, {hi}]");
        }
    }
}

/// The compliant stage (cases/ruiz2019_stage.json geometry) at 54 mm strokes: with the default
/// 20 steps it used to converge to z = −187 mm, a wrong branch (forward kinematics +29.5 mm,
/// 200 steps +30.1 mm). Now: the right branch (within 1 mm of the 200-step answer) or an error
/// naming the step.
#[test]
fn stage_at_54_mm_strokes_takes_the_right_branch_or_fails() {
    use flexfem::stage::Drive;
    let text =
        std::fs::read_to_string(common::root().join("cases/ruiz2019_stage.json")).unwrap_or_else(|e| panic!("{e}"));
    let flexfem::analysis::Case::Stage(c) = flexfem::analysis::parse(&text).unwrap_or_else(|e| panic!("{e}")) else {
        panic!("not a stage case")
    };
    let stage = c
        .validate()
        .unwrap_or_else(|e| panic!("{e}"))
        .0
        .build()
        .unwrap_or_else(|e| panic!("{e}"));
    let cases = vec![("s54".to_string(), Drive::Strokes([54.0, 54.0, 54.0]))];
    let fine = stage
        .solve_nonlinear(&cases, 200)
        .unwrap_or_else(|e| panic!("200 steps: {e}"));
    let zf = fine[0].platform.z;
    println!("stage 54 mm, 200 steps: z = {zf:.3} mm, stable {:?}", fine[0].stability);
    assert!((zf - 30.1).abs() < 0.5, "200 steps: z = {zf}");
    match stage.solve_nonlinear(&cases, 20) {
        Ok(r) => {
            let z = r[0].platform.z;
            println!("stage 54 mm, 20 steps: z = {z:.3} mm, stable {:?}", r[0].stability);
            assert!((z - zf).abs() < 1.0, "20 steps: z = {z} vs {zf}");
        }
        Err(e) => {
            println!("stage 54 mm, 20 steps: {e}");
            assert!(e.to_string().contains("(step "), "{e}");
        }
    }
}

/// The same leaf through the CLI: `"stable": false` and `"critical_load_factor"` in the
/// result, and a warning in the Markdown report.
#[test]
fn leaf_stability_in_result_and_report() {
    let (n, l) = (16usize, 50.0);
    let pe = PI * PI * 70000.0 * (10.0 * 0.5f64.powi(3) / 12.0) / (l * l);
    let nodes: Vec<String> = (0..=n)
        .map(|i| format!("[0, 0, {}]", l * i as f64 / n as f64))
        .collect();
    let elements: Vec<String> = (0..n)
        .map(|i| {
            format!(r#"{{"type": "beam", "nodes": [{i}, {}], "section": "s", "material": "m", "up": [1, 0, 0], "shear": false}}"#, i + 1)
        })
        .collect();
    let text = format!(
        r#"{{"analysis": "static", "materials": {{"m": {{"E": 70000, "nu": 0.3, "density": 2.7e-9, "yield": 500}}}},
        "sections": {{"s": {{"shape": "rect", "w": 10, "h": 0.5}}}},
        "nodes": [{}], "elements": [{}],
        "supports": [{{"node": 0, "fix": ["ux", "uy", "uz", "rx", "ry", "rz"]}}, {{"node": {n}, "fix": ["uy", "rx", "ry", "rz"]}}],
        "load_cases": [{{"name": "7PE", "forces": [{{"node": {n}, "F": [0, 0, {}, 0, 0, 0]}}]}}],
        "nonlinear": true}}"#,
        nodes.join(", "),
        elements.join(", "),
        -7.0 * pe
    );
    let d = common::tempdir("nl_leaf_cli");
    let p = d.join("leaf.json");
    std::fs::write(&p, text).unwrap_or_else(|e| panic!("{e}"));
    let out = common::run_in(&d, &["run", "leaf.json", "--out", "out"]);
    assert_eq!(out.status.code(), Some(0), "{}", String::from_utf8_lossy(&out.stderr));
    let v: serde_json::Value =
        serde_json::from_str(&std::fs::read_to_string(d.join("out/result.json")).unwrap_or_default())
            .unwrap_or_else(|e| panic!("{e}"));
    let c = &v["load_cases"][0];
    assert_eq!(c["stable"], serde_json::Value::Bool(false));
    let lo = c["critical_load_factor"][0].as_f64().unwrap_or(f64::NAN);
    let hi = c["critical_load_factor"][1].as_f64().unwrap_or(f64::NAN);
    assert!(lo <= 1.001 / 7.0 && hi >= 0.999 / 7.0, "[{lo}, {hi}]");
    let md = std::fs::read_to_string(d.join("out/report.md")).unwrap_or_default();
    assert!(md.contains("**Warning**") && md.contains("lost stability"), "{md}");
    // ... and in the result's `warnings`, which every result carries.
    let warned = v["warnings"].as_array().is_some_and(|w| {
        w.iter().any(|s| {
            s.as_str()
                .is_some_and(|s| s.contains("7PE") && s.contains("lost stability"))
        })
    });
    assert!(warned, "warnings: {}", v["warnings"]);
}
