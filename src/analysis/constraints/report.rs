//! The Markdown and CSV views of a `constraints` result.

use super::ConstraintsResult;
use crate::analysis::Report;
use crate::report::markdown::{sig, Table};

/// Markdown and CSV views.
pub fn report(r: &ConstraintsResult) -> Report {
    let mut md = String::from("# Exact-constraint check\n\n");
    let mut t = Table::new(&["quantity", "value"]);
    for (k, v) in [
        ("bodies (ground not counted)", r.bodies.to_string()),
        ("constraint equations", r.constraints.to_string()),
        ("rank", r.rank.to_string()),
        ("Grübler–Kutzbach 6·bodies − equations", r.grubler_kutzbach.to_string()),
        ("redundant constraints (over-constraint)", r.redundant.to_string()),
        ("mobility (free motions)", r.mobility.to_string()),
        ("smallest singular value", sig(r.smallest_singular_value, 3)),
    ] {
        t.row(vec![k.into(), v]);
    }
    md += &t.render();
    // CSV: what each listed item is and the joint, support, load case or body it names.
    let mut csv = String::from("kind,name\n");
    let mut section = |title: &str, kind: &str, rows: Vec<(String, String)>| {
        if rows.is_empty() {
            return;
        }
        md += &format!("\n## {title}\n\n");
        for (i, (name, text)) in rows.into_iter().enumerate() {
            md += &format!("{}. {text}\n", i + 1);
            csv += &format!("{kind},{name}\n");
        }
    };
    section(
        "Redundant constraints",
        "redundant",
        r.redundancies.iter().map(|x| (x.path.clone(), x.text.clone())).collect(),
    );
    section(
        "Free motions",
        "free_motion",
        r.free_motions
            .iter()
            .map(|x| {
                let bodies: Vec<String> = x.bodies.iter().map(|b| format!("body {}", b.body)).collect();
                (bodies.join(" "), x.text.clone())
            })
            .collect(),
    );
    section(
        "Suggested releases",
        "release",
        r.suggestions
            .iter()
            .map(|x| (x.path.clone(), format!("{} (redundant left: {})", x.change, x.redundant_after)))
            .collect(),
    );
    Report { markdown: md, csv }
}
