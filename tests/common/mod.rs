//! Helpers shared by the integration tests: run the real binary in a temp dir.
#![allow(dead_code)]

use std::path::{Path, PathBuf};
use std::process::{Command, Output};

pub mod fixtures;
pub mod materials;
pub mod meshes;
pub mod nonlinear;
pub mod rust_source;

/// Path of the built `flexfem` binary.
pub fn bin() -> &'static str {
    env!("CARGO_BIN_EXE_flexfem")
}

/// The crate root (bundled cases and meshes live here).
pub fn root() -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR"))
}

/// A fresh temporary directory unique to `name`.
pub fn tempdir(name: &str) -> PathBuf {
    let d = std::env::temp_dir().join(format!("flexfem-test-{}-{name}", std::process::id()));
    let _ = std::fs::remove_dir_all(&d);
    std::fs::create_dir_all(&d).unwrap();
    d
}

/// Runs `flexfem ARGS` in `dir`.
pub fn run_in(dir: &Path, args: &[&str]) -> Output {
    Command::new(bin()).args(args).current_dir(dir).output().unwrap()
}

/// Runs `flexfem ARGS` in `dir` and asserts exit 0.
pub fn run_ok_in(dir: &Path, args: &[&str]) -> Output {
    let o = run_in(dir, args);
    assert_eq!(o.status.code(), Some(0), "{}", stderr(&o));
    o
}

/// Runs `flexfem ARGS` in the crate root.
pub fn run(args: &[&str]) -> Output {
    run_in(&root(), args)
}

/// Runs `flexfem run CASE --out DIR` (DIR a fresh temp dir named `name`), asserts success and
/// returns DIR with its parsed `result.json`.
pub fn run_out(case: &str, name: &str) -> (PathBuf, serde_json::Value) {
    let out = tempdir(name).join("out");
    let o = run(&["run", case, "--out", out.to_str().unwrap()]);
    assert!(o.status.success(), "{}", stderr(&o));
    let r = serde_json::from_slice(&std::fs::read(out.join("result.json")).unwrap()).unwrap();
    (out, r)
}

/// Writes `text` as a case file in a temp dir and runs `flexfem run` on it.
pub fn run_case_text(name: &str, text: &str) -> Output {
    let d = tempdir(name);
    let p = d.join("case.json");
    std::fs::write(&p, text).unwrap();
    run_in(&d, &["run", p.to_str().unwrap()])
}

/// stdout as text.
pub fn stdout(o: &Output) -> String {
    String::from_utf8_lossy(&o.stdout).into_owned()
}

/// stderr as text.
pub fn stderr(o: &Output) -> String {
    String::from_utf8_lossy(&o.stderr).into_owned()
}

/// The `N designs, M already done, K run, F failed` numbers of the stderr summary.
pub fn summary(o: &Output) -> [usize; 4] {
    let err = stderr(o);
    let line = err
        .lines()
        .find(|l| l.starts_with("sweep: "))
        .unwrap_or_else(|| panic!("no summary in stderr: {err}"));
    let num = |marker: &str| -> usize {
        let end = line
            .find(marker)
            .unwrap_or_else(|| panic!("`{marker}` missing in {line}"));
        let head = &line[..end];
        let start = head.rfind(|c: char| !c.is_ascii_digit()).map_or(0, |p| p + 1);
        head[start..].parse().unwrap()
    };
    [num(" designs"), num(" already done"), num(" run"), num(" failed")]
}

/// Runs `flexfem sweep ARGS` in `dir`.
pub fn sweep(dir: &Path, args: &[&str]) -> Output {
    let mut all = vec!["sweep"];
    all.extend_from_slice(args);
    run_in(dir, &all)
}

/// Writes `text` to `dir/name`; the path.
pub fn write(dir: &Path, name: &str, text: &str) -> PathBuf {
    let p = dir.join(name);
    std::fs::write(&p, text).unwrap();
    p
}

/// Removes a passing test's temp dir (a failing test leaves it for inspection).
pub fn cleanup(d: &Path) {
    let _ = std::fs::remove_dir_all(d);
}

/// The exit code.
pub fn code(o: &Output) -> Option<i32> {
    o.status.code()
}

/// Each line of `text` as JSON (a sweep's JSON-lines output).
pub fn parse_lines(text: &str) -> Vec<serde_json::Value> {
    text.lines()
        .map(|l| serde_json::from_str(l).unwrap_or_else(|e| panic!("not a JSON line ({e}): {l}")))
        .collect()
}

/// Asserts that the run exited with `exit` and a stderr naming each of `needles`; stderr.
pub fn exits(o: &Output, exit: i32, needles: &[&str]) -> String {
    let err = stderr(o);
    assert_eq!(code(o), Some(exit), "{err}");
    for n in needles {
        assert!(err.contains(n), "`{n}` missing in: {err}");
    }
    err
}

/// Asserts that the run was refused as a bad case or command line (exit 2) with a message
/// naming each of `needles`; the message.
pub fn exits_2(o: &Output, needles: &[&str]) -> String {
    exits(o, 2, needles)
}
