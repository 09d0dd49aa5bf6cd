//! The cells and header of sweep tables ([`super::table`]): how a parameter or leaf becomes a CSV
//! field, and the header with units.

use crate::analysis::units::UnitOf;
use serde_json::Value;
use std::borrow::Cow;
use std::fmt::Write as _;

/// Longest array flattened into columns.
pub const MAX_ARRAY: usize = 16;

/// Appends a parameter or leaf as a CSV field: strings bare (quoted when RFC 4180 needs it),
/// null and missing empty, everything else as JSON.
pub(super) fn push_cell(out: &mut String, v: Option<&Value>) {
    match v {
        None | Some(Value::Null) => {}
        Some(Value::String(s)) => push_text(out, s),
        Some(Value::Number(n)) => {
            let _ = write!(out, "{n}");
        }
        Some(other) => push_text(out, &other.to_string()),
    }
}

pub(super) fn push_text(out: &mut String, s: &str) {
    if s.contains([',', '"', '\n', '\r']) {
        out.push('"');
        out.push_str(&s.replace('"', "\"\""));
        out.push('"');
    } else {
        out.push_str(s);
    }
}

/// `name [unit]` when `unit_of` gives the dotted path `name` a unit, else `name`.
pub(super) fn with_unit(name: &str, unit_of: Option<UnitOf>) -> Cow<'_, str> {
    let path: Vec<&str> = name.split('.').collect();
    match unit_of.and_then(|f| f(&path)) {
        Some(u) => Cow::Owned(format!("{name} [{u}]")),
        None => Cow::Borrowed(name),
    }
}

/// The header line: `index`, the varied paths, the result columns (with their units), `error`.
pub(super) fn header<'a>(
    axes: &[&str],
    columns: impl Iterator<Item = &'a str>,
    units: Option<(UnitOf, UnitOf)>,
) -> String {
    let mut out = String::new();
    let (result_unit, input_unit) = (units.map(|u| u.0), units.map(|u| u.1));
    let header = std::iter::once(Cow::Borrowed("index"))
        .chain(axes.iter().map(|a| with_unit(a, input_unit)))
        .chain(columns.map(|c| with_unit(c, result_unit)))
        .chain(std::iter::once(Cow::Borrowed("error")));
    for (i, h) in header.enumerate() {
        if i > 0 {
            out.push(',');
        }
        push_text(&mut out, &h);
    }
    out.push('\n');
    out
}
