//! The README's Validation table says exactly what the tests show.
//!
//! Each row of the table (section "## Validation") has six cells: quantity, reference, kind,
//! flexfem, tolerance, test. Checked here, row by row:
//! - the kind is one of `independent` (a published number or closed form no one here wrote),
//!   `cross-check` (two parts of flexfem, or a reference computed here) or `regression` (a pin
//!   on what the model gives: fit residuals, paper entries not reproduced);
//! - the test cell names one or more existing tests as `` `tests/FILE.rs::fn_name` ``;
//! - every value in backquotes in the tolerance cell appears in the source of a named test fn,
//!   of a function or macro of the same file it calls, or of a `const` of that file it uses —
//!   so the tolerance the README quotes is the one a test asserts (change one, and this fails
//!   until the other follows).

mod common;

use common::rust_source::{functions, mask};

const KINDS: [&str; 3] = ["independent", "cross-check", "regression"];

/// The rows of the Validation table, each split into its cells.
fn table() -> Vec<Vec<String>> {
    let readme = std::fs::read_to_string(common::root().join("README.md")).unwrap();
    let start = readme
        .find("\n## Validation\n")
        .expect("README has a Validation section");
    let section = &readme[start + 1..];
    let section = &section[..section[3..].find("\n## ").map_or(section.len(), |e| e + 3)];
    let lines: Vec<&str> = section.lines().filter(|l| l.starts_with('|')).collect();
    assert!(lines.len() > 2, "no table in the Validation section");
    let cells = |l: &str| -> Vec<String> {
        let inner = l.trim().trim_start_matches('|').trim_end_matches('|');
        inner.split(" | ").map(|c| c.trim().to_string()).collect()
    };
    assert_eq!(
        cells(lines[0]),
        ["quantity", "reference", "kind", "flexfem", "tolerance", "test"],
        "Validation table header"
    );
    lines[2..].iter().map(|l| cells(l)).collect()
}

/// Text between backquotes.
fn quoted(cell: &str) -> Vec<String> {
    cell.split('`').skip(1).step_by(2).map(str::to_string).collect()
}

/// Body of `fn name` (or `macro_rules! name`) in `code`, found on the masked source.
fn body<'a>(code: &'a str, name: &str) -> Option<&'a str> {
    functions(&mask(code), true)
        .into_iter()
        .find(|(f, ..)| f == name)
        .map(|(_, _, range)| &code[range])
}

/// Identifiers of `text` (for the helpers and constants a body uses).
fn identifiers(text: &str) -> Vec<&str> {
    text.split(|c: char| !(c.is_alphanumeric() || c == '_'))
        .filter(|w| w.chars().next().is_some_and(|c| c.is_alphabetic() || c == '_'))
        .collect()
}

/// The source a row's tolerance may be found in: the named fns, the same-file functions and
/// macros they call (two levels), and the same-file `const` items they use.
fn searched_source(code: &str, fns: &[&str]) -> String {
    let mut text = String::new();
    let mut frontier: Vec<String> = fns.iter().map(|f| f.to_string()).collect();
    let mut seen = Vec::new();
    for _ in 0..3 {
        let mut next = Vec::new();
        for f in frontier {
            if seen.contains(&f) {
                continue;
            }
            if let Some(b) = body(code, &f) {
                text.push_str(b);
                text.push('\n');
                next.extend(identifiers(b).into_iter().map(str::to_string));
            }
            seen.push(f);
        }
        frontier = next;
    }
    let used = identifiers(&text).into_iter().map(str::to_string).collect::<Vec<_>>();
    for line in code.lines() {
        let l = line.trim_start();
        if let Some(rest) = l.strip_prefix("const ").or_else(|| l.strip_prefix("pub const ")) {
            let name: String = rest.chars().take_while(|c| c.is_alphanumeric() || *c == '_').collect();
            if used.contains(&name) {
                text.push_str(line);
                text.push('\n');
            }
        }
    }
    text
}

#[test]
fn every_row_names_a_test_its_kind_and_the_tolerance_that_test_asserts() {
    let rows = table();
    assert!(rows.len() >= 50, "only {} rows in the Validation table", rows.len());
    let mut problems = Vec::new();
    for (i, row) in rows.iter().enumerate() {
        let what = format!("row {} ({})", i + 1, row.first().map_or("", |s| s.as_str()));
        if row.len() != 6 {
            problems.push(format!("{what}: {} cells, not 6", row.len()));
            continue;
        }
        if !KINDS.contains(&row[2].as_str()) {
            problems.push(format!("{what}: kind {:?} is not one of {KINDS:?}", row[2]));
        }
        let tests = quoted(&row[5]);
        if tests.is_empty() {
            problems.push(format!("{what}: names no test"));
            continue;
        }
        let mut file: Option<(String, String)> = None;
        let mut fns = Vec::new();
        for t in &tests {
            let Some((path, f)) = t.split_once("::") else {
                problems.push(format!("{what}: {t:?} is not tests/FILE.rs::fn"));
                continue;
            };
            let code = match std::fs::read_to_string(common::root().join(path)) {
                Ok(c) if path.starts_with("tests/") => c,
                _ => {
                    problems.push(format!("{what}: no test file {path}"));
                    continue;
                }
            };
            if body(&code, f).is_none() {
                problems.push(format!("{what}: no fn {f} in {path}"));
            }
            match &file {
                Some((p, _)) if p != path => problems.push(format!("{what}: tests from two files")),
                _ => file = Some((path.to_string(), code)),
            }
            fns.push(f);
        }
        let Some((path, code)) = file else { continue };
        let source = searched_source(&code, &fns);
        let tolerances = quoted(&row[4]);
        if tolerances.is_empty() {
            problems.push(format!("{what}: the tolerance cell quotes no value in backquotes"));
        }
        for tol in tolerances {
            if !source.contains(&tol) {
                problems.push(format!(
                    "{what}: tolerance `{tol}` not found in {path}::{fns:?} (or what it uses)"
                ));
            }
        }
    }
    assert!(problems.is_empty(), "Validation table:\n{}", problems.join("\n"));
}

#[test]
fn the_checker_finds_what_it_must_and_rejects_what_it_must_not() {
    // The scheme on a known row: the tolerance of the Table 4 FKP row is in its test…
    let code = std::fs::read_to_string(common::root().join("tests/kinematics.rs")).unwrap();
    let src = searched_source(&code, &["table4_fkp_column_within_2um_and_2arcsec"]);
    assert!(src.contains("<= 2.0"));
    // …a tolerance it does not assert is not…
    assert!(!src.contains("<= 0.5,"));
    // …and a constant is found through its use.
    let code = std::fs::read_to_string(common::root().join("tests/stage.rs")).unwrap();
    let src = searched_source(&code, &["table2_strokes_displacements_and_stress"]);
    assert!(src.contains("const DZ_AT_ALLOWABLE_TOL: f64 = 0.10;"), "{src}");
    assert_eq!(quoted("`a` and `b`"), ["a", "b"]);
}
