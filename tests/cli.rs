//! The command line: exit codes, error messages naming JSON paths, bundled cases.

mod common;
use common::*;

/// Each malformed case must exit 2 (bad case file) with a message naming the JSON path, and
/// must not panic.
#[test]
fn malformed_cases_exit_2_and_name_the_path() {
    let good = r#""mechanism": {"L": 109.215, "b": 47.91, "alpha0_deg": 45}"#;
    let cases: Vec<(&str, String, &str)> = vec![
        ("not json", "{ this is not json".into(), "not valid JSON"),
        ("not an object", "[1, 2, 3]".into(), "must be a JSON object"),
        ("missing analysis", format!("{{{good}, \"fkp\": [{{\"s\": [0,0,0]}}]}}"), "`analysis`"),
        ("unknown analysis", format!("{{\"analysis\": \"kinemaitcs\", {good}}}"), "`analysis`"),
        ("analysis wrong type", format!("{{\"analysis\": 3, {good}}}"), "`analysis`"),
        ("unknown top field", format!("{{\"analysis\": \"kinematics\", {good}, \"fkp\": [], \"colour\": 1}}"), "colour"),
        ("unknown nested field", r#"{"analysis": "kinematics", "mechanism": {"L": 109.215, "b": 47.91, "alpha0_deg": 45, "c": 1}, "ikp": [{}]}"#.into(), "`mechanism.c`"),
        ("missing L", r#"{"analysis": "kinematics", "mechanism": {"b": 47.91, "alpha0_deg": 45}, "ikp": [{}]}"#.into(), "`mechanism`"),
        ("L wrong type", r#"{"analysis": "kinematics", "mechanism": {"L": "long", "b": 47.91, "alpha0_deg": 45}, "ikp": [{}]}"#.into(), "`mechanism.L`"),
        ("negative L", r#"{"analysis": "kinematics", "mechanism": {"L": -109.2, "b": 47.91, "alpha0_deg": 45}, "ikp": [{}]}"#.into(), "`mechanism.L`"),
        ("zero b", r#"{"analysis": "kinematics", "mechanism": {"L": 109.2, "b": 0, "alpha0_deg": 45}, "ikp": [{}]}"#.into(), "`mechanism.b`"),
        ("alpha0 out of range", r#"{"analysis": "kinematics", "mechanism": {"L": 109.2, "b": 47.91, "alpha0_deg": 95}, "ikp": [{}]}"#.into(), "`mechanism.alpha0_deg`"),
        ("L too short to reach", r#"{"analysis": "kinematics", "mechanism": {"L": 20, "b": 47.91, "a": 125}, "ikp": [{}]}"#.into(), "`mechanism.L`"),
        ("both alpha0 and a", r#"{"analysis": "kinematics", "mechanism": {"L": 109.2, "b": 47.91, "a": 125, "alpha0_deg": 45}, "ikp": [{}]}"#.into(), "`mechanism`"),
        ("gamma out of range", r#"{"analysis": "kinematics", "mechanism": {"L": 109.2, "b": 47.91, "alpha0_deg": 45, "gamma_deg": 120}, "ikp": [{}]}"#.into(), "`mechanism.gamma_deg`"),
        ("strokes wrong length", format!("{{\"analysis\": \"kinematics\", {good}, \"fkp\": [{{\"s\": [1, 2]}}]}}"), "`fkp[0].s`"),
        ("stroke wrong type", format!("{{\"analysis\": \"kinematics\", {good}, \"fkp\": [{{\"s\": [0, 0, 0]}}, {{\"s\": [1, null, 2]}}]}}"), "`fkp[1].s[1]`"),
        ("ikp wrong type", format!("{{\"analysis\": \"kinematics\", {good}, \"ikp\": {{\"z\": 1}}}}"), "`ikp`"),
        ("reversed range", format!("{{\"analysis\": \"kinematics\", {good}, \"workspace\": {{\"z\": [2, -2], \"psi_deg\": [0, 0], \"theta_deg\": [0, 0]}}}}"), "`workspace.z`"),
        ("steps too few", format!("{{\"analysis\": \"kinematics\", {good}, \"workspace\": {{\"z\": [-2, 2], \"psi_deg\": [0, 0], \"theta_deg\": [0, 0], \"steps\": 1}}}}"), "`workspace.steps`"),
        ("steps negative", format!("{{\"analysis\": \"kinematics\", {good}, \"workspace\": {{\"z\": [-2, 2], \"psi_deg\": [0, 0], \"theta_deg\": [0, 0], \"steps\": -3}}}}"), "`workspace.steps`"),
        ("nothing to do", format!("{{\"analysis\": \"kinematics\", {good}}}"), "nothing to do"),
        ("huge stroke", format!("{{\"analysis\": \"kinematics\", {good}, \"fkp\": [{{\"s\": [0, 1e9, 0]}}]}}"), "`fkp[0].s[1]`"),
    ];
    assert!(cases.len() >= 12);
    for (name, text, needle) in cases {
        let out = run_case_text(&name.replace(' ', "_"), &text);
        let err = stderr(&out);
        assert_eq!(
            out.status.code(),
            Some(2),
            "{name}: exit {:?}, stderr {err}",
            out.status.code()
        );
        assert!(err.contains(needle), "{name}: stderr does not name {needle}: {err}");
        assert!(!err.contains("panicked"), "{name} panicked: {err}");
        assert!(stdout(&out).is_empty(), "{name}: printed a result");
        // `check` agrees with `run` on every bad case.
        let d = tempdir(&format!("check_{}", name.replace(' ', "_")));
        std::fs::write(d.join("c.json"), &text).unwrap();
        let chk = run_in(&d, &["check", "c.json"]);
        assert_eq!(chk.status.code(), Some(2), "check {name}: {}", stderr(&chk));
    }
}

#[test]
fn missing_case_file_exits_2() {
    let out = run(&["run", "no/such/case.json"]);
    assert_eq!(out.status.code(), Some(2));
    assert!(stderr(&out).contains("cannot read case file"));
}

#[test]
fn unreachable_strokes_exit_1_with_context() {
    // A valid file whose FKP has no solution is a failed analysis (exit 1), not a bad file.
    let out = run_case_text(
        "unreachable",
        r#"{"analysis": "kinematics", "mechanism": {"L": 109.215, "b": 47.91, "alpha0_deg": 45}, "fkp": [{"s": [0, 0, 0]}, {"s": [100, -100, 0]}]}"#,
    );
    let err = stderr(&out);
    assert_eq!(out.status.code(), Some(1), "{err}");
    assert!(err.contains("fkp[1]") && !err.contains("NaN"), "{err}");
}

#[test]
fn bundled_kinematics_case_prints_table4_fkp_column() {
    // Ruiz et al. (2019) Table 4 FKP column: Δz = 1384, 722, −631, −1511 µm (to 2 µm).
    let out = run(&["run", "cases/ruiz2019_kinematics.json"]);
    assert_eq!(out.status.code(), Some(0), "{}", stderr(&out));
    let v: serde_json::Value = serde_json::from_str(&stdout(&out)).unwrap();
    let z: Vec<f64> = v["fkp"]
        .as_array()
        .unwrap()
        .iter()
        .map(|r| r["z"].as_f64().unwrap() * 1000.0)
        .collect();
    assert_eq!(z.len(), 4, "Table 4 rows");
    for (got, want) in z.iter().zip([1384.0, 722.0, -631.0, -1511.0]) {
        assert!((got - want).abs() <= 2.0, "{got} vs {want}");
    }
    let w = &v["workspace"];
    assert!((w["s"][0].as_f64().unwrap() + 2.15).abs() <= 0.02);
    assert!((w["s"][1].as_f64().unwrap() - 2.30).abs() <= 0.02);
    assert_eq!(v["ikp"][0]["spherical_deg"].as_array().unwrap().len(), 3);
}

#[test]
fn markdown_format_prints_dms_table() {
    // Ruiz et al. (2019) Table 4 row 1, FKP: ψ = 8′59″, θ = 1′4″.
    let out = run(&["run", "cases/ruiz2019_kinematics.json", "--format", "md"]);
    assert_eq!(out.status.code(), Some(0));
    let md = stdout(&out);
    assert!(md.contains("| 1395 | 1531 | 1306 | 1385.2 | 8′59″ | 1′04″ |"), "{md}");
    assert!(md.contains("26′06″"), "{md}");
    assert!(md.contains("Requirement ranges"));
}

#[test]
fn out_dir_gets_result_report_and_csv() {
    let d = tempdir("outdir");
    let case = root().join("cases/ruiz2019_kinematics.json");
    run_ok_in(&d, &["run", case.to_str().unwrap(), "--out", "res"]);
    let v: serde_json::Value = serde_json::from_slice(&std::fs::read(d.join("res/result.json")).unwrap()).unwrap();
    assert_eq!(v["fkp"].as_array().unwrap().len(), 4);
    assert!(std::fs::read_to_string(d.join("res/report.md"))
        .unwrap()
        .contains("Forward kinematics"));
    let csv = std::fs::read_to_string(d.join("res/result.csv")).unwrap();
    assert_eq!(csv.lines().filter(|l| l.starts_with("fkp,")).count(), 4);
}

#[test]
fn schema_is_json_and_names_the_analyses() {
    let out = run(&["schema"]);
    assert_eq!(out.status.code(), Some(0));
    let v: serde_json::Value = serde_json::from_str(&stdout(&out)).unwrap();
    let s = v.to_string();
    assert!(s.contains("kinematics") && s.contains("alpha0_deg"), "{s}");
}

#[test]
fn every_bundled_case_checks_and_runs() {
    // Every file in cases/ is valid and runs to completion.
    let mut n = 0;
    for entry in std::fs::read_dir(root().join("cases")).unwrap() {
        let p = entry.unwrap().path();
        if p.extension().and_then(|e| e.to_str()) != Some("json") {
            continue;
        }
        let ps = p.to_str().unwrap();
        let chk = run(&["check", ps]);
        assert_eq!(chk.status.code(), Some(0), "check {ps}: {}", stderr(&chk));
        let name = p.file_name().and_then(|n| n.to_str()).unwrap_or_default();
        if name.contains("sweep") {
            continue; // sweeps run through `flexfem sweep` (tests/sweep.rs)
        }
        let out = run(&["run", ps]);
        assert_eq!(out.status.code(), Some(0), "run {ps}: {}", stderr(&out));
        // No NaN, and no null except fields documented as "not available" (fem_nonlinear; a
        // static result's max_von_mises when no element has a stress, and element_von_mises
        // entries of elements without one: springs, and hinge elements until they report it).
        let text: String = stdout(&out)
            .replace("\"fem_nonlinear\": null", "")
            .replace("\"max_von_mises\": null", "")
            .lines()
            .map(|l| {
                if l.trim_start().starts_with("\"element_von_mises\": [") {
                    l.replace("null", "")
                } else {
                    l.to_string()
                }
            })
            .collect::<Vec<_>>()
            .join("\n");
        assert!(!text.contains("NaN") && !text.contains("null"), "{ps} printed NaN/null");
        n += 1;
    }
    assert!(n >= 1);
}

#[test]
fn out_dir_writes_vtu_for_static_and_stage() {
    // `--out` writes one .vtu per load case (ParaView unstructured grid, line cells, von Mises
    // per cell), for generic models and for the stage (18 element cells, 3 rigid-link lines and
    // a triangle for the platform, 3 slider lines).
    let d = tempdir("vtu");
    for (case, file, cells) in [
        ("cases/static_cantilever.json", "tip.vtu", 2),
        ("cases/ruiz2019_stage.json", "stage_F20.vtu", 25),
    ] {
        let out = run_in(&d, &["run", root().join(case).to_str().unwrap(), "--out", "o"]);
        assert_eq!(out.status.code(), Some(0), "{}", stderr(&out));
        let vtu = std::fs::read_to_string(d.join("o").join(file)).unwrap();
        assert!(
            vtu.starts_with("<?xml") && vtu.trim_end().ends_with("</VTKFile>"),
            "{file}"
        );
        assert!(vtu.contains(&format!("NumberOfCells=\"{cells}\"")), "{file}");
        assert!(
            vtu.contains("Name=\"von_mises_MPa\"") && vtu.contains("Name=\"displacement_mm\""),
            "{file}"
        );
    }
}

#[test]
fn static_case_reproduces_a_cantilever() {
    // Bundled static case: 100 mm Al cantilever 10×10, tip load 10 N (Euler–Bernoulli):
    // δ = PL³/(3EI) = 0.0555556 mm, root stress 6PL/(wh²) = 6 MPa; reactions balance the load.
    let out = run(&["run", "cases/static_cantilever.json"]);
    assert_eq!(out.status.code(), Some(0), "{}", stderr(&out));
    let v: serde_json::Value = serde_json::from_str(&stdout(&out)).unwrap();
    let c = &v["load_cases"][0];
    let uz = c["displacements"][2][2].as_f64().unwrap();
    let expect = -10.0 * 100f64.powi(3) / (3.0 * 72_000.0 * 10f64.powi(4) / 12.0);
    assert!((uz / expect - 1.0).abs() < 1e-9, "{uz} vs {expect}");
    assert!((c["max_von_mises"].as_f64().unwrap() - 6.0).abs() < 1e-9);
    assert!((c["reactions"][0][2].as_f64().unwrap() - 10.0).abs() < 1e-9);
}

#[test]
fn readme_worked_example_matches_the_program() {
    // The README's first command and the whole block of output it shows: every line between the
    // command and the closing "..." (or the end of the block) is the program's output, in order.
    let readme = std::fs::read_to_string(root().join("README.md")).unwrap();
    let cmd = "$ cargo run --release -- run cases/ruiz2019_stage.json --format md";
    let start = readme.find(cmd).expect("README shows the first command and its output");
    let shown: Vec<&str> = readme[start + cmd.len()..]
        .lines()
        .skip(1)
        .take_while(|l| *l != "```" && *l != "...")
        .collect();
    assert!(shown.len() > 10, "README shows only {} lines", shown.len());
    let out = run(&["run", "cases/ruiz2019_stage.json", "--format", "md"]);
    assert_eq!(out.status.code(), Some(0));
    let md = stdout(&out);
    let printed: Vec<&str> = md.lines().collect();
    for (k, line) in shown.iter().enumerate() {
        assert_eq!(
            Some(line),
            printed.get(k),
            "README worked example is out of date at its line {}",
            k + 1
        );
    }
    // A block that closes without "..." shows the whole output: nothing the program prints (a
    // warning, say) may be missing from it.
    let truncated = readme[start + cmd.len()..].lines().nth(1 + shown.len()) == Some("...");
    if !truncated {
        assert_eq!(
            shown.len(),
            printed.len(),
            "README worked example misses the program's last lines"
        );
    }
    assert!(md.contains("| F20 | 20.00, 20.00, 20.00 | 0.9096, 0.9096, 0.9096 | 908.8 |"));
}
