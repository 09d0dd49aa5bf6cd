//! Golden outputs: the JSON result of every bundled case in `cases/` (except the sweeps, whose
//! rows are checked in `tests/sweep.rs`) must equal the stored `tests/golden/<case>.json` byte
//! for byte. This pins the behaviour of the whole front end (case parsing, analysis dispatch,
//! JSON serialisation) while the code is restructured: a refactor that changes any number, key,
//! order or warning text fails here.
//!
//! The reference is the program's own earlier output (regression, not accuracy): the accuracy
//! of each number is asserted against its published source in the other test files.
//!
//! To regenerate after an intended change of output, run
//! `FLEXFEM_BLESS=1 cargo test --release --test golden_outputs` and review `git diff tests/golden`.
//!
//! The comparison is exact: every bundled case produced byte-identical JSON on repeated runs
//! with 1 and 2 rayon threads when the goldens were generated, so no tolerance is applied.

use std::path::{Path, PathBuf};

/// Sweep cases produce JSON lines through `flexfem sweep`, not one result: not covered here.
const SKIPPED: &[&str] = &[
    "ruiz2019_hinge_sweep.json",
    "ruiz2019_stage_sweep.json",
    "parallelogram_parameters_sweep.json",
    "pantilt_8r_parameters_sweep.json",
];

fn root() -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR"))
}

/// The same text `flexfem run CASE` writes to stdout (and `--out DIR` to `DIR/result.json`):
/// serde_json's pretty layout with rows of numbers kept on one line (`report::json::pretty`).
fn result_text(case: &Path) -> String {
    let parsed = flexfem::analysis::load_resolved(case)
        .unwrap_or_else(|e| panic!("{}: case does not load: {e}", case.display()));
    let mut outcome =
        flexfem::analysis::run(&parsed.case).unwrap_or_else(|e| panic!("{}: analysis fails: {e}", case.display()));
    outcome.echo_parameters(&parsed.parameters);
    format!("{}\n", flexfem::report::json::pretty(&outcome.json))
}

/// The first differing line of two texts, for the failure message.
fn first_difference(want: &str, got: &str) -> String {
    // zip-checked: a failure message; unequal line counts are reported after the loop.
    for (i, (w, g)) in want.lines().zip(got.lines()).enumerate() {
        if w != g {
            return format!("line {}:\n  golden: {w}\n  now:    {g}", i + 1);
        }
    }
    format!(
        "one text is a prefix of the other ({} vs {} lines)",
        want.lines().count(),
        got.lines().count()
    )
}

fn cases() -> Vec<PathBuf> {
    let mut all: Vec<PathBuf> = std::fs::read_dir(root().join("cases"))
        .expect("cases/ exists")
        .map(|e| e.expect("readable cases/ entry").path())
        .filter(|p| p.extension().is_some_and(|x| x == "json"))
        .filter(|p| {
            let name = p.file_name().unwrap().to_string_lossy();
            !SKIPPED.contains(&name.as_ref())
        })
        .collect();
    all.sort();
    all
}

#[test]
fn every_bundled_case_matches_its_golden_output() {
    let bless = std::env::var_os("FLEXFEM_BLESS").is_some_and(|v| v == "1");
    let all = cases();
    assert!(all.len() >= 15, "expected the bundled cases, found {}", all.len());
    let mut failures = Vec::new();
    for case in &all {
        let name = case.file_name().unwrap().to_string_lossy().to_string();
        let golden = root().join("tests/golden").join(&name);
        let got = result_text(case);
        if bless {
            std::fs::write(&golden, &got).expect("golden file writable");
            continue;
        }
        let want = match std::fs::read_to_string(&golden) {
            Ok(t) => t,
            Err(e) => {
                failures.push(format!("{name}: no golden file {} ({e})", golden.display()));
                continue;
            }
        };
        if want != got {
            failures.push(format!("{name}: {}", first_difference(&want, &got)));
        }
    }
    assert!(
        failures.is_empty(),
        "{} of {} bundled cases no longer produce their golden result.json:\n{}\n\
         If the change of output is intended, regenerate with\n  \
         FLEXFEM_BLESS=1 cargo test --release --test golden_outputs\nand review `git diff tests/golden`.",
        failures.len(),
        all.len(),
        failures.join("\n")
    );
}
