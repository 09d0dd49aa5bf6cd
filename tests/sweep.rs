//! `flexfem sweep`: the bundled hinge sweep, shards, resume, error rows, CSV, streaming, and
//! bad arguments — all through the real binary.

mod common;
use common::*;
use serde_json::Value;
use std::collections::BTreeSet;
use std::path::Path;
use std::process::Output;

const BUNDLED: &str = "cases/ruiz2019_hinge_sweep.json";
/// `hinge.t` values of the bundled sweep; `hinge.R` runs 2, 3, … 12 (11 steps).
const T: [f64; 5] = [1.0, 1.5, 2.0, 2.5, 3.0];

fn bundled() -> String {
    root().join(BUNDLED).to_str().unwrap().to_string()
}

/// `flexfem sweep ARGS` in `dir`, asserted to succeed.
fn sweep_ok(dir: &Path, args: &[&str]) -> Output {
    let o = sweep(dir, args);
    ok(&o);
    o
}

fn ok(o: &Output) {
    assert_eq!(o.status.code(), Some(0), "stderr: {}", stderr(o));
}

fn index(v: &Value) -> usize {
    v["index"].as_u64().unwrap() as usize
}

fn sorted_lines(text: &str) -> Vec<String> {
    let mut v: Vec<String> = text.lines().map(str::to_string).collect();
    v.sort();
    v
}

fn rel(a: f64, b: f64) -> f64 {
    (a - b).abs() / b.abs()
}

/// 55 lines, indices 0..54 sorted, params row-major (R fastest), and the t = 2, R = 8 design
/// equal to a direct `flexfem run` of the same hinge.
#[test]
fn bundled_hinge_sweep_writes_55_sorted_lines_with_params() {
    let d = tempdir("bundled");
    let out = d.join("s.jsonl");
    let o = sweep_ok(&d, &[&bundled(), "--out", out.to_str().unwrap()]);
    assert_eq!(summary(&o), [55, 0, 55, 0]);
    assert!(!d.join("s.jsonl.partial").exists());
    let text = std::fs::read_to_string(&out).unwrap();
    let lines = parse_lines(&text);
    assert_eq!(lines.len(), 55);
    for (i, v) in lines.iter().enumerate() {
        assert_eq!(index(v), i);
        let p = v["params"].as_object().unwrap();
        assert_eq!(p.keys().collect::<Vec<_>>(), ["hinge.t", "hinge.R"]);
        assert_eq!(p["hinge.t"].as_f64().unwrap(), T[i / 11]);
        assert!((p["hinge.R"].as_f64().unwrap() - (2.0 + (i % 11) as f64)).abs() < 1e-12);
        assert!(v.get("error").is_none(), "design {i}: {v}");
        assert!(v["result"]["k_bend"].as_f64().unwrap() > 0.0);
    }
    // t = 2 (third value), R = 8 (seventh): index 2·11 + 6.
    let d28 = &lines[28];
    assert_eq!(d28["params"]["hinge.t"].as_f64(), Some(2.0));
    assert_eq!(d28["params"]["hinge.R"].as_f64(), Some(8.0));
    let direct = run(&["run", "cases/ruiz2019_hinge_revolute.json"]);
    ok(&direct);
    let direct: Value = serde_json::from_str(&stdout(&direct)).unwrap();
    for key in ["k_bend", "k_bend_off", "k_torsion", "k_axial", "max_rotation_deg"] {
        let (a, b) = (d28["result"][key].as_f64().unwrap(), direct[key].as_f64().unwrap());
        assert!(rel(a, b) < 1e-9, "{key}: sweep {a} vs run {b}");
    }
    // Ruiz et al. (2019): ANSYS 98.37 N·m/rad for R8/t2; the beam model is within a few per cent.
    assert!(rel(d28["result"]["k_bend"].as_f64().unwrap(), 98_370.0) < 0.03);
    // Thicker waist at the same radius is stiffer: t = 3 vs t = 1 at R = 8.
    let k = |i: usize| lines[i]["result"]["k_bend"].as_f64().unwrap();
    assert!(k(4 * 11 + 6) > k(2 * 11 + 6) && k(2 * 11 + 6) > k(6));
    cleanup(&d);
}

/// Without `--out` the lines stream to stdout: each one valid JSON, every index once.
#[test]
fn stdout_streaming_gives_valid_json_lines() {
    let d = tempdir("stdout");
    let o = sweep_ok(&d, &[&bundled()]);
    let text = stdout(&o);
    assert!(text.ends_with('\n'));
    let lines = parse_lines(&text);
    assert_eq!(lines.len(), 55);
    let idx: BTreeSet<usize> = lines.iter().map(index).collect();
    assert_eq!(idx, (0..55).collect());
    for v in &lines {
        let keys: Vec<&String> = v.as_object().unwrap().keys().collect();
        assert_eq!(keys, ["index", "params", "design_hash", "result"]);
        assert_eq!(v["design_hash"].as_str().unwrap().len(), 32);
    }
    assert_eq!(std::fs::read_dir(&d).unwrap().count(), 0, "no files without --out");
    cleanup(&d);
}

/// Shards 1/3 + 2/3 + 3/3 are the unsharded run as a set of lines, each with its residue.
#[test]
fn shards_concatenated_equal_the_unsharded_run() {
    let d = tempdir("shards");
    let all = sweep_ok(&d, &[&bundled()]);
    let mut joined = String::new();
    for (k, count) in [(1, 19), (2, 18), (3, 18)] {
        let o = sweep_ok(&d, &[&bundled(), "--shard", &format!("{k}/3")]);
        assert_eq!(summary(&o), [count, 0, count, 0]);
        let text = stdout(&o);
        let lines = parse_lines(&text);
        assert_eq!(lines.len(), count);
        assert!(lines.iter().all(|v| index(v) % 3 == k - 1));
        joined += &text;
    }
    assert_eq!(sorted_lines(&joined), sorted_lines(&stdout(&all)));

    // Sharded files too: the three files together are the full file's lines.
    let full = d.join("full.jsonl");
    ok(&sweep(&d, &[&bundled(), "--out", full.to_str().unwrap()]));
    let mut from_files = String::new();
    for k in 1..=3 {
        let f = d.join(format!("part{k}.jsonl"));
        ok(&sweep(
            &d,
            &[&bundled(), "--shard", &format!("{k}/3"), "--out", f.to_str().unwrap()],
        ));
        from_files += &std::fs::read_to_string(&f).unwrap();
    }
    assert_eq!(
        sorted_lines(&from_files),
        sorted_lines(&std::fs::read_to_string(&full).unwrap())
    );
    cleanup(&d);
}

/// A killed sweep resumes: lines in FILE.jsonl and FILE.jsonl.partial are kept, a torn last
/// line and a line from another sweep are ignored, only the missing designs run, and the final
/// file equals a fresh run byte for byte.
#[test]
fn resume_after_interruption_runs_only_missing_designs() {
    let d = tempdir("resume");
    let fresh = d.join("fresh.jsonl");
    ok(&sweep(&d, &[&bundled(), "--out", fresh.to_str().unwrap()]));
    let fresh_text = std::fs::read_to_string(&fresh).unwrap();
    let lines: Vec<&str> = fresh_text.lines().collect();
    assert_eq!(lines.len(), 55);

    // As if killed: FILE.jsonl holds designs 0..20 (an earlier run), the partial file holds
    // 30..40 in completion order, then a line whose params belong to another sweep, then a
    // torn line.
    let out = d.join("s.jsonl");
    let partial = d.join("s.jsonl.partial");
    std::fs::write(&out, lines[..20].join("\n") + "\n").unwrap();
    let mut part: Vec<&str> = lines[30..40].to_vec();
    part.reverse();
    let stale = lines[45].replace("\"hinge.t\":3", "\"hinge.t\":3.25");
    assert_ne!(stale, lines[45]);
    part.push(&stale);
    let torn = &lines[41][..lines[41].len() / 2];
    std::fs::write(&partial, part.join("\n") + "\n" + torn).unwrap();

    let o = sweep_ok(&d, &[&bundled(), "--out", out.to_str().unwrap()]);
    assert_eq!(summary(&o), [55, 30, 25, 0]);
    assert!(stderr(&o).contains("ignored 1 earlier lines of other designs and 1 unreadable"));
    assert!(!partial.exists());
    assert_eq!(std::fs::read_to_string(&out).unwrap(), fresh_text);

    // Running again finds everything done and leaves the file as it is.
    let again = sweep_ok(&d, &[&bundled(), "--out", out.to_str().unwrap()]);
    assert_eq!(summary(&again), [55, 55, 0, 0]);
    assert_eq!(std::fs::read_to_string(&out).unwrap(), fresh_text);

    // Only a partial file (killed before the first finish): resumes from it alone.
    std::fs::remove_file(&out).unwrap();
    std::fs::write(&partial, lines[50..].join("\n") + "\n").unwrap();
    let o = sweep_ok(&d, &[&bundled(), "--out", out.to_str().unwrap()]);
    assert_eq!(summary(&o), [55, 5, 50, 0]);
    assert_eq!(std::fs::read_to_string(&out).unwrap(), fresh_text);
    cleanup(&d);
}

const T_UP_TO_12: &str = r#"{"analysis": "sweep",
 "base": {"analysis": "hinge", "material": "Al7075",
          "hinge": {"type": "circular_notch", "R": 8, "t": 2, "w": 10, "h": 10, "blank_length": 20}},
 "vary": {"hinge.t": {"from": 2, "to": 12, "steps": 6}, "hinge.R": [4, 8]}}"#;

/// Runs [`T_UP_TO_12`] in a fresh temp dir `name` with `FLAG FILE` (`--out` or `--csv`), asserting
/// exit 1 (four designs fail); the dir, the path of FILE and the run.
fn sweep_t_up_to_12(name: &str, flag: &str, file: &str) -> (std::path::PathBuf, std::path::PathBuf, Output) {
    let d = tempdir(name);
    let case = write(&d, "sweep.json", T_UP_TO_12);
    let path = d.join(file);
    let o = sweep(&d, &[case.to_str().unwrap(), flag, path.to_str().unwrap()]);
    assert_eq!(o.status.code(), Some(1), "stderr: {}", stderr(&o));
    (d, path, o)
}

/// t ≥ h = 10 is an error row naming `hinge.t`; the other designs finish, and the exit code
/// is 1 with the count of failed designs on stderr.
#[test]
fn design_with_t_not_below_h_is_an_error_row_and_the_rest_finish() {
    let (d, out, o) = sweep_t_up_to_12("errors", "--out", "s.jsonl");
    assert!(stderr(&o).contains("4 of 12 designs failed"), "{}", stderr(&o));
    // t = 2, 4, 6, 8, 10, 12 × R = 4, 8: the last two t values (4 designs) fail.
    assert_eq!(summary(&o), [12, 0, 12, 4]);
    let lines = parse_lines(&std::fs::read_to_string(&out).unwrap());
    assert_eq!(lines.len(), 12);
    for v in &lines {
        let t = v["params"]["hinge.t"].as_f64().unwrap();
        if t >= 10.0 {
            let e = v["error"]
                .as_str()
                .unwrap_or_else(|| panic!("t = {t} should fail: {v}"));
            assert!(e.starts_with("hinge.t: value "), "{e}");
            assert!(e.contains(&format!("value {t}")), "{e}");
            assert!(v.get("result").is_none());
        } else {
            assert!(v.get("error").is_none(), "{v}");
            assert!(v["result"]["k_bend"].as_f64().unwrap() > 0.0);
        }
    }
    // t = 2, R = 8 is index 1 and matches the bundled single-hinge case.
    let direct: Value = serde_json::from_str(&stdout(&run(&["run", "cases/ruiz2019_hinge_revolute.json"]))).unwrap();
    assert!(
        rel(
            lines[1]["result"]["k_bend"].as_f64().unwrap(),
            direct["k_bend"].as_f64().unwrap()
        ) < 1e-9
    );
    cleanup(&d);
}

/// CSV: header `index, varied paths, flattened result leaves…, error`, one row per design;
/// numeric columns carry their unit (`name [unit]`, see tests/sweep_csv_units.rs).
#[test]
fn csv_has_a_header_and_one_row_per_design() {
    // Four designs fail (t ≥ h): exit 1, the CSV is still written.
    let (d, csv, o) = sweep_t_up_to_12("csv", "--csv", "s.csv");
    let jsonl = parse_lines(&stdout(&o));
    let text = std::fs::read_to_string(&csv).unwrap();
    let rows: Vec<&str> = text.lines().collect();
    assert_eq!(rows.len(), 1 + 12);
    let header: Vec<&str> = rows[0].split(',').collect();
    assert_eq!(
        header[..4],
        ["index", "hinge.t [mm]", "hinge.R [mm]", "k_bend [N*mm/rad]"]
    );
    assert_eq!(*header.last().unwrap(), "error");
    assert!(header.contains(&"compliance.5.5 [rad/(N*mm)]"));
    assert!(header.contains(&"closed_form.wu_zhou [N*mm/rad]"));
    assert!(!header.iter().any(|h| h.starts_with("model")), "notes are not columns");
    let col = |name: &str| header.iter().position(|h| h.split(" [").next() == Some(name)).unwrap();
    for (i, row) in rows[1..].iter().enumerate() {
        let cells: Vec<&str> = row.split(',').collect();
        assert_eq!(cells.len(), header.len(), "{row}");
        assert_eq!(cells[0], i.to_string());
        let v = jsonl.iter().find(|v| index(v) == i).unwrap();
        assert_eq!(
            cells[1].parse::<f64>().unwrap(),
            v["params"]["hinge.t"].as_f64().unwrap()
        );
        assert_eq!(
            cells[2].parse::<f64>().unwrap(),
            v["params"]["hinge.R"].as_f64().unwrap()
        );
        if let Some(e) = v.get("error") {
            assert!(cells[col("k_bend")].is_empty());
            assert_eq!(*cells.last().unwrap(), e.as_str().unwrap());
        } else {
            let k: f64 = cells[col("k_bend")].parse().unwrap();
            assert_eq!(k, v["result"]["k_bend"].as_f64().unwrap());
            assert!(cells.last().unwrap().is_empty());
        }
    }
    assert_eq!(rows.iter().filter(|r| r.contains("hinge.t: value")).count(), 4);
    cleanup(&d);
}

/// Bad `--shard` values exit 2 with a message, before anything runs.
#[test]
fn bad_shard_values_exit_2() {
    let d = tempdir("badshard");
    for (shard, needle) in [
        ("0/3", "K must lie in 1..=3"),
        ("4/3", "K must lie in 1..=3"),
        ("1/0", "N must be at least 1"),
        ("3", "K/N"),
        ("a/3", "K must be a whole number"),
        ("1/-2", "N must be a whole number"),
    ] {
        let o = sweep(&d, &[&bundled(), "--shard", shard]);
        assert_eq!(o.status.code(), Some(2), "--shard {shard}: {}", stderr(&o));
        let err = stderr(&o);
        assert!(
            err.contains(&format!("--shard `{shard}`")) && err.contains(needle),
            "{err}"
        );
        assert!(stdout(&o).is_empty());
    }
    cleanup(&d);
}

/// A sweep file that is itself wrong exits 2 naming the JSON path; so does a non-sweep case.
#[test]
fn bad_sweep_files_exit_2_naming_the_path() {
    let d = tempdir("badfile");
    let base = r#""base": {"analysis": "hinge", "material": "Al7075",
        "hinge": {"type": "circular_notch", "R": 8, "t": 2, "w": 10, "h": 10, "blank_length": 20}}"#;
    for (name, vary, needle) in [
        ("path", r#"{"hinge.x.y": [1, 2]}"#, "`vary.hinge.x.y`"),
        ("empty list", r#"{"hinge.t": []}"#, "`vary.hinge.t`"),
        (
            "zero steps",
            r#"{"hinge.t": {"from": 1, "to": 2, "steps": 0}}"#,
            "`vary.hinge.t.steps`",
        ),
        ("nothing", r#"{}"#, "`vary`"),
    ] {
        let case = write(
            &d,
            "sweep.json",
            &format!("{{\"analysis\": \"sweep\", {base}, \"vary\": {vary}}}"),
        );
        let o = sweep(&d, &[case.to_str().unwrap()]);
        assert_eq!(o.status.code(), Some(2), "{name}: {}", stderr(&o));
        assert!(stderr(&o).contains(needle), "{name}: {}", stderr(&o));
        assert!(stdout(&o).is_empty());
    }
    let o = sweep(
        &d,
        &[root().join("cases/ruiz2019_hinge_revolute.json").to_str().unwrap()],
    );
    assert_eq!(o.status.code(), Some(2));
    assert!(stderr(&o).contains("`analysis`"), "{}", stderr(&o));
    let o = sweep(&d, &[d.join("missing.json").to_str().unwrap()]);
    assert_eq!(o.status.code(), Some(2));
    cleanup(&d);
}

/// `mesh` paths in the base resolve beside the sweep file, not the working folder; results are
/// linear in the varied tip load.
#[test]
fn mesh_paths_resolve_beside_the_sweep_file() {
    let d = tempdir("mesh");
    std::fs::create_dir_all(d.join("case/meshes")).unwrap();
    std::fs::create_dir_all(d.join("elsewhere")).unwrap();
    std::fs::copy(
        root().join("meshes/cantilever.json"),
        d.join("case/meshes/cantilever.json"),
    )
    .unwrap();
    let case = write(
        &d.join("case"),
        "sweep.json",
        r#"{"analysis": "sweep",
 "base": {"analysis": "static", "mesh": "meshes/cantilever.json",
          "load_cases": [{"name": "tip", "forces": [{"node": 10, "F": [0, 0, -10, 0, 0, 0]}]}]},
 "vary": {"load_cases.0.forces.0.F.2": [-10, -20, -30]}}"#,
    );
    let o = sweep_ok(&d.join("elsewhere"), &[case.to_str().unwrap()]);
    let mut lines = parse_lines(&stdout(&o));
    lines.sort_by_key(index);
    assert_eq!(lines.len(), 3);
    let uz: Vec<f64> = lines
        .iter()
        .map(|v| v["result"]["load_cases"][0]["displacements"]["10"][2].as_f64().unwrap())
        .collect();
    assert!(uz[0] < 0.0);
    assert!(
        rel(uz[1], 2.0 * uz[0]) < 1e-9 && rel(uz[2], 3.0 * uz[0]) < 1e-9,
        "{uz:?}"
    );
    // Equal to `flexfem run` of the first design (the mesh's own tip_Fz case is the same load).
    let direct = run_case_text(
        "mesh-direct",
        &format!(
            r#"{{"analysis": "static", "mesh": "{}",
                 "load_cases": [{{"name": "tip", "forces": [{{"node": 10, "F": [0, 0, -10, 0, 0, 0]}}]}}]}}"#,
            root().join("meshes/cantilever.json").display()
        ),
    );
    ok(&direct);
    let direct: Value = serde_json::from_str(&stdout(&direct)).unwrap();
    let uz_run = direct["load_cases"][0]["displacements"][10][2].as_f64().unwrap();
    assert!(rel(uz[0], uz_run) < 1e-12);
    cleanup(&d);
    cleanup(&std::env::temp_dir().join(format!("flexfem-test-{}-mesh-direct", std::process::id())));
}

/// The real thing: kill a running sweep (SIGKILL) once its partial file holds some lines, then
/// re-run: the finished designs are not run again and the final file has every design once.
#[test]
fn killed_sweep_resumes_from_its_partial_file() {
    let d = tempdir("kill");
    let case = write(
        &d,
        "sweep.json",
        r#"{"analysis": "sweep",
 "base": {"analysis": "hinge", "material": "Al7075",
          "hinge": {"type": "circular_notch", "R": 8, "t": 2, "w": 10, "h": 10, "blank_length": 20}},
 "vary": {"hinge.t": {"from": 1, "to": 3, "steps": 50}, "hinge.R": {"from": 3, "to": 12, "steps": 100}}}"#,
    );
    let out = d.join("s.jsonl");
    let partial = d.join("s.jsonl.partial");
    let mut child = std::process::Command::new(bin())
        .args(["sweep", case.to_str().unwrap(), "--out", out.to_str().unwrap()])
        .stderr(std::process::Stdio::null())
        .spawn()
        .unwrap();
    let started = std::time::Instant::now();
    loop {
        let n = std::fs::read(&partial).map_or(0, |b| b.iter().filter(|&&c| c == b'\n').count());
        if n >= 200 || started.elapsed().as_secs() > 60 {
            break;
        }
        std::thread::sleep(std::time::Duration::from_millis(1));
    }
    child.kill().unwrap();
    child.wait().unwrap();
    assert!(!out.exists(), "the sweep finished before it could be killed");
    let before = std::fs::read_to_string(&partial).unwrap();
    let complete = before
        .lines()
        .filter(|l| serde_json::from_str::<Value>(l).is_ok())
        .count();
    assert!(complete >= 200, "{complete}");

    let o = sweep_ok(&d, &[case.to_str().unwrap(), "--out", out.to_str().unwrap()]);
    assert_eq!(summary(&o), [5000, complete, 5000 - complete, 0]);
    let lines = parse_lines(&std::fs::read_to_string(&out).unwrap());
    assert_eq!(
        lines.iter().map(index).collect::<Vec<_>>(),
        (0..5000).collect::<Vec<_>>()
    );
    assert!(!partial.exists());
    cleanup(&d);
}
