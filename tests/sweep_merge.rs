//! `flexfem merge` and `flexfem sweep --shard-from-env`, through the real binary, on the
//! bundled stage sweep (256 designs): the merge of 4 shards equals the single run line for line,
//! missing designs are reported, lines of another base case are refused, duplicates are
//! dropped when identical and refused when not.

mod common;
use common::*;
use serde_json::Value;
use std::path::{Path, PathBuf};
use std::process::{Command, Output};

const CASE: &str = "cases/ruiz2019_stage_sweep.json";
const DESIGNS: usize = 256;
const SLURM_VARS: [&str; 5] = [
    "SLURM_ARRAY_TASK_ID",
    "SLURM_ARRAY_TASK_COUNT",
    "SLURM_ARRAY_TASK_MIN",
    "SLURM_ARRAY_TASK_MAX",
    "SLURM_ARRAY_TASK_STEP",
];

fn case() -> String {
    root().join(CASE).to_str().unwrap().to_string()
}

/// `flexfem ARGS` in `dir` with exactly the Slurm array variables `env` set.
fn flexfem(dir: &Path, args: &[&str], env: &[(&str, String)]) -> Output {
    let mut c = Command::new(bin());
    c.args(args).current_dir(dir);
    for v in SLURM_VARS {
        c.env_remove(v);
    }
    c.envs(env.iter().map(|(k, v)| (k, v.as_str())));
    c.output().unwrap()
}

fn code(o: &Output) -> Option<i32> {
    o.status.code()
}

fn s(p: &Path) -> &str {
    p.to_str().unwrap()
}

/// The 4 shards of the bundled stage sweep as array tasks 1..4 would write them (task ids
/// and count through the Slurm variables, as `sbatch --array=1-4` sets them), and the single
/// unsharded run; returns (single run file, shard files).
fn shards_and_single(d: &Path) -> (PathBuf, Vec<PathBuf>) {
    let all = d.join("all.jsonl");
    let o = flexfem(d, &["sweep", &case(), "--out", s(&all)], &[]);
    assert_eq!(code(&o), Some(0), "{}", stderr(&o));
    let mut files = Vec::new();
    for k in 1..=4 {
        let f = d.join(format!("shard_{k}.jsonl"));
        let env = [
            ("SLURM_ARRAY_TASK_ID", k.to_string()),
            ("SLURM_ARRAY_TASK_COUNT", "4".to_string()),
            ("SLURM_ARRAY_TASK_MIN", "1".to_string()),
            ("SLURM_ARRAY_TASK_MAX", "4".to_string()),
        ];
        let o = flexfem(d, &["sweep", &case(), "--shard-from-env", "--out", s(&f)], &env);
        assert_eq!(code(&o), Some(0), "{}", stderr(&o));
        assert!(
            stderr(&o).contains(&format!("(shard {k}/4 of {DESIGNS})")),
            "{}",
            stderr(&o)
        );
        files.push(f);
    }
    (all, files)
}

fn merge(d: &Path, out: &Path, shards: &[&Path], extra: &[&str]) -> Output {
    let mut args = vec!["merge", s(out)];
    args.extend(shards.iter().map(|p| s(p)));
    let c = case();
    args.extend(["--case", c.as_str()]);
    args.extend(extra);
    flexfem(d, &args, &[])
}

fn read(p: &Path) -> String {
    std::fs::read_to_string(p).unwrap()
}

fn json(p: &Path) -> Value {
    serde_json::from_str(&read(p)).unwrap()
}

/// Shards run round-robin hold every design once, so their merge is the single run's file
/// byte for byte (same lines, same order by index), and the notes files agree. The design
/// count 256 = 4⁴ is the bundled case's full factorial.
#[test]
fn shards_merged_equal_the_single_run_line_for_line_and_duplicates() {
    let d = tempdir("merge-equal");
    let (all, shards) = shards_and_single(&d);
    let refs: Vec<&Path> = shards.iter().map(PathBuf::as_path).collect();
    let out = d.join("merged.jsonl");
    let o = merge(&d, &out, &refs, &[]);
    assert_eq!(code(&o), Some(0), "{}", stderr(&o));
    let single = read(&all);
    assert_eq!(single.lines().count(), DESIGNS);
    assert_eq!(read(&out), single, "merged file differs from the single run");
    let notes = |p: &Path| json(&with_notes(p));
    assert_eq!(notes(&out), notes(&all));

    // Shard 1 given twice and the single file too: identical duplicates are dropped and counted.
    let out2 = d.join("merged2.jsonl");
    let twice = [refs[0], refs[1], refs[2], refs[3], refs[0], all.as_path()];
    let o = merge(&d, &out2, &twice, &[]);
    assert_eq!(code(&o), Some(0), "{}", stderr(&o));
    assert!(
        stderr(&o).contains(&format!("{} identical duplicate lines", 64 + DESIGNS)),
        "{}",
        stderr(&o)
    );
    assert_eq!(read(&out2), single);

    // A conflicting duplicate (same design, another result) is refused, naming both places.
    let bad = d.join("shard_1_edited.jsonl");
    let text = read(&shards[0]);
    let first = text.lines().next().unwrap();
    let mut v: Value = serde_json::from_str(first).unwrap();
    let old = v["result"]["stiffness_z"].as_f64().unwrap();
    v["result"]["stiffness_z"] = Value::from(old * 1.01);
    std::fs::write(&bad, format!("{v}\n")).unwrap();
    let out3 = d.join("merged3.jsonl");
    let o = merge(&d, &out3, &[refs[0], refs[1], refs[2], refs[3], &bad], &[]);
    assert_eq!(code(&o), Some(2), "{}", stderr(&o));
    let err = stderr(&o);
    assert!(err.contains("design 0 has two different lines"), "{err}");
    assert!(
        err.contains("shard_1.jsonl line 1") && err.contains("shard_1_edited.jsonl line 1"),
        "{err}"
    );
    assert!(!out3.exists(), "nothing is written on a refusal");
    cleanup(&d);
}

fn with_notes(p: &Path) -> PathBuf {
    PathBuf::from(format!("{}.notes.json", p.display()))
}

/// A shard that never ran: its 64 designs are listed as missing (exit 1), nothing is written
/// unless --allow-missing, which writes the 192 that are there (exit still 1).
#[test]
fn missing_designs_are_reported() {
    let d = tempdir("merge-missing");
    let (_, shards) = shards_and_single(&d);
    let three = [shards[0].as_path(), shards[1].as_path(), shards[3].as_path()];
    let out = d.join("merged.jsonl");
    let o = merge(&d, &out, &three, &[]);
    assert_eq!(code(&o), Some(1), "{}", stderr(&o));
    let err = stderr(&o);
    assert!(err.contains("64 of 256 designs missing: 2, 6, 10"), "{err}");
    assert!(err.contains("all of shard 3/4"), "{err}");
    assert!(!out.exists(), "nothing is written without --allow-missing");
    let o = merge(&d, &out, &three, &["--allow-missing"]);
    assert_eq!(code(&o), Some(1), "{}", stderr(&o));
    let lines: Vec<Value> = read(&out).lines().map(|l| serde_json::from_str(l).unwrap()).collect();
    assert_eq!(lines.len(), 192);
    assert!(lines.iter().all(|v| v["index"].as_u64().unwrap() % 4 != 2));
    assert!(lines
        .windows(2)
        .all(|w| w[0]["index"].as_u64() < w[1]["index"].as_u64()));

    // An unfinished shard's .partial file (lines in completion order, not by index) is refused
    // naming the line, rather than held in memory: its shard is rerun instead.
    let partial = d.join("shard_3.jsonl.partial");
    let o = flexfem(
        &d,
        &["sweep", &case(), "--shard", "3/4", "--out", s(&d.join("s3.jsonl"))],
        &[],
    );
    assert_eq!(code(&o), Some(0), "{}", stderr(&o));
    let mut text: Vec<String> = read(&d.join("s3.jsonl")).lines().map(str::to_string).collect();
    text.swap(0, 1);
    std::fs::write(&partial, text.join("\n") + "\n").unwrap();
    let out2 = d.join("merged2.jsonl");
    let o = merge(&d, &out2, &[three[0], three[1], &partial, three[2]], &[]);
    assert_eq!(code(&o), Some(2), "{}", stderr(&o));
    let err = stderr(&o);
    assert!(
        err.contains("shard_3.jsonl.partial line 2 (index 2) follows index 6"),
        "{err}"
    );
    assert!(!out2.exists());
    cleanup(&d);
}

/// Lines written from another base case (same varied values, a different leg width) carry
/// another design_hash: refused naming the file and line, nothing written. Lines of another
/// sweep altogether (the hinge sweep) are refused too.
#[test]
fn lines_from_another_base_case_are_refused() {
    let d = tempdir("merge-stale");
    let (_, shards) = shards_and_single(&d);
    let mut other: Value = serde_json::from_str(&read(&root().join(CASE))).unwrap();
    other["base"]["stage"]["leg"]["w"] = Value::from(11.0);
    let other_case = d.join("other_case.json");
    std::fs::write(&other_case, other.to_string()).unwrap();
    let stale = d.join("shard_3_other.jsonl");
    let o = flexfem(
        &d,
        &["sweep", s(&other_case), "--shard", "3/4", "--out", s(&stale)],
        &[],
    );
    assert_eq!(code(&o), Some(0), "{}", stderr(&o));
    let out = d.join("merged.jsonl");
    let mixed = [shards[0].as_path(), shards[1].as_path(), &stale, shards[3].as_path()];
    let o = merge(&d, &out, &mixed, &[]);
    assert_eq!(code(&o), Some(2), "{}", stderr(&o));
    let err = stderr(&o);
    assert!(
        err.contains("shard_3_other.jsonl line 1 (index 2) has design_hash"),
        "{err}"
    );
    assert!(err.contains("another base case"), "{err}");
    assert!(!out.exists());

    let hinge = d.join("hinge.jsonl");
    let hinge_case = root().join("cases/ruiz2019_hinge_sweep.json");
    let o = flexfem(&d, &["sweep", s(&hinge_case), "--out", s(&hinge)], &[]);
    assert_eq!(code(&o), Some(0), "{}", stderr(&o));
    let o = merge(&d, &out, &[shards[0].as_path(), &hinge], &[]);
    assert_eq!(code(&o), Some(2), "{}", stderr(&o));
    assert!(stderr(&o).contains("hinge.jsonl line 1 (index 0"), "{}", stderr(&o));
    assert!(stderr(&o).contains("not a design of this sweep"), "{}", stderr(&o));
    assert!(!out.exists());
    cleanup(&d);
}

/// --shard-from-env outside an array task, or with ids outside 1..=N, exits 2 naming the
/// variable; --shard-count gives N for a resubmitted single task.
#[test]
fn shard_from_env_errors_and_resubmission() {
    let d = tempdir("merge-env");
    let o = flexfem(&d, &["sweep", &case(), "--shard-from-env"], &[]);
    assert_eq!(code(&o), Some(2), "{}", stderr(&o));
    assert!(stderr(&o).contains("SLURM_ARRAY_TASK_ID is not set"), "{}", stderr(&o));
    let env = [
        ("SLURM_ARRAY_TASK_ID", "5".to_string()),
        ("SLURM_ARRAY_TASK_COUNT", "4".to_string()),
    ];
    let o = flexfem(&d, &["sweep", &case(), "--shard-from-env"], &env);
    assert_eq!(code(&o), Some(2), "{}", stderr(&o));
    assert!(stderr(&o).contains("K must lie in 1..=4"), "{}", stderr(&o));
    // `sbatch --array=3` (a rerun of task 3 alone): Slurm says 1 task from 3 to 3.
    let rerun = [
        ("SLURM_ARRAY_TASK_ID", "3".to_string()),
        ("SLURM_ARRAY_TASK_COUNT", "1".to_string()),
        ("SLURM_ARRAY_TASK_MIN", "3".to_string()),
        ("SLURM_ARRAY_TASK_MAX", "3".to_string()),
    ];
    let o = flexfem(
        &d,
        &["sweep", &case(), "--shard-from-env", "--shard-count", "4"],
        &rerun,
    );
    assert_eq!(code(&o), Some(0), "{}", stderr(&o));
    assert!(stderr(&o).contains("(shard 3/4 of 256)"), "{}", stderr(&o));
    assert_eq!(stdout(&o).lines().count(), 64);
    let o = flexfem(&d, &["sweep", &case(), "--shard", "1/4", "--shard-from-env"], &rerun);
    assert_eq!(
        code(&o),
        Some(2),
        "--shard and --shard-from-env together: {}",
        stderr(&o)
    );
    cleanup(&d);
}
