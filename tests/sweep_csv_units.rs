//! Units in sweep tables: every numeric column of a stage sweep's and a hinge sweep's CSV is
//! headed `name [unit]` (`[-]` when dimensionless), the unit being the one the result type (or,
//! for a varied path, the case type) declares for that path
//! (`flexfem::analysis::units::Units`), and every number a stage or hinge result holds — load
//! cases, modes, large rotation and damping included — has a declared unit.

mod common;
use common::*;
use flexfem::analysis::registry;
use flexfem::analysis::units::UnitOf;
use flexfem::design::table::visit_leaves;
use serde_json::Value;
use std::fs;

/// The column units the registered analysis `kind` declares.
fn of_kind(kind: &str) -> Option<(UnitOf, UnitOf)> {
    registry::find(kind).and_then(|a| a.column_units())
}

/// Runs `case` as a sweep with `extra` arguments and `--csv`; checks every column's unit.
fn check_table(case: &str, kind: &str, axes: usize, extra: &[&str]) {
    let (result_unit, input_unit) = of_kind(kind).expect("the kind declares units");
    let d = tempdir(&format!("csv-units-{kind}"));
    let mut args = vec![case, "--csv", "t.csv"];
    args.extend_from_slice(extra);
    let o = sweep(&d, &args);
    assert_eq!(o.status.code(), Some(0), "{}", stderr(&o));
    let text = fs::read_to_string(d.join("t.csv")).unwrap();
    let rows: Vec<Vec<&str>> = text.lines().map(|l| l.split(',').collect()).collect();
    let header = &rows[0];
    let mut numeric = 0;
    for (c, h) in header.iter().enumerate() {
        let (name, unit) = match h.split_once(" [") {
            Some((n, u)) => (n, Some(u.strip_suffix(']').expect("`name [unit]`"))),
            None => (*h, None),
        };
        let path: Vec<&str> = name.split('.').collect();
        let declared = |f: UnitOf| f(&path);
        let expected = match c {
            0 => None,
            c if c <= axes => declared(input_unit),
            _ => declared(result_unit),
        };
        assert_eq!(unit, expected, "column {h}");
        let is_number = rows[1..].iter().any(|r| r[c].parse::<f64>().is_ok());
        if is_number && name != "index" {
            numeric += 1;
            assert!(unit.is_some(), "numeric column {name} has no unit");
        }
    }
    assert!(numeric > 40, "{numeric} numeric columns");
    cleanup(&d);
}

#[test]
fn stage_sweep_columns_carry_units() {
    let case = root().join("cases/ruiz2019_stage_sweep.json");
    // --full: the platform compliance too.
    check_table(case.to_str().unwrap(), "stage", 4, &["--full"]);
}

#[test]
fn hinge_sweep_columns_carry_units() {
    let case = root().join("cases/ruiz2019_hinge_sweep.json");
    check_table(case.to_str().unwrap(), "hinge", 2, &[]);
}

/// Every number of the results of the bundled stage and hinge cases (linear, nonlinear,
/// modes, damping; plus a hinge with its large-rotation curve) has a declared unit.
#[test]
fn every_number_of_stage_and_hinge_results_has_a_unit() {
    let large_rotation = r#"{"analysis": "hinge", "material": "Al7075", "nonlinear": true,
        "hinge": {"type": "circular_notch", "R": 8, "t": 2, "w": 10, "h": 10, "blank_length": 5}}"#;
    let mut texts: Vec<(String, String)> = [
        "ruiz2019_stage.json",
        "ruiz2019_stage_modal.json",
        "ruiz2019_stage_nonlinear.json",
        "ruiz2019_stage_fatigue.json",
        "ruiz2019_hinge_revolute.json",
        "ruiz2019_hinge_spherical.json",
        "pantilt_hinge_damping.json",
    ]
    .iter()
    .map(|f| (f.to_string(), fs::read_to_string(root().join("cases").join(f)).unwrap()))
    .collect();
    texts.push(("large rotation".into(), large_rotation.into()));
    for (name, text) in texts {
        let case = flexfem::analysis::parse(&text).unwrap_or_else(|e| panic!("{name}: {e}"));
        let (unit_of, _) = of_kind(case.analysis()).unwrap();
        let out = flexfem::analysis::run(&case).unwrap_or_else(|e| panic!("{name}: {e}"));
        let mut count = 0;
        visit_leaves(&mut String::new(), &out.json, &mut |leaf: &str, v: &Value| {
            if v.is_number() {
                count += 1;
                let path: Vec<&str> = leaf.split('.').collect();
                assert!(unit_of(&path).is_some(), "{name}: {leaf} has no unit");
            }
        });
        assert!(count > 10, "{name}: {count} numbers");
    }
}
