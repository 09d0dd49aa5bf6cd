//! `flexfem sweep --fields` and the model-notes sidecar of `--out`, through the real binary.

mod common;
use common::*;
use serde_json::Value;

/// Two stage designs (revolute t = 1.5, 2) of the bundled stage case, one load case.
fn stage_sweep() -> String {
    let mut base = common::fixtures::ruiz2019_stage_json();
    base["load_cases"] = serde_json::json!([{"name": "F20", "actuator_forces": [20, 20, 20]}]);
    serde_json::json!({"analysis": "sweep", "base": base, "vary": {"stage.revolute.t": [1.5, 2]}}).to_string()
}

/// `--fields` keeps exactly the named result fields (values equal to the full line's);
/// index, params and design_hash stay.
#[test]
fn fields_select_result_fields() {
    let d = tempdir("fields");
    let case = write(&d, "sweep.json", &stage_sweep());
    let full = parse_lines(&stdout(&sweep(&d, &[case.to_str().unwrap()])));
    let o = sweep(
        &d,
        &[
            case.to_str().unwrap(),
            "--fields",
            "stiffness_z,at_allowable.force,load_cases.0.platform.z",
        ],
    );
    assert_eq!(o.status.code(), Some(0), "stderr: {}", stderr(&o));
    let sel = parse_lines(&stdout(&o));
    assert_eq!(sel.len(), 2);
    for v in &sel {
        let f = full.iter().find(|f| f["index"] == v["index"]).unwrap();
        assert_eq!(v["params"], f["params"]);
        assert_eq!(v["design_hash"], f["design_hash"]);
        let r = v["result"].as_object().unwrap();
        assert_eq!(r.len(), 3, "{v}");
        assert_eq!(r["stiffness_z"], f["result"]["stiffness_z"]);
        assert_eq!(v["result"]["at_allowable"].as_object().unwrap().len(), 1);
        assert_eq!(
            v["result"]["at_allowable"]["force"],
            f["result"]["at_allowable"]["force"]
        );
        assert_eq!(
            v["result"]["load_cases"]["0"]["platform"]["z"],
            f["result"]["load_cases"][0]["platform"]["z"]
        );
    }
    // An empty field name is a usage error (exit 2).
    let o = sweep(&d, &[case.to_str().unwrap(), "--fields", "stiffness_z,,x"]);
    assert_eq!(o.status.code(), Some(2));
    assert!(stderr(&o).contains("--fields"), "{}", stderr(&o));
    cleanup(&d);
}

/// With `--out`, lines carry `model_notes` (a reference) instead of the notes, which are in
/// `FILE.jsonl.notes.json` once; a resumed run keeps the sidecar.
#[test]
fn out_moves_model_notes_to_the_sidecar() {
    let d = tempdir("notes");
    let case = write(&d, "sweep.json", &stage_sweep());
    let full = parse_lines(&stdout(&sweep(&d, &[case.to_str().unwrap()])));
    let out = d.join("s.jsonl");
    let o = sweep(&d, &[case.to_str().unwrap(), "--out", out.to_str().unwrap()]);
    assert_eq!(o.status.code(), Some(0), "stderr: {}", stderr(&o));
    let lines = parse_lines(&std::fs::read_to_string(&out).unwrap());
    let notes: Value = serde_json::from_str(&std::fs::read_to_string(d.join("s.jsonl.notes.json")).unwrap()).unwrap();
    for v in &lines {
        assert!(v["result"].get("model").is_none());
        let r = v["result"]["model_notes"].as_str().unwrap();
        let f = full.iter().find(|f| f["index"] == v["index"]).unwrap();
        assert_eq!(notes[r], f["result"]["model"]);
        assert_eq!(v["result"]["stiffness_z"], f["result"]["stiffness_z"]);
    }
    assert_eq!(notes.as_object().unwrap().len(), 1);
    // Everything done: a re-run runs nothing and keeps lines and notes.
    let o = sweep(&d, &[case.to_str().unwrap(), "--out", out.to_str().unwrap()]);
    assert_eq!(o.status.code(), Some(0), "stderr: {}", stderr(&o));
    assert_eq!(parse_lines(&std::fs::read_to_string(&out).unwrap()), lines);
    let again: Value = serde_json::from_str(&std::fs::read_to_string(d.join("s.jsonl.notes.json")).unwrap()).unwrap();
    assert_eq!(again, notes);
    cleanup(&d);
}
