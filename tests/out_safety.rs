//! What flexfem writes: never through a symbolic link planted at a temporary path, never over
//! the case file or a file that is not its own output (unless `--force`), never two outputs
//! to one path; a closed or full stdout is an error (exit 1), not a panic (exit 101). All
//! through the real binary.

mod common;
use common::*;
use std::fs;
use std::os::unix::fs::symlink;
use std::path::{Path, PathBuf};
use std::process::{Command, Stdio};

const SWEEP: &str = r#"{"analysis": "sweep",
 "base": {"analysis": "hinge", "material": "Al7075",
          "hinge": {"type": "circular_notch", "R": 8, "t": 2, "w": 10, "h": 10, "blank_length": 20}},
 "vary": {"hinge.t": [1, 2, 3]}}"#;

const PRECIOUS: &str = "precious data that is not flexfem output\n";

fn s(p: &Path) -> &str {
    p.to_str().unwrap()
}

/// A fresh temp dir `name` holding the sweep case `s.json`.
fn sweep_dir(name: &str) -> (PathBuf, PathBuf) {
    let d = tempdir(name);
    let case = write(&d, "s.json", SWEEP);
    (d, case)
}

fn line_count(p: &Path) -> usize {
    fs::read_to_string(p).unwrap().lines().count()
}

/// Symbolic links planted at every temporary name the old code used (`FILE.tmp`,
/// `FILE.csv.tmp`, `result.tmp~`) pointing at a victim file: the victim must be untouched and
/// the outputs regular files. Temporary names are now unique and created exclusively.
#[test]
fn symlinked_temporary_paths_do_not_redirect_writes() {
    let (d, case) = sweep_dir("symlink-tmp");
    let victim = write(&d, "victim.txt", PRECIOUS);
    let out = d.join("s.jsonl");
    let csv = d.join("s.csv");
    symlink(&victim, d.join("s.jsonl.tmp")).unwrap();
    symlink(&victim, d.join("s.csv.tmp")).unwrap();
    run_ok_in(&d, &["sweep", s(&case), "--out", s(&out), "--csv", s(&csv)]);
    assert_eq!(fs::read_to_string(&victim).unwrap(), PRECIOUS);
    assert!(fs::symlink_metadata(&out).unwrap().is_file());
    assert_eq!(line_count(&out), 3);
    assert_eq!(line_count(&csv), 4);

    // `run --out DIR` into an earlier output folder with a link planted at `result.tmp~`.
    let hinge = root().join("cases/ruiz2019_hinge_revolute.json");
    let res = d.join("res");
    run_ok_in(&d, &["run", s(&hinge), "--out", s(&res)]);
    symlink(&victim, res.join("result.tmp~")).unwrap();
    run_ok_in(&d, &["run", s(&hinge), "--out", s(&res)]);
    assert_eq!(fs::read_to_string(&victim).unwrap(), PRECIOUS);
    assert!(fs::symlink_metadata(res.join("result.json")).unwrap().is_file());
    // No temporary file is left behind (only the planted link, untouched).
    let left: Vec<String> = fs::read_dir(&res)
        .unwrap()
        .map(|e| e.unwrap().file_name().to_string_lossy().into_owned())
        .filter(|n| n.ends_with(".tmp"))
        .collect();
    assert!(left.is_empty(), "{left:?}");
    cleanup(&d);
}

/// The partial file is appended to, so it cannot be made unique: a link planted there is
/// refused (exit 1, naming it) and the victim is untouched.
#[test]
fn symlinked_partial_file_is_refused() {
    let (d, case) = sweep_dir("symlink-partial");
    let victim = write(&d, "victim.txt", PRECIOUS);
    let out = d.join("s.jsonl");
    symlink(&victim, d.join("s.jsonl.partial")).unwrap();
    let o = run_in(&d, &["sweep", s(&case), "--out", s(&out)]);
    assert_eq!(code(&o), Some(1), "{}", stderr(&o));
    assert!(
        stderr(&o).contains("s.jsonl.partial is a symbolic link"),
        "{}",
        stderr(&o)
    );
    assert_eq!(fs::read_to_string(&victim).unwrap(), PRECIOUS);
    assert!(!out.exists());
    // A dangling link (a victim to be created) is refused too.
    fs::remove_file(d.join("s.jsonl.partial")).unwrap();
    symlink(d.join("new-victim"), d.join("s.jsonl.partial")).unwrap();
    let o = run_in(&d, &["sweep", s(&case), "--out", s(&out)]);
    assert_eq!(code(&o), Some(1), "{}", stderr(&o));
    assert!(!d.join("new-victim").exists());
    cleanup(&d);
}

/// The case file is never overwritten, `--force` or not: `sweep --out CASE`, `--csv CASE`,
/// and `run --out DIR` whose `result.json` is the case.
#[test]
fn the_case_file_is_never_overwritten() {
    let (d, case) = sweep_dir("case-file");
    for args in [
        vec!["sweep", s(&case), "--out", s(&case)],
        vec!["sweep", s(&case), "--out", s(&case), "--force"],
        vec!["sweep", s(&case), "--csv", s(&case), "--force"],
        vec!["sweep", s(&case), "--out", "s.json"],
    ] {
        let o = run_in(&d, &args);
        assert_eq!(code(&o), Some(2), "{args:?}: {}", stderr(&o));
        assert!(stderr(&o).contains("the case file and"), "{args:?}: {}", stderr(&o));
        assert_eq!(fs::read_to_string(&case).unwrap(), SWEEP, "{args:?}");
    }
    let res = d.join("res");
    fs::create_dir_all(&res).unwrap();
    let text = fs::read_to_string(root().join("cases/ruiz2019_hinge_revolute.json")).unwrap();
    let inside = write(&res, "result.json", &text);
    for extra in [None, Some("--force")] {
        let mut args = vec!["run", s(&inside), "--out", s(&res)];
        args.extend(extra);
        let o = run_in(&d, &args);
        exits_2(&o, &["is the case file"]);
        assert_eq!(fs::read_to_string(&inside).unwrap(), text);
    }
    cleanup(&d);
}

/// An existing file that is not flexfem's own output is refused (exit 2) and kept; `--force`
/// replaces it. The same holds for `run --out` into a folder that is neither empty nor a
/// flexfem output folder.
#[test]
fn unrelated_files_are_replaced_only_with_force() {
    let (d, case) = sweep_dir("unrelated");
    let notes = write(&d, "notes.jsonl", PRECIOUS);
    let o = run_in(&d, &["sweep", s(&case), "--out", s(&notes)]);
    exits_2(&o, &["not a flexfem sweep line", "--force"]);
    assert_eq!(fs::read_to_string(&notes).unwrap(), PRECIOUS);
    let table = write(&d, "table.csv", "a,b\n1,2\n");
    let o = run_in(&d, &["sweep", s(&case), "--csv", s(&table)]);
    exits_2(&o, &[]);
    assert_eq!(fs::read_to_string(&table).unwrap(), "a,b\n1,2\n");
    assert!(stdout(&o).is_empty(), "refused before running");

    run_ok_in(&d, &["sweep", s(&case), "--out", s(&notes), "--force"]);
    assert_eq!(line_count(&notes), 3);
    // Now it is flexfem's own output: a re-run needs no --force.
    run_ok_in(&d, &["sweep", s(&case), "--out", s(&notes)]);

    let hinge = root().join("cases/ruiz2019_hinge_revolute.json");
    let docs = d.join("docs");
    fs::create_dir_all(&docs).unwrap();
    let readme = write(&docs, "report.md", PRECIOUS);
    let o = run_in(&d, &["run", s(&hinge), "--out", s(&docs)]);
    exits_2(&o, &["neither empty nor a flexfem output folder"]);
    assert_eq!(fs::read_to_string(&readme).unwrap(), PRECIOUS);
    run_ok_in(&d, &["run", s(&hinge), "--out", s(&docs), "--force"]);
    assert!(docs.join("result.json").is_file());
    // `--out` naming an existing file: refused, file kept.
    let o = run_in(&d, &["run", s(&hinge), "--out", s(&notes)]);
    exits_2(&o, &[]);
    assert_eq!(line_count(&notes), 3);
    cleanup(&d);
}

/// `--out x --csv x` would put the CSV over the JSON lines: refused before running.
#[test]
fn identical_output_paths_are_refused() {
    let (d, case) = sweep_dir("identical");
    let o = run_in(&d, &["sweep", s(&case), "--out", "x.csv", "--csv", "x.csv"]);
    exits_2(&o, &["--out and --csv are the same file"]);
    assert!(!d.join("x.csv").exists());
    // Spelled differently, same file.
    let o = run_in(&d, &["sweep", s(&case), "--out", "x.jsonl", "--csv", "./x.jsonl"]);
    exits_2(&o, &[]);
    cleanup(&d);
}

/// stdout on a full device (`> /dev/full`): exit 1 with a message, not a panic (exit 101).
#[test]
fn full_stdout_is_an_error_with_exit_1() {
    let hinge = root().join("cases/ruiz2019_hinge_revolute.json");
    let sweep = root().join("cases/ruiz2019_hinge_sweep.json");
    for args in [
        vec!["run", s(&hinge)],
        vec!["run", s(&hinge), "--format", "md"],
        vec!["schema"],
        vec!["check", s(&hinge)],
        vec!["sweep", s(&sweep)],
    ] {
        let full = fs::OpenOptions::new().write(true).open("/dev/full").unwrap();
        let o = Command::new(bin())
            .args(&args)
            .stdout(Stdio::from(full))
            .stderr(Stdio::piped())
            .output()
            .unwrap();
        assert_eq!(code(&o), Some(1), "{args:?}: {}", stderr(&o));
        assert!(
            stderr(&o).contains("cannot write to stdout"),
            "{args:?}: {}",
            stderr(&o)
        );
        assert!(!stderr(&o).contains("panicked"), "{}", stderr(&o));
    }
}

/// stdout a pipe whose reader has gone (`flexfem schema | true`): exit 1, not a panic. The
/// reader end is closed before flexfem starts writing (it waits 0.5 s in the shell first).
#[test]
fn closed_stdout_is_an_error_with_exit_1() {
    for cmd in ["schema", "run cases/ruiz2019_hinge_revolute.json"] {
        let mut child = Command::new("sh")
            .arg("-c")
            .arg(format!("sleep 0.5; exec \"{}\" {cmd}", bin()))
            .current_dir(root())
            .stdout(Stdio::piped())
            .stderr(Stdio::piped())
            .spawn()
            .unwrap();
        drop(child.stdout.take());
        let o = child.wait_with_output().unwrap();
        assert_eq!(code(&o), Some(1), "{cmd}: {}", stderr(&o));
        assert!(stderr(&o).contains("cannot write to stdout"), "{cmd}: {}", stderr(&o));
    }
}
