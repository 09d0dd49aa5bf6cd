//! The README against the program: every performance figure its prose quotes (µs, ms, designs or
//! items per second) agrees with the performance tables, and its command table names exactly
//! the flags the command line (clap, through the built binary's `--help`) accepts.
//!
//! Plain seconds in prose are not checked: they are mostly other tools' or papers' times (ANSYS,
//! Slurm set-up), which the performance tables do not hold.

use std::collections::BTreeSet;
use std::process::Command;

const README: &str = include_str!("../README.md");

/// What a figure measures: a time (value in s) or a rate (value in 1/s).
#[derive(Debug, Clone, Copy, PartialEq)]
enum Kind {
    Time,
    Rate,
}

/// One quoted figure: a value or a range `lo–hi`, normalised to s or 1/s.
#[derive(Debug, Clone, Copy)]
struct Figure {
    lo: f64,
    hi: f64,
    kind: Kind,
    /// Quoted as approximate (`≈`, `~`).
    approx: bool,
    line: usize,
}

/// A number at the start of `s` (`27,000`, `15.6`), and its byte length.
fn number(s: &str) -> Option<(f64, usize)> {
    let b = s.as_bytes();
    let digit = |k: usize| b.get(k).is_some_and(u8::is_ascii_digit);
    let mut i = 0;
    while digit(i) || (i > 0 && b.get(i) == Some(&b',') && (1..=3).all(|d| digit(i + d)) && !digit(i + 4)) {
        i += if b[i] == b',' { 4 } else { 1 };
    }
    if i > 0 && b.get(i) == Some(&b'.') && digit(i + 1) {
        i += 1;
        while digit(i) {
            i += 1;
        }
    }
    (i > 0).then(|| (s[..i].replace(',', "").parse().expect("digits"), i))
}

/// The unit after a number (after optional spaces): (factor to s or 1/s, kind, length).
fn unit(s: &str) -> Option<(f64, Kind, usize)> {
    let t = s.trim_start_matches(' ');
    let skip = s.len() - t.len();
    let word_end = |rest: &str| rest.chars().next().is_none_or(|c| !c.is_alphanumeric());
    for (u, f, k) in [
        ("µs", 1e-6, Kind::Time),
        ("ms", 1e-3, Kind::Time),
        ("/s", 1.0, Kind::Rate),
        ("stage designs per second", 1.0, Kind::Rate),
        ("designs per second", 1.0, Kind::Rate),
        ("designs/s", 1.0, Kind::Rate),
    ] {
        if let Some(rest) = t.strip_prefix(u) {
            if word_end(rest) {
                return Some((f, k, skip + u.len()));
            }
        }
    }
    None
}

/// Every figure of `text` (one line), with the line number.
fn figures(text: &str, line: usize) -> Vec<Figure> {
    let mut out = Vec::new();
    let mut i = 0;
    while i < text.len() {
        let prev = text[..i].chars().next_back();
        let starts = text[i..].starts_with(|c: char| c.is_ascii_digit())
            && prev.is_none_or(|c| !(c.is_alphanumeric() || c == '.' || c == ',' || c == '_'));
        if !starts {
            i += text[i..].chars().next().map_or(1, char::len_utf8);
            continue;
        }
        let (lo, n) = number(&text[i..]).expect("a digit starts a number");
        let mut j = i + n;
        let mut hi = lo;
        if let Some(r) = text[j..].strip_prefix('–') {
            if let Some((h, m)) = number(r) {
                hi = h;
                j += '–'.len_utf8() + m;
            }
        }
        // `1/s` is a unit (a Rayleigh α), not a rate.
        let unit_name = text[i..].starts_with("1/s");
        if let Some((f, kind, m)) = unit(&text[j..]).filter(|_| !unit_name) {
            let before = text[..i].trim_end();
            let approx = before.ends_with('≈') || before.ends_with('~');
            out.push(Figure {
                lo: lo * f,
                hi: hi * f,
                kind,
                approx,
                line,
            });
            j += m;
        }
        i = j;
    }
    out
}

/// Splits the README into the figures of the tables of its Performance section and those of
/// all other text.
fn table_and_prose() -> (Vec<Figure>, Vec<Figure>) {
    let (mut table, mut prose) = (Vec::new(), Vec::new());
    let mut in_perf = false;
    for (k, l) in README.lines().enumerate() {
        if l.starts_with("## ") {
            in_perf = l.starts_with("## Performance");
        }
        let f = figures(l, k + 1);
        if in_perf && l.starts_with('|') {
            table.extend(f);
        } else {
            prose.extend(f);
        }
    }
    (table, prose)
}

/// A prose figure agrees with a table figure of its kind when its range lies inside the table's
/// (its printed precision: 0.5 %; an approximate figure: 1.5 %, so that "≈ 35 µs" does not pass
/// for a table's 36.0 µs).
fn agrees(p: &Figure, t: &Figure) -> bool {
    let tol = if p.approx { 0.015 } else { 0.005 };
    p.kind == t.kind && p.lo >= t.lo * (1.0 - tol) && p.hi <= t.hi * (1.0 + tol)
}

#[test]
fn figure_scanner_reads_ranges_units_and_approximations() {
    let f = figures(
        "≈ 36 µs, 27,000–30,300 stage designs per second, 7.53 ms, 2,556/s, 384 s, α (1/s), L2 5 ms",
        1,
    );
    assert_eq!(f.len(), 5, "{f:?}");
    assert!((f[0].lo - 36e-6).abs() < 1e-15 && f[0].approx && f[0].kind == Kind::Time);
    assert!(f[1].lo == 27_000.0 && f[1].hi == 30_300.0 && f[1].kind == Kind::Rate && !f[1].approx);
    assert!((f[2].lo - 7.53e-3).abs() < 1e-15);
    assert_eq!(f[3].lo, 2_556.0);
    assert!((f[4].lo - 5e-3).abs() < 1e-15);
    // A figure outside the table's range, or of another kind, does not agree.
    let t = Figure {
        lo: 15.6e-6,
        hi: 15.6e-6,
        kind: Kind::Time,
        approx: false,
        line: 0,
    };
    assert!(agrees(&figures("15.6 µs", 1)[0], &t));
    assert!(!agrees(&figures("0.35 ms", 1)[0], &t));
    assert!(!agrees(&figures("16 µs", 1)[0], &t));
    let neck = Figure {
        lo: 36.0e-6,
        hi: 36.0e-6,
        kind: Kind::Time,
        approx: false,
        line: 0,
    };
    assert!(agrees(&figures("≈ 36 µs", 1)[0], &neck) && !agrees(&figures("≈ 35 µs", 1)[0], &neck));
}

/// Every µs / ms / per-second figure quoted outside the performance tables is one of theirs
/// (or inside one of their ranges).
#[test]
fn prose_performance_figures_agree_with_the_performance_table() {
    let (table, prose) = table_and_prose();
    // The tables quote ~60 such figures; the prose (intro, nonlinear bench, FRF bench) several.
    assert!(
        table.len() >= 40,
        "performance table parsed to only {} figures",
        table.len()
    );
    assert!(prose.len() >= 6, "prose has only {} figures: {prose:?}", prose.len());
    let stale: Vec<String> = prose
        .iter()
        .filter(|p| !table.iter().any(|t| agrees(p, t)))
        .map(|p| format!("README.md:{}: {}–{} {:?}", p.line, p.lo, p.hi, p.kind))
        .collect();
    assert!(
        stale.is_empty(),
        "figures quoted in prose that the performance table does not hold:\n{}",
        stale.join("\n")
    );
}

fn help(args: &[&str]) -> String {
    let out = Command::new(env!("CARGO_BIN_EXE_flexfem"))
        .args(args)
        .arg("--help")
        .output()
        .unwrap();
    assert!(out.status.success(), "flexfem {args:?} --help failed");
    String::from_utf8(out.stdout).unwrap()
}

/// The flags a `--help` text declares: the first `--name` of each line of its Options list (the
/// descriptions and the text after the list mention other commands' flags).
fn declared(help: &str) -> BTreeSet<String> {
    let options = help.split("Options:").nth(1).expect("an Options list");
    options
        .lines()
        .map(str::trim_start)
        .filter(|l| l.starts_with('-'))
        .filter_map(|l| flags(l.split("  ").next().unwrap()).into_iter().next())
        .collect()
}

/// The `--flag` names in `text`.
fn flags(text: &str) -> BTreeSet<String> {
    let mut out = BTreeSet::new();
    for (i, _) in text.match_indices("--") {
        let name: String = text[i + 2..]
            .chars()
            .take_while(|c| c.is_ascii_lowercase() || *c == '-')
            .collect();
        let before = text[..i].chars().next_back();
        if !name.is_empty() && before.is_none_or(|c| !c.is_alphanumeric() && c != '-') {
            out.insert(format!("--{name}"));
        }
    }
    out.remove("--help");
    out.remove("--version");
    out
}

/// The subcommands `flexfem --help` lists (without `help`).
fn subcommands(top: &str) -> Vec<String> {
    let list = top.split("Commands:").nth(1).unwrap().split("\n\n").next().unwrap();
    list.lines()
        .filter_map(|l| l.split_whitespace().next())
        .filter(|c| *c != "help")
        .map(str::to_string)
        .collect()
}

/// The rows of the README's command table.
fn command_rows() -> Vec<&'static str> {
    let section = README.split("\n## Command line\n").nth(1).unwrap();
    let section = section.split("\n## ").next().unwrap();
    section
        .lines()
        .skip_while(|l| !l.starts_with('|'))
        .take_while(|l| l.starts_with('|'))
        .collect()
}

/// Each subcommand has a row of the command table, and the row names exactly the flags of that
/// subcommand; the global flags have a row of their own.
#[test]
fn command_table_names_every_cli_flag() {
    let top = help(&[]);
    let global = declared(&top);
    assert!(global.contains("--threads"), "{global:?}");
    let commands = subcommands(&top);
    assert_eq!(commands, ["run", "check", "schema", "sweep", "merge"]);
    let rows = command_rows();
    assert!(rows.len() >= 2 + commands.len(), "{rows:?}");
    for c in &commands {
        let own: BTreeSet<String> = declared(&help(&[c])).difference(&global).cloned().collect();
        let row = rows
            .iter()
            .find(|r| r.starts_with(&format!("| `flexfem {c}")))
            .unwrap_or_else(|| panic!("no row for `flexfem {c}` in the README's command table"));
        let listed = flags(row);
        assert_eq!(listed, own, "README row of `flexfem {c}` vs `flexfem {c} --help`");
    }
    let row = rows
        .iter()
        .find(|r| r.starts_with("| `flexfem --"))
        .expect("a row for the global flags");
    assert_eq!(flags(row), global);
    // Every subcommand must have its own row: the table holds no command the program lacks.
    for r in rows.iter().skip(2) {
        let name = r.trim_start_matches("| `flexfem ").split([' ', '`']).next().unwrap();
        assert!(
            name.starts_with("--") || commands.iter().any(|c| c == name),
            "README command `{name}` is not a subcommand"
        );
    }
}

/// The `transient` and `frf` examples of the case-file reference run as printed (their mesh
/// path resolves as from `cases/`). `meshes/cantilever.json`: L = 100 mm, Al 7075 (E = 72,000 MPa,
/// ν = 0.33), 10 × 5 mm section bending about y (I = 104.17 mm⁴), Timoshenko κ = 5/6. Transient:
/// the step load of 1 N at x = a = 50 mm settles (ζ₁ = β ω₁/2 ≈ 0.08, 16 periods) to the static
/// tip deflection P a²(3L − a)/(6EI) + P a/(κGA) = 0.013933 mm to 0.1 %; frf: the static gain
/// from the tip push to the tip uz is L³/(3EI) + L/(κGA) = 0.044533 mm/N to 0.1 % (Timoshenko
/// cantilever; e.g. S. Timoshenko, J. Gere, Mechanics of Materials, §9).
#[test]
fn transient_and_frf_reference_examples_run() {
    let section = README
        .split("### `transient` and `frf`")
        .nth(1)
        .unwrap()
        .split("\n## ")
        .next()
        .unwrap();
    let blocks: Vec<&str> = section
        .split("```json\n")
        .skip(1)
        .map(|b| b.split("```").next().unwrap())
        .collect();
    assert_eq!(blocks.len(), 2, "a transient and an frf example");
    let root = std::env::temp_dir().join(format!("flexfem-readme-examples-{}", std::process::id()));
    std::fs::create_dir_all(root.join("cases")).unwrap();
    std::fs::create_dir_all(root.join("meshes")).unwrap();
    std::fs::copy(
        concat!(env!("CARGO_MANIFEST_DIR"), "/meshes/cantilever.json"),
        root.join("meshes/cantilever.json"),
    )
    .unwrap();
    let mut results = Vec::new();
    for (k, b) in blocks.iter().enumerate() {
        let path = root.join(format!("cases/example_{k}.json"));
        std::fs::write(&path, b).unwrap();
        let case = flexfem::analysis::load(&path).unwrap_or_else(|e| panic!("README example {k}: {e}"));
        results.push(
            flexfem::analysis::run(&case)
                .unwrap_or_else(|e| panic!("README example {k}: {e}"))
                .json,
        );
    }
    let _ = std::fs::remove_dir_all(&root);
    let (l, a, e, nu, i, area) = (100.0, 50.0, 72_000.0, 0.33, 10.0 * 125.0 / 12.0, 50.0);
    let kga = 5.0 / 6.0 * e / (2.0 * (1.0 + nu)) * area;
    let settled = a * a * (3.0 * l - a) / (6.0 * e * i) + a / kga;
    let record = &results[0]["records"][0];
    let last = record["final_value"].as_f64().unwrap_or_else(|| panic!("{record}"));
    assert!(
        (-last / settled - 1.0).abs() < 1e-3,
        "tip uz settles at {last} mm vs −{settled} mm"
    );
    let compliance = l * l * l / (3.0 * e * i) + l / kga;
    let gain = results[1]["static_gain"][0][0].as_f64().unwrap();
    assert!(
        (gain / compliance - 1.0).abs() < 1e-3,
        "static gain {gain} vs {compliance} mm/N"
    );
}

/// `key="value"` of an XML start tag.
fn attr<'a>(tag: &'a str, key: &str) -> Option<&'a str> {
    let at = tag.find(&format!(" {key}=\""))? + key.len() + 3;
    tag[at..].split('"').next()
}

/// The SVG figure the README shows: every `<text>` label lies inside the view box, by a
/// generous estimate of its extent (0.6 em per character, ascent 0.8 em, descent 0.25 em; the
/// sans-serif average is ~0.5 em), and no two labels overlap. Before, "Beams: same axes …" and
/// "Blanks (w × h) …" ran past the right edge of the 640-wide view box (to ≈ 810).
#[test]
fn hinge_axes_svg_labels_are_inside_the_view_box() {
    let svg = std::fs::read_to_string(concat!(env!("CARGO_MANIFEST_DIR"), "/docs/hinge_axes.svg")).unwrap();
    assert!(README.contains("docs/hinge_axes.svg"));
    let root = &svg[svg.find("<svg").unwrap()..];
    let root = &root[..root.find('>').unwrap()];
    let view: Vec<f64> = attr(root, "viewBox")
        .unwrap()
        .split_whitespace()
        .map(|v| v.parse().unwrap())
        .collect();
    assert_eq!(view.len(), 4);
    let size: f64 = attr(root, "font-size").unwrap().parse().unwrap();
    let mut boxes: Vec<(String, [f64; 4])> = Vec::new();
    for piece in svg.split("<text").skip(1) {
        let (tag, rest) = piece.split_once('>').unwrap();
        let label = rest.split("</text>").next().unwrap();
        let x: f64 = attr(tag, "x").unwrap().parse().unwrap();
        let y: f64 = attr(tag, "y").unwrap().parse().unwrap();
        let fs: f64 = attr(tag, "font-size").map_or(size, |v| v.parse().unwrap());
        let w = 0.6 * fs * label.chars().count() as f64;
        let left = match attr(tag, "text-anchor") {
            Some("middle") => x - w / 2.0,
            Some("end") => x - w,
            _ => x,
        };
        let b = [left, y - 0.8 * fs, left + w, y + 0.25 * fs];
        let inside = b[0] >= view[0] && b[1] >= view[1] && b[2] <= view[0] + view[2] && b[3] <= view[1] + view[3];
        assert!(
            inside,
            "label {label:?} spans x {:.0}–{:.0}, y {:.0}–{:.0}: outside the view box {view:?}",
            b[0], b[2], b[1], b[3]
        );
        for (other, o) in &boxes {
            let apart = b[2] <= o[0] || o[2] <= b[0] || b[3] <= o[1] || o[3] <= b[1];
            assert!(apart, "labels {label:?} and {other:?} overlap");
        }
        boxes.push((label.to_string(), b));
    }
    assert!(boxes.len() >= 8, "the figure's labels: {}", boxes.len());
}
