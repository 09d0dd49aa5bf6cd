//! Layering of the source tree, checked by parsing the `crate::`, `super::` and `self::` paths
//! (in `use` declarations and inline) of every file in `src/` outside `#[cfg(test)]` modules.
//!
//! The layers, top to bottom — a module may import only from its own layer or below:
//!
//! ```text
//! cli, main                      command line (and the sweep's files, resume, exit codes)
//! design                         the batch driver (sweeps over any analysis kind), sweep tables
//! analysis, gradient             validated case → typed result → JSON/Markdown/CSV views;
//!                                gradients of a case's metrics
//! case                           case files → validated inputs (the only place with JSON paths)
//! stage                          the 3-PRS stage FE model, its sizing and sensitivities
//! hinge, kinematics              flexure-hinge models, parallel kinematics
//! fem                            the finite-element core
//! material, report, output       material data, report writers (numbers, SVG, VTK), output files
//! ```
//!
//! In particular `fem`, `hinge`, `kinematics`, `material` and `report` import none of
//! `analysis`, `cli`, `case`, `design`, `stage`; `case` imports none of `analysis`, `cli`,
//! `design`; `analysis` imports neither `design` nor `cli`. Also, no two files import each other (directly or through a longer cycle), so the
//! data flows one way. Module façades (`lib.rs`, `*/mod.rs`, which re-export their children's
//! items) are left out of the file-cycle check: a child naming an item through its parent's
//! re-export is not a cycle of ideas.
//!
//! Inside `analysis`, [`analysis_reads_top_down`] checks the rooms: one folder per analysis kind
//! above the shared floor `analysis/common/`, below the list of kinds `analysis/dispatch/`.
//!
//! Known violations that are not yet fixed are listed in [`ALLOWED`] with the reason; the test
//! fails on any violation not listed there, and on a listed one that no longer occurs (so the
//! list shrinks as they are fixed).

use std::collections::{BTreeMap, BTreeSet};
use std::path::{Path, PathBuf};

/// Rank of each top-level module: a module may import only modules of equal or lower rank.
const LAYERS: &[(&str, u32)] = &[
    ("main", 90),
    ("cli", 90),
    ("design", 85),
    // Gradients rebuild a parameterised case (through the analysis layer's case parsing).
    ("analysis", 80),
    ("gradient", 80),
    ("case", 70),
    ("stage", 50),
    ("hinge", 40),
    ("kinematics", 40),
    ("fem", 30),
    ("problem", 20),
    ("material", 10),
    ("report", 10),
    ("output", 10),
];

/// Imports forbidden beyond the ranks: `design` holds the batch driver (above the analyses it
/// runs), so neither `case` nor `analysis` may depend on it.
const FORBIDDEN: &[(&str, &str)] = &[("case", "design"), ("analysis", "design")];

/// Violations known and not yet fixed: (importing file, imported top-level module or file,
/// reason). Each entry must still occur; remove it when it is fixed.
const ALLOWED: &[(&str, &str, &str)] = &[];

fn rank(module: &str) -> u32 {
    LAYERS
        .iter()
        .find(|(m, _)| *m == module)
        .map(|(_, r)| *r)
        .unwrap_or_else(|| panic!("module `{module}` has no layer: add it to LAYERS in tests/layering.rs"))
}

fn rust_files(dir: &Path, out: &mut Vec<PathBuf>) {
    for entry in std::fs::read_dir(dir).expect("readable src/") {
        let path = entry.expect("readable entry").path();
        if path.is_dir() {
            rust_files(&path, out);
        } else if path.extension().is_some_and(|e| e == "rs") {
            out.push(path);
        }
    }
}

/// Module path of a source file relative to `src/`: `fem/nonlinear/mod.rs` → `[fem, nonlinear]`,
/// `cli.rs` → `[cli]`, `lib.rs` → `[]`.
fn module_of(rel: &str) -> Vec<String> {
    let mut parts: Vec<String> = rel.trim_end_matches(".rs").split('/').map(str::to_string).collect();
    if matches!(parts.last().map(String::as_str), Some("mod" | "lib")) {
        parts.pop();
    }
    parts
}

fn is_facade(rel: &str) -> bool {
    rel == "lib.rs" || rel.ends_with("/mod.rs") || rel == "mod.rs"
}

/// The code of a file without comments, string literals and `#[cfg(test)]` modules.
fn code_of(text: &str) -> String {
    let mut out = String::new();
    let mut skip_depth: Option<i64> = None;
    let mut depth: i64 = 0;
    let mut pending_cfg_test = false;
    for line in text.lines() {
        let trimmed = line.trim_start();
        if trimmed.starts_with("//") {
            continue;
        }
        // Drop string literals (paths in messages are not imports) and trailing comments.
        let mut clean = String::new();
        let mut in_str = false;
        let mut prev = ' ';
        let chars: Vec<char> = line.chars().collect();
        let mut i = 0;
        while i < chars.len() {
            let c = chars[i];
            if !in_str && c == '/' && chars.get(i + 1) == Some(&'/') {
                break;
            }
            if c == '"' && prev != '\\' && !(prev == '\'' && chars.get(i + 1) == Some(&'\'')) {
                in_str = !in_str;
            } else if !in_str {
                clean.push(c);
            }
            prev = if prev == '\\' && c == '\\' { ' ' } else { c };
            i += 1;
        }
        if trimmed.starts_with("#[cfg(test)]") {
            pending_cfg_test = true;
            continue;
        }
        if pending_cfg_test && trimmed.starts_with("mod ") && skip_depth.is_none() {
            skip_depth = Some(depth);
        }
        pending_cfg_test = false;
        depth += clean.matches('{').count() as i64 - clean.matches('}').count() as i64;
        if let Some(d) = skip_depth {
            if depth <= d {
                skip_depth = None;
            }
            continue;
        }
        out.push_str(&clean);
        out.push('\n');
    }
    out
}

/// `a::{b as c, d}` → `a::{b, d}`: the renames of a `use` tree dropped.
fn drop_renames(tree: &str) -> String {
    let mut out = String::new();
    let mut words = tree.split_whitespace();
    while let Some(w) = words.next() {
        if w == "as" {
            // Keep only the punctuation that follows the new name (`_F},` → `},`).
            let next = words.next().unwrap_or("");
            out.extend(next.chars().filter(|c| !(c.is_alphanumeric() || *c == '_')));
        } else {
            out.push_str(w);
        }
    }
    out
}

/// Expands `a::{b, c::{d, e}}` into `a::b`, `a::c::d`, `a::c::e`.
fn expand(tree: &str) -> Vec<String> {
    let tree: String = tree.chars().filter(|c| !c.is_whitespace()).collect();
    let Some(open) = tree.find('{') else {
        return vec![tree];
    };
    let prefix = &tree[..open];
    let inner = &tree[open + 1..tree.len().saturating_sub(1)];
    let mut parts = Vec::new();
    let (mut level, mut start) = (0, 0);
    for (i, c) in inner.char_indices() {
        match c {
            '{' => level += 1,
            '}' => level -= 1,
            ',' if level == 0 => {
                parts.push(&inner[start..i]);
                start = i + 1;
            }
            _ => {}
        }
    }
    parts.push(&inner[start..]);
    parts
        .into_iter()
        .filter(|p| !p.is_empty())
        .flat_map(|p| expand(p).into_iter().map(move |e| format!("{prefix}{e}")))
        .collect()
}

/// Absolute module paths (segments after `crate`) named by a file.
fn imported_paths(code: &str, module: &[String]) -> Vec<Vec<String>> {
    let mut raw = Vec::new();
    // `use` declarations, with their brace groups expanded.
    for stmt in code.split(';') {
        let at = stmt
            .match_indices("use ")
            .map(|(i, _)| i)
            .filter(|&i| {
                stmt[..i]
                    .chars()
                    .last()
                    .is_none_or(|c| c.is_whitespace() || c == '{' || c == '}' || c == ')')
            })
            .last();
        if let Some(i) = at {
            raw.extend(expand(&drop_renames(&stmt[i + 4..])));
        }
    }
    // Inline paths such as `crate::fem::Model::new`.
    for start in ["crate::", "super::"] {
        let mut from = 0;
        while let Some(i) = code[from..].find(start).map(|k| k + from) {
            let before = code[..i].chars().last();
            from = i + start.len();
            if before.is_some_and(|c| c.is_alphanumeric() || c == '_' || c == ':') {
                continue;
            }
            let end = code[i..]
                .find(|c: char| !(c.is_alphanumeric() || c == '_' || c == ':'))
                .map_or(code.len(), |k| k + i);
            raw.push(code[i..end].to_string());
        }
    }
    // `super` in a file names its module's parent (for `fem/mod.rs`, the crate root).
    let parent: Vec<String> = module[..module.len().saturating_sub(1)].to_vec();
    let mut out = Vec::new();
    for r in raw {
        let segs: Vec<&str> = r.split("::").filter(|s| !s.is_empty()).collect();
        let abs: Vec<String> = match segs.first() {
            Some(&"crate") => segs[1..].iter().map(|s| s.to_string()).collect(),
            Some(&"super") => {
                let mut base = parent.clone();
                let mut rest = &segs[1..];
                while rest.first() == Some(&"super") {
                    base.pop();
                    rest = &rest[1..];
                }
                base.extend(rest.iter().map(|s| s.to_string()));
                base
            }
            Some(&"self") => {
                let mut base = module.to_vec();
                base.extend(segs[1..].iter().map(|s| s.to_string()));
                base
            }
            _ => continue,
        };
        if !abs.is_empty() && abs[0] != "*" {
            out.push(abs);
        }
    }
    out
}

/// The file (relative to `src/`) a module path resolves to: the longest prefix that is a file.
fn file_of(path: &[String], files: &BTreeSet<String>) -> Option<String> {
    for n in (1..=path.len()).rev() {
        let p = path[..n].join("/");
        for cand in [format!("{p}.rs"), format!("{p}/mod.rs")] {
            if files.contains(&cand) {
                return Some(cand);
            }
        }
    }
    None
}

#[test]
fn imports_follow_the_layers_and_files_form_no_cycle() {
    let src = PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("src");
    let mut paths = Vec::new();
    rust_files(&src, &mut paths);
    let rels: BTreeSet<String> = paths
        .iter()
        .map(|p| p.strip_prefix(&src).unwrap().to_string_lossy().replace('\\', "/"))
        .collect();
    assert!(rels.len() > 50, "expected the source tree, found {} files", rels.len());

    let mut violations: BTreeSet<(String, String)> = BTreeSet::new();
    let mut edges: BTreeMap<String, BTreeSet<String>> = BTreeMap::new();
    for rel in &rels {
        let text = std::fs::read_to_string(src.join(rel)).expect("readable source");
        let module = module_of(rel);
        let code = code_of(&text);
        let Some(top) = module.first() else { continue };
        for path in imported_paths(&code, &module) {
            let target = &path[0];
            let upward = LAYERS.iter().any(|(m, _)| m == target) && target != top && rank(target) > rank(top);
            if upward || FORBIDDEN.contains(&(top.as_str(), target.as_str())) {
                violations.insert((format!("src/{rel}"), target.clone()));
            }
            if let Some(file) = file_of(&path, &rels) {
                if &file != rel && !is_facade(&file) && !is_facade(rel) {
                    edges.entry(rel.clone()).or_default().insert(file);
                }
            }
        }
    }

    // File cycles: every strongly connected pair reachable both ways.
    let reach = |from: &str| -> BTreeSet<String> {
        let mut seen = BTreeSet::new();
        let mut stack = vec![from.to_string()];
        while let Some(f) = stack.pop() {
            for g in edges.get(&f).into_iter().flatten() {
                if seen.insert(g.clone()) {
                    stack.push(g.clone());
                }
            }
        }
        seen
    };
    for a in edges.keys() {
        for b in reach(a) {
            if a < &b && reach(&b).contains(a) {
                violations.insert((format!("src/{a}"), format!("src/{b} (cycle)")));
            }
        }
    }

    let allowed: BTreeSet<(String, String)> = ALLOWED.iter().map(|(f, t, _)| (f.to_string(), t.to_string())).collect();
    let new: Vec<_> = violations.difference(&allowed).collect();
    let fixed: Vec<_> = allowed.difference(&violations).collect();
    assert!(
        new.is_empty() && fixed.is_empty(),
        "layering (see the doc comment of tests/layering.rs):\n\
         new violations (file → module it must not import, or a file cycle):\n{}\n\
         allowed violations that no longer occur (remove them from ALLOWED):\n{}",
        new.iter()
            .map(|(f, t)| format!("  {f} → {t}"))
            .collect::<Vec<_>>()
            .join("\n"),
        fixed
            .iter()
            .map(|(f, t)| format!("  {f} → {t}"))
            .collect::<Vec<_>>()
            .join("\n"),
    );
}

/// Where a file of `src/analysis/` sits (see [`analysis_reads_top_down`]).
#[derive(Debug, Clone, PartialEq, Eq)]
enum Room {
    /// `analysis/mod.rs`: the façade and the drivers (`run`, `check`).
    Top,
    /// `analysis/dispatch/`: the list of kinds and what it generates (the `Case` enum, the
    /// registry, the wiring of the built-in kinds).
    Dispatch,
    /// `analysis/common/`: the shared floor.
    Floor,
    /// `analysis/K/` or `analysis/K.rs`: the room of analysis kind `K`.
    Kind(String),
}

fn room_of(rel: &str) -> Option<Room> {
    let rest = rel.strip_prefix("analysis/")?;
    Some(match rest.split('/').next()? {
        "mod.rs" => Room::Top,
        "dispatch" => Room::Dispatch,
        "common" => Room::Floor,
        k => Room::Kind(k.trim_end_matches(".rs").to_string()),
    })
}

/// The names `analysis/mod.rs` brings in with `use` (re-exports such as `analysis::AnalysisError`
/// or the old path `analysis::stage_report`), each with the absolute path it stands for.
fn top_aliases(code: &str) -> BTreeMap<String, Vec<String>> {
    let mut out = BTreeMap::new();
    for stmt in code.split(';') {
        let Some(i) = stmt.find("use ") else { continue };
        if !stmt[..i].trim().is_empty() && stmt[..i].trim() != "pub" {
            continue;
        }
        for leaf in expand(&stmt[i + 4..].replace(" as ", "@")) {
            let (target, name) = match leaf.split_once('@') {
                Some((t, n)) => (t.to_string(), n.to_string()),
                None => (leaf.clone(), leaf.rsplit("::").next().unwrap_or("").to_string()),
            };
            let mut segs: Vec<String> = target.split("::").map(str::to_string).collect();
            if segs.last().is_some_and(|s| s == "self") {
                segs.pop();
            }
            let name = if name == "self" {
                segs.last().cloned().unwrap_or_default()
            } else {
                name
            };
            let abs = match segs.first().map(String::as_str) {
                Some("crate") => segs[1..].to_vec(),
                Some("*") | None => continue,
                _ => std::iter::once("analysis".to_string()).chain(segs).collect(),
            };
            out.insert(name, abs);
        }
    }
    out
}

/// `analysis/` reads top-down, one room per analysis kind:
///
/// - the shared floor, `analysis/common/`, imports nothing else of `analysis` (no kind, no
///   dispatch, not the drivers of `analysis/mod.rs`);
/// - a kind's room, `analysis/K/` (or `analysis/K.rs`), imports neither the dispatch nor the
///   drivers, and from another kind `J` only what `J` names at its root (`analysis/J/mod.rs`,
///   defined or re-exported there: its documented interface), never a file inside `J`;
/// - every arrow from a kind to another is listed in the module docs of `analysis/mod.rs`
///   (as `` `K` → `J` ``).
///
/// Paths are resolved as in [`imports_follow_the_layers_and_files_form_no_cycle`], after the
/// names `analysis/mod.rs` re-exports are replaced by what they stand for (so
/// `analysis::AnalysisError` is the floor's and the old path `analysis::stage_report` is inside
/// the `stage` kind). `analysis/dispatch/` sits above the kinds and may name any of them.
#[test]
fn analysis_reads_top_down() {
    let src = PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("src");
    let mut paths = Vec::new();
    rust_files(&src, &mut paths);
    let rels: BTreeSet<String> = paths
        .iter()
        .map(|p| p.strip_prefix(&src).unwrap().to_string_lossy().replace('\\', "/"))
        .collect();
    let top = std::fs::read_to_string(src.join("analysis/mod.rs")).expect("readable analysis/mod.rs");
    let aliases = top_aliases(&code_of(&top));
    assert!(
        aliases
            .get("AnalysisError")
            .is_some_and(|p| p.starts_with(&["analysis".into(), "common".into()])),
        "expected analysis::AnalysisError re-exported from the floor, aliases: {aliases:?}"
    );

    let mut violations = BTreeSet::new();
    let mut arrows: BTreeSet<(String, String)> = BTreeSet::new();
    let mut kinds = BTreeSet::new();
    for rel in rels.iter().filter(|r| r.starts_with("analysis/")) {
        let from = room_of(rel).expect("a file of analysis/");
        if let Room::Kind(k) = &from {
            kinds.insert(k.clone());
        }
        let text = std::fs::read_to_string(src.join(rel)).expect("readable source");
        for mut path in imported_paths(&code_of(&text), &module_of(rel)) {
            if path.len() >= 2 && path[0] == "analysis" {
                if let Some(abs) = aliases.get(&path[1]) {
                    path.splice(..2, abs.iter().cloned());
                }
            }
            // `analysis` alone is the prefix of a `use` group (`super::{A, B}`), whose leaves
            // are checked one by one.
            if path.len() < 2 || path[0] != "analysis" {
                continue;
            }
            let Some(file) = file_of(&path, &rels) else { continue };
            let Some(to) = room_of(&file) else { continue };
            let why = match (&from, &to) {
                (Room::Floor, t) if *t != Room::Floor => Some("the shared floor imports above itself"),
                (Room::Kind(_), Room::Dispatch | Room::Top) => Some("a kind imports the dispatch or the drivers"),
                (Room::Kind(k), Room::Kind(j)) if k != j => {
                    arrows.insert((k.clone(), j.clone()));
                    let root = [format!("analysis/{j}/mod.rs"), format!("analysis/{j}.rs")];
                    (!root.contains(&file)).then_some("a kind reaches into another kind's files")
                }
                _ => None,
            };
            if let Some(why) = why {
                violations.insert(format!("  src/{rel} → {} (src/{file}): {why}", path.join("::")));
            }
        }
    }
    assert!(
        kinds.len() >= 10,
        "expected the kind folders of analysis/, found {kinds:?}"
    );
    assert!(
        violations.is_empty(),
        "analysis/ must read top-down (see the doc comment of analysis_reads_top_down):\n{}",
        violations.into_iter().collect::<Vec<_>>().join("\n")
    );
    let undocumented: Vec<String> = arrows
        .iter()
        .filter(|(k, j)| !top.contains(&format!("`{k}` → `{j}`")))
        .map(|(k, j)| format!("`{k}` → `{j}`"))
        .collect();
    assert!(
        undocumented.is_empty(),
        "arrows between kinds missing from the module docs of src/analysis/mod.rs: {}",
        undocumented.join(", ")
    );
}
