//! The stage's sensitivity and design loops, pinned at the numbers they gave before they were
//! moved onto the generic design-problem machinery (`flexfem::problem`): regression, not accuracy.
//!
//! The constants are the outputs of `cases/ruiz2019_sensitivity.json` and
//! `cases/ruiz2019_design.json` on main before the move (the same numbers as their goldens in
//! `tests/golden/`), re-pinned after intended model changes (the torsion corrections
//! of `hinge::torsion::solid_torsion_stiffness` and the corner-filleted K_t; then Benscoter's
//! warping shear in that torsion, which moved them by at most 1e-6 relative; then the bending's
//! load spreading for its warping constant, at most 2.5e-6; then the axial modulus's solid factors
//! G and P_a, at most 2e-6);
//! Table 1 of Ruiz et al. (2019) itself is asserted in `tests/design.rs`.

mod common;
use common::*;

/// Relative tolerance of the pins: the generic code keeps the stage's arithmetic order, so the
/// numbers agree to rounding (the goldens check them byte for byte).
const REGRESSION_TOL: f64 = 1e-9;

fn close(got: f64, want: f64, what: &str) {
    let err = (got - want).abs() / want.abs().max(1e-300);
    assert!(
        err <= REGRESSION_TOL,
        "{what}: {got} vs {want} (relative error {err:e})"
    );
}

fn num(v: &serde_json::Value, what: &str) -> f64 {
    v.as_f64().unwrap_or_else(|| panic!("{what} is not a number: {v}"))
}

/// Responses of the base design: η, d, T, σ_rev/mm, σ_sph/mm, σ_rev at demand, σ_sph at demand.
const RESPONSE_KEYS: [&str; 7] = [
    "eta",
    "z_at_allowable",
    "T",
    "revolute_stress_per_mm",
    "spherical_stress_per_mm",
    "revolute_stress_at_demand",
    "spherical_stress_at_demand",
];

const SENS_BASE: [f64; 7] = [
    65.95167666413796,
    2.0432168784252074,
    0.9478515120224659,
    195.7697218654031,
    185.56062687833995,
    459.1499425620975,
    445.9877596273485,
];

/// Rows of Table 1: (parameter, base, increased, [η, d, T] ratios, bins, elasticities).
#[allow(clippy::type_complexity)]
const SENS_ROWS: [(&str, f64, f64, [f64; 3], [&str; 3], [f64; 3]); 5] = [
    (
        "t_rev",
        2.0,
        3.0,
        [2.1239373662274654, 0.8715302667950112, 0.9836139081269286],
        ["> 1.5", "0.8-1", "0.8-1"],
        [1.743224504630962, -0.39374298645404043, -0.1965432844923289],
    ),
    (
        "R_rev",
        8.0,
        12.0,
        [0.8746592240614404, 1.0705125730763398, 1.1980177665388365],
        ["0.8-1", "1-1.2", "1-1.2"],
        [-0.3292426923877968, 0.4772297054167348, 0.43940747188645085],
    ),
    (
        "t_sph",
        3.0,
        4.5,
        [1.8708058328841666, 0.854885276712627, 1.1921492892654537],
        ["> 1.5", "0.8-1", "1-1.2"],
        [0.9778447860647045, -0.0436775251089167, 0.4443291905377987],
    ),
    (
        "R_sph",
        4.0,
        6.0,
        [0.9810842568365871, 1.0013420934030781, 0.9318866481979362],
        ["0.8-1", "1-1.2", "0.8-1"],
        [-0.04294558957651049, 0.00284204273923252, -0.1594458635150546],
    ),
    (
        "l_sph",
        5.0,
        7.5,
        [0.9391828921652722, 1.0045869945827173, 0.8382471168920325],
        ["0.8-1", "1-1.2", "0.8-1"],
        [-0.1545608092720689, 0.009548814110134116, -0.5198845037762071],
    ),
];

/// The design found: t_rev, R_rev, t_sph, R_sph, l_sph, mm.
const DESIGN: [(&str, f64); 5] = [
    ("t_rev", 2.275247038614375),
    ("R_rev", 12.0),
    ("t_sph", 4.0),
    ("R_sph", 4.636536153855395),
    ("l_sph", 8.279082230609088),
];
const DESIGN_RESPONSES: [f64; 7] = [
    91.22721347923832,
    2.3331633591701633,
    0.9686362976537841,
    171.44106023603428,
    166.06403385287163,
    399.9950140827237,
    399.84334351372945,
];
/// Constraint values: z_travel, T_min, T_max, revolute and spherical rotation stress.
const DESIGN_CONSTRAINTS: [(&str, f64, f64); 5] = [
    ("z_travel", 2.3331633591701633, -0.16658167958508163),
    ("T_min", 0.9686362976537841, -0.2107953720672301),
    ("T_max", 0.9686362976537841, -0.1928030852885132),
    ("revolute_rotation_stress", 399.9950140827237, -1.2464793190787304e-05),
    ("spherical_rotation_stress", 399.84334351372945, -0.0003916412156763727),
];
const DESIGN_BINDING: [&str; 2] = ["revolute_rotation_stress", "spherical_rotation_stress"];
const DESIGN_EVALUATIONS: u64 = 829;
const DESIGN_HISTORY_LEN: usize = 302;
/// The last local-search step: parameters, η, d, T, largest violation.
const DESIGN_LAST_STEP: ([f64; 5], [f64; 4]) = (
    [2.2758525309541775, 12.0, 4.0, 4.636346875013006, 8.27928197132402],
    [
        91.26218848710116,
        2.3329199783660464,
        0.9685769328668665,
        0.00012645531374616325,
    ],
);

/// `cases/ruiz2019_sensitivity.json`: every ratio, bin and elasticity of Table 1 and the base
/// responses as before the move onto the generic machinery.
#[test]
fn stage_sensitivity_matches_the_numbers_before_the_generic_machinery() {
    let out = run(&["run", "cases/ruiz2019_sensitivity.json"]);
    assert_eq!(out.status.code(), Some(0), "{}", stderr(&out));
    let v: serde_json::Value = serde_json::from_str(&stdout(&out)).unwrap();
    // zip-checked: both are [_; 7] constants (the compiler checks their lengths).
    for (k, want) in RESPONSE_KEYS.iter().zip(SENS_BASE) {
        close(num(&v["base"][k], k), want, &format!("base.{k}"));
    }
    let rows = v["rows"].as_array().unwrap();
    assert_eq!(rows.len(), SENS_ROWS.len(), "one row per parameter");
    // zip-checked: lengths asserted just above.
    for (row, (p, base, inc, ratios, bins, el)) in rows.iter().zip(SENS_ROWS) {
        assert_eq!(row["parameter"], p);
        close(num(&row["base"], "base"), base, &format!("{p} base"));
        close(num(&row["increased"], "increased"), inc, &format!("{p} increased"));
        let got = ["stiffness_ratio", "displacement_ratio", "stress_ratio_ratio"].map(|k| num(&row[k], k));
        for i in 0..3 {
            close(got[i], ratios[i], &format!("{p} ratio {i}"));
            close(
                num(&row["elasticity"][i], "elasticity"),
                el[i],
                &format!("{p} elasticity {i}"),
            );
        }
        let got_bins = ["stiffness", "displacement", "stress_ratio"]
            .map(|k| row["bins"][k].as_str().unwrap_or_default().to_string());
        assert_eq!(got_bins, bins.map(str::to_string), "{p} bins");
    }
}

/// `cases/ruiz2019_design.json`: the design found, its responses and constraints, the binding
/// set, the number of evaluations and the search history as before the move.
#[test]
fn stage_design_matches_the_numbers_before_the_generic_machinery() {
    let out = run(&["run", "cases/ruiz2019_design.json"]);
    assert_eq!(out.status.code(), Some(0), "{}", stderr(&out));
    let v: serde_json::Value = serde_json::from_str(&stdout(&out)).unwrap();
    assert_eq!(v["meets"], true);
    for (k, want) in DESIGN {
        close(num(&v["design"][k], k), want, &format!("design.{k}"));
    }
    // zip-checked: both are [_; 7] constants (the compiler checks their lengths).
    for (k, want) in RESPONSE_KEYS.iter().zip(DESIGN_RESPONSES) {
        close(num(&v["responses"][k], k), want, &format!("responses.{k}"));
    }
    let cons = v["constraints"].as_array().unwrap();
    assert_eq!(cons.len(), DESIGN_CONSTRAINTS.len());
    // zip-checked: lengths asserted just above.
    for (c, (name, value, violation)) in cons.iter().zip(DESIGN_CONSTRAINTS) {
        assert_eq!(c["name"], name);
        close(num(&c["value"], name), value, &format!("{name} value"));
        close(num(&c["violation"], name), violation, &format!("{name} violation"));
    }
    assert_eq!(v["binding"], serde_json::json!(DESIGN_BINDING));
    assert_eq!(v["evaluations"].as_u64(), Some(DESIGN_EVALUATIONS));
    let history = v["history"].as_array().unwrap();
    assert_eq!(history.len(), DESIGN_HISTORY_LEN);
    let last = history.last().unwrap();
    for (i, want) in DESIGN_LAST_STEP.0.iter().enumerate() {
        close(
            num(&last["params"][i], "params"),
            *want,
            &format!("last step parameter {i}"),
        );
    }
    for (k, want) in ["eta", "z_at_allowable", "T", "max_violation"]
        .iter()
        .zip(DESIGN_LAST_STEP.1)
    {
        close(num(&last[k], k), want, &format!("last step {k}"));
    }
}
