//! `check` refuses, with the JSON path, every input that `run` refuses: conflicting
//! constraints the solver used to find only at `run` ("analysis failed at `model`", exit 1),
//! infinite allowables, over-long load case names and overlapping sweep paths. And inputs that
//! `check` accepts run: a weld between nodes closer than the joint tolerance, a stage with
//! ideal joints.
//!
//! Each refusal is asserted on the same path from `check` and from `run`, with the words of the
//! rule it states.

use flexfem::analysis::{self, Case, RunError};
use serde_json::{json, Value};
use std::path::PathBuf;

fn cases_dir() -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("cases")
}

fn bundled(name: &str) -> Value {
    let text = std::fs::read_to_string(cases_dir().join(format!("{name}.json"))).unwrap();
    serde_json::from_str(&text).unwrap()
}

fn parse(doc: Value) -> Case {
    analysis::parse_value(doc, Some(&cases_dir())).unwrap_or_else(|e| panic!("parses: {e}"))
}

/// `check` refuses `doc` at `path` with every word of `words` in the message, and `run`
/// refuses it as a case-file error at the same path (exit 2, not an analysis failure).
fn refused(doc: Value, path: &str, words: &[&str]) {
    let case = parse(doc);
    let e = analysis::check(&case).expect_err("check must refuse");
    assert_eq!(e.path, path, "check: {e}");
    for w in words {
        assert!(e.message.contains(w), "check message lacks {w:?}: {e}");
    }
    match analysis::run(&case) {
        Err(RunError::Case(r)) => assert_eq!(r.path, path, "run: {r}"),
        Err(RunError::Analysis(a)) => panic!("run failed in the analysis instead of refusing the input: {a}"),
        Ok(_) => panic!("run accepted what check refused"),
    }
}

/// The 100 mm cantilever of `cases/static_cantilever.json` (nodes 0, 1, 2 on x; node 0 clamped;
/// 10 N down at the tip, node 2), with `extra` nodes appended.
fn cantilever(extra: &[[f64; 3]]) -> Value {
    let mut d = bundled("static_cantilever");
    let nodes = d["nodes"].as_array_mut().unwrap();
    nodes.extend(extra.iter().map(|x| json!(x)));
    d
}

fn weld(a: usize, b: usize) -> Value {
    json!({"type": "joint", "kind": "weld", "nodes": [a, b]})
}

#[test]
fn weld_within_the_joint_tolerance_runs_as_the_unwelded_cantilever() {
    // 1e-5 mm apart in a 100 mm model: within the joint tolerance (1e-6 of the model size,
    // 1e-4 mm), so check accepts it; run used to fail with "tie 0: nodes … apart" (a tighter
    // absolute tolerance). The weld is rigid: the tip deflection is that of the plain
    // cantilever, to round-off.
    let mut d = cantilever(&[[100.0, 0.0, 1e-5]]);
    d["elements"].as_array_mut().unwrap().push(weld(2, 3));
    d["load_cases"][0]["forces"][0]["node"] = json!(3);
    let case = parse(d);
    analysis::check(&case).expect("check accepts the weld");
    let welded = analysis::run(&case).unwrap_or_else(|e| panic!("run: {e}"));
    let plain = analysis::run(&parse(bundled("static_cantilever"))).unwrap_or_else(|e| panic!("{e}"));
    let uz = |o: &analysis::Outcome, n: usize| o.json["load_cases"][0]["displacements"][n][2].as_f64().unwrap();
    let (w, p) = (uz(&welded, 3), uz(&plain, 2));
    assert!(p < -0.01, "the plain cantilever deflects: {p} mm");
    assert!((w - p).abs() <= 1e-9 * p.abs(), "welded tip {w} mm vs plain {p} mm");
}

#[test]
fn a_joint_farther_apart_than_the_tolerance_is_refused_at_check() {
    let mut d = cantilever(&[[100.0, 0.0, 1e-3]]);
    d["elements"].as_array_mut().unwrap().push(weld(2, 3));
    refused(
        d,
        "elements[2].nodes",
        &["apart", "a joint joins coincident nodes", "of the model size"],
    );
}

#[test]
fn a_dof_prescribed_twice_in_one_load_case() {
    let mut d = cantilever(&[]);
    d["load_cases"][0]["displacements"] = json!([
        {"node": 2, "dof": "uz", "value": 1},
        {"node": 2, "dof": "uz", "value": 2}
    ]);
    refused(
        d,
        "load_cases[0].displacements[1].dof",
        &["already prescribed", "displacements[0]"],
    );
}

#[test]
fn a_rigid_link_master_listed_as_its_own_slave() {
    let mut d = cantilever(&[]);
    d["rigid_links"] = json!([{"master": 1, "slaves": [1, 2]}]);
    refused(d, "rigid_links[0].slaves[0]", &["own slave"]);
}

#[test]
fn chained_and_duplicate_rigid_link_slaves() {
    let mut d = cantilever(&[[110.0, 0.0, 0.0]]);
    d["rigid_links"] = json!([{"master": 1, "slaves": [2]}, {"master": 2, "slaves": [3]}]);
    refused(d, "rigid_links[1].master", &["chained", "rigid_links[0]"]);
    let mut d = cantilever(&[[110.0, 0.0, 0.0]]);
    d["rigid_links"] = json!([{"master": 1, "slaves": [3]}, {"master": 2, "slaves": [3]}]);
    refused(d, "rigid_links[1].slaves[0]", &["already a slave", "rigid_links[0]"]);
    // The same slave twice in one link, given as a `rigid` element.
    let mut d = cantilever(&[[110.0, 0.0, 0.0]]);
    d["elements"]
        .as_array_mut()
        .unwrap()
        .push(json!({"type": "rigid", "master": 2, "slaves": [3, 3]}));
    refused(d, "elements[2].slaves[1]", &["listed twice"]);
}

#[test]
fn a_supported_or_prescribed_rigid_link_slave() {
    let mut d = cantilever(&[[110.0, 0.0, 0.0]]);
    d["rigid_links"] = json!([{"master": 2, "slaves": [3]}]);
    d["supports"]
        .as_array_mut()
        .unwrap()
        .push(json!({"node": 3, "fix": ["ux"]}));
    refused(
        d,
        "supports[1].node",
        &["slave of `rigid_links[0]`", "support the master"],
    );
    let mut d = cantilever(&[[110.0, 0.0, 0.0]]);
    d["rigid_links"] = json!([{"master": 2, "slaves": [3]}]);
    d["load_cases"][0]["displacements"] = json!([{"node": 3, "dof": "uz", "value": 1}]);
    refused(
        d,
        "load_cases[0].displacements[0].node",
        &["slave of `rigid_links[0]`", "prescribe the master"],
    );
}

#[test]
fn two_joints_on_one_node_pair_and_a_joint_on_a_slave() {
    let mut d = cantilever(&[[100.0, 0.0, 0.0]]);
    d["elements"].as_array_mut().unwrap().extend([weld(2, 3), weld(2, 3)]);
    refused(d, "elements[3].nodes", &["already joined by `elements[2]`"]);
    let mut d = cantilever(&[[110.0, 0.0, 0.0], [110.0, 0.0, 0.0]]);
    d["rigid_links"] = json!([{"master": 2, "slaves": [3]}]);
    d["elements"].as_array_mut().unwrap().push(weld(3, 4));
    refused(d, "elements[2].nodes", &["slave of `rigid_links[0]`"]);
}

#[test]
fn a_tied_dof_that_is_also_supported() {
    // Both nodes of the weld carry a support, so the tie cannot be turned round: node 3's ux
    // follows node 2's and cannot be supported as well.
    let mut d = cantilever(&[[100.0, 0.0, 0.0]]);
    d["elements"].as_array_mut().unwrap().push(weld(2, 3));
    let s = d["supports"].as_array_mut().unwrap();
    s.push(json!({"node": 3, "fix": ["ux"]}));
    s.push(json!({"node": 2, "fix": ["uy"]}));
    refused(d, "supports[1].node", &["tied to node 2", "elements[2]"]);
}

fn transient_with(motions: Value) -> Value {
    let mut d = cantilever(&[[110.0, 0.0, 0.0]]);
    let m = d.as_object_mut().unwrap();
    m.remove("load_cases");
    m.insert("analysis".into(), json!("transient"));
    m.insert("dt".into(), json!(1e-4));
    m.insert("steps".into(), json!(5));
    m.insert("rigid_links".into(), json!([{"master": 2, "slaves": [3]}]));
    m.insert("motions".into(), motions);
    d
}

#[test]
fn transient_motions_given_twice_or_on_a_rigid_link_slave() {
    let ramp = json!({"type": "ramp", "end": 1e-3});
    refused(
        transient_with(json!([
            {"node": 2, "dof": "uz", "value": 0.1, "history": ramp},
            {"node": 2, "dof": "uz", "value": 0.2, "history": ramp}
        ])),
        "motions[1].dof",
        &["already moved by `motions[0]`"],
    );
    refused(
        transient_with(json!([{"node": 3, "dof": "uz", "value": 0.1, "history": ramp}])),
        "motions[0].node",
        &["rigid-link slave", "master 2"],
    );
}

#[test]
fn sensitivity_and_nonlinear_hinge_need_an_allowable() {
    // Both ran into an infinite number (z at an infinite allowable; force levels up to it).
    let mut d = bundled("ruiz2019_sensitivity");
    d["material"] = json!({"E": 71700, "nu": 0.33});
    refused(d, "material", &["allowable"]);
    let mut d = bundled("ruiz2019_hinge_revolute");
    d["material"] = json!({"E": 71700, "nu": 0.33});
    d["nonlinear"] = json!(true);
    d["steps"] = json!(2);
    refused(d, "material", &["allowable", "nonlinear"]);
}

#[test]
fn stage_with_ideal_joints_runs_and_needs_no_force_for_a_compatible_stroke() {
    // Ideal joints make the 3-PRS stage a mechanism of three degrees of freedom driven by its
    // sliders: a stroke set that follows the linearised IKP (the `unit_z` set of stiffness_z)
    // is a rigid-body motion and needs no actuator force, so stiffness_z is ~0 — against
    // several N/mm for the compliant stage. It used to fail: the unit-force load case added
    // for the reach at the allowable is a mechanism with free sliders.
    let mut d = bundled("ruiz2019_stage");
    d["load_cases"] = json!([{"name": "lift", "actuator_strokes": [0.01, 0.01, 0.01]}]);
    let compliant = analysis::run(&parse(d.clone())).unwrap_or_else(|e| panic!("{e}"));
    d["stage"]["ideal_joints"] = json!(true);
    let case = parse(d.clone());
    analysis::check(&case).expect("check");
    let ideal = analysis::run(&case).unwrap_or_else(|e| panic!("run with ideal joints: {e}"));
    let k_c = compliant.json["stiffness_z"].as_f64().unwrap();
    let k_i = ideal.json["stiffness_z"].as_f64().unwrap();
    assert!(k_c > 1.0, "compliant stiffness_z {k_c} N/mm");
    assert!(
        k_i.abs() < 1e-6 * k_c,
        "ideal stiffness_z {k_i} N/mm vs compliant {k_c} N/mm"
    );
    assert!(
        ideal.json["at_allowable"]["force"].is_null(),
        "{}",
        ideal.json["at_allowable"]
    );
    // Actuator forces on free sliders are a mechanism: refused at check.
    d["load_cases"] = json!([{"name": "F", "actuator_forces": [1, 1, 1]}]);
    refused(
        d,
        "load_cases[0].actuator_forces",
        &["ideal_joints", "actuator_strokes"],
    );
}

#[test]
fn a_load_case_name_too_long_for_a_file_name() {
    let mut d = cantilever(&[]);
    d["load_cases"][0]["name"] = json!("x".repeat(300));
    refused(d, "load_cases[0].name", &["at most 200 characters"]);
}

#[test]
fn overlapping_vary_paths() {
    let d = json!({
        "analysis": "sweep",
        "base": bundled("ruiz2019_hinge_revolute"),
        "vary": {
            "hinge": [{"type": "circular_notch", "R": 8, "t": 2, "w": 10, "h": 10}],
            "hinge.t": [1.5, 2.5]
        }
    });
    let Case::Sweep(s) = parse(d) else { panic!("a sweep") };
    let e = s.build().expect_err("overlapping paths refused");
    assert_eq!(e.path, "vary.hinge.t", "{e}");
    assert!(e.message.contains("inside `vary.hinge`"), "{e}");
}

#[test]
fn an_unbalanced_static_solution_is_an_analysis_error_not_a_result() {
    // Found by the fuzzer: the FSW head frame of Han et al. (2019) with one section's Iz set to
    // 2^64 mm⁴, 14 orders above the others. The solve "succeeded" with an equilibrium residual
    // of 22 N against 2.5e5 N of loads and reactions (8.8e-5); the statics check (1e-6) now
    // fails the run, naming the load case.
    let mut d = bundled("han2019_prs_head");
    d["sections"]["platform_arm"]["Iz"] = json!(18446744073709551615u64);
    let case = parse(d);
    analysis::check(&case).expect("the input is valid");
    match analysis::run(&case) {
        Err(RunError::Analysis(e)) => {
            assert!(e.context.starts_with("load case `"), "{e}");
            assert!(e.message.contains("does not balance the loads"), "{e}");
        }
        Err(RunError::Case(e)) => panic!("refused as input: {e}"),
        Ok(o) => panic!(
            "run wrote a result: residual {}",
            o.json["load_cases"][0]["equilibrium_residual"]
        ),
    }
    // The bundled case itself balances.
    let o = analysis::run(&parse(bundled("han2019_prs_head"))).unwrap_or_else(|e| panic!("{e}"));
    assert!(o.json["load_cases"][0]["equilibrium_residual"].is_array());
}
