//! Crashes and unbounded runs that passed `check` (issue 29): Craig–Bampton with no interior
//! and no modes, Craig–Bampton, `frf` and `buckling` over the size and memory limits, an
//! absurd `--shard` count, more `modes` than the model has, and FRF ports on fixed DOFs. Each
//! input now either runs correctly or is refused with exit 2 naming its JSON path; none exits
//! 101 — all through the real binary, as `tests/cli.rs`.

mod common;
use common::*;
use serde_json::{json, Value};
use std::process::{Command, Output};

/// A steel chain of `n` nodes 1 mm apart along x (1 × 1 mm beams), `extra` fields merged in.
fn chain(n: usize, extra: Value) -> Value {
    let nodes: Vec<Value> = (0..n).map(|i| json!([i as f64, 0, 0])).collect();
    let elements: Vec<Value> = (1..n)
        .map(|i| json!({"type": "beam", "nodes": [i - 1, i], "section": "sq", "material": "s", "up": [0, 0, 1]}))
        .collect();
    let mut c = json!({
        "materials": {"s": {"E": 210000, "nu": 0.3, "density": 7.85e-9}},
        "sections": {"sq": {"shape": "rect", "w": 1, "h": 1}},
        "nodes": nodes,
        "elements": elements
    });
    for (k, v) in extra.as_object().unwrap() {
        c[k] = v.clone();
    }
    c
}

/// `flexfem CMD case.json` in a fresh directory, with `FLEXFEM_LIMITS` set when given.
fn flexfem(name: &str, cmd: &str, case: &Value, limits: Option<&str>) -> Output {
    let d = tempdir(name);
    let p = d.join("case.json");
    std::fs::write(&p, case.to_string()).unwrap();
    let mut c = Command::new(bin());
    c.args([cmd, p.to_str().unwrap()]).current_dir(&d);
    match limits {
        Some(l) => c.env("FLEXFEM_LIMITS", l),
        None => c.env_remove("FLEXFEM_LIMITS"),
    };
    c.output().unwrap()
}

#[test]
fn craig_bampton_with_only_interface_equations_is_the_static_condensation() {
    // Both nodes of one free beam are the interface and no modes are kept: there is no
    // interior, so the superelement is the beam itself. Its axial stiffness K[0][0] = EA/L =
    // 210000 · 1 / 1 = 210000 N/mm (it was an eigen-decomposition of an empty matrix).
    let c = chain(2, json!({"analysis": "craig_bampton", "interface": [0, 1], "modes": 0}));
    exits(&flexfem("cb_empty_check", "check", &c, None), 0, &[]);
    let o = flexfem("cb_empty_run", "run", &c, None);
    exits(&o, 0, &[]);
    let r: Value = serde_json::from_slice(&o.stdout).unwrap();
    let k = r["k"].as_array().unwrap();
    assert_eq!(k.len(), 12);
    let kxx = k[0][0].as_f64().unwrap();
    assert!((kxx - 210000.0).abs() < 1e-9 * 210000.0, "{kxx}");
    assert_eq!(r["fixed_interface_frequencies_hz"], json!([]));
}

#[test]
fn craig_bampton_over_the_memory_limit_is_refused_at_check() {
    // 201 interface nodes: 1206 boundary equations, dense K and M of the superelement and its
    // eigen-decomposition need about 0.3 GiB, over a 0.05 GiB limit.
    let all: Vec<usize> = (0..201).collect();
    let c = chain(201, json!({"analysis": "craig_bampton", "interface": all, "modes": 0}));
    for cmd in ["check", "run"] {
        let o = flexfem(&format!("cb_mem_{cmd}"), cmd, &c, Some("memory_gib=0.05"));
        exits_2(
            &o,
            &[
                "`interface`",
                "1206 boundary equations",
                "memory_gib",
                "over the limit of",
            ],
        );
    }
}

#[test]
fn craig_bampton_over_the_dense_size_is_refused_at_check() {
    // 3001 interface nodes: 18006 boundary equations (a dense 18006² K and M: it aborted on
    // allocation), over the 3000 coordinates the dense superelement takes.
    let all: Vec<usize> = (0..3001).collect();
    let c = chain(3001, json!({"analysis": "craig_bampton", "interface": all, "modes": 0}));
    exits_2(
        &flexfem("cb_size", "check", &c, None),
        &["`interface`", "18006 boundary equations", "at most 3000"],
    );
}

#[test]
fn craig_bampton_with_more_modes_than_the_interior_is_refused_at_check() {
    // A 4-node chain clamped at node 0 with interface node 3: the interior (nodes 1, 2) has 12
    // equations, so at most 12 fixed-interface modes.
    let c = chain(
        4,
        json!({"analysis": "craig_bampton", "interface": [3], "modes": 13,
               "supports": [{"node": 0, "fix": ["ux", "uy", "uz", "rx", "ry", "rz"]}]}),
    );
    exits_2(&flexfem("cb_modes", "check", &c, None), &["`modes`", "at most 12"]);
}

#[test]
fn craig_bampton_interface_node_without_equations_is_refused_at_check() {
    // Node 0 is clamped: no equation to keep on the interface (`run` refused it with exit 1
    // after `check` passed).
    let c = chain(
        4,
        json!({"analysis": "craig_bampton", "interface": [3, 0], "modes": 0,
               "supports": [{"node": 0, "fix": ["ux", "uy", "uz", "rx", "ry", "rz"]}]}),
    );
    exits_2(
        &flexfem("cb_bare", "check", &c, None),
        &["`interface[1]`", "has no equations"],
    );
}

#[test]
fn frf_and_buckling_apply_the_modal_memory_estimate() {
    // 1000 modes of a 2001-node chain: modal refused these at once under a 0.05 GiB limit,
    // frf and buckling ran past two minutes.
    let clamp = json!([{"node": 0, "fix": ["ux", "uy", "uz", "rx", "ry", "rz"]}]);
    let frf = chain(
        2001,
        json!({"analysis": "frf", "modes": 1000, "supports": clamp,
               "frequencies": {"from_hz": 1, "to_hz": 100, "points": 3},
               "inputs": [{"node": 2000, "force": [0, 1, 0]}],
               "outputs": [{"node": 2000, "dofs": ["uy"]}]}),
    );
    let buckling = chain(
        2001,
        json!({"analysis": "buckling", "modes": 1000, "supports": clamp,
               "load_cases": [{"name": "push", "forces": [{"node": 2000, "F": [-1, 0, 0, 0, 0, 0]}]}]}),
    );
    for (name, c) in [("frf", &frf), ("buckling", &buckling)] {
        for cmd in ["check", "run"] {
            let o = flexfem(&format!("{name}_mem_{cmd}"), cmd, c, Some("memory_gib=0.05"));
            exits_2(&o, &["`modes`", "2001 nodes", "memory_gib"]);
        }
    }
}

#[test]
fn an_absurd_shard_count_runs_the_first_design() {
    // Shard 1/(2⁶⁴ − 1) of the 55-design bundled sweep holds design 0 only; the count of its
    // designs overflowed to 0 and the sweep exited 0 having run nothing.
    let d = tempdir("absurd_shard");
    let case = root().join("cases/ruiz2019_hinge_sweep.json");
    let out = d.join("s.jsonl");
    let o = sweep(
        &d,
        &[
            case.to_str().unwrap(),
            "--shard",
            "1/18446744073709551615",
            "--out",
            out.to_str().unwrap(),
        ],
    );
    exits(&o, 0, &[]);
    assert_eq!(summary(&o), [1, 0, 1, 0]);
    let lines = parse_lines(&std::fs::read_to_string(&out).unwrap());
    assert_eq!(lines.len(), 1);
    assert_eq!(lines[0]["index"], json!(0));
    // Shard K holds design K − 1 alone: 56 holds none of the 55.
    for (k, count) in [(55, 1), (56, 0)] {
        let o = sweep(
            &d,
            &[case.to_str().unwrap(), "--shard", &format!("{k}/18446744073709551615")],
        );
        exits(&o, 0, &[]);
        assert_eq!(summary(&o)[2], count, "shard {k}");
    }
}

/// A 1 kg (1e-3 t) point mass on a grounded 6-DOF spring: 6 equations, 6 modes.
fn sdof(analysis: &str, extra: Value) -> Value {
    let mut c = json!({
        "analysis": analysis,
        "nodes": [[0, 0, 0]],
        "elements": [
            {"type": "spring", "nodes": [0], "k": [1000, 2000, 3000, 4000, 5000, 6000]},
            {"type": "mass", "node": 0, "mass": 0.001, "inertia": [1, 2, 3]}
        ]
    });
    for (k, v) in extra.as_object().unwrap() {
        c[k] = v.clone();
    }
    c
}

fn frf_ports(extra: Value) -> Value {
    let mut c = sdof(
        "frf",
        json!({"modes": 6, "frequencies": {"from_hz": 10, "to_hz": 400, "points": 3},
               "inputs": [{"node": 0, "force": [1, 0, 0]}],
               "outputs": [{"node": 0, "dofs": ["ux", "uy"]}]}),
    );
    for (k, v) in extra.as_object().unwrap() {
        c[k] = v.clone();
    }
    c
}

#[test]
fn more_modes_than_the_model_has_are_computed_with_a_warning() {
    // 20 modes asked of a model with 6 equations: the 6 there are, and a warning saying so
    // (the modes were cut silently). The lowest is the rz mode, √(6000/3)/2π = 7.1176 Hz.
    for (analysis, extra) in [
        ("modal", json!({"modes": 20})),
        (
            "frf",
            json!({"modes": 20, "frequencies": {"from_hz": 10, "to_hz": 400, "points": 3},
                       "inputs": [{"node": 0, "force": [1, 0, 0]}], "outputs": [{"node": 0, "dofs": ["ux"]}]}),
        ),
    ] {
        let o = flexfem(&format!("modes_{analysis}"), "run", &sdof(analysis, extra), None);
        exits(&o, 0, &[]);
        let r: Value = serde_json::from_slice(&o.stdout).unwrap();
        let modes = r["modes"].as_array().unwrap();
        assert_eq!(modes.len(), 6, "{analysis}");
        let f1 = modes[0]["frequency_hz"].as_f64().unwrap();
        let exact = (6000.0f64 / 3.0).sqrt() / (2.0 * std::f64::consts::PI);
        assert!((f1 - exact).abs() < 1e-9 * exact, "{analysis}: {f1} vs {exact}");
        let w = r["warnings"].to_string();
        assert!(w.contains("20 asked for") && w.contains("only 6"), "{analysis}: {w}");
    }
}

#[test]
fn frf_ports_on_fixed_dofs_are_refused_at_check() {
    let fixed = json!([{"node": 0, "fix": ["ux", "uy"]}]);
    // The input pushes only along the fixed ux: a silent zero response before.
    let c = frf_ports(json!({"supports": fixed, "outputs": [{"node": 0, "dofs": ["uz"]}]}));
    exits_2(
        &flexfem("frf_in_fixed", "check", &c, None),
        &["`inputs[0].node`", "supports fix"],
    );
    // The second output DOF, uy, is fixed.
    let c = frf_ports(json!({"supports": [{"node": 0, "fix": ["uy"]}]}));
    for cmd in ["check", "run"] {
        exits_2(
            &flexfem(&format!("frf_out_fixed_{cmd}"), cmd, &c, None),
            &["`outputs[0].dofs[1]`", "value uy"],
        );
    }
    // A free DOF is accepted.
    exits(&flexfem("frf_ok", "check", &frf_ports(json!({})), None), 0, &[]);
}
