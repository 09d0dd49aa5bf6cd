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
    65.9516766641438,
    2.0432168784249516,
    0.9478515120223568,
    195.7697218654276,
    185.56062687834182,
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
        [2.12393736622742, 0.8715302667951496, 0.9836139081270512],
        ["> 1.5", "0.8-1", "0.8-1"],
        [1.7432245046389554, -0.3937429864603796, -0.19654328450000721],
    ),
    (
        "R_rev",
        8.0,
        12.0,
        [0.8746592240613905, 1.070512573076535, 1.198017766538981],
        ["0.8-1", "1-1.2", "1-1.2"],
        [-0.32924269237558473, 0.4772297054135042, 0.43940747188301],
    ),
    (
        "t_sph",
        3.0,
        4.5,
        [1.8708058328842307, 0.8548852767127516, 1.1921492892653545],
        ["> 1.5", "0.8-1", "1-1.2"],
        [0.9778447860600862, -0.04367752509376266, 0.4443291905493245],
    ),
    (
        "R_sph",
        4.0,
        6.0,
        [0.9810842568364212, 1.001342093403399, 0.9318866481982314],
        ["0.8-1", "1-1.2", "0.8-1"],
        [-0.042945589581306495, 0.0028420427329322144, -0.15944586352146697],
    ),
    (
        "l_sph",
        5.0,
        7.5,
        [0.939182892165041, 1.0045869945827308, 0.8382471168920418],
        ["0.8-1", "1-1.2", "0.8-1"],
        [-0.1545608092578141, 0.009548814122002003, -0.5198845037590735],
    ),
];

/// The design found: t_rev, R_rev, t_sph, R_sph, l_sph, mm.
const DESIGN: [(&str, f64); 5] = [
    ("t_rev", 2.2752470389873505),
    ("R_rev", 12.0),
    ("t_sph", 4.0),
    ("R_sph", 4.636536158206359),
    ("l_sph", 8.279082228778009),
];
const DESIGN_RESPONSES: [f64; 7] = [
    91.22721350177613,
    2.3331633590191716,
    0.9686362976250917,
    171.44106024712914,
    166.06403385869947,
    399.9950141169536,
    399.84334351544015,
];
/// Constraint values: z_travel, T_min, T_max, revolute and spherical rotation stress.
const DESIGN_CONSTRAINTS: [(&str, f64, f64); 5] = [
    ("z_travel", 2.3331633590191716, -0.1665816795095858),
    ("T_min", 0.9686362976250917, -0.21079537203136461),
    ("T_max", 0.9686362976250917, -0.19280308531242352),
    ("revolute_rotation_stress", 399.9950141169536, -1.246470761600449e-05),
    ("spherical_rotation_stress", 399.84334351544015, -0.00039164121139961594),
];
const DESIGN_BINDING: [&str; 2] = ["revolute_rotation_stress", "spherical_rotation_stress"];
const DESIGN_EVALUATIONS: u64 = 829;
const DESIGN_HISTORY_LEN: usize = 302;
/// The last local-search step: parameters, η, d, T, largest violation.
const DESIGN_LAST_STEP: ([f64; 5], [f64; 4]) = (
    [2.2758525303195176, 12.0, 4.0, 4.636346879423911, 8.279281969515907],
    [
        91.26218845069828,
        2.332919978620828,
        0.9685769329203846,
        0.00012645516813847735,
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
