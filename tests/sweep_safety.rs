//! `flexfem sweep` must never lose or silently reuse results: resume after a base-case change,
//! error rows retried, two shards writing one `--out`, exit 1 on failed designs, design-count
//! overflow and huge ranges refused before allocating, and `check` resolving the designs —
//! all through the real binary.

mod common;
use common::*;
use serde_json::Value;
use std::path::{Path, PathBuf};
use std::process::{Command, Output, Stdio};

const HINGE: &str = r#"{"type": "circular_notch", "R": 8, "t": 2, "w": 10, "h": 10, "blank_length": 20}"#;

fn sweep_case(material: &str, hinge: &str, vary: &str) -> String {
    format!(
        r#"{{"analysis": "sweep",
 "base": {{"analysis": "hinge", "material": "{material}", "hinge": {hinge}}},
 "vary": {vary}}}"#
    )
}

/// A fresh directory `name` holding `s.json`, a sweep of the Al7075 circular-notch `HINGE` over
/// `vary`; returns it, the case file and the `--out` path `s.jsonl` in it.
fn al7075_sweep(name: &str, vary: &str) -> (PathBuf, PathBuf, PathBuf) {
    let d = tempdir(name);
    let case = write(&d, "s.json", &sweep_case("Al7075", HINGE, vary));
    let out = d.join("s.jsonl");
    (d, case, out)
}

/// Runs `flexfem sweep CASE --out OUT` in `dir`.
fn sweep_to(dir: &Path, case: &Path, out: &Path) -> Output {
    sweep(dir, &[case.to_str().unwrap(), "--out", out.to_str().unwrap()])
}

/// Runs the sweep afresh into `fresh` (exit 0) and asserts that `out` holds the very same text.
fn assert_same_as_fresh_run(dir: &Path, case: &Path, out: &Path, fresh: &Path) {
    let f = sweep_to(dir, case, fresh);
    assert_eq!(code(&f), Some(0));
    assert_eq!(
        std::fs::read_to_string(out).unwrap(),
        std::fs::read_to_string(fresh).unwrap()
    );
}

/// `flexfem sweep CASE --out OUT --shard SHARD` in `dir`.
fn shard_to(dir: &Path, case: &Path, out: &Path, shard: &str) -> Output {
    sweep(
        dir,
        &[case.to_str().unwrap(), "--out", out.to_str().unwrap(), "--shard", shard],
    )
}

fn lines(path: &Path) -> Vec<Value> {
    parse_lines(&std::fs::read_to_string(path).unwrap())
}

/// Resume after the base case changed: every finished line is stale (its `design_hash` no
/// longer matches) and is rerun, so the file ends equal to a fresh run of the new case; an
/// untouched case resumes with everything done. Steel (E = 210 GPa) vs Al7075 (E = 71.7 GPa):
/// the bending stiffness of the same hinge scales with E, so stale results would be off by
/// 2.9× — the check below compares k_bend with a fresh run to 1e-12.
#[test]
fn resume_after_a_base_case_change_reruns_stale_lines() {
    let vary = r#"{"hinge.t": [1, 2, 3], "hinge.R": [4, 8]}"#;
    let (d, case, out) = al7075_sweep("stale", vary);
    let first = sweep_to(&d, &case, &out);
    assert_eq!(code(&first), Some(0), "{}", stderr(&first));
    assert_eq!(summary(&first), [6, 0, 6, 0]);
    let al = lines(&out);

    // Unchanged: nothing to run.
    let again = sweep_to(&d, &case, &out);
    assert_eq!(summary(&again), [6, 6, 0, 0]);

    // Another base material, same varied values: all six lines are stale.
    write(&d, "s.json", &sweep_case("steel", HINGE, vary));
    let o = sweep_to(&d, &case, &out);
    assert_eq!(code(&o), Some(0), "{}", stderr(&o));
    assert_eq!(summary(&o), [6, 0, 6, 0]);
    assert!(
        stderr(&o).contains("reran 6 designs whose earlier lines were stale"),
        "{}",
        stderr(&o)
    );
    let steel = lines(&out);
    let fresh_dir = d.join("fresh");
    std::fs::create_dir_all(&fresh_dir).unwrap();
    assert_same_as_fresh_run(&d, &case, &out, &fresh_dir.join("f.jsonl"));
    assert_eq!(al.len(), steel.len());
    for (a, s) in al.iter().zip(&steel) {
        assert_eq!(a["params"], s["params"]);
        assert_ne!(a["design_hash"], s["design_hash"]);
        let (ka, ks) = (
            a["result"]["k_bend"].as_f64().unwrap(),
            s["result"]["k_bend"].as_f64().unwrap(),
        );
        assert!(ks > 2.0 * ka, "steel {ks} vs Al7075 {ka}");
    }

    // A base field outside the varied paths (the blank width w) makes every line stale again.
    let wider = HINGE.replace("\"w\": 10", "\"w\": 12");
    write(&d, "s.json", &sweep_case("steel", &wider, vary));
    let o = sweep_to(&d, &case, &out);
    assert_eq!(summary(&o), [6, 0, 6, 0]);
    cleanup(&d);
}

/// A mesh file is part of the resolved design: editing it makes the lines stale.
#[test]
fn resume_after_a_mesh_file_change_reruns_stale_lines() {
    let d = tempdir("stale-mesh");
    let mesh = std::fs::read_to_string(root().join("meshes/cantilever.json")).unwrap();
    write(&d, "m.json", &mesh);
    let case = write(
        &d,
        "s.json",
        r#"{"analysis": "sweep",
 "base": {"analysis": "static", "mesh": "m.json",
          "load_cases": [{"name": "tip", "forces": [{"node": 10, "F": [0, 0, -10, 0, 0, 0]}]}]},
 "vary": {"load_cases.0.forces.0.F.2": [-10, -20]}}"#,
    );
    let out = d.join("s.jsonl");
    let o = sweep_to(&d, &case, &out);
    assert_eq!(code(&o), Some(0), "{}", stderr(&o));
    let o = sweep_to(&d, &case, &out);
    assert_eq!(summary(&o), [2, 2, 0, 0]);
    // Same mesh, one more space: bytes differ, so the lines are stale.
    write(&d, "m.json", &format!("{mesh} "));
    let o = sweep_to(&d, &case, &out);
    assert_eq!(summary(&o), [2, 0, 2, 0]);
    cleanup(&d);
}

/// Asserts a sweep's exit code, its summary numbers and phrases of its stderr.
fn expect(o: &Output, exit: i32, summary_is: [usize; 4], needles: &[&str]) {
    exits(o, exit, needles);
    assert_eq!(summary(o), summary_is);
}

/// t ≥ h fails (4 of 12 designs): exit 1 with the count; a resume retries the error rows
/// (they fail again: still exit 1), `--keep-errors` keeps them.
#[test]
fn failed_designs_exit_1_and_error_rows_are_retried_on_resume() {
    let (d, case, out) = al7075_sweep(
        "retry",
        r#"{"hinge.t": {"from": 2, "to": 12, "steps": 6}, "hinge.R": [4, 8]}"#,
    );
    expect(
        &sweep_to(&d, &case, &out),
        1,
        [12, 0, 12, 4],
        &["error: 4 of 12 designs failed"],
    );

    expect(
        &sweep_to(&d, &case, &out),
        1,
        [12, 8, 4, 4],
        &["retried 4 earlier error rows"],
    );
    assert_eq!(lines(&out).len(), 12);

    // The output still holds failed designs: exit 1.
    let args = [case.to_str().unwrap(), "--out", out.to_str().unwrap(), "--keep-errors"];
    expect(
        &sweep(&d, &args),
        1,
        [12, 12, 0, 0],
        &["kept 4 earlier error rows", "4 of 12 designs failed"],
    );

    // Every design failing on stdout: exit 1 as well.
    let all_bad = write(&d, "bad.json", &sweep_case("Al7075", HINGE, r#"{"hinge.t": [10, 11]}"#));
    expect(&sweep(&d, &[all_bad.to_str().unwrap()]), 1, [2, 0, 2, 2], &[]);
    cleanup(&d);
}

/// Two shards started together on one `--out`: either both finish (one after the other,
/// thanks to the lock) or one is refused naming the lock; after re-running any refused shard
/// the file holds every design exactly once and equal to an unsharded run.
#[test]
fn concurrent_shards_to_one_out_lose_no_designs() {
    let (d, case, out) = al7075_sweep(
        "concurrent",
        r#"{"hinge.t": {"from": 1, "to": 3, "steps": 40}, "hinge.R": {"from": 3, "to": 12, "steps": 50}}"#,
    );
    let spawn = |k: usize| {
        Command::new(bin())
            .args([
                "sweep",
                case.to_str().unwrap(),
                "--out",
                out.to_str().unwrap(),
                "--shard",
                &format!("{k}/2"),
            ])
            .current_dir(&d)
            .stdout(Stdio::null())
            .stderr(Stdio::piped())
            .spawn()
            .unwrap()
    };
    let children = [spawn(1), spawn(2)];
    let results: Vec<Output> = children.into_iter().map(|c| c.wait_with_output().unwrap()).collect();
    for (k, o) in results.iter().enumerate() {
        match code(o) {
            Some(0) => {}
            Some(1) => {
                let err = stderr(o);
                assert!(
                    err.contains("is locked by another flexfem sweep"),
                    "shard {}: {err}",
                    k + 1
                );
                assert!(err.contains("s.jsonl.lock"), "{err}");
                let again = shard_to(&d, &case, &out, &format!("{}/2", k + 1));
                assert_eq!(code(&again), Some(0), "{}", stderr(&again));
            }
            other => panic!("shard {}: exit {other:?}: {}", k + 1, stderr(o)),
        }
    }
    let got = lines(&out);
    let idx: Vec<usize> = got.iter().map(|v| v["index"].as_u64().unwrap() as usize).collect();
    assert_eq!(idx, (0..2000).collect::<Vec<_>>());
    assert!(!d.join("s.jsonl.lock").exists());
    assert!(!d.join("s.jsonl.partial").exists());
    assert_same_as_fresh_run(&d, &case, &out, &d.join("whole.jsonl"));
    cleanup(&d);
}

/// Shards run one after the other into the same file accumulate there (the second does not
/// drop the first one's lines).
#[test]
fn sequential_shards_to_one_out_accumulate() {
    let (d, case, out) = al7075_sweep("seqshards", r#"{"hinge.t": [1, 2, 3], "hinge.R": [4, 8, 12]}"#);
    for k in 1..=3 {
        let o = shard_to(&d, &case, &out, &format!("{k}/3"));
        assert_eq!(code(&o), Some(0), "{}", stderr(&o));
        assert_eq!(summary(&o), [3, 0, 3, 0]);
    }
    let idx: Vec<u64> = lines(&out).iter().map(|v| v["index"].as_u64().unwrap()).collect();
    assert_eq!(idx, (0..9).collect::<Vec<_>>());
    cleanup(&d);
}

/// A lock held by a live process refuses the sweep (exit 1, output untouched); a lock left by
/// a process that no longer exists on this host is taken over.
#[test]
fn held_lock_is_refused_and_stale_lock_taken_over() {
    let (d, case, out) = al7075_sweep("lock", r#"{"hinge.t": [1, 2]}"#);
    let lock = d.join("s.jsonl.lock");
    let host = std::fs::read_to_string("/proc/sys/kernel/hostname").unwrap();
    let host = host.trim();
    // This test process is alive: its lock is held.
    std::fs::write(&lock, format!("pid={} host={host}\n", std::process::id())).unwrap();
    let o = sweep_to(&d, &case, &out);
    assert_eq!(code(&o), Some(1), "{}", stderr(&o));
    assert!(
        stderr(&o).contains("is locked by another flexfem sweep"),
        "{}",
        stderr(&o)
    );
    assert!(!out.exists());
    assert!(lock.exists(), "someone else's lock is left alone");
    // A finished (reaped) child's pid is gone: stale.
    let mut child = Command::new("true").spawn().unwrap();
    let dead = child.id();
    child.wait().unwrap();
    std::fs::write(&lock, format!("pid={dead} host={host}\n")).unwrap();
    let o = sweep_to(&d, &case, &out);
    assert_eq!(code(&o), Some(0), "{}", stderr(&o));
    assert!(stderr(&o).contains("removed the stale lock"), "{}", stderr(&o));
    assert_eq!(lines(&out).len(), 2);
    assert!(!lock.exists());
    cleanup(&d);
}

/// 64 axes of two values are 2⁶⁴ designs: `check` and `sweep` refuse them naming `vary`
/// (a wrapping product made them 0 designs that passed `check` and ran nothing).
#[test]
fn design_count_overflow_is_refused() {
    let d = tempdir("overflow");
    let hinge: String = {
        let mut m = serde_json::Map::new();
        for k in 0..64 {
            m.insert(format!("x{k}"), Value::from(0));
        }
        Value::Object(m).to_string()
    };
    let vary: String = {
        let mut m = serde_json::Map::new();
        for k in 0..64 {
            m.insert(format!("extra.x{k}"), serde_json::json!([1, 2]));
        }
        Value::Object(m).to_string()
    };
    let text = format!(
        r#"{{"analysis": "sweep", "base": {{"analysis": "hinge", "material": "Al7075", "hinge": {HINGE}, "extra": {hinge}}}, "vary": {vary}}}"#
    );
    let case = write(&d, "s.json", &text);
    for cmd in ["check", "sweep"] {
        let o = run_in(&d, &[cmd, case.to_str().unwrap()]);
        assert_eq!(code(&o), Some(2), "{cmd}: {}", stderr(&o));
        let err = stderr(&o);
        assert!(err.contains("`vary`") && err.contains("more than 2^64"), "{cmd}: {err}");
        assert!(stdout(&o).is_empty());
    }
    cleanup(&d);
}

/// A 100-axis sweep of 10⁶ steps each is a few KB of JSON; the design count (10⁶⁰⁰) is refused
/// before any range is expanded. Run under a 1 GiB address-space limit: expanding first needs
/// 10⁸ JSON values (> 3 GB), which aborts instead of exiting 2.
#[test]
fn huge_ranges_are_counted_before_expanding() {
    let d = tempdir("huge");
    let mut base = serde_json::Map::new();
    let mut vary = serde_json::Map::new();
    for k in 0..100 {
        base.insert(format!("x{k}"), Value::from(0));
        vary.insert(
            format!("extra.x{k}"),
            serde_json::json!({"from": 0, "to": 1, "steps": 1_000_000}),
        );
    }
    let text = format!(
        r#"{{"analysis": "sweep", "base": {{"analysis": "hinge", "material": "Al7075", "hinge": {HINGE}, "extra": {}}}, "vary": {}}}"#,
        Value::Object(base),
        Value::Object(vary)
    );
    assert!(text.len() < 11_000, "{}", text.len());
    let case = write(&d, "s.json", &text);
    for cmd in ["check", "sweep"] {
        let o = Command::new("sh")
            .arg("-c")
            .arg(format!(
                "ulimit -v 1048576 && exec \"{}\" {cmd} \"{}\"",
                bin(),
                case.display()
            ))
            .current_dir(&d)
            .output()
            .unwrap();
        assert_eq!(code(&o), Some(2), "{cmd}: {}", stderr(&o));
        assert!(stderr(&o).contains("`vary`"), "{cmd}: {}", stderr(&o));
    }
    cleanup(&d);
}

/// `check` on a sweep resolves design 0 and, per varied path, its last value: a bad base field
/// is named under `base.`, a varied value out of range under `vary.` (both passed before).
#[test]
fn check_validates_the_base_case_and_each_varied_path() {
    let d = tempdir("check");
    let bad_base = HINGE.replace("\"w\": 10", "\"w\": -10");
    let case = write(&d, "a.json", &sweep_case("Al7075", &bad_base, r#"{"hinge.t": [1, 2]}"#));
    let o = run_in(&d, &["check", case.to_str().unwrap()]);
    exits_2(&o, &["`base.hinge.w`"]);

    // t = 12 ≥ h = 10 only at the range's last value.
    let case = write(
        &d,
        "b.json",
        &sweep_case(
            "Al7075",
            HINGE,
            r#"{"hinge.R": [4, 8], "hinge.t": {"from": 2, "to": 12, "steps": 6}}"#,
        ),
    );
    let o = run_in(&d, &["check", case.to_str().unwrap()]);
    exits_2(&o, &[]);
    let err = stderr(&o);
    assert!(err.contains("`vary.hinge.t`") && err.contains("hinge.t = 12"), "{err}");

    let case = write(
        &d,
        "c.json",
        &sweep_case("unobtainium", HINGE, r#"{"hinge.t": [1, 2]}"#),
    );
    let o = run_in(&d, &["check", case.to_str().unwrap()]);
    exits_2(&o, &["`base.material`"]);

    // A good sweep passes and says how many designs were resolved.
    let case = write(
        &d,
        "ok.json",
        &sweep_case("Al7075", HINGE, r#"{"hinge.R": [4, 8], "hinge.t": [1, 2, 3]}"#),
    );
    let o = run_in(&d, &["check", case.to_str().unwrap()]);
    assert_eq!(code(&o), Some(0), "{}", stderr(&o));
    assert!(stdout(&o).contains("6 designs"), "{}", stdout(&o));
    cleanup(&d);
}
