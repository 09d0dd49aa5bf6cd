//! `--threads N`: a global option sizing the worker pool; 0 or a non-number is refused (exit 2),
//! and the result does not depend on the thread count.

mod common;

use serde_json::Value;

/// Every number of `a` and `b` (same shape), side by side.
fn numbers(a: &Value, b: &Value, out: &mut Vec<(f64, f64)>) {
    match (a, b) {
        (Value::Number(x), Value::Number(y)) => out.push((x.as_f64().unwrap(), y.as_f64().unwrap())),
        (Value::Array(x), Value::Array(y)) => {
            assert_eq!(x.len(), y.len());
            x.iter().zip(y).for_each(|(x, y)| numbers(x, y, out));
        }
        (Value::Object(x), Value::Object(y)) => {
            assert_eq!(x.len(), y.len());
            x.iter().for_each(|(k, v)| numbers(v, &y[k], out));
        }
        _ => assert_eq!(a, b),
    }
}

#[test]
fn threads_option_is_checked_and_does_not_change_results() {
    for bad in ["0", "two"] {
        let o = common::run(&["--threads", bad, "check", "cases/static_lattice.json"]);
        assert_eq!(o.status.code(), Some(2), "--threads {bad}");
        assert!(common::stderr(&o).contains("--threads"), "{}", common::stderr(&o));
    }
    let run = |args: &[&str]| -> Value {
        let o = common::run(args);
        assert_eq!(o.status.code(), Some(0), "{}", common::stderr(&o));
        serde_json::from_slice(&o.stdout).unwrap()
    };
    // Global: before or after the subcommand.
    let one = run(&["--threads", "1", "run", "cases/static_lattice.json"]);
    let two = run(&["run", "cases/static_lattice.json", "--threads", "2"]);
    let mut pairs = Vec::new();
    numbers(&one, &two, &mut pairs);
    let scale = pairs.iter().fold(0.0f64, |m, (a, _)| m.max(a.abs()));
    let diff = pairs.iter().fold(0.0f64, |m, (a, b)| m.max((a - b).abs()));
    // Same factorisation up to the summation order of parallel kernels: roundoff only.
    assert!(diff <= 1e-12 * scale, "results differ by {diff:e} (scale {scale:e})");
}
