//! Identical results of the stage analysis across reimplementations: every number of the
//! `stage` result (load-case rows, stiffness_z, at_allowable, platform compliance and its
//! eigenvalues) for 1,000 random stage designs, against reference values computed with the
//! implementation before the stage was condensed (serial leg chains reduced to two-node
//! elements, issue 21). The reference is the previous implementation itself, so the tolerance
//! is roundoff: 1e-9 relative, with an absolute floor of 1e-9 × the largest magnitude in the
//! same JSON array or object (a pose, a compliance row: entries that are zero by symmetry come
//! out as roundoff of their siblings).
//!
//! The table (tests/data/stage_reference.f64: little-endian f64, per design the count of
//! numbers then the numbers; JSON `null` as NaN) is rewritten only with
//! `FLEXFEM_BLESS_STAGE_REFERENCE=1`, which must never be run after a change it is to check.

use flexfem::analysis::{self as case, Case};
use serde_json::{json, Value};

const DESIGNS: usize = 1000;
const TABLE: &str = "tests/data/stage_reference.f64";

#[path = "common/rng.rs"]
mod rng;
use rng::Rng;

/// A random stage case: every revolute family, spherical neck, several materials, legs of 1…8
/// elements, forces and strokes (ideal joints are checked against the kinematics elsewhere).
fn random_case(r: &mut Rng) -> Value {
    let w = r.uniform(5.0, 14.0);
    let h = r.uniform(5.0, 14.0);
    let t = r.uniform(0.1, 0.45) * h;
    let revolute = match r.below(4) {
        0 => json!({"type": "circular_notch", "R": r.uniform(2.0, 12.0), "t": t}),
        1 => json!({"type": "elliptical_notch", "ax": r.uniform(2.0, 12.0), "ay": r.uniform(2.0, 10.0), "t": t}),
        2 => {
            let l = r.uniform(4.0, 16.0);
            json!({"type": "corner_filleted", "l": l, "R": r.uniform(0.1, 0.5) * l, "t": t})
        }
        _ => json!({"type": "leaf", "l": r.uniform(2.0, 12.0), "t": t}),
    };
    let d = w.min(h);
    let spherical = json!({"type": "spherical_neck", "l": r.uniform(1.0, 9.0), "t": r.uniform(0.2, 0.6) * d, "R": r.uniform(1.0, 6.0)});
    let material = ["Al7075", "steel", "nylon66"][r.below(3)];
    let mut load_cases = Vec::new();
    for k in 0..1 + r.below(3) {
        let v = [r.uniform(-30.0, 60.0), r.uniform(-30.0, 60.0), r.uniform(-30.0, 60.0)];
        if r.below(2) == 0 {
            load_cases.push(json!({"name": format!("F{k}"), "actuator_forces": v}));
        } else {
            load_cases.push(json!({"name": format!("S{k}"), "actuator_strokes": v.map(|x| x / 30.0)}));
        }
    }
    json!({
        "analysis": "stage",
        "material": material,
        "stage": {
            "L": r.uniform(70.0, 150.0), "b": r.uniform(25.0, 70.0),
            "alpha0_deg": r.uniform(25.0, 70.0), "gamma_deg": r.uniform(-30.0, 30.0),
            "leg": {"w": w, "h": h},
            "revolute": revolute,
            "spherical": spherical,
            "leg_elements": 1 + r.below(8)
        },
        "load_cases": load_cases
    })
}

/// Every number of a JSON value in document order (`null` as NaN; strings and booleans
/// skipped), each with the index of its group: the array or object that holds it directly.
fn numbers(v: &Value, group: usize, groups: &mut usize, out: &mut Vec<(f64, usize)>) {
    let g = *groups;
    match v {
        Value::Null => out.push((f64::NAN, group)),
        Value::Number(n) => out.push((n.as_f64().expect("finite"), group)),
        Value::Array(a) => {
            *groups += 1;
            a.iter().for_each(|x| numbers(x, g, groups, out));
        }
        Value::Object(o) => {
            *groups += 1;
            o.values().for_each(|x| numbers(x, g, groups, out));
        }
        Value::Bool(_) | Value::String(_) => {}
    }
}

/// The numbers of the stage result of each random design (skipping designs the case validation
/// refuses: the draw sequence is the same for every implementation; none if the analysis fails).
fn results() -> Vec<Vec<(f64, usize)>> {
    let mut r = Rng::new(0x5EED_0021);
    let mut out = Vec::with_capacity(DESIGNS);
    while out.len() < DESIGNS {
        let text = random_case(&mut r).to_string();
        let Ok(Case::Stage(c)) = case::parse(&text) else {
            continue;
        };
        if c.validated().is_err() {
            continue;
        }
        // An analysis error is recorded as a row of no numbers (the reference has none).
        let mut v = Vec::new();
        if let Ok(res) = flexfem::analysis::stage::run_stage(&c) {
            numbers(&serde_json::to_value(&res).expect("serialises"), 0, &mut 0, &mut v);
        }
        out.push(v);
    }
    out
}

fn write_table(rows: &[Vec<(f64, usize)>]) {
    let mut bytes = Vec::new();
    for row in rows {
        bytes.extend_from_slice(&(row.len() as f64).to_le_bytes());
        for (x, _) in row {
            bytes.extend_from_slice(&x.to_le_bytes());
        }
    }
    std::fs::write(TABLE, bytes).expect("writes the table");
}

fn read_table() -> Vec<Vec<f64>> {
    let bytes = std::fs::read(TABLE).expect("tests/data/stage_reference.f64");
    let mut it = bytes
        .chunks_exact(8)
        .map(|c| f64::from_le_bytes(c.try_into().expect("8 bytes")));
    let mut rows = Vec::new();
    while let Some(n) = it.next() {
        rows.push(it.by_ref().take(n as usize).collect::<Vec<f64>>());
    }
    rows
}

#[test]
fn thousand_random_stage_designs_match_the_reference_to_1e_9() {
    let now = results();
    if std::env::var_os("FLEXFEM_BLESS_STAGE_REFERENCE").is_some() {
        write_table(&now);
        return;
    }
    let reference = read_table();
    assert_eq!(reference.len(), DESIGNS);
    let failed = reference.iter().filter(|r| r.is_empty()).count();
    assert_eq!(failed, 0, "{failed} reference designs failed");
    let mut worst = 0.0f64;
    for (d, (a, b)) in now.iter().zip(&reference).enumerate() {
        assert_eq!(a.len(), b.len(), "design {d}: count of numbers");
        // Floor near zero: 1e-9 of the largest magnitude in the same array or object (a
        // component that is zero by symmetry is roundoff of its siblings).
        let mut scale = vec![0.0f64; a.iter().map(|x| x.1 + 1).max().unwrap_or(0)];
        for ((_, g), y) in a.iter().zip(b) {
            if y.is_finite() {
                scale[*g] = scale[*g].max(y.abs());
            }
        }
        for (k, ((x, g), y)) in a.iter().zip(b).enumerate() {
            if y.is_nan() {
                assert!(x.is_nan(), "design {d} number {k}: {x} vs null");
                continue;
            }
            let err = (x - y).abs();
            let tol = 1e-9 * y.abs().max(scale[*g]);
            assert!(err <= tol, "design {d} number {k}: {x} vs reference {y}");
            worst = worst.max(err / y.abs().max(scale[*g]));
        }
    }
    eprintln!("largest relative difference to the reference: {worst:.2e}");
}
