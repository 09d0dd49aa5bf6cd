//! JSON output: pretty-printed, but arrays of scalars stay on one line.

use serde_json::Value;

/// Pretty JSON where arrays holding only numbers, strings, booleans or nulls are written on one
/// line (displacement vectors, matrices' rows), so results stay readable.
pub fn pretty(v: &Value) -> String {
    let mut out = String::new();
    write(v, 0, &mut out);
    out
}

fn scalar(v: &Value) -> bool {
    !matches!(v, Value::Array(_) | Value::Object(_))
}

fn write(v: &Value, indent: usize, out: &mut String) {
    match v {
        Value::Array(a) if a.is_empty() => out.push_str("[]"),
        Value::Array(a) if a.iter().all(scalar) => {
            out.push('[');
            for (i, x) in a.iter().enumerate() {
                if i > 0 {
                    out.push_str(", ");
                }
                out.push_str(&x.to_string());
            }
            out.push(']');
        }
        Value::Array(a) => write_block(('[', ']'), a.iter().map(|x| (None, x)), indent, out),
        Value::Object(m) if m.is_empty() => out.push_str("{}"),
        Value::Object(m) => write_block(('{', '}'), m.iter().map(|(k, x)| (Some(k), x)), indent, out),
        other => out.push_str(&other.to_string()),
    }
}

/// An array or object over several lines: one item (`"key": ` first when given) per line at
/// `indent + 1`, comma-separated, between the `brackets`.
fn write_block<'a>(
    brackets: (char, char),
    items: impl ExactSizeIterator<Item = (Option<&'a String>, &'a Value)>,
    indent: usize,
    out: &mut String,
) {
    let pad = |n: usize| "  ".repeat(n);
    let len = items.len();
    out.push(brackets.0);
    out.push('\n');
    for (i, (k, x)) in items.enumerate() {
        out.push_str(&pad(indent + 1));
        if let Some(k) = k {
            out.push_str(&Value::String(k.clone()).to_string());
            out.push_str(": ");
        }
        write(x, indent + 1, out);
        if i + 1 < len {
            out.push(',');
        }
        out.push('\n');
    }
    out.push_str(&pad(indent));
    out.push(brackets.1);
}
