//! A sweep into a new `--out` file keeps its lines in memory and writes the output from them;
//! a resumed one reads the output back from disk. Both must write the same bytes: the JSON lines,
//! the stage table and plot beside them, the `--csv` table and the notes sidecar (compared as
//! JSON: its entries are in completion order).

mod common;
use common::*;
use serde_json::Value;
use std::fs;
use std::path::Path;

fn files(dir: &Path) -> Vec<String> {
    let mut v: Vec<String> = fs::read_dir(dir)
        .unwrap()
        .map(|e| e.unwrap().file_name().to_string_lossy().into_owned())
        .collect();
    v.sort();
    v
}

#[test]
fn fresh_and_resumed_stage_sweeps_write_the_same_files() {
    let case = root().join("cases/ruiz2019_stage_sweep.json");
    let case = case.to_str().unwrap();
    let fresh = tempdir("fresh-out");
    let o = sweep(&fresh, &[case, "--out", "s.jsonl", "--csv", "t.csv"]);
    assert_eq!(o.status.code(), Some(0), "{}", stderr(&o));
    assert_eq!(summary(&o), [256, 0, 256, 0]);

    // The first 100 lines as an interrupted run's partial file: the rest runs, and the output
    // is read back from the file.
    let text = fs::read_to_string(fresh.join("s.jsonl")).unwrap();
    let head: String = text.lines().take(100).map(|l| format!("{l}\n")).collect();
    let resumed = tempdir("resumed-out");
    fs::write(resumed.join("s.jsonl.partial"), head).unwrap();
    let o = sweep(&resumed, &[case, "--out", "s.jsonl", "--csv", "t.csv"]);
    assert_eq!(o.status.code(), Some(0), "{}", stderr(&o));
    assert_eq!(summary(&o), [256, 100, 156, 0]);

    let names = files(&fresh);
    assert_eq!(names, files(&resumed));
    assert_eq!(names, ["s.jsonl", "s.jsonl.notes.json", "s.svg", "t.csv"]);
    for name in &names {
        let (a, b) = (
            fs::read(fresh.join(name)).unwrap(),
            fs::read(resumed.join(name)).unwrap(),
        );
        if name.ends_with(".notes.json") {
            let parse = |t: &[u8]| serde_json::from_slice::<Value>(t).unwrap();
            assert_eq!(parse(&a), parse(&b), "{name}");
        } else {
            assert!(a == b, "{name} differs between the fresh and the resumed sweep");
        }
    }
}
