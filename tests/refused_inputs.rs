//! Inputs that used to be accepted silently (a run returning zeros, a node silently replaced, a
//! key ignored) are refused as case-file errors naming the JSON path and what is allowed; and
//! elements shorter than 1e-9 of the model size are refused at `check`.

use flexfem::analysis::{self, Case, RunError};
use serde_json::{json, Value};
use std::path::{Path, PathBuf};

mod common;

fn root() -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR"))
}

fn bundled(name: &str) -> Value {
    let text = std::fs::read_to_string(root().join("cases").join(format!("{name}.json"))).unwrap();
    serde_json::from_str(&text).unwrap()
}

/// `check` and `run` both refuse `doc` at `path`, the message holding every word of `words`.
fn refused(doc: Value, base: &Path, path: &str, words: &[&str]) {
    let case = analysis::parse_value(doc, Some(base)).unwrap_or_else(|e| panic!("parses: {e}"));
    let e = analysis::check(&case).expect_err("check must refuse");
    assert_eq!(e.path, path, "check: {e}");
    for w in words {
        assert!(e.message.contains(w), "message lacks {w:?}: {e}");
    }
    match analysis::run(&case) {
        Err(RunError::Case(r)) => assert_eq!(r.path, path, "run: {r}"),
        Err(RunError::Analysis(a)) => panic!("run failed in the analysis: {a}"),
        Ok(_) => panic!("run accepted what check refused"),
    }
}

fn cases() -> PathBuf {
    root().join("cases")
}

#[test]
fn a_static_load_case_without_loads() {
    // It ran and returned zero displacements and reactions.
    let mut d = bundled("static_cantilever");
    d["load_cases"].as_array_mut().unwrap().push(json!({"name": "empty"}));
    refused(d, &cases(), "load_cases[1]", &["loads nothing", "`forces`"]);
}

#[test]
fn a_transient_without_loads_or_motions() {
    let mut d = bundled("pendulum_nonlinear_transient");
    d.as_object_mut().unwrap().remove("loads");
    refused(d, &cases(), "loads", &["no loads and no motions", "`motions`"]);
}

#[test]
fn a_gmsh_file_with_a_node_tag_given_twice() {
    // The bundled plate mesh with node tag 1 defined a second time at the end of its node
    // block: the second definition silently replaced the first.
    let text = std::fs::read_to_string(root().join("meshes/plate_clamped_tris.msh")).unwrap();
    let mut lines: Vec<String> = text.lines().map(str::to_string).collect();
    let i = lines.iter().position(|l| l == "$Nodes").unwrap();
    assert_eq!(lines[i + 1], "1 289 1 289", "the bundled mesh's node header");
    assert_eq!(lines[i + 2], "2 1 0 289", "its one node block");
    lines[i + 1] = "1 290 1 290".into();
    lines[i + 2] = "2 1 0 290".into();
    let tags_end = i + 3 + 289;
    assert_eq!(lines[tags_end - 1], "289");
    lines.insert(tags_end, "1".into());
    let coords_end = tags_end + 1 + 289;
    let first = lines[tags_end + 1].clone();
    lines.insert(coords_end, first);
    assert_eq!(lines[coords_end + 1], "$EndNodes");
    let dir = std::env::temp_dir().join(format!("flexfem-refused-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let msh = dir.join("plate_duplicate_tag.msh");
    std::fs::write(&msh, lines.join("\n") + "\n").unwrap();
    let mut d = bundled("gmsh_plate_tris");
    d["mesh"] = json!(msh.to_string_lossy());
    let e = match analysis::parse_value(d, Some(&cases())) {
        Err(e) => e,
        Ok(_) => panic!("a mesh with a node tag given twice was accepted"),
    };
    let _ = std::fs::remove_dir_all(&dir);
    assert_eq!(e.path, "mesh", "{e}");
    assert!(e.message.contains("node tag 1 twice"), "{e}");
    assert!(e.message.contains("unique"), "{e}");
}

#[test]
fn an_unknown_key_inside_a_vary_range() {
    let d = json!({
        "analysis": "sweep",
        "base": bundled("ruiz2019_hinge_revolute"),
        "vary": {"hinge.R": {"from": 6, "to": 10, "steps": 3, "foo": 1}}
    });
    let Case::Sweep(s) = analysis::parse_value(d, Some(&cases())).unwrap() else {
        panic!("a sweep")
    };
    let e = s.build().expect_err("unknown range key refused");
    assert_eq!(e.path, "vary.hinge.R.foo", "{e}");
    assert!(e.message.contains("\"from\", \"to\", \"steps\""), "{e}");
}

#[test]
fn a_rigid_link_master_as_its_own_slave_in_a_constraints_case() {
    // The `constraints` analysis builds no stiffness, so nothing refused it; `static` did.
    let mesh: Value =
        serde_json::from_str(&std::fs::read_to_string(root().join("meshes/parallelogram_notch.json")).unwrap())
            .unwrap();
    let mut d = bundled("constraints_parallelogram_guide");
    let m = d.as_object_mut().unwrap();
    m.remove("mesh");
    for (k, v) in mesh.as_object().unwrap() {
        if k != "load_cases" && k != "description" {
            m.insert(k.clone(), v.clone());
        }
    }
    let n = mesh["nodes"].as_array().unwrap().len();
    assert!(n >= 2);
    m.insert("rigid_links".into(), json!([{"master": 0, "slaves": [0, 1]}]));
    refused(d, &cases(), "rigid_links[0].slaves[0]", &["own slave"]);
}

/// A 100 mm cantilever (`cases/static_cantilever.json`) with a fourth node `gap` mm beyond its
/// tip, joined to it by `element`.
fn with_short_element(gap: f64, element: Value) -> Value {
    let mut d = bundled("static_cantilever");
    d["nodes"].as_array_mut().unwrap().push(json!([100.0 + gap, 0.0, 0.0]));
    d["elements"].as_array_mut().unwrap().push(element);
    d
}

#[test]
fn elements_shorter_than_1e_9_of_the_model_size() {
    // Model size 100 mm: the limit is 1e-7 mm. 1e-8 mm passed before (the old check was
    // absolute, 1e-12 mm); 1e-13 mm was refused as "zero-length" and still is, now relative.
    let beam = json!({"type": "beam", "nodes": [2, 3], "section": "leg", "material": "al", "up": [0, 0, 1]});
    for gap in [1e-8, 1e-13] {
        refused(
            with_short_element(gap, beam.clone()),
            &cases(),
            "elements[2].nodes",
            &["1e-9 of the model size"],
        );
    }
    let hinge = json!({"type": "hinge", "nodes": [2, 3], "material": "al", "up": [0, 0, 1],
        "hinge": {"type": "circular_notch", "R": 5.0, "t": 1.0, "w": 10.0, "h": 10.0}});
    refused(
        with_short_element(1e-8, hinge),
        &cases(),
        "elements[2].nodes",
        &["1e-9 of the model size"],
    );
    // A shell4 with one edge 1e-8 mm long.
    let mut d = bundled("static_cantilever");
    d["nodes"]
        .as_array_mut()
        .unwrap()
        .extend([json!([100.0, 1e-8, 0.0]), json!([50.0, 20.0, 0.0])]);
    d["sections"]["skin"] = json!({"shape": "shell", "t": 1.0});
    d["elements"]
        .as_array_mut()
        .unwrap()
        .push(json!({"type": "shell4", "nodes": [1, 2, 3, 4], "section": "skin", "material": "al"}));
    refused(d, &cases(), "elements[2].nodes", &["1e-9 of the model size"]);
    // At 1e-6 of the size (1e-4 mm) a beam is accepted: the limit is not an absolute length.
    let ok = with_short_element(
        1e-4,
        json!({"type": "beam", "nodes": [2, 3], "section": "leg", "material": "al", "up": [0, 0, 1]}),
    );
    let case = analysis::parse_value(ok, Some(&cases())).unwrap();
    analysis::check(&case).expect("a 1e-4 mm beam in a 100 mm model is accepted");
}

/// An error in the model of a mesh file the case names is reported at `mesh`, naming the file
/// and the path inside it, for a mesh file without parameters or hinge types too: before, a
/// node index out of range in the bundled pan-tilt's mesh file was reported at
/// `elements[1].nodes[1]`, a path the case file does not have. Errors at keys the case writes,
/// or that neither writes (a missing `modes`), stay the case's.
#[test]
fn an_error_in_a_mesh_files_model_names_the_file() {
    let d = common::tempdir("mesh-file-error");
    let mut mesh: Value =
        serde_json::from_str(&std::fs::read_to_string(root().join("meshes/pantilt_8r.json")).unwrap()).unwrap();
    assert!(mesh.get("parameters").is_none() && mesh.get("hinge_types").is_none());
    mesh["elements"][1]["nodes"] = json!([0, 99]);
    common::write(&d, "my_mesh.json", &mesh.to_string());
    let mut case = bundled("pantilt_8r");
    case["mesh"] = json!("my_mesh.json");
    common::write(&d, "case.json", &case.to_string());
    for cmd in ["check", "run"] {
        let err = common::exits_2(&common::run_in(&d, &[cmd, "case.json"]), &["node index must be < 16"]);
        assert!(
            err.contains("at `mesh`: in mesh file \"my_mesh.json\" at `elements[1].nodes[1]`"),
            "{cmd}: {err}"
        );
    }
    // `check` of `case` beside the mesh file `mesh`: refused, the message holding `needle`.
    let refused = |mesh: &Value, case: &Value, needle: &str| {
        common::write(&d, "my_mesh.json", &mesh.to_string());
        common::write(&d, "case.json", &case.to_string());
        common::exits_2(&common::run_in(&d, &["check", "case.json"]), &[needle])
    };
    // A section only the mesh file defines is the mesh file's, also when the case adds
    // sections of its own (the model takes both); one the case defines is the case's.
    let mut bad = mesh.clone();
    bad["elements"][1]["nodes"] = json!([0, 1]);
    let first = bad["sections"].as_object().unwrap().keys().next().unwrap().clone();
    bad["sections"][&first]["w"] = json!(-1.0);
    let section = bad["sections"][&first].clone();
    for (extra, at) in [
        (None, "at `mesh`: in mesh file \"my_mesh.json\" at `sections."),
        (Some("extra"), "at `mesh`: in mesh file \"my_mesh.json\" at `sections."),
        (Some(first.as_str()), "at `sections."),
    ] {
        let mut c = case.clone();
        if let Some(name) = extra {
            let mut own = section.clone();
            own["w"] = json!(if name == "extra" { 1.0 } else { -2.0 });
            c["sections"] = json!({ name: own });
        }
        let err = refused(&bad, &c, "must be a positive number");
        assert!(err.contains(&format!("{at}{first}.w`")), "{extra:?}: {err}");
    }
    // A list the case writes empty leaves the mesh file's in the model: its errors are the
    // mesh file's (elements: the node index out of range again; load cases: `"load_cases": []`
    // beside a mesh file whose load case names a missing node).
    let mut c = case.clone();
    c["elements"] = json!([]);
    refused(
        &mesh,
        &c,
        "at `mesh`: in mesh file \"my_mesh.json\" at `elements[1].nodes[1]`",
    );
    let mut with_loads = mesh.clone();
    with_loads["elements"] = bad["elements"].clone();
    with_loads["load_cases"] = json!([{"name": "push", "forces": [{"node": 99, "F": [1, 0, 0, 0, 0, 0]}]}]);
    let mut c = case.clone();
    c["load_cases"] = json!([]);
    refused(
        &with_loads,
        &c,
        "at `mesh`: in mesh file \"my_mesh.json\" at `load_cases[0].forces[0].node`",
    );
    // A material only the mesh file defines, its name holding a dot, beside the case's own.
    let mut dotted = mesh.clone();
    dotted["elements"] = bad["elements"].clone();
    dotted["materials"] = json!({"PA6.6": {"E": -1.0, "nu": 0.3, "density": 1.1e-9}});
    for e in dotted["elements"].as_array_mut().unwrap() {
        if e.get("material").is_some() {
            e["material"] = json!("PA6.6");
        }
    }
    let mut c = case.clone();
    c["materials"] = json!({"other": "steel"});
    refused(
        &dotted,
        &c,
        "at `mesh`: in mesh file \"my_mesh.json\" at `materials.PA6.6.E`",
    );
    // A key neither writes stays the case's: a modal case without `modes`, a case without
    // `analysis`, a static case whose mesh file has no load cases.
    let plain = json!({"nodes": mesh["nodes"], "elements": bad["elements"], "materials": mesh["materials"], "sections": mesh["sections"], "supports": mesh["supports"]});
    for (c, at) in [
        (
            json!({"analysis": "modal", "mesh": "my_mesh.json"}),
            "at `modes`: missing field `modes`",
        ),
        (
            json!({"mesh": "my_mesh.json"}),
            "at `analysis`: missing field `analysis`",
        ),
        (
            json!({"analysis": "static", "mesh": "my_mesh.json"}),
            "at `load_cases`: at least one load case",
        ),
    ] {
        let err = refused(&plain, &c, at);
        assert!(!err.contains("in mesh file"), "{err}");
    }
    common::cleanup(&d);
}

/// An expression error in a hinge type the mesh file declares is reported at `mesh`, naming the
/// file and the path inside it (it was reported at `hinge_types.flex.t`, a path the case file
/// does not have); one in a hinge type the case declares stays at the case's path.
#[test]
fn an_error_in_a_mesh_files_hinge_type_names_the_file() {
    let d = common::tempdir("mesh-file-hinge-type");
    let mut mesh: Value =
        serde_json::from_str(&std::fs::read_to_string(root().join("meshes/pantilt_8r_parameters.json")).unwrap())
            .unwrap();
    mesh["hinge_types"]["flex"]["t"] = json!("$tt");
    common::write(&d, "my_mesh.json", &mesh.to_string());
    let mut case = bundled("pantilt_8r");
    case["mesh"] = json!("my_mesh.json");
    common::write(&d, "case.json", &case.to_string());
    common::exits_2(
        &common::run_in(&d, &["check", "case.json"]),
        &[
            "at `mesh`: in mesh file \"my_mesh.json\" at `hinge_types.flex.t`",
            "$tt",
        ],
    );
    case["hinge_types"] = mesh["hinge_types"].clone();
    common::write(&d, "case.json", &case.to_string());
    let err = common::exits_2(
        &common::run_in(&d, &["check", "case.json"]),
        &["at `hinge_types.flex.t`", "$tt"],
    );
    assert!(!err.contains("in mesh file"), "{err}");
    common::cleanup(&d);
}
