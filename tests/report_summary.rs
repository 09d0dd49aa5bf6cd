//! The Markdown report of a `static` mechanism leads with the answer: its first section is a
//! summary per load case (headline stress and utilisation with the element that carries each,
//! displacements of the loaded and prescribed nodes, reactions, warnings), then the hinge and
//! compliance tables, and the table of every node last; numbers in conventional notation with
//! five significant digits (`8.0123e-03`, `0`) and units in every header. Regression: the
//! report of `cases/parallelogram_guide.json` opened with its 37-row node table in Rust's
//! exponent format (`8.012266e-3`, `0.000000e0`), the hinge table after it.
//!
//! Source of the expected numbers: the run's own JSON result (the report formats it); the
//! rounding to five significant digits bounds the difference by 5e-5 relative.

use flexfem::analysis;
use serde_json::Value;

mod common;

fn outcome(case: &str) -> analysis::Outcome {
    let c = analysis::load(&common::root().join(case)).unwrap_or_else(|e| panic!("{e}"));
    analysis::run(&c).unwrap_or_else(|e| panic!("{e}"))
}

/// The `## ` headings of a Markdown text, in order.
fn sections(md: &str) -> Vec<&str> {
    md.lines().filter(|l| l.starts_with("## ")).collect()
}

/// The cells of the first table row of `md` after `from` whose first cell is `first`.
fn row<'a>(md: &'a str, from: usize, first: &str) -> Vec<&'a str> {
    md[from..]
        .lines()
        .map(|l| l.trim_matches('|').split('|').map(str::trim).collect::<Vec<_>>())
        .find(|cells| cells.first() == Some(&first))
        .unwrap_or_else(|| panic!("no row `{first}` after byte {from}"))
}

/// `cell` is `want` to five significant digits (relative to `scale`, the row's largest entry).
fn close(cell: &str, want: f64, scale: f64) {
    let got: f64 = cell.parse().unwrap_or_else(|_| panic!("not a number: {cell}"));
    assert!(
        (got - want).abs() <= 5e-5 * want.abs().max(scale) + 1e-300,
        "{cell} vs {want}"
    );
}

/// Numbers in table cells are plain or `d.dddde±XX`: no Rust exponent (`e-3`, `e0`) and no
/// padded zero (`0.000000e0`).
fn conventional(md: &str) {
    for l in md.lines().filter(|l| l.starts_with('|')) {
        for cell in l.trim_matches('|').split('|').map(str::trim) {
            if cell.parse::<f64>().is_err() {
                continue;
            }
            if let Some((m, e)) = cell.split_once('e') {
                assert!(
                    (e.starts_with('+') || e.starts_with('-')) && e.len() >= 3,
                    "exponent of `{cell}` in `{l}`"
                );
                let digits = m.chars().filter(char::is_ascii_digit).count();
                assert_eq!(digits, 5, "mantissa of `{cell}`");
            } else if cell.parse::<f64>() == Ok(0.0) {
                assert_eq!(cell, "0", "zero written as `{cell}`");
            }
        }
    }
}

#[test]
fn mechanism_report_opens_with_the_summary() {
    let out = outcome("cases/parallelogram_guide.json");
    let md = &out.report.markdown;
    let json = &out.json;
    let heads = sections(md);
    assert_eq!(heads.first(), Some(&"## Summary"), "{heads:?}");
    let cases = json["load_cases"].as_array().unwrap();
    assert_eq!(cases.len(), 2);
    let summary = md.find("## Summary").unwrap();
    let hinges = md.find("Hinge elements").expect("hinge table");
    let nodes = md.find("## Node displacements").expect("node table");
    assert!(summary < hinges && hinges < nodes, "{heads:?}");
    // The node table is the last section of the static report (materials and warnings follow).
    assert!(
        heads
            .iter()
            .skip_while(|h| **h != "## Node displacements")
            .skip(1)
            .all(|h| *h == "## Warnings"),
        "{heads:?}"
    );
    for c in cases {
        let name = c["name"].as_str().unwrap();
        let at = md.find(&format!("### Load case `{name}`")).unwrap();
        assert!(at < hinges, "{name}: summary after the hinge table");
        let vm = c["max_von_mises"].as_f64().unwrap();
        let el = &c["max_von_mises_at"];
        let line = md[at..]
            .lines()
            .find(|l| l.starts_with("- Maximum von Mises stress"))
            .unwrap();
        let expect_tail = format!(" MPa at element {} ({}).", el["element"], el["kind"].as_str().unwrap());
        assert!(line.ends_with(&expect_tail), "{line}");
        let value = line
            .trim_start_matches("- Maximum von Mises stress: ")
            .split(' ')
            .next()
            .unwrap();
        close(value, vm, 0.0);
        let u = &c["max_utilisation"];
        let line = md[at..]
            .lines()
            .find(|l| l.starts_with("- Maximum utilisation"))
            .unwrap();
        assert!(
            line.contains(&format!(
                "at element {} ({};",
                u["element"],
                u["kind"].as_str().unwrap()
            )),
            "{line}"
        );
        // The loaded (or prescribed) node 8 and the total reaction.
        let d: Vec<f64> = c["displacements"][8]
            .as_array()
            .unwrap()
            .iter()
            .map(|v| v.as_f64().unwrap())
            .collect();
        let cells = row(md, at, "8");
        assert_eq!(cells.len(), 7);
        let scale = d.iter().fold(0.0f64, |m, v| m.max(v.abs()));
        for (k, want) in d.iter().enumerate() {
            close(cells[k + 1], *want, scale);
        }
        let total: Vec<f64> = c["total_reaction"]
            .as_array()
            .unwrap()
            .iter()
            .map(|v| v.as_f64().unwrap())
            .collect();
        let cells = row(md, at, "total");
        assert_eq!(cells.len(), 7);
        for (k, want) in total.iter().enumerate() {
            close(cells[k + 1], *want, 0.0);
        }
    }
    // Push 1 N along x: the total reaction is −1 N along x, written −1.0000.
    assert_eq!(
        row(md, md.find("### Load case `push_x_1N`").unwrap(), "total")[1],
        "-1.0000"
    );
    // Headers carry units.
    for h in [
        "| node | ux (mm) | uy (mm) | uz (mm) | rx (°) | ry (°) | rz (°) |",
        "| node | Fx (N) | Fy (N) | Fz (N) | Mx (N·mm) | My (N·mm) | Mz (N·mm) |",
    ] {
        assert!(md.contains(h), "{h}");
    }
    assert!(md.contains("| element | rotation (°) | peak von Mises (MPa) | utilisation (–) |"));
    assert!(
        !md.contains("0.000000e0") && !md.contains("e-3 "),
        "Rust exponent format left"
    );
    conventional(md);
}

/// Warnings of a load case stand in its summary, before any table of the details.
#[test]
fn load_case_warnings_are_in_the_summary() {
    let case: Value = serde_json::json!({
        "analysis": "static",
        "materials": {"al": "Al7075"},
        "nodes": [[0, 0, 0], [40, 0, 0]],
        "elements": [{"type": "hinge", "nodes": [0, 1], "material": "al", "up": [0, 0, 1],
                      "hinge": {"type": "circular_notch", "R": 8, "t": 0.8, "w": 10, "h": 10}}],
        "supports": [{"node": 0, "fix": ["ux", "uy", "uz", "rx", "ry", "rz"]}],
        "load_cases": [{"name": "moment", "forces": [{"node": 1, "F": [0, 0, 0, 0, 2000, 0]}]}]
    });
    let out = analysis::run(&analysis::parse_value(case, None).unwrap()).unwrap();
    let md = &out.report.markdown;
    assert_eq!(out.warnings.len(), 2, "{:?}", out.warnings);
    let hinges = md.find("Hinge elements").unwrap();
    for w in &out.warnings {
        let at = md
            .find(&format!("> **Warning**: {w}"))
            .unwrap_or_else(|| panic!("no callout: {w}"));
        assert!(at < hinges, "{w}");
    }
    assert!(
        md.contains("- Maximum von Mises stress: 1842.7 MPa at element 0 (hinge)."),
        "{md}"
    );
    assert!(md.contains("4.607 at element 0 (hinge; 1842.7 MPa against 400.00 MPa), **above the allowable stress**."));
    conventional(md);
}
