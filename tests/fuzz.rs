//! Deterministic fuzzer of case files: ≥ 2,000 seeded mutations of the bundled cases per run,
//! through the library in-process (parse → check → run with output files, inside
//! `catch_unwind`) plus a few dozen through the real binary for exit codes.
//!
//! What must hold for every mutated case (the rules of the case-file interface):
//! * nothing panics (exit code 101 from the binary);
//! * a refusal is a case-file error (exit 2) that names a JSON path of the mutated file: the path
//!   leads through the document, only its last step may be missing (a missing field);
//! * a case that `check` accepts is not refused as a case-file error by `run` (check validates
//!   everything run does before solving);
//! * no non-finite number in any output: the JSON result (serde_json writes NaN and ±∞ as
//!   `null`, so a `null` outside the fields that are optional by design is a non-finite number),
//!   the Markdown and CSV reports and every output file (`NaN`, `inf` tokens);
//! * every result lists its `warnings` in the JSON and in the Markdown report.
//!
//! Mutations: delete, duplicate, rename or add fields; change a value's type; numbers set to 0,
//! negative, huge (1e300, 1e154), tiny (1e-300, 5e-324), off by one, copied from another
//! number of the case, scaled by 1e±6; NaN-like and empty strings; empty arrays, wrong lengths,
//! swapped and duplicated elements. Sizes are bounded (load steps, modes, samples, elements per
//! leg are capped; arrays grow by one element at most) so the run stays fast.
//!
//! Reproduce one failure: every failure message prints the mutated case; `FLEXFEM_FUZZ_SEED`
//! changes the seed and `FLEXFEM_FUZZ_SCALE` multiplies the number of mutations (e.g. 10 for
//! a longer local run). Failures are also written to `$CARGO_TARGET_TMPDIR/fuzz-failures/`.

use flexfem::analysis::Case;
use flexfem::analysis::{self, RunError};
use serde_json::{Map, Value};
use std::collections::BTreeMap;
use std::panic::{catch_unwind, AssertUnwindSafe};
use std::path::{Path, PathBuf};
use std::process::Command;

// ---------------------------------------------------------------------------------------------
// A tiny seeded PRNG (SplitMix64), shared with the other randomised tests.

#[path = "common/rng.rs"]
mod rng;
use rng::Rng;

fn fnv(s: &str) -> u64 {
    s.bytes().fold(0xcbf2_9ce4_8422_2325u64, |h, b| {
        (h ^ b as u64).wrapping_mul(0x0100_0000_01b3)
    })
}

fn base_seed() -> u64 {
    std::env::var("FLEXFEM_FUZZ_SEED")
        .ok()
        .and_then(|s| s.parse().ok())
        .unwrap_or(20_261_124)
}

fn scale() -> usize {
    std::env::var("FLEXFEM_FUZZ_SCALE")
        .ok()
        .and_then(|s| s.parse().ok())
        .unwrap_or(1)
}

// ---------------------------------------------------------------------------------------------
// The bundled cases, made cheap to run.

fn root() -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR"))
}

fn cases_dir() -> PathBuf {
    root().join("cases")
}

fn bundled() -> Vec<(String, Value)> {
    let mut v: Vec<(String, Value)> = std::fs::read_dir(cases_dir())
        .expect("cases/")
        .map(|e| e.unwrap().path())
        .filter(|p| p.extension().is_some_and(|x| x == "json"))
        .map(|p| {
            let text = std::fs::read_to_string(&p).unwrap();
            let name = p.file_stem().unwrap().to_string_lossy().into_owned();
            (name, serde_json::from_str(&text).unwrap())
        })
        .collect();
    v.sort_by(|a, b| a.0.cmp(&b.0));
    v
}

/// Caps on sizes that cost run time (kept only when the value is valid but large: invalid values
/// are refused before any work and are kept to exercise the checks).
const CAPS: [(&str, f64, f64); 4] = [
    ("steps", 3.0, 1_000_000.0),
    ("samples", 4.0, 100_000.0),
    ("modes", 12.0, 1000.0),
    ("leg_elements", 6.0, 1000.0),
];

/// Bounds the cost of a case: caps the sizes above, and gives nonlinear runs few load steps.
fn bound(v: &mut Value) {
    fn walk(v: &mut Value) {
        match v {
            Value::Object(m) => {
                for (k, x) in m.iter_mut() {
                    if let Some((_, cap, max)) = CAPS.iter().find(|(n, _, _)| n == k) {
                        if let Some(f) = x.as_f64() {
                            if f > *cap && f <= *max {
                                *x = Value::from(*cap as u64);
                            }
                        }
                    }
                    walk(x);
                }
            }
            Value::Array(a) => a.iter_mut().for_each(walk),
            _ => {}
        }
    }
    walk(v);
    if let Value::Object(m) = v {
        let analysis = m.get("analysis").and_then(Value::as_str).unwrap_or("").to_string();
        let nonlinear = m.get("nonlinear") == Some(&Value::Bool(true)) || analysis == "fem_vs_fkp";
        if nonlinear && !m.contains_key("steps") {
            m.insert("steps".into(), Value::from(2));
        }
        if analysis == "fem_vs_fkp" {
            if let Some(Value::Array(s)) = m.get_mut("strokes") {
                s.truncate(2);
            }
        }
        if analysis == "design" && !m.contains_key("samples") {
            m.insert("samples".into(), Value::from(4));
        }
        if let Some(b) = m.get_mut("base") {
            bound(b);
        }
    }
}

// ---------------------------------------------------------------------------------------------
// Mutations.

#[derive(Clone, Debug)]
enum Step {
    Key(String),
    Index(usize),
}

/// Every location in the document (the root excluded).
fn locations(v: &Value) -> Vec<Vec<Step>> {
    fn walk(v: &Value, here: &mut Vec<Step>, out: &mut Vec<Vec<Step>>) {
        match v {
            Value::Object(m) => {
                for (k, x) in m {
                    here.push(Step::Key(k.clone()));
                    out.push(here.clone());
                    walk(x, here, out);
                    here.pop();
                }
            }
            Value::Array(a) => {
                for (i, x) in a.iter().enumerate() {
                    here.push(Step::Index(i));
                    out.push(here.clone());
                    walk(x, here, out);
                    here.pop();
                }
            }
            _ => {}
        }
    }
    let mut out = Vec::new();
    walk(v, &mut Vec::new(), &mut out);
    out
}

fn get_mut<'a>(v: &'a mut Value, path: &[Step]) -> Option<&'a mut Value> {
    let mut cur = v;
    for s in path {
        cur = match (s, cur) {
            (Step::Key(k), Value::Object(m)) => m.get_mut(k)?,
            (Step::Index(i), Value::Array(a)) => a.get_mut(*i)?,
            _ => return None,
        };
    }
    Some(cur)
}

fn show(path: &[Step]) -> String {
    let mut s = String::new();
    for p in path {
        match p {
            Step::Key(k) => {
                if !s.is_empty() {
                    s.push('.');
                }
                s.push_str(k);
            }
            Step::Index(i) => s.push_str(&format!("[{i}]")),
        }
    }
    s
}

fn numbers(v: &Value, out: &mut Vec<f64>) {
    match v {
        Value::Number(n) => out.extend(n.as_f64()),
        Value::Array(a) => a.iter().for_each(|x| numbers(x, out)),
        Value::Object(m) => m.values().for_each(|x| numbers(x, out)),
        _ => {}
    }
}

const ODD_STRINGS: [&str; 8] = ["NaN", "inf", "-Infinity", "", "1e999", "nylon66", " ", "ü"];
const FIELD_NAMES: [&str; 8] = ["R", "t", "nodes", "steps", "modes", "analysis", "name", "type"];

/// One random mutation of `doc`; returns what it did (for the failure report).
fn mutate(doc: &mut Value, rng: &mut Rng) -> String {
    let locs = locations(doc);
    if locs.is_empty() {
        return "nothing to mutate".into();
    }
    let mut nums = Vec::new();
    numbers(doc, &mut nums);
    if nums.is_empty() {
        nums.push(1.0);
    }
    let path = rng.pick(&locs).clone();
    let (parent_path, last) = path.split_at(path.len() - 1);
    let last = last[0].clone();
    let at = show(&path);
    let op = rng.below(16);
    // Structural edits on the parent container.
    if op < 3 {
        let parent = get_mut(doc, parent_path).unwrap();
        match (parent, &last) {
            (Value::Object(m), Step::Key(k)) => match op {
                0 => {
                    m.remove(k);
                    return format!("delete {at}");
                }
                1 => {
                    let v = m.remove(k).unwrap();
                    let new = match rng.below(3) {
                        0 => k.to_uppercase(),
                        1 => format!("{k}_"),
                        _ => k.chars().rev().collect(),
                    };
                    m.insert(new.clone(), v);
                    return format!("rename {at} to {new}");
                }
                _ => {
                    let new = rng.pick(&FIELD_NAMES).to_string();
                    let v = m[k].clone();
                    m.insert(new.clone(), v);
                    return format!("copy {at} into field {new}");
                }
            },
            (Value::Array(a), Step::Index(i)) => match op {
                0 => {
                    a.remove(*i);
                    return format!("remove {at}");
                }
                1 => {
                    if a.len() < 2000 {
                        let x = a[*i].clone();
                        a.insert(*i, x);
                    }
                    return format!("duplicate {at}");
                }
                _ => {
                    let j = rng.below(a.len());
                    a.swap(*i, j);
                    return format!("swap {at} with [{j}]");
                }
            },
            _ => unreachable!(),
        }
    }
    let target = get_mut(doc, &path).unwrap();
    let new: Value = match target {
        Value::Number(n) => {
            let x = n.as_f64().unwrap_or(0.0);
            match op {
                3 => 0.into(),
                4 => (-x).into(),
                5 => (-1).into(),
                6 => (1e300).into(),
                7 => (*rng.pick(&[1e154, -1e300, 1.7e308, 1e20])).into(),
                8 => (*rng.pick(&[1e-300, 5e-324, 1e-12, -1e-300])).into(),
                9 => (x + *rng.pick(&[1.0, -1.0, 0.5])).into(),
                10 => (*rng.pick(&nums)).into(),
                11 => (x * *rng.pick(&[1e6, 1e-6, 1e3])).into(),
                12 => Value::from(u64::MAX),
                13 => Value::String(rng.pick(&ODD_STRINGS).to_string()),
                14 => Value::Bool(true),
                _ => Value::Null,
            }
        }
        Value::String(_) => match op {
            3..=8 => Value::String(rng.pick(&ODD_STRINGS).to_string()),
            9..=10 => (*rng.pick(&nums)).into(),
            11 => Value::Array(vec![]),
            12 => Value::Object(Map::new()),
            _ => Value::Null,
        },
        Value::Array(a) => match op {
            3..=5 => Value::Array(vec![]),
            6..=7 => {
                let mut b = a.clone();
                b.pop();
                Value::Array(b)
            }
            8..=9 => {
                let mut b = a.clone();
                if let Some(x) = b.last().cloned() {
                    b.push(x);
                } else {
                    b.push(0.into());
                }
                Value::Array(b)
            }
            10 => {
                let mut b = a.clone();
                b.reverse();
                Value::Array(b)
            }
            11 => Value::Object(Map::new()),
            12 => 1.into(),
            _ => Value::Null,
        },
        Value::Object(m) => match op {
            3..=5 => Value::Object(Map::new()),
            6..=8 => {
                let mut b = m.clone();
                b.insert(rng.pick(&FIELD_NAMES).to_string(), rng.pick(&nums).to_owned().into());
                Value::Object(b)
            }
            9..=10 => Value::Array(m.values().cloned().collect()),
            11 => "Al7075".into(),
            _ => Value::Null,
        },
        Value::Bool(b) => match op {
            3..=9 => Value::Bool(!*b),
            10..=12 => 1.into(),
            _ => Value::Null,
        },
        Value::Null => match op {
            3..=9 => 1.into(),
            _ => Value::String("x".into()),
        },
    };
    let said = format!("set {at} = {}", short(&new));
    *target = new;
    said
}

/// The longest prefix of `s` of at most `n` bytes that ends on a character boundary.
fn prefix(s: &str, n: usize) -> &str {
    let end = s
        .char_indices()
        .map(|(i, _)| i)
        .take_while(|&i| i < n)
        .last()
        .unwrap_or(0);
    &s[..end]
}

fn short(v: &Value) -> String {
    let s = v.to_string();
    if s.len() > 80 {
        format!("{}…", prefix(&s, 80))
    } else {
        s
    }
}

// ---------------------------------------------------------------------------------------------
// The checks.

/// Does `path` (as printed by a case-file error) lead through `doc`? Its last step may be
/// missing (a missing field). Object keys may contain dots (`vary."hinge.t"`).
fn path_resolves(doc: &Value, path: &str) -> bool {
    if path == "." {
        return true;
    }
    if path.is_empty() {
        return false;
    }
    // Split into key parts and indices.
    let mut parts: Vec<Result<String, usize>> = Vec::new();
    for piece in path.split('.') {
        let mut rest = piece;
        let key_end = rest.find('[').unwrap_or(rest.len());
        if key_end > 0 {
            parts.push(Ok(rest[..key_end].to_string()));
        }
        rest = &rest[key_end..];
        while let Some(stripped) = rest.strip_prefix('[') {
            let Some(close) = stripped.find(']') else {
                return false;
            };
            let Ok(i) = stripped[..close].parse::<usize>() else {
                return false;
            };
            parts.push(Err(i));
            rest = &stripped[close + 1..];
        }
        if !rest.is_empty() {
            return false;
        }
    }
    fn go(v: &Value, parts: &[Result<String, usize>]) -> bool {
        let Some(first) = parts.first() else {
            return true;
        };
        match (first, v) {
            (Err(i), Value::Array(a)) => match a.get(*i) {
                Some(x) => go(x, &parts[1..]),
                None => parts.len() == 1,
            },
            (Ok(_), Value::Object(m)) => {
                // The longest run of key parts that is a key (keys may hold dots).
                let keys: Vec<&String> = parts.iter().map_while(|p| p.as_ref().ok()).collect();
                for n in (1..=keys.len()).rev() {
                    let k = keys[..n].iter().map(|s| s.as_str()).collect::<Vec<_>>().join(".");
                    if let Some(x) = m.get(&k) {
                        return go(x, &parts[n..]);
                    }
                }
                parts.len() == 1
            }
            _ => false,
        }
    }
    go(doc, &parts)
}

/// Fields whose `null` in a result means "not applicable" or "unbounded" by design (an `Option`,
/// or a documented `null` for an unlimited quantity); any other `null` in a result is a NaN or
/// an infinity that serde_json wrote as `null`.
const OPTIONAL_RESULT_FIELDS: [&str; 15] = [
    "max_von_mises",
    "element_von_mises",
    "rotation_at_allowable_deg",
    "linear_rotation_at_allowable_deg",
    "large_rotation",
    "workspace",
    "modes",
    "fem_nonlinear",
    "nonlinear_minus_fkp",
    "message",
    "max_rotation_deg",
    "T",
    "factor_at_allowable",
    // A static hinge's rotation left to the allowable: null when unbounded (no stress).
    "remaining_rotation_deg",
    // The frf direct check up to twice the highest retained mode: null when no frequency of
    // the case lies that low (a mutated stage whose modes fell below 0.5 Hz, the sweep from 1 Hz).
    "max_relative_difference_to_2x_highest_mode",
];

/// Is a `null` at `path` (ending in `key`) one of the documented ones?
fn null_allowed(path: &str, key: &str) -> bool {
    OPTIONAL_RESULT_FIELDS.contains(&key)
        // The stage's reach at the allowable stress: all null when the material has none.
        || (path.ends_with(&format!("at_allowable.{key}")) && ["allowable", "force", "stroke", "z"].contains(&key))
        // The material echo: unlimited strengths.
        || ((path.contains(".material.") || path.contains(".materials.")) && ["yield", "allowable"].contains(&key))
}

fn non_finite_in_json(v: &Value, key: &str, path: &str, out: &mut Vec<String>) {
    match v {
        Value::Null if !null_allowed(path, key) => out.push(format!("null (NaN or ±∞) at {path}")),
        Value::Number(n) if !n.as_f64().is_some_and(f64::is_finite) => out.push(format!("{n} at {path}")),
        Value::Array(a) => {
            for (i, x) in a.iter().enumerate() {
                non_finite_in_json(x, key, &format!("{path}[{i}]"), out);
            }
        }
        Value::Object(m) => {
            for (k, x) in m {
                non_finite_in_json(x, k, &format!("{path}.{k}"), out);
            }
        }
        _ => {}
    }
}

/// The case's strings that a report may echo (names) and that spell a non-finite word.
fn strings(v: &Value, out: &mut Vec<String>) {
    match v {
        Value::String(s)
            if is_non_finite_word(s) || s.split(|c: char| !c.is_ascii_alphanumeric()).any(is_non_finite_word) =>
        {
            out.push(s.clone())
        }
        Value::Array(a) => a.iter().for_each(|x| strings(x, out)),
        Value::Object(m) => m.values().for_each(|x| strings(x, out)),
        _ => {}
    }
}

fn is_non_finite_word(w: &str) -> bool {
    matches!(w.to_ascii_lowercase().as_str(), "nan" | "inf" | "infinity")
}

/// `NaN`/`inf` tokens in a text output (ignoring text copied from the case, e.g. a load case
/// named "NaN").
fn non_finite_in_text(text: &str, case: &Value) -> Option<String> {
    let mut echoed = Vec::new();
    strings(case, &mut echoed);
    echoed.sort_by_key(|s| std::cmp::Reverse(s.len()));
    let mut t = text.to_string();
    for s in &echoed {
        t = t.replace(s.as_str(), " ");
    }
    t.split(|c: char| !(c.is_ascii_alphanumeric() || c == '.' || c == '_'))
        .find(|w| is_non_finite_word(w))
        .map(|w| {
            let i = t.find(w).unwrap_or(0);
            let from = t[..i].char_indices().rev().nth(40).map_or(0, |(j, _)| j);
            let to = t[i..].char_indices().nth(40).map_or(t.len(), |(j, _)| i + j);
            format!("{w:?} in …{}…", &t[from..to])
        })
}

#[derive(Default)]
struct Findings {
    /// class → (count, smallest reproducer: case text, mutations, detail)
    classes: BTreeMap<String, (usize, String, String, String)>,
    mutated: usize,
    runs: usize,
    ok: usize,
    refused: usize,
    failed: usize,
}

impl Findings {
    fn add(&mut self, class: String, case: &Value, what: &str, detail: String) {
        let text = case.to_string();
        let e = self
            .classes
            .entry(class)
            .or_insert((0, text.clone(), what.to_string(), detail.clone()));
        e.0 += 1;
        if text.len() < e.1.len() {
            *e = (e.0, text, what.to_string(), detail);
        }
    }

    /// Records a refusal of `doc` whose error `path` is not in the case.
    fn unlocated(&mut self, doc: &Value, what: &str, analysis: &str, path: &str, message: &str) {
        if !path_resolves(doc, path) {
            let m = format!("error path `{path}` is not in the case: {message}");
            self.add(class_of("refusal without a JSON path", analysis, path), doc, what, m);
        }
    }
}

fn class_of(kind: &str, analysis: &str, detail: &str) -> String {
    // Digits removed so that one defect at many indices or values is one class.
    let d: String = detail.chars().filter(|c| !c.is_ascii_digit()).take(70).collect();
    format!("{kind} [{analysis}] {d}")
}

fn panic_text(p: Box<dyn std::any::Any + Send>) -> String {
    p.downcast_ref::<String>()
        .cloned()
        .or_else(|| p.downcast_ref::<&str>().map(|s| s.to_string()))
        .unwrap_or_else(|| "(non-string panic)".into())
}

thread_local! {
    static QUIET: std::cell::Cell<bool> = const { std::cell::Cell::new(false) };
}

/// Panics inside the fuzzed calls are caught and reported, not printed; the test's own
/// assertion messages are printed as usual.
fn install_quiet_hook() {
    static ONCE: std::sync::Once = std::sync::Once::new();
    ONCE.call_once(|| {
        let default = std::panic::take_hook();
        std::panic::set_hook(Box::new(move |info| {
            if !QUIET.with(|q| q.get()) {
                default(info);
            }
        }));
    });
}

fn quietly<T>(f: impl FnOnce() -> T) -> std::thread::Result<T> {
    QUIET.with(|q| q.set(true));
    let r = catch_unwind(AssertUnwindSafe(f));
    QUIET.with(|q| q.set(false));
    r
}

/// Runs `run` quietly; a panic is recorded as a finding of class `stage` for `analysis` on
/// (`doc`, `what`), and gives `None`.
fn unless_panics<T>(
    f: &mut Findings,
    (stage, analysis, doc, what): (&str, &str, &Value, &str),
    run: impl FnOnce() -> T,
) -> Option<T> {
    quietly(run)
        .map_err(|p| {
            let m = panic_text(p);
            f.add(class_of(stage, analysis, &m), doc, what, m);
        })
        .ok()
}

/// Parses, checks and runs one case in-process; records every broken rule.
fn exercise(doc: &Value, what: &str, f: &mut Findings) {
    let analysis = doc.get("analysis").and_then(Value::as_str).unwrap_or("?").to_string();
    let base = cases_dir();
    // As the command line does: errors of the resolved case are located where the case file
    // sets the value (a parameter, a hinge type, the mesh file).
    let resolved = match quietly(|| analysis::case_file::parse_resolved(doc.clone(), Some(&base), true)) {
        Err(p) => {
            let m = panic_text(p);
            f.add(class_of("panic in parse", &analysis, &m), doc, what, m);
            return;
        }
        Ok(Err(e)) => {
            f.refused += 1;
            f.unlocated(doc, what, &analysis, &e.path, &e.message);
            return;
        }
        Ok(Ok(p)) => p,
    };
    let parsed = &resolved.case;
    if let Case::Sweep(s) = parsed {
        // A sweep runs its designs one by one: the first and the last.
        match quietly(|| s.build()) {
            Err(p) => {
                let m = panic_text(p);
                f.add(class_of("panic in sweep build", &analysis, &m), doc, what, m);
            }
            Ok(Err(e)) => {
                f.refused += 1;
                f.unlocated(doc, what, &analysis, &e.path, &e.message);
            }
            Ok(Ok(sweep)) => {
                let n = sweep.len();
                for i in [0, n.saturating_sub(1)] {
                    match sweep.design(i) {
                        Ok(mut d) => {
                            bound(&mut d);
                            exercise(&d, &format!("{what}; sweep design {i}"), f);
                        }
                        Err(e) => {
                            f.unlocated(doc, what, &analysis, &e.path, &e.message);
                        }
                    }
                }
            }
        }
        return;
    }
    let Some(checked) = unless_panics(f, ("panic in check", &analysis, doc, what), || {
        analysis::check(parsed).map_err(|e| resolved.locate(e))
    }) else {
        return;
    };
    f.runs += 1;
    let Some(outcome) = unless_panics(f, ("panic in run", &analysis, doc, what), || {
        analysis::run_with_files(parsed).map_err(|e| resolved.locate_run(e))
    }) else {
        return;
    };
    match outcome {
        Err(RunError::Case(e)) => {
            f.refused += 1;
            if checked.is_ok() {
                let m = format!("check accepted it, run refused it at `{}`: {}", e.path, e.message);
                f.add(
                    class_of("check accepts what run refuses", &analysis, &e.path),
                    doc,
                    what,
                    m,
                );
            }
            f.unlocated(doc, what, &analysis, &e.path, &e.message);
        }
        Err(RunError::Analysis(e)) => {
            f.failed += 1;
            if checked.is_err() {
                let m = format!("check refused it but run failed in the analysis: {e}");
                f.add(class_of("check refuses, run does not", &analysis, ""), doc, what, m);
            }
            if let Some(w) = INPUT_CONFLICTS.iter().find(|w| e.message.contains(*w)) {
                let m = format!("an input conflict found only by the solver ({w}): {e}");
                f.add(
                    class_of("input conflict as an analysis failure", &analysis, w),
                    doc,
                    what,
                    m,
                );
            }
            if e.context.is_empty() || e.message.is_empty() {
                f.add(
                    class_of("analysis error without context", &analysis, ""),
                    doc,
                    what,
                    e.to_string(),
                );
            }
        }
        Ok(o) => {
            f.ok += 1;
            if let Err(e) = &checked {
                let m = format!("check refused it at `{}` ({}) but run succeeded", e.path, e.message);
                f.add(
                    class_of("check refuses what run accepts", &analysis, &e.path),
                    doc,
                    what,
                    m,
                );
            }
            // Results go through `analysis::to_checked_json` (a non-finite number is an
            // AnalysisError naming the quantity); the null check below is what catches a result
            // that did not. Every result carries its `warnings`, also in the Markdown report.
            let listed: Option<Vec<String>> = o
                .json
                .get("warnings")
                .and_then(|w| serde_json::from_value(w.clone()).ok());
            if listed.as_ref() != Some(&o.warnings) {
                let m = format!(
                    "result.json warnings {:?} vs Outcome::warnings {:?}",
                    o.json.get("warnings"),
                    o.warnings
                );
                f.add(
                    class_of("warnings missing from result.json", &analysis, ""),
                    doc,
                    what,
                    m,
                );
            }
            if let Some(w) = o.warnings.iter().find(|w| !o.report.markdown.contains(w.as_str())) {
                let m = format!("warning not in report.md: {w}");
                f.add(class_of("warning missing from report.md", &analysis, ""), doc, what, m);
            }
            if analysis == "static" {
                for m in static_invariants(&o.json, doc) {
                    f.add(class_of("static invariant", &analysis, &m), doc, what, m);
                }
            }
            let mut bad = Vec::new();
            non_finite_in_json(&o.json, "", "result", &mut bad);
            if let Some(first) = bad.first() {
                let key: String = first.split(" at ").nth(1).unwrap_or("").to_string();
                let m = format!(
                    "{} non-finite: {}",
                    bad.len(),
                    bad.iter().take(4).cloned().collect::<Vec<_>>().join("; ")
                );
                f.add(
                    class_of("non-finite number in result.json", &analysis, &key),
                    doc,
                    what,
                    m,
                );
            }
            for (name, text) in [("report.md", &o.report.markdown), ("result.csv", &o.report.csv)] {
                if let Some(w) = non_finite_in_text(text, doc) {
                    f.add(
                        class_of(&format!("non-finite number in {name}"), &analysis, ""),
                        doc,
                        what,
                        w,
                    );
                }
            }
            for (name, bytes) in &o.files {
                if let Some(w) = non_finite_in_text(&String::from_utf8_lossy(bytes), doc) {
                    f.add(
                        class_of(&format!("non-finite number in {name}"), &analysis, ""),
                        doc,
                        what,
                        w,
                    );
                }
            }
        }
    }
}

/// Messages of the solver's constraint checks ([`flexfem::fem::FemError`]) that are about the
/// input: a case that reaches them passed `check` with an input `run` cannot take.
const INPUT_CONFLICTS: [&str; 3] = [
    "over-constrained",
    "is prescribed twice",
    "a tie joins coincident nodes",
];

/// The static result's own checks, for every load case: equilibrium (the summed reactions
/// balance the applied loads within 1e-6 of the load scale; the applied load is the residual
/// minus the reactions' resultant, whose moments need the case's inline nodes) and a non-null
/// `max_von_mises` when an element reports a positive stress.
fn static_invariants(result: &Value, doc: &Value) -> Vec<String> {
    let mut out = Vec::new();
    let nodes: Option<Vec<[f64; 3]>> = doc.get("nodes").and_then(|n| serde_json::from_value(n.clone()).ok());
    let Some(cases) = result.get("load_cases").and_then(Value::as_array) else {
        out.push("no load_cases array".into());
        return out;
    };
    for c in cases {
        let name = c.get("name").and_then(Value::as_str).unwrap_or("?");
        let vec6 = |v: &Value| -> Option<[f64; 6]> { serde_json::from_value(v.clone()).ok() };
        let (Some(res), Some(reactions), Some(at)) = (
            c.get("equilibrium_residual").and_then(vec6),
            c.get("reactions")
                .and_then(|r| serde_json::from_value::<Vec<[f64; 6]>>(r.clone()).ok()),
            c.get("reaction_nodes")
                .and_then(|r| serde_json::from_value::<Vec<usize>>(r.clone()).ok()),
        ) else {
            out.push(format!(
                "load case {name}: equilibrium_residual, reactions or reaction_nodes missing"
            ));
            continue;
        };
        if reactions.len() != at.len() {
            out.push(format!(
                "load case {name}: {} reactions for {} reaction nodes",
                reactions.len(),
                at.len()
            ));
            continue;
        }
        // Resultant of the reactions about the origin (moments only with the node positions).
        let mut sum = [0.0f64; 6];
        let mut abs = [0.0f64; 6];
        let mut size = 0.0f64;
        // zip-checked: the lengths are compared just above (an unequal pair is reported and skipped).
        for (r, &n) in reactions.iter().zip(&at) {
            let x = nodes.as_ref().and_then(|v| v.get(n)).copied();
            let m = x.map(|x| {
                [
                    x[1] * r[2] - x[2] * r[1] + r[3],
                    x[2] * r[0] - x[0] * r[2] + r[4],
                    x[0] * r[1] - x[1] * r[0] + r[5],
                ]
            });
            for k in 0..3 {
                sum[k] += r[k];
                abs[k] += r[k].abs();
                if let Some(m) = m {
                    sum[3 + k] += m[k];
                    abs[3 + k] += m[k].abs();
                }
            }
            if let Some(x) = x {
                size = size.max(x.iter().map(|v| v.abs()).fold(0.0, f64::max));
            }
        }
        let applied: Vec<f64> = (0..6).map(|k| res[k] - sum[k]).collect();
        let fscale = (0..3).map(|k| applied[k].abs() + abs[k]).fold(0.0, f64::max);
        let mscale = (3..6).map(|k| applied[k].abs() + abs[k]).fold(0.0, f64::max) + fscale * size;
        let with_moments = nodes.is_some();
        for (k, r) in res.iter().enumerate() {
            let scale = if k < 3 { fscale } else { mscale };
            if k >= 3 && !with_moments {
                continue;
            }
            if r.abs() > 1e-6 * scale + 1e-9 {
                out.push(format!(
                    "load case {name}: equilibrium residual[{k}] = {r:e} above 1e-6 of the load scale {scale:e}"
                ));
            }
        }
        let stressed = c
            .get("element_von_mises")
            .and_then(Value::as_array)
            .is_some_and(|v| v.iter().any(|s| s.as_f64().is_some_and(|s| s > 0.0)));
        if stressed && c.get("max_von_mises").is_none_or(Value::is_null) {
            out.push(format!(
                "load case {name}: an element carries stress but max_von_mises is null"
            ));
        }
    }
    out
}

/// Mutations per bundled case (the slow cases get fewer; the total is ≥ 2,000).
fn mutations_for(name: &str) -> usize {
    let n = match name {
        "ruiz2019_design" => 40,
        "gmsh_plate_tris" | "gmsh_plate_quads" | "modal_plate_shell" | "static_plate_shell" => 150,
        _ => 300,
    };
    n * scale()
}

fn fuzz_cases(select: impl Fn(usize) -> bool) -> Findings {
    install_quiet_hook();
    let mut f = Findings::default();
    let mut total = 0;
    for (k, (name, original)) in bundled().into_iter().enumerate() {
        if !select(k) {
            continue;
        }
        let mut cheap = original.clone();
        bound(&mut cheap);
        let mut rng = Rng::new(base_seed() ^ fnv(&name));
        for i in 0..mutations_for(&name) {
            let mut doc = cheap.clone();
            // Mostly one mutation (the case stays close to valid and runs), sometimes two or three.
            let count = if rng.below(3) == 0 { 2 + rng.below(2) } else { 1 };
            let what: Vec<String> = (0..count).map(|_| mutate(&mut doc, &mut rng)).collect();
            bound(&mut doc);
            let what = format!("{name} #{i}: {}", what.join("; "));
            exercise(&doc, &what, &mut f);
            total += 1;
        }
    }
    f.mutated = total;
    eprintln!(
        "fuzz: {total} mutated cases (+ sweep designs): {} passed parsing and were run ({} ok, {} analysis \
         errors, the rest refused by validation); {} case-file refusals in all",
        f.runs, f.ok, f.failed, f.refused
    );
    f
}

fn report(f: &Findings, label: &str) {
    if f.classes.is_empty() {
        return;
    }
    let dir = PathBuf::from(env!("CARGO_TARGET_TMPDIR")).join("fuzz-failures");
    let _ = std::fs::create_dir_all(&dir);
    let mut msg = format!("{label}: {} failure classes\n", f.classes.len());
    for (k, (class, (count, case, what, detail))) in f.classes.iter().enumerate() {
        msg += &format!(
            "\n[{k}] {class}  ({count}×)\n    mutation: {what}\n    found: {detail}\n    case: {}\n",
            short_case(case)
        );
        let _ = std::fs::write(dir.join(format!("{label}-{k}.json")), case);
    }
    panic!("{msg}");
}

fn short_case(s: &str) -> String {
    if s.len() > 600 {
        format!("{}… ({} bytes)", prefix(s, 600), s.len())
    } else {
        s.to_string()
    }
}

#[test]
fn fuzz_library_even_cases() {
    let f = fuzz_cases(|k| k % 2 == 0);
    assert!(f.mutated >= 1000, "only {} mutations", f.mutated);
    report(&f, "even");
}

#[test]
fn fuzz_library_odd_cases() {
    let f = fuzz_cases(|k| k % 2 == 1);
    assert!(f.mutated >= 1000, "only {} mutations", f.mutated);
    report(&f, "odd");
}

// ---------------------------------------------------------------------------------------------
// Through the real binary: exit codes, messages and the files `--out` writes.

fn scan_dir(dir: &Path, case: &Value, problems: &mut Vec<String>) {
    let Ok(entries) = std::fs::read_dir(dir) else {
        return;
    };
    for e in entries.flatten() {
        let p = e.path();
        let Ok(bytes) = std::fs::read(&p) else { continue };
        let name = p.file_name().unwrap().to_string_lossy().into_owned();
        let text = String::from_utf8_lossy(&bytes);
        if name.ends_with(".json") {
            match serde_json::from_str::<Value>(&text) {
                Ok(v) => {
                    let mut bad = Vec::new();
                    non_finite_in_json(&v, "", &name, &mut bad);
                    if !bad.is_empty() {
                        problems.push(format!(
                            "{}: {}",
                            name,
                            bad.iter().take(3).cloned().collect::<Vec<_>>().join("; ")
                        ));
                    }
                }
                Err(e) => problems.push(format!("{name} is not JSON: {e}")),
            }
        } else if let Some(w) = non_finite_in_text(&text, case) {
            problems.push(format!("{name}: {w}"));
        }
    }
}

#[test]
fn fuzz_binary_exit_codes_and_files() {
    let exe = env!("CARGO_BIN_EXE_flexfem");
    let tmp = PathBuf::from(env!("CARGO_TARGET_TMPDIR")).join(format!("fuzz-bin-{}", std::process::id()));
    std::fs::create_dir_all(&tmp).unwrap();
    let mut findings = Findings::default();
    let mut runs = 0;
    for (name, original) in bundled() {
        if matches!(name.as_str(), "ruiz2019_design" | "gmsh_plate_tris") {
            continue; // slow: covered in-process
        }
        let mut cheap = original.clone();
        bound(&mut cheap);
        let mut rng = Rng::new(base_seed() ^ fnv(&name) ^ 0xB1_4A_27);
        for i in 0..3 * scale() {
            let mut doc = cheap.clone();
            let what = mutate(&mut doc, &mut rng);
            bound(&mut doc);
            let what = format!("{name} #{i} (binary): {what}");
            // The case sits in cases/'s sibling temp folder; its mesh paths (`../meshes/…`) are
            // resolved from the working folder, cases/.
            let file = tmp.join(format!("{name}-{i}.json"));
            std::fs::write(&file, doc.to_string()).unwrap();
            let out_dir = tmp.join(format!("{name}-{i}.out"));
            let _ = std::fs::remove_dir_all(&out_dir);
            let is_sweep = doc.get("analysis").and_then(Value::as_str) == Some("sweep");
            let mut cmd = Command::new(exe);
            cmd.current_dir(cases_dir());
            if is_sweep {
                // Only small sweeps: the in-process fuzzer covers the designs.
                let small = analysis::parse_value(doc.clone(), Some(&cases_dir()))
                    .ok()
                    .and_then(|c| match c {
                        Case::Sweep(s) => s.build().ok().map(|s| s.len() <= 64),
                        _ => None,
                    })
                    .unwrap_or(true);
                if !small {
                    continue;
                }
                std::fs::create_dir_all(&out_dir).unwrap();
                cmd.arg("sweep")
                    .arg(&file)
                    .arg("--out")
                    .arg(out_dir.join("designs.jsonl"));
            } else {
                cmd.arg("run").arg(&file).arg("--out").arg(&out_dir);
            }
            let out = cmd.output().expect("run flexfem");
            runs += 1;
            let stderr = String::from_utf8_lossy(&out.stderr).into_owned();
            let analysis = doc.get("analysis").and_then(Value::as_str).unwrap_or("?").to_string();
            // `check` refuses exactly what `run` refuses about the input (exit 2 both or neither).
            let checked = Command::new(exe)
                .current_dir(cases_dir())
                .arg("check")
                .arg(&file)
                .output()
                .expect("check flexfem");
            let (check_code, run_code) = (checked.status.code(), out.status.code());
            if !is_sweep && (check_code == Some(2)) != (run_code == Some(2)) {
                let m = format!(
                    "check exited {check_code:?}, run exited {run_code:?}: {}{}",
                    String::from_utf8_lossy(&checked.stderr),
                    stderr
                );
                findings.add(class_of("check and run disagree", &analysis, ""), &doc, &what, m);
            }
            match out.status.code() {
                Some(0) => {
                    let mut problems = Vec::new();
                    if is_sweep {
                        match std::fs::read_to_string(out_dir.join("designs.jsonl")) {
                            Ok(text) => {
                                if text.lines().next().is_none() {
                                    problems.push("designs.jsonl is empty".into());
                                }
                                for (k, line) in text.lines().enumerate() {
                                    match serde_json::from_str::<Value>(line) {
                                        Ok(v) => {
                                            let mut bad = Vec::new();
                                            non_finite_in_json(
                                                &v,
                                                "",
                                                &format!("designs.jsonl line {}", k + 1),
                                                &mut bad,
                                            );
                                            problems.extend(bad.into_iter().take(2));
                                        }
                                        Err(e) => {
                                            problems.push(format!("designs.jsonl line {} is not JSON: {e}", k + 1))
                                        }
                                    }
                                }
                            }
                            Err(e) => problems.push(format!("sweep exited 0 without designs.jsonl: {e}")),
                        }
                    } else {
                        scan_dir(&out_dir, &doc, &mut problems);
                    }
                    if !problems.is_empty() {
                        let m = problems.join("; ");
                        findings.add(
                            class_of("non-finite number or missing line in --out files", &analysis, ""),
                            &doc,
                            &what,
                            m,
                        );
                    }
                }
                Some(1) => {
                    if !stderr.contains("error") {
                        findings.add(class_of("exit 1 without a message", &analysis, ""), &doc, &what, stderr);
                    }
                }
                Some(2) => {
                    let path = stderr
                        .split("case file error at `")
                        .nth(1)
                        .and_then(|s| s.split('`').next())
                        .map(str::to_string);
                    match path {
                        Some(p) if path_resolves(&doc, &p) => {}
                        _ => findings.add(
                            class_of("exit 2 without a JSON path of the case", &analysis, ""),
                            &doc,
                            &what,
                            stderr,
                        ),
                    }
                }
                other => findings.add(
                    class_of(&format!("exit code {other:?}"), &analysis, ""),
                    &doc,
                    &what,
                    stderr,
                ),
            }
        }
    }
    let _ = std::fs::remove_dir_all(&tmp);
    eprintln!("fuzz: {runs} mutated cases through the binary");
    assert!(runs >= 40, "only {runs} binary runs");
    report(&findings, "binary");
}

/// The fuzzer mutates every bundled case, so it covers every analysis kind only if each kind has
/// a bundled case (a sweep's base counts for its kind).
#[test]
fn every_analysis_kind_has_a_fuzzed_case() {
    let mut kinds: Vec<String> = Vec::new();
    for (_, doc) in bundled() {
        for v in [doc.get("analysis"), doc.get("base").and_then(|b| b.get("analysis"))] {
            if let Some(k) = v.and_then(Value::as_str) {
                kinds.push(k.to_string());
            }
        }
    }
    let missing: Vec<&&str> = analysis::ANALYSES
        .iter()
        .filter(|k| !kinds.iter().any(|x| x == **k))
        .collect();
    assert!(analysis::ANALYSES.len() >= 10, "{} kinds", analysis::ANALYSES.len());
    assert!(
        missing.is_empty(),
        "analysis kinds with no bundled case to fuzz: {missing:?}"
    );
}

#[test]
fn path_resolution_rules() {
    let doc: Value = serde_json::json!({
        "stage": {"revolute": {"t": 2}},
        "elements": [{"nodes": [0, 1]}],
        "vary": {"hinge.t": {"steps": 0}}
    });
    assert!(path_resolves(&doc, "."));
    assert!(path_resolves(&doc, "stage.revolute.t"));
    assert!(
        path_resolves(&doc, "stage.revolute.R"),
        "a missing last field is a path"
    );
    assert!(path_resolves(&doc, "elements[0].nodes[1]"));
    assert!(
        path_resolves(&doc, "elements[0].nodes[2]"),
        "one past the end: a missing element"
    );
    assert!(path_resolves(&doc, "vary.hinge.t.steps"), "keys with dots");
    assert!(!path_resolves(&doc, "elements[3].section"), "no such element");
    assert!(!path_resolves(&doc, "stage.leg.w"), "no such object");
    assert!(!path_resolves(&doc, ""));
    assert!(!path_resolves(&doc, "gmsh.groups.plate.section"));
}

#[test]
fn prng_is_deterministic() {
    // SplitMix64 from seed 0: the first outputs published with the algorithm
    // (e.g. the reference C implementation by Vigna, prng.di.unimi.it/splitmix64.c).
    let mut r = Rng::new(0);
    assert_eq!(r.next(), 0xE220_A839_7B1D_CDAF);
    assert_eq!(r.next(), 0x6E78_9E6A_A1B9_65F4);
}
