//! `flexfem sweep --fields`, the compact default stage line (`--full`), the model-notes sidecar of
//! `--out` and the array check of the designs, through the real binary.

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

/// `flexfem sweep CASE --out OUT` (plus `extra`), which must succeed.
fn sweep_to(d: &std::path::Path, case: &std::path::Path, out: &std::path::Path, extra: &[&str]) {
    let mut args = vec![case.to_str().unwrap(), "--out", out.to_str().unwrap()];
    args.extend_from_slice(extra);
    let o = sweep(d, &args);
    assert_eq!(o.status.code(), Some(0), "stderr: {}", stderr(&o));
}

/// The default stage line leaves out exactly the fields `omitted_fields("stage")` names and is
/// at most 1,000 bytes with `--out` (the brief's target; the full line is ~2,100 bytes);
/// `--full` keeps the full result, equal to the default line's kept fields.
#[test]
fn stage_lines_are_compact_by_default_and_full_on_request() {
    let d = tempdir("compact");
    let case = write(&d, "sweep.json", &stage_sweep());
    let out = d.join("s.jsonl");
    sweep_to(&d, &case, &out, &[]);
    let text = std::fs::read_to_string(&out).unwrap();
    let compact = parse_lines(&text);
    assert_eq!(compact.len(), 2);
    for line in text.lines() {
        assert!(line.len() < 1000, "{} bytes: {line}", line.len());
    }
    let full = parse_lines(&stdout(&sweep(&d, &[case.to_str().unwrap(), "--full"])));
    for v in &compact {
        let f = full.iter().find(|f| f["index"] == v["index"]).unwrap();
        let (r, fr) = (&v["result"], &f["result"]);
        assert!(r.get("material").is_none() && fr["material"].is_object());
        assert!(r["platform_stiffness"].get("compliance").is_none());
        assert_eq!(fr["platform_stiffness"]["compliance"].as_array().unwrap().len(), 6);
        assert_eq!(
            r["platform_stiffness"]["rotational_eigen"],
            fr["platform_stiffness"]["rotational_eigen"]
        );
        let (lc, flc) = (&r["load_cases"][0], &fr["load_cases"][0]);
        assert!(lc.get("forces").is_none() && lc.get("hinge_stress").is_none());
        assert!(flc["hinge_stress"].is_object());
        for k in ["platform", "max_von_mises", "strokes", "T", "factor_at_allowable"] {
            assert_eq!(lc[k], flc[k], "{k}");
        }
        for k in ["stiffness_z", "warnings"] {
            assert_eq!(r[k], fr[k], "{k}");
        }
        for k in ["force", "stroke", "z"] {
            assert_eq!(r["at_allowable"][k], fr["at_allowable"][k], "{k}");
        }
        // Echoes of the case: the material's allowable stress and the `nonlinear` flag.
        assert!(r["at_allowable"].get("allowable").is_none() && fr["at_allowable"]["allowable"] == 400.0);
        assert!(r.get("nonlinear").is_none() && fr["nonlinear"] == false);
        assert_eq!(v["design_hash"], f["design_hash"]);
    }
    // --full and --fields together are refused (exit 2).
    exits_2(
        &sweep(&d, &[case.to_str().unwrap(), "--full", "--fields", "stiffness_z"]),
        &["--full", "--fields"],
    );
    cleanup(&d);
}

/// Notches whose notes differ (R = 8000 mm needs no load spreading, the others do: the notes
/// say which), while the numbers they depend on are result fields, so designs of one kind
/// share notes.
const NOTES_SWEEP: &str = r#"{"analysis": "sweep",
  "base": {"analysis": "hinge", "material": "Al7075",
    "hinge": {"type": "circular_notch", "R": 8, "t": 2, "w": 10, "h": 10, "blank_length": 20}},
  "vary": {"hinge.t": [1, 2], "hinge.R": [4, 8, 8000]}}"#;

/// The sidecar holds one entry per distinct reference (2 for 6 designs), each equal to that
/// design's notes on stdout. A sidecar torn in its last entry (a killed run) is not refused:
/// the complete entries are kept and the file is whole again after the run.
#[test]
fn notes_sidecar_grows_per_design_and_survives_a_torn_entry() {
    let d = tempdir("notes_each");
    let (out, notes_file) = (d.join("n.jsonl"), d.join("n.jsonl.notes.json"));
    let case = write(&d, "sweep.json", NOTES_SWEEP);
    let full = parse_lines(&stdout(&sweep(&d, &[case.to_str().unwrap()])));
    let check = |expect_entries: usize| {
        let lines = parse_lines(&std::fs::read_to_string(&out).unwrap());
        assert_eq!(lines.len(), 6);
        let notes: Value = serde_json::from_str(&std::fs::read_to_string(&notes_file).unwrap()).unwrap();
        assert_eq!(notes.as_object().unwrap().len(), expect_entries);
        for v in &lines {
            let f = full.iter().find(|f| f["index"] == v["index"]).unwrap();
            assert_eq!(
                notes[v["result"]["model_notes"].as_str().unwrap()],
                f["result"]["model"]
            );
        }
    };
    sweep_to(&d, &case, &out, &[]);
    let distinct: std::collections::HashSet<String> = full.iter().map(|f| f["result"]["model"].to_string()).collect();
    assert_eq!(distinct.len(), 2, "two kinds of notes among these designs");
    check(distinct.len());
    // As if killed while writing the last entry (before the line of its design): tear the
    // entry and drop the line referring to it. The rerun keeps the other entries, runs that
    // design and writes its notes again.
    let text = std::fs::read_to_string(&notes_file).unwrap();
    let last_entry = text.lines().rev().nth(1).unwrap();
    let last_ref = &last_entry[1..9];
    std::fs::write(&notes_file, &text[..text.len() - 40]).unwrap();
    let lines = std::fs::read_to_string(&out).unwrap();
    let kept: Vec<&str> = lines.lines().filter(|l| !l.contains(last_ref)).collect();
    // The two designs with R = 8000 (the notes without load spreading) or the other four.
    assert!(kept.len() == 2 || kept.len() == 4, "{} lines kept", kept.len());
    std::fs::write(&out, kept.join("\n") + "\n").unwrap();
    sweep_to(&d, &case, &out, &[]);
    check(distinct.len());
    cleanup(&d);
}

/// A base case with an array where an object belongs fails in every design (the check is done
/// on each design until one passes), and a varied value that is an array is checked in its own
/// design: the error names the JSON path.
#[test]
fn arrays_for_objects_are_refused_in_every_design() {
    let d = tempdir("shapes");
    let base_positional = r#"{"analysis": "sweep",
      "base": {"analysis": "hinge", "material": "Al7075", "hinge": ["circular_notch", 8, 2, 10, 10, 20]},
      "vary": {"material": ["Al7075", "steel"]}}"#;
    let case = write(&d, "a.json", base_positional);
    let o = sweep(&d, &[case.to_str().unwrap()]);
    assert_eq!(o.status.code(), Some(1), "stderr: {}", stderr(&o));
    let lines = parse_lines(&stdout(&o));
    assert_eq!(lines.len(), 2);
    for v in &lines {
        let e = v["error"].as_str().unwrap();
        assert!(e.starts_with("hinge: ") && e.contains("an object is expected"), "{e}");
    }
    let varied_positional = r#"{"analysis": "sweep",
      "base": {"analysis": "hinge", "material": "Al7075",
        "hinge": {"type": "circular_notch", "R": 8, "t": 2, "w": 10, "h": 10, "blank_length": 20}},
      "vary": {"hinge": [{"type": "circular_notch", "R": 8, "t": 2, "w": 10, "h": 10, "blank_length": 20},
                         ["circular_notch", 8, 2, 10, 10, 20]]}}"#;
    let case = write(&d, "b.json", varied_positional);
    let o = sweep(&d, &[case.to_str().unwrap()]);
    assert_eq!(o.status.code(), Some(1), "stderr: {}", stderr(&o));
    let lines = parse_lines(&stdout(&o));
    let by_index = |i: u64| lines.iter().find(|v| v["index"] == i).unwrap();
    assert!(by_index(0)["result"]["k_bend"].as_f64().unwrap() > 0.0);
    let e = by_index(1)["error"].as_str().unwrap();
    assert!(e.starts_with("hinge: ") && e.contains("an object is expected"), "{e}");
    cleanup(&d);
}
