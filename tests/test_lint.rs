//! A lint over the test sources themselves: checks that can pass without checking.
//!
//! Three rules, each over every `tests/*.rs` file (the shared helpers in `tests/common/` included):
//! 1. no `#[ignore]`: a test that does not run is not evidence;
//! 2. every `#[test]` function asserts something — its body holds `assert`, `panic!`,
//!    `unwrap_err`/`expect_err`, or calls a helper (a function of the same file or of
//!    `tests/common/`) that does, up to three calls deep;
//! 3. every `.zip(` is preceded, within [`ZIP_WINDOW`] lines of the same function, by an
//!    `assert_eq!` on a `len()` (a zip stops at the shorter side, so a missing row would pass
//!    silently), or carries a `// zip-checked: <reason>` marker on its line or the line above
//!    (for instance: both sides are arrays of one fixed type, or the length is asserted by a
//!    helper that is named in the reason).

mod common;

use common::rust_source::{functions, mask};
use std::collections::HashMap;
use std::path::{Path, PathBuf};

/// Lines looked back from a `.zip(` for the length assertion.
const ZIP_WINDOW: usize = 15;
const IGNORE: &str = "#[ignore";
const ZIP: &str = ".zip(";
const MARKER: &str = "// zip-checked:";

/// Every test source: path, text, and the text with literals and comments masked.
fn sources() -> Vec<(PathBuf, String, String)> {
    let root = Path::new(env!("CARGO_MANIFEST_DIR")).join("tests");
    let mut files = Vec::new();
    for dir in [root.clone(), root.join("common")] {
        for entry in std::fs::read_dir(&dir).unwrap() {
            let path = entry.unwrap().path();
            if path.extension().is_some_and(|e| e == "rs") {
                let text = std::fs::read_to_string(&path).unwrap();
                let masked = mask(&text);
                files.push((path, text, masked));
            }
        }
    }
    files.sort();
    assert!(files.len() > 50, "only {} test sources found", files.len());
    files
}

fn name(path: &Path) -> String {
    path.strip_prefix(env!("CARGO_MANIFEST_DIR"))
        .unwrap_or(path)
        .display()
        .to_string()
}

fn asserts_directly(body: &str) -> bool {
    ["assert", "panic!", "unwrap_err", "expect_err", "unreachable!"]
        .iter()
        .any(|k| body.contains(k))
}

fn calls(body: &str, name: &str) -> bool {
    body.match_indices(name).any(|(i, _)| {
        let prev = body[..i].chars().next_back().unwrap_or(' ');
        let next = body[i + name.len()..].chars().next().unwrap_or(' ');
        !(prev.is_alphanumeric() || prev == '_') && (next == '(' || next == ':' || next == '!')
    })
}

fn asserting(body: &str, helpers: &HashMap<String, String>, depth: usize) -> bool {
    asserts_directly(body)
        || (depth > 0
            && helpers
                .iter()
                .any(|(name, b)| b.as_str() != body && calls(body, name) && asserting(b, helpers, depth - 1)))
}

#[test]
fn no_ignored_tests() {
    let mut hits = Vec::new();
    for (path, _, masked) in sources() {
        for (i, line) in masked.lines().enumerate() {
            if line.contains(IGNORE) {
                hits.push(format!("{}:{}", name(&path), i + 1));
            }
        }
    }
    assert!(
        hits.is_empty(),
        "{IGNORE}]d tests (run them, make them a bench or remove them): {hits:?}"
    );
}

#[test]
fn every_test_asserts() {
    let files = sources();
    let mut common = HashMap::new();
    for (path, _, masked) in &files {
        if path.parent().is_some_and(|p| p.ends_with("common")) {
            for (f, _, body) in functions(masked, true) {
                common.insert(f, masked[body].to_string());
            }
        }
    }
    let mut hits = Vec::new();
    let mut tests = 0;
    for (path, text, masked) in &files {
        let mut helpers = common.clone();
        let fns: Vec<(String, usize, String)> = functions(masked, true)
            .into_iter()
            .map(|(f, line, body)| (f, line, masked[body].to_string()))
            .collect();
        for (f, _, body) in &fns {
            helpers.insert(f.clone(), body.clone());
        }
        // Test functions: those whose `fn` follows a `#[test]` line (attributes and doc
        // comments in between allowed).
        let lines: Vec<&str> = text.lines().collect();
        for (f, line, body) in &fns {
            let mut k = line - 1;
            let mut is_test = false;
            while k > 0 {
                k -= 1;
                let l = lines[k].trim();
                if l.starts_with("#[test]") {
                    is_test = true;
                    break;
                }
                if !(l.starts_with("#[") || l.starts_with("///") || l.starts_with("//")) {
                    break;
                }
            }
            if !is_test {
                continue;
            }
            tests += 1;
            if !asserting(body, &helpers, 3) {
                hits.push(format!("{}:{line} {f}", name(path)));
            }
        }
    }
    assert!(tests > 400, "only {tests} #[test] functions found: the scan is broken");
    assert!(hits.is_empty(), "tests without an assertion: {hits:?}");
}

/// Lines (0-based) of the `.zip(` calls of `text` and those without a length check.
fn zips(text: &str) -> (usize, Vec<usize>) {
    let lines: Vec<&str> = text.lines().collect();
    let masked = mask(text);
    let code: Vec<&str> = masked.lines().collect();
    assert_eq!(lines.len(), code.len());
    let mut n = 0;
    let mut hits = Vec::new();
    for (i, line) in code.iter().enumerate() {
        if !line.contains(ZIP) {
            continue;
        }
        n += 1;
        let marked = lines[i].contains(MARKER) || (i > 0 && lines[i - 1].contains(MARKER));
        let mut checked = false;
        for back in code[i.saturating_sub(ZIP_WINDOW)..i].iter().rev() {
            if back.contains("assert_eq!") && back.contains("len()") {
                checked = true;
                break;
            }
            if back.trim_start().starts_with("fn ") || back.contains(" fn ") || back.contains("#[test]") {
                break;
            }
        }
        if !(marked || checked) {
            hits.push(i);
        }
    }
    (n, hits)
}

#[test]
fn every_zip_has_its_lengths_checked() {
    let mut hits = Vec::new();
    let mut n = 0;
    for (path, text, _) in sources() {
        let (count, lines) = zips(&text);
        n += count;
        hits.extend(lines.into_iter().map(|i| format!("{}:{}", name(&path), i + 1)));
    }
    assert!(n > 20, "only {n} zips found: the scan is broken");
    assert!(
        hits.is_empty(),
        "zip without a length assertion within {ZIP_WINDOW} lines of the same fn \
         (add assert_eq!(a.len(), b.len()) or a `// zip-checked: <reason>` marker): {hits:#?}"
    );
}

/// The rules on small sources: what must be flagged is, what must not be is not.
#[test]
fn the_lint_flags_what_it_must() {
    let bare = "#[test]\nfn t() {\n    let a = vec![1];\n    for (x, y) in a.iter().zip(&a) {\n        assert!(x == y);\n    }\n}\n";
    assert_eq!(zips(bare), (1, vec![3]));
    let checked = bare.replace("    for (x", "    assert_eq!(a.len(), a.len());\n    for (x");
    assert_eq!(zips(&checked), (1, vec![]));
    let marked = bare.replace("    for (x", "    // zip-checked: one vector with itself.\n    for (x");
    assert_eq!(zips(&marked), (1, vec![]));
    // A length assertion in the previous function does not count.
    let other = format!("fn f(a: &[u8]) {{\n    assert_eq!(a.len(), 1);\n}}\n{bare}");
    assert_eq!(zips(&other).1, vec![6]);
    // Inside a string or a comment, neither a zip nor a brace counts.
    let quoted = "fn t() {\n    let s = \"a.zip(b) {\";\n    // x.zip(y)\n    assert!(s.len() > 0);\n}\n";
    assert_eq!(zips(quoted), (0, vec![]));
    let fns = functions(&mask(quoted), true);
    assert_eq!(fns.len(), 1);
    assert!(quoted[fns[0].2.clone()].trim_end().ends_with('}') && quoted[fns[0].2.clone()].contains("assert!"));
    let helpers = HashMap::from([("helper".to_string(), "{ assert!(true) }".to_string())]);
    assert!(asserting("{ helper(1); }", &helpers, 3));
    assert!(!asserting("{ let x = 1; }", &helpers, 3));
    assert!(!mask("let s = \"#[ignore]\";").contains(IGNORE));
}
