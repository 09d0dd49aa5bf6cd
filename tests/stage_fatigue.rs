//! High-cycle fatigue of the 3-PRS stage's hinges (`"fatigue"` of a `stage` case): the
//! fatigue-limited stroke against a hand computation from the stage's own hinge stresses per
//! unit actuator force and the stress-life chain written out step by step after Budynas &
//! Nisbett, Shigley's Mechanical Engineering Design, 10th ed. (2015), ch. 6; the errors of the
//! block (exit 2 naming the JSON path).
//!
//! Stage: Ruiz et al. (2019), Al 7075-T6, revolute circular notch R = 8 mm, t = 2 mm in a
//! 10 × 10 leg, spherical neck t = 3 mm, R = 4 mm. From the result the hand computation takes
//! only what it cannot compute by hand: the peak stress of each hinge under a unit force on
//! every actuator (the stage's FE answer, K_t included), the strokes of that case, and the
//! notch factor K_t of each hinge's stress model. The tolerance `HAND_TOL` (1e-9 relative) is
//! far inside the 1 % the feature requires: both evaluate the same closed-form steps in
//! different code.

mod common;

/// Relative tolerance of the hand computations (they agree to ~1e-15).
const HAND_TOL: f64 = 1e-9;

fn stage_case(fatigue: &str, material: &str, extra: &str) -> String {
    format!(
        r#"{{"analysis": "stage", "material": {material},
            "stage": {{"L": 109.215, "b": 47.91, "alpha0_deg": 45, "gamma_deg": 0,
                "leg": {{"w": 10, "h": 10}},
                "revolute": {{"type": "circular_notch", "R": 8, "t": 2}},
                "spherical": {{"type": "spherical_neck", "l": 5, "t": 3, "R": 4}}{extra}}},
            "load_cases": [{{"name": "unit", "actuator_forces": [1, 1, 1]}},
                           {{"name": "F40", "actuator_forces": [40, 40, 40]}}],
            "fatigue": {fatigue}}}"#
    )
}

fn run_stage(fatigue: &str) -> serde_json::Value {
    let o = common::run_case_text("stage_fatigue", &stage_case(fatigue, "\"Al7075\"", ""));
    assert!(o.status.success(), "{}", common::stderr(&o));
    serde_json::from_slice(&o.stdout).unwrap()
}

fn rel(a: f64, b: f64) -> f64 {
    (a / b - 1.0).abs()
}

fn num(v: &serde_json::Value) -> f64 {
    v.as_f64().unwrap_or_else(|| panic!("not a number: {v}"))
}

/// The hand chain of one hinge kind: (K_f / K_t, S_e, S_f at `cycles`), with Peterson's q
/// for notch radius `r` (mm) and the bending equivalent diameter `d_e` (mm).
fn hand_chain(kt: f64, r: f64, d_e: f64, cycles: f64) -> (f64, f64, f64) {
    // Peterson's notch sensitivity, a = 0.635 mm for aluminium alloys.
    let q = 1.0 / (1.0 + 0.635 / r);
    // Fatigue notch factor, Shigley eq. (6-32).
    let kf = 1.0 + q * (kt - 1.0);
    // Marin surface factor, machined: k_a = 4.51 S_ut^−0.265, S_ut = 572 MPa (eq. 6-19).
    let ka = 4.51 * 572.0_f64.powf(-0.265);
    // Size factor in bending, eq. (6-20), d_e held to the equation's range 2.79 … 51 mm.
    let kb = 1.24 * d_e.clamp(2.79, 51.0).powf(-0.107);
    // k_c = k_d = k_e = 1; S_e' = 159 MPa at N_e = 5e8 (7075-T6, rotating beam).
    let se = ka * kb * 159.0;
    // Basquin line from 0.9 S_ut at 10³ cycles to S_e at 5e8 (Shigley §6-7, Fig. 6-18).
    let b = (159.0_f64 / (0.9 * 572.0)).log10() / (5e8_f64 / 1e3).log10();
    let sf = se * (cycles / 5e8_f64).min(1.0).powf(b);
    (kf / kt, se, sf)
}

#[test]
fn fatigue_limited_stroke_matches_shigley_chain_by_hand() {
    let cycles = 1e7;
    let r = run_stage(r#"{"cycles": 1e7, "load_ratio": 0, "method": "goodman"}"#);
    let lim = &r["at_fatigue_limit"];
    // Revolute: circular notch r = R = 8 mm, d_e = 0.808 √(t w) (eq. 6-25); spherical neck:
    // shoulder radius 4 mm, d_e = 0.370 t = 1.11 mm (eq. 6-24), clamped to 2.79 mm.
    let chains = [
        hand_chain(
            num(&lim["revolute"]["kt"]),
            8.0,
            0.808 * (2.0_f64 * 10.0).sqrt(),
            cycles,
        ),
        hand_chain(num(&lim["spherical"]["kt"]), 4.0, 0.370 * 3.0, cycles),
    ];
    for (k, name) in ["revolute", "spherical"].iter().enumerate() {
        let (_, se, sf) = chains[k];
        assert!(rel(num(&lim[name]["endurance_corrected"]), se) < HAND_TOL, "{name} S_e");
        assert!(rel(num(&lim[name]["strength_at_cycles"]), sf) < HAND_TOL, "{name} S_f");
    }
    // The unit case: peak stress per N of actuator force of each hinge, the stage's own.
    let unit = &r["load_cases"][0];
    let (mut worst, mut worst_inf) = (0.0_f64, 0.0_f64);
    for (k, name) in ["revolute", "spherical"].iter().enumerate() {
        let (kf_over_kt, se, sf) = chains[k];
        for leg in 0..3 {
            let sigma = num(&unit["hinge_stress"][name][leg]) * kf_over_kt;
            // R = 0: σ_a = σ_m = σ_max/2; modified Goodman (Shigley eq. 6-46).
            let (sa, sm) = (0.5 * sigma, 0.5 * sigma);
            let u = sa / sf + sm / 572.0;
            let got = num(&unit["fatigue"]["utilisation"][name][leg]);
            assert!(
                rel(got, u) < HAND_TOL,
                "{name} leg {leg}: utilisation {got} vs hand {u}"
            );
            worst = worst.max(u);
            worst_inf = worst_inf.max(sa / se + sm / 572.0);
        }
    }
    let strokes: Vec<f64> = unit["strokes"].as_array().unwrap().iter().map(num).collect();
    assert_eq!(strokes.len(), 3);
    let stroke = strokes.iter().sum::<f64>() / 3.0;
    let hand = stroke / worst;
    let got = num(&lim["stroke"]);
    assert!(
        rel(got, hand) < HAND_TOL,
        "fatigue-limited stroke {got} mm vs hand {hand} mm"
    );
    assert!(
        rel(num(&lim["force"]), 1.0 / worst) < HAND_TOL,
        "force at the fatigue limit"
    );
    let hand_inf = stroke / worst_inf;
    let got_inf = num(&lim["stroke_infinite_life"]);
    assert!(
        rel(got_inf, hand_inf) < HAND_TOL,
        "infinite life {got_inf} mm vs hand {hand_inf} mm"
    );
    // Beside the static stroke at the allowable stress (400 MPa): at 1e7 cycles of R = 0 the
    // fatigue limit is the smaller of the two for this stage.
    let stat = num(&r["at_allowable"]["stroke"]);
    assert!(got < stat, "fatigue-limited {got} mm vs static {stat} mm");
    // The linear stage scales: F40's utilisation is 40 × the unit case's.
    let u40 = num(&r["load_cases"][1]["fatigue"]["max_utilisation"]);
    assert!(
        rel(u40, 40.0 * worst) < HAND_TOL,
        "F40 utilisation {u40} vs {}",
        40.0 * worst
    );
}

#[test]
fn stage_fatigue_block_errors_name_the_path() {
    let goodman = r#"{"cycles": 1e7}"#;
    for (text, needles) in [
        (
            stage_case(goodman, r#"{"E": 3300, "nu": 0.33, "yield": 80, "allowable": 50}"#, ""),
            vec!["material.fatigue", "fatigue data"],
        ),
        (
            stage_case(r#"{"cycles": 1e7, "load_ratio": 1}"#, "\"Al7075\"", ""),
            vec!["fatigue.load_ratio", "[−1, 1)"],
        ),
        (
            stage_case(r#"{"cycles": 0.5}"#, "\"Al7075\"", ""),
            vec!["fatigue.cycles"],
        ),
        (
            stage_case(goodman, "\"Al7075\"", r#", "ideal_joints": true"#),
            vec!["fatigue", "ideal_joints"],
        ),
        (
            stage_case(r#"{"cycles": 1e7, "ratio": 0}"#, "\"Al7075\"", ""),
            vec!["ratio"],
        ),
    ] {
        let dir = common::tempdir("stage_fatigue_errors");
        let path = common::write(&dir, "case.json", &text);
        let p = path.to_str().unwrap();
        // `run` and `check` refuse alike.
        common::exits_2(&common::run(&["run", p]), &needles);
        common::exits_2(&common::run(&["check", p]), &needles);
        common::cleanup(&dir);
    }
}

/// A sweep over the revolute notch thickness lists the fatigue quantities as columns, each
/// design's equal to its own run (same code path, to the last bit: `TOL` 1e-12 relative).
#[test]
fn sweep_lines_carry_the_fatigue_limit_of_each_design() {
    const TOL: f64 = 1e-12;
    let d = common::tempdir("stage_fatigue_sweep");
    let fatigue = r#"{"cycles": 1e7, "load_ratio": 0}"#;
    let base = stage_case(fatigue, "\"Al7075\"", "");
    let sweep = format!(r#"{{"analysis": "sweep", "base": {base}, "vary": {{"stage.revolute.t": [1.5, 2]}}}}"#);
    let case = common::write(&d, "sweep.json", &sweep);
    let o = common::sweep(&d, &[case.to_str().unwrap()]);
    assert_eq!(o.status.code(), Some(0), "{}", common::stderr(&o));
    let lines = common::parse_lines(&common::stdout(&o));
    assert_eq!(lines.len(), 2);
    let single = run_stage(fatigue);
    let line = lines
        .iter()
        .find(|l| l["params"]["stage.revolute.t"].as_f64() == Some(2.0))
        .expect("the t = 2 design");
    for path in [
        ["at_fatigue_limit", "stroke"],
        ["at_fatigue_limit", "stroke_infinite_life"],
    ] {
        let (got, want) = (num(&line["result"][path[0]][path[1]]), num(&single[path[0]][path[1]]));
        assert!(rel(got, want) < TOL, "{path:?}: sweep {got} vs run {want}");
    }
    let u = num(&line["result"]["load_cases"][1]["fatigue"]["max_utilisation"]);
    let want = num(&single["load_cases"][1]["fatigue"]["max_utilisation"]);
    assert!(rel(u, want) < TOL, "F40 utilisation: sweep {u} vs run {want}");
    // The thinner notch (t = 1.5) is more compliant and less stressed per mm: a longer
    // fatigue-limited stroke.
    let thin = lines
        .iter()
        .find(|l| l["params"]["stage.revolute.t"].as_f64() == Some(1.5))
        .unwrap();
    assert!(num(&thin["result"]["at_fatigue_limit"]["stroke"]) > num(&line["result"]["at_fatigue_limit"]["stroke"]));
    common::cleanup(&d);
}

/// The Ruiz stage with the hinge dimensions `d` (keys t_rev, R_rev, t_sph, R_sph, l_sph, as a
/// `design` result lists them) and a fatigue block, as a `stage` case: one unit-force load case.
fn stage_with_design(d: &serde_json::Value, fatigue: &str) -> serde_json::Value {
    let text = format!(
        r#"{{"analysis": "stage", "material": "Al7075",
            "stage": {{"L": 109.215, "b": 47.91, "alpha0_deg": 45, "gamma_deg": 0,
                "leg": {{"w": 10, "h": 10}},
                "revolute": {{"type": "circular_notch", "R": {}, "t": {}}},
                "spherical": {{"type": "spherical_neck", "l": {}, "t": {}, "R": {}}}}},
            "load_cases": [{{"name": "unit", "actuator_forces": [1, 1, 1]}}],
            "fatigue": {fatigue}}}"#,
        d["R_rev"], d["t_rev"], d["l_sph"], d["t_sph"], d["R_sph"]
    );
    let o = common::run_case_text("stage_fatigue_design", &text);
    assert!(o.status.success(), "{}", common::stderr(&o));
    serde_json::from_slice(&o.stdout).unwrap()
}

/// `cases/ruiz2019_design_fatigue.json`: the stage sizing with a fatigue requirement (Ruiz et
/// al. (2019) §4 requirements, here
/// Δz ≥ ±1.5 mm, plus the same Δz at the fatigue limit of 10⁷ cycles of R = 0): the sized
/// stage, rerun as a plain `stage` case with that fatigue block, reaches z_travel at its
/// fatigue limit (to the 1e-6 at which the sizing's pure-z unit stroke and the stage's equal
/// unit forces agree for this symmetric stage), and the fatigue requirement is the binding
/// one — fatigue, not the 400 MPa static limit, sizes the hinges (measured: d_f = 1.5001 mm,
/// d = 1.936 mm at 400 MPa).
#[test]
fn sizing_with_a_fatigue_requirement_reaches_z_travel_at_the_fatigue_limit() {
    const AGREE: f64 = 1e-6;
    // `cases/ruiz2019_design_fatigue.json`'s cycle.
    let fatigue = r#"{"cycles": 1e7, "load_ratio": 0, "method": "goodman"}"#;
    let o = common::run(&["run", "cases/ruiz2019_design_fatigue.json"]);
    assert!(o.status.success(), "{}", common::stderr(&o));
    let v: serde_json::Value = serde_json::from_slice(&o.stdout).unwrap();
    assert_eq!(v["meets"], true, "{}", v["message"]);
    let zf = num(&v["responses"]["z_at_fatigue_limit"]);
    assert!(zf >= 1.5, "sized d_f {zf} mm");
    let binding: Vec<&str> = v["binding"]
        .as_array()
        .unwrap()
        .iter()
        .filter_map(|b| b.as_str())
        .collect();
    assert!(binding.contains(&"z_travel_fatigue"), "binding {binding:?}");
    assert!(!binding.contains(&"z_travel"), "binding {binding:?}");
    let d_static = num(&v["responses"]["z_at_allowable"]);
    assert!(d_static > 1.5 * 1.01, "static d {d_static} mm is not binding");
    // The design rerun as a `stage` case with the fatigue block.
    let s = stage_with_design(&v["design"], fatigue);
    let z = num(&s["at_fatigue_limit"]["z"]);
    assert!(
        rel(z, zf) < AGREE,
        "stage run z at the fatigue limit {z} vs sizing {zf}"
    );
    assert!(z >= 1.5 * (1.0 - AGREE), "stage run z at the fatigue limit {z} mm");
    assert!(rel(num(&s["at_allowable"]["z"]), d_static) < AGREE);
}

/// The stage sensitivity with a fatigue block: the base design's d_f is the `stage` case's
/// `at_fatigue_limit.z`, and the t_rev row's d_f ratio is that of two `stage` runs (base and
/// t_rev × 1.5), to the 1e-6 at which pure z and equal forces agree for this symmetric stage.
#[test]
fn sensitivity_fatigue_column_matches_stage_runs() {
    const AGREE: f64 = 1e-6;
    let fatigue = r#"{"cycles": 1e7, "load_ratio": 0}"#;
    let text = format!(
        r#"{{"analysis": "sensitivity", "material": "Al7075",
            "stage": {{"L": 109.215, "b": 47.91, "alpha0_deg": 45, "gamma_deg": 0,
                "leg": {{"w": 10, "h": 10}},
                "revolute": {{"type": "circular_notch", "R": 8, "t": 2}},
                "spherical": {{"type": "spherical_neck", "l": 5, "t": 3, "R": 4}}}},
            "increment": 0.5, "fatigue": {fatigue}}}"#
    );
    let o = common::run_case_text("stage_sensitivity_fatigue", &text);
    assert!(o.status.success(), "{}", common::stderr(&o));
    let v: serde_json::Value = serde_json::from_slice(&o.stdout).unwrap();
    let base = serde_json::json!({"t_rev": 2, "R_rev": 8, "t_sph": 3, "R_sph": 4, "l_sph": 5});
    let z0 = num(&stage_with_design(&base, fatigue)["at_fatigue_limit"]["z"]);
    let got = num(&v["base"]["z_at_fatigue_limit"]);
    assert!(rel(got, z0) < AGREE, "base d_f {got} vs stage run {z0}");
    let thick = serde_json::json!({"t_rev": 3, "R_rev": 8, "t_sph": 3, "R_sph": 4, "l_sph": 5});
    let z1 = num(&stage_with_design(&thick, fatigue)["at_fatigue_limit"]["z"]);
    let rows = v["rows"].as_array().unwrap();
    assert_eq!(rows.len(), 5);
    let row = rows.iter().find(|r| r["parameter"] == "t_rev").unwrap();
    let ratio = num(&row["fatigue_displacement_ratio"]);
    assert!(rel(ratio, z1 / z0) < AGREE, "t_rev d_f ratio {ratio} vs {}", z1 / z0);
    assert!(row["bins"]["fatigue_displacement"].is_string(), "{row}");
    // Without the block the rows carry no fatigue column.
    let plain = common::run_case_text(
        "stage_sensitivity_plain",
        &text.replace(&format!(", \"fatigue\": {fatigue}"), ""),
    );
    assert!(plain.status.success(), "{}", common::stderr(&plain));
    let p: serde_json::Value = serde_json::from_slice(&plain.stdout).unwrap();
    assert!(
        p["rows"][0].get("fatigue_displacement_ratio").is_none(),
        "{}",
        p["rows"][0]
    );
    assert!(p["base"].get("z_at_fatigue_limit").is_none(), "{}", p["base"]);
}

/// A fatigue requirement of the sizing, and a sensitivity's fatigue block, are checked like the
/// stage's block: exit 2 naming the path, by `run` and `check` alike.
#[test]
fn sizing_fatigue_errors_name_the_path() {
    let stage = r#""stage": {"L": 109.215, "b": 47.91, "alpha0_deg": 45, "gamma_deg": 0,
        "leg": {"w": 10, "h": 10}, "revolute": {"type": "circular_notch", "R": 8, "t": 2},
        "spherical": {"type": "spherical_neck", "l": 5, "t": 3, "R": 4}}"#;
    let bounds = r#""bounds": {"t_rev": [1, 3], "R_rev": [3, 12], "t_sph": [2, 4], "R_sph": [2, 6], "l_sph": [2, 10]}"#;
    let no_data = r#"{"E": 72000, "nu": 0.33, "yield": 503, "allowable": 400}"#;
    for (text, needles) in [
        (
            format!(
                r#"{{"analysis": "design", "material": "Al7075", {stage}, {bounds},
                    "requirements": {{"z_travel": 1.5, "fatigue": {{"cycles": 0.5}}}}}}"#
            ),
            vec!["requirements.fatigue.cycles"],
        ),
        (
            format!(
                r#"{{"analysis": "design", "material": {no_data}, {stage}, {bounds},
                    "requirements": {{"z_travel": 1.5, "fatigue": {{"cycles": 1e7}}}}}}"#
            ),
            vec!["material.fatigue", "fatigue data"],
        ),
        (
            format!(
                r#"{{"analysis": "sensitivity", "material": "Al7075", {stage},
                    "fatigue": {{"cycles": 1e7, "load_ratio": 1}}}}"#
            ),
            vec!["fatigue.load_ratio", "[−1, 1)"],
        ),
    ] {
        let dir = common::tempdir("sizing_fatigue_errors");
        let path = common::write(&dir, "case.json", &text);
        let p = path.to_str().unwrap();
        common::exits_2(&common::run(&["run", p]), &needles);
        common::exits_2(&common::run(&["check", p]), &needles);
        common::cleanup(&dir);
    }
}
